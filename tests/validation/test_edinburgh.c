/* Edinburgh elasto-plastic adhesive normal model (seed note 002, eq. 1-9) against closed forms
 * (normal model edinburgh, tangential none).
 * Material: E = 1e8 Pa, nu = 0.3, rho = 2500 kg/m^3, spheres of radius 1 mm; tangential model
 * none; the closed forms are written here from the note (Y* = E / (2 (1 - nu^2)), R* = R/2 for
 * two equal spheres and R for a sphere on a wall, the contact radius a of two equal spheres
 * a^2 = delta (4R - delta) / 4 and on a wall a^2 = 2 R delta - delta^2), not taken from the
 * library.
 *
 * Quasi-static traces: two spheres at prescribed overlaps, zero velocity, the forces recomputed
 * after each move (no step, so no list rebuild: the history delta_p,max lives on; the reload
 * checks show that it does). Points where the closed-form force is below 1e-6 of the peak load
 * are left out of the relative comparisons (the zero crossing is checked by its position).
 *  1. load-unload-reload trace (kappa21 = 5, d_ex = 1.5, c_ex = 1, gamma_s > 0 with F_min below
 *     the eq. 6 limit), path 0 -> delta1 -> 0.05 delta1 -> 1.5 delta1 -> 0, 20000 steps a leg:
 *     worst point of each branch within 1 %: loading k1 delta^d; unloading k2 (delta^d -
 *     delta_p,max^d); the tensile part of that line down to delta* (where it meets the adhesion
 *     curve); the adhesion branch -k_c delta^c (k_c, delta_min of eq. 5-6 with a(delta));
 *     reloading below the old maximum (the unloading closed form) and above it (loading); the
 *     last unloading from 1.5 delta1. Also within 1 %: the zero crossing at lambda delta1, the
 *     slope just below delta1 = k2 d delta1^(d-1) (not k1's), the tensile peak -F_min(a(delta*))
 *     and its position delta*. The regime (F_min below the eq. 6 limit) is checked.
 *  2. the same at the eq. 6 limit (kappa21 = 1.5, larger gamma_s): every point within 1 % of
 *     the closed form with the clamp F_min = 0.5 k2 delta_p,max^d, delta_min = 0.5 delta_p,max
 *     (the note as written; printed: where a(delta) drops the clamp, delta_min jumps from
 *     0.5 delta_p to 0.5^(1/d) delta_p, so the adhesion force jumps by 2^(c(1 - 1/d)), and the
 *     tensile peak exceeds the clamped F_min).
 *  3. (printed with 1 and 2) dissipated energy, trapezoid integral of the simulated F d delta
 *     over a cycle 0 -> delta1 -> 0, over the whole path of trace 1 (its inner unload-reload
 *     loop encloses no area) and over trace 2's cycle, equals the closed-form area within 2 %:
 *     loading k1 delta_m^(d+1)/(d+1) minus the unloading integral of k2 (delta^d - delta_p^d)
 *     over [delta_p, delta_m] plus the tensile work: the line analytically over
 *     [delta*, delta_p], the adhesion branch (a varies with delta) by a 200000-point midpoint
 *     rule of the closed form over [0, delta*].
 *  4. Hertz limit (kappa21 = 1.0001, gamma_s = 0, d_ex = 1.5, e = 1): loading and unloading
 *     traces equal 4/3 Y* sqrt(R*) delta^1.5 within 1 % (unloading for delta >= 0.1 delta_max,
 *     below which the plastic offset lambda^1.5 = 1e-4 of the closed form itself exceeds 0.3 %);
 *     a sphere-wall impact at 1 m/s (4000 steps per Hertz contact time): peak overlap
 *     (15 m v^2 / (16 Y* sqrt R))^(2/5) and contact time 2 I delta_max / v,
 *     I = int_0^1 (1 - x^2.5)^(-1/2) dx, within 1 %.
 * Impacts (velocity Verlet, no gravity, sphere on the plane z = 0 unless said):
 *  5. eq. 8 damping, d_ex = 1, kappa21 = 1.0001, no adhesion: restitution e within 1 % for
 *     e = 0.2, 0.5, 0.9 on a wall and 0.5 for a pair (natural log in eq. 8; the common log would
 *     give exp(log10 e), printed); 2000 steps per pi sqrt(m* / k1).
 *  6. restitution vs impact speed 0.01 ... 3 m/s (9 speeds), d_ex = 1.5, kappa21 = 5, c_ex = 1,
 *     e = 1 (no damping), 4000 steps per Hertz contact time, printed as a table. Plastic only:
 *     within 1 % of the speed-independent closed form (unloading over loading work)
 *     e^2 = kappa21 [(1 - lambda^(d+1)) - (d+1) lambda^d (1 - lambda)]. With gamma_s = 1 and 3 J/m^2: within 1 % of the closed form
 *     e^2 = (W_unload - W_tension) / W_load where that e >= 0.1 (energy balance: without damping
 *     the force is a function of delta on the way out), a capture (no rebound within 100
 *     contact times) where W_tension > W_unload, below the plastic-only e at every speed, and
 *     rising with the speed (towards the plastic-only value). The model gives no fall of e with
 *     speed from plasticity: both branches are homogeneous of degree d_ex in delta.
 *  7. the default dashpot (edinburghDamping restitution, limitForce on) at the elastic limit
 *     (kappa21 = 1.0001, gamma_s = 0): the entered e within 1 % for e = 0.3, 0.5, 0.9,
 *     d_ex = 1.5 and 2 (d_ex = 1.5 also as a pair), at 0.01, 0.1, 1 and 3 m/s. Printed beside it:
 *     seed eq. 8's constant dashpot at the same speeds (speed-dependent for d_ex != 1).
 *  8. limitForce removes only the dashpot's pull: (a) trace 1's path 0 -> delta1 -> 0 quasi-
 *     statically (no dashpot) gives the same forces, to the bit, with limitForce on and off, so
 *     adhesion stays (its tension reaches the closed-form peak within 1 %); (b) in an adhesive
 *     impact (kappa21 = 5, gamma_s = 3, e = 0.5, 0.5 m/s) with limitForce the force never falls
 *     below the adhesive branch's closed-form peak -F_min(a(delta*)) (0.1 % margin), and it does
 *     pull (below 0); (c) the non-adhesive impact of the LIGGGHTS comparison (kappa21 = 5,
 *     gamma_s = 0, e = 0.9, 0.1 m/s) rebounds by default, with e between 0.05 and the plastic-
 *     only e (printed: with eq. 8 and limitForce off the pair stays held).
 *  9. trace 1's path (0 -> delta1 -> 0.05 delta1 -> 1.5 delta1 -> 0) driven through the time
 *     steps by prescribed motion (both spheres prescribed, one at rest, the other at a constant
 *     speed per leg, 4000 steps a leg, e = 1): every point within 1 % of the closed form (points
 *     below 1e-6 of the peak load left out), through the adhesive branch (the first unloading's
 *     tensile peak within 1 % of -F_min(a(delta*))) and back up; the prescribed spheres keep their
 *     velocities exactly.
 */
#include <stdlib.h>
#include <time.h>

#include "harness.h"

static const double E_MOD = 1e8, NU = 0.3, RHO = 2500.0, RAD = 1e-3;

/* ---------- closed forms (seed 002 eq. 1-7) ---------- */
typedef struct ref_model {
    double d, c, gamma, kappa, k1, k2, lam, R;   /* R: particle radius */
    int wall;
} ref_model;

static ref_model ref_make(const dem_edinburgh_params *mp, int wall)
{
    ref_model m;
    const double Y = E_MOD / (2.0 * (1.0 - NU * NU));
    const double reff = wall ? RAD : 0.5 * RAD;
    m.d = mp->d_ex;
    m.c = mp->c_ex;
    m.gamma = mp->gamma_s;
    m.kappa = mp->kappa21;
    m.k1 = m.d == 1.0 ? 2.0 * Y * reff : 4.0 / 3.0 * Y * sqrt(reff);
    m.k2 = m.kappa * m.k1;
    m.lam = pow(1.0 - 1.0 / m.kappa, 1.0 / m.d);
    m.R = RAD;
    m.wall = wall;
    return m;
}

static double ref_a(const ref_model *m, double delta)
{
    return m->wall ? sqrt(delta * (2.0 * m->R - delta)) : 0.5 * sqrt(delta * (4.0 * m->R - delta));
}
static double ref_load(const ref_model *m, double delta) { return m->k1 * pow(delta, m->d); }
static double ref_line(const ref_model *m, double delta, double dp)
{
    return m->k2 * (pow(delta, m->d) - pow(dp, m->d));
}
/* eq. 5-6 at overlap delta with delta_p,max = dp: F_min, delta_min, whether clamped */
static void ref_fmin(const ref_model *m, double delta, double dp, double *fmin, double *dmin, int *clamped)
{
    const double f = 1.5 * M_PI * m->gamma * ref_a(m, delta), lim = 0.5 * m->k2 * pow(dp, m->d);
    *clamped = f > lim;
    *fmin = *clamped ? lim : f;
    *dmin = *clamped ? 0.5 * dp : pow(pow(dp, m->d) - f / m->k2, 1.0 / m->d);
}
static double ref_adh(const ref_model *m, double delta, double dp)
{
    double fmin, dmin;
    int cl;
    ref_fmin(m, delta, dp, &fmin, &dmin, &cl);
    return -fmin * pow(delta / dmin, m->c);
}
/* eq. 7 with the history maximum overlap dmax (delta_p,max = lambda dmax) */
static double ref_force(const ref_model *m, double delta, double dmax)
{
    if (delta >= dmax) return ref_load(m, delta);
    const double dp = m->lam * dmax;
    if (delta >= dp) return ref_line(m, delta, dp);
    const double l = ref_line(m, delta, dp), a = ref_adh(m, delta, dp);
    return l > a ? l : a;
}
/* delta*: where the unloading line meets the adhesion curve below delta_p (first crossing
 * from above, found on a grid and refined by bisection) */
static double ref_dstar(const ref_model *m, double dp)
{
    const int n = 10000;
    double hi = dp;
    for (int k = n - 1; k >= 1; k--) {
        const double x = dp * k / n;
        if (ref_line(m, x, dp) - ref_adh(m, x, dp) < 0.0) {
            double lo = x;
            for (int it = 0; it < 200; it++) {
                const double mid = 0.5 * (lo + hi);
                if (ref_line(m, mid, dp) - ref_adh(m, mid, dp) < 0.0) lo = mid; else hi = mid;
            }
            return 0.5 * (lo + hi);
        }
        hi = x;
    }
    return 0.0;
}
static double ref_work_load(const ref_model *m, double dm) { return m->k1 * pow(dm, m->d + 1) / (m->d + 1); }
/* work returned on the unloading line from dm down to dp = lambda dm */
static double ref_work_unload(const ref_model *m, double dm)
{
    const double dp = m->lam * dm, d = m->d;
    return m->k2 * ((pow(dm, d + 1) - pow(dp, d + 1)) / (d + 1) - pow(dp, d) * (dm - dp));
}
/* work against the tension from dp down to 0: the line analytically over [delta*, dp], the rest
 * by the midpoint rule */
static double ref_work_tension(const ref_model *m, double dm)
{
    const double dp = m->lam * dm, d = m->d;
    if (m->gamma == 0.0) return 0.0;
    const double ds = ref_dstar(m, dp);
    double w = m->k2 * (pow(dp, d) * (dp - ds) - (pow(dp, d + 1) - pow(ds, d + 1)) / (d + 1));
    const int n = 200000;
    const double h = ds / n;
    for (int k = 0; k < n; k++) w -= h * ref_force(m, (k + 0.5) * h, dm);
    return w;
}

/* ---------- quasi-static traces ---------- */
typedef struct trace {
    int n, cap;
    double *d, *f;
} trace;

static void trace_push(trace *t, double d, double f)
{
    if (t->n == t->cap) {
        t->cap = t->cap ? 2 * t->cap : 1024;
        t->d = realloc(t->d, (size_t)t->cap * sizeof(double));
        t->f = realloc(t->f, (size_t)t->cap * sizeof(double));
    }
    t->d[t->n] = d;
    t->f[t->n] = f;
    t->n++;
}

static void pair_system(dem_system *s, const dem_edinburgh_params *mp)
{
    make_system(s, E_MOD, NU, RHO, 1.0, 0.0, normal_edinburgh, tangential_none, 0.01);
    dem_materials_set_model_values(&s->materials, 0, 0, SLOT_NORMAL, mp, sizeof *mp);
    s->nlist.skin = 0.5 * RAD;   /* more than any overlap used: the list is built once */
    add_sphere(s, 0, 0, 0, 0, 0, 0, RAD);
    add_sphere(s, 2.0 * RAD, 0, 0, 0, 0, 0, RAD);
    dem_system_setup(s);
}

/* normal force (+ repulsive) at overlap delta */
static double pair_force(dem_system *s, double delta)
{
    s->p.x[1][0] = 2.0 * RAD - delta;
    dem_system_compute_forces(s);
    return 0.5 * (s->p.f[1][0] - s->p.f[0][0]);
}

/* overlaps from (excluded) to `to` (included) in n equal steps */
static void leg(dem_system *s, trace *t, double from, double to, int n)
{
    for (int k = 1; k <= n; k++) {
        const double d = from + (to - from) * k / n;
        trace_push(t, d, pair_force(s, d));
    }
}

static double trapezoid(const trace *t, int i0, int i1)
{
    double w = 0.0;
    for (int i = i0 + 1; i <= i1; i++) w += 0.5 * (t->f[i] + t->f[i - 1]) * (t->d[i] - t->d[i - 1]);
    return w;
}

/* worst relative deviation of trace points [i0, i1] from ref_force with history max dmax
 * before the leg (0 on first loading: the history is the overlap itself),
 * restricted to lo <= delta <= hi and |F_ref| >= floor; checks it against tol */
static void check_branch(const char *what, const ref_model *m, const trace *t, int i0, int i1,
                         double dmax, double lo, double hi, double floor, double tol)
{
    int worst = -1, count = 0;
    double err = -1.0;
    for (int i = i0; i <= i1; i++) {
        const double d = t->d[i];
        if (d < lo || d > hi) continue;
        const double fr = ref_force(m, d, fmax(dmax, d));
        if (fabs(fr) < floor) continue;
        count++;
        const double e = fabs(t->f[i] - fr) / fabs(fr);
        if (e > err) { err = e; worst = i; }
    }
    char buf[160];
    snprintf(buf, sizeof buf, "%s (worst of %d)", what, count);
    if (worst < 0) { check_true(buf, 0); return; }
    check_rel(buf, t->f[worst], ref_force(m, t->d[worst], fmax(dmax, t->d[worst])), tol);
}

static dem_edinburgh_params edin_params(double kappa, double gamma, double d, double c)
{
    dem_edinburgh_params mp;
    memset(&mp, 0, sizeof mp);
    mp.kappa21 = kappa;
    mp.gamma_s = gamma;
    mp.d_ex = d;
    mp.c_ex = c;
    return mp;
}

static const int NLEG = 20000;

static void trace_main(void)
{
    const double d1 = 2e-6, gamma = 4.0;
    const dem_edinburgh_params mp = edin_params(5.0, gamma, 1.5, 1.0);
    const ref_model m = ref_make(&mp, 0);
    const double d2 = 1.5 * d1, dlow = 0.05 * d1, dp1 = m.lam * d1;
    const double fpeak = ref_load(&m, d1), floor = 1e-6 * fpeak;
    double fmin_star, dmin_star;
    int clamped;
    const double ds1 = ref_dstar(&m, dp1);
    ref_fmin(&m, ds1, dp1, &fmin_star, &dmin_star, &clamped);
    double fa_dp, dm_dp;
    int cl_dp;
    ref_fmin(&m, dp1, dp1, &fa_dp, &dm_dp, &cl_dp);
    printf("\n1. trace kappa21=5 d_ex=1.5 c_ex=1 gamma_s=%g J/m^2: k1=%.5g k2=%.5g lambda=%.5f\n"
           "   delta1=%g m, peak load %.5g N, delta_p,max=%.5g m, delta*=%.5g m (delta_min there %.5g), "
           "F_min(a(delta*))=%.5g N;\n   at delta_p,max: 1.5 pi gamma a=%.5g N vs the eq. 6 limit "
           "0.5 k2 delta_p^d=%.5g N\n",
           gamma, m.k1, m.k2, m.lam, d1, fpeak, dp1, ds1, dmin_star, fmin_star,
           1.5 * M_PI * gamma * ref_a(&m, dp1), 0.5 * m.k2 * pow(dp1, m.d));
    check_true("trace 1: F_min below the eq. 6 limit at delta_p,max", !cl_dp && !clamped);

    dem_system s;
    pair_system(&s, &mp);
    trace t = {0};
    trace_push(&t, 0.0, 0.0);
    leg(&s, &t, 0.0, d1, NLEG);
    const int e1 = t.n - 1;
    leg(&s, &t, d1, dlow, NLEG);
    const int e2 = t.n - 1;
    leg(&s, &t, dlow, d2, NLEG);
    const int e3 = t.n - 1;
    leg(&s, &t, d2, 0.0, NLEG);
    const int e4 = t.n - 1;

    check_branch("trace 1 loading: k1 delta^d", &m, &t, 1, e1, 0, 0, d1, floor, 0.01);
    check_branch("trace 1 unloading above delta_p: k2 (d^d - dp^d)", &m, &t, e1 + 1, e2, d1, dp1, d1, floor, 0.01);
    check_branch("trace 1 tension on the line (delta*, delta_p)", &m, &t, e1 + 1, e2, d1, ds1, dp1, floor, 0.01);
    check_branch("trace 1 adhesion branch -k_c delta^c (< delta*)", &m, &t, e1 + 1, e2, d1, 0, ds1, floor, 0.01);
    check_branch("trace 1 reload below the old max (unloading form)", &m, &t, e2 + 1, e3, d1, 0, d1, floor, 0.01);
    check_branch("trace 1 reload above the old max: k1 delta^d", &m, &t, e2 + 1, e3, d1, d1 * (1 + 1e-12), d2, floor, 0.01);
    check_branch("trace 1 last unloading from 1.5 delta1 (all branches)", &m, &t, e3 + 1, e4 - 1, d2, 0, d2, floor, 0.01);

    /* zero crossing of the first unloading: lambda delta1 */
    double dzero = NAN;
    for (int i = e1 + 1; i <= e2; i++)
        if (t.f[i - 1] > 0.0 && t.f[i] <= 0.0) {
            dzero = t.d[i - 1] + (t.d[i] - t.d[i - 1]) * t.f[i - 1] / (t.f[i - 1] - t.f[i]);
            break;
        }
    check_rel("trace 1 zero force at lambda delta1", dzero, dp1, 0.01);

    /* slope just below delta1: k2 d delta1^(d-1), five times k1's */
    const double slope = (t.f[e1] - t.f[e1 + 1]) / (t.d[e1] - t.d[e1 + 1]);
    printf("   slope below delta1 %.6g N/m (loading slope there %.6g)\n", slope, m.k1 * m.d * pow(d1, m.d - 1));
    check_rel("trace 1 unloading slope at delta1 = k2 d delta1^(d-1)", slope, m.k2 * m.d * pow(d1, m.d - 1), 0.01);

    /* tensile peak of the first unloading: -F_min(a(delta*)) at delta* */
    int imin = e1 + 1;
    for (int i = e1 + 1; i <= e2; i++) if (t.f[i] < t.f[imin]) imin = i;
    check_rel("trace 1 tensile peak = -F_min(a(delta*)) (eq. 5)", t.f[imin], -fmin_star, 0.01);
    check_rel("trace 1 tensile peak position delta*", t.d[imin], ds1, 0.01);

    /* energy: the whole path (the inner loop encloses no area) */
    const double w_path = trapezoid(&t, 0, e4);
    const double w_path_ref = ref_work_load(&m, d2) - ref_work_unload(&m, d2) + ref_work_tension(&m, d2);
    check_rel("energy: trace 1 whole path vs closed-form area", w_path, w_path_ref, 0.02);
    dem_system_free(&s);

    /* energy: a single cycle 0 -> delta1 -> 0 */
    pair_system(&s, &mp);
    trace c = {0};
    trace_push(&c, 0.0, 0.0);
    leg(&s, &c, 0.0, d1, NLEG);
    leg(&s, &c, d1, 0.0, NLEG);
    const double w_cyc = trapezoid(&c, 0, c.n - 1);
    const double wl = ref_work_load(&m, d1), wu = ref_work_unload(&m, d1), wt = ref_work_tension(&m, d1);
    printf("   cycle to delta1: loading work %.6g J, returned %.6g J, tensile work %.6g J\n", wl, wu, wt);
    check_rel("energy: cycle 0 -> delta1 -> 0 vs closed-form area", w_cyc, wl - wu + wt, 0.02);
    dem_system_free(&s);
    free(t.d); free(t.f); free(c.d); free(c.f);
}

static void trace_limit(void)
{
    const double d1 = 2e-6, gamma = 20.0;
    const dem_edinburgh_params mp = edin_params(1.5, gamma, 1.5, 1.0);
    const ref_model m = ref_make(&mp, 0);
    const double dp1 = m.lam * d1, fpeak = ref_load(&m, d1);
    const double lim = 0.5 * m.k2 * pow(dp1, m.d);
    printf("\n2. trace at the eq. 6 limit, kappa21=1.5 gamma_s=%g: at delta_p,max 1.5 pi gamma a=%.5g N "
           "> limit %.5g N\n", gamma, 1.5 * M_PI * gamma * ref_a(&m, dp1), lim);
    /* where 1.5 pi gamma a(delta) falls below the limit: delta_min jumps from 0.5 delta_p
     * to 0.5^(1/d) delta_p there */
    double lo = 0.0, hi = dp1;
    for (int it = 0; it < 200; it++) {
        const double mid = 0.5 * (lo + hi);
        if (1.5 * M_PI * gamma * ref_a(&m, mid) > lim) hi = mid; else lo = mid;
    }
    const double dc = 0.5 * (lo + hi);
    const double ds = ref_dstar(&m, dp1);
    printf("   clamp active above delta=%.5g m (%.3f delta_p); line meets adhesion at delta*=%.5g m, "
           "tensile peak there %.5g N (clamped F_min %.5g N)\n", dc, dc / dp1, ds,
           ref_force(&m, ds, d1), lim);
    check_true("trace 2: F_min at the eq. 6 limit at delta_p,max", 1.5 * M_PI * gamma * ref_a(&m, dp1) > lim);

    dem_system s;
    pair_system(&s, &mp);
    trace t = {0};
    trace_push(&t, 0.0, 0.0);
    leg(&s, &t, 0.0, d1, NLEG);
    const int e1 = t.n - 1;
    leg(&s, &t, d1, 0.0, NLEG);
    const int e2 = t.n - 1;
    check_branch("trace 2 loading", &m, &t, 1, e1, 0, 0, d1, 1e-6 * fpeak, 0.01);
    check_branch("trace 2 unloading, all branches (clamped eq. 6)", &m, &t, e1 + 1, e2 - 1, d1, 0, d1, 1e-6 * fpeak, 0.01);
    int imin = e1 + 1;
    for (int i = e1 + 1; i <= e2; i++) if (t.f[i] < t.f[imin]) imin = i;
    printf("   simulated tensile peak %.5g N at %.5g m; jump of the adhesion force at %.5g m: "
           "%.5g N -> %.5g N\n", t.f[imin], t.d[imin], dc, ref_adh(&m, dc * (1 + 1e-9), dp1), ref_adh(&m, dc * (1 - 1e-9), dp1));
    for (int i = e1 + 2; i <= e2; i++)
        if (t.d[i - 1] >= dc && t.d[i] < dc)
            printf("   simulated on both sides of it: F(%.6g m) = %.6g N, F(%.6g m) = %.6g N\n",
                   t.d[i - 1], t.f[i - 1], t.d[i], t.f[i]);
    const double w = trapezoid(&t, 0, e2);
    const double wr = ref_work_load(&m, d1) - ref_work_unload(&m, d1) + ref_work_tension(&m, d1);
    check_rel("energy: trace 2 cycle vs closed-form area", w, wr, 0.02);
    dem_system_free(&s);
    free(t.d); free(t.f);
}

static void trace_hertz(void)
{
    const double d1 = 1e-5;
    const dem_edinburgh_params mp = edin_params(1.0001, 0.0, 1.5, 1.0);
    const double Y = E_MOD / (2.0 * (1.0 - NU * NU)), kh = 4.0 / 3.0 * Y * sqrt(0.5 * RAD);
    dem_system s;
    pair_system(&s, &mp);
    double wl = 0.0, wu = 0.0, fl = 0, fu = 0, rl = 1, ru = 1;
    for (int k = 1; k <= NLEG; k++) {
        const double d = d1 * k / NLEG, f = pair_force(&s, d), r = kh * pow(d, 1.5);
        if (fabs(f - r) / r > wl) { wl = fabs(f - r) / r; fl = f; rl = r; }
    }
    for (int k = NLEG - 1; k >= 1; k--) {
        const double d = d1 * k / NLEG, f = pair_force(&s, d), r = kh * pow(d, 1.5);
        if (d >= 0.1 * d1 && fabs(f - r) / r > wu) { wu = fabs(f - r) / r; fu = f; ru = r; }
    }
    printf("\n4. Hertz limit kappa21=1.0001 gamma_s=0 d_ex=1.5 e=1, pair, delta_max=%g m\n", d1);
    check_rel("hertz limit: loading 4/3 Y* sqrt(R*) delta^1.5 (worst)", fl, rl, 0.01);
    check_rel("hertz limit: unloading, delta >= 0.1 delta_max (worst)", fu, ru, 0.01);
    dem_system_free(&s);
}

/* ---------- impacts ---------- */
typedef struct impact_out {
    double restitution, contact_time, max_overlap, dt, min_force;
    int captured;
} impact_out;

/* sphere on the plane z = 0 (wall) or two spheres head on, approach speed v; dt = t_scale / steps;
 * limitForce and edinburghDamping seedEq8 as given */
static impact_out edin_impact_with(const dem_edinburgh_params *mp, double e, int wall, double v, double t_scale,
                                   double steps, int limit, int seed_eq8)
{
    dem_system s;
    make_system(&s, E_MOD, NU, RHO, e, 0.0, normal_edinburgh, tangential_none, 0.01);
    dem_materials_set_model_values(&s.materials, 0, 0, SLOT_NORMAL, mp, sizeof *mp);
    s.models.fn_floor = limit ? 0.0 : -INFINITY;
    const dem_edinburgh_case ec = {seed_eq8};
    SET_MODEL_CASE(&s, SLOT_NORMAL, ec);
    s.dt = t_scale / steps;
    s.nlist.skin = 0.05 * RAD;
    if (wall) {
        add_plane(&s, 0, 0, 0, 0, 0, 1);
        add_sphere(&s, 0, 0, RAD, 0, 0, -v, RAD);
    } else {
        add_sphere(&s, 0, 0, -RAD, 0, 0, 0.5 * v, RAD);
        add_sphere(&s, 0, 0, RAD, 0, 0, -0.5 * v, RAD);
    }
    dem_system_setup(&s);
    impact_out o = {0};
    o.dt = s.dt;
    int touched = 0;
    long in_contact = 0;
    const long max_steps = (long)(100 * steps);
    long k;
    for (k = 0; k < max_steps; k++) {
        dem_system_step(&s);
        const double overlap = wall ? RAD - s.p.x[0][2] : 2.0 * RAD - (s.p.x[1][2] - s.p.x[0][2]);
        if (overlap > o.max_overlap) o.max_overlap = overlap;
        const double fn = wall ? s.p.f[0][2] : s.p.f[1][2];   /* + repulsive */
        if (fn < o.min_force) o.min_force = fn;
        if (overlap > 0) { touched = 1; in_contact++; }
        else if (touched) break;
    }
    o.captured = k == max_steps;
    o.restitution = o.captured ? 0.0 : (wall ? s.p.v[0][2] : s.p.v[1][2] - s.p.v[0][2]) / v;
    o.contact_time = in_contact * s.dt;
    dem_system_free(&s);
    return o;
}

/* limitForce off, the restitution-keeping dashpot */
static impact_out edin_impact(const dem_edinburgh_params *mp, double e, int wall, double v, double t_scale, double steps)
{
    return edin_impact_with(mp, e, wall, v, t_scale, steps, 0, 0);
}

static double sphere_mass(void) { return RHO * 4.0 / 3.0 * M_PI * pow(RAD, 3); }

/* Hertz peak overlap and contact time (sphere on a wall) */
static double hertz_peak(double v)
{
    const double Y = E_MOD / (2.0 * (1.0 - NU * NU));
    return pow(15.0 * sphere_mass() * v * v / (16.0 * Y * sqrt(RAD)), 0.4);
}
static double hertz_time(double v)
{
    const double I = tgamma(1.4) * tgamma(0.5) / tgamma(0.9);   /* int_0^1 (1 - x^2.5)^-1/2 dx */
    return 2.0 * I * hertz_peak(v) / v;
}

static void impact_hertz(void)
{
    const dem_edinburgh_params mp = edin_params(1.0001, 0.0, 1.5, 1.0);
    const double v = 1.0;
    const impact_out o = edin_impact(&mp, 1.0, 1, v, hertz_time(v), 4000);
    printf("   wall impact at %g m/s: restitution %.6f, peak overlap %.6g m, contact time %.6g s\n",
           v, o.restitution, o.max_overlap, o.contact_time);
    check_rel("hertz limit impact: peak overlap", o.max_overlap, hertz_peak(v), 0.01);
    check_rel("hertz limit impact: contact time", o.contact_time, hertz_time(v), 0.01);
}

static void impact_damping(void)
{
    printf("\n5. eq. 8 damping: d_ex=1, kappa21=1.0001, gamma_s=0\n");
    const dem_edinburgh_params mp = edin_params(1.0001, 0.0, 1.0, 1.0);
    const double es[] = {0.2, 0.5, 0.9};
    const double Y = E_MOD / (2.0 * (1.0 - NU * NU));
    for (int wall = 1; wall >= 0; wall--)
        for (int q = 0; q < 3; q++) {
            if (!wall && q != 1) continue;
            const double meff = wall ? sphere_mass() : 0.5 * sphere_mass();
            const double k1 = 2.0 * Y * (wall ? RAD : 0.5 * RAD);
            const impact_out o = edin_impact_with(&mp, es[q], wall, 0.5, M_PI * sqrt(meff / k1), 2000, 0, 1);
            char what[128];
            snprintf(what, sizeof what, "eq. 8 damping %s e=%g (natural log)", wall ? "wall" : "pair", es[q]);
            check_rel(what, o.restitution, es[q], 0.01);
            printf("   (the common log would give e = %.4f)\n", exp(log10(es[q])));
        }
}

static void impact_speed(void)
{
    const double speeds[] = {0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1.0, 2.0, 3.0};
    enum { NS = sizeof speeds / sizeof speeds[0], NG = 2 };
    const double gammas[NG] = {1.0, 3.0};
    const dem_edinburgh_params mp_pl = edin_params(5.0, 0.0, 1.5, 1.0);
    const ref_model mpl = ref_make(&mp_pl, 1);
    const double l = mpl.lam, dd = mpl.d, m = sphere_mass();
    const double e_pl = sqrt(mpl.kappa * ((1 - pow(l, dd + 1)) - (dd + 1) * pow(l, dd) * (1 - l)));
    printf("\n6. restitution vs impact speed, sphere on a wall, d_ex=1.5 kappa21=5 c_ex=1 e=1 (no damping)\n"
           "   plastic-only closed form e = %.6f (speed independent); e_ref: closed form with adhesion;\n"
           "   W_t/W_l: tensile over loading work; 0 = captured (no rebound within 100 contact times)\n", e_pl);
    printf("   %7s %10s | %10s %10s %9s | %10s %10s %9s\n", "v [m/s]", "e plastic", "e g=1", "e_ref g=1",
           "W_t/W_l", "e g=3", "e_ref g=3", "W_t/W_l");
    double e_sim[NG][NS], e_ref[NG][NS], e_plv[NS];
    int captured[NG][NS], e2neg[NG][NS], clamped_any = 0;
    double wt_wl[NG][NS];
    for (int k = 0; k < NS; k++) {
        const double v = speeds[k];
        e_plv[k] = edin_impact(&mp_pl, 1.0, 1, v, hertz_time(v), 4000).restitution;
        for (int g = 0; g < NG; g++) {
            const dem_edinburgh_params mp = edin_params(5.0, gammas[g], 1.5, 1.0);
            const ref_model mr = ref_make(&mp, 1);
            const impact_out o = edin_impact(&mp, 1.0, 1, v, hertz_time(v), 4000);
            /* closed form: delta_m from loading work = kinetic energy; rebound energy = work
             * returned on the unloading line - work against the tension */
            const double dm = pow(0.5 * m * v * v * (dd + 1) / mr.k1, 1.0 / (dd + 1));
            const double wl = ref_work_load(&mr, dm), wu = ref_work_unload(&mr, dm), wt = ref_work_tension(&mr, dm);
            const double e2 = (wu - wt) / wl;
            double fmin, dmin;
            int cl;
            ref_fmin(&mr, mr.lam * dm, mr.lam * dm, &fmin, &dmin, &cl);
            clamped_any |= cl;
            e_sim[g][k] = o.restitution;
            captured[g][k] = o.captured;
            e2neg[g][k] = e2 <= 0.0;
            e_ref[g][k] = e2 > 0 ? sqrt(e2) : 0.0;
            wt_wl[g][k] = wt / wl;
        }
        printf("   %7g %10.6f | %10.6f %10.6f %9.4f | %10.6f %10.6f %9.4f\n", v, e_plv[k], e_sim[0][k],
               e_ref[0][k], wt_wl[0][k], e_sim[1][k], e_ref[1][k], wt_wl[1][k]);
    }
    printf("   (F_min at the eq. 6 limit in any of these impacts: %s)\n", clamped_any ? "yes" : "no");
    char what[128];
    for (int k = 0; k < NS; k++) {
        snprintf(what, sizeof what, "e(v) plastic only, v=%g m/s vs closed form", speeds[k]);
        check_rel(what, e_plv[k], e_pl, 0.01);
    }
    for (int g = 0; g < NG; g++) {
        int below = 1, rising = 1;
        for (int k = 0; k < NS; k++) {
            if (e_ref[g][k] >= 0.1) {
                snprintf(what, sizeof what, "e(v) gamma_s=%g, v=%g m/s vs closed form", gammas[g], speeds[k]);
                check_rel(what, e_sim[g][k], e_ref[g][k], 0.01);
            } else if (e2neg[g][k]) {
                snprintf(what, sizeof what, "e(v) gamma_s=%g, v=%g: captured, as W_t > W_unload", gammas[g], speeds[k]);
                check_true(what, captured[g][k]);
            } else {
                printf("   gamma_s=%g v=%g: closed-form e %.4f < 0.1 not compared (simulated %.4f)\n",
                       gammas[g], speeds[k], e_ref[g][k], e_sim[g][k]);
            }
            if (!(e_sim[g][k] < e_plv[k])) below = 0;
            if (k > 0 && !(e_sim[g][k] > e_sim[g][k - 1] || (e_sim[g][k] == 0.0 && e_sim[g][k - 1] == 0.0)))
                rising = 0;
        }
        snprintf(what, sizeof what, "e(v) gamma_s=%g below the plastic-only e at every speed", gammas[g]);
        check_true(what, below);
        snprintf(what, sizeof what, "e(v) gamma_s=%g rises with the impact speed", gammas[g]);
        check_true(what, rising);
    }
    printf("   This model: plasticity alone gives a speed-independent e (loading and unloading\n"
           "   branches are both homogeneous of degree d_ex in delta), so e does NOT fall with\n"
           "   speed as plasticity grows; adhesion takes a tensile work ~ gamma_s a delta_p that\n"
           "   grows more slowly with delta_m than the loading work ~ delta_m^(d+1), so it lowers e\n"
           "   most at low speed (down to capture) and e rises towards the plastic-only value as v grows.\n");
}

static void impact_default_damping(void)
{
    printf("\n7. default dashpot (restitution, limitForce on) at the elastic limit, kappa21=1.0001, gamma_s=0\n"
           "   %-22s %7s %10s %10s\n", "case", "v [m/s]", "e", "eq. 8 e");
    const double speeds[] = {0.01, 0.1, 1.0, 3.0}, es[] = {0.3, 0.5, 0.9}, ds[] = {1.5, 2.0};
    for (int a = 0; a < 2; a++)
        for (int wall = 1; wall >= 0; wall--) {
            if (!wall && a != 0) continue;
            const dem_edinburgh_params mp = edin_params(1.0001, 0.0, ds[a], 1.0);
            for (int q = 0; q < 3; q++)
                for (int k = 0; k < 4; k++) {
                    const double v = speeds[k];
                    const impact_out o = edin_impact_with(&mp, es[q], wall, v, hertz_time(v), 4000, 1, 0);
                    const impact_out o8 = edin_impact_with(&mp, es[q], wall, v, hertz_time(v), 4000, 1, 1);
                    char what[128];
                    snprintf(what, sizeof what, "default dashpot d_ex=%g %s e=%g v=%g", ds[a], wall ? "wall" : "pair",
                             es[q], v);
                    printf("   d_ex=%g %s e=%g %7g %10.5f %10.5f\n", ds[a], wall ? "wall" : "pair", es[q], v,
                           o.restitution, o8.restitution);
                    check_rel(what, o.restitution, es[q], 0.01);
                }
        }
}

static void limit_force_keeps_adhesion(void)
{
    printf("\n8. limitForce removes only the dashpot's pull\n");
    const double d1 = 2e-6;
    const dem_edinburgh_params mp = edin_params(5.0, 4.0, 1.5, 1.0);   /* trace 1 */
    const ref_model m = ref_make(&mp, 0);
    trace t[2] = {{0}};
    for (int limit = 0; limit <= 1; limit++) {
        dem_system s;
        pair_system(&s, &mp);
        s.models.fn_floor = limit ? 0.0 : -INFINITY;
        leg(&s, &t[limit], 0.0, d1, NLEG);
        leg(&s, &t[limit], d1, 0.0, NLEG);
        dem_system_free(&s);
    }
    int same = t[0].n == t[1].n;
    double fmin = 0.0;
    for (int k = 0; same && k < t[0].n; k++) {
        same &= t[0].f[k] == t[1].f[k];
        fmin = fmin < t[1].f[k] ? fmin : t[1].f[k];
    }
    check_true("quasi-static trace 0 -> delta1 -> 0: limitForce on = off, bit for bit", same);
    double fmin_star, dmin_star;
    int clamped;
    ref_fmin(&m, ref_dstar(&m, m.lam * d1), m.lam * d1, &fmin_star, &dmin_star, &clamped);
    check_rel("quasi-static trace with limitForce: tensile peak = -F_min(a(delta*))", fmin, -fmin_star, 0.01);
    for (int k = 0; k < 2; k++) { free(t[k].d); free(t[k].f); }

    /* an adhesive impact: the force stays above the adhesive branch, and does pull */
    const dem_edinburgh_params ma = edin_params(5.0, 3.0, 1.5, 1.0);
    const ref_model mr = ref_make(&ma, 1);
    const double v = 0.5, mass = sphere_mass();
    const double dm = pow(0.5 * mass * v * v * (mr.d + 1) / mr.k1, 1.0 / (mr.d + 1));
    ref_fmin(&mr, ref_dstar(&mr, mr.lam * dm), mr.lam * dm, &fmin_star, &dmin_star, &clamped);
    const impact_out on = edin_impact_with(&ma, 0.5, 1, v, hertz_time(v), 4000, 1, 0);
    const impact_out off = edin_impact_with(&ma, 0.5, 1, v, hertz_time(v), 4000, 0, 0);
    printf("   adhesive impact gamma_s=3 e=0.5 %g m/s: min Fn %.5g N with limitForce, %.5g N without; "
           "adhesive peak of the undamped path -F_min(a(delta*)) = %.5g N; e %.4f / %.4f\n",
           v, on.min_force, off.min_force, -fmin_star, on.restitution, off.restitution);
    check_true("adhesive impact with limitForce: min Fn >= -1.001 F_min(a(delta*))", on.min_force >= -1.001 * fmin_star);
    check_true("adhesive impact with limitForce: the contact still pulls (min Fn < 0)", on.min_force < 0.0);

    /* the LIGGGHTS comparison's non-adhesive impact */
    const dem_edinburgh_params mn = edin_params(5.0, 0.0, 1.5, 1.0);
    const ref_model mpl = ref_make(&mn, 1);
    const double l = mpl.lam, dd = mpl.d;
    const double e_pl = sqrt(mpl.kappa * ((1 - pow(l, dd + 1)) - (dd + 1) * pow(l, dd) * (1 - l)));
    const impact_out def = edin_impact_with(&mn, 0.9, 1, 0.1, hertz_time(0.1), 4000, 1, 0);
    const impact_out old = edin_impact_with(&mn, 0.9, 1, 0.1, hertz_time(0.1), 4000, 0, 1);
    printf("   non-adhesive kappa21=5 e=0.9 0.1 m/s: e %.4f by default (plastic-only %.4f); eq. 8 without "
           "limitForce: %s (e %.4f)\n", def.restitution, e_pl, old.captured ? "held, no rebound" : "rebounds",
           old.restitution);
    check_true("non-adhesive impact rebounds by default (not held)", !def.captured);
    check_true("non-adhesive impact: 0.05 < e < plastic-only e", def.restitution > 0.05 && def.restitution < e_pl);
}

static void trace_prescribed(void)
{
    printf("\n9. trace 1 driven by prescribed motion (dem_system_step)\n");
    const double d1 = 2e-6;
    const dem_edinburgh_params mp = edin_params(5.0, 4.0, 1.5, 1.0);
    const ref_model m = ref_make(&mp, 0);
    dem_system s;
    make_system(&s, E_MOD, NU, RHO, 1.0, 0.0, normal_edinburgh, tangential_none, 0.01);
    dem_materials_set_model_values(&s.materials, 0, 0, SLOT_NORMAL, &mp, sizeof mp);
    s.nlist.skin = 0.5 * RAD;
    add_sphere(&s, 0, 0, 0, 0, 0, 0, RAD);
    add_sphere(&s, 2.0 * RAD, 0, 0, 0, 0, 0, RAD);
    dem_particles_prescribe(&s.p, 0);
    dem_particles_prescribe(&s.p, 1);
    s.dt = 1e-7;
    dem_system_setup(&s);
    const double targets[] = {d1, 0.05 * d1, 1.5 * d1, 0.0};
    const int n = 4000;
    const double fpeak = ref_load(&m, 1.5 * d1);
    double delta = 0.0, dmax = 0.0, worst = 0.0, fmin = 0.0, worst_at = 0.0;
    int count = 0, kept = 1;
    for (int leg = 0; leg < 4; leg++) {
        const double speed = (targets[leg] - delta) / (n * s.dt);
        s.p.v[1][0] = -speed;
        for (int k = 0; k < n; k++) {
            dem_system_step(&s);
            kept &= s.p.v[1][0] == -speed && s.p.v[0][0] == 0.0;
            const int i0 = s.p.id[0] == 0 ? 0 : 1, i1 = 1 - i0;   /* (no sort in 16000 steps, but by id) */
            delta = 2.0 * RAD - (s.p.x[i1][0] - s.p.x[i0][0]);
            if (delta <= 0.0) continue;
            dmax = fmax(dmax, delta);
            const double f = 0.5 * (s.p.f[i1][0] - s.p.f[i0][0]);
            if (leg == 1) fmin = fmin < f ? fmin : f;   /* the first unloading, as in trace 1 */
            const double fr = ref_force(&m, delta, dmax);
            if (fabs(fr) < 1e-6 * fpeak) continue;
            count++;
            const double e = fabs(f - fr) / fabs(fr);
            if (e > worst) { worst = e; worst_at = delta; }
        }
    }
    double fmin_star, dmin_star;
    int clamped;
    const double dp1 = m.lam * d1;
    ref_fmin(&m, ref_dstar(&m, dp1), dp1, &fmin_star, &dmin_star, &clamped);
    printf("   %d points compared, worst relative error %.3g at delta = %.4g m; tensile peak of the first unloading %.6g N "
           "(closed form %.6g N)\n", count, worst, worst_at, fmin, -fmin_star);
    check_rel("prescribed-motion trace: worst point vs closed form (1 + error vs 1)", 1.0 + worst, 1.0, 0.01);
    check_rel("prescribed-motion trace: tensile peak = -F_min(a(delta*))", fmin, -fmin_star, 0.01);
    check_true("prescribed-motion trace: the spheres kept their prescribed velocities", kept);
    check_true("prescribed-motion trace: more than 10000 points compared", count > 10000);
    dem_system_free(&s);
}

int main(void)
{
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    trace_main();
    trace_limit();
    trace_hertz();
    impact_hertz();
    impact_damping();
    impact_speed();
    impact_default_damping();
    limit_force_keeps_adhesion();
    trace_prescribed();
    clock_gettime(CLOCK_MONOTONIC, &t1);
    printf("run time %.2f s\n", (t1.tv_sec - t0.tv_sec) + 1e-9 * (t1.tv_nsec - t0.tv_nsec));
    return finish("test_edinburgh");
}
