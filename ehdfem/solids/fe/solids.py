"""Finite-element solids: axisymmetric linear elasticity (DOLFINx) condensed to the film nodes.

The upper sphere and the lower body (a wall block, a coated wall block, or a second sphere)
are meshed in (r, z) with gmsh (meshes/contact.py through :mod:`ehdfem.solids.fe.mesh`,
lengths by the (reduced) radius a) and solved with P2 Lagrange elements in the r-weighted
axisymmetric form (strain with the hoop term u_r / r). The hat pressure phi_j of film node j,
acting normally on both contact faces, gives the gap opening at every film node i,

    W_i = (u_z^upper(r_i) - c_upper) - (u_z^lower(r_i) - c_lower),

the column j of the compliance matrix. All columns come from one factorisation condensed onto
the contact faces (:mod:`ehdfem.solids.fe.condensation`), on one process. A sphere is a free
:class:`Body`: its film load is balanced by a uniform d'Alembert body force, its far pole is
pinned (u_z) to make the problem definite, and c is its centre-of-mass displacement. A wall
is clamped at its base, 40 radii below (c = 0).

Scales: stresses in units of E_ref (the upper sphere's modulus) make u come out in units of
a p / E_ref; the film pressure unit mu V0 a / x0^2 and the gap unit x0 turn this into the
dimensionless compliance of the half-space kernel,

    C = eps / (4 theta E_ref sqrt(delta)) * u_hat,   theta = sum (1 - nu^2)/(pi E)

over the sphere and the lower body (the substrate, for a coated wall), with film radii R (by
sqrt(a x0)) at r = R sqrt(delta) a. C scales linearly with eps: one factorisation serves a
whole (St, eps) sweep at fixed delta and materials.

Besides the compliance, :meth:`FESolids.deformation` gives the whole solids under one film
pressure (vertex displacements and cell stresses, in the film's scales) for the field exports
(:mod:`ehdfem.outputs.fields`) and the pictures (:mod:`ehdfem.outputs.render`). DOLFINx calls whose
spelling depends on the release go through :mod:`ehdfem.solids.fe.dolfinx_compat`.
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from ... import checks
from ..compliance import LinearCompliance
from . import dolfinx_compat
from .condensation import condensed
from .mesh import cached_matrices, contact_mesh

LOWER_BODIES = ("wall", "coated", "sphere")


@dataclass(frozen=True)
class Body:
    """A free solid (a sphere): its film load is balanced by a uniform d'Alembert body force
    and its far pole is pinned in u_z. ``cell_tag`` and ``contact_tag`` are its gmsh groups
    (cells, contact face; meshes/contact.py), ``pole_z`` the height of the pinned pole (by a)
    and ``direction`` the sign of the body force per unit film load (-1 for the upper sphere,
    which the film pushes up; +1 for a lower sphere, pushed down)."""

    cell_tag: int
    contact_tag: int
    pole_z: float
    direction: float


@dataclass(frozen=True, eq=False)
class Deformation:
    """The solids under one film pressure, on this rank's part of the mesh (read-only arrays).

    ``points``: (n, 2) vertex coordinates (r, z), by a. ``triangles``: (m, 3) the cells owned
    by this rank, as indices into ``points``. ``displacement``: (n, 2) (u_r, u_z) at the
    vertices, by x0, each free sphere relative to its centre of mass. ``von_mises`` and
    ``hydrostatic``: (m,) stress per triangle, by mu V0 a / x0^2 (the film pressure unit; per
    cell, as the hoop strain u_r / r is 0/0 at vertices on the axis). ``upper``: (n,) True at
    the vertices of the upper sphere.
    """

    points: np.ndarray
    triangles: np.ndarray
    displacement: np.ndarray
    von_mises: np.ndarray
    hydrostatic: np.ndarray
    upper: np.ndarray


@dataclass(frozen=True)
class _VertexMesh:
    """The P1 (vertex) mesh of one rank: a P1 displacement to interpolate into, the vertices,
    the owned triangles and the vertices of each free body (in the order of the bodies)."""

    function: object
    points: np.ndarray
    triangles: np.ndarray
    body_vertices: list
    upper: np.ndarray


def solids_of(compliance, purpose: str) -> FESolids:
    """The :class:`FESolids` behind ``compliance`` (an :class:`FECompliance`), or an InputError
    saying that ``purpose`` needs them (a half-space or rigid compliance has no mesh)."""
    solids = getattr(compliance, "solids", None)
    if solids is None:
        model = getattr(compliance, "model", type(compliance).__name__)
        raise checks.InputError(
            f"{purpose} needs FE solids (--model fem); the {model} compliance has no mesh"
        )
    return solids


def interpolation_matrix(nodes, points):
    """The sparse (len(points), len(nodes)) matrix of linear interpolation from values at the
    increasing ``nodes`` to ``points`` (the same length unit): constant before the first node,
    zero beyond the last (as ``np.interp(points, nodes, values, right=0.0)``). Its columns are
    the hat functions of the nodes at the points."""
    import scipy.sparse

    nodes, points = np.asarray(nodes, dtype=float), np.asarray(points, dtype=float)
    right = np.clip(np.searchsorted(nodes, points, side="right"), 1, len(nodes) - 1)
    weight = np.clip((points - nodes[right - 1]) / (nodes[right] - nodes[right - 1]), 0.0, 1.0)
    inside = points <= nodes[-1]
    rows = np.flatnonzero(inside)
    return scipy.sparse.csr_matrix(
        (
            np.concatenate([1 - weight[inside], weight[inside]]),
            (np.concatenate([rows, rows]), np.concatenate([right[inside] - 1, right[inside]])),
        ),
        shape=(len(points), len(nodes)),
    )


def _scipy_matrix(matrix):
    """The owned rows of the PETSc AIJ ``matrix`` as a scipy CSR matrix (global columns)."""
    import scipy.sparse

    indptr, indices, data = matrix.getValuesCSR()
    return scipy.sparse.csr_matrix(
        (data, indices, indptr), shape=(len(indptr) - 1, matrix.getSize()[1])
    )


def _read_only(array: np.ndarray) -> np.ndarray:
    """``array``, no longer writeable (shared between deformations)."""
    array.setflags(write=False)
    return array


class FESolids:
    """FE solids meshed for the film nodes ``radii`` (by sqrt(a x0)); see the module docstring.

    ``delta`` = x0/a. ``sphere``, ``wall`` (the lower body: wall, substrate or lower sphere) and
    ``coating`` are (Young's modulus, Poisson ratio) pairs; only ratios of moduli matter.
    ``lower``: "wall", "coated" (``coating_thickness`` by a) or "sphere". For two spheres a is
    the reduced radius and ``radius_ratio`` = a1/a2 (upper over lower); ``radius_upper`` and
    ``radius_lower`` (None for a wall) are the sphere radii by a. ``size``: the wall block's
    width and depth (by a); ``degree``: of the Lagrange elements. ``comm``: MPI communicator
    (default COMM_WORLD). ``bodies``: the free bodies (:class:`Body`), upper sphere first.
    ``compliance(eps)`` gives the film compliance, ``deformation`` the whole solids.
    """

    def __init__(
        self,
        delta: float,
        radii,
        sphere=(1.0, 0.3),
        wall=(1.0, 0.3),
        lower="wall",
        coating=(1.0, 0.3),
        coating_thickness=None,
        radius_ratio=1.0,
        size=40.0,
        degree=2,
        comm=None,
    ):
        from mpi4py import MPI

        from meshes import contact as geometry

        self.delta = checks.number(
            "delta", delta, lower=0.0, upper=1.0, lower_open=True, upper_open=True
        )
        self.lower = checks.choice("lower", lower, LOWER_BODIES)
        for name, (e, nu) in (("sphere", sphere), ("wall", wall), ("coating", coating)):
            checks.positive(f"{name} Young's modulus", e)
            checks.number(
                f"{name} Poisson ratio", nu, lower=-1.0, upper=0.5, lower_open=True, upper_open=True
            )
        if lower == "coated":
            checks.positive("coating_thickness", coating_thickness)
        ratio = checks.positive("radius_ratio", radius_ratio)
        # radii by the reduced radius a: a1 = a (1 + ratio), a2 = a (1 + 1/ratio)
        self.radius_upper, self.radius_lower = (
            (1 + ratio, 1 + 1 / ratio) if lower == "sphere" else (1.0, None)
        )
        self.comm = comm or MPI.COMM_WORLD
        self._inputs = dict(
            delta=delta,
            radii=radii,
            sphere=sphere,
            wall=wall,
            lower=lower,
            coating=coating,
            coating_thickness=coating_thickness,
            radius_ratio=radius_ratio,
            size=size,
            degree=degree,
        )
        self.radii = np.asarray(radii, dtype=float)
        limit = 0.7 * min(self.radius_upper, self.radius_lower or math.inf)
        if self.radii[-1] * math.sqrt(self.delta) >= limit:
            raise checks.InputError(
                f"the film reaches r = {self.radii[-1] * math.sqrt(self.delta):.3g} a; the FE "
                f"solids need it within 0.7 of the smaller sphere radius ({limit:.3g} a)"
            )
        self._geometry = geometry
        arguments = (
            self.delta,
            self.radii_a,
            lower,
            size,
            self.radius_upper,
            self.radius_lower or 1.0,
            coating_thickness,
        )
        self.mesh, self._cell_tags, self._facet_tags = contact_mesh(
            self.comm, geometry.build, arguments
        )
        self.bodies = self._free_bodies()
        e_ref = sphere[0]
        self._theta_e_ref = sum((1 - nu**2) * e_ref / (math.pi * e) for e, nu in (sphere, wall))
        materials = {geometry.SPHERE: sphere, geometry.LOWER: wall, geometry.COATING: coating}
        scaled = {tag: (e / e_ref, nu) for tag, (e, nu) in materials.items()}
        self.cache_arguments = (arguments, sorted(scaled.items()), degree)
        self._assemble(scaled, degree)

    @property
    def cache_sources(self) -> list:
        """The code whose source keys the cached matrices of these solids (with
        ``cache_arguments``: the mesh generator's arguments, the scaled moduli per cell tag and
        the degree; :func:`ehdfem.solids.fe.mesh.cached_matrices`)."""
        return [sys.modules[__name__], dolfinx_compat, self._geometry.build]

    @property
    def radii_a(self):
        """The film nodes in units of a."""
        return self.radii * math.sqrt(self.delta)

    @property
    def dofs(self) -> int:
        """Number of displacement unknowns (both components, all ranks)."""
        return 2 * self._space.dofmap.index_map.size_global

    def _free_bodies(self) -> tuple[Body, ...]:
        """The upper sphere, and the lower one when there are two spheres."""
        geometry = self._geometry
        top = 2 * self.radius_upper + self.delta
        bodies = (Body(geometry.SPHERE, geometry.SPHERE_CONTACT, top, -1.0),)
        if self.lower == "sphere":
            bottom = -2 * self.radius_lower
            bodies += (Body(geometry.LOWER, geometry.LOWER_CONTACT, bottom, 1.0),)
        return bodies

    def _assemble(self, materials, degree):
        """Assemble and factorise the stiffness; set up the film load and the body forces."""
        import ufl
        from dolfinx import fem
        from petsc4py import PETSc

        V = self._space = dolfinx_compat.lagrange_space(self.mesh, degree, vector=True)
        strain, stress = self._constitutive_law(materials)
        u, v = ufl.TrialFunction(V), ufl.TestFunction(V)
        self._bcs = self._constraints()
        self._stiffness = dolfinx_compat.assemble_matrix(
            fem.form(ufl.inner(stress(u), strain(v)) * self._r * ufl.dx), self._bcs
        )
        # symmetric positive definite once the constraints remove the rigid motions: Cholesky
        self._stiffness.setOption(PETSc.Mat.Option.SPD, True)
        self._ksp = PETSc.KSP().create(self.comm)
        self._ksp.setOperators(self._stiffness)
        self._ksp.setType("preonly")
        self._ksp.getPC().setType("cholesky")
        self._ksp.getPC().setFactorSolverType("mumps")
        self._load_forms(v)

    def _constitutive_law(self, materials):
        """(strain, stress) of a displacement in the r-weighted axisymmetric form, as 3x3 (r,
        theta, z) tensors; stress by E_ref, with the moduli ``materials`` (per cell tag: Young's
        modulus by E_ref, Poisson ratio)."""
        import ufl
        from dolfinx import fem

        cells = dolfinx_compat.cell_space(self.mesh)
        young, poisson = fem.Function(cells), fem.Function(cells)
        for tag, (e, nu) in materials.items():
            tagged = self._cell_tags.find(tag)
            young.x.array[tagged], poisson.x.array[tagged] = e, nu
        lmbda = young * poisson / ((1 + poisson) * (1 - 2 * poisson))
        mu = young / (2 * (1 + poisson))
        r = self._r = ufl.SpatialCoordinate(self.mesh)[0]

        def strain(v):
            grad = [[v[0].dx(0), 0, v[0].dx(1)], [0, v[0] / r, 0], [v[1].dx(0), 0, v[1].dx(1)]]
            return ufl.sym(ufl.as_tensor(grad))

        def stress(v):
            return lmbda * ufl.tr(strain(v)) * ufl.Identity(3) + 2 * mu * strain(v)

        self._stress = stress
        return strain, stress

    def _constraints(self):
        """Dirichlet conditions: u_r = 0 on the axis, a clamped wall base (no free lower body)
        and u_z = 0 at the far pole of each free body."""
        from dolfinx import fem
        from petsc4py import PETSc

        V, geometry, facets = self._space, self._geometry, self._facet_tags
        V0, _ = V.sub(0).collapse()
        V1, _ = V.sub(1).collapse()
        axis = np.concatenate([facets.find(t) for t in (geometry.SPHERE_AXIS, geometry.LOWER_AXIS)])
        bcs = [
            fem.dirichletbc(
                fem.Function(V0), fem.locate_dofs_topological((V.sub(0), V0), 1, axis), V.sub(0)
            )
        ]
        if self.lower != "sphere":
            base = fem.locate_dofs_topological(V, 1, facets.find(geometry.LOWER_BOTTOM))
            bcs.append(fem.dirichletbc(np.zeros(2, dtype=PETSc.ScalarType), base, V))
        for body in self.bodies:
            pole = fem.locate_dofs_geometrical(
                (V.sub(1), V1), lambda p, z=body.pole_z: np.isclose(p[0], 0) & np.isclose(p[1], z)
            )
            bcs.append(fem.dirichletbc(fem.Function(V1), pole, V.sub(1)))
        return bcs

    def _load_forms(self, v):
        """The film loads as matrices on a traction profile (P2, both contact faces): the
        normal pressure -p n and the radial shear traction t_r, each int (.) . v r ds; the
        pressure's resultant on the lower face as a row; each free body's volume; the rows the
        Dirichlet conditions fix (their load is zero)."""
        import dolfinx.fem.petsc
        import ufl
        from dolfinx import fem

        msh, geometry, r = self.mesh, self._geometry, self._r
        dx = self._dx = ufl.Measure("dx", domain=msh, subdomain_data=self._cell_tags)
        self._test = v
        ds = ufl.Measure("ds", domain=msh, subdomain_data=self._facet_tags)
        n = ufl.FacetNormal(msh)
        self._profile_space = dolfinx_compat.lagrange_space(msh, 2)
        q = ufl.TrialFunction(self._profile_space)
        faces = ds(geometry.SPHERE_CONTACT) + ds(geometry.LOWER_CONTACT)
        works = {"pressure": -ufl.dot(n, v), "shear": v[0]}
        self._tractions = {
            kind: dolfinx_compat.assemble_matrix(fem.form(q * work * r * faces), [])
            for kind, work in works.items()
        }
        resultant = ufl.TestFunction(self._profile_space) * r * ds(geometry.LOWER_CONTACT)
        self._resultant = dolfinx_compat.assemble_vector(fem.form(resultant), []).getArray()
        self._volumes = [
            self.comm.allreduce(fem.assemble_scalar(fem.form(r * dx(body.cell_tag))))
            for body in self.bodies
        ]
        self._u = fem.Function(self._space)
        marker = dolfinx.fem.petsc.create_vector(fem.form(v[0] * r * dx))
        with marker.localForm() as local:
            local.set(1.0)
        dolfinx.fem.petsc.set_bc(marker, self._bcs)
        self._constrained = np.flatnonzero(marker.getArray() == 0.0)
        marker.destroy()

    @cached_property
    def _face_hats(self):
        """Per contact face (upper, lower): the sparse (owned P2 traction profile dofs, N) matrix
        of the film nodes' hat functions at the dofs on that face (zero elsewhere)."""
        import scipy.sparse
        from dolfinx import fem

        space = self._profile_space
        owned = space.dofmap.index_map.size_local
        r = space.tabulate_dof_coordinates()[:owned, 0]
        hats = []
        for tag in self._contact_tags:
            dofs = fem.locate_dofs_topological(space, 1, self._facet_tags.find(tag))
            on_face = scipy.sparse.diags(np.isin(np.arange(owned), dofs).astype(float))
            hats.append(on_face @ interpolation_matrix(self.radii_a, r))
        return hats

    def profile_values(self, faces) -> np.ndarray:
        """The owned entries (rows, columns) of the P2 traction profiles with nodal values
        ``faces`` = (upper, lower), each (N, columns) at the film nodes (linear between them,
        zero beyond the last; :meth:`film_pressure`), on the two contact faces, zero elsewhere;
        in the units of the nodal values (the film pressure unit mu V0 a / x0^2 for the films'
        loads)."""
        return sum(hats @ nodal for hats, nodal in zip(self._face_hats, faces, strict=True))

    def traction_loads(self, matrix, values: np.ndarray) -> np.ndarray:
        """The owned rows of ``matrix`` (unknowns x P2 profile dofs) times the owned profile
        entries ``values`` (:meth:`profile_values`), as a dense array (rows, columns): load
        vectors int t . v r ds with lengths by a, in the unit of ``values`` times a^2."""
        from petsc4py import PETSc

        index_map = self._profile_space.dofmap.index_map
        dense = PETSc.Mat().createDense(
            [(index_map.size_local, index_map.size_global), (PETSc.DECIDE, values.shape[1])],
            comm=self.comm,
        )
        dense.setUp()
        dense.getDenseArray()[:] = values
        dense.assemble()
        product = matrix.matMult(dense)
        loads = product.getDenseArray().copy()
        for petsc_object in (dense, product):
            petsc_object.destroy()
        return loads

    def _film_loads(self, pressure: np.ndarray, shear: np.ndarray | None = None) -> np.ndarray:
        """The owned rows (rows, columns) of the loads of film pressures ``pressure`` (N,
        columns) at the film nodes, in the film pressure unit, normal on both contact faces,
        and of radial shear tractions ``shear`` (the same unit, outward positive, on both
        faces; None: none), with the d'Alembert body forces that balance the pressure on the
        free spheres (uniform, int f . v r dx over the body = the resultant times the centre
        weights); zero on the constrained rows."""
        values = self.profile_values((pressure, pressure))
        loads = self.traction_loads(self._tractions["pressure"], values)
        if shear is not None:
            loads += self.traction_loads(
                self._tractions["shear"], self.profile_values((shear,) * 2)
            )
        resultant = self.comm.allreduce(self._resultant @ values)
        for body, weights in zip(self.bodies, self._centre_weights, strict=True):
            loads += np.outer(body.direction * weights, resultant)
        loads[self._constrained] = 0.0
        return loads

    def _solve(self, loads: np.ndarray) -> np.ndarray:
        """The owned rows of the displacements (by a p / E_ref) of the load columns ``loads``,
        from one multiple-right-hand-side solve on the factorisation."""
        from petsc4py import PETSc

        size = (loads.shape[0], self.comm.allreduce(loads.shape[0]))
        rhs = PETSc.Mat().createDense([size, (PETSc.DECIDE, loads.shape[1])], comm=self.comm)
        rhs.setUp()
        rhs.getDenseArray()[:] = loads
        rhs.assemble()
        solution = rhs.duplicate()
        self._ksp.setUp()
        self._ksp.getPC().getFactorMatrix().matSolve(rhs, solution)
        values = solution.getDenseArray().copy()
        for petsc_object in (rhs, solution):  # PETSc memory is not freed by Python's GC
            petsc_object.destroy()
        return values

    def displacement(self, nodal_pressure, nodal_shear=None):
        """Solve for the film pressure with values ``nodal_pressure`` (N,) at the film nodes, in
        the film pressure unit: normal pressure on both contact faces, d'Alembert body forces
        on free spheres; and a radial shear traction ``nodal_shear`` (the same unit, outward
        positive; None: none) on both faces. Returns the displacement (a DOLFINx function, in
        units of a p/E_ref), also kept for :meth:`gap_opening`."""
        columns = [
            None if x is None else np.asarray(x, float)[:, None]
            for x in (nodal_pressure, nodal_shear)
        ]
        values = self._solve(self._film_loads(*columns))
        self._u.x.array[: len(values)] = values[:, 0]
        self._u.x.scatter_forward()
        return self._u

    def _centres(self):
        """Centre-of-mass u_z (by a p/E_ref) of each free body, in the order of ``bodies``."""
        return [
            self.comm.allreduce(weights @ self._u.x.array[: len(weights)])
            for weights in self._centre_weights
        ]

    def _surface(self, tag):
        """(r, u_z) at the dofs of a contact face, gathered from all ranks and sorted by r."""
        rows, r = self._surface_rows[tag]
        pairs = np.concatenate(self.comm.allgather(np.column_stack([r, self._u.x.array[rows]])))
        r, index = np.unique(pairs[:, 0], return_index=True)
        return r, pairs[index, 1]

    def gap_opening(self):
        """W (in units of a p/E_ref) at the film nodes for the current displacement."""
        upper, lower = [*self._centres(), 0.0][:2]  # a clamped wall's centre does not move
        r_up, u_up = self._surface(self._geometry.SPHERE_CONTACT)
        r_lo, u_lo = self._surface(self._geometry.LOWER_CONTACT)
        return (np.interp(self.radii_a, r_up, u_up) - upper) - (
            np.interp(self.radii_a, r_lo, u_lo) - lower
        )

    def close(self) -> None:
        """Free the factorised stiffness (PETSc memory, a few hundred MB at production
        resolution, which Python's garbage collector does not return). Collective under MPI;
        the solids cannot solve afterwards. Studies that build many solids call it for each."""
        self._ksp.destroy()
        self._stiffness.destroy()

    def scale(self, eps: float) -> float:
        """x0 per (a p / E_ref): FE displacements to the gap unit (module docstring)."""
        return checks.positive("eps", eps) / (4 * self._theta_e_ref * math.sqrt(self.delta))

    def film_pressure(self, nodal):
        """The film pressure with values ``nodal`` at the film nodes (by mu V0 a / x0^2), linear
        between them and zero beyond the last, as a callable of r (by a)."""
        nodal = np.asarray(nodal, dtype=float)

        def pressure(r):
            r = np.asarray(r, dtype=float)
            return (interpolation_matrix(self.radii_a, r.ravel()) @ nodal).reshape(r.shape)[()]

        return pressure

    def compliance(self, eps: float, shear: bool = False) -> FECompliance:
        """The film compliance in the units of the half-space kernel; with ``shear`` also the
        gap opening per unit nodal squeeze-shear traction T (by sqrt(delta) times the film
        pressure unit, :meth:`ehdfem.film.reynolds.Film.squeeze_shear`) on both faces. The unit
        loads (hat pressures, then hat shear tractions) are condensed onto the contact faces on one
        process (:meth:`on_one_process`, :meth:`_condensed`)."""
        n = len(self.radii)
        arrays = cached_matrices(
            self.comm,
            ("axisymmetric", *self.cache_arguments, shear),
            self.cache_sources,
            lambda: self.on_one_process(lambda solids: solids._condensed(shear)),
        )
        return FECompliance(
            self, arrays["gap"][:, :n], eps, arrays.get("shear"), arrays["surface_sum"]
        )

    def on_one_process(self, compute):
        """``compute(solids)`` for these solids on one process: on themselves when serial;
        otherwise rank 0 builds the same solids on its own (MPI.COMM_SELF, the mesh from its
        cache) and broadcasts the result. Collective; an error on rank 0 is raised on all."""
        if self.comm.size == 1:
            return compute(self)
        result = error = None
        if self.comm.rank == 0:
            from mpi4py import MPI

            alone = FESolids(**self._inputs, comm=MPI.COMM_SELF)
            try:
                result = compute(alone)
            except Exception as err:  # noqa: BLE001 -- re-raised on every rank below
                error = err
            finally:
                alone.close()
        result, error = self.comm.bcast((result, error))
        if error is not None:
            raise error
        return result

    def _condensed(self, shear: bool) -> dict:
        """{"gap", "surface_sum"[, "shear"]}: the (N, N) unit matrices of :meth:`compliance` (in
        units of a p/E_ref per unit nodal load), on one process, from the stiffness condensed
        onto (:func:`ehdfem.solids.fe.condensation.condensed`) the loads (the hat pressures,
        then the hat shear tractions, on both faces), the read-outs (u_z of each face at the
        film nodes) and each free body's uniform d'Alembert body force w (its centre weights,
        which also read out its centre of mass: w . u)."""
        import scipy.sparse

        n = len(self.radii)
        both_faces = self._face_hats[0] + self._face_hats[1]
        kinds = {"pressure": 1.0, "shear": math.sqrt(self.delta)} if shear else {"pressure": 1.0}
        loads = [
            scale * (_scipy_matrix(self._tractions[kind]) @ both_faces)
            for kind, scale in kinds.items()
        ]
        read_outs = [self._face_read_out(tag) for tag in self._contact_tags]
        weights = scipy.sparse.csr_matrix(np.column_stack(self._centre_weights))
        columns = scipy.sparse.hstack([*loads, *read_outs, weights]).tolil()
        columns[self._constrained] = 0.0
        matrix = condensed(_scipy_matrix(self._stiffness), columns.tocsr())
        # blocks of K^-1 between the column groups: loads L, read-outs R, body weights W
        m = len(kinds) * n
        load, read, weight = slice(0, m), slice(m, m + 2 * n), slice(m + 2 * n, None)
        resultant = np.zeros(m)
        resultant[:n] = self._resultant @ both_faces
        directions = np.array([body.direction for body in self.bodies])
        # total load of column k: l_k + sum_b direction_b w_b resultant_k
        response = matrix[:, load] + np.outer(matrix[:, weight] @ directions, resultant)
        centres = [*response[weight], np.zeros(m)][:2]
        upper, lower = (response[read][k * n : (k + 1) * n] - centres[k] for k in range(2))
        gap, surface_sum = upper - lower, upper + lower
        arrays = {"gap": gap[:, :n], "surface_sum": surface_sum[:, :n]}
        if shear:
            arrays["shear"] = gap[:, n:]
        return arrays

    @property
    def _contact_tags(self):
        """The facet tags of the upper and the lower contact face."""
        return self._geometry.SPHERE_CONTACT, self._geometry.LOWER_CONTACT

    def _face_read_out(self, tag):
        """The sparse (unknowns, N) columns whose products with a displacement are its u_z at
        the film nodes on the contact face ``tag`` (linear between the face's dofs); on one
        process (a rank's own face dofs would not bracket every film node)."""
        import scipy.sparse

        rows, r = self._surface_rows[tag]
        r, first = np.unique(r, return_index=True)
        interpolation = interpolation_matrix(r, self.radii_a).T.tocoo()
        owned = self._space.dofmap.index_map.size_local * self._space.dofmap.index_map_bs
        return scipy.sparse.csr_matrix(
            (interpolation.data, (rows[first][interpolation.row], interpolation.col)),
            shape=(owned, len(self.radii)),
        )

    @cached_property
    def _centre_weights(self):
        """Per free body, the owned entries of the vector w with w.u = its centre-of-mass u_z."""
        from dolfinx import fem

        weights = []
        for body, volume in zip(self.bodies, self._volumes, strict=True):
            form = fem.form(self._test[1] * self._r * self._dx(body.cell_tag))
            vector = dolfinx_compat.assemble_vector(form, [])
            weights.append(vector.getArray() / volume)
        return weights

    @cached_property
    def _surface_rows(self):
        """Per contact face tag: the owned u_z rows of the solution vector and their r."""
        from dolfinx import fem

        space = self._space
        V1, _ = space.sub(1).collapse()
        owned = space.dofmap.index_map.size_local * space.dofmap.index_map_bs
        out = {}
        for tag in self._contact_tags:
            parent, child = fem.locate_dofs_topological(
                (space.sub(1), V1), 1, self._facet_tags.find(tag)
            )
            keep = parent < owned
            out[tag] = (parent[keep], V1.tabulate_dof_coordinates()[child[keep], 0])
        return out

    def deformation(self, nodal_pressure, eps: float) -> Deformation:
        """The solids under the film pressure with values ``nodal_pressure`` at the film nodes
        (by mu V0 a / x0^2) at elasticity parameter ``eps``: one solve; see
        :class:`Deformation` for the fields and their units."""
        self.displacement(nodal_pressure)
        vertices = self._vertex_mesh
        vertices.function.interpolate(self._u)
        values = vertices.function.x.array.reshape(-1, 2).copy()
        for body_vertices, centre in zip(vertices.body_vertices, self._centres(), strict=True):
            values[body_vertices, 1] -= centre
        return Deformation(
            points=vertices.points,
            triangles=vertices.triangles,
            displacement=_read_only(values * self.scale(eps)),
            upper=vertices.upper,
            **self._cell_stresses(),
        )

    @cached_property
    def _vertex_mesh(self) -> _VertexMesh:
        """This rank's P1 mesh (built once); see :class:`_VertexMesh`."""
        from dolfinx import fem

        space = dolfinx_compat.lagrange_space(self.mesh, 1, vector=True)
        cells, _, coordinates = dolfinx_compat.vtk_mesh(space)
        owned = self.mesh.topology.index_map(2).size_local
        body_vertices = [
            fem.locate_dofs_topological(space, 2, self._cell_tags.find(body.cell_tag))
            for body in self.bodies
        ]
        upper = np.zeros(len(coordinates), dtype=bool)
        upper[body_vertices[0]] = True
        return _VertexMesh(
            function=fem.Function(space),
            points=_read_only(coordinates[:, :2]),
            triangles=_read_only(cells.reshape(-1, 4)[:owned, 1:]),
            body_vertices=body_vertices,
            upper=_read_only(upper),
        )

    @cached_property
    def _stress_measures(self):
        """(DG0 function, {name: expression}, dofs of the owned cells) for the von Mises and
        hydrostatic stress of the current displacement (by the film pressure unit, as the
        displacement is by a p/E_ref), built once."""
        import ufl
        from dolfinx import fem

        space = dolfinx_compat.cell_space(self.mesh)
        sigma = self._stress(self._u)
        deviator = sigma - ufl.tr(sigma) / 3 * ufl.Identity(3)
        points = dolfinx_compat.interpolation_points(space)
        expressions = {
            "von_mises": fem.Expression(ufl.sqrt(1.5 * ufl.inner(deviator, deviator)), points),
            "hydrostatic": fem.Expression(ufl.tr(sigma) / 3, points),
        }
        owned = self.mesh.topology.index_map(2).size_local
        return fem.Function(space), expressions, dolfinx_compat.cell_dofs(space, owned)

    def _cell_stresses(self) -> dict:
        """{"von_mises": ..., "hydrostatic": ...} per owned cell for the current displacement."""
        field, expressions, dofs = self._stress_measures
        stresses = {}
        for name, expression in expressions.items():
            field.interpolate(expression)
            stresses[name] = _read_only(field.x.array[dofs])
        return stresses


class FECompliance(LinearCompliance):
    """Compliance of FE solids at the film nodes (the interface of :mod:`ehdfem.solids.compliance`):
    C = solids.scale(eps) * the condensed matrix of gap openings per unit nodal pressure.
    ``solids`` (the :class:`FESolids`) and ``eps`` are kept for the full fields
    (:meth:`FESolids.deformation`)."""

    model = "fem"

    def __init__(
        self,
        solids: FESolids,
        unit_matrix: np.ndarray,
        eps: float,
        unit_shear=None,
        unit_surface_sum=None,
    ):
        self.solids = solids
        super().__init__(solids.radii, unit_matrix, eps, unit_shear, unit_surface_sum)

    def factor(self, eps: float) -> float:
        """x0 per (a p / E_ref) at ``eps``: :meth:`FESolids.scale`."""
        return self.solids.scale(eps)

    def close(self) -> None:
        """Free the solids' factorisation (:meth:`FESolids.close`)."""
        self.solids.close()

    @property
    def surface_radii(self) -> tuple:
        """Radii of the upper sphere and the lower body, by a (math.inf for a wall)."""
        return self.solids.radius_upper, self.solids.radius_lower or math.inf
