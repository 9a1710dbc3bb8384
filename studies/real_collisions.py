"""Real thin-layer collisions: the half-space theory against the full FE model.

A bead of radius 1.5 mm (glass, chrome steel, acetal: presets with their sources in
ehdfem/inputs/presets.py) hits a glass plate at 30 degrees from the normal through a thin
layer of water (0.3 m/s), 50 wt% glycerol-water (0.5 m/s) or 10 cSt silicone oil (0.5 m/s),
x0 = 0.02, 0.05, 0.1, 0.2 and 0.5 radii (30 um ... 0.75 mm); the liquid cavitates at its vapour
pressure (truncation), no gravity, Couette tangential model, 120 film nodes, rtol 1e-5. Inputs
are physical (:class:`ehdfem.inputs.scales.PhysicalCollision`); each collision runs the five
models of :mod:`ehdfem.study.corrections` (theory, + true gap, + surface effects, both on
half-spaces, and the full FE model with the materials' own moduli and Poisson ratios), so the
difference full - theory comes with its causes. Films that would reach beyond 0.7 a (thick
layers: the wetted edge of a layer of x0 = delta a sits near r = a sqrt(2 delta)) are beyond
the FE solids: only the theory is given there.

Writes studies/results/real_collisions.csv (every model's outputs, scaled; resumable) and
prints the markdown table of docs/fem.md (SI values).
Run: nice -n 10 .venv/bin/python studies/real_collisions.py [--table-only]   (about 10 minutes)
"""

import math
import sys
from pathlib import Path

from ehdfem import film_radii  # noqa: E402
from ehdfem.config import RunConfig  # noqa: E402
from ehdfem.inputs.scales import from_presets  # noqa: E402
from ehdfem.study.corrections import (  # noqa: E402
    CAUSES,
    OUTPUTS,
    VARIANTS,
    cause_shares,
    run_model,
    run_variants,
)
from ehdfem.study.sweep import ResultTable  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
TABLE = ROOT / "studies" / "results" / "real_collisions.csv"
RADIUS, WALL, ANGLE = 1.5e-3, "glass", 30.0
SPHERES = ("glass", "steel", "acetal")
LIQUIDS = {"water": 0.3, "glycerol_50": 0.5, "silicone_oil_10cst": 0.5}
LAYERS = (0.02, 0.05, 0.1, 0.2, 0.5)
NODES, FE_LIMIT = 120, 0.7
CONFIG = RunConfig.from_settings(rtol=1e-5)


def physical(sphere, liquid, layer):
    """The collision's physical inputs (SI)."""
    return from_presets(
        sphere=sphere,
        wall=WALL,
        liquid=liquid,
        radius=RADIUS,
        speed=LIQUIDS[liquid],
        angle=ANGLE,
        layer_thickness=layer * RADIUS,
    )


def run_case(collision):
    """{variant: outputs} of the five models, or of the theory alone where the film reaches
    beyond the FE solids."""
    params = collision.dimensionless()
    materials = tuple(
        (m.young_modulus, m.poisson_ratio) for m in (collision.sphere, collision.wall)
    )
    if film_radii(params, NODES)[-1] * math.sqrt(params.delta) < FE_LIMIT:
        return run_variants(params, NODES, materials, CONFIG)
    radii = film_radii(params, NODES)
    return {"theory": run_model(params, "theory", radii, materials, CONFIG)}


def compute():
    table = ResultTable(TABLE, ("sphere", "liquid", "layer", "variant"))
    for sphere in SPHERES:
        for liquid in LIQUIDS:
            for layer in LAYERS:
                key = dict(sphere=sphere, liquid=liquid, layer=layer)
                if table.get(**key, variant="theory") is not None:
                    continue
                collision = physical(sphere, liquid, layer)
                params = collision.dimensionless()
                print(f"{sphere} through {liquid}, x0 = {layer:g} a", flush=True)
                groups = dict(St=params.St, eps=params.eps, delta=params.delta, P_cav=params.p_cav)
                for variant, values in run_case(collision).items():
                    table.add({**key, "variant": variant, **groups, **values})
    return table.rows


SHOWN = {  # output: (label, SI factor of the scales, SI unit shown)
    "e_n": ("e_n", lambda s: 1.0, ""),
    "min_film_thickness": ("H_min", lambda s: s.gap * 1e9, "nm"),
    "max_force": ("F_max", lambda s: s.force, "N"),
    "contact_time": ("t_c", lambda s: s.time * 1e6, "us"),
    "e_t": ("e_t", lambda s: 1.0, ""),
}


def markdown(rows):
    """The docs' table: per collision each output of the theory (SI) with the full model's
    difference (full - theory) / theory in %, and the cause with the largest share of the
    largest difference."""
    found = {}
    for row in rows:
        key = (row["sphere"], row["liquid"], float(row["layer"]))
        found.setdefault(key, {"groups": row})[row["variant"]] = {k: float(row[k]) for k in OUTPUTS}
    labels = [f"{label} {unit}".strip() for label, _, unit in SHOWN.values()]
    head = "| sphere | liquid | x0/a | St | eps | " + " | ".join(labels) + " | dominant cause |"
    lines = [head, "|" + "---|" * (6 + len(SHOWN))]
    for (sphere, liquid, layer), models in found.items():
        scales = physical(sphere, liquid, layer).scales()
        groups = models["groups"]
        cells = [sphere, liquid.replace("_", " "), f"{layer:g}", f"{float(groups['St']):.0f}",
                 f"{float(groups['eps']):.1e}"]  # fmt: skip
        shares = cause_shares(models) if set(VARIANTS) <= set(models) else None
        for key, (_, factor, _) in SHOWN.items():
            theory = f"{models['theory'][key] * factor(scales):.4g}"
            total = "" if shares is None else f" ({100 * shares['total'][key]:+.2f} %)"
            cells.append(theory + total)
        cells.append(_dominant(shares))
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)


def _dominant(shares):
    """'cause (output)' with the largest share of the output the theory misses most, or that
    the FE solids cannot hold the film."""
    if shares is None:
        return "film beyond the FE solids: theory only"
    output = max(SHOWN, key=lambda k: abs(shares["total"][k]))
    cause = max(CAUSES, key=lambda c: abs(shares[c][output]))
    return f"{cause} ({SHOWN[output][0]})"


def main():
    rows = ResultTable(TABLE, ()).rows if "--table-only" in sys.argv else compute()
    print(markdown(rows))


if __name__ == "__main__":
    main()
