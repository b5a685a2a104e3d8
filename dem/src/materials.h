/* Materials (one per particle type) and the per type-pair constants the contact models use.
 * Effective moduli follow LIGGGHTS' definitions so that parameters carry over unchanged. */
#ifndef DEM_MATERIALS_H
#define DEM_MATERIALS_H

#include <stddef.h>

#include "contact/model.h"

#define DEM_MAX_TYPES 16
#define DEM_NAME_LEN 64

typedef struct dem_material {
    char name[DEM_NAME_LEN];
    double youngs_modulus;   /* E [Pa] */
    double poisson_ratio;    /* nu [-] */
    double density;          /* rho [kg/m^3] */
    int rigid;               /* a wall that adds no compliance: 1/E = 0 in Y* and G* (walls only) */
} dem_material;

/* Constants for one pair of types (also used for particle-wall with the wall's material). */
typedef struct dem_pair_coeffs {
    double Y_eff;            /* 1/Y* = (1-nu_i^2)/E_i + (1-nu_j^2)/E_j  [Pa] */
    double G_eff;            /* 1/G* = 2(2-nu_i)(1+nu_i)/E_i + 2(2-nu_j)(1+nu_j)/E_j  [Pa] */
    double restitution;      /* e [-] */
    double beta;             /* ln(e) / sqrt(ln(e)^2 + pi^2), Hertz damping [-] */
    double log_e;            /* ln(e), Hooke damping [-] */
    double friction;         /* Coulomb mu [-] */
    double sqrt_st_over_sn;  /* sqrt(4 G* / Y*): Hertz gamma_t over gamma_n [-] */
    double damping;          /* alpha of the normal dashpot, gamma_n = alpha sqrt(m* dFn/d delta) [-]:
                                Tsuji's 2 sqrt(5/6) |beta| unless the normal model's prepare sets
                                its own (restitution.h) */
    /* per slot: the chosen model's parameters and derived constants (its *_params struct) */
    double model[SLOT_COUNT][MODEL_VALUES];
} dem_pair_coeffs;

/* A model's parameter struct seen in the values of its slot. */
#define MODEL_PARAMS(c, slot, type) ((const type *)(c)->model[slot])

typedef struct dem_material_table {
    int ntypes;
    dem_material mat[DEM_MAX_TYPES];
    dem_pair_coeffs pair[DEM_MAX_TYPES * DEM_MAX_TYPES];  /* [ti * DEM_MAX_TYPES + tj] */
} dem_material_table;

int dem_materials_find(const dem_material_table *t, const char *name);   /* -1 if absent */
/* Fill pair[ti][tj] and pair[tj][ti] from the two materials, e and mu. */
void dem_materials_set_pair(dem_material_table *t, int ti, int tj, double restitution, double friction);
/* A slot's model values for the pair (both orders; after dem_materials_set_pair): bytes of a
 * model's *_params struct. */
void dem_materials_set_model_values(dem_material_table *t, int ti, int tj, enum dem_contact_slot slot,
                                const void *values, size_t bytes);

static inline const dem_pair_coeffs *materials_pair(const dem_material_table *t, int ti, int tj)
{
    return &t->pair[ti * DEM_MAX_TYPES + tj];
}

#endif
