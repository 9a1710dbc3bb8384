/* Closed forms for DEM of a sphere hitting a wall through a liquid layer (thin or
 * immersed), fitted by ehdfem 0.1.0 (`ehdfem fit --c`) to dem_closed_forms.csv (2912
 * collisions; half-spaces, Couette tangential model, e_dry = 1). C99, no dependency but
 * <math.h> (link with -lm).
 * Docs: docs/studies.md of ehdfem, "Closed forms for DEM".
 *
 * Dimensionless inputs (Davis, Serayssol & Hinch scales): St = m V0/(6 pi mu a^2),
 * eps = 4 theta mu V0 a^(3/2)/x0^(5/2), delta = x0/a, P_cav = (p_cav - p_ambient) x0^2/(mu V0 a)
 * < 0 (-INFINITY: no cavitation limit), layer EHD_THIN or EHD_IMMERSED, k = I/(m a^2) (0.4: a
 * solid sphere). e_n is the pure EHD value (multiply by the dry restitution); spin change =
 * a DeltaOmega/U0 (no initial spin).
 * Box: St in [1, 10000], eps in [1e-12, 0.1], P_cav in [-100000, -1], delta in [0.001, 0.5] (P_cav also none); for a thin layer also
 * 2 delta (1 + (13.88 eps St)^(2/5)) <= 1 (the wetted film inside the sphere's radius), for an
 * immersed one 2 delta (13.88 eps St)^(2/5) <= 1 (the flattened contact inside it).
 * Outside it ehd_restitution sets every output to NaN and returns the flags EHD_OUT_* of the
 * parameters outside (0 inside).
 * Largest errors on points held back from the fit: thin: St_c 4.3%, e_n 0.019, e_t 0.00044 (1 - e_t 3%, 45% just above St_c), spin change 0.0011; immersed: St_c 3.0%, e_n 0.011, e_t 0.00045 (1 - e_t 2%, 56% just above St_c), spin change 0.0011.
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

enum { EHD_THIN = 0, EHD_IMMERSED = 1 };
enum {
    EHD_OUT_ST = 1, EHD_OUT_EPS = 2, EHD_OUT_P_CAV = 4, EHD_OUT_DELTA = 8, EHD_OUT_LAYER = 16,
    EHD_OUT_INERTIA = 32, EHD_OUT_LOWER_INERTIA = 64, EHD_OUT_RATIO = 128, EHD_OUT_SPIN = 256
};

typedef struct {
    double St_c;        /* critical Stokes number: no rebound below it */
    double e_n;         /* normal restitution (pure EHD) */
    double e_t;         /* tangential restitution (for rebounds, e_n >= 0.3) */
    double spin_change; /* a DeltaOmega/U0 */
} ehd_restitution_t;

typedef struct {
    double St_c, e_n;           /* the wall's, of the relative normal motion */
    double e_t;                 /* relative: (U1 - U2) at exit over U0 */
    double upper_spin_change;   /* a1 DeltaOmega1/U0 */
    double lower_spin_change;   /* a2 DeltaOmega2/U0 (about the same axis) */
    double contact_spin_change; /* their sum */
    double tangential_impulse;  /* on sphere 1, by m U0 (e_t - 1) */
    double inertia_factor;      /* the pair's k */
} ehd_pair_restitution_t;

typedef struct {
    int terms, features;
    const int *feature; /* indices into (ln St, ln(1/eps), 1/ln(1/eps), w, w/ln(1/eps)) */
    const int *powers;  /* terms x features */
    const double *coefficients;
} ehd_form_t;

static const int ehd_thin_St_c__feature[] = {2, 4};
static const int ehd_thin_St_c__powers[] = {0, 0, 0, 1, 0, 2, 0, 3, 1, 0, 1, 1, 1, 2, 2, 0, 2, 1, 3, 0};
static const double ehd_thin_St_c__coefficients[] = {
    0.20194072290779214,
    4.066911680543236,
    -47.705911291434035,
    157.48911624311424,
    -19.355867828100966,
    54.81900411956095,
    -269.39846587953434,
    42.154529795733474,
    150.1290170977132,
    -85.86487621921327};
static const int ehd_thin_m__feature[] = {2, 4};
static const int ehd_thin_m__powers[] = {0, 0, 0, 1, 0, 2, 0, 3, 1, 0, 1, 1, 1, 2, 2, 0, 2, 1, 3, 0};
static const double ehd_thin_m__coefficients[] = {
    -0.048623180188696755,
    0.21699449530987927,
    -0.8392882953420092,
    0.2593980575543054,
    -3.1856807643942147,
    8.355856264802197,
    -12.870185569261153,
    2.332387742313737,
    2.975587008943733,
    -3.6738803924117813};
static const int ehd_thin_R__feature[] = {0, 2, 4};
static const int ehd_thin_R__powers[] = {0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 1, 0, 0, 1, 1, 0, 2, 0, 1, 0, 0, 1, 0, 1, 1, 1, 0, 2, 0, 0};
static const double ehd_thin_R__coefficients[] = {
    -0.14278023526667466,
    -0.45337034902602263,
    0.2598772038394549,
    7.573697831992784,
    2.0270450558891207,
    -39.63897378250233,
    -0.006113007776028662,
    0.03829457717017818,
    -0.2192746921077954,
    0.0006542052222182962};
static const int ehd_thin_E__feature[] = {0, 2, 4};
static const int ehd_thin_E__powers[] = {0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 1, 0, 0, 1, 1, 0, 2, 0, 1, 0, 0, 1, 0, 1, 1, 1, 0, 2, 0, 0};
static const double ehd_thin_E__coefficients[] = {
    3.2506733280057216,
    0.12893054147367106,
    0.40506752385179917,
    -1.3852420947685327,
    -0.07022610071756427,
    1.2441655453551665,
    -0.2781916334606266,
    -0.034051325395551085,
    0.08518831376317088,
    0.013425493060575923};
static const int ehd_immersed_St_c__feature[] = {2, 4};
static const int ehd_immersed_St_c__powers[] = {0, 0, 0, 1, 0, 2, 0, 3, 1, 0, 1, 1, 1, 2, 2, 0, 2, 1, 3, 0};
static const double ehd_immersed_St_c__coefficients[] = {
    3.097377053764902,
    8.482318414186368,
    -68.78426768927763,
    174.16244203101158,
    -21.43471059733501,
    76.18282343972498,
    -207.70201610261117,
    56.88741783493949,
    49.83160319552052,
    -92.91219304444174};
static const int ehd_immersed_m__feature[] = {2, 4};
static const int ehd_immersed_m__powers[] = {0, 0, 0, 1, 0, 2, 0, 3, 1, 0, 1, 1, 1, 2, 2, 0, 2, 1, 3, 0};
static const double ehd_immersed_m__coefficients[] = {
    -0.06175102195541769,
    0.055377142030996945,
    0.9955927398764975,
    -3.2805608110245,
    -1.674364934431112,
    -0.5374854652293887,
    2.7738989146182185,
    3.1732257888949698,
    -0.9701850067120226,
    -1.9594126714721831};
static const int ehd_immersed_R__feature[] = {0, 2, 4};
static const int ehd_immersed_R__powers[] = {0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 1, 0, 0, 1, 1, 0, 2, 0, 1, 0, 0, 1, 0, 1, 1, 1, 0, 2, 0, 0};
static const double ehd_immersed_R__coefficients[] = {
    0.00919382958841934,
    -0.16144223673914065,
    0.19793692334587165,
    1.1983910457189468,
    0.12095985971504117,
    -4.771199744826723,
    -0.007663010447951337,
    0.009554797540240531,
    0.019313462530849857,
    0.00024252029976805858};
static const int ehd_immersed_E__feature[] = {0, 2, 4};
static const int ehd_immersed_E__powers[] = {0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 1, 0, 0, 1, 1, 0, 2, 0, 1, 0, 0, 1, 0, 1, 1, 1, 0, 2, 0, 0};
static const double ehd_immersed_E__coefficients[] = {
    3.0849318681230486,
    0.1151621270680265,
    0.2886163718548811,
    -1.3443342180217295,
    0.051104292558834336,
    1.1618617591351321,
    -0.23873093281225935,
    -0.02578267513590067,
    0.07576184642002554,
    0.011036871006927351};
static const int ehd_immersed_T__feature[] = {0, 2, 4};
static const int ehd_immersed_T__powers[] = {0, 0, 0};
static const double ehd_immersed_T__coefficients[] = {
    0.015200848651047124};

static const ehd_form_t ehd_forms_[2][5] = {
    {{10, 2, ehd_thin_St_c__feature, ehd_thin_St_c__powers, ehd_thin_St_c__coefficients},
     {10, 2, ehd_thin_m__feature, ehd_thin_m__powers, ehd_thin_m__coefficients},
     {10, 3, ehd_thin_R__feature, ehd_thin_R__powers, ehd_thin_R__coefficients},
     {10, 3, ehd_thin_E__feature, ehd_thin_E__powers, ehd_thin_E__coefficients},
     {0, 0, 0, 0, 0}},
    {{10, 2, ehd_immersed_St_c__feature, ehd_immersed_St_c__powers, ehd_immersed_St_c__coefficients},
     {10, 2, ehd_immersed_m__feature, ehd_immersed_m__powers, ehd_immersed_m__coefficients},
     {10, 3, ehd_immersed_R__feature, ehd_immersed_R__powers, ehd_immersed_R__coefficients},
     {10, 3, ehd_immersed_E__feature, ehd_immersed_E__powers, ehd_immersed_E__coefficients},
     {1, 3, ehd_immersed_T__feature, ehd_immersed_T__powers, ehd_immersed_T__coefficients}}};

static inline double ehd_q_(const ehd_form_t *form, const double *f)
{
    double total = 0.0;
    for (int t = 0; t < form->terms; ++t) {
        double term = form->coefficients[t];
        for (int j = 0; j < form->features; ++j)
            term *= pow(f[form->feature[j]], (double)form->powers[t * form->features + j]);
        total += term;
    }
    return total;
}

static inline int ehd_outside_(double value, double low, double high)
{
    return !(value >= low * (1.0 - 1e-9) && value <= high * (1.0 + 1e-9));
}

/* Flags of the inputs outside the box (0: inside). */
static inline int ehd_check(double St, double eps, double delta, double p_cav, int layer, double k)
{
    int flags = 0;
    if (ehd_outside_(St, 1.0, 10000.0)) flags |= EHD_OUT_ST;
    if (ehd_outside_(eps, 1e-12, 0.1)) flags |= EHD_OUT_EPS;
    if (ehd_outside_(delta, 0.001, 0.5)) flags |= EHD_OUT_DELTA;
    if (p_cav == -INFINITY ? !1 : !(p_cav >= -100000.0 * (1.0 + 1e-9)
                                              && p_cav <= -1.0 * (1.0 - 1e-9)))
        flags |= EHD_OUT_P_CAV;
    if ((layer != EHD_THIN || !1) && (layer != EHD_IMMERSED || !1))
        flags |= EHD_OUT_LAYER;
    if (!(k > 0.0 && k <= 2.0 / 3.0)) flags |= EHD_OUT_INERTIA;
    /* a thin layer's wetted film, an immersed layer's flattened contact would reach past the
     * sphere's radius */
    double compression = pow(13.87913118903191 * eps * St, 0.4);
    if (layer == EHD_THIN && 2.0 * delta * (1.0 + compression) > 1.0) flags |= EHD_OUT_DELTA;
    if (layer == EHD_IMMERSED && 2.0 * delta * compression > 1.0) flags |= EHD_OUT_DELTA;
    return flags;
}

/* St_c, e_n, e_t and the spin change at one collision; returns ehd_check's flags (outputs NaN
 * when they are not 0). */
static inline int ehd_restitution(double St, double eps, double delta, double p_cav, int layer,
                                  double k, ehd_restitution_t *out)
{
    int flags = ehd_check(St, eps, delta, p_cav, layer, k);
    if (flags) {
        out->St_c = out->e_n = out->e_t = out->spin_change = NAN;
        return flags;
    }
    const ehd_form_t *forms = ehd_forms_[layer];
    double L = -log(eps);
    /* w = -ln of the 4-norm of the elastic and the suction gaps, from their logarithms */
    double elastic = -0.4 * L;
    double suction = p_cav == -INFINITY ? -INFINITY : 0.5 * log(0.3 / -p_cav);
    double top = elastic > suction ? elastic : suction;
    double n = 4.0;
    double w = -(top + log(exp(n * (elastic - top)) + exp(n * (suction - top))) / n);
    double f[5] = {log(St), L, 1.0 / L, w, w / L};
    double St_c = (0.4 + f[4]) * L + ehd_q_(&forms[0], f);
    double ratio = St_c / St;
    ratio = ratio < 0.0 ? 0.0 : (ratio > 1.0 ? 1.0 : ratio);
    double e_n = 1.0 - pow(ratio, exp(ehd_q_(&forms[1], f)));
    /* 3 St I: the rigid passes, the elastic contact and (immersed) the far field */
    double passes = (1.0 + 1.0 / (e_n + 1.0 / St)) * exp(ehd_q_(&forms[2], f));
    double total = passes + pow(eps, 0.4) * St * exp(ehd_q_(&forms[3], f));
    if (layer == EHD_IMMERSED) {
        double c = 0.5 / delta;
        double far = log1p(c) + c * log1p(1.0 / c) - 1.0;
        double contact = 2.94 * pow(13.87913118903191 * eps * St, 0.4);
        total += far * (passes + contact * exp(ehd_q_(&forms[4], f)));
    }
    out->St_c = St_c;
    out->e_n = e_n;
    out->e_t = 1.0 - k / (1.0 + k) * -expm1(-(1.0 + 1.0 / k) * delta * total / (3.0 * St));
    out->spin_change = (1.0 - out->e_t) / k;
    return 0;
}

/* Two spheres (see the top): the flags of ehd_restitution at the pair's k, EHD_OUT_INERTIA
 * and EHD_OUT_LOWER_INERTIA for k1 and k2, EHD_OUT_RATIO for a1/a2 or rho2/rho1 not a positive
 * number, EHD_OUT_SPIN for a spin not finite (outputs NaN when they are not 0). */
static inline int ehd_pair_restitution(double St, double eps, double delta, double p_cav,
                                       int layer, double radius_ratio, double density_ratio,
                                       double k1, double k2, double s1, double s2,
                                       ehd_pair_restitution_t *out)
{
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
    if (flags) {
        out->St_c = out->e_n = out->e_t = out->upper_spin_change = out->lower_spin_change = NAN;
        out->contact_spin_change = out->tangential_impulse = out->inertia_factor = NAN;
        return flags;
    }
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
}

#endif /* EHDFEM_CLOSED_FORMS_H */
