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
- :func:`bounce_sphere` with :class:`BounceInputs` (SI) and :class:`BounceRun` (its
  numerics): a sphere settling onto a wall in a liquid and bouncing until it rests, each
  contact an immersed EHD collision (:class:`BounceResult`); its parts are in the subpackage
  :mod:`ehdfem.bounce`.
"""

import importlib

from .version import __version__

# the public names and the modules that define them, imported on first use: `import ehdfem`
# (and so the command's start, where a Ctrl-C ends in one line) costs no numpy or scipy
_PUBLIC = {
    "BounceInputs": "bounce.inputs",
    "BounceResult": "bounce.result",
    "BounceRun": "bounce.run",
    "bounce_sphere": "bounce.trajectory",
    "CollisionResult": "collision",
    "collide": "collision",
    "elasticity": "collision",
    "film_radii": "collision",
    "RunConfig": "config",
    "CollisionParameters": "inputs.scales",
    "PhysicalCollision": "inputs.scales",
    "from_presets": "inputs.scales",
    "NormalResult": "motion.normal",
    "solve_normal": "motion.normal",
    "IntegratorOptions": "motion.timestepping",
    "critical_speed": "study.sweep",
    "critical_stokes": "study.sweep",
    "solve_tangential": "tangential.motion",
    "TangentialResult": "tangential.result",
}


def __getattr__(name: str):
    """A public name of :data:`__all__`, from its module (imported then)."""
    if name not in _PUBLIC:
        raise AttributeError(f"module 'ehdfem' has no attribute {name!r}")
    return getattr(importlib.import_module(f".{_PUBLIC[name]}", __name__), name)


__all__ = [
    "BounceInputs",
    "BounceResult",
    "BounceRun",
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
