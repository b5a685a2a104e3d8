/* Recursive coordinate bisection (decompose.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "decompose.h"
#include "error.h"
#include "reduce.h"

enum { BINS = 64, ROUNDS = 4 };   /* a plane placed to 1/64^4 = 6e-8 of the side */

/* A box of the level being cut: its node, its parts p0 .. p0 + k - 1, its extent */
typedef struct pending {
    int node, p0, k;
    double lo[3], hi[3];
} pending;

void dem_decomposition_free(dem_decomposition *d)
{
    free(d->lo);
    free(d->hi);
    free(d->dim);
    free(d->cut);
    free(d->child);
    memset(d, 0, sizeof *d);
}

static double weight_of(const double *weight, int i) { return weight ? weight[i] : 1.0; }

/* The histogram slot of coordinate c in [a, b) cut into BINS: 0 below a, BINS + 1 at or above b */
static int slot(double c, double a, double b)
{
    if (c < a) return 0;
    if (c >= b) return BINS + 1;
    const int j = (int)((c - a) / (b - a) * BINS);
    return 1 + (j < BINS - 1 ? j : BINS - 1);
}

/* The side along which box j is cut, and where: the histograms of every box of the level summed
 * over the ranks at once, each narrowed to the bin where its target falls. */
static void find_cuts(int m, const pending *box, const int *dim, const double *target, const double *total,
                      int n, const dem_vec3 *x, const double *weight, const int *at, double *cut)
{
    double (*a_b)[2] = dem_malloc((size_t)m * sizeof *a_b);
    double *hist = dem_malloc((size_t)m * (BINS + 2) * sizeof *hist);
    for (int j = 0; j < m; j++) {
        a_b[j][0] = box[j].lo[dim[j]];
        a_b[j][1] = box[j].hi[dim[j]];
    }
    for (int round = 0; round < ROUNDS; round++) {
        memset(hist, 0, (size_t)m * (BINS + 2) * sizeof *hist);
        for (int i = 0; i < n; i++) {
            const int j = at[i];
            if (j < 0) continue;
            const int d = dim[j];
            /* a point outside the domain counts at its face */
            const double c = fmin(fmax(x[i][d], box[j].lo[d]), box[j].hi[d]);
            hist[j * (BINS + 2) + slot(c, a_b[j][0], a_b[j][1])] += weight_of(weight, i);
        }
        dem_reduce_doubles(hist, m * (BINS + 2), DEM_REDUCE_SUM);
        for (int j = 0; j < m; j++) {
            if (!(total[j] > 0.0)) continue;   /* an empty box: cut by its extent below */
            const double *h = hist + j * (BINS + 2);
            double below = h[0];
            int bin = BINS;                     /* the target at the top face (points held there) */
            for (int k = 1; k <= BINS; k++) {
                if (below + h[k] >= target[j]) { bin = k; break; }
                below += h[k];
            }
            const double a = a_b[j][0], w = (a_b[j][1] - a) / BINS;
            a_b[j][0] = a + (bin - 1) * w;
            a_b[j][1] = bin == BINS ? a_b[j][1] : a + bin * w;
        }
    }
    for (int j = 0; j < m; j++) {
        const int d = dim[j];
        const double f = (double)(box[j].k / 2) / box[j].k;
        cut[j] = total[j] > 0.0 ? 0.5 * (a_b[j][0] + a_b[j][1]) : box[j].lo[d] + f * (box[j].hi[d] - box[j].lo[d]);
    }
    free(a_b);
    free(hist);
}

void dem_decompose_rcb(dem_decomposition *d, int nparts, const double lo[3], const double hi[3], int n,
                       const dem_vec3 *x, const double *weight)
{
    if (nparts < 1) dem_fatal("dem_decompose_rcb: %d parts", nparts);
    memset(d, 0, sizeof *d);
    d->nparts = nparts;
    d->lo = dem_malloc((size_t)nparts * sizeof *d->lo);
    d->hi = dem_malloc((size_t)nparts * sizeof *d->hi);
    d->dim = dem_malloc((size_t)nparts * sizeof *d->dim);   /* nparts - 1 cuts */
    d->cut = dem_malloc((size_t)nparts * sizeof *d->cut);
    d->child = dem_malloc((size_t)nparts * sizeof *d->child);
    memcpy(d->lo[0], lo, sizeof d->lo[0]);
    memcpy(d->hi[0], hi, sizeof d->hi[0]);
    if (nparts == 1) return;

    pending *level = dem_malloc((size_t)nparts * sizeof *level), *next = dem_malloc((size_t)nparts * sizeof *next);
    int *at = dem_calloc((size_t)(n ? n : 1), sizeof *at);   /* the level's box of each particle, -1: placed */
    int *dim = dem_malloc((size_t)nparts * sizeof *dim);
    double *total = dem_malloc((size_t)nparts * sizeof *total), *target = dem_malloc((size_t)nparts * sizeof *target);
    double *cut = dem_malloc((size_t)nparts * sizeof *cut), *extent = dem_malloc((size_t)6 * nparts * sizeof *extent);
    int *to = dem_malloc((size_t)2 * nparts * sizeof *to);
    int m = 1;
    level[0] = (pending){.node = 0, .p0 = 0, .k = nparts};
    memcpy(level[0].lo, lo, sizeof level[0].lo);
    memcpy(level[0].hi, hi, sizeof level[0].hi);
    d->nnodes = 1;
    while (m > 0) {
        memset(total, 0, (size_t)m * sizeof *total);
        for (int i = 0; i < n; i++)
            if (at[i] >= 0) total[at[i]] += weight_of(weight, i);
        dem_reduce_doubles(total, m, DEM_REDUCE_SUM);
        /* the extent of each box's particles (as -min, max: one reduction, exact at any rank count) */
        for (int j = 0; j < 6 * m; j++) extent[j] = -INFINITY;
        for (int i = 0; i < n; i++) {
            if (at[i] < 0) continue;
            const pending *b = &level[at[i]];
            for (int e = 0; e < 3; e++) {
                const double c = fmin(fmax(x[i][e], b->lo[e]), b->hi[e]);
                extent[6 * at[i] + e] = fmax(extent[6 * at[i] + e], -c);
                extent[6 * at[i] + 3 + e] = fmax(extent[6 * at[i] + 3 + e], c);
            }
        }
        dem_reduce_doubles(extent, 6 * m, DEM_REDUCE_MAX);
        for (int j = 0; j < m; j++) {
            const pending *b = &level[j];
            /* across the longest side of what the box holds (of the box itself when it is empty): a
             * settled bed in a tall box is cut upright, where its border with the next box is short */
            double side[3];
            for (int e = 0; e < 3; e++)
                side[e] = isfinite(extent[6 * j + e]) ? extent[6 * j + 3 + e] + extent[6 * j + e] : b->hi[e] - b->lo[e];
            dim[j] = 0;   /* the first of equal ones */
            for (int e = 1; e < 3; e++)
                if (side[e] > side[dim[j]]) dim[j] = e;
            target[j] = total[j] * (double)(b->k / 2) / b->k;
        }
        find_cuts(m, level, dim, target, total, n, x, weight, at, cut);
        int mnext = 0;
        for (int j = 0; j < m; j++) {
            const pending *b = &level[j];
            const int node = b->node, kl = b->k / 2;
            d->dim[node] = dim[j];
            d->cut[node] = cut[j];
            for (int side = 0; side < 2; side++) {
                pending c = *b;
                c.p0 = side ? b->p0 + kl : b->p0;
                c.k = side ? b->k - kl : kl;
                if (side) c.lo[dim[j]] = cut[j];
                else c.hi[dim[j]] = cut[j];
                if (c.k == 1) {
                    d->child[node][side] = -1 - c.p0;
                    memcpy(d->lo[c.p0], c.lo, sizeof c.lo);
                    memcpy(d->hi[c.p0], c.hi, sizeof c.hi);
                    to[2 * j + side] = -1;
                } else {
                    c.node = d->nnodes++;
                    d->child[node][side] = c.node;
                    to[2 * j + side] = mnext;
                    next[mnext++] = c;
                }
            }
        }
        for (int i = 0; i < n; i++)
            if (at[i] >= 0) at[i] = to[2 * at[i] + (x[i][dim[at[i]]] >= cut[at[i]])];
        pending *swap = level;
        level = next;
        next = swap;
        m = mnext;
    }
    free(level);
    free(next);
    free(at);
    free(dim);
    free(total);
    free(target);
    free(cut);
    free(extent);
    free(to);
}

int dem_decomposition_owner(const dem_decomposition *d, const double x[3])
{
    if (d->nparts == 1) return 0;
    int k = 0;
    for (;;) {
        const int c = d->child[k][x[d->dim[k]] >= d->cut[k]];
        if (c < 0) return -1 - c;
        k = c;
    }
}

double dem_decomposition_imbalance(const dem_decomposition *d, int n, const dem_vec3 *x, const double *weight,
                                   double *part_weight)
{
    memset(part_weight, 0, (size_t)d->nparts * sizeof *part_weight);
    for (int i = 0; i < n; i++) part_weight[dem_decomposition_owner(d, x[i])] += weight_of(weight, i);
    dem_reduce_doubles(part_weight, d->nparts, DEM_REDUCE_SUM);
    double sum = 0.0, max = 0.0;
    for (int p = 0; p < d->nparts; p++) {
        sum += part_weight[p];
        max = fmax(max, part_weight[p]);
    }
    return sum > 0.0 ? max * d->nparts / sum : 1.0;
}
