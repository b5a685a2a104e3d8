/* The recursive coordinate bisection (dem/src/decompose.h), serially, on 20,000 points of a column
 * with a dense bed under a dilute freeboard (decompose_points.h), for 1 to 16 parts:
 *  1. the boxes tile the domain: their volumes sum to its volume (1e-12), no two overlap;
 *  2. every point's owner box holds it;
 *  3. each part holds N / parts points to within one point per level of the tree (a plane is placed
 *     to 6e-8 of its side, between two points unless they are closer than that);
 *  4. the imbalance (max / mean) is what the counts give, and with a cost per point as the weight
 *     (points in the bed cost twice as much) each part holds an equal share of the cost to within
 *     the largest single cost per level. */
#include <math.h>
#include <stdlib.h>

#include "decompose.h"
#include "decompose_points.h"
#include "harness.h"

enum { N = 20000 };

static double overlap(const double *alo, const double *ahi, const double *blo, const double *bhi)
{
    double v = 1.0;
    for (int d = 0; d < 3; d++) v *= fmax(0.0, fmin(ahi[d], bhi[d]) - fmax(alo[d], blo[d]));
    return v;
}

int main(void)
{
    static double x[N][3], cost[N], part_weight[16];
    decompose_points(N, x);
    const double volume = 0.1 * 0.05 * 0.3;
    const int parts[] = {1, 2, 3, 4, 5, 7, 8, 16};
    for (size_t t = 0; t < sizeof parts / sizeof *parts; t++) {
        const int np = parts[t];
        int levels = 0;
        while ((1 << levels) < np) levels++;
        dem_decomposition d;
        dem_decompose_rcb(&d, np, domain_lo, domain_hi, N, (const dem_vec3 *)x, NULL);
        double vsum = 0.0, vover = 0.0;
        for (int p = 0; p < np; p++) {
            vsum += (d.hi[p][0] - d.lo[p][0]) * (d.hi[p][1] - d.lo[p][1]) * (d.hi[p][2] - d.lo[p][2]);
            for (int q = p + 1; q < np; q++) vover += overlap(d.lo[p], d.hi[p], d.lo[q], d.hi[q]);
        }
        char what[160];
        snprintf(what, sizeof what, "%d parts: the boxes tile the domain (volume sum, overlaps)", np);
        check_true(what, fabs(vsum - volume) <= 1e-12 * volume && vover == 0.0);
        int count[16] = {0}, outside = 0;
        for (int i = 0; i < N; i++) {
            const int p = dem_decomposition_owner(&d, x[i]);
            count[p]++;
            for (int e = 0; e < 3; e++) outside += x[i][e] < d.lo[p][e] || x[i][e] > d.hi[p][e];
        }
        snprintf(what, sizeof what, "%d parts: every point's owner box holds it", np);
        check_true(what, outside == 0);
        double worst = 0.0;
        for (int p = 0; p < np; p++) worst = fmax(worst, fabs(count[p] - (double)N / np));
        snprintf(what, sizeof what, "%d parts: counts within %d of N/parts (worst %.2f)", np, levels, worst);
        check_true(what, worst <= levels + 1e-9);
        const double imb = dem_decomposition_imbalance(&d, N, (const dem_vec3 *)x, NULL, part_weight);
        int maxc = 0;
        for (int p = 0; p < np; p++) maxc = count[p] > maxc ? count[p] : maxc;
        snprintf(what, sizeof what, "%d parts: imbalance %.6f is the counts' max / mean", np, imb);
        check_rel(what, imb, (double)maxc * np / N, 1e-12);
        dem_decomposition_free(&d);

        for (int i = 0; i < N; i++) cost[i] = x[i][2] < 0.03 ? 2.0 : 1.0;
        double total = 0.0;
        for (int i = 0; i < N; i++) total += cost[i];
        dem_decompose_rcb(&d, np, domain_lo, domain_hi, N, (const dem_vec3 *)x, cost);
        dem_decomposition_imbalance(&d, N, (const dem_vec3 *)x, cost, part_weight);
        worst = 0.0;
        for (int p = 0; p < np; p++) worst = fmax(worst, fabs(part_weight[p] - total / np));
        snprintf(what, sizeof what, "%d parts, cost-weighted: shares within %d x 2 of total/parts (worst %.2f)",
                 np, levels, worst);
        check_true(what, worst <= 2.0 * levels + 1e-9);
        dem_decomposition_free(&d);
    }
    return finish("decompose");
}
