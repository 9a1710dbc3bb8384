"""A new undeformed gap declared in this file alone, registered from here, and run through
``collide``, a command-line flag, a study key and a ``collide --from`` round trip: the gap is
a component like the liquid's laws (docs/architecture.md, "Inputs of the physics and
numerics"), and nothing else in ehdfem is edited for it.

The gap: a sphere of radius rho a (rho <= 1) in the paraboloid approximation, S = R^2 / (2 rho)
(R by sqrt(a x0)). Its rigid film is the paraboloid's with R scaled by sqrt(rho): with
R = sqrt(rho) R', d/dR = rho^(-1/2) d/dR', so the Reynolds film dX/dT = (1/(12R)) d/dR(R H^3
dP/dR) with H = X + R'^2/2 gives P(R) = rho P_parab(R'), and the force (1/3) int P R dR =
rho^2 F_parab. A rigid sphere of Stokes number St then stops where the paraboloid's of Stokes
number St / rho^2 does (:func:`ehdfem.exact.rigid_film.stopping_gap`)."""

import json
import math
from dataclasses import dataclass
from typing import ClassVar

import pytest
from small_collision import COMMAND, RUN, SMALL, collide_small

from ehdfem.cli.main import main
from ehdfem.config import read_inputs
from ehdfem.exact import rigid_film
from ehdfem.film import gap
from ehdfem.film.grid import radial_grid
from ehdfem.inputs.scales import CollisionParameters
from ehdfem.motion.normal import solve_normal
from ehdfem.motion.timestepping import IntegratorOptions
from ehdfem.settings import setting, validate
from ehdfem.solids.compliance import RigidSolids
from ehdfem.study.sweep import Study, run_study

pytestmark = pytest.mark.serial

SHARPER = "sharper-sphere-test"


class SharperParaboloid(gap.Paraboloid):
    """S = R^2 / (2 rho): the paraboloid of a sphere of radius rho a (module docstring)."""

    name = SHARPER

    def __init__(self, ratio: float):
        self.ratio = ratio

    def height(self, radius):
        return super().height(radius) / self.ratio

    def profile(self, radius):
        height, slope = super().profile(radius)
        return height / self.ratio, slope / self.ratio

    def between_nodes(self, left, length, xi):
        return super().between_nodes(left, length, xi) / self.ratio

    def slope_between_nodes(self, left, length, xi):
        return super().slope_between_nodes(left, length, xi) / self.ratio


@dataclass(frozen=True)
class SharperSphereGap:
    """The gap of a sphere of radius rho a, the paraboloid's approximation (thin layer)."""

    name: ClassVar[str] = SHARPER
    thin_layer_only: ClassVar[bool] = True
    gap_radius_ratio: float = setting(
        1.0, help="the sphere's radius over a", lower=0.0, upper=1.0, lower_open=True
    )

    def __post_init__(self):
        validate(self)

    def shape(self, delta: float, surface_radii=(1.0, math.inf)) -> SharperParaboloid:
        return SharperParaboloid(self.gap_radius_ratio)


@pytest.fixture(scope="module", autouse=True)
def registered():
    """The gap registered for this file's tests, and removed after them."""
    gap.GAPS.register(SharperSphereGap)
    yield
    gap.GAPS.unregister(SHARPER)


@pytest.mark.slow
def test_the_new_gap_stops_a_rigid_sphere_at_the_scaled_exact_gap():
    """rho = 1/2, St = 1: the rigid sphere stops at the paraboloid's stopping gap of St = 4
    (module docstring) to 1e-3 (measured 2.0e-4 on 200 nodes, the film's force resolution),
    far from the paraboloid's own stop at St = 1 (0.0997 against 0.00412)."""
    ratio, St = 0.5, 1.0
    stop = rigid_film.stopping_gap(St / ratio**2, "thin")
    params = CollisionParameters(St=St, eps=1.0, gap=SharperSphereGap(ratio))
    radii = radial_grid(200, math.sqrt(ratio * stop), 1.05 * math.sqrt(2.0))
    result = solve_normal(params, RigidSolids(radii), IntegratorOptions(rtol=1e-5))
    assert result.status == "stick" and result.gap.name == SHARPER
    assert result.history.gap[-1] == pytest.approx(stop, rel=1e-3)
    assert stop < 0.1 * rigid_film.stopping_gap(St, "thin")


def test_the_new_gap_at_ratio_one_is_the_paraboloid_bit_for_bit():
    """rho = 1 is the paraboloid: every height and slope divided by 1.0, the same numbers."""
    sharper = collide_small(gap=SHARPER, gap_radius_ratio=1.0)
    paraboloid = collide_small(gap="paraboloid")
    assert sharper.normal.e_n == paraboloid.normal.e_n
    assert sharper.tangential.e_t == paraboloid.tangential.e_t


def test_the_new_gap_refuses_an_immersed_layer():
    """Its ``thin_layer_only`` is asked by the inputs' check, not its name."""
    with pytest.raises(Exception, match=f"gap = '{SHARPER}' needs layer = 'thin'"):
        CollisionParameters.from_settings(**SMALL, layer="immersed", gap=SHARPER)


@pytest.mark.slow
def test_flag_and_from_round_trip(tmp_path):
    """`ehdfem collide --gap NAME --gap-radius-ratio X` gives the Python call's results bit for
    bit, its JSON names the gap and its constant, and `collide --from` runs it again bit for
    bit."""
    first, again = tmp_path / "first.json", tmp_path / "again.json"
    flags = ["--gap", SHARPER, "--gap-radius-ratio", "0.7"]
    command = [*COMMAND, *flags, *RUN]
    assert main([*command, "--json", str(first)]) == 0
    written = json.loads(first.read_text())
    direct = collide_small(gap=SHARPER, gap_radius_ratio=0.7)
    assert written["e_n"] == direct.normal.e_n and written["e_t"] == direct.tangential.e_t
    assert written["gap"] == SHARPER
    parameters = written["inputs"]["parameters"]
    assert parameters["gap"] == SHARPER and parameters["gap_radius_ratio"] == 0.7
    assert read_inputs(written["inputs"])[0] == direct.params
    assert main(["collide", "--from", str(first), "--json", str(again)]) == 0
    replayed = json.loads(again.read_text())
    assert replayed["e_n"] == written["e_n"] and replayed["inputs"] == written["inputs"]


def test_help_lists_the_new_gap(capsys):
    """`ehdfem collide --help` offers the new gap and its constant's option."""
    with pytest.raises(SystemExit):
        main(["collide", "--help"])
    text = capsys.readouterr().out
    assert SHARPER in text and "--gap-radius-ratio" in text


@pytest.mark.slow
def test_study_keys(tmp_path):
    """A sweep over the new gap's constant: each row's e_n is the Python call's, bit for bit;
    the sharper sphere (rho = 1/2: the film force rho^2 times the paraboloid's, an effective
    Stokes number St / rho^2) rebounds (e_n 0.46) where the paraboloid's sticks."""
    study_file = tmp_path / "new.toml"
    study_file.write_text(
        "[grid]\nSt = [4.0]\neps = [1e-3]\nangle = [30.0]\n"
        f'gap = ["{SHARPER}"]\ngap_radius_ratio = [0.5, 1.0]\n'
        '[numerics]\nnodes = 60\n[output]\ntable = "out/new.csv"\n'
    )
    rows = run_study(Study(study_file), None, progress=None)
    assert len(rows) == 2
    for row in rows:
        direct = collide_small(gap=SHARPER, gap_radius_ratio=row["gap_radius_ratio"])
        assert row["e_n"] == direct.normal.e_n and row["status"].startswith("ok")
    by_ratio = {row["gap_radius_ratio"]: row["e_n"] for row in rows}
    assert by_ratio[0.5] > 0.3 and by_ratio[1.0] == 0.0
