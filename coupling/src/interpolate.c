/* Cell-centred fields at particle positions: cell value, or least-squares linear reconstruction
 * from the cell and its face neighbours. See interpolate.h. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "interpolate.h"

int cpl_interp_scheme_parse(const char *name, enum cpl_interp_scheme *scheme)
{
    if (!strcmp(name, "cell")) *scheme = CPL_INTERP_CELL;
    else if (!strcmp(name, "cellLinear")) *scheme = CPL_INTERP_LINEAR;
    else {
        fprintf(stderr, "interpolation '%s' unknown: use cell or cellLinear\n", name);
        return -1;
    }
    return 0;
}

void cpl_interp_free(cpl_interp *ip)
{
    free(ip->minv); free(ip->field); free(ip->grad);
    memset(ip, 0, sizeof *ip);
}

/* Inverse of the symmetric matrix sum w d d^T of cell c. A small multiple of the trace is added
 * to the diagonal: negligible (1e-12 relative) when the neighbours span 3D, and it makes an
 * unspanned direction's gradient 0 instead of a division by zero (its right-hand side is 0). */
static void lsq_inverse(const cpl_mesh *m, int c, double inv[9])
{
    double a[9] = {0};
    for (int k = m->cell_face_start[c]; k < m->cell_face_start[c + 1]; k++) {
        const int n = cpl_mesh_other_cell(m, m->cell_faces[k], c);
        if (n < 0) continue;
        double d[3];
        for (int i = 0; i < 3; i++) d[i] = m->cell_centre[n][i] - m->cell_centre[c][i];
        const double w = 1.0 / (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
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

int cpl_interp_init(cpl_interp *ip, const cpl_mesh *m, enum cpl_interp_scheme scheme, int ncomp)
{
    memset(ip, 0, sizeof *ip);
    if (ncomp < 1 || ncomp > 64) {
        fprintf(stderr, "interpolation: %d components per cell (1 .. 64)\n", ncomp);
        return -1;
    }
    if (scheme != CPL_INTERP_CELL && scheme != CPL_INTERP_LINEAR) {
        fprintf(stderr, "interpolation: unknown scheme %d\n", (int)scheme);
        return -1;
    }
    ip->scheme = scheme;
    ip->ncells = m->ncells;
    ip->ncomp = ncomp;
    ip->field = calloc((size_t)m->ncells * ncomp, sizeof(double));
    if (scheme == CPL_INTERP_LINEAR) {
        ip->minv = calloc(m->ncells, sizeof *ip->minv);
        ip->grad = calloc((size_t)m->ncells * ncomp * 3, sizeof(double));
    }
    if (!ip->field || (scheme == CPL_INTERP_LINEAR && (!ip->minv || !ip->grad))) {
        fprintf(stderr, "interpolation: out of memory for %d cells\n", m->ncells);
        cpl_interp_free(ip);
        return -1;
    }
    if (scheme == CPL_INTERP_LINEAR)
        for (int c = 0; c < m->ncells; c++) lsq_inverse(m, c, ip->minv[c]);
    return 0;
}

void cpl_interp_set_field(cpl_interp *ip, const cpl_mesh *m, const double *field)
{
    const int nc = ip->ncomp;
    memcpy(ip->field, field, (size_t)ip->ncells * nc * sizeof(double));
    if (ip->scheme != CPL_INTERP_LINEAR) return;
    for (int c = 0; c < ip->ncells; c++) {
        double b[64][3];
        memset(b, 0, (size_t)nc * sizeof b[0]);
        for (int k = m->cell_face_start[c]; k < m->cell_face_start[c + 1]; k++) {
            const int n = cpl_mesh_other_cell(m, m->cell_faces[k], c);
            if (n < 0) continue;
            double d[3];
            for (int i = 0; i < 3; i++) d[i] = m->cell_centre[n][i] - m->cell_centre[c][i];
            const double w = 1.0 / (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
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
