"""Coatings and two spheres against the half-space: the FE solids' elasticity alone, vs delta.

St = 10, eps = 1e-3 (defined with the substrate), thin layer, P_cav = -2, 30 degrees, Couette
tangential model, 120 film nodes. Every model uses the paraboloid gap and the pressure alone,
so the cases differ from the half-space in their elasticity only (the exact gap and the shear
traction are measured by studies/validity_map.py). FE geometries: bare wall; soft (E/5) and
hard (5 E) coatings of thickness 0.3 and 3 contact-radius scales sqrt(delta) a; two spheres of
equal and unequal (4:1) size. Writes studies/results/fem_vs_halfspace.csv and
docs/figures/fem_vs_halfspace.png.
Run: .venv/bin/python studies/fem_vs_halfspace.py [--plot-only]   (about 5 minutes)
"""

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from ehdfem.collision import collide  # noqa: E402
from ehdfem.config import RunConfig
from ehdfem.inputs.scales import CollisionParameters  # noqa: E402
from ehdfem.study.sweep import study_script  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
DELTAS = (0.001, 0.003, 0.01, 0.03, 0.1)
CASES = {
    "half-space": ("halfspace", None),
    "FE wall": ("fem", None),
    "soft coating, t = 0.3 sqrt(delta) a": ("fem", ("coated", 0.2, 0.3)),
    "soft coating, t = 3 sqrt(delta) a": ("fem", ("coated", 0.2, 3.0)),
    "hard coating, t = 0.3 sqrt(delta) a": ("fem", ("coated", 5.0, 0.3)),
    "hard coating, t = 3 sqrt(delta) a": ("fem", ("coated", 5.0, 3.0)),
    "two spheres 1:1": ("fem", ("sphere", 1.0)),
    "two spheres 4:1": ("fem", ("sphere", 4.0)),
}


def lower_body(spec, delta):
    """The run settings of a case's lower body (the coating's modulus by the wall's)."""
    if spec is None:
        return {}
    if spec[0] == "sphere":
        return {"lower": "sphere", "radius_ratio": spec[1]}
    return {
        "lower": "coated",
        "coating_stiffness": spec[1],
        "coating_poisson": 0.3,
        "coating_thickness": spec[2] * np.sqrt(delta),
    }


def run():
    rows = []
    for delta in DELTAS:
        params = CollisionParameters.from_settings(
            St=10.0,
            eps=1e-3,
            delta=delta,
            layer="thin",
            p_cav=-2.0,
            angle=30.0,
            gap="paraboloid",
            shear_traction=False,
        )
        for name, (model, spec) in CASES.items():
            r = collide(
                params,
                RunConfig.from_settings(model=model, nodes=120, **lower_body(spec, delta)),
            )
            rows.append(
                {
                    "delta": delta,
                    "case": name,
                    "e_n": r.normal.e_n,
                    "e_t": r.tangential.e_t,
                    "min_film_thickness": r.normal.min_film_thickness,
                    "max_compression": r.normal.max_compression,
                }
            )
            print(
                f"delta={delta:g} {name:36s} e_n={r.normal.e_n:.5f} e_t={r.tangential.e_t:.6f} "
                f"H_min={r.normal.min_film_thickness:.5f}",
                flush=True,
            )
    return rows


def plot(rows, figure):
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.5))
    for i, name in enumerate(CASES):
        sel = [r for r in rows if r["case"] == name]
        style = "k-" if name == "half-space" else f"C{i}o-"
        for ax, key in zip(axes, ("e_n", "e_t", "min_film_thickness"), strict=True):
            ax.semilogx(
                [float(r["delta"]) for r in sel],
                [float(r[key]) for r in sel],
                style,
                ms=4,
                label=name,
            )
    for ax, label in zip(axes, ("e_n", "e_t", "minimum film thickness H_min (by x0)"), strict=True):
        ax.set_xlabel("delta = x0 / a")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3, which="both")
    axes[0].legend(fontsize=7)
    fig.suptitle("St = 10, eps = 1e-3, thin layer, P_cav = -2: half-space theory against FE solids")
    fig.tight_layout()
    figure.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(figure, dpi=120)


if __name__ == "__main__":
    study_script(ROOT, "fem_vs_halfspace", run, plot, load="--plot-only" in sys.argv)
