#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "case.h"
#include "dict.h"
#include "error.h"
#include "reduce.h"
#include "insert.h"
#include "memory_budget.h"

static const char *const axis_names[] = {"x", "y", "z", 0};

/* gravity [m/s^2], (0 0 0) by default; up to 1e5 g: beyond, free-fall speeds and forces overflow */
static void read_gravity(const dem_dict *root, double g[3])
{
    const double zero[3] = {0, 0, 0};
    dem_dict_vector_opt(root, "gravity", g, zero);
    for (int k = 0; k < 3; k++)
        if (!(fabs(g[k]) <= 1e6))
            dem_dict_fatal(root, "gravity", "component %c = %g m/s^2 is out of range: allowed [-1e6, 1e6]", "xyz"[k], g[k]);
}

int dem_case_gravity(const char *case_dir, double g[3])
{
    char path[4096];
    snprintf(path, sizeof path, "%s/constant/demProperties", case_dir);
    dem_dict *root = dem_dict_read(path);
    const int found = dem_dict_has(root, "gravity");
    read_gravity(root, g);
    dem_dict_free(root);
    return found;
}

static void read_domain(const dem_dict *root, dem_system *s)
{
    const dem_dict *d = dem_dict_sub(root, "domain");
    dem_dict_vector(d, "min", s->domain_min);
    dem_dict_vector(d, "max", s->domain_max);
    dem_dict_bools3_opt(d, "periodic", s->periodic, 0);
    for (int k = 0; k < 3; k++) {
        if (!(s->domain_max[k] > s->domain_min[k]))
            dem_dict_fatal(d, "max", "max must exceed min in every direction (%c: min %g, max %g)",
                       "xyz"[k], s->domain_min[k], s->domain_max[k]);
        /* coordinates within 1000 km: beyond, free-fall speeds, cell counts and squared distances
         * overflow (a signal under OpenFOAM's floating-point traps) */
        if (!(fabs(s->domain_min[k]) <= 1e6))
            dem_dict_fatal(d, "min", "%c = %g m is out of range: domain coordinates lie within [-1e6, 1e6] m", "xyz"[k], s->domain_min[k]);
        if (!(fabs(s->domain_max[k]) <= 1e6))
            dem_dict_fatal(d, "max", "%c = %g m is out of range: domain coordinates lie within [-1e6, 1e6] m", "xyz"[k], s->domain_max[k]);
    }
    for (int k = 0; k < 3; k++) {   /* as system_setup_begin: the insertions' overlap checks need it */
        s->period[k] = s->periodic[k] ? s->domain_max[k] - s->domain_min[k] : 0.0;
        s->inv_period[k] = s->periodic[k] ? 1.0 / s->period[k] : 0.0;
    }
}

static void read_materials(const dem_dict *root, dem_system *s)
{
    const dem_dict *d = dem_dict_sub(root, "materials");
    dem_material_table *t = &s->materials;
    for (int i = 0; i < dem_dict_size(d); i++) {
        if (!dem_dict_is_dict_at(d, i)) dem_dict_fatal(d, dem_dict_key_at(d, i), "a material is a sub-dictionary { youngsModulus; poissonsRatio; density; }");
        if (t->ntypes == DEM_MAX_TYPES) dem_dict_fatal(d, dem_dict_key_at(d, i), "at most %d materials", DEM_MAX_TYPES);
        const dem_dict *m = dem_dict_dict_at(d, i);
        dem_material *mat = &t->mat[t->ntypes++];
        snprintf(mat->name, sizeof mat->name, "%s", dem_dict_key_at(d, i));
        mat->rigid = dem_dict_bool_opt(m, "rigid", 0);
        if (mat->rigid) {   /* Y* and G* of a contact with it are the particle's alone */
            static const char *const unused[] = {"youngsModulus", "poissonsRatio", "density"};
            for (int k = 0; k < 3; k++)
                if (dem_dict_has(m, unused[k]))
                    dem_dict_fatal(m, unused[k], "a rigid material adds no compliance and has no mass: remove '%s' "
                                   "(or drop 'rigid true' for an elastic wall)", unused[k]);
            mat->youngs_modulus = INFINITY;
            mat->poisson_ratio = 0.0;
            mat->density = 0.0;
            continue;
        }
        mat->youngs_modulus = dem_dict_scalar(m, "youngsModulus", 1e3, 1e13);
        mat->poisson_ratio = dem_dict_scalar(m, "poissonsRatio", 0.0, 0.4999);
        mat->density = dem_dict_scalar(m, "density", 1.0, 1e5);
    }
    if (t->ntypes == 0) dem_dict_fatal_here(d, "define at least one material");
}

/* "a-b" -> two material indices (names may themselves contain '-'). */
static int split_pair(const dem_material_table *t, const char *key, int *a, int *b)
{
    char buf[2 * DEM_NAME_LEN + 2];
    for (const char *dash = strchr(key, '-'); dash; dash = strchr(dash + 1, '-')) {
        const size_t len = (size_t)(dash - key);
        if (len >= sizeof buf) break;
        memcpy(buf, key, len);
        buf[len] = 0;
        *a = dem_materials_find(t, buf);
        *b = dem_materials_find(t, dash + 1);
        if (*a >= 0 && *b >= 0) return 1;
    }
    return 0;
}

/* The chosen models' parameters of one interaction, per slot, from the entry e, else from the
 * 'default' entry def, else the model's fallback (NAN: required); then each model's check. */
static void read_model_values(const dem_dict *e, const dem_dict *def, const dem_contact_models *m,
                              double values[SLOT_COUNT][MODEL_VALUES])
{
    for (int slot = 0; slot < SLOT_COUNT; slot++) {
        const dem_contact_model *md = dem_contact_model_get(slot, contact_model_id(m, slot));
        for (int k = 0; k < MODEL_VALUES; k++) values[slot][k] = 0.0;
        for (int k = 0; k < md->nparams; k++) {
            const dem_model_param *mp = &md->params[k];
            const dem_dict *src = dem_dict_has(e, mp->key) ? e : def && dem_dict_has(def, mp->key) ? def : NULL;
            if (!src && isnan(mp->fallback))
                dem_dict_fatal_here(e, "the %s %s model needs '%s' [%s] in this interaction (or in 'default')",
                                md->name, dem_contact_slot_names[slot], mp->key, mp->unit);
            values[slot][mp->offset / sizeof(double)] = src ? dem_dict_scalar(src, mp->key, mp->lo, mp->hi) : mp->fallback;
        }
        const char *key, *message = md->check ? md->check(values[slot], &key) : NULL;
        if (message) {
            double got = NAN;
            for (int k = 0; k < md->nparams; k++)
                if (strcmp(md->params[k].key, key) == 0) got = values[slot][md->params[k].offset / sizeof(double)];
            dem_dict_fatal(dem_dict_has(e, key) || !def ? e : def, key, "%s (got %g)", message, got);
        }
    }
}

static void read_interactions(const dem_dict *root, dem_system *s)
{
    const dem_dict *d = dem_dict_sub(root, "interactions");
    dem_material_table *t = &s->materials;
    int set[DEM_MAX_TYPES][DEM_MAX_TYPES] = {{0}};
    const dem_dict *def = dem_dict_sub_opt(d, "default");
    for (int pass = 0; pass < 2; pass++) {       /* default first, then the named pairs */
        for (int i = 0; i < dem_dict_size(d); i++) {
            const char *key = dem_dict_key_at(d, i);
            const int is_default = strcmp(key, "default") == 0;
            if (is_default != (pass == 0)) continue;
            const dem_dict *e = is_default ? def : dem_dict_dict_at(d, i);
            if (!e) dem_dict_fatal(d, key, "an interaction is a sub-dictionary { restitution; friction; }");
            const double rest = dem_dict_scalar(e, "restitution", 1e-6, 1.0);
            const double mu = dem_dict_scalar(e, "friction", 0.0, 10.0);
            double mv[SLOT_COUNT][MODEL_VALUES];
            read_model_values(e, is_default ? NULL : def, &s->models, mv);
            if (is_default) {
                for (int a = 0; a < t->ntypes; a++)
                    for (int b = 0; b < t->ntypes; b++) {
                        dem_materials_set_pair(t, a, b, rest, mu);
                        for (int slot = 0; slot < SLOT_COUNT; slot++)
                            dem_materials_set_model_values(t, a, b, slot, mv[slot], sizeof mv[slot]);
                        set[a][b] = 1;
                    }
            } else {
                int a, b;
                if (!split_pair(t, key, &a, &b))
                    dem_dict_fatal(d, key, "expected '<material>-<material>' with two defined materials, or 'default'");
                dem_materials_set_pair(t, a, b, rest, mu);
                for (int slot = 0; slot < SLOT_COUNT; slot++)
                    dem_materials_set_model_values(t, a, b, slot, mv[slot], sizeof mv[slot]);
                set[a][b] = set[b][a] = 1;
            }
        }
    }
    for (int a = 0; a < t->ntypes; a++)
        for (int b = 0; b < t->ntypes; b++)
            if (!set[a][b])
                dem_dict_fatal_here(d, "no entry for the pair %s-%s (add it, or a 'default' entry)",
                                t->mat[a].name, t->mat[b].name);
}

/* contactModels: one model per slot (normal and tangential required, the others default to
 * their slot's first model), limitForce, and each chosen model's case-wide settings. */
static void read_models(const dem_dict *root, dem_system *s)
{
    const dem_dict *d = dem_dict_sub(root, "contactModels");
    dem_contact_models *m = &s->models;
    for (int slot = 0; slot < SLOT_COUNT; slot++)
        *contact_model_id_ref(m, slot) = slot == SLOT_NORMAL || slot == SLOT_TANGENTIAL
            ? dem_dict_choice(d, dem_contact_slot_names[slot], dem_contact_model_names(slot))
            : dem_dict_choice_opt(d, dem_contact_slot_names[slot], dem_contact_model_names(slot), 0);
    const int limit_default = dem_contact_model_get(SLOT_NORMAL, m->normal)->limit_force_default;
    m->fn_floor = dem_dict_bool_opt(d, "limitForce", limit_default) ? 0.0 : -INFINITY;
    for (int slot = 0; slot < SLOT_COUNT; slot++) {
        const dem_contact_model *md = dem_contact_model_get(slot, contact_model_id(m, slot));
        if (md->read_case) md->read_case(d, m->values[slot]);
    }
}

/* coarseGraining cg [-]: each particle is a parcel of cg^3 primary particles (1: none, the
 * default). The case's diameters stay the primary particles'; docs/models/coarse_graining.md. */
static void read_coarse_graining(const dem_dict *root, dem_system *s)
{
    s->coarse_graining = dem_dict_scalar_opt(root, "coarseGraining", 1.0, 1.0, 100.0);
}

/* What does not hold for parcels is refused: a model that says so in its descriptor, and
 * multisphere bodies (a parcel of clumps has no published scaling here). */
static void check_coarse_graining(const dem_dict *root, const dem_system *s)
{
    const double cg = s->coarse_graining;
    if (cg == 1.0) return;
    for (int slot = 0; slot < SLOT_COUNT; slot++) {
        const dem_contact_model *md = dem_contact_model_get(slot, contact_model_id(&s->models, slot));
        if (md->coarse_graining_refused)
            dem_dict_fatal(root, "coarseGraining", "%g: the %s model '%s' does not hold for coarse-grained parcels: %s. "
                           "Use coarseGraining 1, or a model that holds (docs/models/coarse_graining.md)",
                           cg, dem_contact_slot_names[slot], md->name, md->coarse_graining_refused);
    }
    if (s->bodies.ntemplates > 0)
        dem_dict_fatal(root, "coarseGraining", "%g: multisphere templates are not coarse-grained here (their spheres "
                       "and inertia have no parcel rule); use coarseGraining 1", cg);
    dem_info("coarse graining: every particle is a parcel of cg^3 = %g primary particles (cg = %g); the diameters "
             "given are the primary particles', the DEM's are %g times larger", cg * cg * cg, cg, cg);
}

static int material_of(const dem_dict *d, const dem_material_table *t)
{
    const char *name = dem_dict_word(d, "material");
    const int k = dem_materials_find(t, name);
    if (k < 0) dem_dict_fatal(d, "material", "'%s' is not among the materials", name);
    return k;
}

/* a particles' material: not a rigid one */
static int particle_material_of(const dem_dict *d, const dem_material_table *t)
{
    const int k = material_of(d, t);
    if (t->mat[k].rigid)
        dem_dict_fatal(d, "material", "'%s' is rigid: only walls may use it (particles need youngsModulus, "
                       "poissonsRatio and density)", t->mat[k].name);
    return k;
}

/* axis, centre (the two coordinates across the axis) and radius of a cylinder wall or region */
static void read_cylinder(const dem_dict *d, int *axis, double centre[2], double *radius)
{
    *axis = dem_dict_choice(d, "axis", axis_names);
    double *c;
    if (dem_dict_scalar_list(d, "centre", &c) != 2)
        dem_dict_fatal(d, "centre", "give the two coordinates across the axis, e.g. (0 0)");
    centre[0] = c[0];
    centre[1] = c[1];
    free(c);
    for (int k = 0; k < 2; k++)   /* as the domain's coordinates: squared distances must not overflow */
        if (!(fabs(centre[k]) <= 1e6))
            dem_dict_fatal(d, "centre", "%g m is out of range: coordinates lie within [-1e6, 1e6] m", centre[k]);
    *radius = dem_dict_scalar(d, "radius", 1e-9, 1e6);
}

/* a point [m] within the coordinates' range (squared distances must not overflow) */
static void read_point(const dem_dict *e, const char *key, double x[3])
{
    dem_dict_vector(e, key, x);
    for (int k = 0; k < 3; k++)
        if (!(fabs(x[k]) <= 1e6))
            dem_dict_fatal(e, key, "%c = %g m is out of range: coordinates lie within [-1e6, 1e6] m", "xyz"[k], x[k]);
}

static dem_wall *new_wall(dem_system *s, const dem_dict *d, const char *name)
{
    dem_wall *w = dem_walls_add(s);
    snprintf(w->name, sizeof w->name, "%s", name);
    return w;
}

/* A direction, any length: scaled by its largest component first, so that neither 1e200 nor
 * 1e-200 overflows or underflows on the way to a unit vector. n: read by the caller. */
static void read_unit_normal(const dem_dict *e, double n[3])
{
    const double big = fmax(fabs(n[0]), fmax(fabs(n[1]), fabs(n[2])));
    if (!(big > 0.0)) dem_dict_fatal(e, "normal", "the normal must not be zero");
    for (int k = 0; k < 3; k++) n[k] /= big;
    const double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int k = 0; k < 3; k++) n[k] /= len;
}

/* A symmetry plane (symmetry.h): no material and no force, so not a wall. It must lie within
 * the domain (its point inside the domain box) and may not cut a periodic direction. */
static void read_symmetry_plane(const dem_dict *e, const char *name, dem_system *s)
{
    if (dem_dict_has(e, "material"))
        dem_dict_fatal(e, "material", "a symmetryPlane exerts no force and takes no material");
    if (s->nsymmetry == DEM_MAX_SYMMETRY_PLANES) dem_dict_fatal_here(e, "at most %d symmetry planes", DEM_MAX_SYMMETRY_PLANES);
    dem_symmetry_plane *sp = &s->symmetry_planes[s->nsymmetry++];
    memset(sp, 0, sizeof *sp);
    snprintf(sp->name, sizeof sp->name, "%s", name);
    dem_dict_vector(e, "point", sp->point);
    dem_dict_vector(e, "normal", sp->normal);
    read_unit_normal(e, sp->normal);
    for (int k = 0; k < 3; k++) {
        const double slack = 1e-9 * (s->domain_max[k] - s->domain_min[k]);
        if (!(sp->point[k] >= s->domain_min[k] - slack && sp->point[k] <= s->domain_max[k] + slack))
            dem_dict_fatal(e, "point", "a symmetryPlane must lie within the domain: point (%g %g %g) is outside "
                       "min (%g %g %g) max (%g %g %g)", sp->point[0], sp->point[1], sp->point[2],
                       s->domain_min[0], s->domain_min[1], s->domain_min[2],
                       s->domain_max[0], s->domain_max[1], s->domain_max[2]);
        if (s->periodic[k] && fabs(sp->normal[k]) > 1e-12)
            dem_dict_fatal(e, "normal", "a symmetryPlane cannot cut the periodic direction %c (its normal must be "
                       "perpendicular to it)", "xyz"[k]);
    }
    sp->offset = sp->point[0] * sp->normal[0] + sp->point[1] * sp->normal[1] + sp->point[2] * sp->normal[2];
}

/* a plane's translation, `velocity (vx vy vz)` [m/s], 0 by default */
static void read_wall_velocity(const dem_dict *e, dem_wall *w)
{
    static const double zero[3] = {0.0, 0.0, 0.0};
    double u[3];
    dem_dict_vector_opt(e, "velocity", u, zero);
    for (int d = 0; d < 3; d++)
        if (!(fabs(u[d]) <= 1e6)) dem_dict_fatal(e, "velocity", "a wall velocity of %g m/s is out of range", u[d]);
    dem_wall_set_velocity(w, u);
}

static void read_walls(const dem_dict *root, dem_system *s)
{
    const dem_dict *d = dem_dict_sub_opt(root, "walls");
    if (!d) return;
    static const char *const kinds[] = {"plane", "box", "cylinder", "symmetryPlane", 0};
    for (int i = 0; i < dem_dict_size(d); i++) {
        const char *name = dem_dict_key_at(d, i);
        if (!dem_dict_is_dict_at(d, i)) dem_dict_fatal(d, name, "a wall is a sub-dictionary { type ...; }");
        const dem_dict *e = dem_dict_dict_at(d, i);
        const int kind = dem_dict_choice(e, "type", kinds);
        if (kind == 3) {
            read_symmetry_plane(e, name, s);
            continue;
        }
        const int mat = material_of(e, &s->materials);
        if (kind == 0) {
            dem_wall *w = new_wall(s, e, name);
            w->kind = WALL_PLANE;
            w->material = mat;
            dem_dict_vector(e, "point", w->point);
            for (int k = 0; k < 3; k++)
                if (!(fabs(w->point[k]) <= 1e6))
                    dem_dict_fatal(e, "point", "%c = %g m is out of range: coordinates lie within [-1e6, 1e6] m", "xyz"[k], w->point[k]);
            dem_dict_vector(e, "normal", w->normal);
            read_unit_normal(e, w->normal);
            if (dem_dict_has(e, "boundsMin") || dem_dict_has(e, "boundsMax")) {
                w->bounded = 1;
                dem_dict_vector(e, "boundsMin", w->bounds_min);
                dem_dict_vector(e, "boundsMax", w->bounds_max);
            }
            read_wall_velocity(e, w);
        } else if (kind == 1) {
            double lo[3], hi[3];
            dem_dict_vector(e, "min", lo);
            dem_dict_vector(e, "max", hi);
            for (int k = 0; k < 3; k++)
                if (!(hi[k] > lo[k])) dem_dict_fatal(e, "max", "max must exceed min in every direction");
            for (int k = 0; k < 6; k++) {   /* six bounded faces, normals pointing inwards */
                char face[80];
                snprintf(face, sizeof face, "%s.%s%s", name, axis_names[k / 2], k % 2 ? "Max" : "Min");
                dem_wall *w = new_wall(s, e, face);
                w->kind = WALL_PLANE;
                w->material = mat;
                w->bounded = 1;
                const int a = k / 2;
                for (int q = 0; q < 3; q++) { w->bounds_min[q] = lo[q]; w->bounds_max[q] = hi[q]; }
                w->point[0] = lo[0]; w->point[1] = lo[1]; w->point[2] = lo[2];
                w->point[a] = k % 2 ? hi[a] : lo[a];
                w->normal[a] = k % 2 ? -1.0 : 1.0;
                read_wall_velocity(e, w);
            }
        } else {
            dem_wall *w = new_wall(s, e, name);
            w->kind = WALL_CYLINDER;
            w->material = mat;
            read_cylinder(e, &w->axis, w->centre, &w->radius);
            static const char *const sides[] = {"inside", "outside", 0};
            w->inside = dem_dict_choice_opt(e, "side", sides, 0) == 0;
            w->axial_min = dem_dict_scalar_opt(e, "axialMin", -INFINITY, -INFINITY, INFINITY);
            w->axial_max = dem_dict_scalar_opt(e, "axialMax", INFINITY, -INFINITY, INFINITY);
            w->angular_velocity = dem_dict_scalar_opt(e, "angularVelocity", 0.0, -1e6, 1e6);   /* rad/s */
            if (dem_dict_has(e, "velocity"))
                dem_dict_fatal(e, "velocity", "a cylinder wall turns about its axis ('angularVelocity' [rad/s]); "
                               "it does not translate");
        }
    }
}

/* outlets { <name> { type plane; point (x y z); normal (nx ny nz); } <name> { type box; min; max; } }:
 * a plane removes the centres beyond it (the normal points out of the domain), a box those inside;
 * optional `interval` [s]: it acts only in the steps that are multiples of interval / timeStep. */
static void read_outlets(const dem_dict *root, dem_system *s)
{
    const dem_dict *d = dem_dict_sub_opt(root, "outlets");
    if (!d) return;
    static const char *const kinds[] = {"plane", "box", 0};
    for (int i = 0; i < dem_dict_size(d); i++) {
        const char *name = dem_dict_key_at(d, i);
        if (!dem_dict_is_dict_at(d, i)) dem_dict_fatal(d, name, "an outlet is a sub-dictionary { type plane|box; ... }");
        const dem_dict *e = dem_dict_dict_at(d, i);
        if (strlen(name) >= sizeof s->outlets[0].name || strchr(name, ' '))
            dem_dict_fatal(d, name, "an outlet's name has at most %zu characters and no spaces", sizeof s->outlets[0].name - 1);
        dem_outlet *o = dem_outlets_add(s, name);
        o->kind = dem_dict_choice(e, "type", kinds) == 0 ? OUTLET_PLANE : OUTLET_BOX;
        if (o->kind == OUTLET_PLANE) {
            read_point(e, "point", o->point);
            dem_dict_vector(e, "normal", o->normal);
            read_unit_normal(e, o->normal);
        } else {
            read_point(e, "min", o->min);
            read_point(e, "max", o->max);
            for (int k = 0; k < 3; k++)
                if (!(o->max[k] > o->min[k])) dem_dict_fatal(e, "max", "max must exceed min in every direction");
        }
        const double interval = dem_dict_scalar_opt(e, "interval", s->dt, s->dt, 1e9);
        const double steps = fmin(floor(interval / s->dt + 0.5), 1e15);   /* as the streams' counts */
        o->every = steps < 1.0 ? 1 : (long)steps;
    }
}

/* The diameters of an entry are the primary particles'; the DEM's particles are parcels cg times
 * as large (coarseGraining), so the sizes are scaled here, once, after their range checks. */
static void scale_diameters(dem_insertion *ins, double cg)
{
    ins->d_value *= cg; ins->d_min *= cg; ins->d_max *= cg; ins->d_mean *= cg; ins->d_std *= cg;
    for (int k = 0; k < ins->ndiscrete; k++) ins->d_values[k] *= cg;
}

static void read_diameter(const dem_dict *e, dem_insertion *ins, double cg)
{
    const dem_dict *d = dem_dict_sub(e, "diameter");
    static const char *const dists[] = {"constant", "uniform", "normal", "discrete", 0};
    ins->dist = dem_dict_choice(d, "distribution", dists);
    switch (ins->dist) {
    case SIZE_CONSTANT: ins->d_value = dem_dict_scalar(d, "value", 1e-9, 10.0); break;
    case SIZE_UNIFORM:
    case SIZE_NORMAL:
        if (ins->dist == SIZE_NORMAL) {
            ins->d_mean = dem_dict_scalar(d, "mean", 1e-9, 10.0);
            ins->d_std = dem_dict_scalar(d, "stdDev", 0.0, 10.0);
        }
        ins->d_min = dem_dict_scalar(d, "min", 1e-9, 10.0);
        ins->d_max = dem_dict_scalar(d, "max", ins->d_min, 10.0);
        if (ins->dist == SIZE_NORMAL && (ins->d_mean < ins->d_min || ins->d_mean > ins->d_max))
            dem_dict_fatal(d, "mean", "the mean %g m must lie within [min, max] = [%g, %g] m", ins->d_mean, ins->d_min, ins->d_max);
        break;
    case SIZE_DISCRETE: {
        ins->ndiscrete = dem_dict_scalar_list(d, "values", &ins->d_values);
        const int nw = dem_dict_scalar_list(d, "weights", &ins->d_weights);
        if (ins->ndiscrete == 0) dem_dict_fatal(d, "values", "give at least one diameter");
        if (nw != ins->ndiscrete) dem_dict_fatal(d, "weights", "%d weights for %d values", nw, ins->ndiscrete);
        for (int k = 0; k < nw; k++) {
            if (!(ins->d_values[k] > 0.0)) dem_dict_fatal(d, "values", "diameters must be positive (got %g)", ins->d_values[k]);
            if (!(ins->d_weights[k] >= 0.0)) dem_dict_fatal(d, "weights", "weights must not be negative (got %g)", ins->d_weights[k]);
        }
        break;
    }
    }
    scale_diameters(ins, cg);
}

/* The particles a random insertion implies, against what the memory holds (memory_budget.h), at
 * its key: number (x the body's spheres), or solidFraction of the region in particles of the
 * largest diameter (or bodies of their template's volume): the fewest it can mean. */
static void check_random_count(const dem_dict *e, const dem_system *s, const dem_insertion *ins)
{
    const dem_clump_template *t = ins->body ? &s->bodies.templates[ins->body - 1] : NULL;
    char what[128];
    if (t) snprintf(what, sizeof what, "spheres (bodies of %d spheres '%s')", t->n, t->name);
    else snprintf(what, sizeof what, "particles");
    const double spheres = t ? t->n : 1.0;
    if (ins->number > 0) {
        dem_check_affordable(e, "number", (double)ins->number, (double)ins->number * spheres, 1.0, what);
    } else {
        const double d = dem_insertion_max_diameter(ins);
        const double unit = t ? t->mass.volume : M_PI / 6.0 * d * d * d;
        dem_check_affordable(e, "solidFraction", ins->solid_fraction,
                             ins->solid_fraction * dem_insertion_region_volume(ins) / unit * spheres, 1.0, what);
    }
}

/* A body insertion's start rotation (issue 26): `orientation` random (the default: each body its
 * own, uniformly), a unit quaternion (w x y z) (normalised; the template's frame to space), or
 * { axis (x y z); angle a; } (a in degrees about the axis); `angularVelocity` (x y z) [rad/s] in
 * space, 0 by default. A file may give each body its own (insert_file.c). */
static void read_body_rotation(const dem_dict *e, dem_insertion *ins)
{
    if (dem_dict_is_dict(e, "orientation")) {
        const dem_dict *aa = dem_dict_sub(e, "orientation");
        double axis[3];
        dem_dict_vector(aa, "axis", axis);
        const double deg = dem_dict_scalar(aa, "angle", -360.0, 360.0), len = sqrt(axis[0] * axis[0] +
                           axis[1] * axis[1] + axis[2] * axis[2]);
        if (!(len > 0.0)) dem_dict_fatal(aa, "axis", "the axis has no direction");
        const double h = 0.5 * deg * M_PI / 180.0;
        ins->orientation[0] = cos(h);
        for (int k = 0; k < 3; k++) ins->orientation[k + 1] = sin(h) * axis[k] / len;
        ins->orientation_given = 1;
    } else if (dem_dict_has(e, "orientation") && !dem_dict_is_word(e, "orientation")) {
        double *q;
        const int n = dem_dict_scalar_list(e, "orientation", &q);
        const double len = n == 4 ? sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]) : 0.0;
        if (n != 4 || !(len > 0.0) || !isfinite(len)) {
            free(q);
            dem_dict_fatal(e, "orientation", "give 'random', a quaternion (w x y z) of non-zero length, or "
                           "{ axis (x y z); angle a; } with a in degrees");
        }
        for (int k = 0; k < 4; k++) ins->orientation[k] = q[k] / len;
        free(q);
        ins->orientation_given = 1;
    } else if (dem_dict_has(e, "orientation")) {
        static const char *const words[] = {"random", 0};
        dem_dict_choice(e, "orientation", words);
    }
    const double zero[3] = {0.0, 0.0, 0.0};
    dem_dict_vector_opt(e, "angularVelocity", ins->angular_velocity, zero);
    for (int k = 0; k < 3; k++)
        if (!(fabs(ins->angular_velocity[k]) <= 1e6))
            dem_dict_fatal(e, "angularVelocity", "%g rad/s is out of range: allowed [-1e6, 1e6]",
                           ins->angular_velocity[k]);
}

static void read_region(const dem_dict *e, dem_insertion *ins)
{
    const dem_dict *r = dem_dict_sub(e, "region");
    static const char *const kinds[] = {"box", "cylinder", 0};
    ins->region = dem_dict_choice(r, "type", kinds);
    if (ins->region == REGION_BOX) {
        dem_dict_vector(r, "min", ins->min);
        dem_dict_vector(r, "max", ins->max);
        for (int k = 0; k < 3; k++)
            if (!(ins->max[k] > ins->min[k])) dem_dict_fatal(r, "max", "max must exceed min in every direction");
    } else {
        read_cylinder(r, &ins->axis, ins->centre, &ins->radius);
        ins->min[ins->axis] = dem_dict_scalar(r, "axialMin", -1e6, 1e6);
        ins->max[ins->axis] = dem_dict_scalar(r, "axialMax", ins->min[ins->axis], 1e6);
    }
}

/* The lattice spacing: one number (cubic) or (dx dy dz); at least the largest diameter. */
static void read_spacing(const dem_dict *e, dem_insertion *ins)
{
    dem_dict_scalar_or_vector(e, "spacing", 1e-9, 1e3, ins->spacing);
    const double dmax = dem_insertion_max_diameter(ins);
    const double smin = fmin(fmin(ins->spacing[0], ins->spacing[1]), ins->spacing[2]);
    if (smin < dmax)
        dem_dict_fatal(e, "spacing", "insertion '%s': the spacing %g m is smaller than the largest diameter %g m%s: "
                   "neighbouring lattice particles would overlap", ins->name, smin, dmax,
                   ins->dist == SIZE_CONSTANT ? "" : " (the distribution's largest)");
}

/* An insertion's region lies inside the domain (a cylinder: its axial range and its box across
 * the axis). */
static void check_region_inside(const dem_dict *e, const dem_system *s, const dem_insertion *ins)
{
    const dem_dict *r = dem_dict_sub(e, "region");
    if (ins->region == REGION_BOX) {
        for (int k = 0; k < 3; k++)
            if (ins->min[k] < s->domain_min[k] || ins->max[k] > s->domain_max[k])
                dem_dict_fatal(r, "min", "the region must lie inside the domain");
        return;
    }
    const int a = ins->axis, b = (a + 1) % 3, c = (a + 2) % 3;
    double lo[3], hi[3];
    lo[a] = ins->min[a]; lo[b] = ins->centre[0] - ins->radius; lo[c] = ins->centre[1] - ins->radius;
    hi[a] = ins->max[a]; hi[b] = ins->centre[0] + ins->radius; hi[c] = ins->centre[1] + ins->radius;
    for (int k = 0; k < 3; k++)
        if (lo[k] < s->domain_min[k] || hi[k] > s->domain_max[k])
            dem_dict_fatal(r, k == a ? (lo[k] < s->domain_min[k] ? "axialMin" : "axialMax") : "radius",
                           "the cylinder must lie inside the domain: in %c it spans [%g, %g] m, the domain "
                           "[%g, %g] m", "xyz"[k], lo[k], hi[k], s->domain_min[k], s->domain_max[k]);
}

/* multisphere { <name> { material m; centres ((x y z) ...); radii (r ...); massModel union; } ... }:
 * the templates of multisphere bodies, their spheres in the template's own frame [m]. */
static void read_multisphere(const dem_dict *root, dem_system *s)
{
    const dem_dict *d = dem_dict_sub_opt(root, "multisphere");
    if (!d) return;
    static const char *const models[] = {"union", "sphereSum", 0};
    for (int i = 0; i < dem_dict_size(d); i++) {
        const char *name = dem_dict_key_at(d, i);
        if (!dem_dict_is_dict_at(d, i)) dem_dict_fatal(d, name, "a multisphere template is a sub-dictionary");
        const dem_dict *e = dem_dict_dict_at(d, i);
        const int material = particle_material_of(e, &s->materials);
        double *c = NULL, *r = NULL;
        const int n = dem_dict_vector_list(e, "centres", &c);
        const int nr = dem_dict_scalar_list(e, "radii", &r);
        if (n < 1) dem_dict_fatal(e, "centres", "give at least one sphere centre, e.g. ((0 0 0) (0.002 0 0)) [m]");
        if (nr != n) dem_dict_fatal(e, "radii", "%d radii for %d centres", nr, n);
        for (int k = 0; k < n; k++) {
            if (!(r[k] >= 1e-9 && r[k] <= 10.0))
                dem_dict_fatal(e, "radii", "radius %d is %g m: allowed [1e-9, 10] m", k + 1, r[k]);
            for (int q = 0; q < 3; q++)
                if (!(fabs(c[3 * k + q]) <= 10.0))
                    dem_dict_fatal(e, "centres", "centre %d lies %g m from the template's origin: allowed 10 m", k + 1,
                                   c[3 * k + q]);
        }
        /* spheres apart are allowed: the body holds them as a massless rigid frame would */
        const int model = dem_dict_choice_opt(e, "massModel", models, CLUMP_MASS_UNION);
        const int t = dem_bodies_add_template(&s->bodies, name, n, (const double (*)[3])c, r, material,
                                              s->materials.mat[material].density, (enum dem_clump_mass_model)model);
        const dem_clump_mass *mp = &s->bodies.templates[t].mass;
        dem_info("multisphere template '%s': %d spheres, volume %.6g m^3 (%s), mass %.6g kg, principal moments "
                 "(%.4g %.4g %.4g) kg m^2", name, n, mp->volume, model == CLUMP_MASS_UNION ? "union" : "sphereSum", mp->mass, mp->principal[0], mp->principal[1], mp->principal[2]);
        if (model == CLUMP_MASS_UNION)
            dem_info("multisphere template '%s': the union's volume is within %.3g m^3 of the exact one (%.2g %%: a bound; the integration is in practice far closer)", name,
                     mp->volume_error, 100.0 * mp->volume_error / mp->volume);
        free(c);
        free(r);
    }
}

static int template_of(const dem_dict *e, const dem_system *s)
{
    const char *name = dem_dict_word(e, "body");
    for (int t = 0; t < s->bodies.ntemplates; t++)
        if (strcmp(s->bodies.templates[t].name, name) == 0) return t;
    dem_dict_fatal(e, "body", "'%s' is not among the multisphere templates", name);
    return -1;
}

/* Two unit vectors across the unit normal n. */
static void plane_basis(const double n[3], double e1[3], double e2[3])
{
    const double a[3] = {fabs(n[0]) < 0.9 ? 1.0 : 0.0, fabs(n[0]) < 0.9 ? 0.0 : 1.0, 0.0};
    const double an = a[0] * n[0] + a[1] * n[1] + a[2] * n[2];
    for (int k = 0; k < 3; k++) e1[k] = a[k] - an * n[k];
    const double len = sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
    for (int k = 0; k < 3; k++) e1[k] /= len;
    e2[0] = n[1] * e1[2] - n[2] * e1[1];
    e2[1] = n[2] * e1[0] - n[0] * e1[2];
    e2[2] = n[0] * e1[1] - n[1] * e1[0];
}

/* face { type disc; centre (x y z); normal (nx ny nz); radius R; } or
 * face { type rectangle; min (x y z); max (x y z); normal (+-1 0 0 | ...); } (min = max along the normal):
 * the plane the stream enters through, its normal pointing into the domain. */
static void read_stream_face(const dem_dict *e, dem_stream *st, double dmax)
{
    const dem_dict *f = dem_dict_sub(e, "face");
    static const char *const kinds[] = {"disc", "rectangle", 0};
    const int kind = dem_dict_choice(f, "type", kinds);
    dem_dict_vector(f, "normal", st->normal);
    read_unit_normal(f, st->normal);
    if (kind == 0) {
        st->shape = STREAM_DISC;
        read_point(f, "centre", st->centre);
        st->radius = dem_dict_scalar(f, "radius", 1e-9, 1e6);
        if (st->radius <= 0.5 * dmax)
            dem_dict_fatal(f, "radius", "the disc (radius %g m) must be wider than the largest particle (diameter %g m)",
                           st->radius, dmax);
        plane_basis(st->normal, st->e1, st->e2);
        st->area = M_PI * st->radius * st->radius;
        return;
    }
    st->shape = STREAM_RECTANGLE;
    st->axis = -1;
    for (int k = 0; k < 3; k++)
        if (fabs(fabs(st->normal[k]) - 1.0) < 1e-12) st->axis = k;
    if (st->axis < 0)
        dem_dict_fatal(f, "normal", "a rectangle face lies across a coordinate axis: its normal is (1 0 0), (0 -1 0), ...");
    read_point(f, "min", st->fmin);
    read_point(f, "max", st->fmax);
    st->area = 1.0;
    for (int k = 0; k < 3; k++) {
        if (k == st->axis) {
            if (st->fmin[k] != st->fmax[k])
                dem_dict_fatal(f, "max", "the rectangle is flat across its normal: min and max must be equal in %c", "xyz"[k]);
            continue;
        }
        if (!(st->fmax[k] - st->fmin[k] > dmax))
            dem_dict_fatal(f, "max", "the rectangle is %g m wide in %c: it must be wider than the largest diameter %g m",
                           st->fmax[k] - st->fmin[k], "xyz"[k], dmax);
        st->area *= st->fmax[k] - st->fmin[k];
        st->centre[k] = 0.5 * (st->fmin[k] + st->fmax[k]);
    }
    st->centre[st->axis] = st->fmin[st->axis];
    st->normal[st->axis] = st->normal[st->axis] > 0.0 ? 1.0 : -1.0;
}

/* The slab a face stream fills lies in the domain: the face and the face moved by depth + the
 * largest diameter along its normal. */
static void check_stream_inside(const dem_dict *e, const dem_system *s, const dem_stream *st, double dmax)
{
    const dem_dict *f = dem_dict_sub(e, "face");
    const double reach = st->depth + dmax;
    for (int k = 0; k < 3; k++) {
        const double half = st->shape == STREAM_DISC ? st->radius * sqrt(fmax(0.0, 1.0 - st->normal[k] * st->normal[k]))
                                                      : k == st->axis ? 0.0 : 0.5 * (st->fmax[k] - st->fmin[k]);
        const double lo = fmin(st->centre[k], st->centre[k] + reach * st->normal[k]) - half;
        const double hi = fmax(st->centre[k], st->centre[k] + reach * st->normal[k]) + half;
        const double slack = 1e-9 * (s->domain_max[k] - s->domain_min[k]);
        if (lo < s->domain_min[k] - slack || hi > s->domain_max[k] + slack)
            dem_dict_fatal(f, st->shape == STREAM_DISC ? "centre" : "min",
                           "insertion '%s': the face and the slab it fills (%g m deep along the normal) span [%g, %g] m "
                           "in %c, outside the domain [%g, %g] m", st->ins.name, reach, lo, hi, "xyz"[k],
                           s->domain_min[k], s->domain_max[k]);
    }
}

/* method stream: particles at a rate through a face or into a region during the run (insert_stream.h).
 * The settings common to all insertions (name, velocity, seed) are in *ins already. */
static void read_stream(const dem_dict *e, dem_system *s, const dem_insertion *ins)
{
    if (dem_dict_has(e, "body"))
        dem_dict_fatal(e, "body", "a stream inserts spheres; multisphere bodies during the run are not supported yet");
    dem_stream *st = dem_streams_add(s);
    st->ins = *ins;
    st->ins.material = particle_material_of(e, &s->materials);
    read_diameter(e, &st->ins, s->coarse_graining);
    st->ins.max_attempts = (int)dem_dict_label_opt(e, "maxAttempts", 50, 1, 100000000);
    const double dmax = dem_insertion_max_diameter(&st->ins);
    if (dem_dict_has(e, "face") == dem_dict_has(e, "region"))
        dem_dict_fatal_here(e, "give exactly one of 'face' (the plane the particles enter through) and 'region'");
    if (dem_dict_has(e, "massRate") == dem_dict_has(e, "numberRate"))
        dem_dict_fatal_here(e, "give exactly one of 'massRate' [kg/s] and 'numberRate' [particles/s]");
    st->mass_rate = dem_dict_scalar_opt(e, "massRate", 0.0, 1e-30, 1e6);
    st->number_rate = dem_dict_scalar_opt(e, "numberRate", 0.0, 1e-30, 1e12);
    st->velocity_std = dem_dict_scalar_opt(e, "velocityStdDev", 0.0, 0.0, 1e3);
    st->start_time = dem_dict_scalar_opt(e, "startTime", 0.0, 0.0, 1e9);
    st->end_time = dem_dict_scalar_opt(e, "endTime", INFINITY, st->start_time, INFINITY);
    st->interval = dem_dict_scalar_opt(e, "insertInterval", 0.0, s->dt, 1e9);
    st->max_solid_fraction = dem_dict_scalar_opt(e, "maxSolidFraction", 0.25, 1e-3, 0.5);
    for (int k = 0; k < 3; k++)
        if (!(fabs(st->ins.velocity[k]) <= 1e5))
            dem_dict_fatal(e, st->ins.prescribed ? "prescribedVelocity" : "velocity", "%g m/s is out of range: allowed "
                           "[-1e5, 1e5] m/s", st->ins.velocity[k]);
    if (dem_dict_has(e, "face")) {
        read_stream_face(e, st, dmax);
        const double vn = st->ins.velocity[0] * st->normal[0] + st->ins.velocity[1] * st->normal[1] +
                          st->ins.velocity[2] * st->normal[2];
        if (!(vn > 0.0))
            dem_dict_fatal(e, dem_dict_has(e, "velocity") ? "velocity" : "prescribedVelocity",
                           "insertion '%s': the velocity (%g %g %g) m/s must cross the face inwards (velocity . normal "
                           "= %g m/s; the normal points into the domain)", st->ins.name, st->ins.velocity[0],
                           st->ins.velocity[1], st->ins.velocity[2], vn);
        dem_stream_prepare(s, st);
        check_stream_inside(e, s, st, dmax);
        const double largest = dem_stream_largest_rate(s, st), rate = st->mass_rate > 0.0 ? st->mass_rate : st->number_rate;
        const char *unit = st->mass_rate > 0.0 ? "kg/s" : "particles/s";
        if (rate > largest)
            dem_dict_fatal(e, st->mass_rate > 0.0 ? "massRate" : "numberRate",
                           "insertion '%s': %g %s does not fit through the face: over its %g m^2 at velocity . normal = "
                           "%g m/s the stream carries at most %g %s (at solid fraction maxSolidFraction = %g). Lower the "
                           "rate, or raise the velocity, the face or maxSolidFraction (random placement jams near 0.3).",
                           st->ins.name, rate, unit, st->area, vn, largest, unit, st->max_solid_fraction);
    } else {
        st->shape = STREAM_REGION;
        read_region(e, &st->ins);
        check_region_inside(e, s, &st->ins);
        dem_stream_prepare(s, st);
    }
    dem_info("insertion '%s': a stream of %g %s from t = %g s%s, an event every %ld steps (%g s)", st->ins.name,
             st->mass_rate > 0.0 ? st->mass_rate : st->number_rate, st->mass_rate > 0.0 ? "kg/s" : "particles/s",
             st->start_time, isfinite(st->end_time) ? "" : " on", st->every, st->every * s->dt);
}

static void run_insertions(const dem_dict *root, dem_system *s, int insert, const char *constant_dir)
{
    const dem_dict *d = dem_dict_sub_opt(root, "insertion");
    if (!d) return;
    static const char *const methods[] = {"random", "lattice", "file", "stream", 0};
    for (int i = 0; i < dem_dict_size(d); i++) {
        const char *name = dem_dict_key_at(d, i);
        if (!dem_dict_is_dict_at(d, i)) dem_dict_fatal(d, name, "an insertion is a sub-dictionary");
        const dem_dict *e = dem_dict_dict_at(d, i);
        dem_insertion ins;
        memset(&ins, 0, sizeof ins);
        snprintf(ins.name, sizeof ins.name, "%s", name);
        snprintf(ins.source, sizeof ins.source, "%s:%d", dem_dict_path(e), dem_dict_line(e));
        ins.method = dem_dict_choice_opt(e, "method", methods, INSERT_RANDOM);
        const double zero[3] = {0, 0, 0};
        dem_dict_vector_opt(e, "velocity", ins.velocity, zero);
        if (dem_dict_has(e, "prescribedVelocity")) {   /* a piston or probe: moves at it whatever the forces */
            if (dem_dict_has(e, "velocity"))
                dem_dict_fatal(e, "prescribedVelocity", "give either 'velocity' (the start velocity) or "
                               "'prescribedVelocity' (kept for the whole run), not both");
            dem_dict_vector(e, "prescribedVelocity", ins.velocity);
            ins.prescribed = 1;
        }
        ins.seed = (uint64_t)dem_dict_label_opt(e, "seed", 12345, 0, 2147483647L);
        if (ins.method == INSERT_STREAM) {   /* during the run: read on a restart too */
            if (strchr(name, ' ')) dem_dict_fatal(d, name, "a stream's name has no spaces");
            read_stream(e, s, &ins);
            continue;
        }
        if (ins.method == INSERT_FILE) {
            const char *f = dem_dict_word(e, "file");
            const int n = f[0] == '/' ? snprintf(ins.file, sizeof ins.file, "%s", f)
                                      : snprintf(ins.file, sizeof ins.file, "%s/%s", constant_dir, f);
            if (n >= (int)sizeof ins.file) dem_dict_fatal(e, "file", "the path is too long");
            if (dem_dict_has(e, "body")) {   /* the file's points are multisphere bodies' centres */
                ins.body = 1 + template_of(e, s);
                ins.material = s->bodies.templates[ins.body - 1].type;
                read_body_rotation(e, &ins);
            } else {
                ins.material = dem_dict_has(e, "material") ? particle_material_of(e, &s->materials) : -1;
                ins.has_diameter = dem_dict_has(e, "diameter");
                if (ins.has_diameter) read_diameter(e, &ins, s->coarse_graining);
            }
        } else {
            read_region(e, &ins);
            if (dem_dict_has(e, "body")) {   /* multisphere bodies: random or on the lattice's points */
                ins.body = 1 + template_of(e, s);
                ins.material = s->bodies.templates[ins.body - 1].type;
                read_body_rotation(e, &ins);
            } else {
                ins.material = particle_material_of(e, &s->materials);
                read_diameter(e, &ins, s->coarse_graining);
            }
            if (ins.method == INSERT_RANDOM) {
                if (dem_dict_has(e, "number") == dem_dict_has(e, "solidFraction"))
                    dem_dict_fatal_here(e, "give exactly one of 'number' and 'solidFraction'");
                ins.number = dem_dict_label_opt(e, "number", 0, 1, 100000000);
                ins.solid_fraction = dem_dict_scalar_opt(e, "solidFraction", 0.0, 1e-6, 0.6);
                ins.max_attempts = (int)dem_dict_label_opt(e, "maxAttempts", 200, 1, 100000000);
                check_random_count(e, s, &ins);
            } else {
                read_spacing(e, &ins);
                ins.number = dem_dict_label_opt(e, "number", 0, 1, 100000000);   /* 0: the whole lattice */
                const double g = sqrt(s->gravity[0] * s->gravity[0] + s->gravity[1] * s->gravity[1] +
                                      s->gravity[2] * s->gravity[2]);
                for (int k = 0; k < 3; k++) ins.down[k] = g > 0.0 ? s->gravity[k] / g : (k == 2 ? -1.0 : 0.0);
            }
            check_region_inside(e, s, &ins);
        }
        if (insert) {   /* skipped on restart: the particles come from the snapshot */
            switch (ins.method) {
            case INSERT_RANDOM:
                if (ins.body)
                    dem_info("insertion '%s': %ld multisphere bodies '%s'", name, dem_insertion_run(s, &ins),
                             s->bodies.templates[ins.body - 1].name);
                else dem_info("insertion '%s': %ld particles", name, dem_insertion_run(s, &ins));
                break;
            case INSERT_LATTICE:
                if (ins.body)
                    dem_info("insertion '%s': %ld multisphere bodies '%s' (lattice)", name,
                             dem_insertion_lattice(s, &ins, e), s->bodies.templates[ins.body - 1].name);
                else dem_info("insertion '%s': %ld particles (lattice)", name, dem_insertion_lattice(s, &ins, e));
                break;
            case INSERT_STREAM: break;   /* read above */
            case INSERT_FILE:
                if (ins.body)
                    dem_info("insertion '%s': %ld multisphere bodies '%s' (from %s)", name, dem_insertion_file(s, &ins, e),
                             s->bodies.templates[ins.body - 1].name, ins.file);
                else dem_info("insertion '%s': %ld particles (from %s)", name, dem_insertion_file(s, &ins, e), ins.file);
                break;
            }
        }
        free(ins.d_values);
        free(ins.d_weights);
    }
}

/* Default for the contact-time check: the fastest insertion speed plus a free fall over the
 * domain's extent along gravity. */
double dem_case_default_max_velocity(const dem_system *s)
{
    double vmax = 0.0, g = 0.0, h = 0.0;
    for (int i = 0; i < s->p.n; i++) {
        const double *v = s->p.v[i];
        vmax = fmax(vmax, sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
    }
    vmax = fmax(vmax, dem_streams_max_speed(s));   /* the particles still to come */
    dem_reduce_doubles(&vmax, 1, DEM_REDUCE_MAX);   /* the fastest on any rank (reduce.h) */
    for (int k = 0; k < 3; k++) {
        g += s->gravity[k] * s->gravity[k];
        if (s->gravity[k] != 0.0 && !s->periodic[k]) h = fmax(h, s->domain_max[k] - s->domain_min[k]);
    }
    return fmax(vmax + sqrt(2.0 * sqrt(g) * h), 0.1);
}

void dem_case_read(const char *case_dir, dem_system *s, dem_run_settings *rs, int skip_insertion)
{
    snprintf(rs->dict_path, sizeof rs->dict_path, "%s/constant/demProperties", case_dir);
    dem_dict *root = dem_dict_read(rs->dict_path);
    s->dt = dem_dict_scalar(root, "timeStep", 1e-12, 1.0);
    snprintf(rs->timestep_source, sizeof rs->timestep_source, "%s:%d", rs->dict_path, dem_dict_key_line(root, "timeStep"));
    rs->end_time = dem_dict_scalar(root, "endTime", 0.0, 1e9);
    /* the step counter is a long; far below its range, a run this long would never end anyway */
    if (rs->end_time / s->dt > 1e13)
        dem_dict_fatal(root, "endTime", "endTime / timeStep = %g steps: more than 1e13 steps (%g s / %g s); "
                       "shorten endTime or lengthen timeStep", rs->end_time / s->dt, rs->end_time, s->dt);
    rs->write_interval = dem_dict_scalar_opt(root, "writeInterval", 0.0, 0.0, 1e9);
    rs->progress_interval = dem_dict_scalar_opt(root, "progressInterval", 5.0, 0.0, 1e6);
    read_gravity(root, s->gravity);
    s->nlist.skin = dem_dict_scalar_opt(root, "skin", 0.0, 0.0, 10.0);
    s->nlist.sort_interval = (int)dem_dict_label_opt(root, "sortInterval", 20, 0, 1000000);
    s->max_overlap_fraction = dem_dict_scalar_opt(root, "maxOverlapFraction", 0.2, 1e-6, 1.0);
    rs->timestep_override = dem_dict_bool_opt(root, "timeStepOverride", 0);

    read_coarse_graining(root, s);
    read_domain(root, s);
    snprintf(rs->domain_source, sizeof rs->domain_source, "%s:%d", rs->dict_path, dem_dict_key_line(root, "domain"));
    read_materials(root, s);
    read_models(root, s);
    read_interactions(root, s);
    read_walls(root, s);
    read_multisphere(root, s);
    check_coarse_graining(root, s);
    read_outlets(root, s);
    char constant_dir[4200];
    snprintf(constant_dir, sizeof constant_dir, "%s/constant", case_dir);
    run_insertions(root, s, !skip_insertion, constant_dir);
    rs->max_expected_velocity = dem_dict_has(root, "maxExpectedVelocity")
        ? dem_dict_scalar(root, "maxExpectedVelocity", 1e-6, 1e5) : -1.0;
    dem_dict_check_unused(root);
    dem_dict_free(root);
}
