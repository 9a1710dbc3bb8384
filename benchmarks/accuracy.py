"""Accuracy of every reported output at the default numerics, and what it costs.

For a grid of collisions (thin and immersed layers; no cavitation limit, truncation and mass-
conserving cavitation; St from 1.2 St_c to 1000; eps from 1e-6 to 0.1; the FE model at delta =
0.01; see ``cases``), each output of the result is compared with a converged run (rtol 1e-8,
twice the film nodes) and the cost of the default is compared with the old default (rtol 5e-5,
step control on X and V only). Every collision is oblique (30 degrees) so that e_t and the spin
change are measured too. Writes benchmarks/results/accuracy.json (per case and output the
relative error, per case the cost ratio; the largest of each) and prints the table of
docs/performance.md. Resumable: finished cases are kept in benchmarks/results/accuracy.csv.
Run: .venv/bin/python benchmarks/accuracy.py   (about 40 minutes)
"""

import os

os.environ["OPENBLAS_NUM_THREADS"] = os.environ["OMP_NUM_THREADS"] = "1"

import json  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

from ehdfem import (  # noqa: E402
    CollisionParameters,
    IntegratorOptions,
    collide,
    critical_stokes,
    study,  # noqa: E402
)
from ehdfem.collision import DEFAULT_NODES  # noqa: E402
from ehdfem.normal import NormalSolverError  # noqa: E402
from ehdfem.study import ResultTable  # noqa: E402

RESULTS = Path(__file__).resolve().parent / "results"
OUTPUTS = tuple(
    o for o in study.OUTPUTS if o not in ("rebound", "status", "energy_error", "film_nodes")
)
FILMS = {
    "none": {},
    "truncate": {"p_cav": -2.0},
    "mass-conserving": {"p_cav": -2.0, "cavitation": "mass-conserving"},
}
OLD = IntegratorOptions(rtol=5e-5, film_control=False)
CONVERGED = IntegratorOptions(rtol=1e-8)


def cases():
    """(name, layer, film, St, eps, film parameters) of the grid: the thin layer with every
    film model over the whole (St, eps) range, the immersed layer with every film model at
    St = 20, eps = 1e-3 and without a cavitation limit over the range, and the FE model."""
    ranges = ((20.0, 1e-3), (1000.0, 1e-6), (50.0, 0.1), ("near", 1e-3))
    out = []
    for layer in ("thin", "immersed"):
        for film, options in FILMS.items():
            for St, eps in ranges if layer == "thin" or film == "none" else ranges[:1]:
                out.append((f"{layer} {film} St={St} eps={eps:g}", layer, film, St, eps, options))
    out.append(
        ("fem thin truncate St=20 eps=1e-3", "thin", "truncate", 20.0, 1e-3, FILMS["truncate"])
    )
    return out


def parameters(layer, St, eps, options, model):
    base = dict(eps=eps, layer=layer, angle=30.0, delta=0.01, **options)
    if St == "near":
        head_on = CollisionParameters(St=1.0, **{**base, "angle": 0.0})
        St = 1.2 * critical_stokes(head_on, (1.0, 200.0), 1e-3, model=model)["St_c"]
    return CollisionParameters(St=St, **base)


def timed(params, model, nodes, options):
    start = time.perf_counter()
    summary = collide(params, model=model, nodes=nodes, options=options).summary()
    return summary, time.perf_counter() - start


def run_case(name, layer, film, St, eps, options):
    model = "fem" if name.startswith("fem") else "halfspace"
    params = parameters(layer, St, eps, options, model)
    default, seconds = timed(params, model, DEFAULT_NODES, IntegratorOptions())
    _, old_seconds = timed(params, model, DEFAULT_NODES, OLD)
    reference, _ = timed(params, model, 2 * DEFAULT_NODES, CONVERGED)
    row = {"case": name, "St": params.St, "status": default["status"]}
    for output in OUTPUTS:
        exact, value = reference[output], default[output]
        row[output] = "" if exact in (None, 0.0) or value is None else abs(value / exact - 1)
    row["seconds"], row["old_seconds"] = seconds, old_seconds
    return row


def main():
    RESULTS.mkdir(exist_ok=True)
    table = ResultTable(RESULTS / "accuracy.csv", ("case",))
    for case in cases():
        if table.get(case=case[0]) is None:
            print(case[0], flush=True)
            try:
                table.add(run_case(*case))
            except NormalSolverError as err:  # recorded, and left out of the figures
                table.add({"case": case[0], "status": f"failed: {err}"})
    rows = [r for r in table.rows if not r["status"].startswith("failed")]
    worst = {
        output: max((float(r[output]) for r in rows if r[output] not in ("", "None")), default=0)
        for output in OUTPUTS
    }
    ratios = [float(r["seconds"]) / float(r["old_seconds"]) for r in rows]
    summary = {
        "largest_relative_error": worst,
        "cost_ratio_to_old_default": {
            "max": max(ratios),
            "median": sorted(ratios)[len(ratios) // 2],
        },
        "cases": rows,
    }
    (RESULTS / "accuracy.json").write_text(json.dumps(summary, indent=1) + "\n")
    print("| output | largest relative error |\n|---|---|")
    for output, error in worst.items():
        print(f"| {output} | {100 * error:.2f} % |")
    print(
        f"cost / old default: median {summary['cost_ratio_to_old_default']['median']:.2f}, "
        f"max {max(ratios):.2f}"
    )


if __name__ == "__main__":
    main()
