/* Rolling model `epsd` (elastic-plastic spring-dashpot, as LIGGGHTS' rolling epsd, after Ai et
 * al. 2011): a rolling spring kr = 2.25 kn mu_r^2 R*^2 on the tangential relative rotation,
 *   M_spring += kr w_t dt,  |M_spring| <= mu_r R* |Fn|  (at the limit: no dashpot),
 *   M = M_spring + eta_r 2 sqrt(I_r kr) w_t   otherwise,
 * I_r = 1.4 m_i R_i^2 for a wall, 1.4 (m_i R_i^2)(m_j R_j^2)/(m_i R_i^2 + m_j R_j^2) for a pair;
 * torque -M on i and +M on j. History: M_spring (3 doubles). */
#ifndef DEM_ROLLING_EPSD_H
#define DEM_ROLLING_EPSD_H

#include <math.h>
#include "../materials.h"
#include "contact.h"

static inline void rolling_epsd(const pair_coeffs *c, const double en[3], const double w[3],
                                normal_result n, double r_eff, double inertia_r, double dt,
                                double *restrict m_spring, double torque_i[3])
{
    const double w_n = w[0] * en[0] + w[1] * en[1] + w[2] * en[2];
    const double wt[3] = {w[0] - w_n * en[0], w[1] - w_n * en[1], w[2] - w_n * en[2]};
    const double mu_r = c->m.rolling_friction;
    const double kr = 2.25 * n.kn * mu_r * mu_r * r_eff * r_eff;
    double m[3];
    for (int d = 0; d < 3; d++) m[d] = m_spring[d] + kr * wt[d] * dt;
    const double m_mag = sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
    const double m_max = fabs(n.fn) * r_eff * mu_r;
    if (m_mag > m_max) {
        const double factor = m_max / m_mag;
        for (int d = 0; d < 3; d++) {
            m[d] *= factor;
            m_spring[d] = m[d];
        }
    } else {
        const double damping = c->m.rolling_damping * 2.0 * sqrt(inertia_r * kr);
        for (int d = 0; d < 3; d++) {
            m_spring[d] = m[d];
            m[d] += damping * wt[d];
        }
    }
    for (int d = 0; d < 3; d++) torque_i[d] = -m[d];
}

#endif
