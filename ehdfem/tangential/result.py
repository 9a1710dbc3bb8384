"""The result of a tangential model: velocity, spin and shear at the normal solution's steps,
the tangential restitution and spin change, and the sliding film's energy balance (the sign
conventions and scales of :mod:`ehdfem.tangential.motion`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..motion.normal import NormalResult
from .friction import ContactFriction

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
    ``friction``. ``pair``: for two free spheres, the lower sphere's spin, the contact spin and
    the pair's energy balance (:class:`ehdfem.tangential.pair.PairMotion`; None for a sphere on
    a wall); ``velocity`` and ``e_t`` are then the relative ones and ``spin`` the upper sphere's.
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
    pair: object | None = None


def initial_spin(params) -> float:
    """a Omega0 / U0 (0 for a head-on impact, where the spin is refused by the parameters)."""
    tangential = params.tangential_speed
    return 0.0 if tangential == 0.0 else params.spin / tangential


def tangential_result(
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
        end, steps = end_index(normal), np.arange(len(velocity))
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


def end_index(normal: NormalResult) -> float:
    """Fractional step index of the contact's end at the contact time: the exit (X back to 1)
    or the stop (V back to 0) inside the last step, the last step itself at rest or stalled.
    A stuck sphere's e_t and spin change were read at the last step, up to a step after its
    stop (1.7 % in the spin change at thin St 1, eps 1e-3, P_cav -10, 30 degrees)."""
    hist = normal.history
    return float(np.interp(normal.contact_time, hist.time, np.arange(len(hist.time))))
