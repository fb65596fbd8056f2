/* mist_printed.h - the paper's formulas typed in as printed, the baselines
 * that bench/mist_bench.c and examples/tradeoff.c measure mist against
 * (cost, and for eq. 6 the error).  Not part of the library. */
#ifndef MIST_PRINTED_H
#define MIST_PRINTED_H

#include <math.h>

/* callable from CUDA kernels too (tests/gpu/mist_gpu.cu) */
#ifdef __CUDACC__
#  define MP_FN static inline __host__ __device__
#else
#  define MP_FN static inline
#endif

/* [JD23] eq. 2 */
MP_FN float hg_eval_printed(float g, float u)
{
    return 1.0f / (4.0f * 3.14159265f) * (1 - g * g) / powf(1 + g * g - 2 * g * u, 1.5f);
}

/* [JD23] eq. 3, with the eq. 4 isotropic fallback (float and double) */
#define EQ3(T)                                                                 \
    T t;                                                                       \
    if (g < (T)1e-3 && g > -(T)1e-3) return 2 * xi - 1;                        \
    t = (1 - g * g) / (1 - g + 2 * g * xi);                                    \
    return (1 + g * g - t * t) / (2 * g);
MP_FN float  hg_sample_printed(float g, float xi)    { EQ3(float) }
MP_FN double hg_sample_printed_d(double g, double xi) { EQ3(double) }

/* [JD23] eq. 6, typed in as printed */
#define EQ6(T, SQRT, CBRT)                                                     \
    T t0 = alpha - alpha * g * g;                                              \
    T t1 = alpha * g * g * g * g - alpha;                                      \
    T t2 = -3 * (4 * (g * g * g * g - g * g) + t1 * (1 + g * g));              \
    T t3 = g * (2 * xi - 1);                                                   \
    T t4 = 3 * g * g * (1 + t3) + alpha * (2 + g * g * (1 + (1 + 2 * g * g) * t3)); \
    T t5 = t0 * (t1 * t2 + t4 * t4) + t1 * t1 * t1;                            \
    T t6 = t0 * 4 * (g * g * g * g - g * g);                                   \
    T t7 = CBRT(t5 + SQRT(t5 * t5 - t6 * t6 * t6));                            \
    T t8 = 2 * (t1 + t6 / t7 + t7) / t0;                                       \
    T t9 = SQRT(6 * (1 + g * g) + t8);                                         \
    T w = SQRT(6 * (1 + g * g) - t8 + 8 * t4 / (t0 * t9)) - t9;                \
    return g / 2 + (1 / (2 * g) - 1 / (8 * g) * w * w);
MP_FN float  draine_eq6f(float g, float alpha, float xi) { EQ6(float, sqrtf, cbrtf) }
MP_FN double draine_eq6(double g, double alpha, double xi) { EQ6(double, sqrt, cbrt) }
#undef EQ6

/* [JD23] eq. 5 (Draine; Cornette-Shanks at alpha = 1), with eq. 2's pow,
 * and the fog mixture of eq. 2 and 5 (weight w of Draine) */
MP_FN float draine_eval_printed(float g, float alpha, float u)
{
    return 1.0f / (4.0f * 3.14159265f) * (1 - g * g) / powf(1 + g * g - 2 * g * u, 1.5f)
           * (1 + alpha * u * u) / (1 + alpha * (1 + 2 * g * g) / 3);
}
MP_FN float fog_eval_printed(float g_hg, float g_d, float alpha, float w, float u)
{
    return (1 - w) * hg_eval_printed(g_hg, u) + w * draine_eval_printed(g_d, alpha, u);
}

/* Rayleigh: 3/(16 pi) (1 + u^2) */
MP_FN float rayleigh_eval_printed(float u)
{
    return 3.0f / (16.0f * 3.14159265f) * (1 + u * u);
}

/* [I18] eq. 22-23 as printed, one colour channel: the background b seen
 * from y0 (above the fog's base) along a ray of vertical component wy over
 * length s, through extinction bt = sum of beta_t and scattering bs = sum
 * of beta_s (p L_sun + L_amb), both at the base: b T + bs / bt (1 - T),
 * T = exp(-H / wy bt e^(-y0/H) (1 - e^(-wy s / H))).  Divides by wy and
 * bt: NaN for a level ray or no fog, as printed. */
#define I18(T, EXP)                                                            \
    T tr = EXP(-H / wy * bt * EXP(-y0 / H) * (1 - EXP(-wy * s / H)));          \
    return b * tr + bs / bt * (1 - tr);
MP_FN float  hfog_printedf(float b, float y0, float wy, float s, float H, float bt,
                                   float bs) { I18(float, expf) }
MP_FN double hfog_printed(double b, double y0, double wy, double s, double H,
                                  double bt, double bs) { I18(double, exp) }
#undef I18

#endif
