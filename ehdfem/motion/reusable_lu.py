"""A dense LU factorisation that is reused after some of its rows and columns change (Woodbury).

The Newton matrix of an implicit step (:mod:`ehdfem.motion.implicit_step`) is dense (the compliance
couples every film node to every other) and changes mostly by whole rows and columns: a node
that becomes dry or cavitated gets an identity row, one that becomes wet again gets its film
row back, and at a mass-conserving cavity the node's column holds the liquid fraction's
derivative instead of the pressure's. Up to MAX_CHANGES such rows and columns are applied to
the stored LU as a rank-k correction instead of a new factorisation: with A0 the factorised
matrix, R the changed rows and C the changed columns, the matrix is A0 + U V^T with
U = [E_R, (new columns - A0 columns) off the rows R] and V^T = [new rows - A0 rows; E_C^T].

The rows of fixed nodes are identities, so when there are enough of them (MIN_HELD_SHARE)
only the block of the other rows and columns is factorised: with F the free unknowns and X the
fixed ones, x_X = b_X and A_FF x_F = b_F - A_FX b_X. Where the film is dry or cavitated over
much of the grid (a thin layer's rebound, a hard impact under a cavitation limit) this LU is
several times cheaper than the whole matrix's; otherwise the whole matrix is factorised.

The matrix is equilibrated (columns, then rows, scaled by powers of two to a largest entry in
[1/2, 1), so the scaling itself rounds nothing) before the LU: its
unknowns are pressures (up to ~1e8 near a rigid stop), the gap (~1e-4) and the velocity (~1),
many orders of magnitude apart.

The LU may be computed in single precision: the equilibrated matrix rounded to float32,
factorised and solved in float32, the right-hand sides and solutions float64. A Newton
iteration whose residual is formed in double precision corrects the LU's error as it corrects
a kept LU's (:mod:`ehdfem.motion.implicit_step`, whose mixed precision says when).
"""

from __future__ import annotations

import math

import numpy as np
from llvmlite import ir
from numba import njit, types
from numba.core import cgutils
from numba.core.extending import intrinsic

from ..lapack import getrf, getrs


@intrinsic
def _larger(typingctx, a, b):
    """The larger of two floats as LLVM's maxnum: one instruction, which the compiler
    vectorises in a loop (numba's max, with Python's rules for NaN, kept the loops scalar:
    53 against 11 us for a 242-square matrix's column maxima). Exact; a and b are finite."""

    def codegen(context, builder, signature, args):
        double = ir.DoubleType()
        maxnum = ir.FunctionType(double, [double, double])
        return builder.call(
            cgutils.get_or_insert_function(builder.module, maxnum, "llvm.maxnum.f64"), args
        )

    return types.float64(types.float64, types.float64), codegen


@njit(cache=True, error_model="numpy")
def _power_of_two(largest: float) -> float:
    """2^e with largest / 2^e in [0.5, 1) (1 for 0): a scale that divides exactly."""
    if largest == 0.0:
        return 1.0
    return math.ldexp(1.0, math.frexp(largest)[1])


@njit(cache=True, error_model="numpy")
def _equilibrated(matrix, index, out, single):
    """(S, c, r, finite): S = diag(1/r) B diag(1/c) for the square block B = A[index][:, index] (the
    whole A when ``index`` is None), c the powers of two of B's columns' largest absolute
    entries and then r those of the scaled rows' (:func:`_power_of_two`): the scaling is exact.
    S is written into the flat array ``out`` (at least m^2 long) in LAPACK's column order
    (getrf takes it without a copy): B is copied there and scaled in place; with a float32 flat
    array ``single`` (None: none), S rounded to single precision is written there instead, in
    the same order, by the last pass (``out`` then holds B diag(1/c)). The largest entries
    are found by :func:`_larger`; every loop runs down one column of ``out`` and vectorises
    (0.11 -> 0.05 ms at 242 unknowns). A fourth output says whether every entry of B is
    finite: the copy counts those that are not as it goes (an integer count vectorises, a float
    check would not), where numpy's isfinite on the whole matrix cost some 25 us."""
    m = len(matrix) if index is None else len(index)
    not_finite = 0
    for j in range(m):
        start = j * m
        if index is None:
            for i in range(m):
                out[start + i] = matrix[i, j]
        else:
            for i in range(m):
                out[start + i] = matrix[index[i], index[j]]
        for i in range(m):
            not_finite += not abs(out[start + i]) < math.inf
    col = np.empty(m)
    row = np.zeros(m)
    for j in range(m):
        start, largest = j * m, 0.0
        for i in range(m):
            largest = _larger(largest, abs(out[start + i]))
        col[j] = _power_of_two(largest)
        inverse = 1.0 / col[j]
        for i in range(m):
            out[start + i] *= inverse
        for i in range(m):
            row[i] = _larger(row[i], abs(out[start + i]))
    inverse_row = np.empty(m)
    for i in range(m):
        row[i] = _power_of_two(row[i])
        inverse_row[i] = 1.0 / row[i]
    for j in range(m):
        start = j * m
        if single is None:
            for i in range(m):
                out[start + i] *= inverse_row[i]
        else:
            for i in range(m):
                single[start + i] = out[start + i] * inverse_row[i]
    return out[: m * m].reshape((m, m)).T, col, row, not_finite == 0


@njit(cache=True, error_model="numpy")
def _single_right_sides(rhs, row, out):
    """The sizes s_j: ``out`` (float32, n x k) holds the columns of diag(1/r) ``rhs`` divided
    by s_j, the power of two of their largest magnitude (:func:`_power_of_two`), so that their
    rounding to float32 neither overflows nor underflows; both scalings are exact."""
    n, k = rhs.shape
    sizes = np.empty(k)
    for j in range(k):
        largest = 0.0
        for i in range(n):
            largest = _larger(largest, abs(rhs[i, j] / row[i]))
        sizes[j] = _power_of_two(largest)
        inverse = 1.0 / sizes[j]
        for i in range(n):
            out[i, j] = rhs[i, j] / row[i] * inverse
    return sizes


@njit(cache=True, error_model="numpy")
def _double_solutions(single, sizes, col):
    """diag(1/c) times the float32 solutions ``single`` (n x k), column j scaled back by
    ``sizes[j]`` (:func:`_single_right_sides`), in float64."""
    n, k = single.shape
    out = np.empty((n, k))
    for j in range(k):
        for i in range(n):
            out[i, j] = single[i, j] * sizes[j] / col[i]
    return out


class TooManyChanges(Exception):
    """More changed rows than the Woodbury correction takes, or a singular correction."""


class SingularMatrix(Exception):
    """The matrix to factorise is singular or not finite."""


class ReusableLU:
    """LU of ``matrix`` built with the nodes ``fixed`` (boolean mask of identity rows) and
    ``theta`` (boolean mask of the nodes whose columns hold the liquid fraction theta of
    mass-conserving cavities). The rows of the fixed nodes must be identity rows, as the
    Newton matrix's are: only the other rows and columns are factorised (module docstring).
    ``workspace``: a flat float array of at least len(matrix)^2 entries that holds the factors
    while this LU lives (a new one if None): a caller that alternates two of them allocates
    no memory a factorisation. ``single``: a flat float32 array of as many entries, or None:
    with it the LU is computed and held there in single precision (module docstring).
    """

    MAX_CHANGES = 12
    # the share of identity rows from which the free block alone is factorised: gathering it
    # costs some 40 % more than equilibrating the whole matrix, which a few identity rows do
    # not save in the LU (at 240 nodes the estimated break-even is near 10 of them, 1/16 is 15)
    MIN_HELD_SHARE = 1 / 16

    def __init__(self, matrix, fixed, theta, workspace=None, single=None):
        self.matrix, self.fixed, self.theta = matrix, fixed.copy(), theta.copy()
        identity = np.zeros(len(matrix), dtype=bool)
        identity[: len(fixed)] = fixed & ~theta
        self.free = self.coupling = None
        if identity.sum() >= self.MIN_HELD_SHARE * len(matrix):  # A_FF, and A_FX kept
            self.free, self.held = np.flatnonzero(~identity), np.flatnonzero(identity)
            self.coupling = matrix[np.ix_(self.free, self.held)]
            if not np.isfinite(self.coupling).all():
                raise SingularMatrix("Newton matrix not finite")
        if workspace is None:
            workspace = np.empty(len(matrix) ** 2)
        scaled, self.col, self.row, finite = _equilibrated(matrix, self.free, workspace, single)
        if not finite:
            raise SingularMatrix("Newton matrix not finite")
        if single is not None:
            m = len(scaled)
            scaled = single[: m * m].reshape((m, m)).T
        self.lu = scaled
        self.pivots, info = getrf(scaled)
        if info != 0:
            raise SingularMatrix(f"singular Newton matrix (LAPACK getrf info {info})")

    def _base_solve(self, rhs):
        """x with A0 x = ``rhs`` (a vector or the columns of a matrix)."""
        if self.free is None:
            return self._block_solve(rhs)
        solution = rhs.copy()
        held = rhs[self.held]
        solution[self.free] = self._block_solve(rhs[self.free] - self.coupling @ held)
        return solution

    def _block_solve(self, rhs):
        """The factorised block's solve in the LU's precision, scaled back (float64). In single
        precision each right-hand side is first scaled by the power of two of its largest
        entry, so that rounding it to float32 neither overflows nor underflows."""
        if self.lu.dtype == np.float64:
            solution = getrs(self.lu, self.pivots, (rhs.T / self.row).T, overwrite=True)
            return solution / (self.col if rhs.ndim == 1 else self.col[:, None])
        columns = rhs.reshape(len(rhs), -1)
        single = np.empty(columns.shape, np.float32, order="F")
        sizes = _single_right_sides(columns, self.row, single)
        solution = _double_solutions(getrs(self.lu, self.pivots, single, True), sizes, self.col)
        return solution.reshape(rhs.shape)

    def solve(self, rhs, fixed, film_rows, theta=None, columns=None):
        """Solve with the rows of the nodes whose fixed state changed replaced (identity rows
        for newly fixed nodes, ``film_rows(indices)`` for newly free ones) and the columns of
        the nodes whose ``theta`` state changed replaced by ``columns(indices)`` (the current
        matrix's, (N, k); ``theta`` None: no column changes). A node whose row and column both
        change, or more than MAX_CHANGES changes, raise TooManyChanges."""
        rows = (fixed != self.fixed).nonzero()[0]
        cols = (theta != self.theta).nonzero()[0] if theta is not None else rows[:0]
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
