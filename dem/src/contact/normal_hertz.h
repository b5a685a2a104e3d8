/* Normal model `hertz`: Hertz spring with a dashpot that gives a restitution independent of
 * the impact speed (Tsuji et al. 1992, as LIGGGHTS' hertz model):
 *   kn = 4/3 Y* sqrt(R* d),  kt = 8 G* sqrt(R* d),
 *   gamma_n = -2 sqrt(5/6) beta sqrt(2 Y* sqrt(R* d) m*),  gamma_t likewise with kt,
 *   Fn = kn d - gamma_n vn          (vn < 0 while approaching),
 * and with limitForce Fn >= 0 (fn_floor 0; else -inf). */
#ifndef DEM_NORMAL_HERTZ_H
#define DEM_NORMAL_HERTZ_H

#include <math.h>
#include "../materials.h"
#include "contact.h"

static inline normal_result normal_hertz(const pair_coeffs *c, double delta, double r_eff,
                                         double m_eff, double vn, double fn_floor)
{
    const double sqrt_five_sixths = 0.91287092917527685576;
    const double a = sqrt(r_eff * delta);                  /* contact radius */
    const double sn = 2.0 * c->Y_eff * a;
    const double st = 8.0 * c->G_eff * a;
    const double kn = (2.0 / 3.0) * sn;
    const double gamma_n = -2.0 * sqrt_five_sixths * c->beta * sqrt(sn * m_eff);
    const double fn = kn * delta - gamma_n * vn;
    normal_result r;
    r.fn = fn > fn_floor ? fn : fn_floor;
    r.kn = kn;
    r.fn_spring = kn * delta;
    r.kt = st;
    r.gammat = gamma_n * c->sqrt_st_over_sn;    /* sqrt(st m*) = sqrt(sn m*) sqrt(st/sn) */
    return r;
}

#endif
