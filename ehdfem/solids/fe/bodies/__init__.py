"""The lower bodies of the FE solids, one file each (:mod:`.base`: what a lower body is, and
the registry :data:`LOWER_BODIES` that the run configuration and the command line read). The
built-in bodies are registered here, the default first; a body declared elsewhere registers
itself with :func:`register`."""

from .base import LOWER_BODIES, FreeBody, LowerBody, checked_material, register

# the built-in bodies, registered in this order (the default first)
# isort: off
from .wall import Wall
from .coated_wall import CoatedWall
from .lower_sphere import LowerSphere
# isort: on

__all__ = [
    "LOWER_BODIES",
    "CoatedWall",
    "FreeBody",
    "LowerBody",
    "LowerSphere",
    "Wall",
    "checked_material",
    "register",
]
