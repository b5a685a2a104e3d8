/* Rolling model `epsd` (elastic-plastic spring-dashpot, as LIGGGHTS' rolling epsd, after Ai et
 * al. 2011): a rolling spring kr = 2.25 kn mu_r^2 R*^2 on the tangential relative rotation,
 *   M_spring += kr w_t dt,  |M_spring| <= mu_r R* |Fn|  (at the limit: no dashpot),
 *   M = M_spring + eta_r 2 sqrt(I_r kr) w_t   otherwise,
 * I_r = 1.4 m_i R_i^2 for a wall, 1.4 (m_i R_i^2)(m_j R_j^2)/(m_i R_i^2 + m_j R_j^2) for a pair;
 * torque -M on i and +M on j. History: M_spring (3 doubles, antisymmetric). Parameters per
 * interaction: rollingFriction mu_r (required), rollingViscousDamping eta_r (0). Equations,
 * sources and choices: docs/models/rolling_epsd.md. */
#ifndef DEM_ROLLING_EPSD_H
#define DEM_ROLLING_EPSD_H

#include <math.h>
#include "../materials.h"

typedef struct dem_epsd_params {
    double mu_r;    /* rolling friction coefficient [-] */
    double eta_r;   /* dashpot, fraction of critical [-] */
} dem_epsd_params;

static const dem_model_param epsd_param_table[] = {
    {"rollingFriction", "-", NAN, 0.0, 10.0, offsetof(dem_epsd_params, mu_r)},
    {"rollingViscousDamping", "-", 0.0, 0.0, 10.0, offsetof(dem_epsd_params, eta_r)},
};

static inline void rolling_epsd_torque(const dem_contact *k, const dem_pair_coeffs *c, const dem_contact_models *m,
                                       dem_normal_result n, const double w[3], double *restrict m_spring,
                                       double torque_i[3])
{
    const dem_epsd_params *p = MODEL_PARAMS(c, SLOT_ROLLING, dem_epsd_params);
    const double *en = k->en, r_eff = k->r_eff;
    const double w_n = w[0] * en[0] + w[1] * en[1] + w[2] * en[2];
    const double wt[3] = {w[0] - w_n * en[0], w[1] - w_n * en[1], w[2] - w_n * en[2]};
    const double mu_r = p->mu_r;
    const double kr = 2.25 * n.kn * mu_r * mu_r * r_eff * r_eff;
    double mr[3];
    for (int d = 0; d < 3; d++) mr[d] = m_spring[d] + kr * wt[d] * k->dt;
    const double m_mag = sqrt(mr[0] * mr[0] + mr[1] * mr[1] + mr[2] * mr[2]);
    const double m_max = fabs(n.fn) * r_eff * mu_r;
    if (m_mag > m_max) {
        const double factor = m_max / m_mag;
        for (int d = 0; d < 3; d++) {
            mr[d] *= factor;
            m_spring[d] = mr[d];
        }
    } else {
        const double damping = p->eta_r * 2.0 * sqrt(k->rolling_inertia * kr);
        for (int d = 0; d < 3; d++) {
            m_spring[d] = mr[d];
            mr[d] += damping * wt[d];
        }
    }
    for (int d = 0; d < 3; d++) torque_i[d] = -mr[d];
}

static const dem_contact_model rolling_epsd_model = {
    .slot = SLOT_ROLLING, .name = "epsd", .history = 3, .history_antisymmetric = 3,
    .params = epsd_param_table, .nparams = 2,
};

#endif
