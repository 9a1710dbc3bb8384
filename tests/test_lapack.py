"""LAPACK from the packaged OpenBLAS (ehdfem.lapack): the LU, in double and in single precision,
solves exactly representable systems to rounding, pivots where it must, says when a matrix is
singular, leaves its inputs alone, and runs on one thread whatever the environment asks."""

import subprocess
import sys

import numpy as np
import pytest

from ehdfem.lapack import getrf, getrs


def integer_system(size, seed):
    """(A, X, B = A X): integer entries, so B is exact in floating point and X the exact
    solution; a zero leading entry forces getrf to pivot."""
    rng = np.random.default_rng(seed)
    matrix = rng.integers(-9, 10, (size, size)).astype(float) + 10.0 * (size + 1) * np.eye(size)
    if size > 1:  # the first two rows swapped, and a zero leading entry
        matrix[[0, 1]] = matrix[[1, 0]]
        matrix[0, 0] = 0.0
    solution = rng.integers(-5, 6, (size, 3)).astype(float)
    return matrix, solution, matrix @ solution


@pytest.mark.parametrize("size", [1, 2, 17, 242])
@pytest.mark.parametrize("dtype, tolerance", [(np.float64, 1e-13), (np.float32, 2e-6)])
def test_the_lu_solves_an_exact_system_to_rounding(size, dtype, tolerance):
    """x of A x = b, one and several right-hand sides, within ``tolerance`` of the exact
    integers, relative (A is a diagonally dominant matrix with its first two rows swapped: a
    condition number under 1.5): 1e-13 in double precision; 2e-6 in single, the packaged
    library's sgetrf and sgetrs, where float32's rounding is 6e-8 (6e-7 seen at 242 unknowns)."""
    matrix, solution, rhs = integer_system(size, seed=size)
    factors = np.asfortranarray(matrix.astype(dtype))
    pivots, info = getrf(factors)
    assert info == 0 and pivots.dtype == np.intc
    assert 0 <= pivots.min() and pivots.max() < size  # 0-based, as scipy's getrs takes them
    for b, x in ((rhs[:, 0], solution[:, 0]), (rhs, solution)):
        b = b.astype(dtype)
        kept = b.copy()
        found = getrs(factors, pivots, b)
        assert found.dtype == dtype and np.array_equal(b, kept)
        assert np.abs(found - x).max() <= tolerance * max(np.abs(x).max(), 1.0)
    if size > 1:
        assert pivots[0] != 0  # the zero leading entry was pivoted away
    if dtype == np.float32:  # the float32 routine reads a float32 right-hand side only
        with pytest.raises(ValueError, match="dtype"):
            getrs(factors, pivots, rhs)


def test_a_singular_matrix_is_reported_and_a_row_ordered_one_refused():
    """A zero column gives info > 0 (U's zero diagonal entry, 1-based); getrf factorises in
    place, so a matrix in row order (whose transpose it would factorise) is refused."""
    matrix = np.asfortranarray(np.arange(1.0, 10.0).reshape(3, 3))
    matrix[:, 1] = 0.0
    assert getrf(matrix)[1] == 2
    with pytest.raises(ValueError, match="column order"):
        getrf(np.ones((3, 3)))


def test_the_library_runs_on_one_thread_whatever_the_environment_asks():
    """With OPENBLAS_NUM_THREADS=2 (and the machine's BLAS then on two threads) the packaged
    OpenBLAS is on one: its LU's last bits would otherwise depend on the thread count
    (ehdfem.threads)."""
    probe = (
        "import ehdfem.lapack, scipy_openblas32, threadpoolctl\n"
        "for i in threadpoolctl.threadpool_info():\n"
        "    if i['filepath'].startswith(scipy_openblas32.get_lib_dir()):\n"
        "        print(i['num_threads'])"
    )
    env = {"OPENBLAS_NUM_THREADS": "2", "PATH": "/usr/bin:/bin"}
    out = subprocess.run(
        [sys.executable, "-c", probe], env=env, capture_output=True, text=True, check=True
    ).stdout
    assert out.split() == ["1"]
