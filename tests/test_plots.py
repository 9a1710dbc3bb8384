"""The figures a user gets (ehdfem.outputs.plots) as drawn: no label covers another, however
the pressure axis spans suction and peak (the symlog axis of profiles.png) and however close the
bounces come (bounce.png). Each figure is laid out as it is saved and every text of it measured
on the canvas."""

from itertools import combinations
from types import SimpleNamespace

import matplotlib
import numpy as np
import pytest

from ehdfem.collision import collide
from ehdfem.config import RunConfig
from ehdfem.inputs.scales import CollisionParameters
from ehdfem.outputs import plots

pytestmark = pytest.mark.serial  # drawing has nothing to check on 2 ranks


@pytest.fixture(autouse=True)
def laid_out_not_saved(monkeypatch):
    """The plot functions return their figure laid out as saved (tight layout), unsaved."""

    def lay_out(fig, path):
        fig.tight_layout()
        return fig

    monkeypatch.setattr(plots, "_save", lay_out)
    yield
    matplotlib.pyplot.close("all")


def _texts(fig):
    """Every text a reader sees: the titles, axis labels, tick labels (of the ticks in view),
    legends and annotations of every axes (its secondary axes too), and the figure's title."""
    axes = [*fig.axes, *(child for ax in fig.axes for child in ax.child_axes)]
    for ax in axes:
        yield from (ax.title, ax._left_title, ax._right_title, *ax.texts)
        for axis in (ax.xaxis, ax.yaxis):
            yield axis.label
            low, high = sorted(axis.get_view_interval())
            for tick in axis.get_major_ticks():
                if low <= tick.get_loc() <= high:
                    yield from (tick.label1, tick.label2)
        if ax.get_legend() is not None:
            yield from (ax.get_legend().get_title(), *ax.get_legend().get_texts())
    yield from fig.texts


def overlapping_texts(fig) -> list[tuple[str, str]]:
    """The pairs of visible texts of ``fig`` whose boxes on the canvas overlap."""
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    boxes = [
        (text.get_text(), text.get_window_extent(renderer))
        for text in _texts(fig)
        if text.get_visible() and text.get_text().strip()
    ]
    return [(a, b) for (a, box_a), (b, box_b) in combinations(boxes, 2) if box_a.overlaps(box_b)]


def film_result(suction: float, peak: float):
    """A stand-in collision whose film pressure rises to ``peak`` and later sucks at
    ``suction`` (scaled units), with the histories plot_profiles reads."""
    radii, time = np.linspace(0.0, 2.0, 60), np.linspace(0.0, 4.0, 40)
    pressure = np.outer(peak * np.sin(np.pi * time / 3.0), np.exp(-(radii**2)))
    pressure[30:] = -suction * (radii < 1.5)
    gap = 0.9 - time + 0.3 * time**2
    history = SimpleNamespace(
        time=time,
        gap=gap,
        force=pressure.sum(axis=1),
        pressure=pressure,
        film_thickness=np.abs(gap)[:, None] + 0.01 + radii**2 / 2,
    )
    params = SimpleNamespace(St=10.0, eps=1e-3, layer="thin")
    return SimpleNamespace(history=history, radii=radii, rebound=True, e_n=0.5, params=params)


@pytest.mark.parametrize(
    "suction, peak",
    [(3.0, 1e9), (9.9e4, 1e9), (0.5, 1e3), (1e-3, 1e9), (2.0, 400.0), (7e4, 2e5), (40.0, 3e6)],
)
def test_the_pressure_axis_labels_never_overlap(suction, peak):
    """A suction anywhere from 1e-12 to 1 of the peak: the symlog axis's linear range is a power
    of ten at or below the suction, so that its ticks are 0 and whole decades; the suction
    shows within the axis. (A linear range of 3 or 9.9e4 put a tick at 1 or 1e4 into the
    linear range, a fraction of a decade from 0, and the labels overlapped.)"""
    fig = plots.plot_profiles(film_result(suction, peak), "profiles.png")
    assert overlapping_texts(fig) == []
    axis = fig.axes[0]
    linear = axis.yaxis.get_transform().linthresh
    assert np.log10(linear) == pytest.approx(round(np.log10(linear)), abs=1e-12)
    assert linear <= max(suction, 1e-6 * peak) and axis.get_ylim()[0] <= -suction


def test_the_linear_range_is_the_power_of_ten_at_or_below_the_suction():
    """... but not below 1e-6 of the largest pressure, whose decades would crowd the axis."""
    assert plots.symlog_threshold(9.9e4, 1e9) == 1e4
    assert plots.symlog_threshold(1.01e5, 1e9) == 1e5
    assert plots.symlog_threshold(1e5, 1e9) == 1e5
    assert plots.symlog_threshold(1e-3, 1e9) == 1e3
    assert plots.symlog_threshold(3.0, 400.0) == 1.0
    assert plots.symlog_threshold(0.5, 1e3) == pytest.approx(0.1, rel=1e-15)


def test_the_tours_collision_profiles_have_no_overlapping_label():
    """The README tour's first collision, as ``collide --plots`` draws it."""
    params = CollisionParameters.from_settings(St=10, eps=1e-3, layer="thin", p_cav=-2)
    result = collide(params, RunConfig.from_settings(nodes=80)).normal
    for draw in (plots.plot_profiles, plots.plot_histories):
        assert overlapping_texts(draw(result, "figure.png")) == []


def bounce_result(apexes: list[tuple[float, float]]):
    """A stand-in bounce of a 3 mm sphere: contacts at ``apexes`` (t / sqrt(D/g), gap / D),
    each after a contact, e falling from 0.83, on a trajectory through them."""
    diameter, unit = 3e-3, np.sqrt(3e-3 / 9.81)
    times = np.array([0.0, *(t for t, _ in apexes)])
    trajectory_time = np.linspace(-4.0, times[-1] + 1.0, 400)
    gap = np.interp(
        trajectory_time, [-4.0, *times, times[-1] + 1.0], [6.0, 0.0, *(g for _, g in apexes), 0.0]
    )
    contacts = [
        SimpleNamespace(
            e=0.83 - 0.2 * i, St=113.0 / (i + 1), apex_time=t * unit, apex_gap=g * diameter
        )
        for i, (t, g) in enumerate(apexes)
    ]
    inputs = SimpleNamespace(
        diameter=diameter,
        time_scale=lambda: unit,
        drag="schiller-naumann",
        sphere=SimpleNamespace(name="steel"),
        liquid=SimpleNamespace(name="silicone_oil_10cst"),
    )
    trajectory = {
        "time": trajectory_time * unit,
        "gap": gap * diameter,
        "phase": np.where(gap <= 0.0, "contact", "flight"),
    }
    return SimpleNamespace(
        inputs=inputs,
        trajectory=trajectory,
        contacts=contacts,
        model="halfspace",
        status="rest: the apex is inside the hand-over region",
    )


@pytest.mark.parametrize(
    "apexes",
    [
        [(1.8, 1.45), (4.8, 0.38), (6.2, 0.07), (6.7, 0.004)],  # the bounce of docs/bounce.md
        [(1.0, 0.5), (1.4, 0.1), (1.6, 0.02), (1.7, 0.004), (1.75, 0.001)],
    ],
)
def test_bounce_figure_labels_never_overlap(apexes):
    """bounce.png, however close the late bounces come: each contact's e and St are in a panel
    of their own, not written at its apex (where they covered each other)."""
    result = bounce_result(apexes)
    fig = plots.plot_bounce(result, "bounce.png")
    assert overlapping_texts(fig) == []
    panel = fig.axes[1]
    assert list(panel.lines[0].get_ydata()) == [c.e for c in result.contacts]
    assert list(panel.lines[0].get_xdata()) == [c.St for c in result.contacts]


def test_a_physical_collisions_plots_name_its_inputs_and_overlap_nowhere(tmp_path, monkeypatch):
    """``collide --example --plots``: each figure's title names the physical inputs (sphere,
    radius, speed, angle, wall, layer, liquid) above the scaled groups, no text of the three
    figures covers another, and the tangential one has its SI axes beside the scaled ones."""
    from ehdfem.cli.main import main

    figures = []

    def keep(fig, path):
        fig.tight_layout()
        figures.append(fig)
        return path

    monkeypatch.setattr(plots, "_save", keep)
    assert main(["collide", "--example", "--nodes", "80", "--plots", str(tmp_path)]) == 0
    assert len(figures) == 3
    for fig in figures:
        title = fig._suptitle.get_text()
        assert title.startswith("steel sphere of radius 6.35 mm at 1 m/s, 30 deg from the normal")
        assert "St = 98.52, eps = 7.14e-07, thin layer: e_n = 0.88" in title
        assert overlapping_texts(fig) == []
    tangential = {text.get_text() for text in _texts(figures[2])}
    assert {"t [s]", "velocity [m/s]", "tangential force [N]"} <= tangential  # SI beside scaled
