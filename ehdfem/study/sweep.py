"""Parameter studies over MPI ranks: resumable result tables and the critical Stokes number.

A study is a TOML file (see studies/*.toml):

    [grid]                        # every combination is one point
    St = {geomspace = [3, 1000, 12]}   # or a list, or {linspace = [a, b, n]}
    eps = [1e-5, 1e-3]
    layer = ["thin"]              # any CollisionParameters field, a cavitation model or a
    p_cav = [-10.0, -1.0]         # viscosity law by name (ehdfem.film.cavitation.MODELS,
    alpha = [0.0, 3.0]            # ehdfem.film.viscosity.LAWS) or any of their constants
    model = ["halfspace", "fem"]  # or any run setting (ehdfem.config.setting_names)
    [run]                         # run settings held fixed, e.g.
    tangential = "lubrication"
    [numerics]                    # the numerics among them (also allowed in [run])
    nodes = 240
    rtol = 5e-5
    [output]
    table = "results/example.csv" # relative to the study file

or, with physical inputs (SI), a ``[physical]`` table of
:class:`ehdfem.inputs.scales.PhysicalCollision` fields held fixed, and a ``[grid]`` over
PhysicalCollision fields (plus run settings):

    [physical]
    sphere = "steel"              # a preset name, or a table of values, with an optional preset
    wall = {young_modulus = 3e9, poisson_ratio = 0.35, density = 1200}
    liquid = {preset = "glycerol_80", viscosity = 0.05}
    radius = 6.35e-3
    layer_thickness = 3e-4
    [grid]
    speed = {geomspace = [0.05, 2.0, 8]}
    angle = [0.0, 30.0]

Every row gives the point's run settings (:meth:`ehdfem.config.RunConfig.settings`)
and the outputs of :mod:`ehdfem.outputs.registry`; those of a physical study also give St, eps,
delta, P_cav and the SI results (``*_m``, ``*_N``, ...).
Points are claimed dynamically by the ranks, in groups that share their normal motion
(:func:`normal_groups`: an exclusive file per group; a point alone where nothing is shared), so
ranks that draw cheap groups take more of them; a group's rank integrates each of its normal
motions once and solves each point's tangential motion on it (docs/studies.md, "Shared normal
motions"). Each finished point is written atomically as its own JSON file
next to the table (``<table>.points/``); a run that is killed and started again skips the
points already there, so nothing finished is lost or duplicated. The table (CSV, one row per
point with inputs, outputs, status, seconds, code version and git commit) is rewritten
atomically from the point files at the end of every run, with its sidecar
``<table stem>.provenance.json``: the provenance of the run (version, git commit, date,
libraries, command line, MPI size), the [physical] table and every input and run setting held
fixed, defaults included (docs/studies.md). All inputs and outputs are dimensionless (DSH
scales), but for the SI columns of a physical study.
"""

from __future__ import annotations

import csv
import hashlib
import io
import itertools
import json
import math
import os
import socket
import time
import tomllib
from dataclasses import asdict, fields, replace
from pathlib import Path

import numpy as np

from .. import checks
from ..collision import SharedNormals, collide, elasticity, film_radii, normal_key
from ..config import Numerics, RunConfig, setting_names
from ..console.progress import Counter
from ..console.progress import progress as progress_bar
from ..inputs.scales import CollisionParameters, PhysicalCollision, from_presets
from ..motion.normal import NormalSolverError
from ..motion.timestepping import IntegratorOptions
from ..outputs import provenance
from ..outputs import registry as outputs
from ..settings import described, flat_names
from ..version import __version__
from .threshold import threshold

PHYSICAL_FIELDS = tuple(f.name for f in fields(PhysicalCollision))
PHYSICAL_REQUIRED = ("sphere", "wall", "liquid", "radius", "speed", "layer_thickness")
SCALED_GROUPS = ("St", "eps", "delta", "p_cav")  # given in the rows of a physical study
NUMERICS = tuple(f.name for cls in (Numerics, IntegratorOptions) for f in described(cls))


class Study:
    """A parsed study file: the points (dicts of CollisionParameters fields, or with a
    [physical] table of PhysicalCollision fields, and of run settings), the fixed physical
    inputs (None for a dimensionless study), the fixed run settings ([run] and [numerics])
    and the table path."""

    def __init__(self, path: str | Path):
        self.path = Path(path)
        if not self.path.is_file():
            raise checks.InputError(f"study file {str(self.path)!r} does not exist")
        try:
            spec = tomllib.loads(self.path.read_text())
        except tomllib.TOMLDecodeError as err:
            raise checks.InputError(f"study file {self.path}: {err}") from err
        _known_keys("study file", spec, ("name", "grid", "physical", "run", "numerics", "output"))
        grid = spec.get("grid", {})
        self.physical = spec.get("physical")
        _check_grid(grid, self.physical)
        self.name = spec.get("name", self.path.stem)
        numerics = spec.get("numerics", {})
        _known_keys("[numerics]", numerics, NUMERICS)
        _known_keys("[run]", spec.get("run", {}), setting_names())
        self.run = {**spec.get("run", {}), **numerics}
        output = spec.get("output", {})
        _known_keys("[output]", output, ("table",))
        self.table = self.path.parent / output.get("table", f"results/{self.path.stem}.csv")
        axes = {name: _values(f"grid.{name}", value) for name, value in grid.items()}
        self.points = [
            dict(zip(axes, combo, strict=True)) for combo in itertools.product(*axes.values())
        ]
        self.stokes_numbers = []  # validate every point before any work starts
        for point in self.points:
            inputs = self.inputs(point)
            scaled = inputs.dimensionless() if self.physical is not None else inputs
            self.stokes_numbers.append(scaled.St)
            self.config(point).check_inputs(scaled)

    @property
    def point_dir(self) -> Path:
        return self.table.with_name(self.table.name + ".points")

    @property
    def provenance_file(self) -> Path:
        """The table's sidecar: results/example.csv -> results/example.provenance.json."""
        return self.table.with_suffix(".provenance.json")

    def fixed(self) -> dict:
        """Every input and run setting that the grid does not sweep, with the value its points
        used, whether the study file gives it or it is a default: "parameters" (every
        CollisionParameters field, DSH scales; P_cav None for no limit) or "physical" (every
        PhysicalCollision field, SI, the materials and liquid with all their values), and
        "run" (the flat run settings)."""
        first = self.points[0]
        inputs = self.inputs(first)
        values = asdict(inputs) if self.physical else inputs.settings(written=True)
        settings = self.config(first).settings()
        return {
            "parameters" if self.physical is None else "physical": {
                k: v for k, v in values.items() if k not in first
            },
            "run": {k: v for k, v in settings.items() if k not in first},
        }

    def inputs(self, point: dict) -> CollisionParameters | PhysicalCollision:
        """The collision inputs of ``point``: dimensionless, or the [physical] table's values
        (SI) with the point's."""
        if self.physical is None:
            return _parameters(point)
        values = {k: v for k, v in {**self.physical, **point}.items() if k not in setting_names()}
        return from_presets(**values)

    def config(self, point: dict) -> RunConfig:
        """The run configuration of ``point``: the fixed run settings with the point's."""
        swept = {k: v for k, v in point.items() if k in setting_names()}
        return RunConfig.from_settings(**{**self.run, **swept})

    def key(self, point: dict) -> str:
        """The name of ``point``'s result file: a hash of its inputs, with the [physical] table
        and the fixed run settings ([run], [numerics]) where there are any, so that a changed
        table or setting is not mistaken for finished points."""
        fixed = {"[physical]": self.physical, "[run]": self.run}
        return point_key({**point, **{k: v for k, v in fixed.items() if v}})


def _check_grid(grid: dict, physical: dict | None) -> None:
    """Refuse unknown or missing keys: a dimensionless grid needs St and eps; with a
    [physical] table, the grid is over PhysicalCollision fields and the two tables together
    need the sphere, wall, liquid, radius, speed and layer thickness."""
    if physical is None:
        _known_keys("[grid]", grid, grid_keys())
        for name in ("St", "eps"):
            if name not in grid:
                raise checks.InputError(f"[grid] needs {name}")
        return
    if not isinstance(physical, dict):
        raise checks.InputError("[physical] must be a table of PhysicalCollision fields")
    _known_keys("[physical]", physical, PHYSICAL_FIELDS)
    _known_keys("[grid] (with [physical])", grid, (*PHYSICAL_FIELDS, *setting_names()))
    missing = [name for name in PHYSICAL_REQUIRED if name not in physical and name not in grid]
    if missing:
        raise checks.InputError(f"[physical] (or [grid]) needs {', '.join(missing)}")


def _known_keys(where, table, allowed):
    unknown = sorted(set(table) - set(allowed))
    if unknown:
        raise checks.InputError(
            f"{where}: unknown key(s) {', '.join(unknown)}; allowed: {', '.join(allowed)}"
        )


def _values(name, value):
    """A grid axis: a list, a scalar, or {geomspace|linspace = [start, stop, count]}."""
    if isinstance(value, dict):
        if len(value) != 1 or next(iter(value)) not in ("geomspace", "linspace"):
            raise checks.InputError(
                f"{name}: use a list or {{geomspace = [a, b, n]}} / {{linspace = [a, b, n]}}"
            )
        kind, args = next(iter(value.items()))
        if not (isinstance(args, list) and len(args) == 3):
            raise checks.InputError(f"{name}.{kind} needs [start, stop, count]")
        count = checks.integer(f"{name}.{kind} count", args[2], lower=1, upper=100000)
        return [float(v) for v in getattr(np, kind)(args[0], args[1], count)]
    return list(value) if isinstance(value, list) else [value]


def parameter_names() -> tuple[str, ...]:
    """The keys of the dimensionless inputs: CollisionParameters' flat settings (its fields,
    each component's name and the fields of every registered component of its role)."""
    return flat_names(CollisionParameters)


def grid_keys() -> tuple[str, ...]:
    """The keys a dimensionless [grid] takes: the inputs' and the run settings."""
    return (*parameter_names(), *setting_names())


def _parameters(point) -> CollisionParameters:
    names = parameter_names()
    values = {k: v for k, v in point.items() if k in names}
    return CollisionParameters.from_settings(read=True, **values)


def point_key(point) -> str:
    """A stable name for a point (hash of its inputs)."""
    text = json.dumps(point, sort_keys=True, default=str)
    return hashlib.sha1(text.encode()).hexdigest()[:16]


def write_atomic(path: Path, text: str) -> None:
    """Write to a temporary file in the same folder, fsync, then rename over ``path``."""
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    with tmp.open("w") as f:
        f.write(text)
        f.flush()
        os.fsync(f.fileno())
    os.replace(tmp, path)


def run_point(study: Study, point: dict, normals: SharedNormals | None = None) -> dict:
    """One collision; failures are recorded with their reason instead of stopping the study.
    ``normals``: the normal motions its group solved before
    (:class:`ehdfem.collision.SharedNormals`; None: solved here); the row is the same either
    way. ``seconds``: the wall time of this point's collision (its solids, its tangential
    motion, and its normal motion where it was integrated for this point, not where it was
    shared)."""
    start = time.perf_counter()
    config = study.config(point)
    row = {**point, **{k: v for k, v in config.settings().items() if k not in point}}
    try:
        result = collide(study.inputs(point), config, normals=normals)
        summary = result.summary()
        if study.physical is not None:
            row.update({name: summary.get(name) for name in SCALED_GROUPS})
        row.update(_output_columns(study, summary))
        row["status"] = "ok:" + summary["status"]
    except (NormalSolverError, checks.InputError, np.linalg.LinAlgError) as err:
        row.update(_output_columns(study, {}))
        row["status"] = f"failed: {type(err).__name__}: {err}"
    row["seconds"] = round(time.perf_counter() - start, 3)
    row["version"] = __version__
    row["commit"] = provenance.commit_text()
    return row


def _output_columns(study: Study, summary: dict) -> dict:
    """A row's outputs from a summary: every output of :mod:`ehdfem.outputs.registry` (scaled;
    None where the summary has none) and, for a physical study, every SI value."""
    columns = {name: summary.get(name) for name in outputs.names()}
    if study.physical is not None:
        si = summary.get("si", {})
        columns.update({key: si.get(key) for key in outputs.si_keys()})
    return columns


def run_study(study: Study, comm=None, progress=print) -> list[dict]:
    """Run every point not yet in the study's point folder, spread over the ranks of ``comm``
    (mpi4py communicator or None), then write the table. Returns the rows (on every rank).
    The points run in the groups of :func:`normal_groups`, each group on one rank, which
    integrates each of its normal motions once (:class:`ehdfem.collision.SharedNormals`).
    ``progress(line)`` reports each finished point (:func:`progress_line`);
    on a terminal, rank 0 also draws a bar of the points done with rate and time left
    (:mod:`ehdfem.console.progress`)."""
    rank = comm.rank if comm is not None else 0
    points_dir = study.point_dir
    claims = points_dir / "claims"
    if rank == 0:
        claims.mkdir(parents=True, exist_ok=True)
        for stale in claims.iterdir():  # claims of a killed run: their points were not finished
            stale.unlink()
    if comm is not None:
        comm.Barrier()
    groups = normal_groups(study, comm)
    total, keys = len(study.points), {study.key(point) for point in study.points}
    with Counter(
        total, f"sweep {study.name}", finished_points(points_dir, keys), unit="point"
    ) as bar:
        for name, members in groups:
            normals = SharedNormals()
            for i, row, shared in _claim_and_run(study, name, members, claims, normals):
                finished = finished_points(points_dir, keys)
                bar.advance_to(finished)
                if progress is not None:
                    with bar.paused():
                        line = progress_line(finished, total, rank, study.points[i], row, shared)
                        progress(line)
    if comm is not None:
        comm.Barrier()
    rows = collect(study)
    if rank == 0:
        write_table(study, rows)
    return rows


def normal_groups(study: Study, comm=None) -> list[tuple[str, list[int]]]:
    """The unfinished points (indices into ``study.points``) in groups of equal
    :func:`ehdfem.collision.normal_key` (the digest of the first normal problem their
    collisions solve), as (name, indices): the name, the key's first 16 digits, names the
    group's claim file; each group's points in the study's order, the groups by their
    largest St, largest first (the costly ones first). A point of the FE model, or whose key
    is None or fails, is a group of its own named by its point key (:meth:`Study.key`): its
    key would cost a build of its solids, as much as its own collision's. The keys, of a
    half-space compliance each (some 5 ms at 240 nodes), are computed by the ranks of
    ``comm`` in turn and gathered, for the points rank 0 found unfinished (on a terminal rank
    0 shows a bar over its share: the DEM table's 2912 keys take some 40 s on 2 ranks)."""
    rank, size = (comm.rank, comm.size) if comm is not None else (0, 1)
    pending = [i for i, point in enumerate(study.points) if not _result_file(study, point).exists()]
    if comm is not None:
        pending = comm.bcast(pending)
    mine = progress_bar(pending[rank::size], desc=f"sweep {study.name}: normal problems")
    keys = {i: _normal_key(study, study.points[i]) for i in mine}
    if comm is not None:
        keys = {i: key for part in comm.allgather(keys) for i, key in part.items()}
    groups: dict[str, list[int]] = {}
    for i in pending:
        name = keys[i][:16] if keys[i] is not None else study.key(study.points[i])
        groups.setdefault(name, []).append(i)
    return sorted(groups.items(), key=lambda g: -max(study.stokes_numbers[i] for i in g[1]))


def _normal_key(study: Study, point: dict) -> str | None:
    """:func:`ehdfem.collision.normal_key` of a half-space point; None for the FE model and
    where it fails (the point's collision then records the failure)."""
    config = study.config(point)
    if config.model != "halfspace":
        return None
    try:
        return normal_key(study.inputs(point), config)
    except (NormalSolverError, checks.InputError, np.linalg.LinAlgError):
        return None


def _result_file(study: Study, point: dict) -> Path:
    """The result file of a finished point: <table>.points/<point key>.json."""
    return study.point_dir / f"{study.key(point)}.json"


def _claim_and_run(study: Study, name: str, members: list[int], claims: Path, normals):
    """Run the unfinished points ``members`` of the group ``name`` (:func:`normal_groups`) with
    the shared normal motions ``normals``, writing each result file as it finishes, unless the
    group is finished or claimed by another rank (then nothing): the claim is an exclusive
    file in ``claims``, removed when done. Yields (index, row, whether its normal motion was
    shared) for each point run."""
    if all(_result_file(study, study.points[i]).exists() for i in members):
        return
    try:
        fd = os.open(claims / name, os.O_CREAT | os.O_EXCL | os.O_WRONLY)
    except FileExistsError:
        return
    os.write(fd, f"{socket.gethostname()}:{os.getpid()}".encode())
    os.close(fd)
    try:
        for i in members:
            done = _result_file(study, study.points[i])
            if done.exists():
                continue
            solved = normals.solved
            row = run_point(study, study.points[i], normals)
            write_atomic(done, json.dumps(row))
            yield i, row, normals.solved == solved
    finally:
        (claims / name).unlink(missing_ok=True)


def finished_points(points_dir: Path, keys: set[str]) -> int:
    """How many of the points named ``keys`` are finished (have their result file in
    ``points_dir``, which may also hold the points of an earlier grid or earlier fixed
    settings: those are not counted)."""
    return len(keys.intersection(path.stem for path in points_dir.glob("*.json")))


def progress_line(
    finished: int, total: int, rank: int, point: dict, row: dict, shared: bool = False
) -> str:
    """``[done/total] rank r: St=3.16, eps=0.001 -> ok:rebound e_n=0.5432 (1.2 s)``: numbers to
    four significant digits; ``(0.03 s, normal shared)`` where the point's normal motion was
    that of an earlier point of its group."""
    inputs = ", ".join(f"{k}={_short(v)}" for k, v in point.items())
    note = ", normal shared" if shared else ""
    return (
        f"[{finished}/{total}] rank {rank}: {inputs} -> {row['status']} "
        f"e_n={_short(row['e_n'])} ({row['seconds']:.3g} s{note})"
    )


def _short(value) -> str:
    """A float to four significant digits; anything else as it is."""
    return f"{value:.4g}" if isinstance(value, float) else str(value)


def collect(study: Study) -> list[dict]:
    """The finished rows, in the order of the study's points (missing points are skipped)."""
    rows = []
    for point in study.points:
        path = _result_file(study, point)
        if path.exists():
            rows.append(json.loads(path.read_text()))
    return rows


def write_table(study: Study, rows: list[dict]) -> Path:
    """Write the study's CSV table atomically, and beside it its sidecar
    (:attr:`Study.provenance_file`): the study's name and file, the swept names, the
    provenance of this run (:func:`ehdfem.outputs.provenance.record`), the [physical] table as
    written and every input and run setting held fixed, defaults included
    (:meth:`Study.fixed`)."""
    sidecar = {
        "study": study.name,
        "study_file": str(study.path),
        "table": str(study.table),
        "rows": len(rows),
        "swept": list(study.points[0]),
        "provenance": provenance.record(),
        "physical_table": study.physical,
        "fixed": study.fixed(),
    }
    table = write_csv(study.table, rows, list(grid_keys()))
    write_atomic(study.provenance_file, json.dumps(sidecar, indent=2) + "\n")
    return table


def write_csv(path: Path, rows: list[dict], empty_header=()) -> Path:
    """Write rows (dicts; the header is the union of their keys) to a CSV file atomically."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    names = list(dict.fromkeys(itertools.chain.from_iterable(rows))) if rows else list(empty_header)
    text = io.StringIO()
    writer = csv.DictWriter(text, fieldnames=names)
    writer.writeheader()
    writer.writerows(rows)
    write_atomic(path, text.getvalue())
    return path


class ResultTable:
    """A study script's rows in a CSV, keyed by ``keys`` (column names): ``get`` finds a
    finished row, ``add`` appends one and rewrites the CSV atomically, so a script that is
    stopped and started again computes only what is missing. Values are kept as strings."""

    def __init__(self, path, keys):
        self.path, self.keys = Path(path), tuple(keys)
        self.rows = list(csv.DictReader(self.path.open())) if self.path.exists() else []

    def _key(self, row):
        return tuple(str(row[k]) for k in self.keys)

    def get(self, **key):
        wanted = self._key(key)
        return next((r for r in self.rows if self._key(r) == wanted), None)

    def add(self, row):
        self.rows.append({k: str(v) for k, v in row.items()})
        write_csv(self.path, self.rows)
        return self.rows[-1]


def computed_or_loaded(path: Path, compute, load: bool) -> list[dict]:
    """The rows of a study script: read from the CSV ``path`` when ``load`` (to redraw figures),
    otherwise ``compute()`` them and write them there atomically."""
    if load:
        with Path(path).open() as f:
            return list(csv.DictReader(f))
    rows = compute()
    write_csv(path, rows)
    return rows


def study_script(root: Path, name: str, compute, plot, load: bool) -> None:
    """The main of a study script: rows in root/studies/results/NAME.csv (computed, or read
    back when ``load``), figure root/docs/figures/NAME.png by ``plot(rows, path)``."""
    table = root / "studies" / "results" / f"{name}.csv"
    figure = root / "docs" / "figures" / f"{name}.png"
    plot(computed_or_loaded(table, compute, load), figure)
    print(f"wrote {table} and {figure}")


def critical_stokes(
    params: CollisionParameters,
    bracket=(1.0, 1000.0),
    rtol: float = 1e-3,
    config: RunConfig | None = None,
    progress_label: str | None = None,
) -> dict:
    """St_c: the smallest St at which the sphere leaves the layer (e_n > 0), by bisection in
    log St on the outcome of the collision (other inputs from ``params``, computed as
    ``config`` says). Returns St_c, the final bracket [sticks, rebounds], the relative
    tolerance and the number of collisions. ``progress_label``: label of a progress bar over
    the collisions (terminal only; None: no bar).

    The film grid is chosen once, for the top of the bracket (the widest contact), and the
    compliance is built once on it: the FE solids are factorised a single time."""
    lo, hi = (
        checks.positive("bracket low", bracket[0]),
        checks.positive("bracket high", bracket[1]),
    )
    if lo >= hi:
        raise checks.InputError(
            f"bracket = {bracket[0]:g} .. {bracket[1]:g} must be increasing", "bracket"
        )
    checks.number("bracket_rtol", rtol, lower=1e-8, upper=0.5)
    widest = replace(params, St=4 * hi)
    config = RunConfig() if config is None else config
    compliance = elasticity(widest, film_radii(widest, config.numerics.nodes), config)

    def rebounds(St):
        return collide(replace(params, St=St), config, compliance=compliance).normal.e_n

    try:
        lo, hi, evaluations = threshold(rebounds, lo, hi, rtol, "St", (1e-3, 1e7), progress_label)
    finally:
        compliance.close()
    return {
        "St_c": math.sqrt(lo * hi),
        "bracket": [lo, hi],
        "bracket_rtol": rtol,
        "collisions": evaluations,
    }


def critical_speed(
    physical: PhysicalCollision,
    bracket=(0.01, 10.0),
    rtol: float = 0.01,
    config: RunConfig | None = None,
    rebounds=None,
    progress_label: str | None = None,
) -> dict:
    """The critical impact speed [m/s] of a physical collision (its other inputs fixed; eps,
    P_cav and alpha change with the speed) and St_c, the Stokes number there, by bisection in
    log speed on the rebound outcome. ``rebounds(speed)``: the outcome (default: a collision
    computed as ``config`` says; pass a cached one to resume a study). ``progress_label``: as
    for :func:`critical_stokes`."""
    checks.number("bracket_rtol", rtol, lower=1e-8, upper=0.5)
    lo, hi = (
        checks.positive("bracket low", bracket[0]),
        checks.positive("bracket high", bracket[1]),
    )
    if rebounds is None:

        def rebounds(speed):
            result = collide(replace(physical, speed=speed), config)
            result.compliance.close()
            return result.normal.e_n

    limits = (1e-4, 1e3)
    lo, hi, evaluations = threshold(rebounds, lo, hi, rtol, "speed [m/s]", limits, progress_label)
    speed = math.sqrt(lo * hi)
    return {
        "speed": speed,
        "St_c": replace(physical, speed=speed).dimensionless().St,
        "bracket": [lo, hi],
        "bracket_rtol": rtol,
        "collisions": evaluations,
    }
