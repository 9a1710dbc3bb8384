"""Closed forms for DEM of a sphere hitting a wall through a liquid layer (thin or
immersed), fitted by ehdfem 0.1.0 (`ehdfem fit`) to dem_closed_forms_reduced.csv (1080 collisions;
half-spaces, Couette tangential model, e_dry = 1). Docs: docs/studies.md of ehdfem, "Closed
forms for DEM".

Dimensionless inputs (Davis, Serayssol & Hinch scales): St = m V0/(6 pi mu a^2), eps = 4 theta
mu V0 a^(3/2)/x0^(5/2), delta = x0/a, P_cav = (p_cav - p_ambient) x0^2/(mu V0 a) < 0 (None: no
cavitation limit), layer "thin" or "immersed", k = I/(m a^2) (2/5: solid sphere). e_n is the
pure EHD value (multiply by the dry restitution); spin change = a DeltaOmega/U0.
Box: St in [1, 10000], eps in [1e-12, 0.1], P_cav in [-100000, -1], delta in [0.001, 0.5] (P_cav also none); for a thin layer also 2 delta (1 + (13.88 eps St)^(2/5)) <= 1 (the wetted film
inside the sphere's radius), for an immersed one 2 delta (13.88 eps St)^(2/5) <= 1 (the
flattened contact inside it). Outside it every function raises ValueError naming the parameter.
Largest errors on points held back from the fit: thin: St_c 2.7%, e_n 0.018, e_t 0.00032 (1 - e_t 3%, 53% just above St_c), spin change 0.00079; immersed: St_c 2.7%, e_n 0.023, e_t 0.00034 (1 - e_t 2%, 65% just above St_c), spin change 0.00086.
"""

import math

BOX = {'St': [1.0, 10000.0], 'eps': [1e-12, 0.1], 'p_cav': [-100000.0, -1.0], 'delta': [0.001, 0.5], 'no_limit': True}
FORMS = {'thin': {'St_c': {'features': ['v', 'h'], 'powers': [[0, 0], [0, 1], [0, 2], [0, 3], [1, 0], [1, 1], [1, 2], [2, 0], [2, 1], [3, 0]], 'coefficients': [0.37546067112185794, -0.013520886303938957, -21.582846378886657, 124.17633850483637, -19.896170231544936, 29.556409538954025, -247.7762766150346, 62.547782093010014, 164.76775837304962, -115.49637500115836]}, 'm': {'features': ['v', 'h'], 'powers': [[0, 0], [0, 1], [0, 2], [0, 3], [1, 0], [1, 1], [1, 2], [2, 0], [2, 1], [3, 0]], 'coefficients': [-0.07137432473390733, 0.04808311922806654, 0.6866285934143147, -2.122105146121393, -2.80970360473612, 6.0772822958643395, -9.506027347580272, 2.098056312298125, 2.8344472197710844, -3.081852258114754]}, 'R': {'features': ['x', 'v', 'h'], 'powers': [[0, 0, 0], [0, 0, 1], [0, 0, 2], [0, 1, 0], [0, 1, 1], [0, 2, 0], [1, 0, 0], [1, 0, 1], [1, 1, 0], [2, 0, 0]], 'coefficients': [-0.1906889739509978, -0.37562710171434227, 0.12991531722554595, 8.967063120877464, 1.7984407769100854, -44.23653776475656, -0.0030065110478233394, 0.03571419580355116, -0.35502132907071965, 0.0012289890347302438]}, 'E': {'features': ['x', 'v', 'h'], 'powers': [[0, 0, 0], [0, 0, 1], [0, 0, 2], [0, 1, 0], [0, 1, 1], [0, 2, 0], [1, 0, 0], [1, 0, 1], [1, 1, 0], [2, 0, 0]], 'coefficients': [3.204231670472388, 0.16951486271543895, 0.406978312333508, -1.251266981409145, -0.1400099266782718, 1.1449185629280907, -0.2712152695953694, -0.03810698546722124, 0.0768050728790616, 0.013238965611813617]}}, 'immersed': {'St_c': {'features': ['v', 'h'], 'powers': [[0, 0], [0, 1], [0, 2], [0, 3], [1, 0], [1, 1], [1, 2], [2, 0], [2, 1], [3, 0]], 'coefficients': [3.6199776453518626, -2.3356843063183255, -18.811024101353976, 120.34952585694373, -23.503002334712246, 72.87729880721751, -250.11371885870116, 78.92600617448639, 99.9065095764215, -145.17802237060923]}, 'm': {'features': ['v', 'h'], 'powers': [[0, 0], [0, 1], [0, 2], [0, 3], [1, 0], [1, 1], [1, 2], [2, 0], [2, 1], [3, 0]], 'coefficients': [-0.0540615519077936, -0.4749669693131344, 3.404832570078362, -5.90556871122985, -1.5797968876649298, -0.07383520340975902, -0.6224586661606556, 3.1791902643476337, 2.439261090592444, -3.8815400690396555]}, 'R': {'features': ['x', 'v', 'h'], 'powers': [[0, 0, 0], [0, 0, 1], [0, 0, 2], [0, 1, 0], [0, 1, 1], [0, 2, 0], [1, 0, 0], [1, 0, 1], [1, 1, 0], [2, 0, 0]], 'coefficients': [-0.010527251823575409, -0.1873204970717953, 0.13962453230951985, 1.3547313923274122, 0.9256443258613962, -5.252909383635597, -0.00023983552631911712, 0.011626043600378933, -0.05088728707338562, -1.623797245397951e-05]}, 'E': {'features': ['x', 'v', 'h'], 'powers': [[0, 0, 0], [0, 0, 1], [0, 0, 2], [0, 1, 0], [0, 1, 1], [0, 2, 0], [1, 0, 0], [1, 0, 1], [1, 1, 0], [2, 0, 0]], 'coefficients': [3.04638134900497, 0.13684074895605453, 0.250272517606479, -1.264488498552739, 0.006394729058835703, 1.1291037199481544, -0.23080485861712802, -0.026008449999041908, 0.06817634092243183, 0.010742117892899453]}, 'T': {'features': ['x', 'v', 'h'], 'powers': [[0, 0, 0]], 'coefficients': [0.017982415257110095]}}}


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
