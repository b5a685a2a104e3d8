/* The particle field table (dem/src/particles.h): every field the list names is allocated,
 * zeroed for a new particle, sorted, copied, packed for another rank, written to the HDF5
 * snapshot and read back on restart, bit for bit, as its flags say.
 *
 * The test walks the table, so a field added to PARTICLE_FIELDS (one line) is covered here
 * without touching this file. What it cannot take from the table it derives on its own: the
 * number of fields is counted from the struct's layout (every member after n and capacity is one
 * field's array), so a member added to the struct by hand, outside the list, fails the test.
 * Usage: test_fields [folder for temporary files] */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <hdf5.h>

#include "error.h"
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

enum { MAX_ELEMENT = 64 };

/* The element of field k for pattern number `seed`: distinct per field, seed and component,
 * with bit patterns that a float round trip or a conversion would lose. */
static void expected(int k, int seed, unsigned char out[MAX_ELEMENT])
{
    const dem_particle_field *f = &dem_particle_fields[k];
    for (int c = 0; c < f->components; c++) {
        if (f->scalar == PF_DOUBLE) {
            const double v = (k + 1) / 3.0 + sin(0.7 * seed + c) * 1e-3 + seed * 1e-7;
            memcpy(out + c * sizeof v, &v, sizeof v);
        } else if (f->scalar == PF_INT) {
            const int v = -(k + 1) * 100003 + 7 * seed + c;
            memcpy(out + c * sizeof v, &v, sizeof v);
        } else {
            const int64_t v = ((int64_t)(k + 1) << 40) + 1000 * (int64_t)seed + c;
            memcpy(out + c * sizeof v, &v, sizeof v);
        }
    }
}

static unsigned char *element(const dem_particles *p, int k, int i)
{
    return (unsigned char *)particle_field_data(p, &dem_particle_fields[k]) + (size_t)i * dem_particle_fields[k].element_size;
}

static void fill(dem_particles *p, int k, int i, int seed)
{
    unsigned char e[MAX_ELEMENT];
    expected(k, seed, e);
    memcpy(element(p, k, i), e, dem_particle_fields[k].element_size);
}

static void fill_all(dem_particles *p, int n)
{
    dem_particles_reserve(p, n);
    p->n = n;
    for (int k = 0; k < PARTICLE_FIELD_COUNT; k++)
        for (int i = 0; i < n; i++) fill(p, k, i, i);
}

static int holds(const dem_particles *p, int k, int i, int seed)
{
    unsigned char e[MAX_ELEMENT];
    expected(k, seed, e);
    return memcmp(element(p, k, i), e, dem_particle_fields[k].element_size) == 0;
}

static int is_zero(const dem_particles *p, int k, int i)
{
    const unsigned char *b = element(p, k, i);
    for (size_t q = 0; q < dem_particle_fields[k].element_size; q++)
        if (b[q]) return 0;
    return 1;
}

/* 1. The table itself: one entry per member, sizes that agree with the types, unique names,
 *    the dataset names of the first file format. */
static void check_table(void)
{
    const size_t arrays = (sizeof(dem_particles) - offsetof(dem_particles, x)) / sizeof(void *);
    CHECK(PARTICLE_FIELD_COUNT == (int)arrays, "the table has %d fields, the struct %zu arrays",
          PARTICLE_FIELD_COUNT, arrays);
    int seen[64] = {0};
    for (int k = 0; k < PARTICLE_FIELD_COUNT; k++) {
        const dem_particle_field *f = &dem_particle_fields[k];
        const size_t slot = (f->offset - offsetof(dem_particles, x)) / sizeof(void *);
        CHECK(f->offset >= offsetof(dem_particles, x) && slot < 64 && !seen[slot]++, "%s: offset %zu", f->member,
              f->offset);
        const size_t scalar = f->scalar == PF_DOUBLE ? sizeof(double) : f->scalar == PF_INT ? sizeof(int) : sizeof(int64_t);
        CHECK(f->components >= 1 && f->element_size == scalar * (size_t)f->components && f->element_size <= MAX_ELEMENT,
              "%s: %zu bytes for %d components", f->member, f->element_size, f->components);
        CHECK(f->unit && f->unit[0], "%s: no unit", f->member);
        for (int j = 0; j < k; j++) {
            CHECK(strcmp(f->member, dem_particle_fields[j].member) != 0, "member %s twice", f->member);
            CHECK(strcmp(f->dataset, dem_particle_fields[j].dataset) != 0, "dataset %s twice", f->dataset);
        }
    }
    /* what the tests' and tutorials' post-processing read from every snapshot */
    static const struct { int field; const char *dataset; unsigned flags; } kept[] = {
        {PF_FIELD_x, "position", PF_WRITE | PF_RESTART}, {PF_FIELD_v, "velocity", PF_WRITE | PF_RESTART},
        {PF_FIELD_omega, "omega", PF_WRITE | PF_RESTART}, {PF_FIELD_f, "force", PF_WRITE | PF_RESTART},
        {PF_FIELD_torque, "torque", PF_RESTART}, {PF_FIELD_radius, "radius", PF_WRITE | PF_RESTART},
        {PF_FIELD_id, "id", PF_WRITE | PF_RESTART}, {PF_FIELD_type, "type", PF_WRITE | PF_RESTART}};
    for (size_t q = 0; q < sizeof kept / sizeof kept[0]; q++) {
        const dem_particle_field *f = &dem_particle_fields[kept[q].field];
        CHECK(strcmp(f->dataset, kept[q].dataset) == 0 && (f->flags & kept[q].flags) == kept[q].flags,
              "%s: dataset '%s' flags %u, expected '%s' with %u", f->member, f->dataset, f->flags,
              kept[q].dataset, kept[q].flags);
    }
}

/* 2. Allocation: every field has room for the capacity, and growing keeps the contents. */
static void check_allocation(void)
{
    dem_particles p;
    dem_particles_init(&p);
    fill_all(&p, 1000);
    for (int k = 0; k < PARTICLE_FIELD_COUNT; k++)
        CHECK(particle_field_data(&p, &dem_particle_fields[k]) != NULL, "%s not allocated", dem_particle_fields[k].member);
    dem_particles_reserve(&p, 5000);
    CHECK(p.capacity == 5000, "capacity %d after reserve(5000)", p.capacity);
    for (int k = 0; k < PARTICLE_FIELD_COUNT; k++) {
        fill(&p, k, 4999, 4999);   /* the last element is writable (valgrind/ASan would see it) */
        int bad = 0;
        for (int i = 0; i < 1000; i++) bad += !holds(&p, k, i, i);
        CHECK(!bad, "%s: %d values lost when growing", dem_particle_fields[k].member, bad);
    }
    dem_particles_free(&p);
    for (int k = 0; k < PARTICLE_FIELD_COUNT; k++)
        CHECK(particle_field_data(&p, &dem_particle_fields[k]) == NULL, "%s not freed", dem_particle_fields[k].member);
}

/* 3. dem_particles_add: the fields it is given or derives are set, every other one is 0 (the
 *    memory is dirtied first). */
static void check_add(void)
{
    dem_particles p;
    dem_particles_init(&p);
    fill_all(&p, 8);
    p.n = 5;
    const double x[3] = {0.1, -0.2, 0.3}, v[3] = {1.5, 2.5, -3.5}, r = 1e-3, rho = 2500.0;
    const int i = dem_particles_add(&p, x, v, r, rho, 2, 77);
    CHECK(i == 5 && p.n == 6, "dem_particles_add gave index %d, n %d", i, p.n);
    const double m = rho * 4.0 / 3.0 * M_PI * r * r * r;
    CHECK(p.x[i][0] == x[0] && p.x[i][1] == x[1] && p.x[i][2] == x[2] && p.v[i][0] == v[0] &&
              p.v[i][1] == v[1] && p.v[i][2] == v[2] && p.radius[i] == r && p.type[i] == 2 && p.id[i] == 77 &&
              p.mass[i] == m && p.inv_mass[i] == 1.0 / m && p.inv_inertia[i] == 1.0 / (0.4 * m * r * r),
          "dem_particles_add: the given and derived values are not as given");
    static const int set_by_add[] = {PF_FIELD_x, PF_FIELD_v, PF_FIELD_radius, PF_FIELD_type, PF_FIELD_id,
                                     PF_FIELD_mass, PF_FIELD_inv_mass, PF_FIELD_inv_inertia};
    for (int k = 0; k < PARTICLE_FIELD_COUNT; k++) {
        int given = 0;
        for (size_t q = 0; q < sizeof set_by_add / sizeof set_by_add[0]; q++) given |= set_by_add[q] == k;
        if (!given) CHECK(is_zero(&p, k, i), "dem_particles_add: %s not zeroed", dem_particle_fields[k].member);
        CHECK(holds(&p, k, 4, 4), "dem_particles_add: %s of particle 4 changed", dem_particle_fields[k].member);
    }
    /* growing from full */
    dem_particles q;
    dem_particles_init(&q);
    for (int j = 0; j < 1500; j++) dem_particles_add(&q, x, v, r, rho, 0, j);
    CHECK(q.n == 1500 && q.id[0] == 0 && q.id[1499] == 1499, "1500 adds: n %d", q.n);
    dem_particles_free(&q);
    dem_particles_free(&p);
}

/* 4. Sorting: after dem_particles_permute, new index j holds every field of old index order[j]. */
static void check_permute(void)
{
    enum { N = 257 };
    dem_particles p;
    dem_particles_init(&p);
    fill_all(&p, N);
    int order[N];
    for (int j = 0; j < N; j++) order[j] = j;
    unsigned state = 12345;
    for (int j = N - 1; j > 0; j--) {   /* Fisher-Yates with a fixed LCG */
        state = 1103515245u * state + 12345u;
        const int r = (int)((state >> 8) % (unsigned)(j + 1));
        const int t = order[j];
        order[j] = order[r];
        order[r] = t;
    }
    dem_particles_permute(&p, order);
    for (int k = 0; k < PARTICLE_FIELD_COUNT; k++) {
        int bad = 0;
        for (int j = 0; j < N; j++) bad += !holds(&p, k, j, order[j]);
        CHECK(!bad, "permute: %s wrong at %d of %d particles", dem_particle_fields[k].member, bad, N);
    }
    dem_particles_free(&p);
}

/* 5. Copying one particle onto another, and packing one for another rank: the PF_MIGRATE
 *    fields travel, the others arrive as 0. */
static void check_copy_and_pack(void)
{
    dem_particles p, q;
    dem_particles_init(&p);
    dem_particles_init(&q);
    fill_all(&p, 20);
    dem_particles_copy(&p, 3, 10);
    for (int k = 0; k < PARTICLE_FIELD_COUNT; k++)
        CHECK(holds(&p, k, 10, 3) && holds(&p, k, 3, 3) && holds(&p, k, 11, 11), "copy: %s",
              dem_particle_fields[k].member);

    size_t migrating = 0;
    for (int k = 0; k < PARTICLE_FIELD_COUNT; k++)
        if (dem_particle_fields[k].flags & PF_MIGRATE) migrating += dem_particle_fields[k].element_size;
    CHECK(dem_particles_pack_size() == migrating, "pack size %zu, expected %zu", dem_particles_pack_size(), migrating);
    unsigned char *buf = malloc(dem_particles_pack_size() + 1);
    CHECK(dem_particles_pack(&p, 7, buf) == migrating, "dem_particles_pack wrote another size");
    fill_all(&q, 4);
    const int i = dem_particles_unpack(&q, buf);
    CHECK(i == 4 && q.n == 5, "unpack gave index %d, n %d", i, q.n);
    for (int k = 0; k < PARTICLE_FIELD_COUNT; k++) {
        if (dem_particle_fields[k].flags & PF_MIGRATE)
            CHECK(holds(&q, k, i, 7), "unpack: %s did not travel", dem_particle_fields[k].member);
        else
            CHECK(is_zero(&q, k, i), "unpack: %s (not migrating) is not 0", dem_particle_fields[k].member);
    }
    free(buf);
    dem_particles_free(&p);
    dem_particles_free(&q);
}

/* 6. The ghosts' roles (ghosts.h), field by field: a border gather of particles (2, 5) carries
 *    exactly the PF_BORDER fields onto 9, 10 with each one's shift added to its position and nothing else
 *    changed; the same for forward and reverse; take + scatter-add sums (doubles only, a repeated
 *    index twice); zeroing covers its range only. */
static void check_roles(void)
{
    dem_particles p;
    dem_particles_init(&p);
    fill_all(&p, 12);
    const unsigned roles[3] = {PF_BORDER, PF_FORWARD, PF_REVERSE};
    const char *names[3] = {"border", "forward", "reverse"};
    unsigned char *buf = malloc(2 * dem_particles_role_size(PF_BORDER | PF_FORWARD | PF_REVERSE) + 1);
    const dem_vec3 shift[2] = {{0.5, -2.0, 0.0}, {-1.5, 0.0, 3.0}};   /* each particle its own image */
    const int from[2] = {2, 5};
    for (int r = 0; r < 3; r++) {
        size_t bytes = 0;
        for (int k = 0; k < PARTICLE_FIELD_COUNT; k++)
            if (dem_particle_fields[k].flags & roles[r]) bytes += dem_particle_fields[k].element_size;
        CHECK(bytes > 0 && dem_particles_role_size(roles[r]) == bytes, "%s size %zu, expected %zu", names[r],
              dem_particles_role_size(roles[r]), bytes);
        CHECK(dem_particles_gather_roles(&p, roles[r], from, 2, shift, buf) == 2 * bytes, "%s gather wrote another size",
              names[r]);
        dem_particles_put_roles(&p, roles[r], 9, 2, buf);
        for (int m = 0; m < 2; m++)
            for (int k = 0; k < PARTICLE_FIELD_COUNT; k++) {
                const int to = 9 + m;
                if (!(dem_particle_fields[k].flags & roles[r])) {
                    CHECK(holds(&p, k, to, to), "%s: %s (not in the role) changed", names[r], dem_particle_fields[k].member);
                } else if (k == PF_FIELD_x) {
                    int ok = 1;
                    for (int q = 0; q < 3; q++) ok &= p.x[to][q] == p.x[from[m]][q] + shift[m][q];
                    CHECK(ok, "%s: the position is not the source's plus the shift", names[r]);
                } else {
                    CHECK(holds(&p, k, to, from[m]), "%s: %s did not travel", names[r], dem_particle_fields[k].member);
                }
            }
        for (int k = 0; k < PARTICLE_FIELD_COUNT; k++) { fill(&p, k, 9, 9); fill(&p, k, 10, 10); }
    }
    /* reverse: particles 4, 5 summed onto 9 and (twice) 9 again: 9 += f4 + f5 */
    double f9[3], t9[3];
    memcpy(f9, p.f[9], sizeof f9);
    memcpy(t9, p.torque[9], sizeof t9);
    const int onto[2] = {9, 9};
    dem_particles_take_roles(&p, PF_REVERSE, 4, 2, buf);
    dem_particles_scatter_add_roles(&p, PF_REVERSE, onto, 2, buf);
    int summed = 1;
    for (int q = 0; q < 3; q++)
        summed &= p.f[9][q] == (f9[q] + p.f[4][q]) + p.f[5][q] && p.torque[9][q] == (t9[q] + p.torque[4][q]) + p.torque[5][q];
    CHECK(summed, "reverse: force and torque not summed onto the target");
    for (int k = 0; k < PARTICLE_FIELD_COUNT; k++)
        if (!(dem_particle_fields[k].flags & PF_REVERSE))
            CHECK(holds(&p, k, 9, 9), "reverse add: %s changed", dem_particle_fields[k].member);
    for (int k = 0; k < PARTICLE_FIELD_COUNT; k++)
        if (dem_particle_fields[k].flags & PF_REVERSE)
            CHECK(dem_particle_fields[k].scalar == PF_DOUBLE, "reverse field %s is not a double", dem_particle_fields[k].member);
    /* the one-pass forms a swap to itself uses: the same as through the buffer, bit for bit */
    dem_particles q;
    dem_particles_init(&q);
    fill_all(&q, 12);
    dem_particles_gather_roles(&q, PF_BORDER, from, 2, shift, buf);
    dem_particles_put_roles(&q, PF_BORDER, 9, 2, buf);
    dem_particles_take_roles(&q, PF_REVERSE, 4, 2, buf);
    dem_particles_scatter_add_roles(&q, PF_REVERSE, onto, 2, buf);
    dem_particles r;
    dem_particles_init(&r);
    fill_all(&r, 12);
    dem_particles_copy_roles(&r, PF_BORDER, from, 2, shift, 9);
    dem_particles_fold_roles(&r, PF_REVERSE, 4, 2, onto);
    int same = 1;
    for (int k = 0; k < PARTICLE_FIELD_COUNT; k++)
        for (int i = 0; i < 12; i++) same &= memcmp(element(&q, k, i), element(&r, k, i), dem_particle_fields[k].element_size) == 0;
    CHECK(same, "copy_roles and fold_roles differ from gather + put and take + scatter_add");
    dem_particles_free(&q);
    dem_particles_free(&r);
    dem_particles_zero_roles(&p, PF_REVERSE, 5, 3);
    for (int i = 4; i <= 8; i++)
        for (int k = 0; k < PARTICLE_FIELD_COUNT; k++) {
            const int in_range = i >= 5 && i < 8 && (dem_particle_fields[k].flags & PF_REVERSE);
            CHECK(in_range ? is_zero(&p, k, i) : holds(&p, k, i, i), "zero_roles: particle %d's %s", i,
                  dem_particle_fields[k].member);
        }
    free(buf);
    dem_particles_free(&p);
}

/* Raw contents of dataset `name` of /snapshots/000000 in the field's memory type; NULL if absent.
 * *units gets its units attribute (malloc'd, or NULL). */
static void *read_raw(const char *h5, const dem_particle_field *f, int n, char **units, int *shape_ok)
{
    *units = NULL;
    *shape_ok = 0;
    hid_t file = H5Fopen(h5, H5F_ACC_RDONLY, H5P_DEFAULT);
    if (file < 0) return NULL;
    char path[256];
    snprintf(path, sizeof path, "/snapshots/000000/%s", f->dataset);
    void *data = NULL;
    if (H5Lexists(file, path, H5P_DEFAULT) > 0) {
        hid_t d = H5Dopen2(file, path, H5P_DEFAULT);
        hid_t space = H5Dget_space(d);
        hsize_t dims[2] = {0, 0};
        const int rank = H5Sget_simple_extent_ndims(space);
        H5Sget_simple_extent_dims(space, dims, NULL);
        *shape_ok = rank == (f->components > 1 ? 2 : 1) && dims[0] == (hsize_t)n &&
                    (f->components == 1 || dims[1] == (hsize_t)f->components);
        const hid_t mem = f->scalar == PF_DOUBLE ? H5T_NATIVE_DOUBLE : f->scalar == PF_INT ? H5T_NATIVE_INT : H5T_NATIVE_INT64;
        data = calloc((size_t)n, f->element_size);
        if (*shape_ok) H5Dread(d, mem, H5S_ALL, H5S_ALL, H5P_DEFAULT, data);
        if (H5Aexists(d, "units") > 0) {
            hid_t a = H5Aopen(d, "units", H5P_DEFAULT);
            hid_t t = H5Aget_type(a);
            const size_t len = H5Tget_size(t);
            *units = calloc(len + 1, 1);
            H5Aread(a, t, *units);
            H5Tclose(t);
            H5Aclose(a);
        }
        H5Sclose(space);
        H5Dclose(d);
    }
    H5Fclose(file);
    return data;
}

static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    const long len = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *s = malloc((size_t)len + 1);
    const size_t got = fread(s, 1, (size_t)len, f);
    s[got] = '\0';
    fclose(f);
    return s;
}

static int warnings_about_torque = 0;

static void count_warnings(enum dem_log_level level, const char *message)
{
    if (level == DEM_LOG_WARNING && strstr(message, "'torque'")) warnings_about_torque++;
}

/* 6. The snapshot holds exactly the PF_WRITE and PF_RESTART fields, bit for bit, each with its
 *    unit; the XDMF index lists the PF_WRITE ones; the restart reader gives back the
 *    PF_RESTART fields bit for bit and 0 for the others. A snapshot without a restart field (an
 *    older file) reads with that field 0, a warning, and no forces kept for the restart. */
static void check_snapshot(const char *dir)
{
    enum { N = 123 };
    char base[4200], h5[4300], xdmf[4300];
    snprintf(base, sizeof base, "%s/particles", dir);
    snprintf(h5, sizeof h5, "%s.h5", base);
    snprintf(xdmf, sizeof xdmf, "%s.xdmf", base);
    dem_particles p, r;
    dem_particles_init(&p);
    dem_particles_init(&r);
    fill_all(&p, N);
    dem_particle_writer *w = dem_io_open_writer(base, 0);
    dem_io_write_snapshot(w, &p, 0.25, 9);
    dem_io_close_writer(w);

    for (int k = 0; k < PARTICLE_FIELD_COUNT; k++) {
        const dem_particle_field *f = &dem_particle_fields[k];
        char *units;
        int shape_ok;
        void *raw = read_raw(h5, f, N, &units, &shape_ok);
        const int stored = (f->flags & (PF_WRITE | PF_RESTART)) != 0;
        CHECK((raw != NULL) == stored, "snapshot: dataset '%s' %s", f->dataset, stored ? "missing" : "written");
        if (raw) {
            CHECK(shape_ok, "snapshot: dataset '%s' has the wrong shape", f->dataset);
            CHECK(memcmp(raw, particle_field_data(&p, f), (size_t)N * f->element_size) == 0,
                  "snapshot: dataset '%s' differs from the particles' %s", f->dataset, f->member);
            CHECK(units && strcmp(units, f->unit) == 0, "snapshot: dataset '%s' units '%s', expected '%s'",
                  f->dataset, units ? units : "(none)", f->unit);
        }
        free(raw);
        free(units);
    }

    char *x = slurp(xdmf);
    CHECK(x != NULL, "no %s", xdmf);
    for (int k = 0; x && k < PARTICLE_FIELD_COUNT; k++) {
        const dem_particle_field *f = &dem_particle_fields[k];
        char item[256], attr[256];
        snprintf(item, sizeof item, "particles.h5:/snapshots/000000/%s<", f->dataset);
        snprintf(attr, sizeof attr, "<Attribute Name=\"%s\" AttributeType=\"%s\"", f->dataset,
                 f->components == 3 ? "Vector" : "Scalar");
        const int listed = strstr(x, item) != NULL;
        CHECK(listed == ((f->flags & PF_WRITE) != 0), "xdmf: '%s' %s", f->dataset, listed ? "listed" : "missing");
        if (listed && k != PF_FIELD_x) CHECK(strstr(x, attr) != NULL, "xdmf: no %s", attr);
    }
    CHECK(x && strstr(x, "<Geometry GeometryType=\"XYZ\">\n     <DataItem") != NULL, "xdmf: no geometry");
    free(x);

    fill_all(&r, 40);   /* garbage that the reader must overwrite or clear */
    dem_contact_state cs;
    double t;
    long step;
    CHECK(dem_io_read_snapshot_at(base, NAN, 0.0, &r, &t, &step, &cs) == 0 && r.n == N && t == 0.25 && step == 9,
          "restart read: n %d t %g step %ld", r.n, t, step);
    CHECK(cs.forces_read == 1, "restart read: the forces were not kept");
    for (int k = 0; r.n == N && k < PARTICLE_FIELD_COUNT; k++) {
        const dem_particle_field *f = &dem_particle_fields[k];
        int bad = 0;
        for (int i = 0; i < N; i++) bad += (f->flags & PF_RESTART) ? !holds(&r, k, i, i) : !is_zero(&r, k, i);
        CHECK(!bad, "restart read: %s wrong at %d of %d particles (%s)", f->member, bad, N,
              (f->flags & PF_RESTART) ? "expected as written" : "expected 0");
    }
    dem_contact_state_free(&cs);

    /* an older snapshot, without torque */
    hid_t file = H5Fopen(h5, H5F_ACC_RDWR, H5P_DEFAULT);
    H5Ldelete(file, "/snapshots/000000/torque", H5P_DEFAULT);
    H5Fclose(file);
    dem_logger old = dem_set_logger(count_warnings);
    fill_all(&r, 40);
    CHECK(dem_io_read_snapshot_at(base, NAN, 0.0, &r, &t, &step, &cs) == 0 && r.n == N, "older file: not read");
    dem_set_logger(old);
    CHECK(warnings_about_torque == 1, "older file: %d warnings about torque", warnings_about_torque);
    CHECK(cs.forces_read == 0, "older file: forces kept without torque");
    int bad = 0;
    for (int i = 0; r.n == N && i < N; i++) bad += !is_zero(&r, PF_FIELD_torque, i) || !holds(&r, PF_FIELD_f, i, i);
    CHECK(!bad, "older file: torque not 0 or force not read at %d particles", bad);
    dem_contact_state_free(&cs);

    dem_particles_free(&p);
    dem_particles_free(&r);
    if (!failures) {
        remove(h5);
        remove(xdmf);
    }
}

int main(int argc, char **argv)
{
    const char *parent = argc > 1 ? argv[1] : "/tmp";
    char dir[4096];
    snprintf(dir, sizeof dir, "%s/test_fields_XXXXXX", parent);
    if (!mkdtemp(dir)) {
        perror("mkdtemp");
        return 1;
    }
    check_table();
    check_allocation();
    check_add();
    check_permute();
    check_copy_and_pack();
    check_roles();
    check_snapshot(dir);
    printf("fields:");
    for (int k = 0; k < PARTICLE_FIELD_COUNT; k++)
        printf(" %s%s%s%s", dem_particle_fields[k].member, dem_particle_fields[k].flags & PF_WRITE ? " W" : "",
               dem_particle_fields[k].flags & PF_RESTART ? " R" : "", dem_particle_fields[k].flags & PF_MIGRATE ? " M" : "");
    printf("\n");
    if (failures) {
        fprintf(stderr, "test_fields: files kept in %s\n", dir);
        printf("test_fields: %d of %d checks FAILED\n", failures, checks);
        return 1;
    }
    rmdir(dir);
    printf("test_fields: %d checks passed for %d fields\n", checks, PARTICLE_FIELD_COUNT);
    return 0;
}
