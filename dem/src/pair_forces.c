/* Particle-particle contact forces over the half neighbour list.
 *
 * pair_loop() is written once for all models; each entry of the kernel table calls it with
 * constant model ids, so the compiler builds one loop per combination with the unused models
 * removed. The choice is made once per call, outside the loop. */
#include <math.h>
#include <stddef.h>

#include "contact/normal_hertz.h"
#include "contact/normal_hooke.h"
#include "contact/tangential_history.h"
#include "system.h"

#define ALWAYS_INLINE inline __attribute__((always_inline))

/* Partners of one particle are handled in chunks: a first pass finds the touching ones
 * (branch-free; it clears the history of contacts that just ended), a second computes their
 * forces. That
 * keeps the contact test out of the force code, where its mispredictions cost most. */
#define CHUNK 64

static ALWAYS_INLINE void pair_loop(dem_system *s, const enum normal_model normal,
                                    const enum tangential_model tangential, const int periodic)
{
    particles *p = &s->p;
    neighbour_list *nl = &s->nlist;
    const vec3 *restrict x = p->x, *restrict v = p->v, *restrict w = p->omega;
    vec3 *restrict f = p->f, *restrict t = p->torque;
    const double *restrict rad = p->radius, *restrict mass = p->mass;
    const int *restrict type = p->type;
    const int *restrict start = nl->start, *restrict partner = nl->partner;
    double *restrict hist = nl->history;
    unsigned char *restrict was_touching = nl->touching;
    /* doubles of history per pair, a constant for each kernel (the models' own sizes) */
    const int hs = tangential == TANGENTIAL_HISTORY ? 3 : 0;
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
                if (tangential == TANGENTIAL_HISTORY) {   /* a contact that ended forgets */
                    if (was_touching[k] > touch) {
                        double *h = hist + (size_t)k * hs;
                        h[0] = h[1] = h[2] = 0.0;
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
                const double en[3] = {d[0] * rinv, d[1] * rinv, d[2] * rinv};
                const double delta = radsum - r;
                const double overlap = delta / (ri < rj ? ri : rj);
                max_overlap = overlap > max_overlap ? overlap : max_overlap;

                const double vr[3] = {v[i][0] - v[j][0], v[i][1] - v[j][1], v[i][2] - v[j][2]};
                const double vn = vr[0] * en[0] + vr[1] * en[1] + vr[2] * en[2];

                normal_result n;
                if (normal == NORMAL_HERTZ) n = normal_hertz(c, delta, r_eff, m_eff, vn, fn_floor);
                else n = normal_hooke(c, delta, r_eff, m_eff, vn, v_char, fn_floor);

                double fc[3] = {n.fn * en[0], n.fn * en[1], n.fn * en[2]};
                if (tangential == TANGENTIAL_HISTORY) {
                    /* contact-point velocity: lever arms to the centre of the overlap */
                    const double cri = ri - 0.5 * delta, crj = rj - 0.5 * delta;
                    const double wr[3] = {cri * w[i][0] + crj * w[j][0], cri * w[i][1] + crj * w[j][1],
                                          cri * w[i][2] + crj * w[j][2]};
                    const double vt[3] = {vr[0] - vn * en[0] - (wr[1] * en[2] - wr[2] * en[1]),
                                          vr[1] - vn * en[1] - (wr[2] * en[0] - wr[0] * en[2]),
                                          vr[2] - vn * en[2] - (wr[0] * en[1] - wr[1] * en[0])};
                    double ft[3];
                    tangential_history(hist + (size_t)k * hs, en, vt, n, c->friction, dt, ft);
                    fc[0] += ft[0]; fc[1] += ft[1]; fc[2] += ft[2];
                    /* torque = lever x force, lever -cr en for i and +cr en for j (force -ft) */
                    const double ent[3] = {en[1] * ft[2] - en[2] * ft[1], en[2] * ft[0] - en[0] * ft[2],
                                           en[0] * ft[1] - en[1] * ft[0]};
                    for (int q = 0; q < 3; q++) {
                        ti[q] -= cri * ent[q];
                        t[j][q] -= crj * ent[q];
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

#define KERNEL(NAME, NORMAL, TANGENTIAL, PERIODIC) \
    static void NAME(dem_system *s) { pair_loop(s, NORMAL, TANGENTIAL, PERIODIC); }
KERNEL(hooke_none, NORMAL_HOOKE, TANGENTIAL_NONE, 0)
KERNEL(hooke_history, NORMAL_HOOKE, TANGENTIAL_HISTORY, 0)
KERNEL(hertz_none, NORMAL_HERTZ, TANGENTIAL_NONE, 0)
KERNEL(hertz_history, NORMAL_HERTZ, TANGENTIAL_HISTORY, 0)
KERNEL(hooke_none_periodic, NORMAL_HOOKE, TANGENTIAL_NONE, 1)
KERNEL(hooke_history_periodic, NORMAL_HOOKE, TANGENTIAL_HISTORY, 1)
KERNEL(hertz_none_periodic, NORMAL_HERTZ, TANGENTIAL_NONE, 1)
KERNEL(hertz_history_periodic, NORMAL_HERTZ, TANGENTIAL_HISTORY, 1)

typedef void (*pair_kernel)(dem_system *);
static const pair_kernel kernels[2][NORMAL_COUNT][TANGENTIAL_COUNT] = {
    {{hooke_none, hooke_history}, {hertz_none, hertz_history}},
    {{hooke_none_periodic, hooke_history_periodic}, {hertz_none_periodic, hertz_history_periodic}},
};

void pair_forces_add(dem_system *s)
{
    const int periodic = s->periodic[0] || s->periodic[1] || s->periodic[2];
    kernels[periodic][s->models.normal][s->models.tangential](s);
}
