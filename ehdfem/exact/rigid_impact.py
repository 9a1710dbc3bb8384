"""The impact of a rigid sphere on a plane with Coulomb friction, exact (rigid-body impact
theory: the normal impulse builds up while the friction opposes a slip of constant sign, and a
sphere on a plane has no coupling of the normal and tangential impulses).

psi = u_s U0 / (|V| V0), the contact point's tangential velocity over the normal approach
velocity; k = I / (m a^2), mu the friction coefficient, e_n the normal restitution. The
tangential impulse is at most mu (1 + e_n) m |V|, and changes psi by (1 + 1/k) times it over
m |V|: the contact slides throughout, or sticks (then rolls, psi_out = 0).
"""

from __future__ import annotations

import numpy as np


def frictional_impact(psi_in: float, mu: float, e_n: float, k: float) -> tuple[float, bool]:
    """(psi_out, stuck) of a rigid sphere's impact on a plane with Coulomb friction ``mu``,
    normal restitution ``e_n`` and inertia factor k (psi = contact-point tangential velocity
    over the normal approach velocity; module docstring): sliding throughout,
    psi_out = psi_in - (1 + 1/k) mu (1 + e_n) sign(psi_in); stuck (psi_out = 0) once
    |psi_in| <= (1 + 1/k) mu (1 + e_n)."""
    reach = (1.0 + 1.0 / k) * mu * (1.0 + e_n)
    if abs(psi_in) <= reach:
        return 0.0, True
    return psi_in - reach * np.sign(psi_in), False
