"""The asperities of rough surfaces: Greenwood & Tripp's contact pressure and its load on the
solids (scaled).

Scaled as in :mod:`ehdfem.motion.normal`: film thickness H and roughness sigma by x0, pressure by
mu V0 a / x0^2, radius by sqrt(a x0). sigma is the combined rms roughness of the two surfaces,
sqrt(sigma_1^2 + sigma_2^2).

Greenwood & Tripp (1970-71): two rough surfaces whose asperity summits (density eta per area
and tip radius beta on each surface, Gaussian heights whose sum has the rms sigma) touch
elastically (Hertz) carry at the mean separation h the nominal pressure

    p_a(h) = (16 sqrt(2) / 15) pi (eta beta sigma)^2 sqrt(sigma / beta) E* F_{5/2}(h / sigma),

with E* the Hertz modulus of the pair, 1/E* = (1 - nu_1^2)/E_1 + (1 - nu_2^2)/E_2 = pi theta
(a summit pair of radius beta/2 pressed together by w carries (4/3) E* sqrt(beta/2) w^(3/2),
the convention of Greenwood & Williamson 1966), and the Gaussian integral
F_n(t) = (1/sqrt(2 pi)) int_t^inf (s - t)^n exp(-s^2/2) ds. Summing that Hertz force over
pairs offset laterally by r (overlap w = z_1 + z_2 - h - r^2/(4 beta)) gives the law: the pair
integral over r turns (4/3) w^(3/2) into (32/15) pi beta (z_1 + z_2 - h)^(5/2), and the sum of
the two heights is Gaussian with rms sigma. The mixed-lubrication literature often writes the
same law with the plane-strain modulus E' = 2 E* and the prefactor (8 sqrt(2) / 15) pi; the
prefactor 16 sqrt(2)/15 with E' = 2 E* is twice too large (tests/test_roughness.py checks the
law against the summit-pair sum by quadrature). F_n's closed form is
F_n(t) = Gamma(n + 1) exp(-t^2/4) D_{-n-1}(t) / sqrt(2 pi), D the parabolic cylinder function
(:func:`gaussian_integral`; the fit 4.4086e-5 (4 - t)^6.804 often used instead is 10 % low at
contact). With eps = 4 theta mu V0 a^(3/2) / x0^(5/2), E* by the pressure scale mu V0 a / x0^2
is 4 / (pi eps sqrt(delta)), and the scaled pressure is P_a = K F_{5/2}(H/sigma),

    K = (64 sqrt(2) / 15) (eta beta sigma)^2 sqrt(sigma / beta) / (eps sqrt(delta)),

and the energy stored in the asperities per area, int_H^inf P_a dH = (2/7) K sigma F_{7/2}(H/sigma)
(dF_n/dt = -n F_{n-1}). The solids carry the asperities' load with the film's: at given film
pressure P and gap X the thickness solves H = X + S(R) + C (P + P_a(H)) (:meth:`GreenwoodTripp.
thickness`), and the implicit step's Newton matrix takes dH/dP = (I - C D)^-1 C and dH/dX =
(I - C D)^-1 1 with D = diag(dP_a/dH) (:meth:`GreenwoodTripp.loaded`).

The other asperity model, the impact, has no pressure law: the approach ends in a solid
collision when the thinnest film reaches sigma (:mod:`ehdfem.motion.normal`).

Each asperity model is a component (:mod:`ehdfem.settings`): a frozen dataclass with its
name, the surfaces' roughness sigma (by x0; 0: smooth), the Coulomb friction coefficient of
their solid contact and its own constants, with the members of :class:`AsperityModel`,
registered in :data:`MODELS`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar, Protocol

import numpy as np
from scipy.special import gamma, pbdv

from .. import checks
from ..settings import Registry, setting, validate
from .reynolds import FilmError

REACH = 6.0  # H/sigma beyond which P_a is taken as 0 (F_{5/2}(6) = 3e-11, 5e-11 of F_{5/2}(0))
NEWTON_TOL = 1e-13  # the loaded thickness's Newton tolerance, relative to H
STIFF = 1e-6  # a node is in the Newton matrices where |dP_a/dH| times its compliance exceeds this
# Greenwood & Williamson 1966 measured eta beta sigma of 0.03 to 0.05 on many surfaces; sigma/beta
# 1e-3 is the mixed-lubrication literature's value for ground steel (Gelinck & Schipper 2000)
ASPERITY_DENSITY = 0.04
ASPERITY_SLOPE = 1e-3


def gaussian_integral(order: float, t):
    """F_n(t) = (1/sqrt(2 pi)) int_t^inf (s - t)^n exp(-s^2/2) ds (n = ``order`` > -1), in
    closed form Gamma(n + 1) exp(-t^2/4) D_{-n-1}(t) / sqrt(2 pi); 0 for t >= REACH, and
    F_n(-REACH) for t < -REACH (no film is that thin: such a value only stops a Newton
    iterate, whose step then fails and is retried)."""
    t = np.asarray(t, dtype=float)
    near = np.clip(t, -REACH, REACH)  # below -REACH (H < -6 sigma: a failing iterate) it saturates
    value = gamma(order + 1.0) * np.exp(-0.25 * near**2) * pbdv(-order - 1.0, near)[0]
    return np.where(t < REACH, value / math.sqrt(2.0 * math.pi), 0.0)


def stiffness(asperity_density, asperity_slope, eps, delta) -> float:
    """K = (64 sqrt(2)/15) (eta beta sigma)^2 sqrt(sigma/beta) / (eps sqrt(delta)) (by
    mu V0 a / x0^2): Greenwood & Tripp's prefactor (16 sqrt(2)/15) pi (eta beta sigma)^2
    sqrt(sigma/beta) times the Hertz modulus E* = 1/(pi theta), itself 4/(pi eps sqrt(delta))
    in the pressure scale (module docstring). ``asperity_density`` eta beta sigma and
    ``asperity_slope`` sigma/beta are pure numbers, sigma the combined roughness."""
    gt = 16.0 * math.sqrt(2.0) / 15.0 * math.pi * asperity_density**2 * math.sqrt(asperity_slope)
    return gt * 4.0 / (math.pi * eps * math.sqrt(delta))


@dataclass(frozen=True)
class LoadedThickness:
    """The film thickness under the film and asperity pressures (by x0) with its sensitivities:
    ``thickness`` H, ``asperity_pressure`` P_a(H), ``slope`` dP_a/dH, ``by_pressure`` dH/dP
    (matrix) and ``by_gap`` dH/dX (vector)."""

    thickness: np.ndarray
    asperity_pressure: np.ndarray
    slope: np.ndarray
    by_pressure: np.ndarray
    by_gap: np.ndarray


@dataclass(frozen=True)
class GreenwoodTripp:
    """Greenwood & Tripp's asperity pressure P_a(H) = K F_{5/2}(H/sigma) (module docstring):
    ``roughness`` sigma (by x0) and ``stiffness`` K (by mu V0 a / x0^2), both > 0."""

    roughness: float
    stiffness: float

    def __post_init__(self):
        checks.positive("roughness", self.roughness)
        checks.positive("stiffness", self.stiffness)

    def pressure(self, h) -> np.ndarray:
        """P_a = K F_{5/2}(H/sigma) (by mu V0 a / x0^2)."""
        return self.stiffness * gaussian_integral(2.5, np.asarray(h) / self.roughness)

    def slope(self, h) -> np.ndarray:
        """dP_a/dH = -(5/2) (K/sigma) F_{3/2}(H/sigma) (<= 0)."""
        t = np.asarray(h) / self.roughness
        return -2.5 * self.stiffness / self.roughness * gaussian_integral(1.5, t)

    def energy(self, h) -> np.ndarray:
        """The energy stored per area, int_H^inf P_a dH = (2/7) K sigma F_{7/2}(H/sigma)
        (by mu V0 a / x0^2 times x0)."""
        t = np.asarray(h) / self.roughness
        return 2.0 / 7.0 * self.stiffness * self.roughness * gaussian_integral(3.5, t)

    def thickness(self, base, compliance) -> np.ndarray:
        """H solving H = base + C P_a(H) (by x0), ``base`` = X + S(R) + C P the thickness
        without the asperities' load, ``compliance`` C: Newton, on the nodes within REACH
        sigma (P_a is 0 beyond). Raises FilmError if it does not converge (the time step is
        then retried shorter)."""
        h = np.array(base, dtype=float)
        reach = np.abs(compliance).max(axis=0)
        for _ in range(50):
            loaded = np.flatnonzero(h < REACH * self.roughness)
            if loaded.size == 0:
                return h
            residual = h - base - compliance[:, loaded] @ self.pressure(h[loaded])
            d = self.slope(h)
            step = self._correction(residual, _stiff(d, reach), d, compliance)
            h = h - step
            if np.abs(step).max() <= NEWTON_TOL * max(np.abs(h).max(), 1.0):
                return h
        raise FilmError("the asperities' load on the solids did not converge")

    @staticmethod
    def _correction(residual, active, d, compliance):
        """Newton's step (I - C D)^-1 r with D = diag(dP_a/dH) on the ``active`` nodes (its
        entries elsewhere, below STIFF, left out): (I - C_AA D_A) d_A = r_A, then
        d = r + C_{:,A} D_A d_A."""
        if active.size == 0:
            return residual
        d = d[active]
        local = np.eye(active.size) - compliance[np.ix_(active, active)] * d
        step_active = np.linalg.solve(local, residual[active])
        return residual + compliance[:, active] @ (d * step_active)

    def loaded(self, h, compliance) -> LoadedThickness:
        """The loaded thickness ``h`` (from :meth:`thickness`) with its sensitivities:
        dH/dP = (I - C D)^-1 C = C + C_{:,A} D_A (I - C_AA D_A)^-1 C_{A,:} and
        dH/dX = 1 + C_{:,A} D_A (I - C_AA D_A)^-1 1 (Woodbury, D = diag(dP_a/dH) on the nodes A
        whose stiffness exceeds STIFF)."""
        load, d = self.pressure(h), self.slope(h)
        active = _stiff(d, np.abs(compliance).max(axis=0))
        by_pressure, by_gap = compliance, np.ones(len(h))
        if active.size:
            local = np.eye(active.size) - compliance[np.ix_(active, active)] * d[active]
            rhs = np.column_stack([compliance[active], np.ones(active.size)])
            solved = np.linalg.solve(local, rhs)
            spread = compliance[:, active] * d[active]
            by_pressure = compliance + spread @ solved[:, :-1]
            by_gap = by_gap + spread @ solved[:, -1]
        return LoadedThickness(h, load, d, by_pressure, by_gap)


def _stiff(slope, reach) -> np.ndarray:
    """The nodes whose asperity stiffness |dP_a/dH| times their largest compliance ``reach``
    exceeds STIFF: those whose load moves the film by a part of its change."""
    return np.flatnonzero(np.abs(slope) * reach > STIFF)


class AsperityModel(Protocol):
    """An asperity model of the surfaces as an input (scaled): ``name``; ``roughness`` sigma
    (by x0, 0: smooth) and ``friction_coefficient`` of the solid contact; ``pressure_law(eps,
    delta)``, the asperities' pressure law for the film (None: no pressure); ``touch()``, the
    thinnest film (by x0) at which the approach ends in a solid collision (None: none). The
    physical inputs reach a model through :meth:`ehdfem.settings.Registry.of_inputs` (the
    roughness by x0 and the pure numbers), which refuses another model's constants given
    with it."""

    name: ClassVar[str]
    roughness: float
    friction_coefficient: float

    def pressure_law(self, eps: float, delta: float) -> GreenwoodTripp | None: ...
    def touch(self) -> float | None: ...


MODELS = Registry("asperities", AsperityModel)  # the asperity models by name

ROUGHNESS = {
    "help": "combined rms roughness sqrt(s1^2 + s2^2) of the surfaces (0: smooth)",
    "unit": "by x0",
    "lower": 0.0,
    "upper": 1.0,
    "upper_open": True,
}
FRICTION = {
    "help": "Coulomb friction coefficient of the solid (asperity) contact, tangential over "
    "normal load (0: none)",
    "lower": 0.0,
}
TANGENTIAL_COMPLIANCE = {
    "help": "tangential over normal stiffness k_t/k_n = 4 G*/E* of the solid impact's Hertz "
    "contact (Mindlin; 2 (1-nu)/(2-nu) for identical solids, 0.824 at nu = 0.3), in "
    "[2/3, 4/3]: stick, partial slip and the slip's reversal (Maw, Barber & Fawcett); "
    "0: the rigid-body Coulomb impact",
    "lower": 0.0,
    "upper": 4 / 3,
}


def _check_solid_contact(model) -> None:
    """Refuse a friction coefficient > 0 on smooth surfaces (roughness 0), where it never acts."""
    if model.roughness == 0.0 and model.friction_coefficient > 0.0:
        raise checks.InputError(
            f"friction_coefficient = {model.friction_coefficient!r} needs roughness > 0: "
            "smooth surfaces never touch through the film, so Coulomb friction never acts",
            "friction_coefficient",
        )


@MODELS.register
@dataclass(frozen=True)
class ImpactAsperities:
    """The asperities collide when the thinnest film reaches sigma (a solid impact with e_dry,
    :mod:`ehdfem.motion.normal`); no asperity pressure before. The default, smooth with
    roughness 0."""

    name: ClassVar[str] = "impact"
    roughness: float = setting(0.0, **ROUGHNESS)
    friction_coefficient: float = setting(0.0, **FRICTION)
    tangential_compliance: float = setting(0.0, **TANGENTIAL_COMPLIANCE)

    def __post_init__(self):
        validate(self)
        _check_solid_contact(self)
        self._check_tangential_compliance()

    def _check_tangential_compliance(self) -> None:
        """Refuse a tangential compliance that cannot act: outside Mindlin's range [2/3, 4/3]
        (2 (1 - nu)/(2 - nu) over nu in (-1, 1/2], and the weighted means of two solids'),
        without friction (mu = 0) or on smooth surfaces (no solid contact); the impact's
        obliquity is checked by :class:`ehdfem.inputs.scales.CollisionParameters`."""
        compliance = self.tangential_compliance
        if compliance == 0.0:
            return
        if compliance < 2.0 / 3.0:
            raise checks.InputError(
                f"tangential_compliance = {compliance!r} must be 0 (rigid) or in [2/3, 4/3]: "
                "k_t/k_n = 4 G*/E* of a Hertz contact lies there for Poisson ratios in (-1, 1/2]",
                "tangential_compliance",
            )
        if self.friction_coefficient == 0.0 or self.roughness == 0.0:
            raise checks.InputError(
                f"tangential_compliance = {compliance!r} needs a solid contact with friction "
                "(roughness > 0, friction_coefficient > 0): without them no tangential load "
                "acts on the contact",
                "tangential_compliance",
            )

    def pressure_law(self, eps: float, delta: float) -> None:
        """None: the impact model puts no pressure on the film."""
        return None

    def touch(self) -> float | None:
        """sigma (by x0), None for smooth surfaces."""
        return self.roughness if self.roughness > 0.0 else None


@MODELS.register
@dataclass(frozen=True)
class GreenwoodTrippAsperities:
    """Mixed lubrication: Greenwood & Tripp's asperity pressure shares the load with the film
    (module docstring), with eta beta sigma and sigma/beta; needs roughness > 0."""

    name: ClassVar[str] = "greenwood-tripp"
    roughness: float = setting(0.0, **ROUGHNESS)
    friction_coefficient: float = setting(0.0, **FRICTION)
    asperity_density: float = setting(
        ASPERITY_DENSITY,
        help="asperity density x tip radius x roughness, eta beta sigma",
        lower=0.0,
        lower_open=True,
    )
    asperity_slope: float = setting(
        ASPERITY_SLOPE,
        help="roughness over asperity tip radius, sigma / beta",
        lower=0.0,
        upper=1.0,
        lower_open=True,
        upper_open=True,
    )

    def __post_init__(self):
        validate(self)
        if self.roughness == 0.0:
            raise checks.InputError(
                f"asperities = {self.name!r} needs roughness > 0 (sphere_roughness or "
                "wall_roughness): smooth surfaces have no asperities",
                "asperities",
            )

    def pressure_law(self, eps: float, delta: float) -> GreenwoodTripp:
        """P_a(H) = K F_{5/2}(H/sigma) with K of eta beta sigma, sigma/beta, eps and delta."""
        k = stiffness(self.asperity_density, self.asperity_slope, eps, delta)
        return GreenwoodTripp(self.roughness, k)

    def touch(self) -> None:
        """None: the asperities' pressure carries the load, no solid impact."""
        return None
