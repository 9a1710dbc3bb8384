"""Runs on every rank under `mpirun -n 2` too: results must not depend on the rank."""

from mpi4py import MPI

from ehdfem.collision import collide
from ehdfem.inputs.scales import CollisionParameters


def test_collision_is_identical_on_every_rank():
    """Each rank integrates the same collision; the results agree bit for bit (no rank- or
    thread-dependent arithmetic in the solver)."""
    comm = MPI.COMM_WORLD
    result = collide(CollisionParameters(St=10.0, eps=1e-3, layer="thin", p_cav=-2.0, angle=30.0))
    values = (result.normal.e_n, result.normal.min_film_thickness, result.tangential.e_t)
    assert all(other == values for other in comm.allgather(values))
