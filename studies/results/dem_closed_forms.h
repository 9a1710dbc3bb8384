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
 * Largest errors on points held back from the fit: thin: e_n 0.067, e_t 0.0021 (1 - e_t 36%, 81% just above St_c), spin change 0.0052; immersed: e_n 0.037, e_t 0.0033 (1 - e_t 31%, 88% just above St_c), spin change 0.0081.
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
static const int ehd_thin_A__feature[] = {0, 2, 4};
static const int ehd_thin_A__powers[] = {0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0, 4, 0, 1, 0, 0, 1, 1, 0, 1, 2, 0, 1, 3, 0, 2, 0, 0, 2, 1, 0, 2, 2, 0, 3, 0, 0, 3, 1, 0, 4, 0, 1, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0, 3, 1, 1, 0, 1, 1, 1, 1, 1, 2, 1, 2, 0, 1, 2, 1, 1, 3, 0, 2, 0, 0, 2, 0, 1, 2, 0, 2, 2, 1, 0, 2, 1, 1, 2, 2, 0, 3, 0, 0, 3, 0, 1, 3, 1, 0, 4, 0, 0};
static const double ehd_thin_A__coefficients[] = {
    5.622955647039954,
    2.894463970615483,
    -8.506721876535428,
    23.942705455876094,
    -20.26356926767839,
    -79.03168404539497,
    -2.813698844795534,
    8.86655433365315,
    -13.123046244078804,
    357.0650722529455,
    -29.428454217867472,
    17.010434366582505,
    -378.1213592480783,
    26.898620620376835,
    -176.71310359866075,
    -3.7917665423903437,
    -0.9944649813581025,
    1.0449680795248277,
    -1.2999841281717357,
    33.40773668194587,
    1.6929725908106443,
    -0.9621745896762471,
    -122.02542030071405,
    0.9340408691851444,
    144.59174130890517,
    0.3013692095253339,
    0.10245850286191473,
    -0.028777285297575762,
    -0.9198342193232529,
    -0.12474433076131278,
    0.9455509725237805,
    -0.018031454905878375,
    -0.002969198065929754,
    0.017972269775154516,
    0.0005281339208260682};
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
static const int ehd_immersed_A__feature[] = {0, 2, 4};
static const int ehd_immersed_A__powers[] = {0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0, 4, 0, 1, 0, 0, 1, 1, 0, 1, 2, 0, 1, 3, 0, 2, 0, 0, 2, 1, 0, 2, 2, 0, 3, 0, 0, 3, 1, 0, 4, 0, 1, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0, 3, 1, 1, 0, 1, 1, 1, 1, 1, 2, 1, 2, 0, 1, 2, 1, 1, 3, 0, 2, 0, 0, 2, 0, 1, 2, 0, 2, 2, 1, 0, 2, 1, 1, 2, 2, 0, 3, 0, 0, 3, 0, 1, 3, 1, 0, 4, 0, 0};
static const double ehd_immersed_A__coefficients[] = {
    7.936816833188292,
    2.6374028564724146,
    -8.510577944759932,
    23.311953956290566,
    -17.636277181603973,
    -107.19166778222954,
    8.625692290191948,
    5.670718919758936,
    -11.922348537884549,
    393.4025155354407,
    -69.29864800854057,
    19.167463375600928,
    156.55681310787136,
    65.1477159232398,
    -1271.8787633706152,
    -4.827087627801896,
    -1.3164674257458988,
    1.217513619483298,
    -1.5394019655821525,
    45.89590239429907,
    1.5382029352111037,
    -0.9449872211126035,
    -192.41573133985946,
    2.372305013448999,
    233.02306993075044,
    0.399589563936232,
    0.17096167330053763,
    -0.035994107648620835,
    -0.7341390038252523,
    -0.1990299146454378,
    1.9343952942843727,
    -0.024772242621276256,
    -0.006504789135270536,
    -0.051581181869699615,
    0.0009419840787384414};
static const int ehd_immersed_B__feature[] = {0, 2, 4};
static const int ehd_immersed_B__powers[] = {0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0, 4, 0, 1, 0, 0, 1, 1, 0, 1, 2, 0, 1, 3, 0, 2, 0, 0, 2, 1, 0, 2, 2, 0, 3, 0, 0, 3, 1, 0, 4, 0, 1, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0, 3, 1, 1, 0, 1, 1, 1, 1, 1, 2, 1, 2, 0, 1, 2, 1, 1, 3, 0, 2, 0, 0, 2, 0, 1, 2, 0, 2, 2, 1, 0, 2, 1, 1, 2, 2, 0, 3, 0, 0, 3, 0, 1, 3, 1, 0, 4, 0, 0};
static const double ehd_immersed_B__coefficients[] = {
    6.367660199814017,
    4.8647910352507875,
    4.432573102049153,
    -6.922743983575871,
    -3.6585205498253357,
    -136.46629500540493,
    -25.930760128026133,
    -8.676604318552698,
    0.7453742157815337,
    1252.0014936001426,
    65.73737944529991,
    7.077206153994201,
    -4477.531014297257,
    -56.69147890395943,
    5183.577854757129,
    -2.3662338525164746,
    -1.4409188208789179,
    -0.6004427811081737,
    1.2659946547471645,
    6.756143359014586,
    3.8136448171863666,
    0.7952686510377955,
    -22.642392128786152,
    -3.8962654585683025,
    32.89947392418091,
    0.08594539673645928,
    0.139094037318803,
    -0.002521812099558964,
    0.5708760116263386,
    -0.15225797431105145,
    -1.2124972441371236,
    0.0031659131097970597,
    -0.004306977432857271,
    -0.0036844656329542477,
    -0.0005662676798055147};

static const ehd_form_t ehd_forms_[2][4] = {
    {{10, 2, ehd_thin_St_c__feature, ehd_thin_St_c__powers, ehd_thin_St_c__coefficients},
     {10, 2, ehd_thin_m__feature, ehd_thin_m__powers, ehd_thin_m__coefficients},
     {35, 3, ehd_thin_A__feature, ehd_thin_A__powers, ehd_thin_A__coefficients},
     {0, 0, 0, 0, 0}},
    {{10, 2, ehd_immersed_St_c__feature, ehd_immersed_St_c__powers, ehd_immersed_St_c__coefficients},
     {10, 2, ehd_immersed_m__feature, ehd_immersed_m__powers, ehd_immersed_m__coefficients},
     {35, 3, ehd_immersed_A__feature, ehd_immersed_A__powers, ehd_immersed_A__coefficients},
     {35, 3, ehd_immersed_B__feature, ehd_immersed_B__powers, ehd_immersed_B__coefficients}}};

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
    double integral = exp(ehd_q_(&forms[2], f));
    if (layer == EHD_IMMERSED)
        integral += exp(ehd_q_(&forms[3], f)) * log((1.0 + delta) / (2.0 * delta));
    out->St_c = St_c;
    out->e_n = 1.0 - pow(ratio, exp(ehd_q_(&forms[1], f)));
    out->e_t = 1.0 - k / (1.0 + k) * -expm1(-(1.0 + 1.0 / k) * delta * integral);
    out->spin_change = (1.0 - out->e_t) / k;
    return 0;
}

#endif /* EHDFEM_CLOSED_FORMS_H */
