"""ehdfem: elastohydrodynamic wet collisions of a sphere with a liquid-covered wall.

The public API (dimensionless inputs on the scales of Davis, Serayssol & Hinch 1986, physical
inputs in SI; see :mod:`ehdfem.inputs.scales`):

- :func:`collide`: one collision, normal and tangential, with the half-space or FE solids;
- :class:`CollisionParameters` (St, eps, delta, P_cav, ...) and :class:`PhysicalCollision`
  (materials, liquid, speed, layer in SI; :func:`from_presets` builds one from preset names);
- :func:`elasticity` and :func:`film_radii`: a compliance built once and passed to
  :func:`collide` for a whole sweep at fixed geometry and materials;
- :func:`solve_normal`, :func:`solve_tangential`: the two motions on their own;
- :func:`critical_stokes`, :func:`critical_speed`: the rebound threshold;
- :class:`RunConfig`: how a collision is computed (model, lower body, tangential film model,
  numerics; :mod:`ehdfem.config`), and :class:`IntegratorOptions`, its time-step
  tolerance and limits;
- :func:`bounce_sphere` with :class:`BounceInputs` (SI): a sphere settling onto a wall in a
  liquid and bouncing until it rests, each contact an immersed EHD collision
  (:class:`BounceResult`); its parts are in the subpackage :mod:`ehdfem.bounce`.
"""

from .bounce.inputs import BounceInputs
from .bounce.result import BounceResult
from .bounce.trajectory import bounce_sphere
from .collision import CollisionResult, collide, elasticity, film_radii
from .config import RunConfig
from .inputs.scales import CollisionParameters, PhysicalCollision, from_presets
from .motion.normal import NormalResult, solve_normal
from .motion.timestepping import IntegratorOptions
from .study.sweep import critical_speed, critical_stokes
from .tangential.motion import TangentialResult, solve_tangential
from .version import __version__

__all__ = [
    "BounceInputs",
    "BounceResult",
    "CollisionParameters",
    "CollisionResult",
    "IntegratorOptions",
    "NormalResult",
    "PhysicalCollision",
    "RunConfig",
    "TangentialResult",
    "__version__",
    "bounce_sphere",
    "collide",
    "critical_speed",
    "critical_stokes",
    "elasticity",
    "film_radii",
    "from_presets",
    "solve_normal",
    "solve_tangential",
]
