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

/* The samplers renderers ship, written here from their published form as
 * the benchmark's baselines.  Blender Cycles and pbrt-v4 sample HG by eq. 3
 * with the eq. 4 fallback (hg_sample_printed above); Cycles samples Draine
 * by eq. 6 in float and Rayleigh by the cubic's closed form, both with a
 * cube root from the exponent bits and two Newton steps in place of cbrtf.
 * rcbrt_bitsf(x) = x^(-1/3) for normal x > 0: the bits' estimate is within
 * ~4% (the exponent divided by 3, the mantissa linear), each Newton step
 * y (4 - x y^3) / 3 squares the relative error: ~2e-5 after two. */
MP_FN float rcbrt_bitsf(float x)
{
    union { float f; unsigned int u; } v;
    float y;
    v.f = x;
    v.u = 0x54a2fa8cu - v.u / 3u;   /* (4/3) 2^23 (127 - 0.0450466) */
    y = v.f;
    y = y * (4.0f - x * y * y * y) * (1.0f / 3.0f);
    y = y * (4.0f - x * y * y * y) * (1.0f / 3.0f);
    return y;
}
MP_FN float cbrt_bitsf(float x) { return 1.0f / rcbrt_bitsf(x); }
MP_FN float draine_cyclesf(float g, float alpha, float xi) { EQ6(float, sqrtf, cbrt_bitsf) }
#undef EQ6
/* Rayleigh: u^3 + 3u = a (a = 4 xi - 2) has the root u = c - 1/c, c =
 * cbrt(a + sqrt(a^2 + 4)) / cbrt(2); with r = 1/c from rcbrt_bitsf */
MP_FN float rayleigh_cyclesf(float xi)
{
    float a = 2 - 4 * xi;
    float r = -rcbrt_bitsf(sqrtf(1 + a * a) + a);
    return 1 / r - r;
}

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

/* [BH83] Appendix A (BHMIE), the textbook Lorenz-Mie series as printed:
 * nstop = x + 4 x^(1/3) + 2 terms; D_n(mx) by the downward recurrence
 * from nmx = max(nstop, |mx|) + 15, started at 0; psi_n and chi_n upward
 * from n = 0; a_n, b_n as its two quotients.  In real arithmetic (no
 * <complex.h>: MSVC), complex division done as printed (no scaling).
 * The baseline of mist_mie_sphere_make (bench/mist_bench.c), which adds
 * Lentz's start for D_n, psi_n downward past x, the series' tail past
 * nstop and range checks.  bhmie_nmx: the D_n array's last index;
 * d: 2 (nmx + 1) doubles; ab: 4 nstop doubles (a_n then b_n, re and im,
 * n = 1..nstop).  Returns nstop; *qsum = sum (2n+1)(|a_n|^2 + |b_n|^2). */
static inline int bhmie_nstop(double x) { return (int)(x + 4 * cbrt(x) + 2); }
static inline int bhmie_nmx(double x, double mr, double mi)
{
    double y = sqrt(mr * mr + mi * mi) * x;
    int nstop = bhmie_nstop(x);
    return (int)(y > nstop ? y : nstop) + 15;
}
static inline void bhmie_cdiv(double ar, double ai, double br, double bi, double *r, double *i)
{
    double q = br * br + bi * bi;
    *r = (ar * br + ai * bi) / q;
    *i = (ai * br - ar * bi) / q;
}
/* a_n or b_n: (t psi - psi_{n-1}) / (t xi - xi_{n-1}), xi = psi - i chi,
 * for t = tr + i ti (D_n/m + n/x for a_n, m D_n + n/x for b_n) */
static inline void bhmie_coef(double tr, double ti, double psi, double chi, double psi1,
                              double chi1, double *r, double *i)
{
    bhmie_cdiv(tr * psi - psi1, ti * psi, tr * psi + ti * chi - psi1,
               ti * psi - tr * chi + chi1, r, i);
}
static inline int bhmie_printed(double x, double mr, double mi, double *d, double *ab,
                                double *qsum)
{
    int nstop = bhmie_nstop(x), nmx = bhmie_nmx(x, mr, mi), n;
    double yr = mr * x, yi = mi * x, yy = yr * yr + yi * yi;
    double psi0 = cos(x), psi1 = sin(x), chi0 = -sin(x), chi1 = cos(x), q = 0;
    d[2 * nmx] = 0; d[2 * nmx + 1] = 0;
    for (n = nmx; n > 1; --n) {                 /* D_{n-1} = n/y - 1/(D_n + n/y) */
        double er = n * yr / yy, ei = -n * yi / yy, tr, ti;
        bhmie_cdiv(1, 0, d[2 * n] + er, d[2 * n + 1] + ei, &tr, &ti);
        d[2 * n - 2] = er - tr; d[2 * n - 1] = ei - ti;
    }
    for (n = 1; n <= nstop; ++n) {
        double psi = (2 * n - 1) * psi1 / x - psi0, chi = (2 * n - 1) * chi1 / x - chi0;
        double dr, di, ar, ai, br, bi;
        bhmie_cdiv(d[2 * n], d[2 * n + 1], mr, mi, &dr, &di);          /* D_n / m */
        bhmie_coef(dr + n / x, di, psi, chi, psi1, chi1, &ar, &ai);
        dr = mr * d[2 * n] - mi * d[2 * n + 1];                          /* m D_n */
        di = mr * d[2 * n + 1] + mi * d[2 * n];
        bhmie_coef(dr + n / x, di, psi, chi, psi1, chi1, &br, &bi);
        ab[2 * n - 2] = ar; ab[2 * n - 1] = ai;
        ab[2 * nstop + 2 * n - 2] = br; ab[2 * nstop + 2 * n - 1] = bi;
        q += (2 * n + 1) * (ar * ar + ai * ai + br * br + bi * bi);
        psi0 = psi1; psi1 = psi; chi0 = chi1; chi1 = chi;
    }
    *qsum = q;
    return nstop;
}
/* BHMIE's angle sums S1, S2 at mu (pi_n, tau_n upward), as a phase
 * function per steradian: (|S1|^2 + |S2|^2) / (4 pi qsum) */
static inline double bhmie_phase_printed(const double *ab, int nstop, double qsum, double mu)
{
    double p0 = 0, p1 = 1, s1r = 0, s1i = 0, s2r = 0, s2i = 0;
    int n;
    for (n = 1; n <= nstop; ++n) {
        double f = (2.0 * n + 1) / (n * (n + 1.0)), tau = n * mu * p1 - (n + 1) * p0, p2;
        const double *a = ab + 2 * n - 2, *b = ab + 2 * nstop + 2 * n - 2;
        s1r += f * (a[0] * p1 + b[0] * tau); s1i += f * (a[1] * p1 + b[1] * tau);
        s2r += f * (a[0] * tau + b[0] * p1); s2i += f * (a[1] * tau + b[1] * p1);
        p2 = ((2.0 * n + 1) * mu * p1 - (n + 1.0) * p0) / n;
        p0 = p1; p1 = p2;
    }
    return (s1r * s1r + s1i * s1i + s2r * s2r + s2i * s2i) / (4 * 3.14159265358979323846 * qsum);
}

#endif
