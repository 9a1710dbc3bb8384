"""Every output of a collision, once: its name, meaning, scale, SI unit and how to compute it.

The summary of a collision (:meth:`ehdfem.collision.CollisionResult.summary`), the rows of a
study (:mod:`ehdfem.study.sweep`), the contacts of a bounce (:mod:`ehdfem.bounce.contact`)
and the command line's result table all read :data:`OUTPUTS`: a new output is one
:class:`Output` entry here (docs/outputs.md lists them).

Values are scaled (Davis, Serayssol & Hinch 1986): gap and film thickness by x0, time by
x0/V0, normal velocity by V0, force by 6 pi mu V0 a^2 / x0; the tangential velocity by U0 and
the spin by U0/a. For physical inputs an output with an SI key also has its SI value, the scaled
value times its factor (:attr:`Output.si_factor`, from the inputs' :class:`Scales
<ehdfem.inputs.scales.Scales>`, or U0 for the tangential outputs).

An output is None where the collision has none (e_t of a head-on impact; the sliding film's
diagnostics, which the summary then leaves out) or where it does not apply
(:attr:`Output.applies`: the energy balance with a cavitation limit), the reason then under
the summary's "not_applicable".
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Protocol

import numpy as np
import scipy.integrate

from ..film import cavitation

if TYPE_CHECKING:
    from ..inputs.scales import PhysicalCollision


class Collision(Protocol):
    """What an output reads of a collision (:class:`ehdfem.collision.CollisionResult`, which
    builds on this module): its scaled inputs, its physical inputs (None for a scaled run) and
    its normal and tangential results."""

    params: Any
    physical: Any
    normal: Any
    tangential: Any


@dataclass(frozen=True)
class Output:
    """One output of a collision.

    ``name``: its key in the summary and in a study row; ``meaning``: one line; ``scale``: what
    the value is scaled by ("-": a pure number, a count, a flag or a word); ``unit``: the SI
    unit of the quantity (None for a pure number); ``compute(result)``: the scaled value from
    a :class:`ehdfem.collision.CollisionResult` (None where the collision has none);
    ``si_key`` and ``si_factor(physical)``: the key of the SI value and the SI unit of its scale
    from the :class:`ehdfem.inputs.scales.PhysicalCollision` (None: no SI value reported);
    ``applies(result)``: False where the value means nothing (then None, with ``reason``);
    ``optional``: the summary leaves the key out where the value is None.
    """

    name: str
    meaning: str
    scale: str
    unit: str | None
    compute: Callable[[Collision], Any]
    si_key: str | None = None
    si_factor: Callable[[PhysicalCollision], float] | None = None
    applies: Callable[[Collision], bool] | None = None
    reason: str = ""
    optional: bool = False

    def __post_init__(self):
        if not (self.name and self.meaning and self.scale):
            raise ValueError(f"output {self.name!r} needs a name, a meaning and a scale")
        if (self.si_key is None) != (self.si_factor is None):
            raise ValueError(f"output {self.name!r}: si_key and si_factor go together")
        if self.si_key is not None and self.unit is None:
            raise ValueError(f"output {self.name!r}: an SI value needs a unit")
        if (self.applies is None) != (not self.reason):
            raise ValueError(f"output {self.name!r}: applies and reason go together")

    def value(self, result: Collision):
        """The scaled value, None where it does not apply."""
        if self.applies is not None and not self.applies(result):
            return None
        return self.compute(result)


def _without_suction_limit(result: Collision) -> bool:
    """No cavitation limit: the model without one, or P_cav = -inf."""
    p = result.params
    return p.p_cav == cavitation.NO_LIMIT


def _tangential(name):
    """The TangentialResult's attribute ``name`` (None for a head-on impact)."""
    return lambda r: None if r.tangential is None else getattr(r.tangential, name)


def _tangential_energy(read):
    """``read(energy)`` of the sliding film's energy balance (None without one)."""
    return lambda r: (
        None if r.tangential is None or r.tangential.energy is None else read(r.tangential.energy)
    )


def _superposition(name):
    """The SuperpositionValidity's attribute ``name`` (None for the Couette film)."""
    return lambda r: None if r.superposition is None else getattr(r.superposition, name)


def _oblique(read):
    """``read(result, tan(angle))`` for an oblique impact (None for a head-on one, where the
    tangential motion is not solved)."""
    return lambda r: None if r.tangential is None else read(r, r.params.tangential_speed)


def _rebound_angle(r, tangent) -> float:
    """The rebound angle from the wall normal [deg]: atan(e_t U0 / (e_n V0)) =
    atan(e_t tan(angle) / e_n)."""
    return math.degrees(math.atan2(r.tangential.e_t * tangent, r.normal.e_n))


def _effective_friction(r, tangent) -> float:
    """Tangential over normal impulse of the whole collision, m U0 (1 - e_t) / (m V0 (1 + e_n))
    = tan(angle) (1 - e_t) / (1 + e_n) (positive when the tangential motion is slowed)."""
    return tangent * (1.0 - r.tangential.e_t) / (1.0 + r.normal.e_n)


def _psi_out(r, tangent) -> float:
    """The contact point's slip at exit or stop over V0: tan(angle) (e_t - a Omega_end / U0),
    for two spheres tan(angle) (e_t - w_end), w = a1 Omega1 + a2 Omega2 the contact spin."""
    t = r.tangential
    if t.pair is None:
        return tangent * (t.e_t - t.spin[0] - t.spin_change)
    return tangent * (t.e_t - t.spin[0] - t.pair.lower_spin[0] - t.pair.contact_spin_change)


def _pair(read):
    """``read(pair)`` of a two-sphere collision's :class:`ehdfem.tangential.pair.PairMotion`
    (None for a sphere on a wall or a head-on impact)."""
    return lambda r: (
        None if r.tangential is None or r.tangential.pair is None else read(r.tangential.pair)
    )


def _friction(read):
    """``read(friction)`` of the solid contact's Coulomb friction (None without one)."""

    def value(r):
        friction = None if r.tangential is None else r.tangential.friction
        return None if friction is None else read(friction)

    return value


def _impact_psi(which):
    """psi_in (0) or psi_out (1) at the solid impact (None without a frictional impact)."""
    return _friction(lambda f: None if f.impact_psi is None else f.impact_psi[which])


def _outer_film(name):
    """The OuterFilm estimate's attribute ``name`` (None without one: a thin layer, a head-on
    impact, the flat model, or a run that adds that flow, outer_flow "exact")."""
    return lambda r: None if r.outer_film is None else getattr(r.outer_film, name)


def _halfspace_range(name):
    """The HalfSpaceRange's attribute ``name`` (None for the other models)."""
    return lambda r: None if r.halfspace_range is None else getattr(r.halfspace_range, name)


def _rough(compute):
    """``compute(normal, sigma)`` for rough surfaces (roughness sigma > 0, by x0), else None."""
    return lambda r: None if r.params.roughness == 0.0 else compute(r.normal, r.params.roughness)


def _mixed(compute):
    """``compute(normal, sigma)`` for rough surfaces whose asperities carry a load: an
    asperity model that puts a pressure on the film (Greenwood & Tripp's: mixed lubrication),
    or the impact model's asperity obstacle where it took a touch
    (:mod:`ehdfem.film.asperity_obstacle`); else None."""

    def value(r):
        p = r.params
        mixed = p.asperities.pressure_law(p.eps, p.delta) is not None
        force = r.normal.asperity_force
        loaded = mixed or (force is not None and bool(np.max(force, initial=0.0) > 0.0))
        return compute(r.normal, p.roughness) if loaded and p.roughness else None

    return value


def _impact(name, then=float):
    """``then`` of the solid impact's attribute ``name`` (None without one)."""
    return lambda r: (
        None if r.normal.solid_impact is None else then(getattr(r.normal.solid_impact, name))
    )


def _touched(normal, sigma) -> bool:
    """The thinnest film reached the roughness sigma (an impact ends there)."""
    return normal.solid_impact is not None or normal.min_film_thickness <= sigma


def _touch_radius(normal, sigma) -> float | None:
    """The radius of the thinnest film at the step where it first reaches sigma (the impact's
    for a solid impact), by sqrt(a x0); None if it never does (0: on the axis, > 0: at the rim
    of a flattened contact)."""
    hist = normal.history
    if normal.solid_impact is not None:
        step = normal.solid_impact.index
    else:
        reached = np.flatnonzero(hist.min_film <= sigma)
        if reached.size == 0:
            return None
        step = int(reached[0])
    return float(normal.radii[int(np.argmin(hist.film_thickness[step]))])


def _largest_asperity_share(normal, sigma) -> float:
    """The asperities' largest load over the largest total load on the sphere,
    max F_a / max (F_film + F_a) (0 if they never carry load; the ratio at one instant is
    ill-defined where the film's force changes sign)."""
    asperity = normal.asperity_force
    largest = float(np.max(asperity))
    return largest / float(np.max(normal.history.force + asperity)) if largest > 0 else 0.0


def _solid_impulse_share(normal, sigma) -> float:
    """The solids' share of the collision's normal impulse: the solid impact's St (1 + e_dry)
    |V_c| plus the asperities' load int F_a dT (trapezoid over the steps), over the sphere's
    change of normal momentum St (1 + e_n) (impulses by 6 pi mu a^2, the force scale times
    x0/V0). With sliding Coulomb friction throughout, the effective friction is mu times it
    plus the film's (docs/tangential.md)."""
    solid = 0.0 if normal.solid_impact is None else normal.solid_impact.normal_impulse
    solid += float(scipy.integrate.trapezoid(normal.asperity_force, normal.history.time))
    return solid / (normal.params.St * (1.0 + normal.e_n))


def _contact_end(normal, sigma) -> float | None:
    """The time the thinnest film last rises back above sigma (the impact's time for a solid
    impact after which the film stays above sigma; None if it never reached sigma), by linear
    interpolation between the steps."""
    hist, impact = normal.history, normal.solid_impact
    first = 0 if impact is None else impact.index + 1
    below = first + np.flatnonzero(hist.min_film[first:] <= sigma)
    if below.size == 0:
        return None if impact is None else impact.time
    i = int(below[-1])
    if i == len(hist.time) - 1:
        return float(hist.time[i])
    (t0, t1), (h0, h1) = hist.time[i : i + 2], hist.min_film[i : i + 2]
    return float(t0 + (sigma - h0) / (h1 - h0) * (t1 - t0))


FORCE = "6 pi mu V0 a^2 / x0"
TANGENTIAL_ENERGY = "m U0^2 / St"
NO_BALANCE = (
    "a cavitation limit caps the film's suction, and the balance does not count that work: "
    "it checks the time integration only without one (docs/model.md)"
)

# fmt: off
OUTPUTS: tuple[Output, ...] = (
    Output("rebound", "the sphere left the layer (gap back to x0, moving away)", "-", None,
           lambda r: r.normal.rebound),
    Output("status", "how the normal motion ended: rebound, stick or stalled", "-", None,
           lambda r: r.normal.status),
    Output("e_n", "normal restitution e_dry V_exit, after a solid impact V_exit (0: sticks)",
           "V0", "m/s", lambda r: r.normal.e_n, "rebound_normal_speed_m_s",
           lambda p: p.scales().velocity),
    Output("exit_velocity", "normal velocity V_exit when the gap is back to x0, before e_dry",
           "V0", "m/s", lambda r: r.normal.exit_velocity),
    Output("max_rebound_velocity", "largest rebound velocity (DSH 1986's immersed restitution)",
           "V0", "m/s", lambda r: r.normal.max_rebound_velocity),
    Output("min_film_thickness", "thinnest film over radius and time", "x0", "m",
           lambda r: r.normal.min_film_thickness, "min_film_thickness_m",
           lambda p: p.scales().gap),
    Output("max_force", "largest film force on the sphere", FORCE, "N",
           lambda r: r.normal.max_force, "max_force_N", lambda p: p.scales().force),
    Output("contact_time", "time from first touch of the layer to exit or stop", "x0/V0", "s",
           lambda r: r.normal.contact_time, "contact_time_s", lambda p: p.scales().time),
    Output("max_compression", "largest overlap -min X of the undeformed surfaces", "x0", "m",
           lambda r: r.normal.max_compression, "max_compression_m", lambda p: p.scales().gap),
    Output("compression_by_radius", "largest compression over the sphere radius, delta max(-X)",
           "a", "m", lambda r: r.normal.compression_by_radius),
    Output("load_radius", "radius carrying 95 % of the largest film force (half-space model)",
           "a", "m", _halfspace_range("load_radius"), "load_radius_m", lambda p: p.radius,
           optional=True),
    Output("halfspace_range_flag", "the half-space result is outside the theory's range",
           "-", None, _halfspace_range("flagged"), optional=True),
    Output("energy_error", "|KE0 - KE - E_elastic - dissipated| / KE0 at the end", "-", None,
           lambda r: r.normal.energy_error, applies=_without_suction_limit, reason=NO_BALANCE),
    Output("film_nodes", "film nodes used (after any refinement)", "-", None,
           lambda r: len(r.normal.radii)),
    Output("time_steps", "accepted time steps of the normal motion", "-", None,
           lambda r: r.normal.steps),
    Output("e_t", "tangential restitution U/U0 of the centre (two spheres: of U1 - U2) at exit "
           "or stop", "U0", "m/s", _tangential("e_t"), "exit_tangential_speed_m_s",
           lambda p: p.tangential_speed),
    Output("spin_change", "spin change a (Omega - Omega0) / U0 at exit or stop (two spheres: the "
           "upper one's, a = a1)", "U0/a", "rad/s", _tangential("spin_change"),
           "spin_change_rad_s", lambda p: p.tangential_speed / p.radius),
    Output("outer_film_e_t_change", "estimated change of e_t by the flow beyond the immersed "
           "film's tangential integrals (r > a), left out", "U0", "m/s",
           _outer_film("e_t_change"), "outer_film_speed_change_m_s",
           lambda p: p.tangential_speed, optional=True),
    Output("outer_film_spin_change", "estimated change of spin_change by that flow, left out",
           "U0/a", "rad/s", _outer_film("spin_change_change"), "outer_film_spin_change_rad_s",
           lambda p: p.tangential_speed / p.radius, optional=True),
    Output("lower_spin_change", "two spheres: the lower one's spin change a2 (Omega2 - Omega2(0)) "
           "/ U0, about the upper one's axis", "U0/a2", "rad/s",
           _pair(lambda p: p.lower_spin_change), optional=True),
    Output("tangential_impulse", "tangential impulse on the (upper) sphere, m (U_end - U0), m the "
           "reduced mass for two spheres", "m U0", "N s",
           _oblique(lambda r, tangent: r.tangential.e_t - 1.0),
           "tangential_impulse_N_s",
           lambda p: (p.mass + p.added_mass) * p.tangential_speed),
    Output("pair_balance_error", "two spheres: energy balance of both spheres' translation and "
           "spin over the energy lost", "-", None, _pair(lambda p: p.balance_error),
           optional=True),
    Output("rebound_angle", "rebound angle of the centre from the wall normal, atan(U/V) at exit",
           "deg", "deg", _oblique(_rebound_angle), applies=lambda r: r.normal.rebound,
           reason="the sphere sticks: it does not leave the layer"),
    Output("effective_friction", "tangential over normal impulse of the whole collision",
           "-", None, _oblique(_effective_friction)),
    Output("psi_in", "contact point's slip over the normal speed at first touch, (U0-a Omega0)/V0",
           "-", None, _oblique(lambda r, tangent: tangent * float(r.tangential.slip[0]))),
    Output("psi_out", "contact point's slip at exit or stop over the normal speed at first touch",
           "-", None, _oblique(_psi_out)),
    Output("contact_stuck", "the solid contact's friction stopped the slip (stick; compliant: "
           "some of the contact stuck)",
           "-", None, _friction(lambda f: f.any_stuck), optional=True),
    Output("friction_dissipated", "Coulomb friction's dissipation in the solid contact",
           TANGENTIAL_ENERGY, "J", _friction(lambda f: float(f.dissipated[-1])), optional=True),
    Output("impact_psi_in", "contact point's slip over the approach speed before the solid impact",
           "-", None, _impact_psi(0), optional=True),
    Output("impact_psi_out", "contact point's slip after the solid impact over its approach speed",
           "-", None, _impact_psi(1), optional=True),
    Output("tangential_balance_error", "sliding film's energy balance error over its loss",
           "-", None, _tangential_energy(lambda e: e.balance_error), optional=True),
    Output("tangential_work_exchanged", "work the normal motion gave the sliding film",
           TANGENTIAL_ENERGY, "J", _tangential_energy(lambda e: float(e.exchanged[-1])),
           optional=True),
    Output("tangential_dissipated", "sliding film's viscous dissipation", TANGENTIAL_ENERGY,
           "J", _tangential_energy(lambda e: float(e.dissipated[-1])), optional=True),
    Output("tangential_energy_gain", "largest rise of the tangential kinetic energy, max/E0 - 1",
           "-", None, _tangential_energy(lambda e: e.gain), optional=True),
    Output("tangential_energy_flag", "the sliding film created tangential kinetic energy",
           "-", None, _tangential_energy(lambda e: e.flagged), optional=True),
    Output("superposition_flag", "the sliding film's mode-1 superposition is out of range",
           "-", None, _superposition("flagged"), optional=True),
    Output("superposition_sensitivity", "relative change of e_t or spin with the cavity rule",
           "-", None, _superposition("sensitivity"), optional=True),
    Output("superposition_tilt", "largest mode-1 tilt s|H1|/H0", "-", None,
           _superposition("largest_tilt"), optional=True),
    Output("superposition_viscosity_tilt", "largest viscosity tilt s|q| d ln(mu)/dP", "-",
           None, _superposition("largest_viscosity_tilt"), optional=True),
    Output("superposition_overlap", "largest overlap of the mode-1 suction with the cavity",
           "-", None, _superposition("suction_overlap"), optional=True),
    Output("asperity_contact", "the thinnest film reached the roughness sigma (rough surfaces)",
           "-", None, _rough(_touched), optional=True),
    Output("asperity_touch_radius", "where the thinnest film first reached sigma (0: the axis)",
           "sqrt(a x0)", "m", _rough(_touch_radius), "asperity_touch_radius_m",
           lambda p: p.scales().radius, optional=True),
    Output("solid_impact_velocity", "approach speed |V_c| at the asperities' solid impact",
           "V0", "m/s", _impact("approach_velocity", abs), "solid_impact_speed_m_s",
           lambda p: p.scales().velocity, optional=True),
    Output("solid_impact_time", "time of the asperities' solid impact from first touch",
           "x0/V0", "s", _impact("time"), "solid_impact_time_s", lambda p: p.scales().time,
           optional=True),
    Output("max_asperity_share", "the asperities' largest load over the largest total load",
           "-", None, _mixed(_largest_asperity_share), optional=True),
    Output("max_asperity_force", "largest asperity load on the sphere (pressure, obstacle)", FORCE,
           "N", _mixed(lambda n, s: float(np.max(n.asperity_force))), "max_asperity_force_N",
           lambda p: p.scales().force, optional=True),
    Output("solid_impulse_share", "the solids' share (impact, asperity load) of the normal impulse",
           "-", None, _rough(_solid_impulse_share), optional=True),
    Output("asperity_contact_end", "time the thinnest film last rises above sigma (or impact)",
           "x0/V0", "s", _rough(_contact_end), optional=True),
    Output("impact_stored_share", "solids' elastic energy at the impact over St/2",
           "-", None, _impact("stored_share"), optional=True),
)
# fmt: on


def names() -> tuple[str, ...]:
    """The outputs' names, in registry order."""
    return tuple(o.name for o in OUTPUTS)


def si_keys() -> tuple[str, ...]:
    """The keys of the outputs that have an SI value, in registry order."""
    return tuple(o.si_key for o in OUTPUTS if o.si_key is not None)


def computed(result: Collision) -> dict:
    """Every output as computed, whether or not it applies (scaled): the raw numbers, e.g.
    for a table of reference values."""
    return {o.name: o.compute(result) for o in OUTPUTS}


def values(result: Collision) -> dict:
    """The outputs of a summary (scaled): None where not applicable; an optional output
    left out where it is None."""
    out = {o.name: o.value(result) for o in OUTPUTS}
    return {o.name: out[o.name] for o in OUTPUTS if not (o.optional and out[o.name] is None)}


def not_applicable(result: Collision) -> dict:
    """{name: reason} of the outputs that do not apply to ``result``."""
    return {o.name: o.reason for o in OUTPUTS if o.applies is not None and not o.applies(result)}


def si_values(result: Collision) -> dict:
    """The SI values {si_key: scaled value * factor} of a collision with physical inputs
    (empty without them), where the value exists and applies."""
    if result.physical is None:
        return {}
    out = {}
    for o in OUTPUTS:
        value = o.value(result) if o.si_key is not None else None
        if value is not None:
            out[o.si_key] = value * o.si_factor(result.physical)
    return out


def in_si_where_possible(result: Collision) -> dict:
    """Every output once, for a collision with physical inputs: its SI value under its SI key
    where it has one, else its scaled value under its name (None where there is none)."""
    si = si_values(result)
    out = {}
    for o in OUTPUTS:
        if o.si_key is None:
            out[o.name] = o.value(result)
        else:
            out[o.si_key] = si.get(o.si_key)
    return out


def _text(value) -> str:
    """A value in a table: 6 significant digits for a float, "-" for None."""
    return "-" if value is None else f"{value:.6g}" if isinstance(value, float) else str(value)


def table_rows(summary: dict) -> list[tuple[str, str, str, str]]:
    """The result table of a summary: (name, value, scale, meaning) of every output it holds,
    then (SI key, value, unit, what it is) of its SI values, what it is being the scaled
    output times its scale (``rebound_normal_speed_m_s``: e_n times V0); values as text (6
    digits, "-" for None, "n/a" for an output that does not apply, its reason after its
    meaning)."""
    reasons = summary.get("not_applicable", {})
    si = summary.get("si", {})
    rows, si_rows = [], []
    for o in OUTPUTS:
        if o.name in summary:
            meaning = o.meaning
            if o.name in reasons:
                meaning += f" (not applicable: {reasons[o.name]})"
            value = "n/a" if o.name in reasons else _text(summary[o.name])
            rows.append((o.name, value, o.scale, meaning))
        if o.si_key in si:
            meaning = f"{o.name} times {o.scale}" if o.scale != "-" else o.meaning
            si_rows.append((o.si_key, _text(si[o.si_key]), o.unit, meaning))
    return rows + si_rows


def format_table(summary: dict) -> str:
    """:func:`table_rows` as aligned lines of text, one output a line."""
    rows = table_rows(summary)
    widths = [max(len(row[i]) for row in rows) for i in range(3)]
    lines = []
    for row in rows:
        cells = [cell.ljust(width) for cell, width in zip(row[:3], widths, strict=True)]
        lines.append("  " + "  ".join([*cells, row[3]]))
    return "\n".join(lines)


def markdown_table() -> str:
    """The registry as the Markdown table of docs/outputs.md: name, meaning, scale, SI unit, SI
    key, and a note where an output may be missing (optional) or may not apply (the reason)."""
    lines = [
        "| name | meaning | scaled by | SI unit | SI key | note |",
        "|---|---|---|---|---|---|",
    ]
    for o in OUTPUTS:
        note = "left out of the summary where there is none" if o.optional else ""
        note = f"None where not applicable: {o.reason}" if o.applies is not None else note
        si_key = f"`{o.si_key}`" if o.si_key else "-"
        cells = (f"`{o.name}`", o.meaning, o.scale, o.unit or "-", si_key, note)
        lines.append("| " + " | ".join(cell.replace("|", "\\|") for cell in cells) + " |")
    return "\n".join(lines)
