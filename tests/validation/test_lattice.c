/* Lattice insertion (dem/src/insert_lattice.c), through dem_case_read as demRun reads a case:
 *  1. DPMFoam's Goldschmidt bed: region (-0.0075 -0.075 0) .. (0.0075 0.075 0.297), spacing
 *     0.003 m gives 24,750 points equal, in order, to x = -0.006 + 0.003 i, y = -0.0735 + 0.003 j,
 *     z = 0.0015 + 0.003 k (i fastest; 1e-12 m), and equal to the tutorial's own
 *     constant/kinematicCloudPositions.gz when it is installed (decompressed with gzip -dc, read
 *     by the file insertion; skipped otherwise);
 *  2. `number` fills from the bottom: 1000 points are the lowest four z layers (gravity -z);
 *     with gravity -y, 600 points are the whole lowest y layer (495) and 105 of the next;
 *  3. a vector spacing (0.003 0.004 0.005): n_k = floor(L_k / s_k) per direction, centred;
 *  4. a cylinder region: the points of the centred square lattice whose sphere lies inside,
 *     the same set as a brute-force count here (exact);
 *  5. a uniform size distribution with max diameter = spacing: all in range, none overlapping. */
#include <stdlib.h>

#include "case.h"
#include "case_files.h"
#include "harness.h"

static const char *head =
    "timeStep 1e-5; endTime 0; gravity %s;\n"
    "domain { min (-0.0075 -0.075 0); max (0.0075 0.075 0.45); }\n"
    "materials { glass { youngsModulus 1e8; poissonsRatio 0.35; density 2526; } }\n"
    "contactModels { normal hertz; tangential history; }\n"
    "interactions { default { restitution 0.97; friction 0.09; } }\n"
    "walls { front { type symmetryPlane; point (-0.0075 0 0); normal (1 0 0); }\n"
    "        back  { type symmetryPlane; point (0.0075 0 0); normal (-1 0 0); }\n"
    "        floor { type plane; point (0 0 0); normal (0 0 1); material glass; } }\n"
    "insertion { bed { %s material glass; diameter { %s } } }\n";

static void read_case(dem_system *s, const char *gravity, const char *entry, const char *diameter)
{
    char dir[256], text[4096];
    scratch_case("test_lattice", dir, sizeof dir);
    snprintf(text, sizeof text, head, gravity, entry, diameter);
    write_text(dir, "constant/demProperties", text);
    dem_run_settings rs;
    dem_system_init(s);
    dem_case_read(dir, s, &rs, 0);
    remove_case(dir);
}

static const char *dpm_entry =
    "method lattice; region { type box; min (-0.0075 -0.075 0); max (0.0075 0.075 0.297); } spacing 0.003;";
static const char *d25 = "distribution constant; value 0.0025;";

/* Largest distance of s's particle k from DPMFoam's point k. */
static double dpm_error(const dem_system *s)
{
    double worst = 0.0;
    for (int k = 0; k < s->p.n; k++) {
        const int i = k % 5, j = (k / 5) % 50, l = k / 250;
        const double e[3] = {-0.006 + 0.003 * i, -0.0735 + 0.003 * j, 0.0015 + 0.003 * l};
        for (int d = 0; d < 3; d++) worst = fmax(worst, fabs(s->p.x[k][d] - e[d]));
    }
    return worst;
}

static void openfoam_file(const dem_system *lattice)
{
    const char *gz = "/usr/share/doc/openfoam-examples/examples/lagrangian/DPMFoam/Goldschmidt/constant/"
                     "kinematicCloudPositions.gz";
    if (access(gz, R_OK) != 0) {
        printf("SKIP the tutorial's kinematicCloudPositions.gz is not installed (%s)\n", gz);
        return;
    }
    char dir[256], cmd[1024], entry[512];
    scratch_case("test_lattice_of", dir, sizeof dir);
    snprintf(cmd, sizeof cmd, "gzip -dc '%s' > '%s/constant/kinematicCloudPositions' 2>/dev/null", gz, dir);
    if (system(cmd) != 0) {
        printf("SKIP gzip could not decompress %s\n", gz);
        remove_case(dir);
        return;
    }
    snprintf(entry, sizeof entry, "method file; file \"kinematicCloudPositions\";");
    char text[4096];
    snprintf(text, sizeof text, head, "(0 0 -9.81)", entry, d25);
    write_text(dir, "constant/demProperties", text);
    dem_system s;
    dem_run_settings rs;
    dem_system_init(&s);
    dem_case_read(dir, &s, &rs, 0);
    remove_case(dir);
    double worst = 0.0;
    const int same_n = s.p.n == lattice->p.n;
    for (int k = 0; same_n && k < s.p.n; k++)
        for (int d = 0; d < 3; d++) worst = fmax(worst, fabs(s.p.x[k][d] - lattice->p.x[k][d]));
    printf("kinematicCloudPositions: %d positions, largest difference from the lattice %.3g m\n", s.p.n, worst);
    check_true("DPMFoam's own file: 24,750 positions", s.p.n == 24750);
    check_true("DPMFoam's own file: the lattice's points, in order (1e-12 m)", same_n && worst <= 1e-12);
    dem_system_free(&s);
}

int main(void)
{
    { /* 1. */
        dem_system s;
        read_case(&s, "(0 0 -9.81)", dpm_entry, d25);
        const double err = dpm_error(&s);
        printf("Goldschmidt lattice: %d points, largest difference from DPMFoam's %.3g m\n", s.p.n, err);
        check_true("Goldschmidt lattice: 24,750 points (5 x 50 x 99)", s.p.n == 24750);
        check_true("Goldschmidt lattice: DPMFoam's positions in DPMFoam's order (1e-12 m)", err <= 1e-12);
        int d_ok = 1, v_ok = 1;
        for (int i = 0; i < s.p.n; i++) {
            d_ok &= s.p.radius[i] == 0.00125 && s.p.type[i] == 0;
            v_ok &= s.p.v[i][0] == 0 && s.p.v[i][1] == 0 && s.p.v[i][2] == 0;
        }
        check_true("Goldschmidt lattice: diameter 0.0025 m, material glass, at rest", d_ok && v_ok);
        openfoam_file(&s);
        dem_system_free(&s);
    }
    { /* 2. from the bottom */
        char entry[512];
        snprintf(entry, sizeof entry, "%s number 1000;", dpm_entry);
        dem_system s;
        read_case(&s, "(0 0 -9.81)", entry, d25);
        double zmax = 0.0;
        for (int i = 0; i < s.p.n; i++) zmax = fmax(zmax, s.p.x[i][2]);
        check_true("number 1000, gravity -z: 1000 points, DPMFoam's first 1000 (1e-12 m)",
                   s.p.n == 1000 && dpm_error(&s) <= 1e-12);
        check_true("number 1000, gravity -z: the lowest four layers (z <= 0.0105 m)", zmax < 0.0105 + 1e-12);
        dem_system_free(&s);
        snprintf(entry, sizeof entry, "%s number 600;", dpm_entry);
        read_case(&s, "(0 -9.81 0)", entry, d25);
        int first = 0, second = 0, other = 0;
        for (int i = 0; i < s.p.n; i++) {
            if (fabs(s.p.x[i][1] + 0.0735) < 1e-12) first++;
            else if (fabs(s.p.x[i][1] + 0.0705) < 1e-12) second++;
            else other++;
        }
        printf("number 600, gravity -y: %d in the lowest y layer, %d in the next, %d elsewhere\n", first, second, other);
        check_true("number 600, gravity -y: 495 + 105 in the two lowest y layers", s.p.n == 600 && first == 495 &&
                   second == 105 && other == 0);
        dem_system_free(&s);
    }
    { /* 3. vector spacing */
        dem_system s;
        read_case(&s, "(0 0 -9.81)",
                  "method lattice; region { type box; min (-0.0075 -0.075 0); max (0.0075 0.075 0.1); } "
                  "spacing (0.003 0.004 0.005);", d25);
        /* n = floor(0.015/0.003) = 5, floor(0.15/0.004) = 37, floor(0.1/0.005) = 20 */
        const int n[3] = {5, 37, 20};
        const double sp[3] = {0.003, 0.004, 0.005}, mid[3] = {0, 0, 0.05};
        double worst = 0.0;
        for (int k = 0; k < s.p.n && s.p.n == 5 * 37 * 20; k++) {
            const int idx[3] = {k % 5, (k / 5) % 37, k / (5 * 37)};
            for (int d = 0; d < 3; d++)
                worst = fmax(worst, fabs(s.p.x[k][d] - (mid[d] + (idx[d] - 0.5 * (n[d] - 1)) * sp[d])));
        }
        check_true("spacing (0.003 0.004 0.005): 5 x 37 x 20 centred points (1e-12 m)", s.p.n == 3700 && worst <= 1e-12);
        dem_system_free(&s);
    }
    { /* 4. cylinder */
        dem_system s;
        read_case(&s, "(0 0 -9.81)",
                  "method lattice; region { type cylinder; axis z; centre (0 0.01); radius 0.0074; axialMin 0.001; "
                  "axialMax 0.031; } spacing 0.003;", d25);
        /* across: n = floor(0.0148 / 0.003) = 4 points per direction, at (i - 1.5) 0.003 from the
         * axis; along: floor(0.03 / 0.003) = 10; keep rho + 0.00125 <= 0.0074 */
        int expected = 0, found = 0;
        for (int l = 0; l < 10; l++)
            for (int j = 0; j < 4; j++)
                for (int i = 0; i < 4; i++) {
                    const double x = (i - 1.5) * 0.003, y = 0.01 + (j - 1.5) * 0.003, z = 0.016 + (l - 4.5) * 0.003;
                    if (hypot(x, y - 0.01) + 0.00125 > 0.0074) continue;
                    expected++;
                    for (int k = 0; k < s.p.n; k++)
                        if (fabs(s.p.x[k][0] - x) < 1e-12 && fabs(s.p.x[k][1] - y) < 1e-12 && fabs(s.p.x[k][2] - z) < 1e-12) {
                            found++;
                            break;
                        }
                }
        printf("cylinder: %d points, %d expected, %d of them found\n", s.p.n, expected, found);
        check_true("cylinder: the lattice points whose sphere is inside, exactly", s.p.n == expected && found == expected && expected > 0);
        dem_system_free(&s);
    }
    { /* 5. size distribution up to the spacing */
        dem_system s;
        read_case(&s, "(0 0 -9.81)", dpm_entry, "distribution uniform; min 0.002; max 0.003;");
        int in_range = 1;
        double dmin = 1, dmax = 0;
        for (int i = 0; i < s.p.n; i++) {
            const double d = 2 * s.p.radius[i];
            in_range &= d >= 0.002 && d <= 0.003;
            dmin = fmin(dmin, d);
            dmax = fmax(dmax, d);
        }
        printf("uniform 0.002-0.003 m at spacing 0.003 m: diameters %.4g .. %.4g m\n", dmin, dmax);
        check_true("uniform diameters up to the spacing: 24,750, all in [0.002, 0.003] m", s.p.n == 24750 && in_range);
        dem_system_free(&s);
    }
    return finish("test_lattice");
}
