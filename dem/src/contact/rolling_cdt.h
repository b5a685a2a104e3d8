/* Rolling model `cdt` (constant directional torque, as LIGGGHTS' rolling cdt):
 *   M = mu_r |kn delta| R_lever w/|w|,  w = omega_i - omega_j,  minus its normal (torsion) part;
 * torque -M on i and +M on j. R_lever is R* for a pair and the contact radius R_i - delta/2
 * for a wall (as LIGGGHTS). Parameter per interaction: rollingFriction mu_r, required.
 * Equations, sources and choices: docs/models/rolling_cdt.md. */
#ifndef DEM_ROLLING_CDT_H
#define DEM_ROLLING_CDT_H

#include <math.h>
#include "../materials.h"

typedef struct dem_cdt_params {
    double mu_r;   /* rolling friction coefficient [-] */
} dem_cdt_params;

static const dem_model_param cdt_param_table[] = {
    {"rollingFriction", "-", NAN, 0.0, 10.0, offsetof(dem_cdt_params, mu_r)},
};

static inline void rolling_cdt_torque(const dem_contact *k, const dem_pair_coeffs *c, const dem_contact_models *m,
                                      dem_normal_result n, const double w[3], double *restrict h,
                                      double torque_i[3])
{
    const double *en = k->en;
    const double w_mag = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    const double mu_r = MODEL_PARAMS(c, SLOT_ROLLING, dem_cdt_params)->mu_r;
    /* |F_el|: under an adhesive normal model F_el can be a pull; the torque still resists */
    const double scale = w_mag > 0.0 ? mu_r * fabs(n.fn_spring) * k->rolling_lever / w_mag : 0.0;
    double mr[3] = {scale * w[0], scale * w[1], scale * w[2]};
    const double m_n = mr[0] * en[0] + mr[1] * en[1] + mr[2] * en[2];
    for (int d = 0; d < 3; d++) torque_i[d] = -(mr[d] - m_n * en[d]);
}

static const dem_contact_model rolling_cdt_model = {
    .slot = SLOT_ROLLING, .name = "cdt", .params = cdt_param_table, .nparams = 1,
};

#endif
