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

The Schur complement itself (MUMPS, through ctypes) is :func:`ehdfem.fenicsx.schur.condensed`.
Nothing here knows about scales: the result carries the units of the stiffness and the columns
it is given.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse

from ...fenicsx.schur import condensed


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
    zero there). On this process, from one Schur complement
    (:func:`ehdfem.fenicsx.schur.condensed`) of K bordered by X = [faces, the bodies' inertia
    columns]: g_j = X L_j and the read-out b_i . u' = (X R_i) . u, with the coefficients
    L = [I; -G^-1 R^T faces] and R = [I; -G^-T R^T faces] per body, so the matrix is
    R^T (X^T K^-1 X) L."""
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
