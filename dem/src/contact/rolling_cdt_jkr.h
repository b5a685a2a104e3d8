/* Rolling model `cdtJkr`: constant directional torque with mu_r from JKR adhesion
 * (seed note 000, "CDT-JKR rolling resistance", eq. 1-11). Equations:
 * docs/models/rolling_cdt_jkr.md, which keeps the note's numbering: "eq. N" in this file is that
 * page's eq. N and seed 000's eq. N.
 *
 * Where the note is ambiguous: eq. 9 takes the torque direction "from the instantaneous
 * rotational velocity difference (eq. 4)" but writes the projected rate of eq. 5, which has no
 * normal part, so the torsionTorque switch of eq. 10 would do nothing. We read it as the
 * physics needs: the direction is that of omega_ij (eq. 4), so with torsionTorque true the
 * torque also resists twisting, and torsionTorque false removes the normal part (eq. 10).
 * E* in eq. 2 is the effective modulus Y* of the normal model. The rolling displacement
 * xi_r (eq. 5-6) is kept in the contact history as the note defines it; the torque of eq. 9
 * depends on its rate only.
 * Parameters per interaction: workOfAdhesion W [J/m^2] (> 0) and adhesionHysteresis eta_adh
 * [-], both required; case-wide: torsionTorque (contactModels, default true). History: xi_r
 * (3 doubles, antisymmetric). */
#ifndef DEM_ROLLING_CDT_JKR_H
#define DEM_ROLLING_CDT_JKR_H

#include <math.h>
#include "../dict.h"
#include "../materials.h"

typedef struct dem_cdt_jkr_params {
    double work_of_adhesion;      /* W [J/m^2] (rolling_cdt_jkr.md eq. 2) */
    double adhesion_hysteresis;   /* eta_adh [-] (rolling_cdt_jkr.md eq. 3) */
} dem_cdt_jkr_params;

static const dem_model_param cdt_jkr_param_table[] = {
    {"workOfAdhesion", "J/m^2", NAN, 0.0, 1e3, offsetof(dem_cdt_jkr_params, work_of_adhesion)},
    {"adhesionHysteresis", "-", NAN, 0.0, 1e3, offsetof(dem_cdt_jkr_params, adhesion_hysteresis)},
};

typedef struct dem_cdt_jkr_case {
    double torsion_torque;   /* 1: keep the normal (torsion) part of the torque (rolling_cdt_jkr.md eq. 10) */
} dem_cdt_jkr_case;

/* mu_r of a contact with effective radius R* (rolling_cdt_jkr.md eq. 2-3). */
static inline double cdt_jkr_rolling_friction(const dem_pair_coeffs *c, double r_eff)
{
    const dem_cdt_jkr_params *p = MODEL_PARAMS(c, SLOT_ROLLING, dem_cdt_jkr_params);
    const double a0 = cbrt(9.0 * M_PI * p->work_of_adhesion * r_eff * r_eff / (2.0 * c->Y_eff));  /* rolling_cdt_jkr.md eq. 2 */
    return M_PI * a0 / (4.0 * r_eff) * p->adhesion_hysteresis;                                     /* rolling_cdt_jkr.md eq. 3 */
}

/* w = omega_i - omega_j (rolling_cdt_jkr.md eq. 4; omega_j = 0 for a wall); k->r_eff = R*
 * (rolling_cdt_jkr.md eq. 1, R_i for a wall); xi: the rolling displacement history (3 doubles).
 * Returns the torque on i; j gets minus it. */
static inline void rolling_cdt_jkr_torque(const dem_contact *k, const dem_pair_coeffs *c, const dem_contact_models *m,
                                          dem_normal_result n, const double w[3], double *restrict xi,
                                          double torque_i[3])
{
    const double *en = k->en, r_eff = k->r_eff;
    const double w_n = w[0] * en[0] + w[1] * en[1] + w[2] * en[2];
    for (int d = 0; d < 3; d++) xi[d] += r_eff * (w[d] - w_n * en[d]) * k->dt;     /* rolling_cdt_jkr.md eq. 5, 6 */
    const double fn = fabs(n.fn_spring);   /* rolling_cdt_jkr.md eq. 7; |F_el|: a pull (adhesive normal model) still resists */
    const double m_max = cdt_jkr_rolling_friction(c, r_eff) * fn * r_eff;         /* rolling_cdt_jkr.md eq. 8 */
    const double w_mag = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    const double scale = w_mag > 0.0 ? -m_max / w_mag : 0.0;
    double mr[3] = {scale * w[0], scale * w[1], scale * w[2]};                     /* rolling_cdt_jkr.md eq. 9 */
    if (!MODEL_CASE(m, SLOT_ROLLING, dem_cdt_jkr_case)->torsion_torque) {              /* rolling_cdt_jkr.md eq. 10 */
        const double m_n = mr[0] * en[0] + mr[1] * en[1] + mr[2] * en[2];
        for (int d = 0; d < 3; d++) mr[d] -= m_n * en[d];
    }
    for (int d = 0; d < 3; d++) torque_i[d] = mr[d];                               /* rolling_cdt_jkr.md eq. 11: +M_r on i, -M_r on j */
}

static inline const char *cdt_jkr_check(const double *values, const char **key)
{
    *key = "workOfAdhesion";
    return ((const dem_cdt_jkr_params *)values)->work_of_adhesion > 0.0 ? NULL
        : "cdtJkr takes mu_r from the JKR contact radius (seed 000 eq. 2-3): the work of adhesion "
          "must be positive [J/m^2] (use rolling cdt for a given mu_r)";
}

static inline void cdt_jkr_read_case(const dem_dict *d, double *values)
{
    ((dem_cdt_jkr_case *)values)->torsion_torque = dem_dict_bool_opt(d, "torsionTorque", 1);
}

static const dem_contact_model rolling_cdt_jkr_model = {
    .slot = SLOT_ROLLING, .name = "cdtJkr", .history = 3, .history_antisymmetric = 3,
    .params = cdt_jkr_param_table, .nparams = 2, .check = cdt_jkr_check, .read_case = cdt_jkr_read_case,
    .coarse_graining_refused = "its JKR neck (work of adhesion) does not scale with the parcel as the contact forces do "
        "(see normal jkr)",
};

#endif
