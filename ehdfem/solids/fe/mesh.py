"""The FE solids' on-disk caches: their gmsh mesh and their condensed compliance matrices.

Meshing the graded contact geometry takes longer than assembling and factorising on it, and a
study builds the same solids many times, so rank 0 keeps every mesh it builds in
``MESH_CACHE`` (``EHDFEM_MESH_CACHE``, default ~/.cache/ehdfem/meshes). The condensed unit
matrices (:mod:`ehdfem.solids.fe.solids`, :mod:`ehdfem.solids.fe.mode_one`: one
factorisation and hundreds of solves) are kept likewise in ``COMPLIANCE_CACHE``
(``EHDFEM_COMPLIANCE_CACHE``, default ~/.cache/ehdfem/compliances; "off" keeps none). They are
scaled matrices (by a p / E_ref per unit nodal load), independent of eps, so one entry serves
every St and eps at fixed geometry, materials and film nodes. An entry is keyed by a hash of
its arguments, of the source of the code that computes it and of the versions of the libraries
that do (gmsh for a mesh; gmsh, DOLFINx and PETSc for a matrix), so editing that code or
running on the other install stack (docs/fem.md) invalidates it; it is written to a
temporary name and renamed, so that concurrent runs never read a half-written file. Lengths
are by the (reduced) sphere radius a, as in the generator.
"""

from __future__ import annotations

import hashlib
import inspect
import os
from pathlib import Path

import numpy as np

from ...fenicsx import domain, libraries

_CACHES = Path.home() / ".cache" / "ehdfem"
MESH_CACHE = Path(os.environ.get("EHDFEM_MESH_CACHE", _CACHES / "meshes"))
COMPLIANCE_CACHE = os.environ.get("EHDFEM_COMPLIANCE_CACHE", str(_CACHES / "compliances"))


def cache_key(arguments, sources) -> str:
    """A hash of ``arguments`` (numbers, strings, arrays, nested sequences) and of the source
    code of ``sources`` (functions, classes or modules)."""
    key = hashlib.sha1(
        repr(
            [np.asarray(a).tolist() if isinstance(a, np.ndarray) else a for a in arguments]
        ).encode()
    )
    for source in sources:
        key.update(inspect.getsource(source).encode())
    return key.hexdigest()[:20]


def library_versions(meshing_only: bool = False) -> tuple:
    """The versions of gmsh, DOLFINx and PETSc (gmsh's alone with ``meshing_only``): part of
    every cache key, as the two install stacks mesh and solve differently."""
    import gmsh

    if meshing_only:
        return (f"gmsh {gmsh.__version__}",)
    dolfinx, petsc = libraries.dolfinx_version(), libraries.petsc_version()
    return (f"gmsh {gmsh.__version__}", f"dolfinx {dolfinx}", f"petsc {petsc}")


def load_or_build(gmsh, build, arguments) -> None:
    """Put the mesh of ``build(*arguments)`` in the current gmsh model: opened from the cache
    when it holds that mesh (keyed by the arguments, gmsh's version and the source of the
    generator's module), else built, stored there and opened from there. A mesh is always
    read from its file: the model gmsh built in memory numbers its nodes otherwise, which
    moved the FE compliance by 1e-12 between a first run and the runs after it."""
    keyed = [*arguments, library_versions(meshing_only=True)]
    path = MESH_CACHE / f"{cache_key(keyed, [inspect.getmodule(build)])}.msh"
    if not path.exists():
        build(*arguments)
        MESH_CACHE.mkdir(parents=True, exist_ok=True)
        tmp = path.with_name(f".{path.stem}.{os.getpid()}.msh")
        gmsh.write(str(tmp))
        os.replace(tmp, path)
        gmsh.clear()
    gmsh.open(str(path))


def cached_matrices(comm, arguments, sources, compute) -> dict:
    """The arrays of ``compute()`` (a dict of name: array, the same on every rank of ``comm``;
    collective), or their copy in COMPLIANCE_CACHE under :func:`cache_key` of ``arguments`` and
    ``sources`` (and :func:`library_versions`); a computed dict is stored there by rank 0. No
    cache when COMPLIANCE_CACHE is "off"."""
    if COMPLIANCE_CACHE == "off":
        return compute()
    keyed = [*arguments, library_versions()]
    path = Path(COMPLIANCE_CACHE) / f"{cache_key(keyed, sources)}.npz"
    if comm.bcast(path.exists() if comm.rank == 0 else None):
        with np.load(path) as stored:
            return {name: stored[name] for name in stored.files}
    arrays = compute()
    if comm.rank == 0:
        path.parent.mkdir(parents=True, exist_ok=True)
        tmp = path.with_name(f".{path.stem}.{os.getpid()}.npz")
        with tmp.open("wb") as f:
            np.savez(f, **arrays)
        os.replace(tmp, path)
    comm.barrier()
    return arrays


def contact_mesh(comm, build, arguments):
    """(mesh, cell tags, facet tags) of ``build(*arguments)`` (a generator of meshes/contact.py,
    lengths by a), meshed or loaded by rank 0 of ``comm`` and distributed over ``comm``."""
    import gmsh

    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    try:
        if comm.rank == 0:
            load_or_build(gmsh, build, arguments)
        return domain.mesh_from_gmsh(gmsh.model, comm, 0, gdim=2)
    finally:
        gmsh.finalize()
