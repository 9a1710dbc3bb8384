"""The flight of a sphere through a liquid towards and away from a wall, between its contacts
(docs/bounce.md): the force laws, the equation of motion and its integration, and the hand-over
criterion to the film model of the contacts.

All quantities are SI: gap h [m] between the sphere's lowest point and the wall (the centre's
height minus the radius a), velocity v = dh/dt [m/s] (positive away from the wall), time t [s],
force [N], energy [J]. The motion is normal to the wall:

    M(h) dv/dt = -(m - m_f) g - 6 pi mu a v [phi(Re) + lambda(h/a) - 1 - (1 - s) a/h]
                 + F_H - (1/2) M'(h) v^2,     M(h) = m + C_M(h) m_f,

m = 4/3 pi a^3 rho_p, m_f = 4/3 pi a^3 rho_f, Re = rho_f |v| 2a / mu. phi = C_D Re / 24 is the
steady drag law's factor over Stokes drag (:func:`drag_factor`), lambda Brenner's (1961) exact
Stokes-flow resistance factor of a sphere moving normal to a plane wall
(:func:`ehdfem.exact.sphere_towards_wall.resistance`, 1 far away, a/h near contact). The
wall's increment lambda - 1 is added to the unbounded drag
(it is a viscous effect of the narrowing gap; the wake's inertia, phi - 1, is not multiplied by
it). Moving away from the wall, the lubrication part a/h of lambda is capped by cavitation as
in the film model: s in (0, 1] (:func:`cavity_edge_ratio`; 1 when approaching). C_M(h): the
input C_M (1/2 far away) raised near the wall by the sphere's images (``wall_added_mass``;
:func:`ehdfem.bounce.unsteady.wall_added_mass`), the term in M' making the equation Lagrange's.
F_H: the history force with Mei & Adrian's finite-Re kernel (or Basset's, or none), a sum of
exponentials whose memory z_i is part of the flight's state (:mod:`ehdfem.bounce.unsteady`).

While falling, the sphere hands over to the film model of the contact
(:mod:`ehdfem.bounce.contact`) at the first gap h_c where the film's force there, the rigid
lubrication force 6 pi mu a^2 |v| / h, differs from the flight's hydrodynamic force by at most
``handover_jump`` (relative), or where h_c = ``ehd_multiple`` h_EHD, h_EHD = (4 theta mu |v|
a^(3/2))^(2/5) the gap at which the elasticity parameter is 1, whichever comes first
(:meth:`FarField.handover_margin`); the film model hands back at :meth:`FarField.exit_gap`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from .. import checks
from ..exact import sphere_towards_wall as towards_wall
from ..film import cavitation
from ..inputs.scales import elasticity_parameter
from ..motion.forces import HistoryForce
from . import unsteady
from .inputs import DRAG_LAWS, BounceInputs

HANDOVER_JUMP = 0.02  # largest relative force jump at the hand-over to the film model
EHD_MULTIPLE = 10.0  # hand over at the latest at this multiple of the EHD gap h_EHD
FLIGHT_RTOL = 1e-10  # relative tolerance of the flight's ODE integration
MEMORY_RTOL = 1e-7  # its relative tolerance on the history force's memory z_i
FLIGHT_SAMPLES = 200  # trajectory samples per flight leg (besides the integrator's steps)
# relative step of the flight Jacobian's central differences: its columns by the gap and the
# velocity hold to 1e-7 for steps from 1e-6 to 1e-4 (tests/test_bounce.py)
DIFFERENCE_STEP = 1e-5


def drag_factor(law: str, reynolds):
    """phi = C_D Re / 24, the steady drag over Stokes drag of a sphere in unbounded liquid at
    the particle Reynolds number Re = rho_f |v| 2a / mu (dimensionless):

    - "schiller-naumann": 1 + 0.15 Re^0.687 (Schiller & Naumann 1933; Re < 800);
    - "abraham": C_D = 0.2924 (1 + 9.06 / sqrt(Re))^2 (Abraham 1970; Re < 5000), so
      phi = 0.2924 (sqrt(Re) + 9.06)^2 / 24 (1.00004 at Re = 0);
    - "stokes": 1 (creeping flow, Re << 1).
    """
    reynolds = np.asarray(reynolds, dtype=float)
    if law == "schiller-naumann":
        return 1.0 + 0.15 * reynolds**0.687
    if law == "abraham":
        return 0.2924 * (np.sqrt(reynolds) + 9.06) ** 2 / 24.0
    if law == "stokes":
        return np.ones_like(reynolds)
    raise checks.InputError(f"drag = {law!r} is not one of {', '.join(map(repr, DRAG_LAWS))}")


def cavity_edge_ratio(cavitation_number: float) -> float:
    """s = h / h_c in (0, 1]: the lubrication suction of a rigid sphere leaving a wall, capped by
    cavitation, is -6 pi mu a^2 v s / h instead of -6 pi mu a^2 v / h.

    The gap is h + r^2/(2a), the sphere moves away at v > 0, and the pressure may not fall more
    than Delta p = p_ambient - p_cavitation below ambient. Inside a cavity r < r_c it is
    -Delta p; outside it solves the Reynolds equation r h^3 dp/dr = 6 mu v (r^2 - r_c^2) (dp/dr
    = 0 at the cavity's edge, as the film model's truncation gives) with p -> 0 far away.
    Integrating, the force is -6 pi mu a^2 v / h_c with h_c the gap at the edge, and s = h/h_c
    solves

        Pi = Delta p h^2 / (6 mu a v) = s^2 [1/2 - (1 - s) q(s)],
        q(s) = sum_{k>=0} s^k / (k + 3) = (-ln(1 - s) - s - s^2/2) / s^3,

    whose right side rises from 0 to 1/2; for ``cavitation_number`` Pi >= 1/2 there is no
    cavity (the uncapped suction on the axis, 3 mu a v / h^2, is below Delta p) and s = 1."""
    if cavitation_number >= 0.5:
        return 1.0
    return brentq(lambda s: _capped_suction(s) - cavitation_number, 0.0, 1.0, xtol=1e-15)


def _capped_suction(s: float) -> float:
    """s^2 [1/2 - (1 - s) q(s)] of :func:`cavity_edge_ratio` (q by its series below s = 0.05)."""
    if s < 0.05:
        q = sum(s**k / (k + 3) for k in range(14))
    else:
        q = (-math.log1p(-s) - s - 0.5 * s * s) / s**3 if s < 1.0 else 0.0
    return s * s * (0.5 - (1.0 - s) * q)


@dataclass(frozen=True)
class FlightState:
    """The sphere at one instant (SI): time t [s], gap h [m], velocity v [m/s], the work done so
    far on the liquid by the drag and by the history force [J] (from the start of the bounce),
    and the history force's memory z_i [m/s] (one per exponential of
    :data:`ehdfem.bounce.unsteady.RELAXATION_TIMES`; empty without a history force)."""

    time: float
    gap: float
    velocity: float
    drag_work: float = 0.0
    history_work: float = 0.0
    memory: np.ndarray = field(default_factory=lambda: np.zeros(0))


@dataclass
class Flight:
    """One flight leg: samples of time [s], gap [m], velocity [m/s], the drag's and the history
    force's work so far [J] (from the start of the bounce), the memory z_i [m/s] at its end,
    and how it ended: "handover" (the film model takes over), "apex" (v = 0 on the way up),
    "end" (the given duration ran out) or "inside" (it started falling inside the hand-over
    region: no flight)."""

    time: np.ndarray
    gap: np.ndarray
    velocity: np.ndarray
    drag_dissipated: np.ndarray
    history_dissipated: np.ndarray
    memory: np.ndarray
    end: str

    @classmethod
    def single(cls, state: FlightState, end: str) -> Flight:
        """A leg of the one sample ``state``, ended by ``end``."""
        columns = (state.time, state.gap, state.velocity, state.drag_work, state.history_work)
        return cls(*(np.array([x]) for x in columns), state.memory, end)

    def last(self) -> FlightState:
        """The state at the end of the leg."""
        return FlightState(
            float(self.time[-1]),
            float(self.gap[-1]),
            float(self.velocity[-1]),
            float(self.drag_dissipated[-1]),
            float(self.history_dissipated[-1]),
            self.memory,
        )


class FarField:
    """The flight's force law and its integration (module docstring), for ``inputs``.

    ``mass``, ``fluid_mass`` = rho_f times the sphere's volume [kg] (the inertia with the added
    mass: :meth:`inertia`); ``net_weight`` = (mass - fluid_mass) g [N]; ``stokes`` =
    6 pi mu a [N s/m]; ``relaxation_times`` tau_i = sigma_i a^2 / nu [s] of the history force's
    exponentials (none without it)."""

    def __init__(
        self,
        inputs: BounceInputs,
        handover_jump: float = HANDOVER_JUMP,
        ehd_multiple: float = EHD_MULTIPLE,
    ):
        self.inputs = inputs
        self.handover_jump, self.ehd_multiple = handover_jump, ehd_multiple
        a, liquid = inputs.radius, inputs.liquid
        self.mass = inputs.volume * inputs.sphere.density
        self.fluid_mass = inputs.volume * liquid.density
        self.net_weight = (self.mass - self.fluid_mass) * inputs.gravity
        self.stokes = 6.0 * math.pi * liquid.viscosity * a
        capped = cavitation.has_limit(inputs.cavitation)
        self.suction_limit = inputs.ambient_pressure - liquid.vapour_pressure if capped else None
        modes = len(unsteady.history_weights(inputs.history, 0.0))
        viscous_time = a * a * liquid.density / liquid.viscosity
        self.relaxation_times = unsteady.RELAXATION_TIMES[:modes] * viscous_time

    def inertia(self, gap: float) -> tuple[float, float]:
        """(M, dM/dh): the sphere's mass with its added mass, M = m + C_M(h) m_f [kg], and its
        slope [kg/m]; C_M(h) = C_M (C_M(h)/C_M(inf) of the sphere's image,
        :func:`ehdfem.bounce.unsteady.wall_added_mass`) with ``wall_added_mass``, else C_M."""
        if not self.inputs.wall_added_mass:
            return self.far_inertia(), 0.0
        added = self.inputs.added_mass * self.fluid_mass
        factor, slope = unsteady.wall_added_mass(gap / self.inputs.radius)
        return self.mass + added * factor, added * slope / self.inputs.radius

    def far_inertia(self) -> float:
        """m + C_M m_f [kg], the inertia far from the wall."""
        return self.mass + self.inputs.added_mass * self.fluid_mass

    def history_weights(self, gap: float, velocity: float) -> np.ndarray:
        """The weights w_i of the history kernel at the Reynolds number of ``velocity`` [m/s]
        and, for the wall-bounded kernel, the gap ``gap`` [m]
        (:func:`ehdfem.bounce.unsteady.history_weights`)."""
        reynolds = float(self.reynolds(velocity))
        return unsteady.history_weights(self.inputs.history, reynolds, gap / self.inputs.radius)

    def reynolds(self, velocity):
        """Re = rho_f |v| 2a / mu."""
        liquid = self.inputs.liquid
        return liquid.density * np.abs(velocity) * self.inputs.diameter / liquid.viscosity

    def phi(self, velocity):
        """phi(Re) = C_D Re / 24 of the inputs' drag law at ``velocity`` [m/s]
        (:func:`drag_factor`)."""
        return drag_factor(self.inputs.drag, self.reynolds(velocity))

    def resistance(self, gap: float, velocity: float) -> float:
        """phi(Re) + lambda(h/a) - 1 - (1 - s) a/h: the flight's drag over Stokes drag
        6 pi mu a |v|, with s the cavity's cap on the lubrication suction when moving away
        (:meth:`cavity_factor`)."""
        a = self.inputs.radius
        phi = float(self.phi(velocity))
        lubrication_cap = (1.0 - self.cavity_factor(gap, velocity)) * a / gap
        return phi + float(towards_wall.resistance(gap / a)) - 1.0 - lubrication_cap

    def cavity_factor(self, gap: float, velocity: float) -> float:
        """s of :func:`cavity_edge_ratio` at Pi = Delta p h^2 / (6 mu a v) when the sphere moves
        away (v > 0) and the inputs' cavitation model caps the suction; 1 otherwise."""
        if velocity <= 0.0 or self.suction_limit is None:
            return 1.0
        viscous = 6.0 * self.inputs.liquid.viscosity * self.inputs.radius * velocity
        return cavity_edge_ratio(self.suction_limit * gap**2 / viscous)

    def drag(self, gap, velocity):
        """The hydrodynamic force of the flight, -6 pi mu a v times :meth:`resistance` [N]."""
        return -self.stokes * velocity * self.resistance(gap, velocity)

    def terminal_velocity(self) -> float:
        """The settling speed far from walls [m/s]: v phi(Re(v)) = (m - m_f) g / (6 pi mu a)."""
        stokes_speed = self.net_weight / self.stokes
        if self.inputs.drag == "stokes":
            return stokes_speed
        return brentq(
            lambda v: v * float(self.phi(v)) - stokes_speed,
            0.0,
            stokes_speed,
            xtol=1e-14 * stokes_speed,
            rtol=1e-14,
        )

    def exit_gap(self, handover_gap: float, speed: float) -> float:
        """Where the film model hands back after a rebound [m]: the hand-over gap h_c, or, with
        ``clear_exit`` and a suction limit Delta p, the larger h_cav = sqrt(3 mu a V0 / Delta p),
        above which a rigid sphere leaving the wall at any speed up to the hand-over speed
        ``speed`` V0 (the exit's is lower) forms no cavity (Pi >= 1/2 of
        :func:`cavity_edge_ratio`): the film's cavitation no longer acts there, and its
        elasticity already did not at h_c (the hand-over criterion)."""
        if not self.inputs.clear_exit or self.suction_limit is None:
            return handover_gap
        viscous = 3.0 * self.inputs.liquid.viscosity * self.inputs.radius * speed
        return max(handover_gap, math.sqrt(viscous / self.suction_limit))

    def ehd_gap(self, speed: float) -> float:
        """h_EHD = (4 theta mu |v| a^(3/2))^(2/5) [m], the gap x0 at which eps = 1 (eps at
        x0 = 1 m, to the power 2/5)."""
        inputs = self.inputs
        eps = elasticity_parameter(
            inputs.theta, inputs.liquid.viscosity, abs(speed), inputs.radius, 1.0
        )
        return eps**0.4

    def handover_margin(self, gap: float, velocity: float) -> float:
        """Positive above the hand-over gap, zero at it, negative inside: the smaller of
        J - handover_jump and h / (ehd_multiple h_EHD) - 1, where J = 1 - (a/h) / (phi + lambda - 1)
        is the relative jump from the flight's force to the film's rigid lubrication force."""
        jump = 1.0 - (self.inputs.radius / gap) / self.resistance(gap, velocity)
        ehd = self.ehd_multiple * self.ehd_gap(velocity)
        return min(jump - self.handover_jump, gap / ehd - 1.0 if ehd > 0 else math.inf)

    def rates(self, y) -> np.ndarray:
        """d/dt of (h, v, drag work, history work, z_1..z_n) for y = those (SI): the Lagrangian
        M(h) dv/dt = F_drag - (m - m_f) g + F_H - (1/2) dM/dh v^2 (the image's added mass
        conserves the kinetic energy M v^2 / 2 with the forces' work), the history force
        F_H = -6 pi mu a sum_i w_i(Re) z_i (:meth:`history_force`), dz_i/dt = -z_i/tau_i + dv/dt."""
        gap, velocity, memory = max(y[0], 1e-300), y[1], y[4:]
        drag = self.drag(gap, velocity)
        history = self.history_force(gap, velocity, memory)
        mass, slope = self.inertia(gap)
        acceleration = (drag - self.net_weight + history - 0.5 * slope * velocity**2) / mass
        rates = np.empty(len(y))
        rates[:4] = velocity, acceleration, -drag * velocity, -history * velocity
        rates[4:] = -memory / self.relaxation_times + acceleration
        return rates

    def rates_jacobian(self, y) -> np.ndarray:
        """d(rates)/dy of :meth:`rates` [SI, per s]: the memory's columns exact (the history
        force -6 pi mu a sum_i w_i z_i is linear in z_i, and dz_i/dt = -z_i/tau_i + dv/dt), the
        gap's and the velocity's by central differences of relative step DIFFERENCE_STEP, the
        works' zero. LSODA's own forward differences took one call of :meth:`rates` per
        unknown, 4 + len(z) of them (53 with the default memory), 70 % of a bounce's calls;
        their step, sqrt(machine epsilon), is below the rounding of the history force (a sum of
        weights of both signs), which put the gap's column 15 % off near the wall."""
        y = np.asarray(y, dtype=float)
        jacobian = np.zeros((len(y), len(y)))
        scales = (self.inputs.radius * 1e-6, 1e-3 * self.terminal_velocity())
        for k, scale in enumerate(scales):
            step = DIFFERENCE_STEP * max(abs(y[k]), scale)
            up, down = y.copy(), y.copy()
            up[k] += step
            down[k] -= step
            jacobian[:, k] = (self.rates(up) - self.rates(down)) / (2.0 * step)
        gap, velocity, memory = max(y[0], 1e-300), y[1], y[4:]
        if len(memory):
            weights = self.stokes * self.history_weights(gap, velocity)  # -dF_H/dz_i
            by_memory = -weights / self.inertia(gap)[0]  # d(dv/dt)/dz_i
            jacobian[1, 4:] = by_memory
            jacobian[3, 4:] = weights * velocity  # d(-F_H v)/dz_i
            jacobian[4:, 4:] = by_memory
            jacobian[4:, 4:] -= np.diag(1.0 / self.relaxation_times)
        return jacobian

    def history_force(self, gap: float, velocity: float, memory) -> float:
        """F_H = -6 pi mu a sum_i w_i(Re, h) z_i [N]: the memory z_i [m/s] weighted by the
        kernel at the current Reynolds number and gap [m] (0 without a history force)."""
        if not len(memory):
            return 0.0
        return -self.stokes * float(self.history_weights(gap, velocity) @ memory)

    def contact_history_force(self, gap: float, speed: float, memory) -> HistoryForce:
        """The history force in the film model of a contact handed over at ``gap`` [m] (its x0)
        and ``speed`` [m/s] (its V0), from the flight's memory z_i [m/s], in the contact's
        scales (:class:`ehdfem.motion.forces.HistoryForce`: k = x0 / a, T_i = tau_i V0 / x0,
        Z_i = z_i / V0, the weights at the Reynolds number of V V0)."""
        return HistoryForce(
            gap / self.inputs.radius,
            self.relaxation_times * speed / gap,
            lambda velocity: self.history_weights(gap, velocity * speed),
            np.asarray(memory, dtype=float) / speed,
        )

    def fly(self, start: FlightState, rising: bool, duration: float | None = None) -> Flight:
        """Integrate a flight leg from ``start`` until the apex (``rising``) or the hand-over
        (falling), or at most for ``duration`` [s] (None: until the event). LSODA, relative
        tolerance FLIGHT_RTOL."""
        t0, gap, velocity = start.time, start.gap, start.velocity
        memory = np.zeros(len(self.relaxation_times))  # at rest since ever, unless given
        if len(start.memory):
            memory = np.asarray(start.memory, dtype=float)
        if not rising and self.handover_margin(gap, velocity) <= 0.0:
            return Flight.single(replace(start, memory=memory), end="inside")

        def apex(_, y):
            return y[1]

        def handover(_, y):
            return self.handover_margin(max(y[0], 1e-300), y[1])

        for event in (apex, handover):
            event.terminal, event.direction = True, -1.0
        span = duration if duration is not None else self._longest_leg(gap, velocity)
        y0 = [gap, velocity, start.drag_work, start.history_work, *memory]
        solution = solve_ivp(
            lambda _, y: self.rates(y),
            (t0, t0 + span),
            y0,
            method="LSODA",
            jac=lambda _, y: self.rates_jacobian(y),
            rtol=[FLIGHT_RTOL] * 4 + [MEMORY_RTOL] * len(memory),
            atol=self._tolerances(velocity, len(memory)),
            events=apex if rising else handover,
            dense_output=True,
        )
        if solution.status == -1:
            raise checks.InputError(f"the flight could not be integrated: {solution.message}")
        t_end, end = solution.t[-1], "end"
        if solution.t_events[0].size:
            t_end, end = solution.t_events[0][0], "apex" if rising else "handover"
        elif duration is None:
            raise checks.InputError(
                f"no {'apex' if rising else 'hand-over'} within {span:.3g} s of flight from "
                f"h = {gap:.4g} m, v = {velocity:.4g} m/s"
            )
        times = np.union1d(solution.t[solution.t <= t_end], np.linspace(t0, t_end, FLIGHT_SAMPLES))
        states = solution.sol(times)
        return Flight(times, *states[:4], solution.sol(t_end)[4:], end)

    def _tolerances(self, velocity: float, modes: int) -> list[float]:
        """Absolute tolerances of (h, v, the two works, z_i)."""
        speed = max(abs(velocity), self.terminal_velocity())
        energy = 1e-3 * FLIGHT_RTOL * self.far_inertia() * speed**2
        small = 1e-3 * FLIGHT_RTOL * speed
        memory = [1e-3 * MEMORY_RTOL * speed] * modes
        return [1e-9 * FLIGHT_RTOL * self.inputs.radius, small, energy, energy] + memory

    def _longest_leg(self, gap: float, velocity: float) -> float:
        """A time within which any flight leg from (gap, velocity) has its event [s]: free fall
        from the top of a rise, at a speed of at least a thousandth of the terminal one."""
        mass = self.far_inertia()
        top = gap + velocity**2 * mass / (2.0 * self.net_weight)
        relax = mass / self.stokes
        return (
            10.0 * (relax + abs(velocity) * mass / self.net_weight)
            + 1e3 * (top + self.inputs.radius) / self.terminal_velocity()
        )


def release_height_for_speed(inputs: BounceInputs, speed: float, top: float = 1.0):
    """The release height [m] (at rest) from which the sphere's largest approach speed before
    its first contact is ``speed`` [m/s], by bisection on heights in [a, ``top``]; None when no
    height up to ``top`` reaches it (the drag law's terminal velocity is below ``speed``, or
    approached too slowly)."""
    checks.positive("speed", speed)
    far = FarField(inputs)
    if far.terminal_velocity() <= speed:
        return None

    def excess(height):
        leg = far.fly(FlightState(0.0, height, 0.0), rising=False)
        return float(np.max(np.abs(leg.velocity))) - speed

    low = inputs.radius
    if excess(low) >= 0.0:
        raise checks.InputError(f"the sphere exceeds {speed!r} m/s already from h = {low:.3g} m")
    if excess(top) < 0.0:
        return None
    return brentq(excess, low, top, xtol=1e-9 * top, rtol=1e-9)
