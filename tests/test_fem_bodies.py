"""The lower bodies of the FE solids: a new lower body is one class; the built-in ones, their
settings and the registry."""

from dataclasses import dataclass
from typing import ClassVar

import numpy as np
import pytest
from mpi4py import MPI

from ehdfem.checks import InputError
from ehdfem.film.grid import radial_grid
from ehdfem.settings import setting
from ehdfem.solids.fe.bodies import (
    LOWER_BODIES,
    CoatedWall,
    LowerBody,
    LowerSphere,
    Wall,
    register,
)
from ehdfem.solids.fe.mode_one import FEModeOne
from ehdfem.solids.fe.solids import FESolids
from meshes import contact

RADII = radial_grid(20, 0.5, 2.0)


@dataclass(frozen=True)
class Block(LowerBody):
    """A clamped elastic block under the sphere, declared here only (not registered): the
    wall's geometry, material and support, written anew as a new lower body would be."""

    kind: ClassVar[str] = "block"
    description: ClassVar[str] = "the wall written anew"
    clamped: ClassVar[tuple[int, ...]] = (contact.LOWER_BOTTOM,)

    def materials(self, wall):
        return {contact.LOWER: wall}

    def geometry(self, gap, contact_radii, size):
        return contact.build, (gap, contact_radii, "wall", size, 1.0, 1.0, None)


@pytest.mark.serial
def test_a_new_lower_body_is_one_class():
    """The block declared above gives the built-in wall's axisymmetric and mode-1 compliances
    to round-off (1e-12 relative: the same mesh, forms and factorisation, so they agree to the
    last digits; a wrong support or material would move them by percents)."""
    block = FESolids(1e-3, RADII, wall=(0.5, 0.25), lower=Block(), comm=MPI.COMM_SELF)
    wall = FESolids(1e-3, RADII, wall=(0.5, 0.25), comm=MPI.COMM_SELF)
    assert block.lower == Block() and block.radius_lower is None
    for new, built_in in (
        (block.compliance(1.0, shear=True), wall.compliance(1.0, shear=True)),
        (FEModeOne(block, 1.0), FEModeOne(wall, 1.0)),
    ):
        scale = np.abs(built_in.matrix).max()
        assert np.abs(new.matrix - built_in.matrix).max() < 1e-12 * scale
        new.close()
        built_in.close()


def test_the_built_in_bodies_their_materials_and_radii():
    """The built-in bodies are registered by kind, the default wall first; a coated wall's
    coating is its stiffness times the wall's modulus, with its own Poisson ratio; two spheres
    of radius ratio 2 have a1 = 3 a and a2 = 1.5 a (a = a1 a2 / (a1 + a2))."""
    assert list(LOWER_BODIES)[:3] == ["wall", "coated", "sphere"]
    assert [LOWER_BODIES[k] for k in ("wall", "coated", "sphere")] == [
        Wall,
        CoatedWall,
        LowerSphere,
    ]
    wall = (2.0, 0.2)
    assert Wall().materials(wall) == {contact.LOWER: wall}
    coated = CoatedWall(0.1, coating_stiffness=1.5, coating_poisson=0.25)
    assert coated.materials(wall) == {contact.LOWER: wall, contact.COATING: (3.0, 0.25)}
    spheres = LowerSphere(radius_ratio=2.0)
    assert (spheres.sphere_radius, spheres.radius) == (3.0, 1.5)
    assert spheres.free_body().centre_z == -1.5
    assert Wall().free_body() is None and Wall().radius is None


@pytest.mark.parametrize(
    ("make", "named"),
    [
        (lambda: CoatedWall(0.0), "coating_thickness"),
        (lambda: CoatedWall(0.1, coating_poisson=0.5), "coating_poisson"),
        (lambda: CoatedWall(0.1, coating_stiffness=-1.0), "coating_stiffness"),
        (lambda: LowerSphere(0.0), "radius_ratio"),
    ],
)
def test_a_body_checks_its_settings(make, named):
    with pytest.raises(InputError, match=named) as caught:
        make()
    assert caught.value.name == named


def test_the_solids_take_a_lower_body_only():
    with pytest.raises(InputError, match="lower must be a lower body"):
        FESolids(1e-3, RADII, lower="sphere", comm=MPI.COMM_SELF)


def test_the_registry_refuses_what_it_could_not_name_once():
    """A kind taken by another class, a field of another body (the flat settings name each
    field once), a class that is not a frozen LowerBody dataclass and one without a kind are
    refused; the registry is unchanged. A body without its geometry cannot be made."""
    before = dict(LOWER_BODIES)

    @dataclass(frozen=True)
    class SecondWall(Wall):
        kind: ClassVar[str] = "wall"

    @dataclass(frozen=True)
    class Thin(LowerBody):
        kind: ClassVar[str] = "thin"
        coating_thickness: float = setting(0.1, help="t", unit="by a")

    @dataclass
    class Loose(LowerBody):
        kind: ClassVar[str] = "loose"

    @dataclass(frozen=True)
    class NoKind(LowerBody):
        pass

    for body, text in (
        (SecondWall, "kind 'wall' is taken"),
        (Thin, r"\['coating_thickness'\] are CoatedWall's"),
        (Loose, "frozen dataclass"),
        (NoKind, "with a kind"),
        (dict, "frozen dataclass"),
    ):
        with pytest.raises(TypeError, match=text):
            register(body)
    assert register(Wall) is Wall and LOWER_BODIES == before
    with pytest.raises(TypeError, match="abstract"):
        NoKind()
