"""Elastic compliance of the two solids at the film nodes.

A compliance maps the film pressure to the gap opening by elastic deformation,

    W_i = sum_j C_ij P_j,

with P in units of mu V0 a / x0^2 at the film nodes ``radii`` (in units of sqrt(a x0)) and W in
units of x0. The time integrator only uses ``radii`` and ``matrix``; it does not know whether the
solids are elastic half-spaces (:mod:`ehdfem.solids.halfspace`) or finite-element meshes
(:mod:`ehdfem.solids.fe.solids`). C is proportional to eps, so a compliance built once serves
every St, and every eps through ``with_eps``: a study at fixed geometry and materials builds
one and passes it to :func:`ehdfem.collision.collide`.
"""

from __future__ import annotations

import copy
import math
from typing import Protocol

import numpy as np


def default_shear_traction(model: str) -> bool:
    """The tangential surface effects a collision takes when its inputs leave them to the
    solids (``shear_traction`` None; docs/architecture.md, "Inputs of the physics and
    numerics"): on for the FE solids ``model`` "fem" (finite delta: their faces carry the
    squeeze flow's shear traction), off for the half-space theory and rigid solids (the
    leading order in delta, where the traction's effects, of order sqrt(delta), drop out)."""
    return model == "fem"


class Compliance(Protocol):
    """What the film and the time integrator need from an elasticity model."""

    radii: np.ndarray  # (N,) film nodes, scaled by sqrt(a x0), increasing, radii[0] = 0
    matrix: np.ndarray  # (N, N) gap opening W (scaled by x0) per unit nodal pressure
    eps: float | None  # the elasticity parameter the matrix is built for (None: rigid)
    model: str  # the name of the elasticity model ("halfspace", "fem", "rigid")
    surface_radii: tuple  # radii of the sphere and the lower body by a (math.inf: a wall)
    shear_matrix: np.ndarray | None  # (N, N) gap opening per unit nodal squeeze-shear traction
    # T (by sqrt(delta) mu V0 a / x0^2, :meth:`ehdfem.film.reynolds.Film.squeeze_shear`);
    # None: not applied
    surface_sum_matrix: np.ndarray | None  # (N, N) sum of the two surfaces' displacements along
    # z (from the wall into the sphere; by x0) per unit nodal pressure; None: zero (identical
    # half-spaces, rigid solids). The sliding film's force needs it (ehdfem.tangential.motion).
    surface_radial_matrix: np.ndarray | None  # (N, N) mean radial displacement of the two faces,
    # (u_r sphere face + u_r lower face)/2, positive away from the axis (by x0), per unit nodal
    # pressure; None: zero (the surfaces' radial velocity is not carried in the film's flux)

    def deflection(self, pressure: np.ndarray) -> np.ndarray:
        """Gap opening W (by x0) for nodal pressures P (by mu V0 a / x0^2)."""

    def with_eps(self, eps: float) -> Compliance:
        """The same solids at another eps (the matrix scaled by eps / self.eps)."""

    def close(self) -> None:
        """Free what the solids hold outside Python (the FE factorisation); a no-op else."""


class ProportionalToEps:
    """Solids whose matrices are factor(eps) times eps-free unit matrices: ``_set_eps`` forms
    them at an eps, ``with_eps`` gives a copy at another."""

    def factor(self, eps: float | None) -> float:
        """x0 per unit of the unit matrices at ``eps``."""
        raise NotImplementedError

    def with_eps(self, eps: float):
        """The same solids at ``eps`` (self if eps is unchanged)."""
        if eps == self.eps:
            return self
        other = copy.copy(self)
        other._set_eps(eps)
        return other


class LinearCompliance(ProportionalToEps):
    """A compliance C = factor(eps) * unit_matrix: ``unit_matrix`` comes from the solids
    (half-space kernel, FE condensation) and ``factor`` turns it into the units of the module
    docstring at a given eps; the same for the squeeze-shear opening ``unit_shear`` (None: the
    shear traction of the film is not applied), the faces' displacement sum along z
    ``unit_surface_sum`` and their mean radial displacement per unit pressure
    ``unit_surface_radial`` (None: zero). Subclasses define ``factor``. The surfaces are a
    sphere of radius a on a wall unless a subclass says otherwise."""

    surface_radii = (1.0, math.inf)

    def __init__(
        self,
        radii: np.ndarray,
        unit_matrix: np.ndarray,
        eps: float | None,
        unit_shear=None,
        unit_surface_sum=None,
        unit_surface_radial=None,
    ):
        self.radii = np.asarray(radii, dtype=float)
        self.unit_matrix, self.unit_shear = unit_matrix, unit_shear
        self.unit_surface_sum = unit_surface_sum
        self.unit_surface_radial = unit_surface_radial
        self._set_eps(eps)

    def _set_eps(self, eps):
        self.eps = eps
        factor = self.factor(eps)

        def scaled(unit):
            return None if unit is None else factor * unit

        self.matrix = factor * self.unit_matrix
        self.shear_matrix = scaled(self.unit_shear)
        self.surface_sum_matrix = scaled(self.unit_surface_sum)
        self.surface_radial_matrix = scaled(self.unit_surface_radial)

    def deflection(self, pressure: np.ndarray) -> np.ndarray:
        """Gap opening W (by x0) for nodal pressures P (by mu V0 a / x0^2)."""
        return self.matrix @ np.asarray(pressure, dtype=float)

    def close(self) -> None:
        """Nothing to free for a matrix held in numpy."""


class RigidSolids(LinearCompliance):
    """The rigid limit eps -> 0: no deformation, W = 0 (for checks against exact solutions);
    rigid whatever eps it is asked for."""

    model = "rigid"

    def __init__(self, radii: np.ndarray):
        n = len(radii)
        super().__init__(radii, np.zeros((n, n)), None)

    def factor(self, eps):
        return 0.0

    def with_eps(self, eps):
        return self


FILM_REACH_LIMIT = 0.7  # the FE solids take a film reaching up to this share of the smaller
# sphere radius (their meshes' contact faces); an immersed film reaches R = 30 sqrt(a x0)

MODE_ONE_LOADS = ("pressure", "sphere_radial", "sphere_hoop", "wall_radial", "wall_hoop")
MODE_ONE_DISPLACEMENTS = (
    "sphere_radial",
    "sphere_hoop",
    "sphere_normal",
    "wall_radial",
    "wall_hoop",
    "wall_normal",
)


class ModeOneCompliance(ProportionalToEps):
    """The solids' response to the film's azimuthal mode-1 (cos phi) loads at the film nodes.

    Frame: z normal to the wall, pointing from the wall into the sphere; x the sliding
    direction, phi measured from it. Loads, each an amplitude on the film nodes (hat functions,
    zero beyond the last node), in the order of ``MODE_ONE_LOADS``:

    - "pressure": the mode-1 film pressure q(R) cos(phi), acting normally on both faces: it
      pushes the sphere up and the wall down (on the half-spaces a traction -/+ q cos phi along
      z; the FE sphere's curved face also takes its radial part, of relative size r/a); by the
      film pressure unit mu V0 a / x0^2;
    - "<face>_radial", "<face>_hoop": the film's shear traction on that face, t_r = A(R) cos phi
      and t_phi = -B(R) sin phi (A = B = tau(R): a traction tau(R) along x); by sqrt(delta) times
      the film pressure unit (as the squeeze shear of
      :meth:`ehdfem.film.reynolds.Film.squeeze_shear`).

    Displacements of each face, in the order of ``MODE_ONE_DISPLACEMENTS``: u_r = U_r cos phi,
    u_phi = -U_phi sin phi, u_z = U_z cos phi (global z, so the gap opens by U_z of the sphere
    minus U_z of the wall), by x0, each free sphere's relative to its rigid motion. Radii R by
    sqrt(a x0). ``matrix`` (6N, 5N) = factor(eps) * ``unit_matrix``, proportional to eps like
    the axisymmetric compliance; ``block(displacement, load)`` is one (N, N) block.
    """

    model = "none"

    def __init__(self, radii, unit_matrix: np.ndarray, eps: float | None):
        self.radii = np.asarray(radii, dtype=float)
        n = len(self.radii)
        if unit_matrix.shape != (6 * n, 5 * n):
            raise ValueError(f"mode-1 unit matrix must be (6N, 5N) = {(6 * n, 5 * n)}")
        self.unit_matrix = unit_matrix
        self._set_eps(eps)

    def _set_eps(self, eps):
        self.eps = eps
        self.matrix = self.factor(eps) * self.unit_matrix

    def close(self) -> None:
        """Free what the solids hold outside Python (an FE factorisation); a no-op here."""

    def block(self, displacement: str, load: str) -> np.ndarray:
        """The (N, N) block of ``matrix`` from nodal ``load`` to nodal ``displacement``."""
        n = len(self.radii)
        i = MODE_ONE_DISPLACEMENTS.index(displacement)
        j = MODE_ONE_LOADS.index(load)
        return self.matrix[i * n : (i + 1) * n, j * n : (j + 1) * n]
