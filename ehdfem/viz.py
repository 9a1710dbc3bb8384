"""Plots of a collision (matplotlib, PNG). All axes are in the scaled units of ehdfem.scales."""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def snapshot_indices(result, count: int = 6) -> list[int]:
    """Steps worth showing: evenly spread in time plus the instants of maximum force and
    maximum compression and the last step."""
    hist = result.history
    steps = np.unique(
        np.concatenate(
            [
                np.searchsorted(hist.time, np.linspace(0, hist.time[-1], count)[1:-1]),
                [int(np.argmax(hist.force)), int(np.argmin(hist.gap)), len(hist.time) - 1],
            ]
        )
    )
    return [int(i) for i in steps if 0 < i < len(hist.time)]


def plot_histories(result, path: Path) -> Path:
    """Gap X, velocity V, force F and film thickness (central and minimum) against time T."""
    hist = result.history
    fig, axes = plt.subplots(2, 2, figsize=(10, 7), sharex=True)
    panels = [
        (axes[0, 0], hist.gap, "gap X (by $x_0$)"),
        (axes[0, 1], hist.velocity, "normal velocity V (by $V_0$)"),
        (axes[1, 0], hist.force, r"force F (by $6\pi\mu V_0 a^2/x_0$)"),
    ]
    for ax, values, label in panels:
        ax.plot(hist.time, values, lw=1.5)
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    ax = axes[1, 1]
    ax.semilogy(hist.time, hist.central_film, label="on the axis")
    ax.semilogy(hist.time, hist.min_film, "--", label="minimum")
    ax.set_ylabel("film thickness H (by $x_0$)")
    ax.legend()
    ax.grid(alpha=0.3, which="both")
    for ax in axes[1]:
        ax.set_xlabel("time T (by $x_0/V_0$)")
    fig.suptitle(_title(result))
    return _save(fig, path)


def plot_profiles(result, path: Path) -> Path:
    """Pressure P(R) and film thickness H(R) at the snapshot instants."""
    hist = result.history
    fig, (ax_p, ax_h) = plt.subplots(1, 2, figsize=(11, 4.5))
    steps = snapshot_indices(result)
    colours = plt.cm.viridis(np.linspace(0, 0.9, len(steps)))
    # show the radii where the pressure matters: 1.5 times the widest 1 % support of P
    pressure = np.abs(hist.pressure[steps])
    loaded = result.radii[(pressure > 0.01 * pressure.max()).any(axis=0)]
    shown = result.radii <= 1.5 * (loaded.max() if len(loaded) else result.radii[-1])
    for colour, i in zip(colours, steps, strict=True):
        label = f"T = {hist.time[i]:.4g}"
        ax_p.plot(result.radii[shown], hist.pressure[i][shown], color=colour, label=label)
        ax_h.semilogy(result.radii[shown], hist.film_thickness[i][shown], color=colour, label=label)
    ax_p.set_ylabel("pressure P (by $\\mu V_0 a/x_0^2$)")
    ax_h.set_ylabel("film thickness H (by $x_0$)")
    for ax in (ax_p, ax_h):
        ax.set_xlabel("radius R (by $\\sqrt{a x_0}$)")
        ax.grid(alpha=0.3)
    ax_p.legend(fontsize=8)
    fig.suptitle(_title(result))
    return _save(fig, path)


def plot_tangential(collision, path: Path) -> Path:
    """Tangential velocity U, spin a Omega, slip U - a Omega (all by U0) and the tangential
    force (by 6 pi mu a^2 U0 / x0) against time T."""
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
    e_t = "-" if t.e_t is None else f"{t.e_t:.5g}"
    fig.suptitle(f"{_title(collision.normal)}; {t.model}: e_t = {e_t} ({t.at})")
    return _save(fig, path)


def _title(result) -> str:
    p = result.params
    outcome = f"e_n = {result.e_n:.4g}" if result.rebound else "sticks"
    return f"St = {p.St:g}, eps = {p.eps:g}, {p.layer} layer: {outcome}"


def _save(fig, path: Path) -> Path:
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path
