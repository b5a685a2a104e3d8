/* A single head-on or oblique impact (two spheres, or a sphere on a plane z = 0), run until the
 * contact ends; shared by the restitution and oblique-impact tests. */
#ifndef TEST_IMPACT_H
#define TEST_IMPACT_H

#include "harness.h"

typedef struct impact_spec {
    double E, nu, rho, r;                 /* material and radius */
    double e, mu;                         /* pair restitution and friction */
    enum dem_normal_model normal;
    enum dem_tangential_model tangential;
    double v_char;                        /* hooke */
    int wall;                             /* 0: two spheres; 1: sphere on plane z = 0 */
    double vn, vt;                        /* approach speed; tangential speed (x) */
    double steps_per_contact;             /* dt = contact time / this */
    int limit_force;                      /* clip Fn >= 0 */
} impact_spec;

typedef struct impact_result {
    double restitution;                   /* normal separation / approach speed */
    double vt_after, vn_after, omega_after; /* sphere (or first sphere): v_x, v_z, omega_y */
    double dt;
} impact_result;

static double spec_contact_time(const impact_spec *sp)
{
    const double Y = 1.0 / (2.0 * (1.0 - sp->nu * sp->nu) / sp->E);
    const double mass = sp->rho * 4.0 / 3.0 * M_PI * pow(sp->r, 3);
    const double R = sp->wall ? sp->r : 0.5 * sp->r, meff = sp->wall ? mass : 0.5 * mass;
    if (sp->normal == normal_hooke) {
        const double sr = sqrt(R);
        const double kn = 16.0 / 15.0 * sr * Y * pow(15.0 * meff * sp->v_char * sp->v_char / (16.0 * sr * Y), 0.2);
        return M_PI * sqrt(meff / kn);
    }
    return 2.87 * pow(meff * meff / (R * Y * Y * sp->vn), 0.2);
}

static impact_result run_impact(const impact_spec *sp)
{
    dem_system s;
    make_system(&s, sp->E, sp->nu, sp->rho, sp->e, sp->mu, sp->normal, sp->tangential, 1.0);
    const dem_hooke_case hc = {sp->v_char};
    SET_MODEL_CASE(&s, SLOT_NORMAL, hc);
    s.models.fn_floor = sp->limit_force ? 0.0 : -INFINITY;
    s.dt = spec_contact_time(sp) / sp->steps_per_contact;
    s.nlist.skin = 0.05 * sp->r;
    const double r = sp->r, gap = 1e-6 * r;
    if (sp->wall) {
        add_plane(&s, 0, 0, 0, 0, 0, 1);
        add_sphere(&s, 0, 0, r + gap, sp->vt, 0, -sp->vn, r);
    } else {   /* along z, so that vn is the z component and vt the x component */
        add_sphere(&s, 0, 0, -r - gap, 0.5 * sp->vt, 0, 0.5 * sp->vn, r);
        add_sphere(&s, 0, 0, r + gap, -0.5 * sp->vt, 0, -0.5 * sp->vn, r);
    }
    dem_system_setup(&s);
    int touched = 0;
    for (long k = 0; k < 100000000; k++) {
        dem_system_step(&s);
        const double dist = sp->wall ? s.p.x[0][2] : s.p.x[1][2] - s.p.x[0][2];
        const double overlap = (sp->wall ? r : 2 * r) - dist;
        if (overlap > 0) touched = 1;
        else if (touched) break;
    }
    impact_result res;
    res.dt = s.dt;
    if (sp->wall) {
        res.restitution = s.p.v[0][2] / sp->vn;
        res.vt_after = s.p.v[0][0];
        res.vn_after = s.p.v[0][2];
        res.omega_after = s.p.omega[0][1];
    } else {
        res.restitution = (s.p.v[1][2] - s.p.v[0][2]) / sp->vn;
        res.vt_after = s.p.v[1][0];
        res.vn_after = s.p.v[1][2];
        res.omega_after = s.p.omega[1][1];
    }
    dem_system_free(&s);
    return res;
}

#endif
