/* Reading a case: constant/demProperties into a dem_system and the run settings. */
#ifndef DEM_CASE_H
#define DEM_CASE_H

#include "system.h"

typedef struct dem_run_settings {
    char dict_path[4096];
    double end_time;             /* [s] */
    double write_interval;       /* [s], 0: final state only */
    double progress_interval;    /* [s] wall clock */
    double max_expected_velocity;/* [m/s]; < 0: not given, use dem_case_default_max_velocity */
    int timestep_override;
    char timestep_source[4200];  /* "file:line" of timeStep, for messages */
    char domain_source[4200];    /* "file:line" of the domain entry (the coupling checks its periodic sides) */
} dem_run_settings;

/* Read <case_dir>/constant/demProperties and set up s (materials, models, walls, domain, and,
 * unless skip_insertion, the inserted particles). Every error names file, line and key. The
 * time-step check is left to the caller (after a restart has loaded its particles). */
void dem_case_read(const char *case_dir, dem_system *s, dem_run_settings *rs, int skip_insertion);

/* gravity [m/s^2] of <case_dir>/constant/demProperties, read and checked as dem_case_read does
 * (the coupled solver needs it before the session; it must not parse our file itself): 1 if the
 * key is there, else 0 with g = 0. */
int dem_case_gravity(const char *case_dir, double g[3]);

/* The fastest particle now plus a free fall over the domain's extent along gravity [m/s]. */
double dem_case_default_max_velocity(const dem_system *s);

#endif
