/* Periodic images as ghost particles.
 *
 * At each neighbour-list build, every particle within the list's cutoff of a periodic side gets
 * a copy shifted by the period (corner and edge images too: the copies made for one direction
 * are copied again for the next). The copies are stored after the real particles, at indices
 * p->n .. p->n + ghosts.n - 1; the neighbour list pairs real particles with them like any other
 * particle, so the force kernels know nothing of periodicity. Before each force computation the
 * copies take their owners' positions (plus the shift) and velocities; after the pair forces
 * their forces and torques are added onto their owners. The MPI halo will be the same mechanism
 * with the copies coming from another rank. Only the first n particles are real: integration,
 * walls, output and the coupling never see a ghost. */
#ifndef DEM_GHOSTS_H
#define DEM_GHOSTS_H

#include "particles.h"

typedef struct dem_ghost_list {
    int n, capacity;
    int *owner;        /* the real particle each ghost copies */
    dem_vec3 *shift;       /* ghost position - owner position [m] */
} dem_ghost_list;

struct dem_system;
void dem_ghosts_free(dem_ghost_list *g);
/* Make the images of the particles within cutoff [m] of a periodic side (after the real
 * particles were wrapped into the box). */
void dem_ghosts_build(struct dem_system *s, double cutoff);
/* The ghosts' positions, velocities and angular velocities from their owners; forces zeroed. */
void dem_ghosts_update(struct dem_system *s);
/* Add the ghosts' forces and torques onto their owners. */
void dem_ghosts_fold_forces(struct dem_system *s);

#endif
