"""The tangential surface effects' first correction in closed form: weak elasticity, thin layer.

The constant c1 of the surface effects (:mod:`ehdfem.study.corrections`) measured at finite eps
has a closed form in the limit eps -> 0, where the leading-order solution is the rigid approach
(docs/fem.md, "The surface effects in closed form"). Scaled as in docs/model.md: gap X and film
H by x0, radius R by sqrt(a x0), time by x0/V0, velocity V by V0, pressure by mu V0 a / x0^2,
force by 6 pi mu V0 a^2 / x0; s = sqrt(delta); kappa the shear coefficient of the two
solids (:func:`ehdfem.solids.halfspace.shear_coefficient`, a number here).

The rigid approach through a thin layer (P = 0 at the wetted edge H = X + R^2/2 = 1, no
cavitation): P0 = 3 |V| (1/H^2 - 1), force |V| (1 - X)^2 / X, and from St V dV/dX = force,
V0(X) = -1 + G(X)/St, G = ln(1/X) - 3/2 + 2 X - X^2/2; the sphere stops at X_s, G(X_s) = St.

The two surface terms on half-spaces are linear in eps P0. The shear opening
w = -eps s kappa int_R T0 dS = 3 eps s kappa V (1/H - 1) and the faces' mean radial
displacement U = -eps (kappa/2) (1/R) int_0^R P0 S dS = (3/2) eps kappa (V/R)(1/X - 1/H - H + X)
change the film force, -2 int R (Q + s R H dU/dT) / H^3 dR with Q = int_0^R R' dH/dT dR', by

    f1 = eps s kappa (A(X) V^2 + B(X) dV/dT)          (to first order in eps s),

A = (1 - X)^2 (5 + 4X - 3X^2) / (2 X^3) (opening) + (1 - X)^2 (2 + X) / X^3 (velocity),
B = 3 b(X) / (2 X^2) for each term, b = 2X^3 - 3X^2 + 2X - 1 - 2 X^2 ln X
(:func:`surface_force_coefficients`). With dV/dT = -V (1 - X)^2 / (X St), the velocity at a gap
moves by V1 with St dV1/dX = f1 / V0 (the rigid force over V does not depend on V), so
V1(X) = -(eps s kappa / St) J(X), J(X) = int_X^1 (V0 A - (1 - X')^2 B / (X' St)) dX', and the
stopping gap, the thinnest film, by dX_s = -V1(X_s) / V0'(X_s):

    (H_min(on) - H_min(off)) / H_min(off) = c sqrt(delta) eps,
    c = -kappa J(X_s) / (1 - X_s)^2          (:func:`stopping_gap_constant`).

Assumed: a quasi-steady film without cavitation on identical or dissimilar half-spaces, the
paraboloid gap, weak elasticity (eps |V| X^(-5/2) << 1 all along the approach, so the rigid
solution is the leading order), and the surface terms' signs of docs/model.md (both faces
rise into the film under an outward shear; both move towards the axis under pressure).
"""

from __future__ import annotations

import math

from .. import checks
from . import rigid_film

EFFECTS = ("opening", "velocity", "both")
"""The surface terms: the squeeze shear's gap opening, the faces' radial velocity, both."""


def surface_force_coefficients(gap: float, effect: str = "both") -> tuple[float, float]:
    """(A, B) of the film force's first-order change f1 = eps sqrt(delta) kappa (A V^2 +
    B dV/dT) (by 6 pi mu V0 a^2 / x0) by the surface term ``effect`` (``EFFECTS``) at the gap
    X (by x0) of the rigid approach (module docstring)."""
    x = checks.number("gap", gap, lower=0.0, upper=1.0, lower_open=True)
    effect = checks.choice("effect", effect, EFFECTS)
    opening = (1 - x) ** 2 * (5 + 4 * x - 3 * x * x) / (2 * x**3)
    velocity = (1 - x) ** 2 * (2 + x) / x**3
    b = 2 * x**3 - 3 * x * x + 2 * x - 1 - 2 * x * x * math.log(x)
    per_term = 1.5 * b / (x * x)
    if effect == "opening":
        return opening, per_term
    if effect == "velocity":
        return velocity, per_term
    return opening + velocity, 2.0 * per_term


def velocity_integral(gap: float, St: float, effect: str = "both") -> float:
    """J(X) = int_X^1 (V0 A - (1 - X')^2 B / (X' St)) dX' in closed form (module docstring):
    V1(X) = -(eps sqrt(delta) kappa / St) J(X) is the first-order change of the sphere's
    velocity (by V0) at the gap X (by x0) by the surface term ``effect``."""
    x = checks.number("gap", gap, lower=0.0, upper=1.0, lower_open=True)
    St = checks.positive("St", St)
    effect = checks.choice("effect", effect, EFFECTS)
    if effect == "both":
        return velocity_integral(x, St, "opening") + velocity_integral(x, St, "velocity")
    log, y = math.log(x), 1.0 / x
    if effect == "opening":
        fixed = -3 * log - 0.75 * x * x + 5 * x - 6 + 3 * y - 1.25 * y * y
        per_st = (
            -3 * log * log
            + log * (-2.25 * x * x + 11 * x - 9.25 + 3 * y - 1.25 * y * y)
            + (-3 / 16 * x**4 + 17 / 6 * x**3 - 11 * x * x + 16 * x - 595 / 48)
            + 6.5 * y
            - 1.75 * y * y
        )
    else:
        fixed = x - 3 + 3 * y - y * y
        per_st = (
            -1.5 * log * log
            + log * (-1.5 * x * x + 7 * x - 5 + 3 * y - y * y)
            + (7 / 6 * x**3 - 5.5 * x * x + 8 * x - 95 / 12)
            + 5.5 * y
            - 1.25 * y * y
        )
    return fixed + per_st / St


def stopping_gap_constant(St: float, kappa: float, effect: str = "both") -> float:
    """c = -kappa J(X_s) / (1 - X_s)^2: the thinnest film's relative change by the surface
    term ``effect`` is c eps sqrt(delta) as eps -> 0 (thin layer, half-spaces, paraboloid, no
    cavitation; module docstring), for the rigid stopping gap X_s of ``St`` and the solids'
    shear coefficient ``kappa``."""
    stop = rigid_film.stopping_gap(St, "thin")
    return -kappa * velocity_integral(stop, St, effect) / (1 - stop) ** 2
