"""The undeformed gap between the two surfaces: the theory's paraboloid or the true spheres.

In film units (gap and film thickness by x0, radius R by sqrt(a x0), delta = x0 / a with a the
(reduced) sphere radius) the film thickness is

    H(R, T) = X(T) + S(R) + W(R, T),

with S the height of the two undeformed surfaces above their closest points, summed (a gap
class gives S, with its slope dS/dR (``profile``), and S minus its chord between nodes with
that difference's slope):

- ``paraboloid`` (the asymptotic theory): S = R^2 / 2;
- ``exact``: each sphere of radius rho a (rho by a; a flat wall or coating contributes 0) adds
  (rho - sqrt(rho^2 - delta R^2)) / delta = R^2 / (rho + sqrt(rho^2 - delta R^2)), so for a
  sphere on a wall S = R^2/2 + delta R^4/8 + O(delta^2 R^6), and for two spheres
  (1/rho_1 + 1/rho_2 = 1) S = R^2/2 + delta R^4 (rho_1^-3 + rho_2^-3)/8 + ...

Either way the film stays a thin film normal to the wall: the Reynolds equation keeps its flat
form (the surface slope dS/dR = O(sqrt(delta) R) is neglected in the flow, and so are the
curvature terms; see docs/model.md). The film's elements take S exactly between their nodes:
``between_nodes`` is S minus its linear interpolant at points of an element.

The choice of gap is a component of the inputs (:mod:`ehdfem.settings`), registered in
:data:`GAPS`: a frozen dataclass with its ``name``, whether it holds in a thin layer only
(``thin_layer_only``: the immersed film's far field assumes the paraboloid) and ``shape(delta,
surface_radii)``, the gap above for the solids' surfaces. A new gap (a worn sphere, say) is one
shape class here and one such component. ``CollisionParameters.gap`` None leaves the choice to
the solids (:func:`default_gap`: the order in delta they are computed at).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar, Protocol

import numpy as np
from numba import njit

from .. import checks
from ..settings import Registry


class Paraboloid:
    """S = R^2 / 2 (the asymptotic theory)."""

    name = "paraboloid"

    @classmethod
    def of(cls, delta: float, surface_radii=(1.0, math.inf)) -> Paraboloid:
        """The paraboloid: delta and the surfaces' radii do not enter."""
        return cls()

    def height(self, radius):
        """S(R) by x0 at R by sqrt(a x0)."""
        return 0.5 * radius**2

    def profile(self, radius):
        """(S, dS/dR) at R (by x0 and sqrt(x0/a), R by sqrt(a x0))."""
        return 0.5 * radius**2, radius

    def between_nodes(self, left, length, xi):
        """S(left + xi L) minus the linear interpolant of S between left and left + L, for the
        elements (left, length) at the points xi in [0, 1]: -xi (1 - xi) L^2 / 2."""
        return -0.5 * (xi * (1.0 - xi)) * length[:, None] ** 2

    def slope_between_nodes(self, left, length, xi):
        """dS/dR at left + xi L minus the element's chord slope: -(1 - 2 xi) L / 2."""
        return -(1 - 2 * xi) * length[:, None] / 2


class ExactSpheres(Paraboloid):
    """S for true spheres of radii ``radii`` (by a; math.inf for a flat wall) at delta = x0/a
    (module docstring). The paraboloid part is kept in closed form and only the remainder
    D = S - R^2/2 (of order delta R^4) is interpolated, so no precision is lost to cancellation."""

    name = "exact"

    @classmethod
    def of(cls, delta: float, surface_radii=(1.0, math.inf)) -> ExactSpheres:
        """The true spheres at delta = x0/a with the surfaces' radii by a."""
        return cls(delta, surface_radii)

    def __init__(self, delta: float, radii=(1.0, math.inf)):
        self.delta = checks.number("delta", delta, lower=0.0, upper=1.0, lower_open=True)
        self.radii = [checks.positive("surface radius", r) for r in radii if not math.isinf(r)]
        self.limit = min(self.radii) / math.sqrt(self.delta)  # the smaller sphere's equator
        # the spheres' radii and their squares, as the compiled loops take them
        self._spheres = (np.array([r**2 for r in self.radii]), np.array(self.radii), self.delta)

    def _within(self, largest: float) -> None:
        """Refuse a film that reaches ``largest`` (R by sqrt(a x0)) at or beyond the smaller
        sphere's equator, where the gap has no value."""
        if largest >= self.limit:
            raise checks.InputError(
                f"the film reaches R = {largest:.4g} sqrt(a x0), beyond the "
                f"sphere's equator at {self.limit:.4g}: no exact gap there"
            )

    def _remainder(self, radius):
        """D = S - R^2/2 and dD/dR (at a float R or an array of them; a float is the wetted
        edge's Newton's, some ten times an iterate), by :func:`_sphere_remainder`."""
        if isinstance(radius, float):
            self._within(radius)
            return _sphere_remainder(radius, *self._spheres)
        self._within(float(np.max(radius, initial=-math.inf)))
        value, slope = _sphere_remainders(np.ravel(radius), *self._spheres)
        return value.reshape(np.shape(radius)), slope.reshape(np.shape(radius))

    def height(self, radius):
        return 0.5 * radius**2 + self._remainder(radius)[0]

    def profile(self, radius):
        value, slope = self._remainder(radius)
        return 0.5 * radius**2 + value, radius + slope

    def between_nodes(self, left, length, xi):
        """The paraboloid's S minus its chord (:meth:`Paraboloid.between_nodes`) plus D minus its
        chord, in one compiled loop (:func:`_sphere_between_nodes`): the film's cut element
        asks for one element at every iterate, where numpy's calls cost 15 us."""
        self._within(float(np.max(left + length, initial=-math.inf)))
        return _sphere_between_nodes(left, length, xi, *self._spheres)

    def slope_between_nodes(self, left, length, xi):
        (d_left, d_right, _), (_, _, slope) = self._at_points(left, length, xi)
        chord = ((d_right - d_left) / length)[:, None]
        return super().slope_between_nodes(left, length, xi) + slope - chord

    def _at_points(self, left, length, xi):
        """(D, dD/dR), each as (at the left ends, at the right ends, at the points xi of the
        elements (left, length)), from one evaluation of :meth:`_remainder`."""
        points = left[:, None] + length[:, None] * xi
        every = np.concatenate([left, left + length, points.ravel()])
        m = len(left)
        return tuple(
            (values[:m], values[m : 2 * m], values[2 * m :].reshape(points.shape))
            for values in self._remainder(every)
        )


@njit(cache=True, error_model="numpy")
def _sphere_remainder(radius, squares, radii, delta):
    """(D, dD/dR) at one R (by sqrt(a x0)): D = sum_rho R^2 / (rho + sqrt(rho^2 - delta R^2)) -
    R^2 / 2 over the spheres' radii rho (by a; ``squares`` their squares), the exact gap's
    excess over the paraboloid (module docstring)."""
    square = radius * radius
    value, slope = -0.5 * square, -radius
    for k in range(len(radii)):
        root = math.sqrt(squares[k] - delta * square)
        value = value + square / (radii[k] + root)
        slope = slope + radius / root
    return value, slope


@njit(cache=True, error_model="numpy")
def _sphere_remainders(radius, squares, radii, delta):
    """:func:`_sphere_remainder` at each R of the 1-D array ``radius``: (D, dD/dR)."""
    value, slope = np.empty(len(radius)), np.empty(len(radius))
    for i in range(len(radius)):
        value[i], slope[i] = _sphere_remainder(radius[i], squares, radii, delta)
    return value, slope


@njit(cache=True, error_model="numpy")
def _sphere_between_nodes(left, length, xi, squares, radii, delta):
    """S minus its chord at the points xi of the elements (left, length) for the true spheres:
    -xi (1 - xi) L^2 / 2 (the paraboloid's) plus D(left + xi L) minus D's chord
    (:func:`_sphere_remainder`), (elements, points)."""
    out = np.empty((len(left), len(xi)))
    for e in range(len(left)):
        d_left = _sphere_remainder(left[e], squares, radii, delta)[0]
        d_right = _sphere_remainder(left[e] + length[e], squares, radii, delta)[0]
        for j in range(len(xi)):
            inside = _sphere_remainder(left[e] + length[e] * xi[j], squares, radii, delta)[0]
            parabolic = -0.5 * (xi[j] * (1.0 - xi[j])) * (length[e] * length[e])
            chord = d_left * (1.0 - xi[j]) + d_right * xi[j]
            out[e, j] = parabolic + inside - chord
    return out


class GapChoice(Protocol):
    """What a collision asks of its choice of gap: ``name``, ``thin_layer_only`` and
    ``shape(delta, surface_radii)``: the gap (:class:`Paraboloid` or a subclass) for delta =
    x0/a and the surfaces' radii by a (the sphere's, then the lower body's: math.inf for a
    wall)."""

    name: ClassVar[str]
    thin_layer_only: ClassVar[bool]

    def shape(self, delta: float, surface_radii) -> Paraboloid: ...


GAPS = Registry("gap", GapChoice)  # the choices of gap by name


class ShapeOfGap:
    """The members every built-in choice of gap shares (a base of their frozen dataclasses):
    its ``name`` is that of its shape class ``gap_class``, which builds the gap."""

    gap_class: ClassVar[type]

    def shape(self, delta: float, surface_radii=(1.0, math.inf)) -> Paraboloid:
        """The gap ``gap_class.of(delta, surface_radii)`` (delta = x0/a, radii by a)."""
        return self.gap_class.of(delta, surface_radii)


@GAPS.register
@dataclass(frozen=True)
class ParaboloidGap(ShapeOfGap):
    """The asymptotic theory's gap S = R^2 / 2 (:class:`Paraboloid`), whatever the surfaces."""

    gap_class: ClassVar[type] = Paraboloid
    name: ClassVar[str] = Paraboloid.name
    thin_layer_only: ClassVar[bool] = False


@GAPS.register
@dataclass(frozen=True)
class ExactGap(ShapeOfGap):
    """The true spheres' gap (:class:`ExactSpheres`); a thin layer only."""

    gap_class: ClassVar[type] = ExactSpheres
    name: ClassVar[str] = ExactSpheres.name
    thin_layer_only: ClassVar[bool] = True


def default_gap(model: str, layer: str) -> GapChoice:
    """The gap a collision uses when none is asked for (docs/architecture.md, "Inputs of the
    physics and numerics"): the true spheres for the FE model with a thin layer (the FE
    solids are true spheres, at finite delta), the paraboloid otherwise (the asymptotic
    theory, the leading order in delta; the immersed far field needs it)."""
    return ExactGap() if model == "fem" and layer == "thin" else ParaboloidGap()
