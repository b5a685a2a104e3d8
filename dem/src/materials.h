/* Materials (one per particle type) and the per type-pair constants the contact models use.
 * Effective moduli follow LIGGGHTS' definitions so that parameters carry over unchanged. */
#ifndef DEM_MATERIALS_H
#define DEM_MATERIALS_H

#define DEM_MAX_TYPES 16
#define DEM_NAME_LEN 64

typedef struct material {
    char name[DEM_NAME_LEN];
    double youngs_modulus;   /* E [Pa] */
    double poisson_ratio;    /* nu [-] */
    double density;          /* rho [kg/m^3] */
} material;

/* Parameters of the optional contact models, per pair of materials (zero when unused). */
typedef struct pair_model_params {
    double rolling_friction;        /* mu_r [-] (cdt, epsd) */
    double rolling_damping;         /* eta_r [-] (epsd dashpot, fraction of critical) */
    double work_of_adhesion;        /* W [J/m^2] (cdtJkr, seed 000 eq. 2) */
    double adhesion_hysteresis;     /* eta_adh [-] (cdtJkr, seed 000 eq. 3) */
    double cohesion_energy_density; /* k_coh [J/m^3] (sjkr) */
    double unloading_ratio;         /* kappa21 = k2/k1 > 1 [-] (edinburgh, seed 002 eq. 1) */
    double surface_energy;          /* gamma_s [J/m^2] (edinburgh eq. 5) */
    double loading_exponent;        /* d_ex >= 1 [-] (edinburgh eq. 2) */
    double adhesion_exponent;       /* c_ex > 0 [-] (edinburgh eq. 2) */
    double tension_threshold;       /* F_0 [N] (edinburgh eq. 9) */
} pair_model_params;

/* Constants for one pair of types (also used for particle-wall with the wall's material). */
typedef struct pair_coeffs {
    double Y_eff;            /* 1/Y* = (1-nu_i^2)/E_i + (1-nu_j^2)/E_j  [Pa] */
    double G_eff;            /* 1/G* = 2(2-nu_i)(1+nu_i)/E_i + 2(2-nu_j)(1+nu_j)/E_j  [Pa] */
    double restitution;      /* e [-] */
    double beta;             /* ln(e) / sqrt(ln(e)^2 + pi^2), Hertz damping [-] */
    double log_e;            /* ln(e), Hooke damping [-] */
    double friction;         /* Coulomb mu [-] */
    double sqrt_st_over_sn;  /* sqrt(4 G* / Y*): Hertz gamma_t over gamma_n [-] */
    pair_model_params m;     /* parameters of the optional models */
    double edinburgh_lambda; /* (1 - 1/kappa21)^(1/d_ex), seed 002 eq. 3 */
} pair_coeffs;

typedef struct material_table {
    int ntypes;
    material mat[DEM_MAX_TYPES];
    pair_coeffs pair[DEM_MAX_TYPES * DEM_MAX_TYPES];  /* [ti * DEM_MAX_TYPES + tj] */
} material_table;

int materials_find(const material_table *t, const char *name);   /* -1 if absent */
/* Fill pair[ti][tj] and pair[tj][ti] from the two materials, e and mu. */
void materials_set_pair(material_table *t, int ti, int tj, double restitution, double friction);
/* Parameters of the optional models for the pair (after materials_set_pair). */
void materials_set_models(material_table *t, int ti, int tj, const pair_model_params *m);

static inline const pair_coeffs *materials_pair(const material_table *t, int ti, int tj)
{
    return &t->pair[ti * DEM_MAX_TYPES + tj];
}

#endif
