"""psi_out against psi_in and the effective friction of a smooth and a rough sphere.

A steel sphere (a = 6.35 mm) hits a Zerodur wall through a 0.5 mm layer of 80 % glycerol at
|v| = 0.3 m/s and angles of 5 to 75 degrees from the normal (half-space solids, the sliding
film "lubrication", 120 film nodes, e_dry = 0.9, no initial spin). psi = contact-point
tangential velocity over the normal speed at first touch: psi_in = tan(angle).

- smooth: the film alone (the collision as computed);
- rough: the same normal motion with a solid impact where the thinnest film first reaches
  sigma = 1e-3 a (SolidImpact at that step, approach velocity V_c, normal impulse
  St (1 + e_dry) |V_c|) and Coulomb friction mu = 0.15 there (ehdfem.tangential.friction). The
  normal motion after the impact is the smooth one's (the impact model of the normal motion is
  a separate part: once it is in, the study runs it instead); its normal impulse is therefore
  taken as that of a rough collision, m V0 (1 + e_dry |V_c|), in the effective friction;
- dry: the rigid-body closed form psi_out = psi_in - (1 + 1/k) mu (1 + e_dry), 0 once that is
  reached (stick), and mu_eff = min(mu, psi_in / ((1 + 1/k)(1 + e_dry))).

Writes studies/results/oblique_friction.csv (resumable) and docs/figures/oblique_friction.png.
Run: .venv/bin/python studies/oblique_friction.py [--plot-only]   (about a minute)
"""

import math
import sys
from dataclasses import replace
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from ehdfem.collision import collide, with_tangential  # noqa: E402
from ehdfem.inputs.scales import from_presets  # noqa: E402
from ehdfem.motion.normal import SolidImpact  # noqa: E402
from ehdfem.outputs import registry  # noqa: E402
from ehdfem.study.sweep import ResultTable, study_script  # noqa: E402
from ehdfem.tangential.friction import rigid_impact  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
TABLE = ROOT / "studies" / "results" / "oblique_friction.csv"
ANGLES = (5.0, 10.0, 20.0, 30.0, 40.0, 50.0, 60.0, 70.0, 75.0)
FRICTION = 0.15  # an illustrative dry Coulomb coefficient
E_DRY = 0.9
ROUGHNESS = 1e-3  # sigma / a
RADIUS, LAYER = 6.35e-3, 0.5e-3
NODES = 120


def collision(angle):
    """The physical inputs at ``angle`` [deg]."""
    return from_presets(
        sphere="steel",
        wall="zerodur",
        liquid="glycerol_80",
        radius=RADIUS,
        speed=0.3,
        angle=angle,
        layer_thickness=LAYER,
        e_dry=E_DRY,
    )


def roughened(result):
    """``result`` with the solid impact where its thinnest film first reaches sigma (by x0)
    and the friction coefficient FRICTION; None if the film never gets that thin."""
    normal = result.normal
    reached = np.flatnonzero(normal.history.min_film <= ROUGHNESS * RADIUS / LAYER)
    if reached.size == 0:
        return None
    index = int(reached[0])
    velocity = float(normal.history.velocity[index])
    params = replace(result.params, friction_coefficient=FRICTION)
    impulse = params.St * (1.0 + E_DRY) * abs(velocity)
    impact = SolidImpact(index, float(normal.history.time[index]), velocity, impulse)
    rough = replace(normal, params=params, solid_impact=impact)
    return replace(result, params=params, normal=rough)


def angle_row(angle):
    """One angle: psi_out and the effective friction, smooth and rough."""
    smooth = collide(collision(angle), nodes=NODES, tangential="lubrication")
    out = registry.computed(smooth)
    row = {
        "angle": angle,
        "St": smooth.params.St,
        "eps": smooth.params.eps,
        "psi_in": out["psi_in"],
        "smooth_psi_out": out["psi_out"],
        "smooth_e_t": out["e_t"],
        "smooth_e_n": out["e_n"],
        "smooth_effective_friction": out["effective_friction"],
        "min_film_thickness": out["min_film_thickness"],
    }
    rough = roughened(smooth)
    if rough is not None:
        rough = with_tangential(rough, "lubrication")
        tangential, impact = rough.tangential, rough.normal.solid_impact
        tangent = rough.params.tangential_speed
        rough_out = registry.computed(rough)
        row.update(
            impact_velocity=impact.approach_velocity,
            impact_psi_in=rough_out["impact_psi_in"],
            impact_psi_out=rough_out["impact_psi_out"],
            contact_stuck=rough_out["contact_stuck"],
            rough_psi_out=rough_out["psi_out"],
            rough_e_t=tangential.e_t,
            rough_effective_friction=tangent
            * (1.0 - tangential.e_t)
            / (1.0 + E_DRY * abs(impact.approach_velocity)),
        )
    print(f"angle {angle:4.1f}: {row}", flush=True)
    return row


def run():
    table = ResultTable(TABLE, ("angle",))
    for angle in ANGLES:
        if table.get(angle=angle) is None:
            table.add(angle_row(angle))
    return table.rows


def number(value):
    return float(value) if value not in (None, "", "None") else math.nan


def plot(rows, figure):
    """psi_out against psi_in, and the effective friction against psi_in: smooth, rough, dry."""
    psi = np.array([number(r["psi_in"]) for r in rows])
    k = 0.4
    dense = np.linspace(0.0, psi.max() * 1.02, 200)
    dry = [rigid_impact(p, FRICTION, E_DRY, k)[0] for p in dense]
    dry_friction = np.minimum(FRICTION, dense / ((1 + 1 / k) * (1 + E_DRY)))
    fig, (ax_psi, ax_mu) = plt.subplots(1, 2, figsize=(12, 4.8))
    ax_psi.plot(dense, dense, ":", color="grey", label="psi_out = psi_in (no friction)")
    ax_psi.plot(dense, dry, "-", color="k", label=f"dry rigid impact, mu = {FRICTION}")
    ax_mu.plot(dense, dry_friction, "-", color="k", label="dry rigid impact")
    for name, marker, label in (
        ("smooth", "o", "smooth: film only"),
        ("rough", "s", f"rough: sigma = {ROUGHNESS:g} a, impact with mu = {FRICTION}"),
    ):
        ax_psi.plot(psi, [number(r.get(f"{name}_psi_out")) for r in rows], marker, label=label)
        ax_mu.semilogy(
            psi, [number(r.get(f"{name}_effective_friction")) for r in rows], marker, label=label
        )
    ax_psi.set_xlabel("psi_in = (U0 - a Omega0) / V0")
    ax_psi.set_ylabel("psi_out = contact-point slip at exit / V0")
    ax_mu.set_xlabel("psi_in")
    ax_mu.set_ylabel("effective friction: tangential / normal impulse")
    for ax in (ax_psi, ax_mu):
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=8)
    fig.suptitle(
        "steel (a = 6.35 mm) on Zerodur through 0.5 mm of 80 % glycerol, |v| = 0.3 m/s, "
        f"e_dry = {E_DRY}, sliding film, {NODES} nodes"
    )
    fig.tight_layout()
    figure.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(figure, dpi=120)


if __name__ == "__main__":
    study_script(ROOT, "oblique_friction", run, plot, load="--plot-only" in sys.argv)
