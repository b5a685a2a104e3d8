/* The particles' copies on the fluid's ranks (proxies.h). */
#include "proxies.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "comm.h"
#include "error.h"
#include "reduce.h"

void cpl_proxies_init(cpl_proxies *pr, const cpl_mesh *m)
{
    memset(pr, 0, sizeof *pr);
    pr->rank = dem_comm_rank();
    pr->size = dem_comm_size();
    const int size = pr->size;
    pr->box = dem_calloc((size_t)size, sizeof *pr->box);
    /* one sum with one term per slot: exact */
    for (int d = 0; d < 3; d++) {
        pr->box[pr->rank][d] = m->ncells ? m->bounds_min[d] : INFINITY;
        pr->box[pr->rank][3 + d] = m->ncells ? m->bounds_max[d] : -INFINITY;
    }
    if (size > 1) {
        for (int r = 0; r < size; r++)
            if (r != pr->rank) for (int k = 0; k < 6; k++) pr->box[r][k] = 0.0;
        if (!m->ncells) for (int k = 0; k < 6; k++) pr->box[pr->rank][k] = 0.0;   /* no cells: an empty box */
        dem_reduce_doubles(&pr->box[0][0], 6 * size, DEM_REDUCE_SUM);
    }
    pr->send_count = dem_calloc((size_t)size, sizeof *pr->send_count);
    pr->send_start = dem_calloc((size_t)size + 1, sizeof *pr->send_start);
    pr->recv_count = dem_calloc((size_t)size, sizeof *pr->recv_count);
    pr->recv_start = dem_calloc((size_t)size + 1, sizeof *pr->recv_start);
}

void cpl_proxies_free(cpl_proxies *pr)
{
    free(pr->box);
    free(pr->sent_particle);
    free(pr->send_count); free(pr->send_start);
    free(pr->recv_count); free(pr->recv_start);
    free(pr->send_buf); free(pr->recv_buf);
    memset(pr, 0, sizeof *pr);
}

/* the ball of radius reach about x touches rank r's box (with a margin of round-off) */
static int touches(const cpl_proxies *pr, int r, const double x[3], double reach)
{
    const double *b = pr->box[r];
    for (int d = 0; d < 3; d++) {
        const double tol = 1e-9 * (b[3 + d] - b[d]) + reach;
        if (!(x[d] >= b[d] - tol && x[d] <= b[3 + d] + tol)) return 0;
    }
    return 1;
}

void cpl_proxies_place(cpl_proxies *pr, int np, const double (*x)[3], const double *reach)
{
    const int size = pr->size;
    for (int r = 0; r < size; r++) pr->send_count[r] = 0;
    if (size == 1) pr->send_count[0] = (size_t)np;
    else
        for (int i = 0; i < np; i++)
            for (int r = 0; r < size; r++) pr->send_count[r] += touches(pr, r, x[i], reach[i]);
    pr->send_start[0] = 0;
    for (int r = 0; r < size; r++) pr->send_start[r + 1] = pr->send_start[r] + pr->send_count[r];
    pr->nsent = (int)pr->send_start[size];
    if (pr->nsent > pr->sent_cap) {
        pr->sent_cap = pr->nsent + pr->nsent / 2 + 16;
        pr->sent_particle = dem_realloc(pr->sent_particle, (size_t)pr->sent_cap * sizeof *pr->sent_particle);
    }
    if (size == 1)
        for (int i = 0; i < np; i++) pr->sent_particle[i] = i;
    else {
        size_t *fill = pr->recv_start;   /* scratch until the counts below */
        for (int r = 0; r < size; r++) fill[r] = pr->send_start[r];
        for (int i = 0; i < np; i++)
            for (int r = 0; r < size; r++)
                if (touches(pr, r, x[i], reach[i])) pr->sent_particle[fill[r]++] = i;
    }
    int64_t *counts = dem_malloc(2 * (size_t)size * sizeof *counts);
    for (int r = 0; r < size; r++) counts[r] = (int64_t)pr->send_count[r];
    dem_comm_counts(counts, counts + size);
    pr->recv_start[0] = 0;
    for (int r = 0; r < size; r++) {
        pr->recv_count[r] = (size_t)counts[size + r];
        pr->recv_start[r + 1] = pr->recv_start[r] + pr->recv_count[r];
    }
    free(counts);
    if (pr->recv_start[size] > (size_t)0x7fffffff) dem_fatal("coupling: %zu particle copies on one rank", pr->recv_start[size]);
    pr->n = (int)pr->recv_start[size];
}

static double *grow(double **buf, size_t *cap, size_t n)
{
    if (n > *cap) {
        *cap = n + n / 2 + 64;
        *buf = dem_realloc(*buf, *cap * sizeof **buf);
    }
    return *buf;
}

/* Each rank r gets `send_items[r]` rows of ncomp doubles from send + send_first[r] rows, and
 * this rank gets recv_items[r] rows into recv + recv_first[r] rows; this rank's own rows copied. */
static void swap(cpl_proxies *pr, int ncomp, const double *send, const size_t *send_items, const size_t *send_first,
                 double *recv, const size_t *recv_items, const size_t *recv_first)
{
    const int size = pr->size, me = pr->rank;
    const size_t row = (size_t)ncomp * sizeof(double);
    size_t *b = dem_malloc(4 * (size_t)size * sizeof *b);
    size_t *sb = b, *so = b + size, *rb = b + 2 * size, *ro = b + 3 * size;
    for (int r = 0; r < size; r++) {
        sb[r] = send_items[r] * row; so[r] = send_first[r] * row;
        rb[r] = recv_items[r] * row; ro[r] = recv_first[r] * row;
        if (r != me) pr->bytes_sent += (double)sb[r];
    }
    if (send_items[me]) memcpy(recv + recv_first[me] * ncomp, send + send_first[me] * ncomp, sb[me]);
    dem_comm_exchange(send, sb, so, recv, rb, ro);
    free(b);
    pr->moves++;
}

void cpl_proxies_forward(cpl_proxies *pr, int ncomp, const double *per_particle, double *per_copy)
{
    double *buf = grow(&pr->send_buf, &pr->send_cap, (size_t)pr->nsent * ncomp + 1);
    for (int k = 0; k < pr->nsent; k++)
        memcpy(buf + (size_t)k * ncomp, per_particle + (size_t)pr->sent_particle[k] * ncomp, (size_t)ncomp * sizeof(double));
    swap(pr, ncomp, buf, pr->send_count, pr->send_start, per_copy, pr->recv_count, pr->recv_start);
}

void cpl_proxies_reverse(cpl_proxies *pr, int ncomp, const double *per_copy, double *per_particle, int np,
                         enum cpl_proxy_op op)
{
    double *buf = grow(&pr->recv_buf, &pr->recv_cap, (size_t)pr->nsent * ncomp + 1);
    swap(pr, ncomp, per_copy, pr->recv_count, pr->recv_start, buf, pr->send_count, pr->send_start);
    const double none = op == CPL_PROXY_SUM ? 0.0 : -1.0;
    for (size_t k = 0; k < (size_t)np * ncomp; k++) per_particle[k] = none;
    for (int k = 0; k < pr->nsent; k++) {
        double *to = per_particle + (size_t)pr->sent_particle[k] * ncomp;
        const double *from = buf + (size_t)k * ncomp;
        for (int j = 0; j < ncomp; j++) {
            if (op == CPL_PROXY_SUM) to[j] += from[j];
            else if (from[j] > to[j]) to[j] = from[j];
        }
    }
}
