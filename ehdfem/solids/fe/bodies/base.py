"""What every lower body of the FE solids is, and the one registry of them.

A lower body is the solid below the film. It is one frozen dataclass, a subclass of
:class:`LowerBody`, whose fields are its settings (declared with
:func:`ehdfem.settings.setting`: help, unit or scale, allowed range, default; lengths by
the (reduced) sphere radius a, moduli by the wall's Young's modulus) and whose members say what
the FE solids need of it and nothing of how they solve: its gmsh geometry (a generator of
meshes/contact.py and its arguments), its material per gmsh cell tag from the wall's (E, nu),
its radius, and how it is held: clamped on some facets (a wall's base) or free (a sphere, held
by its own d'Alembert body force, :class:`FreeBody`). The tags are those of meshes/contact.py:
every lower body has the contact face LOWER_CONTACT and the axis LOWER_AXIS.

:func:`register` enters a body class into :data:`LOWER_BODIES` under its ``kind``: the run
configuration (:class:`ehdfem.config.RunConfig`), the command line (``--lower`` and the body's
fields as options), the study keys and the JSON inputs read that registry, so a new body is
one file (the built-in ones: wall.py, coated_wall.py, lower_sphere.py).

Materials are (Young's modulus, Poisson ratio) pairs, of which the FE solids use only the
ratios of the moduli (to the upper sphere's).
"""

from __future__ import annotations

import abc
import dataclasses
from dataclasses import dataclass
from typing import ClassVar

from .... import checks
from ....settings import described, validate


@dataclass(frozen=True)
class FreeBody:
    """A free solid (a sphere): its film load is balanced by a uniform d'Alembert body force
    and its far pole is pinned in u_z. ``cell_tag`` and ``contact_tag`` are its gmsh groups
    (cells, contact face; meshes/contact.py), ``pole_z`` the height of the pinned pole and
    ``radius`` its radius (by a), ``direction`` the sign of the body force per unit film load
    (-1 for the upper sphere, which the film pushes up; +1 for a lower sphere, pushed down)."""

    cell_tag: int
    contact_tag: int
    pole_z: float
    direction: float
    radius: float

    @property
    def centre_z(self) -> float:
        """The height of the sphere's centre (by a)."""
        return self.pole_z + self.direction * self.radius


class LowerBody(abc.ABC):
    """The body below the film (module docstring); subclasses are frozen dataclasses.
    ``kind``: its name in :data:`LOWER_BODIES` (the value of ``--lower``); ``description``:
    what it is, in a few words (for ``--lower``'s help); ``models``: the elasticity models
    that compute it (the FE solids; the half-space kernel too for a body it stands for);
    ``sphere_radius``: the upper sphere's
    radius and ``radius`` its own (None: a flat body), by a; ``clamped``: the facet tags held
    fixed (empty for a free body). Its fields are checked against their settings."""

    kind: ClassVar[str]
    description: ClassVar[str]
    models: ClassVar[tuple[str, ...]] = ("fem",)
    sphere_radius: ClassVar[float] = 1.0
    radius: ClassVar[float | None] = None
    clamped: ClassVar[tuple[int, ...]] = ()

    def __post_init__(self):
        validate(self)

    @abc.abstractmethod
    def materials(self, wall: tuple[float, float]) -> dict[int, tuple[float, float]]:
        """(E, nu) per gmsh cell tag of the body, from the wall's (E, nu) ``wall`` (the
        material of the half-space kernel's lower solid, which sets the compliance scale
        theta: a coated wall's substrate, a lower sphere's own)."""

    def free_body(self) -> FreeBody | None:
        """The body as a free solid, or None when it is clamped."""
        return None

    @abc.abstractmethod
    def geometry(self, gap: float, contact_radii, size: float) -> tuple:
        """(generator, arguments): ``generator(*arguments)`` builds the gmsh model of the upper
        sphere at ``gap`` above this body, both contact faces through ``contact_radii`` (by a),
        the far parts ``size`` away (meshes/contact.py)."""


LOWER_BODIES: dict[str, type[LowerBody]] = {}
"""Every lower body class by its kind, in the order registered (the default, "wall", first)."""


def register(body: type[LowerBody]) -> type[LowerBody]:
    """Enter the lower body class ``body`` into :data:`LOWER_BODIES` (a class decorator; again
    for the same class changes nothing). Refused: a class that is not a frozen dataclass
    subclassing :class:`LowerBody` with a ``kind``, a kind already taken by another class,
    and a field name of another body (the flat settings name each field once)."""
    if not (
        isinstance(body, type)
        and issubclass(body, LowerBody)
        and dataclasses.is_dataclass(body)
        and body.__dataclass_params__.frozen
        and isinstance(getattr(body, "kind", None), str)
    ):
        raise TypeError(
            f"a lower body is a frozen dataclass subclassing LowerBody with a kind, not {body!r}"
        )
    if LOWER_BODIES.get(body.kind, body) is not body:
        raise TypeError(f"the lower body kind {body.kind!r} is taken by {LOWER_BODIES[body.kind]}")
    names = {f.name for f in described(body)}
    for other in (b for b in LOWER_BODIES.values() if b is not body):
        shared = names & {f.name for f in described(other)}
        if shared:
            raise TypeError(f"{body.__name__}'s field(s) {sorted(shared)} are {other.__name__}'s")
    LOWER_BODIES[body.kind] = body
    return body


def checked_material(name: str, pair) -> tuple[float, float]:
    """(E, nu) checked: E > 0, -1 < nu < 0.5 (``name`` names the solid in the error)."""
    young, poisson = pair
    checks.positive(f"{name} Young's modulus", young)
    checks.number(
        f"{name} Poisson ratio", poisson, lower=-1.0, upper=0.5, lower_open=True, upper_open=True
    )
    return float(young), float(poisson)
