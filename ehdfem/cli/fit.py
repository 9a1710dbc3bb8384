"""``ehdfem fit``: closed-form fits (and DEM formulas) against a sweep table."""

from __future__ import annotations

import csv
from pathlib import Path

from .. import checks
from ..dem.closedform import GROUPED, describe_ranges, fit_table, python_source
from ..study.sweep import write_atomic
from ..version import __version__
from . import paths
from .arguments import report_stream, write_json

HELP = "closed-form fits (and DEM formulas) against a sweep table"


def add_fit(parser) -> None:
    parser.add_argument(
        "table", help="CSV table written by ehdfem sweep (columns status, St, eps, e_n, ...)"
    )
    parser.add_argument(
        "--json", metavar="FILE", help="write the fits as JSON ('-': stdout); default: none"
    )
    parser.add_argument(
        "--python",
        metavar="FILE",
        help="write the closed forms for DEM (e_n, e_t, spin change) as a Python module to "
        "copy; default: none",
    )


def fit_command(args) -> int:
    path = paths.input_file("table", args.table)
    paths.output_file("json", args.json, stdout=True)
    paths.output_file("python", args.python)
    try:
        fits = fit_table(read_table(path))
    except checks.InputError as err:
        raise checks.InputError(f"{args.table!r}: {err}", "table") from err
    if not fits["normal"] and "closed_forms" not in fits:
        raise checks.InputError(
            f"nothing to fit in {args.table!r}: {fits['normal_skipped']}; "
            f"{fits['closed_forms_skipped']}",
            "table",
        )
    if args.python and "closed_forms" not in fits:
        raise checks.InputError(fits["closed_forms_skipped"], "python")
    report = report_stream(args)
    print_fits(fits, report)
    write_json(fits, args.json)
    if args.python:
        write_atomic(Path(args.python), python_source(fits["closed_forms"], path.name, __version__))
        print(f"wrote {args.python}", file=report)
    return 0


def read_table(path: Path) -> list[dict]:
    """The rows of the CSV table at ``path``; a file that is not a readable CSV table is
    refused (the table's columns are checked by :func:`ehdfem.dem.closedform.table_rows`)."""
    try:
        with path.open(newline="") as f:
            return list(csv.DictReader(f))
    except (UnicodeDecodeError, csv.Error) as err:
        raise checks.InputError(f"not a CSV table ({err})", "table") from err


def print_fits(fits: dict, report) -> None:
    """The fits, one line each, and why a fit was left out (``..._skipped``)."""
    for group in fits["normal"]:
        print(
            f"{_labels(group)}, eps = {group['eps']:g}: "
            f"e_n = {group['e_inf']:.4f} (1 - {group['St_c']:.4g}/St)"
            f"  max error {group['max_error']:.3g}, rms {group['rms_error']:.3g}",
            file=report,
        )
    for law in fits["critical_stokes_laws"]:
        print(
            f"St_c ({_labels(law['model'])}): {law['coefficient']:.4g} eps^{law['eps']:.4g}"
            f"  max error {law['max_error']:.3g}, rms {law['rms_error']:.3g}",
            file=report,
        )
    forms = fits.get("closed_forms")
    if forms is not None:
        print(f"closed forms for DEM over {describe_ranges(forms['ranges'])}:", file=report)
        for name in ("normal", "tangential_loss", "spin_change"):
            form = forms[name]
            relative = form.get("max_relative_error")
            print(
                f"  {form['form']}\n    max error {form['max_error']:.3g}, rms "
                f"{form['rms_error']:.3g}"
                + ("" if relative is None else f", max relative error {relative:.3g}"),
                file=report,
            )
    for name, errors in fits["dem_formulas"].items():
        error, rms = errors["max_error"], errors["rms_error"]
        print(f"DEM formula {name}: max error {error:.3g}, rms {rms:.3g}", file=report)
    for skipped in ("normal_skipped", "closed_forms_skipped"):
        if skipped in fits:
            print(f"left out: {fits[skipped]}", file=report)


def _labels(group: dict) -> str:
    """The model labels of a fit group (delta, layer, P_cav, cavitation, viscosity, alpha)."""
    keys = ("delta", *(k for k, _ in GROUPED))
    shown = {k: "none" if group[k] is None else group[k] for k in keys if k in group}
    return ", ".join(f"{k} = {v}" for k, v in shown.items())
