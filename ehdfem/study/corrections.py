"""The first correction to the half-space theory, split by cause (docs/fem.md).

Five models on one film grid, each one change from a neighbour (``VARIANTS``: elasticity model,
undeformed gap, tangential surface effects):

- theory:    half-space, paraboloid gap, pressure only (the asymptotic theory);
- geometry:  half-space, the true sphere's gap;
- surface:   half-space, paraboloid, the squeeze shear's gap opening and the faces' radial
             velocity in the film's flux (``shear_traction``, docs/model.md);
- halfspace: half-space, true gap and surface effects;
- full:      FE solids, true gap and surface effects (the full model).

The causes of full - theory, each relative to the theory's output:
geometry = (geometry - theory), surface = (surface - theory), finite size = (full - halfspace),
interaction = (halfspace - geometry - surface + theory); they add up to (full - theory) / theory.
An immersed layer has no true-gap variant (its film reaches beyond the sphere): its geometry
and halfspace variants are the theory and surface ones, and its geometry share is zero.

The first correction: each share divided by sqrt(delta) tends to a constant c1 as delta -> 0
when the cause acts at order sqrt(delta) (:func:`first_order_fit`: q = c1 + c2 sqrt(delta) by
least squares, with the standard errors of c1 and c2). The surface effects' c1 in closed form,
where the leading order is the rigid approach (eps -> 0): :mod:`ehdfem.exact.surface_limit`.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from .. import checks
from ..collision import collide, elasticity, film_radii
from ..config import RunConfig
from ..film.gap import GAPS, ParaboloidGap
from ..inputs.scales import CollisionParameters

VARIANTS = {
    "theory": ("halfspace", "paraboloid", False),
    "geometry": ("halfspace", "exact", False),
    "surface": ("halfspace", "paraboloid", True),
    "halfspace": ("halfspace", "exact", True),
    "full": ("fem", "exact", True),
}
"""Each model's (elasticity, undeformed gap, tangential surface effects)."""

CAUSES = ("geometry", "surface", "finite size", "interaction")
OUTPUTS = ("e_n", "min_film_thickness", "max_force", "contact_time", "max_compression", "e_t")
"""The summary keys compared (e_n, thinnest film by x0, largest force by 6 pi mu V0 a^2 / x0,
contact time by x0/V0, largest compression by x0, e_t)."""


def variant_parameters(params: CollisionParameters, variant: str) -> CollisionParameters:
    """``params`` with the gap and the surface effects of ``variant`` (the true gap only for a
    thin layer: an immersed layer keeps the paraboloid)."""
    _, gap, shear = VARIANTS[checks.choice("variant", variant, tuple(VARIANTS))]
    gap = GAPS[gap]() if params.layer == "thin" else ParaboloidGap()
    return replace(params, gap=gap, shear_traction=shear)


def run_variants(
    params: CollisionParameters,
    nodes: int,
    materials,
    config: RunConfig | None = None,
) -> dict[str, dict[str, float]]:
    """The outputs (``OUTPUTS``) of the five models at ``params`` on one film grid of ``nodes``
    (that of ``params``), for ``materials`` ((E, nu) of sphere and wall, E by any common unit);
    the time integration of ``config``. Immersed: geometry and halfspace are copies of theory
    and surface."""
    radii = film_radii(params, nodes)
    out = {}
    for variant in VARIANTS:
        if params.layer != "thin" and variant in ("geometry", "halfspace"):
            out[variant] = out["theory" if variant == "geometry" else "surface"]
        else:
            out[variant] = run_model(params, variant, radii, materials, config)
    return out


def run_model(params, variant, radii, materials, config=None) -> dict[str, float]:
    """The outputs (``OUTPUTS``; None as nan) of one model ``variant`` at ``params`` on the
    film nodes ``radii`` (by sqrt(a x0)); ``materials`` and ``config`` as in
    :func:`run_variants`."""
    config = RunConfig() if config is None else config
    inputs = variant_parameters(params, variant)
    model = VARIANTS[variant][0]
    solids = elasticity(inputs, radii, replace(config, model=model), materials=materials)
    try:
        summary = collide(inputs, config, compliance=solids).summary()
    finally:
        solids.close()
    return {key: _number(summary.get(key)) for key in OUTPUTS}


def _number(value) -> float:
    """A summary value as a float (None, e.g. e_t of a head-on impact: nan)."""
    return math.nan if value is None else float(value)


def cause_shares(values: dict[str, dict[str, float]]) -> dict[str, dict[str, float]]:
    """{cause: {output: share}} of the five models' ``values`` ({variant: {output: value}}),
    each share relative to the theory's output, and "total" = (full - theory) / theory, the
    sum of the four (module docstring)."""
    theory = values["theory"]
    out = {cause: {} for cause in (*CAUSES, "total")}
    for key in theory:

        def change(a, b):
            return (values[a][key] - values[b][key]) / theory[key]  # noqa: B023

        out["geometry"][key] = change("geometry", "theory")
        out["surface"][key] = change("surface", "theory")
        out["finite size"][key] = change("full", "halfspace")
        out["interaction"][key] = change("halfspace", "geometry") - out["surface"][key]
        out["total"][key] = change("full", "theory")
    return out


def first_order_fit(deltas, shares) -> tuple[float, float, float, float]:
    """(c1, c2, standard error of c1, of c2) of the least-squares fit
    share / sqrt(delta) = c1 + c2 sqrt(delta) over ``deltas`` (at least three; nan shares are
    left out). c1 is the first correction's constant: share = c1 sqrt(delta) + c2 delta + ...
    The standard errors are those of the residuals (zero for exact data)."""
    deltas, shares = np.asarray(deltas, dtype=float), np.asarray(shares, dtype=float)
    keep = np.isfinite(shares)
    if keep.sum() < 3:
        raise checks.InputError(
            f"the first-order fit needs at least 3 finite shares, got {int(keep.sum())}",
            "shares",
        )
    root = np.sqrt(deltas[keep])
    quotient = shares[keep] / root
    design = np.column_stack([np.ones_like(root), root])
    coefficients, _, _, _ = np.linalg.lstsq(design, quotient, rcond=None)
    residual = quotient - design @ coefficients
    variance = residual @ residual / (len(quotient) - 2)
    errors = np.sqrt(np.diag(variance * np.linalg.inv(design.T @ design)))
    return float(coefficients[0]), float(coefficients[1]), float(errors[0]), float(errors[1])
