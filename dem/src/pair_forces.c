/* Particle-particle contact forces over the half neighbour list.
 *
 * pair_loop() is written once for all models; each entry of the kernel table calls it with
 * constant model ids, so the compiler builds one loop per combination with the unused models
 * removed. The choice is made once per call, outside the loop. */
#include <math.h>
#include <stddef.h>

#include "contact/normal_force.h"
#include "contact/rolling_cdt.h"
#include "contact/rolling_cdt_jkr.h"
#include "contact/rolling_epsd.h"
#include "contact/surface_roughness.h"
#include "contact/tangential_history.h"
#include "system.h"

#define ALWAYS_INLINE inline __attribute__((always_inline))

/* Partners of one particle are handled in chunks: a first pass finds the touching ones
 * (branch-free; it clears the history of contacts that just ended), a second computes their
 * forces. That
 * keeps the contact test out of the force code, where its mispredictions cost most. */
#define CHUNK 64

static ALWAYS_INLINE void pair_loop(dem_system *s, const enum normal_model normal,
                                    const enum tangential_model tangential,
                                    const enum rolling_model rolling, const enum cohesion_model cohesion,
                                    const enum surface_model surface, const int periodic)
{
    particles *p = &s->p;
    neighbour_list *nl = &s->nlist;
    const vec3 *restrict x = p->x, *restrict v = p->v, *restrict w = p->omega;
    vec3 *restrict f = p->f, *restrict t = p->torque;
    const double *restrict rad = p->radius, *restrict mass = p->mass;
    const int *restrict type = p->type;
    const int64_t *restrict id = p->id;
    const double *restrict inv_inertia = p->inv_inertia;
    const int *restrict start = nl->start, *restrict partner = nl->partner;
    double *restrict hist = nl->history;
    unsigned char *restrict was_touching = nl->touching;
    /* history per pair [tangential][rolling][normal][surface]: constants for each kernel */
    const int h_roll = tangential_history_size(tangential), h_norm = h_roll + rolling_history_size(rolling);
    const int h_surf = h_norm + normal_history_size(normal), hs = h_surf + surface_history_size(surface);
    const int torsion_torque = s->models.torsion_torque;
    const roughness_params rough = s->models.roughness;
    const long step = s->step;
    const double dt = s->dt, v_char = s->models.characteristic_velocity, fn_floor = s->models.fn_floor;
    const double period[3] = {s->period[0], s->period[1], s->period[2]};
    const double inv_period[3] = {s->inv_period[0], s->inv_period[1], s->inv_period[2]};
    const material_table *mt = &s->materials;
    double max_overlap = 0.0;
    int touching[CHUNK];
    double sep[CHUNK][4];   /* separation vector and its square, kept for the force pass */

    for (int i = 0; i < nl->rows; i++) {
        const double xi = x[i][0], yi = x[i][1], zi = x[i][2], ri = rad[i], mi = mass[i];
        double fi[3] = {0.0, 0.0, 0.0}, ti[3] = {0.0, 0.0, 0.0};
        const pair_coeffs *row = &mt->pair[type[i] * DEM_MAX_TYPES];
        for (int k0 = start[i]; k0 < start[i + 1]; k0 += CHUNK) {
            const int k1 = k0 + CHUNK < start[i + 1] ? k0 + CHUNK : start[i + 1];
            int nc = 0;
            for (int k = k0; k < k1; k++) {
                const int j = partner[k];
                double d[3] = {xi - x[j][0], yi - x[j][1], zi - x[j][2]};
                if (periodic)
                    for (int c = 0; c < 3; c++) d[c] -= period[c] * nearbyint(d[c] * inv_period[c]);
                const double radsum = ri + rad[j];
                const double rsq = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
                const int touch = rsq < radsum * radsum;
                touching[nc] = k;
                sep[nc][0] = d[0]; sep[nc][1] = d[1]; sep[nc][2] = d[2]; sep[nc][3] = rsq;
                nc += touch;
                if (hs > 0) {   /* a contact that ended forgets */
                    if (was_touching[k] > touch) {
                        double *h = hist + (size_t)k * hs;
                        for (int q = 0; q < hs; q++) h[q] = 0.0;
                    }
                    was_touching[k] = (unsigned char)touch;
                }
            }
            for (int m = 0; m < nc; m++) {
                const int k = touching[m], j = partner[k];
                const double *d = sep[m], rsq = sep[m][3];
                const double rj = rad[j], mj = mass[j], radsum = ri + rj;
                const pair_coeffs *c = &row[type[j]];
                /* one division serves 1/r, R* and m* (divisions dominate this loop's cost) */
                const double r = sqrt(rsq);
                const double q = 1.0 / (r * radsum * (mi + mj));
                const double rinv = q * radsum * (mi + mj);
                const double r_eff = ri * rj * (mi + mj) * r * q, m_eff = mi * mj * radsum * r * q;
                const double delta = radsum - r;
                const double overlap = delta / (ri < rj ? ri : rj);
                max_overlap = overlap > max_overlap ? overlap : max_overlap;
                double *h = hist + (size_t)k * hs;

                /* en: the geometric normal (j to i); en_f: the one the forces use (surface model) */
                const double en[3] = {d[0] * rinv, d[1] * rinv, d[2] * rinv};
                double en_f[3] = {en[0], en[1], en[2]};
                double contact_radius_sq = 0.0;
                if (normal == NORMAL_EDINBURGH || cohesion == COHESION_SJKR || surface == SURFACE_ROUGHNESS)
                    contact_radius_sq = contact_radius_sq_pair(ri, rj, r);
                const double vr[3] = {v[i][0] - v[j][0], v[i][1] - v[j][1], v[i][2] - v[j][2]};
                if (surface == SURFACE_ROUGHNESS) {
                    const double sign = id[i] < id[j] ? 1.0 : -1.0;
                    const double n_ref[3] = {sign * en[0], sign * en[1], sign * en[2]};
                    const double cri = ri - 0.5 * delta, crj = rj - 0.5 * delta;
                    const double wr[3] = {cri * w[i][0] + crj * w[j][0], cri * w[i][1] + crj * w[j][1],
                                          cri * w[i][2] + crj * w[j][2]};
                    const double vrn = vr[0] * en[0] + vr[1] * en[1] + vr[2] * en[2];
                    double vs[3];   /* sliding velocity on the true tangent plane */
                    contact_tangential_velocity(vr, vrn, en, wr, en, vs);
                    roughness_update(&rough, (uint64_t)(id[i] < id[j] ? id[i] : id[j]),
                                     (uint64_t)(id[i] < id[j] ? id[j] : id[i]), step, n_ref,
                                     sqrt(contact_radius_sq), sqrt(vs[0] * vs[0] + vs[1] * vs[1] + vs[2] * vs[2]),
                                     dt, h + h_surf);
                    roughness_normal(h + h_surf, en, sign, en_f);
                }

                const double vn = vr[0] * en_f[0] + vr[1] * en_f[1] + vr[2] * en_f[2];

                double fn;
                const normal_result n = contact_normal(normal, cohesion, c, delta, r_eff, m_eff, vn, v_char, fn_floor,
                                                       contact_radius_sq, h + h_norm, &fn);
                double fc[3] = {fn * en_f[0], fn * en_f[1], fn * en_f[2]};
                if (tangential == TANGENTIAL_HISTORY) {
                    /* contact-point velocity: lever arms to the centre of the overlap */
                    const double cri = ri - 0.5 * delta, crj = rj - 0.5 * delta;
                    const double wr[3] = {cri * w[i][0] + crj * w[j][0], cri * w[i][1] + crj * w[j][1],
                                          cri * w[i][2] + crj * w[j][2]};
                    double vt[3], ft[3];
                    contact_tangential_velocity(vr, vn, en_f, wr, en, vt);
                    tangential_history(h, en_f, vt, n, c->friction, dt, ft);
                    fc[0] += ft[0]; fc[1] += ft[1]; fc[2] += ft[2];
                    /* torque = lever x force, lever -cr en for i and +cr en for j (force -ft) */
                    const double ent[3] = {en[1] * ft[2] - en[2] * ft[1], en[2] * ft[0] - en[0] * ft[2],
                                           en[0] * ft[1] - en[1] * ft[0]};
                    for (int q = 0; q < 3; q++) {
                        ti[q] -= cri * ent[q];
                        t[j][q] -= crj * ent[q];
                    }
                }
                if (rolling != ROLLING_NONE) {
                    const double wij[3] = {w[i][0] - w[j][0], w[i][1] - w[j][1], w[i][2] - w[j][2]};
                    double mr[3];
                    if (rolling == ROLLING_CDT) rolling_cdt(c, en, wij, n, r_eff, mr);
                    else if (rolling == ROLLING_CDT_JKR)
                        rolling_cdt_jkr(c, en, wij, n, r_eff, dt, torsion_torque, h + h_roll, mr);
                    else {
                        const double ii = 1.0 / inv_inertia[i], ij = 1.0 / inv_inertia[j];
                        /* 1.4 m r^2 = 3.5 I of a sphere; reduced for the pair */
                        rolling_epsd(c, en, wij, n, r_eff, 3.5 * ii * ij / (ii + ij), dt, h + h_roll, mr);
                    }
                    for (int q = 0; q < 3; q++) {
                        ti[q] += mr[q];
                        t[j][q] -= mr[q];
                    }
                }
                for (int q = 0; q < 3; q++) {
                    fi[q] += fc[q];
                    f[j][q] -= fc[q];
                }
            }
        }
        for (int q = 0; q < 3; q++) {
            f[i][q] += fi[q];
            t[i][q] += ti[q];
        }
    }
    if (max_overlap > s->max_overlap_seen) s->max_overlap_seen = max_overlap;
}

/* One kernel per combination of models (and periodic or not), listed by the X-macros below;
 * the table is indexed by the case's model ids. */
#define PAIR_KERNEL(N, T, R, C, S, P) \
    static void pair_##N##_##T##_##R##_##C##_##S##_##P(dem_system *s) { pair_loop(s, N, T, R, C, S, P); }
#define PAIR_ENTRY(N, T, R, C, S, P) [N][T][R][C][S][P] = pair_##N##_##T##_##R##_##C##_##S##_##P,
#define FOR_PERIODIC(X, N, T, R, C, S) X(N, T, R, C, S, 0) X(N, T, R, C, S, 1)
#define FOR_SURFACE(X, N, T, R, C) FOR_PERIODIC(X, N, T, R, C, SURFACE_DEFAULT) FOR_PERIODIC(X, N, T, R, C, SURFACE_ROUGHNESS)
#define FOR_COHESION(X, N, T, R) FOR_SURFACE(X, N, T, R, COHESION_NONE) FOR_SURFACE(X, N, T, R, COHESION_SJKR)
#define FOR_ROLLING(X, N, T) FOR_COHESION(X, N, T, ROLLING_NONE) FOR_COHESION(X, N, T, ROLLING_CDT) \
    FOR_COHESION(X, N, T, ROLLING_CDT_JKR) FOR_COHESION(X, N, T, ROLLING_EPSD)
#define FOR_TANGENTIAL(X, N) FOR_ROLLING(X, N, TANGENTIAL_NONE) FOR_ROLLING(X, N, TANGENTIAL_HISTORY)
#define FOR_ALL(X) FOR_TANGENTIAL(X, NORMAL_HOOKE) FOR_TANGENTIAL(X, NORMAL_HERTZ) FOR_TANGENTIAL(X, NORMAL_EDINBURGH)

FOR_ALL(PAIR_KERNEL)

typedef void (*pair_kernel)(dem_system *);
static const pair_kernel kernels[NORMAL_COUNT][TANGENTIAL_COUNT][ROLLING_COUNT][COHESION_COUNT][SURFACE_COUNT][2] = {
    FOR_ALL(PAIR_ENTRY)
};

void pair_forces_add(dem_system *s)
{
    const contact_models *m = &s->models;
    const int periodic = s->periodic[0] || s->periodic[1] || s->periodic[2];
    kernels[m->normal][m->tangential][m->rolling][m->cohesion][m->surface][periodic](s);
}
