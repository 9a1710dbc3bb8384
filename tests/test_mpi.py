"""Runs on every rank under `mpirun -n 2` too: results must not depend on the rank or the
process."""

import json
import subprocess
import sys

from mpi4py import MPI

from ehdfem.collision import collide
from ehdfem.inputs.scales import CollisionParameters

CASE = dict(St=10.0, eps=1e-3, layer="thin", p_cav=-2.0, angle=30.0)
OUTPUTS = """
import json, sys
from ehdfem.collision import collide
from ehdfem.inputs.scales import CollisionParameters
result = collide(CollisionParameters.from_settings(**json.loads(sys.argv[1])))
values = (result.normal.e_n, result.normal.min_film_thickness, result.tangential.e_t)
print(json.dumps([repr(v) for v in values]))
"""


def test_collision_is_identical_on_every_rank():
    """Each rank integrates the same collision; the results agree bit for bit (no rank- or
    thread-dependent arithmetic in the solver). On one process the other process is a fresh
    Python (its own imports, caches and memory layout), so the test compares two processes
    either way."""
    comm = MPI.COMM_WORLD
    result = collide(CollisionParameters.from_settings(**CASE))
    values = [repr(v) for v in (result.normal.e_n, result.normal.min_film_thickness)]
    values.append(repr(result.tangential.e_t))
    if comm.size > 1:
        others = comm.allgather(values)
    else:
        out = subprocess.run(
            [sys.executable, "-c", OUTPUTS, json.dumps(CASE)],
            capture_output=True,
            text=True,
            check=True,
        )
        others = [json.loads(out.stdout.splitlines()[-1])]
    assert all(other == values for other in others)
