"""A dense LU factorisation that is reused after some of its rows change (Woodbury identity).

The Newton matrix of an implicit step (:mod:`ehdfem.implicit_step`) is dense (the compliance
couples every film node to every other) and changes mostly by whole rows: a node that becomes
dry or cavitated gets an identity row, one that becomes wet again gets its film row back. Up
to MAX_CHANGES such rows are applied to the stored LU as a rank-k correction instead of a new
factorisation.

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
    """LU of ``matrix`` built with the nodes ``fixed`` (boolean mask of identity rows).

    ``rate`` is the a0/dt the matrix was built for and ``columns`` the nodes (as bytes) whose
    columns hold the theta unknown of mass-conserving cavities: the caller compares both with
    the current step to decide when to factorise again.
    """

    MAX_CHANGES = 12

    def __init__(self, matrix, fixed, rate, columns):
        self.matrix, self.fixed, self.rate, self.columns = matrix, fixed.copy(), rate, columns
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

    def solve(self, rhs, fixed, film_rows):
        """Solve with the rows of the nodes whose fixed state changed replaced: identity rows
        for newly fixed nodes, ``film_rows(indices)`` for newly free ones."""
        changed = np.flatnonzero(fixed != self.fixed)
        y = self._base_solve(rhs)
        if len(changed) == 0:
            return y
        if len(changed) > self.MAX_CHANGES:
            raise TooManyChanges
        new_rows = np.zeros((len(changed), len(rhs)))
        now_fixed = fixed[changed]
        new_rows[now_fixed, changed[now_fixed]] = 1.0
        if (~now_fixed).any():
            new_rows[~now_fixed] = film_rows(changed[~now_fixed])
        delta = new_rows - self.matrix[changed]
        selector = np.zeros((len(rhs), len(changed)))
        selector[changed, np.arange(len(changed))] = 1.0
        z = self._base_solve(selector)
        small = np.eye(len(changed)) + delta @ z
        try:
            return y - z @ np.linalg.solve(small, delta @ y)
        except np.linalg.LinAlgError as err:
            raise TooManyChanges from err
