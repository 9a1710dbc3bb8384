"""e_t and the spin change against St for eps = 1e-5, 1e-3, 0.1 at delta = 0.01: four models.

Thin layer, P_cav = -10, e_dry = 1, zero initial spin, 30 degrees. Four models, each differing
from the one before in one thing:

- couette:          half-space, paraboloid gap, Couette shear of the normal film only;
- sliding film:     the same solids, the sliding film ("lubrication", mode-1 gap "gap");
- FE, paraboloid:   FE solids with the half-space's gap and loads (paraboloid gap, pressure
                    only): the elasticity alone differs;
- FE, full:         FE solids with their defaults (exact sphere gap, squeeze-shear traction).

Per eps, every model runs on one film grid, that of the widest collision (St = 1000), with
compliances built once on it: the half-space and its mode-1 compliance, and one FE solids
whose factorisation gives both FE compliances (with and without the shear traction's opening)
and one FE mode-1 compliance. On a given grid the film is not refined: a collision whose film
closes is recorded as failed. Writes studies/results/tangential_vs_stokes.csv (resumable:
finished rows are kept and skipped) and docs/figures/tangential_vs_stokes.png.
Run: .venv/bin/python studies/tangential_vs_stokes.py [--plot-only]   (about 9 minutes, one process)
"""

import math
import sys
import time
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402

from ehdfem.collision import collide, elasticity, film_radii, mode_one_elasticity  # noqa: E402
from ehdfem.config import RunConfig
from ehdfem.inputs.scales import CollisionParameters  # noqa: E402
from ehdfem.motion.normal import NormalSolverError  # noqa: E402
from ehdfem.solids.fe.solids import FECompliance  # noqa: E402
from ehdfem.study.sweep import ResultTable, study_script  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
TABLE = ROOT / "studies" / "results" / "tangential_vs_stokes.csv"
STOKES = np.geomspace(3, 1000, 12)
ELASTICITY = (1e-5, 1e-3, 1e-1)
NODES = 120
# label: (elasticity, tangential model, the half-space's gap and loads (True) or the FE defaults)
MODELS = {
    "couette": ("halfspace", "couette", True),
    "sliding film": ("halfspace", "lubrication", True),
    "FE, paraboloid": ("fem", "lubrication", True),
    "FE, full": ("fem", "lubrication", False),
}
STYLES = dict(zip(MODELS, ("-", "--", "-.", ":"), strict=True))
COLOURS = dict(zip(ELASTICITY, ("C0", "C1", "C2"), strict=True))


def parameters(eps, St, theory_gap):
    """The collision; ``theory_gap``: the paraboloid gap and the pressure alone (the half-space
    theory's), else the elasticity model's defaults."""
    extra = dict(gap="paraboloid", shear_traction=False) if theory_gap else {}
    return CollisionParameters.from_settings(
        St=float(St), eps=eps, delta=0.01, layer="thin", p_cav=-10.0, angle=30.0, **extra
    )


def solids(eps):
    """{label: (compliance, mode-1 compliance or None)} on the grid of the widest collision;
    the closers of what holds a factorisation."""
    widest = parameters(eps, STOKES[-1], True)
    radii = film_radii(widest, NODES)
    half_space = elasticity(widest, radii)
    start = time.perf_counter()
    full = elasticity(parameters(eps, STOKES[-1], False), radii, RunConfig(model="fem"))
    # the same solids' opening under the pressure alone (the shear traction's columns dropped)
    paraboloid = FECompliance(full.solids, full.unit_matrix, eps, None, full.unit_surface_sum)
    fe_mode_one = mode_one_elasticity(widest, full)
    print(f"eps = {eps:g}: FE solids built in {time.perf_counter() - start:.0f} s", flush=True)
    built = {
        "couette": (half_space, None),
        "sliding film": (half_space, mode_one_elasticity(widest, half_space)),
        "FE, paraboloid": (paraboloid, fe_mode_one),
        "FE, full": (full, fe_mode_one),
    }
    return built, (fe_mode_one.close, full.close)


def collision_row(eps, St, label, compliance, mode_one):
    """One collision as a row; a film that closes on the grid (or any failed integration) is
    recorded as failed."""
    _, tangential, theory_gap = MODELS[label]
    params = parameters(eps, St, theory_gap)
    row = {"eps": eps, "St": float(St), "model": label}
    start = time.perf_counter()
    try:
        r = collide(
            params,
            RunConfig.from_settings(tangential=tangential),
            compliance=compliance,
            mode_one=mode_one,
        )
    except NormalSolverError as err:
        print(f"eps={eps:g} St={St:8.3f} {label:15s} failed: {err}", flush=True)
        return {**row, "status": f"failed: {type(err).__name__}"}
    t = r.tangential
    row.update(
        status="ok",
        rebound=r.normal.rebound,
        e_n=r.normal.e_n,
        e_t=t.e_t,
        spin_change=t.spin_change,
        at=t.at,
        tangential_balance_error="" if t.energy is None else t.energy.balance_error,
        superposition_flag=r.summary().get("superposition_flag", ""),
        film_nodes=len(r.normal.radii),
        seconds=round(time.perf_counter() - start, 2),
    )
    print(
        f"eps={eps:g} St={St:8.3f} {label:15s} e_n={r.normal.e_n:.4f} e_t={t.e_t:.6f} "
        f"spin={t.spin_change:.5f} ({row['seconds']} s)",
        flush=True,
    )
    return row


def run():
    table = ResultTable(TABLE, ("eps", "St", "model"))
    for eps in ELASTICITY:
        missing = [
            (St, label)
            for St in STOKES
            for label in MODELS
            if table.get(eps=eps, St=float(St), model=label) is None
        ]
        if not missing:
            continue
        built, closers = solids(eps)
        try:
            for St, label in missing:
                table.add(collision_row(eps, St, label, *built[label]))
        finally:
            for close in closers:
                close()
    return table.rows


def number(value):
    return float(value) if value not in (None, "", "None") else math.nan


def plot(rows, figure):
    """1 - e_t, the spin change and (1 - e_t) relative to the Couette model against St: lines
    through the rebounds, open circles at the sticking spheres (their state at stop; the third
    panel's range is that of the rebounds)."""
    fig, (ax_e, ax_s, ax_r) = plt.subplots(1, 3, figsize=(16, 4.8))
    couette = {
        (float(r["eps"]), float(r["St"])): number(r.get("e_t"))
        for r in rows
        if r["model"] == "couette"
    }
    rebound_ratios = []
    for eps, colour in COLOURS.items():
        for label, style in STYLES.items():
            sel = [r for r in rows if float(r["eps"]) == eps and r["model"] == label]
            st = np.array([float(r["St"]) for r in sel])
            loss = 1 - np.array([number(r.get("e_t")) for r in sel])
            spin = np.array([number(r.get("spin_change")) for r in sel])
            ratio = loss / np.array([1 - couette.get((eps, s), math.nan) for s in st])
            stuck = np.array([r.get("at") == "stop" for r in sel], dtype=bool)
            rebound_ratios += list(ratio[~stuck])
            for ax, values in ((ax_e, loss), (ax_s, spin), (ax_r, ratio)):
                ax.loglog(st[~stuck], values[~stuck], style, color=colour)
                ax.loglog(st[stuck], values[stuck], "o", ms=4, mfc="none", color=colour)
    ax_r.set_yscale("linear")
    low, high = np.nanmin(rebound_ratios), np.nanmax(rebound_ratios)
    ax_r.set_ylim(low - 0.05 * (high - low), high + 0.05 * (high - low))
    ax_e.set_ylabel("1 - e_t (e_t: tangential restitution)")
    ax_s.set_ylabel(r"spin change a$\Delta\Omega/U_0$")
    ax_r.set_ylabel("(1 - e_t) / (1 - e_t of the Couette model)")
    for ax in (ax_e, ax_s, ax_r):
        ax.set_xlabel("St")
        ax.grid(alpha=0.3, which="both")
    colours = [Line2D([], [], color=c, label=f"eps = {eps:g}") for eps, c in COLOURS.items()]
    styles = [Line2D([], [], color="k", ls=s, label=label) for label, s in STYLES.items()]
    ax_e.legend(handles=colours, fontsize=8)
    ax_r.legend(handles=styles, fontsize=8)
    fig.suptitle(
        f"thin layer, delta = 0.01, P_cav = -10, 30 deg, {NODES} film nodes; "
        "open circles: the sphere sticks (state at stop)"
    )
    fig.tight_layout()
    figure.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(figure, dpi=120)


if __name__ == "__main__":
    study_script(ROOT, "tangential_vs_stokes", run, plot, load="--plot-only" in sys.argv)
