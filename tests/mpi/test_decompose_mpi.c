/* The recursive coordinate bisection on several ranks (run under mpirun -np 2 and 4): every rank
 * holds every size-th of the 20,000 points of decompose_points.h, the histograms are summed by
 * MPI_Allreduce through dem_mpi_use, and
 *  1. each rank's tree is bit for bit the serial tree over all the points (counts are exact sums,
 *     so the cut planes do not depend on how the points are spread over the ranks), for 1 to 16
 *     parts;
 *  2. the imbalance that every rank computes from its own points is the serial one (1e-15);
 *  3. every point lies in exactly one part: the parts' counts, summed over the ranks, are N. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "decompose.h"
#include "decompose_points.h"
#include "dem_mpi.h"
#include "harness.h"

enum { N = 20000 };

static int same_tree(const dem_decomposition *a, const dem_decomposition *b)
{
    if (a->nparts != b->nparts || a->nnodes != b->nnodes) return 0;
    for (int k = 0; k < a->nnodes; k++)
        if (a->dim[k] != b->dim[k] || a->cut[k] != b->cut[k] || memcmp(a->child[k], b->child[k], sizeof a->child[k]))
            return 0;
    return !memcmp(a->lo, b->lo, (size_t)a->nparts * sizeof *a->lo) &&
           !memcmp(a->hi, b->hi, (size_t)a->nparts * sizeof *a->hi);
}

int main(int argc, char **argv)
{
    MPI_Init(&argc, &argv);
    int rank, size;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    static double x[N][3], mine[N][3], w[16];
    decompose_points(N, x);
    int n = 0;
    for (int i = rank; i < N; i += size) memcpy(mine[n++], x[i], sizeof x[i]);
    const int parts[] = {1, 2, 3, 4, 5, 7, 8, 16};
    int failed = 0;
    for (size_t t = 0; t < sizeof parts / sizeof *parts; t++) {
        const int np = parts[t];
        dem_decomposition serial, par;
        dem_mpi_release();   /* serial: the identity reductions over all the points */
        dem_decompose_rcb(&serial, np, domain_lo, domain_hi, N, (const dem_vec3 *)x, NULL);
        const double imb_serial = dem_decomposition_imbalance(&serial, N, (const dem_vec3 *)x, NULL, w);
        dem_mpi_use(MPI_COMM_WORLD);
        dem_decompose_rcb(&par, np, domain_lo, domain_hi, n, (const dem_vec3 *)mine, NULL);
        const double imb = dem_decomposition_imbalance(&par, n, (const dem_vec3 *)mine, NULL, w);
        double counted = 0.0;
        for (int p = 0; p < np; p++) counted += w[p];
        int ok[3] = {same_tree(&serial, &par), fabs(imb - imb_serial) <= 1e-15 * imb_serial, counted == N};
        MPI_Allreduce(MPI_IN_PLACE, ok, 3, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
        if (rank == 0) {
            char what[160];
            snprintf(what, sizeof what, "%d ranks, %d parts: every rank's tree is the serial one bit for bit", size, np);
            check_true(what, ok[0]);
            snprintf(what, sizeof what, "%d ranks, %d parts: imbalance %.6f is the serial %.6f", size, np, imb, imb_serial);
            check_true(what, ok[1]);
            snprintf(what, sizeof what, "%d ranks, %d parts: the parts hold the %d points once each", size, np, N);
            check_true(what, ok[2]);
        }
        failed |= !(ok[0] && ok[1] && ok[2]);
        dem_decomposition_free(&serial);
        dem_decomposition_free(&par);
    }
    dem_mpi_release();
    int status = 0;
    if (rank == 0) status = finish("decompose_mpi");
    MPI_Bcast(&status, 1, MPI_INT, 0, MPI_COMM_WORLD);
    MPI_Finalize();
    return status | failed;
}
