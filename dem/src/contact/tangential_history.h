/* Tangential model `history`: Mindlin-type spring on the accumulated tangential displacement,
 * with dashpot and Coulomb limit (as LIGGGHTS' tangential history):
 *   s += vt dt, then s is projected onto the current tangent plane;
 *   Ft = -kt s - gamma_t vt                       while kt |s| <= mu |Fn|;
 *   Ft = -mu |Fn| s/|s|,  s = -Ft/kt (slip)      otherwise (no dashpot while sliding).
 * vt: relative tangential velocity of the contact points (rotation included). */
#ifndef DEM_TANGENTIAL_HISTORY_H
#define DEM_TANGENTIAL_HISTORY_H

#include <math.h>
#include "contact.h"

static inline void tangential_history(double *restrict s, const double en[3], const double vt[3],
                                      normal_result n, double mu, double dt, double ft[3])
{
    s[0] += vt[0] * dt;
    s[1] += vt[1] * dt;
    s[2] += vt[2] * dt;
    const double s_n = s[0] * en[0] + s[1] * en[1] + s[2] * en[2];
    s[0] -= s_n * en[0];
    s[1] -= s_n * en[1];
    s[2] -= s_n * en[2];

    const double s_mag = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    const double f_spring = n.kt * s_mag;
    const double f_coulomb = mu * fabs(n.fn);
    if (f_spring > f_coulomb) {
        const double ratio = s_mag > 0.0 ? f_coulomb / f_spring : 0.0;
        for (int d = 0; d < 3; d++) {
            ft[d] = -n.kt * s[d] * ratio;
            s[d] *= ratio;
        }
    } else {
        for (int d = 0; d < 3; d++) ft[d] = -n.kt * s[d] - n.gammat * vt[d];
    }
}

#endif
