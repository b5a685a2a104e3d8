/* Tangential model `history`: Mindlin-type spring on the accumulated tangential displacement,
 * with dashpot and Coulomb limit:
 *   s += vt dt, then s is projected onto the current tangent plane;
 *   Ft = -kt s - gamma_t vt                                   while |Ft| <= mu |Fn|;
 *   Ft = mu |Fn| Ft/|Ft|, and s = -Ft/kt (the spring holds the sliding force)  otherwise.
 * vt: relative tangential velocity of the contact points (rotation included).
 * Parameters and stiffness are LIGGGHTS' (tangential history with the hertz/hooke kt, gamma_t).
 * One deliberate difference: LIGGGHTS 3.8 bounds only the spring part kt|s| by mu|Fn|, so at
 * the start of a sliding contact its dashpot adds friction beyond Coulomb (10 % more tangential
 * impulse for e = 0.5, vt/vn = 3, see tests/validation/test_oblique.c); here the whole
 * tangential force obeys |Ft| <= mu |Fn|. In sticking contacts the two agree.
 * Parameters: the interaction's friction mu; history: the spring's displacement s (3 doubles,
 * antisymmetric: built from v_i - v_j). Equations, sources and choices:
 * docs/models/tangential_history.md. */
#ifndef DEM_TANGENTIAL_HISTORY_H
#define DEM_TANGENTIAL_HISTORY_H

#include <math.h>
#include "../materials.h"

static inline void tangential_history_force(const dem_contact *k, const dem_pair_coeffs *c, dem_normal_result n,
                                            const double en[3], const double vt[3], double *restrict s,
                                            double ft[3])
{
    const double dt = k->dt;
    s[0] += vt[0] * dt;
    s[1] += vt[1] * dt;
    s[2] += vt[2] * dt;
    const double s_n = s[0] * en[0] + s[1] * en[1] + s[2] * en[2];
    s[0] -= s_n * en[0];
    s[1] -= s_n * en[1];
    s[2] -= s_n * en[2];

    for (int d = 0; d < 3; d++) ft[d] = -n.kt * s[d] - n.gammat * vt[d];
    const double ft2 = ft[0] * ft[0] + ft[1] * ft[1] + ft[2] * ft[2];
    const double f_coulomb = c->friction * fabs(n.fn);
    if (ft2 > f_coulomb * f_coulomb) {
        const double ft_mag = sqrt(ft2);
        const double q = 1.0 / (ft_mag * n.kt);   /* one division for the ratio and 1/kt */
        const double ratio = f_coulomb * n.kt * q, inv_kt = ft_mag * q;
        for (int d = 0; d < 3; d++) {
            ft[d] *= ratio;
            s[d] = -ft[d] * inv_kt;
        }
    }
}

static const dem_contact_model tangential_history_model = {
    .slot = SLOT_TANGENTIAL, .name = "history", .history = 3, .history_antisymmetric = 3,
};

#endif
