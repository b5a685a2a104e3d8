/* Ghost particles by swaps (ghosts.h). */
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "system.h"

void dem_ghosts_free(dem_ghost_list *g)
{
    for (int w = 0; w < 6; w++) free(g->swap[w].send);
    memset(g, 0, sizeof *g);
}

static void push_send(dem_ghost_swap *w, int i)
{
    if (w->nsend == w->send_capacity) {
        w->send_capacity = w->send_capacity ? 2 * w->send_capacity : 1024;
        w->send = dem_realloc(w->send, (size_t)w->send_capacity * sizeof *w->send);
    }
    w->send[w->nsend++] = i;
}

/* One swap's exchange of `roles`: its sent particles packed (the shift added) and unpacked into
 * its ghosts. Every swap here goes to this process itself, so the pack writes straight into the
 * receiving slots (dem_particles_copy_roles: gather_roles then put_roles without the buffer); a
 * swap to another rank will gather into a buffer, send it and put what it receives. */
static void exchange_swap(dem_system *s, const dem_ghost_swap *w, unsigned roles)
{
    dem_particles_copy_roles(&s->p, roles, w->send, w->nsend, w->shift, s->p.n + w->first);
}

void dem_ghosts_build(dem_system *s, double cutoff)
{
    dem_particles *p = &s->p;
    dem_ghost_list *g = &s->ghosts;
    g->n = 0;
    g->nswap = 0;
    for (int d = 0; d < 3; d++) {
        if (!s->periodic[d]) continue;
        const double lo = s->domain_min[d] + cutoff, hi = s->domain_max[d] - cutoff;
        const int count = p->n + g->n;   /* the real particles and the ghosts so far: both swaps of a
                                            direction choose from these, not from each other's ghosts */
        for (int side = -1; side <= 1; side += 2) {
            dem_ghost_swap *w = &g->swap[g->nswap++];
            w->dim = d;
            w->side = side;
            for (int q = 0; q < 3; q++) w->shift[q] = 0.0;
            w->shift[d] = -side * s->period[d];   /* the low side's particles reappear beyond the high side */
            w->nsend = 0;
            for (int i = 0; i < count; i++)
                if (side < 0 ? p->x[i][d] < lo : p->x[i][d] >= hi) push_send(w, i);
            w->first = g->n;
            if (p->n + g->n + w->nsend > p->capacity) dem_particles_reserve(p, 2 * (p->n + g->n + w->nsend) + 1024);
            exchange_swap(s, w, PF_BORDER);
            g->n += w->nsend;
        }
    }
}

void dem_ghosts_update(dem_system *s)
{
    dem_ghost_list *g = &s->ghosts;
    for (int k = 0; k < g->nswap; k++) {   /* in order: a ghost sent on is current before it is sent */
        const dem_ghost_swap *w = &g->swap[k];
        exchange_swap(s, w, PF_FORWARD);
    }
    dem_particles_zero_roles(&s->p, PF_REVERSE, s->p.n, g->n);
}

void dem_ghosts_fold_forces(dem_system *s)
{
    dem_particles *p = &s->p;
    const dem_ghost_list *g = &s->ghosts;
    for (int k = g->nswap - 1; k >= 0; k--) {   /* backwards: a ghost's ghosts are folded onto it first */
        const dem_ghost_swap *w = &g->swap[k];
        /* to itself: take_roles then scatter_add_roles without the buffer */
        dem_particles_fold_roles(p, PF_REVERSE, p->n + w->first, w->nsend, w->send);
    }
}

int dem_ghosts_owner(const dem_system *s, int k)
{
    const dem_ghost_list *g = &s->ghosts;
    int i = s->p.n + k;
    while (i >= s->p.n) {
        const int j = i - s->p.n;
        int w = 0;
        while (w < g->nswap && !(j >= g->swap[w].first && j < g->swap[w].first + g->swap[w].nsend)) w++;
        if (w == g->nswap) return -1;
        i = g->swap[w].send[j - g->swap[w].first];
    }
    return i;
}
