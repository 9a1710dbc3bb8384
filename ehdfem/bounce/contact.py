"""A contact within a bounce: the immersed EHD collision from the flight's hand-over state to its
exit (docs/bounce.md).

The film model (:func:`ehdfem.collision.collide`, Davis, Serayssol & Hinch 1986) starts at the
hand-over (:meth:`ehdfem.bounce.flight.FarField.handover_margin`) at X = 1 (x0 = h_c) with
V0 = |v(h_c)|, the inertia M(h_c) (the sphere's mass, and the added mass not in the weight),
gravity and buoyancy (``contact_gravity``), e_dry and the cavitation limit of the inputs; it
ends at exit (X = h_exit / h_c, speed e_n V0 with the collision's e_n: e_dry V_exit for smooth
surfaces, V_exit for rough ones, whose asperities act inside the contact;
:meth:`ehdfem.bounce.flight.FarField.exit_gap`) or sticks. The surfaces' roughness [m] is the
same at every contact, sigma / x0 is not. With ``contact_history`` (the default) the history
force acts in the film model's time stepping (:class:`ehdfem.motion.forces.HistoryForce`, from
the flight's memory, in the contact's scales:
:meth:`ehdfem.bounce.flight.FarField.contact_history_force`); without it its impulse over the
contact is measured only. The flight's remainder (phi - 1 + lambda - a/h) is not applied during
the contact; its impulse is measured (:class:`ehdfem.bounce.result.Contact`; ``contact_drag``
adds it to the rebound's momentum at exit, a first-order estimate). The contact's velocity
change is carried into the history force's memory (``history_memory`` "keep"), or the memory is
emptied ("reset") or keeps only the flight before the contact ("approach"). Flight resumes at
h_exit with the kinetic energy of the exit.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np
from scipy.integrate import cumulative_trapezoid, trapezoid

from ..collision import collide, film_radii
from ..config import Numerics, RunConfig
from ..exact import sphere_towards_wall as towards_wall
from ..film import cavitation
from ..inputs.scales import PhysicalCollision
from ..outputs import registry as outputs
from ..solids.compliance import RigidSolids
from . import unsteady
from .flight import FarField, Flight, FlightState
from .result import Contact

MODELS = ("halfspace", "rigid")  # the solids of the contacts
SETTLED_FILM = 0.95  # the film's pressure has built up once X <= this (entry force jump)


@dataclass(frozen=True)
class ImmersedCollision:
    """The film model of a bounce's contacts: the flight ``far`` (the bounce's inputs and the
    flight's force law), the solids ``model`` of the contacts (:data:`MODELS`: "halfspace" or
    "rigid") and the film's ``numerics`` (its nodes, refinements and time-step control; the
    exit gap is each contact's own)."""

    far: FarField
    model: str
    numerics: Numerics

    def collide(self, leg: Flight) -> tuple[Contact, FlightState, dict]:
        """The contact after the falling ``leg``: the film model from the hand-over state (its
        inertia M(h_c), handing back at :meth:`FarField.exit_gap`, with the history force when
        ``contact_history``). Returns the Contact, the FlightState where flight resumes after a
        rebound (the speed e_n V0 sqrt(M(h_c) / M(h_exit)), e_n the collision's restitution,
        which keeps the kinetic energy across the added mass's change, as the flight's own
        equation does; plus the drag's kick with ``contact_drag``, :meth:`_exit_kick`) and the
        contact's trajectory samples (:meth:`_columns`)."""
        far, inputs = self.far, self.far.inputs
        start = leg.last()
        speed = -start.velocity
        mass, exit_gap = far.inertia(start.gap)[0], far.exit_gap(start.gap, speed)
        result, scales = self._film_collision(start, speed, mass, exit_gap)
        normal, params = result.normal, result.params
        energy_unit = mass * speed**2 / params.St
        at_end, times, samples = self._contact_samples(normal, start, scales)
        velocities = samples["velocity"] * speed
        exit_speed = normal.exit_velocity * speed
        rebound_speed = normal.e_n * speed * math.sqrt(mass / far.inertia(exit_gap)[0])
        jump = (np.append(times, times[-1]), np.append(velocities, rebound_speed))
        memory, history_impulse, history_work = self._carry_memory(
            start.gap, start.memory, *(jump if normal.rebound else (times, velocities))
        )
        history_work = start.history_work + inputs.contact_history * history_work
        columns = self._columns(start, times, samples, energy_unit, history_work[: len(times)])
        film_dissipated = at_end["dissipated"] * energy_unit
        exit_loss = 0.5 * mass * (exit_speed**2 - (normal.e_n * speed) ** 2)
        exit_loss += at_end["elastic"] * energy_unit
        omitted = self._omitted(normal.history, normal.contact_time, scales, speed, mass)
        exit_state = FlightState(
            times[-1], exit_gap, rebound_speed, start.drag_work, history_work[-1], memory
        )
        if normal.rebound:
            exit_state = self._exit_kick(exit_state, omitted["drag_impulse"])
        impact = float(np.max(np.abs(leg.velocity)))
        contact = Contact(
            impact_speed=impact,
            St=inputs.stokes_number(impact),
            handover_gap=start.gap,
            handover_speed=speed,
            exit_gap=exit_gap,
            contact_St=params.St,
            eps=params.eps,
            p_cav=cavitation.suction_limit_output(params.p_cav),
            e=exit_state.velocity / impact,
            **self._jumps(normal.history, normal, scales),
            gravity_impulse=omitted["gravity_impulse"],
            remainder_impulse=omitted["remainder_impulse"],
            history_impulse=history_impulse / (mass * speed),
            film_dissipated=film_dissipated,
            exit_loss=exit_loss,
            film=outputs.in_si_where_possible(result),
        )
        return contact, exit_state, columns

    def _exit_kick(self, state: FlightState, drag_impulse) -> FlightState:
        """The exit ``state`` with the flight's remainder's impulse over the contact [N s]
        added to its momentum when ``contact_drag``: v += J / M(h_exit), a first-order estimate
        of its effect on the rebound (the contact lasts 30-160 us, the impulse is below 1 % of
        the momentum), the kinetic energy it adds taken from the liquid (the drag's work
        column) and the velocity change carried into the memory as a jump."""
        inertia = self.far.inertia(state.gap)[0]
        velocity = state.velocity + self.far.inputs.contact_drag * drag_impulse / inertia
        work = 0.5 * inertia * (state.velocity**2 - velocity**2)
        memory = state.memory + (velocity - state.velocity) if len(state.memory) else state.memory
        return replace(state, velocity=velocity, drag_work=state.drag_work + work, memory=memory)

    def _carry_memory(self, gap, memory, times, velocities) -> tuple[np.ndarray, float, np.ndarray]:
        """The history force's memory after the contact handed over at ``gap`` [m] (the gap of
        the kernel's weights in it) whose velocity ``velocities`` [m/s] at ``times`` [s] it
        follows (the exit's jump included as the last sample), the impulse
        [N s] of the history force during it (applied in the contact's time stepping with
        ``contact_history``, else only measured) and its work on the liquid from the hand-over
        at each sample, -int F_H v dt [J] (trapezoidal rule, as the film model's
        :class:`ehdfem.motion.forces.HistoryForce` integrates it). With ``history_memory``
        "reset" the memory is emptied at exit; with "approach" it is the hand-over's memory
        faded over the contact, z_i e^(-duration / tau_i), without the contact's velocity
        change (variations that isolate the memory of the contact's reversal)."""
        far = self.far
        if not len(memory):
            return memory, 0.0, np.zeros(len(times))
        carried = unsteady.carry_memory(memory, times, velocities, far.relaxation_times)
        pairs = zip(velocities, carried, strict=True)
        force = np.array([far.history_force(gap, v, z) for v, z in pairs])
        impulse = float(trapezoid(force, times))
        work = -cumulative_trapezoid(force * velocities, times, initial=0.0)
        if far.inputs.history_memory == "reset":
            return np.zeros_like(memory), impulse, work
        if far.inputs.history_memory == "approach":
            faded = memory * np.exp(-(times[-1] - times[0]) / far.relaxation_times)
            return faded, impulse, work
        return carried[-1], impulse, work

    def _film_collision(self, start: FlightState, speed: float, mass: float, exit_gap: float):
        """The immersed EHD collision from the hand-over at ``start.gap`` (m, the contact's layer
        thickness x0) and approach ``speed`` (m/s, its V0), with the inertia ``mass`` [kg]
        (the sphere's own mass plus its added mass there), gravity and buoyancy if
        ``contact_gravity``, the history force from the flight's memory if ``contact_history``
        (:meth:`FarField.contact_history_force`), the surfaces' roughness (SI, scaled by the
        collision by this contact's x0) and asperity model, leaving at ``exit_gap`` [m]; returns
        the collision result (scaled) and its SI scales."""
        far, inputs, gap = self.far, self.far.inputs, start.gap
        physical = PhysicalCollision(
            radius=inputs.radius,
            sphere=inputs.sphere,
            wall=inputs.wall,
            liquid=inputs.liquid,
            speed=speed,
            layer_thickness=gap,
            layer="immersed",
            e_dry=inputs.e_dry,
            ambient_pressure=inputs.ambient_pressure,
            added_mass=mass - far.mass,
            cavitation=inputs.cavitation,
            viscosity=inputs.viscosity,
            pressure_viscosity=inputs.pressure_viscosity,
            gravity=inputs.gravity if inputs.contact_gravity else 0.0,
            sphere_roughness=inputs.sphere_roughness,  # sigma / x0 differs between contacts
            wall_roughness=inputs.wall_roughness,
            asperities=inputs.asperities,
        )
        options = replace(self.numerics.integrator, exit_gap=exit_gap / gap)
        config = RunConfig(numerics=replace(self.numerics, integrator=options))  # half-space
        forces = ()
        if inputs.contact_history and len(start.memory):
            forces = (far.contact_history_force(gap, speed, start.memory),)
        solids = None
        if self.model == "rigid":
            solids = RigidSolids(film_radii(physical.dimensionless(), self.numerics.nodes))
        result = collide(physical, config, compliance=solids, forces=forces)
        return result, physical.scales()

    def _contact_samples(self, normal, start: FlightState, scales) -> tuple:
        """The contact's samples from the hand-over ``start`` to the exit or the stop, the exit
        interpolated between the last two steps: the scaled gap, velocity, dissipated and
        elastic energy at the end (a dict), the samples' times [s] and the scaled samples of
        the same four (a dict)."""
        hist, end = normal.history, normal.contact_time
        names = ("gap", "velocity", "dissipated", "elastic")
        at_end = {name: float(np.interp(end, hist.time, getattr(hist, name))) for name in names}
        shown = hist.time <= end
        times = hist.time[shown]
        samples = {name: getattr(hist, name)[shown] for name in names}
        if normal.rebound:
            times = np.append(times, end)
            samples = {name: np.append(samples[name], at_end[name]) for name in names}
        return at_end, start.time + times * scales.time, samples

    def _columns(self, start: FlightState, times, samples, energy_unit, history_work) -> dict:
        """The contact's samples as trajectory columns (SI; ``samples`` scaled as
        :meth:`_contact_samples` gives them, energies by ``energy_unit`` = M V0^2 / St, in J),
        with the history force's work on the liquid so far [J] at each; all of
        :data:`ehdfem.bounce.result.TRAJECTORY_COLUMNS` but ``contacts`` and ``exit_loss``,
        ``film_dissipated`` from the hand-over on. The potential energy follows the gap when
        gravity acts in the contact, else it is held at its hand-over value."""
        far, gap, speed = self.far, start.gap, -start.velocity
        velocities, gaps = samples["velocity"] * speed, samples["gap"] * gap
        height = gaps if far.inputs.contact_gravity else np.full(len(times), gap)
        return {
            "time": times,
            "gap": gaps,
            "velocity": velocities,
            "phase": ["contact"] * len(times),
            "kinetic": 0.5 * far.inertia(gap)[0] * velocities**2,
            "potential": far.net_weight * height,
            "elastic": samples["elastic"] * energy_unit,
            "drag_dissipated": np.full(len(times), start.drag_work),
            "history_dissipated": history_work,
            "film_dissipated": samples["dissipated"] * energy_unit,
        }

    def _jumps(self, hist, normal, scales) -> dict:
        """Relative force jumps flight -> film at entry (X <= SETTLED_FILM) and before exit."""
        far = self.far
        x0, v0 = scales.gap, scales.velocity

        def jump(i):
            gap, velocity = hist.gap[i] * x0, hist.velocity[i] * v0
            flight = far.drag(gap, velocity)
            return float(1.0 - hist.force[i] * scales.force / flight)

        settled = np.flatnonzero(hist.gap <= SETTLED_FILM)
        entry = jump(int(settled[0])) if settled.size else math.nan
        leaving = np.flatnonzero((hist.time < normal.contact_time) & (hist.velocity > 0))
        exit_jump = jump(int(leaving[-1])) if normal.rebound and leaving.size else math.nan
        return {"entry_jump": entry, "exit_jump": exit_jump}

    def _omitted(self, hist, end, scales, speed, mass) -> dict:
        """Impulses of gravity-buoyancy (0 when it acts in the contact) and of the flight's
        remainder over the contact, relative to the hand-over momentum M V0 (the remainder's
        of its magnitude), and ``drag_impulse`` [N s], the remainder's signed impulse (positive
        away from the wall): int -6 pi mu a v (phi - 1 + lambda - a/h) dt, h the thinnest
        film."""
        far = self.far
        shown = hist.time <= end
        time = hist.time[shown] * scales.time
        gap = np.maximum(hist.min_film[shown], 1e-12) * scales.gap
        velocity = hist.velocity[shown] * speed
        phi = far.phi(velocity)
        lam = towards_wall.resistance(gap / far.inputs.radius)
        remainder = -far.stokes * velocity * (phi - 1.0 + lam - far.inputs.radius / gap)
        momentum = mass * speed
        weight = 0.0 if far.inputs.contact_gravity else far.net_weight
        return {
            "gravity_impulse": weight * end * scales.time / momentum,
            "remainder_impulse": float(trapezoid(np.abs(remainder), time)) / momentum,
            "drag_impulse": float(trapezoid(remainder, time)),
        }
