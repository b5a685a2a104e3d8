/* Periodic images (ghosts.h). */
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "system.h"

void dem_ghosts_free(dem_ghost_list *g)
{
    free(g->owner);
    free(g->shift);
    memset(g, 0, sizeof *g);
}

/* A copy of particle src (real or ghost) shifted by `shift` along direction d. */
static void add_image(dem_system *s, int src, int d, double shift)
{
    dem_particles *p = &s->p;
    dem_ghost_list *g = &s->ghosts;
    if (g->n == g->capacity) {
        g->capacity = g->capacity ? 2 * g->capacity : 1024;
        g->owner = dem_realloc(g->owner, (size_t)g->capacity * sizeof *g->owner);
        g->shift = dem_realloc(g->shift, (size_t)g->capacity * sizeof *g->shift);
    }
    if (p->n + g->n >= p->capacity) dem_particles_reserve(p, 2 * (p->n + g->n) + 1024);
    const int k = g->n++, dst = p->n + k;
    const int from_ghost = src >= p->n;
    g->owner[k] = from_ghost ? g->owner[src - p->n] : src;
    for (int q = 0; q < 3; q++) g->shift[k][q] = from_ghost ? g->shift[src - p->n][q] : 0.0;
    g->shift[k][d] += shift;
    dem_particles_copy(p, src, dst);
    p->x[dst][d] += shift;
}

void dem_ghosts_build(dem_system *s, double cutoff)
{
    const dem_particles *p = &s->p;
    s->ghosts.n = 0;
    for (int d = 0; d < 3; d++) {
        if (!s->periodic[d]) continue;
        const double lo = s->domain_min[d] + cutoff, hi = s->domain_max[d] - cutoff, period = s->period[d];
        const int count = p->n + s->ghosts.n;   /* the real particles and the images so far */
        for (int i = 0; i < count; i++) {
            if (p->x[i][d] < lo) add_image(s, i, d, period);
            else if (p->x[i][d] >= hi) add_image(s, i, d, -period);
        }
    }
}

void dem_ghosts_update(dem_system *s)
{
    dem_particles *p = &s->p;
    const dem_ghost_list *g = &s->ghosts;
    for (int k = 0; k < g->n; k++) {
        const int i = p->n + k, o = g->owner[k];
        for (int q = 0; q < 3; q++) {
            p->x[i][q] = p->x[o][q] + g->shift[k][q];
            p->v[i][q] = p->v[o][q];
            p->omega[i][q] = p->omega[o][q];
            p->f[i][q] = 0.0;
            p->torque[i][q] = 0.0;
        }
    }
}

void dem_ghosts_fold_forces(dem_system *s)
{
    dem_particles *p = &s->p;
    const dem_ghost_list *g = &s->ghosts;
    for (int k = 0; k < g->n; k++) {
        const int i = p->n + k, o = g->owner[k];
        for (int q = 0; q < 3; q++) {
            p->f[o][q] += p->f[i][q];
            p->torque[o][q] += p->torque[i][q];
        }
    }
}
