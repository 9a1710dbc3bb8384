"""Mode-1 (cos phi) FE solids: the film's azimuthal loads condensed to the film nodes.

An oblique collision loads both solids with a film pressure q(R) cos phi and shear tractions
t_r = A(R) cos phi, t_phi = -B(R) sin phi (:class:`ehdfem.solids.compliance.ModeOneCompliance`). On
the (r, z) meshes of :class:`ehdfem.solids.fe.solids.FESolids` the displacement they cause is

    (u_r, u_phi, u_z) = (U_r(r, z) cos phi, -U_phi(r, z) sin phi, U_z(r, z) cos phi).

With d/dphi replaced by the mode number, the strains are e_ij = E_ij cos phi for
ij = rr, phiphi, zz, rz and e_ij = -E_ij sin phi for ij = rphi, phiz, with the amplitudes

    E_rr = U_r,r,  E_phiphi = (U_r - U_phi)/r,  E_zz = U_z,z,  2 E_rz = U_r,z + U_z,r,
    2 E_rphi = U_phi,r + (U_r - U_phi)/r,  2 E_phiz = U_phi,z + U_z/r.

An isotropic stress does not mix the cos and sin families, and cos^2 and sin^2 both integrate
to pi over phi, so the strain energy is pi times int sigma(E) : E r dr dz; the loads' work
carries the same pi (int t.v dphi = pi (A V_r + B V_phi + T V_z)), which cancels. On the axis
the displacement must be one vector: u_x = U_r cos^2 + U_phi sin^2, u_y = (U_r - U_phi)
sin cos and u_z = U_z cos do not depend on phi only if U_r = U_phi and U_z = 0 there. The
unknowns are therefore S = (U_r + U_phi)/2, D = (U_r - U_phi)/2 and U_z, and the axis
conditions are the exact Dirichlet conditions D = 0, U_z = 0 on the axis facets.

Loads, on both contact faces, each a nodal profile on the film nodes (hat functions, zero beyond
the last node): the pressure q cos phi acts normally on each face, as in FESolids (traction
-q n cos phi, n the outward normal: t_z = +q cos phi on the sphere and -q cos phi on the wall,
up to the face's slope r/a); the shear amplitudes A along r and B along phi. Each face's
displacements at film node i are read in these load directions, G_i . u / m_i with G_i the
load of the hat i on that face and m_i the film's lumped weight
(:class:`ehdfem.solids.fe.meshed.MeshedBodies`): U_r and U_phi hat-averaged, and the normal one
as the surface's vertical motion U_z - U_r dz/dr. Loads and read-outs being the same balanced
functionals, the 5N x 5N matrix of the loads against their own directions (the pressure against
the gap opening sphere_normal - wall_normal, each shear against its face's displacement in its
direction) times diag(m), with the shear loads' sqrt(delta) divided out, is symmetric to the
solver's rounding (Betti; docs/fem.md).

Mode 1 holds two rigid motions of a free sphere: the translation along x (S = 1, D = U_z = 0)
and the rotation about y through the centre of mass z_c (S = z - z_c, D = 0, U_z = -r). The
film load of a free sphere is balanced by the d'Alembert body force of the rigid acceleration
its net x-force and y-moment cause (uniform density): with R_k the two motions and m_k the
vectors of int R_k . v r dx, the load b becomes b - sum_k m_k c_k with G c = (R_k . b),
G_kl = int R_k . R_l r dx. Pins (S at the far pole, U_z on the equator ring) then remove the
rigid motions without carrying any force, and the sphere's displacement is reported relative
to its rigid motion, u - sum_k R_k c_k with G c = (m_k . u): the mass-weighted mean translation
and mean rotation about the centre of mass. A wall is clamped at its base.

Every entry of the unit matrix is such a read-out of such a balanced load, both combinations of
the 6N face loads (each face's pressure, radial and hoop hats) and the sphere's two vectors
m_k. The stiffness bordered by them is factorised once by MUMPS, whose Schur complement on the
border gives all entries at once (:func:`ehdfem.solids.fe.condensation.balanced_condensation`,
shared with the axisymmetric build); PETSc forms it on one process only, so under MPI rank 0
builds the same solids alone and broadcasts the matrix, which is then the same bits on any
number of ranks. A face's load moves only its own body, so each face's read-outs are taken of
its own face's loads. :meth:`FEModeOne.field` solves the distributed solids instead.

The mesh, materials, free bodies, contact faces and traction profiles are those of the
axisymmetric solids (:class:`ehdfem.solids.fe.meshed.MeshedBodies`, ``solids.meshed``).

Scales as in :mod:`ehdfem.solids.fe.solids`: stresses by E_ref, displacements by a p / E_ref for
tractions by p, where p is the film pressure unit mu V0 a / x0^2 for the pressure and
sqrt(delta) times it for the shear tractions; ``factor(eps)`` = :meth:`FESolids.scale` turns
them into x0. Film radii R by sqrt(a x0), at r = R sqrt(delta) a on the mesh.
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from ... import checks
from ...fenicsx import assembly, domain, functions, matrices, spaces
from ...fenicsx.matrices import CholeskySolver, scipy_matrix
from ..compliance import MODE_ONE_LOADS, ModeOneCompliance
from .condensation import RigidMotions, balanced_condensation
from .mesh import cached_matrices
from .solids import FESolids

DEGREE = 2  # of the Lagrange elements
QUADRATURE_DEGREE = 9
"""Of the stiffness integrand: products of P2 strain amplitudes (with the 1/r terms) times r and
the moduli. UFL would estimate 7 for moduli constant per cell; 9 is the degree the mode-1
compliance was validated with (tests/test_fem_mode_one.py) and stored with (the regression
table, tests/test_regression.py), so it is fixed here."""
TRACTIONS = ("pressure", "radial", "hoop")
"""The load kinds: the same nodal profile (or each face its own) on both faces."""


def mode_one_space(mesh):
    """The P2 space of the unknowns (S, D, U_z) (module docstring) on the (r, z) ``mesh``."""
    return spaces.lagrange_space(mesh, DEGREE, vector=True, components=3)


def amplitudes(unknowns):
    """(U_r, U_phi, U_z) of the unknowns (S, D, U_z): U_r = S + D, U_phi = S - D (UFL)."""
    import ufl

    return ufl.as_vector((unknowns[0] + unknowns[1], unknowns[0] - unknowns[1], unknowns[2]))


def strain(unknowns, r):
    """The mode-1 strain amplitudes E (module docstring; the rphi and phiz entries are those
    of -sin phi) of the unknowns (S, D, U_z), a symmetric 3x3 UFL tensor in the order (r, phi,
    z); ``r`` the radial coordinate (UFL)."""
    import ufl

    u_r, u_phi, u_z = (amplitudes(unknowns)[k] for k in range(3))
    hoop = 2 * unknowns[1] / r  # (U_r - U_phi) / r
    rz = (u_r.dx(1) + u_z.dx(0)) / 2
    r_phi = (u_phi.dx(0) + hoop) / 2
    phi_z = (u_phi.dx(1) + u_z / r) / 2
    return ufl.as_tensor([[u_r.dx(0), r_phi, rz], [r_phi, hoop, phi_z], [rz, phi_z, u_z.dx(1)]])


def stress(strain_amplitudes, lame):
    """Isotropic stress amplitudes lambda tr(E) I + 2 mu E; ``lame`` = (lambda, mu)."""
    import ufl

    lmbda, mu = lame
    return lmbda * ufl.tr(strain_amplitudes) * ufl.Identity(3) + 2 * mu * strain_amplitudes


def stiffness_form(space, lame):
    """The bilinear form int sigma(E(u)) : E(v) r dr dz on ``space`` (:func:`mode_one_space`),
    the mode-1 strain energy divided by pi/2 (UFL; ``lame`` = (lambda, mu) by E_ref), with
    QUADRATURE_DEGREE."""
    import ufl

    r = ufl.SpatialCoordinate(spaces.mesh_of(space))[0]
    u, v = ufl.TrialFunction(space), ufl.TestFunction(space)
    dx = ufl.dx(metadata={"quadrature_degree": QUADRATURE_DEGREE})
    return ufl.inner(stress(strain(u, r), lame), strain(v, r)) * r * dx


def zero_condition(space, component: int, dofs):
    """A homogeneous Dirichlet condition on unknown ``component`` (0: S, 1: D, 2: U_z) of
    ``space`` at ``dofs``, the pair (parent, collapsed) of a
    :func:`ehdfem.fenicsx.spaces.entity_dofs` or ``point_dofs`` call with that
    component; returns (condition, owned rows of the solution vector)."""
    parent = dofs[0]
    owned = spaces.owned_dof_count(space)
    return assembly.zero_condition(space, dofs, component), parent[parent < owned]


def axis_conditions(space, axis_facets):
    """The axis regularity conditions D = 0 and U_z = 0 on the facets ``axis_facets`` (r = 0):
    a list of (condition, owned rows), as :func:`zero_condition`."""
    return [zero_condition(space, k, spaces.entity_dofs(space, 1, axis_facets, k)) for k in (1, 2)]


def rigid_motions(space, cells, centre_z: float):
    """The x translation and the rotation about y through z = ``centre_z`` (by a) as functions
    of the unknowns (S, D, U_z) on ``space``, zero outside ``cells``: (1, 0, 0) and
    (z - z_c, 0, -r), per unit displacement and per unit angle."""
    translation, rotation = functions.function(space), functions.function(space)
    functions.interpolate(
        translation, lambda x: np.vstack([np.ones_like(x[0]), 0 * x[0], 0 * x[0]]), cells
    )
    functions.interpolate(rotation, lambda x: np.vstack([x[1] - centre_z, 0 * x[0], -x[0]]), cells)
    return translation, rotation


@dataclass(frozen=True)
class _Assembly:
    """The assembled mode-1 solids on their communicator: the stiffness's ``solver`` (MUMPS
    Cholesky, factorised on its first solve), the ``tractions`` matrices per load kind of
    TRACTIONS, the ``free_bodies``' rigid motions and the ``constrained`` owned rows."""

    solver: CholeskySolver
    tractions: dict
    free_bodies: list
    constrained: np.ndarray


class FEModeOne(ModeOneCompliance):
    """Mode-1 compliance of FE solids (:class:`ehdfem.solids.compliance.ModeOneCompliance`) on the
    mesh of ``solids`` (a :class:`FESolids`, whose materials, free bodies and film nodes it shares),
    at ``eps``; see the module docstring. The unit matrix comes from one factorisation of the
    stiffness bordered by the 6N face loads (the pressure, radial and hoop hats j on each face)
    and the free sphere's d'Alembert forces: its Schur complement holds every face's read-out
    of every balanced face load (:func:`ehdfem.solids.fe.condensation.balanced_condensation`),
    on one process (:meth:`FESolids.on_one_process`), as the axisymmetric build. ``space``: the
    P2 space of the unknowns (S, D, U_z) on that mesh. :meth:`field` gives the whole solids
    under given nodal loads (distributed solves); :meth:`close` frees their factorisation (its
    own, besides the solids' axisymmetric one)."""

    model = "fem"

    def __init__(self, solids: FESolids, eps: float):
        if not isinstance(solids, FESolids):
            raise checks.InputError(f"solids must be FESolids, got {type(solids).__name__}")
        checks.positive("eps", eps)
        self._build(solids)
        unit = cached_matrices(
            solids.comm,
            ("mode one", *solids.cache_arguments),
            [sys.modules[__name__], *solids.cache_sources],
            lambda: {"unit": self._condense()},
        )["unit"]
        super().__init__(solids.radii, unit, eps)

    def _build(self, solids: FESolids) -> None:
        """The space on the mesh of ``solids``; the stiffness, loads and free bodies are
        assembled on first use (:attr:`_assembly`: a distributed build condensed on rank 0
        alone needs them only for :meth:`field`)."""
        self.solids = solids
        self.space = mode_one_space(solids.mesh)

    def factor(self, eps: float) -> float:
        """x0 per (a p / E_ref) at ``eps``: :meth:`FESolids.scale`."""
        return self.solids.scale(eps)

    def close(self) -> None:
        """Free the factorised stiffness and the traction matrices (PETSc memory that Python's
        garbage collector does not return), if assembled. Collective under MPI; no solves
        afterwards."""
        if "_assembly" in self.__dict__:
            self._assembly.solver.close()
            matrices.free(*self._assembly.tractions.values())

    @cached_property
    def _assembly(self) -> _Assembly:
        """Assemble the stiffness and set up its factorisation (MUMPS Cholesky, made on the
        first solve: it is symmetric positive definite once pinned); set up the traction
        matrices and the free bodies. Collective."""
        conditions = self._constraints()
        stiffness = assembly.assemble_matrix(
            assembly.form(stiffness_form(self.space, self.solids.meshed.lame)),
            [bc for bc, _ in conditions],
        )
        return _Assembly(
            CholeskySolver(stiffness, self.solids.comm),
            self._traction_matrices(),
            [self._free_body(body.cell_tag) for body in self.solids.free_bodies],
            np.concatenate([rows for _, rows in conditions]),
        )

    def _constraints(self):
        """(condition, owned rows) pairs: the axis conditions, the lower body's clamped facets
        (all three unknowns: a wall's base) and, for each free sphere, S = 0 at its far pole
        and U_z = 0 at its equator (which fix its translation and rotation)."""
        bodies, space = self.solids.meshed, self.space
        conditions = axis_conditions(space, bodies.axis_facets)
        if bodies.lower.clamped:
            clamped = bodies.clamped_facets
            conditions += [
                zero_condition(space, k, spaces.entity_dofs(space, 1, clamped, k)) for k in range(3)
            ]
        for body in bodies.free_bodies:
            for k, (r, z) in ((0, (0.0, body.pole_z)), (2, (body.radius, body.centre_z))):
                dofs = spaces.point_dofs(
                    space, lambda x, r=r, z=z: np.isclose(x[0], r) & np.isclose(x[1], z), k
                )
                pin = zero_condition(space, k, dofs)
                if bodies.comm.allreduce(len(pin[1])) == 0:
                    raise RuntimeError(f"no mesh vertex at the pin (r, z) = ({r}, {z})")
                conditions.append(pin)
        return conditions

    def _traction_matrices(self):
        """Per load kind of TRACTIONS, the matrix (unknowns x scalar P2 dofs) that turns a
        traction profile q (P2, by its unit) on both contact faces into the load vector:
        normal pressure -q n, radial t_r = q, hoop t_phi = -q sin phi (amplitude q)."""
        import ufl

        bodies = self.solids.meshed
        v_r, v_phi, v_z = (amplitudes(ufl.TestFunction(self.space))[k] for k in range(3))
        n = ufl.FacetNormal(bodies.mesh)
        works = {"pressure": -(n[0] * v_r + n[1] * v_z), "radial": v_r, "hoop": v_phi}
        return {kind: bodies.traction_matrix(work) for kind, work in works.items()}

    def _free_body(self, cell_tag: int) -> RigidMotions:
        """The rigid motions of the free body of ``cell_tag`` about its centre of mass."""
        import ufl

        bodies, space = self.solids.meshed, self.space
        r, z = ufl.SpatialCoordinate(bodies.mesh)
        centre = bodies.body_integral(z, cell_tag) / bodies.body_integral(1.0, cell_tag)
        motions = rigid_motions(space, domain.tagged(bodies.cell_tags, cell_tag), centre)
        v = amplitudes(ufl.TestFunction(space))
        inertia = [
            assembly.assembled_values(
                assembly.form(ufl.dot(amplitudes(motion), v) * r * bodies.dx(cell_tag))
            )
            for motion in motions
        ]
        motions = np.column_stack([functions.owned_values(motion) for motion in motions])
        inertia = np.column_stack(inertia)
        return RigidMotions(motions, inertia, bodies.comm.allreduce(inertia.T @ motions))

    def _loads(self, profiles) -> np.ndarray:
        """The owned rows of the load vectors (rows, columns) of nodal traction profiles:
        ``profiles[kind]`` = (upper, lower), each (N, columns) of amplitudes at the film nodes
        on that face (hat functions, zero beyond the last node), by the film pressure unit p
        (shear profiles already multiplied by sqrt(delta)); kinds from TRACTIONS."""
        bodies = self.solids.meshed
        return sum(
            bodies.traction_loads(self._assembly.tractions[kind], bodies.profile_values(faces))
            for kind, faces in profiles.items()
        )

    def _solve(self, loads: np.ndarray) -> np.ndarray:
        """Displacements (owned rows of the unknowns, by a p / E_ref) of the load columns
        ``loads``: balanced on each free body by the d'Alembert body force, solved on the one
        factorisation, then relative to each free body's rigid motion (module docstring)."""
        comm, assembly = self.solids.comm, self._assembly
        for body in assembly.free_bodies:
            loads = body.balanced(loads, comm)
        loads[assembly.constrained] = 0.0
        values = assembly.solver.solve(loads)
        for body in assembly.free_bodies:
            values = body.relative(values, comm)
        return values

    def face_displacements(self, values: np.ndarray) -> list:
        """Per contact face (upper, lower): the (3N, columns) displacement amplitudes at the
        film nodes in the directions of the loads, (radial, hoop, normal) stacked, for the
        owned rows ``values`` of solutions in the unknowns (S, D, U_z) (by a p / E_ref): each
        the read-out G_i . u / m_i of its load on that face
        (:meth:`ehdfem.solids.fe.meshed.MeshedBodies.face_read_outs`), the normal one signed as
        the surface's vertical motion (the pressure pushes the sphere up, the lower body down),
        U_z - U_r dz/dr on the face at fixed r."""
        bodies = self.solids.meshed
        tractions = self._assembly.tractions
        reads = {kind: bodies.face_read_outs(tractions[kind], values) for kind in TRACTIONS}
        weights = np.tile(bodies.film_weights, 3)[:, None]
        return [
            np.vstack([reads["radial"][f], reads["hoop"][f], sign * reads["pressure"][f]]) / weights
            for f, sign in enumerate((1.0, -1.0))
        ]

    def _condense(self) -> np.ndarray:
        """The (6N, 5N) unit matrix (by a p / E_ref per unit nodal load, see the module
        docstring), in the orders of MODE_ONE_DISPLACEMENTS and MODE_ONE_LOADS, computed on one
        process: on these solids when serial, else rank 0 builds them alone
        (:meth:`FESolids.on_one_process`) and broadcasts it."""

        def compute(solids: FESolids) -> np.ndarray:
            if solids is self.solids:
                return self._condensed()
            alone = FEModeOne.__new__(FEModeOne)
            alone._build(solids)
            try:
                return alone._condensed()
            finally:
                alone.close()

        return self.solids.on_one_process(compute)

    def _condensed(self) -> np.ndarray:
        """:meth:`_condense` on this process (serial solids): the 6N face loads, per face
        (upper, lower) its radial, hoop and pressure hats (the read-outs in the directions of
        MODE_ONE_DISPLACEMENTS), condensed with the free sphere's balance
        (:func:`ehdfem.solids.fe.condensation.balanced_condensation`). A face's read-outs are
        those of its own face's loads (a face's load moves only its own body; the pressure
        loads both faces): divided by the film weights m, the normal one signed as in
        :meth:`face_displacements`, the shear loads by sqrt(delta) p."""
        import scipy.sparse

        n = len(self.solids.radii)
        bodies, assembly = self.solids.meshed, self._assembly
        kinds = ("radial", "hoop", "pressure")
        faces = scipy.sparse.hstack(
            [
                scipy_matrix(assembly.tractions[kind]) @ hats
                for hats in bodies.face_hats
                for kind in kinds
            ]
        )
        stiffness = scipy_matrix(assembly.solver.matrix)
        matrix = balanced_condensation(stiffness, faces, assembly.free_bodies, assembly.constrained)
        unit = np.zeros((6 * n, 5 * n))
        shear = math.sqrt(self.solids.delta)
        weights = np.tile(bodies.film_weights, 3)[:, None]
        for f, (face, sign) in enumerate((("sphere", 1.0), ("wall", -1.0))):
            rows = slice(3 * f * n, 3 * (f + 1) * n)
            reads = matrix[rows] / weights
            reads[2 * n :] *= sign
            for k, kind in enumerate(kinds):
                j = MODE_ONE_LOADS.index(kind if kind == "pressure" else f"{face}_{kind}")
                load = 1.0 if kind == "pressure" else shear
                unit[rows, j * n : (j + 1) * n] = load * reads[:, (3 * f + k) * n :][:, :n]
        return unit

    def field(self, nodal_loads):
        """The solids under the nodal loads ``nodal_loads`` ((5N,), in the order and units of
        MODE_ONE_LOADS, as the columns of ``matrix``) at this compliance's eps: a DOLFINx
        function on :attr:`space` holding (U_r, U_phi, U_z) (not the unknowns), by x0, each
        free sphere relative to its rigid motion; its read-outs at the film nodes
        (:meth:`face_displacements` of its unknowns) equal ``matrix @ nodal_loads``."""
        n = len(self.radii)
        loads = np.asarray(nodal_loads, dtype=float)
        if loads.shape != (5 * n,) or not np.isfinite(loads).all():
            raise checks.InputError(f"nodal_loads must be {5 * n} finite values (5 per film node)")
        shear = math.sqrt(self.solids.delta)
        by_name = dict(zip(MODE_ONE_LOADS, loads.reshape(5, n)[:, :, None], strict=True))
        profiles = {"pressure": (by_name["pressure"], by_name["pressure"])}
        for kind in TRACTIONS[1:]:
            profiles[kind] = (shear * by_name[f"sphere_{kind}"], shear * by_name[f"wall_{kind}"])
        s, d, u_z = self._solve(self._loads(profiles))[:, 0].reshape(-1, 3).T
        field = functions.function(self.space)
        functions.set_owned_values(
            field, self.factor(self.eps) * np.column_stack([s + d, s - d, u_z]).ravel()
        )
        return field
