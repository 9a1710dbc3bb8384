"""Loading the FEniCSx libraries, and their versions.

DOLFINx and petsc4py are imported through :func:`load`, which loads two modules first.
``mpi4py.MPI``: the MPICH wheel's ``libmpi`` is found by mpi4py, and importing DOLFINx or
petsc4py before it fails there. ``h5py`` (which writes the fields' XDMF): 0.11's
``dolfinx.fem.petsc`` opens the wheel's PETSc library with global symbols, and its HDF5 then
shadows the HDF5 of h5py's own wheel if h5py is imported later ("Not a datatype"); imported
first, each keeps its own. The imports stay lazy so that a half-space run loads none of them.
"""

from __future__ import annotations

import importlib
import importlib.util
import sys


def load(name: str):
    """The module ``name`` (``dolfinx.fem``, ``petsc4py.PETSc``, ...), with MPI and h5py (when
    installed) loaded before it (module docstring)."""
    importlib.import_module("mpi4py.MPI")
    if "h5py" not in sys.modules and importlib.util.find_spec("h5py") is not None:
        importlib.import_module("h5py")
    return importlib.import_module(name)


def fem():
    """``dolfinx.fem``."""
    return load("dolfinx.fem")


def fem_petsc():
    """``dolfinx.fem.petsc``: a submodule that 0.7+ no longer imports with ``dolfinx.fem``."""
    return load("dolfinx.fem.petsc")


def petsc():
    """petsc4py's ``PETSc`` module, MPI loaded first."""
    return load("petsc4py.PETSc")


def dolfinx_version() -> str:
    """The installed DOLFINx's version (e.g. "0.5.2", "0.11.0")."""
    return load("dolfinx").__version__


def petsc_version() -> str:
    """The version of the PETSc library petsc4py runs on (e.g. "3.18.5")."""
    return ".".join(map(str, petsc().Sys.getVersion()))
