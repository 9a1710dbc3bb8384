"""How a bounce is computed (docs/bounce.md): the solids and film numerics of its contacts, the
hand-over criterion between the flight and the film model, and when the bounce ends. Each
field is declared with its help, unit, allowed values and default
(:func:`ehdfem.settings.setting`), validated, and an option of ``ehdfem bounce``
(:mod:`ehdfem.cli.bounce`), as the bounce's physical inputs
(:class:`ehdfem.bounce.inputs.BounceInputs`) are."""

from __future__ import annotations

from dataclasses import dataclass, field, fields

from .. import checks
from ..config import Numerics
from ..motion.timestepping import IntegratorOptions
from ..settings import setting, validate
from .contact import MODELS
from .flight import EHD_MULTIPLE, HANDOVER_JUMP


@dataclass(frozen=True)
class BounceRun:
    """The numerics of a bounce: ``contact_solids``, the solids of the contacts, "halfspace"
    (the elastic half-space theory) or "rigid" (eps -> 0; the FE solids do not apply to the
    immersed film, which reaches beyond the sphere); ``handover_jump`` in (0, 0.5) and
    ``ehd_multiple`` >= 1, the hand-over criterion
    (:meth:`ehdfem.bounce.flight.FarField.handover_margin`); ``max_bounces``, the most contacts
    computed; ``rest_apex``, an apex below this fraction of D ends the bounce; ``numerics``,
    the film model's :class:`ehdfem.config.Numerics` (nodes, refinements, time-step control),
    its exit gap left to each contact (:meth:`ehdfem.bounce.flight.FarField.exit_gap`)."""

    contact_solids: str = setting(
        "halfspace",
        help="solids of the contacts: elastic half-spaces, or rigid (eps -> 0); collide's "
        "--model chooses between half-spaces and FE solids",
        choices=MODELS,
    )
    handover_jump: float = setting(
        HANDOVER_JUMP,
        help="largest relative force jump at the hand-over to the film model",
        lower=0.0,
        upper=0.5,
        lower_open=True,
        upper_open=True,
    )
    ehd_multiple: float = setting(
        EHD_MULTIPLE,
        help="hand over at the latest at this multiple of the EHD gap",
        lower=1.0,
        upper=1e4,
    )
    max_bounces: int = setting(30, help="most contacts computed", lower=1, upper=1000)
    rest_apex: float = setting(
        1e-3,
        help="an apex below this fraction of D ends the bounce",
        lower=0.0,
        upper=1.0,
        upper_open=True,
    )
    numerics: Numerics = field(default_factory=Numerics)

    def __post_init__(self):
        validate(self)
        if not isinstance(self.numerics, Numerics):
            raise checks.InputError(f"numerics must be Numerics, got {self.numerics!r}", "numerics")
        exit_gap = next(f for f in fields(IntegratorOptions) if f.name == "exit_gap").default
        if self.numerics.integrator.exit_gap != exit_gap:
            raise checks.InputError(
                f"exit_gap = {self.numerics.integrator.exit_gap!r} cannot act in a bounce: each "
                "contact hands back to the flight at its own exit gap (docs/bounce.md)",
                "exit_gap",
            )
