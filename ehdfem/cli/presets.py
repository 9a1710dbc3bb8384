"""``ehdfem presets``: the material and liquid presets, their values (SI) and sources."""

from __future__ import annotations

from dataclasses import asdict, fields

from ..inputs.presets import LIQUIDS, MATERIALS
from . import paths
from .arguments import report_stream, write_json

HELP = "list the material and liquid presets: values (SI) and sources"


def add_presets(parser) -> None:
    parser.add_argument(
        "--json", metavar="FILE", help="write the presets as JSON ('-': stdout); default: none"
    )


def presets_command(args) -> int:
    """The material and liquid presets: a table each (SI units in the header), with sources."""
    paths.output_file("json", args.json, stdout=True)
    report = report_stream(args)
    tables = [
        ("materials", MATERIALS, ("E [Pa]", "nu", "density [kg/m^3]")),
        ("liquids", LIQUIDS, ("mu [Pa s]", "density [kg/m^3]", "p_vap [Pa]", "alpha [1/Pa]")),
    ]
    for title, presets, header in tables:
        print(f"{title} (sphere/wall presets)" if title == "materials" else title, file=report)
        rows = [
            (p.name, *(f"{v:.6g}" for v in _preset_values(p)), p.source) for p in presets.values()
        ]
        rows.insert(0, ("name", *header, "source"))
        widths = [max(len(row[i]) for row in rows) for i in range(len(header) + 1)]
        for row in rows:
            cells = [cell.ljust(width) for cell, width in zip(row, widths, strict=False)]
            print("  " + "  ".join([*cells, row[-1]]), file=report)
        print(file=report)
    print(
        "Give your own values with --sphere-modulus, --sphere-poisson, --sphere-density (and "
        "--wall-*), --liquid-viscosity, --liquid-density, --vapour-pressure, "
        "--pressure-viscosity; with a preset they change its values.",
        file=report,
    )
    write_json(
        {kind: {n: asdict(p) for n, p in presets.items()} for kind, presets, _ in tables},
        args.json,
    )
    return 0


def _preset_values(preset) -> list[float]:
    """The numbers of a Material or Liquid, in the order of the presets table."""
    return [getattr(preset, f.name) for f in fields(preset) if f.name not in ("name", "source")]
