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

import numpy as np

from ... import checks
from ...console.progress import progress
from ..compliance import MODE_ONE_LOADS, ModeOneCompliance
from . import dolfinx_compat
from .linear_algebra import CholeskySolver
from .mesh import cached_matrices
from .solids import FESolids

DEGREE = 2  # of the Lagrange elements
QUADRATURE_DEGREE = 9
"""Of the stiffness integrand: products of P2 strain amplitudes (with the 1/r terms) times r and
the moduli. UFL would estimate 7 for moduli constant per cell; 9 is the degree the mode-1
compliance was validated with (tests/test_fem_mode_one.py) and stored with (the regression
table, tests/test_regression.py), so it is fixed here."""
BLOCK = 48  # right-hand sides per multiple-RHS solve (memory: 8 B x unknowns x BLOCK)
TRACTIONS = ("pressure", "radial", "hoop")
"""The load kinds of one solve: the same nodal profile (or each face its own) on both faces."""


def mode_one_space(mesh):
    """The P2 space of the unknowns (S, D, U_z) (module docstring) on the (r, z) ``mesh``."""
    return dolfinx_compat.lagrange_space(mesh, DEGREE, vector=True, components=3)


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

    r = ufl.SpatialCoordinate(space.mesh)[0]
    u, v = ufl.TrialFunction(space), ufl.TestFunction(space)
    dx = ufl.dx(metadata={"quadrature_degree": QUADRATURE_DEGREE})
    return ufl.inner(stress(strain(u, r), lame), strain(v, r)) * r * dx


def zero_condition(space, component: int, dofs):
    """A homogeneous Dirichlet condition on unknown ``component`` (0: S, 1: D, 2: U_z) of
    ``space`` at ``dofs``, the pair (parent, collapsed) of a
    :func:`ehdfem.solids.fe.dolfinx_compat.entity_dofs` or ``point_dofs`` call with that
    component; returns (condition, owned rows of the solution vector)."""
    parent = dofs[0]
    owned = space.dofmap.index_map.size_local * space.dofmap.index_map_bs
    return dolfinx_compat.zero_condition(space, dofs, component), parent[parent < owned]


def axis_conditions(space, axis_facets):
    """The axis regularity conditions D = 0 and U_z = 0 on the facets ``axis_facets`` (r = 0):
    a list of (condition, owned rows), as :func:`zero_condition`."""
    return [
        zero_condition(space, k, dolfinx_compat.entity_dofs(space, 1, axis_facets, k))
        for k in (1, 2)
    ]


def rigid_motions(space, cells, centre_z: float):
    """The x translation and the rotation about y through z = ``centre_z`` (by a) as functions
    of the unknowns (S, D, U_z) on ``space``, zero outside ``cells``: (1, 0, 0) and
    (z - z_c, 0, -r), per unit displacement and per unit angle."""
    translation, rotation = dolfinx_compat.function(space), dolfinx_compat.function(space)
    translation.interpolate(lambda x: np.vstack([np.ones_like(x[0]), 0 * x[0], 0 * x[0]]), cells)
    rotation.interpolate(lambda x: np.vstack([x[1] - centre_z, 0 * x[0], -x[0]]), cells)
    return translation, rotation


@dataclass(frozen=True)
class _RigidMotions:
    """A free sphere's rigid motions on the owned rows: ``motions`` (rows, 2) the vectors R_k,
    ``inertia`` (rows, 2) the vectors m_k of int R_k . v r dx, ``gram`` G = m^T R (2x2)."""

    motions: np.ndarray
    inertia: np.ndarray
    gram: np.ndarray


class FEModeOne(ModeOneCompliance):
    """Mode-1 compliance of FE solids (:class:`ehdfem.solids.compliance.ModeOneCompliance`) on the
    mesh of ``solids`` (a :class:`FESolids`, whose materials, free bodies and film nodes it shares),
    at ``eps``; see the module docstring. The unit matrix comes from one factorisation and 3N
    unit loads (the pressure hat j on both faces; the radial hat j on both faces, read per face
    as "sphere_radial" and "wall_radial"; the same for the hoop hat), solved in blocks of
    BLOCK right-hand sides. ``space``: the P2 space of the unknowns (S, D, U_z) on that mesh.
    :meth:`field` gives the whole solids under given nodal loads; :meth:`close` frees the
    factorisation (its own, besides the solids' axisymmetric one)."""

    model = "fem"

    def __init__(self, solids: FESolids, eps: float):
        if not isinstance(solids, FESolids):
            raise checks.InputError(f"solids must be FESolids, got {type(solids).__name__}")
        checks.positive("eps", eps)
        self.solids = solids
        self.space = mode_one_space(solids.mesh)
        self._assemble()
        unit = cached_matrices(
            solids.comm,
            ("mode one", *solids.cache_arguments),
            [sys.modules[__name__], *solids.cache_sources],
            lambda: {"unit": self._condense()},
        )["unit"]
        super().__init__(solids.radii, unit, eps)

    def factor(self, eps: float) -> float:
        """x0 per (a p / E_ref) at ``eps``: :meth:`FESolids.scale`."""
        return self.solids.scale(eps)

    def close(self) -> None:
        """Free the factorised stiffness and the traction matrices (PETSc memory that Python's
        garbage collector does not return). Collective under MPI; no solves afterwards."""
        self._solver.close()
        for petsc_object in self._tractions.values():
            petsc_object.destroy()

    def _assemble(self):
        """Assemble the stiffness and set up its factorisation (MUMPS Cholesky, made on the
        first solve: it is symmetric positive definite once pinned); set up the traction
        matrices, the free bodies and the contact faces."""
        conditions = self._constraints()
        self._constrained = np.concatenate([rows for _, rows in conditions])
        stiffness = dolfinx_compat.assemble_matrix(
            dolfinx_compat.form(stiffness_form(self.space, self.solids.meshed.lame)),
            [bc for bc, _ in conditions],
        )
        self._solver = CholeskySolver(stiffness, self.solids.comm)
        self._tractions = self._traction_matrices()
        self._free_bodies = [self._free_body(body.cell_tag) for body in self.solids.free_bodies]

    def _constraints(self):
        """(condition, owned rows) pairs: the axis conditions, the lower body's clamped facets
        (all three unknowns: a wall's base) and, for each free sphere, S = 0 at its far pole
        and U_z = 0 at its equator (which fix its translation and rotation)."""
        bodies, space = self.solids.meshed, self.space
        conditions = axis_conditions(space, bodies.axis_facets)
        if bodies.lower.clamped:
            clamped = bodies.clamped_facets
            conditions += [
                zero_condition(space, k, dolfinx_compat.entity_dofs(space, 1, clamped, k))
                for k in range(3)
            ]
        for body in bodies.free_bodies:
            for k, (r, z) in ((0, (0.0, body.pole_z)), (2, (body.radius, body.centre_z))):
                dofs = dolfinx_compat.point_dofs(
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

    def _free_body(self, cell_tag: int) -> _RigidMotions:
        """The rigid motions of the free body of ``cell_tag`` about its centre of mass."""
        import ufl

        bodies, space = self.solids.meshed, self.space
        r, z = ufl.SpatialCoordinate(bodies.mesh)
        centre = bodies.body_integral(z, cell_tag) / bodies.body_integral(1.0, cell_tag)
        motions = rigid_motions(space, bodies.cell_tags.find(cell_tag), centre)
        v = amplitudes(ufl.TestFunction(space))
        inertia = [
            dolfinx_compat.assemble_vector(
                dolfinx_compat.form(ufl.dot(amplitudes(motion), v) * r * bodies.dx(cell_tag)), []
            ).getArray()
            for motion in motions
        ]
        owned = len(inertia[0])
        motions = np.column_stack([motion.x.array[:owned] for motion in motions])
        inertia = np.column_stack(inertia)
        return _RigidMotions(motions, inertia, bodies.comm.allreduce(inertia.T @ motions))

    def _loads(self, profiles) -> np.ndarray:
        """The owned rows of the load vectors (rows, columns) of nodal traction profiles:
        ``profiles[kind]`` = (upper, lower), each (N, columns) of amplitudes at the film nodes
        on that face (hat functions, zero beyond the last node), by the film pressure unit p
        (shear profiles already multiplied by sqrt(delta)); kinds from TRACTIONS."""
        bodies = self.solids.meshed
        return sum(
            bodies.traction_loads(self._tractions[kind], bodies.profile_values(faces))
            for kind, faces in profiles.items()
        )

    def _solve(self, loads: np.ndarray) -> np.ndarray:
        """Displacements (owned rows of the unknowns, by a p / E_ref) of the load columns
        ``loads``: balanced on each free body by the d'Alembert body force, solved on the one
        factorisation, then relative to each free body's rigid motion (module docstring)."""
        comm = self.solids.comm
        loads = loads.copy()
        for body in self._free_bodies:
            loads -= body.inertia @ np.linalg.solve(
                body.gram, comm.allreduce(body.motions.T @ loads)
            )
        loads[self._constrained] = 0.0
        values = self._solver.solve(loads)
        for body in self._free_bodies:
            values -= body.motions @ np.linalg.solve(
                body.gram, comm.allreduce(body.inertia.T @ values)
            )
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
        reads = {kind: bodies.face_read_outs(self._tractions[kind], values) for kind in TRACTIONS}
        weights = np.tile(bodies.film_weights, 3)[:, None]
        return [
            np.vstack([reads["radial"][f], reads["hoop"][f], sign * reads["pressure"][f]]) / weights
            for f, sign in enumerate((1.0, -1.0))
        ]

    def _condense(self) -> np.ndarray:
        """The (6N, 5N) unit matrix (by a p / E_ref per unit nodal load, see the module
        docstring), in the orders of MODE_ONE_DISPLACEMENTS and MODE_ONE_LOADS."""
        n = len(self.solids.radii)
        unit = np.zeros((6 * n, 5 * n))
        shear = math.sqrt(self.solids.delta)
        blocks = [(kind, start) for kind in TRACTIONS for start in range(0, n, BLOCK)]
        for kind, start in progress(blocks, desc="FE mode-1 compliance"):
            hats = np.eye(n)[:, start : start + BLOCK] * (1.0 if kind == "pressure" else shear)
            values = self._solve(self._loads({kind: (hats, hats)}))
            columns = slice(start, start + hats.shape[1])
            # a face's load moves only its own body: one solve serves both faces' columns
            for f, (face, displacements) in enumerate(
                zip(("sphere", "wall"), self.face_displacements(values), strict=True)
            ):
                j = MODE_ONE_LOADS.index(kind if kind == "pressure" else f"{face}_{kind}")
                unit[3 * f * n : 3 * (f + 1) * n, j * n : (j + 1) * n][:, columns] = displacements
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
        field = dolfinx_compat.function(self.space)
        field.x.array[: 3 * len(s)] = (
            self.factor(self.eps) * np.column_stack([s + d, s - d, u_z]).ravel()
        )
        field.x.scatter_forward()
        return field
