"""The physical inputs of a bounce (SI): the sphere, wall and liquid, the start, and the
modelling choices of its flight and contacts (docs/bounce.md), each validated."""

from __future__ import annotations

import math
from dataclasses import dataclass

from .. import checks
from ..film import cavitation
from ..film.asperities import MODELS as ASPERITY_MODELS
from ..film.asperities import ImpactAsperities
from ..inputs.presets import Liquid, Material, body, check_vapour_pressure
from ..inputs.scales import ATMOSPHERE, elastic_theta, stokes_number
from .unsteady import HISTORY_KERNELS

GRAVITY = 9.81  # m/s^2
DRAG_LAWS = ("schiller-naumann", "abraham", "stokes")  # the steady drag laws of the flight
HISTORY_MEMORIES = ("keep", "reset", "approach")  # the history force's memory across a contact
SWITCHES = (  # the on/off modelling choices of BounceInputs
    "wall_added_mass",
    "contact_gravity",
    "clear_exit",
    "contact_history",
    "contact_drag",
)


@dataclass(frozen=True)
class BounceInputs:
    """Physical inputs of a bounce (SI): sphere radius a [m]; the sphere, wall and liquid (a
    preset name, a Material or Liquid, or a dict of values, as :func:`ehdfem.from_presets`);
    the start: ``release_height`` [m], the gap from which the sphere is released at rest, or
    ``start_gap`` [m] with ``start_speed`` [m/s] towards the wall; e_dry in (0, 1], applied at
    each exit as in the collision model (e_n = e_dry V_exit; rough: at the asperities'
    impact); the drag law (:data:`DRAG_LAWS`, :func:`ehdfem.bounce.flight.drag_factor`); the
    added-mass coefficient C_M in [0, 1] (far from the wall); gravity g [m/s^2]; the film's
    cavitation model (:data:`ehdfem.film.cavitation.MODELS`) with the ambient pressure [Pa]
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
    gap where a cavity can form (:meth:`ehdfem.bounce.flight.FarField.exit_gap`). The
    surfaces' rms roughness ``sphere_roughness`` and ``wall_roughness`` [m] (0: smooth), the
    same at every contact (scaled there by that contact's x0 = h_c), with the collision's
    ``asperities`` model (:data:`ehdfem.film.asperities.MODELS`). ``contact_history`` (default
    on): the history force acts in the contact's time stepping, so that the memory the flight
    carries on and the contact's motion are one (off: only its impulse is measured).
    ``contact_drag`` (default off, a variation, docs/bounce.md "The forces of the contact")
    adds the flight's remainder's impulse over the contact to the rebound's momentum at
    exit."""

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
    cavitation: str = cavitation.Truncation.name
    ambient_pressure: float = ATMOSPHERE
    history: str = "mei-adrian"
    history_memory: str = "keep"
    wall_added_mass: bool = True
    contact_gravity: bool = True
    clear_exit: bool = True
    sphere_roughness: float = 0.0
    wall_roughness: float = 0.0
    asperities: str = ImpactAsperities.name
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

    def start(self) -> tuple[float, float]:
        """The gap [m] and velocity [m/s] (positive away from the wall) at the start: at rest at
        ``release_height``, or at ``start_gap`` moving towards the wall at ``start_speed``."""
        if self.release_height is not None:
            return self.release_height, 0.0
        return self.start_gap, -self.start_speed
