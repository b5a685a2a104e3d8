/* Cohesion model `sjkr` (simplified JKR, as LIGGGHTS' cohesion sjkr): an attraction equal to the
 * cohesion energy density times the contact area,
 *   F_coh = -k_coh pi a^2,
 * a the radius of the circle where the two spheres (or sphere and wall) intersect. It acts only
 * while the bodies overlap and is added after the tangential model, so the Coulomb limit uses
 * the normal model's force alone (as LIGGGHTS). */
#ifndef DEM_COHESION_SJKR_H
#define DEM_COHESION_SJKR_H

#include <math.h>
#include "../materials.h"

static inline double cohesion_sjkr(const pair_coeffs *c, double contact_radius_sq)
{
    return -c->m.cohesion_energy_density * M_PI * contact_radius_sq;
}

#endif
