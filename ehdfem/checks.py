"""Input validation shared by every entry point (Python API, CLI, study files).

Every public function that takes physical or dimensionless inputs checks them here
before any work starts, so a bad value gives one clear message naming the parameter
and the allowed range instead of a traceback or a silent NaN.
"""

from __future__ import annotations

import math
from numbers import Real


class InputError(ValueError):
    """A parameter is missing, of the wrong type, not finite or out of its range."""


def number(name: str, value, *, lower=None, upper=None, lower_open=False, upper_open=False):
    """Return ``value`` as a float after checking it is a finite real in the given range.

    ``lower``/``upper`` are inclusive unless ``lower_open``/``upper_open`` is set. The
    error message names ``name`` and states the allowed range.
    """
    if isinstance(value, bool) or not isinstance(value, Real):
        raise InputError(f"{name} must be a real number, got {value!r}")
    value = float(value)
    if not math.isfinite(value):
        raise InputError(f"{name} must be finite, got {value!r}")
    low_ok = lower is None or (value > lower if lower_open else value >= lower)
    up_ok = upper is None or (value < upper if upper_open else value <= upper)
    if not (low_ok and up_ok):
        allowed = _range(lower, upper, lower_open, upper_open)
        raise InputError(f"{name} = {value!r} is outside the allowed range {allowed}")
    return value


def positive(name: str, value) -> float:
    """A finite real number > 0."""
    return number(name, value, lower=0.0, lower_open=True)


def integer(name: str, value, *, lower=None, upper=None) -> int:
    """An integer in [lower, upper]."""
    if isinstance(value, bool) or not isinstance(value, int):
        raise InputError(f"{name} must be an integer, got {value!r}")
    if (lower is not None and value < lower) or (upper is not None and value > upper):
        raise InputError(
            f"{name} = {value!r} is outside the allowed range {_range(lower, upper, False, False)}"
        )
    return value


def choice(name: str, value, allowed):
    """One of the strings in ``allowed``."""
    if value not in allowed:
        raise InputError(f"{name} = {value!r} is not one of {', '.join(map(repr, allowed))}")
    return value


def range_text(lower=None, upper=None, lower_open=False, upper_open=False) -> str:
    """The range of :func:`number`'s keyword arguments as text, e.g. "(0, 2e+12]"."""
    return _range(lower, upper, lower_open, upper_open)


def _range(lower, upper, lower_open, upper_open) -> str:
    left = "(" if lower_open or lower is None else "["
    right = ")" if upper_open or upper is None else "]"
    lo = "-inf" if lower is None else f"{lower:g}"
    up = "inf" if upper is None else f"{upper:g}"
    return f"{left}{lo}, {up}{right}"
