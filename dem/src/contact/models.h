/* Every contact model, once. The enums of model ids, the names accepted in contactModels, the
 * reading of the parameters, the history sizes and the time-step check all come from these
 * lists; the dispatch in evaluate.h too. The model headers are included by
 * contact_model_headers.h, which CMake writes from the files in this folder (normal_*.h,
 * tangential_*.h, cohesion_*.h, rolling_*.h, surface_*.h).
 *
 * Adding a model: its header (model.h says what it holds), and one line here. The line
 * X(slot, name) refers to slot_name_model (its descriptor) and to its force function,
 * slot_name_force (_torque for rolling; _normal and _wall_guard for surface). Within a slot the
 * order of the lines is the order of the ids; the first line is the slot's default. */
#ifndef DEM_CONTACT_MODELS_H
#define DEM_CONTACT_MODELS_H

#include "contact_model_headers.h"

#define NORMAL_MODELS(X) \
    X(normal, hertz) \
    X(normal, hooke) \
    X(normal, edinburgh) \
    X(normal, jkr) \
    X(normal, dmt)

#define TANGENTIAL_MODELS(X) \
    X(tangential, history) \
    X(tangential, none)

#define COHESION_MODELS(X) \
    X(cohesion, none) \
    X(cohesion, sjkr)

#define ROLLING_MODELS(X) \
    X(rolling, none) \
    X(rolling, cdt) \
    X(rolling, cdt_jkr) \
    X(rolling, epsd)

#define SURFACE_MODELS(X) \
    X(surface, default) \
    X(surface, roughness)

#define CONTACT_MODEL_ID(S, N) S##_##N,
enum dem_normal_model { NORMAL_MODELS(CONTACT_MODEL_ID) NORMAL_COUNT };
enum dem_tangential_model { TANGENTIAL_MODELS(CONTACT_MODEL_ID) TANGENTIAL_COUNT };
enum dem_cohesion_model { COHESION_MODELS(CONTACT_MODEL_ID) COHESION_COUNT };
enum dem_rolling_model { ROLLING_MODELS(CONTACT_MODEL_ID) ROLLING_COUNT };
enum dem_surface_model { SURFACE_MODELS(CONTACT_MODEL_ID) SURFACE_COUNT };
#undef CONTACT_MODEL_ID

/* The descriptor of model id in a slot (NULL if there is none). */
const dem_contact_model *dem_contact_model_get(enum dem_contact_slot slot, int id);
/* The names of a slot's models, NULL-terminated (for the dictionary's choice). */
const char *const *dem_contact_model_names(enum dem_contact_slot slot);
/* The slots' names, as contactModels spells its keys. */
extern const char *const dem_contact_slot_names[SLOT_COUNT];
/* The id of the chosen model in each slot, as an array indexed by enum contact_slot. */
static inline int contact_model_id(const dem_contact_models *m, enum dem_contact_slot slot)
{
    const int ids[SLOT_COUNT] = {m->normal, m->tangential, m->cohesion, m->rolling, m->surface};
    return ids[slot];
}
/* Where a slot's model id is kept in m (to set it). */
static inline int *contact_model_id_ref(dem_contact_models *m, enum dem_contact_slot slot)
{
    int *const ids[SLOT_COUNT] = {&m->normal, &m->tangential, &m->cohesion, &m->rolling, &m->surface};
    return ids[slot];
}

/* Doubles of history per contact for the chosen models, laid out as
 * [tangential][rolling][normal][surface][cohesion]; the tangential and rolling parts change
 * sign when i and j swap (they are built from v_i - v_j and omega_i - omega_j), the others do
 * not (each model states its antisymmetric part; it must be all or nothing of its history). */
int dem_contact_history_size(const dem_contact_models *m);
/* The leading part that is antisymmetric in (i, j). */
int dem_contact_history_antisymmetric(const dem_contact_models *m);
/* Copy one contact's history; flipped: the pair is now stored as (j, i). */
void dem_contact_history_copy(double *dst, const double *src, int size, int antisymmetric, int flipped);

#endif
