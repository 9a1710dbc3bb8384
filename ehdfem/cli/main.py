"""Command line: ``ehdfem collide`` (one collision), ``ehdfem render`` (pictures of the FE
solids), ``ehdfem sweep`` (a study file over MPI ranks), ``ehdfem critical`` (the critical
Stokes number), ``ehdfem fit`` (closed-form fits), ``ehdfem presets`` (materials and liquids),
``ehdfem bounce`` (a sphere settling and bouncing in a liquid, its contacts EHD collisions).

Inputs are either dimensionless (``--St --eps --delta ...``, DSH scales) or physical (SI
units): presets (``--sphere --wall --liquid``) and/or their values (``--sphere-modulus``,
``--liquid-viscosity``, ...), with ``--radius --speed --layer-thickness``; ``--example`` runs a
steel sphere hitting a glass plate through a 0.3 mm silicone-oil layer at 30 degrees.

Output: the results table on standard output, or on standard error when ``--json -`` puts the
JSON alone on standard output. The form compiler's build log and VTK's warnings are hidden
unless ``--verbose`` (:mod:`ehdfem.console.quiet`); progress bars show on a terminal only
(:mod:`ehdfem.console.progress`).
"""

from __future__ import annotations

import argparse
import csv
import json
import sys
from dataclasses import asdict, fields
from pathlib import Path

import numpy as np

from .. import checks
from ..bounce.trajectory import (
    DRAG_LAWS,
    EHD_MULTIPLE,
    GRAVITY,
    HANDOVER_JUMP,
    BounceInputs,
    bounce,
)
from ..bounce.trajectory import MODELS as BOUNCE_MODELS
from ..collision import DEFAULT_NODES, MODELS, TANGENTIAL_MODELS, collide
from ..console.quiet import is_quiet, set_quiet
from ..dem.closedform import GROUPED, describe_ranges, fit_table, python_source
from ..film import cavitation
from ..film.gap import GAPS
from ..film.reynolds import LAYERS
from ..film.viscosity import LAWS as VISCOSITY_LAWS
from ..film.viscosity import ROELANDS_INDEX
from ..inputs.presets import (
    EXAMPLE,
    LIQUID_RANGES,
    LIQUIDS,
    MATERIAL_RANGES,
    MATERIALS,
    custom_liquid,
    custom_material,
)
from ..inputs.scales import ATMOSPHERE, CollisionParameters, PhysicalCollision, from_presets
from ..motion.normal import NormalSolverError
from ..motion.timestepping import IntegratorOptions
from ..outputs import plots as viz
from ..outputs.fields import field_snapshots, write_fields
from ..solids.fe.bodies import LOWER_BODIES
from ..study.sweep import Study, _write_atomic, critical_stokes, run_study, write_csv
from ..tangential.motion import DEFORMATIONS
from ..version import __version__

DESCRIPTION = (
    "Elastohydrodynamic wet collisions: a sphere hits a wall through a liquid layer; ehdfem "
    "predicts rebound or sticking, the restitution coefficients, the film's pressure and "
    "thickness, and the critical Stokes number."
)
BODIES = ("sphere", "wall", "liquid")
SCALAR_PHYSICAL = ("radius", "speed", "layer_thickness")
PHYSICAL = (*BODIES, *SCALAR_PHYSICAL)
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


def _collision_arguments(c) -> None:
    """The inputs of one collision (shared by collide and render)."""
    dim = c.add_argument_group("dimensionless inputs (DSH scales)")
    dim.add_argument("--St", type=float, help="Stokes number m V0 / (6 pi mu a^2), > 0")
    dim.add_argument(
        "--eps", type=float, help="elasticity parameter 4 theta mu V0 a^1.5 / x0^2.5, > 0"
    )
    dim.add_argument(
        "--delta", type=float, default=0.01, help="layer thickness / radius x0/a, (0, 1)"
    )
    dim.add_argument(
        "--p-cav",
        type=float,
        default=None,
        help="cavitation pressure (p_cav - p_ambient) x0^2/(mu V0 a), <= 0; default: none",
    )
    dim.add_argument("--spin", type=float, default=0.0, help="initial spin a Omega0 / V0")
    _physical_arguments(c.add_argument_group("physical inputs (SI)"))
    common = c.add_argument_group("both")
    common.add_argument(
        "--angle", type=float, default=None, help="impact angle from the wall normal [deg], [0, 90)"
    )
    common.add_argument("--layer", choices=LAYERS, default="thin")
    _film_arguments(common, dim)
    common.add_argument(
        "--e-dry", type=float, default=1.0, help="dry restitution, (0, 1]; 1 = pure EHD"
    )
    _numerics_arguments(c.add_argument_group("numerics and output"))
    _solids_arguments(c.add_argument_group("FE solids (--model fem)"))


def _physical_arguments(phys) -> None:
    """The physical (SI) inputs of one collision."""
    _body_arguments(phys)
    phys.add_argument("--radius", type=float, help="sphere radius a [m]")
    phys.add_argument("--speed", type=float, help="impact speed |v| [m/s]")
    phys.add_argument("--layer-thickness", type=float, help="liquid layer thickness x0 [m]")
    phys.add_argument(
        "--pressure-viscosity",
        type=float,
        help="pressure-viscosity coefficient alpha [1/Pa], [0, 1e-6]; default: the liquid's",
    )
    phys.add_argument(
        "--example",
        action="store_true",
        help="steel sphere (a = 6.35 mm) on glass through 0.3 mm of 100 cSt silicone oil, "
        "1 m/s at 30 deg",
    )


def _body_arguments(phys) -> None:
    """The sphere, wall and liquid: presets and their values (collide, render, bounce)."""
    phys.add_argument(
        "--sphere", help="sphere material preset (e.g. steel, glass; see ehdfem presets)"
    )
    phys.add_argument("--wall", help="wall material preset")
    phys.add_argument(
        "--liquid", help="liquid preset (e.g. water, silicone_oil_100cst; see ehdfem presets)"
    )
    for body in ("sphere", "wall"):
        for suffix, (field, metavar, text) in MATERIAL_OPTIONS.items():
            phys.add_argument(
                f"--{body}-{suffix}",
                type=float,
                metavar=metavar,
                help=f"{body} {text}, {checks.range_text(**MATERIAL_RANGES[field])}; changes "
                f"--{body}'s value, or with no preset give all three",
            )
    for option, (field, metavar, text) in LIQUID_OPTIONS.items():
        phys.add_argument(
            _option(option),
            type=float,
            metavar=metavar,
            help=f"{text}, {checks.range_text(**LIQUID_RANGES[field])}; changes --liquid's "
            "value, or with no preset give all three",
        )


def _numerics_arguments(num) -> None:
    """Model choice, grid, tolerance and outputs of one collision."""
    num.add_argument("--model", choices=MODELS, default="halfspace")
    num.add_argument(
        "--tangential",
        choices=TANGENTIAL_MODELS,
        default="couette",
        help="film model of the tangential motion (oblique impacts): 'couette' (the source's "
        "shear only), 'lubrication' (the sliding film: mode-1 pressure on both deformed "
        "surfaces), or the reduced 'gcb' (rigid-sphere logarithms at the thinnest film) and "
        "'flat' (Couette over the Hertz disk); docs/tangential.md",
    )
    num.add_argument(
        "--sliding-deformation",
        choices=DEFORMATIONS,
        default="gap",
        help="mode-1 deformation of the solids under the sliding film (--tangential "
        "lubrication): 'gap' the normal displacements (default), 'full' also the tangential "
        "ones in the slip, 'none' rigid mode-1 solids (exact for rigid solids only)",
    )
    num.add_argument("--nodes", type=int, default=DEFAULT_NODES, help="film nodes")
    num.add_argument(
        "--rtol", type=float, default=IntegratorOptions.rtol, help="time-step tolerance"
    )
    num.add_argument("--json", metavar="FILE", help="write the results as JSON ('-' for stdout)")
    num.add_argument("--plots", metavar="DIR", help="write PNG plots into DIR")
    num.add_argument(
        "--field-times",
        type=float,
        nargs="+",
        metavar="T",
        help="with --fields: further instants T (by x0/V0) to write",
    )
    num.add_argument(
        "--fields",
        metavar="FILE.xdmf",
        help="FE model: displacement and stresses of both solids at maximum compression, "
        "maximum force and the end (and --field-times), as XDMF for ParaView",
    )


def _solids_arguments(fe) -> None:
    """The FE model's lower body: wall block, coated wall, or a second sphere."""
    fe.add_argument(
        "--lower",
        choices=LOWER_BODIES,
        default="wall",
        help="body below the sphere: wall block, coated wall block, or a second sphere",
    )
    fe.add_argument("--coating-thickness", type=float, help="coating thickness (by a), > 0")
    fe.add_argument(
        "--coating-stiffness", type=float, default=1.0, help="coating Young's modulus / wall's, > 0"
    )
    fe.add_argument("--coating-poisson", type=float, default=0.3, help="coating Poisson ratio")
    fe.add_argument(
        "--radius-ratio",
        type=float,
        default=1.0,
        help="two spheres: upper radius / lower radius (a is the reduced radius)",
    )


def _film_arguments(group, scaled) -> None:
    """The film's undeformed gap, cavitation model and viscosity law (collide, render,
    critical); the scaled viscosity constants go into the ``scaled`` argument group."""
    group.add_argument(
        "--gap",
        choices=GAPS,
        default=None,
        help="undeformed gap: the theory's paraboloid or the true spheres (thin layer only); "
        "default: exact for --model fem with a thin layer, paraboloid otherwise",
    )
    group.add_argument(
        "--shear-traction",
        choices=("on", "off"),
        default=None,
        help="load the solids with the squeeze flow's shear traction too; "
        "default: on for --model fem, off for the half-space theory",
    )
    group.add_argument(
        "--cavitation",
        choices=cavitation.MODELS,
        default="truncate",
        help="truncate at P_cav (the source's), mass-conserving (JFO), or none",
    )
    group.add_argument(
        "--viscosity",
        choices=VISCOSITY_LAWS,
        default="constant",
        help="viscosity against pressure: constant, barus or roelands",
    )
    scaled.add_argument(
        "--alpha",
        type=float,
        default=0.0,
        help="pressure-viscosity coefficient scaled by mu V0 a / x0^2, >= 0 (with --viscosity)",
    )
    scaled.add_argument(
        "--roelands-pressure",
        type=float,
        help="Roelands p_r = 1.96e8 Pa scaled by mu V0 a / x0^2, > 0 (--viscosity roelands)",
    )
    scaled.add_argument(
        "--roelands-index", type=float, default=ROELANDS_INDEX, help="Roelands index Z, (0, 2]"
    )


VERBOSE_HELP = "show the form compiler's build log and VTK's warnings (hidden by default)"


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="ehdfem", description=DESCRIPTION)
    parser.add_argument("--version", action="version", version=f"%(prog)s {__version__}")
    parser.add_argument("--verbose", action="store_true", help=VERBOSE_HELP)
    every = argparse.ArgumentParser(add_help=False)  # options of every subcommand
    every.add_argument(
        "--verbose", action="store_true", default=argparse.SUPPRESS, help=VERBOSE_HELP
    )
    sub = parser.add_subparsers(dest="command", required=True)

    def command(name, text):
        return sub.add_parser(name, help=text, description=text, parents=[every])

    _collision_arguments(command("collide", "simulate one collision and print its results"))
    r = command("render", "FE collision: picture of the deformed solids (and a film GIF)")
    _collision_arguments(r)
    r.add_argument("--out", default="render.png", help="PNG file (default render.png)")
    r.add_argument("--time", type=float, help="instant T (by x0/V0); default: maximum compression")
    r.add_argument(
        "--field",
        choices=("von_mises", "hydrostatic", "displacement", "pressure"),
        default="von_mises",
    )
    r.add_argument(
        "--magnification", type=float, help="displacement display factor (default: automatic)"
    )
    r.add_argument("--animation", metavar="FILE.gif", help="also write the film animation")

    s = command("sweep", "run a study file (TOML) over the MPI ranks; resumable")
    s.add_argument("study", help="study file, e.g. studies/kantak_davis.toml")

    k = command("critical", "critical Stokes number St_c by bisection on rebound")
    k.add_argument("--eps", type=float, required=True, help="elasticity parameter, > 0")
    k.add_argument("--delta", type=float, default=0.01, help="x0/a, (0, 1)")
    k.add_argument("--layer", choices=LAYERS, default="thin")
    k.add_argument("--p-cav", type=float, default=None, help="cavitation pressure (scaled), <= 0")
    _film_arguments(k, k)
    k.add_argument("--bracket", type=float, nargs=2, default=(1.0, 1000.0), metavar=("LOW", "HIGH"))
    k.add_argument("--rtol", type=float, default=1e-3, help="relative width of the final bracket")
    k.add_argument("--nodes", type=int, default=DEFAULT_NODES)
    k.add_argument("--model", choices=MODELS, default="halfspace")
    k.add_argument(
        "--json", metavar="FILE", help="write {St_c, bracket, ...} as JSON ('-': stdout)"
    )

    f = command("fit", "closed-form fits (and DEM formulas) against a sweep table")
    f.add_argument("table", help="CSV table written by ehdfem sweep")
    f.add_argument("--json", metavar="FILE", help="write the fits as JSON ('-': stdout)")
    f.add_argument(
        "--python",
        metavar="FILE",
        help="write the closed forms for DEM (e_n, e_t, spin change) as a Python module to copy",
    )

    p = command("presets", "list the material and liquid presets: values (SI) and sources")
    p.add_argument("--json", metavar="FILE", help="write the presets as JSON ('-': stdout)")
    _bounce_arguments(
        command(
            "bounce",
            "a sphere released in a liquid settles onto a wall and bounces until it rests; each "
            "contact is an immersed EHD collision (docs/bounce.md)",
        )
    )
    return parser


def _bounce_arguments(b) -> None:
    """The inputs of ``ehdfem bounce``: materials, liquid, start, modelling choices, output."""
    phys = b.add_argument_group("physical inputs (SI)")
    _body_arguments(phys)
    phys.add_argument("--radius", type=float, help="sphere radius a [m], (0, 1]")
    phys.add_argument(
        "--release-height", type=float, help="gap [m] at which the sphere is released at rest"
    )
    phys.add_argument("--start-gap", type=float, help="or: start gap [m], with --start-speed")
    phys.add_argument("--start-speed", type=float, help="speed [m/s] towards the wall at the start")
    model = b.add_argument_group("modelling choices")
    model.add_argument(
        "--e-dry", type=float, default=1.0, help="dry restitution, (0, 1]; 1 = pure EHD"
    )
    model.add_argument("--drag", choices=DRAG_LAWS, default=DRAG_LAWS[0], help="steady drag law")
    model.add_argument(
        "--added-mass", type=float, default=0.5, help="added-mass coefficient C_M, [0, 1]"
    )
    model.add_argument("--gravity", type=float, default=GRAVITY, help="g [m/s^2]")
    model.add_argument(
        "--cavitation",
        choices=cavitation.MODELS,
        default="truncate",
        help="film cavitation at the liquid's vapour pressure: truncate, mass-conserving or none",
    )
    model.add_argument(
        "--ambient-pressure", type=float, default=ATMOSPHERE, help="ambient pressure [Pa]"
    )
    model.add_argument(
        "--model",
        choices=BOUNCE_MODELS,
        default="halfspace",
        help="solids of the contacts: elastic half-spaces, or rigid (eps -> 0)",
    )
    num = b.add_argument_group("numerics and output")
    num.add_argument(
        "--handover-jump",
        type=float,
        default=HANDOVER_JUMP,
        help="largest relative force jump at the hand-over to the film model, (0, 0.5)",
    )
    num.add_argument(
        "--ehd-multiple",
        type=float,
        default=EHD_MULTIPLE,
        help="hand over at the latest at this multiple of the EHD gap, >= 1",
    )
    num.add_argument("--max-bounces", type=int, default=30, help="most contacts computed")
    num.add_argument(
        "--rest-apex", type=float, default=1e-3, help="an apex below this fraction of D ends it"
    )
    num.add_argument("--nodes", type=int, default=DEFAULT_NODES, help="film nodes")
    num.add_argument(
        "--rtol", type=float, default=IntegratorOptions.rtol, help="film time-step tolerance"
    )
    num.add_argument(
        "--out",
        metavar="DIR",
        help="write trajectory.csv, contacts.csv, bounce.json and bounce.png into DIR",
    )
    num.add_argument("--json", metavar="FILE", help="write the results as JSON ('-' for stdout)")


def _inputs(args) -> CollisionParameters | PhysicalCollision:
    """Build the collision inputs from the arguments, refusing mixed or incomplete sets."""
    values = _physical_values(args)
    if values is None:
        return _dimensionless_inputs(args)
    missing = [_body_hint(name) for name in PHYSICAL if name not in values]
    if missing:
        raise checks.InputError(f"physical inputs need {', '.join(missing)}")
    if args.St is not None or args.eps is not None:
        raise checks.InputError(
            "give either dimensionless (--St, --eps) or physical inputs, not both"
        )
    if args.alpha or args.roelands_pressure is not None:
        raise checks.InputError(
            "physical inputs take --pressure-viscosity [1/Pa], not the scaled --alpha or "
            "--roelands-pressure"
        )
    own_liquid = args.liquid is None and not args.example
    if own_liquid and args.viscosity != "constant" and args.pressure_viscosity is None:
        raise checks.InputError(
            f"--viscosity {args.viscosity} with a liquid of your own needs its "
            "--pressure-viscosity [1/Pa], [0, 1e-6]"
        )
    return from_presets(
        **values,
        layer=args.layer,
        e_dry=args.e_dry,
        cavitation=args.cavitation,
        viscosity=args.viscosity,
        pressure_viscosity=args.pressure_viscosity,
        gap=args.gap,
        shear_traction=_on_off(args.shear_traction),
    )


def _option(dest: str) -> str:
    """The command-line spelling of an argument's name: layer_thickness -> --layer-thickness."""
    return "--" + dest.replace("_", "-")


def _body_hint(name: str) -> str:
    """How to give the physical input ``name`` (for the message listing what is missing)."""
    if name == "liquid":
        return f"--liquid (or {', '.join(map(_option, LIQUID_OPTIONS))})"
    if name in BODIES:
        values = ", ".join(_option(f"{name}_{suffix}") for suffix in MATERIAL_OPTIONS)
        return f"--{name} (or {values})"
    return _option(name)


def _physical_values(args) -> dict | None:
    """The physical inputs given (SI; with --example, its values where not given), the
    sphere, wall and liquid as Material and Liquid; None when there are none."""
    values = dict(EXAMPLE) if args.example else {}
    values.update({n: getattr(args, n) for n in SCALAR_PHYSICAL if getattr(args, n) is not None})
    for name in BODIES:
        body = _body(args, name, getattr(args, name) or values.get(name))
        values.pop(name, None)
        if body is not None:
            values[name] = body
    if not values:
        return None
    if args.angle is not None or "angle" not in values:
        values["angle"] = 0.0 if args.angle is None else args.angle
    return values


def _body(args, name: str, preset: str | None):
    """The sphere's or wall's Material, or the liquid's Liquid, from its preset and the values
    given on the command line (which change the preset's); None when neither is given."""
    if name == "liquid":
        options, build = LIQUID_OPTIONS, custom_liquid
    else:
        options = {f"{name}_{suffix}": spec for suffix, spec in MATERIAL_OPTIONS.items()}
        build = custom_material
    given = {dest: getattr(args, dest) for dest in options if getattr(args, dest) is not None}
    if preset is None and not given:
        return None
    field = {dest: spec[0] for dest, spec in options.items()}
    labels = {field[dest]: _option(dest) for dest in options}
    return build(preset, labels=labels.get, **{field[dest]: v for dest, v in given.items()})


def _dimensionless_inputs(args) -> CollisionParameters:
    """The dimensionless inputs (DSH scales) of the arguments."""
    if args.pressure_viscosity is not None:
        raise checks.InputError(
            "--pressure-viscosity [1/Pa] needs physical inputs; give the scaled --alpha instead"
        )
    for name in ("St", "eps"):
        if getattr(args, name) is None:
            raise checks.InputError(f"--{name} is required (or give physical inputs, or --example)")
    checks.positive("eps", args.eps)
    return CollisionParameters(
        St=args.St,
        eps=args.eps,
        delta=args.delta,
        p_cav=cavitation.parse_suction_limit(args.p_cav),
        e_dry=args.e_dry,
        layer=args.layer,
        angle=0.0 if args.angle is None else args.angle,
        spin=args.spin,
        **_film_parameters(args),
    )


def _on_off(value):
    """True, False or None (not given) from an "on"/"off" option."""
    return None if value is None else value == "on"


def _film_parameters(args) -> dict:
    """CollisionParameters fields of the film models from the dimensionless arguments."""
    return {
        "gap": args.gap,
        "shear_traction": _on_off(args.shear_traction),
        "cavitation": args.cavitation,
        "viscosity": args.viscosity,
        "alpha": args.alpha,
        "roelands_pressure": args.roelands_pressure,
        "roelands_index": args.roelands_index,
    }


def _print_table(summary: dict, stream) -> None:
    """The results of a summary, one per line (the SI ones after the scaled ones; the inputs
    are in the JSON only)."""
    rows = [(k, v) for k, v in summary.items() if not isinstance(v, dict)]
    rows += list(summary.get("si", {}).items())
    width = max(len(k) for k, _ in rows)
    for key, value in rows:
        text = f"{value:.6g}" if isinstance(value, float) else str(value)
        print(f"  {key:<{width}}  {text}", file=stream)


def _report_stream(args):
    """Where the human-readable report goes: standard error when ``--json -`` takes standard
    output for the JSON alone, else standard output."""
    return sys.stderr if getattr(args, "json", None) == "-" else sys.stdout


def _solids(args, inputs) -> dict | None:
    """FESolids options from the command line (None for the default wall block)."""
    if args.lower == "wall":
        return None
    if args.model != "fem":
        raise checks.InputError(f"--lower {args.lower} needs --model fem")
    if args.lower == "sphere":
        return {"lower": "sphere", "radius_ratio": args.radius_ratio}
    if args.coating_thickness is None:
        raise checks.InputError("--lower coated needs --coating-thickness (by a), > 0")
    wall = inputs.wall.young_modulus if isinstance(inputs, PhysicalCollision) else 1.0
    return {
        "lower": "coated",
        "coating_thickness": args.coating_thickness,
        "coating": (
            checks.positive("coating-stiffness", args.coating_stiffness) * wall,
            args.coating_poisson,
        ),
    }


def _run_collision(args, model: str):
    """The collision of the arguments with ``model``; returns (result, run options), the
    options being those :meth:`ehdfem.collision.CollisionResult.summary` records."""
    inputs = _inputs(args)
    solids = _solids(args, inputs)
    result = collide(
        inputs,
        model=model,
        nodes=args.nodes,
        options=IntegratorOptions(rtol=args.rtol),
        tangential=args.tangential,
        solids=solids,
        deformation=args.sliding_deformation,
    )
    run = {
        "model": model,
        "nodes": args.nodes,
        "rtol": args.rtol,
        "tangential": args.tangential,
        "deformation": args.sliding_deformation,
        "solids": solids,
    }
    return result, run


def collide_command(args) -> int:
    if args.fields and args.model != "fem":
        raise checks.InputError("--fields needs --model fem (the half-space has no mesh)")
    result, run = _run_collision(args, args.model)
    summary = result.summary(run)
    report = _report_stream(args)
    print("ehdfem collide: results (dimensionless, DSH scales; SI under si)", file=report)
    _print_table(summary, report)
    _write_json(summary, args.json)
    wrote = []
    if args.fields:
        snapshots = field_snapshots(result.normal, args.field_times)
        write_fields(
            result.compliance,
            args.fields,
            snapshots,
            units=result.physical.scales() if result.physical else None,
        )
        wrote.append(f"{args.fields} (T = {', '.join(f'{t:.4g}' for t, _ in snapshots)})")
    if args.plots:
        out = Path(args.plots)
        wrote.append(viz.plot_histories(result.normal, out / "histories.png"))
        wrote.append(viz.plot_profiles(result.normal, out / "profiles.png"))
        if result.tangential is not None:
            wrote.append(viz.plot_tangential(result, out / "tangential.png"))
    for path in wrote:
        print(f"  wrote {path}", file=report)
    return 0


def sweep_command(args) -> int:
    from mpi4py import MPI

    comm = MPI.COMM_WORLD
    study = Study(args.study)
    if comm.rank == 0:
        print(f"ehdfem sweep {study.name}: {len(study.points)} points on {comm.size} rank(s)")
    run_study(study, comm, progress=print if comm.rank == 0 else None)
    if comm.rank == 0:
        print(f"wrote {study.table}")
    return 0


def critical_command(args) -> int:
    checks.positive("eps", args.eps)
    params = CollisionParameters(
        St=1.0,
        eps=args.eps,
        delta=args.delta,
        layer=args.layer,
        p_cav=cavitation.parse_suction_limit(args.p_cav),
        **_film_parameters(args),
    )
    found = critical_stokes(
        params,
        tuple(args.bracket),
        args.rtol,
        args.nodes,
        model=args.model,
        progress_label="St_c bisection",
    )
    out = {
        **found,
        "ehdfem_version": __version__,
        "eps": args.eps,
        "delta": args.delta,
        "layer": args.layer,
        "p_cav": args.p_cav,
        "nodes": args.nodes,
        "model": args.model,
        **_film_parameters(args),
    }
    print(
        f"St_c = {found['St_c']:.6g} (bracket {found['bracket'][0]:.6g} .. "
        f"{found['bracket'][1]:.6g}, rtol {args.rtol:g}, {found['collisions']} collisions)",
        file=_report_stream(args),
    )
    _write_json(out, args.json)
    return 0


def _json_ready(value):
    """``value`` with every non-finite float (NaN, +-inf) as None and tuples as lists, so that
    the text is strict JSON (jq, JSON.parse and json.load all read it)."""
    if isinstance(value, dict):
        return {key: _json_ready(item) for key, item in value.items()}
    if isinstance(value, list | tuple):
        return [_json_ready(item) for item in value]
    if isinstance(value, float | np.floating) and not np.isfinite(value):
        return None
    return value.item() if isinstance(value, np.generic) else value


def _write_json(data: dict, target: str | None) -> None:
    """Write ``data`` as strict JSON to the file ``target``, or alone to standard output when
    ``target`` is "-"; nothing when it is None."""
    if not target:
        return
    text = json.dumps(_json_ready(data), indent=2, allow_nan=False)
    if target == "-":
        sys.stdout.write(text + "\n")
        sys.stdout.flush()
    else:
        Path(target).parent.mkdir(parents=True, exist_ok=True)
        _write_atomic(Path(target), text + "\n")


def fit_command(args) -> int:
    path = Path(args.table)
    if not path.is_file():
        raise checks.InputError(f"table {args.table!r} does not exist")
    with path.open() as f:
        fits = fit_table(list(csv.DictReader(f)))
    report = _report_stream(args)
    for group in fits["normal"]:
        print(
            f"{_labels(group)}, eps = {group['eps']:g}: "
            f"e_n = {group['e_inf']:.4f} (1 - {group['St_c']:.4g}/St)"
            f"  max error {group['max_error']:.3g}, rms {group['rms_error']:.3g}",
            file=report,
        )
    for law in fits["critical_stokes_laws"]:
        print(
            f"St_c ({_labels(law['model'])}): {law['coefficient']:.4g} eps^{law['eps']:.4g}"
            f"  max error {law['max_error']:.3g}, rms {law['rms_error']:.3g}",
            file=report,
        )
    forms = fits.get("closed_forms")
    if forms is not None:
        print(f"closed forms for DEM over {describe_ranges(forms['ranges'])}:", file=report)
        for name in ("normal", "tangential_loss", "spin_change"):
            form = forms[name]
            relative = form.get("max_relative_error")
            print(
                f"  {form['form']}\n    max error {form['max_error']:.3g}, rms "
                f"{form['rms_error']:.3g}"
                + ("" if relative is None else f", max relative error {relative:.3g}"),
                file=report,
            )
    elif args.python:
        raise checks.InputError(f"--python: {fits['closed_forms_skipped']}")
    for name, errors in fits["dem_formulas"].items():
        error, rms = errors["max_error"], errors["rms_error"]
        print(f"DEM formula {name}: max error {error:.3g}, rms {rms:.3g}", file=report)
    _write_json(fits, args.json)
    if args.python:
        _write_atomic(Path(args.python), python_source(forms, path.name, __version__))
        print(f"wrote {args.python}", file=report)
    return 0


def _labels(group: dict) -> str:
    """The model labels of a fit group (delta, layer, P_cav, cavitation, viscosity, alpha)."""
    return ", ".join(f"{k} = {group[k]}" for k in ("delta", *(k for k, _ in GROUPED)) if k in group)


def render_command(args) -> int:
    from ..outputs.render import animate_film, render_solids

    args.model = "fem"
    result, run = _run_collision(args, "fem")
    report = _report_stream(args)
    _write_json(result.summary(run), args.json)
    hist = result.normal.history
    time = float(hist.time[int(np.argmin(hist.gap))] if args.time is None else args.time)
    pressure = dict(field_snapshots(result.normal, [time]))[time]
    p = result.params
    title = (
        f"St = {p.St:.4g}, eps = {p.eps:.3g}, delta = {p.delta:.3g}: T = {time:.4g}, "
        f"e_n = {result.normal.e_n:.4f}"
    )
    magnification = render_solids(
        result.compliance, pressure, args.out, args.field, args.magnification, title
    )
    print(
        f"  wrote {args.out} ({args.field}, displacement x {magnification:.3g}, T = {time:.4g})",
        file=report,
    )
    if args.animation:
        frames = animate_film(result.normal, args.animation)
        print(f"  wrote {args.animation} ({frames} frames)", file=report)
    return 0


def presets_command(args) -> int:
    """The material and liquid presets: a table each (SI units in the header), with sources."""
    report = _report_stream(args)
    tables = [
        ("materials", MATERIALS, ("E [Pa]", "nu", "density [kg/m^3]")),
        ("liquids", LIQUIDS, ("mu [Pa s]", "density [kg/m^3]", "p_vap [Pa]", "alpha [1/Pa]")),
    ]
    for title, presets, header in tables:
        print(f"{title} (sphere/wall presets)" if title == "materials" else title, file=report)
        rows = [
            (p.name, *(f"{v:.6g}" for v in _preset_values(p)), p.source) for p in presets.values()
        ]
        rows.insert(0, ("name", *header, "source"))
        widths = [max(len(row[i]) for row in rows) for i in range(len(header) + 1)]
        for row in rows:
            cells = [cell.ljust(width) for cell, width in zip(row, widths, strict=False)]
            print("  " + "  ".join([*cells, row[-1]]), file=report)
        print(file=report)
    print(
        "Give your own values with --sphere-modulus, --sphere-poisson, --sphere-density (and "
        "--wall-*), --liquid-viscosity, --liquid-density, --vapour-pressure, "
        "--pressure-viscosity; with a preset they change its values.",
        file=report,
    )
    _write_json(
        {kind: {n: asdict(p) for n, p in presets.items()} for kind, presets, _ in tables},
        args.json,
    )
    return 0


def _preset_values(preset) -> list[float]:
    """The numbers of a Material or Liquid, in the order of the presets table."""
    return [getattr(preset, f.name) for f in fields(preset) if f.name not in ("name", "source")]


def _bounce_inputs(args) -> BounceInputs:
    """The bounce's inputs from the arguments; a missing material or liquid is named."""
    bodies = {name: _body(args, name, getattr(args, name)) for name in BODIES}
    missing = [_body_hint(name) for name, value in bodies.items() if value is None]
    if args.radius is None:
        missing.append("--radius")
    if missing:
        raise checks.InputError(f"ehdfem bounce needs {', '.join(missing)}")
    return BounceInputs(
        radius=args.radius,
        **bodies,
        release_height=args.release_height,
        start_gap=args.start_gap,
        start_speed=args.start_speed,
        e_dry=args.e_dry,
        drag=args.drag,
        added_mass=args.added_mass,
        gravity=args.gravity,
        cavitation=args.cavitation,
        ambient_pressure=args.ambient_pressure,
    )


def bounce_command(args) -> int:
    inputs = _bounce_inputs(args)
    result = bounce(
        inputs,
        model=args.model,
        nodes=args.nodes,
        options=IntegratorOptions(rtol=args.rtol),
        handover_jump=args.handover_jump,
        ehd_multiple=args.ehd_multiple,
        max_bounces=args.max_bounces,
        rest_apex=args.rest_apex,
    )
    summary = result.summary()
    report = _report_stream(args)
    diameter = inputs.diameter
    print(
        f"ehdfem bounce: {result.status}; terminal velocity {result.terminal_velocity:.4g} m/s, "
        f"energy balance {summary['energy_error']:.2g}",
        file=report,
    )
    print("  contact  impact [m/s]  St       h_c [m]    e       apex/D    outcome", file=report)
    for i, c in enumerate(result.contacts, 1):
        apex = "-" if c.apex_gap is None else f"{c.apex_gap / diameter:.4g}"
        print(
            f"  {i:<7d}  {c.impact_speed:<12.4g}  {c.St:<7.4g}  {c.handover_gap:<9.3g}  "
            f"{c.e:<6.4f}  {apex:<8s}  {c.status}",
            file=report,
        )
    _write_json(summary, args.json)
    if args.out:
        out = Path(args.out)
        _write_json(summary, str(out / "bounce.json"))
        wrote = [
            write_csv(out / "trajectory.csv", result.trajectory_rows()),
            write_csv(out / "contacts.csv", result.contact_rows()),
            out / "bounce.json",
            viz.plot_bounce(result, out / "bounce.png"),
        ]
        for path in wrote:
            print(f"  wrote {path}", file=report)
    return 0


COMMANDS = {
    "bounce": bounce_command,
    "collide": collide_command,
    "render": render_command,
    "sweep": sweep_command,
    "critical": critical_command,
    "fit": fit_command,
    "presets": presets_command,
}


def main(argv=None) -> int:
    """The ``ehdfem`` command; returns the exit status (0 done, 2 bad input, 3 solver
    failure)."""
    args = _parser().parse_args(argv)
    was_quiet = is_quiet()
    set_quiet(not args.verbose)
    try:
        return COMMANDS[args.command](args)
    except checks.InputError as err:
        print(f"ehdfem: error: {err}", file=sys.stderr)
        return 2
    except NormalSolverError as err:
        print(f"ehdfem: solver failure: {err}", file=sys.stderr)
        return 3
    finally:
        set_quiet(was_quiet)


if __name__ == "__main__":
    sys.exit(main())
