/* The error and log hooks (dem/src/error.h), with real library errors:
 *  - a logger set by the program gets the libraries' info and warning lines (reading a case:
 *    the insertion; the time-step check: its report and the override warning), and nothing
 *    reaches stdout or stderr; a message longer than the formatting buffer arrives whole;
 *  - a fatal handler set by the program gets a bad demProperties' error with "file:line" apart
 *    from the message "key '...': ...", and a coupling error (no place: where is NULL); here it
 *    jumps back, and nothing was printed;
 *  - the setters return the hook set before, NULL puts the default back;
 *  - the defaults (in a child process): info on stdout, "WARNING: " lines on stderr, and
 *    "<where>: error: <message>" on stderr with exit status 1, also after a handler that
 *    breaks its contract and returns. */
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "case.h"
#include "case_files.h"
#include "catch_fatal.h"
#include "error.h"
#include "harness.h"
#include "mesh.h"
#include "timestep.h"

/* ------------------------------------------------------------------ a logger that keeps lines */

enum { MAX_LINES = 16 };
static int nlines;
static enum dem_log_level line_level[MAX_LINES];
static char *line_text[MAX_LINES];

static void keep_line(enum dem_log_level level, const char *message)
{
    if (nlines == MAX_LINES) return;
    line_level[nlines] = level;
    line_text[nlines] = strdup(message);
    nlines++;
}

/* The first kept line of that level containing text, or NULL. */
static const char *kept(enum dem_log_level level, const char *text)
{
    for (int k = 0; k < nlines; k++)
        if (line_level[k] == level && strstr(line_text[k], text)) return line_text[k];
    return NULL;
}

/* ------------------------------------------------------------------ what the libraries print */

static int saved_out = -1, saved_err = -1;

/* stdout and stderr into <path> until output_size() */
static void divert_output(const char *path)
{
    fflush(stdout);
    fflush(stderr);
    saved_out = dup(1);
    saved_err = dup(2);
    const int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0 || saved_out < 0 || saved_err < 0) { perror(path); exit(2); }
    dup2(fd, 1);
    dup2(fd, 2);
    close(fd);
}

/* Back to the terminal; the bytes printed meanwhile. */
static long output_size(const char *path)
{
    fflush(stdout);
    fflush(stderr);
    dup2(saved_out, 1);
    dup2(saved_err, 2);
    close(saved_out);
    close(saved_err);
    struct stat st;
    return stat(path, &st) == 0 ? (long)st.st_size : -1;
}

static char *read_file(const char *path)
{
    static char text[4096];
    text[0] = '\0';
    FILE *f = fopen(path, "r");
    if (!f) return text;
    const size_t n = fread(text, 1, sizeof text - 1, f);
    text[n] = '\0';
    fclose(f);
    return text;
}

/* ------------------------------------------------------------------ the checks */

/* 20 spheres; timeStep 1e-4 s is above the largest safe step, allowed by the override */
static const char good_case[] =
    "timeStep 1e-4; timeStepOverride true; endTime 0.01; writeInterval 0; gravity (0 0 -9.81);\n"
    "domain { min (-0.01 -0.01 0); max (0.01 0.01 0.04); }\n"
    "materials { glass { youngsModulus 5e6; poissonsRatio 0.45; density 2500; } }\n"
    "contactModels { normal hertz; tangential history; }\n"
    "interactions { default { restitution 0.5; friction 0.5; } }\n"
    "insertion { fill { region { type box; min (-0.01 -0.01 0); max (0.01 0.01 0.04); }\n"
    "    number 20; material glass; diameter { distribution constant; value 2e-3; } } }\n";

static void logger_gets_the_lines(const char *dir)
{
    char out[4300];
    snprintf(out, sizeof out, "%s/printed", dir);
    write_text(dir, "constant/demProperties", good_case);
    const dem_logger previous = dem_set_logger(keep_line);
    divert_output(out);
    dem_system s;
    dem_system_init(&s);
    dem_run_settings rs;
    dem_case_read(dir, &s, &rs, 0);
    dem_timestep_check(&s, dem_case_default_max_velocity(&s), rs.timestep_override, rs.timestep_source);
    static char long_name[3001];
    memset(long_name, 'x', 3000);
    dem_info("%s", long_name);
    const long printed = output_size(out);
    dem_set_logger(previous);
    dem_system_free(&s);

    for (int k = 0; k < nlines; k++) printf("      logged (%s): %.100s\n", line_level[k] ? "warning" : "info", line_text[k]);
    check_true("logger: the insertion's info line", kept(DEM_LOG_INFO, "insertion 'fill': 20 particles") != NULL);
    check_true("logger: the time step report as info", kept(DEM_LOG_INFO, "time step 0.0001 s:") != NULL);
    check_true("logger: the override as a warning, without the default's prefix",
               kept(DEM_LOG_WARNING, "exceeds the largest safe step") && !kept(DEM_LOG_WARNING, "WARNING"));
    const char *lng = kept(DEM_LOG_INFO, "xxxx");
    check_true("logger: a 3000-character message arrives whole", lng && strlen(lng) == 3000);
    printf("      printed to stdout and stderr meanwhile: %ld bytes\n", printed);
    check_true("nothing printed to stdout or stderr by the libraries", printed == 0);
}

static void handler_gets_the_error(const char *dir)
{
    char out[4300];
    snprintf(out, sizeof out, "%s/printed", dir);
    /* line 3 of the file: density -2500 */
    char bad[sizeof good_case + 1];
    snprintf(bad, sizeof bad, "%s", good_case);
    char *d = strstr(bad, "density 2500");
    memmove(d + 9, d + 8, strlen(d + 8) + 1);
    d[8] = '-';
    write_text(dir, "constant/demProperties", bad);

    const dem_fatal_handler previous = dem_set_fatal_handler(keep_and_jump);
    volatile int stopped = 0;   /* set after the jump back */
    divert_output(out);
    if (setjmp(caught_jump) == 0) {
        dem_system s;
        dem_system_init(&s);
        dem_run_settings rs;
        dem_case_read(dir, &s, &rs, 0);
    } else {
        stopped = 1;
    }
    long printed = output_size(out);
    printf("      where: '%s', message: '%s'\n", caught_where, caught_message);
    char where[4300];
    snprintf(where, sizeof where, "%s/constant/demProperties:3", dir);
    check_true("bad density: the handler was called", stopped);
    check_true("bad density: where = <case>/constant/demProperties:3", strcmp(caught_where, where) == 0);
    check_true("bad density: message \"key 'density': ...-2500...\"",
               strncmp(caught_message, "key 'density': ", 15) == 0 && strstr(caught_message, "-2500"));
    check_true("bad density: nothing printed", printed == 0);

    /* a coupling error has no place in a file */
    stopped = 0;
    divert_output(out);
    if (setjmp(caught_jump) == 0) {
        cpl_mesh m;
        const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
        cpl_mesh_box(&m, lo, hi, 0, 2, 2);
    } else {
        stopped = 1;
    }
    printed = output_size(out);
    printf("      where: '%s', message: '%s'\n", caught_where, caught_message);
    check_true("coupling error: handler called, no place, the message",
               stopped && caught_where[0] == '\0' && strcmp(caught_message, "cpl_mesh_box: bad cell counts 0 x 2 x 2") == 0);
    check_true("coupling error: nothing printed", printed == 0);
    dem_set_fatal_handler(previous);
}

static void setters_return_the_previous(void)
{
    const dem_fatal_handler default_handler = dem_set_fatal_handler(keep_and_jump);
    const dem_fatal_handler mine = dem_set_fatal_handler(NULL);
    const dem_fatal_handler back = dem_set_fatal_handler(NULL);
    const dem_logger default_logger = dem_set_logger(keep_line);
    const dem_logger mine_l = dem_set_logger(NULL);
    const dem_logger back_l = dem_set_logger(NULL);
    check_true("setters: return the previous hook; NULL restores the default",
               default_handler && mine == keep_and_jump && back == default_handler && default_logger &&
               mine_l == keep_line && back_l == default_logger);
}

static void returns_anyway(const char *where, const char *message)
{
    fprintf(stderr, "handler returned: %s\n", message);
}

static void defaults_print_and_exit(const char *dir)
{
    char out[4300], err[4300];
    snprintf(out, sizeof out, "%s/stdout", dir);
    snprintf(err, sizeof err, "%s/stderr", dir);
    fflush(stdout);
    const pid_t pid = fork();
    if (pid == 0) {
        if (!freopen(out, "w", stdout) || !freopen(err, "w", stderr)) _exit(3);
        dem_info("an info line");
        dem_warning("a warning");
        dem_set_fatal_handler(returns_anyway);
        dem_fatal_at("here.c:7", "stop %d", 3);
        _exit(0);   /* not reached */
    }
    int status = 0;
    waitpid(pid, &status, 0);
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    char sout[4096];
    snprintf(sout, sizeof sout, "%s", read_file(out));
    const char *serr = read_file(err);
    printf("      exit status %d, stdout '%s', stderr '%s'\n", code, sout, serr);
    check_true("defaults: exit status 1", code == 1);
    check_true("defaults: info on stdout", strcmp(sout, "an info line\n") == 0);
    check_true("defaults: warning, the returning handler, then the error on stderr",
               strcmp(serr, "WARNING: a warning\nhandler returned: stop 3\nhere.c:7: error: stop 3\n") == 0);
}

int main(void)
{
    char dir[256];
    scratch_case("test_hooks", dir, sizeof dir);
    logger_gets_the_lines(dir);
    handler_gets_the_error(dir);
    setters_return_the_previous();
    defaults_print_and_exit(dir);
    remove_case(dir);
    return finish("test_hooks");
}
