#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "contacts.h"
#include "error.h"
#include "reduce.h"
#include "restart.h"

void dem_restart_save_contacts(const dem_system *s, dem_contact_state *cs)
{
    dem_contact_store store;
    dem_contact_store_init(&store, s->history_size, s->nlist.history_antisymmetric);
    dem_contacts_gather(s, &store);
    dem_contacts_to_state(&store, s->nwalls, cs);
    dem_contact_store_free(&store);
    int64_t bodies = s->bodies.n;   /* over all ranks: the snapshot's bodies group is written by all or none */
    dem_reduce_int64s(&bodies, 1, DEM_REDUCE_SUM);
    if (bodies > 0) {
        dem_bodies_to_state(s, &cs->bodies);
        cs->bodies.present = 1;
    }
    dem_lifecycle_to_state(s, &cs->lifecycle);
    cs->coarse_graining = s->coarse_graining;
}

void dem_restart_setup(dem_system *s, const dem_contact_state *cs)
{
    const int matches = cs && cs->history_size == dem_contact_history_size(&s->models) && cs->nwalls == s->nwalls;
    if (cs && cs->history_size > 0 && !matches)
        dem_warning("the restart snapshot's contact history (%d values per contact, %d walls) does not "
                    "fit this case's models and walls; contacts start afresh", cs->history_size, cs->nwalls);
    if (!matches || cs->history_size == 0) {
        dem_system_setup(s);
        return;
    }
    dem_contact_store saved;
    dem_contact_store_init(&saved, cs->history_size, dem_contact_history_antisymmetric(&s->models));
    dem_contacts_from_state(cs, &saved);
    /* the snapshot's forces were computed in the step that wrote it (with the half-step
     * velocity, and adding that step's tangential increment); computing them again here would
     * add the increment twice */
    const long restored = dem_system_setup_with_contacts(s, &saved, !cs->forces_read);
    dem_info("restart: contact history of %ld of %ld contacts restored", restored, cs->count);
    dem_contact_store_free(&saved);
}

int dem_restart_read(dem_system *s, const char *base, double at_time, double tolerance, dem_contact_state *cs)
{
    long step;
    if (dem_io_read_snapshot_at(base, at_time, tolerance, &s->p, &s->time, &step, cs) != 0) return -1;
    s->step = step;
    if (cs && cs->coarse_graining != s->coarse_graining)   /* the snapshot's diameters are its parcels' */
        dem_fatal("%s.h5 was written with coarseGraining %g, but the case now has %g: a restart keeps the "
                  "parcels as they are; set coarseGraining back to %g", base, cs->coarse_graining,
                  s->coarse_graining, cs->coarse_graining);
    for (int i = 0; i < s->p.n; i++) {
        if (s->p.type[i] < 0 || s->p.type[i] >= s->materials.ntypes)
            dem_fatal("%s.h5: particle id %lld has type %d, but the case defines %d materials",
                      base, (long long)s->p.id[i], s->p.type[i], s->materials.ntypes);
        dem_particles_set_mass(&s->p, i, s->materials.mat[s->p.type[i]].density);
        if (s->p.id[i] >= s->next_id) s->next_id = s->p.id[i] + 1;
    }
    int64_t next = s->next_id;   /* the next free id over all ranks (reduce.h) */
    dem_reduce_int64s(&next, 1, DEM_REDUCE_MAX);
    s->next_id = next;
    char where[4200];
    snprintf(where, sizeof where, "%s.h5", base);
    if (cs && cs->bodies.count > 0)   /* multisphere bodies: their spheres take their mass */
        dem_bodies_from_state(s, &cs->bodies, where);
    dem_lifecycle_from_state(s, cs ? &cs->lifecycle : NULL, where);
    return 0;
}
