/* What every contact model is made of, and what the force loops hand to it.
 *
 * A contact model lives in one header in this folder (normal_*.h, tangential_*.h, cohesion_*.h,
 * rolling_*.h, surface_*.h). The header holds everything about the model: its equations, its
 * parameters (a struct of doubles and a table of their keys, units, defaults and ranges), its
 * history, the geometry it needs, its checks and derived constants, and its force function
 * with the signature of its slot (below). models.h lists every model once; the enums, the
 * names, the reading of the parameters, the history sizes and the time-step check come from
 * that list. Adding a model: its header, and one line in models.h.
 *
 * Force functions by slot (all static inline, called by evaluate.h for pairs and walls alike):
 *   normal:     normal_result normal_X_force(const contact *k, const pair_coeffs *c,
 *                                            const contact_models *m, double *h)
 *   tangential: void tangential_X_force(const contact *k, const pair_coeffs *c, normal_result n,
 *                                       const double en_f[3], const double vt[3], double *h, double ft[3])
 *   cohesion:   double cohesion_X_force(const contact *k, const pair_coeffs *c)   (added to Fn)
 *   rolling:    void rolling_X_torque(const contact *k, const pair_coeffs *c, const contact_models *m,
 *                                     normal_result n, const double w[3], double *h, double torque_i[3])
 *   surface:    void surface_X_normal(const contact *k, const contact_models *m, double *h, double en_f[3])
 *               void surface_X_wall_guard(const contact_models *m, const double en[3],
 *                                         const double f[3], double v[3])
 * h points at the model's own part of the contact's history. */
#ifndef DEM_CONTACT_MODEL_H
#define DEM_CONTACT_MODEL_H

#include <stddef.h>
#include <stdint.h>

enum dem_contact_slot { SLOT_NORMAL, SLOT_TANGENTIAL, SLOT_COHESION, SLOT_ROLLING, SLOT_SURFACE, SLOT_COUNT };

/* Doubles a model may keep per material pair (its parameters, then its derived constants) and
 * per case; each model's parameter struct must fit (checked by a static assertion). */
#define MODEL_VALUES 8

/* The models chosen for a case, and their case-wide settings. */
typedef struct dem_contact_models {
    int normal, tangential, cohesion, rolling, surface;   /* ids: enum normal_model, ... */
    double fn_floor;      /* limitForce: 0 (Fn never below min(F_el, 0): no pull from the dashpot), else -inf */
    /* per slot: the chosen model's case-wide settings (its *_case struct), from contactModels */
    double values[SLOT_COUNT][MODEL_VALUES];
} dem_contact_models;

/* A model's settings struct seen in the case-wide values of its slot. */
#define MODEL_CASE(m, slot, type) ((const type *)(m)->values[slot])

/* A numeric parameter of one interaction (a material pair in demProperties' interactions). */
typedef struct dem_model_param {
    const char *key;
    const char *unit;       /* SI, "-" for a number without unit */
    double fallback;        /* NAN: required */
    double lo, hi;          /* accepted range, inclusive */
    size_t offset;          /* where it goes: offsetof(<model>_params, field) */
} dem_model_param;

struct dem_dict;
struct dem_pair_coeffs;
/* A contact model: what the generic code needs to know about it. */
typedef struct dem_contact_model {
    enum dem_contact_slot slot;
    const char *name;                 /* as written in contactModels */
    int history;                      /* doubles of history per contact */
    int history_antisymmetric;        /* leading doubles that change sign when (i, j) swap */
    int needs_contact_radius;         /* the loops compute a^2 of the intersection circle */
    const dem_model_param *params;        /* per interaction */
    int nparams;
    /* optional: reject a parameter combination; returns a message and sets *key, or NULL */
    const char *(*check)(const double *values, const char **key);
    /* optional: derived constants of one material pair: into its values (c->model[slot], after
     * the parameters) or, for normal models, the dashpot c->damping; m: the case's settings */
    void (*prepare)(struct dem_pair_coeffs *c, const dem_contact_models *m);
    /* normal models: limitForce when the case does not say (1: on) */
    int limit_force_default;
    /* optional: read the case-wide settings from contactModels into values */
    void (*read_case)(const struct dem_dict *contact_models_dict, double *values);
    /* normal models: duration of an elastic impact at relative speed v [s], and its name */
    double (*contact_time)(const struct dem_pair_coeffs *c, const dem_contact_models *m, double r_eff,
                           double m_eff, double v);
    const char *contact_time_name;
    /* optional: the largest separation (negative overlap) at which a contact with effective
     * radius r_eff still acts [m] (a JKR neck); 0 when NULL */
    double (*reach)(const struct dem_pair_coeffs *c, double r_eff);
    /* NULL: the model holds for coarse-grained parcels as it is (its forces scale as cg^2 at
     * the same relative overlap, with the contact stresses; docs/models/coarse_graining.md);
     * else why it does not, the message with which a case with coarseGraining > 1 is refused */
    const char *coarse_graining_refused;
} dem_contact_model;

/* What the normal model hands to the other slots. */
typedef struct dem_normal_result {
    double fn;        /* normal force magnitude, + repulsive [N] */
    double kn;        /* normal stiffness [N/m] (the rolling models use it) */
    double fn_spring; /* elastic part of fn [N] */
    double kt;        /* tangential stiffness [N/m] */
    double gammat;    /* tangential damping [N s/m] */
    int active;       /* 0: no contact (a model with a reach, outside its contact) */
} dem_normal_result;

/* One contact as the pair and wall loops see it; a wall is a partner of infinite radius and
 * mass at rest (R* = R_i, m* = m_i, lever_j = 0, w_j = 0). */
typedef struct dem_contact {
    double en[3];           /* unit normal, from j (or the wall) to i */
    double delta;           /* overlap [m]; negative: a gap (models with a reach) */
    double r_eff, m_eff;    /* R*, m* */
    double lever_i, lever_j;/* centre to the contact point, R - delta/2 [m] */
    double rolling_lever;   /* cdt's lever: R* for a pair, R_i - delta/2 at a wall (as LIGGGHTS) */
    double rolling_inertia; /* 1.4 m R^2, reduced for a pair (epsd) [kg m^2] */
    double a2;              /* squared radius of the intersection circle, if a model needs it [m^2] */
    double vr[3];           /* v_i - v_j [m/s] */
    double vn;              /* vr along the normal the forces use (set by evaluate.h) [m/s] */
    double wi[3], wj[3];    /* angular velocities [rad/s] */
    uint64_t key_lo, key_hi;/* the contact's key: lower and higher id, or ~wall and id */
    double sign;            /* +1 if en points from key_hi to key_lo's particle (i is key_lo) */
    double dt;              /* [s] */
    long step;
} dem_contact;

/* Relative tangential velocity of the contact points: v_r - v_n n_f - w_r x n, with
 * w_r = c_i omega_i + c_j omega_j (levers c to the centre of the overlap), n the geometric
 * normal and n_f the one the forces use (they differ under the roughness model). */
static inline void contact_tangential_velocity(const double vr[3], double vn, const double n_f[3],
                                               const double wr[3], const double n[3], double vt[3])
{
    vt[0] = vr[0] - vn * n_f[0] - (wr[1] * n[2] - wr[2] * n[1]);
    vt[1] = vr[1] - vn * n_f[1] - (wr[2] * n[0] - wr[0] * n[2]);
    vt[2] = vr[2] - vn * n_f[2] - (wr[0] * n[1] - wr[1] * n[0]);
}

/* Squared radius of the circle where two spheres intersect at centre distance d
 * (docs/models/README.md eq. 10; normal_edinburgh.md eq. 5a, written beside seed 002's eq. 5); a
 * wall is the limit R_j -> infinity, a^2 = 2 R_i delta - delta^2. */
static inline double contact_radius_sq_pair(double ri, double rj, double d)
{
    const double q = d * d - rj * rj + ri * ri;
    const double a2 = (4.0 * d * d * ri * ri - q * q) / (4.0 * d * d);
    return a2 > 0.0 ? a2 : 0.0;
}
static inline double contact_radius_sq_wall(double ri, double delta)
{
    const double a2 = 2.0 * ri * delta - delta * delta;
    return a2 > 0.0 ? a2 : 0.0;
}

/* The rolling models' inertia 1.4 m R^2 = 3.5 I, reduced for a pair, from the two inverse
 * inertias: an inverse of 0 is an infinite inertia (a wall, a prescribed particle), which leaves
 * the other's. Two of them (two prescribed particles, neither of which turns): 0, no damping
 * (where 1 / (0 + 0) would put an infinity, and 0 x infinity a NaN, into the torques). */
static inline double rolling_inertia_pair(double inv_i, double inv_j)
{
    if (inv_i == 0.0) return inv_j == 0.0 ? 0.0 : 3.5 / inv_j;
    if (inv_j == 0.0) return 3.5 / inv_i;
    const double ii = 1.0 / inv_i, ij = 1.0 / inv_j;
    return 3.5 * ii * ij / (ii + ij);
}

#endif
