/* Restitution of a power-law spring with a dashpot sqrt(m dF/dx) alpha: the impact in scaled
 * units (restitution.h), integrated by classical RK4, and the inverse by regula falsi. */
#include "restitution.h"

#include <math.h>

#include "error.h"

/* x^p for the exponents the models use most, exactly as pow would give them but cheaper */
static double power(double x, double p)
{
    if (p == 1.0) return x;
    if (p == 1.5) return x * sqrt(x);
    if (p == 0.0) return 1.0;
    if (p == 0.25) return sqrt(sqrt(x));
    return pow(x, p);
}

typedef struct impact {
    double d, damping;   /* exponent; alpha sqrt(d) */
} impact;

/* the repulsive force in scaled units (X'' = -force) */
static double force(const impact *q, double x, double v)
{
    const double xp = x > 0.0 ? x : 0.0;
    return power(xp, q->d) + q->damping * power(xp, 0.5 * (q->d - 1.0)) * v;
}

double dem_restitution_of_damping(double alpha, double d, int clipped)
{
    if (!(alpha >= 0.0) || !(d >= 1.0)) dem_fatal("restitution: damping %g or exponent %g out of range", alpha, d);
    const impact q = {d, alpha * sqrt(d)};
    /* the undamped contact lasts 2 int_0^1 dx / sqrt(1 - x^(d+1)) * (2/(d+1))^(1/(d+1)) in these
     * units (pi for d = 1, 3.22 for d = 1.5); 4e4 steps over about that */
    const double h = 3.5 / 4e4, t_end = 100.0;   /* 100: e down to about 1e-6 */
    double x = 0.0, v = 1.0;
    for (double t = 0.0; t < t_end; t += h) {
        const double a1 = -force(&q, x, v);
        const double a2 = -force(&q, x + 0.5 * h * v, v + 0.5 * h * a1);
        const double a3 = -force(&q, x + 0.5 * h * (v + 0.5 * h * a1), v + 0.5 * h * a2);
        const double a4 = -force(&q, x + h * (v + 0.5 * h * a2), v + h * a3);
        const double x1 = x + h * v + h * h / 6.0 * (a1 + a2 + a3);
        const double v1 = v + h / 6.0 * (a1 + 2.0 * a2 + 2.0 * a3 + a4);
        if (clipped && v1 < 0.0) {   /* on the way out: part where the force reaches 0 */
            const double f0 = force(&q, x, v), f1 = force(&q, x1, v1);
            if (f1 <= 0.0) {
                const double s = f0 > 0.0 ? f0 / (f0 - f1) : 0.0;
                return -(v + s * (v1 - v));
            }
        }
        if (x1 <= 0.0 && v1 < 0.0) {   /* back at zero overlap */
            const double s = x / (x - x1);
            return -(v + s * (v1 - v));
        }
        x = x1;
        v = v1;
    }
    return 0.0;   /* overdamped: never parts */
}

double dem_damping_for_restitution(double e, double d, int clipped)
{
    if (!(e > 0.0 && e <= 1.0)) dem_fatal("restitution %g: must lie in (0, 1]", e);
    if (e == 1.0) return 0.0;
    double lo = 0.0, f_lo = 1.0 - e, hi = 1.0, f_hi;
    while ((f_hi = dem_restitution_of_damping(hi, d, clipped) - e) > 0.0) {
        lo = hi; f_lo = f_hi;
        hi *= 2.0;
        if (hi > 1e6) dem_fatal("restitution %g: no damping gives it (exponent %g)", e, d);
    }
    /* regula falsi, Illinois variant: e(alpha) is smooth and decreasing */
    int side = 0;
    for (int it = 0; it < 200; it++) {
        const double mid = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
        const double f_mid = dem_restitution_of_damping(mid, d, clipped) - e;
        if (fabs(f_mid) < 1e-12 || hi - lo < 1e-14 * hi) return mid;
        if (f_mid > 0.0) {
            lo = mid; f_lo = f_mid;
            if (side == -1) f_hi *= 0.5;
            side = -1;
        } else {
            hi = mid; f_hi = f_mid;
            if (side == 1) f_lo *= 0.5;
            side = 1;
        }
    }
    return 0.5 * (lo + hi);
}
