"""A sphere settling onto a wall in a liquid and bouncing: its trajectory, each contact an EHD
collision (docs/bounce.md).

All quantities are SI: gap h [m] between the sphere's lowest point and the wall (the centre's
height minus the radius a), velocity v = dh/dt [m/s] (positive away from the wall), time t [s],
force [N], energy [J]. The motion is normal to the wall.

**Flight** (far from contact):

    M(h) dv/dt = -(m - m_f) g - 6 pi mu a v [phi(Re) + lambda(h/a) - 1 - (1 - s) a/h]
                 + F_H - (1/2) M'(h) v^2,     M(h) = m + C_M(h) m_f,

m = 4/3 pi a^3 rho_p, m_f = 4/3 pi a^3 rho_f, Re = rho_f |v| 2a / mu. phi = C_D Re / 24 is the
steady drag law's factor over Stokes drag (:func:`drag_factor`), lambda Brenner's (1961) exact
Stokes-flow resistance factor of a sphere moving normal to a plane wall (:func:`brenner_factor`,
1 far away, a/h near contact). The wall's increment lambda - 1 is added to the unbounded drag
(it is a viscous effect of the narrowing gap; the wake's inertia, phi - 1, is not multiplied by
it). Moving away from the wall, the lubrication part a/h of lambda is capped by cavitation as
in the film model: s in (0, 1] (:func:`cavity_edge_ratio`; 1 when approaching). C_M(h): the
input C_M (1/2 far away) raised near the wall by the sphere's images (``wall_added_mass``;
:func:`ehdfem.bounce.unsteady.wall_added_mass`), the term in M' making the equation Lagrange's.
F_H: the history force with Mei & Adrian's finite-Re kernel (or Basset's, or none), a sum of
exponentials whose memory z_i is part of the flight's state (:mod:`ehdfem.bounce.unsteady`).

**Contact**: while falling, the sphere hands over to the immersed EHD film model
(:func:`ehdfem.collision.collide`, Davis, Serayssol & Hinch 1986) at the first gap h_c where the
film's force there, the rigid lubrication force 6 pi mu a^2 |v| / h, differs from the flight's
hydrodynamic force by at most ``handover_jump`` (relative), or where h_c = ``ehd_multiple``
h_EHD, h_EHD = (4 theta mu |v| a^(3/2))^(2/5) the gap at which the elasticity parameter is 1,
whichever comes first. The film model starts at X = 1 (x0 = h_c) with V0 = |v(h_c)|, the
inertia M(h_c) (the sphere's mass, and the added mass not in the weight), gravity and buoyancy
(``contact_gravity``), e_dry and the cavitation limit of the inputs; it ends at exit (X =
h_exit / h_c, speed e_n V0 with the collision's e_n: e_dry V_exit for smooth surfaces, V_exit
for rough ones, whose asperities act inside the contact; :meth:`FarField.exit_gap`) or sticks.
The surfaces' roughness [m] is the same at every contact, sigma / x0 is not. With
``contact_history`` (the default) the history force acts in the film model's time stepping
(:class:`ehdfem.motion.forces.HistoryForce`, from the flight's memory, in the contact's
scales: :meth:`FarField.contact_history_force`); without it its impulse over the contact is
measured only. The flight's remainder (phi - 1 + lambda - a/h) is not applied
during the contact; its impulse is measured (:class:`Contact`; ``contact_drag`` adds it to the
rebound's momentum at exit, a first-order estimate). The contact's velocity change is carried
into the history force's memory (``history_memory`` "keep"), or the memory is emptied
("reset") or keeps only the flight before the contact ("approach"). Flight resumes at h_exit
with the kinetic energy of the exit.

**Rest**: the sphere rests when a contact sticks or stalls, or when an apex is below
``rest_apex`` D or already inside the hand-over region; the computation also stops at the apex
after ``max_bounces`` contacts.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass, field, replace

import numpy as np
from scipy.integrate import cumulative_trapezoid, solve_ivp, trapezoid
from scipy.optimize import brentq

from .. import checks
from ..collision import collide, film_radii
from ..config import DEFAULT_NODES, Numerics, RunConfig
from ..dem.closedform import legendre
from ..film import cavitation
from ..film.asperities import MODELS as ASPERITY_MODELS
from ..inputs.presets import Liquid, Material, body, check_vapour_pressure
from ..inputs.scales import (
    ATMOSPHERE,
    PhysicalCollision,
    elastic_theta,
    elasticity_parameter,
    stokes_number,
)
from ..motion.forces import HistoryForce
from ..motion.timestepping import IntegratorOptions
from ..outputs import provenance
from ..outputs import registry as outputs
from ..solids.compliance import RigidSolids
from . import unsteady
from .unsteady import HISTORY_KERNELS

GRAVITY = 9.81  # m/s^2
DRAG_LAWS = ("schiller-naumann", "abraham", "stokes")
MODELS = ("halfspace", "rigid")
HANDOVER_JUMP = 0.02  # largest relative force jump at the hand-over to the film model
EHD_MULTIPLE = 10.0  # hand over at the latest at this multiple of the EHD gap h_EHD
FLIGHT_RTOL = 1e-10  # relative tolerance of the flight's ODE integration
MEMORY_RTOL = 1e-7  # its relative tolerance on the history force's memory z_i
FLIGHT_SAMPLES = 200  # trajectory samples per flight leg (besides the integrator's steps)
SETTLED_FILM = 0.95  # the film's pressure has built up once X <= this (entry force jump)
LUBRICATION_GAP = 1e-4  # h/a below which Brenner's factor is its lubrication expansion
ENDINGS = {"stick": "sticks", "stalled": "stalled (settling through the film)"}
HISTORY_MEMORIES = ("keep", "reset", "approach")  # the history force's memory across a contact
SWITCHES = (  # the on/off modelling choices of BounceInputs
    "wall_added_mass",
    "contact_gravity",
    "clear_exit",
    "contact_history",
    "contact_drag",
)


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


def brenner_factor(gap_over_radius):
    """lambda(h/a): Brenner's (1961) exact resistance of a sphere translating normal to a plane
    wall in Stokes flow, F = -6 pi mu a v lambda, with alpha = arccosh(1 + h/a):

        lambda = (4/3) sinh(alpha) sum_{n>=1} n(n+1) / ((2n-1)(2n+3))
                 [ (2 sinh((2n+1) alpha) + (2n+1) sinh(2 alpha))
                   / (4 sinh^2((n+1/2) alpha) - (2n+1)^2 sinh^2(alpha)) - 1 ].

    The bracket is summed as e^-k alpha (2 - 2 e^-k alpha + k sinh 2alpha + k^2 sinh^2 alpha)
    / (1 - 2 e^-k alpha + e^-2k alpha - k^2 sinh^2(alpha) e^-k alpha), k = 2n + 1 (the same
    quantity without overflow), until its terms are below 1e-17 of the sum (about 22/alpha
    terms; 60/alpha + 50 are taken). lambda -> 1 + 9a/(8(h+a)) far away. Below h/a =
    LUBRICATION_GAP the lubrication expansion a/h + (1/5) ln(a/h) + 0.9713 (Cox & Brenner
    1967) is used instead: there it differs from the series by less than 1e-8 relative."""
    gaps = np.atleast_1d(np.asarray(gap_over_radius, dtype=float))
    values = np.array(
        [
            _brenner_series(math.acosh(1.0 + g))
            if g >= LUBRICATION_GAP
            else 1.0 / g + 0.2 * math.log(1.0 / g) + 0.9713
            for g in gaps
        ]
    )
    return values[0] if np.ndim(gap_over_radius) == 0 else values


def _brenner_series(alpha: float) -> float:
    """Brenner's series (:func:`brenner_factor`) at alpha = arccosh(1 + h/a) > 0."""
    n = np.arange(1.0, int(60.0 / alpha) + 51)
    k = 2.0 * n + 1.0
    decay = np.exp(-k * alpha)
    sinh2 = math.sinh(alpha) ** 2
    bracket = (
        decay
        * (2.0 - 2.0 * decay + k * math.sinh(2.0 * alpha) + k * k * sinh2)
        / (1.0 - 2.0 * decay + decay * decay - k * k * sinh2 * decay)
    )
    weights = n * (n + 1.0) / ((2.0 * n - 1.0) * (2.0 * n + 3.0))
    return 4.0 / 3.0 * math.sinh(alpha) * float(np.sum(weights * bracket))


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
class BounceInputs:
    """Physical inputs of a bounce (SI): sphere radius a [m]; the sphere, wall and liquid (a
    preset name, a Material or Liquid, or a dict of values, as :func:`ehdfem.from_presets`);
    the start: ``release_height`` [m], the gap from which the sphere is released at rest, or
    ``start_gap`` [m] with ``start_speed`` [m/s] towards the wall; e_dry in (0, 1], applied at
    each exit as in the collision model (e_n = e_dry V_exit; rough: at the asperities'
    impact); the drag law (:data:`DRAG_LAWS`); the added-mass coefficient C_M in [0, 1] (far
    from the wall); gravity g [m/s^2]; the film's cavitation model
    (:data:`ehdfem.film.cavitation.MODELS`) with the ambient pressure [Pa]
    (the cavitation pressure is the liquid's vapour pressure, as in
    :class:`ehdfem.PhysicalCollision`). The
    modelling choices of docs/bounce.md, each switchable: the history force's kernel
    (:data:`ehdfem.bounce.unsteady.HISTORY_KERNELS`) and its memory across a contact
    (:data:`HISTORY_MEMORIES`: "keep" carries the contact's velocity change into it, "reset"
    forgets everything at each exit, "approach" forgets the contact's velocity change at each
    exit and keeps the memory of the flight before it, faded over the contact);
    ``wall_added_mass``: C_M rises near the wall as the sphere's image says (C_M above is then
    its value far away); ``contact_gravity``: gravity
    and buoyancy act during the contacts; ``clear_exit``: the film model hands back above the
    gap where a cavity can form (:meth:`FarField.exit_gap`). The surfaces' rms roughness
    ``sphere_roughness`` and ``wall_roughness`` [m] (0: smooth), the same at every contact
    (scaled there by that contact's x0 = h_c), with the collision's ``asperities`` model
    (:data:`ehdfem.film.asperities.MODELS`). ``contact_history`` (default on): the history force
    acts in the contact's time stepping, so that the memory the flight carries on and the
    contact's motion are one (off: only its impulse is measured). ``contact_drag`` (default
    off, a variation, docs/bounce.md "The forces of the contact") adds the flight's
    remainder's impulse over the contact to the rebound's momentum at exit."""

    radius: float
    sphere: Material | str | dict
    wall: Material | str | dict
    liquid: Liquid | str | dict
    release_height: float | None = None
    start_gap: float | None = None
    start_speed: float | None = None
    e_dry: float = 1.0
    drag: str = "schiller-naumann"
    added_mass: float = 0.5
    gravity: float = GRAVITY
    cavitation: str = "truncate"
    ambient_pressure: float = ATMOSPHERE
    history: str = "mei-adrian"
    history_memory: str = "keep"
    wall_added_mass: bool = True
    contact_gravity: bool = True
    clear_exit: bool = True
    sphere_roughness: float = 0.0
    wall_roughness: float = 0.0
    asperities: str = "impact"
    contact_history: bool = True
    contact_drag: bool = False

    def __post_init__(self):
        for role in ("sphere", "wall", "liquid"):
            object.__setattr__(self, role, body(role, getattr(self, role)))
        checks.number("radius", self.radius, lower=0.0, upper=1.0, lower_open=True)
        if self.sphere.density <= self.liquid.density:
            raise checks.InputError(
                f"the sphere's density {self.sphere.density!r} kg/m^3 must exceed the liquid's "
                f"{self.liquid.density!r} kg/m^3 (the allowed range is "
                f"({self.liquid.density:g}, 3e4]): a lighter sphere does not settle"
            )
        released = self.release_height is not None
        started = self.start_gap is not None or self.start_speed is not None
        if released == started:
            raise checks.InputError(
                "give either release_height (released at rest) or start_gap with start_speed"
            )
        if released:
            checks.number(
                "release_height", self.release_height, lower=0.0, upper=100.0, lower_open=True
            )
        else:
            if self.start_gap is None or self.start_speed is None:
                raise checks.InputError("start_gap and start_speed must be given together")
            checks.number("start_gap", self.start_gap, lower=0.0, upper=100.0, lower_open=True)
            checks.number("start_speed", self.start_speed, lower=0.0, upper=100.0)
        checks.number("e_dry", self.e_dry, lower=0.0, upper=1.0, lower_open=True)
        checks.choice("drag", self.drag, DRAG_LAWS)
        checks.number("added_mass", self.added_mass, lower=0.0, upper=1.0)
        checks.number("gravity", self.gravity, lower=0.0, upper=100.0, lower_open=True)
        checks.choice("cavitation", self.cavitation, cavitation.MODELS)
        checks.positive("ambient_pressure", self.ambient_pressure)
        check_vapour_pressure(self.liquid, self.ambient_pressure)
        checks.choice("history", self.history, HISTORY_KERNELS)
        checks.choice("history_memory", self.history_memory, HISTORY_MEMORIES)
        for surface in ("sphere_roughness", "wall_roughness"):
            checks.number(surface, getattr(self, surface), lower=0.0, upper=0.01 * self.radius)
        checks.choice("asperities", self.asperities, ASPERITY_MODELS)
        for switch in SWITCHES:
            if not isinstance(getattr(self, switch), bool):
                raise checks.InputError(f"{switch} must be True or False")

    @property
    def diameter(self) -> float:
        """D = 2a [m]."""
        return 2.0 * self.radius

    @property
    def volume(self) -> float:
        """The sphere's volume 4/3 pi a^3 [m^3]."""
        return 4.0 / 3.0 * math.pi * self.radius**3

    @property
    def theta(self) -> float:
        """theta = sum (1 - nu^2) / (pi E) of sphere and wall [1/Pa]."""
        return elastic_theta(self.sphere, self.wall)

    def stokes_number(self, speed: float) -> float:
        """St = m |v| / (6 pi mu a^2) = rho_p D |v| / (9 mu), the sphere's own mass (the
        experiments' convention, Gondret et al. 2002; no added mass)."""
        mass = self.sphere.density * self.volume
        return stokes_number(mass, speed, self.liquid.viscosity, self.radius)

    def time_scale(self) -> float:
        """sqrt(D / g) [s], the time unit of the experiments' trajectories."""
        return math.sqrt(self.diameter / self.gravity)


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
        capped = inputs.cavitation != "none"
        self.suction_limit = inputs.ambient_pressure - liquid.vapour_pressure if capped else None
        modes = len(unsteady.history_weights(inputs.history, 0.0))
        viscous_time = a * a * liquid.density / liquid.viscosity
        self.relaxation_times = unsteady.RELAXATION_TIMES[:modes] * viscous_time

    def inertia(self, gap: float) -> tuple[float, float]:
        """(M, dM/dh): the sphere's mass with its added mass, M = m + C_M(h) m_f [kg], and its
        slope [kg/m]; C_M(h) = C_M (C_M(h)/C_M(inf) of the sphere's image,
        :func:`ehdfem.bounce.unsteady.wall_added_mass`) with ``wall_added_mass``, else C_M."""
        added = self.inputs.added_mass * self.fluid_mass
        if not self.inputs.wall_added_mass:
            return self.mass + added, 0.0
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

    def resistance(self, gap: float, velocity: float) -> float:
        """phi(Re) + lambda(h/a) - 1 - (1 - s) a/h: the flight's drag over Stokes drag
        6 pi mu a |v|, with s the cavity's cap on the lubrication suction when moving away
        (:meth:`cavity_factor`)."""
        a = self.inputs.radius
        phi = float(drag_factor(self.inputs.drag, self.reynolds(velocity)))
        lubrication_cap = (1.0 - self.cavity_factor(gap, velocity)) * a / gap
        return phi + float(brenner_factor(gap / a)) - 1.0 - lubrication_cap

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
            lambda v: v * float(drag_factor(self.inputs.drag, self.reynolds(v))) - stokes_speed,
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
            columns = (t0, gap, velocity, start.drag_work, start.history_work)
            return Flight(*(np.array([x]) for x in columns), memory, end="inside")

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


@dataclass
class Contact:
    """One contact (film model, :func:`ehdfem.collision.collide`) within a bounce (SI).

    ``impact_speed``: the largest approach speed since the last apex (the release); the
    restitution ``e`` = rebound speed / ``impact_speed``, as measured in experiments (the
    rebound speed at the exit gap, the largest rising speed after it); ``St``: rho_p D
    impact_speed / (9 mu). ``handover_gap`` h_c and ``handover_speed`` V0 = |v(h_c)|;
    ``exit_gap`` [m]: where the film model hands back (:meth:`FarField.exit_gap`);
    ``contact_St``, ``eps``, ``p_cav``: the film model's groups (with the added mass).
    ``film``: every output of the film model (:mod:`ehdfem.outputs.registry`,
    :func:`ehdfem.outputs.registry.in_si_where_possible`): in SI under its SI key where it has
    one (``min_film_thickness_m`` [m], ``max_force_N`` [N], ``contact_time_s`` [s],
    ``max_compression_m`` [m], ``rebound_normal_speed_m_s`` the rebound speed [m/s]), else
    under its name scaled by the contact's own scales, x0 = h_c and V0 (``exit_velocity``
    V_exit by V0, before e_dry; ``status`` "rebound" or "stick"; ``energy_error`` the film
    model's relative balance error, None with a cavitation limit). Force jumps (relative,
    flight to film, both at the same h and v): ``entry_jump`` once the film pressure has built
    up (the first step with X <= SETTLED_FILM), ``exit_jump`` at the last step before exit.
    Impulses over the contact, relative to the hand-over momentum M(h_c) V0 (not applied during
    it, but the history force's with ``contact_history``):
    ``gravity_impulse`` ((m - m_f) g duration; 0 when gravity acts in the contact),
    ``remainder_impulse`` (int 6 pi mu a |v| |phi - 1 + lambda - a/h| dt, with h the thinnest
    film) and ``history_impulse`` (int F_H dt from the memory carried through the contact,
    signed, positive away from the wall; 0 without a history force). Energies [J]:
    ``film_dissipated`` (the film's viscous dissipation up to exit), ``exit_loss`` (the
    exit's kinetic energy less the rebound's at e_n, the dry loss of smooth surfaces, plus
    the elastic energy left in the solids)."""

    impact_speed: float
    St: float
    handover_gap: float
    handover_speed: float
    exit_gap: float
    contact_St: float
    eps: float
    p_cav: float | None
    e: float
    entry_jump: float
    exit_jump: float
    gravity_impulse: float
    remainder_impulse: float
    history_impulse: float
    film_dissipated: float
    exit_loss: float
    film: dict
    apex_gap: float | None = None
    apex_time: float | None = None

    @property
    def status(self) -> str:
        """The film model's outcome, "rebound" or "stick" (``film["status"]``)."""
        return self.film["status"]

    def row(self) -> dict:
        """The contact as one flat dict: its fields, then the film model's outputs."""
        fields = asdict(self)
        film = fields.pop("film")
        return {**fields, **film}


TRAJECTORY_COLUMNS = (
    "time",
    "gap",
    "velocity",
    "phase",
    "contacts",
    "kinetic",
    "potential",
    "elastic",
    "drag_dissipated",
    "history_dissipated",
    "film_dissipated",
    "exit_loss",
)


@dataclass
class BounceResult:
    """A bounce's trajectory and contacts (SI).

    ``trajectory``: arrays over the samples, as TRAJECTORY_COLUMNS: time [s] (0 at release or
    start), gap [m] (centre height - a; during a contact X x0, negative by the solids'
    compression), velocity [m/s], phase ("flight" or "contact"), contacts (how many began so
    far), and the energies [J]: kinetic 1/2 M(h) v^2 (M = m + C_M(h) m_f; M(h_c) in a contact),
    potential (m - m_f) g h (held at its hand-over value during a contact where gravity is not
    applied), elastic (in the solids), the cumulated work of the drag and of the history force
    on the liquid, film dissipation and exit losses. Their sum is the start's energy
    up to the integration errors (:meth:`energy_error`). ``contacts``: one :class:`Contact`
    each. ``status``: why it stopped. ``terminal_velocity``: the drag law's settling speed
    [m/s]."""

    inputs: BounceInputs
    model: str
    trajectory: dict
    contacts: list[Contact]
    status: str
    terminal_velocity: float
    handover_jump: float
    ehd_multiple: float
    rest_apex: float

    def energy_error(self) -> float:
        """max over the samples of |sum of the energies - its start value| / start value."""
        t = self.trajectory
        total = sum(np.asarray(t[name], dtype=float) for name in TRAJECTORY_COLUMNS[5:])
        return float(np.max(np.abs(total - total[0])) / total[0])

    def trajectory_rows(self) -> list[dict]:
        """The trajectory as rows (dicts of TRAJECTORY_COLUMNS), e.g. for a CSV table."""
        columns = [np.asarray(self.trajectory[name]).tolist() for name in TRAJECTORY_COLUMNS]
        rows = zip(*columns, strict=True)
        return [dict(zip(TRAJECTORY_COLUMNS, row, strict=True)) for row in rows]

    def contact_rows(self) -> list[dict]:
        """The contacts as rows (:meth:`Contact.row`, numbered from 1)."""
        return [{"contact": i + 1, **c.row()} for i, c in enumerate(self.contacts)]

    def summary(self, command: list[str] | None = None) -> dict:
        """The results as a JSON-ready dict: status, contacts, apexes, energy balance, where
        it comes from (:func:`ehdfem.outputs.provenance.record`, ``command`` its command line,
        default sys.argv) and every input."""
        inputs = asdict(self.inputs)
        first = self.contacts[0] if self.contacts else None
        return {
            "provenance": provenance.record(command),
            "status": self.status,
            "model": self.model,
            "contacts": len(self.contacts),
            "first_e": None if first is None else first.e,
            "first_St": None if first is None else first.St,
            "legendre_first_e": None if first is None else self.legendre(first.St),
            "terminal_velocity": self.terminal_velocity,
            "time_scale": self.inputs.time_scale(),
            "energy_error": self.energy_error(),
            "impacts": self.contact_rows(),
            "inputs": {
                **inputs,
                "handover_jump": self.handover_jump,
                "ehd_multiple": self.ehd_multiple,
                "rest_apex": self.rest_apex,
                "model": self.model,
            },
        }

    def legendre(self, St: float) -> float:
        """Legendre et al. (2006)'s empirical e = e_dry exp(-35 / St_L) at the Stokes number St,
        with St_L including the added mass (:func:`ehdfem.dem.closedform.legendre`)."""
        ratio = self.inputs.liquid.density / self.inputs.sphere.density
        return float(legendre(St, self.inputs.e_dry, ratio))


def bounce(
    inputs: BounceInputs,
    model: str = "halfspace",
    nodes: int = DEFAULT_NODES,
    options: IntegratorOptions | None = None,
    handover_jump: float = HANDOVER_JUMP,
    ehd_multiple: float = EHD_MULTIPLE,
    max_bounces: int = 30,
    rest_apex: float = 1e-3,
) -> BounceResult:
    """The trajectory of a sphere settling onto a wall in a liquid and bouncing until it rests
    (module docstring). ``model``: the solids of the contacts, "halfspace" (the elastic
    half-space theory) or "rigid" (eps -> 0); the FE solids do not apply to the immersed film,
    which reaches beyond the sphere. ``nodes`` and ``options``: the film model's grid and
    time-step control. ``handover_jump`` in (0, 0.5), ``ehd_multiple`` >= 1: the hand-over
    criterion. ``max_bounces``: the most contacts computed. ``rest_apex``: an apex below this
    fraction of D ends the bounce."""
    if not isinstance(inputs, BounceInputs):
        raise checks.InputError(f"inputs must be BounceInputs, got {inputs!r}")
    checks.choice("model", model, MODELS)
    checks.integer("nodes", nodes, lower=20, upper=5000)
    checks.number(
        "handover_jump", handover_jump, lower=0.0, upper=0.5, lower_open=True, upper_open=True
    )
    checks.number("ehd_multiple", ehd_multiple, lower=1.0, upper=1e4)
    checks.integer("max_bounces", max_bounces, lower=1, upper=1000)
    checks.number("rest_apex", rest_apex, lower=0.0, upper=1.0, upper_open=True)
    far = FarField(inputs, handover_jump, ehd_multiple)
    if inputs.release_height is not None:
        gap, velocity = inputs.release_height, 0.0
    else:
        gap, velocity = inputs.start_gap, -inputs.start_speed
    if far.handover_margin(gap, velocity) <= 0.0:
        raise checks.InputError(
            f"the start gap {gap!r} m is inside the hand-over region of the film model: "
            "start the sphere higher"
        )
    run = _Bounce(far, model, nodes, options or IntegratorOptions(), rest_apex)
    status = run.go(FlightState(0.0, gap, velocity), max_bounces)
    return BounceResult(
        inputs,
        model,
        run.arrays(),
        run.contacts,
        status,
        far.terminal_velocity(),
        handover_jump,
        ehd_multiple,
        rest_apex,
    )


class _Bounce:
    """The loop of :func:`bounce`: flight legs and contacts, with the trajectory's samples."""

    def __init__(self, far: FarField, model, nodes, options, rest_apex):
        self.far, self.model, self.nodes, self.options = far, model, nodes, options
        self.rest_apex = rest_apex * far.inputs.diameter
        self.samples = {name: [] for name in TRAJECTORY_COLUMNS}
        self.contacts: list[Contact] = []
        self.film_dissipated = self.exit_loss = 0.0

    def go(self, start: FlightState, max_bounces) -> str:
        """Fly and collide from ``start`` until the sphere rests; returns the reason it
        stopped."""
        leg = self._fly(start, rising=False)
        while True:
            if leg.end == "inside":
                return "rest: the apex is inside the hand-over region"
            contact, exit_state = self._collide(leg)
            if contact.status != "rebound":
                return f"rest: the contact {ENDINGS[contact.status]}"
            rise = self._fly(exit_state, rising=True)
            contact.apex_gap, contact.apex_time = float(rise.gap[-1]), float(rise.time[-1])
            if rise.gap[-1] < self.rest_apex:
                return "rest: the apex is below rest_apex D"
            if len(self.contacts) >= max_bounces:
                return "stopped at the apex after max_bounces contacts"
            leg = self._fly(rise.last(), rising=False)

    def _fly(self, start, rising) -> Flight:
        leg = self.far.fly(start, rising)
        if leg.end != "inside":
            self._record_flight(leg)
        return leg

    def _record_flight(self, leg: Flight):
        far = self.far
        mass = np.array([far.inertia(gap)[0] for gap in leg.gap])
        self._append(
            time=leg.time,
            gap=leg.gap,
            velocity=leg.velocity,
            phase=["flight"] * len(leg.time),
            kinetic=0.5 * mass * leg.velocity**2,
            potential=far.net_weight * leg.gap,
            elastic=np.zeros(len(leg.time)),
            drag_dissipated=leg.drag_dissipated,
            history_dissipated=leg.history_dissipated,
        )

    def _append(self, **columns):
        count = len(columns["time"])
        columns.setdefault("contacts", [len(self.contacts)] * count)
        columns.setdefault("film_dissipated", [self.film_dissipated] * count)
        columns.setdefault("exit_loss", [self.exit_loss] * count)
        for name in TRAJECTORY_COLUMNS:
            self.samples[name].extend(np.asarray(columns[name]).tolist())

    def _collide(self, leg: Flight):
        """The contact after the falling ``leg``: the film model from the hand-over state (its
        inertia M(h_c), handing back at :meth:`FarField.exit_gap`, with the history force when
        ``contact_history``), its samples recorded; returns the Contact and the FlightState
        where flight resumes after a rebound (the speed e_n V0 sqrt(M(h_c) / M(h_exit)), e_n the
        collision's restitution, which keeps the kinetic energy across the added mass's change,
        as the flight's own equation does; plus the drag's kick with ``contact_drag``,
        :meth:`_exit_kick`)."""
        far, inputs = self.far, self.far.inputs
        start = leg.last()
        speed = -start.velocity
        mass, exit_gap = far.inertia(start.gap)[0], far.exit_gap(start.gap, speed)
        result, scales = self._film_collision(start, speed, mass, exit_gap)
        normal, params = result.normal, result.params
        energy_unit = mass * speed**2 / params.St
        at_end, times, samples = self._contact_samples(normal, start, scales)
        velocities = samples["velocity"] * speed
        exit_speed = normal.exit_velocity * speed
        rebound_speed = normal.e_n * speed * math.sqrt(mass / far.inertia(exit_gap)[0])
        jump = (np.append(times, times[-1]), np.append(velocities, rebound_speed))
        memory, history_impulse, history_work = self._carry_memory(
            start.gap, start.memory, *(jump if normal.rebound else (times, velocities))
        )
        history_work = start.history_work + inputs.contact_history * history_work
        self._record_contact(start, times, samples, energy_unit, history_work[: len(times)])
        film_dissipated = at_end["dissipated"] * energy_unit
        exit_loss = 0.5 * mass * (exit_speed**2 - (normal.e_n * speed) ** 2)
        exit_loss += at_end["elastic"] * energy_unit
        self.film_dissipated += film_dissipated
        self.exit_loss += exit_loss
        omitted = self._omitted(normal.history, normal.contact_time, scales, speed, mass)
        exit_state = FlightState(
            times[-1], exit_gap, rebound_speed, start.drag_work, history_work[-1], memory
        )
        if normal.rebound:
            exit_state = self._exit_kick(exit_state, omitted["drag_impulse"])
        impact = float(np.max(np.abs(leg.velocity)))
        contact = Contact(
            impact_speed=impact,
            St=inputs.stokes_number(impact),
            handover_gap=start.gap,
            handover_speed=speed,
            exit_gap=exit_gap,
            contact_St=params.St,
            eps=params.eps,
            p_cav=cavitation.suction_limit_output(params.p_cav),
            e=exit_state.velocity / impact,
            **self._jumps(normal.history, normal, scales),
            gravity_impulse=omitted["gravity_impulse"],
            remainder_impulse=omitted["remainder_impulse"],
            history_impulse=history_impulse / (mass * speed),
            film_dissipated=film_dissipated,
            exit_loss=exit_loss,
            film=outputs.in_si_where_possible(result),
        )
        self.contacts.append(contact)
        if normal.rebound:  # the exit's velocity jump (e_dry, the kick) as a second sample
            self._append_exit(exit_state)
        return contact, exit_state

    def _append_exit(self, state: FlightState):
        """The sample of the flight's start after a contact (the exit's velocity jump)."""
        inertia = self.far.inertia(state.gap)[0]
        self._append(
            time=[state.time],
            gap=[state.gap],
            velocity=[state.velocity],
            phase=["flight"],
            kinetic=[0.5 * inertia * state.velocity**2],
            potential=[self.far.net_weight * state.gap],
            elastic=[0.0],
            drag_dissipated=[state.drag_work],
            history_dissipated=[state.history_work],
        )

    def _exit_kick(self, state: FlightState, drag_impulse) -> FlightState:
        """The exit ``state`` with the flight's remainder's impulse over the contact [N s]
        added to its momentum when ``contact_drag``: v += J / M(h_exit), a first-order estimate
        of its effect on the rebound (the contact lasts 30-160 us, the impulse is below 1 % of
        the momentum), the kinetic energy it adds taken from the liquid (the drag's work
        column) and the velocity change carried into the memory as a jump."""
        inertia = self.far.inertia(state.gap)[0]
        velocity = state.velocity + self.far.inputs.contact_drag * drag_impulse / inertia
        work = 0.5 * inertia * (state.velocity**2 - velocity**2)
        memory = state.memory + (velocity - state.velocity) if len(state.memory) else state.memory
        return replace(state, velocity=velocity, drag_work=state.drag_work + work, memory=memory)

    def _carry_memory(self, gap, memory, times, velocities) -> tuple[np.ndarray, float, np.ndarray]:
        """The history force's memory after the contact handed over at ``gap`` [m] (the gap of
        the kernel's weights in it) whose velocity ``velocities`` [m/s] at ``times`` [s] it
        follows (the exit's jump included as the last sample), the impulse
        [N s] of the history force during it (applied in the contact's time stepping with
        ``contact_history``, else only measured) and its work on the liquid from the hand-over
        at each sample, -int F_H v dt [J] (trapezoidal rule, as the film model's
        :class:`ehdfem.motion.forces.HistoryForce` integrates it). With ``history_memory``
        "reset" the memory is emptied at exit; with "approach" it is the hand-over's memory
        faded over the contact, z_i e^(-duration / tau_i), without the contact's velocity
        change (variations that isolate the memory of the contact's reversal)."""
        far = self.far
        if not len(memory):
            return memory, 0.0, np.zeros(len(times))
        carried = unsteady.carry_memory(memory, times, velocities, far.relaxation_times)
        pairs = zip(velocities, carried, strict=True)
        force = np.array([far.history_force(gap, v, z) for v, z in pairs])
        impulse = float(trapezoid(force, times))
        work = -cumulative_trapezoid(force * velocities, times, initial=0.0)
        if far.inputs.history_memory == "reset":
            return np.zeros_like(memory), impulse, work
        if far.inputs.history_memory == "approach":
            faded = memory * np.exp(-(times[-1] - times[0]) / far.relaxation_times)
            return faded, impulse, work
        return carried[-1], impulse, work

    def _film_collision(self, start: FlightState, speed: float, mass: float, exit_gap: float):
        """The immersed EHD collision from the hand-over at ``start.gap`` (m, the contact's layer
        thickness x0) and approach ``speed`` (m/s, its V0), with the inertia ``mass`` [kg]
        (the sphere's own mass plus its added mass there), gravity and buoyancy if
        ``contact_gravity``, the history force from the flight's memory if ``contact_history``
        (:meth:`contact_history_force`), the surfaces' roughness (SI, scaled by the collision
        by this contact's x0) and asperity model, leaving at ``exit_gap`` [m]; returns the
        collision result (scaled) and its SI scales."""
        far, inputs, gap = self.far, self.far.inputs, start.gap
        physical = PhysicalCollision(
            radius=inputs.radius,
            sphere=inputs.sphere,
            wall=inputs.wall,
            liquid=inputs.liquid,
            speed=speed,
            layer_thickness=gap,
            layer="immersed",
            e_dry=inputs.e_dry,
            ambient_pressure=inputs.ambient_pressure,
            added_mass=mass - far.mass,
            cavitation=inputs.cavitation,
            gravity=inputs.gravity if inputs.contact_gravity else 0.0,
            sphere_roughness=inputs.sphere_roughness,  # sigma / x0 differs between contacts
            wall_roughness=inputs.wall_roughness,
        )
        options = replace(self.options, exit_gap=exit_gap / gap)
        numerics = Numerics(nodes=self.nodes, integrator=options)
        config = RunConfig(asperities=inputs.asperities, numerics=numerics)  # half-space
        forces = ()
        if inputs.contact_history and len(start.memory):
            forces = (far.contact_history_force(gap, speed, start.memory),)
        solids = None
        if self.model == "rigid":
            solids = RigidSolids(film_radii(physical.dimensionless(), self.nodes))
        result = collide(physical, config, compliance=solids, forces=forces)
        return result, physical.scales()

    def _contact_samples(self, normal, start: FlightState, scales) -> tuple:
        """The contact's samples from the hand-over ``start`` to the exit or the stop, the exit
        interpolated between the last two steps: the scaled gap, velocity, dissipated and
        elastic energy at the end (a dict), the samples' times [s] and the scaled samples of
        the same four (a dict)."""
        hist, end = normal.history, normal.contact_time
        names = ("gap", "velocity", "dissipated", "elastic")
        at_end = {name: float(np.interp(end, hist.time, getattr(hist, name))) for name in names}
        shown = hist.time <= end
        times = hist.time[shown]
        samples = {name: getattr(hist, name)[shown] for name in names}
        if normal.rebound:
            times = np.append(times, end)
            samples = {name: np.append(samples[name], at_end[name]) for name in names}
        return at_end, start.time + times * scales.time, samples

    def _record_contact(self, start: FlightState, times, samples, energy_unit, history_work):
        """Append the contact's samples (SI; ``samples`` scaled as :meth:`_contact_samples`
        gives them, energies by ``energy_unit`` = M V0^2 / St, in J) to the trajectory, with the
        history force's work on the liquid so far [J] at each. The potential energy follows
        the gap when gravity acts in the contact, else it is held at its hand-over value."""
        far, gap, speed = self.far, start.gap, -start.velocity
        velocities, gaps = samples["velocity"] * speed, samples["gap"] * gap
        height = gaps if far.inputs.contact_gravity else np.full(len(times), gap)
        self._append(
            time=times,
            gap=gaps,
            velocity=velocities,
            phase=["contact"] * len(times),
            contacts=[len(self.contacts) + 1] * len(times),
            kinetic=0.5 * far.inertia(gap)[0] * velocities**2,
            potential=far.net_weight * height,
            elastic=samples["elastic"] * energy_unit,
            drag_dissipated=np.full(len(times), start.drag_work),
            history_dissipated=history_work,
            film_dissipated=self.film_dissipated + samples["dissipated"] * energy_unit,
        )

    def _jumps(self, hist, normal, scales) -> dict:
        """Relative force jumps flight -> film at entry (X <= SETTLED_FILM) and before exit."""
        far = self.far
        x0, v0 = scales.gap, scales.velocity

        def jump(i):
            gap, velocity = hist.gap[i] * x0, hist.velocity[i] * v0
            flight = far.drag(gap, velocity)
            return float(1.0 - hist.force[i] * scales.force / flight)

        settled = np.flatnonzero(hist.gap <= SETTLED_FILM)
        entry = jump(int(settled[0])) if settled.size else math.nan
        leaving = np.flatnonzero((hist.time < normal.contact_time) & (hist.velocity > 0))
        exit_jump = jump(int(leaving[-1])) if normal.rebound and leaving.size else math.nan
        return {"entry_jump": entry, "exit_jump": exit_jump}

    def _omitted(self, hist, end, scales, speed, mass) -> dict:
        """Impulses of gravity-buoyancy (0 when it acts in the contact) and of the flight's
        remainder over the contact, relative to the hand-over momentum M V0 (the remainder's
        of its magnitude), and ``drag_impulse`` [N s], the remainder's signed impulse (positive
        away from the wall): int -6 pi mu a v (phi - 1 + lambda - a/h) dt, h the thinnest
        film."""
        far = self.far
        shown = hist.time <= end
        time = hist.time[shown] * scales.time
        gap = np.maximum(hist.min_film[shown], 1e-12) * scales.gap
        velocity = hist.velocity[shown] * speed
        phi = drag_factor(far.inputs.drag, far.reynolds(velocity))
        lam = brenner_factor(gap / far.inputs.radius)
        remainder = -far.stokes * velocity * (phi - 1.0 + lam - far.inputs.radius / gap)
        momentum = mass * speed
        weight = 0.0 if far.inputs.contact_gravity else far.net_weight
        return {
            "gravity_impulse": weight * end * scales.time / momentum,
            "remainder_impulse": float(trapezoid(np.abs(remainder), time)) / momentum,
            "drag_impulse": float(trapezoid(remainder, time)),
        }

    def arrays(self) -> dict:
        """The trajectory samples as numpy arrays."""
        return {name: np.asarray(values) for name, values in self.samples.items()}


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
