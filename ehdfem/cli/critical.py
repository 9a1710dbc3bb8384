"""``ehdfem critical``: the critical Stokes number St_c by bisection on the rebound, or for
physical inputs the critical impact speed [m/s] (and St_c there)."""

from __future__ import annotations

from dataclasses import asdict

from ..inputs.scales import CollisionParameters, PhysicalCollision
from ..outputs import provenance
from ..study.sweep import critical_speed, critical_stokes
from . import interrupt_says, paths
from .arguments import add_fields, report_stream, write_json
from .inputs import add_body_arguments, add_run_arguments, collision_inputs, run_config, shared

HELP = "critical Stokes number St_c (or, for physical inputs, speed) by bisection on rebound"
NOT_ASKED = ("St", "angle", "spin")  # St is searched; the bisection is on the normal motion
NOT_ASKED_PHYSICAL = ("speed", "angle", "spin")  # the speed is searched
NO_EFFECT = ("tangential", "deformation")  # the tangential motion does not decide a rebound
BRACKETS = {"St": (1.0, 1000.0), "speed": (0.01, 10.0)}  # starting brackets, St and m/s
UNSAVED = (
    "stopped by Ctrl-C; the search writes nothing until it ends, so nothing was saved: run the "
    "command again to search anew"
)


def add_critical(parser) -> None:
    inputs = parser.add_argument_group("dimensionless inputs (DSH scales): St_c")
    add_fields(inputs, CollisionParameters, exclude=NOT_ASKED)
    phys = parser.add_argument_group("physical inputs (SI): the critical speed [m/s]")
    add_body_arguments(phys)
    add_fields(phys, PhysicalCollision, exclude={*shared(), *NOT_ASKED_PHYSICAL})
    search = parser.add_argument_group("bisection")
    search.add_argument(
        "--bracket",
        type=float,
        nargs=2,
        metavar=("LOW", "HIGH"),
        help="starting bracket of St (or of the speed [m/s] for physical inputs), widened "
        "until it holds the critical value; default: 1 1000 (St), 0.01 10 (m/s)",
    )
    search.add_argument(
        "--bracket-rtol",
        type=float,
        default=1e-3,
        help="relative width of the final bracket, [1e-8, 0.5]; default: 0.001 (--rtol is "
        "each collision's time-step tolerance, as in collide)",
    )
    add_run_arguments(parser, exclude=NO_EFFECT)
    parser.add_argument(
        "--json",
        metavar="FILE",
        help="write {St_c (and speed), bracket, ..., provenance, the inputs, run} as JSON "
        "('-': stdout); default: none",
    )


def critical_command(args) -> int:
    paths.output_file("json", args.json, stdout=True)
    config = run_config(args)
    low = BRACKETS["speed"][0] if args.bracket is None else args.bracket[0]
    inputs = collision_inputs(args, sought={"St": 1.0, "speed": low})
    kind = "speed" if isinstance(inputs, PhysicalCollision) else "St"
    bracket = BRACKETS[kind] if args.bracket is None else tuple(args.bracket)
    label = f"{'critical speed' if kind == 'speed' else 'St_c'} bisection"
    with interrupt_says(lambda: UNSAVED):
        found, given, where, unit = _search(args, inputs, kind, bracket, config, label)
    out = {
        **found,
        "provenance": provenance.record(args.command_line),
        **given,
        "run": config.settings(),
    }
    low, high = found["bracket"]
    print(
        f"{where} (bracket {low:.6g} .. {high:.6g}{unit}, bracket rtol {args.bracket_rtol:g}, "
        f"{found['collisions']} collisions)",
        file=report_stream(args),
    )
    write_json(out, args.json)
    return 0


def _search(args, inputs, kind, bracket, config, label):
    """The critical speed or St_c of ``inputs``: (what the search found, the inputs it was
    given, the result's line and its unit)."""
    if kind == "speed":
        found = critical_speed(inputs, bracket, args.bracket_rtol, config, progress_label=label)
        given = {k: v for k, v in asdict(inputs).items() if k not in NOT_ASKED_PHYSICAL}
        where = f"speed = {found['speed']:.6g} m/s, St_c = {found['St_c']:.6g}"
        unit = " m/s"
    else:
        found = critical_stokes(inputs, bracket, args.bracket_rtol, config, progress_label=label)
        given = {k: v for k, v in inputs.settings(written=True).items() if k not in NOT_ASKED}
        where, unit = f"St_c = {found['St_c']:.6g}", ""
    return found, given, where, unit
