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
/* The libFuzzer entry point of the phase, dir and hfog harnesses: the input
 * is a sequence of records, each a selector byte and the words the harness
 * draws through mi_src (missing bytes read as 0); each harness defines
 * fz_record, which handles one record.  (fuzz_mie.c reads its own format.) */
#ifndef FZ_OWN_ENTRY
static void fz_record(mi_src *s, unsigned sel);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    mi_bytes b;
    mi_src s;
    b.p = data; b.n = size; b.i = 0;
    s.rng = NULL; s.bytes = &b;
    mi_abort_on_fail = fz_abort();
    while (b.i < b.n) fz_record(&s, data[b.i++]);
    return 0;
}
#endif
#endif
