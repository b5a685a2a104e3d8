/* Normal model `edinburgh`: elasto-plastic adhesive contact (seed note 002, "Edinburgh normal
 * contact model", eq. 1-9). Equations: docs/models/normal_edinburgh.md, which keeps the note's
 * numbering: "eq. N" in this file is that page's eq. N and seed 002's eq. N. Loading follows
 * k1 delta^d_ex; unloading leaves that branch at the historic maximum overlap and follows
 * k2 = kappa21 k1 down to the plastic overlap; below it the force turns tensile down to the
 * adhesion branch -k_c delta^c_ex. History: the maximum plastic overlap delta_p,max of the
 * contact (1 double), forgotten when the contact ends. Parameters per interaction:
 * unloadingRatio kappa21 (> 1, required), surfaceEnergy gamma_s [J/m^2] (0), loadingExponent d_ex
 * (1.5), adhesionExponent c_ex (1.5), tensionThreshold F_0 [N] (0); the time-step check shortens
 * the elastic contact time by sqrt(kappa21). Case-wide in contactModels: edinburghDamping
 * `restitution` (default) or `seedEq8`; limitForce defaults to on for this model.
 *
 * The dashpot (eq. 8 of the note, and a default that keeps the entered restitution):
 *  - seedEq8: gamma_n = sqrt(4 m* k1 / (1 + (pi / ln e)^2)), constant, as the note and LIGGGHTS.
 *    Exact only for d_ex = 1: with d_ex = 1.5 the spring is soft at small overlap, the dashpot
 *    constant, and the rebound depends on the speed (e = 0.9 entered gives about 0.1-0.3 at
 *    0.01-1 m/s). docs/models/normal_edinburgh.md has the curves.
 *  - restitution: gamma_n = alpha sqrt(m* dF/d delta) on the loading branch, alpha from e, d_ex
 *    and limitForce (restitution.h): at the elastic limit (kappa21 -> 1) the restitution is e at
 *    every speed; for d_ex = 1 without limitForce it is eq. 8.
 * limitForce keeps Fn >= min(F_el + F_0, 0): the dashpot cannot pull, adhesion stays. It is on by
 * default: without it a non-adhesive pair that has deformed plastically is held by the dashpot
 * (F_el = 0 below the plastic overlap) and never parts.
 *
 * Choices where the note is open:
 *  - eq. 8 calls e_log the common logarithm of the restitution; we use the natural one, the only
 *    one for which eq. 8 gives restitution e (for d_ex = 1, kappa21 -> 1, no adhesion: tested).
 *  - eq. 6, "F_min at the limit": F_min > 0.5 k2 delta_p,max^d_ex is clamped to that value and
 *    then delta_min = 0.5 delta_p,max, as written.
 *  - the tangential model needs a stiffness the note does not give: Mindlin's 8 G* sqrt(R* d),
 *    as the hertz model; the tangential damping is 0 (the note: "optional, 0 by default").
 *  - the rolling models get F_el (eq. 7) as the spring force and dF_el/d delta on the loading
 *    branch, k1 d_ex delta^(d_ex - 1), as the stiffness. */
#ifndef DEM_NORMAL_EDINBURGH_H
#define DEM_NORMAL_EDINBURGH_H

#include <math.h>
#include "../dict.h"
#include "../materials.h"
#include "../restitution.h"

/* Parameters per interaction (keys in edinburgh_param_table), then the derived lambda. */
typedef struct dem_edinburgh_params {
    double kappa21;     /* k2/k1 > 1 [-] (normal_edinburgh.md eq. 1) */
    double gamma_s;     /* surface energy [J/m^2] (normal_edinburgh.md eq. 5) */
    double d_ex;        /* loading exponent >= 1 [-] (normal_edinburgh.md eq. 2) */
    double c_ex;        /* adhesion exponent > 0 [-] (normal_edinburgh.md eq. 2) */
    double f0;          /* tension threshold F_0 [N] (normal_edinburgh.md eq. 9) */
    double lambda;      /* (1 - 1/kappa21)^(1/d_ex) (normal_edinburgh.md eq. 3), derived */
} dem_edinburgh_params;

/* Case-wide: which dashpot (see above). */
typedef struct dem_edinburgh_case {
    double seed_eq8;    /* 1: seed 002 eq. 8; 0: restitution-keeping alpha */
} dem_edinburgh_case;
_Static_assert(sizeof(dem_edinburgh_params) <= MODEL_VALUES * sizeof(double), "edinburgh_params too large");

static const dem_model_param edinburgh_param_table[] = {
    {"unloadingRatio", "-", NAN, -1e300, 1e6, offsetof(dem_edinburgh_params, kappa21)},
    {"surfaceEnergy", "J/m^2", 0.0, 0.0, 1e3, offsetof(dem_edinburgh_params, gamma_s)},
    {"loadingExponent", "-", 1.5, 1.0, 3.0, offsetof(dem_edinburgh_params, d_ex)},
    {"adhesionExponent", "-", 1.5, 1e-3, 3.0, offsetof(dem_edinburgh_params, c_ex)},
    {"tensionThreshold", "N", 0.0, -1e6, 1e6, offsetof(dem_edinburgh_params, f0)},
};

/* k1 of normal_edinburgh.md eq. 1: 2 Y* R* for a linear loading branch, 4/3 Y* sqrt(R*) otherwise */
static inline double edinburgh_k1(const dem_pair_coeffs *c, const dem_edinburgh_params *p, double r_eff)
{
    return p->d_ex == 1.0 ? 2.0 * c->Y_eff * r_eff : 4.0 / 3.0 * c->Y_eff * sqrt(r_eff);
}

/* k->a2: the contact radius squared (normal_edinburgh.md eq. 5a); h: delta_p,max (1 double). */
static inline dem_normal_result normal_edinburgh_force(const dem_contact *k, const dem_pair_coeffs *c,
                                                   const dem_contact_models *m, double *restrict h)
{
    const dem_edinburgh_params *p = MODEL_PARAMS(c, SLOT_NORMAL, dem_edinburgh_params);
    const double delta = k->delta, a = sqrt(k->a2);
    const double d_ex = p->d_ex, c_ex = p->c_ex, xi = 1.0 / d_ex;                       /* normal_edinburgh.md eq. 2 */
    const double k1 = edinburgh_k1(c, p, k->r_eff);                                     /* normal_edinburgh.md eq. 1 */
    const double k2 = k1 * p->kappa21;                                                  /* normal_edinburgh.md eq. 1 */
    const double delta_d = pow(delta, d_ex), delta_c = pow(delta, c_ex);                /* normal_edinburgh.md eq. 2 */
    const double delta_p = p->lambda * delta;                                           /* normal_edinburgh.md eq. 3 */
    const double delta_pmax = h[0] > delta_p ? h[0] : delta_p;                          /* normal_edinburgh.md eq. 3 */
    h[0] = delta_pmax;
    const double delta_pmax_d = pow(delta_pmax, d_ex);                                  /* normal_edinburgh.md eq. 4 */
    const double f_tmp = k2 * (delta_d - delta_pmax_d);                                 /* normal_edinburgh.md eq. 4 */

    double f_min = 1.5 * M_PI * p->gamma_s * a;                                         /* normal_edinburgh.md eq. 5 */
    double delta_min;
    if (f_min > 0.5 * k2 * delta_pmax_d) {                                              /* normal_edinburgh.md eq. 6, limit */
        f_min = 0.5 * k2 * delta_pmax_d;
        delta_min = 0.5 * delta_pmax;
    } else {
        delta_min = pow(delta_pmax_d - f_min / k2, xi);                                 /* normal_edinburgh.md eq. 6 */
    }
    const double k_c = delta_min > 0.0 ? f_min / pow(delta_min, c_ex) : 0.0;            /* normal_edinburgh.md eq. 6 */

    const double f_load = k1 * delta_d, f_adh = -k_c * delta_c;
    const double f_el = f_tmp >= f_load ? f_load : (f_tmp > f_adh ? f_tmp : f_adh);     /* normal_edinburgh.md eq. 7 */

    dem_normal_result r;
    r.kn = k1 * d_ex * (delta > 0.0 ? delta_d / delta : 0.0);                           /* dF/d delta on loading */
    double gamma_n;
    if (MODEL_CASE(m, SLOT_NORMAL, dem_edinburgh_case)->seed_eq8 != 0.0) {
        const double pi_over_log_e = M_PI / c->log_e;                   /* e = 1: -inf, gamma 0 */
        gamma_n = sqrt(4.0 * k->m_eff * k1 / (1.0 + pi_over_log_e * pi_over_log_e));   /* normal_edinburgh.md eq. 8 */
    } else {
        gamma_n = c->damping * sqrt(k->m_eff * r.kn);                                   /* normal_edinburgh.md eq. 8a */
    }
    r.fn = f_el - gamma_n * k->vn + p->f0;                                              /* normal_edinburgh.md eq. 8, 9 */
    r.fn_spring = f_el + p->f0;   /* what limitForce keeps (evaluate.h) */
    r.kt = 8.0 * c->G_eff * sqrt(k->r_eff * delta);
    r.gammat = 0.0;
    r.active = 1;
    return r;
}

/* Elastic impact on F = k1 delta^d (normal_edinburgh.md eq. 1), 2 (delta_max / v) int_0^1 dx /
 * sqrt(1 - x^(d+1)), shortened by sqrt(kappa21) for the stiffer unloading branch
 * (normal_edinburgh.md eq. 11). */
static inline double edinburgh_contact_time(const dem_pair_coeffs *c, const dem_contact_models *m, double r_eff,
                                            double m_eff, double v)
{
    const dem_edinburgh_params *p = MODEL_PARAMS(c, SLOT_NORMAL, dem_edinburgh_params);
    const double d = p->d_ex, k1 = edinburgh_k1(c, p, r_eff);
    const double delta_max = pow((d + 1.0) * m_eff * v * v / (2.0 * k1), 1.0 / (d + 1.0));
    const double integral = sqrt(M_PI) * tgamma(1.0 + 1.0 / (d + 1.0)) / tgamma(0.5 + 1.0 / (d + 1.0));
    return 2.0 * delta_max / v * integral / sqrt(p->kappa21);
}

static inline const char *edinburgh_check(const double *values, const char **key)
{
    const dem_edinburgh_params *p = (const dem_edinburgh_params *)values;
    *key = "unloadingRatio";
    return p->kappa21 > 1.0 ? NULL
        : "kappa21 = k2/k1 must exceed 1: with k2 <= k1 the plastic overlap of seed 002 eq. 3 is undefined";
}

static inline void edinburgh_prepare(dem_pair_coeffs *c, const dem_contact_models *m)
{
    dem_edinburgh_params *p = (dem_edinburgh_params *)c->model[SLOT_NORMAL];
    p->lambda = pow(1.0 - 1.0 / p->kappa21, 1.0 / p->d_ex);                            /* normal_edinburgh.md eq. 3 */
    if (MODEL_CASE(m, SLOT_NORMAL, dem_edinburgh_case)->seed_eq8 == 0.0)               /* normal_edinburgh.md eq. 8a */
        c->damping = dem_damping_for_restitution(c->restitution, p->d_ex, m->fn_floor == 0.0);
}

static inline void edinburgh_read_case(const dem_dict *d, double *values)
{
    static const char *const dampings[] = {"restitution", "seedEq8", NULL};
    ((dem_edinburgh_case *)values)->seed_eq8 = dem_dict_choice_opt(d, "edinburghDamping", dampings, 0);
}

static const dem_contact_model normal_edinburgh_model = {
    .slot = SLOT_NORMAL, .name = "edinburgh", .history = 1, .needs_contact_radius = 1,
    .params = edinburgh_param_table, .nparams = 5,
    .check = edinburgh_check, .prepare = edinburgh_prepare, .read_case = edinburgh_read_case,
    .limit_force_default = 1,
    .contact_time = edinburgh_contact_time, .contact_time_name = "edinburgh unloading",
    .coarse_graining_refused = "its tension threshold F_0 [N] and adhesion branch k_c delta^c_ex have no published "
        "scaling for parcels",
};

#endif
