"""LAPACK's dense LU (getrf) from the OpenBLAS the package installs (scipy-openblas32, a wheel of
the package registry), on one thread, and its solve (getrs).

A collision factorises a dense Newton matrix of a few hundred unknowns at nearly every step
(:mod:`ehdfem.motion.reusable_lu`, which the sliding film's system of every step uses too), and
those LUs are about a third of its time. The machine's own LAPACK may not know its CPU: Debian
12's OpenBLAS 0.3.21 falls back to its generic kernels on recent processors (an LU of 242
unknowns took 0.62 ms on the project's machine, the packaged OpenBLAS 0.3.34 0.38 ms). With
the packaged library both install stacks factorise with the same code, and nothing on the
machine is changed. The library serves these calls alone and is held to one thread
(:mod:`ehdfem.threads`: a thread count would change the last bits). Arrays are float64, or
float32 for an LU in single precision (:class:`ehdfem.motion.reusable_lu.ReusableLU`), in
LAPACK's column order; pivots are 0-based (scipy's wrappers' convention).
"""

from __future__ import annotations

import ctypes
from pathlib import Path

import numpy as np
import scipy_openblas32
from scipy.linalg import lapack

_INT = ctypes.c_int
_POINTER = ctypes.c_void_p
_BY_REFERENCE = ctypes.POINTER(_INT)


def _library() -> ctypes.CDLL:
    """The packaged OpenBLAS, its thread count set to one."""
    name = scipy_openblas32.get_library(fullname=True)
    library = ctypes.CDLL(str(Path(scipy_openblas32.get_lib_dir()) / name))
    library.scipy_openblas_set_num_threads(1)
    for routine in (library.scipy_dgetrf_, library.scipy_sgetrf_):
        routine.argtypes = [_BY_REFERENCE] * 2 + [_POINTER, _BY_REFERENCE, _POINTER, _BY_REFERENCE]
    library.scipy_sgetrs_.argtypes = [ctypes.c_char_p, _BY_REFERENCE, _BY_REFERENCE, _POINTER]
    library.scipy_sgetrs_.argtypes += [_BY_REFERENCE, _POINTER, _POINTER, _BY_REFERENCE]
    library.scipy_sgetrs_.argtypes += [_BY_REFERENCE]
    return library


_LAPACK = _library()
_GETRF = {np.dtype(np.float64): _LAPACK.scipy_dgetrf_, np.dtype(np.float32): _LAPACK.scipy_sgetrf_}
_GETRS = lapack.get_lapack_funcs("getrs", dtype=np.float64)


def getrf(matrix: np.ndarray) -> tuple[np.ndarray, int]:
    """P L U = A for the square ``matrix`` A (float64 or float32, column order), factorised in
    place: (pivots, 0-based, and info), info > 0 where U's diagonal entry info (1-based) is
    zero."""
    if not matrix.flags.f_contiguous or matrix.dtype not in _GETRF:
        raise ValueError("getrf takes a float64 or float32 matrix in column order")
    size = _INT(matrix.shape[0])
    pivots = np.empty(matrix.shape[0], dtype=np.intc)
    info = _INT(0)
    _GETRF[matrix.dtype](size, size, matrix.ctypes.data, size, pivots.ctypes.data, info)
    pivots -= 1  # 0-based, as scipy's getrs wrapper takes them
    return pivots, info.value


def getrs(factors: np.ndarray, pivots: np.ndarray, rhs: np.ndarray, overwrite=False):
    """x with A x = ``rhs`` (a vector, or one right-hand side per column) from getrf's
    ``factors`` and ``pivots`` of A, in the factors' precision (``rhs`` of their dtype);
    ``rhs`` is left as it is unless ``overwrite``. In double precision the triangular solves
    are the machine's LAPACK's, through scipy: a call through ctypes costs 3 us, more than the
    packaged library gains on a solve of a few right-hand sides (about 9 us each at 200
    unknowns). In single precision they are the packaged library's, as its LU: the same code
    on every BLAS build and install stack, whose float32 rounding a Newton iteration would
    otherwise carry from one build to the other at 6e-8 of its updates."""
    if factors.dtype == np.float64:
        solution, _ = _GETRS(factors, pivots, rhs, overwrite_b=overwrite)
        return solution
    if rhs.dtype != factors.dtype:
        raise ValueError("getrs takes a right-hand side of its factors' dtype")
    solution = rhs if overwrite and rhs.flags.f_contiguous else np.array(rhs, order="F")
    size, count = _INT(len(factors)), _INT(1 if rhs.ndim == 1 else rhs.shape[1])
    one_based, info = pivots + 1, _INT(0)
    _LAPACK.scipy_sgetrs_(
        b"N", size, count, factors.ctypes.data, size, one_based.ctypes.data,
        solution.ctypes.data, size, info,
    )  # fmt: skip
    return solution
