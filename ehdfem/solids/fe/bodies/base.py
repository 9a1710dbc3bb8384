"""The bodies of the FE solids: the upper sphere and one lower body, as plain data.

A lower body says what the FE solids need of it and nothing of how they solve
(:class:`LowerBody`): its gmsh geometry (a generator of meshes/contact.py and its arguments),
its material per gmsh cell tag, the material that sets the compliance scale, its radius, and
how it is held: clamped on some facets (a wall's base) or free (a sphere, held by its own
d'Alembert body force, :class:`FreeBody`). The tags are those of meshes/contact.py: every
lower body has the contact face LOWER_CONTACT and the axis LOWER_AXIS. A new lower body is
one class here (or anywhere) with these members, plus its geometry in meshes/contact.py;
:func:`lower_body` maps a name and its numbers to the built-in ones.

Lengths by the (reduced) sphere radius a; materials are (Young's modulus, Poisson ratio)
pairs, of which the FE solids use only the ratios of the moduli (to the upper sphere's).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol

from meshes import contact

from ... import checks


@dataclass(frozen=True)
class FreeBody:
    """A free solid (a sphere): its film load is balanced by a uniform d'Alembert body force
    and its far pole is pinned in u_z. ``cell_tag`` and ``contact_tag`` are its gmsh groups
    (cells, contact face; meshes/contact.py), ``pole_z`` the height of the pinned pole and
    ``radius`` its radius (by a), ``direction`` the sign of the body force per unit film load
    (-1 for the upper sphere, which the film pushes up; +1 for a lower sphere, pushed down)."""

    cell_tag: int
    contact_tag: int
    pole_z: float
    direction: float
    radius: float

    @property
    def centre_z(self) -> float:
        """The height of the sphere's centre (by a)."""
        return self.pole_z + self.direction * self.radius


class LowerBody(Protocol):
    """The body below the film (module docstring). ``name``: its name in :data:`LOWER_BODIES`;
    ``material``: the (E, nu) of the half-space kernel's lower solid, which sets the
    compliance scale theta; ``sphere_radius``: the upper sphere's radius and ``radius`` its own
    (None: flat), by a; ``clamped``: the facet tags held fixed (empty for a free body)."""

    name: str
    material: tuple[float, float]
    sphere_radius: float
    radius: float | None
    clamped: tuple[int, ...]

    def materials(self) -> dict[int, tuple[float, float]]:
        """(E, nu) per gmsh cell tag of the lower body."""

    def free_body(self) -> FreeBody | None:
        """The lower body as a free solid, or None when it is clamped."""

    def geometry(self, gap: float, contact_radii, size: float) -> tuple:
        """(generator, arguments): ``generator(*arguments)`` builds the gmsh model of the upper
        sphere at ``gap`` above this body, both contact faces through ``contact_radii`` (by a),
        the far parts ``size`` away (meshes/contact.py)."""


def checked_material(name: str, pair) -> tuple[float, float]:
    """(E, nu) checked: E > 0, -1 < nu < 0.5 (``name`` names the solid in the error)."""
    young, poisson = pair
    checks.positive(f"{name} Young's modulus", young)
    checks.number(
        f"{name} Poisson ratio", poisson, lower=-1.0, upper=0.5, lower_open=True, upper_open=True
    )
    return float(young), float(poisson)


@dataclass(frozen=True)
class Wall:
    """A wall block [0, size] x [-size, 0] of one ``material``, clamped at its base."""

    material: tuple[float, float] = (1.0, 0.3)
    name = "wall"
    sphere_radius = 1.0
    radius = None
    clamped = (contact.LOWER_BOTTOM,)

    def __post_init__(self):
        object.__setattr__(self, "material", checked_material("wall", self.material))

    def materials(self):
        return {contact.LOWER: self.material}

    def free_body(self):
        return None

    def geometry(self, gap, contact_radii, size):
        return contact.build, (gap, contact_radii, self.name, size, 1.0, 1.0, None)


@dataclass(frozen=True)
class CoatedWall:
    """A wall block of ``material`` (the substrate) under a bonded ``coating`` (E, nu) of
    ``thickness`` (by a, > 0), clamped at its base."""

    thickness: float
    material: tuple[float, float] = (1.0, 0.3)
    coating: tuple[float, float] = (1.0, 0.3)
    name = "coated"
    sphere_radius = 1.0
    radius = None
    clamped = (contact.LOWER_BOTTOM,)

    def __post_init__(self):
        object.__setattr__(self, "material", checked_material("wall", self.material))
        object.__setattr__(self, "coating", checked_material("coating", self.coating))
        checks.positive("coating_thickness", self.thickness)

    def materials(self):
        return {contact.LOWER: self.material, contact.COATING: self.coating}

    def free_body(self):
        return None

    def geometry(self, gap, contact_radii, size):
        return contact.build, (gap, contact_radii, self.name, size, 1.0, 1.0, self.thickness)


@dataclass(frozen=True)
class LowerSphere:
    """A second, free sphere of ``material`` below the film. a is the reduced radius and
    ``radius_ratio`` = a1/a2 (upper over lower): a1 = a (1 + ratio), a2 = a (1 + 1/ratio)."""

    material: tuple[float, float] = (1.0, 0.3)
    radius_ratio: float = 1.0
    name = "sphere"
    clamped = ()

    def __post_init__(self):
        object.__setattr__(self, "material", checked_material("wall", self.material))
        checks.positive("radius_ratio", self.radius_ratio)

    @property
    def sphere_radius(self):
        return 1 + self.radius_ratio

    @property
    def radius(self):
        return 1 + 1 / self.radius_ratio

    def materials(self):
        return {contact.LOWER: self.material}

    def free_body(self):
        return FreeBody(contact.LOWER, contact.LOWER_CONTACT, -2 * self.radius, 1.0, self.radius)

    def geometry(self, gap, contact_radii, size):
        arguments = (gap, contact_radii, self.name, size, self.sphere_radius, self.radius, None)
        return contact.build, arguments


LOWER_BODIES = {"wall": Wall, "coated": CoatedWall, "sphere": LowerSphere}
"""The built-in lower bodies by name."""


def lower_body(
    name: str, wall=(1.0, 0.3), coating=(1.0, 0.3), coating_thickness=None, radius_ratio=1.0
) -> LowerBody:
    """The built-in lower body ``name`` (:data:`LOWER_BODIES`) with its numbers: ``wall`` the
    (E, nu) of the wall, the coated wall's substrate or the lower sphere; ``coating`` and
    ``coating_thickness`` (by a) of a coated wall; ``radius_ratio`` of two spheres (upper over
    lower). The numbers another body does not have are ignored."""
    checks.choice("lower", name, tuple(LOWER_BODIES))
    if name == "coated":
        return CoatedWall(coating_thickness, wall, coating)
    if name == "sphere":
        return LowerSphere(wall, radius_ratio)
    return Wall(wall)
