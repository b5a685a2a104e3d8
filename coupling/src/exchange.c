/* Per-cell K_sl, K-weighted particle velocity and explicit source; gather with the same weights
 * (see exchange.h). */
#include <math.h>

#include "error.h"
#include "exchange.h"

void cpl_cell_weights_check(const cpl_cell_weights *w, int ncells, double tol)
{
    if (w->start[0] != 0) dem_fatal("coupling: cell weights: start[0] = %d, must be 0", w->start[0]);
    for (int i = 0; i < w->nparticles; i++) {
        if (w->start[i + 1] < w->start[i])
            dem_fatal("coupling: cell weights: start decreases at particle %d (%d, then %d)", i, w->start[i],
                      w->start[i + 1]);
        if (w->start[i + 1] == w->start[i]) continue;   /* outside the mesh */
        double sum = 0.0;
        for (int j = w->start[i]; j < w->start[i + 1]; j++) {
            if (w->cell[j] < 0 || w->cell[j] >= ncells)
                dem_fatal("coupling: cell weights: particle %d refers to cell %d (mesh has %d)", i, w->cell[j], ncells);
            if (!(w->weight[j] >= 0.0) || !isfinite(w->weight[j]))
                dem_fatal("coupling: cell weights: particle %d has weight %g on cell %d", i, w->weight[j], w->cell[j]);
            sum += w->weight[j];
        }
        if (fabs(sum - 1.0) > tol)
            dem_fatal("coupling: cell weights: particle %d's weights sum to %.17g, not 1 (tolerance %g)", i, sum, tol);
    }
}

void cpl_gather_scalar(const cpl_cell_weights *w, const double *cell_field, double *at_particle)
{
    for (int i = 0; i < w->nparticles; i++) {
        double s = 0.0;
        for (int j = w->start[i]; j < w->start[i + 1]; j++) s += w->weight[j] * cell_field[w->cell[j]];
        at_particle[i] = s;
    }
}

void cpl_gather_vector(const cpl_cell_weights *w, const double (*cell_field)[3], double (*at_particle)[3])
{
    for (int i = 0; i < w->nparticles; i++) {
        double s[3] = {0.0, 0.0, 0.0};
        for (int j = w->start[i]; j < w->start[i + 1]; j++)
            for (int k = 0; k < 3; k++) s[k] += w->weight[j] * cell_field[w->cell[j]][k];
        for (int k = 0; k < 3; k++) at_particle[i][k] = s[k];
    }
}

void cpl_exchange_cells(const cpl_cell_weights *w, const cpl_fluid_forces *f, const double (*v)[3],
                        int ncells, const double *cell_volume,
                        double *ksl, double (*up)[3], double (*source)[3])
{
    if (f->n != w->nparticles)
        dem_fatal("coupling: exchange: %d particles have forces but %d have cell weights", f->n, w->nparticles);
    /* accumulate sums first (ksl: sum w beta [kg/s]; up: sum w beta v [N]; source: -sum w f [N]),
     * then divide once per cell */
    for (int c = 0; c < ncells; c++) {
        ksl[c] = 0.0;
        for (int k = 0; k < 3; k++) up[c][k] = source[c][k] = 0.0;
    }
    for (int i = 0; i < w->nparticles; i++)
        for (int j = w->start[i]; j < w->start[i + 1]; j++) {
            const int c = w->cell[j];
            const double wb = w->weight[j] * f->beta[i];
            ksl[c] += wb;
            for (int k = 0; k < 3; k++) {
                up[c][k] += wb * v[i][k];
                source[c][k] -= w->weight[j] * f->f_exchange[i][k];
            }
        }
    for (int c = 0; c < ncells; c++) {
        const double inv_sum = ksl[c] > 0.0 ? 1.0 / ksl[c] : 0.0;   /* no implicit coupling here: up unused */
        for (int k = 0; k < 3; k++) {
            up[c][k] *= inv_sum;
            source[c][k] /= cell_volume[c];
        }
        ksl[c] /= cell_volume[c];
    }
}
