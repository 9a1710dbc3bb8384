"""Pictures of a collision: deformed solids (pyvista, off-screen) and a film animation (GIF).

`render_solids` takes the solids' deformation under one film pressure
(:meth:`ehdfem.solids.fe.solids.FESolids.deformation`) and revolves the axisymmetric (r, z)
section about the axis into a 3-D cut-away (270 degrees: the surfaces of revolution of the
solids' boundaries plus the two flat cuts that show the field inside), with the displacement
magnified by a stated factor and coloured by von Mises stress, hydrostatic stress or
displacement magnitude (range from the 1st to the 99.5th percentile, stated on the picture;
logarithmic over at most 4 decades for the positive fields); a second view is a close-up of
the contact with the film pressure profile drawn above the contact. Lengths are by the sphere
radius a, stresses by mu V0 a / x0^2, displacements by x0 (magnified for display only).

`animate_film` writes a GIF of the film thickness H(R) and pressure P(R) next to the sphere's
gap X(T) and velocity V(T), through approach, maximum compression and rebound.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from .. import checks
from ..console.quiet import quiet_vtk
from ..solids.fe.solids import solids_of

FIELDS = ("von_mises", "hydrostatic", "displacement", "pressure")
BAR_WIDTH = 160  # pixels kept for the colour bar


def _pyvista():
    """pyvista, imported on first use, with VTK's logging set as :mod:`ehdfem.console.quiet` says
    (quiet: no "bad X server connection" warning from off-screen rendering)."""
    import pyvista

    quiet_vtk()
    return pyvista


def _section(solids, shape, nodal_pressure, field, magnification):
    """The (r, z) triangles of ``shape`` (a :class:`ehdfem.solids.fe.fields.Deformation` of
    ``solids``) moved by the magnified displacement, with ``field`` at the points."""
    pyvista = _pyvista()

    triangles = np.asarray(shape.triangles)
    cells = np.column_stack([np.full(len(triangles), 3), triangles]).ravel()
    types = np.full(len(triangles), pyvista.CellType.TRIANGLE, dtype=np.uint8)
    points = np.column_stack([shape.points, np.zeros(len(shape.points))])
    grid = pyvista.UnstructuredGrid(cells, types, points)
    if field == "displacement":
        grid.point_data[field] = np.linalg.norm(shape.displacement, axis=1)
    elif field == "pressure":
        r, z = shape.points.T
        grid.point_data[field] = solids.film_pressure(nodal_pressure)(r) * (np.abs(z) < 1e-9)
    else:
        grid.cell_data[field] = getattr(shape, field)
        grid = grid.cell_data_to_point_data()
    # displacement by x0, geometry by a: x0 = delta a
    grid.points[:, :2] += magnification * solids.delta * shape.displacement
    return grid


def _cut_away(section, angle=270.0, resolution=72):
    """The (r, z) section revolved about the axis over ``angle`` degrees: the outer boundary as
    surfaces of revolution plus the two flat cuts at 0 and ``angle`` degrees (field kept)."""
    flat = section.extract_surface(algorithm="dataset_surface")
    flat.points[:] = np.column_stack(
        [flat.points[:, 0], np.zeros(flat.n_points), flat.points[:, 1]]
    )
    edges = flat.extract_feature_edges(
        boundary_edges=True, feature_edges=False, manifold_edges=False, non_manifold_edges=False
    )
    shell = edges.extrude_rotate(resolution=resolution, angle=angle, capping=False)
    turned = flat.rotate_z(angle, inplace=False)
    return flat, turned, shell


def _pressure_curve(solids, nodal_pressure):
    """The film pressure P(r) drawn above the wall's contact face in both cut planes, its
    height scaled so that the peak stands at a third of the film radius (a picture of the
    pressure profile, not to any length scale)."""
    pyvista = _pyvista()

    r = solids.radii_a
    peak = max(float(np.abs(nodal_pressure).max()), 1e-300)
    height = nodal_pressure / peak * r[-1] / 3
    curves = []
    for angle in (0.0, 270.0):
        c, s = np.cos(np.radians(angle)), np.sin(np.radians(angle))
        points = np.column_stack([r * c, r * s, solids.delta / 2 + height])
        curves.append(pyvista.lines_from_points(points))
    return curves[0].merge(curves[1])


def render_solids(
    compliance,
    nodal_pressure,
    path,
    field="von_mises",
    magnification=None,
    title="",
    size=(1600, 800),
):
    """PNG of the FE solids of ``compliance`` (an :class:`ehdfem.solids.fe.solids.FECompliance`,
    at its eps) deformed by the film pressure with values ``nodal_pressure`` at the film nodes
    (by mu V0 a / x0^2): overview cut-away + contact close-up, ``size`` pixels. ``field``: one
    of FIELDS. ``magnification``: display factor on the displacement (default: so that the
    largest displacement shows as a tenth of the contact region). Returns the magnification
    used."""
    pyvista = _pyvista()

    checks.choice("field", field, FIELDS)
    solids = solids_of(compliance, "rendering the solids")
    pyvista.OFF_SCREEN = True
    shape = solids.deformation(nodal_pressure, compliance.eps)
    if magnification is None:
        largest = float(np.linalg.norm(shape.displacement, axis=1).max()) * solids.delta
        magnification = 0.1 * solids.radii_a[-1] / max(largest, 1e-300)
    magnification = checks.positive("magnification", magnification)
    section = _section(solids, shape, nodal_pressure, field, magnification)
    values = section.point_data[field]
    limits = (float(np.percentile(values, 1)), float(np.percentile(values, 99.5)))
    upper = solids.radius_upper
    lower = solids.radius_lower or upper
    plotter = pyvista.Plotter(
        off_screen=True, shape=(1, 2), window_size=(size[0] - BAR_WIDTH, size[1])
    )
    logarithmic = field in ("von_mises", "displacement")  # positive, spanning decades
    if logarithmic:
        limits = (max(limits[0], limits[1] * 1e-4), limits[1])
    for column, half_width in enumerate((1.3 * max(upper, lower), 1.5 * solids.radii_a[-1])):
        plotter.subplot(0, column)
        top = 2 * upper + solids.delta if column == 0 else half_width
        bottom = -2 * lower if column == 0 else -half_width
        window = section.clip_box([0, half_width, bottom, top, -1, 1], invert=False)
        for piece in _cut_away(window):
            plotter.add_mesh(
                piece,
                scalars=field,
                cmap="viridis",
                clim=limits,
                log_scale=logarithmic,
                show_scalar_bar=False,
            )
        if column == 1:
            plotter.add_mesh(_pressure_curve(solids, nodal_pressure), color="red", line_width=4)
        plotter.view_xz()
        plotter.camera.azimuth = 25
        plotter.camera.elevation = 20
        plotter.reset_camera()
        plotter.camera.zoom(1.0 if column == 0 else 1.3)
        label = "cut-away (270 deg)" if column == 0 else "contact close-up; red: film pressure"
        plotter.add_text(
            f"{label}; displacement x {magnification:.3g}; {field.replace('_', ' ')} "
            f"from {limits[0]:.3g} to {limits[1]:.3g}{' (log)' if logarithmic else ''}",
            font_size=9,
            position="lower_left",
        )
    plotter.subplot(0, 0)
    plotter.add_text(title, font_size=10, position="upper_left")
    image = plotter.screenshot(return_img=True)
    plotter.close()
    _with_colour_bar(image, field, limits, logarithmic, size, path)
    return magnification


def _with_colour_bar(image, field, limits, logarithmic, size, path):
    """Save the rendered image with a colour bar beside it, ``size`` pixels in all (drawn by
    matplotlib: VTK's own scalar bar aborts when VTK shares the process with Debian's DOLFINx
    libraries)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import LogNorm, Normalize

    fig = plt.figure(figsize=(size[0] / 100, size[1] / 100), dpi=100)
    share = image.shape[1] / size[0]
    ax = fig.add_axes([0, 0, share, 1])
    ax.imshow(image)
    ax.axis("off")
    bar = fig.add_axes([share + 0.1 * (1 - share), 0.15, 0.15 * (1 - share), 0.7])
    norm = LogNorm(*limits) if logarithmic else Normalize(*limits)
    units = "(by x0)" if field == "displacement" else "(by mu V0 a / x0^2)"
    fig.colorbar(
        plt.cm.ScalarMappable(norm=norm, cmap="viridis"),
        cax=bar,
        label=f"{field.replace('_', ' ')} {units}",
    )
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=100)
    plt.close(fig)


def animate_film(normal, path, frames: int = 40, fps: int = 10) -> int:
    """GIF of H(R) and P(R) next to X(T) and V(T); returns the number of frames written."""
    import imageio.v2 as imageio
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    frames = checks.integer("frames", frames, lower=2, upper=2000)
    hist = normal.history
    steps = np.unique(
        np.searchsorted(hist.time, np.linspace(0, hist.time[-1], frames)).clip(
            0, len(hist.time) - 1
        )
    )
    pressure = np.abs(hist.pressure)
    loaded = normal.radii[(pressure > 0.01 * pressure.max()).any(axis=0)]
    shown = normal.radii <= 1.5 * (loaded.max() if len(loaded) else normal.radii[-1])
    images = []
    for i in steps:
        fig, axes = plt.subplots(2, 2, figsize=(9, 6))
        (ax_h, ax_x), (ax_p, ax_v) = axes
        ax_h.semilogy(normal.radii[shown], hist.film_thickness[i][shown])
        ax_h.set_ylim(max(hist.min_film.min() * 0.5, 1e-6), 2.0)
        ax_h.set_ylabel("film H (by x0)")
        ax_p.plot(normal.radii[shown], hist.pressure[i][shown])
        ax_p.set_ylim(
            min(0.0, hist.pressure[:, shown].min()) * 1.05, hist.pressure[:, shown].max() * 1.05
        )
        ax_p.set_ylabel("pressure P (by mu V0 a/x0^2)")
        ax_p.set_xlabel("R (by sqrt(a x0))")
        for ax, values, label in (
            (ax_x, hist.gap, "gap X (by x0)"),
            (ax_v, hist.velocity, "velocity V (by V0)"),
        ):
            ax.plot(hist.time, values, color="0.7")
            ax.plot(hist.time[: i + 1], values[: i + 1], color="C0")
            ax.plot(hist.time[i], values[i], "o", color="C3")
            ax.set_ylabel(label)
        ax_v.set_xlabel("T (by x0/V0)")
        fig.suptitle(f"T = {hist.time[i]:.4g}")
        fig.tight_layout()
        fig.canvas.draw()
        images.append(np.asarray(fig.canvas.buffer_rgba())[:, :, :3].copy())
        plt.close(fig)
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    imageio.mimsave(str(path), images, duration=1.0 / fps, loop=0)
    return len(images)
