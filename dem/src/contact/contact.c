#include "contact.h"

const char *const normal_model_names[] = {"hooke", "hertz", "edinburgh", 0};
const char *const tangential_model_names[] = {"none", "history", 0};
const char *const cohesion_model_names[] = {"none", "sjkr", 0};
const char *const rolling_model_names[] = {"none", "cdt", "cdtJkr", "epsd", 0};
const char *const surface_model_names[] = {"default", "roughness", 0};

int contact_history_size(const contact_models *m)
{
    return tangential_history_size(m->tangential) + rolling_history_size(m->rolling) +
           normal_history_size(m->normal) + surface_history_size(m->surface);
}

int contact_history_antisymmetric(const contact_models *m)
{
    return tangential_history_size(m->tangential) + rolling_history_size(m->rolling);
}

void contact_history_copy(double *dst, const double *src, int size, int antisymmetric, int flipped)
{
    for (int k = 0; k < size; k++) dst[k] = flipped && k < antisymmetric ? -src[k] : src[k];
}
