"""The loop of a bounce: flight legs (:mod:`ehdfem.bounce.flight`) and contacts
(:mod:`ehdfem.bounce.contact`) in turn until the sphere rests, with the trajectory's samples
and their energies (docs/bounce.md).

The sphere rests when a contact sticks or stalls, or when an apex is below ``rest_apex`` D or
already inside the hand-over region; the computation also stops at the apex after
``max_bounces`` contacts.
"""

from __future__ import annotations

import numpy as np

from .contact import ImmersedCollision
from .flight import Flight, FlightState
from .result import TRAJECTORY_COLUMNS, Contact

ENDINGS = {"stick": "sticks", "stalled": "stalled (settling through the film)"}


class BounceLoop:
    """Flight legs and contacts (each by ``collision``) until the sphere rests (:meth:`go`), an
    apex below ``rest_apex`` D ending it; with the trajectory's samples (``samples``, lists
    over :data:`ehdfem.bounce.result.TRAJECTORY_COLUMNS`), the ``contacts`` and the energy
    the films dissipated and the exits lost so far [J]."""

    def __init__(self, collision: ImmersedCollision, rest_apex: float):
        self.collision, self.far = collision, collision.far
        self.rest_apex = rest_apex * self.far.inputs.diameter
        self.samples = {name: [] for name in TRAJECTORY_COLUMNS}
        self.contacts: list[Contact] = []
        self.film_dissipated = self.exit_loss = 0.0

    def go(self, start: FlightState, max_bounces) -> str:
        """Fly and collide from ``start`` until the sphere rests; returns the reason it
        stopped."""
        leg = self._fly(start, rising=False)
        while True:
            if leg.end == "inside":
                return "rest: the apex is inside the hand-over region"
            contact, exit_state = self._collide(leg)
            if contact.status != "rebound":
                return f"rest: the contact {ENDINGS[contact.status]}"
            rise = self._fly(exit_state, rising=True)
            contact.apex_gap, contact.apex_time = float(rise.gap[-1]), float(rise.time[-1])
            if rise.gap[-1] < self.rest_apex:
                return "rest: the apex is below rest_apex D"
            if len(self.contacts) >= max_bounces:
                return "stopped at the apex after max_bounces contacts"
            leg = self._fly(rise.last(), rising=False)

    def _fly(self, start, rising) -> Flight:
        leg = self.far.fly(start, rising)
        if leg.end != "inside":
            self._record_flight(leg)
        return leg

    def _record_flight(self, leg: Flight):
        far = self.far
        mass = np.array([far.inertia(gap)[0] for gap in leg.gap])
        self._append(
            time=leg.time,
            gap=leg.gap,
            velocity=leg.velocity,
            phase=["flight"] * len(leg.time),
            kinetic=0.5 * mass * leg.velocity**2,
            potential=far.net_weight * leg.gap,
            elastic=np.zeros(len(leg.time)),
            drag_dissipated=leg.drag_dissipated,
            history_dissipated=leg.history_dissipated,
        )

    def _append(self, **columns):
        count = len(columns["time"])
        columns.setdefault("contacts", [len(self.contacts)] * count)
        columns.setdefault("film_dissipated", [self.film_dissipated] * count)
        columns.setdefault("exit_loss", [self.exit_loss] * count)
        for name in TRAJECTORY_COLUMNS:
            self.samples[name].extend(np.asarray(columns[name]).tolist())

    def _collide(self, leg: Flight) -> tuple[Contact, FlightState]:
        """The contact after the falling ``leg`` (:meth:`ImmersedCollision.collide`), its
        samples and energies recorded; returns the Contact and the FlightState where flight
        resumes after a rebound."""
        contact, exit_state, columns = self.collision.collide(leg)
        columns["contacts"] = [len(self.contacts) + 1] * len(columns["time"])
        columns["film_dissipated"] = self.film_dissipated + columns["film_dissipated"]
        self._append(**columns)
        self.film_dissipated += contact.film_dissipated
        self.exit_loss += contact.exit_loss
        self.contacts.append(contact)
        if contact.status == "rebound":  # the exit's velocity jump (e_dry, the kick)
            self._append_exit(exit_state)
        return contact, exit_state

    def _append_exit(self, state: FlightState):
        """The sample of the flight's start after a contact (the exit's velocity jump)."""
        inertia = self.far.inertia(state.gap)[0]
        self._append(
            time=[state.time],
            gap=[state.gap],
            velocity=[state.velocity],
            phase=["flight"],
            kinetic=[0.5 * inertia * state.velocity**2],
            potential=[self.far.net_weight * state.gap],
            elastic=[0.0],
            drag_dissipated=[state.drag_work],
            history_dissipated=[state.history_work],
        )

    def arrays(self) -> dict:
        """The trajectory samples as numpy arrays."""
        return {name: np.asarray(values) for name, values in self.samples.items()}
