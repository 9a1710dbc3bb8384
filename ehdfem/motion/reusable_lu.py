"""A dense LU factorisation that is reused after some of its rows and columns change (Woodbury).

The Newton matrix of an implicit step (:mod:`ehdfem.motion.implicit_step`) is dense (the compliance
couples every film node to every other) and changes mostly by whole rows and columns: a node
that becomes dry or cavitated gets an identity row, one that becomes wet again gets its film
row back, and at a mass-conserving cavity the node's column holds the liquid fraction's
derivative instead of the pressure's. Up to MAX_CHANGES such rows and columns are applied to
the stored LU as a rank-k correction instead of a new factorisation: with A0 the factorised
matrix, R the changed rows and C the changed columns, the matrix is A0 + U V^T with
U = [E_R, (new columns - A0 columns) off the rows R] and V^T = [new rows - A0 rows; E_C^T].

The matrix is equilibrated (columns, then rows, scaled to unit max norm) before the LU: its
unknowns are pressures (up to ~1e8 near a rigid stop), the gap (~1e-4) and the velocity (~1),
many orders of magnitude apart.
"""

from __future__ import annotations

import numpy as np
import scipy.linalg


class TooManyChanges(Exception):
    """More changed rows than the Woodbury correction takes, or a singular correction."""


class SingularMatrix(Exception):
    """The matrix to factorise is singular or not finite."""


class ReusableLU:
    """LU of ``matrix`` built with the nodes ``fixed`` (boolean mask of identity rows) and
    ``theta`` (boolean mask of the nodes whose columns hold the liquid fraction theta of
    mass-conserving cavities). ``rate`` is the a0/dt the matrix was built for: the caller
    compares it with the current step to decide when to factorise again.
    """

    MAX_CHANGES = 12

    def __init__(self, matrix, fixed, rate, theta):
        self.matrix, self.fixed, self.rate, self.theta = matrix, fixed.copy(), rate, theta.copy()
        self.col = np.abs(matrix).max(axis=0)
        self.col[self.col == 0] = 1.0
        scaled = matrix / self.col
        self.row = np.abs(scaled).max(axis=1)
        self.row[self.row == 0] = 1.0
        scaled /= self.row[:, None]
        try:
            self.lu = scipy.linalg.lu_factor(scaled, overwrite_a=True, check_finite=False)
        except (scipy.linalg.LinAlgError, ValueError) as err:
            raise SingularMatrix(f"singular Newton matrix ({err})") from err

    def _base_solve(self, rhs):
        return scipy.linalg.lu_solve(self.lu, (rhs.T / self.row).T, check_finite=False) / (
            self.col if rhs.ndim == 1 else self.col[:, None]
        )

    def solve(self, rhs, fixed, film_rows, theta=None, columns=None):
        """Solve with the rows of the nodes whose fixed state changed replaced (identity rows
        for newly fixed nodes, ``film_rows(indices)`` for newly free ones) and the columns of
        the nodes whose ``theta`` state changed replaced by ``columns(indices)`` (the current
        matrix's, (N, k); ``theta`` None: no column changes). A node whose row and column both
        change, or more than MAX_CHANGES changes, raise TooManyChanges."""
        rows = np.flatnonzero(fixed != self.fixed)
        cols = np.flatnonzero(theta != self.theta) if theta is not None else rows[:0]
        y = self._base_solve(rhs)
        k = len(rows) + len(cols)
        if k == 0:
            return y
        if k > self.MAX_CHANGES or np.intersect1d(rows, cols).size:
            raise TooManyChanges
        u, vt = np.zeros((len(rhs), k)), np.zeros((k, len(rhs)))
        if len(rows):
            new_rows = np.zeros((len(rows), len(rhs)))
            now_fixed = fixed[rows]
            new_rows[now_fixed, rows[now_fixed]] = 1.0
            if (~now_fixed).any():
                new_rows[~now_fixed] = film_rows(rows[~now_fixed])
            u[rows, np.arange(len(rows))] = 1.0
            vt[: len(rows)] = new_rows - self.matrix[rows]
        if len(cols):
            delta = columns(cols) - self.matrix[:, cols]
            delta[rows] = 0.0  # those rows are replaced whole
            u[:, len(rows) :] = delta
            vt[len(rows) + np.arange(len(cols)), cols] = 1.0
        z = self._base_solve(u)
        small = np.eye(k) + vt @ z
        try:
            return y - z @ np.linalg.solve(small, vt @ y)
        except np.linalg.LinAlgError as err:
            raise TooManyChanges from err
