"""Every DOLFINx call of the package: the FE solids, their fields, the disk film and the liquid
around a bouncing sphere.

The package runs on two DOLFINx releases: Debian 12's 0.5.2 and 0.11 (the ``dolfinx-solver-real``
wheel on Python >= 3.12, with numpy 2 and petsc4py 3.25). Nothing outside this module imports
``dolfinx`` (:mod:`ehdfem.solids.fe`, :mod:`ehdfem.tangential.disk`,
:mod:`ehdfem.bounce.wall_flow`, :mod:`ehdfem.bounce.sphere_flow` and
:mod:`ehdfem.bounce.near_wall_flow` reach it only through these functions), so the two
releases differ here and nowhere else. Each difference is decided by what the installed
DOLFINx offers (``hasattr(fem, "functionspace")``, a dofmap that is already a 2-D array, ...),
not by its version number, so a release in between takes whichever form it has. The docstring
of each call that differs names both forms; the others (``fem.form``, ``fem.Function``,
``fem.Expression``, ``fem.dirichletbc``, ``fem.locate_dofs_*``, ``fem.assemble_scalar``, ...)
kept theirs. UFL (forms) and petsc4py (matrices, factorisations) are separate packages, used
directly.

DOLFINx and petsc4py are imported through :func:`_module`, which loads two modules first.
``mpi4py.MPI``: the MPICH wheel's ``libmpi`` is found by mpi4py, and importing DOLFINx or
petsc4py before it fails there. ``h5py`` (which writes the fields' XDMF): 0.11's
``dolfinx.fem.petsc`` opens the wheel's PETSc library with global symbols, and its HDF5 then
shadows the HDF5 of h5py's own wheel if h5py is imported later ("Not a datatype"); imported
first, each keeps its own. The imports stay lazy so that a half-space run loads none of them.

Nothing here knows about scales: meshes, spaces, matrices and vectors carry whatever units the
caller's forms give them.
"""

from __future__ import annotations

import importlib
import importlib.util
import inspect
import sys

import numpy as np


def _module(name: str):
    """The module ``name`` (``dolfinx.fem``, ``petsc4py.PETSc``, ...), with MPI and h5py (when
    installed) loaded before it (module docstring)."""
    importlib.import_module("mpi4py.MPI")
    if "h5py" not in sys.modules and importlib.util.find_spec("h5py") is not None:
        importlib.import_module("h5py")
    return importlib.import_module(name)


def _fem():
    return _module("dolfinx.fem")


def _fem_petsc():
    """``dolfinx.fem.petsc``: a submodule that 0.7+ no longer imports with ``dolfinx.fem``."""
    return _module("dolfinx.fem.petsc")


def petsc():
    """petsc4py's ``PETSc`` module, MPI loaded first (also for the modules that build PETSc
    objects of their own: the linear algebra and the condensation)."""
    return _module("petsc4py.PETSc")


def version() -> str:
    """The installed DOLFINx's version (e.g. "0.5.2", "0.11.0")."""
    return _module("dolfinx").__version__


def _space(mesh, family: str, degree: int, shape: tuple | None = None):
    """The space of the ``family`` elements of ``degree`` on ``mesh``, ``shape`` components.

    0.5: ``fem.FunctionSpace(mesh, (family, k))``, ``fem.VectorFunctionSpace(mesh, (family,
    k), dim=n)``; 0.7+: ``fem.functionspace(mesh, (family, k, shape))``, the only form from 0.8.
    """
    fem = _fem()
    if hasattr(fem, "functionspace"):
        return fem.functionspace(mesh, (family, degree, *([shape] if shape else [])))
    if shape:
        return fem.VectorFunctionSpace(mesh, (family, degree), dim=shape[0])
    return fem.FunctionSpace(mesh, (family, degree))


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


def mesh_from_gmsh(model, comm, rank: int = 0, gdim: int = 2):
    """(mesh, cell tags, facet tags): the DOLFINx mesh of the gmsh ``model`` held by ``rank``,
    distributed over ``comm``, and its physical groups.

    0.5: ``dolfinx.io.gmshio.model_to_mesh`` returns that tuple. 0.10 moves it to
    ``dolfinx.io.gmsh.model_to_mesh`` and returns a ``MeshData`` record (``.mesh``,
    ``.cell_tags``, ``.facet_tags``).
    """
    _module("dolfinx.io")
    if importlib.util.find_spec("dolfinx.io.gmshio") is not None:
        return _module("dolfinx.io.gmshio").model_to_mesh(model, comm, rank, gdim=gdim)
    data = _module("dolfinx.io.gmsh").model_to_mesh(model, comm, rank, gdim=gdim)
    return data.mesh, data.cell_tags, data.facet_tags


def vtk_mesh(space):
    """(VTK cell array, VTK cell types, coordinates (n, 3)) of the dofs of a P1 ``space``: the
    vertices in the order of the space's dofs, one VTK cell per local cell (owned cells first).

    0.5: ``dolfinx.plot.create_vtk_mesh(space)``; renamed ``dolfinx.plot.vtk_mesh`` in 0.7.
    """
    plot = _module("dolfinx.plot")
    return (plot.vtk_mesh if hasattr(plot, "vtk_mesh") else plot.create_vtk_mesh)(space)


def assemble_matrix(form, bcs):
    """The assembled PETSc matrix of a bilinear ``form``, with the rows and columns of the
    Dirichlet ``bcs`` replaced by the identity.

    0.5: ``fem.petsc.assemble_matrix(form, bcs=bcs)`` then ``.assemble()``; the same in 0.11,
    where the submodule must be imported explicitly (:func:`_fem_petsc`).
    """
    matrix = _fem_petsc().assemble_matrix(form, bcs=bcs)
    matrix.assemble()
    return matrix


def _vector_of(form):
    """A ghosted PETSc vector laid out as the test space of the linear ``form``, not zeroed.

    0.5: ``fem.petsc.create_vector(form)``; 0.10 takes the space instead of the form
    (``create_vector(form.function_spaces[0])``).
    """
    create = _fem_petsc().create_vector
    if next(iter(inspect.signature(create).parameters)) == "V":  # 0.10+: of a space ("V")
        return create(form.function_spaces[0])
    return create(form)  # 0.5: of a form ("L")


def assemble_vector(form, bcs):
    """The assembled PETSc vector of a linear ``form``: ghost contributions summed onto their
    owners, then the values of the Dirichlet ``bcs`` set (zero here: homogeneous conditions,
    no lifting needed).

    ``fem.petsc.assemble_vector``, ``ghostUpdate(ADD, REVERSE)`` and ``fem.petsc.set_bc(vector,
    bcs)``: the same calls in 0.5 and 0.11 (see :func:`_lifted`).
    """
    PETSc = petsc()
    fem_petsc = _fem_petsc()
    vector = fem_petsc.assemble_vector(form)
    vector.ghostUpdate(addv=PETSc.InsertMode.ADD, mode=PETSc.ScatterMode.REVERSE)
    fem_petsc.set_bc(vector, bcs)
    return vector


def _lifted(vector, linear, bilinear, bcs, x0=None, scale: float = 1.0) -> None:
    """Assemble the linear form ``linear`` into the PETSc ``vector`` (zeroed first), lift the
    Dirichlet ``bcs`` of the bilinear form ``bilinear`` (b - scale A (g - x0)), sum the ghosts
    onto their owners and set the constrained rows to scale (g - x0).

    Positional arguments, as the keywords differ: 0.5 ``apply_lifting(b, [a], [bcs], x0=[x],
    scale=s)`` and ``set_bc(b, bcs, x0, scale)``; 0.10+ names ``scale`` ``alpha`` (and takes
    ``x0=None`` for none).
    """
    PETSc = petsc()
    fem_petsc = _fem_petsc()
    with vector.localForm() as local:
        local.set(0.0)
    fem_petsc.assemble_vector(vector, linear)
    fem_petsc.apply_lifting(vector, [bilinear], [bcs], [] if x0 is None else [x0], scale)
    vector.ghostUpdate(addv=PETSc.InsertMode.ADD, mode=PETSc.ScatterMode.REVERSE)
    fem_petsc.set_bc(vector, bcs, x0, scale)


def petsc_vector(function):
    """The PETSc vector that holds the values of ``function`` (a solver writes into it).

    0.5: ``function.vector``; ``function.x.petsc_vec`` from 0.8, where ``.vector`` is deprecated
    (and removed in 0.10).
    """
    return function.x.petsc_vec if hasattr(function.x, "petsc_vec") else function.vector


def form(expression):
    """The compiled form of the UFL ``expression`` (bilinear, linear or a functional)."""
    return _fem().form(expression)


def function(space, name: str | None = None):
    """A finite-element function on ``space``, zero (``name`` labels it in exported files)."""
    fem = _fem()
    return fem.Function(space) if name is None else fem.Function(space, name=name)


def constant(mesh, value: float):
    """A constant on ``mesh`` whose value can be changed between solves (``.value``)."""
    return _fem().Constant(mesh, petsc().ScalarType(value))


def expression(ufl_expression, space):
    """``ufl_expression`` compiled for interpolation into ``space`` (``function.interpolate``)."""
    return _fem().Expression(ufl_expression, interpolation_points(space))


def integral(integrand, comm) -> float:
    """The value of the functional ``integrand`` (a UFL form with its measure), summed over the
    ranks of ``comm``."""
    fem = _fem()
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
    spaces = space if component is None else list(sub_space(space, component))
    return _fem().locate_dofs_topological(spaces, dim, entities)


def point_dofs(space, where, component: int | None = None):
    """The local dofs of ``space`` at the points x (3, n) where ``where(x)`` is True; with
    ``component``, the pair (parent dofs, collapsed dofs) of that component."""
    spaces = space if component is None else list(sub_space(space, component))
    return _fem().locate_dofs_geometrical(spaces, where)


def zero_condition(space, dofs, component: int | None = None):
    """The homogeneous Dirichlet condition on the ``dofs`` of ``space`` (every component of a
    vector space), or of its ``component`` (then ``dofs`` is the pair of :func:`entity_dofs`)."""
    fem, PETSc = _fem(), petsc()
    if component is not None:
        sub, collapsed = sub_space(space, component)
        return fem.dirichletbc(function(collapsed), dofs, sub)
    size = space.dofmap.index_map_bs
    value = np.zeros(size, dtype=PETSc.ScalarType) if size > 1 else PETSc.ScalarType(0.0)
    return fem.dirichletbc(value, dofs, space)


def constrained_rows(form, bcs) -> np.ndarray:
    """The owned rows of the vector of the linear ``form`` that the Dirichlet ``bcs`` fix
    (a vector of ones, the constrained rows set to zero: :func:`_vector_of`, ``set_bc``)."""
    marker = _vector_of(form)
    with marker.localForm() as local:
        local.set(1.0)
    _fem_petsc().set_bc(marker, bcs)
    rows = np.flatnonzero(marker.getArray() == 0.0)
    marker.destroy()
    return rows


def exterior_facets(mesh) -> np.ndarray:
    """The local facets of ``mesh`` on its boundary.

    0.5: ``dolfinx.mesh.exterior_facet_indices(topology)`` after the facet-to-cell
    connectivity is created; the same in 0.11.
    """
    mesh.topology.create_connectivity(mesh.topology.dim - 1, mesh.topology.dim)
    return _module("dolfinx.mesh").exterior_facet_indices(mesh.topology)


def cell_nodes(mesh) -> np.ndarray:
    """The geometry nodes of each local cell (cells x nodes per cell), indices into
    ``mesh.geometry.x``.

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


def facet_midpoints(mesh, facets) -> np.ndarray:
    """The midpoints (n, 3) of the local ``facets`` of ``mesh``."""
    return _module("dolfinx.mesh").compute_midpoints(mesh, mesh.topology.dim - 1, facets)


def point_values(function, points: np.ndarray):
    """(values, found) of the scalar ``function`` at ``points`` (n, 3) on this rank: the value
    at each point inside a local cell (owned or ghost) and the mask of those points (0
    elsewhere).

    0.5: ``geometry.BoundingBoxTree(mesh, dim)`` and ``geometry.compute_collisions(tree,
    points)``; 0.7+: ``geometry.bb_tree(mesh, dim)`` and ``compute_collisions_points``.
    """
    geometry = _module("dolfinx.geometry")
    mesh = function.function_space.mesh
    if hasattr(geometry, "bb_tree"):
        tree = geometry.bb_tree(mesh, mesh.topology.dim)
        candidates = geometry.compute_collisions_points(tree, points)
    else:
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

    The residual and Jacobian are assembled by hand into PETSc objects of ``create_vector``
    and ``create_matrix`` (:func:`_lifted`), on 0.5 and 0.11 alike. 0.10's
    ``fem.petsc.NonlinearProblem`` builds the same SNES, but registers options of its own at
    each construction, and the variational-inequality bounds of :mod:`ehdfem.tangential.disk`
    need the SNES before the solve anyway, so the one hand-written path serves both.
    """
    PETSc = petsc()
    fem_petsc = _fem_petsc()
    target = petsc_vector(solution)

    def assemble_residual(snes, x, b):
        x.ghostUpdate(addv=PETSc.InsertMode.INSERT, mode=PETSc.ScatterMode.FORWARD)
        x.copy(target)
        solution.x.scatter_forward()
        _lifted(b, residual, jacobian, bcs, x, -1.0)

    def assemble_jacobian(snes, x, matrix, preconditioner):
        matrix.zeroEntries()
        fem_petsc.assemble_matrix(matrix, jacobian, bcs)
        matrix.assemble()

    matrix = fem_petsc.create_matrix(jacobian)
    vector = _vector_of(residual)
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
    ``basix.ufl.element`` and ``basix.ufl.mixed_element`` (UFL's own elements are gone), and
    given to ``fem.functionspace``.
    """
    fem = _fem()
    if hasattr(fem, "functionspace"):
        elements = importlib.import_module("basix.ufl")
        cell = mesh.basix_cell()
        velocity = elements.element("Lagrange", cell, 2, shape=(mesh.geometry.dim,))
        pressure = elements.element("Lagrange", cell, 1)
        return fem.functionspace(mesh, elements.mixed_element([velocity, pressure]))
    ufl = importlib.import_module("ufl")
    cell = mesh.ufl_cell()
    velocity = ufl.VectorElement("Lagrange", cell, 2)
    return fem.FunctionSpace(
        mesh, ufl.MixedElement([velocity, ufl.FiniteElement("Lagrange", cell, 1)])
    )


def velocity_component_dofs(space, component: int, facets) -> np.ndarray:
    """The local dofs (in ``space``'s numbering) of ``component`` of the velocity (sub-space 0)
    of a :func:`taylor_hood_space` on the mesh ``facets``."""
    sub = space.sub(0).sub(component)
    return _fem().locate_dofs_topological(sub, space.mesh.topology.dim - 1, facets)


def velocity_component_condition(space, component: int, facets, value):
    """The Dirichlet condition ``value`` (a number, or a :func:`constant` whose value can be
    changed between solves) on ``component`` of the velocity of a :func:`taylor_hood_space` on
    the mesh ``facets``."""
    dofs = velocity_component_dofs(space, component, facets)
    if isinstance(value, int | float):
        value = petsc().ScalarType(value)
    return _fem().dirichletbc(value, dofs, space.sub(0).sub(component))


def solve_linear(bilinear, linear, bcs, solution) -> None:
    """Solve the linear problem a(u, v) = L(v) with the Dirichlet ``bcs`` (lifted) by a direct
    LU factorisation (MUMPS) into the function ``solution``; every PETSc object is destroyed
    after the solve (no options are left in PETSc's database, so it can be called any number of
    times).

    Assembled by hand (:func:`assemble_matrix`, :func:`_lifted`) on 0.5 and 0.11 alike;
    ``fem.petsc.LinearProblem`` would do the same but registers new options at each
    construction.
    """
    PETSc = petsc()
    matrix = assemble_matrix(bilinear, bcs)
    vector = _vector_of(linear)
    _lifted(vector, linear, bilinear, bcs)
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
