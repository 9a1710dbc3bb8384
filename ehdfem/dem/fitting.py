"""The closed forms for DEM (:mod:`ehdfem.dem.forms`) fitted to a study table, and their errors.

Rows are those of :func:`ehdfem.dem.table.table_rows` (dimensionless, DSH scales) of one model:
half-spaces, the Couette tangential model, one inertia factor. For each layer in the table:

- e_n: (St_c, m) per (eps, P_cav) group with 3 rebounds (least squares of e_n = 1 - (St_c/St)^m
  on the group's points, sticking ones included), then Q_c and Q_m by linear least squares on
  the groups, then every coefficient together on every point;
- e_t: I = int J dT/(3 St) from each rebound with e_n >= CLEAR_REBOUND (exact inverse of the
  Couette form) inside the box's reach (:func:`ehdfem.dem.box.wetted_reach`: a thin layer's
  wetted film, an immersed layer's contact inside r = a); Q_R, Q_E (and Q_T immersed, which
  needs rebounds at two delta) together by least squares on ln I, with the fitted e_n in the
  rigid passes.

Errors (:func:`errors`) are absolute in e_n, e_t and the spin change, relative in 1 - e_t and
St_c; the stated ones are measured on a table held back from the fit.
"""

from __future__ import annotations

from collections import defaultdict

import numpy as np
from scipy.optimize import least_squares

from .. import checks
from . import forms as shape
from .box import LAYERS, check_inside, wetted_reach

CLEAR_REBOUND = 0.3
"""The smallest e_n of the rebounds the tangential forms are fitted to: just above St_c the
contact lasts much longer and 1 - e_t rises steeply (its error there is reported apart)."""


def columns(rows: list[dict]) -> dict:
    """The rows' St, eps, delta, e_n, e_t, inertia factor (arrays) and p_cav (a list, None for
    no limit) and layer (a list)."""
    out = {k: np.array([r[k] for r in rows], dtype=float) for k in ("St", "eps", "delta", "e_n")}
    out["e_t"] = np.array([np.nan if r["e_t"] is None else r["e_t"] for r in rows])
    out["k"] = np.array([float(r.get("inertia_factor") or 0.4) for r in rows])
    out["p_cav"] = [r["p_cav"] for r in rows]
    out["layer"] = [r["layer"] for r in rows]
    return out


def feature_values(data: dict, select) -> dict:
    """The features of :func:`ehdfem.dem.forms.features` at the selected rows (per row, as
    P_cav may be none at some)."""
    index = np.flatnonzero(select)
    values = [shape.features(data["St"][i], data["eps"][i], data["p_cav"][i]) for i in index]
    return {n: np.array([float(v[n]) for v in values]) for n in ("x", "L", "v", "w", "h")}


def fit_forms(rows: list[dict]) -> dict:
    """{"box", "points", "inertia_factor", layer: {name: form}} for each layer of the rows."""
    data = columns(rows)
    k = set(data["k"].tolist())
    if len(k) > 1:
        raise checks.InputError(f"the table mixes inertia factors {sorted(k)}: fit one at a time")
    if np.isnan(data["e_t"]).any():
        raise checks.InputError("they need e_t at every point (an oblique impact: angle > 0)")
    out = {"box": _box(data), "points": len(rows), "inertia_factor": k.pop()}
    for layer in LAYERS:
        select = np.array([value == layer for value in data["layer"]])
        if select.any():
            normal = _fit_normal(data, select)
            out[layer] = {**normal, **_fit_tangential(data, select, layer, normal)}
    return out


def _box(data: dict) -> dict:
    """The ranges of the table: the box the forms hold in (P_cav [0, 0] when the table has no
    finite P_cav, so that every finite limit is refused)."""
    limits = [p for p in data["p_cav"] if p is not None]
    ranges = {k: [float(data[k].min()), float(data[k].max())] for k in ("St", "eps", "delta")}
    return {
        **ranges,
        "p_cav": [min(limits), max(limits)] if limits else [0.0, 0.0],
        "no_limit": any(p is None for p in data["p_cav"]),
    }


def _least_squares(form_names, forms, residual_of):
    """Refine the coefficients of ``forms[name]`` for ``form_names`` together on
    ``residual_of(trial forms)``."""
    sizes = [len(forms[n]["coefficients"]) for n in form_names]
    split = np.cumsum(sizes)[:-1]

    def trial(flat):
        parts = np.split(flat, split)
        return {**forms, **{n: {**forms[n], "coefficients": list(c)} for n, c in zip(
            form_names, parts, strict=True)}}  # fmt: skip

    start = np.concatenate([forms[n]["coefficients"] for n in form_names])
    flat = least_squares(lambda c: residual_of(trial(c)), start, xtol=1e-14, ftol=1e-14).x
    return {n: {**forms[n], "coefficients": [float(c) for c in cs]} for n, cs in zip(
        form_names, np.split(flat, split), strict=True)}  # fmt: skip


def _linear_form(name: str, values: dict, target, select=None) -> dict:
    """The form ``name`` over its features fitted to ``target`` by linear least squares."""
    names = shape.FEATURES[name]
    select = np.ones(len(target), dtype=bool) if select is None else select
    distinct = {n: len(np.unique(np.round(values[n][select], 12))) for n in names}
    form = {"features": list(names), "powers": shape.powers(names, shape.DEGREE[name], distinct)}
    picked = {n: values[n][select] for n in names}
    coefficients, *_ = np.linalg.lstsq(shape.design(form, picked), target[select], rcond=None)
    return {**form, "coefficients": [float(c) for c in coefficients]}


def group_fit(St, e_n) -> tuple:
    """(St_c, m) of e_n = 1 - (St_c/St)^m on one (eps, P_cav) group."""
    start = [np.log(0.95 * St[e_n > 0].min()), 0.0]
    result = least_squares(
        lambda p: 1.0 - np.clip(np.exp(p[0]) / St, 0.0, 1.0) ** np.exp(p[1]) - e_n,
        start,
        bounds=([-5.0, -3.0], [10.0, 3.0]),
    )
    return float(np.exp(result.x[0])), float(np.exp(result.x[1]))


def _fit_normal(data: dict, select) -> dict:
    """Q_c and Q_m of one layer (the module docstring)."""
    groups = defaultdict(list)
    for i in np.flatnonzero(select):
        groups[(data["eps"][i], data["p_cav"][i])].append(i)
    fitted = {
        key: group_fit(data["St"][members], data["e_n"][members])
        for key, members in groups.items()
        if (data["e_n"][members] > 0).sum() >= 3
    }
    if not fitted:
        raise checks.InputError(
            "the closed form of e_n needs a group of equal eps and P_cav with 3 rebounding "
            f"points (e_n > 0); the table's {len(groups)} groups have at most "
            f"{max((data['e_n'][m] > 0).sum() for m in groups.values())}"
        )
    at = {"eps": np.array([e for e, _ in fitted]), "p_cav": [p for _, p in fitted]}
    values = feature_values({**at, "St": np.ones(len(fitted))}, np.ones(len(fitted), bool))
    St_c, m = (np.array([g[j] for g in fitted.values()]) for j in (0, 1))
    rigid = (shape.CRITICAL_SLOPE + values["h"]) * values["L"]
    forms = {
        "St_c": _linear_form("St_c", values, St_c - rigid),
        "m": _linear_form("m", values, np.log(m)),
    }
    layer = data["layer"][np.flatnonzero(select)[0]]
    every = np.flatnonzero(select)

    def residual(trial):
        return np.array(
            [
                shape.normal_restitution({layer: trial}, data["St"][i], data["eps"][i],
                                         data["p_cav"][i], layer)[0] - data["e_n"][i]
                for i in every
            ]
        )  # fmt: skip

    return _least_squares(shape.NORMAL, forms, residual)


def _fit_tangential(data: dict, select, layer: str, normal: dict) -> dict:
    """Q_R, Q_E (and Q_T immersed) of one layer (:mod:`ehdfem.dem.forms`), by least squares
    on ln of 3 St I at the rebounds with e_n >= CLEAR_REBOUND inside the box's reach (the
    film or the contact inside r = a) where the ``normal`` forms rebound too, from R = T = 1,
    E = 5."""
    reach = np.array([wetted_reach(*(data[n][i] for n in ("St", "eps", "delta")),
                                   data["layer"][i]) for i in range(len(data["St"]))])  # fmt: skip
    clear = select & (data["e_n"] >= CLEAR_REBOUND) & (reach <= 1.0)
    e_n = np.array([_value({layer: normal}, data, i, "e_n") if clear[i] else 0.0
                    for i in range(len(clear))])  # fmt: skip
    clear &= e_n > 0.0
    if not clear.any():
        raise checks.InputError(f"the tangential forms need rebounds with e_n >= {CLEAR_REBOUND}")
    if layer == "immersed" and len(np.unique(data["delta"][clear])) < 2:
        raise checks.InputError(
            "the immersed tangential forms need rebounds at two values of delta (to tell the "
            "far field's share D(delta) from the near field's)"
        )
    integral = shape.sliding_integral_of(data["e_t"], data["delta"], data["k"])[clear]
    values = feature_values(data, clear)
    names = shape.TANGENTIAL[layer]
    forms = {**normal}
    for name in names:
        form = {"features": list(shape.FEATURES[name]),
                "powers": shape.powers(shape.FEATURES[name], shape.DEGREE[name])}  # fmt: skip
        start = np.zeros(len(form["powers"]))
        start[0] = np.log(START[name])
        forms[name] = {**form, "coefficients": list(start)}
    at = [data[n][clear] for n in ("St", "eps", "delta")]

    def residual(trial):
        return np.log(shape.integral_of(trial, layer, values, e_n[clear], *at) / integral)

    fitted = _least_squares(names, forms, residual)
    return {name: fitted[name] for name in names}


START = {"R": 1.0, "E": 5.0, "T": 1.0}  # the tangential factors' starting values


def errors(forms: dict, rows: list[dict]) -> dict:
    """Per layer, the largest errors of the forms on ``rows``: e_n (absolute, every point),
    e_t and the spin change (absolute) and 1 - e_t (relative) over the rebounds with e_n >=
    CLEAR_REBOUND, and 1 - e_t (relative) over the rebounds below it, St_c (relative) against
    that of each (eps, P_cav) group with 3 rebounds (:func:`group_fit`; 0 without one); with
    the numbers of points. A row outside the forms' box is refused (InputError naming the input
    and the line)."""
    data = columns(rows)
    for line, i in enumerate(range(len(rows)), 2):
        try:
            check_inside(forms["box"], data["St"][i], data["eps"][i], data["delta"][i],
                         data["p_cav"][i], data["layer"][i], data["k"][i])  # fmt: skip
        except checks.InputError as err:
            raise checks.InputError(f"point {line - 1}: {err}", err.name) from None
    out = {}
    for layer in LAYERS:
        select = np.flatnonzero([value == layer for value in data["layer"]])
        if not len(select) or layer not in forms:
            continue
        e_n, e_t = (np.array([_value(forms, data, i, name) for i in select]) for name in (
            "e_n", "e_t"))  # fmt: skip
        k = data["k"][select]
        found_n, found_t = data["e_n"][select], data["e_t"][select]
        clear, near = found_n >= CLEAR_REBOUND, (found_n > 0) & (found_n < CLEAR_REBOUND)
        relative = np.abs((1 - e_t) / (1 - found_t) - 1)
        out[layer] = {
            "points": len(select),
            "rebounds": int(clear.sum()),
            "e_n": float(np.abs(e_n - found_n).max()),
            "e_t": float(np.abs(e_t - found_t)[clear].max(initial=0.0)),
            "spin_change": float((np.abs(e_t - found_t) / k)[clear].max(initial=0.0)),
            "tangential_loss_relative": float(relative[clear].max(initial=0.0)),
            "near_threshold_relative": float(relative[near].max(initial=0.0)),
            "St_c_relative": _critical_error(forms, data, select, layer),
        }
    return out


def _critical_error(forms: dict, data: dict, select, layer: str) -> float:
    """The largest relative error of the forms' St_c against :func:`group_fit`'s on the
    (eps, P_cav) groups of ``select`` with 3 rebounds (0 without such a group)."""
    groups = defaultdict(list)
    for i in select:
        groups[(data["eps"][i], data["p_cav"][i])].append(i)
    worst = 0.0
    for (eps, p_cav), members in groups.items():
        if (data["e_n"][members] > 0).sum() >= 3:
            found = group_fit(data["St"][members], data["e_n"][members])[0]
            form = shape.critical_stokes(forms, eps, p_cav, layer)[0]
            worst = max(worst, abs(form / found - 1.0))
    return float(worst)


def _value(forms: dict, data: dict, i: int, name: str) -> float:
    """e_n or e_t of the forms at row ``i`` (no check of the box)."""
    St, eps, p_cav, layer = data["St"][i], data["eps"][i], data["p_cav"][i], data["layer"][i]
    if name == "e_n":
        return float(shape.normal_restitution(forms, St, eps, p_cav, layer)[0])
    return float(
        shape.tangential_restitution(forms, St, eps, data["delta"][i], p_cav, layer, data["k"][i])[
            0
        ]
    )
