"""The film's element assembly, compiled: lumped masses, conductances and their derivatives.

Scaled as :mod:`ehdfem.film.reynolds` (R by sqrt(a x0), H by x0, P by mu V0 a / x0^2). On the
wetted elements of the P1 grid (``regular`` whole cells 0..m-1, then, for a thin layer, the cell
m cut at the wetted edge, where H = 1 and P = 0) one call forms

    m_i  = int phi_i R dR                                  (lumped mass, the weight R),
    k_e  = <mu0/mu>_e A_e^2 / int_e 3 R^3 / H^3 dR          (element conductance),
    K    = sum_e k_e (e_l - e_r)(e_l - e_r)^T               (the flux (K P)_i, tridiagonal),
    D    = sum_e (dk_e/dH) (P_l - P_r) (e_l - e_r)^T        (d(K P)/dH, tridiagonal),
    E    = sum_e (dk_e/dP) (P_l - P_r) (e_l - e_r)^T        (d(K P)/dP - K, piezoviscous),

with A_e = R_l^2/2 + L (3 R_l + L)/6 the flux through the element of a uniform unit squeeze and
<mu0/mu>_e = (Pi(P_r) - Pi(P_l)) / (P_r - P_l) the mean fluidity over the element's linear P,
Pi(P) = int_0^P mu0/mu dP' the reduced pressure (the factor of an element that carries a
constant flux, exact however steeply mu grows across it; docs/model.md). The integral of
R^3/H^3 is by the six-point Gauss-Legendre rule (points ``xi``, weights ``w`` on [0, 1]), H at
the points given by the caller (the undeformed gap exact between nodes). The viscosity law
stays a plug-in: the elements' mean fluidities and their derivatives by the nodal pressures
are inputs (:meth:`ehdfem.film.reynolds.Film._fluidity`).

One compiled loop over the elements replaces some forty small array operations a call, each of
which cost more in overhead than its arithmetic (docs/performance.md). The loops use numpy's
error model: a division by zero gives inf instead of raising, so no test precedes each division
and the loops vectorise (the assembly at 240 nodes 48 -> 27 us). No divisor here can vanish (H
is checked positive before the film is assembled, and a Newton matrix that is not finite is
refused as singular).
"""

from __future__ import annotations

import numpy as np
from numba import njit


@njit(cache=True, error_model="numpy")
def _conductance(r_left, length, h_points, mean, d_left, d_right, xi, w, density):
    """(k, dk/dH_left, dk/dH_right, dk/dP_left, dk/dP_right) of an element from its left
    radius, its length and H at its points (module docstring); ``mean``, ``d_left`` and
    ``d_right``: its mean fluidity <mu0/mu>_e and that mean's derivatives by the left and right
    nodes' pressures (1, 0, 0 at constant viscosity); ``density``: room for the resistance's
    terms at the points."""
    points = len(xi)
    squeeze_flux = 0.5 * r_left * r_left + length * (3.0 * r_left + length) / 6.0
    resistance = 0.0
    for q in range(points):
        radius = r_left + length * xi[q]
        h = h_points[q]
        density[q] = 3.0 * w[q] * length * (radius * radius * radius) / (h * h * h)
        resistance += density[q]
    geometric = squeeze_flux * squeeze_flux / resistance
    dk_dp_left = geometric * d_left
    dk_dp_right = geometric * d_right
    factor = 3.0 * geometric / resistance * mean
    dk_dh_left = dk_dh_right = 0.0
    for q in range(points):
        slope = factor * density[q] / h_points[q]
        dk_dh_left += slope * (1.0 - xi[q])
        dk_dh_right += slope * xi[q]
    return geometric * mean, dk_dh_left, dk_dh_right, dk_dp_left, dk_dp_right


@njit(cache=True, error_model="numpy")
def assemble_bands(
    radii,
    thickness,
    pressure,
    regular,
    cut_length,
    cut_between,
    between,
    fluidity,
    d_left,
    d_right,
    xi,
    w,
):
    """(mass, conductance, dflux_dH, dflux_dP) on ``len(radii)`` nodes, each band triple
    (lower, diagonal, upper) with lower[0] and upper[-1] unused (module docstring).

    The wetted elements are the whole cells 0..``regular``-1 and, if ``cut_length`` > 0, the
    cell ``regular`` cut to that length at the wetted edge (H = 1, P = 0 there). ``thickness``
    H and ``pressure`` P are nodal; H at the points is linear between the element's ends plus
    the undeformed gap's excess over its chord, ``between`` (cells, len(xi)) on whole cells and
    ``cut_between`` on the cut one. ``fluidity``, ``d_left``, ``d_right``: each element's mean
    fluidity <mu0/mu>_e and its derivatives by the pressures of its left and right ends; empty
    arrays: constant viscosity, E = 0."""
    n = len(radii)
    mass = np.zeros(n)
    k_bands = (np.zeros(n), np.zeros(n), np.zeros(n))
    h_bands = (np.zeros(n), np.zeros(n), np.zeros(n))
    p_bands = (np.zeros(n), np.zeros(n), np.zeros(n))
    h_points, density = np.empty(len(xi)), np.empty(len(xi))
    piezoviscous = fluidity.shape[0] > 0
    for e in range(regular + (1 if cut_length > 0.0 else 0)):
        r_left, whole = radii[e], e < regular
        if whole:
            length, p_right = radii[e + 1] - r_left, pressure[e + 1]
            h_right, excess = thickness[e + 1], between[e]
        else:
            length, p_right, h_right, excess = cut_length, 0.0, 1.0, cut_between
        for q in range(len(xi)):
            h_points[q] = thickness[e] * (1.0 - xi[q]) + h_right * xi[q] + excess[q]
        mean = fluidity[e] if piezoviscous else 1.0
        slope_left = d_left[e] if piezoviscous else 0.0
        slope_right = d_right[e] if piezoviscous else 0.0
        k, dh_left, dh_right, dp_left, dp_right = _conductance(
            r_left, length, h_points, mean, slope_left, slope_right, xi, w, density
        )
        jump = pressure[e] - p_right
        # int phi R dR of the falling (left) hat over the element, and of the rising one
        mass[e] += length * (2.0 * r_left + (r_left + length)) / 6.0
        if whole:
            mass[e + 1] += length * (r_left + 2.0 * radii[e + 1]) / 6.0
        _add_flux(k_bands, e, k, -k, whole)
        _add_flux(h_bands, e, dh_left * jump, dh_right * jump, whole)
        _add_flux(p_bands, e, dp_left * jump, dp_right * jump, whole)
    return mass, k_bands, h_bands, p_bands


@njit(cache=True, error_model="numpy")
def _add_flux(bands, e, left, right, whole):
    """Add to the bands the derivatives (d/dy_left, d/dy_right) = (``left``, ``right``) of the
    flux q out of element e's left node (and, on a ``whole`` element, into its right node:
    that row takes -q's)."""
    lower, diagonal, upper = bands
    diagonal[e] += left
    if whole:
        upper[e] += right
        lower[e + 1] -= left
        diagonal[e + 1] -= right


@njit(cache=True, error_model="numpy")
def _thickness_at(thickness, e, whole, between, cut_between, xi, q):
    """H at point xi[q] of element e: linear between its ends (H = 1 at a cut element's edge)
    plus the undeformed gap's excess over its chord."""
    if whole:
        return thickness[e] * (1.0 - xi[q]) + thickness[e + 1] * xi[q] + between[e, q]
    return thickness[e] * (1.0 - xi[q]) + xi[q] + cut_between[q]


@njit(cache=True, error_model="numpy")
def squeeze_shear_load(
    radii, thickness, pressure, regular, cut_length, cut_between, between, xi, w
):
    """int phi_j T R dR at the nodes for the element-wise traction T = -(H/2) dP/dR, P linear
    on each wetted element (P = 0 at a cut element's edge), H at the points ``xi`` (weights
    ``w``), phi_j the hats of the grid's whole cells (a cut element keeps its cell's hats).
    The wetted elements, ``thickness`` H, ``between`` and ``cut_between`` as in
    :func:`assemble_bands`."""
    n = len(radii)
    load = np.zeros(n)
    for e in range(regular + (1 if cut_length > 0.0 else 0)):
        whole = e < regular
        length = radii[e + 1] - radii[e] if whole else cut_length
        cell = radii[min(e + 1, n - 1)] - radii[e] if e < n - 1 else length
        slope = ((pressure[e + 1] if whole else 0.0) - pressure[e]) / length
        for q in range(len(xi)):
            h = _thickness_at(thickness, e, whole, between, cut_between, xi, q)
            radius = radii[e] + length * xi[q]
            rising = length * xi[q] / cell
            weight = length * w[q] * radius * (-0.5 * h * slope)
            load[e] += weight * (1.0 - rising)
            load[min(e + 1, n - 1)] += weight * rising
    return load


@njit(cache=True, error_model="numpy")
def surface_transport_bands(
    radii, thickness, fill, regular, cut_length, cut_between, between, xi, w
):
    """Bands (lower, diagonal, upper) of B, (B v)_i = -int phi_i' R theta H v dR over the
    wetted elements, v and the liquid fraction theta (``fill``, 1 at a cut element's edge)
    linear on the grid's cells (a cut element keeps its cell's hats), H at the points ``xi``
    (weights ``w``); the wetted elements, ``thickness`` H, ``between`` and ``cut_between`` as
    in :func:`assemble_bands`."""
    n = len(radii)
    lower, diagonal, upper = np.zeros(n), np.zeros(n), np.zeros(n)
    for e in range(regular + (1 if cut_length > 0.0 else 0)):
        whole = e < regular
        length = radii[e + 1] - radii[e] if whole else cut_length
        cell = radii[e + 1] - radii[e]
        fill_right = fill[e + 1] if whole else 1.0
        from_left = from_right = 0.0
        for q in range(len(xi)):
            h = _thickness_at(thickness, e, whole, between, cut_between, xi, q)
            radius = radii[e] + length * xi[q]
            theta = fill[e] * (1.0 - xi[q]) + fill_right * xi[q]
            rising = (radius - radii[e]) / cell
            weight = w[q] * radius * h * theta
            from_left += weight * (1.0 - rising)
            from_right += weight * rising
        diagonal[e] += from_left
        upper[e] += from_right
        if whole:
            lower[e + 1] -= from_left
            diagonal[e + 1] -= from_right
    return lower, diagonal, upper


@njit(cache=True, error_model="numpy")
def tridiagonal_rows(bands, matrix, rows) -> np.ndarray:
    """The rows ``rows`` of tridiag(lower, diagonal, upper) @ ``matrix`` (n x m) for the bands
    (lower, diagonal, upper) of an n x n tridiagonal matrix (lower[0] and upper[-1] unused),
    one compiled pass over the three rows each output row combines."""
    lower, diagonal, upper = bands
    n, m = matrix.shape
    out = np.empty((len(rows), m))
    for j in range(len(rows)):
        i = rows[j]
        for k in range(m):
            out[j, k] = diagonal[i] * matrix[i, k]
        if i > 0:
            for k in range(m):
                out[j, k] += lower[i] * matrix[i - 1, k]
        if i < n - 1:
            for k in range(m):
                out[j, k] += upper[i] * matrix[i + 1, k]
    return out


@njit(cache=True, error_model="numpy")
def add_band_rows(bands, rows, out):
    """out[j, i-1..i+1] += the bands' row i = rows[j] (lower[0] and upper[-1] unused): the rows
    ``rows`` of a tridiagonal matrix added to the first n columns of ``out`` (its whole n x n
    part for every row)."""
    lower, diagonal, upper = bands
    n = len(diagonal)
    for j in range(len(rows)):
        i = rows[j]
        if i > 0:
            out[j, i - 1] += lower[i]
        out[j, i] += diagonal[i]
        if i < n - 1:
            out[j, i + 1] += upper[i]


@njit(cache=True, error_model="numpy")
def _banded_product(bands, column, out, k):
    """out[:, k] = tridiag(lower, diagonal, upper) @ ``column``, the interior rows in one
    branch-free pass (each row summed diagonal, lower, upper, as :func:`tridiagonal_rows`)."""
    lower, diagonal, upper = bands
    n = len(diagonal)
    out[0, k] = diagonal[0] * column[0] + upper[0] * column[1]
    for i in range(1, n - 1):
        out[i, k] = diagonal[i] * column[i] + lower[i] * column[i - 1] + upper[i] * column[i + 1]
    out[n - 1, k] = diagonal[n - 1] * column[n - 1] + lower[n - 1] * column[n - 2]


@njit(cache=True, error_model="numpy")
def add_banded_product(bands, matrix, scale, out):
    """out[:n, :m] += ``scale`` tridiag(lower, diagonal, upper) @ ``matrix`` (n x m), column by
    column (:func:`_banded_product`: the same sums as :func:`tridiagonal_rows`; ``matrix`` and
    ``out`` best in column order)."""
    n, m = matrix.shape
    column = np.empty((n, 1))
    for k in range(m):
        _banded_product(bands, matrix[:, k], column, 0)
        for i in range(n):
            out[i, k] += column[i, 0] * scale


@njit(cache=True, error_model="numpy")
def film_jacobian(squeeze, compliance, by_gap, flux_bands, viscous_bands, out):
    """The film's rows of the Newton matrix into ``out`` (at least n x (n + 1)):
    d(r)/dP = S C + K + E and d(r)/dX = S g, with S = ``squeeze`` the bands of d(r)/dH,
    C = ``compliance`` (dH/dP), g = ``by_gap`` (dH/dX), K = ``flux_bands`` and E =
    ``viscous_bands`` (:mod:`ehdfem.motion.implicit_step`). Column by column, so that a matrix
    in LAPACK's column order is written in its own order (``compliance`` best so too)."""
    n = len(by_gap)
    for k in range(n):
        _banded_product(squeeze, compliance[:, k], out, k)
    _banded_product(squeeze, by_gap, out, n)
    every_row = np.arange(n)
    add_band_rows(flux_bands, every_row, out)
    add_band_rows(viscous_bands, every_row, out)


@njit(cache=True, error_model="numpy")
def mode_one_bands(
    n, left, right, length, gauss_r, weight, thickness, fluidity, dfluidity, pressure_slope, xi
):
    """The mode-1 film's three tridiagonal matrices (:mod:`ehdfem.film.mode_one`)
    on the elements (``left`` and ``right`` nodes, -1 for a cut element's, whose right end is no
    unknown; ``length``), as out[matrix, band, node], the bands (lower, diagonal, upper) of

        conductance_ab        = (1/12) sum_q w_q phi H^3 (s_a s_b + h_a h_b / R_q^2),
        thickness_coupling_ab = (1/4)  sum_q w_q phi H^2 P0' s_a h_b,
        pressure_coupling_ab  = (1/12) sum_q w_q phi_P H^3 P0' s_a h_b

    for the element's hats a, b (h their values at the points ``xi``, s their slopes), with
    ``weight`` w = R dR, ``thickness`` H0, ``fluidity`` phi = mu0/mu and ``dfluidity`` its
    pressure derivative at the Gauss points (elements, points), ``pressure_slope`` P0' on each
    element (scaled as the axisymmetric film). One loop replaces some sixty array operations
    (135 -> 15 us at 240 nodes)."""
    out = np.zeros((3, 3, n))
    points = len(xi)
    for e in range(len(left)):
        regular = right[e] >= 0
        nodes = (left[e], right[e] if regular else left[e])
        slopes = (-1.0 / length[e], (1.0 if regular else 0.0) / length[e])
        for a in range(2):
            for b in range(2):
                if not regular and (a == 1 or b == 1):
                    continue
                stiff = hoop = thick = press = 0.0
                for q in range(points):
                    hat_a = 1.0 - xi[q] if a == 0 else xi[q]
                    hat_b = 1.0 - xi[q] if b == 0 else xi[q]
                    h = thickness[e, q]
                    cube = fluidity[e, q] * h * h * h
                    radius = gauss_r[e, q]
                    stiff += weight[e, q] * cube
                    hoop += weight[e, q] * cube * hat_a * hat_b / (radius * radius)
                    grad = slopes[a] * pressure_slope[e] * hat_b * weight[e, q]
                    thick += grad * fluidity[e, q] * h * h
                    press += grad * dfluidity[e, q] * h * h * h
                values = (
                    (stiff * slopes[a] * slopes[b] + hoop) / 12.0,
                    thick / 4.0,
                    press / 12.0,
                )
                for matrix in range(3):
                    if a == b:
                        out[matrix, 1, nodes[a]] += values[matrix]
                    elif a == 1:
                        out[matrix, 0, nodes[1]] += values[matrix]
                    else:
                        out[matrix, 2, nodes[0]] += values[matrix]
    return out
