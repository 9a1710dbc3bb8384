"""Command line: ``ehdfem collide`` (one collision), ``ehdfem render`` (pictures of the FE
solids), ``ehdfem sweep`` (a study file over MPI ranks), ``ehdfem critical`` (the critical
Stokes number), ``ehdfem fit`` (closed-form fits), ``ehdfem presets`` (materials and liquids),
``ehdfem bounce`` (a sphere settling and bouncing in a liquid, its contacts EHD collisions).

Each command is a module of :mod:`ehdfem.cli`; their options are generated from the inputs'
and the run configuration's field metadata (:mod:`ehdfem.cli.arguments`). Inputs are either
dimensionless (``--St --eps --delta ...``, DSH scales) or physical (SI units): presets
(``--sphere --wall --liquid``) and/or their values (``--sphere-modulus``,
``--liquid-viscosity``, ...), with ``--radius --speed --layer-thickness``; ``--example`` runs
a steel sphere hitting a glass plate through a 0.3 mm silicone-oil layer at 30 degrees.

Output: the results table on standard output, or on standard error when ``--json -`` puts the
JSON alone on standard output. The form compiler's build log and VTK's warnings are hidden
unless ``--verbose`` (:mod:`ehdfem.console.quiet`); progress bars show on a terminal only
(:mod:`ehdfem.console.progress`). Bad input: ``ehdfem <command>: error: <flag>: <message>``
and exit status 2. A result outside a model's checked range (the half-space theory's range, the
sliding film's superposition or energy) is warned of as ``ehdfem <command>: warning:
<message>`` on standard error, once (by MPI rank 0), and flagged in the result.
"""

from __future__ import annotations

import argparse
import sys
import warnings

from .. import checks
from ..console.quiet import is_quiet, set_quiet
from ..motion.normal import NormalSolverError
from ..version import __version__
from . import bounce, collide, critical, fit, presets, sweep

DESCRIPTION = (
    "Elastohydrodynamic wet collisions: a sphere hits a wall through a liquid layer; ehdfem "
    "predicts rebound or sticking, the restitution coefficients, the film's pressure and "
    "thickness, and the critical Stokes number."
)
VERBOSE_HELP = "show the form compiler's build log and VTK's warnings; default: hidden"
COMMANDS = {  # name: (help, add its arguments, run it)
    "collide": (collide.COLLIDE_HELP, collide.add_collide, collide.collide_command),
    "render": (collide.RENDER_HELP, collide.add_render, collide.render_command),
    "sweep": (sweep.HELP, sweep.add_sweep, sweep.sweep_command),
    "critical": (critical.HELP, critical.add_critical, critical.critical_command),
    "fit": (fit.HELP, fit.add_fit, fit.fit_command),
    "presets": (presets.HELP, presets.add_presets, presets.presets_command),
    "bounce": (bounce.HELP, bounce.add_bounce, bounce.bounce_command),
}


def parsers() -> tuple[argparse.ArgumentParser, dict]:
    """The ``ehdfem`` parser and each command's parser."""
    from .arguments import Parser

    parser = Parser(prog="ehdfem", description=DESCRIPTION)
    parser.add_argument("--version", action="version", version=f"%(prog)s {__version__}")
    parser.add_argument("--verbose", action="store_true", help=VERBOSE_HELP)
    every = Parser(add_help=False)  # options of every command
    every.add_argument(
        "--verbose", action="store_true", default=argparse.SUPPRESS, help=VERBOSE_HELP
    )
    sub = parser.add_subparsers(dest="command", required=True)
    commands = {}
    for name, (text, add, _) in COMMANDS.items():
        commands[name] = sub.add_parser(name, help=text, description=text, parents=[every])
        add(commands[name])
    return parser, commands


def flag_of(parser: argparse.ArgumentParser, name: str | None) -> str | None:
    """The option of ``parser`` whose destination is ``name`` (a field's name), else None."""
    for action in parser._actions:
        if action.dest == name and action.option_strings:
            return action.option_strings[0]
    return None


def _warning_printer(command: str):
    """A warnings.showwarning that prints ``ehdfem <command>: warning: <message>`` on standard
    error, on MPI rank 0 only."""

    def show(message, category, filename, lineno, file=None, line=None):
        mpi = sys.modules.get("mpi4py.MPI")
        if mpi is None or mpi.COMM_WORLD.rank == 0:
            print(f"ehdfem {command}: warning: {message}", file=sys.stderr)

    return show


def main(argv=None) -> int:
    """The ``ehdfem`` command; returns the exit status (0 done, 2 bad input, 3 solver
    failure)."""
    parser, commands = parsers()
    args = parser.parse_args(argv)
    args.command_line = ["ehdfem", *(sys.argv[1:] if argv is None else argv)]
    was_quiet = is_quiet()
    set_quiet(not args.verbose)
    try:
        with warnings.catch_warnings():
            warnings.showwarning = _warning_printer(args.command)
            return COMMANDS[args.command][2](args)
    except checks.InputError as err:
        flag = flag_of(commands[args.command], err.name)
        where = f"{flag}: " if flag else ""
        print(f"ehdfem {args.command}: error: {where}{err}", file=sys.stderr)
        return 2
    except NormalSolverError as err:
        print(f"ehdfem {args.command}: solver failure: {err}", file=sys.stderr)
        return 3
    finally:
        set_quiet(was_quiet)


if __name__ == "__main__":
    sys.exit(main())
