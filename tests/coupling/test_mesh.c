/* The fluid mesh: box mesh in OpenFOAM's ordering with exact geometry; particle location by walk
 * and by full search agrees with brute force (inside test over all cells) on a box, on a sheared
 * and graded hex mesh, and on a polyhedral mesh with a refined block (split faces, hanging
 * points); points outside the mesh give -1; bad input is a fatal error with a message naming it,
 * not a crash. */
#include <stdlib.h>

#include "catch_fatal.h"
#include "harness.h"
#include "test_meshes.h"
#include "mesh.h"
#include "rng.h"

/* Sum over the cells of |sum of outward area vectors| / sum |S|: 0 for closed cells. */
static double worst_open_cell(const cpl_mesh *m)
{
    double worst = 0;
    for (int c = 0; c < m->ncells; c++) {
        double sum[3] = {0, 0, 0}, mag = 0;
        for (int k = m->cell_face_start[c]; k < m->cell_face_start[c + 1]; k++) {
            const int f = m->cell_faces[k];
            const double sgn = m->owner[f] == c ? 1 : -1;
            for (int d = 0; d < 3; d++) sum[d] += sgn * m->face_area[f][d];
            mag += sqrt(m->face_area[f][0] * m->face_area[f][0] + m->face_area[f][1] * m->face_area[f][1] +
                        m->face_area[f][2] * m->face_area[f][2]);
        }
        worst = fmax(worst, sqrt(sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]) / mag);
    }
    return worst;
}

/* OpenFOAM ordering: owner < neighbour, internal faces sorted by (owner, neighbour), area vectors
 * pointing from the owner's centre to the neighbour's (or out of the mesh on boundary faces). */
static int ordering_ok(const cpl_mesh *m)
{
    for (int f = 0; f < m->nfaces; f++) {
        double r[3];
        for (int d = 0; d < 3; d++) r[d] = m->face_centre[f][d] - m->cell_centre[m->owner[f]][d];
        if (r[0] * m->face_area[f][0] + r[1] * m->face_area[f][1] + r[2] * m->face_area[f][2] <= 0) return 0;
        if (f >= m->ninternal_faces) continue;
        if (m->owner[f] >= m->neighbour[f]) return 0;
        if (f > 0 && (m->owner[f] < m->owner[f - 1] ||
                      (m->owner[f] == m->owner[f - 1] && m->neighbour[f] <= m->neighbour[f - 1]))) return 0;
    }
    return 1;
}

static double total_volume(const cpl_mesh *m)
{
    double v = 0;
    for (int c = 0; c < m->ncells; c++) v += m->cell_volume[c];
    return v;
}

/* Random points in the mesh's bounding box (widened by 5 %): walk from a random cell, walk from
 * the true cell's neighbour, full search, against brute force. Returns mismatches; counts the
 * outside points and the walks that needed a full search. */
static int locate_agrees(const cpl_mesh *m, int npts, unsigned seed, int *outside, int *searches_short)
{
    dem_rng r;
    rng_seed(&r, seed);
    int bad = 0;
    *outside = 0;
    *searches_short = 0;
    int *hits = malloc(m->ncells * sizeof(int));
    for (int t = 0; t < npts; t++) {
        double x[3];
        for (int d = 0; d < 3; d++) {
            const double w = m->bounds_max[d] - m->bounds_min[d];
            x[d] = m->bounds_min[d] - 0.05 * w + 1.1 * w * rng_uniform(&r);
        }
        int nhit = 0;
        for (int c = 0; c < m->ncells; c++)
            if (cpl_mesh_inside(m, c, x)) hits[nhit++] = c;
        const int guess = (int)(rng_uniform(&r) * m->ncells);
        int searched;
        const int by_walk = cpl_mesh_locate(m, x, guess, &searched);
        const int by_search = cpl_mesh_locate(m, x, -1, NULL);
        if (nhit == 0) {
            (*outside)++;
            bad += by_walk != -1 || by_search != -1;
            continue;
        }
        int ok_walk = 0, ok_search = 0;
        for (int k = 0; k < nhit; k++) { ok_walk |= hits[k] == by_walk; ok_search |= hits[k] == by_search; }
        bad += !ok_walk + !ok_search;
        /* from a face neighbour of the true cell the walk must get there without searching */
        const int c = hits[0];
        int near = c;
        for (int k = m->cell_face_start[c]; k < m->cell_face_start[c + 1] && near == c; k++) {
            const int n = cpl_mesh_other_cell(m, m->cell_faces[k], c);
            if (n >= 0) near = n;
        }
        int ok_near = 0;
        const int by_near = cpl_mesh_locate(m, x, near, &searched);
        for (int k = 0; k < nhit; k++) ok_near |= hits[k] == by_near;
        bad += !ok_near;
        *searches_short += searched;
    }
    free(hits);
    return bad;
}

int main(void)
{
    /* 1. box mesh */
    {
        const double lo[3] = {-0.5, 0, 1}, hi[3] = {0.5, 0.6, 3};
        cpl_mesh m;
        cpl_mesh_box(&m, lo, hi, 4, 3, 5);
        check_true("box 4x3x5: 60 cells, 133 internal faces, 227 faces, 120 points",
                   m.ncells == 60 && m.ninternal_faces == 133 && m.nfaces == 227 && m.npoints == 120);
        check_true("box: OpenFOAM ordering (owner < neighbour, sorted, S out of owner)", ordering_ok(&m));
        check_true("box: cells closed (|sum S| / sum |S| < 1e-14)", worst_open_cell(&m) < 1e-14);
        double worst_v = 0, worst_c = 0;
        for (int k = 0; k < 5; k++)
            for (int j = 0; j < 3; j++)
                for (int i = 0; i < 4; i++) {
                    const int c = i + 4 * (j + 3 * k);
                    const double ctr[3] = {-0.5 + 0.25 * (i + 0.5), 0.2 * (j + 0.5), 1 + 0.4 * (k + 0.5)};
                    worst_v = fmax(worst_v, fabs(m.cell_volume[c] / 0.02 - 1));
                    for (int d = 0; d < 3; d++) worst_c = fmax(worst_c, fabs(m.cell_centre[c][d] - ctr[d]));
                }
        check_true("box: cell volumes 0.02 m^3 to 1e-13 relative", worst_v < 1e-13);
        check_true("box: cell centres exact to 1e-13 m", worst_c < 1e-13);
        int outside, searches;
        const int bad = locate_agrees(&m, 4000, 1, &outside, &searches);
        printf("box: %d outside points, %d full searches from a neighbour's cell\n", outside, searches);
        check_true("box: walk and full search agree with brute force (4000 points)", bad == 0);
        check_true("box: some points were outside and gave -1", outside > 100);
        check_true("box: from a neighbour cell no full search", searches == 0);
        const double mid[3] = {-0.5 + 0.25 * 1.5, 0.2 * 0.5 + 0.03, 1 + 0.4 * 2.5};   /* in cell (1, 0, 2) */
        check_true("box: depth of a point 0.03 m off a centre = 0.1 - 0.03 m (1e-14 m)",
                   fabs(cpl_mesh_depth(&m, 1 + 4 * (0 + 3 * 2), mid) - 0.07) < 1e-14);
        const double far[3] = {0, 0.3, 5};
        int searched;
        check_true("box: point beyond the top gives -1 after a search",
                   cpl_mesh_locate(&m, far, 10, &searched) == -1 && searched == 1);
        const double nan3[3] = {NAN, 0, 0};
        check_true("box: NaN position gives -1", cpl_mesh_locate(&m, nan3, 3, NULL) == -1);
        /* a long walk: from cell 0 to the far corner */
        const double corner[3] = {0.49, 0.59, 2.99};
        const int cfar = cpl_mesh_locate(&m, corner, 0, &searched);
        check_true("box: walk across the mesh reaches the far corner cell without searching",
                   cfar == 59 && searched == 0);

        /* given centres and volumes are taken as they are */
        cpl_mesh m2;
        double *vol = malloc(m.ncells * sizeof(double));
        for (int c = 0; c < m.ncells; c++) vol[c] = 2.0 * m.cell_volume[c];
        cpl_mesh_init(&m2, m.npoints, (const double (*)[3])m.points, m.nfaces, m.face_start, m.face_points,
                      m.ninternal_faces, m.owner, m.neighbour, m.ncells, (const double (*)[3])m.cell_centre, vol);
        check_true("init with given cell volumes keeps them", m2.cell_volume[7] == vol[7]);
        cpl_mesh_free(&m2);

        /* bad input: a fatal error that names it */
        int *own = malloc(m.nfaces * sizeof(int));
        memcpy(own, m.owner, m.nfaces * sizeof(int));
        own[5] = m.ncells;
        int ok;
        STOPS_WITH(ok, cpl_mesh_init(&m2, m.npoints, (const double (*)[3])m.points, m.nfaces, m.face_start,
                                     m.face_points, m.ninternal_faces, own, m.neighbour, m.ncells, NULL, NULL),
                   "cpl_mesh_init: face 5 has owner 60 (there are 60 cells)");
        check_true("owner out of range: fatal error naming the face", ok);
        /* a face list with every face reversed: negative volumes */
        int *rev = malloc(m.face_start[m.nfaces] * sizeof(int));
        for (int f = 0; f < m.nfaces; f++) {
            const int a = m.face_start[f], b = m.face_start[f + 1];
            for (int k = a; k < b; k++) rev[k] = m.face_points[b - 1 - (k - a)];
        }
        STOPS_WITH(ok, cpl_mesh_init(&m2, m.npoints, (const double (*)[3])m.points, m.nfaces, m.face_start, rev,
                                     m.ninternal_faces, m.owner, m.neighbour, m.ncells, NULL, NULL),
                   "has a non-positive volume");
        check_true("reversed faces: fatal error (non-positive volume)", ok);
        STOPS_WITH(ok, cpl_mesh_box(&m2, hi, lo, 2, 2, 2), "cpl_mesh_box: empty box: lo[0] = 0.5 m, hi[0] = -0.5 m");
        check_true("empty box: fatal error naming the box", ok);
        free(own); free(rev); free(vol);
        cpl_mesh_free(&m);
        cpl_mesh_free(&m);   /* a freed mesh can be freed again */
    }

    /* 2. sheared, graded hex mesh with a non-uniform shear */
    {
        const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
        cpl_mesh m;
        cpl_mesh_box(&m, lo, hi, 9, 7, 11);
        cpl_mesh_map_points(&m, shear_grade, NULL);
        check_true("skewed: OpenFOAM ordering kept", ordering_ok(&m));
        check_true("skewed: cells closed (1e-14)", worst_open_cell(&m) < 1e-14);
        /* volume: the shears have unit Jacobian, the stretches give x: 1, z: 3 */
        check_rel("skewed: total volume [m^3], rel. 1e-12", total_volume(&m), 3.0, 1e-12);
        int outside, searches;
        const int bad = locate_agrees(&m, 6000, 2, &outside, &searches);
        printf("skewed: %d outside points, %d full searches from a neighbour's cell\n", outside, searches);
        check_true("skewed: walk and full search agree with brute force (6000 points)", bad == 0);
        check_true("skewed: many points outside the sheared mesh gave -1", outside > 1000);
        cpl_mesh_free(&m);
    }

    /* 3. polyhedral: a 2x2x2 block of a 5x4x4 mesh refined, then graded and sheared */
    {
        const double lo[3] = {0, 0, 0}, hi[3] = {1, 0.8, 0.8};
        const int rlo[3] = {1, 1, 1}, rhi[3] = {3, 3, 3};
        cpl_mesh m;
        cpl_mesh_box_refined(&m, lo, hi, 5, 4, 4, rlo, rhi);
        int maxf = 0, maxp = 0;
        for (int c = 0; c < m.ncells; c++) {
            const int nf = m.cell_face_start[c + 1] - m.cell_face_start[c];
            if (nf > maxf) maxf = nf;
        }
        for (int f = 0; f < m.nfaces; f++)
            if (m.face_start[f + 1] - m.face_start[f] > maxp) maxp = m.face_start[f + 1] - m.face_start[f];
        printf("refined: %d cells, %d faces, up to %d faces per cell, up to %d points per face\n",
               m.ncells, m.nfaces, maxf, maxp);
        check_true("refined: 80 - 8 + 64 = 136 cells", m.ncells == 136);
        check_true("refined: polyhedral cells (9 faces) and faces with hanging points (> 4)", maxf == 9 && maxp > 4);
        check_true("refined: OpenFOAM ordering", ordering_ok(&m));
        check_true("refined: cells closed (1e-14)", worst_open_cell(&m) < 1e-14);
        check_rel("refined: total volume [m^3], rel. 1e-13", total_volume(&m), 0.64, 1e-13);
        int nfine = 0;
        for (int c = 0; c < m.ncells; c++) nfine += fabs(m.cell_volume[c] - 0.001) < 1e-15;
        check_true("refined: 64 cells of 0.001 m^3 (to 1e-15 m^3)", nfine == 64);
        int outside, searches;
        int bad = locate_agrees(&m, 4000, 3, &outside, &searches);
        check_true("refined: walk and full search agree with brute force (4000 points)", bad == 0);
        cpl_mesh_map_points(&m, shear_linear, NULL);
        check_true("refined+sheared: cells closed (1e-14)", worst_open_cell(&m) < 1e-14);
        check_true("refined+sheared: OpenFOAM ordering", ordering_ok(&m));
        bad = locate_agrees(&m, 6000, 4, &outside, &searches);
        printf("refined+sheared: %d outside points, %d full searches from a neighbour's cell\n", outside, searches);
        check_true("refined+sheared: walk and search agree with brute force (6000 points)", bad == 0);
        check_true("refined+sheared: points outside gave -1", outside > 1000);
        cpl_mesh_free(&m);
    }
    return finish("test_mesh");
}
