"""Closed forms for DEM of a sphere hitting a wall through a liquid layer (thin or
immersed), fitted by ehdfem 0.1.0 (`ehdfem fit`) to dem_closed_forms_reduced.csv (900 collisions;
half-spaces, Couette tangential model, e_dry = 1). Docs: docs/studies.md of ehdfem, "Closed
forms for DEM".

Dimensionless inputs (Davis, Serayssol & Hinch scales): St = m V0/(6 pi mu a^2), eps = 4 theta
mu V0 a^(3/2)/x0^(5/2), delta = x0/a, P_cav = (p_cav - p_ambient) x0^2/(mu V0 a) < 0 (None: no
cavitation limit), layer "thin" or "immersed", k = I/(m a^2) (2/5: solid sphere). e_n is the
pure EHD value (multiply by the dry restitution); spin change = a DeltaOmega/U0.
Box: St in [1, 10000], eps in [1e-12, 0.1], P_cav in [-100000, -1], delta in [0.001, 0.5] (P_cav also none); for a thin layer also 2 delta (1 + (13.88 eps St)^(2/5)) <= 1 (the wetted film
inside the sphere's radius). Outside it every function raises ValueError naming the parameter.
Largest errors on points held back from the fit: thin: e_n 0.089, e_t 0.011 (1 - e_t 91%, 78% just above St_c), spin change 0.029; immersed: e_n 0.053, e_t 0.0092 (1 - e_t 57%, 87% just above St_c), spin change 0.023.
"""

import math

BOX = {'St': [1.0, 10000.0], 'eps': [1e-12, 0.1], 'p_cav': [-100000.0, -1.0], 'delta': [0.001, 0.5], 'no_limit': True}
FORMS = {'thin': {'St_c': {'features': ['v', 'h'], 'powers': [[0, 0], [0, 1], [0, 2], [0, 3], [1, 0], [1, 1], [1, 2], [2, 0], [2, 1], [3, 0]], 'coefficients': [2.464937854563208, 7.3765115887608514, -6.8742113410587296, 4.988862958609785, -47.671451390993255, -42.2458741687462, 10.578948119426387, 281.9511084275598, 46.357393697347, -428.3567174275112]}, 'm': {'features': ['v', 'h'], 'powers': [[0, 0], [0, 1], [0, 2], [0, 3], [1, 0], [1, 1], [1, 2], [2, 0], [2, 1], [3, 0]], 'coefficients': [0.006833383934738108, 1.2900220652715575, -6.773996887802023, 8.338143294936387, -4.73668796189965, -3.517711410394285, 11.17689790141679, 23.919622560156565, -3.440117658587113, -34.8720984367035]}, 'A': {'features': ['x', 'v', 'h'], 'powers': [[0, 0, 0], [0, 0, 1], [0, 0, 2], [0, 0, 3], [0, 0, 4], [0, 1, 0], [0, 1, 1], [0, 1, 2], [0, 1, 3], [0, 2, 0], [0, 2, 1], [0, 2, 2], [0, 3, 0], [0, 3, 1], [0, 4, 0], [1, 0, 0], [1, 0, 1], [1, 0, 2], [1, 0, 3], [1, 1, 0], [1, 1, 1], [1, 1, 2], [1, 2, 0], [1, 2, 1], [1, 3, 0], [2, 0, 0], [2, 0, 1], [2, 0, 2], [2, 1, 0], [2, 1, 1], [2, 2, 0], [3, 0, 0], [3, 0, 1], [3, 1, 0], [4, 0, 0]], 'coefficients': [13.60858211532286, 1.0645353201203638, 5.026157524425665, -0.8830367933503364, -5.169492586915971, -385.28963144560987, -17.71791642796284, -19.41177746959164, 3.6925047840066605, 4011.312456745362, 104.9886868670443, 20.91087878950365, -16670.112261489685, -159.14797317570162, 21466.121051864156, -4.620072657734703, -0.2946659604506162, -0.6308051819506635, 0.42308630643831796, 55.45949035933385, 1.3005894744401134, 1.203862307122471, -270.64850002723483, -1.968747046201291, 381.1836957955939, 0.3152090585450746, 0.025049217521964304, 0.004990354133194011, -1.121380742775174, -0.04763135001292919, 1.2632781628757765, -0.016766101450653853, -0.00011468341241661559, 0.019189230715080743, 0.0004250025613201647]}}, 'immersed': {'St_c': {'features': ['v', 'h'], 'powers': [[0, 0], [0, 1], [0, 2], [0, 3], [1, 0], [1, 1], [1, 2], [2, 0], [2, 1], [3, 0]], 'coefficients': [3.0286273938891806, 8.815918903706605, -14.183839542740976, 21.823821952360714, 16.612175945436796, -19.53000163987961, 14.976685518339762, -100.26072224734976, -18.55502865477932, 156.20029711304878]}, 'm': {'features': ['v', 'h'], 'powers': [[0, 0], [0, 1], [0, 2], [0, 3], [1, 0], [1, 1], [1, 2], [2, 0], [2, 1], [3, 0]], 'coefficients': [-0.13166383397987827, 0.7496092063959542, -4.1144586717752585, 5.3666598220831405, 0.13639820550586357, -2.3455832276470225, 6.879415635889017, -5.961784838180113, -1.8029765976611412, 11.46996440645557]}, 'A': {'features': ['x', 'v', 'h'], 'powers': [[0, 0, 0], [0, 0, 1], [0, 0, 2], [0, 0, 3], [0, 0, 4], [0, 1, 0], [0, 1, 1], [0, 1, 2], [0, 1, 3], [0, 2, 0], [0, 2, 1], [0, 2, 2], [0, 3, 0], [0, 3, 1], [0, 4, 0], [1, 0, 0], [1, 0, 1], [1, 0, 2], [1, 0, 3], [1, 1, 0], [1, 1, 1], [1, 1, 2], [1, 2, 0], [1, 2, 1], [1, 3, 0], [2, 0, 0], [2, 0, 1], [2, 0, 2], [2, 1, 0], [2, 1, 1], [2, 2, 0], [3, 0, 0], [3, 0, 1], [3, 1, 0], [4, 0, 0]], 'coefficients': [15.12764078431644, 7.203060754436963, 0.11762253339529218, 1.487942017192443, -8.61472873129096, -431.99943060459265, -35.21019486448326, -7.9525120861408, 5.206681717439266, 4282.924567744816, 79.2353336532338, 15.41158779417701, -16563.472299350593, -80.60361391512407, 20369.000764909266, -5.038516187339921, -2.6656540305148138, 0.3197513348754318, 0.5292269692507134, 64.9131065211562, 7.579380823545185, 0.007461431852412081, -353.2817114002438, -6.137986101068033, 503.1281194527388, 0.3654713461181863, 0.31657061847524504, -0.0502413790798091, -0.4339372113290624, -0.4230574669202271, 1.7124887259999084, -0.02751437550301963, -0.011980928682421703, -0.05881097490167504, 0.001209765099003759]}, 'B': {'features': ['x', 'v', 'h'], 'powers': [[0, 0, 0], [0, 0, 1], [0, 0, 2], [0, 0, 3], [0, 0, 4], [0, 1, 0], [0, 1, 1], [0, 1, 2], [0, 1, 3], [0, 2, 0], [0, 2, 1], [0, 2, 2], [0, 3, 0], [0, 3, 1], [0, 4, 0], [1, 0, 0], [1, 0, 1], [1, 0, 2], [1, 0, 3], [1, 1, 0], [1, 1, 1], [1, 1, 2], [1, 2, 0], [1, 2, 1], [1, 3, 0], [2, 0, 0], [2, 0, 1], [2, 0, 2], [2, 1, 0], [2, 1, 1], [2, 2, 0], [3, 0, 0], [3, 0, 1], [3, 1, 0], [4, 0, 0]], 'coefficients': [-0.6177728890506375, 3.104984530077889, 0.3896162868245139, 2.223178429189392, -9.798950227852988, 61.65400860945608, -10.139038881642557, 2.7254669672295995, 0.7160689609645763, -382.7163969126979, -9.315979228890853, -4.043591601683753, 405.18199888923175, 40.04633164707416, 377.7324729888036, -0.5682269827626274, -0.988906563988352, -0.09202392938113674, 0.4143773657455511, -26.292363881597744, 2.305675387058332, 0.22863504490743894, 159.17081412952695, -1.8429841004261938, -228.2635444699169, -0.1034017357917217, 0.09829588276256099, -0.007788035149410445, 1.6017492155190867, -0.1031631632891886, -3.1156359628218824, 0.016857168415366643, -0.0030155749737215956, -0.008969156782044307, -0.0010213886463602505]}}}


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
