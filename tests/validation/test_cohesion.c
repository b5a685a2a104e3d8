/* Cohesion model `sjkr`: F_coh = -k_coh pi a^2 added to the Hertz normal force, a the radius of
 * the circle where the two spheres intersect.
 *
 * Two spheres (r_i 1 mm, r_j 1.25 mm; E 5 MPa, nu 0.45, rho 2500), Hertz normal with e = 0.3,
 * tangential history (mu 0.5, idle: the motion is head-on), k_coh = 1e5 J/m^3, no gravity.
 * At overlap delta (centre distance d = r_i + r_j - delta) the net attraction is
 *     g(delta) = k_coh pi a^2(delta) - 4/3 Y* sqrt(R*) delta^1.5,
 *     a^2 = r_i^2 - x^2,  x = (d^2 + r_i^2 - r_j^2) / (2 d)   (intersection circle),
 *     Y* = E / (2 (1 - nu^2)),  R* = r_i r_j / (r_i + r_j),
 * written here from the geometry, not taken from the library. g rises from 0 (a^2 ~ 2 R* delta
 * beats delta^1.5), peaks and falls through 0 again. Closed forms, evaluated numerically:
 *     zero-load equilibrium delta_0: the root of g (bisection);
 *     pull-off force F_po = max g (golden section), at delta_*;
 *     under a pull P < F_po the stable equilibrium is the root of g = P on delta > delta_*.
 * With these numbers delta_0 = 1.25 % of r_i (12.5 um) and F_po = 6.5e-4 N.
 *
 * The pull is applied as equal and opposite external forces (s.p.f_ext) along the line of
 * centres, ramped linearly from 0 over 0.2 s and then held for 0.1 s. The slowest contact
 * oscillation (near pull-off) has a period of ~3 ms and the contact is about critically damped
 * (e 0.3), so the ramp is quasi-static; the dashpot lag only keeps the pair deeper in the well.
 * Checks, all within 2 %:
 *  1. zero-load equilibrium overlap (settled 0.05 s from a light touch) = delta_0;
 *  2. ramp to 0.98 F_po and hold: the pair stays bonded throughout, and its overlap at the end
 *     is the stable root of g = 0.98 F_po (within 2 %);
 *  3. ramp to 1.02 F_po and hold: the pair separates;
 *  4. a slow ramp from 0.9 to 1.1 F_po over 0.4 s: the pull at which the contact opens = F_po
 *     (within 2 %; it opens a little late, since the escape past the maximum of g takes time
 *     while the ramp goes on: 0.7 % here).
 * (2 and 3 bracket F_po much more tightly than required: 0.999 / 1.001 F_po also hold / separate.)
 */
#include <time.h>

#include "harness.h"

static const double E = 5e6, NU = 0.45, RHO = 2500, RI = 1e-3, RJ = 1.25e-3, K_COH = 1e5, DT = 2e-6;

/* ---------------------------------------------------------------- closed form */

static double g_net(double delta)
{
    const double Y = E / (2.0 * (1.0 - NU * NU)), R = RI * RJ / (RI + RJ);
    const double d = RI + RJ - delta, x = (d * d + RI * RI - RJ * RJ) / (2.0 * d);
    return K_COH * M_PI * (RI * RI - x * x) - 4.0 / 3.0 * Y * sqrt(R) * pow(delta, 1.5);
}

/* root of g(delta) = P in [lo, hi], g - P changing sign there */
static double root(double P, double lo, double hi)
{
    const double slo = g_net(lo) - P > 0 ? 1.0 : -1.0;
    for (int k = 0; k < 200; k++) {
        const double mid = 0.5 * (lo + hi);
        if ((g_net(mid) - P > 0 ? 1.0 : -1.0) == slo) lo = mid; else hi = mid;
    }
    return 0.5 * (lo + hi);
}

static double golden_max(double lo, double hi)
{
    const double q = 0.5 * (sqrt(5.0) - 1.0);
    double a = hi - q * (hi - lo), b = lo + q * (hi - lo);
    for (int k = 0; k < 200; k++) {
        if (g_net(a) > g_net(b)) { hi = b; b = a; a = hi - q * (hi - lo); }
        else { lo = a; a = b; b = lo + q * (hi - lo); }
    }
    return 0.5 * (lo + hi);
}

/* ---------------------------------------------------------------- simulation */

static void pair_setup(dem_system *s, double delta_start)
{
    make_system(s, E, NU, RHO, 0.3, 0.5, normal_hertz, tangential_history, 0.05);
    const dem_sjkr_params mp = {K_COH};
    dem_materials_set_model_values(&s->materials, 0, 0, SLOT_COHESION, &mp, sizeof mp);
    s->models.cohesion = cohesion_sjkr;
    add_sphere(s, -RI, 0, 0, 0, 0, 0, RI);                        /* id 0 */
    add_sphere(s, RJ - delta_start, 0, 0, 0, 0, 0, RJ);           /* id 1 */
    s->dt = DT;
    dem_system_setup(s);
}

static double overlap(const dem_system *s)
{
    double d2 = 0.0;
    for (int q = 0; q < 3; q++) d2 += (s->p.x[0][q] - s->p.x[1][q]) * (s->p.x[0][q] - s->p.x[1][q]);
    return RI + RJ - sqrt(d2);
}

/* Pull P apart along x: -P on id 0, +P on id 1 (located by id: the list may sort them). */
static void set_pull(dem_system *s, double P)
{
    for (int i = 0; i < s->p.n; i++) s->p.f_ext[i][0] = s->p.id[i] == 0 ? -P : P;
}

static void settle(dem_system *s, double t)
{
    set_pull(s, 0.0);
    const long n = lround(t / DT);
    for (long k = 0; k < n; k++) dem_system_step(s);
}

/* Ramp 0 -> P over t_ramp, hold for t_hold; returns 1 if the contact stayed closed throughout,
 * *delta_end the overlap at the end. */
static int pull(dem_system *s, double P, double t_ramp, double t_hold, double *delta_end)
{
    const long nr = lround(t_ramp / DT), nh = lround(t_hold / DT);
    int bonded = 1;
    for (long k = 1; k <= nr + nh; k++) {
        set_pull(s, P * (k < nr ? (double)k / nr : 1.0));
        dem_system_step(s);
        if (overlap(s) <= 0.0) bonded = 0;
        if (overlap(s) < -0.1 * RI) break;   /* well apart: stop before they leave the domain */
    }
    *delta_end = overlap(s);
    return bonded;
}

int main(void)
{
    const clock_t t0 = clock();
    const double delta_star = golden_max(1e-12, 0.05 * RI);
    const double F_po = g_net(delta_star);
    const double delta_0 = root(0.0, delta_star, 0.05 * RI);
    printf("closed form: delta_* = %.6g m, F_po = %.6g N, delta_0 = %.6g m (%.3g %% of r_i); "
           "g(0.05 r_i) = %.3g N (< 0: the root is bracketed)\n",
           delta_star, F_po, delta_0, 100 * delta_0 / RI, g_net(0.05 * RI));

    /* 1. zero-load equilibrium */
    dem_system s;
    pair_setup(&s, 0.3 * delta_0);
    settle(&s, 0.05);
    check_rel("1. zero-load equilibrium overlap [m]", overlap(&s), delta_0, 0.02);
    printf("   (relative speed at the end %.3g m/s)\n", fabs(s.p.v[0][0] - s.p.v[1][0]));

    /* 2. 0.98 F_po from the settled state */
    double delta_end;
    const int held = pull(&s, 0.98 * F_po, 0.2, 0.1, &delta_end);
    check_true("2. pull 0.98 F_po (ramp 0.2 s, hold 0.1 s): stays bonded", held);
    const double delta_098 = root(0.98 * F_po, delta_star, delta_0);
    check_rel("2. overlap under 0.98 F_po = stable root of g = P [m]", delta_end, delta_098, 0.02);
    dem_system_free(&s);

    /* 3. 1.02 F_po */
    pair_setup(&s, 0.3 * delta_0);
    settle(&s, 0.05);
    const int held_102 = pull(&s, 1.02 * F_po, 0.2, 0.1, &delta_end);
    printf("   1.02 F_po: overlap at the end %.3g m\n", delta_end);
    check_true("3. pull 1.02 F_po (ramp 0.2 s, hold 0.1 s): separates", !held_102 && delta_end < 0.0);
    dem_system_free(&s);

    /* 4. slow ramp through the pull-off force */
    pair_setup(&s, 0.3 * delta_0);
    settle(&s, 0.05);
    double dummy;
    pull(&s, 0.9 * F_po, 0.2, 0.05, &dummy);
    const long n = lround(0.4 / DT);
    double P_open = NAN;
    for (long k = 1; k <= n; k++) {
        const double P = F_po * (0.9 + 0.2 * (double)k / n);
        set_pull(&s, P);
        dem_system_step(&s);
        if (overlap(&s) <= 0.0) { P_open = P; break; }
    }
    check_rel("4. pull at which the contact opens (slow ramp) = F_po [N]", P_open, F_po, 0.02);
    dem_system_free(&s);

    printf("(%.1f s)\n", (double)(clock() - t0) / CLOCKS_PER_SEC);
    return finish("test_cohesion");
}
