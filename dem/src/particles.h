/* Particle storage: a structure of arrays, one array per quantity. Vector quantities are
 * stored as double[3] per particle, so that a neighbour's position is one cache line.
 *
 * Every per-particle quantity is named once, in PARTICLE_FIELDS below; the struct's members,
 * allocation, zeroing of a new particle, sorting, copying, packing for another rank, the HDF5
 * snapshot, the XDMF index and the restart all come from that list. A new field is one line. */
#ifndef DEM_PARTICLES_H
#define DEM_PARTICLES_H

#include <stddef.h>
#include <stdint.h>
#include <string.h>

typedef double dem_vec3[3];

/* What happens to a field besides living in memory:
 *   PF_WRITE    in every HDF5 snapshot and in the XDMF index (ParaView shows it)
 *   PF_RESTART  in every HDF5 snapshot and read back on restart: needed to continue exactly
 *   PF_MIGRATE  moved with the particle when it changes rank (else the arriving particle has 0)
 * and what a ghost (a periodic image, or a particle of another rank near this one's border,
 * ghosts.h) carries of it:
 *   PF_BORDER   copied once, when the ghost is made: what the pair kernel reads of a partner
 *   PF_FORWARD  copied again before every force computation: what changes each step
 *   PF_REVERSE  summed back onto the owner after the pair forces (doubles only): the ghost's
 *               share of the owner's forces; zeroed on the ghosts by every forward copy */
enum { PF_WRITE = 1, PF_RESTART = 2, PF_MIGRATE = 4, PF_BORDER = 8, PF_FORWARD = 16, PF_REVERSE = 32 };

/* X(member, element, unit, dataset, flags)
 *   member   the struct's member: an array with one element per particle
 *   element  vec3, double, int or int64 (the components and the HDF5 type follow from it)
 *   unit     SI unit ("1": a pure number or an index), the dataset's `units` attribute
 *   dataset  the name in the snapshot and the XDMF index (kept from the first file format)
 * Why the flags are as they are:
 *   - f and torque are a restart field because the snapshot's forces were computed with the
 *     step's contact history; evaluating them again on restart would add the last tangential
 *     increment twice (restart.c). They migrate: the next step's first half kick uses them.
 *   - mass and the inverses follow from radius and the material's density: recomputed on
 *     restart (dem_restart_read), moved along on migration (cheaper than looking up the material).
 *   - prescribed particles (a piston, a probe) keep their velocity whatever the forces: their
 *     inverse mass and inertia are 0, so the integrator's kicks leave them as they are and the
 *     drift moves them; their forces are still computed (and written). A restart field, since
 *     the inverses are recomputed from it.
 *   - A ghost carries what the pair kernel reads of a partner (pair_forces.c, neighbour.c):
 *     position, velocity and spin (BORDER and FORWARD), radius, mass, inverse inertia, type,
 *     id (the contact history's key) and body (no contact within one body) once; it gives
 *     back its force and torque (REVERSE). Nothing else of a ghost is read: walls, bodies,
 *     integration, output and the coupling see only the real particles.
 *   - The coupling's fields (coupling/src/coupling.c): beta and f_fluid are set at the end of
 *     each fluid step's DEM steps, where the fluid receives them (its K_sl and explicit source),
 *     and the particles feel them through the next fluid step: a restart field, so that a
 *     continued run feels what the fluid of its start time received. u_fluid and f_pgrad are
 *     taken again from the fluid field at the start of every fluid step. fluid_cell is only
 *     where the search for the particle's cell starts (0 is as good a start as any), and a cell
 *     number of one rank's mesh means nothing on another: it does not migrate. */
#define PARTICLE_FIELDS(X)                                                                      \
    X(x,           dem_vec3,   "m",        "position",        PF_WRITE | PF_RESTART | PF_MIGRATE | PF_BORDER | PF_FORWARD) \
    X(v,           dem_vec3,   "m/s",      "velocity",        PF_WRITE | PF_RESTART | PF_MIGRATE | PF_BORDER | PF_FORWARD) \
    X(omega,       dem_vec3,   "rad/s",    "omega",           PF_WRITE | PF_RESTART | PF_MIGRATE | PF_BORDER | PF_FORWARD) \
    /* total force and torque of this step */                                                  \
    X(f,           dem_vec3,   "N",        "force",           PF_WRITE | PF_RESTART | PF_MIGRATE | PF_REVERSE) \
    X(torque,      dem_vec3,   "N m",      "torque",          PF_RESTART | PF_MIGRATE | PF_REVERSE)  \
    /* external force held between exchanges (the fluid force in a coupled run) */             \
    X(f_ext,       dem_vec3,   "N",        "external_force",  PF_MIGRATE)                            \
    X(radius,      double, "m",        "radius",          PF_WRITE | PF_RESTART | PF_MIGRATE | PF_BORDER) \
    X(mass,        double, "kg",       "mass",            PF_MIGRATE | PF_BORDER)                \
    X(inv_mass,    double, "1/kg",     "inverse_mass",    PF_MIGRATE)                            \
    /* 1 / (2/5 m r^2) */                                                                      \
    X(inv_inertia, double, "1/(kg m^2)", "inverse_inertia", PF_MIGRATE | PF_BORDER)              \
    /* material index */                                                                       \
    X(type,        int,    "1",        "type",            PF_WRITE | PF_RESTART | PF_MIGRATE | PF_BORDER) \
    /* global id, stable across sorting, restarts and ranks */                                 \
    X(id,          int64,  "1",        "id",              PF_WRITE | PF_RESTART | PF_MIGRATE | PF_BORDER) \
    /* 1: moves at its velocity whatever the forces (insertion's prescribedVelocity) */          \
    X(prescribed,  int,    "1",        "prescribed",      PF_WRITE | PF_RESTART | PF_MIGRATE)    \
    /* multisphere: 1 + the global id of the body this sphere belongs to (bodies.h), 0 for a    \
     * free sphere; its centre in the body's principal frame, relative to the centre of mass */ \
    X(body,        int,    "1",        "body",            PF_WRITE | PF_RESTART | PF_MIGRATE | PF_BORDER) \
    X(body_offset, dem_vec3,   "m",        "body_offset",     PF_RESTART | PF_MIGRATE)               \
    /* coupling: the fluid cell of the centre at the last exchange (-1: outside the mesh) */   \
    X(fluid_cell,  int,    "1",        "fluid_cell",      0)                                     \
    /* coupling: the fluid force is beta (u_fluid - v) + f_fluid + f_pgrad; beta (0 when      \
     * explicit) and f_fluid (the exchanged part that does not depend on v) as the fluid        \
     * received them, u_fluid and f_pgrad (model A's -V_p grad p) from the current field */    \
    X(beta,        double, "kg/s",     "drag_coefficient", PF_RESTART | PF_MIGRATE)              \
    X(u_fluid,     dem_vec3,   "m/s",      "fluid_velocity",  PF_WRITE | PF_MIGRATE)                 \
    X(f_fluid,     dem_vec3,   "N",        "fluid_force_fixed", PF_RESTART | PF_MIGRATE)             \
    X(f_pgrad,     dem_vec3,   "N",        "pressure_gradient_force", PF_MIGRATE)

/* The element types the list may use: C type, components, scalar kind. */
#define PF_CTYPE_dem_vec3 dem_vec3
#define PF_CTYPE_double double
#define PF_CTYPE_int int
#define PF_CTYPE_int64 int64_t
#define PF_COMPONENTS_dem_vec3 3
#define PF_COMPONENTS_double 1
#define PF_COMPONENTS_int 1
#define PF_COMPONENTS_int64 1
#define PF_SCALAR_dem_vec3 PF_DOUBLE
#define PF_SCALAR_double PF_DOUBLE
#define PF_SCALAR_int PF_INT
#define PF_SCALAR_int64 PF_INT64

enum dem_particle_scalar { PF_DOUBLE, PF_INT, PF_INT64 };

typedef struct dem_particles {
    int n;                 /* particles in use */
    int capacity;
    /* Bumped whenever the set of particles or their order changes (add, remove, permute,
     * unpack): whatever is kept per particle index outside this table (the neighbour list, the
     * ghosts, the wall lists, the coupling's weights and tetrahedra) was made for one generation
     * and is stale when the number differs. A count cannot tell: one removal plus one insertion
     * leaves it as it was. */
    long generation;
#define PF_MEMBER(member, element, unit, dataset, flags) PF_CTYPE_##element *member;
    PARTICLE_FIELDS(PF_MEMBER)
#undef PF_MEMBER
} dem_particles;

/* Index of each field in dem_particle_fields[]: PF_FIELD_x, PF_FIELD_v, ... */
enum dem_particle_field_index {
#define PF_INDEX(member, element, unit, dataset, flags) PF_FIELD_##member,
    PARTICLE_FIELDS(PF_INDEX)
#undef PF_INDEX
    PARTICLE_FIELD_COUNT
};

/* One field, for code that treats them all alike (I/O, packing). */
typedef struct dem_particle_field {
    const char *member;          /* the C name */
    const char *dataset;         /* name in the snapshot and the XDMF index */
    const char *unit;
    size_t offset;               /* offsetof(particles, member): where the array pointer is */
    size_t element_size;         /* bytes per particle */
    int components;
    enum dem_particle_scalar scalar; /* double, int or int64: gives the HDF5 type */
    unsigned flags;              /* PF_WRITE, PF_RESTART, PF_MIGRATE */
} dem_particle_field;

extern const dem_particle_field dem_particle_fields[PARTICLE_FIELD_COUNT];

/* The array of field f in p (the member at f->offset). Read as bytes: the member is a typed
 * pointer, and reading it through a void * lvalue would break the aliasing rules. */
static inline void *particle_field_data(const dem_particles *p, const dem_particle_field *f)
{
    void *data;
    memcpy(&data, (const char *)p + f->offset, sizeof data);
    return data;
}

void dem_particles_init(dem_particles *p);
void dem_particles_free(dem_particles *p);
void dem_particles_reserve(dem_particles *p, int capacity);
/* Append one particle at rest, every other field 0; returns its index. density in kg/m^3. */
int dem_particles_add(dem_particles *p, const double x[3], const double v[3], double radius,
                  double density, int type, int64_t id);
/* Recompute mass, inverse mass and inverse inertia from radius and a per-type density. */
void dem_particles_set_mass(dem_particles *p, int i, double density);
/* Particle i moves at its present velocity from now on, without rotation, whatever the forces. */
void dem_particles_prescribe(dem_particles *p, int i);
/* Remove particle i: the last particle takes its index (so every other index stays as it is).
 * Several removals go from the highest index down: then the particle moved in is never one
 * still to be removed. */
void dem_particles_remove(dem_particles *p, int i);
/* Reorder all arrays so that new index k holds old index order[k]. */
void dem_particles_permute(dem_particles *p, const int *order);
/* Every field of particle `from` copied onto particle `to` (both within the capacity; the
 * periodic images beyond n are made this way). */
void dem_particles_copy(dem_particles *p, int from, int to);
/* Bytes of one particle's PF_MIGRATE fields, as dem_particles_pack writes them. */
size_t dem_particles_pack_size(void);
/* Particle i's PF_MIGRATE fields into buf (dem_particles_pack_size() bytes); returns the bytes. */
size_t dem_particles_pack(const dem_particles *p, int i, void *buf);
/* Append a particle from dem_particles_pack's bytes, its other fields 0; returns its index. */
int dem_particles_unpack(dem_particles *p, const void *buf);

/* The same for any set of roles (a mask of PF_ flags: a field is packed if it has any of them),
 * for the ghosts' exchanges, field by field (the buffer holds each field's elements for all the
 * particles in turn, so that every copy is a plain loop or one memcpy):
 *   role_size     bytes per particle;
 *   gather_roles  particles idx[0 .. count-1] into buf, shift[m] [m] (NULL: none) added to the
 *                 position of idx[m] (a periodic image's period); returns the bytes;
 *   put_roles     buf onto particles first .. first + count - 1 (overwritten);
 *   copy_roles    gather_roles and put_roles in one pass, without the buffer (a swap to itself);
 *   fold_roles    take_roles and scatter_add_roles in one pass, without the buffer;
 *   take_roles    particles first .. first + count - 1 into buf;
 *   scatter_add_roles  buf added onto particles idx[0 .. count-1] (the mask's fields must all be
 *                 doubles: PF_REVERSE; an index may repeat);
 *   zero_roles    particles first .. first + count - 1: the mask's fields zeroed. */
size_t dem_particles_role_size(unsigned roles);
size_t dem_particles_gather_roles(const dem_particles *p, unsigned roles, const int *idx, int count,
                                  const dem_vec3 *shift, void *buf);
void dem_particles_put_roles(dem_particles *p, unsigned roles, int first, int count, const void *buf);
void dem_particles_copy_roles(dem_particles *p, unsigned roles, const int *idx, int count, const dem_vec3 *shift,
                              int first);
void dem_particles_take_roles(const dem_particles *p, unsigned roles, int first, int count, void *buf);
void dem_particles_scatter_add_roles(dem_particles *p, unsigned roles, const int *idx, int count, const void *buf);
void dem_particles_fold_roles(dem_particles *p, unsigned roles, int first, int count, const int *idx);
void dem_particles_zero_roles(dem_particles *p, unsigned roles, int first, int count);

#endif
