"""A study table as the fits read it: its successful rows, numbers as floats, defaults filled.

The table is the CSV of ``ehdfem sweep`` (:mod:`ehdfem.study.sweep`); every value is
dimensionless (DSH scales, :mod:`ehdfem.inputs.scales`). A table the fits cannot read is
refused with a message naming what is missing: the column, or the line of the CSV file.
"""

from __future__ import annotations

from .. import checks
from ..inputs.scales import CollisionParameters

_FIELDS = CollisionParameters.__dataclass_fields__
# the labels besides eps and delta that tell the fit groups apart, with their defaults (P_cav
# None: no cavitation limit; the default cavitation model and viscosity law by name)
GROUPED = (
    ("layer", "thin"),
    ("p_cav", None),
    ("cavitation", _FIELDS["cavitation"].default.name),
    ("viscosity", _FIELDS["viscosity"].default.name),
    ("alpha", 0.0),
)
REQUIRED_COLUMNS = ("status", "St", "eps", "e_n")  # the others have their defaults
NUMBERS = ("St", "eps", "delta", "e_n", "e_t", "spin_change", "alpha", "p_cav")  # None if empty
DEFAULTS = {"delta": _FIELDS["delta"].default, **dict(GROUPED)}
EMPTY = ("", "None", "none", "-inf", None)  # an empty cell; for P_cav, no limit


def table_rows(rows: list[dict]) -> list[dict]:
    """The successful rows of a study table (as read from its CSV: values as strings or
    numbers) with every number a float, an empty cell None (for P_cav: no limit), and delta and
    the model labels of GROUPED at their defaults where their column or cell is empty (a study
    that does not sweep them holds them there). A table without the REQUIRED_COLUMNS, without
    a successful point, or with a cell that is not a number is refused by name (column, and
    the line of the CSV file)."""
    missing = [c for c in REQUIRED_COLUMNS if not rows or c not in rows[0]]
    if missing:
        raise checks.InputError(
            f"the table has no column {', '.join(missing)} (a table of ehdfem sweep has "
            f"{', '.join(REQUIRED_COLUMNS)} and the other outputs)"
            if rows
            else "the table has no rows"
        )
    ok = [(line, r) for line, r in enumerate(rows, 2) if str(r["status"]).startswith("ok")]
    if not ok:
        raise checks.InputError(
            f"the table has no successful point to fit (status ok:...; {len(rows)} failed)"
        )
    return [_numbers({**DEFAULTS, **_given(r)}, line) for line, r in ok]


def _given(row: dict) -> dict:
    """The cells of ``row`` but the empty ones of the columns with a default."""
    return {k: v for k, v in row.items() if k and not (k in DEFAULTS and v in EMPTY)}


def _numbers(row: dict, line: int) -> dict:
    """``row`` with its NUMBERS as floats (None where empty; P_cav None for no limit)."""
    for key in NUMBERS:
        value = row.get(key)
        if value in EMPTY:
            row[key] = None
            continue
        try:
            row[key] = float(value)
        except (TypeError, ValueError):
            raise checks.InputError(
                f"line {line}: column {key} = {value!r} is not a number", key
            ) from None
    for key in REQUIRED_COLUMNS[1:]:
        if row[key] is None:
            raise checks.InputError(f"line {line}: column {key} is empty", key)
    return row
