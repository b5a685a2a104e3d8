/* The reduction hook (dem/src/reduce.h): without a hook every reduction is the identity; with
 * one, the DEM's global decisions take the other ranks' values. A hook here stands for a second
 * rank holding fixed values (what an MPI_Allreduce over two ranks would combine):
 *  1. any, sum, min, max element by element, doubles and int64s;
 *  2. the time-step check of a case of 2 mm particles, when the other rank holds a 1 mm one
 *     (its material's smallest radius is the other rank's): the Rayleigh time of 1 mm particles
 *     (== that of a case of 1 mm particles, which has the same material);
 *  3. the default maxExpectedVelocity takes the other rank's fastest particle. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "case.h"
#include "case_files.h"
#include "harness.h"
#include "reduce.h"
#include "timestep.h"

typedef struct other_rank { double d[4]; int64_t i[4]; } other_rank;

static double combine(double a, double b, enum dem_reduce_op op)
{
    return op == DEM_REDUCE_SUM ? a + b : op == DEM_REDUCE_MIN ? fmin(a, b) : fmax(a, b);
}

static void two_ranks_doubles(double *v, int n, enum dem_reduce_op op, void *context)
{
    const other_rank *o = context;
    for (int k = 0; k < n; k++) v[k] = combine(v[k], o->d[k < 4 ? k : 3], op);
}

static void two_ranks_int64s(int64_t *v, int n, enum dem_reduce_op op, void *context)
{
    const other_rank *o = context;
    for (int k = 0; k < n; k++) {
        const int64_t b = o->i[k < 4 ? k : 3];
        v[k] = op == DEM_REDUCE_SUM ? v[k] + b : op == DEM_REDUCE_MIN ? (v[k] < b ? v[k] : b) : (v[k] > b ? v[k] : b);
    }
}

static const char *text =
    "timeStep 1e-7; endTime 0; gravity (0 0 0);\n"
    "domain { min (-0.02 -0.02 0); max (0.02 0.02 0.04); }\n"
    "materials { glass { youngsModulus 1e8; poissonsRatio 0.35; density 2500; } }\n"
    "contactModels { normal hertz; tangential history; }\n"
    "interactions { default { restitution 0.9; friction 0.3; } }\n"
    "insertion { a { region { type box; min (-0.02 -0.02 0); max (0.02 0.02 0.02); } number 20; material glass;\n"
    "  diameter { distribution constant; value %g; } velocity (0 0 %g); seed 1; } }\n";

static void read_case(dem_system *s, const char *dir, double d, double v)
{
    char t[4096];
    snprintf(t, sizeof t, text, d, v);
    write_text(dir, "constant/demProperties", t);
    dem_run_settings rs;
    dem_system_init(s);
    dem_case_read(dir, s, &rs, 0);
}

int main(void)
{
    /* 1 */
    double v[2] = {1.0, 5.0};
    int64_t w[2] = {3, 9};
    dem_reduce_doubles(v, 2, DEM_REDUCE_SUM);
    dem_reduce_int64s(w, 2, DEM_REDUCE_MAX);
    check_true("no hook: reductions leave their values", v[0] == 1.0 && v[1] == 5.0 && w[0] == 3 && w[1] == 9 &&
               dem_reduce_any(0) == 0 && dem_reduce_any(7) == 1);
    other_rank o = {{2.0, 4.0, 0.0, 0.0}, {1, 12, 0, 0}};
    const dem_reduce_hook hook = {two_ranks_doubles, two_ranks_int64s, &o};
    dem_set_reduce_hook(&hook);
    double s[2] = {1.0, 5.0}, mn[2] = {1.0, 5.0}, mx[2] = {1.0, 5.0};
    dem_reduce_doubles(s, 2, DEM_REDUCE_SUM);
    dem_reduce_doubles(mn, 2, DEM_REDUCE_MIN);
    dem_reduce_doubles(mx, 2, DEM_REDUCE_MAX);
    int64_t iw[2] = {3, 9};
    dem_reduce_int64s(iw, 2, DEM_REDUCE_MAX);
    check_true("two ranks: sum, min, max element by element", s[0] == 3.0 && s[1] == 9.0 && mn[0] == 1.0 &&
               mn[1] == 4.0 && mx[0] == 2.0 && mx[1] == 5.0 && iw[0] == 3 && iw[1] == 12);
    o.i[0] = 1;
    check_true("two ranks: any is set when only the other rank's flag is", dem_reduce_any(0) == 1);
    o.i[0] = 0;
    check_true("two ranks: any is clear when neither flag is", dem_reduce_any(0) == 0);

    /* 2, 3: cases read without the hook, then the checks with it */
    dem_set_reduce_hook(NULL);
    char dir[512];
    scratch_case("test_reduce", dir, sizeof dir);
    dem_system big, small;
    read_case(&big, dir, 0.002, 0.5);
    read_case(&small, dir, 0.001, 0.5);
    const double alone = dem_timestep_limits_compute(&big, 1.0).rayleigh_time;
    const double fastest_alone = dem_case_default_max_velocity(&big);
    o.d[0] = 0.0005;   /* the other rank's smallest glass radius, and (below) its fastest particle */
    dem_set_reduce_hook(&hook);
    const double with_other = dem_timestep_limits_compute(&big, 1.0).rayleigh_time;
    o.d[0] = 3.0;
    const double fastest = dem_case_default_max_velocity(&big);
    dem_set_reduce_hook(NULL);
    const double small_alone = dem_timestep_limits_compute(&small, 1.0).rayleigh_time;
    printf("      Rayleigh time: 2 mm alone %.6g s, with a 1 mm particle on the other rank %.6g s, 1 mm case %.6g s\n",
           alone, with_other, small_alone);
    check_true("time-step check: the other rank's smaller particle sets the Rayleigh time (== a 1 mm case)",
               with_other == small_alone && with_other < alone);
    printf("      default maxExpectedVelocity: alone %.6g m/s, with a particle of 3 m/s on the other rank %.6g m/s\n",
           fastest_alone, fastest);
    check_true("default maxExpectedVelocity: the other rank's fastest particle (3 m/s, the domain has no gravity)",
               fabs(fastest - 3.0) < 1e-12 && fabs(fastest_alone - 0.5) < 1e-12);
    dem_system_free(&big);
    dem_system_free(&small);
    remove_case(dir);
    return finish("test_reduce");
}
