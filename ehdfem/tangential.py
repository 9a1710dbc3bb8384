"""Tangential motion and spin, driven by the film of the normal solution (decoupled).

Sign conventions (used everywhere in ehdfem):
- x is the direction of the tangential impact velocity, U0 = |v| sin(angle) >= 0;
- U is the tangential velocity of the sphere's centre along x;
- the spin Omega is counted so that a Omega = U when the sphere rolls without slipping, i.e. the
  sphere's surface at the contact moves at the slip velocity u_s = U - a Omega.

Scales: U, a Omega and u_s by U0 (when U0 > 0); time by x0/V0; tangential force by
6 pi mu a^2 U0 / x0 (so St dU/dT = F_t, as for the normal motion); torque by 6 pi mu a^3 U0/x0.
The initial spin input is a Omega0 / V0 (scaled by the normal speed, so that it is defined for
head-on impacts too).

With the film integrals J, G, M of :meth:`ehdfem.film.Film.sliding_integrals`, the slip
u_s = U - a Omega and the rolling speed w = U + a Omega, and I = k m a^2:

    St dU/dT = F_t = -(delta/3) (J u_s + G w),
    k St d(a Omega)/dT = -F_t - delta M w.

- ``couette`` (the source's sliding lubrication): Couette shear only, G = M = 0; then the slip
  decays as u_s0 exp(-(1 + 1/k) (delta/(3 St)) int J dT) and a DeltaOmega/U0 = (1 - e_t)/k.
- ``lubrication`` (beyond the source): the sliding-induced pressure too (azimuthal mode 1 of
  the Reynolds equation on the deformed film). On a rigid sphere near a wall it gives the
  classical leading logarithms: force 8/15 (translation) and 2/15 (rotation) of
  6 pi mu a U ln(a/h), torque 1/10 and 2/5 of 8 pi mu a^2 U ln(a/h). It is exact for rigid
  solids only: on deformable ones its force takes the gap slope for the surfaces' slope and its
  mode-1 film does not deform, and the system can create energy in a flattened contact
  (docs/tangential.md derives the consistent model).

Each step of the normal solution is integrated exactly for the step's mean coefficients (a
2x2 matrix exponential, by Sylvester's formula so that it stays exact for the very large rates
of a piezoviscous film), which is exact for the Couette model given int J dT (trapezoid).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.linalg

from . import checks
from .film import Film
from .normal import NormalResult

MODELS = ("couette", "lubrication")


@dataclass
class TangentialResult:
    """Tangential outcome (scaled as in the module docstring).

    ``e_t`` = U / U0 and ``spin_change`` = a (Omega - Omega0) / U0, at exit for a rebounding
    sphere, or when the normal motion stopped for a sticking one (``at`` = "exit" or "stop").
    Both are None for a head-on impact (U0 = 0). Histories at the normal solution's steps:
    ``velocity`` U/U0, ``spin`` a Omega/U0, ``slip`` u_s/U0, ``force`` F_t, ``shear`` J(T).
    """

    model: str
    at: str
    e_t: float | None
    spin_change: float | None
    time: np.ndarray
    shear: np.ndarray
    velocity: np.ndarray
    spin: np.ndarray
    slip: np.ndarray
    force: np.ndarray


def film_integrals(normal: NormalResult, model: str = "couette") -> np.ndarray:
    """(steps, 3) array of J, G, M at each step of the normal solution (G = M = 0 for Couette),
    with the film's viscosity at each step's pressure and its liquid fraction."""
    checks.choice("tangential model", model, MODELS)
    params = normal.params
    film = Film(normal.radii, params.layer, params.viscosity_law(), normal.gap)
    outer = 1.0 / np.sqrt(params.delta)
    hist = normal.history
    values = np.array(
        [
            film.sliding_integrals(h, outer, p, theta)
            for h, p, theta in zip(hist.film_thickness, hist.pressure, hist.fill, strict=True)
        ]
    )
    if model == "couette":
        values[:, 1:] = 0.0
    return values


def solve_tangential(normal: NormalResult, model: str = "couette") -> TangentialResult:
    """Tangential velocity and spin through the collision from the normal solution's film."""
    params = normal.params
    hist = normal.history
    integrals = film_integrals(normal, model)
    shear, force_pressure, torque_pressure = integrals.T
    k, St, delta = params.inertia_factor, params.St, params.delta
    tangential = params.tangential_speed  # U0 / V0
    head_on = tangential == 0.0
    spin0 = 0.0 if head_on else params.spin / tangential  # a Omega0 / U0
    # mean coefficients over each step (the rates are linear in J, G, M)
    shear_m, force_m, torque_m = (
        0.5 * (v[1:] + v[:-1]) for v in (shear, force_pressure, torque_pressure)
    )
    rate = delta / (3 * St) * np.diff(hist.time)
    rates = rate * np.array(
        [
            [-(shear_m + force_m), shear_m - force_m],
            [
                (shear_m + force_m - 3 * torque_m) / k,
                -(shear_m - force_m + 3 * torque_m) / k,
            ],
        ]
    )  # (2, 2, steps - 1): d(U, a Omega)/dT = rates @ (U, a Omega) / dT over each step
    determinants = rate**2 * 6.0 * torque_m * shear_m / k  # exact, free of cancellation
    states = np.empty((len(hist.time), 2))
    states[0] = (1.0, spin0)
    for i in range(len(hist.time) - 1):
        states[i + 1] = _exponential(rates[:, :, i], determinants[i]) @ states[i]
    velocity, spin = states.T
    slip, rolling = velocity - spin, velocity + spin
    end = _end_index(normal)
    steps = np.arange(len(velocity))
    return TangentialResult(
        model=model,
        at="exit" if normal.rebound else "stop",
        e_t=None if head_on else float(np.interp(end, steps, velocity)),
        spin_change=None if head_on else float(np.interp(end, steps, spin) - spin0),
        time=hist.time,
        shear=shear,
        velocity=velocity,
        spin=spin,
        slip=slip,
        force=-delta / 3.0 * (shear * slip + force_pressure * rolling),
    )


def _exponential(matrix, determinant):
    """exp(matrix) for a 2x2 matrix with real eigenvalues l1, l2 (Sylvester's formula),

        exp(A) = (l1 e^l2 - l2 e^l1) / (l1 - l2) I + (e^l1 - e^l2) / (l1 - l2) A,

    with the small eigenvalue from the given determinant, l2 = det / l1, so that it stays exact
    when a piezoviscous film makes l1 so large that exp(l1) underflows (there the entries of A
    are huge and the closed forms that use them to find both eigenvalues lose l2)."""
    trace = matrix[0, 0] + matrix[1, 1]
    discriminant = trace**2 - 4.0 * determinant
    if discriminant <= 0.0:
        return scipy.linalg.expm(matrix)
    large = 0.5 * (trace + np.copysign(np.sqrt(discriminant), trace))
    if large == 0.0:
        return np.eye(2)
    small = determinant / large
    gap = large - small
    if abs(gap) <= 1e-8 * abs(large):
        return scipy.linalg.expm(matrix)
    e_large, e_small = np.exp(large), np.exp(small)
    return (large * e_small - small * e_large) / gap * np.eye(2) + (
        e_large - e_small
    ) / gap * matrix


def _end_index(normal: NormalResult) -> float:
    """Fractional step index of the exit (X back to 1), or the last step for a sticking sphere."""
    hist = normal.history
    if not normal.rebound:
        return float(len(hist.time) - 1)
    return float(np.interp(normal.contact_time, hist.time, np.arange(len(hist.time))))
