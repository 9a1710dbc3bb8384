"""The box of inputs the closed forms for DEM are fitted over, and the refusal outside it.

Inputs are dimensionless (DSH scales, :mod:`ehdfem.inputs.scales`): St = m V0/(6 pi mu a^2),
eps = 4 theta mu V0 a^(3/2)/x0^(5/2), delta = x0/a, P_cav = (p_cav - p_ambient) x0^2/(mu V0 a)
(None or -inf: no cavitation limit), the layer ("thin" or "immersed") and the sphere's inertia
factor k = I/(m a^2). BOX is the regime real collisions cover (docs/studies.md); a fitted form
carries the box of its own table, which may be smaller.

A thin layer is also refused where its wetted film would reach past the sphere's radius r = a,
2 delta (1 + C) > 1 (R_edge^2 = 2 (1 + C) against 1/delta, by a x0), C the dry Hertz
compression (13.88 eps St)^(2/5) by x0, an upper bound of the compression: there the model's
film is cut at r = a and its e_t is no longer that of a thin layer. An immersed layer is
refused where the flattened contact would: 2 delta C > 1 (its radius^2 2 C against 1/delta; the
compression is then above a/2, far out of the half-spaces' range, and the film's cut at r = a
caps the contact's share of the tangential integral).
"""

from __future__ import annotations

import math

from .. import checks
from ..exact import hertz

BOX = {
    "St": (1.0, 1e4),
    "eps": (1e-12, 0.1),
    "p_cav": (-1e5, -1.0),
    "delta": (1e-3, 0.5),
}
LAYERS = ("thin", "immersed")
INERTIA_FACTOR = (0.0, 2.0 / 3.0)  # open below: k = I/(m a^2), 2/5 a solid sphere
RELATIVE_SLACK = 1e-9  # a box edge read back from a table's decimal text still counts as inside


def no_limit(p_cav) -> bool:
    """True for P_cav None or -inf (no cavitation limit)."""
    return p_cav is None or (isinstance(p_cav, float) and p_cav == -math.inf)


def check_inside(box: dict, St, eps, delta, p_cav, layer, inertia_factor) -> None:
    """Refuse inputs outside ``box`` ({"St", "eps", "p_cav", "delta": (low, high)} and
    "no_limit": whether P_cav none was fitted): an InputError (a ValueError) naming the
    parameter, its value and the box."""
    checks.choice("layer", layer, LAYERS)
    checks.number("inertia_factor", inertia_factor, lower=0.0, upper=2.0 / 3.0, lower_open=True)
    if no_limit(p_cav):
        if not box["no_limit"]:
            raise checks.InputError(
                "p_cav = none (no cavitation limit) is outside the fitted box: P_cav in "
                f"[{box['p_cav'][0]:g}, {box['p_cav'][1]:g}]",
                "p_cav",
            )
        values = {"St": St, "eps": eps, "delta": delta}
    else:
        values = {"St": St, "eps": eps, "delta": delta, "p_cav": p_cav}
    for name, value in values.items():
        low, high = box[name]
        value = checks.number(name, value)
        if not low - RELATIVE_SLACK * abs(low) <= value <= high + RELATIVE_SLACK * abs(high):
            raise checks.InputError(
                f"{name} = {value!r} is outside the box of the closed forms [{low:g}, {high:g}] "
                f"(fitted over {describe(box)}): they refuse to extrapolate",
                name,
            )
    reach = wetted_reach(St, eps, delta, layer)
    if reach > 1.0:
        raise checks.InputError(
            f"delta = {delta!r} is outside the box of the closed forms for {REACH[layer][0]} "
            f"at St = {St:g}, eps = {eps:g}: {REACH[layer][1]} = {reach:.3g} > 1",
            "delta",
        )


REACH = {  # what would reach past the sphere's radius r = a where wetted_reach > 1
    "thin": (
        "a thin layer (the wetted film would reach past the sphere's radius)",
        "2 delta (1 + (13.88 eps St)^(2/5))",
    ),
    "immersed": (
        "an immersed layer (the flattened contact would reach past the sphere's radius)",
        "2 delta (13.88 eps St)^(2/5)",
    ),
}


def wetted_reach(St, eps, delta, layer) -> float:
    """The squared radius by a^2 of what must stay inside the sphere's radius r = a, at the dry
    Hertz compression C = (13.88 eps St)^(2/5) (by x0), an upper bound: a thin layer's wetted
    film, 2 delta (1 + C); an immersed layer's flattened contact, 2 delta C."""
    compression = hertz.max_compression(float(eps), float(St))
    return 2.0 * float(delta) * ((layer == "thin") + compression)


def describe(box: dict) -> str:
    """'St in [1, 1e+04], eps in [...], P_cav in [...] or none, delta in [...]'."""
    text = ", ".join(
        f"{'P_cav' if k == 'p_cav' else k} in [{box[k][0]:g}, {box[k][1]:g}]"
        for k in ("St", "eps", "p_cav", "delta")
    )
    return text + (" (P_cav also none)" if box["no_limit"] else "")
