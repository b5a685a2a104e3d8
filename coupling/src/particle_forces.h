/* Fluid forces on the particles, per momentum coupling model A or B (Zhou, Kuang, Chu & Yu 2010,
 * J. Fluid Mech. 661:482: model A = their set II, model B = their set III), and how each force is
 * handed to the fluid (exchange.h spreads it onto the cells).
 *
 * Notation: beta_p the drag law's coefficient (drag.h), v the particle velocity, u_f the fluid
 * velocity at the particle, alpha the fluid fraction at the particle, V_p the particle volume,
 * grad p the gradient of the full pressure [Pa/m] (it includes the hydrostatic part rho_f g),
 * g gravity [m/s^2].
 *
 * Model A (set II): the particle feels the drag and the pressure-gradient force,
 *     F = beta_p (u_f - v) - V_p grad p
 * and the fluid equation (per unit volume of mixture, [N/m^3]) carries alpha grad p and the drag:
 *     rho_f [d(alpha u)/dt + div(alpha u u)] = -alpha grad p + div(alpha tau) + alpha rho_f g
 *                                               + K_sl (up - u) + S
 * The reaction of -V_p grad p is in -alpha grad p = -grad p + (1 - alpha) grad p: when alpha is
 * built from the same cell weights, (1 - alpha) V_cell grad p = sum of V_p grad p over the cell's
 * particles. So S holds only the drag kept explicit. Buoyancy is part of -V_p grad p: in a
 * hydrostatic fluid (grad p = rho_f g) it is exactly -rho_f V_p g.
 *
 * Model B (set III): the particle feels the drag divided by alpha and the Archimedes buoyancy,
 *     F = (beta_p / alpha) (u_f - v) - rho_f V_p g
 * and the fluid equation carries grad p and the total interaction:
 *     rho_f [d(alpha u)/dt + div(alpha u u)] = -grad p + div(alpha tau) + alpha rho_f g
 *                                               + K_sl (up - u) + S,
 *     S = sum over the cell's particles of w rho_f V_p g / V_cell (+ the explicit drag).
 * (Zhou et al.'s set III has div(tau); voidPimpleFoam keeps alpha tau in both models, as
 * DPMFoam does: the viscous stress of the gas acts on the gas's share of the cell.)
 * Why beta_p / alpha: in a steady uniform suspension the fluid equation of model A gives
 * grad p = rho_f g - n f_d / alpha (n particles per volume, f_d the drag), so the model A force
 * f_d - V_p grad p = f_d / alpha - rho_f V_p g: the dynamic part of the pressure gradient is
 * folded into the drag, the hydrostatic part is the Archimedes term. In a static column both
 * models give the particle exactly -rho_f V_p g; alpha rho_f g + S = rho_f g keeps the column
 * hydrostatic in model B (with alpha from the same weights).
 *
 * If the solver uses a pressure without the hydrostatic part, p' = p - rho_f g.x, pass
 * grad p = grad p' + rho_f g here; its equations become: model A  -alpha grad p' (no gravity
 * term), model B  -grad p' - (1 - alpha) rho_f g (plus S as above).
 *
 * Exchange: beta is the coefficient the particle and the fluid share (beta_p in model A,
 * beta_p / alpha in model B). Implicit: the fluid gets K_sl = sum w beta / V_cell into its matrix
 * and the particle feels beta (u_f - v) with its current v during the DEM sub-steps (beta and
 * u_f frozen at the evaluation). Explicit: the drag is evaluated once and frozen; the particle
 * feels it unchanged and its reaction goes to S.
 *
 * Per particle the evaluation stores three parts, F(v) = beta (u_f - v) + f_exchange + f_equation:
 *   beta        implicit coefficient [kg/s] (0 in explicit mode);
 *   f_exchange  force whose reaction goes to the fluid's explicit source S [N]
 *               (explicit drag; model B's buoyancy);
 *   f_equation  force whose reaction is in the fluid equation's own terms [N]
 *               (model A's -V_p grad p; 0 in model B).
 * The fluid's sources then balance beta (u_f - v) + f_exchange exactly (exchange.h), provided
 * u_f at the particle is gathered from the cells with the same weights (cpl_gather_vector).
 * Equations (numbered), sources and choices: docs/models/forces_modelA_B.md. */
#ifndef CPL_PARTICLE_FORCES_H
#define CPL_PARTICLE_FORCES_H

#include "coupling.h"
#include "drag.h"

#ifdef __cplusplus
extern "C" {
#endif

enum cpl_exchange_mode { CPL_EXCHANGE_IMPLICIT, CPL_EXCHANGE_EXPLICIT, CPL_EXCHANGE_COUNT };

extern const char *const cpl_model_type_names[];      /* "A", "B", 0 */
extern const char *const cpl_exchange_mode_names[];   /* "implicit", "explicit", 0 */
/* Index of `name` in a 0-terminated name table, or -1. */
int cpl_name_find(const char *const *names, const char *name);

typedef struct cpl_force_params {
    enum cpl_model_type model;
    enum cpl_drag_law drag;
    enum cpl_exchange_mode exchange;
    double rho_f;        /* fluid density [kg/m^3] */
    double mu_f;         /* dynamic viscosity [Pa s] (= rho_f nu_f) */
    double gravity[3];   /* [m/s^2] (model B's buoyancy) */
    /* A driving pressure gradient imposed on the periodic fluid, -grad p_drive [N/m^3] (not in the
     * solver's periodic p): each particle feels V_p drive, as it feels -V_p grad p. Model A: in
     * f_equation (its reaction is in the fluid's -alpha grad p_drive, which the solver adds as
     * alpha drive); model B: in f_exchange (its reaction goes to S; the solver adds the full drive,
     * as model B's fluid has the full grad p). Either way the fluid keeps alpha drive of it. */
    double drive[3];
    /* Coarse graining cg (docs/models/coarse_graining.md): a particle of diameter d is a parcel of
     * cg^3 primary particles of diameter d / cg, and its drag is theirs, cg^3 beta_p(d / cg), as
     * CFDEM-PFM's drag models scale it (the drag law's Re from d / cg). Its volume is the parcel's
     * (cg^3 primary volumes) already. 0 or 1: none (a zeroed struct means none). */
    double coarse_graining;
} cpl_force_params;

/* A bad parameter is a fatal error naming it (error.h). */
void cpl_force_params_check(const cpl_force_params *p);

/* Inputs per particle: views of the caller's arrays, all of length n. */
typedef struct cpl_particle_fluid {
    int n;
    const double (*v)[3];        /* particle velocity [m/s] */
    const double *d;             /* diameter [m] */
    const double *volume;        /* volume [m^3] */
    const double (*u_f)[3];      /* fluid velocity at the particle [m/s] */
    const double (*grad_p)[3];   /* full pressure gradient at the particle [Pa/m] (model A) */
    const double *alpha;         /* fluid fraction at the particle, 0 < alpha <= 1 */
    const int *cell;             /* may be NULL; else cell[i] < 0 marks a particle outside the
                                    mesh (as cpl_vf_compute sets it): it gets no fluid force */
} cpl_particle_fluid;

/* Outputs per particle (owned; grown by cpl_fluid_forces_eval). */
typedef struct cpl_fluid_forces {
    int n, capacity;
    double *beta;             /* [kg/s] */
    double (*u_f)[3];         /* fluid velocity at the particle at the evaluation [m/s] */
    double (*f_exchange)[3];  /* [N] */
    double (*f_equation)[3];  /* [N] */
} cpl_fluid_forces;

void cpl_fluid_forces_init(cpl_fluid_forces *f);
void cpl_fluid_forces_free(cpl_fluid_forces *f);

/* Evaluate the drag law and split the forces for every particle of `in` (see above). A particle
 * in the mesh with alpha outside (0, 1 + 1e-9] or a diameter <= 0 stops the program with its
 * index (alpha just above 1 from round-off is taken as 1). */
void cpl_fluid_forces_eval(const cpl_force_params *p, const cpl_particle_fluid *in, cpl_fluid_forces *out);

/* The force on particle i at velocity v [N]: every DEM sub-step (implicit mode gives the drag at
 * the current v; explicit mode returns the frozen force). It is affine in v,
 * F = (beta u_f + f_exchange + f_equation) - beta v, so a DEM integrator may also treat the
 * beta v part implicitly. */
static inline void cpl_fluid_force(const cpl_fluid_forces *f, int i, const double v[3], double F[3])
{
    for (int k = 0; k < 3; k++)
        F[k] = f->beta[i] * (f->u_f[i][k] - v[k]) + f->f_exchange[i][k] + f->f_equation[i][k];
}

/* The part of it whose reaction is in the fluid's K_sl and explicit source [N]. */
static inline void cpl_fluid_force_exchanged(const cpl_fluid_forces *f, int i, const double v[3], double F[3])
{
    for (int k = 0; k < 3; k++)
        F[k] = f->beta[i] * (f->u_f[i][k] - v[k]) + f->f_exchange[i][k];
}

/* force[i] += cpl_fluid_force(f, i, v[i]) for all f->n particles. */
void cpl_fluid_forces_add(const cpl_fluid_forces *f, const double (*v)[3], double (*force)[3]);

#ifdef __cplusplus
}
#endif
#endif
