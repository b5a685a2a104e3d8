/* OpenFOAM-syntax dictionary reader. See dict.h for the accepted syntax and the error
 * policy: every problem is a fatal error (error.h) about "<file>:<line>", which by default
 * prints "<file>:<line>: error: ..." and exits with 1.
 *
 * Structure: a small lexer turns the file into tokens; the parser builds a tree of
 * dictionaries whose entries are either a sub-dictionary or the raw value tokens up to
 * the ';'. Values are interpreted only when an accessor asks for them, because only
 * then is the expected type known. Accessors remember the keys they were asked for so
 * that dem_dict_check_unused() can suggest the intended key for a typo. */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dict.h"
#include "error.h"
#include "number.h"

/* Guards against runaway recursion (self-including files, absurd nesting). */
enum { MAX_INCLUDE_DEPTH = 16, MAX_DICT_DEPTH = 64 };

typedef enum { T_EOF, T_WORD, T_NUMBER, T_STRING, T_PUNCT } tok_type;

typedef struct {
    tok_type type;
    char punct;          /* the character for T_PUNCT */
    int line;
    char *text;          /* owned; NULL for T_PUNCT and T_EOF */
} token;

typedef struct {
    char *key;
    char *file;          /* file the entry was read from (differs from the dict's after #include) */
    int line;
    int used;            /* touched by an accessor */
    dem_dict *sub;           /* non-NULL for `key { ... }` */
    token *tok;          /* value tokens without the ';' */
    int ntok, captok;
} entry;

struct dem_dict {
    char *name;
    char *file;
    int line;
    const dem_dict *parent;  /* for messages: "demProperties/materials/glass" */
    entry *ent;
    int n, cap;
    int *slot;           /* hash index of ent by key: entry number or -1; nslot a power of two */
    int nslot;           /* (a linear search per key made N keys cost N^2: 100,000 took minutes) */
    char **asked;        /* every key an accessor asked for, for suggestions */
    int nasked, capasked;
};

/* ------------------------------------------------------------------ small helpers */

static char *xstrndup(const char *s, size_t n)
{
    char *p = dem_malloc(n + 1);
    memcpy(p, s, n);
    p[n] = '\0';
    return p;
}

static char *xstrdup(const char *s) { return xstrndup(s, strlen(s)); }

/* A fatal error (error.h) about "<file>:<line>", the message starting with "key '<key>': ". */
static void vfatal_at(const char *file, int line, const char *key, const char *fmt, va_list ap)
    __attribute__((noreturn));
static void vfatal_at(const char *file, int line, const char *key, const char *fmt, va_list ap)
{
    char where[4200];
    if (line > 0)
        snprintf(where, sizeof where, "%s:%d", file, line);
    else
        snprintf(where, sizeof where, "%s", file);
    va_list again;
    va_copy(again, ap);
    const int n = vsnprintf(NULL, 0, fmt, ap);
    char *what = dem_malloc(n > 0 ? (size_t)n + 1 : 1);
    vsnprintf(what, n > 0 ? (size_t)n + 1 : 1, fmt, again);
    va_end(again);
    if (key) dem_fatal_at(where, "key '%s': %s", key, what);
    dem_fatal_at(where, "%s", what);
}

static void fatal_at(const char *file, int line, const char *key, const char *fmt, ...)
    __attribute__((format(printf, 4, 5), noreturn));
static void fatal_at(const char *file, int line, const char *key, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vfatal_at(file, line, key, fmt, ap);
}

static int levenshtein(const char *a, const char *b)
{
    size_t la = strlen(a), lb = strlen(b);
    int *prev = dem_malloc((lb + 1) * sizeof *prev);
    int *cur = dem_malloc((lb + 1) * sizeof *cur);
    for (size_t j = 0; j <= lb; j++) prev[j] = (int)j;
    for (size_t i = 1; i <= la; i++) {
        cur[0] = (int)i;
        for (size_t j = 1; j <= lb; j++) {
            int sub = prev[j - 1] + (a[i - 1] != b[j - 1]);
            int del = prev[j] + 1, ins = cur[j - 1] + 1;
            cur[j] = sub < del ? (sub < ins ? sub : ins) : (del < ins ? del : ins);
        }
        int *t = prev; prev = cur; cur = t;
    }
    int d = prev[lb];
    free(prev);
    free(cur);
    return d;
}

/* Nearest candidate to `word`, or NULL if none is close enough to be a plausible typo. */
static const char *nearest(const char *word, const char *const *cand, int ncand)
{
    int len = (int)strlen(word), limit = len / 2 > 2 ? len / 2 : 2;
    const char *best = NULL;
    int bestd = limit + 1;
    for (int i = 0; i < ncand; i++) {
        if (strcmp(cand[i], word) == 0) continue;
        int d = levenshtein(word, cand[i]);
        if (d < bestd) { bestd = d; best = cand[i]; }
    }
    return best;
}

/* "demProperties/materials/glass": the dictionary's position for messages. */
static void scope_name(const dem_dict *d, char *buf, size_t n)
{
    if (d->parent) {
        scope_name(d->parent, buf, n);
        size_t l = strlen(buf);
        snprintf(buf + l, n - l, "/%s", d->name);
    } else {
        snprintf(buf, n, "%s", d->name);
    }
}

/* ------------------------------------------------------------------ lexer */

typedef struct {
    const char *file;    /* path as shown in messages */
    const char *buf;     /* NUL-terminated file contents */
    size_t pos;
    int line;
    int include_depth;
    char key[64];        /* last key seen (a copy), for context in lexical errors */
    int in_entry;        /* between that key and its ';' or '{' */
    token peeked;
    int has_peek;
} lexer;

static int is_punct(int c) { return c == ';' || c == '{' || c == '}' || c == '(' || c == ')'; }

/* Lexical errors have no key of their own; naming the last key helps locate them. */
static void lex_fatal(const lexer *lx, int line, const char *what) __attribute__((noreturn));
static void lex_fatal(const lexer *lx, int line, const char *what)
{
    if (lx->key[0] && lx->in_entry)
        fatal_at(lx->file, line, lx->key, "%s", what);
    if (lx->key[0])
        fatal_at(lx->file, line, NULL, "%s (after key '%s')", what, lx->key);
    fatal_at(lx->file, line, NULL, "%s", what);
}

static void skip_space_and_comments(lexer *lx)
{
    const char *b = lx->buf;
    for (;;) {
        char c = b[lx->pos];
        if (c == '\n') {
            lx->line++;
            lx->pos++;
        } else if (isspace((unsigned char)c)) {
            lx->pos++;
        } else if (c == '/' && b[lx->pos + 1] == '/') {
            while (b[lx->pos] && b[lx->pos] != '\n') lx->pos++;
        } else if (c == '/' && b[lx->pos + 1] == '*') {
            int start = lx->line;
            lx->pos += 2;
            for (;;) {
                if (!b[lx->pos]) lex_fatal(lx, start, "unterminated comment: '/*' has no matching '*/'");
                if (b[lx->pos] == '*' && b[lx->pos + 1] == '/') { lx->pos += 2; break; }
                if (b[lx->pos] == '\n') lx->line++;
                lx->pos++;
            }
        } else {
            return;
        }
    }
}

/* OpenFOAM-style number: [+-] digits [. digits] [e [+-] digits]. Anything else
 * (including inf/nan/hex that strtod would take) is a word. */
static int looks_numeric(const char *s)
{
    int digits = 0;
    if (*s == '+' || *s == '-') s++;
    while (isdigit((unsigned char)*s)) { s++; digits++; }
    if (*s == '.') {
        s++;
        while (isdigit((unsigned char)*s)) { s++; digits++; }
    }
    if (!digits) return 0;
    if (*s == 'e' || *s == 'E') {
        s++;
        if (*s == '+' || *s == '-') s++;
        if (!isdigit((unsigned char)*s)) return 0;
        while (isdigit((unsigned char)*s)) s++;
    }
    return *s == '\0';
}

static token lex_next(lexer *lx)
{
    if (lx->has_peek) {
        lx->has_peek = 0;
        return lx->peeked;
    }
    skip_space_and_comments(lx);
    const char *b = lx->buf;
    size_t p = lx->pos;
    token t = { T_EOF, 0, lx->line, NULL };
    char c = b[p];
    if (!c) return t;
    if (is_punct(c)) {
        t.type = T_PUNCT;
        t.punct = c;
        lx->pos++;
        return t;
    }
    if (c == '"') {
        /* \" and \\ are escapes; any other backslash is kept as written. */
        char *s = dem_malloc(strlen(b + p) + 1);
        size_t n = 0, q = p + 1;
        int start = lx->line;
        for (;;) {
            if (!b[q]) lex_fatal(lx, start, "unterminated string: '\"' has no closing '\"'");
            if (b[q] == '"') break;
            if (b[q] == '\\' && (b[q + 1] == '"' || b[q + 1] == '\\')) q++;
            if (b[q] == '\n') lx->line++;
            s[n++] = b[q++];
        }
        s[n] = '\0';
        lx->pos = q + 1;
        t.type = T_STRING;
        t.text = s;
        return t;
    }
    size_t q = p;
    while (b[q] && !isspace((unsigned char)b[q]) && !is_punct(b[q]) && b[q] != '"' &&
           !(b[q] == '/' && (b[q + 1] == '/' || b[q + 1] == '*')))
        q++;
    t.text = xstrndup(b + p, q - p);
    t.type = looks_numeric(t.text) ? T_NUMBER : T_WORD;
    lx->pos = q;
    return t;
}

static const token *lex_peek(lexer *lx)
{
    if (!lx->has_peek) {
        lx->peeked = lex_next(lx);
        lx->has_peek = 1;
    }
    return &lx->peeked;
}

/* ------------------------------------------------------------------ file reading */

/* Whole file as a NUL-terminated string, or NULL with the reason in *why and, for a NUL byte,
 * its line in *line (else 0). */
static char *read_file(const char *path, const char **why, int *line)
{
    *line = 0;
    FILE *f = fopen(path, "rb");
    if (!f) { *why = strerror(errno); return NULL; }
    size_t n = 0, cap = 4096;
    char *buf = dem_malloc(cap);
    for (;;) {
        if (cap - n < 2) buf = dem_realloc(buf, cap *= 2);
        size_t got = fread(buf + n, 1, cap - n - 1, f);
        n += got;
        if (got == 0) break;
    }
    int bad = ferror(f);
    int err = errno;
    fclose(f);
    if (bad) {
        free(buf);
        *why = strerror(err ? err : EIO);
        return NULL;
    }
    buf[n] = '\0';
    const char *nul = memchr(buf, '\0', n);
    if (nul) {
        *line = 1;
        for (const char *c = buf; c < nul; c++) *line += *c == '\n';
        free(buf);
        *why = "a NUL byte (not a text file?)";
        return NULL;
    }
    return buf;
}

/* ------------------------------------------------------------------ tree building */

static dem_dict *dict_new(const char *name, const char *file, int line, const dem_dict *parent)
{
    dem_dict *d = dem_calloc(1, sizeof *d);
    d->name = xstrdup(name);
    d->file = xstrdup(file);
    d->line = line;
    d->parent = parent;
    return d;
}

static void entry_clear(entry *e)
{
    free(e->key);
    free(e->file);
    dem_dict_free(e->sub);
    for (int i = 0; i < e->ntok; i++) free(e->tok[i].text);
    free(e->tok);
    memset(e, 0, sizeof *e);
}

static size_t key_hash(const char *key)   /* FNV-1a */
{
    size_t h = 1469598103934665603ULL;
    for (const unsigned char *c = (const unsigned char *)key; *c; c++) h = (h ^ *c) * 1099511628211ULL;
    return h;
}

static entry *find(const dem_dict *d, const char *key)
{
    if (d->nslot == 0) return NULL;
    for (size_t k = key_hash(key) & (size_t)(d->nslot - 1);; k = (k + 1) & (size_t)(d->nslot - 1)) {
        const int i = d->slot[k];
        if (i < 0) return NULL;
        if (strcmp(d->ent[i].key, key) == 0) return &d->ent[i];
    }
}

/* Index entry i (its key not yet indexed); the index is kept at most half full. */
static void index_entry(dem_dict *d, int i)
{
    if (2 * (d->n + 1) > d->nslot) {
        free(d->slot);
        d->nslot = d->nslot ? 2 * d->nslot : 16;
        while (2 * (d->n + 1) > d->nslot) d->nslot *= 2;
        d->slot = dem_malloc((size_t)d->nslot * sizeof *d->slot);
        for (int k = 0; k < d->nslot; k++) d->slot[k] = -1;
        for (int j = 0; j < d->n; j++)
            if (j != i) index_entry(d, j);
    }
    size_t k = key_hash(d->ent[i].key) & (size_t)(d->nslot - 1);
    while (d->slot[k] >= 0) k = (k + 1) & (size_t)(d->nslot - 1);
    d->slot[k] = i;
}

/* Takes ownership of key. A repeated key replaces the earlier entry (OpenFOAM: the
 * later one wins); it keeps the earlier position so iteration order stays stable. */
static entry *add_entry(dem_dict *d, char *key, const char *file, int line)
{
    entry *e = find(d, key);
    if (e) {
        entry_clear(e);
    } else {
        if (d->n == d->cap) {
            d->cap = d->cap ? 2 * d->cap : 8;
            d->ent = dem_realloc(d->ent, (size_t)d->cap * sizeof *d->ent);
        }
        e = &d->ent[d->n++];
        memset(e, 0, sizeof *e);
        e->key = key;
        index_entry(d, d->n - 1);
    }
    e->key = key;
    e->file = xstrdup(file);
    e->line = line;
    return e;
}

static void push_token(entry *e, token t)
{
    if (e->ntok == e->captok) {
        e->captok = e->captok ? 2 * e->captok : 4;
        e->tok = dem_realloc(e->tok, (size_t)e->captok * sizeof *e->tok);
    }
    e->tok[e->ntok++] = t;
}

static void mark_all_used(dem_dict *d)
{
    for (int i = 0; i < d->n; i++) {
        d->ent[i].used = 1;
        if (d->ent[i].sub) mark_all_used(d->ent[i].sub);
    }
}

/* Value tokens of `key ... ;`. Parentheses must balance. A token that starts a new line
 * at parenthesis depth 0 after the value has begun almost always means a forgotten ';'
 * (`timeStep 1e-5` <newline> `endTime 0.2;`), so that is reported right here. */
static void parse_value(lexer *lx, entry *e)
{
    int depth = 0, open_line = 0, last_line = e->line;
    for (;;) {
        token t = lex_next(lx);
        if (t.type == T_EOF) {
            if (depth)
                fatal_at(lx->file, open_line, e->key, "missing ')': the '(' on this line is never closed");
            fatal_at(lx->file, last_line, e->key, "missing ';' at the end of the entry");
        }
        if (depth == 0 && e->ntok > 0 && t.line > last_line && t.type != T_PUNCT)
            fatal_at(lx->file, last_line, e->key, "missing ';' at the end of line %d", last_line);
        if (t.type == T_PUNCT) {
            switch (t.punct) {
            case ';':
                if (depth)
                    fatal_at(lx->file, t.line, e->key, "missing ')': ';' inside the '(' opened on line %d",
                             open_line);
                return;
            case '{':
                fatal_at(lx->file, t.line, e->key, "unexpected '{' in the value (missing ';' before it?)");
            case '}':
                if (depth)
                    fatal_at(lx->file, t.line, e->key, "missing ')': '}' inside the '(' opened on line %d",
                             open_line);
                fatal_at(lx->file, last_line, e->key, "missing ';' before '}'");
            case '(':
                if (depth++ == 0) open_line = t.line;
                break;
            case ')':
                if (depth-- == 0) fatal_at(lx->file, t.line, e->key, "unbalanced ')' without a matching '('");
                break;
            }
        }
        push_token(e, t);
        last_line = t.line;
    }
}

static void parse_body(lexer *lx, dem_dict *d, int depth, int braced);

static void parse_include(lexer *lx, dem_dict *d, int depth, const token *directive)
{
    int if_present = strcmp(directive->text, "#includeIfPresent") == 0;
    if (strcmp(directive->text, "#include") != 0 && !if_present)
        fatal_at(lx->file, directive->line, NULL, "unsupported directive '%s' (only #include is supported)",
                 directive->text);
    token f = lex_next(lx);
    if (f.type != T_STRING)
        fatal_at(lx->file, directive->line, NULL, "%s expects a file name in double quotes", directive->text);
    if (lx->include_depth >= MAX_INCLUDE_DEPTH)
        fatal_at(lx->file, directive->line, NULL, "#include nested more than %d deep (does \"%s\" include itself?)",
                 MAX_INCLUDE_DEPTH, f.text);

    /* Relative names are relative to the directory of the including file. */
    char *path;
    const char *slash = strrchr(lx->file, '/');
    if (f.text[0] == '/' || !slash) {
        path = xstrdup(f.text);
    } else {
        size_t dl = (size_t)(slash - lx->file) + 1;
        path = dem_malloc(dl + strlen(f.text) + 1);
        memcpy(path, lx->file, dl);
        strcpy(path + dl, f.text);
    }
    const char *why = NULL;
    int bad_line;
    char *buf = read_file(path, &why, &bad_line);
    if (!buf) {
        if (if_present && !bad_line) { free(path); free(f.text); return; }
        if (bad_line) fatal_at(path, bad_line, NULL, "included from %s:%d: %s", lx->file, directive->line, why);
        fatal_at(lx->file, directive->line, NULL, "cannot read included file '%s': %s", path, why);
    }
    lexer sub = { path, buf, 0, 1, lx->include_depth + 1, "", 0, { T_EOF, 0, 0, NULL }, 0 };
    memcpy(sub.key, lx->key, sizeof sub.key);
    parse_body(&sub, d, depth, 0);
    free(buf);
    free(path);
    free(f.text);
}

/* Entries until '}' (braced) or end of file (top level of a file). */
static void parse_body(lexer *lx, dem_dict *d, int depth, int braced)
{
    for (;;) {
        token t = lex_next(lx);
        if (t.type == T_EOF) {
            if (braced)
                fatal_at(d->file, d->line, d->name, "missing '}': the '{' on this line is never closed");
            return;
        }
        if (t.type == T_PUNCT) {
            if (t.punct == '}') {
                if (braced) return;
                lex_fatal(lx, t.line, "unexpected '}' without a matching '{'");
            }
            if (t.punct == ';') continue;   /* a stray ';' (e.g. after '}') is harmless */
            char what[64];
            snprintf(what, sizeof what, "expected a keyword, got '%c'", t.punct);
            lex_fatal(lx, t.line, what);
        }
        if (t.type != T_WORD) {
            char what[128];
            snprintf(what, sizeof what, "expected a keyword, got %s '%.60s'",
                     t.type == T_NUMBER ? "the number" : "the string", t.text);
            lex_fatal(lx, t.line, what);
        }
        if (t.text[0] == '#') {
            parse_include(lx, d, depth, &t);
            free(t.text);
            continue;
        }
        snprintf(lx->key, sizeof lx->key, "%s", t.text);
        lx->in_entry = 1;
        const token *nx = lex_peek(lx);
        entry *e = add_entry(d, t.text, lx->file, t.line);
        if (nx->type == T_PUNCT && nx->punct == '{') {
            if (depth >= MAX_DICT_DEPTH)
                fatal_at(lx->file, t.line, e->key, "sub-dictionaries nested more than %d deep", MAX_DICT_DEPTH);
            int brace_line = nx->line;
            lex_next(lx);
            lx->in_entry = 0;
            dem_dict *sub = dict_new(e->key, lx->file, brace_line, d);
            e->sub = sub;
            parse_body(lx, sub, depth + 1, 1);   /* e may move only if d grows, not sub */
            if (depth == 0 && strcmp(sub->name, "FoamFile") == 0) {
                /* The header is informational; nobody needs to read it. */
                entry *h = find(d, "FoamFile");
                h->used = 1;
                mark_all_used(sub);
            }
        } else {
            parse_value(lx, e);
            lx->in_entry = 0;
        }
    }
}

dem_dict *dem_dict_read(const char *path)
{
    const char *why = NULL;
    int bad_line;
    char *buf = read_file(path, &why, &bad_line);
    if (!buf) fatal_at(path, bad_line, NULL, "cannot read dictionary file: %s", why);
    const char *slash = strrchr(path, '/');
    dem_dict *d = dict_new(slash ? slash + 1 : path, path, 1, NULL);
    lexer lx = { path, buf, 0, 1, 0, "", 0, { T_EOF, 0, 0, NULL }, 0 };
    parse_body(&lx, d, 0, 0);
    free(buf);
    return d;
}

void dem_dict_free(dem_dict *d)
{
    if (!d) return;
    for (int i = 0; i < d->n; i++) entry_clear(&d->ent[i]);
    free(d->ent);
    free(d->slot);
    for (int i = 0; i < d->nasked; i++) free(d->asked[i]);
    free(d->asked);
    free(d->name);
    free(d->file);
    free(d);
}

/* ------------------------------------------------------------------ info and iteration */

const char *dem_dict_path(const dem_dict *d) { return d->file; }
const char *dem_dict_name(const dem_dict *d) { return d->name; }
int dem_dict_line(const dem_dict *d) { return d->line; }

int dem_dict_key_line(const dem_dict *d, const char *key)
{
    const entry *e = find(d, key);
    return e ? e->line : d->line;
}

/* Accessors take `const dict *` but record what was asked; the bookkeeping is not part
 * of the dictionary's observable contents, so casting away const is deliberate. */
static void record(const dem_dict *cd, const char *key)
{
    dem_dict *d = (dem_dict *)cd;
    for (int i = 0; i < d->nasked; i++)
        if (strcmp(d->asked[i], key) == 0) return;
    if (d->nasked == d->capasked) {
        d->capasked = d->capasked ? 2 * d->capasked : 8;
        d->asked = dem_realloc(d->asked, (size_t)d->capasked * sizeof *d->asked);
    }
    d->asked[d->nasked++] = xstrdup(key);
}

/* Records the key; marks the entry used if present. */
static entry *lookup(const dem_dict *d, const char *key)
{
    record(d, key);
    entry *e = find(d, key);
    if (e) e->used = 1;
    return e;
}

static entry *require(const dem_dict *d, const char *key)
{
    entry *e = lookup(d, key);
    if (e) return e;
    char scope[256];
    scope_name(d, scope, sizeof scope);
    /* A present-but-misspelt key is the usual cause; point at it. */
    const char **keys = dem_malloc((size_t)(d->n + 1) * sizeof *keys);
    for (int i = 0; i < d->n; i++) keys[i] = d->ent[i].key;
    const char *near = nearest(key, keys, d->n);
    if (near)
        fatal_at(d->file, d->line, key, "required entry missing in '%s' (found '%s' on line %d: a typo?)", scope,
                 near, dem_dict_key_line(d, near));
    fatal_at(d->file, d->line, key, "required entry missing in '%s'", scope);
}

int dem_dict_has(const dem_dict *d, const char *key)
{
    /* Presence checks count as asking (for suggestions) but not as reading. */
    record(d, key);
    return find(d, key) != NULL;
}

int dem_dict_size(const dem_dict *d) { return d->n; }

const char *dem_dict_key_at(const dem_dict *d, int i)
{
    if (i < 0 || i >= d->n) dem_dict_fatal_here(d, "internal: entry index %d out of range [0, %d)", i, d->n);
    return d->ent[i].key;
}

int dem_dict_is_dict_at(const dem_dict *d, int i)
{
    if (i < 0 || i >= d->n) dem_dict_fatal_here(d, "internal: entry index %d out of range [0, %d)", i, d->n);
    return d->ent[i].sub != NULL;
}

dem_dict *dem_dict_dict_at(const dem_dict *d, int i)
{
    if (i < 0 || i >= d->n) dem_dict_fatal_here(d, "internal: entry index %d out of range [0, %d)", i, d->n);
    entry *e = &d->ent[i];
    record(d, e->key);
    e->used = 1;
    if (!e->sub) fatal_at(e->file, e->line, e->key, "expected a sub-dictionary { ... }");
    return e->sub;
}

dem_dict *dem_dict_sub(const dem_dict *d, const char *key)
{
    entry *e = require(d, key);
    if (!e->sub) fatal_at(e->file, e->line, key, "expected a sub-dictionary { ... }");
    return e->sub;
}

dem_dict *dem_dict_sub_opt(const dem_dict *d, const char *key)
{
    entry *e = lookup(d, key);
    if (!e) return NULL;
    if (!e->sub) fatal_at(e->file, e->line, key, "expected a sub-dictionary { ... }");
    return e->sub;
}

/* ------------------------------------------------------------------ value helpers */

/* The value as written, for messages (shortened if long). */
static const char *show_value(const entry *e, char *buf, size_t n)
{
    size_t l = 0;
    buf[0] = '\0';
    for (int i = 0; i < e->ntok && l + 1 < n; i++) {
        const token *t = &e->tok[i];
        const token *prev = i ? &e->tok[i - 1] : NULL;
        int space = prev && !(prev->type == T_PUNCT && prev->punct == '(') &&
                    !(t->type == T_PUNCT && t->punct == ')') &&
                    !(t->type == T_PUNCT && t->punct == '(' && prev->type == T_NUMBER);
        if (t->type == T_PUNCT)
            l += (size_t)snprintf(buf + l, n - l, "%s%c", space ? " " : "", t->punct);
        else if (t->type == T_STRING)
            l += (size_t)snprintf(buf + l, n - l, "%s\"%s\"", space ? " " : "", t->text);
        else
            l += (size_t)snprintf(buf + l, n - l, "%s%s", space ? " " : "", t->text);
    }
    if (l >= n - 1 && n > 4) strcpy(buf + n - 4, "...");
    return buf;
}

static const char *show_token(const token *t, char *buf, size_t n)
{
    if (t->type == T_PUNCT)
        snprintf(buf, n, "%c", t->punct);
    else
        snprintf(buf, n, "%s", t->text);
    return buf;
}

/* The single token of a one-token value; `what` is e.g. "a number". */
static const token *single(const entry *e, const char *what)
{
    char buf[128];
    if (e->sub) fatal_at(e->file, e->line, e->key, "expected %s, got a sub-dictionary", what);
    if (e->ntok == 0) fatal_at(e->file, e->line, e->key, "expected %s, got nothing", what);
    if (e->ntok > 1) fatal_at(e->file, e->line, e->key, "expected %s, got '%s'", what, show_value(e, buf, sizeof buf));
    return &e->tok[0];
}

static double tok_number(const entry *e, const token *t, const char *what)
{
    char buf[128];
    if (t->type != T_NUMBER)
        fatal_at(e->file, t->line, e->key, "expected %s, got '%s'", what, show_token(t, buf, sizeof buf));
    double v = dem_strtod(t->text, NULL);
    if (!isfinite(v)) fatal_at(e->file, t->line, e->key, "number '%s' is too large", t->text);
    return v;
}

static void range_text(double lo, double hi, char *buf, size_t n)
{
    if (hi >= HUGE_VAL && lo <= -HUGE_VAL)
        snprintf(buf, n, "any value");
    else if (hi >= HUGE_VAL)
        snprintf(buf, n, "must be >= %.15g", lo);
    else if (lo <= -HUGE_VAL)
        snprintf(buf, n, "must be <= %.15g", hi);
    else
        snprintf(buf, n, "allowed range is [%.15g, %.15g]", lo, hi);
}

static double scalar_of(const entry *e, double lo, double hi)
{
    const token *t = single(e, "a number");
    double v = tok_number(e, t, "a number");
    if (!(v >= lo && v <= hi)) {
        char r[128];
        range_text(lo, hi, r, sizeof r);
        fatal_at(e->file, e->line, e->key, "value %s is out of range: %s", t->text, r);
    }
    return v;
}

double dem_dict_scalar(const dem_dict *d, const char *key, double lo, double hi)
{
    return scalar_of(require(d, key), lo, hi);
}

double dem_dict_scalar_opt(const dem_dict *d, const char *key, double def, double lo, double hi)
{
    entry *e = lookup(d, key);
    return e ? scalar_of(e, lo, hi) : def;
}

static long label_of(const entry *e, long lo, long hi)
{
    const token *t = single(e, "an integer");
    double v = tok_number(e, t, "an integer");
    /* 5e4 is accepted as 50000; 2.5 is not. 9e15 keeps the double exact. */
    if (v != floor(v) || fabs(v) > 9e15) fatal_at(e->file, e->line, e->key, "expected an integer, got '%s'", t->text);
    long l = (long)v;
    if (l < lo || l > hi)
        fatal_at(e->file, e->line, e->key, "value %s is out of range: allowed range is [%ld, %ld]", t->text, lo, hi);
    return l;
}

long dem_dict_label(const dem_dict *d, const char *key, long lo, long hi)
{
    return label_of(require(d, key), lo, hi);
}

long dem_dict_label_opt(const dem_dict *d, const char *key, long def, long lo, long hi)
{
    entry *e = lookup(d, key);
    return e ? label_of(e, lo, hi) : def;
}

/* 1/0 for a switch word, -1 if not one. */
static int switch_value(const token *t)
{
    static const char *const yes[] = { "true", "yes", "on" }, *const no[] = { "false", "no", "off" };
    if (t->type != T_WORD) return -1;
    for (int i = 0; i < 3; i++) {
        if (strcmp(t->text, yes[i]) == 0) return 1;
        if (strcmp(t->text, no[i]) == 0) return 0;
    }
    return -1;
}

int dem_dict_bool_opt(const dem_dict *d, const char *key, int def)
{
    entry *e = lookup(d, key);
    if (!e) return def;
    const token *t = single(e, "true/false (or yes/no, on/off)");
    int v = switch_value(t);
    char buf[128];
    if (v < 0)
        fatal_at(e->file, e->line, key, "expected true/false (or yes/no, on/off), got '%s'",
                 show_token(t, buf, sizeof buf));
    return v;
}

/* ------------------------------------------------------------------ lists */

/* A position in an entry's value tokens. */
typedef struct {
    const entry *e;
    int pos;
} cursor;

static const token *cur_tok(const cursor *c) { return c->pos < c->e->ntok ? &c->e->tok[c->pos] : NULL; }

static int is_p(const token *t, char p) { return t && t->type == T_PUNCT && t->punct == p; }

/* Consumes an optional count and '('; returns the count or -1 if none was given. */
static long list_open(cursor *c, const char *what)
{
    const entry *e = c->e;
    const token *t = cur_tok(c);
    long count = -1;
    char buf[128];
    if (t && t->type == T_NUMBER && is_p(c->pos + 1 < e->ntok ? &e->tok[c->pos + 1] : NULL, '(')) {
        double v = dem_strtod(t->text, NULL);
        if (!(v >= 0 && v <= 1e9 && v == floor(v)))
            fatal_at(e->file, t->line, e->key, "bad list length '%s' before '('", t->text);
        count = (long)v;
        c->pos++;
        t = cur_tok(c);
    }
    if (e->sub) fatal_at(e->file, e->line, e->key, "expected %s, got a sub-dictionary", what);
    if (e->ntok == 0) fatal_at(e->file, e->line, e->key, "expected %s, got nothing", what);
    if (!is_p(t, '('))
        fatal_at(e->file, t ? t->line : e->line, e->key, "expected %s, got '%s'", what, show_value(e, buf, sizeof buf));
    c->pos++;
    return count;
}

static void list_close(const cursor *c, long declared, int got, int line)
{
    if (declared >= 0 && declared != got)
        fatal_at(c->e->file, line, c->e->key, "list length %ld given before '(' but the list has %d elements",
                 declared, got);
}

/* After the outermost list: nothing may follow. */
static void value_end(const cursor *c)
{
    const token *t = cur_tok(c);
    char buf[128];
    if (t)
        fatal_at(c->e->file, t->line, c->e->key, "unexpected '%s' after the list", show_token(t, buf, sizeof buf));
}

/* Reads "[3](x y z)" at the cursor. */
static void read_vec3(cursor *c, double out[3])
{
    const entry *e = c->e;
    const char *what = "a vector (x y z)";
    int line = cur_tok(c) ? cur_tok(c)->line : e->line;
    long declared = list_open(c, what);
    int n = 0;
    for (;;) {
        const token *t = cur_tok(c);
        if (!t) fatal_at(e->file, line, e->key, "missing ')' in the vector");
        if (is_p(t, ')')) { c->pos++; break; }
        double v = tok_number(e, t, "a number in the vector (x y z)");
        if (n < 3) out[n] = v;
        n++;
        c->pos++;
    }
    list_close(c, declared, n, line);
    if (n != 3) fatal_at(e->file, line, e->key, "wrong vector length: expected 3 numbers (x y z), got %d", n);
}

void dem_dict_vector(const dem_dict *d, const char *key, double out[3])
{
    cursor c = { require(d, key), 0 };
    read_vec3(&c, out);
    value_end(&c);
}

void dem_dict_vector_opt(const dem_dict *d, const char *key, double out[3], const double def[3])
{
    entry *e = lookup(d, key);
    if (!e) {
        for (int i = 0; i < 3; i++) out[i] = def[i];
        return;
    }
    cursor c = { e, 0 };
    read_vec3(&c, out);
    value_end(&c);
}

int dem_dict_scalar_or_vector(const dem_dict *d, const char *key, double lo, double hi, double out[3])
{
    entry *e = require(d, key);
    if (!e->sub && e->ntok == 1) {
        out[0] = out[1] = out[2] = scalar_of(e, lo, hi);
        return 1;
    }
    cursor c = { e, 0 };
    if (!e->sub && e->ntok > 0 && e->tok[0].type == T_NUMBER && !is_p(e->ntok > 1 ? &e->tok[1] : NULL, '('))
        fatal_at(e->file, e->line, key, "expected a number or a vector (x y z)");
    read_vec3(&c, out);
    value_end(&c);
    for (int k = 0; k < 3; k++)
        if (!(out[k] >= lo && out[k] <= hi)) {
            char r[128];
            range_text(lo, hi, r, sizeof r);
            fatal_at(e->file, e->line, key, "component %d value %.15g is out of range: %s", k + 1, out[k], r);
        }
    return 3;
}

void dem_dict_bools3_opt(const dem_dict *d, const char *key, int out[3], int def)
{
    entry *e = lookup(d, key);
    if (!e) {
        for (int i = 0; i < 3; i++) out[i] = def;
        return;
    }
    cursor c = { e, 0 };
    const char *what = "three switches (e.g. (false false true))";
    long declared = list_open(&c, what);
    int n = 0;
    char buf[128];
    for (;;) {
        const token *t = cur_tok(&c);
        if (!t) fatal_at(e->file, e->line, key, "missing ')'");
        if (is_p(t, ')')) { c.pos++; break; }
        int v = switch_value(t);
        if (v < 0)
            fatal_at(e->file, t->line, key, "expected true/false (or yes/no, on/off), got '%s'",
                     show_token(t, buf, sizeof buf));
        if (n < 3) out[n] = v;
        n++;
        c.pos++;
    }
    list_close(&c, declared, n, e->line);
    if (n != 3) fatal_at(e->file, e->line, key, "wrong length: expected %s, got %d values", what, n);
    value_end(&c);
}

int dem_dict_scalar_list(const dem_dict *d, const char *key, double **out)
{
    cursor c = { require(d, key), 0 };
    const entry *e = c.e;
    long declared = list_open(&c, "a list of numbers (a b ...)");
    int n = 0, cap = 8;
    double *v = dem_malloc((size_t)cap * sizeof *v);
    for (;;) {
        const token *t = cur_tok(&c);
        if (!t) fatal_at(e->file, e->line, key, "missing ')'");
        if (is_p(t, ')')) { c.pos++; break; }
        if (n == cap) v = dem_realloc(v, (size_t)(cap *= 2) * sizeof *v);
        v[n++] = tok_number(e, t, "a number in the list");
        c.pos++;
    }
    list_close(&c, declared, n, e->line);
    value_end(&c);
    *out = v;
    return n;
}

int dem_dict_vector_list(const dem_dict *d, const char *key, double **out)
{
    cursor c = { require(d, key), 0 };
    const entry *e = c.e;
    long declared = list_open(&c, "a list of vectors ((x y z) ...)");
    int n = 0, cap = 4;
    double *v = dem_malloc((size_t)cap * 3 * sizeof *v);
    for (;;) {
        const token *t = cur_tok(&c);
        if (!t) fatal_at(e->file, e->line, key, "missing ')'");
        if (is_p(t, ')')) { c.pos++; break; }
        if (n == cap) v = dem_realloc(v, (size_t)(cap *= 2) * 3 * sizeof *v);
        read_vec3(&c, v + 3 * n);
        n++;
    }
    list_close(&c, declared, n, e->line);
    value_end(&c);
    *out = v;
    return n;
}

/* ------------------------------------------------------------------ words */

static const char *word_of(const entry *e)
{
    const token *t = single(e, "a word");
    char buf[128];
    if (t->type != T_WORD && t->type != T_STRING)
        fatal_at(e->file, e->line, e->key, "expected a word, got '%s'", show_token(t, buf, sizeof buf));
    return t->text;
}

const char *dem_dict_word(const dem_dict *d, const char *key) { return word_of(require(d, key)); }

int dem_dict_is_dict(const dem_dict *d, const char *key)
{
    const entry *e = lookup(d, key);
    return e && e->sub;
}

int dem_dict_is_word(const dem_dict *d, const char *key)
{
    const entry *e = lookup(d, key);
    return e && !e->sub && e->ntok == 1 && (e->tok[0].type == T_WORD || e->tok[0].type == T_STRING);
}

const char *dem_dict_word_opt(const dem_dict *d, const char *key, const char *def)
{
    entry *e = lookup(d, key);
    return e ? word_of(e) : def;
}

static int choice_of(const entry *e, const char *const options[])
{
    const char *w = word_of(e);
    int n = 0;
    for (; options[n]; n++)
        if (strcmp(options[n], w) == 0) return n;
    char list[512];
    size_t l = 0;
    list[0] = '\0';
    for (int i = 0; i < n && l < sizeof list; i++)
        l += (size_t)snprintf(list + l, sizeof list - l, "%s%s", i ? ", " : "", options[i]);
    const char *near = nearest(w, (const char *const *)options, n);
    if (near)
        fatal_at(e->file, e->line, e->key, "unknown option '%s' (did you mean '%s'?); valid options: %s", w, near, list);
    fatal_at(e->file, e->line, e->key, "unknown option '%s'; valid options: %s", w, list);
}

int dem_dict_choice(const dem_dict *d, const char *key, const char *const options[])
{
    return choice_of(require(d, key), options);
}

int dem_dict_choice_opt(const dem_dict *d, const char *key, const char *const options[], int def)
{
    entry *e = lookup(d, key);
    return e ? choice_of(e, options) : def;
}

/* ------------------------------------------------------------------ checks and errors */

void dem_dict_check_unused(const dem_dict *d)
{
    for (int i = 0; i < d->n; i++) {
        const entry *e = &d->ent[i];
        if (e->used) {
            if (e->sub) dem_dict_check_unused(e->sub);
            continue;
        }
        char scope[256];
        scope_name(d, scope, sizeof scope);
        const char *near = nearest(e->key, (const char *const *)d->asked, d->nasked);
        if (near)
            fatal_at(e->file, e->line, NULL, "unknown key '%s' in '%s' (did you mean '%s'?)", e->key, scope, near);
        fatal_at(e->file, e->line, NULL, "unknown key '%s' in '%s'", e->key, scope);
    }
}

void dem_dict_fatal(const dem_dict *d, const char *key, const char *fmt, ...)
{
    const entry *e = find(d, key);
    va_list ap;
    va_start(ap, fmt);
    vfatal_at(e ? e->file : d->file, e ? e->line : d->line, key, fmt, ap);
}

void dem_dict_fatal_here(const dem_dict *d, const char *fmt, ...)
{
    char scope[256], msg[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    scope_name(d, scope, sizeof scope);
    fatal_at(d->file, d->line, NULL, "in '%s': %s", scope, msg);
}
