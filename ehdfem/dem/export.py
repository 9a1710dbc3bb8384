"""The closed forms for DEM written out for particle codes: a Python module (standard library
only), a C99 header (no dependency but <math.h>) and the fitted table (CSV) with its
interpolation recipe (:mod:`ehdfem.dem.lookup`). The formulas are those of
:mod:`ehdfem.dem.forms` (and, for two spheres, :mod:`ehdfem.dem.pair_forms`); inputs and
outputs are dimensionless (DSH scales). Outside the fitted box the Python module raises
ValueError naming the parameter and the box; the C functions return NaN and a flag naming it.
"""

from __future__ import annotations

import math

from . import forms as shape
from .box import LAYERS, describe
from .fitting import CLEAR_REBOUND

FEATURE_ORDER = ("x", "L", "v", "w", "h")  # the feature vector of the C header
HERTZ = 90.0 * math.pi**2 / 64.0  # C = (HERTZ eps St)^(2/5): the dry Hertz compression by x0

_PY = '''"""Closed forms for DEM of a sphere hitting a wall through a liquid layer (thin or
immersed), fitted by ehdfem {version} (`ehdfem fit`) to {table} ({points} collisions;
half-spaces, Couette tangential model, e_dry = 1). Docs: docs/studies.md of ehdfem, "Closed
forms for DEM".

Dimensionless inputs (Davis, Serayssol & Hinch scales): St = m V0/(6 pi mu a^2), eps = 4 theta
mu V0 a^(3/2)/x0^(5/2), delta = x0/a, P_cav = (p_cav - p_ambient) x0^2/(mu V0 a) < 0 (None: no
cavitation limit), layer "thin" or "immersed", k = I/(m a^2) (2/5: solid sphere). e_n is the
pure EHD value (multiply by the dry restitution); spin change = a DeltaOmega/U0.
Box: {box}; for a thin layer also 2 delta (1 + (13.88 eps St)^(2/5)) <= 1 (the wetted film
inside the sphere's radius), for an immersed one 2 delta (13.88 eps St)^(2/5) <= 1 (the
flattened contact inside it). Outside it every function raises ValueError naming the parameter.
Largest errors on points held back from the fit: {errors}
"""

import math

BOX = {box_dict!r}
FORMS = {forms!r}


def _check(St, eps, delta, p_cav, layer, k):
    if layer not in ("thin", "immersed") or layer not in FORMS:
        raise ValueError(f"layer = {{layer!r}} is not one of {{sorted(FORMS)}}")
    if not 0.0 < k <= 2.0 / 3.0:
        raise ValueError(f"inertia_factor = {{k!r}} is outside (0, 2/3]")
    if p_cav is None or p_cav == -math.inf:
        if not BOX["no_limit"]:
            raise ValueError("p_cav = None (no limit) is outside the box: " + {box!r})
    elif not BOX["p_cav"][0] * (1 + 1e-9) <= p_cav <= BOX["p_cav"][1] * (1 - 1e-9):
        raise ValueError(f"p_cav = {{p_cav!r}} is outside the box {{BOX['p_cav']}}")
    for name, value in (("St", St), ("eps", eps), ("delta", delta)):
        low, high = BOX[name]
        if value is not None and not low * (1 - 1e-9) <= value <= high * (1 + 1e-9):
            raise ValueError(f"{{name}} = {{value!r}} is outside the box [{{low:g}}, {{high:g}}]")
    if St is None or delta is None:
        return
    compression = ({hertz!r} * eps * St) ** 0.4
    if layer == "thin" and 2.0 * delta * (1.0 + compression) > 1.0:
        raise ValueError(
            f"delta = {{delta!r}} is outside the box for a thin layer: the wetted film would "
            "reach past the sphere's radius, 2 delta (1 + (13.88 eps St)^(2/5)) > 1"
        )
    if layer == "immersed" and 2.0 * delta * compression > 1.0:
        raise ValueError(
            f"delta = {{delta!r}} is outside the box for an immersed layer: the flattened "
            "contact would reach past the sphere's radius, 2 delta (13.88 eps St)^(2/5) > 1"
        )


def _features(St, eps, p_cav):
    L = -math.log(eps)
    elastic = -0.4 * L  # ln of the elastic gap, and of the suction gap:
    limited = p_cav is not None and p_cav != -math.inf
    suction = 0.5 * math.log({gap!r} / -p_cav) if limited else -math.inf
    top = max(elastic, suction)
    n = {norm!r}
    w = -(top + math.log(math.exp(n * (elastic - top)) + math.exp(n * (suction - top))) / n)
    return {{"x": math.log(St), "L": L, "v": 1.0 / L, "w": w, "h": w / L}}


def _q(form, f):
    total = 0.0
    for c, powers in zip(form["coefficients"], form["powers"]):
        term = c
        for name, p in zip(form["features"], powers):
            term *= f[name] ** p
        total += term
    return total


def critical_stokes(eps, p_cav, layer="thin"):
    """St_c = (2/5 + h) L + Q_c(v, h): no rebound below it (eps, P_cav and the layer checked
    against the box; St_c itself may lie outside the St range of the fit)."""
    _check(None, eps, None, p_cav, layer, 0.4)
    f = _features(1.0, eps, p_cav)
    return ({slope!r} + f["h"]) * f["L"] + _q(FORMS[layer]["St_c"], f)


def normal_restitution(St, eps, p_cav, layer="thin", delta=None):
    """e_n = 1 - (St_c/St)^m above St_c, else 0; m = exp(Q_m(v, h)). e_n does not depend on
    delta; a delta given is checked against the box as for e_t."""
    _check(St, eps, delta, p_cav, layer, 0.4)
    f = _features(St, eps, p_cav)
    St_c = ({slope!r} + f["h"]) * f["L"] + _q(FORMS[layer]["St_c"], f)
    if St <= St_c:
        return 0.0
    return 1.0 - (St_c / St) ** math.exp(_q(FORMS[layer]["m"], f))


def tangential_restitution(St, eps, delta, p_cav, layer="thin", inertia_factor=0.4):
    """e_t = 1 - k/(1 + k) (1 - exp(-(1 + 1/k) delta I)), 3 St I = P R + eps^(2/5) St E (thin),
    P (1 + D) R + eps^(2/5) St E + 2.94 C D T (immersed), P = 1 + 1/(e_n + 1/St), D =
    (1 + c) ln(1 + c) - c ln c - 1 with c = 1/(2 delta), C = (13.88 eps St)^(2/5), R, E, T =
    exp(Q(x, v, h)); stated errors for rebounds (e_n >= {clear})."""
    e_n = normal_restitution(St, eps, p_cav, layer)
    _check(St, eps, delta, p_cav, layer, inertia_factor)
    f = _features(St, eps, p_cav)
    forms = FORMS[layer]
    passes = (1.0 + 1.0 / (e_n + 1.0 / St)) * math.exp(_q(forms["R"], f))
    total = passes + eps**0.4 * St * math.exp(_q(forms["E"], f))
    if layer == "immersed":
        c = 0.5 / delta
        far = math.log1p(c) + c * math.log1p(1.0 / c) - 1.0
        contact = {contact_time!r} * ({hertz!r} * eps * St) ** 0.4
        total += far * (passes + contact * math.exp(_q(forms["T"], f)))
    k = inertia_factor
    return 1.0 - k / (1.0 + k) * -math.expm1(-(1.0 + 1.0 / k) * delta * total / (3.0 * St))


def spin_change(St, eps, delta, p_cav, layer="thin", inertia_factor=0.4):
    """a DeltaOmega/U0 = (1 - e_t)/k (no initial spin)."""
    e_t = tangential_restitution(St, eps, delta, p_cav, layer, inertia_factor)
    return (1.0 - e_t) / inertia_factor


def pair_restitution(
    St, eps, delta, p_cav, layer="thin", radius_ratio=1.0, density_ratio=1.0, upper_inertia=0.4,
    lower_inertia=0.4, upper_spin=0.0, lower_spin=0.0,
):
    """Two spheres: St, eps, delta, P_cav by the reduced radius a1 a2/(a1 + a2) and mass
    m1 m2/(m1 + m2); radius_ratio a1/a2, density_ratio rho2/rho1 (m1/m2 = (a1/a2)^3/(rho2/rho1)),
    the inertia factors k1, k2 in (0, 2/3], the initial spins s_i = a_i Omega_i/U0 about one
    axis. The wall at 1/k = 1/(k1 (1 + m1/m2)) + 1/(k2 (1 + m2/m1)), the slip scaled by 1 - w0,
    w0 = s1 + s2 (exact for the Couette model): a dict of St_c, e_n, the relative e_t, both
    spin changes a_i DeltaOmega_i/U0 and their sum, the impulse on sphere 1 (e_t - 1, by m U0)
    and k. The wall's errors hold relative to 1 - e_t and the spin changes."""
    for name, value in (("radius_ratio", radius_ratio), ("density_ratio", density_ratio)):
        if not 0.0 < value < math.inf:
            raise ValueError(f"{{name}} = {{value!r}} is outside (0, inf)")
    for name, value in (("upper_inertia", upper_inertia), ("lower_inertia", lower_inertia)):
        if not 0.0 < value <= 2.0 / 3.0:
            raise ValueError(f"{{name}} = {{value!r}} is outside (0, 2/3]")
    if not math.isfinite(upper_spin + lower_spin):
        raise ValueError(f"the spins {{upper_spin!r}}, {{lower_spin!r}} must be finite")
    mass_ratio = radius_ratio**3 / density_ratio
    upper, lower = upper_inertia * (1.0 + mass_ratio), lower_inertia * (1.0 + 1.0 / mass_ratio)
    k = min(1.0 / (1.0 / upper + 1.0 / lower), max(upper_inertia, lower_inertia))
    e_t = tangential_restitution(St, eps, delta, p_cav, layer, k)
    slip = 1.0 - (upper_spin + lower_spin)
    change = slip * (1.0 - e_t) / k
    e_t = 1.0 - slip * (1.0 - e_t)
    return {{
        "St_c": critical_stokes(eps, p_cav, layer),
        "e_n": normal_restitution(St, eps, p_cav, layer),
        "e_t": e_t,
        "upper_spin_change": lower / (upper + lower) * change,
        "lower_spin_change": upper / (upper + lower) * change,
        "contact_spin_change": change,
        "tangential_impulse": e_t - 1.0,
        "inertia_factor": k,
    }}


def dimensionless_groups(
    radius, density, normal_speed, viscosity, theta, layer_thickness, cavitation_pressure,
    ambient_pressure=101325.0,
):
    """(St, eps, delta, P_cav) of a solid sphere (SI inputs: m, kg/m^3, m/s, Pa s; theta =
    sum (1 - nu^2)/(pi E) of sphere and wall in 1/Pa; pressures absolute in Pa)."""
    mass = 4.0 / 3.0 * math.pi * radius**3 * density
    St = mass * normal_speed / (6.0 * math.pi * viscosity * radius**2)
    eps = 4.0 * theta * viscosity * normal_speed * radius**1.5 / layer_thickness**2.5
    scale = viscosity * normal_speed * radius / layer_thickness**2
    return St, eps, layer_thickness / radius, (cavitation_pressure - ambient_pressure) / scale
'''


def _plain(fits: dict) -> dict:
    """The forms as plain lists, by layer and name."""
    return {
        layer: {
            name: {
                "features": list(form["features"]),
                "powers": [list(p) for p in form["powers"]],
                "coefficients": [float(c) for c in form["coefficients"]],
            }
            for name, form in fits[layer].items()
        }
        for layer in LAYERS
        if layer in fits
    }


def _box(fits: dict) -> dict:
    box = fits["box"]
    return {k: list(box[k]) for k in ("St", "eps", "p_cav", "delta")} | {
        "no_limit": bool(box["no_limit"])
    }


def describe_errors(held_back: dict | None) -> str:
    """One sentence per layer of the held-back errors (or a note that none were measured)."""
    if not held_back:
        return "none measured (no held-back table)."
    parts = [
        f"{layer}: St_c {e['St_c_relative']:.1%}, e_n {e['e_n']:.2g}, e_t {e['e_t']:.2g} (1 - e_t "
        f"{e['tangential_loss_relative']:.0%}, {e['near_threshold_relative']:.0%} just above "
        f"St_c), spin change {e['spin_change']:.2g}"
        for layer, e in held_back.items()
    ]
    return "; ".join(parts) + "."


def python_source(fits: dict, table: str, version: str, held_back: dict | None = None) -> str:
    """A Python module (text, standard library only) with the forms ``fits`` of
    :func:`ehdfem.dem.fitting.fit_forms`, fitted to the table named ``table``."""
    return _PY.format(
        version=version,
        table=table,
        points=fits["points"],
        box=describe(fits["box"]),
        box_dict=_box(fits),
        forms=_plain(fits),
        errors=describe_errors(held_back),
        gap=shape.SUCTION_GAP,
        norm=shape.SUCTION_NORM,
        slope=shape.CRITICAL_SLOPE,
        clear=CLEAR_REBOUND,
        hertz=HERTZ,
        contact_time=shape.HERTZ_TIME,
    )


_C_HEAD = """/* Closed forms for DEM of a sphere hitting a wall through a liquid layer (thin or
 * immersed), fitted by ehdfem {version} (`ehdfem fit --c`) to {table} ({points}
 * collisions; half-spaces, Couette tangential model, e_dry = 1). C99, no dependency but
 * <math.h> (link with -lm).
 * Docs: docs/studies.md of ehdfem, "Closed forms for DEM".
 *
 * Dimensionless inputs (Davis, Serayssol & Hinch scales): St = m V0/(6 pi mu a^2),
 * eps = 4 theta mu V0 a^(3/2)/x0^(5/2), delta = x0/a, P_cav = (p_cav - p_ambient) x0^2/(mu V0 a)
 * < 0 (-INFINITY: no cavitation limit), layer EHD_THIN or EHD_IMMERSED, k = I/(m a^2) (0.4: a
 * solid sphere). e_n is the pure EHD value (multiply by the dry restitution); spin change =
 * a DeltaOmega/U0 (no initial spin).
 * Box: {box}; for a thin layer also
 * 2 delta (1 + (13.88 eps St)^(2/5)) <= 1 (the wetted film inside the sphere's radius), for an
 * immersed one 2 delta (13.88 eps St)^(2/5) <= 1 (the flattened contact inside it).
 * Outside it ehd_restitution sets every output to NaN and returns the flags EHD_OUT_* of the
 * parameters outside (0 inside).
 * Largest errors on points held back from the fit: {errors}
 *
 * Two spheres (ehd_pair_restitution; docs/tangential.md of ehdfem, "Two spheres"): St, eps,
 * delta, P_cav by the reduced radius a1 a2/(a1 + a2) and mass m1 m2/(m1 + m2); a1/a2 and
 * rho2/rho1 > 0 (m1/m2 = (a1/a2)^3/(rho2/rho1)), k1 and k2 in (0, 2/3], the initial spins
 * s_i = a_i Omega_i/U0 about one axis (U0 the relative tangential speed at first touch). The
 * pair is the wall at 1/k = 1/(k1 (1 + m1/m2)) + 1/(k2 (1 + m2/m1)) with the slip scaled by
 * 1 - w0, w0 = s1 + s2, exactly for the Couette model: 1 - e_t = (1 - w0)(1 - e_t(k)), the
 * contact spin's change (1 - w0)(1 - e_t(k))/k, split as c1 = k/(k1 (1 + m1/m2)) and 1 - c1;
 * e_t relative (U1 - U2), the impulse on sphere 1 e_t - 1 (by m U0). The wall's errors hold
 * relative to 1 - e_t and the spin changes (|1 - w0| times the absolute ones).
 */
#ifndef EHDFEM_CLOSED_FORMS_H
#define EHDFEM_CLOSED_FORMS_H

#include <math.h>

enum {{ EHD_THIN = 0, EHD_IMMERSED = 1 }};
enum {{
    EHD_OUT_ST = 1, EHD_OUT_EPS = 2, EHD_OUT_P_CAV = 4, EHD_OUT_DELTA = 8, EHD_OUT_LAYER = 16,
    EHD_OUT_INERTIA = 32, EHD_OUT_LOWER_INERTIA = 64, EHD_OUT_RATIO = 128, EHD_OUT_SPIN = 256
}};

typedef struct {{
    double St_c;        /* critical Stokes number: no rebound below it */
    double e_n;         /* normal restitution (pure EHD) */
    double e_t;         /* tangential restitution (for rebounds, e_n >= {clear}) */
    double spin_change; /* a DeltaOmega/U0 */
}} ehd_restitution_t;

typedef struct {{
    double St_c, e_n;           /* the wall's, of the relative normal motion */
    double e_t;                 /* relative: (U1 - U2) at exit over U0 */
    double upper_spin_change;   /* a1 DeltaOmega1/U0 */
    double lower_spin_change;   /* a2 DeltaOmega2/U0 (about the same axis) */
    double contact_spin_change; /* their sum */
    double tangential_impulse;  /* on sphere 1, by m U0 (e_t - 1) */
    double inertia_factor;      /* the pair's k */
}} ehd_pair_restitution_t;

typedef struct {{
    int terms, features;
    const int *feature; /* indices into (ln St, ln(1/eps), 1/ln(1/eps), w, w/ln(1/eps)) */
    const int *powers;  /* terms x features */
    const double *coefficients;
}} ehd_form_t;
"""

_C_TAIL = """
static inline double ehd_q_(const ehd_form_t *form, const double *f)
{{
    double total = 0.0;
    for (int t = 0; t < form->terms; ++t) {{
        double term = form->coefficients[t];
        for (int j = 0; j < form->features; ++j)
            term *= pow(f[form->feature[j]], (double)form->powers[t * form->features + j]);
        total += term;
    }}
    return total;
}}

static inline int ehd_outside_(double value, double low, double high)
{{
    return !(value >= low * (1.0 - 1e-9) && value <= high * (1.0 + 1e-9));
}}

/* Flags of the inputs outside the box (0: inside). */
static inline int ehd_check(double St, double eps, double delta, double p_cav, int layer, double k)
{{
    int flags = 0;
    if (ehd_outside_(St, {St_lo!r}, {St_hi!r})) flags |= EHD_OUT_ST;
    if (ehd_outside_(eps, {eps_lo!r}, {eps_hi!r})) flags |= EHD_OUT_EPS;
    if (ehd_outside_(delta, {delta_lo!r}, {delta_hi!r})) flags |= EHD_OUT_DELTA;
    if (p_cav == -INFINITY ? !{no_limit} : !(p_cav >= {p_lo!r} * (1.0 + 1e-9)
                                              && p_cav <= {p_hi!r} * (1.0 - 1e-9)))
        flags |= EHD_OUT_P_CAV;
    if ((layer != EHD_THIN || !{has_thin}) && (layer != EHD_IMMERSED || !{has_immersed}))
        flags |= EHD_OUT_LAYER;
    if (!(k > 0.0 && k <= 2.0 / 3.0)) flags |= EHD_OUT_INERTIA;
    /* a thin layer's wetted film, an immersed layer's flattened contact would reach past the
     * sphere's radius */
    double compression = pow({hertz!r} * eps * St, 0.4);
    if (layer == EHD_THIN && 2.0 * delta * (1.0 + compression) > 1.0) flags |= EHD_OUT_DELTA;
    if (layer == EHD_IMMERSED && 2.0 * delta * compression > 1.0) flags |= EHD_OUT_DELTA;
    return flags;
}}

/* St_c, e_n, e_t and the spin change at one collision; returns ehd_check's flags (outputs NaN
 * when they are not 0). */
static inline int ehd_restitution(double St, double eps, double delta, double p_cav, int layer,
                                  double k, ehd_restitution_t *out)
{{
    int flags = ehd_check(St, eps, delta, p_cav, layer, k);
    if (flags) {{
        out->St_c = out->e_n = out->e_t = out->spin_change = NAN;
        return flags;
    }}
    const ehd_form_t *forms = ehd_forms_[layer];
    double L = -log(eps);
    /* w = -ln of the 4-norm of the elastic and the suction gaps, from their logarithms */
    double elastic = -0.4 * L;
    double suction = p_cav == -INFINITY ? -INFINITY : 0.5 * log({gap!r} / -p_cav);
    double top = elastic > suction ? elastic : suction;
    double n = {norm!r};
    double w = -(top + log(exp(n * (elastic - top)) + exp(n * (suction - top))) / n);
    double f[5] = {{log(St), L, 1.0 / L, w, w / L}};
    double St_c = ({slope!r} + f[4]) * L + ehd_q_(&forms[0], f);
    double ratio = St_c / St;
    ratio = ratio < 0.0 ? 0.0 : (ratio > 1.0 ? 1.0 : ratio);
    double e_n = 1.0 - pow(ratio, exp(ehd_q_(&forms[1], f)));
    /* 3 St I: the rigid passes, the elastic contact and (immersed) the far field */
    double passes = (1.0 + 1.0 / (e_n + 1.0 / St)) * exp(ehd_q_(&forms[2], f));
    double total = passes + pow(eps, 0.4) * St * exp(ehd_q_(&forms[3], f));
    if (layer == EHD_IMMERSED) {{
        double c = 0.5 / delta;
        double far = log1p(c) + c * log1p(1.0 / c) - 1.0;
        double contact = {contact_time!r} * pow({hertz!r} * eps * St, 0.4);
        total += far * (passes + contact * exp(ehd_q_(&forms[4], f)));
    }}
    out->St_c = St_c;
    out->e_n = e_n;
    out->e_t = 1.0 - k / (1.0 + k) * -expm1(-(1.0 + 1.0 / k) * delta * total / (3.0 * St));
    out->spin_change = (1.0 - out->e_t) / k;
    return 0;
}}

/* Two spheres (see the top): the flags of ehd_restitution at the pair's k, EHD_OUT_INERTIA
 * and EHD_OUT_LOWER_INERTIA for k1 and k2, EHD_OUT_RATIO for a1/a2 or rho2/rho1 not a positive
 * number, EHD_OUT_SPIN for a spin not finite (outputs NaN when they are not 0). */
static inline int ehd_pair_restitution(double St, double eps, double delta, double p_cav,
                                       int layer, double radius_ratio, double density_ratio,
                                       double k1, double k2, double s1, double s2,
                                       ehd_pair_restitution_t *out)
{{
    int flags = 0;
    if (!(k1 > 0.0 && k1 <= 2.0 / 3.0)) flags |= EHD_OUT_INERTIA;
    if (!(k2 > 0.0 && k2 <= 2.0 / 3.0)) flags |= EHD_OUT_LOWER_INERTIA;
    if (!(radius_ratio > 0.0 && isfinite(radius_ratio) && density_ratio > 0.0
          && isfinite(density_ratio)))
        flags |= EHD_OUT_RATIO;
    if (!isfinite(s1) || !isfinite(s2)) flags |= EHD_OUT_SPIN;
    double mass_ratio = radius_ratio * radius_ratio * radius_ratio / density_ratio;
    double upper = k1 * (1.0 + mass_ratio), lower = k2 * (1.0 + 1.0 / mass_ratio);
    double k = 1.0 / (1.0 / upper + 1.0 / lower), top = k1 > k2 ? k1 : k2;
    k = k < top ? k : top; /* a weighted harmonic mean of k1 and k2, capped against rounding */
    ehd_restitution_t wall;
    flags |= ehd_check(St, eps, delta, p_cav, layer, flags ? 0.4 : k);
    if (flags) {{
        out->St_c = out->e_n = out->e_t = out->upper_spin_change = out->lower_spin_change = NAN;
        out->contact_spin_change = out->tangential_impulse = out->inertia_factor = NAN;
        return flags;
    }}
    ehd_restitution(St, eps, delta, p_cav, layer, k, &wall);
    double slip = 1.0 - (s1 + s2); /* u_s(0) = 1 - w0 */
    double change = slip * wall.spin_change;
    out->St_c = wall.St_c;
    out->e_n = wall.e_n;
    out->e_t = 1.0 - slip * (1.0 - wall.e_t);
    out->upper_spin_change = lower / (upper + lower) * change;
    out->lower_spin_change = upper / (upper + lower) * change;
    out->contact_spin_change = change;
    out->tangential_impulse = out->e_t - 1.0;
    out->inertia_factor = k;
    return 0;
}}

#endif /* EHDFEM_CLOSED_FORMS_H */
"""


def _c_number(x: float) -> str:
    return repr(float(x))


def _c_form(prefix: str, form: dict) -> tuple[str, str]:
    """The static arrays of one form and its initialiser."""
    indices = ", ".join(str(FEATURE_ORDER.index(n)) for n in form["features"])
    powers = ", ".join(str(p) for term in form["powers"] for p in term)
    coefficients = ",\n    ".join(_c_number(c) for c in form["coefficients"])
    arrays = (
        f"static const int {prefix}_feature[] = {{{indices}}};\n"
        f"static const int {prefix}_powers[] = {{{powers}}};\n"
        f"static const double {prefix}_coefficients[] = {{\n    {coefficients}}};\n"
    )
    init = (
        f"{{{len(form['powers'])}, {len(form['features'])}, {prefix}_feature, {prefix}_powers, "
        f"{prefix}_coefficients}}"
    )
    return arrays, init


def c_header(fits: dict, table: str, version: str, held_back: dict | None = None) -> str:
    """A C99 header (text) with the forms ``fits`` of :func:`ehdfem.dem.fitting.fit_forms`:
    ehd_restitution, ehd_pair_restitution and ehd_check (static functions), the same values as
    :func:`python_source`'s module (tested to 1e-12)."""
    box = fits["box"]
    parts, tables = [], []
    for layer in LAYERS:
        inits = []
        for name in shape.NAMES:
            form = fits.get(layer, {}).get(name)
            if form is None:  # a layer not fitted, or T of the thin layer: unused
                inits.append("{0, 0, 0, 0, 0}")
                continue
            arrays, init = _c_form(f"ehd_{layer}_{name}_", form)
            parts.append(arrays)
            inits.append(init)
        tables.append("{" + ",\n     ".join(inits) + "}")
    head = _C_HEAD.format(
        version=version,
        table=table,
        points=fits["points"],
        box=describe(box),
        errors=describe_errors(held_back),
        clear=CLEAR_REBOUND,
    )
    forms = (
        f"static const ehd_form_t ehd_forms_[2][{len(shape.NAMES)}] = {{\n    "
        + ",\n    ".join(tables)
        + "};\n"
    )
    tail = _C_TAIL.format(
        St_lo=box["St"][0], St_hi=box["St"][1], eps_lo=box["eps"][0], eps_hi=box["eps"][1],
        delta_lo=box["delta"][0], delta_hi=box["delta"][1], p_lo=box["p_cav"][0],
        p_hi=box["p_cav"][1], no_limit=int(box["no_limit"]), has_thin=int("thin" in fits),
        has_immersed=int("immersed" in fits), gap=shape.SUCTION_GAP, norm=shape.SUCTION_NORM,
        slope=shape.CRITICAL_SLOPE, hertz=HERTZ, contact_time=shape.HERTZ_TIME,
    )  # fmt: skip
    return head + "\n" + "".join(parts) + "\n" + forms + tail
