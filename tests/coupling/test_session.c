/* The coupling session without OpenFOAM: a box mesh, a case written here, the fluid at rest
 * with the hydrostatic pressure gradient (grad p = rho_f g) handed in every fluid step.
 *  - One sphere (d 100 um, rho_p 3000, fluid rho_f 10, nu 1e-5) released at rest reaches the
 *    Schiller-Naumann terminal velocity 0.1373 m/s within 1 %, for model A and model B.
 *  - The fields handed to the fluid balance the particles' force: sum over cells of
 *    V (K_sl (up - U) + S) equals minus the exchanged part of the fluid force on the particles
 *    (model B: drag and buoyancy), within 0.1 % at terminal velocity.
 *  - The same with the fluid fields interpolated (cellPoint, cellLinear) instead of gathered.
 *  - A dt_f that is not couplingInterval x the DEM step is refused (tested in the shell cases).
 *  - In a field that jitters from step to step (U_z = 0.1 +- 0.05 m/s, alternating, as the
 *    centre void fraction's gas does), the force the particle feels over a fluid step equals
 *    what the fluid received for that step (K_sl (up - U) + S with the U it then solved), summed
 *    over 1000 steps, within 1e-4: the particle keeps the drag coefficient the fluid received.
 *    (Evaluating it again with the new slip made the particle feel 3.0 % more here.)
 *  - A multisphere body of two such spheres 10 diameters apart settles at the single sphere's
 *    terminal velocity (1 %); the fluid receives its weight (1e-3). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "coupling.h"
#include "harness.h"

/* body: the particle is a multisphere body of two such spheres 1 mm apart (10 diameters) */
static int with_body;

static void write_case(const char *dir, const char *model, const char *interp)
{
    char path[512];
    snprintf(path, sizeof path, "%s/constant", dir);
    mkdir(dir, 0755);
    mkdir(path, 0755);
    snprintf(path, sizeof path, "%s/constant/demProperties", dir);
    FILE *f = fopen(path, "w");
    fprintf(f, "timeStep 2e-6; endTime 1; writeInterval 0; gravity (0 0 -9.81); maxExpectedVelocity 1;\n"
               "domain { min (-0.01 -0.01 0); max (0.01 0.01 0.1); }\n"
               "materials { s { youngsModulus 1e6; poissonsRatio 0.3; density 3000; } }\n"
               "contactModels { normal hertz; tangential history; }\n"
               "interactions { default { restitution 0.5; friction 0.5; } }\n"
               "%s", with_body
               ? "multisphere { pair { material s; centres ((0 0 0) (1e-3 0 0)); radii (5e-5 5e-5); massModel sphereSum; } }\n"
                 "insertion { one { region { type box; min (-7e-4 -7e-4 0.0893); max (7e-4 7e-4 0.0907); }\n"
                 "  number 1; body pair; } }\n"
               : "insertion { one { region { type box; min (-1e-4 -1e-4 0.0899); max (1e-4 1e-4 0.0901); }\n"
                 "  number 1; material s; diameter { distribution constant; value 1e-4; } } }\n");
    fclose(f);
    snprintf(path, sizeof path, "%s/constant/couplingProperties", dir);
    f = fopen(path, "w");
    fprintf(f, "couplingInterval 50; voidFraction { model centre; alphaMin 0.3; }\n"
               "drag SchillerNaumann; momentumCoupling %s; exchange implicit; interpolation %s;\n", model, interp);
    fclose(f);
}

/* The session of one test: the case written to dir, a 4 x 4 x 20 box mesh, and the fluid at
 * rest with the hydrostatic pressure gradient (grad p = rho_f g). */
enum { NX = 4, NY = 4, NZ = 20 };
static const double RHO_F = 10.0, NU = 1e-5, G = 9.81, CELL_VOLUME = 1.25e-7;   /* [m^3] */
typedef struct session {
    char dir[256];
    coupling *c;
    int nc;
    double (*U)[3], (*gp)[3];
} session;

static void session_open(session *t, const char *name, const char *model, const char *interp)
{
    snprintf(t->dir, sizeof t->dir, "/tmp/cpl_session_%s_%d", name, (int)getpid());
    write_case(t->dir, model, interp);
    cpl_mesh m;
    const double lo[3] = {-0.01, -0.01, 0.0}, hi[3] = {0.01, 0.01, 0.1};
    cpl_mesh_box(&m, lo, hi, NX, NY, NZ);
    t->nc = m.ncells;
    t->c = coupling_create(t->dir, &m, RHO_F, NU, 1e-4, 0.0);
    t->U = calloc((size_t)t->nc, sizeof *t->U);
    t->gp = calloc((size_t)t->nc, sizeof *t->gp);
    for (int k = 0; k < t->nc; k++) t->gp[k][2] = -RHO_F * G;
}

static void session_close(session *t)
{
    coupling_free(t->c);
    free(t->U);
    free(t->gp);
    char cmd[300];
    snprintf(cmd, sizeof cmd, "rm -rf %s", t->dir);
    if (system(cmd) != 0) perror("rm");
}

/* What the fluid receives from the last exchange with its velocity t->U, the z component of
 * sum over cells of V_c (K_sl (up - U) + S) [N]. */
static double received_z(const session *t)
{
    const double *ksl = coupling_ksl(t->c), (*up)[3] = coupling_particle_velocity(t->c);
    const double (*S)[3] = coupling_explicit_source(t->c);
    double sum = 0.0;
    for (int k = 0; k < t->nc; k++) sum += (ksl[k] * (up[k][2] - t->U[k][2]) + S[k][2]) * CELL_VOLUME;
    return sum;
}

static void settle(const char *model, const char *interp)
{
    session t;
    session_open(&t, model, model, interp);
    double v[3], x[3], fluid_z = 0.0;
    for (int step = 0; step < 1500; step++) {   /* 0.15 s: about 9 relaxation times */
        coupling_evolve(t.c, (const double (*)[3])t.U, (const double (*)[3])t.gp);
        fluid_z = received_z(&t);
    }
    coupling_particle_means(t.c, v, x);
    char what[96];
    snprintf(what, sizeof what, "model %s, %s: terminal velocity vs Schiller-Naumann", model, interp);
    check_rel(what, -v[2], 0.1373, 0.01);
    /* At terminal velocity the fluid force on the sphere carries its weight. The fluid receives
     * the reaction of the exchanged part: model B drag + buoyancy = m g; model A the drag only,
     * (m - rho_f V) g (its buoyancy, -V grad p, is in the fluid equation's alpha grad p). */
    const double vol = M_PI / 6.0 * 1e-12, mass = 3000.0 * vol;
    const double expected = -(model[0] == 'B' ? mass : mass - RHO_F * vol) * G;
    snprintf(what, sizeof what, "model %s, %s: force on the fluid at terminal velocity [N]", model, interp);
    check_rel(what, fluid_z, expected, 1e-3);
    session_close(&t);
}

/* A body of two spheres 1 mm apart (seed 004's multisphere, sphereSum): each sphere feels the
 * drag and buoyancy of its own cell, the body sums them, so it settles at the single sphere's
 * terminal velocity (1 %), and the fluid receives the body's whole weight (model B, 1e-3). */
static void settle_body(void)
{
    with_body = 1;
    session t;
    session_open(&t, "body", "B", "cell");
    double fluid_z = 0.0;
    for (int step = 0; step < 1500; step++) {
        coupling_evolve(t.c, (const double (*)[3])t.U, (const double (*)[3])t.gp);
        fluid_z = received_z(&t);
    }
    double v[3], x[3];
    coupling_particle_means(t.c, v, x);   /* the mean over the two spheres */
    check_true("body of two spheres: two particles", coupling_particle_count(t.c) == 2);
    check_rel("body of two spheres 10 d apart: terminal velocity vs the single sphere's (Schiller-Naumann)", -v[2],
              0.1373, 0.01);
    const double vol = M_PI / 6.0 * 1e-12, mass = 2 * 3000.0 * vol;
    check_rel("body of two spheres: force on the fluid at terminal velocity = its weight [N]", fluid_z, -mass * G, 1e-3);
    session_close(&t);
    with_body = 0;
}

static void jitter(void)
{
    session t;
    session_open(&t, "jitter", "B", "cell");
    double felt = 0.0, received = 0.0, fluid[3], walls[3];
    for (int step = 0; step < 1500; step++) {
        for (int k = 0; k < t.nc; k++) t.U[k][2] = 0.1 + (step % 2 ? 0.05 : -0.05);
        if (step >= 500) received += received_z(&t);   /* step-1's exchange, with the U it solved */
        coupling_evolve(t.c, (const double (*)[3])t.U, (const double (*)[3])t.gp);
        coupling_particle_forces(t.c, fluid, walls);
        if (step >= 500) felt += fluid[2];   /* from the particle settled in the mean flow */
    }
    /* the last exchange's counterpart is not felt yet: drop it from neither side, both sums
     * cover steps 500..1499 (received for the exchanges of steps 499..1498) */
    check_rel("jittering field: force felt by the particle over 1000 fluid steps vs received by the fluid",
              felt, -received, 1e-4);
    session_close(&t);
}

int main(void)
{
    jitter();
    settle("B", "cell");
    settle("A", "cell");
    settle("B", "cellPoint");   /* grad p interpolated: uniform here, so the same result */
    settle("B", "cellLinear");
    settle_body();
    return finish("test_session");
}
