"""Two free spheres colliding obliquely: the pair's tangential motion, mapped exactly onto the
sphere on a wall where the film's force depends on the slip alone, the two spheres'
resistances in ``gcb`` and their sliding film (docs/tangential.md, "Two spheres").

Sphere 1 (upper: radius a1, mass m1, inertia factor k1 = I1/(m1 a1^2)) meets sphere 2 (lower:
a2, m2, k2) along the line of centres, the normal. U = U1 - U2 is the relative tangential
velocity of the centres along x and s_i = a_i Omega_i the spins' surface speeds (all by U0, the
relative tangential speed at first touch), both spins counted about the same axis, so that the
surfaces at the contact move at U1 - s1 and U2 + s2 and slip at u_s = U - w, w = s1 + s2 (the
contact spin). The normal motion is the half-space theory's (or the FE solids') with the
reduced radius a and mass m; St is by m. A tangential force F on sphere 1 at the contact is
-F on sphere 2 there, so that

    St dU = J,   St ds1 = -J / (k1 (1 + m1/m2)),   St ds2 = -J / (k2 (1 + m2/m1)),

for the impulse J on sphere 1 (by 6 pi mu a^2 U0 / V0), and the contact spin obeys
k St dw = -J with 1/k = 1/(k1 (1 + m1/m2)) + 1/(k2 (1 + m2/m1)): the wall's equations with
(U, a Omega, k) -> (U, w, k). Where the tangential force depends on the slip alone (the
Couette shear of the ``couette`` and ``flat`` films, the solid contact's Coulomb friction) the
pair is the sphere on a wall of inertia factor k and initial spin w0 = s1(0) + s2(0), exactly;
each sphere then takes its share s_i - s_i(0) = c_i (w - w0), c1 = k / (k1 (1 + m1/m2)),
c2 = k / (k2 (1 + m2/m1)), c1 + c2 = 1. The kinetic energy of the pair in its centre-of-mass
frame (by m U0^2 / St)

    E = (St/2) (U^2 + k1 (1 + m1/m2) s1^2 + k2 (1 + m2/m1) s2^2)

changes at the rate F u_s, as the wall's (St/2)(U^2 + k w^2) does.

``gcb``: the film's pressure also turns the spheres. The surfaces at the gap entrain the
liquid at w_pair = rho U + s1 - s2, rho = (a2 - a1)/(a1 + a2) (U + a Omega on a wall), whose
mode-1 pressure pushes sphere 1 by rho times its force on a wall and turns the spheres
oppositely; with the Couette shear of the slip, the force on sphere 1 and the torques over
each sphere's radius are -delta L R (U, s1, s2) with R = (1/3) e e^T + (1/5) g g^T,
e = (1, -1, -1), g = (rho, 1, -1): Jeffrey & Onishi's (1984) logarithmic resistances
(:mod:`ehdfem.exact.sphere_pair`). The equations St dU/dT = -(R v)_1,
St k_i (1 + m_i/m_j) ds_i/dT = -(R v)_(i+1) keep the pair's angular momentum about the contact
point, (a1 + a2) U + a1 k1 (1 + m1/m2) s1 + a2 k2 (1 + m2/m1) s2 (R's null vector), and
lose E at the rate v.R v: not a function of the slip alone, the pair is no longer the sphere on
a wall. Equal spheres (rho = 0): the pressure exerts no net force, and equal and opposite spins
(rolling like gears) are braked by it, unlike in the slip-only models.

``lubrication``: the sliding film's system with the same entrainment, rho times the
undeformed slope in the force on sphere 1 and each sphere's torque from its own shear traction,
T_i/a_i = -F1 -+ (a/a_i) P with P the mode-1 pressure's x-force
(:class:`ehdfem.tangential.sliding_film.FilmBodies`); on half-spaces only.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from .. import checks
from ..exact.sphere_pair import pair_logarithmic
from ..motion.normal import NormalResult
from .friction import CoulombContact
from .motion import integrate_resistance, resistance_step, solve_tangential
from .result import TangentialResult, end_index, tangential_result
from .sliding_film import FilmBodies, SlidingFilm

SLIP_MODELS = ("couette", "flat")  # the tangential models whose force depends on the slip alone
PAIR_MODELS = (*SLIP_MODELS, "gcb", "lubrication")


@dataclass(frozen=True)
class SpherePair:
    """The partner of a two-sphere collision as the tangential motion needs it: ``mass_ratio``
    m1/m2 in (0, inf), the inertia factors ``upper_inertia`` k1 and ``lower_inertia`` k2 in
    (0, 2/3], the lower sphere's initial spin ``lower_spin`` a2 Omega2 / V0, the
    ``radius_ratio`` a1/a2 in (0, inf) (module docstring)."""

    mass_ratio: float
    upper_inertia: float
    lower_inertia: float
    lower_spin: float = 0.0
    radius_ratio: float = 1.0

    def __post_init__(self):
        checks.positive("mass_ratio", self.mass_ratio)
        checks.positive("radius_ratio", self.radius_ratio)
        for name in ("upper_inertia", "lower_inertia"):
            checks.number(name, getattr(self, name), lower=0.0, upper=2 / 3, lower_open=True)
        checks.number("lower_spin", self.lower_spin)

    @property
    def spin_weights(self) -> tuple[float, float]:
        """(k1 (1 + m1/m2), k2 (1 + m2/m1)): each spin's inertia I_i / (m a_i^2) by the reduced
        mass m."""
        ratio = self.mass_ratio
        return self.upper_inertia * (1.0 + ratio), self.lower_inertia * (1.0 + 1.0 / ratio)

    @property
    def inertia_factor(self) -> float:
        """The pair's k = 1 / (1/(k1 (1 + m1/m2)) + 1/(k2 (1 + m2/m1))), a weighted harmonic mean
        of k1 and k2 (k1 itself when k1 = k2), capped at the larger against rounding."""
        upper, lower = self.spin_weights
        exact = 1.0 / (1.0 / upper + 1.0 / lower)
        return min(exact, max(self.upper_inertia, self.lower_inertia))

    @property
    def rho(self) -> float:
        """(a2 - a1)/(a1 + a2): the entrainment's factor of U and the undeformed slope's of
        the force on sphere 1 (1 for a wall, 0 for equal spheres)."""
        return (1.0 - self.radius_ratio) / (1.0 + self.radius_ratio)

    @property
    def shares(self) -> tuple[float, float]:
        """(c1, c2) = k / (k1 (1 + m1/m2)), k / (k2 (1 + m2/m1)): each sphere's share of the
        contact spin's change (c1 + c2 = 1); c_i = (1/weight_i) / sum 1/weight_j for the
        :attr:`spin_weights`."""
        upper, lower = self.spin_weights
        return lower / (upper + lower), upper / (upper + lower)


@dataclass(frozen=True)
class PairMotion:
    """The pair's own histories and outcomes (scales of the module docstring): ``pair`` its
    :class:`SpherePair`; ``lower_spin`` s2 = a2 Omega2 / U0 at the normal solution's steps
    (the upper sphere's s1 is the TangentialResult's ``spin``); ``lower_spin_change`` and
    ``contact_spin_change`` a2 (Omega2 - Omega2(0)) / U0 and (w - w0) at exit or stop;
    ``kinetic`` the centre-of-mass frame's kinetic energy E of both spheres at the steps,
    ``film_dissipated`` and ``friction_dissipated`` what the film's shear and the solid
    contact took so far (by m U0^2 / St), ``balance_error`` |E(0) - E - film - friction| at
    exit or stop over E(0) - E there."""

    pair: SpherePair
    lower_spin: np.ndarray
    lower_spin_change: float
    contact_spin_change: float
    kinetic: np.ndarray
    film_dissipated: np.ndarray
    friction_dissipated: np.ndarray
    balance_error: float


def solve_pair(
    normal: NormalResult,
    model: str,
    pair: SpherePair,
    mode_one=None,
    surface_sum=None,
    deformation: str = "gap",
) -> TangentialResult:
    """The tangential motion of two free spheres on the normal solution ``normal`` (by the
    reduced radius and mass), with the film ``model`` (PAIR_MODELS) and the partner ``pair``.
    The slip-only models (SLIP_MODELS): the sphere-on-wall motion of inertia factor
    ``pair.inertia_factor`` and initial spin w0 = s1(0) + s2(0)
    (:func:`ehdfem.tangential.motion.solve_tangential`), split between the spheres by their
    shares; ``gcb``: the two spheres' logarithmic resistances on (U, s1, s2)
    (:func:`gcb_pair`); ``lubrication``: the sliding film of two spheres (:func:`sliding_pair`,
    with ``mode_one``, ``surface_sum`` and ``deformation`` as for
    :func:`ehdfem.tangential.motion.solve_tangential`). The result's ``velocity`` and ``e_t``
    are the relative ones (U1 - U2), ``spin`` and ``spin_change`` the upper sphere's, ``slip``
    u_s = U - s1 - s2, and ``pair`` the rest (:class:`PairMotion`)."""
    checks.choice("tangential model of two spheres", model, PAIR_MODELS)
    params = normal.params
    if params.tangential_speed == 0.0:
        raise checks.InputError("the tangential motion of two spheres needs angle > 0", "angle")
    if params.inertia_factor != pair.upper_inertia:
        raise checks.InputError(
            f"the pair's upper inertia factor {pair.upper_inertia!r} differs from the "
            f"collision's inertia_factor {params.inertia_factor!r}",
            "inertia_factor",
        )
    mapped = replace(params, inertia_factor=pair.inertia_factor, spin=params.spin + pair.lower_spin)
    if model == "gcb":
        return gcb_pair(replace(normal, params=mapped), pair)
    if model == "lubrication":
        film = (mode_one, surface_sum, deformation)
        return sliding_pair(replace(normal, params=mapped), pair, *film)
    wall = solve_tangential(replace(normal, params=mapped), model)
    tangent = params.tangential_speed
    first, second = pair.shares
    upper_start, lower_start = params.spin / tangent, pair.lower_spin / tangent
    turned = wall.spin - wall.spin[0]  # w - w0 at the steps
    upper, lower = upper_start + first * turned, lower_start + second * turned
    change = wall.spin_change
    motion = _pair_motion(normal, wall, pair, (upper, lower), change)
    return replace(wall, spin=upper, spin_change=first * change, pair=motion)


def gcb_resistance_pair(delta: float, min_film, radius_ratio: float) -> np.ndarray:
    """The two spheres' leading logarithmic resistances on (U, s1, s2) at the thinnest film
    h = H_min x0 (``min_film``, any shape) and a1/a2 ``radius_ratio``: delta L R with
    L = ln(a/h) = -ln(delta H_min), a the reduced radius, and R Jeffrey & Onishi's
    (:func:`ehdfem.exact.sphere_pair.pair_logarithmic`; force on sphere 1 and the torques
    T_i/a_i by 6 pi mu a^2 U0 / x0; shape (..., 3, 3)). The O(1) terms are left out, as in the
    wall's :func:`ehdfem.tangential.motion.gcb_resistance`, which it is for a1/a2 -> 0."""
    logarithm = -np.log(delta * np.asarray(min_film, dtype=float))
    return delta * logarithm[..., None, None] * pair_logarithmic(radius_ratio)


def gcb_pair(normal: NormalResult, pair: SpherePair) -> TangentialResult:
    """The gcb model of two spheres on the normal solution ``normal`` whose parameters carry
    the pair's inertia factor k and contact spin w0 (:func:`solve_pair`):
    St dU/dT = -(R v)_1, St k_i (1 + m_i/m_j) ds_i/dT = -(R v)_(i+1) for v = (U, s1, s2) and
    R of :func:`gcb_resistance_pair` (module docstring), by the exact exponential of each
    step's mean R (:func:`ehdfem.tangential.motion.integrate_resistance`), also from the last
    step to the end; the solid contact's Coulomb impulse on the slip after each step (its
    change of w = s1 + s2 shared as c1, c2). Not a function of the slip alone: the pressure's
    force and torques act on the entrainment rho U + s1 - s2 (docs/tangential.md)."""
    params, hist = normal.params, normal.history
    resistance = gcb_resistance_pair(params.delta, hist.min_film, pair.radius_ratio)
    contact = CoulombContact.of(normal)
    shares = np.array((0.0, *pair.shares))

    def jump(i, state):  # (U, s1, s2) after the contact's impulse at step i
        velocity, spin = contact.act(i, state[0], state[1] + state[2])
        return state + (velocity - state[0], 0.0, 0.0) + shares * (spin - state[1] - state[2])

    inertia, start = (1.0, *pair.spin_weights), _pair_start(params, pair)
    states, film = integrate_resistance(
        hist.time, resistance, params.St, inertia, start, None if contact is None else jump
    )
    end = end_index(normal)  # in step i: the exact exponential of its mean R over its share
    i = min(int(end), len(states) - 2)
    impulse = 0.5 * (resistance[i] + resistance[i + 1]) * (hist.time[i + 1] - hist.time[i])
    propagator, gram = resistance_step(
        impulse, np.diag(1.0 / (params.St * np.array(inertia))), end - i
    )
    at_end = propagator @ states[i]
    velocity, upper, lower = states.T
    force = -np.einsum("ij,ij->i", resistance[:, 0], states)
    histories = (velocity, upper + lower, 3.0 * resistance[:, 0, 0] / params.delta, force)
    wall = tangential_result(
        normal, "gcb", "none", histories, None, at_end=(at_end[0], at_end[1] + at_end[2]),
        contact=contact,
    )  # fmt: skip
    friction = np.zeros(len(states)) if contact is None else wall.friction.dissipated
    kinetic = 0.5 * params.St * (states**2 @ np.array(inertia))
    lost = kinetic[0] - 0.5 * params.St * (at_end**2 @ np.array(inertia))
    residual = lost - film[i] - states[i] @ gram @ states[i] - friction[i]
    motion = PairMotion(
        pair=pair,
        lower_spin=lower,
        lower_spin_change=float(at_end[2] - lower[0]),
        contact_spin_change=float(wall.spin_change),
        kinetic=kinetic,
        film_dissipated=film,
        friction_dissipated=friction,
        balance_error=float(abs(residual) / lost) if lost > 0 else 0.0,
    )
    return replace(wall, spin=upper, spin_change=float(at_end[1] - upper[0]), pair=motion)


def sliding_pair(normal, pair, mode_one, surface_sum, deformation) -> TangentialResult:
    """The sliding film of two spheres on the normal solution ``normal`` whose parameters
    carry the pair's k and contact spin w0 (:func:`solve_pair`): the wall's system
    (:class:`ehdfem.tangential.sliding_film.SlidingFilm`) on (q, v, U, s1, s2), its mode-1
    pressure driven by the entrainment w_pair = rho U + s1 - s2, rho times the undeformed
    slope in the force on sphere 1, each sphere's torque from its own shear traction and its
    energy balance over both spheres (docs/tangential.md, "Two spheres"). ``mode_one``: the
    half-spaces' mode-1 compliance (None: rigid), ``surface_sum`` and ``deformation`` as for
    the wall. The end's values are interpolated linearly, as the wall's."""
    bodies = FilmBodies((1.0, *pair.spin_weights), pair.rho)
    start = _pair_start(normal.params, pair)
    film = SlidingFilm(normal, mode_one, surface_sum, deformation, None, bodies, start)
    wall = film.solve()
    motion = film.states[:, film.motion]
    end, steps = end_index(normal), np.arange(len(motion))
    upper, lower = motion[:, 1], motion[:, 2]
    ends = [float(np.interp(end, steps, spin)) for spin in (upper, lower)]
    energy = wall.energy
    record = PairMotion(
        pair=pair,
        lower_spin=lower,
        lower_spin_change=ends[1] - lower[0],
        contact_spin_change=float(wall.spin_change),
        kinetic=energy.kinetic,
        film_dissipated=energy.dissipated,
        friction_dissipated=energy.friction,
        balance_error=energy.balance_error,
    )
    return replace(wall, spin=upper, spin_change=ends[0] - upper[0], pair=record)


def _pair_start(params, pair: SpherePair) -> tuple[float, float, float]:
    """(U, s1, s2) at impact by U0 from the mapped ``params`` (their spin the contact spin
    w0 = s1(0) + s2(0), by V0) and the partner's own spin."""
    tangent = params.tangential_speed
    return 1.0, (params.spin - pair.lower_spin) / tangent, pair.lower_spin / tangent


def _pair_motion(normal, wall, pair, spins, change) -> PairMotion:
    """The :class:`PairMotion` of the wall-mapped result ``wall`` with the spheres' spins
    ``spins`` (s1, s2) at the steps and the contact spin's change ``change`` at the end. The
    film's dissipation of a step is what it took from the slip's energy (St/2) k/(1 + k) u_s^2
    (the film conserves U + k w), from the slip after the last step's contact to the slip
    before this step's; the end's partial step likewise."""
    St, k = normal.params.St, pair.inertia_factor
    weights = (1.0, *pair.spin_weights)

    def kinetic_energy(*velocities):  # (U, s1, s2)
        return 0.5 * St * sum(w * v**2 for w, v in zip(weights, velocities, strict=True))

    upper, lower = spins
    kinetic = kinetic_energy(wall.velocity, upper, lower)
    friction = np.zeros(len(wall.velocity))
    slip_before = wall.slip.copy()  # the slip each step's film left, before the contact acted
    if wall.friction is not None:
        friction = wall.friction.dissipated
        slip_before = wall.slip - (1.0 + 1.0 / k) * wall.friction.impulse / St
    slip_energy = 0.5 * St * k / (1.0 + k)
    taken = slip_energy * (wall.slip[:-1] ** 2 - slip_before[1:] ** 2)
    film = np.concatenate(([0.0], np.cumsum(taken)))
    first, second = pair.shares
    i = min(int(end_index(normal)), len(film) - 2)  # the end lies in step i
    end_slip = wall.e_t - (wall.spin[0] + change)
    film_end = film[i] + slip_energy * (wall.slip[i] ** 2 - end_slip**2)
    at_end = kinetic_energy(wall.e_t, upper[0] + first * change, lower[0] + second * change)
    lost = kinetic[0] - at_end
    error = abs(lost - film_end - friction[i]) / lost if lost > 0 else 0.0
    return PairMotion(
        pair=pair,
        lower_spin=lower,
        lower_spin_change=second * change,
        contact_spin_change=change,
        kinetic=kinetic,
        film_dissipated=film,
        friction_dissipated=friction,
        balance_error=float(error),
    )
