"""Materials and liquids: presets, a user's own values (checked against their ranges), physical
study files, and the progress bars of long work."""

import io
import math

import pytest

from ehdfem import checks
from ehdfem.checks import InputError
from ehdfem.collision import collide
from ehdfem.config import RunConfig
from ehdfem.console import progress
from ehdfem.inputs.presets import (
    LIQUID_RANGES,
    LIQUIDS,
    MATERIAL_RANGES,
    MATERIALS,
    Liquid,
    Material,
    body,
    custom_liquid,
    custom_material,
    liquid,
    material,
)
from ehdfem.inputs.scales import from_presets
from ehdfem.study.sweep import Study, run_study

pytestmark = pytest.mark.serial


def test_presets_are_inside_their_ranges_and_consistent():
    """Every preset's values lie inside the ranges a user's values are checked against
    (MATERIAL_RANGES, LIQUID_RANGES, checked here value by value), and the liquids agree with
    what defines them: a silicone oil's viscosity is its grade in cSt times its density, the
    glycerol-water mixtures grow more viscous and denser and less volatile with the glycerol
    fraction, and water at 20 C has 1.00 mPa s, 998 kg/m^3 and 2.34 kPa (handbook values,
    within 2 %)."""
    for m in MATERIALS.values():
        for key, bounds in MATERIAL_RANGES.items():
            checks.number(f"{m.name}.{key}", getattr(m, key), **bounds)
    for liq in LIQUIDS.values():
        for key, bounds in LIQUID_RANGES.items():
            checks.number(f"{liq.name}.{key}", getattr(liq, key), **bounds)
    for name, liq in LIQUIDS.items():
        if name.startswith("silicone_oil_"):
            grade = float(name.removeprefix("silicone_oil_").removesuffix("cst"))
            assert liq.viscosity == pytest.approx(grade * 1e-6 * liq.density, rel=1e-9), name
    mixtures = [liquid(name) for name in ("water", "glycerol_50", "glycerol_80", "glycerol_90")]
    mixtures.append(liquid("glycerol"))
    for thinner, thicker in zip(mixtures, mixtures[1:], strict=False):
        assert thinner.viscosity < thicker.viscosity and thinner.density < thicker.density
        assert thinner.vapour_pressure > thicker.vapour_pressure
    water = liquid("water")
    assert (water.viscosity, water.density) == (pytest.approx(1.0e-3, rel=0.02), 998.0)
    assert water.vapour_pressure == pytest.approx(2.34e3, rel=0.02)


@pytest.mark.parametrize(
    ("values", "name"),
    [
        ((0.0, 0.3, 1000.0), "young_modulus"),
        ((-1e9, 0.3, 1000.0), "young_modulus"),
        ((math.inf, 0.3, 1000.0), "young_modulus"),
        ((1e9, 0.5, 1000.0), "poisson_ratio"),
        ((1e9, -1.0, 1000.0), "poisson_ratio"),
        ((1e9, 0.3, 0.0), "density"),
        ((1e9, 0.3, math.nan), "density"),
        (("1e9", 0.3, 1000.0), "young_modulus"),
    ],
)
def test_bad_materials_are_refused_by_name(values, name):
    with pytest.raises(InputError, match=name):
        Material("test", *values)


@pytest.mark.parametrize(
    ("values", "name"),
    [
        ((0.0, 900.0, 0.0, 0.0), "viscosity"),
        ((0.1, -900.0, 0.0, 0.0), "density"),
        ((0.1, 900.0, -1.0, 0.0), "vapour_pressure"),
        ((0.1, 900.0, 0.0, -1e-8), "pressure_viscosity"),
        ((0.1, 900.0, 0.0, 1e-3), "pressure_viscosity"),
    ],
)
def test_bad_liquids_are_refused_by_name(values, name):
    with pytest.raises(InputError, match=name):
        Liquid("test", *values)


def test_custom_values_change_a_preset_or_make_a_new_body():
    soft = custom_material("steel", young_modulus=19e9)
    assert soft.young_modulus == 19e9 and soft.poisson_ratio == material("steel").poisson_ratio
    assert "young_modulus = 1.9e+10" in soft.source and soft.name == "steel (changed)"
    assert custom_material("glass") is material("glass")
    oil = custom_liquid(viscosity=0.05, density=900, vapour_pressure=0)
    assert (oil.name, oil.pressure_viscosity, oil.density) == ("custom", 0.0, 900.0)
    with pytest.raises(InputError, match="needs density"):
        custom_material(young_modulus=1e9, poisson_ratio=0.3)
    with pytest.raises(InputError, match="colour"):
        custom_liquid("water", colour=1.0)
    with pytest.raises(InputError, match="--wall-poisson"):
        custom_material("glass", labels={"poisson_ratio": "--wall-poisson"}.get, poisson_ratio=1)


def test_a_body_from_a_name_a_table_or_itself():
    assert body("sphere", "steel") is material("steel")
    assert body("liquid", liquid("water")) == liquid("water")
    assert body("wall", {"preset": "glass", "density": 2500}).density == 2500.0
    with pytest.raises(InputError, match="sphere.poisson_ratio"):
        body("sphere", {"young_modulus": 1e9, "poisson_ratio": 0.7, "density": 1000})
    with pytest.raises(InputError, match="liquid must be a preset name or a table"):
        body("liquid", 3.0)


EXAMPLE = dict(radius=6.35e-3, speed=1.0, layer_thickness=3e-4, angle=30.0)


def test_physical_inputs_from_values_equal_the_presets():
    """The same numbers as a preset give the same groups and the same collision."""
    presets = from_presets(sphere="steel", wall="glass", liquid="silicone_oil_100cst", **EXAMPLE)
    values = from_presets(
        sphere={"young_modulus": 190e9, "poisson_ratio": 0.27, "density": 7780},
        wall={"preset": "acetal", "young_modulus": 60e9, "poisson_ratio": 0.23, "density": 2540},
        liquid={
            "viscosity": 0.0965,
            "density": 965,
            "vapour_pressure": 0,
            "pressure_viscosity": 1.5e-8,
        },
        **EXAMPLE,
    )
    assert values.dimensionless() == presets.dimensionless()
    first, second = (
        collide(c, RunConfig.from_settings(nodes=60)).summary() for c in (presets, values)
    )
    assert first["e_n"] == second["e_n"] and first["si"] == second["si"]


def test_vapour_pressure_must_be_below_the_ambient_pressure():
    with pytest.raises(InputError, match="vapour_pressure.*ambient"):
        from_presets(sphere="steel", wall="glass", liquid="water", ambient_pressure=2e3, **EXAMPLE)
    with pytest.raises(InputError, match="sphere must be a Material"):
        from_presets(sphere="steel", wall="glass", liquid="water", **EXAMPLE).__class__(
            sphere="steel", wall=material("glass"), liquid=liquid("water"), **EXAMPLE
        )


PHYSICAL_STUDY = """
name = "physical"
[physical]
sphere = "steel"
wall = {young_modulus = 60e9, poisson_ratio = 0.23, density = 2540}
liquid = {preset = "silicone_oil_100cst", viscosity = 0.0965}
radius = 6.35e-3
layer_thickness = 3e-4
[grid]
speed = [0.5, 1.0]
angle = [0.0]
[numerics]
nodes = 60
[output]
table = "out/physical.csv"
"""


def test_physical_study_runs_the_collisions_of_its_inputs(tmp_path):
    path = tmp_path / "physical.toml"
    path.write_text(PHYSICAL_STUDY)
    rows = run_study(Study(path), None, progress=None)
    assert [float(row["speed"]) for row in rows] == [0.5, 1.0]
    for row in rows:
        inputs = from_presets(
            sphere="steel",
            wall="glass",
            liquid="silicone_oil_100cst",
            radius=6.35e-3,
            layer_thickness=3e-4,
            speed=float(row["speed"]),
        )
        expected = collide(inputs, RunConfig.from_settings(nodes=60)).summary()
        assert row["e_n"] == expected["e_n"] and row["St"] == expected["St"]
        assert row["max_force_N"] == expected["si"]["max_force_N"]


@pytest.mark.parametrize(
    ("change", "message"),
    [
        (("radius = 6.35e-3\n", ""), "needs radius"),
        (("poisson_ratio = 0.23", "poisson_ratio = 0.7"), "wall.poisson_ratio"),
        (('sphere = "steel"', 'sphere = "unobtainium"'), "unobtainium"),
        (("speed = [0.5, 1.0]", "speed = [0.5, -1.0]"), "speed"),
        (("angle = [0.0]", "St = [1.0]"), "St"),
        (("radius = 6.35e-3", "radius = 6.35e-3\ncolour = 1"), "colour"),
    ],
)
def test_bad_physical_studies_are_refused_before_any_work(tmp_path, change, message):
    path = tmp_path / "bad.toml"
    path.write_text(PHYSICAL_STUDY.replace(*change))
    with pytest.raises(InputError, match=message):
        Study(path)


class Terminal(io.StringIO):
    """Standard error as a terminal."""

    def isatty(self):
        return True


def test_progress_bars_only_on_a_terminal_of_rank_zero(monkeypatch):
    monkeypatch.delenv("EHDFEM_PROGRESS", raising=False)
    items = range(5)
    assert progress.progress(items, desc="x") is items  # pytest's stderr is no terminal
    terminal = Terminal()
    monkeypatch.setattr("sys.stderr", terminal)
    assert list(progress.progress(items, desc="counting")) == list(items)
    assert "counting" in terminal.getvalue() and "/5 [" in terminal.getvalue()
    with progress.Counter(4, "bisection") as bar:
        bar.advance_to(3, total=6)
        with bar.paused():
            pass
    assert "bisection" in terminal.getvalue()
    monkeypatch.setenv("EHDFEM_PROGRESS", "0")
    assert progress.progress(items) is items
    monkeypatch.setenv("EHDFEM_PROGRESS", "1")
    monkeypatch.setattr(progress, "rank", lambda: 1)
    assert progress.progress(items) is items and not progress.enabled()
