"""Closed forms for DEM of a sphere hitting a wall through a liquid layer (thin or
immersed), fitted by ehdfem 0.1.0 (`ehdfem fit`) to dem_closed_forms_reduced.csv (1080 collisions;
half-spaces, Couette tangential model, e_dry = 1). Docs: docs/studies.md of ehdfem, "Closed
forms for DEM".

Dimensionless inputs (Davis, Serayssol & Hinch scales): St = m V0/(6 pi mu a^2), eps = 4 theta
mu V0 a^(3/2)/x0^(5/2), delta = x0/a, P_cav = (p_cav - p_ambient) x0^2/(mu V0 a) < 0 (None: no
cavitation limit), layer "thin" or "immersed", k = I/(m a^2) (2/5: solid sphere). e_n is the
pure EHD value (multiply by the dry restitution); spin change = a DeltaOmega/U0.
Box: St in [1, 10000], eps in [1e-12, 0.1], P_cav in [-100000, -1], delta in [0.001, 0.5] (P_cav also none); for a thin layer also 2 delta (1 + (13.88 eps St)^(2/5)) <= 1 (the wetted film
inside the sphere's radius). Outside it every function raises ValueError naming the parameter.
Largest errors on points held back from the fit: thin: e_n 0.067, e_t 0.00056 (1 - e_t 4%, 36% just above St_c), spin change 0.0014; immersed: e_n 0.037, e_t 0.00083 (1 - e_t 6%, 57% just above St_c), spin change 0.0021.
"""

import math

BOX = {'St': [1.0, 10000.0], 'eps': [1e-12, 0.1], 'p_cav': [-100000.0, -1.0], 'delta': [0.001, 0.5], 'no_limit': True}
FORMS = {'thin': {'St_c': {'features': ['v', 'h'], 'powers': [[0, 0], [0, 1], [0, 2], [0, 3], [1, 0], [1, 1], [1, 2], [2, 0], [2, 1], [3, 0]], 'coefficients': [0.7510783156674254, 12.035883464158356, -19.48079989006516, 5.01161715525705, -4.844877599463705, -66.65448976092158, 39.61335440975715, 20.096436651150206, 77.83214917289511, -31.550680529442467]}, 'm': {'features': ['v', 'h'], 'powers': [[0, 0], [0, 1], [0, 2], [0, 3], [1, 0], [1, 1], [1, 2], [2, 0], [2, 1], [3, 0]], 'coefficients': [-0.10745925644212502, 1.6678490693050982, -7.568035226028594, 8.300324072687593, -1.924592091444689, -6.374520999073137, 13.180227221609872, 7.243147923180116, 1.1263559097824303, -10.070775782465185]}, 'R': {'features': ['x', 'v', 'h'], 'powers': [[0, 0, 0], [0, 0, 1], [0, 0, 2], [0, 1, 0], [0, 1, 1], [0, 2, 0], [1, 0, 0], [1, 0, 1], [1, 1, 0], [2, 0, 0]], 'coefficients': [-0.2202952256310015, -0.48365494574459095, 0.29865772500220306, 9.61093183694879, 4.133455722542304, -47.32006785030662, 0.004067670618529788, 0.02816916201844204, -0.5330067259220371, 0.0014019415890320957]}, 'E': {'features': ['x', 'v', 'h'], 'powers': [[0, 0, 0], [0, 0, 1], [0, 0, 2], [0, 1, 0], [0, 1, 1], [0, 2, 0], [1, 0, 0], [1, 0, 1], [1, 1, 0], [2, 0, 0]], 'coefficients': [3.253297056266974, 0.19773901901867186, -0.07762168214422137, -1.1245862655715935, -0.19853944602546075, 1.051892672195397, -0.2795308179999323, -0.013451647710845874, 0.06796338973997167, 0.013282606730527485]}}, 'immersed': {'St_c': {'features': ['v', 'h'], 'powers': [[0, 0], [0, 1], [0, 2], [0, 3], [1, 0], [1, 1], [1, 2], [2, 0], [2, 1], [3, 0]], 'coefficients': [3.5728694766170825, 13.41367553024312, -11.554488622489222, -11.795379729533973, 1.0120527869556897, -52.945021974679314, 24.53711205367503, 14.599041641629634, 55.07313653041078, -39.77650703854035]}, 'm': {'features': ['v', 'h'], 'powers': [[0, 0], [0, 1], [0, 2], [0, 3], [1, 0], [1, 1], [1, 2], [2, 0], [2, 1], [3, 0]], 'coefficients': [-0.08884395969475271, 0.7920185163698542, -3.1510201647563805, 2.7352019970110026, -0.9625270599447971, -3.288306003140851, 6.097454635004669, 1.138210752851459, 1.7585682460681111, -0.27797763927321195]}, 'R': {'features': ['x', 'v', 'h'], 'powers': [[0, 0, 0], [0, 0, 1], [0, 0, 2], [0, 1, 0], [0, 1, 1], [0, 2, 0], [1, 0, 0], [1, 0, 1], [1, 1, 0], [2, 0, 0]], 'coefficients': [-0.08118446840590073, -0.3277688355905111, 0.29005450928383264, 1.7340137821857888, 1.6068598170471653, -2.2197981463395395, 0.021653178283117056, 0.01982210447152124, -0.2298587652523906, -0.0010740257719867555]}, 'E': {'features': ['x', 'v', 'h'], 'powers': [[0, 0, 0], [0, 0, 1], [0, 0, 2], [0, 1, 0], [0, 1, 1], [0, 2, 0], [1, 0, 0], [1, 0, 1], [1, 1, 0], [2, 0, 0]], 'coefficients': [3.69975247085235, 0.31102141862357036, -0.0054448613394127345, -4.482238697700979, 0.07207406435282152, -0.7195833169724063, -0.35781084103880617, -0.03446785595614854, 0.4265637526580231, 0.01671290239311411]}, 'T': {'features': ['x', 'v', 'h'], 'powers': [[0, 0, 0], [0, 0, 1], [0, 0, 2], [0, 1, 0], [0, 1, 1], [0, 2, 0], [1, 0, 0], [1, 0, 1], [1, 1, 0], [2, 0, 0]], 'coefficients': [-0.7987628063772155, -0.09183231193580266, -0.16105710028449088, 4.124975717029931, -0.0795376386805002, -6.3969583699528005, 0.023654579641041413, 0.011076245182617137, 0.4548673463157343, 0.004343499000445477]}}}


def _check(St, eps, delta, p_cav, layer, k):
    if layer not in ("thin", "immersed") or layer not in FORMS:
        raise ValueError(f"layer = {layer!r} is not one of {sorted(FORMS)}")
    if not 0.0 < k <= 2.0 / 3.0:
        raise ValueError(f"inertia_factor = {k!r} is outside (0, 2/3]")
    if p_cav is None or p_cav == -math.inf:
        if not BOX["no_limit"]:
            raise ValueError("p_cav = None (no limit) is outside the box: " + 'St in [1, 10000], eps in [1e-12, 0.1], P_cav in [-100000, -1], delta in [0.001, 0.5] (P_cav also none)')
    elif not BOX["p_cav"][0] * (1 + 1e-9) <= p_cav <= BOX["p_cav"][1] * (1 - 1e-9):
        raise ValueError(f"p_cav = {p_cav!r} is outside the box {BOX['p_cav']}")
    for name, value in (("St", St), ("eps", eps), ("delta", delta)):
        low, high = BOX[name]
        if not low * (1 - 1e-9) <= value <= high * (1 + 1e-9):
            raise ValueError(f"{name} = {value!r} is outside the box [{low:g}, {high:g}]")
    if layer == "thin" and 2.0 * delta * (1.0 + (13.87913118903191 * eps * St) ** 0.4) > 1.0:
        raise ValueError(
            f"delta = {delta!r} is outside the box for a thin layer: the wetted film would "
            "reach past the sphere's radius, 2 delta (1 + (13.88 eps St)^(2/5)) > 1"
        )


def _features(St, eps, p_cav):
    L = -math.log(eps)
    suction = 0.0 if p_cav is None or p_cav == -math.inf else math.sqrt(3.0 / abs(p_cav))
    w = -math.log(eps**0.4 + suction)
    return {"x": math.log(St), "L": L, "v": 1.0 / L, "w": w, "h": w / L}


def _q(form, f):
    total = 0.0
    for c, powers in zip(form["coefficients"], form["powers"]):
        term = c
        for name, p in zip(form["features"], powers):
            term *= f[name] ** p
        total += term
    return total


def critical_stokes(eps, p_cav, layer="thin"):
    """St_c = (2/5 + h) L + Q_c(v, h): no rebound below it."""
    _check(1.0, eps, BOX["delta"][0], p_cav, layer, 0.4)
    f = _features(1.0, eps, p_cav)
    return (0.4 + f["h"]) * f["L"] + _q(FORMS[layer]["St_c"], f)


def normal_restitution(St, eps, p_cav, layer="thin"):
    """e_n = 1 - (St_c/St)^m above St_c, else 0; m = exp(Q_m(v, h))."""
    _check(St, eps, BOX["delta"][0], p_cav, layer, 0.4)
    f = _features(St, eps, p_cav)
    St_c = (0.4 + f["h"]) * f["L"] + _q(FORMS[layer]["St_c"], f)
    if St <= St_c:
        return 0.0
    return 1.0 - (St_c / St) ** math.exp(_q(FORMS[layer]["m"], f))


def tangential_restitution(St, eps, delta, p_cav, layer="thin", inertia_factor=0.4):
    """e_t = 1 - k/(1 + k) (1 - exp(-(1 + 1/k) delta I)), 3 St I = P R + eps^(2/5) St E (thin),
    P (1 + D) R + eps^(2/5) St E + 2.94 C D T (immersed), P = 1 + 1/(e_n + 1/St), D =
    (1 + c) ln(1 + c) - c ln c - 1 with c = 1/(2 delta), C = (13.88 eps St)^(2/5), R, E, T =
    exp(Q(x, v, h)); stated errors for rebounds (e_n >= 0.3)."""
    e_n = normal_restitution(St, eps, p_cav, layer)
    _check(St, eps, delta, p_cav, layer, inertia_factor)
    f = _features(St, eps, p_cav)
    forms = FORMS[layer]
    passes = (1.0 + 1.0 / (e_n + 1.0 / St)) * math.exp(_q(forms["R"], f))
    total = passes + eps**0.4 * St * math.exp(_q(forms["E"], f))
    if layer == "immersed":
        c = 0.5 / delta
        far = math.log1p(c) + c * math.log1p(1.0 / c) - 1.0
        contact = 2.94 * (13.87913118903191 * eps * St) ** 0.4
        total += far * (passes + contact * math.exp(_q(forms["T"], f)))
    k = inertia_factor
    return 1.0 - k / (1.0 + k) * -math.expm1(-(1.0 + 1.0 / k) * delta * total / (3.0 * St))


def spin_change(St, eps, delta, p_cav, layer="thin", inertia_factor=0.4):
    """a DeltaOmega/U0 = (1 - e_t)/k (no initial spin)."""
    e_t = tangential_restitution(St, eps, delta, p_cav, layer, inertia_factor)
    return (1.0 - e_t) / inertia_factor


def dimensionless_groups(
    radius, density, normal_speed, viscosity, theta, layer_thickness, cavitation_pressure,
    ambient_pressure=101325.0,
):
    """(St, eps, delta, P_cav) of a solid sphere (SI inputs: m, kg/m^3, m/s, Pa s; theta =
    sum (1 - nu^2)/(pi E) of sphere and wall in 1/Pa; pressures absolute in Pa)."""
    mass = 4.0 / 3.0 * math.pi * radius**3 * density
    St = mass * normal_speed / (6.0 * math.pi * viscosity * radius**2)
    eps = 4.0 * theta * viscosity * normal_speed * radius**1.5 / layer_thickness**2.5
    scale = viscosity * normal_speed * radius / layer_thickness**2
    return St, eps, layer_thickness / radius, (cavitation_pressure - ambient_pressure) / scale
