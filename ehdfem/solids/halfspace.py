"""Two elastic half-spaces: the axisymmetric ring-load kernel at the film nodes.

An axisymmetric pressure on two elastic half-spaces (sphere and wall, combined through
theta = sum (1 - nu^2)/(pi E)) opens the gap by, in scaled form (W by x0; R, S by sqrt(a x0);
P by mu V0 a / x0^2),

    W(R) = eps * int_0^inf P(S) S/(R+S) K(m) dS,    m = 4 R S / (R+S)^2,

with K the complete elliptic integral of the first kind (parameter m). K has a logarithmic
singularity at S = R: K ~ ln 4 - ln|1 - m| / 2.

For a pressure that is piecewise linear on the film nodes (hat functions phi_j, the last one a
half hat, zero beyond), W_i = eps * sum_j A_ij P_j with A_ij = int phi_j(S) S/(R_i+S) K dS. Each
cell at least one of its lengths away from R_i is integrated by Gauss-Legendre: 8 points up to
MIDDLE_CELLS lengths away, 6 up to FAR_CELLS, 4 beyond. The logarithm at S = R_i, d cell lengths
away, bounds the error of n points by about (4 d + 2)^(-2n) of the cell's integral (at d = 3
with 6 points and at d = 20 with 4 it is below 1e-14), and the matrices (the pressure's and the
mode-1 response's) agree with 16 points everywhere to 7e-15 of their largest entry, as with 8
points everywhere, from 38 % fewer points. Cells that touch R_i or are closer than their length
are integrated by a composite Gauss rule graded geometrically towards the end nearest R_i, which
resolves the logarithm (or its near presence on strongly non-uniform grids) to ~1e-12 without
adaptive quadrature.

The film's squeeze flow also drags both surfaces radially, by the same traction tau = -(h/2)
dp/dr in the flow direction on each (:meth:`ehdfem.film.reynolds.Film.squeeze_shear`). Summing
Cerruti's point-force solution over rings (Johnson, Contact Mechanics, ch. 3), a radial surface
traction q(s) on a half-space lifts its surface at r out of the solid by (1 - 2 nu)/(2 G)
int_r^inf q(s) ds; rings inside r do not move it. (The sign follows from Betti's reciprocity
with the inward radial displacement (1 - 2 nu) F / (4 pi G r) of a surface indented by a
normal force F.) The two surfaces are loaded alike and each rises out of its own solid
towards the film, so an outflow closes the gap by the sum over both solids, also for identical
materials: the loading is symmetric about the mid-plane. Only equal and opposite tractions,
such as the Couette shear of sliding, leave the gap of identical solids unchanged. Scaled,
with T = -(H/2) dP/dR by sqrt(delta) mu V0 a / x0^2,

    W_shear(R) = -eps sqrt(delta) kappa int_R^inf T dS,
    kappa = (pi/4) sum (1 - 2 nu)(1 + nu)/E / sum (1 - nu^2)/E   (0.449 for nu = 0.3).

The same pressure moves each face radially towards the axis (Johnson, Contact Mechanics,
1985, eq. 3.41b for the Hertz pressure; rings outside r do not move it):
u_r(r) = -((1 - 2 nu)(1 + nu)/(E r)) int_0^r p(s) s ds. Both faces are pressed into their own
solids and both move inwards, so their mean radial displacement U (by x0), which carries liquid
in the film's flux (docs/model.md, "Tangential surface effects at order sqrt(delta)"), is, with
eps = 4 theta mu V0 a^(3/2) / x0^(5/2),

    U(R) = -eps (kappa/2) (1/R) int_0^R P(S) S dS     (the same kappa, for any two solids).

The mean radial displacement by the squeeze shear is O(sqrt(delta) H/R) smaller still (its flux
is of second order) and is not formed.

The theory's own range: the half-spaces and the paraboloid gap stand for a sphere whose
loaded region is small against its radius. :func:`halfspace_range` measures, over a collision,
the largest compression and the radius that carries the film force, both by a, and flags the
result beyond COMPRESSION_LIMIT or LOAD_RADIUS_LIMIT (docs/model.md, "Range of the half-space
theory").
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numba import njit
from scipy.integrate import cumulative_trapezoid
from scipy.special import ellipkm1

from ..checks import InputError, number
from .compliance import FILM_REACH_LIMIT, LinearCompliance

IDENTICAL_SOLIDS = (
    (1.0, 0.3),
    (1.0, 0.3),
)  # (Young's modulus ratio, Poisson) of dimensionless runs

MIDDLE_CELLS = 3.0  # cells at least this many of their lengths from R_i take 6 Gauss points
FAR_CELLS = 20.0  # and from this many on 4 (8 nearer; module docstring)


def _gauss_rule(points: int) -> tuple[np.ndarray, np.ndarray]:
    """Gauss-Legendre's nodes and weights on [0, 1]."""
    nodes, weights = np.polynomial.legendre.leggauss(points)
    return 0.5 * (nodes + 1.0), 0.5 * weights


# Gauss's rules (nodes, weights) of the cells within MIDDLE_CELLS, within FAR_CELLS and beyond
GAUSS_RULES = (_gauss_rule(8), _gauss_rule(6), _gauss_rule(4))


def _graded_rule(levels: int = 12, ratio: float = 0.15):
    """Nodes and weights on [0, 1] for integrands with a log singularity at 0: Gauss on
    [q^(k+1), q^k], k = 0..levels-1, and on [0, q^levels]."""
    edges = np.concatenate([[0.0], ratio ** np.arange(levels, -1, -1)])
    lengths = np.diff(edges)
    nodes, weights = _gauss_rule(8)
    x = (edges[:-1, None] + lengths[:, None] * nodes).ravel()
    w = (lengths[:, None] * weights).ravel()
    return x, w


_GRADED_X, _GRADED_W = _graded_rule()


def _ring_kernel(radius, offset):
    """S/(R+S) K(m) at S = R + offset, with K from 1 - m = (offset/(R+S))^2: the offset is
    carried separately so that S next to R keeps its full relative accuracy."""
    total = 2.0 * radius + offset
    return (radius + offset) / total * ellipkm1((offset / total) ** 2)


ROWS_AT_ONCE = 8  # the nodes whose quadrature points hat_integrals forms at a time
KEPT_KERNELS = 4  # the matrices of each kind for the latest grids built that a process keeps
_kernels: dict[tuple[str, bytes], np.ndarray] = {}  # (kind, the grid's radii as bytes) -> matrix


def kept_on_grid(kind: str, radii: np.ndarray, build) -> np.ndarray:
    """``build()``, a matrix that depends on the grid ``radii`` alone, kept read-only for the
    latest KEPT_KERNELS grids of its ``kind``: the points of a sweep share a few grids (an angle
    sweep one per normal motion), and a build at 240 nodes costs some 5 ms (the pressure's
    influence matrix) to 27 ms (the mode-1 response)."""
    key = (kind, np.asarray(radii, dtype=float).tobytes())
    if key not in _kernels:
        matrix = build()
        matrix.flags.writeable = False
        mine = [k for k in _kernels if k[0] == kind]
        for old in mine[: max(len(mine) - KEPT_KERNELS + 1, 0)]:
            del _kernels[old]
        _kernels[key] = matrix
    return _kernels[key]


def influence_matrix(radii: np.ndarray) -> np.ndarray:
    """A[i, j] = int phi_j(S) S/(R_i+S) K(m) dS for hat functions on ``radii`` (W = eps A P).

    Scales: radii by sqrt(a x0); A maps P (by mu V0 a / x0^2) to W / eps (by x0). A depends on
    the grid alone and is kept (:func:`kept_on_grid`): each point of a sweep asks for its own
    twice (its normal motion's key and its collision).
    """
    r = np.asarray(radii, dtype=float)
    return kept_on_grid("pressure", r, lambda: hat_integrals(r, _ring_kernel, 1)[0])


def hat_integrals(radii, kernel, size, gauss=GAUSS_RULES):
    """M[p, i, j] = int phi_j(S) kernel(R_i, S - R_i)[p] dS for the hat functions phi_j on
    ``radii`` (by sqrt(a x0); the last hat a half hat, zero beyond). Each cell is integrated by
    Gauss-Legendre of 8, 6 or 4 points by its distance from R_i, or by the graded rule when it
    is closer to R_i than its length (module docstring; ``gauss``: the three Gauss rules, by
    distance, as GAUSS_RULES); ``kernel(radius, offset)`` takes the
    1-D arrays of every quadrature point's R_i and S - R_i and returns ``size`` values per point,
    (size, points). The nodes i are taken ROWS_AT_ONCE at a time, so that the points' arrays
    stay small and are reused: all the points of 240 nodes at once were half a million, 25 MB
    of fresh memory a build, whose page faults cost as much as the kernel's evaluation
    (docs/performance.md)."""
    r = np.asarray(radii, dtype=float)
    graded = (_GRADED_X, _GRADED_W)
    rules = (*graded, *graded, *(array for rule in gauss for array in rule))
    matrix = np.zeros((size, len(r), len(r)))
    for first in range(0, len(r), ROWS_AT_ONCE):
        rows = (first, min(first + ROWS_AT_ONCE, len(r)))
        node, cell, radius, offset, weight, to_right = _quadrature_points(r, rows, rules)
        values = np.asarray(kernel(radius, offset)).reshape(size, len(radius))
        _accumulate(matrix, values, node, cell, weight, to_right)
    return matrix


@njit(cache=True)
def _cell_rule(r, i, j) -> int:
    """The quadrature rule of cell j for node i (:func:`hat_integrals`): 0 the graded rule from
    the cell's left end, 1 from its right end (the end nearer R_i, where the cell is closer to
    R_i than its length), 2, 3 and 4 Gauss-Legendre of 8, 6 and 4 points by the cell's distance
    from R_i in its lengths (module docstring)."""
    left, right = r[j], r[j + 1]
    distance, length = max(left - r[i], r[i] - right), right - left
    if distance < length:
        return 1 if abs(r[i] - left) > abs(r[i] - right) else 0
    if distance < MIDDLE_CELLS * length:
        return 2
    return 3 if distance < FAR_CELLS * length else 4


@njit(cache=True)
def _quadrature_points(r, rows, rules):
    """Every quadrature point of :func:`hat_integrals` for the nodes i in range(*``rows``): its
    node i and cell j, R_i, the offset S - R_i (from the cell's nearer end where the graded
    rule is used, so that the points next to R_i keep their relative accuracy), its weight
    (times the cell length) and the share of the cell's right hat. ``rules``: the nodes and
    weights of the graded rule and of Gauss's 8, 6 and 4 points, as :func:`_cell_rule`
    numbers them (the graded one twice)."""
    n = len(r)
    total = 0
    for i in range(rows[0], rows[1]):
        for j in range(n - 1):
            total += len(rules[2 * _cell_rule(r, i, j)])
    node, cell = np.empty(total, np.int64), np.empty(total, np.int64)
    radius, offset = np.empty(total), np.empty(total)
    weight, to_right = np.empty(total), np.empty(total)
    k = 0
    for i in range(rows[0], rows[1]):
        for j in range(n - 1):
            left, right = r[j], r[j + 1]
            length = right - left
            rule = _cell_rule(r, i, j)
            x, w = rules[2 * rule], rules[2 * rule + 1]
            from_right = rule == 1
            start = right if from_right else left
            for q in range(len(x)):
                node[k], cell[k], radius[k] = i, j, r[i]
                if from_right:
                    offset[k] = (start - r[i]) - length * x[q]
                    to_right[k] = 1.0 - x[q]
                else:
                    offset[k] = (start - r[i]) + length * x[q]
                    to_right[k] = x[q]
                weight[k] = w[q] * length
                k += 1
    return node, cell, radius, offset, weight, to_right


@njit(cache=True)
def _accumulate(matrix, values, node, cell, weight, to_right):
    """Add to ``matrix`` (size, n, n) the terms of M[p, i, j] of :func:`hat_integrals` from the
    kernel's ``values`` (size, points) at quadrature points of :func:`_quadrature_points`."""
    size = values.shape[0]
    for k in range(len(node)):
        i, j = node[k], cell[k]
        for p in range(size):
            value = values[p, k] * weight[k]
            matrix[p, i, j] += value * (1.0 - to_right[k])
            matrix[p, i, j + 1] += value * to_right[k]


def film_nodes(radii) -> np.ndarray:
    """``radii`` (by sqrt(a x0)) as a float array, or an InputError unless they are at least 3
    finite film nodes starting at 0 and increasing strictly."""
    r = np.asarray(radii, dtype=float)
    if r.ndim != 1 or len(r) < 3:
        raise InputError("radii must be a 1-D array of at least 3 film nodes")
    if not np.all(np.isfinite(r)) or r[0] != 0.0 or np.any(np.diff(r) <= 0):
        raise InputError("radii must be finite, start at 0 and increase strictly")
    return r


def theta_shares(solids) -> tuple[float, float]:
    """Each solid's share of theta, ((1 - nu^2)/E) / sum((1 - nu^2)/E), for the (Young's
    modulus, Poisson ratio) pairs of sphere and wall (moduli in any common unit)."""
    sphere, wall = ((1 - nu**2) / e for e, nu in solids)
    return sphere / (sphere + wall), wall / (sphere + wall)


class HalfSpaceCompliance(LinearCompliance):
    """Elastic half-spaces at the film nodes: W = matrix @ P (see the module docstring).

    ``radii``: film nodes (by sqrt(a x0)), starting at 0 and strictly increasing. ``eps``: the
    elasticity parameter 4 theta mu V0 a^(3/2) / x0^(5/2) (> 0; 0 gives rigid solids).
    ``shear``: None (the squeeze shear is not applied, the asymptotic theory) or (delta,
    solids) with solids the (Young's modulus, Poisson ratio) pairs of sphere and wall: then
    ``shear_matrix`` = -eps sqrt(delta) kappa B and ``surface_radial_matrix`` =
    -eps (kappa/2) Q, the faces' mean radial displacement (module docstring; the tangential
    surface effects are switched together). ``solids``: those pairs for
    the split of the opening between the faces (each takes its share of theta,
    (1 - nu^2)/E over the sum): ``surface_sum_matrix`` = (share_sphere - share_wall) * matrix,
    None for equal shares (identical solids, the default).
    """

    model = "halfspace"

    def __init__(self, radii: np.ndarray, eps: float, shear=None, solids=None):
        radii = film_nodes(radii)
        unit_shear = unit_radial = None
        if shear is not None:
            delta, solids = shear
            kappa = shear_coefficient(solids)
            unit_shear = -np.sqrt(delta) * kappa * outer_integral_matrix(radii)
            unit_radial = -0.5 * kappa * inner_moment_matrix(radii)
        kernel = influence_matrix(radii)
        self.materials, unit_sum = solids, None
        if solids is not None:
            sphere, wall = theta_shares(solids)
            if sphere != wall:
                unit_sum = (sphere - wall) * kernel
        eps = number("eps", eps, lower=0.0)
        super().__init__(radii, kernel, eps, unit_shear, unit_sum, unit_radial)

    def factor(self, eps: float) -> float:
        """The kernel is per unit eps: C = eps * kernel."""
        return number("eps", eps, lower=0.0)


def outer_integral_matrix(radii: np.ndarray) -> np.ndarray:
    """B[i, j] = int_{R_i}^{R_N} phi_j dS for hat functions on ``radii``: (B T)_i is the
    integral of the piecewise linear T from R_i to the last node (by sqrt(a x0))."""
    r = np.asarray(radii, dtype=float)
    half = 0.5 * np.diff(r)
    matrix = np.zeros((len(r), len(r)))
    for i in range(len(r) - 1):
        matrix[i, i] += half[i]
        matrix[i, i + 1 :] += half[i:]
        matrix[i, i + 1 : -1] += half[i + 1 :]
    return matrix


def inner_moment_matrix(radii: np.ndarray) -> np.ndarray:
    """Q[i, j] = (1/R_i) int_0^{R_i} phi_j S dS for hat functions on ``radii`` (by sqrt(a x0)),
    exact for the piecewise linear P; row 0 (R = 0) is 0, the limit of (1/R) int_0^R P S dS."""
    r = np.asarray(radii, dtype=float)
    left, right = r[:-1], r[1:]
    cells = np.zeros((len(r) - 1, len(r)))
    cell = np.arange(len(r) - 1)
    cells[cell, cell] = (right - left) * (2.0 * left + right) / 6.0
    cells[cell, cell + 1] = (right - left) * (left + 2.0 * right) / 6.0
    moments = np.vstack([np.zeros(len(r)), np.cumsum(cells, axis=0)])
    moments[1:] /= r[1:, None]
    return moments


def shear_coefficient(solids=IDENTICAL_SOLIDS) -> float:
    """kappa = (pi/4) sum (1 - 2 nu)(1 + nu)/E / sum (1 - nu^2)/E over the two solids, given as
    (Young's modulus, Poisson ratio) pairs (any common unit of modulus)."""
    radial = sum((1 - 2 * nu) * (1 + nu) / e for e, nu in solids)
    normal = sum((1 - nu**2) / e for e, nu in solids)
    return np.pi / 4 * radial / normal


COMPRESSION_LIMIT = 0.1  # flag above this largest compression, by the sphere radius a
LOAD_RADIUS_LIMIT = 0.5  # flag above this load radius, by a
LOAD_SHARE = 0.95  # the load radius carries this share of the largest film force


class HalfSpaceRangeWarning(UserWarning):
    """A half-space result whose loaded region is not small against the sphere."""


@dataclass(frozen=True)
class HalfSpaceRange:
    """How far a collision strays from the half-space theory's range (dimensionless, by the
    sphere radius a): ``compression`` the largest overlap of the undeformed surfaces,
    delta max(-X); ``load_radius`` the radius within which LOAD_SHARE of the film force acts,
    at the instant of the largest force, R sqrt(delta); ``film_reach`` the radius where the
    film grid ends, R_end sqrt(delta) (0: not known). ``flagged`` beyond either limit."""

    compression: float
    load_radius: float
    film_reach: float = 0.0

    @property
    def flagged(self) -> bool:
        """True beyond COMPRESSION_LIMIT or LOAD_RADIUS_LIMIT."""
        return self.compression > COMPRESSION_LIMIT or self.load_radius > LOAD_RADIUS_LIMIT

    def warning(self) -> str:
        """The warning for a flagged collision: the FE solids where they take the film, else
        the layer thickness at which they would (they take a film reaching FILM_REACH_LIMIT a,
        so delta below (FILM_REACH_LIMIT / R_end)^2 on the same scaled grid)."""
        advice = "use the FE solids (model fem) here"
        if self.film_reach >= FILM_REACH_LIMIT:
            thinner = (FILM_REACH_LIMIT / self.film_reach) ** 2
            advice = (
                f"the FE solids take no film reaching past {FILM_REACH_LIMIT} a and this one's "
                f"grid reaches {self.film_reach:.3g} a: a layer x0 about {thinner:.2g} times "
                "this one or thinner (--delta or --layer-thickness) lets them take it; until "
                "then read the result as the asymptotic theory's"
            )
        return (
            f"the half-space theory is outside its range: largest compression "
            f"{self.compression:.3g} a (limit {COMPRESSION_LIMIT} a) and load radius "
            f"{self.load_radius:.3g} a (limit {LOAD_RADIUS_LIMIT} a); the half-spaces and the "
            f"paraboloid gap stand for a sphere only where both are small: {advice} "
            "(docs/model.md)"
        )


def load_radius(radii: np.ndarray, pressure: np.ndarray) -> float:
    """The radius (by sqrt(a x0)) within which LOAD_SHARE of the positive part of the film
    force int P R dR acts, for nodal pressures P on the film nodes ``radii`` (trapezoid rule;
    the suction does not carry the load)."""
    cumulative = cumulative_trapezoid(np.maximum(pressure, 0.0) * radii, radii, initial=0.0)
    if cumulative[-1] <= 0.0:
        return 0.0
    return float(np.interp(LOAD_SHARE * cumulative[-1], cumulative, radii))


def halfspace_range(
    radii: np.ndarray, pressure: np.ndarray, compression: float, delta: float
) -> HalfSpaceRange:
    """The :class:`HalfSpaceRange` of a collision from its film nodes ``radii`` (by
    sqrt(a x0)), its nodal pressure at the largest force (by mu V0 a / x0^2), its largest
    compression (by a) and delta = x0/a."""
    return HalfSpaceRange(
        compression=compression,
        load_radius=load_radius(radii, pressure) * float(np.sqrt(delta)),
        film_reach=float(radii[-1] * np.sqrt(delta)),
    )
