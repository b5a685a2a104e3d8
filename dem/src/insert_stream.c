/* Insertion during the run (insert_stream.h). */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "comm.h"
#include "decompose.h"
#include "error.h"
#include "memory_budget.h"
#include "reduce.h"
#include "system.h"

dem_stream *dem_streams_add(dem_system *s)
{
    s->streams = dem_realloc(s->streams, (size_t)(s->nstreams + 1) * sizeof *s->streams);
    dem_stream *st = &s->streams[s->nstreams++];
    memset(st, 0, sizeof *st);
    return st;
}

void dem_streams_free(dem_system *s)
{
    for (int k = 0; k < s->nstreams; k++) {
        free(s->streams[k].ins.d_values);
        free(s->streams[k].ins.d_weights);
    }
    free(s->streams);
    s->streams = NULL;
    s->nstreams = 0;
}

static double dot(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* The mean volume of the stream's diameter distribution [m^3]: exact for one diameter, else the
 * mean of 20,000 draws from a generator of its own (the stream's is not touched). */
static double mean_particle_volume(const dem_stream *st)
{
    if (st->ins.dist == SIZE_CONSTANT) return M_PI / 6.0 * pow(st->ins.d_value, 3);
    dem_rng r;
    rng_seed(&r, st->ins.seed ^ 0x5eedULL);
    double sum = 0.0;
    for (int k = 0; k < 20000; k++) sum += pow(dem_insertion_draw_diameter(&st->ins, &r), 3);
    return M_PI / 6.0 * sum / 20000.0;
}

/* A number of steps as a long: at most 1e15 (a run is below 1e13 steps: case.c), so that no
 * quotient of the keys' ranges (1e9 s over 1e-12 s) overflows the conversion */
static long steps_of(double steps) { return (long)fmin(steps, 1e15); }

void dem_stream_prepare(const dem_system *s, dem_stream *st)
{
    const double dt = s->dt;
    if (!(dt > 0.0)) dem_fatal("insertion '%s': the time step must be set before the stream", st->ins.name);
    const double vn = dot(st->ins.velocity, st->normal);
    st->mean_volume = mean_particle_volume(st);
    if (st->interval > 0.0) st->every = steps_of(fmax(1.0, nearbyint(st->interval / dt)));
    else if (st->shape != STREAM_REGION)   /* the slab 1.5 of the largest diameter deep */
        st->every = steps_of(fmax(1.0, ceil(1.5 * dem_insertion_max_diameter(&st->ins) / (vn * dt))));
    else st->every = 100;
    st->start_step = steps_of(fmax(1.0, ceil(st->start_time / dt - 1e-9)));
    st->end_step = isfinite(st->end_time) && st->end_time / dt < 1e15 ? (long)floor(st->end_time / dt + 1e-9) : LONG_MAX;
    if (st->shape != STREAM_REGION) st->depth = vn * st->every * dt;
    rng_seed(&st->rng, st->ins.seed);
}

double dem_stream_largest_rate(const dem_system *s, const dem_stream *st)
{
    if (st->shape == STREAM_REGION) return INFINITY;
    const double fits = st->max_solid_fraction * st->area * dot(st->ins.velocity, st->normal);   /* [m^3/s] */
    return st->mass_rate > 0.0 ? fits * s->materials.mat[st->ins.material].density : fits / st->mean_volume;
}

/* Events on the schedule until endTime, and after it while something is still due (carried over) */
static int event_at(const dem_stream *st, long step)
{
    const int behind = st->behind_count > 0 || st->behind_mass > 0.0 || st->pending_diameter > 0.0;
    return step >= st->start_step && (step <= st->end_step || behind) && (step - st->start_step) % st->every == 0;
}

int dem_streams_due(const dem_system *s, long step)
{
    for (int k = 0; k < s->nstreams; k++)
        if (event_at(&s->streams[k], step)) return 1;
    return 0;
}

/* A centre for a particle of radius r: in the slab in front of the face, or in the region. */
static void draw_centre(dem_stream *st, double r, double x[3])
{
    dem_rng *g = &st->rng;
    if (st->shape == STREAM_REGION) {
        dem_insertion_draw_position(&st->ins, r, g, x);
        return;
    }
    const double along = r + st->depth * rng_uniform(g);   /* from the face inwards */
    if (st->shape == STREAM_DISC) {
        double u, w;
        do {   /* uniform in the disc of radius R - r */
            u = 2.0 * rng_uniform(g) - 1.0;
            w = 2.0 * rng_uniform(g) - 1.0;
        } while (u * u + w * w > 1.0);
        const double reach = st->radius - r;
        for (int d = 0; d < 3; d++)
            x[d] = st->centre[d] + along * st->normal[d] + reach * (u * st->e1[d] + w * st->e2[d]);
        return;
    }
    for (int d = 0; d < 3; d++)
        x[d] = d == st->axis ? st->centre[d] + along * st->normal[d]
                             : st->fmin[d] + r + (st->fmax[d] - st->fmin[d] - 2.0 * r) * rng_uniform(g);
}

/* The m-th event (0, 1, ...) places what is due by the end of its interval: the rate times the
 * time from startTime, at most up to endTime. */
static double due_time(const dem_system *s, const dem_stream *st, long step)
{
    const long m = (step - st->start_step) / st->every;
    return fmin((double)(m + 1) * st->every * s->dt, st->end_time - st->start_time);
}

/* One event of one stream; `pl` is the placement grid of all particles (shared by the streams
 * of the step). In a parallel run `near` holds the particles of every rank near the due streams'
 * faces (the same on every rank), `pl` is laid over them, and every rank draws and places alike:
 * each new particle joins `near` everywhere and the system on the rank whose box holds it, with
 * the same id at any rank count. */
static void stream_event(dem_system *s, dem_stream *st, long step, dem_placement *pl, dem_particles *near)
{
    dem_particles *p = &s->p;
    const double t_due = due_time(s, st, step);
    const int64_t due_count = st->number_rate > 0.0 ? (int64_t)floor(st->number_rate * t_due + 1e-9) : 0;
    const double due_mass = st->mass_rate * t_due;
    const double density = s->materials.mat[st->ins.material].density;
    const double most = dem_particles_affordable();   /* memory_budget.h */
    int stuck = 0;
    for (;;) {
        if (st->number_rate > 0.0 ? st->inserted.count >= due_count
                                  : dem_quanta_to_kg(st->inserted.mass) >= due_mass) break;
        const double d = st->pending_diameter > 0.0 ? st->pending_diameter : dem_insertion_draw_diameter(&st->ins, &st->rng);
        const double r = 0.5 * d;
        double x[3];
        int ok = 0;
        for (int attempt = 0; attempt < st->ins.max_attempts && !ok; attempt++) {
            draw_centre(st, r, x);
            ok = dem_placement_free(pl, s, x, r);
        }
        if (!ok) {   /* no room now: this one first at the next event, the rest carried with it */
            st->pending_diameter = d;
            stuck = 1;
            break;
        }
        st->pending_diameter = 0.0;
        if (p->n + 1.0 > most)
            dem_fatal_at(st->ins.source, "key '%s': insertion '%s' has filled the memory at t = %g s: %d particles "
                         "are the most this machine's memory holds (%.0f bytes each, %d x a particle's fields). Lower "
                         "the rate or the stream's endTime, or add an outlet.", st->number_rate > 0.0 ? "numberRate"
                         : "massRate", st->ins.name, s->time, p->n, (double)dem_particle_memory_bytes(),
                         PARTICLE_MEMORY_FACTOR);
        double v[3];
        for (int q = 0; q < 3; q++)
            v[q] = st->ins.velocity[q] + (st->velocity_std > 0.0 ? st->velocity_std * rng_normal(&st->rng) : 0.0);
        const int64_t id = s->next_id++;
        double mass;
        if (near) {   /* every rank: among the particles the next draws are placed against */
            const int k = dem_particles_add(near, x, v, r, density, st->ins.material, id);
            dem_placement_add(pl, s, k);
            mass = near->mass[k];
        }
        if (!near || dem_decomposition_owner(&s->decomp, x) == dem_comm_rank()) {
            const int i = dem_particles_add(p, x, v, r, density, st->ins.material, id);
            for (int q = 0; q < 3; q++) p->f[i][q] = p->mass[i] * s->gravity[q];   /* the step's forces so far */
            if (st->ins.prescribed) dem_particles_prescribe(p, i);
            if (!near) dem_placement_add(pl, s, i);
            mass = p->mass[i];
            dem_tally_add(&s->inserted, 1, dem_mass_to_quanta(mass));   /* this rank's: summed over the ranks */
        }
        dem_tally_add(&st->inserted, 1, dem_mass_to_quanta(mass));      /* the stream's: the same on every rank */
    }
    /* the particles carried for the first time: what is behind now beyond what was behind before
     * (those are placed first); a mass rate's in particles of the mean mass */
    const int64_t was_behind = st->behind_count;
    st->behind_mass = st->mass_rate > 0.0 ? fmax(0.0, due_mass - dem_quanta_to_kg(st->inserted.mass)) : 0.0;
    st->behind_count = st->number_rate > 0.0 ? (due_count > st->inserted.count ? due_count - st->inserted.count : 0)
                                             : (int64_t)ceil(st->behind_mass / (density * st->mean_volume));
    if (stuck && st->behind_count > was_behind) st->carried_total += st->behind_count - was_behind;
}

/* Where a stream's centres may fall, widened by dmax (what a particle there may touch) [m]; the
 * whole length along a periodic direction. */
static void stream_zone(const dem_system *s, const dem_stream *st, double dmax, double lo[3], double hi[3])
{
    for (int d = 0; d < 3; d++) {
        switch (st->shape) {
        case STREAM_REGION:
            lo[d] = st->ins.min[d];
            hi[d] = st->ins.max[d];
            if (st->ins.region == REGION_CYLINDER && d != st->ins.axis) {   /* the box around the cylinder */
                const double c = st->ins.centre[d < st->ins.axis ? d : d - 1];
                lo[d] = c - st->ins.radius;
                hi[d] = c + st->ins.radius;
            }
            break;
        case STREAM_DISC:
            lo[d] = st->centre[d] - st->radius - st->depth - dmax;
            hi[d] = st->centre[d] + st->radius + st->depth + dmax;
            break;
        case STREAM_RECTANGLE:
            lo[d] = fmin(st->fmin[d], st->fmin[d] + st->normal[d] * (st->depth + dmax));
            hi[d] = fmax(st->fmax[d], st->fmax[d] + st->normal[d] * (st->depth + dmax));
            break;
        }
        lo[d] -= dmax;
        hi[d] += dmax;
        if (s->periodic[d]) { lo[d] = -INFINITY; hi[d] = INFINITY; }
    }
}

/* Every rank's particles within the due streams' zones, in rank order, into `near` (the same on
 * every rank): each rank sends its own to every other. */
static void gather_near(dem_system *s, long step, double dmax, dem_particles *near)
{
    const int size = dem_comm_size(), me = dem_comm_rank();
    const dem_particles *p = &s->p;
    double (*zone)[6] = dem_malloc((size_t)(s->nstreams + 1) * sizeof *zone);
    int nz = 0;
    for (int k = 0; k < s->nstreams; k++)
        if (event_at(&s->streams[k], step)) { stream_zone(s, &s->streams[k], dmax, zone[nz], zone[nz] + 3); nz++; }
    double *mine = dem_malloc(((size_t)p->n * 4 + 1) * sizeof *mine);
    int n = 0;
    for (int i = 0; i < p->n; i++)
        for (int z = 0; z < nz; z++) {
            int in = 1;
            for (int d = 0; d < 3; d++) in &= p->x[i][d] >= zone[z][d] && p->x[i][d] <= zone[z][3 + d];
            if (!in) continue;
            memcpy(mine + 4 * n, p->x[i], 3 * sizeof(double));
            mine[4 * n + 3] = p->radius[i];
            n++;
            break;
        }
    int64_t *counts = dem_malloc(2 * (size_t)size * sizeof *counts);
    for (int r = 0; r < size; r++) counts[r] = n;
    dem_comm_counts(counts, counts + size);
    size_t *b = dem_malloc(4 * (size_t)size * sizeof *b), total = 0;
    for (int r = 0; r < size; r++) {
        b[r] = r == me ? 0 : (size_t)n * 4 * sizeof(double);             /* to each: all of mine */
        b[size + r] = 0;
        b[2 * size + r] = r == me ? 0 : (size_t)counts[size + r] * 4 * sizeof(double);
        b[3 * size + r] = total * 4 * sizeof(double);
        total += r == me ? (size_t)n : (size_t)counts[size + r];
    }
    double *all = dem_malloc((total * 4 + 1) * sizeof *all);
    memcpy((char *)all + b[3 * size + me], mine, (size_t)n * 4 * sizeof(double));
    dem_comm_exchange(mine, b, b + size, all, b + 2 * size, b + 3 * size);
    static const double still[3] = {0.0, 0.0, 0.0};
    for (size_t k = 0; k < total; k++) dem_particles_add(near, all + 4 * k, still, all[4 * k + 3], 1.0, 0, -1);
    free(all); free(b); free(counts); free(mine); free(zone);
}

void dem_streams_insert(dem_system *s, long step)
{
    if (dem_comm_size() > 1) {   /* every rank alike, against the particles of all ranks near the faces */
        int due = 0;
        for (int k = 0; k < s->nstreams; k++) due |= event_at(&s->streams[k], step);
        if (!due) return;
        double dmin, dmax, rmax = 0.0;
        dem_streams_diameters(s, -1, &dmin, &dmax);
        for (int i = 0; i < s->p.n; i++) rmax = fmax(rmax, s->p.radius[i]);
        dem_reduce_doubles(&rmax, 1, DEM_REDUCE_MAX);
        dmax = fmax(dmax, 2.0 * rmax);
        dem_particles near;
        dem_particles_init(&near);
        gather_near(s, step, dmax, &near);
        dem_placement *pl = dem_placement_begin_on(s, &near, dmax, 1024);
        for (int k = 0; k < s->nstreams; k++)
            if (event_at(&s->streams[k], step)) stream_event(s, &s->streams[k], step, pl, &near);
        dem_placement_end(pl);
        dem_particles_free(&near);
        return;
    }
    dem_placement *pl = NULL;
    for (int k = 0; k < s->nstreams; k++) {
        dem_stream *st = &s->streams[k];
        if (!event_at(st, step)) continue;
        if (!pl) {
            double dmin, dmax;
            dem_streams_diameters(s, -1, &dmin, &dmax);
            pl = dem_placement_begin(s, dmax, 1024);
        }
        stream_event(s, st, step, pl, NULL);
    }
    dem_placement_end(pl);
}

void dem_streams_diameters(const dem_system *s, int type, double *dmin, double *dmax)
{
    *dmin = INFINITY;
    *dmax = 0.0;
    for (int k = 0; k < s->nstreams; k++) {
        const dem_insertion *ins = &s->streams[k].ins;
        if (type >= 0 && ins->material != type) continue;
        *dmin = fmin(*dmin, dem_insertion_min_diameter(ins));
        *dmax = fmax(*dmax, dem_insertion_max_diameter(ins));
    }
}

double dem_streams_max_speed(const dem_system *s)
{
    double vmax = 0.0;
    for (int k = 0; k < s->nstreams; k++) {
        const dem_stream *st = &s->streams[k];
        vmax = fmax(vmax, sqrt(dot(st->ins.velocity, st->ins.velocity)) + 4.0 * st->velocity_std);
    }
    return vmax;
}
