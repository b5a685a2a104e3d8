/* Particle-wall contact forces. Each wall keeps a candidate list of the particles within
 * radius + skin of it, refreshed with the neighbour list; the force loop visits only those. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "contact/normal_force.h"
#include "contact/rolling_cdt.h"
#include "contact/rolling_cdt_jkr.h"
#include "contact/rolling_epsd.h"
#include "contact/surface_roughness.h"
#include "contact/tangential_history.h"
#include "error.h"
#include "system.h"

#define ALWAYS_INLINE inline __attribute__((always_inline))

int wall_gap(const wall *w, const double x[3], double radius, double *gap, double en[3])
{
    if (w->kind == WALL_PLANE) {
        const double dist = (x[0] - w->point[0]) * w->normal[0] + (x[1] - w->point[1]) * w->normal[1] +
                            (x[2] - w->point[2]) * w->normal[2];
        if (w->bounded) {
            for (int d = 0; d < 3; d++) {
                const double proj = x[d] - dist * w->normal[d];
                if (proj < w->bounds_min[d] || proj > w->bounds_max[d]) return 0;
            }
        }
        *gap = dist - radius;
        en[0] = w->normal[0]; en[1] = w->normal[1]; en[2] = w->normal[2];
        return 1;
    }
    /* cylinder */
    const int a = w->axis, b = (a + 1) % 3, c = (a + 2) % 3;
    if (x[a] < w->axial_min || x[a] > w->axial_max) return 0;
    const double db = x[b] - w->centre[0], dc = x[c] - w->centre[1];
    const double rho = sqrt(db * db + dc * dc);
    if (rho == 0.0) {               /* on the axis: no defined normal, and far from the wall */
        *gap = w->inside ? w->radius - radius : -w->radius - radius;
        en[0] = en[1] = en[2] = 0.0;
        en[b] = w->inside ? -1.0 : 1.0;
        return 1;
    }
    const double sign = w->inside ? -1.0 : 1.0;   /* normal from the wall towards the centre */
    en[a] = 0.0;
    en[b] = sign * db / rho;
    en[c] = sign * dc / rho;
    *gap = (w->inside ? w->radius - rho : rho - w->radius) - radius;
    return 1;
}

/* Refresh the candidate lists (called after each neighbour-list build). */
void walls_build_candidates(dem_system *s)
{
    const particles *p = &s->p;
    for (int k = 0; k < s->nwalls; k++) {
        s->wall_candidates[k] = dem_realloc(s->wall_candidates[k], (size_t)(p->n ? p->n : 1) * sizeof(int));
        int count = 0;
        for (int i = 0; i < p->n; i++) {
            double gap, en[3];
            /* bounded walls: test with the bounds widened by the skin, cheaply, by testing the
             * position itself and letting the force loop decide the exact bounds */
            wall probe = s->walls[k];
            if (probe.bounded)
                for (int d = 0; d < 3; d++) {
                    probe.bounds_min[d] -= s->nlist.skin;
                    probe.bounds_max[d] += s->nlist.skin;
                }
            if (probe.kind == WALL_CYLINDER) {
                probe.axial_min -= s->nlist.skin;
                probe.axial_max += s->nlist.skin;
            }
            if (wall_gap(&probe, p->x[i], p->radius[i], &gap, en) && gap < s->nlist.skin)
                s->wall_candidates[k][count++] = i;
            else if (s->history_size > 0)
                memset(s->wall_history + ((size_t)i * s->nwalls + k) * s->history_size, 0,
                       (size_t)s->history_size * sizeof(double));
        }
        s->wall_ncandidates[k] = count;
    }
}

/* Wall contacts see the wall as a sphere of infinite radius and mass: R* = R_i, m* = m_i,
 * omega_j = 0. The models are those of pair_forces.c, with the same history layout. */
static ALWAYS_INLINE void wall_loop(dem_system *s, const enum normal_model normal,
                                    const enum tangential_model tangential,
                                    const enum rolling_model rolling, const enum cohesion_model cohesion,
                                    const enum surface_model surface)
{
    particles *p = &s->p;
    const int hs = s->history_size;
    const int h_roll = tangential_history_size(tangential), h_norm = h_roll + rolling_history_size(rolling);
    const int h_surf = h_norm + normal_history_size(normal);
    const double dt = s->dt, v_char = s->models.characteristic_velocity, fn_floor = s->models.fn_floor;
    const int torsion_torque = s->models.torsion_torque;
    double max_overlap = 0.0;
    double fw[3] = {0.0, 0.0, 0.0};   /* the walls' total force on the particles */
    for (int k = 0; k < s->nwalls; k++) {
        const wall *wl = &s->walls[k];
        const int *cand = s->wall_candidates[k];
        for (int m = 0; m < s->wall_ncandidates[k]; m++) {
            const int i = cand[m];
            double *h = s->wall_history + ((size_t)i * s->nwalls + k) * hs;
            double gap, en[3];
            if (!wall_gap(wl, p->x[i], p->radius[i], &gap, en) || gap >= 0.0) {
                for (int q = 0; q < hs; q++) h[q] = 0.0;
                continue;
            }
            const double delta = -gap, ri = p->radius[i], mi = p->mass[i];
            const pair_coeffs *c = materials_pair(&s->materials, p->type[i], wl->material);
            max_overlap = fmax(max_overlap, delta / ri);
            double *vi = p->v[i];
            double en_f[3] = {en[0], en[1], en[2]};
            double contact_radius_sq = 0.0;
            if (normal == NORMAL_EDINBURGH || cohesion == COHESION_SJKR || surface == SURFACE_ROUGHNESS)
                contact_radius_sq = contact_radius_sq_wall(ri, delta);
            if (surface == SURFACE_ROUGHNESS) {   /* keyed on (wall, particle id) */
                const double *wi = p->omega[i], cr = ri - 0.5 * delta;
                const double wr[3] = {cr * wi[0], cr * wi[1], cr * wi[2]};
                const double vin = vi[0] * en[0] + vi[1] * en[1] + vi[2] * en[2];
                double vs[3];   /* sliding velocity on the true tangent plane */
                contact_tangential_velocity(vi, vin, en, wr, en, vs);
                roughness_update(&s->models.roughness, ~(uint64_t)k, (uint64_t)p->id[i], s->step, en,
                                 sqrt(contact_radius_sq), sqrt(vs[0] * vs[0] + vs[1] * vs[1] + vs[2] * vs[2]),
                                 dt, h + h_surf);
                roughness_normal(h + h_surf, en, 1.0, en_f);
            }
            const double vn = vi[0] * en_f[0] + vi[1] * en_f[1] + vi[2] * en_f[2];
            double fn;
            const normal_result n = contact_normal(normal, cohesion, c, delta, ri, mi, vn, v_char, fn_floor,
                                                   contact_radius_sq, h + h_norm, &fn);
            double fc[3] = {fn * en_f[0], fn * en_f[1], fn * en_f[2]};
            const double *wi = p->omega[i];
            const double cr = ri - 0.5 * delta;
            if (tangential == TANGENTIAL_HISTORY) {
                const double wr[3] = {cr * wi[0], cr * wi[1], cr * wi[2]};
                double vt[3], ft[3];
                contact_tangential_velocity(vi, vn, en_f, wr, en, vt);
                tangential_history(h, en_f, vt, n, c->friction, dt, ft);
                fc[0] += ft[0]; fc[1] += ft[1]; fc[2] += ft[2];
                p->torque[i][0] -= cr * (en[1] * ft[2] - en[2] * ft[1]);
                p->torque[i][1] -= cr * (en[2] * ft[0] - en[0] * ft[2]);
                p->torque[i][2] -= cr * (en[0] * ft[1] - en[1] * ft[0]);
            }
            if (rolling != ROLLING_NONE) {
                double mr[3];
                if (rolling == ROLLING_CDT) rolling_cdt(c, en, wi, n, cr, mr);   /* lever R_i - delta/2, as LIGGGHTS */
                else if (rolling == ROLLING_CDT_JKR)
                    rolling_cdt_jkr(c, en, wi, n, ri, dt, torsion_torque, h + h_roll, mr);
                else rolling_epsd(c, en, wi, n, ri, 3.5 / p->inv_inertia[i], dt, h + h_roll, mr);
                for (int q = 0; q < 3; q++) p->torque[i][q] += mr[q];
            }
            if (surface == SURFACE_ROUGHNESS) {   /* eq. 17: the rough contact fails to hold it */
                const double v_plane = vi[0] * en[0] + vi[1] * en[1] + vi[2] * en[2];
                if (v_plane < 0.0 && fc[0] * en[0] + fc[1] * en[1] + fc[2] * en[2] <= 0.0)
                    for (int q = 0; q < 3; q++) vi[q] -= 2.0 * v_plane * en[q];
            }
            p->f[i][0] += fc[0]; p->f[i][1] += fc[1]; p->f[i][2] += fc[2];
            fw[0] += fc[0]; fw[1] += fc[1]; fw[2] += fc[2];
        }
    }
    s->max_overlap_seen = fmax(s->max_overlap_seen, max_overlap);
    s->wall_force[0] = fw[0]; s->wall_force[1] = fw[1]; s->wall_force[2] = fw[2];
}

#define WALL_KERNEL(N, T, R, C, S) \
    static void wall_##N##_##T##_##R##_##C##_##S(dem_system *s) { wall_loop(s, N, T, R, C, S); }
#define WALL_ENTRY(N, T, R, C, S) [N][T][R][C][S] = wall_##N##_##T##_##R##_##C##_##S,
#define FOR_SURFACE(X, N, T, R, C) X(N, T, R, C, SURFACE_DEFAULT) X(N, T, R, C, SURFACE_ROUGHNESS)
#define FOR_COHESION(X, N, T, R) FOR_SURFACE(X, N, T, R, COHESION_NONE) FOR_SURFACE(X, N, T, R, COHESION_SJKR)
#define FOR_ROLLING(X, N, T) FOR_COHESION(X, N, T, ROLLING_NONE) FOR_COHESION(X, N, T, ROLLING_CDT) \
    FOR_COHESION(X, N, T, ROLLING_CDT_JKR) FOR_COHESION(X, N, T, ROLLING_EPSD)
#define FOR_TANGENTIAL(X, N) FOR_ROLLING(X, N, TANGENTIAL_NONE) FOR_ROLLING(X, N, TANGENTIAL_HISTORY)
#define FOR_ALL(X) FOR_TANGENTIAL(X, NORMAL_HOOKE) FOR_TANGENTIAL(X, NORMAL_HERTZ) FOR_TANGENTIAL(X, NORMAL_EDINBURGH)

FOR_ALL(WALL_KERNEL)

typedef void (*wall_kernel)(dem_system *);
static const wall_kernel kernels[NORMAL_COUNT][TANGENTIAL_COUNT][ROLLING_COUNT][COHESION_COUNT][SURFACE_COUNT] = {
    FOR_ALL(WALL_ENTRY)
};

void walls_add_forces(dem_system *s)
{
    const contact_models *m = &s->models;
    kernels[m->normal][m->tangential][m->rolling][m->cohesion][m->surface](s);
}
