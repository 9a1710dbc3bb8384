"""Coulomb friction on real rough collisions: both asperity models end to end.

The normal motion is a real rough collision (run setting asperities = "impact" or
"greenwood-tripp"); the friction coefficient and the angle act on the tangential motion only
(the normal motion does not depend on them), so they are varied with dataclasses.replace on
one normal solution and ehdfem.collision.with_tangential.

Closed forms used (docs/tangential.md, "Coulomb friction of the solid contact"):
- Coulomb's impulses conserve U + k a Omega, and so does the Couette film; a contact that
  sticks leaves U = a Omega, so a sphere without initial spin leaves rolling with
  e_t = 1/(1 + k) exactly in the Couette model (it acts on the slip only);
- while the contact slides throughout, its tangential impulse is (mu / tan(angle)) times the
  solids' normal impulse N_s (the impact's St (1 + e_dry) |V_c| plus int F_a dT), so
  mu_eff = tan(angle) (1 - e_t) / (1 + e_n) = mu s + f, with s = N_s / (St (1 + e_n)) the
  solids' share of the normal impulse (output solid_impulse_share) and f >= 0 the film's
  share, which in the Couette model is at most the film-alone value (mu = 0): the slip it
  shears is smaller with friction.
"""

from dataclasses import replace
from functools import cache

import numpy as np
import pytest
import scipy.integrate

from ehdfem.collision import collide, with_tangential
from ehdfem.inputs.scales import CollisionParameters
from ehdfem.outputs import registry
from ehdfem.tangential.friction import rigid_impact

pytestmark = pytest.mark.serial

THIN = dict(layer="thin", delta=0.01, p_cav=-2.0, e_dry=0.8)
NODES = 40
ROUNDING = 1e-12  # closed forms of O(1) numbers, reproduced up to a few roundings
K = 0.4  # a solid sphere


@cache
def rough(St, eps, sigma, asperities):
    """A real rough oblique collision (30 degrees, no friction yet), thin layer."""
    params = CollisionParameters(St=St, eps=eps, angle=30.0, roughness=sigma, **THIN)
    return collide(params, nodes=NODES, asperities=asperities, tangential="couette")


def sliding(result, model, **changes):
    """``result`` with its parameters changed (friction_coefficient, angle: the tangential
    motion's inputs only) and the tangential ``model`` solved again."""
    params = replace(result.params, **changes)
    normal = replace(result.normal, params=params)
    return with_tangential(replace(result, params=params, normal=normal), model)


GRID = [
    (St, eps, sigma, asperities)
    for St in (5.0, 50.0)
    for eps in (1e-4, 1e-2)
    for sigma in (0.03, 0.2)
    for asperities in ("impact", "greenwood-tripp")
]


@pytest.mark.parametrize("St,eps,sigma,asperities", GRID)
def test_energy_is_never_created(St, eps, sigma, asperities):
    """Over mu (0.05, 0.5), the angle (15, 60 deg) and the Couette and sliding films: the
    tangential kinetic energy never rises above its impact value (1e-12 of it: the exact
    integrations only remove energy, the sliding film by its balance, which closes to 0.05 of
    the energy lost: its BDF2 error on the normal motion's steps, at most 9e-3 here); every
    friction impulse dissipates; the normal motion's kinetic plus stored energy never exceeds
    St/2 by more than its own balance error; so the total, normal plus tan^2(angle) times
    tangential (both by m V0^2 / St), is never created either. The solids carry 0.3 to 100 %
    of the normal impulse where the film reaches sigma; at eps 1e-2 the flattened film stays
    above 0.055, so sigma = 0.03 is never reached: the impact model's contact takes no friction
    impulse (Greenwood & Tripp's asperities carry their Gaussian tail's load, 1e-5 of the
    normal impulse and less)."""
    base = rough(St, eps, sigma, asperities)
    hist = base.normal.history
    slack = base.normal.energy_error + 1e-12
    normal_energy = np.asarray(hist.kinetic) + np.asarray(hist.elastic) - hist.elastic[0]
    assert normal_energy.max() <= 0.5 * St * (1 + slack)
    frictionless = asperities == "impact" and base.normal.min_film_thickness > sigma
    for mu in (0.05, 0.5):
        for angle in (15.0, 60.0):
            tangent = np.tan(np.radians(angle))
            for model in ("couette", "lubrication"):
                result = sliding(base, model, friction_coefficient=mu, angle=angle)
                t = result.tangential
                kinetic = 0.5 * St * (t.velocity**2 + K * t.spin**2)
                assert kinetic.max() <= kinetic[0] * (1 + 1e-12), (mu, angle, model)
                assert np.diff(t.friction.dissipated).min() >= 0.0
                assert not (frictionless and np.any(t.friction.impulse))
                total = normal_energy + tangent**2 * kinetic
                assert total.max() <= 0.5 * St * (1 + tangent**2) * (1 + slack)
                if t.energy is not None:
                    assert t.energy.balance_error < 0.05, (mu, angle, t.energy.balance_error)


@pytest.mark.parametrize("asperities", ["impact", "greenwood-tripp"])
def test_sticking_contact_leaves_rolling(asperities):
    """mu = 1 at 5 degrees stops the slip (the asperities of Greenwood & Tripp's model carry
    1.8 % of the normal impulse here: (1 + 1/k) mu s (1 + e_n) = 0.12 > psi_in = 0.087, while
    at 15 degrees they slide throughout); the Couette film acts on the slip only, so the
    sphere leaves rolling: psi_out = 0 and e_t = 1/(1 + k) (module docstring), to rounding.
    The impact model's jump is the rigid-body stick (impact_psi_out = 0); the sliding film
    leaves a slip of the film's making only (its force and torque on a rolling sphere differ),
    4e-5 of psi_in here (bound 1e-3)."""
    base = rough(50.0, 1e-4, 0.1, asperities)
    result = sliding(base, "couette", friction_coefficient=1.0, angle=5.0)
    out = registry.computed(result)
    assert out["contact_stuck"] is True
    assert abs(out["psi_out"]) <= ROUNDING
    assert result.tangential.e_t == pytest.approx(1.0 / (1.0 + K), abs=ROUNDING)
    if asperities == "impact":
        assert out["impact_psi_out"] == 0.0
    film = registry.computed(sliding(base, "lubrication", friction_coefficient=1.0, angle=5.0))
    assert film["contact_stuck"] is True
    assert abs(film["psi_out"]) < 1e-3 * film["psi_in"]


@pytest.mark.parametrize("St", [100.0, 1000.0])
def test_effective_friction_tends_to_mu_when_sliding_throughout(St):
    """Impact model, a nearly rigid sphere (eps 1e-6), sigma = 0.1, mu = 0.1 at 70 degrees:
    psi_in = tan(70)/|V_c| > (1 + 1/k) mu (1 + e_dry), so the contact slides throughout, and
    mu s <= mu_eff <= mu s + f_0 (module docstring; f_0 the film-alone mu_eff, to rounding)
    in the Couette model. As St grows the film takes less of the normal impulse (s -> 1) and
    shears less (f_0 -> 0): |mu_eff - mu| falls below 0.1/St (measured 0.039/St and 0.046/St at
    St = 100 and 1000: mu (1 - s), the film's share of the normal impulse, less the film's
    shear f_0 of about 8e-3/St)."""
    mu = 0.1
    base = rough(St, 1e-6, 0.1, "impact")
    result = sliding(base, "couette", friction_coefficient=mu, angle=70.0)
    out = registry.computed(result)
    assert out["contact_stuck"] is False
    assert out["impact_psi_out"] == pytest.approx(
        rigid_impact(out["impact_psi_in"], mu, 0.8, K)[0], abs=ROUNDING
    )
    film_alone = registry.computed(sliding(base, "couette", friction_coefficient=0.0, angle=70.0))
    share = out["solid_impulse_share"]
    assert mu * share - ROUNDING <= out["effective_friction"]
    assert out["effective_friction"] <= mu * share + film_alone["effective_friction"] + ROUNDING
    assert abs(out["effective_friction"] - mu) < 0.1 / St


@pytest.mark.parametrize("model", ["couette", "lubrication"])
def test_mixed_model_friction_carries_its_asperity_load(model):
    """Greenwood & Tripp's model with mu = 0.05 at 60 degrees (sliding throughout): each step's
    friction impulse is -(mu / tan(angle)) times the asperities' normal impulse over the step,
    by the trapezoid rule for the one-step Couette model and at the step's end for the sliding
    film's implicit force (ehdfem.tangential.friction), to rounding; and in the Couette model
    mu s <= mu_eff <= mu s + f_0 (module docstring)."""
    mu, angle = 0.05, 60.0
    base = rough(50.0, 1e-4, 0.1, "greenwood-tripp")
    result = sliding(base, model, friction_coefficient=mu, angle=angle)
    normal, friction = result.normal, result.tangential.friction
    load, time = normal.asperity_force, normal.history.time
    assert load.max() > 0 and not friction.any_stuck
    steps = np.diff(time)
    per_step = 0.5 * (load[1:] + load[:-1]) if model == "couette" else load[1:]
    expected = -(mu / np.tan(np.radians(angle))) * per_step * steps
    scale = np.abs(expected).max()
    assert np.abs(friction.impulse[1:] - expected).max() <= ROUNDING * scale
    out = registry.computed(result)
    share = scipy.integrate.trapezoid(load, time) / (normal.params.St * (1 + normal.e_n))
    assert out["solid_impulse_share"] == pytest.approx(share, rel=ROUNDING)
    if model == "couette":
        film_alone = registry.computed(sliding(base, model, friction_coefficient=0.0, angle=angle))
        assert mu * share - ROUNDING <= out["effective_friction"]
        assert out["effective_friction"] <= mu * share + film_alone["effective_friction"]
