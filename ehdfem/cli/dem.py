"""``ehdfem dem``: a real DEM engine (Yade or LIGGGHTS) on one collision, its rebound printed
beside the full model's at the same physical inputs (:mod:`ehdfem.dem.engines`). The engine's
input script, log, history and rebound stay in ``--folder`` to open and rerun by hand. On rough
surfaces (``--sphere-roughness``, ``--wall-roughness`` [m]) the full model runs with their sigma
and the engine's asperity parameter, unless given, is set from it
(:func:`ehdfem.dem.engines.compare.engine_law`)."""

from __future__ import annotations

from pathlib import Path

from .. import CollisionParameters, checks
from ..dem.engines.compare import ENGINES, RERUN, compare, engine_law
from ..inputs.presets import EXAMPLE
from ..outputs import provenance
from . import paths
from .arguments import JSON_HELP, add_fields, given, report_stream, write_json
from .inputs import MATERIAL_OPTIONS, add_collision_arguments, collision_inputs, run_config

HELP = "run a DEM engine (Yade, LIGGGHTS) on one collision beside ehdfem's model"


def add_dem(parser) -> None:
    engine = parser.add_argument_group("DEM engine")
    engine.add_argument(
        "--engine",
        choices=tuple(ENGINES),
        required=True,
        help="yade: a sphere on a wall with its implicit lubrication law; liggghts: two equal "
        "spheres (--wall the sphere's material) with its easo/capillary/viscous bridge and "
        "Hertz-Mindlin contact, beside the half-space model at the reduced radius and mass; "
        "default: required",
    )
    engine.add_argument(
        "--folder",
        metavar="DIR",
        required=True,
        help="folder for the engine's input script, log, history and rebound (made if "
        "missing; rerun by hand there); default: required",
    )
    for law, _ in ENGINES.values():
        add_fields(engine, law)
    add_collision_arguments(parser)
    parser.add_argument("--json", metavar="FILE", help=JSON_HELP)


def dem_command(args) -> int:
    paths.output_folder("folder", args.folder)
    paths.output_file("json", args.json, stdout=True)
    paths.distinct_outputs({"folder": args.folder, "json": args.json})
    law_class = ENGINES[args.engine][0]
    for other, _ in ENGINES.values():
        if other is not law_class and given(args, other):
            name = next(iter(given(args, other)))
            raise checks.InputError(f"is a setting of another engine than {args.engine}", name)
    if args.engine == "liggghts" and getattr(args, "example", False):
        _two_equal_spheres_example(args)
    collision = collision_inputs(args)
    if isinstance(collision, CollisionParameters):
        raise checks.InputError(
            "the engines take physical inputs: --sphere, --wall, --liquid, --radius, --speed, "
            "--layer-thickness (or --example)"
        )
    law = engine_law(args.engine, collision, given(args, law_class))
    result = compare(args.engine, collision, law, args.folder, run_config(args))
    report = report_stream(args)
    print_comparison(result, report)
    write_json({**result, "provenance": provenance.record(args.command_line)}, args.json)
    return 0


def _two_equal_spheres_example(args) -> None:
    """The main job's example as LIGGGHTS can run it (two equal spheres): the wall of the
    sphere's material where the user gave none (a given other one is refused by the engine
    with the reason)."""
    own_wall = args.wall is not None or any(
        getattr(args, f"wall_{suffix}", None) is not None for suffix in MATERIAL_OPTIONS
    )
    if not own_wall:
        args.wall = args.sphere or EXAMPLE["sphere"]


def print_comparison(result: dict, report) -> None:
    """The engine's e_n (e_t, spin change) beside ehdfem's model's, one line each, and every
    file in the engine's folder."""
    engine, model = result["engine"], result["full_model"]
    solids = {"halfspace": "half-space", "fem": "FE"}[model["model"]]
    print(
        f"ehdfem dem: {engine['engine']} beside ehdfem's {solids} model (St = {model['St']:.4g}, "
        f"eps = {model['eps']:.3g}, delta = {model['delta']:.3g}, "
        f"sigma/x0 = {model['roughness']:.3g}, asperities {model['asperities']})",
        file=report,
    )
    for key in ("e_n", "e_t", "spin_change"):
        if engine[key] is None and key != "e_n":
            continue
        full = "n/a" if model[key] is None else f"{model[key]:.6g}"
        print(
            f"  {key:<12} {engine['engine']} {engine[key]:.6g}   ehdfem {solids} {full}",
            file=report,
        )
    written = ", ".join(sorted(path.name for path in Path(engine["folder"]).iterdir()))
    rerun = RERUN[engine["engine"]]
    print(f"  files in {engine['folder']}: {written} (rerun there: {rerun})", file=report)
