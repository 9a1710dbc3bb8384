"""The sphere's normal motion: its equation, its rows of the implicit step and its energies.

Scaled as in :mod:`ehdfem.motion.normal`: gap X by x0, velocity V by V0 (< 0 while approaching),
time T by x0/V0, pressure P by mu V0 a / x0^2 at the film nodes, force by 6 pi mu V0 a^2 / x0,
energy by m V0^2 / St. The sphere obeys

    St dV/dT = F_film + sum_i F_i(X, V, T, H),     dX/dT = V,     X(0) = 1, V(0) = -1,

with the film's force F_film = f . P (f the film state's force weights, (1/3) int P R dR) and
the applied forces F_i (:class:`ehdfem.motion.forces.SphereForce`, positive away from the
wall). With a BDF formula dy/dT ~ (a0 y + past_y) / dt (:mod:`ehdfem.motion.timestepping`) its
rows of the implicit step (:mod:`ehdfem.motion.implicit_step`) are

    a0 X + past_X - dt V = 0,     St (a0 V + past_V) - dt (f . P + sum_i F_i) = 0.

Its energy balance: kinetic St V^2 / 2 + elastic + dissipated - sum_i W_i = St / 2, with W_i the
work of the applied forces (:mod:`ehdfem.motion.history`).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

import numpy as np

from .. import checks
from .forces import BuoyantWeight, ConstantForce, SphereForce, SphereState

if TYPE_CHECKING:
    from ..inputs.scales import CollisionParameters

IMPACT_VELOCITY = -1.0  # V at first touch (by V0, towards the wall)


@dataclass(frozen=True)
class Sphere:
    """The sphere's equation of motion (module docstring): Stokes number St > 0 and the
    applied forces (a tuple of :class:`ehdfem.motion.forces.SphereForce`)."""

    St: float
    forces: tuple[SphereForce, ...] = ()

    def __post_init__(self):
        checks.positive("St", self.St)
        if not isinstance(self.forces, tuple):
            raise checks.InputError(f"forces must be a tuple of forces, got {self.forces!r}")

    @classmethod
    def of(cls, params: CollisionParameters, forces: tuple[SphereForce, ...] = ()) -> Sphere:
        """The sphere of the collision ``params``: St, the external force and the buoyant
        weight (each only when not zero), then the further ``forces`` (e.g. a
        :class:`ehdfem.motion.forces.HistoryForce` built by the caller)."""
        if not isinstance(forces, tuple):
            raise checks.InputError(f"forces must be a tuple of forces, got {forces!r}")
        applied = []
        if params.external_force != 0.0:
            applied.append(ConstantForce(params.external_force))
        if params.buoyant_weight != 0.0:
            applied.append(BuoyantWeight.of(params.buoyant_weight))
        return cls(params.St, (*applied, *forces))

    def advanced(self, state: SphereState) -> Sphere:
        """The sphere for the steps after the accepted ``state``: each force's
        :meth:`ehdfem.motion.forces.SphereForce.advance` (a force of the past motion moves its
        memory on; the others stay)."""
        forces = tuple(force.advance(state) for force in self.forces)
        if all(new is old for new, old in zip(forces, self.forces, strict=True)):
            return self
        return replace(self, forces=forces)

    def applied_force(self, state: SphereState) -> float:
        """sum_i F_i at the state (by 6 pi mu V0 a^2 / x0)."""
        return sum((force.value(state) for force in self.forces), 0.0)

    def residual(self, step, a0, past, state: SphereState, film_force: float):
        """(r_X, r_V) = (a0 X + past_X - dt V, St (a0 V + past_V) - dt (F_film + sum_i F_i))
        for ``past`` = (past_X, past_V) and the film's force F_film = f . P."""
        gap_past, velocity_past = past
        r_gap = a0 * state.gap + gap_past - step * state.velocity
        force = film_force + self.applied_force(state)
        return r_gap, self.St * (a0 * state.velocity + velocity_past) - step * force

    def jacobian_rows(self, step, a0, state: SphereState, force_weights) -> np.ndarray:
        """The two rows d(r_X, r_V)/d(P, X, V) ((2, n + 2)): (0, a0, -dt) and
        (-dt f, -dt sum dF_i/dX, St a0 - dt sum dF_i/dV)."""
        n = len(force_weights)
        rows = np.zeros((2, n + 2))
        rows[0, n], rows[0, n + 1] = a0, -step
        rows[1, :n] = -step * force_weights
        rows[1, n + 1] = self.St * a0
        for force in self.forces:
            d_gap, d_velocity = force.derivatives(state)
            rows[1, n] -= step * d_gap
            rows[1, n + 1] -= step * d_velocity
        return rows

    def kinetic_energy(self, velocity: float) -> float:
        """St V^2 / 2 (by m V0^2 / St)."""
        return 0.5 * self.St * velocity**2

    def work(self, state: SphereState) -> float:
        """The applied forces' work on the sphere since first touch, sum_i W_i (by m V0^2 / St)."""
        return sum((force.work(state) for force in self.forces), 0.0)

    @staticmethod
    def left_layer(gap: float, velocity: float, exit_gap: float) -> bool:
        """The exit: the gap is back at ``exit_gap`` (by x0: the layer surface X = 1, or a larger
        exit from an immersed film, :attr:`ehdfem.motion.timestepping.IntegratorOptions.exit_gap`),
        X >= exit_gap, with V > 0."""
        return gap >= exit_gap and velocity > 0
