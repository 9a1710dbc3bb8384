"""Closed-form wet-restitution models (as used in DEM codes) and fits to computed tables.

Every formula takes our Stokes number St = m V0 / (6 pi mu a^2) = rho_p D V0 / (9 mu) (solid
sphere) and converts it to the convention of its source:

- Davis, Rager & Good (2002): e = e_dry (1 - St_c/St) for St > St_c, else 0 (same St).
- Legendre et al. (2006): e / e_dry = exp(-35 / St_L), St_L = (rho_p + C_M rho_f) D V / (9 mu)
  with added mass C_M = 1/2, i.e. St_L = St (1 + rho_f / (2 rho_p)).
- Yade's lubrication law (Maurin 2021 validation): e = max(1e-3, e_dry (1 + ln(2 rough/D) / St_Y))
  with St_Y = rho_p V D / mu = 9 St and rough the roughness height.
- Exponential form with a free critical number (LIGGGHTS-style): e = e_max exp(-St_c / St).

Fits (`fit_table`): the normal restitution per (eps, delta, layer, P_cav, cavitation model,
viscosity law, alpha) group to e_n = e_inf (1 - St_c/St), St_c against eps as a power law
St_c = A eps^B (for each model), with the maximum and rms error over the rebounding points; and,
for tables with e_t, the closed forms for DEM of `fit_closed_forms`: e_n, e_t and the spin
change as functions of (St, eps, delta, P_cav), with their errors and ranges, which
`python_source` writes out as a module a particle code can copy.
"""

from __future__ import annotations

import math
from collections import defaultdict
from itertools import product

import numpy as np
from scipy.optimize import least_squares

from .. import checks
from ..inputs.scales import CollisionParameters

# the labels besides eps and delta that tell the fit groups apart, with their defaults (P_cav
# None: no cavitation limit)
GROUPED = (
    ("layer", "thin"),
    ("p_cav", None),
    ("cavitation", "truncate"),
    ("viscosity", "constant"),
    ("alpha", 0.0),
)
REQUIRED_COLUMNS = ("status", "St", "eps", "e_n")  # the others have their defaults
NUMBERS = ("St", "eps", "delta", "e_n", "e_t", "spin_change", "alpha", "p_cav")  # None if empty
DEFAULTS = {"delta": CollisionParameters.__dataclass_fields__["delta"].default, **dict(GROUPED)}
EMPTY = ("", "None", "none", "-inf", None)  # an empty cell; for P_cav, no limit


def davis_rager_good(St, St_c, e_dry=1.0):
    """e = e_dry (1 - St_c/St) above St_c, 0 below."""
    St = np.asarray(St, dtype=float)
    return np.where(St > St_c, e_dry * (1.0 - St_c / St), 0.0)


def legendre(St, e_dry=1.0, density_ratio=0.0):
    """e = e_dry exp(-35 / St_L), St_L = St (1 + density_ratio / 2), density_ratio = rho_f/rho_p."""
    checks.number("density_ratio", density_ratio, lower=0.0)
    return e_dry * np.exp(-35.0 / (np.asarray(St, dtype=float) * (1.0 + 0.5 * density_ratio)))


def yade(St, roughness_ratio, e_dry=1.0):
    """e = max(1e-3, e_dry (1 + ln(2 roughness_ratio) / (9 St))), roughness_ratio = rough / D."""
    checks.number("roughness_ratio", roughness_ratio, lower=0.0, upper=0.5, lower_open=True)
    return np.maximum(
        1e-3, e_dry * (1.0 + math.log(2 * roughness_ratio) / (9.0 * np.asarray(St, dtype=float)))
    )


def exponential(St, St_c, e_max=1.0):
    """e = e_max exp(-St_c / St)."""
    return e_max * np.exp(-St_c / np.asarray(St, dtype=float))


def fit_normal(St, e_n):
    """Least-squares (e_inf, St_c) of e_n = e_inf (1 - St_c/St) on rebounding points (e_n > 0)."""
    St, e_n = np.asarray(St, dtype=float), np.asarray(e_n, dtype=float)
    keep = e_n > 0
    if keep.sum() < 2:
        raise checks.InputError("fit_normal needs at least two rebounding points")
    # linear in (e_inf, e_inf St_c): e_n = e_inf - (e_inf St_c) / St
    design = np.column_stack([np.ones(keep.sum()), -1.0 / St[keep]])
    (e_inf, product), *_ = np.linalg.lstsq(design, e_n[keep], rcond=None)
    return float(e_inf), float(product / e_inf)


def fit_power_law(features: dict, target) -> dict:
    """target = exp(c0) * prod x_k^c_k, fitted in logs: {"coefficient": exp(c0), name: c_k}."""
    names = list(features)
    design = np.column_stack([np.ones(len(target))] + [np.log(features[k]) for k in names])
    coef, *_ = np.linalg.lstsq(design, np.log(target), rcond=None)
    return {
        "coefficient": float(np.exp(coef[0])),
        **{k: float(c) for k, c in zip(names, coef[1:], strict=True)},
    }


def power_law(fit: dict, **features):
    """Evaluate a fit_power_law result."""
    value = fit["coefficient"]
    for name, x in features.items():
        value = value * np.asarray(x, dtype=float) ** fit[name]
    return value


def _errors(predicted, actual) -> dict:
    diff = np.asarray(predicted) - np.asarray(actual)
    return {"max_error": float(np.abs(diff).max()), "rms_error": float(np.sqrt(np.mean(diff**2)))}


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


def _group_order(item) -> tuple:
    """Sort key of a fit group: its labels, a missing value (None) first."""
    return tuple((value is not None, "" if value is None else value) for value in item[0])


def fit_table(rows: list[dict]) -> dict:
    """Closed-form fits to a study table (rows as read from the CSV, values as strings or
    numbers; :func:`table_rows`). Returns the fitted coefficients and their max / rms errors
    over the data, and the errors of the DEM formulas against the computed e_n; a fit that the
    table cannot give is left out, and its "..._skipped" entry says why."""
    ok = table_rows(rows)
    groups = defaultdict(list)
    for r in ok:
        groups[(r["eps"], r["delta"], *(r[k] for k, _ in GROUPED))].append(r)
    normal = []
    for (eps, delta, *labels), members in sorted(groups.items(), key=_group_order):
        St = np.array([r["St"] for r in members])
        e_n = np.array([r["e_n"] for r in members])
        if (e_n > 0).sum() < 2:
            continue
        e_inf, St_c = fit_normal(St, e_n)
        rebound = e_n > 0
        normal.append(
            {
                "eps": eps,
                "delta": delta,
                **dict(zip((k for k, _ in GROUPED), labels, strict=True)),
                "e_inf": e_inf,
                "St_c": St_c,
                **_errors(davis_rager_good(St[rebound], St_c, e_inf), e_n[rebound]),
            }
        )
    out = {"normal": normal}
    if not normal:
        out["normal_skipped"] = _too_few(
            "e_n = e_inf (1 - St_c/St)", groups.values(), 2, "eps, delta and model"
        )
    models = defaultdict(list)  # St_c against eps, for each model (delta and labels)
    for g in normal:
        models[(g["delta"], *(g[k] for k, _ in GROUPED))].append(g)
    laws = []
    for (delta, *labels), members in models.items():
        eps = np.array([g["eps"] for g in members])
        if len(set(eps)) < 2:
            continue
        St_c = np.array([g["St_c"] for g in members])
        law = fit_power_law({"eps": eps}, St_c)
        model = {"delta": delta, **dict(zip((k for k, _ in GROUPED), labels, strict=True))}
        laws.append({**law, **_errors(power_law(law, eps=eps), St_c), "model": model})
    out["critical_stokes_laws"] = laws
    if len(laws) == 1:  # a table of one model (the usual case)
        out["critical_stokes_law"] = laws[0]
    out.update(_closed_forms_of(ok))
    St_all = np.array([r["St"] for r in ok])
    e_all = np.array([r["e_n"] for r in ok])
    out["dem_formulas"] = {
        "legendre_2006": _errors(legendre(St_all), e_all),
        "exponential_fitted": _exponential_errors(St_all, e_all),
    }
    return out


# the labels of one model, besides the closed forms' inputs (delta and P_cav are inputs)
MODEL_LABELS = (*((k, d) for k, d in GROUPED if k != "p_cav"), ("tangential", "couette"))


def _closed_forms_of(rows: list[dict]) -> dict:
    """{"closed_forms": ...} fitted to the rows with e_t (:func:`fit_closed_forms`), or
    {"closed_forms_skipped": why} when the table has none, mixes models or cannot give them."""
    oblique = [r for r in rows if r.get("e_t") is not None]
    if not oblique:
        return {"closed_forms_skipped": "no closed forms: the table has no e_t (no angle)"}
    labels = {k: {r.get(k) or d for r in oblique} for k, d in MODEL_LABELS}
    mixed = [k for k, values in labels.items() if len(values) > 1]
    if mixed:
        return {
            "closed_forms_skipped": f"no closed forms: the table mixes {', '.join(mixed)} (fit "
            "one model at a time)"
        }
    try:
        forms = fit_closed_forms(oblique)
    except checks.InputError as err:
        return {"closed_forms_skipped": f"no closed forms: {err}"}
    return {"closed_forms": {**forms, "model": {k: v.pop() for k, v in labels.items()}}}


def _too_few(what: str, groups, needed: int, alike: str) -> str:
    """Why ``what`` cannot be fitted: no group of points of equal ``alike`` has ``needed``
    rebounds (e_n > 0)."""
    groups = list(groups)
    best = max(sum(r["e_n"] > 0 for r in members) for members in groups)
    points = sum(len(members) for members in groups)
    text = (
        f"{what} needs a group of points of equal {alike} with {needed} "
        f"rebounding points (e_n > 0); the table's {points} points make {len(groups)} "
        f"group(s), the most rebounding points in one is {best}"
    )
    if len(groups) > points / 2:
        text += (
            " (eps changes at nearly every point, as in a physical study, where it changes "
            "with the speed: fit a dimensionless study over St at fixed eps)"
        )
    return text


def describe_ranges(ranges: dict) -> str:
    """ "St in [lo, hi], ..." for a form's ranges."""
    return ", ".join(f"{k} in [{lo:.3g}, {hi:.3g}]" for k, (lo, hi) in ranges.items())


def _exponential_errors(St, e_n) -> dict:
    """Fit e_max exp(-St_c/St) to all points and report its errors."""
    result = least_squares(lambda p: exponential(St, p[0], p[1]) - e_n, x0=[10.0, 1.0])
    St_c, e_max = result.x
    return {
        "St_c": float(St_c),
        "e_max": float(e_max),
        **_errors(exponential(St, St_c, e_max), e_n),
    }


# --- Closed forms for DEM -------------------------------------------------------------------
# Every group q(St, eps, P_cav) below is exp of a full polynomial in the logarithms of the
# inputs that vary in the fitted table (ln St, ln eps, ln |P_cav|), cubic (NORMAL_DEGREE,
# DEGREE): for St_c and the exponent m of e_n, and for the tangential loss and the spin
# change, whose higher terms carry the curvature in log St that a single power law misses.


def _logs(values: dict, names) -> np.ndarray:
    """Columns ln|x| of ``values[name]`` for ``names``."""
    columns = np.broadcast_arrays(*(np.asarray(values[n], dtype=float) for n in names))
    return np.column_stack([np.log(np.abs(np.ravel(c))) for c in columns])


def _powers(logs: np.ndarray, degree: int) -> list[tuple]:
    """The monomials of total degree <= ``degree`` in the columns of ``logs`` as exponent
    tuples, each column's power below its number of distinct values (a column of three values
    gets at most its square: higher powers would not be determined)."""
    distinct = [len(np.unique(column)) for column in logs.T]
    return [
        powers
        for powers in product(*(range(min(degree, n - 1) + 1) for n in distinct))
        if sum(powers) <= degree
    ]


def _design(logs: np.ndarray, powers) -> np.ndarray:
    """Columns prod_i x_i^p_i for every exponent tuple p of ``powers``."""
    return np.column_stack([np.prod(logs ** np.array(p), axis=1) for p in powers])


def log_polynomial(form: dict, **inputs):
    """exp(polynomial in the logs) of a fitted ``form`` ({"inputs": names, "powers": exponent
    tuples, "coefficients"}) at ``inputs`` (arrays or numbers, by name; dimensionless, on the
    scales of the table it was fitted to, e.g. St, eps and P_cav on DSH scales)."""
    logs = _logs(inputs, form["inputs"]) if form["inputs"] else np.zeros((1, 0))
    return np.exp(_design(logs, form["powers"]) @ np.asarray(form["coefficients"]))


def _fit_log_polynomial(inputs: dict, target, degree: int) -> dict:
    """Least squares of ln target on a polynomial of ``degree`` in the logs of ``inputs``."""
    names = tuple(inputs)
    logs = _logs(inputs, names)
    powers = _powers(logs, degree)
    coefficients, *_ = np.linalg.lstsq(_design(logs, powers), np.log(target), rcond=None)
    return {"inputs": names, "powers": powers, "coefficients": coefficients.tolist()}


def normal_closed_form(forms: dict, St, eps, p_cav):
    """e_n = 1 - (St_c/St)^m above St_c, else 0 (pure EHD, which tends to 1 at large St;
    multiply by e_dry), with St_c and m each exp(cubic in ln eps, ln |P_cav|). St, eps and
    P_cav are dimensionless (DSH scales, :mod:`ehdfem.inputs.scales`)."""
    inputs = {"eps": eps, "p_cav": p_cav}
    St_c, m = (log_polynomial(forms[k], **inputs) for k in NORMAL_FORMS)
    return 1.0 - np.clip(St_c / np.asarray(St, dtype=float), 0.0, 1.0) ** m


def _varying(rows, names) -> tuple:
    """Those of ``names`` that take more than one value in ``rows`` (the others are held fixed
    by the table and left out of the forms)."""
    return tuple(n for n in names if len({r[n] for r in rows}) > 1)


def fit_closed_forms(rows: list[dict]) -> dict:
    """Closed forms for DEM fitted to the successful rows of a table with e_n, e_t and the spin
    change (dimensionless; spin change a DeltaOmega/U0):

    - e_n = 1 - (St_c/St)^m, 0 below St_c (:func:`normal_closed_form`): first per
      (eps, P_cav) group, then St_c and m as exp(cubic in ln eps, ln |P_cav|), then all
      coefficients together on every point (sticking ones included, where the form must
      give 0);
    - 1 - e_t = delta exp(Q) and spin change = delta exp(Q), Q cubic in ln St, ln eps,
      ln |P_cav| (least squares in the logs), over the clear rebounds, e_n >= CLEAR_REBOUND.
      Just above St_c the contact lasts much longer and 1 - e_t rises steeply; those rebounds
      are outside the forms' range, and their largest error is reported apart.

    Inputs held fixed by the table are left out. Each form carries its maximum and rms error
    (absolute, in e_n, e_t, spin change); the result also has the number of points and the
    ranges it was fitted over."""
    rows = table_rows(rows)
    for name in ("p_cav", "e_t", "spin_change"):
        empty = sum(r[name] is None for r in rows)
        if empty:
            raise checks.InputError(
                f"they need {name} at every point ({name} = none at {empty} of {len(rows)}; "
                "ln |P_cav| is one of their inputs)"
            )
    varying = _varying(rows, ("eps", "p_cav"))
    columns = {k: np.array([r[k] for r in rows]) for k in ("St", "eps", "p_cav", "delta")}
    e_n = np.array([r["e_n"] for r in rows])
    ranges = {k: [float(v.min()), float(v.max())] for k, v in columns.items()}
    normal = _fit_normal_form(columns, e_n, varying)
    out = {"points": len(rows), "ranges": ranges, "normal": normal}
    clear, near = e_n >= CLEAR_REBOUND, (e_n > 0) & (e_n < CLEAR_REBOUND)
    for name, target in (
        ("tangential_loss", 1 - np.array([r["e_t"] for r in rows])),
        ("spin_change", np.array([r["spin_change"] for r in rows])),
    ):
        inputs = {k: columns[k][clear] for k in ("St", *varying)}
        form = _fit_log_polynomial(inputs, target[clear] / columns["delta"][clear], DEGREE)
        predicted = columns["delta"] * log_polynomial(form, **{k: columns[k] for k in inputs})
        relative = np.abs(predicted / np.where(e_n > 0, target, 1.0) - 1)
        out[name] = {
            **form,
            "form": f"{name} = delta exp(Q(ln St, ln eps, ln |P_cav|)), Q cubic, for e_n >= "
            f"{CLEAR_REBOUND}",
            **_errors(predicted[clear], target[clear]),
            "max_relative_error": float(relative[clear].max()),
            "near_threshold_max_relative_error": float(relative[near].max(initial=0.0)),
        }
    return out


NORMAL_FORMS = ("St_c", "m")
NORMAL_DEGREE = DEGREE = 3  # of the polynomials in the logs: St_c and m; 1 - e_t and spin
CLEAR_REBOUND = 0.3
"""The smallest e_n of the rebounds the tangential closed forms are fitted to and valid for."""


def _constant_forms(logs) -> dict:
    """The e_n forms with no inputs: St_c and m = exp(``logs``)."""
    return {
        n: {"inputs": (), "powers": [()], "coefficients": [c]}
        for n, c in zip(NORMAL_FORMS, logs, strict=True)
    }


def _fit_normal_form(columns: dict, e_n, varying: tuple) -> dict:
    """The e_n closed form (see :func:`fit_closed_forms`)."""
    keys = [tuple(columns[k][i] for k in varying) for i in range(len(e_n))]
    groups = defaultdict(list)
    for i, key in enumerate(keys):
        groups[key].append(i)
    per_group = {}
    for key, members in groups.items():
        St, target = columns["St"][members], e_n[members]
        if (target > 0).sum() < 3:
            continue
        start = [np.log(0.95 * St[target > 0].min()), 0.0]
        result = least_squares(
            lambda p, St=St, target=target: (
                normal_closed_form(_constant_forms(p), St, 1.0, 1.0) - target
            ),
            start,
            bounds=([-10, -3], [10, 3]),
            xtol=1e-15,
            ftol=1e-15,
        )
        per_group[key] = result.x
    if len(per_group) < 1:
        members = [[{"e_n": e_n[i]} for i in group] for group in groups.values()]
        raise checks.InputError(_too_few("the closed form of e_n", members, 3, "eps and P_cav"))
    group_inputs = {k: np.array([key[i] for key in per_group]) for i, k in enumerate(varying)}
    forms = {
        name: _fit_log_polynomial(
            group_inputs, np.exp([p[j] for p in per_group.values()]), NORMAL_DEGREE
        )
        for j, name in enumerate(NORMAL_FORMS)
    }
    sizes = [len(f["coefficients"]) for f in forms.values()]
    at = {k: columns[k] for k in ("St", "eps", "p_cav")}

    def residual(flat):
        split = np.split(flat, np.cumsum(sizes)[:-1])
        trial = {
            n: {**forms[n], "coefficients": c} for n, c in zip(NORMAL_FORMS, split, strict=True)
        }
        return normal_closed_form(trial, **at) - e_n

    flat = np.concatenate([f["coefficients"] for f in forms.values()])
    flat = least_squares(residual, flat, xtol=1e-15, ftol=1e-15, gtol=1e-15).x
    for form, coefficients in zip(
        forms.values(), np.split(flat, np.cumsum(sizes)[:-1]), strict=True
    ):
        form["coefficients"] = coefficients.tolist()
    predicted = residual(flat) + e_n
    return {
        **forms,
        "form": "e_n = 1 - (St_c/St)^m above St_c, else 0; St_c and m = exp(Q(ln eps, "
        "ln |P_cav|)), Q cubic",
        **_errors(predicted, e_n),
        "clear_rebound_max_error": float(np.abs(predicted - e_n)[e_n >= CLEAR_REBOUND].max()),
    }


_MODULE = '''"""Closed forms for wet collisions of a sphere on a wall through a thin liquid
layer, fitted by ehdfem {version} (`ehdfem fit`) to {table}: {points} collisions of the
{model} model.

All inputs and outputs are dimensionless (Davis, Serayssol & Hinch scales): St = m V0/(6 pi mu
a^2), eps = 4 theta mu V0 a^(3/2)/x0^(5/2), delta = x0/a, P_cav = (p_cav - p_ambient) x0^2/(mu
V0 a) < 0, with V0 the normal impact speed and x0 the layer thickness (dimensionless_groups
computes them from SI inputs). e_n is the pure EHD value: multiply by the dry restitution.
The spin change is a DeltaOmega/U0 (U0 the tangential impact speed).

Fitted over {ranges}.
Errors against the table: e_n max {normal_max:.2g} (rms {normal_rms:.2g}) over every point,
max {normal_clear:.2g} where e_n >= {clear}.
For rebounds with e_n >= {clear} (the range of e_t and the spin change): e_t max {loss_max:.2g}
(relative to 1 - e_t {loss_rel:.2g}), spin change max {spin_max:.2g} (relative {spin_rel:.2g}).
Just above St_c (0 < e_n < {clear}) 1 - e_t and the spin change are off by up to
{near_rel:.0%}. Outside these ranges the forms are extrapolations.
"""

import math

FORMS = {forms!r}


def _fitted(name, **inputs):
    """exp of the polynomial in the logarithms of the form's inputs (|x| for P_cav)."""
    form = FORMS[name]
    logs = [math.log(abs(inputs[key])) for key in form["inputs"]]
    terms = [math.prod(x**p for x, p in zip(logs, powers)) for powers in form["powers"]]
    return math.exp(sum(c * t for c, t in zip(form["coefficients"], terms)))


def critical_stokes(eps, p_cav):
    """St_c: no rebound below it."""
    return _fitted("St_c", eps=eps, p_cav=p_cav)


def normal_restitution(St, eps, p_cav):
    """e_n = 1 - (St_c/St)^m above St_c, else 0 (pure EHD)."""
    St_c = critical_stokes(eps, p_cav)
    if St <= St_c:
        return 0.0
    return 1.0 - (St_c / St) ** _fitted("m", eps=eps, p_cav=p_cav)


def tangential_restitution(St, eps, delta, p_cav):
    """e_t = 1 - delta exp(Q(ln St, ln eps, ln |P_cav|)), Q cubic, for a rebounding sphere."""
    return 1.0 - delta * _fitted("tangential_loss", St=St, eps=eps, p_cav=p_cav)


def spin_change(St, eps, delta, p_cav):
    """a DeltaOmega/U0 = delta exp(Q(ln St, ln eps, ln |P_cav|)), Q cubic, for a rebound."""
    return delta * _fitted("spin_change", St=St, eps=eps, p_cav=p_cav)


def dimensionless_groups(
    radius, density, normal_speed, viscosity, theta, layer_thickness, cavitation_pressure,
    ambient_pressure=101325.0,
):
    """(St, eps, delta, P_cav) of a solid sphere (SI inputs: m, kg/m^3, m/s, Pa s; theta =
    sum (1 - nu^2)/(pi E) of sphere and wall in 1/Pa; pressures absolute in Pa)."""
    mass = 4.0 / 3.0 * math.pi * radius**3 * density
    St = mass * normal_speed / (6.0 * math.pi * viscosity * radius**2)
    eps = 4.0 * theta * viscosity * normal_speed * radius**1.5 / layer_thickness**2.5
    scale = viscosity * normal_speed * radius / layer_thickness**2
    return St, eps, layer_thickness / radius, (cavitation_pressure - ambient_pressure) / scale
'''


def python_source(fits: dict, table: str, version: str) -> str:
    """A Python module (text) with the closed forms ``fits`` of :func:`fit_table` (its
    "closed_forms", fitted to the table named ``table``): the functions critical_stokes,
    normal_restitution, tangential_restitution, spin_change and dimensionless_groups, standard
    library only, for a particle code to copy."""
    normal, loss, spin = fits["normal"], fits["tangential_loss"], fits["spin_change"]
    forms = {n: _plain(normal[n]) for n in NORMAL_FORMS}
    forms.update(tangential_loss=_plain(loss), spin_change=_plain(spin))
    ranges = describe_ranges(fits["ranges"])
    return _MODULE.format(
        version=version,
        table=table,
        points=fits["points"],
        model=", ".join(f"{k} {v}" for k, v in fits["model"].items()),
        ranges=ranges,
        forms=forms,
        normal_max=normal["max_error"],
        normal_rms=normal["rms_error"],
        normal_clear=normal["clear_rebound_max_error"],
        loss_max=loss["max_error"],
        loss_rel=loss["max_relative_error"],
        spin_max=spin["max_error"],
        spin_rel=spin["max_relative_error"],
        clear=CLEAR_REBOUND,
        near_rel=max(f["near_threshold_max_relative_error"] for f in (loss, spin)),
    )


def _plain(form: dict) -> dict:
    """A form's inputs and coefficients as plain lists (for the written module)."""
    return {
        "inputs": list(form["inputs"]),
        "powers": [list(p) for p in form["powers"]],
        "coefficients": [float(c) for c in form["coefficients"]],
    }
