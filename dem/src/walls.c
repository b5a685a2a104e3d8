/* Particle-wall contact forces. Each wall keeps a candidate list of the particles within
 * radius + skin of it, refreshed with the neighbour list; the force loop visits only those. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "contact/evaluate.h"
#include "error.h"
#include "system.h"

int dem_wall_gap(const dem_wall *w, const double x[3], double radius, double *gap, double en[3])
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

void dem_wall_set_velocity(dem_wall *w, const double velocity[3])
{
    for (int d = 0; d < 3; d++) {
        w->velocity[d] = velocity[d];
        w->point0[d] = w->point[d];
        w->bounds0_min[d] = w->bounds_min[d];
        w->bounds0_max[d] = w->bounds_max[d];
    }
}

static int translates(const dem_wall *w)
{
    return w->kind == WALL_PLANE && (w->velocity[0] != 0.0 || w->velocity[1] != 0.0 || w->velocity[2] != 0.0);
}

int dem_walls_move(dem_system *s, double t)
{
    const double limit = 0.25 * s->nlist.skin * s->nlist.skin;
    int far = 0;
    for (int k = 0; k < s->nwalls; k++) {
        dem_wall *w = &s->walls[k];
        if (!translates(w)) continue;
        double moved = 0.0;
        for (int d = 0; d < 3; d++) {
            const double shift = w->velocity[d] * t;
            w->point[d] = w->point0[d] + shift;
            w->bounds_min[d] = w->bounds0_min[d] + shift;
            w->bounds_max[d] = w->bounds0_max[d] + shift;
            moved += (w->point[d] - w->point_at_build[d]) * (w->point[d] - w->point_at_build[d]);
        }
        far |= moved > limit;
    }
    return far;
}

void dem_wall_surface_velocity(const dem_wall *w, const double xc[3], double u[3])
{
    if (w->kind == WALL_PLANE) {
        for (int d = 0; d < 3; d++) u[d] = w->velocity[d];
        return;
    }
    const int a = w->axis, b = (a + 1) % 3, c = (a + 2) % 3;   /* omega e_a x (xc - axis) */
    u[a] = 0.0;
    u[b] = -w->angular_velocity * (xc[c] - w->centre[1]);
    u[c] = w->angular_velocity * (xc[b] - w->centre[0]);
}

dem_wall *dem_walls_add(dem_system *s)
{
    if (s->nwalls == s->wall_capacity) {
        s->wall_capacity = s->wall_capacity ? 2 * s->wall_capacity : 8;
        s->walls = dem_realloc(s->walls, (size_t)s->wall_capacity * sizeof *s->walls);
        s->wall_lists = dem_realloc(s->wall_lists, (size_t)s->wall_capacity * sizeof *s->wall_lists);
    }
    memset(&s->walls[s->nwalls], 0, sizeof *s->walls);
    memset(&s->wall_lists[s->nwalls], 0, sizeof *s->wall_lists);
    return &s->walls[s->nwalls++];
}

void dem_walls_free(dem_system *s)
{
    for (int k = 0; k < s->nwalls; k++) {
        free(s->wall_lists[k].particle);
        free(s->wall_lists[k].history);
        free(s->wall_lists[k].touching);
    }
    free(s->walls);
    free(s->wall_lists);
    s->walls = NULL;
    s->wall_lists = NULL;
    s->nwalls = s->wall_capacity = 0;
}

/* Refresh the candidate lists (called after each neighbour-list build): real particles only. */
void dem_walls_build_candidates(dem_system *s)
{
    const dem_particles *p = &s->p;
    const int hs = s->history_size;
    const double range = s->nlist.skin + s->contact_reach;
    for (int k = 0; k < s->nwalls; k++) {
        dem_wall_contacts *wc = &s->wall_lists[k];
        for (int d = 0; d < 3; d++) s->walls[k].point_at_build[d] = s->walls[k].point[d];
        /* bounded walls: test with the bounds widened by the range, cheaply, by testing the
         * position itself and letting the force loop decide the exact bounds */
        dem_wall probe = s->walls[k];
        if (probe.bounded)
            for (int d = 0; d < 3; d++) {
                probe.bounds_min[d] -= range;
                probe.bounds_max[d] += range;
            }
        if (probe.kind == WALL_CYLINDER) {
            probe.axial_min -= range;
            probe.axial_max += range;
        }
        wc->n = 0;
        for (int i = 0; i < p->n; i++) {
            double gap, en[3];
            if (!dem_wall_gap(&probe, p->x[i], p->radius[i], &gap, en) || gap >= range) continue;
            if (wc->n == wc->capacity) {
                wc->capacity = wc->capacity ? 2 * wc->capacity : 256;
                wc->particle = dem_realloc(wc->particle, (size_t)wc->capacity * sizeof(int));
                wc->history = dem_realloc(wc->history, (size_t)wc->capacity * (hs ? hs : 1) * sizeof(double));
                wc->touching = dem_realloc(wc->touching, (size_t)wc->capacity);
            }
            wc->particle[wc->n] = i;
            memset(wc->history + (size_t)wc->n * hs, 0, (size_t)hs * sizeof(double));
            wc->touching[wc->n] = 0;
            wc->n++;
        }
    }
}

/* Wall contacts see the wall as a sphere of infinite radius and mass: R* = R_i, m* = m_i; its
 * surface velocity at the contact point is subtracted from the particle's (a moving wall), and a
 * turning cylinder's angular velocity is omega_j (for the rolling models; its lever is 0); the
 * contact is evaluated as a pair's (contact/evaluate.h), with the same history layout. */
static ALWAYS_INLINE void wall_loop(dem_system *s, const int normal, const int tangential, const int cohesion,
                                    const int rolling, const int surface)
{
    dem_particles *p = &s->p;
    const int hs = s->history_size;
    const int needs_radius = contact_needs_radius(normal, cohesion, surface);
    const double reach = normal_has_reach(normal) ? s->contact_reach : 0.0;
    const double dt = s->dt;
    const long step = s->step;
    double max_overlap = 0.0;
    double fw[3] = {0.0, 0.0, 0.0};   /* the walls' total force on the particles */
    for (int q = 0; q < s->nwalls; q++) {
        const dem_wall *wl = &s->walls[q];
        dem_wall_contacts *wc = &s->wall_lists[q];
        const int moving = translates(wl) || (wl->kind == WALL_CYLINDER && wl->angular_velocity != 0.0);
        double fq[3] = {0.0, 0.0, 0.0};   /* this wall's */
        for (int m = 0; m < wc->n; m++) {
            const int i = wc->particle[m];
            double *h = wc->history + (size_t)m * hs;
            dem_contact k = {.dt = dt, .step = step};
            double gap;
            if (!dem_wall_gap(wl, p->x[i], p->radius[i], &gap, k.en) || gap >= reach) {
                for (int c = 0; c < hs; c++) h[c] = 0.0;
                wc->touching[m] = 0;
                continue;
            }
            const double ri = p->radius[i];
            const dem_pair_coeffs *c = materials_pair(&s->materials, p->type[i], wl->material);
            k.delta = -gap;
            k.r_eff = ri;
            k.m_eff = p->mass[i];
            max_overlap = fmax(max_overlap, k.delta / ri);
            k.lever_i = ri - 0.5 * k.delta;
            k.lever_j = 0.0;
            for (int d = 0; d < 3; d++) {
                k.vr[d] = p->v[i][d];
                k.wi[d] = p->omega[i][d];
                k.wj[d] = 0.0;
            }
            if (moving) {
                double xc[3], u[3];
                for (int d = 0; d < 3; d++) xc[d] = p->x[i][d] - k.lever_i * k.en[d];   /* contact point */
                dem_wall_surface_velocity(wl, xc, u);
                for (int d = 0; d < 3; d++) k.vr[d] -= u[d];
                if (wl->kind == WALL_CYLINDER) k.wj[wl->axis] = wl->angular_velocity;
            }
            k.a2 = needs_radius ? contact_radius_sq_wall(ri, k.delta) : 0.0;
            if (rolling != rolling_none) {
                k.rolling_lever = k.lever_i;                    /* as LIGGGHTS' cdt at a wall */
                k.rolling_inertia = rolling_inertia_pair(p->inv_inertia[i], 0.0);   /* the wall does not turn */
            }
            if (surface != surface_default) {   /* keyed on (wall, particle id) */
                k.sign = 1.0;
                k.key_lo = ~(uint64_t)q;
                k.key_hi = (uint64_t)p->id[i];
            }
            double fc[3] = {0.0, 0.0, 0.0}, f_wall[3] = {0.0, 0.0, 0.0}, t_wall[3] = {0.0, 0.0, 0.0};   /* the wall's share: unused */
            wc->touching[m] = (unsigned char)contact_evaluate(normal, tangential, cohesion, rolling, surface,
                                                              &s->models, c, &k, h, fc, f_wall, p->torque[i], t_wall);
            if (!wc->touching[m]) continue;
            if (surface != surface_default) surface_wall_guard(surface, &s->models, k.en, fc, p->v[i]);
            for (int d = 0; d < 3; d++) {
                p->f[i][d] += fc[d];
                fq[d] += fc[d];
            }
        }
        for (int d = 0; d < 3; d++) {
            wc->force[d] = fq[d];
            fw[d] += fq[d];
        }
    }
    s->max_overlap_seen = fmax(s->max_overlap_seen, max_overlap);
    s->wall_force[0] = fw[0]; s->wall_force[1] = fw[1]; s->wall_force[2] = fw[2];
}

/* One kernel per combination of contact/evaluate.h's SPECIALISED_KERNELS, and the generic one. */
#define WALL_KERNEL(N, T, C, R, S)                                                                     \
    static void wall_##N##_##T##_##C##_##R##_##S(dem_system *s)                                        \
    {                                                                                                  \
        wall_loop(s, normal_##N, tangential_##T, cohesion_##C, rolling_##R, surface_##S);              \
    }
SPECIALISED_KERNELS(WALL_KERNEL)

static void wall_generic(dem_system *s)
{
    const dem_contact_models *m = &s->models;
    wall_loop(s, m->normal, m->tangential, m->cohesion, m->rolling, m->surface);
}

#define WALL_ENTRY(N, T, C, R, S) wall_##N##_##T##_##C##_##R##_##S,
static void (*const kernels[])(dem_system *) = {SPECIALISED_KERNELS(WALL_ENTRY)};

void dem_walls_add_forces(dem_system *s)
{
    const int q = s->generic_kernels ? -1 : contact_specialised(&s->models);
    if (q >= 0) kernels[q](s);
    else wall_generic(s);
}
