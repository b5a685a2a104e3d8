/* demRun <caseDir> [-restart] [-phases n1,n2,...]
 * Standalone DEM run of <caseDir>/constant/demProperties; particles go to
 * <caseDir>/particles.h5 (+ .xdmf for ParaView). With -phases the run is a benchmark: it takes
 * the given step counts one after another and prints particle-steps per second for each.
 *
 * Under mpirun (mpirun -np N demRun <caseDir>) the DEM is decomposed over the N ranks (issue 23):
 * every rank reads the case and inserts every particle, keeps the ones its box owns, and they write
 * one particles.h5 together; rank 0 prints, and an error on any rank ends them all. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "case.h"
#include "comm.h"
#include "dem_mpi.h"
#include "reduce.h"
#include "error.h"
#include "io.h"
#include "restart.h"
#include "system.h"
#include "timestep.h"

static double wall_clock(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* CPU time of this process [s]: beside the wall time, since these machines are shared */
static double cpu_clock(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* Sums over the ranks (the identity serially): what the log reports is the whole system's. */
static double sum_ranks(double v)
{
    dem_reduce_doubles(&v, 1, DEM_REDUCE_SUM);
    return v;
}

/* Started by mpirun (Open MPI's or a PMI launcher's variables): MPI is started and the DEM uses it.
 * A plain `demRun case` makes no MPI call (no singleton start-up). */
static int start_mpi(int *argc, char ***argv)
{
    if (!getenv("OMPI_COMM_WORLD_SIZE") && !getenv("PMIX_RANK") && !getenv("PMI_RANK")) return 0;
    MPI_Init(argc, argv);
    dem_mpi_use(MPI_COMM_WORLD);
    dem_mpi_set_fatal_abort();
    if (dem_comm_rank() != 0 && !freopen("/dev/null", "w", stdout)) return 1;   /* rank 0 prints */
    return 1;
}

/* The bytes each rank sent per step (halo and migration), against what CFDEMcoupling's twoWayMPI
 * way would move: every particle's position, velocity and spin to every rank each step (`all`:
 * the mean particle count over the steps). */
static void report_exchange(const dem_system *s, long steps, double all)
{
    const int size = dem_comm_size();
    double sent[2] = {dem_comm_bytes_sent(), dem_comm_bytes_sent()};
    dem_reduce_doubles(&sent[0], 1, DEM_REDUCE_SUM);
    dem_reduce_doubles(&sent[1], 1, DEM_REDUCE_MAX);
    const double per_step = steps > 0 ? sent[0] / size / steps : 0.0, most = steps > 0 ? sent[1] / steps : 0.0;
    const double allgather = all * (double)dem_particles_role_size(PF_FORWARD) * (size - 1) / size;
    printf("decomposition: cut again %ld times as the load moved (each time the busiest rank had > %.2f x the "
           "mean compute time)\n", s->rebalances, DEM_REBALANCE_ABOVE);
    printf("exchange on %d ranks: %.4g bytes sent per rank per step (mean; the most %.4g), against %.4g for an "
           "all-gather of every particle's position, velocity and spin (%.1f%% of it)\n",
           size, per_step, most, allgather, allgather > 0 ? 100.0 * per_step / allgather : 0.0);
    const dem_ghost_list *g = &s->ghosts;
    double halo[2] = {(double)(g->n - g->recv_count[dem_comm_rank()]), (double)s->p.n};   /* ghosts from others, own */
    dem_reduce_doubles(halo, 2, DEM_REDUCE_SUM);
    printf("halo at the end: %.4g ghosts from other ranks per rank (mean), %.3f of a rank's particles\n", halo[0] / size,
           halo[1] > 0 ? halo[0] / halo[1] : 0.0);
}

static void usage(void)
{
    fprintf(stderr, "usage: demRun <caseDir> [-restart] [-phases n1,n2,...]\n");
    exit(2);
}

static long last_written_step = -1;

static void write_snapshot(dem_particle_writer *w, dem_system *s)
{
    if (s->step == last_written_step) return;
    dem_contact_state cs;
    dem_restart_save_contacts(s, &cs);
    dem_io_write_snapshot_contacts(w, &s->p, s->time, s->step, &cs);
    dem_contact_state_free(&cs);
    last_written_step = s->step;
    dem_lifecycle_log(s);   /* the mass balance, the outlets and streams, at every write */
}

/* Run nsteps, writing snapshots every write_every steps (0: none) and progress lines; returns
 * the particle-steps (the particle count may change from step to step: streams, outlets). */
static double run_steps(dem_system *s, long nsteps, long write_every, dem_particle_writer *w,
                        double progress_interval)
{
    const double start = wall_clock();
    double next_report = start + progress_interval, particle_steps = 0.0;
    /* this rank's particle-steps, summed over the ranks at the end; the progress lines (rank 0's
     * clock decides when, so no rank waits for them) give the count of every rank as it was at
     * the start or the last snapshot, where the ranks meet anyway */
    const int parallel = dem_comm_size() > 1;
    double all_particles = sum_ranks(s->p.n);
    for (long k = 1; k <= nsteps; k++) {
        dem_system_step(s);
        particle_steps += s->p.n;
        if (write_every > 0 && s->step % write_every == 0) {
            write_snapshot(w, s);
            dem_system_relist(s);   /* as a restart from this snapshot will: the two runs stay equal */
            all_particles = sum_ranks(s->p.n);
        }
        if (progress_interval > 0 && (k & 63) == 0) {
            const double now = wall_clock();
            if (now >= next_report) {
                const double rate = (parallel ? all_particles * k : particle_steps) / (now - start);
                const double eta = (double)(nsteps - k) * (now - start) / (double)k;
                printf("step %ld  t = %.6g s  %5.1f %%  %.0f particles  %.3g particle-steps/s  "
                       "ETA %.0f s\n", s->step, s->time, 100.0 * k / nsteps, parallel ? all_particles : s->p.n, rate, eta);
                fflush(stdout);
                next_report = now + progress_interval;
            }
        }
    }
    return sum_ranks(particle_steps);
}

int main(int argc, char **argv)
{
    const int mpi = start_mpi(&argc, &argv);
    if (argc < 2) usage();
    const char *case_dir = argv[1];
    int restart = 0;
    const char *phases = NULL;
    for (int a = 2; a < argc; a++) {
        if (strcmp(argv[a], "-restart") == 0) restart = 1;
        else if (strcmp(argv[a], "-phases") == 0 && a + 1 < argc) phases = argv[++a];
        else usage();
    }
    setvbuf(stdout, NULL, _IOLBF, 0);

    dem_system s;
    dem_system_init(&s);
    dem_run_settings rs;
    dem_case_read(case_dir, &s, &rs, restart);
    /* benchmarks (bench/unused_model.sh): the generic force kernels, every model's code present
     * and dispatched per contact, in place of the case's specialised kernel */
    const char *generic = getenv("DEM_GENERIC_KERNELS");
    if (generic && *generic && strcmp(generic, "0") != 0) {
        if (strcmp(generic, "1") != 0) {
            fprintf(stderr, "demRun: error: environment variable DEM_GENERIC_KERNELS is '%s'; it must be 0 or 1\n", generic);
            return 2;
        }
        s.generic_kernels = 1;
        printf("DEM_GENERIC_KERNELS=1: the generic force kernels (every model dispatched per contact)\n");
    }

    char base[4200];
    snprintf(base, sizeof base, "%s/particles", case_dir);
    dem_contact_state saved;
    memset(&saved, 0, sizeof saved);
    if (restart) {
        if (dem_restart_read(&s, base, NAN, 0.0, &saved) != 0)
            dem_fatal("%s.h5: no complete snapshot to restart from", base);
        printf("restart from %s.h5 at t = %g s (step %ld), %d particles\n", base, s.time, s.step, s.p.n);   /* all: not yet decomposed */
    }
    const double vmax = rs.max_expected_velocity > 0 ? rs.max_expected_velocity : dem_case_default_max_velocity(&s);
    dem_timestep_check(&s, vmax, rs.timestep_override, rs.timestep_source);
    dem_restart_setup(&s, restart ? &saved : NULL);
    dem_contact_state_free(&saved);

    dem_particle_writer *w = dem_io_open_writer(base, restart);
    if (restart) last_written_step = s.step;
    else write_snapshot(w, &s);

    const double t0 = wall_clock();
    long total_steps = 0;
    double particle_steps = 0.0;
    if (phases) {
        int k = 0;
        for (const char *c = phases; *c;) {
            char *end;
            const long n = strtol(c, &end, 10);
            if (end == c || n < 0) usage();
            const double start = wall_clock(), cpu_start = cpu_clock();
            const double ps = run_steps(&s, n, 0, w, rs.progress_interval);
            particle_steps += ps;
            const double secs = wall_clock() - start, cpu = cpu_clock() - cpu_start;
            printf("PHASE %d steps=%ld particles=%.0f wall_s=%.3f particle_steps_per_s=%.4g cpu_s=%.3f\n", k++, n,
                   sum_ranks(s.p.n), secs, secs > 0 ? ps / secs : 0.0, cpu);
            total_steps += n;
            c = *end == ',' ? end + 1 : end;
        }
    } else {
        const long nsteps = (long)llround((rs.end_time - s.time) / s.dt);
        /* a writeInterval longer than the run: the final state only (in double: 1e9 / 1e-12 is no long) */
        const double per_write = rs.write_interval / s.dt;
        const long write_every = rs.write_interval > 0 && per_write < (double)nsteps ? (long)fmax(1.0, llround(per_write)) : 0;
        printf("running %ld steps of %g s to t = %g s, %.0f particles%s\n", nsteps, s.dt, rs.end_time, sum_ranks(s.p.n),
               mpi ? " (decomposed)" : "");
        if (dem_comm_size() > 1) printf("on %d ranks: rank 0 holds %d particles\n", dem_comm_size(), s.p.n);
        particle_steps = run_steps(&s, nsteps, write_every, w, rs.progress_interval);
        total_steps = nsteps;
    }
    dem_system_check_health(&s);
    write_snapshot(w, &s);
    dem_io_close_writer(w);
    const double secs = wall_clock() - t0;
    const double energy = sum_ranks(dem_system_kinetic_energy(&s)), all = sum_ranks(s.p.n);
    printf("done: t = %g s, %ld steps in %.2f s wall (%.3g particle-steps/s), %ld neighbour "
           "builds, %ld sorts, kinetic energy %.6g J\n",
           s.time, total_steps, secs, secs > 0 ? particle_steps / secs : 0.0,
           s.nlist.builds, s.nlist.sorts, energy);
    int prescribed_here = 0;
    for (int i = 0; i < s.p.n; i++) prescribed_here += s.p.prescribed[i] != 0;
    const double prescribed = sum_ranks(prescribed_here);
    if (prescribed > 0)
        printf("kinetic energy: the %.0f prescribed particles (driven at their set velocity) left out\n", prescribed);
    printf("neighbour list: %.2f pairs per particle (skin %g m)\n", all > 0 ? sum_ranks((double)s.nlist.npairs) / all : 0.0,
           s.nlist.skin);
    if (dem_comm_size() > 1) report_exchange(&s, total_steps, total_steps > 0 ? particle_steps / total_steps : all);
    const double bodies = s.bodies.ntemplates ? sum_ranks(s.bodies.n) : 0.0;
    const double e_rot = s.bodies.ntemplates ? sum_ranks(dem_bodies_rotational_energy(&s)) : 0.0;
    if (bodies > 0)   /* each body's is in the snapshots */
        printf("multisphere: %.0f bodies, rotational kinetic energy %.6g J (seed 004 eq. 8, summed over the bodies)\n",
               bodies, e_rot);
    dem_stage_report(&s, total_steps);
    dem_system_free(&s);
    if (mpi) {
        dem_mpi_release();
        MPI_Finalize();
    }
    return 0;
}
