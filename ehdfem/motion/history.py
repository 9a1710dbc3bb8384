"""The record of a normal collision: histories at the accepted time steps, with the energies.

Scaled (DSH 1986): time by x0/V0, gap X and film thickness H by x0, velocity V by V0, pressure
P by mu V0 a / x0^2 at the film nodes, force by 6 pi mu V0 a^2 / x0, radius by sqrt(a x0).
Energies are by m V0^2 / St, so that the kinetic energy is St V^2 / 2 (St / 2 at impact), the
elastic energy stored in the solids is (1/6) P.M C P (M the film's lumped mass, C the
compliance; with the tangential surface effects, plus the pressure's work on the shear
opening, (1/3) int P.M dW_shear, and the film's work on the faces' radial motion,
(sqrt(delta)/3) int P.B dU, B the film's surface transport), the dissipation is the time
integral of the film's viscous dissipation rate
(:meth:`ehdfem.film.reynolds.Film.dissipation_rate`) and the work is that of the forces
applied to the sphere since first touch (:class:`ehdfem.motion.forces.SphereForce`;
F_ext (X - 1) for a constant force). Rough surfaces: with Greenwood & Tripp's asperity
pressure P_a(H) the solids carry P + P_a, so the elastic energy is (1/6) (P + P_a).M C (P + P_a)
plus the energy stored in the asperities, (1/3) int (int_H^inf P_a dh) R dR
(:mod:`ehdfem.film.asperities`); a solid impact's loss is in the dissipation
(:mod:`ehdfem.motion.normal`). Without cavitation and with e_dry = 1 the balance
kinetic + elastic + dissipated - work = St / 2 holds to discretisation error.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..film.reynolds import FilmState
from .forces import SphereState


@dataclass
class NormalHistory:
    """Time histories at the accepted steps (scaled as in the module docstring).

    ``pressure``, ``fill`` and ``film_thickness`` are (steps, nodes): ``fill`` is the liquid
    fraction theta of the gap (1 where the film is full, and everywhere but in mass-conserving
    cavities), so theta H is the liquid per area (by x0). ``force`` is the film's force
    (1/3) int P R dR; ``work`` the applied forces' work on the sphere. ``surface_radial``
    (steps, nodes): the faces' mean radial displacement U (by x0), recorded only when the film
    carries the surfaces' radial velocity (empty otherwise).
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
    work: list = field(default_factory=list)
    pressure: list = field(default_factory=list)
    fill: list = field(default_factory=list)
    film_thickness: list = field(default_factory=list)
    surface_radial: list = field(default_factory=list)

    def arrays(self):
        """Convert every history to a numpy array in place; returns self."""
        for name, values in vars(self).items():
            setattr(self, name, np.asarray(values))
        return self

    def record(self, time, gap, velocity, pressure, fill, h, state: FilmState, energies):
        """Append one accepted step. ``energies``: (the sphere
        (:class:`ehdfem.motion.sphere.Sphere`), compliance matrix, full lumped mass, dissipation
        so far, the film's work on the tangential surface effects so far, the asperities'
        pressure law or None), from which the kinetic and elastic energies and the applied
        forces' work are formed."""
        sphere, compliance, mass, dissipated, tangential_work, asperities = energies
        self.time.append(time)
        self.gap.append(gap)
        self.velocity.append(velocity)
        self.force.append(float(state.force_weights @ pressure))
        self.central_film.append(h[0])
        self.min_film.append(h.min())
        self.edge_radius.append(state.edge_radius)
        self.kinetic.append(sphere.kinetic_energy(velocity))
        load = pressure if asperities is None else pressure + asperities.pressure(h)
        normal_work = float(mass * load @ (compliance @ load)) / 6.0
        if asperities is not None:
            normal_work += float(mass @ asperities.energy(h)) / 3.0
        self.elastic.append(normal_work + tangential_work)
        self.dissipated.append(dissipated)
        self.work.append(sphere.work(SphereState(time, gap, velocity, h)))
        self.pressure.append(pressure)
        self.fill.append(fill)
        self.film_thickness.append(h)
