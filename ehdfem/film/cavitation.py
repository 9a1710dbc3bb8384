"""Cavitation models: how far the film pressure may fall below ambient, and where the liquid goes.

The pressure P is scaled by mu V0 a / x0^2 and P_cav = (p_cav - p_ambient) x0^2 / (mu V0 a) <= 0
is the suction the liquid can hold (-inf: no limit). Three models, each a component
(:mod:`ehdfem.settings`: a frozen dataclass with its name and its scaled P_cav, the members of
:class:`CavitationModel`, registered in :data:`MODELS`), whose ``solver()`` gives the object the
implicit step (:mod:`ehdfem.motion.implicit_step`) uses on every Newton iterate:

- :class:`NoCavitation` (or any model with P_cav = -inf): unlimited suction; the
  Reynolds equation holds at every wet node.
- :class:`Truncation` (the source's model): P >= P_cav as a complementarity with
  the Reynolds residual r = m dH/dT + K P: at a cavitated node P = P_cav and the film would need
  r >= 0 there; the semismooth-Newton active set is min(P - P_cav, r / s) = 0 with s the
  residual's diagonal sensitivity. Liquid in the cavity is neither tracked nor conserved.
- :class:`MassConserving` (Jakobsson-Floberg-Olsson, Elrod-Adams p-theta
  form): the liquid fraction theta in [0, 1] of the gap is an unknown and everywhere

      d(theta H)/dT = (1 / (12 R)) d/dR (R H^3 dP/dR),
      P - P_cav >= 0,   1 - theta >= 0,   (P - P_cav)(1 - theta) = 0,

  so a cavity (theta < 1, P = P_cav) keeps its liquid and refills only with liquid that flows
  in. The node unknown is theta at cavitated nodes (a column swap in the Newton matrix).

Per Newton iterate the step calls, in order: ``wet`` (after the film is assembled),
``limit`` (on the Reynolds residual), ``fixed_nodes`` and ``theta_nodes`` (which rows and
columns of the Newton matrix change) and ``switch`` (after the update).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar, Protocol

import numpy as np

from .. import checks
from ..settings import Registry, setting

NO_LIMIT = -math.inf  # P_cav of a film without a cavitation limit


def suction_limit(value) -> float:
    """P_cav checked: -inf (no limit) or a finite number <= 0 (scaled by mu V0 a / x0^2)."""
    if isinstance(value, float) and value == NO_LIMIT:
        return NO_LIMIT
    return checks.number("p_cav", value, upper=0.0)


def parse_suction_limit(value) -> float:
    """P_cav from a command line or study file: None, "none" or "-inf" mean no limit."""
    return NO_LIMIT if value is None or value in ("none", "-inf") else suction_limit(value)


def suction_limit_output(p_cav: float) -> float | None:
    """P_cav for JSON and tables: None when there is no limit."""
    return None if p_cav == NO_LIMIT else p_cav


class CavitationModel(Protocol):
    """A cavitation model as an input (scaled): ``name``, its flat name; ``p_cav``, the suction
    limit P_cav (-inf: none); ``tracks_liquid``, whether a cavity keeps its liquid (the disk
    film's obstacle limit cannot stand for such a model); ``solver()``, a new object with the
    per-iterate methods of :class:`Unlimited` for one film; ``with_limit(p_cav)`` (a
    classmethod), the model with the limit P_cav, physical inputs' route to it."""

    name: ClassVar[str]
    tracks_liquid: ClassVar[bool]
    p_cav: float

    def solver(self): ...
    def with_limit(cls, p_cav: float): ...


MODELS = Registry("cavitation", CavitationModel)  # the cavitation models by name

P_CAV = {
    "help": "cavitation pressure (p_cav - p_ambient), <= 0 (none: no limit)",
    "unit": "by mu V0 a / x0^2",
    "default_text": "none",
    "checked": False,
    "read": parse_suction_limit,
    "write": suction_limit_output,
}


def has_limit(name: str) -> bool:
    """Whether the cavitation model ``name`` holds the pressure at a suction limit when given
    one (a model that ignores the limit has unlimited suction)."""
    return MODELS[name].with_limit(-1.0).p_cav != NO_LIMIT


class Unlimited:
    """Unlimited suction: no node is ever held at a cavitation pressure. The per-iterate
    methods every model's solver has (module docstring)."""

    p_cav = NO_LIMIT
    tracks_liquid = False

    def start(self, fill, cavitated):
        """(theta, cavitated) at the start of a step's Newton iteration: a full film."""
        return np.ones_like(fill), np.zeros(len(cavitated), bool)

    def wet(self, fill, cavitated, dry):
        """(theta, cavitated) once the wetted edge of the iterate is known."""
        return fill, cavitated

    def limit(self, residual, pressure, cavitated, dry, sensitivity):
        """The cavitated nodes for this iterate; may overwrite their rows of ``residual``.
        ``sensitivity()`` gives the residual's diagonal derivative by P at every node."""
        return np.zeros(len(dry), bool)

    def fixed_nodes(self, dry, cavitated):
        """Nodes whose Newton row is an identity (P prescribed)."""
        return dry | cavitated

    def theta_nodes(self, cavitated):
        """Nodes whose unknown is the liquid fraction theta instead of P."""
        return np.zeros(len(cavitated), bool)

    def switch(self, pressure, fill, cavitated, dry, stiffness):
        """(P, theta, cavitated) after a Newton update; ``stiffness()`` is the pressure that
        balances a unit change of theta in each node's equation."""
        return pressure, fill, cavitated


class TruncationSolver(Unlimited):
    """P >= P_cav by a semismooth-Newton active set (module docstring); P_cav scaled.

    The active set frees a cavitated node only once its neighbour's pressure has risen, so a
    cavity that the film refills over many nodes in one step would shrink by one node per
    Newton iterate. While it does, the release reaches further into the cavity, twice as far at
    each iterate (1, 2, 4, ... nodes beyond the freed one); a node freed too far falls below
    P_cav in the next solve and is held again, and from then on the step's iteration frees
    node by node. The converged set satisfies the same complementarity either way: the reach
    only shortens the path to it.
    """

    def __init__(self, p_cav: float):
        self.p_cav = p_cav
        self._reach = None  # None: the step's first iterate, -1: node by node

    def start(self, fill, cavitated):
        self._reach = None
        return super().start(fill, cavitated)

    def limit(self, residual, pressure, cavitated, dry, sensitivity):
        scale = sensitivity()
        scale = np.where(scale > 0, scale, 1.0)
        held = (pressure - self.p_cav < residual / scale) & ~dry
        if self._reach is None:
            self._reach = 0
        elif self._reach >= 0:
            held = self._reach_into(cavitated, held)
        residual[held] = pressure[held] - self.p_cav
        return held

    def _reach_into(self, previous, held):
        """``held`` with the release of nodes freed at a cavity's edge carried further into
        the cavity (class docstring); the reach stops for the step once a node is held again."""
        if (held & ~previous).any():  # a node freed too far (or a new cavity): node by node
            self._reach = -1
            return held
        freed = np.flatnonzero(previous & ~held)
        if len(freed) == 0:
            return held
        self._reach = max(1, 2 * self._reach)
        held = held.copy()
        n = len(held)
        for node in freed:
            for side in (1, -1):
                k = node + side
                for _ in range(self._reach):
                    if not (0 <= k < n and held[k]):
                        break
                    held[k] = False
                    k += side
        return held


class MassConservingSolver(Unlimited):
    """JFO cavitation in the Elrod-Adams p-theta form (module docstring); P_cav scaled."""

    tracks_liquid = True

    def __init__(self, p_cav: float):
        self.p_cav = p_cav

    def start(self, fill, cavitated):
        return fill, cavitated

    def wet(self, fill, cavitated, dry):
        """A cavity the wetted edge passed over is dry, not cavitated."""
        return np.where(dry, 1.0, fill), cavitated & ~dry

    def limit(self, residual, pressure, cavitated, dry, sensitivity):
        return cavitated

    def fixed_nodes(self, dry, cavitated):
        return dry

    def theta_nodes(self, cavitated):
        return cavitated

    def switch(self, pressure, fill, cavitated, dry, stiffness):
        """The Elrod-Adams switch. The node unknown is read as one universal variable u,
        P = P_cav + u (full film, u >= 0) or theta = 1 + u / s (cavity, u < 0), with s the
        stiffness (> 0 at wet nodes). A full node whose pressure fell below P_cav ruptures and a
        cavity whose theta passed 1 refills, the overshoot carried over to the other variable:
        the semismooth Newton for min(P - P_cav, s (1 - theta)) = 0, which does not cycle at
        nodes where both vanish."""
        stiffness = stiffness()
        u = np.where(cavitated, (fill - 1.0) * stiffness, pressure - self.p_cav)
        cavitated = (u < 0.0) & ~dry
        pressure = np.where(cavitated, self.p_cav, np.where(dry, pressure, self.p_cav + u))
        fill = np.ones_like(fill)
        fill[cavitated] = np.maximum(1.0 + u[cavitated] / stiffness[cavitated], 0.0)
        return pressure, fill, cavitated


@dataclass(frozen=True)
class LimitedSuction:
    """What the models with a suction limit share (a base of their frozen dataclasses): the
    scaled limit P_cav (-inf, the default: none), checked when made, and ``solver()``, a new
    ``limited_solver`` at P_cav, or :class:`Unlimited` without a limit."""

    limited_solver: ClassVar[type]
    p_cav: float = setting(NO_LIMIT, **P_CAV)

    def __post_init__(self):
        suction_limit(self.p_cav)

    def solver(self):
        """A new ``limited_solver`` at P_cav, or :class:`Unlimited` without a limit."""
        return Unlimited() if self.p_cav == NO_LIMIT else self.limited_solver(self.p_cav)

    @classmethod
    def with_limit(cls, p_cav: float):
        """The model with the scaled limit ``p_cav``."""
        return cls(p_cav=p_cav)


@MODELS.register
@dataclass(frozen=True)
class Truncation(LimitedSuction):
    """The source's model: P >= P_cav, the liquid in a cavity neither tracked nor conserved
    (:class:`TruncationSolver`); P_cav = -inf (the default): no limit."""

    name: ClassVar[str] = "truncate"
    tracks_liquid: ClassVar[bool] = False
    limited_solver: ClassVar[type] = TruncationSolver


@MODELS.register
@dataclass(frozen=True)
class MassConserving(LimitedSuction):
    """Jakobsson-Floberg-Olsson cavitation, a cavity keeps its liquid
    (:class:`MassConservingSolver`); P_cav = -inf (the default): no limit."""

    name: ClassVar[str] = "mass-conserving"
    tracks_liquid: ClassVar[bool] = True
    limited_solver: ClassVar[type] = MassConservingSolver


@MODELS.register
@dataclass(frozen=True)
class NoCavitation:
    """Unlimited suction whatever the liquid (:class:`Unlimited`)."""

    name: ClassVar[str] = "none"
    tracks_liquid: ClassVar[bool] = False
    p_cav: ClassVar[float] = NO_LIMIT

    def solver(self):
        """A new :class:`Unlimited`."""
        return Unlimited()

    @classmethod
    def with_limit(cls, p_cav: float):
        """No limit, whatever ``p_cav``."""
        return cls()
