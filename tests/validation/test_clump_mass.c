/* Multisphere templates: mass properties and rotational energy (seed note 004 eq. 1-10,
 * dem/src/clump_mass.h) against closed forms.
 *  - sphereSum, a dumbbell of two separated spheres: mass, centre, inertia against the
 *    parallel-axis closed form (1e-12), E_rot of eq. 10 against 1/2 w.I.w of that tensor and
 *    against eq. 9's sum over spheres (1e-12); an asymmetric three-sphere clump: eq. 9 = eq. 10,
 *    and the principal axes diagonalise the tensor (1e-12).
 *  - union of separated spheres = sphereSum, within the integration's stated bound.
 *  - union of two equal spheres overlapping by half a radius: volume, inertia and E_rot against
 *    the closed form of the solid of revolution (polynomial integrals below), each within the
 *    bound the integration states (volume_error, and 2 rho volume_error R^2 for the tensor); and
 *    sphereSum exceeds the union by the lens volume, within the same bound; sphereSum's E_rot of
 *    the overlapping pair against its parallel-axis closed form (1e-12). */
#include "clump_mass.h"
#include "harness.h"

static double sphere_mass(double rho, double a) { return rho * 4.0 / 3.0 * M_PI * a * a * a; }

/* int_0^b of c0 + c1 x + ... + c4 x^4 */
static double poly_integral(const double c[5], double b)
{
    double s = 0.0, p = b;
    for (int k = 0; k < 5; k++, p *= b) s += c[k] * p / (k + 1);
    return s;
}

static void dumbbell_sphere_sum(void)
{
    const double rho = 2500.0, a = 1e-3, d = 3e-3;
    const double x[2][3] = {{-d, 0, 0}, {d, 0, 0}}, r[2] = {a, a};
    dem_clump_mass m;
    dem_clump_mass_sphere_sum(2, x, r, rho, &m);
    const double ms = sphere_mass(rho, a);
    const double Ixx = 2 * 0.4 * ms * a * a, Iyy = 2 * (0.4 * ms * a * a + ms * d * d);
    check_rel("sphereSum dumbbell: mass (eq. 1)", m.mass, 2 * ms, 1e-12);
    check_true("sphereSum dumbbell: centre at the middle (eq. 2)", fabs(m.com[0]) + fabs(m.com[1]) + fabs(m.com[2]) < 1e-18);
    check_rel("sphereSum dumbbell: I_xx (eq. 5-7)", m.inertia[0][0], Ixx, 1e-12);
    check_rel("sphereSum dumbbell: I_yy (eq. 5-7)", m.inertia[1][1], Iyy, 1e-12);
    check_rel("sphereSum dumbbell: I_zz (eq. 5-7)", m.inertia[2][2], Iyy, 1e-12);
    const double w[3] = {10.0, -20.0, 30.0};
    const double closed = 0.5 * (Ixx * w[0] * w[0] + Iyy * w[1] * w[1] + Iyy * w[2] * w[2]);
    check_rel("sphereSum dumbbell: E_rot eq. 10 vs closed form", dem_rotational_energy(m.inertia, w), closed, 1e-12);
    const double rel[2][3] = {{-d, 0, 0}, {d, 0, 0}}, mass[2] = {ms, ms};
    check_rel("sphereSum dumbbell: E_rot eq. 9 (sum over spheres) vs closed form",
              dem_rotational_energy_spheres(2, rel, r, mass, w), closed, 1e-12);
}

static void asymmetric_sphere_sum(void)
{
    const double rho = 1000.0;
    const double x[3][3] = {{0.1e-3, 0.2e-3, -0.3e-3}, {2.2e-3, -0.4e-3, 0.5e-3}, {0.7e-3, 1.9e-3, 1.1e-3}};
    const double r[3] = {1.0e-3, 0.6e-3, 0.8e-3};
    dem_clump_mass m;
    dem_clump_mass_sphere_sum(3, x, r, rho, &m);
    double rc[3][3], mass[3];
    for (int i = 0; i < 3; i++) {
        mass[i] = sphere_mass(rho, r[i]);
        for (int d = 0; d < 3; d++) rc[i][d] = x[i][d] - m.com[d];
    }
    const double w[3] = {3.0, -1.0, 7.0};
    check_rel("sphereSum, three unequal spheres: E_rot eq. 9 = eq. 10", dem_rotational_energy_spheres(3, rc, r, mass, w),
              dem_rotational_energy(m.inertia, w), 1e-12);
    double worst = 0.0;
    for (int k = 0; k < 3; k++) {
        double Ia[3] = {0, 0, 0};
        for (int d = 0; d < 3; d++)
            for (int e = 0; e < 3; e++) Ia[d] += m.inertia[d][e] * m.axes[k][e];
        for (int d = 0; d < 3; d++) worst = fmax(worst, fabs(Ia[d] - m.principal[k] * m.axes[k][d]));
    }
    const double tr = m.inertia[0][0] + m.inertia[1][1] + m.inertia[2][2];
    printf("  principal moments %.6g %.6g %.6g kg m^2; worst |I a_k - lambda_k a_k| / tr I = %.2e\n", m.principal[0],
           m.principal[1], m.principal[2], worst / tr);
    check_true("principal axes: I a_k = lambda_k a_k to 1e-12 of tr I", worst <= 1e-12 * tr);
    check_true("principal moments ascending", m.principal[0] <= m.principal[1] && m.principal[1] <= m.principal[2]);
    const double *a0 = m.axes[0], *a1 = m.axes[1], *a2 = m.axes[2];
    const double det = a0[0] * (a1[1] * a2[2] - a1[2] * a2[1]) - a0[1] * (a1[0] * a2[2] - a1[2] * a2[0]) +
                       a0[2] * (a1[0] * a2[1] - a1[1] * a2[0]);
    check_rel("principal axes right-handed (det = 1)", det, 1.0, 1e-12);
}

static void union_separated(void)
{
    const double rho = 2500.0, a = 1e-3, d = 3e-3;
    const double x[2][3] = {{-d, 0, 0}, {d, 0, 0}}, r[2] = {a, a};
    dem_clump_mass su, un;
    dem_clump_mass_sphere_sum(2, x, r, rho, &su);
    dem_clump_mass_union(2, x, r, rho, 1e-2, &un);
    printf("  union, separated: volume %.9g m^3 (exact %.9g), stated bound %.3g, %ld cells\n", un.volume, su.volume,
           un.volume_error, un.cells);
    check_true("union of separated spheres: |V - V_exact| <= stated bound", fabs(un.volume - su.volume) <= un.volume_error);
    check_true("union: the stated bound is at most the asked 1 %", un.volume_error <= 1e-2 * un.volume);
}

static void union_overlapping(void)
{
    /* two spheres of radius a at x = -+d, d = a/2; for x >= 0 the surface is the right sphere's,
     * R^2(x) = a^2 - (x - d)^2 = -x^2 + 2 d x + (a^2 - d^2), 0 <= x <= a + d */
    const double rho = 2500.0, a = 1e-3, d = 0.5e-3, b = a + d;
    const double c0 = a * a - d * d, c1 = 2 * d, c2 = -1.0;
    const double R2[5] = {c0, c1, c2, 0, 0};
    const double R4[5] = {c0 * c0, 2 * c0 * c1, c1 * c1 + 2 * c0 * c2, 2 * c1 * c2, c2 * c2};   /* (R^2)^2 */
    const double x2R2[5] = {0, 0, c0, c1, c2};
    const double V = 2 * M_PI * poly_integral(R2, b);
    const double Ixx = rho * 2 * M_PI / 2 * poly_integral(R4, b);
    const double Iyy = rho * 2 * M_PI * (poly_integral(R4, b) / 4 + poly_integral(x2R2, b));
    const double x[2][3] = {{-d, 0, 0}, {d, 0, 0}}, r[2] = {a, a};
    for (int pass = 0; pass < 1; pass++) {   /* a bound of 1e-3 costs 100 times as many cells (35 s) */
        const double tol = 1e-2;
        dem_clump_mass un;
        dem_clump_mass_union(2, x, r, rho, tol, &un);
        const double Rmax2 = 3 * b * b;   /* |x|^2 at the bounding cube's corners */
        const double bound_I = 2 * rho * un.volume_error * Rmax2;
        printf("  union, overlapping (asked %.0e): V %.9g (exact %.9g, error %.2e, bound %.2e), I_xx error %.2e, "
               "I_yy error %.2e (bound %.2e), %ld cells\n",
               tol, un.volume, V, fabs(un.volume - V) / V, un.volume_error / V, fabs(un.inertia[0][0] - Ixx) / Ixx,
               fabs(un.inertia[1][1] - Iyy) / Iyy, bound_I / Iyy, un.cells);
        char what[120];
        snprintf(what, sizeof what, "union, overlapping (bound %.0e): |V - V_exact| <= stated bound", tol);
        check_true(what, fabs(un.volume - V) <= un.volume_error && un.volume_error <= tol * un.volume);
        snprintf(what, sizeof what, "union, overlapping (bound %.0e): I_xx, I_yy, I_zz within 2 rho bound R^2", tol);
        check_true(what, fabs(un.inertia[0][0] - Ixx) <= bound_I && fabs(un.inertia[1][1] - Iyy) <= bound_I &&
                             fabs(un.inertia[2][2] - Iyy) <= bound_I);
        const double w[3] = {10.0, -20.0, 30.0};
        const double E = 0.5 * (Ixx * w[0] * w[0] + Iyy * (w[1] * w[1] + w[2] * w[2]));
        const double bound_E = 0.5 * bound_I * (fabs(w[0]) + fabs(w[1]) + fabs(w[2])) *
                               (fabs(w[0]) + fabs(w[1]) + fabs(w[2]));
        snprintf(what, sizeof what, "union, overlapping (bound %.0e): E_rot eq. 10 within its bound", tol);
        check_true(what, fabs(dem_rotational_energy(un.inertia, w) - E) <= bound_E);
        if (pass == 0) {
            dem_clump_mass su;
            dem_clump_mass_sphere_sum(2, x, r, rho, &su);
            /* the lens: two caps of height a - d */
            const double hc = a - d, lens = 2 * M_PI * hc * hc * (3 * a - hc) / 3;
            check_true("sphereSum - union = the lens volume, within the union's bound",
                       fabs(su.volume - un.volume - lens) <= un.volume_error);
            /* sphereSum of the overlapping pair: the parallel-axis closed form, the lens counted twice */
            const double ms = sphere_mass(rho, a), Jxx = 2 * 0.4 * ms * a * a, Jyy = Jxx + 2 * ms * d * d;
            check_rel("sphereSum, overlapping: E_rot eq. 10 vs closed form", dem_rotational_energy(su.inertia, w),
                      0.5 * (Jxx * w[0] * w[0] + Jyy * (w[1] * w[1] + w[2] * w[2])), 1e-12);
        }
    }
}

int main(void)
{
    dumbbell_sphere_sum();
    asymmetric_sphere_sum();
    union_separated();
    union_overlapping();
    return finish("test_clump_mass");
}
