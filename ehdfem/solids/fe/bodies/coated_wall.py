"""A coated wall: a wall block under a bonded coating of its own material."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from meshes import contact

from ....settings import setting
from .base import LowerBody, register


@register
@dataclass(frozen=True)
class CoatedWall(LowerBody):
    """A wall block of the wall's material (the substrate) under a bonded coating of thickness
    t (by a), Young's modulus E_c = ``coating_stiffness`` E_wall and Poisson ratio
    ``coating_poisson``, clamped at its base."""

    kind: ClassVar[str] = "coated"
    description: ClassVar[str] = "coated wall block (FE solids)"
    clamped: ClassVar[tuple[int, ...]] = (contact.LOWER_BOTTOM,)
    coating_thickness: float = setting(
        help="coating thickness t", unit="by a", lower=0.0, lower_open=True
    )
    coating_stiffness: float = setting(
        1.0, help="coating Young's modulus E_c", unit="by the wall's", lower=0.0, lower_open=True
    )
    coating_poisson: float = setting(
        0.3, help="coating Poisson ratio", lower=-1.0, upper=0.5, lower_open=True, upper_open=True
    )

    def materials(self, wall):
        """The substrate of the wall's (E, nu), the coating of (E_c, nu_c), E_c = stiffness E."""
        coating = (self.coating_stiffness * wall[0], self.coating_poisson)
        return {contact.LOWER: wall, contact.COATING: coating}

    def geometry(self, gap, contact_radii, size):
        arguments = (gap, contact_radii, self.kind, size, 1.0, 1.0, self.coating_thickness)
        return contact.build, arguments
