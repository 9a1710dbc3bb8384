"""The EHD minimum film of Nijssen, Ottens & Padding (2022) as the minimum gap of the
lubrication model (docs/validation.md, "Two spheres obliquely: the reduced CFD-DEM models").

Instead of a fixed cut-off, the lubrication force of :mod:`ehdfem.dem.reduced.lubrication`
stops growing at the film an elastohydrodynamic collision keeps between the solids,

    h_eps = 0.37 ((mu v / E*)^2 a^3)^(1/5),   1/E* = sum (1 - nu^2)/E,

the Davis, Serayssol & Hinch (1986) scaling x0 eps^(2/5) of the thinnest film with the
prefactor Nijssen et al. use; v is the relative normal impact speed and a the reduced radius.
With 1/E* = pi theta and eps = 4 theta mu V0 a^(3/2) / x0^(5/2), the scaled minimum gap is

    H_eps = h_eps / x0 = 0.37 (pi eps / 4)^(2/5),

independent of the layer's thickness x0 once eps is given. Below it the solids touch with
Hertz's force and Coulomb friction, as in the lubrication model.
"""

from __future__ import annotations

import math
from dataclasses import replace

from ... import checks
from .lubrication import ReducedCollision, ReducedOutcome, reduced_collision

PREFACTOR = 0.37  # Nijssen, Ottens & Padding (2022)


def ehd_film_thickness(viscosity: float, speed: float, modulus: float, radius: float) -> float:
    """h_eps [m] for the liquid's ``viscosity`` mu [Pa s], the normal impact ``speed`` v [m/s],
    the contact ``modulus`` E* [Pa] and the (reduced) ``radius`` a [m] (module docstring)."""
    for name, value in (("viscosity", viscosity), ("speed", speed), ("modulus", modulus)):
        checks.positive(name, value)
    checks.positive("radius", radius)
    return PREFACTOR * ((viscosity * speed / modulus) ** 2 * radius**3) ** 0.2


def ehd_minimum_gap(eps: float) -> float:
    """H_eps = 0.37 (pi eps / 4)^(2/5), h_eps by x0, for the elasticity parameter ``eps``."""
    return PREFACTOR * (math.pi * checks.positive("eps", eps) / 4.0) ** 0.4


def ehd_gap_collision(inputs: ReducedCollision) -> ReducedOutcome:
    """The lubrication model's collision ``inputs`` with its minimum gap set to
    :func:`ehd_minimum_gap` at ``inputs.eps`` (its own ``minimum_gap`` is replaced); refused
    when H_eps >= 1, a film thicker than the layer."""
    gap = ehd_minimum_gap(inputs.eps)
    if gap >= 1.0:
        raise checks.InputError(
            f"the EHD minimum film H_eps = {gap:.3g} x0 at eps = {inputs.eps!r} is not thinner "
            "than the layer (the model needs eps < 4/pi 0.37^(-5/2) = 15.3)",
            "eps",
        )
    return reduced_collision(replace(inputs, minimum_gap=gap))
