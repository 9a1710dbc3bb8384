"""Where the asymptotic half-space theory holds: a validity map against the full FE model.

For each layer-to-radius ratio delta and dry Hertz compression c = (13.88 eps St)^(2/5) (gap
units; St = 20, eps from c), thin layer, P_cav = -2, 30 degrees, Couette tangential model, 120
film nodes, rtol 1e-5 (film thickness controlled), the five models of
:mod:`ehdfem.study.corrections` on the same film grid, each one change from a neighbour: the
theory (half-space, paraboloid, pressure only), + the true sphere gap (geometry), + the
tangential surface effects (the squeeze shear's opening and the faces' radial velocity in the
flux), both on half-spaces, and the full model (FE solids with both).

Two material pairs: identical solids (nu = 0.3) and a hard sphere on a soft wall (E ratio 50,
nu 0.2 on 0.35). The relative error of the theory in each output is (theory - full) / full;
the causes' shares (geometry, surface effects, finite size of the solids, interaction) are
relative to the theory and add up to (full - theory) / theory. Points where the film would
reach beyond 0.7 of the sphere radius (the FE solids' limit) are skipped: with a thin layer
the film's grid ends at 1.05 sqrt(2 (1 + c)) sqrt(delta) a, so nothing above delta = 0.22 fits.

Writes studies/results/validity_map.csv, docs/figures/validity_map.png and the tables of
docs/fem.md's study section (printed). Resumable: finished points are kept in the CSV.
Run: nice -n 10 .venv/bin/python studies/validity_map.py [--plot-only]   (about 15 minutes
on 2 cores)
"""

import math
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from ehdfem import CollisionParameters, film_radii  # noqa: E402
from ehdfem.config import RunConfig  # noqa: E402
from ehdfem.study.corrections import CAUSES, OUTPUTS, VARIANTS, run_variants  # noqa: E402
from ehdfem.study.sweep import ResultTable  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
TABLE = ROOT / "studies" / "results" / "validity_map.csv"
FIGURE = ROOT / "docs" / "figures" / "validity_map.png"
DELTAS = (1e-4, 3e-4, 1e-3, 3e-3, 0.01, 0.03, 0.1, 0.2, 0.5)
COMPRESSIONS = (0.03, 0.1, 0.3, 1.0, 3.0)
MATERIALS = {
    "identical": ((1.0, 0.3), (1.0, 0.3)),
    "hard sphere, soft wall": ((50.0, 0.2), (1.0, 0.35)),
}
PLOTTED = ("e_n", "min_film_thickness", "max_compression", "e_t")
ST, NODES, FE_LIMIT = 20.0, (120, 240), 0.7
CONFIG = RunConfig.from_settings(rtol=1e-5)


def parameters(delta, compression):
    eps = compression**2.5 / (90 * math.pi**2 / 64 * ST)
    return CollisionParameters(St=ST, eps=eps, delta=delta, layer="thin", p_cav=-2.0, angle=30.0)


def feasible(delta, compression):
    radii = film_radii(parameters(delta, compression), NODES[-1])
    return radii[-1] * math.sqrt(delta) < FE_LIMIT


def compute():
    table = ResultTable(TABLE, ("nodes", "materials", "delta", "compression", "variant"))
    for nodes in NODES:
        for materials in MATERIALS:
            for delta in DELTAS:
                for compression in COMPRESSIONS:
                    run_point(table, nodes, materials, delta, compression)
    return table.rows


def run_point(table, nodes, materials, delta, compression):
    """The five models at one point on ``nodes`` film nodes, into ``table`` (skipped: done)."""
    key = dict(nodes=nodes, materials=materials, delta=delta, compression=compression)
    if table.get(**key, variant="full") is not None:
        return
    if not feasible(delta, compression):
        table.add({**key, "variant": "full", "skipped": "film beyond 0.7 a"})
        return
    print(f"{nodes} nodes, {materials}: delta = {delta:g}, c = {compression:g}", flush=True)
    found = run_variants(parameters(delta, compression), nodes, MATERIALS[materials], CONFIG)
    for variant, values in found.items():
        table.add({**key, "variant": variant, "skipped": "", **values})


def errors(rows):
    """{(materials, delta, compression): {variant: {output: (variant - full)/full}}} for the
    points that ran (theory's entry is the theory's error; the others are relative to it)."""
    values = {}
    for row in rows:
        if row.get("skipped"):
            continue
        key = (row["materials"], float(row["delta"]), float(row["compression"]))
        values.setdefault(key, {})[row["variant"]] = {
            k: float(row[k]) if row[k] not in ("", "None") else math.nan for k in OUTPUTS
        }
    out = {}
    for key, models in values.items():
        full = models["full"]
        out[key] = {
            "theory": {k: (models["theory"][k] - full[k]) / full[k] for k in OUTPUTS},
            **{
                v: {k: (models[v][k] - models["theory"][k]) / full[k] for k in OUTPUTS}
                for v in ("geometry", "shear", "finite")
            },
        }
    return out


def log_edges(values):
    """Cell edges around log-spaced values: geometric midpoints, extended at both ends."""
    v = np.log10(values)
    inner = 0.5 * (v[1:] + v[:-1])
    return 10 ** np.concatenate([[2 * v[0] - inner[0]], inner, [2 * v[-1] - inner[-1]]])


def plot(found):
    labels = {"e_n": "e_n", "min_film_thickness": "H_min", "max_compression": "max compression"}
    labels["e_t"] = "e_t"
    fig, axes = plt.subplots(len(MATERIALS), len(OUTPUTS), figsize=(15, 7), sharex=True)
    for row, materials in enumerate(MATERIALS):
        for col, output in enumerate(OUTPUTS):
            ax = axes[row, col]
            grid = np.full((len(COMPRESSIONS), len(DELTAS)), np.nan)
            for i, c in enumerate(COMPRESSIONS):
                for j, d in enumerate(DELTAS):
                    if (materials, d, c) in found:
                        grid[i, j] = abs(found[(materials, d, c)]["theory"][output]) * 100
            mesh = ax.pcolormesh(
                log_edges(DELTAS),
                log_edges(COMPRESSIONS),
                np.log10(np.maximum(grid, 1e-3)),
                vmin=-2,
                vmax=1,
                cmap="viridis",
            )
            masked = np.ma.masked_invalid(grid)
            contours = ax.contour(DELTAS, COMPRESSIONS, masked, levels=(1.0, 5.0), colors="w")
            ax.clabel(contours, fmt="%g %%", fontsize=7)
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_title(f"{materials}: {labels[output]}", fontsize=9)
            if row == len(MATERIALS) - 1:
                ax.set_xlabel("delta = x0 / a")
            if col == 0:
                ax.set_ylabel("dry Hertz compression / x0")
    bar = fig.colorbar(mesh, ax=axes, shrink=0.8)
    bar.set_label("log10 of |theory - full FE model| / full model, in %")
    fig.suptitle(
        "Error of the half-space theory: St = 20, thin layer, P_cav = -2, 30 deg "
        "(white: 1 % and 5 % contours; blank: film beyond 0.7 a)"
    )
    FIGURE.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(FIGURE, dpi=110)


def tables(found):
    """Markdown: per point the theory's error in e_n and H_min and the causes' shares (%)."""
    lines = []
    for output in ("e_n", "min_film_thickness"):
        lines += [
            f"\n{output}: (full - theory) / full = geometry + shear + finite size + interaction"
            " (%)\n",
            "| materials | delta | c | full - theory | geometry | shear | finite size "
            "| interaction |",
            "|---|---|---|---|---|---|---|---|",
        ]
        for (materials, delta, c), parts in sorted(found.items()):
            shares = [100 * parts[v][output] for v in ("geometry", "shear", "finite")]
            total = -100 * parts["theory"][output]
            cells = [f"{x:+.2f}" for x in (total, *shares, total - sum(shares))]
            lines.append(f"| {materials} | {delta:g} | {c:g} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def main():
    rows = ResultTable(TABLE, ()).rows if "--plot-only" in sys.argv else compute()
    found = errors(rows)
    plot(found)
    print(tables(found))
    print(f"wrote {TABLE} and {FIGURE}")


if __name__ == "__main__":
    main()
