/* The tables of models.h: descriptors and names per slot, history layout. */
#include "models.h"

#define ENTRY(S, N) &S##_##N##_model,
static const dem_contact_model *const normal_table[] = {NORMAL_MODELS(ENTRY)};
static const dem_contact_model *const tangential_table[] = {TANGENTIAL_MODELS(ENTRY)};
static const dem_contact_model *const cohesion_table[] = {COHESION_MODELS(ENTRY)};
static const dem_contact_model *const rolling_table[] = {ROLLING_MODELS(ENTRY)};
static const dem_contact_model *const surface_table[] = {SURFACE_MODELS(ENTRY)};
#undef ENTRY

#define NAME(S, N) S##_##N##_model.name,
static const char *normal_names[] = {NORMAL_MODELS(NAME) 0};
static const char *tangential_names[] = {TANGENTIAL_MODELS(NAME) 0};
static const char *cohesion_names[] = {COHESION_MODELS(NAME) 0};
static const char *rolling_names[] = {ROLLING_MODELS(NAME) 0};
static const char *surface_names[] = {SURFACE_MODELS(NAME) 0};
#undef NAME

static const dem_contact_model *const *const tables[SLOT_COUNT] = {normal_table, tangential_table, cohesion_table,
                                                                rolling_table, surface_table};
static const int counts[SLOT_COUNT] = {NORMAL_COUNT, TANGENTIAL_COUNT, COHESION_COUNT, ROLLING_COUNT, SURFACE_COUNT};
static const char *const *const names[SLOT_COUNT] = {normal_names, tangential_names, cohesion_names,
                                                      rolling_names, surface_names};

const dem_contact_model *dem_contact_model_get(enum dem_contact_slot slot, int id)
{
    return slot >= 0 && slot < SLOT_COUNT && id >= 0 && id < counts[slot] ? tables[slot][id] : 0;
}

const char *const *dem_contact_model_names(enum dem_contact_slot slot) { return names[slot]; }

const char *const dem_contact_slot_names[SLOT_COUNT] = {"normal", "tangential", "cohesion", "rolling", "surface"};

/* the order of the slots in a contact's history */
static const enum dem_contact_slot history_order[SLOT_COUNT] = {SLOT_TANGENTIAL, SLOT_ROLLING, SLOT_NORMAL,
                                                           SLOT_SURFACE, SLOT_COHESION};

int dem_contact_history_size(const dem_contact_models *m)
{
    int size = 0;
    for (int k = 0; k < SLOT_COUNT; k++)
        size += dem_contact_model_get(history_order[k], contact_model_id(m, history_order[k]))->history;
    return size;
}

int dem_contact_history_antisymmetric(const dem_contact_models *m)
{
    int size = 0;   /* the leading slots whose whole history is antisymmetric */
    for (int k = 0; k < SLOT_COUNT; k++) {
        const dem_contact_model *d = dem_contact_model_get(history_order[k], contact_model_id(m, history_order[k]));
        if (d->history_antisymmetric != d->history) break;
        size += d->history;
    }
    return size;
}

void dem_contact_history_copy(double *dst, const double *src, int size, int antisymmetric, int flipped)
{
    for (int k = 0; k < size; k++) dst[k] = flipped && k < antisymmetric ? -src[k] : src[k];
}
