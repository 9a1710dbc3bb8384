"""The normal solution's film as the tangential models read it, step by step: the film, its
cavitated nodes, its mode-1 operators and the Couette integral J (scales of
:mod:`ehdfem.tangential.motion`).
"""

from __future__ import annotations

import numpy as np

from ..film.mode_one import ModeOneFilm, mode_one_operators
from ..film.reynolds import Film
from ..motion.normal import NormalResult


def normal_film(normal: NormalResult) -> Film:
    """The film of the normal solution (its nodes, layer, viscosity law and gap)."""
    params = normal.params
    return Film(normal.radii, params.layer, params.viscosity_law(), normal.gap)


def cavitated_nodes(normal: NormalResult, step: int) -> np.ndarray:
    """Where the normal solution's film is cavitated at ``step`` (boolean, per node): P0 at the
    cavitation limit, or a liquid fraction below 1."""
    hist = normal.history
    p_cav = normal.params.p_cav
    at_limit = p_cav + 1e-12 * abs(p_cav) if np.isfinite(p_cav) else -np.inf
    return (hist.fill[step] < 1.0) | (hist.pressure[step] <= at_limit)


def mode_one_film(
    normal: NormalResult, step: int, film: Film | None = None, unloaded=None
) -> ModeOneFilm:
    """The film's mode-1 operators (:class:`ehdfem.film.mode_one.ModeOneFilm`) at one step of the
    normal solution, with the viscosity at that step's pressure, its liquid fraction and q = 0
    at its cavitated nodes and at the nodes ``unloaded`` (boolean; None: none). ``film``:
    :func:`normal_film`, if built already."""
    film = normal_film(normal) if film is None else film
    cavitated = cavitated_nodes(normal, step)
    if unloaded is not None:
        cavitated = cavitated | unloaded
    hist = normal.history
    outer = 1.0 / np.sqrt(normal.params.delta)
    return mode_one_operators(
        film,
        hist.film_thickness[step],
        outer,
        hist.pressure[step],
        hist.fill[step],
        cavitated,
    )


def mode_one_films(normal: NormalResult, unloaded=None):
    """:func:`mode_one_film` at each step of the normal solution, in order (``unloaded``:
    (steps, N) boolean, more nodes with q = 0 at each step; None: none)."""
    film = normal_film(normal)
    for step in range(len(normal.history.time)):
        yield mode_one_film(normal, step, film, None if unloaded is None else unloaded[step])


def film_integrals(normal: NormalResult) -> np.ndarray:
    """The Couette integral J(T) at the steps of the normal solution (immersed: with the far
    field out to the sphere's radius)."""
    film, outer = normal_film(normal), 1.0 / np.sqrt(normal.params.delta)
    hist = normal.history
    shear = []
    for h, p, theta in zip(hist.film_thickness, hist.pressure, hist.fill, strict=True):
        weights, tail = film.couette_weights(h, outer, p, theta)
        shear.append(weights.sum() + tail)
    return np.array(shear)
