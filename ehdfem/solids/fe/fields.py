"""The FE solids' fields for pictures: displacement, stresses, the film pressure on the contact
faces and the body of each cell, under one film pressure, on the vertices and cells of the (r, z)
mesh.

Used by the field exports (:mod:`ehdfem.outputs.fields`) and the pictures
(:mod:`ehdfem.outputs.render`) through :meth:`ehdfem.solids.fe.solids.FESolids.deformation`.
Scales: points by a; displacements by x0 (the solve's a p / E_ref times
:meth:`~ehdfem.solids.fe.solids.FESolids.scale`); stresses by the film pressure unit
mu V0 a / x0^2 (the solve's stresses by E_ref of displacements by a p / E_ref); the film
pressure by the same unit.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from meshes import contact

from ...fenicsx import domain, functions, spaces
from .meshed import FACES

BODIES = {contact.SPHERE: 0, contact.LOWER: 1, contact.COATING: 2}
"""The region number of each body's gmsh cell tag: 0 the upper sphere, 1 the lower body (wall,
substrate or lower sphere), 2 the coating."""


@dataclass(frozen=True, eq=False)
class Deformation:
    """The solids under one film pressure, on this rank's part of the mesh (read-only arrays).

    ``points``: (n, 2) vertex coordinates (r, z), by a. ``triangles``: (m, 3) the cells owned
    by this rank, as indices into ``points``. ``displacement``: (n, 2) (u_r, u_z) at the
    vertices, by x0, each free sphere relative to its centre of mass. ``von_mises`` and
    ``hydrostatic``: (m,) stress per triangle, by mu V0 a / x0^2 (the film pressure unit; per
    cell, as the hoop strain u_r / r is 0/0 at vertices on the axis). ``film_pressure``: (n,)
    the film pressure p(r) (linear between the film nodes, zero beyond the last) at the vertices
    of both contact faces, zero elsewhere, by mu V0 a / x0^2. ``body``: (m,) the region of each
    triangle (:data:`BODIES`: 0 upper sphere, 1 lower body, 2 coating). ``upper``: (n,) True at
    the vertices of the upper sphere.
    """

    points: np.ndarray
    triangles: np.ndarray
    displacement: np.ndarray
    von_mises: np.ndarray
    hydrostatic: np.ndarray
    film_pressure: np.ndarray
    body: np.ndarray
    upper: np.ndarray


@dataclass(frozen=True)
class _VertexMesh:
    """The P1 (vertex) mesh of one rank: a P1 displacement to interpolate into, the vertices,
    the owned triangles, the vertices of each free body (in the order of the bodies), the
    vertices on the contact faces and the region (:data:`BODIES`) of each owned triangle."""

    function: object
    points: np.ndarray
    triangles: np.ndarray
    body_vertices: list
    upper: np.ndarray
    face_vertices: np.ndarray
    body: np.ndarray


def _read_only(array: np.ndarray) -> np.ndarray:
    """``array``, no longer writeable (shared between deformations)."""
    array.setflags(write=False)
    return array


class SolidsFields:
    """The fields of the FE ``solids`` (an :class:`ehdfem.solids.fe.solids.FESolids`): their
    displacement solve, free-body centres, stress law and scale; the vertex mesh and the stress
    expressions are built on first use."""

    def __init__(self, solids):
        self.solids = solids

    def deformation(self, nodal_pressure, eps: float) -> Deformation:
        """The solids under the film pressure with values ``nodal_pressure`` at the film nodes
        (by mu V0 a / x0^2) at elasticity parameter ``eps``: one solve; see
        :class:`Deformation` for the fields and their units."""
        solids = self.solids
        displacement = solids.displacement(nodal_pressure)
        vertices = self._vertex_mesh
        functions.interpolate(vertices.function, displacement)
        values = functions.local_values(vertices.function).reshape(-1, 2).copy()
        for body_vertices, centre in zip(vertices.body_vertices, solids.centres(), strict=True):
            values[body_vertices, 1] -= centre
        film = np.zeros(len(vertices.points))
        faces = vertices.face_vertices
        film[faces] = solids.film_pressure(nodal_pressure)(vertices.points[faces, 0])
        return Deformation(
            points=vertices.points,
            triangles=vertices.triangles,
            displacement=_read_only(values * solids.scale(eps)),
            film_pressure=_read_only(film),
            body=vertices.body,
            upper=vertices.upper,
            **self._cell_stresses(),
        )

    @cached_property
    def _vertex_mesh(self) -> _VertexMesh:
        """This rank's P1 mesh (built once); see :class:`_VertexMesh`."""
        bodies = self.solids.meshed
        space = spaces.lagrange_space(bodies.mesh, 1, vector=True)
        cells, _, coordinates = spaces.vtk_mesh(space)
        owned = domain.owned_cell_count(bodies.mesh)
        body_vertices = [
            spaces.entity_dofs(space, 2, domain.tagged(bodies.cell_tags, body.cell_tag))
            for body in bodies.free_bodies
        ]
        upper = np.zeros(len(coordinates), dtype=bool)
        upper[body_vertices[0]] = True
        body = np.full(owned, -1, dtype=np.int32)
        for tag, region in BODIES.items():
            cells_of_body = domain.tagged(bodies.cell_tags, tag)
            body[cells_of_body[cells_of_body < owned]] = region
        return _VertexMesh(
            function=functions.function(space),
            points=_read_only(coordinates[:, :2]),
            triangles=_read_only(cells.reshape(-1, 4)[:owned, 1:]),
            body_vertices=body_vertices,
            upper=_read_only(upper),
            face_vertices=_read_only(spaces.entity_dofs(space, 1, bodies.facets(*FACES))),
            body=_read_only(body),
        )

    @cached_property
    def _stress_measures(self):
        """(DG0 function, {name: expression}, dofs of the owned cells) for the von Mises and
        hydrostatic stress of the solids' current displacement (by the film pressure unit, as
        the displacement is by a p/E_ref), built once."""
        import ufl

        mesh = self.solids.mesh
        space = spaces.cell_space(mesh)
        sigma = self.solids.stress(self.solids.displacement_function)
        deviator = sigma - ufl.tr(sigma) / 3 * ufl.Identity(3)
        expressions = {
            "von_mises": functions.expression(ufl.sqrt(1.5 * ufl.inner(deviator, deviator)), space),
            "hydrostatic": functions.expression(ufl.tr(sigma) / 3, space),
        }
        owned = domain.owned_cell_count(mesh)
        return functions.function(space), expressions, spaces.cell_dofs(space, owned)

    def _cell_stresses(self) -> dict:
        """{"von_mises": ..., "hydrostatic": ...} per owned cell for the current displacement."""
        field, expressions, dofs = self._stress_measures
        stresses = {}
        for name, expression in expressions.items():
            functions.interpolate(field, expression)
            stresses[name] = _read_only(functions.local_values(field)[dofs])
        return stresses
