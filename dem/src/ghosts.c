/* Ghost particles by swaps (ghosts.h). */
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "system.h"

void dem_ghosts_free(dem_ghost_list *g)
{
    for (int w = 0; w < 6; w++) free(g->swap[w].send);
    free(g->buffer);
    memset(g, 0, sizeof *g);
}

static char *buffer_for(dem_ghost_list *g, int count, size_t bytes_each)
{
    const size_t need = (size_t)count * bytes_each;
    if (need > g->buffer_capacity) {
        g->buffer_capacity = 2 * need + 4096;
        g->buffer = dem_realloc(g->buffer, g->buffer_capacity);
    }
    return g->buffer;
}

static void push_send(dem_ghost_swap *w, int i)
{
    if (w->nsend == w->send_capacity) {
        w->send_capacity = w->send_capacity ? 2 * w->send_capacity : 1024;
        w->send = dem_realloc(w->send, (size_t)w->send_capacity * sizeof *w->send);
    }
    w->send[w->nsend++] = i;
}

/* Pack `roles` of the swap's sent particles into the buffer (returns it). */
static const char *pack_swap(dem_system *s, const dem_ghost_swap *w, unsigned roles, size_t each)
{
    char *buf = buffer_for(&s->ghosts, w->nsend, each);
    for (int m = 0; m < w->nsend; m++) dem_particles_pack_roles(&s->p, roles, w->send[m], w->shift, buf + (size_t)m * each);
    return buf;   /* serial: what this process sends to itself is what it receives */
}

/* The swap's ghosts from the received buffer. */
static void unpack_swap(dem_system *s, const dem_ghost_swap *w, unsigned roles, size_t each, const char *buf)
{
    for (int m = 0; m < w->nsend; m++) dem_particles_unpack_roles(&s->p, roles, s->p.n + w->first + m, buf + (size_t)m * each);
}

void dem_ghosts_build(dem_system *s, double cutoff)
{
    dem_particles *p = &s->p;
    dem_ghost_list *g = &s->ghosts;
    g->n = 0;
    g->nswap = 0;
    const size_t each = dem_particles_role_size(PF_BORDER);
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
            unpack_swap(s, w, PF_BORDER, each, pack_swap(s, w, PF_BORDER, each));
            g->n += w->nsend;
        }
    }
}

void dem_ghosts_update(dem_system *s)
{
    dem_ghost_list *g = &s->ghosts;
    const size_t each = dem_particles_role_size(PF_FORWARD);
    for (int k = 0; k < g->nswap; k++) {   /* in order: a ghost sent on is current before it is sent */
        const dem_ghost_swap *w = &g->swap[k];
        unpack_swap(s, w, PF_FORWARD, each, pack_swap(s, w, PF_FORWARD, each));
    }
    dem_particles_zero_roles(&s->p, PF_REVERSE, s->p.n, g->n);
}

void dem_ghosts_fold_forces(dem_system *s)
{
    dem_particles *p = &s->p;
    dem_ghost_list *g = &s->ghosts;
    const size_t each = dem_particles_role_size(PF_REVERSE);
    for (int k = g->nswap - 1; k >= 0; k--) {   /* backwards: a ghost's ghosts are folded onto it first */
        const dem_ghost_swap *w = &g->swap[k];
        char *buf = buffer_for(g, w->nsend, each);
        for (int m = 0; m < w->nsend; m++) dem_particles_pack_roles(p, PF_REVERSE, p->n + w->first + m, NULL, buf + (size_t)m * each);
        for (int m = 0; m < w->nsend; m++) dem_particles_unpack_add_roles(p, PF_REVERSE, w->send[m], buf + (size_t)m * each);
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
