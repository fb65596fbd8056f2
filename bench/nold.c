/* nold.c - the double samplers as built without a wider long double
 * (MIST_NO_LONG_DOUBLE) and, on x86 with gcc or clang, without fma
 * (-mno-fma -mno-avx512f, CMakeLists.txt): what MSVC x64 gets, double-double
 * by Dekker's product (see "Henyey-Greenstein: exact sampling" in mist.h;
 * for HG and Rayleigh also what every build without fma gets),
 * timed by bench/mist_bench.c in loops of the same shape as its own
 * (bench/bench.h).  -mno-fma alone is not enough: AVX-512 keeps fma and
 * FP_FAST_FMA. */
#define MIST_NO_LONG_DOUBLE
#include "mist.h"
#include "bench.h"

#define NOLD_LOOP(EXPR) { int i; for (i = 0; i < n; ++i) { double v_ = EXPR; NOVEC(v_); \
                          out[i] = v_; } return out[n / 2]; }

double nold_hg_sample(double g, const double *x, double *out, int n)
    NOLD_LOOP(mist_hg_sample(g, x[i]))
double nold_draine_sample(double g, double a, const double *x, double *out, int n)
    NOLD_LOOP(mist_draine_sample(g, a, x[i]))
double nold_rayleigh_sample(const double *x, double *out, int n)
    NOLD_LOOP(mist_rayleigh_sample(x[i]))

double nold_hg_sample_n(double g, const double *x, double *out, int n)
{
    mist_hg_sample_n(g, x, out, (size_t)n);
    return out[n / 2];
}

double nold_rayleigh_sample_n(const double *x, double *out, int n)
{
    mist_rayleigh_sample_n(x, out, (size_t)n);
    return out[n / 2];
}
