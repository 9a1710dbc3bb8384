"""``ehdfem bounce``: a sphere released in a liquid settles onto a wall and bounces until it
rests; each contact is an immersed EHD collision (docs/bounce.md). Inputs in SI."""

from __future__ import annotations

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
from ..inputs.scales import ATMOSPHERE
from ..study.sweep import write_csv
from . import paths
from .arguments import report_stream, write_json
from .inputs import BODIES, add_body_arguments, body_hint, body_of

HELP = (
    "a sphere released in a liquid settles onto a wall and bounces until it rests; each "
    "contact is an immersed EHD collision (docs/bounce.md)"
)


def add_bounce(b) -> None:
    """The inputs of ``ehdfem bounce``: materials, liquid, start, modelling choices, output."""
    phys = b.add_argument_group("physical inputs (SI)")
    add_body_arguments(phys)
    phys.add_argument("--radius", type=float, help="sphere radius a [m], (0, 1]")
    phys.add_argument(
        "--release-height", type=float, help="gap [m] at which the sphere is released at rest"
    )
    phys.add_argument("--start-gap", type=float, help="or: start gap [m], with --start-speed")
    phys.add_argument("--start-speed", type=float, help="speed [m/s] towards the wall at the start")
    model = b.add_argument_group("modelling choices")
    model.add_argument(
        "--e-dry", type=float, default=1.0, help="dry restitution, (0, 1]; 1 = pure EHD"
    )
    model.add_argument("--drag", choices=DRAG_LAWS, default=DRAG_LAWS[0], help="steady drag law")
    model.add_argument(
        "--added-mass-coefficient",
        dest="added_mass",
        type=float,
        default=0.5,
        help="added-mass coefficient C_M far from the wall, [0, 1] (collide's --added-mass is "
        "a mass in kg)",
    )
    model.add_argument("--gravity", type=float, default=GRAVITY, help="g [m/s^2]")
    model.add_argument(
        "--cavitation",
        choices=cavitation.MODELS,
        default="truncate",
        help="film cavitation at the liquid's vapour pressure: truncate, mass-conserving or none",
    )
    model.add_argument(
        "--ambient-pressure", type=float, default=ATMOSPHERE, help="ambient pressure [Pa]"
    )
    _add_flight_choices(model)
    model.add_argument(
        "--contact-solids",
        dest="model",
        choices=BOUNCE_MODELS,
        default="halfspace",
        help="solids of the contacts: elastic half-spaces, or rigid (eps -> 0); collide's "
        "--model chooses between half-spaces and FE solids",
    )
    num = b.add_argument_group("numerics and output")
    num.add_argument(
        "--handover-jump",
        type=float,
        default=HANDOVER_JUMP,
        help="largest relative force jump at the hand-over to the film model, (0, 0.5)",
    )
    num.add_argument(
        "--ehd-multiple",
        type=float,
        default=EHD_MULTIPLE,
        help="hand over at the latest at this multiple of the EHD gap, >= 1",
    )
    num.add_argument("--max-bounces", type=int, default=30, help="most contacts computed")
    num.add_argument(
        "--rest-apex", type=float, default=1e-3, help="an apex below this fraction of D ends it"
    )
    num.add_argument("--nodes", type=int, default=DEFAULT_NODES, help="film nodes")
    num.add_argument(
        "--rtol", type=float, default=IntegratorOptions.rtol, help="film time-step tolerance"
    )
    num.add_argument(
        "--out",
        metavar="DIR",
        help="write trajectory.csv, contacts.csv, bounce.json and bounce.png into DIR (made if "
        "missing)",
    )
    num.add_argument("--json", metavar="FILE", help="write the results as JSON ('-' for stdout)")


def _add_flight_choices(model) -> None:
    """The switchable choices of the flight and the contacts (docs/bounce.md), default on."""
    model.add_argument(
        "--history",
        choices=HISTORY_KERNELS,
        default=HISTORY_KERNELS[0],
        help="history (Basset) force in flight: Mei & Adrian's finite-Re kernel; the same with "
        "the wall-bounded unsteady Stokes kernel in place of Basset's (mei-adrian-wall); "
        "Basset's; none",
    )
    model.add_argument(
        "--history-memory",
        choices=HISTORY_MEMORIES,
        default=HISTORY_MEMORIES[0],
        help="the history force's memory across a contact: keep the contact's velocity change, "
        "reset it at each exit, or keep only the approach's memory (the contact's velocity "
        "change forgotten at exit)",
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
            help=f"{text} (default {'on' if default else 'off'})",
        )
    for surface in ("sphere", "wall"):
        model.add_argument(
            f"--{surface}-roughness",
            type=float,
            default=0.0,
            help=f"rms roughness of the {surface}'s surface [m], [0, 0.01 a]; 0: smooth",
        )
    model.add_argument(
        "--asperities",
        choices=ASPERITY_MODELS,
        default=ASPERITY_MODELS[0],
        help="asperity contact of rough surfaces at each contact (docs/model.md)",
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
    paths.output_file("json", args.json, stdout=True)
    paths.output_folder("out", args.out)
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
    if args.out:
        out = Path(args.out)
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
