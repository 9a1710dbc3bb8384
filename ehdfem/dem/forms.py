"""Closed forms for DEM whose shape carries the known limits: e_n, St_c, e_t and the spin change.

All inputs and outputs are dimensionless (DSH scales, :mod:`ehdfem.inputs.scales`): St, eps,
delta, P_cav (None: no cavitation limit), for a thin or an immersed layer, half-spaces, the
Couette tangential model; e_n is the pure EHD value (multiply by e_dry); the spin change is
a DeltaOmega/U0 of a sphere without initial spin. Features of the inputs:

    L = ln(1/eps),  v = 1/L,  x = ln St,
    w = -(1/4) ln(eps^(8/5) + (0.3/|P_cav|)^2)   (the P_cav term 0 without a limit),  h = w / L.

Normal motion. A rigid sphere loses ln(1/X) of St reaching the gap X (immersed; thin: ln(1/X)
- 3/2 + 2X - X^2/2), and elastic flattening starts at X ~ eps^(2/5): the approach costs
(2/5) ln(1/eps). Leaving, the unlimited suction of Stokes flow costs as much again (the motion
is reversible), but a receding sphere's suction -3V/H^2 reaches P_cav below the gap
sqrt(3V/|P_cav|), under which its force is capped at about |P_cav| H: the exit costs
ln(1/max(eps^(2/5), sqrt(3V/|P_cav|))) + O(1). w is that logarithm with the maximum smoothed
as a 4-norm and V = 0.1, the speed of a sphere leaving near St_c (e_n 0.1-0.3): of the pairs
tried (V 0.01-1, norms 1-8) about the smallest residual of e_n on the reduced fit table (rms
0.0030 and 0.0014, thin and immersed; 0.0073 and 0.0055 with the plain sum and V = 1); the
crossover from the suction limit to unlimited suction is sharp: St_c at P_cav = -1e5 equals
that without a limit from eps = 1e-6 on (docs/studies.md). So

    St_c = (2/5 + h) L + Q_c(v, h),
    e_n  = 1 - (St_c/St)^m above St_c, else 0,   m = exp(Q_m(v, h)),

with Q_c, Q_m cubic: as eps -> 0, St_c / ln(1/eps) -> 2/5 with a cavitation limit (h -> 0)
and 4/5 without (h = 2/5), and e_n -> 0 at fixed St (a rigid sphere sticks); as St -> inf,
e_n -> 1 (times e_dry: the dry limit).

Tangential motion (Couette: St dU/dT = -(delta/3) J u_s, k St d(a Omega)/dT = (delta/3) J u_s,
J = int R dR / H0, docs/tangential.md). U + k a Omega is conserved and the slip decays exactly as
exp(-(1 + 1/k) delta I), I = int J dT / (3 St), so

    1 - e_t = k/(1 + k) (1 - exp(-(1 + 1/k) delta I)),   spin change = (1 - e_t)/k,

linear in delta for small delta and tending to rolling (e_t = 1/(1 + k)) for large delta I.
The shape of 3 St I = int J dT (time by x0/V0) is that of its three parts:

- the rigid approach and departure: a rigid sphere's film, H0 = X + R^2/2, gives J = ln(1/X)
  out to the wetted edge of a thin layer; int_0^1 ln(1/X) dX = 1 at the approach speed 1, and
  int_0^1 ln(1/X) dX / V(X) leaving, V(X) = e_n + ln(1/X)/St the exit speed plus what the
  unlimited suction between X and the exit still takes: St (1 - b e^b E_1(b)), b = e_n St,
  which tends to 1/e_n for b >> 1 and to St for b -> 0, as does 1/(e_n + 1/St). So the passes
  cost P = 1 + 1/(e_n + 1/St) (within 5 % of the computed collisions at eps 1e-12, St 30-1e3);
- the elastic contact: the film under the flattened contact, its area 2 pi C (C the compression
  by x0) and thickness ~ eps^(2/5), lasts a time ~ C: int J dT = eps^(2/5) St E, E within a
  factor 6 over the whole box while eps^(2/5) St spans eleven decades (computed collisions,
  thin, P_cav -30, St 1e4: (int J dT - 2)/eps^(2/5) = 5.7e4 at eps 1e-12 and 5.85e4 at 0.1);
- immersed, the far field out to r = a (R = 1/sqrt(delta)): ln((X + c)/X), c = 1/(2 delta),
  adds int_0^1 ln(X + c) dX = D(delta) = (1 + c) ln(1 + c) - c ln c - 1 (ln(1/(2 delta)) + delta
  for small delta) per unit gap swept, and D times the contact time, that of dry Hertz
  2.94 C at C = (13.88 eps St)^(2/5).

So, with R = exp(Q_R), E = exp(Q_E) quadratic in (x, v, h), T = exp(Q_T) a constant and e_n the
form's own,

    thin:      3 St I = P R + eps^(2/5) St E,
    immersed:  3 St I = P (1 + D) R + eps^(2/5) St E + 2.94 C D T,      P = 1 + 1/(e_n + 1/St),

R 0.99-1.17 where the rigid passes carry I (eps <= 1e-6), E 3-19 over the reduced table's
rebounds (studies/dem_closed_forms_reduced.toml), and T fitted 1.02 against the 1 of the
derivation (a quadratic Q_T was not determined: the table's immersed contacts at large eps St
have one delta inside the box, where E and T cannot be told apart, and it missed 1 - e_t by 6 %
at delta = 0.03 instead of 2 %). Below St_c (e_n = 0) P = 2 + St: the sphere followed until
it stops in the film. I is the same for every k (the normal motion does
not depend on the tangential one), so the forms hold for any k. In a thin layer I does not
depend on delta while the wetted film stays inside r = a; immersed, it is A + B D with
A = (P R + eps^(2/5) St E)/(3 St), B = (P R + 2.94 C T)/(3 St), exact in delta to the extent
that the gap swept and the contact do not depend on it (:mod:`ehdfem.dem.box`: the contact
inside r = a).
"""

from __future__ import annotations

from itertools import product

import numpy as np

from ..exact import hertz
from . import box as inputs_box

CRITICAL_SLOPE = 0.4  # St_c / ln(1/eps) of the approach to the elastic gap eps^(2/5)
SUCTION_GAP = 0.3  # the receding sphere's suction 3 V/H^2 reaches P_cav at H = sqrt(3 V/|P_cav|)
SUCTION_NORM = 4.0  # w = -ln of the 4-norm of the elastic and the suction gaps
HERTZ_TIME = 2.94  # the dry Hertz contact time by the compression C/V0 (Johnson 1985, 11.2)
DEGREE = {"St_c": 3, "m": 3, "R": 2, "E": 2, "T": 0}  # of the polynomials Q
NORMAL = ("St_c", "m")
TANGENTIAL = {"thin": ("R", "E"), "immersed": ("R", "E", "T")}
NAMES = ("St_c", "m", "R", "E", "T")  # every form, in the order of the C header's table
FEATURES = {"St_c": ("v", "h"), "m": ("v", "h")} | {n: ("x", "v", "h") for n in "RET"}


def features(St, eps, p_cav) -> dict:
    """x, L, v, w, h of the module docstring (arrays; p_cav None or -inf: no limit); w from the
    logarithms of the gaps, so that eps^(8/5) may underflow."""
    eps = np.asarray(eps, dtype=float)
    L = -np.log(eps)
    if inputs_box.no_limit(p_cav):
        suction = np.full_like(eps, -np.inf)  # ln of the suction gap
    else:
        suction = 0.5 * np.log(SUCTION_GAP / np.abs(np.asarray(p_cav, dtype=float)))
    n = SUCTION_NORM
    w = -np.logaddexp(-0.4 * n * L, n * suction) / n
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
    """D = (1 + c) ln(1 + c) - c ln c - 1, c = 1/(2 delta): int_0^1 ln(X + c) dX, the immersed
    far field's share of J (the rigid film out to r = a) per unit gap swept."""
    c = 0.5 / np.asarray(delta, dtype=float)
    return np.log1p(c) + c * np.log1p(1.0 / c) - 1.0


def contact_time(St, eps):
    """2.94 C: the dry Hertz contact time (by x0/V0) at the compression C = (13.88 eps St)^(2/5)
    (by x0)."""
    return HERTZ_TIME * hertz.max_compression(np.asarray(eps, float), np.asarray(St, float))


def sliding_integral(forms: dict, St, eps, delta, p_cav, layer: str):
    """I = int J dT / (3 St) of the module docstring."""
    e_n = normal_restitution(forms, St, eps, p_cav, layer)
    return integral_of(forms[layer], layer, features(St, eps, p_cav), e_n, St, eps, delta)


def integral_of(layer_forms: dict, layer: str, values: dict, e_n, St, eps, delta):
    """I of the module docstring from the features ``values`` and the rebound's ``e_n``."""
    St, eps = np.asarray(St, dtype=float), np.asarray(eps, dtype=float)
    passes = 1.0 + 1.0 / (np.asarray(e_n, dtype=float) + 1.0 / St)
    part = {name: np.exp(polynomial(layer_forms[name], values)) for name in TANGENTIAL[layer]}
    total = passes * part["R"] + eps**0.4 * St * part["E"]
    if layer == "immersed":
        D = far_field(delta)
        total = total + D * (passes * part["R"] + contact_time(St, eps) * part["T"])
    return total / (3.0 * St)


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
        "R": "R = exp(Q(x, v, h)) of the rigid passes (1 + 1/(e_n + 1/St)) (1 + D) in 3 St I",
        "E": "E = exp(Q(x, v, h)) of the elastic contact eps^(2/5) St E in 3 St I",
        "T": "T = exp(Q(x, v, h)) of the far field in contact 2.94 C D T in 3 St I (immersed)",
    }[name]


LAYER_FORMS = {layer: (*NORMAL, *TANGENTIAL[layer]) for layer in inputs_box.LAYERS}
