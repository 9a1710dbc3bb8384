"""Walton's (1993) three-parameter impact law: the normal restitution e_n, Coulomb's mu and the
tangential restitution of a sticking contact beta_0.

psi = u_s U0 / (|V| V0), the contact point's tangential velocity over the normal approach
velocity (as in :mod:`ehdfem.exact.rigid_impact`), k = I / (m a^2). The contact point's
tangential velocity is reversed and scaled by beta, psi_out = -beta psi_in, with

    beta = min(beta_0, -1 + (1 + 1/k) mu (1 + e_n) / |psi_in|):

Coulomb's sliding impact (the rigid-body law) where the contact slides throughout, and the
constant beta_0 in [-1, 1] below (beta_0 = 0 is the rigid-body stick, which leaves rolling;
beta_0 > 0 a reversal of the slip by the contact's tangential elasticity). The compliant
contact's rigid-impact limits set beta_0: its ratio in the limit of complete adhesion,
beta_0 = -Psi_2/Psi_1 (:func:`ehdfem.exact.compliant_impact.adhesive_ratio`).
"""

from __future__ import annotations

import numpy as np


def walton_impact(psi_in, mu: float, e_n: float, k: float, beta_0: float):
    """psi_out = -beta psi_in of Walton's law (module docstring) for ``psi_in`` (arrays
    broadcast), Coulomb's ``mu``, the normal restitution ``e_n``, the inertia factor k and the
    sticking contact's tangential restitution ``beta_0`` in [-1, 1]."""
    if not -1.0 <= beta_0 <= 1.0:
        raise ValueError(f"beta_0 = {beta_0!r} must lie in [-1, 1]")
    psi_in = np.asarray(psi_in, dtype=float)
    reach = (1.0 + 1.0 / k) * mu * (1.0 + e_n)
    sliding = np.abs(psi_in) - reach  # psi_out of the sliding impact, by sign(psi_in)
    sticking = -beta_0 * np.abs(psi_in)
    return np.sign(psi_in) * np.maximum(sticking, sliding)
