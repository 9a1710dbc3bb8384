"""The unsteady forces of a bouncing sphere's flight (ehdfem.bounce.unsteady) against exact
results: the history force of unsteady Stokes flow (a sphere started impulsively, Basset's
closed form; a sphere oscillating at a given frequency, Stokes' drag), the finite-Re kernel's
limits, and the added mass of a sphere moving normal to a wall (its images)."""

import math

import numpy as np
import pytest

from ehdfem.bounce.unsteady import (
    CONTACT_ALPHA,
    RELAXATION_TIMES,
    ZETA3,
    carry_memory,
    fitted_kernel,
    history_kernel,
    history_weights,
    kernel_decay,
    wall_added_mass,
)

pytestmark = pytest.mark.serial  # no parallel path: the MPI pass leaves it out

# a 3 mm sphere in a 10 cSt oil: a^2 / nu = 0.233 s
RADIUS, VISCOSITY, DENSITY = 1.5e-3, 9.35e-3, 935.0
NU = VISCOSITY / DENSITY
VISCOUS_TIME = RADIUS**2 / NU


def history_force(memory):
    """F_H = -6 pi mu a sum_i w_i z_i [N] with Basset's weights, for memories z [m/s] (rows)."""
    return -6 * math.pi * VISCOSITY * RADIUS * memory @ history_weights("basset", 0.0)


def test_impulsively_started_sphere_feels_bassets_force():
    """A sphere at rest set moving at U at t = 0 (a velocity jump, carried into the memory as
    the contacts' velocity change is) then held at U: the history force of unsteady Stokes
    flow is Basset's closed form, F_H = -6 a^2 U sqrt(pi rho mu / t) (Basset 1888; the added
    mass's impulse is at t = 0 only). To 1e-4 from t = 1e-7 to 100 a^2/nu (the sum of
    exponentials' error, 2e-6 relative there, module docstring of ehdfem.bounce.unsteady),
    with the memory advanced over uneven steps (exact for constant v)."""
    speed = 0.2
    times = np.concatenate([[0.0, 0.0], np.geomspace(1e-7, 100, 60) * VISCOUS_TIME])
    velocities = np.concatenate([[0.0], np.full(len(times) - 1, speed)])
    taus = RELAXATION_TIMES * VISCOUS_TIME
    memory = carry_memory(np.zeros(len(taus)), times, velocities, taus)
    force = history_force(memory[2:])
    basset = -6 * RADIUS**2 * speed * np.sqrt(math.pi * DENSITY * VISCOSITY / times[2:])
    assert np.max(np.abs(force / basset - 1)) < 1e-4


@pytest.mark.parametrize("frequency", [0.3, 3.0, 30.0])
def test_oscillating_sphere_has_stokes_history_drag(frequency):
    """A sphere oscillating as v = U sin(omega t) in liquid at rest: once the start is
    forgotten, its history force is Stokes' (1851) unsteady drag beyond the steady and added
    mass terms, F_H = -6 pi mu a U (a/delta) (sin omega t + cos omega t), delta = sqrt(2 nu /
    omega) (the Basset integral of e^(i omega t) is a sqrt(i omega / nu) e^(i omega t)), at
    omega a^2/nu = 0.3, 3 and 30. Over the last of 40 periods, to 1e-3 of the amplitude
    (measured 2.4e-4 to 5e-4): the memory's update is exact for v linear between the 800
    samples per period, which errs by O((omega dt)^(3/2)) on the singular kernel; the start's
    transient decays as t^(-3/2); the sum of exponentials misses the kernel below s = 1e-7,
    a share of order 1e-4 sqrt(omega a^2/nu) of the force (3e-3 when it stopped at 1e-5)."""
    speed, omega = 0.1, frequency / VISCOUS_TIME
    periods, per = 40, 800
    times = np.linspace(0.0, periods * 2 * math.pi / omega, periods * per + 1)
    velocities = speed * np.sin(omega * times)
    taus = RELAXATION_TIMES * VISCOUS_TIME
    memory = carry_memory(np.zeros(len(taus)), times, velocities, taus)
    last = slice(-per, None)
    delta = math.sqrt(2 * NU / omega)
    phase = omega * times[last]
    stokes = -6 * math.pi * VISCOSITY * RADIUS * speed * RADIUS / delta
    exact = stokes * (np.sin(phase) + np.cos(phase))
    error = np.max(np.abs(history_force(memory[last]) - exact)) / abs(stokes * math.sqrt(2))
    assert error < 1e-3


def test_finite_reynolds_kernel_limits():
    """Mei & Adrian's kernel K = [(pi s)^(1/4) + c(Re) s]^(-2): (i) Re -> 0 gives Basset's 1/sqrt(pi
    s): their relative difference is 2 c s^(3/4) / pi^(1/4) to first order, with c ~
    (sqrt(pi)/4)(Re/0.75)^(3/2): up to s = 100 below 1.1e-3 at Re = 1e-3 and 4e-8 at Re = 1e-6,
    falling as Re^(3/2); (ii) at long times it decays as (c s)^(-2), faster than Basset's
    s^(-1/2) (within 1 % of (c s)^-2 at s = 1e4 for Re = 30 to 800), and it never exceeds
    Basset's; (iii) c(Re) rises to (sqrt(pi)/4)(1/0.105)^(3/2) = 13.2 as Re -> inf (to 1e-3 at
    Re = 1e6); (iv) the sum of exponentials the flight uses follows the kernel to 1e-5 of K for
    s <= 10, 2e-4 for s <= 100 (where K is down to 1e-5 K_B) and to 2e-6 of Basset's for 1e-7 <=
    s <= 1e3, at Re = 0 to 800 (its fit, module docstring)."""
    s = np.logspace(-5, 2, 200)
    for re, bound in ((1e-3, 1.1e-3), (1e-6, 4e-8)):
        assert np.max(np.abs(history_kernel(s, re) * np.sqrt(math.pi * s) - 1)) < bound
    assert kernel_decay(1e-3) == pytest.approx(math.sqrt(math.pi) / 4 * (1e-3 / 0.75) ** 1.5, 1e-3)
    for re in (30.0, 150.0, 800.0):
        c = float(kernel_decay(re))
        assert history_kernel(1e4, re) * (c * 1e4) ** 2 == pytest.approx(1.0, rel=1e-2)
        assert np.all(history_kernel(s, re) <= history_kernel(s, 0.0))
    assert kernel_decay(1e6) == pytest.approx(math.sqrt(math.pi) / 4 / 0.105**1.5, rel=1e-3)
    wide = np.logspace(-7, 3, 400)
    for re in (0.0, 30.0, 164.0, 800.0):
        exact = history_kernel(wide, re)
        fitted = fitted_kernel(wide, "mei-adrian", re)
        assert np.max(np.abs(fitted / exact - 1)[wide <= 10]) < 1e-5
        assert np.max(np.abs(fitted / exact - 1)[wide <= 100]) < 2e-4
        assert np.max(np.abs(fitted - exact) * np.sqrt(math.pi * wide)) < 2e-6
    assert np.array_equal(fitted_kernel(wide, "basset", 500.0), fitted_kernel(wide, "basset", 0.0))
    assert not fitted_kernel(wide, "none", 100.0).any()


def test_wall_added_mass_of_the_sphere_and_its_images():
    """C_M(h)/C_M(inf) = 1 + 3 sum_{n>=2} (sinh alpha / sinh n alpha)^3, cosh alpha = 1 + h/a:
    (i) far away the first image, 1 + (3/8)(a/d)^3 + O((a/d)^6), d = h + a (to 1e-4 at
    d = 10 a, 0.5 % at d = 3a); (ii) at contact 1 + 3 (zeta(3) - 1) = 1.6062 (C_M = 0.8031;
    the terms tend to 1/n^3, to 1e-3 at h/a = 1e-6, where the correction is O(alpha^2));
    (iii) its slope matches central differences to 1e-6."""
    for d, tolerance in ((10.0, 1e-4), (3.0, 5e-3)):
        assert wall_added_mass(d - 1)[0] == pytest.approx(1 + 3 / 8 / d**3, rel=tolerance)
    assert wall_added_mass(1e-6)[0] == pytest.approx(1 + 3 * (ZETA3 - 1), rel=1e-3)
    for gap in (1e-3, 0.05, 0.7, 4.0):
        step = 1e-5 * gap
        central = (wall_added_mass(gap + step)[0] - wall_added_mass(gap - step)[0]) / (2 * step)
        assert wall_added_mass(gap)[1] == pytest.approx(central, rel=1e-6)


def test_wall_added_mass_against_the_images_in_long_double():
    """The compiled sums (n alpha up to 15, the smallest first) against the images' terms
    (sinh alpha / sinh n alpha)^3 and their slope summed in long double to n alpha = 60, for
    h/a from 1e-7 (alpha at CONTACT_ALPHA) to 1e3: C_M within 2e-14, its slope within 1e-9
    (coth alpha - n coth n alpha cancels as alpha -> 0; 3.7e-10 at h/a = 5e-7)."""
    for gap in np.logspace(-7.0, 3.0, 31):
        alpha = max(np.arccosh(1 + np.longdouble(gap)), np.longdouble(CONTACT_ALPHA))
        n = np.arange(2, int(60 / alpha) + 2, dtype=np.longdouble)
        ratio = np.sinh(alpha) / np.sinh(n * alpha)
        rate = (1 / np.tanh(alpha) - n / np.tanh(n * alpha)) / np.sinh(alpha)
        factor, slope = wall_added_mass(gap)
        assert factor == pytest.approx(float(1 + 3 * np.sum(ratio**3)), rel=2e-14)
        assert slope == pytest.approx(float(9 * np.sum(ratio**3 * rate)), rel=1e-9)
