/* The DEM's MPI glue (dem_mpi.h). */
#include "dem_mpi.h"

#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include <hdf5.h>

#include "comm.h"
#include "error.h"
#include "io.h"
#include "reduce.h"

static MPI_Comm dem_comm = MPI_COMM_NULL;
static MPI_Request *requests;
static int request_capacity;

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

/* Point to point with the ranks a message goes to or comes from: the receives posted first. */
static void exchange(const void *send, const size_t *send_bytes, const size_t *send_offset, void *recv,
                     const size_t *recv_bytes, const size_t *recv_offset, void *context)
{
    const MPI_Comm comm = *(MPI_Comm *)context;
    int rank, size;
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &size);
    if (2 * size > request_capacity) {
        request_capacity = 2 * size;
        requests = dem_realloc(requests, (size_t)request_capacity * sizeof *requests);
    }
    int nreq = 0;
    for (int r = 0; r < size; r++) {
        if (r == rank || recv_bytes[r] == 0) continue;
        if (recv_bytes[r] > (size_t)0x7fffffff) dem_fatal("a halo message of %zu bytes is larger than MPI's int count", recv_bytes[r]);
        MPI_Irecv((char *)recv + recv_offset[r], (int)recv_bytes[r], MPI_BYTE, r, 7, comm, &requests[nreq++]);
    }
    for (int r = 0; r < size; r++) {
        if (r == rank || send_bytes[r] == 0) continue;
        if (send_bytes[r] > (size_t)0x7fffffff) dem_fatal("a halo message of %zu bytes is larger than MPI's int count", send_bytes[r]);
        MPI_Isend((const char *)send + send_offset[r], (int)send_bytes[r], MPI_BYTE, r, 7, comm, &requests[nreq++]);
    }
    MPI_Waitall(nreq, requests, MPI_STATUSES_IGNORE);
}

/* HDF5's MPI-IO driver for the writer's shared file (io.h) */
static int use_mpio(int64_t fapl, void *context)
{
    return H5Pset_fapl_mpio((hid_t)fapl, *(MPI_Comm *)context, MPI_INFO_NULL) < 0 ? -1 : 0;
}

static int collective(int64_t dxpl, void *context)
{
    (void)context;
    return H5Pset_dxpl_mpio((hid_t)dxpl, H5FD_MPIO_COLLECTIVE) < 0 ? -1 : 0;
}

static void counts(const int64_t *send, int64_t *recv, void *context)
{
    MPI_Alltoall(send, 1, MPI_INT64_T, recv, 1, MPI_INT64_T, *(MPI_Comm *)context);
}

/* An error on one rank ends every rank: the message once, from the rank that met it. An error
 * every rank meets alike (the input, read by all) is said by rank 0 alone: the others wait two
 * seconds before they speak, and rank 0's abort has ended them by then; an error of one rank
 * alone (a particle that blew up in its box) is said by that rank after the wait. */
static void fatal_abort(const char *where, const char *message)
{
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    fflush(stdout);
    if (rank != 0) sleep(2);
    if (where) fprintf(stderr, "%s: error: %s\n", where, message);
    else fprintf(stderr, "error: %s\n", message);
    if (rank != 0) fprintf(stderr, "(on rank %d)\n", rank);
    fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, 1);
    exit(1);
}

void dem_mpi_use(MPI_Comm comm)
{
    dem_mpi_release();
    MPI_Comm_dup(comm, &dem_comm);
    const dem_reduce_hook hook = {allreduce_doubles, allreduce_int64s, &dem_comm};
    dem_set_reduce_hook(&hook);
    dem_comm_hook c = {0, 1, exchange, counts, &dem_comm};
    MPI_Comm_rank(dem_comm, &c.rank);
    MPI_Comm_size(dem_comm, &c.size);
    dem_set_comm_hook(&c);
    const dem_io_parallel_hook io = {use_mpio, collective, &dem_comm};
    dem_io_set_parallel_hook(&io);
}

void dem_mpi_set_fatal_abort(void)
{
    dem_set_fatal_handler(fatal_abort);
}

void dem_mpi_release(void)
{
    dem_set_reduce_hook(NULL);
    dem_set_comm_hook(NULL);
    dem_io_set_parallel_hook(NULL);
    if (dem_comm != MPI_COMM_NULL) MPI_Comm_free(&dem_comm);
}

void dem_mpi_use_world(void) { dem_mpi_use(MPI_COMM_WORLD); }
