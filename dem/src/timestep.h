/* Time-step check at start: the Rayleigh time of the smallest particle of each material, and
 * the contact time (Hertz, or the linear spring's for hooke) of the smallest, softest pair at
 * the largest expected impact velocity. The step must not exceed RAYLEIGH_FRACTION of the
 * first and CONTACT_FRACTION of the second. */
#ifndef DEM_TIMESTEP_H
#define DEM_TIMESTEP_H

#define RAYLEIGH_FRACTION 0.2
#define CONTACT_FRACTION 0.1

struct dem_system;
typedef struct dem_timestep_limits {
    double rayleigh_time;     /* [s] smallest over the particles present */
    double contact_time;      /* [s] smallest over type pairs and walls */
    double largest_safe_dt;   /* [s] */
    const char *rayleigh_material, *contact_pair;
} dem_timestep_limits;

dem_timestep_limits dem_timestep_limits_compute(const struct dem_system *s, double max_velocity);
/* Print the fractions; stop with the largest safe step if dt is too large (unless override,
 * which prints a loud warning instead). source names the file for the message. */
void dem_timestep_check(const struct dem_system *s, double max_velocity, int override, const char *source);

#endif
