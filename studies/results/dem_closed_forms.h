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
 * 2 delta (1 + (13.88 eps St)^(2/5)) <= 1 (the wetted film inside the sphere's radius), for an
 * immersed one 2 delta (13.88 eps St)^(2/5) <= 1 (the flattened contact inside it).
 * Outside it ehd_restitution sets every output to NaN and returns the flags EHD_OUT_* of the
 * parameters outside (0 inside).
 * Largest errors on points held back from the fit: thin: St_c 2.7%, e_n 0.018, e_t 0.00032 (1 - e_t 3%, 53% just above St_c), spin change 0.00079; immersed: St_c 2.7%, e_n 0.023, e_t 0.00034 (1 - e_t 2%, 65% just above St_c), spin change 0.00086.
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
    0.37546067112185794,
    -0.013520886303938957,
    -21.582846378886657,
    124.17633850483637,
    -19.896170231544936,
    29.556409538954025,
    -247.7762766150346,
    62.547782093010014,
    164.76775837304962,
    -115.49637500115836};
static const int ehd_thin_m__feature[] = {2, 4};
static const int ehd_thin_m__powers[] = {0, 0, 0, 1, 0, 2, 0, 3, 1, 0, 1, 1, 1, 2, 2, 0, 2, 1, 3, 0};
static const double ehd_thin_m__coefficients[] = {
    -0.07137432473390733,
    0.04808311922806654,
    0.6866285934143147,
    -2.122105146121393,
    -2.80970360473612,
    6.0772822958643395,
    -9.506027347580272,
    2.098056312298125,
    2.8344472197710844,
    -3.081852258114754};
static const int ehd_thin_R__feature[] = {0, 2, 4};
static const int ehd_thin_R__powers[] = {0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 1, 0, 0, 1, 1, 0, 2, 0, 1, 0, 0, 1, 0, 1, 1, 1, 0, 2, 0, 0};
static const double ehd_thin_R__coefficients[] = {
    -0.1906889739509978,
    -0.37562710171434227,
    0.12991531722554595,
    8.967063120877464,
    1.7984407769100854,
    -44.23653776475656,
    -0.0030065110478233394,
    0.03571419580355116,
    -0.35502132907071965,
    0.0012289890347302438};
static const int ehd_thin_E__feature[] = {0, 2, 4};
static const int ehd_thin_E__powers[] = {0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 1, 0, 0, 1, 1, 0, 2, 0, 1, 0, 0, 1, 0, 1, 1, 1, 0, 2, 0, 0};
static const double ehd_thin_E__coefficients[] = {
    3.204231670472388,
    0.16951486271543895,
    0.406978312333508,
    -1.251266981409145,
    -0.1400099266782718,
    1.1449185629280907,
    -0.2712152695953694,
    -0.03810698546722124,
    0.0768050728790616,
    0.013238965611813617};
static const int ehd_immersed_St_c__feature[] = {2, 4};
static const int ehd_immersed_St_c__powers[] = {0, 0, 0, 1, 0, 2, 0, 3, 1, 0, 1, 1, 1, 2, 2, 0, 2, 1, 3, 0};
static const double ehd_immersed_St_c__coefficients[] = {
    3.6199776453518626,
    -2.3356843063183255,
    -18.811024101353976,
    120.34952585694373,
    -23.503002334712246,
    72.87729880721751,
    -250.11371885870116,
    78.92600617448639,
    99.9065095764215,
    -145.17802237060923};
static const int ehd_immersed_m__feature[] = {2, 4};
static const int ehd_immersed_m__powers[] = {0, 0, 0, 1, 0, 2, 0, 3, 1, 0, 1, 1, 1, 2, 2, 0, 2, 1, 3, 0};
static const double ehd_immersed_m__coefficients[] = {
    -0.0540615519077936,
    -0.4749669693131344,
    3.404832570078362,
    -5.90556871122985,
    -1.5797968876649298,
    -0.07383520340975902,
    -0.6224586661606556,
    3.1791902643476337,
    2.439261090592444,
    -3.8815400690396555};
static const int ehd_immersed_R__feature[] = {0, 2, 4};
static const int ehd_immersed_R__powers[] = {0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 1, 0, 0, 1, 1, 0, 2, 0, 1, 0, 0, 1, 0, 1, 1, 1, 0, 2, 0, 0};
static const double ehd_immersed_R__coefficients[] = {
    -0.010527251823575409,
    -0.1873204970717953,
    0.13962453230951985,
    1.3547313923274122,
    0.9256443258613962,
    -5.252909383635597,
    -0.00023983552631911712,
    0.011626043600378933,
    -0.05088728707338562,
    -1.623797245397951e-05};
static const int ehd_immersed_E__feature[] = {0, 2, 4};
static const int ehd_immersed_E__powers[] = {0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 1, 0, 0, 1, 1, 0, 2, 0, 1, 0, 0, 1, 0, 1, 1, 1, 0, 2, 0, 0};
static const double ehd_immersed_E__coefficients[] = {
    3.04638134900497,
    0.13684074895605453,
    0.250272517606479,
    -1.264488498552739,
    0.006394729058835703,
    1.1291037199481544,
    -0.23080485861712802,
    -0.026008449999041908,
    0.06817634092243183,
    0.010742117892899453};
static const int ehd_immersed_T__feature[] = {0, 2, 4};
static const int ehd_immersed_T__powers[] = {0, 0, 0};
static const double ehd_immersed_T__coefficients[] = {
    0.017982415257110095};

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
