"""Normal motion: the Reynolds film, the elastic solids and the sphere, integrated in time.

Scaled unknowns (DSH 1986): pressure P(R, T) (by mu V0 a / x0^2) at the film nodes, the gap X(T)
between the undeformed surfaces on the axis (by x0) and the normal velocity V(T) (by V0, < 0
while approaching). With the compliance C of the solids (W = C P, by x0) and the undeformed
gap S(R) (R^2/2 in the asymptotic theory, the true spheres with ``gap = "exact"``:
:mod:`ehdfem.film.gap`),

    H = X + S(R) + C P,     m dH/dT + K(H) P = 0  (film),     P(0) = 0,
    St dV/dT = (1/3) int P R dR + sum_i F_i,     dX/dT = V,     X(0) = 1, V(0) = -1,

force by 6 pi mu V0 a^2 / x0, the F_i the forces applied to the sphere (an external force, the
buoyant weight, a force with memory such as the history force of the liquid around the film;
positive away from the wall). The sphere's equation, its rows of the implicit
step and its energies are :class:`ehdfem.motion.sphere.Sphere`; its forces
:mod:`ehdfem.motion.forces`.

The parts: the film (:mod:`ehdfem.film.reynolds`), the cavitation model
(:mod:`ehdfem.film.cavitation`), the viscosity law (:mod:`ehdfem.film.viscosity`), the elasticity
(any :class:`ehdfem.solids.compliance.Compliance`: the integrator only sees its ``radii`` and
``matrix``, half-space kernel or FE solids alike), one implicit step
(:mod:`ehdfem.motion.implicit_step`: Newton on (P, X, V)) and the variable-step BDF stepper with
its error control on X (relative to the thinnest film) and V (:mod:`ehdfem.motion.timestepping`).
This module runs them in time, detects the events and collects the result; the histories are
:class:`ehdfem.motion.history.NormalHistory`.

Events: the sphere leaves the layer when X returns to 1 (or to the options' larger ``exit_gap``,
immersed films only) with V > 0 (exit); it sticks when its
velocity returns to <= 0 after it had started to rebound, or when it comes to rest (|V| below
1e-10 or the time limit). e_dry, the dry restitution of the solids' contact, acts once: at
the asperities' solid impact if the approach ends in one (e_n = V_exit), otherwise on the exit
velocity, e_n = e_dry * V_exit (smooth surfaces, a roughness the film never reaches, the mixed
model's elastic asperities; e_dry = 1 is pure EHD; docs/model.md, "Decisions").

Rough surfaces (roughness sigma > 0, by x0; docs/model.md, "Rough surfaces"), two asperity
models. "impact": the asperities are a rigid layer the surfaces touch where the film is sigma
thick. The step is shortened until it ends at the first touch, H_min = sigma (to TOUCH_TOL).
A touch while the sphere approaches (V < 0), before any rebound, is a solid collision: the
velocity jumps from V_c to -e_dry V_c (X, P and the film stay: the solids' elastic state is
continuous), the kinetic energy lost, (1 - e_dry^2) St V_c^2 / 2, joins the dissipation. From
the first touch on (after the impact, or a first touch during the rebound, where the unloading
solids close the exit constriction while the sphere recedes, which no impact of the sphere can
reverse), the same layer is the contact constraint H >= sigma on elastic solids, the asperity
obstacle (:mod:`ehdfem.film.asperity_obstacle`) in the implicit step: it carries a load
wherever the film reaches it, stores its energy in the solids and gives it back. The BDF
history restarts at the touching state (order 1, a first step of first_step sigma; the
dissipation rate before the touch is not used after it). The film then acts on the rebound
(suction, cavitation) until exit, or stops the sphere (stick). Rigid solids get no obstacle:
their film thins only while the sphere approaches, and a film that brings the sphere back to
V <= 0 ends the motion. "greenwood-tripp": the asperities'
pressure shares the load with the film (:mod:`ehdfem.film.asperities`, in the implicit step);
the motion stays continuous and the energy they store is in the elastic energy (they return
it; e_dry stands for the plastic loss they leave out).
"""

from __future__ import annotations

from collections import deque
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

import numpy as np

from ..film.asperity_obstacle import AsperityObstacle
from ..film.gap import Paraboloid
from ..film.reynolds import Film, FilmError
from .forces import LAYER_SURFACE, SphereForce, SphereState
from .history import NormalHistory
from .implicit_step import ImplicitStep, StepFailed
from .normal_problem import NormalProblem, normal_problem
from .sphere import IMPACT_VELOCITY
from .timestepping import (
    BDFStepper,
    IntegratorOptions,
    crossing,
    extrapolate,
    latest,
    peak,
    step_integral,
)

if TYPE_CHECKING:
    from ..inputs.scales import CollisionParameters
    from ..solids.compliance import Compliance

REST_VELOCITY = 1e-10  # |V| below which the sphere is at rest (scaled by V0)
CLOSED_FILM = 1e-8  # film thickness (by x0) taken as closed when a step then fails
NEAR_THINNEST = 1.1  # the thinnest node's film is checked within this factor of the thinnest yet
# (1.05 leaves the thinnest film of a thin mass-conserving impact near St_c 2 % off)
# With film control, the error weight of X (relative to the thinnest film): e_n near St_c,
# through X at exit, is the output most sensitive to the time step (docs/model.md, "Time").
GAP_WEIGHT = 3.0
# With film control, the factor on the velocity error's effect on the gap (_momentum_weight):
# the stopping gap's error is the sum of the steps' errors over the approach; 5 brings a rigid
# sphere's stop at St = 10 within 0.42 % (1.7-1.9 % with 1, 0.55 % with 3;
# docs/performance.md).
MOMENTUM_WEIGHT = 5.0
TOUCH_TOL = 1e-4  # the impact's step ends where H_min is sigma to this relative tolerance


class NormalSolverError(RuntimeError):
    """The time integration failed; the message carries time, step size and residual."""


@dataclass(frozen=True)
class SolidImpact:
    """The asperities' solid collision that ends a rough sphere's approach (scaled): at the
    recorded step ``index`` (time ``time``, by x0/V0) the sphere meets the wall at the
    approach velocity ``approach_velocity`` (V < 0, by V0) and leaves at
    -e_dry approach_velocity; ``normal_impulse`` = St (1 + e_dry) |V| is the asperities'
    impulse on the sphere (by 6 pi mu a^2, the force scale times the time scale);
    ``stored_share``: the elastic energy the solids hold at the impact over the impact energy
    St/2 (the impact model assumes unloaded solids: a large share means it does not hold)."""

    index: int
    time: float
    approach_velocity: float
    normal_impulse: float
    stored_share: float = 0.0


class FilmClosedError(NormalSolverError):
    """The film thickness collapsed (below CLOSED_FILM) and the step failed: either the solids
    are about to touch or the grid does not resolve the thin rim of the flattened contact."""


@dataclass
class NormalResult:
    """Outcome of the normal collision (scaled; see the module docstring).

    ``rebound``: the sphere left the layer (X back to 1 with V > 0). ``exit_velocity``: V there
    (the pure EHD restitution), ``e_n`` = exit_velocity after a solid impact, e_dry *
    exit_velocity without one (0 if it sticks).
    ``max_rebound_velocity``: the largest V > 0 reached (DSH 1986's restitution for immersed
    spheres). ``min_film_thickness``: min over R and T of H (by x0). ``max_force``: by
    6 pi mu V0 a^2 / x0 (extrema up to the contact time, on the dense output).
    ``contact_time``: from first touch of the layer to exit (or to the stop for a sticking
    sphere), by x0 / V0. ``max_compression``: -min X (by x0; positive once
    the undeformed surfaces overlap). ``energy_error``: |KE0 - KE - E_el - dissipation + work| /
    KE0 at the end, with the applied forces' work, E_el counted from first touch (the
    asperities' stored energy in it, a solid impact's loss in the dissipation; meaningful
    without cavitation). The extremes of a collision with a solid impact are taken on each side
    of the impact's record (the velocity and, for nearly rigid solids, the force jump there).
    ``status``: "rebound", "stick" or "stalled".
    Exit, the stop and the extremes are located on the dense output between accepted steps
    (the interpolating polynomials of the BDF history; :func:`ehdfem.motion.timestepping.peak`).
    ``rtol``, ``film_control`` and ``order`` (the highest BDF order): the time-step control
    used (docs/model.md says what the default guarantees; ``energy_error`` is the achieved
    accuracy of the balance).
    ``gap``: the undeformed gap used (:mod:`ehdfem.film.gap`; ``gap.name`` says which).
    ``asperity_force``: the asperities' load on the sphere at each recorded step (by
    6 pi mu V0 a^2 / x0: Greenwood & Tripp's pressure, or the impact model's obstacle after
    its touch; None for smooth surfaces). ``solid_impact``: the asperities' solid
    collision, if the approach ended in one (:class:`SolidImpact`).
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
    film_control: bool
    order: int
    gap: Paraboloid
    asperity_force: np.ndarray | None = None
    solid_impact: SolidImpact | None = None

    @property
    def compression_by_radius(self) -> float:
        """The largest compression by the sphere radius a, delta max(-X, 0)."""
        return max(self.max_compression, 0.0) * self.params.delta


def solve_normal(
    params: CollisionParameters,
    compliance: Compliance,
    options: IntegratorOptions | None = None,
    forces: tuple[SphereForce, ...] = (),
) -> NormalResult:
    """Integrate the normal collision from first touch of the layer to exit or sticking.

    ``params``: dimensionless inputs (St, the applied forces, e_dry, layer, the cavitation model,
    the viscosity law and the asperity model of the surfaces with their roughness (module
    docstring) are used here; eps is already in the compliance).
    ``compliance``: the elasticity, W = matrix @ P at the film nodes ``radii`` (by x0, P by
    mu V0 a / x0^2, R by sqrt(a x0)).
    ``forces``: forces on the sphere besides those of ``params`` (the external force, the
    buoyant weight), such as the history force of the liquid around the film
    (:class:`ehdfem.motion.forces.HistoryForce`), advanced at every accepted step.
    Returns a :class:`NormalResult`. The integration reads these inputs only through their
    :class:`ehdfem.motion.normal_problem.NormalProblem` (:func:`normal_problem`), and ``params``
    is kept in the result.
    """
    problem = normal_problem(params, compliance, options, forces)
    return _NormalIntegration(params, problem).run()


class _NormalIntegration:
    """The time loop of :func:`solve_normal`: steps, events and the result."""

    def __init__(self, params, problem: NormalProblem):
        """``params``: the collision's inputs, kept in the result only; every input of the
        integration is in ``problem`` (:mod:`ehdfem.motion.normal_problem`), so that equal
        problems integrate alike."""
        self.params, self.options = params, problem.options
        self.problem = problem
        self.touch = problem.touch
        self.impact, self.restart = None, 0  # the solid impact; the history's first usable step
        # the asperity obstacle takes the touches no impact takes, on elastic solids only (a
        # rigid sphere's film thins only while it approaches)
        self.yielding = bool(np.diag(problem.matrix).min() > 0.0)
        self.radii = problem.radii
        self.shape = problem.shape
        self.film = Film(self.radii, problem.layer, problem.viscosity, self.shape)
        self.cavitation = problem.cavitation.solver()
        self.sphere = problem.sphere
        self.step_solver = ImplicitStep(
            self.film,
            problem.matrix,
            self.cavitation,
            self.sphere,
            problem.options,
            problem.shear_matrix,
            problem.surface_motion,
            problem.asperity_law,
        )
        self.hist = NormalHistory()
        self.stepper = BDFStepper(self.options, self.hist.time)
        n = len(self.radii)
        self.pressure, self.gap, self.velocity = np.zeros(n), LAYER_SURFACE, IMPACT_VELOCITY
        self.cavitated = np.zeros(n, bool)
        self.dissipation_rates, self.tangential_work = [0.0], 0.0
        self.rejected = self.iterations = 0
        self.rebounding = False
        self.end_time = self.exit_velocity = np.nan
        thickness = self.step_solver.thickness_parts(self.pressure, self.gap)
        state = self.film.assemble(thickness[0], self.pressure)
        # the film's states at the nodes of the latest accepted steps, as many as the widest BDF
        # stencil holds (:meth:`_film_states`)
        self.film_states = deque(
            [self._film_states(self.pressure, state)], maxlen=self.options.order + 1
        )
        self.thinnest = float(np.min(thickness[0]))  # the thinnest film of the accepted steps
        self.surface_weights = np.zeros(n)
        self._record(0.0, np.ones(n), thickness, state, 0.0)

    def _record(self, time, fill, thickness, state, dissipated):
        """Record the current state, with ``thickness`` = (H, shear opening, the faces' mean
        radial displacement U; None where not applied) from
        :meth:`ImplicitStep.thickness_parts`. The film's work on the tangential surface effects
        is accumulated by the trapezoidal rule: the pressure's work on the shear opening,
        (1/3) int P.M dW_shear, and the work of the film on the faces' radial motion,
        (sqrt(delta)/3) int P.B dU (docs/model.md, "Tangential surface effects at order
        sqrt(delta)"); both are in the elastic energy."""
        (h, opening, radial), mass = thickness, self.film.full_mass
        if opening is not None and self.hist.time:
            mean = 0.5 * (self.hist.pressure[-1] + self.pressure)
            self.tangential_work += float(mass * mean @ (opening - self.opening)) / 3.0
        if radial is not None:
            weights = state.surface_flux_weights(self.pressure)
            if self.hist.time:
                mean = 0.5 * (self.surface_weights + weights)
                change = radial - self.hist.surface_radial[-1]
                motion = self.step_solver.surface_motion
                self.tangential_work += motion.sqrt_delta * float(mean @ change) / 3.0
            self.surface_weights = weights
        self.opening = opening
        compliance = self.step_solver.compliance
        law = self.step_solver.asperities
        energies = (self.sphere, compliance, mass, dissipated, self.tangential_work, law)
        self.hist.record(time, self.gap, self.velocity, self.pressure, fill, h, state, energies)
        if radial is not None:
            self.hist.surface_radial.append(radial)

    def run(self) -> NormalResult:
        status = None
        while status is None:
            if len(self.hist.time) > self.options.max_steps:
                raise NormalSolverError(
                    f"more than {self.options.max_steps} steps at T = {self.hist.time[-1]:.6g}"
                )
            status = self._advance()
        return self._result(status)

    def _advance(self):
        """Try one step; on success record it and return the event (None: go on)."""
        hist, stepper = self.hist, self.stepper
        t_old = hist.time[-1]
        t_new = t_old + stepper.step
        order = stepper.order()
        weights = stepper.weights(t_new, order)
        content = np.array(latest(hist.fill, order)) * np.array(latest(hist.film_thickness, order))
        recent = [content, latest(hist.gap, order), latest(hist.velocity, order)]
        if hist.surface_radial:
            recent.append(latest(hist.surface_radial, order))
        past = stepper.past(weights, recent)
        guess = stepper.guess(t_new, (hist.pressure, hist.gap, hist.velocity), order)
        guess[0] = np.where(self.cavitated, self.cavitation.p_cav, guess[0])
        try:
            solution = self.step_solver.solve(
                (*guess, hist.fill[-1], self.cavitated), stepper.step, weights[0], past, t_new
            )
        except (StepFailed, FilmError) as failure:
            self._failed(failure, t_old)
            return None
        self.iterations += solution.iterations
        thickness = self.step_solver.thickness_parts(solution.pressure, solution.gap)
        if self._overshoots(float(np.min(thickness[0])), solution.velocity):
            self._step_to_touch(t_new, t_old, float(np.min(thickness[0])))
            return None
        states = self._film_states(solution.pressure, solution.state)  # once a step
        error = self._error(t_new, order, solution, thickness[0], states)
        if error > 1.0:
            self.rejected += 1
            stepper.reject(error, order)
            return None
        status = self._accept(solution, thickness, t_new, states)
        stepper.accept(error, order)
        return status

    def _error(self, t_new, order, solution, film_thickness, states) -> float:
        """The step's estimated local error over rtol: the largest of |dX|/H_min, |dV| and, with
        film control, |dH/H| at the thinnest node where the reported minimum can still form: its
        film within NEAR_THINNEST of the thinnest yet, and thinning (below the last step's thinnest)
        or the last step holding the thinnest yet (the step after the minimum, which its parabola
        needs). A film that only thickens or drifts near its minimum, as when a constriction moves
        inward through the nodes after it, is left to the mean square: the window saves 20-30 % of
        the steps at hard impacts, the thinning condition a further 10-35 % at soft and cavitating
        ones, and neither raises an output's error by more than 0.05 %. The root mean square of dH/H
        is over the settled nodes (:meth:`_settled`): where a node cavitates, refills, or the
        wetted edge passes it, the semi-discrete film has a kink in time there and at its
        neighbours, the predictor then measures the kink, an error of first order in the step,
        and holding it to rtol cost up to 9 times the steps while a cavity grew node by node
        (docs/model.md, "Time"). X and V, integrals over the film, stay controlled across such
        switches; with film control |dX|/H_min weighs GAP_WEIGHT times and |dV| by the gap error
        it will cause (:meth:`_momentum_weight`)."""
        hist, stepper = self.hist, self.stepper
        share = stepper.error_share(t_new, order)
        if share is None:
            return 0.0
        thinnest = int(np.argmin(film_thickness))
        h_min = max(min(hist.min_film[-1], film_thickness[thinnest]), 1e-12)
        control = self.options.film_control
        errors = [
            abs(stepper.correction(t_new, order, hist.gap, solution.gap))
            / h_min
            * (GAP_WEIGHT if control else 1.0),
            abs(stepper.correction(t_new, order, hist.velocity, solution.velocity)),
        ]
        if control:
            errors[1] *= max(1.0, MOMENTUM_WEIGHT * self._momentum_weight(solution, h_min))
            film = stepper.correction(t_new, order, hist.film_thickness, film_thickness)
            relative = film / film_thickness
            near = film_thickness[thinnest] <= NEAR_THINNEST * min(self.thinnest, h_min)
            thinning = film_thickness[thinnest] < hist.min_film[-1]
            if near and (thinning or hist.min_film[-1] <= self.thinnest):
                errors.append(abs(relative[thinnest]))
            settled = self._settled(states, order)
            if settled.any():
                errors.append(np.sqrt(np.mean(relative[settled] ** 2)))
        return share * max(errors) / self.options.rtol

    def _momentum_weight(self, solution, h_min) -> float:
        """How much a velocity error dV moves the gap, relative to the thinnest film, by the
        time the film has taken up the sphere's momentum: the film's damping g = f.P / |V|
        stops a speed error within St / g, over which the gap moves by St dV / g, so the weight
        is St |V| / (f.P H_min) while approaching (V < 0) against a film that pushes (f.P > 0),
        0 otherwise (force by 6 pi mu V0 a^2 / x0, V by V0, H by x0). It is at most St, the
        weight of a rigid sphere (g H_min = 1 immersed and near the stop), whose stopping gap
        moves by St dV relative for a speed error anywhere on its approach: a thin layer's
        film barely damps as the sphere enters (g = (1 - X)^2 / X), yet the error reaches the
        stop. A control of dV alone to rtol left X_stop 5-7 % high at St = 10
        (docs/performance.md). With film control the velocity error counts MOMENTUM_WEIGHT
        times this weight where that is above 1."""
        force = float(solution.state.force_weights @ solution.pressure)
        if solution.velocity >= 0.0 or force <= 0.0:
            return 0.0
        return self.sphere.St * min(1.0, -solution.velocity / (force * h_min))

    def _film_states(self, pressure, state) -> np.ndarray:
        """The film's state at each node: 0 dry, 1 wet at or below the cavitation pressure,
        2 full (wet and above it)."""
        wet = ~state.dry
        return wet.view(np.int8) + (wet & (pressure > self.cavitation.p_cav)).view(np.int8)

    def _settled(self, states, order) -> np.ndarray:
        """The nodes the film's mean-square error is taken over: full at every value of the step's
        BDF stencil (``states`` of the new step and of the order + 1 latest accepted ones,
        :meth:`_film_states`) and no neighbour of a node the wetted edge passes within it; none
        while a wet node cavitates or refills within it. The wetted edge moves continuously (cut
        into its element, docs/model.md), so its passing a node kinks that node's film in time and,
        through the three-point rows, its neighbours'. A cavity's boundary moves node by node and
        kinks the film further (leaving out one to three neighbours still cost a mass-conserving
        cavity growing node by node 1.05 to 7.4 times the steps). Leaving the mean square out at
        every switch of either kind left a thin layer's rebound uncontrolled, as its wetted edge
        passes a node every few steps: the thinnest film of a suction dip there was 4 % off at the
        default rtol and did not converge with it (docs/performance.md)."""
        recent = list(self.film_states)[-(order + 1) :]
        if len({states.tobytes(), *(kept.tobytes() for kept in recent)}) == 1:  # none switched
            return states == 2
        stencil = np.array(recent)
        switching = (stencil != states).any(axis=0)
        if np.any(switching & (stencil > 0).all(axis=0) & (states > 0)):
            return np.zeros(len(states), bool)  # a wet node cavitates or refills
        switching[1:] |= switching[:-1].copy()
        switching[:-1] |= switching[1:].copy()
        return (states == 2) & (stencil == 2).all(axis=0) & ~switching

    def _failed(self, failure, t_old):
        """A step whose Newton failed: the film closed, or retry with a quarter step."""
        hist = self.hist
        if hist.min_film[-1] < CLOSED_FILM:
            i = int(np.argmin(hist.film_thickness[-1]))
            raise FilmClosedError(
                f"film closed at T = {t_old:.6g}: H = {hist.min_film[-1]:.3g} at R = "
                f"{self.radii[i]:.4g} (X = {self.gap:.4g}, V = {self.velocity:.4g}); "
                "refine the film grid"
            ) from failure
        self.rejected += 1
        self.stepper.fail()
        if self.stepper.step < 1e-14 * max(1.0, t_old):
            residual = getattr(failure, "residual", np.nan)
            raise NormalSolverError(
                f"time step underflow at T = {t_old:.6g}, dt = {self.stepper.step:.3g}: "
                f"{failure} (residual {residual:.3g})"
            ) from failure

    def _touch_pending(self, velocity) -> bool:
        """Impact model: the asperities have not touched yet, and a touch now would act: as the
        solid impact (approaching, before any rebound) or, on elastic solids, as the asperity
        obstacle (:mod:`ehdfem.film.asperity_obstacle`; after a rebound of a rigid sphere V back
        to 0 is the stop, which comes first)."""
        if self.touch is None or self.impact is not None or self.step_solver.asperities is not None:
            return False
        return self.yielding or (not self.rebounding and velocity < 0)

    def _overshoots(self, thinnest, velocity) -> bool:
        """Impact model: the step's thinnest film went below sigma before the touch."""
        return self._touch_pending(velocity) and thinnest < self.touch * (1 - TOUCH_TOL)

    def _step_to_touch(self, t_new, t_old, thinnest):
        """Retry the step shortened to where the thinnest film reaches sigma, on the dense output
        through the step's solution and the latest accepted thinnest films."""
        hist = self.hist
        times = [t_new, *latest(hist.time, 2)]
        films = [thinnest, *latest(hist.min_film, 2)]
        touch_time = crossing(times, films, self.touch)
        self.rejected += 1
        self.stepper.step = touch_time - t_old if touch_time > t_old else 0.5 * self.stepper.step
        if self.stepper.step < 1e-14 * max(1.0, t_old):
            raise NormalSolverError(
                f"time step underflow at T = {t_old:.6g}: the thinnest film {thinnest:.4g} is "
                f"below the roughness {self.touch:.4g} and no step reaches it"
            )

    def _dissipated(self, t_new, rate) -> float:
        """The dissipation up to t_new: the rate integrated over the step on the quadratic
        through the three latest rates since the start or the solid impact (the first step after
        an impact by the rectangle rule at its end)."""
        self.dissipation_rates.append(rate)
        known = min(len(self.hist.time) - self.restart, 2)
        if known == 0:
            return self.hist.dissipated[-1] + (t_new - self.hist.time[-1]) * rate
        times = [t_new, *latest(self.hist.time, known)]
        return self.hist.dissipated[-1] + step_integral(
            times, latest(self.dissipation_rates, known + 1)
        )

    def _accept(self, solution, thickness, t_new, states):
        """Record an accepted step (the dissipation rate integrated over it) and return its event,
        if any; a step that ends at the asperities' touch is the solid impact."""
        rate = self.film.dissipation_rate(solution.state, solution.pressure)
        dissipated = self._dissipated(t_new, rate)
        self.pressure, self.gap, self.velocity = solution.pressure, solution.gap, solution.velocity
        self.cavitated = solution.cavitated
        self.film_states.append(states)
        thinnest = float(np.min(thickness[0]))
        self.thinnest = min(self.thinnest, thinnest)
        self._advance_sphere(t_new, thickness[0])
        touches = self._touch_pending(self.velocity) and thinnest <= self.touch * (1 + TOUCH_TOL)
        impact = touches and not self.rebounding and self.velocity < 0
        if impact:
            dissipated += self._solid_impact(t_new)
            self._advance_sphere(t_new, thickness[0])  # the velocity's jump, into any memory
        self._record(t_new, solution.fill, thickness, solution.state, dissipated)
        if impact:
            stored = self.hist.elastic[-1] - self.hist.elastic[0]
            share = stored / self.sphere.kinetic_energy(IMPACT_VELOCITY)
            self.impact = replace(self.impact, stored_share=float(share))
        if touches:
            self._touched(min(thinnest, self.touch))
        self.rebounding = self.rebounding or self.velocity > 0
        return self._event(t_new)

    def _touched(self, height):
        """From the asperities' touch on, on elastic solids, the asperity obstacle at the
        touching film ``height`` (sigma within TOUCH_TOL; it carries no load there) takes every
        later touch; the BDF history restarts at the touching state (the velocity's jump of an
        impact, the obstacle's kink in the load)."""
        if self.yielding:
            self.step_solver.load_asperities(
                AsperityObstacle.on(height, self.step_solver.compliance)
            )
        self.restart = len(self.hist.time)
        self.stepper.restart(self.options.first_step * self.touch)

    def _advance_sphere(self, time, film_thickness):
        """The sphere (its forces' memory) moved on to the accepted state, in the step solver
        too (:meth:`ehdfem.motion.sphere.Sphere.advanced`)."""
        state = SphereState(time, self.gap, self.velocity, film_thickness)
        self.sphere = self.step_solver.sphere = self.sphere.advanced(state)

    def _solid_impact(self, t_new) -> float:
        """The asperities' solid collision at the latest state: V_c -> -e_dry V_c; returns the
        kinetic energy lost, (1 - e_dry^2) St V_c^2 / 2."""
        e_dry, approach = self.problem.e_dry, self.velocity
        impulse = self.sphere.St * (1.0 + e_dry) * abs(approach)
        self.impact = SolidImpact(len(self.hist.time), t_new, approach, impulse)
        self.velocity = -e_dry * approach
        return (1.0 - e_dry**2) * self.sphere.kinetic_energy(approach)

    def _event(self, t_new):
        """The event of the latest accepted step, if any: exit, stop, rest or stall."""
        exit_gap = self.options.exit_gap
        if self.sphere.left_layer(self.gap, self.velocity, exit_gap):  # exit, on the dense output
            times = latest(self.hist.time, 3)
            self.end_time = crossing(times, latest(self.hist.gap, 3), exit_gap)
            self.exit_velocity = extrapolate(times, latest(self.hist.velocity, 3), self.end_time)
            return "rebound"
        if self.rebounding and self.velocity <= 0:  # the stop: V back to 0, on the dense output
            times = latest(self.hist.time, 3)
            self.end_time = crossing(times, latest(self.hist.velocity, 3), 0.0)
            return "stick"
        self.end_time = t_new  # at rest or stalled: the end is this step
        if abs(self.velocity) < REST_VELOCITY:
            return "stick"
        if t_new > self.options.max_time:
            return "stalled"
        return None

    def _result(self, status) -> NormalResult:
        hist = self.hist.arrays()
        params = self.params
        rebound = status == "rebound"
        kinetic0 = self.sphere.kinetic_energy(IMPACT_VELOCITY)
        stored = hist.elastic[-1] - hist.elastic[0]  # from first touch (asperities at X = 1)
        balance = hist.kinetic[-1] + stored + hist.dissipated[-1] - hist.work[-1]
        restitution = 1.0 if self.impact is not None else self.problem.e_dry  # e_dry acts once
        return NormalResult(
            params=params,
            radii=self.radii,
            history=hist,
            rebound=rebound,
            status=status,
            exit_velocity=float(self.exit_velocity) if rebound else 0.0,
            e_n=restitution * float(self.exit_velocity) if rebound else 0.0,
            max_rebound_velocity=max(self._largest(hist.velocity), 0.0),
            min_film_thickness=-self._largest(-hist.min_film),
            max_force=self._largest(hist.force),
            contact_time=float(self.end_time),
            max_compression=self._largest(-hist.gap),
            energy_error=float(abs(kinetic0 - balance) / kinetic0),
            steps=len(hist.time) - 1,
            rejected_steps=self.rejected,
            newton_iterations=self.iterations,
            rtol=self.options.rtol,
            film_control=self.options.film_control,
            order=self.options.order,
            gap=self.shape,
            asperity_force=self._asperity_force(),
            solid_impact=self.impact,
        )

    def _largest(self, values) -> float:
        """The largest of a history up to the end on the dense output (:func:`peak`), on each
        side of a solid impact's record separately (the velocity and the force jump there)."""
        times, k = self.hist.time, 0 if self.impact is None else self.impact.index
        before = peak(times[: k + 1], values[: k + 1])[1] if k else -np.inf
        return max(before, peak(times[k:], values[k:], self.end_time)[1])

    def _asperity_force(self) -> np.ndarray | None:
        """The asperities' load on the sphere at each recorded step, w.P_a(H) (by 6 pi mu V0
        a^2 / x0): Greenwood & Tripp's, or the impact model's obstacle (zero before its touch,
        and where it has none: the impact's load is its impulse), None for smooth surfaces."""
        law = self.step_solver.asperities
        if law is not None:
            return law.pressure(self.hist.film_thickness) @ self.step_solver.asperity_weights
        return None if self.touch is None else np.zeros(len(self.hist.time))
