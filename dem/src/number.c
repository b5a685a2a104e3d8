/* dem_strtod (number.h): fegetexcept/fedisableexcept are glibc's; without them (another C
 * library) no traps can have been enabled by these means, and strtod is called as it is. */
#define _GNU_SOURCE
#include "number.h"

#include <fenv.h>
#include <stdlib.h>

double dem_strtod(const char *text, char **end)
{
#if defined(__GLIBC__)
    const int traps = fegetexcept();
    if (traps) fedisableexcept(traps);
    const double v = strtod(text, end);
    feclearexcept(FE_ALL_EXCEPT);
    if (traps) feenableexcept(traps);
    return v;
#else
    return strtod(text, end);
#endif
}
