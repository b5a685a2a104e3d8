/* Cohesion model `none`: no attraction beyond what the normal model has. */
#ifndef DEM_COHESION_NONE_H
#define DEM_COHESION_NONE_H

#include "../materials.h"

static inline double cohesion_none_force(const contact *k, const pair_coeffs *c) { return 0.0; }

static const contact_model cohesion_none_model = {.slot = SLOT_COHESION, .name = "none"};

#endif
