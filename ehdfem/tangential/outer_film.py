"""What an immersed collision's tangential integrals leave out beyond the sphere's radius, and
its first-order effect on e_t and the spin change (scales of :mod:`ehdfem.tangential.motion`).

The tangential models integrate the film's shear and mode-1 pressure out to r = a
(R = 1/sqrt(delta)), where the lubrication approximation stops holding (the gap there is of
order a). The rest of the flow adds to a rigid sphere's resistance a constant matrix dR (by
6 pi mu a U, torque over a), the difference between Goldman, Cox & Brenner's (1967) exact
two-term resistances and the model's own at small gaps
(:mod:`ehdfem.exact.sliding_sphere`):

- ``lubrication`` and ``couette``: the film cut at r = a,
  dR = [[1.655, 0.487], [0.487, 1.205]] (the Couette model also leaves out the film's mode-1
  pressure inside r = a, docs/tangential.md);
- ``gcb``: its logarithms are the exact ones, dR = C, Goldman, Cox & Brenner's constants;
- ``flat``: none (it has no shear outside the Hertz disk at all).

The far flow does not see the contact, so dR holds on deformed films whose contact is small
against a. With dR constant, the change it makes to (U, a Omega) at the end of the collision is,
to first order in delta dR T / St,

    d(U_end) = -(delta/St) int (dR (U, a Omega))_1 dT,
    d(a Omega_end) = -(delta/(k St)) int (dR (U, a Omega))_2 dT,

over the time the sliding is followed (first touch to exit or stop), on the model's own
(U, a Omega): the e_t and spin change the whole flow would give are e_t + d(U_end) and
spin_change + d(a Omega_end), up to terms of order (1 - e_t) and d(U_end) relative.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.integrate

from .. import checks
from ..exact.sliding_sphere import EXACT_CONSTANTS, left_out_by_cut
from ..motion.normal import NormalResult
from .result import TangentialResult, end_index

OUTER_FILM_LIMIT = 0.01  # flag a left-out change of 1 - e_t above this share of it
OUTER_FLOWS = ("none", "exact")  # the flow beyond the integrals: left out, or added


def check_outer_flow(outer_flow: str, model: str, layer: str, angle: float) -> str:
    """``outer_flow`` (OUTER_FLOWS) for the tangential ``model``, the ``layer`` and the impact
    ``angle`` [deg]: "exact" is refused, naming the option, where it cannot act (a thin layer's
    film ends at its wetted edge, a head-on impact has no tangential motion, the flat model no
    film outside the Hertz disk)."""
    checks.choice("outer_flow", outer_flow, OUTER_FLOWS)
    if outer_flow == "exact" and (layer != "immersed" or angle == 0.0 or model == "flat"):
        raise checks.InputError(
            "outer_flow = 'exact' acts only on an oblique impact (angle > 0) through an "
            f"immersed layer with tangential couette, lubrication or gcb, not layer = {layer!r} "
            f"at angle {angle!r} with {model!r} (a thin layer's film ends at its wetted edge, "
            "inside the sphere's radius; the flat model has no film outside the Hertz disk)",
            "outer_flow",
        )
    return outer_flow


def left_out_resistance(model: str) -> np.ndarray | None:
    """dR, what the tangential ``model`` leaves out of a rigid sphere's resistance near a wall
    (by 6 pi mu a U, torque over a; module docstring); None for "flat", which has no far film."""
    if model == "flat":
        return None
    return EXACT_CONSTANTS.copy() if model == "gcb" else left_out_by_cut()


@dataclass(frozen=True)
class OuterFilm:
    """The first-order effect of the flow beyond the tangential integrals (module docstring):
    ``e_t_change`` d(U_end)/U0 and ``spin_change_change`` d(a Omega_end)/U0 (both by U0, for
    the tangential ``model``), ``share`` |e_t_change| / (1 - e_t); ``flagged`` above
    OUTER_FILM_LIMIT."""

    model: str
    e_t_change: float
    spin_change_change: float
    share: float

    @property
    def flagged(self) -> bool:
        """The left-out change of 1 - e_t exceeds OUTER_FILM_LIMIT of it."""
        return self.share > OUTER_FILM_LIMIT

    def note(self) -> str:
        """The plausibility note (and warning) of a flagged estimate."""
        text = (
            f"the tangential film is integrated to the sphere's radius r = a only; the flow "
            f"beyond it (from Goldman, Cox & Brenner 1967's exact resistances of a rigid sphere)"
            f" would change e_t by about {self.e_t_change:+.3g} ({100 * self.share:.0f} % of "
            f"1 - e_t) and the spin change by {self.spin_change_change:+.3g} (outputs "
            "outer_film_e_t_change, outer_film_spin_change): --outer-flow exact (outer_flow = "
            "'exact') adds it to the tangential motion (docs/tangential.md)"
        )
        if self.model == "couette":
            text += "; --tangential lubrication also adds the film's mode-1 pressure"
        return text


def unestimated_for_pair(normal: NormalResult, tangential: TangentialResult | None) -> str | None:
    """The note on an immersed oblique collision of two spheres (``tangential`` not None): the
    flow beyond its film's integrals is that of two spheres, whose O(1) resistances this module
    does not have (dR is a sphere's near a wall), so it is neither estimated nor added; None for
    a thin layer or a head-on impact."""
    if normal.params.layer != "immersed" or tangential is None or tangential.e_t is None:
        return None
    return (
        "the tangential film of the two spheres is integrated to r = a only, and the flow "
        "beyond it (the two spheres' O(1) resistances) is neither estimated nor added: for a "
        "sphere near a wall it changes 1 - e_t by 30-160 % in immersed runs "
        "(docs/tangential.md, 'The flow beyond r = a'); e_t and the spin changes leave it out"
    )


def outer_film(normal: NormalResult, tangential: TangentialResult | None) -> OuterFilm | None:
    """The :class:`OuterFilm` estimate of an immersed oblique collision (its normal and
    tangential results); None for a thin layer (its film ends at the wetted edge, inside r = a),
    a head-on impact and the flat model."""
    params = normal.params
    if params.layer != "immersed" or tangential is None or tangential.e_t is None:
        return None
    resistance = left_out_resistance(tangential.model)
    if resistance is None:
        return None
    end = end_index(normal)
    last = int(np.floor(end))
    steps = np.arange(len(tangential.time))
    states = np.column_stack([tangential.velocity, tangential.spin])
    at_end = [np.interp(end, steps, values) for values in (tangential.time, *states.T)]
    time = np.append(tangential.time[: last + 1], at_end[0])
    states = np.vstack([states[: last + 1], at_end[1:]])
    integral = scipy.integrate.trapezoid(states, time, axis=0)  # int (U, a Omega) dT
    scale = params.delta / params.St
    change = -scale * (resistance @ integral)
    loss = 1.0 - tangential.e_t
    return OuterFilm(
        model=tangential.model,
        e_t_change=float(change[0]),
        spin_change_change=float(change[1] / params.inertia_factor),
        share=abs(float(change[0])) / max(abs(loss), np.finfo(float).tiny),
    )
