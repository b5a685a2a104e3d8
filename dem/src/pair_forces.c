/* Particle-particle contact forces over the half neighbour list.
 *
 * pair_loop() is written once; it builds each touching pair's contact (geometry and
 * velocities) and hands it to contact_evaluate() (contact/evaluate.h), which the wall loop
 * shares. The short list of common model combinations in evaluate.h runs in specialised kernels
 * (constant model ids: the unused models are compiled out); every other combination runs the
 * generic kernel, which dispatches on the case's model ids per contact. */
#include <math.h>
#include <stddef.h>

#include "contact/evaluate.h"
#include "system.h"

/* Partners of one particle are handled in chunks: a first pass finds the touching ones
 * (branch-free; it clears the history of contacts that just ended), a second computes their
 * forces. That keeps the contact test out of the force code, where its mispredictions cost
 * most. */
#define CHUNK 64

static ALWAYS_INLINE void pair_loop(dem_system *s, const int normal, const int tangential, const int cohesion,
                                    const int rolling, const int surface)
{
    dem_particles *p = &s->p;
    dem_neighbour_list *nl = &s->nlist;
    const dem_vec3 *restrict x = p->x, *restrict v = p->v, *restrict w = p->omega;
    dem_vec3 *restrict f = p->f, *restrict t = p->torque;
    const double *restrict rad = p->radius, *restrict mass = p->mass;
    const int *restrict type = p->type;
    const int64_t *restrict id = p->id;
    const double *restrict inv_inertia = p->inv_inertia;
    const int *restrict start = nl->start, *restrict partner = nl->partner;
    double *restrict hist = nl->history;
    unsigned char *restrict was_touching = nl->touching;
    const int hs = tangential_history_size(tangential) + rolling_history_size(rolling) + normal_history_size(normal) +
                   surface_history_size(surface) + cohesion_history_size(cohesion);   /* = s->history_size */
    const int needs_radius = contact_needs_radius(normal, cohesion, surface);
    const double reach = normal_has_reach(normal) ? s->contact_reach : 0.0;
    const dem_contact_models models_copy = s->models;   /* a local copy: no store in the loop can alias it */
    const dem_contact_models *models = &models_copy;
    const dem_material_table *mt = &s->materials;
    double max_overlap = 0.0;
    int touching[CHUNK];
    double sep[CHUNK][4];   /* separation vector and its square, kept for the force pass */
    const double dt = s->dt;
    const long step = s->step;

    for (int i = 0; i < nl->rows; i++) {
        const double xi = x[i][0], yi = x[i][1], zi = x[i][2], ri = rad[i], mi = mass[i];
        double fi[3] = {0.0, 0.0, 0.0}, ti[3] = {0.0, 0.0, 0.0};
        const dem_pair_coeffs *row = &mt->pair[type[i] * DEM_MAX_TYPES];
        for (int k0 = start[i]; k0 < start[i + 1]; k0 += CHUNK) {
            const int k1 = k0 + CHUNK < start[i + 1] ? k0 + CHUNK : start[i + 1];
            int nc = 0;
            for (int kk = k0; kk < k1; kk++) {
                const int j = partner[kk];
                const double d[3] = {xi - x[j][0], yi - x[j][1], zi - x[j][2]};   /* j may be an image */
                const double radsum = normal_has_reach(normal) ? ri + rad[j] + reach : ri + rad[j];
                const double rsq = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
                const int touch = rsq < radsum * radsum;
                touching[nc] = kk;
                sep[nc][0] = d[0]; sep[nc][1] = d[1]; sep[nc][2] = d[2]; sep[nc][3] = rsq;
                nc += touch;
                if (hs > 0) {   /* a contact that ended forgets */
                    if (was_touching[kk] > touch) {
                        double *h = hist + (size_t)kk * hs;
                        for (int q = 0; q < hs; q++) h[q] = 0.0;
                    }
                    was_touching[kk] = (unsigned char)touch;
                }
            }
            for (int mm = 0; mm < nc; mm++) {
                const int kk = touching[mm], j = partner[kk];
                const double *d = sep[mm], rsq = sep[mm][3];
                const double rj = rad[j], mj = mass[j], radsum = ri + rj;
                const dem_pair_coeffs *c = &row[type[j]];
                dem_contact k;   /* the fields the models need are set below */
                k.dt = dt;
                k.step = step;
                /* one division serves 1/r, R* and m* (divisions dominate this loop's cost) */
                const double r = sqrt(rsq);
                const double q = 1.0 / (r * radsum * (mi + mj));
                const double rinv = q * radsum * (mi + mj);
                k.r_eff = ri * rj * (mi + mj) * r * q;
                k.m_eff = mi * mj * radsum * r * q;
                k.delta = radsum - r;
                const double overlap = k.delta / (ri < rj ? ri : rj);
                max_overlap = overlap > max_overlap ? overlap : max_overlap;

                k.en[0] = d[0] * rinv; k.en[1] = d[1] * rinv; k.en[2] = d[2] * rinv;
                k.lever_i = ri - 0.5 * k.delta;
                k.lever_j = rj - 0.5 * k.delta;
                for (int q3 = 0; q3 < 3; q3++) {
                    k.vr[q3] = v[i][q3] - v[j][q3];
                    k.wi[q3] = w[i][q3];
                    k.wj[q3] = w[j][q3];
                }
                k.a2 = needs_radius ? contact_radius_sq_pair(ri, rj, r) : 0.0;
                if (rolling != rolling_none) {
                    k.rolling_lever = k.r_eff;
                    k.rolling_inertia = rolling_inertia_pair(inv_inertia[i], inv_inertia[j]);
                } else {
                    k.rolling_inertia = 0.0;   /* unread; set for the compiler's view of the generic kernel */
                }
                if (surface != surface_default) {   /* the contact's key: the two ids, lower first */
                    k.sign = id[i] < id[j] ? 1.0 : -1.0;
                    k.key_lo = (uint64_t)(id[i] < id[j] ? id[i] : id[j]);
                    k.key_hi = (uint64_t)(id[i] < id[j] ? id[j] : id[i]);
                }
                if (!contact_evaluate(normal, tangential, cohesion, rolling, surface, models, c, &k,
                                      hist + (size_t)kk * hs, fi, f[j], ti, t[j]))
                    was_touching[kk] = 0;   /* within the reach, but no contact (a JKR neck broke) */
            }
        }
        for (int q = 0; q < 3; q++) {
            f[i][q] += fi[q];
            t[i][q] += ti[q];
        }
    }
    if (max_overlap > s->max_overlap_seen) s->max_overlap_seen = max_overlap;
}

/* One kernel per combination of contact/evaluate.h's SPECIALISED_KERNELS, and the generic one. */
#define PAIR_KERNEL(N, T, C, R, S)                                                                     \
    static void pair_##N##_##T##_##C##_##R##_##S(dem_system *s)                                        \
    {                                                                                                  \
        pair_loop(s, normal_##N, tangential_##T, cohesion_##C, rolling_##R, surface_##S);              \
    }
SPECIALISED_KERNELS(PAIR_KERNEL)

static void pair_generic(dem_system *s)
{
    const dem_contact_models *m = &s->models;
    pair_loop(s, m->normal, m->tangential, m->cohesion, m->rolling, m->surface);
}

#define PAIR_ENTRY(N, T, C, R, S) pair_##N##_##T##_##C##_##R##_##S,
static void (*const kernels[])(dem_system *) = {SPECIALISED_KERNELS(PAIR_ENTRY)};

void dem_pair_forces_add(dem_system *s)
{
    const int q = s->generic_kernels ? -1 : contact_specialised(&s->models);
    if (q >= 0) kernels[q](s);
    else pair_generic(s);
}
