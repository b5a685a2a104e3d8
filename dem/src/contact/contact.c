#include "contact.h"

const char *const normal_model_names[] = {"hooke", "hertz", 0};
const char *const tangential_model_names[] = {"none", "history", 0};
const char *const cohesion_model_names[] = {"none", 0};
const char *const rolling_model_names[] = {"none", 0};
const char *const surface_model_names[] = {"default", 0};

int contact_history_size(const contact_models *m)
{
    return m->tangential == TANGENTIAL_HISTORY ? 3 : 0;
}
