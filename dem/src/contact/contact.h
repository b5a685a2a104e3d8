/* Contact model slots and the per-contact data the models share.
 *
 * A model is a small static inline function in its own header; pair_forces.c and walls.c
 * build one loop per combination of models, chosen once outside the loop, so a model that a
 * case does not use costs nothing there. Adding a model: a header here, an enum value, a
 * name in contact.c, its history size below, and its call in pair_forces.c / walls.c. */
#ifndef DEM_CONTACT_H
#define DEM_CONTACT_H

#include <stdint.h>

enum normal_model { NORMAL_HOOKE, NORMAL_HERTZ, NORMAL_EDINBURGH, NORMAL_COUNT };
enum tangential_model { TANGENTIAL_NONE, TANGENTIAL_HISTORY, TANGENTIAL_COUNT };
enum cohesion_model { COHESION_NONE, COHESION_SJKR, COHESION_COUNT };
enum rolling_model { ROLLING_NONE, ROLLING_CDT, ROLLING_CDT_JKR, ROLLING_EPSD, ROLLING_COUNT };
enum surface_model { SURFACE_DEFAULT, SURFACE_ROUGHNESS, SURFACE_COUNT };

/* Distribution of the roughness scatter angle Delta Gamma (seed note 001). */
enum scatter_distribution { SCATTER_NORMAL, SCATTER_UNIFORM };
typedef struct roughness_params {
    enum scatter_distribution distribution;
    double std_dev;      /* normal: Delta Gamma ~ N(0, std_dev) [rad] ... */
    double max;          /* ... truncated to |Delta Gamma| <= max; uniform: U(0, max) [rad] */
    uint64_t seed;       /* key of the counter-based generator */
} roughness_params;

typedef struct contact_models {
    enum normal_model normal;
    enum tangential_model tangential;
    enum cohesion_model cohesion;
    enum rolling_model rolling;
    enum surface_model surface;
    double characteristic_velocity;   /* [m/s], hooke's stiffness */
    double fn_floor;                  /* 0 with limitForce (no pull from the dashpot), else -inf */
    int torsion_torque;               /* cdtJkr: keep the normal (torsion) part of the torque */
    roughness_params roughness;
} contact_models;

extern const char *const normal_model_names[];
extern const char *const tangential_model_names[];
extern const char *const cohesion_model_names[];
extern const char *const rolling_model_names[];
extern const char *const surface_model_names[];

/* Doubles of per-contact history each model keeps (pair list and wall contacts), laid out as
 * [tangential][rolling][normal][surface]; the offsets are compile-time constants in the force
 * loops. The tangential and rolling parts change sign when i and j swap (they are built from
 * v_i - v_j and omega_i - omega_j); the normal and surface parts do not. */
static inline int tangential_history_size(enum tangential_model t) { return t == TANGENTIAL_HISTORY ? 3 : 0; }
static inline int rolling_history_size(enum rolling_model r)
{
    return r == ROLLING_EPSD || r == ROLLING_CDT_JKR ? 3 : 0;
}
static inline int normal_history_size(enum normal_model n) { return n == NORMAL_EDINBURGH ? 1 : 0; }
static inline int surface_history_size(enum surface_model s) { return s == SURFACE_ROUGHNESS ? 6 : 0; }
int contact_history_size(const contact_models *m);
/* The leading part that is antisymmetric in (i, j). */
int contact_history_antisymmetric(const contact_models *m);
/* Copy one contact's history; flipped: the pair is now stored as (j, i). */
void contact_history_copy(double *dst, const double *src, int size, int antisymmetric, int flipped);

/* What the normal model hands to the tangential and rolling ones. */
typedef struct normal_result {
    double fn;       /* normal force magnitude, + repulsive [N] */
    double kn;       /* normal stiffness [N/m] (the rolling models use it) */
    double fn_spring;/* elastic part of fn [N] */
    double kt;       /* tangential stiffness [N/m] */
    double gammat;   /* tangential damping [N s/m] */
} normal_result;

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

/* Contact radius of two spheres at centre distance d (seed 002, beside eq. 5; edinburgh and sjkr use it); a wall is the
 * limit R_j -> infinity, a^2 = 2 R_i delta - delta^2. */
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

#endif
