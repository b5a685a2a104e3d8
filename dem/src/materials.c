#include <math.h>
#include <string.h>

#include "materials.h"

int dem_materials_find(const dem_material_table *t, const char *name)
{
    for (int i = 0; i < t->ntypes; i++)
        if (strcmp(t->mat[i].name, name) == 0) return i;
    return -1;
}

void dem_materials_set_model_values(dem_material_table *t, int ti, int tj, enum dem_contact_slot slot,
                                const void *values, size_t bytes)
{
    double v[MODEL_VALUES] = {0};
    memcpy(v, values, bytes < sizeof v ? bytes : sizeof v);
    memcpy(t->pair[ti * DEM_MAX_TYPES + tj].model[slot], v, sizeof v);
    memcpy(t->pair[tj * DEM_MAX_TYPES + ti].model[slot], v, sizeof v);
}

void dem_materials_set_pair(dem_material_table *t, int ti, int tj, double restitution, double friction)
{
    const dem_material *a = &t->mat[ti], *b = &t->mat[tj];
    dem_pair_coeffs c = {0};
    c.Y_eff = 1.0 / ((1.0 - a->poisson_ratio * a->poisson_ratio) / a->youngs_modulus +
                     (1.0 - b->poisson_ratio * b->poisson_ratio) / b->youngs_modulus);
    c.G_eff = 1.0 / (2.0 * (2.0 - a->poisson_ratio) * (1.0 + a->poisson_ratio) / a->youngs_modulus +
                     2.0 * (2.0 - b->poisson_ratio) * (1.0 + b->poisson_ratio) / b->youngs_modulus);
    c.restitution = restitution;
    c.log_e = log(restitution);
    c.beta = c.log_e / sqrt(c.log_e * c.log_e + M_PI * M_PI);
    c.friction = friction;
    c.sqrt_st_over_sn = sqrt(4.0 * c.G_eff / c.Y_eff);
    c.damping = -2.0 * 0.91287092917527685576 * c.beta;   /* 2 sqrt(5/6) |beta| (normal_hertz.md) */
    t->pair[ti * DEM_MAX_TYPES + tj] = c;
    t->pair[tj * DEM_MAX_TYPES + ti] = c;
}
