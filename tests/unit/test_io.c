/* Round trip of particle snapshots through io_hdf5.c: write, read back bit for bit, killed
 * runs (unfinished snapshot groups, writer never closed), append numbering, truncation, the
 * XDMF index, and that unreadable files end in a clean fatal error rather than a crash.
 * Usage: test_io [folder for temporary files] */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <hdf5.h>

#include "io.h"
#include "particles.h"

static int checks = 0, failures = 0;

#define CHECK(cond, ...)                                                                       \
    do {                                                                                       \
        checks++;                                                                              \
        if (!(cond)) {                                                                         \
            failures++;                                                                        \
            fprintf(stderr, "FAIL %s:%d: ", __FILE__, __LINE__);                               \
            fprintf(stderr, __VA_ARGS__);                                                      \
            fputc('\n', stderr);                                                               \
        }                                                                                      \
    } while (0)

/* Known, non-round values for snapshot k (bit patterns that a float round trip would lose). */
static void fill(dem_particles *p, int n, int k)
{
    dem_particles_reserve(p, n);
    p->n = n;
    for (int i = 0; i < n; i++) {
        for (int d = 0; d < 3; d++) {
            p->x[i][d] = sin(0.1 * i + d + k) * 1e-2 + 1.0 / 3.0;
            p->v[i][d] = cos(0.37 * i - d + k) * 1e-3;
            p->omega[i][d] = exp(1e-3 * i) * (d - 1) * (k + 1) / 7.0;
            p->f[i][d] = -1e-9 * (i + 1) * (d + 2) / 3.0 + k;
            p->torque[i][d] = 1.0;
            p->f_ext[i][d] = 2.0;
        }
        p->radius[i] = 1e-3 * (1.0 + 0.1 * sin(i + k));
        p->mass[i] = 1.0;
        p->id[i] = ((int64_t)1 << 40) + 1000 * k + (int64_t)(n - i);
        p->type[i] = (i + k) % 3;
    }
}

/* Compare what the reader gave back with snapshot k of size n, field by field, exactly. */
static void compare(const dem_particles *r, int n, int k, const char *what)
{
    dem_particles e;
    dem_particles_init(&e);
    fill(&e, n, k);
    CHECK(r->n == n, "%s: n = %d, expected %d", what, r->n, n);
    if (r->n != n) {
        dem_particles_free(&e);
        return;
    }
    int bad_x = 0, bad_v = 0, bad_w = 0, bad_f = 0, bad_r = 0, bad_id = 0, bad_t = 0, bad_zero = 0;
    for (int i = 0; i < n; i++) {
        for (int d = 0; d < 3; d++) {
            bad_x += r->x[i][d] != e.x[i][d];
            bad_v += r->v[i][d] != e.v[i][d];
            bad_w += r->omega[i][d] != e.omega[i][d];
            bad_f += r->f[i][d] != e.f[i][d] || r->torque[i][d] != e.torque[i][d];
            bad_zero += r->f_ext[i][d] != 0.0;
        }
        bad_r += r->radius[i] != e.radius[i];
        bad_id += r->id[i] != e.id[i];
        bad_t += r->type[i] != e.type[i];
    }
    CHECK(!bad_x, "%s: %d position values differ", what, bad_x);
    CHECK(!bad_v, "%s: %d velocity values differ", what, bad_v);
    CHECK(!bad_w, "%s: %d omega values differ", what, bad_w);
    CHECK(!bad_f, "%s: %d force/torque values differ", what, bad_f);
    CHECK(!bad_r, "%s: %d radii differ", what, bad_r);
    CHECK(!bad_id, "%s: %d ids differ", what, bad_id);
    CHECK(!bad_t, "%s: %d types differ", what, bad_t);
    CHECK(!bad_zero, "%s: %d f_ext values not reset to zero", what, bad_zero);
    dem_particles_free(&e);
}

static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    long len = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *s = malloc((size_t)len + 1);
    size_t got = fread(s, 1, (size_t)len, f);
    s[got] = '\0';
    fclose(f);
    return s;
}

static int count_occurrences(const char *s, const char *pat)
{
    int c = 0;
    for (const char *q = s; (q = strstr(q, pat)); q += strlen(pat)) c++;
    return c;
}

/* 1 when /snapshots/<name> exists (with its step and complete attributes), 0 if not, -1 on error. */
static int snapshot_exists(const char *h5, const char *name, long *step_out, int *complete_out)
{
    hid_t f = H5Fopen(h5, H5F_ACC_RDONLY, H5P_DEFAULT);
    if (f < 0) return -1;
    char path[64];
    snprintf(path, sizeof path, "/snapshots/%s", name);
    int exists = H5Lexists(f, "snapshots", H5P_DEFAULT) > 0 && H5Lexists(f, path, H5P_DEFAULT) > 0;
    if (exists) {
        hid_t g = H5Gopen2(f, path, H5P_DEFAULT);
        long long step = -1;
        int complete = 0;
        if (H5Aexists(g, "step") > 0) {
            hid_t a = H5Aopen(g, "step", H5P_DEFAULT);
            H5Aread(a, H5T_NATIVE_LLONG, &step);
            H5Aclose(a);
        }
        if (H5Aexists(g, "complete") > 0) {
            hid_t a = H5Aopen(g, "complete", H5P_DEFAULT);
            H5Aread(a, H5T_NATIVE_INT, &complete);
            H5Aclose(a);
        }
        if (step_out) *step_out = (long)step;
        if (complete_out) *complete_out = complete;
        H5Gclose(g);
    }
    H5Fclose(f);
    return exists;
}

/* Add an unfinished snapshot group, as a run killed while writing would leave it. */
static void add_partial_snapshot(const char *h5, const char *name)
{
    hid_t f = H5Fopen(h5, H5F_ACC_RDWR, H5P_DEFAULT);
    char path[64];
    snprintf(path, sizeof path, "/snapshots/%s", name);
    hid_t g = H5Gcreate2(f, path, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    hsize_t dims[2] = {5, 3};
    hid_t s = H5Screate_simple(2, dims, NULL);
    hid_t d = H5Dcreate2(g, "position", H5T_NATIVE_DOUBLE, s, H5P_DEFAULT, H5P_DEFAULT,
                         H5P_DEFAULT);
    double buf[15] = {0};
    H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf);
    hid_t as = H5Screate(H5S_SCALAR);
    hid_t a = H5Acreate2(g, "time", H5T_NATIVE_DOUBLE, as, H5P_DEFAULT, H5P_DEFAULT);
    double t = 99.0;
    H5Awrite(a, H5T_NATIVE_DOUBLE, &t);
    H5Aclose(a);
    H5Sclose(as);
    H5Dclose(d);
    H5Sclose(s);
    H5Gclose(g);
    H5Fclose(f);
}

/* Run dem_io_read_last_snapshot in a child; returns its exit status, or -signal if it crashed. */
static int read_in_child(const char *base)
{
    fflush(NULL);
    pid_t pid = fork();
    if (pid == 0) {
        freopen("/dev/null", "w", stderr);
        dem_particles p;
        dem_particles_init(&p);
        double t;
        long s;
        dem_io_read_last_snapshot(base, &p, &t, &s);
        _exit(0);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    if (WIFSIGNALED(status)) return -WTERMSIG(status);
    return WEXITSTATUS(status);
}

int main(int argc, char **argv)
{
    const char *parent = argc > 1 ? argv[1] : "/tmp";
    char dir[4096];
    snprintf(dir, sizeof dir, "%s/test_io_XXXXXX", parent);
    if (!mkdtemp(dir)) {
        perror("mkdtemp");
        return 1;
    }
    char base[4200], h5[4300], xdmf[4300];
    snprintf(base, sizeof base, "%s/particles", dir);
    snprintf(h5, sizeof h5, "%s.h5", base);
    snprintf(xdmf, sizeof xdmf, "%s.xdmf", base);
    const int sizes[] = {300, 320, 350, 280, 310};
    const double times[] = {0.0, 1.25e-3, 2.5e-3, 3.75e-3, 5.0e-3};
    const long steps[] = {0, 100, 200, 300, 400};

    dem_particles p, r;
    dem_particles_init(&p);
    dem_particles_init(&r);
    double t;
    long s;

    /* 1. Three snapshots, read the last one back. */
    dem_particle_writer *w = dem_io_open_writer(base, 0);
    for (int k = 0; k < 3; k++) {
        fill(&p, sizes[k], k);
        dem_io_write_snapshot(w, &p, times[k], steps[k]);
    }
    dem_io_close_writer(w);
    /* Garbage in the destination to see that everything is overwritten. */
    fill(&r, 10, 7);
    CHECK(dem_io_read_last_snapshot(base, &r, &t, &s) == 0, "read after 3 snapshots failed");
    CHECK(t == times[2] && s == steps[2], "time/step %g/%ld, expected %g/%ld", t, s, times[2],
          steps[2]);
    compare(&r, sizes[2], 2, "snapshot 2");

    /* 2. The XDMF index: exists, relative paths, all datasets, three time steps. */
    char *x = slurp(xdmf);
    CHECK(x != NULL, "%s missing", xdmf);
    if (x) {
        CHECK(strstr(x, "CollectionType=\"Temporal\"") != NULL, "xdmf: no temporal collection");
        CHECK(count_occurrences(x, "TopologyType=\"Polyvertex\"") == 3,
              "xdmf: expected 3 Polyvertex grids");
        CHECK(count_occurrences(x, "<Time ") == 3, "xdmf: expected 3 times");
        const char *names[] = {"position", "velocity", "omega", "force", "radius", "id", "type"};
        for (int i = 0; i < 7; i++) {
            char pat[128];
            snprintf(pat, sizeof pat, ">particles.h5:/snapshots/000002/%s<", names[i]);
            CHECK(strstr(x, pat) != NULL, "xdmf: no %s", pat);
        }
        CHECK(strstr(x, "Name=\"velocity\" AttributeType=\"Vector\"") != NULL,
              "xdmf: velocity not a Vector");
        CHECK(strstr(x, "Name=\"radius\" AttributeType=\"Scalar\"") != NULL,
              "xdmf: radius not a Scalar");
        CHECK(strstr(x, dir) == NULL, "xdmf: contains the absolute folder");
        free(x);
    }

    /* 3. Killed run after a complete snapshot: the writer is never closed. */
    fflush(NULL);
    pid_t pid = fork();
    if (pid == 0) {
        dem_particle_writer *cw = dem_io_open_writer(base, 1);
        dem_particles q;
        dem_particles_init(&q);
        fill(&q, sizes[3], 3);
        dem_io_write_snapshot(cw, &q, times[3], steps[3]);
        _exit(0); /* no dem_io_close_writer, no HDF5 shutdown */
    }
    int status = 0;
    waitpid(pid, &status, 0);
    CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 0, "writer child failed");
    CHECK(dem_io_read_last_snapshot(base, &r, &t, &s) == 0, "read after killed writer failed");
    CHECK(s == steps[3] && t == times[3], "after killed writer: step %ld, expected %ld", s,
          steps[3]);
    compare(&r, sizes[3], 3, "snapshot 3 (writer killed)");

    /* 4. Killed while writing: a group without `complete` is ignored. */
    add_partial_snapshot(h5, "000004");
    CHECK(snapshot_exists(h5, "000004", NULL, NULL) == 1, "partial group not created");
    CHECK(dem_io_read_last_snapshot(base, &r, &t, &s) == 0, "read with partial group failed");
    CHECK(s == steps[3] && t == times[3], "with partial group: step %ld, expected %ld", s,
          steps[3]);
    compare(&r, sizes[3], 3, "snapshot 3 (partial 4 present)");

    /* 5. Append continues after the last complete snapshot, replacing the partial group. */
    w = dem_io_open_writer(base, 1);
    CHECK(snapshot_exists(h5, "000004", NULL, NULL) == 0, "partial group not removed on append");
    fill(&p, sizes[4], 4);
    dem_io_write_snapshot(w, &p, times[4], steps[4]);
    dem_io_close_writer(w);
    long st = -1;
    int complete = 0;
    CHECK(snapshot_exists(h5, "000004", &st, &complete) == 1 && complete == 1 && st == steps[4],
          "append: /snapshots/000004 step %ld complete %d", st, complete);
    CHECK(snapshot_exists(h5, "000005", NULL, NULL) == 0, "append: unexpected 000005");
    CHECK(dem_io_read_last_snapshot(base, &r, &t, &s) == 0, "read after append failed");
    CHECK(s == steps[4] && t == times[4], "after append: step %ld", s);
    compare(&r, sizes[4], 4, "snapshot 4 (appended)");
    x = slurp(xdmf);
    CHECK(x && count_occurrences(x, "TopologyType=\"Polyvertex\"") == 5,
          "xdmf after append: expected 5 grids");
    CHECK(x && strstr(x, "particles.h5:/snapshots/000004/position") != NULL,
          "xdmf after append: no 000004");
    free(x);

    /* 6. append=0 truncates; an empty particle set round-trips too. */
    w = dem_io_open_writer(base, 0);
    CHECK(dem_io_read_last_snapshot(base, &r, &t, &s) == -1, "new file should have no snapshot");
    p.n = 0;
    dem_io_write_snapshot(w, &p, 0.5, 7);
    dem_io_close_writer(w);
    CHECK(snapshot_exists(h5, "000000", NULL, NULL) == 1, "truncate: no 000000");
    CHECK(snapshot_exists(h5, "000001", NULL, NULL) == 0, "truncate: old 000001 still there");
    CHECK(dem_io_read_last_snapshot(base, &r, &t, &s) == 0 && r.n == 0 && t == 0.5 && s == 7,
          "empty snapshot: n %d t %g s %ld", r.n, t, s);

    /* 7. Append to a file that does not exist yet creates it. */
    char base2[4300];
    snprintf(base2, sizeof base2, "%s/fresh", dir);
    w = dem_io_open_writer(base2, 1);
    fill(&p, 5, 1);
    dem_io_write_snapshot(w, &p, 1.0, 1);
    dem_io_close_writer(w);
    CHECK(dem_io_read_last_snapshot(base2, &r, &t, &s) == 0 && s == 1, "append to missing file");
    compare(&r, 5, 1, "fresh file");

    /* 8. Missing or corrupt files: clean fatal exit (status 1), never a crash. */
    char base3[4300], bad[4400];
    snprintf(base3, sizeof base3, "%s/missing", dir);
    int rc = read_in_child(base3);
    CHECK(rc == 1, "missing file: child status %d, expected 1", rc);
    snprintf(base3, sizeof base3, "%s/corrupt", dir);
    snprintf(bad, sizeof bad, "%s.h5", base3);
    FILE *f = fopen(bad, "w");
    fputs("this is not an HDF5 file\n", f);
    fclose(f);
    rc = read_in_child(base3);
    CHECK(rc == 1, "corrupt file: child status %d, expected 1", rc);

    /* Clean up the temporary folder on success. */
    if (!failures) {
        const char *files[] = {"particles.h5", "particles.xdmf", "fresh.h5", "fresh.xdmf",
                               "corrupt.h5"};
        for (int i = 0; i < 5; i++) {
            char path[4400];
            snprintf(path, sizeof path, "%s/%s", dir, files[i]);
            remove(path);
        }
        rmdir(dir);
    } else {
        fprintf(stderr, "test_io: files kept in %s\n", dir);
    }
    dem_particles_free(&p);
    dem_particles_free(&r);
    if (failures) {
        printf("test_io: %d of %d checks FAILED\n", failures, checks);
        return 1;
    }
    printf("test_io: %d checks passed\n", checks);
    return 0;
}
