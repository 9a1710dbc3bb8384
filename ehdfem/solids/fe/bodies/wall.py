"""The FE model's default lower body: a wall block of the wall's material."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from meshes import contact

from .base import LowerBody, register


@register
@dataclass(frozen=True)
class Wall(LowerBody):
    """A wall block [0, size] x [-size, 0] (by a) of the wall's material, clamped at its base:
    the solid the half-space kernel stands for."""

    kind: ClassVar[str] = "wall"
    description: ClassVar[str] = "wall block"
    models: ClassVar[tuple[str, ...]] = ("halfspace", "fem")
    clamped: ClassVar[tuple[int, ...]] = (contact.LOWER_BOTTOM,)

    def materials(self, wall):
        return {contact.LOWER: wall}

    def geometry(self, gap, contact_radii, size):
        return contact.build, (gap, contact_radii, self.kind, size, 1.0, 1.0, None)
