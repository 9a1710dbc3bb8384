"""``ehdfem collide``: one collision (or again, ``--from`` a result), its results table, JSON
with provenance, histories (.npz), plots and FE fields; and
``ehdfem render``: pictures of the FE solids of one collision."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from .. import checks, collide
from ..config import read_inputs
from ..outputs.fields import field_snapshots, write_fields
from ..outputs.histories import write_histories
from . import paths
from .arguments import JSON_HELP, physical_inputs_line, print_table, report_stream, write_json
from .inputs import add_collision_arguments, collision_inputs, run_config

COLLIDE_HELP = "simulate one collision and print its results"
RENDER_HELP = "FE collision: picture of the deformed solids (and a film GIF)"


def add_collide(parser) -> None:
    first = len(parser._actions)
    add_collision_arguments(parser)
    inputs = tuple(a.dest for a in parser._actions[first:] if a.option_strings)
    parser.set_defaults(input_options=inputs)  # the options that --from refuses
    again = parser.add_argument_group("run again")
    again.add_argument(
        "--from",
        dest="from_file",
        metavar="FILE",
        help="run the collision of FILE again: a JSON of collide, render or --json, or a "
        "--histories file, whose inputs and run settings are used as they are (no input or "
        "run setting may be given with it); default: none",
    )
    out = parser.add_argument_group("output")
    out.add_argument("--json", metavar="FILE", help=JSON_HELP)
    out.add_argument(
        "--histories",
        metavar="FILE.npz",
        help="write the histories (gap, velocity, force, energies, H(R,T), P(R,T), ...; SI "
        "copies for physical inputs) as NumPy .npz, units inside (docs/outputs.md); "
        "default: none",
    )
    out.add_argument("--plots", metavar="DIR", help="write PNG plots into DIR; default: none")
    out.add_argument(
        "--field-times",
        type=float,
        nargs="+",
        metavar="T",
        help="with --fields: further instants T [by x0/V0] to write, from 0 to the collision's "
        "end; default: none",
    )
    out.add_argument(
        "--fields",
        metavar="FILE.xdmf",
        help="FE model: displacement, stresses, film pressure and body regions of both solids "
        "at maximum compression, maximum force and the end (and --field-times), as one XDMF "
        "time series for ParaView (SI for physical inputs; docs/pictures.md); default: none",
    )


def check_outputs(args) -> None:
    """Refuse, before any work, an output that cannot be written (:mod:`ehdfem.cli.paths`):
    --json, --histories and --fields in existing folders, --plots a folder (made if missing),
    no two of them the same path; --field-times without --fields is refused (no field file
    would take them)."""
    paths.output_file("json", args.json, stdout=True)
    paths.output_file("histories", args.histories)
    paths.output_file("fields", args.fields)
    paths.output_folder("plots", args.plots)
    paths.distinct_outputs(
        {name: getattr(args, name) for name in ("json", "histories", "fields", "plots")}
    )
    if args.field_times and not args.fields:
        raise checks.InputError(
            "needs --fields FILE.xdmf (the file the fields go to)", "field_times"
        )
    check_instants("field_times", args.field_times)


def check_instants(name: str, times, end: float | None = None) -> None:
    """Refuse an instant T (by x0/V0) of option ``name`` below 0, before any work, or, once the
    collision's end T ``end`` is known, after it."""
    for t in times or ():
        checks.number(name, t, lower=0.0)
        if end is not None and t > end:
            raise checks.InputError(
                f"T = {t:g} is after the collision's end, T = {end:.5g} (by x0/V0): give an "
                f"instant in [0, {end:.5g}]",
                name,
            )


def replayed_inputs(args):
    """The collision inputs and run configuration of ``--from FILE`` (its JSON "inputs", or
    the "inputs" text of a histories file), refusing every input or run setting also given."""
    for dest in args.input_options:
        if getattr(args, dest, None) not in (None, False):
            raise checks.InputError(
                f"cannot be given with --from, which runs {args.from_file}'s inputs and run "
                "settings as they are (run without --from to change them)",
                dest,
            )
    path = paths.input_file("from_file", args.from_file)
    try:
        if path.suffix == ".npz":
            with np.load(path) as stored:
                inputs = json.loads(str(stored["inputs"]))
        else:
            inputs = json.loads(path.read_text())["inputs"]
        return read_inputs(inputs)
    except (KeyError, TypeError, ValueError, OSError) as err:
        what = f"no {err.args[0]!r} entry" if isinstance(err, KeyError) else str(err)
        raise checks.InputError(
            f"{args.from_file!r} holds no collision inputs that can be read (a JSON of collide "
            f'with its "inputs", or a --histories file): {what}',
            "from_file",
        ) from err


def collide_command(args) -> int:
    check_outputs(args)
    if args.from_file is not None:
        inputs, config = replayed_inputs(args)
    else:
        inputs, config = collision_inputs(args), run_config(args)
    if args.fields and config.model != "fem":
        raise checks.InputError("needs --model fem (the half-space has no mesh)", "fields")
    result = collide(inputs, config)
    check_instants("field_times", args.field_times, float(result.normal.history.time[-1]))
    summary = result.summary(args.command_line)
    report = report_stream(args)
    print("ehdfem collide: results (dimensionless, DSH scales; SI under si)", file=report)
    print_table(summary, report)
    write_json(summary, args.json)
    wrote = []
    if args.histories:
        wrote.append(write_histories(result, args.histories, args.command_line))
    if args.fields:
        snapshots = field_snapshots(result.normal, args.field_times)
        units = result.physical.scales() if result.physical else None
        write_fields(result.compliance, args.fields, snapshots, units=units)
        times = ", ".join(f"{t * (units.time if units else 1.0):.4g}" for t, _ in snapshots)
        wrote.append(f"{args.fields} ({'t [s]' if units else 'T'} = {times})")
    if args.plots:
        out = Path(args.plots)
        from ..outputs import plots  # matplotlib costs 0.25 s to import: only when plotting

        units = result.physical.scales() if result.physical else None
        physical = summary["inputs"].get("physical")
        heading = physical_inputs_line(physical).split(": ", 1)[1] if physical else None
        normal = result.normal
        wrote.append(plots.plot_histories(normal, out / "histories.png", units, heading))
        wrote.append(plots.plot_profiles(normal, out / "profiles.png", units, heading))
        if result.tangential is not None:
            wrote.append(plots.plot_tangential(result, out / "tangential.png", heading, units))
    for path in wrote:
        print(f"  wrote {path}", file=report)
    return 0


def add_render(parser) -> None:
    add_collision_arguments(parser, exclude=("model",))  # pictures of the FE solids only
    r = parser.add_argument_group("picture")
    r.add_argument(
        "--out",
        default="render.png",
        help="picture file, its format by its suffix (.png, .pdf, .svg, ...); default: render.png",
    )
    r.add_argument(
        "--time",
        type=float,
        help="instant T [by x0/V0], from 0 to the collision's end; default: maximum compression",
    )
    r.add_argument(
        "--field",
        choices=("von_mises", "hydrostatic", "displacement", "pressure"),
        default="von_mises",
        help="field shown on the solids; default: von_mises",
    )
    r.add_argument(
        "--magnification",
        type=float,
        help="displacement display factor, (0, inf); default: automatic",
    )
    r.add_argument(
        "--animation", metavar="FILE.gif", help="also write the film animation; default: none"
    )
    r.add_argument("--json", metavar="FILE", help=JSON_HELP)


def picture_formats() -> tuple[str, ...]:
    """The suffixes of the picture formats matplotlib writes (render's --out)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    return tuple(f".{kind}" for kind in FigureCanvasAgg(Figure()).get_supported_filetypes())


def render_command(args) -> int:
    from ..outputs.render import animate_film, render_solids

    args.model = "fem"  # no option of render: its pictures are of the FE solids
    paths.output_file("out", args.out, formats=picture_formats())
    paths.output_file("animation", args.animation, formats=(".gif",))
    if args.magnification is not None:
        checks.positive("magnification", args.magnification)
    check_instants("time", [] if args.time is None else [args.time])
    paths.output_file("json", args.json, stdout=True)
    paths.distinct_outputs({name: getattr(args, name) for name in ("out", "animation", "json")})
    result = collide(collision_inputs(args), run_config(args))
    hist = result.normal.history
    check_instants("time", [] if args.time is None else [args.time], float(hist.time[-1]))
    report = report_stream(args)
    write_json(result.summary(args.command_line), args.json)
    time = float(hist.time[int(np.argmin(hist.gap))] if args.time is None else args.time)
    pressure = dict(field_snapshots(result.normal, [time]))[time]
    units = result.physical.scales() if result.physical else None
    p = result.params
    when = f"t = {time * units.time:.4g} s" if units else f"T = {time:.4g}"
    title = (
        f"St = {p.St:.4g}, eps = {p.eps:.3g}, delta = {p.delta:.3g}: {when}, "
        f"e_n = {result.normal.e_n:.4f}"
    )
    picture = render_solids(
        result.compliance, pressure, args.out, args.field, args.magnification, title, units=units
    )
    print(
        f"  wrote {args.out} ({picture.colour_bar}, displacement x {picture.magnification:.3g}, "
        f"{when}, scale bars {' and '.join(picture.scale_bars)})",
        file=report,
    )
    if args.animation:
        frames = animate_film(result.normal, args.animation, units=units)
        print(f"  wrote {args.animation} ({frames} frames)", file=report)
    return 0
