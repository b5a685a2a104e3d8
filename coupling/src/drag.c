/* Drag laws (formulas, references and conventions in drag.h). */
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "drag.h"

const char *const cpl_drag_law_names[] = {"SchillerNaumann", "DiFelice", "Gidaspow", "KochHill", "Beetstra", 0};

int cpl_drag_law_find(const char *name)
{
    for (int k = 0; cpl_drag_law_names[k]; k++)
        if (strcmp(name, cpl_drag_law_names[k]) == 0) return k;
    return -1;
}

/* Cd Re of the Schiller-Naumann single sphere, with the Cd = 0.44 cap above Re = 1000. */
static double schiller_naumann_cd_re(double re)
{
    return re <= 1000.0 ? 24.0 * (1.0 + 0.15 * pow(re, 0.687)) : 0.44 * re;
}

double cpl_drag_schiller_naumann(double rho_f, double mu_f, double d, double alpha, double slip)
{
    (void)alpha;   /* isolated sphere: no voidage function */
    const double re_s = rho_f * slip * d / mu_f;
    /* (pi/8) Cd rho d^2 |u| = (pi/8) mu d (Cd Re_s) */
    return M_PI / 8.0 * mu_f * d * schiller_naumann_cd_re(re_s);
}

double cpl_drag_di_felice(double rho_f, double mu_f, double d, double alpha, double slip)
{
    const double re = cpl_drag_reynolds(rho_f, mu_f, d, alpha, slip);
    /* chi -> 3.7 as Re -> 0 (log10 0 = -inf); written out so no infinities are formed */
    const double chi = re > 0.0 ? 3.7 - 0.65 * exp(-0.5 * (1.5 - log10(re)) * (1.5 - log10(re))) : 3.7;
    const double cd_sqrt_re = 0.63 * sqrt(re) + 4.8;   /* sqrt(Cd Re), Dallavalle */
    /* (pi/8) Cd rho d^2 alpha^(2-chi) |u|, with rho |u| = mu Re / (alpha d) */
    return M_PI / 8.0 * mu_f * d * pow(alpha, 1.0 - chi) * cd_sqrt_re * cd_sqrt_re;
}

double cpl_drag_gidaspow(double rho_f, double mu_f, double d, double alpha, double slip)
{
    const double vp = M_PI / 6.0 * d * d * d;
    if (alpha < 0.8)   /* Ergun, beta_vol V_p / (1 - alpha) */
        return vp * (150.0 * (1.0 - alpha) * mu_f / (alpha * d * d) + 1.75 * rho_f * slip / d);
    /* Wen-Yu: (3/4) Cd alpha rho |u| alpha^-2.65 V_p / d = (pi/8) mu d (Cd Re_p) alpha^-2.65 */
    const double re = cpl_drag_reynolds(rho_f, mu_f, d, alpha, slip);
    return M_PI / 8.0 * mu_f * d * schiller_naumann_cd_re(re) * pow(alpha, -2.65);
}

/* (1-w) (1 + 3 sqrt(phi/2) + 135/64 phi ln phi + a phi) / (1 + 0.681 phi + b phi^2 + c phi^3)
 * + w 10 phi / (1-phi)^3: the blended zero-Re parts F0 and F2 of Koch-Hill below phi = 0.4. */
static double koch_hill_blend(double phi, double w, double a, double b, double c)
{
    const double phi_ln_phi = phi > 0.0 ? phi * log(phi) : 0.0;   /* limit 0 at phi = 0 */
    const double dense = 10.0 * phi / ((1.0 - phi) * (1.0 - phi) * (1.0 - phi));
    return (1.0 - w) * (1.0 + 3.0 * sqrt(phi / 2.0) + 135.0 / 64.0 * phi_ln_phi + a * phi)
               / (1.0 + 0.681 * phi + b * phi * phi + c * phi * phi * phi)
           + w * dense;
}

double cpl_drag_koch_hill(double rho_f, double mu_f, double d, double alpha, double slip)
{
    const double phi = 1.0 - alpha;
    const double re = 0.5 * cpl_drag_reynolds(rho_f, mu_f, d, alpha, slip);
    const double w = phi > 0.0 ? exp(-10.0 * (0.4 - phi) / phi) : 0.0;
    const double dense = 10.0 * phi / ((1.0 - phi) * (1.0 - phi) * (1.0 - phi));

    const double f2 = phi < 0.4 ? koch_hill_blend(phi, w, 17.89, -11.03, 15.41) : dense;
    const double f3 = phi < 0.0953 ? 0.9351 * phi + 0.03667
                                   : 0.0673 + 0.212 * phi + 0.0232 / pow(1.0 - phi, 5.0);
    double f;
    if (phi <= 0.01) {
        const double re_t1 = (f2 - 1.0) / (3.0 / 8.0 - f3);
        f = re <= re_t1 ? 1.0 + 3.0 / 8.0 * re : f2 + f3 * re;
    } else {
        const double f0 = phi < 0.4 ? koch_hill_blend(phi, w, 17.14, -8.48, 8.16) : dense;
        const double f1 = phi <= 0.1 ? sqrt(2.0 / phi) / 40.0 : 0.11 + 5.1e-4 * exp(11.6 * phi);
        const double re_t2 = (f3 + sqrt(f3 * f3 - 4.0 * f1 * (f0 - f2))) / (2.0 * f1);
        f = re <= re_t2 ? f0 + f1 * re * re : f2 + f3 * re;
    }
    /* beta_vol V_p / phi with beta_vol = 18 mu alpha^2 phi F / d^2 */
    return 3.0 * M_PI * mu_f * d * alpha * alpha * f;
}

double cpl_drag_beetstra(double rho_f, double mu_f, double d, double alpha, double slip)
{
    const double phi = 1.0 - alpha;
    const double re = cpl_drag_reynolds(rho_f, mu_f, d, alpha, slip);
    double f = 10.0 * phi / (alpha * alpha) + alpha * alpha * (1.0 + 1.5 * sqrt(phi));
    if (re > 0.0)   /* the inertial term vanishes as Re^0.657 at Re -> 0 */
        f += 0.413 * re / (24.0 * alpha * alpha) * (1.0 / alpha + 3.0 * alpha * phi + 8.4 * pow(re, -0.343))
             / (1.0 + pow(10.0, 3.0 * phi) * pow(re, -0.5 * (1.0 + 4.0 * phi)));
    /* beta_vol V_p / phi with beta_vol = 18 mu alpha phi F / d^2 */
    return 3.0 * M_PI * mu_f * d * alpha * f;
}

cpl_drag_fn cpl_drag_function(enum cpl_drag_law law)
{
    switch (law) {
    case CPL_DRAG_SCHILLER_NAUMANN: return cpl_drag_schiller_naumann;
    case CPL_DRAG_DI_FELICE: return cpl_drag_di_felice;
    case CPL_DRAG_GIDASPOW: return cpl_drag_gidaspow;
    case CPL_DRAG_KOCH_HILL: return cpl_drag_koch_hill;
    case CPL_DRAG_BEETSTRA: return cpl_drag_beetstra;
    case CPL_DRAG_COUNT: break;
    }
    return NULL;
}

double cpl_drag_beta(enum cpl_drag_law law, double rho_f, double mu_f, double d, double alpha, double slip)
{
    const cpl_drag_fn fn = cpl_drag_function(law);
    return fn ? fn(rho_f, mu_f, d, alpha, slip) : NAN;
}
