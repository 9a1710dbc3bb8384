"""Physical inputs, the dimensionless groups and the scales (Davis, Serayssol & Hinch 1986).

Throughout ehdfem: gap and film thickness are scaled by x0 (the layer thickness, the initial
gap), radius by sqrt(a x0), time by x0/V0, velocity by V0 (the normal impact speed), pressure by
mu V0 a / x0^2, force by 6 pi mu V0 a^2 / x0 (so that St dV/dT = F) and energy by m V0^2.
The groups are

    St = m V0 / (6 pi mu a^2),   eps = 4 theta mu V0 a^(3/2) / x0^(5/2),   delta = x0 / a,
    P_cav = (p_cav - p_ambient) x0^2 / (mu V0 a),
    theta = (1 - nu1^2)/(pi E1) + (1 - nu2^2)/(pi E2).

For two spheres, a and m are the reduced radius and mass. Material and liquid presets with
their sources live in :mod:`ehdfem.inputs.presets`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from .. import checks
from ..film import cavitation
from ..film.asperities import ASPERITY_DENSITY, ASPERITY_SLOPE, AsperityModel, ImpactAsperities
from ..film.asperities import MODELS as ASPERITY_MODELS
from ..film.gap import GAPS, GapChoice
from ..film.reynolds import LAYERS
from ..film.viscosity import LAWS as VISCOSITY_LAWS
from ..film.viscosity import ConstantViscosity, ViscosityLaw
from ..settings import (
    check_components,
    component,
    flat,
    from_flat,
    setting,
    validate,
    without_other_components,
)
from .presets import Liquid, Material, body, check_vapour_pressure

ATMOSPHERE = 101325.0  # Pa


def stokes_number(mass: float, speed: float, viscosity: float, radius: float) -> float:
    """St = m V0 / (6 pi mu a^2) (SI inputs)."""
    return mass * speed / (6.0 * math.pi * viscosity * radius**2)


def elastic_theta(*solids) -> float:
    """theta = sum (1 - nu^2)/(pi E) over ``solids`` (each with young_modulus [Pa] and
    poisson_ratio) [1/Pa]."""
    return sum((1 - s.poisson_ratio**2) / (math.pi * s.young_modulus) for s in solids)


def elasticity_parameter(theta, viscosity, speed, radius, layer_thickness) -> float:
    """eps = 4 theta mu V0 a^(3/2) / x0^(5/2) (SI inputs, theta in 1/Pa)."""
    return 4.0 * theta * viscosity * speed * radius**1.5 / layer_thickness**2.5


def reduced_radius(a1: float, a2: float) -> float:
    """a = a1 a2 / (a1 + a2) for two spheres (a2 = inf: a wall)."""
    return a1 if math.isinf(a2) else a1 * a2 / (a1 + a2)


def reduced_mass(m1: float, m2: float) -> float:
    """m = m1 m2 / (m1 + m2) for two spheres (m2 = inf: a wall)."""
    return m1 if math.isinf(m2) else m1 * m2 / (m1 + m2)


@dataclass(frozen=True)
class CollisionParameters:
    """Dimensionless inputs of one collision (DSH scales; see the module docstring).

    St > 0; eps > 0; delta = x0/a in (0, 1); e_dry in (0, 1] (1: pure EHD); layer "thin" or
    "immersed"; angle [deg] of the impact velocity from the wall normal, in [0, 90); spin =
    a Omega0 / V0 (positive in the rolling sense, see ehdfem.tangential.motion); inertia_factor
    k = I/(m a^2) in (0, 2/3] (2/5 solid, 2/3 thin shell); cavitation: a cavitation model with
    its scaled suction limit P_cav (a component of :data:`ehdfem.film.cavitation.MODELS`, by
    default truncation without a limit); viscosity: a viscosity law with its scaled constants
    (a component of :data:`ehdfem.film.viscosity.LAWS`, by default constant); gap: a choice
    of :data:`ehdfem.film.gap.GAPS`, the paraboloid (the asymptotic theory) or the exact
    spheres (thin layer only), or None, the solids' (:func:`ehdfem.film.gap.default_gap`);
    shear_traction: the tangential surface effects of order sqrt(delta) (True: the squeeze
    flow's shear traction loads the solids too and the film carries the liquid the faces' radial
    velocity drags), only the pressure (False), or None, the model's default (on for the FE
    solids, off for the half-space theory; :mod:`ehdfem.solids.halfspace`, docs/model.md);
    external_force: a constant force on the sphere, scaled by 6 pi mu V0 a^2 / x0, positive
    away from the wall (finite; 0: none);
    buoyant_weight: the sphere's weight less the displaced fluid's, (m - rho_f V_s) g, scaled
    likewise, positive towards the wall (finite; 0: no gravity) (:mod:`ehdfem.motion.forces`);
    asperities: the asperity model of the surfaces (a component of
    :data:`ehdfem.film.asperities.MODELS`) with their combined rms roughness sigma =
    sqrt(sigma_1^2 + sigma_2^2) by x0, in [0, 1) (0: smooth, the default), the Coulomb
    friction coefficient mu >= 0 of their solid contact, which acts where the normal motion has
    one (a solid impact, an asperity load; :mod:`ehdfem.tangential.friction`), and the model's
    own constants (Greenwood & Tripp's eta beta sigma and sigma/beta).
    """

    St: float = setting(help="Stokes number m V0 / (6 pi mu a^2)", lower=0.0, lower_open=True)
    eps: float = setting(
        help="elasticity parameter 4 theta mu V0 a^1.5 / x0^2.5", lower=0.0, lower_open=True
    )
    delta: float = setting(
        0.01, help="layer thickness x0 / a", lower=0.0, upper=1.0, lower_open=True,
        upper_open=True,
    )  # fmt: skip
    e_dry: float = setting(
        1.0, help="dry restitution (1: pure EHD)", lower=0.0, upper=1.0, lower_open=True
    )
    layer: str = setting("thin", help="liquid layer: thin, or the sphere immersed", choices=LAYERS)
    angle: float = setting(
        0.0, help="impact angle from the wall normal", unit="deg", lower=0.0, upper=90.0,
        upper_open=True,
    )  # fmt: skip
    spin: float = setting(0.0, help="initial spin, rolling sense positive", unit="a Omega0 / V0")
    inertia_factor: float = setting(
        0.4, help="sphere inertia I / (m a^2) (2/5 solid, 2/3 thin shell)", lower=0.0,
        upper=2 / 3, lower_open=True,
    )  # fmt: skip
    viscosity: ViscosityLaw = component(
        VISCOSITY_LAWS, ConstantViscosity(), help="viscosity law against pressure"
    )
    cavitation: cavitation.CavitationModel = component(
        cavitation.MODELS,
        cavitation.Truncation(),
        help="cavitation model: truncate at P_cav (the source's), mass-conserving (JFO), none",
    )
    gap: GapChoice | None = component(
        GAPS,
        None,
        help="undeformed gap: the theory's paraboloid or the true spheres (thin layer only)",
        default_text="exact for FE solids with a thin layer, paraboloid otherwise",
    )
    shear_traction: bool | None = setting(
        None,
        help="tangential surface effects: the squeeze flow's shear traction on the solids and "
        "the liquid their radial velocity carries",
        default_text="on for FE solids, off for the half-space theory",
    )
    external_force: float = setting(
        0.0,
        help="constant force on the sphere, positive away from the wall",
        unit="by 6 pi mu V0 a^2 / x0",
    )
    buoyant_weight: float = setting(
        0.0,
        help="the sphere's weight less its buoyancy, positive towards the wall",
        unit="by 6 pi mu V0 a^2 / x0",
    )
    asperities: AsperityModel = component(
        ASPERITY_MODELS,
        ImpactAsperities(),
        help="asperity contact of rough surfaces (roughness > 0): a solid collision with e_dry "
        "when the thinnest film reaches the roughness, or mixed lubrication (the asperities' "
        "pressure shares the load with the film; docs/model.md)",
    )

    def __post_init__(self):
        validate(self)
        check_components(self)
        if self.spin != 0.0 and self.tangential_speed == 0.0:
            raise checks.InputError(
                f"spin = {self.spin!r} needs an oblique impact (angle > 0): the tangential "
                "motion of a head-on impact is not solved, so its spin would be ignored",
                "spin",
            )
        if self.tangential_compliance != 0.0 and self.tangential_speed == 0.0:
            raise checks.InputError(
                f"tangential_compliance = {self.tangential_compliance!r} needs an oblique impact "
                "(angle > 0): a head-on impact puts no tangential load on the contact",
                "tangential_compliance",
            )
        if self.gap is not None and self.gap.thin_layer_only and self.layer == "immersed":
            raise checks.InputError(
                f"gap = {self.gap.name!r} needs layer = 'thin': the immersed film reaches "
                "beyond the sphere and its far-field closure assumes the paraboloid",
                "gap",
            )

    @classmethod
    def from_settings(cls, read: bool = False, **values) -> CollisionParameters:
        """The inputs of flat settings (:meth:`settings`: the fields, each component's name
        and its fields' keys, e.g. a viscosity law's name and ``alpha=3.0``); ``read``: values of a
        study file or JSON (P_cav None or "none" for no limit)."""
        return from_flat(cls, values, read)

    def with_settings(self, **changes) -> CollisionParameters:
        """These inputs with some flat settings changed (e.g. ``roughness=0.01``, or another
        component by name with its constants); a component's constants are kept where the
        component is, dropped where it changes to one without them."""
        kept = without_other_components(type(self), {**self.settings(), **changes})
        return from_flat(type(self), {**kept, **changes})

    def settings(self, written: bool = False) -> dict:
        """The flat settings (``written``: for a study file or JSON, P_cav None for no
        limit)."""
        return flat(self, written)

    @property
    def roughness(self) -> float:
        """The surfaces' combined rms roughness sigma (by x0; 0: smooth)."""
        return self.asperities.roughness

    @property
    def friction_coefficient(self) -> float:
        """Coulomb's friction coefficient of the surfaces' solid contact."""
        return self.asperities.friction_coefficient

    @property
    def tangential_compliance(self) -> float:
        """k_t/k_n of the solid impact's Hertz contact (0: the rigid-body Coulomb impact, and
        for asperity models without a single impact; :mod:`ehdfem.tangential.compliant_contact`)."""
        return getattr(self.asperities, "tangential_compliance", 0.0)

    @property
    def p_cav(self) -> float:
        """The cavitation model's suction limit P_cav (scaled; -inf: none)."""
        return self.cavitation.p_cav

    def cavitation_model(self):
        """A new solver of the film's cavitation model (:mod:`ehdfem.film.cavitation`)."""
        return self.cavitation.solver()

    def viscosity_law(self) -> ViscosityLaw:
        """The film's viscosity law mu(P)/mu0 (scaled, :mod:`ehdfem.film.viscosity`)."""
        return self.viscosity

    @property
    def tangential_speed(self) -> float:
        """U0 / V0 = tan(angle)."""
        return math.tan(math.radians(self.angle))


@dataclass(frozen=True)
class Scales:
    """SI units of the scaled quantities: gap [m], radius [m], time [s], velocity [m/s],
    pressure [Pa], force [N], energy [J], and the sphere radius a [m]."""

    gap: float
    radius: float
    time: float
    velocity: float
    pressure: float
    force: float
    energy: float
    sphere_radius: float


@dataclass(frozen=True)
class PhysicalCollision:
    """Physical inputs (SI): sphere radius [m], materials, liquid, impact speed |v| [m/s], angle
    from the normal [deg], layer thickness x0 [m], layer kind, e_dry, spin [rad/s], ambient
    pressure [Pa], cavitation pressure [Pa absolute; default: the liquid's vapour pressure],
    inertia factor, an optional sphere mass [kg] (default 4/3 pi a^3 rho), the added mass [kg]
    of liquid moving with it (in St, not in the weight; default 0), the cavitation model,
    the viscosity law, the pressure-viscosity coefficient alpha [1/Pa; default: the liquid's
    preset], the undeformed gap and the shear traction (as in :class:`CollisionParameters`), the
    gravity g [m/s^2] >= 0, towards the wall (default 0: none). Gravity acts through the
    buoyant weight (m - rho_f V_s) g (:attr:`scaled_buoyant_weight`), with rho_f the liquid's
    density when the sphere is immersed; in a thin layer the sphere is in the ambient gas, whose
    buoyancy is neglected (rho_f = 0). The surfaces' rms roughness sphere_roughness and
    wall_roughness [m] (default 0: smooth) combine to sigma = sqrt(s1^2 + s2^2) < x0; the
    asperities' eta beta sigma and sigma/beta are pure numbers, taken by the asperity model
    ``asperities`` that uses them (:class:`CollisionParameters`). The cavitation model, the
    viscosity law and the asperity model are named here; their scaled constants come from the
    physical inputs through their classes (``with_limit``, ``of_liquid``) and their registry
    (:meth:`ehdfem.settings.Registry.of_inputs`, which refuses another asperity model's
    constants).
    The friction coefficient of the solid contact and its tangential compliance k_t/k_n are
    dimensionless (as in :class:`CollisionParameters`; k_t/k_n of two materials from
    :func:`ehdfem.tangential.compliant_contact.mindlin_stiffness_ratio`).
    Roelands takes Z = alpha 1.96e8 Pa / (ln(mu0 / Pa s) + 9.67)."""

    radius: float = setting(
        help="sphere radius a", unit="m", lower=0.0, lower_open=True, checked=False
    )
    sphere: Material = field()
    wall: Material = field()
    liquid: Liquid = field()
    speed: float = setting(
        help="impact speed |v|", unit="m/s", lower=0.0, lower_open=True, checked=False
    )
    layer_thickness: float = setting(
        help="liquid layer thickness x0 (less than the radius a)", unit="m", lower=0.0,
        lower_open=True, checked=False,
    )  # fmt: skip
    angle: float = 0.0
    layer: str = "thin"
    e_dry: float = 1.0
    spin: float = setting(
        0.0, help="initial spin, rolling sense positive", unit="rad/s", flag="spin-rate",
        checked=False,
    )  # fmt: skip
    ambient_pressure: float = setting(
        ATMOSPHERE, help="ambient pressure", unit="Pa", lower=0.0, lower_open=True, checked=False
    )
    cavitation_pressure: float | None = setting(
        None, help="cavitation pressure, absolute, up to the ambient pressure", unit="Pa",
        lower=0.0, default_text="the liquid's vapour pressure", checked=False,
    )  # fmt: skip
    inertia_factor: float = 0.4
    sphere_mass: float | None = setting(
        None,
        help="sphere mass",
        unit="kg",
        lower=0.0,
        lower_open=True,
        default_text="4/3 pi a^3 rho",
        checked=False,
    )
    added_mass: float = setting(
        0.0,
        help="mass of liquid moving with the sphere, added to its inertia but not to its weight",
        unit="kg",
        lower=0.0,
        checked=False,
    )
    cavitation: str = setting(
        cavitation.Truncation.name,
        help="cavitation model: truncate at P_cav (the source's), mass-conserving (JFO), none",
        choices=cavitation.MODELS,
        checked=False,
    )
    viscosity: str = setting(
        ConstantViscosity.name,
        help="viscosity law against pressure",
        choices=VISCOSITY_LAWS,
        checked=False,
    )
    pressure_viscosity: float | None = setting(
        None, help="pressure-viscosity coefficient alpha, [0, 1e-6]", unit="1/Pa",
        default_text="the liquid's", checked=False,
    )  # fmt: skip
    gap: str | None = None
    shear_traction: bool | None = None
    gravity: float = setting(
        0.0,
        help="gravitational acceleration towards the wall, acting through the sphere's buoyant "
        "weight during the contact (0: none)",
        unit="m/s^2",
        lower=0.0,
        checked=False,
    )
    friction_coefficient: float = 0.0
    tangential_compliance: float = 0.0
    asperities: str = setting(
        ImpactAsperities.name,
        help="asperity contact of rough surfaces",
        choices=ASPERITY_MODELS,
        checked=False,
    )
    sphere_roughness: float = setting(
        0.0, help="rms roughness of the sphere's surface (combined with the wall's, less "
        "than the layer thickness)", unit="m", lower=0.0, checked=False,
    )  # fmt: skip
    wall_roughness: float = setting(
        0.0, help="rms roughness of the wall's surface", unit="m", lower=0.0, checked=False
    )
    asperity_density: float = ASPERITY_DENSITY
    asperity_slope: float = ASPERITY_SLOPE

    def __post_init__(self):
        for role, kind in (("sphere", Material), ("wall", Material), ("liquid", Liquid)):
            if not isinstance(getattr(self, role), kind):
                raise checks.InputError(
                    f"{role} must be a {kind.__name__} (see ehdfem.inputs.presets), "
                    f"got {getattr(self, role)!r}"
                )
        checks.positive("radius", self.radius)
        checks.positive("speed", self.speed)
        checks.positive("layer_thickness", self.layer_thickness)
        if self.layer_thickness >= self.radius:
            raise checks.InputError(
                f"layer_thickness = {self.layer_thickness!r} m must be smaller than the radius "
                f"{self.radius!r} m (the allowed range is (0, radius))",
                "layer_thickness",
            )
        checks.number("angle", self.angle, lower=0.0, upper=90.0, upper_open=True)
        checks.number("gravity", self.gravity, lower=0.0)
        checks.positive("ambient_pressure", self.ambient_pressure)
        if self.cavitation_pressure is not None:
            checks.number(
                "cavitation_pressure",
                self.cavitation_pressure,
                lower=0.0,
                upper=self.ambient_pressure,
            )
        else:
            check_vapour_pressure(self.liquid, self.ambient_pressure)
        if self.sphere_mass is not None:
            checks.positive("sphere_mass", self.sphere_mass)
        checks.number("added_mass", self.added_mass, lower=0.0)
        self._check_roughness()
        if self.pressure_viscosity is not None:
            checks.number("pressure_viscosity", self.pressure_viscosity, lower=0.0, upper=1e-6)
        checks.choice("viscosity", self.viscosity, VISCOSITY_LAWS.names())
        checks.choice("cavitation", self.cavitation, cavitation.MODELS.names())
        checks.choice("asperities", self.asperities, ASPERITY_MODELS.names())
        self.dimensionless()  # validates e_dry, layer, spin, inertia_factor and the groups

    def _check_roughness(self):
        """Each roughness >= 0 [m], their combination sigma below the layer thickness."""
        checks.number("sphere_roughness", self.sphere_roughness, lower=0.0)
        checks.number("wall_roughness", self.wall_roughness, lower=0.0)
        if self.roughness >= self.layer_thickness:
            raise checks.InputError(
                f"the combined roughness sqrt(sphere_roughness^2 + wall_roughness^2) = "
                f"{self.roughness!r} m must be smaller than layer_thickness "
                f"{self.layer_thickness!r} m (the allowed range is [0, layer_thickness))",
                "sphere_roughness",
            )

    @property
    def roughness(self) -> float:
        """sigma = sqrt(sphere_roughness^2 + wall_roughness^2) [m]."""
        return math.hypot(self.sphere_roughness, self.wall_roughness)

    @property
    def normal_speed(self) -> float:
        """V0 = |v| cos(angle) [m/s]."""
        return self.speed * math.cos(math.radians(self.angle))

    @property
    def tangential_speed(self) -> float:
        """U0 = |v| sin(angle) [m/s]."""
        return self.speed * math.sin(math.radians(self.angle))

    @property
    def mass(self) -> float:
        """Sphere mass [kg]."""
        if self.sphere_mass is not None:
            return self.sphere_mass
        return 4.0 / 3.0 * math.pi * self.radius**3 * self.sphere.density

    @property
    def theta(self) -> float:
        """theta = sum (1 - nu^2)/(pi E) of sphere and wall [1/Pa] (:func:`elastic_theta`)."""
        return elastic_theta(self.sphere, self.wall)

    @property
    def alpha(self) -> float:
        """The pressure-viscosity coefficient [1/Pa]: the given one, else the liquid's."""
        if self.pressure_viscosity is not None:
            return self.pressure_viscosity
        return self.liquid.pressure_viscosity

    @property
    def scaled_buoyant_weight(self) -> float:
        """W = (m - rho_f V_s) g by the force scale 6 pi mu V0 a^2 / x0: the sphere's weight
        less the displaced fluid's (SI: m [kg], V_s [m^3], rho_f [kg/m^3], g [m/s^2]), rho_f the
        liquid's density when immersed, 0 (the ambient gas neglected) in a thin layer; it
        pushes the sphere towards the wall when > 0."""
        fluid_density = self.liquid.density if self.layer == "immersed" else 0.0
        volume = 4.0 / 3.0 * math.pi * self.radius**3
        return (self.mass - fluid_density * volume) * self.gravity / self.scales().force

    def dimensionless(self) -> CollisionParameters:
        """St, eps, delta, e_dry, ... for these inputs, the cavitation model with its scaled
        P_cav and the viscosity law of the liquid (its ``of_liquid``)."""
        mu, a, x0, v0 = self.liquid.viscosity, self.radius, self.layer_thickness, self.normal_speed
        p_cav = (
            self.liquid.vapour_pressure
            if self.cavitation_pressure is None
            else self.cavitation_pressure
        )
        pressure_scale = mu * v0 * a / x0**2
        return CollisionParameters(
            St=stokes_number(self.mass + self.added_mass, v0, mu, a),
            eps=elasticity_parameter(self.theta, mu, v0, a, x0),
            delta=x0 / a,
            e_dry=self.e_dry,
            layer=self.layer,
            angle=self.angle,
            spin=self.spin * a / v0,
            inertia_factor=self.inertia_factor,
            cavitation=cavitation.MODELS[self.cavitation].with_limit(
                (p_cav - self.ambient_pressure) * x0**2 / (mu * v0 * a)
            ),
            viscosity=VISCOSITY_LAWS[self.viscosity].of_liquid(self.alpha, mu, pressure_scale),
            gap=None if self.gap is None else GAPS[self.gap](),
            shear_traction=self.shear_traction,
            buoyant_weight=self.scaled_buoyant_weight,
            asperities=ASPERITY_MODELS.of_inputs(
                self.asperities,
                {
                    "roughness": self.roughness / x0,
                    "friction_coefficient": self.friction_coefficient,
                    "asperity_density": self.asperity_density,
                    "asperity_slope": self.asperity_slope,
                    "tangential_compliance": self.tangential_compliance,
                },
            ),
        )

    def scales(self) -> Scales:
        """The SI units of the scaled results."""
        mu, a, x0, v0 = self.liquid.viscosity, self.radius, self.layer_thickness, self.normal_speed
        return Scales(
            gap=x0,
            radius=math.sqrt(a * x0),
            time=x0 / v0,
            velocity=v0,
            pressure=mu * v0 * a / x0**2,
            force=6.0 * math.pi * mu * v0 * a**2 / x0,
            energy=(self.mass + self.added_mass) * v0**2,
            sphere_radius=a,
        )


def from_presets(**values) -> PhysicalCollision:
    """A :class:`PhysicalCollision` (SI inputs) whose ``sphere``, ``wall`` (materials) and
    ``liquid`` are each given by preset name, as a Material or Liquid, or as a dict of values
    (SI) with an optional "preset" key whose values it changes (:func:`ehdfem.inputs.presets.body`),
    e.g. ``sphere={"young_modulus": 3e9, "poisson_ratio": 0.35, "density": 1200}``."""
    bodies = ("sphere", "wall", "liquid")
    return PhysicalCollision(**{k: body(k, v) if k in bodies else v for k, v in values.items()})


@dataclass(frozen=True)
class PhysicalPair:
    """Physical inputs (SI) of two free spheres colliding: the upper sphere's ``upper_radius``
    a1 [m] and material ``upper``, the lower one's ``lower_radius`` a2 [m] and ``lower``, each
    sphere of its material's density; the ``liquid``; the relative impact speed ``speed``
    |v1 - v2| [m/s] at the ``angle`` [deg] from the line of centres; the layer thickness x0 [m]
    (the gap at which the film starts acting) and its kind; the inertia factors
    k_i = I_i / (m_i a_i^2); the surfaces' friction coefficient. The pair collides as the
    sphere of the reduced radius a = a1 a2 / (a1 + a2) and mass m = m1 m2 / (m1 + m2) on the
    lower material (docs/tangential.md, "Two spheres"): :meth:`equivalent` is that sphere's
    :class:`PhysicalCollision` (theta of both materials, so that 1/E* = pi theta), and
    :meth:`lower_settings` the lower sphere's run settings (``lower="sphere"``, a1/a2,
    rho2/rho1, k2), for :func:`ehdfem.collision.collide` with :meth:`dimensionless`. Two
    materials enter the groups through theta alone; the sliding film's mode-1 elasticity takes
    the pair's half-spaces as identical solids (docs/tangential.md, "Two spheres")."""

    upper_radius: float
    lower_radius: float
    upper: Material
    lower: Material
    liquid: Liquid
    speed: float
    layer_thickness: float
    angle: float = 0.0
    layer: str = "thin"
    upper_inertia_factor: float = 0.4
    lower_inertia_factor: float = 0.4
    friction_coefficient: float = 0.0

    def __post_init__(self):
        checks.positive("upper_radius", self.upper_radius)
        checks.positive("lower_radius", self.lower_radius)
        checks.number(
            "lower_inertia_factor", self.lower_inertia_factor, lower=0.0, upper=2 / 3,
            lower_open=True,
        )  # fmt: skip
        self.equivalent()  # validates the rest against the equivalent sphere's ranges

    @property
    def masses(self) -> tuple[float, float]:
        """(m1, m2) = 4/3 pi a_i^3 rho_i [kg]."""
        volumes = (4.0 / 3.0 * math.pi * a**3 for a in (self.upper_radius, self.lower_radius))
        return tuple(v * m.density for v, m in zip(volumes, (self.upper, self.lower), strict=True))

    def equivalent(self) -> PhysicalCollision:
        """The sphere of the reduced radius and mass on the lower sphere's material."""
        return PhysicalCollision(
            radius=reduced_radius(self.upper_radius, self.lower_radius),
            sphere=self.upper,
            wall=self.lower,
            liquid=self.liquid,
            speed=self.speed,
            layer_thickness=self.layer_thickness,
            angle=self.angle,
            layer=self.layer,
            inertia_factor=self.upper_inertia_factor,
            sphere_mass=reduced_mass(*self.masses),
            friction_coefficient=self.friction_coefficient,
        )

    def lower_settings(self) -> dict:
        """The lower sphere's run settings: a1/a2, rho2/rho1 and k2 (module docstring)."""
        return dict(
            lower="sphere",
            radius_ratio=self.upper_radius / self.lower_radius,
            density_ratio=self.lower.density / self.upper.density,
            lower_inertia_factor=self.lower_inertia_factor,
        )

    def dimensionless(self) -> CollisionParameters:
        """St, eps, delta, ... by the reduced radius and mass (:meth:`equivalent`)."""
        return self.equivalent().dimensionless()

    def scales(self) -> Scales:
        """The SI units of the scaled results (force by the reduced radius, energy by the
        reduced mass)."""
        return self.equivalent().scales()
