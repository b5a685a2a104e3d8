#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "ghosts.h"
#include "neighbour.h"
#include "reduce.h"
#include "stage_timer.h"
#include "system.h"

void dem_neighbour_init(dem_neighbour_list *nl, double skin, int sort_interval, int history_size)
{
    memset(nl, 0, sizeof *nl);
    nl->skin = skin;
    nl->sort_interval = sort_interval;
    nl->history_size = history_size;
}

void dem_neighbour_free(dem_neighbour_list *nl)
{
    free(nl->start); free(nl->partner); free(nl->history); free(nl->touching); free(nl->x_at_build); free(nl->id_at_build);
    free(nl->cell_start); free(nl->cell_of); free(nl->cell_order);
    memset(nl, 0, sizeof *nl);
}

void dem_neighbour_wrap(dem_system *s)
{
    dem_particles *p = &s->p;
    for (int i = 0; i < p->n; i++) {
        for (int d = 0; d < 3; d++) {
            double *xd = &p->x[i][d];
            if (s->periodic[d]) {
                if (!(*xd >= s->domain_min[d] && *xd < s->domain_max[d])) {   /* one shift, however far */
                    if (!isfinite(*xd))
                        dem_fatal("particle id %lld has a position that is not a number at t = %g s (step %ld)",
                                  (long long)p->id[i], s->time, s->step);
                    *xd -= floor((*xd - s->domain_min[d]) / s->period[d]) * s->period[d];
                    if (*xd >= s->domain_max[d]) *xd -= s->period[d];   /* round-off at the sides */
                    if (*xd < s->domain_min[d]) *xd = s->domain_min[d];
                }
            } else if (*xd < s->domain_min[d] - p->radius[i] || *xd > s->domain_max[d] + p->radius[i]) {
                dem_fatal("particle id %lld left the domain at t = %g s (step %ld): position "
                          "(%g %g %g) m, domain min (%g %g %g) max (%g %g %g) m. Close the domain "
                          "with walls, make that direction periodic, or let particles leave there "
                          "through an outlet (outlets { <name> { type plane; ... } }).",
                          (long long)p->id[i], s->time, s->step, p->x[i][0], p->x[i][1], p->x[i][2],
                          s->domain_min[0], s->domain_min[1], s->domain_min[2],
                          s->domain_max[0], s->domain_max[1], s->domain_max[2]);
            }
        }
    }
}

static int cell_coord(const dem_neighbour_list *nl, double x, int d)
{
    int c = (int)floor((x - nl->origin[d]) / nl->cell_size[d]);
    if (c < 0) c = 0;
    if (c >= nl->ncell[d]) c = nl->ncell[d] - 1;
    return c;
}

/* The list's cutoff: the largest diameter + skin + the normal model's reach [m], over all ranks
 * (the halo, ghosts.h, is the same width on every rank). */
static double list_cutoff(const dem_system *s)
{
    double rmax = 0.0;
    for (int i = 0; i < s->p.n; i++) rmax = fmax(rmax, s->p.radius[i]);
    dem_reduce_doubles(&rmax, 1, DEM_REDUCE_MAX);
    return 2.0 * rmax + s->nlist.skin + s->nlist.reach;
}

/* Size the cell grid and bin the first `count` particles (counting sort). In a periodic
 * direction the grid has one more layer of cells on each side, where the ghosts lie (they are
 * within the cutoff of the box, and cells are no smaller than the cutoff). */
static void bin_particles(dem_system *s, int count, double cutoff)
{
    dem_neighbour_list *nl = &s->nlist;
    const dem_particles *p = &s->p;
    /* Cells no smaller than the cutoff, and not many more cells than particles (a sparse
     * system in a large domain would otherwise spend its time on empty cells). */
    const long max_cells = 4L * count + 64;
    long ncells;
    for (double size = cutoff;; size *= 1.26) {
        ncells = 1;
        for (int d = 0; d < 3; d++) {
            const double len = s->domain_max[d] - s->domain_min[d];
            int n = (int)fmin(floor(len / size), 1 << 20);
            if (n < 1) n = 1;
            nl->cell_size[d] = len / n;
            nl->origin[d] = s->domain_min[d] - (s->periodic[d] ? nl->cell_size[d] : 0.0);
            nl->ncell[d] = n + (s->periodic[d] ? 2 : 0);
            ncells *= nl->ncell[d];
        }
        if (ncells <= max_cells) break;
    }
    if (ncells + 1 > nl->cell_capacity) {
        nl->cell_capacity = ncells + 1;
        nl->cell_start = dem_realloc(nl->cell_start, (size_t)nl->cell_capacity * sizeof(int));
    }
    nl->cell_of = dem_realloc(nl->cell_of, (size_t)(count ? count : 1) * sizeof(int));
    nl->cell_order = dem_realloc(nl->cell_order, (size_t)(count ? count : 1) * sizeof(int));
    memset(nl->cell_start, 0, (size_t)(ncells + 1) * sizeof(int));
    for (int i = 0; i < count; i++) {
        const int c = (cell_coord(nl, p->x[i][2], 2) * nl->ncell[1] + cell_coord(nl, p->x[i][1], 1))
                      * nl->ncell[0] + cell_coord(nl, p->x[i][0], 0);
        nl->cell_of[i] = c;
        nl->cell_start[c + 1]++;
    }
    for (long c = 0; c < ncells; c++) nl->cell_start[c + 1] += nl->cell_start[c];
    int *fill = dem_malloc((size_t)ncells * sizeof(int));
    memcpy(fill, nl->cell_start, (size_t)ncells * sizeof(int));
    for (int i = 0; i < count; i++) nl->cell_order[fill[nl->cell_of[i]]++] = i;
    free(fill);
}

/* Re-order the particles by cell (after binning them alone). */
static void sort_by_cell(dem_system *s)
{
    const int n = s->p.n;
    int *order = dem_malloc((size_t)(n ? n : 1) * sizeof(int));
    memcpy(order, s->nlist.cell_order, (size_t)n * sizeof(int));
    dem_particles_permute(&s->p, order);
    free(order);
}

static void push_pair(dem_neighbour_list *nl, int j)
{
    if (nl->npairs == nl->capacity) {
        nl->capacity = nl->capacity ? 2 * nl->capacity : 4096;
        nl->partner = dem_realloc(nl->partner, (size_t)nl->capacity * sizeof(int));
    }
    nl->partner[nl->npairs++] = j;
}

void dem_neighbour_rebuild(dem_system *s)
{
    dem_neighbour_list *nl = &s->nlist;
    dem_particles *p = &s->p;
    const double t_start = dem_clock();
    dem_neighbour_wrap(s);
    const double cutoff = list_cutoff(s);
    for (int d = 0; d < 3; d++)
        if (s->periodic[d] && s->domain_max[d] - s->domain_min[d] < 3.0 * cutoff)
            dem_fatal("periodic direction %c: the domain length %g m must be at least 3 x "
                      "(largest diameter + skin) = %g m", "xyz"[d],
                      s->domain_max[d] - s->domain_min[d], 3.0 * cutoff);
    if (nl->sort_interval > 0 && nl->schedule % nl->sort_interval == 0) {
        bin_particles(s, p->n, cutoff);
        sort_by_cell(s);
        nl->sorts++;
    }
    const double t_halo = dem_clock();
    dem_ghosts_build(s, cutoff);
    const double t_search = dem_clock();
    const int total = p->n + s->ghosts.n;
    bin_particles(s, total, cutoff);

    if (p->n + 1 > nl->rows_capacity) {
        nl->rows_capacity = p->n + 1;
        nl->start = dem_realloc(nl->start, (size_t)nl->rows_capacity * sizeof(int));
    }
    nl->npairs = 0;
    const int nx = nl->ncell[0], ny = nl->ncell[1], nz = nl->ncell[2];
    const int64_t *id = p->id;
    const int *body = p->body;
    for (int i = 0; i < p->n; i++) {
        nl->start[i] = (int)nl->npairs;
        const int body_i = body[i];
        const int c = nl->cell_of[i];
        const int cx = c % nx, cy = (c / nx) % ny, cz = c / (nx * ny);
        for (int z = cz - 1; z <= cz + 1; z++) {
            if (z < 0 || z >= nz) continue;
            for (int y = cy - 1; y <= cy + 1; y++) {
                if (y < 0 || y >= ny) continue;
                for (int x = cx - 1; x <= cx + 1; x++) {
                    if (x < 0 || x >= nx) continue;
                    const int cell = (z * ny + y) * nx + x;
                    for (int m = nl->cell_start[cell]; m < nl->cell_start[cell + 1]; m++) {
                        const int j = nl->cell_order[m];
                        /* every pair once, under the particle with the lower id: a pair with a
                         * ghost has its mirror (the ghost's owner with the ghost of i, here for a
                         * periodic image, on another rank for a ghost from there), and the one
                         * rule keeps a contact with the same particle whether its partner is real
                         * or a ghost, so that its history goes where that particle goes (migrate.h) */
                        if (id[j] <= id[i]) continue;
                        if (body_i && body_i == body[j]) continue;   /* one rigid body: no contact */
                        double d2 = 0.0;
                        for (int d = 0; d < 3; d++) {
                            const double dx = p->x[i][d] - p->x[j][d];
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

    /* histories start at zero: contacts.c puts back those of continuing contacts */
    const int hs = nl->history_size;
    if (nl->capacity > nl->history_capacity) {
        nl->history_capacity = nl->capacity;
        nl->history = dem_realloc(nl->history, (size_t)nl->history_capacity * (hs ? hs : 1) * sizeof(double));
        nl->touching = dem_realloc(nl->touching, (size_t)nl->history_capacity);
    }
    memset(nl->history, 0, (size_t)nl->npairs * hs * sizeof(double));
    memset(nl->touching, 0, (size_t)nl->npairs);

    if (p->n > nl->build_capacity) {
        nl->build_capacity = p->n;
        nl->x_at_build = dem_realloc(nl->x_at_build, (size_t)p->n * sizeof(dem_vec3));
    }
    memcpy(nl->x_at_build, p->x, (size_t)p->n * sizeof(dem_vec3));
    if (total > nl->id_capacity) {
        nl->id_capacity = total + total / 4 + 16;
        nl->id_at_build = dem_realloc(nl->id_at_build, (size_t)nl->id_capacity * sizeof(int64_t));
    }
    memcpy(nl->id_at_build, p->id, (size_t)total * sizeof(int64_t));
    nl->generation = p->generation;
    nl->build_seconds += (t_halo - t_start) + (dem_clock() - t_search);
    nl->builds++;
    nl->schedule++;
}
