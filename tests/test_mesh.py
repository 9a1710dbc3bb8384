"""The contact meshes (meshes/contact.py) have no degenerate triangles."""

import gmsh
import numpy as np
import pytest

from ehdfem import collision
from ehdfem.collision import film_radii
from ehdfem.film import grid
from ehdfem.inputs.scales import CollisionParameters
from meshes import contact

pytestmark = pytest.mark.serial

# delta = 1e-3, 120 film nodes, dry compression 0.03 x0 (St 20), on the contact grid's earlier
# law (axis spacing 0.7, far field growing by 8 per rim radius): Frontal-Delaunay left a sliver
# with its three vertices on the wall face here, and the FE compliance came out NaN.
DELTA = 1e-3
SLIVER_CASE = CollisionParameters(St=20.0, eps=0.03**2.5 / (13.88 * 20.0), delta=DELTA)


@pytest.fixture
def earlier_grid_law(monkeypatch):
    """The contact grid's law on which the sliver was found."""
    monkeypatch.setattr(collision, "contact_spacings", lambda St: {"axis_spacing": 0.7})
    monkeypatch.setattr(grid, "_CONTACT_SPACING_SLOPE", 8.0)


def wall_mesh_shape(algorithm=None):
    """The worst triangle's area / side^2 of the wall mesh of SLIVER_CASE, meshed by
    contact.build, or by one gmsh algorithm alone."""
    radii = film_radii(SLIVER_CASE, 120) * np.sqrt(DELTA)  # by a
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    try:
        contact.build(DELTA, radii, "wall", 40.0)
        if algorithm is not None:
            gmsh.option.setNumber("Mesh.Algorithm", algorithm)
            gmsh.model.mesh.clear()
            gmsh.model.mesh.generate(2)
        return contact.worst_shape(gmsh.model)
    finally:
        gmsh.finalize()


def test_the_sliver_case_is_meshed_without_a_sliver(earlier_grid_law):
    """Debian's gmsh 4.8 meshed this case with a sliver under Frontal-Delaunay alone (shape
    below 1e-6; gmsh 4.15 of the wheel stack no longer does); the generator's mesh has none
    (shape above SLIVER = 1e-3; an equilateral triangle has 0.43)."""
    assert wall_mesh_shape() >= contact.SLIVER


def test_a_sliver_is_meshed_again_by_the_other_algorithm(monkeypatch):
    """Whatever gmsh makes, a mesh reported as a sliver is meshed again: with Frontal-Delaunay's
    mesh reported degenerate the kept mesh is Delaunay's; with both reported degenerate the
    generator refuses with MeshError naming the film radii."""
    shape, tried = contact.worst_shape, []

    def reported(model, degenerate):
        tried.append(int(gmsh.option.getNumber("Mesh.Algorithm")))
        return 0.0 if tried[-1] in degenerate else shape(model)

    monkeypatch.setattr(contact, "worst_shape", lambda m: reported(m, {contact.FRONTAL_DELAUNAY}))
    assert wall_mesh_shape() >= contact.SLIVER
    assert tried == [contact.FRONTAL_DELAUNAY, contact.DELAUNAY, contact.DELAUNAY]
    both = {contact.FRONTAL_DELAUNAY, contact.DELAUNAY}
    monkeypatch.setattr(contact, "worst_shape", lambda m: reported(m, both))
    with pytest.raises(contact.MeshError, match="with both its algorithms for film radii"):
        wall_mesh_shape()
