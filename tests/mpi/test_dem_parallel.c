/* The DEM decomposed over ranks (issue 23; run under mpirun -np 2 and 4): the halo (ghosts.h)
 * and migration (migrate.h) against the serial run of the same bed.
 *
 * The bed: 648 spheres of 0.5 mm (Hertz, tangential history), on a lattice 0.1 mm apart, in a box
 * of 10 mm periodic in x with walls in y and z, thrown along x at 5 m/s with +-1 m/s of
 * scatter in every direction, under gravity: in 100 steps of 2 us every sphere moves about a
 * diameter, many cross a rank's boundary or the periodic side, and contacts (with their tangential
 * history) form across the cuts. Every rank runs the serial bed too (the reductions and messages
 * switched off), then the same bed decomposed.
 *  1. After 100 steps every sphere is where the serial run put it, to 1e-12 m (the only
 *     difference allowed is the order of the force sums: round-off).
 *  2. At every step of 100 and then of 2,000 more: the particles summed over the ranks are the 648,
 *     their ids 0 .. 647 each once, their total mass the serial mass to 1e-12 (no particle lost
 *     or duplicated by migration).
 *  3. On 2 and 4 ranks the test means something: particles changed rank in the first 100 steps
 *     and ghosts came from other ranks, and contacts (with tangential history) joined particles of
 *     two ranks.
 * On one rank the same code runs with its periodic images only: the serial run bit for bit. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dem_mpi.h"
#include "comm.h"
#include "harness.h"
#include "mpi_finish.h"

enum { NX = 9, NY = 9, NZ = 8, N = NX * NY * NZ };
static const double E = 5e6, NU = 0.3, RHO = 2500, RAD = 5e-4, L = 0.005;

static double uniform(unsigned *state)
{
    *state = *state * 1103515245u + 12345u;
    return ((*state >> 8) & 0xffff) / 65535.0 * 2.0 - 1.0;
}

static void make_bed(dem_system *s)
{
    make_system(s, E, NU, RHO, 0.5, 0.5, normal_hertz, tangential_history, L);
    s->periodic[0] = 1;
    s->gravity[2] = -9.81;
    s->dt = 2e-6;
    s->nlist.skin = 0.2 * RAD;
    add_plane(s, 0, 0, -L, 0, 0, 1);
    add_plane(s, 0, -L, 0, 0, 1, 0);
    add_plane(s, 0, L, 0, 0, -1, 0);
    add_plane(s, 0, 0, L, 0, 0, -1);
    unsigned seed = 12345;
    for (int i = 0; i < NX; i++)
        for (int j = 0; j < NY; j++)
            for (int m = 0; m < NZ; m++)
                add_sphere(s, -L + RAD + i * 2.2 * RAD, -L + 1.1 * RAD + j * 2.2 * RAD, -L + 1.1 * RAD + m * 2.2 * RAD,
                           5.0 + uniform(&seed), uniform(&seed), uniform(&seed), RAD);
    dem_system_setup(s);
}

/* Every rank's (id, x) on rank 0, in id order: x_by_id[id]; returns the count gathered. */
static int gather_by_id(const dem_system *s, int rank, int size, double (*x_by_id)[3], int *seen)
{
    int n = s->p.n, *counts = malloc((size_t)size * sizeof(int)), *displs = malloc((size_t)size * sizeof(int));
    MPI_Allgather(&n, 1, MPI_INT, counts, 1, MPI_INT, MPI_COMM_WORLD);
    int total = 0;
    for (int r = 0; r < size; r++) { displs[r] = total; total += counts[r]; }
    int64_t *ids = malloc((size_t)(total + 1) * sizeof(int64_t));
    double *xs = malloc((size_t)(3 * total + 3) * sizeof(double));
    MPI_Allgatherv(s->p.id, n, MPI_INT64_T, ids, counts, displs, MPI_INT64_T, MPI_COMM_WORLD);
    for (int r = 0; r < size; r++) { counts[r] *= 3; displs[r] *= 3; }
    MPI_Allgatherv(s->p.x, 3 * n, MPI_DOUBLE, xs, counts, displs, MPI_DOUBLE, MPI_COMM_WORLD);
    memset(seen, 0, N * sizeof(int));
    int valid = total == N;
    for (int k = 0; k < total; k++) {
        if (ids[k] < 0 || ids[k] >= N || seen[ids[k]]++) { valid = 0; continue; }
        memcpy(x_by_id[ids[k]], xs + 3 * k, 3 * sizeof(double));
    }
    (void)rank;
    free(counts); free(displs); free(ids); free(xs);
    return valid ? total : -1;
}

static double total_mass(const dem_system *s)
{
    double m = 0.0;
    for (int i = 0; i < s->p.n; i++) m += s->p.mass[i];
    MPI_Allreduce(MPI_IN_PLACE, &m, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    return m;
}

int main(int argc, char **argv)
{
    MPI_Init(&argc, &argv);
    int rank, size;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    static double serial_x[N][3], par_x[N][3];
    static int seen[N], owner[N], owner_before[N];

    dem_mpi_release();   /* the serial bed: one rank, every reduction the identity */
    dem_system ser;
    make_bed(&ser);
    double serial_mass = 0.0;
    for (int i = 0; i < ser.p.n; i++) serial_mass += ser.p.mass[i];
    for (int k = 0; k < 100; k++) dem_system_step(&ser);
    for (int i = 0; i < ser.p.n; i++) memcpy(serial_x[ser.p.id[i]], ser.p.x[i], sizeof serial_x[0]);
    dem_system_free(&ser);

    dem_mpi_use(MPI_COMM_WORLD);
    dem_system par;
    make_bed(&par);
    int conserved = 1, moves_100 = 0, moves = 0;
    long remote_ghosts = 0, remote_contacts = 0;
    for (int step = 0; step <= 2100; step++) {
        if (step > 0) dem_system_step(&par);
        /* count, ids, mass */
        const int got = gather_by_id(&par, rank, size, par_x, seen);
        const double m = total_mass(&par);
        if (got != N || fabs(m - serial_mass) > 1e-12 * serial_mass) {
            if (conserved && rank == 0)
                printf("step %d: %d particles gathered (-1: an id missing or twice), mass %.15g kg against %.15g\n",
                       step, got, m, serial_mass);
            conserved = 0;
        }
        /* who owns each id now: the changes are migrations */
        for (int i = 0; i < N; i++) owner[i] = -1;
        for (int i = 0; i < par.p.n; i++) owner[par.p.id[i]] = rank;
        MPI_Allreduce(MPI_IN_PLACE, owner, N, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
        if (step > 0)
            for (int i = 0; i < N; i++) moves += owner[i] != owner_before[i];
        memcpy(owner_before, owner, sizeof owner);
        long remote[2] = {par.ghosts.n - par.ghosts.recv_count[rank], 0};
        const int self_lo = par.p.n + par.ghosts.recv_first[rank], self_hi = self_lo + par.ghosts.recv_count[rank];
        for (int i = 0; i < par.p.n; i++)   /* touching pairs with another rank's particle */
            for (int k = par.nlist.start[i]; k < par.nlist.start[i + 1]; k++) {
                const int j = par.nlist.partner[k];
                remote[1] += par.nlist.touching[k] && j >= par.p.n && !(j >= self_lo && j < self_hi);
            }
        MPI_Allreduce(MPI_IN_PLACE, remote, 2, MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
        remote_ghosts += remote[0];
        remote_contacts += remote[1];
        if (step == 100) {
            moves_100 = moves;
            double dmax = 0.0;
            for (int i = 0; i < N; i++)
                for (int d = 0; d < 3; d++) {
                    double dx = fabs(par_x[i][d] - serial_x[i][d]);
                    if (d == 0) dx = fmin(dx, fabs(dx - 2 * L));   /* the same place through the periodic side */
                    dmax = fmax(dmax, dx);
                }
            if (rank == 0) {
                char what[200];
                snprintf(what, sizeof what, "%d ranks, 100 steps: every sphere where the serial run put it (largest "
                         "difference %.3g m, 1e-12 m allowed)", size, dmax);
                check_true(what, got == N && dmax <= 1e-12);
            }
        }
    }
    if (rank == 0) {
        char what[200];
        snprintf(what, sizeof what, "%d ranks, 2,100 steps: 648 particles, ids each once, mass exact to 1e-12 at every step",
                 size);
        check_true(what, conserved);
        if (size > 1) {
            snprintf(what, sizeof what, "particles changed rank: %d times in the first 100 steps, %d in all", moves_100, moves);
            check_true(what, moves_100 > 0);
            snprintf(what, sizeof what, "ghosts from other ranks: %ld summed over the steps", remote_ghosts);
            check_true(what, remote_ghosts > 0);
            snprintf(what, sizeof what, "contacts across ranks (with their tangential history): %ld summed over the steps",
                     remote_contacts);
            check_true(what, remote_contacts > 0);
        }
        printf("bytes sent to other ranks by rank 0: %.0f\n", dem_comm_bytes_sent());
    }
    dem_system_free(&par);
    return mpi_finish("test_dem_parallel");
}
