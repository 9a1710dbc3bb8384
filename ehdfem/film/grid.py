"""Radial film grids (scaled by sqrt(a x0)): where the film's nodes sit.

A collision's film needs fine nodes where the solids flatten and the film is thinnest (the
contact, its rim and the exit constriction) and few in the far field, whose extent grows
with the contact: the grids here grow their spacing in proportion to R beyond a fine radius
(:func:`radial_grid`) or follow a spacing law graded to the contact's rim (:func:`contact_grid`),
so the far field costs a logarithmic number of nodes.
"""

from __future__ import annotations

import numpy as np

from .. import checks


def radial_grid(n: int, fine_radius: float, outer_radius: float) -> np.ndarray:
    """Film nodes R_i = R_f sinh(A i/(n-1)), A = asinh(R_max / R_f), scaled by sqrt(a x0).

    The spacing is nearly uniform, A R_f / (n-1), inside the fine radius R_f (where the solids
    flatten and the film is thinnest) and grows in proportion to R beyond it, so a far field
    out to R_max costs only a logarithmic number of nodes.
    """
    n = checks.integer("n (film nodes)", n, lower=8)
    fine_radius = checks.positive("fine_radius", fine_radius)
    outer_radius = checks.number("outer_radius", outer_radius, lower=fine_radius, lower_open=True)
    stretch = np.arcsinh(outer_radius / fine_radius)
    radii = fine_radius * np.sinh(stretch * np.linspace(0.0, 1.0, n))
    radii[-1] = outer_radius
    return radii


# The contact grid's spacing, a piecewise-linear function of rho = R / R_c (module docstring of
# contact_grid): the caller's spacing on the axis and at the rim and outlet radius (where the
# spacing is back to _OUTLET_SPACING), the fixed knots (rho, spacing) inside the contact, and
# the slope beyond the outlet.
AXIS_SPACING = 0.2
RIM_SPACING = 0.3
OUTLET_RADIUS = 1.5
_CONTACT_INTERIOR_KNOTS = ((0.4, 1.0), (1.0 - 0.65 / 3.0, 1.0))
_OUTLET_SPACING = 4.35
_CONTACT_SPACING_SLOPE = 16.0


def contact_grid(
    n: int,
    rim_radius: float,
    outer_radius: float,
    node_at: float | None = None,
    axis_spacing: float = AXIS_SPACING,
    rim_spacing: float = RIM_SPACING,
    outlet_radius: float = OUTLET_RADIUS,
) -> np.ndarray:
    """Film nodes graded to a contact rim R_c, by sqrt(a x0).

    The spacing is c s(R/R_c), s piecewise linear: ``axis_spacing`` (0.2) on the axis (where a
    soft rebound's film is thinnest), 1 from 0.4 R_c to 0.78 R_c, down to ``rim_spacing`` (0.3)
    at the rim (where a hard impact's exit constriction makes the film thinnest), up to 4.35 at
    ``outlet_radius`` (1.5) R_c and growing by 16 per R_c beyond, so the far field grows
    geometrically and costs a logarithmic number of nodes. The nodes sit at equal steps of
    int dR / s(R/R_c), with c set by n. ``node_at``: a radius given a node of its own if it lies
    inside the grid (the sphere's radius, where the immersed film's shear integrals end).
    """
    rim_radius = checks.positive("rim_radius", rim_radius)
    outer_radius = checks.number("outer_radius", outer_radius, lower=rim_radius, lower_open=True)
    axis_spacing = checks.number("axis_spacing", axis_spacing, lower=0.01, upper=1.0)
    rim_spacing = checks.number("rim_spacing", rim_spacing, lower=0.01, upper=1.0)
    outlet_radius = checks.number(
        "outlet_radius", outlet_radius, lower=1.0, upper=3.0, lower_open=True
    )
    if node_at is not None and node_at <= rim_radius:
        node_at = None
    law = (
        (0.0, axis_spacing),
        *_CONTACT_INTERIOR_KNOTS,
        (1.0, rim_spacing),
        (outlet_radius, _OUTLET_SPACING),
    )
    radii = graded_grid(n, _contact_spacing(law, outer_radius / rim_radius), rim_radius, node_at)
    radii[-1] = outer_radius  # not rim_radius * (outer_radius / rim_radius)
    return radii


def _contact_spacing(law, end: float) -> tuple[np.ndarray, np.ndarray]:
    """(rho, s) knots of the contact grid's spacing ``law`` (its knots (rho, s), then the slope
    _CONTACT_SPACING_SLOPE; :func:`contact_grid`) out to the grid's end rho = R_end / R_c, both
    by the rim radius R_c."""
    knots = [(rho, s) for rho, s in law if rho < end]
    last_rho, last_s = law[len(knots) - 1]
    slope = _CONTACT_SPACING_SLOPE
    if len(knots) < len(law):
        slope = (law[len(knots)][1] - last_s) / (law[len(knots)][0] - last_rho)
    rho = np.array([k[0] for k in knots] + [end])
    spacing = np.array([k[1] for k in knots] + [last_s + slope * (end - last_rho)])
    return rho, spacing


def graded_grid(n: int, knots, scale: float = 1.0, node_at: float | None = None) -> np.ndarray:
    """n nodes at equal steps of int dR / s(R) from 0 to the last knot, s piecewise linear
    through ``knots`` (R, s), both in units of ``scale`` (R from 0, s > 0); ``node_at``: a
    radius given a node of its own if it lies inside the grid (equal steps of the share on
    either side of it)."""
    n = checks.integer("n (film nodes)", n, lower=8)
    rho, spacing = (np.asarray(k, dtype=float) for k in knots)
    outer_radius = scale * rho[-1]
    pieces = _SpacingPieces(rho, spacing)
    if node_at is None or not 0.0 < node_at < outer_radius:
        radii = scale * pieces.position(np.linspace(0.0, 1.0, n))
    else:
        at = pieces.share(node_at / scale)
        k = min(max(round(at * (n - 1)), 1), n - 2)
        share = np.concatenate([np.linspace(0.0, at, k + 1), np.linspace(at, 1.0, n - k)[1:]])
        radii = scale * pieces.position(share)
        radii[k] = node_at
    radii[0], radii[-1] = 0.0, outer_radius
    return radii


class _SpacingPieces:
    """A spacing s(rho) linear between knots and the exact share of the nodes up to rho,
    int_0^rho d rho' / s over the total, and its inverse."""

    def __init__(self, rho: np.ndarray, spacing: np.ndarray):
        self.rho, self.spacing = rho, spacing
        self.slope = np.diff(spacing) / np.diff(rho)
        self.cumulative = np.concatenate([[0.0], np.cumsum(self._integral(np.diff(rho)))])

    def _integral(self, width, piece=slice(None)):
        """int d rho / s over ``width`` from the start of each piece."""
        s0, m = self.spacing[:-1][piece], self.slope[piece]
        flat = np.abs(m) < 1e-12
        return np.where(flat, width / s0, np.log1p(m * width / s0) / np.where(flat, 1.0, m))

    def share(self, rho: float) -> float:
        """The share of the nodes inside rho."""
        i = min(int(np.searchsorted(self.rho, rho, side="right")) - 1, len(self.slope) - 1)
        partial = self._integral(np.array([rho - self.rho[i]]), slice(i, i + 1))[0]
        return float((self.cumulative[i] + partial) / self.cumulative[-1])

    def position(self, share: np.ndarray) -> np.ndarray:
        """rho at the given shares of the nodes (the inverse of :meth:`share`)."""
        target = np.asarray(share) * self.cumulative[-1]
        i = np.clip(
            np.searchsorted(self.cumulative, target, side="right") - 1, 0, len(self.slope) - 1
        )
        left = target - self.cumulative[i]
        s0, m = self.spacing[:-1][i], self.slope[i]
        flat = np.abs(m) < 1e-12
        grown = np.expm1(m * left) / np.where(flat, 1.0, m)
        return self.rho[i] + s0 * np.where(flat, left, grown)
