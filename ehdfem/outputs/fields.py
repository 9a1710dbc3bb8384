"""Exports of the FE fields: the solids' displacement and stresses as an XDMF time series.

`field_snapshots` picks the instants of a collision worth looking at (maximum compression,
maximum force, the end, and any requested times) with the film pressure there; `write_fields`
solves the FE solids of the collision's compliance under each of those pressures and writes
the fields for ParaView (or meshio): scaled by the film's units, or in SI given the scales.
"""

from __future__ import annotations

import contextlib
from pathlib import Path

import numpy as np

from .. import checks
from ..solids.fe.solids import solids_of

CELL_FIELDS = ("von_mises", "hydrostatic")


def field_snapshots(normal, times=None) -> list:
    """(T, nodal pressure) at maximum compression, maximum force, the end (exit or stop) and
    any requested times T (by x0/V0; the pressure is interpolated linearly between steps)."""
    hist = normal.history
    chosen = {
        hist.time[int(np.argmin(hist.gap))],
        hist.time[int(np.argmax(hist.force))],
        hist.time[-1],
    }
    for t in times or []:
        checks.number("field time", t, lower=0.0, upper=float(hist.time[-1]))
        chosen.add(t)
    snapshots = []
    for t in sorted(chosen):
        i = min(int(np.searchsorted(hist.time, t)), len(hist.time) - 1)
        j = max(i - 1, 0)
        w = 0.0 if i == j else (t - hist.time[j]) / (hist.time[i] - hist.time[j])
        snapshots.append((float(t), (1 - w) * hist.pressure[j] + w * hist.pressure[i]))
    return snapshots


def write_fields(compliance, path, snapshots, units=None) -> None:
    """XDMF time series (ParaView, meshio) of the FE solids of ``compliance`` (an
    :class:`ehdfem.solids.fe.solids.FECompliance`, at its eps) under the film pressure.

    ``snapshots``: (time, nodal pressure) pairs, at least one, time by x0/V0 and pressure by
    mu V0 a / x0^2 (e.g. from :func:`field_snapshots`). Per instant: point field
    ``displacement`` (by x0; free spheres relative to their centre of mass) and cell fields
    ``von_mises`` and ``hydrostatic`` (by mu V0 a / x0^2; per cell, as the hoop strain u_r/r is
    0/0 at vertices on the axis). The (r, z) mesh is by a. With ``units``
    (:class:`ehdfem.inputs.scales.Scales`) everything is in SI instead: mesh and displacement in m,
    stresses in Pa, time in s. Every rank solves its part; rank 0 gathers and writes.
    """
    solids = solids_of(compliance, "writing the fields (--fields)")
    if not snapshots:
        raise checks.InputError("write_fields needs at least one (time, pressure) snapshot")
    length, gap, stress_unit, time_unit = (
        (units.sphere_radius, units.gap, units.pressure, units.time)
        if units
        else (1.0, 1.0, 1.0, 1.0)
    )
    local = {"steps": []}
    for time, nodal in snapshots:
        shape = solids.deformation(nodal, compliance.eps)
        step = {"time": time * time_unit, "displacement": shape.displacement * gap}
        for name in CELL_FIELDS:
            step[name] = getattr(shape, name) * stress_unit
        local["steps"].append(step)
    local["points"], local["triangles"] = shape.points * length, shape.triangles
    parts = solids.comm.gather(local, root=0)
    if solids.comm.rank == 0:
        _write_xdmf(Path(path), parts)


def _write_xdmf(path: Path, parts) -> None:
    """Merge the ranks' points, triangles and fields and write them as one time series."""
    import meshio

    offsets = np.cumsum([0] + [len(p["points"]) for p in parts[:-1]])
    points = np.concatenate([p["points"] for p in parts])
    triangles = np.concatenate([p["triangles"] + o for p, o in zip(parts, offsets, strict=True)])
    path = path.resolve()
    path.parent.mkdir(parents=True, exist_ok=True)
    # meshio 5.0 (Debian) writes the .h5 beside the working directory: write from path's folder
    with contextlib.chdir(path.parent), meshio.xdmf.TimeSeriesWriter(path.name) as writer:
        writer.write_points_cells(points, [("triangle", triangles)])
        for k, step in enumerate(parts[0]["steps"]):
            merged = {
                name: np.concatenate([p["steps"][k][name] for p in parts])
                for name in ("displacement", *CELL_FIELDS)
            }
            writer.write_data(
                step["time"],
                point_data={"displacement": merged["displacement"]},
                cell_data={name: [merged[name]] for name in CELL_FIELDS},
            )
