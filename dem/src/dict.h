/* OpenFOAM-syntax dictionary reader (constant/demProperties, couplingProperties).
 *
 * Syntax: `key value...;` entries and `key { ... }` sub-dictionaries, `//` and block
 * comments, vectors/lists in `( ... )` (optionally with a leading count, `3(1 2 3)`),
 * double-quoted strings, and `#include "file"` (path relative to the including file).
 * A `FoamFile { }` header is accepted and ignored.
 *
 * Every error is fatal, through the fatal handler of error.h, about "<file>:<line>" with the
 * message "key '<key>': ..." (by default printed as "<file>:<line>: error: key '<key>': ..."
 * with exit status 1). Every accessor records the key it
 * was asked for, found or not; dem_dict_check_unused() then reports a key that nobody read
 * as unknown and suggests the nearest key that was asked for (edit distance).
 */
#ifndef DEM_DICT_H
#define DEM_DICT_H

#include <stddef.h>

typedef struct dem_dict dem_dict;

dem_dict *dem_dict_read(const char *path);            /* fatal on I/O or syntax error */
void dem_dict_free(dem_dict *d);

const char *dem_dict_path(const dem_dict *d);          /* file the dictionary (or key) came from */
const char *dem_dict_name(const dem_dict *d);          /* "demProperties", or the sub-dictionary's key */
int dem_dict_line(const dem_dict *d);                  /* line of the opening brace (1 for the file) */
int dem_dict_key_line(const dem_dict *d, const char *key); /* line of key, or dem_dict_line(d) if absent */

/* Presence and iteration (in file order). */
int dem_dict_has(const dem_dict *d, const char *key);
int dem_dict_size(const dem_dict *d);
const char *dem_dict_key_at(const dem_dict *d, int i);
int dem_dict_is_dict_at(const dem_dict *d, int i);
dem_dict *dem_dict_dict_at(const dem_dict *d, int i);       /* marks the entry used */

/* Sub-dictionaries. */
dem_dict *dem_dict_sub(const dem_dict *d, const char *key);       /* fatal if missing or not a dict */
dem_dict *dem_dict_sub_opt(const dem_dict *d, const char *key);   /* NULL if missing */

/* Scalars with a range check [lo, hi] (fatal outside; message names file, line, key, range). */
double dem_dict_scalar(const dem_dict *d, const char *key, double lo, double hi);
double dem_dict_scalar_opt(const dem_dict *d, const char *key, double def, double lo, double hi);
long dem_dict_label(const dem_dict *d, const char *key, long lo, long hi);
long dem_dict_label_opt(const dem_dict *d, const char *key, long def, long lo, long hi);

/* true/false, yes/no, on/off. */
int dem_dict_bool_opt(const dem_dict *d, const char *key, int def);

/* Vectors: exactly three numbers in parentheses. */
void dem_dict_vector(const dem_dict *d, const char *key, double out[3]);
void dem_dict_vector_opt(const dem_dict *d, const char *key, double out[3], const double def[3]);
/* One number `s` (returns 1; out = (s s s)) or a vector `(a b c)` (returns 3), each value in
 * [lo, hi]; e.g. a lattice spacing. */
int dem_dict_scalar_or_vector(const dem_dict *d, const char *key, double lo, double hi, double out[3]);
/* Three booleans in parentheses, e.g. periodic (false false true). */
void dem_dict_bools3_opt(const dem_dict *d, const char *key, int out[3], int def);

/* Words. dem_dict_choice returns the index in options[] (NULL-terminated); anything else is
 * fatal and the message lists the options and the nearest one. */
const char *dem_dict_word(const dem_dict *d, const char *key);
const char *dem_dict_word_opt(const dem_dict *d, const char *key, const char *def);
int dem_dict_is_word(const dem_dict *d, const char *key);   /* key present with one word as its value */
int dem_dict_is_dict(const dem_dict *d, const char *key);   /* key present with a sub-dictionary */
int dem_dict_choice(const dem_dict *d, const char *key, const char *const options[]);
int dem_dict_choice_opt(const dem_dict *d, const char *key, const char *const options[], int def);

/* List of numbers `(a b c ...)`; returns the count, *out malloc'd (caller frees). */
int dem_dict_scalar_list(const dem_dict *d, const char *key, double **out);
/* List of vectors `((x y z) (x y z) ...)`; returns the count, *out malloc'd as 3*count doubles. */
int dem_dict_vector_list(const dem_dict *d, const char *key, double **out);

/* Report the first key (recursively, in sub-dictionaries) that no accessor asked for. */
void dem_dict_check_unused(const dem_dict *d);

/* Fatal error about `key` in d, with file and line: "<file>:<line>: error: key '<key>': <msg>". */
void dem_dict_fatal(const dem_dict *d, const char *key, const char *fmt, ...)
    __attribute__((format(printf, 3, 4), noreturn));
/* Same, at the line of the dictionary itself. */
void dem_dict_fatal_here(const dem_dict *d, const char *fmt, ...)
    __attribute__((format(printf, 2, 3), noreturn));

#endif
