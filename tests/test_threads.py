"""Results do not depend on the BLAS thread count (ehdfem.threads).

A threaded BLAS changes the rounding of the dense products with the thread count; unpinned,
the 24 collisions of benchmarks/sweep.py all differed between 1 and 2 OpenBLAS threads (by 1e-12
to 1e-9 in e_n, and a soft case's step sequence diverged). The set-up installs Debian's threaded
OpenBLAS (make.sh), and these tests load it in a fresh process (a BLAS reads its thread count
when it loads) from its own folder, whichever BLAS the system's alternatives select.
"""

import json
import os
import subprocess
import sys

import pytest

pytestmark = pytest.mark.serial

COLLISION = """
import json, sys
from threadpoolctl import threadpool_info
from ehdfem.collision import collide
from ehdfem.inputs.scales import CollisionParameters
params = CollisionParameters.from_settings(St=3.0, eps=0.01, p_cav=-10.0, angle=30.0)
result = collide(params, tangential="lubrication", deformation="gap", nodes=80)
threads = max(info["num_threads"] for info in threadpool_info() if info["user_api"] == "blas")
values = (result.normal.e_n, result.normal.min_film_thickness, result.normal.steps,
          result.tangential.e_t, result.tangential.spin_change)
print(json.dumps({"threads": threads, "values": [repr(v) for v in values]}))
"""


OPENBLAS = "/usr/lib/x86_64-linux-gnu/openblas-pthread"  # Debian's libopenblas0-pthread


def run_with_blas_threads(threads: int) -> dict:
    """The collision's outputs in a fresh process on OpenBLAS with ``threads`` threads."""
    env = {
        **os.environ,
        "LD_LIBRARY_PATH": os.pathsep.join([OPENBLAS, os.environ.get("LD_LIBRARY_PATH", "")]),
        "OPENBLAS_NUM_THREADS": str(threads),
        "OMP_NUM_THREADS": str(threads),
    }
    out = subprocess.run(
        [sys.executable, "-c", COLLISION], env=env, capture_output=True, text=True, check=True
    )
    return json.loads(out.stdout.splitlines()[-1])


def test_the_collision_runs_on_a_threaded_blas():
    """Outside a computation the BLAS keeps the thread count it was given, so the next test
    compares two different thread counts (fails without Debian's OpenBLAS: run the set-up)."""
    assert run_with_blas_threads(2)["threads"] == 2


@pytest.mark.slow
def test_a_collision_is_bit_equal_on_one_and_two_blas_threads():
    """A soft oblique collision with the sliding film: every output equal bit for bit."""
    assert run_with_blas_threads(1)["values"] == run_with_blas_threads(2)["values"]
