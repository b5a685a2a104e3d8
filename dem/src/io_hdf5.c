/* Particle output and restart in HDF5 with an XDMF index; layout described in io.h.
 *
 * Serially the file is opened with the default (sec2) driver; the parallel HDF5 build works
 * without MPI_Init then (checked with HDF5 1.10.8 / Open MPI on Debian 12). A parallel run's
 * writer opens it through MPI-IO (io.h's hook, in make_fapl) and every rank writes its rows of
 * each dataset (place(): its offset in the whole), collectively; no MPI call is made here.
 *
 * Every HDF5 call is checked; HDF5's own error printing is switched off and a failure ends the
 * program through dem_fatal with the file name and the innermost HDF5 message. */
#include <errno.h>
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <hdf5.h>

#include "comm.h"
#include "error.h"
#include "io.h"
#include "reduce.h"

typedef struct snapshot_info {
    long index;        /* group /snapshots/<index> */
    double time;
    long step;
    int64_t n;
} snapshot_info;

struct dem_particle_writer {
    hid_t file;
    char *h5_path;     /* <base>.h5 as given, for messages and opening */
    char *h5_name;     /* file name of the .h5 without directories, used inside the .xdmf */
    char *xdmf_path;   /* <base>.xdmf */
    long next_index;   /* number of the next snapshot group */
    snapshot_info *snaps; /* complete snapshots, in index order */
    int nsnaps, capsnaps;
};

/* ---------------------------------------------------------------- error handling */

typedef struct h5_err_detail {
    char api[64];      /* outermost function (the API call) */
    char inner[384];   /* innermost description */
} h5_err_detail;

static herr_t walk_errors(unsigned n, const H5E_error2_t *e, void *data)
{
    h5_err_detail *d = data;
    if (n == 0 && e->func_name) snprintf(d->api, sizeof d->api, "%s", e->func_name);
    if (e->desc) snprintf(d->inner, sizeof d->inner, "%s", e->desc);
    return 0;
}

static void h5_quiet(void)
{
    static int done = 0;
    if (!done) {
        H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
        done = 1;
    }
}

__attribute__((noreturn)) static void h5_fail(const char *path, const char *what)
{
    h5_err_detail d = {"", ""};
    H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, walk_errors, &d);
    H5Eclear2(H5E_DEFAULT);
    if (d.api[0] || d.inner[0])
        dem_fatal("HDF5 file '%s': %s (%s%s%s)", path, what, d.api, d.api[0] ? ": " : "",
                  d.inner);
    dem_fatal("HDF5 file '%s': %s", path, what);
}

/* Check the result of an HDF5 call (hid_t or herr_t); negative means failure. */
static hid_t chk(hid_t r, const char *path, const char *what)
{
    if (r < 0) h5_fail(path, what);
    return r;
}

/* ---------------------------------------------------------------- small helpers */

static char *str_dup(const char *s)
{
    size_t len = strlen(s) + 1;
    char *c = dem_malloc(len);
    memcpy(c, s, len);
    return c;
}

static char *str_cat(const char *a, const char *b)
{
    size_t la = strlen(a), lb = strlen(b);
    char *c = dem_malloc(la + lb + 1);
    memcpy(c, a, la);
    memcpy(c + la, b, lb + 1);
    return c;
}

static const char *file_name_part(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

static dem_io_parallel_hook parallel_hook;

void dem_io_set_parallel_hook(const dem_io_parallel_hook *hook)
{
    if (hook) parallel_hook = *hook;
    else memset(&parallel_hook, 0, sizeof parallel_hook);
}

/* Whether this is a parallel run's shared file: written by every rank at once. */
static int shared_file(void) { return parallel_hook.use_mpio && dem_comm_size() > 1; }

/* The transfer list of a dataset write: collective in a shared file. Closed with H5Pclose. */
static hid_t make_dxpl(const char *path)
{
    hid_t dxpl = chk(H5Pcreate(H5P_DATASET_XFER), path, "cannot create a transfer list");
    if (shared_file() && parallel_hook.collective(dxpl, parallel_hook.context) < 0)
        h5_fail(path, "cannot make the transfers collective");
    return dxpl;
}

/* This rank's rows of a dataset that holds every rank's: its offset and the total. */
static void place(int64_t rows, int64_t *offset, int64_t *total)
{
    const int size = dem_comm_size(), rank = dem_comm_rank();
    if (!shared_file()) {
        *offset = 0;
        *total = rows;
        return;
    }
    int64_t *counts = dem_malloc((size_t)size * sizeof *counts);
    dem_reduce_gather_int64s(&rows, 1, counts);
    *offset = *total = 0;
    for (int r = 0; r < size; r++) {
        if (r < rank) *offset += counts[r];
        *total += counts[r];
    }
    free(counts);
}

/* The one place where the file access property list is made: MPI-IO for a parallel run's
 * writer (shared), the process's own file otherwise (a reader: every rank reads alone). */
static hid_t make_fapl(const char *path, int shared)
{
    hid_t fapl = chk(H5Pcreate(H5P_FILE_ACCESS), path, "cannot create file access list");
    if (shared && parallel_hook.use_mpio(fapl, parallel_hook.context) < 0) h5_fail(path, "cannot select MPI-IO");
#if H5_VERSION_GE(1, 10, 7)
    /* Keep file locking, but do not fail on file systems without lock support. */
    chk(H5Pset_file_locking(fapl, 1, 1), path, "cannot set file locking");
#endif
    return fapl;
}

static void snapshot_name(char *buf, size_t size, long index)
{
    snprintf(buf, size, "%06ld", index);
}

/* Parse a group name made of decimal digits only; -1 otherwise. */
static long parse_index(const char *name)
{
    if (!name[0]) return -1;
    long v = 0;
    for (const char *c = name; *c; c++) {
        if (*c < '0' || *c > '9' || v > 100000000L) return -1;
        v = 10 * v + (*c - '0');
    }
    return v;
}

static void write_string_attr(hid_t obj, const char *name, const char *value, const char *path)
{
    hid_t type = chk(H5Tcopy(H5T_C_S1), path, "cannot copy string type");
    chk(H5Tset_size(type, strlen(value) + 1), path, "cannot size string type");
    chk(H5Tset_strpad(type, H5T_STR_NULLTERM), path, "cannot set string padding");
    hid_t space = chk(H5Screate(H5S_SCALAR), path, "cannot create scalar dataspace");
    hid_t attr = chk(H5Acreate2(obj, name, type, space, H5P_DEFAULT, H5P_DEFAULT), path,
                     "cannot create string attribute");
    chk(H5Awrite(attr, type, value), path, "cannot write string attribute");
    H5Aclose(attr);
    H5Sclose(space);
    H5Tclose(type);
}

static void write_scalar_attr(hid_t obj, const char *name, hid_t file_type, hid_t mem_type,
                              const void *value, const char *path)
{
    hid_t space = chk(H5Screate(H5S_SCALAR), path, "cannot create scalar dataspace");
    hid_t attr = chk(H5Acreate2(obj, name, file_type, space, H5P_DEFAULT, H5P_DEFAULT), path,
                     "cannot create attribute");
    chk(H5Awrite(attr, mem_type, value), path, "cannot write attribute");
    H5Aclose(attr);
    H5Sclose(space);
}

/* Read a scalar attribute; returns 0 when it does not exist. */
static int read_scalar_attr(hid_t obj, const char *name, hid_t mem_type, void *value,
                            const char *path)
{
    htri_t has = chk(H5Aexists(obj, name), path, "cannot query attribute");
    if (!has) return 0;
    hid_t attr = chk(H5Aopen(obj, name, H5P_DEFAULT), path, "cannot open attribute");
    hid_t space = chk(H5Aget_space(attr), path, "cannot get attribute dataspace");
    hssize_t count = H5Sget_simple_extent_npoints(space);
    if (count != 1) {
        H5Sclose(space);
        H5Aclose(attr);
        dem_fatal("HDF5 file '%s': attribute '%s' is not a scalar", path, name);
    }
    chk(H5Aread(attr, mem_type, value), path, "cannot read attribute");
    H5Sclose(space);
    H5Aclose(attr);
    return 1;
}

/* A string attribute, malloc'd; NULL when it does not exist. */
static char *read_string_attr(hid_t obj, const char *name, const char *path)
{
    if (!chk(H5Aexists(obj, name), path, "cannot query attribute")) return NULL;
    hid_t attr = chk(H5Aopen(obj, name, H5P_DEFAULT), path, "cannot open attribute");
    hid_t type = chk(H5Aget_type(attr), path, "cannot get attribute type");
    if (H5Tget_class(type) != H5T_STRING || H5Tis_variable_str(type) > 0)
        dem_fatal("HDF5 file '%s': attribute '%s' is not a fixed-length string", path, name);
    const size_t size = H5Tget_size(type);
    char *value = dem_calloc(size + 1, 1);
    chk(H5Aread(attr, type, value), path, "cannot read string attribute");
    H5Tclose(type);
    H5Aclose(attr);
    return value;
}

/* ---------------------------------------------------------------- snapshot listing */

typedef struct scan_state {
    const char *path;
    snapshot_info *complete; /* complete snapshots found */
    int ncomplete, capcomplete;
    long *incomplete;        /* indices of groups without `complete` */
    int nincomplete, capincomplete;
} scan_state;

static herr_t scan_link(hid_t group, const char *name, const H5L_info_t *info, void *data)
{
    scan_state *s = data;
    long index = parse_index(name);
    if (index < 0) return 0;   /* not ours; leave it alone */
    if (info->type != H5L_TYPE_HARD) return 0;
    hid_t g = chk(H5Oopen(group, name, H5P_DEFAULT), s->path, "cannot open snapshot group");
    if (H5Iget_type(g) != H5I_GROUP) {
        H5Oclose(g);
        return 0;
    }
    int complete = 0;
    int ok = read_scalar_attr(g, "complete", H5T_NATIVE_INT, &complete, s->path) && complete;
    snapshot_info si = {index, 0.0, 0, 0};
    if (ok) {
        long long step = 0;
        ok = read_scalar_attr(g, "time", H5T_NATIVE_DOUBLE, &si.time, s->path) &&
             read_scalar_attr(g, "step", H5T_NATIVE_LLONG, &step, s->path) &&
             read_scalar_attr(g, "n", H5T_NATIVE_INT64, &si.n, s->path);
        si.step = (long)step;
    }
    H5Oclose(g);
    if (ok) {
        if (s->ncomplete == s->capcomplete) {
            s->capcomplete = s->capcomplete ? 2 * s->capcomplete : 16;
            s->complete = dem_realloc(s->complete, (size_t)s->capcomplete * sizeof *s->complete);
        }
        s->complete[s->ncomplete++] = si;
    } else {
        if (s->nincomplete == s->capincomplete) {
            s->capincomplete = s->capincomplete ? 2 * s->capincomplete : 4;
            s->incomplete = dem_realloc(s->incomplete,
                                        (size_t)s->capincomplete * sizeof *s->incomplete);
        }
        s->incomplete[s->nincomplete++] = index;
    }
    return 0;
}

static int cmp_snap(const void *a, const void *b)
{
    long ia = ((const snapshot_info *)a)->index, ib = ((const snapshot_info *)b)->index;
    return (ia > ib) - (ia < ib);
}

/* List the snapshot groups of an open file (no /snapshots group: nothing found). */
static void scan_snapshots(hid_t file, const char *path, scan_state *s)
{
    memset(s, 0, sizeof *s);
    s->path = path;
    htri_t has = chk(H5Lexists(file, "snapshots", H5P_DEFAULT), path, "cannot query /snapshots");
    if (!has) return;
    hid_t g = chk(H5Gopen2(file, "snapshots", H5P_DEFAULT), path, "cannot open /snapshots");
    hsize_t idx = 0;
    chk(H5Literate(g, H5_INDEX_NAME, H5_ITER_INC, &idx, scan_link, s), path,
        "cannot list /snapshots");
    H5Gclose(g);
    if (s->ncomplete > 1) qsort(s->complete, (size_t)s->ncomplete, sizeof *s->complete, cmp_snap);
}

/* ---------------------------------------------------------------- XDMF */

static void xml_escape(FILE *f, const char *s)
{
    for (; *s; s++) {
        switch (*s) {
        case '&': fputs("&amp;", f); break;
        case '<': fputs("&lt;", f); break;
        case '>': fputs("&gt;", f); break;
        case '"': fputs("&quot;", f); break;
        case '\'': fputs("&apos;", f); break;
        default: fputc(*s, f);
        }
    }
}

static void xdmf_item(FILE *f, const dem_particle_writer *w, const char *group, const dem_particle_field *pf,
                      int64_t n)
{
    static const char *const number_type[] = {[PF_DOUBLE] = "Float", [PF_INT] = "Int", [PF_INT64] = "Int"};
    fprintf(f, "     <DataItem Format=\"HDF\" NumberType=\"%s\" Precision=\"%zu\" "
               "Dimensions=\"%" PRId64,
            number_type[pf->scalar], pf->element_size / (size_t)pf->components, n);
    if (pf->components > 1) fprintf(f, " %d", pf->components);
    fputs("\">", f);
    xml_escape(f, w->h5_name);
    fprintf(f, ":/snapshots/%s/%s</DataItem>\n", group, pf->dataset);
}

static void xdmf_attribute(FILE *f, const dem_particle_writer *w, const char *group,
                           const dem_particle_field *pf, int64_t n)
{
    fprintf(f, "    <Attribute Name=\"%s\" AttributeType=\"%s\" Center=\"Node\">\n", pf->dataset,
            pf->components == 3 ? "Vector" : "Scalar");
    xdmf_item(f, w, group, pf, n);
    fputs("    </Attribute>\n", f);
}

/* Rewrite <base>.xdmf through a temporary file and rename, so it is never half written.
 * Snapshots with no particles are left out (zero-sized data items upset readers). */
static void write_xdmf(const dem_particle_writer *w)
{
    if (shared_file() && dem_comm_rank() != 0) return;   /* one index, by rank 0 */
    char *tmp = str_cat(w->xdmf_path, ".tmp");
    FILE *f = fopen(tmp, "w");
    if (!f) dem_fatal("cannot write '%s': %s", tmp, strerror(errno));
    fputs("<?xml version=\"1.0\" ?>\n"
          "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
          "<Xdmf Version=\"2.0\">\n"
          " <Domain>\n"
          "  <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n",
          f);
    for (int k = 0; k < w->nsnaps; k++) {
        const snapshot_info *s = &w->snaps[k];
        if (s->n <= 0) continue;
        char group[32];
        snapshot_name(group, sizeof group, s->index);
        fprintf(f, "   <Grid Name=\"%s\" GridType=\"Uniform\">\n", group);
        fprintf(f, "    <Time Value=\"%.17g\"/>\n", s->time);
        fprintf(f, "    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"%" PRId64
                   "\" NodesPerElement=\"1\"/>\n",
                s->n);
        fputs("    <Geometry GeometryType=\"XYZ\">\n", f);
        xdmf_item(f, w, group, &dem_particle_fields[PF_FIELD_x], s->n);
        fputs("    </Geometry>\n", f);
        for (int k = 0; k < PARTICLE_FIELD_COUNT; k++)
            if (k != PF_FIELD_x && (dem_particle_fields[k].flags & PF_WRITE))
                xdmf_attribute(f, w, group, &dem_particle_fields[k], s->n);
        fputs("   </Grid>\n", f);
    }
    fputs("  </Grid>\n </Domain>\n</Xdmf>\n", f);
    if (ferror(f) | fclose(f)) dem_fatal("cannot write '%s': %s", tmp, strerror(errno));
    if (rename(tmp, w->xdmf_path) != 0)
        dem_fatal("cannot rename '%s' to '%s': %s", tmp, w->xdmf_path, strerror(errno));
    free(tmp);
}

/* ---------------------------------------------------------------- writer */

static hid_t create_file(const char *path)
{
    hid_t fapl = make_fapl(path, shared_file());
    hid_t file = chk(H5Fcreate(path, H5F_ACC_TRUNC, H5P_DEFAULT, fapl), path,
                     "cannot create file");
    H5Pclose(fapl);
    return file;
}

dem_particle_writer *dem_io_open_writer(const char *base, int append)
{
    h5_quiet();
    dem_particle_writer *w = dem_calloc(1, sizeof *w);
    w->h5_path = str_cat(base, ".h5");
    w->xdmf_path = str_cat(base, ".xdmf");
    w->h5_name = str_dup(file_name_part(w->h5_path));
    w->file = -1;

    FILE *probe = append ? fopen(w->h5_path, "rb") : NULL;
    if (probe) {
        fclose(probe);
        hid_t fapl = make_fapl(w->h5_path, shared_file());
        w->file = chk(H5Fopen(w->h5_path, H5F_ACC_RDWR, fapl), w->h5_path,
                      "cannot open file to append snapshots");
        H5Pclose(fapl);
        scan_state s;
        scan_snapshots(w->file, w->h5_path, &s);
        w->snaps = s.complete;
        w->nsnaps = w->capsnaps = s.ncomplete;
        w->next_index = s.ncomplete ? s.complete[s.ncomplete - 1].index + 1 : 0;
        /* Groups left without `complete` by a killed run are removed (their space is not
         * reclaimed by HDF5, but they would otherwise block or confuse the numbering). */
        if (s.nincomplete) {
            hid_t g = chk(H5Gopen2(w->file, "snapshots", H5P_DEFAULT), w->h5_path,
                          "cannot open /snapshots");
            for (int k = 0; k < s.nincomplete; k++) {
                char name[32];
                snapshot_name(name, sizeof name, s.incomplete[k]);
                htri_t has = chk(H5Lexists(g, name, H5P_DEFAULT), w->h5_path,
                                 "cannot query snapshot group");
                if (has)
                    chk(H5Ldelete(g, name, H5P_DEFAULT), w->h5_path,
                        "cannot delete incomplete snapshot group");
            }
            H5Gclose(g);
        }
        free(s.incomplete);
        htri_t has = chk(H5Lexists(w->file, "snapshots", H5P_DEFAULT), w->h5_path,
                         "cannot query /snapshots");
        if (!has)
            H5Gclose(chk(H5Gcreate2(w->file, "snapshots", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                         w->h5_path, "cannot create /snapshots"));
        chk(H5Fflush(w->file, H5F_SCOPE_LOCAL), w->h5_path, "cannot flush file");
    } else {
        w->file = create_file(w->h5_path);
        H5Gclose(chk(H5Gcreate2(w->file, "snapshots", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                     w->h5_path, "cannot create /snapshots"));
        chk(H5Fflush(w->file, H5F_SCOPE_LOCAL), w->h5_path, "cannot flush file");
    }
    write_xdmf(w);
    return w;
}

/* HDF5 types of a field's scalar: in the file (fixed, little endian) and in memory. */
static hid_t file_type_of(const dem_particle_field *pf)
{
    return pf->scalar == PF_DOUBLE ? H5T_IEEE_F64LE : pf->scalar == PF_INT ? H5T_STD_I32LE : H5T_STD_I64LE;
}

static hid_t memory_type_of(const dem_particle_field *pf)
{
    return pf->scalar == PF_DOUBLE ? H5T_NATIVE_DOUBLE : pf->scalar == PF_INT ? H5T_NATIVE_INT : H5T_NATIVE_INT64;
}

/* rows x cols of data (this rank's) into rows offset .. offset + rows - 1 of dset's total; every
 * rank calls it in a shared file, also one without rows. */
static void write_rows(hid_t dset, hid_t mem_type, const void *data, int64_t rows, int64_t cols, int64_t offset,
                       int64_t total, int rank2, const char *path)
{
    const hsize_t start[2] = {(hsize_t)offset, 0}, count[2] = {(hsize_t)rows, (hsize_t)cols};
    const hsize_t whole[2] = {(hsize_t)total, (hsize_t)cols};
    hid_t file_space = chk(H5Screate_simple(rank2, whole, NULL), path, "cannot create dataspace");
    hid_t mem_space = chk(H5Screate_simple(rank2, count, NULL), path, "cannot create dataspace");
    if (rows > 0 && cols > 0) {
        chk(H5Sselect_hyperslab(file_space, H5S_SELECT_SET, start, NULL, count, NULL), path, "cannot select rows");
    } else {
        chk(H5Sselect_none(file_space), path, "cannot select rows");
        chk(H5Sselect_none(mem_space), path, "cannot select rows");
    }
    hid_t dxpl = make_dxpl(path);
    if (total > 0 && cols > 0)   /* every rank knows the total: all call, or none */
        chk(H5Dwrite(dset, mem_type, mem_space, file_space, dxpl, data), path, "cannot write dataset");
    H5Pclose(dxpl);
    H5Sclose(mem_space);
    H5Sclose(file_space);
}

/* One field of the n particles: n values, or n x components; its unit as the `units` attribute.
 * In a shared file the dataset holds every rank's, this rank's at `offset` of `total`. */
static void write_field(hid_t group, const dem_particle_field *pf, const dem_particles *p, int64_t n, int64_t offset,
                        int64_t total, const char *path)
{
    const int rank2 = pf->components > 1 ? 2 : 1;
    hsize_t dims[2] = {(hsize_t)total, (hsize_t)pf->components};
    hid_t space = chk(H5Screate_simple(rank2, dims, NULL), path, "cannot create dataspace");
    hid_t dset = chk(H5Dcreate2(group, pf->dataset, file_type_of(pf), space, H5P_DEFAULT, H5P_DEFAULT,
                                H5P_DEFAULT),
                     path, "cannot create dataset");
    write_rows(dset, memory_type_of(pf), particle_field_data(p, pf), n, pf->components, offset, total, rank2, path);
    write_string_attr(dset, "units", pf->unit, path);
    H5Dclose(dset);
    H5Sclose(space);
}

static void body_state_free(dem_body_state *b)
{
    free(b->id); free(b->template_of); free(b->x); free(b->v); free(b->q); free(b->Lb); free(b->omega);
    free(b->f); free(b->torque); free(b->e_rot);
    memset(b, 0, sizeof *b);
}

static void lifecycle_state_free(dem_lifecycle_state *l)
{
    free(l->outlets); free(l->streams); free(l->stream_reals); free(l->outlet_names); free(l->stream_names);
    memset(l, 0, sizeof *l);
}

void dem_contact_state_free(dem_contact_state *cs)
{
    free(cs->keys);
    free(cs->history);
    body_state_free(&cs->bodies);
    lifecycle_state_free(&cs->lifecycle);
    memset(cs, 0, sizeof *cs);
}

/* A 2-D dataset of doubles or int64 with `cols` columns, compressed (deflate, level 1): much of
 * a contact's history is zeros. `distributed`: each rank holds some of the rows (the contacts);
 * otherwise every rank holds them all alike and rank 0 writes them. A shared file's datasets are
 * not compressed (a filter would make every write collective per chunk). */
static void write_matrix(hid_t group, const char *name, hid_t file_type, hid_t mem_type,
                         const void *data, int64_t rows, int64_t cols, int distributed, const char *path)
{
    int64_t offset = 0, total = rows;
    if (distributed) place(rows, &offset, &total);
    else if (shared_file() && dem_comm_rank() != 0) rows = 0;
    hsize_t dims[2] = {(hsize_t)total, (hsize_t)cols};
    hid_t space = chk(H5Screate_simple(2, dims, NULL), path, "cannot create dataspace");
    hid_t dcpl = chk(H5Pcreate(H5P_DATASET_CREATE), path, "cannot create a dataset property list");
    if (!shared_file() && total > 0 && cols > 0 && H5Zfilter_avail(H5Z_FILTER_DEFLATE) > 0) {
        hsize_t chunk[2] = {(hsize_t)(total < 65536 ? total : 65536), (hsize_t)cols};
        chk(H5Pset_chunk(dcpl, 2, chunk), path, "cannot set the chunk size");
        chk(H5Pset_shuffle(dcpl), path, "cannot set the shuffle filter");
        chk(H5Pset_deflate(dcpl, 1), path, "cannot set the deflate filter");
    }
    hid_t dset = chk(H5Dcreate2(group, name, file_type, space, H5P_DEFAULT, dcpl, H5P_DEFAULT),
                     path, "cannot create dataset");
    H5Pclose(dcpl);
    write_rows(dset, mem_type, data, rows, cols, offset, total, 2, path);
    H5Dclose(dset);
    H5Sclose(space);
}

static void write_contacts(hid_t g, const dem_contact_state *cs, const char *path)
{
    hid_t c = chk(H5Gcreate2(g, "contacts", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), path,
                  "cannot create contacts group");
    write_scalar_attr(c, "history_size", H5T_STD_I32LE, H5T_NATIVE_INT, &cs->history_size, path);
    write_scalar_attr(c, "nwalls", H5T_STD_I32LE, H5T_NATIVE_INT, &cs->nwalls, path);
    write_matrix(c, "keys", H5T_STD_I64LE, H5T_NATIVE_INT64, cs->keys, cs->count, 2, 1, path);
    write_matrix(c, "history", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, cs->history, cs->count, cs->history_size, 1, path);
    H5Gclose(c);
}

/* The columns of a body state: name, units, components, where. */
#define BODY_COLUMNS(X, b)                                                  \
    X("position", "m", 3, (b)->x)                                           \
    X("velocity", "m/s", 3, (b)->v)                                         \
    X("orientation", "1", 4, (b)->q)                                        \
    X("angular_momentum_body", "kg m^2/s", 3, (b)->Lb)                      \
    X("omega", "rad/s", 3, (b)->omega)                                      \
    X("force", "N", 3, (b)->f)                                              \
    X("torque", "N m", 3, (b)->torque)                                      \
    X("rotational_energy", "J", 1, (b)->e_rot)

static void write_bodies(hid_t g, const dem_body_state *b, const char *path)
{
    hid_t c = chk(H5Gcreate2(g, "bodies", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), path, "cannot create bodies group");
    write_matrix(c, "id", H5T_STD_I64LE, H5T_NATIVE_INT64, b->id, b->count, 1, 1, path);
    write_matrix(c, "template", H5T_STD_I64LE, H5T_NATIVE_INT64, b->template_of, b->count, 1, 1, path);
#define WRITE_BODY_COLUMN(name, units, cols, data)                                                  \
    {                                                                                               \
        write_matrix(c, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, data, b->count, cols, 1, path);    \
        hid_t d = chk(H5Dopen2(c, name, H5P_DEFAULT), path, "cannot open dataset");                 \
        write_string_attr(d, "units", units, path);                                                 \
        H5Dclose(d);                                                                                \
    }
    BODY_COLUMNS(WRITE_BODY_COLUMN, b)
#undef WRITE_BODY_COLUMN
    H5Gclose(c);
}

static void write_lifecycle(hid_t g, const dem_lifecycle_state *l, const char *path)
{
    hid_t c = chk(H5Gcreate2(g, "lifecycle", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), path, "cannot create lifecycle group");
    write_matrix(c, "balance", H5T_STD_I64LE, H5T_NATIVE_INT64, l->balance, 1, 6, 0, path);
    write_matrix(c, "outlets", H5T_STD_I64LE, H5T_NATIVE_INT64, l->outlets, l->noutlets, 3, 0, path);
    write_matrix(c, "streams", H5T_STD_I64LE, H5T_NATIVE_INT64, l->streams, l->nstreams, LIFECYCLE_STREAM_INTS, 0, path);
    write_matrix(c, "stream_reals", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, l->stream_reals, l->nstreams,
                 LIFECYCLE_STREAM_REALS, 0, path);
    write_string_attr(c, "outlet_names", l->outlet_names ? l->outlet_names : "", path);
    write_string_attr(c, "stream_names", l->stream_names ? l->stream_names : "", path);
    write_string_attr(c, "mass_units", "2^-64 kg, as two int64 (high, low)", path);
    H5Gclose(c);
}

void dem_io_write_snapshot(dem_particle_writer *w, const dem_particles *p, double time, long step)
{
    dem_io_write_snapshot_contacts(w, p, time, step, NULL);
}

void dem_io_write_snapshot_contacts(dem_particle_writer *w, const dem_particles *p, double time, long step,
                                const dem_contact_state *cs)
{
    const char *path = w->h5_path;
    char name[32];
    snapshot_name(name, sizeof name, w->next_index);
    hid_t snaps = chk(H5Gopen2(w->file, "snapshots", H5P_DEFAULT), path, "cannot open /snapshots");
    htri_t has = chk(H5Lexists(snaps, name, H5P_DEFAULT), path, "cannot query snapshot group");
    if (has) chk(H5Ldelete(snaps, name, H5P_DEFAULT), path, "cannot replace snapshot group");
    hid_t g = chk(H5Gcreate2(snaps, name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), path,
                  "cannot create snapshot group");

    int64_t offset, n;   /* this rank's first row; the particles of all ranks */
    place(p->n, &offset, &n);
    for (int k = 0; k < PARTICLE_FIELD_COUNT; k++)
        if (dem_particle_fields[k].flags & (PF_WRITE | PF_RESTART))
            write_field(g, &dem_particle_fields[k], p, p->n, offset, n, path);
    if (cs && cs->history_size > 0) write_contacts(g, cs, path);   /* the models' size: alike on every rank */
    if (cs && cs->bodies.present) write_bodies(g, &cs->bodies, path);   /* each rank its own bodies' rows */
    if (cs && cs->lifecycle.present) write_lifecycle(g, &cs->lifecycle, path);
    if (cs && cs->coarse_graining > 1.0)   /* the diameters written are the parcels' */
        write_scalar_attr(g, "coarse_graining", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &cs->coarse_graining, path);

    const long long step_ll = step;
    write_scalar_attr(g, "time", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &time, path);
    write_string_attr(g, "time_units", "s", path);
    write_scalar_attr(g, "step", H5T_STD_I64LE, H5T_NATIVE_LLONG, &step_ll, path);
    write_scalar_attr(g, "n", H5T_STD_I64LE, H5T_NATIVE_INT64, &n, path);
    /* Data on disk first, then the mark that says it is all there. */
    chk(H5Fflush(w->file, H5F_SCOPE_LOCAL), path, "cannot flush file");
    const int one = 1;
    write_scalar_attr(g, "complete", H5T_STD_I32LE, H5T_NATIVE_INT, &one, path);
    H5Gclose(g);
    H5Gclose(snaps);
    chk(H5Fflush(w->file, H5F_SCOPE_LOCAL), path, "cannot flush file");

    if (w->nsnaps == w->capsnaps) {
        w->capsnaps = w->capsnaps ? 2 * w->capsnaps : 16;
        w->snaps = dem_realloc(w->snaps, (size_t)w->capsnaps * sizeof *w->snaps);
    }
    w->snaps[w->nsnaps++] = (snapshot_info){w->next_index, time, step, n};
    w->next_index++;
    write_xdmf(w);
}

void dem_io_close_writer(dem_particle_writer *w)
{
    if (!w) return;
    if (w->file >= 0) chk(H5Fclose(w->file), w->h5_path, "cannot close file");
    free(w->snaps);
    free(w->h5_path);
    free(w->h5_name);
    free(w->xdmf_path);
    free(w);
}

/* ---------------------------------------------------------------- reader */

/* Read one field of n particles; a field the snapshot does not have is set to 0 (returns 0). */
static int read_field(hid_t group, const dem_particle_field *pf, dem_particles *p, int64_t n, const char *path)
{
    void *data = particle_field_data(p, pf);
    if (!chk(H5Lexists(group, pf->dataset, H5P_DEFAULT), path, "cannot query dataset")) {
        if (n > 0) memset(data, 0, (size_t)n * pf->element_size);
        return 0;
    }
    hid_t dset = chk(H5Dopen2(group, pf->dataset, H5P_DEFAULT), path, "cannot open dataset");
    hid_t space = chk(H5Dget_space(dset), path, "cannot get dataset dataspace");
    const int vec = pf->components > 1;
    int rank = chk(H5Sget_simple_extent_ndims(space), path, "cannot get dataset rank");
    hsize_t dims[2] = {0, 0};
    if (rank == (vec ? 2 : 1)) H5Sget_simple_extent_dims(space, dims, NULL);
    if (rank != (vec ? 2 : 1) || dims[0] != (hsize_t)n || (vec && dims[1] != (hsize_t)pf->components)) {
        char expected[64];
        if (vec) snprintf(expected, sizeof expected, "%" PRId64 " x %d", n, pf->components);
        else snprintf(expected, sizeof expected, "%" PRId64, n);
        dem_fatal("HDF5 file '%s': dataset '%s' has the wrong shape (expected %s)", path, pf->dataset,
                  expected);
    }
    if (n > 0)
        chk(H5Dread(dset, memory_type_of(pf), H5S_ALL, H5S_ALL, H5P_DEFAULT, data), path,
            "cannot read dataset");
    H5Sclose(space);
    H5Dclose(dset);
    return 1;
}

/* The restart fields of n particles from snapshot group g, the others 0. A restart field the
 * snapshot lacks (written before the field was kept, as torque before the contact history was)
 * is 0 too, with a warning; found[k] says which were there. */
static void read_restart_fields(hid_t g, dem_particles *p, int64_t n, const char *group, const char *path,
                                int found[PARTICLE_FIELD_COUNT])
{
    for (int k = 0; k < PARTICLE_FIELD_COUNT; k++) {
        const dem_particle_field *pf = &dem_particle_fields[k];
        found[k] = 0;
        if (pf->flags & PF_RESTART) {
            found[k] = read_field(g, pf, p, n, path);
            if (!found[k])
                dem_warning("HDF5 file '%s': %s has no dataset '%s' (an older file?): it starts at 0", path,
                            group, pf->dataset);
        } else if (n > 0) {
            memset(particle_field_data(p, pf), 0, (size_t)n * pf->element_size);
        }
    }
}

/* Rows of a 2-D dataset with `cols` columns (fatal on another shape); data malloc'd. */
static void *read_matrix(hid_t group, const char *name, hid_t mem_type, size_t elem, int64_t cols,
                         int64_t *rows, const char *path)
{
    hid_t dset = chk(H5Dopen2(group, name, H5P_DEFAULT), path, "cannot open dataset");
    hid_t space = chk(H5Dget_space(dset), path, "cannot get dataset dataspace");
    hsize_t dims[2] = {0, 0};
    if (H5Sget_simple_extent_ndims(space) != 2 || H5Sget_simple_extent_dims(space, dims, NULL) < 0 ||
        (int64_t)dims[1] != cols)
        dem_fatal("HDF5 file '%s': dataset '%s' has the wrong shape (expected N x %" PRId64 ")",
                  path, name, cols);
    *rows = (int64_t)dims[0];
    void *data = dem_malloc((size_t)(*rows * cols) * elem);
    if (*rows > 0 && cols > 0)
        chk(H5Dread(dset, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), path, "cannot read dataset");
    H5Sclose(space);
    H5Dclose(dset);
    return data;
}

static void read_contacts(hid_t g, dem_contact_state *cs, const char *path)
{
    memset(cs, 0, sizeof *cs);
    if (!chk(H5Lexists(g, "contacts", H5P_DEFAULT), path, "cannot query contacts group")) return;
    hid_t c = chk(H5Gopen2(g, "contacts", H5P_DEFAULT), path, "cannot open contacts group");
    if (!read_scalar_attr(c, "history_size", H5T_NATIVE_INT, &cs->history_size, path) ||
        !read_scalar_attr(c, "nwalls", H5T_NATIVE_INT, &cs->nwalls, path))
        dem_fatal("HDF5 file '%s': contacts group without history_size/nwalls", path);
    if (!chk(H5Lexists(c, "keys", H5P_DEFAULT), path, "cannot query contacts/keys")) {
        dem_warning("HDF5 file '%s': the snapshot's contact history is in an older layout (pair_ids, "
                    "wall_history); contacts start afresh", path);
        H5Gclose(c);
        cs->history_size = 0;
        return;
    }
    int64_t rows;
    cs->keys = read_matrix(c, "keys", H5T_NATIVE_INT64, sizeof(int64_t), 2, &rows, path);
    cs->count = (long)rows;
    cs->history = read_matrix(c, "history", H5T_NATIVE_DOUBLE, sizeof(double), cs->history_size, &rows, path);
    if (rows != cs->count)
        dem_fatal("HDF5 file '%s': contacts/history has %" PRId64 " rows for %ld keys", path, rows, cs->count);
    H5Gclose(c);
}

static void read_bodies(hid_t g, dem_body_state *b, const char *path)
{
    memset(b, 0, sizeof *b);
    if (!chk(H5Lexists(g, "bodies", H5P_DEFAULT), path, "cannot query bodies group")) return;
    hid_t c = chk(H5Gopen2(g, "bodies", H5P_DEFAULT), path, "cannot open bodies group");
    b->present = 1;
    int64_t rows;
    b->id = read_matrix(c, "id", H5T_NATIVE_INT64, sizeof(int64_t), 1, &rows, path);
    b->count = (long)rows;
    b->template_of = read_matrix(c, "template", H5T_NATIVE_INT64, sizeof(int64_t), 1, &rows, path);
    if (rows != b->count) dem_fatal("HDF5 file '%s': bodies/template has %" PRId64 " rows for %ld bodies", path, rows, b->count);
#define READ_BODY_COLUMN(name, units, cols, data)                                                       \
    {                                                                                                   \
        data = read_matrix(c, name, H5T_NATIVE_DOUBLE, sizeof(double), cols, &rows, path);              \
        if (rows != b->count)                                                                           \
            dem_fatal("HDF5 file '%s': bodies/%s has %" PRId64 " rows for %ld bodies", path, name, rows, b->count); \
    }
    BODY_COLUMNS(READ_BODY_COLUMN, b)
#undef READ_BODY_COLUMN
    H5Gclose(c);
}

static void read_lifecycle(hid_t g, dem_lifecycle_state *l, const char *path)
{
    memset(l, 0, sizeof *l);
    if (!chk(H5Lexists(g, "lifecycle", H5P_DEFAULT), path, "cannot query lifecycle group")) return;
    hid_t c = chk(H5Gopen2(g, "lifecycle", H5P_DEFAULT), path, "cannot open lifecycle group");
    int64_t rows;
    int64_t *balance = read_matrix(c, "balance", H5T_NATIVE_INT64, sizeof(int64_t), 6, &rows, path);
    if (rows != 1) dem_fatal("HDF5 file '%s': lifecycle/balance has %" PRId64 " rows (1 expected)", path, rows);
    memcpy(l->balance, balance, sizeof l->balance);
    free(balance);
    l->outlets = read_matrix(c, "outlets", H5T_NATIVE_INT64, sizeof(int64_t), 3, &rows, path);
    l->noutlets = (int)rows;
    l->streams = read_matrix(c, "streams", H5T_NATIVE_INT64, sizeof(int64_t), LIFECYCLE_STREAM_INTS, &rows, path);
    l->nstreams = (int)rows;
    l->stream_reals = read_matrix(c, "stream_reals", H5T_NATIVE_DOUBLE, sizeof(double), LIFECYCLE_STREAM_REALS, &rows, path);
    if (rows != l->nstreams)
        dem_fatal("HDF5 file '%s': lifecycle/stream_reals has %" PRId64 " rows for %d streams", path, rows, l->nstreams);
    l->outlet_names = read_string_attr(c, "outlet_names", path);
    l->stream_names = read_string_attr(c, "stream_names", path);
    if (!l->outlet_names || !l->stream_names) dem_fatal("HDF5 file '%s': lifecycle group without its names", path);
    l->present = 1;
    H5Gclose(c);
}

int dem_io_read_last_snapshot(const char *base, dem_particles *p, double *time, long *step)
{
    return dem_io_read_last_snapshot_contacts(base, p, time, step, NULL);
}

int dem_io_read_last_snapshot_contacts(const char *base, dem_particles *p, double *time, long *step,
                                   dem_contact_state *cs)
{
    return dem_io_read_snapshot_at(base, NAN, 0.0, p, time, step, cs);
}

int dem_io_read_snapshot_at(const char *base, double at_time, double tolerance, dem_particles *p, double *time,
                        long *step, dem_contact_state *cs)
{
    h5_quiet();
    char *path = str_cat(base, ".h5");
    hid_t fapl = make_fapl(path, 0);
    hid_t file = chk(H5Fopen(path, H5F_ACC_RDONLY, fapl), path, "cannot open file for reading");
    H5Pclose(fapl);

    scan_state s;
    scan_snapshots(file, path, &s);
    free(s.incomplete);
    if (s.ncomplete == 0) {
        free(s.complete);
        chk(H5Fclose(file), path, "cannot close file");
        free(path);
        return -1;
    }
    int pick = s.ncomplete - 1;     /* the last; or the last one at at_time */
    if (!isnan(at_time)) {
        while (pick >= 0 && !(fabs(s.complete[pick].time - at_time) <= tolerance)) pick--;
        if (pick < 0) {
            free(s.complete);
            chk(H5Fclose(file), path, "cannot close file");
            free(path);
            return -1;
        }
    }
    const snapshot_info last = s.complete[pick];
    free(s.complete);
    if (last.n < 0 || last.n > INT32_MAX)
        dem_fatal("HDF5 file '%s': snapshot %06ld has an invalid particle count %" PRId64, path,
                  last.index, last.n);

    char name[64];
    snprintf(name, sizeof name, "snapshots/%06ld", last.index);
    hid_t g = chk(H5Gopen2(file, name, H5P_DEFAULT), path, "cannot open snapshot group");
    const int n = (int)last.n;
    dem_particles_reserve(p, n);
    p->n = n;
    p->generation++;
    int found[PARTICLE_FIELD_COUNT];
    read_restart_fields(g, p, n, name, path, found);
    if (cs) {
        read_contacts(g, cs, path);
        read_bodies(g, &cs->bodies, path);
        read_lifecycle(g, &cs->lifecycle, path);
        if (!read_scalar_attr(g, "coarse_graining", H5T_NATIVE_DOUBLE, &cs->coarse_graining, path))
            cs->coarse_graining = 1.0;
        cs->forces_read = found[PF_FIELD_f] && found[PF_FIELD_torque];
        cs->coupling_read = found[PF_FIELD_beta] && found[PF_FIELD_f_fluid];
    }
    H5Gclose(g);
    chk(H5Fclose(file), path, "cannot close file");
    free(path);
    if (time) *time = last.time;
    if (step) *step = last.step;
    return 0;
}

int dem_io_drop_snapshots_after(const char *base, double after_time)
{
    h5_quiet();
    char *path = str_cat(base, ".h5");
    hid_t fapl = make_fapl(path, 0);
    hid_t file = chk(H5Fopen(path, H5F_ACC_RDWR, fapl), path, "cannot open file to drop snapshots");
    H5Pclose(fapl);
    scan_state s;
    scan_snapshots(file, path, &s);
    free(s.incomplete);
    int dropped = 0;
    if (s.ncomplete > 0) {
        hid_t g = chk(H5Gopen2(file, "snapshots", H5P_DEFAULT), path, "cannot open /snapshots");
        for (int k = 0; k < s.ncomplete; k++) {
            if (!(s.complete[k].time > after_time)) continue;
            char name[32];
            snapshot_name(name, sizeof name, s.complete[k].index);
            chk(H5Ldelete(g, name, H5P_DEFAULT), path, "cannot delete a snapshot group");
            dropped++;
        }
        H5Gclose(g);
    }
    free(s.complete);
    chk(H5Fflush(file, H5F_SCOPE_LOCAL), path, "cannot flush file");
    chk(H5Fclose(file), path, "cannot close file");
    free(path);
    return dropped;
}
