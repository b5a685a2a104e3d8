/* The end of an MPI test (tests/mpi): rank 0 holds the checks (harness.h) and tells every rank the
 * verdict, so that each exits with it, whichever rank mpirun looks at; the DEM's hooks are
 * released before MPI ends. Returns the exit status. */
#ifndef TEST_MPI_FINISH_H
#define TEST_MPI_FINISH_H

#include <mpi.h>

#include "dem_mpi.h"
#include "harness.h"

static inline int mpi_finish(const char *name)
{
    int rank, failed = checks_failed;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Bcast(&failed, 1, MPI_INT, 0, MPI_COMM_WORLD);
    dem_mpi_release();
    if (rank == 0) finish(name);
    MPI_Finalize();
    return failed ? 1 : 0;
}

#endif
