"""Variable-step BDF time stepping: the formulas, the predictor and the step-size control.

Time T is scaled by x0/V0. For accepted times t_n > t_{n-1} > ... the BDF formula of order q
approximates dy/dT at a new time t from the polynomial through (t, y) and the q latest accepted
values; the same polynomial through q + 1 past values, extrapolated, predicts y(t), and the
difference between corrector and predictor, weighted by Milne's device, estimates the local
error. The stepper knows nothing of what y is: the problem (:mod:`ehdfem.motion.normal`) gives the
values and the scale of each error.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..settings import setting, validate

PREDICTOR_DEGREE = 3  # the highest degree of the polynomial that starts Newton (BDFStepper.guess)
# the Newton error left in a step by default, a share of rtol: 1e-5 at the default rtol, where
# 1e-7 took 16-37 % more Newton sweeps for outputs that agree to 2e-7 (docs/performance.md)
NEWTON_SHARE = 0.05
# the precisions of the Newton matrix's LU (IntegratorOptions.lu_precision)
LU_PRECISIONS = ("mixed", "double")


@dataclass(frozen=True)
class IntegratorOptions:
    """Accuracy and limits of the time integration (all scaled).

    ``rtol``: local error per step in X relative to the thinnest film, in V (relative to V0)
    and, with ``film_control``, in the film thickness H relative to itself, at the thinnest
    node near the thinnest film yet and in the root mean square over the nodes whose film is
    full, so that the thinnest film and the fast suction phase of the rebound are resolved;
    with ``film_control`` X is held to rtol/3 (GAP_WEIGHT of :mod:`ehdfem.motion.normal`) and,
    while the film takes up the sphere's momentum, V to rtol over 5 times the gap error a
    velocity error causes (``_momentum_weight`` there: St at a rigid sphere's stop). Without
    it only X and V are controlled, which left the minimum film thickness up to 10 % off at
    the old default rtol 5e-5 (docs/performance.md). ``order``: the highest BDF order (1 to
    5; BDF is zero-stable up to 6, and orders 3 to 5 are stable on the negative real axis,
    where the film's stiff modes lie). ``max_growth``: the largest step growth per step.
    ``newton_tol``: the error left in a step's Newton iteration, relative to the solution size
    (the latest update, or rho/(1 - rho) times it at a contraction rate rho < 1/2); None (the
    default) takes NEWTON_SHARE of rtol (:attr:`newton_tolerance`), as stiff BDF codes tie
    their Newton test to the error test, so that a tighter rtol tightens Newton with it.
    ``lu_precision``: "mixed" (the default) factorises the Newton matrix in single precision
    until an update from it would close the film (or a step's Newton iteration fails), then in
    double precision for the rest of the collision; "double" always in double precision
    (:mod:`ehdfem.motion.implicit_step`; the residual, hence the solution, is double precision
    either way). ``first_step``: initial time step (by x0 / V0). ``max_time``: give up after
    this scaled time (sticking by stalling).
    ``exit_gap``: the gap X (by x0) at which a rebounding sphere leaves the film model (V > 0);
    1, the layer surface, by default; above 1 only for an immersed film, which then follows the
    sphere further out (a bounce hands back to its flight where cavitation no longer acts,
    docs/bounce.md).
    """

    rtol: float = setting(
        2e-4,
        help="time-step tolerance: local error per step",
        unit="relative",
        lower=1e-10,
        upper=0.1,
    )
    film_control: bool = setting(
        True, help="control the film thickness's local error too", default_text="on"
    )
    order: int = setting(4, help="highest BDF order", lower=1, upper=5)
    max_growth: float = setting(
        1.5, help="largest step growth per step", unit="ratio", lower=1.1, upper=3.0
    )
    newton_tol: float | None = setting(
        None,
        help="Newton's error left after an update, relative to the solution size",
        unit="relative",
        lower=1e-14,
        upper=1e-3,
        default_text=f"{NEWTON_SHARE:g} rtol",
    )
    lu_precision: str = setting(
        "mixed",
        help="the Newton matrix's LU: single precision until an update would close the film "
        "(mixed), or double",
        choices=LU_PRECISIONS,
    )
    max_newton: int = setting(30, help="most Newton iterations per step", lower=2, upper=100)
    first_step: float = setting(
        1e-3, help="initial time step", unit="by x0/V0", lower=1e-12, upper=0.1
    )
    max_steps: int = setting(50000, help="most time steps", lower=10)
    max_time: float = setting(
        1e4,
        help="give up after this time (sticking by stalling)",
        unit="by x0/V0",
        lower=0.0,
        lower_open=True,
    )
    exit_gap: float = setting(
        1.0,
        help="gap at which a rebounding sphere leaves the film model (above 1: immersed only)",
        unit="by x0",
        lower=1.0,
        upper=1e3,
    )

    def __post_init__(self):
        validate(self)

    @property
    def newton_tolerance(self) -> float:
        """The Newton test's tolerance: ``newton_tol``, or NEWTON_SHARE rtol if it is None."""
        return NEWTON_SHARE * self.rtol if self.newton_tol is None else self.newton_tol


def derivative_weights(nodes):
    """Weights w_j with dy/dT(nodes[0]) ~ sum_j w_j y(nodes[j]) (derivative of the interpolant).

    This is the variable-step BDF formula of order len(nodes) - 1.
    """
    t0 = nodes[0]
    weights = np.empty(len(nodes))
    weights[0] = sum(1.0 / (t0 - tk) for tk in nodes[1:])
    for j in range(1, len(nodes)):
        others = [tk for k, tk in enumerate(nodes) if k != j]
        weights[j] = math.prod(t0 - tk for tk in others[1:]) / math.prod(
            nodes[j] - tk for tk in others
        )
    return weights


def latest(values, count):
    """The last ``count`` entries of a history list, newest first."""
    return values[-1 : -count - 1 : -1]


def interpolation_weights(nodes, t) -> list:
    """Weights l_j(t) of the Lagrange polynomials through ``nodes``: the polynomial through
    (nodes[j], y_j) is sum_j l_j(t) y_j at t (any units of time)."""
    weights = []
    for j, tj in enumerate(nodes):
        weight = 1.0
        for k, tk in enumerate(nodes):
            if k != j:
                weight *= (t - tk) / (tj - tk)
        weights.append(weight)
    return weights


def extrapolate(nodes, values, t):
    """Value at t of the polynomial through (nodes[j], values[j]) (scalars or arrays)."""
    return combine(interpolation_weights(nodes, t), values)


def combine(weights, values):
    """sum_j weights[j] values[j], summed in order (scalars or arrays)."""
    total = 0.0
    for weight, value in zip(weights, values, strict=True):
        total = total + weight * value
    return total


def step_integral(nodes, values) -> float:
    """The integral over the latest step [nodes[1], nodes[0]] (nodes newest first) of the
    polynomial through (nodes[j], values[j]), by two-point Gauss-Legendre: exact for the
    quadratic through three values, so a rate's running integral is third-order accurate. Any
    units: the result is in those of values times nodes (scaled time by x0/V0 in the solver)."""
    early, late = nodes[1], nodes[0]
    half, middle = 0.5 * (late - early), 0.5 * (late + early)
    offset = half / math.sqrt(3.0)
    gauss = (middle - offset, middle + offset)
    return half * sum(extrapolate(nodes, values, t) for t in gauss)


def crossing(nodes, values, level: float) -> float:
    """The time in [nodes[1], nodes[0]] (the two newest of ``nodes``, newest first) where the
    polynomial through (nodes[j], values[j]) reaches ``level``, which lies between values[1]
    and values[0]: the dense output's event time, by bisection to rounding."""
    early, late = nodes[1], nodes[0]
    rising = values[0] > values[1]
    for _ in range(60):
        middle = 0.5 * (early + late)
        if (extrapolate(nodes, values, middle) < level) == rising:
            early = middle
        else:
            late = middle
    return 0.5 * (early + late)


def peak(times, values, end=math.inf) -> tuple[float, float]:
    """(time, value) of the largest of ``values`` at the accepted ``times``, refined by the
    dense output: the vertex of the parabola through the largest value and its two
    neighbours, when it lies between them (error O(step^3) instead of O(step^2)). Up to the
    time ``end``: where it lies inside the last step (an exit's or a stop's crossing), that
    step's value is the dense output's at ``end`` (the polynomial through the three latest
    values), as the exit velocity is, so that a history still growing at the end is not read
    past it."""
    if end < times[-1]:
        last = extrapolate(times[-3:], values[-3:], end)
        times, values = np.r_[times[:-1], end], np.r_[values[:-1], last]
    i = int(np.argmax(values))
    if not 0 < i < len(values) - 1:
        return float(times[i]), float(values[i])
    (t0, t1, t2), (y0, y1, y2) = times[i - 1 : i + 2], values[i - 1 : i + 2]
    slope_left, slope_right = (y1 - y0) / (t1 - t0), (y2 - y1) / (t2 - t1)
    curvature = (slope_right - slope_left) / (t2 - t0)  # half the second derivative
    if curvature >= 0:
        return float(t1), float(y1)
    vertex = 0.5 * (t0 + t1) - slope_left / (2 * curvature)
    if not t0 <= vertex <= t2:
        return float(t1), float(y1)
    return float(vertex), float(extrapolate([t0, t1, t2], [y0, y1, y2], vertex))


def error_share(t_new, past):
    """Share of (corrector - predictor) that is the local error of BDF of order len(past) - 1.

    Both differ from the exact solution by y^(q+1)/(q+1)! times a product of time differences:
    prod_{j<=q} d_j / sum_{j<=q} 1/d_j for BDF-q and prod_{j<=q+1} d_j for the extrapolation
    through q+1 past points (d_j = t_new - t_{n+1-j}); Milne's device splits the difference.
    """
    d = [t_new - t for t in past]  # Python floats: numpy's calls cost more than the arithmetic
    q = len(past) - 1
    bdf = math.prod(d[:q]) / sum(1.0 / x for x in d[:q])
    predictor = math.prod(d)
    return bdf / (bdf + predictor)


class BDFStepper:
    """Order, weights, predictor, error estimate and step size of a variable-step BDF
    integration over the accepted times ``times`` (a list the caller appends to), from the
    latest :meth:`restart` on (the first time at the start)."""

    def __init__(self, options: IntegratorOptions, times: list):
        self.options, self.times = options, times
        self.step = options.first_step
        self.first = 0  # the index of the first accepted time the history may use
        self._kept_weights = (None, None)  # (key, weights) of _predictor_weights

    def restart(self, step: float) -> None:
        """Start a new history at the latest accepted time, whose values are a new initial
        state (after a jump of an unknown, such as the velocity at a solid impact), with the
        time step ``step``: the order drops to 1 and climbs again."""
        self.first = len(self.times) - 1
        self.step = step

    def _known(self) -> int:
        """The accepted times since the start or the latest restart."""
        return len(self.times) - self.first

    def order(self) -> int:
        """BDF order of the next step: order q uses q past values (the predictor q + 1)."""
        return min(self.options.order, max(self._known() - 1, 1))

    def weights(self, t_new: float, order: int) -> np.ndarray:
        """step * (BDF weights at t_new): weights[0] multiplies y(t_new), the rest the
        ``order`` latest accepted values, newest first."""
        return self.step * derivative_weights([t_new, *latest(self.times, order)])

    def past(self, weights, recent) -> list:
        """The weighted sums of earlier values: ``recent`` holds, per unknown, its ``order``
        latest accepted values, newest first."""
        return [weights[1:] @ np.asarray(values) for values in recent]

    def guess(self, t_new, histories, order) -> list:
        """Newton's start: each history extrapolated by the polynomial of the step's ``order``
        through its latest accepted values, but at most cubic (PREDICTOR_DEGREE). The
        quadratic it replaced started a step's Newton iteration 10-100 times further from the
        solution; a quartic overshoots where a cavity's edge or the wetted edge passes a node
        (a kink in that node's pressure), which cost a truncated cavity 15 % more steps."""
        known = min(self._known(), min(order, PREDICTOR_DEGREE) + 1)
        weights = self._predictor_weights(t_new, known)
        return [combine(weights, latest(values, known)) for values in histories]

    def error_share(self, t_new, order) -> float | None:
        """The share of (corrector - predictor) that is the local error of the step to t_new
        (Milne's device, :func:`error_share`); None while there are too few accepted values
        for the predictor."""
        if self._known() <= order:
            return None
        return error_share(t_new, latest(self.times, order + 1))

    def correction(self, t_new, order, history, new):
        """corrector - predictor: ``new`` (a scalar or an array), the value at t_new of the
        unknown whose accepted values are ``history``, minus the extrapolation of its order + 1
        latest values."""
        return np.asarray(new) - combine(
            self._predictor_weights(t_new, order + 1), latest(history, order + 1)
        )

    def _predictor_weights(self, t_new, count) -> list:
        """The Lagrange weights at t_new through the ``count`` latest accepted times, kept for
        the step's (t_new, count): the guesses of P, X and V and the errors of X, V and H ask
        for the same ones."""
        key = (t_new, count, len(self.times))
        if self._kept_weights[0] != key:
            self._kept_weights = (key, interpolation_weights(latest(self.times, count), t_new))
        return self._kept_weights[1]

    def reject(self, error: float, order: int) -> None:
        """Shrink the step after a rejected one (error > 1)."""
        self.step *= max(0.2, 0.8 * error ** (-1.0 / (order + 1)))

    def fail(self) -> None:
        """Shrink the step after a failed nonlinear solve."""
        self.step *= 0.25

    def accept(self, error: float, order: int) -> None:
        """The next step after an accepted one, grown by at most ``max_growth``."""
        growth = self.options.max_growth if error == 0.0 else 0.8 * error ** (-1.0 / (order + 1))
        self.step *= min(max(growth, 0.2), self.options.max_growth)
