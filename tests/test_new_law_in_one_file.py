"""A new viscosity law and a new cavitation model declared in this file alone, registered from
here, and run through every entry: ``collide`` (Python), a command-line flag (``ehdfem collide``
in process), a study key (a sweep) and a ``collide --from`` round trip. Nothing else in ehdfem
is edited for them (docs/architecture.md, "A viscosity law or a cavitation model").

The law is checked against the exact rigid squeeze film, the model against the complementarity
it imposes; the entries against the Python call, bit for bit."""

import json
import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
import pytest
from scipy.integrate import quad
from small_collision import COMMAND, RUN, collide_small

from ehdfem.cli.main import main
from ehdfem.config import read_inputs
from ehdfem.film import cavitation, viscosity
from ehdfem.film.cavitation import NO_LIMIT, Truncation, Unlimited
from ehdfem.film.grid import radial_grid
from ehdfem.inputs.scales import CollisionParameters
from ehdfem.motion.normal import solve_normal
from ehdfem.motion.timestepping import IntegratorOptions
from ehdfem.settings import setting, validate
from ehdfem.solids.compliance import RigidSolids
from ehdfem.study.sweep import Study, run_study

pytestmark = pytest.mark.serial

LINEAR = "linear-test"
SUCTION = "suction-test"


@dataclass(frozen=True)
class LinearViscosity:
    """mu / mu0 = 1 + beta P at the compressive pressure P = max(P, 0) (scaled by the pressure
    scale mu0 V0 a / x0^2); beta by the inverse pressure scale."""

    name: ClassVar[str] = LINEAR
    pressure_dependent: ClassVar[bool] = True
    beta: float = setting(
        0.0, help="thickening slope d(mu/mu0)/dP", unit="by x0^2 / (mu V0 a)", lower=0.0
    )

    def __post_init__(self):
        validate(self)

    @property
    def constant(self) -> bool:
        return self.beta == 0.0

    def log_ratio(self, compressive):
        return np.log1p(self.beta * compressive)

    def ratio(self, pressure):
        pressure = np.asarray(pressure, dtype=float)
        compressive = np.maximum(pressure, 0.0)
        slope = np.where(pressure > 0.0, self.beta / (1.0 + self.beta * compressive), 0.0)
        return 1.0 + self.beta * compressive, slope

    def fluidity_integral(self, lower, upper):
        """int_lower^upper dP / (1 + beta P) = ln(1 + beta (upper - lower) / (1 + beta lower))
        / beta."""
        lower, upper = np.asarray(lower, dtype=float), np.asarray(upper, dtype=float)
        if self.beta == 0.0:
            return upper - lower
        return np.log1p(self.beta * (upper - lower) / (1.0 + self.beta * lower)) / self.beta

    def overflow(self, pressure) -> str:
        return "the linear viscosity does not overflow"

    def validity_pressure(self, pressure_viscosity, viscosity):
        return math.inf

    @classmethod
    def of_liquid(cls, pressure_viscosity, viscosity, pressure_scale):
        """The same low-pressure slope as Barus's: beta = alpha_SI times the pressure scale."""
        return cls(beta=pressure_viscosity * pressure_scale)


class HeldAtLimit(Unlimited):
    """P >= -S as a plain semismooth-Newton active set: a wet node whose pressure would fall
    below the limit with a non-negative Reynolds residual is held there (no accelerated
    release of a refilling cavity, unlike ehdfem's truncation)."""

    def __init__(self, p_cav):
        self.p_cav = p_cav

    def limit(self, residual, pressure, cavitated, dry, sensitivity):
        scale = sensitivity()
        scale = np.where(scale > 0, scale, 1.0)
        held = (pressure - self.p_cav < residual / scale) & ~dry
        residual[held] = pressure[held] - self.p_cav
        return held


@dataclass(frozen=True)
class LargestSuction:
    """A cavitation model given by the largest suction S = -P_cav >= 0 the liquid holds
    (scaled by mu V0 a / x0^2), the liquid in a cavity not tracked."""

    name: ClassVar[str] = SUCTION
    tracks_liquid: ClassVar[bool] = False
    largest_suction: float = setting(
        help="largest suction the liquid holds, -P_cav", unit="by mu V0 a / x0^2", lower=0.0
    )

    def __post_init__(self):
        validate(self)

    @property
    def p_cav(self) -> float:
        return -self.largest_suction

    def solver(self):
        return HeldAtLimit(self.p_cav)

    @classmethod
    def with_limit(cls, p_cav):
        return cls(largest_suction=-p_cav)


@pytest.fixture(scope="module", autouse=True)
def registered():
    """The two components registered for this file's tests, and removed after them."""
    viscosity.LAWS.register(LinearViscosity)
    cavitation.MODELS.register(LargestSuction)
    yield
    viscosity.LAWS.unregister(LINEAR)
    cavitation.MODELS.unregister(SUCTION)


def exact_linear_force(gap, velocity, beta):
    """Thin-layer rigid sphere: the reduced pressure q = int_0^P mu0/mu dp = ln(1 + beta P) /
    beta obeys the constant-viscosity film, q = -3 V (1/H^2 - 1), so P = (exp(beta q) - 1) /
    beta and F = (1/3) int_X^1 P dH."""

    def pressure(h):
        return math.expm1(beta * -3 * velocity * (1 / h**2 - 1)) / beta

    return quad(pressure, gap, 1.0, limit=200, epsabs=0, epsrel=1e-10)[0] / 3


@pytest.mark.slow
def test_the_new_law_gives_the_exact_rigid_film_force():
    """A rigid sphere (St = 3) through a thin layer of the linear liquid: the film force at each
    step equals the exact quasi-steady force within 3e-3 (the rigid constant-viscosity force
    has the same error on 200 nodes, tests/test_viscosity.py) while beta P reaches about 1
    (the viscosity twice mu0)."""
    beta = 5e-4
    params = CollisionParameters(St=3.0, eps=1.0, viscosity=LinearViscosity(beta=beta))
    radii = radial_grid(200, 0.1, 1.05 * math.sqrt(2))
    hist = solve_normal(params, RigidSolids(radii), IntegratorOptions(rtol=1e-5)).history
    approach = np.flatnonzero(hist.velocity < 0)
    steps = approach[np.linspace(5, len(approach) - 5, 12).astype(int)]
    largest = max(math.expm1(beta * -3 * hist.velocity[i] / hist.gap[i] ** 2) for i in steps)
    assert 0.5 < largest < 1.5
    for i in steps:
        exact = exact_linear_force(hist.gap[i], hist.velocity[i], beta)
        assert hist.force[i] == pytest.approx(exact, rel=3e-3)


@pytest.mark.slow
def test_the_new_model_holds_the_film_at_its_limit():
    """The largest-suction model through collide: no wet node's pressure goes below -S (to
    1e-12 of S), the limit is reached, and the collision agrees with ehdfem's truncation at the
    same P_cav, which solves the same complementarity by another path of Newton iterates, to
    1e-6 in e_n and e_t (measured 1.1e-7 and 8e-11 at the default Newton tolerance, rtol/20 =
    1e-5, through the adaptive steps; 2.2e-9 and 5e-12 at 1e-7); with a limit never reached no
    node is held: the unlimited film, bit for bit."""
    suction = 2.0
    result = collide_small(cavitation=SUCTION, largest_suction=suction)
    pressure = result.normal.history.pressure
    assert pressure.min() >= -suction * (1 + 1e-12)
    assert pressure.min() == pytest.approx(-suction, rel=1e-12)
    truncated = collide_small(p_cav=-suction)
    assert result.normal.e_n == pytest.approx(truncated.normal.e_n, rel=1e-6)
    assert result.tangential.e_t == pytest.approx(truncated.tangential.e_t, rel=1e-6)
    free = collide_small(cavitation=SUCTION, largest_suction=1e6)
    unlimited = collide_small(p_cav=NO_LIMIT)
    assert free.normal.e_n == unlimited.normal.e_n  # no node held: the same film, bit for bit
    assert result.summary()["cavitation"] == SUCTION


def test_the_new_law_at_zero_slope_is_the_constant_viscosity_bit_for_bit():
    """beta = 0 is the constant viscosity: the film takes the law's ``constant`` path."""
    linear = collide_small(viscosity=LINEAR, beta=0.0)
    constant = collide_small()
    assert linear.normal.e_n == constant.normal.e_n
    assert linear.tangential.e_t == constant.tangential.e_t


@pytest.mark.slow
@pytest.mark.parametrize(
    "flags, values",
    [
        (["--viscosity", LINEAR, "--beta", "0.05"], {"viscosity": LINEAR, "beta": 0.05}),
        (
            ["--cavitation", SUCTION, "--largest-suction", "2"],
            {"cavitation": SUCTION, "largest_suction": 2.0},
        ),
    ],
    ids=["viscosity", "cavitation"],
)
def test_flags_and_from_round_trip(flags, values, tmp_path, capsys):
    """`ehdfem collide` with the new component's flags gives the Python call's results bit for
    bit, its JSON names the component and its constant, `collide --from` on that JSON runs it
    again bit for bit, and a constant of the new component with another one is warned of."""
    first, again = tmp_path / "first.json", tmp_path / "again.json"
    command = [*COMMAND, *flags, *RUN]
    assert main([*command, "--json", str(first)]) == 0
    written = json.loads(first.read_text())
    direct = collide_small(**values)
    assert written["e_n"] == direct.normal.e_n and written["e_t"] == direct.tangential.e_t
    assert values.items() <= written["inputs"]["parameters"].items()
    params, _ = read_inputs(written["inputs"])
    assert params == direct.params
    assert main(["collide", "--from", str(first), "--json", str(again)]) == 0
    replayed = json.loads(again.read_text())
    assert replayed["e_n"] == written["e_n"] and replayed["inputs"] == written["inputs"]
    capsys.readouterr()
    role, _, constant, value = flags
    assert main(["collide", "--St", "4", "--eps", "1e-3", constant, value, *RUN]) == 0
    assert f"{constant} has no effect with --{role[2:]}" in capsys.readouterr().err


def test_help_lists_the_new_components(capsys):
    """`ehdfem collide --help` offers the new names and their constants' options."""
    with pytest.raises(SystemExit):
        main(["collide", "--help"])
    text = capsys.readouterr().out
    assert LINEAR in text and SUCTION in text
    assert "--beta" in text and "--largest-suction" in text


@pytest.mark.slow
def test_study_keys(tmp_path):
    """A sweep over the new law's and model's names and constants: each row's e_n is the
    Python call's, bit for bit."""
    study_file = tmp_path / "new.toml"
    study_file.write_text(
        "[grid]\nSt = [4.0]\neps = [1e-3]\nangle = [30.0]\n"
        f'viscosity = ["{LINEAR}"]\nbeta = [0.0, 0.05]\n'
        f'cavitation = ["{SUCTION}"]\nlargest_suction = [2.0]\n'
        '[numerics]\nnodes = 60\n[output]\ntable = "out/new.csv"\n'
    )
    rows = run_study(Study(study_file), None, progress=None)
    assert len(rows) == 2
    for row in rows:
        direct = collide_small(
            viscosity=LINEAR, beta=row["beta"], cavitation=SUCTION, largest_suction=2.0
        )
        assert row["e_n"] == direct.normal.e_n and row["status"].startswith("ok")


def test_registry_refuses_a_component_without_its_members():
    """A class lacking a member of its role's protocol, a taken name, or a field without
    setting metadata is refused at registration."""

    @dataclass(frozen=True)
    class Incomplete:
        name: ClassVar[str] = "incomplete-test"

    with pytest.raises(TypeError, match="lacks"):
        viscosity.LAWS.register(Incomplete)
    with pytest.raises(TypeError, match="new name"):
        cavitation.MODELS.register(Truncation)
    assert "incomplete-test" not in viscosity.LAWS
