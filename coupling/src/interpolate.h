/* Fluid fields at the particles: cell-centred values (fluid velocity, pressure gradient)
 * interpolated to particle positions.
 *
 *   cell        the value of the particle's cell.
 *   cellLinear  least-squares linear reconstruction: u(x) = u_c + G_c (x - x_c), G_c minimising
 *               sum over the face neighbours n of |u_n - u_c - G_c (x_n - x_c)|^2 / |x_n - x_c|^2
 *               (OpenFOAM's leastSquares gradient without boundary values). A linear field is
 *               reproduced exactly (to round-off) in every cell whose neighbours' centres span
 *               3D, boundary cells included. This is NOT OpenFOAM's cellPoint (tetrahedra with
 *               inverse-distance point values): it is linear-exact on any mesh but not continuous
 *               across faces, and not bounded (no limiter).
 *   cellPoint   as OpenFOAM's interpolationCellPoint: point values are the inverse-distance
 *               average of the cells around each point; the cell is split into tetrahedra
 *               (cell centre, face centre, two consecutive face points; the face centre's value
 *               is the mean of its points') and the value is linear (barycentric) in the
 *               tetrahedron holding x. Continuous across faces; linear-exact where the point
 *               averages are (interior points of uniform meshes). Boundary points average only
 *               the cells there (OpenFOAM uses the boundary values), so it is not linear-exact
 *               next to walls.
 * A direction the neighbours do not span (one cell thick meshes) gets a zero gradient.
 * Equations, sources and choices: docs/models/interpolation_cell.md, interpolation_cellLinear.md,
 * interpolation_cellPoint.md. */
#ifndef CPL_INTERPOLATE_H
#define CPL_INTERPOLATE_H

#include "mesh.h"

#ifdef __cplusplus
extern "C" {
#endif

enum cpl_interp_scheme { CPL_INTERP_CELL, CPL_INTERP_LINEAR, CPL_INTERP_CELL_POINT };

typedef struct cpl_interp {
    enum cpl_interp_scheme scheme;
    int ncells, ncomp;
    double (*minv)[9];          /* cellLinear: inverse least-squares matrix of cell c [m^2] */
    double *field;              /* [ncells][ncomp] copy of the last field */
    double *grad;               /* [ncells][ncomp][3] its reconstructed gradient [field/m] */
    int *pc_start, *pc_cell;    /* cellPoint: CSR point -> cells */
    double *pc_w;               /* cellPoint: inverse-distance weights, summing to 1 per point */
    double *point_value;        /* cellPoint: [npoints][ncomp] */
    double *face_value;         /* cellPoint: [nfaces][ncomp], the mean of the face's points */
    double *pyramid_inv;        /* cellPoint: 1/((x_f - x_c).A_f) per cell face (cell_faces order) */
} cpl_interp;

/* name: "cell", "cellLinear" or "cellPoint". Returns 0, or -1 for another name (the caller says
 * where it came from). */
int cpl_interp_scheme_parse(const char *name, enum cpl_interp_scheme *scheme);

/* For fields of ncomp (1 .. 64) components per cell on mesh m; other counts are a fatal error. */
void cpl_interp_init(cpl_interp *ip, const cpl_mesh *m, enum cpl_interp_scheme scheme, int ncomp);
void cpl_interp_free(cpl_interp *ip);

/* Take a new field ([ncells][ncomp], copied) and reconstruct its gradients (cellLinear). */
void cpl_interp_set_field(cpl_interp *ip, const cpl_mesh *m, const double *field);

/* The field at x in cell `cell` (from cpl_mesh_locate): out[ncomp]. Returns 0, or -1 (out set
 * to 0) when cell < 0 (particle outside the mesh). */
int cpl_interp_at(const cpl_interp *ip, const cpl_mesh *m, int cell, const double x[3], double *out);

/* The same for np particles: out[np][ncomp]; returns the number outside (cell < 0, out 0). */
int cpl_interp_particles(const cpl_interp *ip, const cpl_mesh *m, int np, const int *cell,
                         const double (*x)[3], double *out);

/* cellPoint in two halves, for fields that change while the particles stay (and the other way
 * round): the tetrahedron and barycentric weights of each particle, then the value of the field
 * last given to cpl_interp_set_field. tets[i].cell = -1 for a particle outside (value 0). On
 * entry tets holds the last locations (or cell -1): a particle still inside its last
 * tetrahedron is found with one test (the test holds whatever particle the entry came from, so
 * a re-sorted array only costs searches). */
typedef struct cpl_interp_tet { int cell, face, edge; double l[4]; } cpl_interp_tet;
int cpl_interp_locate(const cpl_interp *ip, const cpl_mesh *m, int np, const int *cell, const double (*x)[3],
                      cpl_interp_tet *tets);
void cpl_interp_apply(const cpl_interp *ip, const cpl_mesh *m, int np, const cpl_interp_tet *tets, double *out);

#ifdef __cplusplus
}
#endif
#endif
