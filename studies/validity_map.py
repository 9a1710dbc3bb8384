"""Where the asymptotic half-space theory holds: a validity map against the full FE model.

For each layer-to-radius ratio delta and dry Hertz compression c = (13.88 eps St)^(2/5) (gap
units; St = 20, eps from c), thin layer, P_cav = -2, 30 degrees, Couette tangential model, rtol
1e-5 (film thickness controlled), the five models of :mod:`ehdfem.study.corrections` on one
film grid, 120 and then 240 nodes (the causes' shares extrapolated to the continuum by
Richardson's rule for order 2), each model one change from a neighbour: the
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
Run: nice -n 10 .venv/bin/python studies/validity_map.py [--plot-only]   (about 40 minutes
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
from ehdfem.film.reynolds import FilmError  # noqa: E402
from ehdfem.study.corrections import CAUSES, OUTPUTS, cause_shares, run_variants  # noqa: E402
from ehdfem.study.sweep import ResultTable  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
TABLE = ROOT / "studies" / "results" / "validity_map.csv"
FIGURE = ROOT / "docs" / "figures" / "validity_map.png"
DELTAS = (1e-4, 1e-3, 3e-3, 0.01, 0.03, 0.1, 0.2, 0.5)
COMPRESSIONS = (0.1, 0.3, 1.0, 3.0)
MATERIALS = {
    "identical": ((1.0, 0.3), (1.0, 0.3)),
    "hard sphere, soft wall": ((50.0, 0.2), (1.0, 0.35)),
}
PLOTTED = ("e_n", "min_film_thickness", "max_compression", "e_t")
ST, NODES, FE_LIMIT = 20.0, (120, 240), 0.7
CONFIG = RunConfig.from_settings(rtol=1e-5)


def parameters(delta, compression):
    eps = compression**2.5 / (90 * math.pi**2 / 64 * ST)
    return CollisionParameters.from_settings(
        St=ST, eps=eps, delta=delta, layer="thin", p_cav=-2.0, angle=30.0
    )


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
    try:
        found = run_variants(parameters(delta, compression), nodes, MATERIALS[materials], CONFIG)
    except FilmError as error:  # e.g. FE solids whose compliance is not finite
        table.add({**key, "variant": "full", "skipped": f"failed: {error}"})
        return
    for variant, values in found.items():
        table.add({**key, "variant": variant, "skipped": "", **values})


def continuum(rows):
    """{(materials, delta, compression): ({cause or "total": {output: share}}, grids)}: the
    causes' shares (relative to the theory, :func:`ehdfem.study.corrections.cause_shares`) by
    Richardson's rule for order 2 from 120 and 240 film nodes, (4 s_240 - s_120) / 3, or on
    the one grid that ran (``grids`` says which)."""
    values = {}
    for row in rows:
        if row.get("skipped"):
            continue
        key = (row["materials"], float(row["delta"]), float(row["compression"]))
        if key[1] not in DELTAS or key[2] not in COMPRESSIONS:
            continue  # a point of an earlier grid
        grid = values.setdefault(key, {}).setdefault(int(row["nodes"]), {})
        grid[row["variant"]] = {k: _number(row.get(k)) for k in OUTPUTS}
    out = {}
    for key, grids in values.items():
        shares = {n: cause_shares(models) for n, models in grids.items() if len(models) == 5}
        if set(NODES) <= set(shares):
            coarse, fine = (shares[n] for n in NODES)
            found = {c: {k: (4 * fine[c][k] - coarse[c][k]) / 3 for k in OUTPUTS} for c in fine}
            out[key] = (found, NODES)
        elif shares:
            (nodes, found), *_ = shares.items()
            out[key] = (found, (nodes,))
    return out


def _number(value):
    return float(value) if value not in (None, "", "None") else math.nan


def theory_error(shares, output):
    """(theory - full) / full from the total share (full - theory) / theory."""
    total = shares["total"][output]
    return -total / (1 + total)


def log_edges(values):
    """Cell edges around log-spaced values: geometric midpoints, extended at both ends."""
    v = np.log10(values)
    inner = 0.5 * (v[1:] + v[:-1])
    return 10 ** np.concatenate([[2 * v[0] - inner[0]], inner, [2 * v[-1] - inner[-1]]])


def plot(found):
    labels = {"e_n": "e_n", "min_film_thickness": "H_min", "max_compression": "max compression"}
    labels["e_t"] = "e_t"
    fig, axes = plt.subplots(len(MATERIALS), len(PLOTTED), figsize=(15, 7), sharex=True)
    for row, materials in enumerate(MATERIALS):
        for col, output in enumerate(PLOTTED):
            ax = axes[row, col]
            grid = np.full((len(COMPRESSIONS), len(DELTAS)), np.nan)
            for i, c in enumerate(COMPRESSIONS):
                for j, d in enumerate(DELTAS):
                    if (materials, d, c) in found:
                        shares = found[(materials, d, c)][0]
                        grid[i, j] = abs(theory_error(shares, output)) * 100
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
    """Markdown: the theory's largest error over the compressions per delta, and per point the
    causes' shares (%) of e_n, the thinnest film and the largest compression."""
    lines = ["| materials: output | " + " | ".join(f"{d:g}" for d in DELTAS) + " |",
             "|---" * (len(DELTAS) + 1) + "|"]  # fmt: skip
    for materials in MATERIALS:
        for output in OUTPUTS:
            cells = []
            for delta in DELTAS:
                errs = [abs(theory_error(v[0], output)) for (m, d, _), v in found.items()
                        if m == materials and d == delta]  # fmt: skip
                cells.append(f"{100 * max(errs):.2f}" if errs else "")
            lines.append(f"| {materials}: {output} | " + " | ".join(cells) + " |")
    lines += ["", "| materials: output | within 1 % up to delta | within 5 % up to delta |",
              "|---|---|---|"]  # fmt: skip
    for materials in MATERIALS:
        for output in OUTPUTS:
            limits = [_within(found, materials, output, level) for level in (0.01, 0.05)]
            lines.append(f"| {materials}: {output} | " + " | ".join(limits) + " |")
    lines += ["", "| materials | delta | c | output | full - theory | geometry | surface | "
              "finite size | interaction | grids |", "|---" * 10 + "|"]  # fmt: skip
    for (materials, delta, c), (shares, grids) in sorted(found.items()):
        for output in ("e_n", "min_film_thickness", "max_compression"):
            cells = [f"{100 * shares[k][output]:+.2f}" for k in ("total", *CAUSES)]
            lines.append(f"| {materials} | {delta:g} | {c:g} | {output} | " + " | ".join(cells)
                         + f" | {'/'.join(map(str, grids))} |")  # fmt: skip
    return "\n".join(lines)


def _within(found, materials, output, level):
    """The largest delta up to which the theory's error stays below ``level`` at every
    compression that ran (text; "> d" when it holds at every delta that ran)."""
    largest = None
    for delta in DELTAS:
        errs = [abs(theory_error(v[0], output)) for (m, d, _), v in found.items()
                if m == materials and d == delta]  # fmt: skip
        if not errs:
            continue
        if max(errs) > level:
            return f"{largest:g}" if largest is not None else f"< {delta:g}"
        largest = delta
    return f">= {largest:g}" if largest is not None else ""


def main():
    rows = ResultTable(TABLE, ()).rows if "--plot-only" in sys.argv else compute()
    found = continuum(rows)
    plot(found)
    print(tables(found))
    print(f"wrote {TABLE} and {FIGURE}")


if __name__ == "__main__":
    main()
