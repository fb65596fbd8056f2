/* mist_bench.c - nanoseconds per call of mist's evaluation and sampling
 * functions, beside baselines measured in the same run:
 *   - the paper's formulas typed in as printed ([JD23] eq. 2-3 for HG, eq. 6
 *     for Draine), which are what mist's stable forms replace;
 *   - the cheap alternatives a renderer might use instead (HG alone, a
 *     Schlick lobe, a 256-entry table: tests/mist_alt.h), and the droplet
 *     fits typed in as printed;
 * Each figure: median of 15 timed repetitions (after a warm-up) over a
 * stream of 4096 random inputs, with the spread (min..max of the
 * repetitions).  Run: ./build/mist_bench  (see README.md). */
#define _POSIX_C_SOURCE 199309L
#include "mist.h"
#include "mist_mie.h"
#include "mist_printed.h"
#include "mist_alt.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

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

static double measure(bench_fn f, double *lo, double *hi)
{
    double t[REPS], tmp;
    int i, j;
    sink += f();                                   /* warm-up */
    for (i = 0; i < REPS; ++i) {
        double t0 = now();
        sink += f();
        t[i] = (now() - t0) / N * 1e9;
    }
    for (i = 0; i < REPS; ++i)
        for (j = i + 1; j < REPS; ++j)
            if (t[j] < t[i]) { tmp = t[i]; t[i] = t[j]; t[j] = tmp; }
    *lo = t[0]; *hi = t[REPS - 1];
    return t[REPS / 2];
}

#define LOOP(T, EXPR) { T s = 0; int i; for (i = 0; i < N; ++i) s += EXPR; return (double)s; }

static double b_hg_eval_printed(void)  LOOP(float, hg_eval_printed(0.8f, uf[i]))
static double b_hg_evalf(void)         LOOP(float, mist_hg_evalf(0.8f, uf[i]))
static double b_hg_eval(void)          LOOP(double, mist_hg_eval(0.8, ud[i]))
static double b_hg_sample_printed(void) LOOP(float, hg_sample_printed(0.8f, xf[i]))
static double b_hg_samplef(void)       LOOP(float, mist_hg_samplef(0.8f, xf[i]))
static double b_hg_sample(void)        LOOP(double, mist_hg_sample(0.8, xd[i]))
/* the same formulas in float arithmetic only (internal; up to 1.1x the
 * accuracy bar, which is why the public float functions use double inside) */
static double b_hg_sample_floatonly(void) LOOP(float, mist__hg_samplef(0.8f, xf[i]))
static double b_rayleigh_floatonly(void) LOOP(float, (xf[i] <= 0.5f ? mist__rayleigh_lowerf(xf[i])
                                                      : -mist__rayleigh_lowerf(1 - xf[i])))
static double b_draine_evalf(void)     LOOP(float, mist_draine_evalf(0.5f, 17.f, uf[i]))
static double b_draine_eval(void)      LOOP(double, mist_draine_eval(0.5, 17., ud[i]))
static double b_eq6f(void)             LOOP(float, draine_eq6f(0.5f, 17.f, xf[i]))
static double b_eq6(void)              LOOP(double, draine_eq6(0.5, 17., xd[i]))
static double b_draine_samplef(void)   LOOP(float, mist_draine_samplef(0.5f, 17.f, xf[i]))
static double b_draine_sample(void)    LOOP(double, mist_draine_sample(0.5, 17., xd[i]))
static double b_eq6f_250(void)         LOOP(float, draine_eq6f(0.1f, 250.f, xf[i]))
static double b_draine_samplef_250(void) LOOP(float, mist_draine_samplef(0.1f, 250.f, xf[i]))
static double b_cs_samplef(void)       LOOP(float, mist_cs_samplef(0.7f, xf[i]))
static double b_rayleigh_samplef(void) LOOP(float, mist_rayleigh_samplef(xf[i]))
static double b_rayleigh_sample(void)  LOOP(double, mist_rayleigh_sample(xd[i]))
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

static void row(const char *name, bench_fn f, const char *base_name, double base);

static void alternatives(void)
{
    double lo, hi, base;
    mist_fog fog = mist_fog_from_diameter(10);
    alt_k = alt_schlick_kf(0.8f);
    alt_fog_lut = alt_lut_buildf(256, alt_fog_dens, &fog);
    printf("\nThe cheap alternatives a renderer might use instead (tests/mist_alt.h):\n");
    base = measure(b_hg_evalf, &lo, &hi);
    row("mist_hg_evalf (g .8)", b_hg_evalf, NULL, 0);
    row("Schlick eval (k from g .8, float)", b_schlick_evalf, "mist_hg_evalf", base);
    row("LUT eval, 256 entries (fog 10 um)", b_lut_evalf, "mist_hg_evalf", base);
    row("mist_fog_evalf (d = 10 um)", b_fog_evalf, "mist_hg_evalf", base);
    base = measure(b_hg_samplef, &lo, &hi);
    row("mist_hg_samplef (g .8)", b_hg_samplef, NULL, 0);
    row("Schlick sample (float)", b_schlick_samplef, "mist_hg_samplef", base);
    row("LUT inverse CDF, 256 entries (fog)", b_lut_samplef, "mist_hg_samplef", base);
    row("mist_fog_samplef (d = 10 um)", b_fog_samplef, "mist_hg_samplef", base);
    base = measure(b_fit_printedf, &lo, &hi);
    row("fits eq. 7-10 as printed (float)", b_fit_printedf, NULL, 0);
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

static void row(const char *name, bench_fn f, const char *base_name, double base)
{
    double lo, hi, m = measure(f, &lo, &hi);
    if (base_name)
        printf("%-34s %8.2f  [%6.2f..%6.2f]  %6.2fx %s\n", name, m, lo, hi, m / base, base_name);
    else
        printf("%-34s %8.2f  [%6.2f..%6.2f]\n", name, m, lo, hi);
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
}

int main(void)
{
    double lo, hi, base;
    int i;
    unsigned long long s = 88172645463325252ULL;
    for (i = 0; i < N; ++i) {
        s ^= s << 13; s ^= s >> 7; s ^= s << 17;
        xd[i] = (double)(s >> 11) * 0x1p-53;
        ud[i] = 2 * xd[i] - 1;
        xf[i] = (float)xd[i];
        uf[i] = (float)ud[i];
    }
    machine();
    printf("ns per call: median of %d repetitions of %d calls [min..max]; "
           "ratio to the baseline named\n\n", REPS, N);

    base = measure(b_hg_eval_printed, &lo, &hi);
    row("eq. 2 HG eval as printed (float)", b_hg_eval_printed, NULL, 0);
    row("mist_hg_evalf", b_hg_evalf, "eq. 2", base);
    row("mist_hg_eval", b_hg_eval, "eq. 2", base);
    base = measure(b_hg_sample_printed, &lo, &hi);
    row("eq. 3 HG sample as printed (float)", b_hg_sample_printed, NULL, 0);
    row("mist_hg_samplef", b_hg_samplef, "eq. 3", base);
    row("mist_hg_sample", b_hg_sample, "eq. 3", base);
    base = measure(b_hg_sample_floatonly, &lo, &hi);
    row("HG sample, float arithmetic only", b_hg_sample_floatonly, NULL, 0);
    row("mist_hg_samplef (double inside)", b_hg_samplef, "float only", base);
    row("mist_hg_sample_dirf", b_hg_sample_dirf, "eq. 3", base);
    printf("\n");
    row("mist_draine_evalf (g .5, a 17)", b_draine_evalf, "eq. 2", measure(b_hg_eval_printed, &lo, &hi));
    row("mist_draine_eval  (g .5, a 17)", b_draine_eval, NULL, 0);
    base = measure(b_eq6f, &lo, &hi);
    row("eq. 6 Draine as printed (float)", b_eq6f, NULL, 0);
    row("eq. 6 Draine as printed (double)", b_eq6, "eq. 6 float", base);
    row("mist_draine_samplef (g .5, a 17)", b_draine_samplef, "eq. 6 float", base);
    row("mist_draine_sample  (g .5, a 17)", b_draine_sample, "eq. 6 float", base);
    base = measure(b_eq6f_250, &lo, &hi);
    row("eq. 6 float (g .1, a 250)", b_eq6f_250, NULL, 0);
    row("mist_draine_samplef (g .1, a 250)", b_draine_samplef_250, "eq. 6 float", base);
    row("mist_cs_samplef (g .7)", b_cs_samplef, "eq. 6 float", base);
    printf("\n");
    base = measure(b_rayleigh_floatonly, &lo, &hi);
    row("Rayleigh sample, float arithmetic only", b_rayleigh_floatonly, NULL, 0);
    row("mist_rayleigh_samplef (double inside)", b_rayleigh_samplef, "float only", base);
    row("mist_rayleigh_sample", b_rayleigh_sample, NULL, 0);
    row("mist_fog_evalf (d = 10 um)", b_fog_evalf, NULL, 0);
    row("mist_fog_samplef (d = 10 um)", b_fog_samplef, NULL, 0);
    alternatives();
    printf("\nLorenz-Mie (mist_mie.h), one diameter, 1800 angles x 3 wavelengths, "
           "median of 5:\n");
    printf("  d = 10 um: %.2f ms\n  d = 50 um: %.2f ms\n", mie_ms(10), mie_ms(50));
    return 0;
}
