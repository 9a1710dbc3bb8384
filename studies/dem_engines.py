"""Yade's lubrication law and LIGGGHTS's liquid bridge against the full model: each engine's
e_n(St) beside the full model's over the impact speed, for sphere materials, liquids and layer
thicknesses; for each engine and case the law's settings that reproduce the full model best and
the error left. Writes studies/results/dem_engines.json (each finished run at once, atomically:
a run stopped and started again computes only what is missing), the figures
docs/figures/dem_engines_{yade,liggghts}.png and the section "DEM engines" of docs/validation.md.
The engines' own files stay in out/dem_engines/ (input script, log, history, rebound).
Run: bash make.sh dem-engines
Roughness: the full model is run smooth here; once it has a roughness (the asperities'
contact), pass it through FULL_MODEL_INPUTS to set Yade's eps beside it.
"""

import dataclasses
import json
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from ehdfem import collide, from_presets  # noqa: E402
from ehdfem.dem.engines import liggghts, yade  # noqa: E402
from ehdfem.dem.engines.compare import ENGINES, full_model_collision  # noqa: E402
from ehdfem.study.sweep import write_atomic  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
TABLE = ROOT / "studies/results/dem_engines.json"
RUNS = ROOT / "out/dem_engines"
REPORT = ROOT / "docs/validation.md"
SECTION = "## DEM engines: Yade and LIGGGHTS against the full model"
SPEEDS = (0.15, 0.3, 0.6, 1.2, 2.4)  # m/s
RADIUS = 2e-3  # m
FULL_MODEL_INPUTS = {}  # e.g. the full model's roughness, once it has one
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
    "`studies/dem_engines.py`): Yade 2023.02a's `Law2_ScGeom_ImplicitLubricationPhys` for a "
    "sphere (radius 2 mm) on a wall, LIGGGHTS 3.8's `cohesion easo/capillary/viscous` (Hertz "
    "contact, surface tension 0) for two equal spheres, set beside the half-space model at the "
    "reduced radius and mass (exact to leading order in x0/a for two spheres, and seconds per "
    "run). The full model is run smooth, with the liquid's vapour pressure as the cavitation "
    "limit. e_n is the relative normal speed when the gap reopens to the layer thickness x0 over "
    "the approach speed; 0: the sphere stays in the layer (for Yade: its speed stays below "
    "1e-2 V0 for x0/V0, so e_n < 1e-2 counts as 0). Errors are |e_n(engine) - e_n(full model)| "
    "over the five speeds 0.15-2.4 m/s; the engines' time steps (Yade 0.02 sqrt(m/kn), "
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
    "- **Roughness:** the full model here is smooth; Yade's eps is its only stand-in for the "
    "asperities. Set beside the full model's roughness once it has one (FULL_MODEL_INPUTS in "
    "studies/dem_engines.py).",
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
                    e_n = collide(dataclasses.replace(full, **FULL_MODEL_INPUTS)).normal.e_n
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


def oblique(table):
    """Yade's e_n, e_t and spin change at 30 degrees beside the full model's (OBLIQUE's case and
    setting); the rows of a markdown table."""
    case, name, angle = OBLIQUE
    lines = ["| St | e_n Yade / full | e_t Yade / full | spin change Yade / full |",
             "|---|---|---|---|"]  # fmt: skip
    for speed in SPEEDS:
        physical = dataclasses.replace(collision("yade", case, speed), angle=angle)
        key = f"yade oblique|{case}|{name}|{speed}"
        if key not in table:
            result = collide(dataclasses.replace(physical, **FULL_MODEL_INPUTS))
            folder = RUNS / "yade_oblique" / f"{speed}"
            rebound = yade.run(physical, SETTINGS["yade"][name], folder)
            motion = result.tangential
            full = {"St": physical.dimensionless().St, "e_n": result.normal.e_n,
                    "e_t": motion.e_t, "spin_change": motion.spin_change}  # fmt: skip
            table[key] = {"yade": rebound.summary(), "full model": full}
            write_atomic(TABLE, json.dumps(table, indent=1))
        run, full = table[key]["yade"], table[key]["full model"]
        lines.append(
            f"| {full['St']:.3g} | "
            + " | ".join(f"{run[q]:.3f} / {full[q]:.3f}" for q in ("e_n", "e_t", "spin_change"))
            + " |"
        )
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


def write_section(table):
    """The section "DEM engines" of docs/validation.md (replacing an earlier one): the tables
    of errors, the figures, and what a DEM user should set."""
    text = REPORT.read_text()
    head = text.partition(SECTION)[0].rstrip("\n")
    lines = [head, "", SECTION, "", *INTRODUCTION, ""]
    for engine in ENGINES:
        lines += [f"### {engine}", "", *error_table(table, engine), ""]
        lines += [f"![{engine}](figures/dem_engines_{engine}.png)", ""]
    case, name, angle = OBLIQUE
    lines += [f"### yade, oblique ({angle:g} degrees; {case}; {name})", "", *oblique(table), ""]
    lines += [*OBLIQUE_TEXT, "", *CONCLUSIONS, ""]
    REPORT.write_text("\n".join(lines))
    print(f"wrote {REPORT}")


if __name__ == "__main__":
    table = json.loads(TABLE.read_text()) if TABLE.exists() else {}
    compute(table)
    for engine in ENGINES:
        print(figure(table, engine))
        print("\n".join(error_table(table, engine)))
        print(
            f"{engine}: largest error of the best setting {largest_best_error(table, engine):.3f}"
        )
    write_section(table)
