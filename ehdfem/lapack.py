"""LAPACK's dense LU (getrf), its solve (getrs) and the two at once (gesv), from the OpenBLAS
the package installs (scipy-openblas32, a wheel of the package registry), on one thread.

A collision factorises a dense Newton matrix of a few hundred unknowns at nearly every step
(:mod:`ehdfem.motion.reusable_lu`; the sliding film's (3N + 2)-square system every step), and
those LUs are about a third of its time. The machine's own LAPACK may not know its CPU: Debian
12's OpenBLAS 0.3.21 falls back to its generic kernels on recent processors (an LU of 242
unknowns took 0.62 ms on the project's machine, the packaged OpenBLAS 0.3.34 0.38 ms). With
the packaged library both install stacks factorise with the same code, and nothing on the
machine is changed. The library serves these calls alone and is held to one thread
(:mod:`ehdfem.threads`: a thread count would change the last bits). Arrays are float64 in
LAPACK's column order; LAPACK's 1-based pivots are kept as it returns them.
"""

from __future__ import annotations

import ctypes
from pathlib import Path

import numpy as np
import scipy_openblas32

_INT = ctypes.c_int
_POINTER = ctypes.c_void_p
_BY_REFERENCE = ctypes.POINTER(_INT)


def _library() -> ctypes.CDLL:
    """The packaged OpenBLAS, its thread count set to one."""
    name = scipy_openblas32.get_library(fullname=True)
    library = ctypes.CDLL(str(Path(scipy_openblas32.get_lib_dir()) / name))
    library.scipy_openblas_set_num_threads(1)
    library.scipy_dgetrf_.argtypes = [_BY_REFERENCE] * 2 + [_POINTER, _BY_REFERENCE]
    library.scipy_dgetrf_.argtypes += [_POINTER, _BY_REFERENCE]
    library.scipy_dgetrs_.argtypes = [ctypes.c_char_p, _BY_REFERENCE, _BY_REFERENCE, _POINTER]
    library.scipy_dgetrs_.argtypes += [_BY_REFERENCE, _POINTER, _POINTER, _BY_REFERENCE]
    library.scipy_dgetrs_.argtypes += [_BY_REFERENCE, ctypes.c_size_t]
    return library


_LAPACK = _library()


def getrf(matrix: np.ndarray) -> tuple[np.ndarray, int]:
    """P L U = A for the square ``matrix`` A (float64, column order), factorised in place:
    (pivots, info), info > 0 where U's diagonal entry info is zero."""
    if not matrix.flags.f_contiguous or matrix.dtype != np.float64:
        raise ValueError("getrf takes a float64 matrix in column order")
    size = _INT(matrix.shape[0])
    pivots = np.empty(matrix.shape[0], dtype=np.intc)
    info = _INT(0)
    _LAPACK.scipy_dgetrf_(size, size, matrix.ctypes.data, size, pivots.ctypes.data, info)
    return pivots, info.value


def getrs(factors: np.ndarray, pivots: np.ndarray, rhs: np.ndarray) -> np.ndarray:
    """x with A x = ``rhs`` (a vector, or one right-hand side per column) from getrf's
    ``factors`` and ``pivots`` of A; ``rhs`` is left as it is."""
    solution = np.array(rhs, dtype=np.float64, order="F")
    size = _INT(factors.shape[0])
    columns = _INT(1 if solution.ndim == 1 else solution.shape[1])
    info = _INT(0)
    _LAPACK.scipy_dgetrs_(
        b"N",
        size,
        columns,
        factors.ctypes.data,
        size,
        pivots.ctypes.data,
        solution.ctypes.data,
        size,
        info,
        1,
    )
    return solution


def gesv(matrix: np.ndarray, rhs: np.ndarray) -> tuple[np.ndarray, int]:
    """(x, info) with A x = ``rhs`` for the square ``matrix`` A (neither changed): getrf on a
    copy of A, then getrs; info > 0 for a singular A (x is then not defined)."""
    factors = np.array(matrix, dtype=np.float64, order="F")
    pivots, info = getrf(factors)
    if info != 0:
        return rhs, info
    return getrs(factors, pivots, rhs), 0
