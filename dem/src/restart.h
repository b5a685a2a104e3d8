/* Contact history across a restart: saved by particle ids, so it does not depend on the
 * particle order or on the neighbour list of the run that wrote it. */
#ifndef DEM_RESTART_H
#define DEM_RESTART_H

#include "io.h"
#include "system.h"

/* Collect the history of every pair in contact and of every particle-wall contact. */
void dem_restart_save_contacts(const dem_system *s, dem_contact_state *cs);
/* Set up the system (as dem_system_setup) and put the saved history back onto the same pairs and
 * walls. A snapshot written with other models or walls cannot be matched: its history is
 * dropped with a warning. */
void dem_restart_setup(dem_system *s, const dem_contact_state *cs);
/* Read the particles of <base>.h5's snapshot at at_time (within tolerance; NAN: the last
 * complete one) into s, with their masses from the case's materials, the time and step, and
 * the contact history into cs (for dem_restart_setup). Returns -1 when there is no such snapshot;
 * fatal when a particle's type is not among the case's materials. */
int dem_restart_read(dem_system *s, const char *base, double at_time, double tolerance, dem_contact_state *cs);

#endif
