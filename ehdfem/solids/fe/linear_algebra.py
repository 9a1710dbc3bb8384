"""The linear algebra of the FE solids: a factorised stiffness solved for blocks of loads, PETSc
matrices as scipy ones, and linear interpolation between film nodes as a sparse matrix.

Nothing here knows about scales: results carry the units of the matrices and values given.
"""

from __future__ import annotations

import numpy as np


def interpolation_matrix(nodes, points):
    """The sparse (len(points), len(nodes)) matrix of linear interpolation from values at the
    increasing ``nodes`` to ``points`` (the same length unit): constant before the first node,
    zero beyond the last (as ``np.interp(points, nodes, values, right=0.0)``). Its columns are
    the hat functions of the nodes at the points."""
    import scipy.sparse

    nodes, points = np.asarray(nodes, dtype=float), np.asarray(points, dtype=float)
    right = np.clip(np.searchsorted(nodes, points, side="right"), 1, len(nodes) - 1)
    weight = np.clip((points - nodes[right - 1]) / (nodes[right] - nodes[right - 1]), 0.0, 1.0)
    inside = points <= nodes[-1]
    rows = np.flatnonzero(inside)
    return scipy.sparse.csr_matrix(
        (
            np.concatenate([1 - weight[inside], weight[inside]]),
            (np.concatenate([rows, rows]), np.concatenate([right[inside] - 1, right[inside]])),
        ),
        shape=(len(points), len(nodes)),
    )


def scipy_matrix(matrix):
    """The owned rows of the PETSc AIJ ``matrix`` as a scipy CSR matrix (global columns)."""
    import scipy.sparse

    indptr, indices, data = matrix.getValuesCSR()
    return scipy.sparse.csr_matrix(
        (data, indices, indptr), shape=(len(indptr) - 1, matrix.getSize()[1])
    )


def _dense(values: np.ndarray, comm):
    """A PETSc dense matrix over ``comm`` holding this rank's rows ``values`` (rows, columns)."""
    from petsc4py import PETSc

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
    for petsc_object in (dense, product):  # PETSc memory is not freed by Python's GC
        petsc_object.destroy()
    return result


class CholeskySolver:
    """The symmetric positive definite PETSc ``matrix`` (a stiffness with its rigid motions
    pinned) factorised by MUMPS Cholesky on the first solve, for blocks of right-hand sides."""

    def __init__(self, matrix, comm):
        from petsc4py import PETSc

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
        for petsc_object in (rhs, solution):  # PETSc memory is not freed by Python's GC
            petsc_object.destroy()
        return values

    def close(self) -> None:
        """Free the factorisation and the matrix (collective under MPI; no solves afterwards)."""
        self._ksp.destroy()
        self.matrix.destroy()
