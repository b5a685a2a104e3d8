/* Fatal errors: print a message and stop the program cleanly with exit status 1. */
#ifndef DEM_ERROR_H
#define DEM_ERROR_H

#include <stddef.h>

void dem_fatal(const char *fmt, ...) __attribute__((format(printf, 1, 2), noreturn));
/* Same, as "<where>: error: ..." (where = "file:line"), like the dictionary's errors. */
void dem_fatal_at(const char *where, const char *fmt, ...) __attribute__((format(printf, 2, 3), noreturn));
void dem_warning(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
void *dem_malloc(size_t bytes);                 /* fatal on failure */
void *dem_calloc(size_t n, size_t size);
void *dem_realloc(void *p, size_t bytes);

#endif
