/* Symmetry planes: the bounce of a centre that crossed a plane in the drift (equations in
 * symmetry.h). Called only for the few particles at a plane in a step. */
#include <math.h>

#include "symmetry.h"

void dem_symmetry_bounce(const dem_symmetry_plane *planes, int nplanes, double x[3], double v[3], const double f[3],
                     double inv_mass, double dt)
{
    const double h = 0.5 * dt;
    int crossed = 1;
    for (int pass = 0; crossed && pass < 4; pass++) {
        crossed = 0;
        for (int k = 0; k < nplanes; k++) {
            const double *n = planes[k].normal;
            const double d = symmetry_distance(&planes[k], x);
            if (!(d < 0.0)) continue;
            const double vn = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
            const double alpha = (f[0] * n[0] + f[1] * n[1] + f[2] * n[2]) * inv_mass;
            const double d_start = d - dt * vn;          /* where the drift began */
            double d_end = -d, vn_end = -vn;              /* no force, or started beyond: the plain mirror */
            if (alpha != 0.0 && d_start >= 0.0) {
                const double u = vn - h * alpha;          /* normal velocity before the first half kick */
                const double den = -u + sqrt(fmax(u * u - 2.0 * alpha * d_start, 0.0));
                const double tau = den > 0.0 ? fmin(fmax(2.0 * d_start / den, 0.0), dt) : 0.0;
                const double w = -(u + alpha * tau), rest = dt - tau;
                d_end = fmax(w * rest + 0.5 * alpha * rest * rest, 0.0);
                vn_end = w + alpha * (h - tau);
            }
            for (int q = 0; q < 3; q++) {
                x[q] += (d_end - d) * n[q];
                v[q] += (vn_end - vn) * n[q];
            }
            crossed = nplanes > 1;
        }
    }
}
