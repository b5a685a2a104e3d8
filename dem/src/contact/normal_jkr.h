/* Normal model `jkr`: Johnson-Kendall-Roberts adhesive elastic contact (Johnson, Kendall and
 * Roberts 1971, Proc. R. Soc. Lond. A 324, 301), with its hysteresis. The contact radius a and
 * the force follow from the overlap delta through
 *   delta = a^2 / R* - sqrt(2 pi W a / Y*),        F = 4 Y* a^3 / (3 R*) - sqrt(8 pi W Y* a^3),
 * W the work of adhesion. Approaching spheres feel nothing until they touch (delta = 0); there
 * the neck snaps in (a^3 = 2 pi W R*^2 / Y*, F = -4/3 pi W R*). Pulled apart, the neck holds
 * past delta = 0 into a gap: the largest pull, 1.5 pi W R*, comes at a^3 = 9 pi W R*^2 / (8 Y*),
 * and the neck breaks where d delta / da = 0, at a_c^3 = pi W R*^2 / (8 Y*), i.e. at the gap
 *   delta_c = 3 a_c^2 / R* = 3/4 (pi^2 W^2 R* / Y*^2)^(1/3)          (the model's reach);
 * from then on the pair is free until it touches again. History: 1 double, 1 while the neck
 * exists. a(delta) is the largest root of the quartic in sqrt(a), found by Newton's method from
 * an upper bound (the quartic is convex in sqrt(a), so the iteration falls monotonically onto
 * the stable branch a >= a_c).
 * Choices: the dashpot is hertz's at the JKR contact radius (gamma_n from the restitution e,
 * sn = 2 Y* a), the stiffnesses handed to the tangential and rolling models are hertz's at that
 * radius (kt = 8 G* a, kn = 4/3 Y* a); the exact dF/d delta diverges where the neck breaks.
 * limitForce clips the whole normal force at zero, adhesion included. The time-step check uses
 * the Hertz contact time (adhesion lengthens the contact).
 * Parameter per interaction: workOfAdhesion W [J/m^2], required, > 0. Equations, sources and
 * choices: docs/models/normal_jkr.md. */
#ifndef DEM_NORMAL_JKR_H
#define DEM_NORMAL_JKR_H

#include <math.h>
#include "../materials.h"
#include "normal_hertz.h"

typedef struct dem_jkr_params {
    double w;   /* work of adhesion [J/m^2] */
} dem_jkr_params;

static const dem_model_param jkr_param_table[] = {
    {"workOfAdhesion", "J/m^2", NAN, 0.0, 1e3, offsetof(dem_jkr_params, w)},
};

/* The gap at which the neck of a contact with effective radius r_eff breaks [m]. */
static inline double jkr_reach(const dem_pair_coeffs *c, double r_eff)
{
    const double w = MODEL_PARAMS(c, SLOT_NORMAL, dem_jkr_params)->w;
    return 0.75 * cbrt(M_PI * M_PI * w * w * r_eff / (c->Y_eff * c->Y_eff));
}

/* The contact radius on the stable branch at overlap delta >= -delta_c:
 * u = sqrt(a) solves g(u) = u^4 / R - q u - delta = 0, q = sqrt(2 pi W / Y*); the root lies
 * below max((2 R max(delta, 0))^(1/4), (2 R q)^(1/3)). */
static inline double jkr_contact_radius(double r_eff, double y_eff, double w, double delta)
{
    const double q = sqrt(2.0 * M_PI * w / y_eff);
    double u = fmax(sqrt(sqrt(2.0 * r_eff * fmax(delta, 0.0))), cbrt(2.0 * r_eff * q));
    for (int it = 0; it < 200; it++) {
        const double u3 = u * u * u;
        const double dg = 4.0 * u3 / r_eff - q;
        if (!(dg > 0.0)) break;                      /* at the double root where the neck breaks */
        const double du = (u3 * u / r_eff - q * u - delta) / dg;
        u -= du;
        if (!(fabs(du) > 1e-15 * u)) break;
    }
    return u * u;
}

static inline dem_normal_result normal_jkr_force(const dem_contact *k, const dem_pair_coeffs *c,
                                             const dem_contact_models *m, double *restrict h)
{
    dem_normal_result r = {0};
    if (k->delta >= 0.0) h[0] = 1.0;                         /* touching: the neck forms */
    if (h[0] == 0.0) return r;                               /* approaching, not yet touching */
    if (k->delta < -jkr_reach(c, k->r_eff)) {                /* the neck breaks */
        h[0] = 0.0;
        return r;
    }
    const double w = MODEL_PARAMS(c, SLOT_NORMAL, dem_jkr_params)->w, y = c->Y_eff;
    const double a = jkr_contact_radius(k->r_eff, y, w, k->delta), a3 = a * a * a;
    const double gamma_n = hertz_stiffness_damping(c, a, k->m_eff, &r);
    r.fn_spring = 4.0 * y * a3 / (3.0 * k->r_eff) - sqrt(8.0 * M_PI * w * y * a3);
    r.fn = r.fn_spring - gamma_n * k->vn;
    return r;
}

static inline const char *jkr_check(const double *values, const char **key)
{
    *key = "workOfAdhesion";
    return ((const dem_jkr_params *)values)->w > 0.0 ? NULL
        : "the jkr normal model needs a positive work of adhesion [J/m^2] (use hertz without adhesion)";
}

static const dem_contact_model normal_jkr_model = {
    .slot = SLOT_NORMAL, .name = "jkr", .history = 1,
    .params = jkr_param_table, .nparams = 1, .check = jkr_check,
    .contact_time = hertz_contact_time, .contact_time_name = "Hertz",
    .reach = jkr_reach,
    .coarse_graining_refused = "the pull-off force 3/2 pi w R* grows as cg while the contact forces grow as cg^2, so a "
        "parcel is less sticky than its particles (LIGGGHTS refuses cohesion too); no rule for w is applied implicitly",
};

#endif
