/* Insertion: fill a region once, at t = 0, without overlaps. Three methods:
 *   random   random sequential placement into a box or cylinder region, a given number or up
 *            to a solid fraction, with a size distribution (insert.c); or multisphere bodies of
 *            one template, each turned to a uniformly random orientation;
 *   lattice  the points of a simple cubic (or rectangular) lattice in a box or cylinder region,
 *            all of them or the lowest `number` along gravity (insert_lattice.c);
 *   file     positions (and optionally diameters, velocities, materials) read from a file,
 *            whitespace columns or OpenFOAM's vectorField (insert_file.c).
 * Lattice and file particles go through dem_insertion_add_batch(), which checks each one against
 * the domain, the walls, the symmetry planes and every particle already placed (O(N), on a
 * grid) and stops with a message that names the offending point or file line. */
#ifndef DEM_INSERT_H
#define DEM_INSERT_H

#include <stdint.h>

#include "particles.h"
#include "rng.h"

enum dem_insertion_method { INSERT_RANDOM, INSERT_LATTICE, INSERT_FILE, INSERT_STREAM };
enum dem_size_distribution { SIZE_CONSTANT, SIZE_UNIFORM, SIZE_NORMAL, SIZE_DISCRETE };
enum dem_region_kind { REGION_BOX, REGION_CYLINDER };

typedef struct dem_insertion {
    char name[64];
    char source[4200];              /* "file:line" of the entry, for errors found while inserting */
    enum dem_insertion_method method;
    enum dem_region_kind region;
    double min[3], max[3];          /* box; for a cylinder the axial range is min/max[axis] */
    int axis;                       /* cylinder */
    double centre[2], radius;       /* cylinder */
    long number;                    /* > 0: this many particles (lattice: the lowest this many; 0: all) */
    double solid_fraction;          /* random: else fill to this solid fraction of the region */
    int material;                   /* -1: none given (file: then every line must name one) */
    int body;                       /* 1 + the multisphere template (bodies.h) to insert; 0: spheres */
    int orientation_given;          /* bodies: 1: every one turned by `orientation`; 0: each at random */
    double orientation[4];          /* bodies: unit quaternion, the template's frame to space */
    double angular_velocity[3];     /* bodies: [rad/s], in space */
    double velocity[3];
    int prescribed;                 /* 1: velocity is prescribedVelocity (the particles keep it) */
    int has_diameter;               /* file: a diameter entry was given */
    enum dem_size_distribution dist;
    double d_value, d_min, d_max, d_mean, d_std;  /* diameters [m] */
    int ndiscrete;
    double *d_values, *d_weights;
    uint64_t seed;
    int max_attempts;
    double spacing[3];              /* lattice [m] */
    double down[3];                 /* lattice: unit vector along gravity (-z without gravity) */
    char file[4096];                /* file: the resolved path */
} dem_insertion;

/* Particles given one by one (lattice points, file lines), before they are placed. */
typedef struct dem_insert_batch {
    long n, capacity;
    dem_vec3 *x, *v;
    double *diameter;               /* [m] */
    int *material;
    int *line;                      /* file line of each particle (file insertions) */
    double (*q)[4];                 /* bodies: an orientation of its own (q[i][0] NaN: the entry's) */
    dem_vec3 *w;                    /* bodies: an angular velocity of its own [rad/s] (NaN: the entry's) */
} dem_insert_batch;

void dem_insert_batch_init(dem_insert_batch *b);
void dem_insert_batch_free(dem_insert_batch *b);
long dem_insert_batch_push(dem_insert_batch *b, const double x[3], const double v[3], double diameter, int material, int line);
/* Body i of the batch with an orientation (unit quaternion, template frame to space) and an
 * angular velocity [rad/s] of its own; either may be NULL (the entry's) */
void dem_insert_batch_set_rotation(dem_insert_batch *b, long i, const double q[4], const double w[3]);

struct dem_system;
struct dem_dict;
/* Random insertion; fatal (naming the insertion) when the particles do not fit. Returns the count. */
long dem_insertion_run(struct dem_system *s, const dem_insertion *ins);
double dem_insertion_max_diameter(const dem_insertion *ins);
double dem_insertion_min_diameter(const dem_insertion *ins);
double dem_insertion_region_volume(const dem_insertion *ins);   /* [m^3] */   /* the smallest it may draw [m] */
/* A centre in the insertion's region, a radius inside its sides. */
void dem_insertion_draw_position(const dem_insertion *ins, double radius, dem_rng *r, double x[3]);

/* Placing particles one at a time among those already there (and walls and mirrors), on a grid
 * over the domain of cells no smaller than dmax or the largest particle present; room for
 * `extra` more (it grows). */
typedef struct dem_placement dem_placement;
dem_placement *dem_placement_begin(const struct dem_system *s, double dmax, long extra);
/* The same against the particles of p (not the system's own: a parallel stream places against
 * the particles of every rank near its face, gathered; insert_stream.c) */
dem_placement *dem_placement_begin_on(const struct dem_system *s, const dem_particles *p, double dmax, long extra);
/* 1 if a sphere of `radius` at x overlaps no particle, wall or mirror */
int dem_placement_free(const dem_placement *pl, const struct dem_system *s, const double x[3], double radius);
/* particle i (just added) among those the next look-ups see */
void dem_placement_add(dem_placement *pl, const struct dem_system *s, int i);
void dem_placement_end(dem_placement *pl);
double dem_insertion_draw_diameter(const dem_insertion *ins, dem_rng *r);

/* Lattice points of the region, in order (x fastest, then y, then z), keeping the lowest
 * ins->number along ins->down when number > 0. Fatal (naming `key` of `entry`) when the
 * lattice holds fewer points. Returns the count; *xyz malloc'd, 3 doubles per point. */
long dem_lattice_points(const dem_insertion *ins, const struct dem_dict *entry, double **xyz);
/* Lattice insertion: the points, diameters drawn from the distribution (seed), checked and placed. */
long dem_insertion_lattice(struct dem_system *s, const dem_insertion *ins, const struct dem_dict *entry);

/* Read a positions file into b (formats in insert_file.c); fatal with "<file>:<line>: ..." on
 * any error. Columns missing from a line take the insertion's diameter, velocity, material. */
void dem_insert_file_read(const struct dem_system *s, const dem_insertion *ins, dem_insert_batch *b);
/* Multisphere bodies of template ins->body - 1 at the batch's points (centres of mass), each at a
 * random orientation (ins->seed), checked as dem_insertion_add_batch checks spheres: fatal naming
 * the file line of a body whose sphere leaves the domain or overlaps a wall or a particle. */
long dem_insertion_add_body_batch(struct dem_system *s, const dem_insertion *ins, const dem_insert_batch *b,
                                  const char *file);
/* File insertion: read, check and place. */
long dem_insertion_file(struct dem_system *s, const dem_insertion *ins, const struct dem_dict *entry);

/* Check each particle of b (centre inside the domain, on the particle side of every symmetry
 * plane, no wall overlap, no overlap with any particle placed before or earlier in b: centre
 * distance >= (r_i + r_j)(1 - 1e-9)) and add it. Errors name file:line when b->line is set and
 * `file` is given, else the point and `key` of `entry`. Returns the count. */
long dem_insertion_add_batch(struct dem_system *s, const dem_insertion *ins, const dem_insert_batch *b,
                         const char *file, const struct dem_dict *entry, const char *key);

#endif
