"""Rough surfaces: the critical Stokes number against the roughness, the regime map of the
roughness against the EHD film, and the two asperity models compared.

1. St_c against sigma/x0 (0: smooth; 1e-3 to 3e-2) and eps (1e-6, 1e-4, 1e-2), the impact model
   with e_dry = 0.97 (Gondret et al. 2002's steel), half-space solids, delta = 0.01, 120 film
   nodes, by bisection to 2 % (in St 1.5-40 thin, 4-100 immersed): thin layer with
   P_cav = -10 (as docs/validation.md's thin layers) and immersed without a suction limit.
   Beside them the rigid sphere's closed form St_c = (1 + 1/e_dry) L(sigma) without a
   suction limit, L = ln(1/sigma) immersed and ln(1/sigma) - (1 - sigma)(3 - sigma)/2 thin
   (tests/test_roughness.py derives it).
2. The regime map: a steel ball (a = 6.35 mm) on glass through 0.5 mm of 80 % glycerol, thin
   layer, cavitation at the liquid's vapour pressure (about 1 atm of suction), smooth
   surfaces, impact speeds 0.03-3 m/s: the model's thinnest film against Nijssen, Ottens &
   Padding 2022's h_eps = 0.37 ((mu v / E*)^2 R*^3)^(1/5) (1/E* = sum (1 - nu^2)/E, R* = a),
   beside roughness heights (Gondret's 1e-4 a; ground steel 0.1 um). The roughness ends the
   approach wherever it lies above the thinnest film.
3. e_n against St for the two asperity models and smooth surfaces: thin, eps = 1e-6 (the
   smooth film's thinnest, about 0.008 at St = 10, lies below sigma), sigma = 0.01,
   e_dry = 0.97, no suction limit, 120 nodes (for smooth surfaces e_n = e_dry V_exit).

Writes studies/results/roughness.csv and docs/figures/roughness.png; prints the St_c table of
docs/validation.md. Resumable: finished points are kept in the CSV.
Run: nice -n 10 .venv/bin/python studies/roughness.py [--plot-only]   (about 2 minutes)
"""

import math
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from ehdfem.collision import collide  # noqa: E402
from ehdfem.config import RunConfig  # noqa: E402
from ehdfem.dem.reduced.ehd_gap import ehd_film_thickness  # noqa: E402
from ehdfem.exact import rigid_film  # noqa: E402
from ehdfem.inputs.scales import CollisionParameters, from_presets  # noqa: E402
from ehdfem.study.sweep import ResultTable, critical_stokes  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
TABLE = ROOT / "studies" / "results" / "roughness.csv"
FIGURE = ROOT / "docs" / "figures" / "roughness.png"
KEYS = ("part", "layer", "eps", "roughness", "St", "model", "speed")
E_DRY, NODES = 0.97, 120
SIGMAS = (0.0, 1e-3, 3e-3, 1e-2, 3e-2)
EPSILONS = (1e-6, 1e-4, 1e-2)
LAYERS = {"thin": {"p_cav": -10.0}, "immersed": {}}
BRACKETS = {"thin": (1.5, 40.0), "immersed": (4.0, 100.0)}  # St_c lies inside (checked)
SPEEDS = (0.03, 0.1, 0.3, 1.0, 3.0)
BALL = dict(radius=6.35e-3, sphere="steel", wall="glass", liquid="glycerol_80")
LAYER_THICKNESS = 5e-4
ROUGHNESS_LINES = {"Gondret 1e-4 a": 1e-4 * 6.35e-3, "ground steel 0.1 um": 1e-7}
COMPARED = (("smooth", 0.0), ("impact", 0.01), ("greenwood-tripp", 0.01))
COMPARED_EPS = 1e-6
STOKES = (4.0, 6.0, 9.0, 14.0, 25.0, 50.0, 100.0)


def critical_points(table):
    """Part 1: St_c on the (layer, eps, sigma) grid."""
    config = RunConfig.from_settings(nodes=NODES)
    for layer, extra in LAYERS.items():
        for eps in EPSILONS:
            for sigma in SIGMAS:
                key = dict(part="critical", layer=layer, eps=eps, roughness=sigma, St="", model="")
                if table.get(**key, speed="") is not None:
                    continue
                params = CollisionParameters.from_settings(
                    St=10.0, eps=eps, layer=layer, roughness=sigma, e_dry=E_DRY, **extra
                )
                found = critical_stokes(params, BRACKETS[layer], 0.02, config)
                table.add({**key, "speed": "", "value": found["St_c"], "h_eps": ""})
                print(f"{layer} eps {eps:g} sigma {sigma:g}: St_c = {found['St_c']:.3f}")


def regime_points(table):
    """Part 2: the smooth model's thinnest film and Nijssen's h_eps against the impact speed."""
    for speed in SPEEDS:
        key = dict(part="regime", layer="thin", eps="", roughness=0.0, St="", model="", speed=speed)
        if table.get(**key) is not None:
            continue
        physical = from_presets(**BALL, speed=speed, layer_thickness=LAYER_THICKNESS)
        result = collide(physical, nodes=NODES)
        film = result.normal.min_film_thickness * LAYER_THICKNESS
        table.add({**key, "value": film, "h_eps": nijssen_film(physical)})
        print(f"v = {speed} m/s: thinnest film {film:.3g} m")


def nijssen_film(physical) -> float:
    """h_eps = 0.37 ((mu v / E*)^2 R*^3)^(1/5) [m], 1/E* = pi theta, R* = a
    (:func:`ehdfem.dem.reduced.ehd_gap.ehd_film_thickness`)."""
    modulus = 1.0 / (math.pi * physical.theta)
    return ehd_film_thickness(physical.liquid.viscosity, physical.speed, modulus, physical.radius)


def compared_points(table):
    """Part 3: e_n against St, smooth and both asperity models."""
    for model, sigma in COMPARED:
        for St in STOKES:
            key = dict(part="models", layer="thin", eps=COMPARED_EPS, roughness=sigma, St=St,
                       model=model)  # fmt: skip
            if table.get(**key, speed="") is not None:
                continue
            asperities = "impact" if model == "smooth" else model
            params = CollisionParameters.from_settings(
                St=St, eps=COMPARED_EPS, roughness=sigma, e_dry=E_DRY, asperities=asperities
            )
            normal = collide(params, nodes=NODES).normal
            table.add({**key, "speed": "", "value": normal.e_n, "h_eps": ""})
            print(f"{model} St {St}: e_n = {normal.e_n:.4f}")


def plot(rows):
    """Three panels: St_c against sigma; thinnest film against speed; e_n against St."""
    fig, (ax_c, ax_r, ax_m) = plt.subplots(1, 3, figsize=(15, 4.5))
    critical = [r for r in rows if r["part"] == "critical"]
    sigmas = np.geomspace(5e-4, 5e-2, 50)
    for layer, style in (("thin", "-"), ("immersed", "--")):
        for eps, colour in zip(EPSILONS, ("C0", "C1", "C2"), strict=True):
            points = sorted(
                (float(r["roughness"]), float(r["value"]))
                for r in critical
                if r["layer"] == layer and float(r["eps"]) == eps and float(r["roughness"]) > 0
            )
            if points:
                ax_c.plot(*zip(*points, strict=True), style + "o", color=colour,
                          label=f"{layer}, eps {eps:g}")  # fmt: skip
        closed = [rigid_film.rough_critical_stokes(s, E_DRY, layer) for s in sigmas]
        ax_c.plot(sigmas, closed, style, color="k", label=f"{layer}, rigid closed form")
    ax_c.axhspan(5, 20, color="0.9", label="experiments, St_c ~ 10")
    ax_c.set(xscale="log", xlabel="sigma / x0", ylabel="St_c", title="impact model, e_dry 0.97")
    ax_c.legend(fontsize=7)
    regime = sorted((float(r["speed"]), r) for r in rows if r["part"] == "regime")
    speeds = [s for s, _ in regime]
    ax_r.plot(speeds, [float(r["value"]) for _, r in regime], "o-", label="model, thinnest film")
    ax_r.plot(speeds, [float(r["h_eps"]) for _, r in regime], "s--", label="Nijssen h_eps")
    for (label, height), style in zip(ROUGHNESS_LINES.items(), (":", "-."), strict=True):
        ax_r.axhline(height, color="0.5", ls=style, label=f"sigma: {label}")
    ax_r.set(xscale="log", yscale="log", xlabel="impact speed [m/s]", ylabel="film [m]",
             title="steel on glass, 0.5 mm of 80 % glycerol")  # fmt: skip
    ax_r.legend(fontsize=7)
    for model, _ in COMPARED:
        points = sorted(
            (float(r["St"]), float(r["value"]))
            for r in rows
            if r["part"] == "models" and r["model"] == model and float(r["eps"]) == COMPARED_EPS
        )
        if points:
            ax_m.plot(*zip(*points, strict=True), "o-", label=model)
    ax_m.set(xscale="log", xlabel="St", ylabel="e_n", title="thin, eps 1e-6, sigma 0.01")
    ax_m.legend(fontsize=7)
    fig.tight_layout()
    FIGURE.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(FIGURE, dpi=120)


def markdown(rows) -> str:
    """The St_c table of docs/validation.md: thin (P_cav = -10) and immersed, per eps and sigma."""
    lines = ["| layer | eps | " + " | ".join(f"sigma {s:g}" for s in SIGMAS) + " |"]
    lines.append("|---|---|" + "---|" * len(SIGMAS))
    for layer in LAYERS:
        for eps in EPSILONS:
            values = {
                float(r["roughness"]): float(r["value"])
                for r in rows
                if r["part"] == "critical" and r["layer"] == layer and float(r["eps"]) == eps
            }
            cells = [f"{values[s]:.2f}" if s in values else "" for s in SIGMAS]
            lines.append(f"| {layer} | {eps:g} | " + " | ".join(cells) + " |")
    for layer in LAYERS:
        closed = [
            f"{rigid_film.rough_critical_stokes(s, E_DRY, layer):.2f}" if s else "-" for s in SIGMAS
        ]
        label = f"{layer}, rigid closed form (no suction limit)"
        lines.append(f"| {label} | - | " + " | ".join(closed) + " |")
    return "\n".join(lines)


def main():
    table = ResultTable(TABLE, KEYS)
    if "--plot-only" not in sys.argv:
        regime_points(table)
        critical_points(table)
        compared_points(table)
    plot(table.rows)
    print(markdown(table.rows))
    print(f"wrote {TABLE} and {FIGURE}")


if __name__ == "__main__":
    main()
