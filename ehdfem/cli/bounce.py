"""``ehdfem bounce``: a sphere released in a liquid settles onto a wall and bounces until it
rests; each contact is an immersed EHD collision (docs/bounce.md). Inputs in SI."""

from __future__ import annotations

import argparse
from argparse import BooleanOptionalAction
from pathlib import Path

from .. import BounceInputs, IntegratorOptions, bounce_sphere, checks
from ..bounce.contact import MODELS as BOUNCE_MODELS
from ..bounce.flight import EHD_MULTIPLE, HANDOVER_JUMP
from ..bounce.inputs import DRAG_LAWS, GRAVITY, HISTORY_MEMORIES
from ..bounce.unsteady import HISTORY_KERNELS
from ..config import DEFAULT_NODES
from ..film import cavitation
from ..film.asperities import MODELS as ASPERITY_MODELS
from ..film.asperities import ImpactAsperities
from ..inputs.scales import ATMOSPHERE
from ..study.sweep import write_csv
from . import paths
from .arguments import JSON_HELP, report_stream, write_json
from .inputs import BODIES, add_body_arguments, body_hint, body_of

HELP = (
    "a sphere released in a liquid settles onto a wall and bounces until it rests; each "
    "contact is an immersed EHD collision (docs/bounce.md)"
)


def _with_default(text: str, default) -> str:
    """``text; default: <default>`` (argparse's help, its % escaped)."""
    return f"{text}; default: {default}".replace("%", "%%")


def add_bounce(b) -> None:
    """The inputs of ``ehdfem bounce``: materials, liquid, start, modelling choices, output;
    each option's help gives its unit, range and default."""
    phys = b.add_argument_group("physical inputs (SI)")
    add_body_arguments(phys)
    for name, text in (
        ("radius", "sphere radius a [m], (0, 1]; default: required"),
        (
            "release-height",
            "gap [m] at which the sphere is released at rest, (0, 100]; "
            "default: none (give it, or --start-gap with --start-speed)",
        ),
        ("start-gap", "or: start gap [m], with --start-speed, (0, 100]; default: none"),
        ("start-speed", "speed [m/s] towards the wall at --start-gap, [0, 100]; default: none"),
    ):
        phys.add_argument(f"--{name}", type=float, metavar="X", help=text)
    model = b.add_argument_group("modelling choices")
    model.add_argument(
        "--e-dry",
        type=float,
        default=1.0,
        metavar="X",
        help=_with_default("dry restitution (1: pure EHD), (0, 1]", 1),
    )
    model.add_argument(
        "--drag",
        choices=DRAG_LAWS,
        default=DRAG_LAWS[0],
        help=_with_default("steady drag law", DRAG_LAWS[0]),
    )
    model.add_argument(
        "--added-mass-coefficient",
        dest="added_mass",
        type=float,
        default=0.5,
        metavar="C_M",
        help=_with_default(
            "added-mass coefficient C_M far from the wall, [0, 1] (collide's --added-mass is a "
            "mass in kg)",
            0.5,
        ),
    )
    model.add_argument(
        "--gravity",
        type=float,
        default=GRAVITY,
        metavar="X",
        help=_with_default("gravitational acceleration g [m/s^2], (0, 100]", GRAVITY),
    )
    model.add_argument(
        "--cavitation",
        choices=cavitation.MODELS,
        default=cavitation.Truncation.name,
        help=_with_default(
            f"film cavitation at the liquid's vapour pressure: {', '.join(cavitation.MODELS)}",
            cavitation.Truncation.name,
        ),
    )
    model.add_argument(
        "--ambient-pressure",
        type=float,
        default=ATMOSPHERE,
        metavar="X",
        help=_with_default("ambient pressure [Pa], (0, inf)", f"{ATMOSPHERE:g}"),
    )
    _add_flight_choices(model)
    model.add_argument(
        "--contact-solids",
        dest="model",
        choices=BOUNCE_MODELS,
        default="halfspace",
        help=_with_default(
            "solids of the contacts: elastic half-spaces, or rigid (eps -> 0); collide's "
            "--model chooses between half-spaces and FE solids",
            "halfspace",
        ),
    )
    _add_numerics(b.add_argument_group("numerics and output"))


def _add_numerics(num) -> None:
    """The hand-over, the film model's numerics and the outputs."""
    for name, kind, default, text in (
        ("handover-jump", float, HANDOVER_JUMP, "largest relative force jump at the hand-over "
         "to the film model, (0, 0.5)"),
        ("ehd-multiple", float, EHD_MULTIPLE, "hand over at the latest at this multiple of the "
         "EHD gap, [1, 1e4]"),
        ("max-bounces", int, 30, "most contacts computed, [1, 1000]"),
        ("rest-apex", float, 1e-3, "an apex below this fraction of D ends the bounce, [0, 1)"),
        ("nodes", int, DEFAULT_NODES, "film nodes of each contact, [20, 5000]"),
        ("rtol", float, IntegratorOptions.rtol, "time-step tolerance of each contact: local "
         "error per step [relative], [1e-10, 0.1]"),
    ):  # fmt: skip
        num.add_argument(
            f"--{name}",
            type=kind,
            default=default,
            metavar="X",
            help=_with_default(text, f"{default:g}"),
        )
    num.add_argument(
        "--folder",
        metavar="DIR",
        help="write trajectory.csv, contacts.csv, bounce.json and bounce.png into DIR (made if "
        "missing); default: none",
    )
    num.add_argument("--out", dest="old_out", help=argparse.SUPPRESS)  # refused: see --folder
    num.add_argument("--json", metavar="FILE", help=JSON_HELP)


def _add_flight_choices(model) -> None:
    """The switchable choices of the flight and the contacts (docs/bounce.md), default on."""
    model.add_argument(
        "--history",
        choices=HISTORY_KERNELS,
        default=HISTORY_KERNELS[0],
        help=_with_default(
            "history (Basset) force in flight: Mei & Adrian's finite-Re kernel; the same with "
            "the wall-bounded unsteady Stokes kernel in place of Basset's (mei-adrian-wall); "
            "Basset's; none",
            HISTORY_KERNELS[0],
        ),
    )
    model.add_argument(
        "--history-memory",
        choices=HISTORY_MEMORIES,
        default=HISTORY_MEMORIES[0],
        help=_with_default(
            "the history force's memory across a contact: keep the contact's velocity change, "
            "reset it at each exit, or keep only the approach's memory (the contact's velocity "
            "change forgotten at exit)",
            HISTORY_MEMORIES[0],
        ),
    )
    switches = {
        "wall-added-mass": ("the added mass rises near the wall (the sphere's image)", True),
        "contact-gravity": ("gravity and buoyancy act during the contacts", True),
        "clear-exit": ("the film model hands back above the gap where a cavity can form", True),
        "contact-history": ("the history force acts in each contact's time stepping", True),
        "contact-drag": (
            "the flight's remainder drag's impulse over each contact added at exit",
            False,
        ),
    }
    for name, (text, default) in switches.items():
        model.add_argument(
            f"--{name}",
            action=BooleanOptionalAction,
            default=default,
            help=_with_default(text, "on" if default else "off"),
        )
    for surface in ("sphere", "wall"):
        model.add_argument(
            f"--{surface}-roughness",
            type=float,
            default=0.0,
            metavar="X",
            help=_with_default(
                f"rms roughness of the {surface}'s surface (0: smooth) [m], [0, 0.01 a]", 0
            ),
        )
    model.add_argument(
        "--asperities",
        choices=ASPERITY_MODELS,
        default=ImpactAsperities.name,
        help=_with_default(
            "asperity contact of rough surfaces at each contact (docs/model.md)",
            ImpactAsperities.name,
        ),
    )


def _bounce_inputs(args) -> BounceInputs:
    """The bounce's inputs from the arguments; a missing material or liquid is named."""
    bodies = {name: body_of(args, name, getattr(args, name)) for name in BODIES}
    missing = [body_hint(name) for name, value in bodies.items() if value is None]
    if args.radius is None:
        missing.append("--radius")
    if missing:
        raise checks.InputError(f"the bounce needs {', '.join(missing)}")
    return BounceInputs(
        radius=args.radius,
        **bodies,
        release_height=args.release_height,
        start_gap=args.start_gap,
        start_speed=args.start_speed,
        e_dry=args.e_dry,
        drag=args.drag,
        added_mass=args.added_mass,
        gravity=args.gravity,
        cavitation=args.cavitation,
        ambient_pressure=args.ambient_pressure,
        history=args.history,
        history_memory=args.history_memory,
        wall_added_mass=args.wall_added_mass,
        contact_gravity=args.contact_gravity,
        clear_exit=args.clear_exit,
        sphere_roughness=args.sphere_roughness,
        wall_roughness=args.wall_roughness,
        asperities=args.asperities,
        contact_history=args.contact_history,
        contact_drag=args.contact_drag,
    )


def bounce_command(args) -> int:
    if args.old_out is not None:
        raise checks.InputError(
            "the bounce's output folder is --folder (render's --out names a picture file)",
            "old_out",
        )
    paths.output_file("json", args.json, stdout=True)
    paths.output_folder("folder", args.folder)
    paths.distinct_outputs({"json": args.json, "folder": args.folder})
    inputs = _bounce_inputs(args)
    result = bounce_sphere(
        inputs,
        model=args.model,
        nodes=args.nodes,
        options=IntegratorOptions(rtol=args.rtol),
        handover_jump=args.handover_jump,
        ehd_multiple=args.ehd_multiple,
        max_bounces=args.max_bounces,
        rest_apex=args.rest_apex,
    )
    summary = result.summary(args.command_line)
    report = report_stream(args)
    diameter = inputs.diameter
    print(
        f"ehdfem bounce: {result.status}; terminal velocity {result.terminal_velocity:.4g} m/s, "
        f"energy balance {summary['energy_error']:.2g}",
        file=report,
    )
    print("  contact  impact [m/s]  St       h_c [m]    e       apex/D    outcome", file=report)
    for i, c in enumerate(result.contacts, 1):
        apex = "-" if c.apex_gap is None else f"{c.apex_gap / diameter:.4g}"
        print(
            f"  {i:<7d}  {c.impact_speed:<12.4g}  {c.St:<7.4g}  {c.handover_gap:<9.3g}  "
            f"{c.e:<6.4f}  {apex:<8s}  {c.status}",
            file=report,
        )
    write_json(summary, args.json)
    if args.folder:
        out = Path(args.folder)
        from ..outputs import plots  # matplotlib costs 0.25 s to import: only when plotting

        out.mkdir(parents=True, exist_ok=True)
        write_json(summary, str(out / "bounce.json"))
        wrote = [
            write_csv(out / "trajectory.csv", result.trajectory_rows()),
            write_csv(out / "contacts.csv", result.contact_rows()),
            out / "bounce.json",
            plots.plot_bounce(result, out / "bounce.png"),
        ]
        for path in wrote:
            print(f"  wrote {path}", file=report)
    return 0
