/* Rotation of a rigid body in its principal frame: orientation quaternion and angular momentum.
 * docs/models/multisphere.md explains the choice.
 *
 * State: q, the unit quaternion (w, x, y, z) that turns body-frame vectors into space-frame ones;
 * L_b, the angular momentum in the body (principal) frame; I = (I1, I2, I3), the principal
 * moments. Angular velocity w_b = L_b / I (per component).
 *
 * Scheme: the free rotor H = sum_k L_k^2 / (2 I_k) split into its three axis parts and composed
 * symmetrically, R1(h/2) R2(h/2) R3(h) R2(h/2) R1(h/2) (Dullweber, Leimkuhler & McLachlan, J. Chem.
 * Phys. 107 (1997) 5840; in quaternion form the NO_SQUISH rotor of Miller et al., J. Chem. Phys.
 * 116 (2002) 8649). Each part is an exact rotation about one principal axis by phi = tau L_k / I_k:
 * the body turns by phi (q <- q (cos phi/2, sin phi/2 e_k)), and L_b, fixed in space, turns by
 * -phi in the body frame. So the step is symplectic and time-reversible, |L| is kept to round-off
 * and the space-frame L too (each part is a rotation of both together), and the energy error is
 * O(h^2) and bounded, not drifting: the properties a torque-free asymmetric body needs, where an
 * explicit Euler-equation integrator drifts in energy. With torques the step is the usual
 * velocity-Verlet splitting: half kick of the space-frame L by the torque, this free rotation,
 * half kick (dem_rigid_kick). */
#ifndef DEM_RIGID_ROTATION_H
#define DEM_RIGID_ROTATION_H

/* v_space = R(q) v_body, and back */
void dem_quat_rotate(const double q[4], const double v[3], double out[3]);
void dem_quat_rotate_inverse(const double q[4], const double v[3], double out[3]);
/* the rotation matrix of q (body to space; rows: space components) */
void dem_quat_matrix(const double q[4], double R[3][3]);
/* out = a b (apply b, then a) */
void dem_quat_multiply(const double a[4], const double b[4], double out[4]);
/* q from the rows-are-axes matrix of dem_principal_axes (body axis k = axes[k] in space) */
void dem_quat_from_axes(const double axes[3][3], double q[4]);

/* One free-rotor step of length h: q and L_b advance; q renormalised. */
void dem_rigid_free_rotation(const double I[3], double q[4], double Lb[3], double h);
/* L_b += h x (the space-frame torque T turned into the body frame) */
void dem_rigid_kick(const double q[4], double Lb[3], const double T[3], double h);

#endif
