/* One contact's forces, for pairs and walls alike: the five slots in order (surface normal,
 * normal force, cohesion, tangential force, rolling torque), dispatched on the model ids.
 * Called with constant ids (a specialised kernel) every switch folds to one model's code;
 * called with the case's ids at run time (the generic kernel) it is a jump per slot. */
#ifndef DEM_CONTACT_EVALUATE_H
#define DEM_CONTACT_EVALUATE_H

#include "models.h"

#define ALWAYS_INLINE inline __attribute__((always_inline))

static ALWAYS_INLINE void surface_normal(int id, const dem_contact *k, const dem_contact_models *m, double *h, double en_f[3])
{
    switch (id) {
#define CASE(S, N) case S##_##N: S##_##N##_normal(k, m, h, en_f); return;
    SURFACE_MODELS(CASE)
#undef CASE
    }
    __builtin_unreachable();   /* ids come from models.h */
}

static ALWAYS_INLINE void surface_wall_guard(int id, const dem_contact_models *m, const double en[3], const double f[3],
                                             double v[3])
{
    switch (id) {
#define CASE(S, N) case S##_##N: S##_##N##_wall_guard(m, en, f, v); return;
    SURFACE_MODELS(CASE)
#undef CASE
    }
    __builtin_unreachable();   /* ids come from models.h */
}

static ALWAYS_INLINE dem_normal_result normal_force(int id, const dem_contact *k, const dem_pair_coeffs *c, const dem_contact_models *m,
                                                double *h)
{
    switch (id) {
#define CASE(S, N) case S##_##N: return S##_##N##_force(k, c, m, h);
    NORMAL_MODELS(CASE)
#undef CASE
    }
    __builtin_unreachable();   /* ids come from models.h */
}

static ALWAYS_INLINE double cohesion_force(int id, const dem_contact *k, const dem_pair_coeffs *c)
{
    switch (id) {
#define CASE(S, N) case S##_##N: return S##_##N##_force(k, c);
    COHESION_MODELS(CASE)
#undef CASE
    }
    __builtin_unreachable();   /* ids come from models.h */
}

static ALWAYS_INLINE void tangential_force(int id, const dem_contact *k, const dem_pair_coeffs *c, dem_normal_result n,
                                           const double en_f[3], const double vt[3], double *h, double ft[3])
{
    switch (id) {
#define CASE(S, N) case S##_##N: S##_##N##_force(k, c, n, en_f, vt, h, ft); return;
    TANGENTIAL_MODELS(CASE)
#undef CASE
    }
    __builtin_unreachable();   /* ids come from models.h */
}

static ALWAYS_INLINE void rolling_torque(int id, const dem_contact *k, const dem_pair_coeffs *c, const dem_contact_models *m,
                                         dem_normal_result n, const double w[3], double *h, double mr[3])
{
    switch (id) {
#define CASE(S, N) case S##_##N: S##_##N##_torque(k, c, m, n, w, h, mr); return;
    ROLLING_MODELS(CASE)
#undef CASE
    }
    __builtin_unreachable();   /* ids come from models.h */
}

/* Whether a slot's model keeps history, needs the contact radius, acts beyond touching. */
#define SLOT_QUERY(fname, SLOT_MODELS, expr)                                      \
    static ALWAYS_INLINE int fname(int id)                                        \
    {                                                                             \
        switch (id) { SLOT_MODELS(expr) }                                         \
        return 0;                                                                 \
    }
#define HISTORY(S, N) case S##_##N: return S##_##N##_model.history;
SLOT_QUERY(normal_history_size, NORMAL_MODELS, HISTORY)
SLOT_QUERY(tangential_history_size, TANGENTIAL_MODELS, HISTORY)
SLOT_QUERY(rolling_history_size, ROLLING_MODELS, HISTORY)
SLOT_QUERY(surface_history_size, SURFACE_MODELS, HISTORY)
SLOT_QUERY(cohesion_history_size, COHESION_MODELS, HISTORY)
#undef HISTORY
#define RADIUS(S, N) case S##_##N: return S##_##N##_model.needs_contact_radius;
SLOT_QUERY(normal_needs_radius, NORMAL_MODELS, RADIUS)
SLOT_QUERY(cohesion_needs_radius, COHESION_MODELS, RADIUS)
SLOT_QUERY(surface_needs_radius, SURFACE_MODELS, RADIUS)
#undef RADIUS
#define REACH(S, N) case S##_##N: return S##_##N##_model.reach != 0;
SLOT_QUERY(normal_has_reach, NORMAL_MODELS, REACH)
#undef REACH
#undef SLOT_QUERY

static ALWAYS_INLINE int contact_needs_radius(int normal, int cohesion, int surface)
{
    return normal_needs_radius(normal) || cohesion_needs_radius(cohesion) || surface_needs_radius(surface);
}

/* The forces of one contact, added to the sums of i and j: the force on i to fi, its opposite
 * to fj, the torques on i and j to ti and tj;
 * h: the contact's history, [tangential][rolling][normal][surface][cohesion]. k->vn is set here (along
 * the normal the forces use). Returns 0, with the history cleared, if the normal model finds no
 * contact (a model with a reach, outside its neck). */
static ALWAYS_INLINE int contact_evaluate(int normal, int tangential, int cohesion, int rolling, int surface,
                                          const dem_contact_models *m, const dem_pair_coeffs *c, dem_contact *k,
                                          double *restrict h, double fi[3], double fj[3], double ti[3], double tj[3])
{
    const int h_roll = tangential_history_size(tangential), h_norm = h_roll + rolling_history_size(rolling);
    /* the cohesion slot's history last (models.c's order); no cohesion model keeps any yet, but the
     * stride counts it, so that one that does gets its own doubles and is cleared with the rest */
    const int h_surf = h_norm + normal_history_size(normal);
    const int hs = h_surf + surface_history_size(surface) + cohesion_history_size(cohesion);
    const double *en = k->en;
    double en_f[3] = {en[0], en[1], en[2]};   /* the normal the forces use */
    if (surface != surface_default) surface_normal(surface, k, m, h + h_surf, en_f);
    k->vn = k->vr[0] * en_f[0] + k->vr[1] * en_f[1] + k->vr[2] * en_f[2];

    dem_normal_result n = normal_force(normal, k, c, m, h + h_norm);
    if (normal_has_reach(normal) && !n.active) {
        for (int q = 0; q < hs; q++) h[q] = 0.0;
        return 0;
    }
    /* limitForce: the dashpot may not pull below what the elastic and adhesive branches give */
    const double fn_min = n.fn_spring < m->fn_floor ? n.fn_spring : m->fn_floor;
    if (!(n.fn > fn_min)) n.fn = fn_min;
    const double fn = cohesion != cohesion_none ? n.fn + cohesion_force(cohesion, k, c) : n.fn;
    double f[3] = {fn * en_f[0], fn * en_f[1], fn * en_f[2]};
    if (tangential != tangential_none) {
        /* contact-point velocity: lever arms to the centre of the overlap */
        const double cri = k->lever_i, crj = k->lever_j;
        const double wr[3] = {cri * k->wi[0] + crj * k->wj[0], cri * k->wi[1] + crj * k->wj[1],
                              cri * k->wi[2] + crj * k->wj[2]};
        double vt[3], ft[3];
        contact_tangential_velocity(k->vr, k->vn, en_f, wr, en, vt);
        tangential_force(tangential, k, c, n, en_f, vt, h, ft);
        f[0] += ft[0]; f[1] += ft[1]; f[2] += ft[2];
        /* torque = lever x force, lever -cr en for i and +cr en for j (force -ft) */
        const double ent[3] = {en[1] * ft[2] - en[2] * ft[1], en[2] * ft[0] - en[0] * ft[2],
                               en[0] * ft[1] - en[1] * ft[0]};
        for (int q = 0; q < 3; q++) {
            ti[q] -= cri * ent[q];
            tj[q] -= crj * ent[q];
        }
    }
    if (rolling != rolling_none) {
        const double wij[3] = {k->wi[0] - k->wj[0], k->wi[1] - k->wj[1], k->wi[2] - k->wj[2]};
        double mr[3];
        rolling_torque(rolling, k, c, m, n, wij, h + h_roll, mr);
        for (int q = 0; q < 3; q++) {
            ti[q] += mr[q];
            tj[q] -= mr[q];
        }
    }
    for (int q = 0; q < 3; q++) {
        fi[q] += f[q];
        fj[q] -= f[q];
    }
    return 1;
}

/* The combinations with their own kernel (pair and wall): (normal, tangential, cohesion,
 * rolling, surface). Every other combination runs the generic kernel; test_kernels checks
 * that the two agree for every combination listed here. */
#define SPECIALISED_KERNELS(X) \
    X(hertz, history, none, none, default) \
    X(hertz, none, none, none, default) \
    X(hooke, history, none, none, default) \
    X(hertz, history, sjkr, none, default) \
    X(hertz, history, none, cdt, default) \
    X(hertz, history, none, epsd, default)

/* The index of the case's combination in SPECIALISED_KERNELS, or -1. */
static inline int contact_specialised(const dem_contact_models *m)
{
#define IDS(N, T, C, R, S) {normal_##N, tangential_##T, cohesion_##C, rolling_##R, surface_##S},
    static const int ids[][SLOT_COUNT] = {SPECIALISED_KERNELS(IDS)};
#undef IDS
    for (int q = 0; q < (int)(sizeof ids / sizeof ids[0]); q++) {
        int same = 1;
        for (int slot = 0; slot < SLOT_COUNT; slot++) same &= ids[q][slot] == contact_model_id(m, slot);
        if (same) return q;
    }
    return -1;
}

#endif
