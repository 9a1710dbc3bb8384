"""Tangential compliance of the solid contact: the rough sphere's solid impact with the
tangential elasticity of a Hertz contact (Maw, Barber & Fawcett 1976, 1981), stick, partial slip,
gross slip and the slip's reversal.

The impact is short on the film's time scale (the impact model of :mod:`ehdfem.motion.normal`),
so its tangential law is a map of the contact point's slip: psi_in -> psi_out, with
psi = u_s U0 / (|V| V0) the contact point's tangential velocity over the impact's normal approach
velocity |V| (by V0), as for the rigid-body Coulomb impact
(:func:`ehdfem.exact.rigid_impact.frictional_impact`). Inside the impact the variables are those
of :mod:`ehdfem.exact.compliant_impact`: indentation xi by its largest value d_m, time tau by
d_m / v, contact radius X by a_m = (R d_m)^(1/2), and MBF's Psi = kappa psi / mu, with kappa =
k_t / k_n = 4 G*/E* the contact's tangential over normal stiffness (Mindlin: k_t = 8 G* a_c,
1/G* = (2 - nu1)/G1 + (2 - nu2)/G2; k_n = 2 E* a_c, 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2;
:func:`mindlin_stiffness_ratio`) and chi = kappa (1 + 1/k) / 2.

The law (docs/tangential.md derives it): the Hertz normal impact with restitution e (the
contact retraces its loads e times as fast while it unloads), and Mindlin & Deresiewicz's
tangential contact in its exact one-dimensional form (Popov & Hess 2015, the method of
dimensionality reduction): springs at X in (0, 1) with tangential displacement sigma (by
mu d_m / kappa), in contact while X^2 < xi, each stuck to the contact's displacement W or
slipping at |sigma| = xi - X^2, and

    W'' = -(15/4) chi int_0^(xi^(1/2)) sigma dX,     W'(0) = Psi_in,     Psi_out = W'(end).

Discretisation (:func:`compliant_impact`): ``cells`` springs at the midpoints of equal cells of
(0, 1); a staggered (leapfrog) step, with W' at half steps, ``steps`` equal steps of tau over
the compression and as many over the restitution (each e times as long): each spring moves with
W' and is projected onto [-(xi - X^2), xi - X^2] (a slipping spring's Coulomb limit, exact, no
regularisation), then W' takes the springs' force. The energy of the impact's tangential
motion, in the scaled form E = W'^2 / (2 c) + int sigma^2 / 2 dX with c = (15/4) chi (by
2 mu^2 E* d_m^2 a_m / kappa: the slip's kinetic energy (m / (2 (1 + 1/k))) u_s^2 and the
springs' 2 int G s^2 / 2 dx, with G = kappa E* the springs' shear modulus), falls only by the
springs' slip, sum (sigma_trial^2 - sigma^2) / 2 over the projections (:class:`CompliantImpact`
records each), and its stored part is 0 once the contact has left.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..exact.compliant_impact import COMPRESSION_TIME, impact_parameter, indentation

CELLS = 400  # springs over the largest contact radius
STEPS = 2000  # steps of the compression (and of the restitution)


def mindlin_stiffness_ratio(solids) -> float:
    """kappa = k_t / k_n = 4 G*/E* of a Hertz contact (Mindlin 1949) between ``solids``, each
    with ``young_modulus`` E [Pa] and ``poisson_ratio`` nu: 2 sum (1 - nu^2)/E over
    sum (2 - nu)(1 + nu)/E (2 (1 - nu)/(2 - nu) for identical solids, 0.824 at nu = 0.3)."""
    normal = sum((1.0 - s.poisson_ratio**2) / s.young_modulus for s in solids)
    shear = sum((2.0 - s.poisson_ratio) * (1.0 + s.poisson_ratio) / s.young_modulus for s in solids)
    return 2.0 * normal / shear


@dataclass(frozen=True)
class CompliantImpact:
    """A compliant impact in MBF's variables (module docstring): ``psi_in``, ``psi_out``
    (Psi = kappa psi / mu), ``gross_slip`` whether every spring in contact slid at every step,
    and the histories at the step ends: ``time`` tau (by d_m / v), ``velocity`` W' (by
    mu v / kappa), ``stored`` the springs' energy int sigma^2 / 2 dX, ``kinetic`` W'^2 / (2 c)
    and ``dissipated`` the slip's dissipation so far (energies in one unit, so that
    E_in = Psi_in^2 / (2 c) = kinetic + stored + dissipated up to the step's error)."""

    psi_in: float
    psi_out: float
    gross_slip: bool
    time: np.ndarray
    velocity: np.ndarray
    stored: np.ndarray
    kinetic: np.ndarray
    dissipated: np.ndarray

    @property
    def energy_error(self) -> float:
        """|E_in - kinetic - stored - dissipated| at the end over E_in: the leapfrog's error."""
        total = self.kinetic[-1] + self.stored[-1] + self.dissipated[-1]
        return abs(self.kinetic[0] - total) / self.kinetic[0]


def impact_times(e_n: float, steps: int) -> tuple[np.ndarray, np.ndarray]:
    """(tau, xi): the step ends of the compression (``steps`` equal steps to tau_c) and of the
    restitution (as many, each e times as long), and the indentation there: the Hertz
    compression's xi(tau), retraced at e times its rate (xi = 0 at both ends)."""
    compression = np.linspace(0.0, COMPRESSION_TIME, steps + 1)
    xi = indentation(compression)
    xi[0] = 0.0
    time = np.concatenate([compression, COMPRESSION_TIME + e_n * compression[1:]])
    return time, np.concatenate([xi, xi[-2::-1]])


def compliant_impact(
    psi_in: float, chi: float, e_n: float, cells: int = CELLS, steps: int = STEPS
) -> CompliantImpact:
    """The compliant impact of Psi_in (MBF's variables) for MBF's chi and the restitution e in
    (0, 1] (module docstring): springs on ``cells`` cells, ``steps`` leapfrog steps per phase."""
    time, xi = impact_times(e_n, steps)
    radius_squared = ((np.arange(cells) + 0.5) / cells) ** 2
    c = 3.75 * chi
    sigma = np.zeros(cells)
    half = velocity = float(psi_in)  # W' at the half step and at the step end
    n = len(time)
    speeds, kinetic = np.full(n, velocity), np.full(n, velocity**2 / (2 * c))
    stored, dissipated = np.zeros(n), np.zeros(n)
    gross = True
    for i in range(1, n):
        step = time[i] - time[i - 1]
        limit = np.maximum(xi[i] - radius_squared, 0.0)
        trial = sigma + half * step
        sigma = np.clip(trial, -limit, limit)
        touching = limit > 0.0
        gross &= bool(np.all(np.abs(sigma[touching]) == limit[touching]))
        dissipated[i] = dissipated[i - 1] + 0.5 * np.sum(trial**2 - sigma**2) / cells
        stored[i] = 0.5 * np.sum(sigma**2) / cells
        force = np.sum(sigma) / cells
        velocity = half - 0.5 * c * force * step
        following = time[i + 1] - time[i] if i + 1 < n else 0.0
        half = velocity - 0.5 * c * force * following
        speeds[i], kinetic[i] = velocity, velocity**2 / (2 * c)
    return CompliantImpact(
        float(psi_in), float(velocity), gross, time, speeds, stored, kinetic, dissipated
    )


def compliant_rebound(
    psi_in: float, mu: float, e_n: float, stiffness_ratio: float, k: float
) -> tuple[float, bool]:
    """(psi_out, slip_stopped) of the solid impact with tangential compliance, in the project's
    psi (contact-point slip over the impact's normal approach velocity; module docstring): the
    law is odd in psi, Psi = kappa |psi_in| / mu goes through :func:`compliant_impact` with
    chi = kappa (1 + 1/k) / 2, and psi_out = sign(psi_in) mu Psi_out / kappa. ``slip_stopped``:
    some spring stuck during the impact (not gross slip throughout), the compliant contact's
    counterpart of the rigid impact's stick."""
    if psi_in == 0.0:
        return 0.0, True
    scale = mu / stiffness_ratio
    chi = impact_parameter(stiffness_ratio, k)
    impact = compliant_impact(abs(psi_in) / scale, chi, e_n)
    return float(np.sign(psi_in) * scale * impact.psi_out), not impact.gross_slip
