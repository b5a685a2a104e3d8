#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "neighbour.h"
#include "system.h"

void neighbour_init(neighbour_list *nl, double skin, int sort_interval, int history_size)
{
    memset(nl, 0, sizeof *nl);
    nl->skin = skin;
    nl->sort_interval = sort_interval;
    nl->history_size = history_size;
}

void neighbour_free(neighbour_list *nl)
{
    free(nl->start); free(nl->partner); free(nl->history); free(nl->touching); free(nl->x_at_build);
    free(nl->cell_start); free(nl->cell_of); free(nl->cell_order);
    memset(nl, 0, sizeof *nl);
}

/* Wrap periodic coordinates into the box; stop if a particle left a closed side. */
static void wrap_and_check_domain(dem_system *s)
{
    particles *p = &s->p;
    for (int i = 0; i < p->n; i++) {
        for (int d = 0; d < 3; d++) {
            double *xd = &p->x[i][d];
            if (s->periodic[d]) {
                while (*xd < s->domain_min[d]) *xd += s->period[d];
                while (*xd >= s->domain_max[d]) *xd -= s->period[d];
            } else if (*xd < s->domain_min[d] - p->radius[i] || *xd > s->domain_max[d] + p->radius[i]) {
                dem_fatal("particle id %lld left the domain at t = %g s (step %ld): position "
                          "(%g %g %g) m, domain min (%g %g %g) max (%g %g %g) m. Close the domain "
                          "with walls or make that direction periodic.",
                          (long long)p->id[i], s->time, s->step, p->x[i][0], p->x[i][1], p->x[i][2],
                          s->domain_min[0], s->domain_min[1], s->domain_min[2],
                          s->domain_max[0], s->domain_max[1], s->domain_max[2]);
            }
        }
    }
}

static int cell_coord(const neighbour_list *nl, double x, int d)
{
    int c = (int)floor((x - nl->origin[d]) / nl->cell_size[d]);
    if (c < 0) c = 0;
    if (c >= nl->ncell[d]) c = nl->ncell[d] - 1;
    return c;
}

/* Size the cell grid for the largest particle and bin all particles (counting sort). */
static void bin_particles(dem_system *s)
{
    neighbour_list *nl = &s->nlist;
    const particles *p = &s->p;
    double rmax = 0.0;
    for (int i = 0; i < p->n; i++) rmax = fmax(rmax, p->radius[i]);
    const double cutoff = 2.0 * rmax + nl->skin + nl->reach;
    for (int d = 0; d < 3; d++)
        if (s->periodic[d] && s->domain_max[d] - s->domain_min[d] < 3.0 * cutoff)
            dem_fatal("periodic direction %c: the domain length %g m must be at least 3 x "
                      "(largest diameter + skin) = %g m", "xyz"[d],
                      s->domain_max[d] - s->domain_min[d], 3.0 * cutoff);
    /* Cells no smaller than the cutoff, and not many more cells than particles (a sparse
     * system in a large domain would otherwise spend its time on empty cells). */
    const long max_cells = 4L * p->n + 64;
    long ncells;
    for (double size = cutoff;; size *= 1.26) {
        ncells = 1;
        for (int d = 0; d < 3; d++) {
            const double len = s->domain_max[d] - s->domain_min[d];
            int n = (int)fmin(floor(len / size), 1 << 20);
            if (n < 1) n = 1;
            if (s->periodic[d] && n < 3) n = 3;
            nl->ncell[d] = n;
            nl->cell_size[d] = len / n;
            nl->origin[d] = s->domain_min[d];
            ncells *= n;
        }
        if (ncells <= max_cells) break;
    }
    if (ncells + 1 > nl->cell_capacity) {
        nl->cell_capacity = ncells + 1;
        nl->cell_start = dem_realloc(nl->cell_start, (size_t)nl->cell_capacity * sizeof(int));
    }
    nl->cell_of = dem_realloc(nl->cell_of, (size_t)(p->n ? p->n : 1) * sizeof(int));
    nl->cell_order = dem_realloc(nl->cell_order, (size_t)(p->n ? p->n : 1) * sizeof(int));
    memset(nl->cell_start, 0, (size_t)(ncells + 1) * sizeof(int));
    for (int i = 0; i < p->n; i++) {
        const int c = (cell_coord(nl, p->x[i][2], 2) * nl->ncell[1] + cell_coord(nl, p->x[i][1], 1))
                      * nl->ncell[0] + cell_coord(nl, p->x[i][0], 0);
        nl->cell_of[i] = c;
        nl->cell_start[c + 1]++;
    }
    for (long c = 0; c < ncells; c++) nl->cell_start[c + 1] += nl->cell_start[c];
    int *fill = dem_malloc((size_t)ncells * sizeof(int));
    memcpy(fill, nl->cell_start, (size_t)ncells * sizeof(int));
    for (int i = 0; i < p->n; i++) nl->cell_order[fill[nl->cell_of[i]]++] = i;
    free(fill);
}

/* Re-order particles (and their wall histories) by cell; returns the old index of each new one. */
static int *sort_by_cell(dem_system *s)
{
    const int n = s->p.n;
    int *order = dem_malloc((size_t)(n ? n : 1) * sizeof(int));
    memcpy(order, s->nlist.cell_order, (size_t)n * sizeof(int));
    particles_permute(&s->p, order);
    const size_t wall_block = (size_t)s->nwalls * s->history_size;
    if (wall_block > 0) {
        double *sorted = dem_malloc((size_t)n * wall_block * sizeof(double));
        for (int k = 0; k < n; k++)
            memcpy(sorted + k * wall_block, s->wall_history + (size_t)order[k] * wall_block,
                   wall_block * sizeof(double));
        free(s->wall_history);
        s->wall_history = sorted;
    }
    for (int k = 0; k < n; k++) s->nlist.cell_order[k] = k;
    int *cell_of = dem_malloc((size_t)(n ? n : 1) * sizeof(int));
    for (int k = 0; k < n; k++) cell_of[k] = s->nlist.cell_of[order[k]];
    free(s->nlist.cell_of);
    s->nlist.cell_of = cell_of;
    return order;
}

static void push_pair(neighbour_list *nl, int j)
{
    if (nl->npairs == nl->capacity) {
        nl->capacity = nl->capacity ? 2 * nl->capacity : 4096;
        nl->partner = dem_realloc(nl->partner, (size_t)nl->capacity * sizeof(int));
    }
    nl->partner[nl->npairs++] = j;
}

/* Copy the history of pairs that existed before the rebuild. old_of_new maps new particle
 * indices to the indices the old list used (NULL: unchanged). Pairs sit under the lower index. */
static void transfer_history(neighbour_list *nl, const int *old_start, const int *old_partner,
                             const double *old_history, int old_rows, const int *old_of_new)
{
    const int hs = nl->history_size;
    nl->history = dem_realloc(nl->history, (size_t)(nl->capacity ? nl->capacity : 1) * hs * sizeof(double));
    memset(nl->history, 0, (size_t)nl->npairs * hs * sizeof(double));
    nl->touching = dem_realloc(nl->touching, (size_t)(nl->capacity ? nl->capacity : 1));
    memset(nl->touching, 0, (size_t)nl->npairs);
    if (!old_history || hs == 0) return;
    for (int i = 0; i < nl->rows; i++) {
        for (int k = nl->start[i]; k < nl->start[i + 1]; k++) {
            int a = old_of_new ? old_of_new[i] : i;
            int b = old_of_new ? old_of_new[nl->partner[k]] : nl->partner[k];
            const int flipped = a > b;   /* the old list held the pair as (j, i) */
            if (flipped) { const int t = a; a = b; b = t; }
            if (a >= old_rows) continue;
            for (int m = old_start[a]; m < old_start[a + 1]; m++) {
                if (old_partner[m] == b) {
                    contact_history_copy(nl->history + (size_t)k * hs, old_history + (size_t)m * hs, hs,
                                         nl->history_antisymmetric, flipped);
                    nl->touching[k] = 1;   /* the force loop clears it if the contact is over */
                    break;
                }
            }
        }
    }
}

void neighbour_rebuild(dem_system *s)
{
    neighbour_list *nl = &s->nlist;
    particles *p = &s->p;
    wrap_and_check_domain(s);
    bin_particles(s);

    int *old_of_new = NULL;
    if (nl->sort_interval > 0 && nl->builds % nl->sort_interval == 0) {
        old_of_new = sort_by_cell(s);
        nl->sorts++;
    }

    int *old_start = nl->start, *old_partner = nl->partner;
    double *old_history = nl->history;
    const int old_rows = nl->rows;
    const long old_capacity = nl->capacity;
    nl->start = dem_malloc((size_t)(p->n + 1) * sizeof(int));
    nl->partner = dem_malloc((size_t)(old_capacity ? old_capacity : 4096) * sizeof(int));
    nl->capacity = old_capacity ? old_capacity : 4096;
    nl->history = NULL;
    nl->npairs = 0;

    const int nx = nl->ncell[0], ny = nl->ncell[1], nz = nl->ncell[2];
    for (int i = 0; i < p->n; i++) {
        nl->start[i] = (int)nl->npairs;
        const int c = nl->cell_of[i];
        const int cx = c % nx, cy = (c / nx) % ny, cz = c / (nx * ny);
        for (int oz = -1; oz <= 1; oz++) {
            int z = cz + oz;
            if (s->periodic[2]) z = (z + nz) % nz; else if (z < 0 || z >= nz) continue;
            for (int oy = -1; oy <= 1; oy++) {
                int y = cy + oy;
                if (s->periodic[1]) y = (y + ny) % ny; else if (y < 0 || y >= ny) continue;
                for (int ox = -1; ox <= 1; ox++) {
                    int x = cx + ox;
                    if (s->periodic[0]) x = (x + nx) % nx; else if (x < 0 || x >= nx) continue;
                    const int cell = (z * ny + y) * nx + x;
                    for (int m = nl->cell_start[cell]; m < nl->cell_start[cell + 1]; m++) {
                        const int j = nl->cell_order[m];
                        if (j <= i) continue;
                        double d2 = 0.0;
                        for (int d = 0; d < 3; d++) {
                            double dx = p->x[i][d] - p->x[j][d];
                            dx -= s->period[d] * nearbyint(dx * s->inv_period[d]);
                            d2 += dx * dx;
                        }
                        const double cut = p->radius[i] + p->radius[j] + nl->skin + nl->reach;
                        if (d2 < cut * cut) push_pair(nl, j);
                    }
                }
            }
        }
    }
    nl->start[p->n] = (int)nl->npairs;
    nl->rows = p->n;

    transfer_history(nl, old_start, old_partner, old_history, old_rows, old_of_new);
    free(old_start); free(old_partner); free(old_history); free(old_of_new);

    if (p->n > nl->build_capacity) {
        nl->build_capacity = p->n;
        nl->x_at_build = dem_realloc(nl->x_at_build, (size_t)p->n * sizeof(vec3));
    }
    memcpy(nl->x_at_build, p->x, (size_t)p->n * sizeof(vec3));
    nl->builds++;
}
