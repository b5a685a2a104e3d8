#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "restart.h"

void restart_save_contacts(const dem_system *s, contact_state *cs)
{
    const neighbour_list *nl = &s->nlist;
    const int hs = s->history_size;
    memset(cs, 0, sizeof *cs);
    cs->history_size = hs;
    cs->nwalls = s->nwalls;
    if (hs == 0) return;
    long count = 0;
    for (long k = 0; k < nl->npairs; k++) count += nl->touching[k];
    cs->pair_ids = dem_malloc((size_t)(2 * count) * sizeof(int64_t));
    cs->pair_history = dem_malloc((size_t)(count * hs) * sizeof(double));
    for (int i = 0; i < nl->rows; i++)
        for (int k = nl->start[i]; k < nl->start[i + 1]; k++) {
            if (!nl->touching[k]) continue;
            cs->pair_ids[2 * cs->npairs] = s->p.id[i];
            cs->pair_ids[2 * cs->npairs + 1] = s->p.id[nl->partner[k]];
            memcpy(cs->pair_history + cs->npairs * hs, nl->history + (size_t)k * hs, (size_t)hs * sizeof(double));
            cs->npairs++;
        }
    const size_t wall_doubles = (size_t)s->p.n * s->nwalls * hs;
    cs->wall_history = dem_malloc(wall_doubles * sizeof(double));
    memcpy(cs->wall_history, s->wall_history, wall_doubles * sizeof(double));
}

typedef struct id_index { int64_t id; int index; } id_index;

static int by_id(const void *a, const void *b)
{
    const int64_t x = ((const id_index *)a)->id, y = ((const id_index *)b)->id;
    return (x > y) - (x < y);
}

static int index_of(const id_index *map, int n, int64_t id)
{
    const id_index key = {id, -1};
    const id_index *hit = bsearch(&key, map, (size_t)n, sizeof *map, by_id);
    return hit ? hit->index : -1;
}

void restart_setup(dem_system *s, const contact_state *cs)
{
    const int matches = cs && cs->history_size == contact_history_size(&s->models) && cs->nwalls == s->nwalls;
    if (cs && cs->history_size > 0 && !matches)
        dem_warning("the restart snapshot's contact history (%d values per contact, %d walls) does not "
                    "fit this case's models and walls; contacts start afresh", cs->history_size, cs->nwalls);
    if (!matches || cs->history_size == 0) {
        system_setup(s);
        return;
    }
    /* the snapshot's forces were computed in the step that wrote it (with the half-step
     * velocity, and adding that step's tangential increment); computing them again here would
     * add the increment twice */
    const int keep_forces = cs->forces_read;   /* the list build permutes them along */
    /* wall history is in the snapshot's particle order, which is the order now: put it in
     * before the first list build re-orders the particles */
    system_setup_begin(s);
    memcpy(s->wall_history, cs->wall_history, (size_t)s->p.n * s->nwalls * cs->history_size * sizeof(double));
    system_setup_finish_list(s);

    const int n = s->p.n, hs = cs->history_size;
    id_index *map = dem_malloc((size_t)(n ? n : 1) * sizeof *map);
    for (int i = 0; i < n; i++) map[i] = (id_index){s->p.id[i], i};
    qsort(map, (size_t)n, sizeof *map, by_id);
    neighbour_list *nl = &s->nlist;
    long restored = 0;
    for (long c = 0; c < cs->npairs; c++) {
        int a = index_of(map, n, cs->pair_ids[2 * c]), b = index_of(map, n, cs->pair_ids[2 * c + 1]);
        if (a < 0 || b < 0) continue;
        const int flipped = a > b;   /* saved as (i, j), stored now as (j, i) */
        if (flipped) { const int t = a; a = b; b = t; }
        for (int k = nl->start[a]; k < nl->start[a + 1]; k++)
            if (nl->partner[k] == b) {
                contact_history_copy(nl->history + (size_t)k * hs, cs->pair_history + c * hs, hs,
                                     nl->history_antisymmetric, flipped);
                nl->touching[k] = 1;
                restored++;
                break;
            }
    }
    free(map);
    dem_info("restart: contact history of %ld of %ld particle pairs restored", restored, cs->npairs);
    if (!keep_forces) system_compute_forces(s);
}

int restart_read(dem_system *s, const char *base, double at_time, double tolerance, contact_state *cs)
{
    long step;
    if (io_read_snapshot_at(base, at_time, tolerance, &s->p, &s->time, &step, cs) != 0) return -1;
    s->step = step;
    for (int i = 0; i < s->p.n; i++) {
        if (s->p.type[i] < 0 || s->p.type[i] >= s->materials.ntypes)
            dem_fatal("%s.h5: particle id %lld has type %d, but the case defines %d materials",
                      base, (long long)s->p.id[i], s->p.type[i], s->materials.ntypes);
        particles_set_mass(&s->p, i, s->materials.mat[s->p.type[i]].density);
        if (s->p.id[i] >= s->next_id) s->next_id = s->p.id[i] + 1;
    }
    return 0;
}
