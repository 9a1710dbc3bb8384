"""Plots of a collision (matplotlib, PNG): the normal motion's histories and profiles in SI for
a physical collision (given its :class:`ehdfem.inputs.scales.Scales`), else in the scaled
units of ehdfem.inputs.scales; the tangential motion in its scaled units (by U0)."""

from __future__ import annotations

import textwrap
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

PRESSURE_UNIT = "mu V0 a / x0^2"  # the film pressure scale


def axes(units=None) -> dict:
    """{quantity: (factor, axis label)} of the normal motion's plots and animation: SI given
    ``units`` (:class:`ehdfem.inputs.scales.Scales`), else the scaled variables and their
    scales."""
    if units:
        return {
            "radius": (units.radius, "r [m]"),
            "film": (units.gap, "film h [m]"),
            "pressure": (units.pressure, "pressure p [Pa]"),
            "gap": (units.gap, "gap x [m]"),
            "velocity": (units.velocity, "velocity v [m/s]"),
            "force": (units.force, "force F [N]"),
            "time": (units.time, "t [s]"),
        }
    return {
        "radius": (1.0, "R (by sqrt(a x0))"),
        "film": (1.0, "film H (by x0)"),
        "pressure": (1.0, f"pressure P (by {PRESSURE_UNIT})"),
        "gap": (1.0, "gap X (by x0)"),
        "velocity": (1.0, "velocity V (by V0)"),
        "force": (1.0, "force F (by 6 pi mu V0 a^2 / x0)"),
        "time": (1.0, "T (by x0/V0)"),
    }


def profile_instants(result) -> list[tuple[int, str]]:
    """The steps where the film changes, each with the name of its phase, in time order:

    - approach: the gap X has closed to half the layer (the film still a paraboloid);
    - X = 0: the undeformed solids would touch, from here on the solids flatten;
    - maximum force;
    - maximum compression (smallest X, V = 0): the dimple (film thinner at its rim than on
      the axis) is deepest around here;
    - rebound: after maximum compression, the force back to half its maximum;
    - strongest suction: the most negative force (the film pulls the sphere back), if any;
    - exit (rebound) or end (sticking): the last step.

    Phases that do not occur (a sphere that stops before X = 0, no suction) are left out, and
    phases at the same step share it. Returns [(step, label)]."""
    hist = result.history
    last = len(hist.time) - 1
    deepest = int(np.argmin(hist.gap))
    strongest = int(np.argmax(hist.force))
    phases = [
        (_first(hist.gap <= 0.5), "approach"),
        (_first(hist.gap <= 0.0), "X = 0"),
        (strongest, "maximum force"),
        (deepest, "maximum compression"),
        (
            _first((hist.force <= 0.5 * hist.force[strongest]) & (np.arange(last + 1) > deepest)),
            "rebound",
        ),
        (int(np.argmin(hist.force)) if hist.force.min() < 0 else None, "strongest suction"),
        (last, "exit" if result.rebound else "end"),
    ]
    labels = {}
    for step, phase in phases:
        if step is not None and step > 0:
            labels.setdefault(step, []).append(phase)
    return [(step, " + ".join(labels[step])) for step in sorted(labels)]


def _first(condition) -> int | None:
    """The first index where ``condition`` holds, None if nowhere."""
    hits = np.flatnonzero(condition)
    return int(hits[0]) if len(hits) else None


def plot_histories(result, path: Path, units=None, heading: str | None = None) -> Path:
    """Gap, velocity, force and film thickness (central and minimum) against time, in SI given
    ``units`` (:func:`axes`); ``heading``: a line above the title (a physical collision's
    inputs)."""
    hist, of = result.history, axes(units)
    time = of["time"][0] * hist.time
    fig, panels = plt.subplots(2, 2, figsize=(10, 7), sharex=True)
    for ax, (values, name) in zip(
        panels.flat,
        ((hist.gap, "gap"), (hist.velocity, "velocity"), (hist.force, "force")),
        strict=False,
    ):
        ax.plot(time, of[name][0] * values, lw=1.5)
        ax.set_ylabel(of[name][1])
        ax.grid(alpha=0.3)
    ax = panels[1, 1]
    film = of["film"][0]
    ax.semilogy(time, film * hist.central_film, label="on the axis")
    ax.semilogy(time, film * hist.min_film, "--", label="minimum")
    ax.set_ylabel(of["film"][1])
    ax.legend(loc="best")
    ax.grid(alpha=0.3, which="both")
    for ax in panels[1]:
        ax.set_xlabel(of["time"][1])
    fig.suptitle(_title(result, heading))
    return _save(fig, path)


def plot_profiles(result, path: Path, units=None, heading: str | None = None) -> Path:
    """Pressure and film thickness against the radius at the instants where the film changes
    (:func:`profile_instants`: approach, X = 0, maximum force, maximum compression, rebound,
    strongest suction, exit), each labelled with its phase and time; in SI given ``units``
    (:func:`axes`), else by mu V0 a / x0^2, x0, sqrt(a x0) and x0/V0; ``heading`` as in
    :func:`plot_histories`."""
    hist, of = result.history, axes(units)
    (p_unit, p_label), (h_unit, h_label) = of["pressure"], of["film"]
    (r_unit, r_label), (t_unit, t_label) = of["radius"], of["time"]
    fig, (ax_p, ax_h) = plt.subplots(1, 2, figsize=(14.5, 4.8))
    instants = profile_instants(result)
    steps = [step for step, _ in instants]
    colours = plt.cm.viridis(np.linspace(0, 0.9, len(steps)))
    # show the radii where the pressure matters: 1.5 times the widest 1 % support of P
    pressure = np.abs(hist.pressure[steps])
    loaded = result.radii[(pressure > 0.01 * pressure.max()).any(axis=0)]
    shown = result.radii <= 1.5 * (loaded.max() if len(loaded) else result.radii[-1])
    radii = r_unit * result.radii[shown]
    symbol, _, unit = t_label.partition(" ")
    unit = unit.removeprefix("[").removesuffix("]")
    for colour, (i, phase) in zip(colours, instants, strict=True):
        label = f"{phase}, {symbol} = {t_unit * hist.time[i]:.4g} {unit}".rstrip()
        ax_p.plot(radii, p_unit * hist.pressure[i][shown], color=colour, label=label)
        ax_h.semilogy(radii, h_unit * hist.film_thickness[i][shown], color=colour, label=label)
    ax_p.axhline(0.0, color="0.6", lw=0.8)
    ax_p.set_ylabel(p_label)
    suction = -p_unit * float(hist.pressure[steps][:, shown].min())
    if suction > 0:  # linear near 0, logarithmic beyond: the suction and the peak both show
        linear = symlog_threshold(suction, p_unit * float(pressure.max()))
        ax_p.set_yscale("symlog", linthresh=linear)
        ax_p.set_ylim(bottom=-2 * max(suction, linear))
        exponent = round(np.log10(linear))
        ax_p.set_ylabel(f"{p_label}; linear within $\\pm 10^{{{exponent}}}$")
    ax_h.set_ylabel(h_label)
    for ax in (ax_p, ax_h):
        ax.set_xlabel(r_label)
        ax.grid(alpha=0.3)
    ax_h.legend(  # beside the plots: the curves stay visible
        fontsize=8, title="phase", title_fontsize=8, loc="upper left", bbox_to_anchor=(1.02, 1.0)
    )
    fig.suptitle(_title(result, heading))
    return _save(fig, path)


def symlog_threshold(suction: float, largest: float) -> float:
    """The linear range +-L of a symlog pressure axis for a film whose strongest suction is
    ``suction`` and whose largest pressure is ``largest`` (both > 0, in the axis's unit): the
    power of ten at or below the suction, but not below 1e-6 of the largest pressure. A power
    of ten puts the ticks at 0 and at whole decades only (+-L, +-10 L, ...), each a decade or
    more from the next, so their labels cannot overlap; a threshold such as 2 or 9.9e4 put a
    decade tick (1, 1e4) inside the linear range, a fraction of a decade from 0."""
    return float(10.0 ** np.floor(np.log10(max(suction, 1e-6 * largest))))


def plot_tangential(collision, path: Path, heading: str | None = None, units=None) -> Path:
    """Tangential velocity U, spin a Omega, slip U - a Omega (all by U0) and the tangential
    force (by 6 pi mu a^2 U0 / x0) against time T; with ``units``
    (:class:`ehdfem.inputs.scales.Scales`) also in SI on the opposite axes (m/s, N, s; U0 =
    V0 tan(angle)); ``heading`` as in :func:`plot_histories`."""
    t = collision.tangential
    fig, (ax_v, ax_f) = plt.subplots(1, 2, figsize=(11, 4.5))
    ax_v.plot(t.time, t.velocity, label="U")
    ax_v.plot(t.time, t.spin, label=r"a$\Omega$")
    ax_v.plot(t.time, t.slip, "--", label=r"slip U - a$\Omega$")
    ax_v.set_ylabel("velocity (by $U_0$)")
    ax_v.legend()
    ax_f.plot(t.time, t.force)
    ax_f.set_ylabel(r"tangential force (by $6\pi\mu a^2 U_0/x_0$)")
    for ax in (ax_v, ax_f):
        ax.set_xlabel("time T (by $x_0/V_0$)")
        ax.grid(alpha=0.3)
    if units:
        along = collision.normal.params.tangential_speed  # U0 / V0
        for ax, factor, label in (
            (ax_v, units.velocity * along, "velocity [m/s]"),
            (ax_f, units.force * along, "tangential force [N]"),
        ):
            _si_axes(ax, units.time, factor, label)
    e_t = "-" if t.e_t is None else f"{t.e_t:.5g}"
    fig.suptitle(f"{_title(collision.normal, heading)}; {t.model}: e_t = {e_t} ({t.at})")
    return _save(fig, path)


def _si_axes(ax, time_unit: float, value_unit: float, label: str) -> None:
    """Secondary axes in SI beside a scaled plot: t [s] on top, ``label`` on the right, the
    scaled values times ``value_unit``."""
    top = ax.secondary_xaxis("top", functions=(lambda x: x * time_unit, lambda x: x / time_unit))
    top.set_xlabel("t [s]")
    right = ax.secondary_yaxis(
        "right", functions=(lambda y: y * value_unit, lambda y: y / value_unit)
    )
    right.set_ylabel(label)


def plot_bounce(result, path: Path) -> Path:
    """A bounce (:class:`ehdfem.bounce.result.BounceResult`) as in the experiments: left,
    gap / D against t / sqrt(D/g), time 0 at the first contact, each apex marked, with the gap
    [mm] and the time [s] on the opposite axes; right, each contact's restitution e against its
    St, the contacts joined in order. No text is placed inside the plots, so no label can cover
    another however close the late, small bounces come."""
    inputs = result.inputs
    diameter, unit = inputs.diameter, inputs.time_scale()
    trajectory = result.trajectory
    contact = np.flatnonzero(trajectory["phase"] == "contact")
    start = trajectory["time"][contact[0]] if contact.size else 0.0
    fig, (ax, ax_e) = plt.subplots(1, 2, figsize=(12, 4.8), gridspec_kw={"width_ratios": (2.3, 1)})
    ax.plot(
        (trajectory["time"] - start) / unit,
        trajectory["gap"] / diameter,
        lw=1.4,
        label=f"ehdfem bounce ({result.model}, {inputs.drag})",
    )
    apexes = [c for c in result.contacts if c.apex_time is not None]
    ax.plot(
        [(c.apex_time - start) / unit for c in apexes],
        [c.apex_gap / diameter for c in apexes],
        "o",
        ms=4,
        color="C3",
        label="apex after a contact",
    )
    ax.set_xlabel(r"$t/\sqrt{D/g}$")
    ax.set_ylabel("gap / D")
    ax.set_ylim(bottom=0.0)
    ax.grid(alpha=0.3)
    ax.legend(loc="best", fontsize=9)
    millimetres = 1e3 * diameter
    _si_axes(ax, unit, millimetres, "gap [mm]")
    restitutions = [c.e for c in result.contacts]
    ax_e.plot([c.St for c in result.contacts], restitutions, "o-", ms=5)
    ax_e.set_xlabel(r"St of the contact, $\rho_p D v / (9 \mu)$")
    ax_e.set_ylabel("restitution e of the contact")
    ax_e.set_ylim(0.0, max([1.0, *restitutions]))
    ax_e.grid(alpha=0.3)
    ax_e.set_title("each contact (the first at the largest St)", fontsize=9)
    fig.suptitle(
        f"{inputs.sphere.name} sphere, D = {millimetres:.3g} mm, in {inputs.liquid.name}: "
        f"{result.status}",
        fontsize=10,
    )
    return _save(fig, path)


def _title(result, heading: str | None = None) -> str:
    """The groups and the outcome, below ``heading`` (wrapped at 100 characters) if given."""
    p = result.params
    outcome = f"e_n = {result.e_n:.4g}" if result.rebound else "sticks"
    title = f"St = {p.St:.4g}, eps = {p.eps:.3g}, {p.layer} layer: {outcome}"
    return f"{textwrap.fill(heading, 100)}\n{title}" if heading else title


def _save(fig, path: Path) -> Path:
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path
