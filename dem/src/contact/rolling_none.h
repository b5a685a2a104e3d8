/* Rolling model `none`: no rolling resistance; docs/models/rolling_none.md. */
#ifndef DEM_ROLLING_NONE_H
#define DEM_ROLLING_NONE_H

#include "../materials.h"

static inline void rolling_none_torque(const dem_contact *k, const dem_pair_coeffs *c, const dem_contact_models *m,
                                       dem_normal_result n, const double w[3], double *restrict h,
                                       double torque_i[3])
{
    torque_i[0] = torque_i[1] = torque_i[2] = 0.0;
}

static const dem_contact_model rolling_none_model = {.slot = SLOT_ROLLING, .name = "none"};

#endif
