"""Pictures: a render is a PNG of the requested size with the solids in frame, a scale bar in
each view and its colour bar in the stated unit (Pa given the SI scales); the animation's
frames follow the contact."""

import imageio.v2 as imageio
import numpy as np
import pytest

from ehdfem.checks import InputError
from ehdfem.collision import collide
from ehdfem.config import RunConfig
from ehdfem.inputs.scales import CollisionParameters, Scales, from_presets
from ehdfem.outputs.render import animate_film, film_frames, render_solids, scale_bar
from ehdfem.solids.halfspace import HalfSpaceCompliance

pytestmark = pytest.mark.serial

# SI scales of a collision at delta = 0.01: a = 3 mm, x0 = 30 um
UNITS = Scales(
    gap=3e-5,
    radius=3e-4,
    time=3e-5,
    velocity=1.0,
    pressure=3.0e3,
    force=0.0,
    energy=0.0,
    sphere_radius=3e-3,
)


@pytest.fixture(scope="module")
def fe_collision():
    params = CollisionParameters.from_settings(
        St=10.0, eps=1e-3, layer="thin", p_cav=-2.0, delta=0.01, angle=30.0
    )
    return collide(params, RunConfig.from_settings(model="fem", nodes=40))


def widest_black_shape(image) -> int:
    """The width in pixels of the widest connected set of black pixels: the scale bar (drawn
    black, 8 pixels thick, tens of pixels long) and not a glyph of text (a few pixels)."""
    from scipy import ndimage

    labels, count = ndimage.label(image.sum(axis=2) < 100)
    widths = [s[1].stop - s[1].start for s in ndimage.find_objects(labels)]
    return max(widths, default=0)


@pytest.mark.slow
def test_render_is_a_picture_of_the_solids_with_scale_bars(fe_collision, tmp_path):
    hist = fe_collision.normal.history
    i = int(np.argmin(hist.gap))
    path = tmp_path / "solids.png"
    picture = render_solids(
        fe_collision.compliance, hist.pressure[i], path, title="test", size=(800, 400)
    )
    image = imageio.imread(path)[:, :, :3]
    assert image.shape == (400, 800, 3) and picture.magnification > 0
    colours = {tuple(c) for c in image.reshape(-1, 3)[::7]}
    assert len(colours) > 50  # a colour map, not a blank or single-colour frame
    drawn = (image.sum(axis=2) < 700).mean()  # pixels that are not (near) white
    assert 0.1 < drawn < 0.95
    for half in (image[:, :320], image[:, 320:640]):  # both views: the solids and a scale bar
        assert (half.sum(axis=2) < 700).mean() > 0.05
        assert widest_black_shape(half) >= 20  # the bars: 26 and 40 pixels; glyphs: <= 8
    assert picture.colour_bar == "von mises [mu V0 a / x0^2]"
    assert all(label.endswith(" a") for label in picture.scale_bars)


def test_render_with_the_si_scales_is_in_pascal_and_metres(fe_collision, tmp_path):
    """The same picture given the SI scales: colour range in Pa, the scaled one times
    mu V0 a / x0^2 (to rounding); scale bars in m with a prefix."""
    pressure = fe_collision.normal.history.pressure[
        int(np.argmax(fe_collision.normal.history.force))
    ]
    options = dict(field="hydrostatic", size=(400, 200))
    scaled = render_solids(fe_collision.compliance, pressure, tmp_path / "s.png", **options)
    si = render_solids(
        fe_collision.compliance, pressure, tmp_path / "si.png", units=UNITS, **options
    )
    assert si.colour_bar == "hydrostatic [Pa]"
    assert np.allclose(
        si.colour_range, np.multiply(UNITS.pressure, scaled.colour_range), rtol=1e-12
    )
    assert all(label.split()[1] in ("m", "mm", "µm", "nm") for label in si.scale_bars)
    displacement = render_solids(
        fe_collision.compliance,
        pressure,
        tmp_path / "u.png",
        "displacement",
        units=UNITS,
        size=(400, 200),
    )
    assert displacement.colour_bar == "displacement [m]"


def test_scale_bar_is_a_round_length_in_the_stated_unit():
    """1, 2 or 5 times a power of ten, not longer than asked: 0.0123 a of a = 3 mm is
    36.9 um, so the bar is 20 um = 2e-5 / 3e-3 a; without scales 0.0123 a gives 0.01 a."""
    length, label = scale_bar(0.0123, UNITS)
    assert label == "20 µm" and length == pytest.approx(2e-5 / 3e-3, rel=1e-14)
    assert scale_bar(0.0123) == (pytest.approx(0.01, rel=1e-14), "0.01 a")
    assert scale_bar(2.0)[1] == "2 a" and scale_bar(0.5, UNITS)[1] == "1 mm"
    with pytest.raises(InputError, match="scale bar"):
        scale_bar(0.0)


def test_rendering_twice_draws_the_same_picture(fe_collision, tmp_path):
    """A render does not move the solids' mesh: the same inputs draw the same picture."""
    hist = fe_collision.normal.history
    pressure = hist.pressure[int(np.argmax(hist.force))]
    for name in ("first.png", "second.png"):
        render_solids(fe_collision.compliance, pressure, tmp_path / name, size=(400, 200))
    first, second = (imageio.imread(tmp_path / name) for name in ("first.png", "second.png"))
    assert np.array_equal(first, second)


def test_render_needs_fe_solids(fe_collision, tmp_path):
    compliance = HalfSpaceCompliance(fe_collision.normal.radii, 1e-3)
    with pytest.raises(InputError, match="--model fem"):
        render_solids(compliance, np.zeros(len(compliance.radii)), tmp_path / "none.png")


def test_animation_frames_fall_in_the_contact():
    """Glass on glass through 0.2 mm of water, 1 m/s: the film force is above 5 % of its
    peak for about 2 % of the collision, so frames even in time show it in about one frame in
    ten; frames even in time and in the force's impulse put at least 45 % of them there."""
    physical = from_presets(
        radius=3e-3,
        sphere="glass",
        wall="glass",
        liquid="water",
        speed=1.0,
        layer_thickness=2e-4,
    )
    hist = collide(physical, RunConfig.from_settings(nodes=60)).normal.history
    contact = hist.force >= 0.05 * hist.force.max()
    even = np.unique(np.searchsorted(hist.time, np.linspace(0, hist.time[-1], 40)))
    assert contact[even.clip(0, len(hist.time) - 1)].mean() < 0.15
    steps = film_frames(hist, 40)
    assert steps[0] == 0 and steps[-1] == len(hist.time) - 1 and (np.diff(steps) > 0).all()
    assert contact[steps].mean() >= 0.45


@pytest.mark.slow
def test_animation_has_one_frame_per_sampled_step(fe_collision, tmp_path):
    path = tmp_path / "film.gif"
    frames = animate_film(fe_collision.normal, path, frames=12, units=UNITS)
    assert frames == len(film_frames(fe_collision.normal.history, 12)) == len(imageio.mimread(path))


def test_render_offers_no_plots_or_fields_it_would_ignore(capsys):
    """`render --help` lists neither --plots nor --fields (options of collide); given, they
    are refused by name."""
    from ehdfem.cli.main import main

    with pytest.raises(SystemExit) as exit_info:
        main(["render", "--help"])
    assert exit_info.value.code == 0
    help_text = capsys.readouterr().out
    assert "--animation" in help_text and "--plots" not in help_text
    assert "--fields" not in help_text
    for flag in ("--plots", "--fields"):
        with pytest.raises(SystemExit) as exit_info:
            main(["render", "--St", "10", "--eps", "1e-3", flag, "out"])
        assert exit_info.value.code == 2
        assert flag in capsys.readouterr().err
