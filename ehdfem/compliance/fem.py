"""Finite-element solids: axisymmetric linear elasticity (DOLFINx) condensed to the film nodes.

The upper sphere and the lower body (a wall block, a coated wall block, or a second sphere)
are meshed in (r, z) with gmsh (meshes/contact.py, lengths by the (reduced) radius a) and
solved with P2 Lagrange elements in the r-weighted axisymmetric form (strain with the hoop term
u_r / r). The stiffness is factorised once (LU); one solve per film node j, with the hat
pressure phi_j acting normally on both contact faces, gives the gap opening at every film
node i,

    W_i = (u_z^upper(r_i) - c_upper) - (u_z^lower(r_i) - c_lower),

the column j of the compliance matrix. A sphere is free: its film load is balanced by a
uniform d'Alembert body force, its far pole is pinned (u_z) to make the problem definite, and
c is its centre-of-mass displacement. A wall is clamped at its base, 40 radii below (c = 0).

Scales: stresses in units of E_ref (the upper sphere's modulus) make u come out in units of
a p / E_ref; the film pressure unit mu V0 a / x0^2 and the gap unit x0 turn this into the
dimensionless compliance of the half-space kernel,

    C = eps / (4 theta E_ref sqrt(delta)) * u_hat,   theta = sum (1 - nu^2)/(pi E)

over the sphere and the lower body (the substrate, for a coated wall), with film radii R (by
sqrt(a x0)) at r = R sqrt(delta) a. C scales linearly with eps: one factorisation serves a
whole (St, eps) sweep at fixed delta and materials.
"""

from __future__ import annotations

import contextlib
import hashlib
import math
import os
from pathlib import Path

import numpy as np

from .. import checks

LOWER_BODIES = ("wall", "coated", "sphere")


MESH_CACHE = Path(os.environ.get("EHDFEM_MESH_CACHE", Path.home() / ".cache" / "ehdfem" / "meshes"))


def _cached_mesh(gmsh, build, arguments) -> None:
    """Load the gmsh mesh for ``arguments`` from the cache, or build it and store it there
    (``EHDFEM_MESH_CACHE``, default ~/.cache/ehdfem/meshes; keyed by a hash of the arguments
    and of the generator's source, written atomically)."""
    import inspect

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


class FESolids:
    """FE solids meshed for the film nodes ``radii`` (by sqrt(a x0)); see the module docstring.

    ``delta`` = x0/a. ``sphere``, ``wall`` (the lower body: wall, substrate or lower sphere) and
    ``coating`` are (Young's modulus, Poisson ratio) pairs; only ratios of moduli matter.
    ``lower``: "wall", "coated" (``coating_thickness`` by a) or "sphere". For two spheres a is
    the reduced radius and ``radius_ratio`` = a1/a2 (upper over lower). ``comm``: MPI
    communicator (default COMM_WORLD). ``compliance(eps)`` gives the film compliance.
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
        import gmsh
        from dolfinx.io import gmshio
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
        self.radii = np.asarray(radii, dtype=float)
        limit = 0.7 * min(self.radius_upper, self.radius_lower or math.inf)
        if self.radii[-1] * math.sqrt(self.delta) >= limit:
            raise checks.InputError(
                f"the film reaches r = {self.radii[-1] * math.sqrt(self.delta):.3g} a; the FE "
                f"solids need it within half the smaller sphere radius ({limit:.3g} a)"
            )
        self.geometry = geometry
        gmsh.initialize()
        gmsh.option.setNumber("General.Terminal", 0)
        try:
            if self.comm.rank == 0:
                arguments = (
                    self.delta,
                    self.radii_a,
                    lower,
                    size,
                    self.radius_upper,
                    self.radius_lower or 1.0,
                    coating_thickness,
                )
                _cached_mesh(gmsh, geometry.build, arguments)
            self.mesh, self.cell_tags, self.facet_tags = gmshio.model_to_mesh(
                gmsh.model, self.comm, 0, gdim=2
            )
        finally:
            gmsh.finalize()
        e_ref = sphere[0]
        self.theta_e_ref = sum((1 - nu**2) * e_ref / (math.pi * e) for e, nu in (sphere, wall))
        materials = {geometry.SPHERE: sphere, geometry.LOWER: wall, geometry.COATING: coating}
        self._assemble({tag: (e / e_ref, nu) for tag, (e, nu) in materials.items()}, degree)

    @property
    def radii_a(self):
        """The film nodes in units of a."""
        return self.radii * math.sqrt(self.delta)

    def _assemble(self, materials, degree):
        import ufl
        from dolfinx import fem
        from petsc4py import PETSc

        geometry, msh = self.geometry, self.mesh
        V = self.V = fem.VectorFunctionSpace(msh, ("CG", degree))
        Q = fem.FunctionSpace(msh, ("DG", 0))
        young, poisson = fem.Function(Q), fem.Function(Q)
        for tag, (e, nu) in materials.items():
            cells = self.cell_tags.find(tag)
            young.x.array[cells], poisson.x.array[cells] = e, nu
        lmbda = young * poisson / ((1 + poisson) * (1 - 2 * poisson))
        mu = young / (2 * (1 + poisson))
        r = self.r = ufl.SpatialCoordinate(msh)[0]

        def strain(v):
            grad = [[v[0].dx(0), 0, v[0].dx(1)], [0, v[0] / r, 0], [v[1].dx(0), 0, v[1].dx(1)]]
            return ufl.sym(ufl.as_tensor(grad))

        def stress(v):
            return lmbda * ufl.tr(strain(v)) * ufl.Identity(3) + 2 * mu * strain(v)

        self.stress = stress
        u, v = ufl.TrialFunction(V), ufl.TestFunction(V)
        V0, _ = V.sub(0).collapse()
        V1, _ = V.sub(1).collapse()
        axis = np.concatenate(
            [self.facet_tags.find(t) for t in (geometry.SPHERE_AXIS, geometry.LOWER_AXIS)]
        )
        bcs = [
            fem.dirichletbc(
                fem.Function(V0), fem.locate_dofs_topological((V.sub(0), V0), 1, axis), V.sub(0)
            )
        ]
        self.bodies = [
            (geometry.SPHERE, geometry.SPHERE_CONTACT, 2 * self.radius_upper + self.delta, -1.0)
        ]
        if self.lower == "sphere":
            self.bodies.append(
                (geometry.LOWER, geometry.LOWER_CONTACT, -2 * self.radius_lower, 1.0)
            )
        else:
            base = fem.locate_dofs_topological(V, 1, self.facet_tags.find(geometry.LOWER_BOTTOM))
            bcs.append(fem.dirichletbc(np.zeros(2, dtype=PETSc.ScalarType), base, V))
        for _, _, pole_z, _ in self.bodies:
            pole = fem.locate_dofs_geometrical(
                (V.sub(1), V1), lambda p, z=pole_z: np.isclose(p[0], 0) & np.isclose(p[1], z)
            )
            bcs.append(fem.dirichletbc(fem.Function(V1), pole, V.sub(1)))
        self.bcs = bcs
        A = fem.petsc.assemble_matrix(
            fem.form(ufl.inner(stress(u), strain(v)) * r * ufl.dx), bcs=bcs
        )
        A.assemble()
        self.ksp = PETSc.KSP().create(self.comm)
        self.ksp.setOperators(A)
        self.ksp.setType("preonly")
        self.ksp.getPC().setType("lu")
        self.ksp.getPC().setFactorSolverType("mumps")
        dx = ufl.Measure("dx", domain=msh, subdomain_data=self.cell_tags)
        ds = ufl.Measure("ds", domain=msh, subdomain_data=self.facet_tags)
        n = ufl.FacetNormal(msh)
        self.pressure = fem.Function(fem.FunctionSpace(msh, ("CG", 2)))
        self.u = fem.Function(V)
        p = self.pressure
        self.resultant = fem.form(p * r * ds(geometry.LOWER_CONTACT))
        load = -p * ufl.dot(n, v) * r * (ds(geometry.SPHERE_CONTACT) + ds(geometry.LOWER_CONTACT))
        self.body_forces, self.volumes, self.centres = [], [], []
        for cell_tag, _, _, _ in self.bodies:
            force = fem.Constant(msh, np.zeros(2))
            self.body_forces.append(force)
            self.volumes.append(
                self.comm.allreduce(fem.assemble_scalar(fem.form(r * dx(cell_tag))))
            )
            self.centres.append(fem.form(self.u[1] * r * dx(cell_tag)))
            load = load + ufl.dot(force, v) * r * dx(cell_tag)
        self.load = fem.form(load)

    def displacement(self, pressure):
        """Displacement (in units of a p/E_ref) for a film pressure given as a callable of r
        (by a): normal pressure on both contact faces, d'Alembert body forces on free spheres."""
        from dolfinx import fem
        from petsc4py import PETSc

        self.pressure.interpolate(lambda x: pressure(x[0]))
        load = self.comm.allreduce(fem.assemble_scalar(self.resultant))
        for force, volume, (_, _, _, direction) in zip(
            self.body_forces, self.volumes, self.bodies, strict=True
        ):
            force.value[:] = (0.0, direction * load / volume)
        b = fem.petsc.assemble_vector(self.load)
        b.ghostUpdate(addv=PETSc.InsertMode.ADD, mode=PETSc.ScatterMode.REVERSE)
        fem.petsc.set_bc(b, self.bcs)
        self.ksp.solve(b, self.u.vector)
        self.u.x.scatter_forward()
        return self.u

    def _centres(self):
        """Centre-of-mass vertical displacement of each free sphere (0 for a clamped wall)."""
        from dolfinx import fem

        centres = [
            self.comm.allreduce(fem.assemble_scalar(form)) / volume
            for form, volume in zip(self.centres, self.volumes, strict=True)
        ]
        return centres + [0.0] * (2 - len(centres))

    def _surface(self, tag):
        """(r, u_z) at the dofs of a contact face, gathered from all ranks and sorted by r."""
        from dolfinx import fem

        V1, _ = self.V.sub(1).collapse()
        parent, child = fem.locate_dofs_topological(
            (self.V.sub(1), V1), 1, self.facet_tags.find(tag)
        )
        r = V1.tabulate_dof_coordinates()[child, 0]
        pairs = np.concatenate(self.comm.allgather(np.column_stack([r, self.u.x.array[parent]])))
        r, index = np.unique(pairs[:, 0], return_index=True)
        return r, pairs[index, 1]

    def gap_opening(self):
        """W (in units of a p/E_ref) at the film nodes for the current displacement."""
        upper, lower = self._centres()
        r_up, u_up = self._surface(self.geometry.SPHERE_CONTACT)
        r_lo, u_lo = self._surface(self.geometry.LOWER_CONTACT)
        return (np.interp(self.radii_a, r_up, u_up) - upper) - (
            np.interp(self.radii_a, r_lo, u_lo) - lower
        )

    def scale(self, eps: float) -> float:
        """x0 per (a p / E_ref): FE displacements to the gap unit (module docstring)."""
        return checks.positive("eps", eps) / (4 * self.theta_e_ref * math.sqrt(self.delta))

    def _film_pressure(self, nodal):
        """The film pressure with nodal values ``nodal`` as a function of r (by a)."""
        return lambda r: np.interp(r / math.sqrt(self.delta), self.radii, nodal, right=0.0)

    def compliance(self, eps: float) -> FECompliance:
        """The film compliance in the units of the half-space kernel; one solve per node."""
        unit = np.empty((len(self.radii), len(self.radii)))
        for j in range(len(self.radii)):
            self.displacement(self._film_pressure(np.eye(len(self.radii))[j]))
            unit[:, j] = self.gap_opening()
        return FECompliance(self.radii, self.scale(eps) * unit, self, eps)

    def write_fields(self, path, snapshots, eps: float, units=None) -> None:
        """XDMF time series (ParaView, meshio) of the solids under the film pressure.

        ``snapshots``: (time, nodal pressure) pairs, time by x0/V0 and pressure by mu V0 a/x0^2.
        Per instant: point field ``displacement`` (by x0; free spheres relative to their centre
        of mass) and cell fields ``von_mises`` and ``hydrostatic`` (by mu V0 a / x0^2; per cell,
        as the hoop strain u_r/r is 0/0 at vertices on the axis). The (r, z) mesh is by a. With
        ``units`` (:class:`ehdfem.scales.Scales`) everything is in SI instead: mesh and
        displacement in m, stresses in Pa, time in s. Gathered and written by rank 0.
        """
        import meshio
        import ufl
        from dolfinx import fem, plot

        cells_space = fem.FunctionSpace(self.mesh, ("DG", 0))
        vertices = fem.VectorFunctionSpace(self.mesh, ("CG", 1))
        displacement = fem.Function(vertices)
        sigma = self.stress(self.u)
        deviator = sigma - ufl.tr(sigma) / 3 * ufl.Identity(3)
        points = cells_space.element.interpolation_points()
        expressions = {
            "von_mises": fem.Expression(ufl.sqrt(1.5 * ufl.inner(deviator, deviator)), points),
            "hydrostatic": fem.Expression(ufl.tr(sigma) / 3, points),
        }
        stress_field = fem.Function(cells_space)
        body_dofs = [
            fem.locate_dofs_topological(vertices, 2, self.cell_tags.find(tag))
            for tag, *_ in self.bodies
        ]
        owned = self.mesh.topology.index_map(2).size_local
        topology, _, coordinates = plot.create_vtk_mesh(vertices)
        triangles = topology.reshape(-1, 4)[:owned, 1:]
        cell_dofs = cells_space.dofmap.list.array[:owned]
        length, gap, stress_unit, time_unit = (
            (units.sphere_radius, units.gap, units.pressure, units.time)
            if units
            else (1.0, 1.0, 1.0, 1.0)
        )
        local = {"points": coordinates[:, :2] * length, "triangles": triangles, "steps": []}
        for time, nodal in snapshots:
            self.displacement(self._film_pressure(nodal))
            displacement.interpolate(self.u)
            values = displacement.x.array.reshape(-1, 2).copy()
            for dofs, centre in zip(body_dofs, self._centres(), strict=False):
                values[dofs, 1] -= centre
            step = {"time": time * time_unit, "displacement": values * self.scale(eps) * gap}
            for name, expression in expressions.items():
                stress_field.interpolate(expression)
                step[name] = stress_field.x.array[cell_dofs] * stress_unit
            local["steps"].append(step)
        parts = self.comm.gather(local, root=0)
        if self.comm.rank != 0:
            return
        offsets = np.cumsum([0] + [len(p["points"]) for p in parts[:-1]])
        mesh_points = np.concatenate([p["points"] for p in parts])
        mesh_cells = np.concatenate(
            [p["triangles"] + o for p, o in zip(parts, offsets, strict=True)]
        )
        path = Path(path).resolve()
        path.parent.mkdir(parents=True, exist_ok=True)
        # meshio 5.0 (Debian) writes the .h5 beside the working directory: write from path's folder
        with contextlib.chdir(path.parent), meshio.xdmf.TimeSeriesWriter(path.name) as writer:
            writer.write_points_cells(mesh_points, [("triangle", mesh_cells)])
            for k, step in enumerate(parts[0]["steps"]):
                merged = {
                    name: np.concatenate([p["steps"][k][name] for p in parts])
                    for name in ("displacement", "von_mises", "hydrostatic")
                }
                writer.write_data(
                    step["time"],
                    point_data={"displacement": merged["displacement"]},
                    cell_data={name: [merged[name]] for name in expressions},
                )


class FECompliance:
    """Compliance matrix of FE solids at the film nodes (same interface as the half-space);
    ``solids`` and ``eps`` are kept for writing the full fields."""

    def __init__(self, radii, matrix, solids=None, eps=None):
        self.radii, self.matrix, self.solids, self.eps = radii, matrix, solids, eps

    def deflection(self, pressure):
        """Gap opening W (by x0) for nodal pressures P (by mu V0 a / x0^2)."""
        return self.matrix @ np.asarray(pressure, dtype=float)
