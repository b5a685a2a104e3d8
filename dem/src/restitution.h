/* The dashpot that gives an entered coefficient of restitution, for any power-law spring.
 *
 * Normal force on an overlap x >= 0 closing at the rate x' (m: the effective mass):
 *     F = k x^d + alpha sqrt(m dF_el/dx) x' = k x^d + alpha sqrt(d k m) x^((d-1)/2) x'
 * (d = 1: Hooke; d = 1.5: Hertz and Edinburgh's loading branch). In the units where the impact
 * speed is 1 and the length (m v0^2 / k)^(1/(d+1)), an impact is
 *     X'' = -X^d - alpha sqrt(d) X^((d-1)/2) X',   X(0) = 0, X'(0) = 1,
 * so the restitution e = -X'(end) depends on alpha and d only: not on the speed, the mass or
 * the stiffness. With limitForce (clipped) the force never pulls: the particles part when F
 * first reaches 0 on the way out, with the speed they have then; without it they part when
 * X returns to 0. Closed forms exist only for d = 1 (docs/models/restitution.md); every other
 * case is found by integrating the impact (RK4, 4e4 steps over the contact) and bisecting on
 * alpha. docs/models/restitution.md gives the derivation and the curves. */
#ifndef DEM_RESTITUTION_H
#define DEM_RESTITUTION_H

/* The restitution of one impact with damping alpha >= 0 and exponent d >= 1. */
double dem_restitution_of_damping(double alpha, double d, int clipped);

/* The alpha that gives restitution e (0 < e <= 1; e = 1 gives 0), to 1e-10 in e. */
double dem_damping_for_restitution(double e, double d, int clipped);

#endif
