/* Particle forces per model A / B (particle_forces.h) and the per-cell exchange (exchange.h):
 *  - momentum balance: random particles (300, some outside the mesh), cells, weights, fluid
 *    and particle velocities; for every drag law x model A/B x implicit/explicit the sum over
 *    cells of V_c (K_sl (up - u_f) + S) equals minus the sum over particles of the exchanged
 *    force beta (u_f - v) + f_exchange, within 1e-12 relative;
 *  - the part carried by the fluid equation's own terms balances too, given the void fraction
 *    built from the same weights: model A sum V_c (1 - alpha_c) grad p_c = -sum (-V_p grad p);
 *    model B S_c = (1 - alpha_c) rho_f g per cell (so alpha rho_f g + S = rho_f g);
 *  - implicit mode: the force at another velocity v' changes by -beta (v' - v); explicit mode:
 *    frozen; sum_c K_sl V_c = sum beta; empty cells get nothing; a lone particle's cell has
 *    up = its velocity;
 *  - static column (u_f = v = 0, grad p = rho_f g): every law, both models, alpha 0.6 and 1,
 *    the particle feels exactly the buoyancy -rho_f V_p g (1e-12);
 *  - settling sphere through the full model A and B forces (alpha = 1, hydrostatic grad p):
 *    terminal velocity 0.1373 m/s within 1 % (d 100 um, rho_p 3000, rho_f 10, nu 1e-5);
 *  - cpl_cell_weights_check accepts good weights and rejects bad ones. */
#include "catch_fatal.h"
#include "harness.h"
#include "rng.h"

#include "exchange.h"

#define NP 300
#define NCELLS 40
#define NFILLED 35   /* particles only go to cells 0 .. NFILLED-1: the rest stay empty */
#define MAXW 4

static const double G[3] = {0.0, 0.0, -9.81};

static double norm3(const double a[3]) { return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

typedef struct scene {
    double cell_volume[NCELLS], alpha_cell[NCELLS], u_cell[NCELLS][3], gradp_cell[NCELLS][3];
    int start[NP + 1], cell_of[NP * MAXW], cell[NP];
    double weight[NP * MAXW];
    double v[NP][3], d[NP], volume[NP], u_f[NP][3], grad_p[NP][3], alpha[NP];
    cpl_cell_weights w;
} scene;

static void make_scene(scene *s, double rho_f)
{
    dem_rng r;
    rng_seed(&r, 20100825);
    for (int c = 0; c < NCELLS; c++) {
        s->cell_volume[c] = 1e-6 * (0.5 + 1.5 * rng_uniform(&r));   /* [m^3] */
        s->alpha_cell[c] = 0.4 + 0.6 * rng_uniform(&r);
        const double bias[3] = {0.3, -0.1, 1.0};                     /* [m/s] */
        for (int k = 0; k < 3; k++) {
            s->u_cell[c][k] = bias[k] + 0.5 * rng_normal(&r);
            s->gradp_cell[c][k] = rho_f * G[k] + 500.0 * rng_normal(&r);   /* [Pa/m] */
        }
    }
    int nw = 0;
    for (int i = 0; i < NP; i++) {
        s->start[i] = nw;
        s->cell[i] = i % 50 == 7 ? -1 : (int)(rng_uniform(&r) * NFILLED);   /* a few outside */
        if (s->cell[i] >= 0) {
            const int m = 1 + (int)(rng_uniform(&r) * MAXW);
            double sum = 0.0;
            for (int j = 0; j < m; j++) {
                s->cell_of[nw + j] = j == 0 ? s->cell[i] : (int)(rng_uniform(&r) * NFILLED);
                s->weight[nw + j] = 0.05 + rng_uniform(&r);
                sum += s->weight[nw + j];
            }
            for (int j = 0; j < m; j++) s->weight[nw + j] /= sum;
            nw += m;
        }
        s->d[i] = 50e-6 + 450e-6 * rng_uniform(&r);   /* [m] */
        s->volume[i] = M_PI / 6.0 * s->d[i] * s->d[i] * s->d[i];
        const double bias[3] = {-0.2, 0.1, -0.5};
        for (int k = 0; k < 3; k++) s->v[i][k] = bias[k] + 0.3 * rng_normal(&r);
    }
    s->start[NP] = nw;
    s->w = (cpl_cell_weights){NP, s->start, s->cell_of, s->weight};
    cpl_gather_vector(&s->w, (const double(*)[3])s->u_cell, s->u_f);
    cpl_gather_vector(&s->w, (const double(*)[3])s->gradp_cell, s->grad_p);
    cpl_gather_scalar(&s->w, s->alpha_cell, s->alpha);
}

static cpl_particle_fluid inputs(const scene *s)
{
    return (cpl_particle_fluid){NP, (const double(*)[3])s->v, s->d, s->volume, (const double(*)[3])s->u_f,
                                (const double(*)[3])s->grad_p, s->alpha, s->cell};
}

static void balance(void)
{
    static scene s;
    const double rho_f = 1000.0, mu_f = 1e-3;
    make_scene(&s, rho_f);
    int stopped;
    STOPS_WITH(stopped, cpl_cell_weights_check(&s.w, NCELLS, 1e-12), "");
    check_true("random weights pass cpl_cell_weights_check", !stopped);

    /* the void fraction the weights imply (what the void fraction code would give) */
    double vp_cell[NCELLS] = {0};
    for (int i = 0; i < NP; i++)
        for (int j = s.start[i]; j < s.start[i + 1]; j++) vp_cell[s.cell_of[j]] += s.weight[j] * s.volume[i];

    cpl_fluid_forces f;
    cpl_fluid_forces_init(&f);
    static double ksl[NCELLS], up[NCELLS][3], src[NCELLS][3];
    const cpl_particle_fluid in = inputs(&s);
    double worst_balance = 0.0, worst_eq_a = 0.0, worst_s_b = 0.0, worst_v = 0.0, worst_k = 0.0;
    int empty_ok = 1, outside_ok = 1;
    for (int law = 0; law < CPL_DRAG_COUNT; law++)
        for (int model = CPL_MODEL_A; model <= CPL_MODEL_B; model++)
            for (int mode = CPL_EXCHANGE_IMPLICIT; mode <= CPL_EXCHANGE_EXPLICIT; mode++) {
                const cpl_force_params prm = {(enum cpl_model_type)model, (enum cpl_drag_law)law,
                                              (enum cpl_exchange_mode)mode, rho_f, mu_f, {G[0], G[1], G[2]}, {0, 0, 0}, 1.0};
                cpl_force_params_check(&prm);   /* valid, or the test stops here */
                cpl_fluid_forces_eval(&prm, &in, &f);
                cpl_exchange_cells(&s.w, &f, (const double(*)[3])s.v, NCELLS, s.cell_volume, ksl, up, src);

                /* what the fluid gains [N] vs what the particles gain [N] */
                double fluid[3] = {0, 0, 0}, part[3] = {0, 0, 0}, eq[3] = {0, 0, 0}, sum_k = 0.0, sum_beta = 0.0;
                for (int c = 0; c < NCELLS; c++) {
                    for (int k = 0; k < 3; k++) fluid[k] += s.cell_volume[c] * (ksl[c] * (up[c][k] - s.u_cell[c][k]) + src[c][k]);
                    sum_k += ksl[c] * s.cell_volume[c];
                    if (c >= NFILLED && (ksl[c] != 0.0 || norm3(up[c]) != 0.0 || norm3(src[c]) != 0.0)) empty_ok = 0;
                }
                for (int i = 0; i < NP; i++) {
                    double F[3], Fall[3];
                    cpl_fluid_force_exchanged(&f, i, s.v[i], F);
                    cpl_fluid_force(&f, i, s.v[i], Fall);
                    for (int k = 0; k < 3; k++) { part[k] += F[k]; eq[k] += f.f_equation[i][k]; }
                    sum_beta += f.beta[i];
                    if (s.cell[i] < 0 && norm3(Fall) != 0.0) outside_ok = 0;
                    /* another velocity: implicit re-evaluates beta (u_f - v'), explicit is frozen */
                    const double v2[3] = {s.v[i][0] + 0.7, s.v[i][1] - 0.2, s.v[i][2] + 0.1};
                    double F2[3];
                    cpl_fluid_force(&f, i, v2, F2);
                    for (int k = 0; k < 3; k++) {
                        const double expect = mode == CPL_EXCHANGE_IMPLICIT ? Fall[k] - f.beta[i] * (v2[k] - s.v[i][k]) : Fall[k];
                        worst_v = fmax(worst_v, fabs(F2[k] - expect) / (norm3(Fall) + 1e-300));
                    }
                }
                double diff[3];
                for (int k = 0; k < 3; k++) diff[k] = fluid[k] + part[k];
                const double err = norm3(diff) / norm3(part);
                worst_balance = fmax(worst_balance, err);
                char what[128];
                snprintf(what, sizeof what, "balance %-15s model %s %-8s |fluid + particles|/|particles|",
                         cpl_drag_law_names[law], cpl_model_type_names[model], cpl_exchange_mode_names[mode]);
                check_below(what, err, 1e-12);
                if (sum_beta > 0.0) worst_k = fmax(worst_k, fabs(sum_k - sum_beta) / sum_beta);

                if (model == CPL_MODEL_A) {
                    /* -alpha grad p = -grad p + (1 - alpha) grad p: the fluid's share of the
                     * particles' -V_p grad p, summed with the same weights */
                    double fl[3] = {0, 0, 0};
                    for (int c = 0; c < NCELLS; c++)
                        for (int k = 0; k < 3; k++) fl[k] += vp_cell[c] * s.gradp_cell[c][k];   /* V_c (1 - alpha_c) grad p */
                    double dd[3];
                    for (int k = 0; k < 3; k++) dd[k] = fl[k] + eq[k];
                    worst_eq_a = fmax(worst_eq_a, norm3(dd) / norm3(eq));
                } else if (mode == CPL_EXCHANGE_IMPLICIT) {
                    /* S_c is the buoyancy reaction (1 - alpha_c) rho_f g */
                    for (int c = 0; c < NFILLED; c++)
                        worst_s_b = fmax(worst_s_b, fabs(src[c][2] - vp_cell[c] / s.cell_volume[c] * rho_f * G[2])
                                                        / fabs(vp_cell[c] / s.cell_volume[c] * rho_f * G[2]));
                    if (norm3(eq) != 0.0) worst_s_b = 1.0;
                }
            }
    check_below("all 20 combinations: momentum balance", worst_balance, 1e-12);
    check_below("model A: sum V_c (1-alpha_c) grad p_c = sum V_p grad p", worst_eq_a, 1e-12);
    check_below("model B implicit: S_c = (1 - alpha_c) rho_f g per cell", worst_s_b, 1e-12);
    check_below("F(v') = F(v) - beta (v' - v) implicit, frozen explicit", worst_v, 1e-12);
    check_below("sum_c K_sl V_c = sum_i beta_i", worst_k, 1e-12);
    check_true("empty cells: K_sl = 0, up = 0, S = 0", empty_ok);
    check_true("particles outside the mesh: no fluid force", outside_ok);

    /* model split of one particle: A has -V_p grad p and beta_p, B has beta_p / alpha and -rho V g */
    const int i = 1;
    const double slip = sqrt(pow(s.u_f[i][0] - s.v[i][0], 2) + pow(s.u_f[i][1] - s.v[i][1], 2) + pow(s.u_f[i][2] - s.v[i][2], 2));
    const double beta_p = cpl_drag_koch_hill(rho_f, mu_f, s.d[i], s.alpha[i], slip);
    cpl_force_params pa = {CPL_MODEL_A, CPL_DRAG_KOCH_HILL, CPL_EXCHANGE_IMPLICIT, rho_f, mu_f, {G[0], G[1], G[2]}, {0, 0, 0}, 1.0};
    cpl_fluid_forces_eval(&pa, &in, &f);
    check_rel("model A: beta = beta_p", f.beta[i], beta_p, 1e-15);
    check_rel("model A: f_equation = -V_p grad p (x)", f.f_equation[i][0], -s.volume[i] * s.grad_p[i][0], 1e-15);
    pa.model = CPL_MODEL_B;
    cpl_fluid_forces_eval(&pa, &in, &f);
    check_rel("model B: beta = beta_p / alpha", f.beta[i], beta_p / s.alpha[i], 1e-15);
    check_rel("model B: f_exchange = -rho_f V_p g (z)", f.f_exchange[i][2], -rho_f * s.volume[i] * G[2], 1e-15);
    /* a driving gradient (issue 21): the particle feels V_p drive, model A in f_equation (its
     * reaction in the fluid's -alpha grad p_drive), model B in f_exchange (its reaction in S) */
    const double drive[3] = {1234.5, 0.0, 0.0};   /* -grad p_drive [N/m^3] */
    for (int q = 0; q < 3; q++) pa.drive[q] = drive[q];
    cpl_fluid_forces_eval(&pa, &in, &f);
    check_rel("model B with a drive: f_exchange = V_p drive (x)", f.f_exchange[i][0], s.volume[i] * drive[0], 1e-15);
    pa.model = CPL_MODEL_A;
    cpl_fluid_forces_eval(&pa, &in, &f);
    check_rel("model A with a drive: f_equation = -V_p grad p + V_p drive (x)", f.f_equation[i][0],
              -s.volume[i] * s.grad_p[i][0] + s.volume[i] * drive[0], 1e-15);
    cpl_fluid_forces_free(&f);
}

/* a particle alone in its cell: up = its velocity; K_sl = beta / V_c */
static void lone_particle(void)
{
    const int start[2] = {0, 1}, cell[1] = {2};
    const double weight[1] = {1.0}, volume[4] = {1e-6, 2e-6, 3e-6, 4e-6};
    const double v[1][3] = {{0.1, -0.2, 0.3}}, u_f[1][3] = {{1.0, 0.5, -0.5}}, gp[1][3] = {{0, 0, -9810}};
    const double d[1] = {1e-3}, vp[1] = {M_PI / 6.0 * 1e-9}, alpha[1] = {0.7};
    const cpl_cell_weights w = {1, start, cell, weight};
    const cpl_particle_fluid in = {1, v, d, vp, u_f, gp, alpha, NULL};
    const cpl_force_params prm = {CPL_MODEL_B, CPL_DRAG_DI_FELICE, CPL_EXCHANGE_IMPLICIT, 1000.0, 1e-3, {0, 0, -9.81}, {0, 0, 0}, 1.0};
    cpl_fluid_forces f;
    cpl_fluid_forces_init(&f);
    cpl_fluid_forces_eval(&prm, &in, &f);
    double ksl[4], up[4][3], src[4][3];
    cpl_exchange_cells(&w, &f, v, 4, volume, ksl, up, src);
    check_rel("lone particle: up = v (y)", up[2][1], v[0][1], 1e-15);
    check_rel("lone particle: K_sl = beta / V_c", ksl[2], f.beta[0] / volume[2], 1e-15);
    cpl_fluid_forces_free(&f);
}

/* u_f = v = 0 and grad p = rho_f g: the particle feels exactly -rho_f V_p g in both models */
static void static_column(void)
{
    const double rho_f = 1000.0, mu_f = 1e-3;
    const double zero[1][3] = {{0, 0, 0}}, gp[1][3] = {{rho_f * G[0], rho_f * G[1], rho_f * G[2]}};
    const double d[1] = {2e-3}, vp[1] = {M_PI / 6.0 * 8e-9};
    double worst = 0.0;
    for (int law = 0; law < CPL_DRAG_COUNT; law++)
        for (int model = CPL_MODEL_A; model <= CPL_MODEL_B; model++)
            for (int mode = CPL_EXCHANGE_IMPLICIT; mode <= CPL_EXCHANGE_EXPLICIT; mode++)
                for (int a = 0; a < 2; a++) {
                    const double alpha[1] = {a ? 1.0 : 0.6};
                    const cpl_particle_fluid in = {1, zero, d, vp, zero, gp, alpha, NULL};
                    const cpl_force_params prm = {(enum cpl_model_type)model, (enum cpl_drag_law)law,
                                                  (enum cpl_exchange_mode)mode, rho_f, mu_f, {G[0], G[1], G[2]}, {0, 0, 0}, 1.0};
                    cpl_fluid_forces f;
                    cpl_fluid_forces_init(&f);
                    cpl_fluid_forces_eval(&prm, &in, &f);
                    double F[3];
                    cpl_fluid_force(&f, 0, zero[0], F);
                    const double buoy = -rho_f * vp[0] * G[2];
                    worst = fmax(worst, fmax(fabs(F[2] - buoy) / buoy, (fabs(F[0]) + fabs(F[1])) / buoy));
                    cpl_fluid_forces_free(&f);
                }
    check_below("static column: F = -rho_f V_p g, 5 laws x A/B x modes x alpha", worst, 1e-12);
}

/* settling sphere through the full force: F_fluid(v) + m g = 0 */
static void settling(void)
{
    const double rho_p = 3000.0, rho_f = 10.0, nu = 1e-5, d = 100e-6;
    const double vp = M_PI / 6.0 * d * d * d, m = rho_p * vp;
    for (int model = CPL_MODEL_A; model <= CPL_MODEL_B; model++) {
        const cpl_force_params prm = {(enum cpl_model_type)model, CPL_DRAG_SCHILLER_NAUMANN, CPL_EXCHANGE_IMPLICIT,
                                      rho_f, rho_f * nu, {G[0], G[1], G[2]}, {0, 0, 0}, 1.0};
        const double u_f[1][3] = {{0, 0, 0}}, gp[1][3] = {{0, 0, rho_f * G[2]}}, dd[1] = {d}, vv[1] = {vp}, alpha[1] = {1.0};
        cpl_fluid_forces f;
        cpl_fluid_forces_init(&f);
        double lo = -10.0, hi = 0.0;   /* settling velocity v_z < 0 */
        for (int it = 0; it < 200; it++) {
            const double vz = 0.5 * (lo + hi);
            const double v[1][3] = {{0, 0, vz}};
            const cpl_particle_fluid in = {1, v, dd, vv, u_f, gp, alpha, NULL};
            cpl_fluid_forces_eval(&prm, &in, &f);
            double F[3];
            cpl_fluid_force(&f, 0, v[0], F);
            if (F[2] + m * G[2] > 0.0) lo = vz; else hi = vz;   /* net up: falling too fast */
        }
        char what[96];
        snprintf(what, sizeof what, "settling sphere, model %s, |v| [m/s]", cpl_model_type_names[model]);
        check_rel(what, -0.5 * (lo + hi), 0.1373, 0.01);
        cpl_fluid_forces_free(&f);
    }
}

/* Coarse graining (docs/models/coarse_graining.md): a parcel of diameter D = cg d stands for cg^3
 * particles of diameter d; its drag is cg^3 times the law's for d (Re from d), for every law and
 * voidage, to round-off; so it settles at its particles' terminal velocity (Schiller-Naumann,
 * model A and B, bisection to 1e-12 relative; 1e-9 stated, the bisection's own tolerance). */
static void parcels(void)
{
    const double rho_f = 10.0, mu_f = 1e-4, d = 200e-6, rho_p = 3000.0;
    double worst = 0.0;
    for (int law = 0; law < CPL_DRAG_COUNT; law++)
        for (int c = 2; c <= 3; c++)
            for (int a = 0; a < 4; a++) {
                const double cg = c, alpha_v[4] = {0.45, 0.7, 0.95, 1.0}, D = cg * d;
                const double v[1][3] = {{0, 0, 0}}, u_f[1][3] = {{0.3, 0, 0.1}}, gp[1][3] = {{0, 0, 0}};
                const double dd[1] = {D}, vv[1] = {M_PI / 6.0 * D * D * D}, alpha[1] = {alpha_v[a]};
                const cpl_force_params prm = {CPL_MODEL_A, (enum cpl_drag_law)law, CPL_EXCHANGE_IMPLICIT, rho_f, mu_f,
                                              {G[0], G[1], G[2]}, {0, 0, 0}, cg};
                cpl_force_params_check(&prm);
                const cpl_particle_fluid in = {1, v, dd, vv, u_f, gp, alpha, NULL};
                cpl_fluid_forces f;
                cpl_fluid_forces_init(&f);
                cpl_fluid_forces_eval(&prm, &in, &f);
                const double want = cg * cg * cg * cpl_drag_beta((enum cpl_drag_law)law, rho_f, mu_f, d, alpha_v[a],
                                                                  sqrt(0.3 * 0.3 + 0.1 * 0.1));
                worst = fmax(worst, fabs(f.beta[0] - want) / want);
                cpl_fluid_forces_free(&f);
            }
    check_below("parcel of cg = 2, 3: beta = cg^3 beta_law(d / cg), 5 laws x 4 voidages", worst, 1e-14);

    double vt[4] = {0, 0, 0, 0};   /* terminal speed: particle and parcel, models A and B */
    for (int model = CPL_MODEL_A; model <= CPL_MODEL_B; model++)
        for (int parcel = 0; parcel < 2; parcel++) {
            const double cg = parcel ? 3.0 : 1.0, D = cg * d, vp = M_PI / 6.0 * D * D * D, m = rho_p * vp;
            const cpl_force_params prm = {(enum cpl_model_type)model, CPL_DRAG_SCHILLER_NAUMANN, CPL_EXCHANGE_IMPLICIT,
                                          rho_f, mu_f, {G[0], G[1], G[2]}, {0, 0, 0}, cg};
            const double u_f[1][3] = {{0, 0, 0}}, gp[1][3] = {{0, 0, rho_f * G[2]}}, dd[1] = {D}, vv[1] = {vp},
                         alpha[1] = {1.0};
            cpl_fluid_forces f;
            cpl_fluid_forces_init(&f);
            double lo = -10.0, hi = 0.0;
            for (int it = 0; it < 200; it++) {
                const double vz = 0.5 * (lo + hi), vel[1][3] = {{0, 0, vz}};
                const cpl_particle_fluid in = {1, vel, dd, vv, u_f, gp, alpha, NULL};
                cpl_fluid_forces_eval(&prm, &in, &f);
                double F[3];
                cpl_fluid_force(&f, 0, vel[0], F);
                if (F[2] + m * G[2] > 0.0) lo = vz; else hi = vz;
            }
            vt[2 * model + parcel] = -0.5 * (lo + hi);
            cpl_fluid_forces_free(&f);
        }
    check_rel("parcel of cg = 3 settles as its particles, model A [m/s]", vt[1], vt[0], 1e-9);
    check_rel("parcel of cg = 3 settles as its particles, model B [m/s]", vt[3], vt[2], 1e-9);
    const cpl_force_params bad = {CPL_MODEL_A, CPL_DRAG_GIDASPOW, CPL_EXCHANGE_IMPLICIT, rho_f, mu_f,
                                  {G[0], G[1], G[2]}, {0, 0, 0}, 0.5};
    volatile int stops;
    STOPS_WITH(stops, cpl_force_params_check(&bad), "coarse-graining factor 0.5 must be in [1, 100]");
    check_true("coarse-graining factor 0.5 refused", stops);
}

static void weights_errors(void)
{
    const int start[3] = {0, 2, 3}, cell[3] = {0, 1, 1}, bad_cell[3] = {0, 1, 5};
    const double weight[3] = {0.25, 0.75, 1.0}, bad_weight[3] = {0.25, 0.7, 1.0};
    const cpl_cell_weights good = {2, start, cell, weight}, out_of_range = {2, start, bad_cell, weight},
                           not_one = {2, start, cell, bad_weight};
    volatile int good_stops, range_stops, sum_stops;   /* kept across the jumps back */
    STOPS_WITH(good_stops, cpl_cell_weights_check(&good, 2, 1e-12), "");
    STOPS_WITH(range_stops, cpl_cell_weights_check(&out_of_range, 2, 1e-12),
               "coupling: cell weights: particle 1 refers to cell 5 (mesh has 2)");
    STOPS_WITH(sum_stops, cpl_cell_weights_check(&not_one, 2, 1e-12), "particle 0's weights sum to 0.94999");
    check_true("weights check: good passes; cell out of range, sum 0.95: fatal errors naming the particle",
               !good_stops && range_stops && sum_stops);
    check_true("name tables: A, B, implicit, explicit",
               cpl_name_find(cpl_model_type_names, "B") == CPL_MODEL_B
                   && cpl_name_find(cpl_exchange_mode_names, "explicit") == CPL_EXCHANGE_EXPLICIT
                   && cpl_name_find(cpl_exchange_mode_names, "semi") == -1);
}

int main(void)
{
    balance();
    lone_particle();
    static_column();
    settling();
    parcels();
    weights_errors();
    return finish("test_exchange");
}
