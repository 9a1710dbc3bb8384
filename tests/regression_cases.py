"""The cases of the refactoring regression table (tests/test_regression.py).

Each case is (name, inputs, collide() keyword arguments). They cover both layers, every
cavitation model and viscosity law, both tangential models, sticking and rebounding spheres,
physical inputs and the FE model at one delta, on small film grids so that the whole table
runs in about a minute. Regenerate the stored table with
``python tests/regression_cases.py tests/data/regression.json`` only when a change of the
numbers is intended and understood.
"""

from __future__ import annotations

import json
import sys

from ehdfem.inputs.presets import EXAMPLE
from ehdfem.inputs.scales import CollisionParameters, from_presets
from ehdfem.outputs import registry

# The outputs of a sweep table row when the table was made (the keys of its cases), all in
# ehdfem.outputs.registry; their raw values (registry.computed) are compared, so that
# energy_error is compared for cavitating cases too, where the summary reports None.
OUTPUTS = (
    "rebound",
    "status",
    "e_n",
    "max_rebound_velocity",
    "min_film_thickness",
    "max_force",
    "contact_time",
    "max_compression",
    "e_t",
    "spin_change",
    "energy_error",
    "film_nodes",
)

THIN = dict(St=10.0, eps=1e-3, layer="thin")
IMMERSED = dict(St=20.0, eps=1e-3, layer="immersed")
FAST = dict(nodes=80)
# the time-step control the table was made with, and the LU in double precision: the
# table guards the numbers at 1e-8 across BLAS builds and CPUs, where an LU in single
# precision (the default since 2026-11-29) moves the Newton iterates, within its tolerance, by
# 6e-8 of their updates (tests/test_normal.py holds the default against double precision)
BEFORE = dict(rtol=5e-5, film_control=False, lu_precision="double")
FE_CASE = CollisionParameters.from_settings(
    St=10.0,
    eps=1e-3,
    delta=0.01,
    layer="thin",
    p_cav=-2.0,
    angle=30.0,
    gap="paraboloid",
    shear_traction=False,
)


def cases():
    """(name, CollisionParameters or PhysicalCollision, collide() keywords)."""
    p = CollisionParameters.from_settings
    return [
        ("thin-none-headon", p(**THIN), FAST),
        ("thin-truncate-couette", p(**THIN, p_cav=-2.0, angle=30.0), FAST),
        (
            "thin-truncate-lubrication",
            p(**THIN, p_cav=-2.0, angle=30.0),
            {**FAST, "tangential": "lubrication"},
        ),
        (
            "thin-masscons-couette",
            p(**THIN, p_cav=-2.0, cavitation="mass-conserving", angle=30.0),
            FAST,
        ),
        (
            "thin-masscons-lubrication",
            p(**THIN, p_cav=-2.0, cavitation="mass-conserving", angle=30.0),
            {**FAST, "tangential": "lubrication"},
        ),
        ("thin-barus", p(**THIN, p_cav=-2.0, viscosity="barus", alpha=0.02, angle=20.0), FAST),
        (
            "thin-roelands",
            p(
                **THIN,
                p_cav=-2.0,
                viscosity="roelands",
                alpha=0.02,
                roelands_pressure=200.0,
                angle=20.0,
            ),
            FAST,
        ),
        ("thin-cavitation-none-flag", p(**THIN, p_cav=-2.0, cavitation="none", angle=10.0), FAST),
        ("thin-sticks", p(St=2.0, eps=1e-3, layer="thin", angle=30.0), FAST),
        ("thin-stiff", p(St=50.0, eps=1e-5, layer="thin", p_cav=-5.0), FAST),
        (
            "thin-soft",
            p(St=100.0, eps=1e-2, layer="thin", p_cav=-10.0, angle=45.0),
            {**FAST, "tangential": "lubrication"},
        ),
        (
            "thin-spin-edry-inertia",
            p(**THIN, p_cav=-2.0, angle=20.0, spin=0.3, e_dry=0.8, inertia_factor=2 / 3),
            FAST,
        ),
        ("immersed-none", p(**IMMERSED), FAST),
        ("immersed-truncate", p(**IMMERSED, p_cav=-5.0, angle=30.0), FAST),
        (
            "immersed-masscons",
            p(**IMMERSED, p_cav=-5.0, cavitation="mass-conserving", angle=30.0),
            FAST,
        ),
        (
            "immersed-barus-lubrication",
            p(**IMMERSED, p_cav=-5.0, viscosity="barus", alpha=0.005, angle=45.0),
            {**FAST, "tangential": "lubrication"},
        ),
        (
            "immersed-roelands",
            p(**IMMERSED, viscosity="roelands", alpha=0.02, roelands_pressure=200.0),
            FAST,
        ),
        ("immersed-sticks", p(St=5.0, eps=1e-3, layer="immersed", angle=30.0), FAST),
        ("thin-rtol", p(**THIN, p_cav=-2.0), {**FAST, "options": {"rtol": 1e-6}}),
        (
            "physical-example",
            from_presets(**EXAMPLE),
            FAST,
        ),
        (
            "physical-masscons-roelands",
            from_presets(
                sphere="glass",
                wall="glass",
                liquid="silicone_oil_100cst",
                radius=3e-3,
                speed=0.5,
                angle=20.0,
                layer_thickness=2e-4,
                cavitation="mass-conserving",
                viscosity="roelands",
            ),
            FAST,
        ),
        ("fem-thin-truncate", FE_CASE, {"nodes": 60, "model": "fem"}),
        (
            "fem-thin-lubrication",
            FE_CASE,
            {"nodes": 60, "model": "fem", "tangential": "lubrication"},
        ),
    ]


def run(inputs, keywords):
    """The regression outputs of one case (a dict of floats, None where not defined)."""
    from ehdfem.collision import collide
    from ehdfem.config import RunConfig

    settings = {**BEFORE, **keywords}
    settings.update(settings.pop("options", {}))  # the time-step settings of the case
    values = registry.computed(collide(inputs, RunConfig.from_settings(**settings)))
    return {name: values[name] for name in OUTPUTS}


if __name__ == "__main__":
    table = {name: run(inputs, keywords) for name, inputs, keywords in cases()}
    with open(sys.argv[1], "w") as f:
        json.dump(table, f, indent=1)
        f.write("\n")
