/* Ghost particles: periodic images now, another rank's border particles with MPI, made by one
 * mechanism (as LAMMPS' and CoMD's halo exchanges make them).
 *
 * A ghost is made by a swap: one side of the box in one direction. At each neighbour-list build,
 * the swaps run in order (x low, x high, y low, ...); each selects the particles within the
 * list's cutoff of its side, real ones and the ghosts earlier swaps made (so edge and corner
 * images come out of the x swaps' ghosts sent on by the y and z swaps), packs their PF_BORDER
 * fields (particles.h) with the periodic shift added to the position at pack time, and unpacks
 * them after the real particles, at indices p->n .. p->n + ghosts.n - 1. Before each force
 * computation the same swaps send the PF_FORWARD fields (position, velocity, spin) again, with the
 * same shifts, and zero the ghosts' PF_REVERSE fields; after the pair forces they run backwards,
 * sending each ghost's PF_REVERSE fields (force, torque) to be summed onto what it was made from.
 * Which particles a swap sends and where their ghosts land is fixed between builds.
 *
 * In a serial run a periodic direction's swaps send to this process itself, so the pack writes
 * straight into the receiving ghosts and the fold adds straight onto the sources (no buffer;
 * particles.h's copy_roles and fold_roles, the buffered gather/put/take/scatter in one pass). A swap that would reach another rank is the MPI halo's (issue 23): the packing,
 * the shifts and the order stay as they are and only the transport changes. The neighbour list
 * pairs real particles with ghosts like any other particle, so the force kernels know nothing of
 * periodicity. Only the first n particles are real: integration, walls, output and the coupling
 * never see a ghost. */
#ifndef DEM_GHOSTS_H
#define DEM_GHOSTS_H

#include "particles.h"

typedef struct dem_ghost_swap {
    int dim;               /* 0, 1, 2: x, y, z */
    int side;              /* -1: the particles near the low side, +1: near the high side */
    double shift[3];       /* added to a sent position [m]: the period where the swap wraps */
    int nsend, send_capacity;
    int *send;             /* the local particles (real or ghost) this swap sends */
    int first;             /* its ghosts are p->n + first .. p->n + first + nsend - 1 */
} dem_ghost_swap;

typedef struct dem_ghost_list {
    int n;                 /* ghosts in all swaps */
    int nswap;
    dem_ghost_swap swap[6];
} dem_ghost_list;

struct dem_system;
void dem_ghosts_free(dem_ghost_list *g);
/* Make the ghosts of the particles within cutoff [m] of a periodic side (after the real
 * particles were wrapped into the box). */
void dem_ghosts_build(struct dem_system *s, double cutoff);
/* The ghosts' positions, velocities and angular velocities from their sources; forces zeroed. */
void dem_ghosts_update(struct dem_system *s);
/* Add the ghosts' forces and torques onto their sources, and so onto the real owners. */
void dem_ghosts_fold_forces(struct dem_system *s);
/* The real particle ghost k (0 .. n - 1) copies, following ghosts of ghosts; for tests and
 * reports (a ghost from another rank has no local owner: -1 then). */
int dem_ghosts_owner(const struct dem_system *s, int k);

#endif
