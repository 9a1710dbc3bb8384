"""The command line as a user meets it (issue 49), each kind of behaviour driven through the
installed ``ehdfem`` command in its own process: no traceback for any input, interruption or
output path; every check before the work, named by its option; a warning for an option that
does not act; one meaning per option name; physical runs in SI; plausibility notes in the
report and the JSON; ``--help`` with defaults, units and ranges."""

import json
import re
import resource
import signal
import subprocess
import sys
import time
from pathlib import Path
from types import SimpleNamespace

import pytest

pytestmark = pytest.mark.serial  # each test starts its own processes

COMMAND = Path(sys.executable).with_name("ehdfem")  # the venv's console script


def interruptible():
    """For a child the test interrupts: SIGINT at its default and unblocked, as a terminal
    starts a command (a test process may ignore or block it, on the wheel stack after MPI and
    PETSc started in it, and a child inherits that)."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)
    signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT})


def ehdfem(*args, cwd=None, timeout=600) -> subprocess.CompletedProcess:
    """``ehdfem *args`` as a user runs it, its output as text; never a traceback."""
    done = subprocess.run(
        [str(COMMAND), *args], capture_output=True, text=True, cwd=cwd, timeout=timeout
    )
    assert "Traceback" not in done.stderr + done.stdout, done.stderr
    return done


def children_cpu_time() -> float:
    """The CPU time [s] of this process's finished children (user and system): a command's
    work, measured apart from the machine's load."""
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def one_line(done: subprocess.CompletedProcess) -> str:
    """The only line a refused command printed (on standard error; nothing on standard
    output)."""
    lines = done.stderr.strip().splitlines()
    assert len(lines) == 1 and not done.stdout, done.stderr
    return lines[0]


def test_plausibility_notes_are_in_the_report_and_the_json():
    """A physical collision through a liquid thinner than any liquid (5e-5 Pa s) gives a film
    of about a nanometre: both are noted in the JSON's "notes" and after the table
    (``note: ...``), besides the warnings; an unremarkable collision has no note."""
    done = ehdfem(
        "collide", "--example", "--liquid-viscosity", "5e-5", "--nodes", "120", "--json", "-"
    )
    assert done.returncode == 0, done.stderr
    notes = json.loads(done.stdout)["notes"]
    assert len(notes) == 2
    assert notes[0].startswith("the liquid viscosity 5e-05 Pa s is outside the Newtonian")
    assert (
        notes[1].startswith("the thinnest film is 1.1") and " nm, below the roughness" in notes[1]
    )
    printed = [line for line in done.stderr.splitlines() if line.startswith("  note: ")]
    assert printed == [f"  note: {note}" for note in notes]
    assert f"ehdfem collide: warning: {notes[1]}" in done.stderr
    plain = ehdfem("collide", "--St", "10", "--eps", "1e-3", "--nodes", "60", "--json", "-")
    assert json.loads(plain.stdout)["notes"] == [] and "note:" not in plain.stderr


def test_a_restitution_above_one_is_a_note_of_the_result():
    """e_n > 1 (pure EHD cannot gain energy) is noted with the energy error."""
    from ehdfem.inputs.scales import CollisionParameters
    from ehdfem.outputs.plausibility import result_notes

    normal = SimpleNamespace(
        e_n=1.01,
        energy_error=0.02,
        solid_impact=None,
        min_film_thickness=0.1,
        status="rebound",
        rtol=2e-4,
        exit_velocity=1.01,
    )
    notes = result_notes(CollisionParameters.from_settings(St=10.0, eps=1e-3), None, normal)
    assert len(notes) == 1 and notes[0].startswith("e_n = 1.01 is above 1")
    assert "energy error 0.02" in notes[0]


def test_ctrl_c_in_a_one_rank_sweep_says_what_is_saved_and_how_to_resume(tmp_path):
    """SIGINT while a sweep on one rank computes its points: status 130 and one line giving the
    points saved and the command that resumes; run again, the sweep computes only the rest."""
    study = tmp_path / "small.toml"
    study.write_text(
        'name = "small"\n[grid]\nSt = [4.0, 8.0, 12.0, 20.0, 40.0]\neps = [1e-3, 1e-2]\n'
        'p_cav = [-5.0]\n[numerics]\nnodes = 60\n[output]\ntable = "out/small.csv"\n'
    )
    from ehdfem.study.sweep import Study

    points = Study(study).point_dir
    process = subprocess.Popen(
        [str(COMMAND), "sweep", str(study)],
        preexec_fn=interruptible,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    deadline = time.monotonic() + 120
    while not list(points.glob("*.json")) and time.monotonic() < deadline:
        time.sleep(0.02)
    assert process.poll() is None  # still computing
    process.send_signal(signal.SIGINT)
    out, err = process.communicate(timeout=60)
    assert process.returncode == 130, err
    saved = len(list(points.glob("*.json")))
    assert 1 <= saved < 10
    assert err.strip().splitlines() == [
        f"ehdfem sweep: interrupted: stopped by Ctrl-C; {saved} of 10 points are saved in "
        f"{points}; run the same command again to compute the other {10 - saved}"
    ]
    again = ehdfem("sweep", str(study))
    assert again.returncode == 0, again.stderr
    assert len(again.stdout.splitlines()) == 1 + (10 - saved) + 1  # header, new points, wrote


def test_a_closed_pipe_ends_the_command_quietly():
    """``ehdfem presets | head -1``: the reader leaves after one line; no error, no traceback."""
    process = subprocess.Popen(
        [str(COMMAND), "presets"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, bufsize=0
    )
    process.stdout.read(10)
    process.stdout.close()
    err = process.stderr.read().decode()
    process.wait(timeout=60)
    assert err == "" and process.returncode in (0, 1)


COMMANDS = ("collide", "render", "sweep", "critical", "fit", "presets", "bounce", "dem")


def help_entries(command: str) -> dict[str, str]:
    """``ehdfem <command> --help`` as {option: its usage and help as one line}."""
    entries, current = {}, None
    for line in ehdfem(command, "--help").stdout.splitlines():
        start = re.match(r"^  (--[\w-]+)", line)
        if start:
            current = start.group(1)
            entries[current] = line.strip()
        elif current and line.startswith("    ") and line.strip():
            entries[current] += " " + line.strip()
        else:
            current = None
    return entries


@pytest.fixture(scope="module")
def helps() -> dict[str, dict[str, str]]:
    return {command: help_entries(command) for command in COMMANDS}


def test_every_option_of_every_command_states_its_default(helps):
    """``--help`` of each command: every option says its default (or that it is required)."""
    silent = [
        f"{command} {option}"
        for command, entries in helps.items()
        for option, text in entries.items()
        if option != "--help" and "default" not in text
    ]
    assert silent == []


def _unit(text: str) -> str | None:
    """The first unit or scale in brackets of a help text ([Pa], [by x0/V0]; not a range)."""
    units = re.findall(r"\[([^\]\d(-][^\]]*)\]", text)
    return units[0] if units else None


def _shape(option: str, text: str) -> tuple:
    """What must agree between two commands' options of one name: what follows the name in
    the usage (its metavar or its choices) and its unit."""
    taken = re.match(
        r"(, --no-[\w-]+)?\s+(\{[^}]*\}|[A-Z][A-Z0-9_.]*(?=\s))?", text.removeprefix(option)
    )
    return (taken.group(1) or "") + (taken.group(2) or ""), _unit(text)


def test_an_option_name_has_one_meaning_across_commands(helps):
    """An option of one name takes the same kind of value (metavar or choices) in the same unit
    in every command that has it: render's --out is a picture file and bounce writes into
    --folder, as dem does; --rtol is the time-step tolerance everywhere; --model chooses the
    solids among the same models; --added-mass is a mass in kg."""
    by_name = {}
    for command, entries in helps.items():
        for option, text in entries.items():
            by_name.setdefault(option, {})[command] = _shape(option, text)
    differ = {
        option: shapes
        for option, shapes in by_name.items()
        if option != "--help" and len(set(shapes.values())) > 1
    }
    assert differ == {}
    assert set(by_name["--out"]) == {"render"}
    assert set(by_name["--folder"]) == {"bounce", "dem"}
    assert {command for command, text in by_name["--rtol"].items()} >= {"collide", "bounce"}
    assert all("time-step tolerance" in helps[c]["--rtol"] for c in by_name["--rtol"])
    assert "[kg]" in helps["collide"]["--added-mass"] and "--added-mass" not in helps["bounce"]


BOUNCE = ["bounce", "--sphere", "steel", "--wall", "glass", "--liquid", "silicone_oil_10cst",
          "--radius", "1.5e-3", "--release-height", "0.02"]  # fmt: skip


def test_bounce_options_are_checked_before_the_bounce(tmp_path):
    """bounce's former --out (a folder, where render's --out is a file) is refused naming
    --folder; --json and --folder on one path are refused; each before the bounce: the two
    commands take less CPU time than the bounce itself (about ten seconds; CPU time, not wall
    time, so that a loaded machine does not fail the test)."""
    start = children_cpu_time()
    line = one_line(ehdfem(*BOUNCE, "--out", str(tmp_path / "b")))
    assert line.startswith("ehdfem bounce: error: --out: the bounce's output folder is --folder")
    same = str(tmp_path / "same")
    line = one_line(ehdfem(*BOUNCE, "--json", same, "--folder", same))
    assert line.startswith(f"ehdfem bounce: error: --folder: {same!r} is also the path of --json")
    assert children_cpu_time() - start < 6.0 and not (tmp_path / "b").exists()


@pytest.mark.parametrize(
    "args, line",
    [
        (
            ["render", "--St", "10", "--eps", "1e-3", "--p-cav=-2", "--nodes", "40", "--time",
             "1e9", "--out", "r.png"],
            "ehdfem render: error: --time: T = 1e+09 is after the collision's end, T = ",
        ),
        (
            ["collide", "--St", "10", "--eps", "1e-3", "--p-cav=-2", "--nodes", "40", "--model",
             "fem", "--fields", "f.xdmf", "--field-times", "1", "1e3"],
            "ehdfem collide: error: --field-times: T = 1000 is after the collision's end, T = ",
        ),
        (
            ["render", "--St", "10", "--eps", "1e-3", "--json", "r.png", "--out", "r.png"],
            "ehdfem render: error: --json: 'r.png' is also the path of --out",
        ),
        (
            ["collide", "--example", "--layer-thickness", "0.1"],
            "ehdfem collide: error: --layer-thickness: 0.1 m must be smaller than the radius",
        ),
    ],
)  # fmt: skip
def test_refusals_name_the_option_as_typed(args, line, tmp_path):
    """An instant after the collision's end (known once the collision is computed, before any
    picture or field is written), two outputs on one path, a layer thicker than the sphere:
    one line in the documented form, naming the option (not "field time")."""
    done = ehdfem(*args, cwd=tmp_path)
    assert done.returncode == 2 and one_line(done).startswith(line)
    assert list(tmp_path.iterdir()) == []


def test_a_warning_each_collision_repeats_is_shown_once():
    """A physical critical-speed search whose collisions all make a nanometre film: the first
    warning, then one line counting the others (one per collision, before)."""
    search = ["--sphere", "glass", "--wall", "glass", "--liquid", "water", "--radius", "3e-3",
              "--layer-thickness", "2e-4", "--bracket-rtol", "0.05"]  # fmt: skip
    done = ehdfem("critical", *search)
    assert done.returncode == 0, done.stderr
    warned = [line for line in done.stderr.splitlines() if "warning:" in line]
    assert len(warned) == 2, done.stderr
    assert warned[0].startswith("ehdfem critical: warning: the thinnest film is ")
    assert re.match(r'ehdfem critical: warning: \d+ more like "the thinnest film is ', warned[1])


def test_the_readmes_commands_run_from_the_clone():
    """Every shell line of the README's examples that runs Python or ehdfem does it through the
    set-up's venv (.venv/bin/...): Debian has no ``python`` command, and ehdfem is not on the
    PATH."""
    readme = (Path(__file__).resolve().parents[1] / "README.md").read_text()
    commands = []
    for block in re.findall(r"```sh\n(.*?)```", readme, flags=re.S):
        lines = [line.strip() for line in block.splitlines() if line.strip()]
        prompted = [line[2:] for line in lines if line.startswith("$ ")]  # the rest: output
        commands += prompted or [line for line in lines if not line.startswith("#")]
    bare = [c for c in commands if re.match(r"(python3?|ehdfem)(?![\w.])", c)]  # python3.12: chosen
    assert bare == [] and any(c.startswith(".venv/bin/python -c") for c in commands)


@pytest.mark.parametrize(
    "args, line",
    [
        (["render", "--St", "10", "--eps", "1e-3", "--out", "r.txt"],
         "ehdfem render: error: --out: 'r.txt' has the format '.txt'"),
        (["collide", "--St", "x", "--eps", "1e-3"], "ehdfem collide: error: --St: invalid float"),
        (["collide", "--example", "--liquid", "honey"], "ehdfem collide: error: --liquid: unknown"),
        (["critical", "--eps", "1e-3", "--bracket", "100", "10"],
         "ehdfem critical: error: --bracket: 100 .. 10 must be increasing"),
        (["collide", "--St", "10", "--eps", "1e-3", "--field-times", "1"],
         "ehdfem collide: error: --field-times: needs --fields"),
        (["collide", "--St", "10", "--eps", "1e-3", "--json", "same", "--histories", "same"],
         "ehdfem collide: error: --histories: 'same' is also the path of --json"),
        (["sweep", "missing.toml"], "ehdfem sweep: error: study: 'missing.toml' does not exist"),
    ],
)  # fmt: skip
def test_refused_inputs_end_in_one_line_within_seconds(args, line, tmp_path):
    """Inputs that gave tracebacks, usage texts or minutes of work: one line in the documented
    form, status 2, nothing written, within seconds of CPU time."""
    start = children_cpu_time()
    done = ehdfem(*args, cwd=tmp_path)
    assert done.returncode == 2 and one_line(done).startswith(line)
    assert children_cpu_time() - start < 5.0 and list(tmp_path.iterdir()) == []


def test_an_option_that_cannot_act_is_warned_of_and_the_run_goes_on():
    """--alpha with the constant viscosity and --p-cav with --cavitation none: a warning each,
    naming the option, and the collision's results."""
    done = ehdfem("collide", "--St", "10", "--eps", "1e-3", "--alpha", "0.01", "--p-cav=-2",
                  "--cavitation", "none", "--nodes", "60", "--json", "-")  # fmt: skip
    assert done.returncode == 0 and 0 < json.loads(done.stdout)["e_n"] < 1
    warned = [line for line in done.stderr.splitlines() if ": warning: " in line]
    assert [line.split(": warning: ")[1].split(" ")[0] for line in warned] == ["--alpha", "--p-cav"]


def test_a_physical_collision_is_reported_in_si(tmp_path):
    """``collide --example``: the report names the physical inputs and gives the SI values with
    their units; the JSON holds them under "si"; the plots' axes are in SI."""
    done = ehdfem("collide", "--example", "--nodes", "80", "--plots", "plots", "--json", "-",
                  cwd=tmp_path)  # fmt: skip
    assert done.returncode == 0, done.stderr
    assert "physical inputs: steel sphere of radius 6.35 mm at 1 m/s, 30 deg" in done.stderr
    si = json.loads(done.stdout)["si"]
    row = next(line for line in done.stderr.splitlines() if "contact_time_s" in line).split()
    assert float(row[1]) == pytest.approx(si["contact_time_s"], rel=1e-5) and row[2] == "s"
    assert sorted(p.name for p in (tmp_path / "plots").iterdir()) == [
        "histories.png", "profiles.png", "tangential.png"
    ]  # fmt: skip


def test_dem_runs_its_example_and_records_where_its_result_comes_from(tmp_path):
    """``dem --engine liggghts --example``: the engine's rebound beside ehdfem's half-space
    model, every file the engine wrote, and a JSON with the provenance and the inputs that
    ``collide --from`` runs again."""
    done = ehdfem("dem", "--engine", "liggghts", "--example", "--folder", "engine", "--json",
                  "-", cwd=tmp_path)  # fmt: skip
    assert done.returncode == 0, done.stderr
    assert "liggghts beside ehdfem's half-space model" in done.stderr
    assert "(rerun there: liggghts -in in.collision)" in done.stderr
    result = json.loads(done.stdout)
    assert result["provenance"]["command"][:3] == ["ehdfem", "dem", "--engine"]
    (tmp_path / "dem.json").write_text(done.stdout)
    again = ehdfem("collide", "--from", "dem.json", "--json", "-", cwd=tmp_path)
    assert again.returncode == 0, again.stderr
    assert json.loads(again.stdout)["e_n"] == result["full_model"]["e_n"]


def test_fit_says_which_quantity_its_errors_are_of(tmp_path):
    """fit's report: each error is named by what it is the error of (e_n for the e_n fits and
    the DEM formulas, St_c for the law of the critical Stokes number), since the two differ by
    orders of magnitude; the e_n fit of an exact table has no error."""
    rows = ["status,St,eps,e_n"] + [
        f"ok:rebound,{St},{eps},{0.9 * (1 - 5 * (eps / 1e-3) ** -0.1 / St)!r}"
        for eps in (1e-3, 1e-2)
        for St in (6.0, 10.0, 20.0, 50.0, 100.0)
    ]
    (tmp_path / "t.csv").write_text("\n".join(rows) + "\n")
    lines = ehdfem("fit", "t.csv", cwd=tmp_path).stdout.splitlines()
    fits = [line for line in lines if " error: max " in line]
    assert [line.split(" error: max ")[0].split()[-1] for line in fits] == [
        "e_n", "e_n", "St_c", "e_n", "e_n"
    ]  # fmt: skip
    assert float(fits[0].split(" error: max ")[1].split(",")[0]) < 1e-12


def test_the_liquid_presets_say_what_they_are():
    """``ehdfem presets``: pure glycerol is glycerol (it read "pure glycerol-water"), and the
    silicone oils' source does not state a density range their 10 cSt grade (935 kg/m^3) lies
    outside."""
    table = {line.split()[0]: line for line in ehdfem("presets").stdout.splitlines() if line}
    assert "pure glycerol at 20 C" in table["glycerol"]
    assert " 935 " in table["silicone_oil_10cst"] and "965-970" not in table["silicone_oil_10cst"]


def test_tangential_and_roelands_settings_that_cannot_act_are_warned_of():
    """A head-on impact solves no tangential motion: its film model, mode-1 deformation and
    the sphere's inertia factor cannot act; nor the sliding film's deformation with the Couette
    film, nor the Roelands index with the constant viscosity. A warning each, and the run."""
    dimensionless = ["collide", "--St", "10", "--eps", "1e-3", "--nodes", "60"]
    head_on = ehdfem(*dimensionless, "--tangential", "lubrication", "--inertia-factor", "0.5",
                     "--roelands-index", "0.5")  # fmt: skip
    oblique = ehdfem(*dimensionless, "--angle", "30", "--sliding-deformation", "full")
    warned = [
        line.split(": warning: ")[1]
        for done in (head_on, oblique)
        for line in done.stderr.splitlines()
        if ": warning: " in line
    ]
    assert [w.split(" has no effect ")[0] for w in warned] == [
        "--tangential", "--inertia-factor", "--roelands-index", "--sliding-deformation"
    ]  # fmt: skip
    assert "on a head-on impact" in warned[0] and "with --tangential couette" in warned[3]
    assert head_on.returncode == oblique.returncode == 0


def test_an_error_the_library_names_by_its_field_names_the_option():
    """The time-step control's refusal of --exit-gap on a thin layer ("exit_gap = 2.0 needs an
    immersed layer") comes in the documented form, ``--exit-gap: 2.0 needs ...``."""
    line = one_line(ehdfem("collide", "--St", "10", "--eps", "1e-3", "--exit-gap", "2"))
    assert line.startswith("ehdfem collide: error: --exit-gap: 2.0 needs an immersed layer")


def test_ctrl_c_while_the_command_imports_is_one_line():
    """SIGINT as soon as the command has loaded numpy (the first of the imports its entry point
    makes: numpy, scipy, numba and the package take about half a second), while it still
    imports: one line naming the command, status 130 (a traceback from the imports before the
    entry point caught them). The signal waits for numpy's library in the process's maps, so
    it never lands in the interpreter's own start-up, whatever the machine's load."""
    process = subprocess.Popen(
        [str(COMMAND), "critical", "--eps", "1e-3"],
        preexec_fn=interruptible,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    maps = Path(f"/proc/{process.pid}/maps")
    deadline = time.monotonic() + 30.0
    while "_multiarray_umath" not in maps.read_text() and time.monotonic() < deadline:
        time.sleep(0.002)
    process.send_signal(signal.SIGINT)
    _, err = process.communicate(timeout=60)
    assert process.returncode == 130, err
    assert err.strip().splitlines() == [
        "ehdfem critical: interrupted: stopped by Ctrl-C before the command began; nothing was "
        "written"
    ]
