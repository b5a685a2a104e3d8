/* Particle output and restart: HDF5 (Debian's parallel build, used serially for now) with an
 * XDMF file beside it so that ParaView opens the snapshots as a time series of point clouds.
 *
 * Layout of <base>.h5:
 *   /snapshots/<k>/  (k = 000000, 000001, ...) groups, one per snapshot, each with
 *       attributes time [s] (double), step (int64), n (int64), complete (int, written last)
 *       datasets  position (n x 3) [m], velocity (n x 3) [m/s], omega (n x 3) [rad/s],
 *                 force (n x 3) [N], radius (n) [m], id (n, int64), type (n, int32)
 * The file is flushed after each snapshot, so a killed run leaves every snapshot before the
 * one being written readable; a snapshot without `complete` is ignored on restart.
 * <base>.xdmf is rewritten after each snapshot and lists the complete ones.
 */
#ifndef DEM_IO_H
#define DEM_IO_H

#include "particles.h"

typedef struct particle_writer particle_writer;

/* base: path without extension, e.g. "case/particles". append != 0 keeps existing snapshots
 * (restart); otherwise the files are created anew. Fatal on HDF5 errors, with the path. */
particle_writer *io_open_writer(const char *base, int append);
void io_write_snapshot(particle_writer *w, const particles *p, double time, long step);
void io_close_writer(particle_writer *w);

/* Read the last complete snapshot of <base>.h5 into p (p is reset and refilled; masses are
 * left for the caller to set from the materials). Returns 0 on success, -1 when the file has
 * no complete snapshot; fatal when the file cannot be read. */
int io_read_last_snapshot(const char *base, particles *p, double *time, long *step);

#endif
