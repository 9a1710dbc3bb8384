"""Time per normal collision and e_n against the number of film nodes (half-space model).

Runs on one core (BLAS threads pinned to 1) and writes benchmarks/results/normal_collision.json;
docs/performance.md quotes it. Targets (issue 2): the default resolution under 2 s per collision,
600 nodes under 10 s.
"""

import os

os.environ["OPENBLAS_NUM_THREADS"] = os.environ["OMP_NUM_THREADS"] = "1"

import json  # noqa: E402
import platform  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

from ehdfem.collision import DEFAULT_NODES, collide, film_radii  # noqa: E402
from ehdfem.config import RunConfig
from ehdfem.inputs.scales import CollisionParameters  # noqa: E402
from ehdfem.solids import halfspace  # noqa: E402
from ehdfem.solids.halfspace import HalfSpaceCompliance  # noqa: E402

CASES = {
    "thin St=10 eps=1e-3 P_cav=-2": CollisionParameters.from_settings(
        St=10.0, eps=1e-3, layer="thin", p_cav=-2.0
    ),
    "immersed St=50 eps=1e-4": CollisionParameters.from_settings(
        St=50.0, eps=1e-4, layer="immersed"
    ),
}
NODES = sorted({100, 200, 400, 800, 600, DEFAULT_NODES})


def measure(params, nodes, repeats):
    best = None
    for _ in range(repeats):
        halfspace._kernels.clear()  # each repeat builds its kernel (a sweep keeps it)
        start = time.perf_counter()
        HalfSpaceCompliance(film_radii(params, nodes), params.eps)
        kernel = time.perf_counter() - start
        result = collide(params, RunConfig.from_settings(nodes=nodes, refinements=0))
        total = time.perf_counter() - start
        if best is None or total < best["seconds"]:
            best = {
                "nodes": nodes,
                "seconds": total - kernel,
                "kernel_seconds": kernel,
                "e_n": result.normal.e_n,
                "max_rebound_velocity": result.normal.max_rebound_velocity,
                "steps": result.normal.steps,
                "newton_iterations": result.normal.newton_iterations,
            }
    return best


def main():
    quick = "--quick" in sys.argv
    rows = {}
    for name, params in CASES.items():
        rows[name] = []
        for nodes in NODES if not quick else [100, DEFAULT_NODES]:
            row = measure(params, nodes, repeats=1 if nodes >= 400 else 3)
            rows[name].append(row)
            print(
                f"{name:32s} N={nodes:4d}  {row['seconds']:7.3f} s"
                f" (+ kernel {row['kernel_seconds']:.3f} s)"
                f"  e_n={row['e_n']:.5f}  steps={row['steps']}",
                flush=True,
            )
    out = Path(__file__).parent / "results" / "normal_collision.json"
    out.parent.mkdir(exist_ok=True)
    out.write_text(
        json.dumps(
            {
                "machine": platform.processor() or platform.machine(),
                "python": platform.python_version(),
                "default_nodes": DEFAULT_NODES,
                "cases": rows,
            },
            indent=2,
        )
        + "\n"
    )
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
