/* mist_mie.h - Lorenz-Mie reference for mist: homogeneous spheres, water,
 * and averages over droplet sizes and wavelengths.                  v0.1.0
 *
 * OPT-IN.  A renderer that only wants the analytic phase functions includes
 * mist.h and never this file; nothing in mist.h refers to it.  This header
 * is for building reference curves and tables (fits, LUTs, tests).
 *
 * Header-only C99, also C++ (C++98 and later).  Double precision only.
 * Needs <math.h>; <stdlib.h> (malloc/free) only for mist_mie_sphere_new and
 * mist_mie_average, which say so.
 *
 * USAGE
 *   #include "mist_mie.h"
 *
 *   // One sphere: size parameter x = 2 pi r n_medium / lambda and
 *   // refractive index m = m_particle / n_medium = mr + i mi (mi >= 0).
 *   mist_mie_sphere s = mist_mie_sphere_new(57.1, mist_mie_water(550, NULL));
 *   double q = s.q_sca, g = s.g;               // efficiencies, asymmetry
 *   double p = mist_mie_phase(&s, cos_theta);  // per steradian, sums to 1
 *   mist_mie_complex s1, s2;
 *   mist_mie_amplitudes(&s, cos_theta, &s1, &s2);
 *   mist_mie_sphere_free(&s);
 *
 *   // A fog: droplets of a gamma distribution, three wavelengths, a table
 *   // of the phase function at 1800 angles uniform in theta.
 *   double mu[1800], table[1800];
 *   mist_mie_wavelength wl[3];
 *   mist_mie_dist d = mist_mie_dist_gamma(5.0, 0.1);    // r_eff 5 um, v_eff 0.1
 *   wl[0] = mist_mie_wl(0.45, 1, mist_mie_water(450, NULL));  ... (um)
 *   mist_mie_theta_grid(1800, mu);
 *   mist_mie_avg a = mist_mie_average(&d, wl, 3, 1.0, mu, 1800, table);
 *   // a.c_ext, a.c_sca (um^2 per droplet), a.g, table[j] = p(theta_j) /sr
 *
 *   // Nodes for mist.h's tabulated phase function (mist_tab_init), placed
 *   // to a requested accuracy (log10 RMS over theta, L1), at most 4096:
 *   double tmu[4096], tp[4096];
 *   mist_mie_tabfit f = mist_mie_tab_nodes(&d, wl, 3, 0, 1.0, 0.01, 0.02,
 *                                          4096, tmu, tp);  // f.n nodes
 *
 *   // Three linear-sRGB channels integrated over 380-780 nm (CIE 1931,
 *   // D65, every 5 nm), each normalised: p3[j * 3 + c], for mist_tab_init
 *   // with 3 channels; r.c_sca[c] each channel's cross section (um^2):
 *   double p3[3 * 1800];
 *   mist_mie_rgb r = mist_mie_spectral_rgb(&d, 1.0, NULL, NULL, 81, mu, 1800, p3);
 *
 * CONVENTIONS
 *   Bohren & Huffman [BH83]: m = mr + i mi with mi >= 0 (time factor
 *   exp(-i omega t)), xi_n = psi_n - i chi_n, and their amplitudes S1, S2
 *   (pp. 111-114).  Wiscombe's MIEV0 [W79] and miepython write m = mr -
 *   i mi; their S1, S2 are the complex conjugates of these (a_n, b_n too).
 *   Efficiencies, g and every intensity |S|^2 are the same in both.
 *   theta is the angle between the incident and scattered PROPAGATION
 *   directions, mu = cos(theta); S1(1) = S2(1) is the forward amplitude.
 *   Q_back is [BH83]'s backscattering efficiency 4 |S1(-1)|^2 / x^2, so
 *   Q_back = 4 pi Q_sca p(-1).
 *   The phase function is normalised over the sphere:
 *     p(mu) = (|S1|^2 + |S2|^2) / (2 pi x^2 Q_sca),  2 pi int p dmu = 1.
 *   Size parameter x = 2 pi r n_medium / lambda (lambda in vacuum), m =
 *   m_particle / n_medium.  No global state: every function is reentrant.
 *
 * ACCURACY (tests/test_mie.c)
 *   Wiscombe's 19 MIEV0 test cases: Q_ext, Q_sca, g Q_sca and S1, S2 at
 *   seven angles agree with his 7 printed digits to within half a unit,
 *   except where MIEV0 used its small-particle expansions (x |m| < 0.1;
 *   up to 5e-5 off, confirmed MIEV0's by a 40-digit series) and case 6
 *   (x = 0.101, 4 units off in MIEV0; Du (2004) agrees with mist_mie).
 *   The series runs past Wiscombe's N until a term is below 1e-18 of the
 *   largest (at most N + 4 x^(1/3) + 8 terms: mist_mie__cap).  Against an
 *   independent mpmath series (tests/mie_mpmath_ref.py; test_series_tail:
 *   x from 1e-6 to 1e4, |m| to 1000, two narrow resonances) Q_ext, Q_sca,
 *   Q_back, g (relative to max(|g|, 1e-3)) and p(mu) are within 5e-12 up
 *   to x = 1000, 1e-10 at x = 1e4; an independent check of 372 random
 *   cases with |m - 1| > 0.01, x from 1e-6 to 5000: Q and g within 5e-12,
 *   p(mu) within 1.3e-10 (x = 5000).
 *   m close to 1 (test_near_one, 57 mpmath cases, x to 1e5, m - 1 from
 *   1e-3 to 1e-12 and i 1e-310, real, complex, below 1): every coefficient
 *   is computed with m - 1 or m^2 - 1 a factor (see the sphere), so at
 *   x |m| < 1 Q_ext, Q_sca, Q_back, g (relative to g itself) and S1, S2
 *   are within 1e-13 relative whatever m - 1 (measured at most 1e-15); at
 *   x |m| >= 1 and |m - 1| < 1e-3 Q_ext, Q_sca and g (relative to g) within
 *   1e-14 + 16 eps sqrt(x) (1 + |m - 1| x) relative whatever m - 1
 *   (measured: Q_sca 4.5e-13 at x = 1e5, g 3.4e-14), at |m - 1| >= 1e-3
 *   within 1e-13 + 1e-15 / |m - 1|.  S1, S2 too, and they carry the
 *   rounding of their ~x terms, 8 eps x^(3/2) min(1, sqrt(Q_sca))
 *   absolutely (a random walk of N terms up to (2n+1)(|a_n| + |b_n|)/2:
 *   S(0.5) within 5.4e-11 relative at x = 1e5), which is what p(mu) near
 *   180 degrees shows where it is small.  At mu = -1 the sum cancels
 *   (|S1(-1)| down to 1e-5 of its terms' moduli, Q_back / Q_sca to
 *   1e-10): there a_n - b_n is computed as one number with m - 1 a
 *   factor (below n2, see the sphere) and the terms (2n+1)/2 (a_n - b_n)
 *   summed compensated, so S1(-1), S2(-1) are within 2 eps |m - 1| x^2
 *   absolutely (a few eps of their terms' moduli, ~|m - 1| x^2 / 2 in
 *   all), 4 eps |m - 1| x / sqrt(Q_back) relative, and Q_back = 4
 *   |S1(-1)|^2 / x^2 within twice that relative: 1e-9 wherever Q_back >=
 *   3.2e-12 (|m - 1| x)^2 (measured at most 0.18 of the bound; S1(-1)
 *   3.2e-11 relative at x = 1e5, m = 1.0001 + 1e-7 i, Q_back 4.7e-11;
 *   the difference of the rounded a_n, b_n, eps |a_n| a term, leaves
 *   S1(-1) ~1e-9 off at x = 8000, m = 1.0001).  At |m - 1| >= 1e-3,
 *   Q_back within 32 eps sqrt(x min(1, Q_sca) / Q_back) more.  m - 1
 *   below 2^-64 is scaled by a power of 2, so g, p and S keep their
 *   digits down to a subnormal m - 1
 *   (Q_sca and Q_back are 0 only where they leave double's range; the
 *   dipole limit, x < 1e-8, scales its coefficients the same way).
 *   At mu = +-1 the angle factors are exact integers:
 *   S1(1) = S2(1) and S2(-1) = -S1(-1) bit for bit.  Near mu = +-1 at
 *   large x, p moves by ~x^2/2 times mu's rounding (an independent check:
 *   1.4e-10 at x = 1000, mu = -1 + 2^-53).  Cut at N
 *   itself, as MIEV0 and Du (2004) do, the tail stays in the results: Q_back 2e-7 off
 *   at x = 339 and 4200, 6.3e-6 at x = 1e4, m = 1.33 + 1e-5 i (which is
 *   why their printed amplitudes are compared with mist_mie's coefficients
 *   summed to N in tests/test_mie.c); at x < 0.0148, where N = 1, b_1
 *   and a_2 are dropped (Q_back and p(mu) 0.2 x^2 off, g 30-46%); and a
 *   narrow resonance of an order past N is missed (m = 30, x = 0.2328940:
 *   Q_sca 0.012 for 332).  A resonance narrower than double's resolution
 *   of x (relative width below ~1e-16) cannot be resolved in double; next
 *   to one, the results move by its sensitivity to x times ~1e-16.
 *
 * DOMAIN AND BAD INPUT (tested in tests/test_mie.c)
 *   x    in (0, MIST_MIE_X_MAX], finite.  Tiny x is exact (the dipole limit
 *        below 1e-8, where the neglected terms are below 1e-16 relative;
 *        g there is its leading term, x^2/15 Re((m^2 + 2)(m^2 + 3) /
 *        (2 m^2 + 3)), 0.16 x^2 at m = 1).
 *   m    mr > 0, mi >= 0, both not NaN, MIST_MIE_M_MIN <= |m| <=
 *        MIST_MIE_M_MAX and |m| x <= MIST_MIE_MX_MAX.  mr = +INFINITY (or mi
 *        = +INFINITY) is the perfectly conducting sphere (mist_mie_conductor).
 *        m = 1 is valid: nothing scatters (Q = 0, p = 0 everywhere).
 *   mu   in [-1, 1]; clamped; NaN gives amplitudes 0 and density 0.
 *   mist_mie_average: lengths (wavelengths, radii, in one unit of your
 *        choice) in [MIST_MIE_LEN_MIN, MIST_MIE_LEN_MAX] = [1e-30, 1e30],
 *        weights finite >= 0 of any scale; see there.
 *   Bad x or m: the sphere has status MIST_MIE_EDOMAIN and every number in
 *   it is 0; every function given such a sphere returns 0.  Finite valid
 *   input never gives NaN or infinity.  No function ever reads or writes
 *   outside the memory it was given, nor loops without end, in any build:
 *   also with MIST_ALLOW_FAST_MATH under -ffast-math (which may delete
 *   NaN tests), every size, index and loop count derived from a double is
 *   checked on its bits and bounded in integers (test_mie_fastmath).
 *
 * REFERENCES (section by section below)
 *   [BH83] C. Bohren, D. Huffman, "Absorption and Scattering of Light by
 *          Small Particles", Wiley 1983: ch. 4 (pp. 94-95 pi_n, tau_n;
 *          pp. 111-114 S1, S2; pp. 103, 119-122 cross sections, g,
 *          backscatter; p. 127 eqs. 4.88-4.89 a_n, b_n from D_n) and ch. 5
 *          (the small-particle limit).
 *   [W79]  W. Wiscombe, "Mie scattering calculations: advances in technique
 *          and fast, vector-speed computer codes", NCAR TN-140+STR (1979,
 *          edited 1996) and [W80] "Improved Mie scattering algorithms",
 *          Appl. Opt. 19, 1505-1509 (1980): eqs. 1a-1e (Q_ext, Q_sca, g Q_sca,
 *          S1, S2; W79 eqs. R6-R8), the number of terms (W79 eq. R50, W80
 *          p. 1508), D_n downward from a Lentz start (W79 eq. R23), the
 *          perfectly conducting sphere (W79 eqs. R/A.1-2).
 *   [L76]  W. Lentz, "Generating Bessel functions in Mie scattering
 *          calculations using continued fractions", Appl. Opt. 15, 668-671
 *          (1976); modified as in I. Thompson, A. Barnett, J. Comput. Phys.
 *          64, 490 (1986).
 *   [D04]  H. Du, "Mie-scattering calculation", Appl. Opt. 43, 1951-1956
 *          (2004): why the starting value of the downward recurrence matters.
 *   [HQ73] G. Hale, M. Querry, "Optical constants of water in the 200-nm to
 *          200-um wavelength region", Appl. Opt. 12, 555-563 (1973), Table I.
 *   [HT74] J. Hansen, L. Travis, "Light scattering in planetary atmospheres",
 *          Space Sci. Rev. 16, 527-610 (1974), eq. 2.56.
 *   [D69]  D. Deirmendjian, "Electromagnetic Scattering on Spherical
 *          Polydispersions", Elsevier 1969 (modified gamma distribution).
 *
 * LICENSE: MIT (see the end of include/mist.h).
 */
#ifndef MIST_MIE_H
#define MIST_MIE_H

#define MIST_MIE_VERSION_STRING "0.1.0"

#include <math.h>
#include <float.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* The fast-math guard of mist.h (see FAST MATH there; MIST_ALLOW_FAST_MATH
 * turns it off): without it gcc -ffast-math drops the NaN tests and
 * tests/test_mie.c crashes.  Popped at the end of the file. */
#define MIST__FP_PUSH
#include "mist.h"
#undef MIST__FP_PUSH

#ifndef MIST_MIE_FUNC
#  define MIST_MIE_FUNC static inline
/* The complex helpers of the series, forced inline: in a large translation
 * unit gcc stops inlining them (its unit-growth limits) and each becomes a
 * call: mist_mie_sphere_make then took 1.9-2.3x as long in the benchmark
 * (x = 1 to 1000; docs/history.md).  Not for the public mist_mie_cplx
 * under gcc's fast-math guard (forced into a fast-math caller it would not
 * inline: see MIST__API_HOT in mist.h). */
#  if defined(__GNUC__) && !defined(__CUDACC__)
#    define MIST_MIE__HOT __attribute__((always_inline))
#    if !(defined(MIST__FP_GUARD) && MIST__FP_GUARD == 2)
#      define MIST_MIE__API_HOT MIST_MIE__HOT
#    endif
#  endif
#endif
#ifndef MIST_MIE__HOT
#  define MIST_MIE__HOT
#endif
#ifndef MIST_MIE__API_HOT
#  define MIST_MIE__API_HOT
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ------------------------------------------------------------------------ */
/* Status codes and limits                                                  */
/* ------------------------------------------------------------------------ */

#define MIST_MIE_OK       0   /* success                                       */
#define MIST_MIE_EDOMAIN  1   /* input outside the documented domain           */
#define MIST_MIE_ENOMEM   2   /* workspace too small / NULL, or malloc failed  */
#define MIST_MIE_CLAMPED  3   /* mist_mie_water only: wavelength outside the
                                 table, the nearest end value is returned     */

#define MIST_MIE_X_MAX    1e5   /* largest size parameter                      */
#define MIST_MIE_M_MIN    1e-6  /* smallest |m|                                */
#define MIST_MIE_M_MAX    1e6   /* largest finite |m|                          */
#define MIST_MIE_MX_MAX   1e7   /* largest |m| x (the continued fraction costs
                                   about |m| x steps)                          */
#define MIST_MIE_LEN_MIN  1e-30 /* mist_mie_average: the lengths (wavelengths,  */
#define MIST_MIE_LEN_MAX  1e30  /* radii, law radii) lie in [LEN_MIN, LEN_MAX]  */

/* size distributions, see mist_mie_dist_* */
#define MIST_MIE_DIST_MONO      0
#define MIST_MIE_DIST_GAMMA     1
#define MIST_MIE_DIST_MODGAMMA  2
#define MIST_MIE_DIST_LOGNORMAL 3
#define MIST_MIE_DIST_TABLE     4

#define MIST_MIE__PI    3.14159265358979323846264338327950288
#define MIST_MIE__X_TINY 1e-8   /* below: the dipole limit (see the sphere) */
#define MIST_MIE__NEAR1 1e-3    /* |m - 1| below: cross products (the sphere) */

/* ------------------------------------------------------------------------ */
/* Types                                                                    */
/* ------------------------------------------------------------------------ */

/* A complex number (not <complex.h>, so the header is C++ too). */
typedef struct mist_mie_complex { double re, im; } mist_mie_complex;

/* One homogeneous sphere: the result of mist_mie_sphere_make / _new.
 * On error status != MIST_MIE_OK and every number is 0.  The series
 * coefficients live in the caller's workspace (or, from _new, in memory the
 * sphere owns): the sphere is valid while that memory is. */
typedef struct mist_mie_sphere {
    int status;            /* MIST_MIE_OK or MIST_MIE_EDOMAIN / _ENOMEM     */
    int n_terms;           /* terms summed: Wiscombe's N [W80] and on       */
    double x;              /* size parameter                                */
    mist_mie_complex m;    /* refractive index (mr = +inf: conductor)       */
    double q_ext, q_sca, q_abs, q_back;   /* efficiencies (cross section /
                                              pi r^2); q_abs = q_ext - q_sca */
    double g;              /* asymmetry parameter <cos theta>               */
    /* internal */
    const double *coef_;   /* 6 doubles per term, then S1(-1): see the sphere */
    double amp_scale_;     /* amplitudes = amp_scale_ * the series          */
    double p_norm_;        /* p = p_norm_ * (|S1|^2 + |S2|^2) of the series */
    double *owned_;        /* memory from mist_mie_sphere_new, else NULL    */
} mist_mie_sphere;

/* One wavelength of an average: vacuum wavelength (same length unit as the
 * radii), weight >= 0 (e.g. spectral power times sensitivity; normalised
 * by their sum), and the particle's refractive index there (absolute; it
 * is divided by the medium's index). */
typedef struct mist_mie_wavelength {
    double lambda, weight;
    mist_mie_complex m;
} mist_mie_wavelength;

/* A number distribution of radii n(r) (any normalisation: it is normalised
 * numerically over [r_min, r_max]).  Build it with mist_mie_dist_*; then
 * r_min, r_max (0, 0: automatic) and n_radii (0: automatic) may be set. */
typedef struct mist_mie_dist {
    int kind;                  /* MIST_MIE_DIST_*                            */
    double p1, p2, p3;         /* parameters, see the constructors           */
    double r_min, r_max;       /* integration range; both 0: automatic       */
    int n_radii;               /* quadrature nodes; 0: automatic             */
    const double *r, *w;       /* MIST_MIE_DIST_TABLE: radii and weights     */
    size_t n;                  /* MIST_MIE_DIST_TABLE: number of nodes       */
} mist_mie_dist;

/* The result of mist_mie_average: per particle, averaged over the size
 * distribution and the wavelengths.  Cross sections in (length unit)^2. */
typedef struct mist_mie_avg {
    int status;            /* MIST_MIE_OK, _EDOMAIN or _ENOMEM              */
    double c_ext, c_sca, c_abs, c_back;   /* mean cross sections            */
    double g;              /* asymmetry, weighted by scattering             */
    double albedo;         /* c_sca / c_ext (0 if c_ext = 0)                */
    double area, volume;   /* mean pi r^2 and 4/3 pi r^3                    */
    double r_min, r_max;   /* the range used                                */
    int n_radii;           /* the nodes used                                */
} mist_mie_avg;

/* ======================================================================== */
/* Small helpers                                                            */
/* ======================================================================== */

/* A complex number re + i im (any values; the functions check theirs). */
MIST_MIE_FUNC MIST_MIE__API_HOT mist_mie_complex mist_mie_cplx(double re, double im)
{
    mist_mie_complex z;
    z.re = re; z.im = im;
    return z;
}

/* The perfectly conducting sphere's "refractive index": (+inf, 0). */
MIST_MIE_FUNC mist_mie_complex mist_mie_conductor(void)
{
    return mist_mie_cplx((double)INFINITY, 0.0);
}

/* A wavelength entry for mist_mie_average (checked there). */
MIST_MIE_FUNC mist_mie_wavelength mist_mie_wl(double lambda, double weight,
                                              mist_mie_complex m)
{
    mist_mie_wavelength w;
    w.lambda = lambda; w.weight = weight; w.m = m;
    return w;
}

MIST_MIE_FUNC MIST_MIE__HOT mist_mie_complex mist_mie__add(mist_mie_complex a, mist_mie_complex b)
{ return mist_mie_cplx(a.re + b.re, a.im + b.im); }
MIST_MIE_FUNC MIST_MIE__HOT mist_mie_complex mist_mie__sub(mist_mie_complex a, mist_mie_complex b)
{ return mist_mie_cplx(a.re - b.re, a.im - b.im); }
MIST_MIE_FUNC MIST_MIE__HOT mist_mie_complex mist_mie__mul(mist_mie_complex a, mist_mie_complex b)
{ return mist_mie_cplx(a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re); }
MIST_MIE_FUNC MIST_MIE__HOT mist_mie_complex mist_mie__scale(mist_mie_complex a, double s)
{ return mist_mie_cplx(a.re * s, a.im * s); }
MIST_MIE_FUNC MIST_MIE__HOT double mist_mie__abs2(mist_mie_complex a)
{ return a.re * a.re + a.im * a.im; }

/* a / b by Smith's algorithm (no overflow from |b|^2).  b != 0. */
MIST_MIE_FUNC MIST_MIE__HOT mist_mie_complex mist_mie__div(mist_mie_complex a, mist_mie_complex b)
{
    double r, d;
    if (fabs(b.re) >= fabs(b.im)) {
        r = b.im / b.re; d = b.re + b.im * r;
        return mist_mie_cplx((a.re + a.im * r) / d, (a.im - a.re * r) / d);
    }
    r = b.re / b.im; d = b.re * r + b.im;
    return mist_mie_cplx((a.re * r + a.im) / d, (a.im * r - a.re) / d);
}

/* 1 / b, with an exact zero replaced by a tiny number (the recurrences
 * below divide by quantities that vanish only by coincidence; a huge but
 * finite result keeps the limit right, as [L76] and Thompson-Barnett do). */
MIST_MIE_FUNC MIST_MIE__HOT mist_mie_complex mist_mie__inv(mist_mie_complex b)
{
    if (b.re == 0 && b.im == 0) b.re = 1e-150;
    return mist_mie__div(mist_mie_cplx(1, 0), b);
}

/* The exponent field of v (2047: inf or NaN), read from its bits.  The
 * compiler may assume under -ffinite-math-only (MIST_ALLOW_FAST_MATH with
 * -ffast-math) that no double is NaN or infinite and delete v != v and the
 * comparisons a NaN fails; it cannot delete a test of the bits.  Every
 * check that guards a size, an index or a loop count is made this way:
 * the opt-out may give wrong numbers, never a write outside the memory
 * mist was given or an endless loop. */
MIST_MIE_FUNC int mist_mie__expo(double v)
{
    uint64_t b;
    memcpy(&b, &v, sizeof b);
    return (int)((b >> 52) & 2047u);
}

/* v is NaN (by its bits). */
MIST_MIE_FUNC int mist_mie__isnan(double v)
{
    uint64_t b;
    memcpy(&b, &v, sizeof b);
    return (b & ~((uint64_t)1 << 63)) > ((uint64_t)2047 << 52);
}

/* v as an integer, clamped to [lo, hi] (lo for NaN): the conversion of a
 * NaN or out-of-range double to an integer is undefined, so it is checked
 * on the bits first; finite comparisons hold under every flag. */
MIST_MIE_FUNC long mist_mie__clampl(double v, long lo, long hi)
{
    if (mist_mie__expo(v) == 2047) return mist_mie__isnan(v) || v < 0 ? lo : hi;
    if (v <= (double)lo) return lo;
    if (v >= (double)hi) return hi;
    return (long)v;
}

/* ======================================================================== */
/* Number of terms  [W80 p. 1508, W79 eq. R50]                              */
/*   N = x + 4 x^(1/3) + 1      x <= 8                                      */
/*   N = x + 4.05 x^(1/3) + 2   8 < x < 4200                                */
/*   N = x + 4 x^(1/3) + 2      4200 <= x                                   */
/* truncated to an integer, as MIEV0 does.                                  */
/* ======================================================================== */

/* Wiscombe's N(x).  Domain: x in (0, MIST_MIE_X_MAX]; else 0. */
#define MIST_MIE__N_MAX 100300      /* N(MIST_MIE_X_MAX) = 100188, a bound */
MIST_MIE_FUNC int mist_mie_terms(double x)
{
    double c;
    if (mist_mie__expo(x) == 2047 || !(x > 0 && x <= MIST_MIE_X_MAX)) return 0;
    c = pow(x, 1.0 / 3.0);
    c = x <= 8 ? x + 4 * c + 1 : x < 4200 ? x + 4.05 * c + 2 : x + 4 * c + 2;
    return (int)mist_mie__clampl(c, 1, MIST_MIE__N_MAX);
}

/* The terms summed: from Wiscombe's N on, until a term is below 1e-18 of
 * the largest, at most mist_mie__cap(x) = N + 4 x^(1/3) + 8.  N alone
 * leaves its tail in the results: past the edge n ~ x, |a_n| falls as
 * exp(-1.9 c^(3/2)) at n = x + c x^(1/3) (Debye), ~2e-7 at N's c = 4.05:
 * a 30- to 250-digit mpmath series puts Q_back cut at N 1.7e-7 off at
 * x = 339 and 2.3e-7 at x = 4200; and below x = 0.0148, where N = 1, N
 * drops b_1 and a_2: Q_back and the phase function
 * 0.2 x^2 off (4.5e-5), g 30-46% (its leading terms are a_1 b_1 and a_1
 * a_2).  c = 8 puts the tail at 1e-18; small x stops after a few terms
 * (a_n ~ x^(2n+1)). */
MIST_MIE_FUNC int mist_mie__cap(double x)
{
    int n = mist_mie_terms(x);
    return n > 0 ? n + (int)mist_mie__clampl(4 * pow(x, 1.0 / 3.0), 0, 200) + 8 : 0;
}
#define MIST_MIE__TAIL 1e-36          /* (term / largest term)^2 that stops */

/* Doubles of workspace mist_mie_sphere_make needs at size parameter x
 * (9 (C + 1); 72 (C + 1) bytes, C = N + 4 x^(1/3) + 8, the most terms it
 * may sum: see mist_mie__cap).  Domain as mist_mie_terms; 0 if invalid. */
MIST_MIE_FUNC size_t mist_mie_workspace_size(double x)
{
    int n = mist_mie__cap(x);
    return n > 0 ? 9 * ((size_t)n + 1) : 0;
}

/* ======================================================================== */
/* Logarithmic derivative D_n(z) = psi_n'(z) / psi_n(z)                     */
/* [L76]: D_N from the continued fraction of J_{N-1/2}(z) / J_{N+1/2}(z),   */
/*   D_N = -N/z + a_1 + 1/(a_2 + 1/(a_3 + ...)),                            */
/*   a_k = (-1)^(k+1) (2N + 2k - 1) / z,                                    */
/* evaluated by the modified Lentz method; then the downward recurrence     */
/* [BH83 eq. 4.89, W79 eq. R23]  D_{n-1} = n/z - 1/(D_n + n/z), stable for */
/* every z (MIEV0 recurs upward where that is safe; downward always is).    */
/* Starting from the exact D_N avoids the guessed starting index of BHMIE   */
/* (wrong for large |Im z| [D04]; and, measured, for weakly absorbing large */
/* spheres: BHMIE as printed, D started at 0 at max(N, |z|) + 15, water at  */
/* 550 nm, gives p(mu) 2.2e-3 off at x = 100 and 3.3x off at x = 1000, its  */
/* a_37 at x = 100 1.5% off, which a start at +50 corrects: an mpmath      */
/* series agrees with mist; bench/mist_bench.c prints BHMIE's error).      */
/* The fraction converges once k exceeds about |z|: the cost is O(|z| + N). */
/* ======================================================================== */

/* psi_{n-1}(z) / psi_n(z), the continued fraction above: D_n(z) is it less
 * n/z.  The sphere takes it at n = C + 1 (C the most terms): D_C(z) =
 * (C + 1)/z - 1/it and s_C(z) = psi_{C+1} / (z psi_C) = 1 / (z it). */
MIST_MIE_FUNC mist_mie_complex mist_mie__ratio(int n, mist_mie_complex z)
{
    mist_mie_complex zi = mist_mie__inv(z);
    mist_mie_complex f, c, d, ak, delta;
    double az = sqrt(mist_mie__abs2(z));
    long k, kmax = mist_mie__clampl(4 * az, 0, 4 * (long)MIST_MIE_MX_MAX) + 4L * n + 1000;
    double sgn = -1;
    f = c = mist_mie__scale(zi, 2.0 * n + 1);          /* a_1 */
    d = mist_mie_cplx(0, 0);
    for (k = 2; k < kmax; ++k, sgn = -sgn) {
        ak = mist_mie__scale(zi, sgn * (2.0 * n + 2.0 * (double)k - 1));
        d = mist_mie__inv(mist_mie__add(ak, d));
        c = mist_mie__add(ak, mist_mie__inv(c));
        if (c.re == 0 && c.im == 0) c.re = 1e-150;
        delta = mist_mie__mul(c, d);
        f = mist_mie__mul(f, delta);
        if (fabs(delta.re - 1) + fabs(delta.im) < 2 * DBL_EPSILON) break;
    }
    return f;
}


/* ======================================================================== */
/* The sphere: Mie coefficients a_n, b_n and efficiencies                   */
/*                                                                          */
/* [BH83 eq. 4.88]  a_n = (T_a psi_n - psi_{n-1}) / (T_a xi_n - xi_{n-1}),  */
/*                  T_a = D_n(mx)/m + n/x,  and b_n with T_b = m D_n(mx) +  */
/*                  n/x;  psi_n, xi_n = psi_n - i chi_n at the real x.      */
/* psi_n, chi_n: upward recurrence  f_n = (2n-1)/x f_{n-1} - f_{n-2}  while */
/* n <= x (both oscillate: stable).  For n > x psi_n decays and the upward  */
/* recurrence would lose it (all of it for small x), so there               */
/*   psi_n = psi_{n-1} / (D_n(x) + n/x)  with the real D_n(x) of the        */
/* section above (positive: psi has no zero for x < n), and the numerators  */
/* are written psi_n (D_n(mx)/m - D_n(x)), psi_n (m D_n(mx) - D_n(x)),      */
/* which cancel no n/x.  chi_n grows: upward is stable throughout.          */
/* For n > max(x, |m| x) even these cancel when m is near 1: m D_n(mx) and */
/* D_n(x) share their leading n/x, and the difference is O((m^2 - 1) x /   */
/* n): b_n lost 1/(|m^2 - 1| x^2) of its digits (g 3.1e-7 off at m =       */
/* 1.0001, x = 0.003; 0.6 at x = 1e-7).  There, with mu = m^2, w = x^2 and */
/* s_n(z) = psi_{n+1}(z) / (z psi_n(z)) = 1 / (2n+3 - z^2 s_{n+1}(z)) (no  */
/* zero of psi_n for |z| < n), D_n(z) = (n+1)/z - z s_n(z), so             */
/*   m D_n(mx) - D_n(x) = x U_n,  U_n = s_n(x) - mu s_n(mx)                 */
/*     = s_n(x) s_n(mx) (-(2n+3)(mu - 1) - mu w T_{n+1}),                   */
/*   T_n = s_n(mx) - s_n(x)                                                 */
/*       = w s_n(x) s_n(mx) ((mu - 1) s_{n+1}(mx) + T_{n+1}),               */
/* downward from the continued fraction's s_C (C the most terms; T's       */
/* starting error shrinks by w s s < 1 a step); mu - 1 = (m - 1)(m + 1).   */
/* Every term carries the factor mu - 1: no cancellation, a few eps a term */
/* whatever m - 1.  a_n's numerator is psi_n (x U_n - (mu - 1) D_n(x)) / mu,*/
/* and the denominators T xi_n - xi_{n-1} = num - i (T chi_n - chi_{n-1}). */
/* Below n2 = max(x, |m| x) + 1 the numerators T psi_n - psi_{n-1} are    */
/* O(m - 1) of psi_{n-1}: they lose 1/|m - 1| of their digits (g 3.5e-9   */
/* off at x = 1.5, m = 1 + 1e-7).  For |m - 1| < 1e-3 (MIST_MIE__NEAR1)   */
/* a_n and b_n are written there with p_n = psi_n(mx), q_n = psi_n(x) in  */
/* pole-free products (b_n's numerator and denominator times p_n, a_n's   */
/* times m p_n; f_n' = f_{n-1} - n/z f_n):                                */
/*   b_n = W_n / (W_n - i V_n),    W_n = m p_n' q_n - p_n q_n'            */
/*                                     = (m - 1) p_{n-1} q_n - E_n,       */
/*                                 V_n = m p_n' chi_n - p_n chi_n',       */
/*   a_n = W'_n / (W'_n - i V'_n), W'_n = p_n' q_n - m p_n q_n'           */
/*     = n (m^2 - 1)/(mx) p_n q_n - (m - 1) p_n q_{n-1} - E_n,            */
/*                                 V'_n = p_n' chi_n - m p_n chi_n',      */
/* where E_n = p_n q_{n-1} - p_{n-1} q_n (the Casoratian of the two       */
/* recurrences) changes by  E_n - E_{n+1} = (2n+1) (m - 1)/(mx) p_n q_n   */
/* and vanishes as n -> infinity: it is summed downward from              */
/*   E_n2 = p_n2 q_n2 ((m - 1)(D_n2(x) + n2/x) - x U_n2) / m.             */
/* Every term carries m - 1 as a computed factor (never as the difference */
/* of two O(1) numbers): nothing cancels, whatever m - 1.  And they are   */
/* products of psi, not ratios: a difference of the D_n, whose poles sit  */
/* at the zeros of psi_n, is not consistent there with an upward psi_n.   */
/* p_n = p_{n-1} / r_n with the r_n = D_n(mx) + n/(mx) of the downward    */
/* recurrence (the same numbers: consistent at p's zeros; upward, psi_n   */
/* of a complex argument loses e^(2 Im mx) of itself).  For real m the    */
/* terms of E's sum (~ q_k^2 as m -> 1) share a sign; in general they     */
/* add to at most ~(1 + |m - 1| x) |E_n|.  A few eps a term, a random walk*/
/* over the ~x terms: the coefficients, Q and g within ~eps sqrt(x) (1 +  */
/* |m - 1| x) relative.  At |m - 1| >= 1e-3 the direct form above loses   */
/* at most ~4e-16 / |m - 1| <= 4e-13 and is the faster (no products).     */
/* |m - 1| < 2^-64: m - 1 is scaled by 2^-es to [1/2, 1) (exact, also for */
/* a subnormal m - 1), the coefficients are computed divided by 2^es (the */
/* denominators take num 2^es; T starts at its first order w (mu - 1)     */
/* s^3, the difference of the s being noise there), and the efficiencies  */
/* and amplitudes (amp_scale_ = 2^es) are scaled back.                    */
/* The perfectly conducting sphere [W79 eqs. R/A.1-2]: T_a = n/x and       */
/* b_n = psi_n / xi_n (the m -> infinity limit of the same formulas).       */
/*                                                                          */
/* Efficiencies [W80 eqs. 1a-1c = W79 R6-R8; BH83 pp. 103, 120-122]:       */
/*   Q_ext = 2/x^2 sum (2n+1) Re(a_n + b_n)                                 */
/*   Q_sca = 2/x^2 sum (2n+1) (|a_n|^2 + |b_n|^2)                           */
/*   g Q_sca = 4/x^2 sum [ n(n+2)/(n+1) Re(a_n a*_{n+1} + b_n b*_{n+1})     */
/*                       + (2n+1)/(n(n+1)) Re(a_n b*_n) ]                   */
/*   Q_back = 1/x^2 |sum (2n+1) (-1)^n (a_n - b_n)|^2 = 4 |S1(-1)|^2 / x^2  */
/* (for m near 1 from a_n - b_n computed as one number, summed             */
/* compensated: see the near loop and ACCURACY).                            */
/* For mi = 0 (and the conductor) Q_ext is set to Q_sca, Q_abs = 0.         */
/*                                                                          */
/* The dipole limit [BH83 ch. 5], used for x max(1, |m|) < 1e-8 (x < 1e-8   */
/* for the conductor), where every neglected term is below 1e-16 relative  */
/* and the series would underflow:                                          */
/*   K = (m^2-1)/(m^2+2), a_1 = -i (2/3) x^3 K, b_1 = 0;                    */
/*   Q_abs = 4 x Im K, Q_sca = 8/3 x^4 |K|^2, Q_back = 4 x^4 |K|^2,         */
/*   g = x^2/15 Re((m^2 + 2)(m^2 + 3)/(2 m^2 + 3))  (from a_2, b_1);        */
/*   conductor: a_1 = -i (2/3) x^3, b_1 = i x^3/3, Q_sca = 10/3 x^4,       */
/*   Q_back = 9 x^4, g = -2/5.                                              */
/* The coefficients are then stored divided by x^3 and scaled by powers of */
/* 2 to [1/2, 1) (amp_scale_ = x^3 2^k; exact, also for a subnormal m - 1); */
/* the phase function, a ratio, is unaffected:                              */
/*   p = (|S1|^2 + |S2|^2) / (4 pi sum (2n+1) (|a_n|^2 + |b_n|^2)).          */
/*                                                                          */
/* Stored per term n (6 doubles): c_n a_n, c_n b_n (c_n = (2n+1)/(n(n+1)))  */
/* and the pi_n recurrence factors (2n+1)/n, (n+1)/n, so the per-angle sum  */
/* needs no division; after the last term S1(-1) (see mist_mie__edge).      */
/* ======================================================================== */

/* x, m inside the domain?  *pec: the perfectly conducting sphere. */
MIST_MIE_FUNC int mist_mie__valid(double x, mist_mie_complex m, int *pec)
{
    double am;
    *pec = 0;
    if (mist_mie__expo(x) == 2047 || !(x > 0 && x <= MIST_MIE_X_MAX)) return 0;
    if (mist_mie__isnan(m.re) || mist_mie__isnan(m.im)) return 0;
    if (!(m.re > 0) || !(m.im >= 0)) return 0;
    if (mist_mie__expo(m.re) == 2047 || mist_mie__expo(m.im) == 2047) { *pec = 1; return 1; }
    am = sqrt(m.re * m.re + m.im * m.im);
    if (!(am >= MIST_MIE_M_MIN && am <= MIST_MIE_M_MAX)) return 0;
    if (!(am * x <= MIST_MIE_MX_MAX)) return 0;
    return 1;
}

MIST_MIE_FUNC MIST_MIE__HOT void mist_mie__store(double *c, int n, mist_mie_complex a,
                                                 mist_mie_complex b)
{
    double fn = n, cn = (2 * fn + 1) / (fn * (fn + 1));
    c[0] = cn * a.re; c[1] = cn * a.im;
    c[2] = cn * b.re; c[3] = cn * b.im;
    c[4] = (2 * fn + 1) / fn;
    c[5] = (fn + 1) / fn;
}

/* s[k] + e[k] += t[k], k = 0, 1, compensated [Neumaier 1974]: e collects
 * the rounding of each s + t (exact by Fast2Sum), so a sum of N terms is
 * within eps |sum| + ~N eps^2 sum |t| of the terms' exact sum (plain
 * summation: ~N eps max |partial sum|). */
MIST_MIE_FUNC MIST_MIE__HOT void mist_mie__sum2(double *s, double *e, const double *t)
{
    int k;
    for (k = 0; k < 2; ++k) {
        double a = s[k], v = a + t[k];
        e[k] += fabs(a) >= fabs(t[k]) ? (a - v) + t[k] : (t[k] - v) + a;
        s[k] = v;
    }
}

/* S1, S2 at mu = +-1 (out as mist_mie__sums).  There pi_n = mu^(n-1) n(n+1)/2
 * and tau_n = mu pi_n are exact integers (n < 2e5): S1(1) = sum n(n+1)/2
 * (c_n a_n + c_n b_n), summed compensated, and S2(mu) = mu S1(mu) bit for
 * bit.  S1(-1) = sum (-1)^(n+1) (2n+1)/2 (a_n - b_n) cancels (near m = 1
 * to 1e-5 of its terms' moduli): the sphere sums it (where m is near 1
 * compensated, from a_n - b_n computed as one number) and stores it after
 * the last term (c[6 nt], c[6 nt + 1]; c[6 nt + 2] = -1/2 - nt marks it
 * as the sum of nt terms: with n_terms lowered, from the c_n a_n, c_n b_n). */
MIST_MIE_FUNC void mist_mie__edge(const double *c, int nt, double mu, int pair, double *out)
{
    int n;
    const double *sb = c + 6 * (size_t)nt;         /* the sphere's S1(-1) */
    double f[2] = {0, 0}, e[2] = {0, 0}, g[2] = {0, 0}, h[2] = {0, 0}, t[2], b[2];
    int mine = sb[2] == -0.5 - nt;                  /* its mark: summed to nt */
    if (mu == 1 || pair || !mine)
        for (n = 1; n <= nt; ++n, c += 6) {
            double fn = n, p = fn * (fn + 1) * 0.5;
            t[0] = (c[0] + c[2]) * p;
            t[1] = (c[1] + c[3]) * p;
            mist_mie__sum2(f, e, t);
            if (!mine) {        /* n_terms changed (a series cut short): from c */
                p = (n & 1) ? p : -p;
                t[0] = (c[0] - c[2]) * p;
                t[1] = (c[1] - c[3]) * p;
                mist_mie__sum2(g, h, t);
            }
        }
    f[0] += e[0]; f[1] += e[1];
    b[0] = mine ? sb[0] : g[0] + h[0];
    b[1] = mine ? sb[1] : g[1] + h[1];
    if (mu == 1) { out[0] = f[0]; out[1] = f[1]; }
    else         { out[0] = b[0]; out[1] = b[1]; }
    out[2] = mu * out[0]; out[3] = mu * out[1];
    if (pair) {
        if (mu == 1) { out[4] = b[0]; out[5] = b[1]; }
        else         { out[4] = f[0]; out[5] = f[1]; }
        out[6] = -mu * out[4]; out[7] = -mu * out[5];
    }
}

/* a_n, b_n for n > max(x, |m| x) from dmn = U_n (see the sphere): m D_n(mx)
 * - D_n(x) = x U_n; D_n(mx)/m - D_n(x) = (x U_n - (mu - 1) D_n(x)) / mu.
 * The denominators T xi_n - xi_{n-1} = num - i (T chi_n - chi_{n-1}), as
 * T psi_n - psi_{n-1} = num.  U_n, mu1 = mu - 1 and so num divided by sc
 * (a power of 2; 1 but for a tiny m - 1). */
MIST_MIE_FUNC MIST_MIE__HOT void mist_mie__ab_u(mist_mie_complex dmn, double x, double dn,
                                                double nx, mist_mie_complex mu1,
                                                mist_mie_complex m2, double psi, double chi,
                                                double chi1, double sc, mist_mie_complex *a,
                                                mist_mie_complex *b)
{
    mist_mie_complex dl = mist_mie__scale(dmn, x), qa, t, num;
    qa = mist_mie__div(mist_mie__sub(dl, mist_mie__scale(mu1, dn)), m2);
    num = mist_mie__scale(qa, psi);
    t = mist_mie_cplx(qa.re * sc + dn + nx, qa.im * sc);
    *a = mist_mie__div(num, mist_mie_cplx(num.re * sc + t.im * chi,
                                          num.im * sc - (t.re * chi - chi1)));
    num = mist_mie__scale(dl, psi);
    t = mist_mie_cplx(dl.re * sc + dn + nx, dl.im * sc);
    *b = mist_mie__div(num, mist_mie_cplx(num.re * sc + t.im * chi,
                                          num.im * sc - (t.re * chi - chi1)));
}

MIST_MIE_FUNC mist_mie_sphere mist_mie__zero(int status)
{
    mist_mie_sphere s;
    s.status = status; s.n_terms = 0; s.x = 0; s.m = mist_mie_cplx(0, 0);
    s.q_ext = s.q_sca = s.q_abs = s.q_back = s.g = 0;
    s.coef_ = MIST__NULL; s.amp_scale_ = 0; s.p_norm_ = 0; s.owned_ = MIST__NULL;
    return s;
}

/* The sphere of size parameter x and refractive index m, its coefficients
 * in work[0 .. n_work).  Domain: see DOMAIN AND BAD INPUT; bad x or m:
 * status MIST_MIE_EDOMAIN.  n_work >= mist_mie_workspace_size(x), else
 * (or work NULL) status MIST_MIE_ENOMEM.  No allocation.  Cost O(N + |m| x):
 * about 1 ms at x = 1e4, m = 1.33; 0.16 s at |m| x = MIST_MIE_MX_MAX. */
MIST_MIE_FUNC mist_mie_sphere mist_mie_sphere_make(double x, mist_mie_complex m,
                                                   double *work, size_t n_work)
{
    mist_mie_sphere s;
    int pec, nt, nw, n, n1, n2, near, es = 0, nlo = 1;
    double *coef, *dm, *dx;
    double psi0, psi1, chi0, chi1, sinx, cosx, ix, am, fx = 1, sc = 1;
    double qext = 0, qsca = 0, gsum = 0, tmax = 0;
    double bk[2] = {0, 0}, be[2] = {0, 0};  /* sum (-1)^(n+1) (2n+1)/2 (a_n - b_n), compensated */
    mist_mie_complex ap = mist_mie_cplx(0, 0), bp = ap;
    mist_mie_complex z, mu1 = mist_mie_cplx(0, 0), m2 = mu1, fz = mu1;
    mist_mie_complex d1 = mu1, k1 = mu1, k2 = mu1, zi = mu1;

    if (!mist_mie__valid(x, m, &pec)) return mist_mie__zero(MIST_MIE_EDOMAIN);
    nt = mist_mie__cap(x);                      /* the most terms */
    nw = mist_mie_terms(x);                     /* the fewest: Wiscombe's N */
    if (nt <= 0 || nw <= 0) return mist_mie__zero(MIST_MIE_EDOMAIN);
    /* the size checked here is the one the indices below use: 9 (nt + 1) */
    if (!work || n_work / 9 < (size_t)nt + 1)
        return mist_mie__zero(MIST_MIE_ENOMEM);
    s = mist_mie__zero(MIST_MIE_OK);
    s.x = x; s.m = m; s.coef_ = work; s.amp_scale_ = 1;
    coef = work;

    /* ---- the dipole limit ---- */
    am = pec ? 1 : sqrt(m.re * m.re + m.im * m.im);
    if (x * (am > 1 ? am : 1) < MIST_MIE__X_TINY) {
        mist_mie_complex a1, b1;
        double x2 = x * x, x4 = x2 * x2, s2, cm;
        int e = 0, e2 = 0;
        if (pec) {
            a1 = mist_mie_cplx(0, -2.0 / 3);
            b1 = mist_mie_cplx(0, 1.0 / 3);
            s.q_sca = s.q_ext = 10.0 / 3 * x4;
            s.q_back = 9 * x4;
            s.g = -0.4;
        } else {
            /* K = (m^2 - 1)/(m^2 + 2) with m^2 - 1 = (m - 1)(m + 1): no
             * cancellation for m near 1.  m - 1 is first scaled by 2^-e
             * to [1/2, 1) (exact; a subnormal m - 1 keeps its digits), so
             * K_s = 2^-e K is normal; the efficiencies carry 2^e, 2^2e. */
            mist_mie_complex d = mist_mie_cplx(m.re - 1, m.im), k, t;
            m2 = mist_mie__mul(m, m);
            cm = fabs(d.re) > fabs(d.im) ? fabs(d.re) : fabs(d.im);
            if (cm > 0) (void)frexp(cm, &e);
            d = mist_mie_cplx(ldexp(d.re, -e), ldexp(d.im, -e));
            k = mist_mie__div(mist_mie__mul(d, mist_mie_cplx(m.re + 1, m.im)),
                              mist_mie_cplx(m2.re + 2, m2.im));
            a1 = mist_mie_cplx(2.0 / 3 * k.im, -2.0 / 3 * k.re);   /* -i 2/3 K_s */
            b1 = mist_mie_cplx(0, 0);
            s.q_abs = m.im > 0 ? ldexp(4 * x * k.im, e) : 0;
            if (s.q_abs < 0) s.q_abs = 0;
            s.q_sca = ldexp(8.0 / 3 * x4 * mist_mie__abs2(k), 2 * e);
            s.q_ext = s.q_abs + s.q_sca;
            s.q_back = ldexp(4 * x4 * mist_mie__abs2(k), 2 * e);
            /* g = Re((a_2 + b_1) / a_1) to leading order [BH83 ch. 5:
             * a_1 = -i 2/3 x^3 (mu-1)/(mu+2), a_2 = -i x^5/15 (mu-1)/(2 mu
             * + 3), b_1 = -i x^5/45 (mu-1), mu = m^2]:
             *   g = x^2/15 Re((mu + 2)(mu + 3)/(2 mu + 3))
             * (0.16 x^2 at m = 1, the Rayleigh-Gans limit); the next
             * order is O(x^2 |m|^2) = 1e-16 of it here. */
            t = mist_mie__div(mist_mie__mul(mist_mie_cplx(m2.re + 2, m2.im),
                                            mist_mie_cplx(m2.re + 3, m2.im)),
                              mist_mie_cplx(2 * m2.re + 3, 2 * m2.im));
            s.g = x2 / 15 * t.re;
        }
        /* a1, b1 scaled by 2^-e2 to [1/2, 1) and the amplitudes scaled
         * back (amp_scale_ = x^3 2^(e + e2)); p is their ratio.  Each
         * component by ldexp, not by a factor 2^-e: that factor overflows
         * for a subnormal coefficient. */
        cm = fabs(a1.re);
        if (fabs(a1.im) > cm) cm = fabs(a1.im);
        if (fabs(b1.re) > cm) cm = fabs(b1.re);
        if (fabs(b1.im) > cm) cm = fabs(b1.im);
        if (cm > 0) (void)frexp(cm, &e2);
        a1 = mist_mie_cplx(ldexp(a1.re, -e2), ldexp(a1.im, -e2));
        b1 = mist_mie_cplx(ldexp(b1.re, -e2), ldexp(b1.im, -e2));
        mist_mie__store(coef, 1, a1, b1);
        coef[6] = coef[0] - coef[2]; coef[7] = coef[1] - coef[3];     /* S1(-1) */
        coef[8] = -1.5;
        s.n_terms = 1;
        s.amp_scale_ = ldexp(x2 * x, e + e2);
        s2 = 3 * (mist_mie__abs2(a1) + mist_mie__abs2(b1));
        s.p_norm_ = s2 > 0 ? 1 / (4 * MIST_MIE__PI * s2) : 0;
        return s;
    }

    /* ---- m = 1: no sphere at all; exactly 0 (the series would give
     * rounding noise of order eps) ---- */
    if (!pec && m.re == 1 && m.im == 0) {
        mist_mie__store(coef, 1, mist_mie_cplx(0, 0), mist_mie_cplx(0, 0));
        coef[6] = coef[7] = 0;                                       /* S1(-1) */
        coef[8] = -1.5;
        s.n_terms = 1;
        return s;
    }

    /* ---- the series ---- */
    dm = work + 6 * ((size_t)nt + 1);          /* D_n(mx), 2 doubles per n  */
    dx = work + 8 * ((size_t)nt + 1);          /* D_n(x) for n > x          */
    ix = 1 / x;
    z = mist_mie__scale(m, x);
    /* n > max(x, |m| x) from n2 on; below it, for m near 1, the cross
     * products (see the sphere) and no D_n(mx) */
    n2 = (int)mist_mie__clampl(floor(x * (am > 1 ? am : 1)), 0, nt) + 1;
    d1 = mist_mie_cplx(m.re - 1, m.im);
    near = !pec && n2 > 1 && mist_mie__abs2(d1) < MIST_MIE__NEAR1 * MIST_MIE__NEAR1;
    if (!pec) {
        /* |m - 1| < 2^-64: m - 1 scaled by 2^-es to [1/2, 1) (exact, also
         * for a subnormal m - 1) and the coefficients computed divided by
         * sc = 2^es (see the sphere) */
        double cm = fabs(d1.re) > fabs(d1.im) ? fabs(d1.re) : fabs(d1.im);
        if (cm > 0 && cm < 5.42101086242752217e-20) {         /* 2^-64 */
            (void)frexp(cm, &es);
            d1 = mist_mie_cplx(ldexp(d1.re, -es), ldexp(d1.im, -es));
            sc = ldexp(1.0, es);
        }
    }
    /* the fractions at nt + 1: psi_nt / psi_{nt+1} = 1 / (z s_nt(z)), and
     * D_nt(z) = (nt + 1)/z - z s_nt(z) (see the sphere) */
    if (!pec) {
        mist_mie_complex d;
        zi = mist_mie__inv(z);
        fz = mist_mie__ratio(nt + 1, z);
        d = mist_mie__sub(mist_mie__scale(zi, nt + 1.0), mist_mie__inv(fz));
        dm[2 * nt] = d.re; dm[2 * nt + 1] = d.im;
        if (!near) {
            for (n = nt; n > 1; --n) {
                mist_mie_complex nz = mist_mie__scale(zi, (double)n);
                d = mist_mie__sub(nz, mist_mie__inv(mist_mie__add(d, nz)));
                dm[2 * n - 2] = d.re; dm[2 * n - 1] = d.im;
            }
        } else {
            /* only r_n = D_n(mx) + n/z = psi_{n-1}(mx) / psi_n(mx), in the
             * coefficients' slots 0, 1 (psi_n(mx) = psi_{n-1}(mx) / r_n
             * below: the same r_n as the recurrence, so consistent at the
             * zeros of psi_n) */
            for (n = nt; n >= 1; --n) {
                mist_mie_complex nz = mist_mie__scale(zi, (double)n), r = mist_mie__add(d, nz);
                coef[6 * (size_t)(n - 1)] = r.re; coef[6 * (size_t)(n - 1) + 1] = r.im;
                d = mist_mie__sub(nz, mist_mie__inv(r));
            }
        }
    }
    /* first n with n > x, in [1, nt + 1] whatever x (an integer bound on
     * the indices of dx[] below, in every build) */
    n1 = (int)mist_mie__clampl(floor(x), 0, nt) + 1;
    if (n1 <= nt) {
        double d;
        fx = mist_mie__ratio(nt + 1, mist_mie_cplx(x, 0)).re;     /* > 0: nt > x */
        d = (nt + 1) * ix - 1 / fx;
        dx[nt] = d;
        for (n = nt; n > n1; --n) {
            double den = d + n * ix;
            if (den == 0) den = 1e-150;
            d = n * ix - 1 / den;
            dx[n - 1] = d;
        }
    }

    /* n > max(x, |m| x): U_n = (m D_n(mx) - D_n(x)) / x, see above */
    if (!pec && n2 <= nt) {
        mist_mie_complex zw = mist_mie__mul(z, z), smp, tp, u;
        double w = x * x, sxp = 1 / (x * fx);                     /* s_nt(x) */
        m2 = mist_mie__mul(m, m);
        mu1 = mist_mie__mul(d1, mist_mie_cplx(m.re + 1, m.im));      /* / sc */
        smp = mist_mie__inv(mist_mie__mul(z, fz));                  /* s_nt(mx) */
        /* the top term by the differences (it is past the tail; T's
         * starting error shrinks by x^2 s s' a step below); scaled, by
         * its first order x^2 (mu - 1) s^3 (the difference is noise) */
        if (es == 0) {
            tp = mist_mie_cplx(smp.re - sxp, smp.im);
            u = mist_mie__sub(mist_mie_cplx(sxp, 0), mist_mie__mul(m2, smp));
        } else {
            tp = mist_mie__scale(mist_mie__mul(mu1, mist_mie__mul(smp, smp)), w * sxp);
            u = mist_mie__sub(mist_mie__scale(mu1, -sxp), mist_mie__mul(m2, tp));
        }
        dm[2 * nt] = u.re; dm[2 * nt + 1] = u.im;
        for (n = nt - 1; n >= n2; --n) {
            double an = 2.0 * n + 3, sx = 1 / (an - w * sxp);
            mist_mie_complex zs = mist_mie__mul(zw, smp);
            mist_mie_complex sm = mist_mie__inv(mist_mie_cplx(an - zs.re, -zs.im));
            mist_mie_complex pr = mist_mie__scale(sm, sx);
            /* U_n = s s' (-(2n+3)(mu-1) - mu x^2 T_{n+1}) */
            u = mist_mie__mul(pr, mist_mie__sub(mist_mie__scale(mu1, -an),
                                                mist_mie__scale(mist_mie__mul(m2, tp), w)));
            /* T_n = x^2 s s' ((mu-1) s_{n+1}(mx) + T_{n+1}) */
            tp = mist_mie__add(mist_mie__mul(mu1, smp), tp);
            tp = mist_mie__scale(mist_mie__mul(pr, tp), w);
            dm[2 * n] = u.re; dm[2 * n + 1] = u.im;
            sxp = sx; smp = sm;
        }
    }

    sinx = sin(x); cosx = cos(x);
    if (near) {
        /* n < n2, m near 1 (see the sphere): psi_n(mx) = psi_{n-1}(mx) / r_n
         * upward (in the coefficients' slots 0, 1; psi_n(x) in slot 4), then
         * E_n downward (slots 2, 3) from E_n2 = psi_n2(mx) psi_n2(x)
         * ((m - 1)(D_n2(x) + n2/x) - x U_n2) / m (m - 1 divided by sc) */
        mist_mie_complex p1, pz0, pn = mist_mie_cplx(0, 0), e = pn;
        double ch = cosh(z.im), sh = sinh(z.im), sr = sin(z.re), cr = cos(z.re);
        double q0 = cosx, q1 = sinx, q = 0;
        int nh = n2 <= nt ? n2 : nt;
        k1 = mist_mie__div(d1, mist_mie__scale(m, x));                 /* (m-1)/(mx) */
        k2 = mist_mie__mul(k1, mist_mie_cplx(m.re + 1, m.im));       /* (m^2-1)/(mx) */
        p1 = pz0 = mist_mie_cplx(sr * ch, cr * sh);                   /* sin z */
        for (n = 1; n <= nh; ++n) {
            double *c = coef + 6 * (size_t)(n - 1);
            pn = mist_mie__div(p1, mist_mie_cplx(c[0], c[1]));
            q = n < n1 ? (2.0 * n - 1) * ix * q1 - q0 : q1 / (dx[n] + n * ix);
            c[0] = pn.re; c[1] = pn.im; c[4] = q;
            p1 = pn; q0 = q1; q1 = q;
        }
        if (n2 <= nt) {
            mist_mie_complex u = mist_mie_cplx(dm[2 * n2] * x, dm[2 * n2 + 1] * x);
            e = mist_mie__sub(mist_mie__scale(d1, dx[n2] + n2 * ix), u);
            e = mist_mie__div(mist_mie__scale(mist_mie__mul(pn, e), q), m);
        }
        for (n = n2 - 1; n >= 1; --n) {
            double *c = coef + 6 * (size_t)(n - 1);
            pn = mist_mie_cplx(c[0], c[1]);
            e = mist_mie__add(e, mist_mie__scale(mist_mie__mul(k1, pn), (2.0 * n + 1) * c[4]));
            c[2] = e.re; c[3] = e.im;
        }
        /* a_n, b_n (slots 0-3) from pn = psi_n(mx), en = E_n, q = psi_n(x),
         * q1 = psi_{n-1}(x), p1 = psi_{n-1}(mx) and chi_n upward as below */
        q1 = sinx; p1 = pz0;
        q0 = -sinx; q = cosx;                                /* chi_{-1}, chi_0 */
        for (n = 1; n < n2; ++n) {
            double *c = coef + 6 * (size_t)(n - 1), fn = n, chi, chd;
            mist_mie_complex en = mist_mie_cplx(c[2], c[3]), pd, wa, wb, va, vb, t;
            pn = mist_mie_cplx(c[0], c[1]);
            chi = (2 * fn - 1) * ix * q - q0;
            chd = q - fn * ix * chi;                             /* chi_n'(x) */
            pd = mist_mie__sub(p1, mist_mie__mul(mist_mie__scale(pn, fn), zi));   /* psi_n'(mx) */
            t = mist_mie__scale(pn, c[4]);                       /* psi_n(mx) psi_n(x) */
            wb = mist_mie__sub(mist_mie__scale(mist_mie__mul(d1, p1), c[4]), en);
            wa = mist_mie__sub(mist_mie__mul(k2, mist_mie__scale(t, fn)),
                               mist_mie__add(en, mist_mie__scale(mist_mie__mul(d1, pn), q1)));
            vb = mist_mie__sub(mist_mie__scale(mist_mie__mul(m, pd), chi),
                               mist_mie__scale(pn, chd));
            va = mist_mie__sub(mist_mie__scale(pd, chi),
                               mist_mie__scale(mist_mie__mul(m, pn), chd));
            {   /* a_n - b_n = i (W V' - W' V) / ((W' - i V')(W - i V)) with
                 * W V' - W' V = -(m - 1) W (p_n' chi_n + p_n chi_n') - V (W' - W),
                 * W' - W = n (m^2 - 1)/(mx) p_n q_n - (m - 1)(p_n q_{n-1} + p_{n-1} q_n):
                 * m - 1 a factor again, so a few eps of |a_n - b_n| (the
                 * difference of the rounded a_n, b_n: eps |a_n|), into slots 4, 5 */
                mist_mie_complex dw, sv, nm;
                dw = mist_mie__sub(mist_mie__mul(k2, mist_mie__scale(t, fn)),
                                   mist_mie__add(mist_mie__scale(mist_mie__mul(d1, pn), q1),
                                                 mist_mie__scale(mist_mie__mul(d1, p1), c[4])));
                sv = mist_mie__add(mist_mie__scale(pd, chi), mist_mie__scale(pn, chd));
                nm = mist_mie__add(mist_mie__scale(mist_mie__mul(mist_mie__mul(wb, d1), sv), sc),
                                   mist_mie__mul(vb, dw));                 /* -(W V' - W' V) */
                nm = mist_mie__div(mist_mie_cplx(nm.im, -nm.re),
                                   mist_mie_cplx(wa.re * sc + va.im, wa.im * sc - va.re));
                nm = mist_mie__div(nm, mist_mie_cplx(wb.re * sc + vb.im, wb.im * sc - vb.re));
                q1 = c[4]; c[4] = nm.re; c[5] = nm.im;
            }
            p1 = pn; q0 = q; q = chi;
            wa = mist_mie__div(wa, mist_mie_cplx(wa.re * sc + va.im, wa.im * sc - va.re));
            wb = mist_mie__div(wb, mist_mie_cplx(wb.re * sc + vb.im, wb.im * sc - vb.re));
            c[0] = wa.re; c[1] = wa.im; c[2] = wb.re; c[3] = wb.im;
        }
        nlo = n2;
    }
    if (es && n2 <= nt) {
        /* m - 1 scaled: the terms n >= n2 here (slots 0-3), psi_n(x) and
         * chi_n as below; the main loop then sums stored terms only */
        double p0 = cosx, p1 = sinx, c0 = -sinx, c1 = cosx;
        for (n = 1; n <= nt; ++n) {
            double fn = n, nx = fn * ix, psi, chi;
            if (n < n1) psi = (2 * fn - 1) * ix * p1 - p0;
            else        psi = p1 / (dx[n] + nx);
            chi = (2 * fn - 1) * ix * c1 - c0;
            if (n >= n2) {
                double *c = coef + 6 * (size_t)(n - 1);
                mist_mie_complex a, b;
                mist_mie__ab_u(mist_mie_cplx(dm[2 * n], dm[2 * n + 1]), x, dx[n], nx, mu1, m2,
                               psi, chi, c1, sc, &a, &b);
                c[0] = a.re; c[1] = a.im; c[2] = b.re; c[3] = b.im;
            }
            p0 = p1; p1 = psi; c0 = c1; c1 = chi;
        }
        nlo = nt + 1;
    }
    psi0 = cosx; psi1 = sinx;                   /* psi_{-1}, psi_0 */
    chi0 = -sinx; chi1 = cosx;                  /* chi_{-1}, chi_0 */
    for (n = 1; n <= nt; ++n) {
        double fn = n, psi, chi, nx = fn * ix;
        mist_mie_complex a, b, xin, xim, dmn = mist_mie_cplx(0, 0), dab = dmn;
        if (n < n1) psi = (2 * fn - 1) * ix * psi1 - psi0;
        else        psi = psi1 / (dx[n] + nx);
        chi = (2 * fn - 1) * ix * chi1 - chi0;
        xin = mist_mie_cplx(psi, -chi);
        xim = mist_mie_cplx(psi1, -chi1);
        if (n < nlo) {              /* stored above (cross products; m - 1 scaled) */
            const double *c = coef + 6 * (size_t)(n - 1);
            a = mist_mie_cplx(c[0], c[1]);
            b = mist_mie_cplx(c[2], c[3]);
            if (near && n < n2) dab = mist_mie_cplx(c[4], c[5]);       /* a_n - b_n */
        } else if (!pec && n >= n2) {
            mist_mie__ab_u(mist_mie_cplx(dm[2 * n], dm[2 * n + 1]), x, dx[n], nx, mu1, m2, psi,
                           chi, chi1, 1.0, &a, &b);
        } else {
        if (!pec) dmn = mist_mie_cplx(dm[2 * n], dm[2 * n + 1]);
        {   /* a_n */
            mist_mie_complex qa = pec ? mist_mie_cplx(0, 0) : mist_mie__div(dmn, m);
            mist_mie_complex ta = mist_mie_cplx(qa.re + nx, qa.im), num, den;
            if (n < n1)
                num = mist_mie_cplx(ta.re * psi - psi1, ta.im * psi);
            else
                num = mist_mie__scale(mist_mie_cplx(qa.re - dx[n], qa.im), psi);
            den = mist_mie__sub(mist_mie__mul(ta, xin), xim);
            a = (den.re == 0 && den.im == 0) ? mist_mie_cplx(0, 0) : mist_mie__div(num, den);
        }
        if (pec) {
            b = mist_mie__div(mist_mie_cplx(psi, 0), xin);
        } else {   /* b_n */
            mist_mie_complex qb = mist_mie__mul(m, dmn);
            mist_mie_complex tb = mist_mie_cplx(qb.re + nx, qb.im), num, den;
            if (n < n1)
                num = mist_mie_cplx(tb.re * psi - psi1, tb.im * psi);
            else
                num = mist_mie__scale(mist_mie_cplx(qb.re - dx[n], qb.im), psi);
            den = mist_mie__sub(mist_mie__mul(tb, xin), xim);
            b = (den.re == 0 && den.im == 0) ? mist_mie_cplx(0, 0) : mist_mie__div(num, den);
        }
        }
        mist_mie__store(coef + 6 * (size_t)(n - 1), n, a, b);
        {   /* the backscatter, S1(-1): a_n - b_n as computed above for m
             * near 1 (below n2), else their difference; compensated where
             * m is near 1 (the sum cancels to 1e-5 of its terms' moduli;
             * elsewhere the addition's latency would cost 8% of the sphere) */
            double f = (n & 1) ? fn + 0.5 : -(fn + 0.5), t[2];
            if (!(near && n < n2)) dab = mist_mie__sub(a, b);
            t[0] = f * dab.re; t[1] = f * dab.im;
            if (near) mist_mie__sum2(bk, be, t);
            else { bk[0] += t[0]; bk[1] += t[1]; }
        }

        qext += (2 * fn + 1) * (a.re + b.re);
        qsca += (2 * fn + 1) * (mist_mie__abs2(a) + mist_mie__abs2(b));
        gsum += (2 * fn + 1) / (fn * (fn + 1)) * (a.re * b.re + a.im * b.im);
        if (n > 1)
            gsum += (fn - 1) * (fn + 1) / fn
                  * (ap.re * a.re + ap.im * a.im + bp.re * b.re + bp.im * b.im);
        ap = a; bp = b;
        psi0 = psi1; psi1 = psi;
        chi0 = chi1; chi1 = chi;
        {   /* past Wiscombe's N: stop where the terms have died out */
            double t = (2 * fn + 1) * (2 * fn + 1) * (mist_mie__abs2(a) + mist_mie__abs2(b));
            if (t > tmax) tmax = t;
            if (n >= nw && t <= MIST_MIE__TAIL * tmax) break;
        }
    }
    s.n_terms = n < nt ? n : nt;
    s.q_sca = 2 * qsca * ix * ix;
    if (pec || m.im == 0) {
        s.q_ext = s.q_sca;
        s.q_abs = 0;
    } else {
        s.q_ext = 2 * qext * ix * ix;
        s.q_abs = s.q_ext > s.q_sca ? s.q_ext - s.q_sca : 0;
    }
    /* S1(-1) after the last term (read by the amplitudes at mu = -1);
     * Q_back = 4 |S1(-1)|^2 / x^2 */
    bk[0] += be[0]; bk[1] += be[1];
    coef[6 * (size_t)s.n_terms] = bk[0]; coef[6 * (size_t)s.n_terms + 1] = bk[1];
    coef[6 * (size_t)s.n_terms + 2] = -0.5 - s.n_terms;
    s.q_back = 4 * (bk[0] * bk[0] + bk[1] * bk[1]) * ix * ix;
    if (es) {       /* the coefficients / 2^es (rounded only where the result is subnormal) */
        s.q_sca = s.q_sca * sc * sc;
        s.q_ext = m.im == 0 ? s.q_sca : s.q_ext * sc;
        s.q_abs = s.q_ext > s.q_sca ? s.q_ext - s.q_sca : 0;
        s.q_back = s.q_back * sc * sc;
        s.amp_scale_ = sc;
    }
    s.g = qsca > 0 ? 2 * gsum / qsca : 0;
    s.p_norm_ = qsca > 0 ? 1 / (4 * MIST_MIE__PI * qsca) : 0;
    if (!(s.p_norm_ < (double)INFINITY)) s.p_norm_ = 0;  /* qsca subnormal (a guard:
                                                            tiny m - 1 is scaled) */
    return s;
}

/* The sphere with its own memory (one malloc of mist_mie_workspace_size(x)
 * doubles); malloc failure: status MIST_MIE_ENOMEM.  Free it with
 * mist_mie_sphere_free.  Domain as mist_mie_sphere_make. */
MIST_MIE_FUNC mist_mie_sphere mist_mie_sphere_new(double x, mist_mie_complex m)
{
    mist_mie_sphere s;
    size_t nw;
    double *w;
    int pec;
    if (!mist_mie__valid(x, m, &pec)) return mist_mie__zero(MIST_MIE_EDOMAIN);
    nw = mist_mie_workspace_size(x);
    w = (double *)malloc(nw * sizeof(double));
    if (!w) return mist_mie__zero(MIST_MIE_ENOMEM);
    s = mist_mie_sphere_make(x, m, w, nw);
    if (s.status != MIST_MIE_OK) { free(w); return s; }
    s.owned_ = w;
    return s;
}

/* Frees the memory of a sphere from mist_mie_sphere_new (any other sphere:
 * nothing) and zeroes it, status MIST_MIE_EDOMAIN (so a freed sphere gives
 * 0 everywhere and a second free is harmless).  s may be NULL. */
MIST_MIE_FUNC void mist_mie_sphere_free(mist_mie_sphere *s)
{
    if (!s) return;
    free(s->owned_);
    *s = mist_mie__zero(MIST_MIE_EDOMAIN);
}

/* ======================================================================== */
/* Amplitudes and the phase function  [BH83 pp. 94-95, 111-114; W80 1d-1e]  */
/*   S1 = sum c_n (a_n pi_n + b_n tau_n),  S2 = sum c_n (a_n tau_n + b_n pi_n)*/
/*   pi_{n+1} = (2n+1)/n mu pi_n - (n+1)/n pi_{n-1},  pi_0 = 0, pi_1 = 1,   */
/*   tau_n = n mu pi_n - (n+1) pi_{n-1}   (upward in n: stable).             */
/* With pi_n(-mu) = (-1)^(n-1) pi_n(mu), tau_n(-mu) = (-1)^n tau_n(mu), one */
/* pass gives mu and -mu: the tables use it when their angles pair up.      */
/* At mu = +-1, pi_n = mu^(n-1) n(n+1)/2 and tau_n = mu pi_n are integers  */
/* (exact for n < 2e5): S1 = sum of (c_n a_n + mu c_n b_n) pi_n, S2 = mu S1 */
/* bit for bit, no recurrence (its rounded factors (2n+1)/n, (n+1)/n       */
/* drift: S1(-1) 5.7e-6 off at x = 8000, m = 1.0001), summed compensated    */
/* (mist_mie__edge; S1(-1) from the sphere).                                */
/* ======================================================================== */

/* out[0..3]: S1(mu), S2(mu) (re, im) of the stored series; with pair, also
 * out[4..7]: S1(-mu), S2(-mu). */
MIST_MIE_FUNC void mist_mie__sums(const mist_mie_sphere *s, double mu, int pair,
                                  double *out)
{
    const double *c = s->coef_;
    int n, nt = s->n_terms;
    double pim = 0, pin = 1, fn = 1, sg = 1;
    double s1r = 0, s1i = 0, s2r = 0, s2i = 0;
    double t1r = 0, t1i = 0, t2r = 0, t2i = 0;
    if (mu == 1 || mu == -1) {
        mist_mie__edge(s->coef_, s->n_terms, mu, pair, out);
        return;
    }
    if (!pair) {
        for (n = 1; n <= nt; ++n, c += 6) {
            double tau = fn * mu * pin - (fn + 1) * pim, pnx;
            s1r += c[0] * pin + c[2] * tau;  s1i += c[1] * pin + c[3] * tau;
            s2r += c[0] * tau + c[2] * pin;  s2i += c[1] * tau + c[3] * pin;
            pnx = c[4] * mu * pin - c[5] * pim;
            pim = pin; pin = pnx; fn += 1;
        }
    } else {
        for (n = 1; n <= nt; ++n, c += 6) {
            double tau = fn * mu * pin - (fn + 1) * pim, pnx;
            double apr = c[0] * pin, api = c[1] * pin, btr = c[2] * tau, bti = c[3] * tau;
            double atr = c[0] * tau, ati = c[1] * tau, bpr = c[2] * pin, bpi = c[3] * pin;
            s1r += apr + btr;  s1i += api + bti;
            s2r += atr + bpr;  s2i += ati + bpi;
            t1r += sg * (apr - btr);  t1i += sg * (api - bti);
            t2r += sg * (bpr - atr);  t2i += sg * (bpi - ati);
            pnx = c[4] * mu * pin - c[5] * pim;
            pim = pin; pin = pnx; fn += 1; sg = -sg;
        }
    }
    out[0] = s1r; out[1] = s1i; out[2] = s2r; out[3] = s2i;
    if (pair) { out[4] = t1r; out[5] = t1i; out[6] = t2r; out[7] = t2i; }
}

/* mu clamped to [-1, 1]; NaN -> not usable (returns 0). */
MIST_MIE_FUNC int mist_mie__mu(double *mu)
{
    if (*mu != *mu) return 0;
    if (*mu < -1) *mu = -1;
    if (*mu > 1) *mu = 1;
    return 1;
}

/* Scattering amplitudes S1(mu), S2(mu) [BH83 convention, see the top].
 * Domain: mu in [-1, 1] (clamped; NaN gives 0).  A sphere with an error
 * status gives 0.  s1 or s2 may be NULL.  Cost O(N). */
MIST_MIE_FUNC void mist_mie_amplitudes(const mist_mie_sphere *s, double mu,
                                       mist_mie_complex *s1, mist_mie_complex *s2)
{
    double o[4] = {0, 0, 0, 0}, k = 0;
    if (s && s->status == MIST_MIE_OK && mist_mie__mu(&mu)) {
        mist_mie__sums(s, mu, 0, o);
        k = s->amp_scale_;
    }
    if (s1) *s1 = mist_mie_cplx(k * o[0], k * o[1]);
    if (s2) *s2 = mist_mie_cplx(k * o[2], k * o[3]);
}

/* The phase function p(mu) per steradian, normalised over the sphere:
 * (|S1|^2 + |S2|^2) / (2 pi x^2 Q_sca).  Domain: mu in [-1, 1] (clamped;
 * NaN gives 0).  0 for an error sphere and for one that does not scatter
 * (m = 1).  Cost O(N). */
MIST_MIE_FUNC double mist_mie_phase(const mist_mie_sphere *s, double mu)
{
    double o[4];
    if (!s || s->status != MIST_MIE_OK || !mist_mie__mu(&mu)) return 0;
    mist_mie__sums(s, mu, 0, o);
    return s->p_norm_ * (o[0] * o[0] + o[1] * o[1] + o[2] * o[2] + o[3] * o[3]);
}

/* Blocks of angles for the tables: the same sums as mist_mie__sums, n in
 * the outer loop and up to MIST_MIE__BLK cosines in the inner one, so the
 * compiler can run the angles side by side (MIEV0's "vectorizable loop").
 * ip[b], im[b] = |S1|^2 + |S2|^2 at mu[b] and -mu[b], series units;
 * mu[b] in [-1, 1]. */
#define MIST_MIE__BLK 16
MIST_MIE_FUNC void mist_mie__block(const mist_mie_sphere *s, const double *mu, int nb,
                                   double *ip, double *im)
{
    double pim[MIST_MIE__BLK], pin[MIST_MIE__BLK];
    double s1r[MIST_MIE__BLK], s1i[MIST_MIE__BLK], s2r[MIST_MIE__BLK], s2i[MIST_MIE__BLK];
    double t1r[MIST_MIE__BLK], t1i[MIST_MIE__BLK], t2r[MIST_MIE__BLK], t2i[MIST_MIE__BLK];
    const double *c = s->coef_;
    double fn = 1, sg = 1;
    int n, b, nt = s->n_terms;
    for (b = 0; b < MIST_MIE__BLK; ++b) {
        pim[b] = 0; pin[b] = 1;
        s1r[b] = s1i[b] = s2r[b] = s2i[b] = t1r[b] = t1i[b] = t2r[b] = t2i[b] = 0;
    }
    for (n = 1; n <= nt; ++n, c += 6) {
        double ar = c[0], ai = c[1], br = c[2], bi = c[3], r1 = c[4], r2 = c[5];
        double fn1 = fn + 1;
        for (b = 0; b < MIST_MIE__BLK; ++b) {
            double u = mu[b], p = pin[b], pm = pim[b];
            double tau = fn * u * p - fn1 * pm;
            double apr = ar * p, api = ai * p, btr = br * tau, bti = bi * tau;
            double atr = ar * tau, ati = ai * tau, bpr = br * p, bpi = bi * p;
            s1r[b] += apr + btr;  s1i[b] += api + bti;
            s2r[b] += atr + bpr;  s2i[b] += ati + bpi;
            t1r[b] += sg * (apr - btr);  t1i[b] += sg * (api - bti);
            t2r[b] += sg * (bpr - atr);  t2i[b] += sg * (bpi - ati);
            pim[b] = p;
            pin[b] = r1 * u * p - r2 * pm;
        }
        fn = fn1; sg = -sg;
    }
    for (b = 0; b < nb; ++b) {
        ip[b] = s1r[b] * s1r[b] + s1i[b] * s1i[b] + s2r[b] * s2r[b] + s2i[b] * s2i[b];
        im[b] = t1r[b] * t1r[b] + t1i[b] * t1i[b] + t2r[b] * t2r[b] + t2i[b] * t2i[b];
    }
}

/* out[j] (=, or += if add) scale * (|S1|^2 + |S2|^2) of the stored series
 * at mu[j], j < n.  Angles with mu[n-1-j] = -mu[j] share one evaluation;
 * out-of-range cosines are clamped, NaN gives 0.  mu = +-1 (after the
 * clamp) go through mist_mie__sums' exact pi_n, the others in blocks. */
MIST_MIE_FUNC void mist_mie__table(const mist_mie_sphere *s, const double *mu, size_t n,
                                   double scale, int add, double *out)
{
    double bu[MIST_MIE__BLK], ip[MIST_MIE__BLK], im[MIST_MIE__BLK];
    size_t bj[MIST_MIE__BLK], bk[MIST_MIE__BLK], j;
    int nb = 0, b;
    for (j = 0; j <= n; ++j) {
        if (j < n) {
            size_t k = n - 1 - j;
            double u = mu[j];
            int paired = j != k && mu[k] == -mu[j] && u == u && u >= -1 && u <= 1;
            if (paired && j > k) continue;         /* done with its mirror */
            if (!mist_mie__mu(&u)) {               /* NaN */
                if (!add) out[j] = 0;
                continue;
            }
            if (u == 1 || u == -1) {
                double o[8] = {0, 0, 0, 0, 0, 0, 0, 0}, v;
                mist_mie__sums(s, u, paired, o);
                v = scale * (o[0] * o[0] + o[1] * o[1] + o[2] * o[2] + o[3] * o[3]);
                if (add) out[j] += v; else out[j] = v;
                if (paired) {
                    v = scale * (o[4] * o[4] + o[5] * o[5] + o[6] * o[6] + o[7] * o[7]);
                    if (add) out[k] += v; else out[k] = v;
                }
                continue;
            }
            bu[nb] = u; bj[nb] = j; bk[nb] = paired ? k : n;
            ++nb;
        }
        if (nb == MIST_MIE__BLK || (j == n && nb > 0)) {
            for (b = nb; b < MIST_MIE__BLK; ++b) bu[b] = 0;
            mist_mie__block(s, bu, nb, ip, im);
            for (b = 0; b < nb; ++b) {
                if (add) out[bj[b]] += scale * ip[b]; else out[bj[b]] = scale * ip[b];
                if (bk[b] < n) {
                    if (add) out[bk[b]] += scale * im[b]; else out[bk[b]] = scale * im[b];
                }
            }
            nb = 0;
        }
    }
}

/* p[j] = mist_mie_phase(s, mu[j]) for j < n; angles that come in pairs
 * mu[n-1-j] = -mu[j] (as from mist_mie_theta_grid) cost one evaluation.
 * Domain as mist_mie_phase; mu and p may be NULL only if n = 0. */
MIST_MIE_FUNC void mist_mie_phase_table(const mist_mie_sphere *s, const double *mu,
                                        size_t n, double *p)
{
    size_t j;
    if (!s || s->status != MIST_MIE_OK) {
        for (j = 0; j < n; ++j) p[j] = 0;
        return;
    }
    mist_mie__table(s, mu, n, s->p_norm_, 0, p);
}

/* mu[j] = cos(pi j / (n - 1)), j < n: uniform in theta from 0 to 180
 * degrees, exactly antisymmetric (mu[n-1-j] = -mu[j], mu = 0 exactly in the
 * middle).  n = 1 gives mu[0] = 1; n = 0 writes nothing. */
MIST_MIE_FUNC void mist_mie_theta_grid(size_t n, double *mu)
{
    size_t j;
    if (n == 0) return;
    if (n == 1) { mu[0] = 1; return; }
    for (j = 0; 2 * j < n; ++j) {
        double u = 2 * j + 1 == n ? 0 : cos(MIST_MIE__PI * (double)j / (double)(n - 1));
        mu[n - 1 - j] = -u;
        mu[j] = u;                              /* the middle: +0 */
    }
    mu[0] = 1; mu[n - 1] = -1;
}

/* ======================================================================== */
/* Water  [HQ73, Table I, 25 C]                                             */
/* n + i k of pure liquid water from 350 to 800 nm every 25 nm, as printed  */
/* (n to 3 decimals, k to 3 digits); linear interpolation in wavelength     */
/* between the entries.  Outside [350, 800] nm the nearest end value is     */
/* returned with status MIST_MIE_CLAMPED.  The index is relative to vacuum: */
/* divide by the medium's (air 1.0003) for a relative m, as                 */
/* mist_mie_average does.                                                   */
/* ======================================================================== */

/* Water's refractive index at vacuum wavelength lambda_nm (nanometres).
 * Domain: [350, 800] nm (covers the visible 380-780); outside: clamped to
 * the end value, *status = MIST_MIE_CLAMPED; NaN: returns (0, 0) (which
 * every Mie function rejects) and *status = MIST_MIE_EDOMAIN; else
 * *status = MIST_MIE_OK.  status may be NULL. */
MIST_MIE_FUNC mist_mie_complex mist_mie_water(double lambda_nm, int *status)
{
    static const double n_hq[19] = {
        1.343, 1.341, 1.339, 1.338, 1.337, 1.336, 1.335, 1.334, 1.333, 1.333,
        1.332, 1.332, 1.331, 1.331, 1.331, 1.330, 1.330, 1.330, 1.329 };
    static const double k_hq[19] = {
        6.50e-9, 3.50e-9, 1.86e-9, 1.30e-9, 1.02e-9, 9.35e-10, 1.00e-9, 1.32e-9,
        1.96e-9, 3.60e-9, 1.09e-8, 1.39e-8, 1.64e-8, 2.23e-8, 3.35e-8, 9.15e-8,
        1.56e-7, 1.48e-7, 1.25e-7 };
    int st = MIST_MIE_OK, i;
    double t, f;
    if (mist_mie__isnan(lambda_nm)) {
        if (status) *status = MIST_MIE_EDOMAIN;
        return mist_mie_cplx(0, 0);
    }
    if (lambda_nm < 350) { lambda_nm = 350; st = MIST_MIE_CLAMPED; }
    if (lambda_nm > 800) { lambda_nm = 800; st = MIST_MIE_CLAMPED; }
    if (status) *status = st;
    t = (lambda_nm - 350) / 25;                /* in [0, 18] */
    i = (int)mist_mie__clampl(t, 0, 17);       /* the table's index, in every build */
    f = t - i;
    return mist_mie_cplx(n_hq[i] + f * (n_hq[i + 1] - n_hq[i]),
                         k_hq[i] + f * (k_hq[i + 1] - k_hq[i]));
}

/* ======================================================================== */
/* Size distributions                                                       */
/* Number densities n(r) per unit radius (unnormalised; the average        */
/* normalises numerically over the range it integrates):                    */
/*  gamma [HT74 eq. 2.56]: n = r^((1-3v)/v) exp(-r / (r_eff v)), effective */
/*    radius r_eff = <r^3>/<r^2> and effective variance v, 0 < v < 1/2.     */
/*  modified gamma [D69]: n = r^alpha exp(-(alpha/gamma) (r/r_c)^gamma),    */
/*    mode radius r_c; alpha, gamma > 0.  Deirmendjian's cloud C.1 is       */
/*    alpha = 6, gamma = 1, r_c = 4 um.                                     */
/*  lognormal: n = 1/r exp(-(ln r - ln r_g)^2 / (2 ln^2 sigma_g)), median   */
/*    radius r_g, geometric standard deviation sigma_g > 1.                 */
/*  table: given radii r_i > 0 and weights w_i >= 0 (n(r_i) times the       */
/*    caller's quadrature weight).                                          */
/* The constructors only store their parameters; mist_mie_average checks    */
/* them (outside these domains: status MIST_MIE_EDOMAIN, every number 0).   */
/* ======================================================================== */

MIST_MIE_FUNC mist_mie_dist mist_mie__dist(int kind, double p1, double p2, double p3)
{
    mist_mie_dist d;
    d.kind = kind; d.p1 = p1; d.p2 = p2; d.p3 = p3;
    d.r_min = d.r_max = 0; d.n_radii = 0;
    d.r = d.w = MIST__NULL; d.n = 0;
    return d;
}

/* All particles of radius r > 0. */
MIST_MIE_FUNC mist_mie_dist mist_mie_dist_mono(double r)
{ return mist_mie__dist(MIST_MIE_DIST_MONO, r, 0, 0); }

/* Gamma [HT74]: effective radius r_eff > 0, effective variance v_eff in
 * (0, 1/2).  Below v_eff = 1e-32 the law (relative width ~16 sqrt(v_eff))
 * is narrower than double resolves r (its integration range would round to
 * nothing): it is the monodisperse law at r_eff (at 1e-33 the gamma
 * average equals the monodisperse one to 2 ulps, measured). */
MIST_MIE_FUNC mist_mie_dist mist_mie_dist_gamma(double r_eff, double v_eff)
{
    if (v_eff > 0 && v_eff < 1e-32) return mist_mie__dist(MIST_MIE_DIST_MONO, r_eff, 0, 0);
    return mist_mie__dist(MIST_MIE_DIST_GAMMA, r_eff, v_eff, 0);
}

/* Modified gamma [D69]: alpha > 0, gamma > 0, mode radius r_c > 0. */
MIST_MIE_FUNC mist_mie_dist mist_mie_dist_modgamma(double alpha, double gamma, double r_c)
{ return mist_mie__dist(MIST_MIE_DIST_MODGAMMA, alpha, gamma, r_c); }

/* Lognormal: median radius r_g > 0, geometric standard deviation
 * sigma_g > 1. */
MIST_MIE_FUNC mist_mie_dist mist_mie_dist_lognormal(double r_g, double sigma_g)
{ return mist_mie__dist(MIST_MIE_DIST_LOGNORMAL, r_g, sigma_g, 0); }

/* Explicit nodes: radii r[i] > 0 and weights w[i] >= 0 (not all 0), i < n.
 * The arrays must outlive the average call. */
MIST_MIE_FUNC mist_mie_dist mist_mie_dist_table(const double *r, const double *w, size_t n)
{
    mist_mie_dist d = mist_mie__dist(MIST_MIE_DIST_TABLE, 0, 0, 0);
    d.r = r; d.w = w; d.n = n;
    return d;
}

MIST_MIE_FUNC int mist_mie__finite(double v) { return v - v == 0; }

/* a length inside mist_mie_average's domain (also false for NaN) */
MIST_MIE_FUNC int mist_mie__len(double v)
{ return v >= MIST_MIE_LEN_MIN && v <= MIST_MIE_LEN_MAX; }

/* Checks the parameters and sets the integration variable t (r, or ln r
 * for the lognormal: *logv) and its range [*t0, *t1]. */
MIST_MIE_FUNC int mist_mie__dist_range(const mist_mie_dist *d, double *t0, double *t1,
                                       int *logv)
{
    double a, b, lo, hi;
    int autor = d->r_min == 0 && d->r_max == 0;
    *logv = 0;
    if (!autor && !((d->r_min == 0 || mist_mie__len(d->r_min)) && mist_mie__len(d->r_max)
                    && d->r_max > d->r_min))
        return 0;
    switch (d->kind) {
    case MIST_MIE_DIST_GAMMA:       /* alpha = (1-3v)/v, scale beta = r_eff v */
        if (!(mist_mie__len(d->p1) && d->p2 > 0 && d->p2 < 0.5)) return 0;
        a = (1 - 3 * d->p2) / d->p2;  b = d->p1 * d->p2;
        lo = a + 1 - 8 * sqrt(a + 1) - 16;         /* number: Gamma(alpha+1) */
        hi = a + 3 + 8 * sqrt(a + 3) + 16;         /* area:   Gamma(alpha+3) */
        *t0 = lo > 0 ? lo * b : 0;  *t1 = hi * b;
        break;
    case MIST_MIE_DIST_MODGAMMA: {  /* t = B r^gamma, B = alpha/(gamma r_c^gamma) */
        double g = d->p2, bb, s0, s1;
        if (!(d->p1 > 0 && mist_mie__finite(d->p1) && g > 0 && mist_mie__finite(g)
              && mist_mie__len(d->p3))) return 0;
        if (!autor) break;                          /* (may overflow: not needed) */
        bb = d->p1 / g;                             /* B r_c^gamma */
        s0 = (d->p1 + 1) / g;  s1 = (d->p1 + 3) / g;
        lo = s0 - 8 * sqrt(s0) - 16;  hi = s1 + 8 * sqrt(s1) + 16;
        *t0 = lo > 0 ? d->p3 * pow(lo / bb, 1 / g) : 0;
        *t1 = d->p3 * pow(hi / bb, 1 / g);
        if (!mist_mie__finite(*t1)) return 0;
        break;
    }
    case MIST_MIE_DIST_LOGNORMAL: { /* in ln r: Gaussian (mu, s) */
        double mu = log(d->p1), s;
        if (!(mist_mie__len(d->p1) && d->p2 > 1 && mist_mie__finite(d->p2))) return 0;
        s = log(d->p2);
        *logv = 1;
        *t0 = mu - 7 * s;  *t1 = mu + 2 * s * s + 7 * s;
        if (!autor) {
            if (!(d->r_min > 0)) return 0;
            *t0 = log(d->r_min); *t1 = log(d->r_max);
        }
        return mist_mie__finite(*t0) && mist_mie__finite(*t1) && *t1 > *t0;
    }
    default:
        return 0;
    }
    if (!autor) { *t0 = d->r_min; *t1 = d->r_max; }
    return mist_mie__finite(*t0) && mist_mie__finite(*t1) && *t1 > *t0;
}

/* The log of the density in the integration variable at t (r = t, or
 * e^t), up to a constant (the nodes' weights are normalised by their
 * largest); -inf where it underflows every double (or at r = 0).  Written
 * so that no term overflows alone (the printed forms give inf - inf for
 * narrow laws and far tails):
 *  gamma, alpha > 0: alpha (log1p(d) - d), d = r / r_mode - 1 (r_mode =
 *    alpha beta), which is alpha log(r/r_mode) - (r - r_mode)/beta;
 *  modified gamma: -(alpha u) L (expm1(u) - u) / u^2, L = log(r/r_c),
 *    u = gamma L, which is alpha L - (alpha/gamma)(q^gamma - 1) without
 *    alpha/gamma, and without a subnormal intermediate (L times
 *    (expm1(u) - u)/u was one for gamma = 1e-300: flushed to 0 under
 *    -ffast-math's FTZ, 1.4e-9 off in the area);
 *  lognormal: -y^2/2.
 * The differences log1p(d) - d and expm1(u) - u cancel for small d, u
 * (a narrow gamma law; a modified gamma with gamma -> 0, where the law
 * tends to a lognormal): their Taylor series there. */
MIST_MIE_FUNC double mist_mie__log1pm(double d)      /* log1p(d) - d */
{
    double s = 0;
    int k;
    if (!(fabs(d) < 0.25)) return log1p(d) - d;
    for (k = 28; k >= 2; --k) s = (k % 2 ? 1.0 : -1.0) / k + d * s;   /* 0.25^27 < 1e-16 */
    return d * d * s;
}

MIST_MIE_FUNC double mist_mie__expm1q(double u)      /* (expm1(u) - u) / u^2 */
{
    double s = 0, f = 1;
    int k;
    if (!(fabs(u) < 0.5)) return (expm1(u) - u) / u / u;
    for (k = 2; k <= 18; ++k) f *= k;                 /* 18! */
    for (k = 16; k >= 0; --k) { s = 1 / f + u * s; f /= k + 2; }   /* u^k/(k+2)! */
    return s;
}

MIST_MIE_FUNC double mist_mie__dist_logdensity(const mist_mie_dist *d, double t)
{
    double r = t, e;
    switch (d->kind) {
    case MIST_MIE_DIST_GAMMA: {
        double a = (1 - 3 * d->p2) / d->p2, b = d->p1 * d->p2, dd;
        if (!(r > 0)) return -(double)INFINITY;
        if (a > 0) {
            dd = r / (a * b) - 1;
            e = a * mist_mie__log1pm(dd);
        } else {                                   /* -1 < alpha <= 0: decreasing */
            e = a * log(r / b) - r / b;
        }
        break;
    }
    case MIST_MIE_DIST_MODGAMMA: {
        double L, u;
        if (!(r > 0)) return -(double)INFINITY;
        L = log(r / d->p3);  u = d->p2 * L;
        if (u > 700) return -(double)INFINITY;    /* exp(-(alpha/gamma) e^u) */
        e = -(d->p1 * u) * (L * mist_mie__expm1q(u));
        break;
    }
    case MIST_MIE_DIST_LOGNORMAL: {
        double y = (t - log(d->p1)) / log(d->p2);
        e = -0.5 * y * y;
        break;
    }
    default:
        return -(double)INFINITY;
    }
    return e == e ? e : -(double)INFINITY;
}

/* ======================================================================== */
/* Averages over sizes and wavelengths  [W79 "Integrating over sizes",      */
/* HT74 sec. 2]                                                             */
/* Cross sections and intensities add, not efficiencies or normalised      */
/* phase functions:                                                         */
/*   <C>   = sum_l w_l sum_i w_i C(r_i, l) / (sum_l w_l sum_i w_i)          */
/*   p(mu) = sum w_l w_i (|S1|^2 + |S2|^2) / (2 k_l^2)  /  sum w_l w_i C_sca */
/*   g     = sum w_l w_i g C_sca / sum w_l w_i C_sca                        */
/* with C = Q pi r^2, k_l = 2 pi n_medium / lambda_l, x = k_l r,            */
/* m = m_l / n_medium.  p integrates to 1 over the sphere for any nodes.    */
/* The size integral is composite 8-point Gauss-Legendre over [r_min,       */
/* r_max] in r (gamma laws) or ln r (lognormal).  Automatic range: the      */
/* number and the area (r^2) weighted laws both lose < 1e-9 of their mass  */
/* (gamma: mean +- 8 sd + 16 of the Gamma(alpha+1) / Gamma(alpha+3) law of  */
/* t; lognormal: ln r_g - 7 s .. ln r_g + 2 s^2 + 7 s).                     */
/* Automatic nodes: spacing <= 0.05 in size parameter at the shortest       */
/* wavelength (at r_max), at least 64, at most 65536.  Coarser sampling     */
/* aliases the ripple of Q(x) (water, gamma r_eff = 2 um, v = 0.1, 550 nm:  */
/* C_sca off by 3e-3 at spacing 0.25).  With some absorption (Im m = 1e-3)  */
/* the automatic nodes give ~5e-6 in C_sca, the other cross sections a few */
/* times that (C_ext 2.5e-5, C_abs 4e-4 of itself), and 1e-3 in C_back and */
/* the phase function near 180 degrees (an independent check: gamma r_eff  */
/* 2, v 0.3 and modified gamma (6, 1, 4) at 550 nm; lognormals and narrow   */
/* gammas to 1e-8 .. 2e-5).  Nearly absorption-free droplets (water        */
/* in the visible, Im m ~ 1e-9) have resonances far narrower than any node  */
/* spacing, and a node that lands on one overweights it: expect noise of    */
/* ~1e-3 relative in such averages whatever n_radii (the water example:     */
/* +-4e-4 as n_radii goes from 2000 to 2600), ~1e-2 in C_back and near 180  */
/* degrees.  A smooth phase table may need far fewer nodes: set n_radii.    */
/* Wide laws: a gamma law's number is exact (incomplete gamma) for v_eff > */
/* 1/5, where n(r) is not smooth at 0.  A modified gamma law with small     */
/* gamma spans decades in r, which nodes uniform in r under-resolve: area   */
/* 2.9e-2 off at (1, 0.2, 0.01); 2.1e-6 at Deirmendjian's haze M (1, 0.5,   */
/* 0.05 um; measured by that check).  Use a lognormal or a table there.     */
/* Cost: n_radii x n_wl spheres, each with an O(N n_mu) angle sum (paired   */
/* angles count once; ~3 ns per term and angle pair at -O2, ~0.7 ns with    */
/* -O3 -march=native).  Example, gamma r_eff = 5 um, v = 0.1, 3 wavelengths,*/
/* 1800 angles: 7168 automatic nodes 10 s (2.6 s native); n_radii = 800:   */
/* 1 s, C_ext within 3e-4 and g within 2e-4 of the automatic result.        */
/* ======================================================================== */

/* The size parameter of radius r at vacuum wavelength lambda, x = 2 pi
 * n_medium r / lambda: one expression for the sizing and the spheres. */
MIST_MIE_FUNC double mist_mie__avg_x(double n_medium, double lambda, double r)
{
    return 2 * MIST_MIE__PI * n_medium / lambda * r;
}

MIST_MIE_FUNC mist_mie_avg mist_mie__avg_zero(int status)
{
    mist_mie_avg a;
    a.status = status;
    a.c_ext = a.c_sca = a.c_abs = a.c_back = a.g = a.albedo = 0;
    a.area = a.volume = a.r_min = a.r_max = 0;
    a.n_radii = 0;
    return a;
}

/* ln gamma(a, x) = ln int_0^x t^(a-1) e^-t dt for 0 < a <= 3, x >= 0 (the
 * lower incomplete gamma: its series up to x = a + 1, above it Gamma(a)
 * less the upper one's continued fraction, Lentz).  -inf at x = 0. */
MIST_MIE_FUNC double mist_mie__lngamlow(double a, double x)
{
    if (!(x > 0)) return -(double)INFINITY;
    if (x <= a + 1) {
        double s = 1, t = 1, n;
        for (n = 1; n < 500; ++n) { t *= x / (a + n); s += t; if (t < s * 1e-17) break; }
        return a * log(x) - x + log(s) - log(a);
    } else {   /* Gamma(a, x) = e^-x x^a / (x + 1 - a - 1 (1 - a) / (x + 3 - a - ...)) */
        double b = x + 1 - a, c = 1e300, d = 1 / b, f = d, an, del, lu;
        int i;
        for (i = 1; i < 500 && x < (double)INFINITY; ++i) {
            an = -i * (i - a);
            b += 2;
            d = an * d + b;  if (fabs(d) < 1e-300) d = 1e-300;
            c = b + an / c;  if (fabs(c) < 1e-300) c = 1e-300;
            d = 1 / d;  del = d * c;  f *= del;
            if (fabs(del - 1) < 1e-16) break;
        }
        lu = x < (double)INFINITY ? a * log(x) - x + log(f) : -(double)INFINITY;
        return lgamma(a) + log1p(-exp(lu - lgamma(a)));
    }
}

/* Node i of the size quadrature: its radius *r and the log of its weight
 * (density times Gauss weight; the panel width is common to all and left
 * out) for the laws; mono and table nodes are read directly. */
MIST_MIE_FUNC double mist_mie__node(const mist_mie_dist *d, int logv, double t0, double h,
                                    size_t i, double *r)
{
    static const double gx[4] = {       /* 8-point Gauss-Legendre, x >= 0 */
        0.1834346424956498049394761, 0.5255324099163289858177390,
        0.7966664774136267395915539, 0.9602898564975362316835609 };
    static const double gw[4] = {
        0.3626837833783619829651504, 0.3137066458778872873379622,
        0.2223810344533744705443560, 0.1012285362903762591525314 };
    size_t panel = i / 8, j = i % 8;
    double c = t0 + h * ((double)panel + 0.5), xi, t;
    xi = gx[j < 4 ? 3 - j : j - 4] * (j < 4 ? -1 : 1);
    t = c + 0.5 * h * xi;
    *r = logv ? exp(t) : t;
    return log(gw[j < 4 ? 3 - j : j - 4]) + mist_mie__dist_logdensity(d, t);
}

/* The size- and wavelength-averaged optics of a droplet population.
 *   dist     the size distribution (see mist_mie_dist_*; its r_min, r_max,
 *            n_radii may be set, see there); radii in any length unit;
 *   wl[n_wl] wavelengths in the same unit, weights and particle indices;
 *   n_medium the medium's real refractive index (> 0; 1 for vacuum);
 *   mu[n_mu] cosines for the phase table (any; pairs mu[n-1-j] = -mu[j]
 *            cost one evaluation), phase[n_mu] receives p(mu) per sr.
 *            mu/phase may be NULL with n_mu = 0.
 * Domain: every parameter as documented; the wavelengths and the radii
 * (mono, table, the laws' r_eff, r_c, r_g, a given r_min (or 0, but for the
 * lognormal law, integrated in ln r: r_min > 0) and r_max,
 * and the largest radius of an automatic range) in [MIST_MIE_LEN_MIN,
 * MIST_MIE_LEN_MAX]; n_wl >= 1; weights (wavelengths and table) finite and
 * >= 0, not all 0, of any scale (subnormal or 1e300: they are normalised
 * by the largest); every x = 2 pi n_medium r / lambda and m / n_medium in
 * the sphere's domain.  Else status MIST_MIE_EDOMAIN, every number 0 and
 * phase[] zeroed; also for a law whose density underflows every double at
 * every node (a range more than ~e^700 below its peak: no weight left).
 * Inside the domain every number is finite; C_sca = 0 (m = 1, or so little
 * scattering that Q_sca r^2 underflows at every node) gives g = 0 and
 * phase 0.  Allocates one workspace (malloc, for the largest x); failure:
 * MIST_MIE_ENOMEM.  Nodes with zero weight are skipped.
 * Scaled sums: weights are divided by the largest, radii by the largest
 * (rho = r / r_max), and the means are scaled back at the end (e.g.
 * C_ext = pi r_max^2 <w rho^2 Q_ext> / <w>), so no sum over- or underflows
 * for input in the domain (the plain sums did: weights of 1e214 gave
 * inf / inf, a subnormal weight or a range far in a law's tail gave
 * 0 / 0).  The phase weight |S|^2 / (2 k^2) is taken as r^2 (|S| / x)^2 / 2,
 * where the dipole limit's stored scale x^3 enters as (x^3 / x)^2 (k^2 and
 * x^6 both underflowed for huge wavelengths: 0 / 0). */
MIST_MIE_FUNC mist_mie_avg mist_mie_average(const mist_mie_dist *dist,
                                            const mist_mie_wavelength *wl, size_t n_wl,
                                            double n_medium,
                                            const double *mu, size_t n_mu, double *phase)
{
    mist_mie_avg a = mist_mie__avg_zero(MIST_MIE_OK);
    double t0 = 0, t1 = 0, h = 0, lmin = 0, wmax_l = 0, wsum_l = 0, rmax = 0, wmax_t = 0;
    double lwmax = -(double)INFINITY, xmax, r2s;
    double sw = 0, swx = 0, cext = 0, csca = 0, cabs = 0, cback = 0, gs = 0, area = 0, vol = 0;
    size_t nodes = 1, i, l, nwork;
    int logv = 0, ok = 1;
    double *work;

    if (phase) for (i = 0; i < n_mu; ++i) phase[i] = 0;
    if (!dist || !wl || n_wl == 0 || !(n_medium > 0 && mist_mie__finite(n_medium))
        || (n_mu > 0 && (!mu || !phase)))
        return mist_mie__avg_zero(MIST_MIE_EDOMAIN);
    for (l = 0; l < n_wl; ++l) {
        int pec;
        double lam = wl[l].lambda;
        if (!(mist_mie__len(lam) && wl[l].weight >= 0 && mist_mie__finite(wl[l].weight)))
            return mist_mie__avg_zero(MIST_MIE_EDOMAIN);
        if (!mist_mie__valid(1e-3, mist_mie_cplx(wl[l].m.re / n_medium,
                                                 wl[l].m.im / n_medium), &pec))
            return mist_mie__avg_zero(MIST_MIE_EDOMAIN);
        if (l == 0 || lam < lmin) lmin = lam;
        if (wl[l].weight > wmax_l) wmax_l = wl[l].weight;
    }
    if (!(wmax_l > 0)) return mist_mie__avg_zero(MIST_MIE_EDOMAIN);
    for (l = 0; l < n_wl; ++l) wsum_l += wl[l].weight / wmax_l;

    /* the nodes */
    switch (dist->kind) {
    case MIST_MIE_DIST_MONO:
        if (!mist_mie__len(dist->p1)) return mist_mie__avg_zero(MIST_MIE_EDOMAIN);
        rmax = dist->p1;
        a.r_min = a.r_max = rmax;
        break;
    case MIST_MIE_DIST_TABLE:
        if (!dist->r || !dist->w || dist->n == 0) return mist_mie__avg_zero(MIST_MIE_EDOMAIN);
        for (i = 0; i < dist->n; ++i) {
            if (!(mist_mie__len(dist->r[i]) && dist->w[i] >= 0 && mist_mie__finite(dist->w[i])))
                return mist_mie__avg_zero(MIST_MIE_EDOMAIN);
            if (dist->r[i] > rmax) rmax = dist->r[i];
            if (i == 0 || dist->r[i] < a.r_min) a.r_min = dist->r[i];
            if (dist->w[i] > wmax_t) wmax_t = dist->w[i];
        }
        if (!(wmax_t > 0)) return mist_mie__avg_zero(MIST_MIE_EDOMAIN);
        nodes = dist->n;
        a.r_max = rmax;
        break;
    default: {
        double r0, span, r;
        if (!mist_mie__dist_range(dist, &t0, &t1, &logv) || dist->n_radii < 0)
            return mist_mie__avg_zero(MIST_MIE_EDOMAIN);
        rmax = logv ? exp(t1) : t1;
        r0 = logv ? exp(t0) : t0;
        if (!mist_mie__len(rmax)) return mist_mie__avg_zero(MIST_MIE_EDOMAIN);
        if (dist->n_radii > 0) nodes = (size_t)dist->n_radii;
        else {
            /* size-parameter spacing <= 0.05 at the top of the range */
            span = 2 * MIST_MIE__PI * n_medium / lmin * (logv ? rmax * (t1 - t0) : rmax - r0);
            span = span / 0.05;
            nodes = (size_t)mist_mie__clampl(span, 63, 65535) + 1;
        }
        nodes = (nodes + 7) / 8 * 8;
        h = (t1 - t0) / (double)(nodes / 8);
        a.r_min = r0; a.r_max = rmax;
        for (i = 0; i < nodes; ++i) {          /* the largest weight, for the scale
                                                  (again below: a log and an exp a
                                                  node, beside a Mie sphere a node) */
            double lw = mist_mie__node(dist, logv, t0, h, i, &r);
            if (lw > lwmax) lwmax = lw;
        }
        if (!(lwmax > -(double)INFINITY)) return mist_mie__avg_zero(MIST_MIE_EDOMAIN);
        if (dist->kind == MIST_MIE_DIST_GAMMA) {
            /* alpha < 2 (v_eff > 1/5): n = r^alpha e^(-r/beta) is not smooth
             * at r = 0 (singular for v_eff > 1/3), and the nodes in r missed
             * its number: 3.8x at v_eff = 0.49, 2.3e-5 at 0.3 (an
             * independent check).  The number (sum of the weights) is then
             * the exact integral over [0, t1] (incomplete gamma); the
             * cross sections' integrands, n r^2 Q and above, are smooth
             * enough for the nodes.  Only where the range holds r = 0 and
             * the panels resolve the law's scale b (else the numerators
             * miss what the exact number counts: a range far in the tail
             * gave C = 0, found by fuzz_mie; there the nodes' own sum). */
            double al = (1 - 3 * dist->p2) / dist->p2, b = dist->p1 * dist->p2;
            if (al < 2 && t0 == 0 && h <= 64 * b)  /* (b / h: lengths x 2^k, same bits) */
                swx = 2 * b / h * exp((al > 0 ? al - al * log(al) : 0)
                                      + mist_mie__lngamlow(al + 1, t1 / b) - lwmax);
        }
    }
    }
    a.n_radii = (int)nodes;

    /* The workspace: sized for the largest x, and grown below where a
     * sphere needs more (mist_mie_workspace_size of that sphere's own x,
     * the size mist_mie_sphere_make checks), so the two sizes agree by
     * construction.  The size is not monotone in x (N steps down at x =
     * 4200: a node just below needs more than r_max), and an x computed
     * through another rounding than the sizing's came out an ulp above
     * it, across a step of the size: ENOMEM, every number 0, for valid
     * input.  One expression for x: mist_mie__avg_x. */
    xmax = mist_mie__avg_x(n_medium, lmin, rmax);
    nwork = mist_mie_workspace_size(xmax);
    if (nwork == 0) return mist_mie__avg_zero(MIST_MIE_EDOMAIN);
    work = (double *)malloc(nwork * sizeof(double));
    if (!work) return mist_mie__avg_zero(MIST_MIE_ENOMEM);

    for (i = 0; i < nodes && ok; ++i) {
        double r, w, rho, rho2;
        if (dist->kind == MIST_MIE_DIST_MONO) { r = dist->p1; w = 1; }
        else if (dist->kind == MIST_MIE_DIST_TABLE) { r = dist->r[i]; w = dist->w[i] / wmax_t; }
        else w = exp(mist_mie__node(dist, logv, t0, h, i, &r) - lwmax);
        if (!(w > 0)) continue;
        rho = r / rmax;  rho2 = rho * rho;
        sw += w * wsum_l;
        area += w * wsum_l * rho2;
        vol += w * wsum_l * rho2 * rho;
        for (l = 0; l < n_wl; ++l) {
            double x = mist_mie__avg_x(n_medium, wl[l].lambda, r), as;
            double ww = w * (wl[l].weight / wmax_l);
            size_t need = mist_mie_workspace_size(x);
            mist_mie_sphere s;
            if (!(ww > 0)) continue;
            if (need > nwork) {
                free(work);
                nwork = need;
                work = (double *)malloc(nwork * sizeof(double));
                if (!work) { ok = 0; a.status = MIST_MIE_ENOMEM; nwork = 0; break; }
            }
            s = mist_mie_sphere_make(x, mist_mie_cplx(wl[l].m.re / n_medium,
                                                      wl[l].m.im / n_medium), work, nwork);
            if (s.status != MIST_MIE_OK) { ok = 0; a.status = s.status; break; }
            cext += ww * s.q_ext * rho2;
            csca += ww * s.q_sca * rho2;
            cabs += ww * s.q_abs * rho2;
            cback += ww * s.q_back * rho2;
            gs += ww * s.g * s.q_sca * rho2;
            as = s.amp_scale_ / x;
            if (n_mu > 0) mist_mie__table(&s, mu, n_mu, ww * rho2 * as * as / 2, 1, phase);
        }
    }
    free(work);
    if (swx > 0 && swx < (double)INFINITY && sw > 0) sw = swx * wsum_l;
    if (!ok || !(sw > 0)) {
        int st = ok ? MIST_MIE_EDOMAIN : a.status;
        if (phase) for (i = 0; i < n_mu; ++i) phase[i] = 0;
        return mist_mie__avg_zero(st);
    }
    for (i = 0; i < n_mu; ++i) phase[i] = csca > 0 ? phase[i] / (MIST_MIE__PI * csca) : 0;
    r2s = MIST_MIE__PI * rmax * rmax;
    a.c_ext = cext / sw * r2s;
    a.c_sca = csca / sw * r2s;
    a.c_abs = cabs / sw * r2s;
    a.c_back = cback / sw * r2s;
    a.g = csca > 0 ? gs / csca : 0;
    a.albedo = cext > 0 ? csca / cext : 0;
    a.area = area / sw * r2s;
    a.volume = vol / sw * (4.0 / 3) * r2s * rmax;
    return a;
}


/* ======================================================================== */
/* Nodes for a tabulated phase function (mist_tab_init in mist.h)           */
/* mist_tab interpolates linearly in mu between nodes; this places few      */
/* nodes where the phase function of a size distribution and wavelengths   */
/* allows and many in the forward peak and the glory, to a requested        */
/* accuracy.  Reference: mist_mie_average at MIST_MIE_TAB_REF angles        */
/* uniform in theta (16385: 0.011 degrees apart, ~35 across the forward     */
/* peak's first ring at x = 300).  The nodes are a subset of that grid,     */
/* chosen by splitting: an interval whose linear interpolant is further     */
/* than th from the reference at a grid angle inside it, in |log10|, is     */
/* split at the worst angle; th runs down from 1 by factors of 0.7 and the  */
/* first (so the fewest nodes of the sequence) whose table meets both       */
/* targets is kept.  The errors, of each channel's interpolant normalised   */
/* as mist_tab normalises it, against the reference on the grid (the        */
/* project's fit metrics, examples/fit_error.c):                            */
/*   log_rms = sqrt(int (log10(q / p))^2 dtheta / pi), the worst channel;   */
/*   l1      = int |q - p| dOmega (trapezoids in mu), the worst channel.    */
/* They are measured on the grid: features narrower than its spacing (the   */
/* size average smooths ripples; a single sphere at x > ~1000 does not)    */
/* are not seen.  Channels: per_wl = 0, one (the weighted average over wl); */
/* per_wl = 1, one per wavelength (p[i * n_wl + l]).  Output: mu[n]         */
/* ascending from -1 to 1 and p[n * channels], ready for mist_tab_init;    */
/* n <= n_max.  If no table of n_max nodes meets the targets, the one of    */
/* the smallest th that fits is returned and its errors say by how much it  */
/* misses (compare them with the targets).  Cost: the reference (one        */
/* mist_mie_average per channel at 16385 angles, paired: 8193 angle sums)   */
/* and ~20 passes of O(16385 log) over it.  Uses malloc (~0.4 MB per        */
/* channel).  Domain: as mist_mie_average; log_rms, l1 > 0; n_max >= 2;    */
/* else status MIST_MIE_EDOMAIN and n = 0.                                  */
/* ======================================================================== */

#define MIST_MIE_TAB_REF 16385
/* The result of mist_mie_tab_nodes */
typedef struct mist_mie_tabfit {
    int status;          /* MIST_MIE_OK, _EDOMAIN, _ENOMEM                   */
    size_t n;            /* nodes written                                    */
    double log_rms, l1;  /* the errors reached (see above), worst channel    */
    double th;           /* the split threshold used (|log10| per angle)     */
} mist_mie_tabfit;

/* log10 errors of channel c's interpolant through the flagged nodes, and
 * its L1 error, both normalised (see above) */
MIST_MIE_FUNC void mist_mie__tab_err(const double *mu, const double *th, const double *p,
                                     const unsigned char *on, size_t m, size_t C, size_t c,
                                     double *lrms, double *l1)
{
    size_t i, a = 0, b;
    double iq = 0, s2 = 0, s1 = 0, k;
    for (b = 1; b < m; ++b)                       /* the interpolant's integral */
        if (on[b]) { iq += (mu[b] - mu[a]) * (p[a * C + c] + p[b * C + c]) / 2; a = b; }
    k = 1 / (2 * MIST_MIE__PI * iq);
    a = 0;
    for (b = 1; b < m; ++b) {
        if (!on[b]) continue;
        for (i = a; i < b; ++i) {                 /* [mu_i, mu_i+1] in this cell */
            double w0 = (mu[b] - mu[i]) / (mu[b] - mu[a]);
            double w1 = (mu[b] - mu[i + 1]) / (mu[b] - mu[a]);
            double q0 = k * (w0 * p[a * C + c] + (1 - w0) * p[b * C + c]);
            double q1 = k * (w1 * p[a * C + c] + (1 - w1) * p[b * C + c]);
            double e0 = q0 - p[i * C + c], e1 = q1 - p[(i + 1) * C + c];
            double l0 = log10(q0 / p[i * C + c]), lg1 = log10(q1 / p[(i + 1) * C + c]);
            s1 += (mu[i + 1] - mu[i]) * (fabs(e0) + fabs(e1)) / 2;
            s2 += (th[i] - th[i + 1]) * (l0 * l0 + lg1 * lg1) / 2;
        }
        a = b;
    }
    *l1 = 2 * MIST_MIE__PI * s1;
    *lrms = sqrt(s2 / MIST_MIE__PI);
}

/* Flags the nodes for threshold t (splitting, see above); returns their
 * number.  stk: 2 m size_t. */
MIST_MIE_FUNC size_t mist_mie__tab_split(const double *mu, const double *p, size_t m,
                                         size_t C, double t, unsigned char *on, size_t *stk)
{
    size_t sp = 0, i, c, cnt = 2;
    for (i = 0; i < m; ++i) on[i] = 0;
    on[0] = on[m - 1] = 1;
    stk[sp++] = 0; stk[sp++] = m - 1;
    while (sp) {
        size_t b = stk[--sp], a = stk[--sp], w = 0;
        double worst = t;
        for (i = a + 1; i < b; ++i) {
            double f = (mu[b] - mu[i]) / (mu[b] - mu[a]);
            for (c = 0; c < C; ++c) {
                double q = f * p[a * C + c] + (1 - f) * p[b * C + c];
                double e = fabs(log10(q / p[i * C + c]));
                if (e > worst) { worst = e; w = i; }
            }
        }
        if (w) {
            on[w] = 1; ++cnt;
            stk[sp++] = a; stk[sp++] = w; stk[sp++] = w; stk[sp++] = b;
        }
    }
    return cnt;
}

/* Nodes (mu[], p[]) for mist_tab_init meeting log_rms and l1 with few
 * nodes, at most n_max; see above. */
MIST_MIE_FUNC mist_mie_tabfit mist_mie_tab_nodes(const mist_mie_dist *dist,
                                                 const mist_mie_wavelength *wl, size_t n_wl,
                                                 int per_wl, double n_medium, double log_rms,
                                                 double l1, size_t n_max, double *mu, double *p)
{
    const size_t m = MIST_MIE_TAB_REF;
    size_t C = per_wl ? n_wl : 1, c, i, j, nb;
    mist_mie_tabfit r;
    double *g, *th, *pr, *tmp, t, best_t = 0;
    unsigned char *on;
    size_t *stk;
    int found = 0, have = 0;
    r.status = MIST_MIE_OK; r.n = 0; r.log_rms = r.l1 = 0; r.th = 0;
    if (!mu || !p || !wl || n_wl == 0 || n_max < 2 || !(log_rms > 0) || !(l1 > 0)) {
        r.status = MIST_MIE_EDOMAIN;
        return r;
    }
    g = (double *)malloc(sizeof(double) * m * (3 + C));
    on = (unsigned char *)malloc(m);
    stk = (size_t *)malloc(sizeof(size_t) * 2 * m);
    if (!g || !on || !stk) {
        free(g); free(on); free(stk);
        r.status = MIST_MIE_ENOMEM;
        return r;
    }
    th = g + m; tmp = th + m; pr = tmp + m;
    mist_mie_theta_grid(m, tmp);                  /* descending: reversed */
    for (i = 0; i < m; ++i) {
        g[i] = tmp[m - 1 - i];
        th[i] = MIST_MIE__PI * (double)(m - 1 - i) / (double)(m - 1);
    }
    for (c = 0; c < C; ++c) {
        mist_mie_avg a = mist_mie_average(dist, per_wl ? wl + c : wl, per_wl ? 1 : n_wl,
                                          n_medium, g, m, tmp);
        if (a.status != MIST_MIE_OK) { r.status = a.status; break; }
        for (i = 0; i < m; ++i) {
            if (!(tmp[i] > 0)) { r.status = MIST_MIE_EDOMAIN; break; }
            pr[i * C + c] = tmp[i];
        }
    }
    if (r.status == MIST_MIE_OK) {
        for (t = 1; t > 1e-7; t *= 0.7) {
            double e1 = 0, e2 = 0;
            nb = mist_mie__tab_split(g, pr, m, C, t, on, stk);
            if (nb > n_max) break;
            for (c = 0; c < C; ++c) {
                double a1, a2;
                mist_mie__tab_err(g, th, pr, on, m, C, c, &a2, &a1);
                if (a2 > e2) e2 = a2;
                if (a1 > e1) e1 = a1;
            }
            have = 1; best_t = t; r.log_rms = e2; r.l1 = e1;
            if (e2 <= log_rms && e1 <= l1) { found = 1; break; }
        }
        if (!have) best_t = 1e9;                  /* the two ends */
        if (!found) (void)mist_mie__tab_split(g, pr, m, C, best_t, on, stk);
        if (!have) {
            for (c = 0; c < C; ++c) {
                double a1, a2;
                mist_mie__tab_err(g, th, pr, on, m, C, c, &a2, &a1);
                if (a2 > r.log_rms) r.log_rms = a2;
                if (a1 > r.l1) r.l1 = a1;
            }
        }
        r.th = best_t;
        for (i = 0, j = 0; i < m; ++i)
            if (on[i]) {
                mu[j] = g[i];
                for (c = 0; c < C; ++c) p[j * C + c] = pr[i * C + c];
                ++j;
            }
        mu[0] = -1; mu[j - 1] = 1;
        r.n = j;
    }
    free(g); free(on); free(stk);
    return r;
}

/* ======================================================================== */
/* Spectral to RGB                                                          */
/* A phase table per linear-sRGB channel, integrated over the visible       */
/* spectrum instead of taken at one wavelength per channel.  Light of an    */
/* illuminant S(lambda) scattered by the droplets gives, in channel c, the  */
/*   R_c(mu) = int S(l) rbar_c(l) C_sca(l) p_l(mu) dl / int S(l) rbar_c(l) dl */
/* per droplet and unit irradiance, where rbar = M (xbar, ybar, zbar) are   */
/* the CIE 1931 2-degree colour-matching functions taken to linear sRGB (M: */
/* IEC 61966-2-1's XYZ -> sRGB matrix), C_sca(l) the size-averaged          */
/* scattering cross section and p_l its phase function (mist_mie_average at */
/* the one wavelength l).  Dividing by each channel's illuminant response   */
/* renders the illuminant itself as (1, 1, 1) (white balanced to it: for    */
/* D65, sRGB's white, this is the usual normalisation to Y = 1).  Output:   */
/* c_sca[c] = R_c integrated over the sphere (the channel's cross section;  */
/* a renderer's sigma_s,c = number density times c_sca[c]) and the         */
/* normalised p_c(mu) = R_c(mu) / c_sca[c], 2 pi int p_c dmu = 1, ready for */
/* mist_tab_init with 3 channels.  rbar_r and rbar_g are negative over part */
/* of the spectrum (sRGB's gamut is smaller than the spectrum locus), so    */
/* p_c is a difference where a narrow feature sits at those wavelengths;    */
/* a negative value is set to 0 and counted (`negative`).                   */
/* Quadrature: n_lambda wavelengths evenly from 380 to 780 nm (5 nm steps   */
/* at n_lambda = 81 fall on the table's rows), trapezoids.  The integrands  */
/* are smooth in lambda once averaged over sizes (the size average smooths  */
/* the ripple; a single sphere's is not resolved by any practical step).   */
/* Data: CIE 15:2004 Table T.4 (x, y, zbar, 5 nm, 380-780) and Table T.1   */
/* (D65 relative SPD, 5 nm), linear between rows.  Checks (tests/test_mie.c, */
/* test_spectral): the 5 nm sums times 5 are 106.857 (ybar), equal-energy   */
/* white at x = y = 1/3 within 1e-4, D65 at (0.3127, 0.3290) within 1e-4,   */
/* and M times D65's XYZ (Y = 1) is (1, 1, 1) within 1e-3 (M's 4 digits).   */
/* Another illuminant is given as spd[] at the same wavelengths (sunlight   */
/* above the atmosphere: mist_mie_solar); another particle than water as   */
/* m[].                                                                     */
/* Cost: n_lambda mist_mie_average calls of one wavelength each.            */
/* ======================================================================== */

#define MIST_MIE_CIE_N 81   /* rows of the tables: 380, 385, ..., 780 nm */

/* Row i (380 + 5 i nm): xbar, ybar, zbar (CIE 1931 2-degree observer,
 * CIE 15:2004 Table T.4) and D65's relative spectral power (100 at 560 nm,
 * Table T.1), linear between the rows into out[4]; 0 outside [380, 780]
 * and for NaN. */
MIST_MIE_FUNC void mist_mie__cie(double lambda_nm, double *out)
{
    static const double tab[MIST_MIE_CIE_N][4] = {
        { 0.001368, 0.000039, 0.006450, 49.9755 },   /* 380 */
        { 0.002236, 0.000064, 0.010550, 52.3118 },   /* 385 */
        { 0.004243, 0.000120, 0.020050, 54.6482 },   /* 390 */
        { 0.007650, 0.000217, 0.036210, 68.7015 },   /* 395 */
        { 0.014310, 0.000396, 0.067850, 82.7549 },   /* 400 */
        { 0.023190, 0.000640, 0.110200, 87.1204 },   /* 405 */
        { 0.043510, 0.001210, 0.207400, 91.4860 },   /* 410 */
        { 0.077630, 0.002180, 0.371300, 92.4589 },   /* 415 */
        { 0.134380, 0.004000, 0.645600, 93.4318 },   /* 420 */
        { 0.214770, 0.007300, 1.039050, 90.0570 },   /* 425 */
        { 0.283900, 0.011600, 1.385600, 86.6823 },   /* 430 */
        { 0.328500, 0.016840, 1.622960, 95.7736 },   /* 435 */
        { 0.348280, 0.023000, 1.747060, 104.865 },   /* 440 */
        { 0.348060, 0.029800, 1.782600, 110.936 },   /* 445 */
        { 0.336200, 0.038000, 1.772110, 117.008 },   /* 450 */
        { 0.318700, 0.048000, 1.744100, 117.410 },   /* 455 */
        { 0.290800, 0.060000, 1.669200, 117.812 },   /* 460 */
        { 0.251100, 0.073900, 1.528100, 116.336 },   /* 465 */
        { 0.195360, 0.090980, 1.287640, 114.861 },   /* 470 */
        { 0.142100, 0.112600, 1.041900, 115.392 },   /* 475 */
        { 0.095640, 0.139020, 0.812950, 115.923 },   /* 480 */
        { 0.057950, 0.169300, 0.616200, 112.367 },   /* 485 */
        { 0.032010, 0.208020, 0.465180, 108.811 },   /* 490 */
        { 0.014700, 0.258600, 0.353300, 109.082 },   /* 495 */
        { 0.004900, 0.323000, 0.272000, 109.354 },   /* 500 */
        { 0.002400, 0.407300, 0.212300, 108.578 },   /* 505 */
        { 0.009300, 0.503000, 0.158200, 107.802 },   /* 510 */
        { 0.029100, 0.608200, 0.111700, 106.296 },   /* 515 */
        { 0.063270, 0.710000, 0.078250, 104.790 },   /* 520 */
        { 0.109600, 0.793200, 0.057250, 106.239 },   /* 525 */
        { 0.165500, 0.862000, 0.042160, 107.689 },   /* 530 */
        { 0.225750, 0.914850, 0.029840, 106.047 },   /* 535 */
        { 0.290400, 0.954000, 0.020300, 104.405 },   /* 540 */
        { 0.359700, 0.980300, 0.013400, 104.225 },   /* 545 */
        { 0.433450, 0.994950, 0.008750, 104.046 },   /* 550 */
        { 0.512050, 1.000000, 0.005750, 102.023 },   /* 555 */
        { 0.594500, 0.995000, 0.003900, 100.000 },   /* 560 */
        { 0.678400, 0.978600, 0.002750, 98.1671 },   /* 565 */
        { 0.762100, 0.952000, 0.002100, 96.3342 },   /* 570 */
        { 0.842500, 0.915400, 0.001800, 96.0611 },   /* 575 */
        { 0.916300, 0.870000, 0.001650, 95.7880 },   /* 580 */
        { 0.978600, 0.816300, 0.001400, 92.2368 },   /* 585 */
        { 1.026300, 0.757000, 0.001100, 88.6856 },   /* 590 */
        { 1.056700, 0.694900, 0.001000, 89.3459 },   /* 595 */
        { 1.062200, 0.631000, 0.000800, 90.0062 },   /* 600 */
        { 1.045600, 0.566800, 0.000600, 89.8026 },   /* 605 */
        { 1.002600, 0.503000, 0.000340, 89.5991 },   /* 610 */
        { 0.938400, 0.441200, 0.000240, 88.6489 },   /* 615 */
        { 0.854450, 0.381000, 0.000190, 87.6987 },   /* 620 */
        { 0.751400, 0.321000, 0.000100, 85.4936 },   /* 625 */
        { 0.642400, 0.265000, 0.000050, 83.2886 },   /* 630 */
        { 0.541900, 0.217000, 0.000030, 83.4939 },   /* 635 */
        { 0.447900, 0.175000, 0.000020, 83.6992 },   /* 640 */
        { 0.360800, 0.138200, 0.000010, 81.8630 },   /* 645 */
        { 0.283500, 0.107000, 0, 80.0268 },   /* 650 */
        { 0.218700, 0.081600, 0, 80.1207 },   /* 655 */
        { 0.164900, 0.061000, 0, 80.2146 },   /* 660 */
        { 0.121200, 0.044580, 0, 81.2462 },   /* 665 */
        { 0.087400, 0.032000, 0, 82.2778 },   /* 670 */
        { 0.063600, 0.023200, 0, 80.2810 },   /* 675 */
        { 0.046770, 0.017000, 0, 78.2842 },   /* 680 */
        { 0.032900, 0.011920, 0, 74.0027 },   /* 685 */
        { 0.022700, 0.008210, 0, 69.7213 },   /* 690 */
        { 0.015840, 0.005723, 0, 70.6652 },   /* 695 */
        { 0.011359, 0.004102, 0, 71.6091 },   /* 700 */
        { 0.008111, 0.002929, 0, 72.9790 },   /* 705 */
        { 0.005790, 0.002091, 0, 74.3490 },   /* 710 */
        { 0.004109, 0.001484, 0, 67.9765 },   /* 715 */
        { 0.002899, 0.001047, 0, 61.6040 },   /* 720 */
        { 0.002049, 0.000740, 0, 65.7448 },   /* 725 */
        { 0.001440, 0.000520, 0, 69.8856 },   /* 730 */
        { 0.001000, 0.000361, 0, 72.4863 },   /* 735 */
        { 0.000690, 0.000249, 0, 75.0870 },   /* 740 */
        { 0.000476, 0.000172, 0, 69.3398 },   /* 745 */
        { 0.000332, 0.000120, 0, 63.5927 },   /* 750 */
        { 0.000235, 0.000085, 0, 55.0054 },   /* 755 */
        { 0.000166, 0.000060, 0, 46.4182 },   /* 760 */
        { 0.000117, 0.000042, 0, 56.6118 },   /* 765 */
        { 0.000083, 0.000030, 0, 66.8054 },   /* 770 */
        { 0.000059, 0.000021, 0, 65.0941 },   /* 775 */
        { 0.000042, 0.000015, 0, 63.3828 }    /* 780 */
    };
    double t = (lambda_nm - 380) / 5, f;
    long i;
    int c;
    if (!(t >= 0 && t <= MIST_MIE_CIE_N - 1)) { out[0] = out[1] = out[2] = out[3] = 0; return; }
    i = mist_mie__clampl(t, 0, MIST_MIE_CIE_N - 2);
    f = t - (double)i;
    for (c = 0; c < 4; ++c) out[c] = tab[i][c] + f * (tab[i + 1][c] - tab[i][c]);
}

/* CIE 1931 2-degree colour-matching functions xbar, ybar, zbar at lambda_nm
 * into xyz[3] (see mist_mie__cie). */
MIST_MIE_FUNC void mist_mie_cie1931(double lambda_nm, double *xyz)
{
    double v[4];
    mist_mie__cie(lambda_nm, v);
    xyz[0] = v[0]; xyz[1] = v[1]; xyz[2] = v[2];
}

/* CIE standard illuminant D65's relative spectral power at lambda_nm (100
 * at 560 nm; see mist_mie__cie). */
MIST_MIE_FUNC double mist_mie_d65(double lambda_nm)
{
    double v[4];
    mist_mie__cie(lambda_nm, v);
    return v[3];
}

/* The extraterrestrial solar spectrum (air mass 0) at lambda_nm, W m^-2
 * nm^-1 at 1 au: ASTM G173-03's extraterrestrial column (Gueymard's
 * SMARTS 2.9.2 spectrum, 0.5-1 nm steps) averaged over 5 nm bands centred
 * on 380, 385, ..., 780 nm (the mean of its piecewise-linear curve over
 * [lambda - 2.5, lambda + 2.5]: the Fraunhofer lines averaged as a 5 nm
 * quadrature sees them, not sampled), linear between the rows; 0 outside
 * [380, 780] and for NaN.  For mist_mie_spectral_rgb's spd[] (sunlight
 * above the atmosphere instead of D65: spd[l] = mist_mie_solar(380 + 400 l
 * / (n_lambda - 1))). */
MIST_MIE_FUNC double mist_mie_solar(double lambda_nm)
{
    static const double tab[MIST_MIE_CIE_N] = {
        1.1893, 0.9339, 1.1739, 0.9382, 1.6258, 1.7064, 1.7116, 1.7606,   /* 380 */
        1.7257, 1.7061, 1.4578, 1.7430, 1.7696, 1.9107, 2.0500, 2.0120,   /* 420 */
        2.0379, 2.0089, 1.9975, 2.0270, 2.0612, 1.8822, 1.9184, 1.9748,   /* 460 */
        1.8998, 1.9343, 1.9353, 1.8076, 1.8139, 1.8463, 1.9276, 1.8693,   /* 500 */
        1.8366, 1.8769, 1.8649, 1.8580, 1.8177, 1.8328, 1.8308, 1.8518,   /* 540 */
        1.8286, 1.8359, 1.7533, 1.7912, 1.7543, 1.7631, 1.7310, 1.6786,   /* 580 */
        1.7034, 1.6651, 1.6609, 1.6447, 1.6303, 1.6121, 1.5769, 1.4844,   /* 620 */
        1.5511, 1.5551, 1.5327, 1.5087, 1.4942, 1.4629, 1.4710, 1.4454,   /* 660 */
        1.4178, 1.4154, 1.3942, 1.3674, 1.3429, 1.3491, 1.3188, 1.3200,   /* 700 */
        1.2775, 1.2902, 1.2742, 1.2691, 1.2543, 1.2339, 1.2153, 1.2080,   /* 740 */
        1.1971   /* 780 */
    };
    double t = (lambda_nm - 380) / 5;
    long i;
    if (!(t >= 0 && t <= MIST_MIE_CIE_N - 1)) return 0;
    i = mist_mie__clampl(t, 0, MIST_MIE_CIE_N - 2);
    return tab[i] + (t - (double)i) * (tab[i + 1] - tab[i]);
}

/* Linear sRGB from CIE XYZ (IEC 61966-2-1: D65 white, no gamma). */
MIST_MIE_FUNC void mist_mie_xyz_srgb(const double *xyz, double *rgb)
{
    double x = xyz[0], y = xyz[1], z = xyz[2];
    rgb[0] = 3.2406 * x - 1.5372 * y - 0.4986 * z;
    rgb[1] = -0.9689 * x + 1.8758 * y + 0.0415 * z;
    rgb[2] = 0.0557 * x - 0.2040 * y + 1.0570 * z;
}

/* The result of mist_mie_spectral_rgb */
typedef struct mist_mie_rgb {
    int status;          /* MIST_MIE_OK, _EDOMAIN, _ENOMEM                   */
    double c_sca[3];     /* each channel's scattering cross section (the    */
                         /* radii's unit squared), illuminant white = 1     */
    double g[3];         /* each channel's asymmetry, int p_c mu dOmega      */
    size_t negative;     /* values of p[] below 0, set to 0                  */
} mist_mie_rgb;

/* Three normalised phase functions, linear sRGB, integrated over 380-780
 * nm (see above) into p[j * 3 + c] at mu[j] (j < n_mu).
 *   dist     the droplet sizes, radii in MICROMETRES;
 *   n_medium the medium's real index (1 for vacuum; 1.0003 air);
 *   m        the particle's index at each wavelength, or NULL: water
 *            (mist_mie_water);
 *   spd      the illuminant at each wavelength (>= 0, not all 0, any scale),
 *            or NULL: D65;
 *   n_lambda wavelengths 380 + 400 j / (n_lambda - 1) nm, n_lambda >= 2.
 * Domain: as mist_mie_average at each wavelength; mu, p not NULL (n_mu >=
 * 1).  Else status MIST_MIE_EDOMAIN and p[] zeroed (where p is given).
 * Uses malloc (n_mu doubles). */
MIST_MIE_FUNC mist_mie_rgb mist_mie_spectral_rgb(const mist_mie_dist *dist, double n_medium,
                                                 const mist_mie_complex *m, const double *spd,
                                                 size_t n_lambda, const double *mu, size_t n_mu,
                                                 double *p)
{
    mist_mie_rgb r;
    double resp[3] = { 0, 0, 0 }, gs[3] = { 0, 0, 0 }, *tmp;
    size_t j, l, c;
    r.status = MIST_MIE_OK; r.negative = 0;
    for (c = 0; c < 3; ++c) r.c_sca[c] = r.g[c] = 0;
    if (p) for (j = 0; j < 3 * n_mu; ++j) p[j] = 0;
    if (!dist || !mu || !p || n_mu == 0 || n_lambda < 2) { r.status = MIST_MIE_EDOMAIN; return r; }
    tmp = (double *)malloc(sizeof(double) * n_mu);
    if (!tmp) { r.status = MIST_MIE_ENOMEM; return r; }
    for (l = 0; l < n_lambda && r.status == MIST_MIE_OK; ++l) {
        double lam = 380 + 400 * (double)l / (double)(n_lambda - 1), xyz[3], rgb[3], s, w;
        mist_mie_wavelength wl;
        mist_mie_avg a;
        s = spd ? spd[l] : mist_mie_d65(lam);
        if (!(s >= 0 && mist_mie__finite(s))) { r.status = MIST_MIE_EDOMAIN; break; }
        w = (l == 0 || l == n_lambda - 1 ? 0.5 : 1) * s;    /* trapezoids (common step left out) */
        mist_mie_cie1931(lam, xyz);
        mist_mie_xyz_srgb(xyz, rgb);
        for (c = 0; c < 3; ++c) resp[c] += w * rgb[c];
        if (w == 0) continue;
        wl = mist_mie_wl(lam / 1000, 1, m ? m[l] : mist_mie_water(lam, MIST__NULL));
        a = mist_mie_average(dist, &wl, 1, n_medium, mu, n_mu, tmp);
        if (a.status != MIST_MIE_OK) { r.status = a.status; break; }
        for (c = 0; c < 3; ++c) {
            double k = w * rgb[c] * a.c_sca;
            r.c_sca[c] += k;
            gs[c] += k * a.g;
            for (j = 0; j < n_mu; ++j) p[j * 3 + c] += k * tmp[j];
        }
    }
    free(tmp);
    for (c = 0; c < 3 && r.status == MIST_MIE_OK; ++c)
        if (!(resp[c] > 0 && r.c_sca[c] > 0)) r.status = MIST_MIE_EDOMAIN;
    if (r.status != MIST_MIE_OK) {
        for (j = 0; j < 3 * n_mu; ++j) p[j] = 0;
        for (c = 0; c < 3; ++c) r.c_sca[c] = r.g[c] = 0;
        return r;
    }
    for (c = 0; c < 3; ++c) {
        double k = 1 / r.c_sca[c];
        for (j = 0; j < n_mu; ++j) {
            double v = p[j * 3 + c] * k;
            if (v < 0) { v = 0; ++r.negative; }
            p[j * 3 + c] = v;
        }
        r.g[c] = gs[c] / r.c_sca[c];
        r.c_sca[c] /= resp[c];
    }
    return r;
}

#ifdef __cplusplus
}
#endif

#define MIST__FP_POP
#include "mist.h"
#undef MIST__FP_POP

#endif /* MIST_MIE_H */
