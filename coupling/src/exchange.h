/* Momentum exchange: per-cell accumulation of the particles' coupling into the fields the fluid
 * solver uses, and the gather of cell fields to the particles with the same weights.
 *
 * Each particle i is spread onto cells through (cell, weight) pairs with weights summing to 1
 * (produced by the void fraction code; any scheme: the containing cell only, or divided over
 * several). With the per-particle split of particle_forces.h, for every cell c [N/m^3]:
 *
 *     K_sl[c]  = sum_i w_ic beta_i / V_c                              [kg/(m^3 s)]
 *     up[c]    = sum_i w_ic beta_i v_i / sum_i w_ic beta_i             [m/s]  (0 if the sum is 0)
 *     S[c]     = -sum_i w_ic f_exchange_i / V_c                        [N/m^3]
 *
 * and the fluid's momentum source is K_sl (up - u_f) + S (u_f the cell velocity). Summed over
 * the cells, V_c times that source is exactly minus the sum over particles of
 * beta_i (u_f,i - v_i) + f_exchange_i when u_f,i = sum_c w_ic u_f[c] (cpl_gather_vector):
 * what the fluid loses the particles gain, to round-off, for either model and mode.
 *
 * Order within a fluid step, so that the balance holds:
 *   implicit: DEM sub-steps with cpl_fluid_force (beta, u_f frozen, v current); after them, the
 *             void fraction (new weights), gather u_f, alpha, grad p with those weights,
 *             cpl_fluid_forces_eval, then cpl_exchange_cells with the same v. The fluid solves
 *             with K_sl (up - u_f) implicit in u_f; the next sub-steps use the same beta with
 *             u_f gathered from the new field (coupling.c says why beta is kept).
 *   explicit: the forces of the last exchange (frozen), the DEM sub-steps with them, then the
 *             evaluation and cpl_exchange_cells as above: the fluid receives the forces the
 *             particles will feel in the next sub-steps.
 * Equations, choices: docs/models/exchange_implicit_explicit.md. */
#ifndef CPL_EXCHANGE_H
#define CPL_EXCHANGE_H

#include "particle_forces.h"

#ifdef __cplusplus
extern "C" {
#endif

/* CSR view of the caller's arrays (cpl_voidfraction's w_start, w_cell, w fit as they are):
 * particle i spreads onto cell[start[i] .. start[i+1]) with weight[...] (>= 0, summing to 1 per
 * particle). A particle with no cells (outside the mesh) exchanges nothing; it must then get no
 * fluid force either (cpl_particle_fluid.cell). */
typedef struct cpl_cell_weights {
    int nparticles;
    const int *start;       /* [nparticles + 1], start[0] = 0 */
    const int *cell;        /* [start[nparticles]] cell indices in [0, ncells) */
    const double *weight;   /* [start[nparticles]] */
} cpl_cell_weights;

/* Checks the structure (non-decreasing start, cells in range, weights >= 0 summing to 1 within
 * tol for every particle that has cells); a violation is a fatal error naming the particle.
 * Once per step at most; not needed in production runs. */
void cpl_cell_weights_check(const cpl_cell_weights *w, int ncells, double tol);

/* at_particle[i] = sum_c w_ic cell_field[c]: the cell values seen by each particle with the
 * same weights as the spreading (needed for exact momentum balance). */
void cpl_gather_scalar(const cpl_cell_weights *w, const double *cell_field, double *at_particle);
void cpl_gather_vector(const cpl_cell_weights *w, const double (*cell_field)[3], double (*at_particle)[3]);

/* Fills ksl, up, source for all ncells cells (zeroing first) from the forces evaluated by
 * cpl_fluid_forces_eval for the same particles (f->n == w->nparticles) and their current
 * velocities v [m/s]. cell_volume [m^3]. */
void cpl_exchange_cells(const cpl_cell_weights *w, const cpl_fluid_forces *f, const double (*v)[3],
                        int ncells, const double *cell_volume,
                        double *ksl, double (*up)[3], double (*source)[3]);

#ifdef __cplusplus
}
#endif
#endif
