"""Presets: material and liquid data with their sources, and the inputs of the main job.

Values are SI at about 20 C. "approx." marks typical values of a class of materials rather than
a measured sample. The presets are shortcuts for :class:`ehdfem.scales.PhysicalCollision`;
:func:`ehdfem.scales.from_presets` builds physical inputs from their names.
"""

from __future__ import annotations

from dataclasses import dataclass

from . import checks


@dataclass(frozen=True)
class Material:
    """An elastic solid: Young's modulus [Pa], Poisson's ratio, density [kg/m^3], source."""

    name: str
    young_modulus: float
    poisson_ratio: float
    density: float
    source: str


@dataclass(frozen=True)
class Liquid:
    """A Newtonian liquid at about 20 C: viscosity [Pa s], density [kg/m^3], vapour pressure
    [Pa, absolute], Barus pressure-viscosity coefficient [1/Pa] (0 where negligible), source."""

    name: str
    viscosity: float
    density: float
    vapour_pressure: float
    pressure_viscosity: float
    source: str


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
_GLYCEROL = "glycerol-water at 20 C, standard tables (Segur & Oberstar 1951; Cheng 2008), approx."
_SILICONE = "polydimethylsiloxane oil, kinematic viscosity grade x 965-970 kg/m^3, approx."
LIQUIDS = {
    liq.name: liq
    for liq in [
        Liquid("water", 1.0e-3, 998.0, 2.34e3, 0.0, f"water at 20 C, {_HANDBOOK}"),
        Liquid("glycerol_50", 6.0e-3, 1126.0, 2.0e3, 0.0, f"50 wt% {_GLYCEROL}"),
        Liquid("glycerol_80", 60.1e-3, 1208.0, 1.0e3, 0.0, f"80 wt% {_GLYCEROL}"),
        Liquid("glycerol_90", 219e-3, 1235.0, 0.5e3, 0.0, f"90 wt% {_GLYCEROL}"),
        Liquid("glycerol", 1.41, 1261.0, 0.0, 5.9e-9, f"pure {_GLYCEROL}"),
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
of 100 cSt silicone oil (SI inputs of :func:`ehdfem.scales.from_presets`)."""
