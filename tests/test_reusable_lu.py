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
