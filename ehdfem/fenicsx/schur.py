"""The Schur complement of a bordered symmetric positive definite matrix from one MUMPS
factorisation: G^T K^-1 G for a stiffness K and a few columns G, on one process.

The bordered matrix A = [[K, G], [G^T, 0]] has the Schur complement of its last m unknowns
0 - G^T K^-1 G. MUMPS forms it while it factorises K (the border unknowns are eliminated last
and never pivoted on). PETSc's MUMPS interface computes Schur complements on one process only,
and petsc4py (3.18 on Debian, 3.25 in the wheel) does not wrap MatFactorSetSchurIS and
MatFactorCreateSchurComplement, so this module calls them in the PETSc library through
ctypes. Nothing here knows about scales: the result carries the units of the stiffness and
the columns it is given.
"""

from __future__ import annotations

import ctypes
import ctypes.util
from functools import cache
from pathlib import Path

import numpy as np
import scipy.sparse

from .libraries import petsc


@cache
def _petsc_library():
    """The PETSc shared library that petsc4py is linked against (for the calls it lacks): the
    one this process has loaded (Linux lists it in /proc/self/maps; the wheel of the second
    stack vendors it beside DOLFINx, where no PETSC_DIR names it), else one under petsc4py's
    PETSC_DIR (Debian's) or on the loader's path."""
    import petsc4py

    petsc()  # loads the library
    maps = Path("/proc/self/maps")
    lines = maps.read_text().splitlines() if maps.exists() else []
    loaded = sorted({line.split()[-1] for line in lines if "/libpetsc" in line})
    directory = petsc4py.get_config()["PETSC_DIR"]
    installed = sorted((Path(directory) / "lib").glob("libpetsc*.so*")) if directory else []
    for path in [*loaded, *installed, ctypes.util.find_library("petsc")]:
        if path is not None:
            library = ctypes.CDLL(str(path))
            if hasattr(library, "MatFactorSetSchurIS"):
                return library
    raise RuntimeError(f"no PETSc library with MatFactorSetSchurIS (loaded: {loaded})")


def _call(name: str, *arguments) -> None:
    """Call the PETSc function ``name``; a nonzero error code raises."""
    code = getattr(_petsc_library(), name)(*arguments)
    if code != 0:
        raise RuntimeError(f"PETSc {name} failed with error code {code}")


def condensed(stiffness, columns) -> np.ndarray:
    """G^T K^-1 G (m x m, dense) for the symmetric positive definite ``stiffness`` K (scipy
    sparse, n x n; Dirichlet rows and columns already identities) and the sparse ``columns``
    G (n x m, zero on the Dirichlet rows), on this process: the Schur complement of the
    bordered matrix (module docstring), from one MUMPS factorisation of K."""
    PETSc = petsc()
    unknowns, m = columns.shape
    columns = scipy.sparse.csr_matrix(columns)
    blocks = [[scipy.sparse.csr_matrix(stiffness), columns], [columns.T.tocsr(), None]]
    blocks[1][1] = scipy.sparse.csr_matrix((m, m))  # all CSR: scipy's fast stacking
    bordered = scipy.sparse.bmat(blocks, format="csr")
    bordered.sort_indices()
    matrix = PETSc.Mat().createAIJ(
        size=bordered.shape,
        csr=(
            bordered.indptr.astype(PETSc.IntType),
            bordered.indices.astype(PETSc.IntType),
            bordered.data,
        ),
        comm=PETSc.COMM_SELF,
    )
    # Cholesky of K: the border is the Schur block, which MUMPS does not factorise
    matrix.setOption(PETSc.Mat.Option.SPD, True)
    border = PETSc.IS().createGeneral(
        np.arange(unknowns, unknowns + m, dtype=PETSc.IntType), comm=PETSc.COMM_SELF
    )
    ksp = PETSc.KSP().create(PETSc.COMM_SELF)
    try:
        ksp.setOperators(matrix)
        ksp.setType("preonly")
        pc = ksp.getPC()
        pc.setType("cholesky")
        pc.setFactorSolverType("mumps")
        pc.setFactorSetUpSolverType()
        factor = ctypes.c_void_p(pc.getFactorMatrix().handle)
        _call("MatFactorSetSchurIS", factor, ctypes.c_void_p(border.handle))
        ksp.setUp()
        return -_schur_complement(factor, m)
    finally:
        for petsc_object in (ksp, border, matrix):
            petsc_object.destroy()


def _schur_complement(factor, size: int) -> np.ndarray:
    """A copy of the dense (size x size) Schur complement of the factorisation ``factor``."""
    schur, status = ctypes.c_void_p(), ctypes.c_int()
    _call("MatFactorCreateSchurComplement", factor, ctypes.byref(schur), ctypes.byref(status))
    values = ctypes.POINTER(ctypes.c_double)()
    try:
        _call("MatDenseGetArray", schur, ctypes.byref(values))
        dense = np.ctypeslib.as_array(values, shape=(size, size)).T.copy()  # column-major
        _call("MatDenseRestoreArray", schur, ctypes.byref(values))
    finally:
        _call("MatDestroy", ctypes.byref(schur))
    return dense
