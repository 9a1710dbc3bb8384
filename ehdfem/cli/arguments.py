"""Command-line options built from the input dataclasses' field metadata
(:mod:`ehdfem.settings`), and the output helpers shared by the commands.

Each field becomes ``--name`` (underscores as dashes, or the field's ``flag``) with its help,
unit or scale, allowed values and default in ``--help``. Options are not set unless given
(their default is the dataclass's), so :func:`given` returns only what the user typed.
Negative numbers in scientific notation (``--p-cav -1e1``) are values, not options.
"""

from __future__ import annotations

import argparse
import json
import re
import sys
from pathlib import Path

import numpy as np

from .. import checks
from ..console.progress import rank, settle_ranks
from ..outputs import registry
from ..settings import allowed_text, default_text, flat_fields, kind, meta
from ..study.sweep import write_atomic

NEGATIVE_NUMBER = re.compile(r"^-(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$|^-inf$")


class Parser(argparse.ArgumentParser):
    """An argument parser that reads -1e1, -.5 and -inf as numbers (argparse's own reads
    only -1 and -1.5 so; its subcommands' parsers are of this class too) and takes no
    abbreviated option (argparse's own would read --radius as --radius-ratio where there is
    no --radius), and prints its refusals in the form of the others, once under MPI."""

    def __init__(self, *args, **kwargs):
        kwargs.setdefault("allow_abbrev", False)
        super().__init__(*args, **kwargs)
        self._negative_number_matcher = NEGATIVE_NUMBER

    def error(self, message: str):
        """Exit with status 2 after the one line ``<prog>: error: --flag: message`` (the form of
        every refused input; argparse's own says ``argument --flag: message`` after the whole
        usage, 30 lines for collide), printed by MPI rank 0 only; a refusal that names no
        option points to --help."""
        if rank() == 0:
            text = message.removeprefix("argument ")
            if not text.startswith("-"):
                text += f" (see {self.prog} --help)"
            print(f"{self.prog}: error: {text}", file=sys.stderr)
        settle_ranks()
        sys.exit(2)


def option(f) -> str:
    """The command-line name of field ``f``: --p-cav for p_cav, or its ``flag``."""
    return "--" + (meta(f, "flag") or f.name.replace("_", "-"))


def destination(f) -> str:
    """The argparse destination of field ``f``."""
    return option(f)[2:].replace("-", "_")


def help_text(cls, f) -> str:
    """Help of field ``f`` of ``cls``: what it is, [unit], allowed values, default."""
    unit = meta(f, "unit")
    allowed = "" if kind(cls, f) is bool or meta(f, "choices") else allowed_text(f)
    return (
        meta(f, "help")
        + (f" [{unit}]" if unit else "")
        + (f", {allowed}" if allowed else "")
        + f"; default: {default_text(f)}"
    ).replace("%", "%%")


def _on_off(text: str) -> bool:
    if text not in ("on", "off"):
        raise argparse.ArgumentTypeError(f"expected on or off, got {text!r}")
    return text == "on"


def add_fields(group, cls, names=None, exclude=(), switches=False) -> None:
    """An option per flat setting of the dataclass ``cls`` (those in ``names`` if given, none
    in ``exclude``): its scalar fields, its components by name (``--viscosity barus``) and the
    fields of every registered component (:func:`ehdfem.settings.flat_fields`); floats and
    integers typed, strings with their choices, booleans as on/off (with ``switches``: as
    --name and --no-name); unset unless given."""
    for owner, f in flat_fields(cls):
        if (names is not None and f.name not in names) or f.name in exclude:
            continue
        base = kind(owner, f)
        extra = {"choices": meta(f, "choices")} if meta(f, "choices") else {}
        if base is bool and switches:
            extra = {"action": argparse.BooleanOptionalAction}
        elif base is bool:
            extra = {"type": _on_off, "metavar": "{on,off}"}
        elif base in (int, float):
            extra = {"type": base, "metavar": f.name.upper() if len(f.name) < 4 else "X"}
        group.add_argument(
            option(f),
            dest=destination(f),
            default=argparse.SUPPRESS,
            help=help_text(owner, f),
            **extra,
        )


def named_by_option(err: checks.InputError, cls) -> checks.InputError:
    """``err``, refusing a field of ``cls`` whose option is spelt otherwise than the field
    (its ``flag``), named by that option's destination, so that the refusal names the option
    as typed; else ``err`` itself."""
    renamed = {f.name: destination(f) for _, f in flat_fields(cls)}
    if renamed.get(err.name, err.name) == err.name:
        return err
    text = str(err).removeprefix(f"{err.name} = ").removeprefix(f"{err.name} ")
    return checks.InputError(text, renamed[err.name])


def given(args, cls, names=None) -> dict:
    """The values of ``cls``'s flat settings given on the command line, by name."""
    fields = [f for _, f in flat_fields(cls) if names is None or f.name in names]
    return {f.name: getattr(args, destination(f)) for f in fields if hasattr(args, destination(f))}


def report_stream(args):
    """Where the human-readable report goes: standard error when ``--json -`` takes standard
    output for the JSON alone, else standard output."""
    return sys.stderr if getattr(args, "json", None) == "-" else sys.stdout


def print_table(summary: dict, stream) -> None:
    """The collision's groups, models and time-step control, one per line, then its outputs
    with their scale and meaning, the SI values last (:func:`ehdfem.outputs.registry.format_table`;
    an output that does not apply shows n/a and why; the inputs are in the JSON only), then
    its plausibility notes, a line each (``note: ...``)."""
    physical = summary.get("inputs", {}).get("physical")
    if physical:
        print(f"  {physical_inputs_line(physical)}", file=stream)
    outputs = set(registry.names()) | {"not_applicable", "notes"}
    rows = [(k, v) for k, v in summary.items() if not isinstance(v, dict) and k not in outputs]
    width = max(len(k) for k, _ in rows)
    for key, value in rows:
        text = f"{value:.6g}" if isinstance(value, float) else str(value)
        print(f"  {key:<{width}}  {text}", file=stream)
    print(registry.format_table(summary), file=stream)
    for note in summary.get("notes", ()):
        print(f"  note: {note}", file=stream)


def physical_inputs_line(physical: dict) -> str:
    """One line of a physical collision's inputs (SI, as the JSON's "physical" inputs hold
    them): the sphere, its radius, speed, angle and spin, the wall, the layer and the liquid."""
    sphere, wall, liquid = (physical[k]["name"] for k in ("sphere", "wall", "liquid"))
    spin = f", spin {physical['spin']:.4g} rad/s" if physical.get("spin") else ""
    return (
        f"physical inputs: {sphere} sphere of radius {physical['radius'] * 1e3:.4g} mm at "
        f"{physical['speed']:.4g} m/s, {physical['angle']:.4g} deg from the normal{spin}, on "
        f"{wall} through a {physical['layer']} layer of {physical['layer_thickness'] * 1e3:.4g} "
        f"mm of {liquid} ({physical['liquid']['viscosity']:.4g} Pa s)"
    )


def json_ready(value):
    """``value`` with every non-finite float (NaN, +-inf) as None and tuples as lists, so that
    the text is strict JSON (jq, JSON.parse and json.load all read it)."""
    if isinstance(value, dict):
        return {key: json_ready(item) for key, item in value.items()}
    if isinstance(value, list | tuple):
        return [json_ready(item) for item in value]
    if isinstance(value, float | np.floating) and not np.isfinite(value):
        return None
    return value.item() if isinstance(value, np.generic) else value


def write_json(data: dict, target: str | None) -> None:
    """Write ``data`` as strict JSON to the file ``target`` (in a folder that exists:
    :func:`ehdfem.cli.paths.output_file`), or alone to standard output when ``target`` is "-";
    nothing when it is None."""
    if not target:
        return
    text = json.dumps(json_ready(data), indent=2, allow_nan=False)
    if target == "-":
        sys.stdout.write(text + "\n")
        sys.stdout.flush()
    else:
        write_atomic(Path(target), text + "\n")


JSON_HELP = "write the results as JSON ('-' for standard output alone); default: none"
