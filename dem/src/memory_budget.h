/* What this machine's memory holds (issue 26).
 *
 * A count that a case implies (an insertion's number, the particles a solidFraction of a region
 * means, a lattice's points, a stream's particles over the run) is checked, at the key that
 * implies it, against the particles the machine's physical memory can hold, before anything is
 * allocated: so that a case too large for the machine stops with its file, line and key, the
 * memory it would take and the largest (or smallest) value of that key accepted here, and not with
 * the allocator's "out of memory" and no location.
 *
 * A particle takes its fields (particles.h: about 230 bytes) and, in the neighbour list (partners
 * and contact history), the cell and insertion grids and the arrays' growth by doubling, about as
 * much again twice over: PARTICLE_MEMORY_FACTOR x its fields. The budget is the physical memory
 * (sysconf), or DEM_MEMORY_BYTES from the environment where a test or a shared machine sets less. */
#ifndef DEM_MEMORY_BUDGET_H
#define DEM_MEMORY_BUDGET_H

#include <stddef.h>

#define PARTICLE_MEMORY_FACTOR 3

struct dem_dict;
/* Bytes a particle is budgeted (PARTICLE_MEMORY_FACTOR x its fields) */
size_t dem_particle_memory_bytes(void);
/* The memory budget [bytes] */
double dem_memory_budget_bytes(void);
/* The most particles the budget holds */
double dem_particles_affordable(void);
/* The count particles that value of key implies (count grows as value^power: 1 for a number or a
 * fraction, -3 for a lattice spacing) against dem_particles_affordable(): fatal at the key, with the
 * memory the count would take and the largest (power > 0) or smallest (power < 0) value accepted.
 * what names the count ("particles", "spheres in 300 bodies of 4", ...). */
void dem_check_affordable(const struct dem_dict *d, const char *key, double value, double count, double power,
                          const char *what);

#endif
