/* Insertion during the run: a stream of particles at a mass or number rate, through a plane
 * face or into a region, between a start and an end time (LIGGGHTS' fix insert/stream and
 * insert/rate/region, Lethe's plane insertion).
 *
 * Every `insertInterval` (a whole number of steps) an insertion event places what is due by the
 * end of that interval: for a rate R from startTime, R (m + 1) interval at the m-th event (until
 * endTime). Each particle draws its diameter, then up to maxAttempts positions:
 *   face    a slab in front of the face, of the depth the stream moves in one interval
 *           (v . n x interval): the particles of the last event have moved out of it by then;
 *           the centre at least a radius inside the face and its rim;
 *   region  anywhere in the box or cylinder, a radius inside its sides;
 * and takes the first that overlaps no particle, wall or mirror. A particle that finds no place
 * ends the event: it is tried first at the next one (its diameter kept), and what is still due
 * is carried over and counted (logged at every write), never dropped: events go on after
 * endTime until nothing is due. A mass rate inserts until the mass inserted reaches the mass
 * due (at most one particle over).
 *
 * Velocity: the given vector, plus a normal scatter of velocityStdDev per component. The face's
 * normal points into the domain; the velocity must cross the face inwards.
 *
 * Restart: the random stream, the counts, the carried particle and what is behind are in each
 * snapshot (io.h), so a restarted run inserts the same particles at the same steps. */
#ifndef DEM_INSERT_STREAM_H
#define DEM_INSERT_STREAM_H

#include "insert.h"
#include "lifecycle.h"
#include "rng.h"

enum dem_stream_shape { STREAM_REGION, STREAM_DISC, STREAM_RECTANGLE };

typedef struct dem_stream {
    dem_insertion ins;            /* name, source, material, diameters, velocity, seed, maxAttempts; the region */
    enum dem_stream_shape shape;
    double centre[3], normal[3];  /* the face: a point of it (a disc's centre) and the unit normal into the domain */
    double radius;                /* disc [m] */
    double e1[3], e2[3];          /* disc: two unit vectors in its plane */
    double fmin[3], fmax[3];      /* rectangle: its bounds (min = max along the normal) [m] */
    int axis;                     /* rectangle: the normal's axis */
    double area;                  /* face [m^2] */
    double depth;                 /* face: slab depth, (v . n) x interval [m] */
    double mass_rate, number_rate;/* [kg/s], [1/s]: the one given, the other 0 */
    double velocity_std;          /* [m/s] per component */
    double start_time, end_time;  /* [s] */
    double interval;              /* insertInterval [s]; 0: the default (face: the slab 1.5 largest diameters deep; region: 100 steps) */
    long every;                   /* steps between events */
    long start_step, end_step;    /* the first event's step; the last step an event may take */
    double max_solid_fraction;    /* the rate check's: face rate <= this x area x v.n */
    double mean_volume;           /* of the diameter distribution [m^3] */
    /* the state a restart continues with (in each snapshot) */
    dem_rng rng;
    dem_tally inserted;
    double pending_diameter;      /* the particle that found no place, tried first at the next event; 0: none [m] */
    int64_t carried_total;        /* particles that found no place at the event they were due at (a mass rate's: in
                                     particles of the mean mass) */
    int64_t behind_count;         /* still due after the last event [particles] (a mass rate's: of the mean mass) */
    double behind_mass;           /* still due after the last event [kg] (mass rate) */
    /* at the last log: the rate between logs */
    dem_tally logged;
    double logged_time;
} dem_stream;

struct dem_system;
/* A stream appended to the system, zeroed; the caller fills it and calls dem_stream_prepare. */
dem_stream *dem_streams_add(struct dem_system *s);
/* After the stream's settings and the system's time step are set: the event schedule, the slab,
 * the mean particle volume, the random stream. */
void dem_stream_prepare(const struct dem_system *s, dem_stream *st);
/* The largest rate (in the units of the one given: kg/s or particles/s) that a face stream can
 * carry: maxSolidFraction x area x (velocity . normal) in volume; INFINITY for a region. */
double dem_stream_largest_rate(const struct dem_system *s, const dem_stream *st);
/* Whether an event of some stream falls on step `step`. */
int dem_streams_due(const struct dem_system *s, long step);
/* The events of step `step` (positions as at its end): the due particles placed. */
void dem_streams_insert(struct dem_system *s, long step);
/* The smallest and largest diameter any stream of material `type` (-1: any) may insert [m];
 * *dmin = INFINITY, *dmax = 0 when none. */
void dem_streams_diameters(const struct dem_system *s, int type, double *dmin, double *dmax);
/* The fastest speed a stream gives a particle: |velocity| + 4 velocityStdDev [m/s]. */
double dem_streams_max_speed(const struct dem_system *s);
void dem_streams_free(struct dem_system *s);

#endif
