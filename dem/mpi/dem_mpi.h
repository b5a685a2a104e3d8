/* The DEM's MPI glue (issue 23): the one place where libdem meets MPI. The DEM itself knows nothing
 * of MPI; a parallel program (demRun under mpirun, the coupled solver with -parallel) calls
 * dem_mpi_use once with its communicator, and the DEM's global decisions (reduce.h) become
 * MPI_Allreduce over it. */
#ifndef DEM_MPI_H
#define DEM_MPI_H

#include <mpi.h>

/* Route reduce.h's reductions through MPI_Allreduce over comm (duplicated: the DEM's messages
 * never meet the program's). */
void dem_mpi_use(MPI_Comm comm);
/* Back to serial (every reduction the identity); frees the duplicated communicator. */
void dem_mpi_release(void);

#endif
