/* Tangential model `none`: frictionless contacts (no tangential force, no history);
 * docs/models/tangential_none.md. */
#ifndef DEM_TANGENTIAL_NONE_H
#define DEM_TANGENTIAL_NONE_H

#include "../materials.h"

static inline void tangential_none_force(const dem_contact *k, const dem_pair_coeffs *c, dem_normal_result n,
                                         const double en[3], const double vt[3], double *restrict s,
                                         double ft[3])
{
    ft[0] = ft[1] = ft[2] = 0.0;
}

static const dem_contact_model tangential_none_model = {.slot = SLOT_TANGENTIAL, .name = "none"};

#endif
