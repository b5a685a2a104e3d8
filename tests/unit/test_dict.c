/* Unit tests for the dictionary reader (dem/src/dict.c).
 *
 *   test_dict                 reads dictionaries written to a temporary directory and
 *                             checks every accessor; prints "test_dict: N checks passed".
 *   test_dict --read <file>   reads <file> with a demProperties-like schema (the layout in
 *                             dem/README.md) and checks for unused keys; exits 0 if fine.
 *                             dict_errors.sh uses it to check the error messages. */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L   /* mkdtemp */
#endif
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <sys/stat.h>

#include "dict.h"

static int checks, failures;

#define CHECK(cond)                                                             \
    do {                                                                        \
        checks++;                                                               \
        if (!(cond)) {                                                          \
            failures++;                                                         \
            fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond); \
        }                                                                       \
    } while (0)

#define CHECK_NEAR(a, b) CHECK(fabs((double)(a) - (double)(b)) <= 1e-12 * (1 + fabs((double)(b))))

/* ------------------------------------------------------------------ --read schema */

static void read_schema(const char *path)
{
    static const char *const normal_opts[] = { "hooke", "hertz", NULL };
    static const char *const tangential_opts[] = { "none", "history", NULL };
    static const char *const none_opts[] = { "none", NULL };
    static const char *const surface_opts[] = { "default", NULL };
    static const char *const wall_types[] = { "plane", "box", "cylinder", NULL };
    static const char *const axes[] = { "x", "y", "z", NULL };
    static const char *const sides[] = { "inside", "outside", NULL };
    static const char *const dists[] = { "constant", "uniform", "normal", "discrete", NULL };
    static const char *const regions[] = { "box", "cylinder", NULL };
    const double zero[3] = { 0, 0, 0 };
    double v[3], *list;
    int b3[3];

    dem_dict *d = dem_dict_read(path);
    dem_dict_scalar(d, "timeStep", 1e-12, 1);
    dem_dict_scalar_opt(d, "endTime", 0, 0, HUGE_VAL);
    dem_dict_scalar_opt(d, "writeInterval", 0, 0, HUGE_VAL);
    dem_dict_vector_opt(d, "gravity", v, zero);
    dem_dict_scalar_opt(d, "skin", 1e-3, 0, 1);
    dem_dict_label_opt(d, "sortInterval", 20, 0, 1000000);
    dem_dict_scalar_opt(d, "maxExpectedVelocity", 1, 0, HUGE_VAL);
    dem_dict_bool_opt(d, "timeStepOverride", 0);
    dem_dict_scalar_opt(d, "maxOverlapFraction", 0.2, 0, 1);
    dem_dict_scalar_opt(d, "progressInterval", 5, 0, HUGE_VAL);
    if (dem_dict_has(d, "probePoints")) free((dem_dict_vector_list(d, "probePoints", &list), list));

    dem_dict *dom = dem_dict_sub_opt(d, "domain");
    if (dom) {
        dem_dict_vector(dom, "min", v);
        dem_dict_vector(dom, "max", v);
        dem_dict_bools3_opt(dom, "periodic", b3, 0);
    }
    dem_dict *mat = dem_dict_sub_opt(d, "materials");
    for (int i = 0; mat && i < dem_dict_size(mat); i++) {
        dem_dict *m = dem_dict_dict_at(mat, i);
        dem_dict_scalar(m, "youngsModulus", 1, 1e15);
        dem_dict_scalar(m, "poissonsRatio", 0, 0.5);
        dem_dict_scalar(m, "density", 1, 1e5);
    }
    dem_dict *cm = dem_dict_sub_opt(d, "contactModels");
    if (cm) {
        dem_dict_choice(cm, "normal", normal_opts);
        dem_dict_choice_opt(cm, "tangential", tangential_opts, 1);
        dem_dict_choice_opt(cm, "cohesion", none_opts, 0);
        dem_dict_choice_opt(cm, "rolling", none_opts, 0);
        dem_dict_choice_opt(cm, "surface", surface_opts, 0);
        dem_dict_scalar_opt(cm, "characteristicVelocity", 1, 0, HUGE_VAL);
    }
    dem_dict *ia = dem_dict_sub_opt(d, "interactions");
    for (int i = 0; ia && i < dem_dict_size(ia); i++) {
        dem_dict *p = dem_dict_dict_at(ia, i);
        dem_dict_scalar(p, "restitution", 0, 1);
        dem_dict_scalar(p, "friction", 0, 10);
    }
    dem_dict *walls = dem_dict_sub_opt(d, "walls");
    for (int i = 0; walls && i < dem_dict_size(walls); i++) {
        dem_dict *w = dem_dict_dict_at(walls, i);
        int type = dem_dict_choice(w, "type", wall_types);
        dem_dict_word(w, "material");
        if (type == 0) {
            dem_dict_vector(w, "point", v);
            dem_dict_vector(w, "normal", v);
            dem_dict_vector_opt(w, "boundsMin", v, zero);
            dem_dict_vector_opt(w, "boundsMax", v, zero);
        } else if (type == 1) {
            dem_dict_vector(w, "min", v);
            dem_dict_vector(w, "max", v);
        } else {
            dem_dict_choice(w, "axis", axes);
            if (dem_dict_scalar_list(w, "centre", &list) != 2) dem_dict_fatal(w, "centre", "expected 2 numbers");
            free(list);
            dem_dict_scalar(w, "radius", 0, HUGE_VAL);
            dem_dict_choice(w, "side", sides);
            dem_dict_scalar_opt(w, "zMin", 0, -HUGE_VAL, HUGE_VAL);
            dem_dict_scalar_opt(w, "zMax", 0, -HUGE_VAL, HUGE_VAL);
        }
    }
    dem_dict *ins = dem_dict_sub_opt(d, "insertion");
    for (int i = 0; ins && i < dem_dict_size(ins); i++) {
        dem_dict *f = dem_dict_dict_at(ins, i);
        dem_dict *r = dem_dict_sub(f, "region");
        if (dem_dict_choice(r, "type", regions) == 0) {
            dem_dict_vector(r, "min", v);
            dem_dict_vector(r, "max", v);
        }
        if (dem_dict_has(f, "number"))
            dem_dict_label(f, "number", 1, 100000000);
        else
            dem_dict_scalar(f, "solidFraction", 0, 1);
        dem_dict_word(f, "material");
        dem_dict_vector_opt(f, "velocity", v, zero);
        dem_dict *dia = dem_dict_sub(f, "diameter");
        int dist = dem_dict_choice(dia, "distribution", dists);
        if (dist == 0) dem_dict_scalar(dia, "value", 0, 1);
        if (dist == 3) {
            free((dem_dict_scalar_list(dia, "values", &list), list));
            free((dem_dict_scalar_list(dia, "weights", &list), list));
        }
        dem_dict_label_opt(f, "seed", 1, 0, 2147483647);
        dem_dict_label_opt(f, "maxAttempts", 200, 1, 1000000);
    }
    dem_dict_check_unused(d);
    dem_dict_free(d);
}

/* ------------------------------------------------------------------ unit checks */

static char tmpdir[256];

static void write_file(const char *name, const char *text)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s", tmpdir, name);
    FILE *f = fopen(path, "w");
    if (!f || fputs(text, f) == EOF || fclose(f) != 0) {
        fprintf(stderr, "test_dict: cannot write %s\n", path);
        exit(2);
    }
}

static const char *main_text =
    "FoamFile { version 2.0; format ascii; class dictionary; object demProperties; }\n"
    "/* a block comment\n"
    "   over two lines with ; { ( \" inside */\n"
    "timeStep 1e-5;   // trailing comment\n"
    "endTime 0.2;\n"                                         /* line 5 */
    "negative -0.1; big 5e6; plusExp +2.5E+3;\n"
    "count 42; countExp 5e4; negLabel -7;\n"
    "name glass-steel; odd a/b:c<d>,e+f.g;\n"
    "quoted \"a string; with { } ( ) and \\\"escapes\\\"\";\n"
    "flagT true; flagY yes; flagOn on; flagF false; flagN no; flagOff off;\n" /* line 10 */
    "gravity (0 0 -9.81);\n"
    "counted 3(1 2 3);\n"
    "periodic (false false true);\n"
    "list (1 2.5 -3e-2 4);\n"
    "empty ();\n"                                            /* line 15 */
    "points ((0 0 0) (1 2 3) 3(4 5 6));\n"
    "countedPoints 2((1 1 1)(2 2 2));\n"
    "multiLine\n"
    "(\n"
    "    1\n"                                                /* line 20 */
    "    2\n"
    ");\n"
    "model hertz;\n"
    "dup 1;\n"
    "dup 2;\n"                                               /* line 25 */
    "#include \"inc/extra\"\n"
    "sub\n"
    "{\n"
    "    inner { deep 7; }\n"
    "    x 1;\n"                                             /* line 30 */
    "};\n"
    "materials { glass { density 2500; } steel { density 7800; } }\n"
    "after 1;//comment right after\n";

static void test_values(void)
{
    char path[512];
    snprintf(path, sizeof path, "%s/demProperties", tmpdir);
    dem_dict *d = dem_dict_read(path);
    const double zero[3] = { 0, 0, 0 }, one[3] = { 1, 1, 1 };
    double v[3], *list;
    int b[3];

    CHECK(strcmp(dem_dict_name(d), "demProperties") == 0);
    CHECK(strcmp(dem_dict_path(d), path) == 0);
    CHECK(dem_dict_line(d) == 1);

    /* scalars and labels */
    CHECK_NEAR(dem_dict_scalar(d, "timeStep", 0, 1), 1e-5);
    CHECK_NEAR(dem_dict_scalar(d, "endTime", 0, 1), 0.2);
    CHECK_NEAR(dem_dict_scalar(d, "negative", -1, 0), -0.1);
    CHECK_NEAR(dem_dict_scalar(d, "big", 0, 1e7), 5e6);
    CHECK_NEAR(dem_dict_scalar(d, "plusExp", 0, HUGE_VAL), 2500);
    CHECK_NEAR(dem_dict_scalar(d, "count", 0, 100), 42);   /* an integer is a valid scalar */
    CHECK_NEAR(dem_dict_scalar_opt(d, "absent", 3.5, 0, 1), 3.5);
    CHECK(dem_dict_label(d, "count", 0, 100) == 42);
    CHECK(dem_dict_label(d, "countExp", 0, 100000) == 50000);
    CHECK(dem_dict_label(d, "negLabel", -10, 10) == -7);
    CHECK(dem_dict_label_opt(d, "absentLabel", 9, 0, 1) == 9);
    CHECK(dem_dict_key_line(d, "timeStep") == 4);
    CHECK(dem_dict_key_line(d, "endTime") == 5);
    CHECK(dem_dict_key_line(d, "nope") == 1);

    /* words and strings */
    CHECK(strcmp(dem_dict_word(d, "name"), "glass-steel") == 0);
    CHECK(strcmp(dem_dict_word(d, "odd"), "a/b:c<d>,e+f.g") == 0);
    CHECK(strcmp(dem_dict_word(d, "quoted"), "a string; with { } ( ) and \"escapes\"") == 0);
    CHECK(strcmp(dem_dict_word_opt(d, "absentWord", "dflt"), "dflt") == 0);
    {
        static const char *const opts[] = { "hooke", "hertz", NULL };
        CHECK(dem_dict_choice(d, "model", opts) == 1);
        CHECK(dem_dict_choice_opt(d, "absentChoice", opts, 0) == 0);
    }

    /* booleans */
    CHECK(dem_dict_bool_opt(d, "flagT", 0) == 1);
    CHECK(dem_dict_bool_opt(d, "flagY", 0) == 1);
    CHECK(dem_dict_bool_opt(d, "flagOn", 0) == 1);
    CHECK(dem_dict_bool_opt(d, "flagF", 1) == 0);
    CHECK(dem_dict_bool_opt(d, "flagN", 1) == 0);
    CHECK(dem_dict_bool_opt(d, "flagOff", 1) == 0);
    CHECK(dem_dict_bool_opt(d, "absentFlag", 1) == 1);
    dem_dict_bools3_opt(d, "periodic", b, 1);
    CHECK(b[0] == 0 && b[1] == 0 && b[2] == 1);
    dem_dict_bools3_opt(d, "absentPeriodic", b, 1);
    CHECK(b[0] == 1 && b[1] == 1 && b[2] == 1);

    /* vectors and lists */
    dem_dict_vector(d, "gravity", v);
    CHECK(v[0] == 0 && v[1] == 0 && v[2] == -9.81);
    dem_dict_vector(d, "counted", v);
    CHECK(v[0] == 1 && v[1] == 2 && v[2] == 3);
    dem_dict_vector_opt(d, "absentVector", v, one);
    CHECK(v[0] == 1 && v[1] == 1 && v[2] == 1);
    dem_dict_vector_opt(d, "gravity", v, zero);
    CHECK(v[2] == -9.81);
    CHECK(dem_dict_scalar_list(d, "list", &list) == 4);
    CHECK(list[0] == 1 && list[1] == 2.5 && list[2] == -3e-2 && list[3] == 4);
    free(list);
    CHECK(dem_dict_scalar_list(d, "counted", &list) == 3);
    CHECK(list[2] == 3);
    free(list);
    CHECK(dem_dict_scalar_list(d, "empty", &list) == 0);
    free(list);
    CHECK(dem_dict_scalar_list(d, "multiLine", &list) == 2);
    CHECK(list[0] == 1 && list[1] == 2);
    free(list);
    CHECK(dem_dict_vector_list(d, "points", &list) == 3);
    CHECK(list[0] == 0 && list[3] == 1 && list[4] == 2 && list[5] == 3 && list[6] == 4 && list[8] == 6);
    free(list);
    CHECK(dem_dict_vector_list(d, "countedPoints", &list) == 2);
    CHECK(list[0] == 1 && list[5] == 2);
    free(list);

    /* duplicates: the later one wins, at the first one's position */
    CHECK(dem_dict_label(d, "dup", 0, 10) == 2);
    CHECK(dem_dict_key_line(d, "dup") == 25);

    /* #include, relative to the including file; nested include relative to inc/ */
    CHECK(dem_dict_has(d, "included"));
    CHECK_NEAR(dem_dict_scalar(d, "included", 0, 10), 3.5);
    CHECK(dem_dict_key_line(d, "included") == 2);
    CHECK(dem_dict_label(d, "fromMore", 0, 10) == 1);
    {
        dem_dict *s = dem_dict_sub(d, "incDict");
        char want[512];
        snprintf(want, sizeof want, "%s/inc/extra", tmpdir);
        CHECK(strcmp(dem_dict_path(s), want) == 0);
        CHECK(dem_dict_label(s, "k", 0, 10) == 4);
    }

    /* nested dictionaries */
    CHECK(dem_dict_has(d, "FoamFile"));   /* kept, but marked used */
    dem_dict *sub = dem_dict_sub(d, "sub");
    CHECK(strcmp(dem_dict_name(sub), "sub") == 0);
    CHECK(dem_dict_line(sub) == 28);
    CHECK(dem_dict_size(sub) == 2);
    CHECK(strcmp(dem_dict_key_at(sub, 0), "inner") == 0 && dem_dict_is_dict_at(sub, 0));
    CHECK(strcmp(dem_dict_key_at(sub, 1), "x") == 0 && !dem_dict_is_dict_at(sub, 1));
    CHECK(dem_dict_label(dem_dict_dict_at(sub, 0), "deep", 0, 10) == 7);
    CHECK(dem_dict_label(sub, "x", 0, 10) == 1);
    CHECK(dem_dict_sub_opt(d, "absentSub") == NULL);
    CHECK(dem_dict_sub_opt(d, "sub") == sub);

    dem_dict *mat = dem_dict_sub(d, "materials");
    CHECK(dem_dict_size(mat) == 2);
    CHECK(strcmp(dem_dict_key_at(mat, 0), "glass") == 0);
    CHECK(strcmp(dem_dict_key_at(mat, 1), "steel") == 0);
    for (int i = 0; i < dem_dict_size(mat); i++)
        CHECK(dem_dict_scalar(dem_dict_dict_at(mat, i), "density", 0, 1e4) > 2000);
    CHECK(dem_dict_label(d, "after", 0, 10) == 1);

    /* everything was read, and the FoamFile header counts as used */
    dem_dict_check_unused(d);
    dem_dict_free(d);
}

int main(int argc, char **argv)
{
    if (argc == 3 && strcmp(argv[1], "--read") == 0) {
        read_schema(argv[2]);
        printf("test_dict: %s read without errors\n", argv[2]);
        return 0;
    }
    if (argc != 1) {
        fprintf(stderr, "usage: test_dict [--read <file>]\n");
        return 2;
    }

    const char *base = getenv("TMPDIR");
    snprintf(tmpdir, sizeof tmpdir, "%s/test_dict_XXXXXX", base && *base ? base : "/tmp");
    if (!mkdtemp(tmpdir)) {
        perror("test_dict: mkdtemp");
        return 2;
    }
    char incdir[300];
    snprintf(incdir, sizeof incdir, "%s/inc", tmpdir);
    mkdir(incdir, 0700);
    write_file("demProperties", main_text);
    write_file("inc/extra", "// included\nincluded 3.5;\n#include \"more\"\nincDict { k 4; }\n");
    write_file("inc/more", "fromMore 1;\n");

    test_values();

    char p[512];
    const char *names[] = { "inc/more", "inc/extra", "demProperties" };
    for (int i = 0; i < 3; i++) {
        snprintf(p, sizeof p, "%s/%s", tmpdir, names[i]);
        remove(p);
    }
    rmdir(incdir);
    rmdir(tmpdir);

    if (failures) {
        fprintf(stderr, "test_dict: %d of %d checks FAILED\n", failures, checks);
        return 1;
    }
    printf("test_dict: %d checks passed\n", checks);
    return 0;
}
