/* Coarse graining in the DEM (docs/models/coarse_graining.md), through dem_case_read as demRun
 * reads a case:
 *  1. coarseGraining cg scales every diameter a case gives (constant, uniform, discrete, a file's
 *     column) by cg, exactly, and the parcel's mass is rho pi (cg d)^3 / 6 = cg^3 primary masses
 *     (relative 1e-15);
 *  2. the time-step check sees the parcel: its Rayleigh and contact times equal those of a
 *     case without coarse graining whose particles have the parcel's diameter (==);
 *  3. Bierwisch et al. (2009)'s similarity: a parcel of cg = 3 (same material) impacting a wall
 *     or a parcel, head-on and obliquely, leaves with the particle's restitution, tangential
 *     velocity and omega r (hertz and hooke with tangential history; steps per contact time
 *     the same, so only round-off differs: 1e-9 relative);
 *  4. what does not hold is refused with the key: jkr, dmt, edinburgh, cdtJkr, multisphere
 *     templates; coarseGraining below 1;
 *  5. a restart keeps the parcels: the snapshot carries cg, and a case with another cg is
 *     refused with the message. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "case.h"
#include "case_files.h"
#include "catch_fatal.h"
#include "harness.h"
#include "impact.h"
#include "io.h"
#include "restart.h"
#include "timestep.h"

static const char *head =
    "timeStep 1e-6; endTime 0; gravity (0 0 -9.81); %s\n"
    "domain { min (-0.02 -0.02 0); max (0.02 0.02 0.04); }\n"
    "materials { glass { youngsModulus 1e8; poissonsRatio 0.35; density 2500; } }\n"
    "contactModels { %s }\n"
    "interactions { default { restitution 0.9; friction 0.3; %s } }\n"
    "%s\n";

static void read_case(dem_system *s, const char *dir, const char *cg, const char *models, const char *pair,
                      const char *rest, int skip_insertion)
{
    char text[8192];
    snprintf(text, sizeof text, head, cg, models, pair, rest);
    write_text(dir, "constant/demProperties", text);
    dem_run_settings rs;
    dem_system_init(s);
    dem_case_read(dir, s, &rs, skip_insertion);
}

static const char *hertz = "normal hertz; tangential history;";

static void diameters(const char *dir)
{
    write_text(dir, "constant/points.dat", "0 0 0.03 0.001\n0.01 0 0.03 0.0015\n");
    const char *ins =
        "insertion {\n"
        "  a { region { type box; min (-0.02 -0.02 0); max (0.02 0.02 0.02); } number 40; material glass;\n"
        "      diameter { distribution constant; value 0.001; } seed 1; }\n"
        "  b { region { type box; min (-0.02 -0.02 0.02); max (0.02 0.02 0.028); } number 20; material glass;\n"
        "      diameter { distribution uniform; min 0.0008; max 0.0012; } seed 2; }\n"
        "  c { region { type box; min (-0.02 -0.02 0.02); max (0.02 0.02 0.028); } number 20; material glass;\n"
        "      diameter { distribution discrete; values (0.0005 0.001); weights (1 1); } seed 3; }\n"
        "  f { method file; file \"points.dat\"; material glass; }\n"
        "}";
    dem_system one, two;
    read_case(&one, dir, "", hertz, "", ins, 0);
    read_case(&two, dir, "coarseGraining 2;", hertz, "", ins, 0);
    check_true("cg = 2: as many parcels as the case asks for particles (80 + 2 from the file)",
               one.p.n == 82 && two.p.n == 82);
    /* sizes: a's are all 2 mm; b's within [1.6, 2.4] mm; c's 1 or 2 mm; the file's 2 and 3 mm */
    int a_ok = 1, b_ok = 1, c_ok = 1, f_ok = 0;
    double worst_mass = 0.0;
    for (int i = 0; i < two.p.n; i++) {
        const double d = 2.0 * two.p.radius[i];
        if (i < 40) a_ok &= d == 0.002;
        else if (i < 60) b_ok &= d >= 0.0016 && d <= 0.0024;
        else if (i < 80) c_ok &= d == 0.001 || d == 0.002;
        else f_ok += (i == 80 && d == 0.002) || (i == 81 && d == 0.003);
        const double dp = d / 2.0, m1 = 2500.0 * M_PI / 6.0 * dp * dp * dp;
        worst_mass = fmax(worst_mass, fabs(two.p.mass[i] / (8.0 * m1) - 1.0));
    }
    check_true("cg = 2: constant 1 mm -> 2 mm exactly", a_ok);
    check_true("cg = 2: uniform [0.8, 1.2] mm -> [1.6, 2.4] mm", b_ok);
    check_true("cg = 2: discrete (0.5 1) mm -> (1 2) mm exactly", c_ok);
    check_true("cg = 2: file column 4 (1, 1.5 mm) -> 2, 3 mm exactly", f_ok == 2);
    check_below("cg = 2: parcel mass / (8 primary masses) - 1", worst_mass, 1e-15);

    /* the time-step check: the same limits as a case of 2 mm particles */
    const char *big =
        "insertion { a { region { type box; min (-0.02 -0.02 0); max (0.02 0.02 0.02); } number 40; material glass;\n"
        "  diameter { distribution constant; value 0.002; } seed 1; } }";
    const char *small =
        "insertion { a { region { type box; min (-0.02 -0.02 0); max (0.02 0.02 0.02); } number 40; material glass;\n"
        "  diameter { distribution constant; value 0.001; } seed 1; } }";
    dem_system ref, par;
    read_case(&ref, dir, "", hertz, "", big, 0);
    read_case(&par, dir, "coarseGraining 2;", hertz, "", small, 0);
    const dem_timestep_limits lr = dem_timestep_limits_compute(&ref, 1.0), lp = dem_timestep_limits_compute(&par, 1.0);
    printf("      Rayleigh time: 2 mm particles %.6g s, 1 mm at cg 2 %.6g s; contact time %.6g s, %.6g s\n",
           lr.rayleigh_time, lp.rayleigh_time, lr.contact_time, lp.contact_time);
    check_true("time-step check at cg = 2 sees the parcel: Rayleigh and contact times of 2 mm particles (==)",
               lr.rayleigh_time == lp.rayleigh_time && lr.contact_time == lp.contact_time);
    dem_system_free(&one); dem_system_free(&two); dem_system_free(&ref); dem_system_free(&par);
}

static void similarity(void)
{
    double worst = 0.0;
    for (int normal = 0; normal < 2; normal++)
        for (int wall = 0; wall < 2; wall++) {
            impact_spec sp = {.E = 1e8, .nu = 0.3, .rho = 2500, .r = 5e-4, .e = 0.7, .mu = 0.3,
                              .normal = normal ? normal_hooke : normal_hertz, .tangential = tangential_history,
                              .v_char = 1.0, .wall = wall, .vn = 1.0, .vt = 0.4, .steps_per_contact = 60};
            const impact_result a = run_impact(&sp);
            sp.r *= 3.0;
            const impact_result b = run_impact(&sp);
            const double d[3] = {fabs(b.restitution / a.restitution - 1.0), fabs(b.vt_after / a.vt_after - 1.0),
                                 fabs(b.omega_after * 3.0 / a.omega_after - 1.0)};
            printf("      %s %s: e %.9f / %.9f, vt %.9f / %.9f m/s, omega r %.9f / %.9f m/s\n",
                   normal ? "hooke" : "hertz", wall ? "wall" : "pair", a.restitution, b.restitution, a.vt_after,
                   b.vt_after, a.omega_after * 5e-4, b.omega_after * 15e-4);
            for (int k = 0; k < 3; k++) worst = fmax(worst, d[k]);
        }
    check_below("cg = 3 parcel against particle: restitution, vt, omega r (hertz/hooke, wall/pair), relative", worst, 1e-9);
}

static void refusals(const char *dir)
{
    const char *none = "";
    struct { const char *models, *pair, *rest, *text; } cases[] = {
        {"normal jkr; tangential history;", "workOfAdhesion 0.01;", "", "the normal model 'jkr' does not hold"},
        {"normal dmt; tangential history;", "workOfAdhesion 0.01;", "", "the normal model 'dmt' does not hold"},
        {"normal edinburgh; tangential history;", "unloadingRatio 5;", "", "the normal model 'edinburgh' does not hold"},
        {"normal jkr; tangential history; rolling cdtJkr;", "workOfAdhesion 0.01; adhesionHysteresis 0.5;", "",
         "does not hold"},
        {"normal hertz; tangential history;", "",
         "multisphere { dumbbell { material glass; centres ((0 0 -0.0005) (0 0 0.0005)); radii (0.0005 0.0005); } }",
         "multisphere templates are not coarse-grained"},
    };
    volatile int ok = 1;   /* kept across the jumps back */
    for (volatile size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        volatile int stops;
        dem_system s;
        STOPS_WITH(stops, read_case(&s, dir, "coarseGraining 2;", cases[k].models, cases[k].pair, cases[k].rest, 0),
                   cases[k].text);
        ok &= stops && strstr(caught_text, "coarseGraining") != NULL && strstr(caught_where, "demProperties:1") != NULL;
    }
    check_true("cg = 2 refused with jkr, dmt, edinburgh, jkr + cdtJkr, multisphere (key, file:line named)", ok);
    volatile int low;
    dem_system s;
    STOPS_WITH(low, read_case(&s, dir, "coarseGraining 0.5;", hertz, none, none, 0), "coarseGraining");
    check_true("coarseGraining 0.5 refused", low);
    /* what holds: the cohesion, rolling and surface models that scale with the contact forces */
    volatile int holds;
    STOPS_WITH(holds, read_case(&s, dir, "coarseGraining 2;",
                                "normal hertz; tangential history; cohesion sjkr; rolling epsd; surface roughness; "
                                "roughness { distribution normal; stdDev 0.05; }",
                                "cohesionEnergyDensity 1e4; rollingFriction 0.1;", none, 0), "");
    check_true("cg = 2 accepted with hertz, history, sjkr, epsd, roughness", !holds);
    if (!holds) dem_system_free(&s);
}

static void restart(const char *dir)
{
    const char *ins =
        "insertion { a { region { type box; min (-0.02 -0.02 0); max (0.02 0.02 0.02); } number 30; material glass;\n"
        "  diameter { distribution constant; value 0.001; } seed 1; } }";
    dem_system s;
    read_case(&s, dir, "coarseGraining 3;", hertz, "", ins, 0);
    dem_system_setup(&s);
    char base[4300];
    snprintf(base, sizeof base, "%s/particles", dir);
    dem_particle_writer *w = dem_io_open_writer(base, 0);
    dem_contact_state cs;
    memset(&cs, 0, sizeof cs);
    dem_restart_save_contacts(&s, &cs);
    dem_io_write_snapshot_contacts(w, &s.p, s.time, s.step, &cs);
    dem_io_close_writer(w);
    dem_contact_state_free(&cs);

    dem_system same, other;
    read_case(&same, dir, "coarseGraining 3;", hertz, "", ins, 1);
    dem_contact_state back;
    memset(&back, 0, sizeof back);
    const int found = dem_restart_read(&same, base, NAN, 0.0, &back) == 0;
    int equal = found && same.p.n == s.p.n;
    for (int i = 0; equal && i < s.p.n; i++) equal &= same.p.radius[i] == s.p.radius[i] && same.p.mass[i] == s.p.mass[i];
    check_true("restart at the same cg: the parcels' radii and masses back exactly", equal && back.coarse_graining == 3.0);
    dem_contact_state_free(&back);
    read_case(&other, dir, "", hertz, "", ins, 1);
    memset(&back, 0, sizeof back);
    volatile int stops;
    STOPS_WITH(stops, dem_restart_read(&other, base, NAN, 0.0, &back), "written with coarseGraining 3, but the case now has 1");
    check_true("restart with another cg refused", stops);
    dem_system_free(&s);
    dem_system_free(&same);
}

int main(void)
{
    char dir[256];
    scratch_case("test_coarse_graining", dir, sizeof dir);
    diameters(dir);
    similarity();
    refusals(dir);
    restart(dir);
    remove_case(dir);
    return finish("test_coarse_graining");
}
