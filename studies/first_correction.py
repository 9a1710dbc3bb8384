"""The first correction to the half-space theory: each cause's share / sqrt(delta) as delta -> 0.

The five models of :mod:`ehdfem.study.corrections` (theory, + true gap, + tangential surface
effects, both on half-spaces, and the full FE model) at St = 20, 30 degrees, identical solids
(nu = 0.3), Couette tangential model, rtol 1e-6, for four cases (``CASES``): a thin layer with
eps = 1e-3 (delta = 1e-4 ... 0.05) and 1e-2 without cavitation and eps = 1e-3 with P_cav = -2
(delta = 1e-4, 1e-3, 0.01, 0.05), and an immersed sphere with eps = 1e-3 without cavitation.
Each cause's share (relative to the theory's output) is computed on 120 and 240 film nodes
and extrapolated to the continuum by Richardson's rule for order 2,
s = (4 s_240 - s_120) / 3 (the film, the half-space kernel and the FE read-out converge at
order 2; at a common grid the collocated half-space kernel and the hat-averaged FE read-out
differ by O(h^2), which is 1 % of the thinnest film at 120 nodes). Then
share / sqrt(delta) = c1 + c2 sqrt(delta) is fitted by least squares
(:func:`ehdfem.study.corrections.first_order_fit`): c1 is the first-order constant.

An immersed film reaches R = 30 sqrt(a x0), beyond the FE solids' 0.7 a above delta = 5e-4:
its deltas are 1e-5, 1e-4 and 3e-4. It has no true-gap variant (geometry share zero).

The surface effects are two terms switched together: the squeeze shear's gap opening and the
liquid the faces' radial velocity carries. Their first-order shares add up (each is linear in
the perturbation); :func:`surface_split` runs each alone on half-spaces at delta = 1e-4 (where
the quotient is its limit within O(sqrt(delta)) = 1 %) and writes
studies/results/first_correction_surface.csv.

Writes studies/results/first_correction.csv (the shares per grid; resumable),
studies/results/first_correction_fit.csv (c1, c2 and their standard errors per case, cause and
output) and docs/figures/first_correction.png.
Run: nice -n 10 .venv/bin/python studies/first_correction.py [--plot-only]   (about 15
minutes on 2 cores)
"""

import math
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from ehdfem import CollisionParameters  # noqa: E402
from ehdfem.collision import collide, film_radii  # noqa: E402
from ehdfem.config import RunConfig  # noqa: E402
from ehdfem.solids.compliance import LinearCompliance  # noqa: E402
from ehdfem.solids.halfspace import HalfSpaceCompliance  # noqa: E402
from ehdfem.study.corrections import (  # noqa: E402
    CAUSES,
    OUTPUTS,
    cause_shares,
    first_order_fit,
    run_variants,
    variant_parameters,
)
from ehdfem.study.sweep import ResultTable, write_csv  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
TABLE = ROOT / "studies" / "results" / "first_correction.csv"
FIT = ROOT / "studies" / "results" / "first_correction_fit.csv"
SPLIT = ROOT / "studies" / "results" / "first_correction_surface.csv"
SPLIT_DELTA = 1e-4
EFFECTS = ("opening", "velocity")
NORMAL = OUTPUTS[:5]  # the normal motion's outputs
FIGURE = ROOT / "docs" / "figures" / "first_correction.png"
CASES = {  # the inputs and the deltas of each case
    "thin, eps 1e-3": (dict(eps=1e-3, layer="thin"), (1e-4, 3e-4, 1e-3, 3e-3, 0.01, 0.05)),
    "thin, eps 1e-2": (dict(eps=1e-2, layer="thin"), (1e-4, 1e-3, 0.01, 0.05)),
    "thin, eps 1e-3, P_cav -2": (
        dict(eps=1e-3, layer="thin", p_cav=-2.0),
        (1e-4, 1e-3, 0.01, 0.05),
    ),
    "immersed, eps 1e-3": (dict(eps=1e-3, layer="immersed"), (1e-5, 1e-4, 3e-4)),
}
NODES = (120, 240)
IDENTICAL = ((1.0, 0.3), (1.0, 0.3))
CONFIG = RunConfig.from_settings(rtol=1e-6)


def compute():
    table = ResultTable(TABLE, ("case", "delta", "nodes", "cause"))
    for case, (inputs, deltas) in CASES.items():
        for delta in deltas:
            for nodes in NODES:
                if table.get(case=case, delta=delta, nodes=nodes, cause="total") is not None:
                    continue
                print(f"{case}: delta = {delta:g}, {nodes} nodes", flush=True)
                params = CollisionParameters.from_settings(
                    St=20.0, delta=delta, angle=30.0, **inputs
                )
                shares = cause_shares(run_variants(params, nodes, IDENTICAL, CONFIG))
                for cause, values in shares.items():
                    table.add(dict(case=case, delta=delta, nodes=nodes, cause=cause, **values))
    return table.rows


class OneSurfaceEffect(LinearCompliance):
    """Identical half-spaces (scale: eps times the kernel) with one of the two tangential
    surface effects: "opening" (the squeeze shear's gap opening) or "velocity" (the faces'
    radial velocity in the film's flux)."""

    model = "halfspace"

    def __init__(self, radii, eps, delta, effect):
        both = HalfSpaceCompliance(radii, eps, (delta, IDENTICAL), IDENTICAL)
        opening = both.unit_shear if effect == "opening" else None
        velocity = both.unit_surface_radial if effect == "velocity" else None
        super().__init__(both.radii, both.unit_matrix, eps, opening, None, velocity)

    def factor(self, eps):
        return eps


def surface_split():
    """Rows per case: the shares / sqrt(delta) of the opening alone, the velocity alone and
    both (relative to the theory, Richardson 120/240 nodes) at delta = SPLIT_DELTA."""
    rows = []
    for case, (inputs, _) in CASES.items():
        params = CollisionParameters.from_settings(St=20.0, delta=SPLIT_DELTA, angle=30.0, **inputs)
        params = variant_parameters(params, "surface")
        per_grid = []
        for nodes in NODES:
            radii = film_radii(params, nodes)
            models = {e: OneSurfaceEffect(radii, params.eps, SPLIT_DELTA, e) for e in EFFECTS}
            models["theory"] = HalfSpaceCompliance(radii, params.eps)
            models["both"] = HalfSpaceCompliance(radii, params.eps, (SPLIT_DELTA, IDENTICAL))
            found = {k: collide(params, CONFIG, compliance=m).summary() for k, m in models.items()}
            theory = found.pop("theory")
            per_grid.append(
                {
                    effect: {k: (v[k] / theory[k] - 1) / math.sqrt(SPLIT_DELTA) for k in NORMAL}
                    for effect, v in found.items()
                }
            )
        coarse, fine = per_grid
        for effect in fine:
            richardson = {k: (4 * fine[effect][k] - coarse[effect][k]) / 3 for k in NORMAL}
            rows.append({"case": case, "effect": effect, **richardson})
        print(case, rows[-3:], flush=True)
    return rows


def extrapolated(rows):
    """{(case, cause, output): (deltas, shares)}: Richardson's continuum shares (order 2)."""
    by_key = {}
    for row in rows:
        for output in OUTPUTS:
            key = (row["case"], row["cause"], output, float(row["delta"]))
            by_key.setdefault(key, {})[int(row["nodes"])] = float(row[output])
    out = {}
    for (case, cause, output, delta), grids in sorted(by_key.items()):
        if set(NODES) <= set(grids):
            coarse, fine = (grids[n] for n in NODES)
            series = out.setdefault((case, cause, output), ([], []))
            series[0].append(delta)
            series[1].append((4 * fine - coarse) / 3)
    return out


def fits(series):
    """Rows of c1, c2 and their standard errors for each (case, cause, output)."""
    rows = []
    for (case, cause, output), (ds, shares) in series.items():
        if cause == "geometry" and CASES[case][0]["layer"] != "thin":
            continue
        c1, c2, e1, e2 = first_order_fit(ds, shares)
        rows.append(
            dict(case=case, cause=cause, output=output, c1=c1, c1_error=e1, c2=c2, c2_error=e2)
        )
    return rows


def plot(series):
    """share / sqrt(delta) against sqrt(delta), with the fitted line c1 + c2 sqrt(delta) (its
    intercept c1 is the first-order constant): a column per output, a row per cause."""
    causes = (*CAUSES[:3], "total")
    fig, axes = plt.subplots(len(causes), len(NORMAL), figsize=(17, 11), sharex=True)
    for i, cause in enumerate(causes):
        for j, output in enumerate(NORMAL):
            ax = axes[i, j]
            for k, case in enumerate(CASES):
                if (case, cause, output) not in series:
                    continue
                ds, shares = series[(case, cause, output)]
                root = np.sqrt(ds)
                ax.plot(root, np.asarray(shares) / root, f"C{k}o", ms=4, label=case)
                if len(ds) >= 3:
                    c1, c2, _, _ = first_order_fit(ds, shares)
                    line = np.linspace(0.0, root.max(), 20)
                    ax.plot(line, c1 + c2 * line, f"C{k}--", lw=0.8)
            ax.axhline(0.0, color="k", lw=0.5)
            ax.set_title(f"{cause}: {output}", fontsize=9)
            ax.grid(alpha=0.3)
            if i == len(causes) - 1:
                ax.set_xlabel("sqrt(delta)")
    axes[0, 0].set_ylabel("share / sqrt(delta)")
    axes[0, 0].legend(fontsize=7)
    fig.suptitle(
        "First correction to the half-space theory: (model - its neighbour) / theory / "
        "sqrt(delta), St = 20, identical solids, continuum (Richardson 120/240 nodes); "
        "dashed: c1 + c2 sqrt(delta)"
    )
    fig.tight_layout()
    FIGURE.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(FIGURE, dpi=100)


def markdown(found, split):
    """The docs' tables: c1 +- its standard error per case and cause (rows) and output
    (columns; geometry: c2, the order-delta constant, since its c1 is nil), and the split of
    the surface effects."""
    lines = ["| case | cause | " + " | ".join(NORMAL) + " | e_t |", "|---" * 8 + "|"]
    table = {(r["case"], r["cause"], r["output"]): r for r in found}
    for case in CASES:
        for cause in (*CAUSES[:3], "total"):
            if (case, cause, "e_n") not in table:
                continue
            cells = []
            for output in OUTPUTS:
                row = table[(case, cause, output)]
                which = "c2" if cause == "geometry" else "c1"
                cells.append(f"{float(row[which]):+.4f} ± {float(row[which + '_error']):.4f}")
            label = "geometry (c2: share / delta)" if cause == "geometry" else cause
            lines.append(f"| {case} | {label} | " + " | ".join(cells) + " |")
    lines += ["", "| case | effect | " + " | ".join(NORMAL) + " |", "|---" * 7 + "|"]
    for row in split:
        cells = [f"{float(row[k]):+.4f}" for k in NORMAL]
        lines.append(f"| {row['case']} | {row['effect']} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def main():
    rows = ResultTable(TABLE, ()).rows if "--plot-only" in sys.argv else compute()
    series = extrapolated(rows)
    found = fits(series)
    write_csv(FIT, found)
    plot(series)
    if "--plot-only" not in sys.argv or not SPLIT.exists():
        write_csv(SPLIT, surface_split())
    print(markdown(found, ResultTable(SPLIT, ()).rows))
    print(f"wrote {TABLE}, {FIT}, {SPLIT} and {FIGURE}")


if __name__ == "__main__":
    main()
