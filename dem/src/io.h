/* Particle output and restart: HDF5 (Debian's parallel build, used serially for now) with an
 * XDMF file beside it so that ParaView opens the snapshots as a time series of point clouds.
 *
 * Layout of <base>.h5:
 *   /snapshots/<k>/  (k = 000000, 000001, ...) groups, one per snapshot, each with
 *       attributes time [s] (double), step (int64), n (int64), complete (int, written last)
 *       datasets  the particle fields flagged PF_WRITE or PF_RESTART in particles.h, each
 *                 n or n x components, with a `units` attribute: today position (n x 3) [m],
 *                 velocity [m/s], omega [rad/s], force [N], torque [N m] (n x 3), radius (n) [m],
 *                 id (n, int64), type (n, int32); the XDMF index lists the PF_WRITE ones
 * The file is flushed after each snapshot, so a killed run leaves every snapshot before the
 * one being written readable; a snapshot without `complete` is ignored on restart.
 * <base>.xdmf is rewritten after each snapshot and lists the complete ones.
 * With contact history (the *_contacts variants) a snapshot also holds /snapshots/<k>/contacts/
 *       attributes history_size, nwalls; datasets keys (m x 2, int64: a pair's two particle ids
 *       as the list held them, or -1 - wall index and the particle id for a wall contact) and
 *       history (m x history_size), so that a restart continues the contacts where they were
 *       (contacts.h).
 */
#ifndef DEM_IO_H
#define DEM_IO_H

#include "particles.h"

typedef struct dem_particle_writer dem_particle_writer;

/* Multisphere bodies of a snapshot (bodies.h), written as /snapshots/<k>/bodies/ with one
 * dataset per column group: id and template (int64), position [m], velocity [m/s], orientation
 * (quaternion w x y z, principal frame to space), angular_momentum_body [kg m^2/s] (principal
 * frame), omega [rad/s], force [N], torque [N m] (about the centre of mass), rotational_energy [J]
 * (seed 004 eq. 8). A restart rebuilds the bodies from it; their spheres are particles. */
typedef struct dem_body_state {
    int present;                 /* the snapshot has bodies (on any rank: a parallel write is collective) */
    long count;                  /* the bodies here (written: this rank's; read: all the snapshot's) */
    int64_t *id, *template_of;
    double *x, *v, *q, *Lb, *omega, *f, *torque, *e_rot;   /* 3 per body; q 4; e_rot 1 */
} dem_body_state;

/* The life cycle's counters (lifecycle.h), written as /snapshots/<k>/lifecycle/: the balance
 * (inserted and removed: count, mass as two int64 of 2^-64 kg quanta), per outlet its removed
 * tally, per stream insertion its random stream, tally, carry-over and what is behind; the names
 * as space-separated string attributes, so that a restart gives each its own. */
enum { LIFECYCLE_STREAM_INTS = 9, LIFECYCLE_STREAM_REALS = 2 };
typedef struct dem_lifecycle_state {
    int present;                 /* reader: the snapshot had the group */
    int64_t balance[6];          /* inserted count, mass hi, lo; removed count, mass hi, lo */
    int noutlets, nstreams;
    int64_t *outlets;            /* 3 per outlet: count, mass hi, lo */
    int64_t *streams;            /* LIFECYCLE_STREAM_INTS per stream: rng (4), count, mass hi, lo, carried, behind */
    double *stream_reals;        /* LIFECYCLE_STREAM_REALS per stream: pending diameter [m], behind [kg] */
    char *outlet_names, *stream_names;   /* space-separated */
} dem_lifecycle_state;

/* Contact history in a form independent of particle order and neighbour lists (contacts.h),
 * and the snapshot's other non-particle state (the bodies, the life cycle's counters). */
typedef struct dem_contact_state {
    int history_size;        /* doubles per contact */
    int nwalls;              /* walls of the case that wrote it (wall contacts name their index) */
    long count;
    int64_t *keys;           /* 2 per contact: ids (i, j), or (-1 - wall, particle id) */
    double *history;         /* history_size per contact */
    int forces_read;         /* reader: p->f and p->torque hold the snapshot's forces */
    int coupling_read;       /* reader: p->beta and p->f_fluid hold the snapshot's (coupled runs) */
    dem_body_state bodies;   /* multisphere bodies (count 0: none) */
    dem_lifecycle_state lifecycle;
    double coarse_graining;  /* the case's coarseGraining (the snapshot's attribute; 1 when absent) */
} dem_contact_state;

void dem_contact_state_free(dem_contact_state *cs);

/* A parallel run (issue 23) writes one file from every rank at once, through HDF5's MPI-IO driver:
 * each snapshot's datasets hold every rank's particles (and contacts), each rank writing its own
 * rows, collectively; the XDMF index is written by rank 0. The MPI calls are the hook's, set by
 * dem/mpi (dem_mpi_use); without it (serially) the file is the process's own. Reading is the
 * same on any number of ranks: each rank reads a snapshot whole (its set-up keeps what it owns). */
typedef struct dem_io_parallel_hook {
    int (*use_mpio)(int64_t fapl, void *context);     /* MPI-IO on a file access list; < 0: failed */
    int (*collective)(int64_t dxpl, void *context);   /* collective transfers on a transfer list */
    void *context;
} dem_io_parallel_hook;
void dem_io_set_parallel_hook(const dem_io_parallel_hook *hook);

/* base: path without extension, e.g. "case/particles". append != 0 keeps existing snapshots
 * (restart); otherwise the files are created anew. Fatal on HDF5 errors, with the path. In a
 * parallel run every rank calls the writer's functions alike (collective). */
dem_particle_writer *dem_io_open_writer(const char *base, int append);
void dem_io_write_snapshot(dem_particle_writer *w, const dem_particles *p, double time, long step);
/* The same, with the contact history (cs may be NULL). */
void dem_io_write_snapshot_contacts(dem_particle_writer *w, const dem_particles *p, double time, long step,
                                const dem_contact_state *cs);
void dem_io_close_writer(dem_particle_writer *w);

/* Read the last complete snapshot of <base>.h5 into p (p is reset and refilled: the PF_RESTART
 * fields from the snapshot, the others 0; masses are left for the caller to set from the
 * materials). Returns 0 on success, -1 when the file has no complete snapshot; fatal when the
 * file cannot be read. */
int dem_io_read_last_snapshot(const char *base, dem_particles *p, double *time, long *step);
/* The same, also filling cs with the snapshot's contact history (empty when it has none);
 * cs->forces_read = 1 when the snapshot had p->f and p->torque (restart fields): the restarted
 * run then continues without evaluating the contacts a second time at that step. */
int dem_io_read_last_snapshot_contacts(const char *base, dem_particles *p, double *time, long *step,
                                   dem_contact_state *cs);

/* The snapshot at at_time (the last complete one within tolerance of it; NAN: the last). Returns
 * -1 when there is none; otherwise as dem_io_read_last_snapshot_contacts (cs may be NULL). */
int dem_io_read_snapshot_at(const char *base, double at_time, double tolerance, dem_particles *p, double *time,
                        long *step, dem_contact_state *cs);
/* Remove the complete snapshots later than after_time (a run continued from an earlier time
 * rewrites them, as OpenFOAM rewrites later time directories). Returns how many. */
int dem_io_drop_snapshots_after(const char *base, double after_time);

#endif
