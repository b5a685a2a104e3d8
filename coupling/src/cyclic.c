/* Cyclic (translational) patches of the fluid mesh (mesh.h): the pairs of boundary faces that
 * meet across a periodic side, so that the void fraction and the interpolation see across them
 * as across an interior face. OpenFOAM's cyclicPolyPatch supplies the pairs (the adapter hands
 * them over); only the test meshes pair faces here, by their centres. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "mesh.h"

void cpl_mesh_set_cyclic(cpl_mesh *m, int npairs, const int *face_a, const int *face_b)
{
    const int nb = m->nfaces - m->ninternal_faces;
    if (npairs < 1) dem_fatal("cyclic patch: no face pairs");
    if (!m->cyclic_partner) {
        m->cyclic_partner = dem_malloc((size_t)(nb ? nb : 1) * sizeof(int));
        for (int k = 0; k < nb; k++) m->cyclic_partner[k] = -1;
    }
    double sep[3] = {0, 0, 0};
    for (int k = 0; k < npairs; k++) {
        const int a = face_a[k], b = face_b[k];
        if (a < m->ninternal_faces || a >= m->nfaces || b < m->ninternal_faces || b >= m->nfaces || a == b)
            dem_fatal("cyclic patch: pair %d (faces %d and %d) is not two boundary faces of the mesh (%d to %d)", k, a, b,
                      m->ninternal_faces, m->nfaces - 1);
        double d[3];
        for (int q = 0; q < 3; q++) d[q] = m->face_centre[b][q] - m->face_centre[a][q];
        if (k == 0) memcpy(sep, d, sizeof sep);
        const double size = sqrt(fabs(m->face_area[a][0]) + fabs(m->face_area[a][1]) + fabs(m->face_area[a][2]));
        for (int q = 0; q < 3; q++)
            if (fabs(d[q] - sep[q]) > 1e-6 * size)
                dem_fatal("cyclic patch: pair %d (faces %d and %d) is %g %g %g m apart, pair 0 %g %g %g m: only a "
                          "translation (one separation for every pair) is supported", k, a, b, d[0], d[1], d[2],
                          sep[0], sep[1], sep[2]);
        m->cyclic_partner[a - m->ninternal_faces] = b;
        m->cyclic_partner[b - m->ninternal_faces] = a;
    }
    int axis = -1;
    for (int q = 0; q < 3; q++)
        if (fabs(sep[q]) > 0.5 * (m->bounds_max[q] - m->bounds_min[q])) axis = q;
    const double extent = axis >= 0 ? m->bounds_max[axis] - m->bounds_min[axis] : 0.0;
    if (axis < 0 || fabs(fabs(sep[axis]) - extent) > 1e-9 * extent ||
        fabs(sep[(axis + 1) % 3]) > 1e-9 * extent || fabs(sep[(axis + 2) % 3]) > 1e-9 * extent)
        dem_fatal("cyclic patch: the separation (%g %g %g) m is not the mesh's extent along one coordinate axis "
                  "(bounds (%g %g %g) to (%g %g %g) m): only a periodic box side is supported", sep[0], sep[1], sep[2],
                  m->bounds_min[0], m->bounds_min[1], m->bounds_min[2], m->bounds_max[0], m->bounds_max[1],
                  m->bounds_max[2]);
    m->periodic[axis] = 1;
    m->period[axis] = fabs(sep[axis]);
    m->periodic_min[axis] = fmin(m->face_centre[face_a[0]][axis], m->face_centre[face_b[0]][axis]);
}

void cpl_mesh_wrap(const cpl_mesh *m, double x[3])
{
    for (int q = 0; q < 3; q++) {
        const double lo = m->periodic_min[q], hi = lo + m->period[q];
        if (!m->periodic[q] || (x[q] >= lo && x[q] < hi)) continue;
        x[q] -= floor((x[q] - lo) / m->period[q]) * m->period[q];
        if (x[q] >= hi) x[q] -= m->period[q];   /* round-off at the sides */
        if (x[q] < lo) x[q] = lo;
    }
}

int cpl_mesh_cyclic_cell(const cpl_mesh *m, int f, double shift[3])
{
    if (!m->cyclic_partner || f < m->ninternal_faces) return -1;
    const int g = m->cyclic_partner[f - m->ninternal_faces];
    if (g < 0) return -1;
    for (int q = 0; q < 3; q++) shift[q] = m->periodic[q] ? m->face_centre[f][q] - m->face_centre[g][q] : 0.0;
    return m->owner[g];
}

/* faces of the min plane and of the max plane along an axis, sorted by the other coordinates */
typedef struct side_face { int face; long long u, v; } side_face;   /* u, v: in units of 1e-9 of the extent */
static int side_cmp(const void *pa, const void *pb)
{
    const side_face *a = pa, *b = pb;
    if (a->u != b->u) return a->u < b->u ? -1 : 1;
    if (a->v != b->v) return a->v < b->v ? -1 : 1;
    return 0;
}

int cpl_mesh_pair_box_faces(const cpl_mesh *m, int axis, int **a, int **b)
{
    const int nb = m->nfaces - m->ninternal_faces, u = (axis + 1) % 3, v = (axis + 2) % 3;
    side_face *lo = dem_malloc((size_t)(nb ? nb : 1) * sizeof *lo), *hi = dem_malloc((size_t)(nb ? nb : 1) * sizeof *hi);
    int nlo = 0, nhi = 0;
    const double tol = 1e-9 * (m->bounds_max[axis] - m->bounds_min[axis]);
    for (int f = m->ninternal_faces; f < m->nfaces; f++) {
        const double *c = m->face_centre[f];
        const side_face sf = {f, llround((c[u] - m->bounds_min[u]) / (1e-9 * (m->bounds_max[u] - m->bounds_min[u]))),
                              llround((c[v] - m->bounds_min[v]) / (1e-9 * (m->bounds_max[v] - m->bounds_min[v])))};
        if (fabs(c[axis] - m->bounds_min[axis]) < tol) lo[nlo++] = sf;
        else if (fabs(c[axis] - m->bounds_max[axis]) < tol) hi[nhi++] = sf;
    }
    if (nlo != nhi) dem_fatal("cpl_mesh_pair_box_faces: %d faces on the min side, %d on the max side", nlo, nhi);
    qsort(lo, (size_t)nlo, sizeof *lo, side_cmp);
    qsort(hi, (size_t)nhi, sizeof *hi, side_cmp);
    *a = dem_malloc((size_t)(nlo ? nlo : 1) * sizeof(int));
    *b = dem_malloc((size_t)(nlo ? nlo : 1) * sizeof(int));
    for (int k = 0; k < nlo; k++) {
        (*a)[k] = lo[k].face;
        (*b)[k] = hi[k].face;
    }
    free(lo);
    free(hi);
    return nlo;
}
