/* Random insertion, and the checked placement of given particles (lattice points, file lines)
 * shared by the other two methods (insert.h). */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dict.h"
#include "error.h"
#include "insert.h"
#include "rng.h"
#include "system.h"

double dem_insertion_max_diameter(const dem_insertion *ins)
{
    switch (ins->dist) {
    case SIZE_CONSTANT: return ins->d_value;
    case SIZE_UNIFORM:
    case SIZE_NORMAL: return ins->d_max;
    case SIZE_DISCRETE: {
        double m = 0.0;
        for (int k = 0; k < ins->ndiscrete; k++) m = fmax(m, ins->d_values[k]);
        return m;
    }
    }
    return 0.0;
}

double dem_insertion_min_diameter(const dem_insertion *ins)
{
    switch (ins->dist) {
    case SIZE_CONSTANT: return ins->d_value;
    case SIZE_UNIFORM:
    case SIZE_NORMAL: return ins->d_min;
    case SIZE_DISCRETE: {
        double m = INFINITY;
        for (int k = 0; k < ins->ndiscrete; k++)
            if (ins->d_weights[k] > 0.0) m = fmin(m, ins->d_values[k]);
        return m;
    }
    }
    return 0.0;
}

double dem_insertion_draw_diameter(const dem_insertion *ins, dem_rng *r)
{
    switch (ins->dist) {
    case SIZE_CONSTANT: return ins->d_value;
    case SIZE_UNIFORM: return ins->d_min + (ins->d_max - ins->d_min) * rng_uniform(r);
    case SIZE_NORMAL: {
        /* truncated normal: by rejection where [min, max] holds at least 1 % of the normal's
         * mass (fewer than 100 draws on average), else by inverting its distribution function
         * (bisection): rejection alone never ends when min = max or stdDev is 0 */
        if (ins->d_std == 0.0 || ins->d_max == ins->d_min) return ins->d_std == 0.0 ? ins->d_mean : ins->d_min;
        const double a = (ins->d_min - ins->d_mean) / ins->d_std, b = (ins->d_max - ins->d_mean) / ins->d_std;
        const double pa = 0.5 * erfc(-a / M_SQRT2), pb = 0.5 * erfc(-b / M_SQRT2);
        if (pb - pa >= 0.01)
            for (;;) {
                const double d = ins->d_mean + ins->d_std * rng_normal(r);
                if (d >= ins->d_min && d <= ins->d_max) return d;
            }
        const double u = pa + (pb - pa) * rng_uniform(r);
        double lo = a, hi = b;
        for (int it = 0; it < 100; it++) {
            const double mid = 0.5 * (lo + hi);
            if (0.5 * erfc(-mid / M_SQRT2) < u) lo = mid;
            else hi = mid;
        }
        return ins->d_mean + ins->d_std * 0.5 * (lo + hi);
    }
    case SIZE_DISCRETE: {
        double total = 0.0;
        for (int k = 0; k < ins->ndiscrete; k++) total += ins->d_weights[k];
        double u = rng_uniform(r) * total;
        for (int k = 0; k < ins->ndiscrete; k++) {
            if (u < ins->d_weights[k]) return ins->d_values[k];
            u -= ins->d_weights[k];
        }
        return ins->d_values[ins->ndiscrete - 1];
    }
    }
    return 0.0;
}

void dem_insertion_draw_position(const dem_insertion *ins, double radius, dem_rng *r, double x[3])
{
    if (ins->region == REGION_BOX) {
        for (int d = 0; d < 3; d++)
            x[d] = ins->min[d] + radius + (ins->max[d] - ins->min[d] - 2.0 * radius) * rng_uniform(r);
        return;
    }
    const int a = ins->axis, b = (a + 1) % 3, c = (a + 2) % 3;
    const double reach = ins->radius - radius;
    double u, w;
    do {
        u = 2.0 * rng_uniform(r) - 1.0;
        w = 2.0 * rng_uniform(r) - 1.0;
    } while (u * u + w * w > 1.0);
    x[a] = ins->min[a] + radius + (ins->max[a] - ins->min[a] - 2.0 * radius) * rng_uniform(r);
    x[b] = ins->centre[0] + reach * u;
    x[c] = ins->centre[1] + reach * w;
}

double dem_insertion_region_volume(const dem_insertion *ins)
{
    if (ins->region == REGION_BOX)
        return (ins->max[0] - ins->min[0]) * (ins->max[1] - ins->min[1]) * (ins->max[2] - ins->min[2]);
    return M_PI * ins->radius * ins->radius * (ins->max[ins->axis] - ins->min[ins->axis]);
}

/* A uniform grid over the domain with cell size >= the largest diameter, as linked lists. */
typedef struct grid {
    int n[3];
    double lo[3], h[3];
    int *head, *next;
} grid;

static int grid_cell(const grid *g, const double x[3], int c[3])
{
    for (int d = 0; d < 3; d++) {
        c[d] = (int)floor((x[d] - g->lo[d]) / g->h[d]);
        if (c[d] < 0) c[d] = 0;
        if (c[d] >= g->n[d]) c[d] = g->n[d] - 1;
    }
    return (c[2] * g->n[1] + c[1]) * g->n[0] + c[0];
}

static void grid_add(grid *g, const dem_particles *p, int i)
{
    int c[3];
    const int cell = grid_cell(g, p->x[i], c);
    g->next[i] = g->head[cell];
    g->head[cell] = i;
}

/* Lay the grid over the domain: cells no smaller than dmax, at most about 4 per expected
 * particle; room in `next` for `capacity` particles. */
static void grid_init(grid *g, const dem_system *s, double dmax, long expected, long capacity)
{
    const long max_cells = 4 * expected + 64;
    long ncells;
    for (double size = dmax;; size *= 1.26) {
        ncells = 1;
        for (int d = 0; d < 3; d++) {
            const double len = s->domain_max[d] - s->domain_min[d];
            g->n[d] = (int)fmax(1.0, fmin(1 << 20, floor(len / size)));
            if (s->periodic[d] && g->n[d] < 3) g->n[d] = 1;   /* one cell: no wrap duplicates */
            g->h[d] = len / g->n[d];
            g->lo[d] = s->domain_min[d];
            ncells *= g->n[d];
        }
        if (ncells <= max_cells) break;
    }
    g->head = dem_malloc((size_t)ncells * sizeof(int));
    for (long c = 0; c < ncells; c++) g->head[c] = -1;
    g->next = dem_malloc((size_t)(capacity > 0 ? capacity : 1) * sizeof(int));
}

/* The first particle j whose centre is closer to x than factor (radius + r_j), or -1. */
static int find_overlap_in(const dem_system *s, const dem_particles *p, const grid *g, const double x[3], double radius,
                           double factor)
{
    int c[3];
    grid_cell(g, x, c);
    for (int oz = -1; oz <= 1; oz++)
        for (int oy = -1; oy <= 1; oy++)
            for (int ox = -1; ox <= 1; ox++) {
                int q[3] = {c[0] + ox, c[1] + oy, c[2] + oz};
                int skip = 0;
                for (int d = 0; d < 3; d++) {
                    if (s->periodic[d]) q[d] = (q[d] + g->n[d]) % g->n[d];
                    else if (q[d] < 0 || q[d] >= g->n[d]) skip = 1;
                }
                if (skip) continue;
                for (int j = g->head[(q[2] * g->n[1] + q[1]) * g->n[0] + q[0]]; j >= 0; j = g->next[j]) {
                    double d2 = 0.0;
                    for (int d = 0; d < 3; d++) {
                        double dx = x[d] - p->x[j][d];
                        dx -= s->period[d] * nearbyint(dx * s->inv_period[d]);
                        d2 += dx * dx;
                    }
                    const double reach = factor * (radius + p->radius[j]);
                    if (d2 < reach * reach) return j;
                }
            }
    return -1;
}

static int find_overlap(const dem_system *s, const grid *g, const double x[3], double radius, double factor)
{
    return find_overlap_in(s, &s->p, g, x, radius, factor);
}

static int overlaps_in(const dem_system *s, const dem_particles *p, const grid *g, const double x[3], double radius);
static int overlaps(const dem_system *s, const grid *g, const double x[3], double radius)
{
    return overlaps_in(s, &s->p, g, x, radius);
}

/* x overlaps one of p's particles in the grid, a wall, or lies beyond a mirror */
static int overlaps_in(const dem_system *s, const dem_particles *p, const grid *g, const double x[3], double radius)
{
    if (find_overlap_in(s, p, g, x, radius, 1.0) >= 0) return 1;
    for (int k = 0; k < s->nsymmetry; k++)   /* the centre on the particle side of a mirror */
        if (symmetry_distance(&s->symmetry_planes[k], x) < 0.0) return 1;
    for (int k = 0; k < s->nwalls; k++) {
        double gap, en[3];
        if (dem_wall_gap(&s->walls[k], x, radius, &gap, en) && gap < 0.0) return 1;
    }
    return 0;
}

struct dem_placement {
    grid g;
    long capacity;              /* of g.next */
    const dem_particles *p;     /* the particles placed against */
};

dem_placement *dem_placement_begin_on(const dem_system *s, const dem_particles *p, double dmax, long extra)
{
    for (int i = 0; i < p->n; i++) dmax = fmax(dmax, 2.0 * p->radius[i]);
    dem_placement *pl = dem_malloc(sizeof *pl);
    pl->capacity = p->n + extra + 16;
    pl->p = p;
    grid_init(&pl->g, s, dmax, p->n + extra, pl->capacity);
    for (int i = 0; i < p->n; i++) grid_add(&pl->g, p, i);
    return pl;
}

dem_placement *dem_placement_begin(const dem_system *s, double dmax, long extra)
{
    return dem_placement_begin_on(s, &s->p, dmax, extra);
}

int dem_placement_free(const dem_placement *pl, const dem_system *s, const double x[3], double radius)
{
    return !overlaps_in(s, pl->p, &pl->g, x, radius);
}

void dem_placement_add(dem_placement *pl, const dem_system *s, int i)
{
    (void)s;
    if (i >= pl->capacity) {
        pl->capacity = 2 * (long)i + 16;
        pl->g.next = dem_realloc(pl->g.next, (size_t)pl->capacity * sizeof(int));
    }
    grid_add(&pl->g, pl->p, i);
}

void dem_placement_end(dem_placement *pl)
{
    if (!pl) return;
    free(pl->g.head);
    free(pl->g.next);
    free(pl);
}

/* A uniformly random rotation (Shoemake, Graphics Gems III, 1992: uniform on the unit 3-sphere). */
static void draw_orientation(dem_rng *r, double q[4])
{
    const double u1 = rng_uniform(r), u2 = 2.0 * M_PI * rng_uniform(r), u3 = 2.0 * M_PI * rng_uniform(r);
    q[0] = sqrt(1.0 - u1) * sin(u2);
    q[1] = sqrt(1.0 - u1) * cos(u2);
    q[2] = sqrt(u1) * sin(u3);
    q[3] = sqrt(u1) * cos(u3);
}

/* The largest sphere diameter of a template and of the particles already placed (the grid's
 * cell), and the template's bounding radius about its centre of mass [m]. */
static double body_grid_size(const dem_system *s, const dem_clump_template *t, double *bound)
{
    double dmax = 0.0;
    *bound = 0.0;
    for (int k = 0; k < t->n; k++) {
        const double *o = t->offset[k];
        *bound = fmax(*bound, sqrt(o[0] * o[0] + o[1] * o[1] + o[2] * o[2]) + t->radius[k]);
        dmax = fmax(dmax, 2.0 * t->radius[k]);
    }
    for (int i = 0; i < s->p.n; i++) dmax = fmax(dmax, 2.0 * s->p.radius[i]);
    return dmax;
}

/* The region's smallest extent [m] (a cylinder: its diameter or its length) */
static double region_smallest_extent(const dem_insertion *ins)
{
    return ins->region == REGION_BOX
        ? fmin(fmin(ins->max[0] - ins->min[0], ins->max[1] - ins->min[1]), ins->max[2] - ins->min[2])
        : fmin(2.0 * ins->radius, ins->max[ins->axis] - ins->min[ins->axis]);
}

/* A body's start orientation: its own (a file's line), else the entry's `orientation`, else drawn
 * at random (so the draws are as many as the bodies that take one). */
static void start_orientation(const dem_insertion *ins, const double *own, dem_rng *r, double q[4])
{
    if (own) memcpy(q, own, 4 * sizeof *q);
    else if (ins->orientation_given) memcpy(q, ins->orientation, 4 * sizeof *q);
    else draw_orientation(r, q);
}

/* Random insertion of multisphere bodies of one template: a centre in the region (kept its
 * bounding radius from the sides), a random orientation, accepted when none of its spheres
 * overlaps a particle, wall or mirror already there. */
static long insert_bodies(dem_system *s, const dem_insertion *ins)
{
    dem_particles *p = &s->p;
    const dem_clump_template *t = &s->bodies.templates[ins->body - 1];
    double bound;
    const double dmax = body_grid_size(s, t, &bound);
    const double extent = region_smallest_extent(ins);
    if (extent < 2.0 * bound)
        dem_fatal_at(ins->source[0] ? ins->source : NULL, "insertion '%s': the region (smallest extent %g m) is smaller "
                     "than the body '%s' (%g m across)", ins->name, extent, t->name, 2.0 * bound);
    const long target = ins->number > 0 ? ins->number : -1;
    const double target_volume = ins->solid_fraction * dem_insertion_region_volume(ins);
    const long expected_bodies = target > 0 ? target : (long)(target_volume / t->mass.volume) + 1;
    long capacity = p->n + expected_bodies * t->n + t->n;
    grid g;
    grid_init(&g, s, dmax, p->n + expected_bodies * t->n, capacity);
    for (int i = 0; i < p->n; i++) grid_add(&g, p, i);
    dem_rng r;
    rng_seed(&r, ins->seed);
    long placed = 0;
    double volume = 0.0;
    double (*centre)[3] = dem_malloc((size_t)t->n * sizeof *centre);
    while (target > 0 ? placed < target : volume < target_volume) {
        double x[3], q[4];
        int ok = 0;
        for (int attempt = 0; attempt < ins->max_attempts && !ok; attempt++) {
            dem_insertion_draw_position(ins, bound, &r, x);
            start_orientation(ins, NULL, &r, q);
            dem_body_sphere_centres(t, x, q, centre);
            ok = 1;
            for (int k = 0; k < t->n && ok; k++) ok = !overlaps(s, &g, centre[k], t->radius[k]);
        }
        if (!ok)
            dem_fatal_at(ins->source[0] ? ins->source : NULL, "insertion '%s': placed only %ld bodies '%s' (solid fraction "
                         "%.3f of the region) before one found no free place in %d attempts. Enlarge the region, lower "
                         "number/solidFraction, or raise maxAttempts.",
                         ins->name, placed, t->name, volume / dem_insertion_region_volume(ins), ins->max_attempts);
        if (p->n + t->n > capacity) {
            capacity = 2 * capacity + t->n;
            g.next = dem_realloc(g.next, (size_t)capacity * sizeof(int));
        }
        dem_bodies_add(s, ins->body - 1, x, q, ins->velocity, ins->angular_velocity);
        for (int i = p->n - t->n; i < p->n; i++) grid_add(&g, p, i);
        placed++;
        volume += t->mass.volume;
    }
    free(centre);
    free(g.head);
    free(g.next);
    return placed;
}

long dem_insertion_run(dem_system *s, const dem_insertion *ins)
{
    if (ins->body > 0) return insert_bodies(s, ins);
    dem_particles *p = &s->p;
    double dmax = dem_insertion_max_diameter(ins);
    for (int i = 0; i < p->n; i++) dmax = fmax(dmax, 2.0 * p->radius[i]);
    grid g;
    const long target = ins->number > 0 ? ins->number : -1;
    const double target_volume = ins->solid_fraction * dem_insertion_region_volume(ins);
    const double mean_volume = M_PI / 6.0 * pow(0.5 * dmax, 3);   /* a low guess: more cells */
    const long expected = p->n + (target > 0 ? target : (long)(target_volume / mean_volume));
    long capacity = p->n + (target > 0 ? target : 1024);
    grid_init(&g, s, dmax, expected, capacity);
    for (int i = 0; i < p->n; i++) grid_add(&g, p, i);

    dem_rng r;
    rng_seed(&r, ins->seed);
    const double density = s->materials.mat[ins->material].density;
    long placed = 0;
    double volume = 0.0;
    const double dmax_ins = dem_insertion_max_diameter(ins);
    const double region_extent_ok = region_smallest_extent(ins);
    if (region_extent_ok < dmax_ins)
        dem_fatal_at(ins->source[0] ? ins->source : NULL, "insertion '%s': the region (smallest extent %g m) is smaller than the largest "
                  "diameter %g m", ins->name, region_extent_ok, dmax_ins);

    while (target > 0 ? placed < target : volume < target_volume) {
        const double radius = 0.5 * dem_insertion_draw_diameter(ins, &r);
        double x[3];
        int ok = 0;
        for (int attempt = 0; attempt < ins->max_attempts && !ok; attempt++) {
            dem_insertion_draw_position(ins, radius, &r, x);
            ok = !overlaps(s, &g, x, radius);
        }
        if (!ok)
            dem_fatal_at(ins->source[0] ? ins->source : NULL, "insertion '%s': placed only %ld particles (solid fraction %.3f of the "
                      "region) before a particle found no free place in %d attempts. Enlarge the "
                      "region, lower number/solidFraction (random placement jams near 0.3), or "
                      "raise maxAttempts.",
                      ins->name, placed, volume / dem_insertion_region_volume(ins), ins->max_attempts);
        if (p->n + 1 > capacity) {
            capacity *= 2;
            g.next = dem_realloc(g.next, (size_t)capacity * sizeof(int));
        }
        const int i = dem_particles_add(p, x, ins->velocity, radius, density, ins->material, s->next_id++);
        if (ins->prescribed) dem_particles_prescribe(p, i);
        grid_add(&g, p, i);
        placed++;
        volume += 4.0 / 3.0 * M_PI * radius * radius * radius;
    }
    free(g.head);
    free(g.next);
    return placed;
}

/* ------------------------------------------------------------------ given particles */

void dem_insert_batch_init(dem_insert_batch *b) { memset(b, 0, sizeof *b); }

void dem_insert_batch_free(dem_insert_batch *b)
{
    free(b->x); free(b->v); free(b->diameter); free(b->material); free(b->line);
    free(b->q);
    free(b->w);
    memset(b, 0, sizeof *b);
}

long dem_insert_batch_push(dem_insert_batch *b, const double x[3], const double v[3], double diameter, int material, int line)
{
    if (b->n == b->capacity) {
        b->capacity = b->capacity ? 2 * b->capacity : 1024;
        b->x = dem_realloc(b->x, (size_t)b->capacity * sizeof *b->x);
        b->v = dem_realloc(b->v, (size_t)b->capacity * sizeof *b->v);
        b->diameter = dem_realloc(b->diameter, (size_t)b->capacity * sizeof *b->diameter);
        b->material = dem_realloc(b->material, (size_t)b->capacity * sizeof *b->material);
        b->line = dem_realloc(b->line, (size_t)b->capacity * sizeof *b->line);
        b->q = dem_realloc(b->q, (size_t)b->capacity * sizeof *b->q);
        b->w = dem_realloc(b->w, (size_t)b->capacity * sizeof *b->w);
    }
    const long i = b->n++;
    for (int d = 0; d < 3; d++) { b->x[i][d] = x[d]; b->v[i][d] = v[d]; }
    b->diameter[i] = diameter;
    b->material[i] = material;
    b->line[i] = line;
    b->q[i][0] = b->w[i][0] = NAN;   /* the entry's */
    return i;
}

void dem_insert_batch_set_rotation(dem_insert_batch *b, long i, const double q[4], const double w[3])
{
    if (q) memcpy(b->q[i], q, sizeof b->q[i]);
    if (w) memcpy(b->w[i], w, sizeof b->w[i]);
}

typedef struct batch_where {
    const dem_insertion *ins;
    const dem_insert_batch *b;
    const char *file;
    const dem_dict *entry;
    const char *key;
} batch_where;

/* "<file>:<line>: error: <msg>" for a file line, else the entry's key with the point. */
static void batch_fatal(const batch_where *w, long i, const char *fmt, ...)
    __attribute__((format(printf, 3, 4), noreturn));
static void batch_fatal(const batch_where *w, long i, const char *fmt, ...)
{
    char msg[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    const double *x = w->b->x[i];
    if (w->file && w->b->line[i] > 0) {
        char where[4200];
        snprintf(where, sizeof where, "%s:%d", w->file, w->b->line[i]);
        dem_fatal_at(where, "particle at (%.10g %.10g %.10g) m: %s", x[0], x[1], x[2], msg);
    }
    dem_dict_fatal(w->entry, w->key, "insertion '%s': point %ld at (%.10g %.10g %.10g) m: %s", w->ins->name, i + 1,
               x[0], x[1], x[2], msg);
}

long dem_insertion_add_batch(dem_system *s, const dem_insertion *ins, const dem_insert_batch *b,
                         const char *file, const dem_dict *entry, const char *key)
{
    dem_particles *p = &s->p;
    const batch_where w = {ins, b, file, entry, key};
    const int n0 = p->n;
    double dmax = 0.0;
    for (int i = 0; i < p->n; i++) dmax = fmax(dmax, 2.0 * p->radius[i]);
    for (long i = 0; i < b->n; i++) dmax = fmax(dmax, b->diameter[i]);
    if (b->n > 100000000L) batch_fatal(&w, 0, "more than 10^8 particles in one insertion");
    grid g;
    grid_init(&g, s, dmax, p->n + b->n, p->n + b->n);
    for (int i = 0; i < p->n; i++) grid_add(&g, p, i);
    const double tight = 1.0 - 1e-9;   /* touching (a lattice at spacing = diameter) is allowed */
    for (long i = 0; i < b->n; i++) {
        const double *x = b->x[i], r = 0.5 * b->diameter[i];
        for (int d = 0; d < 3; d++)
            if (!(x[d] >= s->domain_min[d] && x[d] <= s->domain_max[d]))
                batch_fatal(&w, i, "the centre lies outside the domain, min (%g %g %g) max (%g %g %g) m",
                            s->domain_min[0], s->domain_min[1], s->domain_min[2],
                            s->domain_max[0], s->domain_max[1], s->domain_max[2]);
        for (int k = 0; k < s->nsymmetry; k++) {
            const double dist = symmetry_distance(&s->symmetry_planes[k], x);
            if (dist < -1e-9 * r)
                batch_fatal(&w, i, "the centre lies %g m beyond symmetryPlane '%s' (centres must be on "
                            "the side its normal points to)", -dist, s->symmetry_planes[k].name);
        }
        for (int k = 0; k < s->nwalls; k++) {
            double gap, en[3];
            if (dem_wall_gap(&s->walls[k], x, r, &gap, en) && gap < -1e-9 * r)
                batch_fatal(&w, i, "the particle (diameter %g m) overlaps wall '%s' by %g m", b->diameter[i],
                            s->walls[k].name, -gap);
        }
        const int j = find_overlap(s, &g, x, r, tight);
        if (j >= 0) {
            const double *y = p->x[j];
            const double dist = sqrt((x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]) + (x[2] - y[2]) * (x[2] - y[2]));
            if (j < n0)
                batch_fatal(&w, i, "overlaps particle id %lld at (%g %g %g) m of an earlier insertion (centre "
                            "distance %g m < sum of radii %g m)", (long long)p->id[j], y[0], y[1], y[2], dist,
                            r + p->radius[j]);
            if (file && b->line[i] > 0)
                batch_fatal(&w, i, "overlaps the particle of line %d (centre distance %.10g m < sum of radii %.10g m)",
                            b->line[j - n0], dist, r + p->radius[j]);
            batch_fatal(&w, i, "overlaps point %d at (%g %g %g) m (centre distance %g m < sum of radii %g m)",
                        j - n0 + 1, y[0], y[1], y[2], dist, r + p->radius[j]);
        }
        const int k = dem_particles_add(p, x, b->v[i], r, s->materials.mat[b->material[i]].density, b->material[i],
                                    s->next_id++);
        if (ins->prescribed) dem_particles_prescribe(p, k);
        grid_add(&g, p, k);
    }
    free(g.head);
    free(g.next);
    return b->n;
}

long dem_insertion_add_body_batch(dem_system *s, const dem_insertion *ins, const dem_insert_batch *b, const char *file)
{
    dem_particles *p = &s->p;
    const dem_clump_template *t = &s->bodies.templates[ins->body - 1];
    double bound;
    const double dmax = body_grid_size(s, t, &bound);
    long capacity = p->n + (b->n + 1) * t->n;
    grid g;
    grid_init(&g, s, dmax, capacity, capacity);
    for (int i = 0; i < p->n; i++) grid_add(&g, p, i);
    dem_rng r;
    rng_seed(&r, ins->seed);
    double (*centre)[3] = dem_malloc((size_t)t->n * sizeof *centre);
    for (long i = 0; i < b->n; i++) {
        char where[4200];
        if (b->line[i] > 0) snprintf(where, sizeof where, "%s:%d", file, b->line[i]);
        else snprintf(where, sizeof where, "%s: lattice point %ld", file, i + 1);   /* file: the entry's file:line */
        double q[4];
        const int own = !isnan(b->q[i][0]);
        start_orientation(ins, own ? b->q[i] : NULL, &r, q);
        dem_body_sphere_centres(t, b->x[i], q, centre);
        for (int k = 0; k < t->n; k++) {
            for (int d = 0; d < 3; d++)
                if (!(centre[k][d] - t->radius[k] >= s->domain_min[d] && centre[k][d] + t->radius[k] <= s->domain_max[d]))
                    dem_fatal_at(where, "body '%s' at (%g %g %g) m: its sphere %d leaves the domain", t->name,
                                 b->x[i][0], b->x[i][1], b->x[i][2], k + 1);
            if (overlaps(s, &g, centre[k], t->radius[k]))
                dem_fatal_at(where, "body '%s' at (%g %g %g) m (orientation (%g %g %g %g)%s): its sphere %d "
                             "overlaps a wall, a mirror or a particle placed before", t->name, b->x[i][0], b->x[i][1],
                             b->x[i][2], q[0], q[1], q[2], q[3],
                             own || ins->orientation_given ? "" : ", drawn at random", k + 1);
        }
        dem_bodies_add(s, ins->body - 1, b->x[i], q, b->v[i], isnan(b->w[i][0]) ? ins->angular_velocity : b->w[i]);
        for (int j = p->n - t->n; j < p->n; j++) grid_add(&g, p, j);
    }
    free(centre);
    free(g.head);
    free(g.next);
    return b->n;
}
