/* Symmetry planes (dem/src/symmetry.h): a frictionless, elastic mirror for particle centres.
 *  1. one sphere hits a symmetry plane at the domain face obliquely, no force (binary-exact
 *     numbers, so that its centre lands exactly on the plane at one step, where the domain check
 *     runs): it leaves with v - 2 (v.n) n and unchanged omega (1e-12 m/s, rad/s), its centre
 *     never beyond the plane (1e-15 m: round-off), kinetic energy kept (1e-12 relative), and it
 *     ends where the mirrored free flight ends (1e-12 m);
 *  2. the same with a tilted plane n = (1 2 2)/3 inside the domain, and into a corner of two
 *     planes (both normal components reversed);
 *  3. a sphere dropped from 10 mm onto a symmetry floor under gravity, 10 bounces: the impulse
 *     split at the crossing integrates a constant force exactly, so m g z + m v^2/2 is kept to
 *     1e-10 (the plain mirror rule would lose or gain up to 4e-3 of it per bounce at this step);
 *  4. a bed: e = 1, frictionless Hertz spheres, no gravity, 300 spheres in a box whose +x face
 *     is a symmetry plane, 1e5 steps: total energy (kinetic + Hertz elastic of pair and wall
 *     contacts) drifts less than 1e-4, as test_energy's closed box; centres reach the plane
 *     (closer than half a radius, which a wall would not allow) and never cross it (1e-15 m). */
#include <stdlib.h>

#include "harness.h"
#include "rng.h"

static void add_symmetry(dem_system *s, const double p[3], const double n[3])
{
    dem_symmetry_plane *sp = &s->symmetry_planes[s->nsymmetry++];
    memset(sp, 0, sizeof *sp);
    snprintf(sp->name, sizeof sp->name, "mirror%d", s->nsymmetry);
    const double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int k = 0; k < 3; k++) { sp->point[k] = p[k]; sp->normal[k] = n[k] / len; }
    sp->offset = p[0] * sp->normal[0] + p[1] * sp->normal[1] + p[2] * sp->normal[2];
}

static double min_distance(const dem_system *s)
{
    double m = INFINITY;
    for (int i = 0; i < s->p.n; i++)
        for (int k = 0; k < s->nsymmetry; k++) m = fmin(m, symmetry_distance(&s->symmetry_planes[k], s->p.x[i]));
    return m;
}

static double vec_err(const double *a, const double *b)
{
    return fmax(fmax(fabs(a[0] - b[0]), fabs(a[1] - b[1])), fabs(a[2] - b[2]));
}

/* One sphere through the planes of s for nsteps; checks as in the header. */
/* Where the free flight from x0 with v0 over time T ends, mirrored at the planes of s. */
static void mirrored_flight(const dem_system *s, const double x0[3], const double v0[3], double T, double xe[3])
{
    for (int q = 0; q < 3; q++) xe[q] = x0[q] + T * v0[q];
    for (int k = 0; k < s->nsymmetry; k++) {
        const double d = symmetry_distance(&s->symmetry_planes[k], xe);
        if (d < 0)
            for (int q = 0; q < 3; q++) xe[q] -= 2 * d * s->symmetry_planes[k].normal[q];
    }
}

static void single_sphere(const char *what, dem_system *s, const double x0[3], const double v0[3],
                          const double v_expected[3], long nsteps, int expect_exact_touch)
{
    double xe[3];
    mirrored_flight(s, x0, v0, nsteps * s->dt, xe);
    char label[160];
    const double w0[3] = {1.0, 2.0, 3.0};
    const int i = add_sphere(s, x0[0], x0[1], x0[2], v0[0], v0[1], v0[2], 1e-3);
    for (int k = 0; k < 3; k++) s->p.omega[i][k] = w0[k];
    s->nlist.skin = 1e-5;           /* a rebuild (and its domain check) every step */
    dem_system_setup(s);
    const double e0 = dem_system_kinetic_energy(s);
    double dmin = INFINITY;
    int touched = 0;
    for (long k = 0; k < nsteps; k++) {
        dem_system_step(s);
        dem_neighbour_rebuild(s);       /* the domain check, also when a centre sits on a domain face */
        dmin = fmin(dmin, min_distance(s));
        touched |= min_distance(s) == 0.0;
    }
    printf("%s: closest approach of the centre to the plane %.3g m, %ld builds\n", what, dmin, s->nlist.builds);
    snprintf(label, sizeof label, "%s: velocity mirrored, v - 2 (v.n) n (1e-12 m/s)", what);
    check_true(label, vec_err(s->p.v[i], v_expected) <= 1e-12);
    snprintf(label, sizeof label, "%s: omega unchanged (1e-12 rad/s)", what);
    check_true(label, vec_err(s->p.omega[i], w0) <= 1e-12);
    snprintf(label, sizeof label, "%s: centre never beyond the plane (1e-15 m)", what);
    check_true(label, dmin >= -1e-15);
    snprintf(label, sizeof label, "%s: kinetic energy kept (1e-12)", what);
    check_rel(label, dem_system_kinetic_energy(s), e0, 1e-12);
    snprintf(label, sizeof label, "%s: ends where the mirrored free flight ends (1e-12 m)", what);
    check_true(label, vec_err(s->p.x[i], xe) <= 1e-12);
    if (expect_exact_touch) {
        snprintf(label, sizeof label, "%s: centre exactly on the face at one step, no domain error", what);
        check_true(label, touched);
    }
}

/* 3. Dropped onto a mirror floor under gravity. */
static void bouncing(void)
{
    dem_system s;
    make_system(&s, 5e6, 0.45, 2500, 0.5, 0.5, normal_hertz, tangential_history, 0.0625);
    s.domain_min[2] = 0.0;
    s.gravity[2] = -9.81;
    s.dt = 1e-4;
    const double p[3] = {0, 0, 0}, n[3] = {0, 0, 1}, z0 = 0.01;
    add_symmetry(&s, p, n);
    const int i = add_sphere(&s, 0, 0, z0, 0.05, 0, 0, 1e-3);
    dem_system_setup(&s);
    const double m = s.p.mass[i], e0 = m * 9.81 * z0 + 0.5 * m * 0.05 * 0.05;
    const double period = 2 * sqrt(2 * z0 / 9.81);
    const long nsteps = (long)(10.25 * period / s.dt);
    double worst = 0.0, zmin = INFINITY;
    int bounces = 0;
    for (long k = 0; k < nsteps; k++) {
        const double vz = s.p.v[i][2];
        dem_system_step(&s);
        bounces += vz < 0 && s.p.v[i][2] > 0;
        zmin = fmin(zmin, s.p.x[i][2]);
        const double *v = s.p.v[i];
        const double e = m * 9.81 * s.p.x[i][2] + 0.5 * m * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        worst = fmax(worst, fabs(e - e0) / e0);
    }
    printf("floor under gravity: %d bounces in %ld steps, lowest centre %.3g m, largest energy deviation %.3g\n",
           bounces, nsteps, zmin, worst);
    check_true("floor under gravity: 10 bounces", bounces == 10);
    check_true("floor under gravity: m g z + m v^2/2 kept at every step (1e-10)", worst <= 1e-10);
    check_true("floor under gravity: centre never below the floor", zmin >= 0.0);
    dem_system_free(&s);
}

static void bed(void)
{
    const double L = 0.01, E = 5e6, nu = 0.45, rho = 2500, vmax = 0.5;
    dem_system s;
    make_system(&s, E, nu, rho, 1.0, 0.0, normal_hertz, tangential_none, L);
    s.max_overlap_fraction = 0.2;
    add_plane(&s, 0, 0, -L, 0, 0, 1);
    add_plane(&s, 0, 0, L, 0, 0, -1);
    add_plane(&s, 0, -L, 0, 0, 1, 0);
    add_plane(&s, 0, L, 0, 0, -1, 0);
    add_plane(&s, -L, 0, 0, 1, 0, 0);
    const double p[3] = {L, 0, 0}, n[3] = {-1, 0, 0};
    add_symmetry(&s, p, n);               /* the +x face */
    dem_rng r;
    rng_seed(&r, 7);
    int placed = 0;
    for (int a = 0; a < 7 && placed < 300; a++)
        for (int b = 0; b < 7 && placed < 300; b++)
            for (int c = 0; c < 7 && placed < 300; c++, placed++) {
                const double step = 2 * L / 7;
                add_sphere(&s, -L + (a + 0.5) * step, -L + (b + 0.5) * step, -L + (c + 0.5) * step,
                           vmax * (2 * rng_uniform(&r) - 1), vmax * (2 * rng_uniform(&r) - 1),
                           vmax * (2 * rng_uniform(&r) - 1), 0.8e-3 + 0.4e-3 * rng_uniform(&r));
            }
    const double Y = materials_pair(&s.materials, 0, 0)->Y_eff, rmin = 0.8e-3;
    const double m = rho * 4.0 / 3.0 * M_PI * pow(rmin, 3);
    const double t_contact = 2.87 * pow(0.25 * m * m / (0.5 * rmin * Y * Y * 2 * sqrt(3.0) * vmax), 0.2);
    s.dt = t_contact / 50.0;
    s.nlist.skin = 0.1e-3;
    dem_system_setup(&s);
    const dem_particles *q = &s.p;
    double elastic = 0.0;
    /* Hertz energy 8/15 Y* sqrt(R*) delta^(5/2) of pair and wall contacts; the mirror has none */
#define ENERGY(out)                                                                                      \
    do {                                                                                                 \
        out = 0.0;                                                                                       \
        for (int i = 0; i < q->n; i++) {                                                                 \
            for (int j = i + 1; j < q->n; j++) {                                                         \
                const double dx = q->x[i][0] - q->x[j][0], dy = q->x[i][1] - q->x[j][1], dz = q->x[i][2] - q->x[j][2]; \
                const double delta = q->radius[i] + q->radius[j] - sqrt(dx * dx + dy * dy + dz * dz);    \
                if (delta > 0) out += 8.0 / 15.0 * Y * sqrt(q->radius[i] * q->radius[j] / (q->radius[i] + q->radius[j])) * pow(delta, 2.5); \
            }                                                                                            \
            for (int k = 0; k < s.nwalls; k++) {                                                         \
                double gap, en[3];                                                                       \
                if (dem_wall_gap(&s.walls[k], q->x[i], q->radius[i], &gap, en) && gap < 0)                   \
                    out += 8.0 / 15.0 * Y * sqrt(q->radius[i]) * pow(-gap, 2.5);                         \
            }                                                                                            \
        }                                                                                                \
        out += dem_system_kinetic_energy(&s);                                                                \
    } while (0)
    ENERGY(elastic);
    const double e0 = elastic;
    double worst = 0.0, dmin = INFINITY;
    int *reached = calloc((size_t)q->n, sizeof(int));
    for (long k = 1; k <= 100000; k++) {
        dem_system_step(&s);
        for (int i = 0; i < q->n; i++) {
            const double d = L - q->x[i][0];
            dmin = fmin(dmin, d);
            if (d < 0.5 * q->radius[i]) reached[q->id[i]] = 1;
        }
        if (k % 5000 == 0) {
            double e;
            ENERGY(e);
            worst = fmax(worst, fabs(e - e0) / e0);
        }
    }
    int nreached = 0;
    for (int i = 0; i < q->n; i++) nreached += reached[i];
    double e_end;
    ENERGY(e_end);
    printf("bed: dt = %.3g s, %ld neighbour builds, %d of %d spheres came within half a radius of the "
           "plane, closest %.3g m, largest energy deviation %.3g\n", s.dt, s.nlist.builds, nreached, q->n, dmin, worst);
    check_true("bed: centres reached the mirror (> 20 spheres within r/2)", nreached > 20);
    check_true("bed: no centre beyond the mirror (1e-15 m)", dmin >= -1e-15);
    check_rel("bed: total energy after 1e5 steps", e_end, e0, 1e-4);
    check_true("bed: energy deviation below 1e-4 throughout", worst < 1e-4);
    free(reached);
    dem_system_free(&s);
}

int main(void)
{
    const double L = 0.0625, dt = 0x1p-12;   /* binary-exact: the path lands on x = L */
    { /* 1. the +x domain face */
        dem_system s;
        make_system(&s, 5e6, 0.45, 2500, 0.5, 0.5, normal_hertz, tangential_history, L);
        s.dt = dt;
        const double p[3] = {L, 0, 0}, n[3] = {-1, 0, 0};
        add_symmetry(&s, p, n);
        const double v0[3] = {0.5, 0.25, -0.125}, x0[3] = {L - 20 * dt * 0.5, 0, 0};
        const double ve[3] = {-0.5, 0.25, -0.125};
        single_sphere("face", &s, x0, v0, ve, 40, 1);
        dem_system_free(&s);
    }
    { /* 2a. a tilted plane through the domain */
        dem_system s;
        make_system(&s, 5e6, 0.45, 2500, 0.5, 0.5, normal_hertz, tangential_history, L);
        s.dt = 1e-4;
        const double p[3] = {0.001, -0.002, 0.003}, n3[3] = {1, 2, 2};
        add_symmetry(&s, p, n3);
        const double *n = s.symmetry_planes[0].normal;
        const double t[3] = {2 / sqrt(5.0), -1 / sqrt(5.0), 0};   /* t . n = 0 */
        double x0[3], v0[3], ve[3];
        for (int k = 0; k < 3; k++) {
            x0[k] = p[k] + 0.01 * n[k] - 0.005 * t[k];
            v0[k] = -0.3 * n[k] + 0.4 * t[k];
        }
        const double vn = v0[0] * n[0] + v0[1] * n[1] + v0[2] * n[2];
        for (int k = 0; k < 3; k++) ve[k] = v0[k] - 2 * vn * n[k];
        single_sphere("tilted", &s, x0, v0, ve, 700, 0);
        dem_system_free(&s);
    }
    { /* 2b. a corner of two planes */
        dem_system s;
        make_system(&s, 5e6, 0.45, 2500, 0.5, 0.5, normal_hertz, tangential_history, L);
        s.dt = 1e-4;
        const double px[3] = {L, 0, 0}, nx[3] = {-1, 0, 0}, py[3] = {0, L, 0}, ny[3] = {0, -1, 0};
        add_symmetry(&s, px, nx);
        add_symmetry(&s, py, ny);
        const double x0[3] = {L - 0.003, L - 0.002, 0}, v0[3] = {0.3, 0.2, 0.1}, ve[3] = {-0.3, -0.2, 0.1};
        single_sphere("corner", &s, x0, v0, ve, 400, 0);
        dem_system_free(&s);
    }
    bouncing();
    bed();
    return finish("test_symmetry");
}
