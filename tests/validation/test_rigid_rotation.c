/* Torque-free rotation of an asymmetric rigid body (dem/src/rigid_rotation.h) against closed
 * forms.
 *  - Conservation: principal moments (1, 2, 3) x 1e-9 kg m^2, spinning at about 60 rad/s off any
 *    axis, 1e5 steps of 1e-5 s (0.6 mrad per step, about 10 turns): the kinetic energy and the
 *    space-frame angular momentum vector stay within 1e-6 (relative) of their start, at every step.
 *  - The intermediate-axis (Dzhanibekov) flip: spin mostly about the middle axis; Euler's equations
 *    give L_2 proportional to sn(lambda t, k) (Landau & Lifshitz, Mechanics, sec. 37) with
 *    lambda = sqrt((I3 - I2)(L^2 - 2 E I1) / (I1 I2 I3)),
 *    k^2 = (I2 - I1)(2 E I3 - L^2) / ((I3 - I2)(L^2 - 2 E I1))   (L^2 > 2 E I2),
 *    so L_2 changes sign every 2 K(k) / lambda (K the complete elliptic integral of the first
 *    kind, from the arithmetic-geometric mean). The mean interval between sign changes over ten
 *    flips against that: 1 %.
 *  - The kick: a constant space-frame torque on a body at rest about a principal axis turns it at
 *    T t / I (1e-9). */
#include "rigid_rotation.h"
#include "harness.h"

static double energy(const double I[3], const double L[3])
{
    return 0.5 * (L[0] * L[0] / I[0] + L[1] * L[1] / I[1] + L[2] * L[2] / I[2]);
}

/* K(k) = pi / (2 AGM(1, sqrt(1 - k^2))) */
static double elliptic_K(double k2)
{
    double a = 1.0, g = sqrt(1.0 - k2);
    for (int n = 0; n < 60 && fabs(a - g) > 1e-16 * a; n++) {
        const double an = 0.5 * (a + g);
        g = sqrt(a * g);
        a = an;
    }
    return M_PI / (2.0 * a);
}

static void conservation(void)
{
    const double I[3] = {1e-9, 2e-9, 3e-9};
    const double w0[3] = {40.0, 25.0, 35.0};
    double Lb[3] = {I[0] * w0[0], I[1] * w0[1], I[2] * w0[2]};
    double q[4] = {0.9, 0.1, -0.3, 0.2};
    const double nq = sqrt(0.81 + 0.01 + 0.09 + 0.04);
    for (int k = 0; k < 4; k++) q[k] /= nq;
    const double E0 = energy(I, Lb);
    double L0[3];
    dem_quat_rotate(q, Lb, L0);
    const double L0n = sqrt(L0[0] * L0[0] + L0[1] * L0[1] + L0[2] * L0[2]);
    double worst_E = 0.0, worst_L = 0.0;
    const double dt = 1e-5;
    for (long step = 0; step < 100000; step++) {
        dem_rigid_free_rotation(I, q, Lb, dt);
        double L[3];
        dem_quat_rotate(q, Lb, L);
        worst_E = fmax(worst_E, fabs(energy(I, Lb) - E0) / E0);
        worst_L = fmax(worst_L, sqrt((L[0] - L0[0]) * (L[0] - L0[0]) + (L[1] - L0[1]) * (L[1] - L0[1]) +
                                     (L[2] - L0[2]) * (L[2] - L0[2])) / L0n);
    }
    printf("  1e5 steps: worst relative energy error %.2e, angular momentum (space vector) %.2e\n", worst_E, worst_L);
    check_true("torque-free: kinetic energy within 1e-6 at every step of 1e5", worst_E < 1e-6);
    check_true("torque-free: space-frame angular momentum within 1e-6 at every step of 1e5", worst_L < 1e-6);
}

static void intermediate_axis_flip(void)
{
    const double I[3] = {1.0, 2.0, 3.0};
    const double w0[3] = {0.01, 1.0, 0.01};
    double Lb[3] = {I[0] * w0[0], I[1] * w0[1], I[2] * w0[2]};
    double q[4] = {1.0, 0.0, 0.0, 0.0};
    const double E = energy(I, Lb), L2 = Lb[0] * Lb[0] + Lb[1] * Lb[1] + Lb[2] * Lb[2];
    const double lambda = sqrt((I[2] - I[1]) * (L2 - 2 * E * I[0]) / (I[0] * I[1] * I[2]));
    const double k2 = (I[1] - I[0]) * (2 * E * I[2] - L2) / ((I[2] - I[1]) * (L2 - 2 * E * I[0]));
    const double interval = 2.0 * elliptic_K(k2) / lambda;
    const double dt = 1e-3;
    double t = 0.0, first = -1.0, last = -1.0, prev = Lb[1];
    int flips = 0;
    while (flips < 11 && t < 40 * interval) {
        dem_rigid_free_rotation(I, q, Lb, dt);
        t += dt;
        if ((prev > 0) != (Lb[1] > 0)) {
            const double tc = t - dt * Lb[1] / (Lb[1] - prev);   /* linear between the steps */
            if (first < 0) first = tc;
            last = tc;
            flips++;
        }
        prev = Lb[1];
    }
    printf("  L^2 - 2 E I2 = %.3g > 0, k^2 = %.6f, closed-form flip interval 2K/lambda = %.6f s\n",
           L2 - 2 * E * I[1], k2, interval);
    check_true("intermediate axis: the body flipped ten times", flips == 11);
    check_rel("intermediate axis: mean interval between flips vs 2 K(k) / lambda", (last - first) / (flips - 1), interval,
              0.01);
}

static void kick(void)
{
    const double I[3] = {2e-9, 3e-9, 5e-9}, T[3] = {0.0, 0.0, 1e-8};
    double Lb[3] = {0, 0, 0}, q[4] = {1, 0, 0, 0};
    const double dt = 1e-4;
    for (int step = 0; step < 1000; step++) {   /* velocity Verlet: kick, rotate, kick */
        dem_rigid_kick(q, Lb, T, 0.5 * dt);
        dem_rigid_free_rotation(I, q, Lb, dt);
        dem_rigid_kick(q, Lb, T, 0.5 * dt);
    }
    const double t = 1000 * dt;
    check_rel("constant torque about a principal axis: omega = T t / I", Lb[2] / I[2], T[2] * t / I[2], 1e-9);
    /* the angle turned: T t^2 / (2 I), from the quaternion (w = cos(theta / 2)) */
    check_rel("constant torque: angle = T t^2 / (2 I)", 2.0 * atan2(q[3], q[0]), T[2] * t * t / (2 * I[2]), 1e-6);
}

int main(void)
{
    conservation();
    intermediate_axis_flip();
    kick();
    return finish("test_rigid_rotation");
}
