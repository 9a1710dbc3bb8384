"""The condensation of the FE stiffness onto the film's loads and read-outs (exact algebra)."""

import math

import numpy as np
import pytest
import scipy.sparse
from mpi4py import MPI

from ehdfem.fenicsx.schur import condensed
from ehdfem.film.grid import radial_grid
from ehdfem.solids.fe.bodies import CoatedWall, LowerSphere
from ehdfem.solids.fe.condensation import RigidMotions, balanced_condensation
from ehdfem.solids.fe.linear_algebra import interpolation_matrix
from ehdfem.solids.fe.solids import FESolids


def dirichlet_stiffness(rng, n: int, density: float, fixed: list):
    """A random sparse SPD stiffness (n x n, as LIL) with identity rows and columns at the
    Dirichlet unknowns ``fixed``."""
    coupling = scipy.sparse.random(n, n, density=density, random_state=rng)
    stiffness = (coupling @ coupling.T + scipy.sparse.eye(n) * 2.0).tolil()
    stiffness[fixed] = 0.0
    stiffness[:, fixed] = 0.0
    stiffness[fixed, fixed] = 1.0
    return stiffness


@pytest.mark.serial
def test_condensed_is_the_read_outs_of_the_solved_loads():
    """G^T K^-1 G from the bordered Schur complement equals the dense solve to 1e-12, for a
    sparse SPD K with identity (Dirichlet) rows and sparse and dense columns G."""
    rng = np.random.default_rng(3)
    n, m = 400, 12
    fixed = [0, 17, 399]
    stiffness = dirichlet_stiffness(rng, n, 0.01, fixed)
    columns = scipy.sparse.hstack(
        [scipy.sparse.random(n, m - 1, density=0.02, random_state=rng), rng.random((n, 1))]
    ).tolil()
    columns[fixed] = 0.0
    stiffness, columns = stiffness.tocsr(), columns.tocsr()
    dense = columns.toarray()
    expected = dense.T @ np.linalg.solve(stiffness.toarray(), dense)
    result = condensed(stiffness, columns)
    assert np.abs(result - expected).max() < 1e-12 * np.abs(expected).max()


@pytest.mark.serial
def test_interpolation_matrix_is_linear_interpolation():
    """Its product with nodal values is np.interp (constant before the first node, zero beyond
    the last), to rounding."""
    nodes = np.array([0.1, 0.4, 0.5, 1.2, 2.0])
    points = np.array([0.0, 0.1, 0.3, 0.5, 0.9, 2.0, 2.0000001, 3.0])
    values = np.random.default_rng(0).random((len(nodes), 3))
    expected = np.column_stack([np.interp(points, nodes, v, right=0.0) for v in values.T])
    assert np.allclose(interpolation_matrix(nodes, points) @ values, expected, rtol=0, atol=1e-15)


@pytest.mark.parametrize(
    "options",
    [{"lower": CoatedWall(0.02, 0.2, 0.45)}, {"lower": LowerSphere()}],
)
def test_condensed_compliance_equals_a_solve_of_the_whole_solids(options):
    """Runs on 2 ranks too (a distributed solve against rank 0's condensation): the gap the
    condensed pressure and shear compliances give for a film load equals the one the whole
    solids open under it, to 1e-10 of its largest value."""
    radii = radial_grid(20, 0.5, 2.0)
    solids = FESolids(1e-3, radii, comm=MPI.COMM_WORLD, **options)
    compliance = solids.compliance(1.0, shear=True)
    pressure = np.sqrt(np.clip(1 - (radii / 0.8) ** 2, 0, None))
    traction = radii * pressure
    solids.displacement(pressure, math.sqrt(solids.delta) * traction)
    opening = solids.gap_opening()
    expected = compliance.unit_matrix @ pressure + compliance.unit_shear @ traction
    assert np.abs(opening - expected).max() < 1e-10 * np.abs(expected).max()


@pytest.mark.serial
def test_balanced_condensation_is_the_relative_read_outs_of_the_balanced_loads():
    """Each entry of balanced_condensation is b_i . u', u' = u - R G^-1 (M^T u) the
    displacement relative to a free body's rigid motions R (two, with a non-symmetric Gram
    matrix G = M^T R) of u = K^-1 g_j, g_j = b_j - M G^-1 (R^T b_j) the face column b_j
    balanced by the body's d'Alembert forces M and zero on the Dirichlet rows: equal to the
    dense solves to 1e-12."""
    rng = np.random.default_rng(4)
    n, f = 300, 10
    fixed = [3, 150, 299]
    stiffness = dirichlet_stiffness(rng, n, 0.02, fixed)
    faces = scipy.sparse.random(n, f, density=0.05, random_state=rng).tocsr()
    motions, inertia = rng.random((n, 2)), rng.random((n, 2))
    body = RigidMotions(motions, inertia, inertia.T @ motions)
    comm = MPI.COMM_SELF
    loads = body.balanced(faces.toarray(), comm)
    loads[fixed] = 0.0
    values = body.relative(np.linalg.solve(stiffness.toarray(), loads), comm)
    expected = faces.toarray().T @ values
    result = balanced_condensation(stiffness.tocsr(), faces, [body], np.array(fixed))
    assert np.abs(result - expected).max() < 1e-12 * np.abs(expected).max()
