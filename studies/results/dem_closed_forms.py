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
Largest errors on points held back from the fit: thin: e_n 0.067, e_t 0.0021 (1 - e_t 36%, 81% just above St_c), spin change 0.0052; immersed: e_n 0.037, e_t 0.0033 (1 - e_t 31%, 88% just above St_c), spin change 0.0081.
"""

import math

BOX = {'St': [1.0, 10000.0], 'eps': [1e-12, 0.1], 'p_cav': [-100000.0, -1.0], 'delta': [0.001, 0.5], 'no_limit': True}
FORMS = {'thin': {'St_c': {'features': ['v', 'h'], 'powers': [[0, 0], [0, 1], [0, 2], [0, 3], [1, 0], [1, 1], [1, 2], [2, 0], [2, 1], [3, 0]], 'coefficients': [0.7510783156674254, 12.035883464158356, -19.48079989006516, 5.01161715525705, -4.844877599463705, -66.65448976092158, 39.61335440975715, 20.096436651150206, 77.83214917289511, -31.550680529442467]}, 'm': {'features': ['v', 'h'], 'powers': [[0, 0], [0, 1], [0, 2], [0, 3], [1, 0], [1, 1], [1, 2], [2, 0], [2, 1], [3, 0]], 'coefficients': [-0.10745925644212502, 1.6678490693050982, -7.568035226028594, 8.300324072687593, -1.924592091444689, -6.374520999073137, 13.180227221609872, 7.243147923180116, 1.1263559097824303, -10.070775782465185]}, 'A': {'features': ['x', 'v', 'h'], 'powers': [[0, 0, 0], [0, 0, 1], [0, 0, 2], [0, 0, 3], [0, 0, 4], [0, 1, 0], [0, 1, 1], [0, 1, 2], [0, 1, 3], [0, 2, 0], [0, 2, 1], [0, 2, 2], [0, 3, 0], [0, 3, 1], [0, 4, 0], [1, 0, 0], [1, 0, 1], [1, 0, 2], [1, 0, 3], [1, 1, 0], [1, 1, 1], [1, 1, 2], [1, 2, 0], [1, 2, 1], [1, 3, 0], [2, 0, 0], [2, 0, 1], [2, 0, 2], [2, 1, 0], [2, 1, 1], [2, 2, 0], [3, 0, 0], [3, 0, 1], [3, 1, 0], [4, 0, 0]], 'coefficients': [5.622955647039954, 2.894463970615483, -8.506721876535428, 23.942705455876094, -20.26356926767839, -79.03168404539497, -2.813698844795534, 8.86655433365315, -13.123046244078804, 357.0650722529455, -29.428454217867472, 17.010434366582505, -378.1213592480783, 26.898620620376835, -176.71310359866075, -3.7917665423903437, -0.9944649813581025, 1.0449680795248277, -1.2999841281717357, 33.40773668194587, 1.6929725908106443, -0.9621745896762471, -122.02542030071405, 0.9340408691851444, 144.59174130890517, 0.3013692095253339, 0.10245850286191473, -0.028777285297575762, -0.9198342193232529, -0.12474433076131278, 0.9455509725237805, -0.018031454905878375, -0.002969198065929754, 0.017972269775154516, 0.0005281339208260682]}}, 'immersed': {'St_c': {'features': ['v', 'h'], 'powers': [[0, 0], [0, 1], [0, 2], [0, 3], [1, 0], [1, 1], [1, 2], [2, 0], [2, 1], [3, 0]], 'coefficients': [3.5728694766170825, 13.41367553024312, -11.554488622489222, -11.795379729533973, 1.0120527869556897, -52.945021974679314, 24.53711205367503, 14.599041641629634, 55.07313653041078, -39.77650703854035]}, 'm': {'features': ['v', 'h'], 'powers': [[0, 0], [0, 1], [0, 2], [0, 3], [1, 0], [1, 1], [1, 2], [2, 0], [2, 1], [3, 0]], 'coefficients': [-0.08884395969475271, 0.7920185163698542, -3.1510201647563805, 2.7352019970110026, -0.9625270599447971, -3.288306003140851, 6.097454635004669, 1.138210752851459, 1.7585682460681111, -0.27797763927321195]}, 'A': {'features': ['x', 'v', 'h'], 'powers': [[0, 0, 0], [0, 0, 1], [0, 0, 2], [0, 0, 3], [0, 0, 4], [0, 1, 0], [0, 1, 1], [0, 1, 2], [0, 1, 3], [0, 2, 0], [0, 2, 1], [0, 2, 2], [0, 3, 0], [0, 3, 1], [0, 4, 0], [1, 0, 0], [1, 0, 1], [1, 0, 2], [1, 0, 3], [1, 1, 0], [1, 1, 1], [1, 1, 2], [1, 2, 0], [1, 2, 1], [1, 3, 0], [2, 0, 0], [2, 0, 1], [2, 0, 2], [2, 1, 0], [2, 1, 1], [2, 2, 0], [3, 0, 0], [3, 0, 1], [3, 1, 0], [4, 0, 0]], 'coefficients': [7.936816833188292, 2.6374028564724146, -8.510577944759932, 23.311953956290566, -17.636277181603973, -107.19166778222954, 8.625692290191948, 5.670718919758936, -11.922348537884549, 393.4025155354407, -69.29864800854057, 19.167463375600928, 156.55681310787136, 65.1477159232398, -1271.8787633706152, -4.827087627801896, -1.3164674257458988, 1.217513619483298, -1.5394019655821525, 45.89590239429907, 1.5382029352111037, -0.9449872211126035, -192.41573133985946, 2.372305013448999, 233.02306993075044, 0.399589563936232, 0.17096167330053763, -0.035994107648620835, -0.7341390038252523, -0.1990299146454378, 1.9343952942843727, -0.024772242621276256, -0.006504789135270536, -0.051581181869699615, 0.0009419840787384414]}, 'B': {'features': ['x', 'v', 'h'], 'powers': [[0, 0, 0], [0, 0, 1], [0, 0, 2], [0, 0, 3], [0, 0, 4], [0, 1, 0], [0, 1, 1], [0, 1, 2], [0, 1, 3], [0, 2, 0], [0, 2, 1], [0, 2, 2], [0, 3, 0], [0, 3, 1], [0, 4, 0], [1, 0, 0], [1, 0, 1], [1, 0, 2], [1, 0, 3], [1, 1, 0], [1, 1, 1], [1, 1, 2], [1, 2, 0], [1, 2, 1], [1, 3, 0], [2, 0, 0], [2, 0, 1], [2, 0, 2], [2, 1, 0], [2, 1, 1], [2, 2, 0], [3, 0, 0], [3, 0, 1], [3, 1, 0], [4, 0, 0]], 'coefficients': [6.367660199814017, 4.8647910352507875, 4.432573102049153, -6.922743983575871, -3.6585205498253357, -136.46629500540493, -25.930760128026133, -8.676604318552698, 0.7453742157815337, 1252.0014936001426, 65.73737944529991, 7.077206153994201, -4477.531014297257, -56.69147890395943, 5183.577854757129, -2.3662338525164746, -1.4409188208789179, -0.6004427811081737, 1.2659946547471645, 6.756143359014586, 3.8136448171863666, 0.7952686510377955, -22.642392128786152, -3.8962654585683025, 32.89947392418091, 0.08594539673645928, 0.139094037318803, -0.002521812099558964, 0.5708760116263386, -0.15225797431105145, -1.2124972441371236, 0.0031659131097970597, -0.004306977432857271, -0.0036844656329542477, -0.0005662676798055147]}}}


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
    """e_t = 1 - k/(1 + k) (1 - exp(-(1 + 1/k) delta I)), I = A (thin), A + B D, D =
    ln((1 + delta)/(2 delta)) (immersed), A, B = exp(Q(x, v, h)); for rebounds (e_n >= 0.3)."""
    _check(St, eps, delta, p_cav, layer, inertia_factor)
    f = _features(St, eps, p_cav)
    integral = math.exp(_q(FORMS[layer]["A"], f))
    if layer == "immersed":
        integral += math.exp(_q(FORMS[layer]["B"], f)) * math.log((1.0 + delta) / (2.0 * delta))
    k = inertia_factor
    return 1.0 - k / (1.0 + k) * -math.expm1(-(1.0 + 1.0 / k) * delta * integral)


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
