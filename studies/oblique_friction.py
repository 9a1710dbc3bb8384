"""psi_out against psi_in and the effective friction of a smooth and a rough sphere.

A steel sphere (a = 6.35 mm) hits a Zerodur wall through a 0.5 mm layer of 80 % glycerol at
|v| = 0.3 m/s and angles of 5 to 75 degrees from the normal (half-space solids, the sliding
film "lubrication", 120 film nodes, e_dry = 0.9, no initial spin; the issue's example is the
45 degree row). psi = contact-point tangential velocity over the normal speed at first touch:
psi_in = tan(angle). Every collision is computed in full:

- smooth: the film alone (sigma = 0);
- impact: a rough sphere (sigma = 1e-3 a) whose asperities end the approach in a solid impact
  with e_dry, Coulomb friction mu = 0.15 there (run setting asperities = "impact");
- greenwood-tripp: the same roughness with Greenwood & Tripp's asperity pressure sharing the
  load (asperities = "greenwood-tripp", default asperity density and slope), the asperities'
  load carrying Coulomb friction mu;
- each rough model also with mu = 0: the film alone on the rough sphere's normal motion;
- dry: the rigid-body closed form psi_out = psi_in - (1 + 1/k) mu (1 + e_dry), 0 once that is
  reached (stick), and mu_eff = min(mu, psi_in / ((1 + 1/k)(1 + e_dry))).

`solid_impulse_share` is the solids' share of the normal impulse (ehdfem.outputs.registry):
with the contact sliding throughout, mu_eff = mu share plus the film's own.

Writes studies/results/oblique_friction.csv (resumable) and docs/figures/oblique_friction.png.
Run: .venv/bin/python studies/oblique_friction.py [--plot-only]   (a few minutes)
"""

import math
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from ehdfem.collision import collide  # noqa: E402
from ehdfem.exact.rigid_impact import frictional_impact  # noqa: E402
from ehdfem.inputs.scales import from_presets  # noqa: E402
from ehdfem.outputs import registry  # noqa: E402
from ehdfem.study.sweep import ResultTable, study_script  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
TABLE = ROOT / "studies" / "results" / "oblique_friction.csv"
ANGLES = (5.0, 10.0, 20.0, 30.0, 40.0, 45.0, 50.0, 60.0, 70.0, 75.0)
FRICTION = 0.15  # an illustrative dry Coulomb coefficient
E_DRY = 0.9
ROUGHNESS = 1e-3  # sigma / a
RADIUS, LAYER = 6.35e-3, 0.5e-3
NODES = 120
MODELS = ("smooth", "impact", "greenwood-tripp")
KEPT = (
    "e_n", "e_t", "psi_out", "effective_friction", "min_film_thickness", "contact_stuck",
    "impact_psi_in", "impact_psi_out", "solid_impact_velocity", "solid_impulse_share",
    "friction_dissipated", "tangential_balance_error", "tangential_energy_gain",
)  # fmt: skip


def collision(angle, roughness, friction, asperities="impact"):
    """The physical inputs at ``angle`` [deg], sphere roughness [m], Coulomb mu, asperity
    model."""
    return from_presets(
        sphere="steel",
        wall="zerodur",
        liquid="glycerol_80",
        radius=RADIUS,
        speed=0.3,
        angle=angle,
        layer_thickness=LAYER,
        e_dry=E_DRY,
        sphere_roughness=roughness,
        friction_coefficient=friction,
        asperities=asperities,
    )


def outcome(angle, model, friction):
    """The kept outputs of one collision (``model`` one of MODELS)."""
    roughness = 0.0 if model == "smooth" else ROUGHNESS * RADIUS
    asperities = "impact" if model == "smooth" else model
    result = collide(
        collision(angle, roughness, friction, asperities),
        nodes=NODES,
        tangential="lubrication",
    )
    out = registry.computed(result)
    return result.params, {key: out.get(key) for key in KEPT}


def angle_row(angle):
    """One angle: the outputs of the smooth sphere, and of each rough model with mu and without."""
    params, smooth = outcome(angle, "smooth", 0.0)  # smooth: mu never acts, refused
    row = {
        "angle": angle,
        "St": params.St,
        "eps": params.eps,
        "psi_in": math.tan(math.radians(angle)),
    }
    row.update({f"smooth_{key}": value for key, value in smooth.items()})
    for model in MODELS[1:]:
        name = model.replace("-", "_")
        row.update(
            {f"{name}_{key}": value for key, value in outcome(angle, model, FRICTION)[1].items()}
        )
        film_alone = outcome(angle, model, 0.0)[1]
        row.update(
            {
                f"{name}_film_{key}": film_alone[key]
                for key in ("e_t", "psi_out", "effective_friction")
            }
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


def column(rows, key):
    return np.array([number(r.get(key)) for r in rows])


def plot(rows, figure):
    """psi_out against psi_in, and the effective friction against psi_in: smooth, the two
    rough models (with mu, and the film alone on their normal motion), dry."""
    psi = column(rows, "psi_in")
    k = 0.4
    dense = np.linspace(0.0, psi.max() * 1.02, 200)
    dry = [frictional_impact(p, FRICTION, E_DRY, k)[0] for p in dense]
    dry_friction = np.minimum(FRICTION, dense / ((1 + 1 / k) * (1 + E_DRY)))
    fig, (ax_psi, ax_mu) = plt.subplots(1, 2, figsize=(12, 4.8))
    ax_psi.plot(dense, dense, ":", color="grey", label="psi_out = psi_in (no friction)")
    ax_psi.plot(dense, dry, "-", color="k", label=f"dry rigid impact, mu = {FRICTION}")
    ax_mu.semilogy(dense[1:], dry_friction[1:], "-", color="k", label="dry rigid impact")
    curves = (
        ("smooth", "o", "C0", "smooth: film only"),
        ("impact", "s", "C1", f"rough, impact model, mu = {FRICTION}"),
        ("greenwood_tripp", "^", "C2", f"rough, Greenwood-Tripp, mu = {FRICTION}"),
        ("impact_film", "x", "C1", "rough, impact model, mu = 0 (film alone)"),
        ("greenwood_tripp_film", "+", "C2", "rough, Greenwood-Tripp, mu = 0 (film alone)"),
    )
    for name, marker, colour, label in curves:
        ax_psi.plot(psi, column(rows, f"{name}_psi_out"), marker, color=colour, label=label)
        mu = column(rows, f"{name}_effective_friction")
        ax_mu.semilogy(psi, mu, marker, color=colour, label=label)
    share = column(rows, "greenwood_tripp_solid_impulse_share")
    ax_mu.semilogy(
        psi, FRICTION * share, "--", color="C2", label="Greenwood-Tripp: mu x solid share"
    )
    ax_psi.set_xlabel("psi_in = (U0 - a Omega0) / V0")
    ax_psi.set_ylabel("psi_out = contact-point slip at exit / V0")
    ax_mu.set_xlabel("psi_in")
    ax_mu.set_ylabel("effective friction: tangential / normal impulse")
    for ax in (ax_psi, ax_mu):
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=7)
    fig.suptitle(
        "steel (a = 6.35 mm) on Zerodur through 0.5 mm of 80 % glycerol, |v| = 0.3 m/s, "
        f"e_dry = {E_DRY}, sigma = {ROUGHNESS:g} a, sliding film, {NODES} nodes"
    )
    fig.tight_layout()
    figure.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(figure, dpi=120)


if __name__ == "__main__":
    study_script(ROOT, "oblique_friction", run, plot, load="--plot-only" in sys.argv)
