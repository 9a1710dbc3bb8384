"""Gondret, Lance & Petit (2002)'s bouncing steel spheres with ``ehdfem.bounce.trajectory``
(docs/bounce.md).

Five runs with their published parameters (sphere diameter and density, liquid density and
viscosity, impact Reynolds number: ehdfem.inputs.literature.GONDRET_RUNS), each released at rest
from the height at which the drag law's largest approach speed is the published impact speed (or, if
the drag law's terminal velocity is below it, from RELEASE_FAR diameters, where the sphere
arrives at its terminal velocity), bouncing until it rests. Assumed, not published in what we
have: the spheres' elastic constants (the steel preset), a glass plate, e_dry = 0.97 (the value
Biegert, Vowinckel & Meiburg 2017 use for these runs) and a vapour pressure of 0.

The modelling choices are varied one at a time on St 27 and St 152, the two runs whose
trajectories have been digitised from the paper's figures: the five choices of the flight and
the contacts (the history force, in flight and in the contacts; the wall's added mass, gravity
in the contacts, the exit above the cavity, the roughness), each switched on alone on the
steady flight without them, and from the base (all five on) the history kernel and its memory,
the history force left out of the contacts, the drag in the contacts, the wall-bounded history
kernel, the assumed roughness, e_dry and suction limit (ambient minus cavity pressure: 1 atm,
or down to 0.1 atm if dissolved gas cavitates first) over their plausible ranges, cavitation
and the hand-over tolerance (the drag law and the added mass were varied on the steady flight
before, docs/bounce.md). Every run is followed until the sphere rests.
Nothing is fitted to the trajectories. The digitised points are not shipped (third-party data,
see docs/bounce.md); given as a CSV file (comment lines starting with #, columns case, time_s
[s, 0 at the first impact], gap_m [m]) they are compared with the model and drawn in the
figures.

Every finished run is written at once: a row of studies/results/gondret_bounce/runs.csv and its
trajectory CSV; a run that is stopped and started again computes only what is missing, and a
finished table redraws the figures (docs/figures/bounce_*.png) in seconds.
Run: OPENBLAS_NUM_THREADS=1 .venv/bin/python studies/gondret_bounce.py [DIGITISED.csv]
"""

import csv
import sys
import time
from dataclasses import replace
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from ehdfem.bounce.flight import FarField, release_height_for_speed  # noqa: E402
from ehdfem.bounce.inputs import BounceInputs  # noqa: E402
from ehdfem.bounce.run import BounceRun  # noqa: E402
from ehdfem.bounce.trajectory import bounce_sphere  # noqa: E402
from ehdfem.dem.closedform import legendre  # noqa: E402
from ehdfem.inputs.literature import GONDRET_RUNS  # noqa: E402
from ehdfem.inputs.scales import ATMOSPHERE  # noqa: E402
from ehdfem.study.sweep import ResultTable, write_csv  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
RESULTS = ROOT / "studies/results/gondret_bounce"
TABLE = RESULTS / "runs.csv"
FIGURES = ROOT / "docs/figures"
E_DRY = 0.97
ROUGHNESS = 1e-4  # the spheres' rms roughness by their radius (not confirmed in the paper)
RELEASE_FAR = 60.0  # diameters: release height when the published speed is not reachable
MAX_BOUNCES = 30
SMOOTH = {"sphere_roughness": 0.0}
STEADY = {  # the flight and contacts before the choices
    "history": "none",
    "wall_added_mass": False,
    "contact_gravity": False,
    "clear_exit": False,
    **SMOOTH,
}
CHOICES = {  # name: (BounceInputs changes, BounceRun changes); each choice alone, then all
    "steady flight": (STEADY, {}),
    "+ history force": ({**STEADY, "history": "mei-adrian"}, {}),
    "+ wall added mass": ({**STEADY, "wall_added_mass": True}, {}),
    "+ gravity in contact": ({**STEADY, "contact_gravity": True}, {}),
    "+ exit above cavity": ({**STEADY, "clear_exit": True}, {}),
    "+ roughness": ({key: value for key, value in STEADY.items() if key not in SMOOTH}, {}),
    "base": ({}, {}),
    "Basset kernel": ({"history": "basset"}, {}),
    "memory reset at exit": ({"history_memory": "reset"}, {}),
}
CAUSES = {  # the history force and the drag of the contact, from the base
    "history force in flight only": ({"contact_history": False}, {}),
    "+ drag in contact": ({"contact_drag": True}, {}),
    "memory of the approach only": ({"history_memory": "approach"}, {}),
    "wall-bounded history kernel": ({"history": "mei-adrian-wall"}, {}),
    "wall kernel, memory of the approach only": (
        {"history": "mei-adrian-wall", "history_memory": "approach"},
        {},
    ),
}
SENSITIVITY = {  # the assumed surface inputs and suction limit over plausible ranges, from the base
    "roughness 0.3e-4 a": ({"roughness_by_radius": 0.3e-4}, {}),
    "roughness 3e-4 a": ({"roughness_by_radius": 3e-4}, {}),
    "e_dry = 0.9": ({"e_dry": 0.9}, {}),
    "e_dry = 1": ({"e_dry": 1.0}, {}),
    "suction limit 0.25 atm": ({"ambient_pressure": 0.25 * ATMOSPHERE}, {}),
    "suction limit 0.1 atm": ({"ambient_pressure": 0.1 * ATMOSPHERE}, {}),
}
VARIANTS = {  # the choices, then the other modelling variations from the base
    **CHOICES,
    **CAUSES,
    **SENSITIVITY,
    "smooth": (SMOOTH, {}),
    "no cavitation": ({"cavitation": "none"}, {}),
    "hand-over 0.5 %": ({}, {"handover_jump": 0.005}),
    "hand-over 5 %": ({}, {"handover_jump": 0.05}),
}
VARIED = ("St27", "St152")


def case_inputs(run) -> BounceInputs:
    """A Gondret run as bounce inputs (release height set by :func:`released`)."""
    return BounceInputs(
        radius=run.diameter / 2,
        sphere=run.sphere,
        wall="glass",
        liquid=run.liquid,
        release_height=RELEASE_FAR * run.diameter,
        e_dry=E_DRY,
        sphere_roughness=ROUGHNESS * run.diameter / 2,
    )


FALL = ("drag", "added_mass", "history", "wall_added_mass")  # the inputs the first fall has
HEIGHTS = {}  # release heights [m] found, by (radius, the values of FALL, speed)


def released(inputs: BounceInputs, speed: float) -> BounceInputs:
    """``inputs`` released from the height that gives the published impact speed, if any; found
    once per sphere and per choices of the first fall (FALL), which the other variants share."""
    key = (inputs.radius, *(getattr(inputs, name) for name in FALL), speed)
    if key not in HEIGHTS:
        top = RELEASE_FAR * inputs.diameter
        HEIGHTS[key] = release_height_for_speed(inputs, speed, top=top)
    height = HEIGHTS[key]
    return inputs if height is None else replace(inputs, release_height=height)


def run_case(table, run, variant):
    """The row of (run, variant): from the table, or computed and stored with its trajectory."""
    row = table.get(case=run.label, variant=variant)
    path = trajectory_path(run.label, variant)
    if row is not None and path.exists():
        return row
    changes, options = VARIANTS[variant]
    changes = dict(changes)
    if "roughness_by_radius" in changes:
        changes["sphere_roughness"] = changes.pop("roughness_by_radius") * run.diameter / 2
    inputs = released(replace(case_inputs(run), **changes), run.speed)
    start = time.perf_counter()
    result = bounce_sphere(inputs, BounceRun(max_bounces=MAX_BOUNCES, **options))
    seconds = time.perf_counter() - start
    write_csv(path, result.trajectory_rows())
    write_csv(RESULTS / f"{run.label}_{slug(variant)}_contacts.csv", result.contact_rows())
    first = result.contacts[0]
    apexes = [c.apex_gap / inputs.diameter for c in result.contacts if c.apex_gap is not None]
    row = {
        "case": run.label,
        "variant": variant,
        "St_published": inputs.stokes_number(run.speed),
        "speed_published": run.speed,
        "terminal_velocity": result.terminal_velocity,
        "release_height_D": inputs.release_height / inputs.diameter,
        "impact_speed": first.impact_speed,
        "St": first.St,
        "handover_gap_over_a": first.handover_gap / inputs.radius,
        "contact_St": first.contact_St,
        "eps": first.eps,
        "e": first.e,
        "legendre_e": result.legendre(first.St),
        "contacts": len(result.contacts),
        "apexes_D": " ".join(f"{a:.4g}" for a in apexes[:4]),
        "status": result.status,
        "energy_error": result.energy_error(),
        "entry_jump": first.entry_jump,
        "exit_jump": first.exit_jump,
        "largest_gravity_impulse": max(
            c.gravity_impulse for c in result.contacts if c.status == "rebound"
        ),
        "first_gravity_impulse": first.gravity_impulse,
        "first_remainder_impulse": first.remainder_impulse,
        "first_history_impulse": first.history_impulse,
        "exit_gap_over_a": first.exit_gap / inputs.radius,
        "first_min_film_over_a": first.film["min_film_thickness_m"] / inputs.radius,
        "asperity_contacts": sum(
            c.film["solid_impact_speed_m_s"] is not None for c in result.contacts
        ),
        "seconds": round(seconds, 1),
    }
    print(
        f"{run.label} {variant}: e = {first.e:.4f}, {row['contacts']} contacts, {seconds:.1f} s",
        flush=True,
    )
    return table.add(row)


def slug(variant: str) -> str:
    return "".join(ch if ch.isalnum() else "_" for ch in variant).strip("_")


def trajectory_path(label: str, variant: str) -> Path:
    return RESULTS / f"{label}_{slug(variant)}_trajectory.csv"


def trajectory(label: str, variant: str) -> dict:
    """A stored trajectory: time [s], gap [m], velocity [m/s], phase, contacts."""
    with trajectory_path(label, variant).open() as f:
        rows = list(csv.DictReader(f))
    out = {name: np.array([float(r[name]) for r in rows]) for name in ("time", "gap", "velocity")}
    out["phase"] = np.array([r["phase"] for r in rows])
    out["contacts"] = np.array([int(r["contacts"]) for r in rows])
    return out


def digitised(path: Path) -> dict:
    """The digitised experiments in the CSV file ``path``: {case: (time [s], gap [m])}."""
    with path.open() as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    cases = {}
    for r in rows:
        cases.setdefault(r["case"], ([], []))
        cases[r["case"]][0].append(float(r["time_s"]))
        cases[r["case"]][1].append(float(r["gap_m"]))
    return {k: (np.array(t), np.array(h)) for k, (t, h) in cases.items()}


def observed(t, h, approach_speed) -> dict:
    """What the digitised points show (time t [s], 0 at the impact; gap h [m]): the apex gaps
    [m] between impacts (local minima), the impact times [s], and the first restitution
    estimated as the rebound speed over the first two points after the first impact (the first
    two points when the data start after it) over ``approach_speed`` [m/s]."""
    minima = [i for i in range(1, len(h) - 1) if h[i] <= h[i - 1] and h[i] <= h[i + 1]]
    starts_after_impact = t[0] > 0
    bounds = ([0] if starts_after_impact else []) + minima + [len(h) - 1]
    apexes = [float(h[i : j + 1].max()) for i, j in zip(bounds[:-1], bounds[1:], strict=True)]
    first = 0 if starts_after_impact else minima[0] + 1
    rebound = (h[first + 1] - h[first]) / (t[first + 1] - t[first])
    return {
        "apexes": [a for a in apexes if a > 0.02 * apexes[0]],
        "impacts": [float(t[i]) for i in minima],
        "e": rebound / approach_speed,
    }


def sampled_like(traj, t) -> tuple:
    """The model's trajectory at the experiment's times ``t`` (0 at the first contact)."""
    time = traj["time"] - model_time_origin(traj)
    return t, np.interp(t, time, traj["gap"])


def model_time_origin(traj) -> float:
    """The first contact's start [s] (the hand-over), the model's impact instant."""
    return float(traj["time"][np.flatnonzero(traj["phase"] == "contact")[0]])


def plot_digitised(ax, points, unit, diameter):
    """The digitised experiment ``points`` (time [s], gap [m]; None: none) on ``ax``, by
    sqrt(D/g) ``unit`` [s] and D ``diameter`` [m]."""
    if points is not None:
        ax.plot(
            points[0] / unit,
            points[1] / diameter,
            "o",
            mfc="none",
            color="k",
            ms=4,
            label="experiment (digitised)",
        )


def shown(run, data) -> str:
    """What a figure of ``run`` shows: the model alone with the run's published inputs, or
    with the digitised measurements where they were given (``data``)."""
    measured = " and its digitised measurements" if run.label in data else ""
    return f"Model with the inputs of Gondret et al. 2002's run {run.label}{measured}"


def plot_case(run, row, data):
    inputs = case_inputs(run)
    unit, diameter = inputs.time_scale(), inputs.diameter
    traj = trajectory(run.label, "base")
    origin = model_time_origin(traj)
    fig, ax = plt.subplots(figsize=(8, 4))
    ax.plot(
        (traj["time"] - origin) / unit,
        traj["gap"] / diameter,
        lw=1.4,
        label=f"ehdfem bounce: e = {float(row['e']):.3f} at St = {float(row['St']):.0f}",
    )
    plot_digitised(ax, data.get(run.label), unit, diameter)
    after = traj["time"] > origin  # the bounces set the scale, not the release
    highest = max([traj["gap"][after].max(), *data.get(run.label, ([], [0.0]))[1]])
    ax.set_xlim(-0.5, (traj["time"][-1] - origin) / unit)
    ax.set_ylim(0, 1.25 * highest / diameter)
    ax.set_xlabel(r"$t/\sqrt{D/g}$")
    ax.set_ylabel("gap / D")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title(
        f"{shown(run, data)}: steel D = {diameter * 1e3:g} mm, "
        f"mu = {run.viscosity * 1e3:g} mPa s, Re = {run.reynolds:g}",
        fontsize=10,
    )
    fig.tight_layout()
    path = FIGURES / f"bounce_{run.label}.png"
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def plot_choices(run, rows, data, variants, name):
    """The trajectories of ``run`` for ``variants`` (names of VARIANTS) in
    docs/figures/bounce_{name}_{label}.png."""
    inputs = case_inputs(run)
    unit, diameter = inputs.time_scale(), inputs.diameter
    fig, ax = plt.subplots(figsize=(9, 4.5))
    for variant in variants:
        row = next(r for r in rows if r["case"] == run.label and r["variant"] == variant)
        traj = trajectory(run.label, variant)
        origin = model_time_origin(traj)
        ax.plot(
            (traj["time"] - origin) / unit,
            traj["gap"] / diameter,
            lw=2.0 if variant == "base" else 1.1,
            label=f"{variant}: e = {float(row['e']):.3f}",
        )
    plot_digitised(ax, data.get(run.label), unit, diameter)
    ax.set_xlim(-1, 12 if run.label == "St152" else 4)
    ax.set_ylim(0, 4.0 if run.label == "St152" else 0.5)
    ax.set_xlabel(r"$t/\sqrt{D/g}$")
    ax.set_ylabel("gap / D")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    ax.set_title(f"{shown(run, data)}:\none modelling choice changed at a time", fontsize=10)
    fig.tight_layout()
    path = FIGURES / f"bounce_{name}_{run.label}.png"
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def plot_restitution(rows):
    """e against St for every contact of the base runs, with Legendre et al. 2006's curve."""
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for run in GONDRET_RUNS:
        path = RESULTS / f"{run.label}_base_contacts.csv"
        with path.open() as f:
            contacts = list(csv.DictReader(f))
        ax.semilogx(
            [float(c["St"]) for c in contacts],
            [float(c["e"]) for c in contacts],
            "o-",
            ms=4,
            label=f"{run.label}: successive contacts",
        )
    ratio = 935.0 / 7800.0
    stokes = np.logspace(0.5, 3.2, 200)
    ax.semilogx(
        stokes,
        legendre(stokes, E_DRY, ratio),
        "k--",
        label=r"Legendre et al. 2006: $e_{dry}\,\exp(-35/St_L)$",
    )
    ax.set_xlabel(r"St = $\rho_p D V / (9 \mu)$ at each impact")
    ax.set_ylabel("e = rebound / impact speed")
    ax.set_ylim(0, 1)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7)
    fig.tight_layout()
    path = FIGURES / "bounce_restitution.png"
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def main():
    RESULTS.mkdir(parents=True, exist_ok=True)
    table = ResultTable(TABLE, ("case", "variant"))
    rows = []
    for run in GONDRET_RUNS:
        for variant in VARIANTS if run.label in VARIED else ("base", "smooth"):
            rows.append(run_case(table, run, variant))
    data = digitised(Path(sys.argv[1])) if len(sys.argv) > 1 else {}
    for label, (t, h) in data.items():
        run = next(r for r in GONDRET_RUNS if r.label == label)
        unit = case_inputs(run).time_scale()
        for name in ("experiment", *VARIANTS):
            if name == "experiment":
                seen = observed(t, h, run.speed)
            else:
                traj = trajectory(label, name)
                seen = observed(
                    *sampled_like(traj, t),
                    float(table.get(case=label, variant=name)["impact_speed"]),
                )
            apexes = ", ".join(f"{a / run.diameter:.3g}" for a in seen["apexes"][:3])
            impacts = ", ".join(f"{x / unit:.3g}" for x in seen["impacts"][:3])
            print(
                f"{label} {name}: apexes / D = {apexes}; impacts at t/sqrt(D/g) = {impacts}; "
                f"e sampled = {seen['e']:.3f}"
            )
    for run in GONDRET_RUNS:
        row = next(r for r in rows if r["case"] == run.label and r["variant"] == "base")
        print(f"wrote {plot_case(run, row, data)}")
    grouped = {**CHOICES, **CAUSES, **SENSITIVITY}
    others = ["base", *(v for v in VARIANTS if v not in grouped)]
    for label in VARIED:
        run = next(r for r in GONDRET_RUNS if r.label == label)
        print(f"wrote {plot_choices(run, rows, data, CHOICES, 'choices')}")
        print(f"wrote {plot_choices(run, rows, data, others, 'variations')}")
        print(f"wrote {plot_choices(run, rows, data, ['base', *CAUSES], 'causes')}")
        sensitivity = ["base", *SENSITIVITY]
        print(f"wrote {plot_choices(run, rows, data, sensitivity, 'sensitivity')}")
    print(f"wrote {plot_restitution(rows)}")
    far = {run.label: FarField(case_inputs(run)).terminal_velocity() for run in GONDRET_RUNS}
    print("terminal velocities [m/s]:", {k: round(v, 4) for k, v in far.items()})
    print(f"total {sum(float(r['seconds']) for r in rows):.0f} s of bounces; table {TABLE}")


if __name__ == "__main__":
    main()
