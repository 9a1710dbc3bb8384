"""The oblique impact of an elastic sphere with tangential compliance (Maw, Barber & Fawcett
1976, 1981): the Hertz normal impact and the limits of its tangential rebound that are known
without solving the whole stick-slip history.

Variables of the impact (docs/tangential.md, "Tangential compliance of the solid contact"): the
normal indentation d by its largest value d_m, xi = d / d_m; time by d_m / v (v the normal
approach speed), tau; the contact point's tangential velocity over v, psi, and in MBF's form
Psi = kappa psi / mu, with kappa = k_t / k_n the contact's tangential over normal stiffness
(Mindlin: k_t = 8 G* a_c, k_n = 2 E* a_c, kappa = 4 G*/E* = 2 (1 - nu)/(2 - nu) for identical
solids) and chi = kappa (1 + 1/k) / 2 (MBF's parameter, (1 - nu)/(2 - nu) (1 + 1/k); 1.441 for a
solid sphere, k = 2/5, with nu = 0.3).

- **Hertz compression**: (1/2) m v^2 = (8/15) E* R^(1/2) d_m^(5/2) and xi'' = -(5/4) xi^(3/2),
  xi'(0) = 1, so xi' = (1 - xi^(5/2))^(1/2) and

      tau(xi) = int_0^xi (1 - s^(5/2))^(-1/2) ds = xi 2F1(1/2, 2/5; 7/5; xi^(5/2)),

  which reaches xi = 1 at tau_c = Gamma(7/5) Gamma(1/2) / Gamma(9/10) = 1.4716.
- **Restitution e**: the contact retraces its loads in time, e times as fast (the stiffer
  unloading of Walton & Braun 1986 for a Hertz contact): xi(tau_c + s) = xi(tau_c - s / e), so
  the normal impulse is 1 + e (by m v) and the contact radius a = (R d)^(1/2) stays Hertz's.
  MBF's impact is e = 1.
- **Tangential motion** (the method of dimensionality reduction of Popov & Hess 2015, exact for
  Mindlin & Deresiewicz's tangential contact of an axisymmetric body under any history): the
  contact is a row of springs at X (by a_m = (R d_m)^(1/2)) with tangential displacement sigma(X)
  (by mu d_m / kappa), each stuck to the contact's displacement W (sigma' = W') unless
  |sigma| reaches xi - X^2 (Coulomb, with the normal spring xi - X^2), and

      W'' = -(15/4) chi int_0^(xi^(1/2)) sigma dX,      W'(0) = Psi_1.

Limits, exact:

- **Complete adhesion** (Psi_1 -> 0, Jaeger 1994: the slip near the receding edge vanishes with
  Psi_1): every spring entered at tau_e(X) holds sigma = W(tau) - W(tau_e), so
  int sigma dX = xi^(1/2) W - M with M' = W(tau_e) (xi^(1/2))', a delay equation solved here with
  a tight adaptive integrator (:func:`adhesive_ratio`): Psi_2 = r Psi_1, r = -beta_0 of
  Walton's law (:mod:`ehdfem.exact.walton_impact`).
- **Gross slip throughout**: every spring at its limit, W'' = -2 chi xi'' (the normal load's
  impulse, 1 - xi' while compressing, 1 + e q while unloading, xi' = -q/e), so
  Psi_2 = Psi_1 - 2 chi (1 + e) (the rigid-body Coulomb impact) as long as no spring sticks,
  W' >= xi' throughout: Psi_1 >= 2 chi - xi' (2 chi - 1) while compressing and
  Psi_1 >= 2 chi + q (2 chi e - 1/e) while unloading, so Psi_1 >= max(1, 2 chi,
  2 chi (1 + e) - 1/e) (:func:`gross_slip_threshold`; MBF: Psi_1 >= 4 chi - 1 for e = 1 and
  2 chi >= 1, where Psi_2 = -1).
- **chi = 1/2, e = 1**: the tangential springs obey the normal ones' equation (the normal spring
  of X is xi(tau) - xi(tau_e), as sigma = W - W(tau_e) under adhesion), so W = Psi_1 xi sticks
  throughout for Psi_1 <= 1 (|sigma| = Psi_1 (xi - X^2)): Psi_2 = -Psi_1 exactly, and above 1
  the contact slides throughout: the whole curve is known (:func:`half_chi_rebound`).
- **Initial stick**: the edge springs stick at entry iff W' <= xi', Psi_1 <= 1.

Between the limits (partial slip, the reversal) MBF's equations are solved here independently of
the law (:func:`entry_time_rebound`: another discretisation in space and time, the springs laid
down exactly at the moving edge and the implicit trapezoidal rule), as the reference of its
whole curve.
"""

from __future__ import annotations

import math

import numpy as np
import scipy.integrate
import scipy.optimize
import scipy.special

COMPRESSION_TIME = math.gamma(1.4) * math.gamma(0.5) / math.gamma(0.9)  # tau_c = tau(xi = 1)
BISECTIONS = 60  # halvings of [0, 1]: xi to 1e-18


def approach_time(xi):
    """tau(xi) of the Hertz compression (module docstring): the time (by d_m / v) at which the
    indentation reaches xi d_m, xi 2F1(1/2, 2/5; 7/5; xi^(5/2)) (arrays broadcast)."""
    xi = np.asarray(xi, dtype=float)
    return xi * scipy.special.hyp2f1(0.5, 0.4, 1.4, xi**2.5)


def indentation(tau):
    """xi(tau), the Hertz compression's indentation (by d_m) at tau (by d_m / v) in
    [0, tau_c]: :func:`approach_time` inverted by bisection (it rises monotonically)."""
    tau = np.asarray(tau, dtype=float)
    low, high = np.zeros_like(tau), np.ones_like(tau)
    for _ in range(BISECTIONS):
        middle = 0.5 * (low + high)
        below = approach_time(middle) < tau
        low, high = np.where(below, middle, low), np.where(below, high, middle)
    return 0.5 * (low + high)


def impact_parameter(stiffness_ratio: float, k: float) -> float:
    """MBF's chi = kappa (1 + 1/k) / 2 for the contact's tangential over normal stiffness
    kappa = k_t / k_n and the sphere's inertia factor k = I / (m a^2)."""
    return 0.5 * stiffness_ratio * (1.0 + 1.0 / k)


def gross_slip_threshold(chi: float, e_n: float) -> float:
    """The smallest Psi_1 for which the contact slides throughout: max(1, 2 chi,
    2 chi (1 + e) - 1/e) (module docstring; 4 chi - 1 for MBF's e = 1 and 2 chi >= 1)."""
    return max(1.0, 2.0 * chi, 2.0 * chi * (1.0 + e_n) - 1.0 / e_n)


def gross_slip_rebound(psi_in, chi: float, e_n: float):
    """Psi_2 = Psi_1 - 2 chi (1 + e) of a contact sliding throughout (Psi_1 at or above
    :func:`gross_slip_threshold`): the rigid-body Coulomb impact in MBF's variables."""
    return np.asarray(psi_in, dtype=float) - 2.0 * chi * (1.0 + e_n)


def half_chi_rebound(psi_in):
    """Psi_2 of the elastic impact (e = 1) at chi = 1/2 for every Psi_1 >= 0 (module
    docstring): -Psi_1 up to 1, Psi_1 - 2 above."""
    psi_in = np.asarray(psi_in, dtype=float)
    return np.where(psi_in <= 1.0, -psi_in, psi_in - 2.0)


def _compression_rate(tau, state, chi):
    """d/dtau of (xi, xi', W, W', M) while the contact grows (complete adhesion): xi'' =
    -(5/4) xi^(3/2), W'' = -(15/4) chi (xi^(1/2) W - M), M' = W xi' / (2 xi^(1/2)) (the
    entering spring takes the contact's displacement)."""
    xi, xi_rate, displacement, velocity, memory = state
    radius = math.sqrt(max(xi, 0.0))
    force = radius * displacement - memory
    return [
        xi_rate,
        -1.25 * max(xi, 0.0) ** 1.5,
        velocity,
        -3.75 * chi * force,
        displacement * xi_rate / (2.0 * radius),
    ]


def _restitution_rate(tau, state, chi, e_n, compression):
    """d/dtau of (W, W', M) while the contact shrinks: the contact retraces the compression's
    state at tau_e = tau_c - (tau - tau_c) / e (``compression``'s dense output), and the leaving
    spring, which entered at tau_e, takes W(tau_e) with it: M' = W(tau_e) (xi^(1/2))'."""
    entry = COMPRESSION_TIME - (tau - COMPRESSION_TIME) / e_n
    xi, xi_rate, entry_displacement, _, _ = compression(entry)
    displacement, velocity, memory = state
    radius = math.sqrt(max(xi, 0.0))
    force = radius * displacement - memory
    radius_rate = -xi_rate / (2.0 * e_n * radius)
    return [velocity, -3.75 * chi * force, entry_displacement * radius_rate]


def adhesive_ratio(chi: float, e_n: float = 1.0, rtol: float = 1e-11) -> float:
    """r = Psi_2 / Psi_1 in the limit of complete adhesion (Psi_1 -> 0; module docstring),
    for MBF's chi and the restitution e in (0, 1]: the delay equation integrated by DOP853 at
    ``rtol``, the compression from its series start at tau0 (xi = tau, W = tau,
    M = tau^(3/2)/3 for Psi_1 = 1, errors of order tau0^(5/2)), then the restitution with the
    compression's state and W at each leaving spring's entry time from its dense output, up to
    tau0 before the contact ends (where W', the rebound, has stopped changing to order tau0)."""
    tau0 = 1e-10
    options = dict(method="DOP853", rtol=rtol, atol=rtol * 1e-3)
    start = [tau0, 1.0, tau0, 1.0, tau0**1.5 / 3.0]
    compression = scipy.integrate.solve_ivp(
        _compression_rate, (tau0, COMPRESSION_TIME), start, args=(chi,), dense_output=True,
        **options,
    )  # fmt: skip
    end = COMPRESSION_TIME * (1.0 + e_n) - e_n * tau0
    restitution = scipy.integrate.solve_ivp(
        _restitution_rate, (COMPRESSION_TIME, end), compression.y[2:, -1],
        args=(chi, e_n, compression.sol), **options,
    )  # fmt: skip
    return float(restitution.y[1, -1])


def _trapezoid_step(state, step, limits, weights, c):
    """One implicit trapezoidal step of (W, W', sigma) (:func:`entry_time_rebound`): the
    increment dW = (step/2)(W'_old + W'_new) solves dW = step W'_old - (step^2/4) c
    (F_old + F(dW)), F(dW) = sum w sigma(dW), sigma(dW) = clip(sigma + dW, -limits, limits); the
    left side less the right rises strictly with dW, so its root is bracketed and unique."""
    displacement, velocity, sigma = state
    force_old = weights @ sigma

    def residual(increment):
        force = weights @ np.clip(sigma + increment, -limits, limits)
        return increment - step * velocity + 0.25 * step**2 * c * (force_old + force)

    reach = step * abs(velocity) + 0.25 * step**2 * c * (abs(force_old) + weights @ limits)
    reach = 2.0 * reach + 1e-300  # |root| <= reach: the bracket holds with room
    increment = scipy.optimize.brentq(residual, -reach, reach, xtol=1e-16)
    sigma = np.clip(sigma + increment, -limits, limits)
    force = weights @ sigma
    velocity = velocity - 0.5 * step * c * (force_old + force)
    return displacement + increment, velocity, sigma


def entry_time_rebound(psi_in: float, chi: float, e_n: float, steps: int = 1000) -> float:
    """Psi_out of MBF's impact for Psi_in, chi and e (module docstring), by a solution
    independent of the law's (:mod:`ehdfem.tangential.compliant_contact`): the springs are
    laid down at the contact's edge, one per compression step, over [a(tau_j), a(tau_j+1)]
    (weight its width, normal spring xi - X^2 at its midpoint), so the edge is followed exactly
    and they leave in the reverse order; the motion is advanced by the implicit trapezoidal
    rule (second order where it is smooth), each step's increment the root of its monotone
    equation. ``steps`` steps per phase."""
    compression = np.linspace(0.0, COMPRESSION_TIME, steps + 1)
    xi = indentation(compression)
    xi[0] = 0.0
    edges = np.sqrt(xi)
    weights, middle = np.diff(edges), 0.5 * (edges[1:] + edges[:-1])
    times = np.concatenate([compression, COMPRESSION_TIME + e_n * compression[1:]])
    path = np.concatenate([xi, xi[-2::-1]])
    c = 3.75 * chi
    state = (0.0, float(psi_in), np.zeros(steps))
    for i in range(1, len(times)):
        limits = np.maximum(path[i] - middle**2, 0.0)
        state = _trapezoid_step(state, times[i] - times[i - 1], limits, weights, c)
    return float(state[1])
