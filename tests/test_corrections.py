"""The first correction to the half-space theory, by cause (ehdfem.study.corrections)."""

import math

import numpy as np
import pytest

from ehdfem.checks import InputError
from ehdfem.collision import film_radii
from ehdfem.config import RunConfig
from ehdfem.inputs.scales import CollisionParameters
from ehdfem.study.corrections import (
    CAUSES,
    VARIANTS,
    cause_shares,
    first_order_fit,
    run_model,
    variant_parameters,
)

IDENTICAL = ((1.0, 0.3), (1.0, 0.3))
TIGHT = RunConfig.from_settings(rtol=1e-7)
EXACT_NEWTON = RunConfig.from_settings(rtol=1e-7, newton_tol=1e-12)


def test_first_order_fit_recovers_the_constants_of_exact_data():
    """share = c1 sqrt(delta) + c2 delta exactly: c1 and c2 to rounding, zero standard errors."""
    deltas = np.array([1e-4, 1e-3, 1e-2, 0.05])
    c1, c2, e1, e2 = first_order_fit(deltas, -0.44 * np.sqrt(deltas) + 0.3 * deltas)
    assert c1 == pytest.approx(-0.44, abs=1e-12)
    assert c2 == pytest.approx(0.3, abs=1e-11)
    assert e1 < 1e-11 and e2 < 1e-10


def test_first_order_fit_leaves_out_nan_and_needs_three_points():
    deltas = [1e-4, 1e-3, 1e-2, 0.05]
    shares = [0.1 * math.sqrt(d) for d in deltas[:3]] + [math.nan]
    assert first_order_fit(deltas, shares)[0] == pytest.approx(0.1, abs=1e-12)
    with pytest.raises(InputError, match="at least 3"):
        first_order_fit(deltas[:2], shares[:2])


def test_cause_shares_add_up_to_the_difference_of_full_and_theory():
    values = {
        "theory": {"e_n": 0.60},
        "geometry": {"e_n": 0.61},
        "surface": {"e_n": 0.59},
        "halfspace": {"e_n": 0.602},
        "full": {"e_n": 0.58},
    }
    shares = cause_shares(values)
    assert shares["geometry"]["e_n"] == pytest.approx(0.01 / 0.6)
    assert shares["surface"]["e_n"] == pytest.approx(-0.01 / 0.6)
    assert shares["finite size"]["e_n"] == pytest.approx(-0.022 / 0.6)
    assert sum(shares[c]["e_n"] for c in CAUSES) == pytest.approx(shares["total"]["e_n"])
    assert shares["total"]["e_n"] == pytest.approx(-0.02 / 0.6)


def test_each_variant_is_one_change_from_a_neighbour():
    """theory -> geometry changes the gap, theory -> surface the surface effects, halfspace ->
    full the elasticity; an immersed layer keeps the paraboloid."""
    params = CollisionParameters(St=20.0, eps=1e-3, delta=0.01)
    settings = {v: (m, *(lambda p: (p.gap.name, p.shear_traction))(variant_parameters(params, v)))
                for v, (m, _, _) in VARIANTS.items()}  # fmt: skip
    assert settings["theory"] == ("halfspace", "paraboloid", False)
    assert settings["geometry"] == ("halfspace", "exact", False)
    assert settings["surface"] == ("halfspace", "paraboloid", True)
    assert settings["halfspace"] == ("halfspace", "exact", True)
    assert settings["full"] == ("fem", "exact", True)
    immersed = CollisionParameters(St=20.0, eps=1e-3, delta=0.01, layer="immersed")
    assert variant_parameters(immersed, "full").gap.name == "paraboloid"
    with pytest.raises(InputError, match="variant"):
        variant_parameters(params, "rigid")


def _share(variant, delta, output="e_n", config=TIGHT):
    params = CollisionParameters(St=20.0, eps=1e-3, delta=delta)
    radii = film_radii(params, 60)
    theory = run_model(params, "theory", radii, IDENTICAL, config)[output]
    return (run_model(params, variant, radii, IDENTICAL, config)[output] - theory) / theory


@pytest.mark.slow
def test_surface_effects_on_half_spaces_are_of_order_sqrt_delta():
    """On half-spaces with the paraboloid, delta enters only as the factor sqrt(delta) of the
    shear opening and of the faces' radial velocity, so (surface - theory) / theory /
    sqrt(delta) = c1 + O(sqrt(delta)): at delta = 1e-5 and 1e-4 the quotients of e_n and the
    thinnest film agree within 1 % (60 nodes, rtol 1e-7 and the Newton iteration to 1e-12;
    measured 0.09 % and 0.07 %, so the next term, c2 sqrt(delta) / c1, is below that). At
    delta = 1e-6 the share, 6e-5 of e_n, is a difference of two collisions below their own
    error: it moved by 2.4 % between Newton tolerances 1e-7 and 1e-12."""
    for output in ("e_n", "min_film_thickness"):
        small, larger = (
            _share("surface", d, output, EXACT_NEWTON) / math.sqrt(d) for d in (1e-5, 1e-4)
        )
        assert larger == pytest.approx(small, rel=1e-2)
        assert small < 0  # the faces' outflow and the shear lift thin the film, e_n drops


@pytest.mark.slow
def test_true_gap_is_a_correction_of_order_delta():
    """The sphere's gap is R^2/2 + delta R^4/8 + ...: the geometry's share is of order delta,
    not sqrt(delta); share / delta at delta = 1e-3 and 1e-2 agree within 0.5 % (measured 0.12 %,
    60 nodes, rtol 1e-7)."""
    small, larger = (_share("geometry", d) / d for d in (1e-3, 1e-2))
    assert larger == pytest.approx(small, rel=5e-3)
    assert small > 0  # the sphere's gap opens faster than the paraboloid: less dissipation
