"""The BDF formulas and the dense output of the time stepper (exact on polynomials)."""

import numpy as np
import pytest

from ehdfem.motion.timestepping import (
    crossing,
    derivative_weights,
    extrapolate,
    peak,
    step_integral,
)

pytestmark = pytest.mark.serial


def test_bdf_weights_differentiate_polynomials_of_their_order_exactly():
    """Variable-step BDF-q is exact for polynomials of degree q (to rounding)."""
    nodes = [1.0, 0.9, 0.75, 0.7]
    for q in (1, 2, 3):
        weights = derivative_weights(nodes[: q + 1])
        values = [t**q for t in nodes[: q + 1]]
        assert weights @ values == pytest.approx(q * nodes[0] ** (q - 1), rel=1e-12)


def test_peak_is_the_vertex_of_a_sampled_parabola():
    """On unequal steps the refined peak of y = 2 - 3 (t - 0.537)^2 is the vertex (1e-14);
    the largest sample alone misses it by O(step^2)."""
    times = np.array([0.0, 0.2, 0.45, 0.6, 0.9, 1.0])
    values = 2 - 3 * (times - 0.537) ** 2
    time, value = peak(times, values)
    assert time == pytest.approx(0.537, abs=1e-14) and value == pytest.approx(2.0, abs=1e-14)
    assert values.max() < 2.0 - 1e-3


def test_peak_keeps_a_sample_at_the_end_or_a_kink():
    """At the first or last sample, or where the neighbours do not bracket a maximum, the
    largest sample is the peak."""
    times = np.array([0.0, 1.0, 2.0, 3.0])
    assert peak(times, np.array([0.0, 1.0, 2.0, 3.0])) == (3.0, 3.0)
    assert peak(times, np.array([0.0, 1.0, 1.0, 0.0]))[1] >= 1.0


def test_peak_up_to_an_end_inside_the_last_step_reads_the_dense_output_there():
    """A history still growing at the collision's end (y = 1 + t - t^2/4 on t < 2, the end at
    0.93, inside the last step 0.8 -> 1.1): its largest value up to the end is y(0.93) on the
    quadratic dense output (exact, 1e-14), not the last sample past the end; an end at or
    after the last sample changes nothing."""
    times = np.array([0.0, 0.3, 0.55, 0.8, 1.1])
    values = 1 + times - times**2 / 4
    time, value = peak(times, values, end=0.93)
    assert time == 0.93 and value == pytest.approx(1 + 0.93 - 0.93**2 / 4, abs=1e-14)
    assert value < values[-1] - 0.08
    assert peak(times, values, end=1.1) == peak(times, values) == (1.1, values[-1])


def test_crossing_is_the_root_of_the_interpolating_polynomial():
    """X(t) = 1 + (t - 0.73)(t + 0.2) crosses 1 at t = 0.73 between the two newest samples of
    three; the dense output finds it to rounding and reads V there from its own polynomial."""
    nodes = [0.8, 0.7, 0.55]  # newest first
    gap = [1 + (t - 0.73) * (t + 0.2) for t in nodes]
    time = crossing(nodes, gap, 1.0)
    assert time == pytest.approx(0.73, abs=1e-14)
    velocity = [2 * t - 0.53 for t in nodes]
    assert extrapolate(nodes, velocity, time) == pytest.approx(2 * 0.73 - 0.53, abs=1e-14)


def test_step_integral_is_exact_on_the_interpolating_quadratic():
    """On unequal steps the integral over the latest step of r(t) = 3 t^2 - t + 2, sampled at
    three times, equals its antiderivative's difference (0.626) to rounding; from two samples
    it is the trapezoidal rule."""
    nodes = [0.9, 0.7, 0.25]  # newest first
    rates = [3 * t**2 - t + 2 for t in nodes]
    exact = (0.9**3 - 0.9**2 / 2 + 2 * 0.9) - (0.7**3 - 0.7**2 / 2 + 2 * 0.7)
    assert step_integral(nodes, rates) == pytest.approx(exact, rel=1e-14)
    assert step_integral(nodes[:2], rates[:2]) == pytest.approx(0.1 * (rates[0] + rates[1]))
