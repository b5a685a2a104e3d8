/* The DEM's messages between ranks (issue 23), beside reduce.h's reductions.
 *
 * The halo (ghosts.h) and migration (migrate.h) send byte buffers to the ranks that need them
 * and nothing to the others. Like reduce.h this is a hook: serially there is one rank and every
 * message goes to this process itself (the callers copy those without a call); a parallel program
 * sets the hook once (dem/mpi/dem_mpi.c: MPI point to point), so the DEM knows nothing of MPI.
 * Each rank's bytes sent to other ranks are counted, for the run's report. */
#ifndef DEM_COMM_H
#define DEM_COMM_H

#include <stddef.h>
#include <stdint.h>

typedef struct dem_comm_hook {
    int rank, size;
    /* To each rank r: send_bytes[r] bytes at send + send_offset[r]; from each rank r:
     * recv_bytes[r] bytes into recv + recv_offset[r]. Both sides know the sizes beforehand (the
     * counts below give them where they are not known); a message is exchanged only where the
     * size is not 0. The entries of this rank itself are left alone. */
    void (*exchange)(const void *send, const size_t *send_bytes, const size_t *send_offset, void *recv,
                     const size_t *recv_bytes, const size_t *recv_offset, void *context);
    /* One number between every two ranks: send[r] is what this rank tells rank r, recv[r] what r
     * tells this rank (recv[rank] = send[rank]). */
    void (*counts)(const int64_t *send, int64_t *recv, void *context);
    void *context;
} dem_comm_hook;

/* Set the hook (NULL: serial, one rank); returns the one set before. */
dem_comm_hook dem_set_comm_hook(const dem_comm_hook *hook);
int dem_comm_rank(void);
int dem_comm_size(void);
void dem_comm_exchange(const void *send, const size_t *send_bytes, const size_t *send_offset, void *recv,
                       const size_t *recv_bytes, const size_t *recv_offset);
void dem_comm_counts(const int64_t *send, int64_t *recv);
/* Bytes this rank has sent to other ranks through dem_comm_exchange since the start. */
double dem_comm_bytes_sent(void);

#endif
