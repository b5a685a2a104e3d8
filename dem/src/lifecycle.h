/* The particles' life cycle during a run: removal (a free sphere, or a multisphere body as one
 * unit), the insertions and outlets that act while the run goes on, and the mass balance.
 *
 * Where it happens: the step (system.c) asks dem_lifecycle_due() after the drift; when an outlet
 * has something beyond it or a stream insertion is due, the step rebuilds its lists, and
 * dem_lifecycle_apply() runs first inside that rebuild: outlets remove, streams insert. So the
 * particle set changes only where the lists are made again, the contacts of removed particles
 * go with them (the carry is by ids: contacts.h), and the new particles are in the lists and
 * feel the forces of the step they were inserted in.
 *
 * Units: a free sphere, or a body. A particle whose set changes bumps p->generation
 * (particles.h); everything kept per particle index elsewhere compares it.
 *
 * The balance is exact: each unit's mass [kg] is turned once into an integer number of quanta of
 * 2^-64 kg (5.4e-20 kg), the same integer whenever that unit is counted, so inserted - removed -
 * held = 0 holds as integers, in the number of units and in their mass, whatever the order of
 * the sums. (Summed in doubles, the three would differ by round-off, and a lost particle of 1e-15
 * of the total would hide in it.) */
#ifndef DEM_LIFECYCLE_H
#define DEM_LIFECYCLE_H

#include <stdint.h>

/* A count of units and their mass in quanta of 2^-64 kg. __int128: 2^63 quanta are 0.5 kg, and
 * a bed may hold tonnes. */
__extension__ typedef __int128 dem_mass_quanta;
typedef struct dem_tally {
    int64_t count;
    dem_mass_quanta mass;
} dem_tally;

static inline dem_mass_quanta dem_mass_to_quanta(double kg) { return (dem_mass_quanta)(kg * 0x1p64); }
static inline double dem_quanta_to_kg(dem_mass_quanta q) { return (double)q * 0x1p-64; }
static inline void dem_tally_add(dem_tally *t, int64_t count, dem_mass_quanta mass)
{
    t->count += count;
    t->mass += mass;
}
/* The quanta as two int64 (for the snapshot): high and low 64 bits. */
static inline void dem_quanta_split(dem_mass_quanta q, int64_t *hi, int64_t *lo)
{
    *hi = (int64_t)(q >> 64);
    *lo = (int64_t)(uint64_t)q;
}
static inline dem_mass_quanta dem_quanta_join(int64_t hi, int64_t lo)
{
    return (dem_mass_quanta)(((unsigned __int128)(uint64_t)hi << 64) | (uint64_t)lo);
}

struct dem_system;
/* Units (free spheres and bodies) now in the system and their mass. */
dem_tally dem_lifecycle_held(const struct dem_system *s);

/* Remove the particles i with mark[i] != 0; a mark on any sphere of a body removes the whole
 * body. The lists are stale afterwards (the generation says so) and are remade at the next step.
 * Returns what was removed and adds it to s->removed. */
dem_tally dem_system_remove_marked(struct dem_system *s, const int *mark);

/* Whether the step that is ending (its drift done) must change the particle set: something
 * beyond an outlet, a stream insertion due at step s->step + 1. */
int dem_lifecycle_due(const struct dem_system *s);
/* Outlets remove, streams insert (lists are made afterwards by the caller). */
void dem_lifecycle_apply(struct dem_system *s);

/* The log of a write time: the balance, each outlet's removed count and mass and its rate since
 * the last log, each stream's inserted count and mass and what it carries over. Logs nothing for
 * a case without streams and outlets. */
void dem_lifecycle_log(struct dem_system *s);

/* The counters into a snapshot's form (io.h; nothing for a case without streams and outlets)
 * and back at a restart, each outlet and stream by its name (`where` names the snapshot in
 * messages); a snapshot without them starts the balance from the particles it holds. */
struct dem_lifecycle_state;
void dem_lifecycle_to_state(const struct dem_system *s, struct dem_lifecycle_state *l);
void dem_lifecycle_from_state(struct dem_system *s, const struct dem_lifecycle_state *l, const char *where);

#endif
