/* Lattice insertion: the points of a rectangular lattice (spacing s_x, s_y, s_z; cubic when
 * one spacing is given) in a box or cylinder region.
 *
 * Along each direction k of the region's bounding box (a box: min..max; a cylinder: the axial
 * range and the square of side 2R around the axis) there are n_k = floor(L_k / s_k) points
 * (L_k the extent; 1e-9 added before the floor against round-off in L_k / s_k), centred:
 *
 *     x_k,i = (min_k + max_k) / 2 + (i - (n_k - 1) / 2) s_k,     i = 0 .. n_k - 1,
 *
 * so the outer points are (L_k - (n_k - 1) s_k) / 2 >= s_k / 2 >= d_max / 2 from the sides and
 * every sphere lies in the box. (DPMFoam's Goldschmidt lattice, 5 x 50 x 99 = 24,750 points
 * from x -0.006, y -0.0735, z 0.0015 at 0.003 m, is the box (-0.0075 -0.075 0) ..
 * (0.0075 0.075 0.297) at spacing 0.003.) A cylinder keeps the points whose sphere lies inside
 * it: rho + d_max / 2 <= R (rho the distance from the axis, 1e-12 R of slack).
 *
 * Order: x fastest, then y, then z (DPMFoam's file order). With `number` the points are sorted
 * by height along -gravity (-z without gravity), stably, so that within a layer the lattice
 * order is kept, and the lowest `number` are inserted: a bed filled from the bottom.
 *
 * The spacing must be at least the largest diameter (checked when the case is read), so that
 * lattice neighbours do not overlap; diameters of a distribution are drawn per point from
 * `seed`. The points are then checked and placed by dem_insertion_add_batch (insert.c). */
#include <math.h>
#include <stdlib.h>

#include "dict.h"
#include "error.h"
#include "insert.h"
#include "memory_budget.h"
#include "system.h"

typedef struct height_index { double h; long i; } height_index;

static int by_height(const void *a, const void *b)
{
    const height_index *x = a, *y = b;
    if (x->h != y->h) return x->h < y->h ? -1 : 1;
    return (x->i > y->i) - (x->i < y->i);
}

long dem_lattice_points(const dem_insertion *ins, const dem_dict *entry, double **xyz)
{
    double lo[3], hi[3];
    const int a = ins->axis, b = (a + 1) % 3, c = (a + 2) % 3;
    for (int k = 0; k < 3; k++) { lo[k] = ins->min[k]; hi[k] = ins->max[k]; }
    if (ins->region == REGION_CYLINDER) {
        lo[b] = ins->centre[0] - ins->radius; hi[b] = ins->centre[0] + ins->radius;
        lo[c] = ins->centre[1] - ins->radius; hi[c] = ins->centre[1] + ins->radius;
    }
    long n[3];
    double total = 1.0;
    for (int k = 0; k < 3; k++) {
        const double len = hi[k] - lo[k];
        n[k] = (long)floor(len / ins->spacing[k] + 1e-9);
        if (n[k] < 1)
            dem_dict_fatal(entry, "spacing", "insertion '%s': the spacing %g m along %c exceeds the region's "
                       "extent %g m: no lattice point fits", ins->name, ins->spacing[k], "xyz"[k], len);
        total *= (double)n[k];
    }
    {
        const double smallest = fmin(ins->spacing[0], fmin(ins->spacing[1], ins->spacing[2]));
        dem_check_affordable(entry, "spacing", smallest, ins->number > 0 ? fmin((double)ins->number, total) : total,
                             -3.0, "lattice points");
    }
    if (total > 1e8)
        dem_dict_fatal(entry, "spacing", "insertion '%s': the lattice would have %.3g points (%ld x %ld x %ld), "
                   "more than 10^8", ins->name, total, n[0], n[1], n[2]);
    const double dmax = dem_insertion_max_diameter(ins);
    double *pts = dem_malloc((size_t)(3 * total) * sizeof(double));
    long count = 0;
    for (long k2 = 0; k2 < n[2]; k2++)
        for (long k1 = 0; k1 < n[1]; k1++)
            for (long k0 = 0; k0 < n[0]; k0++) {
                const long idx[3] = {k0, k1, k2};
                double x[3];
                for (int k = 0; k < 3; k++)
                    x[k] = 0.5 * (lo[k] + hi[k]) + ((double)idx[k] - 0.5 * (double)(n[k] - 1)) * ins->spacing[k];
                if (ins->region == REGION_CYLINDER &&
                    hypot(x[b] - ins->centre[0], x[c] - ins->centre[1]) + 0.5 * dmax > ins->radius * (1.0 + 1e-12))
                    continue;
                for (int k = 0; k < 3; k++) pts[3 * count + k] = x[k];
                count++;
            }
    if (count == 0)
        dem_dict_fatal(entry, "spacing", "insertion '%s': no lattice point of spacing (%g %g %g) m lies inside the "
                   "cylinder with room for diameter %g m", ins->name, ins->spacing[0], ins->spacing[1],
                   ins->spacing[2], dmax);
    if (ins->number > count)
        dem_dict_fatal(entry, "number", "insertion '%s': the lattice holds only %ld points (%ld x %ld x %ld%s at "
                   "spacing (%g %g %g) m), fewer than number %ld", ins->name, count, n[0], n[1], n[2],
                   ins->region == REGION_CYLINDER ? " box, inside the cylinder" : "", ins->spacing[0],
                   ins->spacing[1], ins->spacing[2], ins->number);
    if (ins->number > 0 && ins->number < count) {   /* the lowest `number` along gravity */
        height_index *order = dem_malloc((size_t)count * sizeof *order);
        for (long i = 0; i < count; i++) {
            const double *x = pts + 3 * i;
            order[i].h = -(x[0] * ins->down[0] + x[1] * ins->down[1] + x[2] * ins->down[2]);
            order[i].i = i;
        }
        qsort(order, (size_t)count, sizeof *order, by_height);
        double *kept = dem_malloc((size_t)(3 * ins->number) * sizeof(double));
        for (long i = 0; i < ins->number; i++)
            for (int k = 0; k < 3; k++) kept[3 * i + k] = pts[3 * order[i].i + k];
        free(order);
        free(pts);
        pts = kept;
        count = ins->number;
    }
    *xyz = pts;
    return count;
}

long dem_insertion_lattice(dem_system *s, const dem_insertion *ins, const dem_dict *entry)
{
    double *pts;
    const long n = dem_lattice_points(ins, entry, &pts);
    dem_insert_batch b;
    dem_insert_batch_init(&b);
    dem_rng r;
    rng_seed(&r, ins->seed);
    for (long i = 0; i < n; i++)   /* a body's size is its template's */
        dem_insert_batch_push(&b, pts + 3 * i, ins->velocity, ins->body ? 0.0 : dem_insertion_draw_diameter(ins, &r),
                              ins->material, 0);
    free(pts);
    const long placed = ins->body ? dem_insertion_add_body_batch(s, ins, &b, ins->source)
                                  : dem_insertion_add_batch(s, ins, &b, NULL, entry, "region");
    dem_insert_batch_free(&b);
    return placed;
}
