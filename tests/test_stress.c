/* test_stress.c - every public function of include/mist.h over its whole
 * documented domain and beyond, in double and float, against the
 * invariants of tests/mist_inv.h (finite output for finite input in the
 * domain, the Dirac limit at |g| = 1, samples in [-1, 1], unit directions,
 * pdf = density, the documented result of out-of-domain input, the height
 * fog's bounds):
 *   - edge grids: every combination of the edge values of each parameter
 *     (mi_specials: +-0, subnormals, each bound and one ulp inside and
 *     outside it, the library's internal thresholds, huge values, +-inf,
 *     NaN);
 *   - dense grids over the domain and beyond; the samplers are swept in
 *     increasing xi, checking they are monotone (documented: inverse CDFs),
 *     and the HG density in u (monotone for fixed g);
 *   - random draws (mi_gen: uniform in the domain, near the bounds, near 0
 *     down to the subnormals, log-uniform over the whole range, ulps
 *     around the bounds, edge values, raw bit patterns).
 * Every library call is counted; the count, the time and the largest
 * error seen per check are printed.
 *
 * ENVIRONMENT
 *   MIST_STRESS_CALLS=N  the number of library calls to aim for (default
 *                        9e7: 1.07e8 made, the 1e8 the suite wants from
 *                        this test alone; 8.9 s of CPU at -O3 (CMake
 *                        Release), gcc 12, an idle 2-core Intel Xeon
 *                        VM).  The edge grids always run in full
 *                        (about 1.3e7 calls); the dense grids and the random
 *                        draws scale with N (a dense grid capped by its
 *                        arrays owes the rest of its share to the random
 *                        draws after it, st_owe).  The long run:
 *                          MIST_STRESS_CALLS=1e10 build/test_stress
 *                        (~73 ns a call: about 12 minutes here; the last long
 *                        runs: README, "Stress and fuzzing").
 *   MIST_STRESS_SEED=S   the seed of the random draws (default fixed).
 *   MIST_STRESS_PRINT=N  print the first N failures (default 25).
 *   MIST_STRESS_ONLY=L   run only the families in the list L (any of dens,
 *                        samp, mix, dir, hfog, prep; for debugging: the call
 *                        count check is then off).
 *   MIST_STRESS_DUMP=D   write each random height fog case (mist_hfog_*,
 *                        layers, mist_segment_linear) that fails a check
 *                        to the directory D as a direct record of
 *                        fuzz/fuzz_hfog.c (files stress-<n>, at most 200):
 *                        replay_hfog D reruns them, and they go to the kept
 *                        corpus fuzz/corpus/hfog/ once fixed.
 *
 * Under -ffast-math (no NaN, no infinity, subnormals flushed to zero) the
 * generators give finite normal input only and the tolerances widen
 * (MI_FAST in tests/mist_inv.h); -DMI_ALL_INPUTS runs everything anyway. */
#ifndef ST_TEMPLATE

#include "mist_inv.h"
#include "mist_test.h"

#include <time.h>

static double st_target = 9e7;             /* calls to aim for */
static const char *st_only;                /* MIST_STRESS_ONLY */

/* the section family is wanted (MIST_STRESS_ONLY unset, or lists it) */
static int st_want(const char *fam) { return !st_only || strstr(st_only, fam) != NULL; }
static mi_rng st_rng;
static mi_src st_src;

/* MIST_STRESS_DUMP: the failing height fog cases as fuzz_hfog records */
static const char *st_dump_dir;
static int st_dumped;
static unsigned char st_rec[4096];
static size_t st_nrec;
static void st_put(const void *p, size_t n)
{
    size_t i;
    for (i = 0; i < n; ++i, ++st_nrec)
        if (st_nrec < sizeof st_rec) st_rec[st_nrec] = ((const unsigned char *)p)[i];
}
/* writes st_rec when checks failed since `fails0` */
static void st_dump(unsigned long long fails0)
{
    char path[1024];
    FILE *fh;
    if (!st_dump_dir || mi_fails == fails0 || st_dumped >= 200 || st_nrec > sizeof st_rec) return;
    snprintf(path, sizeof path, "%s/stress-%03d", st_dump_dir, st_dumped++);
    fh = fopen(path, "wb");
    if (!fh) { printf("MIST_STRESS_DUMP: cannot write %s\n", path); return; }
    fwrite(st_rec, 1, st_nrec, fh);
    fclose(fh);
    printf("  (the case above: %s)\n", path);
}

/* ------------------------------------------------------------------------ */
/* Sections: each checks that none of its checks failed, and reports its    */
/* calls and time.                                                          */
/* ------------------------------------------------------------------------ */

static unsigned long long st_calls0, st_fails0;
static clock_t st_clock0;
static double st_secs_total;

static void st_begin(void)
{
    st_calls0 = mi_calls;
    st_fails0 = mi_fails;
    st_clock0 = clock();
}

static void st_end(const char *name)
{
    double s = (double)(clock() - st_clock0) / CLOCKS_PER_SEC;
    unsigned long long n = mi_calls - st_calls0, f = mi_fails - st_fails0;
    st_secs_total += s;
    printf("  %-42s %11llu calls %6.2f s %6.1f ns/call\n", name, n, s, n ? 1e9 * s / (double)n : 0);
    fflush(stdout);
    mt_check(f == 0, "%s: %llu failed checks", name, f);
}

/* calls for a share of the budget (the share of all sections sum to 1) */
static unsigned long long st_share(double share) { return (unsigned long long)(st_target * share); }

/* A dense grid's sizes are capped (its arrays), so at a large budget it
 * makes fewer calls than its share: st_owe notes the rest, which the next
 * random part makes (the budget is met at any MIST_STRESS_CALLS). */
static unsigned long long st_deficit;
static void st_owe(double share)
{
    unsigned long long want = st_share(share), made = mi_calls - st_calls0;
    if (made < want) st_deficit += want - made;
}

/* the random part of a section: until its share of calls (and what the
 * grids before it owe) is made */
#define ST_UNTIL(share) \
    for (st_stop = mi_calls + st_share(share) + st_deficit, st_deficit = 0; mi_calls < st_stop;)
static unsigned long long st_stop;

/* the double pass, then the float pass */
#define ST_TEMPLATE 1
#define ST_T      double
#define ST_F(n)   n##_d
#define ST_V3     mist_vec3
#define ST_FOG    mist_fog
#define ST_RGB    mist_rgb
#define ST_HFOG   mist_hfog
#define ST_EPS    DBL_EPSILON
#define ST_MANT   53
#define ST_EMIN   (-1074)
#define ST_EMAX   1024
#define ST_NAME   "double"
#define ST_NEXT   nextafter
#define ST_INF    MI_INF_D
#include "test_stress.c"
#undef ST_T
#undef ST_F
#undef ST_V3
#undef ST_FOG
#undef ST_RGB
#undef ST_HFOG
#undef ST_EPS
#undef ST_MANT
#undef ST_EMIN
#undef ST_EMAX
#undef ST_NAME
#undef ST_NEXT
#undef ST_INF

#define ST_T      float
#define ST_F(n)   n##_f
#define ST_V3     mist_vec3f
#define ST_FOG    mist_fogf
#define ST_RGB    mist_rgbf
#define ST_HFOG   mist_hfogf
#define ST_EPS    FLT_EPSILON
#define ST_MANT   24
#define ST_EMIN   (-149)
#define ST_EMAX   128
#define ST_NAME   "float"
#define ST_NEXT   nextafterf
#define ST_INF    MI_INF_F
#include "test_stress.c"
#undef ST_TEMPLATE

int main(void)
{
    const char *e = getenv("MIST_STRESS_CALLS");
    clock_t t0 = clock();
    int ti, k;
    if (e && *e) {
        char *end;
        double v = strtod(e, &end);
        if (end == e || !(v >= 1e4 && v <= 1e13)) {
            printf("MIST_STRESS_CALLS=%s: want a number in [1e4, 1e13]\n", e);
            return 2;
        }
        st_target = v;
    }
    st_only = getenv("MIST_STRESS_ONLY");
    if (st_only && !*st_only) st_only = NULL;
    e = getenv("MIST_STRESS_PRINT");
    if (e && *e) mi_print_max = strtoull(e, NULL, 0);
    st_dump_dir = getenv("MIST_STRESS_DUMP");
    if (st_dump_dir && !*st_dump_dir) st_dump_dir = NULL;
    e = getenv("MIST_STRESS_SEED");
    st_rng.s = e && *e ? strtoull(e, NULL, 0) : 0x5EED0F0651ULL;
    st_src.rng = &st_rng;
    st_src.bytes = NULL;
    printf("test_stress: aiming at %.3g library calls (MIST_STRESS_CALLS), seed %#llx%s\n",
           st_target, (unsigned long long)st_rng.s,
           MI_FAST ? "; -ffast-math: the finite, normal-range subset" : "");
    run_d();
    run_f();
    printf("largest errors seen, in eps of the type (double, float):\n");
    for (k = 0; k < MI_NW; ++k) {
        printf("  %-52s", mi_worst_name[k]);
        for (ti = 0; ti < 2; ++ti) printf(" %9.3g", mi_worst[ti][k]);
        printf("\n");
    }
    printf("test_stress: %llu library calls in %.1f s (%.1f ns per call with its checks)\n",
           mi_calls, (double)(clock() - t0) / CLOCKS_PER_SEC,
           1e9 * st_secs_total / (double)(mi_calls ? mi_calls : 1));
    /* the grids are sized from the budget, not counted into it exactly */
    mt_check(st_only || mi_calls >= 0.8 * st_target, "made %llu calls, fewer than the %.3g aimed at",
             mi_calls, st_target);
    mt_check(mi_fails == 0, "%llu failed checks in all", mi_fails);
    return mt_done("test_stress");
}

#else /* ST_TEMPLATE: the sections, once per type ------------------------- */

static int ST_F(st_cmp)(const void *a, const void *b)
{
    ST_T x = *(const ST_T *)a, y = *(const ST_T *)b;
    return x < y ? -1 : (x > y ? 1 : 0);
}

/* A dense sorted grid of about n values of a kind, NaN-free: uniform over
 * the domain widened by 1/16 on each side, clusters on both sides of each
 * bound and threshold (mi_points: b +- 2^-k, k = 1 .. mantissa + 2) and
 * at 0 (+-2^-k down to the subnormals), and the edge values. */
static int ST_F(st_grid)(int kind, int n, ST_T *out, int cap)
{
    ST_T lo, hi, sp[160], pts[8], x;
    int m = 0, k, i, j, ns = ST_F(mi_specials)(kind, sp), np = ST_F(mi_points)(kind, pts);
    int nu, nb, nz;
    if (n > (cap - ns) * 4 / 5) n = (cap - ns) * 4 / 5;   /* at most 5n/4 + ns values */
    nu = n / 2; nb = n / (4 * np); nz = n / 8;
    ST_F(mi_domain)(kind, &lo, &hi);
    for (k = 0; k < nu; ++k)
        out[m++] = (ST_T)(lo - (hi - lo) / 16 + (hi - lo) * 1.125 * k / (nu - 1));
    for (j = 0; j < np; ++j)
        for (k = 0; k < nb; ++k) {
            double t = (double)(ST_MANT + 2) * k / nb + 1;    /* 2^-t, t in [1, mant+3) */
            double d = ldexp(1, -(int)t) * (2 - (t - (int)t));
            out[m++] = (ST_T)(pts[j] - d * (pts[j] == 0 ? 1 : fabs((double)pts[j])));
            out[m++] = (ST_T)(pts[j] + d * (pts[j] == 0 ? 1 : fabs((double)pts[j])));
        }
    for (k = 0; k < nz; ++k) {
        double t = (double)(-ST_EMIN) * k / nz + 1;
        out[m++] = (ST_T)ldexp(1, -(int)t);
        out[m++] = -(ST_T)ldexp(1, -(int)t);
    }
    for (k = 0; k < ns; ++k) out[m++] = sp[k];
    for (i = k = 0; k < m; ++k) {          /* NaN-free (under fast-math: mi_fast_ok) */
        x = out[k];
        if (ST_F(mi_nan)(x)) continue;
#if MI_FAST
        if (!ST_F(mi_fast_ok_kind)(kind, x)) continue;
#endif
        out[i++] = x;
    }
    m = i;
    qsort(out, (size_t)m, sizeof *out, ST_F(st_cmp));
    for (i = k = 0; k < m; ++k)
        if (i == 0 || out[k] != out[i - 1]) out[i++] = out[k];
    return i;
}

/* xi and a nearby xi2 (xi +- 2^-k, or the next float): for the pairwise
 * monotonicity check of the random draws */
static ST_T ST_F(st_near)(ST_T xi)
{
    uint64_t r = mi_src_next(&st_src);
    int k = (int)(r % (ST_MANT + 4));
    if (r & 64) return ST_F(mi_nan)(xi) ? xi : (ST_T)(xi + ((r >> 7) & 1 ? 1 : -1) * ldexp(1, -k));
    return ST_NEXT(xi, (r >> 7) & 1 ? (ST_T)2 : (ST_T)-2);
}

/* u1 = sampler(xi1), u2 = sampler(xi2): in the order of xi */
static void ST_F(st_order)(const char *fn, ST_T g, ST_T a, ST_T x1, ST_T u1, ST_T x2, ST_T u2)
{
    if (ST_F(mi_nan)(x1) || ST_F(mi_nan)(x2)) return;
    if ((x1 < x2 && u1 > u2) || (x2 < x1 && u2 > u1))
        mi_fail("%s(g=%a, alpha=%a) not monotone in xi: xi %a -> %a, xi %a -> %a", fn,
                (double)g, (double)a, (double)x1, (double)u1, (double)x2, (double)u2);
}

/* ------------------------------------------------------------------------ */
/* Densities                                                                */
/* ------------------------------------------------------------------------ */

static void ST_F(st_evals)(double share)
{
    static ST_T gs[160], as[160], us[160], G[1 << 14], U[1 << 14], A[64];
    int ng = ST_F(mi_specials)(MI_G, gs), na = ST_F(mi_specials)(MI_ALPHA, as);
    int nu = ST_F(mi_specials)(MI_U, us), i, j, k, n, nG, nU, nA;
    unsigned long long grid_calls;
    /* edge grid */
    st_begin();
    for (i = 0; i < ng; ++i)
        for (k = 0; k < nu; ++k) {
            ST_F(mi_hg_eval)(gs[i], us[k]);
            ST_F(mi_cs_eval)(gs[i], us[k]);
            for (j = 0; j < na; ++j) ST_F(mi_draine_eval)(gs[i], as[j], us[k]);
        }
    for (k = 0; k < nu; ++k) ST_F(mi_rayleigh_eval)(us[k]);
    st_end(ST_NAME " densities: edge grid");
    /* dense grid, a third of the share: g x u, HG monotone in u */
    st_begin();
    grid_calls = st_share(share / 3);
    n = (int)sqrt((double)grid_calls / 6);
    n = n < 64 ? 64 : (n > 5000 ? 5000 : n);
    nG = ST_F(st_grid)(MI_G, n, G, (int)(sizeof G / sizeof *G));
    nU = ST_F(st_grid)(MI_U, n, U, (int)(sizeof U / sizeof *U));
    nA = 0;
    for (k = 0; k < 24; ++k) A[nA++] = (ST_T)(k == 0 ? 0 : ldexp(1, 3 * k - 36));
    A[nA++] = 250; A[nA++] = 1;
    for (i = 0; i < nG; ++i) {
        ST_T prev = -1, p;
        for (k = 0; k < nU; ++k) {
            p = ST_F(mi_hg_eval)(G[i], U[k]);
            /* monotone in u: increasing for g > 0, decreasing for g < 0 */
            if (G[i] > -1 && G[i] < 1 && prev >= 0
                && (G[i] > 0 ? p < prev : (G[i] < 0 ? p > prev : p != prev)))
                mi_fail("mist_hg_eval(g=%a, u) not monotone in u at u=%a: %a after %a",
                        (double)G[i], (double)U[k], (double)p, (double)prev);
            prev = p;
            if ((k & 3) == 0) ST_F(mi_cs_eval)(G[i], U[k]);
            ST_F(mi_draine_eval)(G[i], A[(i + k) % nA], U[k]);
        }
    }
    for (k = 0; k < nU; ++k) ST_F(mi_rayleigh_eval)(U[k]);
    st_owe(share / 3);
    st_end(ST_NAME " densities: dense grid");
    /* random draws */
    st_begin();
    ST_UNTIL(share * 2 / 3) {
        ST_T g = ST_F(mi_draw)(&st_src, MI_G), u = ST_F(mi_draw)(&st_src, MI_U);
        ST_T a = ST_F(mi_draw)(&st_src, MI_ALPHA);
        ST_F(mi_hg_eval)(g, u);
        ST_F(mi_draine_eval)(g, a, u);
        ST_F(mi_draine_eval)(g, a, ST_F(mi_draw)(&st_src, MI_U));
        ST_F(mi_cs_eval)(g, u);
        ST_F(mi_rayleigh_eval)(u);
    }
    st_end(ST_NAME " densities: random");
}

/* ------------------------------------------------------------------------ */
/* Samplers                                                                 */
/* ------------------------------------------------------------------------ */

/* u(xi) over the sorted xi grid X: monotone (ties allowed) */
#define ST_SWEEP(name, call, gv, av)                                                  \
    do {                                                                              \
        ST_T prev_ = -2, u_;                                                          \
        for (k = 0; k < nX; ++k) {                                                    \
            u_ = call;                                                                \
            if (u_ < prev_)                                                           \
                mi_fail("%s(g=%a, alpha=%a) not monotone in xi at xi=%a: %a after %a", \
                        name, (double)(gv), (double)(av), (double)X[k], (double)u_,   \
                        (double)prev_);                                               \
            prev_ = u_;                                                               \
        }                                                                             \
    } while (0)

static void ST_F(st_samples)(double s_hg, double s_dr, double s_ray)
{
    static ST_T gs[160], as[160], xs[160], G[1 << 14], X[1 << 14], A[64];
    int ng = ST_F(mi_specials)(MI_G, gs), na = ST_F(mi_specials)(MI_ALPHA, as);
    int nx = ST_F(mi_specials)(MI_XI, xs), i, j, k, n, nG, nX, nA;
    /* edge grid */
    st_begin();
    for (i = 0; i < ng; ++i)
        for (k = 0; k < nx; ++k) {
            ST_F(mi_hg_sample)(gs[i], xs[k]);
            ST_F(mi_cs_sample)(gs[i], xs[k]);
            for (j = 0; j < na; ++j) ST_F(mi_draine_sample)(gs[i], as[j], xs[k]);
        }
    for (k = 0; k < nx; ++k) ST_F(mi_rayleigh_sample)(xs[k]);
    st_end(ST_NAME " samplers: edge grid");
    /* monotone sweeps in xi, half of each share */
    st_begin();
    n = (int)sqrt((double)st_share(s_hg / 2));
    n = n < 64 ? 64 : (n > 8000 ? 8000 : n);
    nG = ST_F(st_grid)(MI_G, n, G, (int)(sizeof G / sizeof *G));
    nX = ST_F(st_grid)(MI_XI, n, X, (int)(sizeof X / sizeof *X));
    for (i = 0; i < nG; ++i) ST_SWEEP("mist_hg_sample", ST_F(mi_hg_sample)(G[i], X[k]), G[i], 0);
    ST_SWEEP("mist_rayleigh_sample", ST_F(mi_rayleigh_sample)(X[k]), 0, 0);
    st_owe(s_hg / 2);
    st_end(ST_NAME " mist_hg_sample: monotone sweeps");
    st_begin();
    nA = 0;
    for (k = 0; k < 16; ++k) A[nA++] = (ST_T)(k == 0 ? 0 : ldexp(1, 4 * k - 28));
    A[nA++] = 250; A[nA++] = 1; A[nA++] = (ST_T)1e-6; A[nA++] = (ST_T)1e4;
    A[nA++] = (ST_T)1e30; A[nA++] = ST_F(mi_from_bits)(ST_F(mi_bits)((ST_T)1e30) + 1);
#if !MI_FAST
    A[nA++] = ST_INF;
#endif
    n = (int)sqrt((double)st_share(s_dr / 2) / 1.5);
    n = n < 32 ? 32 : (n > 8000 ? 8000 : n);
    nG = ST_F(st_grid)(MI_G, n, G, (int)(sizeof G / sizeof *G));
    nX = ST_F(st_grid)(MI_XI, n, X, (int)(sizeof X / sizeof *X));
    for (i = 0; i < nG; ++i) {
        ST_T a = A[i % nA];
        ST_SWEEP("mist_draine_sample", ST_F(mi_draine_sample)(G[i], a, X[k]), G[i], a);
        if (i % 16 == 0) ST_SWEEP("mist_cs_sample", ST_F(mi_cs_sample)(G[i], X[k]), G[i], 1);
    }
    /* every alpha at the g of the edge grid, on a coarser xi grid */
    nX = ST_F(st_grid)(MI_XI, n / 4 > 32 ? n / 4 : 32, X, (int)(sizeof X / sizeof *X));
    for (i = 0; i < ng; ++i)
        for (j = 0; j < nA; ++j)
            ST_SWEEP("mist_draine_sample", ST_F(mi_draine_sample)(gs[i], A[j], X[k]), gs[i], A[j]);
    st_owe(s_dr / 2);
    st_end(ST_NAME " mist_draine_sample: monotone sweeps");
    /* random draws, each with a nearby xi: monotone in pairs */
    st_begin();
    ST_UNTIL(s_hg / 2) {
        ST_T g = ST_F(mi_draw)(&st_src, MI_G), x1 = ST_F(mi_draw)(&st_src, MI_XI);
        ST_T x2 = ST_F(st_near)(x1);
        ST_F(st_order)("mist_hg_sample", g, 0, x1, ST_F(mi_hg_sample)(g, x1),
                       x2, ST_F(mi_hg_sample)(g, x2));
    }
    st_end(ST_NAME " mist_hg_sample: random");
    st_begin();
    ST_UNTIL(s_ray) {
        ST_T x1 = ST_F(mi_draw)(&st_src, MI_XI), x2 = ST_F(st_near)(x1);
        ST_F(st_order)("mist_rayleigh_sample", 0, 0, x1, ST_F(mi_rayleigh_sample)(x1),
                       x2, ST_F(mi_rayleigh_sample)(x2));
    }
    st_end(ST_NAME " mist_rayleigh_sample: random");
    st_begin();
    ST_UNTIL(s_dr / 2) {
        ST_T g = ST_F(mi_draw)(&st_src, MI_G), x1 = ST_F(mi_draw)(&st_src, MI_XI);
        ST_T a = ST_F(mi_draw)(&st_src, MI_ALPHA), x2 = ST_F(st_near)(x1);
        ST_F(st_order)("mist_draine_sample", g, a, x1, ST_F(mi_draine_sample)(g, a, x1),
                       x2, ST_F(mi_draine_sample)(g, a, x2));
        if ((st_rng.s & 15) == 0)
            ST_F(st_order)("mist_cs_sample", g, 1, x1, ST_F(mi_cs_sample)(g, x1),
                           x2, ST_F(mi_cs_sample)(g, x2));
    }
    st_end(ST_NAME " mist_draine/cs_sample: random");
}

/* ------------------------------------------------------------------------ */
/* The fog mixture and its fits                                             */
/* ------------------------------------------------------------------------ */

static ST_FOG ST_F(st_draw_fog)(void)
{
    ST_FOG f;
    uint64_t m = mi_src_next(&st_src);
    f.g_hg = ST_F(mi_draw)(&st_src, MI_G);
    f.g_d = ST_F(mi_draw)(&st_src, MI_G);
    f.alpha = ST_F(mi_draw)(&st_src, MI_ALPHA);
    f.w_d = ST_F(mi_draw)(&st_src, MI_WD);
    if (m % 3 == 0) return ST_F(mi_fog_make)(f.g_hg, f.g_d, f.alpha, f.w_d);
    if (m % 3 == 1) return ST_F(mi_fog_from_diameter)(ST_F(mi_draw)(&st_src, MI_DIAM));
    return f;                                        /* hand-filled */
}

static void ST_F(st_fog)(double share)
{
    static ST_T ds[160], D[1 << 16], ws[160], us[160];
    int nd = ST_F(mi_specials)(MI_DIAM, ds), nw = ST_F(mi_specials)(MI_WD, ws);
    int nu = ST_F(mi_specials)(MI_U, us), i, k, n;
    ST_FOG f;
    /* edge grid: the fits at every edge diameter, mixtures at every edge
     * weight, densities and samples at every edge u and xi */
    st_begin();
    for (i = 0; i < nd; ++i) {
        f = ST_F(mi_fog_from_diameter)(ds[i]);
        for (k = 0; k < nw; ++k) {
            f.w_d = ws[k];
            ST_F(mi_fog_eval)(f, us[(i + k) % nu]);
            ST_F(mi_fog_sample)(f, ws[(i + 3 * k) % nw]);
        }
    }
    st_end(ST_NAME " fog: edge grid");
    /* the fits over a dense grid of d, and their densities at the peaks */
    st_begin();
    n = (int)(st_share(share / 4) / 6);
    n = n < 1000 ? 1000 : n;
    n = ST_F(st_grid)(MI_DIAM, n, D, (int)(sizeof D / sizeof *D));
    for (i = 0; i < n; ++i) {
        f = ST_F(mi_fog_from_diameter)(D[i]);
        ST_F(mi_fog_eval)(f, 1);
        ST_F(mi_fog_sample)(f, D[(i * 7919) % n] / 50);
    }
    st_owe(share / 4);
    st_end(ST_NAME " mist_fog_from_diameter: dense grid");
    st_begin();
    ST_UNTIL(share * 3 / 4) {
        f = ST_F(st_draw_fog)();
        ST_F(mi_fog_eval)(f, ST_F(mi_draw)(&st_src, MI_U));
        ST_F(mi_fog_sample)(f, ST_F(mi_draw)(&st_src, MI_XI));
        if ((st_rng.s & 7) == 0) ST_F(mi_fog_from_diameter)(ST_F(mi_draw)(&st_src, MI_DIAM));
    }
    st_end(ST_NAME " fog: random");
}

/* ------------------------------------------------------------------------ */
/* Directions                                                               */
/* ------------------------------------------------------------------------ */

static void ST_F(st_dirs)(double s_dir, double s_sdir)
{
    static ST_T cs[160], us[160], xs[160];
    int nc = ST_F(mi_specials)(MI_COMP, cs), nu = ST_F(mi_specials)(MI_U, us);
    int nx = ST_F(mi_specials)(MI_XI, xs), i, j, k;
    ST_V3 v;
    /* edge grid: every vector of edge components, every edge u and xi */
    st_begin();
    for (i = 0; i < nc; ++i)
        for (j = 0; j < nc; ++j)
            for (k = 0; k < nc; ++k) {
                v.x = cs[i]; v.y = cs[j]; v.z = cs[k];
                ST_F(mi_normalize)(v);
                ST_F(mi_dir_from_cos)(v, us[(i + j + k) % nu], xs[(i * 3 + k) % nx]);
            }
    v.x = 0; v.y = (ST_T)0.6; v.z = (ST_T)0.8;
    for (i = 0; i < nu; ++i)
        for (k = 0; k < nx; ++k) ST_F(mi_dir_from_cos)(v, us[i], xs[k]);
    st_end(ST_NAME " directions: edge grid");
    st_begin();
    ST_UNTIL(s_dir) {
        v = ST_F(mi_draw_dir)(&st_src);
        ST_F(mi_normalize)(v);
        ST_F(mi_dir_from_cos)(v, ST_F(mi_draw)(&st_src, MI_U), ST_F(mi_draw)(&st_src, MI_XI));
    }
    st_end(ST_NAME " mist_normalize, mist_dir_from_cos");
    st_begin();
    ST_UNTIL(s_sdir) {
        ST_T g = ST_F(mi_draw)(&st_src, MI_G), x1 = ST_F(mi_draw)(&st_src, MI_XI);
        ST_T x2 = ST_F(mi_draw)(&st_src, MI_XI);
        uint64_t m = mi_src_next(&st_src);
        v = ST_F(mi_draw_dir)(&st_src);
        switch ((int)(m % 8)) {
        case 0: case 1: case 2: ST_F(mi_hg_sample_dir)(g, v, x1, x2); break;
        case 3: ST_F(mi_cs_sample_dir)(g, v, x1, x2); break;
        case 4: ST_F(mi_draine_sample_dir)(g, ST_F(mi_draw)(&st_src, MI_ALPHA), v, x1, x2); break;
        case 5: case 6: ST_F(mi_rayleigh_sample_dir)(v, x1, x2); break;
        default: ST_F(mi_fog_sample_dir)(ST_F(st_draw_fog)(), v, x1, x2); break;
        }
    }
    st_end(ST_NAME " *_sample_dir");
}

/* ------------------------------------------------------------------------ */
/* Prepared phase functions and batch forms                                 */
/* ------------------------------------------------------------------------ */

static void ST_F(st_prepared)(double s_prep, double s_batch)
{
    static ST_T gs[160], as[160], us[160], xs[160];
    int ng = ST_F(mi_specials)(MI_G, gs), na = ST_F(mi_specials)(MI_ALPHA, as);
    int nu = ST_F(mi_specials)(MI_U, us), nx = ST_F(mi_specials)(MI_XI, xs), i, j, k;
    ST_V3 wi;
    ST_FOG f;
    wi.x = 0; wi.y = (ST_T)0.6; wi.z = (ST_T)0.8;
    /* edge grid: every kind at every edge g (Draine: with every edge alpha,
     * a prepared Draine costs ~33 samples), each at every edge u and xi */
    st_begin();
    f = ST_F(mi_fog_make)((ST_T)0.9, (ST_T)0.5, 250, (ST_T)0.3);
    for (k = 3; k < 6; ++k) ST_F(mi_phase)(k, 0, 0, f, us, xs, nu < nx ? nu : nx, wi, (ST_T)0.3);
    for (i = 0; i < ng; ++i) {
        ST_F(mi_phase)(0, gs[i], 0, f, us, xs, nu < nx ? nu : nx, wi, (ST_T)0.3);
        ST_F(mi_phase)(2, gs[i], 0, f, us, xs, nu < nx ? nu : nx, wi, (ST_T)0.7);
        for (j = 0; j < na; j += 3)
            ST_F(mi_phase)(1, gs[i], as[(j + i) % na], f, us, xs, 8, wi, (ST_T)0.1);
        f.g_hg = gs[i]; f.g_d = gs[(i * 7 + 3) % ng]; f.alpha = as[i % na];
        f.w_d = (ST_T)((i % 5) / 4.0);
        ST_F(mi_phase)(4, 0, 0, f, us + i % 8, xs + i % 8, 8, wi, (ST_T)0.9);
    }
    for (i = 0; i < ng; ++i)
        for (j = 0; j < na; ++j) ST_F(mi_batch)(gs[i], as[j], us, nu < 80 ? nu : 80);
    st_end(ST_NAME " mist_phase_*, mist_*_n: edge grid");
    /* random: a prepared phase function of a random kind and parameters,
     * 16 draws of u and xi with it */
    st_begin();
    ST_UNTIL(s_prep) {
        ST_T u[16], x[16], g = ST_F(mi_draw)(&st_src, MI_G), a = ST_F(mi_draw)(&st_src, MI_ALPHA);
        int kind = (int)(mi_src_next(&st_src) % 6);
        for (k = 0; k < 16; ++k) {
            u[k] = ST_F(mi_draw)(&st_src, MI_U);
            x[k] = ST_F(mi_draw)(&st_src, MI_XI);
        }
        f = ST_F(st_draw_fog)();
        ST_F(mi_phase)(kind, g, a, f, u, x, 16, ST_F(mi_draw_dir)(&st_src),
                       ST_F(mi_draw)(&st_src, MI_XI));
    }
    st_end(ST_NAME " mist_phase_*: random");
    /* random: batches of 1 to 80 elements (the blocks are 32), drawn as u
     * and as xi */
    st_begin();
    ST_UNTIL(s_batch) {
        ST_T in[80], g = ST_F(mi_draw)(&st_src, MI_G), a = ST_F(mi_draw)(&st_src, MI_ALPHA);
        uint64_t m = mi_src_next(&st_src);
        int n = (int)(m % 80) + 1;
        for (k = 0; k < n; ++k) in[k] = ST_F(mi_draw)(&st_src, (m >> 8) & 1 ? MI_U : MI_XI);
        ST_F(mi_batch)(g, a, in, n);
    }
    st_end(ST_NAME " mist_*_n: random");
}

/* ------------------------------------------------------------------------ */
/* Height fog                                                               */
/* ------------------------------------------------------------------------ */

/* The fields of a fuzz_hfog direct record (fuzz/fuzz_hfog.c): every field
 * of the fog in struct order (sun_extinction: one byte), the ray, the
 * background and w. */
static void ST_F(st_rec_fog)(const ST_HFOG *f, ST_V3 o, ST_V3 d, ST_T len, ST_RGB bg, ST_T w)
{
    unsigned char se = f->sun_extinction != 0;
    st_put(&f->base, sizeof(ST_T)); st_put(&f->density, sizeof(ST_T));
    st_put(&f->scale_height, sizeof(ST_T));
    st_put(&f->rayleigh_scat, sizeof f->rayleigh_scat); st_put(&f->rayleigh_ext, sizeof f->rayleigh_ext);
    st_put(&f->mie_scat, sizeof f->mie_scat); st_put(&f->mie_ext, sizeof f->mie_ext);
    st_put(&f->mie_phase.g_hg, sizeof(ST_T)); st_put(&f->mie_phase.g_d, sizeof(ST_T));
    st_put(&f->mie_phase.alpha, sizeof(ST_T)); st_put(&f->mie_phase.w_d, sizeof(ST_T));
    st_put(&f->sun_dir.x, sizeof(ST_T)); st_put(&f->sun_dir.y, sizeof(ST_T));
    st_put(&f->sun_dir.z, sizeof(ST_T));
    st_put(&f->sun, sizeof f->sun); st_put(&f->ambient, sizeof f->ambient);
    st_put(&se, 1);
    st_put(&o.x, sizeof(ST_T)); st_put(&o.y, sizeof(ST_T)); st_put(&o.z, sizeof(ST_T));
    st_put(&d.x, sizeof(ST_T)); st_put(&d.y, sizeof(ST_T)); st_put(&d.z, sizeof(ST_T));
    st_put(&len, sizeof(ST_T));
    st_put(&bg.r, sizeof(ST_T)); st_put(&bg.g, sizeof(ST_T)); st_put(&bg.b, sizeof(ST_T));
    st_put(&w, sizeof(ST_T));
}

static void ST_F(st_hfog)(double share)
{
#if !MI_FAST
    /* (subnormal vertical cosines and scale heights of either type, and
     * FLT_MAX, DBL_MAX; DBL_MAX is +inf,
     * a uniform fog, in float) */
    static const double ws[] = { 0, 1e-300, -1e-300, 1e-12, -1e-12, 1e-6, -1e-6, 1e-3, -1e-3,
                                 0.5, -0.5, 1, -1, 1e-320, -1e-320, 1e-45, -1e-45 };
    static const double hs[] = { -1000, -800, -700, -90, -80, -1, 0, 1, 80, 90, 700, 800, 1000 };
    static const double ls[] = { 0, 1e-300, 1e-3, 1, 1e3, 1e6, 1e12, 1e300, -1 };
    static const double Hs[] = { 1e-30, 1e-3, 1, 1e3, 1e30, 1e-40, 1e-310, FLT_MAX, DBL_MAX };
#else   /* -ffast-math: where nothing overflows or underflows */
    static const double ws[] = { 0, 1e-12, -1e-12, 1e-6, -1e-6, 1e-3, -1e-3, 0.5, -0.5, 1, -1 };
    static const double hs[] = { -70, -40, -1, 0, 1, 40, 70 };
    static const double ls[] = { 0, 1e-3, 1, 1e3, -1 };
    static const double Hs[] = { 1e-3, 1, 1e3 };
#endif
    ST_HFOG f;
    ST_V3 o, d;
    ST_T len;
    ST_RGB bg;
    size_t a, b, c, e;
    /* grid: vertical cosine x height in scale heights x length x H, each
     * with and without the sun's extinction */
    st_begin();
    ST_F(mi_gen_hfog)(&st_src, &f, &o, &d, &len, &bg);
    f.base = 10; f.density = (ST_T)0.5;
    f.rayleigh_scat.r = (ST_T)0.01; f.rayleigh_scat.g = (ST_T)0.02; f.rayleigh_scat.b = (ST_T)0.04;
    f.rayleigh_ext = f.rayleigh_scat;
    f.mie_scat.r = f.mie_scat.g = f.mie_scat.b = (ST_T)0.05;
    f.mie_ext.r = f.mie_ext.g = f.mie_ext.b = (ST_T)0.06;
    f.mie_phase = ST_F(mi_fog_from_diameter)(10);
    f.sun_dir.x = (ST_T)0.6; f.sun_dir.y = (ST_T)0.48; f.sun_dir.z = (ST_T)0.64;
    f.sun.r = f.sun.g = f.sun.b = 5;
    f.ambient.r = f.ambient.g = f.ambient.b = 1;
    bg.r = bg.g = bg.b = (ST_T)0.5;
    o.x = 1; o.z = 2;
    for (a = 0; a < sizeof ws / sizeof *ws; ++a)
        for (b = 0; b < sizeof hs / sizeof *hs; ++b)
            for (c = 0; c < sizeof ls / sizeof *ls; ++c)
                for (e = 0; e < sizeof Hs / sizeof *Hs * 2; ++e) {
                    ST_T w = (ST_T)ws[a];
                    f.scale_height = (ST_T)Hs[e / 2];
                    f.sun_extinction = (int)(e & 1);
                    o.y = (ST_T)(f.base + hs[b] * Hs[e / 2]);
                    d.x = (ST_T)sqrt(1 - ws[a] * ws[a]); d.y = w; d.z = 0;
                    len = (ST_T)ls[c];
                    if (MI_FAST && fabs(ws[a]) * ls[c] > 0.25 * ST_EMAX * Hs[e / 2]) continue;
                    ST_F(mi_hfog_column)(&f, o.y, w, len);
                    ST_F(mi_hfog_eval)(&f, o, d, len, bg);
                    if (c == 0 && !MI_FAST) {
                        len = (ST_T)1e300 * (ST_T)1e300;   /* +inf */
                        ST_F(mi_hfog_column)(&f, o.y, w, len);
                        ST_F(mi_hfog_eval)(&f, o, d, len, bg);
                    }
                }
    {   /* ray-marching steps: extinctions x sources x lengths */
        static const double ks[] = { 0, 1e-300, 1e-8, 0.5, 1, 3, 100, 1e8, 1e300, -1 };
        static const double ss[] = { 0, 1, -2, 1e-300, 1e300 };
        static const double gl[] = { 0, 1e-300, 1e-6, 1, 50, 1e6, 1e300, -1 };
        size_t i0, i1, j0, j1, q;
        for (i0 = 0; i0 < sizeof ks / sizeof *ks; ++i0)
            for (i1 = 0; i1 < sizeof ks / sizeof *ks; ++i1)
                for (j0 = 0; j0 < sizeof ss / sizeof *ss; ++j0)
                    for (j1 = 0; j1 < sizeof ss / sizeof *ss; ++j1)
                        for (q = 0; q < sizeof gl / sizeof *gl; ++q)
                            if (!MI_FAST || (ks[i0] * gl[q] < 1e30 && ks[i1] * gl[q] < 1e30
                                             && fabs(ss[j0]) * gl[q] < 1e30
                                             && fabs(ss[j1]) * gl[q] < 1e30
                                             && ST_F(mi_fast_ok)((ST_T)ks[i0])
                                             && ST_F(mi_fast_ok)((ST_T)ks[i1])
                                             && ST_F(mi_fast_ok)((ST_T)ss[j0])
                                             && ST_F(mi_fast_ok)((ST_T)ss[j1])
                                             && ST_F(mi_fast_ok)((ST_T)gl[q])))
                                ST_F(mi_segment)((ST_T)ks[i0], (ST_T)ks[i1], (ST_T)ss[j0],
                                                 (ST_T)ss[j1], (ST_T)gl[q]);
    }
    st_end(ST_NAME " height fog: grid");
    st_begin();
    ST_UNTIL(share * 0.6) {
        unsigned long long f0 = mi_fails;
        ST_T w;
        ST_F(mi_gen_hfog)(&st_src, &f, &o, &d, &len, &bg);
        ST_F(mi_hfog_eval)(&f, o, d, len, bg);
        w = ST_F(mi_draw)(&st_src, MI_U);
        ST_F(mi_hfog_column)(&f, o.y, w, len);
        ST_F(mi_hfog_path)(&f, o, d, len, (int)(st_rng.s % 3), ST_F(mi_draw)(&st_src, MI_U));
        if ((st_rng.s & 15) == 0) ST_F(mi_hfog_null)(o, d, len, bg);
        if (st_dump_dir && mi_fails != f0) {
            unsigned char sel = (unsigned char)(2 | (sizeof(ST_T) == 4));
            st_nrec = 0;
            st_put(&sel, 1);
            ST_F(st_rec_fog)(&f, o, d, len, bg, w);
            st_dump(f0);
        }
    }
    st_end(ST_NAME " height fog: random");
    /* several layers: random stacks (n from -1 to 9, or NULL), and one fog
     * split into its Rayleigh and Mie layers (the exact case) */
    st_begin();
    ST_UNTIL(share * 0.04) {                 /* ~7 us a call: fewer */
        static ST_HFOG ls[10];
        static const int pieces[] = { -1, 0, 1, 2, 8, 64, 100 };
        uint64_t m = mi_src_next(&st_src);
        int n = (int)(m % 11) - 1, k, p = pieces[(m >> 8) % 7];
        ST_V3 o2, d2;
        ST_T len2;
        ST_RGB bg2;
        for (k = 0; k < (n > 0 ? n : 1); ++k)
            ST_F(mi_gen_hfog)(&st_src, &ls[k], k ? &o2 : &o, k ? &d2 : &d, k ? &len2 : &len,
                              k ? &bg2 : &bg);
        if (n > 1 && (m >> 16) % 4 == 0)     /* a shared scale height: exact */
            for (k = 1; k < n; ++k) ls[k].scale_height = ls[0].scale_height;
        if (MI_FAST)                         /* the ray in every layer's range */
            for (k = 1; k < n; ++k) {
                ls[k].base = ls[0].base;
                ls[k].scale_height = (ST_T)(ls[0].scale_height * (1 + 0.5 * k));
            }
        unsigned long long f0 = mi_fails;
        ST_F(mi_hfog_layers)((m >> 20) % 16 ? ls : (ST_HFOG *)0, n, o, d, len, p);
        ST_F(mi_hfog_split)(&ls[0], o, d, len, p);
        if (st_dump_dir && mi_fails != f0) {
            /* selector, n + 1, pieces + 2 (100 is 64: both the most), layers */
            unsigned char hd[3];
            hd[0] = (unsigned char)((1 << 2) | 2 | (sizeof(ST_T) == 4));
            hd[1] = (unsigned char)(n + 1);
            hd[2] = (unsigned char)((p > 64 ? 64 : p) + 2);
            st_nrec = 0;
            st_put(hd, 3);
            for (k = 0; k < (n > 0 ? n : 1); ++k) ST_F(st_rec_fog)(&ls[k], o, d, len, bg, 0);
            st_dump(f0);
        }
    }
    st_end(ST_NAME " mist_hfog_layers_eval");
    /* ray-marching steps */
    st_begin();
    ST_UNTIL(share * 0.36) {
        ST_T k0 = ST_F(mi_draw)(&st_src, MI_POS), k1 = ST_F(mi_draw)(&st_src, MI_POS);
        ST_T s0 = ST_F(mi_draw)(&st_src, MI_REAL), s1 = ST_F(mi_draw)(&st_src, MI_REAL);
        ST_T sl = ST_F(mi_draw)(&st_src, MI_POS);
        uint64_t m = mi_src_next(&st_src);
        if (m % 4 == 0) k1 = k0;                          /* constant extinction */
        if (m % 16 == 1) k0 = k1 = 0;                     /* none */
        if (m % 16 == 2 && !MI_FAST) sl = ST_INF;         /* unbounded */
        m = mi_fails;
        ST_F(mi_segment)(k0, k1, s0, s1, sl);
        if (st_dump_dir && mi_fails != m) {
            unsigned char sel = (unsigned char)((2 << 2) | 2 | (sizeof(ST_T) == 4));
            st_nrec = 0;
            st_put(&sel, 1);
            st_put(&k0, sizeof k0); st_put(&k1, sizeof k1); st_put(&s0, sizeof s0);
            st_put(&s1, sizeof s1); st_put(&sl, sizeof sl);
            st_dump(m);
        }
    }
    st_end(ST_NAME " mist_segment_linear");
}

/* The shares of the budget for each type (half each), tuned so that each
 * function gets calls in proportion to how cheap it is. */
static void ST_F(run)(void)
{
    printf("%s:\n", ST_NAME);
    if (st_want("dens")) ST_F(st_evals)(0.5 * 0.39);
    if (st_want("samp")) ST_F(st_samples)(0.5 * 0.12, 0.5 * 0.12, 0.5 * 0.04);
    if (st_want("mix")) ST_F(st_fog)(0.5 * 0.08);
    if (st_want("dir")) ST_F(st_dirs)(0.5 * 0.08, 0.5 * 0.07);
    if (st_want("hfog")) ST_F(st_hfog)(0.5 * 0.05);
    if (st_want("prep")) ST_F(st_prepared)(0.5 * 0.03, 0.5 * 0.02);
}

#endif /* ST_TEMPLATE */
