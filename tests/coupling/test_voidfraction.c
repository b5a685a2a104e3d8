/* Void fraction: the particle volume is mapped in full (sum over cells of (1 - alpha) V = total
 * particle volume to 1e-12 relative) by centre, divided and gaussian, on a box, a sheared and
 * graded mesh and a polyhedral refined mesh; gaussian conserves at walls; the alphaMin floor is
 * applied; divided splits a sphere straddling a face by the geometric overlap within its sampling
 * error; forces spread with the same weights; particles outside are counted, not dropped
 * silently; bad input is a fatal error with a message naming it. */
#include <stdlib.h>
#include <string.h>

#include "catch_fatal.h"
#include "harness.h"
#include "test_meshes.h"
#include "mesh.h"
#include "rng.h"
#include "voidfraction.h"

static const char *model_name[] = {"centre", "divided", "gaussian"};

static double sphere_volume(double r) { return 4.0 / 3.0 * M_PI * r * r * r; }

/* sum over cells of (1 - alpha) V; *floored = cells at the floor */
static double mapped_volume(const cpl_voidfraction *vf, const cpl_mesh *m, int *floored)
{
    double v = 0;
    *floored = 0;
    for (int c = 0; c < m->ncells; c++) {
        v += (1.0 - vf->alpha[c]) * m->cell_volume[c];
        *floored += vf->alpha[c] <= vf->alpha_min;
    }
    return v;
}

/* np random particles, centres inside the mesh (rejection against locate), radii in [rmin, rmax) */
static int random_particles(const cpl_mesh *m, dem_rng *g, int np, double rmin, double rmax, double (*x)[3], double *r,
                            int *cell)
{
    for (int i = 0; i < np; i++) {
        do {
            for (int d = 0; d < 3; d++)
                x[i][d] = m->bounds_min[d] + (m->bounds_max[d] - m->bounds_min[d]) * rng_uniform(g);
        } while (cpl_mesh_locate(m, x[i], -1, NULL) < 0);
        r[i] = rmin + (rmax - rmin) * rng_uniform(g);
        cell[i] = -1;
    }
    return np;
}

/* Conservation of the three models on mesh m for np particles of radii [rmin, rmax). */
static void conservation(const char *mesh_name, const cpl_mesh *m, int np, double rmin, double rmax, unsigned seed,
                         int first_model)
{
    double (*x)[3] = malloc(np * sizeof *x), *r = malloc(np * sizeof(double));
    int *cell = malloc(np * sizeof(int));
    dem_rng g;
    rng_seed(&g, seed);
    random_particles(m, &g, np, rmin, rmax, x, r, cell);
    double total = 0;
    for (int i = 0; i < np; i++) total += sphere_volume(r[i]);
    for (int model = first_model; model < 3; model++) {
        cpl_voidfraction vf;
        cpl_vf_init(&vf, m, (enum cpl_vf_model)model, 0.05);
        for (int i = 0; i < np; i++) cell[i] = -1;
        const int out = cpl_vf_compute(&vf, m, np, (const double (*)[3])x, r, cell);
        int floored;
        const double mapped = mapped_volume(&vf, m, &floored);
        char what[128];
        snprintf(what, sizeof what, "%s, %s: sum (1-alpha)V = particle volume [m^3], rel. 1e-12", mesh_name, model_name[model]);
        check_rel(what, mapped, total, 1e-12);
        snprintf(what, sizeof what, "%s, %s: none outside, no cell at the floor", mesh_name, model_name[model]);
        check_true(what, out == 0 && floored == 0);
        /* the cells found are the brute-force ones */
        int wrong = 0;
        for (int i = 0; i < np; i++) wrong += !cpl_mesh_inside(m, cell[i], x[i]);
        snprintf(what, sizeof what, "%s, %s: particle cells updated and right", mesh_name, model_name[model]);
        check_true(what, wrong == 0);
        /* a force spread with the same weights: total conserved, and the volume spread = vp */
        double *f = malloc(np * 3 * sizeof(double)), *fc = malloc(m->ncells * 3 * sizeof(double));
        double *vol = malloc(np * sizeof(double)), *vc = malloc(m->ncells * sizeof(double));
        double fsum[3] = {0, 0, 0}, fcsum[3] = {0, 0, 0}, dv = 0;
        for (int i = 0; i < np; i++) {
            for (int d = 0; d < 3; d++) { f[3 * i + d] = (d + 1) * (1.0 + rng_uniform(&g)); fsum[d] += f[3 * i + d]; }
            vol[i] = sphere_volume(r[i]);
        }
        cpl_vf_spread(&vf, 3, f, fc);
        cpl_vf_spread(&vf, 1, vol, vc);
        for (int c = 0; c < m->ncells; c++) {
            for (int d = 0; d < 3; d++) fcsum[d] += fc[3 * c + d];
            dv = fmax(dv, fabs(vc[c] - vf.vp[c]));
        }
        snprintf(what, sizeof what, "%s, %s: spread force, sum over cells [N], rel. 1e-12", mesh_name, model_name[model]);
        check_rel(what, fcsum[2], fsum[2], 1e-12);
        snprintf(what, sizeof what, "%s, %s: spread volume = vp (same weights)", mesh_name, model_name[model]);
        check_true(what, dv == 0.0);
        /* a uniform field gathered at the particles is that value */
        double *uni = malloc(m->ncells * sizeof(double)), *up = malloc(np * sizeof(double)), du = 0;
        for (int c = 0; c < m->ncells; c++) uni[c] = 2.5;
        cpl_vf_gather(&vf, 1, uni, up);
        for (int i = 0; i < np; i++) du = fmax(du, fabs(up[i] - 2.5));
        snprintf(what, sizeof what, "%s, %s: gather of a uniform field (1e-14)", mesh_name, model_name[model]);
        check_true(what, du < 1e-14);
        free(uni); free(up); free(f); free(fc); free(vol); free(vc);
        cpl_vf_free(&vf);
    }
    free(x); free(r); free(cell);
}

/* Fraction of particle i's weight in cells whose centre has coordinate d above `plane`. */
static double weight_above(const cpl_voidfraction *vf, const cpl_mesh *m, int i, int d, double plane)
{
    double w = 0;
    for (int k = vf->w_start[i]; k < vf->w_start[i + 1]; k++)
        if (m->cell_centre[vf->w_cell[k]][d] > plane) w += vf->w[k];
    return w;
}

/* a pure linear shear (no grading) */
static void shear_only(double x[3], void *ctx)
{
    (void)ctx;
    x[0] += 0.3 * x[2];
    x[1] += 0.2 * x[0];
}

/* alpha of one particle at x (radius r) on mesh m with model `model` into alpha[] */
static void one_particle_alpha(const cpl_mesh *m, int model, const double x[3], double r, double *alpha, double *mapped)
{
    cpl_voidfraction vf;
    cpl_vf_init(&vf, m, (enum cpl_vf_model)model, 0.0);
    vf.kernel_width = 1.0;   /* gaussian: s = d, several cells, reach 3 s < half the period */
    int cell = -1, floored;
    cpl_vf_compute(&vf, m, 1, (const double (*)[3])x, &r, &cell);
    memcpy(alpha, vf.alpha, (size_t)m->ncells * sizeof *alpha);
    *mapped = mapped_volume(&vf, m, &floored);
    cpl_vf_free(&vf);
}

/* 6. Cyclic sides (issue 21): a channel periodic in x. For a particle near either cyclic face
 * and one straddling it, each model maps the whole volume (sum (1 - alpha) V = V_p to 1e-12) and
 * gives the alpha field of the same particle half a period away, shifted by those cells (1e-12);
 * a centre carried across the face is located in the cell that continues its path. Without the
 * cyclic pairs the divided and gaussian models put the share beyond the face back into the cells
 * on this side (what CFDEM does and Lethe fixed in 2023): the field then differs, printed. */
static void cyclic_sides(void)
{
    const double lo[3] = {0, 0, 0}, hi[3] = {1, 0.4, 0.4};
    cpl_mesh m, plain;
    const int npairs = cyclic_channel(&m, &plain);
    check_true("cyclic: 16 face pairs, periodic in x with the period 1 m", npairs == 16 && m.periodic[0] &&
               m.period[0] == 1.0 && !m.periodic[1]);
    /* the cell half a period on from each cell */
    int *half = malloc((size_t)m.ncells * sizeof *half);
    for (int c = 0; c < m.ncells; c++) {
        double y[3] = {m.cell_centre[c][0] + 0.5, m.cell_centre[c][1], m.cell_centre[c][2]};
        half[c] = cpl_mesh_locate(&m, y, -1, NULL);
    }
    double *a1 = malloc((size_t)m.ncells * sizeof *a1), *a2 = malloc((size_t)m.ncells * sizeof *a2);
    const double r = 0.05, vp = sphere_volume(r);
    const double at[3][3] = {{0.02, 0.17, 0.21}, {0.985, 0.23, 0.16}, {0.0, 0.2, 0.2}};
    const char *where[3] = {"near the min face", "near the max face", "centred on the face"};
    for (int model = CPL_VF_CENTRE; model <= CPL_VF_GAUSSIAN; model++)
        for (int k = 0; k < 3; k++) {
            double mapped, mapped2, mapped_plain;
            one_particle_alpha(&m, model, at[k], r, a1, &mapped);
            const double y[3] = {at[k][0] + 0.5, at[k][1], at[k][2]};
            one_particle_alpha(&m, model, y, r, a2, &mapped2);
            double worst = 0.0;
            for (int c = 0; c < m.ncells; c++) worst = fmax(worst, fabs(a1[c] - a2[half[c]]));
            if (model == CPL_VF_CENTRE && k == 2) {   /* on a face either cell is the centre's: a tie */
                int beside = 0;
                for (int c = 0; c < m.ncells; c++)
                    beside += a1[c] < 1.0 && (m.cell_centre[c][0] < 0.1 || m.cell_centre[c][0] > 0.9);
                worst = beside == 1 ? 0.0 : 1.0;
            }
            one_particle_alpha(&plain, model, at[k], r, a2, &mapped_plain);
            double fault = 0.0;
            for (int c = 0; c < m.ncells; c++) fault = fmax(fault, fabs(a1[c] - a2[c]));
            char what[160];
            snprintf(what, sizeof what, "cyclic %s, particle %s: sum (1-alpha)V = V_p [m^3], rel. 1e-12", model_name[model],
                     where[k]);
            check_rel(what, mapped, vp, 1e-12);
            if (model == CPL_VF_CENTRE && k == 2)
                snprintf(what, sizeof what, "cyclic centre, particle %s: all in one cell beside the face", where[k]);
            else
                snprintf(what, sizeof what, "cyclic %s, particle %s: alpha as half a period on, 1e-12", model_name[model], where[k]);
            printf("      largest |alpha - alpha half a period on| %.3g; without the pairs the field differs by up to %.3g\n",
                   worst, fault);
            check_true(what, worst <= 1e-12);
        }
    /* a centre carried across the max face is found where the path goes on */
    const double before[3] = {0.995, 0.1, 0.1}, beyond[3] = {1.004, 0.1, 0.1}, wrapped[3] = {0.004, 0.1, 0.1};
    const int c0 = cpl_mesh_locate(&m, before, -1, NULL);
    const int c1 = cpl_mesh_locate(&m, beyond, c0, NULL), c2 = cpl_mesh_locate(&m, wrapped, -1, NULL);
    check_true("cyclic: a centre beyond the max face is located in the first cell of the min side",
               c1 == c2 && c1 >= 0 && m.cell_centre[c1][0] < 0.1 && m.cell_centre[c0][0] > 0.9);
    /* a separation that is not the mesh's extent is refused */
    {
        int ok, fx[1] = {m.ninternal_faces}, fy[1] = {m.ninternal_faces + 1};
        cpl_mesh bad;
        cpl_mesh_box(&bad, lo, hi, 10, 4, 4);
        STOPS_WITH(ok, cpl_mesh_set_cyclic(&bad, 1, fx, fy), "cyclic patch: the separation");
        check_true("cyclic: two faces that are not a periodic pair: fatal error", ok);
    }
    free(half); free(a1); free(a2);
    cpl_mesh_free(&m);
    cpl_mesh_free(&plain);
}

int main(void)
{
    const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
    cpl_mesh box;
    cpl_mesh_box(&box, lo, hi, 10, 10, 10);   /* cells 0.1 m, 1e-3 m^3 */

    /* 1. conservation, particles smaller than cells and (gaussian's case) larger than cells */
    conservation("box", &box, 600, 0.01, 0.03, 1, CPL_VF_CENTRE);
    conservation("box, large particles", &box, 6, 0.08, 0.12, 2, CPL_VF_GAUSSIAN);

    /* 2. gaussian at walls and in a corner: all the volume stays in the mesh */
    {
        cpl_voidfraction vf;
        cpl_vf_init(&vf, &box, CPL_VF_GAUSSIAN, 0.0);
        vf.kernel_width = 1.0;   /* s = d: wide enough that even the corner cell stays off the floor */
        double x[4][3] = {{0.02, 0.5, 0.5}, {0.5, 0.97, 0.43}, {0.01, 0.01, 0.99}, {0.51, 0.47, 0.52}};
        double r[4] = {0.08, 0.06, 0.08, 0.08};
        int cell[4] = {-1, -1, -1, -1};
        const int out = cpl_vf_compute(&vf, &box, 4, (const double (*)[3])x, r, cell);
        int floored, spread_over = vf.w_start[1] - vf.w_start[0];
        double total = 0;
        for (int i = 0; i < 4; i++) total += sphere_volume(r[i]);
        printf("gaussian: the particle at the x = 0 wall spreads over %d cells, the interior one over %d\n",
               spread_over, vf.w_start[4] - vf.w_start[3]);
        check_rel("gaussian at walls and a corner: sum (1-alpha)V [m^3], rel. 1e-12", mapped_volume(&vf, &box, &floored), total, 1e-12);
        check_true("gaussian at walls: no cell at the floor", floored == 0);
        check_true("gaussian: kernel over many cells (> 20) at the wall, none outside", spread_over > 20 && out == 0);
        /* interior particle: the weights' centroid is near the particle (symmetric kernel) */
        double cen[3] = {0, 0, 0};
        for (int k = vf.w_start[3]; k < vf.w_start[4]; k++)
            for (int d = 0; d < 3; d++) cen[d] += vf.w[k] * box.cell_centre[vf.w_cell[k]][d];
        const double off = sqrt(pow(cen[0] - 0.51, 2) + pow(cen[1] - 0.47, 2) + pow(cen[2] - 0.52, 2));
        printf("gaussian: interior weights' centroid %.3g m from the particle centre\n", off);
        check_true("gaussian: interior weights' centroid within 0.01 m (a tenth of a cell)", off < 0.01);
        /* the wall particle's centroid is pushed inwards: volume kept in the mesh */
        double cx = 0;
        for (int k = vf.w_start[0]; k < vf.w_start[1]; k++) cx += vf.w[k] * box.cell_centre[vf.w_cell[k]][0];
        check_true("gaussian: wall particle's weights all inside, centroid x > 0.05 m", cx > 0.05);
        cpl_vf_free(&vf);
    }

    /* 3. the floor */
    {
        cpl_voidfraction vf;
        cpl_vf_init(&vf, &box, CPL_VF_CENTRE, 0.3);
        double x[1][3] = {{0.55, 0.55, 0.55}}, r[1] = {0.08};   /* 2.14e-3 m^3 in a 1e-3 m^3 cell */
        int cell[1] = {-1};
        cpl_vf_compute(&vf, &box, 1, (const double (*)[3])x, r, cell);
        check_true("floor: alpha = alphaMin = 0.3 in the overfull cell", vf.alpha[cell[0]] == 0.3);
        check_rel("floor: vp keeps the whole particle volume [m^3], rel. 1e-14", vf.vp[cell[0]], sphere_volume(0.08), 1e-14);
        int at_one = 0;
        for (int c = 0; c < box.ncells; c++) at_one += vf.alpha[c] == 1.0;
        check_true("floor: every other cell at alpha = 1", at_one == box.ncells - 1);
        cpl_vf_free(&vf);
    }

    /* 4. divided: spheres straddling the face x = 0.5 between two cells */
    {
        cpl_voidfraction vf;
        cpl_vf_init(&vf, &box, CPL_VF_DIVIDED, 0.0);
        double x[4][3] = {{0.5, 0.55, 0.55}, {0.5 - 0.02, 0.45, 0.35}, {0.5 + 0.01, 0.35, 0.65}, {0.5, 0.25, 0.55}};
        double r[4] = {0.04, 0.04, 0.04, 0.04};   /* offsets t = d/r: 0, 0.5, 0.25 */
        int cell[4] = {-1, -1, -1, -1};
        cpl_vf_compute(&vf, &box, 4, (const double (*)[3])x, r, cell);
        printf("divided: %d sample points per sphere\n", vf.nsample);
        check_rel("divided: sphere centred on a face, share beyond it, rel. 1e-12", weight_above(&vf, &box, 0, 0, 0.5), 0.5, 1e-12);
        /* cap beyond a plane at t = h/r from the centre: (1-t)^2 (2+t)/4 of the volume; the 64
         * points resolve it to within 0.06 of the volume (the sampling error; 0.057 is the
         * worst over axis-aligned planes found in a scan of t), about 0.015 on average */
        const double cap50 = 0.25 * 2.5 / 4, cap25 = 0.75 * 0.75 * 2.25 / 4;
        const double w1 = weight_above(&vf, &box, 1, 0, 0.5), w2 = 1 - weight_above(&vf, &box, 2, 0, 0.5);
        printf("divided: cap share at t = 0.5: %.4f (exact %.4f); at t = 0.25: %.4f (exact %.4f)\n", w1, cap50, w2, cap25);
        check_true("divided: cap at t = 0.5 within 0.06 of the volume (sampling)", fabs(w1 - cap50) < 0.06);
        check_true("divided: cap at t = 0.25 within 0.06 of the volume (sampling)", fabs(w2 - cap25) < 0.06);
        /* over offsets t = 0 .. 0.95 from a face normal to x, y and z: worst and mean error */
        double worst_cap = 0, mean_cap = 0;
        int ncap = 0;
        for (int axis = 0; axis < 3; axis++)
            for (int it = 0; it < 20; it++) {
                const double t = 0.05 * it;
                double xs[1][3] = {{0.55, 0.55, 0.55}}, rs[1] = {0.04};
                int cs[1] = {-1};
                xs[0][axis] = 0.5 - t * 0.04;
                cpl_vf_compute(&vf, &box, 1, (const double (*)[3])xs, rs, cs);
                const double err = fabs(weight_above(&vf, &box, 0, axis, 0.5) - (1 - t) * (1 - t) * (2 + t) / 4);
                worst_cap = fmax(worst_cap, err);
                mean_cap += err;
                ncap++;
            }
        mean_cap /= ncap;
        printf("divided: cap share error over 60 offsets and 3 axes: mean %.4f, worst %.4f\n", mean_cap, worst_cap);
        check_true("divided: cap share error, worst < 0.06 and mean < 0.025 of the volume", worst_cap < 0.06 && mean_cap < 0.025);
        /* a sphere on the corner line of 4 cells: a quarter in each within the sampling error */
        double xq[1][3] = {{0.5, 0.5, 0.55}}, rq[1] = {0.04};
        int cq[1] = {-1};
        cpl_vf_compute(&vf, &box, 1, (const double (*)[3])xq, rq, cq);
        int ncell = vf.w_start[1] - vf.w_start[0];
        double worst = 0;
        for (int k = 0; k < ncell; k++) worst = fmax(worst, fabs(vf.w[k] - 0.25));
        printf("divided: sphere on a 4-cell edge: %d cells, largest share error %.4f\n", ncell, worst);
        check_true("divided: on a 4-cell edge a quarter each within 0.04", ncell == 4 && worst < 0.04);
        /* sample points beyond a wall are renormalised over the ones inside: volume kept */
        double xw[1][3] = {{0.01, 0.5, 0.5}}, rw[1] = {0.05};
        int cw[1] = {-1}, floored;
        cpl_vf_compute(&vf, &box, 1, (const double (*)[3])xw, rw, cw);
        check_rel("divided at a wall: sum (1-alpha)V [m^3], rel. 1e-12", mapped_volume(&vf, &box, &floored), sphere_volume(0.05), 1e-12);
        cpl_vf_free(&vf);
    }

    /* 5. particles outside the mesh are counted and not mapped */
    {
        cpl_voidfraction vf;
        cpl_vf_init(&vf, &box, CPL_VF_DIVIDED, 0.0);
        double x[4][3] = {{0.5, 0.5, 0.5}, {1.2, 0.5, 0.5}, {0.3, 0.3, 0.3}, {0.5, -0.01, 0.5}};
        double r[4] = {0.02, 0.02, 0.03, 0.005};
        int cell[4] = {0, 0, 0, 0};
        const int out = cpl_vf_compute(&vf, &box, 4, (const double (*)[3])x, r, cell);
        int floored;
        check_true("outside: 2 particles reported, their cells -1", out == 2 && cell[1] == -1 && cell[3] == -1);
        check_rel("outside: the others mapped in full [m^3], rel. 1e-12", mapped_volume(&vf, &box, &floored),
                  sphere_volume(0.02) + sphere_volume(0.03), 1e-12);
        cpl_vf_free(&vf);
    }

    /* 6. skewed and polyhedral meshes */
    {
        cpl_mesh m;
        cpl_mesh_box(&m, lo, hi, 9, 7, 11);
        cpl_mesh_map_points(&m, shear_grade, NULL);
        conservation("skewed", &m, 500, 0.01, 0.04, 3, CPL_VF_CENTRE);
        cpl_mesh_free(&m);
        const double hi2[3] = {1, 0.8, 0.8};
        const int rlo[3] = {1, 1, 1}, rhi[3] = {3, 3, 3};
        cpl_mesh_box_refined(&m, lo, hi2, 5, 4, 4, rlo, rhi);
        cpl_mesh_map_points(&m, shear_only, NULL);
        conservation("refined polyhedral", &m, 300, 0.01, 0.03, 4, CPL_VF_CENTRE);
        cpl_mesh_free(&m);
    }

    /* 7. bad input */
    {
        cpl_voidfraction vf;
        enum cpl_vf_model model;
        check_true("model names parsed, an unknown one not found",
                   cpl_vf_model_parse("gaussian", &model) == 0 && model == CPL_VF_GAUSSIAN &&
                   cpl_vf_model_parse("dividedd", &model) == -1);
        int ok;
        STOPS_WITH(ok, cpl_vf_init(&vf, &box, CPL_VF_CENTRE, 1.0), "void fraction: alphaMin = 1 must be in [0, 1)");
        check_true("alphaMin = 1: fatal error", ok);
        cpl_vf_init(&vf, &box, CPL_VF_CENTRE, 0.0);
        double x[1][3] = {{0.5, 0.5, 0.5}}, r[1] = {0.0};
        int cell[1] = {-1};
        STOPS_WITH(ok, cpl_vf_compute(&vf, &box, 1, (const double (*)[3])x, r, cell),
                   "void fraction: particle 0 has radius 0 m");
        check_true("radius 0: fatal error naming the particle", ok);
        STOPS_WITH(ok, cpl_vf_set_samples(&vf, 2, 3), "divided void fraction: 2 shells of 3 points");
        check_true("3 points per shell: fatal error", ok);
        cpl_vf_free(&vf);
    }
    cyclic_sides();
    cpl_mesh_free(&box);
    return finish("test_voidfraction");
}
