"""``ehdfem collide``: one collision, its results table, JSON, plots and FE fields; and
``ehdfem render``: pictures of the FE solids of one collision."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from .. import checks, collide
from ..outputs import plots
from ..outputs.fields import field_snapshots, write_fields
from .arguments import JSON_HELP, print_table, report_stream, write_json
from .inputs import add_collision_arguments, collision_inputs, run_config

COLLIDE_HELP = "simulate one collision and print its results"
RENDER_HELP = "FE collision: picture of the deformed solids (and a film GIF)"


def add_collide(parser) -> None:
    add_collision_arguments(parser)
    out = parser.add_argument_group("output")
    out.add_argument("--json", metavar="FILE", help=JSON_HELP)
    out.add_argument("--plots", metavar="DIR", help="write PNG plots into DIR; default: none")
    out.add_argument(
        "--field-times",
        type=float,
        nargs="+",
        metavar="T",
        help="with --fields: further instants T [by x0/V0] to write; default: none",
    )
    out.add_argument(
        "--fields",
        metavar="FILE.xdmf",
        help="FE model: displacement, stresses, film pressure and body regions of both solids "
        "at maximum compression, maximum force and the end (and --field-times), as one XDMF "
        "time series for ParaView (SI for physical inputs; docs/pictures.md); default: none",
    )


def collide_command(args) -> int:
    config = run_config(args)
    if args.fields and config.model != "fem":
        raise checks.InputError("--fields needs --model fem (the half-space has no mesh)")
    result = collide(collision_inputs(args), config)
    summary = result.summary()
    report = report_stream(args)
    print("ehdfem collide: results (dimensionless, DSH scales; SI under si)", file=report)
    print_table(summary, report)
    write_json(summary, args.json)
    wrote = []
    if args.fields:
        snapshots = field_snapshots(result.normal, args.field_times)
        units = result.physical.scales() if result.physical else None
        write_fields(result.compliance, args.fields, snapshots, units=units)
        times = ", ".join(f"{t * (units.time if units else 1.0):.4g}" for t, _ in snapshots)
        wrote.append(f"{args.fields} ({'t [s]' if units else 'T'} = {times})")
    if args.plots:
        out = Path(args.plots)
        wrote.append(plots.plot_histories(result.normal, out / "histories.png"))
        wrote.append(plots.plot_profiles(result.normal, out / "profiles.png"))
        if result.tangential is not None:
            wrote.append(plots.plot_tangential(result, out / "tangential.png"))
    for path in wrote:
        print(f"  wrote {path}", file=report)
    return 0


def add_render(parser) -> None:
    add_collision_arguments(parser, exclude=("model",))  # pictures of the FE solids only
    r = parser.add_argument_group("picture")
    r.add_argument("--out", default="render.png", help="PNG file; default: render.png")
    r.add_argument("--time", type=float, help="instant T [by x0/V0]; default: maximum compression")
    r.add_argument(
        "--field",
        choices=("von_mises", "hydrostatic", "displacement", "pressure"),
        default="von_mises",
        help="field shown on the solids; default: von_mises",
    )
    r.add_argument(
        "--magnification", type=float, help="displacement display factor; default: automatic"
    )
    r.add_argument(
        "--animation", metavar="FILE.gif", help="also write the film animation; default: none"
    )
    r.add_argument("--json", metavar="FILE", help=JSON_HELP)


def render_command(args) -> int:
    from ..outputs.render import animate_film, render_solids

    args.model = "fem"  # no option of render: its pictures are of the FE solids
    result = collide(collision_inputs(args), run_config(args))
    report = report_stream(args)
    write_json(result.summary(), args.json)
    hist = result.normal.history
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
