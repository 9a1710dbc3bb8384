"""The gmsh mesh of the FE solids, built by meshes/contact.py or loaded from an on-disk cache.

Meshing the graded contact geometry takes longer than assembling and factorising on it, and a
study builds the same solids many times, so rank 0 keeps every mesh it builds in
``MESH_CACHE`` (``EHDFEM_MESH_CACHE``, default ~/.cache/ehdfem/meshes). A cached mesh is keyed
by a hash of the generator's arguments and of the generator's source, so editing the generator
invalidates it; it is written to a temporary name and renamed, so that concurrent runs never
read a half-written file. Lengths are by the (reduced) sphere radius a, as in the generator.
"""

from __future__ import annotations

import hashlib
import inspect
import os
from pathlib import Path

import numpy as np

from . import dolfinx_compat

MESH_CACHE = Path(os.environ.get("EHDFEM_MESH_CACHE", Path.home() / ".cache" / "ehdfem" / "meshes"))


def load_or_build(gmsh, build, arguments) -> None:
    """Put the mesh of ``build(*arguments)`` in the current gmsh model: opened from the cache
    when it holds that mesh, else built and then stored there."""
    key = hashlib.sha1(
        repr(
            [np.asarray(a).tolist() if isinstance(a, np.ndarray) else a for a in arguments]
        ).encode()
    )
    key.update(inspect.getsource(build).encode())
    path = MESH_CACHE / f"{key.hexdigest()[:20]}.msh"
    if path.exists():
        gmsh.open(str(path))
        return
    build(*arguments)
    MESH_CACHE.mkdir(parents=True, exist_ok=True)
    tmp = path.with_name(f".{path.stem}.{os.getpid()}.msh")
    gmsh.write(str(tmp))
    os.replace(tmp, path)


def contact_mesh(comm, build, arguments):
    """(mesh, cell tags, facet tags) of ``build(*arguments)`` (a generator of meshes/contact.py,
    lengths by a), meshed or loaded by rank 0 of ``comm`` and distributed over ``comm``."""
    import gmsh

    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    try:
        if comm.rank == 0:
            load_or_build(gmsh, build, arguments)
        return dolfinx_compat.mesh_from_gmsh(gmsh.model, comm, 0, gdim=2)
    finally:
        gmsh.finalize()
