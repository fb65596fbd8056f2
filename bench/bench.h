/* bench.h - shared by bench/mist_bench.c and bench/nold.c.
 *
 * A scalar figure is the cost of one call: each result is stored (no sum
 * whose add chain would bound the loop), and NOVEC, an empty asm that
 * claims to change the value, keeps the compiler from vectorising the loop,
 * for mist and for the baselines alike (a vectorised baseline beside a
 * scalar mist call was the old eq. 3 row: 0.68 ns).  The batch rows below
 * compare vector code with vector code.  Where NOVEC is empty (not gcc or
 * clang on x86-64 or AArch64) the output says so. */
#ifndef MIST_BENCH_H
#define MIST_BENCH_H

#if (defined(__GNUC__) || defined(__clang__)) && (defined(__x86_64__) || defined(__i386__))
#  define NOVEC(v) __asm__("" : "+x"(v))
#  define NOVEC_OK 1
#elif (defined(__GNUC__) || defined(__clang__)) && defined(__aarch64__)
#  define NOVEC(v) __asm__("" : "+w"(v))
#  define NOVEC_OK 1
#else
#  define NOVEC(v) ((void)0)
#  define NOVEC_OK 0
#endif

/* bench/nold.c: the double samplers built with MIST_NO_LONG_DOUBLE and
 * without fma (what MSVC x64 gets), each a loop of n calls over
 * x[] into out[] (scalar loops kept scalar by NOVEC; the batch form one
 * call), returning out[n / 2] */
double nold_hg_sample(double g, const double *x, double *out, int n);
double nold_hg_sample_n(double g, const double *x, double *out, int n);
double nold_draine_sample(double g, double a, const double *x, double *out, int n);
double nold_rayleigh_sample(const double *x, double *out, int n);
double nold_rayleigh_sample_n(const double *x, double *out, int n);

#endif
