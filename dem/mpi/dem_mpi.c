/* The DEM's MPI glue (dem_mpi.h). */
#include "dem_mpi.h"

#include "reduce.h"

static MPI_Comm dem_comm = MPI_COMM_NULL;

static MPI_Op op_of(enum dem_reduce_op op)
{
    return op == DEM_REDUCE_SUM ? MPI_SUM : op == DEM_REDUCE_MIN ? MPI_MIN : MPI_MAX;
}

static void allreduce_doubles(double *values, int n, enum dem_reduce_op op, void *context)
{
    MPI_Allreduce(MPI_IN_PLACE, values, n, MPI_DOUBLE, op_of(op), *(MPI_Comm *)context);
}

static void allreduce_int64s(int64_t *values, int n, enum dem_reduce_op op, void *context)
{
    MPI_Allreduce(MPI_IN_PLACE, values, n, MPI_INT64_T, op_of(op), *(MPI_Comm *)context);
}

void dem_mpi_use(MPI_Comm comm)
{
    dem_mpi_release();
    MPI_Comm_dup(comm, &dem_comm);
    const dem_reduce_hook hook = {allreduce_doubles, allreduce_int64s, &dem_comm};
    dem_set_reduce_hook(&hook);
}

void dem_mpi_release(void)
{
    dem_set_reduce_hook(NULL);
    if (dem_comm != MPI_COMM_NULL) MPI_Comm_free(&dem_comm);
}
