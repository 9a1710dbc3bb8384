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
<mu0/mu>_e = sum_q w_q mu0/mu(P_q), P linear on the element (the factor of an element that
carries a constant flux; docs/model.md). The integral of R^3/H^3 is by the six-point
Gauss-Legendre rule (points ``xi``, weights ``w`` on [0, 1]), H at the points given by the
caller (the undeformed gap exact between nodes). The viscosity law stays a plug-in: its
fluidity mu0/mu and d(mu0/mu)/dP at the element's points are inputs.

One compiled loop over the elements replaces some forty small array operations a call, each of
which cost more in overhead than its arithmetic (docs/performance.md).
"""

from __future__ import annotations

import numpy as np
from numba import njit


@njit(cache=True)
def assemble_bands(
    radii,
    thickness,
    pressure,
    regular,
    cut_length,
    cut_between,
    between,
    fluidity,
    dfluidity,
    xi,
    w,
):
    """(mass, conductance, dflux_dH, dflux_dP) on ``len(radii)`` nodes, each band triple
    (lower, diagonal, upper) with lower[0] and upper[-1] unused (module docstring).

    The wetted elements are the whole cells 0..``regular``-1 and, if ``cut_length`` > 0, the
    cell ``regular`` cut to that length at the wetted edge (H = 1, P = 0 there). ``thickness``
    H and ``pressure`` P are nodal; H at the points is linear between the element's ends plus
    the undeformed gap's excess over its chord, ``between`` (cells, len(xi)) on whole cells and
    ``cut_between`` on the cut one. ``fluidity``, ``dfluidity``: mu0/mu and d(mu0/mu)/dP at
    the elements' points (elements, len(xi)); an empty array: constant viscosity, E = 0."""
    n = len(radii)
    mass = np.zeros(n)
    lower, diagonal, upper = np.zeros(n), np.zeros(n), np.zeros(n)
    h_lower, h_diagonal, h_upper = np.zeros(n), np.zeros(n), np.zeros(n)
    p_lower, p_diagonal, p_upper = np.zeros(n), np.zeros(n), np.zeros(n)
    piezoviscous = fluidity.shape[0] > 0
    points = len(xi)
    density = np.empty(points)
    h_points = np.empty(points)
    for e in range(regular + (1 if cut_length > 0.0 else 0)):
        r_left = radii[e]
        is_regular = e < regular
        if is_regular:
            length, r_right = radii[e + 1] - r_left, radii[e + 1]
            h_right, p_right = thickness[e + 1], pressure[e + 1]
            for q in range(points):
                h_points[q] = thickness[e] * (1.0 - xi[q]) + h_right * xi[q] + between[e, q]
        else:
            length, r_right = cut_length, r_left + cut_length
            p_right = 0.0
            for q in range(points):
                h_points[q] = thickness[e] * (1.0 - xi[q]) + xi[q] + cut_between[q]
        jump = pressure[e] - p_right
        # int phi R dR of the falling (left) and rising (right) hats over the element
        falling = length * (2.0 * r_left + (r_left + length)) / 6.0
        rising = length * (r_left + 2.0 * r_right) / 6.0
        squeeze_flux = 0.5 * r_left * r_left + falling
        resistance = 0.0
        for q in range(points):
            radius = r_left + length * xi[q]
            density[q] = 3.0 * w[q] * length * radius**3.0 / h_points[q] ** 3.0
            resistance += density[q]
        geometric = squeeze_flux * squeeze_flux / resistance
        mean = 1.0
        dk_dp_left = dk_dp_right = 0.0
        if piezoviscous:
            mean = 0.0
            for q in range(points):
                mean += w[q] * fluidity[e, q]
                share = geometric * w[q] * dfluidity[e, q]
                dk_dp_left += share * (1.0 - xi[q])
                dk_dp_right += share * xi[q]
        dk_dh_left = dk_dh_right = 0.0
        for q in range(points):
            slope = geometric / resistance * 3.0 * density[q] / h_points[q] * mean
            dk_dh_left += slope * (1.0 - xi[q])
            dk_dh_right += slope * xi[q]
        k = geometric * mean
        mass[e] += falling
        diagonal[e] += k
        h_diagonal[e] += dk_dh_left * jump
        p_diagonal[e] += dk_dp_left * jump
        if is_regular:
            right = e + 1
            mass[right] += rising
            diagonal[right] += k
            upper[e] -= k
            lower[right] -= k
            h_upper[e] += dk_dh_right * jump
            h_lower[right] -= dk_dh_left * jump
            h_diagonal[right] -= dk_dh_right * jump
            p_upper[e] += dk_dp_right * jump
            p_lower[right] -= dk_dp_left * jump
            p_diagonal[right] -= dk_dp_right * jump
    return (
        mass,
        (lower, diagonal, upper),
        (h_lower, h_diagonal, h_upper),
        (p_lower, p_diagonal, p_upper),
    )
