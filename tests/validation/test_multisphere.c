/* Multisphere bodies in the DEM (dem/src/bodies.h) against closed forms.
 *  - A dumbbell (two spheres of 1 mm, centres 3 mm apart) tilted by 30 degrees falls at 1 m/s onto
 *    a plane, frictionless and elastic (Hertz, e = 1, no gravity): after the impact its velocity
 *    and angular velocity against the rigid-body impulse solution, J = (1 + e) v0 /
 *    (1/M + (r x n).I^-1.(r x n)), V' = V + J n / M, w' = I^-1 (r x J n), r from the centre of
 *    mass to the contact point (1 %); the kinetic energy kept (0.5 %); no sideways velocity.
 *  - A clump of three overlapping spheres (union mass), spinning off its axes and drifting in
 *    free space for 2e4 steps: its spheres feel no force from one another (the list leaves them
 *    out), so the kinetic energy and the space-frame angular momentum stay within 1e-6, the centre
 *    moves at constant velocity (1e-12 m), and the spheres keep their distances (1e-12 m). */
#include "bodies.h"
#include "harness.h"
#include "rigid_rotation.h"

static void space_inertia(const dem_bodies *b, int k, double I[3][3])
{
    double R[3][3];
    dem_quat_matrix(b->q[k], R);
    const double *Ip = b->templates[b->template_of[k]].mass.principal;
    for (int d = 0; d < 3; d++)
        for (int e = 0; e < 3; e++) {
            I[d][e] = 0.0;
            for (int m = 0; m < 3; m++) I[d][e] += R[d][m] * Ip[m] * R[e][m];
        }
}

/* x = A^-1 y for a symmetric positive 3x3 (Cramer) */
static void solve3(const double A[3][3], const double y[3], double x[3])
{
    const double det = A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
                       A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
    for (int c = 0; c < 3; c++) {
        double B[3][3];
        memcpy(B, A, sizeof B);
        for (int r = 0; r < 3; r++) B[r][c] = y[r];
        x[c] = (B[0][0] * (B[1][1] * B[2][2] - B[1][2] * B[2][1]) - B[0][1] * (B[1][0] * B[2][2] - B[1][2] * B[2][0]) +
                B[0][2] * (B[1][0] * B[2][1] - B[1][1] * B[2][0])) / det;
    }
}

static void dumbbell_impact(void)
{
    const double a = 1e-3, half = 1.5e-3, v0 = 1.0, theta = M_PI / 6;
    dem_system s;
    make_system(&s, 5e9, 0.3, 2500, 1.0, 0.0, normal_hertz, tangential_none, 0.01);
    add_plane(&s, 0, 0, 0, 0, 0, 1);
    const double x[2][3] = {{-half, 0, 0}, {half, 0, 0}}, r[2] = {a, a};
    const int t = dem_bodies_add_template(&s.bodies, "dumbbell", 2, x, r, 0, 2500, CLUMP_MASS_SPHERE_SUM);
    /* turned by theta about y: the +x sphere is the lower one, 0.1 mm above the plane */
    const double q[4] = {cos(0.5 * theta), 0, sin(0.5 * theta), 0};
    const double X[3] = {0, 0, a + half * sin(theta) + 0.1e-3}, V[3] = {0, 0, -v0}, W[3] = {0, 0, 0};
    dem_bodies_add(&s, t, X, q, V, W);
    s.dt = 1e-7;
    s.nlist.skin = 0.2e-3;
    dem_system_setup(&s);
    const double M = s.bodies.templates[t].mass.mass, E0 = dem_system_kinetic_energy(&s);
    /* the impulse solution at the moment of touching: contact point below the lower sphere */
    double I[3][3];
    space_inertia(&s.bodies, 0, I);
    const double low[3] = {half * cos(theta), 0, -half * sin(theta) - a};   /* contact point - centre of mass */
    const double rxn[3] = {low[1], -low[0], 0.0};                               /* r x z */
    double Iinv_rxn[3];
    solve3(I, rxn, Iinv_rxn);
    const double J = 2.0 * v0 / (1.0 / M + rxn[0] * Iinv_rxn[0] + rxn[1] * Iinv_rxn[1] + rxn[2] * Iinv_rxn[2]);
    const double Vz = -v0 + J / M, Wy = J * Iinv_rxn[1];
    /* run until the impact is over: the wall touched, then no force for 100 steps */
    int touched = 0, free_steps = 0;
    long step = 0;
    for (; step < 200000 && free_steps < 100; step++) {
        dem_system_step(&s);
        const int touching = fabs(s.wall_force[2]) > 0.0;
        touched |= touching;
        free_steps = touched && !touching ? free_steps + 1 : 0;
    }
    double w[3];
    dem_body_omega(&s.bodies, 0, w);
    printf("  impact over after %ld steps: V_z %.6f m/s (impulse solution %.6f), w_y %.3f rad/s (%.3f)\n", step,
           s.bodies.v[0][2], Vz, w[1], Wy);
    check_true("dumbbell: the impact happened and ended", touched && free_steps == 100);
    check_rel("dumbbell: centre velocity after impact vs the impulse solution", s.bodies.v[0][2], Vz, 0.01);
    check_rel("dumbbell: angular velocity after impact vs the impulse solution", w[1], Wy, 0.01);
    check_true("dumbbell: no sideways velocity (frictionless), |V_x| < 1e-3 v0",
               fabs(s.bodies.v[0][0]) < 1e-3 * v0 && fabs(s.bodies.v[0][1]) < 1e-3 * v0);
    check_rel("dumbbell: kinetic energy kept (elastic)", dem_system_kinetic_energy(&s), E0, 0.005);
    dem_system_free(&s);
}

static void free_clump(void)
{
    dem_system s;
    make_system(&s, 5e7, 0.3, 2500, 0.5, 0.5, normal_hertz, tangential_history, 0.05);
    const double x[3][3] = {{0, 0, 0}, {1.2e-3, 0.3e-3, 0}, {0.2e-3, 1.0e-3, 0.6e-3}}, r[3] = {1e-3, 0.8e-3, 0.6e-3};
    const int t = dem_bodies_add_template(&s.bodies, "three", 3, x, r, 0, 2500, CLUMP_MASS_UNION);
    const double q[4] = {0.8, 0.2, -0.4, 0.4}, X[3] = {0, 0, 0}, V[3] = {0.3, -0.1, 0.2}, W[3] = {50, -80, 120};
    const double nq = sqrt(0.64 + 0.04 + 0.16 + 0.16), qn[4] = {q[0] / nq, q[1] / nq, q[2] / nq, q[3] / nq};
    dem_bodies_add(&s, t, X, qn, V, W);
    s.dt = 1e-6;
    s.nlist.skin = 0.2e-3;
    dem_system_setup(&s);
    const double E0 = dem_system_kinetic_energy(&s);
    double L0[3];
    dem_quat_rotate(s.bodies.q[0], s.bodies.Lb[0], L0);
    double d0[3];
    for (int k = 0; k < 3; k++) {
        const int i = k, j = (k + 1) % 3;
        d0[k] = sqrt(pow(s.p.x[i][0] - s.p.x[j][0], 2) + pow(s.p.x[i][1] - s.p.x[j][1], 2) + pow(s.p.x[i][2] - s.p.x[j][2], 2));
    }
    double worst_E = 0, worst_L = 0, worst_d = 0;
    const int steps = 20000;
    for (int n = 0; n < steps; n++) {
        dem_system_step(&s);
        double L[3];
        dem_quat_rotate(s.bodies.q[0], s.bodies.Lb[0], L);
        worst_E = fmax(worst_E, fabs(dem_system_kinetic_energy(&s) - E0) / E0);
        worst_L = fmax(worst_L, sqrt(pow(L[0] - L0[0], 2) + pow(L[1] - L0[1], 2) + pow(L[2] - L0[2], 2)) /
                                    sqrt(L0[0] * L0[0] + L0[1] * L0[1] + L0[2] * L0[2]));
        for (int k = 0; k < 3; k++) {
            const int i = k, j = (k + 1) % 3;
            const double dk = sqrt(pow(s.p.x[i][0] - s.p.x[j][0], 2) + pow(s.p.x[i][1] - s.p.x[j][1], 2) +
                                   pow(s.p.x[i][2] - s.p.x[j][2], 2));
            worst_d = fmax(worst_d, fabs(dk - d0[k]));
        }
    }
    double drift = 0.0;
    for (int d = 0; d < 3; d++) drift = fmax(drift, fabs(s.bodies.x[0][d] - V[d] * steps * s.dt));
    printf("  free clump, %d steps: energy %.2e, angular momentum %.2e, centre off the straight line by %.2e m, "
           "sphere distances by %.2e m; %ld list builds\n", steps, worst_E, worst_L, drift, worst_d, s.nlist.builds);
    check_true("free clump: kinetic energy within 1e-6 (no force between its own spheres)", worst_E < 1e-6);
    check_true("free clump: space-frame angular momentum within 1e-6", worst_L < 1e-6);
    check_true("free clump: centre moves in a straight line (1e-12 m)", drift < 1e-12);
    check_true("free clump: its spheres keep their distances (1e-12 m)", worst_d < 1e-12);
    dem_system_free(&s);
}

int main(void)
{
    dumbbell_impact();
    free_clump();
    return finish("test_multisphere");
}
