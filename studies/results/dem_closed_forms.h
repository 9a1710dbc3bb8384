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
 * Largest errors on points held back from the fit: thin: St_c 4.4%, e_n 0.019, e_t 0.00045 (1 - e_t 3%, 45% just above St_c), spin change 0.0011; immersed: St_c 3.0%, e_n 0.011, e_t 0.00045 (1 - e_t 2%, 56% just above St_c), spin change 0.0011.
 */
#ifndef EHDFEM_CLOSED_FORMS_H
#define EHDFEM_CLOSED_FORMS_H

#include <math.h>

enum { EHD_THIN = 0, EHD_IMMERSED = 1 };
enum {
    EHD_OUT_ST = 1, EHD_OUT_EPS = 2, EHD_OUT_P_CAV = 4, EHD_OUT_DELTA = 8, EHD_OUT_LAYER = 16,
    EHD_OUT_INERTIA = 32
};

typedef struct {
    double St_c;        /* critical Stokes number: no rebound below it */
    double e_n;         /* normal restitution (pure EHD) */
    double e_t;         /* tangential restitution (for rebounds, e_n >= 0.3) */
    double spin_change; /* a DeltaOmega/U0 */
} ehd_restitution_t;

typedef struct {
    int terms, features;
    const int *feature; /* indices into (ln St, ln(1/eps), 1/ln(1/eps), w, w/ln(1/eps)) */
    const int *powers;  /* terms x features */
    const double *coefficients;
} ehd_form_t;

static const int ehd_thin_St_c__feature[] = {2, 4};
static const int ehd_thin_St_c__powers[] = {0, 0, 0, 1, 0, 2, 0, 3, 1, 0, 1, 1, 1, 2, 2, 0, 2, 1, 3, 0};
static const double ehd_thin_St_c__coefficients[] = {
    0.20194126550339103,
    4.066866490985171,
    -47.7055977052666,
    157.48859500951627,
    -19.355842129664406,
    54.81878638217616,
    -269.3980267304028,
    42.15453331117518,
    150.12891545468568,
    -85.86482897007332};
static const int ehd_thin_m__feature[] = {2, 4};
static const int ehd_thin_m__powers[] = {0, 0, 0, 1, 0, 2, 0, 3, 1, 0, 1, 1, 1, 2, 2, 0, 2, 1, 3, 0};
static const double ehd_thin_m__coefficients[] = {
    -0.0486229245683083,
    0.2169839457531963,
    -0.8392185776087597,
    0.2592843601840785,
    -3.18567684101467,
    8.355812472338458,
    -12.870097846528775,
    2.332395051177598,
    2.9755685771465266,
    -3.6738815281041437};
static const int ehd_thin_R__feature[] = {0, 2, 4};
static const int ehd_thin_R__powers[] = {0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 1, 0, 0, 1, 1, 0, 2, 0, 1, 0, 0, 1, 0, 1, 1, 1, 0, 2, 0, 0};
static const double ehd_thin_R__coefficients[] = {
    -0.14278022065349633,
    -0.45337062271829415,
    0.25987738460369203,
    7.573698157620101,
    2.027047549807028,
    -39.63897609924155,
    -0.006113010418212133,
    0.03829459220886459,
    -0.21927473004730974,
    0.0006542053903625756};
static const int ehd_thin_E__feature[] = {0, 2, 4};
static const int ehd_thin_E__powers[] = {0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 1, 0, 0, 1, 1, 0, 2, 0, 1, 0, 0, 1, 0, 1, 1, 1, 0, 2, 0, 0};
static const double ehd_thin_E__coefficients[] = {
    3.2506732973516086,
    0.12893054627673006,
    0.4050673690441501,
    -1.3852419722236244,
    -0.07022596036626592,
    1.2441653841246292,
    -0.2781916273331563,
    -0.03405131921293263,
    0.08518830237190769,
    0.01342549268220502};
static const int ehd_immersed_St_c__feature[] = {2, 4};
static const int ehd_immersed_St_c__powers[] = {0, 0, 0, 1, 0, 2, 0, 3, 1, 0, 1, 1, 1, 2, 2, 0, 2, 1, 3, 0};
static const double ehd_immersed_St_c__coefficients[] = {
    3.0973786406713497,
    8.482306610326036,
    -68.78438254155162,
    174.1628227830318,
    -21.43473939520482,
    76.1834962532791,
    -207.70375829265535,
    56.887229981485866,
    49.8324351218489,
    -92.91235622612919};
static const int ehd_immersed_m__feature[] = {2, 4};
static const int ehd_immersed_m__powers[] = {0, 0, 0, 1, 0, 2, 0, 3, 1, 0, 1, 1, 1, 2, 2, 0, 2, 1, 3, 0};
static const double ehd_immersed_m__coefficients[] = {
    -0.06175087476036886,
    0.05537635856761655,
    0.9955715661572826,
    -3.280501341789588,
    -1.6743686186030566,
    -0.5373752708708341,
    2.773624633002768,
    3.1731867720062517,
    -0.9700569318141439,
    -1.9594250581904913};
static const int ehd_immersed_R__feature[] = {0, 2, 4};
static const int ehd_immersed_R__powers[] = {0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 1, 0, 0, 1, 1, 0, 2, 0, 1, 0, 0, 1, 0, 1, 1, 1, 0, 2, 0, 0};
static const double ehd_immersed_R__coefficients[] = {
    0.00919375912210668,
    -0.16144233444671727,
    0.19793712285637327,
    1.1983922119852646,
    0.12096023433238537,
    -4.771201729060439,
    -0.007662994744183722,
    0.009554796987107613,
    0.019313307652932377,
    0.0002425196448676253};
static const int ehd_immersed_E__feature[] = {0, 2, 4};
static const int ehd_immersed_E__powers[] = {0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 1, 0, 0, 1, 1, 0, 2, 0, 1, 0, 0, 1, 0, 1, 1, 1, 0, 2, 0, 0};
static const double ehd_immersed_E__coefficients[] = {
    3.0849318173957627,
    0.11516206490257376,
    0.28861637651337263,
    -1.344333821408264,
    0.051104054760450976,
    1.1618616762581437,
    -0.2387309230721641,
    -0.02578266421959819,
    0.07576181284256925,
    0.011036870441523487};
static const int ehd_immersed_T__feature[] = {0, 2, 4};
static const int ehd_immersed_T__powers[] = {0, 0, 0};
static const double ehd_immersed_T__coefficients[] = {
    0.015200810143264003};

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

#endif /* EHDFEM_CLOSED_FORMS_H */
