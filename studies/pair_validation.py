"""Two free spheres colliding obliquely: the full model beside the reduced models of CFD-DEM
codes (docs/validation.md, "Two spheres obliquely: the reduced CFD-DEM models").

Glass-glass and steel-steel pairs, equal (a1 = a2) and unequal (a1 = 2 a2), in water and in
glycerol, at three Stokes numbers (the normal impact speed chosen to give them), two layer
thicknesses (x0 = 0.01 a and 0.03 a, a the reduced radius: two eps) and three angles of the
relative impact velocity from the line of centres. For each: e_n, e_t and both spheres' spin
changes of
- the full model: the half-space theory of the pair with the Couette film
  (ehdfem.tangential.pair), smooth and pure EHD (e_dry = 1), the liquid's vapour pressure as
  its cavitation limit, the default film nodes;
- the lubrication model with a fixed minimum gap h_min = 0.002 a, the cut-off 0.001 (2 a) of
  Zhang, Noda & Horio (2005) (ehdfem.dem.reduced.lubrication);
- the same with Nijssen, Ottens & Padding's (2022) EHD film h_eps as the minimum gap
  (ehdfem.dem.reduced.ehd_gap);
both reduced models with Hertz's contact and Coulomb friction mu = 0.1 below their gap, and
again without friction.
Writes studies/results/pair_validation.csv (every point) and studies/results/pair_validation.md
(the table at 45 deg and the spread over the angles). Run: .venv/bin/python
studies/pair_validation.py (about two minutes on one core).
"""

import csv
import math
import time
from dataclasses import replace
from pathlib import Path

from ehdfem import collide
from ehdfem.dem.reduced.ehd_gap import ehd_gap_collision, ehd_minimum_gap
from ehdfem.dem.reduced.lubrication import ReducedCollision, reduced_collision
from ehdfem.inputs.presets import liquid, material
from ehdfem.inputs.scales import PhysicalPair, reduced_mass, reduced_radius
from ehdfem.study.sweep import write_atomic
from ehdfem.tangential.pair import SpherePair

ROOT = Path(__file__).resolve().parents[1]
CSV = ROOT / "studies/results/pair_validation.csv"
MARKDOWN = ROOT / "studies/results/pair_validation.md"
MATERIALS = ("glass", "steel")
RATIOS = (1.0, 2.0)  # a1/a2
LOWER_RADII = {"water": 1e-3, "glycerol": 10e-3}  # a2 [m]: St of order 10 at speeds below 10 m/s
STOKES = (5.0, 20.0, 80.0)
LAYERS = (0.01, 0.03)  # x0 / a
ANGLES = (15.0, 45.0, 75.0)  # deg
FRICTION = 0.1
FIXED_GAP = 0.002  # h_min / a: Zhang, Noda & Horio (2005)
MODELS = ("full", "lubrication", "ehd_gap")  # in the table; in the CSV also the reduced
# models without friction, "lubrication_frictionless" and "ehd_gap_frictionless"
OUTPUTS = ("e_n", "e_t", "upper_spin_change", "lower_spin_change")


def pair_at(name: str, fluid: str, ratio: float, St: float, layer: float, angle: float):
    """The :class:`PhysicalPair` of ``name`` spheres in ``fluid`` with a1/a2 = ``ratio`` whose
    normal impact speed gives ``St`` (V0 = St 6 pi mu a^2 / m), x0 = ``layer`` a."""
    solid, liq = material(name), liquid(fluid)
    lower = LOWER_RADII[fluid]
    upper = ratio * lower
    a = reduced_radius(upper, lower)
    volumes = [4.0 / 3.0 * math.pi * r**3 for r in (upper, lower)]
    m = reduced_mass(*(v * solid.density for v in volumes))
    normal_speed = St * 6.0 * math.pi * liq.viscosity * a**2 / m
    return PhysicalPair(
        upper_radius=upper, lower_radius=lower, upper=solid, lower=solid, liquid=liq,
        speed=normal_speed / math.cos(math.radians(angle)), layer_thickness=layer * a,
        angle=angle,
    )  # fmt: skip


def full_model(pair: PhysicalPair) -> dict:
    """e_n, e_t and both spin changes of the full model, and its thinnest film (by x0)."""
    result = collide(pair.dimensionless(), **pair.lower_settings())
    tangential = result.tangential
    return dict(
        e_n=result.normal.e_n,
        e_t=tangential.e_t,
        upper_spin_change=tangential.spin_change,
        lower_spin_change=tangential.pair.lower_spin_change,
        film=result.normal.min_film_thickness,
    )


def reduced_models(pair: PhysicalPair) -> dict:
    """The outcomes of both reduced models (the full model's groups, the pair's masses), with
    the friction coefficient FRICTION and without friction."""
    params = pair.dimensionless()
    m1, m2 = pair.masses
    inputs = ReducedCollision(
        St=params.St, eps=params.eps, delta=params.delta, angle=params.angle,
        minimum_gap=FIXED_GAP / params.delta, friction_coefficient=FRICTION,
        radius_ratio=pair.upper_radius / pair.lower_radius,
        pair=SpherePair(m1 / m2, pair.upper_inertia_factor, pair.lower_inertia_factor),
    )  # fmt: skip
    frictionless = replace(inputs, friction_coefficient=0.0)
    return dict(
        lubrication=reduced_collision(inputs),
        ehd_gap=ehd_gap_collision(inputs),
        lubrication_frictionless=reduced_collision(frictionless),
        ehd_gap_frictionless=ehd_gap_collision(frictionless),
    )


def rows():
    """Every point of the study, as dicts for the CSV."""
    for name in MATERIALS:
        for fluid in LOWER_RADII:
            for ratio in RATIOS:
                for St in STOKES:
                    for layer in LAYERS:
                        for angle in ANGLES:
                            yield point(name, fluid, ratio, St, layer, angle)


def point(name, fluid, ratio, St, layer, angle) -> dict:
    """One row: the inputs, the groups and each model's outputs."""
    pair = pair_at(name, fluid, ratio, St, layer, angle)
    params = pair.dimensionless()
    full = full_model(pair)
    row = dict(
        material=name, liquid=fluid, radius_ratio=ratio, St=St, layer=layer, angle=angle,
        speed=pair.speed, eps=params.eps, full_film=full["film"],
        fixed_gap=FIXED_GAP / layer, ehd_gap=ehd_minimum_gap(params.eps),
    )  # fmt: skip
    row.update({f"full_{key}": full[key] for key in OUTPUTS})
    for model, outcome in reduced_models(pair).items():
        row.update({f"{model}_{key}": getattr(outcome, key) for key in OUTPUTS})
    return row


def markdown(table) -> str:
    """The table at 45 deg (every pair, liquid, St and layer) and, below it, the largest
    differences from the full model over all angles."""
    head = (
        "| pair | liquid | St | x0/a | v [m/s] | eps | H_film full | H_min lub. / EHD "
        "| e_n full / lub. / EHD | e_t full / lub. / EHD | Δs1 full / lub. / EHD "
        "| Δs2 full / lub. / EHD |"
    )
    lines = [head, "|" + "---|" * 12]
    for r in (r for r in table if r["angle"] == 45.0):
        pair = f"{r['material']} {'a1 = a2' if r['radius_ratio'] == 1.0 else 'a1 = 2 a2'}"
        cells = [pair, r["liquid"], f"{r['St']:g}", f"{r['layer']:g}", f"{r['speed']:.3g}",
                 f"{r['eps']:.2g}", f"{r['full_film']:.3g}",
                 f"{r['fixed_gap']:.3g} / {r['ehd_gap']:.2g}"]  # fmt: skip
        for key in OUTPUTS:
            cells.append(" / ".join(f"{r[f'{model}_{key}']:.3f}" for model in MODELS))
        lines.append("| " + " | ".join(cells) + " |")
    lines += ["", "| model | output | largest difference from the full model (all angles) |"]
    lines.append("|---|---|---|")
    for model in (*MODELS[1:], "lubrication_frictionless", "ehd_gap_frictionless"):
        for key in OUTPUTS:
            worst = max(table, key=lambda r: abs(r[f"{model}_{key}"] - r[f"full_{key}"]))
            difference = worst[f"{model}_{key}"] - worst[f"full_{key}"]
            where = (
                f"{worst['material']}, {worst['liquid']}, a1/a2 {worst['radius_ratio']:g}, "
                f"St {worst['St']:g}, x0/a {worst['layer']:g}, {worst['angle']:g} deg"
            )
            lines.append(f"| {model} | {key} | {difference:+.3f} ({where}) |")
    return "\n".join(lines) + "\n"


def main():
    start = time.process_time()
    table = []
    for row in rows():
        table.append(row)
        print(
            f"{row['material']} {row['liquid']} {row['radius_ratio']:g} St {row['St']:g} "
            f"x0/a {row['layer']:g} {row['angle']:g} deg: e_n "
            + " ".join(f"{row[f'{m}_e_n']:.3f}" for m in MODELS)
            + ", e_t "
            + " ".join(f"{row[f'{m}_e_t']:.3f}" for m in MODELS),
            flush=True,
        )
    with CSV.open("w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(table[0]))
        writer.writeheader()
        writer.writerows(table)
    write_atomic(MARKDOWN, markdown(table))
    print(f"{len(table)} points in {time.process_time() - start:.0f} s CPU")


if __name__ == "__main__":
    main()
