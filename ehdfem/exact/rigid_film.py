"""The rigid sphere's squeeze film, exact (scaled as DSH 1986: gap X and film thickness H by
x0, radius R by sqrt(a x0), velocity V by V0, pressure by mu V0 a / x0^2, force by
6 pi mu V0 a^2 / x0).

With H = X + R^2/2 the quasi-steady film pressure of a sphere approaching at V < 0 is
P = 3 |V| (1/H^2 - 1) in a thin layer (P = 0 where H = 1, the layer surface) and
P = 3 |V| / H^2 fully immersed. The force (1/3) int P R dR = |V| g(X) with

    g(X) = 1/X - 2 + X   (thin),      g(X) = 1/X   (immersed).

St dV/dX = -g(X) from X = 1 at V = -1 gives the speed lost, St times
:func:`velocity_loss`, ln(1/X) - 3/2 + 2X - X^2/2 thin and ln(1/X) immersed; the sphere stops
where that equals St (:func:`stopping_gap`).
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq

from .. import checks

LAYERS = ("thin", "immersed")


def pressure(film_thickness, velocity: float, layer: str):
    """P at the film thickness H (by x0) of a rigid sphere moving at ``velocity`` V (by V0,
    negative approaching): 3 |V| (1/H^2 - 1) thin (zero beyond H = 1), 3 |V| / H^2 immersed
    (by mu V0 a / x0^2)."""
    h = np.asarray(film_thickness, dtype=float)
    if checks.choice("layer", layer, LAYERS) == "immersed":
        return 3.0 * abs(velocity) / h**2
    return np.where(h < 1.0, 3.0 * abs(velocity) * (1.0 / h**2 - 1.0), 0.0)


def force_coefficient(gap, layer: str):
    """g(X) with the film force |V| g(X) at the gap X (by x0): 1/X - 2 + X thin, 1/X
    immersed (module docstring)."""
    x = np.asarray(gap, dtype=float)
    if checks.choice("layer", layer, LAYERS) == "immersed":
        return 1.0 / x
    return 1.0 / x - 2.0 + x


def velocity_loss(gap, layer: str):
    """St times the speed a rigid sphere has lost when its gap has closed from 1 to X (gap by
    x0, speed by V0): int_X^1 g dX, ln(1/X) immersed and ln(1/X) - 3/2 + 2X - X^2/2 thin."""
    gap = np.asarray(gap, dtype=float)
    if checks.choice("layer", layer, LAYERS) == "immersed":
        return -np.log(gap)
    return -np.log(gap) - 1.5 + 2.0 * gap - 0.5 * gap**2


def velocity(gap: float, St: float, layer: str = "thin") -> float:
    """V(X) = -1 + velocity_loss(X) / St: the rigid sphere's velocity (by V0) at the gap X
    (by x0, 0 < X <= 1) on its approach from X = 1 at V = -1."""
    x = checks.number("gap", gap, lower=0.0, upper=1.0, lower_open=True)
    St = checks.positive("St", St)
    return -1.0 + float(velocity_loss(x, layer)) / St


def stopping_gap(St: float, layer: str) -> float:
    """The gap (by x0) where a rigid sphere stops: velocity_loss(X) = St, exp(-St) immersed;
    the thin layer's root by bisection in ln X (about exp(-St - 3/2); 0 where that is below
    the smallest float)."""
    St = checks.positive("St", St)
    if checks.choice("layer", layer, LAYERS) == "immersed":
        return math.exp(-St)
    if St > 700.0:
        return 0.0

    def excess(log_gap):
        return float(velocity_loss(math.exp(log_gap), layer)) - St

    return math.exp(brentq(excess, -St - 2.0, 0.0, xtol=1e-15, rtol=1e-15))


def rough_critical_stokes(roughness: float, e_dry: float, layer: str) -> float:
    """St_c of a rigid rough sphere: its asperities (height ``roughness`` sigma, by x0) end
    the approach at X = sigma with the speed 1 - L/St, L = velocity_loss(sigma); the impact
    returns e_dry of it, and the rebound to X = 1 loses L/St again, so e_n = e_dry (1 - L/St)
    - L/St and the sphere leaves the layer from St_c = (1 + 1/e_dry) L."""
    sigma = checks.number("roughness", roughness, lower=0.0, upper=1.0, lower_open=True)
    e_dry = checks.number("e_dry", e_dry, lower=0.0, upper=1.0, lower_open=True)
    return (1.0 + 1.0 / e_dry) * float(velocity_loss(sigma, layer))
