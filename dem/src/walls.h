/* Static walls: planes (infinite or bounded), and cylinders (particles inside or outside).
 * An axis-aligned box wall is expanded into six bounded planes when the case is read.
 * Wall contacts use the same normal/tangential models as particle pairs, with R_j and m_j
 * taken as infinite (R* = R_i, m* = m_i). */
#ifndef DEM_WALLS_H
#define DEM_WALLS_H

#define DEM_MAX_WALLS 32

enum wall_kind { WALL_PLANE, WALL_CYLINDER };

typedef struct wall {
    char name[96];
    enum wall_kind kind;
    int material;
    /* plane */
    double point[3], normal[3];            /* unit normal pointing into the particle side */
    int bounded;
    double bounds_min[3], bounds_max[3];   /* contact only where the projected centre is inside */
    /* cylinder */
    int axis;                              /* 0 x, 1 y, 2 z */
    double centre[2];                      /* the two other coordinates, in order */
    double radius;
    int inside;                            /* particles inside (1) or outside (0) */
    double axial_min, axial_max;           /* extent along the axis */
} wall;

struct dem_system;
/* Add wall forces to p->f / p->torque (kernel chosen once per model combination). */
void walls_add_forces(struct dem_system *s);
/* Refresh each wall's list of particles within radius + skin (after a neighbour build). */
void walls_build_candidates(struct dem_system *s);
/* Signed gap from a sphere surface to the wall (negative: overlap) and the unit normal from the
 * wall to the centre; returns 0 if the wall does not act at this position (outside bounds). */
int wall_gap(const wall *w, const double x[3], double radius, double *gap, double en[3]);

#endif
