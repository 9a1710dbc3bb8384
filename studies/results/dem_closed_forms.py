"""Closed forms for wet collisions of a sphere on a wall through a thin liquid
layer, fitted by ehdfem 0.1.0 (`ehdfem fit`) to dem_closed_forms.csv: 252 collisions of the
layer thin, cavitation truncate, viscosity constant, alpha 0.0, tangential lubrication model.

All inputs and outputs are dimensionless (Davis, Serayssol & Hinch scales): St = m V0/(6 pi mu
a^2), eps = 4 theta mu V0 a^(3/2)/x0^(5/2), delta = x0/a, P_cav = (p_cav - p_ambient) x0^2/(mu
V0 a) < 0, with V0 the normal impact speed and x0 the layer thickness (dimensionless_groups
computes them from SI inputs). e_n is the pure EHD value: multiply by the dry restitution.
The spin change is a DeltaOmega/U0 (U0 the tangential impact speed).

Fitted over St in [3, 1e+03], eps in [1e-06, 0.1], p_cav in [-30, -3], delta in [0.01, 0.01].
Errors against the table: e_n max 0.072 (rms 0.01) over every point,
max 0.072 where e_n >= 0.3.
For rebounds with e_n >= 0.3 (the range of e_t and the spin change): e_t max 0.00095
(relative to 1 - e_t 0.11), spin change max 0.0016 (relative 0.11).
Just above St_c (0 < e_n < 0.3) 1 - e_t and the spin change are off by up to
86%. Outside these ranges the forms are extrapolations.
"""

import math

FORMS = {'St_c': {'inputs': ['eps', 'p_cav'], 'powers': [[0, 0], [0, 1], [0, 2], [1, 0], [1, 1], [1, 2], [2, 0], [2, 1], [3, 0]], 'coefficients': [-2.729093822756706, 0.5833021887654186, -0.03436552005237075, -0.8808991664877934, 0.055412789726277466, -0.002972962638243839, -0.06930734169387767, 0.001239864067090663, -0.002087218163861616]}, 'm': {'inputs': ['eps', 'p_cav'], 'powers': [[0, 0], [0, 1], [0, 2], [1, 0], [1, 1], [1, 2], [2, 0], [2, 1], [3, 0]], 'coefficients': [-0.8257322762938635, 0.05943692655879935, 0.020478021477773542, -0.11598416099659327, 0.01990964611877708, 0.0023683217478043077, -0.006320437247128251, 0.0015680470619355868, -4.3400720871331376e-05]}, 'tangential_loss': {'inputs': ['St', 'eps', 'p_cav'], 'powers': [[0, 0, 0], [0, 0, 1], [0, 0, 2], [0, 1, 0], [0, 1, 1], [0, 1, 2], [0, 2, 0], [0, 2, 1], [0, 3, 0], [1, 0, 0], [1, 0, 1], [1, 0, 2], [1, 1, 0], [1, 1, 1], [1, 2, 0], [2, 0, 0], [2, 0, 1], [2, 1, 0], [3, 0, 0]], 'coefficients': [1.5155502904053093, 0.06909581799092578, -0.0070740329137786336, 0.24045704752223712, -0.00567651862683803, -0.0005691721313974135, 0.009454567422620868, -0.00039926797701063735, -0.0004655052031150783, -0.18248201140019854, -0.018872453877740256, 0.0005857521264986719, 0.07101151241430875, 0.00037746054674944046, -0.0029829587633870003, 0.037082124252932384, 0.0014417723738472388, -0.009085505885424176, -0.004738596301925782]}, 'spin_change': {'inputs': ['St', 'eps', 'p_cav'], 'powers': [[0, 0, 0], [0, 0, 1], [0, 0, 2], [0, 1, 0], [0, 1, 1], [0, 1, 2], [0, 2, 0], [0, 2, 1], [0, 3, 0], [1, 0, 0], [1, 0, 1], [1, 0, 2], [1, 1, 0], [1, 1, 1], [1, 2, 0], [2, 0, 0], [2, 0, 1], [2, 1, 0], [3, 0, 0]], 'coefficients': [2.4322221153682837, 0.04596227273079687, -0.002379307762845964, 0.3085872745214678, 0.003671328110503866, -3.135246625274313e-05, 0.01855359096347252, 0.00014707347297383735, -0.0002354563886619726, -0.2621117535662236, -0.013582632507628211, 0.0003655900891360222, 0.07462179799383072, -6.849122000101605e-05, -0.003664897984526211, 0.06361248616175026, 0.001239836856032247, -0.010445472188724103, -0.0067677796586531926]}}


def _fitted(name, **inputs):
    """exp of the polynomial in the logarithms of the form's inputs (|x| for P_cav)."""
    form = FORMS[name]
    logs = [math.log(abs(inputs[key])) for key in form["inputs"]]
    terms = [math.prod(x**p for x, p in zip(logs, powers)) for powers in form["powers"]]
    return math.exp(sum(c * t for c, t in zip(form["coefficients"], terms)))


def critical_stokes(eps, p_cav):
    """St_c: no rebound below it."""
    return _fitted("St_c", eps=eps, p_cav=p_cav)


def normal_restitution(St, eps, p_cav):
    """e_n = 1 - (St_c/St)^m above St_c, else 0 (pure EHD)."""
    St_c = critical_stokes(eps, p_cav)
    if St <= St_c:
        return 0.0
    return 1.0 - (St_c / St) ** _fitted("m", eps=eps, p_cav=p_cav)


def tangential_restitution(St, eps, delta, p_cav):
    """e_t = 1 - delta exp(Q(ln St, ln eps, ln |P_cav|)), Q cubic, for a rebounding sphere."""
    return 1.0 - delta * _fitted("tangential_loss", St=St, eps=eps, p_cav=p_cav)


def spin_change(St, eps, delta, p_cav):
    """a DeltaOmega/U0 = delta exp(Q(ln St, ln eps, ln |P_cav|)), Q cubic, for a rebound."""
    return delta * _fitted("spin_change", St=St, eps=eps, p_cav=p_cav)


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
