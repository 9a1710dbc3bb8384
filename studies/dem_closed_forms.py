"""The closed forms for DEM, end to end: the tables, the fit, the held-back errors, the exports.

1. `ehdfem sweep` of studies/dem_closed_forms.toml (the fit table: St 1-1e4 x eps 1e-12-0.1
   x P_cav -1 to -1e5 and none x delta 1e-3, 0.5 x both layers; 2912 collisions) and of
   studies/dem_closed_forms_heldback.toml (192 points between the fit table's nodes in every
   input), on RANKS MPI ranks under `nice -n 10`. Both are resumable: a killed run loses
   nothing, and a rerun computes only the missing points (delete the `.points` folders first
   after a change of the solver, whose results would otherwise be reused).
2. `ehdfem fit` of the fit table with the held-back table: the forms' coefficients and
   their largest errors on the held-back points (studies/results/dem_closed_forms_fit.json),
   the Python module (dem_closed_forms.py), the C header (dem_closed_forms.h) and the fitted
   table (dem_closed_forms_table.csv), all in studies/results/.
3. The table's interpolation recipe (ehdfem.dem.lookup) measured on the held-back points too
   (dem_closed_forms_recipe.json), and the cost: collisions, CPU seconds, wall time.

Run: python studies/dem_closed_forms.py [--reduced] [--ranks N] [--held-back-only]
[--exports-only]
(or bash make.sh closed-forms). --reduced fits the 1080-point grid of
dem_closed_forms_reduced.toml instead of the full one. --held-back-only recomputes the
held-back points alone (after a change of the solver that moves the results by far less than
the forms' errors; delete dem_closed_forms_heldback.points first) and refits on the fit table
as it stands: the errors are then those of the forms against the current solver, and the fit
table's cost is kept from the run that computed it. --exports-only rewrites the Python module
and the C header from the stored fit (dem_closed_forms_fit.json: the forms and their held-back
errors), without sweeping or fitting, after a change of the exports alone.
"""

import argparse
import csv
import json
import os
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

from ehdfem.dem import export, fitting, lookup
from ehdfem.dem.table import table_rows
from ehdfem.version import __version__

STUDIES = Path(__file__).resolve().parent
RESULTS = STUDIES / "results"
MPI_ENV = {
    "OMPI_ALLOW_RUN_AS_ROOT": "1",
    "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1",
    "OMPI_MCA_rmaps_base_oversubscribe": "1",
}


def sweep(study: Path, ranks: int) -> float:
    """Run (or resume) the study on ``ranks`` ranks; its wall time [s]."""
    start = time.time()
    command = ["nice", "-n", "10", "mpirun", "-n", str(ranks), sys.executable, "-m", "ehdfem"]
    subprocess.run([*command, "sweep", str(study)], check=True, env={**os.environ, **MPI_ENV})
    return time.time() - start


def read(path: Path) -> list[dict]:
    with path.open(newline="") as f:
        return list(csv.DictReader(f))


def recipe_errors(fit_rows: list[dict], held_rows: list[dict], box: dict) -> dict:
    """Largest errors of the table's interpolation recipe on the held-back points, per layer
    (e_n over every point, e_t and 1 - e_t relative over the rebounds with e_n >= 0.3)."""
    table = lookup.build(fit_rows)
    out = {}
    for layer in ("thin", "immersed"):
        rows = [r for r in held_rows if r["layer"] == layer]
        found = [
            lookup.interpolate(table, box, r["St"], r["eps"], r["delta"], r["p_cav"], layer)
            for r in rows
        ]
        e_n = np.array([r["e_n"] for r in rows])
        e_t = np.array([r["e_t"] for r in rows])
        clear = e_n >= fitting.CLEAR_REBOUND
        got_n, got_t = (np.array([f[k] for f in found]) for k in ("e_n", "e_t"))
        out[layer] = {
            "e_n": float(np.nanmax(np.abs(got_n - e_n))),
            "e_t": float(np.nanmax(np.abs(got_t - e_t)[clear])),
            "tangential_loss_relative": float(
                np.nanmax(np.abs((1 - got_t) / (1 - e_t) - 1)[clear])
            ),
        }
    return out


def write_exports(name: str) -> None:
    """The Python module and the C header rewritten from the stored fit of ``name``'s table."""
    out = RESULTS / "dem_closed_forms"
    forms = json.loads(Path(f"{out}_fit.json").read_text())["closed_forms"]
    for suffix, writer in ((".py", export.python_source), (".h", export.c_header)):
        text = writer(forms, f"{name}.csv", __version__, forms.get("held_back"))
        Path(f"{out}{suffix}").write_text(text)
        print(f"wrote {out}{suffix}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--reduced", action="store_true", help="the 1080-point grid")
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--held-back-only", action="store_true", help="keep the fit table")
    parser.add_argument("--exports-only", action="store_true", help="rewrite .py, .h from the fit")
    args = parser.parse_args()
    name = "dem_closed_forms_reduced" if args.reduced else "dem_closed_forms"
    if args.exports_only:
        write_exports(name)
        return
    studies = {
        "fit": STUDIES / f"{name}.toml",
        "held_back": STUDIES / "dem_closed_forms_heldback.toml",
    }
    recomputed = ("held_back",) if args.held_back_only else tuple(studies)
    wall = {key: sweep(studies[key], args.ranks) for key in recomputed}
    table, held = RESULTS / f"{name}.csv", RESULTS / "dem_closed_forms_heldback.csv"
    out = RESULTS / "dem_closed_forms"
    subprocess.run(
        [sys.executable, "-m", "ehdfem", "fit", str(table), "--held-back", str(held),
         "--json", f"{out}_fit.json", "--python", f"{out}.py", "--c", f"{out}.h",
         "--table-out", f"{out}_table.csv"],
        check=True,
    )  # fmt: skip
    fit_rows, held_rows = table_rows(read(table)), table_rows(read(held))
    box = json.loads(Path(f"{out}_fit.json").read_text())["closed_forms"]["box"]
    recipe = Path(f"{out}_recipe.json")
    cost = json.loads(recipe.read_text())["cost"] if args.held_back_only else {}
    for key in recomputed:
        rows = read(RESULTS / f"{studies[key].stem}.csv")
        cost[key] = {
            "collisions": len(rows),
            "cpu_seconds": sum(float(r["seconds"]) for r in rows),
            "wall_seconds_this_run": wall[key],
        }
    report = {"recipe_held_back": recipe_errors(fit_rows, held_rows, box), "cost": cost}
    recipe.write_text(json.dumps(report, indent=1) + "\n")
    print(json.dumps(report, indent=1))


if __name__ == "__main__":
    main()
