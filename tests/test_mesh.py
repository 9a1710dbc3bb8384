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


def test_a_sliver_of_the_frontal_mesher_is_meshed_again(earlier_grid_law):
    """Frontal-Delaunay alone makes the sliver (shape below 1e-6); the generator's mesh has none
    (shape above SLIVER = 1e-3; an equilateral triangle has 0.43)."""
    assert wall_mesh_shape(contact.FRONTAL_DELAUNAY) < 1e-6
    assert wall_mesh_shape() >= contact.SLIVER
