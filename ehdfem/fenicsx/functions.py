"""Finite-element functions and constants: made, read, written, interpolated and evaluated at
points."""

from __future__ import annotations

import numpy as np

from .libraries import fem, load, petsc
from .spaces import interpolation_points, owned_dof_count


def function(space, name: str | None = None):
    """A finite-element function on ``space``, zero (``name`` labels it in exported files)."""
    module = fem()
    return module.Function(space) if name is None else module.Function(space, name=name)


def constant(mesh, value: float):
    """A constant on ``mesh`` whose value can be changed between solves
    (:func:`set_constant`)."""
    return fem().Constant(mesh, petsc().ScalarType(value))


def set_constant(constant, value: float) -> None:
    """Give the :func:`constant` ``constant`` the value ``value`` (for the next assembly)."""
    constant.value = value


def expression(ufl_expression, space):
    """``ufl_expression`` compiled for interpolation into ``space`` (:func:`interpolate`)."""
    return fem().Expression(ufl_expression, interpolation_points(space))


def space_of(function):
    """The space ``function`` lives in."""
    return function.function_space


def local_values(function) -> np.ndarray:
    """The values of ``function`` at this rank's dofs (owned, then ghosts; the components of a
    dof together): the function's own array, so that writing into it sets the function (write
    the same values on every rank that holds a dof, or :func:`set_owned_values`)."""
    return function.x.array


def owned_values(function) -> np.ndarray:
    """The values of ``function`` at the dofs this rank owns (a view of
    :func:`local_values`)."""
    return function.x.array[: owned_dof_count(function.function_space)]


def set_owned_values(function, values: np.ndarray) -> None:
    """Set the values of ``function`` at the first ``len(values)`` local entries (the owned
    ones, as :func:`owned_values` orders them) and send them to the ranks that hold them as
    ghosts."""
    function.x.array[: len(values)] = values
    function.x.scatter_forward()


def interpolate(function, source, cells=None) -> None:
    """Interpolate ``source`` into ``function``: a callable of the points x (3, n) giving the
    values (components, n), a function on another space of the same mesh, or an
    :func:`expression`; only on the local ``cells`` when given (the other values are kept)."""
    if cells is None:
        function.interpolate(source)
    else:
        function.interpolate(source, cells)


def petsc_vector(function):
    """The PETSc vector that holds the values of ``function`` (a solver writes into it).

    0.5: ``function.vector``; ``function.x.petsc_vec`` from 0.8, where ``.vector`` is deprecated
    (and removed in 0.10).
    """
    return function.x.petsc_vec if hasattr(function.x, "petsc_vec") else function.vector


def point_values(function, points: np.ndarray):
    """(values, found) of the scalar ``function`` at ``points`` (n, 3) on this rank: the value
    at each point inside a local cell (owned or ghost) and the mask of those points (0
    elsewhere).

    0.5: ``geometry.BoundingBoxTree(mesh, dim)`` and ``geometry.compute_collisions(tree,
    points)``; 0.7+: ``geometry.bb_tree(mesh, dim)`` and ``compute_collisions_points``.
    """
    geometry = load("dolfinx.geometry")
    mesh = function.function_space.mesh
    if hasattr(geometry, "bb_tree"):
        tree = geometry.bb_tree(mesh, mesh.topology.dim)
        candidates = geometry.compute_collisions_points(tree, points)
    else:
        tree = geometry.BoundingBoxTree(mesh, mesh.topology.dim)
        candidates = geometry.compute_collisions(tree, points)
    colliding = geometry.compute_colliding_cells(mesh, candidates, points)
    offsets = colliding.offsets
    found = offsets[1:] > offsets[:-1]
    values = np.zeros(len(points))
    if found.any():
        cells = colliding.array[offsets[np.flatnonzero(found)]]
        values[found] = function.eval(points[found], cells)[:, 0]
    return values, found
