/* The particles' copies on the fluid's ranks (issue 23): how the coupling exchanges only what is
 * needed between the DEM's decomposition and the fluid's.
 *
 * The DEM cuts its particles into boxes (dem/src/decompose.c); OpenFOAM cuts the mesh its own way
 * (simple, hierarchical, scotch: any shape). Each rank holds its own cells. A particle's coupling
 * needs the cells its volume falls into, which may lie on other ranks (a particle straddling a
 * processor patch has cells on two). So each particle is copied to every rank whose cells its
 * reach touches (the ranks' mesh boxes, gathered once), and the void fraction, the gather of the
 * fluid at the particle and the spreading of its forces run there, on the local cells, for the
 * copies. Two moves, as the DEM's ghosts have:
 *   forward   owner -> copies: per-particle values (position, radius, volume; the normaliser of
 *             the weights; the forces to spread) to each copy;
 *   reverse   copies -> owner: per-copy partial sums (the weights each rank found; what each
 *             rank's cells give the particle), summed (or, for a cell index, the largest taken)
 *             on the owner.
 * Serially there is one rank and every particle has one copy, on this rank: the same code, the
 * messages copied in place (comm.h). Only particles near a rank's cells go to it: the bytes per
 * rank and step are counted (cpl_proxies.bytes_sent) and set against an all-gather of every
 * particle, which CFDEMcoupling's twoWayMPI makes. */
#ifndef CPL_PROXIES_H
#define CPL_PROXIES_H

#include <stddef.h>

#include "mesh.h"

#ifdef __cplusplus
extern "C" {
#endif

enum cpl_proxy_op { CPL_PROXY_SUM, CPL_PROXY_MAX };

typedef struct cpl_proxies {
    int rank, size;
    double (*box)[6];        /* [size] each rank's mesh bounds: min xyz, max xyz [m] */
    /* the owner's side: its particles' copies, grouped by the rank they went to */
    int nsent;
    int *sent_particle;      /* [nsent] the particle's index on its owner */
    size_t *send_count, *send_start;   /* [size] copies to each rank */
    /* the fluid side: the copies this rank holds, grouped by the rank they came from */
    int n;
    size_t *recv_count, *recv_start;   /* [size] copies from each rank */
    double *send_buf, *recv_buf;
    size_t send_cap, recv_cap;
    int sent_cap;
    double bytes_sent;       /* to other ranks, since the start [B] */
    long moves;              /* forward and reverse moves since the start */
} cpl_proxies;

/* Gather every rank's mesh bounds (m: this rank's cells). */
void cpl_proxies_init(cpl_proxies *pr, const cpl_mesh *m);
void cpl_proxies_free(cpl_proxies *pr);

/* Choose, for each of the owner's np particles at x [m] with reach[i] [m] (how far from the
 * centre its volume may fall: 0 for a point, the radius for a sphere), the ranks whose mesh box
 * the ball touches, and tell each rank how many copies it holds (pr->n). Serially every particle
 * has its one copy here, in the mesh or not. */
void cpl_proxies_place(cpl_proxies *pr, int np, const double (*x)[3], const double *reach);

/* owner -> copies: per_copy[k][0..ncomp) = per_particle[i][0..ncomp) of copy k's particle i. */
void cpl_proxies_forward(cpl_proxies *pr, int ncomp, const double *per_particle, double *per_copy);

/* copies -> owner: per_particle[i][j] = the sum (or the largest) over particle i's copies of
 * per_copy[k][j]; a particle without copies gets 0 (or -1 for the largest). */
void cpl_proxies_reverse(cpl_proxies *pr, int ncomp, const double *per_copy, double *per_particle, int np,
                         enum cpl_proxy_op op);

#ifdef __cplusplus
}
#endif
#endif
