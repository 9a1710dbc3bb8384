"""The reversal of Gondret et al. (2002)'s St 27 bounce in a resolved flow: the Navier-Stokes flow
around the sphere (``ehdfem.bounce.sphere_flow``, unbounded liquid, axisymmetric) with the
sphere's velocity prescribed as the bounce model gives it from the hand-over to the apex, and
the history force it yields against the flight model's kernels on the same motion
(docs/bounce.md, "The reversal in a resolved flow").

The motion: the base run of studies/gondret_bounce.py (its trajectory CSV must exist), from the
hand-over (the flow steady at the hand-over speed V0 before it) through the contact's reversal
to the rise's end, where the speed has fallen to END_SPEED of the exit's. Scaled by the sphere
radius a, V0 and a/V0 (Re_a = V0 a / nu). The history force of the resolved flow is its force
in the liquid's frame minus the steady drag at the instantaneous Re (the standard drag curve of
Clift, Grace & Weber 1978, which the steady flow matches to 0.07 % at Re 30, tests/
test_sphere_flow.py) minus the added mass's (1/2) m_f dV/dt; the model's is
-6 pi mu a sum_i w_i(Re) z_i on the same velocity samples (ehdfem.bounce.unsteady) with the
memory kept through the contact, with the contact's velocity change forgotten at exit (the
approach's memory only, zero here), and with Basset's kernel. The impulses are by the exit
momentum M v_exit, M = (rho_p / rho_f + 1/2) m_f.

Two resolutions (RESOLUTIONS: elements on the sphere, growth, steps in the contact and in the
rise), each stored as it finishes in studies/results/reversal_flow/; the figure
docs/figures/bounce_reversal_flow.png.
Run: OPENBLAS_NUM_THREADS=1 .venv/bin/python studies/reversal_flow.py (about 15 minutes).
"""

import json
import math
import sys
import time
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpi4py import MPI  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
import gondret_bounce  # noqa: E402
from scipy.integrate import trapezoid  # noqa: E402

from ehdfem.bounce import unsteady  # noqa: E402
from ehdfem.bounce.sphere_flow import DISPLACED, SphereFlow  # noqa: E402
from ehdfem.study.sweep import write_atomic  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
RESULTS = ROOT / "studies/results/reversal_flow"
FIGURE = ROOT / "docs/figures/bounce_reversal_flow.png"
CASE = "St27"
END_SPEED = 0.05  # the rise is followed until the speed is this share of the exit's
RESOLUTIONS = {  # name: (element size on the sphere, growth, step in the contact, in the rise)
    "coarse": (0.02, 0.1, 2e-3, 1e-2),
    "fine": (0.014, 0.07, 5e-4, 5e-3),
}
WINDOWS = (0.05, 0.25, 0.5, 1.0)  # shares of the rise over which impulses are reported


def prescribed_motion(start_gap: float | None = None) -> dict:
    """The base run's motion, scaled by the hand-over speed V0 and the sphere radius a: times
    (by a/V0, from the hand-over: negative before it), gaps (by a) and velocities (by V0) from
    the hand-over, or from the approach's last sample above ``start_gap`` (by a), to the rise's
    end; the exit time, the rise's apex (by a), Re_a, the density ratio, V0 [m/s], g a/V0^2
    and the inputs."""
    run = next(r for r in gondret_bounce.GONDRET_RUNS if r.label == CASE)
    inputs = gondret_bounce.case_inputs(run)
    trajectory = gondret_bounce.trajectory(CASE, "base")
    t, h, v, phase = (trajectory[k] for k in ("time", "gap", "velocity", "phase"))
    handover = int(np.flatnonzero(phase == "contact")[0])
    start = handover
    if start_gap is not None:
        start = int(np.flatnonzero(h[:handover] > start_gap * inputs.radius)[-1])
    exit_ = handover + int(np.flatnonzero(phase[handover:] == "flight")[0])
    speed = -v[handover]
    end = exit_ + int(np.flatnonzero(v[exit_:] < END_SPEED * v[exit_])[0])
    unit = inputs.radius / speed
    # at the exit the contact's last sample and the flight's first share a time (within 1e-10
    # a/V0): the flight's, the later one, is kept
    span = slice(start, end + 1)
    times, last = np.unique((t[span] - t[handover])[::-1] / unit, return_index=True)
    keep = end - start - last
    liquid = inputs.liquid
    return {
        "times": times,
        "gaps": h[span][keep] / inputs.radius,
        "velocities": v[span][keep] / speed,
        "exit_time": (t[exit_] - t[handover]) / unit,
        "apex": h[exit_ + int(np.flatnonzero(v[exit_:] < 0.0)[0]) - 1] / inputs.radius,
        "reynolds": speed * inputs.radius * liquid.density / liquid.viscosity,
        "ratio": inputs.sphere.density / liquid.density,
        "speed": speed,
        "gravity": inputs.gravity * inputs.radius / speed**2,
        "inputs": inputs,
    }


def resolved(name) -> dict:
    """The resolved flow's force on the prescribed motion at resolution ``name`` (stored)."""
    path = RESULTS / f"{name}.json"
    if path.exists():
        return json.loads(path.read_text())
    fine, growth, contact_step, rise_step = RESOLUTIONS[name]
    motion = prescribed_motion()
    times, exit_time, reynolds = motion["times"], motion["exit_time"], motion["reynolds"]
    steps = np.concatenate(
        [
            np.arange(0.0, exit_time, contact_step),
            np.arange(exit_time, times[-1], rise_step),
        ]
    )
    speeds = np.interp(steps, times, motion["velocities"])
    start = time.perf_counter()
    flow = SphereFlow(MPI.COMM_WORLD, reynolds, fine=fine, growth=growth)
    forces = [flow.steady(-1.0)]
    for k in range(1, len(steps)):
        forces.append(flow.step(steps[k] - steps[k - 1], speeds[k]))
        if k % 100 == 0:
            print(f"{name}: step {k} of {len(steps) - 1}", flush=True)
    row = {
        "times": steps.tolist(),
        "speeds": speeds.tolist(),
        "frame_force": forces,
        "cells": flow.cells,
        "seconds": round(time.perf_counter() - start, 1),
    }
    RESULTS.mkdir(parents=True, exist_ok=True)
    write_atomic(path, json.dumps(row))
    return row


def standard_drag(reynolds):
    """phi(Re) = C_D Re / 24 of Clift, Grace & Weber (1978)'s standard drag curve (Re <= 260)."""
    re = np.maximum(np.asarray(reynolds, dtype=float), 1e-12)
    low = 1 + 0.1315 * re ** (0.82 - 0.05 * np.log10(re))
    return np.where(re <= 20, low, 1 + 0.1935 * re**0.6305)


def history_forces(row, exit_time, reynolds) -> dict:
    """The history force (by rho V0^2 a^2) of the resolved flow and of the model's kernels on
    the row's velocity samples."""
    t, v = np.array(row["times"]), np.array(row["speeds"])
    rate = np.gradient(v, t)
    stokes = 6 * math.pi / reynolds
    steady = -stokes * v * standard_drag(2 * reynolds * np.abs(v))
    resolved_force = np.array(row["frame_force"]) + DISPLACED * rate
    forces = {"resolved flow": resolved_force - steady + 0.5 * DISPLACED * rate}
    relaxation = unsteady.RELAXATION_TIMES * reynolds
    kept = unsteady.carry_memory(np.zeros_like(relaxation), t, v, relaxation)
    after = int(np.flatnonzero(t >= exit_time)[0])  # the first sample at or after the exit
    approach = kept.copy()  # zero before the contact: the flow was steady
    approach[after:] = unsteady.carry_memory(
        np.zeros_like(relaxation), t[after:], v[after:], relaxation
    )
    for label, kernel, memory in (
        ("Mei & Adrian, memory kept", "mei-adrian", kept),
        ("Mei & Adrian, approach's memory only", "mei-adrian", approach),
        ("Basset, memory kept", "basset", kept),
    ):
        weights = [unsteady.history_weights(kernel, 2 * reynolds * abs(x)) for x in v]
        forces[label] = -stokes * np.einsum("ij,ij->i", np.array(weights), memory)
    return forces


def main():
    motion = prescribed_motion()
    exit_time, reynolds, speed = motion["exit_time"], motion["reynolds"], motion["speed"]
    momentum = (motion["ratio"] + 0.5) * DISPLACED
    print(f"{CASE}: Re_a = {reynolds:.3g} (Re {2 * reynolds:.3g}) at V0 = {speed:.4g} m/s")
    fig, ax = plt.subplots(figsize=(8, 4.5))
    for name in RESOLUTIONS:
        row = resolved(name)
        t = np.array(row["times"])
        rise = t >= exit_time
        exit_speed = row["speeds"][int(np.flatnonzero(rise)[0])]
        print(f"{name}: {row['cells']} cells, {len(t)} steps, {row['seconds']} s")
        for label, force in history_forces(row, exit_time, reynolds).items():
            shares = []
            for window in WINDOWS:
                inside = rise & (t <= exit_time + window * (t[-1] - exit_time))
                impulse = trapezoid(force[inside], t[inside]) / (momentum * exit_speed)
                shares.append(f"{impulse:+.4f}")
            print(f"  {label}: rise impulse over {WINDOWS} of the rise: {', '.join(shares)}")
            if name == "fine" or label == "resolved flow":
                style = "-" if label == "resolved flow" else "--"
                ax.plot(t[rise], force[rise], style, label=f"{label} ({name})")
    ax.set_xlabel("time since the hand-over, a / V0")
    ax.set_ylabel(r"history force, $\rho V_0^2 a^2$")
    ax.set_title(f"{CASE}'s reversal and rise, unbounded liquid, Re_a = {reynolds:.3g}")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(FIGURE, dpi=110)
    print(f"wrote {FIGURE}")


if __name__ == "__main__":
    main()
