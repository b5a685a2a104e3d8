/* Mass properties of a multisphere (clumped-sphere) body template, and its rotational energy.
 * docs/models/multisphere.md explains each equation; "eq. N" are seed note 004's.
 *
 * A template is N spheres, centres x_i and radii a_i in the template's own frame, of one
 * density rho. Two mass models:
 *
 *   sphereSum (eq. 1-7): each sphere has its own mass m_i = rho 4/3 pi a_i^3; M = sum m_i (1);
 *     the centre of mass R_c from sum m_i R_i = M R_c (2), r_i = R_i - R_c (3); each sphere's own
 *     inertia I_i0 = 2/5 m_i a_i^2 (5), moved to the centre of mass by the parallel-axis theorem,
 *     I_i = I_i0 1 + m_i (|r_i|^2 1 - r_i r_i^T) (6), and summed, I = sum I_i (7). Exact when the
 *     spheres do not overlap; where they do, the overlap is counted once per sphere.
 *
 *   union (the default for bodies): the body is the union of its spheres, overlaps counted once.
 *     Its volume, first and second moments are integrated over an octree of the bounding cube:
 *     a cell inside one sphere adds its exact cube moments, a cell outside all spheres nothing,
 *     and a cell that the surface cuts is split, down to a finest level where it counts whole if
 *     its centre lies in a sphere. The exact volume of each such finest cell lies between 0 and
 *     the cell's, so |V - V_exact| <= the sum of their volumes: volume_error, a bound, not an
 *     estimate (the centre test is in practice much closer: 1e-6 of the volume where the bound
 *     says 1e-2, test_clump_mass). The finest level is the first at which this bound is at most
 *     rel_tol of the volume. The bound falls with the cell size and the cells cut by the surface
 *     grow as its inverse square: 1e-2 takes about 4e7 cells for two spheres (0.5 s), 1e-3 a
 *     hundred times that. Done once per template.
 *
 * Principal axes: the inertia tensor about the centre of mass diagonalised (Jacobi rotations),
 * moments ascending, axes right-handed. A body integrates in its principal frame; its spheres'
 * centres there are body_x = axes (x_i - com).
 *
 * Rotational energy (eq. 8-10): E_rot = 1/2 w^T I w with the body's tensor (eq. 8, 10), and for
 * sphereSum the same as the sum over spheres 1/2 sum [I_i0 |w|^2 + m_i |w x r_i|^2] (eq. 9). */
#ifndef DEM_CLUMP_MASS_H
#define DEM_CLUMP_MASS_H

enum dem_clump_mass_model { CLUMP_MASS_UNION, CLUMP_MASS_SPHERE_SUM };

typedef struct dem_clump_mass {
    double volume;          /* [m^3] */
    double mass;            /* [kg] */
    double com[3];          /* centre of mass, template frame [m] */
    double inertia[3][3];   /* about the centre of mass, template axes [kg m^2] */
    double principal[3];    /* principal moments, ascending [kg m^2] */
    double axes[3][3];      /* axes[k]: the k-th principal axis (unit vector, template frame) */
    double volume_error;    /* bound on |volume - exact volume| [m^3] (union; 0 for sphereSum) */
    long cells;             /* union: octree cells visited */
} dem_clump_mass;

/* eq. 1-7 */
void dem_clump_mass_sphere_sum(int n, const double (*x)[3], const double *a, double density, dem_clump_mass *m);
/* The union of the spheres, volume_error <= rel_tol x volume (rel_tol in [1e-3, 0.1]). */
void dem_clump_mass_union(int n, const double (*x)[3], const double *a, double density, double rel_tol,
                          dem_clump_mass *m);
/* Principal moments (ascending) and axes (rows, right-handed) of a symmetric tensor; also used
 * by both mass models to fill m->principal and m->axes. */
void dem_principal_axes(const double I[3][3], double moments[3], double axes[3][3]);

/* eq. 8 / 10: 1/2 w^T I w [J] */
double dem_rotational_energy(const double I[3][3], const double w[3]);
/* eq. 9: 1/2 sum_i [2/5 m_i a_i^2 |w|^2 + m_i |w x r_i|^2], r_i from the centre of mass [J] */
double dem_rotational_energy_spheres(int n, const double (*r)[3], const double *a, const double *mass,
                                     const double w[3]);

#endif
