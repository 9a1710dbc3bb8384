"""Pictures: a render is a PNG of the requested size with the solids in frame; the animation
has the expected frames."""

import imageio.v2 as imageio
import numpy as np
import pytest

from ehdfem.checks import InputError
from ehdfem.collision import collide
from ehdfem.inputs.scales import CollisionParameters
from ehdfem.outputs.render import animate_film, render_solids
from ehdfem.solids.halfspace import HalfSpaceCompliance

pytestmark = pytest.mark.serial


@pytest.fixture(scope="module")
def fe_collision():
    params = CollisionParameters(
        St=10.0, eps=1e-3, layer="thin", p_cav=-2.0, delta=0.01, angle=30.0
    )
    return collide(params, model="fem", nodes=40)


def test_render_is_a_picture_of_the_solids(fe_collision, tmp_path):
    hist = fe_collision.normal.history
    i = int(np.argmin(hist.gap))
    path = tmp_path / "solids.png"
    magnification = render_solids(
        fe_collision.compliance, hist.pressure[i], path, title="test", size=(800, 400)
    )
    image = imageio.imread(path)[:, :, :3]
    assert image.shape == (400, 800, 3) and magnification > 0
    colours = {tuple(c) for c in image.reshape(-1, 3)[::7]}
    assert len(colours) > 50  # a colour map, not a blank or single-colour frame
    drawn = (image.sum(axis=2) < 700).mean()  # pixels that are not (near) white
    assert 0.1 < drawn < 0.95
    for half in (image[:, :400], image[:, 400:]):  # both views hold the solids
        assert (half.sum(axis=2) < 700).mean() > 0.05


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


def test_animation_has_one_frame_per_sampled_step(fe_collision, tmp_path):
    path = tmp_path / "film.gif"
    frames = animate_film(fe_collision.normal, path, frames=12)
    hist = fe_collision.normal.history
    expected = len(np.unique(np.searchsorted(hist.time, np.linspace(0, hist.time[-1], 12))))
    assert frames == expected == len(imageio.mimread(path))
