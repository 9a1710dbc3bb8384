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

Each law is a component (:mod:`ehdfem.settings`): a frozen dataclass with its ``name``, its
scaled constants declared with ``setting(...)`` and the members of :class:`ViscosityLaw`,
registered in :data:`LAWS`. A new law is one such class, here or in a module of its own.

Decision: the laws act on the compressive part of the pressure, max(P, 0). Under suction the
viscosity is mu0: a liquid holds at most about an atmosphere of suction, where alpha_SI p is
of order 1e-3, and the clip keeps Roelands defined for any suction the film computes.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar, Protocol

import numpy as np
from numba import njit
from scipy.optimize import brentq
from scipy.special import gammainc, gammaincc, gammaln

from .. import checks
from ..settings import Registry, setting, validate

ROELANDS_PRESSURE = 1.96e8  # Pa, the reference pressure p_r of the Roelands law
ROELANDS_LOG_VISCOSITY = 9.67  # -ln(6.31e-5), mu in Pa s: the Roelands asymptote
ROELANDS_INDEX = 0.6  # Z of typical mineral oils, used when alpha does not give one
BARUS_EXCESS = 1.0  # ln of the factor by which Barus may exceed Roelands within its validity
# alpha P_r / Z of the Roelands law at most (ln(mu0 / 6.31e-5 Pa s) of a liquid, some 30 for a
# bitumen): its fluidity integral takes e^(alpha P_r / Z)
ROELANDS_SCALE_LIMIT = 500.0
CUT_DECAY = 60.0  # the Roelands fluidity integral's pieces end where its integrand fell by e^-60
_GAUSS_POINTS, _GAUSS_WEIGHTS = np.polynomial.legendre.leggauss(6)
_GAUSS_POINTS, _GAUSS_WEIGHTS = 0.5 + 0.5 * _GAUSS_POINTS, 0.5 * _GAUSS_WEIGHTS


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
        f"(viscosity {Roelands.name})"
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


class ViscosityLaw(Protocol):
    """What the film, the sliding film and the checks ask of a viscosity law (scaled: pressure
    by mu0 V0 a / x0^2, viscosity by mu0).

    ``name``: its flat name; ``pressure_dependent``: whether it takes the liquid's
    pressure-viscosity coefficient alpha (its physical inputs then need one);
    ``constant``: mu = mu0 at every pressure; ``ratio(P)``: (mu/mu0, d ln(mu/mu0)/dP);
    ``log_ratio(P+)``: ln(mu/mu0) at the compressive pressure, numpy or UFL;
    ``fluidity_integral(lower, upper)``: int_lower^upper mu0/mu dP between compressive
    pressures 0 <= lower <= upper (arrays), to about 1e-12 relative however steeply mu grows
    between them (the film's element conductance, :mod:`ehdfem.film.elements`);
    ``overflow(P)``: why mu/mu0 overflowed; ``validity_pressure(alpha_SI, mu0)``: the
    pressure [Pa] up to which it holds; ``of_liquid(alpha_SI, mu0, pressure_scale)`` (a
    classmethod): the law of a liquid of viscosity mu0 [Pa s] and coefficient alpha_SI
    [1/Pa] at the pressure scale [Pa], the physical inputs' route to it."""

    name: ClassVar[str]
    pressure_dependent: ClassVar[bool]
    constant: bool

    def ratio(self, pressure): ...
    def log_ratio(self, compressive): ...
    def fluidity_integral(self, lower, upper): ...
    def overflow(self, pressure) -> str: ...
    def validity_pressure(self, pressure_viscosity: float, viscosity: float) -> float: ...
    def of_liquid(cls, pressure_viscosity, viscosity, pressure_scale): ...


LAWS = Registry("viscosity", ViscosityLaw)  # the viscosity laws by name


def _ratio(law, pressure, slope):
    """(mu/mu0, its log-slope) of ``law`` at ``pressure`` with the log-slope ``slope`` at the
    compressive part; mu0 and slope 0 under suction."""
    pressure = np.asarray(pressure, dtype=float)
    with np.errstate(over="ignore"):  # inf: the film refuses the iterate (FilmError)
        ratio = np.exp(law.log_ratio(np.maximum(pressure, 0.0)))
    return ratio, np.where(pressure > 0.0, slope, 0.0)


def _overflow(law, pressure) -> str:
    """Why mu/mu0 overflowed (> 1e308, ln > 709) at the scaled pressures ``pressure``."""
    largest = float(np.max(pressure))
    return (
        f"the {law.name} viscosity overflows (mu/mu0 > 1e308) at the pressure iterate "
        f"{largest:.4g} (by mu V0 a / x0^2; alpha P = {law.alpha * largest:.4g})"
    )


@njit(cache=True, error_model="numpy")
def _roelands_one_piece(lower, upper, p_r, z, scale):
    """Roelands's :meth:`Roelands.fluidity_integral` where one six-point Gauss-Legendre rule in
    t = ln(1 + (P - lower)/(P_r + lower)) holds (ln mu grows by less than 1/2 and the
    integrand's logarithm, of slope at most 1 + Z (ln mu + A), by at most 1/2; 0 on an empty
    span), in one compiled pass: (integrals, ln mu's growth, the spans' widths in t, whether
    done), each per span; ``scale`` A = alpha P_r / Z."""
    n = len(lower)
    result, growth, widening = np.zeros(n), np.empty(n), np.empty(n)
    done = np.empty(n, np.bool_)
    for k in range(n):
        base = p_r + lower[k]
        power = (base / p_r) ** z  # (1 + P/P_r)^Z = power e^(Z t) at the span's points
        widening[k] = math.log1p((upper[k] - lower[k]) / base)
        growth[k] = scale * power * math.expm1(z * widening[k])
        top = scale * (power - 1.0) + growth[k]  # ln(mu/mu0) at the upper end
        done[k] = upper[k] == lower[k]
        if done[k] or growth[k] >= 0.5 or widening[k] * (1.0 + z * (top + scale)) > 0.5:
            continue
        result[k] = _gauss_in_log(base, power, widening[k], 1, z, scale)
        done[k] = True
    return result, growth, widening, done


@njit(cache=True, error_model="numpy")
def _gauss_in_log(base, power, width, pieces, z, scale):
    """int mu0/mu dP of a Roelands law (``scale`` A = alpha P_r / Z) from P = lower to the
    point ``width`` along t = ln(1 + (P - lower)/``base``), ``base`` = P_r + lower, by
    six-point Gauss-Legendre on ``pieces`` equal pieces of t: dP = base e^t dt and
    ln(mu/mu0) = A (``power`` e^(Z t) - 1), ``power`` = (base / P_r)^Z."""
    piece = width / pieces
    total = 0.0
    for k in range(pieces):
        for q in range(len(_GAUSS_POINTS)):
            t = piece * (k + _GAUSS_POINTS[q])
            log_ratio = scale * (power * math.exp(z * t) - 1.0)
            total += _GAUSS_WEIGHTS[q] * math.exp(t - log_ratio)
    return base * piece * total


ALPHA_HELP = "pressure-viscosity coefficient, the law's slope d ln(mu)/dP at low pressure"
ALPHA_UNIT = "by x0^2 / (mu V0 a), the inverse pressure scale"


@LAWS.register
@dataclass(frozen=True)
class ConstantViscosity:
    """mu / mu0 = 1 at every pressure."""

    name: ClassVar[str] = "constant"
    pressure_dependent: ClassVar[bool] = False
    constant: ClassVar[bool] = True

    def ratio(self, pressure):
        """(1, 0) at the scaled pressures ``pressure``."""
        pressure = np.asarray(pressure, dtype=float)
        return np.ones_like(pressure), np.zeros_like(pressure)

    def log_ratio(self, compressive):
        """ln(mu / mu0) = 0."""
        return 0.0 * compressive

    def fluidity_integral(self, lower, upper):
        """int_lower^upper dP = upper - lower (scaled pressures)."""
        return np.asarray(upper, dtype=float) - np.asarray(lower, dtype=float)

    def overflow(self, pressure) -> str:
        """Never: mu / mu0 = 1."""
        return "the constant viscosity does not overflow"

    def validity_pressure(self, pressure_viscosity: float, viscosity: float) -> float:
        """inf [Pa]: the law holds at every pressure (within its model)."""
        return math.inf

    @classmethod
    def of_liquid(cls, pressure_viscosity, viscosity, pressure_scale):
        """The constant law whatever the liquid."""
        return cls()


class Piezoviscous:
    """What the pressure-dependent laws share (Barus, Roelands; a base of their frozen
    dataclasses): the liquid's coefficient alpha among their constants, validated when made,
    and the law constant (mu = mu0) when alpha = 0."""

    pressure_dependent: ClassVar[bool] = True
    alpha: float

    def __post_init__(self):
        validate(self)

    @property
    def constant(self) -> bool:
        """True when alpha = 0."""
        return self.alpha == 0.0


@LAWS.register
@dataclass(frozen=True)
class Barus(Piezoviscous):
    """Barus (1893): mu / mu0 = exp(alpha P), alpha scaled by the inverse pressure scale."""

    name: ClassVar[str] = "barus"
    alpha: float = setting(0.0, help=ALPHA_HELP, unit=ALPHA_UNIT, lower=0.0)

    def log_ratio(self, compressive):
        """ln(mu / mu0) = alpha P at the compressive part P = max(P, 0) (numpy or UFL)."""
        return self.alpha * compressive

    def ratio(self, pressure):
        """(mu / mu0, d ln(mu / mu0) / dP = alpha for P > 0) at the scaled ``pressure``."""
        return _ratio(self, pressure, self.alpha)

    def fluidity_integral(self, lower, upper):
        """int_lower^upper exp(-alpha P) dP = exp(-alpha lower) (1 - exp(-alpha (upper -
        lower))) / alpha between compressive scaled pressures (upper - lower at alpha = 0)."""
        lower, upper = np.asarray(lower, dtype=float), np.asarray(upper, dtype=float)
        if self.alpha == 0.0:
            return upper - lower
        return np.exp(-self.alpha * lower) * -np.expm1(-self.alpha * (upper - lower)) / self.alpha

    def overflow(self, pressure) -> str:
        """Why mu/mu0 overflowed at the scaled pressures ``pressure``."""
        return _overflow(self, pressure) + (
            f": far outside the Barus law's validity, use the Roelands law (viscosity "
            f"{Roelands.name})"
        )

    def validity_pressure(self, pressure_viscosity: float, viscosity: float) -> float:
        """:func:`barus_validity_pressure` [Pa]: where the law leaves the Roelands law."""
        return barus_validity_pressure(pressure_viscosity, viscosity)

    @classmethod
    def of_liquid(cls, pressure_viscosity, viscosity, pressure_scale):
        """alpha = alpha_SI [1/Pa] times the pressure scale [Pa]."""
        return cls(alpha=pressure_viscosity * pressure_scale)


@LAWS.register
@dataclass(frozen=True)
class Roelands(Piezoviscous):
    """Roelands (1966): mu / mu0 = exp((alpha P_r / Z) [(1 + P / P_r)^Z - 1]), P_r by the
    pressure scale, Z in (0, 2] (module docstring)."""

    name: ClassVar[str] = "roelands"
    roelands_pressure: float = setting(
        help="Roelands p_r = 1.96e8 Pa", unit="by mu V0 a / x0^2", lower=0.0, lower_open=True
    )
    alpha: float = setting(0.0, help=ALPHA_HELP, unit=ALPHA_UNIT, lower=0.0)
    roelands_index: float = setting(
        ROELANDS_INDEX, help="Roelands index Z", lower=0.0, upper=2.0, lower_open=True
    )

    @property
    def log_scale(self) -> float:
        """A = alpha P_r / Z (dimensionless): ln(mu / mu0) = A [(1 + P / P_r)^Z - 1]."""
        return self.alpha * self.roelands_pressure / self.roelands_index

    def log_ratio(self, compressive):
        """ln(mu / mu0) = (alpha P_r / Z) [(1 + P / P_r)^Z - 1] at the compressive part P."""
        z, p_r = self.roelands_index, self.roelands_pressure
        return self.log_scale * ((1.0 + compressive / p_r) ** z - 1.0)

    def ratio(self, pressure):
        """(mu / mu0, alpha (1 + P / P_r)^(Z - 1) for P > 0) at the scaled ``pressure``."""
        base = 1.0 + np.maximum(np.asarray(pressure, dtype=float), 0.0) / self.roelands_pressure
        return _ratio(self, pressure, self.alpha * base ** (self.roelands_index - 1.0))

    def fluidity_integral(self, lower, upper):
        """int_lower^upper mu0/mu dP between compressive scaled pressures, to about 1e-12.

        In t = ln(1 + P/P_r), dP = (P_r + lower) e^(t - t_lower) dt and ln(mu/mu0) =
        A (e^(Z t) - 1), A = alpha P_r / Z: a span over which the integrand's logarithm changes
        by at most 1/2 and ln(mu) by less than 1/2 is integrated by six-point Gauss-Legendre in
        t. One over which ln(mu) grows more takes the closed form: with x = A (1 + P/P_r)^Z,
        (P_r / Z) e^A A^(-1/Z) times the difference of the regularised incomplete gamma
        functions of 1/Z at x_lower and x_upper, upper Q above the integrand's mode
        x = 1/Z - 1, lower P below it, split at the mode across it (each accurate in its tail).
        Where that difference would cancel (its subtracted term above half the other: a slowly
        thickening liquid, alpha P_r < 1) or underflow, and on a wide span over which ln(mu)
        grows little, the span is cut into pieces of the Gauss rule's size (:meth:`_pieces`)."""
        lower, upper = np.broadcast_arrays(
            np.asarray(lower, dtype=float), np.asarray(upper, dtype=float)
        )
        shape = lower.shape
        lower, upper = lower.ravel(), upper.ravel()
        result, growth, widening, done = _roelands_one_piece(
            lower, upper, self.roelands_pressure, self.roelands_index, self.log_scale
        )
        rest = np.flatnonzero(~done)
        if rest.size:
            closed, exact = self._gamma_integral(lower[rest], upper[rest])
            exact &= growth[rest] >= 0.5
            result[rest] = closed
            for k in rest[~exact]:  # rare: a wide or cancelling span, cut into pieces
                result[k] = self._pieces(float(lower[k]), float(upper[k]), widening[k])
        return result.reshape(shape)

    def _pieces(self, lower: float, upper: float, widening: float) -> float:
        """:meth:`fluidity_integral` of one span by :func:`_gauss_in_log` on equal pieces of
        t (``widening``: the span's width in t). The integrand's logarithm phi(t) = t - ln(mu)
        is concave in t, its slope 1 - Z (ln(mu) + A) falling along the span, so largest in
        magnitude at an end: the span is cut where phi has fallen CUT_DECAY = 60 below its
        largest value (what lies beyond adds about e^-60 of the integral), and the pieces are
        small enough for phi to change by at most 1/2 on each."""
        base = self.roelands_pressure + lower
        z, scale = self.roelands_index, self.log_scale

        def phi(t):
            return t - self.log_ratio(lower + base * math.expm1(t))

        def slope(t):
            return 1.0 - z * (self.log_ratio(lower + base * math.expm1(t)) + scale)

        peak = 0.0 if slope(0.0) <= 0.0 else widening  # phi's largest value on the span
        if 0.0 < slope(0.0) and slope(widening) < 0.0:
            peak = brentq(slope, 0.0, widening, xtol=1e-12 * max(widening, 1.0))
        cut, top = widening, phi(peak)
        if phi(widening) < top - CUT_DECAY:
            cut = brentq(lambda t: phi(t) - (top - CUT_DECAY), peak, widening, xtol=1e-9)
        pieces = max(1, int(np.ceil(2.0 * cut * max(abs(slope(0.0)), abs(slope(cut))))))
        power = (base / self.roelands_pressure) ** z
        return _gauss_in_log(base, power, cut, pieces, z, scale)

    def _gamma_integral(self, lower, upper):
        """(the closed form of :meth:`fluidity_integral` on 1-D arrays, whether it holds to
        full precision): no cancellation (the subtracted incomplete gamma term at most half
        the other) and no underflow."""
        p_r, z = self.roelands_pressure, self.roelands_index
        a, scale = 1.0 / z, self.log_scale
        x_lower = scale * (1.0 + lower / p_r) ** z
        x_upper = scale * (1.0 + upper / p_r) ** z
        mode = max(a - 1.0, 0.0)
        below = np.minimum(x_upper, mode)  # the parts of [x_lower, x_upper] below the mode
        above = np.maximum(x_lower, mode)  # and above it
        lower_first, lower_second = gammainc(a, np.minimum(x_lower, mode)), gammainc(a, below)
        upper_first, upper_second = gammaincc(a, above), gammaincc(a, np.maximum(x_upper, mode))
        tails = (lower_second - lower_first) + (upper_first - upper_second)
        exact = (x_lower >= mode) | (lower_first <= 0.5 * lower_second)
        exact &= (x_upper <= mode) | (upper_second <= 0.5 * upper_first)
        exact &= tails > 1e-290
        log_factor = scale + gammaln(a) - a * math.log(scale) + math.log(p_r / z)
        with np.errstate(divide="ignore"):
            return np.exp(log_factor + np.log(tails)), exact

    def __post_init__(self):
        super().__post_init__()
        scale = self.log_scale
        if scale > ROELANDS_SCALE_LIMIT:
            raise checks.InputError(
                "alpha roelands_pressure / roelands_index must be at most"
                f" {ROELANDS_SCALE_LIMIT} (a liquid's is ln(mu0 / 6.31e-5 Pa s)); got {scale:.4g}"
            )

    def overflow(self, pressure) -> str:
        """Why mu/mu0 overflowed at the scaled pressures ``pressure``."""
        return _overflow(self, pressure)

    def validity_pressure(self, pressure_viscosity: float, viscosity: float) -> float:
        """inf [Pa]: the law is bounded at high pressure."""
        return math.inf

    @classmethod
    def of_liquid(cls, pressure_viscosity, viscosity, pressure_scale):
        """P_r = 1.96e8 Pa and alpha by the pressure scale, Z from alpha_SI and mu0
        (:func:`roelands_index`; ROELANDS_INDEX when alpha is 0); refuses a liquid at or below
        the Roelands asymptote."""
        check_roelands_viscosity("the liquid", viscosity)
        index = roelands_index(pressure_viscosity, viscosity) if pressure_viscosity > 0 else None
        return cls(
            roelands_pressure=ROELANDS_PRESSURE / pressure_scale,
            alpha=pressure_viscosity * pressure_scale,
            roelands_index=ROELANDS_INDEX if index is None else index,
        )
