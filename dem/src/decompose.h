/* The DEM's spatial decomposition (issue 23): recursive coordinate bisection.
 *
 * The domain is split into nparts boxes of equal weight (particle count, or a measured cost per
 * particle). The tree is cut level by level: every box of a level that still holds k > 1 parts is
 * cut across the longest side of the particles it holds (of the box, when empty) at the plane that
 * leaves floor(k/2)/k of its weight below; the two halves hold floor(k/2) and the rest of its parts. A cut is found by histograms of the weight
 * along that side, each narrowed to the bin where the target falls (BINS bins, ROUNDS rounds: the
 * plane is placed to 1/BINS^ROUNDS of the side). The histograms are summed through reduce.h, so a
 * parallel run gives every rank the same tree from its own particles, and with counts as the
 * weight (exact sums) the same tree on any number of ranks: that of a serial run over them all.
 *
 * The boxes are not a grid (four parts cut x once and each half's y at its own plane), so a box may
 * have several neighbours on one side: the ghosts and migration take their partners from the
 * boxes, not from a stencil. A point outside the domain belongs to the box whose tree walk it
 * ends in (the boxes extend to infinity beyond the domain's faces for that purpose). */
#ifndef DEM_DECOMPOSE_H
#define DEM_DECOMPOSE_H

#include "particles.h"

typedef struct dem_decomposition {
    int nparts;
    double (*lo)[3], (*hi)[3];  /* part p's box [m] (within the domain) */
    /* the tree: node 0 is the root; node k cuts along dim[k] at cut[k]: a point with x[dim] < cut
     * goes to child[k][0], else to child[k][1]; a child >= 0 is a node, -1 - p is part p */
    int nnodes;
    int *dim;
    double *cut;
    int (*child)[2];
} dem_decomposition;

/* Split the domain [lo, hi] into nparts boxes holding equal shares of the weight of the n local
 * particles at x (weight NULL: 1 each), summed over the ranks through reduce.h. */
void dem_decompose_rcb(dem_decomposition *d, int nparts, const double lo[3], const double hi[3], int n,
                       const dem_vec3 *x, const double *weight);
/* The part whose box holds x */
int dem_decomposition_owner(const dem_decomposition *d, const double x[3]);
/* The weight each part holds [nparts], summed over the ranks; returns max / mean (1: balanced),
 * the figure a rebalance is decided on. */
double dem_decomposition_imbalance(const dem_decomposition *d, int n, const dem_vec3 *x, const double *weight,
                                   double *part_weight);
void dem_decomposition_free(dem_decomposition *d);

#endif
