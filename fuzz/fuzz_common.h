/* fuzz_common.h - shared by the fuzz harnesses (one per program). */
#ifndef FUZZ_COMMON_H
#define FUZZ_COMMON_H
#include <stdlib.h>

/* Set by fuzz/replay.c: report every violation and go on. */
extern int fz_continue;
int fz_continue = 0;

/* The number of violated invariants so far (for fuzz/replay.c). */
unsigned long long fz_failures(void);
unsigned long long fz_failures(void) { return mi_fails; }

/* A violated invariant aborts (the fuzzer keeps the input), unless
 * fz_continue is set or MIST_FUZZ_CONTINUE is in the environment (to grow
 * a corpus past a known failure): then it is printed and the run goes on. */
static int fz_abort(void)
{
    static int env = -1;
    if (env < 0) {
        const char *e = getenv("MIST_FUZZ_CONTINUE");
        env = e && *e && *e != '0';
        mi_print_max = 5;
    }
    return !(env || fz_continue);
}
#endif
