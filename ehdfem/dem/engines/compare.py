"""An engine's rebound beside the full model's at the same physical inputs (SI).

Yade's sphere on a wall is the full model's collision as given. LIGGGHTS's two equal spheres
(radius R, mass m, relative speed V0) are set beside the half-space model at the reduced radius
R/2 and mass m/2 with theta summed over both spheres: the asymptotic theory of Davis, Serayssol
& Hinch (1986) is exact for two spheres so at leading order in x0 / R, and it runs in seconds
where the FE model's lower sphere (``--lower sphere``) takes minutes; both spheres here are of
one material (theta = 2 (1 - nu^2) / (pi E)). Obliquely, the pair's tangential motion is the
sphere on a wall's with the contact spin w = a1 Omega1 + a2 Omega2 and the pair's inertia
factor, which for equal spheres is each one's (docs/tangential.md, "Two spheres"): the reduced
collision starts with w = R Omega1(0) (sphere 1's spin R Omega1 over the reduced radius R/2 is
twice its rate), and each sphere takes half of the change of w.
"""

from __future__ import annotations

import dataclasses
from pathlib import Path
from typing import Protocol

from ... import checks
from ...collision import collide
from ...config import RunConfig
from ...inputs.scales import PhysicalCollision
from . import liggghts, yade
from .rebound import EngineRebound


class EngineRun(Protocol):
    """An engine's run: write its input into a folder, run its binary, read the rebound."""

    def __call__(self, collision: PhysicalCollision, law, folder: Path) -> EngineRebound: ...


ENGINES: dict[str, tuple[type, EngineRun]] = {  # name: (its law's settings, its run)
    "yade": (yade.YadeLaw, yade.run),
    "liggghts": (liggghts.LiggghtsLaw, liggghts.run),
}


RERUN = {"yade": yade.RERUN, "liggghts": liggghts.RERUN}  # name: its command to rerun by hand

ROUGHNESS = {  # name: (its law's setting for the surfaces' roughness, its value of a collision)
    "yade": ("yade_roughness", yade.roughness_of),
    "liggghts": ("liggghts_min_separation", liggghts.min_separation_of),
}


def engine_law(engine: str, collision: PhysicalCollision, settings: dict):
    """``engine``'s law with ``settings`` (its fields by name); on rough surfaces (sigma > 0)
    the setting that stands for the asperities, unless given, is the collision's roughness
    (:data:`ROUGHNESS`: Yade's eps = sigma / (2 a), LIGGGHTS's minimum gap 3 sigma), as the
    full model's is."""
    checks.choice("engine", engine, tuple(ENGINES))
    name, of_roughness = ROUGHNESS[engine]
    if collision.roughness > 0.0 and name not in settings:
        settings = settings | {name: of_roughness(collision)}
    return ENGINES[engine][0](**settings)


def check_engine_inputs(engine: str, collision: PhysicalCollision) -> None:
    """Refuse inputs that the engine's scene leaves out, so that both sides collide alike: the
    engines run a thin layer without gravity, and Yade's contact spring is undamped (e_dry 1;
    LIGGGHTS's Hertz contact takes e_dry as its coefficientRestitution)."""
    checks.choice("engine", engine, tuple(ENGINES))
    if collision.layer != "thin":
        raise checks.InputError("the engines' scenes are a thin layer: layer must be thin", "layer")
    if collision.gravity != 0.0:
        raise checks.InputError("the engines' scenes have no gravity: gravity must be 0", "gravity")
    if engine == "yade" and collision.e_dry != 1.0:
        raise checks.InputError(
            "Yade's contact spring is undamped: e_dry must be 1 with --engine yade", "e_dry"
        )


def full_model_collision(engine: str, collision: PhysicalCollision) -> PhysicalCollision:
    """The full model's collision beside ``engine``'s: the same (Yade), or the reduced radius
    R/2 and mass m/2 of two equal spheres (LIGGGHTS; see the module docstring)."""
    check_engine_inputs(engine, collision)
    if engine == "yade":
        return collision
    liggghts.check_equal_spheres(collision)
    return dataclasses.replace(
        collision,
        radius=collision.radius / 2,
        sphere_mass=collision.mass / 2,
        spin=2.0 * collision.spin,
    )


def compare(
    engine: str, collision: PhysicalCollision, law, folder: Path, config: RunConfig | None = None
) -> dict:
    """``engine`` run on ``collision`` with ``law`` in ``folder``, and the full model (run with
    ``config``) at the same inputs: the engine's rebound, the full model's e_n, e_t and spin
    change, its solids ("model": halfspace or fem), St, eps, delta, roughness sigma / x0 and
    asperity model, the difference e_n(engine) - e_n(full model), and the inputs of ehdfem's
    collision (as collide's JSON holds them: ``collide --from`` runs it again)."""
    config = config or RunConfig()
    if engine == "liggghts" and config.model != "halfspace":
        raise checks.InputError(
            "LIGGGHTS's two spheres are compared with the half-space model at the reduced "
            "radius and mass (ehdfem.dem.engines.compare)",
            "model",
        )
    full = full_model_collision(engine, collision)
    rebound = ENGINES[engine][1](collision, law, Path(folder))
    result = collide(full, config)
    params = full.dimensionless()
    tangential = result.tangential
    spin_share = 0.5 if engine == "liggghts" else 1.0  # sphere 1's share of the contact spin
    model = {
        "model": result.model,
        "St": params.St,
        "eps": params.eps,
        "delta": params.delta,
        "roughness": params.roughness,
        "asperities": params.asperities.name,
        "e_n": result.normal.e_n,
        "e_t": None if tangential is None else tangential.e_t,
        "spin_change": None if tangential is None else spin_share * tangential.spin_change,
    }
    return {
        "engine": rebound.summary(),
        "law": dataclasses.asdict(law),
        "full_model": model,
        "e_n_difference": rebound.e_n - model["e_n"],
        "inputs": result.inputs(),
    }
