"""Coulomb friction of the solid contact: the asperities' collision and their share of the load.

Conventions of :mod:`ehdfem.tangential.motion`: U the centre's tangential velocity and a Omega
the spin (both by U0), the slip of the contact point u_s = U - a Omega, k = I/(m a^2). A
tangential impulse J on the sphere at the contact (by 6 pi mu a^2 U0 / V0, the tangential force
scale times the time scale x0/V0) changes

    St dU = J,    k St d(a Omega) = -J,    so    d u_s = (1 + 1/k) J / St.

Coulomb's law bounds it by the normal impulse N of the solid contact (by 6 pi mu a^2, the
normal force scale times x0/V0): |J| <= (mu / tan(angle)) N, since U0 / V0 = tan(angle). The
impulse that would stop the slip is J_stop = -St u_s / (1 + 1/k); the contact takes

    J = clip(J_stop, -bound, bound)     (:func:`coulomb_impulse`):

it stops sliding and rolls (sticks) when |J_stop| <= bound, and slides throughout otherwise,
J = -bound sign(u_s). This projection is exact for a rigid-body impact (the normal impulse
builds up while the friction opposes a slip of constant sign, and a sphere on a plane has no
coupling of the normal and tangential impulses), and is the implicit (Moreau) treatment of the
mixed model's friction per step: no regularisation, and the contact point stops exactly.

With the normal approach velocity |V| and psi = u_s U0 / (|V| V0) (tangential contact velocity
over the normal approach velocity) the impact with restitution e_n (N = St (1 + e_n) |V|) gives
:func:`ehdfem.exact.rigid_impact.frictional_impact`:

    psi_out = psi_in - (1 + 1/k) mu (1 + e_n) sign(psi_in)  if |psi_in| > (1 + 1/k) mu (1 + e_n),
    psi_out = 0                                             otherwise (stick, rolling).

Friction dissipation of one impulse (by m U0^2 / St, as the tangential energies): the kinetic
energy (St/2)(U^2 + k (a Omega)^2) falls by D = -J (u_s + u_s') / 2 >= 0, u_s' the slip after
it (same sign as u_s, or 0).

Where the solid contact acts: at the step ``index`` of the normal solution's
:class:`ehdfem.motion.normal.SolidImpact` (the impact model: N its normal impulse, a jump of U
and a Omega at that step), and over each step with the asperities' load F_a of the mixed model
(``NormalResult.asperity_force``, by 6 pi mu V0 a^2 / x0). How the film's integrator takes
them (:mod:`ehdfem.tangential.motion`):

- the one-step models (couette, flat: exact; gcb: exact exponential per step) apply the
  contact's impulse after each film step (:meth:`CoulombContact.act`), with N = int F_a dT over
  the step by the trapezoid rule plus the impact's normal impulse at its step: the Moreau
  time-stepping of a frictional contact, first order in the step;
- the sliding film (BDF2, a multistep method that would carry an impulse of one step into the
  next) takes the asperities' friction as a force inside its implicit step, F_f in
  -(mu / tan(angle)) F_a Sign(u_s) at the step's end (:meth:`CoulombContact.resist`: the
  step's solution is linear in F_f, so the complementarity is one scalar projection), and the
  impact as a jump after its step, followed by a BDF1 step. Its friction dissipation is then
  the trapezoid of -F_f u_s plus the impact's D.

With a tangential compliance (``tangential_compliance`` > 0, the impact model only) the solid
impact's jump is the compliant contact's (:mod:`ehdfem.tangential.compliant_contact`: the
impulse that takes psi_in to its psi_out, with the same dissipation D) in place of the
projection; an asperity load keeps Coulomb's law.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.integrate

from ..motion.normal import NormalResult
from .compliant_contact import compliant_rebound


def coulomb_impulse(slip: float, bound: float, St: float, k: float) -> tuple[float, bool]:
    """(J, stuck): the Coulomb impulse on a sphere slipping at ``slip`` (u_s by U0) with the
    friction impulse at most ``bound`` (by 6 pi mu a^2 U0 / V0), St and k as in the module
    docstring: the projection of the stopping impulse -St u_s / (1 + 1/k) onto [-bound, bound];
    ``stuck`` when the slip stops (then u_s after it is 0)."""
    stopping = -St * slip / (1.0 + 1.0 / k)
    stuck = abs(stopping) <= bound
    return (stopping if stuck else -bound * np.sign(slip)), bool(stuck)


@dataclass(frozen=True)
class ContactFriction:
    """The Coulomb friction of a collision's solid contact, at the normal solution's steps
    (scaled as in the module docstring): ``impulse`` J of each step (by 6 pi mu a^2 U0 / V0),
    ``dissipated`` the friction dissipation so far (by m U0^2 / St, >= 0 and rising), ``stuck``
    whether the contact stopped sliding at the step (rolling). ``impact_psi``: (psi_in,
    psi_out) at the solid impact (the contact-point velocity over that impact's approach
    velocity, before and after it; None without an impact)."""

    impulse: np.ndarray
    dissipated: np.ndarray
    stuck: np.ndarray
    impact_psi: tuple[float, float] | None

    @property
    def any_stuck(self) -> bool:
        """The contact stopped sliding at some step (the slip was stopped by friction)."""
        return bool(self.stuck.any())


class CoulombContact:
    """The friction bounds of each step of a normal solution and the friction taken, by a
    tangential model as impulses after its steps (:meth:`act`) or as a force inside them
    (:meth:`resist`)."""

    def __init__(self, normal: NormalResult):
        params, hist = normal.params, normal.history
        self.St, self.k, self.tangent = params.St, params.inertia_factor, params.tangential_speed
        self.time = np.asarray(hist.time, dtype=float)
        steps = len(self.time)
        per_load = params.friction_coefficient / self.tangent  # |J| <= per_load N
        force = np.zeros(steps)
        if normal.asperity_force is not None:
            force = np.asarray(normal.asperity_force, dtype=float)
        self.force_bounds = per_load * force
        self.load_bounds = np.zeros(steps)
        self.load_bounds[1:] = 0.5 * (self.force_bounds[1:] + self.force_bounds[:-1])
        self.load_bounds[1:] *= np.diff(self.time)
        self.impact = normal.solid_impact
        self.impact_bound = 0.0 if self.impact is None else per_load * self.impact.normal_impulse
        self.friction, self.compliance = params.friction_coefficient, params.tangential_compliance
        self.impulse, self.loss, self.rate = np.zeros(steps), np.zeros(steps), np.zeros(steps)
        self.stuck = np.zeros(steps, bool)
        self.impact_psi = None

    @classmethod
    def of(cls, normal: NormalResult) -> CoulombContact | None:
        """The contact of ``normal``, or None where it has no friction: mu = 0, no solid contact
        (no asperity load and no solid impact), or a head-on impact. Then the tangential models
        run exactly as without it."""
        params = normal.params
        rough = normal.asperity_force is not None or normal.solid_impact is not None
        if params.friction_coefficient == 0.0 or not rough or params.tangential_speed == 0.0:
            return None
        return cls(normal)

    def is_impact(self, step: int) -> bool:
        """Step ``step`` holds the solid impact (U and a Omega jump there)."""
        return self.impact is not None and self.impact.index == step

    def act(self, step: int, velocity: float, spin: float, load=True) -> tuple[float, float]:
        """(U, a Omega) after the contact's impulse at ``step`` on the state (U, a Omega) the
        film left there (by U0): the impact's, and with ``load`` the asperities' over the step
        ending there; records the impulse, its dissipation and whether it stuck."""
        compliant = self.compliance > 0.0 and self.is_impact(step)
        if compliant:  # the impact by the compliant law, then the load's Coulomb impulse
            velocity, spin = self._compliant_impact(step, velocity, spin)
        bound = self.impact_bound if self.is_impact(step) and not compliant else 0.0
        if load:
            bound += self.load_bounds[step]
        slip = velocity - spin
        impulse, stuck = coulomb_impulse(slip, bound, self.St, self.k)
        after = 0.0 if stuck else slip + (1.0 + 1.0 / self.k) * impulse / self.St
        self.impulse[step] += impulse
        self.loss[step] += -0.5 * impulse * (slip + after)
        self.stuck[step] |= stuck and bound > 0.0
        if self.is_impact(step) and not compliant:  # psi per unit slip: tan(angle) / |V|
            ratio = self.tangent / abs(self.impact.approach_velocity)
            self.impact_psi = (float(slip * ratio), float(after * ratio))
        if stuck:  # rolling: U = a Omega exactly, U + k a Omega conserved
            rolling = (velocity + self.k * spin) / (1.0 + self.k)
            return rolling, rolling
        return velocity + impulse / self.St, spin - impulse / (self.k * self.St)

    def _compliant_impact(self, step: int, velocity: float, spin: float) -> tuple[float, float]:
        """(U, a Omega) after the solid impact at ``step`` with tangential compliance
        (:func:`ehdfem.tangential.compliant_contact.compliant_rebound`, restitution
        e = N / (St |V|) - 1 of the impact's normal impulse N); records its impulse
        J = St (u_s' - u_s) / (1 + 1/k), its dissipation -J (u_s + u_s') / 2, psi and the stop
        of the slip."""
        slip, approach = velocity - spin, abs(self.impact.approach_velocity)
        e_n = self.impact.normal_impulse / (self.St * approach) - 1.0
        ratio = self.tangent / approach  # psi per unit slip
        psi_out, stopped = compliant_rebound(
            slip * ratio, self.friction, e_n, self.compliance, self.k
        )
        after = psi_out / ratio
        impulse = self.St * (after - slip) / (1.0 + 1.0 / self.k)
        self.impulse[step] += impulse
        self.loss[step] += -0.5 * impulse * (slip + after)
        self.stuck[step] |= stopped
        self.impact_psi = (float(slip * ratio), float(psi_out))
        return velocity + impulse / self.St, spin - impulse / (self.k * self.St)

    def resist(self, step: int, slip: float, response: float) -> float:
        """The asperities' friction force F_f at ``step`` (by 6 pi mu a^2 U0 / x0) inside an
        implicit step whose slip is ``slip`` + ``response`` F_f (``response`` > 0: the film's
        step solved for F_f = 0 and its change per unit F_f): F_f stops the slip if it can
        within mu F_a / tan(angle), else F_f = -mu F_a sign(u_s) / tan(angle). Records the
        impulse F_f dT over the step, the dissipation rate -F_f u_s >= 0 and the stick."""
        bound = self.force_bounds[step]
        stopping = -slip / response
        stuck = abs(stopping) <= bound
        force = stopping if stuck else -bound * np.sign(slip)
        self.impulse[step] += force * (self.time[step] - self.time[step - 1])
        self.rate[step] = -force * (slip + response * force)
        self.stuck[step] |= bool(stuck) and bound > 0.0
        return float(force)

    def record(self) -> ContactFriction:
        """The friction of the collision so far (:class:`ContactFriction`)."""
        resisted = scipy.integrate.cumulative_trapezoid(self.rate, self.time, initial=0.0)
        return ContactFriction(
            self.impulse.copy(), np.cumsum(self.loss) + resisted, self.stuck.copy(), self.impact_psi
        )
