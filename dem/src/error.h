/* Errors and log lines of the libraries (dem/ and coupling/). They never print or exit
 * themselves: a fatal error goes to the fatal handler, an info or warning line to the logger,
 * and the program that hosts them may set both (demRun keeps the defaults; the OpenFOAM
 * adapter raises FatalError and writes through Info, so that an error inside the solver stops
 * it the way OpenFOAM stops, and a parallel run can say things once).
 *
 * Defaults, as the libraries always printed:
 *   fatal    "<where>: error: <message>" (or "error: <message>") on stderr, exit status 1
 *   info     "<line>" on stdout
 *   warning  "WARNING: <line>" on stderr (stdout flushed first, so the order is kept) */
#ifndef DEM_ERROR_H
#define DEM_ERROR_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* where: the "file:line" (or file) the error is about, or NULL; message: the text after
 * "error: ". Must not return (exit, or longjmp out): the library's state after a fatal error
 * is not usable. A handler that returns anyway is followed by the default one. */
typedef void (*dem_fatal_handler)(const char *where, const char *message);

enum dem_log_level { DEM_LOG_INFO, DEM_LOG_WARNING };
/* One message, without its final newline (a message may span lines). */
typedef void (*dem_logger)(enum dem_log_level level, const char *message);

/* Set a hook (NULL: the default); returns the one set before. */
dem_fatal_handler dem_set_fatal_handler(dem_fatal_handler handler);
dem_logger dem_set_logger(dem_logger logger);

void dem_fatal(const char *fmt, ...) __attribute__((format(printf, 1, 2), noreturn));
/* The same about a place: where = "file:line", as the dictionary's errors. */
void dem_fatal_at(const char *where, const char *fmt, ...) __attribute__((format(printf, 2, 3), noreturn));
void dem_warning(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
void dem_info(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

void *dem_malloc(size_t bytes);                 /* fatal on failure */
void *dem_calloc(size_t n, size_t size);
void *dem_realloc(void *p, size_t bytes);

#ifdef __cplusplus
}
#endif
#endif
