"""``ehdfem fit``: closed-form fits (and DEM formulas) against a sweep table, and the closed
forms for DEM written out (Python module, C header, the fitted table as CSV)."""

from __future__ import annotations

import csv
from pathlib import Path

from .. import checks
from ..dem import export, fitting, lookup
from ..dem.box import describe
from ..dem.closedform import fit_table
from ..dem.forms import NAMES
from ..dem.forms import describe as describe_form
from ..dem.table import GROUPED, table_rows
from ..study.sweep import write_atomic
from ..version import __version__
from . import paths
from .arguments import report_stream, write_json

HELP = "closed-form fits (and DEM formulas) against a sweep table"
EXPORTS = {
    "python": "the closed forms for DEM as a Python module to copy (standard library only)",
    "c": "the closed forms for DEM as a C99 header (no dependency but <math.h>)",
    "table": "the fitted table (CSV: St_c, m, A, B per layer, eps, P_cav, St) to interpolate",
}


def add_fit(parser) -> None:
    parser.add_argument(
        "table", help="CSV table written by ehdfem sweep (columns status, St, eps, e_n, ...)"
    )
    parser.add_argument(
        "--json", metavar="FILE", help="write the fits as JSON ('-': stdout); default: none"
    )
    parser.add_argument(
        "--held-back",
        metavar="TABLE",
        help="a sweep table of points left out of the fit, on which the closed forms' errors "
        "are measured (and stated in the exports); default: none",
    )
    for name, what in EXPORTS.items():
        parser.add_argument(f"--{name}-out" if name == "table" else f"--{name}", metavar="FILE",
                            help=f"write {what}; default: none")  # fmt: skip


def fit_command(args) -> int:
    path = paths.input_file("table", args.table)
    held_path = args.held_back and paths.input_file("held_back", args.held_back)
    paths.output_file("json", args.json, stdout=True)
    outputs = {"python": args.python, "c": args.c, "table_out": args.table_out}
    for name, value in outputs.items():
        paths.output_file(name, value)
    rows = read_table(path, "table")
    try:
        fits = fit_table(rows)
    except checks.InputError as err:
        raise checks.InputError(f"{args.table!r}: {err}", "table") from err
    if not fits["normal"] and "closed_forms" not in fits:
        raise checks.InputError(
            f"nothing to fit in {args.table!r}: {fits['normal_skipped']}; "
            f"{fits['closed_forms_skipped']}",
            "table",
        )
    wanted = [name for name, value in outputs.items() if value]
    if (wanted or held_path) and "closed_forms" not in fits:
        raise checks.InputError(fits["closed_forms_skipped"], (wanted or ["held_back"])[0])
    if held_path:
        fits["closed_forms"]["held_back"] = _held_back(fits["closed_forms"], held_path)
    report = report_stream(args)
    print_fits(fits, report)
    write_json(fits, args.json)
    forms = fits.get("closed_forms")
    held = forms and forms.get("held_back")
    for name, writer in (("python", export.python_source), ("c", export.c_header)):
        if outputs[name]:
            write_atomic(Path(outputs[name]), writer(forms, path.name, __version__, held))
            print(f"wrote {outputs[name]}", file=report)
    if args.table_out:
        ok = table_rows(rows)
        write_atomic(Path(args.table_out), lookup.csv_text(lookup.build(ok)))
        print(f"wrote {args.table_out}", file=report)
    return 0


def _held_back(forms: dict, path: Path) -> dict:
    """The forms' errors on the held-back table at ``path`` (its points must lie in the box)."""
    try:
        return fitting.errors(forms, table_rows(read_table(path, "held_back")))
    except checks.InputError as err:
        raise checks.InputError(f"{str(path)!r}: {err}", "held_back") from err


def read_table(path: Path, option: str) -> list[dict]:
    """The rows of the CSV table at ``path``; a file that is not a readable CSV table is
    refused naming ``option`` (the table's columns are checked by
    :func:`ehdfem.dem.table.table_rows`)."""
    try:
        with path.open(newline="") as f:
            return list(csv.DictReader(f))
    except (UnicodeDecodeError, csv.Error) as err:
        raise checks.InputError(f"not a CSV table ({err})", option) from err


def print_fits(fits: dict, report) -> None:
    """The fits, one line each with the absolute error of what it gives over the table's
    points (e_n, or St_c of a critical Stokes number's law), and why a fit was left out
    (``..._skipped``)."""
    for group in fits["normal"]:
        print(
            f"{_labels(group)}, eps = {group['eps']:g}: "
            f"e_n = {group['e_inf']:.4f} (1 - {group['St_c']:.4g}/St)"
            f"  e_n error: max {group['max_error']:.3g}, rms {group['rms_error']:.3g}",
            file=report,
        )
    for law in fits["critical_stokes_laws"]:
        print(
            f"St_c ({_labels(law['model'])}): {law['coefficient']:.4g} eps^{law['eps']:.4g}"
            f"  St_c error: max {law['max_error']:.3g}, rms {law['rms_error']:.3g}",
            file=report,
        )
    forms = fits.get("closed_forms")
    if forms is not None:
        print(f"closed forms for DEM over {describe(forms['box'])}:", file=report)
        for name in NAMES:
            print(f"  {describe_form(name)}", file=report)
        held = forms.get("held_back")
        print(f"  largest errors on held-back points: {export.describe_errors(held)}", file=report)
    for name, errors in fits["dem_formulas"].items():
        error, rms = errors["max_error"], errors["rms_error"]
        print(f"DEM formula {name}: e_n error: max {error:.3g}, rms {rms:.3g}", file=report)
    for skipped in ("normal_skipped", "closed_forms_skipped"):
        if skipped in fits:
            print(f"left out: {fits[skipped]}", file=report)


def _labels(group: dict) -> str:
    """The model labels of a fit group (delta, layer, P_cav, cavitation, viscosity, alpha)."""
    keys = ("delta", *(k for k, _ in GROUPED))
    shown = {k: "none" if group[k] is None else group[k] for k in keys if k in group}
    return ", ".join(f"{k} = {v}" for k, v in shown.items())
