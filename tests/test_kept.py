"""ehdfem.kept: results kept for the latest inputs, keyed by an array's bits."""

import numpy as np

from ehdfem.kept import Kept


def test_a_kept_result_is_returned_for_the_same_bits_and_key_only():
    """The same bits and key (a copy of the array too) return the kept result without
    computing; another value, another key or a value beyond the kept ones compute again."""
    calls = []

    def compute(value):
        calls.append(value)
        return value * 2.0

    kept = Kept(2)
    a, b, c = np.array([1.0, 2.0]), np.array([1.0, 3.0]), np.array([0.0, 3.0])
    first = kept.get(lambda: compute(a), a, "x")
    assert kept.get(lambda: compute(a), a.copy(), "x") is first
    assert len(calls) == 1
    kept.get(lambda: compute(a), a, "y")  # another key
    kept.get(lambda: compute(b), b, "x")  # a second value pushes (a, "y") along, drops (a, "x")
    assert len(calls) == 3
    kept.get(lambda: compute(a), a, "y")
    assert len(calls) == 3
    kept.get(lambda: compute(a), a, "x")
    assert len(calls) == 4
    kept.get(lambda: compute(c), c[::-1].copy()[::-1], "x")  # a strided view: its values' bits
    kept.get(lambda: compute(c), c, "x")
    assert len(calls) == 5
    kept.clear()
    kept.get(lambda: compute(c), c, "x")
    assert len(calls) == 6


def test_negative_zero_is_another_input():
    """Bits, not values: -0.0 is kept apart from 0.0 (a recomputation, never a wrong hit)."""
    kept = Kept()
    assert kept.get(lambda: "plus", np.array([0.0])) == "plus"
    assert kept.get(lambda: "minus", np.array([-0.0])) == "minus"
