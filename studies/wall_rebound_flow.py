"""St 27's approach, reversal and rise in a resolved flow with the wall: the Navier-Stokes flow
of the sphere moving normal to the wall (``ehdfem.bounce.near_wall_flow``, moving mesh,
axisymmetric) with the sphere's gap and velocity prescribed as the bounce model's base run
gives them, and its force against the flight model's force on the same motion
(docs/bounce.md, "The rebound in a resolved flow with the wall").

One thing differs between the two: the liquid's force. The model's is what moved its sphere,
F = m dv/dt + (m - m_f) g (dynamic part, buoyancy left out), split into its drag law with
Brenner's wall factor, the image's added mass and (the rest) the history force; the resolved
flow's is the finite-element force on the same gaps and velocities. A run starts on the
approach at its start gap (RUNS), the flow there steady in the sphere's frame (the sphere falls
at nearly its terminal speed from 80 a; the start gap is varied to show its effect), and ends
where the rise's speed is 5 % of the exit's (studies/reversal_flow.py's motion). During the
film model's contact the mesh's gap is held at the hand-over gap (the film resolves what
happens below it) while the sphere's velocity follows the film model's. In the rise (from the
exit gap, where no cavity forms) the model's flight has no cavitation cap, so the two forces
answer the same question. With a free rise (FREE), the motion is prescribed to the exit and
the sphere then moves under its weight and the resolved flow's force until it stops rising:
its apex against the model's, from the same exit.

Scaled by a, the hand-over speed V0 and a/V0. Reported: impulses over shares of the rise by the
exit momentum (M v_exit, M = (rho_p/rho_f + 1/2) m_f), the work over the rise, and the free
rise's apex against the model's. Stored in studies/results/wall_rebound_flow/; the figure
docs/figures/bounce_wall_rebound_flow.png.
Run: OPENBLAS_NUM_THREADS=1 .venv/bin/python studies/wall_rebound_flow.py [run names]
(all RUNS by default, about 40 minutes; names to compute some of them in parallel processes).
It reads the base run of studies/gondret_bounce.py (its trajectory CSV must exist).
"""

import json
import sys
import time
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpi4py import MPI  # noqa: E402
from scipy.integrate import trapezoid  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
import reversal_flow  # noqa: E402

from ehdfem.bounce.flight import FarField  # noqa: E402
from ehdfem.bounce.near_wall_flow import NearWallFlow  # noqa: E402
from ehdfem.bounce.sphere_flow import DISPLACED  # noqa: E402
from ehdfem.study.sweep import write_atomic  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
RESULTS = ROOT / "studies/results/wall_rebound_flow"
FIGURE = ROOT / "docs/figures/bounce_wall_rebound_flow.png"
REFERENCE_GAP = 0.055  # the mesh's gap (by a): squeezed 9 times at the hand-over's 6e-3
RUNS = {  # name: (start gap by a, elements on the sphere, growth, steps on the approach,
    # in the contact, in the rise, by a/V0); FREE also with a free rise
    "coarse from 1 a": (1.0, 0.02, 0.1, 0.01, 2e-3, 1e-2),
    "coarse from 2 a": (2.0, 0.02, 0.1, 0.01, 2e-3, 1e-2),
    "coarse from 4 a": (4.0, 0.02, 0.1, 0.01, 2e-3, 1e-2),
    "fine from 4 a": (4.0, 0.014, 0.07, 5e-3, 5e-4, 5e-3),
}
FREE = ("coarse from 4 a",)  # the fine run's rise agrees with the coarse one to 2e-4
WINDOWS = (0.05, 0.25, 0.5, 1.0)  # shares of the rise over which impulses are reported
STEP_GROWTH = 1.5  # the steps' largest ratio after the exit


def step_times(motion, approach, contact, rise):
    """The resolved flow's times (by a/V0): ``approach`` steps to the hand-over (t = 0),
    ``contact`` steps to the exit, then steps growing by STEP_GROWTH up to ``rise`` to the
    end (variable-step BDF2 is stable for ratios below 1 + sqrt(2))."""
    times, exit_time = motion["times"], motion["exit_time"]
    after = [exit_time]
    step = contact
    while after[-1] < times[-1]:
        step = min(step * STEP_GROWTH, rise)
        after.append(after[-1] + step)
    return np.concatenate(
        [np.arange(times[0], 0.0, approach), np.arange(0.0, exit_time, contact), after[:-1]]
    )


def resolved(name, free: bool = False) -> dict:
    """The resolved flow on the prescribed motion at resolution ``name`` (stored): its force,
    or, ``free``, the motion prescribed to the exit and the sphere then moved by the resolved
    flow's force and its weight until it stops rising (gaps, speeds and forces)."""
    path = RESULTS / f"{name.replace(' ', '_')}{'_free' if free else ''}.json"
    if path.exists():
        return json.loads(path.read_text())
    start_gap, fine, growth, *steps = RUNS[name]
    motion = reversal_flow.prescribed_motion(start_gap)
    t = step_times(motion, *steps)
    if free:
        t = t[t <= motion["exit_time"]]
    floor = np.interp(0.0, motion["times"], motion["gaps"])  # the hand-over gap
    gaps = list(np.maximum(np.interp(t, motion["times"], motion["gaps"]), floor))
    speeds = list(np.interp(t, motion["times"], motion["velocities"]))
    start = time.perf_counter()
    flow = NearWallFlow(MPI.COMM_WORLD, motion["reynolds"], REFERENCE_GAP, fine=fine, growth=growth)
    forces = [flow.steady(gaps[0], speeds[0])]
    for k in range(1, len(t)):
        forces.append(flow.step(t[k] - t[k - 1], gaps[k], speeds[k]))
        if k % 100 == 0:
            print(f"{name}: step {k} of {len(t) - 1}, gap {gaps[k]:.4f} a", flush=True)
    times = list(t)
    mass = motion["ratio"] * DISPLACED
    weight = (mass - DISPLACED) * motion["gravity"]
    step = steps[1]  # the contact's, growing by STEP_GROWTH up to the rise's
    while free and speeds[-1] > 0.0:
        step = min(step * STEP_GROWTH, steps[2])
        gap, speed, force = flow.free_step(step, mass, weight)
        times.append(times[-1] + step)
        gaps.append(gap)
        speeds.append(speed)
        forces.append(force)
        if len(times) % 100 == 0:
            print(f"{name}, free: gap {gap:.4f} a, speed {speed:.4f} V0", flush=True)
    row = {
        "times": [float(x) for x in times],
        "gaps": [float(x) for x in gaps],
        "speeds": [float(x) for x in speeds],
        "force": forces,
        "cells": flow.cells,
        "seconds": round(time.perf_counter() - start, 1),
    }
    RESULTS.mkdir(parents=True, exist_ok=True)
    write_atomic(path, json.dumps(row))
    return row


def model_forces(motion) -> dict:
    """The flight model's force on its own motion (by rho V0^2 a^2, on the trajectory's
    samples): in all, and its drag law (with Brenner's factor), added mass and history parts
    (these in the contact at the hand-over gap: the film's force is the whole there)."""
    inputs, speed = motion["inputs"], motion["speed"]
    t, h, v = motion["times"], motion["gaps"], motion["velocities"]
    h = np.maximum(h, np.interp(0.0, t, h))
    far = FarField(inputs)
    unit = inputs.liquid.density * speed**2 * inputs.radius**2
    rate = np.empty_like(v)  # the velocity jumps at the hand-over and the exit
    for phase in (t < 0.0, (t >= 0.0) & (t < motion["exit_time"]), t >= motion["exit_time"]):
        rate[phase] = np.gradient(v[phase], t[phase])
    mass = motion["ratio"] * DISPLACED
    total = mass * rate + (mass - DISPLACED) * motion["gravity"]
    drag = np.array([far.drag(g * inputs.radius, x * speed) for g, x in zip(h, v, strict=True)])
    added = []
    for g, x, dv in zip(h, v, rate, strict=True):
        inertia, slope = far.inertia(g * inputs.radius)
        added.append(
            -(inertia - far.mass) * dv * speed**2 / inputs.radius - 0.5 * slope * x * x * speed**2
        )
    drag, added = drag / unit, np.array(added) / unit
    return {"model": total, "drag law": drag, "added mass": added, "history": total - drag - added}


def rise_summary(t, v, force, motion, label) -> str:
    """Impulses over the rise's WINDOWS by the exit momentum, and the rise's work."""
    exit_time = motion["exit_time"]
    rise = t >= exit_time
    exit_speed = np.interp(exit_time, motion["times"], motion["velocities"])
    momentum = (motion["ratio"] + 0.5) * DISPLACED * exit_speed
    shares = []
    for window in WINDOWS:
        inside = rise & (t <= exit_time + window * (t[-1] - exit_time))
        shares.append(f"{trapezoid(force[inside], t[inside]) / momentum:+.4f}")
    work = trapezoid(force[rise] * v[rise], t[rise])
    return f"  {label}: rise impulse over {WINDOWS}: {', '.join(shares)}; work {work:+.4f}"


def main(names):
    """Compute (or read) the ``names`` of RUNS and report them with the model's forces."""
    motion = reversal_flow.prescribed_motion(max(RUNS[name][0] for name in names))
    model = model_forces(motion)
    t_model, v_model = motion["times"], motion["velocities"]
    rise = t_model >= motion["exit_time"]
    apex = motion["apex"]
    print(f"Re_a {motion['reynolds']:.3g}, model apex {apex:.4f} a; model forces:")
    for label, force in model.items():
        print(rise_summary(t_model, v_model, force, motion, label))
    fig, (ax, rising) = plt.subplots(1, 2, figsize=(11, 4.5))
    since = t_model[rise] - motion["exit_time"]
    for label in ("model", "history"):
        ax.plot(since[1:], model[label][rise][1:], "--", label=f"flight model: {label}")
    rising.plot(since, motion["gaps"][rise], "k--", label="flight model")
    for name in names:
        row = resolved(name)
        t, v, force = (np.array(row[k]) for k in ("times", "speeds", "force"))
        after = t > motion["exit_time"]
        print(f"{name}: {row['cells']} cells, {len(t)} steps, {row['seconds']} s")
        print(rise_summary(t, v, force, motion, "resolved flow"))
        ax.plot(t[after] - motion["exit_time"], force[after], label=f"resolved, {name}")
        if name in FREE:
            free = {k: np.array(x) for k, x in resolved(name, free=True).items() if k != "cells"}
            up = free["times"] >= motion["exit_time"]
            top = free["gaps"][up].max()
            print(f"  free rise: apex {top:.4f} a ({top / apex - 1:+.2%} on the model's)")
            rising.plot(free["times"][up] - motion["exit_time"], free["gaps"][up], label=name)
    ax.set_xscale("log")
    ax.set_xlabel("time since the exit, a / V0")
    ax.set_ylabel(r"liquid's force on the sphere, $\rho V_0^2 a^2$")
    ax.set_title("forces on the model's rise")
    rising.set_xlabel("time since the exit, a / V0")
    rising.set_ylabel("gap / a")
    rising.set_title("free rise in the resolved flow")
    for axis in (ax, rising):
        axis.grid(alpha=0.3)
        axis.legend(fontsize=7)
    fig.tight_layout()
    if set(names) == set(RUNS):
        fig.savefig(FIGURE, dpi=110)
        print(f"wrote {FIGURE}")


if __name__ == "__main__":
    main(sys.argv[1:] or list(RUNS))
