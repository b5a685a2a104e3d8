/* Interpolation to particles: cellLinear (least-squares linear reconstruction) reproduces a
 * linear field u = a + B x at random points of a box, a sheared and graded mesh and a polyhedral
 * refined mesh to 1e-10 (boundary cells included); cell gives the cell's value exactly; on a
 * smooth field cellLinear converges at second order and cell at first; a one-cell-thick mesh
 * gives no NaN; outside particles give -1 and 0. */
#include <stdlib.h>

#include "catch_fatal.h"
#include "harness.h"
#include "test_meshes.h"
#include "interpolate.h"
#include "mesh.h"
#include "rng.h"

static const double A[3] = {1.0, -2.0, 0.5};
static const double B[3][3] = {{0.3, -1.2, 2.0}, {0.7, 0.1, -0.4}, {-1.5, 0.9, 0.25}};   /* [1/s] */

static void linear(const double x[3], double u[3])
{
    for (int i = 0; i < 3; i++) u[i] = A[i] + B[i][0] * x[0] + B[i][1] * x[1] + B[i][2] * x[2];
}

static double smooth(const double x[3]) { return sin(2.0 * x[0]) * cos(1.5 * x[1]) + exp(0.5 * x[2]); }

/* Worst error of cellLinear on the linear field and of cell against the cell's own value, at npts
 * random points located in mesh m. */
static void linear_exact(const char *name, const cpl_mesh *m, int npts, unsigned seed)
{
    cpl_interp lin, cel;
    cpl_interp_init(&lin, m, CPL_INTERP_LINEAR, 3);
    cpl_interp_init(&cel, m, CPL_INTERP_CELL, 3);
    double *u = malloc(m->ncells * 3 * sizeof(double));
    for (int c = 0; c < m->ncells; c++) linear(m->cell_centre[c], u + 3 * c);
    cpl_interp_set_field(&lin, m, u);
    cpl_interp_set_field(&cel, m, u);
    dem_rng g;
    rng_seed(&g, seed);
    double worst = 0, worst_cell = 0;
    int found = 0, guess = -1;
    while (found < npts) {
        double x[3];
        for (int d = 0; d < 3; d++) x[d] = m->bounds_min[d] + (m->bounds_max[d] - m->bounds_min[d]) * rng_uniform(&g);
        const int c = cpl_mesh_locate(m, x, guess, NULL);
        if (c < 0) continue;
        guess = c;
        found++;
        double ui[3], ue[3], uc[3];
        cpl_interp_at(&lin, m, c, x, ui);
        cpl_interp_at(&cel, m, c, x, uc);
        linear(x, ue);
        for (int d = 0; d < 3; d++) {
            worst = fmax(worst, fabs(ui[d] - ue[d]));
            worst_cell = fmax(worst_cell, fabs(uc[d] - u[3 * c + d]));
        }
    }
    char what[128];
    printf("%s: cellLinear worst error on u = a + B x: %.3g m/s\n", name, worst);
    snprintf(what, sizeof what, "%s: cellLinear reproduces a + B x (< 1e-10 m/s, |u| ~ 1)", name);
    check_true(what, worst < 1e-10);
    snprintf(what, sizeof what, "%s: cell gives the cell's value exactly", name);
    check_true(what, worst_cell == 0.0);
    free(u);
    cpl_interp_free(&lin);
    cpl_interp_free(&cel);
}

/* Mean error at random points of a smooth field on an n^3 box. */
static void smooth_error(int n, double *err_linear, double *err_cell)
{
    const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
    cpl_mesh m;
    cpl_mesh_box(&m, lo, hi, n, n, n);
    cpl_interp lin, cel;
    cpl_interp_init(&lin, &m, CPL_INTERP_LINEAR, 1);
    cpl_interp_init(&cel, &m, CPL_INTERP_CELL, 1);
    double *u = malloc(m.ncells * sizeof(double));
    for (int c = 0; c < m.ncells; c++) u[c] = smooth(m.cell_centre[c]);
    cpl_interp_set_field(&lin, &m, u);
    cpl_interp_set_field(&cel, &m, u);
    dem_rng g;
    rng_seed(&g, 7);
    *err_linear = *err_cell = 0;
    const int npts = 20000;
    for (int k = 0; k < npts; k++) {
        double x[3], ul, uc;
        for (int d = 0; d < 3; d++) x[d] = rng_uniform(&g);
        const int c = cpl_mesh_locate(&m, x, -1, NULL);
        cpl_interp_at(&lin, &m, c, x, &ul);
        cpl_interp_at(&cel, &m, c, x, &uc);
        *err_linear += fabs(ul - smooth(x)) / npts;
        *err_cell += fabs(uc - smooth(x)) / npts;
    }
    free(u);
    cpl_interp_free(&lin);
    cpl_interp_free(&cel);
    cpl_mesh_free(&m);
}

/* cellPoint on a uniform 6^3 box: a linear field is exact in cells away from the boundary
 * (their points average 8 symmetric cells), 1e-10; the value is continuous across a face:
 * the same point on a shared face seen from both cells agrees to 1e-12; the cell centre gets
 * the cell's own value. */
static void cell_point(void)
{
    cpl_mesh m;
    const double lo[3] = {0, 0, 0}, hi[3] = {1.2, 0.9, 1.5};
    const int n = 6;
    cpl_mesh_box(&m, lo, hi, n, n, n);
    double (*u)[3] = malloc((size_t)m.ncells * sizeof *u);
    for (int c = 0; c < m.ncells; c++) linear(m.cell_centre[c], u[c]);
    cpl_interp ip;
    cpl_interp_init(&ip, &m, CPL_INTERP_CELL_POINT, 3);
    cpl_interp_set_field(&ip, &m, &u[0][0]);
    srand(7);
    double worst = 0.0, worst_jump = 0.0, worst_centre = 0.0;
    for (int c = 0; c < m.ncells; c++) {
        const int i = c % n, j = c / n % n, k = c / (n * n);
        double out[3], ref[3];
        cpl_interp_at(&ip, &m, c, m.cell_centre[c], out);
        for (int q = 0; q < 3; q++) worst_centre = fmax(worst_centre, fabs(out[q] - u[c][q]));
        if (i == 0 || j == 0 || k == 0 || i == n - 1 || j == n - 1 || k == n - 1) continue;
        for (int t = 0; t < 50; t++) {
            double x[3];
            for (int q = 0; q < 3; q++) {
                const double h = (hi[q] - lo[q]) / n;
                x[q] = m.cell_centre[c][q] + h * ((double)rand() / RAND_MAX - 0.5);
            }
            cpl_interp_at(&ip, &m, c, x, out);
            linear(x, ref);
            for (int q = 0; q < 3; q++) worst = fmax(worst, fabs(out[q] - ref[q]));
        }
        /* a point on the face towards +x, from both sides */
        double x[3] = {m.cell_centre[c][0] + 0.5 * (hi[0] - lo[0]) / n, m.cell_centre[c][1] + 0.013, m.cell_centre[c][2] - 0.021};
        double a[3], b[3];
        cpl_interp_at(&ip, &m, c, x, a);
        cpl_interp_at(&ip, &m, c + 1, x, b);
        for (int q = 0; q < 3; q++) worst_jump = fmax(worst_jump, fabs(a[q] - b[q]));
    }
    printf("   cellPoint: worst error %.3g (interior cells), face jump %.3g, centre %.3g\n", worst, worst_jump, worst_centre);
    check_true("cellPoint: linear field exact in interior cells (1e-10)", worst < 1e-10);
    check_true("cellPoint: continuous across faces (1e-12)", worst_jump < 1e-12);
    check_true("cellPoint: the cell centre gets the cell value (1e-12)", worst_centre < 1e-12);
    cpl_interp_free(&ip);
    free(u);
    cpl_mesh_free(&m);
}

/* f at x interpolated by scheme on m (x located, wrapped across cyclic sides) */
static double value_at(const cpl_interp *ip, const cpl_mesh *m, const double x_in[3])
{
    double x[3] = {x_in[0], x_in[1], x_in[2]}, out;
    cpl_mesh_wrap(m, x);
    cpl_interp_at(ip, m, cpl_mesh_locate(m, x, -1, NULL), x, &out);
    return out;
}

/* Cyclic sides (issue 21): on a channel periodic in x, the field f = sin(2 pi x) g(y, z) (period
 * 1 m) and its half-period image -f: cellLinear and cellPoint give at points next to the cyclic
 * faces the negative of their value half a period on (1e-12: they see across the pair as across an
 * interior face), and cellPoint is continuous across the face (a centre carried through it: the
 * values on the two sides 2e-9 m apart agree to 1e-7). Without the pairs both differ, printed. */
static void cyclic_sides(void)
{
    cpl_mesh m, plain;
    cyclic_channel(&m, &plain);
    double *field = malloc((size_t)m.ncells * sizeof *field);
    for (int c = 0; c < m.ncells; c++) {
        const double *x = m.cell_centre[c];
        field[c] = sin(2.0 * M_PI * x[0]) * (1.0 + x[1] + 2.0 * x[2]);
    }
    const enum cpl_interp_scheme schemes[2] = {CPL_INTERP_LINEAR, CPL_INTERP_CELL_POINT};
    const char *names[2] = {"cellLinear", "cellPoint"};
    const double at[4][3] = {{0.01, 0.13, 0.27}, {0.04, 0.31, 0.05}, {0.97, 0.22, 0.18}, {0.995, 0.07, 0.33}};
    for (int k = 0; k < 2; k++) {
        cpl_interp ip, ipp;
        cpl_interp_init(&ip, &m, schemes[k], 1);
        cpl_interp_set_field(&ip, &m, field);
        cpl_interp_init(&ipp, &plain, schemes[k], 1);
        cpl_interp_set_field(&ipp, &plain, field);
        double worst = 0.0, plain_worst = 0.0;
        for (int j = 0; j < 4; j++) {
            const double y[3] = {at[j][0] + 0.5, at[j][1], at[j][2]};
            const double here = value_at(&ip, &m, at[j]), there = value_at(&ip, &m, y);
            worst = fmax(worst, fabs(here + there));
            plain_worst = fmax(plain_worst, fabs(value_at(&ipp, &plain, at[j]) + value_at(&ipp, &plain, y)));
        }
        printf("      %s: largest |f(x) + f(x + L/2)| %.3g next to the cyclic faces; %.3g without the pairs\n", names[k],
               worst, plain_worst);
        char what[120];
        snprintf(what, sizeof what, "cyclic %s: next to the faces as half a period on (f(x) = -f(x + L/2)), 1e-12", names[k]);
        check_true(what, worst <= 1e-12);
        if (schemes[k] == CPL_INTERP_CELL_POINT) {
            const double a[3] = {1.0 - 1e-9, 0.17, 0.23}, b[3] = {1.0 + 1e-9, 0.17, 0.23};
            const double jump = fabs(value_at(&ip, &m, a) - value_at(&ip, &m, b));
            const double plain_jump = fabs(value_at(&ipp, &plain, a) - value_at(&ipp, &plain, (double[3]){1e-9, 0.17, 0.23}));
            printf("      cellPoint: across the cyclic face the value jumps by %.3g (%.3g without the pairs)\n", jump, plain_jump);
            check_true("cyclic cellPoint: continuous across the face (2e-9 m apart: 1e-7)", jump < 1e-7);
        }
        cpl_interp_free(&ip);
        cpl_interp_free(&ipp);
    }
    free(field);
    cpl_mesh_free(&m);
    cpl_mesh_free(&plain);
}

int main(void)
{
    const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
    cpl_mesh m;
    cpl_mesh_box(&m, lo, hi, 8, 6, 7);
    linear_exact("box", &m, 5000, 1);

    /* outside: -1 and zeros */
    {
        cpl_interp lin;
        cpl_interp_init(&lin, &m, CPL_INTERP_LINEAR, 3);
        const int cell[2] = {5, -1};
        const double x[2][3] = {{0.1, 0.1, 0.1}, {2, 2, 2}};
        double out[2][3] = {{9, 9, 9}, {9, 9, 9}};
        double *u = malloc(m.ncells * 3 * sizeof(double));
        for (int c = 0; c < 3 * m.ncells; c++) u[c] = 1.0;
        cpl_interp_set_field(&lin, &m, u);
        const int outside = cpl_interp_particles(&lin, &m, 2, cell, x, (double *)out);
        check_true("outside particle: counted, value 0; inside one: uniform field 1",
                   outside == 1 && out[1][0] == 0 && out[1][2] == 0 && fabs(out[0][1] - 1) < 1e-14);
        free(u);
        cpl_interp_free(&lin);
    }
    cpl_mesh_free(&m);

    cpl_mesh_box(&m, lo, hi, 9, 7, 11);
    cpl_mesh_map_points(&m, shear_grade, NULL);
    linear_exact("skewed", &m, 5000, 2);
    cpl_mesh_free(&m);

    const double hi2[3] = {1, 0.8, 0.8};
    const int rlo[3] = {1, 1, 1}, rhi[3] = {3, 3, 3};
    cpl_mesh_box_refined(&m, lo, hi2, 5, 4, 4, rlo, rhi);
    cpl_mesh_map_points(&m, shear_linear, NULL);
    linear_exact("refined polyhedral", &m, 5000, 3);
    cpl_mesh_free(&m);

    /* one cell thick: the unspanned z direction gets a zero gradient, x and y stay exact */
    {
        const double hi1[3] = {1, 1, 0.1};
        cpl_mesh_box(&m, lo, hi1, 8, 8, 1);
        cpl_interp lin;
        cpl_interp_init(&lin, &m, CPL_INTERP_LINEAR, 1);
        double *u = malloc(m.ncells * sizeof(double));
        for (int c = 0; c < m.ncells; c++) u[c] = 1 + 2 * m.cell_centre[c][0] - 3 * m.cell_centre[c][1];
        cpl_interp_set_field(&lin, &m, u);
        const double x[3] = {0.33, 0.71, 0.02};
        double v;
        cpl_interp_at(&lin, &m, cpl_mesh_locate(&m, x, -1, NULL), x, &v);
        check_true("one cell thick: finite, x-y linear field exact (1e-10)", isfinite(v) && fabs(v - (1 + 0.66 - 2.13)) < 1e-10);
        free(u);
        cpl_interp_free(&lin);
        cpl_mesh_free(&m);
    }

    /* convergence on a smooth field: mean error ratio between h and h/2 */
    {
        double el8, ec8, el16, ec16;
        smooth_error(8, &el8, &ec8);
        smooth_error(16, &el16, &ec16);
        printf("smooth field, mean error: cellLinear %.3g -> %.3g (ratio %.2f), cell %.3g -> %.3g (ratio %.2f)\n",
               el8, el16, el8 / el16, ec8, ec16, ec8 / ec16);
        check_true("cellLinear second order: error ratio h -> h/2 > 3.5", el8 / el16 > 3.5);
        check_true("cell first order: error ratio h -> h/2 in 1.7 .. 2.3", ec8 / ec16 > 1.7 && ec8 / ec16 < 2.3);
        check_true("cellLinear more accurate than cell (8^3)", el8 < 0.2 * ec8);
    }

    /* bad input */
    {
        cpl_interp ip;
        enum cpl_interp_scheme s;
        cpl_mesh_box(&m, lo, hi, 2, 2, 2);
        check_true("scheme names parsed, an unknown one not found",
                   cpl_interp_scheme_parse("cellLinear", &s) == 0 && s == CPL_INTERP_LINEAR &&
                   cpl_interp_scheme_parse("cell", &s) == 0 && s == CPL_INTERP_CELL &&
                   cpl_interp_scheme_parse("cellPoint", &s) == 0 && s == CPL_INTERP_CELL_POINT &&
                   cpl_interp_scheme_parse("cellPointWallModified", &s) == -1);
        int ok;
        STOPS_WITH(ok, cpl_interp_init(&ip, &m, CPL_INTERP_CELL, 0), "interpolation: 0 components per cell (1 .. 64)");
        check_true("0 components: fatal error", ok);
        cpl_mesh_free(&m);
    }
    cell_point();
    cyclic_sides();
    return finish("test_interpolate");
}
