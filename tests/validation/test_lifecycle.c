/* The particles' life cycle during a run (lifecycle.h, outlets.h, insert_stream.h), against
 * what must hold exactly:
 *   1. removal: every contact between two particles that stay keeps its history bit for bit,
 *      through a rebuild that keeps indices (carry by row) and one that sorts (carry by ids);
 *      none of a removed particle's contacts remain; the generation tells the lists they are stale;
 *   2. one removal and one insertion between two steps (the count unchanged): the step rebuilds
 *      and the new particle is in the list;
 *   3. a multisphere body is removed as one unit, the others keep their spheres and motion;
 *   4. an outlet plane crossed by particles in free flight (no gravity, no contacts) has removed,
 *      at every step, exactly the particles whose x0 + v t has passed it;
 *   5. a stream at a number rate has inserted floor(R t_due) at each event (exact integers); a
 *      stream through a face with an outlet downstream: inserted - removed - held = 0 exactly at
 *      every step, in count and in mass quanta, and at the end everything inserted has left;
 *   6. a stream that cannot place what is due carries it over, counts it, and inserts all of it
 *      later (events go on after endTime until nothing is due);
 *   7. bad input: file:line:key errors (face outside the domain, a rate that cannot fit, with the
 *      largest that fits, a velocity that does not cross the face, both rates, a body stream,
 *      an outlet with a zero normal). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "case.h"
#include "case_files.h"
#include "catch_fatal.h"
#include "harness.h"
#include "insert.h"

static int tally_is(dem_tally a, dem_tally b) { return a.count == b.count && a.mass == b.mass; }

/* inserted - removed - held == 0 exactly */
static int balance_closes(const dem_system *s)
{
    const dem_tally held = dem_lifecycle_held(s);
    return s->inserted.count - s->removed.count - held.count == 0 && s->inserted.mass - s->removed.mass - held.mass == 0;
}

/* A small settled pile: spheres poured into a box onto a floor, with friction (tangential history). */
static void make_pile(dem_system *s, int sort_interval)
{
    make_system(s, 5e6, 0.3, 2500, 0.5, 0.5, normal_hertz, tangential_history, 0.02);
    s->gravity[2] = -9.81;
    s->dt = 2e-6;
    s->nlist.sort_interval = sort_interval;
    add_plane(s, 0, 0, -0.02, 0, 0, 1);
    dem_rng r;
    rng_seed(&r, 7);
    for (int i = 0; i < 300; i++) {   /* a loose lattice, jittered */
        const double x = -0.012 + 0.003 * (i % 9) + 2e-4 * rng_uniform(&r);
        const double y = -0.012 + 0.003 * ((i / 9) % 9) + 2e-4 * rng_uniform(&r);
        const double z = -0.0185 + 0.003 * (i / 81);
        add_sphere(s, x, y, z, 0, 0, 0, 1e-3);
    }
    dem_system_setup(s);
    for (int k = 0; k < 20000; k++) dem_system_step(s);
}

/* 1. */
static void removal_keeps_contacts(int sort_interval)
{
    dem_system s;
    make_pile(&s, sort_interval);
    dem_contact_store before, after;
    dem_contact_store_init(&before, s.history_size, s.nlist.history_antisymmetric);
    dem_contact_store_init(&after, s.history_size, s.nlist.history_antisymmetric);
    dem_contacts_gather(&s, &before);
    int *mark = calloc((size_t)s.p.n, sizeof *mark);
    char *gone_id = calloc((size_t)s.next_id, 1);
    for (int i = 0; i < s.p.n; i++)
        if (i % 7 == 3) { mark[i] = 1; gone_id[s.p.id[i]] = 1; }
    const long generation = s.p.generation;
    const int n0 = s.p.n;
    const dem_tally removed = dem_system_remove_marked(&s, mark);
    check_true("removal: the generation changed", s.p.generation != generation);
    check_true("removal: the count and the removed tally agree", removed.count == n0 - s.p.n && s.removed.count == removed.count);
    /* the lists made again: a relist sorts when sortInterval > 0 (carry by ids); without sorting the
     * rows that kept their particle carry in place */
    dem_system_relist(&s);
    check_true("removal: the lists were made for the new generation", s.nlist.generation == s.p.generation);
    dem_contacts_gather(&s, &after);
    long kept = 0, lost = 0, stale = 0, wrong = 0, walls = 0;
    double *h = malloc((size_t)(s.history_size + 1) * sizeof *h);
    for (long k = 0; k < before.capacity; k++) {
        if (!before.used[k]) continue;
        const int64_t a = before.first[k], b = before.second[k];
        const int out = (a >= 0 && gone_id[a]) || gone_id[b];
        const int found = dem_contact_store_take(&after, a, b, h);
        if (out) { stale += found; continue; }
        if (!found) { lost++; continue; }
        kept++;
        walls += a < 0;
        if (memcmp(h, before.history + (size_t)k * s.history_size, (size_t)s.history_size * sizeof *h) != 0) wrong++;
    }
    char what[120];
    printf("      %ld contacts before, %ld between particles that stay (%ld with the floor), %ld after\n", before.count,
           kept + lost, walls, after.count);
    snprintf(what, sizeof what, "removal (sortInterval %d): contacts kept, none lost", sort_interval);
    check_true(what, kept > 100 && walls > 20 && lost == 0);
    snprintf(what, sizeof what, "removal (sortInterval %d): their histories bit for bit", sort_interval);
    check_true(what, wrong == 0);
    snprintf(what, sizeof what, "removal (sortInterval %d): no contact of a removed particle", sort_interval);
    check_true(what, stale == 0 && after.count == kept);
    check_true("removal: the balance closes", balance_closes(&s));
    for (int k = 0; k < 2000; k++) dem_system_step(&s);   /* runs on, healthy */
    dem_system_check_health(&s);
    free(h); free(mark); free(gone_id);
    dem_contact_store_free(&before);
    dem_contact_store_free(&after);
    dem_system_free(&s);
}

/* 2. */
static void one_out_one_in(void)
{
    dem_system s;
    make_pile(&s, 20);
    for (int k = 0; k < 5; k++) dem_system_step(&s);   /* a step without a rebuild since */
    int *mark = calloc((size_t)s.p.n, sizeof *mark);
    mark[s.p.n / 2] = 1;
    const int n0 = s.p.n;
    dem_system_remove_marked(&s, mark);
    /* a new sphere touching the top of the highest one */
    int top = 0;
    for (int i = 0; i < s.p.n; i++) if (s.p.x[i][2] > s.p.x[top][2]) top = i;
    const int j = add_sphere(&s, s.p.x[top][0], s.p.x[top][1], s.p.x[top][2] + 1.999e-3, 0, 0, 0, 1e-3);
    check_true("one out, one in: the count is as before", s.p.n == n0);
    const long builds = s.nlist.builds;
    dem_system_step(&s);
    check_true("one out, one in: the next step rebuilt its lists", s.nlist.builds == builds + 1 &&
               s.nlist.generation == s.p.generation);
    int listed = 0;
    const int64_t new_id = s.next_id - 1;
    for (int i = 0; i < s.nlist.rows; i++)
        for (int k = s.nlist.start[i]; k < s.nlist.start[i + 1]; k++)
            listed |= (s.p.id[i] == new_id || s.p.id[s.nlist.partner[k]] == new_id);
    (void)j;
    check_true("one out, one in: the new sphere's contact is listed", listed);
    free(mark);
    dem_system_free(&s);
}

/* 3. */
static void body_removed_whole(void)
{
    dem_system s;
    make_system(&s, 5e7, 0.3, 2500, 0.5, 0.5, normal_hertz, tangential_history, 0.1);
    s.dt = 1e-6;
    const double x[2][3] = {{0, 0, 0}, {2e-3, 0, 0}}, r[2] = {1e-3, 1e-3};
    const int t = dem_bodies_add_template(&s.bodies, "pair", 2, x, r, 0, 2500, CLUMP_MASS_SPHERE_SUM);
    const double q[4] = {1, 0, 0, 0};
    for (int b = 0; b < 3; b++) {
        const double X[3] = {-0.05 + 0.04 * b, 0, 0}, V[3] = {0.1 * b, 0, 0}, W[3] = {0, 0, 10.0 * (b + 1)};
        dem_bodies_add(&s, t, X, q, V, W);
    }
    add_sphere(&s, 0, 0.05, 0, 0, 0, 0, 1e-3);
    add_sphere(&s, 0, -0.05, 0, 0, 0, 0, 1e-3);
    dem_system_setup(&s);
    for (int k = 0; k < 100; k++) dem_system_step(&s);
    const int64_t id2 = s.bodies.id[2];
    double w2[3];
    dem_body_omega(&s.bodies, 2, w2);
    int *mark = calloc((size_t)s.p.n, sizeof *mark);
    for (int i = 0; i < s.p.n; i++)
        if (s.p.body[i] == 1 + (int)s.bodies.id[1]) { mark[i] = 1; break; }   /* one sphere of the middle body */
    const dem_tally gone = dem_system_remove_marked(&s, mark);
    const double M = s.bodies.templates[t].mass.mass;
    check_true("body: removed as one unit (one body, its mass)", gone.count == 1 && gone.mass == dem_mass_to_quanta(M));
    check_true("body: 2 bodies and 6 spheres remain", s.bodies.n == 2 && s.p.n == 6);
    int k2 = -1;
    for (int k = 0; k < s.bodies.n; k++) if (s.bodies.id[k] == id2) k2 = k;
    double w[3];
    if (k2 >= 0) dem_body_omega(&s.bodies, k2, w);
    check_true("body: the last body took the freed index, with its spin", k2 == 1 && w[2] == w2[2]);
    for (int k = 0; k < 100; k++) dem_system_step(&s);
    double worst = 0.0;   /* each sphere where its (renumbered) body puts it */
    int spheres_of[2] = {0, 0};
    for (int i = 0; i < s.p.n; i++) {
        if (!s.p.body[i]) continue;
        const int b = dem_body_index(&s.bodies, s.p.body[i]);
        spheres_of[b]++;
        double off[3];
        for (int d = 0; d < 3; d++)
            off[d] = s.bodies.R[b][d][0] * s.p.body_offset[i][0] + s.bodies.R[b][d][1] * s.p.body_offset[i][1] +
                     s.bodies.R[b][d][2] * s.p.body_offset[i][2];
        for (int d = 0; d < 3; d++) worst = fmax(worst, fabs(s.p.x[i][d] - s.bodies.x[b][d] - off[d]));
    }
    check_true("body: each remaining body has its 2 spheres, placed by it", spheres_of[0] == 2 && spheres_of[1] == 2 &&
               worst < 1e-15);
    check_true("body: the balance closes", balance_closes(&s));
    free(mark);
    dem_system_free(&s);
}

/* 4. every: the outlet acts in the steps that are multiples of it (its `interval`) */
static void outlet_free_flight(long every)
{
    dem_system s;
    make_system(&s, 5e7, 0.3, 2500, 0.5, 0.5, normal_hertz, tangential_history, 0.1);
    s.dt = 1e-5;
    const int n = 50;
    const double v = 2.0, L = 0.05;
    double x0[50];
    for (int i = 0; i < n; i++) {
        x0[i] = -0.09 + 0.0027 * i;
        add_sphere(&s, x0[i], 0.01 * (i % 3), 0, v, 0, 0, 1e-3);
    }
    dem_outlet *o = dem_outlets_add(&s, "end");
    o->kind = OUTLET_PLANE;
    o->point[0] = L;
    o->normal[0] = 1.0;
    o->every = every;
    dem_system_setup(&s);
    const double m = s.p.mass[0];
    long worst = 0;
    int closes = 1;
    for (int k = 1; k <= 8000; k++) {
        dem_system_step(&s);
        long expected = 0;   /* the step whose drift carried it across removed it, or the next multiple of `every` */
        const int last = (int)(k / every * every);   /* the last step in which the outlet acted */
        for (int i = 0; i < n; i++) {
            double x = x0[i];
            for (int q = 0; q < last; q++) x += s.dt * v;
            expected += x > L;
        }
        worst = labs(expected - (long)s.outlets[0].removed.count) > worst ? labs(expected - (long)s.outlets[0].removed.count) : worst;
        closes &= balance_closes(&s);
    }
    char what[160];
    snprintf(what, sizeof what, "outlet acting every %ld steps: removed exactly the particles past it in its steps, "
             "none in between", every);
    check_true(what, worst == 0);
    check_true("outlet: all 50 gone, their mass counted exactly", s.p.n == 0 && s.outlets[0].removed.count == n &&
               s.outlets[0].removed.mass == n * dem_mass_to_quanta(m));
    check_true("outlet: the balance closed at every step", closes);
    dem_system_free(&s);
}

/* A stream's diameters: constant d. */
static void constant_diameter(dem_insertion *ins, double d)
{
    ins->dist = SIZE_CONSTANT;
    ins->d_value = d;
}

/* 5. */
static void stream_rates(void)
{
    /* a number rate into a region, no gravity: the particles stay where placed */
    dem_system s;
    make_system(&s, 5e7, 0.3, 2500, 0.5, 0.5, normal_hertz, tangential_history, 0.1);
    s.dt = 1e-5;
    dem_stream *st = dem_streams_add(&s);
    snprintf(st->ins.name, sizeof st->ins.name, "cloud");
    constant_diameter(&st->ins, 1e-3);
    st->ins.max_attempts = 100;
    st->ins.region = REGION_BOX;
    for (int d = 0; d < 3; d++) { st->ins.min[d] = -0.08; st->ins.max[d] = 0.08; }
    st->shape = STREAM_REGION;
    st->number_rate = 3333.0;
    st->start_time = 1e-3;
    st->end_time = INFINITY;
    st->interval = 7e-4;   /* 70 steps */
    dem_stream_prepare(&s, st);
    dem_system_setup(&s);
    int exact = 1, events = 0;
    for (int k = 1; k <= 5000; k++) {
        dem_system_step(&s);
        if (k >= st->start_step && (k - st->start_step) % st->every == 0) {
            events++;
            const long m = (k - st->start_step) / st->every;
            exact &= st->inserted.count == (int64_t)floor(3333.0 * (m + 1) * 70 * 1e-5 + 1e-9);
        }
    }
    printf("      %d events, %lld particles\n", events, (long long)st->inserted.count);
    check_true("stream: a number rate inserts floor(R t) at every event", exact && events == 71 && s.p.n == st->inserted.count);
    dem_system_free(&s);

    /* a mass rate through a disc into a tube with an outlet at its end, no gravity */
    make_system(&s, 5e7, 0.3, 2500, 0.5, 0.5, normal_hertz, tangential_history, 0.1);
    s.dt = 1e-5;
    st = dem_streams_add(&s);
    snprintf(st->ins.name, sizeof st->ins.name, "feed");
    st->ins.dist = SIZE_UNIFORM;
    st->ins.d_min = 1e-3;
    st->ins.d_max = 1.5e-3;
    st->ins.max_attempts = 50;
    st->ins.velocity[2] = 1.0;
    st->ins.seed = 3;
    st->shape = STREAM_DISC;
    st->centre[2] = -0.1;
    st->normal[2] = 1.0;
    st->e1[0] = 1.0;
    st->e2[1] = 1.0;
    st->radius = 0.02;
    st->area = M_PI * 0.02 * 0.02;
    st->mass_rate = 0.02;
    st->end_time = 0.1;
    st->max_solid_fraction = 0.25;
    dem_stream_prepare(&s, st);
    dem_outlet *o = dem_outlets_add(&s, "top");
    o->kind = OUTLET_PLANE;
    o->point[2] = 0.0;
    o->normal[2] = 1.0;
    dem_system_setup(&s);
    int closes = 1;
    for (int k = 1; k <= 25000; k++) {
        dem_system_step(&s);
        closes &= balance_closes(&s);
    }
    const double mass = dem_quanta_to_kg(st->inserted.mass), particle = 2500 * M_PI / 6 * pow(1.5e-3, 3);
    printf("      inserted %lld particles, %.6g kg (due %.6g kg); removed %lld\n", (long long)st->inserted.count, mass,
           0.02 * 0.1, (long long)s.outlets[0].removed.count);
    check_true("stream: a mass rate inserts the mass due within one particle", mass >= 0.002 && mass < 0.002 + particle);
    check_true("stream + outlet: inserted - removed - held = 0 exactly at every step", closes);
    check_true("stream + outlet: everything inserted has left, the outlet counted it all",
               s.p.n == 0 && tally_is(s.outlets[0].removed, st->inserted) && tally_is(s.removed, s.inserted));
    dem_system_free(&s);
}

/* 6. */
static void stream_carries_over(void)
{
    dem_system s;
    make_system(&s, 5e7, 0.3, 2500, 0.5, 0.5, normal_hertz, tangential_history, 0.1);
    s.gravity[2] = -9.81;
    s.dt = 1e-5;
    dem_stream *st = dem_streams_add(&s);
    snprintf(st->ins.name, sizeof st->ins.name, "hopper");
    constant_diameter(&st->ins, 2e-3);
    st->ins.max_attempts = 30;
    st->ins.region = REGION_BOX;
    st->ins.min[0] = st->ins.min[1] = -0.004;
    st->ins.max[0] = st->ins.max[1] = 0.004;
    st->ins.min[2] = 0.09;
    st->ins.max[2] = 0.098;
    st->shape = STREAM_REGION;
    st->number_rate = 20000.0;   /* 20 per event: more than the small box holds at once */
    st->end_time = 0.01;
    st->interval = 1e-3;
    dem_stream_prepare(&s, st);
    dem_outlet *o = dem_outlets_add(&s, "bottom");
    o->kind = OUTLET_PLANE;
    o->point[2] = -0.09;
    o->normal[2] = -1.0;
    dem_system_setup(&s);
    int64_t most_behind = 0;
    int closes = 1;
    for (int k = 1; k <= 40000; k++) {
        dem_system_step(&s);
        if (st->behind_count > most_behind) most_behind = st->behind_count;
        closes &= balance_closes(&s);
    }
    printf("      at most %lld behind, %lld carried over in all; inserted %lld, behind %lld at the end\n",
           (long long)most_behind, (long long)st->carried_total, (long long)st->inserted.count,
           (long long)st->behind_count);
    check_true("carry-over: particles that did not fit were carried and counted", most_behind > 0 && st->carried_total > 0);
    check_true("carry-over: all 200 due were inserted in the end, nothing behind", st->inserted.count == 200 &&
               st->behind_count == 0 && st->pending_diameter == 0.0);
    check_true("carry-over: the balance closed at every step", closes);
    dem_system_free(&s);
}

/* 7. */
static const char *base_case =
    "timeStep 1e-5;\nendTime 0.01;\n"
    "domain { min (-0.05 -0.05 0); max (0.05 0.05 0.3); }\n"
    "materials { glass { youngsModulus 5e6; poissonsRatio 0.3; density 2500; } }\n"
    "contactModels { normal hertz; tangential history; }\n"
    "interactions { default { restitution 0.5; friction 0.5; } }\n"
    "outlets { top { type plane; point (0 0 0.28); normal (0 0 1); } }\n"
    "insertion\n{\n    feed\n    {\n        method stream;\n        material glass;\n"
    "        diameter { distribution constant; value 2e-3; }\n"
    "        face { type disc; centre (0 0 0.001); normal (0 0 1); radius 0.03; }\n"
    "        massRate 0.05;\n        velocity (0 0 3);\n    }\n}\n";

static void bad_input_case(const char *what, const char *from, const char *to, const char *expect)
{
    char dir[256];
    scratch_case("lifecycle_bad", dir, sizeof dir);
    char text[4096];
    const char *at = strstr(base_case, from);
    if (!at) { printf("test defect: '%s' not in the base case\n", from); exit(2); }
    snprintf(text, sizeof text, "%.*s%s%s", (int)(at - base_case), base_case, to, at + strlen(from));
    write_text(dir, "constant/demProperties", text);
    dem_system s;
    dem_system_init(&s);
    dem_run_settings rs;
    int ok;
    STOPS_WITH(ok, dem_case_read(dir, &s, &rs, 0), expect);
    check_true(what, ok);
    remove_case(dir);
}

static void bad_input(void)
{
    /* the base case reads */
    char dir[256];
    scratch_case("lifecycle_ok", dir, sizeof dir);
    write_text(dir, "constant/demProperties", base_case);
    dem_system s;
    dem_system_init(&s);
    dem_run_settings rs;
    dem_case_read(dir, &s, &rs, 0);
    check_true("bad input: the base case reads (one stream, one outlet)", s.nstreams == 1 && s.noutlets == 1);
    dem_system_free(&s);
    remove_case(dir);
    bad_input_case("bad input: a face outside the domain", "centre (0 0 0.001)", "centre (0.04 0 0.001)",
                   "demProperties:15: key 'centre': insertion 'feed': the face and the slab");
    bad_input_case("bad input: a rate that cannot fit, with the largest that does", "massRate 0.05",
                   "massRate 50", "demProperties:16: key 'massRate': insertion 'feed': 50 kg/s does not fit");
    bad_input_case("bad input: ... naming the largest rate that fits", "massRate 0.05", "massRate 50",
                   "carries at most 5.30144 kg/s");
    bad_input_case("bad input: a velocity that does not cross the face", "velocity (0 0 3)", "velocity (3 0 0)",
                   "demProperties:17: key 'velocity': insertion 'feed': the velocity (3 0 0) m/s must cross");
    bad_input_case("bad input: both rates", "massRate 0.05;", "massRate 0.05; numberRate 10;",
                   "demProperties:11: in 'demProperties/insertion/feed': give exactly one of 'massRate'");
    bad_input_case("bad input: a face and a region", "massRate 0.05;",
                   "massRate 0.05; region { type box; min (0 0 0); max (0.01 0.01 0.01); }",
                   "give exactly one of 'face'");
    bad_input_case("bad input: a stream of bodies", "material glass;", "material glass; body pair;",
                   "demProperties:13: key 'body': a stream inserts spheres");
    bad_input_case("bad input: an outlet with a zero normal", "normal (0 0 1); } }", "normal (0 0 0); } }",
                   "demProperties:7: key 'normal': the normal must not be zero");
    bad_input_case("bad input: an outlet of no known type", "type plane; point", "type hole; point",
                   "demProperties:7: key 'type': unknown option 'hole'");
    bad_input_case("bad input: an outlet interval shorter than the step", "normal (0 0 1); } }",
                   "normal (0 0 1); interval 1e-9; } }", "demProperties:7: key 'interval'");
}

int main(void)
{
    removal_keeps_contacts(0);
    removal_keeps_contacts(20);
    one_out_one_in();
    body_removed_whole();
    outlet_free_flight(1);
    outlet_free_flight(37);
    stream_rates();
    stream_carries_over();
    bad_input();
    return finish("test_lifecycle");
}
