"""A sphere settling onto a wall in a liquid and bouncing until it rests: its trajectory, each
contact an immersed EHD collision (docs/bounce.md). :func:`bounce_sphere` computes it from the
bounce's physical inputs (:class:`ehdfem.bounce.inputs.BounceInputs`, SI).

The parts, by role: the flight between contacts, its force laws and the hand-over criterion
(:mod:`ehdfem.bounce.flight`); the film model of each contact from the hand-over to the exit
(:mod:`ehdfem.bounce.contact`); the loop of flight legs and contacts until the sphere rests,
with the trajectory's samples and energies (:mod:`ehdfem.bounce.loop`); the result, its rows
and its JSON summary (:mod:`ehdfem.bounce.result`).
"""

from __future__ import annotations

from .. import checks
from ..config import DEFAULT_NODES
from ..motion.timestepping import IntegratorOptions
from .contact import MODELS, ImmersedCollision
from .flight import EHD_MULTIPLE, HANDOVER_JUMP, FarField, FlightState
from .inputs import BounceInputs
from .loop import BounceLoop
from .result import BounceResult


def bounce_sphere(
    inputs: BounceInputs,
    model: str = "halfspace",
    nodes: int = DEFAULT_NODES,
    options: IntegratorOptions | None = None,
    handover_jump: float = HANDOVER_JUMP,
    ehd_multiple: float = EHD_MULTIPLE,
    max_bounces: int = 30,
    rest_apex: float = 1e-3,
) -> BounceResult:
    """The trajectory of a sphere settling onto a wall in a liquid and bouncing until it rests
    (module docstring). ``model``: the solids of the contacts, "halfspace" (the elastic
    half-space theory) or "rigid" (eps -> 0); the FE solids do not apply to the immersed film,
    which reaches beyond the sphere. ``nodes`` and ``options``: the film model's grid and
    time-step control. ``handover_jump`` in (0, 0.5), ``ehd_multiple`` >= 1: the hand-over
    criterion. ``max_bounces``: the most contacts computed. ``rest_apex``: an apex below this
    fraction of D ends the bounce."""
    if not isinstance(inputs, BounceInputs):
        raise checks.InputError(f"inputs must be BounceInputs, got {inputs!r}")
    checks.choice("model", model, MODELS)
    checks.integer("nodes", nodes, lower=20, upper=5000)
    checks.number(
        "handover_jump", handover_jump, lower=0.0, upper=0.5, lower_open=True, upper_open=True
    )
    checks.number("ehd_multiple", ehd_multiple, lower=1.0, upper=1e4)
    checks.integer("max_bounces", max_bounces, lower=1, upper=1000)
    checks.number("rest_apex", rest_apex, lower=0.0, upper=1.0, upper_open=True)
    far = FarField(inputs, handover_jump, ehd_multiple)
    gap, velocity = inputs.start()
    if far.handover_margin(gap, velocity) <= 0.0:
        raise checks.InputError(
            f"the start gap {gap!r} m is inside the hand-over region of the film model: "
            "start the sphere higher"
        )
    collision = ImmersedCollision(far, model, nodes, options or IntegratorOptions())
    run = BounceLoop(collision, rest_apex)
    status = run.go(FlightState(0.0, gap, velocity), max_bounces)
    return BounceResult(
        inputs,
        model,
        run.arrays(),
        run.contacts,
        status,
        far.terminal_velocity(),
        handover_jump,
        ehd_multiple,
        rest_apex,
    )
