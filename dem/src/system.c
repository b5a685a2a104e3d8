/* Run state and the velocity-Verlet step (translation and rotation of spheres). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "comm.h"
#include "error.h"
#include "migrate.h"
#include "system.h"
#include "reduce.h"
#include "timestep.h"

void dem_system_init(dem_system *s)
{
    memset(s, 0, sizeof *s);
    dem_particles_init(&s->p);
    s->models.fn_floor = -INFINITY;   /* the models: each slot's first (models.h) */
    s->max_overlap_fraction = 0.2;
    s->coarse_graining = 1.0;
    dem_neighbour_init(&s->nlist, 0.0, 20, 0);
}

void dem_system_free(dem_system *s)
{
    dem_particles_free(&s->p);
    dem_bodies_free(&s->bodies);
    dem_neighbour_free(&s->nlist);
    dem_walls_free(s);
    dem_ghosts_free(&s->ghosts);
    dem_decomposition_free(&s->decomp);
    dem_contact_rows_free(&s->carried);
    free(s->outlets);
    dem_streams_free(s);
    memset(s, 0, sizeof *s);
}

/* A new neighbour list and wall lists, the contacts' history carried across by particle ids. */
/* A particle that moves more than half its radius in one step can pass through a contact or a
 * wall unseen. The lists are rebuilt as soon as one particle has moved half the skin since the
 * last build, so at a rebuild every particle had moved less than that up to the step before: one
 * that has now moved more than half the skin plus half its radius moved more than half its radius
 * in this one step. */
static void check_step_motion(const dem_system *s)
{
    const dem_particles *p = &s->p;
    const dem_vec3 *x0 = s->nlist.x_at_build;
    const int listed = p->n < s->nlist.rows ? p->n : s->nlist.rows;
    for (int i = 0; i < listed; i++) {
        if (p->id[i] != s->nlist.id_at_build[i]) continue;   /* another particle since the build */
        const double dx = p->x[i][0] - x0[i][0], dy = p->x[i][1] - x0[i][1], dz = p->x[i][2] - x0[i][2];
        const double lim = 0.5 * (s->nlist.skin + p->radius[i]);
        if (!(dx * dx + dy * dy + dz * dz <= lim * lim)) {
            const double *v = p->v[i], speed = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            if (!isfinite(dx + dy + dz + speed)) dem_system_check_health(s);   /* a NaN is no motion: say it blew up */
            dem_fatal("particle id %lld moved more than half its radius (%g m) in the step to t = %g s (step "
                      "%ld): its speed %g m/s carries it %g m per step of %g s, so it can pass through "
                      "contacts and walls unseen. Lower timeStep below %g s, or find what accelerated it "
                      "(gravity, an insertion velocity, a soft material that let it sink into others).",
                      (long long)p->id[i], p->radius[i], s->time + s->dt, s->step + 1, speed, speed * s->dt, s->dt,
                      speed > 0.0 ? 0.5 * p->radius[i] / speed : s->dt);
        }
    }
}

/* A parallel run's boxes cut again where the load is now, when the busiest rank has more than
 * DEM_REBALANCE_ABOVE x the mean (a bed that settles or bubbles moves its load); looked at every
 * DEM_REBALANCE_EVERY list builds (2 % and 5 since 2026-12-08: 5 % and 10 left the 50k scene's
 * settling at 1.78x on 2 ranks, these give 1.83x, measured).
 * The load is the measured compute time since the last look (what runs without messages:
 * integration, the list builds' own work, pair contacts, walls), shared out on each rank over its
 * particles: a particle's cost is the rank's integration, list and wall time per particle plus
 * its pair time per listed pair times the pairs it holds. (The list builds count: in a settling
 * bed the dilute rank lists more particles for fewer pairs, and left out they cost the 50k scene
 * a rank waiting 3 s of 46 in the step's first reduction, measured.) So the cut follows where the time goes (a dense bed's touching pairs
 * cost more than a dilute region's listed ones), not only the counts. Migration then takes each
 * particle to its new owner. */
static void rebalance(dem_system *s)
{
    if (s->nlist.builds % DEM_REBALANCE_EVERY != 0) return;
    const int nranks = dem_comm_size(), n = s->p.n;
    const dem_neighbour_list *nl = &s->nlist;
    double *secs = s->stage_seconds, *last = s->stage_seconds_at_balance;
    const double t_particles = secs[DEM_STAGE_INTEGRATE] - last[DEM_STAGE_INTEGRATE] + secs[DEM_STAGE_WALLS] - last[DEM_STAGE_WALLS]
                               + nl->build_seconds - s->build_seconds_at_balance;
    const double t_pairs = secs[DEM_STAGE_PAIRS] - last[DEM_STAGE_PAIRS];
    memcpy(last, secs, sizeof s->stage_seconds_at_balance);
    s->build_seconds_at_balance = nl->build_seconds;
    dem_neighbour_wrap(s);
    double *cost = dem_malloc((size_t)(n ? n : 1) * sizeof *cost), *held = dem_malloc((size_t)nranks * sizeof *held);
    const double per_particle = n ? t_particles / n : 0.0, per_pair = nl->npairs ? t_pairs / (double)nl->npairs : 0.0;
    for (int i = 0; i < n; i++)   /* the lists are those of the last build: the same particles */
        cost[i] = per_particle + per_pair * (i < nl->rows && nl->id_at_build[i] == s->p.id[i] ? nl->start[i + 1] - nl->start[i] : 0);
    const double imbalance = dem_decomposition_imbalance(&s->decomp, n, (const dem_vec3 *)s->p.x, cost, held);
    if (imbalance > DEM_REBALANCE_ABOVE) {
        dem_decomposition_free(&s->decomp);
        dem_decompose_rcb(&s->decomp, nranks, s->domain_min, s->domain_max, n, (const dem_vec3 *)s->p.x, cost);
        s->rebalances++;
    }
    free(cost);
    free(held);
}

/* The neighbour and wall lists made again, each contact's history carried over by its ids. */
static void remake_lists(dem_system *s)
{
    dem_contacts_gather_rows(s, &s->carried);
    if (dem_comm_size() > 1) {
        rebalance(s);
        dem_migrate(s);   /* particles that left this rank's box, with their contacts */
    }
    dem_neighbour_rebuild(s);
    dem_walls_build_candidates(s);
    dem_contacts_scatter_rows(s, &s->carried);
}

/* A rebuild within a step; with `lifecycle`, outlets remove and streams insert first (the
 * removal and insertion, and the rebuild they cause, are timed as stages of their own). */
static void rebuild(dem_system *s, int lifecycle, double *t)
{
    check_step_motion(s);
    if (lifecycle) {
        dem_lifecycle_apply(s);
        dem_stage_lap(s->stage_seconds, DEM_STAGE_LIFECYCLE, t);
    }
    remake_lists(s);
    dem_stage_lap(s->stage_seconds, lifecycle ? DEM_STAGE_LIST_LIFECYCLE : DEM_STAGE_LIST, t);
}

/* Each chosen model's derived constants per material pair, and the reach of the normal model
 * (the largest over the material pairs at the largest particle, pair and wall). */
static void prepare_models(dem_system *s)
{
    dem_material_table *t = &s->materials;
    for (int slot = 0; slot < SLOT_COUNT; slot++) {
        const dem_contact_model *d = system_model(s, slot);
        if (d->prepare)
            for (int a = 0; a < t->ntypes; a++)
                for (int b = 0; b < t->ntypes; b++) d->prepare(&t->pair[a * DEM_MAX_TYPES + b], &s->models);
    }
    const dem_contact_model *normal = system_model(s, SLOT_NORMAL);
    s->contact_reach = 0.0;
    if (normal->reach) {
        double dmin, dmax;
        dem_streams_diameters(s, -1, &dmin, &dmax);   /* and the particles still to come */
        double rmax = 0.5 * dmax;
        for (int i = 0; i < s->p.n; i++) rmax = fmax(rmax, s->p.radius[i]);
        dem_reduce_doubles(&rmax, 1, DEM_REDUCE_MAX);
        for (int a = 0; a < t->ntypes; a++)
            for (int b = 0; b < t->ntypes; b++)
                s->contact_reach = fmax(s->contact_reach, fmax(normal->reach(materials_pair(t, a, b), 0.5 * rmax),
                                                               normal->reach(materials_pair(t, a, b), rmax)));
    }
    s->nlist.reach = s->contact_reach;
}

/* The ranks' boxes (decompose.h), by particle count: at set-up every rank holds every particle
 * (the case's insertion draws them all, a restart reads the snapshot whole), so the tree is the
 * same at any rank count for the same particles; then each rank keeps what its box owns. */
static void decompose(dem_system *s)
{
    const int nranks = dem_comm_size();
    dem_decomposition_free(&s->decomp);
    dem_decompose_rcb(&s->decomp, nranks, s->domain_min, s->domain_max, s->p.n, (const dem_vec3 *)s->p.x, NULL);
    dem_migrate_keep_owned(s);
}

long dem_system_setup_with_contacts(dem_system *s, const dem_contact_store *saved, int compute_forces)
{
    s->history_size = dem_contact_history_size(&s->models);
    s->nlist.history_size = s->history_size;
    s->nlist.history_antisymmetric = dem_contact_history_antisymmetric(&s->models);
    dem_contact_rows_free(&s->carried);
    dem_contact_rows_init(&s->carried, s->history_size, s->nlist.history_antisymmetric);
    if (s->nsymmetry && s->bodies.n)
        dem_fatal("multisphere bodies with symmetry planes are not supported yet (a plane mirrors spheres, "
                  "not bodies)");
    for (int d = 0; d < 3; d++) {
        if (s->periodic[d] && s->bodies.n)
            dem_fatal("multisphere bodies in a periodic direction (%c) are not supported yet: close the domain "
                      "with walls", "xyz"[d]);
        s->period[d] = s->periodic[d] ? s->domain_max[d] - s->domain_min[d] : 0.0;
        s->inv_period[d] = s->periodic[d] ? 1.0 / s->period[d] : 0.0;
    }
    if (s->nlist.skin <= 0.0) {   /* 10 % of the smallest diameter, the streams' included */
        double dmin, dmax;
        dem_streams_diameters(s, -1, &dmin, &dmax);
        double rmin = 0.5 * dmin;
        for (int i = 0; i < s->p.n; i++) rmin = fmin(rmin, s->p.radius[i]);
        s->nlist.skin = isfinite(rmin) ? 0.2 * rmin : 1e-3;
    }
    decompose(s);
    if (!s->balance_started) {   /* a fresh run: the initial particles count as inserted */
        s->inserted = dem_lifecycle_held(s);
        s->balance_started = 1;
    }
    prepare_models(s);
    dem_walls_move(s, s->time);
    dem_neighbour_rebuild(s);
    dem_walls_build_candidates(s);
    const long found = saved ? dem_contacts_scatter(s, saved) : 0;
    if (compute_forces) dem_system_compute_forces(s);
    return found;
}

void dem_system_relist(dem_system *s)
{
    s->nlist.schedule = 0;   /* as in a fresh system: the first build sorts */
    dem_walls_move(s, s->time);
    remake_lists(s);
}

void dem_system_setup(dem_system *s)
{
    dem_system_setup_with_contacts(s, NULL, 1);
}

/* t: the clock at the start (each stage's time is lapped off it, stage_timer.h) */
static void add_contact_forces(dem_system *s, double *t)
{
    double *secs = s->stage_seconds;
    s->max_overlap_seen = 0.0;
    dem_ghosts_update(s);
    dem_stage_lap(secs, DEM_STAGE_GHOSTS, t);
    dem_pair_forces_add(s);
    dem_stage_lap(secs, DEM_STAGE_PAIRS, t);
    dem_ghosts_fold_forces(s);
    dem_stage_lap(secs, DEM_STAGE_GHOSTS, t);
    dem_walls_add_forces(s);
    dem_stage_lap(secs, DEM_STAGE_WALLS, t);
    if (s->bodies.n) {
        dem_bodies_sum_forces(s);
        dem_stage_lap(secs, DEM_STAGE_BODIES, t);
    }
}

void dem_system_compute_forces(dem_system *s)
{
    dem_particles *p = &s->p;
    for (int i = 0; i < p->n; i++) {
        for (int d = 0; d < 3; d++) {
            p->f[i][d] = p->mass[i] * s->gravity[d] + p->f_ext[i][d];
            p->torque[i][d] = 0.0;
        }
    }
    double t = dem_clock();
    add_contact_forces(s, &t);
}

static void half_kick(dem_particles *p, double dt)
{
    const double h = 0.5 * dt;
    for (int i = 0; i < p->n; i++) {
        const double am = h * p->inv_mass[i], ai = h * p->inv_inertia[i];
        for (int d = 0; d < 3; d++) {
            p->v[i][d] += am * p->f[i][d];
            p->omega[i][d] += ai * p->torque[i][d];
        }
    }
}

/* First half of the velocity-Verlet step in one pass over the particles: half kick, drift,
 * the forces reset to gravity + external (the old forces are not needed after the kick). Written
 * so that the compiler vectorises it: no reductions. With symmetry planes the
 * same pass mirrors, between drift and reset, the centres that crossed a plane (symmetry.h; the
 * bounce needs the old force); that loop has a branch and is kept apart, so that a case without
 * planes runs the vectorised one. */
static void kick_drift_reset(dem_system *s)
{
    dem_particles *p = &s->p;
    const double dt = s->dt, h = 0.5 * dt, g[3] = {s->gravity[0], s->gravity[1], s->gravity[2]};
    dem_vec3 *restrict x = p->x, *restrict v = p->v, *restrict w = p->omega, *restrict f = p->f, *restrict t = p->torque;
    const dem_vec3 *restrict f_ext = p->f_ext;
    const double *restrict inv_mass = p->inv_mass, *restrict inv_inertia = p->inv_inertia, *restrict mass = p->mass;
    if (s->nsymmetry == 0) {
#pragma GCC ivdep   /* the arrays do not overlap (restrict is not enough for GCC 12 here) */
        for (int i = 0; i < p->n; i++) {
            for (int d = 0; d < 3; d++) {
                v[i][d] += h * inv_mass[i] * f[i][d];
                w[i][d] += h * inv_inertia[i] * t[i][d];
                x[i][d] += dt * v[i][d];
                f[i][d] = mass[i] * g[d] + f_ext[i][d];
                t[i][d] = 0.0;
            }
        }
    } else {
        const dem_symmetry_plane *planes = s->symmetry_planes;
        const int nplanes = s->nsymmetry;
        for (int i = 0; i < p->n; i++) {
            for (int d = 0; d < 3; d++) {
                v[i][d] += h * inv_mass[i] * f[i][d];
                w[i][d] += h * inv_inertia[i] * t[i][d];
                x[i][d] += dt * v[i][d];
            }
            symmetry_apply(planes, nplanes, x[i], v[i], f[i], inv_mass[i], dt);
            for (int d = 0; d < 3; d++) {
                f[i][d] = mass[i] * g[d] + f_ext[i][d];
                t[i][d] = 0.0;
            }
        }
    }
}

/* Whether some particle moved more than half the skin since the last list build (or the
 * particle set changed since: its generation). */
static int moved_far_since_build(const dem_system *s)
{
    if (s->p.generation != s->nlist.generation) return dem_reduce_any(1);
    const dem_vec3 *restrict x = s->p.x, *restrict x0 = s->nlist.x_at_build;
    const double limit = 0.25 * s->nlist.skin * s->nlist.skin;
    const int listed = s->p.n;
    int moved_far = 0;
    for (int i = 0; i < listed; i++) {
        const double dx = x[i][0] - x0[i][0], dy = x[i][1] - x0[i][1], dz = x[i][2] - x0[i][2];
        moved_far |= dx * dx + dy * dy + dz * dz > limit;
    }
    return dem_reduce_any(moved_far);   /* every rank rebuilds when one must (reduce.h) */
}

void dem_system_step(dem_system *s)
{
    dem_particles *p = &s->p;
    double *secs = s->stage_seconds, t = dem_clock();
    kick_drift_reset(s);
    dem_stage_lap(secs, DEM_STAGE_INTEGRATE, &t);
    if (s->bodies.n) {
        dem_bodies_kick_drift(s);   /* the bodies' spheres put where their body is */
        dem_stage_lap(secs, DEM_STAGE_BODIES, &t);
    }
    const int moved_far = moved_far_since_build(s);
    /* particles out or due in (on any rank: the rebuild is made by all) */
    const int lifecycle = (s->noutlets || s->nstreams) && dem_reduce_any(dem_lifecycle_due(s));
    const int walls_moved = dem_walls_move(s, s->time + s->dt);                   /* walls at the step's end */
    dem_stage_lap(secs, DEM_STAGE_LIST, &t);
    if (walls_moved || moved_far || lifecycle) rebuild(s, lifecycle, &t);
    add_contact_forces(s, &t);
    half_kick(p, s->dt);
    dem_stage_lap(secs, DEM_STAGE_INTEGRATE, &t);
    if (s->bodies.n) {
        dem_bodies_kick(s);
        dem_stage_lap(secs, DEM_STAGE_BODIES, &t);
    }
    s->time += s->dt;
    s->step++;
    if (s->max_overlap_seen > s->max_overlap_fraction || s->step % 256 == 0) {
        dem_system_check_health(s);
        dem_stage_lap(secs, DEM_STAGE_CHECKS, &t);
    }
}

void dem_system_check_health(const dem_system *s)
{
    const dem_particles *p = &s->p;
    for (int i = 0; i < p->n; i++) {
        const double *x = p->x[i], *v = p->v[i], *w = p->omega[i];
        if (!(isfinite(x[0]) && isfinite(x[1]) && isfinite(x[2]) && isfinite(v[0]) && isfinite(v[1]) &&
              isfinite(v[2]) && isfinite(w[0]) && isfinite(w[1]) && isfinite(w[2])))
            dem_fatal("the state blew up at t = %g s (step %ld): particle id %lld has position "
                      "(%g %g %g) m, velocity (%g %g %g) m/s. Reduce timeStep or check the "
                      "material and insertion parameters.",
                      s->time, s->step, (long long)p->id[i], x[0], x[1], x[2], v[0], v[1], v[2]);
    }
    if (s->max_overlap_seen > s->max_overlap_fraction) {
        /* which is at fault: the step (too long for the contacts at the present speeds) or the
         * stiffness (the step resolves the contacts, but they sink in that far under the load) */
        double v2 = 0.0;
        for (int i = 0; i < p->n; i++)
            v2 = fmax(v2, p->v[i][0] * p->v[i][0] + p->v[i][1] * p->v[i][1] + p->v[i][2] * p->v[i][2]);
        const double vrel = fmax(2.0 * sqrt(v2), 1e-3);   /* head on */
        const dem_timestep_limits lim = dem_timestep_limits_compute(s, vrel);
        if (s->dt <= lim.largest_safe_dt)
            dem_fatal("a contact overlap reached %.3g of the smaller radius at t = %g s (step %ld) (maxOverlapFraction "
                      "%g). The time step is not the cause: %g s is %.3g of the contact time %.3g s of %s at the "
                      "present speeds (up to %.3g m/s between two particles). The material is too soft for these "
                      "impacts and loads: raise youngsModulus, or maxOverlapFraction if such overlaps are meant.",
                      s->max_overlap_seen, s->time, s->step, s->max_overlap_fraction, s->dt,
                      s->dt / lim.contact_time, lim.contact_time, lim.contact_pair, vrel);
        dem_fatal("the state blew up at t = %g s (step %ld): a contact overlap reached %.3g of the smaller "
                  "radius (maxOverlapFraction %g). The time step %g s is too long for the contacts at the present "
                  "speeds (up to %.3g m/s between two particles: the largest safe step is %.3g s, from the %s "
                  "contact time %.3g s): lower timeStep, or find what accelerated the particles (or whether "
                  "they were inserted overlapping).",
                  s->time, s->step, s->max_overlap_seen, s->max_overlap_fraction, s->dt, vrel,
                  lim.largest_safe_dt, lim.contact_pair, lim.contact_time);
    }
}

double dem_system_kinetic_energy(const dem_system *s)
{
    const dem_particles *p = &s->p;
    double e = dem_bodies_kinetic_energy(s);
    for (int i = 0; i < p->n; i++) {
        /* a body's sphere is counted with its body; a prescribed particle, driven whatever the
         * forces, has no inertia the dynamics sees (inv_mass = inv_inertia = 0): left out */
        if (p->body[i] || p->prescribed[i]) continue;
        const double *v = p->v[i], *w = p->omega[i];
        e += 0.5 * p->mass[i] * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        e += 0.5 / p->inv_inertia[i] * (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    }
    return e;
}
