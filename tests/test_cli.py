"""`ehdfem collide`: results, JSON, plots, and refusal of bad inputs before any work."""

import json

import numpy as np
import pytest

from ehdfem.checks import InputError
from ehdfem.cli import main

pytestmark = pytest.mark.serial

REQUIRED = {
    "rebound",
    "e_n",
    "St",
    "eps",
    "delta",
    "min_film_thickness",
    "max_force",
    "contact_time",
}


def test_dimensionless_collision_writes_json_and_plots(tmp_path, capsys):
    out = tmp_path / "r.json"
    code = main(
        [
            "collide",
            "--St",
            "10",
            "--eps",
            "1e-3",
            "--p-cav",
            "-2",
            "--angle",
            "30",
            "--json",
            str(out),
            "--plots",
            str(tmp_path / "plots"),
        ]
    )
    assert code == 0
    result = json.loads(out.read_text())
    assert REQUIRED <= result.keys()
    assert result["rebound"] is True and 0 < result["e_n"] < 1 and 0 < result["e_t"] < 1
    for name in ("histories.png", "profiles.png", "tangential.png"):
        assert (tmp_path / "plots" / name).stat().st_size > 10_000
    assert "e_n" in capsys.readouterr().out


def test_physical_collision_reports_si_values(capsys):
    code = main(["collide", "--example", "--json", "-"])
    assert code == 0
    text = capsys.readouterr().out
    result = json.loads(text[text.index("{") :])
    assert result["si"]["contact_time_s"] > 0 and result["St"] > 1


def test_film_options_reach_the_collision(capsys):
    """--cavitation and --viscosity with a physical alpha arrive scaled in the results:
    alpha = alpha_SI mu V0 a / x0^2 for the example's oil, speed and layer."""
    args = [
        "--example",
        "--speed",
        "0.2",
        "--cavitation",
        "mass-conserving",
        "--viscosity",
        "barus",
    ]
    assert main(["collide", *args, "--pressure-viscosity", "2e-8", "--json", "-"]) == 0
    text = capsys.readouterr().out
    result = json.loads(text[text.index("{") :])
    scale = 0.0965 * 0.2 * np.cos(np.radians(30)) * 6.35e-3 / 3e-4**2
    assert result["cavitation"] == "mass-conserving" and result["viscosity"] == "barus"
    assert result["alpha"] == pytest.approx(2e-8 * scale, rel=1e-12)


@pytest.mark.parametrize(
    ("args", "name"),
    [
        (["--St", "0", "--eps", "1e-3"], "St"),
        (["--St=-5", "--eps", "1e-3"], "St"),
        (["--St", "10", "--eps", "0"], "eps"),
        (["--St", "10", "--eps=-1e-3"], "eps"),
        (["--St", "10", "--eps", "1e-3", "--delta", "0"], "delta"),
        (["--St", "10", "--eps", "1e-3", "--angle", "90"], "angle"),
        (["--St", "10", "--eps", "1e-3", "--angle=-1"], "angle"),
        (["--St", "10", "--eps", "1e-3", "--e-dry", "0"], "e_dry"),
        (["--St", "10", "--eps", "1e-3", "--e-dry", "1.2"], "e_dry"),
        (["--St", "10", "--eps", "1e-3", "--p-cav", "3"], "p_cav"),
        (["--St", "nan", "--eps", "1e-3"], "St"),
        (["--example", "--sphere", "unobtainium"], "unobtainium"),
        (["--example", "--liquid", "mercury_tea"], "mercury_tea"),
        (["--St", "10"], "eps"),
        (["--St", "10", "--eps", "1e-3", "--viscosity", "barus", "--alpha=-1"], "alpha"),
        (["--St", "10", "--eps", "1e-3", "--viscosity", "roelands"], "roelands_pressure"),
        (["--St", "10", "--eps", "1e-3", "--pressure-viscosity", "1e-8"], "--alpha"),
        (["--example", "--alpha", "0.1"], "--pressure-viscosity"),
        (["--example", "--viscosity", "barus", "--pressure-viscosity", "1"], "pressure_viscosity"),
    ],
)
def test_bad_inputs_are_refused_with_the_parameter_named(args, name, capsys):
    assert main(["collide", *args]) == 2
    err = capsys.readouterr().err
    assert name in err and "Traceback" not in err


def test_field_instants_include_requested_times():
    """Maximum compression, maximum force, the end, and requested times (pressure linear in T
    between steps); a time outside the collision is refused."""
    from ehdfem.collision import collide
    from ehdfem.exports import field_snapshots
    from ehdfem.scales import CollisionParameters

    normal = collide(CollisionParameters(St=10.0, eps=1e-3, p_cav=-2.0), nodes=60).normal
    hist = normal.history
    t = 0.5 * (hist.time[10] + hist.time[11])
    snapshots = field_snapshots(normal, [t])
    times = [s[0] for s in snapshots]
    assert times == sorted(times) and t in times and hist.time[-1] in times
    assert (
        hist.time[int(hist.gap.argmin())] in times and hist.time[int(hist.force.argmax())] in times
    )
    pressure = dict(snapshots)[t]
    assert np.allclose(pressure, 0.5 * (hist.pressure[10] + hist.pressure[11]))
    with pytest.raises(InputError, match="field time"):
        field_snapshots(normal, [hist.time[-1] + 1])
