/* Contact history keyed by particle ids.
 *
 * The force loops keep each contact's history beside the contact (in the neighbour list's
 * pairs, in each wall's candidate list), where a rebuild, a sort or a restart would lose it.
 * So before every rebuild the histories of the contacts that touch are gathered into a store
 * keyed by ids, and after it they are taken back onto the new lists; a restart fills the same
 * store from the snapshot, and a snapshot is written from it. Nothing depends on particle
 * indices, so sorting, periodic images and (later) ranks leave contacts intact.
 *
 * A pair is keyed by its two ids in the order the list held it (first = i): the antisymmetric
 * part of the history (built from v_i - v_j) changes sign when the new list holds it as
 * (j, i). A wall contact is keyed by (contact_wall_key(wall), particle id). */
#ifndef DEM_CONTACTS_H
#define DEM_CONTACTS_H

#include <stdint.h>

#include "io.h"

typedef struct dem_contact_store {
    int history_size;        /* doubles per contact */
    int antisymmetric;       /* its leading part that changes sign when (i, j) swap */
    long count, capacity;    /* entries, slots (a power of two: open addressing) */
    int64_t *first, *second; /* the key as held: ids (i, j), or (wall key, particle id) */
    double *history;         /* history_size per slot */
    unsigned char *used;
} dem_contact_store;

/* Wall contacts carry the wall's index where a pair carries the first id (ids are >= 0). */
static inline int64_t contact_wall_key(int wall) { return -1 - (int64_t)wall; }

struct dem_system;
void dem_contact_store_init(dem_contact_store *cs, int history_size, int antisymmetric);
void dem_contact_store_free(dem_contact_store *cs);
void dem_contact_store_clear(dem_contact_store *cs);
void dem_contact_store_put(dem_contact_store *cs, int64_t first, int64_t second, const double *h);
/* Copy the history of (first, second) into h (its antisymmetric part negated if the store held
 * the pair as (second, first)); returns 1 if found. */
int dem_contact_store_take(const dem_contact_store *cs, int64_t first, int64_t second, double *h);

/* The histories of the system's touching contacts (pairs and walls) into the store. */
void dem_contacts_gather(const struct dem_system *s, dem_contact_store *cs);
/* Onto the current lists: each listed pair and wall candidate finds its history by its ids;
 * returns how many were found. */
long dem_contacts_scatter(struct dem_system *s, const dem_contact_store *cs);

/* Carrying the histories across a rebuild. Most rebuilds keep every particle at its index (only
 * every sortInterval-th sorts), and a contact stays in its owner's row: then each row's new pairs
 * find their histories among the few the row held before, in order through memory, where a hash
 * look-up per listed pair would jump. Whatever does not match so (rows whose particle changed
 * index, pairs that changed owner as a particle wrapped through a periodic side) goes through the
 * store by ids, so the result is the same as a carry by ids alone. */
typedef struct dem_contact_rows {
    int rows;                /* particles listed at the gather */
    int64_t *row_id;         /* the id each row belonged to */
    int *start;              /* row i's contacts: [start[i], start[i+1]) */
    int64_t *partner_id;     /* a pair's partner by id; a wall contact: its particle's index */
    double *history;
    int *wall_start;         /* wall w's contacts after the pairs: [wall_start[w], wall_start[w+1]) */
    unsigned char *matched;
    long count, capacity;
    int rows_capacity, walls_capacity;
    dem_contact_store spill; /* the unmatched, by ids */
} dem_contact_rows;

void dem_contact_rows_init(dem_contact_rows *cr, int history_size, int antisymmetric);
void dem_contact_rows_free(dem_contact_rows *cr);
/* Before a rebuild: the touching contacts, by row. */
void dem_contacts_gather_rows(const struct dem_system *s, dem_contact_rows *cr);
/* After it: onto the new lists (each listed pair and wall candidate whose contact was held, or
 * arrived in the spill with a migrating particle, migrate.h); returns how many were found. */
long dem_contacts_scatter_rows(struct dem_system *s, dem_contact_rows *cr);

/* The flat form a snapshot holds (io.h), from and into a store. */
void dem_contacts_to_state(const dem_contact_store *store, int nwalls, dem_contact_state *state);
void dem_contacts_from_state(const dem_contact_state *state, dem_contact_store *store);

#endif
