"""The record of a normal collision: histories at the accepted time steps, with the energies.

Scaled (DSH 1986): time by x0/V0, gap X and film thickness H by x0, velocity V by V0, pressure
P by mu V0 a / x0^2 at the film nodes, force by 6 pi mu V0 a^2 / x0, radius by sqrt(a x0).
Energies are by m V0^2 / St, so that the kinetic energy is St V^2 / 2 (St / 2 at impact), the
elastic energy stored in the solids is (1/6) P.M C P (M the film's lumped mass, C the
compliance; with the squeeze-shear traction, plus the pressure's work on the shear opening,
(1/3) int P.M dW_shear) and the dissipation is the time integral of the film's viscous
dissipation rate (:meth:`ehdfem.film.reynolds.Film.dissipation_rate`). Without cavitation and with
e_dry = 1 the balance kinetic + elastic + dissipated = St / 2 holds to discretisation error.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..film.reynolds import FilmState


@dataclass
class NormalHistory:
    """Time histories at the accepted steps (scaled as in the module docstring).

    ``pressure``, ``fill`` and ``film_thickness`` are (steps, nodes): ``fill`` is the liquid
    fraction theta of the gap (1 where the film is full, and everywhere but in mass-conserving
    cavities), so theta H is the liquid per area (by x0).
    """

    time: list = field(default_factory=list)
    gap: list = field(default_factory=list)
    velocity: list = field(default_factory=list)
    force: list = field(default_factory=list)
    central_film: list = field(default_factory=list)
    min_film: list = field(default_factory=list)
    edge_radius: list = field(default_factory=list)
    kinetic: list = field(default_factory=list)
    elastic: list = field(default_factory=list)
    dissipated: list = field(default_factory=list)
    pressure: list = field(default_factory=list)
    fill: list = field(default_factory=list)
    film_thickness: list = field(default_factory=list)

    def arrays(self):
        """Convert every history to a numpy array in place; returns self."""
        for name, values in vars(self).items():
            setattr(self, name, np.asarray(values))
        return self

    def record(self, time, gap, velocity, pressure, fill, h, state: FilmState, energies):
        """Append one accepted step. ``energies``: (St, compliance matrix, full lumped mass,
        dissipation so far, the pressure's work on the shear opening so far), from which the
        kinetic and elastic energies are formed."""
        St, compliance, mass, dissipated, shear_work = energies
        self.time.append(time)
        self.gap.append(gap)
        self.velocity.append(velocity)
        self.force.append(float(state.force_weights @ pressure))
        self.central_film.append(h[0])
        self.min_film.append(h.min())
        self.edge_radius.append(state.edge_radius)
        self.kinetic.append(0.5 * St * velocity**2)
        self.elastic.append(float(mass * pressure @ (compliance @ pressure)) / 6.0 + shear_work)
        self.dissipated.append(dissipated)
        self.pressure.append(pressure)
        self.fill.append(fill)
        self.film_thickness.append(h)
