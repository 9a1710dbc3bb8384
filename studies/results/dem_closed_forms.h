/* Closed forms for DEM of a sphere hitting a wall through a liquid layer (thin or
 * immersed), fitted by ehdfem 0.1.0 (`ehdfem fit --c`) to dem_closed_forms_reduced.csv (1080
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
 * 2 delta (1 + (13.88 eps St)^(2/5)) <= 1 (the wetted film inside the sphere's radius).
 * Outside it ehd_restitution sets every output to NaN and returns the flags EHD_OUT_* of the
 * parameters outside (0 inside).
 * Largest errors on points held back from the fit: thin: e_n 0.067, e_t 0.00056 (1 - e_t 4%, 36% just above St_c), spin change 0.0014; immersed: e_n 0.037, e_t 0.00083 (1 - e_t 6%, 57% just above St_c), spin change 0.0021.
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
    0.7510783156674254,
    12.035883464158356,
    -19.48079989006516,
    5.01161715525705,
    -4.844877599463705,
    -66.65448976092158,
    39.61335440975715,
    20.096436651150206,
    77.83214917289511,
    -31.550680529442467};
static const int ehd_thin_m__feature[] = {2, 4};
static const int ehd_thin_m__powers[] = {0, 0, 0, 1, 0, 2, 0, 3, 1, 0, 1, 1, 1, 2, 2, 0, 2, 1, 3, 0};
static const double ehd_thin_m__coefficients[] = {
    -0.10745925644212502,
    1.6678490693050982,
    -7.568035226028594,
    8.300324072687593,
    -1.924592091444689,
    -6.374520999073137,
    13.180227221609872,
    7.243147923180116,
    1.1263559097824303,
    -10.070775782465185};
static const int ehd_thin_R__feature[] = {0, 2, 4};
static const int ehd_thin_R__powers[] = {0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 1, 0, 0, 1, 1, 0, 2, 0, 1, 0, 0, 1, 0, 1, 1, 1, 0, 2, 0, 0};
static const double ehd_thin_R__coefficients[] = {
    -0.2202952256310015,
    -0.48365494574459095,
    0.29865772500220306,
    9.61093183694879,
    4.133455722542304,
    -47.32006785030662,
    0.004067670618529788,
    0.02816916201844204,
    -0.5330067259220371,
    0.0014019415890320957};
static const int ehd_thin_E__feature[] = {0, 2, 4};
static const int ehd_thin_E__powers[] = {0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 1, 0, 0, 1, 1, 0, 2, 0, 1, 0, 0, 1, 0, 1, 1, 1, 0, 2, 0, 0};
static const double ehd_thin_E__coefficients[] = {
    3.253297056266974,
    0.19773901901867186,
    -0.07762168214422137,
    -1.1245862655715935,
    -0.19853944602546075,
    1.051892672195397,
    -0.2795308179999323,
    -0.013451647710845874,
    0.06796338973997167,
    0.013282606730527485};
static const int ehd_immersed_St_c__feature[] = {2, 4};
static const int ehd_immersed_St_c__powers[] = {0, 0, 0, 1, 0, 2, 0, 3, 1, 0, 1, 1, 1, 2, 2, 0, 2, 1, 3, 0};
static const double ehd_immersed_St_c__coefficients[] = {
    3.5728694766170825,
    13.41367553024312,
    -11.554488622489222,
    -11.795379729533973,
    1.0120527869556897,
    -52.945021974679314,
    24.53711205367503,
    14.599041641629634,
    55.07313653041078,
    -39.77650703854035};
static const int ehd_immersed_m__feature[] = {2, 4};
static const int ehd_immersed_m__powers[] = {0, 0, 0, 1, 0, 2, 0, 3, 1, 0, 1, 1, 1, 2, 2, 0, 2, 1, 3, 0};
static const double ehd_immersed_m__coefficients[] = {
    -0.08884395969475271,
    0.7920185163698542,
    -3.1510201647563805,
    2.7352019970110026,
    -0.9625270599447971,
    -3.288306003140851,
    6.097454635004669,
    1.138210752851459,
    1.7585682460681111,
    -0.27797763927321195};
static const int ehd_immersed_R__feature[] = {0, 2, 4};
static const int ehd_immersed_R__powers[] = {0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 1, 0, 0, 1, 1, 0, 2, 0, 1, 0, 0, 1, 0, 1, 1, 1, 0, 2, 0, 0};
static const double ehd_immersed_R__coefficients[] = {
    -0.08118446840590073,
    -0.3277688355905111,
    0.29005450928383264,
    1.7340137821857888,
    1.6068598170471653,
    -2.2197981463395395,
    0.021653178283117056,
    0.01982210447152124,
    -0.2298587652523906,
    -0.0010740257719867555};
static const int ehd_immersed_E__feature[] = {0, 2, 4};
static const int ehd_immersed_E__powers[] = {0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 1, 0, 0, 1, 1, 0, 2, 0, 1, 0, 0, 1, 0, 1, 1, 1, 0, 2, 0, 0};
static const double ehd_immersed_E__coefficients[] = {
    3.69975247085235,
    0.31102141862357036,
    -0.0054448613394127345,
    -4.482238697700979,
    0.07207406435282152,
    -0.7195833169724063,
    -0.35781084103880617,
    -0.03446785595614854,
    0.4265637526580231,
    0.01671290239311411};
static const int ehd_immersed_T__feature[] = {0, 2, 4};
static const int ehd_immersed_T__powers[] = {0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 1, 0, 0, 1, 1, 0, 2, 0, 1, 0, 0, 1, 0, 1, 1, 1, 0, 2, 0, 0};
static const double ehd_immersed_T__coefficients[] = {
    -0.7987628063772155,
    -0.09183231193580266,
    -0.16105710028449088,
    4.124975717029931,
    -0.0795376386805002,
    -6.3969583699528005,
    0.023654579641041413,
    0.011076245182617137,
    0.4548673463157343,
    0.004343499000445477};

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
     {10, 3, ehd_immersed_T__feature, ehd_immersed_T__powers, ehd_immersed_T__coefficients}}};

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
    /* a thin layer's wetted film would reach past the sphere's radius */
    if (layer == EHD_THIN && 2.0 * delta * (1.0 + pow(13.87913118903191 * eps * St, 0.4)) > 1.0)
        flags |= EHD_OUT_DELTA;
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
    double w = -log(pow(eps, 0.4) + (p_cav == -INFINITY ? 0.0 : sqrt(3.0 / fabs(p_cav))));
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
