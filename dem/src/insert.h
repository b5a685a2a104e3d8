/* Insertion: fill a box or cylinder region once with non-overlapping spheres (random
 * sequential placement), a given number or up to a solid fraction, with a size distribution. */
#ifndef DEM_INSERT_H
#define DEM_INSERT_H

#include <stdint.h>

enum size_distribution { SIZE_CONSTANT, SIZE_UNIFORM, SIZE_NORMAL, SIZE_DISCRETE };
enum region_kind { REGION_BOX, REGION_CYLINDER };

typedef struct insertion {
    char name[64];
    enum region_kind region;
    double min[3], max[3];          /* box; for a cylinder the axial range is min/max[axis] */
    int axis;                       /* cylinder */
    double centre[2], radius;       /* cylinder */
    long number;                    /* > 0: this many particles */
    double solid_fraction;          /* else: fill to this solid fraction of the region */
    int material;
    double velocity[3];
    enum size_distribution dist;
    double d_value, d_min, d_max, d_mean, d_std;  /* diameters [m] */
    int ndiscrete;
    double *d_values, *d_weights;
    uint64_t seed;
    int max_attempts;
} insertion;

struct dem_system;
/* Insert; fatal (naming the insertion) when the particles do not fit. Returns the count. */
long insertion_run(struct dem_system *s, const insertion *ins);
double insertion_max_diameter(const insertion *ins);

#endif
