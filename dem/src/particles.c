#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "particles.h"

#define PF_DESCRIPTOR(member, element, unit, dataset, flags)                                     \
    {#member, dataset, unit, offsetof(dem_particles, member), sizeof(PF_CTYPE_##element),            \
     PF_COMPONENTS_##element, PF_SCALAR_##element, flags},
const dem_particle_field dem_particle_fields[PARTICLE_FIELD_COUNT] = {PARTICLE_FIELDS(PF_DESCRIPTOR)};
#undef PF_DESCRIPTOR

void dem_particles_init(dem_particles *p)
{
    memset(p, 0, sizeof *p);
}

void dem_particles_free(dem_particles *p)
{
#define PF_FREE(member, element, unit, dataset, flags) free(p->member);
    PARTICLE_FIELDS(PF_FREE)
#undef PF_FREE
    dem_particles_init(p);
}

void dem_particles_reserve(dem_particles *p, int capacity)
{
    if (capacity <= p->capacity) return;
#define PF_GROW(member, element, unit, dataset, flags)                                           \
    p->member = dem_realloc(p->member, (size_t)capacity * sizeof *p->member);
    PARTICLE_FIELDS(PF_GROW)
#undef PF_GROW
    p->capacity = capacity;
}

void dem_particles_set_mass(dem_particles *p, int i, double density)
{
    const double r = p->radius[i];
    const double m = density * 4.0 / 3.0 * M_PI * r * r * r;
    p->mass[i] = m;
    p->inv_mass[i] = 1.0 / m;
    p->inv_inertia[i] = 1.0 / (0.4 * m * r * r);
    if (p->prescribed[i]) p->inv_mass[i] = p->inv_inertia[i] = 0.0;   /* the kicks leave it alone */
}

void dem_particles_prescribe(dem_particles *p, int i)
{
    p->prescribed[i] = 1;
    p->inv_mass[i] = p->inv_inertia[i] = 0.0;
    p->omega[i][0] = p->omega[i][1] = p->omega[i][2] = 0.0;
}

/* A new particle at index n (grown if needed), all fields 0. */
static int append_zeroed(dem_particles *p)
{
    if (p->n == p->capacity) dem_particles_reserve(p, p->capacity ? 2 * p->capacity : 1024);
    const int i = p->n++;
    p->generation++;
#define PF_ZERO(member, element, unit, dataset, flags) memset(&p->member[i], 0, sizeof *p->member);
    PARTICLE_FIELDS(PF_ZERO)
#undef PF_ZERO
    return i;
}

int dem_particles_add(dem_particles *p, const double x[3], const double v[3], double radius,
                  double density, int type, int64_t id)
{
    const int i = append_zeroed(p);
    for (int d = 0; d < 3; d++) {
        p->x[i][d] = x[d];
        p->v[i][d] = v[d];
    }
    p->radius[i] = radius;
    p->type[i] = type;
    p->id[i] = id;
    dem_particles_set_mass(p, i, density);
    return i;
}

void dem_particles_remove(dem_particles *p, int i)
{
    if (i < 0 || i >= p->n) dem_fatal("dem_particles_remove: index %d outside the %d particles", i, p->n);
    dem_particles_copy(p, p->n - 1, i);
    p->n--;
    p->generation++;
}

/* Each field gathered through `order` into scratch and copied back; the element size is a
 * constant in each expansion, so the copies compile to moves. */
void dem_particles_permute(dem_particles *p, const int *order)
{
    const int n = p->n;
    size_t largest = 1;
    for (int k = 0; k < PARTICLE_FIELD_COUNT; k++)
        if (dem_particle_fields[k].element_size > largest) largest = dem_particle_fields[k].element_size;
    char *scratch = dem_malloc((size_t)(n ? n : 1) * largest);
#define PF_PERMUTE(member, element, unit, dataset, flags)                                        \
    {                                                                                            \
        const size_t elem = sizeof *p->member;                                                   \
        for (int k = 0; k < n; k++) memcpy(scratch + k * elem, &p->member[order[k]], elem);      \
        memcpy(p->member, scratch, (size_t)n * elem);                                            \
    }
    PARTICLE_FIELDS(PF_PERMUTE)
#undef PF_PERMUTE
    free(scratch);
    p->generation++;
}

void dem_particles_copy(dem_particles *p, int from, int to)
{
    if (from == to) return;
#define PF_COPY(member, element, unit, dataset, flags)                                           \
    memcpy(&p->member[to], &p->member[from], sizeof *p->member);
    PARTICLE_FIELDS(PF_COPY)
#undef PF_COPY
}

size_t dem_particles_role_size(unsigned roles)
{
    size_t bytes = 0;
    for (int k = 0; k < PARTICLE_FIELD_COUNT; k++)
        if (dem_particle_fields[k].flags & roles) bytes += dem_particle_fields[k].element_size;
    return bytes;
}

size_t dem_particles_gather_roles(const dem_particles *p, unsigned roles, const int *idx, int count,
                                  const dem_vec3 *shift, void *buf)
{
    char *out = buf;
    for (int k = 0; k < PARTICLE_FIELD_COUNT; k++) {
        const dem_particle_field *f = &dem_particle_fields[k];
        if (!(f->flags & roles)) continue;
        const size_t e = f->element_size;
        if (k == PF_FIELD_x) {   /* the position, shifted: as doubles */
            double (*to)[3] = (double (*)[3])(void *)out;
            for (int m = 0; m < count; m++) {
                const double *x = p->x[idx[m]];
                for (int q = 0; q < 3; q++) to[m][q] = shift ? x[q] + shift[m][q] : x[q];
            }
        } else {
            const char *from = particle_field_data(p, f);
            for (int m = 0; m < count; m++) memcpy(out + (size_t)m * e, from + (size_t)idx[m] * e, e);
        }
        out += (size_t)count * e;
    }
    return (size_t)(out - (char *)buf);
}

void dem_particles_put_roles(dem_particles *p, unsigned roles, int first, int count, const void *buf)
{
    const char *in = buf;
    for (int k = 0; k < PARTICLE_FIELD_COUNT; k++) {
        const dem_particle_field *f = &dem_particle_fields[k];
        if (!(f->flags & roles)) continue;
        const size_t bytes = (size_t)count * f->element_size;
        if (bytes) memcpy((char *)particle_field_data(p, f) + (size_t)first * f->element_size, in, bytes);
        in += bytes;
    }
}

void dem_particles_copy_roles(dem_particles *p, unsigned roles, const int *idx, int count, const dem_vec3 *shift,
                              int first)
{
    for (int k = 0; k < PARTICLE_FIELD_COUNT; k++) {
        const dem_particle_field *f = &dem_particle_fields[k];
        if (!(f->flags & roles)) continue;
        if (k == PF_FIELD_x) {
            for (int m = 0; m < count; m++) {
                const double *x = p->x[idx[m]];
                double *to = p->x[first + m];
                for (int q = 0; q < 3; q++) to[q] = shift ? x[q] + shift[m][q] : x[q];
            }
        } else {
            char *data = particle_field_data(p, f);
            const size_t e = f->element_size;
            for (int m = 0; m < count; m++) memcpy(data + (size_t)(first + m) * e, data + (size_t)idx[m] * e, e);
        }
    }
}

void dem_particles_take_roles(const dem_particles *p, unsigned roles, int first, int count, void *buf)
{
    char *out = buf;
    for (int k = 0; k < PARTICLE_FIELD_COUNT; k++) {
        const dem_particle_field *f = &dem_particle_fields[k];
        if (!(f->flags & roles)) continue;
        const size_t bytes = (size_t)count * f->element_size;
        if (bytes) memcpy(out, (const char *)particle_field_data(p, f) + (size_t)first * f->element_size, bytes);
        out += bytes;
    }
}

void dem_particles_scatter_add_roles(dem_particles *p, unsigned roles, const int *idx, int count, const void *buf)
{
    const double *in = buf;
    for (int k = 0; k < PARTICLE_FIELD_COUNT; k++) {
        const dem_particle_field *f = &dem_particle_fields[k];
        if (!(f->flags & roles)) continue;
        if (f->scalar != PF_DOUBLE) dem_fatal("particles: field '%s' is not a double and cannot be summed", f->member);
        double *to = particle_field_data(p, f);
        const int c = f->components;
        for (int m = 0; m < count; m++)
            for (int q = 0; q < c; q++) to[(size_t)idx[m] * c + q] += in[(size_t)m * c + q];
        in += (size_t)count * c;
    }
}

void dem_particles_fold_roles(dem_particles *p, unsigned roles, int first, int count, const int *idx)
{
    for (int k = 0; k < PARTICLE_FIELD_COUNT; k++) {
        const dem_particle_field *f = &dem_particle_fields[k];
        if (!(f->flags & roles)) continue;
        if (f->scalar != PF_DOUBLE) dem_fatal("particles: field '%s' is not a double and cannot be summed", f->member);
        double *d = particle_field_data(p, f);
        const int c = f->components;
        for (int m = 0; m < count; m++)
            for (int q = 0; q < c; q++) d[(size_t)idx[m] * c + q] += d[(size_t)(first + m) * c + q];
    }
}

void dem_particles_zero_roles(dem_particles *p, unsigned roles, int first, int count)
{
    if (count <= 0) return;
    for (int k = 0; k < PARTICLE_FIELD_COUNT; k++) {
        const dem_particle_field *f = &dem_particle_fields[k];
        if (f->flags & roles)
            memset((char *)particle_field_data(p, f) + (size_t)first * f->element_size, 0, (size_t)count * f->element_size);
    }
}

size_t dem_particles_pack_size(void)
{
    return dem_particles_role_size(PF_MIGRATE);
}

size_t dem_particles_pack(const dem_particles *p, int i, void *buf)
{
    return dem_particles_gather_roles(p, PF_MIGRATE, &i, 1, NULL, buf);
}

int dem_particles_unpack(dem_particles *p, const void *buf)
{
    const int i = append_zeroed(p);
    dem_particles_put_roles(p, PF_MIGRATE, i, 1, buf);
    return i;
}
