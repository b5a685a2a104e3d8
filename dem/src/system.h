/* The DEM system: particles, materials, models, walls, neighbour list and run state. */
#ifndef DEM_SYSTEM_H
#define DEM_SYSTEM_H

#include "bodies.h"
#include "contact/models.h"
#include "contacts.h"
#include "decompose.h"
#include "ghosts.h"
#include "stage_timer.h"
#include "insert_stream.h"
#include "lifecycle.h"
#include "materials.h"
#include "neighbour.h"
#include "outlets.h"
#include "particles.h"
#include "symmetry.h"
#include "walls.h"

/* A parallel run cuts its boxes again when the busiest rank's load is above this x the mean,
 * looked at every DEM_REBALANCE_EVERY list builds (system.c's rebalance) */
#define DEM_REBALANCE_ABOVE 1.02
enum { DEM_REBALANCE_EVERY = 5 };

typedef struct dem_system {
    dem_particles p;
    dem_bodies bodies;                    /* multisphere bodies; their spheres are in p (bodies.h) */
    dem_material_table materials;
    dem_contact_models models;
    int history_size;                 /* doubles per contact, from the models */
    double contact_reach;             /* largest gap at which the normal model still acts [m] (JKR) */
    int generic_kernels;              /* 1: the generic force kernels even where a specialised one exists (tests) */

    double domain_min[3], domain_max[3];
    int periodic[3];
    double period[3];                 /* box length in periodic directions, 0 otherwise */
    double inv_period[3];             /* 1/period, 0 in non-periodic directions */

    int nwalls, wall_capacity;
    dem_wall *walls;                      /* dem_walls_add() appends */
    dem_wall_contacts *wall_lists;        /* per wall: the particles near it and their contact history */
    int nsymmetry;                    /* symmetry planes: mirrors without force (symmetry.h) */
    dem_symmetry_plane symmetry_planes[DEM_MAX_SYMMETRY_PLANES];

    dem_neighbour_list nlist;
    dem_decomposition decomp;             /* each rank's box (decompose.h): one part, the domain, serially */
    long rebalances;                      /* new decompositions since set-up (a parallel run): when the
                                           * busiest rank's load exceeds DEM_REBALANCE_ABOVE x the mean,
                                           * looked at every DEM_REBALANCE_EVERY list builds (system.c) */
    double stage_seconds_at_balance[DEM_STAGE_COUNT];   /* stage_seconds when the load was last looked at */
    double build_seconds_at_balance;      /* nlist.build_seconds then */
    dem_ghost_list ghosts;                /* periodic images and other ranks' particles, after the particles (ghosts.h) */
    dem_contact_rows carried;             /* the contacts' history across a rebuild (contacts.h) */

    /* the life cycle during the run (lifecycle.h) */
    int noutlets, nstreams;
    dem_outlet *outlets;                  /* dem_outlets_add() appends */
    dem_stream *streams;                  /* dem_streams_add() appends */
    dem_tally inserted, removed;          /* units since the run began (the initial insertion included) */
    int balance_started;                  /* inserted holds the initial set (set-up or a restart's snapshot) */

    double gravity[3];                /* [m/s^2] */
    /* coarse graining: every particle is a parcel standing for cg^3 primary particles of
     * diameter d / cg (docs/models/coarse_graining.md); 1: none. The DEM simulates the parcels
     * as they are (Bierwisch et al. 2009); the coupling's drag sees the primary size */
    double coarse_graining;
    double dt;                        /* [s] */
    double time;                      /* [s] */
    long step;
    double max_overlap_fraction;      /* stop above this overlap / smaller radius */
    double max_overlap_seen;          /* largest overlap / smaller radius in the last step */
    double stage_seconds[DEM_STAGE_COUNT];   /* wall time per stage of the step since set-up [s] (stage_timer.h) */
    double wall_force[3];             /* the walls' total force on the particles in the last step [N] */
    int64_t next_id;
} dem_system;

void dem_system_init(dem_system *s);
void dem_system_free(dem_system *s);
/* After particles, materials, models, walls are set: allocate histories, build the list,
 * compute the first forces. */
void dem_system_setup(dem_system *s);
/* Make the neighbour and wall lists again as a restart's set-up makes them (the sorting
 * schedule starts again, the histories carried over by contact): called where a snapshot is
 * written, so that a run restarted from that snapshot continues bit for bit (the order in which
 * each particle's contact forces are summed follows the lists). */
void dem_system_relist(dem_system *s);
/* The same, with the contact history of a store (contacts.h) put back onto the new lists, and
 * the first forces only if compute_forces (a restart keeps its snapshot's); returns how many
 * contacts were found. */
long dem_system_setup_with_contacts(dem_system *s, const dem_contact_store *saved, int compute_forces);
/* One velocity-Verlet step. */
void dem_system_step(dem_system *s);
/* Forces for the current positions (pairs, walls, gravity, external). */
void dem_system_compute_forces(dem_system *s);
/* Stop with a message if a position or velocity is not finite or an overlap is too large. */
void dem_system_check_health(const dem_system *s);
/* Kinetic energy (translational + rotational) [J]: free spheres and bodies (a body's spheres
 * only through their body); prescribed particles, which the forces do not move, are left out. */
double dem_system_kinetic_energy(const dem_system *s);

/* Pair forces (pair_forces.c). */
void dem_pair_forces_add(dem_system *s);
/* The DEM's time per stage and, from a probe of the pair kernel, per contact model (stage_report.c):
 * printed at the end of a run; steps: the run's DEM steps. */
void dem_stage_report(dem_system *s, long steps);
/* The descriptor of the model chosen for a slot. */
static inline const dem_contact_model *system_model(const dem_system *s, enum dem_contact_slot slot)
{
    return dem_contact_model_get(slot, contact_model_id(&s->models, slot));
}

#endif
