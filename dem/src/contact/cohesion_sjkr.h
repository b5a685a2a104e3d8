/* Cohesion model `sjkr` (simplified JKR, as LIGGGHTS' cohesion sjkr): an attraction equal to the
 * cohesion energy density times the contact area,
 *   F_coh = -k_coh pi a^2,
 * a the radius of the circle where the two spheres (or sphere and wall) intersect. It acts only
 * while the bodies overlap and is added after the tangential model, so the Coulomb limit uses
 * the normal model's force alone (as LIGGGHTS). Parameter per interaction:
 * cohesionEnergyDensity k_coh [J/m^3], required (0 switches it off for a pair). Equations,
 * sources and choices: docs/models/cohesion_sjkr.md. */
#ifndef DEM_COHESION_SJKR_H
#define DEM_COHESION_SJKR_H

#include <math.h>
#include "../materials.h"

typedef struct dem_sjkr_params {
    double k_coh;   /* cohesion energy density [J/m^3] */
} dem_sjkr_params;

static const dem_model_param sjkr_param_table[] = {
    {"cohesionEnergyDensity", "J/m^3", NAN, 0.0, 1e12, offsetof(dem_sjkr_params, k_coh)},
};

static inline double cohesion_sjkr_force(const dem_contact *k, const dem_pair_coeffs *c)
{
    return -MODEL_PARAMS(c, SLOT_COHESION, dem_sjkr_params)->k_coh * M_PI * k->a2;
}

static const dem_contact_model cohesion_sjkr_model = {
    .slot = SLOT_COHESION, .name = "sjkr", .needs_contact_radius = 1,
    .params = sjkr_param_table, .nparams = 1,
};

#endif
