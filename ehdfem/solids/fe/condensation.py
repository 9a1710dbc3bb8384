"""Condensation of a stiffness onto a few loads and read-outs: a bordered Schur complement.

The film compliance is a set of numbers b_i . K^-1 f_j: the read-outs b_i (a displacement at a
film node, a centre-of-mass motion) of the loads f_j (a hat pressure, a body force). With the
loads and read-outs as the columns of G (unknowns x m), the stiffness bordered by them,

    A = [[K, G], [G^T, 0]],

has the Schur complement of its last m unknowns 0 - G^T K^-1 G: every b_i . K^-1 f_j at once.
MUMPS forms it while it factorises K (the border unknowns are eliminated last and never
pivoted on), so the whole compliance costs about one factorisation instead of one sparse
triangular solve per load on the whole mesh.

A free body's loads are balanced by the d'Alembert forces of its rigid motions, and its
read-outs are taken relative to them (:class:`RigidMotions`); both are linear combinations of
the bordered columns, so :func:`balanced_condensation` gives the balanced entries from the same
Schur complement. The axisymmetric solids (:mod:`ehdfem.solids.fe.solids`: one motion, the
translation along z) and the mode-1 solids (:mod:`ehdfem.solids.fe.mode_one`: the translation
along x and the rotation about y) are both condensed by it.

PETSc's MUMPS interface computes Schur complements on one process only, and petsc4py (3.18
on Debian, 3.25 in the wheel) does not wrap MatFactorSetSchurIS and
MatFactorCreateSchurComplement, so this module calls them in the PETSc library through
ctypes. Nothing here knows about scales: the result carries the units of the stiffness and
the columns it is given.
"""

from __future__ import annotations

import ctypes
import ctypes.util
from dataclasses import dataclass
from functools import cache
from pathlib import Path

import numpy as np
import scipy.sparse

from . import dolfinx_compat


@dataclass(frozen=True)
class RigidMotions:
    """A free body's rigid motions on the owned rows of the unknowns: ``motions`` R (rows, k),
    ``inertia`` M (rows, k) the vectors of the d'Alembert forces of their accelerations (M_l . v
    = int R_l . v r dx, or the mean of a component), ``gram`` G = M^T R (k x k, summed over the
    ranks). A load g is balanced as g - M G^-1 (R^T g); a displacement u is read relative to
    the motions as u - R G^-1 (M^T u)."""

    motions: np.ndarray
    inertia: np.ndarray
    gram: np.ndarray

    def balanced(self, loads: np.ndarray, comm) -> np.ndarray:
        """The load columns ``loads`` (owned rows) balanced by this body's d'Alembert forces."""
        return loads - self.inertia @ np.linalg.solve(
            self.gram, comm.allreduce(self.motions.T @ loads)
        )

    def relative(self, values: np.ndarray, comm) -> np.ndarray:
        """The displacement columns ``values`` (owned rows) relative to this body's motions."""
        return values - self.motions @ np.linalg.solve(
            self.gram, comm.allreduce(self.inertia.T @ values)
        )


def balanced_condensation(stiffness, faces, bodies, constrained) -> np.ndarray:
    """The (f, f) matrix whose entry (i, j) is the read-out b_i . u' of the face column b_i
    for the displacement u' = K^-1 g_j, relative to the free ``bodies``' rigid motions, of the
    face column b_j balanced on them (g_j): b_i and b_j are the sparse columns of ``faces`` (n
    x f, a film load on a contact face, which is also the read-out in its direction), K the
    ``stiffness`` (scipy sparse, n x n, Dirichlet rows and columns identities), ``bodies`` a
    sequence of :class:`RigidMotions` (rows n), ``constrained`` the Dirichlet rows (loads
    zero there). On this process, from one Schur complement (:func:`condensed`) of K bordered
    by X = [faces, the bodies' inertia columns]: g_j = X L_j and the read-out b_i . u' = (X R_i)
    . u, with the coefficients L = [I; -G^-1 R^T faces] and R = [I; -G^-T R^T faces] per body,
    so the matrix is R^T (X^T K^-1 X) L."""
    import scipy.sparse

    f = faces.shape[1]
    faces = scipy.sparse.csr_matrix(faces)
    loads, reads = [np.zeros((0, f))], [np.zeros((0, f))]  # the bodies' rows of L and R
    for body in bodies:
        resultants = (faces.T @ body.motions).T  # (k, f): R^T b_j
        loads.append(-np.linalg.solve(body.gram, resultants))
        reads.append(-np.linalg.solve(body.gram.T, resultants))
    inertia = [scipy.sparse.csr_matrix(body.inertia) for body in bodies]
    columns = scipy.sparse.hstack([faces, *inertia], format="csr")
    keep = np.ones(columns.shape[0])
    keep[constrained] = 0.0
    columns = scipy.sparse.diags(keep) @ columns
    columns.eliminate_zeros()
    schur = condensed(stiffness, columns)
    # the identity blocks of L and R as slices: products only with the bodies' few rows
    loaded = schur[:, :f] + schur[:, f:] @ np.vstack(loads)
    return loaded[:f] + np.vstack(reads).T @ loaded[f:]


@cache
def _petsc_library():
    """The PETSc shared library that petsc4py is linked against (for the calls it lacks): the
    one this process has loaded (Linux lists it in /proc/self/maps; the wheel of the second
    stack vendors it beside DOLFINx, where no PETSC_DIR names it), else one under petsc4py's
    PETSC_DIR (Debian's) or on the loader's path."""
    import petsc4py

    dolfinx_compat.petsc()  # loads the library
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
    PETSc = dolfinx_compat.petsc()
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
