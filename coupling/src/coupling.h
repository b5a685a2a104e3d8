/* The coupling session: what the OpenFOAM solver calls (through foam/'s adapter), once per fluid
 * time step. It owns the DEM system (dem/) and the coupling state; all arrays are flat and in
 * SI units; the adapter converts OpenFOAM's kinematic pressure (p / rho_f) before calling.
 *
 *   c = coupling_create(case, mesh, rho_f, nu_f, dt_f)   reads constant/demProperties and
 *                                                         constant/couplingProperties
 *   each fluid step:
 *     coupling_evolve(c, U, grad_p)    couplingInterval DEM steps with the drag of the current
 *                                      fluid field and the drag coefficients of the last exchange
 *                                      (implicit: at each particle's current velocity), then void
 *                                      fraction, drag coefficients, K_sl and sources
 *     alpha = coupling_alpha(c)        [ncells] fluid volume fraction (floor alphaMin)
 *     ksl = coupling_ksl(c)            [ncells] implicit exchange coefficient [kg/(m^3 s)]
 *     up = coupling_particle_velocity(c)   [ncells][3] K-weighted particle velocity [m/s]:
 *                                      the fluid momentum source is ksl (up - U_f)
 *     f = coupling_explicit_source(c)  [ncells][3] other force density on the fluid [N/m^3]
 *                                      (model A: the particles' pressure-gradient reaction is in
 *                                      the equations, not here)
 *     coupling_write(c, time)          particles to <case>/particles.h5 / .xdmf
 *   coupling_free(c) logs the time split (DEM, coupling).
 *
 * Errors: one policy in all of coupling/ (and dem/): an error is fatal and goes to the fatal
 * handler of dem/src/error.h with its message (a dictionary's with "file:line" and the key);
 * info and warning lines go to its logger. By default that prints and exits with status 1, as
 * demRun does; the OpenFOAM adapter sets both hooks (FatalError, Info). Functions that look
 * something up (a name, a cell) return -1 for "not found", which is no error.
 */
#ifndef CPL_COUPLING_H
#define CPL_COUPLING_H

#include "mesh.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct coupling coupling;

enum cpl_model_type { CPL_MODEL_A, CPL_MODEL_B };

/* mesh: filled by cpl_mesh_init (the session takes it over). rho_f [kg/m^3], nu_f [m^2/s],
 * dt_f: the fluid time step [s], which must equal couplingInterval x the DEM timeStep. t_start:
 * the fluid's start time [s]; 0 inserts the particles of demProperties, a later time continues
 * from the snapshot of <case>/particles.h5 at that time (contacts and forces included; later
 * snapshots are dropped). Errors in the dictionaries are fatal, with file, line and key. */
/* The DEM's gravity [m/s^2] from <case_dir>/constant/demProperties, read and checked by our
 * reader (errors through the fatal hook): 1 if given, else 0 with g = 0. For the solver, which
 * needs it before the session and must not parse the file with another reader. */
int coupling_case_gravity(const char *case_dir, double g[3]);

coupling *coupling_create(const char *case_dir, cpl_mesh *mesh, double rho_f, double nu_f, double dt_f,
                          double t_start);
/* 1 when the session continued from a snapshot (t_start > 0). */
int coupling_restarted(const coupling *c);
void coupling_free(coupling *c);

/* The driving pressure gradient of a periodic fluid, -grad p_drive [N/m^3] (particle_forces.h),
 * for the fluid steps from now on (0 unless set). */
void coupling_set_drive(coupling *c, const double drive[3]);
/* U: fluid velocity per cell [m/s]; grad_p: pressure gradient per cell [Pa/m]. */
void coupling_evolve(coupling *c, const double (*U)[3], const double (*grad_p)[3]);

const double *coupling_alpha(const coupling *c);
const double *coupling_ksl(const coupling *c);
const double (*coupling_particle_velocity(const coupling *c))[3];
const double (*coupling_explicit_source(const coupling *c))[3];
enum cpl_model_type coupling_model_type(const coupling *c);
int coupling_interval(const coupling *c);       /* DEM steps per fluid step */
long coupling_particle_count(const coupling *c);   /* over all ranks */
/* Mean particle velocity [m/s] and position [m] (for the tutorials' checks and the log). */
void coupling_particle_means(const coupling *c, double v[3], double x[3]);
/* The fluid's and the walls' force on all particles [N], each the mean over the last fluid
 * step's DEM steps (postProcessing/particles.dat has them too). */
void coupling_particle_forces(const coupling *c, double fluid[3], double walls[3]);

void coupling_write(coupling *c, double time);
/* Wall seconds spent so far in the DEM and in the coupling layer; lifecycle_s: the part of dem_s
 * spent in outlets and streams (removal, insertion and the list rebuilds they cause). */
void coupling_timings(const coupling *c, double *dem_s, double *coupling_s, double *lifecycle_s);
/* Print the coupling's time per stage (void fraction, interpolation, drag, exchange, output) and
 * the DEM's per stage and per contact model (dem_stage_report). The DEM's state is left as it was. */
void coupling_report_timings(coupling *c);

#ifdef __cplusplus
}
#endif
#endif
