"""``ehdfem bounce``: a sphere released in a liquid settles onto a wall and bounces until it
rests; each contact is an immersed EHD collision (docs/bounce.md). Inputs in SI."""

from __future__ import annotations

import argparse
from pathlib import Path

from .. import BounceInputs, BounceRun, IntegratorOptions, bounce_sphere, checks
from ..config import Numerics
from ..study.sweep import write_csv
from . import paths
from .arguments import JSON_HELP, add_fields, given, named_by_option, report_stream, write_json
from .inputs import BODIES, add_body_arguments, body_hint, body_of

HELP = (
    "a sphere released in a liquid settles onto a wall and bounces until it rests; each "
    "contact is an immersed EHD collision (docs/bounce.md)"
)

START = ("radius", "release_height", "start_gap", "start_speed")  # BounceInputs' start
NUMERICS = ("nodes", "refinements")  # the contacts' film numerics
INTEGRATOR = ("rtol",)  # and their time-step control (the exit gap is each contact's)


def add_bounce(b) -> None:
    """The inputs of ``ehdfem bounce``: materials, liquid, start, modelling choices (the fields
    of :class:`ehdfem.BounceInputs`), the bounce's numerics (those of :class:`ehdfem.BounceRun`
    with the contacts' film numerics of :class:`ehdfem.config.Numerics` and
    :class:`ehdfem.IntegratorOptions`), each with its unit, range and default, and the
    outputs."""
    phys = b.add_argument_group("physical inputs (SI)")
    add_body_arguments(phys)
    add_fields(phys, BounceInputs, names=START)
    model = b.add_argument_group("modelling choices")
    add_fields(model, BounceInputs, exclude=(*BODIES, *START), switches=True)
    num = b.add_argument_group("numerics and output")
    add_fields(num, BounceRun)
    add_fields(num, Numerics, names=NUMERICS)
    add_fields(num, IntegratorOptions, names=INTEGRATOR)
    num.add_argument(
        "--folder",
        metavar="DIR",
        help="write trajectory.csv, contacts.csv, bounce.json and bounce.png into DIR (made if "
        "missing); default: none",
    )
    num.add_argument("--out", dest="old_out", help=argparse.SUPPRESS)  # refused: see --folder
    num.add_argument("--json", metavar="FILE", help=JSON_HELP)


def _bounce_run(args) -> BounceRun:
    """The bounce's numerics from the arguments."""
    integrator = IntegratorOptions(**given(args, IntegratorOptions, INTEGRATOR))
    numerics = Numerics(**given(args, Numerics, NUMERICS), integrator=integrator)
    return BounceRun(**given(args, BounceRun), numerics=numerics)


def _bounce_inputs(args) -> BounceInputs:
    """The bounce's inputs from the arguments; a missing material, liquid or radius is named."""
    bodies = {name: body_of(args, name, getattr(args, name)) for name in BODIES}
    values = {k: v for k, v in given(args, BounceInputs).items() if k not in BODIES}
    missing = [body_hint(name) for name, value in bodies.items() if value is None]
    if "radius" not in values:
        missing.append(body_hint("radius"))
    if missing:
        raise checks.InputError(f"the bounce needs {', '.join(missing)}")
    try:
        return BounceInputs(**values, **bodies)
    except checks.InputError as err:
        raise named_by_option(err, BounceInputs) from None


def bounce_command(args) -> int:
    if args.old_out is not None:
        raise checks.InputError(
            "the bounce's output folder is --folder (render's --out names a picture file)",
            "old_out",
        )
    paths.output_file("json", args.json, stdout=True)
    paths.output_folder("folder", args.folder)
    paths.distinct_outputs({"json": args.json, "folder": args.folder})
    inputs = _bounce_inputs(args)
    result = bounce_sphere(inputs, _bounce_run(args))
    summary = result.summary(args.command_line)
    report = report_stream(args)
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
    write_json(summary, args.json)
    if args.folder:
        out = Path(args.folder)
        from ..outputs import plots  # matplotlib costs 0.25 s to import: only when plotting

        out.mkdir(parents=True, exist_ok=True)
        write_json(summary, str(out / "bounce.json"))
        wrote = [
            write_csv(out / "trajectory.csv", result.trajectory_rows()),
            write_csv(out / "contacts.csv", result.contact_rows()),
            out / "bounce.json",
            plots.plot_bounce(result, out / "bounce.png"),
        ]
        for path in wrote:
            print(f"  wrote {path}", file=report)
    return 0
