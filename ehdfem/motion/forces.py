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

from collections.abc import Callable
from dataclasses import dataclass, field, replace
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
    energy (for an asperity load, the energy stored in the asperities). ``advance``: the force
    for the steps after an accepted state (the time stepper calls it at each accepted step and
    again after a velocity jump at the same time): itself for a force of the present state, the
    force with its memory moved on for a force of the past motion (:class:`HistoryForce`).
    """

    def value(self, state: SphereState) -> float: ...

    def derivatives(self, state: SphereState) -> tuple[float, float]: ...

    def work(self, state: SphereState) -> float: ...

    def advance(self, state: SphereState) -> SphereForce: ...


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

    def advance(self, state: SphereState) -> ConstantForce:
        return self


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


def memory_gains(step: float, relaxation_times) -> tuple[np.ndarray, np.ndarray]:
    """(e^(-dt/tau_i), (tau_i/dt)(1 - e^(-dt/tau_i))): over a step dt >= 0 the memory of a
    velocity linear in time moves as z_i -> z_i e^(-dt/tau_i) + (v_new - v_old)(tau_i/dt)
    (1 - e^(-dt/tau_i)), the exact solution of dz_i/dt = -z_i/tau_i + dv/dt; a jump (dt = 0)
    adds v_new - v_old (gain 1). dt and tau_i in one time unit (SI or scaled alike)."""
    tau = np.asarray(relaxation_times, dtype=float)
    gain = np.where(step > 0, -np.expm1(-step / tau) * tau / max(step, 1e-300), 1.0)
    return np.exp(-step / tau), gain


@dataclass(frozen=True)
class HistoryForce:
    """The history (Basset) force of the liquid around the film on the sphere, with the memory
    of its whole past motion, as a sum of exponentials (scaled; the kernel and its weights are
    the caller's, e.g. :mod:`ehdfem.bounce.unsteady` for a sphere in flight):

        F_H = -k sum_i w_i(V) Z_i,     dZ_i/dT = -Z_i / T_i + dV/dT,

    k = x0 / a (F_H = -6 pi mu a sum_i w_i z_i [N] by the force scale 6 pi mu V0 a^2 / x0, with
    Z_i = z_i / V0), T_i = tau_i V0 / x0 the relaxation times by the time scale, ``weights`` the
    callable V -> w_i (dimensionless, e.g. at the Reynolds number of the velocity V by V0).
    ``memory`` Z_i (by V0) at the accepted state (``time``, ``velocity``; at first touch T = 0,
    V = -1 the memory the sphere brings from its flight), ``work_done`` its work on the sphere
    up to there (by m V0^2 / St). Between accepted states the memory is advanced exactly for V
    linear in time (:func:`memory_gains`), so F_H at a step's end is linear in its velocity:
    dF/dV = -k w.gain (the weights' own change with V is left out of the Newton matrix; the
    residual holds the force in full), dF/dX = 0. Its work is integrated by the trapezoidal
    rule over the accepted steps (a velocity jump does none: the force stays finite)."""

    scale: float
    relaxation_times: np.ndarray
    weights: Callable[[float], np.ndarray]
    memory: np.ndarray
    time: float = 0.0
    velocity: float = -1.0  # V at first touch (ehdfem.motion.sphere.IMPACT_VELOCITY)
    work_done: float = 0.0
    parameter: ClassVar[str] = "history_force"
    _value: float = field(init=False, repr=False, compare=False)

    def __post_init__(self):
        checks.positive(f"{self.parameter}.scale", self.scale)
        times = np.asarray(self.relaxation_times, dtype=float)
        if times.ndim != 1 or np.any(times <= 0) or np.shape(self.memory) != times.shape:
            raise checks.InputError(
                f"{self.parameter}: relaxation_times must be positive, one per memory entry "
                f"(got {times.shape} times and {np.shape(self.memory)} memories)"
            )
        if not callable(self.weights):
            raise checks.InputError(f"{self.parameter}.weights must be callable V -> w_i")
        object.__setattr__(self, "_value", self._force(self.velocity, self.memory))

    def _force(self, velocity: float, memory) -> float:
        return -self.scale * float(self.weights(velocity) @ memory)

    def _memory_at(self, state: SphereState) -> tuple[np.ndarray, np.ndarray]:
        """Z_i at ``state`` and the gains of the velocity change since the accepted state."""
        decay, gain = memory_gains(state.time - self.time, self.relaxation_times)
        return self.memory * decay + (state.velocity - self.velocity) * gain, gain

    def value(self, state: SphereState) -> float:
        return self._force(state.velocity, self._memory_at(state)[0])

    def derivatives(self, state: SphereState) -> tuple[float, float]:
        gain = self._memory_at(state)[1]
        return 0.0, -self.scale * float(self.weights(state.velocity) @ gain)

    def work(self, state: SphereState) -> float:
        power = self._value * self.velocity + self.value(state) * state.velocity
        return self.work_done + 0.5 * power * (state.time - self.time)

    def advance(self, state: SphereState) -> HistoryForce:
        memory = self._memory_at(state)[0]
        return replace(
            self,
            memory=memory,
            time=state.time,
            velocity=state.velocity,
            work_done=self.work(state),
        )
