/* Rolling model `cdtJkr`: constant directional torque with mu_r from JKR adhesion
 * (seed note 000, "CDT-JKR rolling resistance", eq. 1-11).
 *
 * Where the note is ambiguous: eq. 9 takes the torque direction "from the instantaneous
 * rotational velocity difference (eq. 4)" but writes the projected rate of eq. 5, which has no
 * normal part, so the torsionTorque switch of eq. 10 would do nothing. We read it as the
 * physics needs: the direction is that of omega_ij (eq. 4), so with torsionTorque true the
 * torque also resists twisting, and torsionTorque false removes the normal part (eq. 10).
 * E* in eq. 2 is the effective modulus Y* of the normal model. The rolling displacement
 * xi_r (eq. 5-6) is kept in the contact history as the note defines it; the torque of eq. 9
 * depends on its rate only. */
#ifndef DEM_ROLLING_CDT_JKR_H
#define DEM_ROLLING_CDT_JKR_H

#include <math.h>
#include "../materials.h"
#include "contact.h"

/* mu_r of a contact with effective radius R* (eq. 2-3). */
static inline double cdt_jkr_rolling_friction(const pair_coeffs *c, double r_eff)
{
    const double a0 = cbrt(9.0 * M_PI * c->m.work_of_adhesion * r_eff * r_eff / (2.0 * c->Y_eff));  /* eq. 2 */
    return M_PI * a0 / (4.0 * r_eff) * c->m.adhesion_hysteresis;                                     /* eq. 3 */
}

/* w = omega_i - omega_j (eq. 4; omega_j = 0 for a wall); r_eff = R* (eq. 1, R_i for a wall);
 * xi: the rolling displacement history (3 doubles). Returns the torque on i; j gets minus it. */
static inline void rolling_cdt_jkr(const pair_coeffs *c, const double en[3], const double w[3],
                                   normal_result n, double r_eff, double dt, int torsion_torque,
                                   double *restrict xi, double torque_i[3])
{
    const double w_n = w[0] * en[0] + w[1] * en[1] + w[2] * en[2];
    for (int d = 0; d < 3; d++) xi[d] += r_eff * (w[d] - w_n * en[d]) * dt;       /* eq. 5, 6 */
    const double fn = n.fn_spring;                                                 /* eq. 7 */
    const double m_max = cdt_jkr_rolling_friction(c, r_eff) * fn * r_eff;         /* eq. 8 */
    const double w_mag = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    const double scale = w_mag > 0.0 ? -m_max / w_mag : 0.0;
    double m[3] = {scale * w[0], scale * w[1], scale * w[2]};                      /* eq. 9 */
    if (!torsion_torque) {                                                         /* eq. 10 */
        const double m_n = m[0] * en[0] + m[1] * en[1] + m[2] * en[2];
        for (int d = 0; d < 3; d++) m[d] -= m_n * en[d];
    }
    for (int d = 0; d < 3; d++) torque_i[d] = m[d];                                /* eq. 11: +M_r on i, -M_r on j */
}

#endif
