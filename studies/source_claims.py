"""The source's claims on e_t and the spin change, along the paths a user or experimenter sweeps.

A steel sphere of radius 6.35 mm, 100 cSt silicone oil, thin layer, 30 degrees, vapour
pressure 0 against 1 atm (P_cav = -1 atm x0^2/(mu V0 a)), e_dry = 1. Sweeps (one lever at a
time; what moves with it in brackets):

- speed:     V0 = 0.08-5 m/s, layer x0 = 0.1 mm, on a glass wall (small compliance) and a
             polyurethane wall (large compliance)  [St ~ V0, eps ~ V0, P_cav ~ 1/V0];
- layer:     x0 = 0.03-1 mm at V0 = 1 m/s, both walls  [eps ~ x0^-5/2, delta ~ x0,
             P_cav ~ x0^2; St fixed];
- stiffness: both Young's moduli times k (steel on glass, x0 = 0.1 mm) at V0 = 0.1 and
             5 m/s  [eps ~ 1/k alone];
- St:        the dimensionless sweep, St = 5-1000 at eps = 1e-5, 1e-3, 0.1, delta = 0.01,
             P_cav = -10 (identical solids, Poisson ratio 0.3 for the FE model);
- angle and delta: 10-80 degrees, and delta = 0.003-0.1, at St = 50, eps = 1e-3, P_cav = -10.

Six models on each point: on half-spaces the Couette film, the sliding film and the reduced
models gcb and flat; on FE solids (their defaults: exact sphere gap, squeeze-shear traction)
the Couette and the sliding film. All models of a point share its normal motion on one
elasticity (``with_tangential``), and every point of a group (one set of solids) shares the
film grid of the group's widest collision, with compliances built once on it; the film is not
refined there, so a collision whose film closes is recorded as failed.

Groups run on the MPI ranks (each its own FE solids on one process); each finished point is
written at once to studies/results/source_claims/<group>.csv, so a run that is stopped and
started again computes only what is missing. Rank 0 then writes
studies/results/source_claims.csv and docs/figures/source_claims.png.
Run: mpirun -n 2 .venv/bin/python studies/source_claims.py [--plot-only]   (or bash make.sh claims)
"""

import csv
import math
import sys
import time
from dataclasses import dataclass
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpi4py import MPI  # noqa: E402

from ehdfem.collision import (  # noqa: E402
    collide,
    elasticity,
    film_radii,
    mode_one_elasticity,
    with_tangential,
)
from ehdfem.config import RunConfig
from ehdfem.inputs.presets import MATERIALS  # noqa: E402
from ehdfem.inputs.scales import CollisionParameters, PhysicalCollision, from_presets  # noqa: E402
from ehdfem.motion.normal import NormalSolverError  # noqa: E402
from ehdfem.study.sweep import ResultTable, write_csv  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
RESULTS = ROOT / "studies" / "results"
GROUPS = RESULTS / "source_claims"
TABLE = RESULTS / "source_claims.csv"
FIGURE = ROOT / "docs" / "figures" / "source_claims.png"
NODES = 80
# label: (elasticity, tangential film model)
MODELS = {
    "couette": ("halfspace", "couette"),
    "sliding film": ("halfspace", "lubrication"),
    "gcb": ("halfspace", "gcb"),
    "flat": ("halfspace", "flat"),
    "FE couette": ("fem", "couette"),
    "FE sliding film": ("fem", "lubrication"),
}
REDUCED = ("gcb", "flat")
BASE = dict(sphere="steel", liquid="silicone_oil_100cst", radius=6.35e-3, angle=30.0)
WALLS = {"glass": "small compliance", "polyurethane": "large compliance"}
SPEEDS = np.geomspace(0.08, 5.0, 7)  # m/s
LAYERS = np.geomspace(3e-5, 1e-3, 5)  # m
STIFFNESS = {0.1: np.geomspace(1.0, 1e-4, 4), 5.0: np.geomspace(1.0, 1e-3, 4)}  # V0: factors k
STOKES = np.geomspace(5.0, 1000.0, 7)
ELASTICITY = (1e-5, 1e-3, 0.1)
DIMENSIONLESS = dict(delta=0.01, layer="thin", p_cav=-10.0, angle=30.0)
ANGLES = (10.0, 45.0, 80.0)
DELTAS = (0.003, 0.01, 0.03, 0.1)
SINGLE = dict(St=50.0, eps=1e-3)  # the point of the angle and delta sweeps


@dataclass
class Point:
    """One collision of a sweep: ``sweep`` and ``line`` name the curve, ``variable`` and
    ``value`` its abscissa (SI for physical sweeps), ``inputs`` the collision; ``materials``:
    physical inputs whose sphere and wall the solids take when ``inputs`` are dimensionless."""

    sweep: str
    line: str
    variable: str
    value: float
    inputs: CollisionParameters | PhysicalCollision
    materials: PhysicalCollision | None = None

    def parameters(self) -> CollisionParameters:
        inputs = self.inputs
        return inputs.dimensionless() if isinstance(inputs, PhysicalCollision) else inputs

    @property
    def key(self) -> str:
        return f"{self.sweep}|{self.line}|{self.variable}={self.value:.6g}"


def _physical(**values) -> PhysicalCollision:
    return from_presets(**{**BASE, **values})


def _stiffer(k: float, **values) -> PhysicalCollision:
    """Steel on glass with both Young's moduli times k."""
    scaled = {
        name: {"preset": preset, "young_modulus": k * MATERIALS[preset].young_modulus}
        for name, preset in (("sphere", "steel"), ("wall", "glass"))
    }
    return _physical(**scaled, **values)


def groups() -> dict[str, list[Point]]:
    """The study's points by group: the points of a group share their solids (delta and the
    moduli's ratios) and so one film grid and one set of compliances."""
    out = {}
    for wall, compliance in WALLS.items():
        at_speed = {
            float(v): _physical(wall=wall, speed=float(v), layer_thickness=1e-4) for v in SPEEDS
        }
        out[f"speed {wall}"] = [
            Point("speed", f"{wall} ({compliance})", "V0 [m/s]", v, inputs)
            for v, inputs in at_speed.items()
        ]
        # the same path with the cavitation limit held at its 1 m/s value: St and eps alone
        held = _physical(wall=wall, speed=1.0, layer_thickness=1e-4).dimensionless().p_cav
        out[f"speed {wall} P_cav held"] = [
            Point("speed", f"{wall}, P_cav = {held:.2f} held", "V0 [m/s]", v,
                  inputs.dimensionless().with_settings(p_cav=held), materials=inputs)
            for v, inputs in at_speed.items()
        ]  # fmt: skip
        for x0 in LAYERS:  # one group per thickness: delta sets the FE mesh
            out[f"layer {wall} {x0:.3g}"] = [
                Point(
                    "layer",
                    wall,
                    "x0 [mm]",
                    float(x0 * 1e3),
                    _physical(wall=wall, speed=1.0, layer_thickness=float(x0)),
                )
            ]
    for speed, factors in STIFFNESS.items():
        out[f"stiffness {speed:g}"] = [
            Point(
                "stiffness",
                f"V0 = {speed:g} m/s",
                "k",
                float(k),
                _stiffer(float(k), speed=speed, layer_thickness=1e-4),
            )
            for k in factors
        ]
    for eps in ELASTICITY:
        points = [
            Point(
                "St",
                f"eps = {eps:g}",
                "St",
                float(St),
                CollisionParameters.from_settings(St=float(St), eps=eps, **DIMENSIONLESS),
            )
            for St in STOKES
        ]
        if eps == SINGLE["eps"]:
            points += [
                Point(
                    "angle",
                    "",
                    "angle [deg]",
                    angle,
                    CollisionParameters.from_settings(
                        **{**DIMENSIONLESS, **SINGLE, "angle": angle}
                    ),
                )
                for angle in ANGLES
            ]
        out[f"St {eps:g}"] = points
    for delta in DELTAS:
        out[f"delta {delta:g}"] = [
            Point(
                "delta",
                "",
                "delta",
                delta,
                CollisionParameters.from_settings(**{**DIMENSIONLESS, **SINGLE, "delta": delta}),
            )
        ]
    return out


class Compliances:
    """The half-space and FE compliances (each with its mode-1 compliance) on the film grid
    of a group's widest collision (largest dry Hertz compression); FE solids on this process
    alone. Close to free the factorisations."""

    def __init__(self, points: list[Point]):
        widest = max(points, key=lambda p: _hertz_measure(p.parameters()))
        params = widest.parameters()
        physical = widest.materials
        if isinstance(widest.inputs, PhysicalCollision):
            physical = widest.inputs
        radii = film_radii(params, NODES)
        self.built = {}
        for model in ("halfspace", "fem"):
            config = RunConfig(model=model)
            compliance = elasticity(params, radii, config, physical, comm=MPI.COMM_SELF)
            self.built[model] = (compliance, mode_one_elasticity(params, compliance, physical))

    def close(self):
        for compliance, mode_one in self.built.values():
            mode_one.close()
            if hasattr(compliance, "close"):
                compliance.close()


def _hertz_measure(params: CollisionParameters) -> float:
    """eps St, which orders the dry Hertz compression (eps St)^(2/5)."""
    return params.eps * params.St


def point_rows(point: Point, compliances: Compliances) -> list[dict]:
    """The six models' rows of one point: one normal motion per elasticity, every tangential
    film model on it."""
    params = point.parameters()
    base = {
        "key": point.key, "sweep": point.sweep, "line": point.line,
        "variable": point.variable, "value": point.value, "St": params.St,
        "eps": params.eps, "delta": params.delta, "p_cav": params.p_cav, "angle": params.angle,
    }  # fmt: skip
    rows = []
    for elastic in ("halfspace", "fem"):
        compliance, mode_one = compliances.built[elastic]
        start = time.perf_counter()
        try:
            first = collide(point.inputs, compliance=compliance)
        except NormalSolverError as err:
            for label, (model_elastic, _) in MODELS.items():
                if model_elastic == elastic:
                    rows.append({**base, "model": label, "status": f"failed: {err}"})
            continue
        normal_seconds = time.perf_counter() - start
        for label, (model_elastic, tangential) in MODELS.items():
            if model_elastic != elastic:
                continue
            start = time.perf_counter()
            r = with_tangential(
                first, tangential, mode_one if tangential == "lubrication" else None
            )
            t = r.tangential
            flag = r.superposition.flagged if r.superposition is not None else ""
            rows.append(
                {
                    **base,
                    "model": label,
                    "status": "ok",
                    "rebound": r.normal.rebound,
                    "e_n": r.normal.e_n,
                    "e_t": t.e_t,
                    "spin_change": t.spin_change,
                    "at": t.at,
                    "superposition_flag": flag,
                    "film_nodes": len(r.normal.radii),
                    "seconds": round(normal_seconds + time.perf_counter() - start, 2),
                }
            )
    return rows


def run_group(name: str, points: list[Point]) -> None:
    """Compute the group's missing points into its CSV (resumable)."""
    table = _group_table(name)
    missing = [p for p in points if table.get(key=p.key, model="couette") is None]
    if not missing:
        return
    compliances = Compliances(points)
    try:
        for point in missing:
            rows = point_rows(point, compliances)
            for row in rows:
                table.add(row)
            e_t = " ".join(f"{r['model']}={r.get('e_t', float('nan')):.5f}" for r in rows)
            print(f"[rank {MPI.COMM_WORLD.rank}] {point.key}: {e_t}", flush=True)
    finally:
        compliances.close()


def _group_table(name: str) -> ResultTable:
    """The finished rows of a group, in studies/results/source_claims/<group>.csv."""
    return ResultTable(GROUPS / f"{name.replace(' ', '_')}.csv", ("key", "model"))


def run() -> list[dict]:
    """Every group, spread over the ranks (largest first, each to the least loaded rank);
    returns the merged rows on rank 0 (None on the others)."""
    comm = MPI.COMM_WORLD
    everything = groups()
    load = [0.0] * comm.size
    mine = []
    for name in sorted(everything, key=lambda g: -len(everything[g])):
        rank = int(np.argmin(load))
        load[rank] += len(everything[name])
        if rank == comm.rank:
            mine.append(name)
    if comm.rank == 0:
        GROUPS.mkdir(parents=True, exist_ok=True)
    comm.Barrier()
    for name in mine:
        run_group(name, everything[name])
    comm.Barrier()
    if comm.rank != 0:
        return None
    rows = []
    for name in everything:
        rows += _group_table(name).rows
    write_csv(TABLE, rows)
    return rows


def number(value) -> float:
    return float(value) if value not in (None, "", "None") else math.nan


def curve(rows, sweep, line, model, quantity):
    """(abscissae, values) of one model's rebounds along one line, sorted."""
    sel = sorted(_lines(rows, sweep, model).get(line, []), key=lambda r: float(r["value"]))
    return (
        np.array([float(r["value"]) for r in sel]),
        np.array([number(r[quantity]) for r in sel]),
    )


PANELS = (
    ("speed", "impact speed V0 [m/s]\n(St, eps ~ V0; P_cav ~ 1/V0; x0 = 0.1 mm)"),
    ("layer", "layer x0 [mm] (V0 = 1 m/s)\n(eps ~ x0^-5/2, delta ~ x0, P_cav ~ x0^2)"),
    ("stiffness", "stiffness factor k on both moduli\n(eps ~ 1/k alone; x0 = 0.1 mm)"),
    ("St", "St (delta = 0.01, P_cav = -10)\n(fixed eps)"),
)
STYLES = {
    "couette": ("C0", "-"),
    "sliding film": ("C1", "-"),
    "gcb": ("C2", ":"),
    "flat": ("C4", ":"),
    "FE couette": ("C0", "--"),
    "FE sliding film": ("C1", "--"),
}
MARKERS = ("o", "s", "^", "v")


def plot(rows, figure):
    """1 - e_t (top) and the spin change (bottom) along each physical sweep and the
    dimensionless one: one colour and style per model, one marker per line; rebounds only."""
    fig, axes = plt.subplots(2, len(PANELS), figsize=(19, 8.5))
    for column, (sweep, xlabel) in enumerate(PANELS):
        lines = sorted({r["line"] for r in rows if r["sweep"] == sweep})
        for line, marker in zip(lines, MARKERS, strict=False):
            for model, (colour, style) in STYLES.items():
                for row, quantity in ((0, "e_t"), (1, "spin_change")):
                    x, y = curve(rows, sweep, line, model, quantity)
                    y = 1 - y if quantity == "e_t" else y
                    axes[row, column].loglog(x, y, style, color=colour, marker=marker, ms=3.5)
        axes[1, column].set_xlabel(xlabel, fontsize=8)
        handles = [
            plt.Line2D([], [], color="k", marker=m, ls="", label=line)
            for line, m in zip(lines, MARKERS, strict=False)
        ]
        axes[0, column].legend(handles=handles, fontsize=7)
    models = [plt.Line2D([], [], color=c, ls=s, label=m) for m, (c, s) in STYLES.items()]
    axes[1, 0].legend(handles=models, fontsize=7)
    axes[0, 0].set_ylabel("1 - e_t")
    axes[1, 0].set_ylabel(r"spin change a$\Delta\Omega/U_0$")
    for ax in axes.flat:
        ax.grid(alpha=0.3, which="both")
    fig.suptitle(
        "steel sphere a = 6.35 mm, 100 cSt silicone oil, thin layer, 30 deg; rebounds only "
        f"({NODES} film nodes)"
    )
    fig.tight_layout()
    figure.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(figure, dpi=110)
    plt.close(fig)


# --- Verdicts: each claim of the source's abstract along each parameterisation ---------------

COLUMNS = ("couette", "sliding film", "FE couette", "FE sliding film", "gcb", "flat")
FULL = "FE sliding film"  # the fullest model, which the others are compared with
FLAT_STEP = 0.01  # steps of ln(1 - e_t), ln(spin change) or ln e_n smaller than this are level
QUANTITIES = {  # the variable whose trend is the quantity's (rising with it)
    "e_n": lambda r: math.log(number(r["e_n"])),
    "e_t": lambda r: -math.log(1 - number(r["e_t"])),
    "spin_change": lambda r: math.log(number(r["spin_change"])),
}


def _lines(rows, sweep, model, by="line", keep=None):
    """{line: rows} of one model's rebounds in ``sweep`` whose line name passes ``keep``;
    ``by="St"`` regroups the St sweep's rows by their St (lines of fixed St across eps)."""
    out = {}
    for r in rows:
        if r["sweep"] == sweep and r["model"] == model and r["status"] == "ok":
            if r["rebound"] == "True" and (keep is None or keep(r["line"])):
                out.setdefault(r[by], []).append(r)
    return out


def trend(x, z, name) -> str:
    """ "rises", "falls", "level", or the turning points ("falls, then rises above St 120"),
    of z against x (called ``name``), steps below FLAT_STEP counted as level."""
    order = np.argsort(x)
    x, z = np.asarray(x, float)[order], np.asarray(z, float)[order]
    words = []
    for i, step in enumerate(np.diff(z)):
        if abs(step) < FLAT_STEP:
            continue
        word = "rises" if step > 0 else "falls"
        if not words or words[-1][0] != word:
            words.append((word, x[i]))
    if not words:
        return "level"
    return ", then ".join(
        w if k == 0 else f"{w} above {name} {at:.3g}" for k, (w, at) in enumerate(words)
    )


def _verdict(words: list[str], expected: int) -> str:
    """One cell over the lines' trends: "holds" if every line that is not level goes the
    expected way (+1 rises, -1 falls), "opposite" if every one goes the other way, else the
    trends themselves; level lines are counted."""
    wanted, other = ("rises", "falls") if expected > 0 else ("falls", "rises")
    moving = [w for w in words if w != "level"]
    level = len(words) - len(moving)
    note = f" ({level} of {len(words)} lines level)" if level else ""
    if moving and all(w == wanted for w in moving):
        return "holds" + note
    if moving and all(w == other for w in moving):
        return "opposite" + note
    return "; ".join(sorted(set(words)))


def _named(*words):
    """A line filter: the line's name contains one of ``words``."""
    return lambda line: any(w in line for w in words)


def _physical_speed(line):
    return "held" not in line


# parameterisations: label: (sweep, how rows make lines ("line" or "St"), abscissa, filter)
ALONG_ST = {
    "dimensionless: St at fixed eps, delta, P_cav": ("St", "line", "St", None),
    "speed (St, eps ~ V0; P_cav ~ 1/V0)": ("speed", "line", "St", _physical_speed),
    "speed with P_cav held (St, eps ~ V0)": ("speed", "line", "St", _named("held")),
}
ALONG_EPS = {
    "dimensionless: eps at fixed St, delta, P_cav": ("St", "St", "eps", None),
    "stiffness (eps ~ 1/k alone)": ("stiffness", "line", "eps", None),
    "layer (eps ~ x0^-5/2; delta ~ x0, P_cav ~ x0^2)": ("layer", "line", "eps", None),
}
SMALL, LARGE = _named("1e-05", "glass"), _named("0.1", "polyurethane")
TREND_CLAIMS = (  # claim, quantity, expected sign, parameterisations, which lines
    ("e_n increases with St", "e_n", +1, ALONG_ST, None),
    ("e_n increases with the compliance", "e_n", +1, ALONG_EPS, None),
    ("e_t higher for a larger compliance", "e_t", +1, ALONG_EPS, None),
    ("e_t increases with St at small compliance", "e_t", +1, ALONG_ST, SMALL),
    ("e_t decreases with St at large compliance", "e_t", -1, ALONG_ST, LARGE),
    ("spin change lower for a larger compliance", "spin_change", -1, ALONG_EPS, None),
    ("spin change falls with St at small compliance", "spin_change", -1, ALONG_ST, SMALL),
    ("spin change rises with St at large compliance", "spin_change", +1, ALONG_ST, LARGE),
)


def trend_verdicts(rows) -> list[dict]:
    """For every trend claim and parameterisation: the verdict of each model (COLUMNS) over
    the lines of that parameterisation (those ``which`` keeps, if given)."""
    out = []
    for claim, quantity, expected, along, which in TREND_CLAIMS:
        variable = QUANTITIES[quantity]
        for label, (sweep, by, abscissa, keep) in along.items():
            cells = {}
            for model in COLUMNS:
                lines = _lines(rows, sweep, model, by, keep)
                if which is not None:
                    lines = {k: v for k, v in lines.items() if which(k)}
                words = [
                    trend([float(r[abscissa]) for r in line], [variable(r) for r in line], abscissa)
                    for line in lines.values()
                    if len(line) > 2
                ]
                cells[model] = _verdict(words, expected) if words else ""
            if any(cells.values()):
                out.append({"claim": claim, "parameterisation": label, **cells})
    return out


def spread_verdicts(rows) -> list[dict]:
    """The claims tested by a spread: e_t against the angle, (1 - e_t)/delta against delta
    (largest relative difference), and the smallest e_t of all rebounds."""
    out = []
    for claim, sweep, value in (
        ("e_t independent of the impact angle", "angle", lambda r: 1 - number(r["e_t"])),
        ("1 - e_t linear in delta", "delta", lambda r: (1 - number(r["e_t"])) / number(r["delta"])),
    ):
        cells = {}
        for model in COLUMNS:
            values = [value(r) for r in rows if r["sweep"] == sweep and r["model"] == model]
            if sweep == "angle":  # the angle sweep's point is also on the St line
                values += [
                    value(r) for r in rows
                    if r["model"] == model and r["sweep"] == "St"
                    and number(r["St"]) == SINGLE["St"] and number(r["eps"]) == SINGLE["eps"]
                ]  # fmt: skip
            cells[model] = f"spread {max(values) / min(values) - 1:.1e}"
        out.append({"claim": claim, "parameterisation": f"{sweep} (St 50, eps 1e-3)", **cells})
    cells = {}
    for model in COLUMNS:
        e_t = [number(r["e_t"]) for r in rows if r["model"] == model and r["rebound"] == "True"]
        cells[model] = f"min e_t {min(e_t):.4f}"
    out.append({"claim": "e_t close to unity", "parameterisation": "every rebound", **cells})
    return out


def reduced_against_full(rows) -> list[dict]:
    """Per sweep, the largest |relative difference| of 1 - e_t and of the spin change of each
    model from the FE sliding film (the fullest model), over the rebounds."""
    full = {r["key"]: r for r in rows if r["model"] == FULL and r["rebound"] == "True"}
    out = []
    for sweep in ("speed", "layer", "stiffness", "St"):
        row = {"sweep": sweep}
        for model in COLUMNS:
            if model == FULL:
                continue
            worst = [0.0, 0.0]
            for r in rows:
                f = full.get(r["key"])
                if r["sweep"] != sweep or r["model"] != model or f is None:
                    continue
                for i, (a, b) in enumerate(
                    ((1 - number(r["e_t"]), 1 - number(f["e_t"])),
                     (number(r["spin_change"]), number(f["spin_change"])))
                ):  # fmt: skip
                    worst[i] = max(worst[i], abs(a / b - 1))
            row[model] = f"{100 * worst[0]:.0f} % / {100 * worst[1]:.0f} %"
        out.append(row)
    return out


def markdown(rows) -> list[str]:
    """The verdict table and the reduced-model table, as markdown lines."""
    lines = [
        "| claim | parameterisation | " + " | ".join(COLUMNS) + " |",
        "|---|---|" + "---|" * len(COLUMNS),
    ]
    for v in trend_verdicts(rows) + spread_verdicts(rows):
        lines.append(
            f"| {v['claim']} | {v['parameterisation']} | "
            + " | ".join(v[m] or "-" for m in COLUMNS)
            + " |"
        )
    others = [m for m in COLUMNS if m != FULL]
    lines += [
        "",
        "Largest difference from the FE sliding film over each sweep's rebounds, 1 - e_t / "
        "spin change:",
        "",
        "| sweep | " + " | ".join(others) + " |",
        "|---|" + "---|" * len(others),
    ]
    for r in reduced_against_full(rows):
        lines.append(f"| {r['sweep']} | " + " | ".join(r[m] for m in others) + " |")
    return lines


def read_table(path=TABLE) -> list[dict]:
    with Path(path).open() as f:
        return list(csv.DictReader(f))


if __name__ == "__main__":
    if "--plot-only" in sys.argv:
        plot(read_table(), FIGURE)
    else:
        start = time.perf_counter()
        rows = run()
        if rows is not None:
            plot(rows, FIGURE)
            print("\n".join(markdown(rows)))
            print(f"wrote {TABLE} and {FIGURE} in {time.perf_counter() - start:.0f} s")
