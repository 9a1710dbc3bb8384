"""The bracket search for a threshold: the value where a collision's outcome turns from
sticking to rebounding (the critical Stokes number, the critical speed), to a relative width.
"""

from __future__ import annotations

import math
import warnings

from .. import checks
from ..console.progress import Counter
from ..outputs.plausibility import TimeResolutionWarning


def bisections(low: float, high: float, rtol: float) -> int:
    """How many halvings in log bring the bracket [low, high] to a relative width <= rtol."""
    ratio = math.log(high / low) / math.log1p(rtol)
    return max(0, math.ceil(math.log2(ratio))) if ratio > 1 else 0


def threshold(rebounds, low, high, rtol, name, limits, progress_label=None):
    """The bracket [low, high] (relative width <= rtol) of the value of ``name`` where the
    outcome ``rebounds(value)`` turns from False to True, after widening the starting bracket
    by factors of 4 within ``limits``. Returns (low, high, evaluations). The outcome is a bool,
    or the restitution e_n (0: it sticks), which guides the search: the two lowest rebounds
    fix e_n = 1 - (v_c/v)^m (the form of the closed forms, docs/studies.md), and its v_c,
    nudged by rtol/3 to the side it has not yet bracketed, is tried next (:func:`_guided`);
    where it falls outside the bracket, or the fit mispredicted two outcomes running, a
    bisection in log is. The ends of the final bracket are outcomes computed like every other,
    so the guide changes how fast the bracket closes, not what it holds: 7 collisions
    instead of 15 at thin eps 1e-3 (8-9 elsewhere). The starting bracket's ends are computed
    only if no trial inside replaced them (the high end is the costliest collision: at thin
    eps 1e-3, St = 1000 took a third of the search). ``progress_label``: label of a progress
    bar over the evaluations (terminal only), whose total is the bisection's count (an upper
    bound)."""
    evaluations = 0
    count = 2 + bisections(low, high, rtol)
    bar = Counter(count, progress_label, unit="collision") if progress_label else None
    rebound_at = {}  # value: e_n of the rebounds seen (with a restitution)

    def outcome(value, more):
        """The outcome at ``value``; ``more``: evaluations after this one besides the halvings
        of the current bracket (1 and 0 for the ends' checks, -1 for a halving itself)."""
        nonlocal evaluations
        with warnings.catch_warnings():  # the search reports no contact time and no e_n
            warnings.filterwarnings("ignore", category=TimeResolutionWarning)
            result = rebounds(value)
        evaluations += 1
        if bar is not None:
            bar.advance_to(evaluations, evaluations + more + bisections(low, high, rtol))
        if not isinstance(result, bool) and result > 0.0:
            rebound_at[value] = float(result)
        return bool(result > 0.0)

    # the ends are computed last, where no trial inside the bracket has replaced them: they
    # are the bracket's costliest or most remote collisions
    low_sticks = high_rebounds = False  # the ends' outcomes are known
    try:
        while True:
            missed = 0  # guided trials in a row whose outcome the fit did not predict
            while high / low - 1 > rtol:
                guide = _guided(rebound_at, low, high, rtol) if missed < 2 else None
                trial = math.sqrt(low * high) if guide is None else guide[0]
                rebound = outcome(trial, -1)
                if rebound:
                    high, high_rebounds = trial, True
                else:
                    low, low_sticks = trial, True
                if guide is not None:
                    missed = 0 if rebound == guide[1] else missed + 1
            if not low_sticks and outcome(low, 1):  # it rebounds at the low end: widen
                low, high, high_rebounds = low / 4, low, True
                if low < limits[0]:
                    raise checks.InputError(
                        f"the sphere rebounds even at {name} = {limits[0]:g}: no critical {name}"
                    )
                continue
            low_sticks = True
            if not high_rebounds and not outcome(high, 0):  # it sticks at the high end
                low, high, low_sticks = high, high * 4, True
                if high > limits[1]:
                    raise checks.InputError(f"the sphere sticks up to {name} = {limits[1]:g}")
                continue
            break
    finally:
        if bar is not None:
            bar.close()
    return low, high, evaluations


def _guided(rebound_at: dict, low: float, high: float, rtol: float) -> tuple | None:
    """(the next value to try, whether it should rebound) from the two lowest rebounds
    (v1, e1), (v2, e2) of ``rebound_at``: e = 1 - (v_c/v)^m through both gives
    m = ln((1 - e1)/(1 - e2)) / ln(v2/v1) and v_c = v1 (1 - e1)^(1/m); the trial is just
    above v_c, v_c (1 + rtol/3), while the bracket's upper end is far from it, and just below,
    v_c / (1 + rtol/3), once that end is within rtol of it (both sides then close the
    bracket). None where the fit fails (m <= 0) or the trial is not inside (low, high)."""
    if len(rebound_at) < 2:
        return None
    (v1, e1), (v2, e2) = sorted(rebound_at.items())[:2]
    if not (e1 < 1.0 and e2 < 1.0):
        return None
    m = math.log((1.0 - e1) / (1.0 - e2)) / math.log(v2 / v1)
    if not m > 0.0:
        return None
    critical = v1 * (1.0 - e1) ** (1.0 / m)
    nudge = 1.0 + rtol / 3.0
    below = high <= critical * (1.0 + rtol)
    trial = critical / nudge if below else critical * nudge
    return (trial, not below) if low < trial < high else None
