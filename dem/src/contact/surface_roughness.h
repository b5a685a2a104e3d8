/* Surface model `roughness` (seed note 001, eq. 1-17; equations: docs/models/surface_roughness.md,
 * which keeps the note's numbering: "eq. N" in this file is that page's eq. N and seed 001's
 * eq. N): the contact normal is rotated by a random scatter angle Delta Gamma about a random
 * azimuth psi (eq. 11-12), and the normal and tangential models work with the rotated normal n'.
 * The angles are drawn once, when the contact starts, from a counter-based generator keyed on the
 * seed, the two particle ids (or particle id and wall index) and the start step, so a run is
 * reproducible and independent of particle order. History (6 doubles): cos Delta Gamma, the
 * offset dR of eq. 11 in space, the distance the contact points have slid since the draw, and the
 * largest contact radius since.
 *
 * Choices where the note is open:
 *  - dR is drawn in the frame of the normal oriented from the higher to the lower particle id,
 *    and n' = cos(dG) n + s dR with s = +1 or -1 for the particle seen (eq. 12; "the sign
 *    reverses for a particle pair"), so i and j feel equal and opposite forces. While the
 *    contact lasts dR is projected on the current tangent plane (n turns a little).
 *  - An asperity is as wide as the contact: once the contact points have slid further than the
 *    largest contact radius a since the draw, the angles are drawn anew (keyed on the step of
 *    the redraw; the largest a, so that an impact is not redrawn as a shrinks to 0 at its end). Without this a
 *    wall contact would keep one tilted normal for as long as it lasts, and its sideways part
 *    Fn sin dG would push a sphere along the wall without end, feeding it energy.
 *  - Delta Gamma: `normal` N(0, stdDev) truncated to |dG| <= max, or `uniform` on [0, max];
 *    psi uniform on [0, 2 pi). max < pi/2 so that n' keeps pointing out of the contact.
 *  - v_n and v_t (eq. 6-8) are taken along n'; the rotational part v_omega (eq. 14-15) uses
 *    the true separation, written (c_i w_i + c_j w_j) x n as the default surface computes it,
 *    so that zero scatter reproduces the default surface bit for bit. The normal force acts
 *    along n' through the centres; torques come from the tangential force, lever -c_i n.
 *  - eq. 17 (wall penetration guard; its signs do not fit eq. 4-6) is read as: a particle that
 *    moves into the wall plane (v . n_plane < 0) while the rough contact's total force does
 *    not push it out (F . n_plane <= 0, possible at large Delta Gamma with friction or a pulling
 *    dashpot) has its normal velocity reflected, v -= 2 (v . n_plane) n_plane. In an ordinary
 *    impact the force pushes out and the guard never acts.
 * Case-wide settings, contactModels { roughness { distribution normal | uniform; stdDev [rad];
 * max [rad, < 1.5; normal: default min(3 stdDev, 1.5)]; seed (1); } }.
 */
#ifndef DEM_SURFACE_ROUGHNESS_H
#define DEM_SURFACE_ROUGHNESS_H

#include <math.h>
#include <stdint.h>
#include "../dict.h"
#include "model.h"

/* Distribution of the scatter angle Delta Gamma. */
enum dem_scatter_distribution { SCATTER_NORMAL, SCATTER_UNIFORM };

typedef struct dem_roughness_case {
    double distribution; /* enum scatter_distribution */
    double std_dev;      /* normal: Delta Gamma ~ N(0, std_dev) [rad] ... */
    double max;          /* ... truncated to |Delta Gamma| <= max; uniform: U(0, max) [rad] */
    double seed;         /* key of the counter-based generator (an integer < 2^31) */
} dem_roughness_case;
_Static_assert(sizeof(dem_roughness_case) <= MODEL_VALUES * sizeof(double), "roughness_case too large");

static inline uint64_t roughness_mix(uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

/* The k-th uniform number in [0, 1) of the stream keyed on (seed, a, b, step). */
static inline double roughness_uniform(uint64_t key, uint64_t k)
{
    return (double)(roughness_mix(key + (k + 1) * 0x9e3779b97f4a7c15ULL) >> 11) * 0x1.0p-53;
}

/* Draw the angles of a new contact (surface_roughness.md eq. 18). a < b: the ids (a wall is id
 * ~k); n_ref: the normal oriented from b to a. Fills h = {cos dG, dR}. */
static inline void roughness_start(const dem_roughness_case *rp, uint64_t a, uint64_t b, long step,
                                   const double n_ref[3], double *restrict h)
{
    uint64_t key = roughness_mix((uint64_t)rp->seed + 0x9e3779b97f4a7c15ULL);
    key = roughness_mix(key ^ a);
    key = roughness_mix(key ^ b);
    key = roughness_mix(key ^ (uint64_t)step);
    double dg;
    uint64_t k = 0;
    if (rp->distribution == (double)SCATTER_UNIFORM) {
        dg = rp->max * roughness_uniform(key, k++);
    } else {
        do {   /* Box-Muller; rejection keeps |dG| <= max */
            const double u1 = 1.0 - roughness_uniform(key, k++), u2 = roughness_uniform(key, k++);
            dg = rp->std_dev * sqrt(-2.0 * log(u1)) * cos(2.0 * M_PI * u2);
        } while (fabs(dg) > rp->max);
    }
    const double psi = 2.0 * M_PI * roughness_uniform(key, k++);
    /* an orthonormal pair {n1, n2} across n_ref (Duff et al. 2017) */
    const double sgn = n_ref[2] >= 0.0 ? 1.0 : -1.0;
    const double p = -1.0 / (sgn + n_ref[2]), q = n_ref[0] * n_ref[1] * p;
    const double n1[3] = {1.0 + sgn * n_ref[0] * n_ref[0] * p, sgn * q, -sgn * n_ref[0]};
    const double n2[3] = {q, sgn + n_ref[1] * n_ref[1] * p, -n_ref[1]};
    const double sin_dg = sin(dg), s1 = sin_dg * sin(psi), s2 = sin_dg * cos(psi);
    h[0] = cos(dg);
    for (int d = 0; d < 3; d++) h[1 + d] = s1 * n1[d] + s2 * n2[d];            /* surface_roughness.md eq. 11 */
}

/* Draw at the start of a contact or when the contact has slid past its asperity (radius a;
 * surface_roughness.md eq. 19); then add this step's sliding, |v_t| dt, v_t the contact points'
 * relative tangential velocity. */
static inline void roughness_update(const dem_roughness_case *rp, uint64_t a, uint64_t b, long step,
                                    const double n_ref[3], double contact_radius, double slide_speed,
                                    double dt, double *restrict h)
{
    if (contact_radius > h[5]) h[5] = contact_radius;
    if (h[0] == 0.0 || h[4] > h[5]) {
        roughness_start(rp, a, b, step, n_ref, h);
        h[4] = 0.0;
        h[5] = contact_radius;
    }
    h[4] += slide_speed * dt;
}

/* n' for the particle whose normal is n (from its partner to it); s: +1 if n is n_ref. */
static inline void roughness_normal(const double *restrict h, const double n[3], double s, double n_rot[3])
{
    const double dr_n = h[1] * n[0] + h[2] * n[1] + h[3] * n[2];
    for (int d = 0; d < 3; d++) n_rot[d] = h[0] * n[d] + s * (h[1 + d] - dr_n * n[d]);   /* surface_roughness.md eq. 12 */
}

/* The normal the forces use: drawn or redrawn (roughness_update; surface_roughness.md eqs. 18-19),
 * then tilted (surface_roughness.md eq. 12). */
static inline void surface_roughness_normal(const dem_contact *k, const dem_contact_models *m, double *restrict h,
                                            double en_f[3])
{
    const dem_roughness_case *rp = MODEL_CASE(m, SLOT_SURFACE, dem_roughness_case);
    const double *en = k->en, sign = k->sign;
    const double n_ref[3] = {sign * en[0], sign * en[1], sign * en[2]};
    const double wr[3] = {k->lever_i * k->wi[0] + k->lever_j * k->wj[0], k->lever_i * k->wi[1] + k->lever_j * k->wj[1],
                          k->lever_i * k->wi[2] + k->lever_j * k->wj[2]};
    const double vrn = k->vr[0] * en[0] + k->vr[1] * en[1] + k->vr[2] * en[2];
    double vs[3];   /* sliding velocity on the true tangent plane */
    contact_tangential_velocity(k->vr, vrn, en, wr, en, vs);
    roughness_update(rp, k->key_lo, k->key_hi, k->step, n_ref, sqrt(k->a2),
                     sqrt(vs[0] * vs[0] + vs[1] * vs[1] + vs[2] * vs[2]), k->dt, h);
    roughness_normal(h, en, sign, en_f);
}

/* surface_roughness.md eq. 17 at a wall: the rough contact fails to hold the particle (v: its
 * velocity). */
static inline void surface_roughness_wall_guard(const dem_contact_models *m, const double en[3], const double f[3],
                                                double v[3])
{
    const double v_plane = v[0] * en[0] + v[1] * en[1] + v[2] * en[2];
    if (v_plane < 0.0 && f[0] * en[0] + f[1] * en[1] + f[2] * en[2] <= 0.0)
        for (int q = 0; q < 3; q++) v[q] -= 2.0 * v_plane * en[q];
}

static inline void roughness_read_case(const dem_dict *contact_models_dict, double *values)
{
    const dem_dict *r = dem_dict_sub(contact_models_dict, "roughness");
    static const char *const dists[] = {"normal", "uniform", 0};
    dem_roughness_case *rp = (dem_roughness_case *)values;
    rp->distribution = dem_dict_choice(r, "distribution", dists);
    /* angles in radians; |Delta Gamma| < pi/2 keeps the rotated normal out of the contact */
    if (rp->distribution == (double)SCATTER_NORMAL) {
        rp->std_dev = dem_dict_scalar(r, "stdDev", 0.0, 1.0);
        rp->max = dem_dict_scalar_opt(r, "max", fmin(3.0 * rp->std_dev, 1.5), 0.0, 1.5);
    } else {
        rp->max = dem_dict_scalar(r, "max", 0.0, 1.5);
    }
    rp->seed = (double)dem_dict_label_opt(r, "seed", 1, 0, 2147483647L);
}

static const dem_contact_model surface_roughness_model = {
    .slot = SLOT_SURFACE, .name = "roughness", .history = 6, .needs_contact_radius = 1,
    .read_case = roughness_read_case,
};

#endif
