/* Drag laws: the per-particle drag coefficient beta_p [kg/s] such that the drag on a particle is
 *
 *     F_drag = beta_p (u_f - u_p)                                              [N]
 *
 * given rho_f [kg/m^3], mu_f (dynamic viscosity) [Pa s], the particle diameter d [m], the fluid
 * volume fraction at the particle alpha [-] (0 < alpha <= 1) and the slip speed |u_f - u_p| [m/s].
 *
 * Reynolds number convention (superficial slip): Re_p = alpha rho_f |u_f - u_p| d / mu_f.
 * DiFelice, the Wen-Yu branch of Gidaspow and Beetstra use Re_p; Koch-Hill uses Re_p / 2 (its
 * Reynolds number is built on the radius); Schiller-Naumann is the isolated-sphere law and uses
 * the interstitial Re_s = rho_f |u_f - u_p| d / mu_f (= Re_p / alpha), alpha does not enter it.
 *
 * Volumetric laws (Gidaspow, Koch-Hill, Beetstra) give beta_vol [kg/(m^3 s)], the drag per unit
 * volume of mixture per unit slip, F_vol = beta_vol (u_f - u_p); with n = (1 - alpha) / V_p
 * particles per unit volume, one particle carries
 *
 *     beta_p = beta_vol V_p / (1 - alpha),   V_p = pi d^3 / 6,
 *
 * done analytically below (no division by 1 - alpha, so alpha = 1 is fine).
 *
 * The force beta_p (u_f - u_p) is the drag in the sense of model A (Zhou et al. 2010), i.e. the
 * interaction force without the pressure-gradient (generalised buoyancy) part; particle_forces.h
 * turns it into the force of model A or B.
 *
 * The laws (Cd Re written as one product, so Re = 0 is finite and exact):
 *
 * SchillerNaumann (Schiller & Naumann 1933; isolated sphere, no voidage function):
 *     Cd = 24 / Re_s (1 + 0.15 Re_s^0.687) for Re_s <= 1000, Cd = 0.44 above;
 *     beta_p = (pi/8) Cd rho_f d^2 |u_f - u_p| = 3 pi mu_f d (1 + 0.15 Re_s^0.687) below 1000.
 *     The cap is not exactly continuous: Cd(1000-) = 0.43829 vs 0.44, a 0.39 % jump.
 *
 * DiFelice (Di Felice 1994, Int. J. Multiphase Flow 20:153), Dallavalle single-sphere Cd:
 *     Cd  = (0.63 + 4.8 / sqrt(Re_p))^2,
 *     chi = 3.7 - 0.65 exp(-(1.5 - log10 Re_p)^2 / 2),
 *     F   = (1/2) Cd rho_f (pi d^2 / 4) alpha^2 |u_f - u_p|^2 alpha^-chi,
 *     beta_p = (pi/8) Cd rho_f d^2 alpha^(2 - chi) |u_f - u_p|
 *            = (pi/8) mu_f d alpha^(1 - chi) (0.63 sqrt(Re_p) + 4.8)^2.   Smooth in Re_p and alpha.
 *
 * Gidaspow (Gidaspow 1994, "Multiphase flow and fluidization"; Ding & Gidaspow 1990):
 *     alpha <  0.8, Ergun:  beta_vol = 150 (1-alpha)^2 mu_f / (alpha d^2) + 1.75 (1-alpha) rho_f |u| / d,
 *     alpha >= 0.8, Wen-Yu: beta_vol = (3/4) Cd alpha (1-alpha) rho_f |u| / d alpha^-2.65,
 *                           Cd = 24 / Re_p (1 + 0.15 Re_p^0.687) for Re_p <= 1000, 0.44 above.
 *     Discontinuous at alpha = 0.8 by definition (0.8 itself is on the Wen-Yu side).
 *     At alpha = 1 it equals SchillerNaumann.
 *
 * KochHill (Hill, Koch & Ladd 2001, J. Fluid Mech. 448:213 and 448:243; extended to all Re and
 * volume fractions by Benyahia, Syamlal & O'Brien 2006, Powder Technol. 162:166, the form used in
 * MFiX), phi = 1 - alpha, Re = Re_p / 2:
 *     beta_vol = 18 mu_f alpha^2 phi F / d^2,   beta_p = 3 pi mu_f d alpha^2 F,
 *     w   = exp(-10 (0.4 - phi) / phi),
 *     F0  = (1-w) (1 + 3 sqrt(phi/2) + 135/64 phi ln phi + 17.14 phi)
 *                 / (1 + 0.681 phi - 8.48 phi^2 + 8.16 phi^3) + w 10 phi / (1-phi)^3  (0.01 < phi < 0.4)
 *         = 10 phi / (1-phi)^3                                                          (phi >= 0.4)
 *     F1  = sqrt(2/phi) / 40 (0.01 < phi <= 0.1),  0.11 + 5.1e-4 exp(11.6 phi) (phi > 0.1)
 *     F2  = as F0 with 17.89, -11.03, 15.41 in place of 17.14, -8.48, 8.16 (phi < 0.4),
 *           10 phi / (1-phi)^3 (phi >= 0.4)
 *     F3  = 0.9351 phi + 0.03667 (phi < 0.0953),  0.0673 + 0.212 phi + 0.0232 / (1-phi)^5 above
 *     phi <= 0.01: F = 1 + 3/8 Re for Re <= Re_t1 = (F2 - 1) / (3/8 - F3), else F2 + F3 Re;
 *     phi >  0.01: F = F0 + F1 Re^2 for Re <= Re_t2 = (F3 + sqrt(F3^2 - 4 F1 (F0 - F2))) / (2 F1),
 *                  else F2 + F3 Re.
 *     Continuous in Re (Re_t1, Re_t2 are where the branches meet) and across phi = 0.4; the law
 *     itself jumps at phi = 0.01 (dilute branch), 0.0953 (F3) and 0.1 (F1). At phi = 0 the limit
 *     phi ln phi = 0 is used (and w = 0).
 *
 * Beetstra (Beetstra, van der Hoef & Kuipers 2007, AIChE J. 53:489, monodisperse form),
 * phi = 1 - alpha, Re = Re_p:
 *     F = 10 phi / alpha^2 + alpha^2 (1 + 1.5 sqrt(phi))
 *         + 0.413 Re / (24 alpha^2) (1/alpha + 3 alpha phi + 8.4 Re^-0.343)
 *                                  / (1 + 10^(3 phi) Re^-(1 + 4 phi)/2),
 *     beta_vol = 18 mu_f alpha phi F / d^2,   beta_p = 3 pi mu_f d alpha F.   Smooth.
 *
 * The functions assume valid inputs (rho_f, mu_f, d > 0, 0 < alpha <= 1, slip >= 0): they run in
 * the per-particle loops; the session checks its parameters once.
 *
 * One page per law, with its numbered equations, sources and choices: docs/models/
 * drag_schiller_naumann.md, drag_difelice.md, drag_gidaspow.md, drag_koch_hill.md,
 * drag_beetstra.md. */
#ifndef CPL_DRAG_H
#define CPL_DRAG_H

#ifdef __cplusplus
extern "C" {
#endif

enum cpl_drag_law {
    CPL_DRAG_SCHILLER_NAUMANN,
    CPL_DRAG_DI_FELICE,
    CPL_DRAG_GIDASPOW,
    CPL_DRAG_KOCH_HILL,
    CPL_DRAG_BEETSTRA,
    CPL_DRAG_COUNT
};

/* "SchillerNaumann", "DiFelice", "Gidaspow", "KochHill", "Beetstra", then 0. */
extern const char *const cpl_drag_law_names[];

/* The law called `name`, or -1 (the caller reports the error with its file and key). */
int cpl_drag_law_find(const char *name);

/* beta_p [kg/s] of one particle (arguments as above). */
typedef double (*cpl_drag_fn)(double rho_f, double mu_f, double d, double alpha, double slip);

double cpl_drag_schiller_naumann(double rho_f, double mu_f, double d, double alpha, double slip);
double cpl_drag_di_felice(double rho_f, double mu_f, double d, double alpha, double slip);
double cpl_drag_gidaspow(double rho_f, double mu_f, double d, double alpha, double slip);
double cpl_drag_koch_hill(double rho_f, double mu_f, double d, double alpha, double slip);
double cpl_drag_beetstra(double rho_f, double mu_f, double d, double alpha, double slip);

/* The function of a law: pick it once, outside the particle loop. NULL for an invalid law. */
cpl_drag_fn cpl_drag_function(enum cpl_drag_law law);

/* One evaluation through the table (tests, diagnostics; not for hot loops). */
double cpl_drag_beta(enum cpl_drag_law law, double rho_f, double mu_f, double d, double alpha, double slip);

/* Re_p = alpha rho_f slip d / mu_f [-]. */
static inline double cpl_drag_reynolds(double rho_f, double mu_f, double d, double alpha, double slip)
{
    return alpha * rho_f * slip * d / mu_f;
}

#ifdef __cplusplus
}
#endif
#endif
