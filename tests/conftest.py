"""The suite computes every FE compliance (EHDFEM_COMPLIANCE_CACHE=off, also for the commands
it runs): a cached matrix would let a test on 2 ranks read what 1 rank computed. The cache has
its own test (tests/test_fem.py).

mpi4py is loaded before any test module: the tests that build DOLFINx objects of their own
import ``dolfinx`` directly, and on the wheel stack (MPICH from a wheel) DOLFINx finds
``libmpi`` only once mpi4py has loaded it (the package itself does this in its DOLFINx seam)."""

import os

import mpi4py.MPI  # noqa: F401

os.environ["EHDFEM_COMPLIANCE_CACHE"] = "off"
