"""The finite-element spaces on a mesh and their degrees of freedom (dofs): which dofs this rank
owns, where they are, which lie on given cells, facets or points."""

from __future__ import annotations

import importlib

import numpy as np

from .libraries import fem, load


def _space(mesh, family: str, degree: int, shape: tuple | None = None):
    """The space of the ``family`` elements of ``degree`` on ``mesh``, ``shape`` components.

    0.5: ``fem.FunctionSpace(mesh, (family, k))``, ``fem.VectorFunctionSpace(mesh, (family,
    k), dim=n)``; 0.7+: ``fem.functionspace(mesh, (family, k, shape))``, the only form from 0.8.
    """
    module = fem()
    if hasattr(module, "functionspace"):
        return module.functionspace(mesh, (family, degree, *([shape] if shape else [])))
    if shape:
        return module.VectorFunctionSpace(mesh, (family, degree), dim=shape[0])
    return module.FunctionSpace(mesh, (family, degree))


def lagrange_space(mesh, degree: int, vector: bool = False, components: int | None = None):
    """Continuous Lagrange space of ``degree`` on ``mesh``; with ``vector``, one component per
    geometric dimension (the (u_r, u_z) displacement), or ``components`` of them (the three
    mode-1 displacement amplitudes). The two forms of the call: :func:`_space`."""
    if vector:
        return _space(mesh, "Lagrange", degree, (components or mesh.geometry.dim,))
    return _space(mesh, "Lagrange", degree)


def cell_space(mesh):
    """Piecewise-constant space (DG0): one value per cell, e.g. a material property or a
    stress (:func:`_space`)."""
    return _space(mesh, "DG", 0)


def taylor_hood_space(mesh):
    """The mixed space of a P2 velocity (one component per geometric dimension) and a P1
    pressure.

    0.5: ``fem.FunctionSpace(mesh, ufl.MixedElement([ufl.VectorElement("Lagrange", cell, 2),
    ufl.FiniteElement("Lagrange", cell, 1)]))``; from 0.7 the elements are built with
    ``basix.ufl.element`` and ``basix.ufl.mixed_element`` (UFL's own elements are gone), and
    given to ``fem.functionspace``.
    """
    module = fem()
    if hasattr(module, "functionspace"):
        elements = importlib.import_module("basix.ufl")
        cell = mesh.basix_cell()
        velocity = elements.element("Lagrange", cell, 2, shape=(mesh.geometry.dim,))
        pressure = elements.element("Lagrange", cell, 1)
        return module.functionspace(mesh, elements.mixed_element([velocity, pressure]))
    ufl = importlib.import_module("ufl")
    cell = mesh.ufl_cell()
    velocity = ufl.VectorElement("Lagrange", cell, 2)
    return module.FunctionSpace(
        mesh, ufl.MixedElement([velocity, ufl.FiniteElement("Lagrange", cell, 1)])
    )


def mesh_of(space):
    """The mesh ``space`` is defined on."""
    return space.mesh


def owned_dof_count(space) -> int:
    """The number of entries of a solution vector on ``space`` that this rank owns (dofs times
    components): its local entries are these, then the ghosts'."""
    return space.dofmap.index_map.size_local * space.dofmap.index_map_bs


def dof_count(space) -> int:
    """The number of entries of a solution vector on ``space`` over all ranks (dofs times
    components)."""
    return space.dofmap.index_map.size_global * space.dofmap.index_map_bs


def dof_coordinates(space) -> np.ndarray:
    """The coordinates (n, 3) of this rank's dofs (owned, then ghosts) of the scalar (or
    collapsed) ``space``, in the mesh's length unit."""
    return space.tabulate_dof_coordinates()


def sub_space(space, component: int):
    """(sub-space, collapsed copy) of ``component`` of a vector ``space``: the pair the dof
    locators take to give (parent dofs, dofs of the collapsed copy)."""
    collapsed, _ = space.sub(component).collapse()
    return space.sub(component), collapsed


def cell_dofs(space, cells: int) -> np.ndarray:
    """The dof of each of the first ``cells`` local cells in a space with one dof per cell (DG0).

    0.5: the dofmap list is an AdjacencyList, flattened by ``.array``; from 0.7 it is a 2-D
    array (cells x dofs per cell).
    """
    dofs = space.dofmap.list
    return (dofs[:, 0] if isinstance(dofs, np.ndarray) else dofs.array)[:cells]


def interpolation_points(space) -> np.ndarray:
    """Reference points at which an expression is evaluated to interpolate it into ``space``.

    0.5: the method ``space.element.interpolation_points()``; a property (no call) in 0.10.
    """
    points = space.element.interpolation_points
    return points() if callable(points) else points


def entity_dofs(space, dim: int, entities, component: int | None = None):
    """The local dofs of ``space`` on the mesh entities ``entities`` of dimension ``dim`` (1:
    facets, 2: cells); with ``component``, the pair (parent dofs, collapsed dofs) of that
    component (:func:`sub_space`)."""
    spaces = space if component is None else list(sub_space(space, component))
    return fem().locate_dofs_topological(spaces, dim, entities)


def point_dofs(space, where, component: int | None = None):
    """The local dofs of ``space`` at the points x (3, n) where ``where(x)`` is True; with
    ``component``, the pair (parent dofs, collapsed dofs) of that component."""
    spaces = space if component is None else list(sub_space(space, component))
    return fem().locate_dofs_geometrical(spaces, where)


def velocity_component_dofs(space, component: int, facets) -> np.ndarray:
    """The local dofs (in ``space``'s numbering) of ``component`` of the velocity (sub-space 0)
    of a :func:`taylor_hood_space` on the mesh ``facets``."""
    sub = space.sub(0).sub(component)
    return fem().locate_dofs_topological(sub, space.mesh.topology.dim - 1, facets)


def vtk_mesh(space):
    """(VTK cell array, VTK cell types, coordinates (n, 3)) of the dofs of a P1 ``space``: the
    vertices in the order of the space's dofs, one VTK cell per local cell (owned cells first).

    0.5: ``dolfinx.plot.create_vtk_mesh(space)``; renamed ``dolfinx.plot.vtk_mesh`` in 0.7.
    """
    plot = load("dolfinx.plot")
    return (plot.vtk_mesh if hasattr(plot, "vtk_mesh") else plot.create_vtk_mesh)(space)
