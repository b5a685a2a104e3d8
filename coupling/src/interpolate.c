/* Cell-centred fields at particle positions: cell value, least-squares linear reconstruction
 * from the cell and its face neighbours, or cell-point (tetrahedra). See interpolate.h. Bad
 * arguments and a shortage of memory are fatal errors (error.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "interpolate.h"

int cpl_interp_scheme_parse(const char *name, enum cpl_interp_scheme *scheme)
{
    if (!strcmp(name, "cell")) *scheme = CPL_INTERP_CELL;
    else if (!strcmp(name, "cellLinear")) *scheme = CPL_INTERP_LINEAR;
    else if (!strcmp(name, "cellPoint")) *scheme = CPL_INTERP_CELL_POINT;
    else return -1;
    return 0;
}

void cpl_interp_free(cpl_interp *ip)
{
    free(ip->minv); free(ip->field); free(ip->grad);
    free(ip->pc_start); free(ip->pc_cell); free(ip->pc_w); free(ip->point_value); free(ip->face_value);
    free(ip->pyramid_inv);
    memset(ip, 0, sizeof *ip);
}

/* The neighbour across the k-th face of cell c (-1 on a boundary), the offset d between the
 * centres and the least-squares weight 1/|d|^2. */
static int lsq_neighbour(const cpl_mesh *m, int c, int k, double d[3], double *w)
{
    double shift[3] = {0.0, 0.0, 0.0};   /* across a cyclic face: the other side's cell, moved next to c */
    int n = cpl_mesh_other_cell(m, m->cell_faces[k], c);
    if (n < 0) n = cpl_mesh_cyclic_cell(m, m->cell_faces[k], shift);
    if (n < 0) return -1;
    for (int i = 0; i < 3; i++) d[i] = m->cell_centre[n][i] + shift[i] - m->cell_centre[c][i];
    *w = 1.0 / (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    return n;
}

/* Inverse of the symmetric matrix sum w d d^T of cell c. A small multiple of the trace is added
 * to the diagonal: negligible (1e-12 relative) when the neighbours span 3D, and it makes an
 * unspanned direction's gradient 0 instead of a division by zero (its right-hand side is 0). */
static void lsq_inverse(const cpl_mesh *m, int c, double inv[9])
{
    double a[9] = {0};
    for (int k = m->cell_face_start[c]; k < m->cell_face_start[c + 1]; k++) {
        double d[3], w;
        if (lsq_neighbour(m, c, k, d, &w) < 0) continue;
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) a[3 * i + j] += w * d[i] * d[j];
    }
    const double eps = 1e-12 * (a[0] + a[4] + a[8]);
    for (int i = 0; i < 3; i++) a[4 * i] += eps;
    /* adjugate / determinant */
    inv[0] = a[4] * a[8] - a[5] * a[7];
    inv[1] = a[2] * a[7] - a[1] * a[8];
    inv[2] = a[1] * a[5] - a[2] * a[4];
    inv[3] = a[5] * a[6] - a[3] * a[8];
    inv[4] = a[0] * a[8] - a[2] * a[6];
    inv[5] = a[2] * a[3] - a[0] * a[5];
    inv[6] = a[3] * a[7] - a[4] * a[6];
    inv[7] = a[1] * a[6] - a[0] * a[7];
    inv[8] = a[0] * a[4] - a[1] * a[3];
    const double det = a[0] * inv[0] + a[1] * inv[3] + a[2] * inv[6];
    if (!(fabs(det) > 0) || !isfinite(det)) {   /* no neighbours: cell value only */
        memset(inv, 0, 9 * sizeof(double));
        return;
    }
    for (int i = 0; i < 9; i++) inv[i] /= det;
}

/* cellPoint at cyclic sides: a point on a cyclic face and the point it meets on the partner face
 * are one point of the periodic mesh; each takes the cells of both (so the two get one value and
 * the interpolation is continuous across the side; their distances go to the cells' images). */
static void cyclic_point_cells(cpl_interp *ip, const cpl_mesh *m)
{
    const int np = m->npoints;
    int *partner = dem_malloc((size_t)np * sizeof(int));
    for (int q = 0; q < np; q++) partner[q] = -1;
    for (int f = m->ninternal_faces; f < m->nfaces; f++) {
        const int g = m->cyclic_partner[f - m->ninternal_faces];
        if (g < 0) continue;
        double shift[3];   /* x on g + shift = x on f */
        for (int d = 0; d < 3; d++) shift[d] = m->face_centre[f][d] - m->face_centre[g][d];
        for (int e = m->face_start[f]; e < m->face_start[f + 1]; e++) {
            const int p = m->face_points[e];
            double best = INFINITY;
            for (int e2 = m->face_start[g]; e2 < m->face_start[g + 1]; e2++) {
                const int q = m->face_points[e2];
                double d2 = 0.0;
                for (int d = 0; d < 3; d++) d2 += (m->points[q][d] + shift[d] - m->points[p][d]) * (m->points[q][d] + shift[d] - m->points[p][d]);
                if (d2 < best) { best = d2; partner[p] = q; }
            }
        }
    }
    int *start = dem_malloc(((size_t)np + 1) * sizeof(int));
    start[0] = 0;
    for (int q = 0; q < np; q++) {
        const int own = ip->pc_start[q + 1] - ip->pc_start[q];
        const int other = partner[q] >= 0 ? ip->pc_start[partner[q] + 1] - ip->pc_start[partner[q]] : 0;
        start[q + 1] = start[q] + own + other;
    }
    int *cell = dem_malloc((size_t)(start[np] ? start[np] : 1) * sizeof(int));
    for (int q = 0; q < np; q++) {
        int n = start[q];
        for (int k = ip->pc_start[q]; k < ip->pc_start[q + 1]; k++) cell[n++] = ip->pc_cell[k];
        if (partner[q] >= 0)
            for (int k = ip->pc_start[partner[q]]; k < ip->pc_start[partner[q] + 1]; k++) cell[n++] = ip->pc_cell[k];
    }
    free(ip->pc_start);
    free(ip->pc_cell);
    free(ip->pc_w);
    ip->pc_start = start;
    ip->pc_cell = cell;
    ip->pc_w = dem_malloc((size_t)(start[np] ? start[np] : 1) * sizeof(double));
    free(partner);
}

/* cellPoint: the cells around each point (through the faces of each cell) and their
 * inverse-distance weights. */
static void point_cells(cpl_interp *ip, const cpl_mesh *m, int ncomp)
{
    const int np = m->npoints;
    int *count = dem_calloc((size_t)np + 1, sizeof(int));
    int *last = dem_malloc((size_t)np * sizeof(int));
    for (int pass = 0; pass < 2; pass++) {
        for (int q = 0; q < np; q++) last[q] = -1;
        for (int c = 0; c < m->ncells; c++)
            for (int k = m->cell_face_start[c]; k < m->cell_face_start[c + 1]; k++) {
                const int f = m->cell_faces[k];
                for (int e = m->face_start[f]; e < m->face_start[f + 1]; e++) {
                    const int q = m->face_points[e];
                    if (last[q] == c) continue;   /* a point is on several faces of the cell */
                    last[q] = c;
                    if (pass == 0) count[q + 1]++;
                    else ip->pc_cell[count[q]++] = c;
                }
            }
        if (pass == 0) {
            for (int q = 0; q < np; q++) count[q + 1] += count[q];
            ip->pc_start = dem_malloc(((size_t)np + 1) * sizeof(int));
            ip->pc_cell = dem_malloc((size_t)count[np] * sizeof(int));
            ip->pc_w = dem_malloc((size_t)count[np] * sizeof(double));
            ip->point_value = dem_calloc((size_t)np * ncomp, sizeof(double));
            ip->face_value = dem_calloc((size_t)m->nfaces * ncomp, sizeof(double));
            memcpy(ip->pc_start, count, ((size_t)np + 1) * sizeof(int));
        }
    }
    free(count); free(last);
    if (m->cyclic_partner) cyclic_point_cells(ip, m);
    /* 1 / ((x_f - x_c).A_f) of each cell's faces (cell_faces order), for the pyramid choice */
    ip->pyramid_inv = dem_malloc((size_t)m->cell_face_start[m->ncells] * sizeof(double));
    for (int c = 0; c < m->ncells; c++)
        for (int k = m->cell_face_start[c]; k < m->cell_face_start[c + 1]; k++) {
            const double *a = m->face_area[m->cell_faces[k]], *xf = m->face_centre[m->cell_faces[k]], *xc = m->cell_centre[c];
            ip->pyramid_inv[k] = 1.0 / ((xf[0] - xc[0]) * a[0] + (xf[1] - xc[1]) * a[1] + (xf[2] - xc[2]) * a[2]);
        }
    for (int q = 0; q < np; q++) {
        double sum = 0.0;
        for (int k = ip->pc_start[q]; k < ip->pc_start[q + 1]; k++) {
            const double *xp = m->points[q];
            double xc[3];
            for (int d = 0; d < 3; d++) xc[d] = m->cell_centre[ip->pc_cell[k]][d];
            if (m->cyclic_partner) {   /* a cell across a cyclic side: its image nearest the point */
                for (int d = 0; d < 3; d++)
                    if (m->periodic[d]) xc[d] -= m->period[d] * nearbyint((xc[d] - xp[d]) / m->period[d]);
            }
            const double d = sqrt((xc[0] - xp[0]) * (xc[0] - xp[0]) + (xc[1] - xp[1]) * (xc[1] - xp[1]) +
                                  (xc[2] - xp[2]) * (xc[2] - xp[2]));
            ip->pc_w[k] = 1.0 / d;
            sum += ip->pc_w[k];
        }
        for (int k = ip->pc_start[q]; k < ip->pc_start[q + 1]; k++) ip->pc_w[k] /= sum;
    }
}

/* Barycentric coordinates of x in the tetrahedron (a, b, c, d); returns the smallest. */
static double barycentric(const double *a, const double *b, const double *c, const double *d,
                          const double x[3], double l[4])
{
    double e1[3], e2[3], e3[3], r[3];
    for (int i = 0; i < 3; i++) { e1[i] = b[i] - a[i]; e2[i] = c[i] - a[i]; e3[i] = d[i] - a[i]; r[i] = x[i] - a[i]; }
    const double det = e1[0] * (e2[1] * e3[2] - e2[2] * e3[1]) - e1[1] * (e2[0] * e3[2] - e2[2] * e3[0]) +
                       e1[2] * (e2[0] * e3[1] - e2[1] * e3[0]);
    if (!(fabs(det) > 0)) { l[0] = 1; l[1] = l[2] = l[3] = 0; return -INFINITY; }
    /* Cramer's rule for r = l1 e1 + l2 e2 + l3 e3 */
    l[1] = (r[0] * (e2[1] * e3[2] - e2[2] * e3[1]) - r[1] * (e2[0] * e3[2] - e2[2] * e3[0]) +
            r[2] * (e2[0] * e3[1] - e2[1] * e3[0])) / det;
    l[2] = (e1[0] * (r[1] * e3[2] - r[2] * e3[1]) - e1[1] * (r[0] * e3[2] - r[2] * e3[0]) +
            e1[2] * (r[0] * e3[1] - r[1] * e3[0])) / det;
    l[3] = (e1[0] * (e2[1] * r[2] - e2[2] * r[1]) - e1[1] * (e2[0] * r[2] - e2[2] * r[0]) +
            e1[2] * (e2[0] * r[1] - e2[1] * r[0])) / det;
    l[0] = 1.0 - l[1] - l[2] - l[3];
    return fmin(fmin(l[0], l[1]), fmin(l[2], l[3]));
}

/* The tetrahedra of face f (cell centre, face centre, two consecutive points): the one holding
 * x, or the one it is least outside of; updates best/bf/bp/lb, returns 1 when x is inside. */
static int face_tets(const cpl_mesh *m, int c, int f, const double x[3], double *best, int *bf, int *bp, double lb[4])
{
    const int s = m->face_start[f], n = m->face_start[f + 1] - s;
    for (int e = 0; e < n; e++) {
        double l[4];
        const double lo = barycentric(m->cell_centre[c], m->face_centre[f], m->points[m->face_points[s + e]],
                                      m->points[m->face_points[s + (e + 1) % n]], x, l);
        if (lo > *best) { *best = lo; *bf = f; *bp = e; memcpy(lb, l, 4 * sizeof *lb); }
        if (lo >= 0.0) return 1;
    }
    return 0;
}

/* The tetrahedron of face f that should hold x: the face's triangle (face centre, two
 * consecutive points) whose sector around the face centre holds y, where the ray from the cell
 * centre through x meets the face's plane (y = x_c + (x - x_c)/t, t from cell_point_at); one
 * barycentric evaluation. Returns 1 when x is inside it (else the caller searches). */
static int sector_tet(const cpl_mesh *m, int c, int f, double t, const double x[3], double *best, int *bf,
                      int *bp, double lb[4])
{
    if (!(t > 0.0)) return 0;
    const double *xc = m->cell_centre[c], *cf = m->face_centre[f], *a = m->face_area[f];
    const int s = m->face_start[f], n = m->face_start[f + 1] - s;
    if (n > 64) return 0;
    double y[3];
    for (int i = 0; i < 3; i++) y[i] = xc[i] + (x[i] - xc[i]) / t - cf[i];
    /* side[e] = A.((p_e - x_f) x y): y lies in the sector of edge e (from p_e to p_e+1) when it is
     * on the positive side of p_e's spoke and not on the positive side of p_e+1's (the area
     * vector follows the face's points by the right-hand rule, so A.(u_e x u_e+1) > 0 on a
     * convex face; a non-convex one falls back to the search) */
    double side[65];
    for (int e = 0; e < n; e++) {
        const double *pe = m->points[m->face_points[s + e]];
        const double u[3] = {pe[0] - cf[0], pe[1] - cf[1], pe[2] - cf[2]};
        side[e] = a[0] * (u[1] * y[2] - u[2] * y[1]) + a[1] * (u[2] * y[0] - u[0] * y[2]) +
                  a[2] * (u[0] * y[1] - u[1] * y[0]);
    }
    side[n] = side[0];
    for (int e = 0; e < n; e++) {
        if (side[e] < 0.0 || side[e + 1] > 0.0) continue;
        double l[4];
        const double lo = barycentric(xc, cf, m->points[m->face_points[s + e]],
                                      m->points[m->face_points[s + (e + 1) % n]], x, l);
        if (lo > *best) { *best = lo; *bf = f; *bp = e; memcpy(lb, l, 4 * sizeof *lb); }
        return lo >= 0.0;
    }
    return 0;
}

/* cellPoint at x in cell c: the tetrahedron holding x (or, if rounding puts x outside all of
 * them, the one it is least outside of). In a convex cell x lies in the pyramid (cell centre,
 * face) of the face whose plane the ray from the centre through x reaches first, the largest
 * (x - x_c).A_f / ((x_f - x_c).A_f); its tetrahedra are tried first, the others only if x is
 * in none of them (a non-convex cell). */
static void cell_point_locate(const cpl_interp *ip, const cpl_mesh *m, int c, const double x[3], cpl_interp_tet *t);

static void cell_point_apply(const cpl_interp *ip, const cpl_mesh *m, const cpl_interp_tet *t, double *out)
{
    const int nc = ip->ncomp;
    const double *u = ip->field + (size_t)t->cell * nc;
    if (t->face < 0) { for (int j = 0; j < nc; j++) out[j] = u[j]; return; }
    const int s = m->face_start[t->face], n = m->face_start[t->face + 1] - s;
    const int pa = m->face_points[s + t->edge], pb = m->face_points[s + (t->edge + 1) % n];
    const double *uf = ip->face_value + (size_t)t->face * nc;   /* the mean of the face's points */
    const double *l = t->l;
    for (int j = 0; j < nc; j++)
        out[j] = l[0] * u[j] + l[1] * uf[j] + l[2] * ip->point_value[(size_t)pa * nc + j] +
                 l[3] * ip->point_value[(size_t)pb * nc + j];
}

static void cell_point_at(const cpl_interp *ip, const cpl_mesh *m, int c, const double x[3], double *out)
{
    cpl_interp_tet t;
    cell_point_locate(ip, m, c, x, &t);
    cell_point_apply(ip, m, &t, out);
}

static void cell_point_locate(const cpl_interp *ip, const cpl_mesh *m, int c, const double x[3], cpl_interp_tet *tet)
{
    const double *xc = m->cell_centre[c];
    const double r[3] = {x[0] - xc[0], x[1] - xc[1], x[2] - xc[2]};
    double best = -INFINITY, lb[4] = {1, 0, 0, 0}, t_max = -INFINITY;
    int bf = -1, bp = -1, first = -1;
    for (int k = m->cell_face_start[c]; k < m->cell_face_start[c + 1]; k++) {
        const double *a = m->face_area[m->cell_faces[k]];
        const double t = (r[0] * a[0] + r[1] * a[1] + r[2] * a[2]) * ip->pyramid_inv[k];
        if (t > t_max) { t_max = t; first = m->cell_faces[k]; }
    }
    if (first < 0 || !sector_tet(m, c, first, t_max, x, &best, &bf, &bp, lb))
        if (first < 0 || !face_tets(m, c, first, x, &best, &bf, &bp, lb))
        for (int k = m->cell_face_start[c]; k < m->cell_face_start[c + 1]; k++)
            if (m->cell_faces[k] != first && face_tets(m, c, m->cell_faces[k], x, &best, &bf, &bp, lb)) break;
    tet->cell = c;
    tet->face = bf;
    tet->edge = bp;
    memcpy(tet->l, lb, sizeof lb);
}

void cpl_interp_init(cpl_interp *ip, const cpl_mesh *m, enum cpl_interp_scheme scheme, int ncomp)
{
    memset(ip, 0, sizeof *ip);
    if (ncomp < 1 || ncomp > 64) dem_fatal("interpolation: %d components per cell (1 .. 64)", ncomp);
    if (scheme != CPL_INTERP_CELL && scheme != CPL_INTERP_LINEAR && scheme != CPL_INTERP_CELL_POINT)
        dem_fatal("interpolation: unknown scheme %d", (int)scheme);
    ip->scheme = scheme;
    ip->ncells = m->ncells;
    ip->ncomp = ncomp;
    ip->field = dem_calloc((size_t)m->ncells * ncomp, sizeof(double));
    if (scheme == CPL_INTERP_LINEAR) {
        ip->minv = dem_calloc(m->ncells, sizeof *ip->minv);
        ip->grad = dem_calloc((size_t)m->ncells * ncomp * 3, sizeof(double));
        for (int c = 0; c < m->ncells; c++) lsq_inverse(m, c, ip->minv[c]);
    }
    if (scheme == CPL_INTERP_CELL_POINT) point_cells(ip, m, ncomp);
}

void cpl_interp_set_field(cpl_interp *ip, const cpl_mesh *m, const double *field)
{
    const int nc = ip->ncomp;
    memcpy(ip->field, field, (size_t)ip->ncells * nc * sizeof(double));
    if (ip->scheme == CPL_INTERP_CELL_POINT) {
        for (int q = 0; q < m->npoints; q++)
            for (int j = 0; j < nc; j++) {
                double v = 0.0;
                for (int k = ip->pc_start[q]; k < ip->pc_start[q + 1]; k++)
                    v += ip->pc_w[k] * field[(size_t)ip->pc_cell[k] * nc + j];
                ip->point_value[(size_t)q * nc + j] = v;
            }
        for (int f = 0; f < m->nfaces; f++) {   /* face centres: the mean of their points */
            const int s = m->face_start[f], n = m->face_start[f + 1] - s;
            for (int j = 0; j < nc; j++) {
                double v = 0.0;
                for (int e = 0; e < n; e++) v += ip->point_value[(size_t)m->face_points[s + e] * nc + j];
                ip->face_value[(size_t)f * nc + j] = v / n;
            }
        }
        return;
    }
    if (ip->scheme != CPL_INTERP_LINEAR) return;
    for (int c = 0; c < ip->ncells; c++) {
        double b[64][3];
        memset(b, 0, (size_t)nc * sizeof b[0]);
        for (int k = m->cell_face_start[c]; k < m->cell_face_start[c + 1]; k++) {
            double d[3], w;
            const int n = lsq_neighbour(m, c, k, d, &w);
            if (n < 0) continue;
            for (int j = 0; j < nc; j++) {
                const double du = w * (field[(size_t)n * nc + j] - field[(size_t)c * nc + j]);
                for (int i = 0; i < 3; i++) b[j][i] += du * d[i];
            }
        }
        const double *inv = ip->minv[c];
        double *g = ip->grad + (size_t)c * nc * 3;
        for (int j = 0; j < nc; j++)
            for (int i = 0; i < 3; i++)
                g[3 * j + i] = inv[3 * i] * b[j][0] + inv[3 * i + 1] * b[j][1] + inv[3 * i + 2] * b[j][2];
    }
}

int cpl_interp_at(const cpl_interp *ip, const cpl_mesh *m, int cell, const double x[3], double *out)
{
    const int nc = ip->ncomp;
    if (cell < 0 || cell >= ip->ncells) {
        for (int j = 0; j < nc; j++) out[j] = 0.0;
        return -1;
    }
    const double *u = ip->field + (size_t)cell * nc;
    if (ip->scheme == CPL_INTERP_CELL) {
        for (int j = 0; j < nc; j++) out[j] = u[j];
        return 0;
    }
    if (ip->scheme == CPL_INTERP_CELL_POINT) {
        cell_point_at(ip, m, cell, x, out);
        return 0;
    }
    const double *xc = m->cell_centre[cell], *g = ip->grad + (size_t)cell * nc * 3;
    const double r[3] = {x[0] - xc[0], x[1] - xc[1], x[2] - xc[2]};
    for (int j = 0; j < nc; j++) out[j] = u[j] + g[3 * j] * r[0] + g[3 * j + 1] * r[1] + g[3 * j + 2] * r[2];
    return 0;
}

int cpl_interp_particles(const cpl_interp *ip, const cpl_mesh *m, int np, const int *cell,
                         const double (*x)[3], double *out)
{
    int outside = 0;
    for (int i = 0; i < np; i++) outside += cpl_interp_at(ip, m, cell[i], x[i], out + (size_t)i * ip->ncomp) != 0;
    return outside;
}

int cpl_interp_locate(const cpl_interp *ip, const cpl_mesh *m, int np, const int *cell, const double (*x)[3],
                      cpl_interp_tet *tets)
{
    int outside = 0;
    for (int i = 0; i < np; i++) {
        const int c = cell[i];
        if (c < 0 || c >= ip->ncells) { tets[i].cell = -1; outside++; continue; }
        cpl_interp_tet *t = &tets[i];
        if (t->cell == c && t->face >= 0) {   /* still in the tetrahedron it was in? (one test) */
            const int f = t->face, s = m->face_start[f], n = m->face_start[f + 1] - s;
            double l[4];
            if (barycentric(m->cell_centre[c], m->face_centre[f], m->points[m->face_points[s + t->edge]],
                            m->points[m->face_points[s + (t->edge + 1) % n]], x[i], l) >= 0.0) {
                memcpy(t->l, l, sizeof l);
                continue;
            }
        }
        cell_point_locate(ip, m, c, x[i], t);
    }
    return outside;
}

void cpl_interp_apply(const cpl_interp *ip, const cpl_mesh *m, int np, const cpl_interp_tet *tets, double *out)
{
    const int nc = ip->ncomp;
    for (int i = 0; i < np; i++) {
        double *o = out + (size_t)i * nc;
        if (tets[i].cell < 0) { for (int j = 0; j < nc; j++) o[j] = 0.0; continue; }
        cell_point_apply(ip, m, &tets[i], o);
    }
}
