"""Where the sliding film's mode-1 superposition holds: the 2-D disk film against it.

For eps = 1e-5, 1e-3, 0.1, St = 20, 1000 and no cavitation limit, P_cav = -10, -1 (thin layer,
delta = 0.01, 30 degrees, the sliding film with the mode-1 gap, 120 film nodes), each collision
reports its indicators (ehdfem.tangential.superposition: cavitation-rule sensitivity, tilt,
overlap) and the 2-D film is solved at its default instants (largest normal and tangential force,
strongest suction, largest overlap) on two meshes. One row per instant in
studies/results/superposition_map.csv; docs/figures/superposition_map.png.
Run: .venv/bin/python studies/superposition_map.py [--plot-only]   (about 10 minutes)
"""

import sys
import warnings
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from ehdfem.collision import collide  # noqa: E402
from ehdfem.config import RunConfig
from ehdfem.inputs.scales import CollisionParameters  # noqa: E402
from ehdfem.study.sweep import study_script  # noqa: E402
from ehdfem.tangential.superposition import SuperpositionWarning, check_superposition  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
ELASTICITY = (1e-5, 1e-3, 1e-1)
STOKES = (20.0, 1000.0)
SUCTION = (-np.inf, -10.0, -1.0)
CONCLUSIVE = 0.1  # a check decides when its 2-D moment changes by less than this on a coarser mesh


def run():
    rows = []
    for eps in ELASTICITY:
        for St in STOKES:
            for p_cav in SUCTION:
                params = CollisionParameters.from_settings(
                    St=St, eps=eps, delta=0.01, layer="thin", p_cav=p_cav, angle=30.0
                )
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore", SuperpositionWarning)
                    result = collide(
                        params, RunConfig.from_settings(nodes=120, tangential="lubrication")
                    )
                v = result.superposition
                case = {
                    "eps": eps,
                    "St": St,
                    "p_cav": p_cav,
                    "e_t": result.tangential.e_t,
                    "spin_change": result.tangential.spin_change,
                    "sensitivity": v.sensitivity,
                    "largest_tilt": v.largest_tilt,
                    "suction_overlap": v.suction_overlap,
                    "flagged": v.flagged,
                }
                for check in check_superposition(result):
                    rows.append(
                        {
                            **case,
                            "step": check.step,
                            "time": check.time,
                            "moment_film": check.moment[0],
                            "moment_disk": check.moment[1],
                            "moment_error": check.moment_error,
                            "slope_error": check.slope_error,
                            "mesh_change": check.mesh_change,
                            "lift": check.lift,
                            "base_error": check.base_error,
                            "step_overlap": check.overlap,
                            "step_tilt": check.tilt,
                        }
                    )
                    print(
                        f"eps={eps:g} St={St:g} P_cav={p_cav:g} step {check.step}: moment "
                        f"{check.moment[0]:.4g} (1-D) {check.moment[1]:.4g} (2-D), error "
                        f"{check.moment_error:.2e}, mesh change {check.mesh_change:.2e}, "
                        f"overlap {check.overlap:.2e}, tilt {check.tilt:.3f}",
                        flush=True,
                    )
                print(
                    f"  e_t {result.tangential.e_t:.6f}, sensitivity {v.sensitivity:.2e}, "
                    f"tilt {v.largest_tilt:.3f}, flagged {v.flagged}",
                    flush=True,
                )
    return rows


def plot(rows, figure):
    fig, (ax_o, ax_t) = plt.subplots(1, 2, figsize=(11, 4.5))
    for row in rows:
        error = max(float(row["moment_error"]), 1e-5)
        conclusive = float(row["mesh_change"]) < CONCLUSIVE
        colour = {1e-5: "C0", 1e-3: "C1", 1e-1: "C2"}[float(row["eps"])]
        style = {"mfc": colour if conclusive else "none", "color": colour}
        marker = "o" if float(row["St"]) < 100 else "s"
        ax_o.loglog(max(float(row["step_overlap"]), 1e-6), error, marker, **style)
        ax_t.loglog(max(float(row["step_tilt"]), 1e-4), error, marker, **style)
    ax_o.set_xlabel("suction overlap at the instant (1e-6: none)")
    ax_t.set_xlabel("tilt s|H1|/H0 at the instant")
    for ax in (ax_o, ax_t):
        ax.set_ylabel("2-D vs superposition: moment error")
        ax.grid(alpha=0.3, which="both")
    handles = [
        plt.Line2D([], [], color=c, marker="o", ls="", label=f"eps = {e:g}")
        for e, c in zip(ELASTICITY, ("C0", "C1", "C2"), strict=True)
    ]
    handles += [
        plt.Line2D([], [], color="k", marker="o", ls="", label="St = 20"),
        plt.Line2D([], [], color="k", marker="s", ls="", label="St = 1000"),
        plt.Line2D([], [], color="k", marker="o", mfc="none", ls="", label="mesh change > 10 %"),
    ]
    ax_o.legend(handles=handles, fontsize=7)
    fig.suptitle("thin layer, delta = 0.01, 30 degrees: 2-D film at the default instants")
    fig.tight_layout()
    figure.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(figure, dpi=120)


if __name__ == "__main__":
    study_script(ROOT, "superposition_map", run, plot, load="--plot-only" in sys.argv)
