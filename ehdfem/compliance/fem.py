"""Finite-element solids: axisymmetric linear elasticity (DOLFINx) condensed to the film nodes.

The sphere and the wall block are meshed in (r, z) with gmsh (meshes/sphere_wall.py, lengths
by the sphere radius a) and solved with P2 Lagrange elements in the r-weighted axisymmetric
form (strain with the hoop term u_r / r). The stiffness is factorised once (LU); then one solve
per film node j with the hat pressure phi_j acting normally on both contact faces gives the gap
opening at every film node i,

    W_i = (u_z^sphere(r_i) - u_z^sphere centre of mass) - u_z^wall(r_i),

the column j of the compliance matrix. The sphere is free: its film load is balanced by the
uniform d'Alembert body force, and its rigid translation is removed by measuring relative to
its centre of mass (one point is pinned to make the problem definite). The wall's bottom face
is clamped, 40 radii below the contact.

Scales: with stresses in units of E_ref (here E_ref = the sphere's Young's modulus) the FE
solve gives u in units of a p / E_ref; the film pressure unit mu V0 a / x0^2 and the gap unit
x0 turn this into the same dimensionless compliance as the half-space kernel,

    C = eps / (4 theta E_ref sqrt(delta)) * u_hat,   theta = sum (1 - nu^2)/(pi E),

with film radii R (by sqrt(a x0)) at r = R sqrt(delta) a. The matrix scales linearly with eps,
so one factorisation serves a whole (St, eps) sweep at fixed delta and materials.
"""

from __future__ import annotations

import math

import numpy as np

from .. import checks


def _import_fenicsx():
    import dolfinx
    import dolfinx.fem.petsc  # noqa: F401
    import gmsh
    import ufl
    from dolfinx.io import gmshio
    from mpi4py import MPI
    from petsc4py import PETSc

    return dolfinx, gmsh, ufl, gmshio, MPI, PETSc


class FESolids:
    """Elastic sphere + wall block meshed for the film nodes ``radii`` (by sqrt(a x0)).

    ``delta`` = x0/a; ``sphere`` and ``wall`` are (Young's modulus, Poisson ratio) pairs (only
    the ratio of the moduli matters); ``comm``: MPI communicator (default COMM_WORLD). The film
    radii are mesh vertices of both contact faces; ``compliance(eps)`` gives the compliance.
    """

    def __init__(
        self,
        delta: float,
        radii,
        sphere=(1.0, 0.3),
        wall=(1.0, 0.3),
        size: float = 40.0,
        degree: int = 2,
        comm=None,
    ):
        dolfinx, gmsh, ufl, gmshio, MPI, PETSc = _import_fenicsx()
        self.delta = checks.number(
            "delta", delta, lower=0.0, upper=1.0, lower_open=True, upper_open=True
        )
        for name, (e, nu) in (("sphere", sphere), ("wall", wall)):
            checks.positive(f"{name} Young's modulus", e)
            checks.number(
                f"{name} Poisson ratio", nu, lower=-1.0, upper=0.5, lower_open=True, upper_open=True
            )
        self.comm = comm or MPI.COMM_WORLD
        self.radii = np.asarray(radii, dtype=float)
        if self.radii[-1] * math.sqrt(self.delta) >= 0.5:
            raise checks.InputError(
                f"the film reaches r = {self.radii[-1] * math.sqrt(self.delta):.3g} a; the FE "
                "solids need it within half the sphere radius (outer film radius < 0.5/sqrt(delta))"
            )
        from meshes import sphere_wall as geometry

        self.geometry = geometry
        gmsh.initialize()
        gmsh.option.setNumber("General.Terminal", 0)
        try:
            if self.comm.rank == 0:
                geometry.build(self.delta, self.radii * math.sqrt(self.delta), size)
            self.mesh, self.cell_tags, self.facet_tags = gmshio.model_to_mesh(
                gmsh.model, self.comm, 0, gdim=2
            )
        finally:
            gmsh.finalize()
        e_ref = sphere[0]
        self.theta_e_ref = sum((1 - nu**2) * e_ref / (math.pi * e) for e, nu in (sphere, wall))
        self._assemble(dolfinx, ufl, PETSc, sphere, wall, degree)

    def _assemble(self, dolfinx, ufl, PETSc, sphere, wall, degree):
        from dolfinx import fem

        msh, geometry = self.mesh, self.geometry
        V = fem.VectorFunctionSpace(msh, ("CG", degree))
        self.V = V
        Q = fem.FunctionSpace(msh, ("DG", 0))
        young, poisson = fem.Function(Q), fem.Function(Q)
        for tag, (e, nu) in ((geometry.SPHERE, sphere), (geometry.WALL, wall)):
            cells = self.cell_tags.find(tag)
            young.x.array[cells] = e / sphere[0]
            poisson.x.array[cells] = nu
        lmbda = young * poisson / ((1 + poisson) * (1 - 2 * poisson))
        mu = young / (2 * (1 + poisson))
        x = ufl.SpatialCoordinate(msh)
        self.r = r = x[0]

        def strain(v):
            return ufl.sym(
                ufl.as_tensor(
                    [[v[0].dx(0), 0, v[0].dx(1)], [0, v[0] / r, 0], [v[1].dx(0), 0, v[1].dx(1)]]
                )
            )

        def stress(v):
            return lmbda * ufl.tr(strain(v)) * ufl.Identity(3) + 2 * mu * strain(v)

        self.stress = stress
        u, v = ufl.TrialFunction(V), ufl.TestFunction(V)
        self.v = v
        a = fem.form(ufl.inner(stress(u), strain(v)) * r * ufl.dx)
        fdim = msh.topology.dim - 1
        bcs = []
        V0, _ = V.sub(0).collapse()
        V1, _ = V.sub(1).collapse()
        for tag in (geometry.SPHERE_AXIS, geometry.WALL_AXIS):
            dofs = fem.locate_dofs_topological((V.sub(0), V0), fdim, self.facet_tags.find(tag))
            bcs.append(fem.dirichletbc(fem.Function(V0), dofs, V.sub(0)))
        dofs = fem.locate_dofs_topological(V, fdim, self.facet_tags.find(geometry.WALL_BOTTOM))
        bcs.append(fem.dirichletbc(np.zeros(2, dtype=PETSc.ScalarType), dofs, V))
        top = 2.0 + self.delta
        pole = fem.locate_dofs_geometrical(
            (V.sub(1), V1), lambda p: np.isclose(p[0], 0.0) & np.isclose(p[1], top)
        )
        bcs.append(fem.dirichletbc(fem.Function(V1), pole, V.sub(1)))
        self.bcs = bcs
        A = fem.petsc.assemble_matrix(a, bcs=bcs)
        A.assemble()
        self.ksp = PETSc.KSP().create(self.comm)
        self.ksp.setOperators(A)
        self.ksp.setType("preonly")
        self.ksp.getPC().setType("lu")
        self.ksp.getPC().setFactorSolverType("mumps")
        self.dx = ufl.Measure("dx", domain=msh, subdomain_data=self.cell_tags)
        self.ds = ufl.Measure("ds", domain=msh, subdomain_data=self.facet_tags)
        self.normal = ufl.FacetNormal(msh)
        self.sphere_volume = self._integrate(r * self.dx(geometry.SPHERE))
        self._load_form()

    def _integrate(self, expression) -> float:
        from dolfinx import fem

        return self.comm.allreduce(fem.assemble_scalar(fem.form(expression)))

    def _load_form(self):
        """The linear form of a film pressure p (a CG2 function of r) and its body force."""
        import ufl
        from dolfinx import fem

        geometry = self.geometry
        self.pressure = fem.Function(fem.FunctionSpace(self.mesh, ("CG", 2)))
        self.body = fem.Constant(self.mesh, np.zeros(2))
        p, n, v, r = self.pressure, self.normal, self.v, self.r
        self.load = fem.form(
            -p * ufl.dot(n, v) * r * self.ds(geometry.SPHERE_CONTACT)
            - p * ufl.dot(n, v) * r * self.ds(geometry.WALL_CONTACT)
            + ufl.dot(self.body, v) * r * self.dx(geometry.SPHERE)
        )
        self.resultant = fem.form(p * r * self.ds(geometry.WALL_CONTACT))
        self.u = fem.Function(self.V)
        self.centre = fem.form(self.u[1] * r * self.dx(geometry.SPHERE))

    def displacement(self, pressure):
        """Displacement (in units of a p/E_ref) for a film pressure given as a callable of r
        (by a): normal pressure on both contact faces, d'Alembert body force on the sphere."""
        from dolfinx import fem
        from petsc4py import PETSc

        self.pressure.interpolate(lambda x: pressure(x[0]))
        load = self.comm.allreduce(fem.assemble_scalar(self.resultant))
        self.body.value[:] = (0.0, -load / self.sphere_volume)
        b = fem.petsc.assemble_vector(self.load)
        b.ghostUpdate(addv=PETSc.InsertMode.ADD, mode=PETSc.ScatterMode.REVERSE)
        fem.petsc.set_bc(b, self.bcs)
        self.ksp.solve(b, self.u.vector)
        self.u.x.scatter_forward()
        return self.u

    def _surface(self, u, tag):
        """(r, u_z) at the dofs of a contact face, gathered from all ranks and sorted by r."""
        from dolfinx import fem

        V1, _ = self.V.sub(1).collapse()
        facets = self.facet_tags.find(tag)
        parent, child = fem.locate_dofs_topological((self.V.sub(1), V1), 1, facets)
        r = V1.tabulate_dof_coordinates()[child, 0]
        pairs = np.concatenate(self.comm.allgather(np.column_stack([r, u.x.array[parent]])))
        r, index = np.unique(pairs[:, 0], return_index=True)
        return r, pairs[index, 1]

    def gap_opening(self, u, radii_a):
        """W (in units of a p/E_ref) at radii r (by a): sphere surface relative to the sphere's
        centre of mass, minus the wall surface."""
        from dolfinx import fem

        geometry = self.geometry
        self.u.x.array[:] = u.x.array
        centre = self.comm.allreduce(fem.assemble_scalar(self.centre)) / self.sphere_volume
        r_s, u_s = self._surface(u, geometry.SPHERE_CONTACT)
        r_w, u_w = self._surface(u, geometry.WALL_CONTACT)
        return (np.interp(radii_a, r_s, u_s) - centre) - np.interp(radii_a, r_w, u_w)

    def compliance(self, eps: float) -> FECompliance:
        """The film compliance on the film nodes in the units of the half-space kernel (see the
        module docstring); one solve per film node."""
        radii = self.radii
        unit = np.empty((len(radii), len(radii)))
        for j in range(len(radii)):
            hat = np.zeros(len(radii))
            hat[j] = 1.0
            unit[:, j] = self.gap_opening(self.displacement(self._film_pressure(hat)), self.radii_a)
        return FECompliance(radii, self.scale(eps) * unit, self, eps)

    @property
    def radii_a(self):
        """The film nodes in units of the sphere radius."""
        return self.radii * math.sqrt(self.delta)

    def scale(self, eps: float) -> float:
        """x0 per (a p / E_ref): FE displacements to the gap unit (module docstring)."""
        return checks.positive("eps", eps) / (4 * self.theta_e_ref * math.sqrt(self.delta))

    def _film_pressure(self, nodal):
        """The film pressure with nodal values ``nodal`` as a function of r (by a)."""
        scale = math.sqrt(self.delta)
        return lambda r: np.interp(r / scale, self.radii, nodal, right=0.0)

    def write_fields(self, path, snapshots, eps: float) -> None:
        """XDMF (ParaView) of the solids under the film pressure at several instants.

        ``snapshots``: (time, nodal pressure) pairs, time by x0/V0 and pressure by mu V0 a/x0^2.
        Written per instant: ``displacement`` (by x0), ``von_mises`` and ``hydrostatic`` stress
        (by mu V0 a / x0^2, one value per cell); the mesh is in units of the sphere radius a,
        axisymmetric (r, z).
        Each field is the displacement relative to the sphere's centre of mass in the sphere.
        """
        import ufl
        from dolfinx import fem, io

        W = fem.FunctionSpace(
            self.mesh, ("DG", 0)
        )  # cell values: the hoop strain u_r/r is 0/0 on the axis
        V1 = fem.VectorFunctionSpace(self.mesh, ("CG", 1))
        displacement, von_mises, hydrostatic = fem.Function(V1), fem.Function(W), fem.Function(W)
        displacement.name, von_mises.name, hydrostatic.name = (
            "displacement",
            "von_mises",
            "hydrostatic",
        )
        sigma = self.stress(self.u)
        deviator = sigma - ufl.tr(sigma) / 3 * ufl.Identity(3)
        points = W.element.interpolation_points()
        expressions = (
            fem.Expression(ufl.sqrt(1.5 * ufl.inner(deviator, deviator)), points),
            fem.Expression(ufl.tr(sigma) / 3, points),
        )
        sphere_dofs = fem.locate_dofs_topological(V1, 2, self.cell_tags.find(self.geometry.SPHERE))
        with io.XDMFFile(self.comm, str(path), "w") as xdmf:
            xdmf.write_mesh(self.mesh)
            for time, nodal in snapshots:
                u = self.displacement(self._film_pressure(nodal))
                centre = self.comm.allreduce(fem.assemble_scalar(self.centre)) / self.sphere_volume
                displacement.interpolate(u)
                displacement.x.array[:] *= self.scale(eps)
                displacement.x.array.reshape(-1, 2)[sphere_dofs, 1] -= centre * self.scale(eps)
                von_mises.interpolate(expressions[0])
                hydrostatic.interpolate(expressions[1])
                for field in (displacement, von_mises, hydrostatic):
                    xdmf.write_function(field, time)


class FECompliance:
    """Compliance matrix of FE solids at the film nodes (same interface as the half-space);
    ``solids`` and ``eps`` are kept for writing the full fields."""

    def __init__(self, radii, matrix, solids=None, eps=None):
        self.radii, self.matrix, self.solids, self.eps = radii, matrix, solids, eps

    def deflection(self, pressure):
        """Gap opening W (by x0) for nodal pressures P (by mu V0 a / x0^2)."""
        return self.matrix @ np.asarray(pressure, dtype=float)
