"""Finite-element solids: axisymmetric linear elasticity (DOLFINx) condensed to the film nodes.

The upper sphere and the lower body (a wall block, a coated wall block, or a second sphere)
are meshed in (r, z) with gmsh (meshes/contact.py through :mod:`ehdfem.solids.fe.mesh`,
lengths by the (reduced) radius a) and solved with P2 Lagrange elements in the r-weighted
axisymmetric form (strain with the hoop term u_r / r). The hat pressure phi_j of film node j,
acting normally on both contact faces, is the load G_j = int phi_j (-n . v) r ds; the gap
opening at film node i is the same functional of the displacement divided by the film's lumped
weight m_i = int phi_i r dr (:attr:`ehdfem.solids.fe.meshed.MeshedBodies.film_weights`),

    W_i = G_i . u' / m_i,   u' = u - sum_b Z_b c_b,

the hat-weighted vertical motion of the true surfaces at fixed r (u_z - u_r dz/dr on each face,
u_z - u_r r/a on the sphere at leading order), the column j of the compliance matrix. A sphere
is a free body (:class:`ehdfem.solids.fe.bodies.FreeBody`): the vertical resultant Z_b . g of
any film load g on it is balanced by a uniform d'Alembert body force, g - w_b (Z_b . g) (Z_b its
rigid translation along z, w_b . v = its mean v_z), its far pole is pinned (u_z), and c_b = w_b
. u is its centre-of-mass displacement. A wall is clamped at its base, 40 radii below. Loads and
read-outs being the same balanced functionals, M C = G^T K^-1 G is symmetric (M = diag m): the
compliance is reciprocal to the solver's rounding, and 1/2 P . M C P is the elastic energy. The
squeeze-shear traction acts along each face's tangent (outward), read out likewise. All columns
come from one factorisation condensed onto the loads (:mod:`ehdfem.solids.fe.condensation`), on
one process.

Scales: stresses in units of E_ref (the upper sphere's modulus) make u come out in units of
a p / E_ref; the film pressure unit mu V0 a / x0^2 and the gap unit x0 turn this into the
dimensionless compliance of the half-space kernel,

    C = eps / (4 theta E_ref sqrt(delta)) * u_hat,   theta = sum (1 - nu^2)/(pi E)

over the sphere and the lower body (the substrate, for a coated wall), with film radii R (by
sqrt(a x0)) at r = R sqrt(delta) a. C scales linearly with eps: one factorisation serves a
whole (St, eps) sweep at fixed delta and materials.

The bodies (which lower body, its geometry and materials) are :mod:`ehdfem.solids.fe.bodies`,
their mesh and the film loads on it :mod:`ehdfem.solids.fe.meshed` (shared with the mode-1
solids); this module solves and condenses. Besides the compliance, :meth:`FESolids.deformation`
gives the whole solids under one film pressure (:mod:`ehdfem.solids.fe.fields`) for the field
exports (:mod:`ehdfem.outputs.fields`) and the pictures (:mod:`ehdfem.outputs.render`). Every
DOLFINx call goes through :mod:`ehdfem.fenicsx`.
"""

from __future__ import annotations

import inspect
import math
import sys
from functools import cached_property

import numpy as np

from ... import checks
from ...fenicsx import assembly, domain, functions, libraries, matrices, schur, spaces
from ...fenicsx.matrices import CholeskySolver, scipy_matrix
from ..compliance import LinearCompliance
from . import condensation, linear_algebra, meshed
from .bodies import LowerBody, Wall
from .condensation import RigidMotions, balanced_condensation
from .fields import Deformation, SolidsFields
from .linear_algebra import interpolation_matrix
from .mesh import cached_matrices
from .meshed import MeshedBodies

DEFAULT_BODY = Wall()
"""The lower body of the FE solids unless another is given: a wall block."""


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


class FESolids:
    """FE solids meshed for the film nodes ``radii`` (by sqrt(a x0)); see the module docstring.

    ``delta`` = x0/a. ``sphere`` and ``wall`` (the lower body's: a wall, a coated wall's
    substrate or a lower sphere) are (Young's modulus, Poisson ratio) pairs; only ratios of
    moduli matter. ``lower``: the body below the film, any
    :class:`ehdfem.solids.fe.bodies.LowerBody` (default a wall block; e.g. ``CoatedWall(0.1)``,
    ``LowerSphere(2.0)``). ``size``: the wall block's width and depth (by a); ``degree``: of
    the Lagrange elements. ``comm``: MPI communicator (default COMM_WORLD). ``meshed``: the
    :class:`ehdfem.solids.fe.meshed.MeshedBodies`. ``compliance(eps)`` gives the film
    compliance, ``deformation`` the whole solids.
    """

    def __init__(
        self,
        delta: float,
        radii,
        sphere=(1.0, 0.3),
        wall=(1.0, 0.3),
        lower: LowerBody = DEFAULT_BODY,
        size=40.0,
        degree=2,
        comm=None,
    ):
        if not isinstance(lower, LowerBody):
            raise checks.InputError(
                f"lower must be a lower body (a LowerBody such as Wall()), got {lower!r}", "lower"
            )
        from mpi4py import MPI

        self.comm = comm or MPI.COMM_WORLD
        self._inputs = dict(
            delta=delta, radii=radii, sphere=sphere, wall=wall, lower=lower, size=size
        )
        self.degree = degree
        self.meshed = MeshedBodies(delta, radii, sphere, wall, lower, size, self.comm)
        e_ref = self.meshed.sphere[0]
        self._theta_e_ref = sum(
            (1 - nu**2) * e_ref / (math.pi * e) for e, nu in (self.meshed.sphere, self.meshed.wall)
        )
        moduli = sorted(self.meshed.scaled_moduli.items())
        self.cache_arguments = (self.meshed.mesh_arguments, moduli, degree)
        self._assemble(degree)

    @property
    def delta(self) -> float:
        """x0/a."""
        return self.meshed.delta

    @property
    def radii(self) -> np.ndarray:
        """The film nodes, by sqrt(a x0)."""
        return self.meshed.radii

    @property
    def radii_a(self) -> np.ndarray:
        """The film nodes in units of a."""
        return self.meshed.radii_a

    @property
    def mesh(self):
        """The (r, z) mesh of both bodies, lengths by a."""
        return self.meshed.mesh

    @property
    def lower(self) -> LowerBody:
        """The lower body (:class:`ehdfem.solids.fe.bodies.LowerBody`)."""
        return self.meshed.lower

    @property
    def radius_upper(self) -> float:
        """The upper sphere's radius, by a."""
        return self.meshed.lower.sphere_radius

    @property
    def radius_lower(self) -> float | None:
        """The lower sphere's radius, by a (None for a wall)."""
        return self.meshed.lower.radius

    @property
    def free_bodies(self):
        """The free spheres (:class:`ehdfem.solids.fe.bodies.FreeBody`), the upper one first."""
        return self.meshed.free_bodies

    @property
    def cache_sources(self) -> list:
        """The code whose source keys the cached matrices of these solids (with
        ``cache_arguments``: the mesh generator's arguments, the scaled moduli per cell tag and
        the degree; :func:`ehdfem.solids.fe.mesh.cached_matrices`)."""
        modules = [sys.modules[__name__], meshed, linear_algebra, condensation]
        modules += [assembly, domain, functions, libraries, matrices, schur, spaces]
        return [*modules, type(self.meshed.lower), inspect.getmodule(self.meshed.build)]

    @property
    def dofs(self) -> int:
        """Number of displacement unknowns (both components, all ranks)."""
        return spaces.dof_count(self.space)

    def strain(self, v):
        """The strain of the displacement ``v`` (r-weighted axisymmetric form), as a 3x3 (r,
        theta, z) UFL tensor with the hoop strain u_r / r."""
        import ufl

        r = self.meshed.r
        grad = [[v[0].dx(0), 0, v[0].dx(1)], [0, v[0] / r, 0], [v[1].dx(0), 0, v[1].dx(1)]]
        return ufl.sym(ufl.as_tensor(grad))

    def stress(self, v):
        """The stress of the displacement ``v``, lambda tr(e) I + 2 mu e (UFL), by E_ref for
        a displacement by a."""
        import ufl

        lmbda, mu = self.meshed.lame
        return lmbda * ufl.tr(self.strain(v)) * ufl.Identity(3) + 2 * mu * self.strain(v)

    def _assemble(self, degree):
        """Assemble and set up the factorisation of the stiffness; the film load matrices, the
        lower face's resultant row and the rows the Dirichlet conditions fix (zero load)."""
        import ufl

        bodies = self.meshed
        V = self.space = spaces.lagrange_space(bodies.mesh, degree, vector=True)
        u, v = ufl.TrialFunction(V), ufl.TestFunction(V)
        self._test = v
        self._bcs = self._constraints()
        stiffness = assembly.assemble_matrix(
            assembly.form(ufl.inner(self.stress(u), self.strain(v)) * bodies.r * ufl.dx),
            self._bcs,
        )
        # symmetric positive definite once the constraints remove the rigid motions: Cholesky
        self._solver = CholeskySolver(stiffness, self.comm)
        n = ufl.FacetNormal(bodies.mesh)
        self._tractions = {
            "pressure": bodies.traction_matrix(-ufl.dot(n, v)),
            "shear": bodies.traction_matrix(ufl.dot(bodies.face_tangent(), v)),
        }
        self._u = functions.function(V)
        self._constrained = assembly.constrained_rows(
            assembly.form(v[0] * bodies.r * ufl.dx), self._bcs
        )

    def _constraints(self):
        """Dirichlet conditions: u_r = 0 on the axis, the lower body's clamped facets (a wall's
        base) and u_z = 0 at the far pole of each free body."""
        V, bodies = self.space, self.meshed
        axis = spaces.entity_dofs(V, 1, bodies.axis_facets, 0)
        bcs = [assembly.zero_condition(V, axis, 0)]
        if bodies.lower.clamped:
            clamped = spaces.entity_dofs(V, 1, bodies.clamped_facets)
            bcs.append(assembly.zero_condition(V, clamped))
        for body in self.free_bodies:
            pole = spaces.point_dofs(
                V, lambda p, z=body.pole_z: np.isclose(p[0], 0) & np.isclose(p[1], z), 1
            )
            bcs.append(assembly.zero_condition(V, pole, 1))
        return bcs

    def _film_loads(self, pressure: np.ndarray, shear: np.ndarray | None = None) -> np.ndarray:
        """The owned rows (rows, columns) of the loads of film pressures ``pressure`` (N,
        columns) at the film nodes, in the film pressure unit, normal on both contact faces,
        and of shear tractions ``shear`` (the same unit, along each face's outward tangent, on
        both faces; None: none), balanced on the free spheres (:meth:`_balanced`)."""
        bodies = self.meshed
        loads = bodies.traction_loads(
            self._tractions["pressure"], bodies.profile_values((pressure, pressure))
        )
        if shear is not None:
            loads += bodies.traction_loads(
                self._tractions["shear"], bodies.profile_values((shear,) * 2)
            )
        return self._balanced(loads)

    def _balanced(self, loads: np.ndarray) -> np.ndarray:
        """The load columns (owned rows) with each free body's vertical resultant Z_b . g
        balanced by its uniform d'Alembert body force, g - w_b (Z_b . g) (module docstring);
        zero on the constrained rows."""
        for body in self._free_motions:
            loads = body.balanced(loads, self.comm)
        loads[self._constrained] = 0.0
        return loads

    def displacement(self, nodal_pressure, nodal_shear=None):
        """Solve for the film pressure with values ``nodal_pressure`` (N,) at the film nodes, in
        the film pressure unit: normal pressure on both contact faces, d'Alembert body forces
        on free spheres; and a shear traction ``nodal_shear`` (the same unit, along each face's
        outward tangent; None: none) on both faces. Returns the displacement (a DOLFINx
        function, in units of a p/E_ref), also kept for :meth:`gap_opening`."""
        columns = [
            None if x is None else np.asarray(x, float)[:, None]
            for x in (nodal_pressure, nodal_shear)
        ]
        values = self._solver.solve(self._film_loads(*columns))
        functions.set_owned_values(self._u, values[:, 0])
        return self._u

    @property
    def displacement_function(self):
        """The DOLFINx function that :meth:`displacement` solves into (by a p/E_ref)."""
        return self._u

    def centres(self) -> list:
        """Centre-of-mass u_z (by a p/E_ref) of each free body for the current displacement,
        in the order of ``free_bodies``."""
        return [
            self.comm.allreduce(body.inertia[:, 0] @ functions.owned_values(self._u))
            for body in self._free_motions
        ]

    def gap_opening(self):
        """W (in units of a p/E_ref) at the film nodes for the current displacement: the
        pressure loads' read-outs G_i . u' / m_i of both faces, u' relative to the free
        bodies' centres (module docstring)."""
        values = functions.owned_values(self._u)[:, None]
        for body in self._free_motions:
            values = body.relative(values, self.comm)
        upper, lower = self.meshed.face_read_outs(self._tractions["pressure"], values)
        return (upper + lower)[:, 0] / self.meshed.film_weights

    def close(self) -> None:
        """Free the factorised stiffness (PETSc memory, a few hundred MB at production
        resolution, which Python's garbage collector does not return). Collective under MPI;
        the solids cannot solve afterwards. Studies that build many solids call it for each."""
        self._solver.close()

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
        loads (hat pressures, then hat shear tractions) are condensed onto the contact faces on
        one process (:meth:`on_one_process`, :meth:`_condensed`). With ``shear`` the faces'
        mean tangential displacement per unit pressure (``unit_surface_radial``) is passed on
        too: its rate carries liquid in the film (docs/model.md, "Tangential surface effects
        at order sqrt(delta)"); the one per unit shear is of second order there and, as on
        half-spaces, left out."""
        arrays = cached_matrices(
            self.comm,
            ("axisymmetric", *self.cache_arguments, shear),
            self.cache_sources,
            lambda: self.on_one_process(lambda solids: solids._condensed(shear)),
        )
        return FECompliance(
            self,
            arrays["gap"],
            eps,
            arrays.get("shear"),
            arrays["surface_sum"],
            arrays["radial_pressure"] if shear else None,
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

            alone = FESolids(**self._inputs, degree=self.degree, comm=MPI.COMM_SELF)
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
        """{"gap", "surface_sum", "radial_pressure", "radial_shear"[, "shear"]}: the (N, N)
        unit matrices of :meth:`compliance` (in units of a p/E_ref per unit nodal load, the
        shear loads by sqrt(delta) p), on one process, from the stiffness condensed onto the
        unit loads of each face, pressure and shear, balanced on the free bodies
        (:func:`ehdfem.solids.fe.condensation.balanced_condensation`): every block is a
        combination of the faces' read-outs of each other's loads, divided by the film weights
        m, symmetric once multiplied by them. "radial_*" is the mean of the two faces'
        tangential (outward) displacements per unit nodal pressure and shear traction."""
        import scipy.sparse

        n = len(self.radii)
        bodies = self.meshed
        faces = scipy.sparse.hstack(
            [
                scipy_matrix(self._tractions[kind]) @ hats
                for kind in ("pressure", "shear")
                for hats in bodies.face_hats
            ]
        )
        matrix = balanced_condensation(
            scipy_matrix(self._solver.matrix), faces, self._free_motions, self._constrained
        )
        # the film's loads and read-outs as combinations of the face columns: pressure on both
        # faces, shear on both faces (by sqrt(delta)), the surfaces' vertical motion (upper
        # minus lower face's pressure functional) and the faces' mean tangential motion
        unit = np.eye(n)
        combinations = np.zeros((4 * n, 4 * n))
        for k, weights in enumerate(([1, 1, 0, 0], [0, 0, 1, 1], [1, -1, 0, 0], [0, 0, 0.5, 0.5])):
            for face, weight in enumerate(weights):
                combinations[face * n : (face + 1) * n, k * n : (k + 1) * n] = weight * unit
        combinations[:, n : 2 * n] *= math.sqrt(self.delta)
        blocks = (combinations.T @ matrix @ combinations) / np.tile(bodies.film_weights, 4)[:, None]
        pressure, shears = slice(0, n), slice(n, 2 * n)
        arrays = {
            "gap": blocks[pressure, pressure],
            "surface_sum": blocks[2 * n : 3 * n, pressure],
            "radial_pressure": blocks[3 * n :, pressure],
            "radial_shear": blocks[3 * n :, shears],
        }
        if shear:
            arrays["shear"] = blocks[pressure, shears]
        return arrays

    @cached_property
    def _free_motions(self) -> list:
        """Per free body, its rigid translation along z on the owned rows, Z_b (1 on its u_z
        dofs, 0 elsewhere), with the vector w_b of its centre-of-mass u_z (w_b . u: the mean
        u_z over the body, w_b . Z_b = 1), as :class:`RigidMotions` (module docstring)."""
        motions, bodies = [], self.meshed
        for body in self.free_bodies:
            translation = functions.function(self.space)
            cells = domain.tagged(bodies.cell_tags, body.cell_tag)
            functions.interpolate(translation, lambda x: np.vstack([0 * x[0], 1 + 0 * x[0]]), cells)
            form = assembly.form(self._test[1] * bodies.r * bodies.dx(body.cell_tag))
            weights = assembly.assembled_values(form) / bodies.body_integral(1, body.cell_tag)
            motion = functions.owned_values(translation)[:, None].copy()
            motions.append(RigidMotions(motion, weights[:, None], np.eye(1)))
        return motions

    @cached_property
    def _fields(self) -> SolidsFields:
        return SolidsFields(self)

    def deformation(self, nodal_pressure, eps: float) -> Deformation:
        """The solids under the film pressure with values ``nodal_pressure`` at the film nodes
        (by mu V0 a / x0^2) at elasticity parameter ``eps``: one solve; see
        :class:`ehdfem.solids.fe.fields.Deformation` for the fields and their units."""
        return self._fields.deformation(nodal_pressure, eps)


class FECompliance(LinearCompliance):
    """Compliance of FE solids at the film nodes (the interface of :mod:`ehdfem.solids.compliance`):
    C = solids.scale(eps) * the condensed matrix of gap openings per unit nodal pressure.
    ``solids`` (the :class:`FESolids`) and ``eps`` are kept for the full fields
    (:meth:`FESolids.deformation`). ``unit_surface_radial`` (None: not applied): the mean
    tangential (outward) displacement of the two faces, (u_t(sphere) + u_t(lower)) / 2 at the
    film nodes, per unit nodal pressure, in units of a p / E_ref (times :meth:`factor` for x0),
    as the other unit matrices."""

    model = "fem"

    def __init__(
        self,
        solids: FESolids,
        unit_matrix: np.ndarray,
        eps: float,
        unit_shear=None,
        unit_surface_sum=None,
        unit_surface_radial=None,
    ):
        self.solids = solids
        super().__init__(
            solids.radii, unit_matrix, eps, unit_shear, unit_surface_sum, unit_surface_radial
        )

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
