/* Symmetry planes: a frictionless, perfectly elastic mirror for the particle centres.
 *
 * A symmetry plane exerts no force, so it is not a wall: it is in no wall force loop, has no
 * material, no candidate list and no contact history. A particle's centre may reach the plane (the sphere then sticks out across
 * it; no image particles are made, as in DPMFoam). When a centre has crossed the plane during
 * the drift of a step, its motion is mirrored at the crossing:
 *
 *     d = (x - p).n < 0         signed distance of the centre (n the unit normal, p a point)
 *     x <- x - 2 d n            the position mirrored (the path continued after the bounce)
 *     v <- v - 2 (v.n) n        the normal velocity reversed: e = 1
 *     omega unchanged           no friction: mu = 0
 *
 * That is the whole rule for a particle that feels no force. With a force, the step's impulse
 * is split at the crossing time, so that the part received before the bounce is mirrored and
 * the part after it is not (the plain rule mirrors the whole first half kick, an energy error
 * of order F v dt per bounce: in test_symmetry's bed of elastic spheres that drifted the energy
 * by 0.7e-4 to 6.4e-4 over 1e5 steps (8 seeds), against 1.2e-5 to 2.6e-5 in the same box with
 * a wall; split, 0.9e-5 to 4.5e-5). In the normal coordinate the drift of velocity Verlet follows
 * d(t) = d_n + u t + alpha t^2 / 2 over the step (u = v_n.n, alpha = F_n.n / m, F_n the force
 * of the first half kick: this is exactly where the drift ends), so
 *
 *     tau   = 2 d_n / (-u + sqrt(u^2 - 2 alpha d_n))                     first crossing, in [0, dt]
 *     d     = -(u + alpha tau)(dt - tau) + alpha (dt - tau)^2 / 2        at the end of the step,
 *                                                                        clamped at 0 (pressed onto it)
 *     v.n   = -(u + alpha tau) + alpha (dt/2 - tau)                      at the half step (the second
 *                                                                        half kick adds dt/2 F_n+1.n / m)
 *
 * and the tangential motion is that of the drift. A constant force (a sphere bouncing on a
 * mirror floor under gravity) is so integrated exactly. Several planes are tried in turn; a
 * crossing re-checks the others (at most four passes, enough for a corner of planes at right
 * angles or wider). Applied in dem_system_step's drift (system.c). */
#ifndef DEM_SYMMETRY_H
#define DEM_SYMMETRY_H

#define DEM_MAX_SYMMETRY_PLANES 8

typedef struct dem_symmetry_plane {
    char name[96];
    double point[3];
    double normal[3];        /* unit normal pointing into the particle side */
    double offset;           /* point . normal, so that d = x . normal - offset */
} dem_symmetry_plane;

/* Signed distance of a point from the plane [m] (negative: beyond it). */
static inline double symmetry_distance(const dem_symmetry_plane *sp, const double x[3])
{
    return x[0] * sp->normal[0] + x[1] * sp->normal[1] + x[2] * sp->normal[2] - sp->offset;
}

/* The bounce of one particle that crossed a plane (symmetry.c); x, v after the drift, f the
 * force of the step's first half kick. */
void dem_symmetry_bounce(const dem_symmetry_plane *planes, int nplanes, double x[3], double v[3], const double f[3],
                     double inv_mass, double dt);

/* After the drift of one particle: mirror it if its centre crossed a plane. */
static inline void symmetry_apply(const dem_symmetry_plane *planes, int nplanes, double x[3], double v[3],
                                  const double f[3], double inv_mass, double dt)
{
    for (int k = 0; k < nplanes; k++)
        if (symmetry_distance(&planes[k], x) < 0.0) {
            dem_symmetry_bounce(planes, nplanes, x, v, f, inv_mass, dt);
            return;
        }
}

#endif
