/* Normal model `edinburgh`: elasto-plastic adhesive contact (seed note 002, "Edinburgh normal
 * contact model", eq. 1-9). Loading follows k1 delta^d_ex; unloading leaves that branch at the
 * historic maximum overlap and follows k2 = kappa21 k1 down to the plastic overlap; below it
 * the force turns tensile down to the adhesion branch -k_c delta^c_ex. History: the maximum
 * plastic overlap delta_p,max of the contact (1 double), forgotten when the contact ends.
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
#include "../materials.h"
#include "contact.h"

/* delta: overlap; a: contact radius (contact_radius_sq_*, eq. 5); hist: delta_p,max. */
static inline normal_result normal_edinburgh(const pair_coeffs *c, double delta, double r_eff,
                                             double m_eff, double vn, double a, double fn_floor,
                                             double *restrict hist)
{
    const pair_model_params *m = &c->m;
    const double d_ex = m->loading_exponent, c_ex = m->adhesion_exponent, xi = 1.0 / d_ex;   /* eq. 2 */
    const double k1 = d_ex == 1.0 ? 2.0 * c->Y_eff * r_eff                              /* eq. 1 */
                                  : 4.0 / 3.0 * c->Y_eff * sqrt(r_eff);
    const double k2 = k1 * m->unloading_ratio;                                          /* eq. 1 */
    const double delta_d = pow(delta, d_ex), delta_c = pow(delta, c_ex);                /* eq. 2 */
    const double delta_p = c->edinburgh_lambda * delta;                                 /* eq. 3 */
    const double delta_pmax = hist[0] > delta_p ? hist[0] : delta_p;                    /* eq. 3 */
    hist[0] = delta_pmax;
    const double delta_pmax_d = pow(delta_pmax, d_ex);                                  /* eq. 4 */
    const double f_tmp = k2 * (delta_d - delta_pmax_d);                                 /* eq. 4 */

    double f_min = 1.5 * M_PI * m->surface_energy * a;                                  /* eq. 5 */
    double delta_min;
    if (f_min > 0.5 * k2 * delta_pmax_d) {                                              /* eq. 6, limit */
        f_min = 0.5 * k2 * delta_pmax_d;
        delta_min = 0.5 * delta_pmax;
    } else {
        delta_min = pow(delta_pmax_d - f_min / k2, xi);                                 /* eq. 6 */
    }
    const double k_c = delta_min > 0.0 ? f_min / pow(delta_min, c_ex) : 0.0;            /* eq. 6 */

    const double f_load = k1 * delta_d, f_adh = -k_c * delta_c;
    const double f_el = f_tmp >= f_load ? f_load : (f_tmp > f_adh ? f_tmp : f_adh);     /* eq. 7 */

    const double pi_over_log_e = M_PI / c->log_e;                       /* e = 1: -inf, gamma 0 */
    const double gamma_n = sqrt(4.0 * m_eff * k1 / (1.0 + pi_over_log_e * pi_over_log_e));  /* eq. 8 */
    const double fn = f_el - gamma_n * vn + m->tension_threshold;                       /* eq. 8, 9 */

    normal_result r;
    r.fn = fn > fn_floor ? fn : fn_floor;                                               /* eq. 9, F_n >= 0 */
    r.kn = k1 * d_ex * (delta > 0.0 ? delta_d / delta : 0.0);
    r.fn_spring = f_el;
    r.kt = 8.0 * c->G_eff * sqrt(r_eff * delta);
    r.gammat = 0.0;
    return r;
}

#endif
