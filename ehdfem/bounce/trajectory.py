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
from .contact import ImmersedCollision
from .flight import FarField, FlightState
from .inputs import BounceInputs
from .loop import BounceLoop
from .result import BounceResult
from .run import BounceRun


def bounce_sphere(inputs: BounceInputs, run: BounceRun | None = None) -> BounceResult:
    """The trajectory of a sphere settling onto a wall in a liquid and bouncing until it rests
    (module docstring), computed as ``run`` says (:class:`ehdfem.bounce.run.BounceRun`:
    the contacts' solids and film numerics, the hand-over, when it ends; default: its
    defaults)."""
    if not isinstance(inputs, BounceInputs):
        raise checks.InputError(f"inputs must be BounceInputs, got {inputs!r}")
    run = BounceRun() if run is None else run
    if not isinstance(run, BounceRun):
        raise checks.InputError(f"run must be BounceRun, got {run!r}", "run")
    far = FarField(inputs, run.handover_jump, run.ehd_multiple)
    gap, velocity = inputs.start()
    if far.handover_margin(gap, velocity) <= 0.0:
        raise checks.InputError(
            f"the start gap {gap!r} m is inside the hand-over region of the film model: "
            "start the sphere higher"
        )
    collision = ImmersedCollision(far, run.contact_solids, run.numerics)
    loop = BounceLoop(collision, run.rest_apex)
    status = loop.go(FlightState(0.0, gap, velocity), run.max_bounces)
    return BounceResult(
        inputs,
        run.contact_solids,
        loop.arrays(),
        loop.contacts,
        status,
        far.terminal_velocity(),
        run.handover_jump,
        run.ehd_multiple,
        run.rest_apex,
    )
