"""Tangential compliance of the solid impact (ehdfem.tangential.compliant_contact) against the
exact results of ehdfem.exact.compliant_impact and ehdfem.exact.walton_impact.

Exact references (docs/tangential.md, "Tangential compliance of the solid contact"):
- the Hertz compression tau(xi) = int_0^xi (1 - s^(5/2))^(-1/2) ds, by quadrature here;
- chi = 1/2, e = 1: the tangential springs obey the normal ones' equation, so the whole MBF
  curve is Psi_2 = -Psi_1 (Psi_1 <= 1, no slip at all) and Psi_1 - 2 above (gross slip);
- any chi: complete adhesion (Psi_1 -> 0) gives Psi_2 = r Psi_1, r from a delay equation
  solved by an adaptive integrator; gross slip throughout gives Psi_2 = Psi_1 - 2 chi (1 + e)
  from Psi_1 = max(1, 2 chi, 2 chi (1 + e) - 1/e) on;
- Walton's law with beta_0 = 0 is the rigid-body Coulomb impact.
Between the limits the reference is an independent numerical solution of the same equations
(exact.entry_time_rebound: springs laid down at the moving edge, implicit trapezoidal rule),
itself checked on the exact chi = 1/2 curve.
The discretised law converges at first order (springs projected onto their Coulomb limit each
step); its default grid (400 springs, 2000 steps per phase) is within 7e-4 of the exact limits.
"""

import numpy as np
import pytest
import scipy.integrate

from ehdfem import CollisionParameters, collide, from_presets
from ehdfem.checks import InputError
from ehdfem.exact import compliant_impact as exact
from ehdfem.exact.rigid_impact import frictional_impact
from ehdfem.exact.walton_impact import walton_impact
from ehdfem.film.asperities import GreenwoodTrippAsperities
from ehdfem.inputs.presets import EXAMPLE, MATERIALS
from ehdfem.tangential.compliant_contact import (
    compliant_impact,
    compliant_rebound,
    mindlin_stiffness_ratio,
)

pytestmark = pytest.mark.serial  # no parallel path: the MPI pass leaves it out

SPHERE_NU = 0.3
KAPPA = 2 * (1 - SPHERE_NU) / (2 - SPHERE_NU)  # identical solids, nu = 0.3: 0.8235
K = 0.4  # a solid sphere
CHI = exact.impact_parameter(KAPPA, K)  # MBF's chi = 1.441
COARSE = dict(cells=200, steps=1000)  # half the default grid: the fast tests


def test_hertz_compression_against_quadrature():
    """tau(xi) in closed form (hypergeometric) against the quadrature of its integral to 1e-12,
    tau_c = Gamma(7/5) Gamma(1/2) / Gamma(9/10), and xi(tau) inverts it to 1e-14."""
    xi = np.array([0.1, 0.4, 0.8, 0.99, 1.0])
    quadrature = [
        scipy.integrate.quad(lambda s: (1 - s**2.5) ** -0.5, 0, x, epsabs=1e-14, epsrel=1e-13)[0]
        for x in xi
    ]
    assert np.allclose(exact.approach_time(xi), quadrature, rtol=1e-12, atol=0)
    assert exact.approach_time(1.0) == pytest.approx(exact.COMPRESSION_TIME, rel=1e-14)
    assert exact.COMPRESSION_TIME == pytest.approx(1.4716375921623, rel=1e-12)
    assert np.allclose(exact.indentation(exact.approach_time(xi)), xi, rtol=0, atol=1e-14)


def test_adhesive_ratio_exact_at_half_chi_and_converged():
    """The delay equation's complete-adhesion ratio: -1 at chi = 1/2, e = 1 (the normal springs'
    own motion, xi' from 1 to -1) to 1e-10; at the sphere's chi its value moves by less than
    1e-8 from rtol 1e-9 to 1e-11."""
    assert exact.adhesive_ratio(0.5, 1.0) == pytest.approx(-1.0, abs=1e-10)
    for e_n in (1.0, 0.8):
        tight, loose = exact.adhesive_ratio(CHI, e_n), exact.adhesive_ratio(CHI, e_n, rtol=1e-9)
        assert abs(tight - loose) < 1e-8


@pytest.mark.parametrize("psi_in", [0.1, 0.5, 0.9, 1.0, 1.2, 2.0, 3.0])
def test_half_chi_whole_curve(psi_in):
    """chi = 1/2, e = 1: the law follows the exact curve (no slip up to Psi_1 = 1, then gross
    slip throughout) to 5e-7 over the whole range, the reversal Psi_2 = -Psi_1 included
    (measured 2.6e-7 on this grid, 4.8e-8 on the default one)."""
    impact = compliant_impact(psi_in, 0.5, 1.0, **COARSE)
    assert impact.psi_out == pytest.approx(float(exact.half_chi_rebound(psi_in)), abs=5e-7)
    assert impact.gross_slip == (psi_in > 1.0)


@pytest.mark.parametrize("e_n", [1.0, 0.8])
def test_adhesion_limit(e_n):
    """Psi_1 = 1e-3 (slip near the receding edge of order Psi_1): Psi_2 / Psi_1 within 1.5e-3 of
    the delay equation's ratio (measured 6e-4 at e = 1, 2e-3 of r at e = 0.8: its r is
    -0.095, and the tolerance is on Psi_2 / Psi_1 against r, both of order 1), and the first
    order of the grid: halving it moves the ratio towards r."""
    ratio = exact.adhesive_ratio(CHI, e_n)
    fine = compliant_impact(1e-3, CHI, e_n).psi_out / 1e-3
    coarse = compliant_impact(1e-3, CHI, e_n, **COARSE).psi_out / 1e-3
    assert abs(fine - ratio) < 1.5e-3
    assert abs(fine - ratio) < abs(coarse - ratio)


@pytest.mark.parametrize("e_n", [1.0, 0.8])
def test_gross_slip_line_and_threshold(e_n):
    """From the threshold max(1, 2 chi, 2 chi (1 + e) - 1/e) on the contact slides throughout
    and Psi_2 = Psi_1 - 2 chi (1 + e) (the rigid-body Coulomb impact) to 1e-6; 0.05 below the
    threshold a spring sticks (MBF: Psi_2 = -1 at 4 chi - 1 for e = 1)."""
    threshold = exact.gross_slip_threshold(CHI, e_n)
    for psi_in in (threshold + 0.05, threshold + 1.0, 2 * threshold):
        impact = compliant_impact(psi_in, CHI, e_n, **COARSE)
        assert impact.gross_slip
        assert impact.psi_out == pytest.approx(
            float(exact.gross_slip_rebound(psi_in, CHI, e_n)), abs=1e-6
        )
    assert not compliant_impact(threshold - 0.05, CHI, e_n, **COARSE).gross_slip
    if e_n == 1.0:
        assert threshold == pytest.approx(4 * CHI - 1, rel=1e-15)


@pytest.mark.slow
def test_reversal_region():
    """The solid sphere (chi = 1.441, e = 1): the contact point's slip reverses (Psi_2 < 0)
    from Psi_1 = 0.9 up to the gross-slip threshold, with Psi_2 = -1 there (to 1e-6)."""
    threshold = exact.gross_slip_threshold(CHI, 1.0)
    for psi_in in (0.9, 1.5, 2.5, 3.5, 4.5):
        assert compliant_impact(psi_in, CHI, 1.0, **COARSE).psi_out < 0.0
    assert compliant_impact(threshold, CHI, 1.0, **COARSE).psi_out == pytest.approx(-1.0, abs=1e-6)


@pytest.mark.slow
def test_grid_convergence_between_the_limits():
    """Between the exact limits (partial slip and reversal) the default grid and one twice
    finer differ by less than 2e-4 (measured 1e-4 or less) over Psi_1 = 0.3 to 4.2."""
    for psi_in in (0.3, 2.0, 3.0, 4.2):
        default = compliant_impact(psi_in, CHI, 1.0).psi_out
        fine = compliant_impact(psi_in, CHI, 1.0, cells=800, steps=4000).psi_out
        assert abs(default - fine) < 2e-4


@pytest.mark.slow
def test_independent_solution_on_the_exact_curve():
    """The independent solution reproduces the exact chi = 1/2 curve (2e-4 on 500 steps, both
    branches) and the gross-slip line at the sphere's chi (5e-4: measured 2.6e-4, the midpoint
    sums of its springs' loads and the trapezoidal rule in time)."""
    for psi_in in (0.5, 1.5):
        value = exact.entry_time_rebound(psi_in, 0.5, 1.0, steps=500)
        assert value == pytest.approx(float(exact.half_chi_rebound(psi_in)), abs=2e-4)
    psi_in = 1.1 * exact.gross_slip_threshold(CHI, 1.0)
    assert exact.entry_time_rebound(psi_in, CHI, 1.0, steps=500) == pytest.approx(
        float(exact.gross_slip_rebound(psi_in, CHI, 1.0)), abs=5e-4
    )


@pytest.mark.slow
@pytest.mark.parametrize(
    "e_n, psi_in",
    [(1.0, 0.3), (1.0, 0.6), (1.0, 1.2), (1.0, 2.0), (1.0, 3.0), (1.0, 4.0), (1.0, 4.5),
     (0.8, 0.3), (0.8, 1.2), (0.8, 3.0)],
)  # fmt: skip
def test_mbf_curve_against_the_independent_solution(e_n, psi_in):
    """The solid sphere's MBF curve over the range, the reversal region included: the law
    within 2 % of the independent solution of MBF's equations, and within 5e-4 absolute (the
    measured differences are 5e-6 to 3.9e-4, 0.001-0.96 %, largest where Psi_out is small)."""
    reference = exact.entry_time_rebound(psi_in, CHI, e_n)
    law = compliant_impact(psi_in, CHI, e_n).psi_out
    assert abs(law - reference) <= 0.02 * abs(reference)
    assert abs(law - reference) <= 5e-4


@pytest.mark.parametrize("psi_in", [0.01, 0.5, 2.0, 3.5, 6.0])
def test_energy_closes(psi_in):
    """The impact's tangential energy (slip's kinetic + springs') is returned or dissipated:
    nothing stored once the contact has left, the slip's dissipation never falls, and
    E_in = E_out + dissipated to the time step's first-order error (measured 2.7e-3 to 8.7e-3
    of E_in on the coarse grid for Psi_1 = 0.01 to 6; halved by a grid twice finer, to 1 %)."""
    impact = compliant_impact(psi_in, CHI, 1.0, **COARSE)
    finer = compliant_impact(psi_in, CHI, 1.0)
    assert impact.stored[-1] == 0.0
    assert np.all(np.diff(impact.dissipated) >= 0.0)
    assert impact.energy_error < 1e-2
    assert impact.energy_error / finer.energy_error == pytest.approx(2.0, rel=0.01)
    assert abs(impact.psi_out) <= psi_in * (1 + impact.energy_error)


@pytest.mark.slow
def test_walton_limits():
    """Walton's law: with beta_0 = 0 it is the rigid-body Coulomb impact (to rounding); with the
    compliant contact's beta_0 = -r it meets the compliant law in both limits (small Psi_1 to
    1.5e-3 of Psi_1, gross slip to 1e-6, past both laws' starts of sliding throughout), in the
    project's psi (mu = 0.3)."""
    mu, e_n = 0.3, 1.0
    for psi_in in (-2.0, -0.4, 0.0, 0.1, 0.7, 2.3, 5.0):
        rigid, _ = frictional_impact(psi_in, mu, e_n, K)
        assert walton_impact(psi_in, mu, e_n, K, 0.0) == pytest.approx(rigid, abs=1e-12)
    beta_0 = -exact.adhesive_ratio(CHI, e_n)
    scale = mu / KAPPA  # psi by Psi
    small = 1e-3 * scale
    law, _ = compliant_rebound(small, mu, e_n, KAPPA, K)
    assert abs(law - walton_impact(small, mu, e_n, K, beta_0)) < 1.5e-3 * small
    reach = (1 + 1 / K) * mu * (1 + e_n)  # Walton slides from reach / (1 + beta_0) on
    large = 1.2 * max(exact.gross_slip_threshold(CHI, e_n) * scale, reach / (1 + beta_0))
    for psi_in in (large, -large):
        law, stopped = compliant_rebound(psi_in, mu, e_n, KAPPA, K)
        assert not stopped
        assert law == pytest.approx(float(walton_impact(psi_in, mu, e_n, K, beta_0)), abs=1e-6)
    with pytest.raises(ValueError, match="beta_0"):
        walton_impact(0.1, mu, e_n, K, 1.5)


def test_mindlin_stiffness_ratio():
    """k_t/k_n = 4 G*/E*: 2 (1 - nu)/(2 - nu) for identical solids (to rounding), between the
    two solids' own values for steel on glass."""
    steel, glass = MATERIALS["steel"], MATERIALS["glass"]
    nu = steel.poisson_ratio
    assert mindlin_stiffness_ratio([steel, steel]) == pytest.approx(
        2 * (1 - nu) / (2 - nu), rel=1e-15
    )
    own = [2 * (1 - s.poisson_ratio) / (2 - s.poisson_ratio) for s in (steel, glass)]
    assert min(own) <= mindlin_stiffness_ratio([steel, glass]) <= max(own)


ROUGH = dict(St=50.0, eps=1e-4, delta=0.01, p_cav=-2.0, layer="thin", e_dry=0.8)
ROUGH_CONTACT = dict(ROUGH, roughness=0.03, friction_coefficient=0.3, angle=10.0)


@pytest.mark.parametrize(
    "change, name",
    [
        (dict(tangential_compliance=0.5), "tangential_compliance"),
        (dict(tangential_compliance=1.5), "tangential_compliance"),
        (dict(tangential_compliance=KAPPA, friction_coefficient=0.0), "tangential_compliance"),
        (dict(tangential_compliance=KAPPA, angle=0.0), "tangential_compliance"),
    ],
)
def test_refused_inputs(change, name):
    """Outside [2/3, 4/3], without friction or head-on: refused by name before any work."""
    with pytest.raises(InputError) as error:
        CollisionParameters.from_settings(**{**ROUGH_CONTACT, **change})
    assert error.value.name == name


def test_refused_on_smooth_surfaces_and_with_greenwood_tripp():
    """Smooth surfaces (no solid contact) refuse the option by name; with Greenwood-Tripp's
    asperities (no single Hertz contact) the flat setting is warned of and left out, and the
    physical inputs refuse it by name."""
    smooth = dict(ROUGH, angle=10.0, friction_coefficient=0.0)
    with pytest.raises(InputError) as error:
        CollisionParameters.from_settings(**smooth, tangential_compliance=KAPPA)
    assert error.value.name in ("tangential_compliance", "friction_coefficient")
    with pytest.warns(UserWarning, match="tangential_compliance has no effect"):
        params = CollisionParameters.from_settings(
            **ROUGH_CONTACT, tangential_compliance=KAPPA, asperities="greenwood-tripp"
        )
    assert params.tangential_compliance == 0.0
    with pytest.raises(InputError) as error:
        from_presets(
            **EXAMPLE,
            sphere_roughness=3e-6,
            friction_coefficient=0.3,
            asperities=GreenwoodTrippAsperities.name,
            tangential_compliance=KAPPA,
        )
    assert error.value.name == "tangential_compliance"
    assert "acts only with asperities = 'impact'" in str(error.value)


@pytest.mark.slow
@pytest.mark.filterwarnings("ignore")
def test_real_rough_collision():
    """A real rough collision (impact model, Couette film, 40 nodes): the solid impact's psi_out
    is the compliant law's of its psi_in and restitution e_dry (to rounding), the slip
    reverses where the rigid law sticks, U + k a Omega is conserved through the impact's step
    (by the film and by the impulse), and the impact's friction dissipation is the kinetic
    energy of the slip it removed, (St/2) k/(1 + k) (u_s^2 - u_s'^2) > 0."""
    options = dict(nodes=40, tangential="couette")
    rigid = collide(CollisionParameters.from_settings(**ROUGH_CONTACT), **options)
    params = CollisionParameters.from_settings(**ROUGH_CONTACT, tangential_compliance=KAPPA)
    compliant = collide(params, **options)
    psi_in, psi_out = compliant.tangential.friction.impact_psi
    law, _ = compliant_rebound(psi_in, 0.3, ROUGH["e_dry"], KAPPA, K)
    assert psi_out == pytest.approx(law, abs=1e-12)
    assert rigid.tangential.friction.impact_psi[1] == 0.0 and psi_out < 0.0
    hist, impact = compliant.tangential, compliant.normal.solid_impact
    momentum = hist.velocity + K * hist.spin
    assert momentum[impact.index] == pytest.approx(momentum[impact.index - 1], rel=1e-12)
    per_psi = abs(impact.approach_velocity) / params.tangential_speed  # u_s by psi
    slips = np.array([psi_in, psi_out]) * per_psi
    removed = 0.5 * params.St * K / (1 + K) * (slips[0] ** 2 - slips[1] ** 2)
    dissipated = compliant.tangential.friction.dissipated
    step_loss = dissipated[impact.index] - dissipated[impact.index - 1]
    assert step_loss == pytest.approx(removed, rel=1e-10)
    assert removed > 0.0
    assert 0.0 < compliant.summary()["e_t"] < rigid.summary()["e_t"]
