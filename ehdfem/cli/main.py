"""Command line: ``ehdfem collide`` (one collision), ``ehdfem render`` (pictures of the FE
solids), ``ehdfem sweep`` (a study file over MPI ranks), ``ehdfem critical`` (the critical
Stokes number), ``ehdfem fit`` (closed-form fits), ``ehdfem presets`` (materials and liquids),
``ehdfem bounce`` (a sphere settling and bouncing in a liquid, its contacts EHD collisions),
``ehdfem dem`` (a real DEM engine, Yade or LIGGGHTS, on one collision beside the full model).

Each command is a module of :mod:`ehdfem.cli`; their options are generated from the inputs'
and the run configuration's field metadata (:mod:`ehdfem.cli.arguments`). Inputs are either
dimensionless (``--St --eps --delta ...``, DSH scales) or physical (SI units): presets
(``--sphere --wall --liquid``) and/or their values (``--sphere-modulus``,
``--liquid-viscosity``, ...), with ``--radius --speed --layer-thickness``; ``--example`` runs
a steel sphere hitting a glass plate through a 0.3 mm silicone-oil layer at 30 degrees.

Output: the results table on standard output, or on standard error when ``--json -`` puts the
JSON alone on standard output. The form compiler's build log and VTK's warnings are hidden
unless ``--verbose`` (:mod:`ehdfem.console.quiet`); progress bars show on a terminal only
(:mod:`ehdfem.console.progress`). Bad input, including an output path that cannot be
written (:mod:`ehdfem.cli.paths`), is refused before any work starts: ``ehdfem <command>:
error: <flag>: <message>`` on standard error, once (by MPI rank 0), and exit status 2 on
every rank; a file that cannot be read or written later gives exit status 1. A result
outside a model's checked range (the half-space theory's range, the sliding film's
superposition or energy) is warned of as ``ehdfem <command>: warning: <message>`` on standard
error, once (by MPI rank 0), and flagged in the result.
"""

from __future__ import annotations

import argparse
import os
import re
import sys
import warnings

from .. import checks
from ..console.progress import rank, settle_ranks
from ..console.quiet import is_quiet, set_quiet
from ..motion.normal import NormalSolverError
from ..version import __version__
from . import bounce, caused_by_interrupt, collide, critical, dem, fit, presets, sweep

DESCRIPTION = (
    "Elastohydrodynamic wet collisions: a sphere hits a wall through a liquid layer; ehdfem "
    "predicts rebound or sticking, the restitution coefficients, the film's pressure and "
    "thickness, and the critical Stokes number."
)
INTERRUPTED = "stopped by Ctrl-C; files already written are kept"
VERBOSE_HELP = "show the form compiler's build log and VTK's warnings; default: hidden"
COMMANDS = {  # name: (help, add its arguments, run it)
    "collide": (collide.COLLIDE_HELP, collide.add_collide, collide.collide_command),
    "render": (collide.RENDER_HELP, collide.add_render, collide.render_command),
    "sweep": (sweep.HELP, sweep.add_sweep, sweep.sweep_command),
    "critical": (critical.HELP, critical.add_critical, critical.critical_command),
    "fit": (fit.HELP, fit.add_fit, fit.fit_command),
    "presets": (presets.HELP, presets.add_presets, presets.presets_command),
    "bounce": (bounce.HELP, bounce.add_bounce, bounce.bounce_command),
    "dem": (dem.HELP, dem.add_dem, dem.dem_command),
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
    """How the user names the field or argument ``name`` on ``parser``'s command line: its
    option (``--p-cav`` for p_cav), or a positional argument's name; None when it has none."""
    for action in parser._actions:
        if action.dest == name:
            return action.option_strings[0] if action.option_strings else action.dest
    return None


FIELD_NAME = re.compile(r"(?<![\w-])[a-z]\w*_\w+")  # a field's name such as vapour_pressure


def error_text(err: checks.InputError, parser: argparse.ArgumentParser) -> str:
    """``--flag: message`` for a refused input: the message names the options as typed on the
    command line where the library names the fields (``St = 0.0 is ...`` becomes ``--St: 0.0
    is ...``; ``vapour_pressure`` becomes ``--vapour-pressure``)."""
    text, name = str(err), err.name
    named = re.match(r"([a-z]\w*) = ", text)  # an unnamed error that starts with its field
    if name is None and named and flag_of(parser, named.group(1)):
        name = named.group(1)
    flag = flag_of(parser, name)
    for prefix in (f"{name} = ", f"{name} ", f"{flag} "):
        if flag and text.startswith(prefix):
            text = text[len(prefix) :]
            break
    text = FIELD_NAME.sub(lambda m: flag_of(parser, m.group()) or m.group(), text)
    return f"{flag}: {text}" if flag else text


def say(command: str, kind: str, text: str) -> None:
    """``ehdfem <command>: <kind>: <text>`` on standard error, by MPI rank 0 only (every rank
    has the same inputs and meets the same error or warning)."""
    if rank() == 0:
        print(f"ehdfem {command}: {kind}: {text}", file=sys.stderr)


NUMBER = re.compile(r"\d+(\.\d+)?(e[-+]?\d+)?")  # what differs between repeats of a warning


class WarningPrinter:
    """A warnings.showwarning that prints ``ehdfem <command>: warning: <message>`` (rank 0):
    of warnings that differ only in their numbers (one per collision of a search, a sweep's
    point or a bounce's contact) the first, and at the end (:meth:`repeats`) how many more
    came."""

    def __init__(self, command: str):
        self.command = command
        self.seen: dict[str, list] = {}  # the message with "#" for its numbers: [first, count]

    def __call__(self, message, category, filename, lineno, file=None, line=None):
        text = str(message)
        first = self.seen.setdefault(NUMBER.sub("#", text), [text, 0])
        first[1] += 1
        if first[1] == 1:
            say(self.command, "warning", text)

    def repeats(self) -> None:
        """One line for each warning that came more than once."""
        for text, count in self.seen.values():
            if count > 1:
                shown = text if len(text) <= 60 else text[:57] + "..."
                say(
                    self.command,
                    "warning",
                    f'{count - 1} more like "{shown}", with other numbers, were not shown',
                )


def main(argv=None) -> int:
    """The ``ehdfem`` command; returns the exit status (0 done, 1 a file could not be read or
    written, 2 bad input, 3 solver failure, 130 interrupted by Ctrl-C: one line, no traceback,
    saying what was saved and how to resume where the command knows (a sweep resumes from its
    points); what was written stays), the same on every MPI rank. A reader that closes the pipe
    early (``| head``) ends the command quietly with status 1."""
    parser, commands = parsers()
    args, unknown = parser.parse_known_args(argv)
    if unknown:
        commands[args.command].error(f"unrecognized arguments: {' '.join(unknown)}")
    args.command_line = ["ehdfem", *(sys.argv[1:] if argv is None else argv)]
    was_quiet = is_quiet()
    set_quiet(not args.verbose)
    try:
        with warnings.catch_warnings():
            warnings.showwarning = printer = WarningPrinter(args.command)
            try:
                return COMMANDS[args.command][2](args)
            finally:
                printer.repeats()
    except checks.InputError as err:
        say(args.command, "error", error_text(err, commands[args.command]))
        settle_ranks()
        return 2
    except NormalSolverError as err:
        say(args.command, "solver failure", str(err))
        settle_ranks()
        return 3
    except (KeyboardInterrupt, SystemError) as err:  # SystemError: numba wrapped the Ctrl-C
        if not caused_by_interrupt(err):
            raise
        # a command may say what it saved and how to resume (cli.interrupt_says)
        said = str(err) if isinstance(err, KeyboardInterrupt) else ""
        say(args.command, "interrupted", said or INTERRUPTED)
        return 130
    except BrokenPipeError:  # the reader left (| head): no more output, and no message
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 1
    except OSError as err:  # a file that could not be read or written, possibly on one rank
        where = f"{err.filename}: " if err.filename else ""
        print(f"ehdfem {args.command}: error: {where}{err.strerror or err}", file=sys.stderr)
        return 1
    finally:
        set_quiet(was_quiet)


if __name__ == "__main__":
    sys.exit(main())
