"""Tangential motion and spin: exact rigid-film results and the trends of the source."""

import numpy as np
import pytest
from scipy.integrate import quad

from ehdfem.collision import collide
from ehdfem.compliance import RigidSolids
from ehdfem.film import Film, radial_grid
from ehdfem.normal import solve_normal
from ehdfem.scales import CollisionParameters
from ehdfem.tangential import film_integrals, solve_tangential

pytestmark = pytest.mark.serial

PARAMS = dict(St=10.0, eps=1e-3, layer="thin", p_cav=-2.0, delta=0.01, angle=30.0)


@pytest.fixture(scope="module")
def rigid_approach():
    params = CollisionParameters(St=3.0, eps=1.0, delta=0.01, angle=40.0, layer="thin")
    normal = solve_normal(params, RigidSolids(radial_grid(160, 0.1, 1.5)))
    return params, normal


def test_rigid_film_shear_is_log_of_gap(rigid_approach):
    """For H = X + R^2/2 in a thin layer, J = int_0^edge R dR / H = ln(1/X) (rel. 1e-3)."""
    _, normal = rigid_approach
    gaps = normal.history.gap[1:]
    np.testing.assert_allclose(film_integrals(normal)[1:], np.log(1 / gaps), rtol=1e-3)


def test_slip_decays_as_the_exact_exponential(rigid_approach):
    """u_s = exp(-(1 + 1/k) delta/(3 St) int J dT); int J dT along the rigid approach is
    int_X^1 ln(1/X') / |V(X')| dX' with the exact |V| = 1 - loss(X')/St."""
    params, normal = rigid_approach
    t = solve_tangential(normal, "couette")
    k = params.inertia_factor

    def speed(x):
        return 1 - (np.log(1 / x) - 1.5 + 2 * x - 0.5 * x**2) / params.St

    for i in (len(normal.history.time) // 3, len(normal.history.time) // 2):
        gap = normal.history.gap[i]
        exact_integral = quad(lambda x: np.log(1 / x) / speed(x), gap, 1.0, limit=200)[0]
        exact = np.exp(-(1 + 1 / k) * params.delta / (3 * params.St) * exact_integral)
        assert t.slip[i] == pytest.approx(exact, rel=2e-4)


def test_restitution_does_not_depend_on_the_impact_angle():
    e_t = [
        collide(CollisionParameters(**{**PARAMS, "angle": a})).tangential.e_t for a in (5, 30, 70)
    ]
    assert np.ptp(e_t) < 1e-12


@pytest.mark.parametrize("model", ["couette", "lubrication"])
def test_one_minus_e_t_is_linear_in_delta(model):
    """For small delta, 1 - e_t = slope * delta: the slopes at delta = 5e-4, 1e-3 and 2e-3
    agree to 1 %, and e_t -> 1 as delta -> 0. For the Couette model the slope is known:
    1 - e_t -> k/(1+k) (1 + 1/k) delta/(3 St) int J dT = delta int_0^exit J dT / (3 St)."""
    results = {
        d: collide(CollisionParameters(**{**PARAMS, "delta": d}), tangential=model)
        for d in (5e-4, 1e-3, 2e-3)
    }
    slopes = [(1 - r.tangential.e_t) / d for d, r in results.items()]
    assert max(slopes) / min(slopes) - 1 < 0.01
    assert 1 - results[5e-4].tangential.e_t < 0.01
    if model == "couette":
        r = results[5e-4]
        exit_time = r.normal.contact_time
        time = np.append(r.tangential.time[r.tangential.time < exit_time], exit_time)
        shear = np.interp(time, r.tangential.time, r.tangential.shear)
        expected = np.sum(np.diff(time) * (shear[1:] + shear[:-1])) / 2 / (3 * PARAMS["St"])
        assert slopes[0] == pytest.approx(expected, rel=2e-3)


def test_couette_spin_change_is_the_lost_tangential_speed_over_k():
    result = collide(CollisionParameters(**PARAMS))
    t = result.tangential
    assert t.at == "exit" and 0 < t.e_t < 1
    assert t.spin_change == pytest.approx((1 - t.e_t) / 0.4, rel=1e-12)


def test_sticking_sphere_reports_the_state_at_the_stop():
    result = collide(CollisionParameters(**{**PARAMS, "St": 2.0}))
    assert not result.normal.rebound and result.tangential.at == "stop"


@pytest.mark.parametrize(
    ("slip", "rolling", "force", "torque"),
    [(1, 1, -8 / 15, 1 / 10), (-1, 1, 2 / 15, -2 / 5)],  # translation; rotation (a Omega = 1)
)
def test_lubrication_model_reproduces_near_wall_logarithms(slip, rolling, force, torque):
    """Rigid sphere near a wall: d(force)/d ln(1/h) = 8/15 and 2/15 of 6 pi mu a U, d(torque)/
    d ln(1/h) = 1/10 and 2/5 of 8 pi mu a^2 U, for translation and rotation (1 % at 400 nodes).
    In those units (U0 = 1) and per unit delta, the sliding film's force is
    -(J u_s)/3 - s.q/12 and its torque, -a F - 6 pi mu a^2 U (t.q/6), is -(3/4) (F + t.q/6),
    with q the rigid mode-1 pressure and the immersed far field's 1, 3/5, 2/5 of ln H."""
    values = []
    for gap in (1e-3, 1e-4):
        film = Film(radial_grid(400, np.sqrt(gap), 30.0), "immersed")
        mode_one = film.mode_one(gap + 0.5 * film.radii**2, 10.0)
        q = rolling * mode_one.rigid_pressure()
        tail = mode_one.tail
        shear = mode_one.shear_weights.sum() + tail
        f = -shear * slip / 3 - mode_one.surface_slope_weights() @ q / 12 - 0.2 * tail * rolling
        torque_term = mode_one.torque_weights @ q / 6 + 0.4 * tail * rolling
        values.append((f, -0.75 * (f + torque_term)))
    (f1, t1), (f2, t2) = values
    assert (f2 - f1) / np.log(10) == pytest.approx(force, rel=0.01)
    assert (t2 - t1) / np.log(10) == pytest.approx(torque, rel=0.01)
