"""The registry of outputs (ehdfem.outputs.registry): every entry is described; the summary, a
study row and a bounce's contact carry exactly its names; SI values are the scaled ones times
the SI unit of their scale, formed here from the inputs; a new entry reaches every consumer;
the energy balance is withheld where a cavitation limit makes it meaningless."""

import math
import warnings
from pathlib import Path

import pytest

from ehdfem.bounce.inputs import BounceInputs
from ehdfem.bounce.run import BounceRun
from ehdfem.bounce.trajectory import bounce_sphere
from ehdfem.collision import collide
from ehdfem.config import RunConfig, setting_names
from ehdfem.film.cavitation import NO_LIMIT
from ehdfem.inputs.presets import EXAMPLE
from ehdfem.inputs.scales import CollisionParameters, from_presets
from ehdfem.outputs import registry
from ehdfem.study.sweep import Study, run_point

DOCS = Path(__file__).resolve().parent.parent / "docs"
OBLIQUE = CollisionParameters.from_settings(St=10.0, eps=1e-3, p_cav=-2.0, angle=30.0)
NODES_40 = RunConfig.from_settings(nodes=40)
# the outputs of rough surfaces' asperities, left out of a smooth collision's summary
ROUGH_ONLY = {o.name for o in registry.OUTPUTS if "asperit" in o.name or "impact" in o.name} | {
    "contact_stuck",
    "friction_dissipated",
    "solid_impulse_share",
}
# the estimate of the flow beyond an immersed film's tangential integrals, left out of a thin
# layer's summary (tests/test_outer_flow.py checks it in an immersed one's)
IMMERSED_ONLY = {o.name for o in registry.OUTPUTS if o.name.startswith("outer_film")}
PAIR_ONLY = {"lower_spin_change", "pair_balance_error"}  # two free spheres' outputs
STUDY = """
[grid]
St = [10.0]
eps = [1e-3]
p_cav = [-2.0]
angle = [30.0]
[numerics]
nodes = 40
"""
PHYSICAL_STUDY = """
[physical]
sphere = "steel"
wall = "glass"
liquid = "silicone_oil_100cst"
radius = 6.35e-3
layer_thickness = 3e-4
[grid]
speed = [1.0]
angle = [30.0]
[numerics]
nodes = 40
"""


@pytest.fixture(scope="module")
def sliding():
    """An oblique impact with the sliding film: every output has a value."""
    return collide(OBLIQUE, RunConfig.from_settings(nodes=40, tangential="lubrication"))


def test_every_entry_has_a_meaning_a_scale_and_a_unit():
    """Names are unique, SI keys too; a pure number ("-") has no SI unit, a scaled quantity
    has one; an SI key goes with a factor."""
    names = registry.names()
    assert len(set(names)) == len(names) and len(set(registry.si_keys())) == len(registry.si_keys())
    for o in registry.OUTPUTS:
        assert o.meaning and o.scale and callable(o.compute), o.name
        assert (o.scale == "-") == (o.unit is None), o.name
        assert (o.si_key is None) == (o.si_factor is None), o.name


def test_an_entry_without_a_meaning_or_with_half_an_si_value_is_refused():
    with pytest.raises(ValueError, match="meaning"):
        registry.Output("x", "", "x0", "m", lambda r: 0.0)
    with pytest.raises(ValueError, match="si_key and si_factor"):
        registry.Output("x", "a gap", "x0", "m", lambda r: 0.0, si_key="x_m")
    with pytest.raises(ValueError, match="applies and reason"):
        registry.Output("x", "a gap", "x0", "m", lambda r: 0.0, applies=lambda r: True)


def test_summary_carries_exactly_the_registry_names(sliding):
    """With the sliding film on half-spaces (a thin layer) every output but those of rough
    surfaces (the asperities and the friction of their solid contact), of immersed layers and of
    two spheres is in the summary; with the Couette film the optional ones of the sliding film
    (its diagnostics) are left out and only they, and a pair of spheres has the pair's; a rough
    oblique sphere's summary has the asperities' and the friction's outputs."""
    summary = sliding.summary()
    rough_only = ROUGH_ONLY
    assert set(registry.names()) - set(summary) == rough_only | IMMERSED_ONLY | PAIR_ONLY
    couette = collide(OBLIQUE, NODES_40).summary()
    missing = {name for name in registry.names() if name not in couette}
    optional = {o.name for o in registry.OUTPUTS if o.optional}
    sliding_only = optional - rough_only - IMMERSED_ONLY - PAIR_ONLY
    sliding_only -= {"load_radius", "halfspace_range_flag"}
    assert missing == sliding_only | rough_only | IMMERSED_ONLY | PAIR_ONLY
    pair = collide(OBLIQUE, nodes=40, lower="sphere").summary()
    absent = {name for name in registry.names() if name not in pair}
    assert absent == sliding_only | rough_only | IMMERSED_ONLY
    rough = OBLIQUE.with_settings(
        eps=1e-6, p_cav=NO_LIMIT, roughness=0.01, friction_coefficient=0.2
    )
    greenwood_tripp_only = {"max_asperity_force", "max_asperity_share"}  # impact model here
    assert rough_only - greenwood_tripp_only <= set(collide(rough, NODES_40).summary())
    assert sliding.summary()["not_applicable"] == registry.not_applicable(sliding)


def test_study_rows_carry_exactly_the_registry_names(tmp_path):
    """A dimensionless study row has every output; a physical one also every SI key."""
    for name, text, keys in (
        ("scaled", STUDY, registry.names()),
        ("physical", PHYSICAL_STUDY, (*registry.names(), *registry.si_keys())),
    ):
        (tmp_path / f"{name}.toml").write_text(text)
        study = Study(tmp_path / f"{name}.toml")
        row = run_point(study, study.points[0])
        assert row["status"] == "ok:rebound"
        assert set(keys) <= set(row), name
        settings = set(setting_names())  # the point's run settings
        unknown = (
            set(row)
            - set(keys)
            - settings
            - set(study.points[0])
            - {"seconds", "version", "commit"}
        )
        assert unknown <= {"St", "eps", "delta", "p_cav"}, unknown


@pytest.mark.slow
def test_a_bounce_contact_carries_every_output_once_in_si_where_it_has_a_unit():
    """Steel on glass in a 10 cSt oil, released from 3 mm: the contact's film outputs are the
    registry's, under the SI key where there is one; with the truncation cavitation limit the
    energy balance is withheld."""
    inputs = BounceInputs(
        radius=1.5e-3,
        sphere="steel",
        wall="glass",
        liquid="silicone_oil_10cst",
        release_height=3e-3,
    )
    result = bounce_sphere(inputs, BounceRun(max_bounces=1))
    contact = result.contacts[0]
    expected = {o.si_key or o.name for o in registry.OUTPUTS}
    assert set(contact.film) == expected
    assert contact.status == contact.film["status"] == "rebound"
    assert contact.film["energy_error"] is None
    row = result.contact_rows()[0]
    assert expected <= set(row) and "film" not in row


def test_si_values_are_the_scaled_ones_times_the_units_of_their_scales():
    """The example (steel on glass, 100 cSt oil, 1 m/s at 30 degrees, x0 = 0.3 mm, a =
    6.35 mm): x0, x0/V0, V0 and 6 pi mu V0 a^2 / x0 with V0 = |v| cos(30 deg), U0 = |v|
    sin(30 deg), U0/a, a and m U0, formed here from the inputs; equal to 1e-14 relative (two
    roundings of a product)."""
    physical = from_presets(**EXAMPLE)
    summary = collide(physical, NODES_40).summary()
    x0, a, mu = physical.layer_thickness, physical.radius, physical.liquid.viscosity
    v0 = physical.speed * math.cos(math.radians(physical.angle))
    u0 = physical.speed * math.sin(math.radians(physical.angle))
    units = {
        "min_film_thickness": x0,
        "max_compression": x0,
        "contact_time": x0 / v0,
        "e_n": v0,
        "max_force": 6 * math.pi * mu * v0 * a**2 / x0,
        "e_t": u0,
        "spin_change": u0 / a,
        "load_radius": a,
        "tangential_impulse": physical.mass * u0,  # 4/3 pi a^3 rho U0, no added mass here
    }
    si = summary["si"]
    absent = ROUGH_ONLY | IMMERSED_ONLY
    rough_si = {o.si_key for o in registry.OUTPUTS if o.name in absent}
    assert set(si) == set(registry.si_keys()) - rough_si
    for o in registry.OUTPUTS:
        if o.si_key is not None and o.name not in absent:
            assert si[o.si_key] == pytest.approx(summary[o.name] * units[o.name], rel=1e-14)


def test_a_new_entry_reaches_the_summary_the_study_row_and_the_table(tmp_path, monkeypatch):
    """One Output added to the registry, nothing else changed."""
    new = registry.Output(
        "central_film_at_exit",
        "film thickness on the axis at the end",
        "x0",
        "m",
        lambda r: float(r.normal.history.central_film[-1]),
        "central_film_at_exit_m",
        lambda p: p.scales().gap,
    )
    monkeypatch.setattr(registry, "OUTPUTS", (*registry.OUTPUTS, new))
    result = collide(OBLIQUE, NODES_40)
    summary = result.summary()
    assert summary["central_film_at_exit"] == result.normal.history.central_film[-1]
    assert "central_film_at_exit" in registry.format_table(summary)
    (tmp_path / "study.toml").write_text(STUDY)
    study = Study(tmp_path / "study.toml")
    assert run_point(study, study.points[0])["central_film_at_exit"] > 0
    physical = collide(from_presets(**EXAMPLE), NODES_40).summary()
    assert physical["si"]["central_film_at_exit_m"] == pytest.approx(
        physical["central_film_at_exit"] * EXAMPLE["layer_thickness"], rel=1e-15
    )
    assert "central_film_at_exit_m" in registry.format_table(physical)
    si_rows = {row[0]: row for row in registry.table_rows(physical)}
    assert si_rows["central_film_at_exit_m"][2:] == ("m", "central_film_at_exit times x0")
    assert si_rows["rebound_normal_speed_m_s"][3] == "e_n times V0"  # its SI value, not e_n


@pytest.mark.parametrize(
    "changes,applies",
    [
        ({}, True),  # P_cav = -inf: no limit
        ({"p_cav": -2.0, "cavitation": "none"}, True),  # warned of: no limit with "none"
        ({"p_cav": -2.0}, False),
        ({"p_cav": -2.0, "cavitation": "mass-conserving"}, False),
    ],
)
def test_energy_error_only_without_a_cavitation_limit(changes, applies):
    """The balance is reported without a cavitation limit, else None with the reason; the
    raw number stays available either way."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # p_cav has no effect with "none"
        params = CollisionParameters.from_settings(St=10.0, eps=1e-3, **changes)
    result = collide(params, NODES_40)
    summary = result.summary()
    raw = registry.computed(result)["energy_error"]
    assert raw == result.normal.energy_error
    if applies:
        assert summary["energy_error"] == raw and summary["not_applicable"] == {}
    else:
        assert summary["energy_error"] is None
        assert "cavitation limit" in summary["not_applicable"]["energy_error"]
        assert "n/a" in registry.format_table(summary)


def test_table_rows_give_name_value_scale_and_meaning(sliding):
    rows = registry.table_rows(sliding.summary())
    absent = ROUGH_ONLY | IMMERSED_ONLY | PAIR_ONLY
    assert [row[0] for row in rows] == [n for n in registry.names() if n not in absent]
    e_n = next(row for row in rows if row[0] == "e_n")
    meaning = next(o.meaning for o in registry.OUTPUTS if o.name == "e_n")
    assert e_n == ("e_n", f"{sliding.normal.e_n:.6g}", "V0", meaning)


def test_docs_list_every_output():
    """docs/outputs.md holds the registry's table (registry.markdown_table)."""
    text = (DOCS / "outputs.md").read_text()
    assert registry.markdown_table() in text
    for name in registry.names():
        assert f"| `{name}` |" in text


def test_a_physical_collision_is_plotted_in_si(monkeypatch):
    """histories.png and profiles.png of a physical collision: the axes in SI (m, m/s, N, Pa,
    s) with the values scaled by its Scales; the legend of the profiles beside the plots."""
    from ehdfem.outputs import plots

    result = collide(from_presets(**EXAMPLE), RunConfig.from_settings(nodes=80))
    units = result.physical.scales()
    monkeypatch.setattr(plots, "_save", lambda fig, path: fig)
    histories = plots.plot_histories(result.normal, "h.png", units)
    labels = [ax.get_ylabel() for ax in histories.axes]
    assert labels == ["gap x [m]", "velocity v [m/s]", "force F [N]", "film h [m]"]
    assert histories.axes[0].get_xlabel() == "" and histories.axes[2].get_xlabel() == "t [s]"
    gap = histories.axes[0].lines[0].get_ydata()
    assert gap[0] == pytest.approx(units.gap * result.normal.history.gap[0], rel=1e-12)
    profiles = plots.plot_profiles(result.normal, "p.png", units)
    assert profiles.axes[0].get_xlabel() == "r [m]"
    assert profiles.axes[0].get_ylabel().startswith("pressure p [Pa]")
    legend = profiles.axes[1].get_legend()
    assert legend.get_texts()[0].get_text().endswith(" s") and legend.get_bbox_to_anchor()
