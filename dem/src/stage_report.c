/* What a scene costs, stage by stage and model by model, printed at the end of a run.
 *
 * The stages come from the step's own clock (stage_timer.h). The contact models share one fused
 * pair kernel, so a model's share cannot be read off a clock inside it without slowing it down:
 * instead, at the end of the run, the pair kernel is run on the final lists a few times as the
 * case has it and once more for each optional model (tangential, cohesion, rolling, surface) with
 * that model switched off, each as the case would run it (a specialised kernel where one exists,
 * evaluate.h). The difference is what the model costs; what remains with every optional model
 * off is the contact search and the normal model. The probe works on copies: forces, torques,
 * histories and the touching flags are put back bit for bit, so a run continued afterwards is
 * the run it would have been. */
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "system.h"

#define STAGE_TEXT(N, TEXT) TEXT,
const char *const dem_stage_names[DEM_STAGE_COUNT] = {DEM_STAGES(STAGE_TEXT)};
#undef STAGE_TEXT

/* each optional slot's "off" model */
static const int slot_off[SLOT_COUNT] = {-1, tangential_none, cohesion_none, rolling_none, surface_default};

/* Seconds per evaluation of the pair kernel with models m, on the current lists; history: the
 * one to start from (the case's, or zeros when the models differ: another layout). */
static double time_pairs(dem_system *s, const dem_contact_models *m, const double *history, size_t nhist, int reps)
{
    const dem_contact_models kept = s->models;
    s->models = *m;
    const int nall = s->p.n + s->ghosts.n;
    double best = 1e300;
    for (int r = 0; r < reps; r++) {
        if (history) memcpy(s->nlist.history, history, nhist * sizeof(double));
        else if (nhist) memset(s->nlist.history, 0, nhist * sizeof(double));
        memset(s->p.f, 0, (size_t)nall * sizeof *s->p.f);
        memset(s->p.torque, 0, (size_t)nall * sizeof *s->p.torque);
        const double t0 = dem_clock();
        dem_pair_forces_add(s);
        const double t = dem_clock() - t0;
        best = t < best ? t : best;   /* the least disturbed of the repetitions */
    }
    s->models = kept;
    return best;
}

static void model_probe(dem_system *s, double pair_seconds)
{
    const int nall = s->p.n + s->ghosts.n;
    if (s->nlist.npairs == 0 || nall == 0) return;
    const size_t nhist = (size_t)s->nlist.npairs * (size_t)s->history_size;
    double *hist = nhist ? malloc(nhist * sizeof *hist) : NULL;
    unsigned char *touching = malloc((size_t)s->nlist.npairs);
    dem_vec3 *f = malloc((size_t)nall * sizeof *f), *t = malloc((size_t)nall * sizeof *t);
    if ((nhist && !hist) || !touching || !f || !t) {
        free(hist); free(touching); free(f); free(t);
        dem_warning("stage report: no memory for the contact models' probe; skipped");
        return;
    }
    if (nhist) memcpy(hist, s->nlist.history, nhist * sizeof *hist);
    memcpy(touching, s->nlist.touching, (size_t)s->nlist.npairs);
    memcpy(f, s->p.f, (size_t)nall * sizeof *f);
    memcpy(t, s->p.torque, (size_t)nall * sizeof *t);
    const double overlap = s->max_overlap_seen;

    /* repetitions: about 0.05 s per configuration, 3 to 50 */
    const double one = time_pairs(s, &s->models, hist, nhist, 1);
    int reps = one > 0 ? (int)(0.05 / one) : 50;
    reps = reps < 3 ? 3 : reps > 50 ? 50 : reps;
    const double all = time_pairs(s, &s->models, hist, nhist, reps);
    dem_contact_models base = s->models;
    dem_info("  contact models (probe: the pair kernel on the final lists, best of %d, %.3g ms per step with every model;\n"
             "  each model's share is the time it saves when switched off alone, scaled to the run's pair time):",
             reps, 1e3 * all);
    for (int slot = SLOT_TANGENTIAL; slot < SLOT_COUNT; slot++) {
        if (contact_model_id(&s->models, slot) == slot_off[slot]) continue;
        dem_contact_models m = s->models;
        *contact_model_id_ref(&m, slot) = slot_off[slot];
        *contact_model_id_ref(&base, slot) = slot_off[slot];
        const double without = time_pairs(s, &m, NULL, nhist, reps);
        const double share = all > 0 ? (all - without) / all : 0.0;
        dem_info("    %-12s %-10s %6.1f %% of the pair kernel, %8.3f s of this run%s", dem_contact_slot_names[slot],
                 system_model(s, slot)->name, 100 * share, share * pair_seconds,
                 share < 0 ? " (below the scatter of the timings: a busy machine, or a kernel that is no faster without it)" : "");
    }
    const double rest = time_pairs(s, &base, NULL, nhist, reps);
    dem_info("    %-23s %6.1f %% of the pair kernel, %8.3f s of this run (contact search, geometry, normal %s)",
           "the rest", all > 0 ? 100 * rest / all : 0.0, all > 0 ? rest / all * pair_seconds : 0.0,
           system_model(s, SLOT_NORMAL)->name);

    if (nhist) memcpy(s->nlist.history, hist, nhist * sizeof *hist);
    memcpy(s->nlist.touching, touching, (size_t)s->nlist.npairs);
    memcpy(s->p.f, f, (size_t)nall * sizeof *f);
    memcpy(s->p.torque, t, (size_t)nall * sizeof *t);
    s->max_overlap_seen = overlap;
    free(hist); free(touching); free(f); free(t);
}

void dem_stage_report(dem_system *s, long steps)
{
    double total = 0.0;
    for (int k = 0; k < DEM_STAGE_COUNT; k++) total += s->stage_seconds[k];
    dem_info("DEM time per stage over %ld steps (%.3g s; %% of the DEM's time, us per step):", steps, total);
    for (int k = 0; k < DEM_STAGE_COUNT; k++) {
        if (s->stage_seconds[k] == 0.0) continue;
        dem_info("  %-50s %9.3f s %5.1f %% %9.2f us", dem_stage_names[k], s->stage_seconds[k],
               total > 0 ? 100 * s->stage_seconds[k] / total : 0.0, steps > 0 ? 1e6 * s->stage_seconds[k] / steps : 0.0);
    }
    model_probe(s, s->stage_seconds[DEM_STAGE_PAIRS]);
}
