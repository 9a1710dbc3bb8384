"""The reduced CFD-DEM models of a pair (ehdfem.dem.reduced; docs/validation.md, "Two spheres
obliquely: the reduced CFD-DEM models") against exact results:
- the tangential lubrication forces as Jeffrey & Onishi's (1984) logarithmic resistances of
  the pair (ehdfem.exact.sphere_pair, tested in tests/test_pair_resistance.py), the torques
  as forces at the contact point;
- the approach and the rebound through the lubrication force against their closed forms
  V(H) = -1 + ln(1/H)/St and V_exit = V_r - ln(1/H_min)/St, the stop when St < ln(1/H_min);
- the touch against Hertz's compression and contact time;
- the energy balance over both spheres, Coulomb's impulse law while sliding and the rolling
  outcome of a sticking pair;
- the EHD minimum gap's scaled form against Nijssen, Ottens & Padding's film in SI units.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from ehdfem.checks import InputError
from ehdfem.dem.reduced.ehd_gap import ehd_film_thickness, ehd_gap_collision, ehd_minimum_gap
from ehdfem.dem.reduced.lubrication import ReducedCollision, reduced_collision
from ehdfem.dem.reduced.resistances import tangential_forces
from ehdfem.exact.hertz import contact_time, max_compression
from ehdfem.exact.sphere_pair import pair_logarithmic
from ehdfem.inputs.presets import liquid, material
from ehdfem.inputs.scales import PhysicalPair
from ehdfem.tangential.pair import SpherePair

pytestmark = pytest.mark.serial  # no parallel path: the MPI pass leaves it out

ROUNDING = 1e-12
INTEGRATION = 1e-9  # DOP853 at rtol 1e-10 over a collision: measured errors below 2e-10
UNEQUAL = dict(pair=SpherePair(mass_ratio=0.5**3 / 1.3, upper_inertia=0.4, lower_inertia=2 / 3,
                                lower_spin=0.2, radius_ratio=0.5))  # fmt: skip


def test_tangential_forces_are_the_pairs_resistances_at_the_contact():
    """The forces on (U, s1, s2) are -delta ln(1/(delta H)) R v, R Jeffrey & Onishi's
    (ehdfem.exact.sphere_pair), the torques as forces at the contact point (G_1 = -T_1/a1,
    G_2 = T_2/a2) and the power v.R v; for equal spheres that turn alike (w = 0) every force
    is the Couette shear of the slip at the contact point: F_1 = G_1 = -G_2."""
    velocities = np.array([0.7, -0.2, 0.4])
    R = pair_logarithmic(0.5)
    forces = tangential_forces(0.1, 0.01, R, velocities)
    scale = 0.01 * math.log(1.0 / 0.001)
    generalised = -scale * R @ velocities
    assert forces.upper == pytest.approx(generalised[0], rel=ROUNDING)
    assert forces.upper_turning == pytest.approx(-generalised[1], rel=ROUNDING)
    assert forces.lower_turning == pytest.approx(generalised[2], rel=ROUNDING)
    assert forces.dissipation == pytest.approx(scale * velocities @ R @ velocities, rel=ROUNDING)
    equal = tangential_forces(0.1, 0.01, pair_logarithmic(1.0), np.array([0.7, 0.3, 0.3]))
    couette = -scale * (0.7 - 0.6) / 3.0
    assert equal.upper == pytest.approx(couette, rel=ROUNDING)
    assert equal.upper_turning == pytest.approx(couette, rel=ROUNDING)
    assert equal.lower_turning == pytest.approx(-couette, rel=ROUNDING)


def test_approach_and_rebound_follow_the_lubrication_logarithm():
    """An unequal pair, oblique, with friction: V at the first touch of H_min is
    -1 + ln(1/H_min)/St (the lubrication impulse int dH/H), the elastic touch returns it
    reversed, and the exit speed is e_n = 1 - 2 ln(1/H_min)/St: exact whatever the tangential
    motion does (measured 1e-11)."""
    inputs = ReducedCollision(
        St=30.0, eps=1e-6, delta=0.01, angle=40.0, minimum_gap=0.03, friction_coefficient=0.2,
        **UNEQUAL,
    )  # fmt: skip
    outcome = reduced_collision(inputs)
    loss = math.log(1.0 / inputs.minimum_gap) / inputs.St
    assert outcome.impact_speed == pytest.approx(-1.0 + loss, abs=INTEGRATION)
    assert outcome.rebound_speed == pytest.approx(-outcome.impact_speed, abs=INTEGRATION)
    assert outcome.e_n == pytest.approx(1.0 - 2.0 * loss, abs=INTEGRATION)
    assert not outcome.stopped


def test_lubrication_stops_a_slow_approach_before_the_minimum_gap():
    """St = 4 < ln(1/H_min) = ln(100): the approach stops in the layer without a touch."""
    inputs = ReducedCollision(St=4.0, eps=1e-6, delta=0.01, angle=30.0, minimum_gap=0.01)
    outcome = reduced_collision(inputs)
    assert outcome.stopped and outcome.e_n == 0.0
    assert outcome.impact_speed is None and outcome.normal_impulse == 0.0


def test_touch_is_hertzs_impact():
    """The touch at the impact speed V_c: the compression is (13.88 eps St V_c^2)^(2/5) and
    the contact time Hertz's 2.87 (m^2 / (R E*^2 V_c))^(1/5), with (4/3) E* R^(1/2) the scaled
    stiffness 8/(9 pi^2 eps), to Johnson's three digits (measured -6.0e-4, the rounding of
    2.868 to 2.87); the solids part at the impact speed."""
    inputs = ReducedCollision(St=50.0, eps=1e-6, delta=0.01, angle=20.0, minimum_gap=0.1)
    outcome = reduced_collision(inputs)
    speed = -outcome.impact_speed
    assert outcome.max_compression == pytest.approx(
        max_compression(inputs.eps, inputs.St * speed**2), rel=INTEGRATION
    )
    modulus = 0.75 * 8.0 / (9.0 * math.pi**2 * inputs.eps)  # E* at R = 1
    hertz_time = contact_time(inputs.St, 1.0, modulus, speed)
    assert outcome.contact_time == pytest.approx(hertz_time, rel=1e-3)
    assert outcome.rebound_speed == pytest.approx(speed, rel=INTEGRATION)


@pytest.mark.parametrize("mu", [0.0, 0.05, 1.0])
def test_energy_closes_over_both_spheres(mu):
    """Kinetic energy of both spheres (translation and spin) plus Hertz's elastic energy has
    fallen by the lubrication's and the friction's integrated dissipation (measured 2.1e-10 to
    3.4e-10 of the loss), for an unequal, spinning pair without friction, sliding and sticking."""
    inputs = ReducedCollision(
        St=20.0, eps=1e-5, delta=0.01, angle=45.0, minimum_gap=0.05, friction_coefficient=mu,
        spin=-0.3, **UNEQUAL,
    )  # fmt: skip
    assert reduced_collision(inputs).energy_error < 1e-9


def test_sliding_contact_obeys_coulombs_law():
    """A glancing impact (75 deg, mu = 0.05) slides through the touch: the friction's impulse
    is -mu times Hertz's (the slip positive throughout; measured 1e-14)."""
    inputs = ReducedCollision(
        St=50.0, eps=1e-6, delta=0.01, angle=75.0, minimum_gap=0.05, friction_coefficient=0.05,
        **UNEQUAL,
    )  # fmt: skip
    outcome = reduced_collision(inputs)
    assert outcome.normal_impulse > 1.0
    assert outcome.friction_impulse == pytest.approx(-0.05 * outcome.normal_impulse, rel=1e-12)


def test_sticking_equal_spheres_leave_rolling():
    """Equal spheres without spin (b = 0, w = s1 - s2 = 0 throughout): every tangential force
    acts at the contact point on the slip, so U + k w is kept (k = 2/5) and a pair that sticks
    (mu = 1) leaves rolling, u_s = 0: e_t = 1/(1 + k) = 5/7 and each sphere takes half of
    w = 5/7, a spin change of 5/14 (the rigid-body law of two spheres that stick)."""
    inputs = ReducedCollision(
        St=20.0, eps=1e-5, delta=0.01, angle=45.0, minimum_gap=0.05, friction_coefficient=1.0
    )
    outcome = reduced_collision(inputs)
    assert outcome.e_t == pytest.approx(5.0 / 7.0, abs=INTEGRATION)
    assert outcome.upper_spin_change == pytest.approx(5.0 / 14.0, abs=INTEGRATION)
    assert outcome.lower_spin_change == pytest.approx(5.0 / 14.0, abs=INTEGRATION)


def test_ehd_minimum_gap_is_nijssens_film():
    """H_eps = 0.37 (pi eps/4)^(2/5) equals h_eps = 0.37 ((mu v/E*)^2 a^3)^(1/5) over x0 for a
    glass-steel pair in glycerol (eps by the pair's inputs), to rounding; the EHD model's
    touch comes at V = -1 + ln(1/H_eps)/St."""
    pair = PhysicalPair(
        upper_radius=3e-3, lower_radius=1.5e-3, upper=material("glass"), lower=material("steel"),
        liquid=liquid("glycerol"), speed=2.0, layer_thickness=3e-5, angle=30.0,
    )  # fmt: skip
    params = pair.dimensionless()
    physical = pair.equivalent()
    modulus = 1.0 / (math.pi * physical.theta)
    film = ehd_film_thickness(
        physical.liquid.viscosity, physical.normal_speed, modulus, physical.radius
    )
    assert ehd_minimum_gap(params.eps) == pytest.approx(film / 3e-5, rel=ROUNDING)
    inputs = ReducedCollision(St=40.0, eps=params.eps, delta=params.delta, angle=30.0,
                              minimum_gap=0.5)  # fmt: skip
    outcome = ehd_gap_collision(inputs)
    expected = -1.0 + math.log(1.0 / ehd_minimum_gap(params.eps)) / 40.0
    assert outcome.impact_speed == pytest.approx(expected, abs=INTEGRATION)


def test_bad_inputs_are_refused_by_name():
    """A minimum gap outside (0, 1), an angle of 0 and an EHD film thicker than the layer."""
    base = dict(St=10.0, eps=1e-4, delta=0.01, angle=30.0, minimum_gap=0.1)
    for name, value in (("minimum_gap", 1.0), ("angle", 0.0), ("friction_coefficient", -1.0)):
        with pytest.raises(InputError) as error:
            ReducedCollision(**{**base, name: value})
        assert error.value.name == name
    with pytest.raises(InputError, match="EHD minimum film") as error:
        ehd_gap_collision(ReducedCollision(**{**base, "eps": 20.0}))
    assert error.value.name == "eps"
