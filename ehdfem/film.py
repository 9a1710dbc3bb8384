"""Axisymmetric Reynolds lubrication film: discretisation, wetted edge, sliding integrals.

All quantities are scaled (DSH 1986): radius R by sqrt(a x0), film thickness H by x0, pressure P
by mu V0 a / x0^2, time T by x0 / V0. The film obeys

    dH/dT = (1 / (12 R)) d/dR (R H^3 dP/dR),        0 < R < R_edge,
    dP/dR = 0 at R = 0,    P >= P_cav (cavitation),

with P = 0 at the wetted edge R_edge where H = 1 (thin layer), or, fully immersed, the far-field
condition P ~ H^-2 (exact for the rigid-sphere solution P = -3 V / H^2) at the last node.

Cavitation (the lower limit P_cav of the pressure and the liquid in a cavity) is a separate
part, :mod:`ehdfem.cavitation`; the film supplies the pieces it works on.

With a pressure-dependent viscosity mu(P) (:mod:`ehdfem.viscosity`) H^3 becomes H^3 mu0/mu(P).

Discretisation: continuous piecewise-linear (P1) finite elements in R with the weight R, the
lumped mass m_i = int phi_i R dR and element conductances from 3-point Gauss quadrature of
int R H^3 mu0 / (12 mu) dR with H linear on the element (exact for that H and constant mu).
The thin-layer edge is cut into its element (the element is shortened to end at R_edge, where
P = 0 and H = 1), so the edge moves continuously rather than node by node. The film does not
know about time stepping: it assembles, for a given film thickness H and pressure P, the
weak-form pieces

    m_i d(theta_i H_i)/dT + (K(H, P) P)_i = 0     (wet nodes; theta = 1 unless mass-conserving)

plus the derivatives D = d(K P)/dH and E = d(K P)/dP - K (piezoviscosity), the dry nodes and
the force.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.linalg

from . import checks
from .gap import Paraboloid
from .viscosity import Viscosity

LAYERS = ("thin", "immersed")

# 3-point Gauss-Legendre on [0, 1]: integrates R H^3 exactly for linear R and H.
_GAUSS_XI = 0.5 + 0.5 * np.array([-np.sqrt(0.6), 0.0, np.sqrt(0.6)])
_GAUSS_W = np.array([5.0, 8.0, 5.0]) / 18.0


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


def _ascending_mass(left, right):
    """int over [left, right] of the hat that rises from 0 to 1, times R."""
    return (right - left) * (left + 2.0 * right) / 6.0


def _descending_mass(left, right):
    """int over [left, right] of the hat that falls from 1 to 0, times R."""
    return (right - left) * (2.0 * left + right) / 6.0


@dataclass
class _Elements:
    left: np.ndarray  # left node of each wetted element
    right: np.ndarray  # right node, -1 for an element cut at the wetted edge
    length: np.ndarray
    gauss_r: np.ndarray  # (elements, 3) Gauss radii
    h_left: np.ndarray
    h_right: np.ndarray  # 1 at the wetted edge


@dataclass
class FilmState:
    """The assembled film for one pressure and film-thickness iterate (scaled units).

    ``mass``: lumped m_i; ``conductance`` (lower, diagonal, upper) of K(H); ``dflux_dH`` the
    tridiagonal D = d(K P)/dH; ``dflux_dP`` the tridiagonal d(K P)/dP - K from the
    pressure-dependent viscosity (zero bands at constant viscosity); ``force_weights`` f with
    St dV/dT = f . P; ``dry`` nodes hold P = 0 (outside the wetted edge); ``edge_radius`` is
    R_edge (inf when fully immersed).
    """

    mass: np.ndarray
    conductance: tuple[np.ndarray, np.ndarray, np.ndarray]
    dflux_dH: tuple[np.ndarray, np.ndarray, np.ndarray]
    dflux_dP: tuple[np.ndarray, np.ndarray, np.ndarray]
    force_weights: np.ndarray
    dry: np.ndarray
    edge_radius: float

    def flux(self, pressure: np.ndarray) -> np.ndarray:
        """(K(H) P)_i, the net outward lubrication flux from node i (times 2 pi, scaled)."""
        return tridiagonal_product(self.conductance, pressure)


def tridiagonal_product(bands, vector):
    """(lower, diagonal, upper) band matrix times a vector; lower[0] and upper[-1] unused."""
    lower, diagonal, upper = bands
    out = diagonal * vector
    out[1:] += lower[1:] * vector[:-1]
    out[:-1] += upper[:-1] * vector[1:]
    return out


class Film:
    """Reynolds film on the radial nodes ``radii`` (scaled by sqrt(a x0)).

    ``layer``: "thin" (P = 0 at the wetted edge where H = 1) or "immersed" (far-field condition
    P ~ H^-2 at the last node). ``viscosity``: a :class:`ehdfem.viscosity.Viscosity` (default
    constant). ``gap``: the undeformed gap S(R) of :mod:`ehdfem.gap` (default the paraboloid
    R^2/2), kept exactly between the nodes; the immersed far field assumes the paraboloid.
    """

    def __init__(
        self,
        radii: np.ndarray,
        layer: str = "thin",
        viscosity: Viscosity | None = None,
        gap: Paraboloid | None = None,
    ):
        self.radii = np.asarray(radii, dtype=float)
        self.layer = checks.choice("layer", layer, LAYERS)
        self.viscosity = viscosity or Viscosity()
        self.gap = gap or Paraboloid()
        if self.layer == "immersed" and self.gap.name != "paraboloid":
            raise checks.InputError(
                f"gap = {self.gap.name!r} needs the thin layer: the immersed film reaches "
                "beyond the sphere and its far-field closure assumes the paraboloid"
            )
        left, right = self.radii[:-1], self.radii[1:]
        self._length = right - left
        self._full_mass = np.zeros_like(self.radii)
        self._full_mass[:-1] += _descending_mass(left, right)
        self._full_mass[1:] += _ascending_mass(left, right)

    @property
    def full_mass(self) -> np.ndarray:
        """m_i = int phi_i R dR over the whole grid (used for energies and forces)."""
        return self._full_mass

    def wetted_edge(self, film_thickness: np.ndarray) -> tuple[int, float]:
        """(number of wet nodes, R_edge) for the thin layer: R_edge is where H crosses 1.

        The crossing is interpolated linearly between the last node with H < 1 and the next;
        a node closer to the edge than 1e-3 of its cell is taken as dry (P = 0 there) so the
        cut element never degenerates.
        """
        n = len(self.radii)
        if self.layer == "immersed":
            return n, np.inf
        above = np.flatnonzero(film_thickness >= 1.0)
        if len(above) == 0:
            raise FilmError("the wetted edge left the film grid: enlarge outer_radius")
        first_dry = above[0]
        if first_dry == 0:
            return 0, 0.0
        k = first_dry - 1
        fraction = (1.0 - film_thickness[k]) / (film_thickness[first_dry] - film_thickness[k])
        edge = self.radii[k] + fraction * self._length[k]
        if fraction < 1e-3:
            return k, edge
        return first_dry, edge

    def _elements(self, film_thickness: np.ndarray):
        """(number of wet nodes, R_edge, the wetted elements). A thin layer's last element is
        cut at the edge: its ``right`` index is -1 and H = 1 there."""
        h = film_thickness
        n_wet, edge = self.wetted_edge(h)
        n_elem = max(n_wet - 1, 0)
        left = np.arange(n_elem + int(self.layer == "thin" and n_wet > 0))
        right = left + 1
        length = self._length[np.minimum(left, len(self._length) - 1)].copy()
        h_right = h[np.minimum(right, len(h) - 1)].copy()
        if len(left) > n_elem:  # the cut element
            right[-1] = -1
            length[-1] = edge - self.radii[left[-1]]
            h_right[-1] = 1.0
        gauss_r = self.radii[left, None] + length[:, None] * _GAUSS_XI
        return n_wet, edge, _Elements(left, right, length, gauss_r, h[left], h_right)

    def assemble(self, film_thickness: np.ndarray, pressure: np.ndarray) -> FilmState:
        """Assemble the film for thickness H and pressure P (both at the nodes, scaled)."""
        h = film_thickness
        n = len(self.radii)
        n_wet, edge, el = self._elements(h)
        lower, diagonal, upper = np.zeros(n), np.zeros(n), np.zeros(n)
        mass = np.zeros(n)
        regular = el.right >= 0
        p_left, p_right = pressure[el.left], np.where(regular, pressure[el.right], 0.0)
        k, dk_dh, dk_dp = _conductance(
            el.gauss_r, el.length, self._gauss_thickness(el), p_left, p_right, self.viscosity
        )
        diagonal[el.left] += k
        r_left = self.radii[el.left]
        mass[el.left] += _descending_mass(r_left, r_left + el.length)
        left, right = el.left[regular], el.right[regular]
        diagonal[right] += k[regular]
        upper[left] -= k[regular]
        lower[right] -= k[regular]
        mass[right] += _ascending_mass(self.radii[left], self.radii[right])
        jump = p_left - p_right
        dflux_dH = _derivative_bands(n, el, regular, dk_dh, jump)
        dflux_dP = _derivative_bands(n, el, regular, dk_dp, jump)
        force_weights = mass / 3.0
        if self.layer == "immersed":
            self._add_far_field(h, pressure, diagonal, dflux_dH[1], force_weights)
        dry = np.arange(n) >= n_wet
        return FilmState(
            mass,
            (lower, diagonal, upper),
            dflux_dH,
            dflux_dP,
            force_weights,
            dry,
            edge,
        )

    def _add_far_field(self, h, pressure, diagonal, d_diagonal, force_weights):
        """Robin condition R H^3/12 dP/dR = -R^2 H^2 P / 6 at the last node (P ~ H^-2, dH/dR = R)
        and the force of the pressure beyond it, (1/3) int_Rmax^inf P R dR = P_N H_N / 3."""
        r, hn = self.radii[-1], h[-1]
        diagonal[-1] += r**2 * hn**2 / 6.0
        d_diagonal[-1] += r**2 * hn / 3.0 * pressure[-1]
        force_weights[-1] += hn / 3.0

    def sliding_integrals(
        self, film_thickness: np.ndarray, outer_radius: float = np.inf, pressure=None, fill=None
    ):
        """(J, G, M): the film's resistance to a sliding and spinning sphere (scaled).

        J = int theta (mu/mu0) R dR / H is the Couette shear (a cavity shears only its liquid
        fraction theta; mu at the nodal ``pressure``, theta the nodal ``fill``, 1 if not given;
        tangential force -2 pi mu0 a u_s J). The sliding
        pressure is p = 6 mu U0 sqrt(a) x0^(-3/2) w Pi(R) cos(phi), with w = (U + a Omega)/U0 and
        Pi the azimuthal mode-1 solution of the Reynolds equation on the deformed film,

            (1/R) (R H^3 Pi')' - H^3 Pi / R^2 = -dH/dR,   Pi(0) = 0, Pi = 0 at the edge,

        (P1 elements, weak form int R H^3 Pi' v' + int H^3 Pi v / R = int H' v R; H^3 stands
        for H^3 mu0/mu with the viscosity at the nodal ``pressure``, mu0 if not given). It adds
        G = (3/2) int Pi H' R dR to the force and M = int Pi R^2 dR to the torque. Thin layer: up
        to the wetted edge. Immersed: up to ``outer_radius`` (the sphere radius, 1/sqrt(delta),
        caps the logarithmic far field); beyond the last node the film is taken as the
        undeformed X + R^2/2, where J, G and M grow as ln H, (3/5) ln H and (2/5) ln H.
        """
        h = film_thickness
        n = len(h)
        _, _, el = self._elements(h)
        inside = self.radii[el.left] < outer_radius
        el = _Elements(*(getattr(el, name)[inside] for name in _Elements.__dataclass_fields__))
        thickness = self._gauss_thickness(el)
        regular = el.right >= 0
        right = np.where(regular, el.right, 0)

        def gauss(nodal, edge_value):
            if nodal is None:
                return np.ones_like(thickness)
            return _gauss_values(nodal[el.left], np.where(regular, nodal[right], edge_value))

        viscosity = self.viscosity.ratio(gauss(pressure, 0.0))[0]
        liquid = gauss(fill, 1.0)
        slope = ((el.h_right - el.h_left) / el.length)[:, None] + self.gap.slope_between_nodes(
            self.radii[el.left], el.length, _GAUSS_XI
        )
        weight = el.length[:, None] * _GAUSS_W
        phi_left, phi_right = 1.0 - _GAUSS_XI, _GAUSS_XI
        cube = thickness**3 / viscosity
        stiff = (weight * el.gauss_r * cube).sum(axis=1) / el.length**2
        hoop = [
            (weight * cube * a * b / el.gauss_r).sum(axis=1)
            for a, b in ((phi_left, phi_left), (phi_left, phi_right), (phi_right, phi_right))
        ]
        source = weight * slope * el.gauss_r
        diagonal, lower, upper, rhs = np.zeros(n), np.zeros(n), np.zeros(n), np.zeros(n)
        diagonal[el.left] += stiff + hoop[0]
        rhs[el.left] += (source * phi_left).sum(axis=1)
        left, right = el.left[regular], el.right[regular]
        diagonal[right] += (stiff + hoop[2])[regular]
        upper[left] += (hoop[1] - stiff)[regular]
        lower[right] += (hoop[1] - stiff)[regular]
        rhs[right] += (source * phi_right).sum(axis=1)[regular]
        fixed = np.ones(n, bool)  # Pi = 0 on the axis, at dry nodes and at the immersed end
        fixed[el.left[1:]] = False
        if self.layer == "immersed" and len(el.left):
            fixed[el.right[-1]] = True
        diagonal[fixed], lower[fixed], upper[fixed], rhs[fixed] = 1.0, 0.0, 0.0, 0.0
        pi = _solve_tridiagonal(lower, diagonal, upper, rhs)
        pi_gauss = (
            pi[el.left, None] * phi_left + np.where(regular, pi[el.right], 0.0)[:, None] * phi_right
        )
        shear = float((weight * el.gauss_r * liquid * viscosity / thickness).sum())
        force = 1.5 * float((weight * pi_gauss * slope * el.gauss_r).sum())
        torque = float((weight * pi_gauss * el.gauss_r**2).sum())
        r_last = self.radii[-1]
        if self.layer == "immersed" and outer_radius > r_last:
            gap = h[-1] - 0.5 * r_last**2
            tail = np.log((gap + 0.5 * outer_radius**2) / h[-1])
            shear, force, torque = shear + tail, force + 0.6 * tail, torque + 0.4 * tail
        return shear, force, torque

    def squeeze_shear(self, film_thickness: np.ndarray, pressure: np.ndarray) -> np.ndarray:
        """T at the nodes: the radial shear traction -(H/2) dP/dR that the pressure-driven flow
        exerts on each of the two surfaces, in the flow direction (by sqrt(delta) mu V0 a /
        x0^2; positive outward). Each wetted element carries T = -(H/2) s with its own slope s
        (the cut element up to the wetted edge, where P = 0); the nodal values are its lumped
        projection, T_j = int phi_j T R dR / int phi_j R dR over the whole grid, so a node the
        edge leaves keeps the share its part of the film gives it, and T moves continuously
        with the edge."""
        _, _, el = self._elements(film_thickness)
        regular = el.right >= 0
        right = np.where(regular, el.right, 0)
        slope = (np.where(regular, pressure[right], 0.0) - pressure[el.left]) / el.length
        traction = -0.5 * self._gauss_thickness(el) * slope[:, None]
        # the grid's hats at the Gauss points (a cut element lies inside its full cell)
        full = self._length[np.minimum(el.left, len(self._length) - 1)]
        rising = (el.gauss_r - self.radii[el.left, None]) / full[:, None]
        weight = el.length[:, None] * _GAUSS_W * el.gauss_r * traction
        load = np.zeros_like(pressure)
        np.add.at(load, el.left, (weight * (1.0 - rising)).sum(axis=1))
        np.add.at(load, np.minimum(el.left + 1, len(load) - 1), (weight * rising).sum(axis=1))
        return load / self._full_mass

    def _gauss_thickness(self, el: _Elements):
        """H at the Gauss points of the elements: the undeformed gap S is kept exactly between
        the nodes, H = X + S + W with only W linear (the linear interpolant of H plus S minus
        its own interpolant)."""
        between = self.gap.between_nodes(self.radii[el.left], el.length, _GAUSS_XI)
        return el.h_left[:, None] * (1.0 - _GAUSS_XI) + el.h_right[:, None] * _GAUSS_XI + between

    def dissipation_rate(self, state: FilmState, pressure: np.ndarray) -> float:
        """Viscous dissipation (1/3) int H^3 (dP/dR)^2 R dR / 12 = (1/3) P.K(H)P, in units of
        m V0^2 per (x0/V0) divided by St (the same units as St d(V^2/2)/dT)."""
        return float(pressure @ state.flux(pressure)) / 3.0


def _solve_tridiagonal(lower, diagonal, upper, rhs):
    """Solve the band system with lower[i] = A[i, i-1] and upper[i] = A[i, i+1]."""
    bands = np.zeros((3, len(rhs)))
    bands[0, 1:] = upper[:-1]
    bands[1] = diagonal
    bands[2, :-1] = lower[1:]
    return scipy.linalg.solve_banded((1, 1), bands, rhs)


def _gauss_values(left, right):
    """A linear nodal field at the Gauss points of elements, (elements, 3)."""
    return left[:, None] * (1.0 - _GAUSS_XI) + right[:, None] * _GAUSS_XI


def _conductance(gauss_r, length, h, p_left, p_right, viscosity: Viscosity):
    """Element conductance k = (1/(12 L^2)) int R H^3 mu0/mu(P) dR (H at the Gauss points, P
    linear on the element) and its derivatives ((dk/dH_left, dk/dH_right), (dk/dP_left,
    dk/dP_right)) by the nodal values."""
    scale = 1.0 / (12.0 * length)
    weight = _GAUSS_W * gauss_r * scale[:, None]
    if viscosity.constant:
        fluidity, dlog = 1.0, None
    else:
        ratio, dlog = viscosity.ratio(_gauss_values(p_left, p_right))
        if not np.isfinite(ratio).all():  # mu = inf would let a node carry any pressure
            raise FilmError("the viscosity overflows (mu/mu0 > 1e308): pressure iterate too high")
        fluidity = 1.0 / ratio
    k = (weight * h**3 * fluidity).sum(axis=1)
    dh = weight * 3.0 * h**2 * fluidity
    dk_dh = ((dh * (1.0 - _GAUSS_XI)).sum(axis=1), (dh * _GAUSS_XI).sum(axis=1))
    if dlog is None:
        return k, dk_dh, None
    dp = -weight * h**3 * fluidity * dlog
    return k, dk_dh, ((dp * (1.0 - _GAUSS_XI)).sum(axis=1), (dp * _GAUSS_XI).sum(axis=1))


def _derivative_bands(n, el: _Elements, regular, dk, jump):
    """Tridiagonal bands of sum_e (dk_e/dy) (P_left - P_right) for the element conductances'
    derivatives dk = (dk/dy_left, dk/dy_right) by a nodal field y (H, or P for the viscosity;
    None: zero bands). The cut element's right end is the edge, which is no unknown."""
    lower, diagonal, upper = np.zeros(n), np.zeros(n), np.zeros(n)
    if dk is None:
        return lower, diagonal, upper
    dk_left, dk_right = dk
    diagonal[el.left] += dk_left * jump
    left, right = el.left[regular], el.right[regular]
    dk_left, dk_right, jump = dk_left[regular], dk_right[regular], jump[regular]
    upper[left] += dk_right * jump
    lower[right] -= dk_left * jump
    diagonal[right] -= dk_right * jump
    return lower, diagonal, upper


class FilmError(RuntimeError):
    """The film cannot be assembled (e.g. the wetted edge ran off the grid)."""
