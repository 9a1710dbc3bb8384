"""`ehdfem collide`: results, JSON, plots, and refusal of bad inputs before any work; clean
machine-readable output, quiet runs, custom materials and liquids."""

import contextlib
import csv
import json
import os
import platform
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from test_user_cli import interruptible

from ehdfem.checks import InputError
from ehdfem.cli.main import main
from ehdfem.config import RunConfig
from ehdfem.outputs import histories
from ehdfem.version import __version__

pytestmark = pytest.mark.serial

REQUIRED = {
    "rebound",
    "e_n",
    "St",
    "eps",
    "delta",
    "min_film_thickness",
    "max_force",
    "contact_time",
}


@pytest.mark.slow
def test_dimensionless_collision_writes_json_and_plots(tmp_path, capsys):
    out = tmp_path / "r.json"
    code = main(
        [
            "collide",
            "--St",
            "10",
            "--eps",
            "1e-3",
            "--p-cav",
            "-2",
            "--angle",
            "30",
            "--json",
            str(out),
            "--plots",
            str(tmp_path / "plots"),
        ]
    )
    assert code == 0
    result = json.loads(out.read_text())
    assert REQUIRED <= result.keys()
    assert result["rebound"] is True and 0 < result["e_n"] < 1 and 0 < result["e_t"] < 1
    for name in ("histories.png", "profiles.png", "tangential.png"):
        assert (tmp_path / "plots" / name).stat().st_size > 10_000
    assert "e_n" in capsys.readouterr().out


def test_physical_collision_reports_si_values(capsys):
    """The JSON holds the SI values; the report's header names the physical inputs (sphere,
    radius, speed, angle, wall, layer, liquid), not only the scaled groups."""
    code = main(["collide", "--example", "--json", "-"])
    assert code == 0
    captured = capsys.readouterr()
    result = json.loads(captured.out)
    assert result["si"]["contact_time_s"] > 0 and result["St"] > 1
    assert (
        "physical inputs: steel sphere of radius 6.35 mm at 1 m/s, 30 deg from the normal, on "
        "glass through a thin layer of 0.3 mm of silicone_oil_100cst (0.0965 Pa s)"
    ) in captured.err


def test_sliding_film_options_reach_the_collision(capsys):
    """--tangential lubrication with --sliding-deformation: the result names the deformation
    and reports the tangential energy balance."""
    args = ["collide", "--example", "--nodes", "60", "--tangential", "lubrication"]
    assert main([*args, "--sliding-deformation", "full", "--json", "-"]) == 0
    result = json.loads(capsys.readouterr().out)
    assert result["tangential_model"] == "lubrication"
    assert result["sliding_deformation"] == "full"
    assert result["tangential_dissipated"] > 0 and result["tangential_balance_error"] < 2e-2


def test_film_options_reach_the_collision(capsys):
    """--cavitation and --viscosity with a physical alpha arrive scaled in the results:
    alpha = alpha_SI mu V0 a / x0^2 for the example's oil, speed and layer."""
    args = [
        "--example",
        "--speed",
        "0.2",
        "--cavitation",
        "mass-conserving",
        "--viscosity",
        "barus",
    ]
    assert main(["collide", *args, "--pressure-viscosity", "5e-9", "--json", "-"]) == 0
    result = json.loads(capsys.readouterr().out)
    scale = 0.0965 * 0.2 * np.cos(np.radians(30)) * 6.35e-3 / 3e-4**2
    assert result["cavitation"] == "mass-conserving" and result["viscosity"] == "barus"
    assert result["alpha"] == pytest.approx(5e-9 * scale, rel=1e-12)


@pytest.mark.parametrize(
    ("args", "name"),
    [
        (["--St", "0", "--eps", "1e-3"], "St"),
        (["--St=-5", "--eps", "1e-3"], "St"),
        (["--St", "10", "--eps", "0"], "eps"),
        (["--St", "10", "--eps=-1e-3"], "eps"),
        (["--St", "10", "--eps", "1e-3", "--delta", "0"], "delta"),
        (["--St", "10", "--eps", "1e-3", "--angle", "90"], "angle"),
        (["--St", "10", "--eps", "1e-3", "--angle=-1"], "angle"),
        (["--St", "10", "--eps", "1e-3", "--e-dry", "0"], "--e-dry"),
        (["--St", "10", "--eps", "1e-3", "--e-dry", "1.2"], "--e-dry"),
        (["--St", "10", "--eps", "1e-3", "--p-cav", "3"], "--p-cav"),
        (["--St", "nan", "--eps", "1e-3"], "St"),
        (["--example", "--sphere", "unobtainium"], "unobtainium"),
        (["--example", "--liquid", "mercury_tea"], "mercury_tea"),
        (["--St", "10"], "eps"),
        (["--St", "10", "--eps", "1e-3", "--viscosity", "barus", "--alpha=-1"], "alpha"),
        (["--St", "10", "--eps", "1e-3", "--viscosity", "roelands"], "--roelands-pressure"),
        (["--St", "10", "--eps", "1e-3", "--pressure-viscosity", "1e-8"], "--alpha"),
        (["--example", "--alpha", "0.1"], "--pressure-viscosity"),
        (
            ["--example", "--viscosity", "barus", "--pressure-viscosity", "1"],
            "--pressure-viscosity",
        ),
    ],
)
def test_bad_inputs_are_refused_with_the_parameter_named(args, name, capsys):
    assert main(["collide", *args]) == 2
    err = capsys.readouterr().err
    assert name in err and "Traceback" not in err


def test_a_result_outside_the_theorys_range_is_warned_of_and_flagged(capsys):
    """St 1000, eps 0.1, delta 0.1 compresses the sphere by 1.78 radii: one warning line in
    the command's own form, and the flag in the JSON."""
    assert main(["collide", "--St", "1000", "--eps", "0.1", "--delta", "0.1", "--json", "-"]) == 0
    captured = capsys.readouterr()
    warned = [line for line in captured.err.splitlines() if "warning" in line]
    assert len(warned) == 1
    assert warned[0].startswith("ehdfem collide: warning: the half-space theory is outside")
    assert json.loads(captured.out)["halfspace_range_flag"] is True


def test_abbreviated_options_are_refused(capsys):
    """argparse would read --sphere-mod as --sphere-modulus, and in a command without --radius
    read --radius as --radius-ratio: an option is taken only as spelt."""
    with pytest.raises(SystemExit) as exit_info:
        main(["collide", "--example", "--sphere-mod", "1e9"])
    assert exit_info.value.code == 2
    assert "--sphere-mod" in capsys.readouterr().err


def test_field_instants_include_requested_times():
    """Maximum compression, maximum force, the end, and requested times (pressure linear in T
    between steps); a time outside the collision is refused."""
    from ehdfem.collision import collide
    from ehdfem.inputs.scales import CollisionParameters
    from ehdfem.outputs.fields import field_snapshots

    normal = collide(
        CollisionParameters.from_settings(St=10.0, eps=1e-3, p_cav=-2.0),
        RunConfig.from_settings(nodes=60),
    ).normal
    hist = normal.history
    t = 0.5 * (hist.time[10] + hist.time[11])
    snapshots = field_snapshots(normal, [t])
    times = [s[0] for s in snapshots]
    assert times == sorted(times) and t in times and hist.time[-1] in times
    assert (
        hist.time[int(hist.gap.argmin())] in times and hist.time[int(hist.force.argmax())] in times
    )
    pressure = dict(snapshots)[t]
    assert np.allclose(pressure, 0.5 * (hist.pressure[10] + hist.pressure[11]))
    with pytest.raises(InputError, match="field time"):
        field_snapshots(normal, [hist.time[-1] + 1])


def run_ehdfem(*args, env=None, timeout=120):
    """``ehdfem ARGS`` in a fresh process; returns (exit code, stdout, stderr)."""
    done = subprocess.run(
        [sys.executable, "-m", "ehdfem.cli.main", *args],
        capture_output=True,
        text=True,
        timeout=timeout,
        env={**os.environ, **(env or {})},
    )
    return done.returncode, done.stdout, done.stderr


SMALL_COLLISION = ["--St", "10", "--eps", "1e-3", "--p-cav=-2", "--nodes", "40"]


def test_json_to_stdout_is_the_json_alone():
    """`--json -`: standard output parses as JSON as a whole (jq, json.load); the table goes to
    standard error. The JSON records the version and the inputs to run it again."""
    code, out, err = run_ehdfem("collide", *SMALL_COLLISION, "--angle", "30", "--json", "-")
    assert code == 0
    result = json.loads(out)
    assert 0 < result["e_n"] < 1 and "e_n" in err and "{" not in err
    assert result["provenance"]["ehdfem_version"] == __version__
    inputs = result["inputs"]
    assert inputs["parameters"]["St"] == 10 and inputs["parameters"]["angle"] == 30
    assert inputs["parameters"]["p_cav"] == -2 and inputs["physical"] is None
    run = inputs["run"]
    assert (run["model"], run["nodes"], run["tangential"]) == ("halfspace", 40, "couette")


def test_physical_json_records_the_materials_and_the_liquid(capsys):
    assert main(["collide", "--example", "--nodes", "60", "--json", "-"]) == 0
    physical = json.loads(capsys.readouterr().out)["inputs"]["physical"]
    assert physical["sphere"]["young_modulus"] == 190e9 and physical["wall"]["name"] == "glass"
    assert physical["liquid"]["viscosity"] == 0.0965 and physical["radius"] == 6.35e-3


COMPILER_OR_VTK = re.compile(r"INFO:root|gcc|build_ext|X server", re.IGNORECASE)


@pytest.mark.slow
@pytest.mark.parametrize("verbose", [False, True])
def test_fe_collision_is_quiet_unless_verbose(tmp_path, verbose):
    """A default FE collide on an empty JIT cache compiles its forms: no compiler lines on
    standard output or error, unless --verbose. On Debian's stack --verbose shows the compiler's
    build log; the wheel stack's FFCx gives it no handler, so there it shows nowhere and the
    compiled forms in the cache alone prove the compilation (the filter itself:
    tests/test_quiet.py)."""
    cache = tmp_path / "cache"
    env = {"XDG_CACHE_HOME": str(cache), "EHDFEM_MESH_CACHE": str(tmp_path / "meshes")}
    args = ["collide", *SMALL_COLLISION, "--model", "fem", *(["--verbose"] if verbose else [])]
    code, out, err = run_ehdfem(*args, env=env)
    assert code == 0, err
    assert list((cache / "fenics").glob("libffcx_forms_*.c"))  # compiled on this run
    chatter = [line for line in (out + err).splitlines() if COMPILER_OR_VTK.search(line)]
    assert bool(chatter) == (verbose and _compiler_log_has_a_handler()), chatter
    assert "e_n" in out


def _compiler_log_has_a_handler() -> bool:
    """Whether the form compiler's build log reaches standard error at all: Debian's FFCx 0.5
    gives the root logger a handler when imported (``logging.basicConfig()``), FFCx 0.11 leaves
    it without one (the build log then goes nowhere, verbose or not)."""
    code = "import logging, ffcx; print(bool(logging.getLogger().handlers))"
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    return done.stdout.strip() == "True"


@pytest.mark.slow
def test_render_is_quiet(tmp_path):
    """No VTK "bad X server connection" warning (and no compiler lines) from a render; with
    `--json -` its standard output is the JSON alone."""
    env = {"EHDFEM_MESH_CACHE": str(tmp_path / "meshes")}
    out_file = str(tmp_path / "r.png")
    code, out, err = run_ehdfem(
        "render", *SMALL_COLLISION, "--out", out_file, "--json", "-", env=env
    )
    assert code == 0, err
    assert not [line for line in (out + err).splitlines() if COMPILER_OR_VTK.search(line)]
    assert json.loads(out)["model"] == "fem" and "wrote" in err
    assert json.loads(out)["provenance"]["command"][:2] == ["ehdfem", "render"]
    assert (tmp_path / "r.png").stat().st_size > 10_000


EXAMPLE_VALUES = [
    *("--sphere-modulus 190e9 --sphere-poisson 0.27 --sphere-density 7780").split(),
    *("--wall-modulus 60e9 --wall-poisson 0.23 --wall-density 2540").split(),
    *("--liquid-viscosity 0.0965 --liquid-density 965 --vapour-pressure 0").split(),
    *("--pressure-viscosity 1.5e-8 --radius 6.35e-3 --speed 1 --angle 30").split(),
    *("--layer-thickness 3e-4 --nodes 60 --json -").split(),
]
RESULTS = ("St", "eps", "delta", "p_cav", "e_n", "e_t", "max_force", "min_film_thickness", "si")


def collide_json(capsys, *args):
    assert main(["collide", *args]) == 0
    return json.loads(capsys.readouterr().out)


@pytest.mark.slow
def test_custom_materials_and_liquid_equal_their_presets(capsys):
    """The example's steel, glass and 100 cSt silicone oil given as values, or as other
    presets whose values are all changed to those, give the same collision."""
    preset = collide_json(capsys, "--example", "--nodes", "60", "--json", "-")
    custom = collide_json(capsys, *EXAMPLE_VALUES)
    changed = collide_json(
        capsys, "--sphere", "glass", "--wall", "brass", "--liquid", "water", *EXAMPLE_VALUES
    )
    for result in (custom, changed):
        assert {k: result[k] for k in RESULTS} == {k: preset[k] for k in RESULTS}
    assert custom["inputs"]["physical"]["sphere"]["name"] == "custom"
    assert changed["inputs"]["physical"]["wall"]["name"] == "brass (changed)"


def test_one_changed_value_changes_the_collision(capsys):
    """A softer sphere than the preset's: eps grows by theta's ratio."""
    base = collide_json(capsys, "--example", "--nodes", "60", "--json", "-")
    soft = collide_json(
        capsys, "--example", "--sphere-modulus", "19e9", "--nodes", "60", "--json", "-"
    )
    theta = [(1 - 0.27**2) / e + (1 - 0.23**2) / 60e9 for e in (190e9, 19e9)]
    assert soft["eps"] / base["eps"] == pytest.approx(theta[1] / theta[0], rel=1e-12)
    assert soft["St"] == base["St"]


@pytest.mark.parametrize(
    ("args", "name"),
    [
        (["--sphere-poisson", "0.5"], "--sphere-poisson"),
        (["--sphere-poisson=-1"], "--sphere-poisson"),
        (["--wall-modulus=-60e9"], "--wall-modulus"),
        (["--wall-modulus", "3e12"], "--wall-modulus"),
        (["--sphere-density", "0"], "--sphere-density"),
        (["--liquid-viscosity", "0"], "--liquid-viscosity"),
        (["--liquid-density=-1"], "--liquid-density"),
        (["--vapour-pressure=-1"], "--vapour-pressure"),
        (["--vapour-pressure", "2e5"], "--vapour-pressure"),
        (["--liquid-viscosity", "nan"], "--liquid-viscosity"),
        (["--sphere", "unobtainium", "--sphere-modulus", "1e9"], "unobtainium"),
    ],
)
def test_bad_custom_values_are_refused_with_the_option_named(args, name, capsys):
    assert main(["collide", "--example", *args]) == 2
    err = capsys.readouterr().err
    assert name in err and "Traceback" not in err


def test_a_custom_body_without_preset_needs_all_its_values(capsys):
    """No preset and not every value: the missing ones are named."""
    scalars = ["--radius", "1e-3", "--speed", "1", "--layer-thickness", "1e-4", "--wall", "glass"]
    sphere = ["--sphere-modulus", "1e9", "--sphere-poisson", "0.3"]
    assert main(["collide", *scalars, "--liquid", "water", *sphere]) == 2
    err = capsys.readouterr().err
    assert "--sphere-density" in err and "--sphere-modulus" not in err
    assert main(["collide", *scalars, "--sphere", "steel", "--liquid-viscosity", "0.01"]) == 2
    err = capsys.readouterr().err
    assert "--liquid-density" in err and "--vapour-pressure" in err
    oil = ["--liquid-viscosity", "0.1", "--liquid-density", "900", "--vapour-pressure", "0"]
    assert main(["collide", *scalars, "--sphere", "steel", *oil, "--viscosity", "barus"]) == 2
    assert "--pressure-viscosity" in capsys.readouterr().err


def test_presets_version_and_help(capsys):
    assert main(["presets"]) == 0
    out = capsys.readouterr().out
    assert "E [Pa]" in out and "mu [Pa s]" in out and "Nijssen" in out and "glycerol_80" in out
    assert main(["presets", "--json", "-"]) == 0
    listed = json.loads(capsys.readouterr().out)
    assert listed["materials"]["steel"]["young_modulus"] == 190e9
    assert listed["liquids"]["water"]["source"]
    with pytest.raises(SystemExit):
        main(["--version"])
    assert capsys.readouterr().out.strip() == f"ehdfem {__version__}"
    with pytest.raises(SystemExit):
        main(["--help"])
    description = capsys.readouterr().out.split("\n\n")[1]
    assert description.rstrip().endswith(".") and "critical Stokes number" in description


@pytest.mark.slow
def test_critical_json_to_stdout_is_the_json_alone(capsys):
    args = ["critical", "--eps", "1e-3", "--p-cav=-2", "--nodes", "80", "--bracket-rtol", "0.05"]
    args += ["--bracket", "1", "30"]
    assert main([*args, "--json", "-"]) == 0
    captured = capsys.readouterr()
    found = json.loads(captured.out)
    assert found["bracket"][0] < found["St_c"] < found["bracket"][1] and "St_c" in captured.err


def test_critical_refuses_the_settings_that_cannot_change_st_c(capsys):
    """St_c is decided by the normal motion: the tangential film model and its deformation are
    no options of `critical` (refused by name, not silently ignored)."""
    for flag, value in (("--tangential", "lubrication"), ("--sliding-deformation", "full")):
        with pytest.raises(SystemExit) as exit_info:
            main(["critical", "--eps", "1e-3", flag, value])
        assert exit_info.value.code == 2
        assert flag in capsys.readouterr().err


def test_render_has_no_model_option_it_would_ignore(capsys):
    """render pictures the FE solids whatever the model: --model is refused by name."""
    with pytest.raises(SystemExit) as exit_info:
        main(["render", "--St", "10", "--eps", "1e-3", "--model", "halfspace"])
    assert exit_info.value.code == 2
    assert "--model" in capsys.readouterr().err


def test_json_records_the_provenance(tmp_path, capsys):
    """The JSON says which code computed it (version, the git commit of this checkout and
    whether it had uncommitted changes), when (UTC), with which libraries, by which command
    line and on how many MPI ranks."""
    out = tmp_path / "r.json"
    args = ["collide", *SMALL_COLLISION, "--json", str(out)]
    assert main(args) == 0
    record = json.loads(out.read_text())["provenance"]
    assert record["ehdfem_version"] == __version__ and record["command"] == ["ehdfem", *args]
    head = subprocess.run(
        ["git", "rev-parse", "HEAD"], capture_output=True, text=True, cwd=Path(__file__).parent
    )
    if head.returncode == 0:  # the tests run from a git checkout
        assert record["git"]["commit"] == head.stdout.strip()
        assert isinstance(record["git"]["dirty"], bool)
    assert record["date"].endswith("+00:00") and record["python"] == platform.python_version()
    assert record["libraries"]["numpy"] == np.__version__ and record["mpi_size"] >= 1


@pytest.mark.slow
def test_collide_from_a_result_runs_it_again_exactly(tmp_path, capsys):
    """`collide --from r.json` (or from its histories file) rebuilds the same inputs and run
    settings and gives bit-equal results, for dimensionless and for physical inputs; an input
    or run setting given with --from is refused by name."""
    for inputs in (
        [*SMALL_COLLISION, "--angle", "30", "--tangential", "lubrication"],
        ["--example", "--nodes", "60", "--cavitation", "mass-conserving"],
    ):
        first, histories = tmp_path / "first.json", tmp_path / "first.npz"
        args = ["collide", *inputs, "--json", str(first), "--histories", str(histories)]
        assert main(args) == 0
        for source in (first, histories):
            again = tmp_path / "again.json"
            assert main(["collide", "--from", str(source), "--json", str(again)]) == 0
            a, b = (json.loads(p.read_text()) for p in (first, again))
            assert a.pop("provenance")["command"] != b.pop("provenance")["command"]
            assert a == b  # every output, the SI values and the inputs, bit-equal
    capsys.readouterr()
    for flag in ("--St", "--nodes", "--speed"):
        assert main(["collide", "--from", str(first), flag, "3"]) == 2
        assert f"{flag}: cannot be given with --from" in capsys.readouterr().err
    assert main(["collide", "--from", str(tmp_path / "none.json")]) == 2
    assert "--from" in capsys.readouterr().err


def test_histories_file_holds_the_histories_with_their_units(tmp_path, capsys):
    """--histories: the normal and tangential histories, H(R,T) and P(R,T) exactly as the
    collision computed them, their units, and SI copies (scaled value times its unit) for
    physical inputs."""
    from ehdfem import collide
    from ehdfem.config import read_inputs

    path = tmp_path / "h.npz"
    assert main(["collide", "--example", "--nodes", "60", "--histories", str(path)]) == 0
    with np.load(path) as stored:
        data = dict(stored)
    units = json.loads(str(data["units"]))
    result = collide(*read_inputs(json.loads(str(data["inputs"]))))
    hist = result.normal.history
    for name in ("time", "gap", "velocity", "force", "film_thickness", "pressure", "fill"):
        assert np.array_equal(data[name], getattr(hist, name)), name
    assert data["pressure"].shape == (len(hist.time), len(result.normal.radii))
    assert np.array_equal(data["radius"], result.normal.radii)
    assert np.array_equal(data["tangential_velocity"], result.tangential.velocity)
    scales = result.physical.scales()
    assert np.array_equal(data["pressure_si"], data["pressure"] * scales.pressure)
    assert np.array_equal(data["time_si"], data["time"] * scales.time)
    assert data["velocity_si"][0] == pytest.approx(-result.physical.normal_speed, rel=1e-12)
    assert units["pressure"][1] == "mu V0 a / x0^2" and units["pressure_si"][1] == "Pa"
    assert units["force_si"][1] == "N" and units["time"][1] == "x0/V0"
    assert set(units) == set(data) - {"units", "inputs", "provenance"}
    assert json.loads(str(data["provenance"]))["ehdfem_version"] == __version__
    docs = Path(__file__).resolve().parent.parent / "docs" / "outputs.md"
    assert histories.markdown_table() in docs.read_text()  # the documented format is the file's


@pytest.mark.slow
def test_critical_with_physical_inputs_gives_the_critical_speed(capsys):
    """Physical inputs: the critical impact speed [m/s] by bisection, the sphere sticking at
    the bracket's low end and rebounding at its high end (checked by two collisions); the
    speed, which is sought, is refused by name, as are scaled inputs. --bracket-rtol is the
    final bracket's width; --rtol, the time step's tolerance, is left at its default."""
    from dataclasses import replace

    from ehdfem import collide, from_presets

    bodies = ["--sphere", "glass", "--wall", "glass", "--liquid", "water"]
    sizes = ["--radius", "3e-3", "--layer-thickness", "2e-4", "--nodes", "60"]
    args = ["critical", *bodies, *sizes, "--bracket-rtol", "0.05", "--bracket", "0.002", "0.05"]
    assert main([*args, "--json", "-"]) == 0
    found = json.loads(capsys.readouterr().out)
    low, high = found["bracket"]
    assert low < found["speed"] < high and high / low - 1 <= 0.05
    physical = from_presets(
        sphere="glass", wall="glass", liquid="water", radius=3e-3, layer_thickness=2e-4, speed=1
    )
    config = RunConfig.from_settings(nodes=60)
    assert collide(replace(physical, speed=high), config).normal.rebound
    assert not collide(replace(physical, speed=low), config).normal.rebound
    at = replace(physical, speed=found["speed"]).dimensionless()
    assert found["St_c"] == pytest.approx(at.St, rel=1e-12)
    assert found["sphere"]["name"] == "glass" and found["run"]["nodes"] == 60
    assert found["bracket_rtol"] == 0.05 and found["run"]["rtol"] == RunConfig().options.rtol
    with pytest.raises(SystemExit):
        main(["critical", *bodies, *sizes, "--speed", "1"])
    assert "--speed" in capsys.readouterr().err
    assert main(["critical", *bodies, *sizes, "--eps", "1e-3"]) == 2
    assert "--eps" in capsys.readouterr().err


def test_provenance_without_git_has_no_commit_and_no_error(monkeypatch):
    """Without git (or outside a checkout) the record's git is None, the commit column empty."""
    from ehdfem.outputs import provenance

    monkeypatch.setenv("PATH", "/nonexistent")
    assert provenance.git_state.__wrapped__() is None
    monkeypatch.setattr(provenance, "git_state", lambda: None)
    assert provenance.record(["ehdfem"])["git"] is None and provenance.commit_text() == ""


# --- Paths, error form, fit's tables, the sweep's counter -------------------------------------


def refusal(capsys, *argv) -> str:
    """The one error line of ``ehdfem ARGV`` refused with exit status 2, before any work."""
    assert main(list(argv)) == 2
    err = capsys.readouterr().err
    lines = [line for line in err.splitlines() if "error" in line]
    assert len(lines) == 1 and "Traceback" not in err
    return lines[0]


SMALL_STUDY = '[grid]\nSt = [10.0]\neps = [1e-3]\n[numerics]\nnodes = 40\n[output]\ntable = "{}"\n'


@pytest.fixture
def places(tmp_path):
    """A file where a folder is expected, a missing folder, an unwritable one (/proc), a study
    file and a fit table, all in ``tmp_path``."""
    (tmp_path / "F").write_text("a file")
    (tmp_path / "study.toml").write_text(SMALL_STUDY.format("F/out/t.csv"))
    table = tmp_path / "t.csv"
    table.write_text("status,St,eps,e_n\nok:rebound,10,1e-3,0.3\nok:rebound,20,1e-3,0.6\n")
    return tmp_path


@pytest.mark.parametrize(
    ("argv", "option", "reason"),
    [
        (["collide", *SMALL_COLLISION, "--plots", "{F}/x"], "--plots", "is a file, not a folder"),
        (["collide", *SMALL_COLLISION, "--json", "{missing}/r.json"], "--json", "does not exist"),
        (["collide", *SMALL_COLLISION, "--json", "/proc/r.json"], "--json", "cannot write in"),
        (["collide", *SMALL_COLLISION, "--json", "{dir}"], "--json", "is a folder"),
        (["collide", *SMALL_COLLISION, "--histories", "{F}/h.npz"], "--histories", "is a file"),
        (["collide", *SMALL_COLLISION, "--fields", "{missing}/f.xdmf"], "--fields", "not exist"),
        (["collide", "--from", "{dir}"], "--from", "is a folder"),
        (["render", *SMALL_COLLISION, "--out", "{missing}/r.png"], "--out", "does not exist"),
        (["render", *SMALL_COLLISION, "--animation", "{F}/a.gif"], "--animation", "is a file"),
        (["bounce", "--folder", "{F}/b", "--radius", "1e-3"], "--folder", "is a file"),
        (["bounce", "--json", "{missing}/b.json"], "--json", "does not exist"),
        (["critical", "--eps", "1e-3", "--json", "{F}/c.json"], "--json", "is a file"),
        (["presets", "--json", "{missing}/p.json"], "--json", "does not exist"),
        (["fit", "{dir}/t.csv", "--json", "{missing}/f.json"], "--json", "does not exist"),
        (["fit", "{dir}/t.csv", "--python", "{F}/forms.py"], "--python", "is a file"),
        (["fit", "{dir}/none.csv"], "table", "does not exist"),
        (["sweep", "{dir}/none.toml"], "study", "does not exist"),
        (["sweep", "{dir}/study.toml"], "study", "[output] table"),
    ],
)
def test_unusable_paths_are_refused_naming_the_option(places, capsys, argv, option, reason):
    """A file where a folder must be, a missing folder for an output file (refused, not
    made), an unwritable place, a folder for a file: one error line naming the option, before
    any work (on main, --plots under a file ended in NotADirectoryError and --json made the
    missing folders)."""
    names = {"F": places / "F", "missing": places / "missing", "dir": places}
    line = refusal(capsys, *(arg.format(**names) for arg in argv))
    assert line.startswith(f"ehdfem {argv[0]}: error: {option}: ") and reason in line
    assert not (places / "missing").exists()


def test_errors_have_one_form_naming_the_option_as_typed(capsys):
    """``ehdfem <command>: error: --flag: message``: the field's name of the library becomes
    the option (St = 0.0 -> --St: 0.0, roelands_pressure -> --roelands-pressure), and
    argparse's own refusals (a bad number, an option the command does not have) take the same
    form under the command's name."""
    line = refusal(capsys, "collide", "--St", "0", "--eps", "1e-3")
    assert line == "ehdfem collide: error: --St: 0.0 is outside the allowed range (0, inf)"
    line = refusal(capsys, "collide", "--St", "10", "--eps", "1e-3", "--viscosity", "roelands")
    assert "--roelands-pressure" in line and "roelands_pressure" not in line
    line = refusal(capsys, "collide", "--example", "--vapour-pressure", "2e5")
    assert "--vapour-pressure" in line and "vapour_pressure" not in line
    assert refusal(capsys, "bounce", "--radius", "1e-3").startswith(
        "ehdfem bounce: error: the bounce needs --sphere"
    )
    with pytest.raises(SystemExit) as exit_info:
        main(["collide", "--St", "x", "--eps", "1e-3"])
    assert exit_info.value.code == 2
    assert "ehdfem collide: error: --St: invalid float value: 'x'" in capsys.readouterr().err
    with pytest.raises(SystemExit):
        main(["critical", "--St", "3", "--eps", "1e-3"])
    assert "ehdfem critical: error: unrecognized arguments: --St 3" in capsys.readouterr().err


# the launcher of this Python's MPI: the wheel stack's venv has its own (MPICH), Debian's
# stack takes OpenMPI's from the PATH
MPIRUN = next((str(p) for p in [Path(sys.executable).with_name("mpirun")] if p.exists()), "mpirun")


@pytest.mark.slow
@pytest.mark.parametrize(
    ("argv", "expected"),
    [
        (["--St", "0", "--eps", "1e-3"], "ehdfem collide: error: --St: "),
        (["--St", "x", "--eps", "1e-3"], "ehdfem collide: error: --St: invalid float"),
    ],
)
def test_an_error_under_mpirun_is_printed_once_with_a_failing_status(argv, expected):
    """Under ``mpirun -n 2`` both ranks meet the same bad input: the error is printed once (by
    rank 0; on main it was printed by each rank) and mpirun's exit status is 2."""
    done = subprocess.run(
        [MPIRUN, "-n", "2", sys.executable, "-m", "ehdfem", "collide", *argv],
        stdin=subprocess.DEVNULL,  # mpirun forwards its input to rank 0: not pytest-xdist's
        capture_output=True,
        text=True,
        timeout=120,
        env={
            **os.environ,
            "OMPI_ALLOW_RUN_AS_ROOT": "1",
            "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1",
            "OMPI_MCA_rmaps_base_oversubscribe": "1",
        },
    )
    errors = [line for line in done.stderr.splitlines() if line.startswith("ehdfem collide:")]
    assert len(errors) == 1 and errors[0].startswith(expected), done.stderr
    assert done.returncode == 2


def write_csv_table(path, rows):
    """``rows`` as a CSV table, the union of their keys as header (empty cells where a row has
    no value), as ehdfem sweep writes it."""
    with path.open("w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(dict.fromkeys(k for r in rows for k in r)))
        writer.writeheader()
        writer.writerows(rows)


def fit_rows(eps_of=lambda St: 1e-3, **extra):
    """A table of e_n = 0.9 (1 - 5/St) at St 6..100 (eps by ``eps_of``), with ``extra``
    columns."""
    return [
        {"status": "ok:rebound", "St": St, "eps": eps_of(St), "e_n": 0.9 * (1 - 5 / St), **extra}
        for St in (6.0, 10.0, 20.0, 50.0, 100.0)
    ]


def test_fit_json_writes_numbers_as_numbers_and_no_limit_as_null(tmp_path, capsys):
    """p_cav and alpha are numbers in fit's JSON (strings on main), P_cav none is null; a
    table without delta (a study that does not sweep it) is fitted at delta's default."""
    table = tmp_path / "t.csv"
    write_csv_table(table, fit_rows(p_cav=-2.0, alpha=0.5) + fit_rows(eps_of=lambda St: 1e-2))
    assert main(["fit", str(table), "--json", "-"]) == 0
    groups = json.loads(capsys.readouterr().out)["normal"]
    assert [(g["p_cav"], g["alpha"], g["delta"]) for g in groups] == [
        (-2.0, 0.5, 0.01),
        (None, 0.0, 0.01),
    ]
    assert groups[0]["St_c"] == pytest.approx(5.0, rel=1e-10)


@pytest.mark.parametrize(
    ("rows", "expected"),
    [
        ([{"St": 10, "eps": 1e-3, "e_n": 0.5}], "no column status"),
        ([{"status": "ok:rebound", "St": "x", "eps": 1e-3, "e_n": 0.5}], "column St = 'x'"),
        ([{"status": "failed: InputError", "St": 1, "eps": 1e-3, "e_n": ""}], "no successful"),
        (
            fit_rows(eps_of=lambda St: St * 1e-5, angle=30.0),
            "group(s), the most rebounding points in one is 1",
        ),
    ],
)
def test_fit_names_what_a_table_lacks(tmp_path, capsys, rows, expected):
    """A table fit cannot use gets one error line saying what is missing (KeyError on main for
    a table without status; a physical study, whose eps changes at every point, now says how
    many rebounding points its groups have)."""
    table = tmp_path / "t.csv"
    write_csv_table(table, rows)
    line = refusal(capsys, "fit", str(table))
    assert line.startswith("ehdfem fit: error: table: ") and expected in line


def test_sweep_counts_only_its_own_points_and_prints_short_numbers(tmp_path):
    """Result files of another grid in the point folder do not count (on main: [4/1]), and
    the progress line gives its numbers to four digits (St = 10.000000000000002 -> 10)."""
    from ehdfem.study.sweep import Study, run_study

    (tmp_path / "s.toml").write_text(
        SMALL_STUDY.replace("[10.0]", "[10.000000000000002]").format("t.csv")
    )
    study = Study(tmp_path / "s.toml")
    study.point_dir.mkdir()
    for name in ("a", "b", "c"):  # the finished points of an earlier grid
        (study.point_dir / f"{name}.json").write_text("{}")
    lines = []
    run_study(study, None, progress=lines.append)
    assert len(lines) == 1 and lines[0].startswith("[1/1] rank 0: St=10, eps=0.001 -> ok:")
    assert re.search(r"e_n=0\.\d{4} \(", lines[0])


def cpu_seconds(pid: int) -> float:
    """The CPU time [s] the process ``pid`` has used, user and system (/proc/pid/stat)."""
    fields = Path(f"/proc/{pid}/stat").read_text().rpartition(")")[2].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


@pytest.mark.serial
def test_ctrl_c_ends_a_long_command_with_one_line():
    """SIGINT during `ehdfem critical` (a search of many collisions): exit status 130 and one
    line on standard error naming the command, no traceback."""
    import signal
    import time

    command = ["critical", "--eps", "1e-3", "--bracket-rtol", "1e-8", "--rtol", "1e-7"]
    process = subprocess.Popen(  # about 100 s of collisions: the defaults' 3 s can end first
        [sys.executable, "-m", "ehdfem", *command],
        preexec_fn=interruptible,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    # the search is under way once the solver's imports have loaded scipy's LAPACK wrappers;
    # waiting for them in the process's maps, not a fixed time, keeps a loaded machine's slow
    # imports out of the test (an interrupt there is the imports' line, not the search's)
    maps = Path(f"/proc/{process.pid}/maps")
    deadline = time.monotonic() + 120.0
    while "_flapack" not in maps.read_text() and time.monotonic() < deadline:
        time.sleep(0.05)
    # then 6 s of the process's own CPU time, not of the clock: the rest of the imports and
    # numba's cache load take about one, and a machine busy with other work only stretches them;
    # 2.5 s was once too few on the wheel stack's clean clone, whose first processes also write
    # numba's caches (the search: 100 s)
    start = cpu_seconds(process.pid)
    while cpu_seconds(process.pid) < start + 6.0 and time.monotonic() < deadline:
        time.sleep(0.05)
    process.send_signal(signal.SIGINT)
    _, err = process.communicate(timeout=60)
    assert process.returncode == 130, err
    assert err.strip().splitlines() == [
        "ehdfem critical: interrupted: stopped by Ctrl-C; the search writes nothing until it "
        "ends, so nothing was saved: run the command again to search anew"
    ]


@pytest.mark.parametrize(
    "args,option",
    [
        (["--out", "r.txt"], "--out"),
        (["--out", "render"], "--out"),
        (["--animation", "film.mp4"], "--animation"),
        (["--magnification", "0"], "--magnification"),
        (["--time", "-1"], "--time"),
    ],
)
def test_render_refuses_its_outputs_and_ranges_before_any_work(
    args, option, tmp_path, monkeypatch, capsys
):
    """A picture format matplotlib does not write, an animation that is not a GIF, a
    magnification or time out of range: refused by the option's name within a second (the FE
    work of a render takes tens of seconds)."""
    import time

    monkeypatch.chdir(tmp_path)
    start = time.perf_counter()
    assert main(["render", *args]) == 2
    assert time.perf_counter() - start < 2.0
    err = capsys.readouterr().err
    assert err.startswith(f"ehdfem render: error: {option}:"), err


@pytest.mark.parametrize(
    "args,text",
    [
        (["--St", "10", "--eps", "1e-3", "--alpha", "0.01"], "--alpha has no effect"),
        (
            ["--St", "10", "--eps", "1e-3", "--p-cav=-2", "--cavitation", "none"],
            "--p-cav has no effect with --cavitation none",
        ),
        (
            ["--example", "--cavitation", "none", "--cavitation-pressure", "0"],
            "--cavitation-pressure has no effect",
        ),
        (
            ["--example", "--liquid", "water", "--viscosity", "barus"],
            "--viscosity barus has no effect: the pressure-viscosity coefficient of water is 0",
        ),
    ],
)
def test_an_option_that_cannot_act_is_warned_of(args, text, capsys):
    assert main(["collide", *args, "--nodes", "60"]) == 0
    err = capsys.readouterr().err
    assert f"ehdfem collide: warning: {text}" in err, err


@pytest.mark.parametrize(
    "args,option",
    [
        (["--json", "same.json", "--histories", "same.json"], "--histories"),
        (["--plots", "out", "--json", "out"], "--plots"),
        (["--field-times", "1", "2"], "--field-times"),
    ],
)
def test_outputs_on_one_path_and_field_times_without_fields_are_refused(
    args, option, tmp_path, monkeypatch, capsys
):
    monkeypatch.chdir(tmp_path)
    assert main(["collide", "--St", "10", "--eps", "1e-3", *args]) == 2
    assert capsys.readouterr().err.startswith(f"ehdfem collide: error: {option}:")


@pytest.mark.parametrize(
    "args,line",
    [
        (["collide", "--St", "x", "--eps", "1e-3"], "ehdfem collide: error: --St: invalid float"),
        (["collide", "--example", "--liquid", "honey"], "ehdfem collide: error: --liquid: unknown"),
        (
            ["collide", "--example", "--sphere", "unobtainium"],
            "ehdfem collide: error: --sphere: unknown material preset",
        ),
        (
            ["critical", "--eps", "1e-3", "--bracket", "100", "10"],
            "ehdfem critical: error: --bracket: 100 .. 10 must be increasing",
        ),
        (["collide", "--from", "no_inputs.json"], "ehdfem collide: error: --from: 'no_inputs"),
        (
            ["collide", "--example", "--spin-rate", "nan"],
            "ehdfem collide: error: --spin-rate: must be finite",
        ),
        (
            ["collide", "--model", "fem", "--St", "10", "--eps", "1e-3", "--delta", "0.5"],
            "ehdfem collide: error: --delta: the film reaches r = 1.27 a",
        ),
        (["collide", "--from", "no_parameters.json"], "ehdfem collide: error: --from: 'no_param"),
    ],
)
def test_refusals_are_one_line_naming_the_option(args, line, tmp_path, monkeypatch, capsys):
    """A type error, an unknown preset, a decreasing bracket, a --from file without readable
    inputs: one line in the documented form, no usage text, no traceback."""
    monkeypatch.chdir(tmp_path)
    Path("no_inputs.json").write_text('{"a": 1}')
    Path("no_parameters.json").write_text('{"inputs": {"St": 1}}')
    with pytest.raises(SystemExit) if "invalid float" in line else contextlib.nullcontext():
        assert main(args) == 2
    err = capsys.readouterr().err
    assert err.startswith(line) and len(err.strip().splitlines()) == 1, err


@pytest.mark.parametrize(
    "args,text",
    [
        (["--liquid-viscosity", "5e-5"], "the liquid viscosity 5e-05 Pa s is outside"),
        (["--liquid-viscosity", "5e-5"], "the thinnest film is 1.1"),
    ],
)
def test_results_a_user_should_look_at_twice_are_warned_of(args, text, capsys):
    """A physical collision through a liquid thinner than any liquid at room temperature: its
    viscosity and its nanometre film (below any real surface's roughness) are warned of."""
    assert main(["collide", "--example", *args, "--nodes", "120"]) == 0
    assert f"ehdfem collide: warning: {text}" in capsys.readouterr().err


def test_a_restitution_above_one_is_warned_of():
    """e_n > 1 can only be a discretisation error of pure EHD: warned of with the energy
    error."""
    from types import SimpleNamespace

    from ehdfem.collision import ResultRangeWarning, _check_result_range
    from ehdfem.inputs.scales import CollisionParameters

    params = CollisionParameters.from_settings(St=10.0, eps=1e-3)
    with pytest.warns(ResultRangeWarning, match=r"e_n = 1.01 is above 1.*energy error 0.02"):
        normal = SimpleNamespace(
            e_n=1.01,
            energy_error=0.02,
            solid_impact=None,
            status="rebound",
            rtol=2e-4,
            exit_velocity=1.01,
        )
        _check_result_range(params, None, normal)


def test_an_interrupt_wrapped_by_a_compiled_extension_is_an_interrupt(monkeypatch, capsys):
    """numba, interrupted while it loads a compiled loop from its cache, raises a SystemError
    caused by the KeyboardInterrupt: the command still ends in its own one line and status 130
    (CI runs met a 90-line traceback, then the generic line in place of the search's), and
    outside the part that has its own line, in the generic one. A SystemError of another cause
    still propagates."""
    from ehdfem.cli import caused_by_interrupt, critical

    def interrupted_in_numba(*args):
        try:
            raise KeyboardInterrupt
        except KeyboardInterrupt as err:
            raise SystemError("_numba_unpickle returned a result with an exception set") from err

    monkeypatch.setattr(critical, "_search", interrupted_in_numba)
    assert main(["critical", "--eps", "1e-3"]) == 130
    assert capsys.readouterr().err.strip().splitlines() == [
        f"ehdfem critical: interrupted: {critical.UNSAVED}"
    ]
    commands = sys.modules["ehdfem.cli.main"].COMMANDS  # outside a command's own message
    monkeypatch.setitem(commands, "critical", (*commands["critical"][:2], interrupted_in_numba))
    assert main(["critical", "--eps", "1e-3"]) == 130
    assert capsys.readouterr().err.strip().splitlines() == [
        "ehdfem critical: interrupted: stopped by Ctrl-C; files already written are kept"
    ]
    assert not caused_by_interrupt(SystemError("another cause"))
