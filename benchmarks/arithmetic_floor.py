"""The dense arithmetic of a default collision, measured inside it, against an earlier commit's
time: how fast the present algorithm could be if everything around its dense kernels cost
nothing.

Each default case of against_commit.py (240 film nodes, half-space solids) runs once in a fresh
process on the current checkout with the dense kernels of its Newton iteration timed where they
are called: the LUs (getrf of the packaged OpenBLAS, ehdfem.lapack), the triangular solves
(getrs), the compliance products C P (one per Newton residual: a product of C with a vector of
the film's size, timed alone at that size and counted); listed apart, the forming and
equilibration of the Newton matrices (compiled loops, O(n^2) each) and the build of the
half-space compliance (in both whole times, left out of the floor). The first three's sum is
the collision's arithmetic floor at one LU a step, the algorithm the solver has
(docs/performance.md: a kept LU costs more sweeps than it saves). The same case is timed
whole (fastest of REPEATS, fresh processes, as against_commit.py) on the current checkout and
on COMMIT; the largest ratio the algorithm allows is COMMIT's time over the floor.

Run: .venv/bin/python benchmarks/arithmetic_floor.py COMMIT [REPEATS]
(about a minute at 3 repeats). Writes benchmarks/results/arithmetic_floor.json and prints a
line per case.
"""

import json
import sys
import tempfile
from pathlib import Path

from against_commit import CASES, SETUP, run
from worktree import commit_checkout, head, run_json

ROOT = Path(__file__).resolve().parent.parent
RESULTS = ROOT / "benchmarks" / "results"
KERNELS = (
    SETUP
    + """
import numpy as np
import ehdfem.motion.reusable_lu as reusable_lu
import ehdfem.solids.halfspace as halfspace
from ehdfem.motion.implicit_step import ImplicitStep

collide(params, **settings)  # imports, numba's cache, the compliance kernel
seconds, calls = {}, {}

def timed(name, function):
    def wrapper(*args, **kwargs):
        start = time.perf_counter()
        try:
            return function(*args, **kwargs)
        finally:
            seconds[name] = seconds.get(name, 0.0) + time.perf_counter() - start
            calls[name] = calls.get(name, 0) + 1
    return wrapper

reusable_lu.getrf = timed("getrf", reusable_lu.getrf)
reusable_lu.getrs = timed("getrs", reusable_lu.getrs)
reusable_lu._equilibrated = timed("equilibration", reusable_lu._equilibrated)
ImplicitStep._newton_matrix = timed("newton_matrix", ImplicitStep._newton_matrix)
halfspace.HalfSpaceCompliance.__init__ = timed(
    "compliance_build", halfspace.HalfSpaceCompliance.__init__
)
halfspace._kernels.clear()  # the collision builds its compliance, as in the timed runs
normal = collide(params, **settings).normal
size = len(normal.history.pressure[-1])
rng = np.random.default_rng(1)
compliance, pressure = rng.random((size, size)), rng.random(size)
best = np.inf
for _ in range(2000):
    start = time.perf_counter()
    compliance @ pressure
    best = min(best, time.perf_counter() - start)
seconds["compliance_products"] = best * normal.newton_iterations
calls["compliance_products"] = normal.newton_iterations
print(json.dumps({"seconds": seconds, "calls": calls, "steps": normal.steps,
                  "newton_iterations": normal.newton_iterations, "film_nodes": size}))
"""
)
FLOOR = ("getrf", "getrs", "compliance_products")  # the dense arithmetic itself
MATRICES = ("newton_matrix", "equilibration")  # its O(n^2) preparation, compiled


def main(commit: str, repeats: int = 3):
    rows = {}
    with tempfile.TemporaryDirectory() as tmp, commit_checkout(commit, Path(tmp) / "old") as old:
        for name, case in CASES.items():
            case = (case, {})
            best = {}
            for _ in range(repeats):
                for label, source in (("current", ROOT), ("old", old)):
                    seconds = run(source, case)["seconds"]
                    best[label] = min(best.get(label, seconds), seconds)
            kernels = run_json(ROOT, [sys.executable, "-c", KERNELS, *map(json.dumps, case)])
            floor = sum(kernels["seconds"].get(k, 0.0) for k in FLOOR)
            matrices = sum(kernels["seconds"].get(k, 0.0) for k in MATRICES)
            rows[name] = {
                "seconds": best,
                "kernels": kernels,
                "floor_seconds": floor,
                "floor_with_matrices_seconds": floor + matrices,
                "largest_ratio": best["old"] / floor,
                "largest_ratio_with_matrices": best["old"] / (floor + matrices),
                "floor_share_of_current": floor / best["current"],
            }
            print(
                f"{name:42s} {commit[:10]} {best['old']:.3f} s, current {best['current']:.3f} s, "
                f"floor {1e3 * floor:.1f} ms ({kernels['calls'].get('getrf', 0)} LUs, "
                f"{1e3 * kernels['seconds'].get('getrf', 0.0):.1f} ms), with the matrices "
                f"{1e3 * (floor + matrices):.1f} ms: at most "
                f"{best['old'] / floor:.1f}x ({best['old'] / (floor + matrices):.1f}x)",
                flush=True,
            )
    RESULTS.mkdir(exist_ok=True)
    out = RESULTS / "arithmetic_floor.json"
    out.write_text(
        json.dumps(
            {"current": head(), "against": commit, "repeats": repeats, "cases": rows}, indent=2
        )
        + "\n"
    )
    print(f"wrote {out}")


if __name__ == "__main__":
    arguments = sys.argv[1:]
    if not arguments:
        sys.exit("usage: arithmetic_floor.py COMMIT [REPEATS]")
    main(arguments[0], int(arguments[1]) if len(arguments) > 1 else 3)
