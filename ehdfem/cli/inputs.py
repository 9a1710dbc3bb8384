"""The inputs of one collision on the command line (collide, render): dimensionless
(CollisionParameters' fields, DSH scales) or physical (PhysicalCollision's, SI, with the
sphere, wall and liquid as presets and/or values), the options shared by both, and the run
configuration (:class:`ehdfem.RunConfig`'s flat settings). All generated from the
dataclasses' fields (:mod:`ehdfem.cli.arguments`)."""

from __future__ import annotations

import argparse
import warnings

from .. import CollisionParameters, PhysicalCollision, RunConfig, checks, from_presets
from ..config import Numerics, setting_classes
from ..film import cavitation
from ..film import viscosity as viscosity_laws
from ..inputs.presets import (
    EXAMPLE,
    LIQUID_RANGES,
    MATERIAL_RANGES,
    custom_liquid,
    custom_material,
    liquid,
    material,
)
from ..motion.timestepping import IntegratorOptions
from ..settings import components, default_name, flat_names
from ..solids.fe.bodies import LOWER_BODIES, Wall
from .arguments import add_fields, given, named_by_option

BODIES = ("sphere", "wall", "liquid")
PHYSICAL_TRIGGERS = ("radius", "speed", "layer_thickness")  # with a body: physical inputs
MATERIAL_OPTIONS = {  # option suffix: (Material field, metavar, help)
    "modulus": ("young_modulus", "E", "Young's modulus [Pa]"),
    "poisson": ("poisson_ratio", "NU", "Poisson's ratio"),
    "density": ("density", "RHO", "density [kg/m^3]"),
}
LIQUID_OPTIONS = {  # option: (Liquid field, metavar, help)
    "liquid_viscosity": ("viscosity", "MU", "liquid viscosity [Pa s] at ambient pressure"),
    "liquid_density": ("density", "RHO", "liquid density [kg/m^3]"),
    "vapour_pressure": ("vapour_pressure", "P", "vapour pressure [Pa, absolute], below ambient"),
}
SCALED = {"alpha": "pressure_viscosity", "p_cav": "cavitation_pressure"}  # scaled: SI


def _names(cls) -> set[str]:
    return set(flat_names(cls))


def shared() -> set[str]:
    """Fields of both input kinds with the same meaning (spin differs in unit)."""
    return (_names(CollisionParameters) & _names(PhysicalCollision)) - {"spin"}


def add_collision_arguments(parser, exclude=()) -> None:
    """Every input of one collision and its run configuration (``exclude``: run settings left
    out)."""
    both = shared()
    add_fields(
        parser.add_argument_group("dimensionless inputs (DSH scales)"),
        CollisionParameters,
        exclude=both,
    )
    phys = parser.add_argument_group("physical inputs (SI)")
    add_body_arguments(phys)
    add_fields(phys, PhysicalCollision, exclude=both)
    phys.add_argument(
        "--example",
        action="store_true",
        help="steel sphere (a = 6.35 mm) on glass through 0.3 mm of 100 cSt silicone oil, "
        "1 m/s at 30 deg; default: off",
    )
    add_fields(parser.add_argument_group("both"), CollisionParameters, names=both)
    add_run_arguments(parser, exclude)


def add_run_arguments(parser, exclude=()) -> None:
    """The run configuration's settings, by group (``exclude``: names left out)."""
    run = parser.add_argument_group("run configuration")
    add_fields(run, RunConfig, exclude=exclude)
    fe = parser.add_argument_group("lower body (--lower and its settings)")
    kinds = ", ".join(f"{kind} ({body.description})" for kind, body in LOWER_BODIES.items())
    fe.add_argument(
        "--lower",
        choices=tuple(LOWER_BODIES),
        default=argparse.SUPPRESS,
        help=f"body below the sphere: {kinds}; default: {Wall.kind}",
    )
    for body in LOWER_BODIES.values():
        add_fields(fe, body, exclude=exclude)
    num = parser.add_argument_group("numerics")
    for part in (Numerics, IntegratorOptions):
        add_fields(num, part, exclude=exclude)


def run_config(args) -> RunConfig:
    """The run configuration of the given settings (the others at their defaults)."""
    values = {} if not hasattr(args, "lower") else {"lower": args.lower}
    for cls in setting_classes():
        values.update(given(args, cls))
    return RunConfig.from_settings(**values)


def add_body_arguments(phys) -> None:
    """The sphere, wall and liquid: presets and their values (collide, render, bounce)."""
    phys.add_argument(
        "--sphere", help="sphere material preset (e.g. steel, glass; see ehdfem presets); "
        "default: none",
    )  # fmt: skip
    phys.add_argument("--wall", help="wall material preset; default: none")
    phys.add_argument(
        "--liquid",
        help="liquid preset (e.g. water, silicone_oil_100cst; see ehdfem presets); default: none",
    )
    for body in ("sphere", "wall"):
        for suffix, (field, metavar, text) in MATERIAL_OPTIONS.items():
            phys.add_argument(
                f"--{body}-{suffix}",
                type=float,
                metavar=metavar,
                help=f"{body} {text}, {checks.range_text(**MATERIAL_RANGES[field])}; changes "
                f"--{body}'s value, or with no preset give all three; default: the preset's",
            )
    for name, (field, metavar, text) in LIQUID_OPTIONS.items():
        phys.add_argument(
            _option(name),
            type=float,
            metavar=metavar,
            help=f"{text}, {checks.range_text(**LIQUID_RANGES[field])}; changes --liquid's "
            "value, or with no preset give all three; default: the preset's",
        )


def collision_inputs(args, sought: dict | None = None) -> CollisionParameters | PhysicalCollision:
    """The collision inputs of the arguments, refusing mixed or incomplete sets. ``sought``:
    the value of each input that is searched for rather than given (critical: St, or the
    speed [m/s] for physical inputs), which is then not required."""
    sought = sought or {}
    values = _physical_values(args)
    scaled_only = given(args, CollisionParameters).keys() - shared()
    physical_only = given(args, PhysicalCollision).keys() - shared()
    if values is None:
        for name in sorted(physical_only):
            counterpart = {v: k for k, v in SCALED.items()}.get(name)
            instead = f"; give the scaled {_option(counterpart)} instead" if counterpart else ""
            raise checks.InputError(f"{_option(name)} needs physical inputs{instead}", name)
        return _warn_of_settings_without_effect(args, _dimensionless(args, sought))
    values.update({k: v for k, v in sought.items() if k in _names(PhysicalCollision)})
    missing = [body_hint(name) for name in (*BODIES, *PHYSICAL_TRIGGERS) if name not in values]
    if missing:
        raise checks.InputError(f"physical inputs need {', '.join(missing)}")
    if scaled_only:
        names = sorted(scaled_only)
        instead = [_option(SCALED[n]) + " [SI]" for n in names if n in SCALED]
        raise checks.InputError(
            "give either dimensionless or physical inputs, not both: "
            f"{', '.join(map(_option, names))} are scaled"
            + (f"; physical inputs take {', '.join(instead)}" if instead else ""),
            names[0],
        )
    values.update(given(args, PhysicalCollision))
    values.update(given(args, CollisionParameters, shared()))
    own_liquid = args.liquid is None and not getattr(args, "example", False)
    viscosity = values.get("viscosity", viscosity_laws.ConstantViscosity.name)
    dependent = viscosity_laws.LAWS[viscosity].pressure_dependent
    if own_liquid and dependent and "pressure_viscosity" not in values:
        raise checks.InputError(
            f"--viscosity {viscosity} with a liquid of your own needs its "
            "--pressure-viscosity [1/Pa], [0, 1e-6]"
        )
    _warn_of_physical_options_without_effect(values, dependent)
    coefficient = values.get("pressure_viscosity", values["liquid"].pressure_viscosity)
    if dependent and coefficient == 0.0:
        warnings.warn(
            f"--viscosity {viscosity} has no effect: the pressure-viscosity coefficient of "
            f"{values['liquid'].name} is 0 (give --pressure-viscosity [1/Pa] for a liquid that "
            "thickens under pressure)",
            stacklevel=2,
        )
    try:
        return _warn_of_settings_without_effect(args, from_presets(**values))
    except checks.InputError as err:  # a physical field whose option is spelt otherwise
        renamed = named_by_option(err, PhysicalCollision)
        if renamed is not err:
            raise renamed from None
        raise


def _warn_of_physical_options_without_effect(values: dict, dependent: bool) -> None:
    """Warn of a given --pressure-viscosity with a viscosity law that takes none (not
    ``dependent`` on pressure), and of a given --cavitation-pressure with a cavitation model
    that has no suction limit: such options cannot act in the run."""
    if "pressure_viscosity" in values and not dependent:
        laws = [n for n in viscosity_laws.LAWS if viscosity_laws.LAWS[n].pressure_dependent]
        warnings.warn(
            "--pressure-viscosity has no effect with --viscosity "
            f"{values.get('viscosity', viscosity_laws.ConstantViscosity.name)} "
            f"(give --viscosity {' or '.join(laws)})",
            stacklevel=3,
        )
    model = values.get("cavitation", cavitation.Truncation.name)
    if "cavitation_pressure" in values and not cavitation.has_limit(model):
        warnings.warn(
            f"--cavitation-pressure has no effect with --cavitation {model} (unlimited suction)",
            stacklevel=3,
        )


TANGENTIAL_ONLY = (
    "tangential",
    "sliding_deformation",
    "inertia_factor",
    "friction_coefficient",
    "density_ratio",
    "lower_inertia_factor",
)


def _warn_of_settings_without_effect(args, inputs):
    """``inputs`` (CollisionParameters or PhysicalCollision), after a warning for each option
    given that cannot act in their run: the tangential motion's settings (its film model, the
    solids' mode-1 deformation, the spheres' inertia factors, the contact's friction, the lower
    sphere's density) on a
    head-on impact, where no tangential motion is solved; --sliding-deformation with another
    tangential film than the sliding film; a constant of another viscosity law or cavitation
    model than the one chosen (left out of the inputs: :func:`_foreign`)."""
    if inputs.angle == 0.0:
        for name in (n for n in TANGENTIAL_ONLY if hasattr(args, n)):
            warnings.warn(
                f"{_option(name)} has no effect on a head-on impact (no tangential motion is "
                "solved: give --angle)",
                stacklevel=3,
            )
    elif hasattr(args, "sliding_deformation"):
        film = getattr(args, "tangential", "couette")
        if film != "lubrication":
            warnings.warn(
                f"--sliding-deformation has no effect with --tangential {film} (it deforms the "
                "solids under the sliding film, --tangential lubrication)",
                stacklevel=3,
            )
    if isinstance(inputs, CollisionParameters):
        for role, name, key, owners in _foreign(given(args, CollisionParameters)):
            warnings.warn(
                f"{_option(key)} has no effect with --{role} {name} (give --{role} "
                f"{' or '.join(owners)})",
                stacklevel=3,
            )
    return inputs


def _foreign(values: dict) -> list[tuple[str, str, str, list[str]]]:
    """(role, chosen name, key, the components that have it) of each constant in ``values``
    (flat settings) of a component other than the one chosen for its role."""
    out = []
    for f, registry in components(CollisionParameters):
        name = values.get(f.name, default_name(f))
        out += [(f.name, name, k, registry.owners(k)) for k in registry.foreign(name, values)]
    return out


def _dimensionless(args, sought: dict) -> CollisionParameters:
    """The dimensionless inputs (DSH scales) of the arguments (and ``sought``'s)."""
    values = {k: v for k, v in sought.items() if k in _names(CollisionParameters)}
    values.update(given(args, CollisionParameters))
    example = ", or --example" if hasattr(args, "example") else ""
    for name in ("St", "eps"):
        if name not in values:
            raise checks.InputError(
                f"--{name} is required (or give physical inputs{example})", name
            )
    foreign = {key for _, _, key, _ in _foreign(values)}  # warned of with the others
    return CollisionParameters.from_settings(
        **{k: v for k, v in values.items() if k not in foreign}
    )


def _option(dest: str) -> str:
    """The command-line spelling of an argument's name: layer_thickness -> --layer-thickness."""
    return "--" + dest.replace("_", "-")


def body_hint(name: str) -> str:
    """How to give the physical input ``name`` (for the message listing what is missing)."""
    if name == "liquid":
        return f"--liquid (or {', '.join(map(_option, LIQUID_OPTIONS))})"
    if name in BODIES:
        values = ", ".join(_option(f"{name}_{suffix}") for suffix in MATERIAL_OPTIONS)
        return f"--{name} (or {values})"
    return _option(name)


def _physical_values(args) -> dict | None:
    """The physical inputs that select physical mode (SI; with --example, its values where not
    given), the sphere, wall and liquid as Material and Liquid; None when there are none."""
    values = dict(EXAMPLE) if getattr(args, "example", False) else {}
    values.update({n: getattr(args, n) for n in PHYSICAL_TRIGGERS if hasattr(args, n)})
    for name in BODIES:
        body = body_of(args, name, getattr(args, name) or values.get(name))
        values.pop(name, None)
        if body is not None:
            values[name] = body
    return values or None


def body_of(args, name: str, preset: str | None):
    """The sphere's or wall's Material, or the liquid's Liquid, from its preset and the values
    given on the command line (which change the preset's); None when neither is given."""
    if name == "liquid":
        options, build = LIQUID_OPTIONS, custom_liquid
    else:
        options = {f"{name}_{suffix}": spec for suffix, spec in MATERIAL_OPTIONS.items()}
        build = custom_material
    values = {dest: getattr(args, dest) for dest in options if getattr(args, dest) is not None}
    if preset is None and not values:
        return None
    if isinstance(preset, str):
        try:  # the preset alone first, so that an unknown name is refused by its option
            (liquid if name == "liquid" else material)(preset)
        except checks.InputError as err:
            raise checks.InputError(str(err), name) from None
    field = {dest: spec[0] for dest, spec in options.items()}
    labels = {field[dest]: _option(dest) for dest in options}
    return build(preset, labels=labels.get, **{field[dest]: v for dest, v in values.items()})
