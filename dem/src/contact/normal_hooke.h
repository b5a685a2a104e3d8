/* Normal model `hooke`: linear spring-dashpot with LIGGGHTS' stiffness from a characteristic
 * velocity V (the Hertz peak overlap at V gives the same peak force):
 *   kn = 16/15 sqrt(R*) Y* (15 m* V^2 / (16 sqrt(R*) Y*))^(1/5),  kt = kn,
 *   gamma_n = sqrt(4 m* kn / (1 + (pi / ln e)^2)),  gamma_t = gamma_n,
 *   Fn = kn d - gamma_n vn, and with limitForce Fn >= 0 (fn_floor 0; else -inf).
 * For the linear oscillator this damping gives exactly restitution e when the contact ends at
 * zero overlap. */
#ifndef DEM_NORMAL_HOOKE_H
#define DEM_NORMAL_HOOKE_H

#include <math.h>
#include "../materials.h"
#include "contact.h"

static inline double hooke_stiffness(const pair_coeffs *c, double r_eff, double m_eff, double v_char)
{
    const double sr = sqrt(r_eff);
    return 16.0 / 15.0 * sr * c->Y_eff * pow(15.0 * m_eff * v_char * v_char / (16.0 * sr * c->Y_eff), 0.2);
}

static inline normal_result normal_hooke(const pair_coeffs *c, double delta, double r_eff,
                                         double m_eff, double vn, double v_char,
                                         double fn_floor)
{
    const double kn = hooke_stiffness(c, r_eff, m_eff, v_char);
    const double pi_over_log_e = M_PI / c->log_e;   /* e = 1: -inf, gamma_n = 0 */
    const double gamma_n = sqrt(4.0 * m_eff * kn / (1.0 + pi_over_log_e * pi_over_log_e));
    normal_result r;
    const double fn = kn * delta - gamma_n * vn;
    r.fn = fn > fn_floor ? fn : fn_floor;
    r.kn = kn;
    r.fn_spring = kn * delta;
    r.kt = kn;
    r.gammat = gamma_n;
    return r;
}

#endif
