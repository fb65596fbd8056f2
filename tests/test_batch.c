/* test_batch.c - the batch forms (include/mist.h, "Batch forms") return
 * exactly what their scalar functions return, element by element, bit for
 * bit: mist_hg_eval_n, mist_hg_sample_n, mist_draine_eval_n,
 * mist_draine_sample_n, mist_rayleigh_eval_n, mist_rayleigh_sample_n,
 * the prepared mist_phase_eval_n and mist_phase_sample_n (HG and Draine:
 * against mist_phase_eval and mist_phase_sample; and mist_phase_eval_n of
 * a fog with two lobes, HG 0.9 and Draine (g, alpha), w_d 0.4, which a
 * mutation audit found untested: a batch that dropped its HG lobe passed
 * every test but the stress run), the fog mixture's samplers
 * mist_phase_sample_n of that fog and mist_fog_sample_n, mist_fog_eval_n,
 * and their float forms (_nf).  The mixture also at its edges (mix_T):
 * seventeen fogs (w_d tiny, near 1, 0, 1, NaN; a lobe at the Dirac
 * limit's edge; alpha 0; NaN parameters), xi = w_d and its neighbours
 * (the lobe's pick), each lobe's mirror edge xi' = 1 - 1024 eps and
 * around it, xi near 0 and 1, over lengths across its chunks of 1024
 * (MIST__MIXC) and the Draine blocks of 32; every path (HG, Draine,
 * mirror) reached, counted.  There too the compact form of each fog
 * (mist_phasec_eval: mist_phase_eval's values bit for bit, bad input too;
 * mist_phasec_sample of bad xi that of the clamped xi).  The height fog's
 * mist_hfog_apply_n (see test_hfog_batch) and the float forms (_nf).
 *
 * Inputs: random values over and beyond the domain, and the edges and bad
 * input of DOMAIN AND BAD INPUT (NaN, +-inf, +-0, +-1 and their neighbours,
 * u = g for the Dirac limit); parameters g and alpha the same (|g| = 1,
 * |g| > 1, NaN, alpha = 0, +inf, negative, NaN); lengths 0 (NULL arrays),
 * 1, 15, 16, 17, 31, 32, 33 (the block is 32), 100, 1023, 1024 (from
 * MIST_DRAINE_PREPARE_N = 1024 on, the unprepared Draine batch sampler is
 * the prepared one's, compared with mist_phase_sample, except where its
 * eq. 6 kernel applies, mist__draine_vn(g, alpha, n): there the scalar
 * function's) and 1100; in place; and no element past n is written.  In
 * quick mode (MIST_TEST_QUICK > 1: the variant builds, tests/mist_test.h)
 * the lengths above 100 only where the code depends on n beyond blocks of
 * 32: mist_draine_sample_n (MIST_DRAINE_PREPARE_N, mist__draine_vn) and
 * mist_phase_sample_n (the float form's queue of pending elements, flushed
 * when 32 are pending: 466 mid-loop flushes at n > 100, none at n <= 100,
 * counted) and the fog mixture's samplers (chunks of 1024); for the others 100 already spans three blocks of 32 and a
 * remainder (under ASan at -O0 the long lengths would take most of
 * batch_nold's time).
 * Built twice by CMake: with the project's
 * flags and with -march=native -fno-math-errno (so that the vectorised
 * code is what is compared).  The comparison is by bits (a -0 for a +0 or
 * a different NaN would fail); a negative control checks that it sees a
 * one-ulp change. */
#include "mist.h"
#include "mist_test.h"

#include <float.h>
#include <string.h>

#define NMAX 1100

/* Where the hardware fuses a*b+c (FP_FAST_FMA), a compiler allowed to
 * contract (-ffp-contract=fast: gcc's default outside the ISO modes, the
 * variant_O3 build) may fuse different products in the vectorised batch
 * body and in the scalar function: one rounding fewer here or there, so
 * results may differ by a few ulps (HG's density takes ~10 roundings,
 * Draine's ~20 with its weight and normalisation, most of them
 * multiply-adds of positive terms, each of which may round once more or
 * less in one copy: 8 allowed, 16 for the densities; measured with gcc 12
 * -O3 -march=native -ffp-contract=fast: 1-2 ulps, and 5 in a 1e9-call
 * stress run once the scalar densities test their domain before
 * sanitising; an independent check found 9 in the densities,
 * mist_draine_eval_n and _nf, gcc 12 -O3 -march=native without -std=c99,
 * where 8 had been allowed; 1-3 in the samplers).
 * Without FMA hardware nothing can be fused: bit for bit.  The header's
 * BATCH FORMS paragraph says the same. */
#if defined(FP_FAST_FMA) || defined(FP_FAST_FMAF) || defined(__FMA__) \
    || defined(__ARM_FEATURE_FMA)
#  define FMA_ULPS 8
#  define EVAL_ULPS 16
#else
#  define FMA_ULPS 0
#  define EVAL_ULPS 0
#endif
#define GUARD 4

/* The Draine and Cornette-Shanks batch samplers in float compute a second
 * Newton step (and round by a residual's sign) apart from the scalar
 * function: with contraction two copies may stop at different points of
 * the range the accuracy bar allows, |u - u*| <= 4 ulp(u*) + 4 eps xi
 * du/dxi (tests/test_accuracy.c), which is many ulps of u wherever one ulp
 * of xi moves u by many (near u = 0 at large alpha: include/mist.h, BATCH
 * FORMS).  So there they may differ by twice the bar, each being within
 * it. */
#define DR_BAR (FMA_ULPS > 0)

/* (eq. 6's domain, where the unprepared Draine batch has its kernel: 1e-3
 * <= |g| <= 0.9999, 1e-6 <= alpha <= 1e4; its edges and either side; in
 * float also |g| <= 0.999999 and, where |g| >= 0.5, alpha <= 1e30
 * (mist__draine_okt): those edges, 0.999999046 the float above 0.999999;
 * and either side of where the kernel is taken from MIST_DRAINE_PREPARE_N
 * on: |g| >= 0.01 and alpha <= 300, or |g| >= 0.5) */
static const double g_list[] = { 0, 0.3, -0.3, 0.8, -0.95, 0.999, -0.9999, 1e-6, -1e-6,
                                  1e-3, -0.99991, 0.999999, -0.99999904632568359375, 0.01,
                                  -0.0099, 0.5, -0.4999, 1, -1, 1.5, -7, NAN, INFINITY };
static const double a_list[] = { 0, 1e-7, 1e-6, 1, 17, 250, 300, 301, 1e4, 10001, 1e9,
                                  1e30, 2e30, INFINITY, -1, NAN };
static const int n_list[] = { 0, 1, 15, 16, 17, 31, 32, 33, 100, MIST_DRAINE_PREPARE_N - 1,
                              MIST_DRAINE_PREPARE_N, NMAX };

enum { HG_EVAL, HG_SAMPLE, DR_EVAL, DR_SAMPLE, RL_EVAL, RL_SAMPLE, PD_EVAL, PD_SAMPLE,
       PH_SAMPLE, PF_EVAL, PF_SAMPLE, FG_EVAL, FG_SAMPLE, NKIND };
static const char *kind_name[] = { "hg_eval", "hg_sample", "draine_eval", "draine_sample",
                                   "rayleigh_eval", "rayleigh_sample", "phase_eval (Draine)",
                                   "phase_sample (Draine)", "phase_sample (HG)",
                                   "phase_eval (fog: two lobes)",
                                   "phase_sample (fog mixture)", "fog_eval", "fog_sample" };
/* the fog of the kinds PF_*, FG_*: HG 0.9 and Draine (g, alpha), w_d 0.4 */
#define FOG_GH 0.9
#define FOG_W 0.4
#define MIXK(k) ((k) == PF_SAMPLE || (k) == FG_SAMPLE)

/* One definition for both types: T, its suffix S (empty or f). */
#define CAT_(a, b) a##b
#define CAT(a, b) CAT_(a, b)
#define DEFINE_TYPE(T, S, NEXT)                                                    \
static int bits_##T(T a, T b) { return memcmp(&a, &b, sizeof a) == 0; }          \
/* bit for bit, or where the compiler may contract (see FMA_ULPS) within   */    \
/* ulps ulps of the scalar result, same sign                                */    \
static int within_##T(T a, T b, int ulps)                                        \
{                                                                                \
    int i;                                                                       \
    T lo = b, hi = b;                                                            \
    if (bits_##T(a, b)) return 1;                                                \
    if (a == 0 || b == 0) return 0;   /* +-0 only bit for bit (fast-math safe) */ \
    for (i = 0; i < ulps; ++i) { lo = NEXT(lo, -(T)INFINITY); hi = NEXT(hi, (T)INFINITY); } \
    return a >= lo && a <= hi && (a < 0) == (b < 0);                             \
}                                                                                \
static int same_##T(T a, T b) { return within_##T(a, b, FMA_ULPS); }             \
/* the Draine samplers' accuracy bar at a sample b of xi (x clamped):     */    \
/* 4 ulp(b) + 4 eps xi du/dxi, eps = ulp(1)/2 (tests/test_accuracy.c)      */    \
static double bar_##T(T g, T al, T x, T b)                                       \
{                                                                                \
    double xi = x > 0 ? (x < 1 ? (double)x : 1.0) : 0.0;                        \
    double du = 1 / (2 * 3.14159265358979323846 * mist_draine_eval(g, al, b));  \
    T ab = b < 0 ? -b : b;                                                       \
    return 4 * (double)(NEXT(ab, (T)INFINITY) - ab)                              \
           + 2 * (double)(NEXT((T)1, (T)2) - 1) * xi * du;                       \
}                                                                                \
/* same_T, or for the Draine samplers, where the compiler may contract,   */    \
/* within twice their bar (DR_BAR) of each other                            */    \
static int close_##T(int k, T g, T al, T x, T a, T b)                            \
{                                                                                \
    int ev = k == HG_EVAL || k == DR_EVAL || k == RL_EVAL || k == PD_EVAL || k == PF_EVAL \
             || k == FG_EVAL;                                                    \
    if (within_##T(a, b, ev ? EVAL_ULPS : FMA_ULPS)) return 1;                   \
    if (!DR_BAR || !(k == DR_SAMPLE || k == PD_SAMPLE || MIXK(k)) || x != x) return 0; \
    return fabs((double)a - (double)b) <= 2 * bar_##T(g, al, x, b);              \
}                                                                                 \
                                                                                  \
/* the prepared phase function of kind k at (g, a), kept while they stay  */   \
/* (preparing Draine costs ~129 samples)                                    */   \
static const CAT(mist_phase, S) *prep_##T(int k, T g, T a)                      \
{                                                                                 \
    static CAT(mist_phase, S) p;                                                  \
    static T pg, pa;                                                              \
    static int pk = -1;                                                           \
    if (pk != k || !bits_##T(pg, g) || !bits_##T(pa, a)) {                         \
        p = k == PH_SAMPLE ? CAT(mist_phase_hg, S)(g)                            \
          : k == PF_EVAL || k == PF_SAMPLE                                        \
            ? CAT(mist_phase_fog, S)(CAT(mist_fog_make, S)((T)FOG_GH, g, a, (T)FOG_W)) \
          : CAT(mist_phase_draine, S)(g, a);                                      \
        pk = k; pg = g; pa = a;                                                   \
    }                                                                             \
    return &p;                                                                    \
}                                                                                 \
                                                                                  \
/* the scalar function of kind k for a batch of n (the unprepared Draine  */   \
/* batch of n >= MIST_DRAINE_PREPARE_N is the prepared sampler's, but for  */   \
/* its eq. 6 kernel's media)                                                */   \
static T scalar_##T(int k, T g, T a, T x, int n)                                 \
{                                                                                 \
    if (k == DR_SAMPLE && n >= MIST_DRAINE_PREPARE_N                              \
        && !CAT(mist__draine_vn, S)(g, a, (size_t)n))                             \
        k = PD_SAMPLE;                                                            \
    switch (k) {                                                                  \
    case PD_EVAL: case PF_EVAL:                                                   \
                    return CAT(mist_phase_eval, S)(prep_##T(k, g, a), x);         \
    case PD_SAMPLE: case PH_SAMPLE: case PF_SAMPLE:                               \
                    return CAT(mist_phase_sample, S)(prep_##T(k, g, a), x);       \
    case FG_EVAL:   return CAT(mist_fog_eval, S)(CAT(mist_fog_make, S)((T)FOG_GH, g, a, \
                                                                    (T)FOG_W), x); \
    case FG_SAMPLE: return CAT(mist_fog_sample, S)(CAT(mist_fog_make, S)((T)FOG_GH, g, a, \
                                                                      (T)FOG_W), x); \
    case HG_EVAL:   return CAT(mist_hg_eval, S)(g, x);                            \
    case HG_SAMPLE: return CAT(mist_hg_sample, S)(g, x);                          \
    case DR_EVAL:   return CAT(mist_draine_eval, S)(g, a, x);                     \
    case DR_SAMPLE: return CAT(mist_draine_sample, S)(g, a, x);                   \
    case RL_EVAL:   return CAT(mist_rayleigh_eval, S)(x);                         \
    default:        return CAT(mist_rayleigh_sample, S)(x);                       \
    }                                                                             \
}                                                                                 \
                                                                                  \
static void batch_##T(int k, T g, T a, const T *in, T *out, size_t n)             \
{                                                                                 \
    switch (k) {                                                                  \
    case PD_EVAL: case PF_EVAL:                                                   \
                    CAT(mist_phase_eval_n, S)(prep_##T(k, g, a), in, out, n); break; \
    case PD_SAMPLE: case PH_SAMPLE: case PF_SAMPLE:                               \
        CAT(mist_phase_sample_n, S)(prep_##T(k, g, a), in, out, n); break;        \
    case FG_EVAL:                                                                 \
        CAT(mist_fog_eval_n, S)(CAT(mist_fog_make, S)((T)FOG_GH, g, a, (T)FOG_W), in, out, n); \
        break;                                                                    \
    case FG_SAMPLE:                                                               \
        CAT(mist_fog_sample_n, S)(CAT(mist_fog_make, S)((T)FOG_GH, g, a, (T)FOG_W), in, out, \
                                  n);                                             \
        break;                                                                    \
    case HG_EVAL:   CAT(mist_hg_eval_n, S)(g, in, out, n); break;                  \
    case HG_SAMPLE: CAT(mist_hg_sample_n, S)(g, in, out, n); break;                \
    case DR_EVAL:   CAT(mist_draine_eval_n, S)(g, a, in, out, n); break;           \
    case DR_SAMPLE: CAT(mist_draine_sample_n, S)(g, a, in, out, n); break;         \
    case RL_EVAL:   CAT(mist_rayleigh_eval_n, S)(in, out, n); break;               \
    default:        CAT(mist_rayleigh_sample_n, S)(in, out, n); break;             \
    }                                                                             \
}                                                                                 \
                                                                                  \
/* inputs for kind k: eval takes u, the samplers xi; specials first */            \
static void inputs_##T(int k, T g, mt_rng *r, T *x, int n)                        \
{                                                                                 \
    const T sp[] = { (T)NAN, (T)INFINITY, -(T)INFINITY, (T)0, -(T)0, (T)1, (T)-1,  \
                     NEXT((T)1, (T)2), NEXT((T)1, (T)0), NEXT((T)-1, (T)-2),        \
                     NEXT((T)-1, (T)0), (T)0.5, (T)-0.5, (T)1e-30, (T)-1e-30, g,   \
                     (T)1.5, (T)-0.25, (T)FOG_W, NEXT((T)FOG_W, (T)0),                \
                     NEXT((T)FOG_W, (T)1) };                                       \
    int i, ns = (int)(sizeof sp / sizeof sp[0]);                                  \
    int ev = k == HG_EVAL || k == DR_EVAL || k == RL_EVAL || k == PD_EVAL || k == PF_EVAL \
             || k == FG_EVAL;                                                    \
    for (i = 0; i < n; ++i) {                                                     \
        double v = mt_uniform(r);                                                 \
        if (i % 7 == 3) x[i] = sp[(i / 7) % ns];                                  \
        else x[i] = ev ? (T)(2.4 * v - 1.2) : (T)(1.2 * v - 0.1);                \
    }                                                                             \
}                                                                                 \
                                                                                  \
static void check_##T(int k, T g, T a, mt_rng *r)                                 \
{                                                                                 \
    static T in[NMAX + GUARD], out[NMAX + GUARD], ref[NMAX], xin[NMAX];           \
    size_t ni;                                                                    \
    for (ni = 0; ni < sizeof n_list / sizeof n_list[0]; ++ni) {                   \
        int n = n_list[ni], i, bad = -1;                                          \
        if (n > 100 && k != DR_SAMPLE && k != PD_SAMPLE && !MIXK(k) && mt_quick() > 1) \
            continue;                                                /* QUICK */  \
        inputs_##T(k, g, r, in, n);                                               \
        for (i = 0; i < n; ++i) ref[i] = scalar_##T(k, g, a, in[i], n);             \
        for (i = 0; i < n + GUARD; ++i) out[i] = (T)12345;                        \
        batch_##T(k, g, a, in, out, (size_t)n);                                   \
        for (i = 0; i < n; ++i) xin[i] = in[i];                                   \
        for (i = 0; i < n && bad < 0; ++i)                                        \
            if (!close_##T(k, g, a, xin[i], out[i], ref[i])) bad = i;              \
        mt_check(bad < 0, "%s%s g=%.9g a=%.9g n=%d: in[%d]=%.9g batch %.9g scalar %.9g", \
                 kind_name[k], #S, (double)g, (double)a, n, bad,                  \
                 bad < 0 ? 0. : (double)in[bad], bad < 0 ? 0. : (double)out[bad], \
                 bad < 0 ? 0. : (double)ref[bad]);                                \
        for (i = n, bad = -1; i < n + GUARD; ++i) bad = out[i] == (T)12345 ? bad : i; \
        mt_check(bad < 0, "%s%s n=%d: wrote past n", kind_name[k], #S, n);        \
        /* in place */                                                            \
        batch_##T(k, g, a, in, in, (size_t)n);                                    \
        for (i = 0, bad = -1; i < n && bad < 0; ++i)                              \
            if (!close_##T(k, g, a, xin[i], in[i], ref[i])) bad = i;               \
        mt_check(bad < 0, "%s%s g=%.9g a=%.9g n=%d: in place differs at %d",      \
                 kind_name[k], #S, (double)g, (double)a, n, bad);                 \
    }                                                                             \
    batch_##T(k, g, a, NULL, NULL, 0);          /* n = 0, NULL: nothing */       \
}                                                                                 \
                                                                                  \
/* A prepared Draine medium's start table (mist__phase_make): its nodes u  */   \
/* at xi = j/K are the scalar sampler's (mist__draine_sample with the      */   \
/* medium's F(0), as the table had them before the batch kernel built     */   \
/* them: mist__draine_vn media), bit for bit; 0 without a Draine lobe.     */   \
static int nodes_##T(T g, T a, int bad)                                          \
{                                                                                 \
    CAT(mist_phase, S) p = CAT(mist_phase_draine, S)(g, a);                       \
    T gs = CAT(mist__g, S)(g), as = a > 0 ? a : 0, c0, c1, u;                     \
    int j;                                                                        \
    CAT(mist__draine_c, S)(as, &c0, &c1);                                         \
    if (bad) p.tab[bad] = NEXT(p.tab[bad], (T)2);      /* the control */          \
    for (j = 0; j <= MIST__PHASE_K; ++j) {                                        \
        u = c1 != 0 && gs < 1 && gs > -1                                          \
          ? CAT(mist__draine_sample, S)(gs, as, c0, c1, (T)j / MIST__PHASE_K, p.f0, NULL) \
          : (T)0;                                                                 \
        if (!bits_##T(u, p.tab[j])) return 0;                                     \
    }                                                                             \
    return 1;                                                                     \
}                                                                                 \
                                                                                  \
/* The fog mixture at its lobes' edges, sampled (prepared: mist_phase_   */ \
/* sample_n; unprepared: mist_fog_sample_n) and evaluated (mist_phase_    */ \
/* eval_n, mist_fog_eval_n) against the scalar functions: xi = w and a few */ \
/* ulps either side (the lobe's pick, xi < w), w (1 - j eps), 0, -0, the   */ \
/* smallest values, 1 and below, each lobe's mirror edge (xi' = 1 - 1024   */ \
/* eps, where the scalar sampler takes the mirror image) and around it,    */ \
/* bad input, then random xi; lengths across the chunks of 1024.  cnt[]    */ \
/* counts the elements by their path (HG, Draine, mirror) as              */ \
/* mist__fog_pick sends them, so that the caller can require all three.   */ \
static int mix_##T(T gh, T gd, T a, T w, mt_rng *r, long cnt[3])                 \
{                                                                                 \
    static const int lens[] = { NMAX, 3, 33, 257, 1023, 1024, 1025 };             \
    static T in[NMAX], out[NMAX], ref[NMAX], x0[NMAX];                            \
    CAT(mist_fog, S) f = CAT(mist_fog_make, S)(gh, gd, a, w);                     \
    CAT(mist_phase, S) p = CAT(mist_phase_fog, S)(f);                             \
    T ws = f.w_d, e = (NEXT((T)1, (T)2) - 1) / 2, t, x, sg;                        \
    int i, j, n = 0, bad = 0, l, k;                                               \
    const T sp[] = { 0, -(T)0, (T)1e-45, (T)1e-300, 1, NEXT((T)1, (T)2), (T)NAN,  \
                     (T)INFINITY, -(T)INFINITY, -1, 2, (T)0.5 };                    \
    for (i = 0; i < (int)(sizeof sp / sizeof sp[0]); ++i) in[n++] = sp[i];        \
    for (t = ws, j = 0; j < 8; ++j, t = NEXT(t, (T)2)) in[n++] = t;              \
    for (t = ws, j = 0; j < 8; ++j) in[n++] = t = NEXT(t, (T)0);                 \
    for (j = 1; j < 8; ++j) in[n++] = ws * (1 - (T)j * e);                        \
    for (t = 1, j = 0; j < 8; ++j) in[n++] = t = NEXT(t, (T)0);                  \
    for (j = 1; j < 40; j += 3) { in[n++] = (T)ldexp(1, -j); in[n++] = ws * (T)ldexp(1, -j); } \
    for (l = 0; l < 2; ++l) {               /* the mirror edges, either side */  \
        T c = l ? ws + (1 - ws) * (1 - 1024 * e) : ws * (1 - 1024 * e);           \
        for (t = c, j = 0; j < 6; ++j) in[n++] = t = NEXT(t, (T)0);              \
        for (t = c, j = 0; j < 6; ++j, t = NEXT(t, (T)2)) in[n++] = t;           \
        for (j = 1; j < 5; ++j) in[n++] = c + (T)(j * 300) * e * (l ? 1 - ws : ws); \
        for (j = 1; j < 5; ++j) in[n++] = c - (T)(j * 300) * e * (l ? 1 - ws : ws); \
    }                                                                             \
    for (; n < NMAX; ++n) in[n] = n % 5 ? (T)mt_uniform(r) : (T)(1.2 * mt_uniform(r) - 0.1); \
    for (i = 0; i < NMAX; ++i) {                                                  \
        T xi = in[i] == in[i] ? (in[i] < 0 ? 0 : in[i] > 1 ? 1 : in[i]) : 0;     \
        int dr = CAT(mist__fog_pick, S)(xi, ws, &x, &sg);                         \
        if (ws > 0 && ws < 1) ++cnt[sg < 0 ? 2 : dr];                             \
    }                                                                             \
    for (k = 0; k < 4; ++k)                                                       \
        for (l = 0; l < (int)(sizeof lens / sizeof lens[0]); ++l) {               \
            int m = lens[l], kind = k == 0 ? PF_SAMPLE : k == 1 ? FG_SAMPLE : PF_EVAL; \
            for (i = 0; i < m; ++i) {                                             \
                x0[i] = k < 2 ? in[i] : 2 * in[i] - 1;       /* eval: u */         \
                ref[i] = k == 0 ? CAT(mist_phase_sample, S)(&p, x0[i])            \
                       : k == 1 ? CAT(mist_fog_sample, S)(f, x0[i])               \
                       : k == 2 ? CAT(mist_phase_eval, S)(&p, x0[i])              \
                       : CAT(mist_fog_eval, S)(f, x0[i]);                         \
                out[i] = x0[i];                                                   \
            }                                                                     \
            for (j = 0; j < 2; ++j) {              /* j = 1: in place */          \
                const T *src = j ? out : x0;                                      \
                if (k == 0) CAT(mist_phase_sample_n, S)(&p, src, out, (size_t)m); \
                if (k == 1) CAT(mist_fog_sample_n, S)(f, src, out, (size_t)m);    \
                if (k == 2) CAT(mist_phase_eval_n, S)(&p, src, out, (size_t)m);   \
                if (k == 3) CAT(mist_fog_eval_n, S)(f, src, out, (size_t)m);      \
                for (i = 0; i < m; ++i)                                           \
                    if (!close_##T(kind, gd, a, x0[i], out[i], ref[i])) {         \
                        if (!bad)                                                 \
                            printf("mix%s %d g_hg=%a g_d=%a alpha=%a w=%a n=%d%s: xi=%a " \
                                   "batch %a scalar %a\n", #S, k, (double)gh, (double)gd, \
                                   (double)a, (double)w, m, j ? " in place" : "",  \
                                   (double)x0[i], (double)out[i], (double)ref[i]); \
                        ++bad;                                                    \
                    }                                                             \
                for (i = 0; i < m; ++i) out[i] = x0[i];                           \
            }                                                                     \
        }                                                                         \
    /* the compact form of the same fog (mist_phasec_*): its density is    */ \
    /* mist_phase_eval's bit for bit, bad input too; its samples lie in     */ \
    /* [-1, 1] and take bad xi as the clamp does (NaN as 0)                 */ \
    {                                                                             \
        CAT(mist_phasec, S) c = CAT(mist_phasec_fog, S)(f);                       \
        for (i = 0; i < NMAX; ++i) {                                              \
            T u = 2 * in[i] - 1, xi = in[i], xc, us;                              \
            T e0 = CAT(mist_phase_eval, S)(&p, u), e1 = CAT(mist_phasec_eval, S)(&c, u); \
            xc = xi == xi ? (xi < 0 ? 0 : xi > 1 ? 1 : xi) : 0;                   \
            us = CAT(mist_phasec_sample, S)(&c, xi);                              \
            if (!bits_##T(e0, e1) || !(us >= -1 && us <= 1)                      \
                || !bits_##T(us, CAT(mist_phasec_sample, S)(&c, xc))) {          \
                if (!bad)                                                         \
                    printf("compact%s g_hg=%a g_d=%a alpha=%a w=%a: x=%a eval %a, " \
                           "prepared %a; sample %a\n", #S, (double)gh, (double)gd, \
                           (double)a, (double)w, (double)xi, (double)e1, (double)e0, \
                           (double)us);                                           \
                ++bad;                                                            \
            }                                                                     \
        }                                                                         \
    }                                                                             \
    return bad;                                                                   \
}

DEFINE_TYPE(double, , nextafter)
DEFINE_TYPE(float, f, nextafterf)

/* The height fog's batch form mist_hfog_apply_n (_nf): each ray as
 * mist_hfog_apply gives it (bit for bit; within FMA_ULPS where the
 * compiler may contract), for fogs its straight path takes and fogs it
 * does not (dimmed sun, a halved extinction, coefficients, density or
 * scale height out of its range, NULL, no fog; z up, an axis off the
 * coordinate axes, mie_prepared, a 3-channel mie_tab), rays over and beyond the
 * domain (level, nearly level, to infinity up and down, NaN and negative
 * lengths, zero and NaN directions, origins far below and above), lengths
 * 0 (NULL arrays), 1, 31, 32, 33, 100, in place (out = background), no
 * element past n written. */
#define HFOG_BATCH(T, S, V3, RGB, HF, PH, TAB)                                     \
static PH hfog_ph_##T;          /* kind 12's mie_prepared */                     \
static TAB *hfog_tab_##T;       /* kind 13's mie_tab: 3 channels */              \
static void hfog_tab_make_##T(void)                                              \
{                                                                                \
    static T mu[65], p[3 * 65];                                                  \
    size_t bytes = CAT(mist_tab_bytes, S)(65, 3);                                \
    int i, c;                                                                    \
    for (i = 0; i < 65; ++i) {                                                   \
        mu[i] = (T)(-1 + i / 32.0);                                              \
        for (c = 0; c < 3; ++c)     /* three lobes: the channels differ */      \
            p[3 * i + c] = (T)(0.05 + exp((2 + 3 * c) * (mu[i] - 1)));           \
    }                                                                            \
    mu[64] = 1;                                                                  \
    hfog_ph_##T = CAT(mist_phase_hg, S)((T)0.7);                                 \
    hfog_tab_##T = (TAB *)malloc(bytes);                                         \
    mt_check(hfog_tab_##T != NULL && CAT(mist_tab_init, S)(hfog_tab_##T, bytes, mu, p, 65, 3) == 0, \
             "a 3-channel table for the height fog's batch");                    \
}                                                                                \
static void hfog_fog_##T(HF *f, int kind)                                         \
{                                                                                \
    memset(f, 0, sizeof *f);                                                     \
    f->base = (T)12.5; f->density = (T)1.5; f->scale_height = (T)120;            \
    f->rayleigh_scat.r = (T)5.8e-6; f->rayleigh_scat.g = (T)1.35e-5;             \
    f->rayleigh_scat.b = (T)3.31e-5; f->rayleigh_ext = f->rayleigh_scat;         \
    f->mie_scat.r = f->mie_scat.g = f->mie_scat.b = (T)2e-3;                     \
    f->mie_ext.r = (T)2.2e-3; f->mie_ext.g = (T)2.3e-3; f->mie_ext.b = (T)2.5e-3; \
    f->mie_phase = CAT(mist_fog_make, S)((T)0.9, (T)0.5, 17, (T)0.4);           \
    f->sun_dir.x = (T)0.3; f->sun_dir.y = (T)0.5; f->sun_dir.z = (T)0.8;         \
    f->sun.r = 1; f->sun.g = (T)0.9; f->sun.b = (T)0.8;                          \
    f->ambient.r = (T)0.1; f->ambient.g = (T)0.12; f->ambient.b = (T)0.15;       \
    switch (kind) {                                                              \
    case 1: f->sun_extinction = 1; break;                                        \
    case 2: f->mie_ext.g = (T)INFINITY; break;          /* halved */             \
    case 3: f->sun.b = (T)1e-30; f->ambient.r = (T)NAN; break;                    \
    case 4: f->density = (T)1e30; f->mie_scat.r = 0; break;                      \
    case 5: f->scale_height = (T)INFINITY; break;                                \
    case 6: f->density = 0; break;                                               \
    case 7: f->rayleigh_ext.r = f->rayleigh_scat.r = f->mie_ext.r = f->mie_scat.r = 0; break; \
    case 8: f->scale_height = (T)1e-3; f->sun_dir.y = 0; break;                  \
    case 10: f->up.z = 1; break;                        /* z up */               \
    case 11: f->up.x = (T)0.3; f->up.y = (T)-1.6; f->up.z = (T)1.1; break;       \
    case 12: f->mie_prepared = &hfog_ph_##T; break;                              \
    case 13: f->mie_tab = hfog_tab_##T; f->up.z = -2; break;                     \
    default: break;                                                              \
    }                                                                            \
}                                                                                \
static void hfog_rays_##T(mt_rng *r, V3 *o, V3 *d, T *s, RGB *b, int n)          \
{                                                                                \
    int i;                                                                       \
    for (i = 0; i < n; ++i) {                                                    \
        double u = mt_uniform(r), z = 2 * mt_uniform(r) - 1, a = 6.283 * mt_uniform(r); \
        o[i].x = (T)(100 * u); o[i].y = (T)(-200 + 1000 * mt_uniform(r)); o[i].z = 0; \
        d[i].x = (T)(sqrt(1 - z * z) * cos(a)); d[i].y = (T)z;                   \
        d[i].z = (T)(sqrt(1 - z * z) * sin(a));                                  \
        s[i] = (T)pow(10, -2 + 5 * mt_uniform(r));                               \
        b[i].r = (T)mt_uniform(r); b[i].g = (T)(10 * mt_uniform(r)); b[i].b = 1; \
        switch (i % 23) {                                                        \
        case 1: d[i].y = 0; break;                                               \
        case 2: d[i].y = (T)1e-9; break;                                         \
        case 3: s[i] = (T)INFINITY; break;                                       \
        case 4: s[i] = (T)INFINITY; d[i].y = -d[i].y; break;                     \
        case 5: s[i] = (T)NAN; break;                                            \
        case 6: s[i] = -1; break;                                                \
        case 7: s[i] = 0; break;                                                 \
        case 8: d[i].x = d[i].y = d[i].z = 0; break;                             \
        case 9: d[i].y = (T)NAN; break;                                          \
        case 10: o[i].y = (T)-1e5; break;                                        \
        case 11: o[i].y = (T)1e6; break;                                         \
        case 12: o[i].y = (T)INFINITY; break;                                    \
        case 13: d[i].x *= 3; d[i].y *= 3; d[i].z *= 3; break;                   \
        case 14: s[i] = (T)1e30; break;                                          \
        default: break;                                                          \
        }                                                                        \
    }                                                                            \
}                                                                                \
static long hfog_check_##T(mt_rng *r, int kind, int n, int inplace, const HF *alt) \
{                                                                                \
    static V3 o[104], d[104];                                                    \
    static T s[104];                                                             \
    static RGB b[104], y[104], b0[104];                                          \
    HF f;                                                                        \
    long bad = 0;                                                                \
    int i;                                                                       \
    hfog_fog_##T(&f, kind);                                                      \
    hfog_rays_##T(r, o, d, s, b, n + 4);                                         \
    if (kind == 10)     /* z up: the rays' y and z swapped (the same edges) */  \
        for (i = 0; i < n + 4; ++i) {                                            \
            T t = o[i].y; o[i].y = o[i].z; o[i].z = t;                           \
            t = d[i].y; d[i].y = d[i].z; d[i].z = t;                             \
        }                                                                        \
    memcpy(b0, b, sizeof b);                                                     \
    for (i = 0; i < n + 4; ++i) { y[i].r = y[i].g = y[i].b = (T)-7; }            \
    if (n == 0)                                                                  \
        CAT(mist_hfog_apply_n, S)(kind == 9 ? NULL : &f, NULL, NULL, NULL, NULL, NULL, 0); \
    else if (inplace)                                                            \
        CAT(mist_hfog_apply_n, S)(kind == 9 ? NULL : &f, o, d, s, b, b, (size_t)n); \
    else                                                                         \
        CAT(mist_hfog_apply_n, S)(kind == 9 ? NULL : &f, o, d, s, b, y, (size_t)n); \
    for (i = 0; i < n + 4; ++i) {                                                \
        RGB want = CAT(mist_hfog_apply, S)(alt ? alt : kind == 9 ? NULL : &f, o[i], d[i], s[i], b0[i]); \
        RGB got = inplace ? b[i] : y[i];                                         \
        if (i >= n) bad += inplace ? memcmp(&b[i], &b0[i], sizeof b[i]) != 0     \
                                   : !(y[i].r == (T)-7 && y[i].g == (T)-7 && y[i].b == (T)-7); \
        else bad += !same_##T(got.r, want.r) + !same_##T(got.g, want.g) + !same_##T(got.b, want.b); \
    }                                                                            \
    return bad;                                                                  \
}
HFOG_BATCH(double, , mist_vec3, mist_rgb, mist_hfog, mist_phase, mist_tab)
HFOG_BATCH(float, f, mist_vec3f, mist_rgbf, mist_hfogf, mist_phasef, mist_tabf)

static void test_hfog_batch(mt_rng *r)
{
    static const int ns[] = { 0, 1, 31, 32, 33, 100 };
    long bad = 0, cases = 0;
    int kind, ni, ip;
    mist_hfog alt;
    mist_hfogf altf;
    hfog_tab_make_double();
    hfog_tab_make_float();
    for (kind = 0; kind < 14; ++kind)
        for (ni = 0; ni < 6; ++ni)
            for (ip = 0; ip < 2; ++ip) {
                bad += hfog_check_double(r, kind, ns[ni], ip, NULL)
                     + hfog_check_float(r, kind, ns[ni], ip, NULL);
                cases += 2;
            }
    mt_check(bad == 0, "mist_hfog_apply_n(f): %ld values of %ld calls not the scalar function's",
             bad, cases);
    /* control: against a fog denser by 2^-40 (float 2^-14), more than
     * FMA_ULPS moves the results, the comparison must see it */
    hfog_fog_double(&alt, 0);
    alt.density *= 1 + 0x1p-40;
    hfog_fog_float(&altf, 0);
    altf.density *= 1 + 0x1p-14f;
    mt_check(hfog_check_double(r, 0, 100, 0, &alt) > 0 && hfog_check_float(r, 0, 100, 0, &altf) > 0,
             "control: a fog denser by 2^-40 (float 2^-14) must differ");
    /* control: the axis and the phase pointers are seen (a batch that took
     * y up, or mie_phase, would differ) */
    hfog_fog_double(&alt, 0);
    hfog_fog_float(&altf, 0);
    mt_check(hfog_check_double(r, 10, 100, 0, &alt) > 0 && hfog_check_float(r, 11, 100, 0, &altf) > 0
             && hfog_check_double(r, 12, 100, 0, &alt) > 0 && hfog_check_float(r, 13, 100, 0, &altf) > 0,
             "control: the fog's up and Mie phase pointers must move the results");
    free(hfog_tab_double);
    free(hfog_tab_float);
}

int main(void)
{
    mt_rng r = { 20261126 };
    size_t gi, ai;
    int k;
    for (k = 0; k < NKIND; ++k)
        for (gi = 0; gi < sizeof g_list / sizeof g_list[0]; ++gi)
            for (ai = 0; ai < sizeof a_list / sizeof a_list[0]; ++ai) {
                double g = g_list[gi], a = a_list[ai];
                if ((k == RL_EVAL || k == RL_SAMPLE) && (gi > 0 || ai > 0)) continue;
                if ((k == HG_EVAL || k == HG_SAMPLE || k == PH_SAMPLE) && ai > 0) continue;
                check_double(k, g, a, &r);
                check_float(k, (float)g, (float)a, &r);
            }
    for (gi = 0; gi < sizeof g_list / sizeof g_list[0]; ++gi)
        for (ai = 0; ai < sizeof a_list / sizeof a_list[0]; ++ai) {
            double g = g_list[gi], a = a_list[ai];
            mt_check(nodes_double(g, a, 0) && nodes_float((float)g, (float)a, 0),
                     "prepared table nodes g=%g a=%g: the scalar sampler's (kernel: %d)", g, a,
                     mist__draine_vn(g, a, 129));
        }
    {   /* the fog mixture at its edges: random fogs, the d = 10 um fog
         * first, a lobe at the Dirac limit's edge (the mirror's case), tiny
         * and near-1 w, alpha 0, bad parameters */
        static const double fogs[][4] = {
            { 0.988, 0.556, 22, 0.482 }, { 0.9, -0.3, 250, 0.21 }, { -0.5, 0.999, 17, 0.7 },
            { 0.3, 0.5, 1e4, 1e-6 }, { 0.8, 0.8, 17, 0.4 }, { 0.6, -0.9, 3, 1 - 0x1p-20 },
            { -0x1.ffffffffffffep-1, 0.5, 1, 0x1.fffe7c730755bp-2 }, { 0.2, 0.7, 0, 0.5 },
            { 0.5, 0.9999, 1e9, 0.999999 }, { 0.95, 0.6, 1, 0x1p-30 }, { 0.1, 1e-4, 1e30, 0.5 },
            { NAN, 0.5, 17, 0.3 }, { 0.5, NAN, NAN, 0.6 }, { 0.3, 0.2, 17, 0 },
            { 0.3, 0.2, 17, 1 }, { 0.3, 0.2, 17, NAN }, { 1, -1, 17, 0.5 } };
        long cd[3] = { 0, 0, 0 }, cf[3] = { 0, 0, 0 }, c10[3] = { 0, 0, 0 };
        size_t i;
        int bd = 0, bf = 0;
        for (i = 0; i < sizeof fogs / sizeof fogs[0]; ++i) {
            const double *q = fogs[i];
            bd += mix_double(q[0], q[1], q[2], q[3], &r, i ? cd : c10);
            bf += mix_float((float)q[0], (float)q[1], (float)q[2], (float)q[3], &r, cf);
        }
        mt_check(bd == 0 && bf == 0, "fog mixture batches at the edges (and the compact "
                 "form's density, bad xi): %d double, %d float elements not the scalar "
                 "functions'", bd, bf);
        mt_check(c10[0] > 0 && c10[1] > 0 && c10[2] > 0 && cd[2] > 0 && cf[2] > 0,
                 "the edges reach every path: 10 um fog HG %ld, Draine %ld, mirror %ld; "
                 "mirror: double %ld, float %ld", c10[0], c10[1], c10[2], cd[2], cf[2]);
        /* control: the inputs at w tell the lobes apart (the sample jumps
         * between xi = w and its predecessor: a batch that picked the wrong
         * lobe there would differ) */
        {
            mist_phasef p = mist_phase_fogf(mist_fog_makef(0.988f, 0.556f, 22, 0.482f));
            float w = p.w, a = mist_phase_samplef(&p, w), b = mist_phase_samplef(&p,
                                                                             nextafterf(w, 0));
            mt_check(fabsf(a - b) > 0.5f, "control: the lobe's pick at w moves the sample "
                     "(%g, %g)", (double)a, (double)b);
        }
    }
    mt_check(!nodes_double(0.5, 17, 7) && !nodes_float(0.5f, 17, 7),
             "control: a node one ulp off must differ");
    /* a float Draine medium with |g| >= 0.999 samples as the unprepared
     * sampler (mist__phase_near1f: its table start misses there), so that
     * prepared, one at a time and in a batch, it gives mist_draine_samplef's
     * values (bit for bit but where the compiler may contract: close_float).
     * (Taking the table's start instead gives the same values at these 20
     * media too, both the root correctly rounded: two mutants that did so
     * passed; the routing is seen in ./build/mist_bench, "Batch forms".) */
    {
        static const float gs[] = { 0.999f, -0.999f, 0.9995f, 0.9999f, -0.99995f };
        static const float as[] = { 1, 17, 1e4f, 1e9f };
        static const float edge[] = { 0, 1, 1 - 0x1p-24f, 0x1p-30f };
        static float xs[4096], ys[4096];
        size_t i, j, l;
        long bad = 0, tot = 0;
        for (i = 0; i < sizeof gs / sizeof gs[0]; ++i)
            for (j = 0; j < sizeof as / sizeof as[0]; ++j) {
                mist_phasef p = mist_phase_drainef(gs[i], as[j]);
                for (l = 0; l < 4096; ++l)
                    xs[l] = l < 4 ? edge[l] : mt_uniformf(&r);
                mist_phase_sample_nf(&p, xs, ys, 4096);
                for (l = 0; l < 4096; ++l) {
                    float u = mist_draine_samplef(gs[i], as[j], xs[l]);
                    bad += !close_float(PD_SAMPLE, gs[i], as[j], xs[l], ys[l], u)
                         + !close_float(PD_SAMPLE, gs[i], as[j], xs[l],
                                        mist_phase_samplef(&p, xs[l]), u);
                    tot += 2;
                }
            }
        mt_check(bad == 0, "float Draine media at |g| >= 0.999: %ld of %ld prepared samples "
                 "not mist_draine_samplef's", bad, tot);
        mt_check(mist__phase_near1f(0.999f) && mist__phase_near1f(-0.999f)
                 && !mist__phase_near1f(nextafterf(0.999f, 0)),
                 "the unprepared sampler's range starts at |g| = 0.999");
    }
    test_hfog_batch(&r);
    /* negative controls: the comparison sees a change of one ulp more than
     * it allows (one ulp without FMA hardware), and the sign of 0 */
    {
        double d = 0.7;
        float f = 0.7f;
        int i;
        for (i = 0; i <= FMA_ULPS; ++i) { d = nextafter(d, 1); f = nextafterf(f, 1); }
        mt_check(!same_double(0.7, d) && !same_float(0.7f, f),
                 "control: a change of %d ulps must differ", FMA_ULPS + 1);
    }
    mt_check(!same_double(0.0, -0.0) && !same_float(0.0f, -0.0f),
             "control: -0 must differ from +0");
    mt_check(!close_double(HG_SAMPLE, 0.3, 0, 0.5, 0.5, 0.5 + 8 * DBL_EPSILON),
             "control: the HG samplers must be compared bit for bit");
    {   /* and the densities within EVAL_ULPS, not one more */
        double d = 0.7;
        int i;
        for (i = 0; i <= EVAL_ULPS; ++i) d = nextafter(d, 1);
        mt_check(!close_double(DR_EVAL, 0.3, 1, 0.5, d, 0.7),
                 "control: a density %d ulps off must differ", EVAL_ULPS + 1);
    }
    /* the Draine samplers' tolerance where it applies (twice the bar) must
     * see three times the bar, near u = 0 (alpha 1e4, xi 1/2: a bar of many
     * ulps) and away from it (xi 0.2) */
    {
        static const float xs[] = { 0.5f, 0.2f };
        size_t i;
        for (i = 0; i < sizeof xs / sizeof xs[0]; ++i) {
            float g = 1e-6f, al = 1e4f, b = mist_draine_samplef(g, al, xs[i]);
            double bar = bar_float(g, al, xs[i], b);
            float a = (float)(b + 3 * bar);
            mt_check(!close_float(DR_SAMPLE, g, al, xs[i], a, b) && close_float(DR_SAMPLE, g, al, xs[i], b, b),
                     "control: xi %g, u %g: the Draine tolerance must see 3x the bar (%g)",
                     (double)xs[i], (double)b, bar);
        }
    }
    return mt_done("test_batch");
}
