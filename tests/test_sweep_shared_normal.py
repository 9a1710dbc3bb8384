"""A sweep integrates each normal motion once (ehdfem.collision.SharedNormals, docs/studies.md,
"Shared normal motions"), and its rows are those of collisions computed afresh, bit for bit."""

import json
import tempfile
from dataclasses import dataclass, replace
from pathlib import Path

import pytest
from mpi4py import MPI

import ehdfem.collision
from ehdfem.collision import SharedNormals, collide, normal_key
from ehdfem.config import RunConfig
from ehdfem.inputs.scales import CollisionParameters, from_presets
from ehdfem.motion.forces import ConstantForce
from ehdfem.motion.normal import FilmClosedError
from ehdfem.study.sweep import Study, normal_groups, run_point, run_study

# 16 points: thin and immersed layers, delta 1e-3 and 0.5, two angles, two eps. On half-spaces
# under a thin layer the film grid, the compliance and the gap do not see delta: one normal
# motion per eps (2); an immersed grid has a node at R = 1/sqrt(delta): one per (eps, delta) (4).
GRID = """
name = "shared"
[grid]
St = [10.0]
eps = [1e-3, 1e-2]
delta = [1e-3, 0.5]
angle = [15.0, 30.0]
layer = ["thin", "immersed"]
[numerics]
nodes = 60
[output]
table = "out/shared.csv"
"""
NORMALS = 6


def counting_solves(monkeypatch):
    """Count the normal integrations of every collision (ehdfem.collision.solve_normal)."""
    calls = []
    solve = ehdfem.collision.solve_normal

    def counted(*args, **kwargs):
        calls.append(args[0])
        return solve(*args, **kwargs)

    monkeypatch.setattr(ehdfem.collision, "solve_normal", counted)
    return calls


def row_text(row):
    """A row as JSON without its wall time: equal texts are equal values bit for bit (floats
    in their shortest exact form, NaN as NaN)."""
    return json.dumps({k: v for k, v in row.items() if k != "seconds"}, sort_keys=True)


def study_in(folder):
    (folder / "shared.toml").write_text(GRID)
    return Study(folder / "shared.toml")


@pytest.mark.serial
def test_the_groups_are_those_of_the_normal_problems(tmp_path):
    """Thin: one group per eps across delta and angle (4 points each); immersed: one per
    (eps, delta) across the angle (2 points each)."""
    study = study_in(tmp_path)
    groups = normal_groups(study)
    sizes = sorted(
        (",".join({study.points[i]["layer"] for i in members}), len(members))
        for _, members in groups
    )
    assert sizes == [("immersed", 2)] * 4 + [("thin", 4)] * 2
    for _, members in groups:  # a group's points differ in neither St nor eps
        assert len({(study.points[i]["St"], study.points[i]["eps"]) for i in members}) == 1


@pytest.mark.slow
@pytest.mark.serial
def test_sweep_rows_equal_fresh_collisions_with_one_normal_per_problem(tmp_path, monkeypatch):
    """Every row of the sweep (every output column, status, settings) equals the row of a
    collision computed afresh, and the sweep integrated 6 normal motions for 16 points. The
    shared points are not copies: delta changes a thin layer's e_t (1 - e_t grows with delta),
    the angle its tangential speed."""
    calls = counting_solves(monkeypatch)
    study = study_in(tmp_path)
    lines = []
    rows = run_study(study, None, progress=lines.append)
    assert len(calls) == NORMALS and len(rows) == 16
    assert sum("normal shared" in line for line in lines) == 16 - NORMALS
    fresh = [run_point(study, point) for point in study.points]
    assert len(calls) == NORMALS + 16
    assert [row_text(row) for row in rows] == [row_text(row) for row in fresh]
    assert all(row["status"] == "ok:rebound" for row in rows)
    thin = [row for row in rows if row["layer"] == "thin" and row["eps"] == 1e-3]
    assert len({row["e_n"] for row in thin}) == 1
    assert len({row["e_t"] for row in thin}) == 2  # delta 1e-3, 0.5


@pytest.mark.slow
@pytest.mark.serial
def test_a_resumed_sweep_runs_only_the_missing_points(tmp_path, monkeypatch):
    """Result files of three points removed (one of a thin group of four, both of an immersed
    group): the next run computes those three with one normal motion per group they are in
    (2), leaves every other result file untouched and writes the same table."""
    study = study_in(tmp_path)
    rows = run_study(study, None, progress=None)
    files = sorted(study.point_dir.glob("*.json"))
    before = {path: (path.stat().st_mtime_ns, path.read_text()) for path in files}
    thin = [i for i, p in enumerate(study.points) if p["layer"] == "thin" and p["eps"] == 1e-3]
    immersed = [
        i
        for i, p in enumerate(study.points)
        if p["layer"] == "immersed" and p["eps"] == 1e-2 and p["delta"] == 0.5
    ]
    removed = [thin[2], *immersed]
    for i in removed:
        (study.point_dir / f"{study.key(study.points[i])}.json").unlink()
    kept = [path for path in files if path.exists()]
    assert len(kept) == 13
    calls = counting_solves(monkeypatch)
    lines = []
    again = run_study(study, None, progress=lines.append)
    assert len(calls) == 2 and len(lines) == 3
    assert all((p.stat().st_mtime_ns, p.read_text()) == before[p] for p in kept)
    assert [row_text(row) for row in again] == [row_text(row) for row in rows]


def summaries(results):
    """The JSON of results' summaries without their provenance (the date differs)."""
    texts = []
    for result in results:
        summary = result.summary()
        summary.pop("provenance")
        texts.append(json.dumps(summary, sort_keys=True))
    return texts


@pytest.mark.serial
def test_physical_inputs_share_a_normal_motion_across_spin_not_angle(monkeypatch):
    """A steel sphere on glass through glycerol at 30 degrees, spinning at 0 and 200 rad/s:
    one key (the materials are in the compliance, so in the key), one integration, and the
    summaries of collide alone. At another angle the normal speed V0 = |v| cos(angle), and
    with it St and eps, changes: another key."""
    calls = counting_solves(monkeypatch)
    physical = from_presets(
        sphere="steel", wall="glass", liquid="glycerol_80", radius=3e-3, speed=0.3,
        layer_thickness=1e-4, angle=30.0,
    )  # fmt: skip
    inputs = [replace(physical, spin=spin) for spin in (0.0, 200.0)]
    config = RunConfig.from_settings(nodes=60)
    assert len({normal_key(p, config) for p in inputs}) == 1
    assert normal_key(replace(physical, angle=40.0), config) != normal_key(physical, config)
    normals = SharedNormals()
    shared = [collide(p, config, normals=normals) for p in inputs]
    assert normals.solved == len(calls) == 1
    assert summaries(shared) == summaries(collide(p, config) for p in inputs)
    assert shared[0].tangential.e_t != shared[1].tangential.e_t  # the spin acts


@pytest.mark.serial
def test_a_closed_film_is_shared_and_each_refined_grid_solved_once(monkeypatch):
    """The film closing on the first grid (30 nodes; made to close there) is raised again for
    the second collision without an integration, and the refined grid's (60 nodes) motion is
    shared: 2 integrations for 2 collisions on 2 grids, each the collision collide gives."""
    solve = ehdfem.collision.solve_normal
    grids = []

    def closing_on_30(params, compliance, *args):
        grids.append(len(compliance.radii))
        if len(compliance.radii) == 30:
            raise FilmClosedError("film closed at T = 1: made to close on 30 nodes")
        return solve(params, compliance, *args)

    monkeypatch.setattr(ehdfem.collision, "solve_normal", closing_on_30)
    inputs = [CollisionParameters(St=10.0, eps=1e-2, angle=angle) for angle in (20.0, 35.0)]
    config = RunConfig.from_settings(nodes=30, refinements=1)
    normals = SharedNormals()
    shared = [collide(p, config, normals=normals) for p in inputs]
    assert grids == [30, 60] and normals.solved == 2
    assert all(result.normal.radii.size == 60 for result in shared)
    assert summaries(shared) == summaries(collide(p, config) for p in inputs)
    unrefined = RunConfig.from_settings(nodes=30, refinements=0)
    with pytest.raises(FilmClosedError, match="made to close"):  # no refinement left
        collide(inputs[1], unrefined, normals=normals)
    assert normals.solved == 2


@dataclass(frozen=True)
class LabelledForce(ConstantForce):
    """A constant force with a label that may be a function (which has no digest)."""

    label: object = None


@pytest.mark.serial
def test_a_problem_without_a_digest_is_solved_each_time():
    """A force holding a function gives the problem no digest: each collision integrates its
    own normal motion; with a plain label the two share theirs."""
    params = [CollisionParameters(St=5.0, eps=1e-2, angle=angle) for angle in (20.0, 35.0)]
    config = RunConfig.from_settings(nodes=40)
    for label, solved in ((lambda: 0.0, 2), ("plain", 1)):
        forces = (LabelledForce(0.01, label),)
        normals = SharedNormals()
        for p in params:
            collide(p, config, forces=forces, normals=normals)
        assert normals.solved == solved


@pytest.mark.slow
def test_sweep_on_all_ranks_shares_the_normals_as_one_process():
    """Run under mpirun -n 2 too: the table of the grid from all ranks equals the one from one
    process, and the ranks together integrated 6 normal motions."""
    comm = MPI.COMM_WORLD
    folder = Path(comm.bcast(tempfile.mkdtemp(prefix="ehdfem-shared-") if comm.rank == 0 else None))
    for name in ("parallel", "serial"):
        (folder / name).mkdir(exist_ok=True)
    if comm.rank == 0:
        study_in(folder / "parallel")
    comm.Barrier()
    study = Study(folder / "parallel" / "shared.toml")
    counted = []
    solve = ehdfem.collision.solve_normal
    ehdfem.collision.solve_normal = lambda *a, **k: counted.append(1) or solve(*a, **k)
    try:
        parallel = run_study(study, comm, progress=None)
    finally:
        ehdfem.collision.solve_normal = solve
    assert comm.allreduce(len(counted)) == NORMALS
    if comm.rank == 0:
        serial = run_study(study_in(folder / "serial"), None, progress=None)
        assert [row_text(r) for r in parallel] == [row_text(r) for r in serial]
        assert len(serial) == 16
    comm.Barrier()
