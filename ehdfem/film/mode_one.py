"""The film's azimuthal mode-1 (cos phi) operators about the axisymmetric film: the sliding
and spinning sphere's film (scaled as :mod:`ehdfem.film.reynolds`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .elements import mode_one_bands
from .reynolds import (
    _GAUSS_W,
    _GAUSS_XI,
    Film,
    _at_gauss_points,
    _cell_hat_weights,
    _Elements,
    _hat_weights,
)


@dataclass
class ModeOneFilm:
    """The film's azimuthal mode-1 (cos phi) operators at one instant (scaled).

    A sliding and spinning sphere adds to the axisymmetric film (H0, P0) a mode-1 pressure
    p1 = mu U0 sqrt(a) x0^(-3/2) q(R) cos(phi) and, on elastic solids, a mode-1 gap
    h1 = x0 (U0/V0) sqrt(delta) H1(R) cos(phi). In these units (q is the film pressure unit
    and H1 the gap unit, both times (U0/V0) sqrt(delta)) the mode-1 Reynolds equation,
    linearised about (H0, P0), is

        dH1/dT = (1/(12 R)) (R phi H0^3 q')' - phi H0^3 q / (12 R^2)
                 + (1/(4 R)) (R phi H0^2 H1 P0')' + (1/(12 R)) (R phi_P H0^3 q P0')'
                 + (w/2) dH0/dR,

    with phi = mu0/mu(P0), phi_P = d phi/dP and w = (U + a Omega)/U0 the rolling speed. On P1
    elements (weak form with the weight R, lumped mass) it reads, at the ``free`` nodes,

        mass * dH1/dT + conductance q + thickness_coupling H1 + pressure_coupling q
            = (w/2) drive,

    and q = 0 elsewhere: on the axis, at dry nodes, at the immersed end and at cavitated nodes
    (where P0 sits at the cavitation limit, the linearised limit P0 + q cos phi >= P_cav holds
    for every phi only with q = 0). The three matrices are tridiagonal and kept as their
    bands (lower, diagonal, upper). ``conductance`` is the symmetric form
    (1/12) int phi H0^3 (q' v' + q v / R^2) R dR; q . conductance q is the Poiseuille
    dissipation of the mode-1 flow. ``drive`` is int H0' v R dR. ``torque_weights`` give
    int q R^2 dR. ``shear_weights`` j_i = int phi_i theta (mu/mu0) R dR / H0 give the
    Couette force of nodal slip velocities; their sum is the Couette integral J. ``tail`` (immersed
    only) is ln of the undeformed far-field film between the last node and the sphere's radius,
    where the rigid resistances J, G and M grow as 1, 3/5 and 2/5 of it.
    """

    free: np.ndarray
    mass: np.ndarray
    conductance: np.ndarray
    thickness_coupling: np.ndarray
    pressure_coupling: np.ndarray
    drive: np.ndarray
    torque_weights: np.ndarray
    shear_weights: np.ndarray
    tail: float
    _film: Film
    _elements: _Elements
    _pressure_slope: np.ndarray

    def rigid_pressure(self) -> np.ndarray:
        """q per unit rolling speed w on rigid solids (H1 = 0), the quasi-steady solution of
        conductance q = drive / 2 at the free nodes (q = 6 w Pi of the classical mode-1
        problem (1/R)(R H^3 Pi')' - H^3 Pi / R^2 = -H')."""
        q = np.zeros_like(self.drive)
        free = self.free
        operator = _dense(band_sum(self.conductance, self.pressure_coupling))
        q[free] = np.linalg.solve(operator[np.ix_(free, free)], 0.5 * self.drive[free])
        return q

    def surface_slope_weights(self, surface_sum: np.ndarray | None = None) -> np.ndarray:
        """s with s . q = int q dSigma0/dR R dR, Sigma0 = X + S(R) + u_s + u_w the sum of the
        two surfaces' heights: the undeformed gap plus ``surface_sum``, the nodal sum of the
        sphere's and the wall's axisymmetric displacements along z (by x0, z from the wall into
        the sphere; None: 0, as for identical half-spaces or rigid solids)."""
        el, gap, radii = self._elements, self._film.gap, self._film.radii
        left = radii[el.left]
        chord = (gap.height(left + el.length) - gap.height(left)) / el.length
        slope = chord[:, None] + gap.slope_between_nodes(left, el.length, _GAUSS_XI)
        if surface_sum is not None:
            ends = np.interp(left + el.length, radii, surface_sum) - surface_sum[el.left]
            slope = slope + (ends / el.length)[:, None]
        return _hat_weights(el, slope, len(self.drive))

    def gradient_weights(self) -> np.ndarray:
        """g with g . f = int f P0' R dR for a nodal (P1) f on the whole grid (f need not vanish
        at the wetted edge)."""
        el = self._elements
        values = np.broadcast_to(self._pressure_slope[:, None], el.gauss_r.shape)
        return _cell_hat_weights(el, self._film.radii, values)


def _mode_one_matrices(el, n, weight, thickness, fluidities, pressure_slope):
    """The mode-1 film's P1 matrices on the elements ``el`` (n nodes), as the bands (lower,
    diagonal, upper) of the tridiagonal matrices (:func:`ehdfem.film.reynolds.tridiagonal_product`),
    by Gauss quadrature with ``weight`` = R dR at the Gauss points, H0 ``thickness`` there and
    the fluidity mu0/mu with its pressure derivative (``fluidities``):

        conductance_ab        = (1/12) int (mu0/mu) H0^3 (phi_a' phi_b' + phi_a phi_b / R^2) R dR,
        thickness_coupling_ab = (1/4)  int (mu0/mu) H0^2 dP0/dR phi_a' phi_b R dR,
        pressure_coupling_ab  = (1/12) int d(mu0/mu)/dP H0^3 dP0/dR phi_a' phi_b R dR

    (scaled as the axisymmetric film: H by x0, R by sqrt(a x0), P by mu V0 a / x0^2), in one
    compiled loop (:func:`ehdfem.film.elements.mode_one_bands`). The cut element's right end is
    no unknown, so its rows and columns are left out."""
    fluidity, dfluidity = fluidities
    out = mode_one_bands(
        n,
        el.left,
        el.right,
        el.length,
        el.gauss_r,
        weight,
        thickness,
        np.broadcast_to(fluidity, thickness.shape),
        np.broadcast_to(dfluidity, thickness.shape),
        pressure_slope,
        _GAUSS_XI,
    )
    return tuple(tuple(out[matrix]) for matrix in range(3))


def _dense(bands) -> np.ndarray:
    """The n x n matrix of the bands (lower, diagonal, upper)."""
    lower, diagonal, upper = bands
    return np.diag(diagonal) + np.diag(lower[1:], -1) + np.diag(upper[:-1], 1)


def band_sum(first, second) -> tuple:
    """The bands of the sum of two tridiagonal matrices given by their bands."""
    return tuple(x + y for x, y in zip(first, second, strict=True))


def mode_one_operators(
    film: Film,
    film_thickness: np.ndarray,
    outer_radius: float = np.inf,
    pressure=None,
    fill=None,
    cavitated=None,
) -> ModeOneFilm:
    """The film's azimuthal mode-1 operators at one instant (see :class:`ModeOneFilm`).

    ``film_thickness`` H0 and ``pressure`` P0 are the axisymmetric film at the nodes (by x0
    and mu V0 a / x0^2; the viscosity is taken at P0, mu0 if not given), ``fill`` the liquid
    fraction theta (1 if not given; a cavity shears only its liquid), ``cavitated`` the nodes
    where P0 is at the cavitation limit (boolean; none if not given). Thin layer: up to the
    wetted edge. Immersed: up to ``outer_radius`` (the sphere radius, 1/sqrt(delta), caps
    the logarithmic far field); beyond the last node the film is taken as the undeformed
    X + R^2/2, whose rigid resistances grow as ln H (``tail``).
    """
    h = film_thickness
    n = len(h)
    el = film._inner_elements(h, outer_radius)
    thickness = film._gauss_thickness(el)
    regular = el.right >= 0
    right = np.where(regular, el.right, 0)
    ratio, dlog = film.viscosity.ratio(_at_gauss_points(el, pressure, 0.0))
    fluidity = 1.0 / ratio  # mu0 / mu
    slope = ((el.h_right - el.h_left) / el.length)[:, None] + film.gap.slope_between_nodes(
        film.radii[el.left], el.length, _GAUSS_XI
    )
    weight = el.length[:, None] * _GAUSS_W * el.gauss_r  # R dR at the Gauss points
    pressure_slope = np.zeros(len(el.left))
    if pressure is not None:
        pressure_slope = (np.where(regular, pressure[right], 0.0) - pressure[el.left]) / (el.length)
    dfluidity = -fluidity * (0.0 if dlog is None else dlog)
    conductance, thickness_coupling, pressure_coupling = _mode_one_matrices(
        el, n, weight, thickness, (fluidity, dfluidity), pressure_slope
    )
    free = _mode_one_free(film, el, n, cavitated)
    shear, tail = film._couette_weights_on(el, thickness, ratio, h, outer_radius, fill)
    return ModeOneFilm(
        free=free,
        mass=_hat_weights(el, np.ones_like(thickness), n),
        conductance=conductance,
        thickness_coupling=thickness_coupling,
        pressure_coupling=pressure_coupling,
        drive=_hat_weights(el, slope, n),
        torque_weights=_hat_weights(el, el.gauss_r, n),
        shear_weights=shear,
        tail=tail,
        _film=film,
        _elements=el,
        _pressure_slope=pressure_slope,
    )


def _mode_one_free(film: Film, el, n, cavitated) -> np.ndarray:
    """The nodes where the mode-1 flux unknown q is free: not on the axis, not dry, not at the
    immersed film's last node and not cavitated (q = 0 there)."""
    free = np.zeros(n, bool)
    free[el.left[1:]] = True
    if film.layer == "immersed" and len(el.left):
        free[el.right[-1]] = False
    if cavitated is not None:
        free &= ~np.asarray(cavitated, bool)
    return free
