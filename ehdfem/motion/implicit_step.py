"""One implicit time step of the film, the elastic solids and the sphere: Newton on (P, X, V).

Scaled as in :mod:`ehdfem.motion.normal`: pressure P by mu V0 a / x0^2 at the film nodes, gap X by
x0, velocity V by V0, time by x0/V0. With the compliance C (W = C P, by x0) and a BDF formula
dy/dT ~ (a0 y + past_y) / dt (:mod:`ehdfem.motion.timestepping`) the step solves

    m (a0 theta H + past_(theta H)) / dt + K(H, P) P
        + sqrt(delta) B(theta H) (a0 U + past_U) / dt = 0     at the wet film nodes,
    a0 X + past_X - dt V = 0,     St (a0 V + past_V) - dt (f.P + sum_i F_i) = 0,
    H = X + S(R) + C P + C_T T(H0, P),   H0 = X + S(R) + C P,

with P = 0 at dry nodes and the rows and unknowns of the cavitation model
(:mod:`ehdfem.film.cavitation`). The last two rows and their Jacobian entries are the sphere's
(:class:`ehdfem.motion.sphere.Sphere`: f the film's force weights, F_i the applied forces,
force by 6 pi mu V0 a^2 / x0). S is the undeformed gap (:mod:`ehdfem.film.gap`; R^2/2 for the
paraboloid). C_T T is the opening by the squeeze-shear traction T = -(H/2) dP/dR
(:meth:`ehdfem.film.reynolds.Film.squeeze_shear`) when the compliance applies it: T is formed with
H0, the film without its own shear opening (the neglected product is of relative size
sqrt(delta) kappa (W_shear / H)), and the Newton matrix leaves the shear opening out (it is
O(sqrt(delta)) of the pressure's), so the simplified Newton still contracts while the residual
holds it in full. U = C_r P + C_rT T(H0, P) is the faces' mean radial displacement (by x0) when
the compliance gives it (:class:`SurfaceMotion`), and B the film's transport of the liquid it
drags (:meth:`ehdfem.film.reynolds.Film.surface_transport`); the Newton matrix holds
sqrt(delta) (a0/dt) B C_r, with B's dependence on H and T's on P and X lagged like the shear
opening (docs/model.md, "Tangential surface effects at order sqrt(delta)"). The Jacobian is
dense (the compliance couples all nodes). Each step factorises it at its first iterate (the
film's conductance goes as H^3 and changes within a step near contact, so a factorisation kept
from the step before needed some five sweeps a step instead of three, which cost more than the
LU); the LU (:class:`ehdfem.motion.reusable_lu.ReusableLU`) is reused by the step's later
iterations while they contract fast enough (simplified Newton): rows of nodes that become dry,
wet or cavitated, and the columns of nodes whose unknown switches between P and theta at a
mass-conserving cavity, are swapped in by the Woodbury identity.

Mixed precision (``lu_precision`` "mixed" of :class:`ehdfem.motion.timestepping.IntegratorOptions`,
the default): the LU is computed in single precision, at about half the cost. The residual is
formed in double precision, so the iteration converges to the same solution and stops at the
same test; the LU's rounding (6e-8 relative, times the matrix's condition) only slows its
contraction, as a kept LU's staleness does. Where the film is a small difference of large
deflections (hard impacts, H ~ 1e-6 of a deflection ~ 1e-3), an update's error in P is one
in H that can close the film: the first update that would close it (and is damped) is
formed again from an LU in double precision of the same iterate, and the rest of the
collision is in double precision, as it is after a step whose Newton iteration failed (or
whose iterate the film could not take: a pressure past the viscosity law's range) and after an
LU that single precision finds singular (redone in double at once;
docs/performance.md, "The LU in single precision").

Rough surfaces with Greenwood & Tripp's asperity pressure P_a(H) (mixed lubrication,
:mod:`ehdfem.film.asperities`): the solids carry it with the film's, H = X + S(R) + C (P + P_a(H))
(+ C_T T, T formed without the asperities' share), solved for H at every iterate; the sphere
feels both, St (a0 V + past_V) - dt (f.P + w.P_a(H) + sum_i F_i) = 0 with w = M/3 (M the film's
lumped mass over all nodes). The Newton matrix takes dH/dP = (I - C D)^-1 C in place of C,
dH/dX = (I - C D)^-1 1 in place of 1 (D = diag(dP_a/dH)) and the asperities' force's
derivatives w.D dH/d(P, X) in the sphere's row; the asperities' share of the radial surface
displacement and of the shear opening is left out.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from functools import partial

import numpy as np

from ..film.asperities import GreenwoodTripp, LoadedThickness
from ..film.elements import add_band_rows, add_banded_product, film_jacobian, tridiagonal_rows
from ..film.reynolds import Film, FilmError, FilmState
from ..kept import Kept
from .forces import SphereState
from .reusable_lu import ReusableLU, SingularMatrix, TooManyChanges
from .timestepping import IntegratorOptions

# a step whose Newton updates would close the film (and are damped) at two iterates in a row
# is retried shorter at once: at hard impacts such an iteration almost never converged and
# took some ten iterates to fail (docs/performance.md, "Where the hard impacts lose steps")
DAMPED_IN_A_ROW = 2


def _remaining(norm: float, ratio: float | None) -> float:
    """The error left after a Newton update of size ``norm`` at the contraction rate ``ratio``
    (the latest update over the one before): ratio / (1 - ratio) norm for a contracting
    iteration (the geometric series of the updates still to come), the update itself
    otherwise."""
    if ratio is None or ratio >= 0.5:
        return norm
    return ratio / (1.0 - ratio) * norm


class StepFailed(Exception):
    """The Newton iteration of one step failed; the time stepper retries with a smaller step."""

    def __init__(self, reason, residual):
        super().__init__(reason)
        self.reason, self.residual = reason, residual


@dataclass
class StepSolution:
    """The converged step: P, X, V, theta (liquid fraction), the mass-conserving cavities, the
    assembled film at the solution and the Newton iterations used (scaled)."""

    pressure: np.ndarray
    gap: float
    velocity: float
    fill: np.ndarray
    cavitated: np.ndarray
    state: FilmState
    iterations: int


@dataclass
class _Iterate:
    """The residual of one Newton iterate and the node sets it was built with."""

    rhs: np.ndarray
    state: FilmState
    motion: SphereState
    film_thickness: np.ndarray
    fixed: np.ndarray
    theta_nodes: np.ndarray
    sets: tuple


@dataclass(frozen=True)
class SurfaceMotion:
    """The faces' mean radial displacement U = C_r P (by x0, positive away from the axis; the
    part the squeeze shear causes is of second order in the flux, docs/model.md) and
    sqrt(delta), the size of the flux it carries relative to the film's: the film's rows gain
    sqrt(delta) B dU/dT (module docstring)."""

    matrix: np.ndarray
    sqrt_delta: float

    def displacement(self, pressure) -> np.ndarray:
        """U at the film nodes for nodal P (by x0)."""
        return self.matrix @ pressure


class ImplicitStep:
    """Newton for one step of the coupled system (module docstring).

    ``film``: :class:`ehdfem.film.reynolds.Film`; ``compliance_matrix``: C (by x0 per unit
    pressure); ``cavitation``: a model of :mod:`ehdfem.film.cavitation`; ``sphere``: the
    sphere's equation of motion (:class:`ehdfem.motion.sphere.Sphere`); ``shear_matrix``: C_T
    (by x0 per unit T) or None; ``surface_motion``: the surfaces' mean radial displacement
    (:class:`SurfaceMotion`) or None (not carried in the flux); ``asperities``: an asperity
    pressure law (Greenwood & Tripp's, :class:`ehdfem.film.asperities.GreenwoodTripp`; the
    impact model's obstacle, :class:`ehdfem.film.asperity_obstacle.AsperityObstacle`, loaded
    at its touch by :meth:`load_asperities`) or None (smooth surfaces, or no touch yet).
    """

    def __init__(
        self,
        film: Film,
        compliance_matrix,
        cavitation,
        sphere,
        options=None,
        shear_matrix=None,
        surface_motion: SurfaceMotion | None = None,
        asperities: GreenwoodTripp | None = None,
    ):
        self.film = film
        self.compliance = np.asarray(compliance_matrix, dtype=float)
        self._compliance_columns = np.asfortranarray(self.compliance)  # for the Newton matrix
        self._nodes = np.arange(len(self.compliance))
        self._no_load = np.ones(len(self.compliance))  # dH/dX without asperities
        self.shear = shear_matrix
        self.surface_motion = surface_motion
        if surface_motion is not None:  # C_r in column order, for the Newton matrix's rows
            self._radial_columns = np.asfortranarray(surface_motion.matrix)
        self.compliance_diagonal = np.diag(self.compliance).copy()
        self.cavitation = cavitation
        self.sphere = sphere
        self.options = options or IntegratorOptions()
        self.asperities = asperities
        self.asperity_weights = film.full_mass / 3.0
        self._loaded_at = None  # the latest iterate's H, with asperities
        self._loaded: LoadedThickness | None = None
        self.factor = None
        self.factorisations = 0
        size = len(self.compliance) + 2
        # two Newton matrices and LU workspaces (double, single), taken in turn: the one the
        # kept LU holds and the one the next matrix is formed in (fresh arrays of this size made
        # some 8 000 page faults a collision, docs/performance.md)
        self._slots = [
            (np.zeros((size, size), order="F"), np.empty(size**2), np.empty(size**2, np.float32))
            for _ in range(2)
        ]
        self.single = self.options.lu_precision == "mixed"  # the next LU in single precision
        self._kept_deflection = Kept()  # C P for the latest P
        self._kept_thickness = Kept()  # thickness_parts for the latest (P, X, loaded)

    def thickness(self, pressure, gap):
        """H = X + S(R) + C P (+ C_T T) at the film nodes (by x0)."""
        return self.thickness_parts(pressure, gap)[0]

    def _open(self, pressure, gap) -> bool:
        """The film thickness is positive at every node. The asperities' load (P_a >= 0 on
        the compliance) opens the film: it is solved for only when the film without it
        closes somewhere (where the residual checks it again)."""
        if self.thickness_parts(pressure, gap, loaded=False)[0].min() > 0:
            return True
        return self.asperities is not None and self.thickness(pressure, gap).min() > 0

    def thickness_parts(self, pressure, gap, loaded=True):
        """(H, W_shear, U): the film thickness, its shear opening C_T T(H0, P) and the faces'
        mean radial displacement C_r P (by x0; None without the shear traction, without the
        surface motion), T formed with H0 = X + S(R) + C P; with asperities H also carries
        their load, H = H0 + W_shear + C P_a(H) (unless ``loaded`` is False). Kept for the
        latest (P, X): the damping's check of an update and the next iterate's residual ask
        for the same."""
        loaded = loaded and self.asperities is not None
        return self._kept_thickness.get(
            lambda: self._thickness_parts(pressure, gap, loaded), pressure, (gap, loaded)
        )

    def _thickness_parts(self, pressure, gap, loaded):
        """:meth:`thickness_parts`, computed."""
        h0 = gap + self.film.undeformed + self._deflection(pressure)
        motion = self.surface_motion
        radial = None if motion is None else motion.displacement(pressure)
        opening = None
        if self.shear is not None:
            opening = self.shear @ self.film.squeeze_shear(h0, pressure)
            h0 = h0 + opening
        if self.asperities is not None and loaded:
            h0 = self.asperities.thickness(h0, self.compliance)
        return h0, opening, radial

    def _deflection(self, pressure) -> np.ndarray:
        """C P (by x0), kept for the latest pressure: the damping's check of an update and the
        next iterate's residual ask for the same one."""
        return self._kept_deflection.get(lambda: self.compliance @ pressure, pressure)

    def loaded(self) -> LoadedThickness | None:
        """The latest iterate's thickness under the asperities' load with its sensitivities
        (formed when the Newton matrix needs them); None without asperities."""
        if self._loaded_at is None:
            return None
        if self._loaded is None:
            self._loaded = self.asperities.loaded(self._loaded_at, self.compliance)
        return self._loaded

    def load_asperities(self, law) -> None:
        """Let the asperity pressure ``law`` act from the next step on (the impact model's
        obstacle, switched on at the asperities' touch; :mod:`ehdfem.film.asperity_obstacle`)."""
        self.asperities = law
        self._loaded_at = self._loaded = None
        self._kept_thickness.clear()

    def asperity_force(self, h) -> float:
        """The asperities' force on the sphere w.P_a(H) (by 6 pi mu V0 a^2 / x0; 0 without)."""
        if self.asperities is None:
            return 0.0
        return float(self.asperity_weights @ self.asperities.pressure(h))

    def solve(self, guess, step, a0, past, time) -> StepSolution:
        """Newton for one step of dy/dT ~ (a0 y + past_y) / step to the time ``time``, where
        past_y is the weighted sum of earlier values of y = (theta H, X, V). ``guess``: (P, X, V,
        theta, cavitated).
        Raises StepFailed, or FilmError for an iterate the film cannot take (a pressure past
        the viscosity law's range), after which the LUs are in double precision (module
        docstring). The node unknown is P, except at nodes the cavitation model solves for theta
        (mass-conserving cavities, P = P_cav there)."""
        try:
            return self._newton(guess, step, a0, past, time)
        except (StepFailed, FilmError):
            self.single = False
            raise

    def _newton(self, guess, step, a0, past, time) -> StepSolution:
        """:meth:`solve`'s iteration."""
        pressure, gap, velocity, fill, cavitated = guess
        fill, cavitated = self.cavitation.start(fill, cavitated)
        previous_sets = previous_norm = None
        refresh, damped = False, 0
        for iteration in range(1, self.options.max_newton + 1):
            it, cavitated, fill = self._residual(
                pressure, gap, velocity, fill, cavitated, step, a0, past, time
            )
            fresh = iteration == 1 or refresh
            if fresh:
                self._factorise(self._newton_matrix(it, step, a0, fill), it)
                refresh = False
            update, damping, redone = self._damped_update(it, pressure, gap, step, a0, fill)
            fresh = fresh or redone
            damped = damped + 1 if damping < 1.0 else 0
            if damped == DAMPED_IN_A_ROW:
                raise StepFailed(
                    "Newton updates closed the film twice in a row", np.abs(it.rhs).max()
                )
            d_pressure, d_fill, d_gap, d_velocity = update
            pressure = pressure + damping * d_pressure
            fill = fill + damping * d_fill
            gap += damping * d_gap
            velocity += damping * d_velocity
            h = it.film_thickness
            norm = max(
                np.abs(d_pressure).max() / (np.abs(pressure).max() + 1.0),
                np.abs(d_fill).max(),
                abs(d_gap) / max(h.min(), 1e-12),
                abs(d_velocity) / (abs(velocity) + 1e-3),
            )
            stiffness = partial(self._theta_stiffness, it.state, h, step, a0)
            pressure, fill, cavitated = self.cavitation.switch(
                pressure, fill, cavitated, it.state.dry, stiffness
            )
            sets = (*it.sets[:2], self.cavitation.theta_nodes(cavitated).tobytes())
            same = sets == previous_sets
            ratio = norm / previous_norm if same and previous_norm else None
            if damping == 1.0 and same and _remaining(norm, ratio) <= self.options.newton_tolerance:
                cavities = self.cavitation.theta_nodes(cavitated)
                return StepSolution(pressure, gap, velocity, fill, cavities, it.state, iteration)
            if ratio is not None:
                # refresh a stale factorisation that diverges or whose contraction would need
                # > 6 more sweeps (not on a fresh one's first update, whose ratio to the stale
                # one's update is no contraction rate)
                tol = self.options.newton_tolerance
                slow = 0.1 < ratio < 1.0 and np.log(tol / norm) / np.log(ratio) > 6
                refresh = not fresh and (ratio >= 1.0 or slow)
            previous_sets, previous_norm = sets, norm
        self.factor = None
        raise StepFailed("Newton did not converge", np.abs(it.rhs).max())

    def _damped_update(self, it: _Iterate, pressure, gap, step, a0, fill):
        """(update, damping, redone): the Newton update (:meth:`_newton_update`) and its
        damping (:meth:`_damping`). An update from an LU in single precision that would close
        the film is formed again from a new LU of the iterate in double precision (``redone``),
        which the rest of the collision keeps (module docstring)."""
        update = self._newton_update(it, step, a0, fill)
        try:
            damping = self._damping(pressure, gap, update, it.rhs)
        except StepFailed:
            if not self.single:
                raise
            damping = 0.0
        if damping == 1.0 or not self.single:
            return update, damping, False
        self.single = False
        self._factorise(self._newton_matrix(it, step, a0, fill), it)
        update = self._newton_update(it, step, a0, fill)
        return update, self._damping(pressure, gap, update, it.rhs), True

    def _residual(self, pressure, gap, velocity, fill, cavitated, step, a0, past, time):
        """The residual at an iterate, with the cavitation model's rows and the sphere's;
        returns (iterate, cavitated, theta)."""
        content_past, gap_past, velocity_past, *radial_past = past
        h, _, radial = self.thickness_parts(pressure, gap)
        if h.min() <= 0.0:
            raise StepFailed("film thickness not positive", np.nan)
        state = self.film.assemble(h, pressure)
        fill, cavitated = self.cavitation.wet(fill, cavitated, state.dry)
        residual = state.mass * (a0 * fill * h + content_past) / step + state.flux(pressure)
        if radial is not None:
            state = replace(state, transport=self.film.surface_transport(h, fill))
            surface_velocity = (a0 * radial + radial_past[0]) / step
            residual += self.surface_motion.sqrt_delta * state.surface_flux(surface_velocity)

        def sensitivity():
            return state.mass * a0 / step * self.compliance_diagonal + state.flux_slope()

        cavitated = self.cavitation.limit(residual, pressure, cavitated, state.dry, sensitivity)
        residual[state.dry] = pressure[state.dry]
        motion = SphereState(time, gap, velocity, h)
        film_force = state.force_weights @ pressure
        if self.asperities is not None:
            self._loaded_at, self._loaded = h, None
            film_force = film_force + self.asperity_force(h)
        r_sphere = self.sphere.residual(step, a0, (gap_past, velocity_past), motion, film_force)
        rhs = -np.concatenate([residual, r_sphere])
        fixed = self.cavitation.fixed_nodes(state.dry, cavitated)
        theta_nodes = self.cavitation.theta_nodes(cavitated)
        sets = (int((~state.dry).sum()), fixed.tobytes(), theta_nodes.tobytes())
        return _Iterate(rhs, state, motion, h, fixed, theta_nodes, sets), cavitated, fill

    def _newton_update(self, it: _Iterate, step, a0, fill):
        """(dP, d theta, dX, dV) from the (possibly reused) factorisation; the rows that changed
        since it are formed alone (:meth:`_newton_rows`), the columns that changed taken from
        the iterate's Newton matrix, formed once if needed."""
        formed = []  # the iterate's whole Newton matrix, once formed

        def matrix():
            if not formed:
                formed.append(self._newton_matrix(it, step, a0, fill))
            return formed[0]

        try:
            update = self.factor.solve(
                it.rhs,
                it.fixed,
                partial(self._newton_rows, it, step, a0, fill),
                it.theta_nodes,
                lambda columns: matrix()[:, columns],
            )
        except TooManyChanges:
            self._factorise(matrix(), it)
            update = self.factor.solve(it.rhs, it.fixed, None)
        n = len(it.film_thickness)
        d_node, d_gap, d_velocity = update[:n], update[n], update[n + 1]
        d_pressure = np.where(it.theta_nodes, 0.0, d_node)
        d_fill = np.where(it.theta_nodes, d_node, 0.0)
        return d_pressure, d_fill, d_gap, d_velocity

    def _damping(self, pressure, gap, update, rhs):
        """The largest of 1, 1/2, 1/4, ... that keeps the film thickness positive."""
        d_pressure, _, d_gap, _ = update
        damping = 1.0
        while not self._open(pressure + damping * d_pressure, gap + damping * d_gap):
            damping *= 0.5
            if damping < 1e-3:
                raise StepFailed("Newton update closes the film", np.abs(rhs).max())
        return damping

    @staticmethod
    def _theta_stiffness(state: FilmState, h, step, a0):
        """s = (m H a0/dt) / (K_ii + E_ii): the pressure that balances a unit change of theta
        in a node's equation (by mu V0 a / x0^2)."""
        diagonal = state.flux_slope()
        return state.mass * a0 * h / (step * np.where(diagonal > 0, diagonal, 1.0))

    def _newton_matrix(self, it: _Iterate, step, a0, fill):
        """The Jacobian in the Newton unknowns: at mass-conserving cavities the unknown is
        theta, whose column is d(residual_i)/d(theta_i) = m_i a0 H_i / dt."""
        jacobian = self._jacobian(it.state, it.motion, it.fixed, step, a0, fill)
        return self._theta_columns(it, step, a0, self._nodes, jacobian)

    @staticmethod
    def _theta_columns(it: _Iterate, step, a0, rows, out):
        """``out``, the Newton matrix's rows ``rows`` (``out[k]`` is row ``rows[k]``), with the
        columns of mass-conserving cavities' nodes set to theta's: m_i a0 H_i / dt on their
        own row, 0 elsewhere."""
        out[:, it.theta_nodes.nonzero()[0]] = 0.0
        theta = it.theta_nodes[rows]
        nodes = rows[theta]
        out[theta.nonzero()[0], nodes] = it.state.mass[nodes] * a0 * it.film_thickness[nodes] / step
        return out

    def _factorise(self, matrix, it: _Iterate):
        """A new LU of the iterate's Newton ``matrix`` (:meth:`_newton_matrix`), in single
        precision while :attr:`single` (one that is singular there is redone in double, and
        the collision goes on in double)."""
        _, workspace, single = self._slots[0] if matrix is self._slots[0][0] else self._slots[1]
        try:
            self.factor = ReusableLU(
                matrix, it.fixed, it.theta_nodes, workspace, single if self.single else None
            )
        except SingularMatrix as err:
            if self.single:
                self.single = False
                return self._factorise(matrix, it)
            raise StepFailed(str(err), np.nan) from err
        self.factorisations += 1

    def _squeeze(self, state: FilmState, step, a0, fill):
        """(S, dH/dP, dH/dX): the bands of d(residual)/dH, S = m theta a0/dt + D, and the film
        thickness's sensitivities, C and 1, or (I - C D)^-1 C and (I - C D)^-1 1 under the
        asperities' load."""
        lower, diag, upper = state.dflux_dH
        squeeze = (lower, diag + state.mass * fill * a0 / step, upper)
        loaded = self.loaded()
        if loaded is None:
            return squeeze, self._compliance_columns, self._no_load
        return squeeze, loaded.by_pressure, loaded.by_gap

    def _film_rows(self, state: FilmState, step, a0, fill, out):
        """The film rows of the Jacobian into ``out`` (at least n x (n + 2); their P and X
        columns are overwritten, their V column, zero, is left as it is),
        d(m d(theta H)/dT + K(H, P) P)_i/d(P, X, V) = ((m theta a0/dt + D) C + K + E,
        (m theta a0/dt + D) 1, 0) (E: the viscosity's d(K P)/dP - K)."""
        squeeze, c, by_gap = self._squeeze(state, step, a0, fill)
        film_jacobian(squeeze, c, by_gap, state.conductance, state.dflux_dP, out)
        if state.transport is not None:  # sqrt(delta) B dU/dT through U = C_r P (T lagged)
            scale = self._transport_scale(step, a0)
            add_banded_product(state.transport, self._radial_columns, scale, out)
        return out

    def _transport_rows(self, state: FilmState, step, a0, rows):
        """The rows ``rows`` of sqrt(delta) (a0/dt) B C_r: the liquid the faces' radial motion
        carries (U = C_r P, T lagged); the same bits as the whole matrix's (:meth:`_film_rows`)."""
        rows_of_b_c = tridiagonal_rows(state.transport, self.surface_motion.matrix, rows)
        return rows_of_b_c * self._transport_scale(step, a0)

    def _transport_scale(self, step, a0) -> float:
        """sqrt(delta) a0/dt, the factor of B C_r in the Newton matrix (scaled time)."""
        return self.surface_motion.sqrt_delta * a0 / step

    def _newton_rows(self, it: _Iterate, step, a0, fill, rows):
        """The rows ``rows`` of :meth:`_newton_matrix` at nodes whose row is the film's (not
        fixed), formed alone: the kept LU's Woodbury update asks for a few of them, and the
        whole matrix costs some 0.1 ms. The same sums in the same order as the whole
        matrix's (:func:`ehdfem.film.elements.film_jacobian`), so the same bits."""
        state, n = it.state, len(it.film_thickness)
        squeeze, c, by_gap = self._squeeze(state, step, a0, fill)
        out = np.zeros((len(rows), n + 2))
        out[:, :n] = tridiagonal_rows(squeeze, c, rows)
        out[:, n] = tridiagonal_rows(squeeze, by_gap[:, None], rows)[:, 0]
        add_band_rows(state.conductance, rows, out)
        add_band_rows(state.dflux_dP, rows, out)
        if state.transport is not None:
            out[:, :n] += self._transport_rows(state, step, a0, rows)
        return self._theta_columns(it, step, a0, rows, out)

    def _jacobian(self, state: FilmState, motion: SphereState, fixed, step, a0, fill):
        """d(residual)/d(P, X, V): film rows, identity rows at fixed nodes, the sphere's X and V
        rows (:meth:`ehdfem.motion.sphere.Sphere.jacobian_rows`)."""
        n = len(state.mass)
        held = None if self.factor is None else self.factor.matrix
        jac = self._slots[1][0] if held is self._slots[0][0] else self._slots[0][0]
        # in LAPACK's order; the film rows' columns of P and X and the sphere's rows are
        # written whole below, so only the film rows' V column is cleared
        jac[:n, n + 1] = 0.0
        self._film_rows(state, step, a0, fill, jac)
        fixed_rows = fixed.nonzero()[0]
        jac[fixed_rows, :] = 0.0
        jac[fixed_rows, fixed_rows] = 1.0
        jac[n:] = self.sphere.jacobian_rows(step, a0, motion, state.force_weights)
        loaded = self.loaded()
        if loaded is not None:  # the asperities' force w.P_a(H) in the sphere's V row
            row = self.asperity_weights * loaded.slope
            jac[n + 1, :n] -= step * (row @ loaded.by_pressure)
            jac[n + 1, n] -= step * (row @ loaded.by_gap)
        return jac
