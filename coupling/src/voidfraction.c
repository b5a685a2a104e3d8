/* Void fraction models (centre, divided, gaussian) and the per-particle cell weights they leave
 * behind for the momentum exchange. See voidfraction.h. Bad arguments and a shortage of memory
 * are fatal errors (error.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "voidfraction.h"

int cpl_vf_model_parse(const char *name, enum cpl_vf_model *model)
{
    if (!strcmp(name, "centre")) *model = CPL_VF_CENTRE;
    else if (!strcmp(name, "divided")) *model = CPL_VF_DIVIDED;
    else if (!strcmp(name, "gaussian")) *model = CPL_VF_GAUSSIAN;
    else return -1;
    return 0;
}

void cpl_vf_free(cpl_voidfraction *vf)
{
    free(vf->sample); free(vf->vp); free(vf->alpha);
    free(vf->w_start); free(vf->w_cell); free(vf->w);
    free(vf->mark); free(vf->queue); free(vf->queue_shift);
    memset(vf, 0, sizeof *vf);
}

void cpl_vf_set_samples(cpl_voidfraction *vf, int nshell, int nper)
{
    if (nshell < 1 || nper < 4 || nper % 4 != 0 || (long)nshell * nper > 100000)
        dem_fatal("divided void fraction: %d shells of %d points: need at least one shell and a multiple of 4 "
                  "points per shell", nshell, nper);
    double (*s)[3] = dem_malloc((size_t)nshell * nper * sizeof *s);
    /* Shell k holds the volume between radii (k/K)^(1/3) and ((k+1)/K)^(1/3): its points sit at
     * the volume median ((k + 1/2)/K)^(1/3). On each shell, a spiral of nper/2 points (uniform in
     * z, which is uniform in area; nper/2 even, so none has z = 0; the half-step phase keeps them
     * off the x and y planes) and their opposites, so a plane through the centre cuts exactly
     * half of them. Each shell is turned about z so that shells do not line up. */
    const double golden = M_PI * (3.0 - sqrt(5.0));
    const int half = nper / 2;
    int n = 0;
    for (int k = 0; k < nshell; k++) {
        const double rho = cbrt((k + 0.5) / nshell);
        for (int j = 0; j < half; j++) {
            const double z = 1.0 - (2.0 * j + 1.0) / half;
            const double phi = (j + 0.5) * golden + 1.2 * k;
            const double sxy = sqrt(1.0 - z * z);
            const double p[3] = {rho * sxy * cos(phi), rho * sxy * sin(phi), rho * z};
            for (int d = 0; d < 3; d++) { s[n][d] = p[d]; s[n + 1][d] = -p[d]; }
            n += 2;
        }
    }
    free(vf->sample);
    vf->sample = s;
    vf->nsample = n;
}

void cpl_vf_init(cpl_voidfraction *vf, const cpl_mesh *m, enum cpl_vf_model model, double alpha_min)
{
    memset(vf, 0, sizeof *vf);
    if (!(alpha_min >= 0.0 && alpha_min < 1.0))
        dem_fatal("void fraction: alphaMin = %g must be in [0, 1)", alpha_min);
    if (model != CPL_VF_CENTRE && model != CPL_VF_DIVIDED && model != CPL_VF_GAUSSIAN)
        dem_fatal("void fraction: unknown model %d", (int)model);
    vf->model = model;
    vf->alpha_min = alpha_min;
    vf->kernel_width = 0.5;
    vf->kernel_cutoff = 3.0;
    vf->ncells = m->ncells;
    vf->vp = dem_calloc(m->ncells, sizeof(double));
    vf->alpha = dem_calloc(m->ncells, sizeof(double));
    vf->mark = dem_calloc(m->ncells, sizeof(unsigned));
    vf->queue = dem_calloc(m->ncells, sizeof(int));
    vf->queue_shift = dem_calloc(m->ncells, sizeof *vf->queue_shift);
    vf->w_start = dem_calloc(1, sizeof(int));
    for (int c = 0; c < m->ncells; c++) vf->alpha[c] = 1.0;
    cpl_vf_set_samples(vf, 4, 16);
}

/* Append (cell, weight) to the weight list. */
static void push(cpl_voidfraction *vf, int *nw, int cell, double w)
{
    if (*nw == vf->w_cap) {
        vf->w_cap = vf->w_cap ? 2 * vf->w_cap : 1024;
        vf->w_cell = dem_realloc(vf->w_cell, vf->w_cap * sizeof(int));
        vf->w = dem_realloc(vf->w, vf->w_cap * sizeof(double));
    }
    vf->w_cell[*nw] = cell;
    vf->w[*nw] = w;
    (*nw)++;
}

/* divided: each sample point's share to its own cell; points beyond a cyclic side are located
 * on the other side (cpl_mesh_locate wraps them), points outside the mesh (beyond a wall)
 * dropped and the rest renormalised (by cpl_vf_finish: the points found on every rank). Unscaled
 * here: one per point found. c < 0 (the centre on another rank's cells): the points are sought
 * from scratch, and those found here are this rank's share. Returns the sum of the weights. */
static double weights_divided(cpl_voidfraction *vf, const cpl_mesh *m, const double x[3], double r, int c, int *nw)
{
    /* the whole sphere inside the cell (the common case of particles smaller than cells): every
     * point would be found there, skip locating them */
    if (c >= 0 && cpl_mesh_depth(m, c, x) >= r) { push(vf, nw, c, 1.0); return 1.0; }
    const int first = *nw;
    int inside = 0, guess = c;
    for (int k = 0; k < vf->nsample; k++) {
        double xs[3];
        for (int d = 0; d < 3; d++) xs[d] = x[d] + r * vf->sample[k][d];
        if (c < 0) {   /* sought only where this rank's cells are */
            int near = 1;
            for (int d = 0; d < 3; d++)
                if (!m->periodic[d] && (xs[d] < m->bounds_min[d] || xs[d] > m->bounds_max[d])) near = 0;
            if (!near) continue;
        }
        const int cs = cpl_mesh_locate(m, xs, guess, NULL);
        if (cs < 0) continue;
        if (c < 0) guess = cs;
        inside++;
        int j = first;
        while (j < *nw && vf->w_cell[j] != cs) j++;
        if (j < *nw) vf->w[j] += 1.0;
        else push(vf, nw, cs, 1.0);
    }
    /* only the centre is in the mesh: the whole volume there (weight 0 now; cpl_vf_finish makes it
     * 1 when no rank found a point) */
    if (inside == 0 && c >= 0) push(vf, nw, c, 0.0);
    return inside;
}

/* gaussian: breadth-first through faces from the particle's cell, over cells whose centres are
 * within the cutoff; weights V_c exp(-d^2 / 2 s^2) (the kernel times the cell's volume: the
 * kernel's integral over the cell), normalised over the cells found (cpl_vf_finish; the sum is
 * returned). Across a cyclic face the
 * search goes on in the cells of the other side, each at its centre shifted by the period (the
 * shift travels with the queue), so the kernel sees the periodic image of the mesh. */
static double weights_gaussian(cpl_voidfraction *vf, const cpl_mesh *m, const double x[3], double r, int c, int *nw)
{
    const double s = vf->kernel_width * 2.0 * r, cut = vf->kernel_cutoff * s;
    for (int d = 0; d < 3; d++)   /* one image of each cell within the cutoff */
        if (m->periodic[d] && !(2.0 * cut < m->period[d]))
            dem_fatal("gaussian void fraction: the kernel's reach %g m (kernelCutoff x kernelWidth x d) is more than half "
                      "the period %g m of the cyclic direction %c: lower kernelCutoff or kernelWidth", cut, m->period[d],
                      "xyz"[d]);
    if (++vf->stamp == 0) {   /* wrapped: clear the marks */
        memset(vf->mark, 0, vf->ncells * sizeof(unsigned));
        vf->stamp = 1;
    }
    int head = 0, tail = 0;
    vf->queue[tail] = c;
    memset(vf->queue_shift[tail++], 0, sizeof vf->queue_shift[0]);
    vf->mark[c] = vf->stamp;
    const int first = *nw;
    double d2min = INFINITY;
    while (head < tail) {
        const int a = vf->queue[head];
        const double *sa = vf->queue_shift[head++];
        double d2 = 0;
        for (int d = 0; d < 3; d++) d2 += (m->cell_centre[a][d] + sa[d] - x[d]) * (m->cell_centre[a][d] + sa[d] - x[d]);
        if (d2 < d2min) d2min = d2;
        push(vf, nw, a, d2);   /* distance^2 for now, weight below */
        for (int k = m->cell_face_start[a]; k < m->cell_face_start[a + 1]; k++) {
            const int f = m->cell_faces[k];
            double sn[3] = {sa[0], sa[1], sa[2]}, across[3];
            int n = cpl_mesh_other_cell(m, f, a);
            if (n < 0 && (n = cpl_mesh_cyclic_cell(m, f, across)) >= 0)
                for (int d = 0; d < 3; d++) sn[d] += across[d];
            if (n < 0 || vf->mark[n] == vf->stamp) continue;
            vf->mark[n] = vf->stamp;
            double dn2 = 0;
            for (int d = 0; d < 3; d++) dn2 += (m->cell_centre[n][d] + sn[d] - x[d]) * (m->cell_centre[n][d] + sn[d] - x[d]);
            if (dn2 <= cut * cut) {
                vf->queue[tail] = n;
                memcpy(vf->queue_shift[tail++], sn, sizeof sn);
            }
        }
    }
    /* relative to the nearest centre, so that a kernel narrow compared with the cells cannot
     * underflow to all zeros */
    double sum = 0;
    for (int j = first; j < *nw; j++) {
        vf->w[j] = m->cell_volume[vf->w_cell[j]] * exp(-(vf->w[j] - d2min) / (2.0 * s * s));
        sum += vf->w[j];
    }
    return sum;
}

int cpl_vf_compute(cpl_voidfraction *vf, const cpl_mesh *m, int np, const double (*x)[3],
                   const double *r, int *cell)
{
    return cpl_vf_compute_volumes(vf, m, np, x, r, NULL, cell);
}

int cpl_vf_compute_volumes(cpl_voidfraction *vf, const cpl_mesh *m, int np, const double (*x)[3],
                           const double *r, const double *volume, int *cell)
{
    double *z = dem_malloc(((size_t)np + 1) * sizeof *z), *found = dem_malloc(((size_t)np + 1) * sizeof *found);
    cpl_vf_weigh(vf, m, np, x, r, cell, z);
    int outside = 0;
    for (int i = 0; i < np; i++) {
        found[i] = cell[i] >= 0;
        outside += cell[i] < 0;
    }
    cpl_vf_finish(vf, m, z, found, r, volume);
    free(z);
    free(found);
    return outside;
}

void cpl_vf_weigh(cpl_voidfraction *vf, const cpl_mesh *m, int np, const double (*x)[3], const double *r, int *cell,
                  double *z)
{
    if (np < 0 || m->ncells != vf->ncells)
        dem_fatal("void fraction: %d particles, mesh of %d cells (set up for %d)", np, m->ncells, vf->ncells);
    for (int i = 0; i < np; i++)
        if (!(r[i] > 0) || !isfinite(r[i])) dem_fatal("void fraction: particle %d has radius %g m", i, r[i]);
    if (np + 1 > vf->np_cap) {
        vf->w_start = dem_realloc(vf->w_start, (np + 1) * sizeof(int));
        vf->np_cap = np + 1;
    }
    if (vf->model == CPL_VF_GAUSSIAN && !(vf->kernel_width > 0 && vf->kernel_cutoff > 0))
        dem_fatal("gaussian void fraction: kernel width %g and cutoff %g must be positive", vf->kernel_width,
                  vf->kernel_cutoff);
    int nw = 0;
    vf->np = np;
    for (int i = 0; i < np; i++) {
        vf->w_start[i] = nw;
        z[i] = 0.0;
        const int guess = cell[i] >= 0 && cell[i] < m->ncells ? cell[i] : -1;
        double xi[3] = {x[i][0], x[i][1], x[i][2]};
        cpl_mesh_wrap(m, xi);   /* the image in the mesh, if a cyclic side was crossed */
        const int c = cpl_mesh_locate(m, xi, guess, NULL);
        cell[i] = c;
        switch (vf->model) {
        case CPL_VF_CENTRE:
            if (c >= 0) { push(vf, &nw, c, 1.0); z[i] = 1.0; }
            break;
        case CPL_VF_DIVIDED:
            if (c >= 0 || vf->partial) z[i] = weights_divided(vf, m, xi, r[i], c, &nw);
            break;
        case CPL_VF_GAUSSIAN:
            if (c >= 0) z[i] = weights_gaussian(vf, m, xi, r[i], c, &nw);
            break;
        }
    }
    vf->w_start[np] = nw;
}

void cpl_vf_finish(cpl_voidfraction *vf, const cpl_mesh *m, const double *norm, const double *found, const double *r,
                   const double *volume)
{
    const int np = vf->np;
    for (int i = 0; i < np; i++) {
        for (int k = vf->w_start[i]; k < vf->w_start[i + 1]; k++) {
            if (!(found[i] > 0)) vf->w[k] = 0.0;           /* the centre outside the mesh: not mapped */
            else if (norm[i] > 0) vf->w[k] /= norm[i];
            else vf->w[k] = 1.0;                           /* divided: only the centre was found */
        }
    }
    memset(vf->vp, 0, vf->ncells * sizeof(double));
    for (int i = 0; i < np; i++) {
        const double vol = volume ? volume[i] : 4.0 / 3.0 * M_PI * r[i] * r[i] * r[i];
        for (int k = vf->w_start[i]; k < vf->w_start[i + 1]; k++) vf->vp[vf->w_cell[k]] += vf->w[k] * vol;
    }
    for (int c = 0; c < vf->ncells; c++) vf->alpha[c] = fmax(vf->alpha_min, 1.0 - vf->vp[c] / m->cell_volume[c]);
}

void cpl_vf_spread(const cpl_voidfraction *vf, int ncomp, const double *q, double *out)
{
    memset(out, 0, (size_t)vf->ncells * ncomp * sizeof(double));
    for (int i = 0; i < vf->np; i++)
        for (int k = vf->w_start[i]; k < vf->w_start[i + 1]; k++)
            for (int j = 0; j < ncomp; j++) out[(size_t)vf->w_cell[k] * ncomp + j] += vf->w[k] * q[(size_t)i * ncomp + j];
}

void cpl_vf_gather(const cpl_voidfraction *vf, int ncomp, const double *field, double *out)
{
    memset(out, 0, (size_t)vf->np * ncomp * sizeof(double));
    for (int i = 0; i < vf->np; i++)
        for (int k = vf->w_start[i]; k < vf->w_start[i + 1]; k++)
            for (int j = 0; j < ncomp; j++) out[(size_t)i * ncomp + j] += vf->w[k] * field[(size_t)vf->w_cell[k] * ncomp + j];
}
