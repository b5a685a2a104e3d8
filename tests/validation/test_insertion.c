/* Insertion: no overlaps, every particle inside its region, the requested number or solid
 * fraction, and the size distributions' moments against their closed forms:
 *  constant: all equal; uniform [a, b]: mean (a+b)/2, std (b-a)/sqrt(12);
 *  normal truncated symmetrically at mean +- z sigma: mean, std sigma sqrt(1 - 2 z phi(z) / (2 Phi(z) - 1));
 *  discrete: number fractions equal the weights.
 * Tolerances: 3 standard errors of the sample statistic (stated per check). */
#include <stdlib.h>

#include "harness.h"
#include "insert.h"

static dem_system fresh(void)
{
    dem_system s;
    make_system(&s, 5e6, 0.45, 2500, 0.5, 0.5, normal_hertz, tangential_history, 0.5);
    return s;
}

static dem_insertion box_region(double half)
{
    dem_insertion ins;
    memset(&ins, 0, sizeof ins);
    snprintf(ins.name, sizeof ins.name, "test");
    for (int d = 0; d < 3; d++) { ins.min[d] = -half; ins.max[d] = half; }
    ins.seed = 42;
    ins.max_attempts = 1000;
    return ins;
}

static void stats(const dem_system *s, double *mean, double *std)
{
    double a = 0, b = 0;
    for (int i = 0; i < s->p.n; i++) { const double d = 2 * s->p.radius[i]; a += d; b += d * d; }
    *mean = a / s->p.n;
    *std = sqrt(b / s->p.n - *mean * *mean);
}

static int overlaps_or_outside(const dem_system *s, const dem_insertion *ins)
{
    const dem_particles *p = &s->p;
    for (int i = 0; i < p->n; i++) {
        for (int d = 0; d < 3; d++) {
            if (ins->region == REGION_BOX && (p->x[i][d] - p->radius[i] < ins->min[d] || p->x[i][d] + p->radius[i] > ins->max[d])) return 1;
        }
        if (ins->region == REGION_CYLINDER) {
            const int a = ins->axis, b = (a + 1) % 3, c = (a + 2) % 3;
            const double rho = hypot(p->x[i][b] - ins->centre[0], p->x[i][c] - ins->centre[1]);
            if (rho + p->radius[i] > ins->radius) return 1;
            if (p->x[i][a] - p->radius[i] < ins->min[a] || p->x[i][a] + p->radius[i] > ins->max[a]) return 1;
        }
        for (int j = i + 1; j < p->n; j++) {
            const double dx = p->x[i][0] - p->x[j][0], dy = p->x[i][1] - p->x[j][1], dz = p->x[i][2] - p->x[j][2];
            if (dx * dx + dy * dy + dz * dz < pow(p->radius[i] + p->radius[j], 2)) return 1;
        }
    }
    return 0;
}

int main(void)
{
    const int N = 4000;
    char what[128];
    { /* constant, box, by number */
        dem_system s = fresh();
        dem_insertion ins = box_region(0.1);
        ins.number = N; ins.dist = SIZE_CONSTANT; ins.d_value = 2e-3;
        check_true("constant: the requested number inserted", dem_insertion_run(&s, &ins) == N && s.p.n == N);
        int equal = 1;
        for (int i = 0; i < s.p.n; i++) equal &= 2 * s.p.radius[i] == 2e-3;
        check_true("constant: every diameter equal to the value", equal);
        check_true("constant: no overlaps, all inside the box", !overlaps_or_outside(&s, &ins));
        dem_system_free(&s);
    }
    { /* uniform */
        dem_system s = fresh();
        dem_insertion ins = box_region(0.1);
        const double a = 1e-3, b = 3e-3;
        ins.number = N; ins.dist = SIZE_UNIFORM; ins.d_min = a; ins.d_max = b;
        dem_insertion_run(&s, &ins);
        double mean, std;
        stats(&s, &mean, &std);
        const double sd = (b - a) / sqrt(12.0);
        snprintf(what, sizeof what, "uniform: mean diameter (3 standard errors)");
        check_rel(what, mean, 0.5 * (a + b), 3 * sd / sqrt(N) / (0.5 * (a + b)));
        /* standard error of a sample std: sd sqrt((kurtosis - 1) / (4 N)), kurtosis 1.8 */
        check_rel("uniform: standard deviation (3 standard errors)", std, sd, 3 * sqrt(0.8 / (4.0 * N)));
        check_true("uniform: no overlaps, all inside the box", !overlaps_or_outside(&s, &ins));
        dem_system_free(&s);
    }
    { /* normal truncated at +-1.5 sigma, in a cylinder */
        dem_system s = fresh();
        dem_insertion ins = box_region(0.1);
        ins.region = REGION_CYLINDER; ins.axis = 2; ins.radius = 0.08; ins.centre[0] = 0.01;
        const double mu = 2e-3, sigma = 0.4e-3, z = 1.5;
        ins.number = N; ins.dist = SIZE_NORMAL; ins.d_mean = mu; ins.d_std = sigma;
        ins.d_min = mu - z * sigma; ins.d_max = mu + z * sigma;
        dem_insertion_run(&s, &ins);
        double mean, std;
        stats(&s, &mean, &std);
        const double phi = exp(-0.5 * z * z) / sqrt(2 * M_PI), Phi = 0.5 * (1 + erf(z / sqrt(2.0)));
        const double sd = sigma * sqrt(1 - 2 * z * phi / (2 * Phi - 1));
        check_rel("normal truncated: mean diameter (3 standard errors)", mean, mu, 3 * sd / sqrt(N) / mu);
        /* kurtosis of the truncated normal is below 3: standard error below sd sqrt(2 / (4 N)) */
        check_rel("normal truncated: standard deviation (3 standard errors)", std, sd, 3 * sqrt(2.0 / (4.0 * N)));
        check_true("normal truncated: no overlaps, all inside the cylinder", !overlaps_or_outside(&s, &ins));
        dem_system_free(&s);
    }
    { /* discrete, by solid fraction */
        dem_system s = fresh();
        dem_insertion ins = box_region(0.05);
        double values[2] = {1e-3, 3e-3}, weights[2] = {0.7, 0.3};
        ins.solid_fraction = 0.15; ins.dist = SIZE_DISCRETE; ins.ndiscrete = 2;
        ins.d_values = values; ins.d_weights = weights;
        dem_insertion_run(&s, &ins);
        int small = 0;
        double volume = 0;
        for (int i = 0; i < s.p.n; i++) {
            small += s.p.radius[i] < 1e-3;
            volume += 4.0 / 3.0 * M_PI * pow(s.p.radius[i], 3);
        }
        const double frac = (double)small / s.p.n;
        printf("discrete: %d particles\n", s.p.n);
        check_rel("discrete: number fraction of the first value (3 standard errors)", frac, 0.7,
                  3 * sqrt(0.7 * 0.3 / s.p.n) / 0.7);
        const double target = 0.15 * pow(0.1, 3), last = 4.0 / 3.0 * M_PI * pow(1.5e-3, 3);
        check_true("discrete: solid fraction reached, by less than one particle's volume over",
                   volume >= target && volume - target < last);
        check_true("discrete: no overlaps, all inside the box", !overlaps_or_outside(&s, &ins));
        dem_system_free(&s);
    }
    return finish("test_insertion");
}
