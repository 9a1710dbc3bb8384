"""Two free spheres colliding obliquely (ehdfem.tangential.pair, docs/tangential.md "Two spheres").

Checked against exact results:
- the rigid two-sphere impact with Coulomb friction (ehdfem.exact.rigid_impact.pair_impact)
  against the conservation laws that fix it (the pair's momentum, each sphere's angular
  momentum about the contact point, the slip stopped or the impulse at mu N), and in the limit
  m2 -> inf against the sphere-on-plane law;
- the model's solid impact on a rough pair against that law (psi, impulse, both spins' jumps);
- the model's motion against an independent integration of the four equations of the two
  spheres (U1, U2, Omega1, Omega2) under the film's shear, and its energy over both spheres
  (translation and spin) against the integrated dissipation, in each model offered for a pair
  and with the solid contact's friction;
- equal spheres: equal spin changes, opposite spins (surfaces moving together) changing
  nothing, and the sphere on a wall's e_t at the same groups;
- the large-partner limit a2, m2 -> inf: the sphere on a wall, at first order in a1/a2;
- FE solids against half-spaces for a pair, within the wall's own difference.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import replace

import numpy as np
import pytest
import scipy.integrate
from test_friction import roughened

from ehdfem import CollisionParameters, collide
from ehdfem.checks import InputError
from ehdfem.collision import with_tangential
from ehdfem.config import RunConfig
from ehdfem.exact.rigid_impact import frictional_impact, pair_impact
from ehdfem.exact.sliding_sphere import MODE_ONE_END
from ehdfem.exact.sphere_pair import pair_logarithmic
from ehdfem.film.grid import contact_grid
from ehdfem.inputs.presets import EXAMPLE
from ehdfem.inputs.scales import from_presets, reduced_mass, reduced_radius
from ehdfem.motion.normal import solve_normal
from ehdfem.outputs.plausibility import ResultRangeWarning
from ehdfem.solids.compliance import RigidSolids
from ehdfem.solids.fe.bodies import LowerSphere
from ehdfem.tangential.pair import PAIR_MODELS, SLIP_MODELS, SpherePair, solve_pair

pytestmark = pytest.mark.serial

THIN = dict(layer="thin", delta=0.01, p_cav=-2.0)
ROUNDING = 1e-12  # closed forms reproduced up to a few roundings of O(1) numbers
# an unequal pair: a1/a2 = 0.8, rho2/rho1 = 0.7 (m1/m2 = 0.731), a solid upper and a shell lower
# sphere, the lower one spinning
UNEQUAL = dict(lower="sphere", radius_ratio=0.8, density_ratio=0.7, lower_inertia_factor=2 / 3)


@pytest.fixture(scope="module")
def unequal():
    """An oblique thin-layer collision of the unequal pair on half-spaces (60 film nodes)."""
    params = CollisionParameters.from_settings(St=10.0, eps=1e-3, angle=30.0, spin=0.1, **THIN)
    return collide(params, nodes=60, lower_spin=-0.25, **UNEQUAL)


def momenta(velocities, spins, masses, radii, k):
    """(the pair's tangential momentum, each sphere's angular momentum about the contact
    point): m1 U1 + m2 U2, I1 Omega1 + m1 a1 U1, I2 Omega2 - m2 a2 U2 (centres at +a1 and -a2
    along the normal from the contact point)."""
    (U1, U2), (w1, w2), (m1, m2), (a1, a2) = velocities, spins, masses, radii
    upper = k[0] * m1 * a1**2 * w1 + m1 * a1 * U1
    lower = k[1] * m2 * a2**2 * w2 - m2 * a2 * U2
    return np.array([m1 * U1 + m2 * U2, upper, lower])


@pytest.mark.parametrize("mu", [0.01, 0.5])
def test_rigid_pair_impact_keeps_the_momenta_and_obeys_coulomb(mu):
    """An impulse at the contact point keeps the pair's momentum and each sphere's angular
    momentum about that point; with these three laws the slip after the impact (0 when stuck)
    or the impulse (mu N when sliding) fixes the outcome. mu = 0.01 slides, 0.5 sticks."""
    masses, radii, k = (2.0, 5.0), (0.7, 1.3), (0.4, 2 / 3)
    U, w = (0.9, -0.2), (0.3, 0.5)
    slip = U[0] - U[1] - (radii[0] * w[0] + radii[1] * w[1])
    impact = pair_impact(slip, 1.5, mu, 0.6, masses, radii, k)
    after_U = tuple(u + d for u, d in zip(U, impact.velocity_changes, strict=True))
    after_w = tuple(s + d for s, d in zip(w, impact.spin_changes, strict=True))
    before = momenta(U, w, masses, radii, k)
    after = momenta(after_U, after_w, masses, radii, k)
    assert after == pytest.approx(before, abs=ROUNDING)
    slip_after = after_U[0] - after_U[1] - (radii[0] * after_w[0] + radii[1] * after_w[1])
    assert slip_after == pytest.approx(impact.slip_after, abs=ROUNDING)
    normal = 1.6 * 1.5 * masses[0] * masses[1] / sum(masses)
    assert impact.stuck == (mu == 0.5)
    if impact.stuck:
        assert impact.slip_after == 0.0 and abs(slip_after) <= ROUNDING
        assert abs(impact.impulse) < mu * normal
    else:
        assert impact.impulse == pytest.approx(-mu * normal, rel=ROUNDING)
        assert np.sign(impact.slip_after) == np.sign(slip)


@pytest.mark.parametrize(("psi_in", "mu"), [(1.0, 0.1), (0.3, 0.2)])
def test_rigid_pair_impact_on_a_heavy_large_partner_is_the_wall_law(psi_in, mu):
    """m2 = 1e12 m1, a2 = 1e4 a1: psi_out of the sphere on a plane (sliding and stuck) to the
    partner's share, 1e-10."""
    impact = pair_impact(psi_in, 1.0, mu, 0.8, (1.0, 1e12), (1.0, 1e4), (0.4, 0.4))
    psi_out, stuck = frictional_impact(psi_in, mu, 0.8, 0.4)
    assert impact.stuck == stuck
    assert impact.slip_after == pytest.approx(psi_out, abs=1e-10)


def mapped(pair):
    """(m1, m2) of a pair whose reduced mass is 1: m1 = 1 + m1/m2, m2 = 1 + m2/m1."""
    ratio = pair.mass_ratio
    return (1.0 + ratio, 1.0 + 1.0 / ratio)


@pytest.mark.parametrize("mu", [0.05, 1.0])
def test_rough_pair_impact_follows_the_rigid_two_sphere_law(unequal, mu):
    """The solid impact of a rough unequal pair (impact model, e_dry = 0.8): the slip after it
    over the approach speed, the tangential impulse and both spheres' spin jumps at the
    impact's step (the run with mu less the run with mu = 0, whose film steps are the same) are
    pair_impact's with the reduced mass and radius 1, in units of m |V| V0 and |V| V0 (mu =
    0.05 slides, 1.0 sticks)."""
    normal = roughened(unequal.normal)
    runs = {}
    for coefficient in (0.0, mu):
        params = normal.params.with_settings(friction_coefficient=coefficient)
        rough = replace(unequal, params=params, normal=replace(normal, params=params))
        runs[coefficient] = with_tangential(rough, "couette").tangential
    tangential, film = runs[mu], runs[0.0]
    index = normal.solid_impact.index
    speed = abs(normal.solid_impact.approach_velocity)
    unit = normal.params.tangential_speed / speed  # by U0 -> by |V| V0
    pair = tangential.pair.pair
    masses, radii = mapped(pair), (1.8, 2.25)  # a1/a2 = 0.8, reduced radius 1
    psi_in, psi_out = tangential.friction.impact_psi
    exact = pair_impact(psi_in, 1.0, mu, 0.8, masses, radii, (0.4, 2 / 3))
    assert exact.stuck == (mu == 1.0) == tangential.friction.any_stuck
    assert psi_out == pytest.approx(exact.slip_after, abs=ROUNDING)
    impulse = tangential.friction.impulse[index] / normal.params.St * unit
    assert impulse == pytest.approx(exact.impulse, rel=1e-12)
    jumps = (
        tangential.velocity[index] - film.velocity[index],
        tangential.spin[index] - film.spin[index],
        tangential.pair.lower_spin[index] - film.pair.lower_spin[index],
    )
    expected = (
        exact.velocity_changes[0] - exact.velocity_changes[1],
        radii[0] * exact.spin_changes[0],
        radii[1] * exact.spin_changes[1],
    )
    assert np.array(jumps) * unit == pytest.approx(expected, abs=ROUNDING)


def film_loads(result):
    """The film's force F on sphere 1 and torques T_i/a_i on both spheres (by 6 pi mu a^2 U0 /
    x0) and its dissipation rate as functions of (each step's mean coefficient, u_s, w) with
    w = rho U + s1 - s2 the entrainment, rho = (a2 - a1)/(a1 + a2), written from the film's
    traction on each surface (docs/tangential.md, "Two spheres"), and the coefficient at the
    steps: for Couette the shear integral J, F = -(delta/3) J u_s on sphere 1, its opposite on
    sphere 2, the same torque per radius on both; for gcb L = -ln(delta H_min), the Couette
    shear (1/3) L u_s and the entrainment's pressure (1/5) L w, whose force has the factor rho
    and whose torques differ in sign on the two spheres."""
    tangential, delta = result.tangential, result.params.delta
    if tangential.model == "couette":

        def couette(J, slip, _):
            force = -delta / 3.0 * J * slip
            return force, -force, -force, delta / 3.0 * J * slip**2

        return couette, tangential.shear
    ratio = tangential.pair.pair.radius_ratio
    rho = (1.0 - ratio) / (1.0 + ratio)

    def gcb(L, slip, entrainment):
        shear, pressure = delta * L * slip / 3.0, delta * L * entrainment / 5.0
        loads = (-shear - rho * pressure, shear - pressure, shear + pressure)
        return (*loads, delta * L * (slip**2 / 3.0 + entrainment**2 / 5.0))

    return gcb, -np.log(delta * result.normal.history.min_film)


def four_body(result, steps):
    """The two spheres' equations m1 dU1/dT = F, m2 dU2/dT = -F, I1 dOmega1/dT = T1,
    I2 dOmega2/dT = T2 (reduced mass and radius 1) under the film's loads
    (:func:`film_loads`), each step's coefficient its mean (the models' trapezoid rule), with
    the dissipation (by m U0^2 / St), integrated by scipy's DOP853 at rtol 1e-12 to the step
    ``steps``: (U1 - U2, a1 Omega1, a2 Omega2, dissipated) there, by U0."""
    params, hist = result.params, result.normal.history
    pair = result.tangential.pair.pair
    St, tangent = params.St, params.tangential_speed
    (m1, m2), k = mapped(pair), (pair.upper_inertia, pair.lower_inertia)
    rho = (1.0 - pair.radius_ratio) / (1.0 + pair.radius_ratio)
    loads, coefficient = film_loads(result)
    means = 0.5 * (coefficient[1:] + coefficient[:-1])

    def rates(_, state, mean):  # state (U1, U2, s1, s2, D); s_i = a_i Omega_i
        U1, U2, s1, s2, _ = state
        slip, entrainment = U1 - U2 - s1 - s2, rho * (U1 - U2) + s1 - s2
        force, upper, lower, dissipation = loads(mean, slip, entrainment)
        return [force / (St * m1), -force / (St * m2), upper / (St * k[0] * m1),
                lower / (St * k[1] * m2), dissipation]  # fmt: skip

    state = [1.0, 0.0, params.spin / tangent, pair.lower_spin / tangent, 0.0]
    for i in range(steps):
        span = (hist.time[i], hist.time[i + 1])
        solution = scipy.integrate.solve_ivp(
            rates, span, state, "DOP853", args=(means[i],), rtol=1e-12, atol=1e-15
        )
        state = solution.y[:, -1]
    U1, U2, s1, s2, dissipated = state
    return U1 - U2, s1, s2, dissipated


@pytest.mark.parametrize("model", ["couette", "gcb"])
def test_pair_is_the_two_spheres_equations(unequal, model):
    """The unequal pair with spins, at its last full step before exit: U1 - U2 and both spins
    from the four equations of the two spheres under the film's traction on each surface,
    integrated independently, to 1e-10; the pair's kinetic energy over both spheres
    (translation and spin) has fallen by the integrated dissipation to 1e-10 of the impact
    energy, and so has the model's own record of it. Couette: the shear of the slip alone;
    gcb: also the pressure of the entrainment, with its factor rho in the force and its
    opposite torques."""
    tangential = with_tangential(unequal, model).tangential
    collision = replace(unequal, tangential=tangential)
    step = len(tangential.velocity) - 2
    relative, upper, lower, dissipated = four_body(collision, step)
    assert tangential.velocity[step] == pytest.approx(relative, abs=1e-10)
    assert tangential.spin[step] == pytest.approx(upper, abs=1e-10)
    assert tangential.pair.lower_spin[step] == pytest.approx(lower, abs=1e-10)
    kinetic = tangential.pair.kinetic
    assert kinetic[0] - kinetic[step] == pytest.approx(dissipated, abs=1e-10 * kinetic[0])
    assert tangential.pair.film_dissipated[step] == pytest.approx(
        dissipated, abs=1e-10 * kinetic[0]
    )


ROUGH_CASES = {"impact": (None, 0.05), "stick": (None, 1.0), "asperities": (0.2, 0.3)}


# the energy balance's bound: exact integrations (round-off), and the sliding film's BDF2 on the
# normal motion's steps, as on a wall (measured for the pair 1.8e-3, 4.5e-4, 3.3e-4 smooth, at
# the impact, stuck; 1.8e-2 with the asperity load, where the wall's is 2.7e-2)
BALANCE = {"couette": 1e-10, "flat": 1e-10, "gcb": 1e-10, "lubrication": 3e-3}


@pytest.mark.parametrize("model", PAIR_MODELS)
@pytest.mark.parametrize("rough", [None, *ROUGH_CASES])
def test_energy_closes_over_both_spheres(unequal, model, rough):
    """Every model offered for a pair, smooth and with the solid contact's friction (an impact
    sliding at mu = 0.05 or sticking at mu = 1, an asperity load of 20 % of the film's at
    mu = 0.3): the kinetic energy of both spheres' translation and spin at exit equals its
    impact value less the film's and the friction's dissipation (and the sliding film's
    elastic energy and exchange with the normal motion) to BALANCE of the loss (10 times it
    for the sliding film with the asperity load), never rises, and the pair's angular
    momentum about the contact point, (a1 + a2) U + a1 W1 s1 + a2 W2 s2 with
    W_i = k_i (1 + m_i/m_j), keeps its impact value at every step to 1e-12 (the film's and
    the contact's forces act at the contact point; measured 1e-14 in the sliding film). In
    the slip-only models the spheres' spins change in the ratio of their shares; not in gcb
    and the sliding film, whose pressure turns them by the entrainment too."""
    normal, mu = unequal.normal, 0.0
    if rough is not None:
        share, mu = ROUGH_CASES[rough]
        normal = roughened(normal, asperity_share=share)
    params = normal.params.with_settings(friction_coefficient=mu)
    collision = replace(unequal, params=params, normal=replace(normal, params=params))
    tangential = with_tangential(collision, model).tangential
    motion = tangential.pair
    bound = BALANCE[model] * (10.0 if model == "lubrication" and rough == "asperities" else 1.0)
    assert motion.balance_error <= bound, motion.balance_error
    assert np.all(np.diff(motion.kinetic) <= 1e-12 * motion.kinetic[0])
    assert (tangential.friction is not None) == (rough is not None)
    pair = motion.pair
    radii = (1.0 + pair.radius_ratio, 1.0 + 1.0 / pair.radius_ratio)  # by the reduced radius
    weights = pair.spin_weights
    momentum = sum(radii) * tangential.velocity + radii[0] * weights[0] * tangential.spin
    momentum += radii[1] * weights[1] * motion.lower_spin
    assert np.abs(momentum - momentum[0]).max() <= 1e-12 * abs(momentum[0])
    first, second = pair.shares
    shared = tangential.spin_change * second - motion.lower_spin_change * first
    assert (abs(shared) <= ROUNDING) == (model in SLIP_MODELS), shared


@pytest.fixture(scope="module")
def equal():
    """Equal spheres (the defaults of lower = 'sphere') and the sphere on a wall, at the same
    groups (40 film nodes)."""
    params = CollisionParameters.from_settings(St=20.0, eps=1e-2, angle=40.0, **THIN)
    return collide(params, nodes=40, lower="sphere"), collide(params, nodes=40)


def test_equal_spheres_share_the_spin_and_have_the_wall_e_t(equal):
    """Equal solid spheres: k = 2/5 for the pair, so the relative motion is the sphere on a
    wall's at the same groups (St and the film by the reduced mass and radius): e_t equal to
    rounding, and each sphere takes half the wall sphere's spin change."""
    pair, wall = (r.tangential for r in equal)
    assert pair.pair.pair.inertia_factor == 0.4
    assert pair.e_t == pytest.approx(wall.e_t, abs=ROUNDING)
    assert pair.spin_change == pytest.approx(0.5 * wall.spin_change, abs=ROUNDING)
    assert pair.pair.lower_spin_change == pytest.approx(0.5 * wall.spin_change, abs=ROUNDING)


@pytest.mark.parametrize("spin", [0.3, -1.2])
def test_equal_and_opposite_spins_change_nothing(equal, spin):
    """Equal spheres spinning equally and oppositely about the common axis (a1 Omega1 =
    -a2 Omega2: their surfaces at the contact move together, as two gears): the contact spin is
    0, so e_t and both spin changes are those without spin, and the spins' difference stays."""
    pair = equal[0]
    params = replace(pair.params, spin=spin)
    spun = collide(params, nodes=40, lower="sphere", lower_spin=-spin).tangential
    assert spun.e_t == pytest.approx(pair.tangential.e_t, abs=ROUNDING)
    assert spun.spin_change == pytest.approx(pair.tangential.spin_change, abs=ROUNDING)
    assert spun.pair.lower_spin_change == pytest.approx(spun.spin_change, abs=ROUNDING)
    tangent = params.tangential_speed
    assert spun.spin - spun.pair.lower_spin == pytest.approx(2 * spin / tangent, abs=ROUNDING)


@pytest.mark.parametrize("spin", [0.3, -1.2])
def test_equal_spheres_in_gcb(equal, spin):
    """Equal spheres in gcb, spinning equally and oppositely (s1 = -s2 = s): rho = 0, so the
    entrainment's pressure exerts no net force (F = -(delta/3) L u_s, L = -ln(delta H_min), to
    round-off) and the motion splits exactly: the slip decays as
    exp(-(1 + 1/k)(delta/(3 St)) int L dT) (k = 2/5) and the spins' difference, the
    entrainment s1 - s2, as exp(-(2/5) delta int L dT / (St W)) with W = 2k, each with int L dT
    by the trapezoid rule (1e-12 at every step). The contact spin s1 + s2 is 0 as without
    spin, so e_t and its change are those of the run without spin (round-off); but unlike the
    slip-only models the gears' rolling pumps the liquid through the gap, and its pressure
    and shear brake both spins alike."""
    base = with_tangential(equal[0], "gcb").tangential
    params = replace(equal[0].params, spin=spin)
    spun = collide(params, nodes=40, lower="sphere", lower_spin=-spin, tangential="gcb")
    tangential, hist = spun.tangential, spun.normal.history
    St, delta, k = params.St, params.delta, 0.4
    logarithm = -np.log(delta * hist.min_film)
    integral = scipy.integrate.cumulative_trapezoid(logarithm, hist.time, initial=0.0)
    shear = -delta / 3.0 * logarithm * tangential.slip
    assert tangential.force == pytest.approx(shear, abs=ROUNDING * np.abs(shear).max())
    slip = tangential.slip[0] * np.exp(-(1.0 + 1.0 / k) * delta / (3.0 * St) * integral)
    assert tangential.slip == pytest.approx(slip, abs=1e-12)
    difference = tangential.spin - tangential.pair.lower_spin
    start = 2.0 * spin / params.tangential_speed
    decayed = start * np.exp(-0.4 * delta * integral / (St * 2.0 * k))
    assert difference == pytest.approx(decayed, abs=1e-12)
    assert difference[-1] / difference[0] < 0.995  # braked by 1.05 % (St 20, eps 1e-2, 40 deg)
    assert tangential.e_t == pytest.approx(base.e_t, abs=ROUNDING)
    assert tangential.pair.contact_spin_change == pytest.approx(
        base.pair.contact_spin_change, abs=ROUNDING
    )


def rigid_immersed_approach():
    """A rigid sphere pair's immersed approach by the reduced radius (delta = 1e-3, St = 6: it
    stops near X = exp(-6)) at 45 degrees, spinning, on a grid with a node at R_a = 1/sqrt(delta)
    (400 nodes)."""
    params = CollisionParameters(
        St=6.0, eps=1.0, delta=1e-3, layer="immersed", angle=45.0, spin=0.3
    )
    outer = 1.0 / np.sqrt(params.delta)
    return solve_normal(params, RigidSolids(contact_grid(400, 0.3, 2.0 * outer, node_at=outer)))


@pytest.mark.slow
def test_rigid_pair_sliding_film_has_the_cut_film_resistances():
    """The sliding film of two rigid spheres (deformation "none") at a1/a2 = 0.5 and 3, the
    lower one spinning: at every step with X <= 0.1 its force on sphere 1 is
    -delta (R v)_1 of the film cut at r = a in closed form,
    R = L_a ((1/3) e e^T + (1/5) g g^T) - (1/5)(1 + 2/sqrt(10)) g g^T, L_a = ln(1 + 1/(2 delta X)),
    v = (U, s1, s2), e the slip, g = (rho, 1, -1) the entrainment (the wall's cut film,
    ehdfem.exact.sliding_sphere, with w_pair in place of U + a Omega and rho on the force), to
    2e-3 (the film's discretisation on 400 nodes: measured 9.6e-4 and 1.4e-6), and the torques
    over the radii, St k_i (1 + m_i/m_j) ds_i/dT by differences of the spins' histories, and
    St dU/dT likewise, its rows 2 and 3 to 1e-2 (the differences' error: measured 1.3e-3 to
    7.3e-3). This checks the new terms: the entrainment, rho on the undeformed slope and
    each sphere's torque from its own traction."""
    normal = rigid_immersed_approach()
    hist, delta = normal.history, normal.params.delta
    steps = np.flatnonzero((hist.gap <= 0.1) & (hist.gap > 0))
    steps = steps[(steps > 1) & (steps < len(hist.time) - 2)]
    assert len(steps) > 10
    cut = np.log1p(1.0 / (2.0 * delta * hist.gap[steps]))[:, None, None]
    for ratio in (0.5, 3.0):
        pair = SpherePair(0.731, 0.4, 2 / 3, -0.2, ratio)
        tangential = solve_pair(normal, "lubrication", pair, deformation="none")
        entrainment = np.array([pair.rho, 1.0, -1.0])
        closed = cut * pair_logarithmic(ratio) - MODE_ONE_END * np.outer(entrainment, entrainment)
        histories = (tangential.velocity, tangential.spin, tangential.pair.lower_spin)
        expected = -delta * np.einsum("sij,sj->si", closed, np.column_stack(histories)[steps])
        assert np.abs(tangential.force[steps] / expected[:, 0] - 1.0).max() < 2e-3
        weights = (1.0, *pair.spin_weights)
        for row, (weight, history) in enumerate(zip(weights, histories, strict=True)):
            rate = weight * normal.params.St * np.gradient(history, tangential.time)[steps]
            assert np.abs(rate / expected[:, row] - 1.0).max() < 1e-2, row


@pytest.mark.parametrize("spin", [0.3, -1.2])
def test_equal_spheres_sliding_film(equal, spin):
    """Equal spheres, the sliding film on rigid mode-1 solids (deformation "none"; identical
    half-spaces, so the surfaces' axisymmetric displacements cancel in their sum): rho = 0, so
    the mode-1 pressure exerts no net force and U and the contact spin s1 + s2 move under the
    Couette shear alone. Spinning equally and oppositely: e_t and the contact spin's change
    are those without spin (1e-12), while the entrainment s1 - s2 drives the mode-1 pressure,
    which brakes both spins alike: their difference falls by 0.26 % (St 20, eps 1e-2, 40
    degrees, the thin layer's film; gcb's logarithm brakes it by 1.05 %)."""
    base = with_tangential(equal[0], "lubrication", deformation="none").tangential
    params = replace(equal[0].params, spin=spin)
    spun = collide(
        params, nodes=40, lower="sphere", lower_spin=-spin, tangential="lubrication",
        deformation="none",
    ).tangential  # fmt: skip
    assert spun.e_t == pytest.approx(base.e_t, abs=1e-12)
    assert spun.pair.contact_spin_change == pytest.approx(base.pair.contact_spin_change, abs=1e-12)
    difference = spun.spin - spun.pair.lower_spin
    assert difference[-1] / difference[0] < 0.999


def pair_groups(ratio: float):
    """The scaled inputs of a steel-like upper sphere (St 10, eps 1e-3, delta 0.01 and
    P_cav -2 on a wall) meeting a sphere ``ratio`` times larger, of the same material and
    density: St ~ m/a^2, eps ~ a^(3/2), delta ~ 1/a, P_cav ~ a with the reduced radius
    a = a1 N/(N + 1) and mass m = m1 N^3/(N^3 + 1)."""
    radius, mass = reduced_radius(1.0, ratio), reduced_mass(1.0, ratio**3)
    return CollisionParameters.from_settings(
        St=10.0 * mass / radius**2,
        eps=1e-3 * radius**1.5,
        delta=0.01 / radius,
        p_cav=-2.0 * radius,
        angle=30.0,
    )


LARGE_PARTNERS = {
    "couette": ((10.0, 100.0, 1000.0), 5e-4),
    "gcb": ((100.0, 1000.0, 1e4), 3e-4),
    "lubrication": ((100.0, 1000.0, 1e4), 1e-4),
}


@pytest.mark.slow
@pytest.mark.parametrize("model", LARGE_PARTNERS)
def test_a_large_heavy_partner_is_a_wall(model):
    """a2 = N a1 and m2 = N^3 m1 (same material and density, the lower sphere a shell,
    k2 = 2/3): e_t and the upper sphere's spin change tend to the sphere on a wall's (the
    same model) as N grows, at first order in 1/N (the reduced radius a1 N/(N + 1); in gcb
    also rho = (N - 1)/(N + 1) in the entrainment). Measured relative errors of 1 - e_t:
    Couette 2.0e-2, 2.1e-3, 2.3e-4 at N = 10, 100, 1000 (orders 0.97-1.00 per decade), tested
    within 5e-4 at N = 1000; gcb 2.2e-1, 2.6e-2, 2.7e-3, 2.7e-4 at N = 10 to 10^4 (spin
    change 1.4e-1, 1.8e-2, 1.8e-3, 2.0e-4; orders 0.89-1.01), tested over N = 100 to 10^4,
    within 3e-4 at 10^4; the sliding film (mode-1 gap) 6.3e-2, 8.1e-3, 8.5e-4, 8.3e-5 (spin
    change 1.2e-2, 2.5e-3, 2.6e-4, 2.3e-5; orders 0.69-1.05, from N = 100 on 0.98-1.05),
    tested over N = 100 to 10^4, within 1e-4 at 10^4. The lower sphere's spin change falls
    as N^-3 (its inertia k2 (1 + m2/m1)); in the Couette model it is its share k1 m1/(k2 m2)
    of the contact spin's."""
    ratios, bound = LARGE_PARTNERS[model]
    nodes = 60
    wall = collide(pair_groups(math.inf), nodes=nodes, tangential=model).tangential
    errors = []
    for ratio in ratios:
        pair = collide(
            pair_groups(ratio), nodes=nodes, lower="sphere", radius_ratio=1.0 / ratio,
            lower_inertia_factor=2 / 3, tangential=model,
        ).tangential  # fmt: skip
        errors.append(
            (
                abs(pair.e_t - wall.e_t) / (1.0 - wall.e_t),
                abs(pair.spin_change - wall.spin_change) / wall.spin_change,
            )
        )
        share = pair.pair.pair.shares[1]
        assert share < 1.0 / ratio**3
        assert abs(pair.pair.lower_spin_change) < 1.0 / ratio**3
        if model == "couette":
            assert pair.pair.lower_spin_change == pytest.approx(
                share * pair.pair.contact_spin_change
            )
    errors = np.array(errors)
    orders = np.log10(errors[:-1] / errors[1:])
    assert np.all(orders > 0.9), orders
    assert np.all(errors[-1] < bound), errors


def test_pair_inputs_are_checked():
    """The pair's inputs, by name: a mass ratio > 0, inertia factors in (0, 2/3], a finite
    spin; the pair's models only; the pair's upper inertia factor the collision's."""
    with pytest.raises(InputError, match="mass_ratio"):
        SpherePair(0.0, 0.4, 0.4)
    with pytest.raises(InputError, match="lower_inertia"):
        SpherePair(1.0, 0.4, 0.7)
    with pytest.raises(InputError, match="lower_spin"):
        SpherePair(1.0, 0.4, 0.4, math.nan)


def test_pair_refusals(unequal):
    """The sliding film of a pair on FE solids is refused by name before any work (the lower
    sphere's FE mode-1 compliance is not built), and so is a pair whose upper inertia factor
    is not the collision's; physical inputs (one sphere's radius and mass) are refused for a
    pair before any work."""
    with pytest.raises(InputError, match="reduced radius"):
        collide(from_presets(**EXAMPLE), lower="sphere")
    with pytest.raises(InputError, match="lower = 'sphere' is not supported") as refused:
        RunConfig(model="fem", lower=LowerSphere(), tangential="lubrication")
    assert refused.value.name == "tangential"
    RunConfig(lower=LowerSphere(), tangential="lubrication")  # on half-spaces: built
    with pytest.raises(InputError, match="inertia_factor"):
        solve_pair(unequal.normal, "couette", SpherePair(1.0, 0.5, 0.4))


@pytest.mark.slow
def test_fe_and_halfspace_pairs_agree_as_the_wall_does():
    """FE solids against half-spaces (delta = 1e-3, paraboloid gap and pressure only in both,
    St 10, eps 1e-3, 60 film nodes): the pair of equal spheres and the pair a1 = 3 a2 differ in
    1 - e_t, in the upper sphere's spin change and in e_n by no more than the sphere on a wall
    does, in the Couette film and in gcb (measured, 1 - e_t: Couette -0.21 % for the wall,
    -0.19 % for both pairs; gcb -0.024 % for the wall, -0.019 % and -0.020 % for the pairs;
    e_n by 1.3e-3 and 1.2e-3), the finite solids' own difference."""
    params = CollisionParameters.from_settings(
        St=10.0, eps=1e-3, delta=1e-3, p_cav=-2.0, angle=30.0, gap="paraboloid",
        shear_traction=False,
    )  # fmt: skip

    def differences(**lower):
        half, fe = (collide(params, nodes=60, model=m, **lower) for m in ("halfspace", "fem"))
        by_model = {}
        for model in ("couette", "gcb"):
            h, f = (r if model == "couette" else with_tangential(r, model) for r in (half, fe))
            by_model[model] = np.abs(
                [
                    (f.tangential.e_t - h.tangential.e_t) / (1.0 - h.tangential.e_t),
                    f.tangential.spin_change / h.tangential.spin_change - 1.0,
                    f.normal.e_n - h.normal.e_n,
                ]
            )
        return by_model

    wall = differences()
    for model in ("couette", "gcb"):
        assert np.all(wall[model] < 3e-3), (model, wall)
    for ratio in (1.0, 3.0):
        pair = differences(lower="sphere", radius_ratio=ratio)
        for model in ("couette", "gcb"):
            assert np.all(pair[model] <= wall[model]), (model, ratio, pair, wall)


def test_an_immersed_pair_says_its_outer_flow_is_left_out():
    """An immersed oblique pair warns, and notes in its JSON, that the flow beyond its film's
    integrals (two spheres' O(1) resistances) is neither estimated nor added; a thin pair,
    whose film ends at its wetted edge inside r = a, does not."""
    immersed = CollisionParameters.from_settings(
        St=10.0, eps=1e-3, angle=30.0, layer="immersed", delta=0.01
    )
    with pytest.warns(ResultRangeWarning, match="neither estimated nor added"):
        result = collide(immersed, nodes=60, **UNEQUAL)
    assert any("neither estimated nor added" in note for note in result.summary()["notes"])
    thin = CollisionParameters.from_settings(St=10.0, eps=1e-3, angle=30.0, **THIN)
    with warnings.catch_warnings():
        warnings.simplefilter("error", ResultRangeWarning)
        result = collide(thin, nodes=60, **UNEQUAL)
    assert not any("neither estimated" in note for note in result.summary()["notes"])


def test_physical_pair_gives_the_reduced_groups():
    """Physical inputs of a pair (glass a1 = 2 mm over steel a2 = 1 mm in water, 0.5 m/s at
    30 deg, x0 = 20 um) give the groups by the reduced radius and mass, computed here by hand:
    a = 2/3 mm, m1 = 8.512e-5 kg, m2 = 3.259e-5 kg, m = 2.357e-5 kg, V0 = 0.4330 m/s,
    theta = 1.0126e-11 1/Pa; St = 1.218e3, eps = 3.50e-7, delta = 0.03; the lower sphere's
    settings a1/a2 = 2, rho2/rho1 = 7780/2540; and a collision with them runs as the pair."""
    from ehdfem.inputs.presets import liquid, material
    from ehdfem.inputs.scales import PhysicalPair

    pair = PhysicalPair(
        upper_radius=2e-3, lower_radius=1e-3, upper=material("glass"), lower=material("steel"),
        liquid=liquid("water"), speed=0.5, layer_thickness=2e-5, angle=30.0,
    )  # fmt: skip
    a = 2e-3 * 1e-3 / 3e-3
    m1, m2 = 4 / 3 * math.pi * 8e-9 * 2540.0, 4 / 3 * math.pi * 1e-9 * 7780.0
    m = m1 * m2 / (m1 + m2)
    v0 = 0.5 * math.cos(math.radians(30.0))
    theta = (1 - 0.23**2) / (math.pi * 60e9) + (1 - 0.27**2) / (math.pi * 190e9)
    params = pair.dimensionless()
    assert params.St == pytest.approx(m * v0 / (6 * math.pi * 1e-3 * a**2), rel=ROUNDING)
    assert params.St == pytest.approx(1.218e3, rel=1e-3)
    assert params.eps == pytest.approx(4 * theta * 1e-3 * v0 * a**1.5 / 2e-5**2.5, rel=ROUNDING)
    assert params.delta == pytest.approx(0.03, rel=ROUNDING)
    assert params.angle == 30.0 and params.inertia_factor == 0.4
    settings = pair.lower_settings()
    assert settings == pytest.approx(
        dict(lower="sphere", radius_ratio=2.0, density_ratio=7780 / 2540, lower_inertia_factor=0.4)
    )
    assert pair.scales().force == pytest.approx(6 * math.pi * 1e-3 * v0 * a**2 / 2e-5)
    result = collide(params, nodes=60, **settings)
    assert result.tangential.pair.pair.mass_ratio == pytest.approx(m1 / m2, rel=ROUNDING)
    with pytest.raises(InputError) as error:
        PhysicalPair(**{**vars(pair), "lower_radius": 0.0})
    assert error.value.name == "lower_radius"
