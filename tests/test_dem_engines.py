"""The real DEM engines (Yade, LIGGGHTS; installed by the set-up, so a missing engine fails)
run on small collisions: a known limit of each law reproduced by the engine, and the rebound
read back beside the full model within the error the study states (docs/validation.md,
"DEM engines"). Each run takes about a second."""

import json
import math
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from ehdfem import CollisionParameters, collide, from_presets
from ehdfem.cli.main import main
from ehdfem.config import RunConfig
from ehdfem.dem.engines import liggghts, yade
from ehdfem.dem.engines.compare import compare, engine_law
from ehdfem.dem.engines.rebound import read_rebound, run_binary
from ehdfem.inputs.presets import Liquid

pytestmark = pytest.mark.serial  # the engines are serial binaries: nothing to check on 2 ranks
MU = 96.5e-3  # Pa s, silicone_oil_100cst


def small(**values):
    """A steel sphere of 2 mm through 0.1 mm of 100 cSt silicone oil at 0.5 m/s."""
    inputs = dict(sphere="steel", wall="steel", liquid="silicone_oil_100cst", radius=2e-3,
                  speed=0.5, layer_thickness=1e-4)  # fmt: skip
    return from_presets(**(inputs | values))


@pytest.mark.slow
def test_yade_without_liquid_restitutes_its_contact_spring(tmp_path):
    """eta -> 0 (1e-9 Pa s): the asperities' spring keps kn in series with kn, undamped, gives
    e_n = 1 and the time in the layer 2 (x0 - 2 eps a) / V0 + pi sqrt(m / k) with
    k = kn keps kn / (kn + keps kn) (exact). Tolerances: e_n to 1e-4 (the vanishing viscous
    loss); the time to one recorded interval (20 steps), the history's resolution."""
    collision = small(wall="glass")
    law = yade.YadeLaw(yade_roughness=1e-2)
    inputs = yade.script_inputs(collision, law) | {"eta": 1e-9}
    (tmp_path / "collision.py").write_text(yade.script(inputs))
    run_binary(["yade", "-n", "-x", "collision.py"], tmp_path, "yade.log")
    rebound = read_rebound("yade", tmp_path, "collision.py", "yade.log")
    kn = yade.contact_stiffness(collision, law)
    spring = kn * law.yade_keps * kn / (kn + law.yade_keps * kn)
    approach = collision.layer_thickness - 2 * law.yade_roughness * collision.radius
    expected = 2 * approach / collision.speed + math.pi * math.sqrt(collision.mass / spring)
    assert rebound.rebounded
    assert rebound.e_n == pytest.approx(1.0, abs=1e-4)
    assert rebound.time_in_layer == pytest.approx(expected, abs=20 * inputs["time_step"])


@pytest.mark.slow
def test_yade_wall_force_is_the_rigid_lubrication_force(tmp_path):
    """Far from contact the spring is rigid and Yade's force with eta = 4 mu is the exact wall
    force 6 pi mu a^2 v / h (with eta = mu a quarter of it: Yade's wall is a sphere of radius
    a). Tolerance 1e-3: the force and the recorded gap and velocity are a step apart
    (dt V0 / h < 1e-4) and the spring's deflection F / kn is 1e-6 of the gap."""
    collision = small()
    for factor in (4.0, 1.0):
        folder = tmp_path / str(factor)
        yade.run(collision, yade.YadeLaw(yade_viscosity_factor=factor), folder)
        rows = np.loadtxt(folder / "history.csv", delimiter=",", skiprows=1)
        approach = rows[1:40]  # the first recorded intervals, h from x0 to 0.9 x0
        exact = 6 * math.pi * MU * collision.radius**2 * -approach[:, 2] / approach[:, 1]
        assert approach[:, 5] * 4.0 / factor == pytest.approx(exact, rel=1e-3)


def test_liggghts_bridge_force_is_the_rigid_lubrication_force(tmp_path):
    """After contact, while the bridge holds, LIGGGHTS's viscous force on two separating
    spheres is 6 pi mu R*^2 v / h, R* = R / 2 (exact for rigid spheres), down to the gap
    minSeparationDistanceRatio R*; beyond the cut-off (the layer x0 by default) it is zero.
    Tolerance 1e-2: force and recorded gap are a step apart (dt v / h < 5e-3 at h > x0 / 10)."""
    collision = small()
    liggghts.run(collision, liggghts.LiggghtsLaw(), tmp_path)
    rows = np.loadtxt(tmp_path / "history.txt", skiprows=1)
    time, gap, velocity, force = rows.T[:4]
    after = time > time[np.argmax(gap < 0)]
    bridge = after & (gap > 0.1e-4) & (gap < 0.9e-4)
    exact = 6 * math.pi * MU * (collision.radius / 2) ** 2 * velocity[bridge] / gap[bridge]
    assert bridge.sum() > 10
    assert force[bridge] == pytest.approx(exact, rel=1e-2)
    assert np.all(force[after & (gap > 1.01e-4)] == 0.0)


@pytest.mark.slow
def test_dem_command_prints_the_engine_beside_the_full_model(tmp_path, capsys):
    """``ehdfem dem`` leaves the engine's files in --folder and its JSON holds both rebounds."""
    folder, out = tmp_path / "yade", tmp_path / "dem.json"
    args = ["dem", "--engine", "yade", "--folder", str(folder), "--sphere", "steel", "--wall",
            "glass", "--liquid", "silicone_oil_100cst", "--radius", "2e-3", "--speed", "1",
            "--layer-thickness", "1e-4", "--angle", "20", "--json", str(out)]  # fmt: skip
    assert main(args) == 0
    report = capsys.readouterr().out
    assert "yade beside ehdfem's half-space model" in report
    assert "collision.py, history.csv, rebound.json" in report  # every file the run wrote
    result = json.loads(out.read_text())
    assert result["provenance"]["command"][:4] == ["ehdfem", "dem", "--engine", "yade"]
    assert result["inputs"]["physical"]["radius"] == 2e-3
    assert {p.name for p in folder.iterdir()} >= {"collision.py", "history.csv", "rebound.json"}
    assert result["engine"]["e_t"] is not None and result["full_model"]["e_t"] is not None


def test_the_roughness_sets_each_engine_unless_given():
    """On rough surfaces (sigma = 4 um on a 2 mm sphere) the engine's asperity setting is the
    roughness: Yade's eps = sigma / (2 a) = 1e-3 and LIGGGHTS's minimum gap ratio 3 sigma / R*
    = 1.2e-2 (R* = 1 mm), exact up to rounding; a value given stays; smooth: the defaults."""
    rough = small(sphere_roughness=3.2e-6, wall_roughness=2.4e-6)  # sigma = 4 um
    assert engine_law("yade", rough, {}).yade_roughness == pytest.approx(1e-3, rel=1e-12)
    law = engine_law("liggghts", rough, {})
    assert law.liggghts_min_separation == pytest.approx(1.2e-2, rel=1e-12)
    assert engine_law("yade", rough, {"yade_roughness": 0.02}).yade_roughness == 0.02
    assert engine_law("yade", small(), {}) == yade.YadeLaw()
    assert engine_law("liggghts", small(), {}) == liggghts.LiggghtsLaw()


def test_dem_command_passes_the_roughness_to_the_engine_and_the_full_model(tmp_path):
    """``--sphere-roughness`` [m] reaches the engine's script (Yade's eps) and the full model
    (sigma / x0); ``--friction-coefficient`` mu reaches Yade as the friction angle atan(mu)."""
    out = tmp_path / "dem.json"
    args = ["dem", "--engine", "yade", "--folder", str(tmp_path / "yade"), "--sphere", "steel",
            "--wall", "glass", "--liquid", "silicone_oil_100cst", "--radius", "2e-3", "--speed",
            "1", "--layer-thickness", "1e-4", "--sphere-roughness", "8e-6",
            "--friction-coefficient", "0.5", "--json", str(out)]  # fmt: skip
    assert main(args) == 0
    result = json.loads(out.read_text())
    assert result["law"]["yade_roughness"] == pytest.approx(2e-3, rel=1e-12)
    assert result["full_model"]["roughness"] == pytest.approx(0.08, rel=1e-12)
    script = (tmp_path / "yade" / "collision.py").read_text()
    assert '"eps": 0.002' in script
    assert f'"friction_angle": {math.atan(0.5)!r}' in script


@pytest.mark.parametrize(
    "extra, flag",
    [
        (["--engine", "liggghts", "--wall", "glass"], "--wall"),  # two equal spheres only
        (["--engine", "liggghts", "--wall", "steel", "--yade-keps", "2"], "--yade-keps"),
        (["--engine", "yade", "--wall", "steel", "--yade-roughness", "0.5"], "--yade-roughness"),
        (["--engine", "yade", "--wall", "steel", "--e-dry", "0.9"], "--e-dry"),
        (["--engine", "liggghts", "--wall", "steel", "--gravity", "9.81"], "--gravity"),
    ],
)
def test_dem_command_refuses_bad_input(tmp_path, capsys, extra, flag):
    args = ["dem", "--folder", str(tmp_path), "--sphere", "steel", "--liquid", "water",
            "--radius", "2e-3", "--speed", "1", "--layer-thickness", "1e-4", *extra]  # fmt: skip
    assert main(args) == 2
    assert f"error: {flag}:" in capsys.readouterr().err


def test_each_engine_runs_its_example(tmp_path, capsys):
    """``dem --example`` with either engine, obliquely (the example is steel on glass at 30
    degrees): LIGGGHTS's two equal spheres take the example's sphere material for the wall
    unless the user gives another, which is refused."""
    for engine in ("liggghts", "yade"):
        folder = tmp_path / engine
        assert main(["dem", "--engine", engine, "--example", "--folder", str(folder)]) == 0
        out = capsys.readouterr().out
        assert "beside ehdfem's half-space model" in out and "e_t" in out
    args = ["dem", "--engine", "liggghts", "--example", "--folder", str(tmp_path / "conflict"),
            "--wall", "glass"]  # fmt: skip
    assert main(args) == 2
    err = capsys.readouterr().err
    assert err.startswith("ehdfem dem: error: --wall:") and "two equal spheres" in err


def test_liggghts_oblique_sliding_contact_is_the_rigid_body_law(tmp_path):
    """Two equal steel spheres at 60 degrees through a layer of a liquid of 1e-9 Pa s (no
    liquid force) with Coulomb friction mu = 0.1 slide throughout the contact
    (mu (1 + e_n)(1 + 1/k) = 0.66 < tan 60), so the tangential impulse is mu times the normal
    one: e_t = 1 - mu (1 + e_n) / tan(angle) and each sphere's spin change is (1 - e_t)/(2 k),
    k = 2/5 (rigid-body impact of two spheres, the pair's inertia factor k). Measured 1.1e-4
    and 5e-5 off (relative): the line of centres turns by x0 tan(angle) / R = 1.7e-3 while the
    contact lasts; tested at 3e-4 and 2e-4."""
    thin_liquid = Liquid("inviscid", 1e-9, 1000.0, 2000.0)
    collision = from_presets(
        sphere="steel", wall="steel", liquid=thin_liquid, radius=2e-3, speed=0.5,
        layer_thickness=2e-6, angle=60.0, friction_coefficient=0.1, e_dry=0.9,
        sphere_roughness=1e-7,
    )  # fmt: skip
    rebound = liggghts.run(collision, engine_law("liggghts", collision, {}), tmp_path)
    rigid = 1.0 - 0.1 * (1.0 + rebound.e_n) / math.tan(math.radians(60.0))
    assert rebound.e_n == pytest.approx(0.9, abs=1e-3)  # the Hertz contact's coefficient
    assert rebound.e_t == pytest.approx(rigid, abs=3e-4)
    assert rebound.spin_change == pytest.approx((1.0 - rebound.e_t) / 0.8, rel=2e-4)


def test_liggghts_oblique_full_model_is_the_equal_pair(tmp_path):
    """Obliquely, LIGGGHTS's full-model counterpart (the reduced radius and mass, sphere 1's
    spin rate doubled, half the spin change) is the two-sphere collision of equal spheres
    (``lower = sphere``) at the same groups: e_n, e_t and sphere 1's spin change to 1e-12."""
    collision = small(angle=30.0, spin=50.0)
    result = compare("liggghts", collision, liggghts.LiggghtsLaw(), tmp_path)
    full = result["full_model"]
    params = CollisionParameters.from_settings(**result["inputs"]["parameters"])
    pair = collide(params, lower="sphere", radius_ratio=1.0, density_ratio=1.0,
                   lower_inertia_factor=0.4)  # fmt: skip
    assert full["e_n"] == pytest.approx(pair.normal.e_n, rel=1e-12)
    assert full["e_t"] == pytest.approx(pair.tangential.e_t, rel=1e-12)
    assert full["spin_change"] == pytest.approx(pair.tangential.spin_change, rel=1e-12)
    assert result["engine"]["e_t"] is not None


STUDY = Path(__file__).resolve().parents[1] / "studies/results/dem_engines.json"
CASE = "steel, 100 cSt oil, 0.1 mm"
SPEEDS = (0.15, 0.3, 0.6, 1.2, 2.4)  # m/s, those of studies/dem_engines.py


def stated_error(engine, setting):
    """The largest |e_n(engine) - e_n(full model)| that the study (docs/validation.md, "DEM
    engines") states for ``setting`` on CASE over its speeds."""
    table = json.loads(STUDY.read_text())
    rows = [(table[f"{engine}|{CASE}|{setting}|{v}"], table[f"{engine}|{CASE}|full model|{v}"])
            for v in SPEEDS]  # fmt: skip
    return max(abs(run["e_n"] - full["e_n"]) for run, full in rows)


@pytest.mark.parametrize(
    "engine, setting, law, wall",
    [
        ("yade", "eta = 4 mu, eps = 1e-3", yade.YadeLaw(yade_roughness=1e-3), "glass"),
        ("liggghts", "min 0.001, cut-off at 1 x0", liggghts.LiggghtsLaw(1e-3), "steel"),
    ],
)
def test_engine_rebound_beside_the_full_model(tmp_path, engine, setting, law, wall):
    """The engine's rebound with its best setting, read back, is within the error the study
    states for it (its largest over the case's St) of the full model at the same physical
    inputs (1.2 m/s); 1e-3 more for the run's own spread (time steps move e_n by < 1e-4)."""
    collision = small(wall=wall, speed=1.2)
    result = compare(engine, collision, law, tmp_path)
    assert result["engine"]["rebounded"]
    assert abs(result["e_n_difference"]) <= stated_error(engine, setting) + 1e-3


def stated_rough_error(engine, factor, asperities, sigma=3e-6):
    """The largest |e_n(engine) - e_n(full model by ``asperities``)| that the study states for
    the engine's asperity parameter at ``factor`` times its value of ``sigma`` (docs/validation.md,
    "DEM engines", rough surfaces) over its speeds."""
    table = json.loads(STUDY.read_text())
    key = f"rough|{engine}|{CASE}|{sigma}"
    rows = [(table[f"{key}|x{factor:g}|{v}"], table[f"{key}|full model {asperities}|{v}"])
            for v in SPEEDS]  # fmt: skip
    return max(abs(run["e_n"] - full["e_n"]) for run, full in rows)


@pytest.mark.slow
@pytest.mark.parametrize(
    "engine, wall, factor, asperities",
    [
        ("yade", "glass", 1.0, "greenwood-tripp"),  # eps = sigma / (2 a): mixed lubrication
        ("liggghts", "steel", 3.0, "impact"),  # the smallest gap 3 sigma: the impact model
    ],
)
def test_rough_engine_rebound_beside_the_full_model(tmp_path, engine, wall, factor, asperities):
    """On a rough sphere (sigma = 3 um, sigma / x0 = 0.03) at 1.2 m/s, the engine with the
    asperity parameter that ``ehdfem dem`` sets from the roughness is within the error the study
    states for it of the full model by the asperity model it stands for; 1e-3 more for the
    run's own spread (time steps move e_n by < 1e-4)."""
    collision = small(wall=wall, speed=1.2, sphere_roughness=3e-6, asperities=asperities)
    law = engine_law(engine, collision, {})
    result = compare(engine, collision, law, tmp_path, RunConfig())
    assert result["engine"]["rebounded"]
    assert result["full_model"]["roughness"] == pytest.approx(0.03, rel=1e-12)
    limit = stated_rough_error(engine, factor, asperities)
    assert abs(result["e_n_difference"]) <= limit + 1e-3


def test_a_missing_engine_is_named_with_the_set_up(tmp_path, monkeypatch):
    monkeypatch.setenv("PATH", str(tmp_path))
    with pytest.raises(OSError, match="yade is not installed.*make.sh setup"):
        run_binary(["yade", "-n", "-x", "collision.py"], tmp_path, "yade.log")
    with pytest.raises(OSError, match="yade is not installed.*make.sh setup"):
        yade.run(small(), yade.YadeLaw(), tmp_path)


AUDIT_HOOK = """
import os, sys

def _record(event, args):  # every process of the run: its imports of Yade and its binds
    if event == "import" and args[0] == "yade" or event == "socket.bind":
        with open(os.environ["EHDFEM_TEST_AUDIT"], "a") as log:
            log.write(f"{os.getpid()} {event} {args[0] if event == 'import' else args[1]}\\n")

sys.addaudithook(_record)
"""


def test_yade_runs_without_opening_a_port(tmp_path):
    """``ehdfem dem --engine yade`` run as a user runs it: no process of the run binds a socket
    (Yade's launcher opens a Python console on TCP port 9000 and an info server on 21000, on
    every interface). Each Python process of the run, Yade's included, logs its binds through
    an audit hook; the log must show that Yade was imported, so the hook did watch it."""
    (tmp_path / "hook").mkdir()
    (tmp_path / "hook" / "sitecustomize.py").write_text(AUDIT_HOOK)
    log = tmp_path / "audit.log"
    env = os.environ | {"PYTHONPATH": str(tmp_path / "hook"), "EHDFEM_TEST_AUDIT": str(log)}
    command = [str(Path(sys.executable).parent / "ehdfem"), "dem", "--engine", "yade",
               "--example", "--folder", str(tmp_path / "yade")]  # fmt: skip
    done = subprocess.run(command, env=env, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    assert "(rerun there: python3 collision.py)" in done.stdout
    events = log.read_text().splitlines()
    assert any(line.split()[1] == "import" for line in events)  # Yade ran under the hook
    assert [line for line in events if "socket.bind" in line] == []
