"""Closed forms for DEM of a sphere hitting a wall through a liquid layer (thin or
immersed), fitted by ehdfem 0.1.0 (`ehdfem fit`) to dem_closed_forms.csv (2912 collisions;
half-spaces, Couette tangential model, e_dry = 1). Docs: docs/studies.md of ehdfem, "Closed
forms for DEM".

Dimensionless inputs (Davis, Serayssol & Hinch scales): St = m V0/(6 pi mu a^2), eps = 4 theta
mu V0 a^(3/2)/x0^(5/2), delta = x0/a, P_cav = (p_cav - p_ambient) x0^2/(mu V0 a) < 0 (None: no
cavitation limit), layer "thin" or "immersed", k = I/(m a^2) (2/5: solid sphere). e_n is the
pure EHD value (multiply by the dry restitution); spin change = a DeltaOmega/U0.
Box: St in [1, 10000], eps in [1e-12, 0.1], P_cav in [-100000, -1], delta in [0.001, 0.5] (P_cav also none); for a thin layer also 2 delta (1 + (13.88 eps St)^(2/5)) <= 1 (the wetted film
inside the sphere's radius), for an immersed one 2 delta (13.88 eps St)^(2/5) <= 1 (the
flattened contact inside it). Outside it every function raises ValueError naming the parameter.
Largest errors on points held back from the fit: thin: St_c 4.4%, e_n 0.019, e_t 0.00045 (1 - e_t 3%, 45% just above St_c), spin change 0.0011; immersed: St_c 3.0%, e_n 0.011, e_t 0.00045 (1 - e_t 2%, 56% just above St_c), spin change 0.0011.
"""

import math

BOX = {'St': [1.0, 10000.0], 'eps': [1e-12, 0.1], 'p_cav': [-100000.0, -1.0], 'delta': [0.001, 0.5], 'no_limit': True}
FORMS = {'thin': {'St_c': {'features': ['v', 'h'], 'powers': [[0, 0], [0, 1], [0, 2], [0, 3], [1, 0], [1, 1], [1, 2], [2, 0], [2, 1], [3, 0]], 'coefficients': [0.20194126550339103, 4.066866490985171, -47.7055977052666, 157.48859500951627, -19.355842129664406, 54.81878638217616, -269.3980267304028, 42.15453331117518, 150.12891545468568, -85.86482897007332]}, 'm': {'features': ['v', 'h'], 'powers': [[0, 0], [0, 1], [0, 2], [0, 3], [1, 0], [1, 1], [1, 2], [2, 0], [2, 1], [3, 0]], 'coefficients': [-0.0486229245683083, 0.2169839457531963, -0.8392185776087597, 0.2592843601840785, -3.18567684101467, 8.355812472338458, -12.870097846528775, 2.332395051177598, 2.9755685771465266, -3.6738815281041437]}, 'R': {'features': ['x', 'v', 'h'], 'powers': [[0, 0, 0], [0, 0, 1], [0, 0, 2], [0, 1, 0], [0, 1, 1], [0, 2, 0], [1, 0, 0], [1, 0, 1], [1, 1, 0], [2, 0, 0]], 'coefficients': [-0.14278022065349633, -0.45337062271829415, 0.25987738460369203, 7.573698157620101, 2.027047549807028, -39.63897609924155, -0.006113010418212133, 0.03829459220886459, -0.21927473004730974, 0.0006542053903625756]}, 'E': {'features': ['x', 'v', 'h'], 'powers': [[0, 0, 0], [0, 0, 1], [0, 0, 2], [0, 1, 0], [0, 1, 1], [0, 2, 0], [1, 0, 0], [1, 0, 1], [1, 1, 0], [2, 0, 0]], 'coefficients': [3.2506732973516086, 0.12893054627673006, 0.4050673690441501, -1.3852419722236244, -0.07022596036626592, 1.2441653841246292, -0.2781916273331563, -0.03405131921293263, 0.08518830237190769, 0.01342549268220502]}}, 'immersed': {'St_c': {'features': ['v', 'h'], 'powers': [[0, 0], [0, 1], [0, 2], [0, 3], [1, 0], [1, 1], [1, 2], [2, 0], [2, 1], [3, 0]], 'coefficients': [3.0973786406713497, 8.482306610326036, -68.78438254155162, 174.1628227830318, -21.43473939520482, 76.1834962532791, -207.70375829265535, 56.887229981485866, 49.8324351218489, -92.91235622612919]}, 'm': {'features': ['v', 'h'], 'powers': [[0, 0], [0, 1], [0, 2], [0, 3], [1, 0], [1, 1], [1, 2], [2, 0], [2, 1], [3, 0]], 'coefficients': [-0.06175087476036886, 0.05537635856761655, 0.9955715661572826, -3.280501341789588, -1.6743686186030566, -0.5373752708708341, 2.773624633002768, 3.1731867720062517, -0.9700569318141439, -1.9594250581904913]}, 'R': {'features': ['x', 'v', 'h'], 'powers': [[0, 0, 0], [0, 0, 1], [0, 0, 2], [0, 1, 0], [0, 1, 1], [0, 2, 0], [1, 0, 0], [1, 0, 1], [1, 1, 0], [2, 0, 0]], 'coefficients': [0.00919375912210668, -0.16144233444671727, 0.19793712285637327, 1.1983922119852646, 0.12096023433238537, -4.771201729060439, -0.007662994744183722, 0.009554796987107613, 0.019313307652932377, 0.0002425196448676253]}, 'E': {'features': ['x', 'v', 'h'], 'powers': [[0, 0, 0], [0, 0, 1], [0, 0, 2], [0, 1, 0], [0, 1, 1], [0, 2, 0], [1, 0, 0], [1, 0, 1], [1, 1, 0], [2, 0, 0]], 'coefficients': [3.0849318173957627, 0.11516206490257376, 0.28861637651337263, -1.344333821408264, 0.051104054760450976, 1.1618616762581437, -0.2387309230721641, -0.02578266421959819, 0.07576181284256925, 0.011036870441523487]}, 'T': {'features': ['x', 'v', 'h'], 'powers': [[0, 0, 0]], 'coefficients': [0.015200810143264003]}}}


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
    compression = (13.87913118903191 * eps * St) ** 0.4
    if layer == "thin" and 2.0 * delta * (1.0 + compression) > 1.0:
        raise ValueError(
            f"delta = {delta!r} is outside the box for a thin layer: the wetted film would "
            "reach past the sphere's radius, 2 delta (1 + (13.88 eps St)^(2/5)) > 1"
        )
    if layer == "immersed" and 2.0 * delta * compression > 1.0:
        raise ValueError(
            f"delta = {delta!r} is outside the box for an immersed layer: the flattened "
            "contact would reach past the sphere's radius, 2 delta (13.88 eps St)^(2/5) > 1"
        )


def _features(St, eps, p_cav):
    L = -math.log(eps)
    elastic = -0.4 * L  # ln of the elastic gap, and of the suction gap:
    limited = p_cav is not None and p_cav != -math.inf
    suction = 0.5 * math.log(0.3 / -p_cav) if limited else -math.inf
    top = max(elastic, suction)
    n = 4.0
    w = -(top + math.log(math.exp(n * (elastic - top)) + math.exp(n * (suction - top))) / n)
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
