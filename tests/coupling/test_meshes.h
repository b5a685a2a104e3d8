/* Point maps that turn a box mesh (cpl_mesh_map_points) into the skewed and graded meshes the
 * coupling tests share (every face stays planar), and the periodic channel of the cyclic tests. */
#ifndef CPL_TEST_MESHES_H
#define CPL_TEST_MESHES_H

#include <math.h>
#include <stdlib.h>

#include "mesh.h"

/* per-axis stretch (grading), a non-linear shear of x along z, then a linear shear */
static inline void shear_grade(double x[3], void *ctx)
{
    (void)ctx;
    x[0] = x[0] * x[0];                         /* [0,1] -> [0,1], cells finer near x = 0 */
    x[2] = 2.0 * (x[2] + 0.5 * x[2] * x[2]);    /* [0,1] -> [0,3] */
    x[0] += 0.1 * sin(2.0 * x[2]);
    x[1] += 0.3 * x[0];
    x[0] += 0.3 * x[2];
}

/* graded in y, then sheared */
static inline void shear_linear(double x[3], void *ctx)
{
    (void)ctx;
    x[1] = x[1] * (1.0 + 0.5 * x[1]);
    x[0] += 0.3 * x[2];
    x[1] += 0.2 * x[0];
}

/* The cyclic channel of the cyclic tests: [0, 1] x [0, 0.4] x [0, 0.4] m, 10 x 4 x 4 cells of 0.1 m,
 * periodic along x (its box faces on x = 0 and x = 1 paired, cyclic.c); the same box without the
 * pairs into *plain (NULL: none). */
static inline int cyclic_channel(cpl_mesh *m, cpl_mesh *plain)
{
    const double lo[3] = {0, 0, 0}, hi[3] = {1, 0.4, 0.4};
    cpl_mesh_box(m, lo, hi, 10, 4, 4);
    if (plain) cpl_mesh_box(plain, lo, hi, 10, 4, 4);
    int *fa, *fb;
    const int npairs = cpl_mesh_pair_box_faces(m, 0, &fa, &fb);
    cpl_mesh_set_cyclic(m, npairs, fa, fb);
    free(fa);
    free(fb);
    return npairs;
}

#endif
