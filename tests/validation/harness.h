/* Small helpers for the validation tests: build a system in code, run it, check numbers
 * against closed forms with a stated tolerance, count the checks. */
#ifndef TEST_HARNESS_H
#define TEST_HARNESS_H

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "system.h"

static int checks_passed, checks_failed;

/* |measured - reference| <= tol * |reference| */
static inline int check_rel(const char *what, double measured, double reference, double tol)
{
    const double err = fabs(measured - reference) / fabs(reference);
    const int ok = err <= tol && isfinite(measured);
    printf("CHECK %-58s measured=%-12.6g reference=%-12.6g error=%7.3f%% tolerance=%5.2f%% %s\n",
           what, measured, reference, 100.0 * err, 100.0 * tol, ok ? "PASS" : "FAIL");
    if (ok) checks_passed++; else checks_failed++;
    return ok;
}

static inline int check_true(const char *what, int ok)
{
    printf("CHECK %-58s %s\n", what, ok ? "PASS" : "FAIL");
    if (ok) checks_passed++; else checks_failed++;
    return ok;
}

/* |measured| <= bound (a non-finite measure fails) */
static inline int check_below(const char *what, double measured, double bound)
{
    const int ok = fabs(measured) <= bound && isfinite(measured);
    printf("CHECK %-58s measured=%-12.6g bound=%-12.6g %s\n", what, measured, bound, ok ? "PASS" : "FAIL");
    if (ok) checks_passed++; else checks_failed++;
    return ok;
}

static inline int finish(const char *name)
{
    printf("%s: %d passed, %d failed\n", name, checks_passed, checks_failed);
    return checks_failed ? 1 : 0;
}

/* A system with one material (E, nu, rho), given e and mu, models, in a box [-L, L]^3. */
static inline void make_system(dem_system *s, double E, double nu, double rho, double e, double mu,
                        enum dem_normal_model normal, enum dem_tangential_model tangential, double L)
{
    dem_system_init(s);
    dem_material *m = &s->materials.mat[0];
    snprintf(m->name, sizeof m->name, "test");
    m->youngs_modulus = E;
    m->poisson_ratio = nu;
    m->density = rho;
    s->materials.ntypes = 1;
    dem_materials_set_pair(&s->materials, 0, 0, e, mu);
    s->models.normal = normal;
    s->models.tangential = tangential;
    for (int d = 0; d < 3; d++) { s->domain_min[d] = -L; s->domain_max[d] = L; }
    s->max_overlap_fraction = 1.0;
}

/* A slot's case-wide model settings (a model's *_case struct, e.g. roughness_case). */
#define SET_MODEL_CASE(s, slot, value) memcpy((s)->models.values[slot], &(value), sizeof(value))

static inline int add_sphere(dem_system *s, double x, double y, double z, double vx, double vy, double vz, double r)
{
    const double pos[3] = {x, y, z}, vel[3] = {vx, vy, vz};
    return dem_particles_add(&s->p, pos, vel, r, s->materials.mat[0].density, 0, s->next_id++);
}

static inline void add_plane(dem_system *s, double px, double py, double pz, double nx, double ny, double nz)
{
    dem_wall *w = dem_walls_add(s);
    memset(w, 0, sizeof *w);
    snprintf(w->name, sizeof w->name, "plane%d", s->nwalls);
    w->kind = WALL_PLANE;
    w->point[0] = px; w->point[1] = py; w->point[2] = pz;
    w->normal[0] = nx; w->normal[1] = ny; w->normal[2] = nz;
}

#endif
