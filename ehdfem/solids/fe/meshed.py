"""The meshed bodies of the FE solids: what the axisymmetric and the mode-1 solves share.

:class:`MeshedBodies` holds the (r, z) mesh of the upper sphere over a lower body
(:mod:`ehdfem.solids.fe.bodies`) with its gmsh tags, the material per cell, the free bodies,
the dofs of a space on the contact faces, the film loads on those faces as P2 traction
profiles and their read-outs. It is the public interface of :mod:`ehdfem.solids.fe.solids` and
:mod:`ehdfem.solids.fe.mode_one`; neither reads the other's attributes.

Lengths by the (reduced) sphere radius a: the film nodes R (by sqrt(a x0)) sit at r = R
sqrt(delta) on both faces; moduli by the upper sphere's, E_ref; traction profiles carry the
unit of the nodal values they are made of (the film pressure unit mu V0 a / x0^2 for the film).

Reciprocal read-outs: the load vector of a unit nodal traction j of one kind on one face is
G_j = int_face phi_j t(v) r ds (phi_j the film node's hat, t(v) the traction's work on the test
displacement v), and the displacement read out at film node i in that load's direction is the
same functional divided by the film's lumped weight, G_i . u / m_i, m_i = int phi_i r dr (the
film's lumped mass, :attr:`MeshedBodies.film_weights`). With the loads balanced and the
read-outs taken relative to the same rigid motions, M C = G^T K^-1 G is symmetric to the
solver's rounding (Betti's theorem, exactly in the discrete form; docs/fem.md).
"""

from __future__ import annotations

import math
from functools import cached_property

import numpy as np

from meshes import contact

from ... import checks
from ...fenicsx import assembly, domain, functions, spaces
from ...fenicsx.matrices import matrix_product
from ...film.reynolds import Film
from ..compliance import FILM_REACH_LIMIT
from .bodies import FreeBody, LowerBody, checked_material
from .linear_algebra import interpolation_matrix
from .mesh import contact_mesh

FACES = (contact.SPHERE_CONTACT, contact.LOWER_CONTACT)
"""The facet tags of the contact faces: the upper sphere's, then the lower body's."""


class MeshedBodies:
    """The upper sphere (``sphere``: (E, nu)) at the gap ``delta`` = x0/a above the body
    ``lower`` (a :class:`ehdfem.solids.fe.bodies.LowerBody` of the wall's (E, nu) ``wall``:
    a coated wall's substrate, a lower sphere's own), meshed on ``comm`` for the film
    nodes ``radii`` (by sqrt(a x0)) with the far parts ``size`` away (by a); see the module
    docstring. ``mesh``, ``cell_tags``, ``facet_tags``: the DOLFINx mesh and its gmsh groups
    (meshes/contact.py); ``free_bodies``: the free spheres, the upper one first."""

    def __init__(self, delta: float, radii, sphere, wall, lower: LowerBody, size: float, comm):
        self.delta = checks.number(
            "delta", delta, lower=0.0, upper=1.0, lower_open=True, upper_open=True
        )
        self.sphere, self.lower, self.comm = checked_material("sphere", sphere), lower, comm
        self.wall = checked_material("wall", wall)
        self.radii = np.asarray(radii, dtype=float)
        limit = FILM_REACH_LIMIT * min(lower.sphere_radius, lower.radius or math.inf)
        if self.radii[-1] * math.sqrt(self.delta) >= limit:
            raise checks.InputError(
                f"the film reaches r = {self.radii[-1] * math.sqrt(self.delta):.3g} a at delta = "
                f"x0/a = {self.delta:.3g}; the FE solids need it within {FILM_REACH_LIMIT} of "
                f"the smaller sphere radius ({limit:.3g} a): a thinner layer, or the half-space "
                "model",
                "delta",
            )
        self.build, self.mesh_arguments = lower.geometry(self.delta, self.radii_a, size)
        self.mesh, self.cell_tags, self.facet_tags = contact_mesh(
            comm, self.build, self.mesh_arguments
        )
        top = 2 * lower.sphere_radius + self.delta
        upper = FreeBody(contact.SPHERE, contact.SPHERE_CONTACT, top, -1.0, lower.sphere_radius)
        self.free_bodies = (upper,) + tuple(b for b in (lower.free_body(),) if b is not None)
        self.scaled_moduli = {
            tag: (e / self.sphere[0], nu)
            for tag, (e, nu) in {contact.SPHERE: self.sphere, **lower.materials(self.wall)}.items()
        }

    @property
    def radii_a(self) -> np.ndarray:
        """The film nodes in units of a."""
        return self.radii * math.sqrt(self.delta)

    @cached_property
    def film_weights(self) -> np.ndarray:
        """m_i = int phi_i r dr over the film (by a^2): delta times the film's lumped mass
        int phi_i R dR (:attr:`ehdfem.film.reynolds.Film.full_mass`), the weights with which
        nodal pressures P become the film's force and the FE loads' vertical resultant."""
        return self.delta * Film(self.radii).full_mass

    @property
    def r(self):
        """The radial coordinate (UFL), by a."""
        import ufl

        return ufl.SpatialCoordinate(self.mesh)[0]

    @property
    def dx(self):
        """The cell measure (UFL), by cell tag: ``dx(tag)`` integrates over one body."""
        import ufl

        return ufl.Measure("dx", domain=self.mesh, subdomain_data=self.cell_tags)

    @property
    def ds(self):
        """The boundary measure (UFL), by facet tag."""
        import ufl

        return ufl.Measure("ds", domain=self.mesh, subdomain_data=self.facet_tags)

    def facets(self, *tags) -> np.ndarray:
        """The local facets of the gmsh facet groups ``tags`` (e.g. FACES, the axis)."""
        tagged = [domain.tagged(self.facet_tags, tag) for tag in tags]
        return np.concatenate(tagged or [np.empty(0, np.int32)])

    @property
    def axis_facets(self) -> np.ndarray:
        """The facets on the axis r = 0, of both bodies."""
        return self.facets(contact.SPHERE_AXIS, contact.LOWER_AXIS)

    @property
    def clamped_facets(self) -> np.ndarray:
        """The facets held fixed (a wall's base; none below a free lower sphere)."""
        return self.facets(*self.lower.clamped)

    @cached_property
    def lame(self):
        """(lambda, mu) per cell as UFL expressions, by E_ref, from E and nu of each body."""
        cells = spaces.cell_space(self.mesh)
        young, poisson = functions.function(cells), functions.function(cells)
        for tag, (e, nu) in self.scaled_moduli.items():
            tagged = domain.tagged(self.cell_tags, tag)
            functions.local_values(young)[tagged] = e
            functions.local_values(poisson)[tagged] = nu
        lmbda = young * poisson / ((1 + poisson) * (1 - 2 * poisson))
        return lmbda, young / (2 * (1 + poisson))

    def body_integral(self, integrand, cell_tag: int) -> float:
        """int ``integrand`` r dr dz over the body of ``cell_tag`` (UFL integrand), all ranks."""
        return assembly.integral(integrand * self.r * self.dx(cell_tag), self.comm)

    def face_dofs(self, space, component: int, tag: int):
        """(rows, r): the owned rows of ``component`` of the vector ``space`` in its solution
        vector on the contact face ``tag``, and their radii r (by a)."""
        facets = domain.tagged(self.facet_tags, tag)
        parent, child = spaces.entity_dofs(space, 1, facets, component)
        _, collapsed = spaces.sub_space(space, component)
        keep = parent < spaces.owned_dof_count(space)
        return parent[keep], spaces.dof_coordinates(collapsed)[child[keep], 0]

    @cached_property
    def profile_space(self):
        """The scalar P2 space of the traction profiles on the contact faces."""
        return spaces.lagrange_space(self.mesh, 2)

    def traction_matrix(self, work):
        """The PETSc matrix (unknowns x profile dofs) of int q ``work`` r ds over both contact
        faces, q the profile (trial function) and ``work`` linear in a test displacement: the
        load vector of a traction profile, in the profile's unit times a^2."""
        import ufl

        q = ufl.TrialFunction(self.profile_space)
        faces = self.ds(FACES[0]) + self.ds(FACES[1])
        return assembly.assemble_matrix(assembly.form(q * work * self.r * faces), [])

    def face_tangent(self):
        """The unit tangent of the contact faces pointing away from the axis, sign(n_z) (n_z,
        -n_r) with n the outward normal: (1, 0) on a wall, along the curved faces on a sphere
        (UFL); the direction of the film's squeeze-shear traction, positive outward."""
        import ufl

        n = ufl.FacetNormal(self.mesh)
        return ufl.sign(n[1]) * ufl.as_vector((n[1], -n[0]))

    @cached_property
    def face_hats(self):
        """Per contact face (upper, lower): the sparse (owned profile dofs, N) matrix of the film
        nodes' hat functions at the profile dofs on that face (zero elsewhere)."""
        import scipy.sparse

        space = self.profile_space
        owned = spaces.owned_dof_count(space)
        r = spaces.dof_coordinates(space)[:owned, 0]
        hats = []
        for tag in FACES:
            dofs = spaces.entity_dofs(space, 1, domain.tagged(self.facet_tags, tag))
            on_face = scipy.sparse.diags(np.isin(np.arange(owned), dofs).astype(float))
            hats.append(on_face @ interpolation_matrix(self.radii_a, r))
        return hats

    def profile_values(self, faces) -> np.ndarray:
        """The owned entries (rows, columns) of the P2 traction profiles with nodal values
        ``faces`` = (upper, lower), each (N, columns) at the film nodes (linear between them,
        zero beyond the last), on the two contact faces, zero elsewhere; in the unit of the
        nodal values."""
        return sum(hats @ nodal for hats, nodal in zip(self.face_hats, faces, strict=True))

    def traction_loads(self, matrix, values: np.ndarray) -> np.ndarray:
        """The owned rows (rows, columns) of the loads of a :meth:`traction_matrix` for the
        owned profile entries ``values`` (:meth:`profile_values`): int t . v r ds with lengths
        by a, in the unit of ``values`` times a^2."""
        return matrix_product(matrix, values, self.comm)

    def face_read_outs(self, matrix, values: np.ndarray) -> list:
        """Per contact face (upper, lower): the (N, columns) read-outs G_i . u at the film nodes
        of the loads of a :meth:`traction_matrix` (G_i the load of the hat i on that face) for
        the displacement columns whose owned rows are ``values``, summed over the ranks; in
        the load's unit times a^2 times the displacement's unit. Divided by
        :attr:`film_weights` they are the displacements in the load's direction (module
        docstring)."""
        works = matrix_product(matrix, values, self.comm, transpose=True)
        return [self.comm.allreduce(hats.T @ works) for hats in self.face_hats]
