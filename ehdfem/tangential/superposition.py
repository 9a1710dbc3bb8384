"""Where the sliding film's mode-1 superposition holds: a check at every step and a 2-D check.

The sliding film (``tangential = "lubrication"``, :mod:`ehdfem.tangential.motion`) writes the film
as the normal solution plus a mode-1 part, linearised about it: the pressure
P = P0(R) + s q(R) cos(phi) and the film thickness H = H0(R) + s H1(R) cos(phi), with the
sliding amplitude

    s = (U0/V0) sqrt(delta)   (= tan(angle) sqrt(delta)),

q = 0 where P0 sits at the cavitation limit. Units are scaled (DSH 1986): P by mu V0 a / x0^2,
H by x0, R by sqrt(a x0), T by x0/V0. The linearisation fails where the mode-1 part is not
small against what it is superposed on:

- *suction overlap*: where P0 - s |q| < P_cav the superposed pressure falls below the
  cavitation limit on part of the ring; the limit would cut the pressure
  c(R) = (1/2pi) int max(0, P_cav - P0 - s q cos(phi)) dphi there (in closed form below).
  The overlap at a step is int c R dR over the largest int (2/pi) s |q| R dR of the collision
  (the mean |mode-1 pressure| at its peak): the share of the mode-1 pressure the limit would
  remove;
- *tilt*: s |H1| / H0, the mode-1 gap against the film thickness (at 1 the film closes on one
  side);
- *viscosity tilt*: s |q| d ln(mu)/dP, the change of ln mu that the mode-1 pressure makes and
  the sliding film linearises (0 at constant viscosity; large where a piezoviscous film is
  frozen, as in the elastohydrodynamic contact of hard solids).

:func:`superposition_validity` evaluates both at every step of a collision, cheaply, and flags
the collision when the cavitation-rule sensitivity or a tilt exceeds its limit
(SENSITIVITY_LIMIT, TILT_LIMIT); the sliding film itself stops when a tilt reaches 1
(:class:`ehdfem.tangential.sliding_film.SlidingFilmError`). The limits come from
:func:`check_superposition`, which solves the full Reynolds equation on the disk
(:mod:`ehdfem.tangential.disk`, with the sliding term and the cavitation limit imposed pointwise) at
chosen instants and compares the mode-1 pressure's moment int P X dA and slope force
int P dSigma0/dX dA (which give the sliding film's torque and force) with the superposition's.
docs/tangential.md gives the map of the measured errors (studies/superposition_map.py).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np

from .. import checks
from ..film.mode_one import band_sum
from ..film.reynolds import Film, tridiagonal_product
from .normal_film import cavitated_nodes, mode_one_film, normal_film
from .result import TangentialResult
from .sliding_film import gap_tilt, sliding_amplitude, viscosity_tilt

SENSITIVITY_LIMIT = 0.02  # flag above this change of 1 - e_t or of the spin change
TILT_LIMIT = 0.3  # flag above this largest s |H1| / H0


class SuperpositionWarning(UserWarning):
    """A sliding-film result outside the range where its superposition was checked."""


@dataclass(frozen=True)
class SuperpositionValidity:
    """The mode-1 superposition's indicators over a collision (module docstring; dimensionless).

    ``sliding_amplitude`` s; ``overlap`` and ``tilt`` at the steps, ``suction_overlap`` and
    ``largest_tilt`` their largest values; ``overlapping`` (steps, N) the wet nodes where
    P0 - s |q| < P_cav; ``alternative`` (e_t, spin change) with q = 0 also there, and
    ``sensitivity`` the larger relative change that makes in 1 - e_t or in the spin change
    (0 without overlap); ``viscosity_tilt`` at the steps and ``largest_viscosity_tilt``:
    :func:`ehdfem.tangential.sliding_film.viscosity_tilt`; ``flagged`` when the sensitivity exceeds
    SENSITIVITY_LIMIT or either tilt TILT_LIMIT (at BREAKDOWN_TILT the sliding film stops with
    :class:`ehdfem.tangential.sliding_film.SlidingFilmError`)."""

    sliding_amplitude: float
    overlap: np.ndarray
    tilt: np.ndarray
    overlapping: np.ndarray
    suction_overlap: float
    largest_tilt: float
    viscosity_tilt: np.ndarray
    largest_viscosity_tilt: float
    alternative: tuple[float, float]
    sensitivity: float
    flagged: bool

    def warning(self) -> str:
        """The warning for a flagged collision."""
        return (
            "the sliding film's mode-1 superposition is outside its checked range: "
            f"cavitation-rule sensitivity {self.sensitivity:.3g} (limit {SENSITIVITY_LIMIT}), "
            f"mode-1 tilt s|H1|/H0 {self.largest_tilt:.3g} and viscosity tilt "
            f"s|q| d ln(mu)/dP {self.largest_viscosity_tilt:.3g} (limit {TILT_LIMIT}); e_t and "
            "spin_change of tangential = 'lubrication' are uncertain by about that much "
            "(docs/tangential.md)"
        )


def ring_cut(offset, amplitude):
    """(1/2pi) int_0^2pi max(0, offset - amplitude cos(phi)) dphi for offset <= 0 <= amplitude:
    with cos(theta) = offset / amplitude, (offset (pi - theta) + amplitude sin(theta)) / pi
    where amplitude > -offset, else 0."""
    offset, amplitude = np.asarray(offset, float), np.asarray(amplitude, float)
    cut = amplitude > -offset
    ratio = np.divide(offset, amplitude, out=np.full_like(offset, -1.0), where=cut)
    theta = np.arccos(np.clip(ratio, -1.0, 1.0))
    return np.where(cut, (offset * (np.pi - theta) + amplitude * np.sin(theta)) / np.pi, 0.0)


def superposition_validity(normal, tangential: TangentialResult, resolve) -> SuperpositionValidity:
    """The indicators of the module docstring for a sliding-film result. ``resolve(unloaded)``
    solves the same sliding film again with q = 0 also at the (steps, N) nodes ``unloaded``
    (:func:`ehdfem.tangential.motion.solve_tangential`); it is called only where the superposed
    pressure crosses the cavitation limit."""
    if tangential.mode_one_pressure is None:
        raise checks.InputError("superposition_validity needs tangential = 'lubrication'")
    params, hist = normal.params, normal.history
    s = sliding_amplitude(params)
    mode_one = s * np.abs(tangential.mode_one_pressure)
    mass = Film(normal.radii).full_mass
    size = (2 / np.pi) * mode_one @ mass
    p_cav = params.p_cav
    wet = hist.film_thickness < 1.0 if params.layer == "thin" else np.ones(mode_one.shape, bool)
    overlap = np.zeros(len(hist.time))
    overlapping = np.zeros(mode_one.shape, bool)
    if np.isfinite(p_cav) and size.max() > 0:
        offset = np.minimum(p_cav - hist.pressure, 0.0)
        overlap = ring_cut(offset, mode_one) @ mass / size.max()
        overlapping = wet & (mode_one > -offset)
    tilt = gap_tilt(params, hist.film_thickness, tangential.mode_one_gap).max(axis=1)
    thinning = viscosity_tilt(params, hist.pressure, tangential.mode_one_pressure).max(axis=1)
    alternative, sensitivity = (tangential.e_t, tangential.spin_change), 0.0
    if overlapping.any() and tangential.e_t is not None:
        other = resolve(overlapping)
        alternative = (other.e_t, other.spin_change)
        sensitivity = max(
            _relative(1.0 - tangential.e_t, 1.0 - other.e_t),
            _relative(tangential.spin_change, other.spin_change),
        )
    return SuperpositionValidity(
        sliding_amplitude=s,
        overlap=overlap,
        tilt=tilt,
        overlapping=overlapping,
        suction_overlap=float(overlap.max()),
        largest_tilt=float(tilt.max()),
        viscosity_tilt=thinning,
        largest_viscosity_tilt=float(thinning.max()),
        alternative=alternative,
        sensitivity=sensitivity,
        flagged=bool(
            sensitivity > SENSITIVITY_LIMIT or max(tilt.max(), thinning.max()) > TILT_LIMIT
        ),
    )


@dataclass(frozen=True)
class SuperpositionCheck:
    """The 2-D film against the superposition at one step (scaled; module docstring).

    ``moment``: int q R^2 dR of the superposition and (int P X dA of the 2-D film with the
    sliding, minus without) / (pi s), the same quantity of the 2-D film; ``slope``: int q
    Sigma0' R dR and (int P dSigma0/dX dA, with minus without) / (pi s); ``*_error`` the
    relative differences. ``lift``: the normal force the sliding adds in the 2-D film, over the
    normal force (second order in s; the decoupled model leaves it out). ``base_error``: the
    2-D film without sliding against P0 (max difference over max |P0|), its discretisation
    error. ``mesh_change``: how much the 2-D moment changes on a mesh twice as coarse (relative;
    a frozen film is ill-conditioned where the elasticity sets the pressure, and a check whose
    mesh change is not small against its error says nothing). ``overlap`` and ``tilt``: the
    indicators at the step; ``cavitated_vertices`` of the 2-D film with sliding."""

    step: int
    time: float
    sliding_amplitude: float
    moment: tuple[float, float]
    slope: tuple[float, float]
    moment_error: float
    slope_error: float
    lift: float
    base_error: float
    mesh_change: float
    overlap: float
    tilt: float
    cavitated_vertices: int


def check_superposition(
    result, steps=None, element_size: float | None = None, comm=None, amplitude=None
) -> list[SuperpositionCheck]:
    """Solve the 2-D film at ``steps`` of a sliding-film collision (a
    :class:`ehdfem.collision.CollisionResult`) and compare it with the superposition.

    ``steps``: indices of the normal solution's steps (None: the steps of the largest normal
    force, of the strongest suction, of the largest suction overlap and of the largest
    tangential force). ``element_size``: the disk mesh size at the centre, by sqrt(a x0)
    (None: R_edge / 200, growing four times to the edge). Thin layer only (the disk film has
    P = 0 at the wetted edge), a cavitation model that does not track the liquid in a cavity
    (the disk film's limit is the obstacle problem, without mass conservation); any viscosity
    law. ``amplitude``: the
    sliding amplitude of the 2-D film (None: the collision's s); at a smaller one the 2-D film
    must tend to the superposition, which tells its error from the discretisation's.
    ``comm``: the communicator of the disk mesh (None: MPI.COMM_WORLD)."""
    normal, tangential = result.normal, result.tangential
    params = normal.params
    if tangential is None or tangential.mode_one_pressure is None:
        raise checks.InputError("check_superposition needs an oblique tangential='lubrication'")
    if params.layer != "thin":
        raise checks.InputError("check_superposition needs layer = 'thin' (P = 0 at the edge)")
    if params.cavitation.tracks_liquid:
        raise checks.InputError(
            f"check_superposition needs a cavitation model that does not track the liquid, not "
            f"{params.cavitation.name!r} (the disk film's limit is not mass-conserving)"
        )
    validity = result.superposition
    if amplitude is not None:
        amplitude = checks.positive("amplitude", amplitude)
        validity = dataclasses.replace(validity, sliding_amplitude=amplitude)
    count = len(normal.history.time)
    if steps is None:
        steps = _default_steps(normal, tangential, validity)
    steps = [checks.integer("step", step, lower=1, upper=count - 1) for step in steps]
    return [_check_step(result, validity, step, element_size, comm) for step in steps]


def _default_steps(normal, tangential, validity):
    """The steps of the largest normal and tangential forces and, where there is suction, of
    the strongest suction and of the largest overlap."""
    hist = normal.history
    chosen = {int(np.argmax(hist.force)), int(np.argmax(np.abs(tangential.force)))}
    lowest = hist.pressure.min(axis=1)
    if lowest.min() < 0.0:
        chosen.add(int(np.argmin(lowest)))
    if validity.suction_overlap > 0.0:
        chosen.add(int(np.argmax(validity.overlap)))
    return sorted(max(step, 1) for step in chosen)


def _check_step(result, validity, step, element_size, comm) -> SuperpositionCheck:
    """One step of :func:`check_superposition`."""
    from .disk import solve_disk_film

    normal, tangential = result.normal, result.tangential
    params, hist = normal.params, normal.history
    film = normal_film(normal)
    mf = mode_one_film(normal, step, film)
    radii = normal.radii
    s = validity.sliding_amplitude
    q, gap1 = tangential.mode_one_pressure[step], tangential.mode_one_gap[step]
    rolling = tangential.velocity[step] + tangential.spin[step]
    pressure, thickness = hist.pressure[step], hist.film_thickness[step]
    # the rates the 1-D films satisfy at the step where they hold; elsewhere (cavitated or dry
    # nodes) the rates of the histories
    rate0 = np.gradient(hist.film_thickness, hist.time, axis=0)[step]
    state = film.assemble(thickness, pressure)
    holds = ~state.dry & ~cavitated_nodes(normal, step)
    rate0[holds] = -state.flux(pressure)[holds] / state.mass[holds]
    rate1 = np.gradient(tangential.mode_one_gap, hist.time, axis=0)[step]
    free = mf.free
    film_rows = tridiagonal_product(
        band_sum(mf.conductance, mf.pressure_coupling), q
    ) + tridiagonal_product(mf.thickness_coupling, gap1)
    rate1[free] = (0.5 * rolling * mf.drive[free] - film_rows[free]) / mf.mass[free]
    compliance_sum = getattr(result.compliance, "surface_sum_matrix", None)
    compliance_sum = None if compliance_sum is None else compliance_sum @ pressure
    surface_sum = film.gap.height(radii) + (0.0 if compliance_sum is None else compliance_sum)
    edge = float(hist.edge_radius[step])
    disk = {
        "edge_radius": edge,
        "p_cav": params.p_cav,
        "fluidity": _fluidity(film.viscosity),
        "surface_sum": surface_sum,
        "element_size": edge / 200 if element_size is None else element_size,
        "comm": comm,
    }
    mode_one = {
        "film_thickness_mode_one": s * gap1,
        "squeeze_rate_mode_one": s * rate1,
        "sliding": s * rolling,
    }
    base = solve_disk_film(radii, thickness, rate0, **disk)
    sliding = solve_disk_film(radii, thickness, rate0, **mode_one, **disk)
    disk["element_size"] *= 2
    coarse = [solve_disk_film(radii, thickness, rate0, **extra, **disk) for extra in ({}, mode_one)]
    moment = (
        float(mf.torque_weights @ q),
        (sliding.pressure_moment - base.pressure_moment) / (np.pi * s),
    )
    coarse_moment = (coarse[1].pressure_moment - coarse[0].pressure_moment) / (np.pi * s)
    slope = (
        float(mf.surface_slope_weights(compliance_sum) @ q),
        (sliding.slope_force - base.slope_force) / (np.pi * s),
    )
    wet = radii < edge
    return SuperpositionCheck(
        step=step,
        time=float(hist.time[step]),
        sliding_amplitude=s,
        moment=moment,
        slope=slope,
        moment_error=_relative(*moment),
        slope_error=_relative(*slope),
        lift=(sliding.normal_force - base.normal_force) / base.normal_force,
        base_error=float(
            np.abs(base.axisymmetric_pressure - pressure)[wet].max() / np.abs(pressure[wet]).max()
        ),
        mesh_change=_relative(moment[1], coarse_moment),
        overlap=float(validity.overlap[step]),
        tilt=float(validity.tilt[step]),
        cavitated_vertices=sliding.cavitated_nodes,
    )


def _relative(reference: float, value: float) -> float:
    return abs(value - reference) / abs(reference) if reference != 0.0 else math.inf


def _fluidity(viscosity):
    """mu0/mu of the UFL pressure for the disk film (None at constant viscosity)."""
    if viscosity.constant:
        return None
    import ufl

    return lambda pressure: ufl.exp(-viscosity.log_ratio(ufl.max_value(pressure, 0.0)))
