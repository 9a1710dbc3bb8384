"""The lubrication model of CFD-DEM codes with a minimum gap, for two spheres colliding
obliquely (Zhang, Noda & Horio 2005, Powder Technol. 158; Tomac & Gutierrez 2013, Granular
Matter 15; docs/validation.md, "Two spheres obliquely: the reduced CFD-DEM models").

Two rigid spheres approach through a liquid layer: from the gap x0 down to h_min the
lubrication resistances of :mod:`ehdfem.dem.reduced.resistances` act; below h_min they are cut
off (zero, as in the cited codes: the lubrication force acts for h_min < h only) and the solids
touch with Hertz's force (4/3) E* a^(1/2) (h_min - h)^(3/2)
(:func:`ehdfem.exact.hertz.compression_force`, elastic: the pure EHD collision's e_dry = 1)
and Coulomb friction of coefficient mu at the contact point: F_c = -mu F_H sign(u_s) while the
slip u_s = U - s1 - s2 lasts; once it reaches zero it stays there to the parting (friction is
the only tangential force in the touch, so no force is left to make the surfaces slip again:
F_c = 0 holds it, within mu F_H). The pair's equations in the scales of
:mod:`ehdfem.tangential.pair` (time by x0/V0, velocities by V0, forces by 6 pi mu V0 a^2 / x0,
St and the spins' weights by the reduced mass m):

    St dV/dT = -V/H + F_H,         dH/dT = V,
    St dU/dT = F_1 + F_c,
    St k1 (1 + m1/m2) ds1/dT = -(G_1 + F_c),   St k2 (1 + m2/m1) ds2/dT = G_2 - F_c,

(the lubrication terms for H > H_min, F_H and F_c for H < H_min)
from H = 1, V = -1, U = tan(angle) to the exit H = 1 (e_n = V there, e_t = U / U0, the spin
changes by U0) or the stop (the approach or the rebound halts in the layer: e_n = 0). Exact
limits (tests/test_reduced_pair.py): the approach's V(H) = -1 + ln(1/H)/St down to H_min, the
elastic touch, and so e_n = 1 - 2 ln(1/H_min)/St (or 0), the energy balance over both spheres,
Coulomb's impulse law, Hertz's compression and contact time.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import scipy.integrate

from ... import checks
from ...exact.hertz import compression_force
from ...exact.sphere_pair import pair_logarithmic
from ...tangential.pair import SpherePair
from .resistances import normal_force, tangential_forces

TOLERANCES = dict(rtol=1e-10, atol=1e-13)  # DOP853 on every phase
STALL = 1e-7  # |V| below which the normal motion has stopped in the layer (by V0)
LONGEST = 1e5  # the longest phase (by x0/V0): a motion still going then has stopped
PHASES = 10  # at most this many phases (free flight, sliding or sticking contact)


@dataclass(frozen=True)
class ReducedCollision:
    """The scaled inputs of a reduced collision of two spheres: ``St`` m V0/(6 pi mu a^2) and
    ``eps`` 4 theta mu V0 a^(3/2) / x0^(5/2) by the reduced radius a and mass m (> 0),
    ``delta`` x0/a in (0, 1), ``angle`` of the relative impact velocity from the line of
    centres in (0, 90) deg, ``minimum_gap`` H_min = h_min/x0 in (0, 1), the solids'
    ``friction_coefficient`` mu >= 0, the partner ``pair``
    (:class:`ehdfem.tangential.pair.SpherePair`: m1/m2, k1, k2, s2(0) = a2 Omega2 / V0, a1/a2)
    and the upper sphere's initial ``spin`` s1(0) = a1 Omega1 / V0."""

    St: float
    eps: float
    delta: float
    angle: float
    minimum_gap: float
    friction_coefficient: float = 0.0
    pair: SpherePair = field(default_factory=lambda: SpherePair(1.0, 0.4, 0.4))
    spin: float = 0.0

    def __post_init__(self):
        checks.positive("St", self.St)
        checks.positive("eps", self.eps)
        checks.number("delta", self.delta, lower=0.0, upper=1.0, lower_open=True, upper_open=True)
        checks.number("angle", self.angle, lower=0.0, upper=90.0, lower_open=True, upper_open=True)
        checks.number(
            "minimum_gap", self.minimum_gap, lower=0.0, upper=1.0, lower_open=True, upper_open=True
        )
        checks.number("friction_coefficient", self.friction_coefficient, lower=0.0)
        checks.number("spin", self.spin)
        if not isinstance(self.pair, SpherePair):
            raise checks.InputError(f"pair must be a SpherePair, got {self.pair!r}", "pair")

    @property
    def tangential_speed(self) -> float:
        """U0/V0 = tan(angle)."""
        return math.tan(math.radians(self.angle))


@dataclass(frozen=True)
class ReducedOutcome:
    """A reduced collision's outcome (scales of the module docstring): ``e_n`` the relative
    normal restitution (0: stopped in the layer), ``e_t`` U/U0 at the end, the spin changes
    ``upper_spin_change`` a1 (Omega1 - Omega1(0)) / U0 and ``lower_spin_change`` a2 (Omega2 -
    Omega2(0)) / U0; ``stopped`` whether the normal motion halted in the layer; ``impact_speed``
    V at the first touch of H_min and ``rebound_speed`` V when the solids part (None without a
    touch); ``contact_time`` (by x0/V0) and ``max_compression`` (by x0) of the touch;
    ``normal_impulse`` Hertz's and ``friction_impulse`` the friction's on sphere 1 (by m V0);
    ``energy_error`` |E(0) - E - elastic - dissipated| over E(0) - E at the end."""

    e_n: float
    e_t: float
    upper_spin_change: float
    lower_spin_change: float
    stopped: bool
    impact_speed: float | None
    rebound_speed: float | None
    contact_time: float
    max_compression: float
    normal_impulse: float
    friction_impulse: float
    energy_error: float


class _Pair:
    """The equations of the module docstring; the state is (H, V, U, s1, s2, the dissipation
    by the lubrication and by friction, Hertz's and the friction's impulse on sphere 1), the
    dissipations by 6 pi mu V0 a^2 (their rates by 6 pi mu V0^2 a^2 / x0) and the impulses by
    6 pi mu a^2, so that over St they are by m V0^2 and m V0."""

    def __init__(self, inputs: ReducedCollision):
        self.inputs = inputs
        self.resistance = pair_logarithmic(inputs.pair.radius_ratio)
        self.weights = inputs.pair.spin_weights

    def forces(self, y):
        """(F_n or F_H, F_1, (G_1, G_2), lubrication dissipation, F_H, slip): the
        lubrication's above H_min, Hertz's below (the other terms 0)."""
        p = self.inputs
        H, V, U, s1, s2 = y[:5]
        slip = U - s1 - s2
        if H < p.minimum_gap:
            hertz = compression_force(p.eps, p.minimum_gap - H)
            return hertz, 0.0, (0.0, 0.0), 0.0, hertz, slip
        tangential = tangential_forces(H, p.delta, self.resistance, np.array([U, s1, s2]))
        lubrication = V**2 / H + tangential.dissipation
        turning = (tangential.upper_turning, tangential.lower_turning)
        return normal_force(H, V), tangential.upper, turning, lubrication, 0.0, slip

    def rates(self, y, sliding: float):
        """dy/dT with the friction F_c = -mu F_H ``sliding`` (the slip's sign, 0: stuck)."""
        normal, upper, turning, lubrication, hertz, slip = self.forces(y)
        contact = -sliding * self.inputs.friction_coefficient * hertz
        St, (w1, w2) = self.inputs.St, self.weights
        return np.array(
            [
                y[1],
                normal / St,
                (upper + contact) / St,
                -(turning[0] + contact) / (St * w1),
                (turning[1] - contact) / (St * w2),
                lubrication,
                -contact * slip,
                hertz,
                contact,
            ]
        )

    def energy(self, y) -> float:
        """Kinetic energy of both spheres in the centre-of-mass frame plus Hertz's elastic
        energy (by m V0^2)."""
        p = self.inputs
        H, V, U, s1, s2 = y[:5]
        w1, w2 = self.weights
        kinetic = 0.5 * (V**2 + U**2 + w1 * s1**2 + w2 * s2**2)
        compression = max(p.minimum_gap - H, 0.0)
        elastic = 0.4 * compression * compression_force(p.eps, compression) / p.St
        return kinetic + elastic


def reduced_collision(inputs: ReducedCollision) -> ReducedOutcome:
    """Integrate the reduced collision ``inputs`` (module docstring) phase by phase: free
    flight (no contact), a sliding contact (F_c = -mu F_H sign of the slip) or a stuck one
    (F_c = 0, the slip at zero), each by DOP853 to the event that ends it (rtol 1e-10)."""
    pair = _Pair(inputs)
    y = np.array([1.0, -1.0, inputs.tangential_speed, inputs.spin, inputs.pair.lower_spin])
    y = np.concatenate((y, np.zeros(4)))
    start_energy, phase, sign = pair.energy(y), "free", 0.0
    record = dict(impact_speed=None, rebound_speed=None, contact_time=0.0, max_compression=0.0)
    stopped = False
    for _ in range(PHASES):
        solution, events = _phase(pair, y, phase, sign)
        y = solution.y[:, -1]
        found = zip(events, solution.t_events, strict=True)
        ended = {event.__name__ for event, times in found if len(times)}
        if phase != "free":
            record["contact_time"] += solution.t[-1] - solution.t[0]
            turns = [z[0] for located in solution.y_events for z in located]  # V = 0 among them
            lowest = inputs.minimum_gap - min(solution.y[0].min(), *turns)
            record["max_compression"] = max(record["max_compression"], lowest)
        if solution.status == 0 or "stall" in ended:
            stopped = True  # the longest phase passed, or the normal motion stalled
            break
        if "leave" in ended:
            break  # left the layer
        phase, sign = _next_phase(pair, y, phase, ended, record)
    else:
        raise RuntimeError(f"the reduced collision took more than {PHASES} phases")
    return _outcome(inputs, pair, y, start_energy, stopped, record)


def _phase(pair: _Pair, y, phase: str, sign: float):
    """One phase from ``y``, by DOP853 to the first of its terminal events (free: the touch,
    the exit, the stall |V| = STALL; in contact: the parting, and while sliding the slip at
    zero), the turn V = 0 recorded; the solution and the events."""
    p = pair.inputs

    def touch(_, z):
        return z[0] - p.minimum_gap

    touch.terminal, touch.direction = True, -1.0 if phase == "free" else 1.0
    events = [touch]
    if phase == "free":

        def leave(_, z):
            return z[0] - 1.0

        def stall(_, z):
            return abs(z[1]) - STALL

        leave.terminal, leave.direction = True, 1.0
        stall.terminal, stall.direction = True, -1.0
        events += [leave, stall]
    else:

        def turn(_, z):  # the deepest compression, not terminal
            return z[1]

        events.append(turn)
    sliding = sign if phase == "slide" else 0.0
    if sliding != 0.0 and p.friction_coefficient > 0.0:

        def slip_stops(_, z):
            return z[2] - z[3] - z[4]

        slip_stops.terminal, slip_stops.direction = True, -sliding  # towards zero
        events.append(slip_stops)
    rates = lambda _, z: pair.rates(z, sliding)  # noqa: E731
    solution = scipy.integrate.solve_ivp(
        rates, (0.0, LONGEST), y, method="DOP853", events=events, **TOLERANCES
    )
    return solution, events


def _next_phase(pair: _Pair, y, phase: str, ended, record) -> tuple[str, float]:
    """The phase after ``phase`` ended by the events ``ended`` at ``y``, and the sign of the
    slip a sliding phase opposes; records the touch and the parting speeds."""
    if phase == "free":  # the touch: slide unless the slip is already zero
        record["impact_speed"] = record["impact_speed"] or float(y[1])
        slip = y[2] - y[3] - y[4]
        if abs(slip) > 1e-9 * pair.inputs.tangential_speed:
            return "slide", float(np.sign(slip))
        return "stick", 0.0
    if "touch" in ended:  # the solids part
        record["rebound_speed"] = float(y[1])
        return "free", 0.0
    return "stick", 0.0  # the slip reached zero


def _outcome(inputs, pair, y, start_energy, stopped, record) -> ReducedOutcome:
    """The :class:`ReducedOutcome` at the final state ``y``."""
    tangent = inputs.tangential_speed
    lost = start_energy - pair.energy(y)
    dissipated = (y[5] + y[6]) / inputs.St
    return ReducedOutcome(
        e_n=0.0 if stopped else float(y[1]),
        e_t=float(y[2] / tangent),
        upper_spin_change=float((y[3] - inputs.spin) / tangent),
        lower_spin_change=float((y[4] - inputs.pair.lower_spin) / tangent),
        stopped=stopped,
        impact_speed=record["impact_speed"],
        rebound_speed=record["rebound_speed"],
        contact_time=float(record["contact_time"]),
        max_compression=float(record["max_compression"]),
        normal_impulse=float(y[7] / inputs.St),
        friction_impulse=float(y[8] / inputs.St),
        energy_error=float(abs(lost - dissipated) / lost) if lost > 0 else 0.0,
    )
