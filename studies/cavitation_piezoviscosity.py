"""e_n and St_c with truncated against mass-conserving cavitation, with and without
piezoviscosity, for steel and glass spheres hitting a glass plate through a silicone-oil layer.

Physical inputs (SI): sphere radius 6.35 mm, 100 cSt silicone oil (alpha = 1.5e-8 1/Pa, the
preset), layer 0.3 mm, head-on impacts at speeds from 0.05 to 2 m/s; cavitation pressure the
oil's vapour pressure (P_cav = -1 atm scaled), e_dry = 1. For each sphere and model the critical
impact speed is found by bisection in log speed (to 1 %), and St_c is the Stokes number there.

Every finished collision is written at once (atomically) to the CSV, and a run that is stopped
and started again skips the points already there. Writes
studies/results/cavitation_piezoviscosity.csv and docs/figures/cavitation_piezoviscosity.png.
Run: .venv/bin/python studies/cavitation_piezoviscosity.py [--plot-only]
"""

import math
import sys
import time
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from ehdfem.collision import collide  # noqa: E402
from ehdfem.inputs.presets import EXAMPLE  # noqa: E402
from ehdfem.inputs.scales import from_presets  # noqa: E402
from ehdfem.motion.normal import NormalSolverError  # noqa: E402
from ehdfem.study.sweep import ResultTable, critical_speed  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
TABLE = ROOT / "studies/results/cavitation_piezoviscosity.csv"
FIGURE = ROOT / "docs/figures/cavitation_piezoviscosity.png"
SPHERES = ("steel", "glass")
CAVITATION = ("truncate", "mass-conserving")
VISCOSITY = ("constant", "barus", "roelands")
SPEEDS = np.geomspace(0.05, 2.0, 9)
CRITICAL_RTOL = 0.01


def inputs(sphere, speed, cavitation, viscosity):
    """The main job's collision, head-on, with this sphere, speed and film models."""
    return from_presets(
        **{**EXAMPLE, "sphere": sphere, "speed": float(speed), "angle": 0.0},
        cavitation=cavitation,
        viscosity=viscosity,
    )


def collision(table, sphere, cavitation, viscosity, speed, kind):
    """The row of one collision (computed, or read back from the table)."""
    key = dict(sphere=sphere, cavitation=cavitation, viscosity=viscosity, kind=kind, speed=speed)
    row = table.get(**key)
    if row is not None:
        return row
    physical = inputs(sphere, speed, cavitation, viscosity)
    params = physical.dimensionless()
    start = time.perf_counter()
    try:
        normal = collide(physical).normal
        result = {"status": normal.status, "e_n": normal.e_n, "rebound": normal.rebound}
    except NormalSolverError as err:
        result = {"status": f"failed: {err}", "e_n": "", "rebound": ""}
    row = {
        **key,
        "St": params.St,
        "eps": params.eps,
        "p_cav": params.p_cav,
        "alpha": getattr(params.viscosity, "alpha", 0.0),  # the piezoviscous laws' scaled alpha
        **result,
        "seconds": round(time.perf_counter() - start, 2),
    }
    print(", ".join(f"{k}={v}" for k, v in row.items()), flush=True)
    return table.add(row)


def finished_sweep(table, sphere, cavitation, viscosity):
    """The sweep's rows of one sphere and model whose collision finished, by speed (so by St)."""
    rows = [
        r
        for r in table.rows
        if (r["sphere"], r["cavitation"], r["viscosity"], r["kind"])
        == (sphere, cavitation, viscosity, "sweep")
        and r["rebound"] != ""
    ]
    return sorted(rows, key=lambda r: float(r["speed"]))


class FailedCollision(Exception):
    """A collision of the bisection failed (a Barus film past the law's range): whether the
    sphere rebounds there is unknown, so St_c is not found."""


def critical(table, sphere, cavitation, viscosity):
    """(critical speed, St there) by bisection in log speed on the rebound outcome, between the
    sweep's last sticking speed and its first rebounding one (nan, nan where a collision of
    the bisection fails)."""

    def rebounds(speed):
        row = collision(table, sphere, cavitation, viscosity, speed, "critical")
        if row["rebound"] == "":
            raise FailedCollision(f"{speed:.4g} m/s: {row['status']}")
        return row["rebound"] == "True"

    outcomes = [
        (float(r["speed"]), r["rebound"] == "True")
        for r in finished_sweep(table, sphere, cavitation, viscosity)
    ]
    bracket = (SPEEDS[0], SPEEDS[-1])
    for (low, sticks), (high, bounces) in zip(outcomes[:-1], outcomes[1:], strict=True):
        if not sticks and bounces:
            bracket = (low, high)
            break
    try:
        found = critical_speed(
            inputs(sphere, bracket[0], cavitation, viscosity),
            bracket,
            CRITICAL_RTOL,
            rebounds=rebounds,
        )
    except FailedCollision as failure:
        print(f"St_c of {sphere}, {cavitation}, {viscosity} not found: {failure}", flush=True)
        return math.nan, math.nan
    return found["speed"], found["St_c"]


def run(table):
    summary = []
    for sphere in SPHERES:
        for cavitation in CAVITATION:
            for viscosity in VISCOSITY:
                for speed in SPEEDS:
                    collision(table, sphere, cavitation, viscosity, float(speed), "sweep")
                speed, St_c = critical(table, sphere, cavitation, viscosity)
                summary.append((sphere, cavitation, viscosity, speed, St_c))
    for line in summary:
        print(
            "St_c: sphere={} cavitation={} viscosity={} speed={:.4g} m/s St_c={:.4g}".format(*line)
        )
    return summary


def plot(table):
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5), sharey=True)
    for ax, sphere in zip(axes, SPHERES, strict=True):
        for cavitation, style, marker in zip(CAVITATION, ("-", ":"), ("o", "s"), strict=True):
            for viscosity, colour in zip(VISCOSITY, ("C0", "C1", "C2"), strict=True):
                rows = finished_sweep(table, sphere, cavitation, viscosity)
                ax.plot(
                    [float(r["St"]) for r in rows],
                    [float(r["e_n"]) for r in rows],
                    style,
                    color=colour,
                    marker=marker,
                    ms=3.5,
                    mfc="none" if cavitation == "mass-conserving" else colour,
                    label=f"{cavitation}, {viscosity}",
                )
        ax.set_xscale("log")
        ax.set_xlabel("St")
        ax.set_title(f"{sphere} sphere on glass, 100 cSt silicone oil, x0 = 0.3 mm")
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("e_n (e_dry = 1)")
    axes[0].legend(fontsize=7)
    fig.tight_layout()
    FIGURE.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(FIGURE, dpi=120)
    print(f"wrote {FIGURE}")


if __name__ == "__main__":
    table = ResultTable(TABLE, ("sphere", "cavitation", "viscosity", "kind", "speed"))
    if "--plot-only" not in sys.argv:
        run(table)
    plot(table)
