/* Normal model `hooke`: linear spring-dashpot with LIGGGHTS' stiffness from a characteristic
 * velocity V (the spring stops an impact at V at the Hertz peak overlap; its peak force is then
 * 4/5 of Hertz's):
 *   kn = 16/15 sqrt(R*) Y* (15 m* V^2 / (16 sqrt(R*) Y*))^(1/5),  kt = kn,
 *   gamma_n = alpha sqrt(m* kn),  alpha = 2 |ln e| / sqrt(ln^2 e + pi^2),  gamma_t = gamma_n,
 *   Fn = kn d - gamma_n vn, and with limitForce Fn >= 0.
 * For the linear oscillator this alpha gives exactly restitution e when the contact ends at
 * zero overlap; with limitForce the contact ends earlier, where Fn reaches 0, and alpha is the
 * one that gives e for that (restitution.h; Thornton et al. 2013's closed form). Case-wide setting in contactModels: characteristicVelocity V [m/s], required.
 * Equations, sources and choices: docs/models/normal_hooke.md. */
#ifndef DEM_NORMAL_HOOKE_H
#define DEM_NORMAL_HOOKE_H

#include <math.h>
#include "../dict.h"
#include "../materials.h"
#include "../restitution.h"

typedef struct dem_hooke_case {
    double characteristic_velocity;   /* V [m/s] */
} dem_hooke_case;
_Static_assert(sizeof(dem_hooke_case) <= MODEL_VALUES * sizeof(double), "hooke_case too large");

static inline double hooke_stiffness(const dem_pair_coeffs *c, const dem_contact_models *m, double r_eff, double m_eff)
{
    const double v_char = MODEL_CASE(m, SLOT_NORMAL, dem_hooke_case)->characteristic_velocity;
    const double sr = sqrt(r_eff);
    return 16.0 / 15.0 * sr * c->Y_eff * pow(15.0 * m_eff * v_char * v_char / (16.0 * sr * c->Y_eff), 0.2);
}

static inline dem_normal_result normal_hooke_force(const dem_contact *k, const dem_pair_coeffs *c,
                                               const dem_contact_models *m, double *restrict h)
{
    const double kn = hooke_stiffness(c, m, k->r_eff, k->m_eff);
    const double gamma_n = c->damping * sqrt(k->m_eff * kn);
    dem_normal_result r;
    r.fn_spring = kn * k->delta;
    r.fn = r.fn_spring - gamma_n * k->vn;
    r.kn = kn;
    r.kt = kn;
    r.gammat = gamma_n;
    r.active = 1;
    return r;
}

/* Half period of the undamped linear spring, pi sqrt(m* / kn). */
static inline double hooke_contact_time(const dem_pair_coeffs *c, const dem_contact_models *m, double r_eff,
                                        double m_eff, double v)
{
    return M_PI * sqrt(m_eff / hooke_stiffness(c, m, r_eff, m_eff));
}

static inline void hooke_read_case(const dem_dict *d, double *values)
{
    ((dem_hooke_case *)values)->characteristic_velocity = dem_dict_scalar(d, "characteristicVelocity", 1e-6, 1e4);
}

/* alpha: the linear oscillator's closed form, or for the clipped force the integrated one */
static inline void hooke_prepare(dem_pair_coeffs *c, const dem_contact_models *m)
{
    c->damping = m->fn_floor == 0.0 ? dem_damping_for_restitution(c->restitution, 1.0, 1) : -2.0 * c->beta;
}

static const dem_contact_model normal_hooke_model = {
    .slot = SLOT_NORMAL, .name = "hooke", .read_case = hooke_read_case, .prepare = hooke_prepare,
    .contact_time = hooke_contact_time, .contact_time_name = "linear-spring",
};

#endif
