/* Fluid forces on particles per model A / B and their split for the exchange (see
 * particle_forces.h for the equations). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "particle_forces.h"

const char *const cpl_model_type_names[] = {"A", "B", 0};
const char *const cpl_exchange_mode_names[] = {"implicit", "explicit", 0};

int cpl_name_find(const char *const *names, const char *name)
{
    for (int k = 0; names[k]; k++)
        if (strcmp(name, names[k]) == 0) return k;
    return -1;
}

void cpl_force_params_check(const cpl_force_params *p)
{
    if (p->model != CPL_MODEL_A && p->model != CPL_MODEL_B)
        dem_fatal("coupling: model type %d is neither A nor B", (int)p->model);
    if (!cpl_drag_function(p->drag))
        dem_fatal("coupling: drag law %d is not one of the %d laws", (int)p->drag, CPL_DRAG_COUNT);
    if (p->exchange != CPL_EXCHANGE_IMPLICIT && p->exchange != CPL_EXCHANGE_EXPLICIT)
        dem_fatal("coupling: exchange mode %d is neither implicit nor explicit", (int)p->exchange);
    if (!(p->rho_f > 0.0) || !isfinite(p->rho_f))
        dem_fatal("coupling: fluid density %g must be positive [kg/m^3]", p->rho_f);
    if (!(p->mu_f > 0.0) || !isfinite(p->mu_f))
        dem_fatal("coupling: fluid dynamic viscosity %g must be positive [Pa s]", p->mu_f);
    for (int k = 0; k < 3; k++)
        if (!isfinite(p->gravity[k])) dem_fatal("coupling: gravity component %c is not finite", "xyz"[k]);
    if (!(p->coarse_graining == 0.0 || (p->coarse_graining >= 1.0 && p->coarse_graining <= 100.0)))
        dem_fatal("coupling: coarse-graining factor %g must be in [1, 100] (0: none)", p->coarse_graining);
}

void cpl_fluid_forces_init(cpl_fluid_forces *f)
{
    memset(f, 0, sizeof *f);
}

void cpl_fluid_forces_free(cpl_fluid_forces *f)
{
    free(f->beta);
    free(f->u_f);
    free(f->f_exchange);
    free(f->f_equation);
    cpl_fluid_forces_init(f);
}

static void reserve(cpl_fluid_forces *f, int n)
{
    if (n <= f->capacity) return;
    const int cap = n > 2 * f->capacity ? n : 2 * f->capacity;
    f->beta = dem_realloc(f->beta, (size_t)cap * sizeof *f->beta);
    f->u_f = dem_realloc(f->u_f, (size_t)cap * sizeof *f->u_f);
    f->f_exchange = dem_realloc(f->f_exchange, (size_t)cap * sizeof *f->f_exchange);
    f->f_equation = dem_realloc(f->f_equation, (size_t)cap * sizeof *f->f_equation);
    f->capacity = cap;
}

void cpl_fluid_forces_eval(const cpl_force_params *p, const cpl_particle_fluid *in, cpl_fluid_forces *out)
{
    const cpl_drag_fn drag = cpl_drag_function(p->drag);
    if (!drag) dem_fatal("coupling: drag law %d is not one of the %d laws", (int)p->drag, CPL_DRAG_COUNT);
    const int model_b = p->model == CPL_MODEL_B;
    const int implicit = p->exchange == CPL_EXCHANGE_IMPLICIT;
    const double cg = p->coarse_graining > 1.0 ? p->coarse_graining : 1.0, cg3 = cg * cg * cg;
    reserve(out, in->n);
    out->n = in->n;
    for (int i = 0; i < in->n; i++) {
        if (in->cell && in->cell[i] < 0) {   /* outside the mesh: no fluid, no exchange */
            out->beta[i] = 0.0;
            for (int k = 0; k < 3; k++) out->u_f[i][k] = out->f_exchange[i][k] = out->f_equation[i][k] = 0.0;
            continue;
        }
        double alpha = in->alpha[i];
        /* a bug upstream (void fraction) rather than physics: stop with the particle named */
        if (!(alpha > 0.0 && alpha <= 1.0 + 1e-9) || !(in->d[i] > 0.0))
            dem_fatal("coupling: particle %d has fluid fraction %g (must be in (0, 1]) and diameter %g m (must be > 0)",
                      i, alpha, in->d[i]);
        if (alpha > 1.0) alpha = 1.0;
        double rel[3];
        for (int k = 0; k < 3; k++) rel[k] = in->u_f[i][k] - in->v[i][k];
        const double slip = sqrt(rel[0] * rel[0] + rel[1] * rel[1] + rel[2] * rel[2]);
        const double beta_p = cg == 1.0 ? drag(p->rho_f, p->mu_f, in->d[i], alpha, slip)
                                        : cg3 * drag(p->rho_f, p->mu_f, in->d[i] / cg, alpha, slip);   /* a parcel */
        const double beta = model_b ? beta_p / alpha : beta_p;   /* the shared coefficient */
        const double vp = in->volume[i];
        out->beta[i] = implicit ? beta : 0.0;
        for (int k = 0; k < 3; k++) {
            out->u_f[i][k] = in->u_f[i][k];
            /* model B: Archimedes, reaction in S; model A: -V_p grad p, reaction in -alpha grad p */
            out->f_exchange[i][k] = model_b ? -p->rho_f * vp * p->gravity[k] + vp * p->drive[k] : 0.0;
            out->f_equation[i][k] = model_b ? 0.0 : -vp * in->grad_p[i][k] + vp * p->drive[k];
            if (!implicit) out->f_exchange[i][k] += beta * rel[k];   /* frozen drag */
        }
    }
}

void cpl_fluid_forces_add(const cpl_fluid_forces *f, const double (*v)[3], double (*force)[3])
{
    for (int i = 0; i < f->n; i++) {
        double F[3];
        cpl_fluid_force(f, i, v[i], F);
        for (int k = 0; k < 3; k++) force[i][k] += F[k];
    }
}
