/* Elastic Hertz impacts, sphere-sphere and sphere-wall: maximum overlap, maximum force and
 * contact time against Hertz theory, for glass (E 63 GPa, nu 0.2, rho 2500) and a soft
 * material (E 5 MPa, nu 0.45, rho 2500), impact speeds 0.1 to 10 m/s. Tolerance 2 %.
 *
 * Hertz theory with effective modulus Y*, radius R*, mass m* and impact speed v:
 *   delta_max = (15 m* v^2 / (16 Y* sqrt(R*)))^(2/5),  F_max = 4/3 Y* sqrt(R*) delta_max^(3/2),
 *   t_c = 2 (delta_max / v) I,  I = int_0^1 (1 - x^(5/2))^(-1/2) dx = (2/5) B(2/5, 1/2).
 * Time step t_c / 200: the contact time is counted in whole steps (0.5 % resolution). */
#include "harness.h"

typedef struct impact_result { double delta_max, f_max, t_contact, restitution; } impact_result;

/* Head-on impact at relative speed v; wall != 0: one sphere on a plane. dt = t_c / steps. */
static impact_result impact(double E, double nu, double rho, double r, double v, double e, int wall,
                            enum dem_normal_model normal, double dt)
{
    dem_system s;
    make_system(&s, E, nu, rho, e, 0.0, normal, tangential_none, 0.1);
    s.dt = dt;
    s.nlist.skin = 0.05 * r;
    if (wall) {
        add_plane(&s, 0, 0, -r, 0, 0, 1);
        add_sphere(&s, 0, 0, 1e-9, 0, 0, -v, r);           /* just touching, approaching */
    } else {
        add_sphere(&s, -r - 1e-9, 0, 0, 0.5 * v, 0, 0, r);
        add_sphere(&s, r + 1e-9, 0, 0, -0.5 * v, 0, 0, r);
    }
    dem_system_setup(&s);
    impact_result res = {0, 0, 0, 0};
    long in_contact = 0;
    for (long k = 0; k < 100000000; k++) {
        dem_system_step(&s);
        const double delta = wall ? r - (s.p.x[0][2] + r) : 2 * r - (s.p.x[1][0] - s.p.x[0][0]);
        if (delta > 0) {
            in_contact++;
            res.delta_max = fmax(res.delta_max, delta);
            res.f_max = fmax(res.f_max, fabs(wall ? s.p.f[0][2] : s.p.f[0][0]));
        } else if (in_contact) break;
    }
    res.t_contact = in_contact * dt;
    res.restitution = wall ? s.p.v[0][2] / v : (s.p.v[1][0] - s.p.v[0][0]) / v;
    dem_system_free(&s);
    return res;
}

int main(void)
{
    const double I = 0.4 * tgamma(0.4) * tgamma(0.5) / tgamma(0.9);
    const struct { const char *name; double E, nu; } mats[] = {{"glass", 63e9, 0.2}, {"soft", 5e6, 0.45}};
    const double speeds[] = {0.1, 1.0, 10.0};
    const double rho = 2500, r = 1e-3;
    for (int m = 0; m < 2; m++) {
        for (int wall = 0; wall <= 1; wall++) {
            for (int k = 0; k < 3; k++) {
                const double E = mats[m].E, nu = mats[m].nu, v = speeds[k];
                const double Y = 1.0 / (2.0 * (1.0 - nu * nu) / E);   /* same material both sides */
                const double mass = rho * 4.0 / 3.0 * M_PI * r * r * r;
                const double R = wall ? r : 0.5 * r, meff = wall ? mass : 0.5 * mass;
                const double dmax = pow(15.0 * meff * v * v / (16.0 * Y * sqrt(R)), 0.4);
                const double fmax_ = 4.0 / 3.0 * Y * sqrt(R) * pow(dmax, 1.5);
                const double tc = 2.0 * dmax / v * I;
                const impact_result res = impact(E, nu, rho, r, v, 1.0, wall, normal_hertz, tc / 200.0);
                char what[128];
                snprintf(what, sizeof what, "%s %s v=%g: max overlap", mats[m].name, wall ? "wall" : "pair", v);
                check_rel(what, res.delta_max, dmax, 0.02);
                snprintf(what, sizeof what, "%s %s v=%g: max force", mats[m].name, wall ? "wall" : "pair", v);
                check_rel(what, res.f_max, fmax_, 0.02);
                snprintf(what, sizeof what, "%s %s v=%g: contact time", mats[m].name, wall ? "wall" : "pair", v);
                check_rel(what, res.t_contact, tc, 0.02);
                snprintf(what, sizeof what, "%s %s v=%g: elastic restitution", mats[m].name, wall ? "wall" : "pair", v);
                check_rel(what, res.restitution, 1.0, 0.001);
            }
        }
    }
    return finish("test_hertz_impact");
}
