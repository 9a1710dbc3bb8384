"""e_t and the spin change against St for several eps at delta = 0.01, both tangential models.

Thin layer, P_cav = -10, e_dry = 1, zero initial spin, 30 degrees (e_t does not depend on it).
Writes studies/results/tangential_vs_stokes.csv and docs/figures/tangential_vs_stokes.png.
Run: .venv/bin/python studies/tangential_vs_stokes.py [--plot-only]
"""

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from ehdfem.collision import collide  # noqa: E402
from ehdfem.scales import CollisionParameters  # noqa: E402
from ehdfem.study import study_script  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
STOKES = np.geomspace(3, 1000, 16)
ELASTICITY = (1e-5, 1e-3, 1e-1)
MODELS = ("couette", "lubrication")


def run():
    rows = []
    for eps in ELASTICITY:
        for St in STOKES:
            params = CollisionParameters(
                St=float(St), eps=eps, delta=0.01, layer="thin", p_cav=-10.0, angle=30.0
            )
            for model in MODELS:
                r = collide(params, tangential=model)
                rows.append(
                    {
                        "eps": eps,
                        "St": float(St),
                        "model": model,
                        "rebound": r.normal.rebound,
                        "e_n": r.normal.e_n,
                        "e_t": r.tangential.e_t,
                        "spin_change": r.tangential.spin_change,
                        "at": r.tangential.at,
                    }
                )
                print(
                    f"eps={eps:g} St={St:8.3f} {model:11s} e_n={r.normal.e_n:.4f} "
                    f"e_t={r.tangential.e_t:.5f} spin={r.tangential.spin_change:.5f}",
                    flush=True,
                )
    return rows


def plot(rows, figure):
    fig, (ax_e, ax_s) = plt.subplots(1, 2, figsize=(11, 4.5))
    for eps, colour in zip(ELASTICITY, ("C0", "C1", "C2"), strict=True):
        for model, style in zip(MODELS, ("-", "--"), strict=True):
            sel = [r for r in rows if float(r["eps"]) == eps and r["model"] == model]
            st = np.array([float(r["St"]) for r in sel])
            e_t = np.array([float(r["e_t"]) for r in sel])
            spin = np.array([float(r["spin_change"]) for r in sel])
            stuck = np.array([r["at"] == "stop" for r in sel])
            label = f"eps = {eps:g}, {model}"
            ax_e.semilogx(st, e_t, style, color=colour, label=label)
            ax_s.semilogx(st, spin, style, color=colour, label=label)
            ax_e.semilogx(st[stuck], e_t[stuck], "o", mfc="none", color=colour)
            ax_s.semilogx(st[stuck], spin[stuck], "o", mfc="none", color=colour)
    ax_e.set_ylabel("tangential restitution e_t")
    ax_s.set_ylabel(r"spin change a$\Delta\Omega/U_0$")
    for ax in (ax_e, ax_s):
        ax.set_xlabel("St")
        ax.grid(alpha=0.3, which="both")
    ax_e.legend(fontsize=7)
    fig.suptitle(
        "thin layer, delta = 0.01, P_cav = -10; open circles: the sphere sticks (state at stop)"
    )
    fig.tight_layout()
    figure.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(figure, dpi=120)


if __name__ == "__main__":
    study_script(ROOT, "tangential_vs_stokes", run, plot, load="--plot-only" in sys.argv)
