/* Normal model `hertz`: Hertz spring with a dashpot that gives a restitution independent of
 * the impact speed (Tsuji et al. 1992, as LIGGGHTS' hertz model):
 *   kn = 4/3 Y* sqrt(R* d),  kt = 8 G* sqrt(R* d),
 *   gamma_n = alpha sqrt(2 Y* sqrt(R* d) m*),  gamma_t likewise with kt,
 *   Fn = kn d - gamma_n vn          (vn < 0 while approaching),
 * with alpha = -2 sqrt(5/6) beta (beta = ln e / sqrt(ln^2 e + pi^2), Tsuji's fit, as LIGGGHTS);
 * with limitForce Fn >= 0, and alpha is then the one that gives restitution e for the clipped
 * force (restitution.h: Tsuji's alpha would rebound too fast, e.g. 0.325 for e = 0.2).
 * Parameters: the interaction's restitution e; no history. Equations, sources and choices:
 * docs/models/normal_hertz.md. */
#ifndef DEM_NORMAL_HERTZ_H
#define DEM_NORMAL_HERTZ_H

#include <math.h>
#include "../materials.h"
#include "../restitution.h"

/* The Hertz stiffnesses and dashpots at contact radius a (hertz: a = sqrt(R* delta); the
 * adhesive models use them with their own a); fills kn, kt, gammat and returns gamma_n. */
static inline double hertz_stiffness_damping(const dem_pair_coeffs *c, double a, double m_eff, dem_normal_result *r)
{
    const double sn = 2.0 * c->Y_eff * a;
    const double gamma_n = c->damping * sqrt(sn * m_eff);
    r->kn = (2.0 / 3.0) * sn;
    r->kt = 8.0 * c->G_eff * a;
    r->gammat = gamma_n * c->sqrt_st_over_sn;    /* sqrt(st m*) = sqrt(sn m*) sqrt(st/sn) */
    r->active = 1;
    return gamma_n;
}

static inline dem_normal_result normal_hertz_force(const dem_contact *k, const dem_pair_coeffs *c,
                                               const dem_contact_models *m, double *restrict h)
{
    dem_normal_result r;
    const double gamma_n = hertz_stiffness_damping(c, sqrt(k->r_eff * k->delta), k->m_eff, &r);
    r.fn_spring = r.kn * k->delta;
    r.fn = r.fn_spring - gamma_n * k->vn;
    return r;
}

/* Duration of an elastic Hertz impact at relative speed v: 2.87 (m*^2 / (R* Y*^2 v))^(1/5). */
static inline double hertz_contact_time(const dem_pair_coeffs *c, const dem_contact_models *m, double r_eff,
                                        double m_eff, double v)
{
    return 2.87 * pow(m_eff * m_eff / (r_eff * c->Y_eff * c->Y_eff * v), 0.2);
}

/* alpha for the clipped force (limitForce); unclipped, materials.c's Tsuji alpha stays */
static inline void hertz_prepare(dem_pair_coeffs *c, const dem_contact_models *m)
{
    if (m->fn_floor == 0.0) c->damping = dem_damping_for_restitution(c->restitution, 1.5, 1);
}

static const dem_contact_model normal_hertz_model = {
    .slot = SLOT_NORMAL, .name = "hertz", .prepare = hertz_prepare,
    .contact_time = hertz_contact_time, .contact_time_name = "Hertz",
};

#endif
