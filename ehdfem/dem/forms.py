"""Closed forms for DEM whose shape carries the known limits: e_n, St_c, e_t and the spin change.

All inputs and outputs are dimensionless (DSH scales, :mod:`ehdfem.inputs.scales`): St, eps,
delta, P_cav (None: no cavitation limit), for a thin or an immersed layer, half-spaces, the
Couette tangential model; e_n is the pure EHD value (multiply by e_dry); the spin change is
a DeltaOmega/U0 of a sphere without initial spin. Features of the inputs:

    L = ln(1/eps),  v = 1/L,  x = ln St,
    w = ln(1 / (eps^(2/5) + sqrt(3/|P_cav|)))   (the sqrt term 0 without a limit),  h = w / L.

Normal motion. A rigid sphere loses ln(1/X) of St reaching the gap X (immersed; thin: ln(1/X)
- 3/2 + 2X - X^2/2), and elastic flattening starts at X ~ eps^(2/5): the approach costs
(2/5) ln(1/eps). Leaving, the unlimited suction of Stokes flow costs as much again (the motion
is reversible), but a receding sphere's suction -3V/H^2 reaches P_cav below the gap
sqrt(3V/|P_cav|), under which its force is capped at about |P_cav| H: the exit costs
ln(1/max(eps^(2/5), sqrt(3/|P_cav|))) + O(1), that is w. So

    St_c = (2/5 + h) L + Q_c(v, h),
    e_n  = 1 - (St_c/St)^m above St_c, else 0,   m = exp(Q_m(v, h)),

with Q_c, Q_m cubic: as eps -> 0, St_c / ln(1/eps) -> 2/5 with a cavitation limit (h -> 0)
and 4/5 without (h = 2/5), and e_n -> 0 at fixed St (a rigid sphere sticks); as St -> inf,
e_n -> 1 (times e_dry: the dry limit).

Tangential motion (Couette: St dU/dT = -(delta/3) J u_s, k St d(a Omega)/dT = (delta/3) J u_s,
docs/tangential.md). U + k a Omega is conserved and the slip decays exactly as
exp(-(1 + 1/k) delta I), I = int J dT / (3 St), so

    1 - e_t = k/(1 + k) (1 - exp(-(1 + 1/k) delta I)),   spin change = (1 - e_t)/k,

linear in delta for small delta and tending to rolling (e_t = 1/(1 + k)) for large delta I.
In a thin layer J ends at the wetted edge and I does not depend on delta: I = exp(Q_A(x, v,
h)) (while the wetted film stays inside r = a, :mod:`ehdfem.dem.box`). Immersed, the film's
far field reaches r = a (R = 1/sqrt(delta)) and adds int R dR / (X + R^2/2) = ln((X + 1/(2
delta))/X) to J: with the gap X at a typical 1/2, I = A + B D, D = ln((1 + delta)/(2 delta))
(ln(1/delta) - ln 2 for small delta, so that (1 - e_t)/delta = A' + B ln(1/delta) there),
A = exp(Q_A), B = exp(Q_B); at St 30, eps 1e-6, P_cav -100, I from delta = 1e-3 and 0.5 gives
I at delta = 0.01-0.3 within 0.7 % (with ln(1/delta) for D: 6 %). Q_A and Q_B are quartic in
(x, v, h): a cubic misses by up to 70 %, as I falls by four decades over the box, as 1/St
where the contact time is short and more slowly where it grows. I is the same for every k
(the normal motion does not depend on the tangential one), so the forms hold for any k.
"""

from __future__ import annotations

from itertools import product

import numpy as np

from . import box as inputs_box

CRITICAL_SLOPE = 0.4  # St_c / ln(1/eps) of the approach to the elastic gap eps^(2/5)
SUCTION_GAP = 3.0  # the receding sphere's suction 3 V/H^2 reaches P_cav at H = sqrt(3/|P_cav|)
DEGREE = {"St_c": 3, "m": 3, "A": 4, "B": 4}  # of the polynomials Q
NORMAL = ("St_c", "m")
TANGENTIAL = {"thin": ("A",), "immersed": ("A", "B")}
FEATURES = {"St_c": ("v", "h"), "m": ("v", "h"), "A": ("x", "v", "h"), "B": ("x", "v", "h")}


def features(St, eps, p_cav) -> dict:
    """x, L, v, w, h of the module docstring (arrays; p_cav None or -inf: no limit)."""
    eps = np.asarray(eps, dtype=float)
    L = -np.log(eps)
    if inputs_box.no_limit(p_cav):
        suction = np.zeros_like(eps)
    else:
        suction = np.sqrt(SUCTION_GAP / np.abs(np.asarray(p_cav, dtype=float)))
    w = -np.log(eps**0.4 + suction)
    return {"x": np.log(np.asarray(St, dtype=float)), "L": L, "v": 1.0 / L, "w": w, "h": w / L}


def powers(names, degree: int, distinct=None) -> list[tuple]:
    """Exponent tuples of the monomials of total degree <= ``degree`` in ``names``, each
    feature's power below its number of ``distinct`` values in a table (when given)."""
    tops = [degree if distinct is None else min(degree, distinct[n] - 1) for n in names]
    return [p for p in product(*(range(t + 1) for t in tops)) if sum(p) <= degree]


def design(form: dict, values: dict) -> np.ndarray:
    """Columns prod_i f_i^p_i of the form's monomials at ``values`` (features by name)."""
    columns = np.broadcast_arrays(*(np.atleast_1d(values[n]) for n in form["features"]))
    return np.column_stack(
        [np.prod([c**k for c, k in zip(columns, p, strict=True)], axis=0) for p in form["powers"]]
    )


def polynomial(form: dict, values: dict) -> np.ndarray:
    """Q of a fitted form ({"features", "powers", "coefficients"}) at ``values``."""
    return design(form, values) @ np.asarray(form["coefficients"], dtype=float)


def critical_stokes(forms: dict, eps, p_cav, layer: str):
    """St_c = (2/5 + h) L + Q_c(v, h) of ``layer``'s fitted ``forms`` (no check of the box)."""
    f = features(1.0, eps, p_cav)
    return (CRITICAL_SLOPE + f["h"]) * f["L"] + polynomial(forms[layer]["St_c"], f)


def normal_restitution(forms: dict, St, eps, p_cav, layer: str):
    """e_n = 1 - (St_c/St)^m above St_c, else 0 (pure EHD), m = exp(Q_m(v, h))."""
    f = features(St, eps, p_cav)
    St_c = (CRITICAL_SLOPE + f["h"]) * f["L"] + polynomial(forms[layer]["St_c"], f)
    ratio = np.clip(St_c / np.asarray(St, dtype=float), 0.0, 1.0)
    return 1.0 - ratio ** np.exp(polynomial(forms[layer]["m"], f))


def far_field(delta):
    """D = ln((1 + delta)/(2 delta)): the immersed far field's share of I, by B."""
    delta = np.asarray(delta, dtype=float)
    return np.log((1.0 + delta) / (2.0 * delta))


def sliding_integral(forms: dict, St, eps, delta, p_cav, layer: str):
    """I = int J dT / (3 St): exp(Q_A) in a thin layer, exp(Q_A) + exp(Q_B) D(delta)
    immersed."""
    f = features(St, eps, p_cav)
    integral = np.exp(polynomial(forms[layer]["A"], f))
    if layer == "immersed":
        integral = integral + np.exp(polynomial(forms[layer]["B"], f)) * far_field(delta)
    return integral


def tangential_restitution(forms: dict, St, eps, delta, p_cav, layer: str, inertia_factor=0.4):
    """e_t = 1 - k/(1 + k) (1 - exp(-(1 + 1/k) delta I)), k = ``inertia_factor``."""
    k = inertia_factor
    integral = sliding_integral(forms, St, eps, delta, p_cav, layer)
    return 1.0 - k / (1.0 + k) * -np.expm1(-(1.0 + 1.0 / k) * np.asarray(delta) * integral)


def sliding_integral_of(e_t, delta, inertia_factor=0.4):
    """I from a computed e_t (the inverse of :func:`tangential_restitution`)."""
    k = inertia_factor
    e_t, delta = np.asarray(e_t, dtype=float), np.asarray(delta, dtype=float)
    return -np.log1p(-(1.0 + k) / k * (1.0 - e_t)) / ((1.0 + 1.0 / k) * delta)


def restitution(forms: dict, St, eps, delta, p_cav, layer: str, inertia_factor=0.4) -> dict:
    """{"St_c", "e_n", "e_t", "spin_change"} of the fitted ``forms`` at one collision, after
    refusing inputs outside the forms' box (InputError, a ValueError, naming the parameter)."""
    inputs_box.check_inside(forms["box"], St, eps, delta, p_cav, layer, inertia_factor)
    p_cav = None if inputs_box.no_limit(p_cav) else p_cav
    e_t = float(tangential_restitution(forms, St, eps, delta, p_cav, layer, inertia_factor)[0])
    return {
        "St_c": float(critical_stokes(forms, eps, p_cav, layer)[0]),
        "e_n": float(normal_restitution(forms, St, eps, p_cav, layer)[0]),
        "e_t": e_t,
        "spin_change": (1.0 - e_t) / inertia_factor,
    }


def describe(name: str) -> str:
    """The shape of a form, one line."""
    return {
        "St_c": "St_c = (2/5 + h) L + Q(v, h)",
        "m": "m = exp(Q(v, h)) in e_n = 1 - (St_c/St)^m",
        "A": "A = exp(Q(x, v, h)) in I = A + B ln((1 + delta)/(2 delta))",
        "B": "B = exp(Q(x, v, h)) in I = A + B ln((1 + delta)/(2 delta)) (immersed)",
    }[name]


LAYER_FORMS = {layer: (*NORMAL, *TANGENTIAL[layer]) for layer in inputs_box.LAYERS}
