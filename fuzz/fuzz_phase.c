/* fuzz_phase.c - libFuzzer harness for the phase functions of mist.h:
 * mist_{hg,cs,draine,rayleigh}_{eval,sample}, mist_fog_{make,eval,sample}
 * and mist_fog_from_diameter, and on the same inputs the prepared
 * mist_phase_* and the batch mist_*_eval_n / _sample_n forms, double and
 * float, against the invariants of
 * tests/mist_inv.h (a violation prints the inputs and aborts).
 *
 * The input is a sequence of records: one byte picks the function (bits
 * 1-7, modulo 11) and the type (bit 0: float), then each argument takes two
 * little-endian 64-bit words, mi_gen's: the first picks the recipe (low 4
 * bits: uniform in the domain, near a bound or threshold, near 0,
 * log-uniform, ulps around a bound, an edge value, or, for 14 and 15, the
 * raw bits of the second word) and its parameters; missing bytes read as
 * 0.  The arguments are g, alpha, x (u or xi), x2 (a second xi: samplers
 * are called at both and must be monotone), then for the fog w_d etc.
 *
 *   clang -fsanitize=fuzzer,address,undefined -Iinclude -Itests fuzz/fuzz_phase.c
 * or without libFuzzer, replaying files: fuzz/replay.c. */
#include "mist_inv.h"
#include "fuzz_common.h"

#define FZ_PASS(T, S, V3)                                                              \
    static void fz_phase_##S(mi_src *s, unsigned op)                                   \
    {                                                                                  \
        T g = mi_draw_##S(s, MI_G), a = mi_draw_##S(s, MI_ALPHA);                      \
        T x = mi_draw_##S(s, op < 4 ? MI_U : MI_XI), x2 = mi_draw_##S(s, MI_XI), u1, u2; \
        MI_FOGT_##S f;                                                                 \
        switch (op) {                                                                  \
        case 0: mi_hg_eval_##S(g, x); break;                                           \
        case 1: mi_cs_eval_##S(g, x); break;                                           \
        case 2: mi_draine_eval_##S(g, a, x); break;                                    \
        case 3: mi_rayleigh_eval_##S(x); break;                                        \
        case 4: u1 = mi_hg_sample_##S(g, x); u2 = mi_hg_sample_##S(g, x2);             \
                fz_order("mist_hg_sample", g, 0, x, u1, x2, u2); break;                \
        case 5: u1 = mi_cs_sample_##S(g, x); u2 = mi_cs_sample_##S(g, x2);             \
                fz_order("mist_cs_sample", g, 1, x, u1, x2, u2); break;                \
        case 6: u1 = mi_draine_sample_##S(g, a, x); u2 = mi_draine_sample_##S(g, a, x2); \
                fz_order("mist_draine_sample", g, a, x, u1, x2, u2); break;            \
        case 7: u1 = mi_rayleigh_sample_##S(x); u2 = mi_rayleigh_sample_##S(x2);       \
                fz_order("mist_rayleigh_sample", 0, 0, x, u1, x2, u2); break;          \
        case 8: case 9:                                  /* hand-filled or made */     \
            f.g_hg = g; f.g_d = mi_draw_##S(s, MI_G); f.alpha = a;                     \
            f.w_d = mi_draw_##S(s, MI_WD);                                             \
            if (op == 9) f = mi_fog_make_##S(f.g_hg, f.g_d, f.alpha, f.w_d);           \
            mi_fog_eval_##S(f, mi_draw_##S(s, MI_U));                                  \
            mi_fog_sample_##S(f, x);                                                   \
            break;                                                                     \
        default:                                                                       \
            f = mi_fog_from_diameter_##S(mi_draw_##S(s, MI_DIAM));                     \
            mi_fog_eval_##S(f, mi_draw_##S(s, MI_U));                                  \
            mi_fog_sample_##S(f, x);                                                   \
            break;                                                                     \
        }                                                                              \
        {   /* the prepared (mist_phase_*) and batch (mist_*_n) forms on the same   */ \
            /* inputs, so every record checks them too (no further bytes drawn)    */ \
            static const int pk[11] = { 0, 2, 1, 3, 0, 2, 1, 3, 4, 4, 4 };            \
            T in[2];                                                                   \
            V3 wi;                                                                     \
            in[0] = x; in[1] = x2;                                                     \
            wi.x = (T)0.48; wi.y = (T)-0.6; wi.z = (T)0.64;                            \
            if (op < 8) { f.g_hg = g; f.g_d = g; f.alpha = a; f.w_d = 1; }             \
            if (!FZ_CONTRACT) mi_phase_##S(pk[op], g, a, f, in, in, 2, wi, x2);         \
            if (!FZ_CONTRACT && op < 8) mi_batch_##S(g, a, in, 2);                     \
        }                                                                              \
    }

/* u1 = sampler(x1), u2 = sampler(x2): in the order of the x */
static void fz_order(const char *fn, double g, double a, double x1, double u1, double x2,
                     double u2)
{
    if (mi_nan_d(x1) || mi_nan_d(x2)) return;
    if ((x1 < x2 && u1 > u2) || (x2 < x1 && u2 > u1))
        mi_fail("%s(g=%a, alpha=%a) not monotone in xi: xi %a -> %a, xi %a -> %a", fn, g, a,
                x1, u1, x2, u2);
}

/* Where the hardware fuses a*b+c, a compiler allowed to contract
 * (-ffp-contract=fast: the O3 variant) may fuse differently in two inlined
 * copies of one function, so the bit-for-bit cross-checks of the prepared
 * and batch forms (mi_phase: sample_dir with and without pdf) fail by an
 * ulp there (measured, gcc 12 -O3 -march=native): skipped in such builds;
 * test_stress checks those forms with its contraction tolerances. */
#if defined(__FP_FAST_FMA) || defined(__FP_FAST_FMAF) || defined(__FMA__) \
    || defined(__ARM_FEATURE_FMA)
#  define FZ_CONTRACT 1
#else
#  define FZ_CONTRACT 0
#endif

#define MI_FOGT_d mist_fog
#define MI_FOGT_f mist_fogf
FZ_PASS(double, d, mist_vec3)
FZ_PASS(float, f, mist_vec3f)

/* one record: the selector byte picks the function (bits 1-7) and type */
static void fz_record(mi_src *s, unsigned sel)
{
    if (sel & 1) fz_phase_f(s, (sel >> 1) % 11);
    else fz_phase_d(s, (sel >> 1) % 11);
}
