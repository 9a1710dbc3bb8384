"""Elastic compliance of the two solids at the film nodes.

A compliance object maps the film pressure to the gap opening by elastic deformation,

    W_i = sum_j C_ij P_j,

with P in units of mu V0 a / x0^2 at the film nodes ``radii`` (in units of sqrt(a x0)) and W in
units of x0. The time integrator only uses ``radii`` and ``matrix``; it does not know whether the
solids are elastic half-spaces (:mod:`ehdfem.compliance.halfspace`) or finite-element meshes.
"""

from typing import Protocol

import numpy as np


class Compliance(Protocol):
    """What the film and the time integrator need from an elasticity model."""

    radii: np.ndarray  # (N,) film nodes, scaled by sqrt(a x0), increasing, radii[0] = 0
    matrix: np.ndarray  # (N, N) gap opening W (scaled by x0) per unit nodal pressure


class RigidSolids:
    """The rigid limit eps -> 0: no deformation, W = 0 (for checks against exact solutions)."""

    def __init__(self, radii: np.ndarray):
        self.radii = np.asarray(radii, dtype=float)
        self.matrix = np.zeros((len(self.radii), len(self.radii)))
