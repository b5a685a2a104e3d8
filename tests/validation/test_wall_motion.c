/* Rigid and moving walls against closed forms (Hertz, sphere on a wall, no gravity unless said).
 *  1. Chung & Ooi (2011) test 2, elastic normal impact on a rigid plane: aluminium alloy
 *     (E 7.0e10 Pa, nu 0.30, rho 2699) and magnesium alloy (4.0e10, 0.35, 1800), R = 0.1 m,
 *     0.2 m/s, e = 1 (the values as the YADE reproduction of the benchmark gives them). Peak
 *     overlap (15 m v^2 / (16 E* sqrt R))^(2/5), peak force 4/3 E* sqrt(R) delta_max^1.5 and
 *     contact time 2 I delta_max / v, I = sqrt(pi) Gamma(7/5) / Gamma(9/10), E* = E / (1 - nu^2)
 *     (the wall adds no compliance), each within 0.1 %; 10000 steps per contact time. Printed:
 *     the same against the stiffest elastic wall the reader accepts (E = 1e13 Pa).
 *  2. Chung & Ooi test 3, a sphere on a rigid plane with restitution 0.2 ... 1.0: aluminium oxide
 *     (3.8e11, 0.23, 4000) and cast iron (1.0e11, 0.25, 7000), R = 2.5 mm, 3.9 m/s. The rebound
 *     speed / approach speed equals e within 0.1 %, with and without limitForce; at e = 1 the peak
 *     overlap, force and contact time within 0.1 % of the closed forms of 1.
 *  3. A sphere at rest on a belt (a plane translating at U = 0.1 m/s in x, gravity, friction
 *     mu = 0.3, Hertz + history): it slides until its contact point moves with the belt, then
 *     rolls; Coulomb friction mu m g over the slip gives v = 2U/7 and omega = -5U/(7 r) (about
 *     y), reached at t* = 2U / (7 mu g). Checked at 3 t* within 1 %; the list is rebuilt as the
 *     belt moves (its history carried by contact id).
 *  4. The same on the inside of a drum (a cylinder about x, radius R_d = 0.2 m, turning at
 *     Omega = U / R_d): at the bottom the sphere slips until v = 2U/7, omega = 5U/(7r) about x,
 *     then rolls up the drum as a rolling pendulum, s'' = -(5/7) g s / (R_d - r): at 3 t*,
 *     v = v* cos(W 2t*) - s* W sin(W 2t*), W = sqrt(5 g / (7 (R_d - r))), s* = mu g t*^2 / 2 (the
 *     slip distance), and omega = (U - v) / r (no slip on the drum's surface); within 1 %.
 *  5. A restart halfway through 3 (wall position from the time) continues it exactly.
 *  6. The wall's motion in the tangential and rolling models: a sphere turning with the drum as
 *     one rigid body (centre velocity Omega x x, spin Omega; Hertz + history + rolling cdt,
 *     mu_r = 0.1) feels no tangential force and no torque (below 1e-12 of F_n and F_n r); the same
 *     sphere against the drum at rest slides and spins against it: Coulomb's and cdt's torques
 *     together, (mu + mu_r) F_n (r - delta/2), within 1e-12. */
#include "harness.h"
#include "restart.h"

static const double G = 9.81;

/* material 1: rigid, with e and mu for the pair (0, 1) */
static void add_rigid_material(dem_system *s, double e, double mu)
{
    dem_material *m = &s->materials.mat[1];
    memset(m, 0, sizeof *m);
    snprintf(m->name, sizeof m->name, "rigid");
    m->youngs_modulus = INFINITY;
    m->rigid = 1;
    s->materials.ntypes = 2;
    dem_materials_set_pair(&s->materials, 0, 1, e, mu);
    dem_materials_set_pair(&s->materials, 1, 1, e, mu);   /* every pair is set, as case.c does */
}

static void closed_form(double E, double nu, double rho, double R, double v, double *dmax, double *fmax, double *tc)
{
    const double Es = E / (1 - nu * nu), m = rho * 4.0 / 3.0 * M_PI * R * R * R;
    *dmax = pow(15.0 * m * v * v / (16.0 * Es * sqrt(R)), 0.4);
    *fmax = 4.0 / 3.0 * Es * sqrt(R) * pow(*dmax, 1.5);
    *tc = 2.0 * sqrt(M_PI) * tgamma(1.4) / tgamma(0.9) * *dmax / v;
}

typedef struct impact { double e, peak_overlap, peak_force, contact_time; } impact;

/* sphere (E, nu, rho, R) at speed v onto the plane z = 0, rigid (or of E_wall) */
static impact wall_impact(double E, double nu, double rho, double R, double v, double e, int limit, double E_wall,
                          double steps)
{
    dem_system s;
    make_system(&s, E, nu, rho, 1.0, 0.0, normal_hertz, tangential_none, 10 * R);
    if (E_wall > 0.0) {
        s.materials.mat[1] = s.materials.mat[0];
        s.materials.mat[1].youngs_modulus = E_wall;
        s.materials.ntypes = 2;
        dem_materials_set_pair(&s.materials, 0, 1, e, 0.0);
        dem_materials_set_pair(&s.materials, 1, 1, e, 0.0);
    } else {
        add_rigid_material(&s, e, 0.0);
    }
    s.models.fn_floor = limit ? 0.0 : -INFINITY;
    add_plane(&s, 0, 0, 0, 0, 0, 1);
    s.walls[0].material = 1;
    add_sphere(&s, 0, 0, R * (1 + 1e-9), 0, 0, -v, R);
    double dmax, fmax, tc;
    closed_form(E, nu, rho, R, v, &dmax, &fmax, &tc);
    s.dt = tc / steps;
    s.nlist.skin = 0.05 * R;
    dem_system_setup(&s);
    impact o = {0};
    long in_contact = 0;
    for (long k = 0; k < (long)(100 * steps); k++) {
        dem_system_step(&s);
        const double overlap = R - s.p.x[0][2];
        if (overlap > 0.0) {
            in_contact++;
            if (overlap > o.peak_overlap) o.peak_overlap = overlap;
            if (s.p.f[0][2] > o.peak_force) o.peak_force = s.p.f[0][2];
        } else if (in_contact) {
            break;
        }
    }
    o.e = s.p.v[0][2] / v;
    o.contact_time = in_contact * s.dt;
    dem_system_free(&s);
    return o;
}


/* peak overlap, peak force and contact time of o against the closed forms, within 0.1 % */
static void check_peaks(const char *label, const impact *o, double dmax, double fmax, double tc)
{
    char what[160];   /* label (under 128) + the quantity */
    snprintf(what, sizeof what, "%s: peak overlap", label);
    check_rel(what, o->peak_overlap, dmax, 1e-3);
    snprintf(what, sizeof what, "%s: peak force", label);
    check_rel(what, o->peak_force, fmax, 1e-3);
    snprintf(what, sizeof what, "%s: contact time", label);
    check_rel(what, o->contact_time, tc, 1e-3);
}

static void chung_ooi_2(void)
{
    const struct { const char *name; double E, nu, rho; } mats[] = {{"aluminium alloy", 7.0e10, 0.30, 2699},
                                                                    {"magnesium alloy", 4.0e10, 0.35, 1800}};
    printf("1. Chung & Ooi test 2: R = 0.1 m, 0.2 m/s onto a rigid plane\n");
    for (int k = 0; k < 2; k++) {
        double dmax, fmax, tc;
        closed_form(mats[k].E, mats[k].nu, mats[k].rho, 0.1, 0.2, &dmax, &fmax, &tc);
        const impact o = wall_impact(mats[k].E, mats[k].nu, mats[k].rho, 0.1, 0.2, 1.0, 0, 0.0, 10000);
        const impact w = wall_impact(mats[k].E, mats[k].nu, mats[k].rho, 0.1, 0.2, 1.0, 0, 1e13, 10000);
        printf("   %s: closed form delta_max %.6g m, F_max %.6g N, t_c %.6g s; an elastic wall of E = 1e13 Pa: "
               "%+.3f %%, %+.3f %%, %+.3f %%\n", mats[k].name, dmax, fmax, tc, 100 * (w.peak_overlap / dmax - 1),
               100 * (w.peak_force / fmax - 1), 100 * (w.contact_time / tc - 1));
        char what[128];
        snprintf(what, sizeof what, "C&O 2 %s rigid plane", mats[k].name);
        check_peaks(what, &o, dmax, fmax, tc);
        snprintf(what, sizeof what, "C&O 2 %s rigid plane: rebound speed (e = 1)", mats[k].name);
        check_rel(what, o.e, 1.0, 1e-3);
    }
}

static void chung_ooi_3(void)
{
    const struct { const char *name; double E, nu, rho; } mats[] = {{"aluminium oxide", 3.8e11, 0.23, 4000},
                                                                    {"cast iron", 1.0e11, 0.25, 7000}};
    const double es[] = {0.2, 0.4, 0.6, 0.8, 1.0};
    printf("2. Chung & Ooi test 3: R = 2.5 mm, 3.9 m/s onto a rigid plane\n");
    for (int k = 0; k < 2; k++)
        for (int limit = 0; limit <= 1; limit++)
            for (int q = 0; q < 5; q++) {
                const impact o = wall_impact(mats[k].E, mats[k].nu, mats[k].rho, 2.5e-3, 3.9, es[q], limit, 0.0, 10000);
                char what[128];
                snprintf(what, sizeof what, "C&O 3 %s e=%g%s: rebound / approach speed", mats[k].name, es[q],
                         limit ? " limitForce" : "");
                check_rel(what, o.e, es[q], 1e-3);
                if (es[q] == 1.0 && !limit) {
                    double dmax, fmax, tc;
                    closed_form(mats[k].E, mats[k].nu, mats[k].rho, 2.5e-3, 3.9, &dmax, &fmax, &tc);
                    snprintf(what, sizeof what, "C&O 3 %s e=1", mats[k].name);
                    check_peaks(what, &o, dmax, fmax, tc);
                }
            }
}

/* A sphere (r = 5 mm, E = 1e7 Pa, nu 0.3, rho 2500; e 0.5, mu 0.3) resting on a rigid floor that
 * moves at U in x (drum = 0), or at the bottom of a rigid drum about x of radius 0.2 m turning at
 * U / 0.2 (drum = 1); gravity -z. */
static const double R_SPH = 5e-3, MU = 0.3, U = 0.1, R_DRUM = 0.2;

static void belt_system(dem_system *s, int drum)
{
    make_system(s, 1e7, 0.3, 2500, 0.5, MU, normal_hertz, tangential_history, 1.0);
    add_rigid_material(s, 0.5, MU);
    s->gravity[2] = -G;
    const double m = 2500 * 4.0 / 3.0 * M_PI * pow(R_SPH, 3), Es = 1e7 / (1 - 0.09);
    const double d0 = pow(m * G / (4.0 / 3.0 * Es * sqrt(R_SPH)), 2.0 / 3.0);   /* static overlap */
    dem_wall *w = dem_walls_add(s);
    snprintf(w->name, sizeof w->name, drum ? "drum" : "belt");
    w->material = 1;
    double z;
    if (drum) {
        w->kind = WALL_CYLINDER;
        w->axis = 0;
        w->radius = R_DRUM;
        w->inside = 1;
        w->axial_min = -INFINITY;
        w->axial_max = INFINITY;
        w->angular_velocity = U / R_DRUM;   /* bottom surface moves at +U in y */
        z = -(R_DRUM - R_SPH + d0);
    } else {
        w->kind = WALL_PLANE;
        w->normal[2] = 1.0;
        const double u[3] = {U, 0.0, 0.0};
        dem_wall_set_velocity(w, u);
        z = R_SPH - d0;
    }
    add_sphere(s, 0, 0, z, 0, 0, 0, R_SPH);
    s->dt = 1e-5;
    s->nlist.skin = 0.1 * R_SPH;   /* the belt moves 3 mm: several rebuilds */
    dem_system_setup(s);
}

static void rolling(int drum)
{
    dem_system s;
    belt_system(&s, drum);
    const double t_star = 2.0 * U / (7.0 * MU * G);
    const long steps = (long)(3.0 * t_star / s.dt);
    for (long k = 0; k < steps; k++) dem_system_step(&s);
    const int along = drum ? 1 : 0, about = drum ? 0 : 1;
    double v = 2 * U / 7;   /* the belt: rolling at 2U/7 from t* on */
    if (drum) {             /* the drum: a rolling pendulum from t* on */
        const double w = sqrt(5.0 * G / (7.0 * (R_DRUM - R_SPH))), s_star = 0.5 * MU * G * t_star * t_star;
        v = v * cos(w * (s.time - t_star)) - s_star * w * sin(w * (s.time - t_star));
    }
    const double omega = drum ? (U - v) / R_SPH : -5 * U / (7 * R_SPH);   /* about x (drum), y (belt) */
    printf("%d. %s at t = 3 t* = %.4g s: v = %.6g m/s (closed form %.6g), omega = %.6g rad/s (%.6g), %ld list builds\n",
           drum ? 4 : 3, drum ? "drum" : "belt", s.time, s.p.v[0][along], v, s.p.omega[0][about], omega, s.nlist.builds);
    char what[96];
    snprintf(what, sizeof what, "%s: centre velocity", drum ? "drum" : "belt");
    check_rel(what, s.p.v[0][along], v, 0.01);
    snprintf(what, sizeof what, "%s: spin", drum ? "drum" : "belt");
    check_rel(what, s.p.omega[0][about], omega, 0.01);
    if (!drum) check_true("belt: the moving plane rebuilt the lists (> 1 build)", s.nlist.builds > 1);
    dem_system_free(&s);
}

/* 5: the belt run to 3 t* straight, and stopped at 1.5 t*, saved and restarted */
static void restart_exact(void)
{
    const double t_star = 2.0 * U / (7.0 * MU * G);
    dem_system a, b;
    belt_system(&a, 0);
    const long steps = (long)(3.0 * t_star / a.dt), half = steps / 2;
    for (long k = 0; k < steps; k++) dem_system_step(&a);

    belt_system(&b, 0);
    for (long k = 0; k < half; k++) dem_system_step(&b);
    dem_contact_state saved;
    dem_restart_save_contacts(&b, &saved);
    saved.forces_read = 1;   /* the forces come with the particles, as from a snapshot (restart.c) */
    dem_system c;
    belt_system(&c, 0);
    /* the restarted system: particles, time and contacts of b, set up again (walls from the time) */
    c.time = b.time;
    c.step = b.step;
    for (int d = 0; d < 3; d++) {
        c.p.x[0][d] = b.p.x[0][d]; c.p.v[0][d] = b.p.v[0][d]; c.p.omega[0][d] = b.p.omega[0][d];
        c.p.f[0][d] = b.p.f[0][d]; c.p.torque[0][d] = b.p.torque[0][d];
    }
    dem_restart_setup(&c, &saved);
    dem_contact_state_free(&saved);
    for (long k = half; k < steps; k++) dem_system_step(&c);
    printf("5. belt restarted at step %ld: wall point x %.17g vs %.17g, v %.17g vs %.17g\n", half, c.walls[0].point[0],
           a.walls[0].point[0], c.p.v[0][0], a.p.v[0][0]);
    check_true("belt restart: same wall position, velocity and spin as the straight run, bit for bit",
               c.walls[0].point[0] == a.walls[0].point[0] && c.p.v[0][0] == a.p.v[0][0] &&
               c.p.omega[0][1] == a.p.omega[0][1] && c.p.x[0][0] == a.p.x[0][0]);
    dem_system_free(&a);
    dem_system_free(&b);
    dem_system_free(&c);
}

static void corotating(void)
{
    const double omega = 2.0, delta = 1e-6;
    double torque[2], ft[2], fn[2];
    for (int turning = 1; turning >= 0; turning--) {
        dem_system s;
        make_system(&s, 1e7, 0.3, 2500, 0.5, MU, normal_hertz, tangential_history, 1.0);
        add_rigid_material(&s, 0.5, MU);
        s.models.rolling = rolling_cdt;
        const dem_cdt_params cp = {0.1};
        dem_materials_set_model_values(&s.materials, 0, 1, SLOT_ROLLING, &cp, sizeof cp);
        dem_wall *w = dem_walls_add(&s);
        snprintf(w->name, sizeof w->name, "drum");
        w->material = 1;
        w->kind = WALL_CYLINDER;
        w->axis = 0;
        w->radius = R_DRUM;
        w->inside = 1;
        w->axial_min = -INFINITY;
        w->axial_max = INFINITY;
        w->angular_velocity = turning ? omega : 0.0;
        const double z = -(R_DRUM - R_SPH + delta);
        add_sphere(&s, 0, 0, z, 0, -omega * z, 0, R_SPH);   /* Omega e_x x (0, 0, z) */
        s.p.omega[0][0] = omega;
        s.dt = 1e-6;
        s.nlist.skin = 0.1 * R_SPH;
        dem_system_setup(&s);   /* computes the forces */
        fn[turning] = s.p.f[0][2];
        ft[turning] = sqrt(s.p.f[0][0] * s.p.f[0][0] + s.p.f[0][1] * s.p.f[0][1]);
        torque[turning] = sqrt(s.p.torque[0][0] * s.p.torque[0][0] + s.p.torque[0][1] * s.p.torque[0][1] +
                               s.p.torque[0][2] * s.p.torque[0][2]);
        dem_system_free(&s);
    }
    printf("6. sphere turning with the drum: |F_t| %.3g N, |M| %.3g N m (F_n %.6g N); against the drum at rest "
           "|M| %.6g N m\n", ft[1], torque[1], fn[1], torque[0]);
    check_true("co-rotating with the drum: no tangential force (< 1e-12 F_n)", ft[1] < 1e-12 * fn[1]);
    check_true("co-rotating with the drum: no rolling torque (< 1e-12 F_n r)", torque[1] < 1e-12 * fn[1] * R_SPH);
    check_rel("drum at rest: torque (mu + mu_r) F_n (r - delta/2)", torque[0], (MU + 0.1) * fn[0] * (R_SPH - 0.5 * delta), 1e-12);
}

int main(void)
{
    chung_ooi_2();
    chung_ooi_3();
    rolling(0);
    rolling(1);
    restart_exact();
    corotating();
    return finish("test_wall_motion");
}
