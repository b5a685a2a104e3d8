/* Cohesion model `none`: no attraction beyond what the normal model has;
 * docs/models/cohesion_none.md. */
#ifndef DEM_COHESION_NONE_H
#define DEM_COHESION_NONE_H

#include "../materials.h"

static inline double cohesion_none_force(const dem_contact *k, const dem_pair_coeffs *c) { return 0.0; }

static const dem_contact_model cohesion_none_model = {.slot = SLOT_COHESION, .name = "none"};

#endif
