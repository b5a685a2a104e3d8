/* Void fraction: the particles' volume mapped onto the fluid cells, and the per-particle cell
 * weights that did it, kept so that any per-particle quantity (drag force, exchange coefficient)
 * is spread onto the cells in the same way as the volume (cpl_vf_spread), and cell fields read
 * back at the particles with the same weights (cpl_vf_gather).
 *
 * Models (each particle's weights sum to 1, so the volume is mapped in full):
 *   centre    the whole volume in the cell holding the centre.
 *   divided   the sphere cut into nshell shells of equal volume, each with nper points (antipodal
 *             pairs, spiral on the sphere): nshell x nper points of equal volume, each located in
 *             its own cell (a walk from the particle's cell). Points outside the mesh are dropped
 *             and the others' weights renormalised, so a particle at a wall keeps its volume.
 *   gaussian  weight of cell c proportional to V_c exp(-|x_c - x_p|^2 / (2 s^2)), s =
 *             kernel_width x particle diameter, over the cells reached through faces from the
 *             particle's cell whose centres lie within kernel_cutoff x s (the particle's own cell
 *             always), normalised to 1 over the cells found: conservative at walls too. For
 *             particles large compared with the cells.
 * alpha_c = max(alpha_min, 1 - Vp_c / V_c); Vp_c [m^3] is the particle volume mapped to cell c.
 * Particles whose centre is outside the mesh get cell -1, no weights, and are counted.
 * Equations, sources and choices: docs/models/voidfraction_centre.md, voidfraction_divided.md,
 * voidfraction_gaussian.md. */
#ifndef CPL_VOIDFRACTION_H
#define CPL_VOIDFRACTION_H

#include "mesh.h"

#ifdef __cplusplus
extern "C" {
#endif

enum cpl_vf_model { CPL_VF_CENTRE, CPL_VF_DIVIDED, CPL_VF_GAUSSIAN };

typedef struct cpl_voidfraction {
    enum cpl_vf_model model;
    double alpha_min;           /* floor of alpha [-] */
    double kernel_width;        /* gaussian: s / particle diameter [-] (default 0.5: s = radius) */
    double kernel_cutoff;       /* gaussian: cells within kernel_cutoff x s [-] (default 3) */
    int nsample;                /* divided: points per sphere */
    double (*sample)[3];        /* divided: points in the unit sphere */

    int ncells;
    double *vp;                 /* [ncells] particle volume in the cell [m^3] */
    double *alpha;              /* [ncells] fluid volume fraction [-] */

    /* weights of the last cpl_vf_compute: particle i puts w[k] of itself into cell w_cell[k],
     * k in w_start[i] .. w_start[i+1) */
    int np;
    int *w_start, *w_cell;
    double *w;

    /* 1 when the cells are one rank's share of the mesh (proxies.h): the divided model then
     * seeks the sample points of particles whose centre is on another rank's cells */
    int partial;

    /* private work space */
    int np_cap, w_cap;
    unsigned *mark, stamp;
    int *queue;
    double (*queue_shift)[3];   /* gaussian: the periodic shift each queued cell is seen at [m] */
} cpl_voidfraction;

/* name: "centre", "divided" or "gaussian". Returns 0, or -1 for another name (the caller says
 * where it came from). */
int cpl_vf_model_parse(const char *name, enum cpl_vf_model *model);

/* Set up for mesh m (which must outlive vf): defaults kernel_width 0.5, kernel_cutoff 3,
 * divided 4 shells x 16 points. alpha_min in [0, 1) (else a fatal error, error.h). */
void cpl_vf_init(cpl_voidfraction *vf, const cpl_mesh *m, enum cpl_vf_model model, double alpha_min);
void cpl_vf_free(cpl_voidfraction *vf);

/* divided: nshell >= 1 shells of nper points, nper a multiple of 4 (antipodal pairs, none on
 * the coordinate planes through the centre); other counts are a fatal error. */
void cpl_vf_set_samples(cpl_voidfraction *vf, int nshell, int nper);

/* Map np particles (centres x [m], radii r [m]) onto the cells. cell[i]: the particle's cell
 * from the last call (or -1 if unknown); updated here (-1 when outside the mesh). Fills vp,
 * alpha and the weights. Returns the number of particles outside the mesh (not mapped). Bad input
 * (a radius not positive and finite, a mesh other than vf's) is a fatal error. */
int cpl_vf_compute(cpl_voidfraction *vf, const cpl_mesh *m, int np, const double (*x)[3],
                   const double *r, int *cell);
/* The same with each particle's volume given (volume[i] [m^3]; NULL: 4/3 pi r^3): the spheres of
 * a multisphere body share its volume, overlaps counted once (bodies.h); r still sets where the
 * volume goes (the divided and gaussian models). */
int cpl_vf_compute_volumes(cpl_voidfraction *vf, const cpl_mesh *m, int np, const double (*x)[3],
                           const double *r, const double *volume, int *cell);

/* cpl_vf_compute_volumes in two halves, for a mesh cut over ranks, where a particle's weights
 * are found on each rank that holds some of its cells and normalised by their sum over the ranks
 * (proxies.h); serially cpl_vf_compute_volumes calls them in turn.
 * weigh: each particle's cells among this rank's and its unnormalised weights (centre: 1;
 * divided: one per sample point found; gaussian: V_c times the kernel); cell[i] updated (-1: the
 * centre is not in these cells); z[i] = the sum of its weights here.
 * finish: with norm[i] the sum of z over the ranks and found[i] > 0 where some rank holds the
 * centre: the weights divided by norm (a particle whose centre no rank holds is not mapped; a
 * divided particle of which no point but the centre was found goes whole into the centre's
 * cell), then vp and alpha. */
void cpl_vf_weigh(cpl_voidfraction *vf, const cpl_mesh *m, int np, const double (*x)[3], const double *r, int *cell,
                  double *z);
void cpl_vf_finish(cpl_voidfraction *vf, const cpl_mesh *m, const double *norm, const double *found, const double *r,
                   const double *volume);

/* out[c][k] = sum over particles i of w_ic q[i][k] (q: [np][ncomp], out: [ncells][ncomp],
 * overwritten), with the weights of the last cpl_vf_compute. Sums, not densities: divide by the
 * cell volume for a density. */
void cpl_vf_spread(const cpl_voidfraction *vf, int ncomp, const double *q, double *out);

/* out[i][k] = sum over cells c of w_ic field[c][k] (field: [ncells][ncomp], out: [np][ncomp]);
 * 0 for particles outside the mesh. */
void cpl_vf_gather(const cpl_voidfraction *vf, int ncomp, const double *field, double *out);

#ifdef __cplusplus
}
#endif
#endif
