"""Command line: ``ehdfem collide`` (one collision), ``ehdfem sweep`` (a study file over MPI
ranks), ``ehdfem critical`` (the critical Stokes number), ``ehdfem fit`` (closed-form fits).

Inputs are either dimensionless (``--St --eps --delta ...``, DSH scales) or physical
(``--sphere --wall --liquid --radius --speed --layer-thickness ...``, SI units); ``--example``
runs a steel sphere hitting a glass plate through a 0.3 mm silicone-oil layer at 30 degrees.
"""

from __future__ import annotations

import argparse
import csv
import json
import sys
from pathlib import Path

import numpy as np

from . import cavitation, checks, viz
from .closedform import GROUPED, fit_table
from .collision import DEFAULT_NODES, MODELS, TANGENTIAL_MODELS, collide
from .compliance.fem import LOWER_BODIES
from .exports import field_snapshots, write_fields
from .film import LAYERS
from .gap import GAPS
from .normal import NormalSolverError
from .presets import EXAMPLE
from .scales import CollisionParameters, PhysicalCollision, from_presets
from .study import Study, critical_stokes, run_study
from .timestepping import IntegratorOptions
from .viscosity import LAWS as VISCOSITY_LAWS
from .viscosity import ROELANDS_INDEX

PHYSICAL = ("sphere", "wall", "liquid", "radius", "speed", "layer_thickness")


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
    phys.add_argument("--sphere", help="sphere material preset (e.g. steel, glass)")
    phys.add_argument("--wall", help="wall material preset")
    phys.add_argument("--liquid", help="liquid preset (e.g. water, silicone_oil_100cst)")
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


def _numerics_arguments(num) -> None:
    """Model choice, grid, tolerance and outputs of one collision."""
    num.add_argument("--model", choices=MODELS, default="halfspace")
    num.add_argument(
        "--tangential",
        choices=TANGENTIAL_MODELS,
        default="couette",
        help="film model of the tangential motion (oblique impacts)",
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


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="ehdfem", description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    _collision_arguments(
        sub.add_parser("collide", help="simulate one collision and print its results")
    )
    r = sub.add_parser(
        "render", help="FE collision: picture of the deformed solids (and a film GIF)"
    )
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

    s = sub.add_parser("sweep", help="run a study file (TOML) over the MPI ranks; resumable")
    s.add_argument("study", help="study file, e.g. studies/kantak_davis.toml")

    k = sub.add_parser("critical", help="critical Stokes number St_c by bisection on rebound")
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

    f = sub.add_parser("fit", help="closed-form fits (and DEM formulas) against a sweep table")
    f.add_argument("table", help="CSV table written by ehdfem sweep")
    f.add_argument("--json", metavar="FILE", help="write the fits as JSON ('-': stdout)")
    return parser


def _inputs(args) -> CollisionParameters | PhysicalCollision:
    """Build the collision inputs from the arguments, refusing mixed or incomplete sets."""
    given = [name for name in PHYSICAL if getattr(args, name) is not None]
    if args.example:
        values = {**EXAMPLE, **{name: getattr(args, name) for name in given}}
        if args.angle is not None:
            values["angle"] = args.angle
        given = PHYSICAL
    elif given:
        values = {name: getattr(args, name) for name in given}
        values["angle"] = 0.0 if args.angle is None else args.angle
    if given:
        missing = [name for name in PHYSICAL if name not in values]
        if missing:
            raise checks.InputError(
                f"physical inputs need --{', --'.join(m.replace('_', '-') for m in missing)}"
            )
        if args.St is not None or args.eps is not None:
            raise checks.InputError(
                "give either dimensionless (--St, --eps) or physical inputs, not both"
            )
        if args.alpha or args.roelands_pressure is not None:
            raise checks.InputError(
                "physical inputs take --pressure-viscosity [1/Pa], not the scaled --alpha or "
                "--roelands-pressure"
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


def _print_table(summary: dict) -> None:
    rows = [(k, v) for k, v in summary.items() if k != "si"] + list(summary.get("si", {}).items())
    width = max(len(k) for k, _ in rows)
    for key, value in rows:
        text = f"{value:.6g}" if isinstance(value, float) else str(value)
        print(f"  {key:<{width}}  {text}")


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


def collide_command(args) -> int:
    inputs = _inputs(args)
    options = IntegratorOptions(rtol=args.rtol)
    result = collide(
        inputs,
        model=args.model,
        nodes=args.nodes,
        options=options,
        tangential=args.tangential,
        solids=_solids(args, inputs),
    )
    summary = result.summary()
    print("ehdfem collide: results (dimensionless, DSH scales; SI under si)")
    _print_table(summary)
    _write_json(summary, args.json)
    if args.fields:
        if args.model != "fem":
            raise checks.InputError("--fields needs --model fem (the half-space has no mesh)")
        snapshots = field_snapshots(result.normal, args.field_times)
        write_fields(
            result.compliance,
            args.fields,
            snapshots,
            units=result.physical.scales() if result.physical else None,
        )
        print(f"  wrote {args.fields} (T = {', '.join(f'{t:.4g}' for t, _ in snapshots)})")
    if args.plots:
        out = Path(args.plots)
        paths = [
            viz.plot_histories(result.normal, out / "histories.png"),
            viz.plot_profiles(result.normal, out / "profiles.png"),
        ]
        if result.tangential is not None:
            paths.append(viz.plot_tangential(result, out / "tangential.png"))
        for path in paths:
            print(f"  wrote {path}")
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
    found = critical_stokes(params, tuple(args.bracket), args.rtol, args.nodes, model=args.model)
    out = {
        **found,
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
        f"{found['bracket'][1]:.6g}, rtol {args.rtol:g}, {found['collisions']} collisions)"
    )
    _write_json(out, args.json)
    return 0


def _write_json(data: dict, target: str | None) -> None:
    if not target:
        return
    text = json.dumps(data, indent=2)
    if target == "-":
        print(text)
    else:
        Path(target).parent.mkdir(parents=True, exist_ok=True)
        Path(target).write_text(text + "\n")


def fit_command(args) -> int:
    path = Path(args.table)
    if not path.is_file():
        raise checks.InputError(f"table {args.table!r} does not exist")
    with path.open() as f:
        fits = fit_table(list(csv.DictReader(f)))
    for group in fits["normal"]:
        print(
            f"{_labels(group)}, eps = {group['eps']:g}: "
            f"e_n = {group['e_inf']:.4f} (1 - {group['St_c']:.4g}/St)"
            f"  max error {group['max_error']:.3g}, rms {group['rms_error']:.3g}"
        )
    laws = [(f"St_c ({_labels(law['model'])})", law) for law in fits["critical_stokes_laws"]]
    laws += [(name, fits[name]) for name in ("tangential_loss", "spin_change") if name in fits]
    for name, law in laws:
        terms = " ".join(f"{k}^{v:.4g}" for k, v in law.items() if k in ("St", "eps"))
        print(
            f"{name}: {law['coefficient']:.4g} {terms}"
            f"  max error {law['max_error']:.3g}, rms {law['rms_error']:.3g}"
        )
    for name, errors in fits["dem_formulas"].items():
        error, rms = errors["max_error"], errors["rms_error"]
        print(f"DEM formula {name}: max error {error:.3g}, rms {rms:.3g}")
    _write_json(fits, args.json)
    return 0


def _labels(group: dict) -> str:
    """The model labels of a fit group (delta, layer, P_cav, cavitation, viscosity, alpha)."""
    return ", ".join(f"{k} = {group[k]}" for k in ("delta", *(k for k, _ in GROUPED)) if k in group)


def render_command(args) -> int:
    from .render import animate_film, render_solids

    args.model = "fem"
    inputs = _inputs(args)
    result = collide(
        inputs,
        model="fem",
        nodes=args.nodes,
        options=IntegratorOptions(rtol=args.rtol),
        tangential=args.tangential,
        solids=_solids(args, inputs),
    )
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
    print(f"  wrote {args.out} ({args.field}, displacement x {magnification:.3g}, T = {time:.4g})")
    if args.animation:
        frames = animate_film(result.normal, args.animation)
        print(f"  wrote {args.animation} ({frames} frames)")
    return 0


COMMANDS = {
    "collide": collide_command,
    "render": render_command,
    "sweep": sweep_command,
    "critical": critical_command,
    "fit": fit_command,
}


def main(argv=None) -> int:
    args = _parser().parse_args(argv)
    try:
        return COMMANDS[args.command](args)
    except checks.InputError as err:
        print(f"ehdfem: error: {err}", file=sys.stderr)
        return 2
    except NormalSolverError as err:
        print(f"ehdfem: solver failure: {err}", file=sys.stderr)
        return 3


if __name__ == "__main__":
    sys.exit(main())
