/* The reduction hook (reduce.h). */
#include <stddef.h>
#include <string.h>

#include "comm.h"
#include "reduce.h"

static dem_reduce_hook current;   /* zeroed: serial */

dem_reduce_hook dem_set_reduce_hook(const dem_reduce_hook *hook)
{
    const dem_reduce_hook before = current;
    if (hook) current = *hook;
    else current = (dem_reduce_hook){NULL, NULL, NULL};
    return before;
}

void dem_reduce_doubles(double *values, int n, enum dem_reduce_op op)
{
    if (current.doubles && n > 0) current.doubles(values, n, op, current.context);
}

void dem_reduce_int64s(int64_t *values, int n, enum dem_reduce_op op)
{
    if (current.int64s && n > 0) current.int64s(values, n, op, current.context);
}

int dem_reduce_any(int flag)
{
    int64_t v = flag != 0;
    dem_reduce_int64s(&v, 1, DEM_REDUCE_MAX);
    return v != 0;
}

void dem_reduce_gather_int64s(const int64_t *mine, int n, int64_t *all)
{
    const int size = dem_comm_size(), rank = dem_comm_rank();
    memset(all, 0, (size_t)n * size * sizeof *all);
    memcpy(all + (size_t)rank * n, mine, (size_t)n * sizeof *all);
    dem_reduce_int64s(all, n * size, DEM_REDUCE_SUM);
}
