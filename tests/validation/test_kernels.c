/* Every combination of contact models (normal x tangential x cohesion x rolling x surface, all
 * ids of contact/models.h) in an oblique, spinning pair impact and wall impact.
 *
 * Spheres r 1 mm and 1.2 mm, E 5 MPa, nu 0.45, rho 2500, e 0.5, mu 0.4, no gravity; every
 * model's parameters set (hooke V 1 m/s; edinburgh kappa21 3, gamma_s 0.05 J/m^2; jkr and dmt
 * W 0.02 J/m^2; sjkr k_coh 2e4 J/m^3; cdt / epsd mu_r 0.1, eta_r 0.3; cdtJkr W 0.02 J/m^2,
 * eta_adh 2; roughness normal(0.2 rad, max 0.5)). The pair meets at 0.5 m/s with a sideways
 * component and spin; the wall is hit at 0.4 m/s, 45 degrees, with spin. 2000 steps of 2e-7 s
 * (0.4 ms: about four contact times, the contact is over or bonded).
 * Checks:
 *  - every combination, generic kernel: positions and velocities finite; the impacts happened
 *    (the pair's relative and the wall sphere's normal velocity changed by more than 10 %); the pair's linear
 *    momentum conserved (1e-12 of |p|); without roughness (forces along the centres' line)
 *    its angular momentum about the origin (orbital + spin) conserved (1e-10 of the scale
 *    m v r); the history layout: the antisymmetric part leads (each model's is all or none);
 *  - every combination with a specialised kernel (SPECIALISED_KERNELS): the specialised and the
 *    generic kernel give the same positions, velocities and angular velocities to 1e-12 of
 *    their scale (round-off), pair and wall. */
#include "harness.h"
#include "contact/evaluate.h"

static const double E = 5e6, NU = 0.45, RHO = 2500, R0 = 1e-3, R1 = 1.2e-3, DT = 2e-7;
static const int NSTEPS = 2000;

typedef struct state { double x[2][3], v[2][3], w[2][3]; int n; } state;

static void set_all_params(dem_system *s)
{
    const dem_hooke_case hooke = {1.0};
    const dem_edinburgh_params edinburgh = {3.0, 0.05, 1.5, 1.5, 0.0, 0.0};
    const dem_jkr_params jkr = {0.02};
    const dem_dmt_params dmt = {0.02};
    const dem_sjkr_params sjkr = {2e4};
    const dem_cdt_params cdt = {0.1};
    const dem_epsd_params epsd = {0.1, 0.3};
    const dem_cdt_jkr_params cdt_jkr = {0.02, 2.0};
    const dem_cdt_jkr_case cdt_jkr_c = {1.0};
    const dem_roughness_case rough = {SCATTER_NORMAL, 0.2, 0.5, 7};
    dem_material_table *t = &s->materials;
    const dem_contact_models *m = &s->models;
    if (m->normal == normal_hooke) SET_MODEL_CASE(s, SLOT_NORMAL, hooke);
    if (m->normal == normal_edinburgh) dem_materials_set_model_values(t, 0, 0, SLOT_NORMAL, &edinburgh, sizeof edinburgh);
    if (m->normal == normal_jkr) dem_materials_set_model_values(t, 0, 0, SLOT_NORMAL, &jkr, sizeof jkr);
    if (m->normal == normal_dmt) dem_materials_set_model_values(t, 0, 0, SLOT_NORMAL, &dmt, sizeof dmt);
    if (m->cohesion == cohesion_sjkr) dem_materials_set_model_values(t, 0, 0, SLOT_COHESION, &sjkr, sizeof sjkr);
    if (m->rolling == rolling_cdt) dem_materials_set_model_values(t, 0, 0, SLOT_ROLLING, &cdt, sizeof cdt);
    if (m->rolling == rolling_epsd) dem_materials_set_model_values(t, 0, 0, SLOT_ROLLING, &epsd, sizeof epsd);
    if (m->rolling == rolling_cdt_jkr) {
        dem_materials_set_model_values(t, 0, 0, SLOT_ROLLING, &cdt_jkr, sizeof cdt_jkr);
        SET_MODEL_CASE(s, SLOT_ROLLING, cdt_jkr_c);
    }
    if (m->surface == surface_roughness) SET_MODEL_CASE(s, SLOT_SURFACE, rough);
}

/* Run one impact with the models ids[], generic or not; the final state (by particle id). */
static state run(const int ids[SLOT_COUNT], int wall, int generic)
{
    dem_system s;
    make_system(&s, E, NU, RHO, 0.5, 0.4, ids[SLOT_NORMAL], ids[SLOT_TANGENTIAL], 0.05);
    s.models.cohesion = ids[SLOT_COHESION];
    s.models.rolling = ids[SLOT_ROLLING];
    s.models.surface = ids[SLOT_SURFACE];
    set_all_params(&s);
    s.generic_kernels = generic;
    s.dt = DT;
    s.nlist.skin = 0.2 * R0;
    if (wall) {
        add_plane(&s, 0, 0, 0, 0, 0, 1);
        const int i = add_sphere(&s, 0, 0, R0 + 1e-5, 0.28, 0.05, -0.28, R0);
        s.p.omega[i][0] = 50.0; s.p.omega[i][1] = -120.0; s.p.omega[i][2] = 30.0;
    } else {
        const int i = add_sphere(&s, 0, 0, 0, 0.25, 0.03, 0.0, R0);
        const int j = add_sphere(&s, R0 + R1 + 1e-5, 4e-4, 1e-4, -0.25, 0.0, 0.02, R1);
        s.p.omega[i][2] = 80.0; s.p.omega[j][1] = -60.0; s.p.omega[j][0] = 20.0;
    }
    dem_system_setup(&s);
    for (int k = 0; k < NSTEPS; k++) dem_system_step(&s);
    state out = {.n = s.p.n};
    for (int i = 0; i < s.p.n; i++) {
        const int q = (int)s.p.id[i];
        for (int d = 0; d < 3; d++) {
            out.x[q][d] = s.p.x[i][d];
            out.v[q][d] = s.p.v[i][d];
            out.w[q][d] = s.p.omega[i][d];
        }
    }
    dem_system_free(&s);
    return out;
}

static double mass(double r) { return RHO * 4.0 / 3.0 * M_PI * r * r * r; }

/* linear and angular momentum (about the origin, orbital + spin) of the pair */
static void momenta(const state *st, double p[3], double L[3])
{
    const double m[2] = {mass(R0), mass(R1)}, I[2] = {0.4 * mass(R0) * R0 * R0, 0.4 * mass(R1) * R1 * R1};
    for (int d = 0; d < 3; d++) p[d] = L[d] = 0.0;
    for (int i = 0; i < 2; i++) {
        const double *x = st->x[i], *v = st->v[i];
        for (int d = 0; d < 3; d++) p[d] += m[i] * v[d];
        L[0] += m[i] * (x[1] * v[2] - x[2] * v[1]) + I[i] * st->w[i][0];
        L[1] += m[i] * (x[2] * v[0] - x[0] * v[2]) + I[i] * st->w[i][1];
        L[2] += m[i] * (x[0] * v[1] - x[1] * v[0]) + I[i] * st->w[i][2];
    }
}

/* largest difference of two states, each quantity relative to its scale */
static double state_difference(const state *a, const state *b)
{
    double worst = 0.0;
    for (int i = 0; i < a->n; i++)
        for (int d = 0; d < 3; d++) {
            worst = fmax(worst, fabs(a->x[i][d] - b->x[i][d]) / R0);
            worst = fmax(worst, fabs(a->v[i][d] - b->v[i][d]) / 0.5);
            worst = fmax(worst, fabs(a->w[i][d] - b->w[i][d]) / (0.5 / R0));
        }
    return worst;
}

static int finite_state(const state *st)
{
    for (int i = 0; i < st->n; i++)
        for (int d = 0; d < 3; d++)
            if (!isfinite(st->x[i][d]) || !isfinite(st->v[i][d]) || !isfinite(st->w[i][d])) return 0;
    return 1;
}

int main(void)
{
    const int counts[SLOT_COUNT] = {NORMAL_COUNT, TANGENTIAL_COUNT, COHESION_COUNT, ROLLING_COUNT, SURFACE_COUNT};
    /* the initial momenta of the pair, from a run of no steps' worth: computed from the set-up */
    state start = {.n = 2};
    const double v0[2][3] = {{0.25, 0.03, 0.0}, {-0.25, 0.0, 0.02}};
    const double x0[2][3] = {{0, 0, 0}, {R0 + R1 + 1e-5, 4e-4, 1e-4}};
    const double w0[2][3] = {{0, 0, 80.0}, {20.0, -60.0, 0}};
    memcpy(start.v, v0, sizeof v0);
    memcpy(start.x, x0, sizeof x0);
    memcpy(start.w, w0, sizeof w0);
    double p0[3], L0[3];
    momenta(&start, p0, L0);
    const double p_scale = mass(R0) * 0.5, L_scale = mass(R0) * 0.5 * R0;

    double worst_impact = INFINITY;
    int no_impact = 0;
    int combos = 0, bad_finite = 0, bad_p = 0, bad_L = 0, bad_layout = 0, specialised = 0, bad_same = 0;
    double worst_p = 0.0, worst_L = 0.0, worst_same = 0.0;
    int ids[SLOT_COUNT];
    for (ids[0] = 0; ids[0] < counts[0]; ids[0]++)
        for (ids[1] = 0; ids[1] < counts[1]; ids[1]++)
            for (ids[2] = 0; ids[2] < counts[2]; ids[2]++)
                for (ids[3] = 0; ids[3] < counts[3]; ids[3]++)
                    for (ids[4] = 0; ids[4] < counts[4]; ids[4]++) {
                        combos++;
                        char name[128];
                        snprintf(name, sizeof name, "%s/%s/%s/%s/%s", dem_contact_model_get(0, ids[0])->name,
                                 dem_contact_model_get(1, ids[1])->name, dem_contact_model_get(2, ids[2])->name,
                                 dem_contact_model_get(3, ids[3])->name, dem_contact_model_get(4, ids[4])->name);
                        /* history layout: all antisymmetric parts lead */
                        dem_contact_models m = {.normal = ids[0], .tangential = ids[1], .cohesion = ids[2], .rolling = ids[3], .surface = ids[4]};
                        int anti = 0;
                        for (int slot = 0; slot < SLOT_COUNT; slot++) {
                            const dem_contact_model *d = dem_contact_model_get(slot, ids[slot]);
                            if (d->history_antisymmetric != 0 && d->history_antisymmetric != d->history) bad_layout++;
                            anti += d->history_antisymmetric;
                        }
                        if (anti != dem_contact_history_antisymmetric(&m)) {
                            bad_layout++;
                            printf("history layout: %s antisymmetric %d, layout gives %d\n", name, anti,
                                   dem_contact_history_antisymmetric(&m));
                        }
                        const state pg = run(ids, 0, 1), wg = run(ids, 1, 1);
                        if (!finite_state(&pg) || !finite_state(&wg)) {
                            bad_finite++;
                            printf("not finite: %s\n", name);
                            continue;
                        }
                        /* the impacts happened: the pair's relative velocity along x and the wall
                         * sphere's normal velocity changed by more than 10 % */
                        const double dvx = fabs((pg.v[0][0] - pg.v[1][0]) - (v0[0][0] - v0[1][0])) / 0.5;
                        const double dvz = fabs(wg.v[0][2] + 0.28) / 0.28;
                        worst_impact = fmin(worst_impact, fmin(dvx, dvz));
                        if (dvx < 0.1 || dvz < 0.1) { no_impact++; printf("no impact: %s (%.3g, %.3g)\n", name, dvx, dvz); }
                        double p[3], L[3];
                        momenta(&pg, p, L);
                        const double dp = sqrt(pow(p[0] - p0[0], 2) + pow(p[1] - p0[1], 2) + pow(p[2] - p0[2], 2)) / p_scale;
                        const double dL = sqrt(pow(L[0] - L0[0], 2) + pow(L[1] - L0[1], 2) + pow(L[2] - L0[2], 2)) / L_scale;
                        worst_p = fmax(worst_p, dp);
                        if (dp > 1e-12) { bad_p++; printf("momentum %s: %.3g\n", name, dp); }
                        if (ids[SLOT_SURFACE] == surface_default) {
                            worst_L = fmax(worst_L, dL);
                            if (dL > 1e-10) { bad_L++; printf("angular momentum %s: %.3g\n", name, dL); }
                        }
                        if (contact_specialised(&m) >= 0) {
                            specialised++;
                            const state ps = run(ids, 0, 0), ws = run(ids, 1, 0);
                            const double diff = fmax(state_difference(&ps, &pg), state_difference(&ws, &wg));
                            worst_same = fmax(worst_same, diff);
                            printf("specialised %-40s vs generic: %.3g\n", name, diff);
                            if (diff > 1e-12) bad_same++;
                        }
                    }
    printf("%d combinations, %d with a specialised kernel\n", combos, specialised);
    check_true("every combination: finite after pair and wall impacts", bad_finite == 0);
    char what[120];
    snprintf(what, sizeof what, "every combination: the impacts change the velocities (least %.2f, > 0.1)", worst_impact);
    check_true(what, no_impact == 0);
    snprintf(what, sizeof what, "pair momentum conserved, every combination (worst %.2g, tol 1e-12)", worst_p);
    check_true(what, bad_p == 0);
    snprintf(what, sizeof what, "pair angular momentum, no roughness (worst %.2g, tol 1e-10)", worst_L);
    check_true(what, bad_L == 0);
    check_true("history: antisymmetric parts lead, each all or none", bad_layout == 0);
    snprintf(what, sizeof what, "specialised = generic, pair and wall (worst %.2g, tol 1e-12)", worst_same);
    check_true(what, bad_same == 0 && specialised > 0);
    return finish("test_kernels");
}
