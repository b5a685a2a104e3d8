/* The coupling's copies across ranks (coupling/src/proxies.h; issue 23; run under mpirun -np 1,
 * 2 and 4): the void fraction, the gather and the spreading of a mesh cut over ranks against the
 * same on the whole mesh in one process.
 *
 * The mesh: a box 4 x 4 x 8 cells of 1 mm, cut into slabs along z, one per rank, each rank holding
 * its own cells only (as OpenFOAM's decomposed mesh: the slab's faces to the other ranks are
 * boundary faces here). 300 spheres of radius 0.25-0.45 mm at random places, each owned by rank
 * id % ranks, which has nothing to do with where it is (the DEM cuts its own boxes). Both the
 * divided void fraction (spheres straddling the cuts: their sample points fall on two ranks'
 * cells, normalised by the count over both) and the centre one, each with the moves coupling.c
 * makes: place, forward (x, r, volume, cell), weigh, reverse (the weights' sum, the centre's
 * cell), forward (the sum, found), finish; the gather of a cell field (reverse sum); the spreading
 * of beta and a force (forward, cpl_exchange_cells).
 *  1. Every cell's particle volume, K_sl and source equal the whole mesh's to 1e-12 (relative to
 *     the largest): the order of the sums is the only difference.
 *  2. Every particle's gathered field equals the whole mesh's to 1e-12.
 *  3. On 2 and 4 ranks the test means something: particles straddle the cuts (weights on two
 *     ranks), and the bytes the copies moved are fewer than an all-gather of every particle. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dem_mpi.h"
#include "comm.h"
#include "exchange.h"
#include "harness.h"
#include "mpi_finish.h"
#include "mesh.h"
#include "proxies.h"
#include "voidfraction.h"

enum { NX = 4, NY = 4, NZ = 8, NP = 300 };
static const double H = 1e-3;

static double uniform(unsigned *state)
{
    *state = *state * 1103515245u + 12345u;
    return ((*state >> 8) & 0xffff) / 65535.0;
}

/* the cell field gathered at the particles: a function of the cell centre */
static double field_at(const double x[3]) { return 1.0 + 3.0 * x[0] / H - 2.0 * x[1] / H + 0.5 * x[2] / H; }

static double max_rel(double worst) { MPI_Allreduce(MPI_IN_PLACE, &worst, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD); return worst; }

static void run(enum cpl_vf_model model, int rank, int size)
{
    const char *name = model == CPL_VF_DIVIDED ? "divided" : "centre";
    static double x[NP][3], r[NP], vol[NP], beta[NP], fex[NP][3], v[NP][3];
    unsigned seed = 2026;
    for (int i = 0; i < NP; i++) {
        x[i][0] = NX * H * uniform(&seed);
        x[i][1] = NY * H * uniform(&seed);
        x[i][2] = NZ * H * uniform(&seed);
        r[i] = H * (0.25 + 0.2 * uniform(&seed));
        vol[i] = 4.0 / 3.0 * M_PI * r[i] * r[i] * r[i];
        beta[i] = 1e-4 * (1.0 + uniform(&seed));
        for (int q = 0; q < 3; q++) { fex[i][q] = 1e-6 * (uniform(&seed) - 0.5); v[i][q] = uniform(&seed) - 0.5; }
    }

    /* the whole mesh in one process (every rank, the reductions and messages switched off) */
    dem_mpi_release();
    cpl_mesh whole;
    const double lo[3] = {0, 0, 0}, hi[3] = {NX * H, NY * H, NZ * H};
    cpl_mesh_box(&whole, lo, hi, NX, NY, NZ);
    cpl_voidfraction vfw;
    cpl_vf_init(&vfw, &whole, model, 0.0);
    static int cell_w[NP];
    for (int i = 0; i < NP; i++) cell_w[i] = -1;
    cpl_vf_compute_volumes(&vfw, &whole, NP, (const double (*)[3])x, r, vol, cell_w);
    double *q_whole = malloc((size_t)whole.ncells * sizeof *q_whole);
    for (int c = 0; c < whole.ncells; c++) q_whole[c] = field_at(whole.cell_centre[c]);
    static double gathered_w[NP];
    cpl_cell_weights ww = {vfw.np, vfw.w_start, vfw.w_cell, vfw.w};
    cpl_gather_scalar(&ww, q_whole, gathered_w);
    cpl_fluid_forces fw = {NP, NP, beta, NULL, fex, NULL};
    double *ksl_w = malloc((size_t)whole.ncells * sizeof *ksl_w), (*up_w)[3] = malloc((size_t)whole.ncells * sizeof *up_w),
           (*src_w)[3] = malloc((size_t)whole.ncells * sizeof *src_w);
    cpl_exchange_cells(&ww, &fw, (const double (*)[3])v, whole.ncells, whole.cell_volume, ksl_w, up_w, src_w);

    /* this rank's slab, and its particles (id % size) */
    dem_mpi_use(MPI_COMM_WORLD);
    cpl_mesh slab;
    const double slo[3] = {0, 0, NZ * H * rank / size}, shi[3] = {NX * H, NY * H, NZ * H * (rank + 1) / size};
    cpl_mesh_box(&slab, slo, shi, NX, NY, NZ / size);
    int n = 0;
    static int mine[NP];
    for (int i = 0; i < NP; i++) if (i % size == rank) mine[n++] = i;
    static double px[NP][3], reach[NP], rows[NP * 8], norm[NP], cellmax[NP], z_copy_count[NP];
    for (int k = 0; k < n; k++) {
        const int i = mine[k];
        memcpy(px[k], x[i], sizeof px[k]);
        reach[k] = model == CPL_VF_CENTRE ? 0.0 : r[i];
        double *o = rows + 6 * k;
        memcpy(o, x[i], 3 * sizeof(double));
        o[3] = r[i]; o[4] = vol[i]; o[5] = -1;
    }
    cpl_proxies pr;
    cpl_proxies_init(&pr, &slab);
    cpl_proxies_place(&pr, n, (const double (*)[3])px, reach);
    const int nc = pr.n;
    double *buf = malloc(((size_t)nc * 8 + 1) * sizeof *buf), (*cx)[3] = malloc(((size_t)nc + 1) * sizeof *cx);
    double *cr = malloc(((size_t)nc + 1) * sizeof *cr), *cvol = malloc(((size_t)nc + 1) * sizeof *cvol);
    double *cz = malloc(((size_t)nc + 1) * sizeof *cz), *cnorm = malloc(((size_t)nc + 1) * sizeof *cnorm);
    double *cfound = malloc(((size_t)nc + 1) * sizeof *cfound);
    int *ccell = malloc(((size_t)nc + 1) * sizeof *ccell);
    cpl_proxies_forward(&pr, 6, rows, buf);
    for (int k = 0; k < nc; k++) {
        memcpy(cx[k], buf + 6 * k, 3 * sizeof(double));
        cr[k] = buf[6 * k + 3]; cvol[k] = buf[6 * k + 4]; ccell[k] = (int)buf[6 * k + 5];
    }
    cpl_voidfraction vf;
    cpl_vf_init(&vf, &slab, model, 0.0);
    vf.partial = size > 1;
    cpl_vf_weigh(&vf, &slab, nc, (const double (*)[3])cx, cr, ccell, cz);
    cpl_proxies_reverse(&pr, 1, cz, norm, n, CPL_PROXY_SUM);
    for (int k = 0; k < nc; k++) cnorm[k] = ccell[k];
    cpl_proxies_reverse(&pr, 1, cnorm, cellmax, n, CPL_PROXY_MAX);
    for (int k = 0; k < nc; k++) cnorm[k] = cz[k] > 0;
    cpl_proxies_reverse(&pr, 1, cnorm, z_copy_count, n, CPL_PROXY_SUM);
    for (int k = 0; k < n; k++) { rows[2 * k] = norm[k]; rows[2 * k + 1] = cellmax[k] >= 0; }
    cpl_proxies_forward(&pr, 2, rows, buf);
    for (int k = 0; k < nc; k++) { cnorm[k] = buf[2 * k]; cfound[k] = buf[2 * k + 1]; }
    cpl_vf_finish(&vf, &slab, cnorm, cfound, cr, cvol);

    /* 1. each slab cell against the whole mesh's cell at its centre */
    double vp_max = 0.0, worst_vp = 0.0;
    for (int c = 0; c < whole.ncells; c++) vp_max = fmax(vp_max, vfw.vp[c]);
    static int global_of[NX * NY * NZ];
    for (int c = 0; c < slab.ncells; c++) {
        global_of[c] = cpl_mesh_locate(&whole, slab.cell_centre[c], -1, NULL);
        worst_vp = fmax(worst_vp, fabs(vf.vp[c] - vfw.vp[global_of[c]]) / vp_max);
    }
    char what[200];
    snprintf(what, sizeof what, "%s: every cell's particle volume as on the whole mesh (relative to the largest)", name);
    const double e_vp = max_rel(worst_vp);
    if (rank == 0) check_below(what, e_vp, 1e-12);

    /* 2. the gather */
    const cpl_cell_weights w = {vf.np, vf.w_start, vf.w_cell, vf.w};
    double *q = malloc((size_t)slab.ncells * sizeof *q);
    for (int c = 0; c < slab.ncells; c++) q[c] = field_at(slab.cell_centre[c]);
    cpl_gather_scalar(&w, q, cz);
    static double gathered[NP];
    cpl_proxies_reverse(&pr, 1, cz, gathered, n, CPL_PROXY_SUM);
    double worst_g = 0.0;
    for (int k = 0; k < n; k++) worst_g = fmax(worst_g, fabs(gathered[k] - gathered_w[mine[k]]) / fabs(gathered_w[mine[k]]));
    snprintf(what, sizeof what, "%s: every particle's gathered field as on the whole mesh", name);
    const double e_g = max_rel(worst_g);
    if (rank == 0) check_below(what, e_g, 1e-12);

    /* 1. the spreading: K_sl and the source */
    for (int k = 0; k < n; k++) {
        const int i = mine[k];
        double *o = rows + 7 * k;
        o[0] = beta[i];
        for (int d = 0; d < 3; d++) { o[1 + d] = fex[i][d]; o[4 + d] = v[i][d]; }
    }
    cpl_proxies_forward(&pr, 7, rows, buf);
    double *cb = malloc(((size_t)nc + 1) * sizeof *cb), (*cf)[3] = malloc(((size_t)nc + 1) * sizeof *cf),
           (*cv)[3] = malloc(((size_t)nc + 1) * sizeof *cv);
    for (int k = 0; k < nc; k++) {
        cb[k] = buf[7 * k];
        for (int d = 0; d < 3; d++) { cf[k][d] = buf[7 * k + 1 + d]; cv[k][d] = buf[7 * k + 4 + d]; }
    }
    const cpl_fluid_forces f = {nc, nc, cb, NULL, cf, NULL};
    double *ksl = malloc((size_t)slab.ncells * sizeof *ksl), (*up)[3] = malloc((size_t)slab.ncells * sizeof *up),
           (*src)[3] = malloc((size_t)slab.ncells * sizeof *src);
    cpl_exchange_cells(&w, &f, (const double (*)[3])cv, slab.ncells, slab.cell_volume, ksl, up, src);
    double kmax = 0.0, smax = 0.0, worst_k = 0.0, worst_s = 0.0;
    for (int c = 0; c < whole.ncells; c++) {
        kmax = fmax(kmax, ksl_w[c]);
        for (int d = 0; d < 3; d++) smax = fmax(smax, fabs(src_w[c][d]));
    }
    for (int c = 0; c < slab.ncells; c++) {
        const int g = global_of[c];
        worst_k = fmax(worst_k, fabs(ksl[c] - ksl_w[g]) / kmax);
        for (int d = 0; d < 3; d++) worst_s = fmax(worst_s, fabs(src[c][d] - src_w[g][d]) / smax);
    }
    snprintf(what, sizeof what, "%s: every cell's K_sl as on the whole mesh", name);
    const double e_k = max_rel(worst_k), e_s = max_rel(worst_s);
    if (rank == 0) check_below(what, e_k, 1e-12);
    snprintf(what, sizeof what, "%s: every cell's force source as on the whole mesh", name);
    if (rank == 0) check_below(what, e_s, 1e-12);

    /* 3. straddlers and bytes */
    int straddling = 0;
    for (int k = 0; k < n; k++) straddling += z_copy_count[k] > 1;
    MPI_Allreduce(MPI_IN_PLACE, &straddling, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
    double sent = pr.bytes_sent, allgather = (double)n * 31 * sizeof(double) * (size - 1);
    MPI_Allreduce(MPI_IN_PLACE, &sent, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    MPI_Allreduce(MPI_IN_PLACE, &allgather, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    if (rank == 0 && size > 1) {
        printf("%s: %d of %d particles have weights on two ranks; the copies moved %.0f B in these moves\n", name,
               straddling, NP, sent);
        if (model == CPL_VF_DIVIDED) {
            snprintf(what, sizeof what, "divided: particles straddle the cuts (%d with weights on two ranks)", straddling);
            check_true(what, straddling > 0);
        }
        /* per fluid step the copies move 31 numbers (these moves 6 + 1 + 1 + 1 + 2 + 1 + 7 = 19):
         * scaled to 31, against an all-gather of every particle's 31 */
        snprintf(what, sizeof what, "%s: the copies' bytes per step below an all-gather's (%.0f vs %.0f B)", name,
                 sent * 31.0 / 19.0, allgather);
        check_true(what, sent * 31.0 / 19.0 < allgather);
    }
    cpl_proxies_free(&pr);
    cpl_vf_free(&vf); cpl_vf_free(&vfw);
    cpl_mesh_free(&slab); cpl_mesh_free(&whole);
    free(buf); free(cx); free(cr); free(cvol); free(cz); free(cnorm); free(cfound); free(ccell);
    free(q); free(q_whole); free(cb); free(cf); free(cv); free(ksl); free(up); free(src);
    free(ksl_w); free(up_w); free(src_w);
}

int main(int argc, char **argv)
{
    MPI_Init(&argc, &argv);
    int rank, size;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    if (NZ % size != 0) {
        if (rank == 0) fprintf(stderr, "test_coupling_parallel: %d ranks do not divide the %d cells along z\n", size, NZ);
        MPI_Finalize();
        return 1;
    }
    run(CPL_VF_DIVIDED, rank, size);
    run(CPL_VF_CENTRE, rank, size);
    return mpi_finish("test_coupling_parallel");
}
