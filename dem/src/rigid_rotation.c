/* Rigid-body rotation by quaternion and principal-frame angular momentum (rigid_rotation.h). */
#include <math.h>

#include "rigid_rotation.h"

void dem_quat_rotate(const double q[4], const double v[3], double out[3])
{
    /* v + w t + q_v x t, t = 2 q_v x v */
    const double t[3] = {2.0 * (q[2] * v[2] - q[3] * v[1]), 2.0 * (q[3] * v[0] - q[1] * v[2]),
                         2.0 * (q[1] * v[1] - q[2] * v[0])};
    out[0] = v[0] + q[0] * t[0] + q[2] * t[2] - q[3] * t[1];
    out[1] = v[1] + q[0] * t[1] + q[3] * t[0] - q[1] * t[2];
    out[2] = v[2] + q[0] * t[2] + q[1] * t[1] - q[2] * t[0];
}

void dem_quat_rotate_inverse(const double q[4], const double v[3], double out[3])
{
    const double qc[4] = {q[0], -q[1], -q[2], -q[3]};
    dem_quat_rotate(qc, v, out);
}

void dem_quat_matrix(const double q[4], double R[3][3])
{
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    R[0][0] = 1 - 2 * (y * y + z * z); R[0][1] = 2 * (x * y - w * z);     R[0][2] = 2 * (x * z + w * y);
    R[1][0] = 2 * (x * y + w * z);     R[1][1] = 1 - 2 * (x * x + z * z); R[1][2] = 2 * (y * z - w * x);
    R[2][0] = 2 * (x * z - w * y);     R[2][1] = 2 * (y * z + w * x);     R[2][2] = 1 - 2 * (x * x + y * y);
}

void dem_quat_multiply(const double a[4], const double b[4], double out[4])
{
    const double w = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
    const double x = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
    const double y = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
    const double z = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
    out[0] = w; out[1] = x; out[2] = y; out[3] = z;
}

/* R[d][k] = axes[k][d]; the largest of w, x, y, z found first (Shepperd), for accuracy */
void dem_quat_from_axes(const double axes[3][3], double q[4])
{
    double R[3][3];
    for (int d = 0; d < 3; d++)
        for (int k = 0; k < 3; k++) R[d][k] = axes[k][d];
    const double tr = R[0][0] + R[1][1] + R[2][2];
    if (tr >= R[0][0] && tr >= R[1][1] && tr >= R[2][2]) {
        const double s = 2.0 * sqrt(1.0 + tr);
        q[0] = 0.25 * s;
        q[1] = (R[2][1] - R[1][2]) / s;
        q[2] = (R[0][2] - R[2][0]) / s;
        q[3] = (R[1][0] - R[0][1]) / s;
    } else if (R[0][0] >= R[1][1] && R[0][0] >= R[2][2]) {
        const double s = 2.0 * sqrt(1.0 + R[0][0] - R[1][1] - R[2][2]);
        q[0] = (R[2][1] - R[1][2]) / s;
        q[1] = 0.25 * s;
        q[2] = (R[0][1] + R[1][0]) / s;
        q[3] = (R[0][2] + R[2][0]) / s;
    } else if (R[1][1] >= R[2][2]) {
        const double s = 2.0 * sqrt(1.0 + R[1][1] - R[0][0] - R[2][2]);
        q[0] = (R[0][2] - R[2][0]) / s;
        q[1] = (R[0][1] + R[1][0]) / s;
        q[2] = 0.25 * s;
        q[3] = (R[1][2] + R[2][1]) / s;
    } else {
        const double s = 2.0 * sqrt(1.0 + R[2][2] - R[0][0] - R[1][1]);
        q[0] = (R[1][0] - R[0][1]) / s;
        q[1] = (R[0][2] + R[2][0]) / s;
        q[2] = (R[1][2] + R[2][1]) / s;
        q[3] = 0.25 * s;
    }
}

/* sin and cos of x: for |x| < 0.05 (a DEM step turns a body by far less) their Taylor series to
 * x^9, whose remainder is below 1e-16 of the result, so the value is the same to round-off and
 * costs a few multiplications; otherwise the library's. */
static void sin_cos(double x, double *s, double *c)
{
    if (fabs(x) < 0.05) {   /* multiplications by the reciprocals: no division in this path */
        const double x2 = x * x;
        *s = x * (1.0 - x2 * (1.0 / 6.0) * (1.0 - x2 * (1.0 / 20.0) * (1.0 - x2 * (1.0 / 42.0) * (1.0 - x2 * (1.0 / 72.0)))));
        *c = 1.0 - x2 * 0.5 * (1.0 - x2 * (1.0 / 12.0) * (1.0 - x2 * (1.0 / 30.0) * (1.0 - x2 * (1.0 / 56.0))));
        return;
    }
    *s = sin(x);
    *c = cos(x);
}

/* The body turned by tau L_k / I_k about its axis k; L_b, fixed in space, turns back. */
static void rotate_about_axis(int k, const double inv_I[3], double q[4], double Lb[3], double tau)
{
    const double phi = tau * Lb[k] * inv_I[k];
    double sh, ch;
    sin_cos(0.5 * phi, &sh, &ch);
    const double c = ch * ch - sh * sh, s = 2.0 * sh * ch;   /* of phi, from the half angle */
    const int a = (k + 1) % 3, b = (k + 2) % 3;
    const double La = Lb[a], Lc = Lb[b];
    Lb[a] = c * La + s * Lc;
    Lb[b] = -s * La + c * Lc;
    /* q <- q (ch, sh e_k) */
    double e[4] = {ch, 0.0, 0.0, 0.0};
    e[1 + k] = sh;
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    q[0] = w * e[0] - x * e[1] - y * e[2] - z * e[3];
    q[1] = w * e[1] + x * e[0] + y * e[3] - z * e[2];
    q[2] = w * e[2] - x * e[3] + y * e[0] + z * e[1];
    q[3] = w * e[3] + x * e[2] - y * e[1] + z * e[0];
}

void dem_rigid_free_rotation(const double I[3], double q[4], double Lb[3], double h)
{
    const double inv_I[3] = {1.0 / I[0], 1.0 / I[1], 1.0 / I[2]};
    rotate_about_axis(0, inv_I, q, Lb, 0.5 * h);
    rotate_about_axis(1, inv_I, q, Lb, 0.5 * h);
    rotate_about_axis(2, inv_I, q, Lb, h);
    rotate_about_axis(1, inv_I, q, Lb, 0.5 * h);
    rotate_about_axis(0, inv_I, q, Lb, 0.5 * h);
    const double inv_norm = 1.0 / sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (int k = 0; k < 4; k++) q[k] *= inv_norm;
}

void dem_rigid_kick(const double q[4], double Lb[3], const double T[3], double h)
{
    double Tb[3];
    dem_quat_rotate_inverse(q, T, Tb);
    for (int d = 0; d < 3; d++) Lb[d] += h * Tb[d];
}
