"""The mesh, the domain of the forms: made from a gmsh model, its vertices, cells and facets,
its tagged groups and its communicator."""

from __future__ import annotations

import importlib.util

import numpy as np

from .libraries import load


def mesh_from_gmsh(model, comm, rank: int = 0, gdim: int = 2):
    """(mesh, cell tags, facet tags): the DOLFINx mesh of the gmsh ``model`` held by ``rank``,
    distributed over ``comm``, and its physical groups.

    0.5: ``dolfinx.io.gmshio.model_to_mesh`` returns that tuple. 0.10 moves it to
    ``dolfinx.io.gmsh.model_to_mesh`` and returns a ``MeshData`` record (``.mesh``,
    ``.cell_tags``, ``.facet_tags``).
    """
    load("dolfinx.io")
    if importlib.util.find_spec("dolfinx.io.gmshio") is not None:
        return load("dolfinx.io.gmshio").model_to_mesh(model, comm, rank, gdim=gdim)
    data = load("dolfinx.io.gmsh").model_to_mesh(model, comm, rank, gdim=gdim)
    return data.mesh, data.cell_tags, data.facet_tags


def communicator(mesh):
    """The MPI communicator ``mesh`` is distributed over."""
    return mesh.comm


def tagged(tags, tag: int) -> np.ndarray:
    """The local entities (cells or facets, owned and ghost) of the gmsh physical group ``tag``
    in the mesh tags ``tags`` (the cell or facet tags of :func:`mesh_from_gmsh`)."""
    return tags.find(tag)


def vertex_coordinates(mesh) -> np.ndarray:
    """The coordinates (n, 3) of this rank's geometry nodes (owned and ghost), in the mesh's
    length unit: the mesh's own array, so that writing into it moves the mesh."""
    return mesh.geometry.x


def cell_nodes(mesh) -> np.ndarray:
    """The geometry nodes of each local cell (cells x nodes per cell), indices into
    :func:`vertex_coordinates`.

    0.5: ``mesh.geometry.dofmap``, an AdjacencyList flattened by ``.array``; from 0.7 the 2-D
    array itself, which 0.10 keeps per cell type (``geometry.dofmaps[0]``, ``.dofmap``
    deprecated).
    """
    geometry = mesh.geometry
    if hasattr(geometry, "dofmaps"):
        return geometry.dofmaps[0]
    dofmap = geometry.dofmap
    if isinstance(dofmap, np.ndarray):
        return dofmap
    return dofmap.array.reshape(dofmap.num_nodes, -1)


def owned_cell_count(mesh) -> int:
    """The number of cells this rank owns (its local cells are these, then the ghosts)."""
    return mesh.topology.index_map(mesh.topology.dim).size_local


def cell_count(mesh) -> int:
    """The number of cells of the whole mesh (all ranks)."""
    return mesh.topology.index_map(mesh.topology.dim).size_global


def exterior_facets(mesh) -> np.ndarray:
    """The local facets of ``mesh`` on its boundary.

    0.5: ``dolfinx.mesh.exterior_facet_indices(topology)`` after the facet-to-cell
    connectivity is created; the same in 0.11.
    """
    mesh.topology.create_connectivity(mesh.topology.dim - 1, mesh.topology.dim)
    return load("dolfinx.mesh").exterior_facet_indices(mesh.topology)


def facet_midpoints(mesh, facets) -> np.ndarray:
    """The midpoints (n, 3) of the local ``facets`` of ``mesh``."""
    return load("dolfinx.mesh").compute_midpoints(mesh, mesh.topology.dim - 1, facets)
