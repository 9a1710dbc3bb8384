"""Figures of the kantak_davis study: e_n, St_c, e_t and spin change, fits against data.

Reads studies/results/kantak_davis.csv (ehdfem sweep), critical_*.json (ehdfem critical) and
kantak_davis_fit.json (ehdfem fit); writes docs/figures/kantak_davis_*.png.
"""

import csv
import json
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib import ticker  # noqa: E402

from ehdfem.dem.closedform import (  # noqa: E402
    davis_rager_good,
    fit_power_law,
    legendre,
    power_law,
)
from ehdfem.dem.forms import tangential_restitution  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
RESULTS = ROOT / "studies" / "results"
FIGURES = ROOT / "docs" / "figures"


class PlainLogFormatter(ticker.LogFormatterSciNotation):
    """Log-axis tick labels as plain numbers (6, 20, 0.001), on the ticks matplotlib would
    label, instead of 6x10^0."""

    def __call__(self, x, pos=None):
        return f"{x:g}" if super().__call__(x, pos) else ""


def plain_log_ticks(*axes) -> None:
    """Plain-number labels on the log axes of ``axes``."""
    for ax in axes:
        for axis, scale in ((ax.xaxis, ax.get_xscale()), (ax.yaxis, ax.get_yscale())):
            if scale == "log":
                axis.set_major_formatter(PlainLogFormatter())
                axis.set_minor_formatter(PlainLogFormatter(labelOnlyBase=False))


def main():
    with (RESULTS / "kantak_davis.csv").open() as f:
        rows = [r for r in csv.DictReader(f) if r["status"].startswith("ok")]
    fits = json.loads((RESULTS / "kantak_davis_fit.json").read_text())
    critical = sorted(
        (json.loads(p.read_text()) for p in RESULTS.glob("critical_*.json")), key=lambda c: c["eps"]
    )
    eps_values = sorted({float(r["eps"]) for r in rows})
    colours = plt.cm.viridis(np.linspace(0, 0.9, len(eps_values)))
    FIGURES.mkdir(parents=True, exist_ok=True)

    fig, (ax_n, ax_c) = plt.subplots(1, 2, figsize=(11, 4.5))
    for eps, colour in zip(eps_values, colours, strict=True):
        sel = [r for r in rows if float(r["eps"]) == eps]
        St = np.array([float(r["St"]) for r in sel])
        ax_n.semilogx(
            St, [float(r["e_n"]) for r in sel], "o", ms=3, color=colour, label=f"eps = {eps:g}"
        )
        group = next(g for g in fits["normal"] if g["eps"] == eps)
        fine = np.geomspace(St.min(), St.max(), 200)
        ax_n.semilogx(
            fine, davis_rager_good(fine, group["St_c"], group["e_inf"]), "-", color=colour, lw=1
        )
    ax_n.semilogx(fine, legendre(fine), "k--", lw=1, label="Legendre et al. 2006")
    ax_n.set_xlabel("St")
    ax_n.set_ylabel("e_n (e_dry = 1)")
    ax_n.legend(fontsize=7)
    ax_n.set_title("computed (dots), e_inf (1 - St_c/St) fits (lines)", fontsize=9)
    eps_c = np.array([c["eps"] for c in critical])
    ax_c.loglog(eps_c, [c["St_c"] for c in critical], "o", label="bisection (ehdfem critical)")
    for law, style, what in (
        (fit_power_law({"eps": eps_c}, np.array([c["St_c"] for c in critical])), "-", "power law"),
        (fits["critical_stokes_law"], ":", "St_c of the e_n fits"),
    ):
        label = f"{what}: {law['coefficient']:.3g} eps^{law['eps']:.3g}"
        ax_c.loglog(eps_c, power_law(law, eps=eps_c), style, label=label)
    ax_c.set_xlabel("eps")
    ax_c.set_ylabel("St_c")
    ax_c.legend(fontsize=8)
    plain_log_ticks(ax_n, ax_c)
    fig.suptitle("thin layer, delta = 0.01, P_cav = -10")
    fig.tight_layout()
    fig.savefig(FIGURES / "kantak_davis_normal.png", dpi=120)

    fig, (ax_t, ax_s) = plt.subplots(1, 2, figsize=(11, 4.5))
    for eps, colour in zip(eps_values, colours, strict=True):
        sel = [r for r in rows if float(r["eps"]) == eps and float(r["e_n"]) > 0]
        St = np.array([float(r["St"]) for r in sel])
        ax_t.loglog(
            St, [1 - float(r["e_t"]) for r in sel], "o", ms=3, color=colour, label=f"eps = {eps:g}"
        )
        ax_s.loglog(St, [float(r["spin_change"]) for r in sel], "o", ms=3, color=colour)
        loss = 1 - tangential_restitution(fits["closed_forms"], St, eps, 0.01, -10.0, "thin")
        for ax, line in ((ax_t, loss), (ax_s, loss / 0.4)):  # spin change (1 - e_t)/k
            ax.loglog(St, line, "-", color=colour, lw=1)
    ax_t.set_ylabel("1 - e_t")
    ax_s.set_ylabel(r"a$\Delta\Omega/U_0$")
    for ax in (ax_t, ax_s):
        ax.set_xlabel("St")
    ax_t.legend(fontsize=7)
    plain_log_ticks(ax_t, ax_s)
    fig.suptitle("rebounding spheres; lines: the closed forms for DEM (docs/studies.md)")
    fig.tight_layout()
    fig.savefig(FIGURES / "kantak_davis_tangential.png", dpi=120)
    print(f"wrote {FIGURES}/kantak_davis_normal.png and kantak_davis_tangential.png")


if __name__ == "__main__":
    main()
