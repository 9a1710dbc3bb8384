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

An immersed film's integrals end at the sphere's radius r = a, where the lubrication
approximation stops holding; ``outer_flow`` "exact" adds the rest of the flow as the constant
resistance delta dR that Goldman, Cox & Brenner's (1967) exact resistances of a rigid sphere
leave beyond each model's own (:mod:`ehdfem.tangential.outer_film`), on (U, a Omega) in the
rows of U and a Omega; "none" (default) leaves it out and estimates it.

Where the normal motion has a solid contact (a rough sphere's solid impact, an asperity load)
and the friction coefficient mu > 0, its Coulomb friction acts in every model
(:mod:`ehdfem.tangential.friction`), and the sliding film's balance gains its dissipation.
"""

from __future__ import annotations

import numpy as np
import scipy.integrate
import scipy.linalg

from .. import checks
from ..exact.sliding_sphere import LOGARITHMIC
from ..motion.normal import NormalResult
from ..solids.compliance import ModeOneCompliance
from .friction import CoulombContact
from .normal_film import film_integrals
from .outer_film import check_outer_flow, left_out_resistance
from .result import TangentialResult, end_index, initial_spin, tangential_result
from .sliding_film import SlidingFilm

MODELS = ("couette", "lubrication", "gcb", "flat")
DEFORMATIONS = ("none", "gap", "full")


def solve_tangential(
    normal: NormalResult,
    model: str = "couette",
    mode_one: ModeOneCompliance | None = None,
    surface_sum: np.ndarray | None = None,
    deformation: str = "gap",
    unloaded: np.ndarray | None = None,
    outer_flow: str = "none",
) -> TangentialResult:
    """Tangential velocity and spin through the collision from the normal solution's film.

    ``model`` "couette" or "lubrication" (module docstring). For "lubrication": ``mode_one``
    the solids' mode-1 compliance at the normal solution's eps and film nodes (None: rigid
    solids), ``surface_sum`` the (N, N) sum of the two surfaces' axisymmetric z-displacements
    per unit nodal pressure (:attr:`ehdfem.solids.compliance.Compliance.surface_sum_matrix`; None:
    zero), ``deformation`` which mode-1 deformation acts (DEFORMATIONS), ``unloaded`` a
    (steps, N) boolean array of further nodes where q = 0 at each step (None: only the
    cavitated ones; :mod:`ehdfem.tangential.superposition` uses it to measure the cavitation rule's
    effect). ``outer_flow``: "none" (the film's integrals end at the sphere's radius) or
    "exact" (an immersed film: the flow beyond them added as the constant resistance
    delta dR of :func:`ehdfem.tangential.outer_film.left_out_resistance`; not with "flat")."""
    checks.choice("tangential model", model, MODELS)
    checks.choice("deformation", deformation, DEFORMATIONS)
    params = normal.params
    check_outer_flow(outer_flow, model, params.layer, params.angle)
    outer = None if outer_flow == "none" else params.delta * left_out_resistance(model)
    if model == "lubrication":
        return SlidingFilm(normal, mode_one, surface_sum, deformation, outer).solve(unloaded)
    if model == "flat":
        return _flat(normal)
    return {"couette": _couette, "gcb": _gcb}[model](normal, outer)


def _couette(normal: NormalResult, outer=None) -> TangentialResult:
    """The Couette model (module docstring): the film's Couette integral J(T) on the slip;
    with the constant ``outer`` resistance (delta dR, None: none) integrated as a resistance
    matrix (:func:`integrate_resistance`), since U + k a Omega is then not conserved."""
    shear = film_integrals(normal)
    if outer is None:
        return _sheared(normal, "couette", shear)
    sliding = np.array([[1.0, -1.0], [-1.0, 1.0]])
    resistance = normal.params.delta / 3.0 * shear[:, None, None] * sliding + outer
    return _resisted(normal, "couette", resistance)


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
    states[0] = (1.0, initial_spin(params))

    def decayed(i, factor):  # (U, a Omega) after step i's slip decays by factor
        slip = (states[i, 0] - states[i, 1]) * factor
        momentum = k * states[i, 1] + states[i, 0]  # conserved: U + k a Omega
        return (momentum + k * slip) / (1 + k), (momentum - slip) / (1 + k)

    contact = CoulombContact.of(normal)
    for i, factor in enumerate(decay):
        states[i + 1] = decayed(i, factor)
        if contact is not None:
            states[i + 1] = contact.act(i + 1, *states[i + 1])
    end = end_index(normal)  # the end inside step i: its share of the step's decay
    i = min(int(end), len(decay) - 1)
    at_end = decayed(i, decay[i] ** (end - i))
    velocity, spin = states.T
    force = -delta / 3.0 * shear * (velocity - spin)
    histories = (velocity, spin, shear, force)
    return tangential_result(normal, model, "none", histories, None, at_end=at_end, contact=contact)


def gcb_resistance(delta: float, min_film) -> np.ndarray:
    """Goldman, Cox & Brenner's (1967) leading logarithmic resistances of a rigid sphere
    translating and rotating next to a plane, at the thinnest film h = H_min x0 (``min_film``
    H_min, any shape), L = ln(a/h) = -ln(delta H_min):

        R = delta L [[8/15, -2/15], [-2/15, 8/15]]

    on (U, a Omega) (force by 6 pi mu a^2 U0 / x0, torque over a likewise; shape (..., 2, 2));
    the O(1) terms of the expansions are left out."""
    logarithm = -np.log(delta * np.asarray(min_film, dtype=float))
    return delta * logarithm[..., None, None] * LOGARITHMIC


def _gcb(normal: NormalResult, outer=None) -> TangentialResult:
    """The rigid-sphere model: :func:`gcb_resistance` at the normal solution's thinnest film,
    plus the constant ``outer`` resistance (Goldman, Cox & Brenner's O(1) terms; None: none)."""
    resistance = gcb_resistance(normal.params.delta, normal.history.min_film)
    if outer is not None:
        resistance = resistance + outer
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


def integrate_resistance(time, resistance, St: float, inertia, start, jump=None):
    """(states, dissipated): the velocities v at the instants ``time`` (by x0/V0) under a linear
    resistance R(T) (``resistance`` (steps, n, n), symmetric non-negative, generalised forces
    by 6 pi mu a^2 U0 / x0), St diag(``inertia``) dv/dT = -R v from ``start`` (by U0; a sphere
    on a wall: v = (U, a Omega), inertia (1, k)), and the film's dissipation int v.R v dT so
    far (by m U0^2 / St). Each step takes the exact exponential of its mean R (trapezoid):
    second order, exact for a constant R, and never gaining energy (:func:`resistance_step`).
    ``jump``: a function (step, v) -> v acting after each step (a solid contact's Coulomb
    impulse; None: none)."""
    inverse_mass = np.diag(1.0 / (St * np.asarray(inertia, dtype=float)))
    means = 0.5 * (resistance[1:] + resistance[:-1]) * np.diff(time)[:, None, None]
    states = np.empty((len(time), len(start)))
    dissipated = np.zeros(len(time))
    states[0] = start
    for i, mean in enumerate(means):
        propagator, gram = resistance_step(mean, inverse_mass)
        states[i + 1] = propagator @ states[i]
        dissipated[i + 1] = dissipated[i] + states[i] @ gram @ states[i]
        if jump is not None:
            states[i + 1] = jump(i + 1, states[i + 1])
    return states, dissipated


def resistance_step(impulse, inverse_mass, fraction: float = 1.0):
    """(P, G) of a step under a constant resistance whose impulse over the step is ``impulse``
    (R dT, (n, n)), on the share ``fraction`` of the step: v_end = P v and the dissipation
    int v.R v dT = v.G v, with P = exp(-A f), A = M^-1 R dT, G = int_0^f exp(-A^T s) R dT
    exp(-A s) ds, both from one exponential of the block matrix [[A^T, R dT], [0, -A]] f
    (Van Loan 1978)."""
    n = len(impulse)
    rate = inverse_mass @ impulse
    block = np.zeros((2 * n, 2 * n))
    block[:n, :n], block[:n, n:], block[n:, n:] = rate.T, impulse, -rate
    exponential = scipy.linalg.expm(fraction * block)
    propagator = exponential[n:, n:]
    return propagator, propagator.T @ exponential[:n, n:]


def _resisted(normal: NormalResult, model: str, resistance: np.ndarray) -> TangentialResult:
    """The result of a resistance model (:func:`integrate_resistance`) on the normal solution."""
    params, hist = normal.params, normal.history
    contact = CoulombContact.of(normal)
    jump = None if contact is None else lambda i, state: contact.act(i, *state)
    start = (1.0, initial_spin(params))
    inertia = (1.0, params.inertia_factor)
    states, _ = integrate_resistance(hist.time, resistance, params.St, inertia, start, jump)
    velocity, spin = states.T
    force = -np.einsum("ij,ij->i", resistance[:, 0], states)
    shear = 3.0 * resistance[:, 0, 0] / params.delta
    return tangential_result(
        normal, model, "none", (velocity, spin, shear, force), None, contact=contact
    )
