"""The suite computes every FE compliance (EHDFEM_COMPLIANCE_CACHE=off, also for the commands
it runs): a cached matrix would let a test on 2 ranks read what 1 rank computed. The cache has
its own test (tests/test_fem.py).

On the wheel stack (MPICH from a wheel) mpi4py is loaded before any test module: the tests
that build DOLFINx objects of their own import ``dolfinx`` directly, and there DOLFINx finds
``libmpi`` only once mpi4py has loaded it (the package itself does this in its DOLFINx seam).
Not on Debian's stack: MPI started in a test process (a singleton) makes the ``mpirun`` that a
test starts from it fail with no output (tests/test_cli.py's errors under mpirun)."""

import os
from importlib.metadata import PackageNotFoundError, distribution

try:
    distribution("mpich")  # the wheel stack's MPI
except PackageNotFoundError:
    pass
else:
    import mpi4py.MPI  # noqa: F401

os.environ["EHDFEM_COMPLIANCE_CACHE"] = "off"
