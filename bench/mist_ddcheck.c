/* mist_ddcheck.c - the figures README.md and include/mist.h give for the
 * double HG, Rayleigh and Draine samplers in double-double (where fma is one
 * instruction; CMake builds this with the benchmark's flags, so on x86 with
 * -march=native): over 1e5 random (g, xi) for HG (g from 1e-300 to
 * 1 - 2^-53 in magnitude, xi down to 2^-1074), 2e4 random xi for Rayleigh
 * and 2e4 random (g, alpha, xi) for Draine (g as HG's, alpha log-uniform
 * over [1e-6, 1e30]), the worst error against the bar of
 * tests/test_accuracy.c, how many samples equal the float128 root rounded
 * to double (of those whose root is not within 1e-30 of a midpoint, where
 * float128 cannot decide), and how many adjacent xi pairs come out
 * reversed.  Prints which
 * arithmetic the build uses.  Run: ./build/mist_ddcheck  (~20 s: the
 * Rayleigh reference integrates in float128). */
#include "mist.h"
#include "mist_ref.h"

#include <stdio.h>
#include <stdlib.h>
#include <stdint.h>

static uint64_t s_ = 88172645463325252ull;
static double rnd(void) { s_ ^= s_ << 13; s_ ^= s_ >> 7; s_ ^= s_ << 17; return (s_ >> 11) * 0x1p-53; }

/* one sampler (kind 0 HG, 1 Rayleigh, 2 Draine) at (g, alpha, xi) */
static double sample(int kind, double g, double a, double xi)
{
    return kind == 0 ? mist_hg_sample(g, xi) : kind == 1 ? mist_rayleigh_sample(xi)
                     : mist_draine_sample(g, a, xi);
}

static int dump;   /* MIST_DDCHECK_DUMP set: print each HG sample (g, xi, u) */

/* its tallies */
static void check(int kind, double g, double a, double xi, double *worst, long *exact,
                  long *tie, long *rev)
{
    double u = sample(kind, g, a, xi), x2 = nextafter(xi, 2);
    qreal rg = kind == 1 ? 0 : g, ra = kind == 0 ? 0 : kind == 1 ? 1 : a;
    qreal q = ref_sample_from(rg, ra, xi, u), m;
    double us, r = ref_bar_root((double)rg, ra, xi, u, 0, q, &us), nb;
    if (r > *worst) *worst = r;
    /* a root within 1e-30 of a midpoint between doubles: the float128
     * reference cannot tell which way it rounds (HG at tiny g, where u is
     * 2 xi - 1, a midpoint, plus O(g)): not counted either way */
    nb = q > (qreal)us ? nextafter(us, 2) : nextafter(us, -2);
    m = ((qreal)us + (qreal)nb) / 2;
    if (q - m < (qreal)1e-30 && m - q < (qreal)1e-30) ++*tie;
    else *exact += u == us;
    if (dump && kind == 0) printf("S %a %a %a\n", g, xi, u);   /* bench/hg_exact.py */
    if (x2 <= 1 && sample(kind, g, a, x2) < u) ++*rev;
}

int main(void)
{
    static const char *name[3] = { "mist_hg_sample", "mist_rayleigh_sample",
                                    "mist_draine_sample" };
    long k, n[3] = { 100000, 20000, 20000 }, exact[3] = { 0, 0, 0 }, rev[3] = { 0, 0, 0 };
    long tie[3] = { 0, 0, 0 };
    double worst[3] = { 0, 0, 0 };
    int kind;
    dump = getenv("MIST_DDCHECK_DUMP") != NULL;
#if defined(FP_FAST_FMA)
    printf("double HG, Rayleigh and Draine samplers: double-double (FP_FAST_FMA)\n");
#elif defined(MIST_NO_LONG_DOUBLE) || LDBL_MANT_DIG == DBL_MANT_DIG
    printf("double HG, Rayleigh and Draine samplers: double-double, Dekker's product "
           "(no FP_FAST_FMA, no wider long double)\n");
#else
    printf("double HG and Rayleigh samplers: double-double, Dekker's product (no "
           "FP_FAST_FMA); Draine: long double\n");
#endif
    for (kind = 0; kind < 3; ++kind)
        for (k = 0; k < n[kind]; ++k) {
            int c = (int)(k % 5);
            double g = c == 0 ? pow(10, -300 * rnd()) : c == 1 ? 1 - pow(2, -53 * rnd()) : rnd();
            double a = pow(10, -6 + 36 * rnd()), xi = rnd();
            g = rnd() < 0.5 ? -g : g;
            if (k % 3 == 1) xi = pow(xi, 40);
            else if (k % 3 == 2) xi = 1 - pow(xi, 8);
            if (k % 7 == 0) xi = ldexp(1, -(int)(1074 * rnd()));
            check(kind, g, a, xi, &worst[kind], &exact[kind], &tie[kind], &rev[kind]);
        }
    for (kind = 0; kind < 3; ++kind)
        printf("%s: worst %.3g of the bar; %ld of %ld the rounded root (%ld more within "
               "1e-30 of a midpoint: undecided); %ld reversed adjacent pairs\n", name[kind],
               worst[kind], exact[kind], n[kind] - tie[kind], tie[kind], rev[kind]);
    return 0;
}
