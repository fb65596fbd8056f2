/* fuzz_hfog.c - libFuzzer harness for the analytic height fog of mist.h:
 * mist_hfog_column, mist_hfog_eval, mist_hfog_transmittance,
 * mist_hfog_inscatter, mist_hfog_apply, mist_hfog_layers_eval and
 * mist_segment_linear, double and float, against the
 * invariants of tests/mist_inv.h (no fog: T = 1, L = 0; T in [0, 1] and
 * exp(-sigma_t column) with the column in long double; L between its
 * bounds, finite where they are; the entry points agree; a violation
 * prints the inputs and aborts).  Records: a selector byte (bit 0: float;
 * bit 1: direct; bits 2-7 modulo 3: what), then
 *   what 0: a fog, a ray, a background and a vertical cosine (for
 *       mist_hfog_column): drawn from the bytes (mi_gen_hfog: realistic, or
 *       with some or all fields edge values and raw bits) or, direct, every
 *       field's bits in the order of the struct (sun_extinction: one byte),
 *       then origin, dir, length, background, w;
 *   what 1: a stack of layers: a byte (n + 1, n in -1..9), a byte (pieces
 *       + 2), then each layer as in 0 (the first layer's ray is used);
 *   what 2: a ray-marching step k0, k1, s0, s1, length: drawn as in
 *       fuzz_phase.c, or, direct, their bits.
 * Under -ffast-math (MI_FAST in tests/mist_inv.h: the compiler assumes no
 * NaN and no infinity and flushes subnormals) the direct bit is ignored:
 * every record is read through the generators, which then keep to the
 * fast-math-safe subset the stress test uses (finite, normal-range input
 * whose intermediate results stay normal; mi_fast_ok, mi_gen_hfog).  Raw
 * bit patterns (NaN, inf, subnormal fields, products that overflow) are
 * outside what -ffast-math promises: replayed raw, 13 of the 549 corpus
 * inputs failed (gcc 12 -O2 -ffast-math).  -DMI_ALL_INPUTS reads them raw
 * anyway.
 */
#include "mist_inv.h"
#include "fuzz_common.h"

#define FZ_PASS(T, S, V3, HFOG, RGB, NB)                                               \
    static T fz_raw_##S(mi_bytes *b) { return mi_from_bits_##S(mi_take(b, NB)); }      \
    /* every field's bits, in struct order, then the ray, background and w */          \
    static void fz_direct_##S(mi_bytes *b, HFOG *f, V3 *o, V3 *d, T *len, RGB *bg, T *w) \
    {                                                                                  \
        memset(f, 0, sizeof *f);                                                       \
        f->base = fz_raw_##S(b); f->density = fz_raw_##S(b);                           \
        f->scale_height = fz_raw_##S(b);                                               \
        f->rayleigh_scat.r = fz_raw_##S(b); f->rayleigh_scat.g = fz_raw_##S(b);         \
        f->rayleigh_scat.b = fz_raw_##S(b);                                            \
        f->rayleigh_ext.r = fz_raw_##S(b); f->rayleigh_ext.g = fz_raw_##S(b);           \
        f->rayleigh_ext.b = fz_raw_##S(b);                                             \
        f->mie_scat.r = fz_raw_##S(b); f->mie_scat.g = fz_raw_##S(b);                   \
        f->mie_scat.b = fz_raw_##S(b);                                                 \
        f->mie_ext.r = fz_raw_##S(b); f->mie_ext.g = fz_raw_##S(b);                     \
        f->mie_ext.b = fz_raw_##S(b);                                                  \
        f->mie_phase.g_hg = fz_raw_##S(b); f->mie_phase.g_d = fz_raw_##S(b);            \
        f->mie_phase.alpha = fz_raw_##S(b); f->mie_phase.w_d = fz_raw_##S(b);           \
        f->sun_dir.x = fz_raw_##S(b); f->sun_dir.y = fz_raw_##S(b);                     \
        f->sun_dir.z = fz_raw_##S(b);                                                  \
        f->sun.r = fz_raw_##S(b); f->sun.g = fz_raw_##S(b); f->sun.b = fz_raw_##S(b);    \
        f->ambient.r = fz_raw_##S(b); f->ambient.g = fz_raw_##S(b);                     \
        f->ambient.b = fz_raw_##S(b);                                                  \
        f->sun_extinction = (int)mi_take(b, 1);                                        \
        o->x = fz_raw_##S(b); o->y = fz_raw_##S(b); o->z = fz_raw_##S(b);               \
        d->x = fz_raw_##S(b); d->y = fz_raw_##S(b); d->z = fz_raw_##S(b);               \
        *len = fz_raw_##S(b);                                                          \
        bg->r = fz_raw_##S(b); bg->g = fz_raw_##S(b); bg->b = fz_raw_##S(b);            \
        *w = fz_raw_##S(b);                                                            \
    }                                                                                  \
    static void fz_hfog_##S(mi_src *s, int direct)                                     \
    {                                                                                  \
        HFOG f;                                                                        \
        V3 o, d;                                                                       \
        T len, w;                                                                      \
        RGB bg;                                                                        \
        if (direct) {                                                                  \
            fz_direct_##S(s->bytes, &f, &o, &d, &len, &bg, &w);                        \
        } else {                                                                       \
            mi_gen_hfog_##S(s, &f, &o, &d, &len, &bg);                                 \
            w = mi_draw_##S(s, MI_U);                                                  \
        }                                                                              \
        mi_hfog_eval_##S(&f, o, d, len, bg);                                           \
        mi_hfog_column_##S(&f, o.y, w, len);                                           \
        mi_hfog_null_##S(o, d, len, bg);                                               \
    }                                                                                  \
    static void fz_more_##S(mi_src *s, int op, int direct)                             \
    {                                                                                  \
        HFOG ls[10];                                                                   \
        V3 o, d, o2, d2;                                                               \
        T len, len2, w;                                                                \
        RGB bg, bg2;                                                                   \
        int n, k, p;                                                                   \
        if (op == 1) {                  /* layers: n, pieces, then each layer */       \
            n = (int)(mi_take(s->bytes, 1) % 11) - 1;                                  \
            p = (int)(mi_take(s->bytes, 1) % 70) - 2;                                  \
            for (k = 0; k < (n > 0 ? n : 1); ++k) {                                    \
                if (direct)                                                            \
                    fz_direct_##S(s->bytes, &ls[k], k ? &o2 : &o, k ? &d2 : &d,        \
                                  k ? &len2 : &len, k ? &bg2 : &bg, &w);               \
                else                                                                   \
                    mi_gen_hfog_##S(s, &ls[k], k ? &o2 : &o, k ? &d2 : &d,             \
                                    k ? &len2 : &len, k ? &bg2 : &bg);                 \
            }                                                                          \
            mi_hfog_layers_##S(ls, n, o, d, len, p);                                   \
            mi_hfog_split_##S(&ls[0], o, d, len, p);                                   \
        } else if (direct) {            /* a ray-marching step, raw */                 \
            T k0 = fz_raw_##S(s->bytes), k1 = fz_raw_##S(s->bytes);                    \
            T s0 = fz_raw_##S(s->bytes), s1 = fz_raw_##S(s->bytes);                    \
            mi_segment_##S(k0, k1, s0, s1, fz_raw_##S(s->bytes));                      \
        } else {                        /* a ray-marching step */                      \
            T k0 = mi_draw_##S(s, MI_POS), k1 = mi_draw_##S(s, MI_POS);                \
            T s0 = mi_draw_##S(s, MI_REAL), s1 = mi_draw_##S(s, MI_REAL);              \
            mi_segment_##S(k0, k1, s0, s1, mi_draw_##S(s, MI_POS));                    \
        }                                                                              \
    }

FZ_PASS(double, d, mist_vec3, mist_hfog, mist_rgb, 8)
FZ_PASS(float, f, mist_vec3f, mist_hfogf, mist_rgbf, 4)

/* one record: the selector byte picks the function, the type and raw input */
static void fz_record(mi_src *s, unsigned sel)
{
    int op = (sel >> 2) % 3, direct = (sel >> 1) & 1 && !MI_FAST;
    if (op) {
        if (sel & 1) fz_more_f(s, op, direct);
        else fz_more_d(s, op, direct);
    } else if (sel & 1) {
        fz_hfog_f(s, direct);
    } else {
        fz_hfog_d(s, direct);
    }
}
