"""Physical inputs <-> dimensionless groups, presets and input validation."""

import math

import pytest

from ehdfem.checks import InputError
from ehdfem.exact import hertz
from ehdfem.inputs.presets import LIQUIDS, MATERIALS, liquid, material
from ehdfem.inputs.scales import CollisionParameters, PhysicalCollision

pytestmark = pytest.mark.serial


def glass_on_glass(**changes):
    values = dict(
        radius=6.35e-3,
        sphere=material("glass"),
        wall=material("glass"),
        liquid=liquid("silicone_oil_100cst"),
        speed=0.3,
        layer_thickness=6.35e-4,
    )
    return PhysicalCollision(**{**values, **changes})


def test_groups_from_physical_inputs():
    c = glass_on_glass(angle=0.0)
    a, x0, mu, v = 6.35e-3, 6.35e-4, 96.5e-3, 0.3
    theta = 2 * (1 - 0.23**2) / (math.pi * 60e9)
    p = c.dimensionless()
    assert c.theta == pytest.approx(theta, rel=1e-14)
    assert p.eps == pytest.approx(4 * theta * mu * v * a**1.5 / x0**2.5, rel=1e-14)
    # St = m V / (6 pi mu a^2) = rho D V / (9 mu) for a solid sphere
    assert p.St == pytest.approx(2540 * 2 * a * v / (9 * mu), rel=1e-12)
    assert p.delta == pytest.approx(0.1, rel=1e-14)
    assert p.p_cav == pytest.approx((0 - 101325) * x0**2 / (mu * v * a), rel=1e-14)


def test_oblique_impact_splits_the_speed():
    c = glass_on_glass(angle=30.0, speed=2.0)
    assert c.normal_speed == pytest.approx(2 * math.cos(math.pi / 6), rel=1e-14)
    assert c.tangential_speed == pytest.approx(1.0, rel=1e-14)
    assert c.dimensionless().tangential_speed == pytest.approx(math.tan(math.pi / 6), rel=1e-14)


def test_hertz_compression_matches_the_dimensional_formula():
    """(13.88 eps St)^(2/5) x0 = (15 m V0^2 / (16 E* a^0.5))^(2/5) with 1/E* = pi theta."""
    c = glass_on_glass(speed=1.0)
    p = c.dimensionless()
    e_star = 1 / (math.pi * c.theta)
    exact = (15 * c.mass * c.normal_speed**2 / (16 * e_star * c.radius**0.5)) ** 0.4
    assert hertz.max_compression(p.eps, p.St) * c.layer_thickness == pytest.approx(exact, rel=1e-12)


def test_scales_are_consistent_with_the_equation_of_motion():
    """m dv/dt = F: m V0 / t_scale = St * F_scale."""
    c = glass_on_glass()
    s, p = c.scales(), c.dimensionless()
    assert c.mass * s.velocity / s.time == pytest.approx(p.St * s.force, rel=1e-12)
    assert s.radius == pytest.approx(math.sqrt(c.radius * c.layer_thickness), rel=1e-14)


def test_presets_are_physical():
    for m in MATERIALS.values():
        assert m.young_modulus > 0 and 0 < m.poisson_ratio < 0.5 and m.density > 0 and m.source
    for liq in LIQUIDS.values():
        assert liq.viscosity > 0 and liq.density > 0 and liq.vapour_pressure >= 0 and liq.source


@pytest.mark.parametrize(
    ("changes", "name"),
    [
        ({"St": 0}, "St"),
        ({"St": -1}, "St"),
        ({"St": math.nan}, "St"),
        ({"St": "10"}, "St"),
        ({"eps": 0}, "eps"),
        ({"eps": math.inf}, "eps"),
        ({"delta": 0}, "delta"),
        ({"delta": 1}, "delta"),
        ({"angle": 90}, "angle"),
        ({"angle": -1}, "angle"),
        ({"e_dry": 0}, "e_dry"),
        ({"e_dry": 1.5}, "e_dry"),
        ({"p_cav": 1}, "p_cav"),
        ({"layer": "puddle"}, "layer"),
        ({"inertia_factor": 0.9}, "inertia_factor"),
        ({"spin": 0.2}, "spin"),  # head-on (angle 0): the spin would be ignored
    ],
)
def test_bad_dimensionless_inputs(changes, name):
    with pytest.raises(InputError, match=name):
        CollisionParameters.from_settings(**{"St": 10.0, "eps": 1e-3, **changes})


@pytest.mark.parametrize(
    ("changes", "name"),
    [
        ({"radius": 0}, "radius"),
        ({"speed": -1}, "speed"),
        ({"layer_thickness": 1.0}, "layer_thickness"),
        ({"angle": 95}, "angle"),
        ({"cavitation_pressure": 2e5}, "cavitation_pressure"),
    ],
)
def test_bad_physical_inputs(changes, name):
    with pytest.raises(InputError, match=name):
        glass_on_glass(**changes)


def test_reduced_radius_and_mass_for_two_spheres():
    """1/a = 1/a1 + 1/a2 (a wall is a2 = inf); the FE two-sphere radii 1 + a1/a2 and 1 + a2/a1
    (by a) are a1/a and a2/a."""
    from ehdfem.inputs.scales import reduced_mass, reduced_radius

    assert reduced_radius(2.0, 2.0) == 1.0 and reduced_radius(3.0, math.inf) == 3.0
    assert reduced_mass(4.0, 4.0) == 2.0 and reduced_mass(5.0, math.inf) == 5.0
    a1, a2 = 4.0, 1.0
    a = reduced_radius(a1, a2)
    assert (a1 / a, a2 / a) == pytest.approx((1 + a1 / a2, 1 + a2 / a1), rel=1e-14)


def test_unknown_presets_are_named():
    with pytest.raises(InputError, match="kryptonite"):
        material("kryptonite")
    with pytest.raises(InputError, match="ketchup"):
        liquid("ketchup")
