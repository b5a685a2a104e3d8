/* Walls and periodic boundaries:
 *  - bounded plane: a sphere dropped inside the bounds bounces, one dropped outside falls past;
 *  - box: elastic frictionless spheres stay inside for 20000 steps: no centre leaves, and no wall
 *    overlap exceeds the Hertz maximum overlap of a sphere carrying the whole kinetic energy;
 *  - cylinder inside and outside: a radial impact rebounds with the same restitution as on a
 *    plane (within 1 %: the cylinder is treated as locally flat, R* = R_i);
 *  - periodic: two spheres colliding across the periodic boundary rebound exactly as the same
 *    collision away from it (within 1e-9 relative);
 *  - external force: a constant per-particle force F (as the coupling's drag will be) moves a free
 *    sphere by F t^2 / (2 m), which velocity Verlet reproduces to round-off (1e-9). */
#include "harness.h"
#include "rng.h"

static dem_wall *add_wall(dem_system *s)
{
    dem_wall *w = dem_walls_add(s);
    memset(w, 0, sizeof *w);
    snprintf(w->name, sizeof w->name, "wall%d", s->nwalls);
    return w;
}

static void bounded_plane(void)
{
    for (int inside = 0; inside <= 1; inside++) {
        dem_system s;
        make_system(&s, 5e6, 0.45, 2500, 0.5, 0.3, normal_hertz, tangential_history, 0.1);
        s.gravity[2] = -9.81;
        dem_wall *w = add_wall(&s);
        w->kind = WALL_PLANE;
        w->normal[2] = 1.0;
        w->bounded = 1;
        w->bounds_min[0] = -0.01; w->bounds_max[0] = 0.01;
        w->bounds_min[1] = -0.01; w->bounds_max[1] = 0.01;
        w->bounds_min[2] = -0.001; w->bounds_max[2] = 0.001;
        add_sphere(&s, inside ? 0.0 : 0.02, 0, 0.01, 0, 0, 0, 1e-3);
        s.dt = 1e-5;
        s.nlist.skin = 1e-4;
        dem_system_setup(&s);
        double zmin = 1.0;
        for (int k = 0; k < (inside ? 30000 : 12000); k++) { dem_system_step(&s); zmin = fmin(zmin, s.p.x[0][2]); }
        if (inside) check_true("bounded plane: sphere inside the bounds comes to rest on it",
                               fabs(s.p.x[0][2] - 1e-3) < 1e-5 && fabs(s.p.v[0][2]) < 1e-3);
        else check_true("bounded plane: sphere outside the bounds falls past", zmin < -0.05);
        dem_system_free(&s);
    }
}

static void box(void)
{
    const double L = 0.005;
    dem_system s;
    make_system(&s, 5e6, 0.45, 2500, 1.0, 0.0, normal_hertz, tangential_none, 2 * L);
    for (int k = 0; k < 6; k++) {   /* the six faces, as case.c builds a box wall */
        dem_wall *w = add_wall(&s);
        w->kind = WALL_PLANE;
        w->bounded = 1;
        for (int q = 0; q < 3; q++) { w->bounds_min[q] = -L; w->bounds_max[q] = L; }
        w->point[k / 2] = k % 2 ? L : -L;
        w->normal[k / 2] = k % 2 ? -1.0 : 1.0;
    }
    dem_rng g;
    rng_seed(&g, 3);
    for (int k = 0; k < 27; k++)
        add_sphere(&s, -L + (k % 3 + 0.5) * 2 * L / 3, -L + (k / 3 % 3 + 0.5) * 2 * L / 3, -L + (k / 9 + 0.5) * 2 * L / 3,
                   2 * rng_uniform(&g) - 1, 2 * rng_uniform(&g) - 1, 2 * rng_uniform(&g) - 1, 0.8e-3);
    s.dt = 2e-6;
    s.nlist.skin = 1e-4;
    dem_system_setup(&s);
    const double r = 0.8e-3, m = s.p.mass[0], Y = materials_pair(&s.materials, 0, 0)->Y_eff;
    const double v_all = sqrt(2.0 * dem_system_kinetic_energy(&s) / m);
    const double bound = pow(15.0 * m * v_all * v_all / (16.0 * Y * sqrt(r)), 0.4);
    double worst = 0.0, centre = 0.0;
    for (int k = 0; k < 20000; k++) {
        dem_system_step(&s);
        for (int i = 0; i < s.p.n; i++)
            for (int q = 0; q < 3; q++) {
                worst = fmax(worst, fabs(s.p.x[i][q]) + r - L);
                centre = fmax(centre, fabs(s.p.x[i][q]));
            }
    }
    printf("box: largest wall overlap %.3g m, bound %.3g m\n", worst, bound);
    check_true("box: no sphere centre leaves the box", centre < L);
    check_true("box: wall overlaps below the Hertz overlap at the whole kinetic energy", worst < bound);
    dem_system_free(&s);
}

/* Radial impact at 0.5 m/s on a cylinder (inside or outside) or on a plane; returns e. */
static double radial_impact(int kind)
{
    dem_system s;
    make_system(&s, 5e6, 0.45, 2500, 0.7, 0.0, normal_hertz, tangential_none, 0.1);
    dem_wall *w = add_wall(&s);
    const double r = 1e-3, R = 0.02, v = 0.5;
    if (kind == 0) {             /* plane x = R, normal -x */
        w->kind = WALL_PLANE;
        w->point[0] = R;
        w->normal[0] = -1.0;
    } else {
        w->kind = WALL_CYLINDER;
        w->axis = 2;
        w->radius = R;
        w->inside = kind == 1;
        w->axial_min = -1.0;
        w->axial_max = 1.0;
    }
    const double x0 = kind == 2 ? R + r + 1e-7 : R - r - 1e-7;   /* just touching */
    add_sphere(&s, x0, 0, 0, kind == 2 ? -v : v, 0, 0, r);
    s.dt = 5e-7;
    s.nlist.skin = 1e-4;
    dem_system_setup(&s);
    for (int k = 0; k < 4000; k++) dem_system_step(&s);
    const double e = fabs(s.p.v[0][0]) / v;
    dem_system_free(&s);
    return e;
}

static void cylinder(void)
{
    const double e_plane = radial_impact(0);
    check_rel("cylinder inside: restitution as on a plane", radial_impact(1), e_plane, 0.01);
    check_rel("cylinder outside: restitution as on a plane", radial_impact(2), e_plane, 0.01);
}

/* Two spheres approaching along x; shift moves the pair so that the collision happens across
 * the periodic boundary at x = +-L. Returns the final velocity of the first sphere. */
static double periodic_collision(double shift)
{
    const double L = 0.01, r = 1e-3;
    dem_system s;
    make_system(&s, 5e6, 0.45, 2500, 0.6, 0.3, normal_hertz, tangential_history, L);
    s.periodic[0] = s.periodic[1] = s.periodic[2] = 1;
    double xa = -1.5 * r + shift, xb = 1.5 * r + shift;
    if (xb >= L) xb -= 2 * L;
    add_sphere(&s, xa, 0, 0, 0.5, 0.05, 0, r);
    add_sphere(&s, xb, 0.0002, 0, -0.5, 0, 0, r);
    s.dt = 5e-7;
    s.nlist.skin = 1e-4;
    dem_system_setup(&s);
    for (int k = 0; k < 6000; k++) dem_system_step(&s);
    for (int i = 0; i < s.p.n; i++)
        if (s.p.id[i] == 0) { const double vx = s.p.v[i][0]; dem_system_free(&s); return vx; }
    dem_system_free(&s);
    return NAN;
}

static void external_force(void)
{
    dem_system s;
    make_system(&s, 5e6, 0.45, 2500, 0.5, 0.5, normal_hertz, tangential_history, 1.0);
    const int i = add_sphere(&s, 0, 0, 0, 0, 0, 0, 1e-3);
    s.p.f_ext[i][0] = 2e-6;   /* N */
    s.dt = 1e-5;
    s.nlist.skin = 1e-3;
    dem_system_setup(&s);
    for (int k = 0; k < 10000; k++) dem_system_step(&s);
    const double t = s.time, expected = 0.5 * 2e-6 / s.p.mass[i] * t * t;
    check_rel("external force: displacement F t^2 / (2 m)", s.p.x[i][0], expected, 1e-9);
    dem_system_free(&s);
}

int main(void)
{
    external_force();
    bounded_plane();
    box();
    cylinder();
    const double v_inside = periodic_collision(0.0), v_across = periodic_collision(0.01);
    check_true("periodic: the pair collided (velocity reversed)", v_inside < 0.0);
    check_rel("periodic: collision across the boundary as inside", v_across, v_inside, 1e-9);
    return finish("test_walls");
}
