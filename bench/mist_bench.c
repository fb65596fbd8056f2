/* mist_bench.c - nanoseconds per call of mist's evaluation and sampling
 * functions, beside baselines measured in the same run:
 *   - the paper's formulas typed in as printed ([JD23] eq. 2-3 for HG, eq. 6
 *     for Draine), which are what mist's stable forms replace;
 *   - the cheap alternatives a renderer might use instead (HG alone, a
 *     Schlick lobe, a 256-entry table: tests/mist_alt.h), and the droplet
 *     fits typed in as printed;
 *   - HG against its bare formula, scalar against scalar (NOVEC below) and
 *     vector against vector; the batch forms against a loop of scalar calls;
 *   - the object-code size of a translation unit using one function
 *     (bench/size_one.c) against one using everything (bench/size_all.c),
 *     built by CMake at this benchmark's flags (MIST_BENCH_FLAGS, printed);
 *   - the double samplers as built without a wider long double
 *     and without fma (bench/nold.c, MIST_NO_LONG_DOUBLE -mno-fma: MSVC x64);
 *   - every other public evaluation and sampling function (coverage_rows:
 *     the direction samplers, the height fog, the ray-march step, the
 *     preparation of a medium), beside the formula as printed or the
 *     function it builds on;
 *   - the Lorenz-Mie sphere, phase function, amplitudes and table
 *     (mie_rows), beside the textbook series of [BH83] Appendix A.
 * Each figure: median of 15 timed repetitions (after a warm-up) over a
 * stream of 4096 random inputs, each repetition at least 100 us long (the
 * stream run over k times: MIN_S), with the spread (min..max of the
 * repetitions); a ratio is the median over 15 turns of one repetition of
 * the function and one of its baseline (measure_vs).  Run: ./build/mist_bench  (see README.md;
 * ./build/mist_bench tab: the tabulated phase functions alone; hfog: the
 * height fog alone). */
#define _POSIX_C_SOURCE 199309L
#include "mist.h"
#include "mist_mie.h"
#include "mist_printed.h"
#include "mist_alt.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* fma is one instruction: mist.h's test (MIST__FAST_FMA), for the row labels */
#if defined(FP_FAST_FMA) || defined(__FMA__) || defined(__ARM_FEATURE_FMA)
#  define BENCH_FMA 1
#endif
#define N 4096
#define REPS 15

static float  xf[N], uf[N];
static double xd[N], ud[N];
static volatile double sink;

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

/* ---- timing ------------------------------------------------------------- */

typedef double (*bench_fn)(void);

static void sort(double *t, int n)
{
    int i, j;
    double tmp;
    for (i = 0; i < n; ++i)
        for (j = i + 1; j < n; ++j)
            if (t[j] < t[i]) { tmp = t[i]; t[i] = t[j]; t[j] = tmp; }
}

/* Each timed repetition runs f (4096 calls) k times, k chosen so that it
 * lasts >= MIN_S: a single run of a cheap batch lasts 0.5 us, less than
 * this machine takes to settle after a switch between scalar and vector
 * code (wider vector units powered up, the clock): timed one run at a
 * time in turns with its scalar loop, mist_rayleigh_eval_n came out 0.29
 * ns against a scalar loop of 1.06 (3.7x), where either timed alone gives
 * 0.28 against 0.66 (2.4x). */
#define MIN_S 100e-6

static double timed(bench_fn f, int k)
{
    double t0 = now();
    int j;
    for (j = 0; j < k; ++j) sink += f();
    return (now() - t0) / ((double)N * k) * 1e9;
}

static int reps_for(bench_fn f)
{
    double t;
    sink += f();                                   /* warm-up */
    t = timed(f, 1) * N * 1e-9;
    return t >= MIN_S ? 1 : (t * 1000 < MIN_S ? 1000 : (int)(MIN_S / t) + 1);
}

static double measure(bench_fn f, double *lo, double *hi)
{
    double t[REPS];
    int i, k = reps_for(f);
    for (i = 0; i < REPS; ++i) t[i] = timed(f, k);
    sort(t, REPS);
    *lo = t[0]; *hi = t[REPS - 1];
    return t[REPS / 2];
}

/* f and its baseline timed in turns, one repetition of each a turn, so
 * that a change of the machine's speed during the run (a busy neighbour,
 * the clock: runs here on a shared machine came out 1.5x apart, and
 * flipped between two speeds) hits both alike.  Returns f's median (lo,
 * hi its spread); *ratio is the median over the turns of f's time over
 * the baseline's, *bm the baseline's median. */
static double measure_vs(bench_fn f, bench_fn base, double *lo, double *hi, double *ratio,
                         double *bm)
{
    double t[REPS], tb[REPS], r[REPS];
    int i, k = reps_for(f), kb = reps_for(base);
    for (i = 0; i < REPS; ++i) {     /* each timed right after an untimed run */
        sink += base();
        tb[i] = timed(base, kb);
        sink += f();
        t[i] = timed(f, k);
        r[i] = t[i] / tb[i];
    }
    sort(t, REPS); sort(tb, REPS); sort(r, REPS);
    *lo = t[0]; *hi = t[REPS - 1];
    *ratio = r[REPS / 2];
    *bm = tb[REPS / 2];
    return t[REPS / 2];
}

#include "bench.h"   /* NOVEC: see there */
static float  out_float[N];
static double out_double[N];
#define LOOP(T, EXPR) { int i; for (i = 0; i < N; ++i) { T v_ = EXPR; NOVEC(v_); \
                        out_##T[i] = v_; } return (double)out_##T[N / 2]; }

static double b_hg_eval_printed(void)  LOOP(float, hg_eval_printed(0.8f, uf[i]))
static double b_hg_evalf(void)         LOOP(float, mist_hg_evalf(0.8f, uf[i]))
static double b_hg_eval(void)          LOOP(double, mist_hg_eval(0.8, ud[i]))
static double b_hg_sample_printed(void) LOOP(float, hg_sample_printed(0.8f, xf[i]))
static double b_hg_samplef(void)       LOOP(float, mist_hg_samplef(0.8f, xf[i]))
static double b_hg_sample(void)        LOOP(double, mist_hg_sample(0.8, xd[i]))
/* the same formulas in float arithmetic only (internal; HG's up to 1.1x the
 * accuracy bar, Rayleigh's within it but not monotone, 2.6e6 reversed
 * adjacent pairs over all floats in [0, 1]: which is why the public float
 * functions use double inside) */
static double b_hg_sample_floatonly(void) LOOP(float, mist__hg_samplef(0.8f, xf[i]))
static double b_rayleigh_floatonly(void) LOOP(float, mist__rayleigh_uf(xf[i]))
static double b_draine_evalf(void)     LOOP(float, mist_draine_evalf(0.5f, 17.f, uf[i]))
static double b_draine_eval(void)      LOOP(double, mist_draine_eval(0.5, 17., ud[i]))
static double b_eq6f(void)             LOOP(float, draine_eq6f(0.5f, 17.f, xf[i]))
static double b_eq6(void)              LOOP(double, draine_eq6(0.5, 17., xd[i]))
static double b_draine_samplef(void)   LOOP(float, mist_draine_samplef(0.5f, 17.f, xf[i]))
static double b_draine_sample(void)    LOOP(double, mist_draine_sample(0.5, 17., xd[i]))
/* g 0, alpha 1: outside eq. 6's domain, where the unprepared batch prepares */
static double b_draine_samplef_g0(void) LOOP(float, mist_draine_samplef(0.f, 1.f, xf[i]))
static double b_draine_sample_g0(void)  LOOP(double, mist_draine_sample(0., 1., xd[i]))
/* g .9999, alpha 17: near |g| = 1, at the edge of eq. 6's domain, where the
 * float certificate fails for most xi (u near 1) */
static double b_draine_samplef_1(void) LOOP(float, mist_draine_samplef(0.9999f, 17.f, xf[i]))
static double b_draine_samplef_999(void) LOOP(float, mist_draine_samplef(0.999f, 17.f, xf[i]))
static double b_draine_sample_1(void)  LOOP(double, mist_draine_sample(0.9999, 17., xd[i]))
static double b_eq6f_250(void)         LOOP(float, draine_eq6f(0.1f, 250.f, xf[i]))
static double b_draine_samplef_250(void) LOOP(float, mist_draine_samplef(0.1f, 250.f, xf[i]))
static double b_cs_samplef(void)       LOOP(float, mist_cs_samplef(0.7f, xf[i]))
static double b_eq6f_cs(void)          LOOP(float, draine_eq6f(0.7f, 1.f, xf[i]))
static double b_rayleigh_samplef(void) LOOP(float, mist_rayleigh_samplef(xf[i]))
static double b_rayleigh_sample(void)  LOOP(double, mist_rayleigh_sample(xd[i]))
/* the double samplers without a wider long double (bench/nold.c) */
static double b_hg_sample_nold(void)  { return nold_hg_sample(0.8, xd, out_double, N); }
static double b_hg_sample_nold5(void) { return nold_hg_sample(0.5, xd, out_double, N); }
static double b_hg_sample_nold3(void) { return nold_hg_sample(0.3, xd, out_double, N); }
static double b_hg_sample_nold1(void) { return nold_hg_sample(0.1, xd, out_double, N); }
static double n_hg_sample_nold(void)  { return nold_hg_sample_n(0.8, xd, out_double, N); }
static double b_draine_sample_nold(void) { return nold_draine_sample(0.5, 17., xd, out_double, N); }
static double b_rayleigh_sample_nold(void) { return nold_rayleigh_sample(xd, out_double, N); }
static double n_rayleigh_sample_nold(void) { return nold_rayleigh_sample_n(xd, out_double, N); }
static double b_fog_samplef(void)
{
    mist_fogf fog = mist_fog_makef(0.988f, 0.556f, 22.0f, 0.482f);
    LOOP(float, mist_fog_samplef(fog, xf[i]))
}
static double b_fog_evalf(void)
{
    mist_fogf fog = mist_fog_makef(0.988f, 0.556f, 22.0f, 0.482f);
    LOOP(float, mist_fog_evalf(fog, uf[i]))
}
/* prepared phase functions (mist_phase_*): prepared once per stream, as a
 * renderer prepares once per medium.  The unprepared baselines here read
 * their parameters at run time (volatile), as a renderer does: with
 * literal constants the compiler folds the parameter-only work out of the
 * loop, which is the saving preparation makes by hand. */
static mist_phasef ph_hgf, ph_drf, ph_fogf;
static mist_phase  ph_dr;
static volatile float rt_g = 0.8f, rt_gd = 0.5f, rt_a = 17.f;
static volatile float rt_fog[4] = { 0.988f, 0.556f, 22.0f, 0.482f };
#define LOOP_RT(T, SETUP, EXPR) { int i; SETUP; for (i = 0; i < N; ++i) { T v_ = EXPR; \
                                  NOVEC(v_); out_##T[i] = v_; } return (double)out_##T[N / 2]; }
static double b_hg_evalf_unprep(void)  LOOP_RT(float, float g = rt_g, mist_hg_evalf(g, uf[i]))
static double b_hg_samplef_unprep(void) LOOP_RT(float, float g = rt_g, mist_hg_samplef(g, xf[i]))
static double b_draine_evalf_rt(void)  LOOP_RT(float, float g = rt_gd; float a = rt_a,
                                               mist_draine_evalf(g, a, uf[i]))
static double b_draine_samplef_rt(void) LOOP_RT(float, float g = rt_gd; float a = rt_a,
                                                mist_draine_samplef(g, a, xf[i]))
static double b_draine_sample_rt(void) LOOP_RT(double, double g = rt_gd; double a = rt_a,
                                               mist_draine_sample(g, a, xd[i]))
static double b_fog_evalf_rt(void)     LOOP_RT(float, mist_fogf fog = mist_fog_makef(rt_fog[0],
                                               rt_fog[1], rt_fog[2], rt_fog[3]),
                                               mist_fog_evalf(fog, uf[i]))
static double b_fog_samplef_rt(void)   LOOP_RT(float, mist_fogf fog = mist_fog_makef(rt_fog[0],
                                               rt_fog[1], rt_fog[2], rt_fog[3]),
                                               mist_fog_samplef(fog, xf[i]))
static double b_phase_hg_evalf(void)   LOOP(float, mist_phase_evalf(&ph_hgf, uf[i]))
static double b_phase_hg_samplef(void) LOOP(float, mist_phase_samplef(&ph_hgf, xf[i]))
static double b_phase_draine_evalf(void) LOOP(float, mist_phase_evalf(&ph_drf, uf[i]))
static double b_phase_draine_samplef(void) LOOP(float, mist_phase_samplef(&ph_drf, xf[i]))
static double b_phase_draine_sample(void) LOOP(double, mist_phase_sample(&ph_dr, xd[i]))
static mist_phasef ph_dr250f, ph_csf, ph_dr999f;
/* g .999, alpha 17: a float medium that samples as the unprepared sampler
 * (mist__phase_near1f) */
static double b_phase_dr999_samplef(void) LOOP(float, mist_phase_samplef(&ph_dr999f, xf[i]))
static double n_phase_dr999_samplef(void)
{
    mist_phase_sample_nf(&ph_dr999f, xf, out_float, N);
    return (double)out_float[N / 2];
}
static double b_phase_dr250_samplef(void) LOOP(float, mist_phase_samplef(&ph_dr250f, xf[i]))
static double b_phase_cs_samplef(void) LOOP(float, mist_phase_samplef(&ph_csf, xf[i]))
static double b_phase_fog_evalf(void)  LOOP(float, mist_phase_evalf(&ph_fogf, uf[i]))
static double b_phase_fog_samplef(void) LOOP(float, mist_phase_samplef(&ph_fogf, xf[i]))
/* the fog mixture (d = 10 um: g_hg .988, g_d .556, alpha 22, w_d .482) one
 * at a time and as batches: prepared and unprepared, float and double */
static mist_phase ph_fog;
static const mist_fogf fog10f = { 0.988f, 0.556f, 22.0f, 0.482f };
static const mist_fog fog10 = { 0.988, 0.556, 22.0, 0.482 };
static double b_phase_fog_sample(void) LOOP(double, mist_phase_sample(&ph_fog, xd[i]))
static double b_phase_fog_eval(void)   LOOP(double, mist_phase_eval(&ph_fog, ud[i]))
static double b_fog_sample10(void)     LOOP(double, mist_fog_sample(fog10, xd[i]))
static double b_fog_eval10(void)       LOOP(double, mist_fog_eval(fog10, ud[i]))
static double b_fog_samplef10(void)    LOOP(float, mist_fog_samplef(fog10f, xf[i]))
static double b_fog_evalf10(void)      LOOP(float, mist_fog_evalf(fog10f, uf[i]))

static void prepared_rows(void);
/* the compact prepared form (mist_phasec_*) of the same media */
static mist_phasecf pc_fogf, pc_drf;
static mist_phasec pc_fog, pc_dr;
static double k_fog_samplef(void)  LOOP(float, mist_phasec_samplef(&pc_fogf, xf[i]))
static double k_fog_evalf(void)    LOOP(float, mist_phasec_evalf(&pc_fogf, uf[i]))
static double k_dr_samplef(void)   LOOP(float, mist_phasec_samplef(&pc_drf, xf[i]))
static double k_fog_sample(void)   LOOP(double, mist_phasec_sample(&pc_fog, xd[i]))
static double k_dr_sample(void)    LOOP(double, mist_phasec_sample(&pc_dr, xd[i]))
/* a direction sampler over the float inputs, its direction and pdf summed */
#define DIRF_LOOP(CALL)                                                        \
    {                                                                          \
        mist_vec3f wi = { 0.48f, -0.6f, 0.64f }, wo;                           \
        float pdf, s = 0;                                                      \
        int i;                                                                 \
        for (i = 0; i < N; ++i) { wo = CALL; s += wo.x + pdf; }                \
        return s;                                                              \
    }
static double k_fog_sample_dirf(void)
    DIRF_LOOP(mist_phasec_sample_dirf(&pc_fogf, wi, xf[i], xf[N - 1 - i], &pdf))
static double k_phase_fog_sample_dirf(void)
    DIRF_LOOP(mist_phase_sample_dirf(&ph_fogf, wi, xf[i], xf[N - 1 - i], &pdf))
/* preparing: a new medium per call (the d = 5 .. 50 um fits' parameters) */
static double k_prep_fogf(void) { float s_ = 0; int i; for (i = 0; i < N; ++i) {
    mist_phasecf p = mist_phasec_fogf(mist_fog_makef(0.98f, 0.5f + 0.1f * xf[i], 22.f, 0.48f));
    s_ += p.f0[0]; } return s_; }
static double k_prep_fog(void) { double s_ = 0; int i; for (i = 0; i < N; ++i) {
    mist_phasec p = mist_phasec_fog(mist_fog_make(0.98, 0.5 + 0.1 * xd[i], 22., 0.48));
    s_ += p.f0[0]; } return s_; }

static double b_hg_sample_dirf(void)
{
    mist_vec3f wi = { 0.48f, -0.6f, 0.64f }, wo;
    float pdf, s = 0;
    int i;
    for (i = 0; i < N; ++i) {
        wo = mist_hg_sample_dirf(0.8f, wi, xf[i], xf[N - 1 - i], &pdf);
        s += wo.x + pdf;
    }
    return s;
}

/* ---- the cheap alternatives (tests/mist_alt.h), the same streams -------- */

static float alt_k;                 /* Schlick's k for g = 0.8 */
static alt_lutf alt_fog_lut;        /* the d = 10 um fog, 256 entries */
static double alt_fog_dens(double u, const void *par)
{
    return mist_fog_eval(*(const mist_fog *)par, u);
}
static double b_schlick_evalf(void)    LOOP(float, alt_schlick_evalf(alt_k, uf[i]))
static double b_schlick_samplef(void)  LOOP(float, alt_schlick_samplef(alt_k, xf[i]))
static double b_lut_evalf(void)        LOOP(float, alt_lut_evalf(&alt_fog_lut, uf[i]))
static double b_lut_samplef(void)      LOOP(float, alt_lut_samplef(&alt_fog_lut, xf[i]))

/* the droplet fits: mist's (eq. 7-22) against eq. 7-10 typed in as printed
 * (the 5-50 um range, constants of eq. 8 and 10 outside the exponential) */
static float fit_printedf(float d)
{
    return expf(-0.0990567f / (d - 1.67154f)) + expf(-2.20679f / (d + 3.91029f)) - 0.428934f
         + expf(3.62489f - 8.29288f / (d + 5.52825f))
         + expf(-0.599085f / (d - 0.641583f)) - 0.665888f;
}
static double b_fit_printedf(void)     LOOP(float, fit_printedf(5 + 45 * xf[i]))
static double b_fit_mistf(void)
{
    float s = 0;
    int i;
    for (i = 0; i < N; ++i) {
        mist_fogf f = mist_fog_from_diameterf(5 + 45 * xf[i]);
        s += f.g_hg + f.g_d + f.alpha + f.w_d;
    }
    return s;
}

static void row(const char *name, bench_fn f, const char *base_name, bench_fn base);

static void alternatives(void)
{
    bench_fn base;
    mist_fog fog = mist_fog_from_diameter(10);
    alt_k = alt_schlick_kf(0.8f);
    alt_fog_lut = alt_lut_buildf(256, alt_fog_dens, &fog);
    printf("\nThe cheap alternatives a renderer might use instead (tests/mist_alt.h):\n");
    base = b_hg_evalf;
    row("mist_hg_evalf (g .8)", b_hg_evalf, NULL, NULL);
    row("Schlick eval (k from g .8, float)", b_schlick_evalf, "mist_hg_evalf", base);
    row("LUT eval, 256 entries (fog 10 um)", b_lut_evalf, "mist_hg_evalf", base);
    row("mist_fog_evalf (d = 10 um)", b_fog_evalf, "mist_hg_evalf", base);
    base = b_hg_samplef;
    row("mist_hg_samplef (g .8)", b_hg_samplef, NULL, NULL);
    row("Schlick sample (float)", b_schlick_samplef, "mist_hg_samplef", base);
    row("LUT inverse CDF, 256 entries (fog)", b_lut_samplef, "mist_hg_samplef", base);
    row("mist_fog_samplef (d = 10 um)", b_fog_samplef, "mist_hg_samplef", base);
    base = b_fit_printedf;
    row("fits eq. 7-10 as printed (float)", b_fit_printedf, NULL, NULL);
    row("mist_fog_from_diameterf (5-50 um)", b_fit_mistf, "printed", base);
    free(alt_fog_lut.p);
    free(alt_fog_lut.icdf);
}

/* Lorenz-Mie: one droplet diameter (monodisperse), 1800 angles uniform in
 * theta, three wavelengths (450, 550, 650 nm) of water: milliseconds */
static double mie_ms(double d_um)
{
    static double mu[1800], p[1800];
    mist_mie_wavelength wl[3];
    mist_mie_dist dist = mist_mie_dist_mono(d_um / 2);
    double t[5], tmp;
    int i, j;
    mist_mie_theta_grid(1800, mu);
    wl[0] = mist_mie_wl(0.45, 1, mist_mie_water(450, NULL));
    wl[1] = mist_mie_wl(0.55, 1, mist_mie_water(550, NULL));
    wl[2] = mist_mie_wl(0.65, 1, mist_mie_water(650, NULL));
    for (i = 0; i < 5; ++i) {
        double t0 = now();
        mist_mie_avg a = mist_mie_average(&dist, wl, 3, 1.0, mu, 1800, p);
        t[i] = (now() - t0) * 1e3;
        sink += a.g + p[0];
    }
    for (i = 0; i < 5; ++i)
        for (j = i + 1; j < 5; ++j)
            if (t[j] < t[i]) { tmp = t[i]; t[i] = t[j]; t[j] = tmp; }
    return t[2];
}

/* a row: f's ns per call, and with a baseline the ratio to it, timed in
 * turns with it (measure_vs) */
/* A row: f's time per call (f makes N calls; k: times that, for a bench
 * function making N / k calls, printed in us from 1000 ns on with its
 * unit), and the ratio to base where named. */
static void row_k(const char *name, bench_fn f, const char *base_name, bench_fn base, double k)
{
    double lo, hi, r = 0, bm, m;
    const char *un = k == 1 ? "  " : " ns ";
    m = base_name ? measure_vs(f, base, &lo, &hi, &r, &bm) : measure(f, &lo, &hi);
    m *= k; lo *= k; hi *= k;
    if (k != 1 && m >= 1000) { m *= 1e-3; lo *= 1e-3; hi *= 1e-3; un = " us "; }
    printf("%-34s %8.2f%s[%6.2f..%6.2f]", name, m, un, lo, hi);
    if (base_name) printf("  %6.2fx %s", r, base_name);
    printf("\n");
}
static void row(const char *name, bench_fn f, const char *base_name, bench_fn base)
{
    row_k(name, f, base_name, base, 1);
}

static void machine(void)
{
    FILE *f = fopen("/proc/cpuinfo", "r");
    char line[256];
    printf("machine: ");
    if (f) {
        while (fgets(line, sizeof line, f))
            if (strncmp(line, "model name", 10) == 0) {
                char *p = strchr(line, ':');
                printf("%s", p ? p + 2 : line);
                break;
            }
        fclose(f);
    } else {
        printf("unknown\n");
    }
#ifdef __VERSION__
    printf("compiler: %s\n", __VERSION__);
#endif
#ifdef MIST_BENCH_FLAGS
    printf("flags: %s\n", MIST_BENCH_FLAGS);
#endif
    printf("SIMD: %s\n",
#if defined(__AVX512F__)
           "AVX-512 (512-bit vectors)"
#elif defined(__AVX2__)
           "AVX2 (256-bit vectors)"
#elif defined(__AVX__)
           "AVX (256-bit vectors)"
#elif defined(__SSE2__)
           "SSE2 (128-bit vectors): build with -march=native for more"
#elif defined(__ARM_NEON)
           "NEON (128-bit vectors)"
#else
           "none known"
#endif
           );
}

/* Four media, one picked at random for each call (mi), their parameters
 * read from memory each call by mist and the baselines alike, as in a
 * renderer's loop over rays: no parameter-only work can leave the loop
 * (with one global medium above, the compiler hoists it for both). */
static int mi[N];
static const float md_g[4] = { 0.5f, 0.8f, 0.1f, 0.7f }, md_a[4] = { 17.f, 3.f, 250.f, 40.f };
static mist_phasef md_dr[4], md_hg[4];
static double b_eq6f_media(void)    LOOP(float, draine_eq6f(md_g[mi[i]], md_a[mi[i]], xf[i]))
static double b_phase_dr_media(void) LOOP(float, mist_phase_samplef(&md_dr[mi[i]], xf[i]))
static double b_draine_media(void)  LOOP(float, mist_draine_samplef(md_g[mi[i]], md_a[mi[i]], xf[i]))
static double b_eq3f_media(void)    LOOP(float, hg_sample_printed(md_g[mi[i]], xf[i]))
static double b_phase_hg_media(void) LOOP(float, mist_phase_samplef(&md_hg[mi[i]], xf[i]))
static double b_hg_media(void)      LOOP(float, mist_hg_samplef(md_g[mi[i]], xf[i]))

/* Prepared (mist_phase_*) against unprepared, same parameters, same run:
 * the ratio is the saving of preparing once per medium. */
static void prepared_rows(void)
{
    bench_fn base;
    printf("\nprepared (mist_phase_*) vs unprepared:\n");
    base = b_hg_evalf_unprep;
    row("mist_phase_evalf (HG .8)", b_phase_hg_evalf, "mist_hg_evalf", base);
    base = b_hg_samplef_unprep;
    row("mist_phase_samplef (HG .8)", b_phase_hg_samplef, "mist_hg_samplef", base);
    base = b_draine_evalf_rt;
    row("mist_phase_evalf (Draine .5, 17)", b_phase_draine_evalf, "mist_draine_evalf", base);
    base = b_draine_samplef_rt;
    row("mist_phase_samplef (Draine .5, 17)", b_phase_draine_samplef, "mist_draine_samplef",
        base);
    base = b_draine_sample_rt;
    row("mist_phase_sample (Draine .5, 17)", b_phase_draine_sample, "mist_draine_sample", base);
    base = b_eq6f;
    row("mist_phase_samplef (Draine .5, 17)", b_phase_draine_samplef, "eq. 6 float", base);
    ph_dr250f = mist_phase_drainef(0.1f, 250.f);
    ph_dr999f = mist_phase_drainef(0.999f, 17.f);
    row("mist_phase_samplef (Draine .999, 17)", b_phase_dr999_samplef, "mist_draine_samplef",
        b_draine_samplef_999);
    ph_csf = mist_phase_csf(0.7f);
    base = b_eq6f_250;
    row("eq. 6 float (g .1, a 250)", b_eq6f_250, NULL, NULL);
    row("mist_phase_samplef (Draine .1, 250)", b_phase_dr250_samplef, "eq. 6 float", base);
    base = b_eq6f_cs;
    row("eq. 6 float (g .7, a 1)", b_eq6f_cs, NULL, NULL);
    row("mist_phase_samplef (CS .7)", b_phase_cs_samplef, "eq. 6 float", base);
    base = b_fog_evalf_rt;
    row("mist_phase_evalf (fog, 10 um)", b_phase_fog_evalf, "mist_fog_evalf", base);
    base = b_fog_samplef_rt;
    row("mist_phase_samplef (fog, 10 um)", b_phase_fog_samplef, "mist_fog_samplef", base);
    printf("four media (g, alpha: .5, 17; .8, 3; .1, 250; .7, 40), one at random each call:\n");
    row("eq. 6 float", b_eq6f_media, NULL, NULL);
    row("mist_phase_samplef (Draine)", b_phase_dr_media, "eq. 6 float", b_eq6f_media);
    row("mist_draine_samplef", b_draine_media, "eq. 6 float", b_eq6f_media);
    row("eq. 3 float (the same g)", b_eq3f_media, NULL, NULL);
    row("mist_phase_samplef (HG)", b_phase_hg_media, "eq. 3 float", b_eq3f_media);
    row("mist_hg_samplef", b_hg_media, "eq. 3 float", b_eq3f_media);
}

/* ---- HG against its bare formula; the batch forms -------------------- */

/* The bare formulas in each type: HG [JD23 eq. 2] with V^3 = V^2 sqrt(V^2)
 * (the printed pow is slower), and eq. 3 as printed (with its g ~ 0
 * fallback: hg_sample_printed and _d, tests/mist_printed.h). */
static float hg_eval_baref(float g, float u)
{
    float v2 = 1 + g * g - 2 * g * u;
    return (1 - g * g) * (float)MIST__INV4PI / (v2 * sqrtf(v2));
}
static double hg_eval_bare(double g, double u)
{
    double v2 = 1 + g * g - 2 * g * u;
    return (1 - g * g) * MIST__INV4PI / (v2 * sqrt(v2));
}
/* g known only at run time, as in a renderer: one medium's g read once
 * (rt_g, volatile), and a g for each call (gv: uniform in [.05, .95]; gs:
 * of either sign, |g| <= .95).  With the literal 0.8 above the compiler
 * folds every g-only term for mist and the baseline alike. */
static float gv[N], gs[N];
static double b_bare_evalf_rt(void) LOOP_RT(float, float g = rt_g, hg_eval_baref(g, uf[i]))
static double b_eq3f_rt(void)       LOOP_RT(float, float g = rt_g, hg_sample_printed(g, xf[i]))
static double b_bare_eval_rt(void)  LOOP_RT(double, double g = rt_g, hg_eval_bare(g, ud[i]))
static double b_hg_eval_rt(void)    LOOP_RT(double, double g = rt_g, mist_hg_eval(g, ud[i]))
static double b_eq3_rt(void)        LOOP_RT(double, double g = rt_g, hg_sample_printed_d(g, xd[i]))
static double b_hg_sample_rt(void)  LOOP_RT(double, double g = rt_g, mist_hg_sample(g, xd[i]))
static double b_bare_evalf_gv(void) LOOP(float, hg_eval_baref(gv[i], uf[i]))
static double b_hg_evalf_gv(void)   LOOP(float, mist_hg_evalf(gv[i], uf[i]))
static double b_eq3f_gv(void)       LOOP(float, hg_sample_printed(gv[i], xf[i]))
static double b_hg_samplef_gv(void) LOOP(float, mist_hg_samplef(gv[i], xf[i]))
static double b_bare_evalf_gs(void) LOOP(float, hg_eval_baref(gs[i], uf[i]))
static double b_hg_evalf_gs(void)   LOOP(float, mist_hg_evalf(gs[i], uf[i]))
static double b_eq3f_gs(void)       LOOP(float, hg_sample_printed(gs[i], xf[i]))
static double b_hg_samplef_gs(void) LOOP(float, mist_hg_samplef(gs[i], xf[i]))
static double b_bare_evalf(void)   LOOP(float, hg_eval_baref(0.8f, uf[i]))
static double b_bare_eval(void)    LOOP(double, hg_eval_bare(0.8, ud[i]))
static double b_bare_sample(void)  LOOP(double, hg_sample_printed_d(0.8, xd[i]))
static double b_rayleigh_evalf(void) LOOP(float, mist_rayleigh_evalf(uf[i]))
static double b_rayleigh_eval(void)  LOOP(double, mist_rayleigh_eval(ud[i]))

/* the same bare formulas over arrays, vectorised by the compiler */
#define VLOOP(T, EXPR) { int i; for (i = 0; i < N; ++i) out_##T[i] = EXPR; \
                         return (double)out_##T[N / 2]; }
static double v_bare_evalf(void)   VLOOP(float, hg_eval_baref(0.8f, uf[i]))
static double v_bare_eval(void)    VLOOP(double, hg_eval_bare(0.8, ud[i]))
static double v_bare_samplef(void) VLOOP(float, hg_sample_printed(0.8f, xf[i]))
static double v_bare_sample(void)  VLOOP(double, hg_sample_printed_d(0.8, xd[i]))

/* the batch forms over the same inputs */
#define NCALL(T, CALL) { CALL; return (double)out_##T[N / 2]; }
static double n_hg_evalf(void)   NCALL(float, mist_hg_eval_nf(0.8f, uf, out_float, N))
static double n_hg_eval(void)    NCALL(double, mist_hg_eval_n(0.8, ud, out_double, N))
static double n_hg_samplef(void) NCALL(float, mist_hg_sample_nf(0.8f, xf, out_float, N))
static double n_hg_sample(void)  NCALL(double, mist_hg_sample_n(0.8, xd, out_double, N))
static double n_draine_evalf(void) NCALL(float, mist_draine_eval_nf(0.5f, 17.f, uf, out_float, N))
static double n_draine_eval(void)  NCALL(double, mist_draine_eval_n(0.5, 17., ud, out_double, N))
static double n_draine_samplef(void) NCALL(float, mist_draine_sample_nf(0.5f, 17.f, xf, out_float, N))
static double n_draine_sample(void)  NCALL(double, mist_draine_sample_n(0.5, 17., xd, out_double, N))
/* the same in batches of M: 64 (in eq. 6's domain: the kernel, no
 * preparation); and at g 0, alpha 1 (outside it), one array of N and
 * batches of MIST_DRAINE_PREPARE_N (1024), each prepared anew */
#define STR_(x) #x
#define STR(x) STR_(x)
#define NCHUNK(T, M, CALL) { int c; for (c = 0; c < N; c += (M)) { CALL; } \
                             return (double)out_##T[N / 2]; }
static double n_draine_samplef_64(void)
    NCHUNK(float, 64, mist_draine_sample_nf(0.5f, 17.f, xf + c, out_float + c, 64))
static double n_draine_sample_64(void)
    NCHUNK(double, 64, mist_draine_sample_n(0.5, 17., xd + c, out_double + c, 64))
static double n_draine_samplef_g0(void)
    NCALL(float, mist_draine_sample_nf(0.f, 1.f, xf, out_float, N))
static double n_draine_samplef_1(void)
    NCALL(float, mist_draine_sample_nf(0.9999f, 17.f, xf, out_float, N))
static double n_draine_sample_g0(void)
    NCALL(double, mist_draine_sample_n(0., 1., xd, out_double, N))
static double n_draine_samplef_chunk(void)
    NCHUNK(float, MIST_DRAINE_PREPARE_N, mist_draine_sample_nf(0.f, 1.f, xf + c, out_float + c,
                                                               MIST_DRAINE_PREPARE_N))
static double n_draine_sample_chunk(void)
    NCHUNK(double, MIST_DRAINE_PREPARE_N, mist_draine_sample_n(0., 1., xd + c, out_double + c,
                                                               MIST_DRAINE_PREPARE_N))
static double n_phase_dr_samplef(void) NCALL(float, mist_phase_sample_nf(&ph_drf, xf, out_float, N))
static double n_phase_dr_evalf(void) NCALL(float, mist_phase_eval_nf(&ph_drf, uf, out_float, N))
static double n_phase_dr_sample(void) NCALL(double, mist_phase_sample_n(&ph_dr, xd, out_double, N))
static double v_eq6f(void) VLOOP(float, draine_eq6f(0.5f, 17.f, xf[i]))
static double n_phase_fog_samplef(void) NCALL(float, mist_phase_sample_nf(&ph_fogf, xf, out_float, N))
static double n_phase_fog_sample(void) NCALL(double, mist_phase_sample_n(&ph_fog, xd, out_double, N))
static double n_phase_fog_evalf(void) NCALL(float, mist_phase_eval_nf(&ph_fogf, uf, out_float, N))
static double n_phase_fog_eval(void) NCALL(double, mist_phase_eval_n(&ph_fog, ud, out_double, N))
static double n_fog_samplef(void) NCALL(float, mist_fog_sample_nf(fog10f, xf, out_float, N))
static double n_fog_sample(void)  NCALL(double, mist_fog_sample_n(fog10, xd, out_double, N))
static double n_fog_evalf(void)   NCALL(float, mist_fog_eval_nf(fog10f, uf, out_float, N))
static double n_fog_eval(void)    NCALL(double, mist_fog_eval_n(fog10, ud, out_double, N))
static double n_phase_fog_samplef_64(void)
    NCHUNK(float, 64, mist_phase_sample_nf(&ph_fogf, xf + c, out_float + c, 64))
static double n_rayleigh_evalf(void) NCALL(float, mist_rayleigh_eval_nf(uf, out_float, N))
static double n_rayleigh_eval(void)  NCALL(double, mist_rayleigh_eval_n(ud, out_double, N))
static double n_rayleigh_samplef(void) NCALL(float, mist_rayleigh_sample_nf(xf, out_float, N))
static double n_rayleigh_sample(void)  NCALL(double, mist_rayleigh_sample_n(xd, out_double, N))

/* a row whose ratio is a speed-up: the baseline's time over this one's */
static void row_speedup(const char *name, bench_fn f, bench_fn scalar)
{
    double lo, hi, r, s, m = measure_vs(f, scalar, &lo, &hi, &r, &s);
    printf("%-34s %8.2f  [%6.2f..%6.2f]  %5.2fx the scalar loop (%.2f ns)\n",
           name, m, lo, hi, 1 / r, s);
}

static void hg_target_rows(void)
{
    bench_fn b;
    printf("\nHG against the bare formula (eq. 2 with sqrt, eq. 3), same type, "
           "same loop;\nscalar loops %s, vector loops vectorised by the compiler:\n",
           NOVEC_OK ? "kept scalar (NOVEC)" : "MAY BE VECTORISED (no NOVEC here)");
    b = b_bare_evalf;
    row("bare HG eval (float, scalar)", b_bare_evalf, NULL, NULL);
    row("mist_hg_evalf", b_hg_evalf, "bare", b);
    b = b_bare_eval;
    row("bare HG eval (double, scalar)", b_bare_eval, NULL, NULL);
    row("mist_hg_eval", b_hg_eval, "bare", b);
    b = b_hg_sample_printed;
    row("eq. 3 HG sample (float, scalar)", b_hg_sample_printed, NULL, NULL);
    row("mist_hg_samplef", b_hg_samplef, "eq. 3", b);
    b = b_bare_sample;
    row("eq. 3 HG sample (double, scalar)", b_bare_sample, NULL, NULL);
    row("mist_hg_sample", b_hg_sample, "eq. 3", b);
    row("mist_hg_sample (no fma: Dekker's product)", b_hg_sample_nold, "eq. 3", b);
    row("  the same at g .5", b_hg_sample_nold5, "eq. 3", b);
    row("  the same at g .3", b_hg_sample_nold3, "eq. 3", b);
    row("  the same at g .1", b_hg_sample_nold1, "eq. 3", b);
    printf("g at run time (read once), baseline with the same g:\n");
    row("mist_hg_evalf", b_hg_evalf_unprep, "bare", b_bare_evalf_rt);
    row("mist_hg_eval", b_hg_eval_rt, "bare", b_bare_eval_rt);
    row("mist_hg_samplef", b_hg_samplef_unprep, "eq. 3", b_eq3f_rt);
    row("mist_hg_sample", b_hg_sample_rt, "eq. 3", b_eq3_rt);
    printf("g new each call (float; in [.05, .95], then of random sign):\n");
    row("mist_hg_evalf", b_hg_evalf_gv, "bare", b_bare_evalf_gv);
    row("mist_hg_samplef", b_hg_samplef_gv, "eq. 3", b_eq3f_gv);
    row("mist_hg_evalf (random sign)", b_hg_evalf_gs, "bare", b_bare_evalf_gs);
    row("mist_hg_samplef (random sign)", b_hg_samplef_gs, "eq. 3", b_eq3f_gs);
    b = v_bare_evalf;
    row("bare HG eval (float, vector)", v_bare_evalf, NULL, NULL);
    row("mist_hg_eval_nf", n_hg_evalf, "bare", b);
    b = v_bare_eval;
    row("bare HG eval (double, vector)", v_bare_eval, NULL, NULL);
    row("mist_hg_eval_n", n_hg_eval, "bare", b);
    b = v_bare_samplef;
    row("eq. 3 HG sample (float, vector)", v_bare_samplef, NULL, NULL);
    row("mist_hg_sample_nf", n_hg_samplef, "eq. 3", b);
    b = v_bare_sample;
    row("eq. 3 HG sample (double, vector)", v_bare_sample, NULL, NULL);
    row("mist_hg_sample_n", n_hg_sample, "eq. 3", b);
    row("mist_hg_sample_n (no fma: Dekker's product)", n_hg_sample_nold, "eq. 3", b);
    b = v_eq6f;
    row("eq. 6 Draine sample (float, array)", v_eq6f, NULL, NULL);
    row("mist_phase_sample_nf (Draine)", n_phase_dr_samplef, "eq. 6", b);
}

static void batch_rows(void)
{
    printf("\nBatch forms (ns per element, n = %d) against a loop of scalar calls:\n", N);
    row_speedup("mist_hg_eval_nf", n_hg_evalf, b_hg_evalf);
    row_speedup("mist_hg_eval_n", n_hg_eval, b_hg_eval);
    row_speedup("mist_hg_sample_nf", n_hg_samplef, b_hg_samplef);
#if defined(BENCH_FMA)
    row_speedup("mist_hg_sample_n (double-double)", n_hg_sample, b_hg_sample);
#else
    row_speedup("mist_hg_sample_n (Dekker's product, a loop)", n_hg_sample, b_hg_sample);
#endif
    row_speedup("mist_hg_sample_n (no fma: Dekker's, a loop)", n_hg_sample_nold, b_hg_sample_nold);
    row_speedup("mist_draine_eval_nf (g .5, a 17)", n_draine_evalf, b_draine_evalf);
    row_speedup("mist_draine_eval_n  (g .5, a 17)", n_draine_eval, b_draine_eval);
    row_speedup(mist__draine_vnf(0.5f, 17.f, N) ? "mist_draine_sample_nf (.5, 17: eq. 6 kernel)"
                : "mist_draine_sample_nf (.5, 17: prepares once)", n_draine_samplef,
                b_draine_samplef);
    row_speedup(mist__draine_vn(0.5, 17., N) ? "mist_draine_sample_n  (.5, 17: eq. 6 kernel)"
                : "mist_draine_sample_n  (.5, 17: prepares once)", n_draine_sample,
                b_draine_sample);
    row_speedup("mist_draine_sample_nf (.5, 17, n = 64 each)", n_draine_samplef_64,
                b_draine_samplef);
    row_speedup("mist_draine_sample_n  (.5, 17, n = 64 each)", n_draine_sample_64,
                b_draine_sample);
    row_speedup("mist_draine_sample_nf (0, 1: prepares once)", n_draine_samplef_g0,
                b_draine_samplef_g0);
    row_speedup("mist_draine_sample_nf (.9999, 17)", n_draine_samplef_1, b_draine_samplef_1);
    row_speedup("mist_draine_sample_n  (0, 1: prepares once)", n_draine_sample_g0,
                b_draine_sample_g0);
    row_speedup("mist_draine_sample_nf (0, 1, n = " STR(MIST_DRAINE_PREPARE_N) " each)",
                n_draine_samplef_chunk, b_draine_samplef_g0);
    row_speedup("mist_draine_sample_n  (0, 1, n = " STR(MIST_DRAINE_PREPARE_N) " each)",
                n_draine_sample_chunk, b_draine_sample_g0);
    row_speedup("mist_phase_eval_nf (Draine .5, 17)", n_phase_dr_evalf, b_phase_draine_evalf);
    row_speedup("mist_phase_sample_nf (Draine .5, 17)", n_phase_dr_samplef,
                b_phase_draine_samplef);
    row_speedup("mist_phase_sample_nf (Draine .999, 17)", n_phase_dr999_samplef,
                b_phase_dr999_samplef);
#if defined(BENCH_FMA)
    row_speedup("mist_phase_sample_n  (Draine, double-double)", n_phase_dr_sample,
                b_phase_draine_sample);
#else
    row_speedup("mist_phase_sample_n  (Draine, loop)", n_phase_dr_sample, b_phase_draine_sample);
#endif
    row_speedup("mist_phase_sample_nf (fog 10 um)", n_phase_fog_samplef, b_phase_fog_samplef);
    row_speedup("mist_phase_sample_nf (fog, n = 64 each)", n_phase_fog_samplef_64,
                b_phase_fog_samplef);
    row_speedup("mist_phase_sample_n  (fog 10 um)", n_phase_fog_sample, b_phase_fog_sample);
    row_speedup("mist_fog_sample_nf (10 um)", n_fog_samplef, b_fog_samplef10);
    row_speedup("mist_fog_sample_n  (10 um)", n_fog_sample, b_fog_sample10);
    row_speedup("mist_phase_eval_nf (fog 10 um)", n_phase_fog_evalf, b_phase_fog_evalf);
    row_speedup("mist_phase_eval_n  (fog 10 um)", n_phase_fog_eval, b_phase_fog_eval);
    row_speedup("mist_fog_eval_nf (10 um)", n_fog_evalf, b_fog_evalf10);
    row_speedup("mist_fog_eval_n  (10 um)", n_fog_eval, b_fog_eval10);
    row_speedup("mist_rayleigh_eval_nf", n_rayleigh_evalf, b_rayleigh_evalf);
    row_speedup("mist_rayleigh_eval_n", n_rayleigh_eval, b_rayleigh_eval);
    row_speedup("mist_rayleigh_sample_nf", n_rayleigh_samplef, b_rayleigh_samplef);
#if defined(BENCH_FMA)
    row_speedup("mist_rayleigh_sample_n (double-double)", n_rayleigh_sample, b_rayleigh_sample);
#else
    row_speedup("mist_rayleigh_sample_n (Dekker's product)", n_rayleigh_sample, b_rayleigh_sample);
#endif
    row_speedup("mist_rayleigh_sample_n (no fma: Dekker's product)", n_rayleigh_sample_nold,
                b_rayleigh_sample_nold);
}

/* Lorenz-Mie, the single sphere (water at 550 nm, size parameter x): the
 * series (mist_mie_sphere_make) against the textbook series of [BH83]
 * Appendix A typed in (tests/mist_printed.h: bhmie_printed), the phase
 * function and amplitudes at one cosine against BHMIE's angle sums, and
 * the table form (mist_mie_phase_table) against a loop of
 * mist_mie_phase.  Each bench function makes mie_calls calls (sized to
 * ~1 ms); the rows print per call (mie_row). */
static double mie_x;
static int mie_calls;
static mist_mie_complex mie_m;
static double *mie_work, *mie_d, *mie_ab, mie_q, mie_mu[N], mie_p[N];
static size_t mie_nwork;
static int mie_nstop;
static mist_mie_sphere mie_s;
static double m_make(void)
{
    double s_ = 0;
    int i;
    for (i = 0; i < mie_calls; ++i) {
        mist_mie_sphere s = mist_mie_sphere_make(mie_x * (1 + 1e-3 * xd[i]), mie_m, mie_work,
                                                 mie_nwork);
        s_ += s.q_sca;
    }
    return s_;
}
static double m_bhmie(void)
{
    double s_ = 0, q;
    int i;
    for (i = 0; i < mie_calls; ++i) {
        (void)bhmie_printed(mie_x * (1 + 1e-3 * xd[i]), mie_m.re, mie_m.im, mie_d, mie_ab, &q);
        s_ += q;
    }
    return s_;
}
static double m_phase(void)
{
    double s_ = 0;
    int i;
    for (i = 0; i < mie_calls; ++i) s_ += mist_mie_phase(&mie_s, mie_mu[i]);
    return s_;
}
static double m_amp(void)
{
    double s_ = 0;
    int i;
    for (i = 0; i < mie_calls; ++i) {
        mist_mie_complex s1, s2;
        mist_mie_amplitudes(&mie_s, mie_mu[i], &s1, &s2);
        s_ += s1.re + s2.im;
    }
    return s_;
}
static double m_table(void)
{
    mist_mie_phase_table(&mie_s, mie_mu, (size_t)mie_calls, mie_p);
    return mie_p[mie_calls / 2];
}
static double m_bhphase(void)
{
    double s_ = 0;
    int i;
    for (i = 0; i < mie_calls; ++i) s_ += bhmie_phase_printed(mie_ab, mie_nstop, mie_q, mie_mu[i]);
    return s_;
}
static double m_water(void)
{
    double s_ = 0;
    int i;
    for (i = 0; i < mie_calls; ++i) s_ += mist_mie_water(200 + 1000 * xd[i], NULL).re;
    return s_;
}
/* a row of mie_calls calls a bench function: per call (row_k) */
static void mie_row(const char *name, bench_fn f, const char *base_name, bench_fn base)
{
    row_k(name, f, base_name, base, (double)N / mie_calls);
}
static void mie_rows(void)
{
    static const double xs[4] = { 1, 10, 100, 1000 };
    int i, j, nmx;
    mie_m = mist_mie_water(550, NULL);
    printf("\nLorenz-Mie (mist_mie.h), one sphere of water at 550 nm (m = %.4f + %.2g i), size "
           "parameter x; per call;\nagainst the textbook series of [BH83] Appendix A typed in "
           "(BHMIE: tests/mist_printed.h), and how far\nBHMIE's p(mu) is from mist's (the "
           "largest relative difference over the cosines; mist's p is within\n5e-12 of an "
           "mpmath series to x = 1000: test_mie):\n", mie_m.re, mie_m.im);
    for (j = 0; j < 4; ++j) {
        double dmax = 0;
        mie_x = xs[j];
        mie_nwork = mist_mie_workspace_size(mie_x * 1.001);
        nmx = bhmie_nmx(mie_x * 1.001, mie_m.re, mie_m.im);
        mie_work = (double *)malloc(mie_nwork * sizeof(double));
        mie_d = (double *)malloc(2 * ((size_t)nmx + 1) * sizeof(double));
        mie_ab = (double *)malloc(4 * (size_t)bhmie_nstop(mie_x * 1.001) * sizeof(double));
        if (!mie_work || !mie_d || !mie_ab) { printf("  (out of memory)\n"); return; }
        mie_s = mist_mie_sphere_make(mie_x, mie_m, mie_work, mie_nwork);
        mie_nstop = bhmie_printed(mie_x, mie_m.re, mie_m.im, mie_d, mie_ab, &mie_q);
        for (i = 0; i < N; ++i) {
            double pm, pb;
            mie_mu[i] = ud[i];
            pm = mist_mie_phase(&mie_s, ud[i]);
            pb = bhmie_phase_printed(mie_ab, mie_nstop, mie_q, ud[i]);
            if (fabs(pm - pb) > dmax * pm) dmax = fabs(pm - pb) / pm;
        }
        printf("x = %g: mist %d terms, BHMIE %d; BHMIE's p(mu) off by up to %.1e over %d "
               "cosines\n", mie_x, mie_s.n_terms, mie_nstop, dmax, N);
        mie_calls = mie_x >= 1000 ? 8 : (mie_x >= 100 ? 64 : (mie_x >= 10 ? 256 : 1024));
        mie_row("  BHMIE series as printed", m_bhmie, NULL, NULL);
        mie_row("  mist_mie_sphere_make", m_make, "BHMIE", m_bhmie);
        mie_calls = mie_x >= 1000 ? 128 : (mie_x >= 100 ? 1024 : N);
        mie_row("  BHMIE angle sums at one mu", m_bhphase, NULL, NULL);
        mie_row("  mist_mie_phase", m_phase, "BHMIE sums", m_bhphase);
        mie_row("  mist_mie_amplitudes", m_amp, "mist_mie_phase", m_phase);
        mie_row("  mist_mie_phase_table, per angle", m_table, "mist_mie_phase", m_phase);
        free(mie_work); free(mie_d); free(mie_ab);
    }
    mie_calls = N;
    mie_row("mist_mie_water (200-1200 nm)", m_water, NULL, NULL);
}

/* ---- every other public function ------------------------------------------ */

/* The rest of the public evaluation and sampling functions (every
 * public evaluation and sampling function, float and double), each beside
 * a baseline of the same run: the formula as printed (tests/mist_printed.h)
 * where there is one, else the scalar function it builds on (the direction
 * samplers against their u samplers: the cost of the direction), else its
 * float version. */
static const float  cs_g = 0.7f;
static mist_phasef  ph_rlf;
static mist_phase   ph_rl;
static mist_fog     fog_d;
static mist_fogf    fog_f;
#define DIRLOOP(T, V3, CALL) { V3 wi = { (T)0.48, (T)-0.6, (T)0.64 }, wo; T pdf = 0, s_ = 0; \
    int i; for (i = 0; i < N; ++i) { wo = CALL; s_ += wo.x + pdf; } return (double)s_; }
#define XI2F xf[N - 1 - i]
#define XI2D xd[N - 1 - i]
static double c_eq5f(void)           LOOP(float, draine_eval_printed(0.5f, 17.f, uf[i]))
static double c_eq5f_cs(void)        LOOP(float, draine_eval_printed(cs_g, 1.f, uf[i]))
static double c_cs_evalf(void)       LOOP(float, mist_cs_evalf(cs_g, uf[i]))
static double c_cs_eval(void)        LOOP(double, mist_cs_eval(cs_g, ud[i]))
static double c_rl_printedf(void)    LOOP(float, rayleigh_eval_printed(uf[i]))
static double c_fog_printedf(void)   LOOP(float, fog_eval_printed(fog_f.g_hg, fog_f.g_d,
                                                                  fog_f.alpha, fog_f.w_d, uf[i]))
static double c_fog_eval(void)       LOOP(double, mist_fog_eval(fog_d, ud[i]))
static double c_phase_dr_eval(void)  LOOP(double, mist_phase_eval(&ph_dr, ud[i]))
static double c_phase_rl_evalf(void) LOOP(float, mist_phase_evalf(&ph_rlf, uf[i]))
static double c_phase_rl_eval(void)  LOOP(double, mist_phase_eval(&ph_rl, ud[i]))
static double c_cs_sample(void)      LOOP(double, mist_cs_sample(cs_g, xd[i]))
static double c_fog_samplef(void)    LOOP(float, mist_fog_samplef(fog_f, xf[i]))
static double c_fog_sample(void)     LOOP(double, mist_fog_sample(fog_d, xd[i]))
static double c_phase_rl_samplef(void) LOOP(float, mist_phase_samplef(&ph_rlf, xf[i]))
static double c_phase_rl_sample(void)  LOOP(double, mist_phase_sample(&ph_rl, xd[i]))
static double c_phase_eval_n(void)   NCALL(double, mist_phase_eval_n(&ph_dr, ud, out_double, N))
static double c_fit(void)
{
    double s_ = 0;
    int i;
    for (i = 0; i < N; ++i) {
        mist_fog f = mist_fog_from_diameter(5 + 45 * xd[i]);
        s_ += f.g_hg + f.g_d + f.alpha + f.w_d;
    }
    return s_;
}
/* directions: mist's, against a bare [DHB17] basis typed in (wi taken as
 * unit, no checks) and a bare normalisation */
#define BARE_DIR(T, SQRT, COS, SIN)                                            \
    T sg = n.z >= 0 ? (T)1 : (T)-1, a = -1 / (sg + n.z), b = n.x * n.y * a;    \
    T sn = SQRT(1 - u * u), ph = (T)MIST__2PI * xi, c = sn * COS(ph), d = sn * SIN(ph); \
    r.x = u * n.x + c * (1 + sg * n.x * n.x * a) + d * b;                      \
    r.y = u * n.y + c * (sg * b) + d * (sg + n.y * n.y * a);                   \
    r.z = u * n.z - c * (sg * n.x) - d * n.y;                                  \
    return r;
static mist_vec3f bare_dirf(mist_vec3f n, float u, float xi)
{ mist_vec3f r; BARE_DIR(float, sqrtf, cosf, sinf) }
static mist_vec3 bare_dir(mist_vec3 n, double u, double xi)
{ mist_vec3 r; BARE_DIR(double, sqrt, cos, sin) }
#define BARE_NORM(T, V3, SQRT) { V3 r; T k = 1 / SQRT(v.x * v.x + v.y * v.y + v.z * v.z); \
                                 r.x = v.x * k; r.y = v.y * k; r.z = v.z * k; return r; }
static mist_vec3f bare_normf(mist_vec3f v) BARE_NORM(float, mist_vec3f, sqrtf)
static mist_vec3  bare_norm(mist_vec3 v)   BARE_NORM(double, mist_vec3, sqrt)
static double c_bare_dirf(void)  DIRLOOP(float, mist_vec3f, bare_dirf(wi, uf[i], XI2F))
static double c_bare_dir(void)   DIRLOOP(double, mist_vec3, bare_dir(wi, ud[i], XI2D))
static double c_dirf(void)       DIRLOOP(float, mist_vec3f, mist_dir_from_cosf(wi, uf[i], XI2F))
static double c_dir(void)        DIRLOOP(double, mist_vec3, mist_dir_from_cos(wi, ud[i], XI2D))
#define NLOOP(T, V3, F) { V3 v; T s_ = 0; int i; for (i = 0; i < N; ++i) { \
    v.x = (T)ud[i]; v.y = (T)ud[N - 1 - i]; v.z = (T)0.3; v = F(v); NOVEC(v.x); s_ += v.x; } \
    return s_; }   /* (NOVEC: gcc had vectorised the double loops, bare and mist's) */
static double c_bare_normf(void) NLOOP(float, mist_vec3f, bare_normf)
static double c_bare_norm(void)  NLOOP(double, mist_vec3, bare_norm)
static double c_normf(void)      NLOOP(float, mist_vec3f, mist_normalizef)
static double c_norm(void)       NLOOP(double, mist_vec3, mist_normalize)
static double c_hg_dir(void)     DIRLOOP(double, mist_vec3, mist_hg_sample_dir(0.8, wi, xd[i], XI2D, &pdf))
static double c_dr_dirf(void)    DIRLOOP(float, mist_vec3f,
                                         mist_draine_sample_dirf(0.5f, 17.f, wi, xf[i], XI2F, &pdf))
static double c_dr_dir(void)     DIRLOOP(double, mist_vec3,
                                         mist_draine_sample_dir(0.5, 17., wi, xd[i], XI2D, &pdf))
static double c_cs_dirf(void)    DIRLOOP(float, mist_vec3f, mist_cs_sample_dirf(cs_g, wi, xf[i], XI2F, &pdf))
static double c_cs_dir(void)     DIRLOOP(double, mist_vec3, mist_cs_sample_dir(cs_g, wi, xd[i], XI2D, &pdf))
static double c_rl_dirf(void)    DIRLOOP(float, mist_vec3f, mist_rayleigh_sample_dirf(wi, xf[i], XI2F, &pdf))
static double c_rl_dir(void)     DIRLOOP(double, mist_vec3, mist_rayleigh_sample_dir(wi, xd[i], XI2D, &pdf))
static double c_fog_dirf(void)   DIRLOOP(float, mist_vec3f, mist_fog_sample_dirf(fog_f, wi, xf[i], XI2F, &pdf))
static double c_fog_dir(void)    DIRLOOP(double, mist_vec3, mist_fog_sample_dir(fog_d, wi, xd[i], XI2D, &pdf))
static double c_ph_dirf(void)    DIRLOOP(float, mist_vec3f,
                                         mist_phase_sample_dirf(&ph_drf, wi, xf[i], XI2F, &pdf))
static double c_ph_dir(void)     DIRLOOP(double, mist_vec3,
                                         mist_phase_sample_dir(&ph_dr, wi, xd[i], XI2D, &pdf))

/* the height fog [I18]: a layer of haze and fog (coefficients per metre at
 * the base, scale height 120 m), rays from heights 0-500 m in random
 * directions over 1-2000 m; against eq. 22-23 typed in (three channels,
 * the same phase values, tests/mist_printed.h: hfog_printed) */
static mist_hfogf hff[2];
static mist_hfog  hfd[2];
static mist_vec3f ray_of[N], ray_df[N];
static mist_vec3  ray_od[N], ray_dd[N];
static float ray_sf[N];
static int hfog_deep;   /* 1: rays go on below the base (to y = -1500), into fog e^12 denser */
static double ray_sd[N];
static mist_rgbf bg_f = { 1, 1, 1 };
static mist_rgb  bg_d = { 1, 1, 1 };
static mist_rgbf bgs_f[N];
static mist_rgb  bgs_d[N];
#define HFOG_INIT(F, T)                                                        \
    F[0].base = 0; F[0].density = 1; F[0].scale_height = 120;                  \
    F[0].rayleigh_scat.r = (T)5.8e-6; F[0].rayleigh_scat.g = (T)1.35e-5;       \
    F[0].rayleigh_scat.b = (T)3.31e-5; F[0].rayleigh_ext = F[0].rayleigh_scat; \
    F[0].mie_scat.r = F[0].mie_scat.g = F[0].mie_scat.b = (T)2e-3;             \
    F[0].mie_ext.r = F[0].mie_ext.g = F[0].mie_ext.b = (T)2.2e-3;              \
    F[0].sun_dir.x = (T)0.3; F[0].sun_dir.y = (T)0.5; F[0].sun_dir.z = (T)0.812404; \
    F[0].sun.r = 1; F[0].sun.g = (T)0.95; F[0].sun.b = (T)0.9;                 \
    F[0].ambient.r = (T)0.1; F[0].ambient.g = (T)0.12; F[0].ambient.b = (T)0.15; \
    F[0].sun_extinction = 0;                                                   \
    F[1] = F[0]; F[1].base = 300; F[1].scale_height = 800; F[1].density = (T)0.2;
static void hfog_setup(void)
{
    int i;
    memset(hff, 0, sizeof hff);
    memset(hfd, 0, sizeof hfd);
    hff[0].mie_phase = fog_f;
    hfd[0].mie_phase = fog_d;
    HFOG_INIT(hff, float)
    HFOG_INIT(hfd, double)
    for (i = 0; i < N; ++i) {
        double z = ud[i], t = MIST__2PI * xd[(i * 7 + 3) % N], r = sqrt(1 - z * z);
        ray_od[i].x = 0; ray_od[i].y = 500 * xd[(i * 13 + 5) % N]; ray_od[i].z = 0;
        ray_dd[i].x = r * cos(t); ray_dd[i].y = z; ray_dd[i].z = r * sin(t);
        ray_sd[i] = 1 + 1999 * xd[(i * 29 + 11) % N];
        if (hfog_deep == 0 && z < 0 && ray_od[i].y + z * ray_sd[i] < 0)
            ray_sd[i] = ray_od[i].y / -z;           /* the ray ends on the ground, y = 0 */
        ray_of[i].x = (float)ray_od[i].x; ray_of[i].y = (float)ray_od[i].y; ray_of[i].z = 0;
        ray_df[i].x = (float)ray_dd[i].x; ray_df[i].y = (float)ray_dd[i].y;
        ray_df[i].z = (float)ray_dd[i].z;
        ray_sf[i] = (float)ray_sd[i];
        bgs_f[i] = bg_f; bgs_d[i] = bg_d;
    }
}
/* eq. 22-23 for one ray, three channels, background 1 */
#define PRINTED_RAY(T, FN, F, O, D, S)                                                 \
    T u = F.sun_dir.x * D.x + F.sun_dir.y * D.y + F.sun_dir.z * D.z;                   \
    T pr = rayleigh_eval_printed((float)u), pm = fog_eval_printed(F.mie_phase.g_hg,    \
        F.mie_phase.g_d, F.mie_phase.alpha, F.mie_phase.w_d, (float)u);                \
    T y0 = O.y - F.base, H = F.scale_height;                                           \
    T r_ = FN(1, y0, D.y, S, H, F.rayleigh_ext.r + F.mie_ext.r, F.rayleigh_scat.r * (pr * F.sun.r \
              + F.ambient.r) + F.mie_scat.r * (pm * F.sun.r + F.ambient.r));           \
    T g_ = FN(1, y0, D.y, S, H, F.rayleigh_ext.g + F.mie_ext.g, F.rayleigh_scat.g * (pr * F.sun.g \
              + F.ambient.g) + F.mie_scat.g * (pm * F.sun.g + F.ambient.g));           \
    T b_ = FN(1, y0, D.y, S, H, F.rayleigh_ext.b + F.mie_ext.b, F.rayleigh_scat.b * (pr * F.sun.b \
              + F.ambient.b) + F.mie_scat.b * (pm * F.sun.b + F.ambient.b));
#define PRINTED_LOOP(T, FN, F, O, D, S) { T s_ = 0; int i; for (i = 0; i < N; ++i) { \
    PRINTED_RAY(T, FN, F, O[i], D[i], S[i]) s_ += r_ + g_ + b_; } return s_; }
static double c_hf_printedf(void) PRINTED_LOOP(float, hfog_printedf, hff[0], ray_of, ray_df, ray_sf)
static double c_hf_printed(void)  PRINTED_LOOP(double, hfog_printed, hfd[0], ray_od, ray_dd, ray_sd)
#define RGBLOOP(T, RGB, CALL) { T s_ = 0; int i; for (i = 0; i < N; ++i) { RGB c_ = CALL; \
    s_ += c_.r + c_.g + c_.b; } return s_; }
static double c_hf_trf(void) RGBLOOP(float, mist_rgbf,
                                     mist_hfog_transmittancef(hff, ray_of[i], ray_df[i], ray_sf[i]))
static double c_hf_tr(void)  RGBLOOP(double, mist_rgb,
                                     mist_hfog_transmittance(hfd, ray_od[i], ray_dd[i], ray_sd[i]))
static double c_hf_inf(void) RGBLOOP(float, mist_rgbf,
                                     mist_hfog_inscatterf(hff, ray_of[i], ray_df[i], ray_sf[i]))
static double c_hf_in(void)  RGBLOOP(double, mist_rgb,
                                     mist_hfog_inscatter(hfd, ray_od[i], ray_dd[i], ray_sd[i]))
static double c_hf_apf(void) RGBLOOP(float, mist_rgbf,
                                     mist_hfog_applyf(hff, ray_of[i], ray_df[i], ray_sf[i], bg_f))
static double c_hf_ap(void)  RGBLOOP(double, mist_rgb,
                                     mist_hfog_apply(hfd, ray_od[i], ray_dd[i], ray_sd[i], bg_d))
/* the batch form over the same rays (a fog pass), against its scalar loop */
static mist_rgbf out_rgbf[N];
static mist_rgb  out_rgb[N];
static double c_hf_apnf(void) { mist_hfog_apply_nf(hff, ray_of, ray_df, ray_sf, bgs_f, out_rgbf, N);
                                return out_rgbf[N / 2].g; }
static double c_hf_apn(void)  { mist_hfog_apply_n(hfd, ray_od, ray_dd, ray_sd, bgs_d, out_rgb, N);
                                return out_rgb[N / 2].g; }
#define EVLOOP(T, RGB, FN, F, O, D, S) { T s_ = 0; int i; for (i = 0; i < N; ++i) { RGB t_, l_; \
    FN(F, O[i], D[i], S[i], &t_, &l_); s_ += t_.r + l_.g; } return s_; }
static double c_hf_evf(void) EVLOOP(float, mist_rgbf, mist_hfog_evalf, hff, ray_of, ray_df, ray_sf)
static double c_hf_ev(void)  EVLOOP(double, mist_rgb, mist_hfog_eval, hfd, ray_od, ray_dd, ray_sd)
#define LYLOOP(T, RGB, FN, F, O, D, S) { T s_ = 0; int i; for (i = 0; i < N; ++i) { RGB t_, l_, e_; \
    FN(F, 2, O[i], D[i], S[i], 8, &t_, &l_, &e_); s_ += t_.r + l_.g; } return s_; }
static double c_hf_lyf(void) LYLOOP(float, mist_rgbf, mist_hfog_layers_evalf, hff, ray_of, ray_df, ray_sf)
static double c_hf_ly(void)  LYLOOP(double, mist_rgb, mist_hfog_layers_eval, hfd, ray_od, ray_dd, ray_sd)
/* the column alone against eq. 14's exponent as printed */
static double c_col_printedf(void) LOOP(float, 120.f / ray_df[i].y * expf(-ray_of[i].y / 120.f)
                                             * (1 - expf(-ray_df[i].y * ray_sf[i] / 120.f)))
static double c_colf(void) LOOP(float, mist_hfog_columnf(hff, ray_of[i].y, ray_df[i].y, ray_sf[i]))
static double c_col(void)  LOOP(double, mist_hfog_column(hfd, ray_od[i].y, ray_dd[i].y, ray_sd[i]))
/* a free-flight distance (channel g, xi from the table, tmax the ray's
 * length): against the closed-form inversion of eq. 14 typed in as
 * printed, t = -(H/w) ln(1 - w e^(y0/H) (-ln(1 - xi)) / (H st)), with its
 * two tests (it escapes: the logarithm's argument <= 0; beyond tmax) */
#define SD_PRINTED(T, EXP, LOG, F, O, D, S, X) {                                     \
    T st_ = F[0].rayleigh_ext.g + F[0].mie_ext.g, H_ = F[0].scale_height;             \
    T a_ = 1 - D.y * -LOG(1 - X) * EXP((O.y - F[0].base) / H_) / (H_ * st_), t_;      \
    t_ = a_ > 0 ? -H_ / D.y * LOG(a_) : (T)INFINITY;                                   \
    v_ = t_ <= S ? t_ : (T)INFINITY; }
static float sd_printedf(int i)
{
    float v_;
    SD_PRINTED(float, expf, logf, hff, ray_of[i], ray_df[i], ray_sf[i], xf[(i * 17 + 1) % N])
    return v_;
}
static double sd_printed(int i)
{
    double v_;
    SD_PRINTED(double, exp, log, hfd, ray_od[i], ray_dd[i], ray_sd[i], xd[(i * 17 + 1) % N])
    return v_;
}
static double c_sd_printedf(void) LOOP(float, sd_printedf(i))
static double c_sd_printed(void)  LOOP(double, sd_printed(i))
static double c_sdf(void) LOOP(float, mist_hfog_sample_distancef(hff, ray_of[i], ray_df[i],
                                                                ray_sf[i], 1, xf[(i * 17 + 1) % N]))
static double c_sd(void)  LOOP(double, mist_hfog_sample_distance(hfd, ray_od[i], ray_dd[i],
                                                                ray_sd[i], 1, xd[(i * 17 + 1) % N]))
static double c_odf(void) RGBLOOP(float, mist_rgbf,
                                  mist_hfog_optical_depthf(hff, ray_of[i], ray_df[i], ray_sf[i]))
static double c_od(void)  RGBLOOP(double, mist_rgb,
                                  mist_hfog_optical_depth(hfd, ray_od[i], ray_dd[i], ray_sd[i]))
static void sd_rows(void)
{
    printf("free-flight distances (one channel, xi uniform, tmax the ray's length):\n");
    row("eq. 14 inverted as printed (float)", c_sd_printedf, NULL, NULL);
    row("mist_hfog_sample_distancef", c_sdf, "printed", c_sd_printedf);
    row("eq. 14 inverted as printed (double)", c_sd_printed, NULL, NULL);
    row("mist_hfog_sample_distance", c_sd, "printed", c_sd_printed);
    row("mist_hfog_optical_depthf (3 channels)", c_odf, "printed", c_sd_printedf);
    row("mist_hfog_optical_depth (3 channels)", c_od, "printed", c_sd_printed);
}

/* a ray-march step: against the constant-coefficient step a renderer
 * might use instead, s/k (1 - e^(-k L)) with the mean k and s */
static float seg_constf(float k0, float k1, float s0, float s1, float L)
{
    float k = (k0 + k1) / 2, s = (s0 + s1) / 2;
    return s / k * (1 - expf(-k * L));
}
static double c_seg_constf(void) LOOP(float, seg_constf(uf[i] + 1.5f, xf[i], 0.5f + xf[N - 1 - i],
                                                        0.2f, 0.01f + 4 * xf[(i * 7) % N]))
static double c_segf(void) LOOP(float, mist_segment_linearf(uf[i] + 1.5f, xf[i], 0.5f + xf[N - 1 - i],
                                                           0.2f, 0.01f + 4 * xf[(i * 7) % N], NULL))
static double c_seg(void)  LOOP(double, mist_segment_linear(ud[i] + 1.5, xd[i], 0.5 + xd[N - 1 - i],
                                                           0.2, 0.01 + 4 * xd[(i * 7) % N], NULL))

/* Preparing a medium (mist_phase_*, mist_fog_make): microseconds per call,
 * median of REPS calls (the Draine table is the cost: its nodes by the
 * unprepared batch sampler's eq. 6 kernel where that applies, else by the
 * scalar sampler, as at g ~ 0 (cases 4, 5: outside eq. 6's domain)). */
static double prep_us(int which)
{
    static mist_phasef pf;                      /* scratch, not the rows' media */
    static mist_phase  pd;
    double t[REPS];
    int i;
    for (i = 0; i < REPS; ++i) {
        double t0 = now();
        switch (which) {
        case 0: pf = mist_phase_drainef(0.5f + 1e-3f * (float)i, 17.f); sink += pf.tab[5]; break;
        case 1: pd = mist_phase_draine(0.5 + 1e-3 * i, 17.); sink += pd.tab[5]; break;
        case 2: pf = mist_phase_fogf(mist_fog_from_diameterf(5.f + (float)i)); sink += pf.tab[5];
                break;
        case 3: pd = mist_phase_fog(mist_fog_from_diameter(5. + i)); sink += pd.tab[5]; break;
        case 4: pf = mist_phase_drainef(1e-6f * (float)i, 1.f); sink += pf.tab[5]; break;
        default: pd = mist_phase_draine(1e-6 * i, 1.); sink += pd.tab[5]; break;
        }
        t[i] = (now() - t0) * 1e6;
    }
    sort(t, REPS);
    return t[REPS / 2];
}
static double c_prep_hgf(void) { float s_ = 0; int i; for (i = 0; i < N; ++i) {
    mist_phasef p = mist_phase_hgf(uf[i]); s_ += p.a1; } return s_; }
static double c_fog_makef(void) { float s_ = 0; int i; for (i = 0; i < N; ++i) {
    mist_fogf f = mist_fog_makef(uf[i], 0.5f, 17.f * xf[i], xf[N - 1 - i]); s_ += f.alpha; } return s_; }
static double c_fog_make(void) { double s_ = 0; int i; for (i = 0; i < N; ++i) {
    mist_fog f = mist_fog_make(ud[i], 0.5, 17. * xd[i], xd[N - 1 - i]); s_ += f.alpha; } return s_; }

static void compact_rows(void)
{
    pc_fogf = mist_phasec_fogf(fog10f);
    pc_fog = mist_phasec_fog(fog10);
    pc_drf = mist_phasec_drainef(0.5f, 17.f);
    pc_dr = mist_phasec_draine(0.5, 17.);
    printf("\nCompact prepared (mist_phasec_*: %zu bytes float, %zu double) against the full "
           "prepared form\n(mist_phase_*: %zu bytes float, %zu double) and the unprepared "
           "functions, same media, same run:\n", sizeof(mist_phasecf), sizeof(mist_phasec),
           sizeof(mist_phasef), sizeof(mist_phase));
    row("mist_phasec_samplef (fog 10 um)", k_fog_samplef, "mist_phase_samplef", b_phase_fog_samplef);
    row("mist_phasec_samplef (fog 10 um)", k_fog_samplef, "mist_fog_samplef", b_fog_samplef_rt);
    row("mist_phasec_samplef (Draine .5, 17)", k_dr_samplef, "mist_phase_samplef",
        b_phase_draine_samplef);
    row("mist_phasec_samplef (Draine .5, 17)", k_dr_samplef, "mist_draine_samplef",
        b_draine_samplef_rt);
    row("mist_phasec_sample (fog 10 um)", k_fog_sample, "mist_phase_sample", b_phase_fog_sample);
    row("mist_phasec_sample (fog 10 um)", k_fog_sample, "mist_fog_sample", b_fog_sample10);
    row("mist_phasec_sample (Draine .5, 17)", k_dr_sample, "mist_phase_sample",
        b_phase_draine_sample);
    row("mist_phasec_sample (Draine .5, 17)", k_dr_sample, "mist_draine_sample",
        b_draine_sample_rt);
    row("mist_phasec_evalf (fog 10 um)", k_fog_evalf, "mist_phase_evalf", b_phase_fog_evalf);
    row("mist_phasec_sample_dirf (fog 10 um)", k_fog_sample_dirf, "mist_phase_sample_dirf",
        k_phase_fog_sample_dirf);
    {
        double lo, hi, cf = measure(k_prep_fogf, &lo, &hi), cd = measure(k_prep_fog, &lo, &hi);
        printf("preparing a fog: mist_phasec_fogf %.3f us, mist_phasec_fog %.3f us; "
               "mist_phase_fogf %.1f us, mist_phase_fog %.1f us (medians of %d)\n",
               cf / 1e3, cd / 1e3, prep_us(2), prep_us(3), REPS);
    }
}

/* the height fog's rows (./mist_bench hfog: these alone) */
static void hfog_rows(void)
{
    bench_fn base;
    hfog_setup();
    printf("\nHeight fog [I18], per ray (three channels), rays ending on the ground "
           "(the fog's base):\n");
    base = c_hf_printedf;
    row("eq. 22-23 as printed (float)", c_hf_printedf, NULL, NULL);
    row("mist_hfog_transmittancef", c_hf_trf, "printed", base);
    row("mist_hfog_inscatterf", c_hf_inf, "printed", base);
    row("mist_hfog_applyf", c_hf_apf, "printed", base);
    row("mist_hfog_evalf", c_hf_evf, "printed", base);
    row("mist_hfog_apply_nf (batch)", c_hf_apnf, "printed", base);
    row_speedup("mist_hfog_apply_nf (batch)", c_hf_apnf, c_hf_apf);
    row("mist_hfog_layers_evalf (2, 8 pieces)", c_hf_lyf, "printed", base);
    base = c_hf_printed;
    row("eq. 22-23 as printed (double)", c_hf_printed, NULL, NULL);
    row("mist_hfog_transmittance", c_hf_tr, "printed", base);
    row("mist_hfog_inscatter", c_hf_in, "printed", base);
    row("mist_hfog_apply", c_hf_ap, "printed", base);
    row("mist_hfog_eval", c_hf_ev, "printed", base);
    row("mist_hfog_apply_n (batch)", c_hf_apn, "printed", base);
    row_speedup("mist_hfog_apply_n (batch)", c_hf_apn, c_hf_ap);
    row("mist_hfog_layers_eval (2, 8 pieces)", c_hf_ly, "printed", base);
    hfog_deep = 1;
    hfog_setup();
    printf("rays going on below the ground, to y = -1500 (fog up to e^12 denser):\n");
    base = c_hf_printedf;
    row("eq. 22-23 as printed (float)", c_hf_printedf, NULL, NULL);
    row("mist_hfog_applyf", c_hf_apf, "printed", base);
    base = c_hf_printed;
    row("eq. 22-23 as printed (double)", c_hf_printed, NULL, NULL);
    row("mist_hfog_apply", c_hf_ap, "printed", base);
    hfog_deep = 0;
    hfog_setup();
    sd_rows();
    base = c_col_printedf;
    row("eq. 14 column as printed (float)", c_col_printedf, NULL, NULL);
    row("mist_hfog_columnf", c_colf, "printed", base);
    row("mist_hfog_column", c_col, "printed", base);
}

static void coverage_rows(void)
{
    bench_fn base;
    fog_f = mist_fog_makef(0.988f, 0.556f, 22.0f, 0.482f);
    fog_d = mist_fog_make(0.988, 0.556, 22.0, 0.482);
    ph_rlf = mist_phase_rayleighf();
    ph_rl = mist_phase_rayleigh();
    hfog_setup();
    printf("\nEvery other public function, against its printed formula, the function it "
           "builds on, or its float version:\n");
    base = c_eq5f;
    row("eq. 5 Draine eval as printed (float)", c_eq5f, NULL, NULL);
    row("mist_draine_evalf (g .5, a 17)", b_draine_evalf, "eq. 5", base);
    row("mist_draine_eval  (g .5, a 17)", b_draine_eval, "eq. 5", base);
    row("mist_phase_eval (Draine .5, 17)", c_phase_dr_eval, "eq. 5", base);
    base = c_eq5f_cs;
    row("eq. 5 at alpha 1 (CS, float)", c_eq5f_cs, NULL, NULL);
    row("mist_cs_evalf (g .7)", c_cs_evalf, "eq. 5", base);
    row("mist_cs_eval  (g .7)", c_cs_eval, "eq. 5", base);
    base = c_rl_printedf;
    row("Rayleigh eval as printed (float)", c_rl_printedf, NULL, NULL);
    row("mist_rayleigh_evalf", b_rayleigh_evalf, "printed", base);
    row("mist_rayleigh_eval", b_rayleigh_eval, "printed", base);
    row("mist_phase_evalf (Rayleigh)", c_phase_rl_evalf, "printed", base);
    row("mist_phase_eval  (Rayleigh)", c_phase_rl_eval, "printed", base);
    base = c_fog_printedf;
    row("eq. 2 + 5 fog mixture as printed", c_fog_printedf, NULL, NULL);
    row("mist_fog_evalf (d = 10 um)", b_fog_evalf, "printed", base);
    row("mist_fog_eval  (d = 10 um)", c_fog_eval, "printed", base);
    base = b_eq6f_cs;
    row("eq. 6 float (g .7, a 1)", b_eq6f_cs, NULL, NULL);
    row("mist_cs_sample (g .7)", c_cs_sample, "eq. 6 float", base);
    base = b_fog_samplef;
    row("mist_fog_sample (d = 10 um)", c_fog_sample, "mist_fog_samplef", base);
    base = b_rayleigh_samplef;
    row("mist_phase_samplef (Rayleigh)", c_phase_rl_samplef, "mist_rayleigh_samplef", base);
    base = b_rayleigh_sample;
    row("mist_phase_sample  (Rayleigh)", c_phase_rl_sample, "mist_rayleigh_sample", base);
    row_speedup("mist_phase_eval_n (Draine .5, 17)", c_phase_eval_n, c_phase_dr_eval);
    base = b_fit_mistf;
    row("mist_fog_from_diameter (5-50 um)", c_fit, "float", base);
    base = c_fog_makef;
    row("mist_fog_makef", c_fog_makef, NULL, NULL);
    row("mist_fog_make", c_fog_make, "float", base);
    row("mist_phase_hgf (prepare HG)", c_prep_hgf, "mist_fog_makef", base);
    printf("%-34s %8.2f us  (median of %d; double: %.2f us)\n", "mist_phase_drainef (prepare)",
           prep_us(0), REPS, prep_us(1));
    printf("%-34s %8.2f us  (median of %d; double: %.2f us)\n", "mist_phase_fogf (prepare)",
           prep_us(2), REPS, prep_us(3));
    printf("%-34s %8.2f us  (median of %d; double: %.2f us)\n", "  the same, Draine g ~ 0, alpha 1",
           prep_us(4), REPS, prep_us(5));

    printf("\nDirections (wi fixed, xi pairs from the stream):\n");
    base = c_bare_dirf;
    row("bare [DHB17] basis (float)", c_bare_dirf, NULL, NULL);
    row("mist_dir_from_cosf", c_dirf, "bare", base);
    base = c_bare_dir;
    row("bare [DHB17] basis (double)", c_bare_dir, NULL, NULL);
    row("mist_dir_from_cos", c_dir, "bare", base);
    base = c_bare_normf;
    row("bare normalisation (float)", c_bare_normf, NULL, NULL);
    row("mist_normalizef", c_normf, "bare", base);
    base = c_bare_norm;
    row("bare normalisation (double)", c_bare_norm, NULL, NULL);
    row("mist_normalize", c_norm, "bare", base);
    row("mist_hg_sample_dir (g .8)", c_hg_dir, "mist_hg_sample", b_hg_sample);
    row("mist_draine_sample_dirf (.5, 17)", c_dr_dirf, "mist_draine_samplef", b_draine_samplef);
    row("mist_draine_sample_dir  (.5, 17)", c_dr_dir, "mist_draine_sample", b_draine_sample);
    row("mist_cs_sample_dirf (g .7)", c_cs_dirf, "mist_cs_samplef", b_cs_samplef);
    row("mist_cs_sample_dir  (g .7)", c_cs_dir, "mist_cs_sample", c_cs_sample);
    row("mist_rayleigh_sample_dirf", c_rl_dirf, "mist_rayleigh_samplef", b_rayleigh_samplef);
    row("mist_rayleigh_sample_dir", c_rl_dir, "mist_rayleigh_sample", b_rayleigh_sample);
    row("mist_fog_sample_dirf (10 um)", c_fog_dirf, "mist_fog_samplef", c_fog_samplef);
    row("mist_fog_sample_dir  (10 um)", c_fog_dir, "mist_fog_sample", c_fog_sample);
    row("mist_phase_sample_dirf (Draine)", c_ph_dirf, "mist_phase_samplef", b_phase_draine_samplef);
    row("mist_phase_sample_dir  (Draine)", c_ph_dir, "mist_phase_sample", b_phase_draine_sample);

    hfog_rows();
    base = c_seg_constf;
    row("constant-coefficient step (float)", c_seg_constf, NULL, NULL);
    row("mist_segment_linearf", c_segf, "constant", base);
    row("mist_segment_linear", c_seg, "constant", base);
}

/* ---- object-code size ---------------------------------------------------- */

/* Sizes of an object file: the whole file, and for ELF64 little-endian (no
 * binutils needed) the bytes of its executable sections and of its other
 * allocated ones (constants, data).  Returns 0 when it cannot be read. */
#if defined(MIST_SIZE_ONE) && defined(MIST_SIZE_ALL)
static int object_size(const char *path, long *file, long *text, long *other)
{
    FILE *f = fopen(path, "rb");
    unsigned char *b;
    long n, i;
    *file = *text = *other = -1;
    if (!f) return 0;
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    fseek(f, 0, SEEK_SET);
    b = (unsigned char *)malloc(n > 0 ? (size_t)n : 1);
    if (!b || fread(b, 1, (size_t)n, f) != (size_t)n) { fclose(f); free(b); return 0; }
    fclose(f);
    *file = n;
    if (n > 64 && b[0] == 0x7f && b[1] == 'E' && b[2] == 'L' && b[3] == 'F'
        && b[4] == 2 && b[5] == 1) {                    /* ELF64, little-endian */
        long shoff = 0, shent = b[0x3a] | b[0x3b] << 8, shnum = b[0x3c] | b[0x3d] << 8;
        for (i = 7; i >= 0; --i) shoff = shoff << 8 | b[0x28 + i];
        *text = *other = 0;
        for (i = 0; i < shnum && shoff + (i + 1) * shent <= n; ++i) {
            const unsigned char *s = b + shoff + i * shent;
            long flags = 0, size = 0, k;
            for (k = 7; k >= 0; --k) flags = flags << 8 | s[8 + k];
            for (k = 7; k >= 0; --k) size = size << 8 | s[32 + k];
            if (flags & 4) *text += size;               /* SHF_EXECINSTR */
            else if (flags & 2) *other += size;         /* SHF_ALLOC */
        }
    }
    free(b);
    return 1;
}
#endif

static void size_rows(void)
{
#if defined(MIST_SIZE_ONE) && defined(MIST_SIZE_ALL)
    const char *path[2] = { MIST_SIZE_ONE, MIST_SIZE_ALL };
    const char *what[2] = { "bench/size_one.c (mist_hg_evalf only)",
                            "bench/size_all.c (every function)" };
    int i;
    printf("\nObject-code size, compiled as this benchmark (bytes):\n");
    for (i = 0; i < 2; ++i) {
        long file, text, other;
        if (!object_size(path[i], &file, &text, &other))
            printf("  %-40s cannot read %s\n", what[i], path[i]);
        else if (text >= 0)
            printf("  %-40s code %7ld  other allocated %6ld  (object file %7ld)\n",
                   what[i], text, other, file);
        else
            printf("  %-40s object file %7ld (not ELF64: code size not read)\n",
                   what[i], file);
    }
#else
    printf("\nObject-code size: build the benchmark with CMake (mist_size_one/all)\n");
#endif
}

/* ---- what renderers ship ---------------------------------------------------- */

/* The samplers a renderer would otherwise use (tests/mist_printed.h: Blender
 * Cycles' and pbrt-v4's HG sampler is eq. 3; Cycles' Draine and Rayleigh
 * samplers take a cube root from the bits), one call at a time and over an
 * array, against mist's exact samplers in float, unprepared and prepared
 * (the medium prepared once, outside the timed loop), in the same run. */
static double r_cy_dr(void)      LOOP(float, draine_cyclesf(0.5f, 17.f, xf[i]))
static double r_cy_ray(void)     LOOP(float, rayleigh_cyclesf(xf[i]))
static double v_cy_dr(void)      VLOOP(float, draine_cyclesf(0.5f, 17.f, xf[i]))
static double v_cy_ray(void)     VLOOP(float, rayleigh_cyclesf(xf[i]))
/* (Cycles' and pbrt-v4's HG sampler is eq. 3: b_hg_sample_printed, and
 * vectorised v_bare_samplef; mist's rows are the ones timed above, on the
 * media prepared in main) */
static void renderer_rows(void)
{
    ph_rlf = mist_phase_rayleighf();
    printf("\nWhat renderers ship (float; HG g .8, Draine g .5, alpha 17), one call at a time:\n");
    row("Cycles / pbrt-v4 HG sample (eq. 3)", b_hg_sample_printed, NULL, NULL);
    row("mist_hg_samplef", b_hg_samplef, "Cycles", b_hg_sample_printed);
    row("mist_phase_samplef (HG)", b_phase_hg_samplef, "Cycles", b_hg_sample_printed);
    row("Cycles Draine sample (eq. 6)", r_cy_dr, NULL, NULL);
    row("mist_draine_samplef", b_draine_samplef, "Cycles", r_cy_dr);
    row("mist_phase_samplef (Draine)", b_phase_draine_samplef, "Cycles", r_cy_dr);
    row("Cycles Rayleigh sample", r_cy_ray, NULL, NULL);
    row("mist_rayleigh_samplef", b_rayleigh_samplef, "Cycles", r_cy_ray);
    row("mist_phase_samplef (Rayleigh)", c_phase_rl_samplef, "Cycles", r_cy_ray);
    printf("over an array of %d (each a loop the compiler vectorises), per element:\n", N);
    row("Cycles / pbrt-v4 HG sample (eq. 3)", v_bare_samplef, NULL, NULL);
    row("mist_hg_sample_nf", n_hg_samplef, "Cycles", v_bare_samplef);
    row("mist_hg_sample_nf", n_hg_samplef, "Cycles' scalar loop", b_hg_sample_printed);
    row("Cycles Draine sample (eq. 6)", v_cy_dr, NULL, NULL);
    row("mist_phase_sample_nf (Draine)", n_phase_dr_samplef, "Cycles", v_cy_dr);
    row("mist_phase_sample_nf (Draine)", n_phase_dr_samplef, "Cycles' scalar loop", r_cy_dr);
    row("Cycles Rayleigh sample", v_cy_ray, NULL, NULL);
    row("mist_rayleigh_sample_nf", n_rayleigh_samplef, "Cycles", v_cy_ray);
    row("mist_rayleigh_sample_nf", n_rayleigh_samplef, "Cycles' scalar loop", r_cy_ray);
}

/* Tabulated phase functions (mist_tab_*): float tables of HG .9 at n nodes
 * uniform in theta, one channel.  Baselines: mist_hg_evalf / _samplef, and
 * the textbook table sampler, written here: a binary search of xi in the
 * cells' cumulative sums (double), then the cell's quadratic root by the
 * usual formula (what mist_tab_samplef's guide table replaces). */
#define TAB_MAXN 16384
static mist_tabf *tabs[5];
static const size_t tab_n[5] = { 64, 256, 1024, 4096, 16384 };
static double bs_mu[TAB_MAXN], bs_f[TAB_MAXN], bs_F[TAB_MAXN];
static float tab_mu[5][TAB_MAXN];
static size_t tab_m[5];              /* the nodes each table has */
static size_t bs_n;
static mist_tabf *tab_cur;
static void tab_make(size_t n, mist_tabf **t, float *mu, size_t *nm)
{
    static float p[TAB_MAXN];
    size_t i, m = 0, bytes;
    for (i = 0; i < n; ++i) {     /* (nodes that round to the same float: once) */
        float u = i == 0 ? -1.f : i == n - 1 ? 1.f
                : (float)-cos(3.14159265358979323846 * (double)i / (double)(n - 1));
        if (m > 0 && !(u > mu[m - 1])) continue;
        if (i == n - 1 && m > 0 && mu[m - 1] == 1.f) --m;
        mu[m] = u;
        p[m++] = (float)((1 - 0.81) / pow(1.81 - 1.8 * (double)u, 1.5));
    }
    n = m;
    bytes = mist_tab_bytesf(n, 1);
    *t = (mist_tabf *)malloc(bytes);
    if (mist_tab_initf(*t, bytes, mu, p, n, 1) != 0) { printf("mist_tab_initf failed\n"); exit(1); }
    *nm = n;
}
static void bs_make(const float *mu, size_t n)
{
    size_t i;
    double tot;
    for (i = 0; i < n; ++i) {
        bs_mu[i] = mu[i];
        bs_f[i] = (1 - 0.81) / pow(1.81 - 1.8 * bs_mu[i], 1.5);
    }
    bs_F[0] = 0;
    for (i = 0; i + 1 < n; ++i)
        bs_F[i + 1] = bs_F[i] + (bs_mu[i + 1] - bs_mu[i]) * (bs_f[i] + bs_f[i + 1]) / 2;
    tot = bs_F[n - 1];
    for (i = 0; i < n; ++i) { bs_F[i] /= tot; bs_f[i] /= tot; }
    bs_n = n;
}
static float bs_sample(float xi)
{
    size_t lo = 0, hi = bs_n - 2;
    double x = xi, a, b, h, r, d;
    while (lo < hi) {
        size_t mid = (lo + hi + 1) / 2;
        if (bs_F[mid] <= x) lo = mid; else hi = mid - 1;
    }
    h = bs_mu[lo + 1] - bs_mu[lo];
    a = bs_f[lo]; b = (bs_f[lo + 1] - a) / h; r = x - bs_F[lo];
    d = a * a + 2 * b * r;
    return (float)(bs_mu[lo] + (b == 0 ? r / a : (sqrt(d > 0 ? d : 0) - a) / b));
}
static double b_tab_evalf(void)     LOOP(float, mist_tab_evalf(tab_cur, uf[i], NULL))
static double b_tab_samplef(void)   LOOP(float, mist_tab_samplef(tab_cur, xf[i]))
static double b_bs_samplef(void)    LOOP(float, bs_sample(xf[i]))
static double n_tab_evalf(void)
{
    mist_tab_eval_nf(tab_cur, uf, out_float, N);
    return (double)out_float[N / 2];
}
static double n_tab_samplef(void)
{
    mist_tab_sample_nf(tab_cur, xf, out_float, N);
    return (double)out_float[N / 2];
}

static void tab_rows(void)
{
    int k;
    char name[64];
    for (k = 0; k < 5; ++k) tab_make(tab_n[k], &tabs[k], tab_mu[k], &tab_m[k]);
    printf("\nTabulated phase functions (float tables of HG .9, n nodes uniform in theta):\n");
    for (k = 0; k < 5; ++k) {
        tab_cur = tabs[k];
        snprintf(name, sizeof name, "mist_tab_evalf (n %zu)", tab_m[k]);
        row(name, b_tab_evalf, "mist_hg_evalf", b_hg_evalf);
    }
    for (k = 0; k < 5; ++k) {
        tab_cur = tabs[k];
        bs_make(tab_mu[k], tab_m[k]);
        snprintf(name, sizeof name, "mist_tab_samplef (n %zu)", tab_m[k]);
        row(name, b_tab_samplef, "binary search, same n", b_bs_samplef);
    }
    bs_make(tab_mu[2], tab_m[2]);
    row("binary-search sampler (n 1024)", b_bs_samplef, "mist_hg_samplef", b_hg_samplef);
    for (k = 0; k < 5; ++k) {
        tab_cur = tabs[k];
        snprintf(name, sizeof name, "mist_tab_samplef (n %zu)", tab_m[k]);
        row(name, b_tab_samplef, "binary search, n 1024", b_bs_samplef);
    }
    tab_cur = tabs[2];
    row("mist_tab_eval_nf (n 1024)", n_tab_evalf, "loop of mist_tab_evalf", b_tab_evalf);
    row("mist_tab_sample_nf (n 1024)", n_tab_samplef, "loop of mist_tab_samplef", b_tab_samplef);
    printf("bytes per node: %.1f (1 channel), %.1f (3 channels), at n 1024; "
           "header %zu bytes\n", (double)mist_tab_bytesf(1024, 1) / 1024,
           (double)mist_tab_bytesf(1024, 3) / 1024, sizeof(mist_tabf));
    for (k = 0; k < 5; ++k) free(tabs[k]);
}

int main(int argc, char **argv)
{
    bench_fn base;
    int i;
    unsigned long long s = 88172645463325252ULL;
    for (i = 0; i < N; ++i) {
        s ^= s << 13; s ^= s >> 7; s ^= s << 17;
        xd[i] = (double)(s >> 11) * 0x1p-53;
        ud[i] = 2 * xd[i] - 1;
        xf[i] = (float)xd[i];
        uf[i] = (float)ud[i];
    }
    for (i = 0; i < N; ++i) {       /* g per call: from other xi, in [.05, .95] */
        gv[i] = 0.05f + 0.9f * xf[(i * 2654435761u) % N];
        gs[i] = (i * 40503u >> 7) % 2 ? gv[i] : -gv[i];
    }
    for (i = 0; i < N; ++i) mi[i] = (int)((i * 2246822519u) >> 30);   /* 0..3 */
    for (i = 0; i < 4; ++i) {
        md_dr[i] = mist_phase_drainef(md_g[i], md_a[i]);
        md_hg[i] = mist_phase_hgf(md_g[i]);
    }
    ph_hgf = mist_phase_hgf(0.8f);              /* the media, prepared once */
    ph_drf = mist_phase_drainef(0.5f, 17.f);
    ph_dr  = mist_phase_draine(0.5, 17.);
    ph_fogf = mist_phase_fogf(mist_fog_makef(0.988f, 0.556f, 22.0f, 0.482f));
    ph_fog = mist_phase_fog(fog10);
    machine();
    printf("ns per call: median of %d repetitions of %d calls [min..max]; "
           "ratio to the baseline named\n\n", REPS, N);
    if (argc > 1 && strcmp(argv[1], "tab") == 0) {   /* ./mist_bench tab: the tables alone */
        tab_rows();
        return 0;
    }
    if (argc > 1 && strcmp(argv[1], "batch") == 0) {  /* ./mist_bench batch: the batch forms */
        batch_rows();
        return 0;
    }
    if (argc > 1 && strcmp(argv[1], "compact") == 0) {   /* ./mist_bench compact */
        compact_rows();
        return 0;
    }
    if (argc > 1 && strcmp(argv[1], "hfog_path") == 0) {   /* the free-flight distances alone */
        fog_f = mist_fog_makef(0.988f, 0.556f, 22.0f, 0.482f);
        fog_d = mist_fog_make(0.988, 0.556, 22.0, 0.482);
        hfog_setup();
        sd_rows();
        return 0;
    }
    if (argc > 1 && strcmp(argv[1], "hfog") == 0) {  /* ./mist_bench hfog: the height fog alone */
        fog_f = mist_fog_makef(0.988f, 0.556f, 22.0f, 0.482f);
        fog_d = mist_fog_make(0.988, 0.556, 22.0, 0.482);
        hfog_rows();
        return 0;
    }

    base = b_hg_eval_printed;
    row("eq. 2 HG eval as printed (float)", b_hg_eval_printed, NULL, NULL);
    row("mist_hg_evalf", b_hg_evalf, "eq. 2", base);
    row("mist_hg_eval", b_hg_eval, "eq. 2", base);
    base = b_hg_sample_printed;
    row("eq. 3 HG sample as printed (float)", b_hg_sample_printed, NULL, NULL);
    row("mist_hg_samplef", b_hg_samplef, "eq. 3", base);
    row("mist_hg_sample", b_hg_sample, "eq. 3", base);
    base = b_hg_sample_floatonly;
    row("HG sample, float arithmetic only", b_hg_sample_floatonly, NULL, NULL);
    row("mist_hg_samplef (double inside)", b_hg_samplef, "float only", base);
    row("mist_hg_sample_dirf", b_hg_sample_dirf, "eq. 3", base);
    printf("\n");
    row("mist_draine_evalf (g .5, a 17)", b_draine_evalf, "eq. 2", b_hg_eval_printed);
    row("mist_draine_eval  (g .5, a 17)", b_draine_eval, NULL, NULL);
    base = b_eq6f;
    row("eq. 6 Draine as printed (float)", b_eq6f, NULL, NULL);
    row("eq. 6 Draine as printed (double)", b_eq6, "eq. 6 float", base);
    row("mist_draine_samplef (g .5, a 17)", b_draine_samplef, "eq. 6 float", base);
    row("mist_draine_sample  (g .5, a 17)", b_draine_sample, "eq. 6 float", base);
    row("  the same, no long double, no fma", b_draine_sample_nold, "eq. 6 float", base);
    base = b_draine_sample_1;
    row("mist_draine_sample  (g .9999, a 17)", b_draine_sample_1, NULL, NULL);
    row("mist_draine_samplef (g .9999, a 17)", b_draine_samplef_1, "double", base);
    base = b_eq6f_250;
    row("eq. 6 float (g .1, a 250)", b_eq6f_250, NULL, NULL);
    row("mist_draine_samplef (g .1, a 250)", b_draine_samplef_250, "eq. 6 float", base);
    row("mist_cs_samplef (g .7)", b_cs_samplef, "eq. 6 float", base);
    printf("\n");
    base = b_rayleigh_floatonly;
    row("Rayleigh sample, float arithmetic only", b_rayleigh_floatonly, NULL, NULL);
    row("mist_rayleigh_samplef (double inside)", b_rayleigh_samplef, "float only", base);
    row("mist_rayleigh_sample", b_rayleigh_sample, NULL, NULL);
    row("mist_rayleigh_sample (no fma: Dekker's product)", b_rayleigh_sample_nold, NULL, NULL);
    row("mist_fog_evalf (d = 10 um)", b_fog_evalf, NULL, NULL);
    row("mist_fog_samplef (d = 10 um)", b_fog_samplef, NULL, NULL);
    renderer_rows();
    prepared_rows();
    compact_rows();
    alternatives();
    hg_target_rows();
    batch_rows();
    tab_rows();
    coverage_rows();
    size_rows();
    mie_rows();
    printf("\nLorenz-Mie (mist_mie.h), one diameter, 1800 angles x 3 wavelengths, "
           "median of 5:\n");
    printf("  d = 10 um: %.2f ms\n  d = 50 um: %.2f ms\n", mie_ms(10), mie_ms(50));
    return 0;
}
