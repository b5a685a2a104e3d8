/* File insertion (dem/src/insert_file.c), through dem_case_read as demRun reads a case. Round trips,
 * compared exactly (==): 400 spheres with random positions, diameters, velocities and materials
 * written with %.17g
 *  1. as 8 columns (x y z d vx vy vz material), with '#' and '//' comments, blank lines and
 *     CRLF line ends, path relative to constant/;
 *  2. as OpenFOAM's vectorField (FoamFile header, count, '(' (x y z) ... ')'), diameter,
 *     velocity and material from the entry; and without header and count, absolute path;
 *  3. lines of 3, 4, 7 and 8 columns in one file: the missing columns from the entry. */
#include <stdlib.h>

#include "case.h"
#include "case_files.h"
#include "harness.h"
#include "rng.h"

#define N 400

typedef struct truth { double x[N][3], v[N][3], d[N]; int m[N]; } truth;

static const char *head =
    "timeStep 1e-5; endTime 0; gravity (0 0 -9.81);\n"
    "domain { min (-0.02 -0.02 0); max (0.02 0.02 0.04); }\n"
    "materials { glass { youngsModulus 1e8; poissonsRatio 0.35; density 2500; }\n"
    "            steel { youngsModulus 2e8; poissonsRatio 0.3; density 7800; } }\n"
    "contactModels { normal hertz; tangential history; }\n"
    "interactions { default { restitution 0.9; friction 0.3; } }\n"
    "walls { floor { type plane; point (0 0 0); normal (0 0 1); material glass; } }\n"
    "insertion { from { method file; %s } }\n";

static void read_case(dem_system *s, const char *dir, const char *entry)
{
    char text[4096];
    snprintf(text, sizeof text, head, entry);
    write_text(dir, "constant/demProperties", text);
    dem_run_settings rs;
    dem_system_init(s);
    dem_case_read(dir, s, &rs, 0);
}

static void make_truth(truth *t)
{
    dem_rng r;
    rng_seed(&r, 3);
    int k = 0;
    for (int c = 0; c < 8; c++)   /* spacing 0.005 m, jitter 0.4 mm, d <= 3 mm: no overlaps */
        for (int b = 0; b < 8; b++)
            for (int a = 0; a < 8 && k < N; a++, k++) {
                const int idx[3] = {a, b, c};
                for (int q = 0; q < 3; q++) {
                    t->x[k][q] = (q == 2 ? 0.0025 : -0.0175) + 0.005 * idx[q] + 0.0008 * (rng_uniform(&r) - 0.5);
                    t->v[k][q] = 2 * rng_uniform(&r) - 1;
                }
                t->d[k] = 0.002 + 0.001 * rng_uniform(&r);
                t->m[k] = rng_uniform(&r) < 0.5;
            }
}

int main(void)
{
    static truth t;
    make_truth(&t);
    static const char *names[2] = {"glass", "steel"};
    char dir[256];
    scratch_case("test_file_insertion", dir, sizeof dir);
    char path[4300];
    { /* 1. columns */
        snprintf(path, sizeof path, "%s/constant/positions.dat", dir);
        FILE *f = fopen(path, "w");
        fprintf(f, "# x y z d vx vy vz material\n\n// a comment line\n");
        for (int k = 0; k < N; k++)
            fprintf(f, "%.17g %.17g\t%.17g  %.17g %.17g %.17g %.17g %s%s%s", t.x[k][0], t.x[k][1], t.x[k][2], t.d[k],
                    t.v[k][0], t.v[k][1], t.v[k][2], names[t.m[k]], k % 7 == 0 ? "   # trailing comment" : "",
                    k % 5 == 0 ? "\r\n" : "\n");
        fclose(f);
        dem_system s;
        read_case(&s, dir, "file \"positions.dat\";");
        int x_eq = s.p.n == N, d_eq = x_eq, v_eq = x_eq, m_eq = x_eq;
        for (int k = 0; k < N && x_eq; k++) {
            for (int q = 0; q < 3; q++) { x_eq &= s.p.x[k][q] == t.x[k][q]; v_eq &= s.p.v[k][q] == t.v[k][q]; }
            d_eq &= 2 * s.p.radius[k] == t.d[k];
            m_eq &= s.p.type[k] == t.m[k];
        }
        check_true("columns: 400 particles, positions exact", x_eq);
        check_true("columns: diameters exact", d_eq);
        check_true("columns: velocities exact", v_eq);
        check_true("columns: materials by name", m_eq);
        dem_system_free(&s);
    }
    for (int variant = 0; variant < 2; variant++) { /* 2. vectorField */
        snprintf(path, sizeof path, variant ? "%s/cloud" : "%s/constant/cloud", dir);
        FILE *f = fopen(path, "w");
        if (variant == 0)
            fprintf(f, "/* banner */\nFoamFile\n{\n    version 2.0;\n    format ascii;\n    class vectorField;\n"
                       "    object kinematicCloudPositions;\n}\n// * * * //\n\n%d\n(\n", N);
        else
            fprintf(f, "(\n");
        for (int k = 0; k < N; k++) fprintf(f, "(%.17g %.17g %.17g)\n", t.x[k][0], t.x[k][1], t.x[k][2]);
        fprintf(f, ")\n\n// ***** //\n");
        fclose(f);
        char entry[4500];
        if (variant == 0)
            snprintf(entry, sizeof entry, "file \"cloud\"; material steel; velocity (0.1 0 -0.2); "
                                          "diameter { distribution constant; value 0.002; }");
        else
            snprintf(entry, sizeof entry, "file \"%s\"; material steel; velocity (0.1 0 -0.2); "
                                          "diameter { distribution constant; value 0.002; }", path);
        dem_system s;
        read_case(&s, dir, entry);
        int x_eq = s.p.n == N, rest = x_eq;
        for (int k = 0; k < N && x_eq; k++) {
            for (int q = 0; q < 3; q++) x_eq &= s.p.x[k][q] == t.x[k][q];
            rest &= s.p.radius[k] == 0.001 && s.p.type[k] == 1 && s.p.v[k][0] == 0.1 && s.p.v[k][1] == 0 &&
                    s.p.v[k][2] == -0.2;
        }
        check_true(variant ? "vectorField, no header, absolute path: positions exact"
                           : "vectorField with FoamFile header and count: positions exact", x_eq);
        check_true(variant ? "vectorField, no header: d, v, material from the entry"
                           : "vectorField with header: d, v, material from the entry", rest);
        dem_system_free(&s);
    }
    { /* 3. mixed column counts */
        snprintf(path, sizeof path, "%s/constant/mixed.dat", dir);
        FILE *f = fopen(path, "w");
        for (int k = 0; k < N; k++) {
            const int cols = (int[]){3, 4, 7, 8}[k % 4];
            fprintf(f, "%.17g %.17g %.17g", t.x[k][0], t.x[k][1], t.x[k][2]);
            if (cols >= 4) fprintf(f, " %.17g", t.d[k]);
            if (cols >= 7) fprintf(f, " %.17g %.17g %.17g", t.v[k][0], t.v[k][1], t.v[k][2]);
            if (cols == 8) fprintf(f, " %s", names[t.m[k]]);
            fprintf(f, "\n");
        }
        fclose(f);
        dem_system s;
        read_case(&s, dir, "file \"mixed.dat\"; material glass; velocity (0 0 -1); "
                           "diameter { distribution constant; value 0.0015; }");
        int ok = s.p.n == N;
        for (int k = 0; k < N && ok; k++) {
            const int cols = (int[]){3, 4, 7, 8}[k % 4];
            const double d = cols >= 4 ? t.d[k] : 0.0015;
            const double v[3] = {cols >= 7 ? t.v[k][0] : 0, cols >= 7 ? t.v[k][1] : 0, cols >= 7 ? t.v[k][2] : -1};
            const int m = cols == 8 ? t.m[k] : 0;
            for (int q = 0; q < 3; q++) ok &= s.p.x[k][q] == t.x[k][q] && s.p.v[k][q] == v[q];
            ok &= 2 * s.p.radius[k] == d && s.p.type[k] == m;
        }
        check_true("3, 4, 7 and 8 columns in one file: given columns exact, the rest from the entry", ok);
        dem_system_free(&s);
    }
    remove_case(dir);
    return finish("test_file_insertion");
}
