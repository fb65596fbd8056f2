/* mist_alt.h - the cheap alternatives a renderer might use instead of an
 * exact phase function, as baselines for bench/mist_bench.c (cost) and
 * examples/tradeoff.c (cost and error).  Not part of the library.
 *
 *   Schlick   p(u) = (1 - k^2) / (4 pi (1 - k u)^2), k = 1.55 g - 0.55 g^3
 *             (the usual mapping from g).  It integrates to 1 as written;
 *             its inverse CDF is u = (2 xi - 1 + k) / (1 - k + 2 k xi).
 *   LUT       a table of a density at N values of u uniform in [-1, 1],
 *             linear interpolation (eval), and a table of its inverse CDF
 *             at N values of xi uniform in [0, 1], linear interpolation
 *             (sample): what a renderer bakes once per medium.  The tables
 *             are built by the caller (alt_lut_build) from any density.
 * Each is defined once for double and float (ALT_DEF below). */
#ifndef MIST_ALT_H
#define MIST_ALT_H

#include <math.h>
#include <stdlib.h>

#define ALT_INV4PI 0.0795774715459476678844418816862571810

typedef struct { int n; double *p, *icdf; } alt_lut;
typedef struct { int n; float *p, *icdf; } alt_lutf;

#define ALT_DEF(T, S, LUT)                                                     \
static inline T alt_schlick_k##S(T g) { return (T)1.55 * g - (T)0.55 * g * g * g; } \
static inline T alt_schlick_eval##S(T k, T u)                                  \
{                                                                              \
    T d = 1 - k * u;                                                           \
    return (T)ALT_INV4PI * (1 - k * k) / (d * d);                              \
}                                                                              \
static inline T alt_schlick_sample##S(T k, T xi)                               \
{                                                                              \
    return (2 * xi - 1 + k) / (1 - k + 2 * k * xi);                            \
}                                                                              \
/* linear interpolation in a table t[0..n-1] at x in [0, n-1] */               \
static inline T alt_lerp##S(const T *t, int n, T x)                            \
{                                                                              \
    int i = (int)x;                                                            \
    T f;                                                                       \
    if (i > n - 2) i = n - 2;                                                  \
    if (i < 0) i = 0;                                                          \
    f = x - (T)i;                                                              \
    return t[i] + f * (t[i + 1] - t[i]);                                       \
}                                                                              \
static inline T alt_lut_eval##S(const LUT *l, T u)                             \
{                                                                              \
    return alt_lerp##S(l->p, l->n, (u + 1) * (T)0.5 * (T)(l->n - 1));          \
}                                                                              \
static inline T alt_lut_sample##S(const LUT *l, T xi)                          \
{                                                                              \
    return alt_lerp##S(l->icdf, l->n, xi * (T)(l->n - 1));                     \
}                                                                              \
/* Tables of n entries of the density dens(u) (per steradian): the CDF on a   \
 * fine grid (trapezoid rule on 64 n intervals), inverted by linear search. */ \
static inline LUT alt_lut_build##S(int n, double (*dens)(double u, const void *), \
                                   const void *par)                            \
{                                                                              \
    LUT l;                                                                     \
    int i, j, m = 64 * n;                                                      \
    double *c = (double *)malloc(sizeof(double) * (size_t)(m + 1));            \
    l.n = n;                                                                   \
    l.p = (T *)malloc(sizeof(T) * (size_t)n);                                  \
    l.icdf = (T *)malloc(sizeof(T) * (size_t)n);                               \
    if (!c || !l.p || !l.icdf) abort();                                        \
    for (i = 0; i < n; ++i) l.p[i] = (T)dens(-1 + 2.0 * i / (n - 1), par);     \
    c[0] = 0;                                                                  \
    for (j = 0; j < m; ++j) {                                                  \
        double u0 = -1 + 2.0 * j / m, u1 = -1 + 2.0 * (j + 1) / m;             \
        c[j + 1] = c[j] + (dens(u0, par) + dens(u1, par)) * (u1 - u0) / 2;    \
    }                                                                          \
    for (j = 0, i = 0; i < n; ++i) {                                           \
        double x = c[m] * i / (n - 1);                                         \
        while (j < m - 1 && c[j + 1] < x) ++j;                                 \
        l.icdf[i] = (T)(-1 + 2.0 * (j + (c[j + 1] > c[j]                       \
                        ? (x - c[j]) / (c[j + 1] - c[j]) : 0)) / m);           \
    }                                                                          \
    free(c);                                                                   \
    return l;                                                                  \
}

ALT_DEF(double, , alt_lut)
ALT_DEF(float, f, alt_lutf)
#undef ALT_DEF

#endif
