/* The particles' life cycle during a run (lifecycle.h). */
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "comm.h"
#include "error.h"
#include "reduce.h"
#include "system.h"

dem_tally dem_lifecycle_held(const dem_system *s)
{
    const dem_particles *p = &s->p;
    dem_tally t = {0, 0};
    for (int i = 0; i < p->n; i++)
        if (!p->body[i]) dem_tally_add(&t, 1, dem_mass_to_quanta(p->mass[i]));
    for (int b = 0; b < s->bodies.n; b++)
        dem_tally_add(&t, 1, dem_mass_to_quanta(dem_body_mass(&s->bodies, b)));
    return t;
}

dem_tally dem_system_remove_marked(dem_system *s, const int *mark)
{
    dem_particles *p = &s->p;
    dem_bodies *b = &s->bodies;
    dem_tally gone = {0, 0};
    unsigned char *body_gone = dem_calloc((size_t)(b->n ? b->n : 1), 1);
    for (int i = 0; i < p->n; i++)
        if (mark[i] && p->body[i]) body_gone[dem_body_index(b, p->body[i])] = 1;
    for (int k = 0; k < b->n; k++)
        if (body_gone[k]) dem_tally_add(&gone, 1, dem_mass_to_quanta(dem_body_mass(b, k)));
    /* from the top down: the particle moved into a hole is always one that stays */
    for (int i = p->n - 1; i >= 0; i--) {
        const int body = p->body[i];
        if (!(mark[i] || (body && body_gone[dem_body_index(b, body)]))) continue;
        if (!body) dem_tally_add(&gone, 1, dem_mass_to_quanta(p->mass[i]));
        dem_particles_remove(p, i);
    }
    /* mark[] was indexed as the particles were: the ones moved down were all kept, so the pass
     * above saw each index once */
    if (b->n) dem_bodies_remove(s, body_gone);
    free(body_gone);
    dem_tally_add(&s->removed, gone.count, gone.mass);
    return gone;
}

int dem_lifecycle_due(const dem_system *s)
{
    return (s->nstreams && dem_streams_due(s, s->step + 1)) || (s->noutlets && dem_outlets_any(s, s->step + 1));
}

void dem_lifecycle_apply(dem_system *s)
{
    if (s->noutlets) dem_outlets_remove(s, s->step + 1);
    if (s->nstreams) dem_streams_insert(s, s->step + 1);
}

/* A tally summed over the ranks, exactly: every rank's (count, mass) gathered (reduce.h) and
 * added up here in 128 bits. In a parallel run each rank counts what it removed and inserted;
 * the balance, the log and the snapshot are of them all. */
static dem_tally over_ranks(dem_tally t)
{
    const int size = dem_comm_size();
    if (size == 1) return t;
    int64_t mine[3] = {t.count, 0, 0}, *v = dem_malloc((size_t)3 * size * sizeof *v);
    dem_quanta_split(t.mass, &mine[1], &mine[2]);
    dem_reduce_gather_int64s(mine, 3, v);
    dem_tally sum = {0, 0};
    for (int r = 0; r < size; r++) dem_tally_add(&sum, v[3 * r], dem_quanta_join(v[3 * r + 1], v[3 * r + 2]));
    free(v);
    return sum;
}

/* "n (m kg)" */
static const char *tally_text(char *buf, size_t size, dem_tally t)
{
    snprintf(buf, size, "%" PRId64 " (%.9g kg)", t.count, dem_quanta_to_kg(t.mass));
    return buf;
}

/* the rate since the last log [1/s] and [kg/s]; the log point moved to now */
static void rate_since(dem_tally now, dem_tally *logged, double *logged_time, double time, double *number_rate,
                       double *mass_rate)
{
    const double dt = time - *logged_time;
    *number_rate = dt > 0.0 ? (double)(now.count - logged->count) / dt : 0.0;
    *mass_rate = dt > 0.0 ? dem_quanta_to_kg(now.mass - logged->mass) / dt : 0.0;
    *logged = now;
    *logged_time = time;
}

void dem_lifecycle_log(dem_system *s)
{
    if (!s->noutlets && !s->nstreams) return;
    const dem_tally held = over_ranks(dem_lifecycle_held(s)), inserted = over_ranks(s->inserted),
                    removed = over_ranks(s->removed);
    const int64_t dn = inserted.count - removed.count - held.count;
    const dem_mass_quanta dm = inserted.mass - removed.mass - held.mass;
    char a[96], b[96], c[96];
    dem_info("mass balance at t = %.9g s: inserted %s - removed %s - held %s = %" PRId64 " particles, %.3g kg%s",
             s->time, tally_text(a, sizeof a, inserted), tally_text(b, sizeof b, removed),
             tally_text(c, sizeof c, held), dn, dem_quanta_to_kg(dm), dn == 0 && dm == 0 ? " (exact)" : " MISMATCH");
    if (dn != 0 || dm != 0)
        dem_fatal("the particle mass balance does not close at t = %g s: %" PRId64 " particles, %g kg unaccounted "
                  "for (a defect: please report it with the case)", s->time, dn, dem_quanta_to_kg(dm));
    for (int k = 0; k < s->nstreams; k++) {
        dem_stream *st = &s->streams[k];
        double nr, mr;
        rate_since(st->inserted, &st->logged, &st->logged_time, s->time, &nr, &mr);
        char behind[128] = "";
        if (st->behind_count > 0 || st->behind_mass > 0.0)
            snprintf(behind, sizeof behind, "; behind by %" PRId64 " particles / %.4g kg, carried to the next event",
                     st->behind_count, st->behind_mass);
        dem_info("insertion '%s': inserted %s, %.6g particles/s, %.6g kg/s since the last write; %" PRId64
                 " particles carried over so far%s", st->ins.name, tally_text(a, sizeof a, st->inserted), nr, mr,
                 st->carried_total, behind);
    }
    for (int k = 0; k < s->noutlets; k++) {
        dem_outlet *o = &s->outlets[k];
        double nr, mr;
        const dem_tally gone = over_ranks(o->removed);   /* logged: the sum over the ranks too */
        rate_since(gone, &o->logged, &o->logged_time, s->time, &nr, &mr);
        dem_info("outlet '%s': removed %s, %.6g particles/s, %.6g kg/s since the last write", o->name,
                 tally_text(a, sizeof a, gone), nr, mr);
    }
}

/* "a b c" of the names */
static char *join_names(int n, const char *(*name_of)(const dem_system *, int), const dem_system *s)
{
    size_t len = 1;
    for (int k = 0; k < n; k++) len += strlen(name_of(s, k)) + 1;
    char *out = dem_calloc(len, 1);
    for (int k = 0; k < n; k++) {
        if (k) strcat(out, " ");
        strcat(out, name_of(s, k));
    }
    return out;
}
static const char *outlet_name(const dem_system *s, int k) { return s->outlets[k].name; }
static const char *stream_name(const dem_system *s, int k) { return s->streams[k].ins.name; }

/* The index of `name` among the space-separated `names`, or -1. */
static int name_index(const char *names, const char *name)
{
    const size_t len = strlen(name);
    int k = 0;
    for (const char *c = names; *c;) {
        const char *end = strchr(c, ' ');
        const size_t n = end ? (size_t)(end - c) : strlen(c);
        if (n == len && strncmp(c, name, n) == 0) return k;
        k++;
        if (!end) break;
        c = end + 1;
    }
    return -1;
}

static void put_tally(int64_t *out, dem_tally t)
{
    out[0] = t.count;
    dem_quanta_split(t.mass, &out[1], &out[2]);
}
static dem_tally get_tally(const int64_t *in)
{
    const dem_tally t = {in[0], dem_quanta_join(in[1], in[2])};
    return t;
}

void dem_lifecycle_to_state(const dem_system *s, dem_lifecycle_state *l)
{
    memset(l, 0, sizeof *l);
    if (!s->noutlets && !s->nstreams) return;
    l->present = 1;
    put_tally(&l->balance[0], over_ranks(s->inserted));   /* the whole run's: every rank writes the same */
    put_tally(&l->balance[3], over_ranks(s->removed));
    l->noutlets = s->noutlets;
    l->nstreams = s->nstreams;
    l->outlets = dem_malloc((size_t)(3 * s->noutlets + 1) * sizeof(int64_t));
    l->streams = dem_malloc((size_t)(LIFECYCLE_STREAM_INTS * s->nstreams + 1) * sizeof(int64_t));
    l->stream_reals = dem_malloc((size_t)(LIFECYCLE_STREAM_REALS * s->nstreams + 1) * sizeof(double));
    for (int k = 0; k < s->noutlets; k++) put_tally(&l->outlets[3 * k], over_ranks(s->outlets[k].removed));
    for (int k = 0; k < s->nstreams; k++) {
        const dem_stream *st = &s->streams[k];
        int64_t *o = &l->streams[LIFECYCLE_STREAM_INTS * k];
        for (int q = 0; q < 4; q++) o[q] = (int64_t)st->rng.s[q];
        put_tally(&o[4], st->inserted);
        o[7] = st->carried_total;
        o[8] = st->behind_count;
        l->stream_reals[LIFECYCLE_STREAM_REALS * k] = st->pending_diameter;
        l->stream_reals[LIFECYCLE_STREAM_REALS * k + 1] = st->behind_mass;
    }
    l->outlet_names = join_names(s->noutlets, outlet_name, s);
    l->stream_names = join_names(s->nstreams, stream_name, s);
}

void dem_lifecycle_from_state(dem_system *s, const dem_lifecycle_state *l, const char *where)
{
    s->balance_started = 1;
    if (!l || !l->present) {   /* a snapshot from before the life cycle: the balance starts here */
        s->inserted = dem_lifecycle_held(s);
        s->removed = (dem_tally){0, 0};
        if (s->noutlets || s->nstreams)
            dem_info("%s: the snapshot has no insertion and outlet counts; they start from here", where);
    } else {
        s->inserted = get_tally(&l->balance[0]);
        s->removed = get_tally(&l->balance[3]);
    }
    for (int k = 0; k < s->noutlets; k++) {
        dem_outlet *o = &s->outlets[k];
        const int j = l && l->present ? name_index(l->outlet_names, o->name) : -1;
        if (j >= 0 && j < l->noutlets) o->removed = get_tally(&l->outlets[3 * j]);
        else if (l && l->present) dem_info("%s: outlet '%s' is new: its counts start from here", where, o->name);
        o->logged = o->removed;
        o->logged_time = s->time;
    }
    /* every rank has read the whole run's counts; in a parallel run rank 0 carries them on and the
     * others count from zero, so that the sums over the ranks stay the run's (the logged values are
     * sums already) */
    if (dem_comm_rank() != 0) {
        s->inserted = s->removed = (dem_tally){0, 0};
        for (int k = 0; k < s->noutlets; k++) s->outlets[k].removed = (dem_tally){0, 0};
    }
    for (int k = 0; k < s->nstreams; k++) {
        dem_stream *st = &s->streams[k];
        const int j = l && l->present ? name_index(l->stream_names, st->ins.name) : -1;
        if (j >= 0 && j < l->nstreams) {
            const int64_t *in = &l->streams[LIFECYCLE_STREAM_INTS * j];
            for (int q = 0; q < 4; q++) st->rng.s[q] = (uint64_t)in[q];
            st->inserted = get_tally(&in[4]);
            st->carried_total = in[7];
            st->behind_count = in[8];
            st->pending_diameter = l->stream_reals[LIFECYCLE_STREAM_REALS * j];
            st->behind_mass = l->stream_reals[LIFECYCLE_STREAM_REALS * j + 1];
        } else if (s->time > st->start_time) {
            dem_warning("%s: insertion '%s' is not in the snapshot: it starts now, at t = %g s, with nothing "
                        "inserted, and so inserts at once what was due since its startTime %g s",
                        where, st->ins.name, s->time, st->start_time);
        }
        st->logged = st->inserted;
        st->logged_time = s->time;
    }
}
