/* Outlets: a plane or a box that removes every unit (a free sphere, or a multisphere body as
 * one) whose centre is beyond it or inside it, counting per outlet the number and mass removed
 * (LIGGGHTS' fix massflow/mesh with delete_atoms, Lethe's outlet boundary). An outlet acts in the
 * step whose drift carried the centre across (lifecycle.h), or, with an `interval`, in the steps
 * that are multiples of interval / dt: each removal remakes the lists, and a stream of fine
 * particles crossing an outlet every few steps would otherwise rebuild them every few steps
 * (the units beyond it meanwhile go on as before; they must not reach the domain's side). The
 * steps are counted from the run's start, so a restart removes in the same steps. */
#ifndef DEM_OUTLETS_H
#define DEM_OUTLETS_H

#include "lifecycle.h"

enum dem_outlet_kind { OUTLET_PLANE, OUTLET_BOX };

typedef struct dem_outlet {
    char name[64];
    enum dem_outlet_kind kind;
    double point[3], normal[3];   /* plane: a centre with (x - point) . normal > 0 is out (unit normal, outwards) */
    double min[3], max[3];        /* box: a centre inside is out [m] */
    long every;                   /* acts in the steps that are multiples of it (1: every step) */
    dem_tally removed;            /* since the run began (restart: from the snapshot) */
    dem_tally logged;             /* at the last log, and its time: the rate between logs */
    double logged_time;
} dem_outlet;

struct dem_system;
/* 1 if a centre at x is out through o */
static inline int dem_outlet_takes(const dem_outlet *o, const double x[3])
{
    if (o->kind == OUTLET_PLANE)
        return (x[0] - o->point[0]) * o->normal[0] + (x[1] - o->point[1]) * o->normal[1] +
               (x[2] - o->point[2]) * o->normal[2] > 0.0;
    return x[0] >= o->min[0] && x[0] <= o->max[0] && x[1] >= o->min[1] && x[1] <= o->max[1] &&
           x[2] >= o->min[2] && x[2] <= o->max[2];
}
/* An outlet appended to the system (name, kind and geometry set by the caller); returns it. */
dem_outlet *dem_outlets_add(struct dem_system *s, const char *name);
/* Whether some unit is out through some outlet that acts in step `step`. */
int dem_outlets_any(const struct dem_system *s, long step);
/* Remove every unit that is out through an outlet acting in step `step`, counted by the first
 * such outlet (in the case's order) that takes it. */
void dem_outlets_remove(struct dem_system *s, long step);

#endif
