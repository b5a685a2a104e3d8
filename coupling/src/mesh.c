/* The fluid mesh: copy of OpenFOAM's polyMesh arrays, derived geometry (face centres and area
 * vectors as primitiveMeshFaceCentresAndAreas, cell centres and volumes as
 * primitiveMeshCellCentresAndVols), cell -> faces, and particle location (walk, then a uniform
 * grid of cells for the full search). Lengths in m, areas in m^2, volumes in m^3.
 * Bad input and a shortage of memory are fatal errors (error.h), as everywhere in coupling/. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "mesh.h"

/* Private data of the full search and of the inside test. */
typedef struct mesh_search {
    int n[3];                   /* grid cells per direction */
    double lo[3], inv_h[3];     /* grid origin [m], 1 / grid spacing [1/m] */
    int *start, *cells;         /* CSR: mesh cells whose bounding box overlaps grid cell g */
    double *face_inv_mag;       /* 1 / |S_f| [1/m^2] */
    double *cell_tol;           /* inside tolerance of cell c [m] */
    int walk_cap;               /* walk steps before giving up and searching */
} mesh_search;

static void cross(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

static double dot(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void search_free(mesh_search *s)
{
    if (!s) return;
    free(s->start); free(s->cells); free(s->face_inv_mag); free(s->cell_tol);
    free(s);
}

void cpl_mesh_free(cpl_mesh *m)
{
    free(m->points); free(m->face_start); free(m->face_points); free(m->owner); free(m->neighbour);
    free(m->cell_centre); free(m->cell_volume); free(m->face_centre); free(m->face_area);
    free(m->cell_face_start); free(m->cell_faces); free(m->cyclic_partner);
    search_free(m->search);
    memset(m, 0, sizeof *m);
}

/* Face centre and area vector from triangles fanned about the points' average; the triangle
 * areas are projected on the face normal (as OpenFOAM does), so a warped face still gets its
 * mean plane. */
static void face_geometry(cpl_mesh *m)
{
    for (int f = 0; f < m->nfaces; f++) {
        const int *fp = m->face_points + m->face_start[f];
        const int n = m->face_start[f + 1] - m->face_start[f];
        double *fc = m->face_centre[f], *S = m->face_area[f];
        double avg[3] = {0, 0, 0};
        for (int k = 0; k < n; k++)
            for (int d = 0; d < 3; d++) avg[d] += m->points[fp[k]][d];
        for (int d = 0; d < 3; d++) avg[d] /= n;
        double sumN[3] = {0, 0, 0};
        for (int k = 0; k < n; k++) {
            const double *p = m->points[fp[k]], *q = m->points[fp[(k + 1) % n]];
            double e[3], r[3], t[3];
            for (int d = 0; d < 3; d++) { e[d] = q[d] - p[d]; r[d] = avg[d] - p[d]; }
            cross(e, r, t);
            for (int d = 0; d < 3; d++) sumN[d] += t[d];
        }
        const double magN = sqrt(dot(sumN, sumN));
        double sumA = 0, sumAc[3] = {0, 0, 0};
        for (int k = 0; k < n && magN > 0; k++) {
            const double *p = m->points[fp[k]], *q = m->points[fp[(k + 1) % n]];
            double e[3], r[3], t[3];
            for (int d = 0; d < 3; d++) { e[d] = q[d] - p[d]; r[d] = avg[d] - p[d]; }
            cross(e, r, t);
            const double a = dot(t, sumN) / magN;
            sumA += a;
            for (int d = 0; d < 3; d++) sumAc[d] += a * (p[d] + q[d] + avg[d]);
        }
        for (int d = 0; d < 3; d++) {
            fc[d] = sumA > 0 ? sumAc[d] / (3.0 * sumA) : avg[d];
            S[d] = 0.5 * sumN[d];
        }
    }
}

/* Cell centres and volumes by pyramids from an estimated centre (the face centres' average) to
 * each face. Returns -1 if a cell has a non-positive volume (faces wrongly oriented). */
static void cell_geometry(cpl_mesh *m)
{
    double (*est)[3] = dem_calloc(m->ncells, sizeof *est);
    for (int c = 0; c < m->ncells; c++) {
        const int n = m->cell_face_start[c + 1] - m->cell_face_start[c];
        for (int k = m->cell_face_start[c]; k < m->cell_face_start[c + 1]; k++)
            for (int d = 0; d < 3; d++) est[c][d] += m->face_centre[m->cell_faces[k]][d] / n;
    }
    for (int c = 0; c < m->ncells; c++) {
        double vol3 = 0, ctr[3] = {0, 0, 0};
        for (int k = m->cell_face_start[c]; k < m->cell_face_start[c + 1]; k++) {
            const int f = m->cell_faces[k];
            const double sgn = m->owner[f] == c ? 1.0 : -1.0;
            double r[3];
            for (int d = 0; d < 3; d++) r[d] = m->face_centre[f][d] - est[c][d];
            const double pyr3 = sgn * dot(m->face_area[f], r);     /* 3 x pyramid volume */
            vol3 += pyr3;
            for (int d = 0; d < 3; d++) ctr[d] += pyr3 * (0.75 * m->face_centre[f][d] + 0.25 * est[c][d]);
        }
        if (!(vol3 > 0))
            dem_fatal("cpl_mesh: cell %d has a non-positive volume %g m^3 (are the face area vectors "
                      "pointing out of their owner?)", c, vol3 / 3.0);
        for (int d = 0; d < 3; d++) m->cell_centre[c][d] = ctr[d] / vol3;
        m->cell_volume[c] = vol3 / 3.0;
    }
    free(est);
}

/* Cell -> faces (CSR), from owner and neighbour. */
static void cell_faces(cpl_mesh *m)
{
    m->cell_face_start = dem_calloc(m->ncells + 1, sizeof(int));
    m->cell_faces = dem_calloc(m->nfaces + m->ninternal_faces, sizeof(int));
    int *fill = dem_calloc(m->ncells, sizeof(int));
    for (int f = 0; f < m->nfaces; f++) m->cell_face_start[m->owner[f] + 1]++;
    for (int f = 0; f < m->ninternal_faces; f++) m->cell_face_start[m->neighbour[f] + 1]++;
    for (int c = 0; c < m->ncells; c++) m->cell_face_start[c + 1] += m->cell_face_start[c];
    for (int f = 0; f < m->nfaces; f++) {
        const int c = m->owner[f];
        m->cell_faces[m->cell_face_start[c] + fill[c]++] = f;
        if (f < m->ninternal_faces) {
            const int n = m->neighbour[f];
            m->cell_faces[m->cell_face_start[n] + fill[n]++] = f;
        }
    }
    free(fill);
    for (int c = 0; c < m->ncells; c++)
        if (m->cell_face_start[c + 1] - m->cell_face_start[c] < 4)
            dem_fatal("cpl_mesh: cell %d has %d faces (a closed cell has at least 4)", c,
                      m->cell_face_start[c + 1] - m->cell_face_start[c]);
}

/* Bounding boxes, inside tolerances and the search grid. The grid has about one mesh cell per
 * grid cell; each grid cell lists the mesh cells whose bounding box overlaps it. */
static void build_search(cpl_mesh *m)
{
    search_free(m->search);
    mesh_search *s = dem_calloc(1, sizeof *s);
    m->search = s;
    s->face_inv_mag = dem_calloc(m->nfaces, sizeof(double));
    s->cell_tol = dem_calloc(m->ncells, sizeof(double));
    double (*blo)[3] = dem_calloc(m->ncells, sizeof *blo), (*bhi)[3] = dem_calloc(m->ncells, sizeof *bhi);
    for (int f = 0; f < m->nfaces; f++) {
        const double mag = sqrt(dot(m->face_area[f], m->face_area[f]));
        if (!(mag > 0)) dem_fatal("cpl_mesh: face %d has zero area", f);
        s->face_inv_mag[f] = 1.0 / mag;
    }
    for (int d = 0; d < 3; d++) { m->bounds_min[d] = INFINITY; m->bounds_max[d] = -INFINITY; }
    for (int c = 0; c < m->ncells; c++) {
        /* round-off of (x - fc).n is ~1e-16 |x|; 1e-9 of the cell size is far above it and far
         * below anything a particle cares about */
        s->cell_tol[c] = 1e-9 * cbrt(m->cell_volume[c]);
        for (int d = 0; d < 3; d++) { blo[c][d] = INFINITY; bhi[c][d] = -INFINITY; }
        for (int k = m->cell_face_start[c]; k < m->cell_face_start[c + 1]; k++) {
            const int f = m->cell_faces[k];
            for (int j = m->face_start[f]; j < m->face_start[f + 1]; j++)
                for (int d = 0; d < 3; d++) {
                    blo[c][d] = fmin(blo[c][d], m->points[m->face_points[j]][d]);
                    bhi[c][d] = fmax(bhi[c][d], m->points[m->face_points[j]][d]);
                }
        }
        for (int d = 0; d < 3; d++) {
            blo[c][d] -= s->cell_tol[c];
            bhi[c][d] += s->cell_tol[c];
            m->bounds_min[d] = fmin(m->bounds_min[d], blo[c][d]);
            m->bounds_max[d] = fmax(m->bounds_max[d], bhi[c][d]);
        }
    }
    double ext[3], vol = 1;
    for (int d = 0; d < 3; d++) { ext[d] = m->bounds_max[d] - m->bounds_min[d]; vol *= ext[d]; }
    const double h = cbrt(vol / m->ncells);
    long total = 1;
    for (int d = 0; d < 3; d++) {
        double nd = ceil(ext[d] / h);
        s->n[d] = (int)fmax(1.0, fmin(nd, 1024.0));
        s->lo[d] = m->bounds_min[d];
        s->inv_h[d] = s->n[d] / ext[d];
        total *= s->n[d];
    }
    s->start = dem_calloc(total + 1, sizeof(int));
    /* two passes: count, then fill */
    for (int pass = 0; pass < 2; pass++) {
        if (pass == 1) {
            for (long g = 0; g < total; g++) s->start[g + 1] += s->start[g];
            s->cells = dem_calloc(s->start[total], sizeof(int));
        }
        for (int c = 0; c < m->ncells; c++) {
            int i0[3], i1[3];
            for (int d = 0; d < 3; d++) {
                i0[d] = (int)floor((blo[c][d] - s->lo[d]) * s->inv_h[d]);
                i1[d] = (int)floor((bhi[c][d] - s->lo[d]) * s->inv_h[d]);
                if (i0[d] < 0) i0[d] = 0;
                if (i1[d] >= s->n[d]) i1[d] = s->n[d] - 1;
            }
            for (int k = i0[2]; k <= i1[2]; k++)
                for (int j = i0[1]; j <= i1[1]; j++)
                    for (int i = i0[0]; i <= i1[0]; i++) {
                        const long g = i + (long)s->n[0] * (j + (long)s->n[1] * k);
                        if (pass == 0) s->start[g + 1]++;
                        else s->cells[s->start[g]++] = c;
                    }
        }
        if (pass == 1)   /* the fill advanced start[g] to the next grid cell's start: shift back */
            for (long g = total; g > 0; g--) s->start[g] = s->start[g - 1];
        if (pass == 1) s->start[0] = 0;
    }
    free(blo); free(bhi);
    s->walk_cap = 2 * (int)cbrt((double)m->ncells) + 10;
}

/* Everything derived from points, faces, owner and neighbour; cell centres and volumes too
 * when compute_cells is set. */
static void derive(cpl_mesh *m, int compute_cells)
{
    face_geometry(m);
    if (compute_cells) cell_geometry(m);
    build_search(m);
}

static void check_input(int npoints, const double (*points)[3], int nfaces, const int *face_start,
                        const int *face_points, int ninternal_faces, const int *owner,
                        const int *neighbour, int ncells, const double *cell_volume)
{
    if (npoints < 4 || nfaces < 4 || ncells < 1 || ninternal_faces < 0 || ninternal_faces > nfaces)
        dem_fatal("cpl_mesh_init: bad sizes: %d points, %d faces (%d internal), %d cells", npoints, nfaces,
                  ninternal_faces, ncells);
    if (!points || !face_start || !face_points || !owner || (ninternal_faces > 0 && !neighbour))
        dem_fatal("cpl_mesh_init: missing array (points, faces, owner or neighbour)");
    for (int p = 0; p < npoints; p++)
        for (int d = 0; d < 3; d++)
            if (!isfinite(points[p][d])) dem_fatal("cpl_mesh_init: point %d is not finite", p);
    if (face_start[0] != 0) dem_fatal("cpl_mesh_init: face_start[0] = %d, must be 0", face_start[0]);
    for (int f = 0; f < nfaces; f++) {
        if (face_start[f + 1] - face_start[f] < 3)
            dem_fatal("cpl_mesh_init: face %d has %d points (at least 3)", f, face_start[f + 1] - face_start[f]);
        for (int k = face_start[f]; k < face_start[f + 1]; k++)
            if (face_points[k] < 0 || face_points[k] >= npoints)
                dem_fatal("cpl_mesh_init: face %d uses point %d (there are %d)", f, face_points[k], npoints);
        if (owner[f] < 0 || owner[f] >= ncells)
            dem_fatal("cpl_mesh_init: face %d has owner %d (there are %d cells)", f, owner[f], ncells);
        if (f < ninternal_faces && (neighbour[f] < 0 || neighbour[f] >= ncells || neighbour[f] == owner[f]))
            dem_fatal("cpl_mesh_init: internal face %d has neighbour %d (owner %d, %d cells)", f, neighbour[f],
                      owner[f], ncells);
    }
    if (cell_volume)
        for (int c = 0; c < ncells; c++)
            if (!(cell_volume[c] > 0)) dem_fatal("cpl_mesh_init: cell %d has volume %g m^3", c, cell_volume[c]);
}

void cpl_mesh_init(cpl_mesh *m, int npoints, const double (*points)[3], int nfaces, const int *face_start,
                   const int *face_points, int ninternal_faces, const int *owner, const int *neighbour,
                   int ncells, const double (*cell_centre)[3], const double *cell_volume)
{
    memset(m, 0, sizeof *m);
    check_input(npoints, points, nfaces, face_start, face_points, ninternal_faces, owner, neighbour, ncells,
                cell_volume);
    m->npoints = npoints; m->nfaces = nfaces; m->ninternal_faces = ninternal_faces; m->ncells = ncells;
    const int nfp = face_start[nfaces];
    m->points = dem_calloc(npoints, sizeof *m->points);
    m->face_start = dem_calloc(nfaces + 1, sizeof(int));
    m->face_points = dem_calloc(nfp, sizeof(int));
    m->owner = dem_calloc(nfaces, sizeof(int));
    m->neighbour = dem_calloc(ninternal_faces, sizeof(int));
    m->cell_centre = dem_calloc(ncells, sizeof *m->cell_centre);
    m->cell_volume = dem_calloc(ncells, sizeof(double));
    m->face_centre = dem_calloc(nfaces, sizeof *m->face_centre);
    m->face_area = dem_calloc(nfaces, sizeof *m->face_area);
    memcpy(m->points, points, npoints * sizeof *m->points);
    memcpy(m->face_start, face_start, (nfaces + 1) * sizeof(int));
    memcpy(m->face_points, face_points, nfp * sizeof(int));
    memcpy(m->owner, owner, nfaces * sizeof(int));
    if (ninternal_faces) memcpy(m->neighbour, neighbour, ninternal_faces * sizeof(int));
    const int given = cell_centre && cell_volume;
    if (given) {
        memcpy(m->cell_centre, cell_centre, ncells * sizeof *m->cell_centre);
        memcpy(m->cell_volume, cell_volume, ncells * sizeof(double));
    }
    cell_faces(m);
    derive(m, !given);
}

void cpl_mesh_map_points(cpl_mesh *m, void (*map)(double x[3], void *ctx), void *ctx)
{
    for (int p = 0; p < m->npoints; p++) map(m->points[p], ctx);
    derive(m, 1);
}

/* How far x lies outside face f of cell c, along the outward normal [m] (negative inside). */
static double outside_distance(const cpl_mesh *m, const mesh_search *s, int c, int f, const double x[3])
{
    const double *fc = m->face_centre[f], *S = m->face_area[f];
    const double d = ((x[0] - fc[0]) * S[0] + (x[1] - fc[1]) * S[1] + (x[2] - fc[2]) * S[2]) * s->face_inv_mag[f];
    return m->owner[f] == c ? d : -d;
}

int cpl_mesh_inside(const cpl_mesh *m, int c, const double x[3])
{
    const mesh_search *s = m->search;
    if (c < 0 || c >= m->ncells || !isfinite(x[0]) || !isfinite(x[1]) || !isfinite(x[2])) return 0;
    for (int k = m->cell_face_start[c]; k < m->cell_face_start[c + 1]; k++)
        if (outside_distance(m, s, c, m->cell_faces[k], x) > s->cell_tol[c]) return 0;
    return 1;
}

double cpl_mesh_depth(const cpl_mesh *m, int c, const double x[3])
{
    double depth = INFINITY;
    for (int k = m->cell_face_start[c]; k < m->cell_face_start[c + 1]; k++)
        depth = fmin(depth, -outside_distance(m, m->search, c, m->cell_faces[k], x));
    return depth;
}

static int full_search(const cpl_mesh *m, const double x[3])
{
    const mesh_search *s = m->search;
    int g[3];
    for (int d = 0; d < 3; d++) {
        if (!(x[d] >= m->bounds_min[d] && x[d] <= m->bounds_max[d])) return -1;   /* also NaN */
        g[d] = (int)floor((x[d] - s->lo[d]) * s->inv_h[d]);
        if (g[d] >= s->n[d]) g[d] = s->n[d] - 1;
        if (g[d] < 0) g[d] = 0;
    }
    const long gi = g[0] + (long)s->n[0] * (g[1] + (long)s->n[1] * g[2]);
    for (int k = s->start[gi]; k < s->start[gi + 1]; k++)
        if (cpl_mesh_inside(m, s->cells[k], x)) return s->cells[k];
    return -1;
}

int cpl_mesh_locate(const cpl_mesh *m, const double x_in[3], int guess, int *searched)
{
    const mesh_search *s = m->search;
    if (searched) *searched = 0;
    if (!s || !isfinite(x_in[0]) || !isfinite(x_in[1]) || !isfinite(x_in[2])) return -1;
    double x[3] = {x_in[0], x_in[1], x_in[2]};
    if (m->cyclic_partner) cpl_mesh_wrap(m, x);   /* a point beyond a cyclic side is inside, on the other */
    int c = guess;
    for (int step = 0; c >= 0 && c < m->ncells && step < s->walk_cap; step++) {
        /* cross the face whose plane x is furthest outside of; inside all of them: found */
        double worst = s->cell_tol[c];
        int across = -1;
        for (int k = m->cell_face_start[c]; k < m->cell_face_start[c + 1]; k++) {
            const int f = m->cell_faces[k];
            const double d = outside_distance(m, s, c, f, x);
            if (d > worst) { worst = d; across = f; }
        }
        if (across < 0) return c;
        c = cpl_mesh_other_cell(m, across, c);   /* -1 at a boundary: x may be outside, search */
    }
    if (searched) *searched = 1;
    return full_search(m, x);
}

/* ---- Test meshes: axis-aligned boxes of lattice units, faces split where cells differ ---- */

typedef struct lattice_face {
    int owner, neighbour;       /* neighbour -1: boundary */
    int side;                   /* side of the owner: 0 -x, 1 +x, 2 -y, 3 +y, 4 -z, 5 +z */
    int plane, u0, u1, v0, v1;  /* lattice coordinates of the rectangle */
    int seq;                    /* order found, for a deterministic sort */
} lattice_face;

static int lattice_face_cmp(const void *pa, const void *pb)
{
    const lattice_face *a = pa, *b = pb;
    const int ba = a->neighbour < 0, bb = b->neighbour < 0;
    if (ba != bb) return ba - bb;                              /* internal faces first */
    if (!ba) {
        if (a->owner != b->owner) return a->owner - b->owner;  /* upper-triangular order */
        if (a->neighbour != b->neighbour) return a->neighbour - b->neighbour;
    } else {
        if (a->side != b->side) return a->side - b->side;      /* one patch per box side */
        if (a->owner != b->owner) return a->owner - b->owner;
    }
    return a->seq - b->seq;
}

/* Build a mesh from cells given as boxes [b0, b1) x [b2, b3) x [b4, b5) of a lattice of L[0] x
 * L[1] x L[2] units spanning lo..hi. Faces are the rectangles where two cells touch (or a cell
 * touches the domain side), with every lattice vertex on their perimeter among their points. */
static void build_lattice(cpl_mesh *m, const double lo[3], const double hi[3], const int L[3], int nc,
                          const int (*box)[6])
{
    const long nl = (long)L[0] * L[1] * L[2];
    const long np = (long)(L[0] + 1) * (L[1] + 1) * (L[2] + 1);
    int *at = dem_calloc(nl, sizeof(int)), *vid = dem_calloc(np, sizeof(int));
    lattice_face *faces = NULL;
    int nfaces = 0, cap = 0;
#define LAT(i, j, k) ((i) + (long)L[0] * ((j) + (long)L[1] * (k)))
#define VTX(i, j, k) ((i) + (long)(L[0] + 1) * ((j) + (long)(L[1] + 1) * (k)))
    for (long q = 0; q < nl; q++) at[q] = -1;
    for (long q = 0; q < np; q++) vid[q] = -1;
    for (int c = 0; c < nc; c++) {
        const int *b = box[c];
        for (int k = b[4]; k < b[5]; k++)
            for (int j = b[2]; j < b[3]; j++)
                for (int i = b[0]; i < b[1]; i++) at[LAT(i, j, k)] = c;
        for (int corner = 0; corner < 8; corner++)
            vid[VTX(b[corner & 1], b[2 + ((corner >> 1) & 1)], b[4 + ((corner >> 2) & 1)])] = 1;
    }
    int npts = 0;
    for (long q = 0; q < np; q++)
        if (vid[q] > 0) vid[q] = npts++;
    double (*points)[3] = dem_calloc(npts, sizeof *points);
    int *nbr = dem_calloc(nl, sizeof(int));
    for (int k = 0; k <= L[2]; k++)
        for (int j = 0; j <= L[1]; j++)
            for (int i = 0; i <= L[0]; i++) {
                const int p = vid[VTX(i, j, k)];
                if (p < 0) continue;
                const int ijk[3] = {i, j, k};
                for (int d = 0; d < 3; d++) points[p][d] = lo[d] + (hi[d] - lo[d]) * ijk[d] / L[d];
            }
    /* faces: each internal one from its lower-numbered cell */
    for (int c = 0; c < nc; c++) {
        const int *b = box[c];
        for (int side = 0; side < 6; side++) {
            const int a = side / 2, u = (a + 1) % 3, v = (a + 2) % 3, plus = side & 1;
            const int plane = plus ? b[2 * a + 1] : b[2 * a];
            const int layer = plus ? plane : plane - 1;
            int nn = 0;
            if (layer >= 0 && layer < L[a])
                for (int jv = b[2 * v]; jv < b[2 * v + 1]; jv++)
                    for (int ju = b[2 * u]; ju < b[2 * u + 1]; ju++) {
                        int ijk[3];
                        ijk[a] = layer; ijk[u] = ju; ijk[v] = jv;
                        const int n = at[LAT(ijk[0], ijk[1], ijk[2])];
                        int seen = 0;
                        for (int q = 0; q < nn; q++) seen |= nbr[q] == n;
                        if (!seen) nbr[nn++] = n;
                    }
            else
                nbr[nn++] = -1;
            for (int q = 0; q < nn; q++) {
                const int n = nbr[q];
                if (n >= 0 && n < c) continue;
                if (nfaces == cap) {
                    cap = cap ? 2 * cap : 1024;
                    faces = dem_realloc(faces, cap * sizeof *faces);
                }
                lattice_face *F = &faces[nfaces];
                F->owner = c; F->neighbour = n; F->side = side; F->plane = plane; F->seq = nfaces;
                F->u0 = b[2 * u]; F->u1 = b[2 * u + 1]; F->v0 = b[2 * v]; F->v1 = b[2 * v + 1];
                if (n >= 0) {   /* the shared rectangle: intersection of the two cells' sides */
                    const int *bn = box[n];
                    if (bn[2 * u] > F->u0) F->u0 = bn[2 * u];
                    if (bn[2 * u + 1] < F->u1) F->u1 = bn[2 * u + 1];
                    if (bn[2 * v] > F->v0) F->v0 = bn[2 * v];
                    if (bn[2 * v + 1] < F->v1) F->v1 = bn[2 * v + 1];
                }
                nfaces++;
            }
        }
    }
    qsort(faces, nfaces, sizeof *faces, lattice_face_cmp);
    int ninternal = 0;
    while (ninternal < nfaces && faces[ninternal].neighbour >= 0) ninternal++;
    /* face points: walk the rectangle's perimeter counter-clockwise in (u, v), which gives the
     * normal +a (e_u x e_v = e_a); reversed on a minus side, so it points out of the owner */
    int *face_start = dem_calloc(nfaces + 1, sizeof(int));
    int *owner = dem_calloc(nfaces, sizeof(int));
    int *neighbour = dem_calloc(ninternal, sizeof(int));
    long perim = 0;
    for (int f = 0; f < nfaces; f++)
        perim += 2L * (faces[f].u1 - faces[f].u0 + faces[f].v1 - faces[f].v0);
    int *face_points = dem_calloc(perim, sizeof(int));
    int nfp = 0;
    for (int f = 0; f < nfaces; f++) {
        const lattice_face *F = &faces[f];
        const int a = F->side / 2, u = (a + 1) % 3, v = (a + 2) % 3;
        const int first = nfp;
        const int du[4] = {1, 0, -1, 0}, dv[4] = {0, 1, 0, -1};
        int pu = F->u0, pv = F->v0;
        for (int edge = 0; edge < 4; edge++) {
            const int len = edge % 2 == 0 ? F->u1 - F->u0 : F->v1 - F->v0;
            for (int t = 0; t < len; t++) {
                int ijk[3];
                ijk[a] = F->plane; ijk[u] = pu; ijk[v] = pv;
                const int p = vid[VTX(ijk[0], ijk[1], ijk[2])];
                if (p >= 0) face_points[nfp++] = p;
                pu += du[edge]; pv += dv[edge];
            }
        }
        if (!(F->side & 1))
            for (int i = first, j = nfp - 1; i < j; i++, j--) {
                const int t = face_points[i]; face_points[i] = face_points[j]; face_points[j] = t;
            }
        face_start[f + 1] = nfp;
        owner[f] = F->owner;
        if (f < ninternal) neighbour[f] = F->neighbour;
    }
#undef LAT
#undef VTX
    cpl_mesh_init(m, npts, (const double (*)[3])points, nfaces, face_start, face_points, ninternal, owner,
                  neighbour, nc, NULL, NULL);
    free(at); free(vid); free(faces); free(nbr); free(points);
    free(face_start); free(face_points); free(owner); free(neighbour);
}

static void check_box_args(const char *who, const double lo[3], const double hi[3], int nx, int ny, int nz)
{
    if (nx < 1 || ny < 1 || nz < 1 || (long)nx * ny * nz > 100000000L)
        dem_fatal("%s: bad cell counts %d x %d x %d", who, nx, ny, nz);
    for (int d = 0; d < 3; d++)
        if (!(hi[d] > lo[d])) dem_fatal("%s: empty box: lo[%d] = %g m, hi[%d] = %g m", who, d, lo[d], d, hi[d]);
}

void cpl_mesh_box(cpl_mesh *m, const double lo[3], const double hi[3], int nx, int ny, int nz)
{
    memset(m, 0, sizeof *m);
    check_box_args("cpl_mesh_box", lo, hi, nx, ny, nz);
    const int L[3] = {nx, ny, nz};
    const int nc = nx * ny * nz;
    int (*box)[6] = dem_calloc(nc, sizeof *box);
    for (int k = 0; k < nz; k++)
        for (int j = 0; j < ny; j++)
            for (int i = 0; i < nx; i++) {
                int *b = box[i + nx * (j + ny * k)];
                b[0] = i; b[1] = i + 1; b[2] = j; b[3] = j + 1; b[4] = k; b[5] = k + 1;
            }
    build_lattice(m, lo, hi, L, nc, (const int (*)[6])box);
    free(box);
}

void cpl_mesh_box_refined(cpl_mesh *m, const double lo[3], const double hi[3], int nx, int ny, int nz,
                          const int rlo[3], const int rhi[3])
{
    memset(m, 0, sizeof *m);
    check_box_args("cpl_mesh_box_refined", lo, hi, nx, ny, nz);
    const int L[3] = {2 * nx, 2 * ny, 2 * nz};
    int (*box)[6] = dem_calloc(8L * nx * ny * nz, sizeof *box);
    int nc = 0;
    for (int k = 0; k < nz; k++)
        for (int j = 0; j < ny; j++)
            for (int i = 0; i < nx; i++) {
                const int refined = i >= rlo[0] && i < rhi[0] && j >= rlo[1] && j < rhi[1] && k >= rlo[2] && k < rhi[2];
                const int s = refined ? 2 : 1, w = 2 / s;
                for (int c = 0; c < s * s * s; c++) {
                    int *b = box[nc++];
                    const int o[3] = {c % s, (c / s) % s, c / (s * s)};
                    b[0] = 2 * i + w * o[0]; b[1] = b[0] + w;
                    b[2] = 2 * j + w * o[1]; b[3] = b[2] + w;
                    b[4] = 2 * k + w * o[2]; b[5] = b[4] + w;
                }
            }
    build_lattice(m, lo, hi, L, nc, (const int (*)[6])box);
    free(box);
}
