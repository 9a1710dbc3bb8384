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
Largest errors on points held back from the fit: thin: St_c 4.3%, e_n 0.019, e_t 0.00044 (1 - e_t 3%, 45% just above St_c), spin change 0.0011; immersed: St_c 3.0%, e_n 0.011, e_t 0.00045 (1 - e_t 2%, 56% just above St_c), spin change 0.0011.
"""

import math

BOX = {'St': [1.0, 10000.0], 'eps': [1e-12, 0.1], 'p_cav': [-100000.0, -1.0], 'delta': [0.001, 0.5], 'no_limit': True}
FORMS = {'thin': {'St_c': {'features': ['v', 'h'], 'powers': [[0, 0], [0, 1], [0, 2], [0, 3], [1, 0], [1, 1], [1, 2], [2, 0], [2, 1], [3, 0]], 'coefficients': [0.20194072290779214, 4.066911680543236, -47.705911291434035, 157.48911624311424, -19.355867828100966, 54.81900411956095, -269.39846587953434, 42.154529795733474, 150.1290170977132, -85.86487621921327]}, 'm': {'features': ['v', 'h'], 'powers': [[0, 0], [0, 1], [0, 2], [0, 3], [1, 0], [1, 1], [1, 2], [2, 0], [2, 1], [3, 0]], 'coefficients': [-0.048623180188696755, 0.21699449530987927, -0.8392882953420092, 0.2593980575543054, -3.1856807643942147, 8.355856264802197, -12.870185569261153, 2.332387742313737, 2.975587008943733, -3.6738803924117813]}, 'R': {'features': ['x', 'v', 'h'], 'powers': [[0, 0, 0], [0, 0, 1], [0, 0, 2], [0, 1, 0], [0, 1, 1], [0, 2, 0], [1, 0, 0], [1, 0, 1], [1, 1, 0], [2, 0, 0]], 'coefficients': [-0.14278023526667466, -0.45337034902602263, 0.2598772038394549, 7.573697831992784, 2.0270450558891207, -39.63897378250233, -0.006113007776028662, 0.03829457717017818, -0.2192746921077954, 0.0006542052222182962]}, 'E': {'features': ['x', 'v', 'h'], 'powers': [[0, 0, 0], [0, 0, 1], [0, 0, 2], [0, 1, 0], [0, 1, 1], [0, 2, 0], [1, 0, 0], [1, 0, 1], [1, 1, 0], [2, 0, 0]], 'coefficients': [3.2506733280057216, 0.12893054147367106, 0.40506752385179917, -1.3852420947685327, -0.07022610071756427, 1.2441655453551665, -0.2781916334606266, -0.034051325395551085, 0.08518831376317088, 0.013425493060575923]}}, 'immersed': {'St_c': {'features': ['v', 'h'], 'powers': [[0, 0], [0, 1], [0, 2], [0, 3], [1, 0], [1, 1], [1, 2], [2, 0], [2, 1], [3, 0]], 'coefficients': [3.097377053764902, 8.482318414186368, -68.78426768927763, 174.16244203101158, -21.43471059733501, 76.18282343972498, -207.70201610261117, 56.88741783493949, 49.83160319552052, -92.91219304444174]}, 'm': {'features': ['v', 'h'], 'powers': [[0, 0], [0, 1], [0, 2], [0, 3], [1, 0], [1, 1], [1, 2], [2, 0], [2, 1], [3, 0]], 'coefficients': [-0.06175102195541769, 0.055377142030996945, 0.9955927398764975, -3.2805608110245, -1.674364934431112, -0.5374854652293887, 2.7738989146182185, 3.1732257888949698, -0.9701850067120226, -1.9594126714721831]}, 'R': {'features': ['x', 'v', 'h'], 'powers': [[0, 0, 0], [0, 0, 1], [0, 0, 2], [0, 1, 0], [0, 1, 1], [0, 2, 0], [1, 0, 0], [1, 0, 1], [1, 1, 0], [2, 0, 0]], 'coefficients': [0.00919382958841934, -0.16144223673914065, 0.19793692334587165, 1.1983910457189468, 0.12095985971504117, -4.771199744826723, -0.007663010447951337, 0.009554797540240531, 0.019313462530849857, 0.00024252029976805858]}, 'E': {'features': ['x', 'v', 'h'], 'powers': [[0, 0, 0], [0, 0, 1], [0, 0, 2], [0, 1, 0], [0, 1, 1], [0, 2, 0], [1, 0, 0], [1, 0, 1], [1, 1, 0], [2, 0, 0]], 'coefficients': [3.0849318681230486, 0.1151621270680265, 0.2886163718548811, -1.3443342180217295, 0.051104292558834336, 1.1618617591351321, -0.23873093281225935, -0.02578267513590067, 0.07576184642002554, 0.011036871006927351]}, 'T': {'features': ['x', 'v', 'h'], 'powers': [[0, 0, 0]], 'coefficients': [0.015200848651047124]}}}


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
        if value is not None and not low * (1 - 1e-9) <= value <= high * (1 + 1e-9):
            raise ValueError(f"{name} = {value!r} is outside the box [{low:g}, {high:g}]")
    if St is None or delta is None:
        return
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
    """St_c = (2/5 + h) L + Q_c(v, h): no rebound below it (eps, P_cav and the layer checked
    against the box; St_c itself may lie outside the St range of the fit)."""
    _check(None, eps, None, p_cav, layer, 0.4)
    f = _features(1.0, eps, p_cav)
    return (0.4 + f["h"]) * f["L"] + _q(FORMS[layer]["St_c"], f)


def normal_restitution(St, eps, p_cav, layer="thin", delta=None):
    """e_n = 1 - (St_c/St)^m above St_c, else 0; m = exp(Q_m(v, h)). e_n does not depend on
    delta; a delta given is checked against the box as for e_t."""
    _check(St, eps, delta, p_cav, layer, 0.4)
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


def pair_restitution(
    St, eps, delta, p_cav, layer="thin", radius_ratio=1.0, density_ratio=1.0, upper_inertia=0.4,
    lower_inertia=0.4, upper_spin=0.0, lower_spin=0.0,
):
    """Two spheres: St, eps, delta, P_cav by the reduced radius a1 a2/(a1 + a2) and mass
    m1 m2/(m1 + m2); radius_ratio a1/a2, density_ratio rho2/rho1 (m1/m2 = (a1/a2)^3/(rho2/rho1)),
    the inertia factors k1, k2 in (0, 2/3], the initial spins s_i = a_i Omega_i/U0 about one
    axis. The wall at 1/k = 1/(k1 (1 + m1/m2)) + 1/(k2 (1 + m2/m1)), the slip scaled by 1 - w0,
    w0 = s1 + s2 (exact for the Couette model): a dict of St_c, e_n, the relative e_t, both
    spin changes a_i DeltaOmega_i/U0 and their sum, the impulse on sphere 1 (e_t - 1, by m U0)
    and k. The wall's errors hold relative to 1 - e_t and the spin changes."""
    for name, value in (("radius_ratio", radius_ratio), ("density_ratio", density_ratio)):
        if not 0.0 < value < math.inf:
            raise ValueError(f"{name} = {value!r} is outside (0, inf)")
    for name, value in (("upper_inertia", upper_inertia), ("lower_inertia", lower_inertia)):
        if not 0.0 < value <= 2.0 / 3.0:
            raise ValueError(f"{name} = {value!r} is outside (0, 2/3]")
    if not math.isfinite(upper_spin + lower_spin):
        raise ValueError(f"the spins {upper_spin!r}, {lower_spin!r} must be finite")
    mass_ratio = radius_ratio**3 / density_ratio
    upper, lower = upper_inertia * (1.0 + mass_ratio), lower_inertia * (1.0 + 1.0 / mass_ratio)
    k = min(1.0 / (1.0 / upper + 1.0 / lower), max(upper_inertia, lower_inertia))
    e_t = tangential_restitution(St, eps, delta, p_cav, layer, k)
    slip = 1.0 - (upper_spin + lower_spin)
    change = slip * (1.0 - e_t) / k
    e_t = 1.0 - slip * (1.0 - e_t)
    return {
        "St_c": critical_stokes(eps, p_cav, layer),
        "e_n": normal_restitution(St, eps, p_cav, layer),
        "e_t": e_t,
        "upper_spin_change": lower / (upper + lower) * change,
        "lower_spin_change": upper / (upper + lower) * change,
        "contact_spin_change": change,
        "tangential_impulse": e_t - 1.0,
        "inertia_factor": k,
    }


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
