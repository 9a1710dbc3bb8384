"""The fitted table itself, for DEM codes that interpolate rather than evaluate the closed forms.

One row per (layer, eps, P_cav, St) of a study table (dimensionless, DSH scales; P_cav empty:
no cavitation limit), with the group's St_c and m (the e_n form 1 - (St_c/St)^m fitted to the
group's points of equal eps and P_cav) and the point's A and B of I = A + B D,
D = (1 + c) ln(1 + c) - c ln c - 1, c = 1/(2 delta) (:func:`ehdfem.dem.forms.far_field`; B = 0
in a thin layer; immersed, A and B solved from the points at two or more delta). The recipe
(:func:`interpolate`):

- St_c and m: bilinear in (ln eps, ln |P_cav|) between the four nearest groups of the layer
  (P_cav none: linear in ln eps on the groups without a limit);
- ln(St A) and ln(St B) (St I = int J dT / 3 varies far more slowly than I): trilinear in
  (ln St, ln eps, ln |P_cav|) (none: bilinear in ln St, ln eps); NaN where a corner has A or B
  <= 0 (immersed at eps 0.1 and St >= 3000, where the half-space model is out of its range);
- e_n = 1 - (St_c/St)^m above St_c, else 0; I = A + B D;
  1 - e_t = k/(1 + k) (1 - exp(-(1 + 1/k) delta I)); spin change = (1 - e_t)/k.

Outside the table's box it refuses like the forms (:func:`ehdfem.dem.box.check_inside`).
"""

from __future__ import annotations

import csv
import io
from collections import defaultdict

import numpy as np
from scipy.interpolate import RegularGridInterpolator

from .. import checks
from . import fitting
from . import forms as shape
from .box import check_inside, no_limit

COLUMNS = ("layer", "eps", "p_cav", "St", "St_c", "m", "A", "B")


def build(rows: list[dict]) -> list[dict]:
    """The table's rows (COLUMNS; p_cav None for no limit) from study rows (those of
    :func:`ehdfem.dem.table.table_rows`, one model, with e_t)."""
    data = fitting.columns(rows)
    integral = shape.sliding_integral_of(data["e_t"], data["delta"], data["k"])
    points = defaultdict(list)
    for i, layer in enumerate(data["layer"]):
        points[(layer, data["eps"][i], data["p_cav"][i], data["St"][i])].append(i)
    groups = defaultdict(list)
    for layer, eps, p_cav, St in points:
        groups[(layer, eps, p_cav)].append(St)
    normal = {key: _group(data, points, key, sorted(St)) for key, St in groups.items()}
    table = []
    for (layer, eps, p_cav, St), members in sorted(points.items(), key=_order):
        A, B = _coefficients(integral[members], data["delta"][members], layer)
        St_c, m = normal[(layer, eps, p_cav)]
        table.append(dict(zip(COLUMNS, (layer, eps, p_cav, St, St_c, m, A, B), strict=True)))
    return table


def _order(item):
    (layer, eps, p_cav, St), _ = item
    return (layer, eps, p_cav is None, 0.0 if p_cav is None else -p_cav, St)


def _group(data, points, key, St) -> tuple:
    """(St_c, m) of one group (NaN with fewer than 3 rebounds)."""
    e_n = np.array([data["e_n"][points[(*key, s)][0]] for s in St])
    if (e_n > 0).sum() < 3:
        return np.nan, np.nan
    return fitting.group_fit(np.array(St), e_n)


def _coefficients(integral, delta, layer) -> tuple:
    """(A, B) of I = A + B D(delta) (thin: I at the smallest delta, B = 0)."""
    if layer == "thin":
        return float(integral[np.argmin(delta)]), 0.0
    logs = shape.far_field(delta)
    if len(np.unique(logs)) < 2:
        raise checks.InputError("the immersed table needs each point at two values of delta")
    (A, B), *_ = np.linalg.lstsq(np.column_stack([np.ones(len(logs)), logs]), integral, None)
    return float(A), float(B)


def csv_text(table: list[dict]) -> str:
    """The table as CSV (P_cav empty: no limit)."""
    out = io.StringIO()
    writer = csv.DictWriter(out, fieldnames=COLUMNS, lineterminator="\n")
    writer.writeheader()
    for row in table:
        writer.writerow({k: "" if row[k] is None else row[k] for k in COLUMNS})
    return out.getvalue()


def read_csv(text: str) -> list[dict]:
    """The rows of :func:`csv_text` (numbers as floats, P_cav None for no limit)."""
    rows = []
    for row in csv.DictReader(io.StringIO(text)):
        values = {k: float(row[k]) if row[k] else None for k in COLUMNS[1:]}
        rows.append({"layer": row["layer"], **values})
    return rows


def _node(row: dict, name: str) -> float:
    """The value the recipe interpolates: St_c and m, ln(St A) and ln(St B) (NaN if <= 0)."""
    if name in ("St_c", "m"):
        return row[name]
    value = row[name] * row["St"]
    return float(np.log(value)) if value > 0 else np.nan


def interpolate(table: list[dict], box: dict, St, eps, delta, p_cav, layer, inertia_factor=0.4):
    """{"St_c", "e_n", "e_t", "spin_change"} by the recipe of the module docstring."""
    check_inside(box, St, eps, delta, p_cav, layer, inertia_factor)
    limited = not no_limit(p_cav)
    rows = [r for r in table if r["layer"] == layer and (r["p_cav"] is not None) == limited]
    axes = [sorted({np.log(r["St"]) for r in rows}), sorted({np.log(r["eps"]) for r in rows})]
    at = [np.log(St), np.log(eps)]
    if limited:
        axes.append(sorted({np.log(-r["p_cav"]) for r in rows}))
        at.append(np.log(-p_cav))
    values = {}
    for name in ("St_c", "m", "A", "B"):
        grid = np.full([len(a) for a in axes], np.nan)
        for r in rows:
            keys = [np.log(r["St"]), np.log(r["eps"])] + ([np.log(-r["p_cav"])] if limited else [])
            grid[tuple(a.index(k) for a, k in zip(axes, keys, strict=True))] = _node(r, name)
        values[name] = float(RegularGridInterpolator(axes, grid)(at)[0])
    values["A"] = np.exp(values["A"]) / St
    values["B"] = 0.0 if layer == "thin" else np.exp(values["B"]) / St
    k = inertia_factor
    integral = values["A"] + values["B"] * shape.far_field(delta)
    e_t = 1.0 - k / (1.0 + k) * -np.expm1(-(1.0 + 1.0 / k) * delta * integral)
    ratio = min(max(values["St_c"] / St, 0.0), 1.0)
    return {
        "St_c": values["St_c"],
        "e_n": 1.0 - ratio ** values["m"],
        "e_t": float(e_t),
        "spin_change": float((1.0 - e_t) / k),
    }
