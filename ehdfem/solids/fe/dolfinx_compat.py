"""The DOLFINx calls of the FE solids whose spelling depends on the DOLFINx release.

The package is written against Debian's DOLFINx 0.5.2. Every call below changed name, argument
form or return type in a later release; :mod:`ehdfem.solids.fe.solids`,
:mod:`ehdfem.solids.fe.mesh` and :mod:`ehdfem.outputs.render` reach them only through this module,
so moving to a newer DOLFINx means editing these functions and nothing else. Each docstring
names what the 0.5 call is and what replaces it later. Plain ``ufl`` and ``fem.form``,
``fem.Function``, ``fem.Constant``, ``fem.Expression``, ``fem.dirichletbc``,
``fem.locate_dofs_*`` and ``fem.assemble_scalar``, which kept their form, are used directly.

Nothing here knows about scales: meshes, spaces, matrices and vectors carry whatever units the
caller's forms give them.
"""

from __future__ import annotations

import numpy as np


def lagrange_space(mesh, degree: int, vector: bool = False, components: int | None = None):
    """Continuous Lagrange space of ``degree`` on ``mesh``; with ``vector``, one component per
    geometric dimension (the (u_r, u_z) displacement), or ``components`` of them (the three
    mode-1 displacement amplitudes).

    0.5: ``fem.FunctionSpace(mesh, ("CG", k))`` and ``fem.VectorFunctionSpace(mesh, ("CG", k),
    dim=n)``. 0.7 adds ``fem.functionspace(mesh, ("Lagrange", k, shape))`` (or a
    ``basix.ufl.element("Lagrange", mesh.basix_cell(), k, shape=...)``), the only form from 0.8.
    """
    from dolfinx import fem

    if vector:
        return fem.VectorFunctionSpace(mesh, ("CG", degree), dim=components)
    return fem.FunctionSpace(mesh, ("CG", degree))


def cell_space(mesh):
    """Piecewise-constant space (DG0): one value per cell, e.g. a material property or a stress.

    0.5: ``fem.FunctionSpace(mesh, ("DG", 0))``; 0.7+: ``fem.functionspace(mesh, ("DG", 0))``.
    """
    from dolfinx import fem

    return fem.FunctionSpace(mesh, ("DG", 0))


def cell_dofs(space, cells: int) -> np.ndarray:
    """The dof of each of the first ``cells`` local cells in a space with one dof per cell (DG0).

    0.5: the dofmap list is an AdjacencyList, flattened by ``.array``; from 0.7 it is a 2-D
    array (cells x dofs per cell), to be read as ``dofmap.list[:cells, 0]``.
    """
    return space.dofmap.list.array[:cells]


def interpolation_points(space) -> np.ndarray:
    """Reference points at which an expression is evaluated to interpolate it into ``space``.

    0.5: the method ``space.element.interpolation_points()``; a property (no call) in 0.10.
    """
    return space.element.interpolation_points()


def mesh_from_gmsh(model, comm, rank: int = 0, gdim: int = 2):
    """The DOLFINx mesh, cell tags and facet tags of the gmsh ``model`` held by ``rank``,
    distributed over ``comm``.

    0.5: ``dolfinx.io.gmshio.model_to_mesh`` returns the tuple (mesh, cell tags, facet tags).
    0.10 moves it to ``dolfinx.io.gmsh.model_to_mesh`` and returns a ``MeshData`` record
    (``.mesh``, ``.cell_tags``, ``.facet_tags``).
    """
    from dolfinx.io import gmshio

    return gmshio.model_to_mesh(model, comm, rank, gdim=gdim)


def vtk_mesh(space):
    """(VTK cell array, VTK cell types, coordinates (n, 3)) of the dofs of a P1 ``space``: the
    vertices in the order of the space's dofs, one VTK cell per local cell (owned cells first).

    0.5: ``dolfinx.plot.create_vtk_mesh(space)``; renamed ``dolfinx.plot.vtk_mesh`` in 0.7.
    """
    from dolfinx import plot

    return plot.create_vtk_mesh(space)


def assemble_matrix(form, bcs):
    """The assembled PETSc matrix of a bilinear ``form``, with the rows and columns of the
    Dirichlet ``bcs`` replaced by the identity.

    0.5: ``fem.petsc.assemble_matrix(form, bcs=bcs)`` then ``.assemble()``. From 0.7 the
    submodule must be imported explicitly (``import dolfinx.fem.petsc``), as done here.
    """
    import dolfinx.fem.petsc

    matrix = dolfinx.fem.petsc.assemble_matrix(form, bcs=bcs)
    matrix.assemble()
    return matrix


def assemble_vector(form, bcs):
    """The assembled PETSc vector of a linear ``form``: ghost contributions summed onto their
    owners, then the values of the Dirichlet ``bcs`` set (zero here: homogeneous conditions,
    no lifting needed).

    0.5: ``fem.petsc.assemble_vector``, ``ghostUpdate(ADD, REVERSE)`` and ``fem.petsc.set_bc``;
    from 0.7 ``dolfinx.fem.petsc`` must be imported explicitly, and 0.10 reworked these PETSc
    helpers (check ``set_bc``'s arguments there).
    """
    import dolfinx.fem.petsc
    from petsc4py import PETSc

    vector = dolfinx.fem.petsc.assemble_vector(form)
    vector.ghostUpdate(addv=PETSc.InsertMode.ADD, mode=PETSc.ScatterMode.REVERSE)
    dolfinx.fem.petsc.set_bc(vector, bcs)
    return vector


def petsc_vector(function):
    """The PETSc vector that holds the values of ``function`` (a solver writes into it).

    0.5: ``function.vector``; ``function.x.petsc_vec`` from 0.8, where ``.vector`` is deprecated
    (and later removed).
    """
    return function.vector
