#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

#include "error.h"

void dem_fatal(const char *fmt, ...)
{
    va_list ap;
    fflush(stdout);
    fputs("error: ", stderr);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    exit(1);
}

void dem_fatal_at(const char *where, const char *fmt, ...)
{
    va_list ap;
    fflush(stdout);
    fprintf(stderr, "%s: error: ", where);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    exit(1);
}

void dem_warning(const char *fmt, ...)
{
    va_list ap;
    fflush(stdout);
    fputs("WARNING: ", stderr);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
}

void *dem_malloc(size_t bytes)
{
    void *p = malloc(bytes ? bytes : 1);
    if (!p) dem_fatal("out of memory allocating %zu bytes", bytes);
    return p;
}

void *dem_calloc(size_t n, size_t size)
{
    void *p = calloc(n ? n : 1, size ? size : 1);
    if (!p) dem_fatal("out of memory allocating %zu x %zu bytes", n, size);
    return p;
}

void *dem_realloc(void *p, size_t bytes)
{
    void *q = realloc(p, bytes ? bytes : 1);
    if (!q) dem_fatal("out of memory reallocating to %zu bytes", bytes);
    return q;
}
