"""The result of a bounce (SI): its trajectory's samples, one record per contact, their rows
for CSV tables and the JSON summary."""

from __future__ import annotations

from dataclasses import asdict, dataclass

import numpy as np

from ..dem.closedform import legendre
from ..outputs import provenance
from .inputs import BounceInputs


@dataclass
class Contact:
    """One contact (film model, :func:`ehdfem.collision.collide`) within a bounce (SI).

    ``impact_speed``: the largest approach speed since the last apex (the release); the
    restitution ``e`` = rebound speed / ``impact_speed``, as measured in experiments (the
    rebound speed at the exit gap, the largest rising speed after it); ``St``: rho_p D
    impact_speed / (9 mu). ``handover_gap`` h_c and ``handover_speed`` V0 = |v(h_c)|;
    ``exit_gap`` [m]: where the film model hands back
    (:meth:`ehdfem.bounce.flight.FarField.exit_gap`);
    ``contact_St``, ``eps``, ``p_cav``: the film model's groups (with the added mass).
    ``film``: every output of the film model (:mod:`ehdfem.outputs.registry`,
    :func:`ehdfem.outputs.registry.in_si_where_possible`): in SI under its SI key where it has
    one (``min_film_thickness_m`` [m], ``max_force_N`` [N], ``contact_time_s`` [s],
    ``max_compression_m`` [m], ``rebound_normal_speed_m_s`` the rebound speed [m/s]), else
    under its name scaled by the contact's own scales, x0 = h_c and V0 (``exit_velocity``
    V_exit by V0, before e_dry; ``status`` "rebound" or "stick"; ``energy_error`` the film
    model's relative balance error, None with a cavitation limit). Force jumps (relative,
    flight to film, both at the same h and v): ``entry_jump`` once the film pressure has built
    up (the first step with X <=
    :data:`ehdfem.bounce.contact.SETTLED_FILM`), ``exit_jump`` at the last step before exit.
    Impulses over the contact, relative to the hand-over momentum M(h_c) V0 (not applied during
    it, but the history force's with ``contact_history``):
    ``gravity_impulse`` ((m - m_f) g duration; 0 when gravity acts in the contact),
    ``remainder_impulse`` (int 6 pi mu a |v| |phi - 1 + lambda - a/h| dt, with h the thinnest
    film) and ``history_impulse`` (int F_H dt from the memory carried through the contact,
    signed, positive away from the wall; 0 without a history force). Energies [J]:
    ``film_dissipated`` (the film's viscous dissipation up to exit), ``exit_loss`` (the
    exit's kinetic energy less the rebound's at e_n, the dry loss of smooth surfaces, plus
    the elastic energy left in the solids)."""

    impact_speed: float
    St: float
    handover_gap: float
    handover_speed: float
    exit_gap: float
    contact_St: float
    eps: float
    p_cav: float | None
    e: float
    entry_jump: float
    exit_jump: float
    gravity_impulse: float
    remainder_impulse: float
    history_impulse: float
    film_dissipated: float
    exit_loss: float
    film: dict
    apex_gap: float | None = None
    apex_time: float | None = None

    @property
    def status(self) -> str:
        """The film model's outcome, "rebound" or "stick" (``film["status"]``)."""
        return self.film["status"]

    def row(self) -> dict:
        """The contact as one flat dict: its fields, then the film model's outputs."""
        fields = asdict(self)
        film = fields.pop("film")
        return {**fields, **film}


TRAJECTORY_COLUMNS = (
    "time",
    "gap",
    "velocity",
    "phase",
    "contacts",
    "kinetic",
    "potential",
    "elastic",
    "drag_dissipated",
    "history_dissipated",
    "film_dissipated",
    "exit_loss",
)


@dataclass
class BounceResult:
    """A bounce's trajectory and contacts (SI).

    ``trajectory``: arrays over the samples, as TRAJECTORY_COLUMNS: time [s] (0 at release or
    start), gap [m] (centre height - a; during a contact X x0, negative by the solids'
    compression), velocity [m/s], phase ("flight" or "contact"), contacts (how many began so
    far), and the energies [J]: kinetic 1/2 M(h) v^2 (M = m + C_M(h) m_f; M(h_c) in a contact),
    potential (m - m_f) g h (held at its hand-over value during a contact where gravity is not
    applied), elastic (in the solids), the cumulated work of the drag and of the history force
    on the liquid, film dissipation and exit losses. Their sum is the start's energy
    up to the integration errors (:meth:`energy_error`). ``contacts``: one :class:`Contact`
    each. ``status``: why it stopped. ``terminal_velocity``: the drag law's settling speed
    [m/s]."""

    inputs: BounceInputs
    model: str
    trajectory: dict
    contacts: list[Contact]
    status: str
    terminal_velocity: float
    handover_jump: float
    ehd_multiple: float
    rest_apex: float

    def energy_error(self) -> float:
        """max over the samples of |sum of the energies - its start value| / start value."""
        t = self.trajectory
        total = sum(np.asarray(t[name], dtype=float) for name in TRAJECTORY_COLUMNS[5:])
        return float(np.max(np.abs(total - total[0])) / total[0])

    def trajectory_rows(self) -> list[dict]:
        """The trajectory as rows (dicts of TRAJECTORY_COLUMNS), e.g. for a CSV table."""
        columns = [np.asarray(self.trajectory[name]).tolist() for name in TRAJECTORY_COLUMNS]
        rows = zip(*columns, strict=True)
        return [dict(zip(TRAJECTORY_COLUMNS, row, strict=True)) for row in rows]

    def contact_rows(self) -> list[dict]:
        """The contacts as rows (:meth:`Contact.row`, numbered from 1)."""
        return [{"contact": i + 1, **c.row()} for i, c in enumerate(self.contacts)]

    def summary(self, command: list[str] | None = None) -> dict:
        """The results as a JSON-ready dict: status, contacts, apexes, energy balance, where
        it comes from (:func:`ehdfem.outputs.provenance.record`, ``command`` its command line,
        default sys.argv) and every input."""
        inputs = asdict(self.inputs)
        first = self.contacts[0] if self.contacts else None
        return {
            "provenance": provenance.record(command),
            "status": self.status,
            "model": self.model,
            "contacts": len(self.contacts),
            "first_e": None if first is None else first.e,
            "first_St": None if first is None else first.St,
            "legendre_first_e": None if first is None else self.legendre(first.St),
            "terminal_velocity": self.terminal_velocity,
            "time_scale": self.inputs.time_scale(),
            "energy_error": self.energy_error(),
            "impacts": self.contact_rows(),
            "inputs": {
                **inputs,
                "handover_jump": self.handover_jump,
                "ehd_multiple": self.ehd_multiple,
                "rest_apex": self.rest_apex,
                "model": self.model,
            },
        }

    def legendre(self, St: float) -> float:
        """Legendre et al. (2006)'s empirical e = e_dry exp(-35 / St_L) at the Stokes number St,
        with St_L including the added mass (:func:`ehdfem.dem.closedform.legendre`)."""
        ratio = self.inputs.liquid.density / self.inputs.sphere.density
        return float(legendre(St, self.inputs.e_dry, ratio))
