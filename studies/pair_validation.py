"""Two free spheres colliding obliquely: the full model beside the reduced models of CFD-DEM
codes (docs/validation.md, "Two spheres obliquely: the reduced CFD-DEM models").

Glass-glass and steel-steel pairs, equal (a1 = a2) and unequal (a1 = 2 a2), in water and in
glycerol, at three Stokes numbers (the normal impact speed chosen to give them), two layer
thicknesses (x0 = 0.01 a and 0.03 a, a the reduced radius: two eps) and three angles of the
relative impact velocity from the line of centres. For each: e_n, e_t and both spheres' spin
changes of
- the full model: the half-space theory of the pair with the sliding film (and with the
  Couette film, in the CSV; ehdfem.tangential.pair), smooth and pure EHD (e_dry = 1), the
  liquid's vapour pressure as its cavitation limit, the default film nodes;
- the lubrication model with a fixed minimum gap h_min = 0.002 a, the cut-off 0.001 (2 a) of
  Zhang, Noda & Horio (2005) (ehdfem.dem.reduced.lubrication);
- the same with Nijssen, Ottens & Padding's (2022) EHD film h_eps as the minimum gap
  (ehdfem.dem.reduced.ehd_gap);
both reduced models with Hertz's contact and Coulomb friction mu = 0.1 below their gap, and
again without friction.
Writes studies/results/pair_validation.csv (every point), studies/results/pair_validation.md
(the table at 45 deg and the largest differences over all angles) and the section "Two spheres
obliquely" at the end of docs/validation.md (replacing an earlier one). Run: .venv/bin/python
studies/pair_validation.py (171 s CPU measured); with the CSV present it only
rewrites the tables and the section from it, ``--rerun`` computes every point again.
"""

import csv
import math
import sys
import time
from dataclasses import replace
from pathlib import Path

from ehdfem import collide
from ehdfem.collision import with_tangential
from ehdfem.dem.reduced.ehd_gap import ehd_gap_collision, ehd_minimum_gap
from ehdfem.dem.reduced.lubrication import ReducedCollision, reduced_collision
from ehdfem.inputs.presets import liquid, material
from ehdfem.inputs.scales import PhysicalPair, reduced_mass, reduced_radius
from ehdfem.study.report import replace_section
from ehdfem.study.sweep import write_atomic
from ehdfem.tangential.pair import SpherePair

ROOT = Path(__file__).resolve().parents[1]
CSV = ROOT / "studies/results/pair_validation.csv"
MARKDOWN = ROOT / "studies/results/pair_validation.md"
REPORT = ROOT / "docs/validation.md"
SECTION = "## Two spheres obliquely: the reduced CFD-DEM models beside the full model"
DEM_ENGINES = "## DEM engines: Yade and LIGGGHTS against the full model"  # the section before
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

INTRODUCTION = [
    "Most collisions of a CFD-DEM simulation are between two particles, and the codes give them "
    "a reduced wet law rather than a film. `studies/pair_validation.py` runs two of these laws "
    "(ehdfem/dem/reduced/) beside the full model of the pair (the half-space theory with the "
    "reduced radius and mass and the sliding film of two spheres, the Couette shear of the slip "
    'and the mode-1 pressure of the surfaces\' entrainment, docs/tangential.md, "Two spheres";'
    " the Couette film alone is in the CSV as `couette_*`), on the same pairs and groups: "
    "glass-glass and steel-steel, equal (a1 = a2) and "
    "unequal (a1 = 2 a2), in water (a2 = 1 mm) and pure glycerol (a2 = 10 mm), St = 5, 20, 80 by "
    "the reduced mass (the normal impact speed chosen for it; v in the table), layers x0 = 0.01 a "
    "and 0.03 a (a the reduced radius; two eps per speed), angles 15, 45 and 75 degrees from the "
    "line of centres. The physical inputs of the pair are turned into the groups by "
    "`ehdfem.inputs.scales.PhysicalPair` (a, m, theta of both materials; tested against values "
    "computed by hand in tests/test_pair.py). The full model is smooth and pure EHD (e_dry = 1), "
    "its cavitation limit the liquid's vapour pressure, on the default 240 film nodes.",
    "",
    "- **lubrication** (`ehdfem.dem.reduced.lubrication`): the lubrication force of the CFD-DEM "
    "codes between the gap x0 and a fixed minimum gap h_min, the normal Reynolds force "
    "6 pi mu a^2 v/h and the tangential forces and torques of the two spheres at leading order "
    "in ln(a/h) (Jeffrey & Onishi 1984's two-sphere terms, Goldman, Cox & Brenner 1967's for a "
    "wall; `ehdfem.dem.reduced.resistances`); below h_min no lubrication, an elastic Hertz "
    "contact (the combined modulus of the pair) and Coulomb friction mu = 0.1 at the contact "
    "point, integrated through the collision for both spheres (normal, tangential and both "
    "spins). h_min = 0.002 a, the cut-off 0.001 (2 a) of Zhang, Noda & Horio 2005 (Powder "
    "Technol. 158) and Tomac & Gutierrez 2013 (Granular Matter 15) as a DEM code documents it: "
    "H_min = h_min/x0 = 0.2 and 0.067 for the two layers.",
    "- **EHD gap** (`ehdfem.dem.reduced.ehd_gap`): the same law with the minimum gap set to the "
    "EHD film h_eps = 0.37 ((mu v/E*)^2 a^3)^(1/5) of Nijssen, Ottens & Padding 2022, v the "
    "normal impact speed, 1/E* = sum (1 - nu^2)/E; scaled, H_eps = 0.37 (pi eps/4)^(2/5), the "
    "Davis, Serayssol & Hinch (1986) scaling x0 eps^(2/5) of the thinnest film. The paper's own "
    "text could not be obtained here: the formula is the one the project already compares with "
    'its thinnest film (docs/studies.md, "Rough surfaces"), and the law around it (the lubrication '
    "cut off at h_eps, an elastic Hertz contact and Coulomb friction below it) is the standard "
    "structure of a minimum-gap model, not checked against the paper's details (for instance "
    "whether it keeps a damping in the contact or takes e_dry there).",
    "",
    "Both reduced laws are checked against exact limits in tests/test_reduced_pair.py: their "
    "tangential forces are Jeffrey & Onishi's logarithmic resistances of the pair "
    "(`ehdfem.exact.sphere_pair`, tested in tests/test_pair_resistance.py); the approach "
    "V(H) = -1 + ln(1/H)/St, so e_n = 1 - 2 ln(1/H_min)/St or a stop (1e-11); Hertz's compression "
    "(2e-11) and contact time (Johnson's three digits); the energy over both spheres (3e-10); "
    "Coulomb's impulse law (1e-14) and the rolling exit 5/7 of a sticking equal pair; and H_eps "
    "against Nijssen's film in SI units. The last columns of the first table are the upper and "
    "lower spheres' spin changes a_i (Omega_i - Omega_i(0))/U0 (both about the same axis, "
    "docs/tangential.md); H_film full is the full model's thinnest film and H_min the reduced "
    "models' gaps, all by x0. Every point (all angles, and both reduced laws without friction) "
    "is in studies/results/pair_validation.csv.",
    "",
    "### The pairs at 45 degrees, and the largest differences over all angles (e_t and the "
    "spins where both models rebound)",
    "",
]
ANALYSIS = [
    "",
    "### What each reduced model gets right and wrong",
    "",
    "- **The normal restitution of the fixed gap is a number of the gap, not of the film.** The "
    "law dissipates only the rigid squeeze from x0 to h_min, twice: e_n = 1 - 2 ln(x0/h_min)/St "
    "(0.356, 0.839, 0.960 at x0 = 0.01 a for every material and liquid; 0, 0.729, 0.932 at "
    "0.03 a). It ignores eps: it is near the full model in glycerol (0.839 against 0.76-0.83 "
    "at St 20, 0.960 against 0.92-0.94 at St 80), where the elastic film of eps ~ 1e-3 keeps the "
    "surfaces at a gap of the order of h_min, and far above it in water (0.839 against "
    "0.40-0.49 at St 20), where the stiff film lets the surfaces come within 1e-4 to 7e-4 x0 and "
    "the squeeze below h_min dissipates most of the energy. At St 5 it rebounds (0.356) where "
    "the full model stops in water, and stops where the full model still rebounds for glass in "
    "glycerol at x0 = 0.03 a (0.21-0.25, from the elastic energy of the deformed solids that the "
    "rigid law does not store).",
    "- **The EHD gap is the right film thickness, but a rigid squeeze down to it dissipates too "
    "much.** H_eps is 0.74-1.04 times the full model's thinnest film wherever the full model "
    "rebounds (e.g. 1.07e-3 against 1.03e-3 for glass in water at St 80; 0.032 against 0.041 in "
    "glycerol at St 20): the minimum gap follows St and eps as the film does, which the fixed "
    "gap cannot. Yet e_n is low everywhere, by 0.016-0.033 at St 80 and 0.17-0.25 at St 20 (0.26 "
    "against 0.49 for glass in water), and the law stops at St 5 in glycerol where the full model "
    "rebounds with e_n 0.28-0.47. In the full model the deformation flattens the gap while it "
    "thins: the film's pressure spreads over a disk, the approach is slowed by the solids' "
    "elastic storage rather than by a rigid squeeze of ln(x0/h) growth, and much of the energy "
    "comes back from the solids; the reduced law spends 2 ln(x0/h_eps)/St on a rigid squeeze at "
    "gaps where the real film is already flat, and then returns everything else elastically at "
    "a dry touch. Its e_n is right only when ln(x0/h_eps) << St.",
    "- **Neither has the approach-phase physics of the full film**: both treat the film as a "
    "rigid-sphere lubrication force down to a gap and a dry contact below, so the pair's "
    "energy balance is lubrication (approach and rebound, the same ln each way) plus a lossless "
    "touch; the full film dissipates asymmetrically (the suction of the rebound is capped by "
    "cavitation) and stores energy in the solids through the film without any touch.",
    "- **The tangential outcome is the dry contact's, not the film's.** A smooth EHD film never "
    "lets the solids touch, so the full model's e_t is 0.987-1.000 and its spin changes "
    "4e-5 to 0.028 (the film's shear, of order delta ln): only the stopped steel pairs in "
    "glycerol turn more (e_t 0.89-0.93). Both reduced laws touch at every rebound and the "
    "friction sets e_t: 1 - e_t = mu (1 + e) |V_c| / tan(angle) while the contact slides, capped "
    "at the rolling exit 1 - 1/(1 + k) (e_t = 5/7 for solid spheres, reached at 15 degrees), so "
    "e_t = 0.71-0.96 and spin changes of 0.01-0.63 against the full model's 1e-3: a difference "
    "of up to 0.29 in e_t and 0.63 in the small sphere's spin change. That is right for rough "
    "surfaces whose asperities touch (the full model with roughness and friction, "
    'docs/tangential.md, "Coulomb friction of the solid contact"), and wrong for a smooth film.',
    "- **The tangential lubrication itself is of the right order.** Without friction "
    "(`*_frictionless` in the CSV) the reduced laws' 1 - e_t (4e-4 to 3e-2 when they rebound) is "
    "within a factor of 0.1-10 of the full model's film shear: close in water at St 80 "
    "(4e-4-1.4e-3 against 1e-4-4e-4), larger for the EHD gap at St 20 (the rigid approach "
    "lingers at gaps near h_eps: 1 - e_t 4e-3-3e-2 against 6e-4-2e-3) and ten times smaller in "
    "glycerol at St 80 (4e-4 "
    "against 4.6e-3), where the full film stays thin and flat over the long contact while the "
    "reduced laws switch the lubrication off during the touch. How the turning is split "
    "between unequal spheres: the Couette film and the reduced laws' friction act at the contact "
    "point on the slip, so each sphere takes its inertia share (the smaller sphere of "
    "a1 = 2 a2 turns 8 times more; the CSV's `couette_*`); the sliding film and the reduced "
    "laws' lubrication also carry the pressure of the surfaces' entrainment (Jeffrey & Onishi's "
    "w/5 terms), which turns the spheres unequally: 6.4-7.6 times more in the full model (its "
    "pressure spread over the flattened film), 5.1-5.3 in the frictionless reduced laws (the "
    "rigid logarithm's weights). The entrainment moves the full model's e_t by at most 2e-3 "
    "from the Couette film's.",
    "- **Stopped pairs** (e_n = 0) are not compared tangentially: the full model's tangential "
    "motion ends at its stop, the reduced laws run until the normal motion has stalled in the "
    "layer (|V| < 1e-7 V0), still shearing at small gaps (the fixed gap's 1 - e_t of 0.21-0.26 at "
    "St 5, x0 = 0.03 a without friction).",
    "",
    "In short: the fixed minimum gap gives an e_n that does not know the materials, right only "
    "where the film happens to stay near h_min; the EHD minimum gap knows the film's thickness but "
    "not its shape, so it dissipates too much at moderate St and misses the elastic rebounds at "
    "small St; and both put a dry, frictional touch into every collision, which sets their e_t "
    "and spins, where a smooth EHD film has none. LIGGGHTS's two-sphere law was not run "
    "beside these laws; its oblique comparison with the full model of rough pairs is the "
    'section "Two spheres obliquely: LIGGGHTS" below.',
    "",
]


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
    """e_n, e_t and both spin changes of the full model with the sliding film ("full_") and
    with the Couette film ("couette_"), and its thinnest film (by x0)."""
    result = collide(pair.dimensionless(), tangential="lubrication", **pair.lower_settings())
    couette = with_tangential(result, "couette")
    outcome = dict(full_film=result.normal.min_film_thickness)
    for name, run in (("full", result), ("couette", couette)):
        tangential = run.tangential
        outcome.update(
            {
                f"{name}_e_n": run.normal.e_n,
                f"{name}_e_t": tangential.e_t,
                f"{name}_upper_spin_change": tangential.spin_change,
                f"{name}_lower_spin_change": tangential.pair.lower_spin_change,
            }
        )
    return outcome


def reduced_models(pair: PhysicalPair) -> dict:
    """The outcomes of both reduced models (the full model's groups, the pair's masses), with
    the friction coefficient FRICTION and without friction."""
    params = pair.dimensionless()
    m1, m2 = pair.masses
    inputs = ReducedCollision(
        St=params.St, eps=params.eps, delta=params.delta, angle=params.angle,
        minimum_gap=FIXED_GAP / params.delta, friction_coefficient=FRICTION,
        pair=SpherePair(m1 / m2, pair.upper_inertia_factor, pair.lower_inertia_factor,
                        radius_ratio=pair.upper_radius / pair.lower_radius),
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
        speed=pair.speed, eps=params.eps, full_film=full.pop("full_film"),
        fixed_gap=FIXED_GAP / layer, ehd_gap=ehd_minimum_gap(params.eps),
    )  # fmt: skip
    row.update(full)
    for model, outcome in reduced_models(pair).items():
        row.update({f"{model}_{key}": getattr(outcome, key) for key in OUTPUTS})
    return row


def markdown(table) -> str:
    """The table at 45 deg (every pair, liquid, St and layer) and, below it, the largest
    differences from the full model over all angles (e_t and the spins over the points where
    both rebound: a stopped pair's tangential end is not the same in both)."""
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
        rebounds = [r for r in table if r["full_e_n"] > 0.0 and r[f"{model}_e_n"] > 0.0]
        for key in OUTPUTS:
            points = table if key == "e_n" else rebounds
            worst = max(points, key=lambda r: abs(r[f"{model}_{key}"] - r[f"full_{key}"]))
            difference = worst[f"{model}_{key}"] - worst[f"full_{key}"]
            where = (
                f"{worst['material']}, {worst['liquid']}, a1/a2 {worst['radius_ratio']:g}, "
                f"St {worst['St']:g}, x0/a {worst['layer']:g}, {worst['angle']:g} deg"
            )
            lines.append(f"| {model} | {key} | {difference:+.3f} ({where}) |")
    return "\n".join(lines) + "\n"


def computed() -> list[dict]:
    """Every point, computed (printed as it goes) and written to the CSV."""
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
    print(f"{len(table)} points in {time.process_time() - start:.0f} s CPU")
    return table


def read() -> list[dict]:
    """The points of the CSV, numbers as floats."""
    with CSV.open() as f:
        return [
            {k: v if k in ("material", "liquid") else float(v) for k, v in row.items()}
            for row in csv.DictReader(f)
        ]


def write_section(tables: str) -> None:
    """The section SECTION of docs/validation.md after the DEM engines' (replacing an earlier
    one, the other sections kept)."""
    lines = [*INTRODUCTION, "", tables, *ANALYSIS]
    replace_section(REPORT, SECTION, lines, after=DEM_ENGINES)
    print(f"wrote {REPORT}")


def main():
    table = computed() if "--rerun" in sys.argv or not CSV.exists() else read()
    tables = markdown(table)
    write_atomic(MARKDOWN, tables)
    write_section(tables)


if __name__ == "__main__":
    main()
