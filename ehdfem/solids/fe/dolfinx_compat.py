"""Every DOLFINx call of the package: the FE solids, their fields, the disk film and the liquid
around a bouncing sphere.

The package is written against Debian's DOLFINx 0.5.2. Nothing outside this module imports
``dolfinx`` (:mod:`ehdfem.solids.fe`, :mod:`ehdfem.tangential.disk`,
:mod:`ehdfem.bounce.wall_flow`, :mod:`ehdfem.bounce.sphere_flow` and
:mod:`ehdfem.bounce.near_wall_flow` reach it only through these functions and the meshes' and
spaces' own ``geometry.x`` and ``tabulate_dof_coordinates()``), so moving to a newer DOLFINx
means editing this module and nothing else. The docstrings of the calls that changed name,
argument form or return type in a later release name
what the 0.5 call is and what replaces it later; the others (``fem.form``, ``fem.Function``,
``fem.Expression``, ``fem.dirichletbc``, ``fem.locate_dofs_*``, ``fem.assemble_scalar``, ...)
kept their form up to 0.10. UFL (forms) and petsc4py (matrices,
factorisations) are separate packages, used directly.

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


def form(expression):
    """The compiled form of the UFL ``expression`` (bilinear, linear or a functional)."""
    from dolfinx import fem

    return fem.form(expression)


def function(space, name: str | None = None):
    """A finite-element function on ``space``, zero (``name`` labels it in exported files)."""
    from dolfinx import fem

    return fem.Function(space) if name is None else fem.Function(space, name=name)


def constant(mesh, value: float):
    """A constant on ``mesh`` whose value can be changed between solves (``.value``)."""
    from dolfinx import fem
    from petsc4py import PETSc

    return fem.Constant(mesh, PETSc.ScalarType(value))


def expression(ufl_expression, space):
    """``ufl_expression`` compiled for interpolation into ``space`` (``function.interpolate``)."""
    from dolfinx import fem

    return fem.Expression(ufl_expression, interpolation_points(space))


def integral(integrand, comm) -> float:
    """The value of the functional ``integrand`` (a UFL form with its measure), summed over the
    ranks of ``comm``."""
    from dolfinx import fem

    return comm.allreduce(fem.assemble_scalar(fem.form(integrand)))


def sub_space(space, component: int):
    """(sub-space, collapsed copy) of ``component`` of a vector ``space``: the pair the dof
    locators take to give (parent dofs, dofs of the collapsed copy)."""
    collapsed, _ = space.sub(component).collapse()
    return space.sub(component), collapsed


def entity_dofs(space, dim: int, entities, component: int | None = None):
    """The local dofs of ``space`` on the mesh entities ``entities`` of dimension ``dim`` (1:
    facets, 2: cells); with ``component``, the pair (parent dofs, collapsed dofs) of that
    component (:func:`sub_space`)."""
    from dolfinx import fem

    spaces = space if component is None else sub_space(space, component)
    return fem.locate_dofs_topological(spaces, dim, entities)


def point_dofs(space, where, component: int | None = None):
    """The local dofs of ``space`` at the points x (3, n) where ``where(x)`` is True; with
    ``component``, the pair (parent dofs, collapsed dofs) of that component."""
    from dolfinx import fem

    spaces = space if component is None else sub_space(space, component)
    return fem.locate_dofs_geometrical(spaces, where)


def zero_condition(space, dofs, component: int | None = None):
    """The homogeneous Dirichlet condition on the ``dofs`` of ``space`` (every component of a
    vector space), or of its ``component`` (then ``dofs`` is the pair of :func:`entity_dofs`)."""
    from dolfinx import fem
    from petsc4py import PETSc

    if component is not None:
        sub, collapsed = sub_space(space, component)
        return fem.dirichletbc(function(collapsed), dofs, sub)
    size = space.dofmap.index_map_bs
    value = np.zeros(size, dtype=PETSc.ScalarType) if size > 1 else PETSc.ScalarType(0.0)
    return fem.dirichletbc(value, dofs, space)


def constrained_rows(form, bcs) -> np.ndarray:
    """The owned rows of the vector of the linear ``form`` that the Dirichlet ``bcs`` fix.

    0.5: ``fem.petsc.create_vector`` and ``fem.petsc.set_bc`` (see :func:`assemble_vector`).
    """
    import dolfinx.fem.petsc

    marker = dolfinx.fem.petsc.create_vector(form)
    with marker.localForm() as local:
        local.set(1.0)
    dolfinx.fem.petsc.set_bc(marker, bcs)
    rows = np.flatnonzero(marker.getArray() == 0.0)
    marker.destroy()
    return rows


def exterior_facets(mesh) -> np.ndarray:
    """The local facets of ``mesh`` on its boundary.

    0.5: ``dolfinx.mesh.exterior_facet_indices(topology)`` after the facet-to-cell
    connectivity is created; the same in 0.10.
    """
    from dolfinx import mesh as dmesh

    mesh.topology.create_connectivity(mesh.topology.dim - 1, mesh.topology.dim)
    return dmesh.exterior_facet_indices(mesh.topology)


def cell_nodes(mesh) -> np.ndarray:
    """The geometry nodes of each local cell (cells x nodes per cell), indices into
    ``mesh.geometry.x``.

    0.5: ``mesh.geometry.dofmap`` is an AdjacencyList, flattened by ``.array``; from 0.7 it is
    already the 2-D array.
    """
    dofmap = mesh.geometry.dofmap
    return dofmap.array.reshape(dofmap.num_nodes, -1)


def facet_midpoints(mesh, facets) -> np.ndarray:
    """The midpoints (n, 3) of the local ``facets`` of ``mesh``."""
    from dolfinx import mesh as dmesh

    return dmesh.compute_midpoints(mesh, mesh.topology.dim - 1, facets)


def point_values(function, points: np.ndarray):
    """(values, found) of the scalar ``function`` at ``points`` (n, 3) on this rank: the value
    at each point inside a local cell (owned or ghost) and the mask of those points (0
    elsewhere).

    0.5: ``geometry.BoundingBoxTree(mesh, dim)``; 0.7+: ``geometry.bb_tree(mesh, dim)``.
    """
    from dolfinx import geometry

    mesh = function.function_space.mesh
    tree = geometry.BoundingBoxTree(mesh, mesh.topology.dim)
    candidates = geometry.compute_collisions(tree, points)
    colliding = geometry.compute_colliding_cells(mesh, candidates, points)
    offsets = colliding.offsets
    found = offsets[1:] > offsets[:-1]
    values = np.zeros(len(points))
    if found.any():
        cells = colliding.array[offsets[np.flatnonzero(found)]]
        values[found] = function.eval(points[found], cells)[:, 0]
    return values, found


def solve_nonlinear(residual, jacobian, bcs, solution, configure):
    """Solve residual(u) = 0 for the function ``solution`` (its values the initial guess) by
    PETSc SNES with the Jacobian form ``jacobian`` and the Dirichlet ``bcs``, the solution's
    values set on them; ``configure(snes, vector)`` chooses the method, its tolerances and
    bounds (``vector`` a template of the solution). Returns (converged reason, iterations).

    0.5: the residual and Jacobian are assembled by ``fem.petsc.assemble_vector``,
    ``apply_lifting``, ``set_bc`` and ``assemble_matrix`` into PETSc objects of
    ``create_vector`` and ``create_matrix``; 0.10 offers ``fem.petsc.NonlinearProblem`` with
    the SNES built in instead.
    """
    import dolfinx.fem.petsc
    from petsc4py import PETSc

    target = petsc_vector(solution)

    def assemble_residual(snes, x, b):
        x.ghostUpdate(addv=PETSc.InsertMode.INSERT, mode=PETSc.ScatterMode.FORWARD)
        x.copy(target)
        solution.x.scatter_forward()
        with b.localForm() as local:
            local.set(0.0)
        dolfinx.fem.petsc.assemble_vector(b, residual)
        dolfinx.fem.petsc.apply_lifting(b, [jacobian], [bcs], x0=[x], scale=-1.0)
        b.ghostUpdate(addv=PETSc.InsertMode.ADD, mode=PETSc.ScatterMode.REVERSE)
        dolfinx.fem.petsc.set_bc(b, bcs, x, -1.0)

    def assemble_jacobian(snes, x, matrix, preconditioner):
        matrix.zeroEntries()
        dolfinx.fem.petsc.assemble_matrix(matrix, jacobian, bcs)
        matrix.assemble()

    matrix = dolfinx.fem.petsc.create_matrix(jacobian)
    vector = dolfinx.fem.petsc.create_vector(residual)
    snes = PETSc.SNES().create(solution.function_space.mesh.comm)
    try:
        snes.setFunction(assemble_residual, vector)
        snes.setJacobian(assemble_jacobian, matrix)
        configure(snes, vector)
        snes.solve(None, target)
        return snes.getConvergedReason(), snes.getIterationNumber()
    finally:
        solution.x.scatter_forward()
        for petsc_object in (snes, matrix, vector):
            petsc_object.destroy()


def taylor_hood_space(mesh):
    """The mixed space of a P2 velocity (one component per geometric dimension) and a P1
    pressure.

    0.5: ``fem.FunctionSpace(mesh, ufl.MixedElement([ufl.VectorElement("Lagrange", cell, 2),
    ufl.FiniteElement("Lagrange", cell, 1)]))``; from 0.7 the elements are built with
    ``basix.ufl.element`` and ``basix.ufl.mixed_element``.
    """
    import ufl
    from dolfinx import fem

    cell = mesh.ufl_cell()
    velocity = ufl.VectorElement("Lagrange", cell, 2)
    return fem.FunctionSpace(
        mesh, ufl.MixedElement([velocity, ufl.FiniteElement("Lagrange", cell, 1)])
    )


def velocity_component_dofs(space, component: int, facets) -> np.ndarray:
    """The local dofs (in ``space``'s numbering) of ``component`` of the velocity (sub-space 0)
    of a :func:`taylor_hood_space` on the mesh ``facets``."""
    from dolfinx import fem

    sub = space.sub(0).sub(component)
    return fem.locate_dofs_topological(sub, space.mesh.topology.dim - 1, facets)


def velocity_component_condition(space, component: int, facets, value):
    """The Dirichlet condition ``value`` (a number, or a :func:`constant` whose value can be
    changed between solves) on ``component`` of the velocity of a :func:`taylor_hood_space` on
    the mesh ``facets``."""
    from dolfinx import fem
    from petsc4py import PETSc

    dofs = velocity_component_dofs(space, component, facets)
    if isinstance(value, int | float):
        value = PETSc.ScalarType(value)
    return fem.dirichletbc(value, dofs, space.sub(0).sub(component))


def solve_linear(bilinear, linear, bcs, solution) -> None:
    """Solve the linear problem a(u, v) = L(v) with the Dirichlet ``bcs`` (lifted) by a direct
    LU factorisation (MUMPS) into the function ``solution``; every PETSc object is destroyed
    after the solve (no options are left in PETSc's database, so it can be called any number of
    times).

    0.5: ``fem.petsc.assemble_matrix``, ``assemble_vector``, ``apply_lifting`` and ``set_bc``
    (as :func:`solve_nonlinear`); ``fem.petsc.LinearProblem`` would do the same but registers
    new options at each construction. 0.10 reworked these PETSc helpers (check ``set_bc``'s and
    ``apply_lifting``'s arguments there).
    """
    import dolfinx.fem.petsc
    from petsc4py import PETSc

    matrix = assemble_matrix(bilinear, bcs)
    vector = dolfinx.fem.petsc.assemble_vector(linear)
    dolfinx.fem.petsc.apply_lifting(vector, [bilinear], [bcs])
    vector.ghostUpdate(addv=PETSc.InsertMode.ADD, mode=PETSc.ScatterMode.REVERSE)
    dolfinx.fem.petsc.set_bc(vector, bcs)
    ksp = PETSc.KSP().create(solution.function_space.mesh.comm)
    try:
        ksp.setOperators(matrix)
        ksp.setType("preonly")
        ksp.getPC().setType("lu")
        ksp.getPC().setFactorSolverType("mumps")
        ksp.solve(vector, petsc_vector(solution))
        if ksp.getConvergedReason() <= 0:
            raise RuntimeError(f"the linear solve failed (KSP reason {ksp.getConvergedReason()})")
        solution.x.scatter_forward()
    finally:
        for petsc_object in (ksp, matrix, vector):
            petsc_object.destroy()
