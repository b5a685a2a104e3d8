/* Walls: planes (infinite or bounded), and cylinders (particles inside or outside).
 * An axis-aligned box wall is expanded into six bounded planes when the case is read.
 * Wall contacts use the same normal/tangential models as particle pairs, with R_j and m_j
 * taken as infinite (R* = R_i, m* = m_i).
 * Moving walls: a plane (or box) translates at a constant velocity, its position a function of
 * the time (point(t) = point(0) + velocity t, so a restart puts it back exactly); a cylinder
 * turns about its own axis at a constant angular velocity (its shape does not change, only its
 * surface moves). The wall's surface velocity at the contact point enters the contact's relative
 * velocity (tangential history, damping) and a turning cylinder's angular velocity the rolling
 * models' relative rotation. */
#ifndef DEM_WALLS_H
#define DEM_WALLS_H

enum dem_wall_kind { WALL_PLANE, WALL_CYLINDER };

typedef struct dem_wall {
    char name[96];
    enum dem_wall_kind kind;
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
    /* motion */
    double velocity[3];                    /* plane: translation [m/s] */
    double angular_velocity;               /* cylinder: about its axis, right-handed [rad/s] */
    double point0[3], bounds0_min[3], bounds0_max[3];   /* plane at t = 0 (dem_wall_set_velocity) */
    double point_at_build[3];              /* where the candidate list was built */
} dem_wall;

/* The particles within radius + skin (+ the normal model's reach) of one wall, refreshed at each
 * neighbour-list build, each with its contact history beside it. */
typedef struct dem_wall_contacts {
    int n, capacity;
    int *particle;               /* particle indices */
    double *history;             /* history_size doubles per candidate */
    unsigned char *touching;     /* in contact at the last force computation */
    double force[3];             /* this wall's force on the particles in the last step [N] */
} dem_wall_contacts;

struct dem_system;
/* Append a wall (its fields zeroed) to the system; there is no limit on their number. */
dem_wall *dem_walls_add(struct dem_system *s);
void dem_walls_free(struct dem_system *s);
/* Add wall forces to p->f / p->torque (kernel chosen once per model combination). */
void dem_walls_add_forces(struct dem_system *s);
/* Refresh each wall's list of particles within radius + skin (after a neighbour build); the
 * histories start at zero (contacts.c puts back those of continuing contacts). */
void dem_walls_build_candidates(struct dem_system *s);
/* A translating plane: velocity [m/s]; the wall's present point and bounds are its t = 0 ones. */
void dem_wall_set_velocity(dem_wall *w, const double velocity[3]);
/* Place the translating walls at time t; returns 1 if one has moved more than half the skin
 * since its candidate list was built (the lists must then be rebuilt). */
int dem_walls_move(struct dem_system *s, double t);
/* The wall's surface velocity at point xc [m/s]. */
void dem_wall_surface_velocity(const dem_wall *w, const double xc[3], double u[3]);

/* Signed gap from a sphere surface to the wall (negative: overlap) and the unit normal from the
 * wall to the centre; returns 0 if the wall does not act at this position (outside bounds). */
int dem_wall_gap(const dem_wall *w, const double x[3], double radius, double *gap, double en[3]);

#endif
