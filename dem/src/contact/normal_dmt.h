/* Normal model `dmt`: Derjaguin-Muller-Toporov adhesive elastic contact (Derjaguin, Muller and
 * Toporov 1975, J. Colloid Interface Sci. 53, 314): the Hertz force less a constant pull acting
 * while the bodies overlap,
 *   F = 4/3 Y* sqrt(R*) delta^(3/2) - 2 pi W R*,
 * W the work of adhesion; the pull-off force is 2 pi W R* (the DMT limit of stiff, small
 * spheres, where the JKR neck does not form). No hysteresis: contact begins and ends at
 * delta = 0. The dashpot and the tangential stiffness are hertz's. limitForce clips the whole
 * normal force at zero, adhesion included. Parameter per interaction: workOfAdhesion W
 * [J/m^2], required, > 0. Equations, sources and choices: docs/models/normal_dmt.md. */
#ifndef DEM_NORMAL_DMT_H
#define DEM_NORMAL_DMT_H

#include <math.h>
#include "../materials.h"
#include "normal_hertz.h"

typedef struct dem_dmt_params {
    double w;   /* work of adhesion [J/m^2] */
} dem_dmt_params;

static const dem_model_param dmt_param_table[] = {
    {"workOfAdhesion", "J/m^2", NAN, 0.0, 1e3, offsetof(dem_dmt_params, w)},
};

static inline dem_normal_result normal_dmt_force(const dem_contact *k, const dem_pair_coeffs *c,
                                             const dem_contact_models *m, double *restrict h)
{
    dem_normal_result r;
    const double gamma_n = hertz_stiffness_damping(c, sqrt(k->r_eff * k->delta), k->m_eff, &r);
    r.fn_spring = r.kn * k->delta - 2.0 * M_PI * MODEL_PARAMS(c, SLOT_NORMAL, dem_dmt_params)->w * k->r_eff;
    r.fn = r.fn_spring - gamma_n * k->vn;
    return r;
}

static inline const char *dmt_check(const double *values, const char **key)
{
    *key = "workOfAdhesion";
    return ((const dem_dmt_params *)values)->w > 0.0 ? NULL
        : "the dmt normal model needs a positive work of adhesion [J/m^2] (use hertz without adhesion)";
}

static const dem_contact_model normal_dmt_model = {
    .slot = SLOT_NORMAL, .name = "dmt",
    .params = dmt_param_table, .nparams = 1, .check = dmt_check,
    .contact_time = hertz_contact_time, .contact_time_name = "Hertz",
    .coarse_graining_refused = "the adhesion 2 pi w R* grows as cg while the contact forces grow as cg^2, so a parcel is "
        "less sticky than its particles (LIGGGHTS refuses cohesion too); no rule for w is applied implicitly",
};

#endif
