/* Linked cells and a half Verlet list with skin. Each pair is stored once (under the one of its
 * two particles with the lower id, a real one; the other may be a ghost: a periodic image or another
 * rank's particle, ghosts.h), with its contact history
 * beside it; contacts.c carries the history across rebuilds and sorts by particle ids.
 * The list is rebuilt only when some particle has moved more than half the skin since the
 * last build (dem_system_step measures that while it moves the particles). Every sortInterval-th rebuild first re-orders the particles by cell, so that
 * neighbours are near each other in memory. */
#ifndef DEM_NEIGHBOUR_H
#define DEM_NEIGHBOUR_H

#include "particles.h"

typedef struct dem_neighbour_list {
    double skin;                 /* [m] */
    double reach;                /* the normal model's reach beyond touching (JKR), added to the skin [m] */
    int sort_interval;           /* rebuilds between sorts, 0 = never */
    int history_size;            /* doubles per pair */
    int history_antisymmetric;   /* leading doubles that change sign when i and j swap */
    /* CSR half list: partners of i are partner[start[i] .. start[i+1]) */
    int *start;                  /* rows_capacity entries */
    int *partner;
    double *history;             /* history_size doubles per pair */
    unsigned char *touching;     /* per pair: in contact at the last force computation */
    long npairs, capacity, history_capacity;
    int rows_capacity;
    int rows;                    /* particles the list was built for */
    dem_vec3 *x_at_build;            /* positions at the last build */
    int build_capacity;
    /* What the list was built for: the particles' generation (particles.h) and the id at each
     * index, the images' too (rows + images entries). The contacts are carried by these ids, so a
     * particle removed or moved to another index since the build leaves no wrong history. */
    long generation;
    int64_t *id_at_build;
    int id_capacity;
    long builds, sorts;              /* since the start of the run */
    double build_seconds;            /* the builds' own compute time (sorting, binning, the pair search;
                                      * not the halo's messages), for a parallel run's load [s] */
    long schedule;                   /* builds since the sorting schedule began (a relist begins it again) */
    /* cells */
    int ncell[3];
    double cell_size[3], origin[3];
    int *cell_start, *cell_of, *cell_order;
    long cell_capacity;
} dem_neighbour_list;

struct dem_system;
void dem_neighbour_init(dem_neighbour_list *nl, double skin, int sort_interval, int history_size);
void dem_neighbour_free(dem_neighbour_list *nl);
/* Wrap periodic coordinates into the box; stop if a particle left a closed side. */
void dem_neighbour_wrap(struct dem_system *s);
/* Rebuild: wrap the particles into the box, sort them by cell when due, make the periodic
 * images, build the list; every pair's history starts at zero. */
void dem_neighbour_rebuild(struct dem_system *s);

#endif
