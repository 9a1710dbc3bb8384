"""PETSc matrices as the solids use them: products with blocks of columns, a factorised stiffness
solved for blocks of loads, and the owned rows as a scipy matrix.

Nothing here knows about scales: results carry the units of the matrices and values given.
"""

from __future__ import annotations

import numpy as np

from .libraries import petsc


def scipy_matrix(matrix):
    """The owned rows of the PETSc AIJ ``matrix`` as a scipy CSR matrix (global columns)."""
    import scipy.sparse

    indptr, indices, data = matrix.getValuesCSR()
    return scipy.sparse.csr_matrix(
        (data, indices, indptr), shape=(len(indptr) - 1, matrix.getSize()[1])
    )


def free(*petsc_objects) -> None:
    """Destroy PETSc objects (matrices, vectors, solvers): their memory is not returned by
    Python's garbage collector. Collective under MPI."""
    for petsc_object in petsc_objects:
        petsc_object.destroy()


def _dense(values: np.ndarray, comm):
    """A PETSc dense matrix over ``comm`` holding this rank's rows ``values`` (rows, columns)."""
    PETSc = petsc()
    size = (values.shape[0], comm.allreduce(values.shape[0]))
    dense = PETSc.Mat().createDense([size, (PETSc.DECIDE, values.shape[1])], comm=comm)
    dense.setUp()
    dense.getDenseArray()[:] = values
    dense.assemble()
    return dense


def matrix_product(matrix, values: np.ndarray, comm, transpose: bool = False) -> np.ndarray:
    """The owned rows of the PETSc ``matrix`` (``transpose``: of its transpose) times the
    columns whose owned rows are ``values`` (rows, columns; rows distributed as the matrix's
    columns, or as its rows with ``transpose``), as a dense array. The transpose gives the
    read-outs b . u of the loads b that ``matrix`` makes, for displacements u."""
    dense = _dense(values, comm)
    product = matrix.transposeMatMult(dense) if transpose else matrix.matMult(dense)
    result = product.getDenseArray().copy()
    free(dense, product)
    return result


class CholeskySolver:
    """The symmetric positive definite PETSc ``matrix`` (a stiffness with its rigid motions
    pinned) factorised by MUMPS Cholesky on the first solve, for blocks of right-hand sides."""

    def __init__(self, matrix, comm):
        PETSc = petsc()
        self.matrix, self.comm = matrix, comm
        matrix.setOption(PETSc.Mat.Option.SPD, True)
        self._ksp = PETSc.KSP().create(comm)
        self._ksp.setOperators(matrix)
        self._ksp.setType("preonly")
        self._ksp.getPC().setType("cholesky")
        self._ksp.getPC().setFactorSolverType("mumps")

    def solve(self, loads: np.ndarray) -> np.ndarray:
        """The owned rows of K^-1 times the load columns whose owned rows are ``loads`` (rows,
        columns), from one multiple-right-hand-side solve on the factorisation."""
        rhs = _dense(loads, self.comm)
        solution = rhs.duplicate()
        self._ksp.setUp()  # factorises on the first solve only
        self._ksp.getPC().getFactorMatrix().matSolve(rhs, solution)
        values = solution.getDenseArray().copy()
        free(rhs, solution)
        return values

    def close(self) -> None:
        """Free the factorisation and the matrix (collective under MPI; no solves afterwards)."""
        free(self._ksp, self.matrix)
