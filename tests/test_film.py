"""The Reynolds film against exact rigid-sphere solutions.

For a rigid sphere approaching at speed V, H = X + R^2/2 and the quasi-steady film pressure is
P = -3 V (1/H^2 - 1) in a thin layer (P = 0 where H = 1) and P = -3 V / H^2 fully immersed, with
force F = (1/3) int P R dR = -V (1/X - 2 + X) and -V / X.
"""

import numpy as np
import pytest

from ehdfem import CollisionParameters, film_radii
from ehdfem.collision import film_extent
from ehdfem.exact import rigid_film
from ehdfem.film.grid import contact_grid, radial_grid
from ehdfem.film.reynolds import Film

pytestmark = pytest.mark.serial


def quasi_steady(film, gap, velocity):
    """Solve m V + K(H) P = 0 for P (dry nodes P = 0) on a rigid film at gap X, by the fluxes:
    the rows up to node i sum to k_i (P_i - P_i+1) = -V (m_0 + ... + m_i) (k_i the conductance
    of the element right of node i, K's upper band negated), and all the wet rows to k_end P_last
    = -V (m_0 + ... + m_last) (k_end the cut element's conductance or the immersed far field's
    Robin coefficient). Every term has one sign, so P is exact to rounding where an LU of K
    (condition number up to 1e6 on the immersed grids) lost 2e-10 of the force."""
    h = gap + film.gap.height(film.radii)
    state = film.assemble(h, np.zeros_like(h))
    lower, diagonal, upper = state.conductance
    last = np.flatnonzero(~state.dry)[-1]
    squeezed = -velocity * np.cumsum(state.mass[: last + 1])
    end = diagonal[last] + (lower[last] if last > 0 else 0.0)
    pressure = np.zeros_like(h)
    pressure[last] = squeezed[last] / end
    drops = squeezed[:last] / -upper[:last]
    pressure[:last] = pressure[last] + np.cumsum(drops[::-1])[::-1]
    return pressure, float(state.force_weights @ pressure), state


def test_edge_is_where_film_reaches_layer_thickness():
    """The edge is found on the element's H with the undeformed gap exact between the nodes:
    for a rigid sphere, X + R^2/2 = 1 to rounding (linear interpolation of H was 2e-3 off)."""
    film = Film(radial_grid(50, 0.3, 1.6), "thin")
    gap = 0.3
    n_wet, edge = film.wetted_edge(gap + 0.5 * film.radii**2)
    assert edge == pytest.approx(np.sqrt(2 * (1 - gap)), rel=1e-13)
    assert film.radii[n_wet - 1] < edge <= film.radii[n_wet]


@pytest.mark.parametrize("layer", ["thin", "immersed"])
def test_rigid_force_is_exact_on_any_grid(layer):
    """The quasi-steady rigid film's force equals -V (1/X - 2 + X) (thin) and -V / X
    (immersed) on coarse and fine grids alike, to rounding (1e-12): the element conductances
    make the dissipation, and so the force (1/3) m.P = (1/3) P.K P, exact for a uniform
    squeeze (ehdfem.film.reynolds). The P1 Galerkin conductance converged at second order
    (1.4e-3 off at 200 nodes)."""
    gap, velocity = 0.01, -1.0
    exact = -velocity * rigid_film.force_coefficient(gap, layer)
    outer = 1.5 if layer == "thin" else 30.0
    for n in (20, 50, 200):
        film = Film(radial_grid(n, np.sqrt(gap), outer), layer)
        _, force, _ = quasi_steady(film, gap, velocity)
        assert force / exact - 1 == pytest.approx(0.0, abs=1e-12), n


def test_rigid_pressure_profile_thin_layer():
    gap, velocity = 0.02, -0.7
    film = Film(radial_grid(200, np.sqrt(gap), 1.5), "thin")
    pressure, _, state = quasi_steady(film, gap, velocity)
    h = gap + 0.5 * film.radii**2
    exact = rigid_film.pressure(h, velocity, "thin")
    assert np.abs(pressure - exact).max() / exact.max() < 2e-3
    assert state.edge_radius == pytest.approx(np.sqrt(2 * (1 - gap)), rel=1e-3)


def test_dissipation_equals_work_of_the_film():
    """(1/3) P.K P equals -F V for the rigid quasi-steady film (power balance, exact for the
    discrete system because the force weights are the lumped masses / 3)."""
    film = Film(radial_grid(80, 0.2, 1.5), "thin")
    pressure, force, state = quasi_steady(film, 0.05, -0.5)
    assert film.dissipation_rate(state, pressure) == pytest.approx(-force * -0.5, rel=1e-12)


@pytest.mark.parametrize("rim, outer, node_at", [(0.42, 1.61, None), (0.685, 30.0, 10.0)])
def test_contact_grid_follows_its_spacing_law(rim, outer, node_at):
    """The nodes sit at equal steps of int dR / s(R / R_c): 0.2 of the contact's spacing on the
    axis, 0.3 of it at the rim, smooth (no spacing jumps by more than 17 % between neighbours:
    the far field grows by 14.6 % per node, and the node at ``node_at``, placed to 1e-12, moves
    its neighbours' spacing by up to 16 %)."""
    radii = contact_grid(240, rim, outer, node_at)
    spacing = np.diff(radii)
    assert radii[0] == 0.0 and radii[-1] == outer and np.all(spacing > 0)
    at_rim = spacing[np.searchsorted(radii, rim) - 1]
    in_contact = spacing[np.searchsorted(radii, 0.6 * rim)]
    assert spacing[0] / in_contact == pytest.approx(0.2, rel=0.02)
    assert at_rim / in_contact == pytest.approx(0.3, rel=0.02)
    assert np.all(np.abs(spacing[1:] / spacing[:-1] - 1) < 0.17)
    if node_at is not None:
        assert np.min(np.abs(radii - node_at)) < 1e-12


@pytest.mark.parametrize("St", [10.0, 1000.0, 1e4, 1e6])
def test_hard_impacts_grid_the_exit_constriction_finer(St):
    """The collision's film grid (ehdfem.collision.film_radii): up to St = 1000 the contact
    grid's own law; above it the rim's spacing relative to the contact's falls as St^(-1/2)
    (0.095 at St = 1e4, the width of the exit constriction relative to the contact radius,
    (H_min/C)^(2/3) with H_min/C ~ St^(-3/4)), at least 0.03, and the axis's rises to at most
    0.5; the grid stays smooth (neighbouring spacings within 17 %)."""
    params = CollisionParameters.from_settings(St=St, eps=1e-9, layer="thin", p_cav=-1e5)
    radii = film_radii(params)
    rim, _ = film_extent(params)
    spacing = np.diff(radii)
    at_rim = spacing[np.searchsorted(radii, rim) - 1]
    in_contact = spacing[np.searchsorted(radii, 0.6 * rim)]
    expected_rim = 0.3 * min(1.0, np.sqrt(1000.0 / St))
    assert at_rim / in_contact == pytest.approx(max(0.03, expected_rim), rel=0.06)
    expected_axis = 0.2 if St <= 1000.0 else 0.5
    assert spacing[0] / in_contact == pytest.approx(expected_axis, rel=0.03)
    assert np.all(np.abs(spacing[1:] / spacing[:-1] - 1) < 0.17)


@pytest.mark.parametrize("St, eps, delta", [(20.0, 1e-3, 0.01), (50.0, 0.1, 0.04)])
def test_immersed_couette_integral_ends_at_the_sphere(St, eps, delta):
    """On the collision's film grid the Couette integral of an undeformed immersed film,
    J = int_0^{1/sqrt(delta)} R dR / (X + R^2/2) = ln(1 + 1/(2 delta X)), is exact to 1e-9:
    the grid has a node at the sphere's radius (the sinh grid without one is 0.3-1.2 % off)."""
    params = CollisionParameters.from_settings(St=St, eps=eps, layer="immersed", delta=delta)
    radii = film_radii(params)
    film = Film(radii, "immersed")
    for gap in (1.0, 0.1, 0.01):
        weights, tail = film.couette_weights(gap + 0.5 * radii**2, 1.0 / np.sqrt(delta))
        exact = np.log(1.0 + 1.0 / (2.0 * delta * gap))
        assert weights.sum() + tail == pytest.approx(exact, rel=1e-9)
