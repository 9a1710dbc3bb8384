"""Collisions per second of `ehdfem sweep` on 1 and 2 MPI ranks, and the parallel efficiency.

A 24-point study (St from 3 to 300, three eps, thin layer, default grid) is run from scratch
with one process and with `mpirun -n 2`; BLAS is pinned to one thread per rank. Writes
benchmarks/results/sweep.json. Target (issue 5): parallel efficiency >= 85 % on 2 ranks.
"""

import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

STUDY = """
name = "bench"
[grid]
St = {geomspace = [3.0, 300.0, 8]}
eps = [1e-5, 1e-3, 1e-2]
p_cav = [-10.0]
angle = [30.0]
"""


def run(ranks: int) -> float:
    folder = Path(tempfile.mkdtemp(prefix="ehdfem-bench-"))
    (folder / "bench.toml").write_text(STUDY)
    ehdfem = str(Path(sys.executable).with_name("ehdfem"))
    command = [ehdfem, "sweep", str(folder / "bench.toml")]
    if ranks > 1:
        command = ["mpirun", "-n", str(ranks), *command]
    env = {
        **os.environ,
        "OPENBLAS_NUM_THREADS": "1",
        "OMP_NUM_THREADS": "1",
        "OMPI_ALLOW_RUN_AS_ROOT": "1",
        "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1",
    }
    start = time.perf_counter()
    subprocess.run(command, check=True, capture_output=True, env=env)
    return time.perf_counter() - start


def main():
    points = 24
    serial, parallel = run(1), run(2)
    result = {
        "points": points,
        "seconds_1_rank": serial,
        "seconds_2_ranks": parallel,
        "collisions_per_second_1_rank": points / serial,
        "collisions_per_second_2_ranks": points / parallel,
        "parallel_efficiency": serial / (2 * parallel),
    }
    out = Path(__file__).parent / "results" / "sweep.json"
    out.parent.mkdir(exist_ok=True)
    out.write_text(json.dumps(result, indent=2) + "\n")
    print(json.dumps(result, indent=2))


if __name__ == "__main__":
    main()
