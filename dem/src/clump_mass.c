/* Mass properties of multisphere templates (clump_mass.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "clump_mass.h"
#include "error.h"

/* I = rho (tr(J) 1 - J) from the second moment J about the centre of mass (J_de = int x_d x_e dV). */
static void inertia_from_second_moment(const double J[3][3], double density, double I[3][3])
{
    const double tr = J[0][0] + J[1][1] + J[2][2];
    for (int d = 0; d < 3; d++)
        for (int e = 0; e < 3; e++) I[d][e] = density * ((d == e ? tr : 0.0) - J[d][e]);
}

void dem_clump_mass_sphere_sum(int n, const double (*x)[3], const double *a, double density, dem_clump_mass *m)
{
    memset(m, 0, sizeof *m);
    double sum_mx[3] = {0.0, 0.0, 0.0};
    for (int i = 0; i < n; i++) {
        const double mi = density * 4.0 / 3.0 * M_PI * a[i] * a[i] * a[i];
        m->volume += 4.0 / 3.0 * M_PI * a[i] * a[i] * a[i];
        m->mass += mi;                                              /* eq. 1 */
        for (int d = 0; d < 3; d++) sum_mx[d] += mi * x[i][d];
    }
    for (int d = 0; d < 3; d++) m->com[d] = sum_mx[d] / m->mass;    /* eq. 2 */
    for (int i = 0; i < n; i++) {
        const double mi = density * 4.0 / 3.0 * M_PI * a[i] * a[i] * a[i];
        const double r[3] = {x[i][0] - m->com[0], x[i][1] - m->com[1], x[i][2] - m->com[2]};   /* eq. 3 */
        const double r2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
        const double own = 0.4 * mi * a[i] * a[i];                  /* eq. 5 */
        for (int d = 0; d < 3; d++)
            for (int e = 0; e < 3; e++)                             /* eq. 6, summed: eq. 7 */
                m->inertia[d][e] += (d == e ? own + mi * r2 : 0.0) - mi * r[d] * r[e];
    }
    dem_principal_axes(m->inertia, m->principal, m->axes);
}

/* The octree integration of the union: moments of the cells inside, the bound from the cut
 * cells of the finest level. */
typedef struct union_sums {
    int n;
    const double (*x)[3];
    const double *a;
    int finest;
    int *lists;   /* per level, the spheres that cut the cell being visited (n each) */
    double v, s1[3], s2[3][3], bound;
    long cells;
} union_sums;

static void add_cube(union_sums *u, const double c[3], double h)
{
    const double v = 8.0 * h * h * h;
    u->v += v;
    for (int d = 0; d < 3; d++) {
        u->s1[d] += v * c[d];
        for (int e = 0; e < 3; e++) u->s2[d][e] += v * (c[d] * c[e] + (d == e ? h * h / 3.0 : 0.0));
    }
}

/* cand: the spheres that may cut this cell (nc of them) */
static void visit(union_sums *u, const double c[3], double h, int level, const int *cand, int nc)
{
    u->cells++;
    int *cut = u->lists + (size_t)level * u->n, ncut = 0;
    for (int k = 0; k < nc; k++) {
        const int s = cand[k];
        double far2 = 0.0, near2 = 0.0;
        for (int d = 0; d < 3; d++) {
            const double dd = fabs(c[d] - u->x[s][d]);
            far2 += (dd + h) * (dd + h);
            const double gap = dd - h > 0.0 ? dd - h : 0.0;
            near2 += gap * gap;
        }
        const double a2 = u->a[s] * u->a[s];
        if (far2 <= a2) {   /* inside this sphere */
            add_cube(u, c, h);
            return;
        }
        if (near2 < a2) cut[ncut++] = s;
    }
    if (ncut == 0) return;   /* outside every sphere */
    if (level == u->finest) {
        for (int k = 0; k < ncut; k++) {
            const int s = cut[k];
            double r2 = 0.0;
            for (int d = 0; d < 3; d++) r2 += (c[d] - u->x[s][d]) * (c[d] - u->x[s][d]);
            if (r2 <= u->a[s] * u->a[s]) {
                add_cube(u, c, h);
                break;
            }
        }
        u->bound += 8.0 * h * h * h;
        return;
    }
    const double q = 0.5 * h;
    for (int oct = 0; oct < 8; oct++) {
        const double cc[3] = {c[0] + (oct & 1 ? q : -q), c[1] + (oct & 2 ? q : -q), c[2] + (oct & 4 ? q : -q)};
        visit(u, cc, q, level + 1, cut, ncut);
    }
}

void dem_clump_mass_union(int n, const double (*x)[3], const double *a, double density, double rel_tol,
                          dem_clump_mass *m)
{
    memset(m, 0, sizeof *m);
    if (!(rel_tol >= 1e-3 && rel_tol <= 0.1))
        dem_fatal("multisphere union mass: relative tolerance %g outside [1e-3, 0.1]", rel_tol);
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; i < n; i++)
        for (int d = 0; d < 3; d++) {
            lo[d] = fmin(lo[d], x[i][d] - a[i]);
            hi[d] = fmax(hi[d], x[i][d] + a[i]);
        }
    double c[3], h = 0.0;
    for (int d = 0; d < 3; d++) {
        c[d] = 0.5 * (lo[d] + hi[d]);
        h = fmax(h, 0.5 * (hi[d] - lo[d]));
    }
    int *all = dem_malloc((size_t)n * sizeof(int));
    for (int i = 0; i < n; i++) all[i] = i;
    int *lists = dem_malloc((size_t)17 * n * sizeof(int));
    union_sums u;
    /* each finer level costs about four times the last and halves the bound */
    for (int finest = 5;; finest++) {
        memset(&u, 0, sizeof u);
        u.n = n;
        u.x = x;
        u.a = a;
        u.finest = finest;
        u.lists = lists;
        visit(&u, c, h, 0, all, n);
        m->cells += u.cells;
        if (u.bound <= rel_tol * u.v || finest == 16) break;
    }
    free(all);
    free(lists);
    m->volume = u.v;
    m->volume_error = u.bound;
    m->mass = density * u.v;
    for (int d = 0; d < 3; d++) m->com[d] = u.s1[d] / u.v;
    double J[3][3];
    for (int d = 0; d < 3; d++)
        for (int e = 0; e < 3; e++) J[d][e] = u.s2[d][e] - u.v * m->com[d] * m->com[e];
    inertia_from_second_moment(J, density, m->inertia);
    dem_principal_axes(m->inertia, m->principal, m->axes);
}

/* Jacobi rotations on a symmetric 3x3 tensor until the off-diagonal is round-off. */
void dem_principal_axes(const double I[3][3], double moments[3], double axes[3][3])
{
    double A[3][3], V[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    memcpy(A, I, sizeof A);
    const double scale = fabs(A[0][0]) + fabs(A[1][1]) + fabs(A[2][2]);
    for (int sweep = 0; sweep < 50; sweep++) {
        const double off = fabs(A[0][1]) + fabs(A[0][2]) + fabs(A[1][2]);
        if (!(off > 1e-15 * scale)) break;
        for (int p = 0; p < 2; p++)
            for (int q = p + 1; q < 3; q++) {
                if (A[p][q] == 0.0) continue;
                const double theta = 0.5 * (A[q][q] - A[p][p]) / A[p][q];
                const double t = (theta >= 0 ? 1.0 : -1.0) / (fabs(theta) + sqrt(theta * theta + 1.0));
                const double cs = 1.0 / sqrt(t * t + 1.0), sn = t * cs;
                for (int k = 0; k < 3; k++) {   /* A <- A G (columns p, q) */
                    const double akp = A[k][p], akq = A[k][q];
                    A[k][p] = cs * akp - sn * akq;
                    A[k][q] = sn * akp + cs * akq;
                }
                for (int k = 0; k < 3; k++) {   /* A <- G^T A (rows p, q) */
                    const double apk = A[p][k], aqk = A[q][k];
                    A[p][k] = cs * apk - sn * aqk;
                    A[q][k] = sn * apk + cs * aqk;
                }
                for (int k = 0; k < 3; k++) {   /* V <- V G: columns are the eigenvectors */
                    const double vkp = V[k][p], vkq = V[k][q];
                    V[k][p] = cs * vkp - sn * vkq;
                    V[k][q] = sn * vkp + cs * vkq;
                }
            }
    }
    int order[3] = {0, 1, 2};
    for (int i = 0; i < 3; i++)
        for (int j = i + 1; j < 3; j++)
            if (A[order[j]][order[j]] < A[order[i]][order[i]]) {
                const int t = order[i];
                order[i] = order[j];
                order[j] = t;
            }
    for (int k = 0; k < 3; k++) {
        moments[k] = A[order[k]][order[k]];
        for (int d = 0; d < 3; d++) axes[k][d] = V[d][order[k]];
    }
    /* right-handed: the third axis is the cross product of the first two */
    axes[2][0] = axes[0][1] * axes[1][2] - axes[0][2] * axes[1][1];
    axes[2][1] = axes[0][2] * axes[1][0] - axes[0][0] * axes[1][2];
    axes[2][2] = axes[0][0] * axes[1][1] - axes[0][1] * axes[1][0];
}

double dem_rotational_energy(const double I[3][3], const double w[3])
{
    double e = 0.0;
    for (int d = 0; d < 3; d++)
        for (int k = 0; k < 3; k++) e += w[d] * I[d][k] * w[k];
    return 0.5 * e;
}

double dem_rotational_energy_spheres(int n, const double (*r)[3], const double *a, const double *mass,
                                     const double w[3])
{
    const double w2 = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
    double e = 0.0;
    for (int i = 0; i < n; i++) {
        const double c[3] = {w[1] * r[i][2] - w[2] * r[i][1], w[2] * r[i][0] - w[0] * r[i][2],
                             w[0] * r[i][1] - w[1] * r[i][0]};
        e += 0.4 * mass[i] * a[i] * a[i] * w2 + mass[i] * (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    }
    return 0.5 * e;
}
