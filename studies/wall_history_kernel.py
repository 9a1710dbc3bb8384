"""The wall-bounded history kernel of a sphere moving normal to a plane wall, from the unsteady
Stokes flow solved by finite elements in the Laplace domain (``ehdfem.bounce.wall_flow``), at
the gaps of ``ehdfem.bounce.unsteady.WALL_GAPS`` (docs/bounce.md, "The wall's history kernel").

For each gap h (by a) the impedance Z(k) is computed at Z(0) (Brenner's lambda, checked against
the series) and at the k of WALL_K (a sqrt(p/nu), 0.1 to 100: times from 1e-4 to 100 a^2/nu), and
the kernel's part is stored as its ratio to Basset's, rho^(k) = (Z(k) - Z(0) - (2/9) C_M(h) k^2)
/ k, with the FE's own Z(0) (its 1e-4 error would swamp the kernel at small k near contact) and
Hicks's C_M(h). The table is written to ehdfem/bounce/wall_kernel.json, which the "mei-adrian-wall"
kernel reads; each gap is stored as soon as it is done (studies/results/wall_history_kernel/),
so a stopped run computes only what is missing.

With ``--refinement`` it computes rho^ again at h = 0.01 a and 0.3 a with elements half as large
(FINE / 2) and writes the largest difference to studies/results/wall_history_kernel/
refinement.json (the table's discretisation error, docs/bounce.md).

Run: OPENBLAS_NUM_THREADS=1 mpirun -n 2 .venv/bin/python studies/wall_history_kernel.py
[--refinement] (about 4 minutes on 2 ranks; the refinement about 5 more).
"""

import json
import os
import sys
import time
from pathlib import Path

import numpy as np
from mpi4py import MPI

from ehdfem.bounce import unsteady
from ehdfem.bounce.wall_flow import FINE, WallFlow
from ehdfem.exact.sphere_towards_wall import resistance as brenner_factor

ROOT = Path(__file__).resolve().parents[1]
RESULTS = ROOT / "studies/results/wall_history_kernel"


def write_json(path: Path, data) -> None:
    """``data`` as JSON at ``path``, written to a temporary name and renamed."""
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_name(f".{path.name}.{os.getpid()}")
    tmp.write_text(json.dumps(data, indent=1))
    os.replace(tmp, path)


def gap_row(comm, gap: float, fine: float = FINE) -> dict:
    """Z(0) and rho^(k) at WALL_K for a sphere at ``gap`` (by a), elements ``fine`` (by a) on
    the sphere."""
    start = time.perf_counter()
    flow = WallFlow(comm, gap, fine=fine)
    steady = flow.impedance(0.0)
    k = unsteady.WALL_K
    added = 2.0 / 9.0 * 0.5 * unsteady.wall_added_mass(gap)[0] * k**2
    ratio = (np.array([flow.impedance(x) for x in k]) - steady - added) / k
    brenner = float(brenner_factor(gap))
    if comm.rank == 0:
        print(
            f"h/a = {gap:g}: {flow.cells} cells, Z(0)/lambda - 1 = {steady / brenner - 1:+.1e}, "
            f"{time.perf_counter() - start:.0f} s",
            flush=True,
        )
    return {
        "gap": gap,
        "steady": steady,
        "brenner": brenner,
        "cells": flow.cells,
        "ratio": ratio.tolist(),
    }


def refinement(comm) -> None:
    """rho^ at h = 0.01 a and 0.3 a with elements FINE / 2 against the table's."""
    table = json.loads(unsteady.WALL_TABLE.read_text())
    report = {}
    for gap in (0.01, 0.3):
        fine = gap_row(comm, gap, FINE / 2)
        coarse = table["ratio"][int(np.argmin(np.abs(np.array(table["gaps"]) - gap)))]
        report[f"{gap:g}"] = {
            "largest_difference": float(np.max(np.abs(np.array(fine["ratio"]) - coarse))),
            "fine_cells": fine["cells"],
        }
    if comm.rank == 0:
        write_json(RESULTS / "refinement.json", report)
        print(report)


def main():
    comm = MPI.COMM_WORLD
    if "--refinement" in sys.argv:
        refinement(comm)
        return
    rows = []
    for gap in unsteady.WALL_GAPS:
        path = RESULTS / f"gap_{gap:g}.json"
        if not path.exists():
            row = gap_row(comm, float(gap))
            if comm.rank == 0:
                write_json(path, row)
            comm.barrier()
        rows.append(json.loads(path.read_text()))
    if comm.rank == 0:
        table = {
            "source": "studies/wall_history_kernel.py",
            "k": unsteady.WALL_K.tolist(),
            "gaps": [row["gap"] for row in rows],
            "ratio": [row["ratio"] for row in rows],
            "steady_over_brenner": [row["steady"] / row["brenner"] for row in rows],
        }
        write_json(unsteady.WALL_TABLE, table)
        print(f"written {unsteady.WALL_TABLE.relative_to(ROOT)}")


if __name__ == "__main__":
    main()
