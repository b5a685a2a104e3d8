/* dem_mpi.h for a program that does not include mpi.h itself (the OpenFOAM adapter, whose
 * -parallel run has started MPI already): the DEM and the coupling's messages over a copy of
 * MPI_COMM_WORLD, and back to serial. */
#ifndef DEM_MPI_WORLD_H
#define DEM_MPI_WORLD_H

#ifdef __cplusplus
extern "C" {
#endif

void dem_mpi_use_world(void);
void dem_mpi_release(void);

#ifdef __cplusplus
}
#endif
#endif
