"""Closed forms for DEM of two free spheres: the sphere-on-wall forms (:mod:`ehdfem.dem.forms`)
at the pair's inertia factor, by the exact mapping of the pair's tangential motion onto the
wall's (docs/tangential.md, "Two spheres"; docs/studies.md, "Closed forms for DEM").

Inputs (dimensionless): St, eps, delta, P_cav and the layer by the reduced radius
a = a1 a2/(a1 + a2) and mass m = m1 m2/(m1 + m2), as the pair's normal motion takes them;
``radius_ratio`` a1/a2 and ``density_ratio`` rho2/rho1 (m1/m2 = (a1/a2)^3/(rho2/rho1)); the
inertia factors k1, k2 in (0, 2/3]; the initial spins s_i = a_i Omega_i(0)/U0 about one axis
(U0 the relative tangential speed of the centres at first touch; a1 Omega1 = U1 rolls on a
wall), of which only the contact spin w0 = s1 + s2 acts (give w0 as ``upper_spin`` alone).

The pair is the sphere on a wall of inertia factor 1/k = 1/(k1 (1 + m1/m2)) +
1/(k2 (1 + m2/m1)), each sphere taking the share c1 = k/(k1 (1 + m1/m2)), c2 = k/(k2 (1 +
m2/m1)) of the contact spin's change. The Couette force is linear in the slip u_s = U - w:
St dU/dT = -(delta/3) J u_s, k St dw/dT = (delta/3) J u_s, so U + k w is conserved and
u_s = (1 - w0) exp(-(1 + 1/k) delta I) from u_s(0) = 1 - w0, whence, with e_t^w(k) the wall's
form at k (no initial spin, as it was fitted),

    1 - e_t = (1 - w0) (1 - e_t^w(k)),   w - w0 = (1 - w0) (1 - e_t^w(k))/k,
    s_i - s_i(0) = c_i (w - w0),   tangential impulse on sphere 1 = e_t - 1 (by m U0).

e_n and St_c are the wall's (the relative normal motion, which does not depend on the
tangential one). The mapping is exact where the wall forms hold (half-spaces, the Couette
model, no friction: e_dry = 1; an immersed film cut at r = a, the reduced radius, as the pair
model cuts it), so the pair forms' errors are the wall forms' at k: the same relative error
in 1 - e_t and the spin changes, |1 - w0| times the absolute one.
"""

from __future__ import annotations

from .. import checks
from ..tangential.pair import SpherePair
from . import forms as shape


def sphere_pair(radius_ratio, density_ratio, upper_inertia, lower_inertia) -> SpherePair:
    """The pair (:class:`ehdfem.tangential.pair.SpherePair`: k and the shares) of
    ``radius_ratio`` a1/a2 > 0, ``density_ratio`` rho2/rho1 > 0 and the inertia factors k1, k2
    in (0, 2/3] (InputError naming the input outside)."""
    radius_ratio = checks.positive("radius_ratio", radius_ratio)
    density_ratio = checks.positive("density_ratio", density_ratio)
    return SpherePair(
        radius_ratio**3 / density_ratio, upper_inertia, lower_inertia, radius_ratio=radius_ratio
    )


def pair_restitution(
    forms: dict,
    St,
    eps,
    delta,
    p_cav,
    layer: str,
    radius_ratio=1.0,
    density_ratio=1.0,
    upper_inertia=0.4,
    lower_inertia=0.4,
    upper_spin=0.0,
    lower_spin=0.0,
) -> dict:
    """{"St_c", "e_n", "e_t", "upper_spin_change", "lower_spin_change", "contact_spin_change",
    "tangential_impulse", "inertia_factor"} of two spheres by the fitted wall ``forms``
    (module docstring; e_t relative, U1 - U2 at exit over U0; spin changes a_i DeltaOmega_i/U0;
    the impulse on the upper sphere by m U0), after refusing inputs outside the forms' box
    (InputError, a ValueError, naming the input and its range)."""
    pair = sphere_pair(radius_ratio, density_ratio, upper_inertia, lower_inertia)
    contact_spin = checks.number("upper_spin", upper_spin) + checks.number("lower_spin", lower_spin)
    wall = shape.restitution(forms, St, eps, delta, p_cav, layer, pair.inertia_factor)
    slip = 1.0 - contact_spin  # u_s(0) by U0
    e_t = 1.0 - slip * (1.0 - wall["e_t"])
    change = slip * wall["spin_change"]
    upper_share, lower_share = pair.shares
    return {
        "St_c": wall["St_c"],
        "e_n": wall["e_n"],
        "e_t": e_t,
        "upper_spin_change": upper_share * change,
        "lower_spin_change": lower_share * change,
        "contact_spin_change": change,
        "tangential_impulse": e_t - 1.0,
        "inertia_factor": pair.inertia_factor,
    }
