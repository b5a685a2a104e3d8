/* Multisphere bodies: rigid clumps of spheres (docs/models/multisphere.md).
 *
 * A template is the clump's spheres in its own frame, reduced once to mass properties
 * (clump_mass.h) and to the spheres' centres in the principal frame. A body is a template placed
 * in the system: centre of mass X, velocity V, orientation q (principal frame to space), angular
 * momentum L_b in the principal frame (rigid_rotation.h). Its spheres are ordinary particles
 * (field `body` = 1 + the body's id, `body_offset` = the centre in the principal frame), so
 * the neighbour list, the contact models, the walls and the output treat them as spheres; the
 * list leaves out pairs of one body.
 *
 * A body's id is global and never reused; its index in the table below is local and changes as
 * bodies are removed. The spheres name their body by id (dem_body_index finds the index), so that
 * a sphere keeps its body when the table is renumbered, and when it moves to another process.
 *
 * In a parallel run (issue 23) a body and all its spheres belong to the rank whose box holds the
 * body's centre (migrate.h sends them together, the body packed by dem_bodies_pack), so that the
 * step's kick, drift and force sum stay local. A sphere may then lie outside its rank's box; the
 * halo (ghosts.h) sends to each rank what lies within the cutoff of the spheres it holds, so a
 * contact with another rank's particle is found where the rule of neighbour.c wants it. The
 * forces other ranks compute on a sphere's ghost come back with the halo's fold before the sum.
 *
 * Each sphere carries the body's mass (so a contact's effective mass m* and the time-step check
 * see the body: LIGGGHTS' fix multisphere does the same) and moves with the body: after each
 * drift its centre is X + R(q) offset, its velocity V + omega x R(q) offset and its angular
 * velocity omega = R(q) L_b / I (seed 004 eq. 4). The spheres' forces and torques are summed
 * onto the body, gravity once with the body's mass, and the body takes the velocity-Verlet step
 * (translation) and the split free rotor between two torque kicks (rotation).
 *
 * Not yet: periodic directions and symmetry planes with bodies (refused). */
#ifndef DEM_BODIES_H
#define DEM_BODIES_H

#include <stdint.h>

#include "clump_mass.h"
#include "io.h"
#include "particles.h"

typedef struct dem_clump_template {
    char name[64];
    int n;                      /* spheres */
    double (*offset)[3];        /* centres in the principal frame, from the centre of mass [m] */
    double *radius;             /* [m] */
    int type;                   /* material index */
    double q_axes[4];           /* principal frame to the template's own frame */
    double volume_scale;        /* the body's volume / the sum of its spheres' (< 1 with overlaps, union) */
    double inv_principal[3];    /* 1 / the principal moments [1/(kg m^2)] */
    dem_clump_mass mass;        /* mass, inertia, principal moments (template frame) */
} dem_clump_template;

typedef struct dem_bodies {
    int ntemplates;
    dem_clump_template *templates;
    int n, capacity;
    int64_t next_id;            /* ids stay unique as bodies come and go */
    int *index_of;              /* id -> index in this table, -1 for a body not here */
    int64_t index_capacity;     /* ids below it have an entry in index_of */
    int *template_of;
    int64_t *id;
    dem_vec3 *x, *v;            /* centre of mass [m], its velocity [m/s] */
    double (*q)[4];             /* orientation: principal frame to space */
    dem_vec3 *Lb;               /* angular momentum, principal frame [kg m^2/s] */
    dem_vec3 *f, *torque;       /* total force [N] and torque about the centre [N m] of the step */
    double (*R)[3][3];          /* R(q), kept with q: the rotation of the body frame into space */
    dem_vec3 *w;                /* angular velocity in space [rad/s], kept with L_b */
} dem_bodies;

/* The index of the body that a sphere's `body` field (1 + id, > 0) names, or -1 if it is not in
 * this table */
static inline int dem_body_lookup(const dem_bodies *b, int body)
{
    return body - 1 < b->index_capacity ? b->index_of[body - 1] : -1;
}
/* The same, fatal when the body is not here (a sphere must be where its body is) */
_Noreturn void dem_body_not_here(const dem_bodies *b, int body);
static inline int dem_body_index(const dem_bodies *b, int body)
{
    const int k = dem_body_lookup(b, body);
    if (k < 0) dem_body_not_here(b, body);
    return k;
}

/* Body k's mass [kg] (its template's) */
static inline double dem_body_mass(const dem_bodies *b, int k) { return b->templates[b->template_of[k]].mass.mass; }

struct dem_system;
void dem_bodies_free(dem_bodies *b);
/* A template from its spheres in its own frame; density in kg/m^3; model: union or sphereSum
 * (union to 1 % of its volume, clump_mass.h). Returns its index. */
int dem_bodies_add_template(dem_bodies *b, const char *name, int n, const double (*x)[3], const double *radius,
                            int type, double density, enum dem_clump_mass_model model);
/* A body of template t with its centre of mass at x, the template's frame turned by q_frame
 * (unit quaternion; template frame to space), velocity v [m/s] and angular velocity w [rad/s]
 * (space frame); its spheres are appended to the particles. Returns the body's index. */
int dem_bodies_add(struct dem_system *s, int t, const double x[3], const double q_frame[4], const double v[3],
                   const double w[3]);

/* A body as migration sends it (migrate.h): id, template, centre, velocity, orientation, angular
 * momentum, force and torque (bytes: dem_bodies_pack_size()); R and omega are made again from them
 * on arrival, as every step makes them. */
size_t dem_bodies_pack_size(void);
size_t dem_bodies_pack(const dem_bodies *b, int k, void *buf);
void dem_bodies_unpack(dem_bodies *b, const void *buf);
/* Body k's centre of mass [m] */
static inline const double *dem_body_centre(const dem_bodies *b, int k) { return b->x[k]; }

/* Remove the bodies k with gone[k] (their spheres must have been removed from the particles
 * already: lifecycle.h removes a body as one unit); the last body takes a removed one's index
 * (its spheres keep its id). */
void dem_bodies_remove(struct dem_system *s, const unsigned char *gone);

/* The step's parts (system.c calls them): first half kick and drift of each body, its spheres
 * put where it is; after the forces, their sum onto the bodies (also at set-up); the second half
 * kick, the spheres' velocities from it. */
void dem_bodies_kick_drift(struct dem_system *s);
void dem_bodies_sum_forces(struct dem_system *s);
void dem_bodies_kick(struct dem_system *s);
/* The bodies as a snapshot holds them (io.h), with each body's rotational energy (seed 004
 * eq. 8); and back, at a restart: the body table rebuilt (the templates come from the case) and
 * the spheres' masses set to their body's. Fatal, naming `where`, when the snapshot does not fit
 * the case's templates. */
void dem_bodies_to_state(const struct dem_system *s, dem_body_state *state);
void dem_bodies_from_state(struct dem_system *s, const dem_body_state *state, const char *where);
/* Particle i's volume [m^3]: 4/3 pi r^3, for a body's sphere scaled so that the body's spheres
 * sum to its volume (the coupling: void fraction, buoyancy, drag per unit volume). */
double dem_particle_volume(const struct dem_system *s, int i);
/* A body's angular velocity in space [rad/s] */
void dem_body_omega(const dem_bodies *b, int k, double w[3]);
/* Translational + rotational kinetic energy of all bodies [J] (eq. 8 with the principal tensor) */
double dem_bodies_kinetic_energy(const struct dem_system *s);
/* Their rotational energy alone, summed over the bodies [J] (seed 004 eq. 8) */
double dem_bodies_rotational_energy(const struct dem_system *s);
/* The centres of template t's spheres for a body with its centre of mass at x and the template's
 * frame turned by q_frame (template frame to space), as dem_bodies_add places them [m]. */
void dem_body_sphere_centres(const dem_clump_template *t, const double x[3], const double q_frame[4],
                             double (*centre)[3]);

#endif
