"""A collision's histories as data: one NumPy ``.npz`` file (``ehdfem collide --histories``).

Every array is at the accepted time steps of the normal motion (``steps`` long), the film's
fields (steps, nodes) at the film nodes ``radius``. Scaled as the rest of ehdfem (DSH 1986):
time by x0/V0, gap X and film thickness H by x0, radius by sqrt(a x0), velocity by V0,
pressure by mu V0 a / x0^2 (above ambient), force by 6 pi mu V0 a^2 / x0, energies by
m V0^2 / St; the tangential velocity, the spin a Omega and the slip by U0. For physical inputs
every dimensional history has its SI copy too, named ``<name>_si``. The file says what each
array is: ``units`` is a JSON text (a 0-d string array) {name: [meaning, scale or SI unit]},
``inputs`` the collision's inputs (:meth:`ehdfem.collision.CollisionResult.inputs`, which
``ehdfem collide --from`` reads too) and ``provenance`` its provenance
(:mod:`ehdfem.outputs.provenance`), both JSON texts.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from . import provenance

if TYPE_CHECKING:
    from ..collision import CollisionResult

# name: (meaning, scale, SI unit, the SI unit of its scale from (Scales, St) or None)
# fmt: off
NORMAL = {
    "time": ("time since first touch of the layer", "x0/V0", "s", lambda s, St: s.time),
    "gap": ("gap X of the undeformed surfaces on the axis", "x0", "m", lambda s, St: s.gap),
    "velocity": ("normal velocity V, towards the wall negative", "V0", "m/s",
                 lambda s, St: s.velocity),
    "force": ("film force on the sphere (1/3) int P R dR", "6 pi mu V0 a^2 / x0", "N",
              lambda s, St: s.force),
    "central_film": ("film thickness on the axis", "x0", "m", lambda s, St: s.gap),
    "min_film": ("thinnest film over radius", "x0", "m", lambda s, St: s.gap),
    "edge_radius": ("radius of the wetted edge", "sqrt(a x0)", "m", lambda s, St: s.radius),
    "kinetic": ("kinetic energy St V^2 / 2", "m V0^2 / St", "J", lambda s, St: s.energy / St),
    "elastic": ("elastic energy in the solids (and rough surfaces' asperities)", "m V0^2 / St",
                "J", lambda s, St: s.energy / St),
    "dissipated": ("film's viscous dissipation so far (and a solid impact's loss)",
                   "m V0^2 / St", "J", lambda s, St: s.energy / St),
    "work": ("applied forces' work on the sphere", "m V0^2 / St", "J",
             lambda s, St: s.energy / St),
    "film_thickness": ("film thickness H(R, T), (steps, nodes)", "x0", "m", lambda s, St: s.gap),
    "pressure": ("film pressure P(R, T) above ambient, (steps, nodes)", "mu V0 a / x0^2", "Pa",
                 lambda s, St: s.pressure),
    "fill": ("liquid fraction theta of the gap, (steps, nodes)", "-", None, None),
}
TANGENTIAL = {  # the tangential motion's histories, for oblique impacts; SI from U0 [m/s]
    "tangential_velocity": ("tangential velocity U of the centre", "U0", "m/s"),
    "spin": ("spin a Omega", "U0", "m/s"),
    "slip": ("slip velocity U - a Omega at the contact", "U0", "m/s"),
}
# fmt: on
RADIUS = ("radius", "film nodes R", "sqrt(a x0)", "m")
ASPERITY = (  # rough surfaces only (NormalResult.asperity_force)
    "asperity_force",
    "asperities' load on the sphere (rough surfaces)",
    "6 pi mu V0 a^2 / x0",
    "N",
)


def arrays(result: CollisionResult, command: list[str] | None = None) -> dict:
    """The histories of ``result`` as {name: numpy array}, with ``units``, ``inputs`` and
    ``provenance`` (``command``: its command line, default sys.argv) as JSON texts; see the
    module docstring."""
    hist = result.normal.history
    data = {name: np.asarray(getattr(hist, name)) for name in NORMAL}
    data[RADIUS[0]] = np.asarray(result.normal.radii)
    units = {name: [meaning, scale] for name, (meaning, scale, _, _) in NORMAL.items()}
    units[RADIUS[0]] = list(RADIUS[1:3])
    if result.normal.asperity_force is not None:
        data[ASPERITY[0]] = np.asarray(result.normal.asperity_force)
        units[ASPERITY[0]] = list(ASPERITY[1:3])
    if result.tangential is not None:
        t = result.tangential
        for name, (meaning, scale, _) in TANGENTIAL.items():
            data[name] = np.asarray(getattr(t, _field(name)))
            units[name] = [meaning, scale]
    if result.physical is not None:
        _add_si(result, data, units)
    data["units"] = np.array(json.dumps(units))
    data["inputs"] = np.array(json.dumps(result.inputs()))
    data["provenance"] = np.array(json.dumps(provenance.record(command)))
    return data


def _field(name: str) -> str:
    """The TangentialResult field of a tangential history."""
    return "velocity" if name == "tangential_velocity" else name


def _add_si(result: CollisionResult, data: dict, units: dict) -> None:
    """Add the SI copy ``<name>_si`` of every dimensional history of a physical collision."""
    scales, St = result.physical.scales(), result.params.St
    for name, (meaning, _, unit, factor) in NORMAL.items():
        if factor is not None:
            data[f"{name}_si"] = data[name] * factor(scales, St)
            units[f"{name}_si"] = [meaning, unit]
    data["radius_si"] = data["radius"] * scales.radius
    units["radius_si"] = [RADIUS[1], RADIUS[3]]
    if ASPERITY[0] in data:
        data[f"{ASPERITY[0]}_si"] = data[ASPERITY[0]] * scales.force
        units[f"{ASPERITY[0]}_si"] = [ASPERITY[1], ASPERITY[3]]
    for name, (meaning, _, unit) in TANGENTIAL.items():
        if name in data:
            data[f"{name}_si"] = data[name] * result.physical.tangential_speed
            units[f"{name}_si"] = [meaning, unit]


def write_histories(result: CollisionResult, path, command: list[str] | None = None) -> Path:
    """Write the histories of ``result`` to the ``.npz`` file ``path`` (uncompressed; read
    with ``numpy.load``, ``json.loads(str(f["units"]))``); ``command`` as in :func:`arrays`."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    with path.open("wb") as f:
        np.savez(f, **arrays(result, command))
    return path


def markdown_table() -> str:
    """The table of docs/outputs.md: every array of a histories file, its meaning, its scale
    and the SI unit of its ``<name>_si`` copy (physical inputs)."""
    rows = [(name, meaning, scale, unit) for name, (meaning, scale, unit, _) in NORMAL.items()]
    rows += [RADIUS, ASPERITY]
    rows += [(name, *spec) for name, spec in TANGENTIAL.items()]
    lines = ["| name | meaning | scaled by | SI copy |", "|---|---|---|---|"]
    for name, meaning, scale, unit in rows:
        copy = f"`{name}_si` [{unit}]" if unit else "-"
        lines.append(f"| `{name}` | {meaning} | {scale} | {copy} |")
    return "\n".join(lines)
