/* File insertion: particles read from a text file, in one of two formats (told apart by the
 * first thing that is not a comment: `FoamFile`, `(`, or a count followed by `(` mean the
 * second):
 *
 *   columns      one particle per line, whitespace-separated:  x y z [d [vx vy vz [material]]]
 *                ([m], [m], [m/s], a material name); 3, 4, 7 or 8 columns, each line on its
 *                own; `#` and `//` start a comment to the end of the line; blank lines skipped.
 *   vectorField  OpenFOAM's positions list as in DPMFoam's kinematicCloudPositions: an optional
 *                FoamFile { } header, an optional count, then `(` , one `(x y z)` per position,
 *                `)`; `//` and block comments. ASCII only.
 *
 * With `body <template>` each line (or position) is a multisphere body's centre of mass, 3
 * columns, turned to a random orientation drawn with `seed`, at the entry's velocity.
 * A column a line does not give is taken from the insertion entry: diameter from `diameter`
 * (drawn from its distribution with `seed`), velocity from `velocity` (default 0), material
 * from `material`. Every error names the file and line ("positions.dat:17: ..."). A gzipped
 * file (OpenFOAM reads X.gz) is refused with "gunzip it first": zlib is not linked here. */
#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "dict.h"
#include "error.h"
#include "insert.h"
#include "number.h"
#include "system.h"

typedef struct reader {
    const char *path;
    const char *buf;
    size_t len, pos;
    int line;
    const dem_system *s;
    const dem_insertion *ins;
    dem_insert_batch *b;
    dem_rng r;
} reader;

static void file_fatal(const reader *rd, int line, const char *fmt, ...)
    __attribute__((format(printf, 3, 4), noreturn));
static void file_fatal(const reader *rd, int line, const char *fmt, ...)
{
    char where[4200], msg[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (line > 0) snprintf(where, sizeof where, "%s:%d", rd->path, line);
    else snprintf(where, sizeof where, "%s", rd->path);
    dem_fatal_at(where, "%s", msg);
}

static char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        char gz[4200];
        struct stat st;
        snprintf(gz, sizeof gz, "%s.gz", path);
        if (stat(gz, &st) == 0)
            dem_fatal_at(path, "cannot open the positions file, but '%s' exists: gunzip it first "
                         "(gunzip -k '%s'; OpenFOAM reads .gz files, this reader does not)", gz, gz);
        dem_fatal_at(path, "cannot open the positions file (the key 'file' is read relative to the case's "
                     "constant/ directory unless it starts with '/')");
    }
    size_t cap = 1 << 16, n = 0;
    char *buf = dem_malloc(cap + 1);
    for (;;) {
        const size_t got = fread(buf + n, 1, cap - n, f);
        n += got;
        if (n < cap) break;
        cap *= 2;
        buf = dem_realloc(buf, cap + 1);
    }
    const int bad = ferror(f);
    fclose(f);
    if (bad) dem_fatal_at(path, "read error");
    buf[n] = '\0';
    *len = n;
    return buf;
}

/* ------------------------------------------------------------------ shared pieces */

static double number_or_fatal(const reader *rd, int line, const char *text, size_t n, const char *what)
{
    char tok[128];
    snprintf(tok, sizeof tok, "%.*s", (int)(n < sizeof tok ? n : sizeof tok - 1), text);
    char *end;
    const double v = dem_strtod(tok, &end);
    if (end == tok || *end != '\0' || n >= sizeof tok) file_fatal(rd, line, "%s: '%s' is not a number", what, tok);
    if (!isfinite(v)) file_fatal(rd, line, "%s: '%s' is not a finite number", what, tok);
    return v;
}

static void push(reader *rd, int line, const double x[3], const double *v, double d, int material)
{
    const dem_insertion *ins = rd->ins;
    if (ins->body) {   /* a body's centre of mass (OpenFOAM's positions): its template and the entry give the rest */
        dem_insert_batch_push(rd->b, x, ins->velocity, 0.0, ins->material, line);
        return;
    }
    if (isnan(d)) {
        if (!ins->has_diameter)
            file_fatal(rd, line, "no diameter column, and insertion '%s' has no 'diameter' entry: give one of "
                       "the two", ins->name);
        d = dem_insertion_draw_diameter(ins, &rd->r);   /* the entry's diameters are the parcels' already */
    } else {
        d *= rd->s->coarse_graining;   /* the file gives the primary particles' diameter */
    }
    if (material < 0) {
        if (ins->material < 0)
            file_fatal(rd, line, "no material column, and insertion '%s' has no 'material' entry: give one of "
                       "the two", ins->name);
        material = ins->material;
    }
    dem_insert_batch_push(rd->b, x, v ? v : ins->velocity, d, material, line);
}

/* ------------------------------------------------------------------ columns */

static int is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

/* A body's line: x y z [vx vy vz [qw qx qy qz [wx wy wz]]]: its centre of mass [m], velocity
 * [m/s], orientation (a quaternion, normalised: the template's frame to space) and angular
 * velocity [rad/s, in space]; what a line leaves out is the entry's. */
static void read_body_line(reader *rd, int line, const char *const *col, const size_t *clen, int ncol)
{
    if (ncol != 3 && ncol != 6 && ncol != 10 && ncol != 13)
        file_fatal(rd, line, "insertion '%s' places multisphere bodies: 3, 6, 10 or 13 columns (x y z [vx vy vz "
                   "[qw qx qy qz [wx wy wz]]]), got %d", rd->ins->name, ncol);
    static const char *const names[] = {"column 1 (x)", "column 2 (y)", "column 3 (z)", "column 4 (vx)",
                                         "column 5 (vy)", "column 6 (vz)", "column 7 (qw)", "column 8 (qx)",
                                         "column 9 (qy)", "column 10 (qz)", "column 11 (wx)", "column 12 (wy)",
                                         "column 13 (wz)"};
    double val[13];
    for (int k = 0; k < ncol; k++) val[k] = number_or_fatal(rd, line, col[k], clen[k], names[k]);
    const long i = dem_insert_batch_push(rd->b, val, ncol >= 6 ? val + 3 : rd->ins->velocity, 0.0, rd->ins->material, line);
    if (ncol >= 10) {
        double *q = val + 6;
        const double len = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        if (!(len > 0.0) || !isfinite(len))
            file_fatal(rd, line, "columns 7-10: the quaternion (%g %g %g %g) has no length", q[0], q[1], q[2], q[3]);
        for (int k = 0; k < 4; k++) q[k] /= len;
        dem_insert_batch_set_rotation(rd->b, i, q, ncol == 13 ? val + 10 : NULL);
    }
}

static void read_columns(reader *rd)
{
    const char *buf = rd->buf;
    size_t pos = 0;
    int line = 0;
    while (pos < rd->len) {
        line++;
        size_t end = pos;
        while (end < rd->len && buf[end] != '\n') end++;
        /* the line without its comment */
        size_t stop = pos;
        while (stop < end && buf[stop] != '#' && !(buf[stop] == '/' && stop + 1 < end && buf[stop + 1] == '/')) stop++;
        const char *col[13];
        size_t clen[13];
        int ncol = 0;
        for (size_t q = pos; q < stop;) {
            while (q < stop && is_blank(buf[q])) q++;
            if (q >= stop) break;
            const size_t start = q;
            while (q < stop && !is_blank(buf[q])) q++;
            if (ncol < 13) { col[ncol] = buf + start; clen[ncol] = q - start; }
            ncol++;
        }
        pos = end + 1;
        if (ncol == 0) continue;
        if (rd->ins->body) {
            read_body_line(rd, line, col, clen, ncol);
            continue;
        }
        if (ncol != 3 && ncol != 4 && ncol != 7 && ncol != 8)
            file_fatal(rd, line, "expected 3, 4, 7 or 8 columns (x y z [d [vx vy vz [material]]]), got %d", ncol);
        static const char *const names[] = {"column 1 (x)", "column 2 (y)", "column 3 (z)", "column 4 (diameter)",
                                             "column 5 (vx)", "column 6 (vy)", "column 7 (vz)"};
        double val[7];
        for (int k = 0; k < ncol && k < 7; k++) val[k] = number_or_fatal(rd, line, col[k], clen[k], names[k]);
        double d = NAN;
        if (ncol >= 4) {
            d = val[3];
            if (!(d > 0.0 && d <= 10.0))
                file_fatal(rd, line, "column 4: the diameter %g m is out of range: allowed (0, 10] m", d);
        }
        int material = -1;
        if (ncol == 8) {
            char name[DEM_NAME_LEN + 1];
            snprintf(name, sizeof name, "%.*s", (int)(clen[7] < sizeof name ? clen[7] : sizeof name - 1), col[7]);
            material = dem_materials_find(&rd->s->materials, name);
            if (material < 0 || clen[7] >= sizeof name) {
                char list[512];
                size_t l = 0;
                list[0] = '\0';
                for (int t = 0; t < rd->s->materials.ntypes && l < sizeof list; t++)
                    l += (size_t)snprintf(list + l, sizeof list - l, "%s%s", t ? ", " : "", rd->s->materials.mat[t].name);
                file_fatal(rd, line, "column 8: material '%.*s' is not among the materials (%s)", (int)clen[7], col[7], list);
            }
            if (rd->s->materials.mat[material].rigid)
                file_fatal(rd, line, "column 8: material '%s' is rigid: only walls may use it", name);
        }
        push(rd, line, val, ncol >= 7 ? val + 4 : NULL, d, material);
    }
}

/* ------------------------------------------------------------------ vectorField */

enum { TK_EOF, TK_PUNCT, TK_WORD };
typedef struct token { int type; char punct; const char *text; size_t n; int line; } token;

/* Skip blanks, newlines (counted) and // and block comments. */
static void skip_space(reader *rd)
{
    const char *b = rd->buf;
    while (rd->pos < rd->len) {
        const char c = b[rd->pos];
        if (c == '\n') { rd->line++; rd->pos++; }
        else if (isspace((unsigned char)c)) rd->pos++;
        else if (c == '/' && b[rd->pos + 1] == '/') {
            while (rd->pos < rd->len && b[rd->pos] != '\n') rd->pos++;
        } else if (c == '/' && b[rd->pos + 1] == '*') {
            const int start = rd->line;
            rd->pos += 2;
            while (rd->pos < rd->len && !(b[rd->pos] == '*' && b[rd->pos + 1] == '/')) {
                if (b[rd->pos] == '\n') rd->line++;
                rd->pos++;
            }
            if (rd->pos >= rd->len) file_fatal(rd, start, "unterminated comment: '/*' has no closing '*/'");
            rd->pos += 2;
        } else break;
    }
}

static int is_punct(char c) { return c == '(' || c == ')' || c == '{' || c == '}' || c == ';'; }

static token next_token(reader *rd)
{
    skip_space(rd);
    token t = {TK_EOF, 0, NULL, 0, rd->line};
    if (rd->pos >= rd->len) return t;
    const char *b = rd->buf;
    if (is_punct(b[rd->pos])) {
        t.type = TK_PUNCT;
        t.punct = b[rd->pos++];
        return t;
    }
    const size_t start = rd->pos;
    while (rd->pos < rd->len && !isspace((unsigned char)b[rd->pos]) && !is_punct(b[rd->pos]) &&
           !(b[rd->pos] == '/' && (b[rd->pos + 1] == '/' || b[rd->pos + 1] == '*')))
        rd->pos++;
    t.type = TK_WORD;
    t.text = b + start;
    t.n = rd->pos - start;
    return t;
}

static int is_word(const token *t, const char *w) { return t->type == TK_WORD && t->n == strlen(w) && memcmp(t->text, w, t->n) == 0; }
static int is_p(const token *t, char p) { return t->type == TK_PUNCT && t->punct == p; }

static const char *show(const token *t, char *buf, size_t n)
{
    if (t->type == TK_EOF) snprintf(buf, n, "end of file");
    else if (t->type == TK_PUNCT) snprintf(buf, n, "%c", t->punct);
    else snprintf(buf, n, "%.*s", (int)(t->n < 100 ? t->n : 100), t->text);
    return buf;
}

static void read_vector_field(reader *rd)
{
    char sb[128];
    rd->pos = 0;
    rd->line = 1;
    token t = next_token(rd);
    if (is_word(&t, "FoamFile")) {   /* skip the header; refuse binary */
        const int hline = t.line;
        t = next_token(rd);
        if (!is_p(&t, '{')) file_fatal(rd, t.line, "expected '{' after FoamFile, got '%s'", show(&t, sb, sizeof sb));
        for (int depth = 1; depth > 0;) {
            t = next_token(rd);
            if (t.type == TK_EOF) file_fatal(rd, hline, "the FoamFile header is not closed: '}' missing");
            if (is_p(&t, '{')) depth++;
            else if (is_p(&t, '}')) depth--;
            else if (is_word(&t, "format")) {
                t = next_token(rd);
                if (is_word(&t, "binary"))
                    file_fatal(rd, t.line, "a binary vectorField: write it in ascii first (foamFormatConvert, "
                               "or writeFormat ascii)");
            }
        }
        t = next_token(rd);
    }
    long declared = -1;
    int count_line = 0;
    if (t.type == TK_WORD) {
        const double c = number_or_fatal(rd, t.line, t.text, t.n, "the list's count");
        if (!(c >= 0 && c == floor(c) && c <= 1e9))
            file_fatal(rd, t.line, "the list's count '%s' is not a count", show(&t, sb, sizeof sb));
        declared = (long)c;
        count_line = t.line;
        t = next_token(rd);
        if (is_p(&t, '{'))
            file_fatal(rd, t.line, "a uniform list N{(x y z)} puts every particle at one place: give the positions");
    }
    if (!is_p(&t, '('))
        file_fatal(rd, t.line, "expected '(' to open the list of positions, got '%s'", show(&t, sb, sizeof sb));
    const int open_line = t.line;
    long got = 0;
    for (;;) {
        t = next_token(rd);
        if (is_p(&t, ')')) break;
        if (t.type == TK_EOF) file_fatal(rd, open_line, "the list of positions opened here is not closed: ')' missing");
        if (!is_p(&t, '('))
            file_fatal(rd, t.line, "expected a position (x y z) or ')' closing the list, got '%s'", show(&t, sb, sizeof sb));
        const int line = t.line;
        double x[3];
        for (int k = 0; k < 3; k++) {
            t = next_token(rd);
            if (t.type != TK_WORD)
                file_fatal(rd, t.line, "a position is (x y z): expected a number, got '%s'", show(&t, sb, sizeof sb));
            x[k] = number_or_fatal(rd, t.line, t.text, t.n, "a position is (x y z)");
        }
        t = next_token(rd);
        if (!is_p(&t, ')'))
            file_fatal(rd, t.line, "a position is (x y z): expected ')' after three numbers, got '%s'", show(&t, sb, sizeof sb));
        push(rd, line, x, NULL, NAN, -1);
        got++;
    }
    if (declared >= 0 && declared != got)
        file_fatal(rd, count_line, "the count says %ld positions, the list has %ld", declared, got);
    t = next_token(rd);
    if (t.type != TK_EOF) file_fatal(rd, t.line, "unexpected '%s' after the list of positions", show(&t, sb, sizeof sb));
}

/* vectorField when the first non-comment item is FoamFile, '(' or a count followed by '('. */
static int looks_like_vector_field(reader *rd)
{
    rd->pos = 0;
    rd->line = 1;
    for (;;) {   /* '#' lines are comments in the column format */
        skip_space(rd);
        if (rd->pos < rd->len && rd->buf[rd->pos] == '#') {
            while (rd->pos < rd->len && rd->buf[rd->pos] != '\n') rd->pos++;
        } else break;
    }
    token t = next_token(rd);
    if (is_word(&t, "FoamFile") || is_p(&t, '(')) return 1;
    if (t.type != TK_WORD) return 0;
    for (size_t k = 0; k < t.n; k++)
        if (!isdigit((unsigned char)t.text[k])) return 0;
    t = next_token(rd);
    return is_p(&t, '(');
}

void dem_insert_file_read(const dem_system *s, const dem_insertion *ins, dem_insert_batch *b)
{
    reader rd;
    memset(&rd, 0, sizeof rd);
    rd.path = ins->file;
    rd.s = s;
    rd.ins = ins;
    rd.b = b;
    rng_seed(&rd.r, ins->seed);
    const size_t plen = strlen(ins->file);
    char *buf = slurp(ins->file, &rd.len);
    rd.buf = buf;
    if ((rd.len >= 2 && (unsigned char)buf[0] == 0x1f && (unsigned char)buf[1] == 0x8b) ||
        (plen > 3 && strcmp(ins->file + plen - 3, ".gz") == 0))
        file_fatal(&rd, 0, "a gzipped file: gunzip it first (gunzip -k '%s'; zlib is not linked into this reader)",
                   ins->file);
    if (memchr(buf, '\0', rd.len)) file_fatal(&rd, 0, "not a text file (it holds NUL bytes)");
    if (looks_like_vector_field(&rd)) read_vector_field(&rd);
    else read_columns(&rd);
    free(buf);
    if (b->n == 0) file_fatal(&rd, 0, "no positions in the file");
}

long dem_insertion_file(dem_system *s, const dem_insertion *ins, const dem_dict *entry)
{
    dem_insert_batch b;
    dem_insert_batch_init(&b);
    dem_insert_file_read(s, ins, &b);
    const long placed = ins->body ? dem_insertion_add_body_batch(s, ins, &b, ins->file)
                                  : dem_insertion_add_batch(s, ins, &b, ins->file, entry, "file");
    dem_insert_batch_free(&b);
    return placed;
}
