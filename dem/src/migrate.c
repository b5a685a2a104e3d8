/* Migration of particles and their contacts between ranks (migrate.h). */
#include <stdlib.h>
#include <string.h>

#include "comm.h"
#include "error.h"
#include "migrate.h"
#include "system.h"

/* Remove the particles marked with a destination other than `me`, from the highest index down (the
 * last particle takes a removed one's place: most keep their index, and their contacts' rows). */
static void remove_leaving(dem_particles *p, const int *dest, int n, int me)
{
    for (int i = n - 1; i >= 0; i--)
        if (dest[i] != me) dem_particles_remove(p, i);
}

/* The rank whose box owns each particle, by its position wrapped into the domain; a body's sphere
 * goes with its body, to the rank whose box holds the body's centre (bodies.h). Both malloc'd;
 * *body_dest is per body of the table. */
static int *owners(dem_system *s, int **body_dest)
{
    dem_neighbour_wrap(s);
    const dem_bodies *b = &s->bodies;
    int *bdest = dem_malloc((size_t)(b->n ? b->n : 1) * sizeof(int));
    for (int k = 0; k < b->n; k++) bdest[k] = dem_decomposition_owner(&s->decomp, dem_body_centre(b, k));
    int *dest = dem_malloc((size_t)(s->p.n ? s->p.n : 1) * sizeof(int));
    for (int i = 0; i < s->p.n; i++)
        dest[i] = s->p.body[i] ? bdest[dem_body_index(b, s->p.body[i])]
                               : dem_decomposition_owner(&s->decomp, s->p.x[i]);
    *body_dest = bdest;
    return dest;
}

/* The bodies whose destination is another rank leave the table (after their spheres left) */
static void remove_leaving_bodies(dem_system *s, const int *body_dest, int me)
{
    dem_bodies *b = &s->bodies;
    if (!b->n) return;
    unsigned char *gone = dem_malloc((size_t)b->n);
    int any = 0;
    for (int k = 0; k < b->n; k++) any |= gone[k] = body_dest[k] != me;
    if (any) dem_bodies_remove(s, gone);
    free(gone);
}

void dem_migrate_keep_owned(dem_system *s)
{
    if (dem_comm_size() == 1) return;
    int *body_dest, *dest = owners(s, &body_dest);
    remove_leaving(&s->p, dest, s->p.n, dem_comm_rank());
    remove_leaving_bodies(s, body_dest, dem_comm_rank());
    free(dest);
    free(body_dest);
}

/* The present index of each row of the contacts gathered at the last build (-1: the particle is
 * gone). Mostly the row's own index; an outlet's removal in this rebuild moved a few particles
 * (the last into a removed one's place), and those are found by id. */
static int *rows_now(const dem_particles *p, const dem_contact_rows *cr)
{
    int *now = dem_malloc((size_t)(cr->rows ? cr->rows : 1) * sizeof *now);
    int moved = 0;
    for (int r = 0; r < cr->rows; r++) {
        now[r] = r < p->n && cr->row_id[r] == p->id[r] ? r : -1;
        moved |= now[r] < 0;
    }
    if (!moved) return now;
    dem_contact_store where;   /* id -> index, through the store's hash: history [index] */
    dem_contact_store_init(&where, 1, 0);
    for (int i = 0; i < p->n; i++) dem_contact_store_put(&where, p->id[i], 0, &(double){(double)i});
    for (int r = 0; r < cr->rows; r++) {
        double i;
        if (now[r] < 0 && dem_contact_store_take(&where, cr->row_id[r], 0, &i)) now[r] = (int)i;
    }
    dem_contact_store_free(&where);
    return now;
}

static void put_i64(unsigned char **at, int64_t v)
{
    memcpy(*at, &v, sizeof v);
    *at += sizeof v;
}

static int64_t get_i64(const unsigned char **at)
{
    int64_t v;
    memcpy(&v, *at, sizeof v);
    *at += sizeof v;
    return v;
}

void dem_migrate(dem_system *s)
{
    if (dem_comm_size() == 1) return;
    dem_particles *p = &s->p;
    dem_contact_rows *cr = &s->carried;
    const int me = dem_comm_rank(), nr = dem_comm_size(), hs = s->history_size, n = p->n;
    int *body_dest, *dest = owners(s, &body_dest);
    int64_t *np_to = dem_calloc((size_t)nr, sizeof(int64_t)), *nc_to = dem_calloc((size_t)nr, sizeof(int64_t));
    int64_t *nb_to = dem_calloc((size_t)nr, sizeof(int64_t));
    int64_t *bytes_to = dem_malloc((size_t)nr * sizeof(int64_t)), *bytes_from = dem_malloc((size_t)nr * sizeof(int64_t));
    for (int i = 0; i < n; i++)
        if (dest[i] != me) np_to[dest[i]]++;
    for (int k = 0; k < s->bodies.n; k++)
        if (body_dest[k] != me) nb_to[body_dest[k]]++;
    /* the contacts by row, gathered at the last build's indices: the pairs of row r and the wall
     * contacts whose partner is r go where the particle of row r goes */
    int *now = rows_now(p, cr);
    for (int r = 0; r < cr->rows; r++)
        if (now[r] >= 0 && dest[now[r]] != me) nc_to[dest[now[r]]] += cr->start[r + 1] - cr->start[r];
    for (long c = cr->start[cr->rows]; c < cr->count; c++) {   /* the wall contacts: partner is the row */
        const int i = now[cr->partner_id[c]];
        if (i >= 0 && dest[i] != me) nc_to[dest[i]]++;
    }
    const size_t ps = dem_particles_pack_size(), cs = 2 * sizeof(int64_t) + (size_t)hs * sizeof(double),
                 bs = dem_bodies_pack_size();
    size_t *send_bytes = dem_malloc((size_t)nr * sizeof(size_t)), *send_offset = dem_malloc((size_t)nr * sizeof(size_t));
    size_t *recv_bytes = dem_malloc((size_t)nr * sizeof(size_t)), *recv_offset = dem_malloc((size_t)nr * sizeof(size_t));
    size_t out = 0;
    for (int r = 0; r < nr; r++) {
        send_bytes[r] = r == me ? 0 : 3 * sizeof(int64_t) + (size_t)np_to[r] * ps + (size_t)nc_to[r] * cs
                                          + (size_t)nb_to[r] * bs;
        send_offset[r] = out;
        out += send_bytes[r];
        bytes_to[r] = (int64_t)send_bytes[r];
    }
    dem_comm_counts(bytes_to, bytes_from);
    size_t in = 0;
    for (int r = 0; r < nr; r++) {
        recv_bytes[r] = r == me ? 0 : (size_t)bytes_from[r];
        recv_offset[r] = in;
        in += recv_bytes[r];
    }
    unsigned char *send = dem_malloc(out + 1), *recv = dem_malloc(in + 1);
    unsigned char **part_at = dem_malloc((size_t)nr * sizeof *part_at), **contact_at = dem_malloc((size_t)nr * sizeof *contact_at);
    unsigned char **body_at = dem_malloc((size_t)nr * sizeof *body_at);
    for (int r = 0; r < nr; r++) {
        if (r == me) continue;
        unsigned char *at = send + send_offset[r];
        put_i64(&at, np_to[r]);
        put_i64(&at, nc_to[r]);
        put_i64(&at, nb_to[r]);
        part_at[r] = at;
        contact_at[r] = at + (size_t)np_to[r] * ps;
        body_at[r] = contact_at[r] + (size_t)nc_to[r] * cs;
    }
    for (int k = 0; k < s->bodies.n; k++)
        if (body_dest[k] != me) body_at[body_dest[k]] += dem_bodies_pack(&s->bodies, k, body_at[body_dest[k]]);
    for (int i = 0; i < n; i++)
        if (dest[i] != me) part_at[dest[i]] += dem_particles_pack(p, i, part_at[dest[i]]);
    for (int row = 0; row < cr->rows; row++) {
        const int i = now[row];
        if (i < 0 || dest[i] == me) continue;
        const int r = dest[i];
        for (int c = cr->start[row]; c < cr->start[row + 1]; c++) {
            put_i64(&contact_at[r], p->id[i]);
            put_i64(&contact_at[r], cr->partner_id[c]);
            memcpy(contact_at[r], cr->history + (size_t)c * hs, (size_t)hs * sizeof(double));
            contact_at[r] += (size_t)hs * sizeof(double);
            cr->matched[c] = 1;   /* gone with its particle */
        }
    }
    for (int w = 0; w < s->nwalls; w++)
        for (int c = cr->wall_start[w]; c < cr->wall_start[w + 1]; c++) {
            const int i = now[cr->partner_id[c]];
            if (i < 0 || dest[i] == me) continue;
            put_i64(&contact_at[dest[i]], contact_wall_key(w));
            put_i64(&contact_at[dest[i]], p->id[i]);
            memcpy(contact_at[dest[i]], cr->history + (size_t)c * hs, (size_t)hs * sizeof(double));
            contact_at[dest[i]] += (size_t)hs * sizeof(double);
            cr->matched[c] = 1;
        }
    dem_comm_exchange(send, send_bytes, send_offset, recv, recv_bytes, recv_offset);
    remove_leaving(p, dest, n, me);
    remove_leaving_bodies(s, body_dest, me);
    double *h = dem_malloc((size_t)(hs ? hs : 1) * sizeof(double));
    for (int r = 0; r < nr; r++) {
        if (r == me || recv_bytes[r] == 0) continue;
        const unsigned char *at = recv + recv_offset[r];
        const int64_t np = get_i64(&at), nc = get_i64(&at), nb = get_i64(&at);
        for (int64_t k = 0; k < np; k++) {
            dem_particles_unpack(p, at);
            at += ps;
        }
        for (int64_t k = 0; k < nc; k++) {
            const int64_t first = get_i64(&at), second = get_i64(&at);
            memcpy(h, at, (size_t)hs * sizeof(double));
            at += (size_t)hs * sizeof(double);
            dem_contact_store_put(&cr->spill, first, second, h);
        }
        for (int64_t k = 0; k < nb; k++) {
            dem_bodies_unpack(&s->bodies, at);
            at += bs;
        }
    }
    free(h);
    free(now);
    free(send);
    free(recv);
    free(part_at);
    free(contact_at);
    free(body_at);
    free(send_bytes);
    free(send_offset);
    free(recv_bytes);
    free(recv_offset);
    free(bytes_to);
    free(bytes_from);
    free(np_to);
    free(nc_to);
    free(nb_to);
    free(dest);
    free(body_dest);
}
