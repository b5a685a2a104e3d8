/* Energy conservation: elastic (e = 1), frictionless spheres (Hertz, no tangential model) in a
 * closed box of six walls, no gravity. Total energy = kinetic + Hertz elastic energy of every
 * contact, U = 8/15 Y* sqrt(R*) delta^(5/2); its relative drift over 1e5 steps must stay below
 * 1e-4. The time step is 1/50 of the Hertz contact time at the fastest initial speed x 2. */
#include <stdlib.h>

#include "harness.h"
#include "rng.h"

static double elastic_energy(const dem_system *s)
{
    const dem_particles *p = &s->p;
    double u = 0.0;
    for (int i = 0; i < p->n; i++) {
        for (int j = i + 1; j < p->n; j++) {
            const double dx = p->x[i][0] - p->x[j][0], dy = p->x[i][1] - p->x[j][1], dz = p->x[i][2] - p->x[j][2];
            const double delta = p->radius[i] + p->radius[j] - sqrt(dx * dx + dy * dy + dz * dz);
            if (delta <= 0) continue;
            const double R = p->radius[i] * p->radius[j] / (p->radius[i] + p->radius[j]);
            u += 8.0 / 15.0 * materials_pair(&s->materials, 0, 0)->Y_eff * sqrt(R) * pow(delta, 2.5);
        }
        for (int k = 0; k < s->nwalls; k++) {
            double gap, en[3];
            if (dem_wall_gap(&s->walls[k], p->x[i], p->radius[i], &gap, en) && gap < 0)
                u += 8.0 / 15.0 * materials_pair(&s->materials, 0, 0)->Y_eff * sqrt(p->radius[i]) * pow(-gap, 2.5);
        }
    }
    return u;
}

int main(void)
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
    add_plane(&s, L, 0, 0, -1, 0, 0);
    dem_rng r;
    rng_seed(&r, 7);
    /* 300 spheres, radii 0.8-1.2 mm, on a loose lattice, random velocities up to vmax */
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
    const double e0 = dem_system_kinetic_energy(&s) + elastic_energy(&s);
    double worst = 0.0;
    for (long k = 1; k <= 100000; k++) {
        dem_system_step(&s);
        if (k % 5000 == 0) {
            const double e = dem_system_kinetic_energy(&s) + elastic_energy(&s);
            worst = fmax(worst, fabs(e - e0) / e0);
        }
    }
    printf("dt = %.3g s (contact time %.3g s), %ld neighbour builds\n", s.dt, t_contact, s.nlist.builds);
    check_true("neighbour list was rebuilt during the run", s.nlist.builds > 10);
    check_rel("total energy after 1e5 steps", dem_system_kinetic_energy(&s) + elastic_energy(&s), e0, 1e-4);
    printf("largest relative energy deviation seen (every 5000 steps): %.3g\n", worst);
    check_true("energy deviation below 1e-4 throughout", worst < 1e-4);
    dem_system_free(&s);
    return finish("test_energy");
}
