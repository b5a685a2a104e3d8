/* Point maps that turn a box mesh (cpl_mesh_map_points) into the skewed and graded meshes the
 * coupling tests share. Every face stays planar. */
#ifndef CPL_TEST_MESHES_H
#define CPL_TEST_MESHES_H

#include <math.h>

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

#endif
