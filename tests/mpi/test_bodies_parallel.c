/* Multisphere bodies decomposed over ranks (issue 23; run under mpirun -np 1, 2 and 4): a body and
 * its spheres belong to the rank whose box holds the body's centre (bodies.h), against the serial
 * run of the same bed.
 *
 * The bed: 256 rods of three spheres (radius 0.4 mm, centres 0.6 mm apart along the rod, union
 * mass), on a lattice in a closed box of 10 mm (six walls; Hertz, tangential history), thrown with
 * +-1 m/s and +-2,000 rad/s of scatter, under gravity: in 1,000 steps of 2 us the rods turn by up
 * to 4 rad and move up to 3.5 mm, so that centres cross the cuts, many spheres lie outside the
 * box of their body's rank, and rods touch across the cuts. Every rank runs the serial bed too
 * (the reductions and messages switched off), then the same bed decomposed.
 *  1. After 1,000 steps every body's centre and every sphere are where the serial run put them,
 *     to 1e-12 m (the only difference allowed is the order of the force sums: round-off), and the
 *     kinetic energy (translation and rotation, seed 004 eq. 8) is the serial one to 1e-9.
 *  2. At every step of 2,000: the bodies summed over the ranks are the 256,
 *     their ids each once, the spheres the 768 each once, each on its body's rank (a sphere whose
 *     body is not on its rank stops the run: bodies.h), the mass of the bodies the serial mass to
 *     1e-12.
 *  3. On 2 and 4 ranks the test means something: bodies changed rank, spheres were held outside
 *     their rank's box, and contacts joined spheres of two ranks.
 * On one rank the same code runs as the serial run: bit for bit. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "comm.h"
#include "dem_mpi.h"
#include "harness.h"
#include "mpi_finish.h"

enum { NX = 4, NY = 8, NZ = 8, NB = NX * NY * NZ, NS = 3 * NB, COMPARE = 1000 };
static const double E = 5e6, NU = 0.3, RHO = 2500, RAD = 4e-4, L = 0.005;

static double uniform(unsigned *state)
{
    *state = *state * 1103515245u + 12345u;
    return ((*state >> 8) & 0xffff) / 65535.0 * 2.0 - 1.0;
}

static void make_bed(dem_system *s)
{
    make_system(s, E, NU, RHO, 0.5, 0.5, normal_hertz, tangential_history, L);
    s->gravity[2] = -9.81;
    s->dt = 2e-6;
    s->nlist.skin = 0.2 * RAD;
    add_plane(s, 0, 0, -L, 0, 0, 1);
    add_plane(s, 0, 0, L, 0, 0, -1);
    add_plane(s, 0, -L, 0, 0, 1, 0);
    add_plane(s, 0, L, 0, 0, -1, 0);
    add_plane(s, -L, 0, 0, 1, 0, 0);
    add_plane(s, L, 0, 0, -1, 0, 0);
    const double x[3][3] = {{-6e-4, 0, 0}, {0, 0, 0}, {6e-4, 0, 0}}, r[3] = {RAD, RAD, RAD};
    const int t = dem_bodies_add_template(&s->bodies, "rod", 3, x, r, 0, RHO, CLUMP_MASS_UNION);
    const double q[4] = {1, 0, 0, 0};
    unsigned seed = 2024;
    for (int i = 0; i < NX; i++)
        for (int j = 0; j < NY; j++)
            for (int k = 0; k < NZ; k++) {
                const double X[3] = {-L + 1.25e-3 + i * 2.5e-3, -L + 0.6e-3 + j * 1.2e-3, -L + 0.6e-3 + k * 1.2e-3};
                const double V[3] = {uniform(&seed), uniform(&seed), uniform(&seed)};
                const double W[3] = {2000 * uniform(&seed), 2000 * uniform(&seed), 2000 * uniform(&seed)};
                dem_bodies_add(s, t, X, q, V, W);
            }
    dem_system_setup(s);
}

/* n values per item of count items, every rank's, on every rank in rank order (malloc'd) */
static double *gather_all(const double *mine, int count, int n, int size, int *total)
{
    int *counts = malloc((size_t)size * sizeof(int)), *displs = malloc((size_t)size * sizeof(int)), m = count * n;
    MPI_Allgather(&m, 1, MPI_INT, counts, 1, MPI_INT, MPI_COMM_WORLD);
    int all = 0;
    for (int r = 0; r < size; r++) { displs[r] = all; all += counts[r]; }
    double *out = malloc((size_t)(all + 1) * sizeof(double));
    MPI_Allgatherv(mine, m, MPI_DOUBLE, out, counts, displs, MPI_DOUBLE, MPI_COMM_WORLD);
    free(counts); free(displs);
    *total = all / n;
    return out;
}

/* Every body's centre by id and every sphere's position by id, gathered from all ranks; returns
 * 1 when each of the NB bodies and NS spheres came once and each sphere sat on its body's rank. */
static int gather_bed(const dem_system *s, int size, double (*body_x)[3], double (*sphere_x)[3])
{
    const dem_bodies *b = &s->bodies;
    double *mine = malloc((size_t)(4 * b->n + 1) * sizeof(double));
    for (int k = 0; k < b->n; k++) {
        mine[4 * k] = (double)b->id[k];
        memcpy(mine + 4 * k + 1, b->x[k], 3 * sizeof(double));
    }
    int nb, ns, valid = 1;
    double *all = gather_all(mine, b->n, 4, size, &nb);
    static int seen_b[NB], seen_s[NS];
    memset(seen_b, 0, sizeof seen_b);
    memset(seen_s, 0, sizeof seen_s);
    valid &= nb == NB;
    for (int k = 0; k < nb; k++) {
        const long id = (long)all[4 * k];
        if (id < 0 || id >= NB || seen_b[id]++) { valid = 0; continue; }
        memcpy(body_x[id], all + 4 * k + 1, 3 * sizeof(double));
    }
    free(all);
    free(mine);
    const dem_particles *p = &s->p;
    mine = malloc((size_t)(4 * p->n + 1) * sizeof(double));
    for (int i = 0; i < p->n; i++) {
        mine[4 * i] = (double)p->id[i];
        memcpy(mine + 4 * i + 1, p->x[i], 3 * sizeof(double));
        valid &= p->body[i] > 0 && dem_body_lookup(b, p->body[i]) >= 0;   /* its body is here */
    }
    all = gather_all(mine, p->n, 4, size, &ns);
    valid &= ns == NS;
    for (int k = 0; k < ns; k++) {
        const long id = (long)all[4 * k];
        if (id < 0 || id >= NS || seen_s[id]++) { valid = 0; continue; }
        memcpy(sphere_x[id], all + 4 * k + 1, 3 * sizeof(double));
    }
    free(all);
    free(mine);
    MPI_Allreduce(MPI_IN_PLACE, &valid, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    return valid;
}

static double body_mass(const dem_system *s)
{
    double m = 0.0;
    for (int k = 0; k < s->bodies.n; k++) m += dem_body_mass(&s->bodies, k);
    MPI_Allreduce(MPI_IN_PLACE, &m, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    return m;
}

static double max_difference(const double (*a)[3], const double (*b)[3], int n)
{
    double d = 0.0;
    for (int i = 0; i < n; i++)
        for (int k = 0; k < 3; k++) d = fmax(d, fabs(a[i][k] - b[i][k]));
    return d;
}

int main(int argc, char **argv)
{
    MPI_Init(&argc, &argv);
    int rank, size;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    static double ser_body[NB][3], ser_sphere[NS][3], par_body[NB][3], par_sphere[NS][3];
    static int owner[NB], owner_before[NB];

    dem_mpi_release();   /* the serial bed: one rank, every reduction the identity */
    dem_system ser;
    make_bed(&ser);
    double serial_mass = 0.0;
    for (int k = 0; k < ser.bodies.n; k++) serial_mass += dem_body_mass(&ser.bodies, k);
    for (int k = 0; k < COMPARE; k++) dem_system_step(&ser);
    for (int k = 0; k < ser.bodies.n; k++) memcpy(ser_body[ser.bodies.id[k]], ser.bodies.x[k], sizeof ser_body[0]);
    for (int i = 0; i < ser.p.n; i++) memcpy(ser_sphere[ser.p.id[i]], ser.p.x[i], sizeof ser_sphere[0]);
    const double serial_energy = dem_system_kinetic_energy(&ser);
    dem_system_free(&ser);

    dem_mpi_use(MPI_COMM_WORLD);
    dem_system par;
    make_bed(&par);
    int conserved = 1, moves = 0, moves_compared = 0;
    long outside = 0, remote_contacts = 0;
    for (int step = 0; step <= 2000; step++) {
        if (step > 0) dem_system_step(&par);
        const int valid = gather_bed(&par, size, par_body, par_sphere);
        const double m = body_mass(&par);
        if (!valid || fabs(m - serial_mass) > 1e-12 * serial_mass) {
            if (conserved && rank == 0)
                printf("step %d: bodies or spheres missing, twice or apart from their body; mass %.15g kg against %.15g\n",
                       step, m, serial_mass);
            conserved = 0;
        }
        for (int k = 0; k < NB; k++) owner[k] = -1;   /* who holds each body now: changes are migrations */
        for (int k = 0; k < par.bodies.n; k++) owner[par.bodies.id[k]] = rank;
        MPI_Allreduce(MPI_IN_PLACE, owner, NB, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
        if (step > 0)
            for (int k = 0; k < NB; k++) moves += owner[k] != owner_before[k];
        memcpy(owner_before, owner, sizeof owner);
        long here[2] = {0, 0};   /* spheres outside this rank's box; touching pairs with another rank's sphere */
        for (int i = 0; i < par.p.n; i++) {
            int in = 1;
            for (int d = 0; d < 3; d++)
                in &= par.p.x[i][d] >= par.decomp.lo[rank][d] && par.p.x[i][d] <= par.decomp.hi[rank][d];
            here[0] += !in;
            for (int k = par.nlist.start[i]; k < par.nlist.start[i + 1]; k++)
                here[1] += par.nlist.touching[k] && par.nlist.partner[k] >= par.p.n;
        }
        MPI_Allreduce(MPI_IN_PLACE, here, 2, MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
        outside += here[0];
        remote_contacts += here[1];
        if (step == COMPARE) {
            moves_compared = moves;
            double e = dem_system_kinetic_energy(&par);
            MPI_Allreduce(MPI_IN_PLACE, &e, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
            const double db = max_difference((const double (*)[3])par_body, (const double (*)[3])ser_body, NB);
            const double ds = max_difference((const double (*)[3])par_sphere, (const double (*)[3])ser_sphere, NS);
            if (rank == 0) {
                char what[240];
                snprintf(what, sizeof what, "%d ranks, %d steps: every body's centre and every sphere where the serial "
                         "run put them (largest difference %.3g m, %.3g m; 1e-12 m allowed)", size, COMPARE, db, ds);
                check_true(what, valid && db <= 1e-12 && ds <= 1e-12);
                check_rel("kinetic energy then against the serial run's [J]", e, serial_energy, 1e-9);
            }
        }
    }
    if (rank == 0) {
        char what[240];
        snprintf(what, sizeof what, "%d ranks, 2,000 steps: 256 bodies and 768 spheres each once, each sphere with its "
                 "body, the bodies' mass exact to 1e-12 at every step", size);
        check_true(what, conserved);
        if (size > 1) {
            snprintf(what, sizeof what, "bodies changed rank: %d times in the first %d steps, %d in all", moves_compared, COMPARE, moves);
            check_true(what, moves_compared > 0);
            snprintf(what, sizeof what, "spheres held outside their rank's box: %ld summed over the steps", outside);
            check_true(what, outside > 0);
            snprintf(what, sizeof what, "contacts with ghosts (other ranks' spheres): %ld summed over the steps",
                     remote_contacts);
            check_true(what, remote_contacts > 0);
        }
        printf("bytes sent to other ranks by rank 0: %.0f\n", dem_comm_bytes_sent());
    }
    dem_system_free(&par);
    return mpi_finish("test_bodies_parallel");
}
