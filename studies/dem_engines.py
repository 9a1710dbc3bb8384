"""Yade's lubrication law and LIGGGHTS's liquid bridge against the full model: each engine's
e_n(St) beside the full model's over the impact speed, for sphere materials, liquids and layer
thicknesses; for each engine and case the law's settings that reproduce the full model best and
the error left. Writes studies/results/dem_engines.json (each finished run at once, atomically:
a run stopped and started again computes only what is missing), the figures
docs/figures/dem_engines_{yade,liggghts}.png and the section "DEM engines" of docs/validation.md.
The engines' own files stay in out/dem_engines/ (input script, log, history, rebound).
Rough surfaces: for a sphere of roughness sigma, each engine's parameter that stands for the
asperities (Yade's eps, LIGGGHTS's minimum gap) at a factor times its value of sigma
(ehdfem.dem.engines.compare.ROUGHNESS) beside the full model with that sigma, by the impact
model and Greenwood-Tripp's; the figure docs/figures/dem_engines_roughness.png.
Run: bash make.sh dem-engines
"""

import dataclasses
import json
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from ehdfem import collide, from_presets  # noqa: E402
from ehdfem.config import RunConfig  # noqa: E402
from ehdfem.dem.engines import liggghts, yade  # noqa: E402
from ehdfem.dem.engines.compare import (  # noqa: E402
    ENGINES,
    ROUGHNESS,
    engine_law,
    full_model_collision,
)
from ehdfem.study.report import replace_section  # noqa: E402
from ehdfem.study.sweep import write_atomic  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
TABLE = ROOT / "studies/results/dem_engines.json"
RUNS = ROOT / "out/dem_engines"
REPORT = ROOT / "docs/validation.md"
SECTION = "## DEM engines: Yade and LIGGGHTS against the full model"
LITERATURE_END = "## Sources whose numbers could not be obtained"  # studies/validation.py's last
# studies/pair_validation.py's section, kept after ours
SPEEDS = (0.15, 0.3, 0.6, 1.2, 2.4)  # m/s
RADIUS = 2e-3  # m
CASES = {  # name: (sphere, Yade's wall (LIGGGHTS: a second sphere alike), liquid, layer [m])
    "steel, 100 cSt oil, 0.1 mm": ("steel", "glass", "silicone_oil_100cst", 1e-4),
    "glass, 80 % glycerol, 0.1 mm": ("glass", "glass", "glycerol_80", 1e-4),
    "steel, 100 cSt oil, 0.2 mm": ("steel", "glass", "silicone_oil_100cst", 2e-4),
}
SETTINGS = {
    "yade": {
        "as given (eta = mu, eps = 1e-3)": yade.YadeLaw(yade_viscosity_factor=1.0),
        "eta = 4 mu, eps = 1e-4": yade.YadeLaw(yade_roughness=1e-4),
        "eta = 4 mu, eps = 1e-3": yade.YadeLaw(yade_roughness=1e-3),
        "eta = 4 mu, eps = 1e-2": yade.YadeLaw(yade_roughness=1e-2),
        "eta = 4 mu, eps = 1e-3, kn / 100": yade.YadeLaw(yade_stiffness=0.01),
    },
    "liggghts": {  # (minSeparationDistanceRatio, the bridge's cut-off gap by x0)
        f"min {low:g}, cut-off at {layers:g} x0": (low, layers)
        for low in (1.01, 1e-1, 1e-2, 1e-3, 1e-4)  # 1.01: LIGGGHTS's recommended value
        for layers in (1, 2)
    },
}


INTRODUCTION = [
    "Both engines run as a DEM user runs them (`ehdfem dem`, ehdfem/dem/engines/; the input "
    "script, log and history of every run below are in out/dem_engines/ after "
    "`studies/dem_engines.py`): Yade 2023.02a's `Law2_ScGeom_ImplicitLubricationPhys` for a sphere"
    " (radius 2 mm) on a wall, LIGGGHTS 3.8's `cohesion easo/capillary/viscous` (Hertz contact, "
    "surface tension 0) for two equal spheres, set beside the half-space model at the reduced "
    "radius and mass (exact to leading order in x0/a for two spheres, and seconds per run). The "
    "full model is run smooth (rough surfaces below), with the liquid's vapour pressure as the "
    "cavitation limit. e_n is the relative normal speed when the gap reopens to the layer "
    "thickness x0 over the approach speed; 0: the sphere stays in the layer (for Yade: its speed "
    "stays below 1e-2 V0 for x0/V0, so e_n < 1e-2 counts as 0). Errors are |e_n(engine) - e_n(full"
    " model)| over the five speeds 0.15-2.4 m/s; the engines' time steps (Yade 0.02 sqrt(m/kn), "
    "LIGGGHTS 1 % of the Hertz contact time) move e_n by less than 1e-4 (a quarter of them).",
    "",
    "Two facts of the laws, checked on the engines (tests/test_dem_engines.py): Yade treats a wall "
    "as a sphere of the same radius, so that its rigid force (3/2) pi eta a^2 v/u is a quarter of "
    "the exact 6 pi mu a^2 v/h; eta = 4 mu restores it. LIGGGHTS's bridge forms only at contact: "
    "no force acts during the approach, and after contact the force is 6 pi mu R*^2 v/h, cut at "
    "h = minSeparationDistanceRatio R* and zero beyond the cut-off "
    "(maxSeparationDistanceRatio - 1) 2R.",
]
OBLIQUE_TEXT = [
    "Yade's tangential loss 1 - e_t and its spin change are 4-12 times the full model's "
    "(Couette film, the default; docs/model.md). Its tangential resistance "
    "pi eta/2 (-2a + (2a + u) ln((2a + u)/u)) per slip speed is set by one film thickness u, "
    "which its series spring holds near 2 eps a through the contact, and acts at the contact "
    "point, where the full model's sliding film spreads over the flattened region; the "
    "comparison does not separate the two. e_t and the spin change are not fitted here.",
]
CONCLUSIONS = [
    "### What a DEM user should set, and what no setting can do",
    "",
    "- **Yade, sphere on a wall:** eta = 4 mu (the exact rigid force; eta = mu, as given, "
    "overestimates e_n everywhere) and a roughness eps near 1e-3 (asperities at 2 eps a = 4 um "
    "here), Yade's own kn. A smaller eps does not approach the smooth full model: the film "
    "then thins to well below the EHD film and Yade's law, which has no cavitation, pulls the "
    "sphere back on the rebound with a suction as large as the compression force, so that e_n "
    "falls as the speed rises (e_n = 0.09 at 2.4 m/s with eps = 1e-4, and below 1e-2 on glass) "
    "where the full model's rises; the full model's cavitation limits that suction to the "
    "vapour pressure. A softer "
    "spring (kn / 100) makes it worse. What is left is the shape of the deformation: Yade's "
    "spring is linear and in series with a film of one thickness u, where the full model's "
    "film is flattened over a contact radius and wets a finite region (the layer's extent); "
    "the best setting's error (table) is what a DEM user must accept near St_c, where e_n is "
    "steepest.",
    "- **LIGGGHTS, two spheres:** minSeparationDistanceRatio sets the whole loss: the "
    "recommended 1.01 (a minimum gap as large as R*) leaves e_n near 1 at every St; the best "
    "of the values tried is 1e-3 (a minimum gap of 1e-3 R*, 1 um here), and at 1e-4 the "
    "bridge's suction on separation holds the spheres. The cut-off (the bridge's rupture at x0 "
    "or 2 x0) hardly matters. No setting gives the full model's curve: the law has no force "
    "while the spheres approach (the bridge forms at contact), where the full model dissipates "
    "most and sticks below St_c, so that LIGGGHTS rebounds where the full model sticks "
    "(e_n = 0.28 against 0.02 at St = 10.7, 0.2 mm); and its fixed minimum gap does not follow "
    "the film's thickness at contact, which in the full model thins as St and the deformation "
    "(eps, the flattened shape) grow, so that one ratio that fits low St overestimates the "
    "loss at high St.",
    "- **Rough surfaces (rms sigma known), Yade:** eta = 4 mu and eps = sigma/(2a), its "
    "asperities where the full model's touch (what `ehdfem dem` sets from `--sphere-roughness` "
    "and `--wall-roughness`): Yade's law is then the full model's mixed lubrication "
    "(Greenwood-Tripp; `ehdfem dem --asperities greenwood-tripp` sets it beside that model), "
    "within 0.025 at sigma/x0 = 0.03 (0.014 on glass in glycerol). Keep 2 eps a at or above about "
    "3 um (0.03 x0, eps = 7.5e-4 here), or the suction on the rebound holds "
    "the sphere at high St (sigma/x0 = 0.01: eps = 3 sigma/(2a) is within 0.03). At "
    "sigma/x0 = 0.1 the error left is 0.28 at best (eps = sigma/(2a)), at the lowest St, "
    "where the mixed model rebounds at 0.42 and Yade at 0.14. Where the asperities' "
    "contact is a solid impact (the impact model; plastic asperities, e_dry), raise eps to "
    "3-10 sigma/(2a) (errors 0.04-0.17): Yade's undamped asperity spring in parallel with the "
    "film is not an impact.",
    "- **Rough surfaces, LIGGGHTS:** minSeparationDistanceRatio = 3 sigma/R* (a smallest gap "
    "of 3 sigma; what `ehdfem dem` sets) and coefficientRestitution = e_dry: within 0.05 of "
    "the impact model over sigma/x0 = 0.01-0.1 and St 5.6-172 in both cases run. The factor "
    "3 is a fit of these cases: the bridge's only loss, on separation, has to stand for the "
    "full model's loss in the approach too, and for the cavitation that limits its suction on "
    "the rebound. As for smooth surfaces, no setting follows the mixed lubrication's low-St "
    "losses (0.05-0.17 at best).",
]
ROUGH_TEXT = [
    "The sphere's rms roughness sigma = 1, 3 and 10 um (sigma/x0 = 0.01-0.1, the wall smooth) "
    "on steel, 100 cSt oil, 0.1 mm, and 3 um on glass, 80 % glycerol, 0.1 mm; the full model "
    "by both asperity models (impact with "
    "e_dry = 1, Yade's spring being undamped, and Greenwood-Tripp's mixed lubrication with "
    'its default asperities; docs/model.md, "Rough surfaces"); each engine\'s asperity '
    "parameter at a factor 0.3-10 times its value of sigma: Yade's asperity height "
    "2 eps a = factor sigma (eta = 4 mu, its own kn, keps = 1), LIGGGHTS's smallest gap "
    "minSeparationDistanceRatio R* = factor sigma (cut-off at x0). Errors as above, over the "
    "five speeds.",
    "",
    "The Greenwood-Tripp runs of this section and of the rough oblique table below are computed "
    "with the asperity pressure at its corrected prefactor (docs/model.md, Greenwood & "
    "Tripp's prefactor), half the former one; the engines' runs and the impact model do not "
    "depend on it (they are recomputed too, the engines' to 1e-12). With the softer "
    "asperities the mixed model rebounds less where they carry most, the larger sigma and "
    "the lower St: its e_n fell by up to 0.11 (sigma = 10 um beside Yade: 0.53 -> 0.42 at "
    "St 5.4; sigma = 3 um beside LIGGGHTS: 0.38 -> 0.28 at St 10.7) and by 0.002 or less "
    "from St 43 up.",
]
ROUGH_ENGINE_TEXT = {
    "yade": "Yade's asperities are a spring keps kn in parallel with its film, which keeps "
    "thinning below 2 eps a and dissipating: a mixed lubrication, so that at factor 1 Yade "
    "follows the full model's Greenwood-Tripp curve (sigma = 3 um: within 0.025 in oil, 0.014 "
    "in glycerol) and rebounds less "
    "than the impact model, which ends the approach at sigma with a solid bounce; only a "
    "higher asperity height (factor 3-10) approaches the impact model. At sigma = 1 um and "
    "factor 1 (2 eps a = 1 um) Yade's suction without cavitation holds the sphere on the "
    "rebound at high St (e_n falls from 0.75 to 0.54 between St 43 and 86), as in the smooth "
    "runs with eps = 1e-4. At sigma = 10 um the mixed full model's e_n stays near 0.42-0.43 "
    "from St 5.4 to 10.7 before it rises with St, while Yade's rises steeply over that range "
    "at every factor (factor 1: 0.14 -> 0.57, factor 3: 0.55 -> 0.78): no factor tried "
    "reproduces the plateau; factor 1 is now the closest (0.28 below it at St 5.4), factor 3 "
    "is closer at St 5.4 but 0.34 above it at St 10.7.",
    "liggghts": "LIGGGHTS's smallest gap at 3 sigma is the best against the impact model at "
    "every sigma, in both cases (the bridge's loss grows as ln(x0/h_min), one factor fits "
    "them all). "
    "Against Greenwood-Tripp's mixed lubrication no factor fits: its loss at low St, where the "
    "film and the asperities share the load during the approach, has no counterpart in a "
    "bridge that forms at contact. (At sigma = 10 um the mixed model's e_n is not even "
    "monotonic in St here: 0.73 at St 10.7, 0.68 at 21.5, then rising.)",
}
ROUGH_OBLIQUE_TEXT = [
    "The full model by the impact model and by Greenwood-Tripp's mixed lubrication (Couette "
    "film, the default). Yade's e_n follows the mixed model (within 0.03), as head-on. Without "
    "friction Yade's tangential loss 1 - e_t and spin change are 2-5 times the mixed model's "
    "where the sphere rebounds (St 9.3-74.5) and 6-13 times the impact model's; at St 4.65, "
    "where neither Yade's sphere nor the mixed model's leaves the layer, the mixed model's film "
    "brings its sphere to rolling (e_t = spin change = 5/7), and Yade's 1 - e_t and spin "
    "change are a third and a quarter of the mixed model's. "
    "With Coulomb friction mu = 0.3 (Yade's friction angle "
    "atan(mu)) the three part: the impact model's friction impulse at the asperities' impact "
    "stops the slip and the sphere leaves rolling, e_t = spin change = 1/(1 + k) = 5/7 for a "
    "solid sphere (k = 2/5) at every St (docs/tangential.md); the mixed model's friction acts "
    "on the asperities' load only, which the film keeps small (docs/model.md), so e_t falls "
    "only to 0.94-0.99 and the spin change rises to 0.15-0.02 (St 9.3-74.5); Yade's contact "
    "takes a far larger tangential impulse and its tangential spring, undamped in this law, "
    "returns the slip: e_t 0.49-0.52 and a spin change of 1.0-1.26 (St 9.3-74.5), the contact "
    "point leaving with a backward slip of 0.5-0.77 U0 where the impact model's rolls. eps "
    "does not enter the recovery (ks and the friction are as Yade derives them from the "
    "materials); only a tangential damping or a friction law without elastic recovery would "
    "remove it (not tried here). With friction Yade's e_t and spin change are therefore "
    "further from both full models than without it. The normal motion is the same with and "
    "without friction in all three (the friction acts tangentially only).",
]


def collision(engine, case, speed):
    """The engine's collision (SI) of ``case`` at ``speed``: a sphere on its wall (Yade), two
    spheres of the sphere's material (LIGGGHTS)."""
    sphere, wall, liquid, layer = CASES[case]
    wall = wall if engine == "yade" else sphere
    return from_presets(sphere=sphere, wall=wall, liquid=liquid, radius=RADIUS, speed=speed,
                        layer_thickness=layer)  # fmt: skip


def law_of(engine, case, name):
    """The setting ``name`` (LIGGGHTS: its cut-off made a ratio for ``case``'s layer)."""
    if engine == "yade":
        return SETTINGS[engine][name]
    low, layers = SETTINGS[engine][name]
    return liggghts.LiggghtsLaw(low, 1.0 + layers * CASES[case][3] / (2 * RADIUS))


def compute(table):
    """Every missing run: the full model per (engine, case, speed), the engine per setting."""
    for engine in ENGINES:
        for case in CASES:
            for speed in SPEEDS:
                physical = collision(engine, case, speed)
                key = f"{engine}|{case}|full model|{speed}"
                if key not in table:
                    full = full_model_collision(engine, physical)
                    params = full.dimensionless()
                    e_n = collide(full).normal.e_n
                    table[key] = {"St": params.St, "eps": params.eps, "e_n": e_n}
                    write_atomic(TABLE, json.dumps(table, indent=1))
                for name in SETTINGS[engine]:
                    key = f"{engine}|{case}|{name}|{speed}"
                    if key in table:
                        continue
                    folder = (
                        RUNS
                        / engine
                        / f"{list(CASES).index(case)}"
                        / name.replace(" ", "_").replace("/", "by")
                    )
                    run = ENGINES[engine][1]
                    rebound = run(physical, law_of(engine, case, name), folder / f"{speed}")
                    table[key] = rebound.summary()
                    write_atomic(TABLE, json.dumps(table, indent=1))
                    print(key, f"e_n = {rebound.e_n:.4f}", flush=True)


OBLIQUE = ("steel, 100 cSt oil, 0.1 mm", "eta = 4 mu, eps = 1e-3", 30.0)  # deg
ROUGH_OBLIQUE = (3e-6, (0.0, 0.3))  # the sphere's roughness sigma [m], friction coefficients


def oblique_full_model(physical, asperities="impact"):
    """The full model's St, e_n, e_t and spin change of ``physical`` by ``asperities``."""
    result = collide(dataclasses.replace(physical, asperities=asperities), RunConfig())
    motion = result.tangential
    return {"St": physical.dimensionless().St, "e_n": result.normal.e_n, "e_t": motion.e_t,
            "spin_change": motion.spin_change}  # fmt: skip


def oblique_run(table, speed, sigma=0.0, friction=0.0):
    """Yade and the full model at OBLIQUE's angle and ``speed`` on OBLIQUE's case: smooth with
    OBLIQUE's setting, or rough (the sphere's ``sigma`` [m], Coulomb's ``friction``) with Yade's
    eps = sigma / (2 a) and friction angle atan(friction), and the full model by both asperity
    models; Yade's rebound and the full model's (impact, then Greenwood-Tripp when rough)."""
    case, name, angle = OBLIQUE
    physical = dataclasses.replace(
        collision("yade", case, speed), angle=angle, sphere_roughness=sigma,
        friction_coefficient=friction,
    )  # fmt: skip
    rough = sigma > 0.0
    label = f"sigma {sigma:g}, mu {friction:g}" if rough else name
    key = f"yade oblique|{case}|{label}|{speed}"
    if key not in table:
        law = engine_law("yade", physical, {}) if rough else SETTINGS["yade"][name]
        folder = RUNS / "yade_oblique" / (f"sigma_{sigma:g}_mu_{friction:g}" if rough else "")
        rebound = yade.run(physical, law, folder / f"{speed}")
        table[key] = {"yade": rebound.summary(), "full model": oblique_full_model(physical)}
        write_atomic(TABLE, json.dumps(table, indent=1))
    models = ["full model"]
    if rough:
        models.append("full model greenwood-tripp")
        if models[1] not in table[key]:
            table[key][models[1]] = oblique_full_model(physical, "greenwood-tripp")
            write_atomic(TABLE, json.dumps(table, indent=1))
    return table[key]["yade"], [table[key][model] for model in models]


def oblique(table, sigma=0.0, frictions=(0.0,)):
    """Yade's e_n, e_t and spin change at OBLIQUE's angle beside the full model's, smooth or
    rough (:func:`oblique_run`; then by the impact model and Greenwood-Tripp's) for each
    friction coefficient; the rows of a markdown table."""
    full = "impact / mixed" if sigma > 0.0 else "full"
    lines = [f"| mu | St | e_n Yade / {full} | e_t Yade / {full} | spin change Yade / {full} |",
             "|---|---|---|---|---|"]  # fmt: skip
    for friction in frictions:
        for speed in SPEEDS:
            run, models = oblique_run(table, speed, sigma, friction)
            cells = [" / ".join(f"{r[q]:.3f}" for r in (run, *models))
                     for q in ("e_n", "e_t", "spin_change")]  # fmt: skip
            lines.append(f"| {friction:g} | {models[0]['St']:.3g} | " + " | ".join(cells) + " |")
    return lines


def curves(table, engine, case):
    """St, the full model's e_n and each setting's e_n over the speeds."""
    rows = [table[f"{engine}|{case}|full model|{v}"] for v in SPEEDS]
    St = np.array([r["St"] for r in rows])
    full = np.array([r["e_n"] for r in rows])
    settings = {
        name: np.array([table[f"{engine}|{case}|{name}|{v}"]["e_n"] for v in SPEEDS])
        for name in SETTINGS[engine]
    }
    return St, full, settings


def errors(table, engine):
    """Per case: each setting's RMS and largest |e_n - e_n(full model)| over the speeds."""
    out = {}
    for case in CASES:
        _, full, settings = curves(table, engine, case)
        out[case] = {
            name: (float(np.sqrt(np.mean((e - full) ** 2))), float(np.max(np.abs(e - full))))
            for name, e in settings.items()
        }
    return out


def figure(table, engine):
    """e_n(St) of the full model and of every setting, a panel per case."""
    fig, axes = plt.subplots(1, len(CASES), figsize=(5 * len(CASES), 4), sharey=True)
    for ax, case in zip(axes, CASES, strict=True):
        St, full, settings = curves(table, engine, case)
        ax.plot(St, full, "k-", lw=2, label="full model")
        for name, e in settings.items():
            ax.plot(St, e, "o--", ms=4, label=name)
        ax.set_xscale("log")
        ax.set_xlabel("St")
        ax.set_title(case, fontsize=9)
    axes[0].set_ylabel("e_n")
    axes[0].legend(fontsize=7)
    fig.suptitle(f"{engine} beside the full model (radius {RADIUS * 1e3:g} mm)")
    fig.tight_layout()
    path = ROOT / f"docs/figures/dem_engines_{engine}.png"
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def error_table(table, engine):
    """A markdown table: per case the best setting, its RMS and largest error, and the
    as-given setting's."""
    first = next(iter(SETTINGS[engine]))
    lines = ["| case | St | best setting | RMS / max error | " + f"{first}: RMS / max |",
             "|---|---|---|---|---|"]  # fmt: skip
    for case, by_setting in errors(table, engine).items():
        St = curves(table, engine, case)[0]
        best = min(by_setting, key=lambda name: by_setting[name][0])
        rms, worst = by_setting[best]
        rms0, worst0 = by_setting[first]
        lines.append(
            f"| {case} | {St.min():.3g}-{St.max():.3g} | {best} | {rms:.3f} / {worst:.3f} | "
            f"{rms0:.3f} / {worst0:.3f} |"
        )
    return lines


def largest_best_error(table, engine):
    """The largest |e_n - e_n(full model)| of the best setting over the cases."""
    return max(min(by_setting.values())[1] for by_setting in errors(table, engine).values())


ROUGH = (  # (case, the sphere's rms roughness sigma [m]; the wall smooth)
    *(("steel, 100 cSt oil, 0.1 mm", sigma) for sigma in (1e-6, 3e-6, 1e-5)),
    ("glass, 80 % glycerol, 0.1 mm", 3e-6),
)
ROUGH_FACTORS = (0.3, 1.0, 3.0, 10.0)  # the engine's parameter by its value of sigma
ASPERITY_MODELS = ("impact", "greenwood-tripp")


def rough_full_model(table, engine, point, speed):
    """The full model's St and e_n beside ``engine`` at ``speed`` on ``point`` (case, sigma),
    by each asperity model (e_dry 1, as Yade's spring); the engine's collision."""
    case, sigma = point
    physical = dataclasses.replace(collision(engine, case, speed), sphere_roughness=sigma)
    full = full_model_collision(engine, physical)
    for model in ASPERITY_MODELS:
        key = f"rough|{engine}|{case}|{sigma}|full model {model}|{speed}"
        if key not in table:
            e_n = collide(dataclasses.replace(full, asperities=model), RunConfig()).normal.e_n
            table[key] = {"St": full.dimensionless().St, "e_n": e_n}
            write_atomic(TABLE, json.dumps(table, indent=1))
            print(key, f"e_n = {e_n:.4f}", flush=True)
    return physical


def compute_rough(table):
    """Every missing rough run: the full model by each asperity model, the engine at each
    factor of its roughness parameter (Yade: eta = 4 mu, its own kn; LIGGGHTS: the cut-off
    at x0)."""
    for engine in ENGINES:
        name, of_roughness = ROUGHNESS[engine]
        for point in ROUGH:
            case, sigma = point
            for speed in SPEEDS:
                physical = rough_full_model(table, engine, point, speed)
                for factor in ROUGH_FACTORS:
                    key = f"rough|{engine}|{case}|{sigma}|x{factor:g}|{speed}"
                    if key in table:
                        continue
                    law = engine_law(engine, physical, {name: of_roughness(physical, factor)})
                    folder = (RUNS / "rough" / engine / f"{list(CASES).index(case)}"
                              / f"sigma_{sigma:g}" / f"x{factor:g}")  # fmt: skip
                    rebound = ENGINES[engine][1](physical, law, folder / f"{speed}")
                    table[key] = rebound.summary()
                    write_atomic(TABLE, json.dumps(table, indent=1))
                    print(key, f"e_n = {rebound.e_n:.4f}", flush=True)


def rough_curves(table, engine, point):
    """St, the full model's e_n by asperity model, and the engine's e_n by factor."""
    key = "rough|{}|{}|{}".format(engine, *point)
    St = np.array([table[f"{key}|full model impact|{v}"]["St"] for v in SPEEDS])
    full = {
        model: np.array([table[f"{key}|full model {model}|{v}"]["e_n"] for v in SPEEDS])
        for model in ASPERITY_MODELS
    }
    runs = {
        factor: np.array([table[f"{key}|x{factor:g}|{v}"]["e_n"] for v in SPEEDS])
        for factor in ROUGH_FACTORS
    }
    return St, full, runs


def rough_errors(table, engine, point, model):
    """Each factor's RMS and largest |e_n - e_n(full model by ``model``)| over the speeds."""
    _, full, runs = rough_curves(table, engine, point)
    difference = {factor: e - full[model] for factor, e in runs.items()}
    return {f: (float(np.sqrt(np.mean(d**2))), float(np.max(np.abs(d))))
            for f, d in difference.items()}  # fmt: skip


def rough_table(table, engine):
    """A markdown table per case, sigma and asperity model: the best factor and its RMS / max
    error, and factor 1's (the engine's parameter at sigma itself)."""
    lines = ["| case | sigma (sigma/x0) | St | full model | best factor | RMS / max | "
             "factor 1: RMS / max |", "|---|---|---|---|---|---|---|"]  # fmt: skip
    for point in ROUGH:
        case, sigma = point
        St = rough_curves(table, engine, point)[0]
        for model in ASPERITY_MODELS:
            by_factor = rough_errors(table, engine, point, model)
            best = min(by_factor, key=lambda f: by_factor[f][0])
            (rms, worst), (rms1, worst1) = by_factor[best], by_factor[1.0]
            lines.append(
                f"| {case} | {sigma * 1e6:g} um ({sigma / CASES[case][3]:g}) | "
                f"{St.min():.3g}-{St.max():.3g} | {model} | {best:g} | {rms:.3f} / {worst:.3f} "
                f"| {rms1:.3f} / {worst1:.3f} |"
            )
    return lines


def rough_figure(table):
    """e_n(St) on rough surfaces: a row per engine, a column per (case, sigma); the full model
    by each asperity model and the engine at each factor."""
    fig, axes = plt.subplots(len(ENGINES), len(ROUGH), figsize=(18, 8), sharey=True)
    for row, engine in zip(axes, ENGINES, strict=True):
        for ax, point in zip(row, ROUGH, strict=True):
            St, full, runs = rough_curves(table, engine, point)
            ax.plot(St, full["impact"], "k-", lw=2, label="full model, impact")
            ax.plot(St, full["greenwood-tripp"], "k:", lw=2, label="full model, Greenwood-Tripp")
            for factor, e in runs.items():
                ax.plot(St, e, "o--", ms=4, label=f"{engine}, factor {factor:g}")
            ax.set_xscale("log")
            ax.set_xlabel("St")
            ax.set_title(f"{engine}: {point[0]}, sigma = {point[1] * 1e6:g} um", fontsize=9)
        row[0].set_ylabel("e_n")
        row[0].legend(fontsize=7)
    fig.suptitle(f"rough surfaces (radius {RADIUS * 1e3:g} mm)")
    fig.tight_layout()
    path = ROOT / "docs/figures/dem_engines_roughness.png"
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def write_section(table):
    """The section "DEM engines" of docs/validation.md (replacing an earlier one, the other
    sections kept): the tables of errors, the figures, and what a DEM user should set."""
    lines = [*INTRODUCTION, ""]
    for engine in ENGINES:
        lines += [f"### {engine}", "", *error_table(table, engine), ""]
        lines += [f"![{engine}](figures/dem_engines_{engine}.png)", ""]
    case, name, angle = OBLIQUE
    lines += [f"### yade, oblique ({angle:g} degrees; {case}; {name})", "", *oblique(table), ""]
    lines += [*OBLIQUE_TEXT, ""]
    lines += ["### Rough surfaces", "", *ROUGH_TEXT, ""]
    for engine in ENGINES:
        lines += [f"#### {engine}", "", *rough_table(table, engine), "", ROUGH_ENGINE_TEXT[engine]]
        lines += [""]
    lines += ["![roughness](figures/dem_engines_roughness.png)", ""]
    sigma, frictions = ROUGH_OBLIQUE
    lines += [
        f"### yade, rough and oblique ({angle:g} degrees; {case}; sigma = "
        f"{sigma * 1e6:g} um, eps = sigma / (2a))",
        "",
        *oblique(table, sigma, frictions),
        "",
    ]
    lines += [*ROUGH_OBLIQUE_TEXT, "", *CONCLUSIONS, ""]
    replace_section(REPORT, SECTION, lines, after=LITERATURE_END)
    print(f"wrote {REPORT}")


if __name__ == "__main__":
    table = json.loads(TABLE.read_text()) if TABLE.exists() else {}
    compute(table)
    compute_rough(table)
    print(rough_figure(table))
    for engine in ENGINES:
        print(figure(table, engine))
        print("\n".join(error_table(table, engine)))
        print(
            f"{engine}: largest error of the best setting {largest_best_error(table, engine):.3f}"
        )
    write_section(table)
