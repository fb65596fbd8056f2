/* mist_worst.c - the double Draine samplers' worst case against their
 * median call, in the build this file is compiled for (CMakeLists.txt: the
 * default flags, the benchmark's flags, and without long double and fma).
 *
 * The median: the time per call of mist_draine_sample (unprepared) and
 * mist_phase_sample (prepared) at 4096 random (g, alpha, xi), g uniform in
 * (-1, 1), alpha log-uniform in [1e-3, 1e4], xi uniform: each point's calls
 * timed together, the median of those per-point times.  The worst: the
 * largest per-point time over an adversarial grid: |g| from 0 and 1e-300
 * to 1 - 2^-53 (near-Dirac lobes), alpha from 1e-300 to DBL_MAX and +inf
 * (the HG and HG u^2 limits), xi at 1/2 and its neighbours, 1/2 +- 1e-9,
 * the tails, and random.  Each point: 16 calls, the best of 3 such runs
 * (this machine may be shared: the ratio is taken within one run, the
 * median and the worst timed alike).  Prints the ratio and the worst
 * points.  Measured, not a test. */
#define _POSIX_C_SOURCE 199309L
#include "mist.h"
#include "bench.h"

#include <float.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#ifndef MIST_WORST_NAME
#  define MIST_WORST_NAME "mist_worst"
#endif

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

typedef struct { double t, g, a, xi; } point;

static uint64_t rng_s = 0x9e3779b97f4a7c15u;
static double rnd(void)                         /* splitmix64, [0, 1) */
{
    uint64_t z = (rng_s += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return (double)((z ^ (z >> 31)) >> 11) * 0x1p-53;
}

static volatile double sink;

/* ns a call at one point: 16 calls, the best of 3 runs */
static double time_point(const mist_phase *p, double g, double a, double xi)
{
    double best = 1e30;
    int r, i;
    for (r = 0; r < 3; ++r) {
        double t0 = now(), v;
        for (i = 0; i < 16; ++i) {
            NOVEC(xi);                          /* (not hoisted out of the loop) */
            v = p ? mist_phase_sample(p, xi) : mist_draine_sample(g, a, xi);
            sink = v;
        }
        t0 = (now() - t0) / 16;
        if (t0 < best) best = t0;
    }
    return best * 1e9;
}

static int cmp_t(const void *a, const void *b)
{
    double x = ((const point *)a)->t, y = ((const point *)b)->t;
    return x < y ? -1 : x > y;
}

static point pts[2][60000];

int main(void)
{
    static const double gb[] = { 0, 1e-300, 1e-100, 1e-20, 1e-8, 1e-4, 1e-3, 0.01, 0.1, 0.5,
                                 0.9, 0.99, 0.9999, 0.99999, 1 - 1e-6, 1 - 0x1p-30,
                                 1 - 0x1p-46, 1 - 0x1p-51, 1 - 0x1p-53 };
    static const double as[] = { 1e-300, 1e-100, 1e-30, 1e-10, 1e-6, 1e-3, 0.1, 1, 17, 1e3,
                                 1e4, 1e5, 1e8, 1e15, 1e30, 1e100, 1e300, DBL_MAX, INFINITY };
    static const double cx[] = { 0.5, 0.25, 0.75, 1e-3, 1 - 1e-3, 1e-10, 1 - 1e-10, 0.1, 0.9,
                                 0.45, 0.55, 0.49, 0.51, 0.4999, 0.5001, 0.5 - 1e-9,
                                 0.5 + 1e-9, 0.5 - 1e-6, 0.5 + 1e-6,
                                 0x1.99765aeac596bp-1, 0x1.3344d4a8a7294p-3 };
    int ng = (int)(sizeof gb / sizeof *gb), na = (int)(sizeof as / sizeof *as);
    int nx = (int)(sizeof cx / sizeof *cx), s, ig, ia, k, j, pr, nm = 4096, np = 0;
    double med[2], x;
    const char *nm_[2] = { "mist_draine_sample", "mist_phase_sample (prepared)" };
    if (!NOVEC_OK) printf("(NOVEC is empty here: loops may vectorise)\n");
    /* the median */
    for (k = 0; k < nm; ++k) {
        double g = 2 * rnd() - 1, a = pow(10, -3 + 7 * rnd()), xi = rnd();
        mist_phase p = mist_phase_draine(g, a);
        for (pr = 0; pr < 2; ++pr) {
            point q;
            q.t = time_point(pr ? &p : NULL, g, a, xi); q.g = g; q.a = a; q.xi = xi;
            pts[pr][k] = q;
        }
    }
    for (pr = 0; pr < 2; ++pr) {
        qsort(pts[pr], (size_t)nm, sizeof **pts, cmp_t);
        med[pr] = pts[pr][nm / 2].t;
    }
    /* the grid */
    for (s = 0; s < 2; ++s)
        for (ig = 0; ig < ng; ++ig) {
            if (s && gb[ig] == 0) continue;
            for (ia = 0; ia < na; ++ia) {
                double g = s ? -gb[ig] : gb[ig], a = as[ia], xs[48];
                mist_phase p = mist_phase_draine(g, a);
                int n = 0;
                for (k = 0; k < nx; ++k) xs[n++] = cx[k];
                x = 0.5;
                for (k = 0; k < 4; ++k) x = nextafter(x, 0);
                for (k = 0; k < 8; ++k) { xs[n++] = x; x = nextafter(x, 1); }
                for (k = 0; k < 8; ++k) xs[n++] = rnd();
                for (k = 0; k < n; ++k)
                    for (pr = 0; pr < 2; ++pr) {
                        point q;
                        q.t = time_point(pr ? &p : NULL, g, a, xs[k]);
                        q.g = g; q.a = a; q.xi = xs[k];
                        pts[pr][np + k] = q;
                    }
                np += n;
            }
        }
    printf("%s (%s)\n", MIST_WORST_NAME,
#ifdef MIST_BENCH_FLAGS
           MIST_BENCH_FLAGS
#else
           "?"
#endif
           );
    for (pr = 0; pr < 2; ++pr) {
        qsort(pts[pr], (size_t)np, sizeof **pts, cmp_t);
        printf("  %s: median %.1f ns (random, 4096 points), worst %.1f ns (grid, %d points): "
               "%.1fx; 99.9%%: %.1fx\n", nm_[pr], med[pr], pts[pr][np - 1].t, np,
               pts[pr][np - 1].t / med[pr], pts[pr][np - 1 - np / 1000].t / med[pr]);
        for (j = 1; j <= 5; ++j) {
            const point *q = &pts[pr][np - j];
            printf("    %7.1f ns  g %-24.17g alpha %-8.3g xi %a\n", q->t, q->g, q->a, q->xi);
        }
    }
    return 0;
}
