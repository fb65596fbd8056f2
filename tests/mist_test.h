/* mist_test.h - helpers shared by the tests: checks and the closing line,
 * a random number generator, adaptive quadrature, and the chi-square
 * goodness-of-fit machinery.  Nothing here uses include/mist.h. */
#ifndef MIST_TEST_H
#define MIST_TEST_H

#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

/* ------------------------------------------------------------------------ */
/* Checks                                                                   */
/* ------------------------------------------------------------------------ */

static int mt_passed = 0, mt_failed = 0;

/* Records one check; prints the message of a failing one. */
static inline int mt_check(int ok, const char *fmt, ...)
{
    if (ok) { ++mt_passed; return 1; }
    ++mt_failed;
    {
        va_list ap;
        va_start(ap, fmt);
        printf("FAIL: ");
        vprintf(fmt, ap);
        printf("\n");
        va_end(ap);
    }
    return 0;
}

/* The closing line ('N passed, N failed') and the exit status. */
static inline int mt_done(const char *name)
{
    printf("%s: %d passed, %d failed\n", name, mt_passed, mt_failed);
    return mt_failed ? 1 : 0;
}

/* ------------------------------------------------------------------------ */
/* Quick mode: MIST_TEST_QUICK=k in the environment (an integer k >= 1;     */
/* unset, empty, 0 or 1: full size) divides the random draws and sample     */
/* counts of test_accuracy, test_chi2 and test_height_fog by k (test_fits:  */
/* its Mie reference's radii, not below half; test_batch: its arrays longer */
/* than 100 only where the code depends on n, test_batch.c).  The fixed     */
/* edge cases and grids always run in full.  For the slow sub-builds of     */
/* tests/robustness.cmake (the asan variant, -O0 under ASan + UBSan), so    */
/* that they run the whole suite; the main build runs at full size.         */
/* ------------------------------------------------------------------------ */

static inline long mt_quick(void)
{
    static long k = 0;
    if (k == 0) {
        const char *e = getenv("MIST_TEST_QUICK");
        k = e && *e ? strtol(e, NULL, 10) : 1;
        if (k < 1) k = 1;
        if (k > 1) printf("MIST_TEST_QUICK=%ld: random draws and sample counts / %ld\n", k, k);
    }
    return k;
}

/* n / k (k from MIST_TEST_QUICK), but not below lo (and never above n):
 * each caller's lo is the smallest count its thresholds are justified for. */
static inline long mt_scale(long n, long lo)
{
    long m = n / mt_quick();
    if (m < lo) m = lo;
    return m < n ? m : n;
}

/* ------------------------------------------------------------------------ */
/* Random numbers: splitmix64, fixed seeds, so every run is reproducible.   */
/* ------------------------------------------------------------------------ */

typedef struct { uint64_t s; } mt_rng;

static inline uint64_t mt_next(mt_rng *r)
{
    uint64_t z = (r->s += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

/* uniform in [0, 1) with 53 (double) or 24 (float) random bits */
static inline double mt_uniform(mt_rng *r) { return (double)(mt_next(r) >> 11) * 0x1p-53; }
static inline float mt_uniformf(mt_rng *r) { return (float)(mt_next(r) >> 40) * 0x1p-24f; }

/* ------------------------------------------------------------------------ */
/* Adaptive Gauss-Kronrod 7-15 quadrature (double).                         */
/* The error estimate is |K15 - G7|; an interval is split in two until the  */
/* estimate is below its share of the tolerance or the depth limit is hit.  */
/* ------------------------------------------------------------------------ */

typedef double (*mt_fn)(double x, const void *ctx);

static const double mt_xk[8] = {
    0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
    0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
    0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
    0.207784955007898467600689403773245, 0.000000000000000000000000000000000};
static const double mt_wk[8] = {
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
    0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
    0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
static const double mt_wg[4] = {
    0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
    0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

static inline double mt_gk15(mt_fn f, const void *c, double a, double b, double *err)
{
    double m = 0.5 * (a + b), h = 0.5 * (b - a), fc = f(m, c);
    double k = mt_wk[7] * fc, g = mt_wg[3] * fc;
    int j;
    for (j = 0; j < 7; ++j) {
        double x = h * mt_xk[j], s = f(m - x, c) + f(m + x, c);
        k += mt_wk[j] * s;
        if (j & 1) g += mt_wg[j / 2] * s;
    }
    *err = fabs((k - g) * h);
    return k * h;
}

static inline double mt_adapt(mt_fn f, const void *c, double a, double b,
                       double tol, int depth, double *err)
{
    double e, r = mt_gk15(f, c, a, b, &e);
    if (e <= tol || depth <= 0) { *err = e; return r; }
    {
        double m = 0.5 * (a + b), e1, e2;
        double r1 = mt_adapt(f, c, a, m, 0.5 * tol, depth - 1, &e1);
        double r2 = mt_adapt(f, c, m, b, 0.5 * tol, depth - 1, &e2);
        *err = e1 + e2;
        return r1 + r2;
    }
}

/* Integral of f over [a, b] to absolute tolerance tol; *err gets the
 * estimated error (compare it with tol to know the result is trusted). */
static inline double mt_integrate(mt_fn f, const void *c, double a, double b,
                           double tol, double *err)
{
    return mt_adapt(f, c, a, b, tol, 40, err);
}

/* ------------------------------------------------------------------------ */
/* Chi-square goodness of fit (in the style of Mitsuba 3 and pbrt-v4).      */
/* ------------------------------------------------------------------------ */

/* Regularised upper incomplete gamma Q(a, x) = Gamma(a, x) / Gamma(a):
 * series for x < a + 1, Lentz continued fraction otherwise. */
static inline double mt_gamma_q(double a, double x)
{
    double gln = lgamma(a);
    int n;
    if (x <= 0) return 1;
    if (x < a + 1) {
        double ap = a, sum = 1 / a, del = sum;
        for (n = 0; n < 100000; ++n) {
            ap += 1; del *= x / ap; sum += del;
            if (fabs(del) < fabs(sum) * 1e-16) break;
        }
        return 1 - sum * exp(-x + a * log(x) - gln);
    } else {
        double b = x + 1 - a, c = 1 / 1e-300, d = 1 / b, h = d;
        for (n = 1; n < 100000; ++n) {
            double an = -n * (n - a), del;
            b += 2;
            d = an * d + b; if (fabs(d) < 1e-300) d = 1e-300;
            c = b + an / c; if (fabs(c) < 1e-300) c = 1e-300;
            d = 1 / d; del = d * c; h *= del;
            if (fabs(del - 1) < 1e-16) break;
        }
        return exp(-x + a * log(x) - gln) * h;
    }
}

/* Per-test significance for `ntests` tests at overall level `alpha`
 * (Sidak correction). */
static inline double mt_sidak(double alpha, int ntests)
{
    return 1 - pow(1 - alpha, 1.0 / ntests);
}

/* Pearson chi-square test of observed counts against expected counts (n
 * cells, expected from quadrature of the pdf).  Cells with an expected
 * count below 5 are pooled into one (and dropped if the pool stays below
 * 5); an observation in a cell with expected count 0 is an outright fail
 * (p = 0).  Returns the p-value; *dof_out gets the degrees of freedom. */
static inline double mt_chi2(const double *obs, const double *expct, int n, int *dof_out)
{
    double chi2 = 0, pool_o = 0, pool_e = 0;
    int dof = 0, i;
    for (i = 0; i < n; ++i) {
        if (expct[i] <= 0) {
            if (obs[i] > 0) { if (dof_out) *dof_out = 0; return 0; }
            continue;
        }
        if (expct[i] < 5) { pool_o += obs[i]; pool_e += expct[i]; continue; }
        chi2 += (obs[i] - expct[i]) * (obs[i] - expct[i]) / expct[i];
        ++dof;
    }
    if (pool_e >= 5) {
        chi2 += (pool_o - pool_e) * (pool_o - pool_e) / pool_e;
        ++dof;
    } else if (pool_e > 0) {
        /* too little expected mass to test on its own: merge its
         * discrepancy into nothing, but fail gross excess (a sampler that
         * puts many samples where the pdf says there are almost none) */
        if (pool_o > pool_e + 10 + 5 * sqrt(pool_e)) {
            if (dof_out) *dof_out = 0;
            return 0;
        }
    }
    dof -= 1;                              /* the counts sum to the total */
    if (dof_out) *dof_out = dof;
    if (dof < 1) return 1;
    return mt_gamma_q(0.5 * dof, 0.5 * chi2);
}

#endif
