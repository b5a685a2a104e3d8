/* The coupling session (coupling.h): the DEM system, the fluid mesh, the void fraction, the
 * fluid forces on the particles and the fields handed to the fluid.
 *
 * Order within coupling_evolve (the fluid has just solved U, p of the last step):
 *   1. the new field: gather u_f (and model A's grad p) at the particles, whose positions are
 *      unchanged since the last void-fraction update; the drag coefficient beta and the
 *      exchanged velocity-independent force (model B's buoyancy, explicit drag) stay as the
 *      fluid received them at the end of the last step (3), so that the particles feel
 *      beta (u_f - v) with the same beta the fluid's K_sl holds. (Evaluating beta again with
 *      the new slip made the particles feel more than the fluid received: the drag law grows
 *      with the slip, and the step-to-step jitter of the centre void fraction's gas velocity
 *      then biased the product; 2.5 % of the bed's weight in the full fluidisedBed.) The first
 *      step of a run, or a run continued from a snapshot without them, evaluates everything.
 *   2. couplingInterval DEM steps, each with the fluid force at the particle's current velocity
 *      (implicit: beta (u_f - v); explicit: frozen), held in p->f_ext;
 *   3. void fraction with the new positions; gather, evaluate the forces with the same weights
 *      and the particles' velocities, and spread them onto the cells (exchange.h): the fluid
 *      solves with these beta and forces, and the particles feel them in the next step. What
 *      the fluid receives, sum beta (v - u_f) - f, differs from the particles' mean force over
 *      the next step only by sum beta (v - <v>), v's change within the step.
 * What a particle keeps across DEM steps (its fluid cell, beta, u_f and the velocity-independent
 * forces) lives in the particle table (particles.h), so that it follows the DEM's sorting; the
 * per-particle arrays here are rebuilt at each exchange, in the current order. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "case.h"
#include "comm.h"
#include "coupling.h"
#include "dict.h"
#include "number.h"
#include "error.h"
#include "exchange.h"
#include "interpolate.h"
#include "io.h"
#include "particle_forces.h"
#include "proxies.h"
#include "reduce.h"
#include "restart.h"
#include "system.h"
#include "timestep.h"
#include "voidfraction.h"

/* The coupling's stages, timed for the end-of-run report (coupling_report_timings). */
#define CPL_STAGES(X)                                                                            \
    X(VOIDFRACTION, "void fraction (particle volumes onto cells)")                              \
    X(INTERPOLATION, "interpolation (fluid fields at the particles)")                           \
    X(DRAG, "drag and fluid forces (the law per particle)")                                     \
    X(EXCHANGE, "exchange (forces to the DEM, sources to the cells)")                           \
    X(OUTPUT, "output (snapshots, postProcessing/particles.dat)")
#define CPL_STAGE_ID(N, TEXT) CPL_STAGE_##N,
enum { CPL_STAGES(CPL_STAGE_ID) CPL_STAGE_COUNT, CPL_STAGE_DEM = -1 };
#undef CPL_STAGE_ID
#define CPL_STAGE_TEXT(N, TEXT) TEXT,
static const char *const cpl_stage_names[CPL_STAGE_COUNT] = {CPL_STAGES(CPL_STAGE_TEXT)};
#undef CPL_STAGE_TEXT

#define CPL_ROW_DOUBLES 31   /* doubles moved per particle copy and fluid step (update_void_fraction,
                                evaluate_forces twice, spread_forces) */

struct coupling {
    char case_dir[4096];
    dem_system s;
    dem_run_settings rs;
    cpl_mesh mesh;
    cpl_voidfraction vf;
    enum cpl_interp_scheme interp_scheme;
    cpl_interp interp;             /* U and grad p as one 6-component field: one search per particle */
    double (*ugp)[6];              /* [ncells] U, grad p for the interpolation; [copies] at the particles */
    double (*ugp_p)[6];
    cpl_interp_tet *tets;          /* cellPoint: each copy's tetrahedron */
    /* The particles' copies on this rank's cells (proxies.h): serially one per particle, in the
     * DEM's order. The void fraction, the gather and the spreading work on the copies; the
     * forces are evaluated on the owner. */
    cpl_proxies pr;
    int copy_cap;
    double (*copy_x)[3], *copy_r, *copy_volume;
    int *copy_cell;                /* the cell of the copy's centre among this rank's (-1: not here) */
    double *copy_z, *copy_norm, *copy_found;
    double *copy_alpha, (*copy_u)[3], (*copy_gp)[3];   /* each copy's share of alpha, U, grad p */
    double *copy_beta, (*copy_f)[3], (*copy_v)[3];
    double *copy_buf, *particle_buf;   /* the moves' rows: [copies][8], [particles][8] */
    double *reach;                 /* [particles] how far from its centre a particle's volume may fall [m] */
    long fluid_steps;
    double allgather_bytes;        /* what an all-gather of every particle's rows would have sent [B] */
    int tets_valid, field_set;
    long tets_generation, vf_generation;   /* the particles' generation (particles.h) they were made for */
    cpl_force_params params;
    cpl_fluid_forces forces;
    int interval;
    /* per particle (current DEM order), rebuilt each exchange */
    int np_cap;
    double *d, *volume, *alpha_p;
    double (*u_p)[3], (*gp_p)[3];
    /* per cell */
    double *ksl;
    double (*up)[3], (*source)[3];
    dem_particle_writer *writer;
    FILE *means;
    double dem_seconds;            /* wall time in the DEM's steps and list remakes [s] */
    double stage_seconds[CPL_STAGE_COUNT];   /* the coupling's own wall time per stage [s] */
    long dem_steps;               /* taken in this run */
    long outside_reported;
    int restarted;                /* continued from a particle snapshot at t_start > 0 */
    int exchanged;                /* p->beta, p->f_fluid hold what the fluid received (step 3) */
    double wall_force[3];         /* the walls' force on the particles, mean over the last
                                     fluid step's DEM steps [N] */
    double fluid_force[3];        /* the fluid's force on the particles, the same mean [N] */
    double (*each_wall)[3];       /* each wall's force on the particles, the same mean [N] */
};

/* c->stage_seconds[stage] (or, for CPL_STAGE_DEM, c->dem_seconds) += the time since *t; *t = now */
static void lap(coupling *c, int stage, double *t)
{
    const double now = dem_clock();
    if (stage == CPL_STAGE_DEM) c->dem_seconds += now - *t;
    else c->stage_seconds[stage] += now - *t;
    *t = now;
}

static void read_coupling_properties(coupling *c, double dt_f, double *alpha_min, enum cpl_vf_model *vf_model,
                                     double *kernel_width, double *kernel_cutoff)
{
    char path[4200];
    snprintf(path, sizeof path, "%s/constant/couplingProperties", c->case_dir);
    dem_dict *d = dem_dict_read(path);
    c->interval = (int)dem_dict_label(d, "couplingInterval", 1, 1000000);
    const double dt_dem = c->s.dt;
    if (fabs(dt_f - c->interval * dt_dem) > 1e-9 * dt_f)
        dem_dict_fatal(d, "couplingInterval", "the fluid time step (system/controlDict deltaT %g s) must equal "
                   "couplingInterval x the DEM timeStep (%d x %g s = %g s)", dt_f, c->interval, dt_dem,
                   c->interval * dt_dem);
    const dem_dict *v = dem_dict_sub(d, "voidFraction");
    static const char *const vf_names[] = {"centre", "divided", "gaussian", 0};
    *vf_model = (enum cpl_vf_model)dem_dict_choice(v, "model", vf_names);
    *alpha_min = dem_dict_scalar_opt(v, "alphaMin", 0.3, 0.01, 0.99);
    *kernel_width = *vf_model == CPL_VF_GAUSSIAN ? dem_dict_scalar_opt(v, "kernelWidth", 0.5, 0.05, 20.0) : 0.0;
    *kernel_cutoff = *vf_model == CPL_VF_GAUSSIAN ? dem_dict_scalar_opt(v, "kernelCutoff", 3.0, 1.0, 10.0) : 0.0;
    c->params.drag = (enum cpl_drag_law)dem_dict_choice(d, "drag", cpl_drag_law_names);
    c->params.model = (enum cpl_model_type)dem_dict_choice(d, "momentumCoupling", cpl_model_type_names);
    c->params.exchange = (enum cpl_exchange_mode)dem_dict_choice_opt(d, "exchange", cpl_exchange_mode_names,
                                                                 CPL_EXCHANGE_IMPLICIT);
    static const char *const interp_names[] = {"cell", "cellLinear", "cellPoint", 0};
    static const enum cpl_interp_scheme schemes[] = {CPL_INTERP_CELL, CPL_INTERP_LINEAR, CPL_INTERP_CELL_POINT};
    c->interp_scheme = schemes[dem_dict_choice_opt(d, "interpolation", interp_names, 0)];
    dem_dict_check_unused(d);
    dem_dict_free(d);
}

static const char *interp_names_of(enum cpl_interp_scheme s)
{
    return s == CPL_INTERP_CELL ? "cell" : s == CPL_INTERP_LINEAR ? "cellLinear" : "cellPoint";
}

static void grow_particles(coupling *c, int n)
{
    if (n <= c->np_cap) return;
    c->np_cap = n + n / 2 + 16;
    c->d = dem_realloc(c->d, (size_t)c->np_cap * sizeof *c->d);
    c->reach = dem_realloc(c->reach, (size_t)c->np_cap * sizeof *c->reach);
    c->particle_buf = dem_realloc(c->particle_buf, (size_t)c->np_cap * 8 * sizeof *c->particle_buf);
    c->volume = dem_realloc(c->volume, (size_t)c->np_cap * sizeof *c->volume);
    c->alpha_p = dem_realloc(c->alpha_p, (size_t)c->np_cap * sizeof *c->alpha_p);
    c->u_p = dem_realloc(c->u_p, (size_t)c->np_cap * sizeof *c->u_p);
    c->gp_p = dem_realloc(c->gp_p, (size_t)c->np_cap * sizeof *c->gp_p);
}

/* room for n copies on this rank */
static void grow_copies(coupling *c, int n)
{
    if (n <= c->copy_cap) return;
    c->copy_cap = n + n / 2 + 16;
    const size_t cap = (size_t)c->copy_cap;
    c->copy_x = dem_realloc(c->copy_x, cap * sizeof *c->copy_x);
    c->copy_r = dem_realloc(c->copy_r, cap * sizeof *c->copy_r);
    c->copy_volume = dem_realloc(c->copy_volume, cap * sizeof *c->copy_volume);
    c->copy_cell = dem_realloc(c->copy_cell, cap * sizeof *c->copy_cell);
    c->copy_z = dem_realloc(c->copy_z, cap * sizeof *c->copy_z);
    c->copy_norm = dem_realloc(c->copy_norm, cap * sizeof *c->copy_norm);
    c->copy_found = dem_realloc(c->copy_found, cap * sizeof *c->copy_found);
    c->copy_beta = dem_realloc(c->copy_beta, cap * sizeof *c->copy_beta);
    c->copy_alpha = dem_realloc(c->copy_alpha, cap * sizeof *c->copy_alpha);
    c->copy_u = dem_realloc(c->copy_u, cap * sizeof *c->copy_u);
    c->copy_gp = dem_realloc(c->copy_gp, cap * sizeof *c->copy_gp);
    c->copy_f = dem_realloc(c->copy_f, cap * sizeof *c->copy_f);
    c->copy_v = dem_realloc(c->copy_v, cap * sizeof *c->copy_v);
    c->copy_buf = dem_realloc(c->copy_buf, cap * 8 * sizeof *c->copy_buf);
    if (c->interp_scheme != CPL_INTERP_CELL) c->ugp_p = dem_realloc(c->ugp_p, cap * sizeof *c->ugp_p);
    if (c->interp_scheme == CPL_INTERP_CELL_POINT) {
        c->tets = dem_realloc(c->tets, cap * sizeof *c->tets);
        for (size_t i = 0; i < cap; i++) c->tets[i].cell = -1;
    }
    c->tets_valid = 0;
}

static cpl_cell_weights weights_of(const coupling *c)
{
    cpl_cell_weights w = {c->vf.np, c->vf.w_start, c->vf.w_cell, c->vf.w};
    return w;
}

static long global_count(long n)
{
    int64_t v = n;
    dem_reduce_int64s(&v, 1, DEM_REDUCE_SUM);
    return (long)v;
}

/* Void fraction with the particles' current positions: each particle copied to the ranks whose
 * cells its volume may reach (proxies.h), weighed there (each particle's last cell as the walk's
 * start), the weights normalised by their sum over the ranks, and the volumes mapped. */
static void particle_volumes(coupling *c)
{
    for (int i = 0; i < c->s.p.n; i++) c->volume[i] = dem_particle_volume(&c->s, i);
}

static void update_void_fraction(coupling *c)
{
    double t = dem_clock();
    dem_particles *p = &c->s.p;
    const int np = p->n;
    grow_particles(c, np);
    particle_volumes(c);
    double *row = c->particle_buf;
    for (int i = 0; i < np; i++) {
        c->reach[i] = c->vf.model == CPL_VF_CENTRE ? 0.0 : p->radius[i];
        double *o = row + (size_t)i * 6;
        for (int q = 0; q < 3; q++) o[q] = p->x[i][q];
        o[3] = p->radius[i];
        o[4] = c->volume[i];
        o[5] = p->fluid_cell[i];
    }
    cpl_proxies_place(&c->pr, np, (const double (*)[3])p->x, c->reach);
    const int n = c->pr.n;
    grow_copies(c, n);
    cpl_proxies_forward(&c->pr, 6, row, c->copy_buf);
    for (int k = 0; k < n; k++) {
        const double *o = c->copy_buf + (size_t)k * 6;
        for (int q = 0; q < 3; q++) c->copy_x[k][q] = o[q];
        c->copy_r[k] = o[3];
        c->copy_volume[k] = o[4];
        c->copy_cell[k] = (int)o[5];
    }
    cpl_vf_weigh(&c->vf, &c->mesh, n, (const double (*)[3])c->copy_x, c->copy_r, c->copy_cell, c->copy_z);
    /* the owner: the sum of the weights over the ranks, and the cell of the centre (-1: none) */
    double *norm = c->d, *cell = c->alpha_p;   /* scratch until evaluate_forces */
    cpl_proxies_reverse(&c->pr, 1, c->copy_z, norm, np, CPL_PROXY_SUM);
    for (int k = 0; k < n; k++) c->copy_norm[k] = c->copy_cell[k];
    cpl_proxies_reverse(&c->pr, 1, c->copy_norm, cell, np, CPL_PROXY_MAX);
    long outside = 0;
    for (int i = 0; i < np; i++) {
        p->fluid_cell[i] = (int)cell[i];
        outside += cell[i] < 0;
        row[2 * i] = norm[i];
        row[2 * i + 1] = cell[i] >= 0;
    }
    cpl_proxies_forward(&c->pr, 2, row, c->copy_buf);
    for (int k = 0; k < n; k++) {
        c->copy_norm[k] = c->copy_buf[2 * k];
        c->copy_found[k] = c->copy_buf[2 * k + 1];
    }
    cpl_vf_finish(&c->vf, &c->mesh, c->copy_norm, c->copy_found, c->copy_r, c->copy_volume);
    c->tets_valid = 0;
    c->vf_generation = p->generation;
    outside = c->pr.size > 1 ? global_count(outside) : outside;
    if (outside > 0 && outside != c->outside_reported) {
        dem_warning("coupling: %ld particle(s) lie outside the fluid mesh at t = %g s; they feel no fluid "
                    "force and give none to the fluid", outside, c->s.time);
        c->outside_reported = outside;
    }
    lap(c, CPL_STAGE_VOIDFRACTION, &t);
}

/* Fluid quantities at the particles and their forces, for the current weights and velocities.
 * new_field: U, grad p changed since the last call (else the interpolation's field is kept);
 * new_positions: the particles moved (else cellPoint keeps each particle's tetrahedron). The
 * exchange evaluates twice per fluid step: a new field at unmoved particles, then moved
 * particles in the same field. */
static void evaluate_forces(coupling *c, const double (*U)[3], const double (*grad_p)[3], int new_field,
                            int new_positions)
{
    dem_particles *p = &c->s.p;
    if (c->vf_generation != p->generation) update_void_fraction(c);   /* particles came or went since */
    double t = dem_clock();
    /* on this rank's cells, per copy: its share of alpha, U and grad p (cell: with the void
     * fraction's weights; the other schemes at the centre, by the rank that holds it) */
    const int n = c->pr.n;
    double *out = c->copy_buf;
    const cpl_cell_weights w = weights_of(c);
    cpl_gather_scalar(&w, c->vf.alpha, c->copy_alpha);
    if (c->interp_scheme == CPL_INTERP_CELL) {   /* the spreading weights: exact balance */
        cpl_gather_vector(&w, U, c->copy_u);
        cpl_gather_vector(&w, grad_p, c->copy_gp);
    } else {
        if (new_field || !c->field_set) {
            for (int k = 0; k < c->mesh.ncells; k++)
                for (int q = 0; q < 3; q++) { c->ugp[k][q] = U[k][q]; c->ugp[k][3 + q] = grad_p[k][q]; }
            cpl_interp_set_field(&c->interp, &c->mesh, &c->ugp[0][0]);
            c->field_set = 1;
        }
        if (c->interp_scheme == CPL_INTERP_CELL_POINT) {
            if (new_positions || !c->tets_valid || c->tets_generation != p->generation)
                cpl_interp_locate(&c->interp, &c->mesh, n, c->copy_cell, (const double (*)[3])c->copy_x, c->tets);
            c->tets_valid = 1;
            c->tets_generation = p->generation;
            cpl_interp_apply(&c->interp, &c->mesh, n, c->tets, &c->ugp_p[0][0]);
        } else {
            cpl_interp_particles(&c->interp, &c->mesh, n, c->copy_cell, (const double (*)[3])c->copy_x, &c->ugp_p[0][0]);
        }
        for (int k = 0; k < n; k++)
            for (int q = 0; q < 3; q++) { c->copy_u[k][q] = c->ugp_p[k][q]; c->copy_gp[k][q] = c->ugp_p[k][3 + q]; }
    }
    for (int k = 0; k < n; k++) {
        double *o = out + (size_t)k * 7;
        o[0] = c->copy_alpha[k];
        for (int q = 0; q < 3; q++) { o[1 + q] = c->copy_u[k][q]; o[4 + q] = c->copy_gp[k][q]; }
    }
    double *row = c->particle_buf;
    cpl_proxies_reverse(&c->pr, 7, out, row, p->n, CPL_PROXY_SUM);
    for (int i = 0; i < p->n; i++) {
        const double *o = row + (size_t)i * 7;
        c->alpha_p[i] = o[0];
        for (int q = 0; q < 3; q++) { c->u_p[i][q] = o[1 + q]; c->gp_p[i][q] = o[4 + q]; }
    }
    lap(c, CPL_STAGE_INTERPOLATION, &t);
    for (int i = 0; i < p->n; i++) c->d[i] = 2.0 * p->radius[i];
    particle_volumes(c);   /* a body's spheres share its volume (bodies.h) */
    const cpl_particle_fluid in = {p->n, (const double (*)[3])p->v, c->d, c->volume,
                                   (const double (*)[3])c->u_p, (const double (*)[3])c->gp_p, c->alpha_p, p->fluid_cell};
    cpl_fluid_forces_eval(&c->params, &in, &c->forces);
    lap(c, CPL_STAGE_DRAG, &t);
}

/* Into the particle table (which follows the DEM's sorting): the field's parts (u_f, model A's
 * -V_p grad p) and, with exchanged_too, the parts the fluid receives (beta, f_exchange). */
static void store_forces(coupling *c, int exchanged_too)
{
    dem_particles *p = &c->s.p;
    for (int i = 0; i < p->n; i++) {
        if (exchanged_too) p->beta[i] = c->forces.beta[i];
        for (int q = 0; q < 3; q++) {
            p->u_fluid[i][q] = c->forces.u_f[i][q];
            p->f_pgrad[i][q] = c->forces.f_equation[i][q];
            if (exchanged_too) p->f_fluid[i][q] = c->forces.f_exchange[i][q];
        }
    }
}

/* The forces the fluid receives, from the owners to the copies, spread onto this rank's cells
 * (exchange.h) with the void fraction's weights. */
static void spread_forces(coupling *c)
{
    const dem_particles *p = &c->s.p;
    double *row = c->particle_buf;
    for (int i = 0; i < p->n; i++) {
        double *o = row + (size_t)i * 7;
        o[0] = c->forces.beta[i];
        for (int q = 0; q < 3; q++) { o[1 + q] = c->forces.f_exchange[i][q]; o[4 + q] = p->v[i][q]; }
    }
    cpl_proxies_forward(&c->pr, 7, row, c->copy_buf);
    const int n = c->pr.n;
    for (int k = 0; k < n; k++) {
        const double *o = c->copy_buf + (size_t)k * 7;
        c->copy_beta[k] = o[0];
        for (int q = 0; q < 3; q++) { c->copy_f[k][q] = o[1 + q]; c->copy_v[k][q] = o[4 + q]; }
    }
    const cpl_fluid_forces at_copies = {n, n, c->copy_beta, NULL, c->copy_f, NULL};
    const cpl_cell_weights w = weights_of(c);
    cpl_exchange_cells(&w, &at_copies, (const double (*)[3])c->copy_v, c->mesh.ncells, c->mesh.cell_volume, c->ksl,
                       c->up, c->source);
}

/* p->f_ext = the fluid force at each particle's current velocity (as cpl_fluid_force, from the
 * particle table: the DEM may have re-sorted the particles since the evaluation). */
static void apply_fluid_forces(coupling *c)
{
    dem_particles *p = &c->s.p;
    for (int i = 0; i < p->n; i++) {
        const double b = p->beta[i];
        for (int q = 0; q < 3; q++)
            p->f_ext[i][q] = b * (p->u_fluid[i][q] - p->v[i][q]) + p->f_fluid[i][q] + p->f_pgrad[i][q];
    }
}

/* sum += the fluid's force on all particles in this DEM step (f_ext as the step used it) */
static void add_fluid_force(const coupling *c, double sum[3])
{
    const dem_particles *p = &c->s.p;
    double f[3] = {0.0, 0.0, 0.0};
    for (int i = 0; i < p->n; i++)
        for (int q = 0; q < 3; q++) f[q] += p->f_ext[i][q];
    for (int q = 0; q < 3; q++) sum[q] += f[q];
}

static void write_means(coupling *c)
{
    double v[3], x[3];
    coupling_particle_means(c, v, x);   /* every rank: sums over the ranks */
    const long np = coupling_particle_count(c);
    if (!c->means) return;              /* rank 0 writes */
    const double *fw = c->wall_force, *ff = c->fluid_force;
    fprintf(c->means, "%.9g %ld %.9g %.9g %.9g %.9g %.9g %.9g %.9g %.9g %.9g %.9g %.9g %.9g", c->s.time, np,
            x[0], x[1], x[2], v[0], v[1], v[2], fw[0], fw[1], fw[2], ff[0], ff[1], ff[2]);
    for (int w = 0; w < c->s.nwalls; w++)
        fprintf(c->means, " %.9g %.9g %.9g", c->each_wall[w][0], c->each_wall[w][1], c->each_wall[w][2]);
    fputc('\n', c->means);
    fflush(c->means);
}

/* The centre void fraction puts a particle's whole volume into the cell of its centre: a particle
 * wider than its cell (d > V_cell^(1/3)) drives that cell to alphaMin and leaves its neighbours
 * empty. Said once, at the start. */
static void warn_large_particles(const coupling *c)
{
    double count = 0, worst = 0.0;
    for (int k = 0; k < c->pr.n; k++) {   /* the copies whose centre is in this rank's cells */
        if (c->copy_cell[k] < 0) continue;
        const double ratio = 2.0 * c->copy_r[k] / cbrt(c->mesh.cell_volume[c->copy_cell[k]]);
        if (ratio > 1.0) count++;
        worst = fmax(worst, ratio);
    }
    dem_reduce_doubles(&count, 1, DEM_REDUCE_SUM);
    dem_reduce_doubles(&worst, 1, DEM_REDUCE_MAX);
    if (count > 0)
        dem_warning("couplingProperties: voidFraction model centre: %.0f of %ld particles are wider than their fluid "
                    "cell (d up to %.2f times the cell size V_cell^(1/3)); the centre model puts each particle's "
                    "volume into one cell, so those cells fall to alphaMin: use a coarser mesh or model divided",
                    count, global_count(c->s.p.n), worst);
}

/* postProcessing/particles.dat: a fresh run writes it anew; a continued run keeps the lines up
 * to its start time and goes on after them, so the file stays one continuous record. */
static void open_means(coupling *c, const char *path)
{
    static const char header[] = "# time [s], particles, mean position x y z [m], mean velocity x y z [m/s], "
                                 "the walls' force on the particles x y z [N], the fluid's force on the particles x y z [N] "
                                 "(both the mean over the fluid step's DEM steps)\n";
    char *kept = NULL;
    size_t nkept = 0;
    const int writer = dem_comm_rank() == 0;   /* rank 0 writes; the sums are taken on every rank */
    FILE *old = c->restarted && writer ? fopen(path, "r") : NULL;
    if (old) {
        char line[1024];
        size_t cap = 0;
        while (fgets(line, sizeof line, old)) {
            if (line[0] == '#') continue;
            char *end;
            const double t = dem_strtod(line, &end);
            if (end == line || !(t <= c->s.time + 0.5 * c->s.dt)) continue;
            const size_t len = strlen(line);
            if (nkept + len + 1 > cap) {
                cap = 2 * (nkept + len + 1) + 4096;
                kept = dem_realloc(kept, cap);
            }
            memcpy(kept + nkept, line, len + 1);
            nkept += len;
        }
        fclose(old);
    }
    int64_t fresh = writer && !nkept;   /* the first line now: rank 0 knows, every rank sums */
    dem_reduce_int64s(&fresh, 1, DEM_REDUCE_MAX);
    if (!writer) {
        if (fresh) write_means(c);
        return;
    }
    c->means = fopen(path, "w");
    if (!c->means) dem_fatal("coupling: cannot write %s", path);
    fputs(header, c->means);
    if (c->s.nwalls) {   /* a section's wall (a bounded cylinder, a plane) measured on its own */
        fputs("# then each wall's force on the particles x y z [N], the same mean:", c->means);
        for (int w = 0; w < c->s.nwalls; w++) fprintf(c->means, " %s", c->s.walls[w].name);
        fputc('\n', c->means);
    }
    if (nkept) fputs(kept, c->means);
    free(kept);
    if (fresh) write_means(c);
    else fflush(c->means);
}

/* The particles of a fresh run (insertion at t = 0), or of a run continued from t_start > 0:
 * the snapshot of <case>/particles.h5 at t_start with its contact history and forces, later
 * snapshots dropped (they are written again). */
static void setup_particles(coupling *c, const char *case_dir, double t_start)
{
    c->restarted = t_start > 0.0;
    dem_case_read(case_dir, &c->s, &c->rs, c->restarted);
    dem_contact_state saved;
    memset(&saved, 0, sizeof saved);
    char base[4200];
    snprintf(base, sizeof base, "%s/particles", case_dir);
    if (c->restarted) {
        char h5[4300];
        snprintf(h5, sizeof h5, "%s.h5", base);
        FILE *probe = fopen(h5, "rb");
        if (!probe)
            dem_fatal("%s does not exist: the fluid starts at t = %g s, and a coupled run from t > 0 continues "
                      "from the particle snapshot of that time in it (start from t = 0 to insert the particles)",
                      h5, t_start);
        fclose(probe);
        if (dem_restart_read(&c->s, base, t_start, 0.5 * c->s.dt, &saved) != 0)
            dem_fatal("%s.h5: no complete particle snapshot at t = %g s, where the fluid starts (a coupled "
                      "run starts at t = 0, or continues from a write time: its fields and its particle "
                      "snapshot)", base, t_start);
        /* the DEM keeps its own clock (the snapshot's, within half a step of t_start) */
        c->exchanged = saved.coupling_read;   /* what the fluid of t_start received */
        /* rank 0 drops them once every rank has read the snapshot, and the writer opens the file
         * after that (dem_reduce_any: the ranks wait for each other) */
        dem_reduce_any(0);
        const int dropped = dem_comm_rank() == 0 ? dem_io_drop_snapshots_after(base, c->s.time) : 0;
        dem_reduce_any(0);
        dem_info("coupling: continuing from %s.h5 at t = %g s (DEM step %ld), %d particles%s", base, c->s.time,
                 c->s.step, c->s.p.n, dropped ? "; later snapshots dropped" : "");
    }
    const double vmax = c->rs.max_expected_velocity > 0 ? c->rs.max_expected_velocity
                                                        : dem_case_default_max_velocity(&c->s);
    dem_timestep_check(&c->s, vmax, c->rs.timestep_override, c->rs.timestep_source);
    dem_restart_setup(&c->s, c->restarted ? &saved : NULL);
    dem_contact_state_free(&saved);
    c->writer = dem_io_open_writer(base, c->restarted);
}

/* The particles are periodic exactly where the gas is: a DEM periodic direction has the mesh's
 * cyclic pair across it, with the same period and sides (else particles would wrap where the gas
 * meets a wall, or stop at a side the gas flows through). */
static void check_periodic_sides(const coupling *c)
{
    const dem_system *s = &c->s;
    const cpl_mesh *m = &c->mesh;
    for (int d = 0; d < 3; d++) {
        if (s->periodic[d] != m->periodic[d])
            dem_fatal_at(c->rs.domain_source, "key 'periodic': the particles are %speriodic in %c, but the fluid mesh has "
                         "%s cyclic patch pair across %c: make both periodic there (demProperties domain periodic, "
                         "constant/polyMesh/boundary type cyclic) or neither", s->periodic[d] ? "" : "not ", "xyz"[d],
                         m->periodic[d] ? "a" : "no", "xyz"[d]);
        if (!s->periodic[d]) continue;
        const double L = m->period[d], tol = 1e-9 * L;
        if (fabs(s->period[d] - L) > tol || fabs(s->domain_min[d] - m->periodic_min[d]) > tol)
            dem_fatal_at(c->rs.domain_source, "key 'min': the particles' periodic side in %c is [%.10g, %.10g] m, the fluid "
                         "mesh's cyclic sides are at [%.10g, %.10g] m: they must be the same", "xyz"[d], s->domain_min[d],
                         s->domain_max[d], m->periodic_min[d], m->periodic_min[d] + L);
    }
}

/* What the parallel coupling does not do yet (issue 23): each says so and stops. The centre and
 * divided void fractions and the cell interpolation need nothing beyond a rank's own cells and
 * the particles' copies (cyclic pairs within a rank included: the adapter refuses a cut across
 * them); the gaussian kernel's walk through faces and the interpolation's neighbours would need
 * the cells across processor patches. */
static void refuse_in_parallel(const coupling *c, enum cpl_vf_model vf_model)
{
    char path[4200];
    snprintf(path, sizeof path, "%s/constant/couplingProperties", c->case_dir);
    if (vf_model == CPL_VF_GAUSSIAN)
        dem_fatal_at(path, "voidFraction model gaussian runs in one process only, not yet with -parallel (its kernel "
                     "walks through the faces into other ranks' cells): use centre or divided, or run serially");
    if (c->interp_scheme != CPL_INTERP_CELL)
        dem_fatal_at(path, "interpolation %s runs in one process only, not yet with -parallel (it needs the cells "
                     "across processor patches): use interpolation cell, or run serially", interp_names_of(c->interp_scheme));
}

int coupling_case_gravity(const char *case_dir, double g[3]) { return dem_case_gravity(case_dir, g); }

coupling *coupling_create(const char *case_dir, cpl_mesh *mesh, double rho_f, double nu_f, double dt_f,
                          double t_start)
{
    coupling *c = dem_calloc(1, sizeof *c);
    snprintf(c->case_dir, sizeof c->case_dir, "%s", case_dir);
    c->mesh = *mesh;                       /* the session takes the mesh over */
    memset(mesh, 0, sizeof *mesh);

    dem_system_init(&c->s);
    setup_particles(c, case_dir, t_start);

    double alpha_min, kernel_width, kernel_cutoff;
    enum cpl_vf_model vf_model;
    read_coupling_properties(c, dt_f, &alpha_min, &vf_model, &kernel_width, &kernel_cutoff);
    /* checked before the product (under OpenFOAM's traps an overflow is a signal) */
    if (!(rho_f > 0.0 && rho_f <= 1e5))
        dem_fatal("constant/transportProperties: rho = %g kg/m^3 is out of range: allowed (0, 1e5]", rho_f);
    if (!(nu_f > 0.0 && nu_f <= 1e2))
        dem_fatal("constant/transportProperties: nu = %g m^2/s is out of range: allowed (0, 1e2]", nu_f);
    c->params.rho_f = rho_f;
    c->params.mu_f = rho_f * nu_f;
    for (int q = 0; q < 3; q++) c->params.gravity[q] = c->s.gravity[q];
    c->params.coarse_graining = c->s.coarse_graining;   /* demProperties' coarseGraining */
    cpl_force_params_check(&c->params);
    cpl_proxies_init(&c->pr, &c->mesh);
    if (c->pr.size > 1) refuse_in_parallel(c, vf_model);
    check_periodic_sides(c);
    cpl_vf_init(&c->vf, &c->mesh, vf_model, alpha_min);
    c->vf.partial = c->pr.size > 1;
    if (vf_model == CPL_VF_GAUSSIAN) { c->vf.kernel_width = kernel_width; c->vf.kernel_cutoff = kernel_cutoff; }
    if (c->interp_scheme != CPL_INTERP_CELL) {
        cpl_interp_init(&c->interp, &c->mesh, c->interp_scheme, 6);
        c->ugp = dem_calloc((size_t)c->mesh.ncells, sizeof *c->ugp);
    }
    cpl_fluid_forces_init(&c->forces);

    const int nc = c->mesh.ncells;
    c->ksl = dem_calloc((size_t)nc, sizeof *c->ksl);
    c->up = dem_calloc((size_t)nc, sizeof *c->up);
    c->source = dem_calloc((size_t)nc, sizeof *c->source);
    update_void_fraction(c);
    if (vf_model == CPL_VF_CENTRE) warn_large_particles(c);

    char path[4200];
    snprintf(path, sizeof path, "%s/postProcessing", case_dir);
    char cmd[4400];
    snprintf(cmd, sizeof cmd, "mkdir -p '%s'", path);
    if (system(cmd) != 0) dem_fatal("coupling: cannot create %s", path);
    snprintf(path, sizeof path, "%s/postProcessing/particles.dat", case_dir);
    c->each_wall = dem_calloc((size_t)c->s.nwalls + 1, sizeof *c->each_wall);
    open_means(c, path);
    dem_info("coupling: %ld particles, %ld fluid cells; %d DEM steps of %g s per fluid step; void fraction %s "
             "(alphaMin %g), drag %s, model %s, %s exchange, %s interpolation",
             global_count(c->s.p.n), (long)global_count(nc), c->interval, c->s.dt, vf_model == CPL_VF_CENTRE ? "centre" : vf_model == CPL_VF_DIVIDED ? "divided" : "gaussian",
             alpha_min, cpl_drag_law_names[c->params.drag], cpl_model_type_names[c->params.model],
             cpl_exchange_mode_names[c->params.exchange], interp_names_of(c->interp_scheme));
    if (c->s.coarse_graining > 1.0)
        dem_info("coupling: coarse graining %g: each parcel's drag is %g times the drag law's for diameter d / %g "
                 "(Re from d / %g); its volume and mass are those of its %g particles",
                 c->s.coarse_graining, pow(c->s.coarse_graining, 3), c->s.coarse_graining, c->s.coarse_graining,
                 pow(c->s.coarse_graining, 3));
    return c;
}

void coupling_set_drive(coupling *c, const double drive[3])
{
    for (int q = 0; q < 3; q++) {
        if (!isfinite(drive[q])) dem_fatal("coupling: the driving pressure gradient %g N/m^3 is not finite", drive[q]);
        c->params.drive[q] = drive[q];
    }
}

void coupling_evolve(coupling *c, const double (*U)[3], const double (*grad_p)[3])
{
    evaluate_forces(c, U, grad_p, 1, 0);               /* 1 */
    double t = dem_clock();
    store_forces(c, !c->exchanged);
    lap(c, CPL_STAGE_EXCHANGE, &t);
    double fw[3] = {0.0, 0.0, 0.0}, ff[3] = {0.0, 0.0, 0.0};
    for (int w = 0; w < c->s.nwalls; w++) c->each_wall[w][0] = c->each_wall[w][1] = c->each_wall[w][2] = 0.0;
    for (int k = 0; k < c->interval; k++) {            /* 2 */
        apply_fluid_forces(c);   /* implicit: at the current velocity; explicit: frozen (beta 0) */
        lap(c, CPL_STAGE_EXCHANGE, &t);
        dem_system_step(&c->s);
        lap(c, CPL_STAGE_DEM, &t);
        for (int q = 0; q < 3; q++) fw[q] += c->s.wall_force[q];
        for (int w = 0; w < c->s.nwalls; w++)
            for (int q = 0; q < 3; q++) c->each_wall[w][q] += c->s.wall_lists[w].force[q];
        add_fluid_force(c, ff);
        lap(c, CPL_STAGE_OUTPUT, &t);   /* the sums for postProcessing/particles.dat */
    }
    c->dem_steps += c->interval;
    for (int q = 0; q < 3; q++) {
        c->wall_force[q] = fw[q] / c->interval;
        c->fluid_force[q] = ff[q] / c->interval;
    }
    for (int w = 0; w < c->s.nwalls; w++)
        for (int q = 0; q < 3; q++) c->each_wall[w][q] /= c->interval;
    if (c->pr.size > 1) {   /* each rank summed its own particles */
        dem_reduce_doubles(c->wall_force, 3, DEM_REDUCE_SUM);
        dem_reduce_doubles(c->fluid_force, 3, DEM_REDUCE_SUM);
        if (c->s.nwalls) dem_reduce_doubles(&c->each_wall[0][0], 3 * c->s.nwalls, DEM_REDUCE_SUM);
    }
    c->fluid_steps++;
    /* the rows a fluid step moves per copy: 6 + 1 + 1 + 2 (void fraction), 7 + 7 (the two
     * gathers), 7 (the forces): an all-gather sends each particle's to every other rank */
    c->allgather_bytes += (double)c->s.p.n * CPL_ROW_DOUBLES * sizeof(double) * (c->pr.size - 1);
    dem_system_check_health(&c->s);
    lap(c, CPL_STAGE_DEM, &t);
    update_void_fraction(c);                            /* 3 */
    evaluate_forces(c, U, grad_p, 0, 1);
    t = dem_clock();
    spread_forces(c);
    store_forces(c, 1);
    c->exchanged = 1;
    lap(c, CPL_STAGE_EXCHANGE, &t);
    write_means(c);
    lap(c, CPL_STAGE_OUTPUT, &t);
}

const double *coupling_alpha(const coupling *c) { return c->vf.alpha; }
const double *coupling_ksl(const coupling *c) { return c->ksl; }
const double (*coupling_particle_velocity(const coupling *c))[3] { return (const double (*)[3])c->up; }
const double (*coupling_explicit_source(const coupling *c))[3] { return (const double (*)[3])c->source; }
enum cpl_model_type coupling_model_type(const coupling *c) { return c->params.model; }
int coupling_interval(const coupling *c) { return c->interval; }
long coupling_particle_count(const coupling *c) { return c->pr.size > 1 ? global_count(c->s.p.n) : c->s.p.n; }

void coupling_particle_means(const coupling *c, double v[3], double x[3])
{
    const dem_particles *p = &c->s.p;
    double sum[7] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, (double)p->n};
    for (int i = 0; i < p->n; i++)
        for (int q = 0; q < 3; q++) { sum[q] += p->v[i][q]; sum[3 + q] += p->x[i][q]; }
    if (c->pr.size > 1) dem_reduce_doubles(sum, 7, DEM_REDUCE_SUM);
    for (int q = 0; q < 3; q++) {
        v[q] = sum[6] > 0 ? sum[q] / sum[6] : 0.0;
        x[q] = sum[6] > 0 ? sum[3 + q] / sum[6] : 0.0;
    }
}

void coupling_particle_forces(const coupling *c, double fluid[3], double walls[3])
{
    for (int q = 0; q < 3; q++) { fluid[q] = c->fluid_force[q]; walls[q] = c->wall_force[q]; }
}

void coupling_write(coupling *c, double time)
{
    /* at an exchange the DEM's time is the fluid's but for round-off (each accumulates its own
     * steps); the snapshot keeps the DEM's clock exactly, so that a run continued from it steps
     * the same times, and a continued run finds it by the fluid's time within half a DEM step */
    if (fabs(time - c->s.time) > 0.5 * c->s.dt)
        dem_fatal("coupling: particle snapshot asked at t = %g s, but the DEM is at t = %g s", time, c->s.time);
    double t = dem_clock();
    dem_contact_state cs;
    dem_restart_save_contacts(&c->s, &cs);
    dem_io_write_snapshot_contacts(c->writer, &c->s.p, c->s.time, c->s.step, &cs);
    dem_contact_state_free(&cs);
    dem_lifecycle_log(&c->s);
    /* Continue from here as a run continued from this snapshot does (bit for bit): lists made
     * anew (sorted, histories carried by ids), so that contact forces sum in its order, and the
     * void fraction's per-particle weights and cellPoint's tetrahedra made again in that order.
     * The fluid keeps the void fraction it solved with (written with the fields; a continued
     * run reads it back). */
    lap(c, CPL_STAGE_OUTPUT, &t);
    dem_system_relist(&c->s);
    lap(c, CPL_STAGE_DEM, &t);
    update_void_fraction(c);
    c->tets_valid = 0;
}

int coupling_restarted(const coupling *c) { return c->restarted; }

static double coupling_seconds(const coupling *c)
{
    double total = 0.0;
    for (int k = 0; k < CPL_STAGE_COUNT; k++) total += c->stage_seconds[k];
    return total;
}

void coupling_timings(const coupling *c, double *dem_s, double *coupling_s, double *lifecycle_s)
{
    *dem_s = c->dem_seconds;
    *coupling_s = coupling_seconds(c);
    *lifecycle_s = c->s.stage_seconds[DEM_STAGE_LIFECYCLE] + c->s.stage_seconds[DEM_STAGE_LIST_LIFECYCLE];
}

/* The bytes each rank sent per fluid step: the coupling's copies, the DEM's halo and migration,
 * and what an all-gather of every particle's coupling rows (CFDEMcoupling's twoWayMPI) would have
 * sent (issue 23). */
static void report_exchange(coupling *c)
{
    const double steps = c->fluid_steps > 0 ? (double)c->fluid_steps : 1.0;
    double mine[3] = {c->pr.bytes_sent, dem_comm_bytes_sent() - c->pr.bytes_sent, c->allgather_bytes};
    double most[3] = {mine[0], mine[1], mine[2]};
    dem_reduce_doubles(mine, 3, DEM_REDUCE_SUM);
    dem_reduce_doubles(most, 3, DEM_REDUCE_MAX);
    const double n = c->pr.size;
    dem_info("Bytes sent per rank per fluid step (mean over the %d ranks, the most on one): coupling copies %.4g B "
             "(%.4g B), the DEM's halo and migration %.4g B (%.4g B); an all-gather of every particle's %d coupling "
             "numbers would send %.4g B (%.4g B): the copies are %.2g %% of it", c->pr.size, mine[0] / n / steps,
             most[0] / steps, mine[1] / n / steps, most[1] / steps, CPL_ROW_DOUBLES, mine[2] / n / steps,
             most[2] / steps, mine[2] > 0 ? 100.0 * mine[0] / mine[2] : 0.0);
}

void coupling_report_timings(coupling *c)
{
    const double total = coupling_seconds(c);
    dem_info("Coupling time per stage (%.3g s; %% of the coupling's time, us per fluid step of %d DEM steps):", total,
             c->interval);
    const long fluid_steps = c->dem_steps / c->interval;
    for (int k = 0; k < CPL_STAGE_COUNT; k++)
        dem_info("  %-50s %9.3f s %5.1f %% %9.1f us", cpl_stage_names[k], c->stage_seconds[k],
                 total > 0 ? 100 * c->stage_seconds[k] / total : 0.0,
                 fluid_steps > 0 ? 1e6 * c->stage_seconds[k] / fluid_steps : 0.0);
    dem_stage_report(&c->s, c->dem_steps);
    if (c->pr.size > 1) report_exchange(c);
}

void coupling_free(coupling *c)
{
    if (!c) return;
    dem_io_close_writer(c->writer);
    if (c->means) fclose(c->means);
    free(c->each_wall);
    cpl_fluid_forces_free(&c->forces);
    if (c->interp_scheme != CPL_INTERP_CELL) cpl_interp_free(&c->interp);
    free(c->ugp); free(c->ugp_p); free(c->tets);
    cpl_vf_free(&c->vf);
    cpl_mesh_free(&c->mesh);
    dem_system_free(&c->s);
    cpl_proxies_free(&c->pr);
    free(c->copy_x); free(c->copy_r); free(c->copy_volume); free(c->copy_cell); free(c->copy_z);
    free(c->copy_norm); free(c->copy_found); free(c->copy_beta); free(c->copy_f); free(c->copy_v);
    free(c->copy_alpha); free(c->copy_u); free(c->copy_gp);
    free(c->copy_buf); free(c->particle_buf); free(c->reach);
    free(c->d); free(c->volume); free(c->alpha_p); free(c->u_p); free(c->gp_p);
    free(c->ksl); free(c->up); free(c->source);
    free(c);
}
