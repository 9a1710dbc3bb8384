"""The sliding film's mode-1 superposition against the 2-D disk film, and its indicators.

Collisions: thin layer, delta = 0.01, 30 degrees, the sliding film with the mode-1 gap, 120 film
nodes. Runs on 2 ranks too (the disk film is distributed, the collision is the same on each).
"""

import re
import warnings

import numpy as np
import pytest
from mpi4py import MPI
from scipy.integrate import quad

from ehdfem.checks import InputError
from ehdfem.collision import collide
from ehdfem.config import Numerics, RunConfig
from ehdfem.inputs.scales import CollisionParameters
from ehdfem.motion.timestepping import IntegratorOptions
from ehdfem.tangential.superposition import (
    TILT_LIMIT,
    SuperpositionWarning,
    check_superposition,
    ring_cut,
)


def sliding_collision(eps, St, p_cav, options=None, **extra):
    params = CollisionParameters.from_settings(
        St=St, eps=eps, delta=0.01, layer="thin", p_cav=p_cav, angle=30.0, **extra
    )
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", SuperpositionWarning)
        return collide(
            params,
            RunConfig(
                tangential="lubrication",
                numerics=Numerics(nodes=160, integrator=options or IntegratorOptions()),
            ),
        )


def report(text):
    if MPI.COMM_WORLD.rank == 0:
        print(text)


@pytest.mark.parametrize("offset, amplitude", [(0.0, 1.0), (-0.3, 1.0), (-0.99, 1.0), (-2, 1)])
def test_ring_cut_is_the_azimuthal_mean_of_the_cut_pressure(offset, amplitude):
    """(1/2pi) int max(0, c - a cos phi) dphi in closed form against adaptive quadrature
    (split at the kinks), to 1e-12."""
    kink = np.arccos(np.clip(offset / amplitude, -1, 1))
    integrand = lambda phi: max(0.0, offset - amplitude * np.cos(phi))  # noqa: E731
    exact = quad(integrand, 0, 2 * np.pi, points=[kink, 2 * np.pi - kink], epsabs=1e-14)[0]
    assert ring_cut(offset, amplitude) == pytest.approx(exact / (2 * np.pi), abs=1e-12)


@pytest.mark.slow
def test_two_dimensional_film_is_the_superposition_without_suction():
    """eps = 1e-3, St = 20, no cavitation limit (small eps St): at the instants of the largest
    normal and tangential force the 2-D film's mode-1 moment int P X dA and slope force int P
    dSigma0/dX dA agree with the superposition's within 1 % (measured 0.03-0.7 % at centre
    element size 0.005, on a base film of 160 nodes), its mesh change is below 3 % (measured 1.7
    % at most), the lift the sliding adds is below 1e-2 of the normal force (second order;
    measured 1.4e-3), and the collision is not flagged."""
    result = sliding_collision(1e-3, 20.0, -np.inf)
    assert not result.superposition.flagged
    assert result.superposition.sensitivity == 0.0
    checks = check_superposition(result, element_size=0.005)
    for check in checks:
        report(
            f"step {check.step}: moment {check.moment}, errors {check.moment_error:.2e}"
            f" {check.slope_error:.2e}, mesh change {check.mesh_change:.2e}, lift {check.lift:.1e}"
        )
        assert check.moment_error < 1e-2
        assert check.slope_error < 1e-2
        assert check.mesh_change < 3e-2
        assert abs(check.lift) < 1e-2
        assert check.cavitated_vertices == 0


@pytest.mark.slow
def test_superposition_fails_under_suction_and_returns_as_the_sliding_vanishes():
    """eps = 1e-3, St = 20, P_cav = -1: at the step of the largest suction overlap the
    superposed pressure crosses the limit and the 2-D film's moment differs by more than 5 % and
    by five times its difference at a ten times smaller sliding amplitude, which is within 4 %
    (measured 9.1 % and 1.5 % on a base film of 160 nodes, the mesh changing the moment by 3.1
    %; 1.5 % is the discretisation at centre element size 0.007): the difference is the
    superposition's, not the mesh's. The overlap peaks sharply in time (T = 1.95), so the
    collision is stepped with BDF of order 3, whose steps come near the peak (overlap 0.012 at T
    = 1.943; 0.042 and a moment error of 23 % on the peak, where the steps landed before the
    velocity's error was weighted by the gap error it causes); the default order-4 steps step
    over it (their largest overlap, 0.0046, was at T = 1.99, where the 120-node base film's own
    cavitation edge differs from the 2-D one by 9 %, 1.4 % on 240 nodes). The cavitation-rule
    sensitivity of e_t is computed (measured 5e-3) and the collision not flagged."""
    result = sliding_collision(1e-3, 20.0, -1.0, options=IntegratorOptions(order=3))
    validity = result.superposition
    step = int(np.argmax(validity.overlap))
    assert validity.suction_overlap > 0 and validity.overlapping.any()
    assert 0 < validity.sensitivity < 0.02 and not validity.flagged
    full, small = (
        check_superposition(result, [step], amplitude=factor * validity.sliding_amplitude)[0]
        for factor in (1.0, 0.1)
    )
    report(f"suction: error {full.moment_error:.2e} at s, {small.moment_error:.2e} at s/10")
    assert full.moment_error > 0.05
    assert full.moment_error > 5 * small.moment_error
    assert full.cavitated_vertices > 0
    assert small.moment_error < 4e-2


@pytest.mark.slow
def test_two_dimensional_film_with_a_piezoviscous_liquid():
    """Barus, scaled alpha = 5e-3 (mu/mu0 up to 27, viscosity tilt 0.04), eps = 1e-3, St = 20,
    no cavitation limit, at the instant of the largest normal force: the disk film with the
    viscosity mu0 exp(alpha max(P, 0)) reproduces P0 within 1.5 % (measured 1.04 %, 0.51 % on
    elements of 0.0035: the disk's own discretisation error, second order; 70 % with the
    viscosity left constant) and the superposition's moment and slope force within 1.5 %
    (measured 0.92 % and 0.96 %; 0.45 % and 0.49 % on elements of 0.0035)."""
    result = sliding_collision(1e-3, 20.0, -np.inf, viscosity="barus", alpha=5e-3)
    assert 0.0 < result.superposition.largest_viscosity_tilt < 0.3
    step = int(np.argmax(result.normal.history.force))
    check = check_superposition(result, [step], element_size=0.005)[0]
    report(f"Barus: base {check.base_error:.2e}, moment {check.moment_error:.2e}")
    assert check.base_error < 1.5e-2
    assert check.moment_error < 1.5e-2
    assert check.slope_error < 1.5e-2


def test_large_tilt_is_flagged_with_a_warning_and_in_the_summary():
    """eps = 0.1, St = 1000, P_cav = -10: the mode-1 gap reaches more than TILT_LIMIT of the
    film thickness (measured 0.36): a SuperpositionWarning, and the summary says so."""
    params = CollisionParameters.from_settings(
        St=1000.0, eps=0.1, delta=0.01, layer="thin", p_cav=-10.0, angle=30.0
    )
    with pytest.warns(SuperpositionWarning, match="tilt"):
        result = collide(params, RunConfig.from_settings(nodes=80, tangential="lubrication"))
    summary = result.summary()
    assert summary["superposition_flag"] is True
    assert summary["superposition_tilt"] == result.superposition.largest_tilt > TILT_LIMIT


@pytest.mark.parametrize(
    "extra, message",
    [
        ({"layer": "immersed"}, "needs layer = 'thin'"),
        ({"cavitation": "mass-conserving", "p_cav": -1.0}, "does not track the liquid"),
    ],
)
def test_check_refuses_what_the_disk_film_cannot_represent(extra, message):
    """Immersed films and mass-conserving cavities are refused before any disk is meshed."""
    values = {"St": 20.0, "eps": 1e-3, "delta": 0.01, "p_cav": -np.inf, "angle": 30.0}
    values.update(extra)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", SuperpositionWarning)
        result = collide(
            CollisionParameters.from_settings(**values),
            RunConfig.from_settings(nodes=40, tangential="lubrication"),
        )
    with pytest.raises(InputError, match=re.escape(message)):
        check_superposition(result)


def test_check_needs_the_sliding_film_and_steps_in_range():
    params = CollisionParameters.from_settings(St=20.0, eps=1e-3, delta=0.01, angle=30.0)
    couette = collide(params, RunConfig.from_settings(nodes=40))
    assert couette.superposition is None
    with pytest.raises(InputError, match="needs an oblique tangential='lubrication'"):
        check_superposition(couette)
    result = collide(params, RunConfig.from_settings(nodes=40, tangential="lubrication"))
    with pytest.raises(InputError, match="step"):
        check_superposition(result, [0])
