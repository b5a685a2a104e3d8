/* Surface model `default`: smooth spheres; the forces act along the line of centres;
 * docs/models/surface_default.md. */
#ifndef DEM_SURFACE_DEFAULT_H
#define DEM_SURFACE_DEFAULT_H

#include "model.h"

static inline void surface_default_normal(const dem_contact *k, const dem_contact_models *m, double *restrict h,
                                          double en_f[3])
{
    en_f[0] = k->en[0]; en_f[1] = k->en[1]; en_f[2] = k->en[2];
}

static inline void surface_default_wall_guard(const dem_contact_models *m, const double en[3], const double f[3],
                                              double v[3])
{
}

static const dem_contact_model surface_default_model = {.slot = SLOT_SURFACE, .name = "default"};

#endif
