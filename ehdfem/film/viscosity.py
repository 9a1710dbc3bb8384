"""Pressure-dependent viscosity of the film liquid (piezoviscosity).

The laws give the viscosity ratio mu(p) / mu0 as a function of the scaled gauge pressure
P = p / (mu0 V0 a / x0^2) (mu0: the viscosity at ambient pressure):

    constant:  mu / mu0 = 1
    Barus:     mu / mu0 = exp(alpha P)
    Roelands:  mu / mu0 = exp((alpha P_r / Z) [(1 + P / P_r)^Z - 1])

with the scaled pressure-viscosity coefficient alpha = alpha_SI mu0 V0 a / x0^2 (alpha_SI in
1/Pa), the Roelands reference pressure P_r = 1.96e8 Pa / (mu0 V0 a / x0^2) and the
pressure-viscosity index Z. Written this way Roelands has the same slope alpha as Barus at low
pressure; with alpha_SI and mu0 in Pa s, Z = alpha_SI 1.96e8 Pa / (ln(mu0) + 9.67), the
classical form mu = mu0 exp{(ln mu0 + 9.67) [(1 + 5.1e-9 p)^Z - 1]} (Roelands 1966).

Barus has no bound: at a pressure where exp(alpha P) exceeds the Roelands law of the same slope
alpha by a factor e (:func:`barus_validity_pressure`, 0.26 GPa for the main job's oil at
alpha_SI = 2e-8 1/Pa) it is outside its validity, and a collision whose film goes past it is
flagged (:class:`ViscosityRangeWarning`).

Decision: the laws act on the compressive part of the pressure, max(P, 0). Under suction the
viscosity is mu0: a liquid holds at most about an atmosphere of suction, where alpha_SI p is
of order 1e-3, and the clip keeps Roelands defined for any suction the film computes.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from .. import checks

LAWS = ("constant", "barus", "roelands")
ROELANDS_PRESSURE = 1.96e8  # Pa, the reference pressure p_r of the Roelands law
ROELANDS_LOG_VISCOSITY = 9.67  # -ln(6.31e-5), mu in Pa s: the Roelands asymptote
ROELANDS_INDEX = 0.6  # Z of typical mineral oils, used when alpha does not give one
BARUS_EXCESS = 1.0  # ln of the factor by which Barus may exceed Roelands within its validity


class ViscosityRangeWarning(UserWarning):
    """A Barus film whose pressure went past the law's validity (barus_validity_pressure)."""


def barus_validity_pressure(pressure_viscosity: float, viscosity: float) -> float:
    """p_B [Pa] with alpha p_B - (alpha p_r / Z) [(1 + p_B / p_r)^Z - 1] = BARUS_EXCESS: the
    gauge pressure above which the Barus viscosity exp(alpha p) exceeds the Roelands law of
    the same low-pressure slope alpha (pressure_viscosity, 1/Pa) for a liquid of viscosity mu0
    (Pa s; p_r = 1.96e8 Pa, Z from :func:`roelands_index`) by more than a factor e; inf for
    alpha = 0, for Z >= 1 (Roelands never below Barus) and at or below the Roelands
    asymptote 6.31e-5 Pa s (no Roelands law to compare with)."""
    if pressure_viscosity <= 0.0 or viscosity <= math.exp(-ROELANDS_LOG_VISCOSITY):
        return math.inf
    index = roelands_index(pressure_viscosity, viscosity)
    if index >= 1.0:
        return math.inf
    scale = pressure_viscosity * ROELANDS_PRESSURE

    def excess(ratio):  # ln(mu_Barus / mu_Roelands) - BARUS_EXCESS at p = ratio p_r
        return scale * ratio - scale / index * ((1.0 + ratio) ** index - 1.0) - BARUS_EXCESS

    upper = BARUS_EXCESS / scale
    while excess(upper) <= 0.0:
        upper *= 2.0
    return ROELANDS_PRESSURE * brentq(excess, 0.0, upper, xtol=1e-15, rtol=1e-14)


def barus_range_warning(largest: float, validity: float) -> str:
    """The warning for a Barus film whose largest pressure ``largest`` went past ``validity``
    (both in Pa, gauge)."""
    return (
        f"the Barus viscosity is outside its validity: the film's pressure reached "
        f"{largest:.3g} Pa, past {validity:.3g} Pa where exp(alpha p) exceeds the Roelands law "
        "of the same alpha by a factor e (docs/model.md, Barus's range): use the Roelands law "
        "(viscosity roelands)"
    )


def roelands_index(pressure_viscosity: float, viscosity: float) -> float:
    """Z = alpha p_r / (ln(mu0 / Pa s) + 9.67): the Roelands index with the low-pressure slope
    alpha (pressure_viscosity in 1/Pa, viscosity mu0 in Pa s)."""
    return pressure_viscosity * ROELANDS_PRESSURE / (math.log(viscosity) + ROELANDS_LOG_VISCOSITY)


def check_roelands_viscosity(liquid: str, viscosity: float) -> None:
    """Refuse a liquid (name ``liquid``, viscosity mu0 in Pa s) at or below the Roelands
    asymptote exp(-ROELANDS_LOG_VISCOSITY) = 6.31e-5 Pa s, where the law's ln(mu0) + 9.67 is
    not positive."""
    floor = math.exp(-ROELANDS_LOG_VISCOSITY)
    if viscosity <= floor:
        raise checks.InputError(
            f"the Roelands law needs a viscosity above {floor:.3g} Pa s; "
            f"{liquid} has {viscosity} Pa s"
        )


@dataclass(frozen=True)
class Viscosity:
    """A viscosity law in scaled form (see the module docstring).

    ``law``: "constant", "barus" or "roelands"; ``alpha``: the scaled pressure-viscosity
    coefficient alpha_SI mu0 V0 a / x0^2, >= 0; ``roelands_pressure``: P_r scaled by
    mu0 V0 a / x0^2 (Roelands only); ``roelands_index``: Z in (0, 2] (Roelands only).
    """

    law: str = "constant"
    alpha: float = 0.0
    roelands_pressure: float | None = None
    roelands_index: float = ROELANDS_INDEX

    def __post_init__(self):
        checks.choice("viscosity", self.law, LAWS)
        checks.number("alpha", self.alpha, lower=0.0)
        checks.number("roelands_index", self.roelands_index, lower=0.0, upper=2.0, lower_open=True)
        if self.law == "roelands":
            if self.roelands_pressure is None:
                raise checks.InputError(
                    "the Roelands law needs roelands_pressure (1.96e8 Pa scaled by "
                    "mu0 V0 a / x0^2), > 0"
                )
            checks.positive("roelands_pressure", self.roelands_pressure)

    @property
    def constant(self) -> bool:
        """True when mu = mu0 at every pressure (the constant law, or alpha = 0)."""
        return self.law == "constant" or self.alpha == 0.0

    def log_ratio(self, compressive):
        """ln(mu / mu0) at the compressive part max(P, 0) of the scaled pressure (a numpy array
        or a UFL expression; not for the constant law)."""
        if self.law == "barus":
            return self.alpha * compressive
        z, p_r = self.roelands_index, self.roelands_pressure
        return self.alpha * p_r / z * ((1.0 + compressive / p_r) ** z - 1.0)

    def ratio(self, pressure):
        """(mu / mu0, d ln(mu / mu0) / dP) at the scaled pressures ``pressure``."""
        pressure = np.asarray(pressure, dtype=float)
        compressive = np.maximum(pressure, 0.0)
        if self.constant:
            return np.ones_like(pressure), np.zeros_like(pressure)
        if self.law == "barus":
            slope = np.where(pressure > 0.0, self.alpha, 0.0)
        else:
            base = 1.0 + compressive / self.roelands_pressure
            slope = np.where(pressure > 0.0, self.alpha * base ** (self.roelands_index - 1.0), 0.0)
        with np.errstate(over="ignore"):  # inf: the film refuses the iterate (FilmError)
            return np.exp(self.log_ratio(compressive)), slope

    def validity_pressure(self, pressure_viscosity: float, viscosity: float) -> float:
        """The pressure [Pa] up to which the law holds for a liquid of ``viscosity`` mu0 [Pa s]
        and ``pressure_viscosity`` alpha [1/Pa]: :func:`barus_validity_pressure` for the Barus
        law (where it leaves the Roelands law), inf for the others."""
        if self.law != "barus":
            return math.inf
        return barus_validity_pressure(pressure_viscosity, viscosity)

    def overflow(self, pressure) -> str:
        """Why mu/mu0 overflowed (> 1e308, ln > 709) at the scaled pressures ``pressure``."""
        largest = float(np.max(pressure))
        note = (
            f"the {self.law} viscosity overflows (mu/mu0 > 1e308) at the pressure iterate "
            f"{largest:.4g} (by mu V0 a / x0^2; alpha P = {self.alpha * largest:.4g})"
        )
        if self.law == "barus":
            note += ": far outside the Barus law's validity, use the Roelands law"
        return note
