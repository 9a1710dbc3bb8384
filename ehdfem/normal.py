"""Normal motion: the Reynolds film, the elastic solids and the sphere, integrated in time.

Scaled unknowns (DSH 1986): pressure P(R, T) (by mu V0 a / x0^2) at the film nodes, the gap X(T)
between the undeformed surfaces on the axis (by x0) and the normal velocity V(T) (by V0, < 0
while approaching). With the compliance C of the solids (W = C P, by x0),

    H = X + R^2/2 + C P,     m dH/dT + K(H) P = 0  (film),
    St dV/dT = F = (1/3) int P R dR,     dX/dT = V,     X(0) = 1, V(0) = -1, P(0) = 0.

Time integration: variable-step BDF2 (BDF1 on the first step), one monolithic Newton solve for
(P, X, V) per step with a dense Jacobian (the compliance makes it dense), cavitation as a
semismooth-Newton complementarity, and the step chosen from a local error estimate on X and V
(relative to the thinnest film) against a quadratic predictor. The integrator only sees
``compliance.radii`` and ``compliance.matrix``: half-space kernel or finite-element solids alike.

Events: the sphere leaves the layer when X returns to 1 with V > 0 (exit); it sticks when its
velocity returns to <= 0 after it had started to rebound, or when it comes to rest (|V| below
1e-10 or the time limit); e_n = e_dry * V_exit (DESIGN.md: e_dry = 1 is pure EHD).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import partial
from typing import TYPE_CHECKING

import numpy as np
import scipy.linalg

from . import checks
from .film import Film, FilmError, FilmState

if TYPE_CHECKING:
    from .scales import CollisionParameters

REST_VELOCITY = 1e-10  # |V| below which the sphere is at rest (scaled by V0)
CLOSED_FILM = 1e-8  # film thickness (by x0) taken as closed when a step then fails


class NormalSolverError(RuntimeError):
    """The time integration failed; the message carries time, step size and residual."""


class FilmClosedError(NormalSolverError):
    """The film thickness collapsed (below CLOSED_FILM) and the step failed: either the solids
    are about to touch or the grid does not resolve the thin rim of the flattened contact."""


@dataclass(frozen=True)
class IntegratorOptions:
    """Accuracy and limits of the normal integrator (all scaled).

    ``rtol``: local error per step in X relative to the thinnest film and in V (relative to V0).
    ``newton_tol``: Newton increments relative to the solution size. ``first_step``: initial
    time step (by x0 / V0). ``max_time``: give up after this scaled time (sticking by stalling).
    """

    rtol: float = 5e-5
    order: int = 3
    max_growth: float = 1.5
    newton_tol: float = 1e-7
    max_newton: int = 30
    first_step: float = 1e-3
    max_steps: int = 50000
    max_time: float = 1e4

    def __post_init__(self):
        checks.number("rtol", self.rtol, lower=1e-10, upper=0.1)
        checks.integer("order", self.order, lower=1, upper=3)
        checks.number("max_growth", self.max_growth, lower=1.1, upper=3.0)
        checks.number("newton_tol", self.newton_tol, lower=1e-14, upper=1e-3)
        checks.integer("max_newton", self.max_newton, lower=2, upper=100)
        checks.number("first_step", self.first_step, lower=1e-12, upper=0.1)
        checks.integer("max_steps", self.max_steps, lower=10)
        checks.positive("max_time", self.max_time)


@dataclass
class NormalHistory:
    """Time histories at the accepted steps (scaled as in the module docstring).

    ``force`` by 6 pi mu V0 a^2 / x0; energies by m V0^2 / St (kinetic = St V^2 / 2, so the
    initial kinetic energy is St / 2); ``pressure``, ``fill`` and ``film_thickness`` are
    (steps, nodes): ``fill`` is the liquid fraction theta of the gap (1 where the film is full,
    and everywhere but in mass-conserving cavities), so theta H is the liquid per area (by x0).
    """

    time: list = field(default_factory=list)
    gap: list = field(default_factory=list)
    velocity: list = field(default_factory=list)
    force: list = field(default_factory=list)
    central_film: list = field(default_factory=list)
    min_film: list = field(default_factory=list)
    edge_radius: list = field(default_factory=list)
    kinetic: list = field(default_factory=list)
    elastic: list = field(default_factory=list)
    dissipated: list = field(default_factory=list)
    pressure: list = field(default_factory=list)
    fill: list = field(default_factory=list)
    film_thickness: list = field(default_factory=list)

    def arrays(self):
        """Convert every history to a numpy array in place; returns self."""
        for name, values in vars(self).items():
            setattr(self, name, np.asarray(values))
        return self


@dataclass
class NormalResult:
    """Outcome of the normal collision (scaled; see the module docstring).

    ``rebound``: the sphere left the layer (X back to 1 with V > 0). ``exit_velocity``: V there
    (the pure EHD restitution), ``e_n`` = e_dry * exit_velocity (0 if it sticks).
    ``max_rebound_velocity``: the largest V > 0 reached (DSH 1986's restitution for immersed
    spheres). ``min_film_thickness``: min over R and T of H (by x0). ``max_force``: by
    6 pi mu V0 a^2 / x0. ``contact_time``: from first touch of the layer to exit (or to the
    stop for a sticking sphere), by x0 / V0. ``max_compression``: -min X (by x0; positive once
    the undeformed surfaces overlap). ``energy_error``: |KE0 - KE - E_el - dissipation| / KE0
    at the end (meaningful without cavitation). ``status``: "rebound", "stick" or "stalled".
    ``rtol``: the local time-step tolerance used (with ``energy_error``, the achieved accuracy).
    """

    params: CollisionParameters
    radii: np.ndarray
    history: NormalHistory
    rebound: bool
    status: str
    exit_velocity: float
    e_n: float
    max_rebound_velocity: float
    min_film_thickness: float
    max_force: float
    contact_time: float
    max_compression: float
    energy_error: float
    steps: int
    rejected_steps: int
    newton_iterations: int
    rtol: float


def _derivative_weights(nodes):
    """Weights w_j with dy/dT(nodes[0]) ~ sum_j w_j y(nodes[j]) (derivative of the interpolant).

    This is the variable-step BDF formula of order len(nodes) - 1.
    """
    t0 = nodes[0]
    weights = np.empty(len(nodes))
    weights[0] = sum(1.0 / (t0 - tk) for tk in nodes[1:])
    for j in range(1, len(nodes)):
        others = [tk for k, tk in enumerate(nodes) if k != j]
        weights[j] = np.prod([t0 - tk for tk in others[1:]]) / np.prod(
            [nodes[j] - tk for tk in others]
        )
    return weights


def _latest(values, count):
    """The last ``count`` entries of a history list, newest first."""
    return values[-1 : -count - 1 : -1]


def _extrapolate(nodes, values, t):
    """Value at t of the polynomial through (nodes[j], values[j])."""
    total = 0.0
    for j, (tj, yj) in enumerate(zip(nodes, values, strict=True)):
        others = [tk for k, tk in enumerate(nodes) if k != j]
        total = total + yj * np.prod([(t - tk) / (tj - tk) for tk in others])
    return total


def _error_share(t_new, past):
    """Share of (corrector - predictor) that is the local error of BDF of order len(past) - 1.

    Both differ from the exact solution by y^(q+1)/(q+1)! times a product of time differences:
    prod_{j<=q} d_j / sum_{j<=q} 1/d_j for BDF-q and prod_{j<=q+1} d_j for the extrapolation
    through q+1 past points (d_j = t_new - t_{n+1-j}); Milne's device splits the difference.
    """
    d = t_new - np.asarray(past)
    q = len(past) - 1
    bdf = np.prod(d[:q]) / np.sum(1.0 / d[:q])
    predictor = np.prod(d)
    return bdf / (bdf + predictor)


class _Newton:
    """One implicit time step: Newton on (P, X, V) with cavitation complementarity.

    The dense Jacobian is factorised only when needed (simplified Newton): a factorisation is
    reused across iterations and steps while the dry and cavitated nodes are unchanged, a0/dt has
    not moved by more than 20 % and the iteration contracts by at least a factor of 2.
    """

    def __init__(self, film: Film, compliance_matrix: np.ndarray, St: float, options):
        self.film = film
        self.compliance = compliance_matrix
        self.compliance_diagonal = np.diag(compliance_matrix).copy()
        self.St = St
        self.options = options
        self.half_r2 = 0.5 * film.radii**2
        self.factor = None
        self.factorisations = 0

    def thickness(self, pressure, gap):
        return gap + self.half_r2 + self.compliance @ pressure

    def solve(self, guess, step, a0, past):
        """Newton for one step of dy/dT ~ (a0 y + past_y) / step, where past_y is the weighted
        sum of earlier values of y = (theta H, X, V). ``guess``: (P, X, V, theta, cavitated).
        Returns (P, X, V, theta, cavitated, state, iterations) or raises _StepFailed.

        The node unknown is P, except at nodes cavitated under the mass-conserving model, where
        it is the liquid fraction theta (P = P_cav there)."""
        content_hist, x_hist, v_hist = past
        pressure, gap, velocity, fill, cavitated = guess
        mass_conserving = self.film.mass_conserving
        if not mass_conserving:
            fill, cavitated = np.ones_like(pressure), np.zeros(len(pressure), bool)
        previous_sets = previous_norm = None
        refresh = False
        for iteration in range(1, self.options.max_newton + 1):
            h = self.thickness(pressure, gap)
            if h.min() <= 0.0:
                raise _StepFailed("film thickness not positive", np.nan)
            state = self.film.assemble(h, pressure)
            if mass_conserving:  # a cavity the wetted edge passed over is dry, not cavitated
                fill, cavitated = np.where(state.dry, 1.0, fill), cavitated & ~state.dry
            residual = state.mass * (a0 * fill * h + content_hist) / step + state.flux(pressure)
            if not mass_conserving:
                scale = state.mass * a0 / step * self.compliance_diagonal + state.conductance[1]
                cavitated = self.film.cavitated(
                    pressure, residual, np.where(scale > 0, scale, 1.0), state.dry
                )
                residual[cavitated] = pressure[cavitated] - self.film.p_cav
            residual[state.dry] = pressure[state.dry]
            r_gap = a0 * gap + x_hist - step * velocity
            r_vel = self.St * (a0 * velocity + v_hist) - step * (state.force_weights @ pressure)
            rhs = -np.concatenate([residual, [r_gap, r_vel]])
            # truncation fixes P in rows; a mass-conserving cavity swaps P for theta (columns)
            fixed = state.dry if mass_conserving else state.dry | cavitated
            theta_nodes = cavitated if mass_conserving else np.zeros_like(cavitated)
            sets = (int((~state.dry).sum()), fixed.tobytes(), theta_nodes.tobytes())
            stale = self.factor is None or self.factor.columns != sets[2]
            if refresh or stale or abs(self.factor.rate * step / a0 - 1.0) > 0.3:
                self._factorise(state, fixed, step, a0, fill, h, theta_nodes)
                refresh = False
            rows = partial(self._rows, state, step=step, a0=a0, fill=fill, theta_nodes=theta_nodes)
            try:
                update = self.factor.solve(rhs, fixed, rows)
            except _TooManyChanges:
                self._factorise(state, fixed, step, a0, fill, h, theta_nodes)
                update = self.factor.solve(rhs, fixed, None)
            n = len(pressure)
            d_node, d_gap, d_velocity = update[:n], update[n], update[n + 1]
            d_pressure = np.where(theta_nodes, 0.0, d_node)
            d_fill = np.where(theta_nodes, d_node, 0.0)
            damping = 1.0
            while self.thickness(pressure + damping * d_pressure, gap + damping * d_gap).min() <= 0:
                damping *= 0.5
                if damping < 1e-3:
                    raise _StepFailed("Newton update closes the film", np.abs(rhs).max())
            pressure = pressure + damping * d_pressure
            fill = fill + damping * d_fill
            gap += damping * d_gap
            velocity += damping * d_velocity
            norm = max(
                np.abs(d_pressure).max() / (np.abs(pressure).max() + 1.0),
                np.abs(d_fill).max(),
                abs(d_gap) / max(h.min(), 1e-12),
                abs(d_velocity) / (abs(velocity) + 1e-3),
            )
            if mass_conserving:
                diagonal = state.conductance[1]
                stiffness = state.mass * a0 * h / (step * np.where(diagonal > 0, diagonal, 1.0))
                pressure, fill, cavitated = self.film.switch(
                    pressure, fill, cavitated, state.dry, stiffness
                )
                sets = (*sets[:2], cavitated.tobytes())
            if norm <= self.options.newton_tol and damping == 1.0 and sets == previous_sets:
                return pressure, gap, velocity, fill, cavitated & mass_conserving, state, iteration
            if previous_norm is not None and sets == previous_sets:
                # refresh a stale factorisation when its contraction would need > 6 more sweeps
                # (not while the fixed nodes move: that slows the iteration whatever the matrix)
                ratio = norm / previous_norm
                tol = self.options.newton_tol
                refresh = ratio >= 1.0 or (ratio > 0.1 and np.log(tol / norm) / np.log(ratio) > 6)
            previous_sets, previous_norm = sets, norm
        self.factor = None
        raise _StepFailed("Newton did not converge", np.abs(rhs).max())

    def _factorise(self, state, fixed, step, a0, fill, h, theta_nodes):
        """A new LU of the Jacobian; at ``theta_nodes`` (mass-conserving cavities) the unknown
        is theta, whose column is d(residual_i)/d(theta_i) = m_i a0 H_i / dt."""
        jacobian = self._jacobian(state, fixed, step, a0, fill)
        nodes = np.flatnonzero(theta_nodes)
        jacobian[:, nodes] = 0.0
        jacobian[nodes, nodes] = state.mass[nodes] * a0 * h[nodes] / step
        self.factor = _Factorisation(jacobian, fixed, a0 / step, theta_nodes.tobytes())
        self.factorisations += 1

    def _rows(self, state: FilmState, rows, *, step, a0, fill=1.0, theta_nodes=None):
        """Film rows of the Jacobian, d(m d(theta H)/dT + K(H, P) P)_i/d(P, X, V) =
        ((m theta a0/dt + D) C + K + E, (m theta a0/dt + D) 1, 0), for the node indices
        ``rows`` (E: the viscosity's d(K P)/dP - K), none of them in ``theta_nodes``: the
        columns of those hold d/d(theta), which is zero off their own rows."""
        n = len(state.mass)
        lower, diag, upper = state.dflux_dH
        diag = diag + state.mass * fill * a0 / step
        below, above = np.maximum(rows - 1, 0), np.minimum(rows + 1, n - 1)
        out = np.zeros((len(rows), n + 2))
        c = self.compliance
        out[:, :n] = (
            diag[rows, None] * c[rows] + lower[rows, None] * c[below] + upper[rows, None] * c[above]
        )
        j = np.arange(len(rows))
        for k_low, k_diag, k_up in (state.conductance, state.dflux_dP):
            out[j, rows] += k_diag[rows]
            out[j, below] += k_low[rows]
            out[j, above] += k_up[rows]
        out[:, n] = lower[rows] + diag[rows] + upper[rows]
        if theta_nodes is not None:
            out[:, np.flatnonzero(theta_nodes)] = 0.0
        return out

    def _jacobian(self, state: FilmState, fixed, step, a0, fill):
        """d(residual)/d(P, X, V): film rows, identity rows at fixed nodes, the X and V rows."""
        n = len(state.mass)
        jac = np.zeros((n + 2, n + 2))
        jac[:n] = self._rows(state, np.arange(n), step=step, a0=a0, fill=fill)
        fixed_rows = np.flatnonzero(fixed)
        jac[fixed_rows, :] = 0.0
        jac[fixed_rows, fixed_rows] = 1.0
        jac[n, n], jac[n, n + 1] = a0, -step
        jac[n + 1, :n] = -step * state.force_weights
        jac[n + 1, n + 1] = self.St * a0
        return jac


class _TooManyChanges(Exception):
    pass


class _Factorisation:
    """LU of a Jacobian, reusable after some nodes became fixed or free.

    The matrix is equilibrated (columns, then rows, scaled to unit max norm) before the LU:
    pressures (up to ~1e8 near a rigid stop), the gap (~1e-4) and the velocity (~1) differ by
    many orders of magnitude. When the fixed nodes (dry or cavitated) differ from those the LU
    was built for, the changed rows are a rank-k correction applied by the Woodbury identity.
    ``rate`` is the a0/dt the matrix was built for, ``columns`` the mass-conserving cavitated
    nodes (as bytes) whose columns it holds for theta.
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
            raise _StepFailed(f"singular Newton matrix ({err})", np.nan) from err

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
            raise _TooManyChanges
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
            raise _TooManyChanges from err


class _StepFailed(Exception):
    def __init__(self, reason, residual):
        super().__init__(reason)
        self.reason, self.residual = reason, residual


def solve_normal(params: CollisionParameters, compliance, options: IntegratorOptions | None = None):
    """Integrate the normal collision from first touch of the layer to exit or sticking.

    ``params``: dimensionless inputs (St, e_dry, layer, p_cav are used here; eps is already in
    the compliance). ``compliance``: any object with ``radii`` (film nodes, by sqrt(a x0)) and
    ``matrix`` (W = matrix @ P, by x0 per mu V0 a / x0^2). Returns a :class:`NormalResult`.
    """
    options = options or IntegratorOptions()
    radii = np.asarray(compliance.radii, dtype=float)
    film = Film(radii, params.layer, params.p_cav, params.cavitation, params.viscosity_law())
    newton = _Newton(film, np.asarray(compliance.matrix, dtype=float), params.St, options)
    n = len(radii)

    hist = NormalHistory()
    pressure, gap, velocity, fill = np.zeros(n), 1.0, -1.0, np.ones(n)
    cavitated = np.zeros(n, bool)
    h = newton.thickness(pressure, gap)
    _record(hist, 0.0, gap, velocity, pressure, fill, h, film.assemble(h, pressure), 0.0, newton)
    dissipation_rate = 0.0
    step = options.first_step
    rejected = iterations = 0
    rebounding = False
    status = None
    exit_time = exit_velocity = np.nan
    while status is None:
        if len(hist.time) > options.max_steps:
            raise NormalSolverError(
                f"more than {options.max_steps} steps at T = {hist.time[-1]:.6g}"
            )
        t_old = hist.time[-1]
        t_new = t_old + step
        # order q uses q past values; the predictor for the error estimate needs q + 1
        order = min(options.order, max(len(hist.time) - 1, 1))
        weights = step * _derivative_weights([t_new, *_latest(hist.time, order)])
        content = np.array(_latest(hist.fill, order)) * np.array(
            _latest(hist.film_thickness, order)
        )
        past = [
            weights[1:] @ values
            for values in (
                content,
                *(np.array(_latest(values, order)) for values in (hist.gap, hist.velocity)),
            )
        ]
        known = min(len(hist.time), 3)
        guess = [
            _extrapolate(_latest(hist.time, known), _latest(values, known), t_new)
            for values in (hist.pressure, hist.gap, hist.velocity)
        ]
        guess[0] = np.where(cavitated, film.p_cav, guess[0])
        try:
            new_p, new_x, new_v, new_fill, new_cavitated, state, its = newton.solve(
                (*guess, hist.fill[-1], cavitated), step, weights[0], past
            )
        except (_StepFailed, FilmError) as failure:
            if hist.min_film[-1] < CLOSED_FILM:
                i = int(np.argmin(hist.film_thickness[-1]))
                raise FilmClosedError(
                    f"film closed at T = {t_old:.6g}: H = {hist.min_film[-1]:.3g} at R = "
                    f"{radii[i]:.4g} (X = {gap:.4g}, V = {velocity:.4g}); refine the film grid"
                ) from failure
            rejected += 1
            step *= 0.25
            if step < 1e-14 * max(1.0, t_old):
                residual = getattr(failure, "residual", np.nan)
                raise NormalSolverError(
                    f"time step underflow at T = {t_old:.6g}, dt = {step:.3g}: {failure}"
                    f" (residual {residual:.3g})"
                ) from failure
            continue
        iterations += its
        new_h = newton.thickness(new_p, new_x)
        error = 0.0
        if len(hist.time) > order:
            nodes = _latest(hist.time, order + 1)
            share = _error_share(t_new, nodes)
            predicted_x = _extrapolate(nodes, _latest(hist.gap, order + 1), t_new)
            predicted_v = _extrapolate(nodes, _latest(hist.velocity, order + 1), t_new)
            h_min = max(min(hist.min_film[-1], new_h.min()), 1e-12)
            error = share * max(abs(new_x - predicted_x) / h_min, abs(new_v - predicted_v))
            error /= options.rtol
        if error > 1.0:
            rejected += 1
            step *= max(0.2, 0.8 * error ** (-1.0 / (order + 1)))
            continue
        new_rate = film.dissipation_rate(state, new_p)
        dissipated = hist.dissipated[-1] + 0.5 * step * (dissipation_rate + new_rate)
        dissipation_rate = new_rate
        old_x, old_v = gap, velocity
        pressure, gap, velocity, h = new_p, new_x, new_v, new_h
        cavitated = new_cavitated
        _record(hist, t_new, gap, velocity, pressure, new_fill, h, state, dissipated, newton)
        rebounding = rebounding or velocity > 0
        if gap >= 1.0 and velocity > 0:
            fraction = (1.0 - old_x) / (gap - old_x)
            exit_time = t_old + fraction * step
            exit_velocity = old_v + fraction * (velocity - old_v)
            status = "rebound"
        elif rebounding and velocity <= 0:
            status = "stick"
        elif abs(velocity) < REST_VELOCITY:
            status = "stick"
        elif t_new > options.max_time:
            status = "stalled"
        growth = options.max_growth if error == 0.0 else 0.8 * error ** (-1.0 / (order + 1))
        step *= min(max(growth, 0.2), options.max_growth)
    hist.arrays()
    rebound = status == "rebound"
    kinetic0 = 0.5 * params.St
    balance = hist.kinetic[-1] + hist.elastic[-1] + hist.dissipated[-1]
    return NormalResult(
        params=params,
        radii=radii,
        history=hist,
        rebound=rebound,
        status=status,
        exit_velocity=float(exit_velocity) if rebound else 0.0,
        e_n=params.e_dry * float(exit_velocity) if rebound else 0.0,
        max_rebound_velocity=float(max(hist.velocity.max(), 0.0)),
        min_film_thickness=float(hist.min_film.min()),
        max_force=float(hist.force.max()),
        contact_time=float(exit_time if rebound else hist.time[-1]),
        max_compression=float(-hist.gap.min()),
        energy_error=float(abs(kinetic0 - balance) / kinetic0),
        steps=len(hist.time) - 1,
        rejected_steps=rejected,
        newton_iterations=iterations,
        rtol=options.rtol,
    )


def _record(hist, time, gap, velocity, pressure, fill, h, state: FilmState, dissipated, newton):
    hist.time.append(time)
    hist.gap.append(gap)
    hist.velocity.append(velocity)
    hist.force.append(float(state.force_weights @ pressure))
    hist.central_film.append(h[0])
    hist.min_film.append(h.min())
    hist.edge_radius.append(state.edge_radius)
    hist.kinetic.append(0.5 * newton.St * velocity**2)
    compliance, mass = newton.compliance, newton.film.full_mass
    hist.elastic.append(float(mass * pressure @ (compliance @ pressure)) / 6.0)
    hist.dissipated.append(dissipated)
    hist.pressure.append(pressure)
    hist.fill.append(fill)
    hist.film_thickness.append(h)
