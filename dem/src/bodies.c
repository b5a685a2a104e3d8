/* Multisphere bodies (bodies.h). */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bodies.h"
#include "error.h"
#include "rigid_rotation.h"
#include "system.h"

void dem_bodies_free(dem_bodies *b)
{
    for (int t = 0; t < b->ntemplates; t++) {
        free(b->templates[t].offset);
        free(b->templates[t].radius);
    }
    free(b->templates);
    free(b->index_of);
    free(b->template_of);
    free(b->id);
    free(b->x);
    free(b->v);
    free(b->q);
    free(b->Lb);
    free(b->f);
    free(b->torque);
    free(b->R);
    free(b->w);
    memset(b, 0, sizeof *b);
}

int dem_bodies_add_template(dem_bodies *b, const char *name, int n, const double (*x)[3], const double *radius,
                            int type, double density, enum dem_clump_mass_model model)
{
    if (n < 1) dem_fatal("multisphere template '%s': no spheres", name);
    b->templates = dem_realloc(b->templates, (size_t)(b->ntemplates + 1) * sizeof *b->templates);
    dem_clump_template *t = &b->templates[b->ntemplates];
    memset(t, 0, sizeof *t);
    snprintf(t->name, sizeof t->name, "%s", name);
    t->n = n;
    t->type = type;
    if (model == CLUMP_MASS_UNION) dem_clump_mass_union(n, x, radius, density, 1e-2, &t->mass);
    else dem_clump_mass_sphere_sum(n, x, radius, density, &t->mass);
    dem_quat_from_axes(t->mass.axes, t->q_axes);
    for (int d = 0; d < 3; d++) t->inv_principal[d] = 1.0 / t->mass.principal[d];
    double spheres = 0.0;
    for (int i = 0; i < n; i++) spheres += 4.0 / 3.0 * M_PI * radius[i] * radius[i] * radius[i];
    t->volume_scale = t->mass.volume / spheres;
    t->offset = dem_malloc((size_t)n * sizeof *t->offset);
    t->radius = dem_malloc((size_t)n * sizeof *t->radius);
    for (int i = 0; i < n; i++) {
        t->radius[i] = radius[i];
        for (int k = 0; k < 3; k++) {   /* principal coordinates: the axes' components */
            t->offset[i][k] = 0.0;
            for (int d = 0; d < 3; d++) t->offset[i][k] += t->mass.axes[k][d] * (x[i][d] - t->mass.com[d]);
        }
    }
    return b->ntemplates++;
}

static const dem_clump_template *template_of(const dem_bodies *b, int k) { return &b->templates[b->template_of[k]]; }

_Noreturn void dem_body_not_here(const dem_bodies *b, int body)
{
    dem_fatal("a sphere belongs to body id %d, which is not among the %d bodies here", body - 1, b->n);
}

/* index_of[id] = k (-1: the body left); the map grows with the ids */
static void set_index(dem_bodies *b, int64_t id, int k)
{
    if (id >= b->index_capacity) {
        int64_t cap = b->index_capacity ? b->index_capacity : 64;
        while (cap <= id) cap *= 2;
        b->index_of = dem_realloc(b->index_of, (size_t)cap * sizeof *b->index_of);
        for (int64_t j = b->index_capacity; j < cap; j++) b->index_of[j] = -1;
        b->index_capacity = cap;
    }
    b->index_of[id] = k;
}

static int append_body(dem_bodies *b)
{
    if (b->n == b->capacity) {
        b->capacity = b->capacity ? 2 * b->capacity : 64;
        const size_t c = (size_t)b->capacity;
        b->template_of = dem_realloc(b->template_of, c * sizeof *b->template_of);
        b->id = dem_realloc(b->id, c * sizeof *b->id);
        b->x = dem_realloc(b->x, c * sizeof *b->x);
        b->v = dem_realloc(b->v, c * sizeof *b->v);
        b->q = dem_realloc(b->q, c * sizeof *b->q);
        b->Lb = dem_realloc(b->Lb, c * sizeof *b->Lb);
        b->f = dem_realloc(b->f, c * sizeof *b->f);
        b->torque = dem_realloc(b->torque, c * sizeof *b->torque);
        b->R = dem_realloc(b->R, c * sizeof *b->R);
        b->w = dem_realloc(b->w, c * sizeof *b->w);
    }
    return b->n++;
}

/* omega = R (L_b / I), with the kept R */
static void update_omega(dem_bodies *b, int k)
{
    const double *inv_I = template_of(b, k)->inv_principal;
    const double wb[3] = {b->Lb[k][0] * inv_I[0], b->Lb[k][1] * inv_I[1], b->Lb[k][2] * inv_I[2]};
    for (int d = 0; d < 3; d++) b->w[k][d] = b->R[k][d][0] * wb[0] + b->R[k][d][1] * wb[1] + b->R[k][d][2] * wb[2];
}

/* R and omega after q or L_b changed */
static void update_frame(dem_bodies *b, int k)
{
    dem_quat_matrix(b->q[k], b->R[k]);
    update_omega(b, k);
}

void dem_body_omega(const dem_bodies *b, int k, double w[3])
{
    for (int d = 0; d < 3; d++) w[d] = b->w[k][d];
}

/* The spheres of every body where their body is (positions only with `positions`), moving with it. */
static void place_spheres(dem_system *s, int positions)
{
    dem_bodies *b = &s->bodies;
    dem_particles *p = &s->p;
    const double (*R)[3][3] = (const double (*)[3][3])b->R;
    const dem_vec3 *w = b->w;
    for (int i = 0; i < p->n; i++) {
        if (!p->body[i]) continue;
        const int k = dem_body_index(b, p->body[i]);
        const double *o = p->body_offset[i];
        double r[3];
        for (int d = 0; d < 3; d++) r[d] = R[k][d][0] * o[0] + R[k][d][1] * o[1] + R[k][d][2] * o[2];
        const double *wk = w[k];
        const double wxr[3] = {wk[1] * r[2] - wk[2] * r[1], wk[2] * r[0] - wk[0] * r[2], wk[0] * r[1] - wk[1] * r[0]};
        for (int d = 0; d < 3; d++) {
            if (positions) p->x[i][d] = b->x[k][d] + r[d];
            p->v[i][d] = b->v[k][d] + wxr[d];   /* seed 004 eq. 4 */
            p->omega[i][d] = wk[d];
        }
    }
}

/* A body's sphere carries the body's mass: m* of its contacts and the time-step check see the body */
static void give_body_mass(dem_particles *p, int i, double M)
{
    p->mass[i] = M;
    p->inv_mass[i] = 1.0 / M;
    p->inv_inertia[i] = 1.0 / (0.4 * M * p->radius[i] * p->radius[i]);
}

void dem_body_sphere_centres(const dem_clump_template *t, const double x[3], const double q_frame[4],
                             double (*centre)[3])
{
    double q[4];
    dem_quat_multiply(q_frame, t->q_axes, q);   /* principal -> template frame -> space */
    for (int k = 0; k < t->n; k++) {
        dem_quat_rotate(q, t->offset[k], centre[k]);
        for (int d = 0; d < 3; d++) centre[k][d] += x[d];
    }
}

int dem_bodies_add(dem_system *s, int t, const double x[3], const double q_frame[4], const double v[3],
                   const double w[3])
{
    dem_bodies *b = &s->bodies;
    if (t < 0 || t >= b->ntemplates) dem_fatal("multisphere body: no template %d", t);
    const int k = append_body(b);
    const dem_clump_template *tp = &b->templates[t];
    b->template_of[k] = t;
    if (b->next_id >= INT_MAX) dem_fatal("multisphere body: more than %d body ids", INT_MAX - 1);
    b->id[k] = b->next_id++;
    set_index(b, b->id[k], k);
    dem_quat_multiply(q_frame, tp->q_axes, b->q[k]);   /* principal -> template frame -> space */
    double wb[3];
    dem_quat_rotate_inverse(b->q[k], w, wb);
    for (int d = 0; d < 3; d++) {
        b->x[k][d] = x[d];
        b->v[k][d] = v[d];
        b->Lb[k][d] = tp->mass.principal[d] * wb[d];
        b->f[k][d] = b->torque[k][d] = 0.0;
    }
    update_frame(b, k);
    const double M = tp->mass.mass;
    for (int i = 0; i < tp->n; i++) {
        const double zero[3] = {0.0, 0.0, 0.0};
        const int j = dem_particles_add(&s->p, zero, zero, tp->radius[i], 1.0, tp->type, s->next_id++);
        s->p.body[j] = (int)b->id[k] + 1;
        for (int d = 0; d < 3; d++) s->p.body_offset[j][d] = tp->offset[i][d];
        give_body_mass(&s->p, j, M);
    }
    place_spheres(s, 1);
    return k;
}

void dem_bodies_sum_forces(dem_system *s)
{
    dem_bodies *b = &s->bodies;
    const dem_particles *p = &s->p;
    for (int k = 0; k < b->n; k++) {
        const double M = dem_body_mass(b, k);
        for (int d = 0; d < 3; d++) {
            b->f[k][d] = M * s->gravity[d];   /* gravity once, with the body's mass */
            b->torque[k][d] = 0.0;
        }
    }
    for (int i = 0; i < p->n; i++) {
        if (!p->body[i]) continue;
        const int k = dem_body_index(b, p->body[i]);
        const double *fi = p->f[i];
        const double r[3] = {p->x[i][0] - b->x[k][0], p->x[i][1] - b->x[k][1], p->x[i][2] - b->x[k][2]};
        for (int d = 0; d < 3; d++) b->f[k][d] += fi[d] - p->mass[i] * s->gravity[d];   /* its own gravity out */
        b->torque[k][0] += r[1] * fi[2] - r[2] * fi[1] + p->torque[i][0];
        b->torque[k][1] += r[2] * fi[0] - r[0] * fi[2] + p->torque[i][1];
        b->torque[k][2] += r[0] * fi[1] - r[1] * fi[0] + p->torque[i][2];
    }
}

/* V += h F / M; L_b += h R^T T (the kept R: q does not change in a kick) */
static void half_kick(dem_bodies *b, double h)
{
    for (int k = 0; k < b->n; k++) {
        const double inv_m = 1.0 / dem_body_mass(b, k);
        const double (*R)[3] = b->R[k], *T = b->torque[k];
        for (int d = 0; d < 3; d++) {
            b->v[k][d] += h * inv_m * b->f[k][d];
            b->Lb[k][d] += h * (R[0][d] * T[0] + R[1][d] * T[1] + R[2][d] * T[2]);
        }
        update_omega(b, k);
    }
}

void dem_bodies_kick_drift(dem_system *s)
{
    dem_bodies *b = &s->bodies;
    half_kick(b, 0.5 * s->dt);
    for (int k = 0; k < b->n; k++) {
        for (int d = 0; d < 3; d++) b->x[k][d] += s->dt * b->v[k][d];
        dem_rigid_free_rotation(template_of(b, k)->mass.principal, b->q[k], b->Lb[k], s->dt);
        update_frame(b, k);
    }
    place_spheres(s, 1);
}

void dem_bodies_kick(dem_system *s)
{
    half_kick(&s->bodies, 0.5 * s->dt);
    place_spheres(s, 0);
}

/* The rotational energy of body k: 1/2 sum L_b^2 / I over the principal axes (seed 004 eq. 8) */
static double rotational_energy(const dem_bodies *b, int k)
{
    const double *L = b->Lb[k], *I = template_of(b, k)->mass.principal;
    return 0.5 * (L[0] * L[0] / I[0] + L[1] * L[1] / I[1] + L[2] * L[2] / I[2]);
}

double dem_bodies_rotational_energy(const dem_system *s)
{
    double e = 0.0;
    for (int k = 0; k < s->bodies.n; k++) e += rotational_energy(&s->bodies, k);
    return e;
}

double dem_bodies_kinetic_energy(const dem_system *s)
{
    const dem_bodies *b = &s->bodies;
    double e = 0.0;
    for (int k = 0; k < b->n; k++) {
        const double *v = b->v[k];
        e += 0.5 * dem_body_mass(b, k) * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) + rotational_energy(b, k);
    }
    return e;
}

void dem_bodies_to_state(const dem_system *s, dem_body_state *st)
{
    const dem_bodies *b = &s->bodies;
    memset(st, 0, sizeof *st);
    st->count = b->n;
    const size_t n = (size_t)(b->n ? b->n : 1);
    st->id = dem_malloc(n * sizeof(int64_t));
    st->template_of = dem_malloc(n * sizeof(int64_t));
    st->x = dem_malloc(n * 3 * sizeof(double));
    st->v = dem_malloc(n * 3 * sizeof(double));
    st->q = dem_malloc(n * 4 * sizeof(double));
    st->Lb = dem_malloc(n * 3 * sizeof(double));
    st->omega = dem_malloc(n * 3 * sizeof(double));
    st->f = dem_malloc(n * 3 * sizeof(double));
    st->torque = dem_malloc(n * 3 * sizeof(double));
    st->e_rot = dem_malloc(n * sizeof(double));
    for (int k = 0; k < b->n; k++) {
        st->id[k] = b->id[k];
        st->template_of[k] = b->template_of[k];
        double w[3];
        dem_body_omega(b, k, w);
        for (int d = 0; d < 3; d++) {
            st->x[3 * k + d] = b->x[k][d];
            st->v[3 * k + d] = b->v[k][d];
            st->Lb[3 * k + d] = b->Lb[k][d];
            st->omega[3 * k + d] = w[d];
            st->f[3 * k + d] = b->f[k][d];
            st->torque[3 * k + d] = b->torque[k][d];
        }
        for (int d = 0; d < 4; d++) st->q[4 * k + d] = b->q[k][d];
        st->e_rot[k] = rotational_energy(b, k);
    }
}

void dem_bodies_from_state(dem_system *s, const dem_body_state *st, const char *where)
{
    dem_bodies *b = &s->bodies;
    for (int k = 0; k < b->n; k++) set_index(b, b->id[k], -1);
    b->n = 0;
    for (long k = 0; k < st->count; k++) {
        const int64_t t = st->template_of[k];
        if (t < 0 || t >= b->ntemplates)
            dem_fatal("%s: body %ld has template %lld, but the case defines %d multisphere templates", where, k,
                      (long long)t, b->ntemplates);
        const int j = append_body(b);   /* no spheres added: they are in the snapshot */
        b->template_of[j] = (int)t;
        b->id[j] = st->id[k];
        if (b->id[j] < 0 || b->id[j] >= INT_MAX || dem_body_lookup(b, (int)b->id[j] + 1) >= 0)
            dem_fatal("%s: body %ld has the id %lld, negative, too large or another body's", where, k,
                      (long long)b->id[j]);
        set_index(b, b->id[j], j);
        if (b->id[j] >= b->next_id) b->next_id = b->id[j] + 1;
        for (int d = 0; d < 3; d++) {
            b->x[j][d] = st->x[3 * k + d];
            b->v[j][d] = st->v[3 * k + d];
            b->Lb[j][d] = st->Lb[3 * k + d];
            b->f[j][d] = st->f[3 * k + d];
            b->torque[j][d] = st->torque[3 * k + d];
        }
        for (int d = 0; d < 4; d++) b->q[j][d] = st->q[4 * k + d];
        update_frame(b, j);
    }
    dem_particles *p = &s->p;
    for (int i = 0; i < p->n; i++) {
        if (!p->body[i]) continue;
        const int k = p->body[i] > 0 ? dem_body_lookup(b, p->body[i]) : -1;
        if (k < 0)
            dem_fatal("%s: particle id %lld belongs to body id %d, which the snapshot's %d bodies do not have", where,
                      (long long)p->id[i], p->body[i] - 1, b->n);
        give_body_mass(p, i, dem_body_mass(b, k));
    }
}

void dem_bodies_remove(dem_system *s, const unsigned char *gone)
{
    dem_bodies *b = &s->bodies;
    for (int k = b->n - 1; k >= 0; k--) {   /* from the top: the last body, moved in, is one that stays */
        if (!gone[k]) continue;
        set_index(b, b->id[k], -1);
        const int last = b->n - 1;
        if (k != last) {
            b->template_of[k] = b->template_of[last];
            b->id[k] = b->id[last];
            memcpy(b->x[k], b->x[last], sizeof b->x[k]);
            memcpy(b->v[k], b->v[last], sizeof b->v[k]);
            memcpy(b->q[k], b->q[last], sizeof b->q[k]);
            memcpy(b->Lb[k], b->Lb[last], sizeof b->Lb[k]);
            memcpy(b->f[k], b->f[last], sizeof b->f[k]);
            memcpy(b->torque[k], b->torque[last], sizeof b->torque[k]);
            memcpy(b->R[k], b->R[last], sizeof b->R[k]);
            memcpy(b->w[k], b->w[last], sizeof b->w[k]);
            set_index(b, b->id[k], k);
        }
        b->n--;
    }
    const dem_particles *p = &s->p;
    for (int i = 0; i < p->n; i++)
        if (p->body[i] && dem_body_lookup(b, p->body[i]) < 0)
            dem_fatal("dem_bodies_remove: particle id %lld of a removed body is still there", (long long)p->id[i]);
}

enum { PACK_INTS = 2, PACK_DOUBLES = 19 };   /* id, template; x v (6) q (4) L_b f torque (9) */

size_t dem_bodies_pack_size(void) { return PACK_INTS * sizeof(int64_t) + PACK_DOUBLES * sizeof(double); }

size_t dem_bodies_pack(const dem_bodies *b, int k, void *buf)
{
    const int64_t ints[PACK_INTS] = {b->id[k], b->template_of[k]};
    double reals[PACK_DOUBLES], *r = reals;
    for (int d = 0; d < 3; d++) *r++ = b->x[k][d];
    for (int d = 0; d < 3; d++) *r++ = b->v[k][d];
    for (int d = 0; d < 4; d++) *r++ = b->q[k][d];
    for (int d = 0; d < 3; d++) *r++ = b->Lb[k][d];
    for (int d = 0; d < 3; d++) *r++ = b->f[k][d];
    for (int d = 0; d < 3; d++) *r++ = b->torque[k][d];
    memcpy(buf, ints, sizeof ints);
    memcpy((unsigned char *)buf + sizeof ints, reals, sizeof reals);
    return dem_bodies_pack_size();
}

void dem_bodies_unpack(dem_bodies *b, const void *buf)
{
    int64_t ints[PACK_INTS];
    double reals[PACK_DOUBLES];
    memcpy(ints, buf, sizeof ints);
    memcpy(reals, (const unsigned char *)buf + sizeof ints, sizeof reals);
    if (ints[1] < 0 || ints[1] >= b->ntemplates || ints[0] < 0 || ints[0] >= INT_MAX)
        dem_fatal("a body arrived from another rank with id %lld and template %lld (%d templates here)",
                  (long long)ints[0], (long long)ints[1], b->ntemplates);
    if (ints[0] < b->index_capacity && b->index_of[ints[0]] >= 0)
        dem_fatal("body id %lld arrived from another rank, but this rank holds it already", (long long)ints[0]);
    const int k = append_body(b);
    b->id[k] = ints[0];
    b->template_of[k] = (int)ints[1];
    set_index(b, b->id[k], k);
    if (b->id[k] >= b->next_id) b->next_id = b->id[k] + 1;
    const double *r = reals;
    for (int d = 0; d < 3; d++) b->x[k][d] = *r++;
    for (int d = 0; d < 3; d++) b->v[k][d] = *r++;
    for (int d = 0; d < 4; d++) b->q[k][d] = *r++;
    for (int d = 0; d < 3; d++) b->Lb[k][d] = *r++;
    for (int d = 0; d < 3; d++) b->f[k][d] = *r++;
    for (int d = 0; d < 3; d++) b->torque[k][d] = *r++;
    update_frame(b, k);
}

double dem_particle_volume(const dem_system *s, int i)
{
    const double r = s->p.radius[i], v = 4.0 / 3.0 * M_PI * r * r * r;
    return s->p.body[i] ? v * template_of(&s->bodies, dem_body_index(&s->bodies, s->p.body[i]))->volume_scale : v;
}
