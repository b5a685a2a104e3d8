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
    const int64_t *id = s->p.id;
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
