/* What this machine's memory holds (memory_budget.h). */
#include <math.h>
#include <stdlib.h>
#include <unistd.h>

#include "dict.h"
#include "memory_budget.h"
#include "particles.h"

size_t dem_particle_memory_bytes(void)
{
    size_t fields = 0;
    for (int k = 0; k < PARTICLE_FIELD_COUNT; k++) fields += dem_particle_fields[k].element_size;
    return PARTICLE_MEMORY_FACTOR * fields;
}

double dem_memory_budget_bytes(void)
{
    const char *set = getenv("DEM_MEMORY_BYTES");
    if (set && *set) {
        char *end;
        const double v = strtod(set, &end);
        if (*end == '\0' && v > 0.0 && isfinite(v)) return v;
    }
    const long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGE_SIZE);
    return pages > 0 && size > 0 ? (double)pages * (double)size : 4.0 * 1024 * 1024 * 1024;   /* unknown: 4 GiB */
}

double dem_particles_affordable(void) { return floor(dem_memory_budget_bytes() / dem_particle_memory_bytes()); }

void dem_check_affordable(const dem_dict *d, const char *key, double value, double count, double power,
                          const char *what)
{
    const double most = dem_particles_affordable();
    if (!(count > most)) return;
    const double bytes = (double)dem_particle_memory_bytes(), gib = 1024.0 * 1024.0 * 1024.0;
    const double limit = value * pow(most / count, 1.0 / power);
    dem_dict_fatal(d, key, "%g is %.3g %s: about %.3g GiB at %.0f bytes each (%d x a particle's fields), where this "
                   "machine's memory (%.3g GiB) holds at most %.3g: the %s %s accepted here is %.4g",
                   value, count, what, count * bytes / gib, bytes, PARTICLE_MEMORY_FACTOR,
                   dem_memory_budget_bytes() / gib, most, power > 0 ? "largest" : "smallest", key, limit);
}
