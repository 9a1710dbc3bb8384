"""Tangential motion and spin, driven by the film of the normal solution (decoupled).

Sign conventions (used everywhere in ehdfem):
- x is the direction of the tangential impact velocity, U0 = |v| sin(angle) >= 0;
- U is the tangential velocity of the sphere's centre along x;
- the spin Omega is counted so that a Omega = U when the sphere rolls without slipping, i.e. the
  sphere's surface at the contact moves at the slip velocity u_s = U - a Omega.

Scales: U, a Omega, u_s and the rolling speed w = U + a Omega by U0; time by x0/V0; tangential
force by 6 pi mu a^2 U0 / x0 (so St dU/dT = F_t, as for the normal motion); torque by
6 pi mu a^3 U0 / x0; energies by m U0^2 / St (kinetic E_t = (St/2)(U^2 + k (a Omega)^2)). The
initial spin input is a Omega0 / V0 (scaled by the normal speed). I = k m a^2.

Two film models (docs/tangential.md derives them):

- ``couette`` (the source's sliding lubrication): the Couette shear of the normal solution's
  film, J = int theta (mu/mu0) R dR / H0,

      St dU/dT = -(delta/3) J u_s,    k St d(a Omega)/dT = (delta/3) J u_s,

  integrated exactly (U + k a Omega is conserved and u_s decays as
  exp(-(1 + 1/k) (delta/(3 St)) int J dT), with int J dT by the trapezoid rule).
- ``gcb`` and ``flat``, reduced models of the kind DEM codes use: ``gcb`` a rigid sphere's
  leading logarithmic resistances on (U, a Omega) at the normal solution's thinnest film
  (:func:`gcb_resistance`, integrated by :func:`integrate_resistance`); ``flat`` the Couette
  model with the shear of a uniform film, the central thickness, over the Hertz contact disk
  of the normal force (:func:`flat_contact`).
- ``lubrication`` (beyond the source): the sliding film. The sphere's sliding and rolling drive
  an azimuthal mode-1 film pressure q(R) cos(phi) (:class:`ehdfem.film.mode_one.ModeOneFilm`, unit
  (U0/V0) sqrt(delta) mu V0 a / x0^2), which deforms the solids (mode-1 compliance,
  :class:`ehdfem.solids.compliance.ModeOneCompliance`): a mode-1 gap H1 = C q + ... that feeds back
  into the film, and, with the Couette traction, tangential surface displacements D whose rate
  adds to the slip (v = u_s + sqrt(delta) dD/dT at each node). Force and torque on the sphere
  from the pressure on both deformed surfaces and the shear:

      St dU/dT = -(delta/12) int q Sigma0' R dR + (delta/12) int Sigma1 P0' R dR
                 - (delta/6) int (mu/mu0) theta (v_r + v_phi) R dR / H0,
      k St d(a Omega)/dT = -St dU/dT - (delta/6) int q R^2 dR,

  with Sigma = z_s + z_w the sum of the surface heights (Sigma0 = X + R^2/2 for identical
  solids). ``deformation``: "none" (rigid mode-1 solids: q solves the quasi-steady rigid
  problem; on rigid solids this gives the classical leading logarithms: force 8/15 and 2/15 of
  6 pi mu a U ln(a/h), torque 1/10 and 2/5 of 8 pi mu a^2 U ln(a/h)), "gap" (the mode-1 normal
  displacements) or "full" (also the tangential ones in the slip). The pressure is linearised
  about the normal solution; where P0 sits at the cavitation limit q = 0.

The lubrication system is a linear differential-algebraic system in (q, v, U, a Omega), solved
at the normal solution's steps by variable-step BDF2 (BDF1 on the first step and where a step
grows by more than 1 + sqrt(2)). Its energy balance (docs/tangential.md)

    dE_t/dT = -(Couette + Poiseuille dissipation) - (delta/6) dE_1/dT + X

is recorded term by term: E_1 the mode-1 elastic energy, X the work exchanged with the normal
motion (zero on rigid solids, where the tangential motion only dissipates).

Where the normal motion has a solid contact (a rough sphere's solid impact, an asperity load)
and the friction coefficient mu > 0, its Coulomb friction acts in every model
(:mod:`ehdfem.tangential.friction`), and the sliding film's balance gains its dissipation.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.integrate
import scipy.linalg

from .. import checks
from ..film.mode_one import ModeOneFilm, mode_one_operators
from ..film.reynolds import Film
from ..motion.normal import NormalResult, NormalSolverError
from ..solids.compliance import ModeOneCompliance
from .friction import ContactFriction, CoulombContact

MODELS = ("couette", "lubrication", "gcb", "flat")
DEFORMATIONS = ("none", "gap", "full")
_BDF2_GROWTH = 1.0 + np.sqrt(2.0)  # largest step ratio for which variable-step BDF2 is stable
BREAKDOWN_TILT = 1.0  # a linearisation tilt (gap_tilt, viscosity_tilt) at which it fails


class SlidingFilmError(NormalSolverError):
    """The sliding film's linearisation broke down: a tilt (:func:`gap_tilt`,
    :func:`viscosity_tilt`) reached BREAKDOWN_TILT or its linear system had no finite solution.
    Where this happens (a film frozen by a pressure-dependent viscosity, docs/tangential.md)
    only the Couette model applies."""


def sliding_amplitude(params) -> float:
    """s = (U0/V0) sqrt(delta): the factor of the mode-1 pressure q and gap H1 (scaled)."""
    return params.tangential_speed * np.sqrt(params.delta)


def gap_tilt(params, film_thickness, mode_one_gap):
    """s |H1| / H0 at the wetted nodes (0 elsewhere; H by x0, any leading shape): the mode-1
    gap against the film thickness it is superposed on; at 1 the film closes on one side."""
    wet = film_thickness < 1.0 if params.layer == "thin" else np.ones(film_thickness.shape, bool)
    return np.where(wet, sliding_amplitude(params) * np.abs(mode_one_gap) / film_thickness, 0.0)


def viscosity_tilt(params, pressure, mode_one_pressure):
    """s |q| d ln(mu/mu0)/dP at P0 (pressures by mu V0 a / x0^2, any leading shape): the change of
    ln mu the mode-1 pressure makes, which the sliding film linearises (mu = mu(P0)
    (1 + s q cos(phi) d ln mu/dP)); 0 at constant viscosity, and at 1 exp differs from its
    linearisation by a factor e/2."""
    slope = params.viscosity_law().ratio(pressure)[1]
    return sliding_amplitude(params) * np.abs(mode_one_pressure) * slope


ENERGY_GAIN_LIMIT = 1e-6  # flag a rise of the tangential kinetic energy above this share


class TangentialEnergyWarning(UserWarning):
    """A sliding-film result whose tangential kinetic energy rose above its impact value."""


@dataclass
class TangentialEnergy:
    """The sliding film's energy balance at the steps (by m U0^2 / St, as E_t): ``kinetic``
    E_t, ``dissipated`` (Couette and Poiseuille, integrated), ``elastic`` (delta/6) E_1 of the
    mode-1 loads, ``exchanged`` the integrated X (work from the normal motion, zero for rigid
    solids), ``friction`` the Coulomb friction's dissipation of the solid contact
    (:mod:`ehdfem.tangential.friction`; zero without one). ``balance_error``:
    |E_t(0) - E_t - dissipated - elastic + exchanged - friction| at the end over the energy the
    tangential motion lost, max(E_t(0) - E_t(end), dissipated + friction)."""

    kinetic: np.ndarray
    dissipated: np.ndarray
    elastic: np.ndarray
    exchanged: np.ndarray
    friction: np.ndarray
    balance_error: float

    @property
    def gain(self) -> float:
        """The largest rise of E_t over its impact value, max(E_t) / E_t(0) - 1 (0 if it never
        rises): energy the sliding film created from the normal motion."""
        return max(float(self.kinetic.max() / self.kinetic[0]) - 1.0, 0.0)

    @property
    def flagged(self) -> bool:
        """The tangential kinetic energy rose above its impact value by more than
        ENERGY_GAIN_LIMIT."""
        return self.gain > ENERGY_GAIN_LIMIT

    def warning(self, deformation: str) -> str:
        """The warning for a flagged sliding film with mode-1 ``deformation``."""
        cause = (
            "with sliding deformation 'none' the deformed solids keep no mode-1 gap, and the "
            "normal motion's work goes into the sliding (docs/tangential.md): use 'gap' or 'full'"
            if deformation == "none"
            else "the first-order sliding film does not forbid it, but e_t and spin_change are "
            "then doubtful (docs/tangential.md)"
        )
        return (
            f"the sliding film raised the tangential kinetic energy to {1 + self.gain:.4g} times "
            f"its impact value: {cause}"
        )


@dataclass
class TangentialResult:
    """Tangential outcome (scaled as in the module docstring).

    ``e_t`` = U / U0 and ``spin_change`` = a (Omega - Omega0) / U0, at exit for a rebounding
    sphere, or when the normal motion stopped for a sticking one (``at`` = "exit" or "stop").
    Both are None for a head-on impact (U0 = 0). Histories at the normal solution's steps:
    ``velocity`` U/U0, ``spin`` a Omega/U0, ``slip`` u_s/U0, ``force`` F_t, ``shear`` J(T) (for
    the reduced models the J with the same translational resistance, 3 R_11 / delta).
    ``deformation``: the mode-1 deformation of the lubrication model ("none" for Couette);
    ``energy``: its balance (:class:`TangentialEnergy`, None for Couette);
    ``mode_one_pressure``: q and ``mode_one_gap``: H1 at the steps and film nodes (by
    (U0/V0) sqrt(delta) times the film pressure unit and times x0; None for Couette).
    ``friction``: the Coulomb friction of the solid contact (:class:`ContactFriction`; None
    without one, or with mu = 0). ``force`` is the film's force; the contact's impulses are in
    ``friction``.
    """

    model: str
    deformation: str
    at: str
    e_t: float | None
    spin_change: float | None
    time: np.ndarray
    shear: np.ndarray
    velocity: np.ndarray
    spin: np.ndarray
    slip: np.ndarray
    force: np.ndarray
    energy: TangentialEnergy | None
    mode_one_pressure: np.ndarray | None = None
    mode_one_gap: np.ndarray | None = None
    friction: ContactFriction | None = None


def normal_film(normal: NormalResult) -> Film:
    """The film of the normal solution (its nodes, layer, viscosity law and gap)."""
    params = normal.params
    return Film(normal.radii, params.layer, params.viscosity_law(), normal.gap)


def cavitated_nodes(normal: NormalResult, step: int) -> np.ndarray:
    """Where the normal solution's film is cavitated at ``step`` (boolean, per node): P0 at the
    cavitation limit, or a liquid fraction below 1."""
    hist = normal.history
    p_cav = normal.params.cavitation_model().p_cav
    at_limit = p_cav + 1e-12 * abs(p_cav) if np.isfinite(p_cav) else -np.inf
    return (hist.fill[step] < 1.0) | (hist.pressure[step] <= at_limit)


def mode_one_film(
    normal: NormalResult, step: int, film: Film | None = None, unloaded=None
) -> ModeOneFilm:
    """The film's mode-1 operators (:class:`ehdfem.film.mode_one.ModeOneFilm`) at one step of the
    normal solution, with the viscosity at that step's pressure, its liquid fraction and q = 0
    at its cavitated nodes and at the nodes ``unloaded`` (boolean; None: none). ``film``:
    :func:`normal_film`, if built already."""
    film = normal_film(normal) if film is None else film
    cavitated = cavitated_nodes(normal, step)
    if unloaded is not None:
        cavitated = cavitated | unloaded
    hist = normal.history
    outer = 1.0 / np.sqrt(normal.params.delta)
    return mode_one_operators(
        film,
        hist.film_thickness[step],
        outer,
        hist.pressure[step],
        hist.fill[step],
        cavitated,
    )


def mode_one_films(normal: NormalResult, unloaded=None):
    """:func:`mode_one_film` at each step of the normal solution, in order (``unloaded``:
    (steps, N) boolean, more nodes with q = 0 at each step; None: none)."""
    film = normal_film(normal)
    for step in range(len(normal.history.time)):
        yield mode_one_film(normal, step, film, None if unloaded is None else unloaded[step])


def film_integrals(normal: NormalResult) -> np.ndarray:
    """The Couette integral J(T) at the steps of the normal solution (immersed: with the far
    field out to the sphere's radius)."""
    film, outer = normal_film(normal), 1.0 / np.sqrt(normal.params.delta)
    hist = normal.history
    shear = []
    for h, p, theta in zip(hist.film_thickness, hist.pressure, hist.fill, strict=True):
        weights, tail = film.couette_weights(h, outer, p, theta)
        shear.append(weights.sum() + tail)
    return np.array(shear)


def solve_tangential(
    normal: NormalResult,
    model: str = "couette",
    mode_one: ModeOneCompliance | None = None,
    surface_sum: np.ndarray | None = None,
    deformation: str = "gap",
    unloaded: np.ndarray | None = None,
) -> TangentialResult:
    """Tangential velocity and spin through the collision from the normal solution's film.

    ``model`` "couette" or "lubrication" (module docstring). For "lubrication": ``mode_one``
    the solids' mode-1 compliance at the normal solution's eps and film nodes (None: rigid
    solids), ``surface_sum`` the (N, N) sum of the two surfaces' axisymmetric z-displacements
    per unit nodal pressure (:attr:`ehdfem.solids.compliance.Compliance.surface_sum_matrix`; None:
    zero), ``deformation`` which mode-1 deformation acts (DEFORMATIONS), ``unloaded`` a
    (steps, N) boolean array of further nodes where q = 0 at each step (None: only the
    cavitated ones; :mod:`ehdfem.tangential.superposition` uses it to measure the cavitation rule's
    effect)."""
    checks.choice("tangential model", model, MODELS)
    checks.choice("deformation", deformation, DEFORMATIONS)
    if model == "lubrication":
        return _SlidingFilm(normal, mode_one, surface_sum, deformation).solve(unloaded)
    return {"couette": _couette, "gcb": _gcb, "flat": _flat}[model](normal)


def _couette(normal: NormalResult) -> TangentialResult:
    """The Couette model (module docstring): the film's Couette integral J(T) on the slip."""
    return _sheared(normal, "couette", film_integrals(normal))


def _sheared(normal: NormalResult, model: str, shear: np.ndarray) -> TangentialResult:
    """The motion under a Couette shear J(T) on the slip (the ``couette`` and ``flat`` models),
    integrated exactly for each step's mean J: St dU/dT = -(delta/3) J u_s = -k St d(a Omega)/dT
    conserves U + k a Omega and makes u_s decay by exp(-(1 + 1/k) delta/(3 St) int J dT) (so
    an overflowing J, a frozen piezoviscous film, rolls the sphere at once), also from the
    last step to the exit; the solid contact's Coulomb impulse after each step
    (:class:`ehdfem.tangential.friction.CoulombContact`)."""
    params = normal.params
    hist = normal.history
    k, St, delta = params.inertia_factor, params.St, params.delta
    shear_m = 0.5 * (shear[1:] + shear[:-1])
    rate = delta / (3 * St) * np.diff(hist.time) * shear_m
    decay = np.exp(-(1.0 + 1.0 / k) * rate)
    states = np.empty((len(hist.time), 2))
    states[0] = (1.0, _initial_spin(params))

    def decayed(i, factor):  # (U, a Omega) after step i's slip decays by factor
        slip = (states[i, 0] - states[i, 1]) * factor
        momentum = k * states[i, 1] + states[i, 0]  # conserved: U + k a Omega
        return (momentum + k * slip) / (1 + k), (momentum - slip) / (1 + k)

    contact = CoulombContact.of(normal)
    for i, factor in enumerate(decay):
        states[i + 1] = decayed(i, factor)
        if contact is not None:
            states[i + 1] = contact.act(i + 1, *states[i + 1])
    end = _end_index(normal)  # the end inside step i: its share of the step's decay
    i = min(int(end), len(decay) - 1)
    at_end = decayed(i, decay[i] ** (end - i))
    velocity, spin = states.T
    force = -delta / 3.0 * shear * (velocity - spin)
    histories = (velocity, spin, shear, force)
    return _result(normal, model, "none", histories, None, at_end=at_end, contact=contact)


def gcb_resistance(delta: float, min_film) -> np.ndarray:
    """Goldman, Cox & Brenner's (1967) leading logarithmic resistances of a rigid sphere
    translating and rotating next to a plane, at the thinnest film h = H_min x0 (``min_film``
    H_min, any shape), L = ln(a/h) = -ln(delta H_min):

        R = delta L [[8/15, -2/15], [-2/15, 8/15]]

    on (U, a Omega) (force by 6 pi mu a^2 U0 / x0, torque over a likewise; shape (..., 2, 2));
    the O(1) terms of the expansions are left out."""
    logarithm = -np.log(delta * np.asarray(min_film, dtype=float))
    return delta * logarithm[..., None, None] * (np.array([[8.0, -2.0], [-2.0, 8.0]]) / 15.0)


def _gcb(normal: NormalResult) -> TangentialResult:
    """The rigid-sphere model: :func:`gcb_resistance` at the normal solution's thinnest film."""
    resistance = gcb_resistance(normal.params.delta, normal.history.min_film)
    return _resisted(normal, "gcb", resistance)


def flat_contact(params, force, film_thickness):
    """(C, J): the Hertz contact radius C = (9 pi^2 eps F / 8)^(1/3) of the scaled force F (by
    6 pi mu V0 a^2 / x0; radius by sqrt(a x0)) and the Couette integral J = C^2 / (2 H_c) of a
    uniform film H_c (by x0) over that disk (Kantak & Davis 2004, Joseph & Hunt 2004: the
    contact as a flat gap)."""
    radius = np.cbrt(9 * np.pi**2 * params.eps * np.maximum(force, 0.0) / 8)
    return radius, radius**2 / (2 * np.asarray(film_thickness))


def _flat(normal: NormalResult) -> TangentialResult:
    """The flat-gap model: the Couette shear of a uniform film, the central thickness H(0, T),
    over the Hertz contact disk of the normal force (:func:`flat_contact`); none outside it."""
    hist = normal.history
    _, shear = flat_contact(normal.params, np.asarray(hist.force), hist.film_thickness[:, 0])
    return _sheared(normal, "flat", shear)


def integrate_resistance(
    time, resistance, St: float, k: float, start, contact: CoulombContact | None = None
) -> np.ndarray:
    """(U, a Omega) at the instants ``time`` (by x0/V0) under a linear resistance R(T)
    (``resistance`` (steps, 2, 2), symmetric non-negative, force by 6 pi mu a^2 U0 / x0):
    St dU/dT = -(R (U, a Omega))_1, k St d(a Omega)/dT = -(R (U, a Omega))_2, from ``start``
    (by U0). Each step takes the exact exponential of its mean R (trapezoid): second order,
    exact for a constant R, and never gaining energy. ``contact``: a solid contact whose
    Coulomb impulse acts after each step (None: none)."""
    inverse_mass = np.diag([1.0 / St, 1.0 / (k * St)])
    means = 0.5 * (resistance[1:] + resistance[:-1]) * np.diff(time)[:, None, None]
    states = np.empty((len(time), 2))
    states[0] = start
    for i, mean in enumerate(means):
        states[i + 1] = scipy.linalg.expm(-inverse_mass @ mean) @ states[i]
        if contact is not None:
            states[i + 1] = contact.act(i + 1, *states[i + 1])
    return states


def _resisted(normal: NormalResult, model: str, resistance: np.ndarray) -> TangentialResult:
    """The result of a resistance model (:func:`integrate_resistance`) on the normal solution."""
    params, hist = normal.params, normal.history
    contact = CoulombContact.of(normal)
    start = (1.0, _initial_spin(params))
    states = integrate_resistance(
        hist.time, resistance, params.St, params.inertia_factor, start, contact
    )
    velocity, spin = states.T
    force = -np.einsum("ij,ij->i", resistance[:, 0], states)
    shear = 3.0 * resistance[:, 0, 0] / params.delta
    return _result(normal, model, "none", (velocity, spin, shear, force), None, contact=contact)


def _initial_spin(params) -> float:
    """a Omega0 / U0 (0 for a head-on impact, where the spin is refused by the parameters)."""
    tangential = params.tangential_speed
    return 0.0 if tangential == 0.0 else params.spin / tangential


def _result(
    normal, model, deformation, histories, energy, mode_one=(None, None), at_end=None, contact=None
):
    """The TangentialResult from the histories (U, a Omega, J, F_t) at the steps and, for the
    sliding film, (q, H1) at the steps. ``at_end``: (U, a Omega) at the end of the collision
    if the model knows them between its steps (None: interpolated linearly). ``contact``: the
    solid contact's :class:`CoulombContact` (None: none)."""
    params, hist = normal.params, normal.history
    velocity, spin, shear, force = histories
    head_on = params.tangential_speed == 0.0
    if at_end is None:
        end, steps = _end_index(normal), np.arange(len(velocity))
        at_end = (np.interp(end, steps, velocity), np.interp(end, steps, spin))
    return TangentialResult(
        model=model,
        deformation=deformation,
        at="exit" if normal.rebound else "stop",
        e_t=None if head_on else float(at_end[0]),
        spin_change=None if head_on else float(at_end[1] - spin[0]),
        time=hist.time,
        shear=shear,
        velocity=velocity,
        spin=spin,
        slip=velocity - spin,
        force=force,
        energy=energy,
        mode_one_pressure=mode_one[0],
        mode_one_gap=mode_one[1],
        friction=None if contact is None else contact.record(),
    )


class _SlidingFilm:
    """The lubrication model's linear system over the normal solution's steps.

    Unknowns z = (q, v_r, v_phi, U, a Omega) at a step (v only with deformation "full"; else
    the nodal slip is u_s). Loads on the solids L = (q, a_r, a_phi), the Couette traction
    a = -(j / m) v on the sphere (m the lumped mass, j the Couette weights; by mu U0 / x0,
    i.e. (U0/V0) sqrt(delta) times the traction unit of the mode-1 compliance) and -a on the
    wall. Relative displacements of the faces: the gap H1, the sum Sigma1 and the tangential
    D = (D_r, D_phi) of sphere minus wall, each the compliance times L."""

    def __init__(self, normal, mode_one, surface_sum, deformation):
        params = normal.params
        self.normal, self.deformation = normal, deformation
        self.St, self.k, self.delta = params.St, params.inertia_factor, params.delta
        n = self.n = len(normal.radii)
        self.mass_full = Film(normal.radii).full_mass
        self.size = n + (2 * n if deformation == "full" else 0) + 2
        self.u, self.omega = self.size - 2, self.size - 1
        # (N, 3N) face combinations of the loads L: gap and sum of the normal displacements,
        # and with "full" the relative tangential ones (r, phi); zero for rigid mode-1 solids
        deformed = mode_one is not None and deformation != "none"
        combinations = {"gap": ("normal", (1.0, -1.0)), "sum": ("normal", (1.0, 1.0))}
        if deformation == "full":
            combinations.update(r=("radial", (1.0, -1.0)), phi=("hoop", (1.0, -1.0)))
        self.compliance = {
            name: _face_combination(mode_one, *combination) if deformed else np.zeros((n, 3 * n))
            for name, combination in combinations.items()
        }
        self.compliance.setdefault("r", None)
        self.compliance.setdefault("phi", None)
        self.surface_sum = surface_sum

    def solve(self, unloaded=None) -> TangentialResult:
        """Step through the normal solution; the tangential result with its energy balance
        (``unloaded``: further nodes with q = 0, as for :func:`mode_one_films`)."""
        normal, n = self.normal, self.n
        hist = normal.history
        steps = len(hist.time)
        z = np.zeros((steps, self.size))
        z[0, self.u], z[0, self.omega] = 1.0, _initial_spin(normal.params)
        z[0, n:-2] = z[0, self.u] - z[0, self.omega]  # v = u_s (nothing deformed yet)
        displacements = {name: np.zeros((steps, n)) for name in ("gap", "r", "phi")}
        shear, force = np.zeros(steps), np.zeros(steps)
        rates = np.zeros((steps, 2))  # dissipation and exchange rates
        elastic = np.zeros(steps)
        contact = CoulombContact.of(normal)
        for i, mf in enumerate(mode_one_films(normal, unloaded)):
            shear[i] = mf.shear_weights.sum() + mf.tail
            ops = self._operators(mf, i)
            if i > 0:
                step = hist.time[i] - hist.time[i - 1]
                ratio = np.inf  # BDF1 on the first step and after the solid impact's jump
                if i >= 2 and not (contact is not None and contact.is_impact(i - 1)):
                    ratio = step / (hist.time[i - 1] - hist.time[i - 2])
                alpha = (1.0, -1.0, 0.0)  # BDF1
                if ratio <= _BDF2_GROWTH:
                    alpha = ((1 + 2 * ratio) / (1 + ratio), -(1 + ratio), ratio**2 / (1 + ratio))
                past = {
                    name: (alpha[1] * values[i - 1] + alpha[2] * values[i - 2]) / step
                    for name, values in (*displacements.items(), ("z", z))
                }
                z[i] = self._step(mf, ops, alpha[0] / step, past, i, contact)
                for name, values in displacements.items():
                    if ops[name] is not None:
                        values[i] = ops[name] @ z[i]
                self._check_tilts(z[i], displacements["gap"][i], i)
                if contact is not None and contact.is_impact(i):
                    self._impact_acts(contact, z[i], i)
            force[i] = ops["force"] @ z[i]
            *rates[i], elastic[i] = self._energy_terms(mf, ops, z[i], i, displacements)
        velocity, spin = z[:, self.u], z[:, self.omega]
        kinetic = 0.5 * self.St * (velocity**2 + self.k * spin**2)
        dissipated, exchanged = scipy.integrate.cumulative_trapezoid(
            rates, hist.time, axis=0, initial=0.0
        ).T
        friction = np.zeros(steps) if contact is None else contact.record().dissipated
        lost = max(kinetic[0] - kinetic[-1], dissipated[-1] + friction[-1], np.finfo(float).tiny)
        residual = kinetic[0] - kinetic[-1] - dissipated[-1] - elastic[-1] + exchanged[-1]
        residual -= friction[-1]
        balance = abs(residual) / lost
        energy = TangentialEnergy(kinetic, dissipated, elastic, exchanged, friction, balance)
        return _result(
            normal,
            "lubrication",
            self.deformation,
            (velocity, spin, shear, force),
            energy,
            (z[:, :n], displacements["gap"]),
            contact=contact,
        )

    def _impact_acts(self, contact: CoulombContact, z: np.ndarray, i: int) -> None:
        """The solid impact's Coulomb impulse at step i on U and a Omega in z (in place); with
        deformation "full" the nodal slips v = u_s + sqrt(delta) dD/dT change by the same jump
        of u_s (the faces' displacements D do not jump)."""
        slip = z[self.u] - z[self.omega]
        z[self.u], z[self.omega] = contact.act(i, z[self.u], z[self.omega], load=False)
        if self.deformation == "full":
            z[self.n : -2] += (z[self.u] - z[self.omega]) - slip

    def _step(self, mf: ModeOneFilm, ops: dict, rate: float, past: dict, i: int, contact=None):
        """z at step i (:meth:`_system`), or SlidingFilmError if it has no finite solution;
        with the asperities' friction force of ``contact`` (a :class:`CoulombContact`; None:
        none) in the rows of U and a Omega (St dU/dT = F + F_f, k St d(a Omega)/dT = T - F_f)."""
        try:
            matrix, rhs = self._system(mf, ops, rate, past)
            if contact is None or contact.force_bounds[i] == 0.0:
                z = _solve_equilibrated(matrix, rhs, self.u, self.omega)
            else:
                unit = np.zeros(self.size)
                unit[self.u], unit[self.omega] = 1.0, -1.0
                rhs = np.column_stack([rhs, unit])
                free, response = _solve_equilibrated(matrix, rhs, self.u, self.omega).T
                slips = [y[self.u] - y[self.omega] for y in (free, response)]
                z = free + contact.resist(i, *slips) * response
        except (np.linalg.LinAlgError, ValueError):
            z = np.full(self.size, np.nan)
        if not np.isfinite(z).all():
            raise SlidingFilmError(
                f"the sliding film has no finite solution at T = {self.normal.history.time[i]:.4g}"
                f" (mu/mu0 up to {self._viscosity_ratio(i):.3g}); use tangential = 'couette'"
            )
        return z

    def _check_tilts(self, z: np.ndarray, mode_one_gap: np.ndarray, i: int) -> None:
        """SlidingFilmError where a tilt of the linearisation reaches BREAKDOWN_TILT at step i."""
        params, hist = self.normal.params, self.normal.history
        tilts = {
            "s |H1| / H0": gap_tilt(params, hist.film_thickness[i], mode_one_gap),
            "s |q| d ln(mu)/dP": viscosity_tilt(params, hist.pressure[i], z[: self.n]),
        }
        for name, tilt in tilts.items():
            if tilt.max() >= BREAKDOWN_TILT:
                raise SlidingFilmError(
                    f"the sliding film's linearisation broke down at T = {hist.time[i]:.4g}:"
                    f" {name} = {tilt.max():.3g} >= {BREAKDOWN_TILT} (mu/mu0 up to"
                    f" {self._viscosity_ratio(i):.3g}); the film is not a small perturbation"
                    " of the normal one (a film frozen by the pressure-dependent viscosity,"
                    " docs/tangential.md); use tangential = 'couette'"
                )

    def _viscosity_ratio(self, i: int) -> float:
        """The largest mu/mu0 of the normal film at step i."""
        law = self.normal.params.viscosity_law()
        return float(law.ratio(self.normal.history.pressure[i])[0].max())

    def _operators(self, mf: ModeOneFilm, i: int) -> dict:
        """Row operators on z at step i: q, the Couette weights, the loads L, the face
        displacements (gap, sum, r, phi), the force and the torque."""
        n, size, delta = self.n, self.size, self.delta
        full = self.deformation == "full"
        rolling, sliding = np.zeros(size), np.zeros(size)
        rolling[[self.u, self.omega]] = 1.0, 1.0
        sliding[[self.u, self.omega]] = 1.0, -1.0
        traction = -mf.shear_weights / self.mass_full  # a = traction * v, by mu U0 / x0

        def slip(component):  # nodal slip velocity v_r or v_phi as rows on z
            if full:
                rows = np.zeros((n, size))
                rows[:, n * (1 + component) : n * (2 + component)] = np.eye(n)
                return rows
            return np.outer(np.ones(n), sliding)

        def displacement(compliance):  # compliance (n, 3n) @ L as rows on z
            if compliance is None:
                return None
            rows = np.zeros((n, size))
            rows[:, :n] = compliance[:, :n]
            for component in range(2):
                part = compliance[:, n * (1 + component) : n * (2 + component)] * traction
                if full:
                    rows[:, n * (1 + component) : n * (2 + component)] += part
                else:
                    rows += np.outer(part.sum(axis=1), sliding)
            return rows

        ops = {"slip_r": slip(0), "slip_phi": slip(1)}
        ops.update({name: displacement(c) for name, c in self.compliance.items()})
        surface_sum = None
        if self.surface_sum is not None:
            surface_sum = self.surface_sum @ self.normal.history.pressure[i]
        slope_weights = mf.surface_slope_weights(surface_sum)
        gradient_weights = mf.gradient_weights()
        force = (delta / 12.0) * (gradient_weights @ ops["sum"])
        force[:n] -= (delta / 12.0) * slope_weights
        force -= (delta / 6.0) * (mf.shear_weights @ (ops["slip_r"] + ops["slip_phi"]))
        force -= (delta / 3.0) * mf.tail * (sliding + 0.6 * rolling)
        torque = -force - 0.4 * delta * mf.tail * rolling
        torque[:n] -= (delta / 6.0) * mf.torque_weights
        ops.update(
            force=force,
            torque=torque,
            gradient_weights=gradient_weights,
            rolling=rolling,
            sliding=sliding,
            traction=traction,
            slope_weights=slope_weights,
        )
        return ops

    def _system(self, mf: ModeOneFilm, ops: dict, rate: float, past: dict):
        """The step's matrix and right-hand side; d/dT of Y is rate Y + past[Y]."""
        n, size = self.n, self.size
        matrix, rhs = np.zeros((size, size)), np.zeros(size)
        free = np.flatnonzero(mf.free)
        gap = ops["gap"]
        film = (mf.conductance + mf.pressure_coupling)[free]
        rows = mf.thickness_coupling[free] @ gap
        rows[:, :n] += film
        rows += rate * mf.mass[free, None] * gap[free]
        rows -= 0.5 * np.outer(mf.drive[free], ops["rolling"])
        matrix[free] = rows
        rhs[free] = -mf.mass[free] * past["gap"][free]
        fixed = np.flatnonzero(~mf.free)
        matrix[fixed, fixed] = 1.0
        if self.deformation == "full":
            root = np.sqrt(self.delta)
            for component, name in enumerate(("r", "phi")):
                block = slice(n * (1 + component), n * (2 + component))
                matrix[block] = ops["slip_" + name] - np.outer(np.ones(n), ops["sliding"])
                matrix[block] -= root * rate * ops[name]
                rhs[block] = root * past[name]
        matrix[self.u] = -ops["force"]
        matrix[self.u, self.u] += self.St * rate
        rhs[self.u] = -self.St * past["z"][self.u]
        matrix[self.omega] = -ops["torque"]
        matrix[self.omega, self.omega] += self.k * self.St * rate
        rhs[self.omega] = -self.k * self.St * past["z"][self.omega]
        return matrix, rhs

    def _energy_terms(self, mf: ModeOneFilm, ops: dict, z: np.ndarray, i: int, displacements):
        """(dissipation rate, exchange rate X, elastic energy) at a step (module docstring)."""
        n, delta = self.n, self.delta
        q = z[:n]
        u_s, w = ops["sliding"] @ z, ops["rolling"] @ z
        v_r, v_phi = ops["slip_r"] @ z, ops["slip_phi"] @ z
        h1 = displacements["gap"][i]
        sigma1 = ops["sum"] @ z
        dissipation = (delta / 6.0) * (
            mf.shear_weights @ (v_r**2 + v_phi**2) + q @ mf.conductance @ q
        )
        dissipation += delta * mf.tail * (u_s**2 / 3.0 + w**2 / 5.0)
        pressure_force = (delta / 12.0) * (
            ops["gradient_weights"] @ sigma1 - ops["slope_weights"] @ q
        )
        exchange = u_s * (pressure_force + (delta / 12.0) * (mf.torque_weights @ q))
        exchange -= (delta / 6.0) * (q @ mf.thickness_coupling @ h1 + q @ mf.pressure_coupling @ q)
        exchange += (delta / 12.0) * w * ((mf.drive - mf.torque_weights) @ q)
        work = self.mass_full @ (q * h1)
        if self.deformation == "full":
            loads = ops["traction"] * np.stack([v_r, v_phi])
            shifts = np.stack([displacements["r"][i], displacements["phi"][i]])
            work += np.sqrt(delta) * (self.mass_full * loads * shifts).sum()
        return dissipation, exchange, (delta / 12.0) * work


def _solve_equilibrated(matrix, rhs, u: int, omega: int):
    """Solve matrix z = rhs (``rhs`` a vector, or one right-hand side per column) in the
    unknowns y = z except the sliding velocity U - a Omega in
    place of U (index ``u``; ``omega`` that of a Omega), with every column of the transformed
    matrix and then every row scaled to unit largest entry. A piezoviscous film's Reynolds rows
    are smaller than the others by mu/mu0 (up to 1e30 and more), and its Couette traction makes
    the columns of the slip velocities larger by as much: the unscaled rows of U and a Omega
    are then parallel to round-off (the film locks the sphere into rolling), the scaled system
    is not."""
    transformed = matrix.copy()  # matrix @ B, B = I + e_u e_omega^T: z_U = (U - a Omega) + a Omega
    transformed[:, omega] += matrix[:, u]
    column_scale = 1.0 / np.abs(transformed).max(axis=0)
    transformed *= column_scale
    row_scale = 1.0 / np.abs(transformed).max(axis=1)
    if rhs.ndim == 2:  # several right-hand sides, one a column
        z = column_scale[:, None] * scipy.linalg.solve(
            transformed * row_scale[:, None], rhs * row_scale[:, None]
        )
    else:
        z = column_scale * scipy.linalg.solve(transformed * row_scale[:, None], rhs * row_scale)
    z[u] += z[omega]  # back from y to z = B y
    return z


def _face_combination(mode_one: ModeOneCompliance, component: str, signs) -> np.ndarray:
    """(N, 3N): sign_s (sphere) + sign_w (wall) of a displacement ``component`` ("normal",
    "radial", "hoop") under the loads L = (q, a_r, a_phi): the pressure q on both faces, the
    traction (a_r, a_phi) on the sphere and its opposite on the wall."""
    blocks = []
    for loads in (("pressure",), ("sphere_radial", "wall_radial"), ("sphere_hoop", "wall_hoop")):
        total = 0.0
        for face, sign in zip(("sphere", "wall"), signs, strict=True):
            for load, load_sign in zip(loads, (1.0, -1.0), strict=False):
                total = total + sign * load_sign * mode_one.block(f"{face}_{component}", load)
        blocks.append(total)
    return np.hstack(blocks)


def _end_index(normal: NormalResult) -> float:
    """Fractional step index of the exit (X back to 1), or the last step for a sticking sphere."""
    hist = normal.history
    if not normal.rebound:
        return float(len(hist.time) - 1)
    return float(np.interp(normal.contact_time, hist.time, np.arange(len(hist.time))))
