"""Parameter studies over MPI ranks: resumable result tables and the critical Stokes number.

A study is a TOML file (see studies/*.toml):

    [grid]                        # every combination is one point
    St = {geomspace = [3, 1000, 12]}   # or a list, or {linspace = [a, b, n]}
    eps = [1e-5, 1e-3]
    layer = ["thin"]              # any CollisionParameters field, plus "tangential", e.g.
    cavitation = ["truncate", "mass-conserving"]
    viscosity = ["barus"]         # with alpha (scaled), see ehdfem.viscosity
    [numerics]
    nodes = 240
    rtol = 5e-5
    [output]
    table = "results/example.csv" # relative to the study file

Points are claimed dynamically by the ranks (an exclusive file per point), so ranks that draw
cheap points take more of them. Each finished point is written atomically as its own JSON file
next to the table (``<table>.points/``); a run that is killed and started again skips the
points already there, so nothing finished is lost or duplicated. The table (CSV, one row per
point with inputs, outputs, status, seconds and code version) is rewritten atomically from the
point files at the end of every run. All inputs and outputs are dimensionless (DSH scales).
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
from dataclasses import fields, replace
from pathlib import Path

import numpy as np

from . import cavitation, checks
from .collision import DEFAULT_NODES, TANGENTIAL_MODELS, collide, elasticity, film_radii
from .normal import NormalSolverError
from .scales import CollisionParameters, PhysicalCollision
from .timestepping import IntegratorOptions
from .version import __version__

PARAMETERS = tuple(f.name for f in fields(CollisionParameters))
GRID_KEYS = (*PARAMETERS, "tangential")
NUMERICS = ("nodes", "rtol")
OUTPUTS = (
    "rebound",
    "status",
    "e_n",
    "max_rebound_velocity",
    "min_film_thickness",
    "max_force",
    "contact_time",
    "max_compression",
    "e_t",
    "spin_change",
    "energy_error",
    "film_nodes",
)


class Study:
    """A parsed study file: the points (dicts of CollisionParameters fields plus "tangential"),
    the numerics and the table path."""

    def __init__(self, path: str | Path):
        self.path = Path(path)
        if not self.path.is_file():
            raise checks.InputError(f"study file {str(self.path)!r} does not exist")
        try:
            spec = tomllib.loads(self.path.read_text())
        except tomllib.TOMLDecodeError as err:
            raise checks.InputError(f"study file {self.path}: {err}") from err
        _known_keys("study file", spec, ("name", "grid", "numerics", "output"))
        grid = spec.get("grid", {})
        _known_keys("[grid]", grid, GRID_KEYS)
        for name in ("St", "eps"):
            if name not in grid:
                raise checks.InputError(f"[grid] needs {name}")
        self.name = spec.get("name", self.path.stem)
        numerics = spec.get("numerics", {})
        _known_keys("[numerics]", numerics, NUMERICS)
        self.nodes = checks.integer(
            "numerics.nodes", numerics.get("nodes", DEFAULT_NODES), lower=20
        )
        self.options = IntegratorOptions(rtol=numerics.get("rtol", IntegratorOptions.rtol))
        output = spec.get("output", {})
        _known_keys("[output]", output, ("table",))
        self.table = self.path.parent / output.get("table", f"results/{self.path.stem}.csv")
        axes = {name: _values(f"grid.{name}", value) for name, value in grid.items()}
        self.points = [
            dict(zip(axes, combo, strict=True)) for combo in itertools.product(*axes.values())
        ]
        for point in self.points:  # validate every point before any work starts
            _parameters(point)
            checks.choice("grid.tangential", point.get("tangential", "couette"), TANGENTIAL_MODELS)

    @property
    def point_dir(self) -> Path:
        return self.table.with_name(self.table.name + ".points")


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


def _parameters(point) -> CollisionParameters:
    values = {k: v for k, v in point.items() if k in PARAMETERS}
    if "p_cav" in values:
        values["p_cav"] = cavitation.parse_suction_limit(values["p_cav"])
    return CollisionParameters(**values)


def point_key(point) -> str:
    """A stable name for a point (hash of its inputs)."""
    text = json.dumps(point, sort_keys=True, default=str)
    return hashlib.sha1(text.encode()).hexdigest()[:16]


def _write_atomic(path: Path, text: str) -> None:
    """Write to a temporary file in the same folder, fsync, then rename over ``path``."""
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    with tmp.open("w") as f:
        f.write(text)
        f.flush()
        os.fsync(f.fileno())
    os.replace(tmp, path)


def run_point(study: Study, point: dict) -> dict:
    """One collision; failures are recorded with their reason instead of stopping the study."""
    start = time.perf_counter()
    row = {**point}
    try:
        result = collide(
            _parameters(point),
            nodes=study.nodes,
            options=study.options,
            tangential=point.get("tangential", "couette"),
        )
        summary = result.summary()
        row.update({name: summary.get(name) for name in OUTPUTS})
        row["status"] = "ok:" + summary["status"]
    except (NormalSolverError, checks.InputError, np.linalg.LinAlgError) as err:
        row.update({name: None for name in OUTPUTS})
        row["status"] = f"failed: {type(err).__name__}: {err}"
    row["seconds"] = round(time.perf_counter() - start, 3)
    row["version"] = __version__
    return row


def run_study(study: Study, comm=None, progress=print) -> list[dict]:
    """Run every point not yet in the study's point folder, spread over the ranks of ``comm``
    (mpi4py communicator or None), then write the table. Returns the rows (on every rank)."""
    rank, size = (comm.rank, comm.size) if comm is not None else (0, 1)
    points_dir = study.point_dir
    claims = points_dir / "claims"
    if rank == 0:
        claims.mkdir(parents=True, exist_ok=True)
        for stale in claims.iterdir():  # claims of a killed run: their points were not finished
            stale.unlink()
    if comm is not None:
        comm.Barrier()
    order = sorted(range(len(study.points)), key=lambda i: -study.points[i]["St"])  # costly first
    for i in order:
        point = study.points[i]
        key = point_key(point)
        done = points_dir / f"{key}.json"
        if done.exists():
            continue
        try:
            fd = os.open(claims / key, os.O_CREAT | os.O_EXCL | os.O_WRONLY)
        except FileExistsError:
            continue
        os.write(fd, f"{socket.gethostname()}:{os.getpid()}".encode())
        os.close(fd)
        row = run_point(study, point)
        _write_atomic(done, json.dumps(row))
        (claims / key).unlink(missing_ok=True)
        finished = sum(1 for _ in points_dir.glob("*.json"))
        if progress is not None:
            progress(
                f"[{finished}/{len(study.points)}] rank {rank}: "
                + ", ".join(f"{k}={v}" for k, v in point.items())
                + f" -> {row['status']} e_n={row['e_n']} ({row['seconds']} s)"
            )
    if comm is not None:
        comm.Barrier()
    rows = collect(study)
    if rank == 0:
        write_table(study, rows)
    return rows


def collect(study: Study) -> list[dict]:
    """The finished rows, in the order of the study's points (missing points are skipped)."""
    rows = []
    for point in study.points:
        path = study.point_dir / f"{point_key(point)}.json"
        if path.exists():
            rows.append(json.loads(path.read_text()))
    return rows


def write_table(study: Study, rows: list[dict]) -> Path:
    """Write the study's CSV table atomically."""
    return write_csv(study.table, rows, list(GRID_KEYS))


def write_csv(path: Path, rows: list[dict], empty_header=()) -> Path:
    """Write rows (dicts; the header is the union of their keys) to a CSV file atomically."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    names = list(dict.fromkeys(itertools.chain.from_iterable(rows))) if rows else list(empty_header)
    text = io.StringIO()
    writer = csv.DictWriter(text, fieldnames=names)
    writer.writeheader()
    writer.writerows(rows)
    _write_atomic(path, text.getvalue())
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


def critical_stokes(
    params: CollisionParameters,
    bracket=(1.0, 1000.0),
    rtol: float = 1e-3,
    nodes: int = DEFAULT_NODES,
    options: IntegratorOptions | None = None,
    model: str = "halfspace",
) -> dict:
    """St_c: the smallest St at which the sphere leaves the layer (e_n > 0), by bisection in
    log St on the outcome of the collision (other inputs from ``params``). Returns St_c, the
    final bracket [sticks, rebounds], the relative tolerance and the number of collisions.

    The film grid is chosen once, for the top of the bracket (the widest contact), and the
    compliance is built once on it: the FE solids are factorised a single time."""
    lo, hi = (
        checks.positive("bracket low", bracket[0]),
        checks.positive("bracket high", bracket[1]),
    )
    if lo >= hi:
        raise checks.InputError(f"bracket = {bracket} must be increasing")
    checks.number("rtol", rtol, lower=1e-8, upper=0.5)
    values = {name: getattr(params, name) for name in PARAMETERS}
    widest = CollisionParameters(**{**values, "St": 4 * hi})
    compliance = elasticity(widest, film_radii(widest, nodes), model)

    def rebounds(St):
        params = CollisionParameters(**{**values, "St": St})
        return collide(params, options=options, compliance=compliance).normal.rebound

    lo, hi, evaluations = threshold(rebounds, lo, hi, rtol, "St", (1e-3, 1e7))
    return {
        "St_c": math.sqrt(lo * hi),
        "bracket": [lo, hi],
        "rtol": rtol,
        "collisions": evaluations,
    }


def threshold(rebounds, low, high, rtol, name, limits):
    """The bracket [low, high] (relative width <= rtol) of the value of ``name`` where the
    outcome ``rebounds(value)`` turns from False to True, by bisection in log after widening
    the starting bracket by factors of 4 within ``limits``. Returns (low, high, evaluations)."""
    evaluations = 0

    def outcome(value):
        nonlocal evaluations
        evaluations += 1
        return rebounds(value)

    while outcome(low):  # widen until the low end sticks and the high end rebounds
        low, high = low / 4, low
        if low < limits[0]:
            raise checks.InputError(
                f"the sphere rebounds even at {name} = {limits[0]:g}: no critical {name}"
            )
    while not outcome(high):
        low, high = high, high * 4
        if high > limits[1]:
            raise checks.InputError(f"the sphere sticks up to {name} = {limits[1]:g}")
    while high / low - 1 > rtol:
        mid = math.sqrt(low * high)
        low, high = (low, mid) if outcome(mid) else (mid, high)
    return low, high, evaluations


def critical_speed(
    physical: PhysicalCollision,
    bracket=(0.01, 10.0),
    rtol: float = 0.01,
    model: str = "halfspace",
    rebounds=None,
) -> dict:
    """The critical impact speed [m/s] of a physical collision (its other inputs fixed; eps,
    P_cav and alpha change with the speed) and St_c, the Stokes number there, by bisection in
    log speed on the rebound outcome. ``rebounds(speed)``: the outcome (default: a collision
    with ``model``; pass a cached one to resume a study)."""
    checks.number("rtol", rtol, lower=1e-8, upper=0.5)
    lo, hi = (
        checks.positive("bracket low", bracket[0]),
        checks.positive("bracket high", bracket[1]),
    )
    if rebounds is None:

        def rebounds(speed):
            return collide(replace(physical, speed=speed), model=model).normal.rebound

    lo, hi, evaluations = threshold(rebounds, lo, hi, rtol, "speed [m/s]", (1e-4, 1e3))
    speed = math.sqrt(lo * hi)
    return {
        "speed": speed,
        "St_c": replace(physical, speed=speed).dimensionless().St,
        "bracket": [lo, hi],
        "rtol": rtol,
        "collisions": evaluations,
    }
