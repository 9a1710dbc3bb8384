"""Accuracy of every reported output at the default numerics, and what it costs.

For a grid of collisions (thin and immersed layers; no cavitation limit, truncation and mass-
conserving cavitation; St from 1.2 St_c to 1000; eps from 1e-6 to 0.1; the FE model at delta =
0.01; see ``cases``), each output of the result is compared with a converged run (rtol 1e-7,
twice the film nodes) and the cost of the default is compared with the old default (BDF up to
order 3, rtol 5e-5, step control on X and V only), in wall time (the fastest of REPEATS runs
each) and in implicit steps tried. The reference's own time error is measured too: the largest
relative change of an output when its rtol is ten times looser. The old default is the old
control on the old film grid (the sinh grid of ehdfem.film.grid.radial_grid, uniform inside the
largest contact radius and geometric beyond). Every collision is oblique (30 degrees) so that
e_t and the spin change are measured too. Writes benchmarks/results/accuracy.json after each
case (per case and output the relative error, per case the cost ratios; the largest of each;
"cases_done" of "cases") and prints the table of docs/performance.md. Resumable: the converged
runs, the expensive part, are kept in benchmarks/results/accuracy_references.csv, keyed by the
case and their film grid (a change of the grid recomputes them); the default and old runs are
redone each time.
Run: .venv/bin/python benchmarks/accuracy.py   (about 40 minutes from scratch, 6 after;
--stored: only the cases whose reference is stored; --corners: the corners of the box real
collisions cover instead, to benchmarks/results/accuracy_corners.json; --hard: its St = 1e4
corners, against 4 times the nodes at rtol 2e-5, to accuracy_hard_corners.json, about 40 min)
"""

import os

os.environ["OPENBLAS_NUM_THREADS"] = os.environ["OMP_NUM_THREADS"] = "1"

import json  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402
from statistics import median  # noqa: E402

import numpy as np  # noqa: E402

from ehdfem import (  # noqa: E402
    CollisionParameters,
    IntegratorOptions,
    collide,
    critical_stokes,
)
from ehdfem.collision import DEFAULT_NODES, elasticity, film_extent, film_radii  # noqa: E402
from ehdfem.config import Numerics, RunConfig
from ehdfem.film.grid import radial_grid  # noqa: E402
from ehdfem.motion.normal import NormalSolverError  # noqa: E402
from ehdfem.study.sweep import (  # noqa: E402
    ResultTable,
    write_atomic,  # noqa: E402
)

RESULTS = Path(__file__).resolve().parent / "results"
OUTPUTS = (  # the measured outputs of ehdfem.outputs.registry (not flags, counts or checks)
    "e_n",
    "max_rebound_velocity",
    "min_film_thickness",
    "max_force",
    "contact_time",
    "max_compression",
    "e_t",
    "spin_change",
)
FILMS = {
    "none": {},
    "truncate": {"p_cav": -2.0},
    "mass-conserving": {"p_cav": -2.0, "cavitation": "mass-conserving"},
}
OLD = IntegratorOptions(rtol=5e-5, film_control=False, order=3)  # the old default control
CONVERGED = IntegratorOptions(rtol=1e-7)
HARD_REFERENCE = (4, IntegratorOptions(rtol=2e-5))  # nodes / default, options: hard_corners
REPEATS = 5  # timed runs of the default and the old default each: runs of ~1 s vary by 15 %


def cases():
    """(name, layer, film, St, eps, film parameters) of the grid: the thin layer with every
    film model over the whole (St, eps) range, the immersed layer with every film model at
    St = 20, eps = 1e-3 and without a cavitation limit over the range, and the FE model; the
    thin mass-conserving cases, whose references take longest, last."""
    ranges = ((20.0, 1e-3), (1000.0, 1e-6), (50.0, 0.1), ("near", 1e-3))
    out = []
    for layer in ("thin", "immersed"):
        for film, options in FILMS.items():
            for St, eps in ranges if layer == "thin" or film == "none" else ranges[:1]:
                out.append((f"{layer} {film} St={St} eps={eps:g}", layer, film, St, eps, options))
    out.append(
        ("fem thin truncate St=20 eps=1e-3", "thin", "truncate", 20.0, 1e-3, FILMS["truncate"])
    )
    slow = [case for case in out if case[0].startswith("thin mass-conserving")]
    return [case for case in out if case not in slow] + slow  # the slowest references last


def corners():
    """(name, layer, film, St, eps, film parameters) of the corners of the box real collisions
    cover (issue 34; eps 1e-12 to 0.1, P_cav -1e5 to -1 and none, St 1 to 1e4, delta 1e-3 to
    0.5), as many as an hour of references allows: the rigid limit (eps 1e-12, St 10: the film
    stops the sphere before it flattens), the mixed regime (eps 1e-9, St 100: rigid over
    decades of gap, then flattened), the weakest suction on the softest impact (P_cav = -1,
    eps = 0.1, St = 2) and the largest delta (0.5)."""
    return [
        ("corner thin none St=10 eps=1e-12", "thin", "none", 10.0, 1e-12, {}),
        ("corner immersed none St=10 eps=1e-12", "immersed", "none", 10.0, 1e-12, {}),
        ("corner immersed none St=100 eps=1e-9", "immersed", "none", 100.0, 1e-9, {}),
        (
            "corner thin truncate St=2 eps=0.1 P_cav=-1",
            "thin",
            "truncate",
            2.0,
            0.1,
            {"p_cav": -1.0},
        ),
        ("corner thin none St=100 eps=1e-6 delta=0.5", "thin", "none", 100.0, 1e-6, {"delta": 0.5}),
    ]


def hard_corners():
    """The box's corners at St = 1e4 (issue 34), where the thinnest film is the exit
    constriction at the rim of a contact flattened a thousand times more than the film is thick,
    and the weakest suction at St = 30: (name, layer, film, St, eps, film parameters). Their
    references are HARD_REFERENCE's: twice the nodes are not converged there (the thinnest
    film moves by 0.2 % from 960 to 1920 nodes)."""
    return [
        (
            "hard thin truncate St=1e4 eps=1e-12 P_cav=-1e5",
            "thin",
            "truncate",
            1e4,
            1e-12,
            {"p_cav": -1e5},
        ),
        (
            "hard immersed truncate St=1e4 eps=1e-6 P_cav=-1e5",
            "immersed",
            "truncate",
            1e4,
            1e-6,
            {"p_cav": -1e5},
        ),
        (
            "hard thin truncate St=1e4 eps=0.1 P_cav=-1",
            "thin",
            "truncate",
            1e4,
            0.1,
            {"p_cav": -1.0},
        ),
        ("hard immersed none St=1e4 eps=1e-9", "immersed", "none", 1e4, 1e-9, {}),
        (
            "hard thin truncate St=30 eps=1e-12 P_cav=-1e5",
            "thin",
            "truncate",
            30.0,
            1e-12,
            {"p_cav": -1e5},
        ),
    ]


SELECTIONS = {  # the command line's choice: its cases and the file it writes
    "cases": (cases, "accuracy.json"),
    "corners": (corners, "accuracy_corners.json"),
    "hard": (hard_corners, "accuracy_hard_corners.json"),
}


def parameters(layer, St, eps, options, model):
    base = {**dict(eps=eps, layer=layer, angle=30.0, delta=0.01), **options}
    if St == "near":  # St_c with the fixed OLD numerics, so the case does not move with defaults
        head_on = CollisionParameters.from_settings(St=1.0, **{**base, "angle": 0.0})
        St = (
            1.2
            * critical_stokes(
                head_on,
                (1.0, 200.0),
                1e-3,
                RunConfig(model=model, numerics=Numerics(integrator=OLD)),
            )["St_c"]
        )
    return CollisionParameters.from_settings(St=St, **base)


def old_radii(params, nodes=DEFAULT_NODES):
    """The old default film grid: sinh nodes, uniform inside the rim of ehdfem.film_extent."""
    rim, outer = film_extent(params)
    return radial_grid(nodes, min(rim, 0.5 * outer), outer)


def grid_key(radii):
    """A fingerprint of a film grid, to tell whether a stored reference was run on it."""
    return f"{len(radii)}:{float(np.sum(radii)):.12g}"


def timed(params, model, nodes, options, repeats=1, radii=None):
    """(summary, the fastest of ``repeats`` wall times, implicit steps tried) of a collision on
    ``film_radii`` with ``nodes`` nodes, or on ``radii`` (the compliance build timed too)."""
    seconds = []
    for _ in range(repeats):
        start = time.perf_counter()
        if radii is None:
            result = collide(
                params, RunConfig(model=model, numerics=Numerics(nodes=nodes, integrator=options))
            )
        else:
            compliance = elasticity(params, radii, RunConfig(model=model))
            result = collide(
                params,
                RunConfig(model=model, numerics=Numerics(integrator=options)),
                compliance=compliance,
            )
        seconds.append(time.perf_counter() - start)
    tried = result.normal.steps + result.normal.rejected_steps
    return result.summary(), min(seconds), tried


def relative_errors(values, exact):
    """Per output |value / exact - 1| ('' where either is missing or the exact value is 0)."""
    errors = {}
    for output in OUTPUTS:
        value, true = values[output], exact[output]
        known = value not in ("", "None", None) and true not in ("", "None", None)
        known = known and float(true) != 0.0
        errors[output] = abs(float(value) / float(true) - 1) if known else ""
    return errors


def reference(table, name, params, model, compute=True):
    """The converged run of case ``name`` (computed once, then read from ``table``; None if
    it is not stored and not ``compute``), with its own time error: the largest relative
    change of an output at a ten times looser rtol. Twice the default nodes at rtol 1e-7, or
    for the hard corners (names starting "hard") HARD_REFERENCE's nodes and rtol."""
    factor, converged_options = (2, CONVERGED) if not name.startswith("hard") else HARD_REFERENCE
    nodes = factor * DEFAULT_NODES
    grid = grid_key(film_radii(params, nodes))
    row = table.get(case=name, grid=grid)
    if row is None and compute:
        converged, _, _ = timed(params, model, nodes, converged_options)
        looser_options = IntegratorOptions(rtol=10 * converged_options.rtol)
        looser, _, _ = timed(params, model, nodes, looser_options)
        errors = [e for e in relative_errors(looser, converged).values() if e != ""]
        row = table.add(
            {
                "case": name,
                "grid": grid,
                **{o: converged[o] for o in OUTPUTS},
                "time_error": max(errors),
            }
        )
    return row


def run_case(references, name, layer, film, St, eps, options, compute=True, repeats=REPEATS):
    """The row of one case (None if its reference is not stored and not ``compute``), the
    default and the old default timed ``repeats`` times each."""
    model = "fem" if name.startswith("fem") else "halfspace"
    params = parameters(layer, St, eps, options, model)
    exact = reference(references, name, params, model, compute)
    if exact is None:
        return None
    default, seconds, tried = timed(params, model, DEFAULT_NODES, IntegratorOptions(), repeats)
    _, old_seconds, old_tried = timed(params, model, DEFAULT_NODES, OLD, repeats, old_radii(params))
    row = {"case": name, "St": params.St, "status": default["status"]}
    row.update(relative_errors(default, exact))
    row["reference_time_error"] = float(exact["time_error"])
    row["cost_ratio"], row["steps_ratio"] = seconds / old_seconds, tried / old_tried
    return row


def main(stored_only=False, selection="cases"):
    """Every case, or with ``stored_only`` (--stored) only those whose reference is stored:
    the cheap runs alone, e.g. to time them again on an idle machine; with ``selection``
    "corners" (--corners) the box's corners instead (:func:`corners`), written to
    accuracy_corners.json, "hard" (--hard) its St = 1e4 corners (:func:`hard_corners`), to
    accuracy_hard_corners.json."""
    RESULTS.mkdir(exist_ok=True)
    references = ResultTable(RESULTS / "accuracy_references.csv", ("case", "grid"))
    select, name = SELECTIONS[selection]
    grid, rows, output = select(), [], RESULTS / name
    for case in grid:
        print(case[0], flush=True)
        try:
            row = run_case(
                references,
                *case,
                compute=not stored_only,
                repeats=1 if selection != "cases" else REPEATS,
            )
        except NormalSolverError as err:  # recorded, and left out of the figures
            row = {"case": case[0], "status": f"failed: {err}"}
        if row is None:
            continue
        rows.append(row)
        summary = summarise(rows, len(grid))
        write_atomic(output, json.dumps(summary, indent=1) + "\n")
    print_table(summary)


def summarise(rows, cases):
    """The largest error of each output and the cost ratios over the cases done so far."""
    done = [r for r in rows if not r["status"].startswith("failed")]
    worst = {o: max((r[o] for r in done if r[o] != ""), default=0.0) for o in OUTPUTS}
    summary = {
        "largest_relative_error": worst,
        "largest_reference_time_error": max(
            (r["reference_time_error"] for r in done), default=None
        ),
        "cost_ratio_to_old_default": {
            key: {"max": max(r[key] for r in done), "median": median([r[key] for r in done])}
            for key in ("cost_ratio", "steps_ratio")
            if done
        },
        "cases_done": len(rows),
        "cases": cases,
        "rows": rows,
    }
    return summary


def print_table(summary):
    """The table of docs/performance.md and the largest errors."""
    done = [r for r in summary["rows"] if not r["status"].startswith("failed")]
    names = ("e_n", "max_rebound_velocity", "min_film_thickness", "max_force", "contact_time")
    names += ("max_compression", "e_t", "spin_change")
    print("| case | " + " | ".join(names) + " | cost | steps |")
    print("|---" * (len(names) + 3) + "|")
    for r in done:
        cells = ["" if r[o] == "" else f"{100 * r[o]:.2f}" for o in names]
        cells += [f"{r['cost_ratio']:.2f}", f"{r['steps_ratio']:.2f}"]
        print(f"| {r['case']} | " + " | ".join(cells) + " |")
    print(json.dumps({k: v for k, v in summary.items() if k != "rows"}, indent=1))


if __name__ == "__main__":
    flags = sys.argv[1:]
    selection = "corners" if "--corners" in flags else "hard" if "--hard" in flags else "cases"
    main(stored_only="--stored" in flags, selection=selection)
