/* Ghost particles by swaps to (rank, image) (ghosts.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "comm.h"
#include "error.h"
#include "reduce.h"
#include "system.h"

enum { IMAGES = 27, SELF_IMAGE = 13 };   /* image 13: no period added */

void dem_ghosts_free(dem_ghost_list *g)
{
    for (int w = 0; w < g->swap_capacity; w++) {
        free(g->swap[w].send);
        free(g->swap[w].shift);
    }
    free(g->swap);
    free(g->send_count); free(g->recv_count); free(g->recv_first);
    free(g->send_bytes); free(g->send_offset); free(g->recv_bytes); free(g->recv_offset);
    free(g->count_out); free(g->count_in);
    free(g->send_buf); free(g->recv_buf);
    free(g->pick_key); free(g->pick_index); free(g->key_count);
    memset(g, 0, sizeof *g);
}

static void size_rank_arrays(dem_ghost_list *g, int nranks)
{
    if (g->nranks == nranks && g->send_count) return;
    g->nranks = nranks;
    const size_t n = (size_t)nranks;
    g->send_count = dem_realloc(g->send_count, n * sizeof(int));
    g->recv_count = dem_realloc(g->recv_count, n * sizeof(int));
    g->recv_first = dem_realloc(g->recv_first, n * sizeof(int));
    g->send_bytes = dem_realloc(g->send_bytes, n * sizeof(size_t));
    g->send_offset = dem_realloc(g->send_offset, n * sizeof(size_t));
    g->recv_bytes = dem_realloc(g->recv_bytes, n * sizeof(size_t));
    g->recv_offset = dem_realloc(g->recv_offset, n * sizeof(size_t));
    g->count_out = dem_realloc(g->count_out, n * sizeof(int64_t));
    g->count_in = dem_realloc(g->count_in, n * sizeof(int64_t));
}

static void *reserve_bytes(unsigned char **buf, size_t *capacity, size_t bytes)
{
    if (bytes > *capacity) {
        *capacity = bytes + bytes / 4 + 4096;
        *buf = dem_realloc(*buf, *capacity);
    }
    return *buf;
}

static void push_pick(dem_ghost_list *g, long *n, int key, int i)
{
    if (*n == g->pick_capacity) {
        g->pick_capacity = g->pick_capacity ? 2 * g->pick_capacity : 4096;
        g->pick_key = dem_realloc(g->pick_key, (size_t)g->pick_capacity * sizeof(int));
        g->pick_index = dem_realloc(g->pick_index, (size_t)g->pick_capacity * sizeof(int));
    }
    g->pick_key[*n] = key;
    g->pick_index[*n] = i;
    (*n)++;
}

/* Part b's box as the halo sees it: a side on a closed face of the domain reaches to infinity
 * (particles may lie up to a radius beyond it, and the owner takes them: decompose.h). */
static void halo_box(const dem_system *s, int b, double lo[3], double hi[3])
{
    for (int k = 0; k < 3; k++) {
        lo[k] = s->decomp.lo[b][k];
        hi[k] = s->decomp.hi[b][k];
        if (!s->periodic[k]) {
            if (lo[k] <= s->domain_min[k]) lo[k] = -INFINITY;
            if (hi[k] >= s->domain_max[k]) hi[k] = INFINITY;
        }
    }
}

static double distance2(const double lo[3], const double hi[3], const double y[3])
{
    double d2 = 0.0;
    for (int k = 0; k < 3; k++) {
        const double e = y[k] < lo[k] ? lo[k] - y[k] : y[k] > hi[k] ? y[k] - hi[k] : 0.0;
        d2 += e * e;
    }
    return d2;
}

/* The squared gap between two boxes (0 when they touch or overlap) */
static double gap2(const double alo[3], const double ahi[3], const double blo[3], const double bhi[3])
{
    double d2 = 0.0;
    for (int k = 0; k < 3; k++) {
        const double e = fmax(0.0, fmax(blo[k] - ahi[k], alo[k] - bhi[k]));
        d2 += e * e;
    }
    return d2;
}

/* With multisphere bodies a rank holds its bodies' spheres wherever they lie (bodies.h), some
 * outside its box: each rank's box grows to hold its bodies' spheres (every rank's bounds through
 * one reduction), so that a particle within the cutoff of such a sphere is sent to its rank.
 * Returns the other ranks whose boxes grew (malloc'd, *n of them). */
static int *grow_to_bodies(const dem_system *s, double (*lo)[3], double (*hi)[3], int *n)
{
    const int nparts = s->decomp.nparts, me = dem_comm_rank();
    double *bounds = dem_malloc((size_t)(6 * nparts) * sizeof(double));   /* per rank: -lo, hi */
    for (int k = 0; k < 6 * nparts; k++) bounds[k] = -INFINITY;
    double *mine = bounds + 6 * me;
    for (int i = 0; i < s->p.n; i++)
        if (s->p.body[i])
            for (int d = 0; d < 3; d++) {
                mine[d] = fmax(mine[d], -s->p.x[i][d]);
                mine[3 + d] = fmax(mine[3 + d], s->p.x[i][d]);
            }
    dem_reduce_doubles(bounds, 6 * nparts, DEM_REDUCE_MAX);
    int *intruders = dem_malloc((size_t)nparts * sizeof(int));
    *n = 0;
    for (int b = 0; b < nparts; b++) {
        int grew = 0;
        for (int d = 0; d < 3; d++) {
            grew |= -bounds[6 * b + d] < lo[b][d] || bounds[6 * b + 3 + d] > hi[b][d];
            lo[b][d] = fmin(lo[b][d], -bounds[6 * b + d]);
            hi[b][d] = fmax(hi[b][d], bounds[6 * b + 3 + d]);
        }
        if (grew && b != me) intruders[(*n)++] = b;
    }
    free(bounds);
    return intruders;
}

/* Which (rank, image) each real particle goes to, as (key = rank * 27 + image, index) picks. lo, hi:
 * each rank's box as the halo sees it; own_lo, own_hi: this rank's box before it grew to its
 * bodies. A particle deeper than the cutoff in its own box goes only to the ranks whose boxes
 * grew into it (the intruders: none without bodies). */
static long pick(dem_system *s, double cutoff, double (*lo)[3], double (*hi)[3], const double own_lo[3],
                 const double own_hi[3], const int *intruders, int nintruders)
{
    dem_ghost_list *g = &s->ghosts;
    const dem_particles *p = &s->p;
    const int me = dem_comm_rank(), nparts = s->decomp.nparts;
    const double c2 = cutoff * cutoff;
    long npick = 0;
    for (int i = 0; i < p->n; i++) {
        const double *x = p->x[i];
        /* most particles are deeper than the cutoff in this rank's box: nothing to send, but to a
         * rank whose bodies reach in */
        if (x[0] - own_lo[0] >= cutoff && own_hi[0] - x[0] > cutoff && x[1] - own_lo[1] >= cutoff &&
            own_hi[1] - x[1] > cutoff && x[2] - own_lo[2] >= cutoff && own_hi[2] - x[2] > cutoff) {
            for (int k = 0; k < nintruders; k++)
                if (distance2(lo[intruders[k]], hi[intruders[k]], x) < c2)
                    push_pick(g, &npick, intruders[k] * IMAGES + SELF_IMAGE, i);
            continue;
        }
        int from[3], to[3];   /* the periods to add in each direction */
        for (int k = 0; k < 3; k++) {
            from[k] = to[k] = 0;
            if (!s->periodic[k]) continue;
            if (x[k] < s->domain_min[k] + cutoff) to[k] = 1;      /* near the low side: beyond the high one */
            if (x[k] >= s->domain_max[k] - cutoff) from[k] = -1;
        }
        for (int iz = from[2]; iz <= to[2]; iz++)
            for (int iy = from[1]; iy <= to[1]; iy++)
                for (int ix = from[0]; ix <= to[0]; ix++) {
                    const int image = (ix + 1) + 3 * (iy + 1) + 9 * (iz + 1);
                    const double y[3] = {x[0] + ix * s->period[0], x[1] + iy * s->period[1], x[2] + iz * s->period[2]};
                    for (int b = 0; b < nparts; b++) {
                        if (b == me && image == SELF_IMAGE) continue;
                        if (distance2(lo[b], hi[b], y) < c2) push_pick(g, &npick, b * IMAGES + image, i);
                    }
                }
    }
    return npick;
}

static dem_ghost_swap *new_swap(dem_ghost_list *g)
{
    if (g->nswap == g->swap_capacity) {
        const int old = g->swap_capacity;
        g->swap_capacity = old ? 2 * old : 16;
        g->swap = dem_realloc(g->swap, (size_t)g->swap_capacity * sizeof *g->swap);
        memset(g->swap + old, 0, (size_t)(g->swap_capacity - old) * sizeof *g->swap);
    }
    return &g->swap[g->nswap++];
}

/* The picks sorted by key (counting sort: stable, so each image sends in index order), one swap
 * per rank that gets any. */
static void make_swaps(dem_system *s, long npick)
{
    dem_ghost_list *g = &s->ghosts;
    const int nkeys = g->nranks * IMAGES;
    if (nkeys + 1 > g->key_capacity) {
        g->key_capacity = nkeys + 1;
        g->key_count = dem_realloc(g->key_count, (size_t)g->key_capacity * sizeof(int));
    }
    memset(g->key_count, 0, (size_t)(nkeys + 1) * sizeof(int));
    for (long k = 0; k < npick; k++) g->key_count[g->pick_key[k] + 1]++;
    for (int key = 0; key < nkeys; key++) g->key_count[key + 1] += g->key_count[key];   /* where each key starts */
    g->nswap = 0;
    int *swap_of_rank = dem_malloc((size_t)g->nranks * sizeof(int)), *rank_start = dem_malloc((size_t)g->nranks * sizeof(int));
    for (int r = 0; r < g->nranks; r++) {
        const int count = g->key_count[(r + 1) * IMAGES] - g->key_count[r * IMAGES];
        rank_start[r] = g->key_count[r * IMAGES];
        g->send_count[r] = count;
        swap_of_rank[r] = -1;
        if (count == 0) continue;
        swap_of_rank[r] = g->nswap;
        dem_ghost_swap *w = new_swap(g);
        w->rank = r;
        if (count > w->send_capacity) {
            w->send_capacity = count + count / 4 + 64;
            w->send = dem_realloc(w->send, (size_t)w->send_capacity * sizeof(int));
            w->shift = dem_realloc(w->shift, (size_t)w->send_capacity * sizeof(dem_vec3));
        }
        w->nsend = count;
    }
    for (long k = 0; k < npick; k++) {
        const int key = g->pick_key[k], r = key / IMAGES, image = key % IMAGES;
        dem_ghost_swap *w = &g->swap[swap_of_rank[r]];
        const int at = g->key_count[key]++ - rank_start[r];
        w->send[at] = g->pick_index[k];
        w->shift[at][0] = (image % 3 - 1) * s->period[0];
        w->shift[at][1] = (image / 3 % 3 - 1) * s->period[1];
        w->shift[at][2] = (image / 9 - 1) * s->period[2];
    }
    free(swap_of_rank);
    free(rank_start);
}

/* The messages of one exchange: out_count[r] particles of rs bytes to each other rank r and
 * in_count[r] from it, laid out rank after rank in the send and receive buffers (returned). */
static void lay_out(dem_ghost_list *g, size_t rs, const int *out_count, const int *in_count, unsigned char **send,
                    unsigned char **recv)
{
    const int me = dem_comm_rank();
    size_t out = 0, in = 0;
    for (int r = 0; r < g->nranks; r++) {
        g->send_offset[r] = out;
        g->send_bytes[r] = r == me ? 0 : (size_t)out_count[r] * rs;
        out += g->send_bytes[r];
        g->recv_offset[r] = in;
        g->recv_bytes[r] = r == me ? 0 : (size_t)in_count[r] * rs;
        in += g->recv_bytes[r];
    }
    *send = reserve_bytes(&g->send_buf, &g->send_buf_capacity, out);
    *recv = reserve_bytes(&g->recv_buf, &g->recv_buf_capacity, in);
}

/* Pack `roles` of every swap to another rank (its shift added when `shifted`), exchange, unpack
 * into the ghost slots; the swaps to this rank copy without a buffer. */
static void exchange_forward(dem_system *s, unsigned roles, int shifted)
{
    dem_particles *p = &s->p;
    dem_ghost_list *g = &s->ghosts;
    const int me = dem_comm_rank(), nr = g->nranks;
    unsigned char *send, *recv;
    lay_out(g, dem_particles_role_size(roles), g->send_count, g->recv_count, &send, &recv);
    for (int k = 0; k < g->nswap; k++) {
        const dem_ghost_swap *w = &g->swap[k];
        const dem_vec3 *shift = shifted ? w->shift : NULL;
        if (w->rank == me) dem_particles_copy_roles(p, roles, w->send, w->nsend, shift, p->n + g->recv_first[me]);
        else dem_particles_gather_roles(p, roles, w->send, w->nsend, shift, send + g->send_offset[w->rank]);
    }
    dem_comm_exchange(send, g->send_bytes, g->send_offset, recv, g->recv_bytes, g->recv_offset);
    for (int r = 0; r < nr; r++)
        if (r != me && g->recv_count[r])
            dem_particles_put_roles(p, roles, p->n + g->recv_first[r], g->recv_count[r], recv + g->recv_offset[r]);
}

void dem_ghosts_build(dem_system *s, double cutoff)
{
    dem_particles *p = &s->p;
    dem_ghost_list *g = &s->ghosts;
    const int nr = dem_comm_size(), nparts = s->decomp.nparts;
    if (nparts != nr)
        dem_fatal("internal: the decomposition has %d parts for %d ranks (dem_system_setup makes it)", nparts, nr);
    size_rank_arrays(g, nr);
    double (*lo)[3] = dem_malloc((size_t)nparts * sizeof *lo), (*hi)[3] = dem_malloc((size_t)nparts * sizeof *hi);
    for (int b = 0; b < nparts; b++) halo_box(s, b, lo[b], hi[b]);
    const int me = dem_comm_rank();
    const double own_lo[3] = {lo[me][0], lo[me][1], lo[me][2]}, own_hi[3] = {hi[me][0], hi[me][1], hi[me][2]};
    int nintruders = 0, *intruders = NULL;
    if (s->bodies.ntemplates && nparts > 1) {   /* the same on every rank: the case's templates */
        intruders = grow_to_bodies(s, lo, hi, &nintruders);
        int kept = 0;   /* those whose grown box comes within the cutoff of this rank's own box */
        for (int k = 0; k < nintruders; k++)
            if (gap2(lo[intruders[k]], hi[intruders[k]], own_lo, own_hi) < cutoff * cutoff) intruders[kept++] = intruders[k];
        nintruders = kept;
    }
    make_swaps(s, pick(s, cutoff, lo, hi, own_lo, own_hi, intruders, nintruders));
    free(intruders);
    free(lo);
    free(hi);
    for (int r = 0; r < nr; r++) g->count_out[r] = g->send_count[r];
    dem_comm_counts(g->count_out, g->count_in);
    g->n = 0;
    for (int r = 0; r < nr; r++) {
        g->recv_count[r] = (int)g->count_in[r];
        g->recv_first[r] = g->n;
        g->n += g->recv_count[r];
    }
    if (p->n + g->n > p->capacity) dem_particles_reserve(p, 2 * (p->n + g->n) + 1024);
    exchange_forward(s, PF_BORDER, 1);
}

void dem_ghosts_update(dem_system *s)
{
    exchange_forward(s, PF_FORWARD, 1);
    dem_particles_zero_roles(&s->p, PF_REVERSE, s->p.n, s->ghosts.n);
}

void dem_ghosts_fold_forces(dem_system *s)
{
    dem_particles *p = &s->p;
    dem_ghost_list *g = &s->ghosts;
    const int me = dem_comm_rank(), nr = g->nranks;
    unsigned char *send, *recv;   /* each ghost goes back to the rank it came from */
    lay_out(g, dem_particles_role_size(PF_REVERSE), g->recv_count, g->send_count, &send, &recv);
    for (int r = 0; r < nr; r++)
        if (r != me && g->recv_count[r])
            dem_particles_take_roles(p, PF_REVERSE, p->n + g->recv_first[r], g->recv_count[r], send + g->send_offset[r]);
    dem_comm_exchange(send, g->send_bytes, g->send_offset, recv, g->recv_bytes, g->recv_offset);
    for (int k = 0; k < g->nswap; k++) {
        const dem_ghost_swap *w = &g->swap[k];
        if (w->rank == me) dem_particles_fold_roles(p, PF_REVERSE, p->n + g->recv_first[me], w->nsend, w->send);
        else dem_particles_scatter_add_roles(p, PF_REVERSE, w->send, w->nsend, recv + g->recv_offset[w->rank]);
    }
}

int dem_ghosts_owner(const dem_system *s, int k)
{
    const dem_ghost_list *g = &s->ghosts;
    const int me = dem_comm_rank();
    const int j = k - g->recv_first[me];
    if (j < 0 || j >= g->recv_count[me]) return -1;
    for (int w = 0; w < g->nswap; w++)
        if (g->swap[w].rank == me) return g->swap[w].send[j];
    return -1;
}
