"""``ehdfem critical``: the critical Stokes number St_c by bisection on the rebound."""

from __future__ import annotations

from dataclasses import asdict

from .. import CollisionParameters, checks, critical_stokes
from ..film import cavitation
from ..inputs.settings import described
from ..motion.timestepping import IntegratorOptions
from ..version import __version__
from .arguments import add_fields, given, report_stream, write_json
from .inputs import add_run_arguments, run_config

HELP = "critical Stokes number St_c by bisection on rebound"
NOT_ASKED = ("St", "angle", "spin")  # St is searched; the bisection is on the normal motion
NO_EFFECT = ("tangential", "deformation")  # the tangential motion does not decide a rebound


def add_critical(parser) -> None:
    inputs = parser.add_argument_group("dimensionless inputs (DSH scales)")
    add_fields(inputs, CollisionParameters, exclude=NOT_ASKED)
    search = parser.add_argument_group("bisection")
    search.add_argument(
        "--bracket",
        type=float,
        nargs=2,
        default=(1.0, 1000.0),
        metavar=("LOW", "HIGH"),
        help="starting bracket of St, widened until it holds St_c; default: 1 1000",
    )
    search.add_argument(
        "--rtol",
        type=float,
        default=1e-3,
        help="relative width of the final bracket; default: 0.001",
    )
    # the time-step settings are left out: --rtol is the bracket's here
    add_run_arguments(parser, exclude=[*NO_EFFECT, *(f.name for f in described(IntegratorOptions))])
    parser.add_argument(
        "--json",
        metavar="FILE",
        help="write {St_c, bracket, ...} as JSON ('-': stdout); default: none",
    )


def critical_command(args) -> int:
    values = given(args, CollisionParameters)
    if "eps" not in values:
        raise checks.InputError("--eps is required", "eps")
    params = CollisionParameters(**values, St=1.0)
    config = run_config(args)
    found = critical_stokes(
        params, tuple(args.bracket), args.rtol, config, progress_label="St_c bisection"
    )
    parameters = {k: v for k, v in asdict(params).items() if k not in NOT_ASKED}
    parameters["p_cav"] = cavitation.suction_limit_output(params.p_cav)
    out = {**found, "ehdfem_version": __version__, **parameters, "run": config.settings()}
    print(
        f"St_c = {found['St_c']:.6g} (bracket {found['bracket'][0]:.6g} .. "
        f"{found['bracket'][1]:.6g}, rtol {args.rtol:g}, {found['collisions']} collisions)",
        file=report_stream(args),
    )
    write_json(out, args.json)
    return 0
