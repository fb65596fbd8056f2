/* fuzz_dir.c - libFuzzer harness for the directions of mist.h:
 * mist_normalize, mist_dir_from_cos and every *_sample_dir, double and
 * float, against the invariants of tests/mist_inv.h (unit, finite, at the
 * sampled cosine to wi, pdf = the density at it; a violation prints the
 * inputs and aborts).  Records as in fuzz_phase.c: a selector byte (bits
 * 1-7 modulo 7: the function; bit 0: float), then the arguments, two
 * 64-bit words each (a direction: three, its recipe and two angles, see
 * mi_gen_dir). */
#include "mist_inv.h"
#include "fuzz_common.h"

#define FZ_PASS(T, S, V3, FOG)                                                         \
    static void fz_dir_##S(mi_src *s, unsigned op)                                     \
    {                                                                                  \
        V3 v = mi_draw_dir_##S(s);                                                     \
        T g = mi_draw_##S(s, MI_G), x1 = mi_draw_##S(s, MI_XI), x2 = mi_draw_##S(s, MI_XI); \
        FOG f;                                                                         \
        switch (op) {                                                                  \
        case 0: mi_normalize_##S(v); break;                                            \
        case 1: mi_dir_from_cos_##S(v, mi_draw_##S(s, MI_U), x1); break;               \
        case 2: mi_hg_sample_dir_##S(g, v, x1, x2); break;                             \
        case 3: mi_cs_sample_dir_##S(g, v, x1, x2); break;                             \
        case 4: mi_draine_sample_dir_##S(g, mi_draw_##S(s, MI_ALPHA), v, x1, x2); break; \
        case 5: mi_rayleigh_sample_dir_##S(v, x1, x2); break;                          \
        default:                                                                       \
            f.g_hg = g; f.g_d = mi_draw_##S(s, MI_G); f.alpha = mi_draw_##S(s, MI_ALPHA); \
            f.w_d = mi_draw_##S(s, MI_WD);                                             \
            mi_fog_sample_dir_##S(f, v, x1, x2);                                       \
            break;                                                                     \
        }                                                                              \
    }

FZ_PASS(double, d, mist_vec3, mist_fog)
FZ_PASS(float, f, mist_vec3f, mist_fogf)

/* one record: the selector byte picks the function (bits 1-7) and type */
static void fz_record(mi_src *s, unsigned sel)
{
    if (sel & 1) fz_dir_f(s, (sel >> 1) % 7);
    else fz_dir_d(s, (sel >> 1) % 7);
}
