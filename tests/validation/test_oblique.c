/* Oblique impact of a sphere on a plane wall, Hertz + tangential history.
 *  - Coulomb sliding throughout the contact (vt > 3.5 dvt, so the contact point never sticks):
 *    the change of tangential velocity equals mu (1 + e) vn, e the measured normal restitution;
 *    tolerance 1 %. That identity needs Fn >= 0 throughout (friction acts on |Fn|, while the
 *    normal impulse counts the dashpot's pull at the end of the contact with its sign), so it is
 *    checked with limitForce on; without it, for e = 0.9 where the pull is small.
 *  - With arguments `E nu rho r e mu vn vt [steps per contact]` it prints the rebound (RESULT vx/vz/omega_y) for
 *    the comparison with LIGGGHTS in the sticking regime (test_liggghts_oblique.sh). */
#include <stdlib.h>

#include "impact.h"

int main(int argc, char **argv)
{
    if (argc == 9 || argc == 10) {
        const impact_spec sp = {atof(argv[1]), atof(argv[2]), atof(argv[3]), atof(argv[4]), atof(argv[5]),
                                atof(argv[6]), normal_hertz, tangential_history, 1.0, 1,
                                atof(argv[7]), atof(argv[8]),
                                argc == 10 ? atof(argv[9]) : 2000.0, 0};
        const impact_result res = run_impact(&sp);
        printf("RESULT vx %.10g\nRESULT vz %.10g\nRESULT omega_y %.10g\n", res.vt_after, res.vn_after, res.omega_after);
        return 0;
    }
    const struct { double E, nu, e, mu, vn, vt; int limit; } cases[] = {
        {5e6, 0.45, 0.5, 0.3, 1.0, 3.0, 1},
        {5e6, 0.45, 0.9, 0.1, 0.5, 2.0, 0},
        {63e9, 0.2, 0.7, 0.5, 2.0, 8.0, 1},
        {63e9, 0.2, 0.9, 0.3, 1.0, 3.0, 0},
    };
    for (int k = 0; k < 4; k++) {
        const impact_spec sp = {cases[k].E, cases[k].nu, 2500, 1e-3, cases[k].e, cases[k].mu,
                                normal_hertz, tangential_history, 1.0, 1, cases[k].vn, cases[k].vt, 2000.0,
                                cases[k].limit};
        const impact_result res = run_impact(&sp);
        const double dvt = cases[k].vt - res.vt_after;
        const double expected = cases[k].mu * (1.0 + res.restitution) * cases[k].vn;
        char what[128];
        snprintf(what, sizeof what, "sliding E=%g e=%g mu=%g vn=%g vt=%g%s: dvt", cases[k].E, cases[k].e,
                 cases[k].mu, cases[k].vn, cases[k].vt, cases[k].limit ? " limitForce" : "");
        check_rel(what, dvt, expected, 0.01);
        /* the contact point keeps sliding forwards: vt - r omega stays positive */
        snprintf(what, sizeof what, "sliding case %d: still sliding at the end", k);
        check_true(what, res.vt_after - 1e-3 * res.omega_after > 0.0);
    }
    return finish("test_oblique");
}
