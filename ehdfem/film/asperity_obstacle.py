"""The impact model's asperities as an obstacle: the solids' touch wherever and whenever the
film reaches the roughness, carried quasi-statically (scaled).

Scaled as in :mod:`ehdfem.motion.normal`: film thickness H and roughness sigma by x0, pressure
by mu V0 a / x0^2. The impact model takes the asperities as a rigid layer: the surfaces touch
where the film is sigma thick (docs/model.md, "Rough surfaces"). Where that touch is no short
collision of the sphere (the film reaching sigma during the rebound, at the rim where the
unloading solids close the exit constriction, or again after the impact), the rigid layer is
the contact constraint H >= h_c with a contact pressure P_c >= 0 where H = h_c (Signorini),
h_c = sigma (the touching state's thinnest film when the touch is located on it, within
TOUCH_TOL of sigma). The solids carry it with the film's pressure, H = X + S(R) + C (P + P_c),
as they carry Greenwood & Tripp's (:mod:`ehdfem.film.asperities`). It is imposed by a penalty
stiff against the solids at each node,

    P_c(H) = k (h_c - H)_+,    k = OBSTACLE_STIFFNESS / min_i C_ii,

so that a node pressed into the layer by a free overlap h_c - H_free settles at most about
(h_c - H_free) / (1 + OBSTACLE_STIFFNESS) into it (the contact pressure within about
1/OBSTACLE_STIFFNESS of the exact constraint's, tests/test_roughness.py against the
constrained solution), and the energy it stores, int_H^inf P_c dH = k (h_c - H)_+^2 / 2 per
area, is elastic: the solids give it back. The loaded thickness H = base + C P_c(H) and its
sensitivities are the same Newton as Greenwood & Tripp's (that Newton uses only the law's
pressure and slope).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .. import checks
from .asperities import GreenwoodTripp

# The penalty's stiffness against the solids' own at a node: the obstacle's overlap is 1e-3 of
# the free overlap (the Newton of a step stays well conditioned: I + C K has entries of 1e3)
OBSTACLE_STIFFNESS = 1e3


@dataclass(frozen=True)
class AsperityObstacle:
    """The rigid asperity layer of height ``roughness`` h_c (by x0) as a contact pressure
    P_c = k (h_c - H)_+, ``stiffness`` k (by mu V0 a / x0^2 per x0; module docstring)."""

    roughness: float
    stiffness: float

    def __post_init__(self):
        checks.positive("roughness", self.roughness)
        checks.positive("stiffness", self.stiffness)

    @classmethod
    def on(cls, height: float, compliance: np.ndarray) -> AsperityObstacle:
        """The obstacle at ``height`` on solids of ``compliance`` C (by x0 per mu V0 a / x0^2):
        k = OBSTACLE_STIFFNESS / min_i C_ii (elastic solids: C_ii > 0)."""
        return cls(height, OBSTACLE_STIFFNESS / float(np.diag(compliance).min()))

    def pressure(self, h) -> np.ndarray:
        """P_c = k (h_c - H)_+ (by mu V0 a / x0^2)."""
        return self.stiffness * np.maximum(self.roughness - np.asarray(h), 0.0)

    def slope(self, h) -> np.ndarray:
        """dP_c/dH = -k where H < h_c, else 0."""
        return np.where(np.asarray(h) < self.roughness, -self.stiffness, 0.0)

    def energy(self, h) -> np.ndarray:
        """The energy stored per area, int_H^inf P_c dH = k (h_c - H)_+^2 / 2 (by
        mu V0 a / x0^2 times x0)."""
        return 0.5 * self.stiffness * np.maximum(self.roughness - np.asarray(h), 0.0) ** 2

    # the loaded thickness and its sensitivities: Greenwood & Tripp's Newton on this law
    thickness = GreenwoodTripp.thickness
    loaded = GreenwoodTripp.loaded
    _correction = staticmethod(GreenwoodTripp._correction)
