"""The seam to FEniCSx (ehdfem.fenicsx) on a unit square, against exact numbers: counts of cells
and dofs, the owned and ghost values of functions, dof coordinates at the vertices, point
values of a linear function, an assembled area, and its input checks. Each runs on 2 ranks
too (the counts and values then cross the ranks), on both DOLFINx releases."""

import numpy as np
import pytest
import ufl
from dolfinx import mesh as dolfinx_mesh
from mpi4py import MPI

from ehdfem.fenicsx import assembly, domain, functions, solvers, spaces

CELLS = 6  # per side of the unit square, each square cut into 2 triangles


@pytest.fixture(scope="module")
def square():
    return dolfinx_mesh.create_unit_square(MPI.COMM_WORLD, CELLS, CELLS)


def linear(x):
    """x + 2 y, which P1 and P2 elements hold exactly."""
    return x[0] + 2.0 * x[1]


def test_counts_are_the_square_s_and_sum_over_the_ranks(square):
    """2 N^2 triangles, (N + 1)^2 P1 vertices (times 2 components for a vector space) and
    (2N + 1)^2 P2 nodes; the owned counts of the ranks sum to them."""
    comm = MPI.COMM_WORLD
    assert domain.cell_count(square) == 2 * CELLS**2
    assert comm.allreduce(domain.owned_cell_count(square)) == 2 * CELLS**2
    for space, count in (
        (spaces.lagrange_space(square, 1), (CELLS + 1) ** 2),
        (spaces.lagrange_space(square, 1, vector=True), 2 * (CELLS + 1) ** 2),
        (spaces.lagrange_space(square, 2, vector=True, components=3), 3 * (2 * CELLS + 1) ** 2),
    ):
        assert spaces.dof_count(space) == count
        assert comm.allreduce(spaces.owned_dof_count(space)) == count
    assert domain.communicator(square).size == comm.size


def test_owned_values_set_on_each_rank_reach_the_ghosts(square):
    """A function given only its owned values (set_owned_values) has them at its owned dofs
    exactly, and at its ghost dofs the owners' values: those of x + 2 y to rounding (1e-14; a
    ghost's own interpolation may differ in the last bit), where they were zero before."""
    space = spaces.lagrange_space(square, 2)
    source, copy = functions.function(space), functions.function(space)
    functions.interpolate(source, linear)
    owned = spaces.owned_dof_count(space)
    functions.set_owned_values(copy, functions.owned_values(source))
    assert np.array_equal(functions.owned_values(copy), functions.owned_values(source))
    exact = linear(spaces.dof_coordinates(space).T)
    assert np.allclose(functions.local_values(copy), exact, rtol=0, atol=1e-14)
    ghosts = MPI.COMM_WORLD.allreduce(len(exact) - owned)
    assert ghosts > 0 or MPI.COMM_WORLD.size == 1


def test_p1_dofs_sit_at_the_vertices(square):
    """The P1 dof coordinates are the mesh's vertices (the same set of points, to rounding: the
    dofs' are pushed forward from the reference cell), and every cell's nodes are three of
    them."""
    vertices = domain.vertex_coordinates(square)
    dofs = spaces.dof_coordinates(spaces.lagrange_space(square, 1))
    assert len(dofs) == len(vertices)
    as_set = [np.unique(np.round(points, 12), axis=0) for points in (vertices, dofs)]
    assert np.array_equal(*as_set)
    nodes = domain.cell_nodes(square)
    assert nodes.shape[1] == 3 and nodes.max() < len(vertices)


def test_point_values_of_a_linear_function_are_exact(square):
    """x + 2 y in P1 at points inside: each rank finds the points in its cells, every point is
    found by some rank, and the values are exact to rounding (1e-14)."""
    function = functions.function(spaces.lagrange_space(square, 1))
    functions.interpolate(function, linear)
    points = np.zeros((50, 3))
    points[:, :2] = np.random.default_rng(5).uniform(0.01, 0.99, (50, 2))
    values, found = functions.point_values(function, points)
    assert np.allclose(values[found], linear(points[found].T), rtol=0, atol=1e-14)
    assert MPI.COMM_WORLD.allreduce(found.astype(int)).min() >= 1


def test_assembled_loads_and_integrals_give_the_area(square):
    """int v dx over the unit square: the owned entries of the assembled vector sum to 1 over
    the ranks (1e-14), as does the functional int 1 dx; the exterior facets lie on its edges."""
    space = spaces.lagrange_space(square, 1)
    loads = assembly.assembled_values(assembly.form(ufl.TestFunction(space) * ufl.dx))
    assert len(loads) == spaces.owned_dof_count(space)
    assert MPI.COMM_WORLD.allreduce(loads.sum()) == pytest.approx(1.0, abs=1e-14)
    one = functions.constant(square, 0.0)
    functions.set_constant(one, 1.0)
    assert assembly.integral(one * ufl.dx(domain=square), MPI.COMM_WORLD) == pytest.approx(
        1.0, abs=1e-14
    )
    midpoints = domain.facet_midpoints(square, domain.exterior_facets(square))
    on_edge = np.isclose(midpoints[:, :2], 0.0) | np.isclose(midpoints[:, :2], 1.0)
    assert on_edge.any(axis=1).all()


def test_nonlinear_solve_refuses_an_unknown_method_before_any_work():
    with pytest.raises(ValueError, match=r"method must be one of \('newton', 'linear'\)"):
        solvers.solve_nonlinear(
            None, None, [], None, rtol=1e-10, atol=0.0, max_iterations=1, method="picard"
        )
