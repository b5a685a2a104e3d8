/* Ghost particles: periodic images and another rank's particles near this rank's box, made by one
 * mechanism (the halo exchange of CoMD and LAMMPS, in one stage because the boxes are not a grid).
 *
 * The rank's box is its part of the decomposition (decompose.h; the whole domain on one rank).
 * At each neighbour-list build, each real particle is sent to every (rank, periodic image) whose
 * box lies within the list's cutoff of the particle's image: its position plus -1, 0 or +1
 * periods in each periodic direction (the image 0 to this rank itself being the particle). With
 * multisphere bodies a rank's box first grows to the spheres it holds outside it (bodies.h: a
 * body's spheres live on the rank of its centre), every rank's bounds through one reduction. What
 * goes to one rank is a swap: its send list (particle, shift) is fixed until the next build, in
 * the order of the images and, within one, of the particles. A swap packs its particles' PF_BORDER
 * fields (particles.h) with each one's shift added to its position at pack time; the receiver
 * unpacks them after its real particles, at p->n .. p->n + ghosts.n - 1, the ghosts of each sending
 * rank together, in the order of the ranks (this one's own images among them). Before each force
 * computation the same swaps send the PF_FORWARD fields (position, velocity, spin) again, with the
 * same shifts, into the same slots, and the ghosts' PF_REVERSE fields are zeroed; after the pair
 * forces each ghost's PF_REVERSE fields (force, torque) go back and are summed onto the particle it
 * was made from.
 *
 * A swap to this rank itself (a periodic image) copies straight into the ghost slots and folds
 * straight back (particles.h's copy_roles and fold_roles: no buffer); a swap to another rank is
 * packed into a buffer and sent (comm.h). Everything else is the same, so a serial periodic run
 * and a parallel one differ only in where the bytes go. The neighbour list pairs real particles
 * with ghosts like any other particle, so the force kernels know nothing of periodicity or ranks.
 * Only the first n particles are real: integration, walls, output and the coupling never see a
 * ghost. A corner image comes straight from its particle (its shift is the sum of two or three
 * periods), not from a ghost of a ghost: there is one stage. */
#ifndef DEM_GHOSTS_H
#define DEM_GHOSTS_H

#include "particles.h"

typedef struct dem_ghost_swap {
    int rank;              /* where the ghosts go (this rank: periodic images) */
    int nsend, send_capacity;
    int *send;             /* the real particles this swap sends */
    dem_vec3 *shift;       /* added to each one's position [m]: its image's periods */
} dem_ghost_swap;

typedef struct dem_ghost_list {
    int n;                 /* ghosts held here: slots p->n .. p->n + n - 1 */
    int nswap, swap_capacity;
    dem_ghost_swap *swap;  /* in order of rank */
    int nranks;
    int *send_count;       /* per rank: particles sent to it by all its swaps */
    int *recv_count;       /* per rank: ghosts it sent here */
    int *recv_first;       /* per rank: where its ghosts start (slot - p->n) */
    /* scratch of the build and the exchanges */
    size_t *send_bytes, *send_offset, *recv_bytes, *recv_offset;
    int64_t *count_out, *count_in;
    unsigned char *send_buf, *recv_buf;
    size_t send_buf_capacity, recv_buf_capacity;
    int *pick_key, *pick_index, *key_count;
    long pick_capacity;
    int key_capacity;
} dem_ghost_list;

struct dem_system;
void dem_ghosts_free(dem_ghost_list *g);
/* Make the ghosts of the real particles within cutoff [m] of another rank's box or of a periodic
 * side (after the particles were wrapped into the domain and migrated to their owners). */
void dem_ghosts_build(struct dem_system *s, double cutoff);
/* The ghosts' positions, velocities and angular velocities from their sources; forces zeroed. */
void dem_ghosts_update(struct dem_system *s);
/* Add the ghosts' forces and torques onto their sources. */
void dem_ghosts_fold_forces(struct dem_system *s);
/* The real particle ghost k (0 .. n - 1) is an image of, for tests and reports; -1 for a ghost
 * from another rank (it has no local owner). */
int dem_ghosts_owner(const struct dem_system *s, int k);

#endif
