"""Pictures of a collision: deformed solids (pyvista, off-screen) and a film animation (GIF).

`render_solids` takes the solids' deformation under one film pressure
(:meth:`ehdfem.solids.fe.solids.FESolids.deformation`) and revolves the axisymmetric (r, z)
section about the axis into a 3-D cut-away (270 degrees: the surfaces of revolution of the
solids' boundaries plus the two flat cuts that show the field inside), with the displacement
magnified by a stated factor and coloured by von Mises stress, hydrostatic stress or
displacement magnitude (range from the 1st to the 99.5th percentile, stated on the picture;
logarithmic over at most 4 decades for the positive fields); a second view is a close-up of
the contact with the film pressure profile drawn above the contact, and each view has a
black scale bar of a stated length. Given the SI scales (physical inputs) the colour bar is in
Pa (stresses, pressure) or m (displacement) and the scale bar in m; otherwise stresses are by
mu V0 a / x0^2, displacements by x0 and lengths by the sphere radius a (displacements are
magnified for display only).

`animate_film` writes a GIF of the film thickness H(R) and pressure P(R) next to the sphere's
gap X(T) and velocity V(T), through approach, maximum compression and rebound, in SI given the
scales; its frames (`film_frames`) are spread evenly over time and over the force's impulse,
so that about half of them show the contact however short it is.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .. import checks
from ..console.quiet import quiet_vtk
from ..solids.fe.solids import solids_of
from . import plots

FIELDS = ("von_mises", "hydrostatic", "displacement", "pressure")
BAR_WIDTH = 160  # pixels kept for the colour bar


@dataclass(frozen=True)
class RenderedPicture:
    """What a render drew: the display ``magnification`` of the displacement, the colour bar's
    label (the field and its unit) and range (in that unit), and the length of each view's
    scale bar (overview, close-up), with its unit."""

    magnification: float
    colour_bar: str
    colour_range: tuple[float, float]
    scale_bars: tuple[str, str]


def field_unit(field: str, units=None) -> tuple[float, str]:
    """(factor, unit) that turn a field of the solids (stresses and pressure by
    mu V0 a / x0^2, displacement by x0) into the unit shown: Pa and m given ``units``
    (:class:`ehdfem.inputs.scales.Scales`), else the scales themselves."""
    if field == "displacement":
        return (units.gap, "m") if units else (1.0, "x0")
    return (units.pressure, "Pa") if units else (1.0, plots.PRESSURE_UNIT)


def scale_bar(longest: float, units=None) -> tuple[float, str]:
    """(length by a, label) of a scale bar: the largest 1, 2 or 5 times a power of ten not
    above ``longest`` (by a), in m (with the prefix that reads best) given ``units``, else
    in units of a."""
    metres = units.sphere_radius if units else 1.0
    longest = checks.positive("scale bar length", longest) * metres
    power = 10.0 ** math.floor(math.log10(longest))
    length = max(m * power for m in (1, 2, 5) if m * power <= longest * (1 + 1e-12))
    if not units:
        return length, f"{length:.3g} a"
    prefixes = ((1.0, "m"), (1e-3, "mm"), (1e-6, "µm"), (1e-9, "nm"))
    factor, prefix = next(((f, p) for f, p in prefixes if length >= 0.999 * f), prefixes[-1])
    return length / metres, f"{length / factor:.3g} {prefix}"


def _pyvista():
    """pyvista, imported on first use, with VTK's logging set as :mod:`ehdfem.console.quiet` says
    (quiet: no "bad X server connection" warning from off-screen rendering)."""
    import pyvista

    quiet_vtk()
    return pyvista


def _section(shape, field, magnification, delta, factor):
    """The (r, z) triangles of ``shape`` (a :class:`ehdfem.solids.fe.fields.Deformation`)
    moved by the magnified displacement, with ``field`` times ``factor`` at the points."""
    pyvista = _pyvista()

    triangles = np.asarray(shape.triangles)
    cells = np.column_stack([np.full(len(triangles), 3), triangles]).ravel()
    types = np.full(len(triangles), pyvista.CellType.TRIANGLE, dtype=np.uint8)
    points = np.column_stack([shape.points, np.zeros(len(shape.points))])
    grid = pyvista.UnstructuredGrid(cells, types, points)
    if field == "displacement":
        grid.point_data[field] = factor * np.linalg.norm(shape.displacement, axis=1)
    elif field == "pressure":
        grid.point_data[field] = factor * shape.film_pressure
    else:
        grid.cell_data[field] = factor * getattr(shape, field)
        grid = grid.cell_data_to_point_data()
    # displacement by x0, geometry by a: x0 = delta a
    grid.points[:, :2] += magnification * delta * shape.displacement
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


def _scale_bar_line(half_width, bottom, top, length):
    """A horizontal bar of ``length`` (by a) along r, just in front of the 0-degree cut (the
    camera looks along +y), near the bottom of the view."""
    pyvista = _pyvista()

    start = np.array([0.1 * half_width, -1e-3 * half_width, bottom + 0.08 * (top - bottom)])
    return pyvista.Line(start, start + [length, 0.0, 0.0])


def render_solids(
    compliance,
    nodal_pressure,
    path,
    field="von_mises",
    magnification=None,
    title="",
    size=(1600, 800),
    units=None,
) -> RenderedPicture:
    """PNG of the FE solids of ``compliance`` (an :class:`ehdfem.solids.fe.solids.FECompliance`,
    at its eps) deformed by the film pressure with values ``nodal_pressure`` at the film nodes
    (by mu V0 a / x0^2): overview cut-away + contact close-up, each with a scale bar, ``size``
    pixels. ``field``: one of FIELDS. ``magnification``: display factor on the displacement
    (default: so that the largest displacement shows as a tenth of the contact region).
    ``units``: the SI scales (:class:`ehdfem.inputs.scales.Scales`) for a colour bar in Pa or
    m and scale bars in m; None: scaled units."""
    pyvista = _pyvista()

    checks.choice("field", field, FIELDS)
    solids = solids_of(compliance, "rendering the solids")
    pyvista.OFF_SCREEN = True
    shape = solids.deformation(nodal_pressure, compliance.eps)
    if magnification is None:
        largest = float(np.linalg.norm(shape.displacement, axis=1).max()) * solids.delta
        magnification = 0.1 * solids.radii_a[-1] / max(largest, 1e-300)
    magnification = checks.positive("magnification", magnification)
    factor, unit = field_unit(field, units)
    section = _section(shape, field, magnification, solids.delta, factor)
    values = section.point_data[field]
    limits = (float(np.percentile(values, 1)), float(np.percentile(values, 99.5)))
    logarithmic = field in ("von_mises", "displacement")  # positive, spanning decades
    if logarithmic:
        limits = (max(limits[0], limits[1] * 1e-4), limits[1])
    plotter = pyvista.Plotter(
        off_screen=True, shape=(1, 2), window_size=(size[0] - BAR_WIDTH, size[1])
    )
    view = {"field": field, "limits": limits, "logarithmic": logarithmic, "units": units}
    bars = tuple(
        _draw_view(plotter, column, section, solids, nodal_pressure, view) for column in (0, 1)
    )
    plotter.subplot(0, 0)
    plotter.add_text(
        f"{title}\ndisplacement x {magnification:.3g}; {field.replace('_', ' ')} from "
        f"{limits[0]:.3g} to {limits[1]:.3g} {unit}{' (log)' if logarithmic else ''}",
        font_size=9,
        position="upper_left",
    )
    image = plotter.screenshot(return_img=True)
    plotter.close()
    label = f"{field.replace('_', ' ')} [{unit}]"
    _with_colour_bar(image, label, limits, logarithmic, size, path)
    return RenderedPicture(magnification, label, limits, bars)


def _draw_view(plotter, column, section, solids, nodal_pressure, view) -> str:
    """Draw the overview (``column`` 0) or the contact close-up (1) of ``section``: the
    cut-away coloured by ``view["field"]``, the film pressure curve (close-up) and a scale bar;
    returns the scale bar's label."""
    upper = solids.radius_upper
    lower = solids.radius_lower or upper
    half_width = 1.3 * max(upper, lower) if column == 0 else 1.5 * solids.radii_a[-1]
    top = 2 * upper + solids.delta if column == 0 else half_width
    bottom = -2 * lower if column == 0 else -half_width
    plotter.subplot(0, column)
    window = section.clip_box([0, half_width, bottom, top, -1, 1], invert=False)
    for piece in _cut_away(window):
        plotter.add_mesh(
            piece,
            scalars=view["field"],
            cmap="viridis",
            clim=view["limits"],
            log_scale=view["logarithmic"],
            show_scalar_bar=False,
        )
    if column == 1:
        plotter.add_mesh(_pressure_curve(solids, nodal_pressure), color="red", line_width=4)
    length, label = scale_bar(0.6 * half_width, view["units"])
    plotter.add_mesh(_scale_bar_line(half_width, bottom, top, length), color="black", line_width=8)
    plotter.view_xz()
    plotter.camera.azimuth = 25
    plotter.camera.elevation = 20
    plotter.reset_camera()
    plotter.camera.zoom(1.0 if column == 0 else 1.3)
    name = "cut-away (270 deg)" if column == 0 else "contact close-up; red: film pressure"
    plotter.add_text(f"{name}; black bar: {label}", font_size=9, position="lower_left")
    return label


def _with_colour_bar(image, label, limits, logarithmic, size, path):
    """Save the rendered image with a colour bar labelled ``label`` beside it, ``size`` pixels
    in all (drawn by matplotlib: VTK's own scalar bar aborts when VTK shares the process with
    Debian's DOLFINx libraries)."""
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
    fig.colorbar(plt.cm.ScalarMappable(norm=norm, cmap="viridis"), cax=bar, label=label)
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=100)
    plt.close(fig)


def film_frames(history, frames: int) -> np.ndarray:
    """The steps of ``history`` to animate: ``frames`` instants spread evenly in
    s(T) = T / T_end + I(T) / I_end, I(T) = int_0^T |F| dT the film force's impulse (so half
    of them are even in time and half follow the force, and a short contact gets about half
    the frames), each the first step at or after its instant, without repeats."""
    frames = checks.integer("frames", frames, lower=2, upper=2000)
    time, force = history.time, np.abs(history.force)
    impulse = np.concatenate([[0.0], np.cumsum(0.5 * (force[1:] + force[:-1]) * np.diff(time))])
    spread = time / time[-1] + (impulse / impulse[-1] if impulse[-1] > 0 else 0.0)
    instants = np.interp(np.linspace(0.0, spread[-1], frames), spread, time)
    return np.unique(np.searchsorted(time, instants).clip(0, len(time) - 1))


def animate_film(normal, path, frames: int = 40, fps: int = 10, units=None) -> int:
    """GIF of H(R) and P(R) next to X(T) and V(T) at the steps :func:`film_frames` picks, in
    SI given ``units`` (:func:`ehdfem.outputs.plots.axes`); returns the number of frames
    written."""
    import imageio.v2 as imageio
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    hist, axes_of = normal.history, plots.axes(units)
    (r_unit, r_label), (h_unit, h_label), (p_unit, p_label) = (
        axes_of[name] for name in ("radius", "film", "pressure")
    )
    pressure = np.abs(hist.pressure)
    loaded = normal.radii[(pressure > 0.01 * pressure.max()).any(axis=0)]
    shown = normal.radii <= 1.5 * (loaded.max() if len(loaded) else normal.radii[-1])
    radii, time = r_unit * normal.radii[shown], axes_of["time"][0] * hist.time
    images = []
    for i in film_frames(hist, frames):
        fig, axes = plt.subplots(2, 2, figsize=(9, 6))
        (ax_h, ax_x), (ax_p, ax_v) = axes
        ax_h.semilogy(radii, h_unit * hist.film_thickness[i][shown])
        ax_h.set_ylim(h_unit * max(hist.min_film.min() * 0.5, 1e-6), h_unit * 2.0)
        ax_h.set_ylabel(h_label)
        ax_p.plot(radii, p_unit * hist.pressure[i][shown])
        low, high = min(0.0, hist.pressure[:, shown].min()), hist.pressure[:, shown].max()
        ax_p.set_ylim(p_unit * low * 1.05, p_unit * high * 1.05)
        ax_p.set_ylabel(p_label)
        ax_p.set_xlabel(r_label)
        for ax, values, name in ((ax_x, hist.gap, "gap"), (ax_v, hist.velocity, "velocity")):
            factor, label = axes_of[name]
            ax.plot(time, factor * values, color="0.7")
            ax.plot(time[: i + 1], factor * values[: i + 1], color="C0")
            ax.plot(time[i], factor * values[i], "o", color="C3")
            ax.set_ylabel(label)
        ax_v.set_xlabel(axes_of["time"][1])
        symbol, _, unit = axes_of["time"][1].partition(" ")
        fig.suptitle(f"{symbol} = {time[i]:.4g} {unit}")
        fig.tight_layout()
        fig.canvas.draw()
        images.append(np.asarray(fig.canvas.buffer_rgba())[:, :, :3].copy())
        plt.close(fig)
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    imageio.mimsave(str(path), images, duration=1.0 / fps, loop=0)
    return len(images)
