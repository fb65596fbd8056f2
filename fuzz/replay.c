/* replay.c - runs a fuzz harness (fuzz/fuzz_*.c, linked in) over files
 * and directories of inputs without libFuzzer: the regression test of the
 * kept corpus (fuzz/corpus/<harness>/), built by any C99 compiler.
 *   replay_<harness> PATH...   (a directory: every regular file in it)
 * Every input runs; each violated invariant is printed (the first 5 in
 * full), each failing input named, and the exit status is 1 if any input
 * failed (or none was found). */
#if !defined(_WIN32)
#  define _POSIX_C_SOURCE 200809L
#  include <dirent.h>
#  include <sys/stat.h>
#endif
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
extern int fz_continue;                     /* fuzz_common.h */
unsigned long long fz_failures(void);

static long failed_inputs;

static long run_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    uint8_t *buf;
    long n;
    if (!f) { printf("replay: cannot open %s\n", path); exit(2); }
    if (fseek(f, 0, SEEK_END) != 0 || (n = ftell(f)) < 0 || fseek(f, 0, SEEK_SET) != 0) {
        printf("replay: cannot read %s\n", path);
        exit(2);
    }
    buf = (uint8_t *)malloc((size_t)n + 1);
    if (!buf || fread(buf, 1, (size_t)n, f) != (size_t)n) {
        printf("replay: cannot read %s\n", path);
        exit(2);
    }
    fclose(f);
    {
        unsigned long long before = fz_failures();
        LLVMFuzzerTestOneInput(buf, (size_t)n);
        if (fz_failures() != before) {
            ++failed_inputs;
            printf("replay: FAILED %s (%ld bytes): %llu violations\n", path, n,
                   fz_failures() - before);
        }
    }
    fflush(stdout);
    free(buf);
    return 1;
}

static int cmp(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

static long run_path(const char *path)
{
#if !defined(_WIN32)
    struct stat st;
    if (stat(path, &st) == 0 && S_ISDIR(st.st_mode)) {
        DIR *d = opendir(path);
        struct dirent *e;
        char **names = NULL;
        size_t nn = 0, cap = 0, i;
        long count = 0;
        if (!d) { printf("replay: cannot open %s\n", path); exit(2); }
        while ((e = readdir(d)) != NULL) {
            size_t len;
            char *p;
            if (e->d_name[0] == '.') continue;
            len = strlen(path) + strlen(e->d_name) + 2;
            p = (char *)malloc(len);
            if (!p) exit(2);
            sprintf(p, "%s/%s", path, e->d_name);
            if (stat(p, &st) != 0 || !S_ISREG(st.st_mode)) { free(p); continue; }
            if (nn == cap) {
                cap = cap ? 2 * cap : 64;
                names = (char **)realloc(names, cap * sizeof *names);
                if (!names) exit(2);
            }
            names[nn++] = p;
        }
        closedir(d);
        if (nn) qsort(names, nn, sizeof *names, cmp);     /* a reproducible order */
        for (i = 0; i < nn; ++i) { count += run_file(names[i]); free(names[i]); }
        free(names);
        return count;
    }
#endif
    return run_file(path);
}

int main(int argc, char **argv)
{
    long n = 0;
    int i;
    fz_continue = 1;
    for (i = 1; i < argc; ++i) n += run_path(argv[i]);
    printf("replay: %ld inputs, %ld with violated invariants (%llu violations)\n", n,
           failed_inputs, fz_failures());
    return n > 0 && failed_inputs == 0 ? 0 : 1;
}
