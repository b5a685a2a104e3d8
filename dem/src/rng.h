/* Small deterministic random numbers (xoshiro256**, seeded through splitmix64), so that a case
 * with the same seed inserts the same particles on every machine. */
#ifndef DEM_RNG_H
#define DEM_RNG_H

#include <math.h>
#include <stdint.h>

typedef struct dem_rng { uint64_t s[4]; } dem_rng;

static inline uint64_t rng_splitmix64(uint64_t *x)
{
    uint64_t z = (*x += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

static inline void rng_seed(dem_rng *r, uint64_t seed)
{
    for (int k = 0; k < 4; k++) r->s[k] = rng_splitmix64(&seed);
}

static inline uint64_t rng_next(dem_rng *r)
{
    uint64_t *s = r->s;
    const uint64_t x = s[1] * 5;
    const uint64_t result = ((x << 7) | (x >> 57)) * 9;
    const uint64_t t = s[1] << 17;
    s[2] ^= s[0]; s[3] ^= s[1]; s[1] ^= s[2]; s[0] ^= s[3];
    s[2] ^= t;
    s[3] = (s[3] << 45) | (s[3] >> 19);
    return result;
}

/* Uniform in [0, 1). */
static inline double rng_uniform(dem_rng *r) { return (double)(rng_next(r) >> 11) * 0x1.0p-53; }

/* Standard normal (Box-Muller). */
static inline double rng_normal(dem_rng *r)
{
    double u = rng_uniform(r);
    while (u <= 0.0) u = rng_uniform(r);
    return sqrt(-2.0 * log(u)) * cos(2.0 * M_PI * rng_uniform(r));
}

#endif
