"""The run configuration: its JSON round trip (and the earlier JSON format), studies sweeping
its fields, and the command line generated from the fields' metadata."""

import csv
import json

import pytest

from ehdfem import RunConfig, collide, elasticity, film_radii
from ehdfem.checks import InputError
from ehdfem.cli.main import main, parsers
from ehdfem.collision import with_tangential
from ehdfem.config import read_inputs, setting_names
from ehdfem.film.asperities import GreenwoodTrippAsperities
from ehdfem.inputs.scales import CollisionParameters, PhysicalCollision, from_presets
from ehdfem.outputs import registry
from ehdfem.solids.fe.bodies import CoatedWall
from ehdfem.study.sweep import PHYSICAL_FIELDS, Study, parameter_names, run_study

pytestmark = pytest.mark.serial


def test_every_collide_option_has_help_and_a_shown_default():
    _, commands = parsers()
    for action in commands["collide"]._actions:
        if action.option_strings == ["-h", "--help"]:
            continue
        assert action.help, action.option_strings
        assert "default:" in action.help, action.option_strings


def test_setting_names_are_disjoint_from_the_inputs():
    """A study's grid keys name one thing each: no run setting is also an input field."""
    assert not set(setting_names()) & (set(parameter_names()) | set(PHYSICAL_FIELDS))


def test_config_round_trips_through_the_json():
    """summary()["inputs"] -> read_inputs gives the same parameters and configuration
    (exactly: the JSON holds the values as they were), dimensionless and physical."""
    config = RunConfig.from_settings(nodes=40, tangential="gcb", rtol=1e-3, order=3)
    params = CollisionParameters.from_settings(St=10.0, eps=1e-3, p_cav=-2.0, angle=20.0)
    inputs = json.loads(json.dumps(collide(params, config).summary()["inputs"]))
    assert read_inputs(inputs) == (params, config)
    physical = from_presets(
        sphere="steel", wall="glass", liquid="silicone_oil_100cst", radius=6.35e-3, speed=1.0,
        layer_thickness=3e-4,
    )  # fmt: skip
    inputs = json.loads(json.dumps(collide(physical, config).summary()["inputs"]))
    assert read_inputs(inputs) == (physical, config)


def test_a_lower_body_round_trips_through_its_settings():
    config = RunConfig.from_settings(model="fem", lower="coated", coating_thickness=0.05)
    assert config.lower == CoatedWall(coating_thickness=0.05)
    assert RunConfig.from_settings(**config.settings()) == config


TODAYS_FORMAT = {  # a result's "inputs" as written before the inputs' components (0.1.0)
    "parameters": {
        "St": 10.0, "eps": 0.001, "delta": 0.01, "p_cav": -2.0, "e_dry": 1.0, "layer": "thin",
        "angle": 0.0, "spin": 0.0, "inertia_factor": 0.4, "cavitation": "truncate",
        "viscosity": "constant", "alpha": 0.0, "roelands_pressure": None,
        "roelands_index": 0.6, "gap": None, "shear_traction": None, "external_force": 0.0,
        "buoyant_weight": 0.0, "friction_coefficient": 0.0, "roughness": 0.0,
        "asperity_density": 0.04, "asperity_slope": 0.001,
    },
    "physical": None,
    "run": {
        "model": "halfspace", "tangential": "couette", "deformation": "gap",
        "asperities": "impact", "lower": "wall", "nodes": 40, "refinements": 2, "rtol": 0.0002,
        "film_control": True, "order": 4, "max_growth": 1.5, "newton_tol": 1e-07,
        "max_newton": 30, "first_step": 0.001, "max_steps": 50000, "max_time": 10000.0,
        "exit_gap": 1.0,
    },
}  # fmt: skip


def test_todays_json_format_replays_with_collide_from(tmp_path, capsys):
    """A result file in today's format (written out above, not by the code under test) is
    read back to its inputs and run settings, collide --from reruns it to the outputs of the
    same collision computed directly, and a lower body's flat settings in that format
    become that body."""
    params, config = read_inputs(TODAYS_FORMAT)
    assert params == CollisionParameters.from_settings(St=10.0, eps=1e-3, p_cav=-2.0)
    # written when Newton's tolerance was 1e-7 whatever rtol and the LU in double precision:
    # replayed with them, as it ran
    assert config == RunConfig.from_settings(nodes=40, newton_tol=1e-7, lu_precision="double")
    source, again = tmp_path / "today.json", tmp_path / "again.json"
    source.write_text(json.dumps({"inputs": TODAYS_FORMAT}))
    assert main(["collide", "--from", str(source), "--json", str(again)]) == 0
    replayed = json.loads(again.read_text())
    direct = collide(params, config).summary()
    names = [name for name in registry.names() if name in direct]
    assert {k: replayed[k] for k in names} == {k: direct[k] for k in names}
    assert RunConfig.from_settings(**replayed["inputs"]["run"]) == config
    coated = {**TODAYS_FORMAT["run"], "model": "fem", "lower": "coated"}
    coated.update(coating_thickness=0.05, coating_stiffness=2.0, coating_poisson=0.25)
    _, config = read_inputs({**TODAYS_FORMAT, "run": coated})
    assert config.lower == CoatedWall(0.05, 2.0, 0.25) and config.model == "fem"
    capsys.readouterr()


def test_a_lower_body_without_its_required_setting_is_refused_by_name():
    with pytest.raises(InputError, match="lower = 'coated' needs coating_thickness") as caught:
        RunConfig.from_settings(model="fem", lower="coated")
    assert caught.value.name == "coating_thickness"


def test_the_earlier_json_format_is_read():
    """The earlier `inputs`: parameters, physical, and the run options at the top level (a
    coating as (E, nu) in Pa for physical inputs: its stiffness is E over the wall's), with
    the Newton matrix's LU in double precision, as they ran."""
    earlier = {
        "parameters": {"St": 10.0, "eps": 1e-3, "p_cav": None, "angle": 30.0},
        "physical": None,
        "model": "fem",
        "rtol": 1e-3,
        "nodes": 60,
        "tangential": "lubrication",
        "solids": {"lower": "coated", "coating": (30e9, 0.25), "coating_thickness": 0.1},
    }
    params, config = read_inputs(earlier)
    assert params == CollisionParameters.from_settings(St=10.0, eps=1e-3, angle=30.0)
    assert (config.model, config.tangential, config.numerics.nodes) == ("fem", "lubrication", 60)
    assert config.options.rtol == 1e-3 and config.lower.coating_stiffness == 30e9
    assert config.options.lu_precision == "double"  # as it ran
    physical = from_presets(
        sphere="steel", wall="glass", liquid="water", radius=1e-3, speed=1.0,
        layer_thickness=1e-4,
    )  # fmt: skip
    inputs = json.loads(json.dumps(collide(physical).summary()["inputs"]))
    earlier = {**earlier, "physical": inputs["physical"], "parameters": inputs["parameters"]}
    found, config = read_inputs(earlier)
    assert isinstance(found, PhysicalCollision) and found == physical
    assert config.lower.coating_stiffness == pytest.approx(30e9 / 60e9, rel=1e-15)


# the "inputs" of a result JSON as the code before the components wrote it (every field of
# the flat CollisionParameters: each viscosity law's constants and P_cav whatever the model)
TODAYS_INPUTS = {
    "parameters": {
        "St": 6.0, "eps": 1e-3, "delta": 0.01, "p_cav": -2.0, "e_dry": 1.0, "layer": "thin",
        "angle": 30.0, "spin": 0.0, "inertia_factor": 0.4, "cavitation": "mass-conserving",
        "viscosity": "roelands", "alpha": 0.05, "roelands_pressure": 40.0,
        "roelands_index": 0.5, "gap": None, "shear_traction": None, "external_force": 0.0,
        "buoyant_weight": 0.0, "friction_coefficient": 0.0, "roughness": 0.0,
        "asperity_density": 0.04, "asperity_slope": 0.001,
    },
    "physical": None,
    "run": {
        "model": "halfspace", "lower": "wall", "tangential": "couette", "deformation": "gap",
        "asperities": "impact", "nodes": 60,
    },
}  # fmt: skip


@pytest.mark.slow
def test_todays_json_results_replay_with_from(tmp_path, capsys):
    """A result JSON in the format before the components (its inputs written literally here)
    is read with the same inputs as the components' flat settings give, and `collide --from`
    on it gives the collision of those inputs bit for bit; with the constant viscosity and no
    cavitation limit, the constants that cannot act (alpha = 0, the Roelands index) are left
    out; the asperity model, then a run setting, becomes the inputs' with its constants."""
    params, config = read_inputs(TODAYS_INPUTS)
    expected = CollisionParameters.from_settings(
        St=6.0, eps=1e-3, angle=30.0, p_cav=-2.0, cavitation="mass-conserving",
        viscosity="roelands", alpha=0.05, roelands_pressure=40.0, roelands_index=0.5,
    )  # fmt: skip
    # written with the LU in double precision: replayed with it, as it ran
    assert params == expected
    assert config == RunConfig.from_settings(nodes=60, lu_precision="double")
    source, again = tmp_path / "today.json", tmp_path / "again.json"
    source.write_text(json.dumps({"e_n": 0.5, "inputs": TODAYS_INPUTS}))
    assert main(["collide", "--from", str(source), "--json", str(again)]) == 0
    replayed = json.loads(again.read_text())
    direct = collide(expected, config)
    assert replayed["e_n"] == direct.normal.e_n and replayed["e_t"] == direct.tangential.e_t
    assert read_inputs(replayed["inputs"]) == (expected, config)
    plain = {**TODAYS_INPUTS["parameters"], "viscosity": "constant", "alpha": 0.0}
    plain.update(cavitation="truncate", p_cav=None, roelands_pressure=None)
    params, _ = read_inputs({**TODAYS_INPUTS, "parameters": plain})
    assert params == CollisionParameters(St=6.0, eps=1e-3, angle=30.0)
    rough = {**plain, "roughness": 0.03, "asperity_slope": 0.002}
    run = {**TODAYS_INPUTS["run"], "asperities": "greenwood-tripp"}
    params, config = read_inputs({**TODAYS_INPUTS, "parameters": rough, "run": run})
    assert params.asperities == GreenwoodTrippAsperities(0.03, asperity_slope=0.002)
    assert config == RunConfig.from_settings(nodes=60, lu_precision="double")


def test_a_study_sweeps_the_model_and_a_lower_body_field(tmp_path):
    """[grid] over run settings: the half-space and the FE wall, and a coated wall's
    thickness; the rows carry each point's settings. At delta = 1e-3 the FE solids are
    half-spaces to about 1 % (docs/fem.md): e_n agrees to 2 %."""
    study_file = tmp_path / "s.toml"
    study_file.write_text(
        "[grid]\nSt = [10.0]\neps = [1e-3]\ndelta = [1e-3]\np_cav = [-2.0]\n"
        'model = ["halfspace", "fem"]\n[numerics]\nnodes = 40\n'
    )
    rows = run_study(Study(study_file), None, progress=None)
    assert [row["model"] for row in rows] == ["halfspace", "fem"]
    assert all(row["nodes"] == 40 and row["lower"] == "wall" for row in rows)
    assert rows[1]["e_n"] == pytest.approx(rows[0]["e_n"], rel=0.02)
    with open(Study(study_file).table) as f:
        assert {"model", "lower", "rtol"} <= set(next(csv.DictReader(f)))
    coated = tmp_path / "c.toml"
    coated.write_text(
        "[grid]\nSt = [10.0]\neps = [1e-3]\ncoating_thickness = [0.05, 0.1]\n"
        '[run]\nmodel = "fem"\nlower = "coated"\n'
    )
    study = Study(coated)
    assert [study.config(p).lower.coating_thickness for p in study.points] == [0.05, 0.1]
    bad = tmp_path / "b.toml"
    bad.write_text("[grid]\nSt = [10.0]\neps = [1e-3]\nradius_ratio = [2.0]\n")
    with pytest.raises(InputError, match="radius_ratio needs lower = 'sphere'"):
        Study(bad)


def test_negative_numbers_in_scientific_notation_are_values(capsys):
    assert main(["collide", "--St", "10", "--eps", "1e-3", "--p-cav", "-1e1", "--nodes", "40",
                 "--json", "-"]) == 0  # fmt: skip
    assert json.loads(capsys.readouterr().out)["p_cav"] == -10.0


PAIR = ["--St", "1", "--eps", "1e-3", "--lower", "sphere"]  # two spheres, head-on


@pytest.mark.parametrize(
    ("args", "flag", "allowed"),
    [
        (["--St", "10", "--eps", "1e-3", "--delta", "2"], "--delta", "(0, 1)"),
        (["--St", "10", "--eps", "1e-3", "--nodes", "5"], "--nodes", "[20, 5000]"),
        (["--St", "10", "--eps", "1e-3", "--coating-poisson", "0.6"], "--coating-poisson", ""),
        (["--St", "10", "--eps", "1e-3", "--lower", "coated", "--coating-thickness", "0.1"],
         "--lower", "fem"),
        ([*PAIR, "--angle", "30", "--model", "fem", "--tangential", "lubrication"],
         "--tangential", "'couette', 'flat' or 'gcb'"),
        ([*PAIR, "--angle", "30", "--lower-inertia-factor", "0.7"], "--lower-inertia-factor",
         "(0, 0.666667]"),
        ([*PAIR, "--angle", "30", "--density-ratio", "0"], "--density-ratio", "(0, inf)"),
        ([*PAIR, "--lower-spin", "0.2"], "--lower-spin", "angle > 0"),
    ],
)  # fmt: skip
def test_a_bad_value_names_the_flag_and_the_allowed_range(args, flag, allowed, capsys):
    assert main(["collide", *args]) == 2
    err = capsys.readouterr().err
    assert err.startswith(f"ehdfem collide: error: {flag}: ") and allowed in err


def test_collide_takes_the_flat_run_settings_as_keywords():
    """collide(params, model=..., nodes=...) is collide(params, RunConfig.from_settings(...)),
    bit for bit; both at once, or an unknown setting, is refused with its name."""
    params = CollisionParameters.from_settings(St=10.0, eps=1e-3, p_cav=-2.0, angle=30.0)
    by_keywords = collide(params, nodes=40, tangential="lubrication", rtol=1e-3).summary()
    config = RunConfig.from_settings(nodes=40, tangential="lubrication", rtol=1e-3)
    by_config = collide(params, config).summary()
    by_keywords.pop("provenance"), by_config.pop("provenance")  # their dates may differ
    assert by_keywords == by_config
    with pytest.raises(InputError, match="either as config or as keywords"):
        collide(params, config, nodes=40)
    with pytest.raises(InputError, match="unknown run setting.*nodez"):
        collide(params, nodez=40)


def test_the_json_records_how_the_collision_was_computed():
    """inputs["run"] names the solids of a compliance passed in and the tangential model that
    with_tangential put on the collision, so that read_inputs reruns what was computed."""
    params = CollisionParameters.from_settings(St=10.0, eps=1e-3, p_cav=-2.0, angle=30.0)
    config = RunConfig.from_settings(nodes=40)
    rigid_free = collide(params, config)
    again = with_tangential(rigid_free, "lubrication", deformation="none")
    assert again.summary()["inputs"]["run"]["tangential"] == "lubrication"
    assert again.summary()["inputs"]["run"]["deformation"] == "none"
    assert rigid_free.summary()["inputs"]["run"]["tangential"] == "couette"
    _, read = read_inputs(again.summary()["inputs"])
    assert (read.tangential, read.deformation) == ("lubrication", "none")
    fem_config = RunConfig.from_settings(model="fem", nodes=40)
    solids = elasticity(params, film_radii(params, 40), fem_config)
    try:
        result = collide(params, config, compliance=solids)
    finally:
        solids.close()
    assert result.summary()["inputs"]["run"]["model"] == "fem"
