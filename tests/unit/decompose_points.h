/* The points both decomposition tests cut: a column [0, 0.1] x [0, 0.05] x [0, 0.3] m whose lower
 * part is dense (z = 0.3 u^3: a bed under a dilute freeboard), from a fixed seed, so that any
 * number of ranks can take every size-th of the same points. */
#ifndef DECOMPOSE_POINTS_H
#define DECOMPOSE_POINTS_H

#include "rng.h"

static const double domain_lo[3] = {0.0, 0.0, 0.0}, domain_hi[3] = {0.1, 0.05, 0.3};

static inline void decompose_points(int n, double (*x)[3])
{
    dem_rng r;
    rng_seed(&r, 12345);
    for (int i = 0; i < n; i++) {
        const double u = rng_uniform(&r);
        x[i][0] = 0.1 * rng_uniform(&r);
        x[i][1] = 0.05 * rng_uniform(&r);
        x[i][2] = 0.3 * u * u * u;
    }
}

#endif
