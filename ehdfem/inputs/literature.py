"""Published facts on wet and immersed restitution, with their sources, for the validation
report (studies/validation.py, docs/validation.md) and its tests (tests/validation/).

Every number says how it was obtained:

- "abstract": stated in the abstract of the paper (the full texts were not reachable);
- "secondary": the paper's experimental parameters as re-typed by a third party (named);
- "introduction": stated in the introduction of the source paper of this project (Kantak &
  Davis 2006, "Elastohydrodynamic theory for wet oblique collisions"), which quotes the
  earlier work.

No value here was read off a figure; no published e-against-St data point was reachable, and
the sources whose numbers could not be obtained are listed in NOT_FOUND. All quantities SI.
"""

from __future__ import annotations

from dataclasses import dataclass

from .presets import Liquid, Material, material
from .scales import PhysicalCollision, from_presets

JOSEPH_2001 = (
    "Joseph, Zenit, Hunt & Rosenwinkel 2001, Particle-wall collisions in a viscous fluid, "
    "J. Fluid Mech. 433"
)
GONDRET_2002 = (
    "Gondret, Lance & Petit 2002, Bouncing motion of spherical particles in fluids, "
    "Phys. Fluids 14, 643"
)
DAVIS_2002 = (
    "Davis, Rager & Good 2002, Elastohydrodynamic rebound of spheres from coated surfaces, "
    "J. Fluid Mech. 468"
)
KANTAK_DAVIS_2006 = "Kantak & Davis 2006, Elastohydrodynamic theory for wet oblique collisions"


@dataclass(frozen=True)
class Claim:
    """A published statement that the model can be checked against: ``value`` (None where
    the source states a trend, not a number), the ``band`` we accept as agreement and why."""

    source: str
    obtained: str
    statement: str
    value: float | None
    band: tuple[float, float] | None
    band_reason: str


IMMERSED_CRITICAL_STOKES = Claim(
    JOSEPH_2001,
    "abstract",
    "no rebound below a Stokes number of approximately 10 (pendulum, D = 3-12 mm, "
    "rho_p/rho_f = 1.2-7.8, glycerol-water); Gondret et al. 2002 saw the same (as quoted by "
    "Biegert, Vowinckel & Meiburg 2017)",
    10.0,
    (5.0, 20.0),
    "'approximately 10' carries one significant figure and no scatter is given: we read it "
    "as within a factor of 2",
)
IMMERSED_DRY_LIMIT = Claim(
    JOSEPH_2001,
    "abstract",
    "for impact Stokes numbers above 500 the restitution appears to asymptote to the dry value",
    500.0,
    (0.9, 1.0),
    "we take 'asymptote' as e/e_dry >= 0.9 at St >= 500 (the pure-EHD e_n, e_dry = 1)",
)
CRITICAL_STOKES_AGAINST_EPS = Claim(
    DAVIS_2002,
    "abstract",
    "the critical Stokes number decreases weakly with increasing elasticity parameter",
    None,
    (-0.25, 0.0),
    "'weakly': the exponent B of St_c ~ eps^B between -0.25 and 0 (St_c changes by less "
    "than a factor of 3 over four decades of eps)",
)
RESTITUTION_FORM = Claim(
    DAVIS_2002,
    "introduction",
    "e = e_dry (1 - St_c/St) above St_c describes the measured restitution, 'with "
    "considerable scatter' (Kantak & Davis 2006, introduction); it also describes e_n in "
    "oblique impacts (Kantak & Davis 2004)",
    None,
    (0.0, 0.1),
    "the scatter is not quantified in what we have; we accept a largest deviation of the "
    "computed e_n from its best fit of this form up to 0.1",
)
TANGENTIAL_CLOSE_TO_ONE = Claim(
    KANTAK_DAVIS_2006,
    "abstract",
    "the tangential restitution is close to unity, independent of the impact angle and "
    "linear in the ratio of layer thickness to radius",
    None,
    (0.95, 1.0),
    "'close to unity' at delta = 0.01: we take e_t >= 0.95",
)
TANGENTIAL_TRENDS = Claim(
    KANTAK_DAVIS_2006,
    "abstract",
    "e_t is generally higher for a larger compliance parameter; it increases with St at small "
    "compliance and decreases with St at large compliance; the change of spin shows the "
    "reverse trends",
    None,
    None,
    "trends: tested along physical sweeps and one group at a time by studies/source_claims.py "
    "(verdicts in docs/validation.md)",
)

CLAIMS = (
    IMMERSED_CRITICAL_STOKES,
    IMMERSED_DRY_LIMIT,
    CRITICAL_STOKES_AGAINST_EPS,
    RESTITUTION_FORM,
    TANGENTIAL_CLOSE_TO_ONE,
    TANGENTIAL_TRENDS,
)

NOT_FOUND = {
    GONDRET_2002: "the measured e against St (tables and figures) and the spheres' and "
    "plate's elastic constants; only the abstract and a re-typing of five runs' parameters "
    "were reachable",
    JOSEPH_2001: "the measured e against St and the materials' e_dry",
    DAVIS_2002: "the St_c values, layer thicknesses and e_dry of the experiments",
    "Barnocky & Davis 1988, Phys. Fluids 31, 1324": "the critical drop heights and St_c",
    "Kantak & Davis 2004 (experiments) and 2006 (theory)": "e_n, e_t, St_c values and the "
    "closed-form fits (only the 2006 abstract and introduction are at hand)",
    "Joseph & Hunt 2004, J. Fluid Mech. 510": "e_n, e_t and friction coefficients",
    "Gollwitzer et al. 2012; Mueller & Huang 2016": "e_inf and St_c against film thickness",
    "Legendre et al. 2006, Chem. Eng. Sci.": "the data behind e/e_dry = exp(-35/St) (the "
    "formula itself is taken from its use in a CFD code, see ehdfem.dem.closedform)",
}


@dataclass(frozen=True)
class GondretRun:
    """One run of Gondret et al. 2002: a steel sphere dropped onto a plate in a liquid (SI).
    Parameters as re-typed in a fluid-particle benchmark input of the waLBerla code and, for
    the St = 27 and 152 runs, in Table 1 of Biegert, Vowinckel & Meiburg 2017 (the two agree
    to three digits). The measured e of these runs was not reachable."""

    label: str
    reynolds: float
    liquid_density: float
    viscosity: float
    sphere_density: float
    diameter: float

    @property
    def speed(self) -> float:
        """Impact speed V0 = Re mu / (rho_f D) [m/s]."""
        return self.reynolds * self.viscosity / (self.liquid_density * self.diameter)

    @property
    def sphere(self) -> Material:
        """The sphere: the published density with the steel preset's elastic constants
        (assumed; not in what we have of the source)."""
        steel = material("steel")
        return Material(
            "gondret_steel",
            steel.young_modulus,
            steel.poisson_ratio,
            self.sphere_density,
            f"{GONDRET_2002} (density); elastic constants of the steel preset",
        )

    @property
    def liquid(self) -> Liquid:
        """The liquid: published viscosity and density; vapour pressure and pressure-viscosity
        coefficient taken as 0."""
        return Liquid("gondret_liquid", self.viscosity, self.liquid_density, 0.0, 0.0, GONDRET_2002)

    def collision(self, gap_over_radius: float = 0.1) -> PhysicalCollision:
        """The run as an immersed collision. Assumptions (not in what we have of the source):
        the sphere and liquid of :attr:`sphere` and :attr:`liquid`, the plate is glass, and the
        lubrication region starts at a gap x0 = ``gap_over_radius`` a, where the sphere still
        moves at V0."""
        radius = self.diameter / 2
        return PhysicalCollision(
            radius=radius,
            sphere=self.sphere,
            wall=material("glass"),
            liquid=self.liquid,
            speed=self.speed,
            layer_thickness=gap_over_radius * radius,
            layer="immersed",
        )


GONDRET_RUNS = (
    GondretRun("St27", 30.0, 965.0, 100e-3, 7800.0, 6e-3),
    GondretRun("St100", 110.0, 953.0, 20e-3, 7800.0, 4e-3),
    GondretRun("St152", 164.0, 935.0, 10e-3, 7800.0, 3e-3),
    GondretRun("St192", 212.0, 953.0, 20e-3, 7800.0, 6e-3),
    GondretRun("St742", 788.0, 920.0, 5e-3, 7800.0, 5e-3),
)

# Spheres and liquids inside Joseph et al. 2001's ranges (D = 3-12 mm, rho_p/rho_f = 1.2-7.8,
# glycerol-water): (sphere preset, diameter [m], liquid preset).
JOSEPH_RANGE = (
    ("steel", 6e-3, "glycerol_80"),
    ("glass", 6e-3, "glycerol_80"),
    ("steel", 3e-3, "glycerol_50"),
    ("glass", 12e-3, "glycerol_90"),
    ("steel", 12e-3, "glycerol_90"),
)


def immersed_collision(sphere: str, diameter: float, liquid: str, speed: float = 1.0):
    """A sphere (preset name, diameter [m]) hitting a glass wall through a liquid (preset
    name) at ``speed`` [m/s], fully immersed, with the lubrication region from x0 = 0.1 a (the
    same assumption as :meth:`GondretRun.collision`)."""
    return from_presets(
        sphere=sphere,
        wall="glass",
        liquid=liquid,
        radius=diameter / 2,
        speed=speed,
        layer_thickness=0.05 * diameter,
        layer="immersed",
    )
