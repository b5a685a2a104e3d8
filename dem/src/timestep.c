#include <math.h>
#include <stdio.h>

#include "error.h"
#include "system.h"
#include "timestep.h"
#include "reduce.h"

/* Rayleigh-wave time across a sphere: pi r sqrt(rho/G) / (0.1631 nu + 0.8766). */
static double rayleigh_time(const dem_material *m, double radius)
{
    const double shear_modulus = m->youngs_modulus / (2.0 * (1.0 + m->poisson_ratio));
    return M_PI * radius * sqrt(m->density / shear_modulus) / (0.1631 * m->poisson_ratio + 0.8766);
}

/* Duration of an elastic impact at relative speed v, from the normal model (its header). */
static double contact_time(const dem_system *s, const dem_pair_coeffs *c, double r_eff, double m_eff, double v)
{
    return system_model(s, SLOT_NORMAL)->contact_time(c, &s->models, r_eff, m_eff, v);
}

dem_timestep_limits dem_timestep_limits_compute(const dem_system *s, double max_velocity)
{
    const dem_particles *p = &s->p;
    const int nt = s->materials.ntypes;
    double rmin[DEM_MAX_TYPES];
    for (int t = 0; t < nt; t++) rmin[t] = INFINITY;
    for (int i = 0; i < p->n; i++) rmin[p->type[i]] = fmin(rmin[p->type[i]], p->radius[i]);
    for (int t = 0; t < nt; t++) {   /* and the particles the streams will insert */
        double dmin, dmax;
        dem_streams_diameters(s, t, &dmin, &dmax);
        rmin[t] = fmin(rmin[t], 0.5 * dmin);
    }
    dem_reduce_doubles(rmin, nt, DEM_REDUCE_MIN);   /* the smallest on any rank (reduce.h) */

    dem_timestep_limits lim = {INFINITY, INFINITY, INFINITY, "-", "-"};
    static char pair_name[2 * DEM_NAME_LEN + 16];
    for (int a = 0; a < nt; a++) {
        if (!isfinite(rmin[a])) continue;
        const dem_material *ma = &s->materials.mat[a];
        const double tr = rayleigh_time(ma, rmin[a]);
        if (tr < lim.rayleigh_time) { lim.rayleigh_time = tr; lim.rayleigh_material = ma->name; }
        const double m_a = ma->density * 4.0 / 3.0 * M_PI * pow(rmin[a], 3);
        for (int b = 0; b < nt; b++) {
            if (!isfinite(rmin[b])) continue;
            const double m_b = s->materials.mat[b].density * 4.0 / 3.0 * M_PI * pow(rmin[b], 3);
            const double tc = contact_time(s, materials_pair(&s->materials, a, b),
                                           rmin[a] * rmin[b] / (rmin[a] + rmin[b]), m_a * m_b / (m_a + m_b),
                                           max_velocity);
            if (tc < lim.contact_time) {
                lim.contact_time = tc;
                snprintf(pair_name, sizeof pair_name, "%s-%s", ma->name, s->materials.mat[b].name);
                lim.contact_pair = pair_name;
            }
        }
        for (int k = 0; k < s->nwalls; k++) {
            const int wm = s->walls[k].material;
            const double tc = contact_time(s, materials_pair(&s->materials, a, wm), rmin[a], m_a, max_velocity);
            if (tc < lim.contact_time) {
                lim.contact_time = tc;
                snprintf(pair_name, sizeof pair_name, "%s-wall '%s'", ma->name, s->walls[k].name);
                lim.contact_pair = pair_name;
            }
        }
    }
    lim.largest_safe_dt = fmin(RAYLEIGH_FRACTION * lim.rayleigh_time, CONTACT_FRACTION * lim.contact_time);
    return lim;
}

void dem_timestep_check(const dem_system *s, double max_velocity, int override, const char *source)
{
    if (s->p.n == 0 && s->nstreams == 0) {
        dem_info("time step %g s: not checked, there are no particles", s->dt);
        return;
    }
    if (!isfinite(max_velocity))   /* no contact time to compare with */
        dem_fatal_at(source, "key 'timeStep': cannot be checked: the expected impact speed is %g m/s (the "
                     "fastest particle at the start plus free fall over the domain's height); give "
                     "maxExpectedVelocity [m/s], or a gravity and domain that give a finite speed",
                     max_velocity);
    const dem_timestep_limits lim = dem_timestep_limits_compute(s, max_velocity);
    const double fr = s->dt / lim.rayleigh_time, fc = s->dt / lim.contact_time;
    dem_info("time step %g s: %.3f of the Rayleigh time %.3g s (%s; limit %.2f), "
             "%.3f of the %s contact time %.3g s at %g m/s (%s; limit %.2f)",
             s->dt, fr, lim.rayleigh_time, lim.rayleigh_material, RAYLEIGH_FRACTION, fc,
             system_model(s, SLOT_NORMAL)->contact_time_name, lim.contact_time,
             max_velocity, lim.contact_pair, CONTACT_FRACTION);
    if (s->dt <= lim.largest_safe_dt) return;
    if (override) {
        dem_warning("\n*****************************************************************\n"
                    "  timeStep %g s exceeds the largest safe step %.3g s; running anyway\n"
                    "  because timeStepOverride is set. Expect wrong contacts or a blow-up.\n"
                    "*****************************************************************",
                    s->dt, lim.largest_safe_dt);
        return;
    }
    dem_fatal_at(source, "key 'timeStep': %g s is too large: the largest safe step is %.3g s "
              "(%.2f x Rayleigh time %.3g s of '%s', %.2f x contact time %.3g s of %s at "
              "maxExpectedVelocity %g m/s). Lower timeStep, or set timeStepOverride true to run anyway.",
              s->dt, lim.largest_safe_dt, RAYLEIGH_FRACTION, lim.rayleigh_time,
              lim.rayleigh_material, CONTACT_FRACTION, lim.contact_time, lim.contact_pair, max_velocity);
}
