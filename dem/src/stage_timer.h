/* Wall time per stage of the DEM step, summed over a run: what each modelled effect costs
 * (printed at the end of demRun and of the coupled solver; stage_report.c).
 *
 * The stages partition the step: every second of dem_system_step() is in exactly one of them,
 * so they add up to the DEM's time. A clock read (CLOCK_MONOTONIC through the vDSO) costs about
 * 20 ns and a step makes about twelve: 0.25 us, under 0.1 % of a 1,000-particle step. */
#ifndef DEM_STAGE_TIMER_H
#define DEM_STAGE_TIMER_H

#include <time.h>

#define DEM_STAGES(X)                                                                           \
    X(INTEGRATE, "integration (velocity Verlet)")                                               \
    X(LIST, "neighbour and wall lists (moved check, rebuilds)")                                 \
    X(LIFECYCLE, "insertion and removal (streams, outlets)")                                    \
    X(LIST_LIFECYCLE, "list rebuilds after insertion/removal")                                  \
    X(GHOSTS, "ghosts: images, halo (update, force fold)")                                      \
    X(PAIRS, "particle-particle contacts (every model)")                                       \
    X(WALLS, "wall contacts")                                                                   \
    X(BODIES, "multisphere bodies")                                                             \
    X(CHECKS, "health checks")

#define DEM_STAGE_ID(N, TEXT) DEM_STAGE_##N,
enum dem_stage { DEM_STAGES(DEM_STAGE_ID) DEM_STAGE_COUNT };
#undef DEM_STAGE_ID

extern const char *const dem_stage_names[DEM_STAGE_COUNT];

static inline double dem_clock(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* seconds[stage] += the time since *t; *t = now (the next stage starts where this one ended) */
static inline void dem_stage_lap(double *seconds, enum dem_stage stage, double *t)
{
    const double now = dem_clock();
    seconds[stage] += now - *t;
    *t = now;
}

#endif
