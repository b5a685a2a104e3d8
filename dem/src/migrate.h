/* Particles that left this rank's box go to the rank that owns where they are now (issue 23).
 *
 * Run at each neighbour-list rebuild, after the contacts' histories were gathered by row
 * (contacts.h) and before the new lists are made: each particle whose position (wrapped into a
 * periodic domain) lies in another rank's box (decompose.h) is packed with its PF_MIGRATE fields
 * (particles.h) and, with it, the contacts it holds: the pairs listed under it (a pair is held by
 * the particle with the lower id, neighbour.c) and its wall contacts, each with its history. The
 * receiver appends the particles and puts the contacts into the store the new lists take their
 * histories from by ids, so a contact survives a change of rank as it survives a sort. A
 * multisphere body's spheres go by the body's centre, not their own, and the body's row
 * (bodies.h's dem_bodies_pack) goes with them: a body is never split between ranks. Between
 * rebuilds no particle moves more than half the skin, so only the boxes around a rank send to it;
 * after a new decomposition any rank may. Serially (one rank) nothing is done. */
#ifndef DEM_MIGRATE_H
#define DEM_MIGRATE_H

struct dem_system;
void dem_migrate(struct dem_system *s);
/* At set-up, where every rank holds every particle (the case's insertion, or a snapshot read
 * whole): keep the ones this rank's box owns, drop the others. */
void dem_migrate_keep_owned(struct dem_system *s);

#endif
