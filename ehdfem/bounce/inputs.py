"""The physical inputs of a bounce (SI): the sphere, wall and liquid, the start, and the
modelling choices of its flight and contacts (docs/bounce.md), each declared with its help,
unit, allowed values and default (:func:`ehdfem.settings.setting`), validated, and
turned into the options of ``ehdfem bounce`` (:mod:`ehdfem.cli.bounce`)."""

from __future__ import annotations

import math
from dataclasses import dataclass

from .. import checks
from ..film import cavitation
from ..film.asperities import MODELS as ASPERITY_MODELS
from ..film.asperities import ImpactAsperities
from ..film.viscosity import LAWS as VISCOSITY_LAWS
from ..film.viscosity import ConstantViscosity
from ..inputs.presets import Liquid, Material, body, check_vapour_pressure
from ..inputs.scales import ATMOSPHERE, elastic_theta, stokes_number
from ..settings import setting, validate
from .unsteady import HISTORY_KERNELS

GRAVITY = 9.81  # m/s^2
DRAG_LAWS = ("schiller-naumann", "abraham", "stokes")  # the steady drag laws of the flight
HISTORY_MEMORIES = ("keep", "reset", "approach")  # the history force's memory across a contact


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
    :class:`ehdfem.PhysicalCollision`); the film's viscosity law
    (:data:`ehdfem.film.viscosity.LAWS`) with the pressure-viscosity coefficient alpha [1/Pa]
    (default: the liquid's), whose scaled constants each contact takes from its own pressure
    scale (the flight's drag and history force use mu0, the pressure there being ambient). The
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

    radius: float = setting(help="sphere radius a", unit="m", lower=0.0, upper=1.0, lower_open=True)
    sphere: Material | str | dict
    wall: Material | str | dict
    liquid: Liquid | str | dict
    release_height: float | None = setting(
        None,
        help="gap at which the sphere is released at rest",
        unit="m",
        lower=0.0,
        upper=100.0,
        lower_open=True,
        default_text="none (give it, or the start gap with the start speed)",
    )
    start_gap: float | None = setting(
        None, help="or: the start gap, with the start speed", unit="m", lower=0.0, upper=100.0,
        lower_open=True,
    )  # fmt: skip
    start_speed: float | None = setting(
        None, help="speed towards the wall at the start gap", unit="m/s", lower=0.0, upper=100.0
    )
    e_dry: float = setting(
        1.0, help="dry restitution (1: pure EHD)", lower=0.0, upper=1.0, lower_open=True
    )
    drag: str = setting("schiller-naumann", help="steady drag law", choices=DRAG_LAWS)
    added_mass: float = setting(
        0.5,
        help="added-mass coefficient C_M far from the wall (collide's --added-mass is a mass "
        "in kg)",
        lower=0.0,
        upper=1.0,
        flag="added-mass-coefficient",
    )
    gravity: float = setting(
        GRAVITY, help="gravitational acceleration g", unit="m/s^2", lower=0.0, upper=100.0,
        lower_open=True,
    )  # fmt: skip
    cavitation: str = setting(
        cavitation.Truncation.name,
        help="film cavitation model, at the liquid's vapour pressure",
        choices=cavitation.MODELS,
    )
    ambient_pressure: float = setting(
        ATMOSPHERE, help="ambient pressure", unit="Pa", lower=0.0, lower_open=True
    )
    viscosity: str = setting(
        ConstantViscosity.name,
        help="viscosity law against pressure of the contacts' films (mu0 in flight)",
        choices=VISCOSITY_LAWS,
    )
    pressure_viscosity: float | None = setting(
        None,
        help="pressure-viscosity coefficient alpha of a pressure-dependent viscosity law",
        unit="1/Pa",
        lower=0.0,
        upper=1e-6,
        default_text="the liquid's",
    )
    history: str = setting(
        "mei-adrian",
        help="history (Basset) force in flight: Mei & Adrian's finite-Re kernel; the same with "
        "the wall-bounded unsteady Stokes kernel in place of Basset's (mei-adrian-wall); "
        "Basset's; none",
        choices=HISTORY_KERNELS,
    )
    history_memory: str = setting(
        "keep",
        help="the history force's memory across a contact: keep the contact's velocity change, "
        "reset it at each exit, or keep only the approach's memory (the contact's velocity "
        "change forgotten at exit)",
        choices=HISTORY_MEMORIES,
    )
    wall_added_mass: bool = setting(
        True, help="the added mass rises near the wall (the sphere's image)"
    )
    contact_gravity: bool = setting(True, help="gravity and buoyancy act during the contacts")
    clear_exit: bool = setting(
        True, help="the film model hands back above the gap where a cavity can form"
    )
    sphere_roughness: float = setting(
        0.0,
        help="rms roughness of the sphere's surface (0: smooth; at most 0.01 a)",
        unit="m",
        checked=False,  # its upper bound is the radius's: checked in __post_init__
    )
    wall_roughness: float = setting(
        0.0,
        help="rms roughness of the wall's surface (0: smooth; at most 0.01 a)",
        unit="m",
        checked=False,
    )
    asperities: str = setting(
        ImpactAsperities.name,
        help="asperity contact of rough surfaces at each contact (docs/model.md)",
        choices=ASPERITY_MODELS,
    )
    contact_history: bool = setting(
        True, help="the history force acts in each contact's time stepping"
    )
    contact_drag: bool = setting(
        False, help="the flight's remainder drag's impulse over each contact added at exit"
    )

    def __post_init__(self):
        for role in ("sphere", "wall", "liquid"):
            object.__setattr__(self, role, body(role, getattr(self, role)))
        validate(self)
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
        if not released and (self.start_gap is None or self.start_speed is None):
            raise checks.InputError("start_gap and start_speed must be given together")
        check_vapour_pressure(self.liquid, self.ambient_pressure)
        if (
            self.pressure_viscosity is not None
            and not VISCOSITY_LAWS[self.viscosity].pressure_dependent
        ):
            raise checks.InputError(
                f"pressure_viscosity = {self.pressure_viscosity!r} acts only with a "
                f"pressure-dependent viscosity law, not viscosity = {self.viscosity!r}",
                "pressure_viscosity",
            )
        for surface in ("sphere_roughness", "wall_roughness"):
            checks.number(surface, getattr(self, surface), lower=0.0, upper=0.01 * self.radius)

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
