#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "particles.h"

void particles_init(particles *p)
{
    memset(p, 0, sizeof *p);
}

void particles_free(particles *p)
{
    free(p->x); free(p->v); free(p->omega); free(p->f); free(p->torque); free(p->f_ext);
    free(p->radius); free(p->mass); free(p->inv_mass); free(p->inv_inertia);
    free(p->type); free(p->id);
    particles_init(p);
}

#define GROW(field, count) p->field = dem_realloc(p->field, (size_t)(count) * sizeof *p->field)

void particles_reserve(particles *p, int capacity)
{
    if (capacity <= p->capacity) return;
    GROW(x, capacity); GROW(v, capacity); GROW(omega, capacity); GROW(f, capacity);
    GROW(torque, capacity); GROW(f_ext, capacity);
    GROW(radius, capacity); GROW(mass, capacity); GROW(inv_mass, capacity);
    GROW(inv_inertia, capacity); GROW(type, capacity); GROW(id, capacity);
    p->capacity = capacity;
}

void particles_set_mass(particles *p, int i, double density)
{
    const double r = p->radius[i];
    const double m = density * 4.0 / 3.0 * M_PI * r * r * r;
    p->mass[i] = m;
    p->inv_mass[i] = 1.0 / m;
    p->inv_inertia[i] = 1.0 / (0.4 * m * r * r);
}

int particles_add(particles *p, const double x[3], const double v[3], double radius,
                  double density, int type, int64_t id)
{
    if (p->n == p->capacity) particles_reserve(p, p->capacity ? 2 * p->capacity : 1024);
    const int i = p->n++;
    for (int d = 0; d < 3; d++) {
        p->x[i][d] = x[d];
        p->v[i][d] = v[d];
        p->omega[i][d] = 0.0;
        p->f[i][d] = 0.0;
        p->torque[i][d] = 0.0;
        p->f_ext[i][d] = 0.0;
    }
    p->radius[i] = radius;
    p->type[i] = type;
    p->id[i] = id;
    particles_set_mass(p, i, density);
    return i;
}

/* Gather one array through `order` using a scratch buffer. */
static void permute_array(void *data, size_t elem, int n, const int *order, void *scratch)
{
    char *src = data, *dst = scratch;
    for (int k = 0; k < n; k++) memcpy(dst + (size_t)k * elem, src + (size_t)order[k] * elem, elem);
    memcpy(data, scratch, (size_t)n * elem);
}

void particles_copy(particles *p, int src, int dst)
{
    memcpy(p->x[dst], p->x[src], sizeof(vec3));
    memcpy(p->v[dst], p->v[src], sizeof(vec3));
    memcpy(p->omega[dst], p->omega[src], sizeof(vec3));
    memcpy(p->f[dst], p->f[src], sizeof(vec3));
    memcpy(p->torque[dst], p->torque[src], sizeof(vec3));
    memcpy(p->f_ext[dst], p->f_ext[src], sizeof(vec3));
    p->radius[dst] = p->radius[src];
    p->mass[dst] = p->mass[src];
    p->inv_mass[dst] = p->inv_mass[src];
    p->inv_inertia[dst] = p->inv_inertia[src];
    p->type[dst] = p->type[src];
    p->id[dst] = p->id[src];
}

void particles_permute(particles *p, const int *order)
{
    void *scratch = dem_malloc((size_t)p->n * sizeof(vec3));
    permute_array(p->x, sizeof(vec3), p->n, order, scratch);
    permute_array(p->v, sizeof(vec3), p->n, order, scratch);
    permute_array(p->omega, sizeof(vec3), p->n, order, scratch);
    permute_array(p->f, sizeof(vec3), p->n, order, scratch);
    permute_array(p->torque, sizeof(vec3), p->n, order, scratch);
    permute_array(p->f_ext, sizeof(vec3), p->n, order, scratch);
    permute_array(p->radius, sizeof(double), p->n, order, scratch);
    permute_array(p->mass, sizeof(double), p->n, order, scratch);
    permute_array(p->inv_mass, sizeof(double), p->n, order, scratch);
    permute_array(p->inv_inertia, sizeof(double), p->n, order, scratch);
    permute_array(p->type, sizeof(int), p->n, order, scratch);
    permute_array(p->id, sizeof(int64_t), p->n, order, scratch);
    free(scratch);
}
