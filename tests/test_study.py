"""Studies: resumable sweeps over MPI ranks and the critical Stokes number."""

import csv
import json
import math
import signal
import subprocess
import sys
import tempfile
import time
import warnings
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
from mpi4py import MPI

from ehdfem.checks import InputError
from ehdfem.collision import collide
from ehdfem.config import RunConfig
from ehdfem.inputs.scales import CollisionParameters, from_presets
from ehdfem.outputs import provenance
from ehdfem.outputs.plausibility import TimeResolutionWarning
from ehdfem.study.sweep import (
    Study,
    critical_speed,
    critical_stokes,
    point_key,
    run_study,
)
from ehdfem.study.threshold import bisections, threshold
from ehdfem.version import __version__

SMALL = """
name = "small"
[grid]
St = [4.0, 12.0, 40.0]
eps = [1e-3, 1e-2]
p_cav = [-5.0]
angle = [30.0]
[numerics]
nodes = 60
[output]
table = "out/small.csv"
"""


def read_table(path):
    with open(path) as f:
        return [
            {k: v for k, v in row.items() if k not in ("seconds", "version")}
            for row in csv.DictReader(f)
        ]


def shared_dir(comm):
    """A temporary folder that every rank sees (created by rank 0)."""
    return Path(comm.bcast(tempfile.mkdtemp(prefix="ehdfem-study-") if comm.rank == 0 else None))


@pytest.mark.slow
def test_sweep_on_all_ranks_equals_one_process():
    """Run under mpirun -n 2 too: the table from all ranks equals the one from one process."""
    comm = MPI.COMM_WORLD
    folder = shared_dir(comm)
    for name in ("parallel", "serial"):
        (folder / name).mkdir(exist_ok=True)
        (folder / name / "small.toml").write_text(SMALL)
    comm.Barrier()
    run_study(Study(folder / "parallel" / "small.toml"), comm, progress=None)
    if comm.rank == 0:
        run_study(Study(folder / "serial" / "small.toml"), None, progress=None)
        parallel = read_table(folder / "parallel" / "out" / "small.csv")
        serial = read_table(folder / "serial" / "out" / "small.csv")
        assert len(parallel) == 6 and parallel == serial
        assert all(row["status"].startswith("ok:") for row in parallel)
    comm.Barrier()


@pytest.mark.slow
@pytest.mark.serial
def test_killed_sweep_resumes_with_every_point_once(tmp_path):
    """SIGKILL a sweep at three different moments (while points are running); after a last
    full run every point is in the table exactly once and every finished point survived."""
    study_file = tmp_path / "small.toml"
    study_file.write_text(
        SMALL.replace("St = [4.0, 12.0, 40.0]", "St = [4.0, 8.0, 12.0, 20.0, 40.0]")
    )
    study = Study(study_file)
    command = [sys.executable, "-m", "ehdfem.cli.main", "sweep", str(study_file)]
    survivors = set()
    for target, delay in ((1, 0.0), (3, 0.05), (5, 0.15)):  # kill once `target` points are done
        process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        deadline = time.monotonic() + 120
        while len(list(study.point_dir.glob("*.json"))) < target and time.monotonic() < deadline:
            time.sleep(0.01)
        time.sleep(delay)
        process.send_signal(signal.SIGKILL)
        process.wait()
        finished = {p.stem for p in study.point_dir.glob("*.json")}
        assert survivors <= finished  # nothing finished is lost
        survivors = finished
    assert len(survivors) < len(study.points)  # the kills did interrupt the study
    subprocess.run(command, check=True, capture_output=True)
    rows = read_table(study.table)
    assert len(rows) == len(study.points) == len({(row["St"], row["eps"]) for row in rows}) == 10
    assert not list(study.point_dir.glob(".*.tmp"))


@pytest.mark.slow
@pytest.mark.serial
def test_critical_stokes_number_agrees_with_a_scan():
    """Bisection on the outcome brackets St_c to 1e-3; a scan in 1 % steps finds the first
    rebound inside the bracket widened by one scan step."""
    params = CollisionParameters.from_settings(St=1.0, eps=1e-2, layer="thin", p_cav=-5.0)
    with warnings.catch_warnings():  # the search reports neither a weak e_n nor a stop
        warnings.simplefilter("error", TimeResolutionWarning)
        found = critical_stokes(params, (1.0, 20.0), 1e-3, RunConfig.from_settings(nodes=60))
    lo, hi = found["bracket"]
    assert hi / lo - 1 <= 1e-3
    scan = found["St_c"] * np.exp(np.linspace(-0.05, 0.05, 11))
    outcome = [
        collide(
            CollisionParameters.from_settings(St=s, eps=1e-2, layer="thin", p_cav=-5.0),
            RunConfig.from_settings(nodes=60),
        ).normal.rebound
        for s in scan
    ]
    first = scan[outcome.index(True)]
    assert not any(outcome[: outcome.index(True)]) and all(outcome[outcome.index(True) :])
    assert lo / 1.0101 <= first <= hi * 1.0101


@pytest.mark.slow
@pytest.mark.serial
def test_critical_speed_agrees_with_the_critical_stokes_number():
    """A physical collision's critical speed (eps, P_cav changing with the speed): St there
    equals St_c of the dimensionless search at that speed's eps and P_cav, to the two
    tolerances (1 % in speed, 0.2 % in St)."""
    physical = from_presets(
        sphere="glass",
        wall="glass",
        liquid="silicone_oil_100cst",
        radius=3e-3,
        speed=1.0,
        layer_thickness=2e-4,
    )
    found = critical_speed(physical, bracket=(0.05, 2.0), rtol=0.01)
    at = replace(physical, speed=found["speed"]).dimensionless()
    reference = critical_stokes(at, bracket=(1.0, 50.0), rtol=2e-3)
    assert found["St_c"] == pytest.approx(reference["St_c"], rel=0.012)
    assert collide(replace(physical, speed=found["bracket"][1])).normal.rebound
    assert not collide(replace(physical, speed=found["bracket"][0])).normal.rebound


@pytest.mark.serial
@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("[grid]\nSt = [1.0]\n", "eps"),
        ("[grid]\nSt = [1.0]\neps = [0.1]\ncolour = [1]\n", "colour"),
        ("[grid]\nSt = [-1.0]\neps = [0.1]\n", "St"),
        ("[grid]\nSt = {logspace = [1, 2, 3]}\neps = [0.1]\n", "geomspace"),
        ("[grid]\nSt = [1.0]\neps = [0.1]\n[numerics]\nnodes = 5\n", "nodes"),
        ("[grid\n", "study file"),
        ('[grid]\nSt = [1.0]\neps = [0.1]\ncavitation = ["jfo"]\n', "cavitation"),
        ('[grid]\nSt = [1.0]\neps = [0.1]\nviscosity = ["roelands"]\n', "roelands_pressure"),
        ('[grid]\nSt = [1.0]\neps = [0.1]\nviscosity = ["barus"]\nalpha = [-1]\n', "alpha"),
        ('[grid]\nSt = [1.0]\neps = [0.1]\nasperities = ["greenwood-tripp"]\n', "roughness"),
        (
            '[grid]\nSt = [1.0]\neps = [0.1]\nroughness = [0.1]\nasperities = ["greenwood-tripp"]\n'
            "asperity_slope = [1.5]\n",
            "asperity_slope",
        ),
        ('[grid]\nSt = [1.0]\neps = [0.1]\n[run]\nasperities = "impact"\n', "unknown key"),
        ("[grid]\nSt = [1.0]\neps = [0.1]\nfriction_coefficient = [0.3]\n", "roughness > 0"),
    ],
)
def test_bad_study_files_are_refused_before_any_work(tmp_path, text, message):
    path = tmp_path / "bad.toml"
    path.write_text(text)
    with pytest.raises(InputError, match=message):
        Study(path)


@pytest.mark.slow
@pytest.mark.serial
def test_critical_stokes_number_of_the_fe_model():
    """At delta = 1e-3 the FE solids are half-spaces to 1 %: St_c agrees within 1 %."""
    params = CollisionParameters.from_settings(
        St=1.0, eps=1e-2, layer="thin", p_cav=-5.0, delta=1e-3
    )
    half_space = critical_stokes(params, (1.0, 20.0), config=RunConfig.from_settings(nodes=60))[
        "St_c"
    ]
    fem = critical_stokes(
        params, (1.0, 20.0), config=RunConfig.from_settings(nodes=60, model="fem")
    )["St_c"]
    assert fem == pytest.approx(half_space, rel=0.01)


def test_a_changed_run_setting_is_not_taken_for_finished_points(tmp_path):
    """The point files are named by the point with the fixed run settings ([run], [numerics]):
    the same study file gives the same names (a killed study resumes), a changed setting new
    ones (its points are computed again, not read from the other setting's files); a study
    without fixed settings names a point by the point alone."""
    names = {}
    for label, text in (
        ("small", SMALL),
        ("again", SMALL),
        ("finer", SMALL.replace("nodes = 60", "nodes = 80")),
        (
            "lubrication",
            SMALL.replace("[numerics]", '[run]\ntangential = "lubrication"\n[numerics]'),
        ),
        ("bare", SMALL.replace("[numerics]\nnodes = 60\n", "")),
    ):
        (tmp_path / f"{label}.toml").write_text(text)
        study = Study(tmp_path / f"{label}.toml")
        names[label] = [study.key(point) for point in study.points]
    assert names["again"] == names["small"]
    for changed in ("finer", "lubrication"):
        assert not set(names[changed]) & set(names["small"]), changed
    study = Study(tmp_path / "bare.toml")
    assert names["bare"] == [point_key(point) for point in study.points]


@pytest.mark.serial
def test_the_table_has_a_provenance_sidecar_with_every_fixed_input(tmp_path):
    """Beside the table, its sidecar holds the run's provenance, the [physical] table as
    written and every input and run setting the grid does not sweep, defaults included (here
    the wall and the liquid with all their values, the angle, the layer kind, the time step's
    rtol); every row names the git commit. Rewritten, not duplicated, by a resumed run."""
    study_file = tmp_path / "physical.toml"
    study_file.write_text(
        """
[physical]
sphere = "glass"
wall = {young_modulus = 3e9, poisson_ratio = 0.35, density = 1200}
liquid = "water"
radius = 3e-3
layer_thickness = 2e-4
[grid]
speed = [0.5, 1.0]
[numerics]
nodes = 40
[output]
table = "out/physical.csv"
"""
    )
    study = Study(study_file)
    run_study(study, None, progress=None)
    sidecar = json.loads((tmp_path / "out" / "physical.provenance.json").read_text())
    assert sidecar["provenance"]["ehdfem_version"] == __version__ and sidecar["rows"] == 2
    assert sidecar["physical_table"]["wall"]["young_modulus"] == 3e9
    assert sidecar["swept"] == ["speed"]
    fixed = sidecar["fixed"]
    assert "speed" not in fixed["physical"] and fixed["physical"]["liquid"]["viscosity"] == 1e-3
    assert fixed["physical"]["wall"]["poisson_ratio"] == 0.35
    assert (fixed["physical"]["angle"], fixed["physical"]["layer"]) == (0.0, "thin")
    assert fixed["run"]["nodes"] == 40 and fixed["run"]["rtol"] == RunConfig().options.rtol
    commit = provenance.git_state()
    rows = list(csv.DictReader(study.table.open()))
    expected = "" if commit is None else commit["commit"]
    assert all(row["commit"].startswith(expected) for row in rows) and len(rows) == 2
    run_study(Study(study_file), None, progress=None)  # resumed: nothing to do, same table
    assert list(csv.DictReader(study.table.open())) == rows


@pytest.mark.parametrize("critical, exponent", [(3.7, 0.8), (16.39, 0.35), (2.3, 2.5)])
def test_the_restitution_guides_the_threshold_search_to_the_same_bracket(critical, exponent):
    """An outcome e(v) = 1 - (v_c/v)^m above v_c (0 below) gives a bracket [stick, rebound]
    that holds v_c, no wider than rtol, in fewer evaluations than the bisection on the bool
    outcome, which finds it too; an e_n of another shape (with a kink, the fit never exact)
    still closes the bracket, the mispredictions falling back on bisection."""

    def restitution(v):
        return max(0.0, 1.0 - (critical / v) ** exponent)

    def kinked(v):
        return 0.0 if v <= critical else 0.05 + 0.9 * math.tanh(3 * math.log(v / critical))

    rtol = 1e-3
    guided = threshold(restitution, 1.0, 1000.0, rtol, "v", (1e-3, 1e7))
    plain = threshold(lambda v: restitution(v) > 0, 1.0, 1000.0, rtol, "v", (1e-3, 1e7))
    other = threshold(kinked, 1.0, 1000.0, rtol, "v", (1e-3, 1e7))
    for low, high, _ in (guided, plain, other):
        assert low < critical <= high and high / low - 1 <= rtol
    assert plain[2] == bisections(1.0, 1000.0, rtol)  # the trials replace both ends
    assert guided[2] <= 6 and other[2] <= plain[2]  # measured 5 and 12-14 against 13


@pytest.mark.parametrize("critical", [0.3, 999.9, 1000.0, 2500.0])
def test_the_threshold_search_computes_an_end_it_kept_and_widens_past_it(critical):
    """Where the threshold lies at or beyond an end of the starting bracket [1, 1000], the
    trials never replace that end: it is computed, and where its outcome is the wrong one the
    bracket widens by 4 beyond it. Every end of the final bracket is a computed outcome on its
    side of the threshold (recorded here)."""
    seen = {}

    def outcome(v):
        seen[v] = v >= critical
        return seen[v]

    low, high, evaluations = threshold(outcome, 1.0, 1000.0, 1e-3, "v", (1e-3, 1e7))
    assert low < critical <= high and high / low - 1 <= 1e-3
    assert seen[low] is False and seen[high] is True and evaluations == len(seen)
    assert (1000.0 in seen) == (critical >= 999.9) and (1.0 in seen) == (critical < 1.0)
