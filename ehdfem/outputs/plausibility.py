"""Plausibility notes: results and inputs a user should look at twice, each a sentence. The
collision warns of each (:class:`ResultRangeWarning`) and keeps them all in its result and its
JSON (``notes``), so that a result read later still says what was questionable about it.

- e_n above 1: pure EHD cannot gain energy, so it is a discretisation error (the energy error
  says how large);
- for physical inputs, a smooth collision's thinnest film below :data:`SMOOTHEST_SURFACE` [m]
  (real surfaces are rougher: their asperities would touch first) and a liquid viscosity
  outside :data:`NEWTONIAN_VISCOSITY` [Pa s];
- for rough surfaces with the impact model, an impact through solids that already hold more
  than :data:`LOADED_IMPACT` of the impact energy (every other touch the asperity obstacle
  carries, :mod:`ehdfem.film.asperity_obstacle`);
- for an immersed oblique impact, the flow beyond the tangential integrals (which end at the
  sphere's radius) when left out and estimated to change 1 - e_t by more than
  :data:`ehdfem.tangential.outer_film.OUTER_FILM_LIMIT` of it;
- a stuck sphere whose motion died out without a finite end (:func:`unresolved_stop`), and a
  weak rebound whose e_n the step control holds to less than 1 % of itself
  (:func:`weak_rebound`): both move with rtol by more than the defaults' stated accuracy, and
  are warned of as :class:`TimeResolutionWarning`.
"""

from __future__ import annotations

import numpy as np

from ..tangential.outer_film import unestimated_for_pair

SMOOTHEST_SURFACE = 1e-8  # m: a thinnest film below it is thinner than real surfaces are rough
NEWTONIAN_VISCOSITY = (1e-4, 1e3)  # Pa s: the liquids that are Newtonian at room temperature
LOADED_IMPACT = 0.1  # stored elastic energy over the impact energy above which an impact is
# not through unloaded solids, as the impact model assumes
RESOLVED_SPEED = 100.0  # times rtol: a speed (by V0) the step control resolves
UNRESOLVED_STOP = 0.01  # share of a stuck sphere's contact time in an unresolved decay, noted
# e_n's time error at rtol 2e-4 (by V0), the largest of 31 rebounds of the DEM table with e_n
# below 0.4 against rtol 2e-6 (3.9e-4 at rtol 2e-5: it scales about as sqrt(rtol))
REBOUND_TIME_ERROR = 1.2e-3
WEAK_REBOUND = 0.01  # the relative time error of e_n above which a rebound is noted


class ResultRangeWarning(UserWarning):
    """A result or input a user should look at twice: e_n above 1 (the discretisation's energy
    error), a thinnest film thinner than any real surface is smooth, a viscosity outside the
    Newtonian liquids, an impact of the asperities through loaded solids (which the impact
    model does not hold for), an immersed tangential motion that leaves out a large flow beyond
    the sphere's radius, and the results of :class:`TimeResolutionWarning`."""


class TimeResolutionWarning(ResultRangeWarning):
    """A result that moves with rtol by more than the defaults' stated accuracy: a stuck
    sphere's stop the step control does not resolve, a weak rebound's e_n. The critical-Stokes
    search, which reports neither a contact time nor e_n, does not show it."""


class Note(str):
    """A note's sentence, with the warning ``category`` the collision warns of it under."""

    category: type[Warning]

    def __new__(cls, text: str, category: type[Warning] = ResultRangeWarning):
        note = super().__new__(cls, text)
        note.category = category
        return note


def liquid_note(physical) -> str | None:
    """The note on a physical collision's liquid viscosity [Pa s] outside
    :data:`NEWTONIAN_VISCOSITY`; None inside it."""
    low, high = NEWTONIAN_VISCOSITY
    mu = physical.liquid.viscosity
    if low <= mu <= high:
        return None
    return (
        f"the liquid viscosity {mu:.3g} Pa s is outside the Newtonian liquids "
        f"({low:g}-{high:g} Pa s): "
        + ("below any liquid at room temperature" if mu < low else "such liquids shear-thin")
    )


def unresolved_stop(normal) -> float | None:
    """The share of a stuck sphere's contact time that its motion spent decaying below the
    speeds the step control resolves (RESOLVED_SPEED rtol, by V0), when that decay is
    asymptotic and the share is above UNRESOLVED_STOP; None otherwise. The film's damping
    takes up the last motion of a sphere it stops as V ~ exp(-T/tau), without a finite end, so
    the stop (V back to 0, or |V| below 1e-10) comes where V reaches the integration's noise,
    and the contact time grows by about 2 tau for each tenfold smaller rtol (thin, St 2,
    eps 1e-12: 2.57 at rtol 2e-4, 4.62 at 2e-6). A decay counts as asymptotic when the time
    from the last resolved speed V_j to the stop is over 3 tau, tau = |V_j / (dV/dT)|; a
    sphere turned back by the film reaches V = 0 in about tau."""
    if normal.status != "stick":
        return None
    times, velocity = normal.history.time, normal.history.velocity
    resolved = np.flatnonzero(np.abs(velocity) > RESOLVED_SPEED * normal.rtol)
    if len(resolved) == 0 or not 0 < resolved[-1] < len(times) - 1:
        return None
    j = resolved[-1]
    slope = (velocity[j + 1] - velocity[j - 1]) / (times[j + 1] - times[j - 1])
    decay = normal.contact_time - times[j]
    share = decay / normal.contact_time
    asymptotic = decay * abs(slope) > 3.0 * abs(velocity[j])
    return float(share) if asymptotic and share > UNRESOLVED_STOP else None


def weak_rebound(normal) -> float | None:
    """A rebound's estimated relative time error in e_n, REBOUND_TIME_ERROR sqrt(rtol / 2e-4)
    / V_exit (V_exit the exit velocity by V0, of which e_n is e_dry times or, after a solid
    impact, all), when above WEAK_REBOUND; None otherwise. Near the critical Stokes number the
    sphere leaves slowly after a long contact, and the exit velocity's absolute time error (up
    to 1.2e-3 at the default rtol, whatever its size) becomes large beside it: thin, St 21.5,
    eps 1e-10, no cavitation limit: e_n 0.01033 at rtol 2e-4, 0.01118 at 2e-5, 0.01134 at
    2e-6."""
    if normal.status != "rebound" or normal.exit_velocity <= 0.0:
        return None
    error = REBOUND_TIME_ERROR * np.sqrt(normal.rtol / 2e-4) / normal.exit_velocity
    return float(error) if error > WEAK_REBOUND else None


def result_notes(params, physical, normal) -> list[Note]:
    """The notes (:class:`Note`) on a normal motion ``normal``
    (:class:`ehdfem.motion.normal.NormalResult`) of ``params`` (dimensionless), with the
    physical inputs ``physical`` (SI) or None: e_n above 1, an impact of the asperities
    through loaded solids, a stuck sphere's unresolved stop (:func:`unresolved_stop`), a weak
    rebound (:func:`weak_rebound`), a smooth physical film thinner than
    :data:`SMOOTHEST_SURFACE` (polished glass and steel have rms roughnesses of 1-100 nm)."""
    notes = []
    if normal.e_n > 1.0:
        notes.append(
            Note(
                f"e_n = {normal.e_n:.6g} is above 1: the collision gained energy, a "
                f"discretisation error (energy error {normal.energy_error:.2g}); refine --nodes "
                "or --rtol"
            )
        )
    impact = normal.solid_impact
    if impact is not None and impact.stored_share > LOADED_IMPACT:
        notes.append(
            Note(
                f"the asperities' impact came through loaded solids: they held "
                f"{100 * impact.stored_share:.0f} % of the impact energy, where the impact model "
                "assumes them unloaded (its e_dry acts on the sphere's velocity alone)"
            )
        )
    decay = unresolved_stop(normal)
    if decay is not None:
        text = (
            "the sphere sticks and its motion died out without a finite end: the last "
            f"{100 * decay:.0f} % of the contact time ({normal.contact_time:.4g} x0/V0) is a "
            "decay below the speeds the step control resolves, so the contact time, and e_t "
            'and the spin change taken at the stop, depend on rtol (docs/performance.md, "The '
            "stuck sphere's stop\")"
        )
        notes.append(Note(text, TimeResolutionWarning))
    error = weak_rebound(normal)
    if error is not None:
        text = (
            f"e_n = {normal.e_n:.4g} is a weak rebound (near the critical Stokes number): its "
            f"time error at rtol {normal.rtol:.2g}, about {100 * error:.2g} % of it, is more than "
            "the 1 % the defaults hold e_n to elsewhere; it falls about threefold for each tenfold "
            'smaller rtol (--rtol; docs/performance.md, "Weak rebounds")'
        )
        notes.append(Note(text, TimeResolutionWarning))
    if physical is not None and params.roughness == 0.0:
        thinnest = normal.min_film_thickness * physical.layer_thickness
        if thinnest < SMOOTHEST_SURFACE:
            notes.append(
                Note(
                    f"the thinnest film is {thinnest * 1e9:.3g} nm, below the roughness of any "
                    "real surface (1-100 nm rms): the asperities would touch first (--roughness)"
                )
            )
    return notes


def notes(result) -> list[str]:
    """Every note on a collision's result (:class:`ehdfem.collision.CollisionResult`): its
    liquid's, its normal motion's (:func:`result_notes`), then its left-out outer flow's
    (:class:`ehdfem.tangential.outer_film.OuterFilm`), or for two spheres that it is left out
    unestimated (:func:`ehdfem.tangential.outer_film.unestimated_for_pair`)."""
    liquid = None if result.physical is None else liquid_note(result.physical)
    outer = result.outer_film
    flagged = [outer.note()] if outer is not None and outer.flagged else []
    if result.config is not None and result.config.lower.kind == "sphere":
        flagged += filter(None, [unestimated_for_pair(result.normal, result.tangential)])
    return (
        [liquid] * (liquid is not None)
        + result_notes(result.params, result.physical, result.normal)
        + flagged
    )
