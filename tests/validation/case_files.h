/* Helpers for tests that read whole cases: a scratch case directory with constant/, a file
 * written into it, and removal afterwards. */
#ifndef TEST_CASE_FILES_H
#define TEST_CASE_FILES_H

#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

/* A new directory /tmp/<name>.XXXXXX with constant/ in it; its path into dir[n]. */
static inline void scratch_case(const char *name, char *dir, size_t n)
{
    snprintf(dir, n, "/tmp/%s.XXXXXX", name);
    if (!mkdtemp(dir)) { perror("mkdtemp"); exit(2); }
    char c[4200];
    snprintf(c, sizeof c, "%s/constant", dir);
    if (mkdir(c, 0755) != 0) { perror("mkdir"); exit(2); }
}

/* Write text to <dir>/<rel>. */
static inline void write_text(const char *dir, const char *rel, const char *text)
{
    char path[4300];
    snprintf(path, sizeof path, "%s/%s", dir, rel);
    FILE *f = fopen(path, "w");
    if (!f || fputs(text, f) < 0 || fclose(f) != 0) { perror(path); exit(2); }
}

static inline void remove_case(const char *dir)
{
    char cmd[4300];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0) fprintf(stderr, "could not remove %s\n", dir);
}

#endif
