"""Coulomb friction of the solid contact: rigid-body impact closed forms, stick, energy.

The normal motion of a rough sphere (its solid impact, its asperity load) is set on real
smooth collisions with dataclasses.replace: the tangential models read only those fields
(ehdfem.tangential.friction), and the normal motion does not depend on the tangential one.
"""

from dataclasses import replace
from types import SimpleNamespace

import numpy as np
import pytest

from ehdfem.checks import InputError
from ehdfem.collision import collide, with_tangential
from ehdfem.inputs.scales import CollisionParameters, from_presets
from ehdfem.motion.normal import SolidImpact
from ehdfem.outputs import registry
from ehdfem.tangential.friction import CoulombContact, coulomb_impulse, rigid_impact
from ehdfem.tangential.motion import MODELS

pytestmark = pytest.mark.serial

THIN = dict(layer="thin", delta=0.01, p_cav=-2.0)
ROUNDING = 1e-12  # closed forms reproduced up to a few roundings of O(1) numbers


def roughened(normal, e_dry=0.8, asperity_share=None):
    """``normal`` with a solid impact where its thinnest film first falls below twice its
    minimum (as a roughness sigma = 2 H_min would end the approach), at the approach velocity
    there with N = St (1 + e_dry) |V|; ``asperity_share``: an asperity load of that share of
    the film force at every step (the mixed model's), None: none."""
    hist = normal.history
    index = int(np.argmax(hist.min_film <= 2.0 * normal.min_film_thickness))
    velocity = float(hist.velocity[index])
    impulse = normal.params.St * (1.0 + e_dry) * abs(velocity)
    impact = SolidImpact(index, float(hist.time[index]), velocity, impulse)
    load = None if asperity_share is None else asperity_share * np.maximum(hist.force, 0.0)
    return replace(normal, solid_impact=impact, asperity_force=load)


def with_friction(result, normal, model, **changes):
    """The collision ``result`` with the normal motion ``normal`` whose parameters get
    ``changes`` (angle, friction_coefficient, ...), and the tangential ``model``."""
    params = replace(normal.params, **changes)
    rough = replace(result, params=params, normal=replace(normal, params=params))
    return with_tangential(rough, model)


@pytest.fixture(scope="module")
def smooth():
    """An oblique thin-layer collision on the half-space (60 film nodes)."""
    return collide(CollisionParameters(St=10.0, eps=1e-3, angle=30.0, **THIN), nodes=60)


def test_friction_coefficient_is_checked():
    with pytest.raises(InputError, match="friction_coefficient"):
        CollisionParameters(St=1.0, eps=1e-3, friction_coefficient=-0.1)


def test_physical_inputs_carry_the_friction_coefficient():
    from ehdfem.inputs.presets import EXAMPLE

    physical = from_presets(**EXAMPLE, friction_coefficient=0.3)
    assert physical.dimensionless().friction_coefficient == 0.3


@pytest.mark.parametrize("k", [0.4, 2 / 3])
@pytest.mark.parametrize("psi_in", [-3.0, -0.4, 0.05, 0.9, 4.0])
def test_projection_gives_the_rigid_impact_closed_form(psi_in, k):
    """The Coulomb impulse of a normal impulse N = St (1 + e) |V| turns psi_in into
    psi_out = psi_in - (1 + 1/k) mu (1 + e) sign(psi_in) (sliding throughout), or 0 (stick)
    once |psi_in| <= (1 + 1/k) mu (1 + e): exact up to rounding."""
    St, e_n, mu, speed, tangent = 7.0, 0.7, 0.25, 0.6, np.tan(np.radians(35.0))
    slip = psi_in * speed / tangent  # u_s by U0 for psi = u_s U0 / (|V| V0)
    bound = mu / tangent * St * (1 + e_n) * speed
    impulse, stuck = coulomb_impulse(slip, bound, St, k)
    psi_out = (slip + (1 + 1 / k) * impulse / St) * tangent / speed
    expected, expected_stuck = rigid_impact(psi_in, mu, e_n, k)
    assert stuck == expected_stuck == (abs(psi_in) <= (1 + 1 / k) * mu * (1 + e_n))
    assert psi_out == pytest.approx(expected, abs=ROUNDING)
    if not stuck:
        assert psi_out == pytest.approx(psi_in - (1 + 1 / k) * mu * (1 + e_n) * np.sign(psi_in))


def test_constant_asperity_load_stops_the_slip_linearly():
    """With no film, a constant asperity load F_a slows the slip linearly, du_s/dT =
    -(1 + 1/k) (mu / tan(angle)) F_a / St, and holds it at 0 from T* = u_s0 St tan(angle) /
    ((1 + 1/k) mu F_a): the per-step projection reproduces it exactly (rounding)."""
    params = CollisionParameters(St=4.0, eps=1e-3, angle=40.0, friction_coefficient=0.3)
    time = np.linspace(0.0, 4.0, 81)
    load = np.full(time.shape, 1.5)
    normal = SimpleNamespace(
        params=params,
        history=SimpleNamespace(time=time),
        asperity_force=load,
        solid_impact=None,
    )
    contact = CoulombContact.of(normal)
    k, tangent = params.inertia_factor, params.tangential_speed
    rate = (1 + 1 / k) * params.friction_coefficient / tangent * 1.5 / params.St
    state = (1.0, 0.0)
    for step in range(1, len(time)):
        state = contact.act(step, *state)
        exact = max(1.0 - rate * time[step], 0.0)
        assert state[0] - state[1] == pytest.approx(exact, abs=ROUNDING)
    stops = time[contact.record().stuck]
    assert stops[0] == pytest.approx(1.0 / rate, abs=time[1])
    assert contact.record().stuck[time > 1.0 / rate].all()
    momentum = state[0] + k * state[1]  # the contact's impulses conserve U + k a Omega
    assert momentum == pytest.approx(1.0, abs=ROUNDING)


@pytest.mark.parametrize("model", MODELS)
def test_impact_jump_follows_the_closed_form_in_every_model(smooth, model):
    """At the solid impact's step the slip jumps by the rigid-body impact's closed form,
    whatever film acts before and after; sliding throughout at mu = 0.05 (psi_in about
    tan(30 deg) / |V| > (1 + 1/k) mu (1 + e))."""
    normal = roughened(smooth.normal)
    result = with_friction(smooth, normal, model, friction_coefficient=0.05)
    friction = result.tangential.friction
    psi_in, psi_out = friction.impact_psi
    k = normal.params.inertia_factor
    expected, stuck = rigid_impact(psi_in, 0.05, 0.8, k)
    assert not stuck and not friction.any_stuck
    assert psi_out == pytest.approx(expected, abs=ROUNDING)
    index = normal.solid_impact.index
    ratio = normal.params.tangential_speed / abs(normal.solid_impact.approach_velocity)
    assert result.tangential.slip[index] * ratio == pytest.approx(psi_out, abs=ROUNDING)


@pytest.mark.parametrize("model", MODELS)
def test_sticking_contact_leaves_rolling(smooth, model):
    """Above the sticking threshold the contact point leaves the impact without slip; the
    Couette-type films (couette, flat) act on the slip only and keep it 0 until exit."""
    normal = roughened(smooth.normal)
    result = with_friction(smooth, normal, model, friction_coefficient=1.0)
    tangential = result.tangential
    assert tangential.friction.any_stuck and tangential.friction.impact_psi[1] == 0.0
    index = normal.solid_impact.index
    assert tangential.slip[index] == 0.0  # U = a Omega exactly
    if model in ("couette", "flat"):
        assert abs(registry.computed(result)["psi_out"]) <= ROUNDING
    summary = result.summary()
    assert summary["contact_stuck"] is True and summary["friction_dissipated"] > 0


def tangential_energy(tangential, St, k):
    """E_t = (St/2)(U^2 + k (a Omega)^2) at the steps (by m U0^2 / St)."""
    return 0.5 * St * (tangential.velocity**2 + k * tangential.spin**2)


@pytest.mark.parametrize("St,eps", [(5.0, 1e-4), (5.0, 1e-2), (50.0, 1e-4), (50.0, 1e-2)])
def test_energy_is_never_created(St, eps):
    """Over mu, the angle, the models and both contacts (impact, and impact with an asperity
    load of half the film force): the tangential kinetic energy never rises above its impact
    value (to 1e-12 of it), each friction impulse dissipates (>= 0), and the sliding film's
    balance with the friction term closes to 0.1 of the energy lost: its time-discretisation
    error, largest where a strong asperity friction stops the slip within a few of the normal
    motion's steps (St 5, eps 1e-4, mu 0.3 at 10 degrees: 5.1e-2, then 1.1e-2 and 3.8e-3 at
    rtol 5e-6 and 5e-7, while e_t moves by 1e-5; docs/tangential.md). The normal motion is the
    smooth collision's own, with its own balance, so the total energy (normal plus tangential) is
    not created either."""
    base = collide(CollisionParameters(St=St, eps=eps, angle=30.0, **THIN), nodes=60)
    k = base.params.inertia_factor
    for share in (None, 0.5):
        normal = roughened(base.normal, asperity_share=share)
        for mu in (0.05, 0.3):
            for angle in (10.0, 60.0):
                for model in ("couette", "gcb", "lubrication"):
                    tangential = with_friction(
                        base, normal, model, angle=angle, friction_coefficient=mu
                    ).tangential
                    energy = tangential_energy(tangential, St, k)
                    assert energy.max() <= energy[0] * (1 + 1e-12)
                    losses = np.diff(tangential.friction.dissipated, prepend=0.0)
                    assert losses.min() >= 0.0
                    if tangential.energy is not None:
                        assert tangential.energy.balance_error < 0.1


def test_no_friction_leaves_the_results_bit_for_bit(smooth):
    """mu = 0 with a solid impact and an asperity load gives the smooth collision's tangential
    motion exactly (every history equal), in every model."""
    normal = roughened(smooth.normal, asperity_share=0.5)
    for model in MODELS:
        before = with_tangential(smooth, model).tangential
        after = with_friction(smooth, normal, model, friction_coefficient=0.0).tangential
        assert after.friction is None
        for name in ("velocity", "spin", "slip", "force"):
            assert np.array_equal(getattr(before, name), getattr(after, name)), (model, name)
        assert (before.e_t, before.spin_change) == (after.e_t, after.spin_change)


def test_oblique_outputs_are_those_of_the_exit_state():
    """psi_in = tan(angle) - a Omega0 / V0; psi_out = tan(angle) u_s(exit) / U0; the
    rebound angle atan(e_t tan(angle) / e_n); the effective friction tan(angle) (1 - e_t) /
    (1 + e_n) (the film alone: of order 1e-3, docs/tangential.md)."""
    params = CollisionParameters(St=10.0, eps=1e-3, angle=30.0, spin=0.2, **THIN)
    result = collide(params, nodes=60)
    out, t, tangent = registry.computed(result), result.tangential, params.tangential_speed
    assert out["psi_in"] == pytest.approx(tangent - 0.2, rel=1e-14)
    assert out["psi_out"] == pytest.approx(tangent * (t.e_t - t.spin[0] - t.spin_change))
    e_n = result.normal.e_n
    assert out["rebound_angle"] == pytest.approx(np.degrees(np.arctan(t.e_t * tangent / e_n)))
    assert out["effective_friction"] == pytest.approx(tangent * (1 - t.e_t) / (1 + e_n))
    assert 0 < out["effective_friction"] < 1e-2
    summary = result.summary()
    assert "contact_stuck" not in summary and "impact_psi_in" not in summary


def test_impact_with_the_full_sliding_deformation(smooth):
    """With deformation "full" (the nodal slips v = u_s + sqrt(delta) dD/dT jump with u_s, the
    faces' displacements do not) the impact follows the closed form, the tangential energy
    never rises and the balance closes (0.1, as above)."""
    normal = roughened(smooth.normal)
    params = replace(normal.params, friction_coefficient=0.05)
    rough = replace(smooth, params=params, normal=replace(normal, params=params))
    tangential = with_tangential(rough, "lubrication", deformation="full").tangential
    psi_in, psi_out = tangential.friction.impact_psi
    assert psi_out == pytest.approx(rigid_impact(psi_in, 0.05, 0.8, params.inertia_factor)[0])
    assert tangential.energy.balance_error < 0.1
    energy = tangential_energy(tangential, params.St, params.inertia_factor)
    assert energy.max() <= energy[0] * (1 + 1e-12)


@pytest.mark.parametrize("model", ["couette", "lubrication"])
def test_a_rough_collision_applies_the_impact_friction_at_its_own_step(model):
    """A real rough collision (the impact model: sigma = 0.03 x0 ends the approach of a nearly
    rigid sphere) with mu = 0.05 at 30 deg: the normal result's velocity jumps at the impact's
    step to -e_dry V_c; the asperity load history has the history's length; the tangential
    jump there follows the rigid-body closed form; mu = 0 gives the smooth tangential model of
    the same rough normal motion, which differs from it."""
    params = CollisionParameters(St=10.0, eps=1e-6, angle=30.0, roughness=0.03, e_dry=0.8, **THIN)
    rough = collide(replace(params, friction_coefficient=0.05), nodes=60, tangential=model)
    normal, impact = rough.normal, rough.normal.solid_impact
    assert impact is not None and len(normal.asperity_force) == len(normal.history.time)
    assert normal.history.velocity[impact.index] == pytest.approx(
        -0.8 * impact.approach_velocity, rel=ROUNDING
    )
    psi_in, psi_out = rough.tangential.friction.impact_psi
    assert psi_out == pytest.approx(rigid_impact(psi_in, 0.05, 0.8, 0.4)[0], abs=ROUNDING)
    summary = rough.summary()
    assert summary["impact_psi_out"] == psi_out and summary["friction_dissipated"] > 0
    frictionless = collide(params, nodes=60, tangential=model)
    assert frictionless.normal.e_n == normal.e_n  # the normal motion does not feel friction
    assert frictionless.tangential.e_t > rough.tangential.e_t
