"""The lower bodies of the FE solids: a new lower body is one class; the built-in ones by name."""

from dataclasses import dataclass

import numpy as np
import pytest
from mpi4py import MPI

from ehdfem.checks import InputError
from ehdfem.film.grid import radial_grid
from ehdfem.solids.fe.bodies import LOWER_BODIES, CoatedWall, LowerSphere, Wall, lower_body
from ehdfem.solids.fe.mode_one import FEModeOne
from ehdfem.solids.fe.solids import FESolids
from meshes import contact

RADII = radial_grid(20, 0.5, 2.0)


@dataclass(frozen=True)
class Block:
    """A clamped elastic block under the sphere, declared here only: the wall's geometry,
    material and support, written anew as a new lower body would be."""

    material: tuple[float, float] = (1.0, 0.3)
    name = "block"
    sphere_radius = 1.0
    radius = None
    clamped = (contact.LOWER_BOTTOM,)

    def materials(self):
        return {contact.LOWER: self.material}

    def free_body(self):
        return None

    def geometry(self, gap, contact_radii, size):
        return contact.build, (gap, contact_radii, "wall", size, 1.0, 1.0, None)


@pytest.mark.serial
def test_a_new_lower_body_is_one_class():
    """The block declared above gives the built-in wall's axisymmetric and mode-1 compliances
    to round-off (1e-12 relative: the same mesh, forms and factorisation, so they agree to the
    last digits; a wrong support or material would move them by percents)."""
    block = FESolids.with_lower_body(1e-3, RADII, Block((0.5, 0.25)), comm=MPI.COMM_SELF)
    wall = FESolids(1e-3, RADII, wall=(0.5, 0.25), comm=MPI.COMM_SELF)
    assert block.lower == "block" and block.radius_lower is None
    for new, built_in in (
        (block.compliance(1.0, shear=True), wall.compliance(1.0, shear=True)),
        (FEModeOne(block, 1.0), FEModeOne(wall, 1.0)),
    ):
        scale = np.abs(built_in.matrix).max()
        assert np.abs(new.matrix - built_in.matrix).max() < 1e-12 * scale
        new.close()
        built_in.close()


def test_lower_bodies_by_name_and_their_numbers():
    """The registry maps each name and its numbers to a body; each checks its numbers."""
    assert set(LOWER_BODIES) == {"wall", "coated", "sphere"}
    assert lower_body("wall", wall=(2.0, 0.2)) == Wall((2.0, 0.2))
    coated = lower_body("coated", coating=(3.0, 0.25), coating_thickness=0.1)
    assert coated == CoatedWall(0.1, (1.0, 0.3), (3.0, 0.25))
    spheres = lower_body("sphere", radius_ratio=2.0)
    assert spheres == LowerSphere((1.0, 0.3), 2.0)
    # a = a1 a2 / (a1 + a2) with a1 / a2 = 2: a1 = 3 a, a2 = 1.5 a
    assert (spheres.sphere_radius, spheres.radius) == (3.0, 1.5)
    assert spheres.free_body().centre_z == -1.5
    with pytest.raises(InputError, match="lower"):
        lower_body("plate")
    with pytest.raises(InputError, match="coating_thickness"):
        lower_body("coated")
    with pytest.raises(InputError, match="coating Poisson ratio"):
        lower_body("coated", coating=(1.0, 0.5), coating_thickness=0.1)
    with pytest.raises(InputError, match="radius_ratio"):
        lower_body("sphere", radius_ratio=0.0)
