/* The fluid mesh as the coupling layer sees it: OpenFOAM's polyMesh arrays, copied once from the
 * adapter (points, faces, owner, neighbour; cell centres and volumes), plus what the layer
 * derives from them (face centres and area vectors, cell -> faces, a search grid).
 * Particle location: walk from the last known cell; a full search only when the walk is lost. */
#ifndef CPL_MESH_H
#define CPL_MESH_H

#ifdef __cplusplus
extern "C" {
#endif

typedef struct cpl_mesh {
    int npoints, nfaces, ninternal_faces, ncells;
    double (*points)[3];
    int *face_start;            /* CSR: points of face f are face_points[face_start[f] .. face_start[f+1]) */
    int *face_points;
    int *owner;                 /* nfaces */
    int *neighbour;             /* ninternal_faces (internal faces first, as OpenFOAM orders them) */
    double (*cell_centre)[3];   /* ncells */
    double *cell_volume;        /* ncells [m^3] */
    /* derived by cpl_mesh_init */
    double (*face_centre)[3];
    double (*face_area)[3];     /* area vector, pointing out of the owner [m^2] */
    int *cell_face_start;       /* CSR: faces of cell c */
    int *cell_faces;
    double bounds_min[3], bounds_max[3];
    void *search;               /* private: grid of cells for the full search */
    /* cyclic (translational) patch pairs, cpl_mesh_set_cyclic (cyclic.c): per boundary face the
     * boundary face it meets across the cycle (-1: none; NULL: no cyclic patches), and per axis
     * whether the mesh is periodic along it and its period (the bounds' extent) [m] */
    int *cyclic_partner;        /* nfaces - ninternal_faces entries, indexed f - ninternal_faces */
    int periodic[3];
    double period[3];
    double periodic_min[3];     /* the lower cyclic side's coordinate: positions wrap into [min, min + period) */
} cpl_mesh;

/* Copy the arrays (the caller keeps its own) and derive the rest. cell_centre / cell_volume may
 * be NULL: then they are computed from the faces. Bad arrays (sizes, indices out of range, a
 * cell that is not closed or has no volume) are a fatal error naming them (error.h). */
void cpl_mesh_init(cpl_mesh *m, int npoints, const double (*points)[3], int nfaces, const int *face_start,
                   const int *face_points, int ninternal_faces, const int *owner, const int *neighbour,
                   int ncells, const double (*cell_centre)[3], const double *cell_volume);
void cpl_mesh_free(cpl_mesh *m);

/* 1 if x lies inside cell c (on the inner side of every face plane; OpenFOAM cells are taken as
 * convex with planar faces for this test). */
int cpl_mesh_inside(const cpl_mesh *m, int c, const double x[3]);

/* The cell containing x: walk from `guess` (or full search if guess < 0 or the walk is lost);
 * -1 if x is outside the mesh. *searched (may be NULL) is set to 1 when a full search was used. */
int cpl_mesh_locate(const cpl_mesh *m, const double x[3], int guess, int *searched);

/* A box mesh of nx x ny x nz hex cells in OpenFOAM's ordering (internal faces first, owner <
 * neighbour, boundary faces after), for tests and for the tutorials' checks. */
void cpl_mesh_box(cpl_mesh *m, const double lo[3], const double hi[3], int nx, int ny, int nz);

/* Cyclic patches (cyclic.c). A translational cyclic pair, as OpenFOAM's cyclicPolyPatch holds
 * it: face_a[k] meets face_b[k] (boundary faces, in the patches' order). The translation must be
 * one and the same for every pair, along a coordinate axis, and equal to the mesh's extent along
 * it (the domain is periodic there); anything else is a fatal error naming the pair. May be
 * called once per axis. From then on the particle location wraps positions into the bounds along
 * that axis, and the void fraction and the interpolation see across the pair's faces as across
 * an interior face. */
void cpl_mesh_set_cyclic(cpl_mesh *m, int npairs, const int *face_a, const int *face_b);
/* x wrapped into [periodic_min, periodic_min + period) along the periodic axes. */
void cpl_mesh_wrap(const cpl_mesh *m, double x[3]);
/* The cell across boundary face f through its cyclic partner, and the shift that puts that cell
 * next to this side: (its coordinates + shift) are where it continues the mesh beyond f; -1 for a
 * face without a partner. */
int cpl_mesh_cyclic_cell(const cpl_mesh *m, int f, double shift[3]);
/* For tests: the boundary faces of a box mesh on its min and max planes along `axis`, paired by
 * their centres; *a, *b malloc'd. Returns the number of pairs. */
int cpl_mesh_pair_box_faces(const cpl_mesh *m, int axis, int **a, int **b);

/* Extensions (mesh.c). */

/* The cell across face f from cell c; -1 for a boundary face. */
static inline int cpl_mesh_other_cell(const cpl_mesh *m, int f, int c)
{
    if (f >= m->ninternal_faces) return -1;
    return m->owner[f] == c ? m->neighbour[f] : m->owner[f];
}

/* Distance from x to the nearest face plane of cell c [m], positive when x is inside all of them
 * (a sphere of radius r about x then lies in the cell if the distance is >= r). */
double cpl_mesh_depth(const cpl_mesh *m, int c, const double x[3]);

/* A box mesh of nx x ny x nz coarse hex cells in which the coarse cells (i, j, k) with
 * rlo <= (i, j, k) < rhi are split 2 x 2 x 2, as a refinement would: the coarse cells facing the
 * refined block have split faces (more than 6 faces) and faces carry the hanging points, so the mesh
 * is genuinely polyhedral. OpenFOAM ordering. For tests. */
void cpl_mesh_box_refined(cpl_mesh *m, const double lo[3], const double hi[3], int nx, int ny, int nz,
                          const int rlo[3], const int rhi[3]);

/* Move every point by map(x, ctx) and re-derive the geometry (face centres and areas, cell
 * centres and volumes, recomputed from the faces, and the search grid). The map must keep faces
 * planar for cpl_mesh_inside to be exact (a shear or a per-axis stretch does). For tests. */
void cpl_mesh_map_points(cpl_mesh *m, void (*map)(double x[3], void *ctx), void *ctx);

#ifdef __cplusplus
}
#endif

#endif
