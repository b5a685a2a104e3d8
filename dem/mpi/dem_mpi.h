/* The DEM's MPI glue (issue 23): the one place where libdem meets MPI. The DEM itself knows nothing
 * of MPI; a parallel program (demRun under mpirun, the coupled solver with -parallel) calls
 * dem_mpi_use once with its communicator: the DEM's global decisions (reduce.h) become
 * MPI_Allreduce over it, and its halo and migration messages (comm.h) point-to-point sends. */
#ifndef DEM_MPI_H
#define DEM_MPI_H

#include <mpi.h>

/* Route reduce.h's reductions through MPI_Allreduce and comm.h's messages through point-to-point
 * sends over comm (duplicated: the DEM's messages never meet the program's). */
void dem_mpi_use(MPI_Comm comm);
/* dem_mpi_use(MPI_COMM_WORLD), for programs that do not include mpi.h (dem_mpi_world.h). */
void dem_mpi_use_world(void);
/* A fatal error (error.h) prints its message once, on the rank that met it, and ends every rank
 * (MPI_Abort); for programs that own MPI (demRun). */
void dem_mpi_set_fatal_abort(void);
/* Back to serial (every reduction the identity); frees the duplicated communicator. */
void dem_mpi_release(void);

#endif
