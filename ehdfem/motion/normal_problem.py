"""The normal problem: everything the normal integration reads, and its digest.

:func:`ehdfem.motion.normal.solve_normal` integrates the film, the solids and the sphere
(:mod:`ehdfem.motion.normal`) from the pieces gathered here and from nothing else of its
inputs: the film nodes R (by sqrt(a x0)), the compliance C and, where the solids apply them,
the squeeze shear's opening C_T and the faces' radial motion (C_r with sqrt(delta)), the
undeformed gap S(R), the layer, the viscosity law, the cavitation model, the asperities'
pressure law (Greenwood & Tripp's, at eps and delta) and touching height (the impact model's
sigma, by x0), the sphere's equation (St and the applied forces), e_dry and the time-step
options. Two collisions whose problems are equal (equal digests) have the same normal motion
bit for bit: inputs the integration does not read (the angle, the spin, the inertia factor,
the friction of the solid contact; delta where the solids, the gap and the asperities do not
see it, as on half-spaces under a thin layer) change no piece, and so no digest. The digest
is taken of the pieces themselves, not of a list of inputs thought to matter: a new input
that reaches the integration reaches it through a piece, and so the digest.
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass, fields, is_dataclass
from typing import TYPE_CHECKING

import numpy as np

from .. import checks
from ..film.gap import Paraboloid, default_gap
from .forces import LAYER_SURFACE, SphereForce
from .implicit_step import SurfaceMotion
from .sphere import Sphere
from .timestepping import IntegratorOptions

if TYPE_CHECKING:
    from ..inputs.scales import CollisionParameters
    from ..solids.compliance import Compliance


@dataclass(frozen=True)
class NormalProblem:
    """The inputs of one normal integration (scaled as in :mod:`ehdfem.motion.normal`):
    ``radii`` R of the film nodes (by sqrt(a x0)); ``matrix`` C (W = C P, by x0 per unit
    pressure mu V0 a / x0^2), ``shear_matrix`` C_T (by x0 per unit sqrt(delta) mu V0 a / x0^2;
    None: not applied), ``surface_motion`` (the faces' mean radial displacement per unit
    pressure with sqrt(delta); None: not carried); ``layer``; ``shape`` the undeformed gap S(R)
    (by x0); ``viscosity`` the viscosity law; ``cavitation`` the cavitation model (a component
    of :data:`ehdfem.film.cavitation.MODELS`; its solver is made per integration);
    ``asperity_law`` Greenwood & Tripp's pressure at eps and delta (None: smooth, or the
    impact model); ``touch`` the impact model's touching film sigma (by x0; None: no touch);
    ``sphere`` (:class:`ehdfem.motion.sphere.Sphere`: St and the applied forces); ``e_dry``;
    ``options`` (:class:`ehdfem.motion.timestepping.IntegratorOptions`)."""

    radii: np.ndarray
    matrix: np.ndarray
    shear_matrix: np.ndarray | None
    surface_motion: SurfaceMotion | None
    layer: str
    shape: Paraboloid
    viscosity: object
    cavitation: object
    asperity_law: object
    touch: float | None
    sphere: Sphere
    e_dry: float
    options: IntegratorOptions

    def digest(self) -> str | None:
        """A SHA-256 hex digest of every piece, bit for bit (arrays by dtype, shape and bytes,
        floats exactly, objects by their type and attributes); None if a piece holds something
        that cannot be compared so (a function, say): such a problem is never taken for
        another."""
        hasher = hashlib.sha256()
        try:
            _feed(hasher, self)
        except TypeError:
            return None
        return hasher.hexdigest()


def normal_problem(
    params: CollisionParameters,
    compliance: Compliance,
    options: IntegratorOptions | None = None,
    forces: tuple[SphereForce, ...] = (),
) -> NormalProblem:
    """The normal problem of the collision ``params`` (dimensionless; eps is already in the
    compliance) on the solids ``compliance`` at their film nodes, with the time-step
    ``options`` (default :class:`~ehdfem.motion.timestepping.IntegratorOptions`) and the
    further ``forces`` on the sphere (:func:`ehdfem.motion.normal.solve_normal`). Refuses an
    exit gap above the layer's surface for a thin layer."""
    options = options or IntegratorOptions()
    if options.exit_gap > LAYER_SURFACE and params.layer != "immersed":
        raise checks.InputError(
            f"exit_gap = {options.exit_gap!r} needs an immersed layer: a sphere leaves a "
            f"{params.layer} layer at its surface (the allowed value is 1)"
        )
    gap = params.gap or default_gap(compliance.model, params.layer)
    radial = getattr(compliance, "surface_radial_matrix", None)
    surface_motion = None if radial is None else SurfaceMotion(radial, float(np.sqrt(params.delta)))
    return NormalProblem(
        radii=np.asarray(compliance.radii, dtype=float),
        matrix=compliance.matrix,
        shear_matrix=compliance.shear_matrix,
        surface_motion=surface_motion,
        layer=params.layer,
        shape=gap.shape(params.delta, compliance.surface_radii),
        viscosity=params.viscosity_law(),
        cavitation=params.cavitation,
        asperity_law=params.asperities.pressure_law(params.eps, params.delta),
        touch=params.asperities.touch(),
        sphere=Sphere.of(params, forces),
        e_dry=params.e_dry,
        options=options,
    )


def _feed(hasher, value) -> None:
    """Feed ``value`` into ``hasher`` so that equal digests mean equal values bit for bit:
    its type with it, floats as their exact hex, arrays by dtype, shape and bytes, sequences
    and mappings item by item, dataclasses field by field and other objects attribute by
    attribute; TypeError for anything else (functions, handles)."""
    kind = type(value)
    hasher.update(f"<{kind.__module__}.{kind.__qualname__}>".encode())
    if value is None or isinstance(value, (bool, int, str)):
        hasher.update(repr(value).encode())
    elif isinstance(value, float):
        hasher.update(float(value).hex().encode())
    elif isinstance(value, np.generic):
        _feed(hasher, value.item())
    elif isinstance(value, np.ndarray):
        hasher.update(f"{value.dtype.str}{value.shape}".encode())
        hasher.update(np.ascontiguousarray(value).tobytes())
    elif isinstance(value, (tuple, list)):
        for item in (len(value), *value):
            _feed(hasher, item)
    elif isinstance(value, dict):
        _feed(hasher, sorted(value.items(), key=lambda item: repr(item[0])))
    elif is_dataclass(value):
        _feed(hasher, [(f.name, getattr(value, f.name)) for f in fields(value)])
    elif hasattr(value, "__dict__") and not callable(value):
        _feed(hasher, vars(value))
    else:
        raise TypeError(f"no digest of {kind.__qualname__}")
