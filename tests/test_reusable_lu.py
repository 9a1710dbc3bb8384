"""The reused LU against a fresh dense solve (exact algebra)."""

import numpy as np
import pytest

from ehdfem.motion.reusable_lu import ReusableLU, TooManyChanges

pytestmark = pytest.mark.serial

N = 30


def matrices(seed=1):
    """A well-conditioned dense matrix, its rows' and columns' replacements."""
    rng = np.random.default_rng(seed)
    matrix = rng.normal(size=(N, N)) + N * np.eye(N)
    return matrix, rng.normal(size=(N, N)) + N * np.eye(N), rng


def test_changed_rows_and_columns_solve_exactly():
    """Rows of newly fixed nodes (identity), of newly free nodes (new rows) and columns of
    nodes whose unknown changed, all at once: the solve equals a dense solve of the changed
    matrix to 1e-12."""
    matrix, other, rng = matrices()
    fixed, theta = np.zeros(N, bool), np.zeros(N, bool)
    fixed[[3, 4]] = True
    theta[[10, 11]] = True
    matrix[[3, 4]] = np.eye(N)[[3, 4]]  # a fixed node's row is an identity
    lu = ReusableLU(matrix.copy(), fixed, theta)
    new_fixed, new_theta = fixed.copy(), theta.copy()
    new_fixed[[4, 7]] = [False, True]  # node 4 freed, node 7 fixed
    new_theta[[11, 20, 21]] = [False, True, True]
    expected = matrix.copy()
    expected[:, [11, 20, 21]] = other[:, [11, 20, 21]]
    expected[4] = other[4]
    expected[7] = np.eye(N)[7]
    rhs = rng.normal(size=N)
    solution = lu.solve(
        rhs, new_fixed, lambda i: other[i], new_theta, lambda j: expected[:, j] * 1.0
    )
    assert np.allclose(solution, np.linalg.solve(expected, rhs), rtol=0, atol=1e-12)


def test_a_node_whose_row_and_column_both_change_asks_for_a_new_factorisation():
    matrix, other, _ = matrices(2)
    lu = ReusableLU(matrix.copy(), np.zeros(N, bool), np.zeros(N, bool))
    changed = np.zeros(N, bool)
    changed[5] = True
    with pytest.raises(TooManyChanges):
        lu.solve(np.ones(N), changed, lambda i: other[i], changed, lambda j: other[:, j])


@pytest.mark.parametrize("held", [0, 1, 15, 29])
def test_only_the_free_block_is_factorised(held):
    """With the identity rows of ``held`` fixed nodes (a dry or cavitated film), the LU is
    that of the free rows and columns alone, and its solves (a vector and the columns of a
    matrix) equal a dense solve of the whole matrix to 1e-12."""
    matrix, _, rng = matrices(3)
    fixed = np.zeros(N, bool)
    fixed[rng.choice(N, held, replace=False)] = True
    matrix[fixed] = np.eye(N)[fixed]
    lu = ReusableLU(matrix.copy(), fixed, np.zeros(N, bool))
    assert lu.lu.shape == ((N - held, N - held) if held >= N * lu.MIN_HELD_SHARE else (N, N))
    rhs = rng.normal(size=(N, 3))
    expected = np.linalg.solve(matrix, rhs)
    assert np.allclose(lu.solve(rhs[:, 0], fixed, None), expected[:, 0], rtol=0, atol=1e-12)
    assert np.allclose(lu._base_solve(rhs), expected, rtol=0, atol=1e-12)


@pytest.mark.parametrize("gathered", [False, True])
def test_the_equilibration_is_exact_and_scales_every_row_and_column_to_one(gathered):
    """S = diag(1/r) B diag(1/c) with c, r powers of two: S times them gives B back bit for bit
    (B = A, or its block on the kept rows and columns); each column of B / c and each row of S
    has its largest magnitude in [1/2, 1); a zero column keeps c = 1. Entries from 1e-100 to
    1e100 (none scaled below the normal range, where a power of two would round), a zero
    column and a row of -0.0."""
    from ehdfem.motion.reusable_lu import _equilibrated

    rng = np.random.default_rng(5)
    n = 37
    matrix = rng.standard_normal((n, n)) * np.exp(rng.uniform(-115, 115, (1, n)))
    matrix = np.asfortranarray(matrix * np.exp(rng.uniform(-115, 115, (n, 1))))
    matrix[:, 3], matrix[7] = 0.0, -0.0
    index = np.flatnonzero(rng.random(n) < 0.6) if gathered else None
    block = matrix if index is None else matrix[np.ix_(index, index)]
    scaled, col, row, finite = _equilibrated(matrix, index, np.empty(n * n), None)
    assert finite
    assert np.array_equal(scaled * row[:, None] * col[None, :], block)
    assert np.array_equal(np.frexp(np.concatenate([col, row]))[0], np.full(2 * len(col), 0.5))
    by_column = np.abs(block / col).max(axis=0)
    assert ((by_column >= 0.5) & (by_column < 1) | (by_column == 0) & (col == 1)).all()
    by_row = np.abs(scaled).max(axis=1)
    assert ((by_row >= 0.5) & (by_row < 1) | (by_row == 0) & (row == 1)).all()
    # in single precision: the same scales, S rounded to float32 in the same order
    single = np.empty(n * n, np.float32)
    _, col32, row32, _ = _equilibrated(matrix, index, np.empty(n * n), single)
    m = len(block)
    assert np.array_equal(col32, col) and np.array_equal(row32, row)
    assert np.array_equal(single[: m * m].reshape((m, m)).T, scaled.astype(np.float32))


@pytest.mark.parametrize("held", [0, 15])
def test_the_lu_in_single_precision_solves_to_single_rounding(held):
    """The LU held in float32 (the whole matrix, or its free block): its solve of a
    well-conditioned system (condition number 1.6, 37 with the identity rows of 15 fixed
    nodes), its rows and columns scaled over 1e-30 to 1e30 (the equilibration takes them out
    exactly), is within 5e-6 of the exact solution, relative: about n u kappa, with float32's
    rounding u = 6e-8 and n = 30 unknowns (0.8e-6 to 1e-6 seen; 1e-15 in double precision).
    The Woodbury update of a newly fixed node (on the unscaled matrix: with its rows scaled
    over 1e60 the update loses its accuracy in double precision too) is within 1e-4 (5e-6 to
    7e-6 seen). The solutions are float64."""
    matrix, _, rng = matrices(4)
    fixed = np.zeros(N, bool)
    fixed[rng.choice(N, held, replace=False)] = True
    matrix[fixed] = np.eye(N)[fixed]
    rows, columns = np.exp(rng.uniform(-69, 69, (2, N)))
    rows[fixed] = columns[fixed] = 1.0  # the identity rows stay identities
    single = np.empty(N * N, np.float32)
    scaled = np.asfortranarray(matrix * rows[:, None] * columns[None, :])
    lu = ReusableLU(scaled.copy(order="F"), fixed, np.zeros(N, bool), single=single)
    assert lu.lu.dtype == np.float32
    exact = rng.normal(size=N)
    solution = lu.solve(scaled @ (exact / columns), fixed, None)
    assert solution.dtype == np.float64
    assert np.abs(solution * columns - exact).max() <= 5e-6 * np.abs(exact).max()
    lu = ReusableLU(np.asfortranarray(matrix), fixed, np.zeros(N, bool), single=single)
    now_fixed = fixed.copy()
    now_fixed[np.flatnonzero(~fixed)[0]] = True
    changed = matrix.copy()
    changed[now_fixed & ~fixed] = np.eye(N)[now_fixed & ~fixed]
    solution = lu.solve(changed @ exact, now_fixed, lambda i: changed[i])
    assert np.abs(solution - exact).max() <= 1e-4 * np.abs(exact).max()
