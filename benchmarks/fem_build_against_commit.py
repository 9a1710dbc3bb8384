"""The FE compliance builds (axisymmetric and mode-1) timed against the code of an earlier commit.

The solids of benchmarks/fem_collision.py (the example collision, steel on glass, 240 film
nodes) are built in a fresh process (``mpirun -n RANKS`` for each rank count asked) on the
current checkout and on a git worktree of COMMIT, in alternation, REPEATS times each; in each
process the axisymmetric compliance (pressure and shear, the FE default) and then the mode-1
compliance of the same solids (the sliding film's, :class:`ehdfem.solids.fe.mode_one.FEModeOne`)
are built twice with the compliance cache off, and the faster of the two counts (the first
pays for loading the compiled forms); over the processes the fastest counts. One BLAS thread
(as in a collision), the machine's BLAS on both sides. The matrices of the last run of both
codes are compared: the largest difference of each unit matrix relative to its largest entry
(and, for the mode-1 matrix, of each of its blocks relative to the block's largest entry).
Writes benchmarks/results/fem_build_against_commit.json (seconds per build and rank count, the
mode-1 / axisymmetric ratio of each code, the differences) and prints a line per rank count.

Run: .venv/bin/python benchmarks/fem_build_against_commit.py COMMIT [REPEATS] [RANKS ...]
(defaults 3 repeats on 1 and 2 ranks; about 3 minutes). Both codes need only the API every
version since issue 15 has had: ``FESolids(delta, radii, sphere=, wall=)``, ``.compliance(eps,
shear=True)`` and ``FEModeOne(solids, eps)``.
"""

import json
import sys
import tempfile
from pathlib import Path

import numpy as np
from worktree import commit_checkout, head, run_json

ROOT = Path(__file__).resolve().parent.parent
RESULTS = ROOT / "benchmarks" / "results"
TIMER = """
import json, sys, time
import numpy as np
from mpi4py import MPI
from ehdfem.collision import DEFAULT_NODES, film_radii
from ehdfem.inputs.presets import EXAMPLE
from ehdfem.inputs.scales import from_presets
from ehdfem.solids.fe.mode_one import FEModeOne
from ehdfem.solids.fe.solids import FESolids

comm = MPI.COMM_WORLD
physical = from_presets(**EXAMPLE)
params = physical.dimensionless()
radii = film_radii(params, DEFAULT_NODES)
sphere, wall = ((m.young_modulus, m.poisson_ratio) for m in (physical.sphere, physical.wall))
solids = FESolids(params.delta, radii, sphere=sphere, wall=wall)
times = {"axisymmetric": [], "mode_one": []}
for _ in range(2):
    comm.barrier()
    start = time.perf_counter()
    compliance = solids.compliance(params.eps, shear=True)
    comm.barrier()
    times["axisymmetric"].append(time.perf_counter() - start)
    start = time.perf_counter()
    mode_one = FEModeOne(solids, params.eps)
    comm.barrier()
    times["mode_one"].append(time.perf_counter() - start)
    mode_one.close()
if comm.rank == 0:
    np.savez(sys.argv[1], mode_one=mode_one.unit_matrix, gap=compliance.unit_matrix,
             shear=compliance.unit_shear, surface_sum=compliance.unit_surface_sum)
    print(json.dumps({name: min(values) for name, values in times.items()}))
"""


def run(source: Path, ranks: int, matrices: Path) -> dict:
    """The fastest build times of one process group of ``ranks`` on the code of ``source``;
    its matrices written to ``matrices`` (npz)."""
    launcher = ["mpirun", "-n", str(ranks)] if ranks > 1 else []
    command = [*launcher, sys.executable, "-c", TIMER, str(matrices)]
    return run_json(source, command, EHDFEM_COMPLIANCE_CACHE="off")


def differences(current: Path, old: Path) -> dict:
    """Per unit matrix, max |current - old| / max |old|; for the mode-1 matrix also the largest
    over its (N x N) blocks of the same relative to the block's own largest entry
    ("mode_one_blocks"; its zero blocks must stay zero)."""
    with np.load(current) as new, np.load(old) as before:
        result = {
            name: float(np.abs(new[name] - before[name]).max() / np.abs(before[name]).max())
            for name in before.files
        }
        n = before["mode_one"].shape[1] // 5
        worst = 0.0
        for rows in range(0, 6 * n, n):
            for columns in range(0, 5 * n, n):
                block = np.s_[rows : rows + n, columns : columns + n]
                a, b = before["mode_one"][block], new["mode_one"][block]
                scale = np.abs(a).max()
                if scale == 0.0:
                    worst = max(worst, np.inf if b.any() else 0.0)
                else:
                    worst = max(worst, float(np.abs(b - a).max() / scale))
        result["mode_one_blocks"] = worst
    return result


def main(commit: str, repeats: int = 3, rank_counts=(1, 2)):
    rows = {}
    with tempfile.TemporaryDirectory() as tmp, commit_checkout(commit, Path(tmp) / "old") as old:
        for ranks in rank_counts:
            best = {"current": {}, "old": {}}
            for _ in range(repeats):
                for label, source in (("current", ROOT), ("old", old)):
                    result = run(source, ranks, Path(tmp) / f"{label}.npz")
                    for build, seconds in result.items():
                        best[label][build] = min(best[label].get(build, seconds), seconds)
            for label in best:
                best[label]["mode_one_ratio"] = (
                    best[label]["mode_one"] / best[label]["axisymmetric"]
                )
            speed_up = best["old"]["mode_one"] / best["current"]["mode_one"]
            diff = differences(Path(tmp) / "current.npz", Path(tmp) / "old.npz")
            rows[str(ranks)] = {**best, "mode_one_speed_up": speed_up, "differences": diff}
            print(
                f"{ranks} rank(s): mode-1 {best['current']['mode_one']:.2f} s "
                f"({best['current']['mode_one_ratio']:.2f} x axisymmetric "
                f"{best['current']['axisymmetric']:.2f} s), {commit[:10]} "
                f"{best['old']['mode_one']:.2f} s ({best['old']['mode_one_ratio']:.2f} x "
                f"{best['old']['axisymmetric']:.2f} s); mode-1 matrix difference "
                f"{diff['mode_one']:.1e} (blockwise {diff['mode_one_blocks']:.1e})",
                flush=True,
            )
    current = head()
    RESULTS.mkdir(exist_ok=True)
    out = RESULTS / "fem_build_against_commit.json"
    summary = {"current": current, "against": commit, "repeats": repeats, "ranks": rows}
    out.write_text(json.dumps(summary, indent=2) + "\n")
    print(f"wrote {out}")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit("usage: fem_build_against_commit.py COMMIT [REPEATS] [RANKS ...]")
    main(
        sys.argv[1],
        int(sys.argv[2]) if len(sys.argv) > 2 else 3,
        tuple(int(r) for r in sys.argv[3:]) or (1, 2),
    )
