"""The run configuration: how a collision is computed, beside what collides
(:class:`ehdfem.inputs.scales.CollisionParameters` or ``PhysicalCollision``).

:class:`RunConfig` holds the elasticity model, the lower body (a registered
:class:`ehdfem.solids.fe.bodies.LowerBody`: :class:`Wall`; :class:`CoatedWall` for the FE model;
:class:`LowerSphere`, a second free sphere, in both), the tangential film model and its mode-1
deformation, and the numerics (:class:`Numerics`: film nodes, refinements and the time
integration's :class:`ehdfem.motion.timestepping.IntegratorOptions`). Every field carries its
help, unit or scale and allowed values (:mod:`ehdfem.settings`); lengths of the lower
body are scaled by the (reduced) sphere radius a, moduli by the wall's Young's modulus.

Its flat form (:meth:`RunConfig.settings`, :meth:`RunConfig.from_settings`) names every
setting once (model, lower, coating_thickness, ..., nodes, rtol, order, ...): the keys of
study files, of the command line and of the JSON ``inputs["run"]``. :func:`read_inputs`
rebuilds the inputs and the configuration of a collision from its JSON ``inputs``.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field

from . import checks
from .inputs.presets import Liquid, Material
from .inputs.scales import CollisionParameters, PhysicalCollision
from .motion.timestepping import IntegratorOptions
from .settings import described, setting, validate, without_other_components
from .solids.fe.bodies import LOWER_BODIES, LowerBody, Wall
from .tangential.motion import DEFORMATIONS
from .tangential.motion import MODELS as TANGENTIAL_MODELS
from .tangential.outer_film import OUTER_FLOWS, check_outer_flow
from .tangential.pair import PAIR_MODELS

MODELS = ("halfspace", "fem")
DEFAULT_NODES = 240


@dataclass(frozen=True)
class Numerics:
    """Film nodes, grid refinements after a closed film, and the time integration."""

    nodes: int = setting(DEFAULT_NODES, help="film nodes", lower=20, upper=5000)
    refinements: int = setting(
        2, help="times the film grid is doubled when the film closes on it", lower=0, upper=4
    )
    integrator: IntegratorOptions = field(default_factory=IntegratorOptions)

    def __post_init__(self):
        validate(self)
        if not isinstance(self.integrator, IntegratorOptions):
            raise checks.InputError(
                f"integrator must be IntegratorOptions, got {self.integrator!r}", "integrator"
            )


def curved_lower_sliding(kind: str) -> str:
    """The refusal of the sliding film over a curved FE lower body of ``kind``, whose mode-1
    compliance is not built."""
    return (
        "tangential = 'lubrication' on FE solids needs a wall or coated wall below the sphere "
        f"(lower = {kind!r} is not supported: the mode-1 compliance of a curved FE lower body is "
        "not built, docs/tangential.md 'Two spheres'); use model = 'halfspace', or tangential = "
        "'couette', 'flat' or 'gcb'"
    )


@dataclass(frozen=True)
class RunConfig:
    """How one collision is computed: the elasticity model, the lower body, the
    tangential film model (solved for oblique impacts) with the mode-1 deformation of its
    solids, and the numerics. See the module docstring
    for the flat settings."""

    model: str = setting(
        "halfspace",
        help="elasticity of the solids: half-space kernel or FE solids",
        choices=MODELS,
    )
    lower: LowerBody = field(default_factory=Wall)
    tangential: str = setting(
        "couette",
        help="film model of the tangential motion: 'couette' (the source's shear only), "
        "'lubrication' (the sliding film), or the reduced 'gcb' and 'flat' "
        "(docs/tangential.md)",
        choices=TANGENTIAL_MODELS,
    )
    deformation: str = setting(
        "gap",
        help="mode-1 deformation of the solids under the sliding film (tangential "
        "lubrication): the normal displacements, also the tangential ones, or rigid ('none', "
        "exact for rigid solids only)",
        choices=DEFORMATIONS,
        flag="sliding-deformation",
    )
    outer_flow: str = setting(
        "none",
        help="the flow beyond an immersed film's tangential integrals, which end at the "
        "sphere's radius: left out and estimated ('none'), or added as Goldman, Cox & "
        "Brenner's exact remainder for a rigid sphere ('exact'; docs/tangential.md)",
        choices=OUTER_FLOWS,
    )
    numerics: Numerics = field(default_factory=Numerics)

    def __post_init__(self):
        validate(self)
        if LOWER_BODIES.get(getattr(self.lower, "kind", None)) is not type(self.lower):
            raise checks.InputError(
                f"lower must be a registered lower body ({', '.join(LOWER_BODIES)}), got "
                f"{self.lower!r}",
                "lower",
            )
        if not isinstance(self.numerics, Numerics):
            raise checks.InputError(f"numerics must be Numerics, got {self.numerics!r}")
        if self.model not in self.lower.models:
            raise checks.InputError(
                f"lower = {self.lower.kind!r} needs model = "
                f"{' or '.join(map(repr, self.lower.models))} (the half-space model stands for "
                "a uniform wall or a second sphere)",
                "lower",
            )
        curved = self.lower.radius is not None
        if curved and (self.tangential not in PAIR_MODELS or self.tangential == "lubrication"):
            if self.tangential != "lubrication" or self.model == "fem":
                raise checks.InputError(curved_lower_sliding(self.lower.kind), "tangential")
        if self.outer_flow == "exact" and self.lower.radius is not None:
            raise checks.InputError(
                "outer_flow = 'exact' needs a flat lower body, a wall below: its resistances are "
                f"a sphere's near a wall (lower = {self.lower.kind!r} is curved)",
                "outer_flow",
            )

    def check_inputs(self, params: CollisionParameters) -> None:
        """Refuse a setting that does not apply to ``params`` (scaled inputs): outer_flow =
        'exact' without an oblique impact through an immersed layer, and a lower sphere's spin
        on a head-on impact."""
        check_outer_flow(self.outer_flow, self.tangential, params.layer, params.angle)
        spin = getattr(self.lower, "lower_spin", 0.0)
        if spin != 0.0 and params.tangential_speed == 0.0:
            raise checks.InputError(
                f"lower_spin = {spin!r} needs an oblique impact (angle > 0): the tangential "
                "motion of a head-on impact is not solved, so its spin would be ignored",
                "lower_spin",
            )

    @property
    def options(self) -> IntegratorOptions:
        """The time integration's options."""
        return self.numerics.integrator

    def settings(self) -> dict:
        """The flat settings: every field by its name, the lower body's kind as "lower"."""
        out = {f.name: getattr(self, f.name) for f in described(RunConfig)}
        out["lower"] = self.lower.kind
        for part in (self.lower, self.numerics, self.numerics.integrator):
            out.update({f.name: getattr(part, f.name) for f in described(type(part))})
        return out

    @classmethod
    def from_settings(cls, **values) -> RunConfig:
        """The configuration of flat settings (any subset of :func:`setting_names`; the others
        at their defaults), e.g. ``RunConfig.from_settings(model="fem", nodes=120)``. A lower
        body's field needs that lower body."""
        unknown = sorted(set(values) - set(setting_names()))
        if unknown:
            raise checks.InputError(
                f"unknown run setting(s) {', '.join(unknown)}; allowed: "
                f"{', '.join(setting_names())}",
                unknown[0],
            )
        kind = checks.choice("lower", values.pop("lower", Wall.kind), tuple(LOWER_BODIES))
        for other, body in LOWER_BODIES.items():
            for f in described(body):
                if f.name in values and other != kind:
                    raise checks.InputError(
                        f"{f.name} needs lower = {other!r}, not {kind!r}", f.name
                    )
        parts = {
            part: {f.name: values.pop(f.name) for f in described(part) if f.name in values}
            for part in (LOWER_BODIES[kind], Numerics, IntegratorOptions)
        }
        numerics = Numerics(
            **parts[Numerics], integrator=IntegratorOptions(**parts[IntegratorOptions])
        )
        body = LOWER_BODIES[kind]
        for f in dataclasses.fields(body):
            if f.name not in parts[body] and f.default is f.default_factory is dataclasses.MISSING:
                raise checks.InputError(f"lower = {kind!r} needs {f.name}", f.name)
        return cls(**values, lower=body(**parts[body]), numerics=numerics)


def setting_classes() -> tuple:
    """The dataclasses whose fields are run settings, in the order of the flat settings."""
    return (RunConfig, *LOWER_BODIES.values(), Numerics, IntegratorOptions)


def setting_names() -> tuple[str, ...]:
    """Every flat setting's name: RunConfig's fields, "lower", the lower bodies', the
    numerics' and the integrator's."""
    names = [f.name for cls in setting_classes() for f in described(cls)]
    return (*names[:1], "lower", *names[1:])


def read_inputs(inputs: dict) -> tuple[CollisionParameters | PhysicalCollision, RunConfig]:
    """The collision inputs (dimensionless or physical) and the run configuration of a
    collision's JSON ``inputs`` (:meth:`ehdfem.collision.CollisionResult.inputs`): its
    "parameters", "physical" and "run". Also reads the earlier formats: the one whose run
    options (model, nodes, rtol, tangential, deformation, solids) were at the top level, and
    the one whose "parameters" held every constant of every viscosity law, the suction
    limit whatever the cavitation model and the asperity constants whatever the asperity model
    (those of the components not chosen are left out), and whose run settings held the
    asperity model (now an input). A file without ``lu_precision`` (written before the LU in
    single precision) is read with "double", as it ran."""
    run = dict(inputs["run"]) if "run" in inputs else None
    moved = {"asperities": run.pop("asperities")} if run and "asperities" in run else {}
    if inputs.get("physical") is not None:
        collision = _physical({**inputs["physical"], **moved})
    else:
        parameters = {**inputs["parameters"], **moved}
        parameters = without_other_components(CollisionParameters, parameters)
        collision = CollisionParameters.from_settings(read=True, **parameters)
    # a file written before the LU in single precision (it has no lu_precision) ran in double:
    # replayed as it ran
    if run is not None:
        return collision, RunConfig.from_settings(**{"lu_precision": "double", **run})
    return collision, RunConfig.from_settings(
        lu_precision="double", **_earlier_run(inputs, collision)
    )


def _physical(values: dict) -> PhysicalCollision:
    """A PhysicalCollision from its JSON dict (materials and liquid as dicts, SI)."""
    bodies = {"sphere": Material, "wall": Material, "liquid": Liquid}
    return PhysicalCollision(**{k: bodies[k](**v) if k in bodies else v for k, v in values.items()})


def _earlier_run(inputs: dict, collision) -> dict:
    """The flat settings of the earlier JSON format: model, nodes, rtol, tangential,
    deformation and FESolids' ``solids`` (coating as (E, nu), E in the wall's unit: its
    Young's modulus for physical inputs, else 1) at the top level of ``inputs``."""
    run = {
        k: inputs[k] for k in ("model", "nodes", "rtol", "tangential", "deformation") if k in inputs
    }
    solids = inputs.get("solids") or {}
    if solids.get("lower", "wall") != "wall":
        run["lower"] = solids["lower"]
    if "radius_ratio" in solids:
        run["radius_ratio"] = solids["radius_ratio"]
    if "coating_thickness" in solids:
        run["coating_thickness"] = solids["coating_thickness"]
    if "coating" in solids:
        wall = collision.wall.young_modulus if isinstance(collision, PhysicalCollision) else 1.0
        run["coating_stiffness"] = solids["coating"][0] / wall
        run["coating_poisson"] = solids["coating"][1]
    return run
