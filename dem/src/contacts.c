/* Contact history keyed by particle ids (contacts.h): an open-addressing hash table. */
#include <stdlib.h>
#include <string.h>

#include "contacts.h"
#include "error.h"
#include "system.h"

void dem_contact_store_init(dem_contact_store *cs, int history_size, int antisymmetric)
{
    memset(cs, 0, sizeof *cs);
    cs->history_size = history_size;
    cs->antisymmetric = antisymmetric;
}

void dem_contact_store_free(dem_contact_store *cs)
{
    free(cs->first);
    free(cs->second);
    free(cs->history);
    free(cs->used);
    dem_contact_store_init(cs, 0, 0);
}

void dem_contact_store_clear(dem_contact_store *cs)
{
    if (cs->used) memset(cs->used, 0, (size_t)cs->capacity);
    cs->count = 0;
}

/* The slot of a key, the pair in either order: a mix of the lower and the higher id. */
static size_t home_slot(const dem_contact_store *cs, int64_t a, int64_t b)
{
    uint64_t lo = (uint64_t)(a < b ? a : b), hi = (uint64_t)(a < b ? b : a);
    uint64_t z = lo * 0x9e3779b97f4a7c15ULL ^ (hi + 0x632be59bd9b4e019ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return (size_t)((z ^ (z >> 31)) & (uint64_t)(cs->capacity - 1));
}

static int same_pair(int64_t a, int64_t b, int64_t c, int64_t d) { return (a == c && b == d) || (a == d && b == c); }

static void grow(dem_contact_store *cs)
{
    dem_contact_store old = *cs;
    cs->capacity = old.capacity ? 2 * old.capacity : 1024;
    const int hs = cs->history_size;
    cs->first = dem_malloc((size_t)cs->capacity * sizeof(int64_t));
    cs->second = dem_malloc((size_t)cs->capacity * sizeof(int64_t));
    cs->history = dem_malloc((size_t)cs->capacity * (hs ? hs : 1) * sizeof(double));
    cs->used = dem_calloc((size_t)cs->capacity, 1);
    cs->count = 0;
    for (long k = 0; k < old.capacity; k++)
        if (old.used[k]) dem_contact_store_put(cs, old.first[k], old.second[k], old.history + (size_t)k * hs);
    free(old.first);
    free(old.second);
    free(old.history);
    free(old.used);
}

void dem_contact_store_put(dem_contact_store *cs, int64_t first, int64_t second, const double *h)
{
    if (2 * (cs->count + 1) > cs->capacity) grow(cs);   /* at most half full */
    size_t k = home_slot(cs, first, second);
    while (cs->used[k] && !same_pair(cs->first[k], cs->second[k], first, second))
        k = (k + 1) & (size_t)(cs->capacity - 1);
    if (!cs->used[k]) cs->count++;
    cs->used[k] = 1;
    cs->first[k] = first;
    cs->second[k] = second;
    memcpy(cs->history + k * cs->history_size, h, (size_t)cs->history_size * sizeof(double));
}

int dem_contact_store_take(const dem_contact_store *cs, int64_t first, int64_t second, double *h)
{
    if (cs->count == 0) return 0;
    for (size_t k = home_slot(cs, first, second); cs->used[k]; k = (k + 1) & (size_t)(cs->capacity - 1)) {
        if (!same_pair(cs->first[k], cs->second[k], first, second)) continue;
        dem_contact_history_copy(h, cs->history + k * cs->history_size, cs->history_size, cs->antisymmetric,
                             cs->first[k] != first);
        return 1;
    }
    return 0;
}

void dem_contacts_gather(const dem_system *s, dem_contact_store *cs)
{
    dem_contact_store_clear(cs);
    const int hs = s->history_size;
    if (hs == 0) return;
    const dem_neighbour_list *nl = &s->nlist;
    const int64_t *id = nl->id_at_build;   /* the particles as the lists hold them */
    for (int i = 0; i < nl->rows; i++)
        for (int k = nl->start[i]; k < nl->start[i + 1]; k++)
            if (nl->touching[k]) dem_contact_store_put(cs, id[i], id[nl->partner[k]], nl->history + (size_t)k * hs);
    for (int w = 0; w < s->nwalls; w++) {
        const dem_wall_contacts *wc = &s->wall_lists[w];
        for (int m = 0; m < wc->n; m++)
            if (wc->touching[m])
                dem_contact_store_put(cs, contact_wall_key(w), id[wc->particle[m]], wc->history + (size_t)m * hs);
    }
}

long dem_contacts_scatter(dem_system *s, const dem_contact_store *cs)
{
    const int hs = s->history_size;
    if (hs == 0 || cs->count == 0) return 0;
    dem_neighbour_list *nl = &s->nlist;
    const int64_t *id = s->p.id;
    long found = 0;
    for (int i = 0; i < nl->rows; i++)
        for (int k = nl->start[i]; k < nl->start[i + 1]; k++)
            if (dem_contact_store_take(cs, id[i], id[nl->partner[k]], nl->history + (size_t)k * hs)) {
                nl->touching[k] = 1;   /* the force loop clears it if the contact is over */
                found++;
            }
    for (int w = 0; w < s->nwalls; w++) {
        dem_wall_contacts *wc = &s->wall_lists[w];
        for (int m = 0; m < wc->n; m++)
            if (dem_contact_store_take(cs, contact_wall_key(w), id[wc->particle[m]], wc->history + (size_t)m * hs)) {
                wc->touching[m] = 1;
                found++;
            }
    }
    return found;
}

void dem_contact_rows_init(dem_contact_rows *cr, int history_size, int antisymmetric)
{
    memset(cr, 0, sizeof *cr);
    dem_contact_store_init(&cr->spill, history_size, antisymmetric);
}

void dem_contact_rows_free(dem_contact_rows *cr)
{
    free(cr->row_id);
    free(cr->start);
    free(cr->partner_id);
    free(cr->history);
    free(cr->wall_start);
    free(cr->matched);
    dem_contact_store_free(&cr->spill);
    memset(cr, 0, sizeof *cr);
}

static void rows_push(dem_contact_rows *cr, int64_t partner, const double *h, int hs)
{
    if (cr->count == cr->capacity) {
        cr->capacity = cr->capacity ? 2 * cr->capacity : 4096;
        cr->partner_id = dem_realloc(cr->partner_id, (size_t)cr->capacity * sizeof(int64_t));
        cr->history = dem_realloc(cr->history, (size_t)cr->capacity * hs * sizeof(double));
        cr->matched = dem_realloc(cr->matched, (size_t)cr->capacity);
    }
    cr->partner_id[cr->count] = partner;
    memcpy(cr->history + (size_t)cr->count * hs, h, (size_t)hs * sizeof(double));
    cr->matched[cr->count] = 0;
    cr->count++;
}

void dem_contacts_gather_rows(const dem_system *s, dem_contact_rows *cr)
{
    const int hs = s->history_size;
    const dem_neighbour_list *nl = &s->nlist;
    const int64_t *id = nl->id_at_build;   /* as built: particles may have gone or moved since */
    cr->count = 0;
    dem_contact_store_clear(&cr->spill);   /* then only migration (migrate.c) adds to it before the scatter */
    cr->rows = hs ? nl->rows : 0;
    if (cr->rows + 1 > cr->rows_capacity) {
        cr->rows_capacity = cr->rows + 1;
        cr->row_id = dem_realloc(cr->row_id, (size_t)cr->rows_capacity * sizeof(int64_t));
        cr->start = dem_realloc(cr->start, (size_t)cr->rows_capacity * sizeof(int));
    }
    if (s->nwalls + 1 > cr->walls_capacity) {
        cr->walls_capacity = s->nwalls + 1;
        cr->wall_start = dem_realloc(cr->wall_start, (size_t)cr->walls_capacity * sizeof(int));
    }
    for (int i = 0; i < cr->rows; i++) {
        cr->row_id[i] = id[i];
        cr->start[i] = (int)cr->count;
        for (int k = nl->start[i]; k < nl->start[i + 1]; k++)
            if (nl->touching[k]) rows_push(cr, id[nl->partner[k]], nl->history + (size_t)k * hs, hs);
    }
    cr->start[cr->rows] = (int)cr->count;
    for (int w = 0; w < s->nwalls; w++) {
        cr->wall_start[w] = (int)cr->count;
        const dem_wall_contacts *wc = &s->wall_lists[w];
        for (int m = 0; hs && m < wc->n; m++)
            if (wc->touching[m]) rows_push(cr, wc->particle[m], wc->history + (size_t)m * hs, hs);
    }
    cr->wall_start[s->nwalls] = (int)cr->count;
}

long dem_contacts_scatter_rows(dem_system *s, dem_contact_rows *cr)
{
    const int hs = s->history_size;
    if (hs == 0 || (cr->count == 0 && cr->spill.count == 0)) return 0;
    dem_neighbour_list *nl = &s->nlist;
    const int64_t *id = s->p.id;
    const int same_rows = nl->rows < cr->rows ? nl->rows : cr->rows;
    long found = 0;
    /* pairs whose owner kept its index and the pair its owner */
    for (int i = 0; i < same_rows; i++) {
        if (cr->row_id[i] != id[i] || cr->start[i] == cr->start[i + 1]) continue;
        for (int k = nl->start[i]; k < nl->start[i + 1]; k++) {
            const int64_t pid = id[nl->partner[k]];
            for (int c = cr->start[i]; c < cr->start[i + 1]; c++)
                if (cr->partner_id[c] == pid && !cr->matched[c]) {
                    memcpy(nl->history + (size_t)k * hs, cr->history + (size_t)c * hs, (size_t)hs * sizeof(double));
                    nl->touching[k] = 1;   /* the force loop clears it if the contact is over */
                    cr->matched[c] = 1;
                    found++;
                    break;
                }
        }
    }
    /* wall contacts of particles that kept their index: both lists ascend by particle index */
    for (int w = 0; w < s->nwalls; w++) {
        dem_wall_contacts *wc = &s->wall_lists[w];
        int m = 0;
        for (int c = cr->wall_start[w]; c < cr->wall_start[w + 1]; c++) {
            const int i = (int)cr->partner_id[c];
            if (i >= same_rows || cr->row_id[i] != id[i]) continue;
            while (m < wc->n && wc->particle[m] < i) m++;
            if (m < wc->n && wc->particle[m] == i) {
                memcpy(wc->history + (size_t)m * hs, cr->history + (size_t)c * hs, (size_t)hs * sizeof(double));
                wc->touching[m] = 1;
                cr->matched[c] = 1;
                found++;
            }
        }
    }
    /* the rest by ids, with the contacts that came with migrating particles */
    dem_contact_store *spill = &cr->spill;
    for (int i = 0; i < cr->rows; i++)
        for (int c = cr->start[i]; c < cr->start[i + 1]; c++)
            if (!cr->matched[c]) dem_contact_store_put(spill, cr->row_id[i], cr->partner_id[c], cr->history + (size_t)c * hs);
    for (int w = 0; w < s->nwalls; w++)
        for (int c = cr->wall_start[w]; c < cr->wall_start[w + 1]; c++)
            if (!cr->matched[c])
                dem_contact_store_put(spill, contact_wall_key(w), cr->row_id[cr->partner_id[c]],
                                      cr->history + (size_t)c * hs);
    if (spill->count == 0) return found;
    for (int i = 0; i < nl->rows; i++)
        for (int k = nl->start[i]; k < nl->start[i + 1]; k++)
            if (!nl->touching[k] &&
                dem_contact_store_take(spill, id[i], id[nl->partner[k]], nl->history + (size_t)k * hs)) {
                nl->touching[k] = 1;
                found++;
            }
    for (int w = 0; w < s->nwalls; w++) {
        dem_wall_contacts *wc = &s->wall_lists[w];
        for (int m = 0; m < wc->n; m++)
            if (!wc->touching[m] &&
                dem_contact_store_take(spill, contact_wall_key(w), id[wc->particle[m]], wc->history + (size_t)m * hs)) {
                wc->touching[m] = 1;
                found++;
            }
    }
    return found;
}

void dem_contacts_to_state(const dem_contact_store *store, int nwalls, dem_contact_state *state)
{
    const int hs = store->history_size;
    memset(state, 0, sizeof *state);
    state->history_size = hs;
    state->nwalls = nwalls;
    state->keys = dem_malloc((size_t)(2 * store->count + 1) * sizeof(int64_t));
    state->history = dem_malloc((size_t)(store->count * hs + 1) * sizeof(double));
    for (long k = 0; k < store->capacity; k++) {
        if (!store->used[k]) continue;
        state->keys[2 * state->count] = store->first[k];
        state->keys[2 * state->count + 1] = store->second[k];
        memcpy(state->history + state->count * hs, store->history + (size_t)k * hs, (size_t)hs * sizeof(double));
        state->count++;
    }
}

void dem_contacts_from_state(const dem_contact_state *state, dem_contact_store *store)
{
    dem_contact_store_clear(store);
    for (long c = 0; c < state->count; c++)
        dem_contact_store_put(store, state->keys[2 * c], state->keys[2 * c + 1],
                          state->history + c * state->history_size);
}
