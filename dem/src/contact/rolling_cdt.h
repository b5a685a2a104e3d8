/* Rolling model `cdt` (constant directional torque, as LIGGGHTS' rolling cdt):
 *   M = mu_r (kn delta) R_lever w/|w|,  w = omega_i - omega_j,  minus its normal (torsion) part;
 * torque -M on i and +M on j. R_lever is R* for a pair and the contact radius R_i - delta/2
 * for a wall (as LIGGGHTS). */
#ifndef DEM_ROLLING_CDT_H
#define DEM_ROLLING_CDT_H

#include <math.h>
#include "../materials.h"
#include "contact.h"

static inline void rolling_cdt(const pair_coeffs *c, const double en[3], const double w[3],
                               normal_result n, double lever, double torque_i[3])
{
    const double w_mag = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    const double scale = w_mag > 0.0 ? c->m.rolling_friction * n.fn_spring * lever / w_mag : 0.0;
    double m[3] = {scale * w[0], scale * w[1], scale * w[2]};
    const double m_n = m[0] * en[0] + m[1] * en[1] + m[2] * en[2];
    for (int d = 0; d < 3; d++) torque_i[d] = -(m[d] - m_n * en[d]);
}

#endif
