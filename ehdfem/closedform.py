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
viscosity law, alpha) group to
e_n = e_inf (1 - St_c/St), St_c against eps as a power law St_c = A eps^B (for each model), and
the tangential
loss 1 - e_t = delta A St^B eps^C (and likewise the spin change), with the maximum and rms error
over the rebounding points.
"""

from __future__ import annotations

import math
from collections import defaultdict

import numpy as np
from scipy.optimize import least_squares

from . import checks

# the labels besides eps and delta that tell the fit groups apart, with their defaults
GROUPED = (
    ("layer", "thin"),
    ("p_cav", ""),
    ("cavitation", "truncate"),
    ("viscosity", "constant"),
    ("alpha", 0.0),
)


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


def fit_table(rows: list[dict]) -> dict:
    """Closed-form fits to a study table (rows as read from the CSV, values as strings or
    numbers). Returns the fitted coefficients and their max / rms errors over the data, and the
    errors of the DEM formulas against the computed e_n."""
    ok = [r for r in rows if str(r["status"]).startswith("ok")]
    if not ok:
        raise checks.InputError("the table has no successful points to fit")
    num = lambda r, k: float(r[k])  # noqa: E731
    groups = defaultdict(list)
    for r in ok:
        key = (num(r, "eps"), num(r, "delta"), *(str(r.get(k, d)) for k, d in GROUPED))
        groups[key].append(r)
    normal = []
    for (eps, delta, *labels), members in sorted(groups.items()):
        St = np.array([num(r, "St") for r in members])
        e_n = np.array([num(r, "e_n") for r in members])
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
    rebound = [r for r in ok if r.get("e_t") not in (None, "", "None") and num(r, "e_n") > 0]
    if len(rebound) >= 4:
        features = {k: np.array([num(r, k) for r in rebound]) for k in ("St", "eps")}
        delta = np.array([num(r, "delta") for r in rebound])
        for name, target in (
            ("tangential_loss", [1 - num(r, "e_t") for r in rebound]),
            ("spin_change", [num(r, "spin_change") for r in rebound]),
        ):
            target = np.array(target)
            law = fit_power_law(features, target / delta)
            out[name] = {
                "form": f"{name} = delta * coefficient * St^St * eps^eps",
                **law,
                **_errors(delta * power_law(law, **features), target),
            }
    St_all = np.array([num(r, "St") for r in ok])
    e_all = np.array([num(r, "e_n") for r in ok])
    out["dem_formulas"] = {
        "legendre_2006": _errors(legendre(St_all), e_all),
        "exponential_fitted": _exponential_errors(St_all, e_all),
    }
    return out


def _exponential_errors(St, e_n) -> dict:
    """Fit e_max exp(-St_c/St) to all points and report its errors."""
    result = least_squares(lambda p: exponential(St, p[0], p[1]) - e_n, x0=[10.0, 1.0])
    St_c, e_max = result.x
    return {
        "St_c": float(St_c),
        "e_max": float(e_max),
        **_errors(exponential(St, St_c, e_max), e_n),
    }
