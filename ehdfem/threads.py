"""One BLAS thread for the computations, so that results do not depend on the machine's BLAS.

A threaded BLAS (OpenBLAS with OPENBLAS_NUM_THREADS > 1, say) splits the sums of a matrix
product over its threads, which changes their rounding: the products of the half-space
compliance, the Newton solves and the FE condensation then differ in the last bits between
thread counts, the time step control turns such bits into another step sequence, and a soft
collision's e_n can move by 1e-4. The film and the solids are small dense problems (hundreds of
nodes), which one thread computes as fast, so every collision and every elasticity runs with
BLAS on one thread (:func:`one_blas_thread`); parallelism comes from MPI ranks, one collision
per rank (docs/performance.md).
"""

from __future__ import annotations

import functools

from threadpoolctl import ThreadpoolController


@functools.cache
def _blas() -> ThreadpoolController:
    """The BLAS libraries loaded (with numpy, scipy and PETSc) when a computation first runs."""
    return ThreadpoolController()


def one_blas_thread():
    """A context in which every loaded BLAS runs on one thread (its thread count restored
    after); a ``with`` block, so that warnings raised inside still name the caller's line."""
    return _blas().limit(limits=1, user_api="blas")
