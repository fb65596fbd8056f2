/* mist_ref.h - independent high-precision references for the tests.
 *
 * Nothing here shares code with include/mist.h.  The reference CDF of the
 * Draine phase function (HG at alpha = 0, Cornette-Shanks at alpha = 1,
 * Rayleigh at g = 0, alpha = 1) is evaluated in __float128 (113-bit
 * significand, unit roundoff 9.6e-35):
 *   - for |g| >= 1e-3: the closed-form CDF printed in the supplemental of
 *     Jendersie & d'Eon 2023 (section 2.2), typed in as printed.  Its terms
 *     cancel as 1/g^3, which costs at most 9 of the 34 digits at g = 1e-3:
 *     absolute error <= ~1e-25 in F;
 *   - for |g| < 1e-3: 40-point Gauss-Legendre quadrature of the density on
 *     [-1, u].  The integrand is analytic with its nearest singularity at
 *     u = (1+g^2)/(2g) >= 500, so the rule's error is below 1e-60.
 * The inverse (ref_sample_from) is safeguarded Newton to ~2^-64 relative,
 * so the reference u* is good to ~1e-25 absolute where F's error over the
 * density allows, far below one ulp of a double (at |g| within ~2^-40 of 1
 * and xi near 1e-16 F's own rounding allows ~1e-18: see ref_sample_from).
 */
#ifndef MIST_REF_H
#define MIST_REF_H

#include <float.h>
#include <math.h>

/* The 113-bit type: __float128 (gcc and clang on x86-64), else a long
 * double that is IEEE binary128 (AArch64 Linux, ...).  Without either
 * (MSVC; Apple's arm64, whose long double is double) the tests that need
 * it are not built: CMakeLists.txt checks this header compiles
 * (MIST_HAVE_QREAL) and reports them skipped. */
#if defined(__SIZEOF_FLOAT128__)
__extension__ typedef __float128 qreal;
#elif defined(LDBL_MANT_DIG) && LDBL_MANT_DIG >= 113
typedef long double qreal;
#else
#  error "tests/mist_ref.h needs __float128 or a 113-bit long double"
#endif

static inline qreal ref_sqrtq(qreal a)
{
    qreal x;
    if (a <= 0) return 0;
    x = (qreal)sqrt((double)a);           /* 53 bits, then two Newton steps */
    x = (x + a / x) / 2;
    x = (x + a / x) / 2;
    return x;
}

/* Legendre P_n and derivative at x */
static inline void ref_legendre(int n, qreal x, qreal *p, qreal *dp)
{
    qreal p0 = 1, p1 = x, p2;
    int k;
    for (k = 2; k <= n; ++k) {
        p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1; p1 = p2;
    }
    *p = p1;
    *dp = n * (x * p1 - p0) / (x * x - 1);
}

#define REF_GL_N 40
static qreal ref_gl_x[REF_GL_N], ref_gl_w[REF_GL_N];
static int ref_gl_ready = 0;

static inline void ref_gl_init(void)
{
    int i, it;
    const double pi = 3.14159265358979323846;
    for (i = 0; i < REF_GL_N; ++i) {
        qreal x = (qreal)cos(pi * (i + 0.75) / (REF_GL_N + 0.5)), p, dp;
        for (it = 0; it < 8; ++it) {
            ref_legendre(REF_GL_N, x, &p, &dp);
            x -= p / dp;
        }
        ref_legendre(REF_GL_N, x, &p, &dp);
        ref_gl_x[i] = x;
        ref_gl_w[i] = 2 / ((1 - x * x) * dp * dp);
    }
    ref_gl_ready = 1;
}

/* Density of u = cos(theta) (per unit u, integrates to 1 over [-1, 1]). */
static inline qreal ref_density_u(qreal g, qreal a, qreal u)
{
    qreal s = 1 + g * g - 2 * g * u;
    return (1 - g * g) / (2 * s * ref_sqrtq(s)) * (1 + a * u * u)
           / (1 + a * (1 + 2 * g * g) / 3);
}

/* P(cos <= u) for the Draine phase function (g in (-1,1), a = alpha). */
static inline qreal ref_cdf(qreal g, qreal a, qreal u)
{
    if (u <= -1) return 0;
    if (u >= 1) return 1;
    if (g < (qreal)1e-3 && g > -(qreal)1e-3) {
        qreal h = (u + 1) / 2, m = (u - 1) / 2, sum = 0;  /* [-1, u] */
        int i;
        if (!ref_gl_ready) ref_gl_init();
        for (i = 0; i < REF_GL_N; ++i)
            sum += ref_gl_w[i] * ref_density_u(g, a, m + h * ref_gl_x[i]);
        return sum * h;
    } else {
        /* [JD23 supplemental, section 2.2], as printed */
        qreal V = ref_sqrtq(g * g - 2 * g * u + 1);
        qreal g2 = g * g, g3 = g2 * g, g4 = g2 * g2, g5 = g4 * g, g6 = g4 * g2;
        qreal W = -2 * a * g6 + g4 * (a * (u * u - 2) - 3)
                  - g2 * (a * (V + u * u - 2) + 3 * (V - 1));
        return (W + 2 * a * g5 * (V + u) + (a + 3) * g3 * V - 2 * a * (V - 1)
                - 2 * a * g * u)
               / (2 * g3 * (2 * a * g2 + a + 3) * V);
    }
}

/* A bound on ref_cdf's absolute error: 8 times its rounding, 1e-34, and
 * for |g| >= 1e-3 (the printed form) the 1/|g|^3 its terms cancel by (the
 * head of this file); the Gauss-Legendre branch's own error is below 1e-60. */
static inline qreal ref_cdf_err(qreal g)
{
    qreal ag = g < 0 ? -g : g;
    return (qreal)8e-34 * (ag >= (qreal)1e-3 ? 1 + 1 / (ag * ag * ag) : 1);
}

/* Reference inverse: u* with P(cos <= u*) = xi.  Safeguarded Newton in
 * __float128 inside a bisection bracket that starts as [-1, 1]: it converges
 * from any start; `start` only saves iterations (it may come from the code
 * under test: the answer is defined by the CDF alone).  |g| = 1 returns g
 * (the delta).  Converged when the bracket is below 1e-30, or when Newton's
 * step is below 1e-30 + 2^-64 |u| and the residual below 2^-64 min(xi,
 * 1 - xi) + F's own error (ref_cdf_err): either way u is within ~2^-12
 * of the tests' smallest bar (4 ulps of u* in double, 4 eps xi du/dxi) of
 * the root of the computed CDF.  A
 * step that would leave the bracket is retried from the bracket's ends
 * (the tangent at an end; at -1 and 1, where F is 0 and 1 exactly, never
 * evaluated), then bisects.  (A test of the step alone, below 1e-30, would
 * bisect down to 1e-30 wherever a step rounds onto u or F's noise at small
 * |g| exceeds 1e-30 f: 14 iterations a call on average in test_accuracy,
 * against 5; the same roots to within 0.22% of the double bar over its 185083
 * calls, the largest differences at |g| within 2^-50 of 1 and xi near
 * 1e-17, where both are at the printed form's own rounding: F ~ xi
 * computed from terms of order 1, 1e-33 apart, over a density ~1e-16.  The
 * old test also took a step below 1e-30 as converged where the density
 * peaks narrower than that near u = -+1 at |g| near 1: from a start 2^-103
 * below 1 at g = 1 - 2^-53, alpha 8.7e13, xi 1.2e-48 it returned 1 for a
 * root at -1 + 9e-19 (found by a review; test_accuracy checks that case).
 * Where F's rounding over a tiny density exceeds the step test, at |g|
 * near 1 with alpha beyond 1e4, it still bisects down to 1e-30: up to ~200
 * iterations on such inputs, measured by the review.) */
static inline qreal ref_sample_stop(qreal g, qreal a, qreal xi, qreal start, qreal rstop)
{
    const qreal d = (qreal)1e-30, p64 = (qreal)1 / 65536 / 65536 / 65536 / 65536;   /* 2^-64 */
    const qreal ulp = p64 / 65536 / 65536 / 65536 / 2;                      /* 2^-113 */
    qreal lo = -1, hi = 1, rlo = -xi, rhi = 1 - xi, flo = -1, fhi = -1;  /* f < 0: not yet */
    qreal u = start, f, r, un, s, x = xi < 1 - xi ? xi : 1 - xi, rt = ref_cdf_err(g);
    int it;
    if (g >= 1 || g <= -1) return g;
    if (xi <= 0) return -1;
    if (xi >= 1) return 1;
    if (!(u > -1 && u < 1)) u = 0;
    for (it = 0; it < 300; ++it) {
        r = ref_cdf(g, a, u) - xi;
        if (r == 0 || (r < 0 ? -r : r) <= rstop) return u;
        f = ref_density_u(g, a, u);
        if (r > 0) { hi = u; rhi = r; fhi = f; } else { lo = u; rlo = r; flo = f; }
        un = u - r / f;
        s = un > u ? un - u : u - un;
        if (s <= d + p64 * (u < 0 ? -u : u) && (r < 0 ? -r : r) <= rt + p64 * x)
            return un > lo && un < hi ? un : u;
        if (s < d) {
            un = (lo + hi) / 2;      /* a tiny step at a large residual: a narrow peak */
        } else if (!(un > lo && un < hi)) {
            if (flo < 0) flo = ref_density_u(g, a, lo);
            un = lo - rlo / flo;
            if (lo == -1 && un == -1) un = -1 + ulp;       /* a root within 2^-113 of -1 */
            if (!(un > lo && un < hi)) {
                if (fhi < 0) fhi = ref_density_u(g, a, hi);
                un = hi - rhi / fhi;
                if (hi == 1 && un == 1) un = 1 - ulp;
            }
            if (!(un > lo && un < hi)) un = (lo + hi) / 2;
        }
        if (hi - lo < d) return un;
        u = un;
    }
    return u;
}

static inline qreal ref_sample_from(qreal g, qreal a, qreal xi, qreal start)
{
    return ref_sample_stop(g, a, xi, start, 0);
}

static inline qreal ref_sample(qreal g, qreal a, qreal xi)
{
    return ref_sample_from(g, a, xi, 0);
}

/* The samplers' accuracy bar (tests/test_accuracy.c says why), for a
 * sample u of xi in double (flt = 0) or float (flt = 1):
 *     |u - u*| <= 4 ulp(u*) + 4 eps xi du/dxi,   du/dxi = 1 / (2 pi p(u*))
 * eps = 2^-53 or 2^-24, ulp(u*) the type's spacing at u* (the smallest
 * subnormal at 0), no xi term at |g| = 1 (the Dirac limit).  Returns
 * |u - u*| over the bound (<= 1 passes) and u* in *us.
 * ref_bar_q: at an exact xi given in __float128 (the fog's rescaled xi'),
 * the bar's xi term taken as 4 eps xt du/dxi (xt: what the rounding of the
 * caller's own xi moves xi' by, in units of eps); ref_bar: xi itself;
 * ref_bar_root: at a root q already found. */
static inline double ref_bar_root(double g, qreal a, double xt, double u, int flt, qreal q,
                                  double *us)
{
    double r = (double)q, tol;
    tol = 4 * (flt ? (double)(nextafterf((float)fabs(r), INFINITY) - (float)fabs(r))
                   : nextafter(fabs(r), INFINITY) - fabs(r));
    if (fabs(g) < 1) tol += 4 * (flt ? 0x1p-24 : 0x1p-53) * xt / (double)ref_density_u(g, a, r);
    *us = r;
    return fabs(u - r) / tol;
}

static inline double ref_bar_q(double g, qreal a, qreal xi, double xt, double u, int flt,
                               double *us)
{
    return ref_bar_root(g, a, xt, u, flt, ref_sample_from(g, a, xi, u), us);
}

/* ref_bar: the root only as closely as the bar needs it.  Besides
 * ref_sample_from's stops, a residual r = F(u) - xi with |r| <= 2^-67
 * min(xi, 1 - xi) ends the search (ref_sample_stop, ref_bar_rstop): u is then within
 * |r| / f of the root, f the density between them, which is 2^-16 of the
 * bar's xi term (4 eps xi du/dxi = 2^-51 xi / f(u*), double's eps) where
 * f is about f(u*); where f ~ k u^2 near u = 0 (alpha -> inf), |r| =
 * k |u^3 - u*^3| / 3 keeps |u - u*| within 4 |r| / f(u*) (the ratio
 * 3 u*^2 / (u^2 + u u* + u*^2) is largest, 4, at u = -0.5 u*: 3.998 2^-16
 * measured there), 4 2^-16 of that term, and
 * 3.2 2^-16 from the samplers' own answers as starts (~5e6 random starts
 * over the whole domain).  There Newton converges only linearly (by
 * 2/3 a step) and ref_sample_from bisects down to 1e-30: test_huge_alpha's
 * 6864 roots took 1.8 s of test_accuracy's 3 in the O3 variant, 0.9 s
 * with this stop, every printed figure the same (test_reference checks the
 * stop against the full inverse there, with a control).  Where
 * F's own rounding (ref_cdf_err) exceeds 2^-67 xi (xi below ~1e-13, or |g|
 * small in the printed form) the stop can fire inside F's noise: the root
 * is then as uncertain as the full inverse's is there anyway, by F's
 * rounding over f (the review: at g = 1 - 2^-53, alpha 1.3e85, xi 5.8e-18
 * the two differ by 0.006 of the bar, each ~0.015 of its xi term from
 * mpmath's root; 0.88 of 2^-14 of the xi term plus 2 ref_cdf_err / f at
 * worst). */
static inline qreal ref_bar_rstop(qreal xi)    /* 2^-67 min(xi, 1 - xi) */
{
    return (xi < 1 - xi ? xi : 1 - xi) / 65536 / 65536 / 65536 / 65536 / 8;
}

static inline double ref_bar(double g, qreal a, double xi, double u, int flt, double *us)
{
    return ref_bar_root(g, a, xi, u, flt, ref_sample_stop(g, a, xi, u, ref_bar_rstop(xi)), us);
}

#endif
