"""psi_out against psi_in of the solid impact with tangential compliance (docs/tangential.md).

MBF's variables Psi = kappa psi / mu (psi the contact point's tangential velocity over the normal
approach velocity) for a solid sphere (k = 2/5) on identical solids with nu = 0.3
(kappa = k_t/k_n = 2 (1 - nu)/(2 - nu) = 0.8235, chi = 1.441), at e = 1 (Maw, Barber & Fawcett's
elastic impact) and e = 0.8, against:

- the rigid-body Coulomb impact (stick: rolling, Psi_out = 0);
- MBF's exact limits (ehdfem.exact.compliant_impact): complete adhesion Psi_out = r Psi_in near
  0, gross slip Psi_out = Psi_in - 2 chi (1 + e) from max(1, 2 chi, 2 chi (1 + e) - 1/e) on;
- MBF's equations solved independently of the law (``entry_time_rebound``: springs laid down at
  the moving edge, implicit trapezoidal rule, 1000 steps per phase) at every fifth Psi_in;
- Walton's law with beta_0 = -r (ehdfem.exact.walton_impact);
- ehdfem's law (ehdfem.tangential.compliant_contact), on its default grid and on one twice as
  fine (the largest difference is printed).

Writes studies/results/compliant_impact.csv and docs/figures/compliant_impact.png.
Run: .venv/bin/python studies/compliant_impact.py   (about a minute)
"""

import csv
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from ehdfem.exact import compliant_impact as exact  # noqa: E402
from ehdfem.exact.walton_impact import walton_impact  # noqa: E402
from ehdfem.tangential.compliant_contact import compliant_impact  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
TABLE = ROOT / "studies" / "results" / "compliant_impact.csv"
FIGURE = ROOT / "docs" / "figures" / "compliant_impact.png"
NU, K = 0.3, 0.4
KAPPA = 2 * (1 - NU) / (2 - NU)
CHI = exact.impact_parameter(KAPPA, K)
RESTITUTIONS = (1.0, 0.8)
PSI_IN = np.linspace(0.05, 7.0, 70)


def rows():
    """One row per (e, Psi_in): the law on two grids, the references."""
    out = []
    for e_n in RESTITUTIONS:
        ratio = exact.adhesive_ratio(CHI, e_n)
        threshold = exact.gross_slip_threshold(CHI, e_n)
        reach = 2 * CHI * (1 + e_n)  # the rigid impact's change of Psi when sliding throughout
        for index, psi_in in enumerate(PSI_IN):
            law = compliant_impact(psi_in, CHI, e_n)
            independent = exact.entry_time_rebound(psi_in, CHI, e_n) if index % 5 == 0 else np.nan
            fine = compliant_impact(psi_in, CHI, e_n, cells=800, steps=4000)
            # Walton's law in psi with mu = kappa (Psi = psi): (1 + 1/k) mu (1 + e) = reach
            walton = walton_impact(psi_in, KAPPA, e_n, K, -ratio)
            out.append(
                dict(
                    e_n=e_n,
                    psi_in=psi_in,
                    ehdfem=law.psi_out,
                    ehdfem_fine=fine.psi_out,
                    gross_slip=law.gross_slip,
                    energy_error=law.energy_error,
                    independent=independent,
                    adhesion=ratio * psi_in,
                    gross_slip_line=psi_in - reach if psi_in >= threshold else np.nan,
                    rigid=max(psi_in - reach, 0.0),
                    walton=float(walton),
                )
            )
    return out


def plot(table):
    """Two panels, e = 1 and e = 0.8."""
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5), sharey=True)
    for ax, e_n in zip(axes, RESTITUTIONS, strict=True):
        part = [r for r in table if r["e_n"] == e_n]
        psi = np.array([r["psi_in"] for r in part])

        def column(name, part=part):
            return np.array([r[name] for r in part], dtype=float)

        ax.plot(psi, column("rigid"), color="0.5", label="rigid-body Coulomb")
        ax.plot(psi, column("walton"), "-.", color="tab:green", label="Walton, beta_0 = -r")
        small = psi <= 1.5
        ax.plot(psi[small], column("adhesion")[small], ":", color="k", lw=2,
                label="MBF exact: complete adhesion")  # fmt: skip
        ax.plot(psi, column("gross_slip_line"), "--", color="k", label="MBF exact: gross slip")
        threshold = exact.gross_slip_threshold(CHI, e_n)
        ax.plot([threshold], [threshold - 2 * CHI * (1 + e_n)], "ko")
        ax.plot(psi, column("ehdfem"), color="tab:red", lw=1.5, label="ehdfem (compliant)")
        ax.plot(psi, column("independent"), "s", mfc="none", color="tab:blue",
                label="MBF's equations, independent solution")  # fmt: skip
        ax.axhline(0.0, color="0.8", lw=0.5)
        ax.set_title(f"solid sphere, nu = {NU}, chi = {CHI:.3f}, e = {e_n}")
        ax.set_xlabel("Psi_in = kappa psi_in / mu")
    axes[0].set_ylabel("Psi_out = kappa psi_out / mu")
    axes[0].legend(fontsize=8)
    fig.tight_layout()
    FIGURE.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(FIGURE, dpi=120)


def main():
    table = rows()
    TABLE.parent.mkdir(parents=True, exist_ok=True)
    with open(TABLE, "w", newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=list(table[0]))
        writer.writeheader()
        writer.writerows(table)
    for e_n in RESTITUTIONS:
        part = [r for r in table if r["e_n"] == e_n]
        grid = max(abs(r["ehdfem"] - r["ehdfem_fine"]) for r in part)
        lowest = min(part, key=lambda r: r["ehdfem"])
        negative = [r["psi_in"] for r in part if r["ehdfem"] < 0]
        walton = max(abs(r["ehdfem"] - r["walton"]) for r in part)
        checked = [r for r in part if np.isfinite(r["independent"])]
        independent = max(abs(r["ehdfem"] - r["independent"]) for r in checked)
        relative = max(abs(r["ehdfem"] / r["independent"] - 1) for r in checked)
        print(
            f"e = {e_n}: r = {exact.adhesive_ratio(CHI, e_n):.5f}, threshold "
            f"{exact.gross_slip_threshold(CHI, e_n):.4f}, grid difference {grid:.1e}, "
            f"lowest Psi_out {lowest['ehdfem']:.4f} at {lowest['psi_in']:.3f}, reversal over "
            f"{min(negative):.3f}-{max(negative):.3f}, largest |law - Walton| {walton:.3f}, "
            f"largest energy error {max(r['energy_error'] for r in part):.1e}, against the "
            f"independent solution {independent:.1e} ({relative:.2%} of it)"
        )
    plot(table)


if __name__ == "__main__":
    main()
