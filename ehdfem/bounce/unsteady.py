"""The unsteady forces on a sphere in flight near a wall: the added mass raised by the wall, and
the history (Basset) force with a finite-Reynolds-number kernel (docs/bounce.md).

SI unless said: gap h [m] between the sphere and the wall, sphere radius a [m], kinematic
viscosity nu [m^2/s], velocity v [m/s] (positive away from the wall). Scaled: the gap by a
(h/a), the time of the history kernel by the viscous time a^2/nu (s = nu t / a^2), the Reynolds
number Re = 2 a |v| / nu.

**Added mass near a wall.** In potential flow a sphere moving normal to a plane wall carries
the added mass C_M(h) m_f, m_f = rho_f 4/3 pi a^3, with (the sphere and its images in the wall,
Hicks 1880; Milne-Thomson, Theoretical Hydrodynamics, two spheres on their line of centres;
Kharlamov, Chara & Vlasak 2007)

    C_M(h) = 1/2 + (3/2) sum_{n>=2} (sinh alpha / sinh n alpha)^3,    cosh alpha = 1 + h/a,

1/2 far away (1/2 + (3/16)(a/(h + a))^3 + ...), (1 + 3 (zeta(3) - 1))/2 = 0.8031 at contact.
:func:`wall_added_mass` gives C_M(h) / (1/2) and its slope in h/a.

**History force.** F_H(t) = -6 pi mu a int_{-inf}^t K(t - tau) dv/dtau dtau with Mei & Adrian
(1992)'s kernel (their eq. 81, a the radius, f_H = 0.75 + 0.105 Re):

    K(t) = [ (pi nu t / a^2)^(1/4) + ((pi/2) |v|^3 t^2 / (a nu f_H^3))^(1/2) ]^(-2)
         = [ (pi s)^(1/4) + c(Re) s ]^(-2),     c(Re) = (sqrt(pi)/4) (Re / f_H)^(3/2),

which is Basset's a / sqrt(pi nu t) at short times and for Re -> 0 (c = 0), and decays as
(c s)^(-2) beyond s ~ (pi^(1/4)/c)^(4/3) (0.05 a^2/nu at Re = 150). c is taken at the current
Reynolds number Re(t): the vorticity shed earlier is carried away by the flow of the present
speed. The kernel is approximated by a sum of exponentials with fixed relaxation times
sigma_i (:data:`RELAXATION_TIMES`, 4 per decade from 1e-8 to 1e4 a^2/nu),

    K(s) ~ sum_i w_i(c) exp(-s / sigma_i),     F_H = -6 pi mu a sum_i w_i(c(t)) z_i,
    dz_i/dt = -z_i / tau_i + dv/dt,            tau_i = sigma_i a^2 / nu,

so that the whole trajectory's memory is carried by the z_i [m/s]. The weights are a fixed
linear map of the kernel's values (least squares with a Tikhonov term on the samples s = 1e-7..1e3,
relative to Basset's kernel): :func:`history_weights`. Their error (:func:`fitted_kernel`): below
2e-6 K_B(s) for 1e-7 <= s <= 1e3 and any Re, below 1e-5 of K itself for s <= 10 and 2e-4 for s <=
100 (where K falls to 1e-5 K_B at Re = 800); the sum is finite at s = 0 (a velocity jump's force is
cut below about 1e-7 a^2/nu, 0.02-0.1 us here; a contact lasts 1e-4 to 1e-3 a^2/nu) and decays
exponentially beyond s = 1e4 (2e3 to 1e4 s here, far beyond any bounce).

**The wall's history kernel** ("mei-adrian-wall"). Near a wall the unsteady Stokes kernel of a
sphere moving normal to it, K_h(s), is not Basset's: the wall takes up the momentum the liquid
carries away. :mod:`ehdfem.bounce.wall_flow` computes its Laplace transform by finite elements
at the gaps WALL_GAPS (studies/wall_history_kernel.py, the table WALL_TABLE); :func:`laplace_fit`
turns it into rho(s) = K_h(s) / K_B(s) (a sum of exponentials with non-negative weights: the
memory of the Stokes flow, whose operator with the wall is self-adjoint and positive, is
completely monotone), and Mei & Adrian's form is kept
with K_h in place of K_B,

    K(s) = [ K_h(s)^(-1/2) + c(Re) s ]^(-2),

taken at the current gap (:func:`wall_ratio`) and Reynolds number. At the table's smallest gap
rho = 1.12 at s = 1e-3, 0.67 at 0.01, 0.32 at 0.1 and 0.076 at 1: the kernel's integral is
finite (the wall takes up the momentum), and rho^ falls as k at small k.
"""

from __future__ import annotations

import json
import math
from functools import cache
from pathlib import Path

import numpy as np
from numba import njit
from scipy.optimize import nnls

from .. import checks
from ..motion.forces import memory_gains

HISTORY_KERNELS = ("mei-adrian", "mei-adrian-wall", "basset", "none")
RELAXATION_TIMES = np.logspace(-8.0, 4.0, 49)  # sigma_i by a^2 / nu
FIT_TIMES = np.logspace(-7.0, 3.0, 500)  # s where the sum of exponentials is fitted
FIT_REGULARISATION = 1e-8  # Tikhonov parameter of the fit (relative to the samples' scale)
CONTACT_ALPHA = 1e-3  # alpha below which C_M takes its value at alpha = 1e-3 (h/a < 5e-7)
ZETA3 = 1.2020569031595942  # Riemann zeta(3)
WALL_TABLE = Path(__file__).with_name("wall_kernel.json")  # studies/wall_history_kernel.py
WALL_GAPS = np.array([3e-3, 1e-2, 3e-2, 0.1, 0.3, 1.0, 3.0, 10.0])  # h/a of the table
WALL_K = np.logspace(-1.0, 2.0, 31)  # k = a sqrt(p / nu) of the table (s = 1e-4 to 100)
WALL_FAR = 1e3  # h/a from which the wall's effect on the kernel is left out
LAPLACE_P = np.logspace(-3.0, 7.0, 300)  # p = k^2 where the sum of exponentials is fitted
LAPLACE_SMOOTHING = 1e-3  # weight of the second differences of w_i sigma_i^(1/2) (laplace_fit)


def wall_added_mass(gap_over_radius: float) -> tuple[float, float]:
    """(C_M(h) / C_M(inf), its derivative in h/a) for a sphere moving normal to a plane wall
    in potential flow (module docstring): 1 + 3 sum_{n>=2} r_n^3, r_n = sinh alpha /
    sinh(n alpha), cosh alpha = 1 + h/a, summed in the overflow-free form
    r_n = 2 sinh(alpha) e^(-n alpha) / (1 - e^(-2 n alpha)) up to n alpha = 15 (the rest is
    below 1e-19 of the sum). d r_n / d alpha = r_n (coth alpha - n coth n alpha), d alpha /
    d(h/a) = 1 / sinh alpha. 1 + 3 (zeta(3) - 1) = 1.606 at contact."""
    checks.positive("gap_over_radius", gap_over_radius)
    return _image_sums(max(math.acosh(1.0 + gap_over_radius), CONTACT_ALPHA))


@njit(cache=True)
def _image_sums(alpha: float) -> tuple[float, float]:
    """:func:`wall_added_mass` at cosh alpha = 1 + h/a, compiled (a flight asks for it at every
    evaluation of its forces): the terms from the last to the first, the smallest first."""
    sinh, coth = math.sinh(alpha), 1.0 / math.tanh(alpha)
    mass = slope = 0.0
    for i in range(int(15.0 / alpha) + 2, 1, -1):
        n = float(i)
        decay = math.exp(-2.0 * n * alpha)
        ratio = 2.0 * sinh * math.exp(-n * alpha) / (1.0 - decay)
        cube = ratio**3
        mass += cube
        slope += 3.0 * cube * (coth - n * (1.0 + decay) / (1.0 - decay)) / sinh
    return 1.0 + 3.0 * mass, 3.0 * slope


def kernel_decay(reynolds):
    """c(Re) = (sqrt(pi)/4) (Re / f_H)^(3/2), f_H = 0.75 + 0.105 Re (Mei & Adrian 1992): the
    finite-Re kernel's long-time term c s (dimensionless; 0 at Re = 0, 13.0 as Re -> inf)."""
    reynolds = np.abs(np.asarray(reynolds, dtype=float))
    return math.sqrt(math.pi) / 4.0 * (reynolds / (0.75 + 0.105 * reynolds)) ** 1.5


def history_kernel(scaled_time, reynolds):
    """K(s) = [(pi s)^(1/4) + c(Re) s]^(-2) at s = nu t / a^2 > 0 (module docstring);
    Basset's 1 / sqrt(pi s) at Re = 0."""
    s = np.asarray(scaled_time, dtype=float)
    return ((math.pi * s) ** 0.25 + kernel_decay(reynolds) * s) ** -2


@cache
def _fit_map() -> np.ndarray:
    """The linear map from K(FIT_TIMES) / K_B(FIT_TIMES) to the weights w_i: the Tikhonov-
    regularised least-squares solution of sum_i w_i e^(-s/sigma_i) = K(s), rows by K_B(s)."""
    design = np.exp(-FIT_TIMES[:, None] / RELAXATION_TIMES[None, :]) / _basset_samples()[:, None]
    u, singular, vt = np.linalg.svd(design, full_matrices=False)
    filtered = singular / (singular**2 + FIT_REGULARISATION**2)
    return vt.T @ (filtered[:, None] * u.T)


@cache
def _basset_samples() -> np.ndarray:
    """Basset's kernel K_B = 1 / sqrt(pi s) at FIT_TIMES."""
    return history_kernel(FIT_TIMES, 0.0)


def history_weights(kernel: str, reynolds: float, gap_over_radius: float = math.inf) -> np.ndarray:
    """The weights w_i of the exponentials exp(-s / sigma_i) (:data:`RELAXATION_TIMES`) that
    sum to the history kernel ``kernel`` at the Reynolds number ``reynolds`` and, for
    "mei-adrian-wall", the gap h/a ``gap_over_radius`` ("basset": Re ignored; "mei-adrian";
    "none": no weights)."""
    checks.choice("history", kernel, HISTORY_KERNELS)
    if kernel == "none":
        return np.zeros(0)
    if kernel == "basset":
        return _fit_map().sum(axis=1)
    # K / K_B = (rho^(-1/2) + c s / (pi s)^(1/4))^-2, (pi s)^(-1/4) = sqrt(K_B), rho = K_h / K_B
    wall = 1.0 if kernel == "mei-adrian" else wall_ratio(gap_over_radius)
    decay = kernel_decay(reynolds) * FIT_TIMES * np.sqrt(_basset_samples())
    return _fit_map() @ (wall**-0.5 + decay) ** -2


def laplace_fit(k, ratio) -> np.ndarray:
    """rho(s) = K_h(s) / K_B(s) at FIT_TIMES of the completely monotone kernel K_h whose
    Laplace transform is p K_h^(p) = k rho^(k) (p = k^2; ``ratio`` rho^ at the increasing ``k``):
    the sum of exponentials sum_i w_i exp(-s / sigma_i) with weights w_i = q_i sigma_i^(-1/2)
    >= 0 (Basset's kernel has q_i nearly constant) whose transform sum_i w_i p sigma_i / (1 + p
    sigma_i) matches k rho^ relative to k at LAPLACE_P, the q_i's second differences weighted by
    LAPLACE_SMOOTHING (non-negative least squares: positivity regularises the inversion, which
    stays ill-conditioned). Beyond the largest k, rho^ is held at its last value; below the
    smallest it follows the power of k of the two smallest (rho^ ~ k when the kernel's integral
    is finite, as with a wall; constant for Basset's). rho^ = 1 gives Basset's kernel within
    0.5 % for 1e-6 <= s <= 100 (tested)."""
    k, ratio = np.asarray(k, dtype=float), np.asarray(ratio, dtype=float)
    root = np.sqrt(LAPLACE_P)
    power = np.clip(np.log(ratio[1] / ratio[0]) / np.log(k[1] / k[0]), 0.0, 1.0)
    target = np.where(
        root < k[0],
        ratio[0] * (root / k[0]) ** power,
        np.interp(np.log(root), np.log(k), ratio),
    )
    scale = RELAXATION_TIMES**-0.5
    transforms = (
        LAPLACE_P[:, None] * RELAXATION_TIMES / (1.0 + LAPLACE_P[:, None] * RELAXATION_TIMES)
    )
    design = transforms * scale / root[:, None]
    smoothing = LAPLACE_SMOOTHING * np.diff(np.eye(len(scale)), 2, axis=0)
    factors, _ = nnls(
        np.vstack([design, smoothing]), np.concatenate([target, np.zeros(len(smoothing))])
    )
    kernel = np.exp(-FIT_TIMES[:, None] / RELAXATION_TIMES) @ (factors * scale)
    return kernel / _basset_samples()


@cache
def _wall_ratios() -> tuple[np.ndarray, np.ndarray]:
    """(ln h/a of the table, rho(s) at FIT_TIMES for each): the table of
    studies/wall_history_kernel.py through :func:`laplace_fit`, floored at 1e-6."""
    table = json.loads(WALL_TABLE.read_text())
    ratios = [np.maximum(laplace_fit(table["k"], row), 1e-6) for row in table["ratio"]]
    return np.log(table["gaps"]), np.array(ratios)


def wall_ratio(gap_over_radius: float) -> np.ndarray:
    """rho(s) = K_h(s) / K_B(s) at FIT_TIMES: the unsteady Stokes history kernel of a sphere at
    the gap h/a (studies/wall_history_kernel.py) over Basset's, linear in ln h between the
    table's gaps and the smallest gap's below them. Beyond the largest gap (10 a) the wall's
    steady drag 9/(8 (1 + h/a)) (its first reflection) acts at once while Basset's memory is
    unchanged, K_h = K_B - 9/(8 (1 + h/a)), not below the 10 a kernel; 1 from WALL_FAR on."""
    if gap_over_radius >= WALL_FAR:  # also no wall at all (inf)
        return np.ones(len(FIT_TIMES))
    checks.positive("gap_over_radius", gap_over_radius)
    gaps, ratios = _wall_ratios()
    x = max(math.log(gap_over_radius), gaps[0])
    if x >= gaps[-1]:
        steady = 9.0 / (8.0 * (1.0 + gap_over_radius))
        return np.maximum(1.0 - steady / _basset_samples(), ratios[-1])
    i = min(int(np.searchsorted(gaps, x, side="right")) - 1, len(gaps) - 2)
    share = (x - gaps[i]) / (gaps[i + 1] - gaps[i])
    return (1.0 - share) * ratios[i] + share * ratios[i + 1]


def fitted_kernel(scaled_time, kernel: str, reynolds: float):
    """The sum of exponentials sum_i w_i exp(-s / sigma_i) that stands for the kernel (the
    error of the approximation is in the module docstring)."""
    s = np.atleast_1d(np.asarray(scaled_time, dtype=float))
    weights = history_weights(kernel, reynolds)
    return np.exp(-s[:, None] / RELAXATION_TIMES[None, : len(weights)]) @ weights


def carry_memory(memory, times, velocities, relaxation_times) -> np.ndarray:
    """The memory z_i [m/s] at each of ``times`` [s] of a motion known by samples: from
    ``memory`` at times[0], dz_i/dt = -z_i / tau_i + dv/dt integrated exactly for v linear
    between samples,

        z_i(t_k+1) = z_i(t_k) e^(-dt/tau_i) + (v_k+1 - v_k) (tau_i / dt)(1 - e^(-dt/tau_i)),

    a jump (dt = 0) adding v_k+1 - v_k (:func:`ehdfem.motion.forces.memory_gains`, which the
    film model's history force uses too). ``relaxation_times``: tau_i [s]. Returns an array
    (len(times), len(memory)); the history force is -6 pi mu a sum_i w_i z_i."""
    z = np.array(memory, dtype=float)
    out = [z.copy()]
    for k in range(len(times) - 1):
        decay, gain = memory_gains(times[k + 1] - times[k], relaxation_times)
        z = z * decay + (velocities[k + 1] - velocities[k]) * gain
        out.append(z.copy())
    return np.array(out)
