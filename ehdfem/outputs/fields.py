"""Exports of the FE fields: the solids' displacement, stresses, film pressure and regions as one
XDMF time series for ParaView (pyvista, meshio).

`field_snapshots` picks the instants of a collision worth looking at (maximum compression,
maximum force, the end, and any requested times) with the film pressure there; `write_fields`
solves the FE solids of the collision's compliance under each of those pressures and writes
the fields, in SI given the scales, scaled otherwise. The mesh and the displacement share one
length unit (m in SI, a when scaled), so that ParaView's warp by ``displacement_m`` (or
``displacement_a``) at factor 1 is the true deformed shape; ``displacement_x0`` is the same
displacement by x0 (warp factor 1 magnifies it by a/x0 = 1/delta). The names and units are in
docs/pictures.md.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from xml.etree import ElementTree

import numpy as np

from .. import checks
from ..solids.fe.solids import solids_of

STRESSES = ("von_mises", "hydrostatic")
"""The cell fields of stress (per triangle)."""


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


@dataclass(frozen=True)
class FieldUnits:
    """The units of the written fields, as factors on the solids' scaled fields (points by a,
    displacement by x0, stresses and pressure by mu V0 a / x0^2, time by x0/V0) and as the
    names that end the arrays' names. ``length``: the mesh's and the displacement's unit per a;
    ``gap``: x0 in that unit (so displacement = ``gap`` * displacement by x0)."""

    length: float
    length_name: str
    gap: float
    stress: float
    stress_name: str
    time: float
    time_name: str

    @classmethod
    def of(cls, delta: float, scales=None) -> FieldUnits:
        """SI units from ``scales`` (:class:`ehdfem.inputs.scales.Scales`: a in m, x0 in m,
        pressure in Pa, time in s), which must have x0 / a = ``delta``; without them the
        scaled units (lengths by a, x0 = delta a, stresses by mu V0 a / x0^2, time by x0/V0)."""
        if scales is None:
            return cls(1.0, "a", delta, 1.0, "muV0a_x0sq", 1.0, "x0/V0")
        if not math.isclose(scales.gap / scales.sphere_radius, delta, rel_tol=1e-9):
            raise checks.InputError(
                f"units: x0 / a = {scales.gap / scales.sphere_radius:.6g} differs from the "
                f"solids' delta = {delta:.6g}"
            )
        return cls(scales.sphere_radius, "m", scales.gap, scales.pressure, "Pa", scales.time, "s")

    def names(self) -> dict:
        """{field of a deformation: array name}: the quantity and its unit."""
        return {
            "displacement": f"displacement_{self.length_name}",
            "displacement_x0": "displacement_x0",
            "film_pressure": f"film_pressure_{self.stress_name}",
            **{name: f"{name}_{self.stress_name}" for name in STRESSES},
        }

    def description(self) -> str:
        """The units in words, for the file's Information element."""
        stress = "Pa" if self.stress_name == "Pa" else "mu V0 a / x0^2"
        return (
            f"time in {self.time_name}; mesh (r, z, 0) and displacement_{self.length_name} "
            f"(u_r, u_z, 0) in {self.length_name} (warp by it at factor 1: the true shape); "
            f"displacement_x0 in x0; film pressure and stresses in {stress}; body: 0 upper "
            "sphere, 1 lower body (wall, substrate or lower sphere), 2 coating"
        )


def write_fields(compliance, path, snapshots, units=None) -> None:
    """XDMF time series (ParaView, pyvista, meshio) of the FE solids of ``compliance`` (an
    :class:`ehdfem.solids.fe.solids.FECompliance`, at its eps) under the film pressure, with
    its data in an HDF5 file beside it (same name, .h5).

    ``snapshots``: (time, nodal pressure) pairs, at least one, time by x0/V0 and pressure by
    mu V0 a / x0^2 (e.g. from :func:`field_snapshots`). Per instant: point fields
    ``displacement_<length>`` and ``displacement_x0`` (3 components (u_r, u_z, 0); free spheres
    relative to their centre of mass) and ``film_pressure_<stress>`` (on the contact faces,
    zero elsewhere); cell fields ``von_mises_<stress>`` and ``hydrostatic_<stress>`` (per
    cell, as the hoop strain u_r/r is 0/0 at vertices on the axis) and ``body``. Points are
    (r, z, 0). Units (:class:`FieldUnits`): with ``units`` (:class:`ehdfem.inputs.scales.Scales`)
    SI: lengths in m, stresses in Pa, time in s; otherwise lengths by a, stresses by
    mu V0 a / x0^2, time by x0/V0. Every rank solves its part; rank 0 gathers and writes.
    """
    solids = solids_of(compliance, "writing the fields (--fields)")
    if not snapshots:
        raise checks.InputError("write_fields needs at least one (time, pressure) snapshot")
    field_units = FieldUnits.of(solids.delta, units)
    names = field_units.names()
    local = {"steps": []}
    for time, nodal in snapshots:
        shape = solids.deformation(nodal, compliance.eps)
        point = {
            names["displacement"]: _three(shape.displacement * field_units.gap),
            names["displacement_x0"]: _three(shape.displacement),
            names["film_pressure"]: shape.film_pressure * field_units.stress,
        }
        cell = {names[name]: getattr(shape, name) * field_units.stress for name in STRESSES}
        step = {"time": time * field_units.time, "Node": point, "Cell": cell}
        local["steps"].append(step)
    local["points"] = _three(shape.points * field_units.length)
    local["triangles"], local["body"] = shape.triangles, shape.body
    parts = solids.comm.gather(local, root=0)
    if solids.comm.rank == 0:
        _write_xdmf(Path(path), _merged(parts), field_units.description())


def _three(pairs: np.ndarray) -> np.ndarray:
    """(n, 2) (r, z) values as (n, 3) (r, z, 0): ParaView's vectors and points."""
    return np.column_stack([pairs, np.zeros(len(pairs))])


def _merged(parts) -> dict:
    """The ranks' points, triangles, regions and fields as one mesh (a vertex shared by ranks
    appears once per rank, with the same values)."""
    offsets = np.cumsum([0] + [len(p["points"]) for p in parts[:-1]])
    steps = []
    for k, step in enumerate(parts[0]["steps"]):
        merged = {"time": step["time"]}
        for center in ("Node", "Cell"):
            merged[center] = {
                name: np.concatenate([p["steps"][k][center][name] for p in parts])
                for name in step[center]
            }
        steps.append(merged)
    return {
        "points": np.concatenate([p["points"] for p in parts]),
        "triangles": np.concatenate(
            [p["triangles"] + o for p, o in zip(parts, offsets, strict=True)]
        ).astype(np.int64),
        "body": np.concatenate([p["body"] for p in parts]).astype(np.int32),
        "steps": steps,
    }


def _write_xdmf(path: Path, mesh: dict, units: str) -> None:
    """One temporal collection of uniform grids and no other grid, so ParaView and pyvista read
    exactly the written times (meshio 5.0's TimeSeriesWriter puts an untimed mesh grid beside
    the collection, which VTK reads as a second block holding the first instant's fields);
    every grid names the same mesh datasets of the HDF5 file."""
    import h5py

    path = path.resolve()
    path.parent.mkdir(parents=True, exist_ok=True)
    h5 = path.with_suffix(".h5")
    root = ElementTree.Element("Xdmf", Version="3.0")
    domain = ElementTree.SubElement(root, "Domain")
    ElementTree.SubElement(domain, "Information", Name="units", Value=units)
    series = ElementTree.SubElement(
        domain, "Grid", Name="fields", GridType="Collection", CollectionType="Temporal"
    )
    n_cells = len(mesh["triangles"])
    with h5py.File(h5, "w") as data:
        for name in ("points", "triangles", "body"):
            data[f"mesh/{name}"] = mesh[name]
        for k, step in enumerate(mesh["steps"]):
            grid = ElementTree.SubElement(series, "Grid", Name=f"step_{k}", GridType="Uniform")
            ElementTree.SubElement(grid, "Time", Value=repr(float(step["time"])))
            geometry = ElementTree.SubElement(grid, "Geometry", GeometryType="XYZ")
            _data_item(geometry, h5, "mesh/points", mesh["points"])
            topology = ElementTree.SubElement(
                grid, "Topology", TopologyType="Triangle", NumberOfElements=str(n_cells)
            )
            _data_item(topology, h5, "mesh/triangles", mesh["triangles"])
            _attribute(grid, "body", "Cell", h5, "mesh/body", mesh["body"])
            for center in ("Node", "Cell"):
                for name, values in step[center].items():
                    data[f"step_{k}/{name}"] = values
                    _attribute(grid, name, center, h5, f"step_{k}/{name}", values)
    ElementTree.indent(root)
    ElementTree.ElementTree(root).write(path, xml_declaration=True, encoding="utf-8")


def _attribute(grid, name, center, h5: Path, dataset: str, values) -> None:
    """An Attribute element (scalar or 3-vector at the nodes or cells) naming ``dataset``."""
    kind = "Vector" if np.ndim(values) == 2 else "Scalar"
    attribute = ElementTree.SubElement(
        grid, "Attribute", Name=name, AttributeType=kind, Center=center
    )
    _data_item(attribute, h5, dataset, values)


def _data_item(parent, h5: Path, dataset: str, values) -> None:
    """A DataItem naming ``dataset`` of the HDF5 file ``h5`` (beside the XDMF file)."""
    values = np.asarray(values)
    kind = "Int" if np.issubdtype(values.dtype, np.integer) else "Float"
    item = ElementTree.SubElement(
        parent,
        "DataItem",
        DataType=kind,
        Dimensions=" ".join(map(str, values.shape)),
        Format="HDF",
        Precision=str(values.dtype.itemsize),
    )
    item.text = f"{h5.name}:/{dataset}"
