/* The fatal handler and the logger (error.h), their defaults, and the functions the libraries
 * report through. The only place in dem/src and coupling/src that prints or exits. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

#include "error.h"

static void print_and_exit(const char *where, const char *message) __attribute__((noreturn));
static void print_and_exit(const char *where, const char *message)
{
    fflush(stdout);   /* what the run printed so far comes before the error */
    if (where)
        fprintf(stderr, "%s: error: %s\n", where, message);
    else
        fprintf(stderr, "error: %s\n", message);
    exit(1);
}

static void print_line(enum dem_log_level level, const char *message)
{
    if (level == DEM_LOG_WARNING) {
        fflush(stdout);
        fprintf(stderr, "WARNING: %s\n", message);
    } else {
        printf("%s\n", message);
    }
}

static dem_fatal_handler fatal_handler = print_and_exit;
static dem_logger logger = print_line;

dem_fatal_handler dem_set_fatal_handler(dem_fatal_handler handler)
{
    const dem_fatal_handler previous = fatal_handler;
    fatal_handler = handler ? handler : print_and_exit;
    return previous;
}

dem_logger dem_set_logger(dem_logger l)
{
    const dem_logger previous = logger;
    logger = l ? l : print_line;
    return previous;
}

/* The formatted message: in buf if it fits, else in memory of its own (the caller frees it
 * when it is not buf; if that memory is not to be had, the message is cut at size). */
static char *format(char *buf, size_t size, const char *fmt, va_list ap)
{
    va_list again;
    va_copy(again, ap);
    const int n = vsnprintf(buf, size, fmt, ap);
    if (n >= 0 && (size_t)n >= size) {
        char *whole = malloc((size_t)n + 1);
        if (whole) {
            vsnprintf(whole, (size_t)n + 1, fmt, again);
            buf = whole;
        }
    }
    va_end(again);
    return buf;
}

static void vfatal(const char *where, const char *fmt, va_list ap) __attribute__((noreturn));
static void vfatal(const char *where, const char *fmt, va_list ap)
{
    char buf[2048];
    const char *message = format(buf, sizeof buf, fmt, ap);   /* not freed: nothing returns */
    fatal_handler(where, message);
    print_and_exit(where, message);   /* a handler that returned broke its contract */
}

void dem_fatal(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vfatal(NULL, fmt, ap);
}

void dem_fatal_at(const char *where, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vfatal(where, fmt, ap);
}

static void vlog(enum dem_log_level level, const char *fmt, va_list ap)
{
    char buf[2048];
    char *message = format(buf, sizeof buf, fmt, ap);
    logger(level, message);
    if (message != buf) free(message);
}

void dem_warning(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vlog(DEM_LOG_WARNING, fmt, ap);
    va_end(ap);
}

void dem_info(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vlog(DEM_LOG_INFO, fmt, ap);
    va_end(ap);
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
