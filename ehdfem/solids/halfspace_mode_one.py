"""Elastic half-spaces under azimuthal mode-1 (cos phi) surface tractions, at the film nodes.

One half-space (solid in z < 0, outward normal +z, shear modulus G, Poisson ratio nu). Summing
the Boussinesq (normal) and Cerruti (tangential) point-force solutions (Johnson, Contact
Mechanics, 1985, ch. 3), a surface traction t at the point y moves the surface at x, with
d = x - y and rho = |d|, by

    u_a = (1/(4 rho)) (delta_ab + beta d_a d_b / rho^2) t_b + (gamma/4) d_a / rho^2 t_z,
    u_z = (1/(4 rho)) t_z - (gamma/4) d_b / rho^2 t_b,
    beta = nu / (1 - nu),   gamma = (1 - 2 nu) / (2 (1 - nu))     (a, b in-plane),

per unit force, in units of 4 (1 - nu^2)/(pi E) = 2 (1 - nu)/(pi G). A pressure (t_z < 0)
pushes the surface down; a normal load pulls the surface around it radially towards itself and,
by Betti's reciprocity, a tangential load lowers the surface ahead of it and lifts it behind.

Mode-1 tractions (t_r, t_phi, t_z) = (A(S) cos phi, -B(S) sin phi, Z(S) cos phi) give mode-1
displacements (u_r, u_phi, u_z) = (U_r cos phi, -U_phi sin phi, U_z cos phi) with

    U_a(R) = int_0^inf k_ab(R, S) L_b(S) dS,   (U_r, U_phi, U_z), L = (A, B, Z),

k = S times the phi-integral of the point-force solution weighted by cos or sin of the angle
between the field point and the ring point (:func:`ring_kernel`). k = k0 + beta k_beta +
gamma k_gamma:

- k0 (the 1/rho part): U_r, U_phi from A, B and U_z from Z, complete elliptic integrals K and E
  of m = 4 R S / (R+S)^2 with a logarithmic singularity at S = R. U_z from Z is the mode-1
  analogue of the axisymmetric kernel S/(R+S) K(m) of :mod:`ehdfem.solids.halfspace`.
- k_beta (the d d / rho^3 part): U_r, U_phi from A, B; the same elliptic integrals.
- k_gamma (the d / rho^2 coupling of normal and tangential, elementary): with S < R | S > R,

      U_r from Z:   (pi/4) (S^2/R^2 | -1),     U_phi from Z: -(pi/4) (S^2/R^2 | 1),
      U_z from A:  -(pi/4) (S/R | -R/S),       U_z from B:   -(pi/4) (S/R | R/S).

  They jump at S = R (the 1/rho principal-value parts of the tangential kernels); a mode-1
  pressure moves the surface tangentially by rings inside and outside R, and a traction along
  x (A = B) lowers the surface by (gamma pi/2) (1/R) int_0^R A S dS, rings outside R not at all.

Betti's reciprocity reads k_ab(R, S)/S = k_ba(S, R)/R. On the film nodes, L is piecewise linear
(hat functions, zero beyond the last node) and is integrated as in
:func:`ehdfem.solids.halfspace.influence_matrix`: 8-point Gauss on cells at least a cell
length from R_i, the graded Gauss rule of that module on the others, so the logarithm and the
jumps (which fall on the nodes) are resolved. The phi-integrals are the closed forms above when
min(R, S)/max(R, S) >= 1/4 and a 32-point periodic trapezoidal rule below (where the closed forms
lose digits and the integrand is smooth: error below 1e-15).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit
from scipy.special import ellipe, ellipkm1

from ..checks import InputError, number, positive
from ..inputs.presets import MATERIAL_RANGES
from .compliance import ModeOneCompliance
from .halfspace import IDENTICAL_SOLIDS, film_nodes, hat_integrals, kept_on_grid, theta_shares

_CLOSED_FORM_RATIO = 0.25  # min(R, S)/max(R, S) from which the elliptic closed forms are used
_TRAPEZOID_COSINES = np.cos(np.linspace(0.0, np.pi, 17))  # half a period: the integrands are even
_TRAPEZOID_WEIGHTS = np.full(17, 2.0 * np.pi / 16) * np.r_[0.5, np.ones(15), 0.5]


# the entries [part, displacement, load] of (k0, k_beta, k_gamma) that are not zero
_NONZERO = (
    (0, 0, 0), (0, 1, 1), (0, 0, 1), (0, 1, 0), (0, 2, 2),
    (1, 0, 0), (1, 0, 1), (1, 1, 0), (1, 1, 1),
    (2, 0, 2), (2, 1, 2), (2, 2, 0), (2, 2, 1),
)  # fmt: skip


def _nonzero_parts(radius, offset) -> np.ndarray:
    """The entries _NONZERO of :func:`ring_kernel_parts`, stacked: shape (13, ...), the others
    being zero (the 1/rho and d d/rho^3 parts act within the plane and on the normal alone,
    the d/rho^2 part couples the two)."""
    r, off = np.broadcast_arrays(np.asarray(radius, dtype=float), np.asarray(offset, dtype=float))
    r, off = r.ravel(), off.ravel()
    s = r + off
    closed = np.minimum(r, s) >= _CLOSED_FORM_RATIO * np.maximum(r, s)
    complement = (off[closed] / (r[closed] + s[closed])) ** 2  # 1 - m
    elliptic = np.zeros((2, len(r)))
    elliptic[:, closed] = ellipkm1(complement), ellipe(1.0 - complement)
    flat = _nonzero_values(r, off, closed, elliptic, _TRAPEZOID_COSINES, _TRAPEZOID_WEIGHTS)
    return flat.reshape((len(_NONZERO),) + np.shape(np.broadcast(radius, offset)))


@njit(cache=True)
def _nonzero_values(r, off, closed, elliptic, cosines, weights):
    """:func:`_nonzero_parts` on 1-D arrays, one pass over the points: the closed forms
    (:func:`_elliptic_entries`, with K(m) and E(m) in ``elliptic``) where ``closed``
    (min(R, S)/max(R, S) >= 1/4), else the trapezoidal sums (:func:`_trapezoid_entries`), and
    the elementary k_gamma entries."""
    parts = np.empty((13, len(r)))
    quarter_pi = np.pi / 4
    for i in range(len(r)):
        s = r[i] + off[i]
        if closed[i]:
            entries = _elliptic_entries(r[i], off[i], elliptic[0, i], elliptic[1, i])
        else:
            entries = _trapezoid_entries(r[i], off[i], cosines, weights)
        cos2, sin2, normal, beta00, beta01, beta10, beta11 = entries
        parts[0, i] = parts[1, i] = cos2  # the 1/rho part: (U_r, A), (U_phi, B)
        parts[2, i] = parts[3, i] = sin2  # (U_r, B), (U_phi, A)
        parts[4, i] = normal  # (U_z, Z)
        parts[5, i], parts[6, i], parts[7, i], parts[8, i] = beta00, beta01, beta10, beta11
        if off[i] < 0:  # a ring inside R; ratio min(R, S)/max(R, S)
            ratio = s / r[i]
            parts[9, i] = quarter_pi * ratio**2
            parts[10, i] = -quarter_pi * ratio**2
            parts[11, i] = -quarter_pi * ratio
        else:
            ratio = r[i] / s
            parts[9, i] = -quarter_pi
            parts[10, i] = -quarter_pi
            parts[11, i] = quarter_pi * ratio
        parts[12, i] = -quarter_pi * ratio
    return parts


@njit(cache=True)
def _elliptic_entries(r, off, k, e):
    """S (1/4) int dpsi of the 1/rho and d d/rho^3 parts, in K(m) = ``k`` and E(m) = ``e``
    (R, S comparable): (cos2, sin2, normal, beta_00, beta_01, beta_10, beta_11), the ring
    part's S/4 int (cos^2, sin^2, cos) psi / rho and the beta part's four entries (the 1/rho
    part's (U_r, A) = (U_phi, B) = cos2, (U_r, B) = (U_phi, A) = sin2, (U_z, Z) = normal;
    beta_00 = sin2)."""
    s = r + off
    t, q, rs = r + s, r**2 + s**2, r * s
    sixth = s / (6 * rs**2)
    cos2 = sixth * ((q**2 + 2 * rs**2) / t * k - t * q * e)
    sin2 = sixth * (t * q * e - off**2 * t * k)
    normal = s / (2 * rs) * (q / t * k - t * e)
    beta01 = sixth * (-off * (r**2 + 2 * s**2) * k - t * (r**2 - 2 * s**2) * e)
    beta10 = sixth * (off * (2 * r**2 + s**2) * k + t * (2 * r**2 - s**2) * e)
    beta11 = 2 * sixth * ((q**2 - rs**2) / t * k - t * q * e)
    return cos2, sin2, normal, sin2, beta01, beta10, beta11


@njit(cache=True)
def _trapezoid_entries(radius, off, cosines, weights):
    """The same integrals as :func:`_elliptic_entries` by the periodic trapezoidal rule over
    psi at the points of cos psi = ``cosines`` (min(R, S)/max(R, S) < 1/4: the integrand is
    analytic and smooth in psi): (S/4) (cos^2, sin^2, cos) / rho and the d d/rho^3 parts
    (along across cos, R along sin^2, -S across sin^2, R S sin^2 cos) / rho^3, d = (along,
    across) the offset along the field's and the ring's radial directions."""
    ring_radius = radius + off
    offset_squared, quarter_ring = off * off, ring_radius / 4
    cos2 = sin2 = normal = beta00 = beta01 = beta10 = beta11 = 0.0
    for j in range(len(cosines)):
        c = cosines[j]
        sine2 = 1.0 - c * c
        inverse = 1.0 / math.sqrt(offset_squared + 2 * radius * ring_radius * (1 - c))  # 1/rho
        w = weights[j] * quarter_ring * inverse
        along, across = radius - ring_radius * c, radius * c - ring_radius
        cos2 += w * c * c
        sin2 += w * sine2
        normal += w * c
        w3 = w * inverse * inverse
        beta00 += w3 * along * across * c
        beta01 += w3 * radius * along * sine2
        beta10 += w3 * -ring_radius * across * sine2
        beta11 += w3 * radius * ring_radius * sine2 * c
    return cos2, sin2, normal, beta00, beta01, beta10, beta11


def _expanded(nonzero: np.ndarray) -> np.ndarray:
    """(3, 3, 3, ...) [part, displacement, load] from the stacked _NONZERO entries."""
    parts = np.zeros((3, 3, 3) + nonzero.shape[1:])
    for row, index in enumerate(_NONZERO):
        parts[index] = nonzero[row]
    return parts


def ring_kernel_parts(radius, offset) -> np.ndarray:
    """(k0, k_beta, k_gamma) of the module docstring at S = R + offset: shape (3, 3, 3, ...)
    as [part, displacement (U_r, U_phi, U_z), load (A, B, Z)], broadcast over ``radius`` and
    ``offset`` (R >= 0 and S > 0 by sqrt(a x0), or any common length). The offset is carried
    separately so that S next to R keeps its full relative accuracy. Unit: displacement per unit
    traction, by 4 (1 - nu^2)/(pi E) (a length: k is per unit S)."""
    return _expanded(_nonzero_parts(radius, offset))


def ring_kernel(radius, offset, poisson: float) -> np.ndarray:
    """k = k0 + beta k_beta + gamma k_gamma (module docstring) at S = R + offset for Poisson
    ratio ``poisson``: shape (3, 3, ...) [displacement (U_r, U_phi, U_z), load (A, B, Z)], by
    4 (1 - nu^2)/(pi E)."""
    nu = _poisson("poisson", poisson)
    return np.tensordot(_nu_weights(nu), ring_kernel_parts(radius, offset), axes=1)


def _nu_weights(nu):
    """(1, beta, gamma) of the module docstring."""
    return np.array([1.0, nu / (1 - nu), (1 - 2 * nu) / (2 * (1 - nu))])


def _stacked(blocks):
    """(..., 3, 3, N, N) nodal blocks -> (..., 3N, 3N) with rows (U_r, U_phi, U_z) and
    columns (A, B, Z)."""
    *lead, _, _, n, _ = blocks.shape
    return np.swapaxes(blocks, -3, -2).reshape(*lead, 3 * n, 3 * n)


def response_parts(radii) -> np.ndarray:
    """(3, 3N, 3N): the parts (k0, k_beta, k_gamma) of :func:`surface_response`, which is
    their sum weighted by (1, beta, gamma) (module docstring). They depend on the grid alone
    and are kept, read-only (:func:`ehdfem.solids.halfspace.kept_on_grid`)."""
    r = film_nodes(radii)
    return kept_on_grid(
        "mode one", r, lambda: _stacked(_expanded(hat_integrals(r, _nonzero_parts, len(_NONZERO))))
    )


def surface_response(radii, poisson: float) -> np.ndarray:
    """(3N, 3N) response of ONE lower half-space at the nodes ``radii`` (by sqrt(a x0), or any
    length unit L; from 0, increasing): stacked nodal amplitudes (A, B, Z) of the mode-1
    traction (t_r, t_phi, t_z) = (A cos phi, -B sin phi, Z cos phi) (hat functions, zero beyond
    the last node; traction unit sigma) -> stacked nodal (U_r, U_phi, U_z) of (u_r, u_phi, u_z)
    = (U_r cos phi, -U_phi sin phi, U_z cos phi), z out of the solid, in units of
    4 (1 - nu^2)/(pi E) sigma L. In these units the axisymmetric analogue of the Z -> U_z block
    is -:func:`ehdfem.solids.halfspace.influence_matrix` (t_z = -P)."""
    nu = _poisson("poisson", poisson)
    return np.tensordot(_nu_weights(nu), response_parts(radii), axes=1)


class HalfSpaceModeOne(ModeOneCompliance):
    """Sphere and wall as elastic half-spaces under the film's mode-1 loads (the contract of
    :class:`ehdfem.solids.compliance.ModeOneCompliance`).

    The wall is the lower half-space of :func:`surface_response` (loads Z = -q, A, B); the
    sphere its mirror image z -> -z, which turns its traction t_z = +q into Z = -q and its
    displacement U_z into -U_z, tangential components unchanged. Solid i takes the share
    ((1 - nu_i^2)/E_i) / sum((1 - nu^2)/E) of the unit eps (its part of theta), the shear loads
    carry sqrt(delta) (their unit), so the gap opening U_z(sphere) - U_z(wall) per unit q is the
    nu-independent Z -> U_z block times eps. Displacements are relative to the far material
    of each half-space.

    ``radii``: film nodes (by sqrt(a x0)), from 0, strictly increasing, at least 3. ``eps``:
    4 theta mu V0 a^(3/2) / x0^(5/2) (>= 0). ``delta``: x0/a in (0, 1). ``solids``: (Young's
    modulus, Poisson ratio) of sphere and wall (moduli in any common unit).
    """

    model = "halfspace"

    def __init__(self, radii, eps: float, delta: float, solids=IDENTICAL_SOLIDS):
        radii = film_nodes(radii)
        delta = number("delta", delta, lower=0.0, upper=1.0, lower_open=True, upper_open=True)
        if len(solids) != 2:
            raise InputError("solids must be two (Young's modulus, Poisson ratio) pairs")
        moduli = [positive(f"{name} Young's modulus", e) for name, (e, _) in _named(solids)]
        ratios = [_poisson(f"{name} Poisson ratio", nu) for name, (_, nu) in _named(solids)]
        shares = theta_shares(tuple(zip(moduli, ratios, strict=True)))
        parts = response_parts(radii)
        n = len(radii)
        unit = np.zeros((6 * n, 5 * n))
        for face, (nu, share) in enumerate(zip(ratios, shares, strict=True)):
            response = share * np.tensordot(_nu_weights(nu), parts, axes=1)
            if face == 0:  # the sphere: mirror image, u_z -> -u_z
                response[2 * n :] *= -1.0
            rows = slice(3 * n * face, 3 * n * (face + 1))
            unit[rows, :n] = -response[:, 2 * n :]  # pressure q: Z = -q on both faces
            # the face's own (radial, hoop) loads are (A, B), by sqrt(delta) mu V0 a / x0^2
            unit[rows, n * (1 + 2 * face) : n * (3 + 2 * face)] = (
                np.sqrt(delta) * response[:, : 2 * n]
            )
        self.delta, self.solids = delta, tuple(zip(moduli, ratios, strict=True))
        super().__init__(radii, unit, number("eps", eps, lower=0.0))

    def factor(self, eps: float) -> float:
        """The unit matrix is per unit eps: C = eps * unit_matrix."""
        return number("eps", eps, lower=0.0)


def _named(solids):
    return zip(("sphere", "wall"), solids, strict=True)


def _poisson(name, nu):
    return number(name, nu, **MATERIAL_RANGES["poisson_ratio"])
