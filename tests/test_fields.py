"""The FE fields for ParaView (ehdfem.outputs.fields): one XDMF time series that meshio and
pyvista read back with exactly the written times, named arrays with their units, 3-component
displacements in the mesh's length unit, the bodies' regions and the film pressure on the
contact faces; SI fields are the scaled ones times the scales. Runs on 2 ranks too (rank 0
writes what all ranks solved)."""

import dataclasses
from pathlib import Path

import numpy as np
import pytest
from mpi4py import MPI

from ehdfem.checks import InputError
from ehdfem.film.grid import radial_grid
from ehdfem.inputs.scales import Scales
from ehdfem.outputs.fields import write_fields
from ehdfem.solids.fe.bodies import CoatedWall
from ehdfem.solids.fe.solids import FESolids
from ehdfem.solids.halfspace import HalfSpaceCompliance

DELTA = 1e-3
RADII = radial_grid(20, 0.5, 2.0)
PRESSURE = np.sqrt(np.clip(1 - (RADII / 0.8) ** 2, 0, None))
TIMES = (0.5, 1.0, 2.0)
SNAPSHOTS = [(0.5, PRESSURE), (1.0, 0.5 * PRESSURE), (2.0, 2.0 * PRESSURE)]
# SI scales of a collision with x0 / a = DELTA: a = 0.1 m, x0 = 0.1 mm
UNITS = Scales(
    gap=1e-4,
    radius=np.sqrt(1e-5),
    time=2e-4,
    velocity=0.5,
    pressure=300.0,
    force=0.0,
    energy=0.0,
    sphere_radius=0.1,
)
SCALED = {
    "point": {"displacement_a", "displacement_x0", "film_pressure_muV0a_x0sq"},
    "cell": {"body", "von_mises_muV0a_x0sq", "hydrostatic_muV0a_x0sq"},
}
SI = {
    "point": {"displacement_m", "displacement_x0", "film_pressure_Pa"},
    "cell": {"body", "von_mises_Pa", "hydrostatic_Pa"},
}


def read(path):
    """(points, triangles, [(time, point data, cell data)]) as meshio reads the series."""
    import meshio

    with meshio.xdmf.TimeSeriesReader(str(path)) as reader:
        points, cells = reader.read_points_cells()
        steps = [reader.read_data(k) for k in range(reader.num_steps)]
    cell_data = [(t, p, {name: c[0] for name, c in cells_.items()}) for t, p, cells_ in steps]
    return points, cells[0].data, cell_data


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    """The solids' compliance and the scaled and SI files of the same snapshots."""
    comm = MPI.COMM_WORLD
    folder = Path(comm.bcast(str(tmp_path_factory.mktemp("fields")) if comm.rank == 0 else None))
    compliance = FESolids(DELTA, RADII, comm=comm).compliance(1e-3)
    write_fields(compliance, folder / "scaled.xdmf", SNAPSHOTS)
    write_fields(compliance, folder / "si.xdmf", SNAPSHOTS, units=UNITS)
    comm.Barrier()
    return compliance, folder


def test_meshio_reads_the_written_times_and_named_fields(written):
    """Exactly the three written times; the arrays by name with their unit; every vector has
    3 components, the third zero (the (r, z) section in the x-y plane)."""
    if MPI.COMM_WORLD.rank != 0:
        return
    _, folder = written
    for name, expected in (("scaled", SCALED), ("si", SI)):
        points, _, steps = read(folder / f"{name}.xdmf")
        assert points.shape[1] == 3 and not points[:, 2].any()
        unit = UNITS.time if name == "si" else 1.0
        assert [t for t, _, _ in steps] == [t * unit for t in TIMES]
        for _, point, cell in steps:
            assert set(point) == expected["point"] and set(cell) == expected["cell"]
            for vector in (v for v in point.values() if v.ndim == 2):
                assert vector.shape == (len(points), 3) and not vector[:, 2].any()
                assert np.abs(vector).max() > 0


def test_pyvista_reads_one_grid_per_written_time(written):
    """pyvista (VTK's XDMF reader) sees the three times and one grid, not a second block of
    the first instant; each time's displacement is that instant's (loads 1, 0.5, 2)."""
    if MPI.COMM_WORLD.rank != 0:
        return
    pyvista = pytest.importorskip("pyvista")
    _, folder = written
    reader = pyvista.get_reader(str(folder / "scaled.xdmf"))
    assert reader.time_values == list(TIMES)
    _, _, steps = read(folder / "scaled.xdmf")
    for time, (_, point, cell) in zip(TIMES, steps, strict=True):
        reader.set_active_time_value(time)
        grid = reader.read()
        assert isinstance(grid, pyvista.UnstructuredGrid)
        assert set(grid.point_data) == SCALED["point"] and set(grid.cell_data) == SCALED["cell"]
        assert np.array_equal(grid.point_data["displacement_a"], point["displacement_a"])
        assert np.array_equal(grid.cell_data["body"], cell["body"])
    first, last = steps[0][1]["displacement_x0"], steps[2][1]["displacement_x0"]
    assert np.allclose(last, 2.0 * first, rtol=1e-8, atol=1e-14 * np.abs(first).max())


def test_film_pressure_is_the_nodal_pressure_on_the_contact_faces(written):
    """At the film nodes r_i = R_i sqrt(delta) a (vertices of both faces: the wall's z = 0 and
    the sphere's z = delta + 1 - sqrt(1 - r^2)) the point field is the nodal pressure, to
    rounding; it is zero off the faces."""
    if MPI.COMM_WORLD.rank != 0:
        return
    _, folder = written
    points, _, steps = read(folder / "scaled.xdmf")
    r, z = points[:, 0], points[:, 1]
    sphere = DELTA + 1 - np.sqrt(np.clip(1 - r**2, 0, None))
    on_faces = (np.abs(z) < 1e-12) | ((np.abs(z - sphere) < 1e-9) & (r < 1))
    radii_a = RADII * np.sqrt(DELTA)
    for (_, nodal), (_, point, _) in zip(SNAPSHOTS, steps, strict=True):
        film = point["film_pressure_muV0a_x0sq"]
        assert not film[~on_faces].any()
        for r_i, p_i in zip(radii_a, nodal, strict=True):
            at_node = on_faces & (np.abs(r - r_i) < 1e-12)
            assert 2 <= at_node.sum()  # both faces (once per rank that holds the vertex)
            assert np.allclose(film[at_node], p_i, rtol=1e-12, atol=1e-12)


def test_si_fields_are_the_scaled_fields_times_the_scales(written):
    """Mesh and displacement in m (times a and x0), stresses and film pressure in Pa (times
    mu V0 a / x0^2), time in s (times x0 / V0): exact up to rounding, 1e-13 of each value or of
    its field's largest (the two files come from two distributed solves, which on the wheel
    stack's MUMPS under 2 ranks agree only to the last bits of the largest values)."""

    def same(si_values, values, factor):
        scaled = factor * values
        return np.allclose(si_values, scaled, rtol=1e-13, atol=1e-13 * np.abs(scaled).max())

    if MPI.COMM_WORLD.rank != 0:
        return
    _, folder = written
    points, triangles, scaled = read(folder / "scaled.xdmf")
    si_points, si_triangles, si = read(folder / "si.xdmf")
    assert np.array_equal(triangles, si_triangles)
    assert np.allclose(si_points, UNITS.sphere_radius * points, rtol=1e-13, atol=0)
    pairs = {
        "displacement_m": ("displacement_a", UNITS.sphere_radius),
        "displacement_x0": ("displacement_x0", 1.0),
        "film_pressure_Pa": ("film_pressure_muV0a_x0sq", UNITS.pressure),
    }
    for (_, point, cell), (_, si_point, si_cell) in zip(scaled, si, strict=True):
        for name, (scaled_name, factor) in pairs.items():
            assert same(si_point[name], point[scaled_name], factor)
        for name in ("von_mises", "hydrostatic"):
            assert same(si_cell[f"{name}_Pa"], cell[f"{name}_muV0a_x0sq"], UNITS.pressure)
        assert np.array_equal(si_cell["body"], cell["body"])


def test_warp_at_factor_one_opens_the_gap_by_the_compliance(written):
    """The mesh and ``displacement_a`` share the unit a: warped at factor 1, the gap on the
    axis between the sphere's pole (r = 0, z = delta) and the wall (r = 0, z = 0) opens by
    delta W(0), W = C P the compliance's gap opening (by x0) at the first film node. W(0) is
    the load's own functional (the average over the first film node's hat, docs/fem.md), the
    warp the vertex value on the axis: they differ by the displacement's curvature over the
    hat (measured 7.3e-4 here; 1e-2 asserted, against the factor 1/delta = 100 that mixed
    length units would give)."""
    compliance, folder = written
    if MPI.COMM_WORLD.rank != 0:
        return
    for name, unit, length in (("scaled", "a", 1.0), ("si", "m", UNITS.sphere_radius)):
        points, _, steps = read(folder / f"{name}.xdmf")
        pole = (np.abs(points[:, 0]) < 1e-12) & (np.abs(points[:, 1] - DELTA * length) < 1e-12)
        wall = (np.abs(points[:, 0]) < 1e-12) & (np.abs(points[:, 1]) < 1e-12 * length)
        for (_, nodal), (_, point, _) in zip(SNAPSHOTS, steps, strict=True):
            warped = points + point[f"displacement_{unit}"]
            gap = warped[pole, 1].mean() - warped[wall, 1].mean()
            opening = compliance.deflection(nodal)[0] * DELTA * length
            assert gap - DELTA * length == pytest.approx(opening, rel=1e-2)


def test_regions_are_tagged_by_body(written):
    """``body`` is 0 in the upper sphere (cells above the film, z > delta / 2) and 1 in the
    wall (below it)."""
    if MPI.COMM_WORLD.rank != 0:
        return
    _, folder = written
    points, triangles, steps = read(folder / "scaled.xdmf")
    centroid_z = points[triangles, 1].mean(axis=1)
    expected = np.where(centroid_z > DELTA / 2, 0, 1)
    assert np.array_equal(steps[0][2]["body"], expected)


@pytest.mark.serial
def test_a_coating_is_its_own_region(tmp_path):
    """Coated wall (thickness 0.03 a): cells in -0.03 < z < 0 are region 2, the substrate
    below 1, the sphere 0."""
    compliance = FESolids(DELTA, RADII, lower=CoatedWall(0.03), comm=MPI.COMM_SELF).compliance(1e-3)
    write_fields(compliance, tmp_path / "coated.xdmf", SNAPSHOTS[:1])
    points, triangles, steps = read(tmp_path / "coated.xdmf")
    z = points[triangles, 1].mean(axis=1)
    expected = np.select([z > DELTA / 2, z > -0.03], [0, 2], 1)
    assert np.array_equal(steps[0][2]["body"], expected)


@pytest.mark.serial
def test_scales_of_another_gap_are_refused(written, tmp_path):
    """SI scales whose x0 / a is not the solids' delta would warp the mesh wrongly."""
    compliance, _ = written
    other = dataclasses.replace(UNITS, gap=2e-4)
    with pytest.raises(InputError, match="units"):
        write_fields(compliance, tmp_path / "f.xdmf", SNAPSHOTS, units=other)


@pytest.mark.serial
def test_fields_need_fe_solids(tmp_path):
    with pytest.raises(InputError, match="--model fem"):
        write_fields(HalfSpaceCompliance(RADII, 1e-3), tmp_path / "f.xdmf", [(0.0, RADII)])
