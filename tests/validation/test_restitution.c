/* Coefficient of restitution.
 *  - hooke: e reproduced within 1 % for e in {0.1, 0.5, 0.9} (pair and wall): for the linear
 *    spring-dashpot, e = exp(-zeta pi / sqrt(1 - zeta^2)) exactly when the contact ends at zero
 *    overlap, and the damping coefficient is chosen from that closed form.
 *  - hertz: the restitution does not depend on the impact speed (0.1 to 10 m/s) within 1 %.
 * With arguments `hertz E nu rho r e v` it prints `RESULT restitution <e>` for one pair impact
 * (for the comparison with LIGGGHTS in test_liggghts_restitution.sh). */
#include <stdlib.h>

#include "impact.h"

static impact_spec spec(double E, double nu, double rho, double r, double e, enum dem_normal_model normal,
                        int wall, double v)
{
    impact_spec sp = {E, nu, rho, r, e, 0.0, normal, tangential_none, 1.0, wall, v, 0.0, 2000.0, 0};
    return sp;
}

int main(int argc, char **argv)
{
    if (argc == 8) {
        const impact_spec sp = spec(atof(argv[2]), atof(argv[3]), atof(argv[4]), atof(argv[5]),
                                    atof(argv[6]), normal_hertz, 0, atof(argv[7]));
        const impact_result res = run_impact(&sp);
        printf("RESULT restitution %.10g\nRESULT dt %.6g\n", res.restitution, res.dt);
        return 0;
    }
    const double es[] = {0.1, 0.5, 0.9};
    for (int wall = 0; wall <= 1; wall++)
        for (int k = 0; k < 3; k++) {
            const impact_spec sp = spec(5e6, 0.45, 2500, 1e-3, es[k], normal_hooke, wall, 0.5);
            char what[128];
            snprintf(what, sizeof what, "hooke %s e=%g", wall ? "wall" : "pair", es[k]);
            check_rel(what, run_impact(&sp).restitution, es[k], 0.01);
        }

    const struct { const char *name; double E, nu; } mats[] = {{"glass", 63e9, 0.2}, {"soft", 5e6, 0.45}};
    const double speeds[] = {0.1, 1.0, 10.0};
    const double hertz_es[] = {0.5, 0.9};
    for (int m = 0; m < 2; m++)
        for (int q = 0; q < 2; q++)
            for (int wall = 0; wall <= 1; wall++) {
                const impact_spec ref_spec = spec(mats[m].E, mats[m].nu, 2500, 1e-3, hertz_es[q], normal_hertz, wall, 1.0);
                const double e_ref = run_impact(&ref_spec).restitution;
                printf("hertz %s %s e_input=%g: restitution at 1 m/s %.5f (%.3f %% from the input)\n",
                       mats[m].name, wall ? "wall" : "pair", hertz_es[q], e_ref,
                       100.0 * (e_ref - hertz_es[q]) / hertz_es[q]);
                for (int k = 0; k < 3; k++) {
                    const impact_spec sp = spec(mats[m].E, mats[m].nu, 2500, 1e-3, hertz_es[q], normal_hertz, wall, speeds[k]);
                    char what[128];
                    snprintf(what, sizeof what, "hertz %s %s e=%g v=%g vs v=1", mats[m].name,
                             wall ? "wall" : "pair", hertz_es[q], speeds[k]);
                    check_rel(what, run_impact(&sp).restitution, e_ref, 0.01);
                }
            }
    return finish("test_restitution");
}
