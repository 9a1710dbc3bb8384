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

from dataclasses import fields

from .. import checks
from ..config import Numerics
from ..motion.timestepping import IntegratorOptions
from .contact import MODELS, ImmersedCollision
from .flight import EHD_MULTIPLE, HANDOVER_JUMP, FarField, FlightState
from .inputs import BounceInputs
from .loop import BounceLoop
from .result import BounceResult


def bounce_sphere(
    inputs: BounceInputs,
    model: str = "halfspace",
    numerics: Numerics | None = None,
    handover_jump: float = HANDOVER_JUMP,
    ehd_multiple: float = EHD_MULTIPLE,
    max_bounces: int = 30,
    rest_apex: float = 1e-3,
) -> BounceResult:
    """The trajectory of a sphere settling onto a wall in a liquid and bouncing until it rests
    (module docstring). ``model``: the solids of the contacts, "halfspace" (the elastic
    half-space theory) or "rigid" (eps -> 0); the FE solids do not apply to the immersed film,
    which reaches beyond the sphere. ``numerics``: the film model's :class:`ehdfem.config.Numerics`
    (nodes, refinements, time-step control; default: a collision's), its exit gap left to each
    contact (:meth:`ehdfem.bounce.flight.FarField.exit_gap`). ``handover_jump`` in (0, 0.5),
    ``ehd_multiple`` >= 1: the hand-over criterion. ``max_bounces``: the most contacts
    computed. ``rest_apex``: an apex below this fraction of D ends the bounce."""
    if not isinstance(inputs, BounceInputs):
        raise checks.InputError(f"inputs must be BounceInputs, got {inputs!r}")
    checks.choice("model", model, MODELS)
    numerics = Numerics() if numerics is None else numerics
    _check_numerics(numerics)
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
    collision = ImmersedCollision(far, model, numerics)
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


def _check_numerics(numerics) -> None:
    """Refuse numerics that are not :class:`ehdfem.config.Numerics`, and an integrator's exit gap,
    which each contact sets from the flight (a given one could not act)."""
    if not isinstance(numerics, Numerics):
        raise checks.InputError(f"numerics must be Numerics, got {numerics!r}", "numerics")
    exit_gap = next(f for f in fields(IntegratorOptions) if f.name == "exit_gap").default
    if numerics.integrator.exit_gap != exit_gap:
        raise checks.InputError(
            f"exit_gap = {numerics.integrator.exit_gap!r} cannot act in a bounce: each contact "
            "hands back to the flight at its own exit gap (docs/bounce.md)",
            "exit_gap",
        )
