/* The normal and cohesion slots of one contact, shared by the pair and wall loops. Called with
 * compile-time model ids, so each kernel keeps only its own model. Returns the normal model's
 * result (its fn drives the Coulomb limit) and, in *fn_total, fn plus the cohesion. */
#ifndef DEM_NORMAL_FORCE_H
#define DEM_NORMAL_FORCE_H

#include "cohesion_sjkr.h"
#include "normal_edinburgh.h"
#include "normal_hertz.h"
#include "normal_hooke.h"

static inline __attribute__((always_inline)) normal_result
contact_normal(enum normal_model normal, enum cohesion_model cohesion, const pair_coeffs *c, double delta,
               double r_eff, double m_eff, double vn, double v_char, double fn_floor,
               double contact_radius_sq, double *restrict h_norm, double *fn_total)
{
    normal_result n;
    if (normal == NORMAL_HERTZ) n = normal_hertz(c, delta, r_eff, m_eff, vn, fn_floor);
    else if (normal == NORMAL_HOOKE) n = normal_hooke(c, delta, r_eff, m_eff, vn, v_char, fn_floor);
    else n = normal_edinburgh(c, delta, r_eff, m_eff, vn, sqrt(contact_radius_sq), fn_floor, h_norm);
    *fn_total = cohesion == COHESION_SJKR ? n.fn + cohesion_sjkr(c, contact_radius_sq) : n.fn;
    return n;
}

#endif
