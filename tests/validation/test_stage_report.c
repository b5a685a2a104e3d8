/* The end-of-run cost report (stage_timer.h, stage_report.c; issue 22 part 4).
 *
 * A bed of 343 spheres (hertz, tangential history, rolling epsd) settles on a floor for 3000
 * steps, periodic in x so that images are made; a twin system runs the same steps. Checked:
 *  1. the twins agree bit for bit before the report (the runs are deterministic);
 *  2. the stages partition the step: their sum is between 0.9 and 1 of the wall time around the
 *     stepping loop (the remainder is the loop itself), every stage finite and >= 0;
 *  3. the report's probe of the contact models leaves the state as it was: forces, torques,
 *     contact histories and touching flags equal the twin's bit for bit after it, and after 500
 *     more steps the positions and velocities of the two still agree bit for bit. */
#include "harness.h"

static const double E = 5e6, NU = 0.3, RHO = 2500, RAD = 1e-3, L = 0.0075;

static void make_bed(dem_system *s)
{
    make_system(s, E, NU, RHO, 0.5, 0.5, normal_hertz, tangential_history, L);
    s->models.rolling = rolling_epsd;
    const dem_epsd_params epsd = {0.1, 0.3};
    dem_materials_set_model_values(&s->materials, 0, 0, SLOT_ROLLING, &epsd, sizeof epsd);
    s->periodic[0] = 1;
    s->period[0] = 2 * L;
    s->inv_period[0] = 1.0 / (2 * L);
    s->gravity[2] = -9.81;
    s->dt = 1e-6;
    s->nlist.skin = 0.2 * RAD;
    add_plane(s, 0, 0, -L, 0, 0, 1);
    add_plane(s, 0, -L, 0, 0, 1, 0);
    add_plane(s, 0, L, 0, 0, -1, 0);
    int k = 0;
    for (int i = 0; i < 7; i++)
        for (int j = 0; j < 7; j++)
            for (int m = 0; m < 7; m++, k++) {
                const double jitter = 1e-5 * ((k * 7919) % 13 - 6);   /* off the lattice: a real bed */
                add_sphere(s, -L + RAD + i * 2.1 * RAD + jitter, -L + RAD * 1.05 + j * 2.1 * RAD, -L + RAD + m * 2.02 * RAD,
                           0.02 * ((k % 5) - 2), 0.0, -0.05, RAD);
            }
    dem_system_setup(s);
}

static int same_bits(const void *a, const void *b, size_t n) { return memcmp(a, b, n) == 0; }

static int same_state(const dem_system *a, const dem_system *b)
{
    const size_t n = (size_t)a->p.n * sizeof(dem_vec3);
    return a->p.n == b->p.n && same_bits(a->p.x, b->p.x, n) && same_bits(a->p.v, b->p.v, n) &&
           same_bits(a->p.omega, b->p.omega, n);
}

int main(void)
{
    dem_system a, b;
    make_bed(&a);
    make_bed(&b);
    for (int k = 0; k < DEM_STAGE_COUNT; k++) a.stage_seconds[k] = 0.0;
    const double t0 = dem_clock();
    for (int k = 0; k < 3000; k++) dem_system_step(&a);
    const double wall = dem_clock() - t0;
    for (int k = 0; k < 3000; k++) dem_system_step(&b);
    check_true("the twin runs agree bit for bit (deterministic)", same_state(&a, &b));

    double sum = 0.0;
    int finite = 1;
    for (int k = 0; k < DEM_STAGE_COUNT; k++) {
        sum += a.stage_seconds[k];
        finite &= isfinite(a.stage_seconds[k]) && a.stage_seconds[k] >= 0.0;
    }
    check_true("every stage's time is finite and >= 0", finite);
    printf("stages sum to %.4f s of the loop's %.4f s wall\n", sum, wall);
    check_true("the stages add up to 0.9-1 of the stepping loop's wall time", sum >= 0.9 * wall && sum <= wall);
    check_true("the bed has contacts and images (the probe has work)", a.nlist.npairs > 0 && a.ghosts.n > 0);

    dem_stage_report(&a, 3000);
    const size_t nf = (size_t)(a.p.n + a.ghosts.n) * sizeof(dem_vec3);
    check_true("after the report: forces and torques as the twin's, bit for bit",
               same_bits(a.p.f, b.p.f, nf) && same_bits(a.p.torque, b.p.torque, nf));
    check_true("after the report: histories and touching flags as the twin's, bit for bit",
               a.nlist.npairs == b.nlist.npairs &&
               same_bits(a.nlist.history, b.nlist.history, (size_t)a.nlist.npairs * a.history_size * sizeof(double)) &&
               same_bits(a.nlist.touching, b.nlist.touching, (size_t)a.nlist.npairs));
    for (int k = 0; k < 500; k++) {
        dem_system_step(&a);
        dem_system_step(&b);
    }
    check_true("500 steps after the report: the same positions, velocities, spins bit for bit", same_state(&a, &b));
    dem_system_free(&a);
    dem_system_free(&b);
    return finish("test_stage_report");
}
