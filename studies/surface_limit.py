"""The surface effects' first correction at weak elasticity: the code against the closed form.

On half-spaces (thin layer, paraboloid gap, identical solids with nu = 0.3, no cavitation) the
thinnest film with the tangential surface effects on and off, and the quotient
q = (H_min(on) / H_min(off) - 1) / (eps sqrt(delta)), against the closed form
c = -kappa J(X_s) / (1 - X_s)^2 of :mod:`ehdfem.exact.surface_limit` (the rigid approach's
first-order change, eps -> 0), at St = 0.5, 1 and 2 (rigid stopping gaps 0.197, 0.0997, 0.0322).

Weak elasticity is measured by k = eps / X_s^(5/2), the elastic opening over the film at the
stop; the quotient is taken at k = 0.1, 0.03, 0.01 (delta = 0.01) to show q -> c as k -> 0,
at delta = 0.1, 0.01, 1e-3 (k = 0.03) to show the sqrt(delta) term, on 60 and 120 film nodes
(the grid ``radial_grid(n, 0.5, 1.5)``: nearly uniform out to R = 0.5, the wetted edge ends
before sqrt(2)), rtol 1e-10 (the change is 1e-5 to 1e-6 of the film: the time-step control
must be far below it). Then each effect alone (the opening, the faces' velocity) at k = 0.01,
delta = 0.01, 120 nodes, against its own constant.

The velocity at a given gap as well: V1(X) = -(eps sqrt(delta) kappa / St) J(X) against the
runs' difference of V at X (a cubic spline of V in X over the approach's accepted steps), at
St = 1, eps = 1e-4 and 3e-5 (k = 0.032 and 0.0096), delta = 0.01, 120 nodes.

Writes studies/results/surface_limit.csv (resumable: a row per run pair) and
studies/results/surface_limit_velocity.csv. Run:
nice -n 10 .venv/bin/python studies/surface_limit.py   (about 10 minutes on 2 cores)
"""

import math
from pathlib import Path

import numpy as np
from scipy.interpolate import CubicSpline

from ehdfem.collision import collide
from ehdfem.config import RunConfig
from ehdfem.exact import rigid_film
from ehdfem.exact.surface_limit import stopping_gap_constant, velocity_integral
from ehdfem.film.grid import radial_grid
from ehdfem.inputs.scales import CollisionParameters
from ehdfem.solids.compliance import LinearCompliance
from ehdfem.solids.halfspace import IDENTICAL_SOLIDS, HalfSpaceCompliance, shear_coefficient
from ehdfem.study.sweep import ResultTable, write_csv

ROOT = Path(__file__).resolve().parents[1]
TABLE = ROOT / "studies" / "results" / "surface_limit.csv"
VELOCITY = ROOT / "studies" / "results" / "surface_limit_velocity.csv"
GAPS = (0.7, 0.5, 0.3, 0.2, 0.15, 0.12)  # the rigid sphere stops at 0.0997 (St = 1)
STOKES = (0.5, 1.0, 2.0)
WEAKNESS = (0.1, 0.03, 0.01)  # k = eps / X_s^(5/2) at delta = 0.01
DELTAS = (0.1, 0.01, 1e-3)  # at k = 0.03
NODES = (60, 120)
CONFIG = RunConfig.from_settings(rtol=1e-10)


class OneSurfaceEffect(LinearCompliance):
    """Half-spaces (eps times the kernel) with one surface term: "opening" or "velocity"."""

    model = "halfspace"

    def __init__(self, radii, eps, delta, effect):
        both = HalfSpaceCompliance(radii, eps, (delta, IDENTICAL_SOLIDS))
        opening = both.unit_shear if effect == "opening" else None
        velocity = both.unit_surface_radial if effect == "velocity" else None
        super().__init__(both.radii, both.unit_matrix, eps, opening, None, velocity)

    def factor(self, eps):
        return eps


def quotient(St, weakness, delta, nodes, effect="both"):
    """(H_min(on) / H_min(off) - 1) / (eps sqrt(delta)) and H_min(off) at eps = weakness
    X_s^(5/2)."""
    eps = weakness * rigid_film.stopping_gap(St, "thin") ** 2.5
    params = CollisionParameters(St=St, eps=eps, delta=delta)
    radii = radial_grid(nodes, 0.5, 1.5)
    solids = {"off": HalfSpaceCompliance(radii, eps)}
    if effect == "both":
        solids["on"] = HalfSpaceCompliance(radii, eps, (delta, IDENTICAL_SOLIDS))
    else:
        solids["on"] = OneSurfaceEffect(radii, eps, delta, effect)
    thinnest = {
        k: collide(params, CONFIG, compliance=s).normal.min_film_thickness
        for k, s in solids.items()
    }
    return (thinnest["on"] / thinnest["off"] - 1) / (eps * math.sqrt(delta)), thinnest["off"]


def points():
    """(St, k, delta, nodes, effect) of every run pair."""
    for St in STOKES:
        for nodes in NODES:
            for k in WEAKNESS:
                yield St, k, 0.01, nodes, "both"
            for delta in DELTAS:
                if delta != 0.01:
                    yield St, 0.03, delta, nodes, "both"
        for effect in ("opening", "velocity"):
            yield St, 0.01, 0.01, NODES[-1], effect


def compute():
    table = ResultTable(TABLE, ("St", "weakness", "delta", "nodes", "effect"))
    for St, k, delta, nodes, effect in points():
        key = dict(St=St, weakness=k, delta=delta, nodes=nodes, effect=effect)
        if table.get(**key) is not None:
            continue
        q, thinnest = quotient(St, k, delta, nodes, effect)
        constant = stopping_gap_constant(St, shear_coefficient(), effect)
        table.add(dict(key, quotient=q, constant=constant, min_film_off=thinnest))
        print(key, f"q = {q:.4f}, c = {constant:.4f}, ratio {q / constant:.4f}", flush=True)
    return table.rows


def summary(rows):
    """Per St: the quotient over c at each k (delta 0.01, finest grid), its linear
    extrapolation to k = 0 from the two weakest, and at each delta (k = 0.03)."""
    by = {
        (float(r["St"]), float(r["weakness"]), float(r["delta"]), int(r["nodes"]), r["effect"]): (
            float(r["quotient"]) / float(r["constant"])
        )
        for r in rows
    }
    for St in STOKES:
        fine = NODES[-1]
        ratios = [by.get((St, k, 0.01, fine, "both"), np.nan) for k in WEAKNESS]
        limit = ratios[-1] - (ratios[-2] - ratios[-1]) * WEAKNESS[-1] / (
            WEAKNESS[-2] - WEAKNESS[-1]
        )
        deltas = [by.get((St, 0.03, d, fine, "both"), np.nan) for d in DELTAS]
        grids = [by.get((St, 0.01, 0.01, n, "both"), np.nan) for n in NODES]
        effects = [by.get((St, 0.01, 0.01, fine, e), np.nan) for e in ("opening", "velocity")]
        constant = stopping_gap_constant(St, shear_coefficient())
        print(
            f"St {St}: c = {constant:.4f}; q/c at k {WEAKNESS}: "
            f"{np.round(ratios, 4)}, k -> 0: {limit:.4f}; at delta {DELTAS}: "
            f"{np.round(deltas, 4)}; nodes {NODES}: {np.round(grids, 4)}; "
            f"opening, velocity alone: {np.round(effects, 4)}"
        )


def approach_velocity(params, solids):
    """V(X) over the approach (V < 0) as a cubic spline of the accepted steps."""
    history = collide(params, CONFIG, compliance=solids).normal.history
    gap, velocity = np.asarray(history.gap), np.asarray(history.velocity)
    approach = velocity < 0
    return CubicSpline(gap[approach][::-1], velocity[approach][::-1])


def velocity_check():
    """Rows (eps, X, quotient (V_on - V_off)/(eps sqrt(delta)), its closed form)."""
    St, delta, rows = 1.0, 0.01, []
    radii = radial_grid(NODES[-1], 0.5, 1.5)
    for eps in (1e-4, 3e-5):
        params = CollisionParameters(St=St, eps=eps, delta=delta)
        off = approach_velocity(params, HalfSpaceCompliance(radii, eps))
        on = approach_velocity(params, HalfSpaceCompliance(radii, eps, (delta, IDENTICAL_SOLIDS)))
        for x in GAPS:
            found = float(on(x) - off(x)) / (eps * math.sqrt(delta))
            closed = -shear_coefficient() / St * velocity_integral(x, St)
            rows.append(dict(eps=eps, gap=x, quotient=found, closed_form=closed))
            print(rows[-1], f"ratio {found / closed:.4f}", flush=True)
    return rows


if __name__ == "__main__":
    summary(compute())
    if not VELOCITY.exists():
        write_csv(VELOCITY, velocity_check())
