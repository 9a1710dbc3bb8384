"""The sliding film (tangential model "lubrication"): the linear differential-algebraic system
in (q, v, U, a Omega) over the normal solution's steps, its mode-1 deformation and its energy
balance (:mod:`ehdfem.tangential.motion` gives the equations, docs/tangential.md derives
them), and the checks that its linearisation holds. For two free spheres (:class:`FilmBodies`)
the same system in (q, v, U, s1, s2): the film driven by the entrainment rho U + s1 - s2, rho
times the undeformed slope in the force, a torque row for each sphere (docs/tangential.md,
"Two spheres").
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.integrate

from ..film.elements import add_band_rows, tridiagonal_rows
from ..film.mode_one import ModeOneFilm, band_sum
from ..film.reynolds import Film, tridiagonal_product
from ..motion.normal import NormalSolverError
from ..motion.reusable_lu import ReusableLU, SingularMatrix
from ..solids.compliance import ModeOneCompliance
from .friction import CoulombContact
from .normal_film import mode_one_films
from .result import TangentialEnergy, TangentialResult, initial_spin, tangential_result

_BDF2_GROWTH = 1.0 + np.sqrt(2.0)  # largest step ratio for which variable-step BDF2 is stable


BREAKDOWN_TILT = 1.0  # a linearisation tilt (gap_tilt, viscosity_tilt) at which it fails


class SlidingFilmError(NormalSolverError):
    """The sliding film's linearisation broke down: a tilt (:func:`gap_tilt`,
    :func:`viscosity_tilt`) reached BREAKDOWN_TILT or its linear system had no finite solution.
    Where this happens (a film frozen by a pressure-dependent viscosity, docs/tangential.md)
    only the Couette model applies."""


@dataclass(frozen=True)
class FilmBodies:
    """The bodies the sliding film moves, as its equations need them: ``inertia`` the weights
    of the motion (U, spins) in the kinetic energy by the mass m ((1, k) for a sphere on a
    wall with its spin a Omega; (1, k1 (1 + m1/m2), k2 (1 + m2/m1)) for two spheres with
    s1 = a1 Omega1, s2 = a2 Omega2 and the reduced mass, docs/tangential.md "Two spheres"),
    and ``rho`` = (a2 - a1)/(a1 + a2) (1 on a wall): the factor of the undeformed surfaces'
    slope in the force and of U in the entrainment."""

    inertia: tuple
    rho: float = 1.0

    @property
    def sliding(self) -> np.ndarray:
        """The slip u_s on the motion: (1, -1) or (1, -1, -1)."""
        return np.r_[1.0, -np.ones(len(self.inertia) - 1)]

    @property
    def entrainment(self) -> np.ndarray:
        """The entrainment w on the motion: U + a Omega (1, 1) on a wall, w_pair = rho U +
        s1 - s2 (rho, 1, -1) for two spheres."""
        return np.array([self.rho, 1.0, -1.0][: len(self.inertia)])

    @property
    def arms(self) -> np.ndarray:
        """Each spin's torque over its radius is -F + arm (P + (2/5) delta tail w), P the
        pressure's x-force (delta/6) int q R^2 dR: (-1,) on a wall, (-(1 + rho)/2,
        (1 - rho)/2) for two spheres (a/a1 and a/a2 of P, on each undeformed sphere)."""
        return np.array([-(1.0 + self.rho) / 2.0, (1.0 - self.rho) / 2.0][: len(self.inertia) - 1])

    @property
    def shares(self) -> np.ndarray:
        """Each spin's share of a change of the contact spin by an impulse at the contact
        point: (1/weight_i) / sum_j (1/weight_j) (1 on a wall)."""
        inverse = 1.0 / np.asarray(self.inertia[1:], dtype=float)
        return inverse / inverse.sum()


def sliding_amplitude(params) -> float:
    """s = (U0/V0) sqrt(delta): the factor of the mode-1 pressure q and gap H1 (scaled)."""
    return params.tangential_speed * np.sqrt(params.delta)


def gap_tilt(params, film_thickness, mode_one_gap):
    """s |H1| / H0 at the wetted nodes (0 elsewhere; H by x0, any leading shape): the mode-1
    gap against the film thickness it is superposed on; at 1 the film closes on one side."""
    wet = film_thickness < 1.0 if params.layer == "thin" else np.ones(film_thickness.shape, bool)
    return np.where(wet, sliding_amplitude(params) * np.abs(mode_one_gap) / film_thickness, 0.0)


def viscosity_tilt(params, pressure, mode_one_pressure):
    """s |q| d ln(mu/mu0)/dP at P0 (pressures by mu V0 a / x0^2, any leading shape): the change of
    ln mu the mode-1 pressure makes, which the sliding film linearises (mu = mu(P0)
    (1 + s q cos(phi) d ln mu/dP)); 0 at constant viscosity, and at 1 exp differs from its
    linearisation by a factor e/2."""
    slope = params.viscosity_law().ratio(pressure)[1]
    return sliding_amplitude(params) * np.abs(mode_one_pressure) * slope


class SlidingFilm:
    """The lubrication model's linear system over the normal solution's steps.

    Unknowns z = (q, v_r, v_phi, U, a Omega) at a step (v only with deformation "full"; else
    the nodal slip is u_s); for two spheres (``bodies``, :class:`FilmBodies`; None: a sphere on
    a wall) (q, v_r, v_phi, U, s1, s2) from ``start`` (1, s1(0), s2(0)), with the entrainment
    w_pair in the film, rho times the undeformed slope in the force and a torque row for each
    sphere. Loads on the solids L = (q, a_r, a_phi), the Couette traction
    a = -(j / m) v on the sphere (m the lumped mass, j the Couette weights; by mu U0 / x0,
    i.e. (U0/V0) sqrt(delta) times the traction unit of the mode-1 compliance) and -a on the
    wall. Relative displacements of the faces: the gap H1, the sum Sigma1 and the tangential
    D = (D_r, D_phi) of sphere minus wall, each the compliance times L. ``outer``: the
    constant resistance delta dR (2, 2) of the flow beyond the film's integrals on
    (U, a Omega), in the force and torque rows and the dissipation (None: left out;
    :mod:`ehdfem.tangential.outer_film`)."""

    def __init__(
        self, normal, mode_one, surface_sum, deformation, outer=None, bodies=None, start=None
    ):
        params = normal.params
        self.normal, self.deformation = normal, deformation
        self.outer = outer  # delta dR on (U, a Omega), the flow beyond the film (None: none)
        self.St, self.delta = params.St, params.delta
        self.bodies = FilmBodies((1.0, params.inertia_factor)) if bodies is None else bodies
        n = self.n = len(normal.radii)
        self.mass_full = Film(normal.radii).full_mass
        self.u = n + (2 * n if deformation == "full" else 0)  # then the spins
        self.size = self.u + len(self.bodies.inertia)
        self.motion = np.arange(self.u, self.size)  # (U, spins) in z
        # the motion at impact (by U0): (1, a Omega0 / U0) on a wall, ``start`` for two spheres
        self.start = np.r_[1.0, initial_spin(params)] if start is None else np.asarray(start)
        self.states = None  # z at the steps, once solved
        # (N, 3N) face combinations of the loads L: gap and sum of the normal displacements,
        # and with "full" the relative tangential ones (r, phi); zero for rigid mode-1 solids
        deformed = mode_one is not None and deformation != "none"
        combinations = {"gap": ("normal", (1.0, -1.0)), "sum": ("normal", (1.0, 1.0))}
        if deformation == "full":
            combinations.update(r=("radial", (1.0, -1.0)), phi=("hoop", (1.0, -1.0)))
        self.compliance = {
            name: _face_combination(mode_one, *combination) if deformed else np.zeros((n, 3 * n))
            for name, combination in combinations.items()
        }
        self.compliance.setdefault("r", None)
        self.compliance.setdefault("phi", None)
        self.surface_sum = surface_sum
        # the rows on z that do not change with the step: the nodal slips (v_r, v_phi), and
        # each face displacement's pressure columns (its traction columns are rewritten at
        # every step, :meth:`_operators`)
        self._slips = tuple(self._slip_rows(component) for component in range(2))
        self._slip_sum = self._slips[0] + self._slips[1]
        self._displacement_rows = {
            name: self._pressure_rows(c) for name, c in self.compliance.items() if c is not None
        }

    def _slip_rows(self, component: int) -> np.ndarray:
        """The nodal slip velocity v_r (``component`` 0) or v_phi (1) as rows on z: v itself
        with deformation "full", else the slip u_s at every node."""
        n, size = self.n, self.size
        if self.deformation == "full":
            rows = np.zeros((n, size))
            rows[:, n * (1 + component) : n * (2 + component)] = np.eye(n)
            return rows
        sliding = np.zeros(size)
        sliding[self.motion] = self.bodies.sliding
        return np.outer(np.ones(n), sliding)

    def _pressure_rows(self, compliance: np.ndarray) -> np.ndarray:
        """Rows on z of a face displacement, compliance (n, 3n) @ L, with its pressure columns
        filled (the traction's are filled at each step)."""
        rows = np.zeros((self.n, self.size))
        rows[:, : self.n] = compliance[:, : self.n]
        return rows

    def solve(self, unloaded=None) -> TangentialResult:
        """Step through the normal solution; the tangential result with its energy balance
        (``unloaded``: further nodes with q = 0, as for :func:`mode_one_films`)."""
        normal, n = self.normal, self.n
        hist = normal.history
        steps = len(hist.time)
        z = np.zeros((steps, self.size))
        z[0, self.motion] = self.start
        z[0, n : self.u] = self.bodies.sliding @ z[0, self.motion]  # v = u_s (nothing deformed)
        displacements = {name: np.zeros((steps, n)) for name in ("gap", "r", "phi")}
        shear, force = np.zeros(steps), np.zeros(steps)
        rates = np.zeros((steps, 2))  # dissipation and exchange rates
        elastic = np.zeros(steps)
        contact = CoulombContact.of(normal)
        for i, mf in enumerate(mode_one_films(normal, unloaded)):
            shear[i] = mf.shear_weights.sum() + mf.tail
            ops = self._operators(mf, i)
            if i > 0:
                step = hist.time[i] - hist.time[i - 1]
                ratio = np.inf  # BDF1 on the first step and after the solid impact's jump
                if i >= 2 and not (contact is not None and contact.is_impact(i - 1)):
                    ratio = step / (hist.time[i - 1] - hist.time[i - 2])
                alpha = (1.0, -1.0, 0.0)  # BDF1
                if ratio <= _BDF2_GROWTH:
                    alpha = ((1 + 2 * ratio) / (1 + ratio), -(1 + ratio), ratio**2 / (1 + ratio))
                past = {
                    name: (alpha[1] * values[i - 1] + alpha[2] * values[i - 2]) / step
                    for name, values in (*displacements.items(), ("z", z))
                }
                z[i] = self._step(mf, ops, alpha[0] / step, past, i, contact)
                for name, values in displacements.items():
                    if ops[name] is not None:
                        values[i] = ops[name] @ z[i]
                self._check_tilts(z[i], displacements["gap"][i], i)
                if contact is not None and contact.is_impact(i):
                    self._impact_acts(contact, z[i], i)
            force[i] = ops["force"] @ z[i]
            *rates[i], elastic[i] = self._energy_terms(mf, ops, z[i], i, displacements)
        self.states = z
        motion = z[:, self.motion]
        velocity = motion[:, 0]
        spin = motion[:, 1:].sum(axis=1)  # a Omega, or the contact spin s1 + s2
        kinetic = 0.5 * self.St * (motion**2 @ np.asarray(self.bodies.inertia))
        dissipated, exchanged = scipy.integrate.cumulative_trapezoid(
            rates, hist.time, axis=0, initial=0.0
        ).T
        friction = np.zeros(steps) if contact is None else contact.record().dissipated
        lost = max(kinetic[0] - kinetic[-1], dissipated[-1] + friction[-1], np.finfo(float).tiny)
        residual = kinetic[0] - kinetic[-1] - dissipated[-1] - elastic[-1] + exchanged[-1]
        residual -= friction[-1]
        balance = abs(residual) / lost
        energy = TangentialEnergy(kinetic, dissipated, elastic, exchanged, friction, balance)
        return tangential_result(
            normal,
            "lubrication",
            self.deformation,
            (velocity, spin, shear, force),
            energy,
            (z[:, :n], displacements["gap"]),
            contact=contact,
        )

    def _impact_acts(self, contact: CoulombContact, z: np.ndarray, i: int) -> None:
        """The solid impact's Coulomb impulse at step i on U and the contact spin in z (in
        place; its change shared between the spins); with deformation "full" the nodal slips
        v = u_s + sqrt(delta) dD/dT change by the same jump of u_s (the faces' displacements D
        do not jump)."""
        sliding, spins = self.bodies.sliding, z[self.motion[1:]]
        slip = sliding @ z[self.motion]
        velocity, spin = contact.act(i, z[self.u], spins.sum(), load=False)
        z[self.u] = velocity
        z[self.motion[1:]] = spins + self.bodies.shares * (spin - spins.sum())
        if self.deformation == "full":
            z[self.n : self.u] += sliding @ z[self.motion] - slip

    def _step(self, mf: ModeOneFilm, ops: dict, rate: float, past: dict, i: int, contact=None):
        """z at step i (:meth:`_system`), or SlidingFilmError if it has no finite solution;
        with the asperities' friction force of ``contact`` (a :class:`CoulombContact`; None:
        none) in the rows of U and a Omega (St dU/dT = F + F_f, k St d(a Omega)/dT = T - F_f)."""
        try:
            matrix, rhs = self._system(mf, ops, rate, past)
            if contact is None or contact.force_bounds[i] == 0.0:
                z = _solve_equilibrated(matrix, rhs, self.motion)
            else:
                unit = np.zeros(self.size)
                unit[self.motion] = self.bodies.sliding  # a force at the contact point
                rhs = np.column_stack([rhs, unit])
                free, response = _solve_equilibrated(matrix, rhs, self.motion).T
                slips = [self.bodies.sliding @ y[self.motion] for y in (free, response)]
                z = free + contact.resist(i, *slips) * response
        except (np.linalg.LinAlgError, ValueError):
            z = np.full(self.size, np.nan)
        if not np.isfinite(z).all():
            raise SlidingFilmError(
                f"the sliding film has no finite solution at T = {self.normal.history.time[i]:.4g}"
                f" (mu/mu0 up to {self._viscosity_ratio(i):.3g}); use tangential = 'couette'"
            )
        return z

    def _check_tilts(self, z: np.ndarray, mode_one_gap: np.ndarray, i: int) -> None:
        """SlidingFilmError where a tilt of the linearisation reaches BREAKDOWN_TILT at step i."""
        params, hist = self.normal.params, self.normal.history
        tilts = {
            "s |H1| / H0": gap_tilt(params, hist.film_thickness[i], mode_one_gap),
            "s |q| d ln(mu)/dP": viscosity_tilt(params, hist.pressure[i], z[: self.n]),
        }
        for name, tilt in tilts.items():
            if tilt.max() >= BREAKDOWN_TILT:
                raise SlidingFilmError(
                    f"the sliding film's linearisation broke down at T = {hist.time[i]:.4g}:"
                    f" {name} = {tilt.max():.3g} >= {BREAKDOWN_TILT} (mu/mu0 up to"
                    f" {self._viscosity_ratio(i):.3g}); the film is not a small perturbation"
                    " of the normal one (a film frozen by the pressure-dependent viscosity,"
                    " docs/tangential.md); use tangential = 'couette'"
                )

    def _viscosity_ratio(self, i: int) -> float:
        """The largest mu/mu0 of the normal film at step i."""
        law = self.normal.params.viscosity_law()
        return float(law.ratio(self.normal.history.pressure[i])[0].max())

    def _operators(self, mf: ModeOneFilm, i: int) -> dict:
        """Row operators on z at step i: q, the Couette weights, the loads L, the face
        displacements (gap, sum, r, phi), the force and the torque."""
        n, size, delta, bodies = self.n, self.size, self.delta, self.bodies
        full = self.deformation == "full"
        rolling, sliding = np.zeros(size), np.zeros(size)
        rolling[self.motion], sliding[self.motion] = bodies.entrainment, bodies.sliding
        traction = -mf.shear_weights / self.mass_full  # a = traction * v, by mu U0 / x0

        def displacement(name):  # compliance (n, 3n) @ L as rows on z (kept, the step's traction)
            compliance, rows = self.compliance[name], self._displacement_rows.get(name)
            if compliance is None:
                return None
            motion = np.zeros((n, len(self.motion)))
            for component in range(2):
                block = compliance[:, n * (1 + component) : n * (2 + component)]
                if full:
                    rows[:, n * (1 + component) : n * (2 + component)] = block * traction
                else:  # the traction of the slip u_s: a column on each of U and the spins
                    motion += np.outer(block @ traction, bodies.sliding)
            rows[:, self.motion] = motion
            return rows

        ops = {"slip_r": self._slips[0], "slip_phi": self._slips[1]}
        ops.update({name: displacement(name) for name in self.compliance})
        surface_sum = None
        if self.surface_sum is not None:
            surface_sum = self.surface_sum @ self.normal.history.pressure[i]
        slope_weights = mf.surface_slope_weights(surface_sum)
        if bodies.rho != 1.0:  # rho times the undeformed surfaces' slope, the deformed one's kept
            slope_weights = slope_weights - (1.0 - bodies.rho) * mf.surface_slope_weights()
        gradient_weights = mf.gradient_weights()
        force = (delta / 12.0) * (gradient_weights @ ops["sum"])
        force[:n] -= (delta / 12.0) * slope_weights
        force -= (delta / 6.0) * (mf.shear_weights @ self._slip_sum)
        force -= (delta / 3.0) * mf.tail * (sliding + 0.6 * bodies.rho * rolling)
        pressure = 0.4 * delta * mf.tail * rolling  # P: the pressure's x-force, tail and film
        pressure[:n] += (delta / 6.0) * mf.torque_weights
        torques = [-force + arm * pressure for arm in bodies.arms]
        if self.outer is not None:  # the flow beyond the film: force and torque over a
            force[self.motion] -= self.outer[0]
            torques[0][self.motion] -= self.outer[1]
        ops.update(
            force=force,
            torques=torques,
            gradient_weights=gradient_weights,
            rolling=rolling,
            sliding=sliding,
            traction=traction,
            slope_weights=slope_weights,
        )
        return ops

    def _system(self, mf: ModeOneFilm, ops: dict, rate: float, past: dict):
        """The step's matrix and right-hand side; d/dT of Y is rate Y + past[Y]."""
        n, size = self.n, self.size
        matrix, rhs = np.zeros((size, size)), np.zeros(size)
        free = np.flatnonzero(mf.free)
        gap = ops["gap"]
        rows = tridiagonal_rows(mf.thickness_coupling, gap, free)
        add_band_rows(band_sum(mf.conductance, mf.pressure_coupling), free, rows)
        rows += rate * mf.mass[free, None] * gap[free]
        rows -= 0.5 * np.outer(mf.drive[free], ops["rolling"])
        matrix[free] = rows
        rhs[free] = -mf.mass[free] * past["gap"][free]
        fixed = np.flatnonzero(~mf.free)
        matrix[fixed, fixed] = 1.0
        if self.deformation == "full":
            root = np.sqrt(self.delta)
            for component, name in enumerate(("r", "phi")):
                block = slice(n * (1 + component), n * (2 + component))
                matrix[block] = ops["slip_" + name] - np.outer(np.ones(n), ops["sliding"])
                matrix[block] -= root * rate * ops[name]
                rhs[block] = root * past[name]
        for row, load, weight in zip(
            self.motion, (ops["force"], *ops["torques"]), self.bodies.inertia, strict=True
        ):  # St weight d(U or spin)/dT = force or torque over the radius
            matrix[row] = -load
            matrix[row, row] += weight * self.St * rate
            rhs[row] = -weight * self.St * past["z"][row]
        return matrix, rhs

    def _energy_terms(self, mf: ModeOneFilm, ops: dict, z: np.ndarray, i: int, displacements):
        """(dissipation rate, exchange rate X, elastic energy) at a step (module docstring)."""
        n, delta = self.n, self.delta
        q = z[:n]
        u_s, w = ops["sliding"] @ z, ops["rolling"] @ z
        v_r, v_phi = ops["slip_r"] @ z, ops["slip_phi"] @ z
        h1 = displacements["gap"][i]
        sigma1 = ops["sum"] @ z
        dissipation = (delta / 6.0) * (
            mf.shear_weights @ (v_r**2 + v_phi**2) + q @ tridiagonal_product(mf.conductance, q)
        )
        dissipation += delta * mf.tail * (u_s**2 / 3.0 + w**2 / 5.0)
        if self.outer is not None:
            motion = z[self.motion]
            dissipation += motion @ self.outer @ motion
        pressure_force = (delta / 12.0) * (
            ops["gradient_weights"] @ sigma1 - ops["slope_weights"] @ q
        )
        rho = self.bodies.rho  # the power of the pressure on the spheres (docs/tangential.md)
        exchange = u_s * (pressure_force + rho * (delta / 12.0) * (mf.torque_weights @ q))
        exchange -= (delta / 6.0) * (
            q @ tridiagonal_product(mf.thickness_coupling, h1)
            + q @ tridiagonal_product(mf.pressure_coupling, q)
        )
        exchange += (delta / 12.0) * w * ((mf.drive - mf.torque_weights) @ q)
        work = self.mass_full @ (q * h1)
        if self.deformation == "full":
            loads = ops["traction"] * np.stack([v_r, v_phi])
            shifts = np.stack([displacements["r"][i], displacements["phi"][i]])
            work += np.sqrt(delta) * (self.mass_full * loads * shifts).sum()
        return dissipation, exchange, (delta / 12.0) * work


def _solve_equilibrated(matrix, rhs, motion):
    """Solve matrix z = rhs (``rhs`` a vector, or one right-hand side per column) in the
    unknowns y = z except the slip U - a Omega (U - s1 - s2) in place of U (``motion``: the
    indices of U and the spins), by the Newton matrix's LU (:class:`ReusableLU`: every column of
    the transformed matrix and then every row scaled by a power of two to a largest entry in
    [1/2, 1), exactly). A piezoviscous film's Reynolds rows are smaller than the others by
    mu/mu0 (up to 1e30 and more), and its Couette traction makes the columns of the slip
    velocities larger by as much: the unscaled rows of U and a Omega are then parallel to
    round-off (the film locks the sphere into rolling), the scaled system is not."""
    u, spins = motion[0], motion[1:]
    transformed = matrix.copy()  # matrix @ B, B = I + e_u sum e_spin^T: z_U = u_s + spins
    transformed[:, spins] += matrix[:, [u]]
    nothing = np.zeros(len(matrix), bool)
    try:
        y = ReusableLU(transformed, nothing, nothing).solve(rhs, nothing, None)
    except SingularMatrix as err:
        raise np.linalg.LinAlgError(f"sliding-film matrix: {err}") from err
    y[u] += y[spins].sum(axis=0)  # back from y to z = B y
    return y


def _face_combination(mode_one: ModeOneCompliance, component: str, signs) -> np.ndarray:
    """(N, 3N): sign_s (sphere) + sign_w (wall) of a displacement ``component`` ("normal",
    "radial", "hoop") under the loads L = (q, a_r, a_phi): the pressure q on both faces, the
    traction (a_r, a_phi) on the sphere and its opposite on the wall."""
    blocks = []
    for loads in (("pressure",), ("sphere_radial", "wall_radial"), ("sphere_hoop", "wall_hoop")):
        total = 0.0
        for face, sign in zip(("sphere", "wall"), signs, strict=True):
            for load, load_sign in zip(loads, (1.0, -1.0), strict=False):
                total = total + sign * load_sign * mode_one.block(f"{face}_{component}", load)
        blocks.append(total)
    return np.hstack(blocks)
