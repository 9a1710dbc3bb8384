"""Forces on the sphere in its normal motion, besides the film's (scaled).

Scaled as in :mod:`ehdfem.motion.normal`: force by 6 pi mu V0 a^2 / x0 (so that St dV/dT = F),
gap X and film thickness H by x0, velocity V by V0, time T by x0/V0, work by m V0^2 / St (the
force scale times x0, so a scaled force F moving the sphere by dX does the work F dX). Sign: a
positive force pushes the sphere away from the wall (it raises V; V < 0 while approaching).

The film's own force, F_film = (1/3) int P R dR = f . P, stays with the film: its weights f are
the assembled film's (:attr:`ehdfem.film.reynolds.FilmState.force_weights`, with the immersed
far field's share), and its work is the elastic energy and the dissipation of the balance
(:mod:`ehdfem.motion.history`). The sphere's equation of motion, which sums them, is
:class:`ehdfem.motion.sphere.Sphere`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar, Protocol

import numpy as np

from .. import checks

LAYER_SURFACE = 1.0  # the gap X at first touch of the layer and at exit (by x0)


@dataclass(frozen=True)
class SphereState:
    """The sphere and its film at one instant (scaled): time T, gap X between the undeformed
    surfaces on the axis, velocity V and the film thickness H at the film nodes."""

    time: float
    gap: float
    velocity: float
    film_thickness: np.ndarray


class SphereForce(Protocol):
    """A force applied to the sphere (scaled by 6 pi mu V0 a^2 / x0, positive away from the
    wall), one class per physical role.

    ``value``: F at the state. ``derivatives``: (dF/dX, dF/dV), the force's entries in the
    Newton matrix of the implicit step. A force of the film thickness, such as an asperity
    contact load F(X, H_min), gives in dF/dX its total derivative at fixed pressure,
    dF/dX + dF/dH_min (H = X + S(R) + C P, so dH/dX = 1 at every node); its dependence on the
    pressure through C P is left out of the Newton matrix (the simplified Newton still
    converges while the residual holds the force in full). ``work``: the work done on the
    sphere since first touch of the layer (T = 0, X = 1), by m V0^2 / St: F (X - 1) for a
    constant force; a conservative force of the gap gives minus the change of its potential
    energy (for an asperity load, the energy stored in the asperities).
    """

    def value(self, state: SphereState) -> float: ...

    def derivatives(self, state: SphereState) -> tuple[float, float]: ...

    def work(self, state: SphereState) -> float: ...


@dataclass(frozen=True)
class ConstantForce:
    """A constant external force F_ext on the sphere (scaled by 6 pi mu V0 a^2 / x0, positive
    away from the wall): value F_ext, no derivatives, work F_ext (X - 1)."""

    force: float
    parameter: ClassVar[str] = "external_force"  # how an input error names the force

    def __post_init__(self):
        checks.number(self.parameter, self.force)

    def value(self, state: SphereState) -> float:
        return self.force

    def derivatives(self, state: SphereState) -> tuple[float, float]:
        return 0.0, 0.0

    def work(self, state: SphereState) -> float:
        return self.force * (state.gap - LAYER_SURFACE)


@dataclass(frozen=True)
class BuoyantWeight(ConstantForce):
    """Gravity with buoyancy: the sphere's weight less the weight of the fluid it displaces,
    (m - rho_f V_s) g, which pushes it towards the wall. Scaled, F = -W with
    W = (m - rho_f V_s) g x0 / (6 pi mu V0 a^2) (= St (g x0 / V0^2)(1 - rho_f / rho_s) for a
    uniform sphere); W < 0 (a sphere lighter than the fluid) pulls it away. Build it with
    :meth:`of` from W (:attr:`ehdfem.inputs.scales.PhysicalCollision.scaled_buoyant_weight`
    forms W from SI inputs)."""

    parameter: ClassVar[str] = "buoyant_weight"

    @classmethod
    def of(cls, weight: float) -> BuoyantWeight:
        """The force -W of the scaled buoyant weight W (towards the wall when W > 0)."""
        return cls(-checks.number(cls.parameter, weight))
