/* Outlets (outlets.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "system.h"

dem_outlet *dem_outlets_add(dem_system *s, const char *name)
{
    s->outlets = dem_realloc(s->outlets, (size_t)(s->noutlets + 1) * sizeof *s->outlets);
    dem_outlet *o = &s->outlets[s->noutlets++];
    memset(o, 0, sizeof *o);
    snprintf(o->name, sizeof o->name, "%s", name);
    return o;
}

static int acts(const dem_outlet *o, long step) { return o->every <= 1 || step % o->every == 0; }

/* 1 + the first outlet acting in `step` that takes a centre at x, 0 if none */
static int outlet_of(const dem_system *s, const double x[3], long step)
{
    for (int k = 0; k < s->noutlets; k++)
        if (acts(&s->outlets[k], step) && dem_outlet_takes(&s->outlets[k], x)) return k + 1;
    return 0;
}

/* Every step: one pass without branches over the free spheres (a body's spheres go by the body's
 * centre), so that it costs a few operations per particle and outlet. */
int dem_outlets_any(const dem_system *s, long step)
{
    const dem_particles *p = &s->p;
    int any = 0;
    for (int k = 0; k < s->noutlets; k++) {
        const dem_outlet *o = &s->outlets[k];
        if (!acts(o, step)) continue;
        for (int i = 0; i < p->n; i++) any |= dem_outlet_takes(o, p->x[i]) & !p->body[i];
        for (int b = 0; b < s->bodies.n; b++) any |= dem_outlet_takes(o, s->bodies.x[b]);
    }
    return any;
}

void dem_outlets_remove(dem_system *s, long step)
{
    dem_particles *p = &s->p;
    int *mark = dem_calloc((size_t)(p->n ? p->n : 1), sizeof *mark);
    int *body_out = dem_calloc((size_t)(s->bodies.n ? s->bodies.n : 1), sizeof *body_out);
    for (int b = 0; b < s->bodies.n; b++) {
        body_out[b] = outlet_of(s, s->bodies.x[b], step);
        if (body_out[b]) dem_tally_add(&s->outlets[body_out[b] - 1].removed, 1, dem_mass_to_quanta(dem_body_mass(&s->bodies, b)));
    }
    for (int i = 0; i < p->n; i++) {
        if (p->body[i]) {
            mark[i] = body_out[dem_body_index(&s->bodies, p->body[i])];
            continue;
        }
        mark[i] = outlet_of(s, p->x[i], step);
        if (mark[i]) dem_tally_add(&s->outlets[mark[i] - 1].removed, 1, dem_mass_to_quanta(p->mass[i]));
    }
    dem_system_remove_marked(s, mark);
    free(mark);
    free(body_out);
}
