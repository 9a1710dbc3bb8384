"""Axisymmetric Reynolds lubrication film: discretisation, wetted edge, sliding integrals.

All quantities are scaled (DSH 1986): radius R by sqrt(a x0), film thickness H by x0, pressure P
by mu V0 a / x0^2, time T by x0 / V0. The film obeys

    dH/dT = (1 / (12 R)) d/dR (R H^3 dP/dR),        0 < R < R_edge,
    dP/dR = 0 at R = 0,    P >= P_cav (cavitation),

with P = 0 at the wetted edge R_edge where H = 1 (thin layer), or, fully immersed, the far-field
condition P ~ H^-2 (exact for the rigid-sphere solution P = -3 V / H^2) at the last node.

Cavitation (the lower limit P_cav of the pressure and the liquid in a cavity) is a separate
part, :mod:`ehdfem.film.cavitation`; the film supplies the pieces it works on.

With a pressure-dependent viscosity mu(P) (:mod:`ehdfem.film.viscosity`) H^3 becomes H^3 mu0/mu(P).

Discretisation: continuous piecewise-linear (P1) elements in R with the weight R, the lumped
mass m_i = int phi_i R dR and element conductances k_e = <mu0/mu> A_e^2 / int_e 3 R^3/H^3 dR,
A_e the flux through the element of a uniform unit squeeze (the masses up to its left node)
and <mu0/mu> the element's mean fluidity over P linear on it: the discrete dissipation P.K P
and force (1/3) m.P are exact for the rigid film P = 3|V|/H^2 at every gap and on every grid,
where the P1 Galerkin conductance (1/(12 L^2)) int R H^3 mu0/mu dR, which k_e equals to
leading order in L, fell short of the force by about 0.9 (L/R)^2.
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

from .. import checks
from ..kept import Kept
from .elements import assemble_bands, squeeze_shear_load, surface_transport_bands
from .gap import Paraboloid
from .viscosity import ConstantViscosity, ViscosityLaw

LAYERS = ("thin", "immersed")

# 3-point Gauss-Legendre on [0, 1]: integrates R H^3 exactly for linear R and H.
_GAUSS_XI = 0.5 + 0.5 * np.array([-np.sqrt(0.6), 0.0, np.sqrt(0.6)])
_GAUSS_W = np.array([5.0, 8.0, 5.0]) / 18.0
# 6-point Gauss-Legendre on [0, 1] for the conductance's int R^3 / H^3 dR: 1e-3 where H changes
# five-fold over an element, 1e-7 where it doubles.
_FLUX_XI, _FLUX_W = np.polynomial.legendre.leggauss(6)
_FLUX_XI, _FLUX_W = 0.5 + 0.5 * _FLUX_XI, 0.5 * _FLUX_W
_POINTS = {"gauss": _GAUSS_XI, "flux": _FLUX_XI}  # the film's quadrature points, by name
_CONSTANT = tuple(np.zeros(0) for _ in range(3))  # no element fluidities: constant viscosity


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
    transport: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None

    def flux_slope(self) -> np.ndarray:
        """d(K P)_i/dP_i = K_ii + E_ii, a node's flux against its own pressure (the sum of its
        elements' Newtonian conductances times mu0/mu(P_i); K_ii at constant viscosity)."""
        return self.conductance[1] + self.dflux_dP[1]

    def flux(self, pressure: np.ndarray) -> np.ndarray:
        """(K(H) P)_i, the net outward lubrication flux from node i (times 2 pi, scaled)."""
        return tridiagonal_product(self.conductance, pressure)

    def surface_flux(self, surface_velocity: np.ndarray) -> np.ndarray:
        """(B U_t)_i, the net outward flux from node i of the liquid the surfaces carry at their
        mean radial velocity U_t (by V0; :meth:`Film.surface_transport`, held in ``transport``),
        to be multiplied by sqrt(delta)."""
        return tridiagonal_product(self.transport, surface_velocity)

    def surface_flux_weights(self, pressure: np.ndarray) -> np.ndarray:
        """w = B^T P, so that w . v = P . (B v) (zero without ``transport``)."""
        if self.transport is None:
            return np.zeros_like(pressure)
        lower, diagonal, upper = self.transport
        return tridiagonal_product((np.roll(upper, 1), diagonal, np.roll(lower, -1)), pressure)


def tridiagonal_product(bands, vector):
    """(lower, diagonal, upper) band matrix times a vector; lower[0] and upper[-1] unused."""
    lower, diagonal, upper = bands
    out = diagonal * vector
    out[1:] += lower[1:] * vector[:-1]
    out[:-1] += upper[:-1] * vector[1:]
    return out


def _node_sums(nodes, values, n: int) -> np.ndarray:
    """The sums of ``values`` over each node index of ``nodes`` (n nodes; repeated indices
    add), as np.add.at but in one pass."""
    return np.bincount(nodes, weights=values, minlength=n)


def _hat_weights(el: _Elements, values: np.ndarray, n: int) -> np.ndarray:
    """w with w . f = int f g R dR over the elements, for a nodal (P1) f that is 0 at a cut
    edge and g given at the elements' Gauss points, ``values`` (elements, 3)."""
    regular = el.right >= 0
    weight = el.length[:, None] * _GAUSS_W * el.gauss_r * values
    out = np.zeros(n)
    out += _node_sums(el.left, (weight * (1.0 - _GAUSS_XI)).sum(axis=1), len(out))
    out += _node_sums(el.right[regular], (weight * _GAUSS_XI).sum(axis=1)[regular], len(out))
    return out


def _at_gauss_points(el: _Elements, nodal, edge_value: float) -> np.ndarray:
    """A nodal field, linear on the elements, at their Gauss points (elements, 3); at a cut
    element's edge it takes ``edge_value``, and everywhere if ``nodal`` is None."""
    if nodal is None:
        return np.full(el.gauss_r.shape, float(edge_value))
    regular = el.right >= 0
    right = np.where(regular, nodal[np.where(regular, el.right, 0)], edge_value)
    return _gauss_values(nodal[el.left], right)


def _cell_hat_weights(el: _Elements, radii: np.ndarray, values: np.ndarray) -> np.ndarray:
    """w with w . f = int f g R dR over the wetted elements, for f linear on the grid's cells
    (a cut element keeps the hats of its full cell, so f need not vanish at the wetted edge)
    and g given at the elements' Gauss points, ``values`` (elements, 3)."""
    full = np.diff(radii)[np.minimum(el.left, len(radii) - 2)]
    rising = (el.gauss_r - radii[el.left, None]) / full[:, None]
    weight = el.length[:, None] * _GAUSS_W * el.gauss_r * values
    out = np.zeros(len(radii))
    out += _node_sums(el.left, (weight * (1.0 - rising)).sum(axis=1), len(out))
    out += _node_sums(
        np.minimum(el.left + 1, len(out) - 1), (weight * rising).sum(axis=1), len(out)
    )
    return out


class Film:
    """Reynolds film on the radial nodes ``radii`` (scaled by sqrt(a x0)).

    ``layer``: "thin" (P = 0 at the wetted edge where H = 1) or "immersed" (far-field condition
    P ~ H^-2 at the last node). ``viscosity``: a law of :data:`ehdfem.film.viscosity.LAWS` (default
    constant). ``gap``: the undeformed gap S(R) of :mod:`ehdfem.film.gap` (default the paraboloid
    R^2/2), kept exactly between the nodes; the immersed far field assumes the paraboloid.
    ``undeformed``: S at the nodes (by x0).
    """

    def __init__(
        self,
        radii: np.ndarray,
        layer: str = "thin",
        viscosity: ViscosityLaw | None = None,
        gap: Paraboloid | None = None,
    ):
        self.radii = np.asarray(radii, dtype=float)
        self.layer = checks.choice("layer", layer, LAYERS)
        self.viscosity = viscosity or ConstantViscosity()
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
        self._kept_elements = Kept(2)  # the wetted elements of the two latest H
        self._kept_edges = Kept(2)  # (wet nodes, R_edge) of the two latest H
        # S at the nodes, and S minus its chord at the quadrature points of the whole cells (a
        # gap that has no value at a node, as a true sphere beyond its equator, refuses the
        # grid here)
        self.undeformed = self.gap.height(self.radii)
        # each cell's (left radius, length, S at its left, S's chord slope) as Python floats,
        # for the wetted edge's scalar Newton (numpy's scalars cost more than its arithmetic)
        chords = np.diff(self.undeformed) / self._length
        self._cells = list(
            zip(
                *(a.tolist() for a in (left, self._length, self.undeformed[:-1], chords)),
                strict=True,
            )
        )
        self._cell_between = {
            name: self.gap.between_nodes(left, self._length, xi) for name, xi in _POINTS.items()
        }

    @property
    def full_mass(self) -> np.ndarray:
        """m_i = int phi_i R dR over the whole grid (used for energies and forces)."""
        return self._full_mass

    def wetted_edge(self, film_thickness: np.ndarray) -> tuple[int, float]:
        """(number of wet nodes, R_edge) for the thin layer: R_edge is where H crosses 1.

        The crossing is found on the element's H between the last node with H < 1 and the
        next, W linear and the undeformed gap S exact (as in the conductances: a rigid film's
        edge is exact); a node closer to the edge than 1e-3 of its cell is taken as dry (P = 0
        there) so the cut element never degenerates. Kept for the two latest H (an iterate's
        film, its surface transport and its shear traction ask for the same one or two).
        """
        n = len(self.radii)
        if self.layer == "immersed":
            return n, np.inf
        return self._kept_edges.get(lambda: self._wetted_edge(film_thickness), film_thickness)

    def _wetted_edge(self, film_thickness: np.ndarray) -> tuple[int, float]:
        """:meth:`wetted_edge`, computed."""
        first_dry = int((film_thickness >= 1.0).argmax())
        if not film_thickness[first_dry] >= 1.0:
            raise FilmError("the wetted edge left the film grid: enlarge outer_radius")
        if first_dry == 0:
            return 0, 0.0
        k = first_dry - 1
        fraction = self._edge_fraction(k, float(film_thickness[k]), float(film_thickness[k + 1]))
        edge = self._cells[k][0] + fraction * self._cells[k][1]
        if fraction < 1e-3:
            return k, edge
        return first_dry, edge

    def _edge_fraction(self, k: int, h_left: float, h_right: float) -> float:
        """xi in [0, 1] where H = h_left (1 - xi) + h_right xi + (S - its chord) = 1 on element
        k (h_left < 1 <= h_right): Newton from the linear crossing, which lies left of the root
        (S lies below its chord) on a convex H, so the iterates bracket it after one step."""
        left, length, s_left, chord = self._cells[k]
        xi = (1.0 - h_left) / (h_right - h_left)
        for _ in range(6):
            height, gap_slope = self.gap.profile(left + xi * length)
            excess = h_left + (h_right - h_left) * xi - 1.0
            excess += float(height) - s_left - chord * xi * length
            slope = h_right - h_left + length * (float(gap_slope) - chord)
            if slope <= 0.0:
                break
            previous, xi = xi, min(max(xi - excess / slope, 0.0), 1.0)
            if abs(xi - previous) <= 1e-15:
                break
        return xi

    def _elements(self, film_thickness: np.ndarray):
        """(number of wet nodes, R_edge, the wetted elements). A thin layer's last element is
        cut at the edge: its ``right`` index is -1 and H = 1 there. Kept for the two latest H
        (an iterate's film and its surface transport ask for the same, and its shear traction
        for the film without the shear's opening)."""
        return self._kept_elements.get(lambda: self._cut_elements(film_thickness), film_thickness)

    def _cut_elements(self, film_thickness: np.ndarray):
        """:meth:`_elements`, computed."""
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
        """Assemble the film for thickness H and pressure P (both at the nodes, scaled): the
        element loop is :func:`ehdfem.film.elements.assemble_bands`; the viscosity law gives
        each element's mean fluidity (:meth:`_fluidity`)."""
        h = film_thickness
        n = len(self.radii)
        (n_wet, edge), regular, cut_length, cut_between = self._wetted(h, "flux")
        fluidity = _CONSTANT
        if not self.viscosity.constant:
            fluidity = self._fluidity(pressure, regular, cut_length > 0.0)
        mass, conductance, dflux_dH, dflux_dP = assemble_bands(
            self.radii,
            h,
            pressure,
            regular,
            cut_length,
            cut_between,
            self._cell_between["flux"],
            *fluidity,
            _FLUX_XI,
            _FLUX_W,
        )
        force_weights = mass / 3.0
        if self.layer == "immersed":
            self._add_far_field(h, pressure, conductance[1], dflux_dH[1], force_weights)
        dry = np.arange(n) >= n_wet
        return FilmState(mass, conductance, dflux_dH, dflux_dP, force_weights, dry, edge)

    def _wetted(self, film_thickness: np.ndarray, points: str):
        """((wet nodes, R_edge), the whole wetted cells, the cut element's length (0: none)
        and its undeformed gap's excess over its chord at the points ``points`` ("gauss" or
        "flux")): the wetted elements as the compiled loops of
        :mod:`ehdfem.film.elements` take them."""
        n_wet, edge = self.wetted_edge(film_thickness)
        regular = max(n_wet - 1, 0)
        if self.layer == "immersed" or n_wet == 0:
            return (n_wet, edge), regular, 0.0, np.zeros(0)
        cut_length = edge - self.radii[regular]
        left, length = self.radii[regular : regular + 1], np.array([cut_length])
        cut_between = self.gap.between_nodes(left, length, _POINTS[points])[0]
        return (n_wet, edge), regular, cut_length, cut_between

    def _fluidity(self, pressure, regular: int, cut: bool):
        """(<mu0/mu>, d<mu0/mu>/dP_left, d<mu0/mu>/dP_right) of the wetted elements (the whole
        cells 0..``regular``-1, then the ``cut`` one, whose edge holds P = 0): the mean
        fluidity over each element's linear P, <mu0/mu> = (Pi(P_r) - Pi(P_l)) / (P_r - P_l)
        with the reduced pressure Pi(P) = int_0^P mu0/mu dP' (mu0 under suction, the law's
        :meth:`fluidity_integral` above 0): the factor of an element that carries a constant
        flux, exact however steeply mu grows across the element (docs/model.md, "The element
        conductance"), and mu0/mu(P) where P_l = P_r. A nodal pressure whose mu/mu0
        overflows is refused (FilmError)."""
        p_left = pressure[: regular + int(cut)]
        p_right = np.concatenate([pressure[1 : regular + 1], np.zeros(int(cut))])
        ratio, dlog = self.viscosity.ratio(pressure[: regular + 1])
        if not np.isfinite(ratio).all():  # mu = inf would let a node carry any pressure
            raise FilmError(self.viscosity.overflow(pressure[: regular + 1]))
        fluidity = 1.0 / ratio
        slope = -fluidity * dlog
        f_left, f_right = fluidity[: len(p_left)], np.concatenate([fluidity[1:], np.ones(int(cut))])
        low, high = np.minimum(p_left, p_right), np.maximum(p_left, p_right)
        compressive = self.viscosity.fluidity_integral(np.maximum(low, 0.0), np.maximum(high, 0.0))
        integral = np.minimum(high, 0.0) - np.minimum(low, 0.0) + compressive
        span = high - low
        level = span == 0.0
        safe = np.where(level, 1.0, p_right - p_left)
        mean = np.where(level, f_left, integral / np.where(level, 1.0, span))
        half_slope = 0.5 * slope[: len(p_left)]
        d_left = np.where(level, half_slope, (mean - f_left) / safe)
        d_right = np.where(level, half_slope, (f_right - mean) / safe)
        return mean, d_left, d_right

    def _add_far_field(self, h, pressure, diagonal, d_diagonal, force_weights):
        """Robin condition R H^3/12 dP/dR = -R^2 H^2 P / 6 at the last node (P ~ H^-2, dH/dR = R)
        and the force of the pressure beyond it, (1/3) int_Rmax^inf P R dR = P_N H_N / 3."""
        r, hn = self.radii[-1], h[-1]
        diagonal[-1] += r**2 * hn**2 / 6.0
        d_diagonal[-1] += r**2 * hn / 3.0 * pressure[-1]
        force_weights[-1] += hn / 3.0

    def couette_weights(
        self, film_thickness: np.ndarray, outer_radius: float = np.inf, pressure=None, fill=None
    ) -> tuple[np.ndarray, float]:
        """(j, tail): the Couette weights j_i = int phi_i theta (mu/mu0) R dR / H0 over the
        wetted film inside ``outer_radius`` (phi_i the grid's hats), so that the Couette
        integral is J = sum(j) + tail, and the far-field ``tail`` (immersed only: ln of the
        undeformed film X + R^2/2 from the last node to ``outer_radius``; 0 for the thin
        layer). H0 by x0, the viscosity at the nodal ``pressure`` P0 (by mu V0 a / x0^2; mu0 if
        not given), theta the nodal ``fill`` (1 if not given)."""
        el = self._inner_elements(film_thickness, outer_radius)
        ratio = self.viscosity.ratio(_at_gauss_points(el, pressure, 0.0))[0]
        thickness = self._gauss_thickness(el)
        return self._couette_weights_on(el, thickness, ratio, film_thickness, outer_radius, fill)

    def _couette_weights_on(self, el, thickness, ratio, film_thickness, outer_radius, fill):
        """:meth:`couette_weights` on the elements ``el`` (:meth:`_inner_elements`), with H0
        and mu/mu0 at their Gauss points given (``thickness``, ``ratio``): the film's mode-1
        operators have them already."""
        liquid = _at_gauss_points(el, fill, 1.0)
        weights = _cell_hat_weights(el, self.radii, liquid * ratio / thickness)
        tail = 0.0
        h, r_last = film_thickness, self.radii[-1]
        if self.layer == "immersed" and outer_radius > r_last:
            gap = h[-1] - 0.5 * r_last**2
            tail = float(np.log((gap + 0.5 * outer_radius**2) / h[-1]))
        return weights, tail

    def _inner_elements(self, film_thickness: np.ndarray, outer_radius: float) -> _Elements:
        """The wetted elements that start inside ``outer_radius``: the integrals end at the
        first node at or beyond it, so a grid should have a node there (:func:`contact_grid`'s
        ``node_at``; an element across it would count whole and move the integral with the
        grid, about 1 % of the spin change at delta = 0.01 on the previous sinh grid)."""
        _, _, el = self._elements(film_thickness)
        inside = self.radii[el.left] < outer_radius
        return _Elements(*(getattr(el, name)[inside] for name in _Elements.__dataclass_fields__))

    def surface_transport(self, film_thickness: np.ndarray, fill=None) -> tuple:
        """Bands (lower, diagonal, upper) of B, (B v)_i = int phi_i d/dR (R theta H v) dR: the
        net outward flux from node i of the liquid that the surfaces carry at the nodal mean
        radial velocity v (P1 on the grid's cells, also on a cut element, whose dry right node
        keeps its velocity), by parts -int phi_i' R theta H v dR plus, at the immersed film's
        last node, the outflow R_N theta_N H_N v_N. H (by x0) at the Gauss points with the
        undeformed gap exact between nodes, as the conductance: exact for the paraboloid and
        linear theta; theta the nodal ``fill`` (1 if not given). Scaled: R by sqrt(a x0), v by
        V0; sqrt(delta) B v is in the units of the film's rows."""
        h = film_thickness
        liquid = np.ones_like(h) if fill is None else fill
        lower, diagonal, upper = surface_transport_bands(
            self.radii, h, liquid, *self._gauss_elements(h)
        )
        if self.layer == "immersed":
            diagonal[-1] += self.radii[-1] * liquid[-1] * h[-1]
        return lower, diagonal, upper

    def squeeze_shear(self, film_thickness: np.ndarray, pressure: np.ndarray) -> np.ndarray:
        """T at the nodes: the radial shear traction -(H/2) dP/dR that the pressure-driven flow
        exerts on each of the two surfaces, in the flow direction (by sqrt(delta) mu V0 a /
        x0^2; positive outward). Each wetted element carries T = -(H/2) s with its own slope s
        (the cut element up to the wetted edge, where P = 0); the nodal values are its lumped
        projection, T_j = int phi_j T R dR / int phi_j R dR over the whole grid, so a node the
        edge leaves keeps the share its part of the film gives it, and T moves continuously
        with the edge."""
        elements = self._gauss_elements(film_thickness)
        load = squeeze_shear_load(self.radii, film_thickness, pressure, *elements)
        return load / self._full_mass

    def _gauss_elements(self, film_thickness: np.ndarray) -> tuple:
        """The wetted elements at the Gauss points as the compiled loops take them: whole
        cells, the cut element's length and gap excess, the cells' gap excess, the points and
        their weights."""
        _, regular, cut_length, cut_between = self._wetted(film_thickness, "gauss")
        between = self._cell_between["gauss"]
        return regular, cut_length, cut_between, between, _GAUSS_XI, _GAUSS_W

    def _gauss_thickness(self, el: _Elements, points: str = "gauss"):
        """H at the quadrature points ``points`` of the elements ("gauss": _GAUSS_XI, "flux":
        _FLUX_XI): the undeformed gap S is kept exactly between the nodes, H = X + S + W with
        only W linear (the linear interpolant of H plus S minus its own interpolant); S minus
        its chord comes from the cells' table, but on a cut last element."""
        xi = _POINTS[points]
        between = self._cell_between[points][: len(el.left)]
        if len(el.left) and el.right[-1] < 0:
            between = between.copy()
            between[-1] = self.gap.between_nodes(self.radii[el.left[-1:]], el.length[-1:], xi)[0]
        return _gauss_values(el.h_left, el.h_right, xi) + between

    def dissipation_rate(self, state: FilmState, pressure: np.ndarray) -> float:
        """Viscous dissipation (1/3) int (mu0/mu) H^3 (dP/dR)^2 R dR / 12 = (1/3) P.K(H, P)P
        (each element's flux times its pressure drop, exact for an element that carries a
        constant flux), in units of m V0^2 per (x0/V0) divided by St (the same units as
        St d(V^2/2)/dT)."""
        return float(pressure @ state.flux(pressure)) / 3.0


def _gauss_values(left, right, xi=_GAUSS_XI):
    """A linear nodal field at the points ``xi`` (on [0, 1]) of elements, (elements, points)."""
    return left[:, None] * (1.0 - xi) + right[:, None] * xi


class FilmError(RuntimeError):
    """The film cannot be assembled (e.g. the wetted edge ran off the grid)."""
