"""Presets: material and liquid data with their sources, and the inputs of the main job.

Values are SI at about 20 C. "approx." marks typical values of a class of materials rather than
a measured sample. The presets are shortcuts for :class:`ehdfem.inputs.scales.PhysicalCollision`;
:func:`ehdfem.inputs.scales.from_presets` builds physical inputs from their names, and
:func:`custom_material` and :func:`custom_liquid` build a user's own sphere, wall or liquid,
from values alone or from a preset with some values changed. Every value is checked against
its range (MATERIAL_RANGES, LIQUID_RANGES) when a Material or Liquid is made.
"""

from __future__ import annotations

from dataclasses import MISSING, dataclass, fields, replace

from .. import checks

USER_SOURCE = "given by the user"

MATERIAL_RANGES = {
    "young_modulus": dict(lower=0.0, lower_open=True, upper=2e12),  # Pa; diamond is 1.1e12
    "poisson_ratio": dict(lower=-1.0, upper=0.5, lower_open=True, upper_open=True),
    "density": dict(lower=0.0, lower_open=True, upper=3e4),  # kg/m^3; osmium is 22,590
}
"""Allowed ranges of a material's values (SI), as keyword arguments of
:func:`ehdfem.checks.number`."""

LIQUID_RANGES = {
    "viscosity": dict(lower=0.0, lower_open=True),  # Pa s
    "density": dict(lower=0.0, lower_open=True, upper=3e4),  # kg/m^3
    "vapour_pressure": dict(lower=0.0),  # Pa, absolute; below the ambient: PhysicalCollision
    "pressure_viscosity": dict(lower=0.0, upper=1e-6),  # 1/Pa
}
"""Allowed ranges of a liquid's values (SI), as keyword arguments of
:func:`ehdfem.checks.number`."""


def _check_values(values: dict, ranges: dict, labels) -> dict:
    """``values`` (a subset of ``ranges``' keys) as floats, each checked against its range;
    an error names the value by ``labels(key)``."""
    return {key: checks.number(labels(key), value, **ranges[key]) for key, value in values.items()}


@dataclass(frozen=True)
class Material:
    """An elastic solid: Young's modulus [Pa], Poisson's ratio, density [kg/m^3], source.
    Refuses values outside MATERIAL_RANGES."""

    name: str
    young_modulus: float
    poisson_ratio: float
    density: float
    source: str = USER_SOURCE

    def __post_init__(self):
        values = {key: getattr(self, key) for key in MATERIAL_RANGES}
        _check_values(values, MATERIAL_RANGES, lambda key: f"{key} of material {self.name!r}")


@dataclass(frozen=True)
class Liquid:
    """A Newtonian liquid at about 20 C: viscosity [Pa s], density [kg/m^3], vapour pressure
    [Pa, absolute], Barus pressure-viscosity coefficient [1/Pa] (0 where negligible), source.
    Refuses values outside LIQUID_RANGES."""

    name: str
    viscosity: float
    density: float
    vapour_pressure: float
    pressure_viscosity: float = 0.0
    source: str = USER_SOURCE

    def __post_init__(self):
        values = {key: getattr(self, key) for key in LIQUID_RANGES}
        _check_values(values, LIQUID_RANGES, lambda key: f"{key} of liquid {self.name!r}")


_NIJSSEN = "Nijssen, Ottens & Padding 2022 (sphere sets of Joseph & Hunt 2004)"
_HANDBOOK = "engineering handbook value, approx."
MATERIALS = {
    m.name: m
    for m in [
        Material("steel", 190e9, 0.27, 7780.0, f"chrome steel ball bearing, {_NIJSSEN}"),
        Material("glass", 60e9, 0.23, 2540.0, f"glass sphere, {_NIJSSEN}"),
        Material("acetal", 2.8e9, 0.35, 1400.0, f"Delrin sphere, {_NIJSSEN}"),
        Material("nylon", 2.7e9, 0.39, 1140.0, f"nylon 6/6, {_HANDBOOK}"),
        Material("ptfe", 0.5e9, 0.46, 2200.0, f"PTFE, {_HANDBOOK}"),
        Material("polyurethane", 30e6, 0.49, 1200.0, f"soft polyurethane elastomer, {_HANDBOOK}"),
        Material("aluminium", 70e9, 0.33, 2700.0, f"aluminium alloy, {_HANDBOOK}"),
        Material("brass", 100e9, 0.34, 8500.0, f"brass, {_HANDBOOK}"),
        Material("tungsten_carbide", 600e9, 0.22, 15000.0, f"cemented WC, {_HANDBOOK}"),
        Material("quartz", 72e9, 0.17, 2200.0, f"fused quartz, {_HANDBOOK}"),
        Material("zerodur", 90.3e9, 0.24, 2530.0, "Schott Zerodur data sheet"),
    ]
}
_GLYCEROL = "at 20 C, standard tables (Segur & Oberstar 1951; Cheng 2008), approx."
_SILICONE = "polydimethylsiloxane oil, the kinematic viscosity grade times the density, approx."
LIQUIDS = {
    liq.name: liq
    for liq in [
        Liquid("water", 1.0e-3, 998.0, 2.34e3, 0.0, f"water at 20 C, {_HANDBOOK}"),
        Liquid("glycerol_50", 6.0e-3, 1126.0, 2.0e3, 0.0, f"50 wt% glycerol-water {_GLYCEROL}"),
        Liquid("glycerol_80", 60.1e-3, 1208.0, 1.0e3, 0.0, f"80 wt% glycerol-water {_GLYCEROL}"),
        Liquid("glycerol_90", 219e-3, 1235.0, 0.5e3, 0.0, f"90 wt% glycerol-water {_GLYCEROL}"),
        Liquid("glycerol", 1.41, 1261.0, 0.0, 5.9e-9, f"pure glycerol {_GLYCEROL}"),
        Liquid("silicone_oil_10cst", 9.35e-3, 935.0, 0.0, 1.5e-8, f"10 cSt {_SILICONE}"),
        Liquid("silicone_oil_100cst", 96.5e-3, 965.0, 0.0, 1.5e-8, f"100 cSt {_SILICONE}"),
        Liquid("silicone_oil_1000cst", 0.970, 970.0, 0.0, 1.5e-8, f"1000 cSt {_SILICONE}"),
        Liquid("silicone_oil_10000cst", 9.70, 970.0, 0.0, 1.5e-8, f"10000 cSt {_SILICONE}"),
        Liquid("mineral_oil", 0.03, 870.0, 0.0, 2.0e-8, f"light mineral oil, {_HANDBOOK}"),
    ]
}


def material(name: str) -> Material:
    """The material preset ``name`` (see MATERIALS)."""
    return _preset("material", name, MATERIALS)


def liquid(name: str) -> Liquid:
    """The liquid preset ``name`` (see LIQUIDS)."""
    return _preset("liquid", name, LIQUIDS)


def _preset(kind, name, table):
    if name not in table:
        raise checks.InputError(f"unknown {kind} preset {name!r}; known: {', '.join(table)}")
    return table[name]


BODIES = {"sphere": "material", "wall": "material", "liquid": "liquid"}


def body(role: str, spec) -> Material | Liquid:
    """The data of the ``role`` ("sphere", "wall" or "liquid") from ``spec``: a preset name, a
    Material or Liquid, or a dict of values with an optional "preset" key (as for
    :func:`custom_material` and :func:`custom_liquid`; errors name a value "role.key")."""
    checks.choice("role", role, tuple(BODIES))
    kind = Material if BODIES[role] == "material" else Liquid
    if isinstance(spec, kind):
        return spec
    if isinstance(spec, str):
        return material(spec) if kind is Material else liquid(spec)
    if not isinstance(spec, dict):
        raise checks.InputError(f"{role} must be a preset name or a table of values, got {spec!r}")
    values = dict(spec)
    preset = values.pop("preset", None)
    build = custom_material if kind is Material else custom_liquid
    return build(preset, labels=lambda key: f"{role}.{key}", **values)


def custom_material(preset: str | None = None, labels=None, **values) -> Material:
    """A material from ``values`` (any of young_modulus [Pa], poisson_ratio, density
    [kg/m^3]): the preset ``preset`` with those values changed, or, with no preset, a new
    material that needs all three. ``labels(key)``: how an error names a value (default: the
    key itself), e.g. the command-line option that gave it."""
    return _custom(Material, MATERIAL_RANGES, material, preset, labels, values)


def custom_liquid(preset: str | None = None, labels=None, **values) -> Liquid:
    """A liquid from ``values`` (any of viscosity [Pa s], density [kg/m^3], vapour_pressure
    [Pa, absolute], pressure_viscosity [1/Pa]): the preset ``preset`` with those values
    changed, or, with no preset, a new liquid that needs the first three (pressure_viscosity
    defaults to 0). ``labels`` as in :func:`custom_material`."""
    return _custom(Liquid, LIQUID_RANGES, liquid, preset, labels, values)


def _custom(kind, ranges, find, preset, labels, values):
    """A ``kind`` (Material or Liquid) from a preset (found by ``find``) and ``values``."""
    labels = labels or str
    unknown = sorted(set(values) - set(ranges))
    if unknown:
        raise checks.InputError(
            f"unknown {kind.__name__.lower()} value(s) {', '.join(unknown)}; "
            f"known: {', '.join(ranges)}"
        )
    values = _check_values(values, ranges, labels)
    if preset is not None:
        base = find(preset)
        if not values:
            return base
        changed = ", ".join(f"{key} = {value:g}" for key, value in values.items())
        return replace(
            base,
            **values,
            name=f"{base.name} (changed)",
            source=f"{base.source}; changed by the user: {changed}",
        )
    required = [f.name for f in fields(kind) if f.name in ranges and f.default is MISSING]
    missing = [labels(key) for key in required if key not in values]
    if missing:
        raise checks.InputError(
            f"a {kind.__name__.lower()} without a preset needs {', '.join(missing)}"
        )
    return kind(name="custom", **values)


EXAMPLE = dict(
    sphere="steel",
    wall="glass",
    liquid="silicone_oil_100cst",
    radius=6.35e-3,
    speed=1.0,
    angle=30.0,
    layer_thickness=3e-4,
)
"""The main job (``ehdfem collide --example``, ``bash make.sh example``): a steel sphere of
radius 6.35 mm hits a glass plate at 1 m/s, 30 degrees from the normal, through a 0.3 mm layer
of 100 cSt silicone oil (SI inputs of :func:`ehdfem.inputs.scales.from_presets`)."""


def check_vapour_pressure(liquid: Liquid, ambient_pressure: float) -> None:
    """Refuse a liquid whose vapour pressure (Pa) is not below the ambient pressure (Pa): the
    cavitation limit p_vap - p_ambient (Pa) would not be a suction."""
    if liquid.vapour_pressure >= ambient_pressure:
        raise checks.InputError(
            f"vapour_pressure of liquid {liquid.name!r} = {liquid.vapour_pressure!r} Pa must be "
            f"below the ambient pressure {ambient_pressure!r} Pa (the allowed range is "
            "[0, ambient_pressure))"
        )
