/* Adhesive normal models `jkr` and `dmt` against their closed forms.
 *
 * Spheres r = 1 mm (E 5 MPa, nu 0.45, rho 2500), work of adhesion W = 0.05 J/m^2, no gravity.
 * Y* = E / (2 (1 - nu^2)); R* = r/2 for the pair, r at the plane wall. Written here from the
 * papers' formulas, not from the library:
 *   JKR: delta(a) = a^2/R* - sqrt(2 pi W a / Y*), F(a) = 4 Y* a^3 / (3 R*) - sqrt(8 pi W Y* a^3),
 *        on the stable branch a >= a_c, a_c^3 = pi W R*^2 / (8 Y*) (a from delta by bisection);
 *        snap-in at delta = 0: F = -4/3 pi W R*; the largest pull 1.5 pi W R*
 *        at a^3 = 9 pi W R*^2 / (8 Y*); the neck breaks at delta = -delta_c = -3 a_c^2 / R*.
 *   DMT: F = 4/3 Y* sqrt(R*) delta^1.5 - 2 pi W R* while delta > 0; pull-off 2 pi W R*.
 * Checks:
 *  1. Quasi-static traces, pair and wall (positions set, velocities 0): JKR approaching from a
 *     gap feels nothing; at touching the snap-in force; loading to 20 delta_c and unloading to
 *     -0.999 delta_c follow F(delta) (1e-9 of max(|F|, pull-off force): a from delta by Newton);
 *     the smallest force of the unloading trace is -1.5 pi W R* (1e-6; the trace steps through
 *     the flat minimum) and at the closed-form pull point exactly so (1e-9); beyond -delta_c
 *     the force is 0 and stays 0 when the gap closes again to -0.5 delta_c (hysteresis);
 *     touching again snaps in again (1e-2: a small overlap). DMT: 0 in a gap, F(delta) to
 *     1e-12 of max(|F|, pull-off force), -2 pi W R* at a tiny overlap (1e-6).
 *  2. Load-controlled pull-off (pair, e = 0.3, pull ramped over 0.2 s and held 0.1 s):
 *     0.98 of the pull-off force (1.5 pi W R* for JKR, 2 pi W R* for DMT): the pair stays
 *     bonded and its overlap is the closed-form equilibrium (2 %); 1.02: it separates. */
#include "harness.h"

static const double E = 5e6, NU = 0.45, RHO = 2500, RAD = 1e-3, W = 0.05, DT = 2e-6;

static double y_eff(void) { return E / (2.0 * (1.0 - NU * NU)); }

/* ---------------------------------------------------------------- JKR closed form */
static double jkr_delta(double a, double R) { return a * a / R - sqrt(2.0 * M_PI * W * a / y_eff()); }
static double jkr_force_a(double a, double R)
{
    return 4.0 * y_eff() * a * a * a / (3.0 * R) - sqrt(8.0 * M_PI * W * y_eff() * a * a * a);
}
static double jkr_ac(double R) { return cbrt(M_PI * W * R * R / (8.0 * y_eff())); }
static double jkr_delta_c(double R) { return -jkr_delta(jkr_ac(R), R); }
/* F at overlap delta >= -delta_c on the stable branch (bisection on a in [a_c, a_hi]) */
static double jkr_force(double delta, double R)
{
    double lo = jkr_ac(R), hi = lo;
    while (jkr_delta(hi, R) < delta) hi *= 2.0;
    for (int k = 0; k < 200; k++) {
        const double mid = 0.5 * (lo + hi);
        if (jkr_delta(mid, R) < delta) lo = mid; else hi = mid;
    }
    return jkr_force_a(0.5 * (lo + hi), R);
}
static double dmt_force(double delta, double R)
{
    return delta > 0.0 ? 4.0 / 3.0 * y_eff() * sqrt(R) * pow(delta, 1.5) - 2.0 * M_PI * W * R : 0.0;
}

/* ---------------------------------------------------------------- systems */
static void setup(dem_system *s, enum dem_normal_model model, double e, int wall, double delta0)
{
    make_system(s, E, NU, RHO, e, 0.0, model, tangential_none, 0.05);
    if (model == normal_jkr) {
        const dem_jkr_params p = {W};
        dem_materials_set_model_values(&s->materials, 0, 0, SLOT_NORMAL, &p, sizeof p);
    } else {
        const dem_dmt_params p = {W};
        dem_materials_set_model_values(&s->materials, 0, 0, SLOT_NORMAL, &p, sizeof p);
    }
    s->nlist.skin = 0.5 * RAD;   /* far more than any motion here: the list is built once */
    s->dt = DT;
    if (wall) {
        add_plane(s, 0, 0, 0, 1, 0, 0);
        add_sphere(s, RAD - delta0, 0, 0, 0, 0, 0, RAD);
    } else {
        add_sphere(s, 0, 0, 0, 0, 0, 0, RAD);
        add_sphere(s, 2.0 * RAD - delta0, 0, 0, 0, 0, 0, RAD);
    }
    dem_system_setup(s);
}

/* normal force (+ repulsive) at overlap delta, particles held in place */
static double force_at(dem_system *s, int wall, double delta)
{
    if (wall) {
        s->p.x[0][0] = RAD - delta;
        dem_system_compute_forces(s);
        return s->p.f[0][0];
    }
    s->p.x[1][0] = 2.0 * RAD - delta;
    dem_system_compute_forces(s);
    return 0.5 * (s->p.f[1][0] - s->p.f[0][0]);
}

typedef double (*closed_form)(double delta, double R);

/* worst error of the model along overlaps from -> to (n steps), relative to max(|F_ref|, scale)
 * (near the zero crossing of F a relative error would only measure the cancellation);
 * *fmin: the smallest force on the way */
static double trace(dem_system *s, int wall, closed_form ref, double R, double from, double to, int n,
                    double scale, double *fmin)
{
    double worst = 0.0;
    for (int k = 1; k <= n; k++) {
        const double d = from + (to - from) * k / n, f = force_at(s, wall, d), fr = ref(d, R);
        if (fmin && f < *fmin) *fmin = f;
        worst = fmax(worst, fabs(f - fr) / fmax(fabs(fr), scale));
        if (!isfinite(f)) worst = INFINITY;
    }
    return worst;
}

/* |measured| <= bound, printed like the harness checks */
static void check_zero(const char *what, double measured, double bound)
{
    const int ok = fabs(measured) <= bound;
    printf("CHECK %-58s measured=%-12.6g bound=%-12.6g %s\n", what, measured, bound, ok ? "PASS" : "FAIL");
    if (ok) checks_passed++; else checks_failed++;
}

static void jkr_trace(int wall)
{
    const double R = wall ? RAD : 0.5 * RAD, dc = jkr_delta_c(R), fc = 1.5 * M_PI * W * R;
    const char *tag = wall ? "wall" : "pair";
    char what[120];
    dem_system s;
    setup(&s, normal_jkr, 1.0, wall, -0.9 * dc);
    printf("\nJKR %s: R* = %g m, delta_c = %.6g m, pull-off 1.5 pi W R* = %.6g N, reach %.6g m\n", tag, R, dc, fc,
           s.contact_reach);
    snprintf(what, sizeof what, "1. JKR %s: approaching, gap 0.5 delta_c: F = 0 [N]", tag);
    check_zero(what, force_at(&s, wall, -0.5 * dc), 0.0);
    snprintf(what, sizeof what, "1. JKR %s: approaching, gap 0.01 delta_c: F = 0 [N]", tag);
    check_zero(what, force_at(&s, wall, -0.01 * dc), 0.0);
    snprintf(what, sizeof what, "1. JKR %s: snap-in at touching = -4/3 pi W R* [N]", tag);
    check_rel(what, force_at(&s, wall, 0.0), -4.0 / 3.0 * M_PI * W * R, 1e-9);
    snprintf(what, sizeof what, "1. JKR %s: loading to 20 delta_c vs F(delta) (worst)", tag);
    check_zero(what, trace(&s, wall, jkr_force, R, 0.0, 20.0 * dc, 2000, fc, NULL), 1e-9);
    double fmin = INFINITY;
    snprintf(what, sizeof what, "1. JKR %s: unloading to -0.999 delta_c vs F(delta) (worst)", tag);
    check_zero(what, trace(&s, wall, jkr_force, R, 20.0 * dc, -0.999 * dc, 20000, fc, &fmin), 1e-9);
    snprintf(what, sizeof what, "1. JKR %s: smallest force of the unloading = -1.5 pi W R* [N]", tag);
    check_rel(what, fmin, -fc, 1e-6);
    const double a_pull = cbrt(9.0 * M_PI * W * R * R / (8.0 * y_eff()));
    snprintf(what, sizeof what, "1. JKR %s: force at the pull point = -1.5 pi W R* [N]", tag);
    check_rel(what, force_at(&s, wall, jkr_delta(a_pull, R)), -fc, 1e-9);
    snprintf(what, sizeof what, "1. JKR %s: beyond -delta_c (-1.001 delta_c): detached, F = 0 [N]", tag);
    check_zero(what, force_at(&s, wall, -1.001 * dc), 0.0);
    snprintf(what, sizeof what, "1. JKR %s: gap closing again to 0.5 delta_c: F = 0 [N]", tag);
    check_zero(what, force_at(&s, wall, -0.5 * dc), 0.0);
    snprintf(what, sizeof what, "1. JKR %s: touching again (overlap 1e-3 delta_c): snap-in [N]", tag);
    check_rel(what, force_at(&s, wall, 1e-3 * dc), -4.0 / 3.0 * M_PI * W * R, 1e-2);
    dem_system_free(&s);
}

static void dmt_trace(int wall)
{
    const double R = wall ? RAD : 0.5 * RAD, fc = 2.0 * M_PI * W * R, dref = 1e-6 * RAD;
    const char *tag = wall ? "wall" : "pair";
    char what[120];
    dem_system s;
    setup(&s, normal_dmt, 1.0, wall, -dref);
    printf("\nDMT %s: R* = %g m, pull-off 2 pi W R* = %.6g N\n", tag, R, fc);
    snprintf(what, sizeof what, "1. DMT %s: in a gap (0.5 um): F = 0 [N]", tag);
    check_zero(what, force_at(&s, wall, -0.5e-6), 0.0);
    snprintf(what, sizeof what, "1. DMT %s: tiny overlap (1e-15 m): F = -2 pi W R* [N]", tag);
    check_rel(what, force_at(&s, wall, 1e-15), -fc, 1e-6);
    snprintf(what, sizeof what, "1. DMT %s: loading to 20 um vs F(delta) (worst)", tag);
    check_zero(what, trace(&s, wall, dmt_force, R, 0.0, 20e-6, 2000, fc, NULL), 1e-12);
    dem_system_free(&s);
}

/* ---------------------------------------------------------------- load-controlled pull-off */
static double overlap(const dem_system *s)
{
    double d2 = 0.0;
    for (int q = 0; q < 3; q++) d2 += (s->p.x[0][q] - s->p.x[1][q]) * (s->p.x[0][q] - s->p.x[1][q]);
    return 2.0 * RAD - sqrt(d2);
}

/* Pull P apart along x: -P on id 0, +P on id 1 (found by id: the list may sort them). */
static void set_pull(dem_system *s, double P)
{
    for (int i = 0; i < s->p.n; i++) s->p.f_ext[i][0] = s->p.id[i] == 0 ? -P : P;
}

/* Settle from a light touch, ramp the pull to P over 0.2 s, hold 0.1 s: bonded throughout
 * (overlap above -limit)? *delta_end: the overlap at the end. */
static int pull(enum dem_normal_model model, double P, double limit, double *delta_end)
{
    dem_system s;
    setup(&s, model, 0.3, 0, 1e-7);
    const long n_settle = lround(0.05 / DT), nr = lround(0.2 / DT), nh = lround(0.1 / DT);
    for (long k = 0; k < n_settle; k++) dem_system_step(&s);
    int bonded = 1;
    for (long k = 1; k <= nr + nh; k++) {
        set_pull(&s, P * (k < nr ? (double)k / nr : 1.0));
        dem_system_step(&s);
        if (overlap(&s) <= -limit) bonded = 0;
        if (overlap(&s) < -0.1 * RAD) break;   /* well apart */
    }
    *delta_end = overlap(&s);
    dem_system_free(&s);
    return bonded;
}

static void pull_off(void)
{
    const double R = 0.5 * RAD, dc = jkr_delta_c(R);
    double delta_end;
    /* JKR: equilibrium under P on the branch a > a_pull: F(a) = -P (bisection) */
    const double fc_jkr = 1.5 * M_PI * W * R, P = 0.98 * fc_jkr;
    double lo = cbrt(9.0 * M_PI * W * R * R / (8.0 * y_eff())), hi = 10.0 * lo;
    for (int k = 0; k < 200; k++) {
        const double mid = 0.5 * (lo + hi);
        if (jkr_force_a(mid, R) < -P) lo = mid; else hi = mid;
    }
    const double delta_eq = jkr_delta(0.5 * (lo + hi), R);
    printf("\nload-controlled pull-off, pair (e = 0.3): JKR 1.5 pi W R* = %.6g N, equilibrium overlap under 0.98 "
           "of it %.6g m; DMT 2 pi W R* = %.6g N\n", fc_jkr, delta_eq, 2.0 * M_PI * W * R);
    check_true("2. JKR pull 0.98 x 1.5 pi W R*: stays bonded", pull(normal_jkr, P, dc, &delta_end));
    check_rel("2. JKR overlap under 0.98 x 1.5 pi W R* = equilibrium [m]", delta_end, delta_eq, 0.02);
    pull(normal_jkr, 1.02 * fc_jkr, dc, &delta_end);
    printf("   JKR 1.02: overlap at the end %.3g m\n", delta_end);
    check_true("2. JKR pull 1.02 x 1.5 pi W R*: separates", delta_end < -dc);

    const double fc_dmt = 2.0 * M_PI * W * R;
    const double delta_dmt = pow((fc_dmt - 0.98 * fc_dmt) / (4.0 / 3.0 * y_eff() * sqrt(R)), 2.0 / 3.0);
    check_true("2. DMT pull 0.98 x 2 pi W R*: stays bonded", pull(normal_dmt, 0.98 * fc_dmt, 0.0, &delta_end));
    check_rel("2. DMT overlap under 0.98 x 2 pi W R* = equilibrium [m]", delta_end, delta_dmt, 0.02);
    pull(normal_dmt, 1.02 * fc_dmt, 0.0, &delta_end);
    printf("   DMT 1.02: overlap at the end %.3g m\n", delta_end);
    check_true("2. DMT pull 1.02 x 2 pi W R*: separates", delta_end < 0.0);
}

int main(void)
{
    jkr_trace(0);
    jkr_trace(1);
    dmt_trace(0);
    dmt_trace(1);
    pull_off();
    return finish("test_adhesion");
}
