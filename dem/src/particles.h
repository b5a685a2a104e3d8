/* Particle storage: a structure of arrays, one array per quantity. Vector quantities are
 * stored as double[3] per particle, so that a neighbour's position is one cache line. */
#ifndef DEM_PARTICLES_H
#define DEM_PARTICLES_H

#include <stdint.h>

typedef double vec3[3];

typedef struct particles {
    int n;                 /* particles in use */
    int capacity;
    vec3 *x;               /* position [m] */
    vec3 *v;               /* velocity [m/s] */
    vec3 *omega;           /* angular velocity [rad/s] */
    vec3 *f;               /* total force of this step [N] */
    vec3 *torque;          /* total torque of this step [N m] */
    vec3 *f_ext;           /* external force held between exchanges (e.g. fluid drag) [N] */
    double *radius;        /* [m] */
    double *mass;          /* [kg] */
    double *inv_mass;      /* [1/kg] */
    double *inv_inertia;   /* 1 / (2/5 m r^2) [1/(kg m^2)] */
    int *type;             /* material index */
    int64_t *id;           /* global id, stable across sorting and restarts */
} particles;

void particles_init(particles *p);
void particles_free(particles *p);
void particles_reserve(particles *p, int capacity);
/* Append one particle at rest; returns its index. density in kg/m^3. */
int particles_add(particles *p, const double x[3], const double v[3], double radius,
                  double density, int type, int64_t id);
/* Recompute mass, inverse mass and inverse inertia from radius and a per-type density. */
void particles_set_mass(particles *p, int i, double density);
/* Copy every quantity of particle src to index dst (within the capacity). */
void particles_copy(particles *p, int src, int dst);
/* Reorder all arrays so that new index k holds old index order[k]. */
void particles_permute(particles *p, const int *order);

#endif
