/* One hook for the decisions every rank must take alike (issue 23).
 *
 * Some of the DEM's decisions are made from every particle: whether any moved far enough since
 * the last list build to rebuild, the next free particle id, the smallest radius per material
 * and the fastest particle for the time-step check. Each is a local loop followed by one of these
 * calls; serially they return their argument, and a parallel run sets the hook once (an
 * MPI_Allreduce over its communicator), so that every rank rebuilds, numbers and checks alike.
 * The DEM itself knows nothing of MPI. */
#ifndef DEM_REDUCE_H
#define DEM_REDUCE_H

#include <stdint.h>

enum dem_reduce_op { DEM_REDUCE_SUM, DEM_REDUCE_MIN, DEM_REDUCE_MAX };

/* Combine n doubles (or n int64s) across all ranks in place: each element becomes the sum,
 * minimum or maximum of that element over the ranks. */
typedef struct dem_reduce_hook {
    void (*doubles)(double *values, int n, enum dem_reduce_op op, void *context);
    void (*int64s)(int64_t *values, int n, enum dem_reduce_op op, void *context);
    void *context;
} dem_reduce_hook;

/* Set the hook (NULL: serial, every reduction the identity); returns the one set before. */
dem_reduce_hook dem_set_reduce_hook(const dem_reduce_hook *hook);

void dem_reduce_doubles(double *values, int n, enum dem_reduce_op op);
void dem_reduce_int64s(int64_t *values, int n, enum dem_reduce_op op);
/* Whether the flag is set on any rank. */
int dem_reduce_any(int flag);
/* Every rank's n int64s, in rank order: all[r * n .. r * n + n - 1] are rank r's `mine` (all holds
 * n x the number of ranks); one sum with one term per slot, so exact. */
void dem_reduce_gather_int64s(const int64_t *mine, int n, int64_t *all);

#endif
