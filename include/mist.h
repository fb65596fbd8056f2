/* mist.h - phase functions and fog models for renderers.          v0.1.0
 *
 * Header-only C99, also C++ (98 and later) and CUDA; needs only <math.h>.
 * MIT license (end of file).  The repository's README.md and docs/ hold the
 * measurements behind the figures below.
 *
 * USAGE
 *   #include "mist.h"
 *
 *   double p  = mist_hg_eval(0.8, cos_theta);        // density per steradian
 *   double u  = mist_draine_sample(0.5, 250.0, xi);  // exact inverse CDF: cos theta
 *   float  pf = mist_cs_evalf(0.7f, cos_theta);      // float: same names + 'f'
 *
 *   // Scatter a propagation direction wi (the frame is built for you):
 *   double pdf;
 *   mist_vec3 wo = mist_hg_sample_dir(0.8, wi, xi1, xi2, &pdf);
 *
 *   // The Jendersie-d'Eon fog phase function: HG and Draine mixed.
 *   mist_fog fog = mist_fog_from_diameter(10.0);     // its fit at d = 10 um
 *   double pf2 = mist_fog_eval(fog, u);
 *
 *   // Per medium, prepare once (also _hg, _cs, _rayleigh, _draine), then
 *   // sample and evaluate through a pointer: same results, less work.
 *   mist_phase ph = mist_phase_fog(fog);
 *   mist_vec3 wo2 = mist_phase_sample_dir(&ph, wi, xi1, xi2, &pdf);
 *   // Compact (60 bytes in float, for a GPU closure): the fog or Draine.
 *   mist_phasecf pc = mist_phasec_fogf(mist_fog_from_diameterf(10.0f));
 *
 *   // Height fog along a ray: a background seen through it.
 *   mist_rgb c = mist_hfog_apply(&hfog, origin, dir, length, background);
 *
 * Every public function is listed in plain C, with its parameters' types,
 * in the section "THE API" below the types.
 *
 * CONVENTIONS
 *   u = cos(theta), theta the angle between the incident and the scattered
 *   PROPAGATION directions: g > 0 scatters forward.  Every *_eval returns the
 *   density per steradian; it integrates to 1 over the sphere.  Every sampler
 *   is exact, so the pdf of a sample is the evaluated density (pbrt / Cycles
 *   convention): *_sample_dir reports it.  Every scalar sampler but the fog
 *   mix is the inverse of the CDF P(cos <= u) = xi, monotone in xi, so
 *   stratified and low-discrepancy sequences keep their structure; the fog
 *   mix's one xi picks the lobe, then samples it at the rescaled xi.
 *   Double is the plain name, float carries an 'f' suffix (as in libm).
 *   Both come from ONE definition of each formula: the header includes
 *   itself once per type (see "The passes").
 *
 * ACCURACY (eps = 2^-53 double, 2^-24 float; worst as the tests print it)
 *   function                   bar                                  worst
 *   *_sample, mist_phase[c]_*  |u - u*| <= 4 ulp(u*)                double 0.250,
 *     (scalar, prepared,         + 4 eps xi du* / dxi, u* the float128 float 0.125
 *     batch)                     inverse CDF; monotone in xi          of the bar
 *   mist_hg_sample (double)    correctly rounded in practice        0 of 40000 not
 *                              (double-double; near u = 0 within      the rounded root
 *                              half an ulp + 2^-104)
 *   mist_fog_sample            its lobe's bar at the rescaled xi    0.352, 0.248
 *   *_eval, mist_phase_eval    a few ulps of the float128 density;  test_quadrature
 *                              integral 1 within 1e-10
 *   *_sample_dir, normalize    unit length within 4 eps             1.17, 0.25 eps
 *   *_eval_n, *_sample_n       bit for bit the scalar function      (see BATCH FORMS)
 *   mist_hfog_* (one layer)    8 eps (1 + tau)                      6.23, 4.43 eps
 *   mist_hfog_sample_distance  |t - t*| <= 4 ulp(t*) + 4 eps xi      0.64, 0.85
 *                              d(t*)/dxi; monotone                  of the bar
 *   mist_hfog_layers_eval      transmittance as above; in-scatter   error/bound 0.95
 *                              within the bound it reports
 *   mist_segment_linear        10 eps                               7.92, 9.13 eps
 *   mist_tab_sample            the samplers' bar, monotone          0.125 of the bar
 *   How each sampler gets there: float computes in float and finishes in
 *   double; double HG and Rayleigh finish in double-double (products by fma
 *   where it is one instruction, FP_FAST_FMA: ARM64, x86 -march=haswell and
 *   later, CUDA; else Dekker's splitting), the same samples in every build
 *   that rounds each operation; double Draine and Cornette-Shanks finish in
 *   double-double where fma is one instruction or long double is no wider
 *   (MSVC, ARM64, CUDA, MIST_NO_LONG_DOUBLE), else in x87 long double.  A
 *   compiler that contracts a*b + c into fma (gcc without -std=c99, clang
 *   -march=native) may change last bits where the bar's xi term rules,
 *   within the bar.  Tested in tests/test_accuracy.c, test_quadrature.c,
 *   test_chi2.c, test_batch.c, test_height_fog.c.
 *
 * DOMAIN AND BAD INPUT (every function; tested in tests/test_domain.c)
 *   g      in [-1, 1]. |g| > 1 is clamped to +-1; NaN is taken as 0.
 *          |g| = 1 is the Dirac limit: samplers return u = g exactly (the
 *          direction +-wi), eval returns 0 for u != g and +INFINITY at u = g,
 *          and the direction samplers report pdf = +INFINITY.  Treat it as a
 *          specular event.  For |g| < 1 every result is finite.
 *   alpha  in [0, +inf].  alpha < 0 and NaN are taken as 0; alpha = +inf is
 *          the exact limit (density proportional to HG * u^2).
 *   u      in [-1, 1].  Values outside are clamped (a dot product of unit
 *          vectors may exceed 1 by an ulp); NaN gives density 0.
 *   xi     in [0, 1].  Values outside are clamped; NaN is taken as 0.
 *          xi = 1 is accepted (returns the upper end, u = 1 for |g| < 1).
 *   wi     any non-zero finite vector; it is normalised.  A zero, NaN or
 *          infinite vector is taken as (0, 0, 1).
 *   w_d    (fog mix weight) in [0, 1]; clamped, NaN taken as 0.
 *   ph     (mist_phase_* functions) built by a mist_phase_* constructor,
 *          which sanitises as above; NULL is the isotropic phase function.
 *   in, out (batch forms) n elements each; out may equal in, no other
 *          overlap; n = 0 does nothing (in, out may then be NULL).
 *   Height fog: see "Analytic height fog".  No function reads or writes
 *   outside the memory it is given, in any build.
 *
 * CONFIGURATION (define before including)
 *   MIST_FUNC     qualifiers of every function (default: static inline, plus
 *                 __host__ __device__ under nvcc, so kernels can call them).
 *   MIST_ALLOW_FAST_MATH  compile mist with the includer's fast-math flags
 *                 instead of guarding against them (see FAST MATH).
 *   MIST_ALLOW_EXCESS_PRECISION  build with x87 math (see EXCESS PRECISION).
 *   MIST_NO_LONG_DOUBLE  build the double Draine samplers as where long
 *                 double is no wider (MSVC, ARM Macs, CUDA device code):
 *                 double-double, the same bar.
 *   MIST_DRAINE_PREPARE_N  (default 1024) from this many elements on, the
 *                 unprepared Draine batch samplers prepare the medium once
 *                 where their eq. 6 kernel does not apply (see BATCH FORMS);
 *                 1: always, (size_t)-1: never.
 *   MIST_HFOG_MAX_LAYERS  (default 8) layers mist_hfog_layers_eval uses.
 *   Leave out what a scene does not need (as stb's STBI_NO_*): each macro
 *   removes whole sections, so they are not even compiled, and the names
 *   are then undeclared.  The types (mist_fog, mist_hfog, ...) always stay.
 *   MIST_NO_DRAINE    Draine and Cornette-Shanks; implies MIST_NO_FOG.
 *   MIST_NO_RAYLEIGH  Rayleigh; implies MIST_NO_HFOG.
 *   MIST_NO_FOG       the fog mix, the droplet fits and the prepared phase
 *                     functions (mist_phase_*); implies MIST_NO_HFOG.
 *   MIST_NO_HFOG      the height fog (mist_hfog_*, mist_segment_linear).
 *   MIST_NO_DIR       the direction samplers; mist_normalize stays.
 *   MIST_NO_BATCH     the array forms (mist_*_eval_n, mist_*_sample_n).
 *   MIST_NO_TAB       the tabulated phase functions (mist_tab_*).
 *   MIST_ONLY_HG      Henyey-Greenstein alone: all of MIST_NO_DRAINE,
 *                     _RAYLEIGH, _FOG, _HFOG and _TAB.
 *   Every combination compiles (tests/compile/config.c).  The Lorenz-Mie
 *   solver is a separate header, mist_mie.h.
 *
 * BATCH FORMS (tests/test_batch.c)
 *   out[i] is what the scalar function returns for in[i], bit for bit: the
 *   same domain and bad-input results.  Two exceptions: a compiler allowed
 *   to contract a*b+c into fma may fuse the two copies differently (then a
 *   few ulps apart; the Draine samplers within their bar of each other);
 *   and from MIST_DRAINE_PREPARE_N elements on, outside their eq. 6 kernel's
 *   domain, the unprepared Draine batch samplers prepare the medium and
 *   return the prepared sampler's values (the same bar, monotone; the last
 *   bit differs from mist_draine_sample's for ~1e-4 of xi in float, ~1e-3
 *   in double).  They work on blocks of 32 with branch-free bodies, which
 *   gcc and clang vectorise at -O2 and -O3; square roots vectorise only
 *   without errno (-fno-math-errno, implied by -ffast-math).  The fog
 *   mixture's samplers (mist_fog_sample_n, mist_phase_sample_n of a fog)
 *   sort each chunk's xi by lobe and run each lobe's batch (mist__mix_n);
 *   in CUDA device code, and in double where fma is no instruction (no
 *   lobe's batch vectorises there), they loop over the scalar function.
 *
 * FAST MATH
 *   Compiled with the includer's -ffast-math mist would break (gcc's
 *   -ffinite-math-only deletes the NaN tests of the bad-input handling,
 *   clang's reassociation undoes the stable forms).  So when the
 *   translation unit has fast-math flags (__FAST_MATH__,
 *   __FINITE_MATH_ONLY__, __ASSOCIATIVE_MATH__, __RECIPROCAL_MATH__), mist
 *   compiles its own functions with precise floating point and gives the
 *   includer's flags back after them (gcc 12, clang 14 measured):
 *   gcc    #pragma GCC optimize("no-fast-math", ...): the documented results
 *          hold (the suite passes under -O2 -ffast-math: variant_fastmath).
 *          gcc does not inline a function with other floating-point flags
 *          into a fast-math caller: each call stays a call, 1x to 3.5x the
 *          time of a plain -O2 build (the cheap evaluations most).
 *   clang  #pragma float_control(precise, on): inlined, no slower.  The
 *          pragma reaches arithmetic and comparisons only: the includer's
 *          no-NaN and no-inf flags stay on selects, negations and calls,
 *          where they may fold a floating-point test away.  The height
 *          fog's input tests and the prepared sampler's table index are
 *          on the bits, so their bad input gets its documented values
 *          (tests/fastmath/); the other functions' bad-input tests are
 *          floating-point ones, which pass under clang -O2 and -O3
 *          -march=native -ffast-math (test_domain) but are not guaranteed
 *          there.  libm calls keep the flags: a float sqrt may be within
 *          3.3 ulp, so float results may differ in the last bits.
 *   Either way -ffast-math links start-up code that flushes subnormals to
 *   zero (FTZ/DAZ) for the whole program: a result that would be subnormal
 *   is 0.  Not guarded: other compilers, and nvcc's --use_fast_math.
 *   MIST_ALLOW_FAST_MATH turns the guard off: faster under gcc, but NaN,
 *   infinite and extreme input lose their documented results.  Memory
 *   safety stays in every build: every index and size derived from a
 *   floating-point value is bounded in integer arithmetic.
 *
 * EXCESS PRECISION (FLT_EVAL_METHOD 1 or 2: 32-bit x86 with x87 math)
 *   mist's stable forms, compensated sums and exact samplers assume every
 *   operation rounds to its type; x87 registers keep 64-bit significands
 *   and round where the compiler spills (22 test checks failed with gcc 12
 *   -m32).  So such a build stops with an error (ctest compile_x87); build
 *   with -msse2 -mfpmath=sse, or define MIST_ALLOW_EXCESS_PRECISION to build
 *   it anyway, without those results.
 *
 * REFERENCES (section by section below)
 *   [JD23] J. Jendersie, E. d'Eon, "An Approximate Mie Scattering Function
 *          for Fog and Cloud Rendering", SIGGRAPH 2023 Talks, and its
 *          supplemental.
 *   [HG41] L. Henyey, J. Greenstein, ApJ 93 (1941).
 *   [CS92] W. Cornette, J. Shanks, Applied Optics 31 (1992).
 *   [D03]  B. Draine, ApJ 598 (2003).
 *   [DHB17] T. Duff et al., "Building an Orthonormal Basis, Revisited",
 *          JCGT 6(1), 2017.
 *   [I18]  K. Ishiyama, "An analytic height fog model for real-time
 *          rendering", 2018.
 *   [B08]  A. Bouthors, F. Neyret, N. Max, E. Bruneton, C. Crassin,
 *          "Interactive multiple anisotropic scattering in clouds", I3D 2008.
 */
/* The null pointer (C++11 and later: nullptr, for -Wzero-as-null-pointer-
 * constant), defined on every inclusion: mist_mie.h, which includes this
 * file for the fast-math guard only, uses it too. */
#ifndef MIST__NULL
#  if defined(__cplusplus) && __cplusplus >= 201103L
#    define MIST__NULL nullptr
#  else
#    define MIST__NULL 0
#  endif
#endif
#if defined(MIST__FP_PUSH) || defined(MIST__FP_POP)
/* ------------------------------------------------------------------------ */
/* The fast-math guard (see FAST MATH above), included with MIST__FP_PUSH   */
/* before mist's functions and with MIST__FP_POP after them, by this file   */
/* and by mist_mie.h.                                                       */
/* ------------------------------------------------------------------------ */
/* gcc: errno and trapping stay off as -ffast-math has them (the batch
 * forms vectorise); signed zeros, NaN, infinity and the written order of
 * operations are honoured again; no contraction into FMA (-std=c99's
 * setting, which the pragma would otherwise reset to gcc's GNU default,
 * "fast", measured).  gcc 12's pop_options leaves the
 * predefined macros of these flags as the pragma set them (__FAST_MATH__
 * undefined, ...), so the includer's are noted here and put back there. */
#ifdef MIST__FP_PUSH
#if !defined(MIST_ALLOW_FAST_MATH) && !defined(__NVCC__) && (defined(__FAST_MATH__) \
    || (defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__) \
    || defined(__ASSOCIATIVE_MATH__) || defined(__RECIPROCAL_MATH__))
#  if defined(__clang__)
#    pragma float_control(precise, on, push)
#    define MIST__FP_GUARD 1
#  elif defined(__GNUC__)
#    define MIST__FP_GUARD 2
#    ifdef __FAST_MATH__
#      define MIST__HAD_FAST_MATH
#    endif
#    if defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__
#      define MIST__HAD_FINITE_MATH_ONLY
#    endif
#    ifdef __ASSOCIATIVE_MATH__
#      define MIST__HAD_ASSOCIATIVE_MATH
#    endif
#    ifdef __RECIPROCAL_MATH__
#      define MIST__HAD_RECIPROCAL_MATH
#    endif
#    ifdef __NO_SIGNED_ZEROS__
#      define MIST__HAD_NO_SIGNED_ZEROS
#    endif
#    ifdef __NO_TRAPPING_MATH__
#      define MIST__HAD_NO_TRAPPING_MATH
#    endif
#    ifdef __NO_MATH_ERRNO__
#      define MIST__HAD_NO_MATH_ERRNO
#    endif
#    pragma GCC push_options
#    pragma GCC optimize("no-fast-math", "no-math-errno", "no-trapping-math", \
                         "fp-contract=off")
#  endif
#endif
#else
#if defined(MIST__FP_GUARD) && MIST__FP_GUARD == 1
#  pragma float_control(pop)
#elif defined(MIST__FP_GUARD) && MIST__FP_GUARD == 2
#  pragma GCC pop_options
#  undef __FAST_MATH__
#  undef __FINITE_MATH_ONLY__
#  undef __ASSOCIATIVE_MATH__
#  undef __RECIPROCAL_MATH__
#  undef __NO_SIGNED_ZEROS__
#  undef __NO_TRAPPING_MATH__
#  undef __NO_MATH_ERRNO__
#  ifdef MIST__HAD_FAST_MATH
#    define __FAST_MATH__ 1
#  endif
#  ifdef MIST__HAD_FINITE_MATH_ONLY
#    define __FINITE_MATH_ONLY__ 1
#  else
#    define __FINITE_MATH_ONLY__ 0
#  endif
#  ifdef MIST__HAD_ASSOCIATIVE_MATH
#    define __ASSOCIATIVE_MATH__ 1
#  endif
#  ifdef MIST__HAD_RECIPROCAL_MATH
#    define __RECIPROCAL_MATH__ 1
#  endif
#  ifdef MIST__HAD_NO_SIGNED_ZEROS
#    define __NO_SIGNED_ZEROS__ 1
#  endif
#  ifdef MIST__HAD_NO_TRAPPING_MATH
#    define __NO_TRAPPING_MATH__ 1
#  endif
#  ifdef MIST__HAD_NO_MATH_ERRNO
#    define __NO_MATH_ERRNO__ 1
#  endif
#endif
#  undef MIST__FP_GUARD
#  undef MIST__HAD_FAST_MATH
#  undef MIST__HAD_FINITE_MATH_ONLY
#  undef MIST__HAD_ASSOCIATIVE_MATH
#  undef MIST__HAD_RECIPROCAL_MATH
#  undef MIST__HAD_NO_SIGNED_ZEROS
#  undef MIST__HAD_NO_TRAPPING_MATH
#  undef MIST__HAD_NO_MATH_ERRNO
#endif

#elif !defined(MIST__TEMPLATE)

#ifndef MIST_H
#define MIST_H

#define MIST_VERSION_MAJOR 0
#define MIST_VERSION_MINOR 1
#define MIST_VERSION_PATCH 0
#define MIST_VERSION_STRING "0.1.0"

#include <math.h>
#include <float.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

/* EXCESS PRECISION (above) */
#if defined(FLT_EVAL_METHOD) && (FLT_EVAL_METHOD == 1 || FLT_EVAL_METHOD == 2) \
    && !defined(MIST_ALLOW_EXCESS_PRECISION)
#  error "mist.h: FLT_EVAL_METHOD is 1 or 2 (x87 math): build with -msse2 -mfpmath=sse, or define MIST_ALLOW_EXCESS_PRECISION (see EXCESS PRECISION in mist.h)"
#endif

/* The fast-math guard (see FAST MATH above): pushed here, popped at the
 * end of the file (the section "The fast-math guard" at the top). */
#define MIST__FP_PUSH
#include "mist.h"
#undef MIST__FP_PUSH

/* The configuration's implications (see CONFIGURATION above). */
#ifdef MIST_ONLY_HG
#  ifndef MIST_NO_DRAINE
#    define MIST_NO_DRAINE
#  endif
#  ifndef MIST_NO_RAYLEIGH
#    define MIST_NO_RAYLEIGH
#  endif
#  ifndef MIST_NO_TAB
#    define MIST_NO_TAB
#  endif
#endif
#if defined(MIST_NO_DRAINE) && !defined(MIST_NO_FOG)
#  define MIST_NO_FOG
#endif
#if (defined(MIST_NO_FOG) || defined(MIST_NO_RAYLEIGH)) && !defined(MIST_NO_HFOG)
#  define MIST_NO_HFOG
#endif

#ifndef MIST_FUNC
#  if defined(__CUDACC__)
#    define MIST_FUNC static inline __host__ __device__
#  else
#    define MIST_FUNC static inline
#    if defined(__GNUC__)
/* The kernels of the vectorised batch loops: gcc stops inlining in a large
 * translation unit (its unit-growth limits), and a loop that calls a
 * function does not vectorise (mist_phase_sample_nf: 40 against 11 ns an
 * element, measured in bench/mist_bench.c). */
#      define MIST__HOT __attribute__((always_inline))
#    endif
#  endif
#endif
#ifndef MIST__HOT
#  define MIST__HOT
#endif
/* The same for a public function (its callers' loops then hoist its work on
 * the parameters): not under gcc's fast-math guard, where forcing it into a
 * fast-math caller would compile it with the caller's flags (NaN input
 * then broke tests/test_domain.c in the fast-math variant). */
#if defined(MIST__FP_GUARD) && MIST__FP_GUARD == 2
#  define MIST__API_HOT
#else
#  define MIST__API_HOT MIST__HOT
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ------------------------------------------------------------------------ */
/* Types                                                                    */
/* ------------------------------------------------------------------------ */

typedef struct mist_vec3  { double x, y, z; } mist_vec3;
typedef struct mist_vec3f { float  x, y, z; } mist_vec3f;

/* The Jendersie-d'Eon fog phase function [JD23, eq. 1]:
 *   p(u) = (1 - w_d) HG(g_hg; u) + w_d Draine(g_d, alpha; u).
 * Build it with mist_fog_make (which sanitises the four parameters). */
typedef struct mist_fog  { double g_hg, g_d, alpha, w_d; } mist_fog;
typedef struct mist_fogf { float  g_hg, g_d, alpha, w_d; } mist_fogf;

/* A prepared phase function: everything that depends only on the medium's
 * parameters, computed once by mist_phase_hg / _draine / _cs / _rayleigh /
 * _fog, for mist_phase_eval / _sample / _sample_dir.  See "Prepared phase
 * functions".  The fields are internal: build it with those functions. */
#define MIST__PHASE_K 128       /* intervals of the prepared sampler's start table */
#ifndef MIST_DRAINE_PREPARE_N
#  define MIST_DRAINE_PREPARE_N 1024  /* see CONFIGURATION */
#endif
typedef struct mist_phase {
    int    kind;                /* 0, 2: (1 - w) HG(g_hg) + w Draine(g, alpha), in one
                                   lobe (0) or two (2); 1: Rayleigh */
    double g_hg, g, alpha, w;   /* sanitised */
    double ge, c0, c1, a1, b1, a2; /* density (a1 + b1 u^2)/V(ge)^3 (kind 0, 1), or
                                      w (a1 + b1 u^2)/V(ge)^3 + a2/V(g_hg)^3 (2);
                                      Draine's weights c0, c1 */
    double f0[4];               /* F_g(0), F_-g(0): hi + lo pairs */
    double tab[3 * MIST__PHASE_K + 2]; /* Draine's u(xi) at xi = j/K, slopes, and
                                          per interval a bound for one Newton step */
} mist_phase;
typedef struct mist_phasef {
    int    kind;
    float  g_hg, g, alpha, w;
    float  ge, c0, c1, a1, b1, a2;
    float  f0[4];
    float  tab[3 * MIST__PHASE_K + 2];
    double hg[3];               /* g_hg, 1 - g_hg, 2 (1 - g_hg)^2 in double: the HG
                                   sampler's terms of g (mist__hg_par) */
} mist_phasef;

/* A compact prepared phase function (see "Compact prepared phase functions"):
 * the fog mixture or Draine as mist_phase without its start table, 60 bytes in
 * float, for a GPU closure's registers or shared memory (mist_phasec_fog /
 * _draine, then mist_phasec_eval / _sample / _sample_dir).  The same fields
 * as mist_phase's first ones; internal: build it with those functions. */
typedef struct mist_phasec {
    int    kind;                /* 0, 2 (as mist_phase) */
    double g_hg, g, alpha, w;
    double ge, c0, c1, a1, b1, a2;
    double f0[4];
} mist_phasec;
typedef struct mist_phasecf {
    int    kind;
    float  g_hg, g, alpha, w;
    float  ge, c0, c1, a1, b1, a2;
    float  f0[4];
} mist_phasecf;

/* A tabulated phase function (see "Tabulated phase functions"): this
 * header, then its arrays, in the caller's memory (mist_tab_bytes bytes,
 * aligned as for a double: malloc's).  Built by mist_tab_init; the fields
 * are internal.  The float and double tables have one layout (their
 * arrays are double in both), and a built table holds no pointer: it may
 * be copied byte for byte (to a GPU, to a file). */
#define MIST__TAB_FIELDS                                                       \
    uint32_t magic;             /* MIST__TAB_OK built, MIST__TAB_BAD failed */ \
    int      channels;                                                         \
    size_t   n;                 /* nodes; n - 1 cells, n - 1 guide buckets */  \
    size_t   klo, khi;          /* first and last cell of positive mass */     \
    size_t   o_mu, o_f, o_F, o_q, o_kc, o_gx, o_gm, o_ih; /* the arrays'      \
                                   byte offsets from the table's start */       \
    double   tot[2];            /* the sampling density's integral, hi + lo */ \
    double   norm;              /* 1 / (2 pi tot) */
typedef struct mist_tab  { MIST__TAB_FIELDS } mist_tab;
typedef struct mist_tabf { MIST__TAB_FIELDS } mist_tabf;
#undef MIST__TAB_FIELDS
#define MIST__TAB_OK  0x6d746162u   /* the magic of a built table */
#define MIST__TAB_BAD 0x6d74625fu   /* of one whose mist_tab_init failed */
/* mist_tab_init's errors (0 is success) */
#define MIST_TAB_EINVAL (-1)  /* a NULL pointer, n < 2, channels outside [1, 64] */
#define MIST_TAB_ESIZE  (-2)  /* bytes < mist_tab_bytes(n, channels), or n >= 2^32 */
#define MIST_TAB_EMU    (-3)  /* mu not strictly increasing from -1 to 1 (NaN too) */
#define MIST_TAB_EVALUE (-4)  /* a value p NaN, infinite or negative */
#define MIST_TAB_EZERO  (-5)  /* a channel all zero (or its integral underflows) */

/* A linear RGB triple: radiance, or a coefficient per colour band. */
typedef struct mist_rgb  { double r, g, b; } mist_rgb;
typedef struct mist_rgbf { float  r, g, b; } mist_rgbf;

/* The analytic height fog [I18]: see "Analytic height fog" below.  The
 * extinction and scattering coefficient of each component at height y is
 * its coefficient here times density * exp(-(y - base) / scale_height);
 * height is the coordinate along `up` (all zero: the y coordinate).  The
 * fields after sun_extinction are optional (zero, NULL: as before): a
 * positional initialiser of the others keeps working. */
typedef struct mist_hfog {
    double    base;           /* reference height */
    double    density;        /* density at the base (>= 0) */
    double    scale_height;   /* H > 0 (+inf: uniform fog) */
    mist_rgb  rayleigh_scat;  /* Rayleigh scattering, per unit length */
    mist_rgb  rayleigh_ext;   /* Rayleigh extinction (raised to >= scat) */
    mist_rgb  mie_scat;       /* Mie scattering */
    mist_rgb  mie_ext;        /* Mie extinction (raised to >= scat) */
    mist_fog  mie_phase;      /* Mie phase function (mist_fog_make) */
    mist_vec3 sun_dir;        /* towards the sun */
    mist_rgb  sun;            /* sun irradiance (radiance x solid angle) */
    mist_rgb  ambient;        /* isotropic ambient radiance */
    int       sun_extinction; /* nonzero: the fog dims the sun too */
    mist_vec3 up;             /* the height axis, unit (all zero: y) */
    const mist_phase *mie_prepared; /* non-NULL: the Mie phase function
                                       (mist_phase_*), not mie_phase */
    const mist_tab   *mie_tab;      /* non-NULL: a tabulated one (each channel
                                       its own where it has 3), before both */
} mist_hfog;
typedef struct mist_hfogf {
    float      base, density, scale_height;
    mist_rgbf  rayleigh_scat, rayleigh_ext, mie_scat, mie_ext;
    mist_fogf  mie_phase;
    mist_vec3f sun_dir;
    mist_rgbf  sun, ambient;
    int        sun_extinction;
    mist_vec3f up;
    const mist_phasef *mie_prepared;
    const mist_tabf   *mie_tab;
} mist_hfogf;

/* 1/(4 pi), 3/(16 pi), 2 pi */
#define MIST__INV4PI  0.0795774715459476678844418816862571810
#define MIST__3_16PI  0.0596831036594607509133314112646928858
#define MIST__2PI     6.28318530717958647692528676655900577

/* [JD23 eq. 6] as printed, in double: only a starting point for the exact
 * Draine sampler (it cancels as 1/g^3 and is NaN at g = 0 or alpha = 0;
 * see "Draine and Cornette-Shanks: exact sampling").  Its divisions are
 * moved off the chain of dependent operations, for latency: t6 / t7 as
 * t6 t7^2 / s (s = t7^3 > 0, its division runs beside the cbrt), 8 t4 /
 * (t0 t9) as 8 t4 t9 / (t0 t9^2) (beside the sqrt), 2 / t0 once.  The same
 * value to a few ulps, and the unprepared samplers ~0.9x the time with the
 * form as printed (float samples bit for bit the same over 2e6 random
 * inputs, double ones within the bar). */
#ifndef MIST_NO_DRAINE
/* cbrt for eq. 6 below: its latency, not glibc's (23.8 against 13.7 ns in
 * a chain of dependent calls, x86 -O2 -march=native; 25.7 against 18.2
 * without -march), within 4.6 ulp (glibc's: 3.3; 2e7 random normal
 * arguments against cbrtq, measured).  s = m 2^e, m in [1, 2), e = 3k + r:
 * y ~ m^(-1/3) by a degree-5 Chebyshev fit on [1, 2) (6.5e-6), corrected
 * to third order in e = 1 - m y^3 (error ~ (35/243) e^4, below double's
 * rounding; no division), then cbrt(s) = m y^2 2^(r/3) 2^k.  Zero,
 * subnormal, negative, inf and NaN go to libm; CUDA device code always. */
MIST_FUNC MIST__HOT double mist__cbrt_m(double s)   /* s positive and normal */
{
    uint64_t b;
    unsigned ex;
    int k, r;
    double m, m2, y, e, sc;
    memcpy(&b, &s, sizeof b);
    ex = (unsigned)(b >> 52);
    k = ((int)ex - 1023 + 1023) / 3 - 341;         /* floor((ex - 1023) / 3) */
    r = (int)ex - 1023 - 3 * k;
    b = (b & (((uint64_t)1 << 52) - 1)) | ((uint64_t)1023 << 52);   /* (C++98: no ull) */
    memcpy(&m, &b, sizeof m);
    m2 = m * m;
    y = (1.77764716848900541601 - 1.55402740771065980698 * m)
        + m2 * (1.22714962002071539165 - 0.586514161588980599019 * m)
        + (m2 * m2) * (0.152249564382217635674 - 0.0165116790912864630493 * m);
    e = 1 - (m * (y * y)) * y;
    y = y + (y * e) * (1.0 / 3 + e * (2.0 / 9 + e * (14.0 / 81)));
    b = (uint64_t)(k + 1023) << 52;                /* 2^k, k in [-341, 341] */
    memcpy(&sc, &b, sizeof sc);
    return ((m * y) * y) * ((r == 0 ? 1.0 : r == 1 ? 1.259921049894873164767211
                                                   : 1.587401051968199474751706) * sc);
}
/* 1 where s is not positive and normal: zero, subnormal, negative, inf, NaN */
MIST_FUNC MIST__HOT int mist__cbrt_odd(double s)
{
    uint64_t b;
    memcpy(&b, &s, sizeof b);
    return (unsigned)(b >> 52) - 1u >= 2046u;      /* the sign bit makes it > 2046 */
}
MIST_FUNC double mist__cbrt(double s)
{
#if !defined(__CUDA_ARCH__)
    return mist__cbrt_odd(s) ? cbrt(s) : mist__cbrt_m(s);
#else
    return cbrt(s);
#endif
}

MIST_FUNC MIST__HOT double mist__draine_eq6x(double g, double alpha, double xi, int vec,
                                             int *odd)
{
    double g2 = g * g, g4 = g2 * g2;
    double t0 = alpha - alpha * g2;
    double t1 = alpha * g4 - alpha;
    double t2 = -3 * (4 * (g4 - g2) + t1 * (1 + g2));
    double t3 = g * (2 * xi - 1);
    double t4 = 3 * g2 * (1 + t3) + alpha * (2 + g2 * (1 + (1 + 2 * g2) * t3));
    double t5 = t0 * (t1 * t2 + t4 * t4) + t1 * t1 * t1;
    double t6 = t0 * 4 * (g4 - g2), i0 = 2 / t0;
    double s  = t5 + sqrt(t5 * t5 - t6 * t6 * t6);
    double t7 = vec ? mist__cbrt_m(s) : mist__cbrt(s), r6 = t6 / s;
    double t8 = (t1 + r6 * t7 * t7 + t7) * i0;
    double y  = 6 * (1 + g2) + t8, q = 4 * t4 * i0 / y;
    double t9 = sqrt(y);
    double w = sqrt(6 * (1 + g2) - t8 + q * t9) - t9;
    *odd = mist__cbrt_odd(s);
    return g / 2 + (1 / (2 * g) - 1 / (8 * g) * w * w);
}
MIST_FUNC double mist__draine_eq6(double g, double alpha, double xi)
{
    int odd;
    return mist__draine_eq6x(g, alpha, xi, 0, &odd);
}
#endif /* !MIST_NO_DRAINE */

/* ------------------------------------------------------------------------ */
/* The passes: the body below is compiled once per type.                    */
/*  - long double, internal formulas only: the wide type of the double       */
/*    Draine samplers' final Newton step, where long double is wider than   */
/*    double (x86: 64-bit significand) and fma no instruction.  Elsewhere   */
/*    (fma; MSVC, Apple, CUDA device code) they finish in double-double.    */
/*  - double (plain names), wide type long double;                           */
/*  - float ('f' suffix), wide type double.                                  */
/* ------------------------------------------------------------------------ */
#define MIST__TEMPLATE 1

#if LDBL_MANT_DIG > DBL_MANT_DIG && !defined(MIST_NO_LONG_DOUBLE)
#  define MIST__HAVE_LD 1
#  define MIST__INTERNAL_ONLY 1
#  define MIST__F     static inline           /* host only: never on a GPU */
#  define MIST__T     long double
#  define MIST__FN(n) n##l
#  define MIST__M(fn) fn##l
#  include "mist.h"
#  undef MIST__INTERNAL_ONLY
#  undef MIST__F
#  undef MIST__T
#  undef MIST__FN
#  undef MIST__M
#endif

#define MIST__F     MIST_FUNC
#define MIST__T     double
#define MIST__FN(n) n
#define MIST__M(fn) fn
#define MIST__EPS   (DBL_EPSILON * 0.5)       /* unit roundoff 2^-53 */
#define MIST__DBL   1                         /* the double pass (an int: no float
                                                 compared with a double) */
#define MIST__MAXIT 64                        /* bisection worst case: 2^-60 */
#define MIST__V3    mist_vec3
#define MIST__FOG   mist_fog
#define MIST__UB    uint64_t                  /* the bits of T: */
#define MIST__MB    52                        /*  its mantissa's, */
#define MIST__EB    2047                      /*  its exponent field's all-ones */
/* fma is one instruction: FP_FAST_FMA (gcc), or the target's fma feature
 * macro (clang defines no FP_FAST_FMA; gcc and clang inline fma() there) */
#if defined(FP_FAST_FMA) || defined(__FMA__) || defined(__ARM_FEATURE_FMA)
#  define MIST__FAST_FMA 1
#endif
#if defined(MIST__HAVE_LD) && !defined(__CUDA_ARCH__)
#  define MIST__W      long double
#  define MIST__WFN(n) n##l
#endif
#include "mist.h"
#undef MIST__T
#undef MIST__FN
#undef MIST__M
#undef MIST__EPS
#undef MIST__DBL
#undef MIST__MAXIT
#undef MIST__V3
#undef MIST__FOG
#undef MIST__UB
#undef MIST__MB
#undef MIST__EB
#undef MIST__FAST_FMA
#undef MIST__W
#undef MIST__WFN

#define MIST__T     float
#define MIST__FN(n) n##f
#define MIST__M(fn) fn##f
#define MIST__EPS   (FLT_EPSILON * 0.5f)      /* unit roundoff 2^-24 */
#define MIST__DBL   0
#define MIST__MAXIT 32
#define MIST__V3    mist_vec3f
#define MIST__FOG   mist_fogf
#define MIST__UB    uint32_t
#define MIST__MB    23
#define MIST__EB    255
#if defined(FP_FAST_FMAF)
#  define MIST__FAST_FMA 1
#endif
#define MIST__W      double
#define MIST__WFN(n) n
#define MIST__W_EXACT 1   /* products of two T, and 1 - xi, exact in W */
#include "mist.h"
#undef MIST__W_EXACT
#undef MIST__T
#undef MIST__FN
#undef MIST__M
#undef MIST__EPS
#undef MIST__DBL
#undef MIST__MAXIT
#undef MIST__V3
#undef MIST__FOG
#undef MIST__UB
#undef MIST__MB
#undef MIST__EB
#undef MIST__FAST_FMA
#undef MIST__W
#undef MIST__WFN
#undef MIST__F

#undef MIST__TEMPLATE

/* ======================================================================== */
/* THE API: every public function in plain C, double then float (the same  */
/* name + f).  Each forwards to its one type-generic definition,            */
/* mist__impl_NAME, in the body below, whose section names the paper and   */
/* equation, the reformulation and its bound.  Domain and bad input: the    */
/* top of the file.                                                         */
/* ======================================================================== */
#define MIST__API MIST_FUNC MIST__API_HOT

/* Henyey-Greenstein [HG41]: the density per steradian at the cosine u, and the exact
 * inverse CDF at xi (u = cos theta between propagation directions) */
MIST__API double mist_hg_eval(double g, double u) { return mist__impl_hg_eval(g, u); }
MIST__API float mist_hg_evalf(float g, float u) { return mist__impl_hg_evalf(g, u); }
MIST__API double mist_hg_sample(double g, double xi) { return mist__impl_hg_sample(g, xi); }
MIST__API float mist_hg_samplef(float g, float xi) { return mist__impl_hg_samplef(g, xi); }

/* Cornette-Shanks [CS92]: Draine at alpha = 1 */
#ifndef MIST_NO_DRAINE
MIST__API double mist_cs_eval(double g, double u) { return mist__impl_cs_eval(g, u); }
MIST__API float mist_cs_evalf(float g, float u) { return mist__impl_cs_evalf(g, u); }
MIST__API double mist_cs_sample(double g, double xi) { return mist__impl_cs_sample(g, xi); }
MIST__API float mist_cs_samplef(float g, float xi) { return mist__impl_cs_samplef(g, xi); }
#endif

/* Draine [D03]: HG (1 + alpha u^2) / (1 + alpha (1 + 2 g^2) / 3) */
#ifndef MIST_NO_DRAINE
MIST__API double mist_draine_eval(double g, double alpha, double u)
    { return mist__impl_draine_eval(g, alpha, u); }
MIST__API float mist_draine_evalf(float g, float alpha, float u)
    { return mist__impl_draine_evalf(g, alpha, u); }
MIST__API double mist_draine_sample(double g, double alpha, double xi)
    { return mist__impl_draine_sample(g, alpha, xi); }
MIST__API float mist_draine_samplef(float g, float alpha, float xi)
    { return mist__impl_draine_samplef(g, alpha, xi); }
#endif

/* Rayleigh: 3 / (16 pi) (1 + u^2) */
#ifndef MIST_NO_RAYLEIGH
MIST__API double mist_rayleigh_eval(double u) { return mist__impl_rayleigh_eval(u); }
MIST__API float mist_rayleigh_evalf(float u) { return mist__impl_rayleigh_evalf(u); }
MIST__API double mist_rayleigh_sample(double xi) { return mist__impl_rayleigh_sample(xi); }
MIST__API float mist_rayleigh_samplef(float xi) { return mist__impl_rayleigh_samplef(xi); }
#endif

/* The fog mix [JD23 eq. 1]: (1 - w_d) HG(g_hg) + w_d Draine(g_d, alpha); one xi picks
 * the lobe, then samples it.  mist_fog_from_diameter: the fits [JD23 eq. 7-22], d in um */
#ifndef MIST_NO_FOG
MIST__API mist_fog mist_fog_make(double g_hg, double g_d, double alpha, double w_d)
    { return mist__impl_fog_make(g_hg, g_d, alpha, w_d); }
MIST__API mist_fogf mist_fog_makef(float g_hg, float g_d, float alpha, float w_d)
    { return mist__impl_fog_makef(g_hg, g_d, alpha, w_d); }
MIST__API double mist_fog_eval(mist_fog fog, double u) { return mist__impl_fog_eval(fog, u); }
MIST__API float mist_fog_evalf(mist_fogf fog, float u) { return mist__impl_fog_evalf(fog, u); }
MIST__API double mist_fog_sample(mist_fog fog, double xi)
    { return mist__impl_fog_sample(fog, xi); }
MIST__API float mist_fog_samplef(mist_fogf fog, float xi)
    { return mist__impl_fog_samplef(fog, xi); }
MIST__API mist_fog mist_fog_from_diameter(double d) { return mist__impl_fog_from_diameter(d); }
MIST__API mist_fogf mist_fog_from_diameterf(float d) { return mist__impl_fog_from_diameterf(d); }
/* The fog mix fitted to Lorenz-Mie (water, 450-650 nm, lognormal width 1.1) at 0.01-50 um,
 * continuous in d: a table in log d, monotone cubic interpolation */
MIST__API mist_fog mist_fog_from_diameter_mie(double d)
    { return mist__impl_fog_from_diameter_mie(d); }
MIST__API mist_fogf mist_fog_from_diameter_mief(float d)
    { return mist__impl_fog_from_diameter_mief(d); }
#endif

/* Prepared phase functions: build once per medium, then evaluate and sample through a
 * pointer (the same results to a few ulps, less work; NULL is isotropic) */
#ifndef MIST_NO_FOG
MIST__API mist_phase mist_phase_hg(double g) { return mist__impl_phase_hg(g); }
MIST__API mist_phasef mist_phase_hgf(float g) { return mist__impl_phase_hgf(g); }
MIST__API mist_phase mist_phase_cs(double g) { return mist__impl_phase_cs(g); }
MIST__API mist_phasef mist_phase_csf(float g) { return mist__impl_phase_csf(g); }
MIST__API mist_phase mist_phase_draine(double g, double alpha)
    { return mist__impl_phase_draine(g, alpha); }
MIST__API mist_phasef mist_phase_drainef(float g, float alpha)
    { return mist__impl_phase_drainef(g, alpha); }
#endif
#if !defined(MIST_NO_FOG) && !defined(MIST_NO_RAYLEIGH)
MIST__API mist_phase mist_phase_rayleigh(void) { return mist__impl_phase_rayleigh(); }
MIST__API mist_phasef mist_phase_rayleighf(void) { return mist__impl_phase_rayleighf(); }
#endif
#ifndef MIST_NO_FOG
MIST__API mist_phase mist_phase_fog(mist_fog fog) { return mist__impl_phase_fog(fog); }
MIST__API mist_phasef mist_phase_fogf(mist_fogf fog) { return mist__impl_phase_fogf(fog); }
MIST__API double mist_phase_eval(const mist_phase *p, double u)
    { return mist__impl_phase_eval(p, u); }
MIST__API float mist_phase_evalf(const mist_phasef *p, float u)
    { return mist__impl_phase_evalf(p, u); }
MIST__API double mist_phase_sample(const mist_phase *p, double xi)
    { return mist__impl_phase_sample(p, xi); }
MIST__API float mist_phase_samplef(const mist_phasef *p, float xi)
    { return mist__impl_phase_samplef(p, xi); }
/* Compact prepared: the fog or Draine without the start table (60 bytes in float) */
MIST__API mist_phasec mist_phasec_fog(mist_fog fog) { return mist__impl_phasec_fog(fog); }
MIST__API mist_phasecf mist_phasec_fogf(mist_fogf fog) { return mist__impl_phasec_fogf(fog); }
MIST__API mist_phasec mist_phasec_draine(double g, double alpha)
    { return mist__impl_phasec_draine(g, alpha); }
MIST__API mist_phasecf mist_phasec_drainef(float g, float alpha)
    { return mist__impl_phasec_drainef(g, alpha); }
MIST__API double mist_phasec_eval(const mist_phasec *p, double u)
    { return mist__impl_phasec_eval(p, u); }
MIST__API float mist_phasec_evalf(const mist_phasecf *p, float u)
    { return mist__impl_phasec_evalf(p, u); }
MIST__API double mist_phasec_sample(const mist_phasec *p, double xi)
    { return mist__impl_phasec_sample(p, xi); }
MIST__API float mist_phasec_samplef(const mist_phasecf *p, float xi)
    { return mist__impl_phasec_samplef(p, xi); }
#endif

/* Directions: a scattered direction about the propagation direction wi (any non-zero
 * length), u from xi1 and the azimuth from xi2; *pdf = the density at it (may be NULL) */
MIST__API mist_vec3 mist_normalize(mist_vec3 v) { return mist__impl_normalize(v); }
MIST__API mist_vec3f mist_normalizef(mist_vec3f v) { return mist__impl_normalizef(v); }
#ifndef MIST_NO_DIR
MIST__API mist_vec3 mist_dir_from_cos(mist_vec3 wi, double u, double xi)
    { return mist__impl_dir_from_cos(wi, u, xi); }
MIST__API mist_vec3f mist_dir_from_cosf(mist_vec3f wi, float u, float xi)
    { return mist__impl_dir_from_cosf(wi, u, xi); }
MIST__API mist_vec3 mist_hg_sample_dir(double g, mist_vec3 wi, double xi1, double xi2, double *pdf)
    { return mist__impl_hg_sample_dir(g, wi, xi1, xi2, pdf); }
MIST__API mist_vec3f mist_hg_sample_dirf(float g, mist_vec3f wi, float xi1, float xi2, float *pdf)
    { return mist__impl_hg_sample_dirf(g, wi, xi1, xi2, pdf); }
#endif
#if !defined(MIST_NO_DIR) && !defined(MIST_NO_DRAINE)
MIST__API mist_vec3 mist_cs_sample_dir(double g, mist_vec3 wi, double xi1, double xi2, double *pdf)
    { return mist__impl_cs_sample_dir(g, wi, xi1, xi2, pdf); }
MIST__API mist_vec3f mist_cs_sample_dirf(float g, mist_vec3f wi, float xi1, float xi2, float *pdf)
    { return mist__impl_cs_sample_dirf(g, wi, xi1, xi2, pdf); }
MIST__API mist_vec3 mist_draine_sample_dir(double g, double alpha, mist_vec3 wi, double xi1,
                                           double xi2, double *pdf)
    { return mist__impl_draine_sample_dir(g, alpha, wi, xi1, xi2, pdf); }
MIST__API mist_vec3f mist_draine_sample_dirf(float g, float alpha, mist_vec3f wi, float xi1,
                                             float xi2, float *pdf)
    { return mist__impl_draine_sample_dirf(g, alpha, wi, xi1, xi2, pdf); }
#endif
#if !defined(MIST_NO_DIR) && !defined(MIST_NO_RAYLEIGH)
MIST__API mist_vec3 mist_rayleigh_sample_dir(mist_vec3 wi, double xi1, double xi2, double *pdf)
    { return mist__impl_rayleigh_sample_dir(wi, xi1, xi2, pdf); }
MIST__API mist_vec3f mist_rayleigh_sample_dirf(mist_vec3f wi, float xi1, float xi2, float *pdf)
    { return mist__impl_rayleigh_sample_dirf(wi, xi1, xi2, pdf); }
#endif
#if !defined(MIST_NO_DIR) && !defined(MIST_NO_FOG)
MIST__API mist_vec3 mist_fog_sample_dir(mist_fog fog, mist_vec3 wi, double xi1, double xi2,
                                        double *pdf)
    { return mist__impl_fog_sample_dir(fog, wi, xi1, xi2, pdf); }
MIST__API mist_vec3f mist_fog_sample_dirf(mist_fogf fog, mist_vec3f wi, float xi1, float xi2,
                                          float *pdf)
    { return mist__impl_fog_sample_dirf(fog, wi, xi1, xi2, pdf); }
#endif
#if !defined(MIST_NO_FOG) && !defined(MIST_NO_DIR)
MIST__API mist_vec3 mist_phase_sample_dir(const mist_phase *p, mist_vec3 wi, double xi1,
                                          double xi2, double *pdf)
    { return mist__impl_phase_sample_dir(p, wi, xi1, xi2, pdf); }
MIST__API mist_vec3f mist_phase_sample_dirf(const mist_phasef *p, mist_vec3f wi, float xi1,
                                            float xi2, float *pdf)
    { return mist__impl_phase_sample_dirf(p, wi, xi1, xi2, pdf); }
MIST__API mist_vec3 mist_phasec_sample_dir(const mist_phasec *p, mist_vec3 wi, double xi1,
                                           double xi2, double *pdf)
    { return mist__impl_phasec_sample_dir(p, wi, xi1, xi2, pdf); }
MIST__API mist_vec3f mist_phasec_sample_dirf(const mist_phasecf *p, mist_vec3f wi, float xi1,
                                             float xi2, float *pdf)
    { return mist__impl_phasec_sample_dirf(p, wi, xi1, xi2, pdf); }
#endif

/* Batch forms: out[i] = the scalar function of in[i] for i < n, bit for bit; out may
 * equal in (no other overlap); n = 0 does nothing */
#ifndef MIST_NO_BATCH
MIST__API void mist_hg_eval_n(double g, const double *in, double *out, size_t n)
    { mist__impl_hg_eval_n(g, in, out, n); }
MIST__API void mist_hg_eval_nf(float g, const float *in, float *out, size_t n)
    { mist__impl_hg_eval_nf(g, in, out, n); }
MIST__API void mist_hg_sample_n(double g, const double *in, double *out, size_t n)
    { mist__impl_hg_sample_n(g, in, out, n); }
MIST__API void mist_hg_sample_nf(float g, const float *in, float *out, size_t n)
    { mist__impl_hg_sample_nf(g, in, out, n); }
#endif
#if !defined(MIST_NO_BATCH) && !defined(MIST_NO_DRAINE)
MIST__API void mist_draine_eval_n(double g, double alpha, const double *in, double *out, size_t n)
    { mist__impl_draine_eval_n(g, alpha, in, out, n); }
MIST__API void mist_draine_eval_nf(float g, float alpha, const float *in, float *out, size_t n)
    { mist__impl_draine_eval_nf(g, alpha, in, out, n); }
MIST__API void mist_draine_sample_n(double g, double alpha, const double *in, double *out,
                                    size_t n)
    { mist__impl_draine_sample_n(g, alpha, in, out, n); }
MIST__API void mist_draine_sample_nf(float g, float alpha, const float *in, float *out, size_t n)
    { mist__impl_draine_sample_nf(g, alpha, in, out, n); }
#endif
#if !defined(MIST_NO_BATCH) && !defined(MIST_NO_RAYLEIGH)
MIST__API void mist_rayleigh_eval_n(const double *in, double *out, size_t n)
    { mist__impl_rayleigh_eval_n(in, out, n); }
MIST__API void mist_rayleigh_eval_nf(const float *in, float *out, size_t n)
    { mist__impl_rayleigh_eval_nf(in, out, n); }
MIST__API void mist_rayleigh_sample_n(const double *in, double *out, size_t n)
    { mist__impl_rayleigh_sample_n(in, out, n); }
MIST__API void mist_rayleigh_sample_nf(const float *in, float *out, size_t n)
    { mist__impl_rayleigh_sample_nf(in, out, n); }
#endif
#if !defined(MIST_NO_BATCH) && !defined(MIST_NO_FOG)
MIST__API void mist_phase_eval_n(const mist_phase *p, const double *in, double *out, size_t n)
    { mist__impl_phase_eval_n(p, in, out, n); }
MIST__API void mist_phase_eval_nf(const mist_phasef *p, const float *in, float *out, size_t n)
    { mist__impl_phase_eval_nf(p, in, out, n); }
MIST__API void mist_phase_sample_n(const mist_phase *p, const double *in, double *out, size_t n)
    { mist__impl_phase_sample_n(p, in, out, n); }
MIST__API void mist_phase_sample_nf(const mist_phasef *p, const float *in, float *out, size_t n)
    { mist__impl_phase_sample_nf(p, in, out, n); }
MIST__API void mist_fog_eval_n(mist_fog fog, const double *in, double *out, size_t n)
    { mist__impl_fog_eval_n(fog, in, out, n); }
MIST__API void mist_fog_eval_nf(mist_fogf fog, const float *in, float *out, size_t n)
    { mist__impl_fog_eval_nf(fog, in, out, n); }
MIST__API void mist_fog_sample_n(mist_fog fog, const double *in, double *out, size_t n)
    { mist__impl_fog_sample_n(fog, in, out, n); }
MIST__API void mist_fog_sample_nf(mist_fogf fog, const float *in, float *out, size_t n)
    { mist__impl_fog_sample_nf(fog, in, out, n); }
#endif

/* Analytic height fog [I18] along origin + t dir, 0 <= t <= length (+inf allowed):
 * transmittance T, in-scattered light L, a background B seen as B T + L; the optical
 * column of the density from height y along vertical cosine w; for path tracers the
 * extinction at a point, the optical depth to t and a free-flight distance of channel
 * 0, 1, 2 (r, g, b) sampled exactly (+inf: none before tmax); several layers, with a
 * bound on the in-scatter's error */
#ifndef MIST_NO_HFOG
MIST__API mist_rgb mist_hfog_transmittance(const mist_hfog *fog, mist_vec3 origin, mist_vec3 dir,
                                           double length)
    { return mist__impl_hfog_transmittance(fog, origin, dir, length); }
MIST__API mist_rgbf mist_hfog_transmittancef(const mist_hfogf *fog, mist_vec3f origin,
                                             mist_vec3f dir, float length)
    { return mist__impl_hfog_transmittancef(fog, origin, dir, length); }
MIST__API mist_rgb mist_hfog_inscatter(const mist_hfog *fog, mist_vec3 origin, mist_vec3 dir,
                                       double length)
    { return mist__impl_hfog_inscatter(fog, origin, dir, length); }
MIST__API mist_rgbf mist_hfog_inscatterf(const mist_hfogf *fog, mist_vec3f origin, mist_vec3f dir,
                                         float length)
    { return mist__impl_hfog_inscatterf(fog, origin, dir, length); }
MIST__API mist_rgb mist_hfog_apply(const mist_hfog *fog, mist_vec3 origin, mist_vec3 dir,
                                   double length, mist_rgb background)
    { return mist__impl_hfog_apply(fog, origin, dir, length, background); }
MIST__API mist_rgbf mist_hfog_applyf(const mist_hfogf *fog, mist_vec3f origin, mist_vec3f dir,
                                     float length, mist_rgbf background)
    { return mist__impl_hfog_applyf(fog, origin, dir, length, background); }
#ifndef MIST_NO_BATCH
MIST__API void mist_hfog_apply_n(const mist_hfog *fog, const mist_vec3 *origin, const mist_vec3 *dir,
                                 const double *length, const mist_rgb *background, mist_rgb *out,
                                 size_t n)
    { mist__impl_hfog_apply_n(fog, origin, dir, length, background, out, n); }
MIST__API void mist_hfog_apply_nf(const mist_hfogf *fog, const mist_vec3f *origin,
                                  const mist_vec3f *dir, const float *length,
                                  const mist_rgbf *background, mist_rgbf *out, size_t n)
    { mist__impl_hfog_apply_nf(fog, origin, dir, length, background, out, n); }
#endif
MIST__API void mist_hfog_eval(const mist_hfog *fog, mist_vec3 origin, mist_vec3 dir,
                              double length, mist_rgb *transmittance, mist_rgb *inscatter)
    { mist__impl_hfog_eval(fog, origin, dir, length, transmittance, inscatter); }
MIST__API void mist_hfog_evalf(const mist_hfogf *fog, mist_vec3f origin, mist_vec3f dir,
                               float length, mist_rgbf *transmittance, mist_rgbf *inscatter)
    { mist__impl_hfog_evalf(fog, origin, dir, length, transmittance, inscatter); }
MIST__API double mist_hfog_column(const mist_hfog *fog, double y, double w, double length)
    { return mist__impl_hfog_column(fog, y, w, length); }
MIST__API float mist_hfog_columnf(const mist_hfogf *fog, float y, float w, float length)
    { return mist__impl_hfog_columnf(fog, y, w, length); }
MIST__API mist_rgb mist_hfog_extinction(const mist_hfog *fog, mist_vec3 p)
    { return mist__impl_hfog_extinction(fog, p); }
MIST__API mist_rgbf mist_hfog_extinctionf(const mist_hfogf *fog, mist_vec3f p)
    { return mist__impl_hfog_extinctionf(fog, p); }
MIST__API mist_rgb mist_hfog_optical_depth(const mist_hfog *fog, mist_vec3 origin, mist_vec3 dir,
                                           double t)
    { return mist__impl_hfog_optical_depth(fog, origin, dir, t); }
MIST__API mist_rgbf mist_hfog_optical_depthf(const mist_hfogf *fog, mist_vec3f origin,
                                             mist_vec3f dir, float t)
    { return mist__impl_hfog_optical_depthf(fog, origin, dir, t); }
MIST__API double mist_hfog_sample_distance(const mist_hfog *fog, mist_vec3 origin, mist_vec3 dir,
                                           double tmax, int channel, double xi)
    { return mist__impl_hfog_sample_distance(fog, origin, dir, tmax, channel, xi); }
MIST__API float mist_hfog_sample_distancef(const mist_hfogf *fog, mist_vec3f origin,
                                           mist_vec3f dir, float tmax, int channel, float xi)
    { return mist__impl_hfog_sample_distancef(fog, origin, dir, tmax, channel, xi); }
MIST__API void mist_hfog_layers_eval(const mist_hfog *layers, int n, mist_vec3 origin,
                                     mist_vec3 dir, double length, int pieces,
                                     mist_rgb *transmittance, mist_rgb *inscatter, mist_rgb *bound)
    { mist__impl_hfog_layers_eval(layers, n, origin, dir, length, pieces, transmittance,
                                  inscatter, bound); }
MIST__API void mist_hfog_layers_evalf(const mist_hfogf *layers, int n, mist_vec3f origin,
                                      mist_vec3f dir, float length, int pieces,
                                      mist_rgbf *transmittance, mist_rgbf *inscatter,
                                      mist_rgbf *bound)
    { mist__impl_hfog_layers_evalf(layers, n, origin, dir, length, pieces, transmittance,
                                   inscatter, bound); }
#endif

/* Tabulated phase functions: n cosines mu (rising from -1 to 1) and channels values each,
 * linear in mu per channel and normalised exactly, in the caller's bytes; evaluated and
 * sampled by the exact inverse CDF of the channels' mean in O(1) (docs/tables.md) */
#ifndef MIST_NO_TAB
MIST__API size_t mist_tab_bytes(size_t n, int channels)
    { return mist__impl_tab_bytes(n, channels); }
MIST__API size_t mist_tab_bytesf(size_t n, int channels)
    { return mist__impl_tab_bytesf(n, channels); }
MIST__API int mist_tab_init(mist_tab *t, size_t bytes, const double *mu, const double *p,
                            size_t n, int channels)
    { return mist__impl_tab_init(t, bytes, mu, p, n, channels); }
MIST__API int mist_tab_initf(mist_tabf *t, size_t bytes, const float *mu, const float *p,
                             size_t n, int channels)
    { return mist__impl_tab_initf(t, bytes, mu, p, n, channels); }
MIST__API double mist_tab_eval(const mist_tab *t, double u, double *channel)
    { return mist__impl_tab_eval(t, u, channel); }
MIST__API float mist_tab_evalf(const mist_tabf *t, float u, float *channel)
    { return mist__impl_tab_evalf(t, u, channel); }
MIST__API double mist_tab_sample(const mist_tab *t, double xi)
    { return mist__impl_tab_sample(t, xi); }
MIST__API float mist_tab_samplef(const mist_tabf *t, float xi)
    { return mist__impl_tab_samplef(t, xi); }
#endif
#if !defined(MIST_NO_TAB) && !defined(MIST_NO_DIR)
MIST__API mist_vec3 mist_tab_sample_dir(const mist_tab *t, mist_vec3 wi, double xi1, double xi2,
                                        double *pdf)
    { return mist__impl_tab_sample_dir(t, wi, xi1, xi2, pdf); }
MIST__API mist_vec3f mist_tab_sample_dirf(const mist_tabf *t, mist_vec3f wi, float xi1, float xi2,
                                          float *pdf)
    { return mist__impl_tab_sample_dirf(t, wi, xi1, xi2, pdf); }
#endif
#if !defined(MIST_NO_TAB) && !defined(MIST_NO_BATCH)
MIST__API void mist_tab_eval_n(const mist_tab *t, const double *in, double *out, size_t n)
    { mist__impl_tab_eval_n(t, in, out, n); }
MIST__API void mist_tab_eval_nf(const mist_tabf *t, const float *in, float *out, size_t n)
    { mist__impl_tab_eval_nf(t, in, out, n); }
MIST__API void mist_tab_sample_n(const mist_tab *t, const double *in, double *out, size_t n)
    { mist__impl_tab_sample_n(t, in, out, n); }
MIST__API void mist_tab_sample_nf(const mist_tabf *t, const float *in, float *out, size_t n)
    { mist__impl_tab_sample_nf(t, in, out, n); }
#endif

/* A ray-marching step [B08]: extinction linear from k0 to k1 and source from s0 to s1
 * over length; returns the in-scatter, *transmittance the step's */
#ifndef MIST_NO_HFOG
MIST__API double mist_segment_linear(double k0, double k1, double s0, double s1, double length,
                                     double *transmittance)
    { return mist__impl_segment_linear(k0, k1, s0, s1, length, transmittance); }
MIST__API float mist_segment_linearf(float k0, float k1, float s0, float s1, float length,
                                     float *transmittance)
    { return mist__impl_segment_linearf(k0, k1, s0, s1, length, transmittance); }
#endif
#undef MIST__API

#define MIST__FP_POP
#include "mist.h"
#undef MIST__FP_POP

#ifdef __cplusplus
}
#endif

#endif /* MIST_H */

#else /* MIST__TEMPLATE: the body, compiled once per type ----------------- */

/* In this body: MIST__T is the type, MIST__FN(name) its public name,
 * MIST__M(f) the libm function for it (sqrt / sqrtf), MIST__C(x) a constant
 * of that type. */
#define MIST__C(x) ((MIST__T)(x))
/* The double pass: the HG and Rayleigh samplers in double-double (see
 * "Henyey-Greenstein: exact sampling", "Rayleigh: exact sampling") ... */
#if !defined(MIST__W_EXACT) && !defined(MIST__INTERNAL_ONLY)
#  define MIST__DD 1
/* ... and the Draine samplers' finish too where fma is one instruction or
 * long double is no wider (else long double: see "Draine and Cornette-
 * Shanks: exact sampling") */
#  if defined(MIST__FAST_FMA) || defined(__CUDA_ARCH__) || !defined(MIST__W)
#    define MIST__DDR 1
#  endif
#endif
/* ... whose batch forms (HG's, the prepared Draine sampler's) vectorise
 * where fma is one instruction; with Dekker's product they loop over the
 * scalar function (Rayleigh's vectorises in every build) */
#if defined(MIST__DD) && (defined(MIST__FAST_FMA) || defined(__CUDA_ARCH__))
#  define MIST__DDV 1
#endif

/* ======================================================================== */
/* Input sanitising (the documented domain, see the top of the file)        */
/* ======================================================================== */

/* g: NaN -> 0, clamped to [-1, 1]. */
MIST__F MIST__T MIST__FN(mist__g)(MIST__T g)
{
    if (!(g == g)) return MIST__C(0);
    return g < MIST__C(-1) ? MIST__C(-1) : (g > MIST__C(1) ? MIST__C(1) : g);
}

#if defined(MIST__W_EXACT)
/* float only: |g| < 1 and xi in [+0, 1], tested on the bits (IEEE
 * binary32: NaN's bits lie above those of 1, so NaN fails both).  Two
 * integer compares where the floating-point tests took four and their
 * flags: a sampler called with a new g each time went 1.30x -> 1.19x the
 * printed eq. 3 (tests of g and xi in one branch, measured); and no
 * compiler flag (-ffinite-math-only) can drop them. */
MIST__F MIST__HOT int MIST__FN(mist__gxi_in)(MIST__T g, MIST__T xi)
{
    uint32_t bg, bx;
    memcpy(&bg, &g, sizeof bg);
    memcpy(&bx, &xi, sizeof bx);
    return ((bg & 0x7fffffffu) < 0x3f800000u) & (bx <= 0x3f800000u);
}
#endif

/* xi and u: NaN -> 0 resp. caller-handled; clamped to [lo, hi]. */
MIST__F MIST__T MIST__FN(mist__clamp)(MIST__T x, MIST__T lo, MIST__T hi)
{
    if (!(x == x)) return lo < MIST__C(0) ? MIST__C(0) : lo;
    return x < lo ? lo : (x > hi ? hi : x);
}

/* a * b + c, fused where the hardware fuses it (one rounding), else plain:
 * never a slow software fma. */
MIST__F MIST__T MIST__FN(mist__fma)(MIST__T a, MIST__T b, MIST__T c)
{
#if defined(MIST__FAST_FMA) || defined(__CUDA_ARCH__)
    return MIST__M(fma)(a, b, c);
#else
    return a * b + c;
#endif
}

#ifndef MIST__INTERNAL_ONLY
/* Error-free transformations (the height fog's compensated sums, the double
 * HG and Rayleigh samplers in double-double). */
/* the largest finite T */
#define MIST__BIG   ((MIST__T)(MIST__DBL ? DBL_MAX : (double)FLT_MAX))
#define MIST__TMIN  ((MIST__T)(MIST__DBL ? DBL_MIN : (double)FLT_MIN))   /* smallest normal */

/* s + *e = a + b exactly where |a| >= |b| (or a = 0; Dekker's Fast2Sum). */
MIST__F MIST__HOT MIST__T MIST__FN(mist__fast_two_sum)(MIST__T a, MIST__T b, MIST__T *e)
{
    MIST__T s = a + b;
    *e = b - (s - a);
    return s;
}

/* s + *e = a + b exactly (Knuth's TwoSum). */
MIST__F MIST__HOT MIST__T MIST__FN(mist__two_sum)(MIST__T a, MIST__T b, MIST__T *e)
{
    MIST__T s = a + b, bb = s - a;
    *e = (a - (s - bb)) + (b - bb);
    return s;
}

/* p + *e = a * b exactly for |a|, |b| < MIST__BIG / 2^28 (2^13 in float;
 * the double samplers' bounded terms): one fma where the hardware has it,
 * else Dekker's product, Veltkamp's split by 2^27 + 1 (2^12 + 1), no
 * branch (exact also if a compiler fuses its products: they are exact). */
MIST__F MIST__HOT MIST__T MIST__FN(mist__two_prod_b)(MIST__T a, MIST__T b, MIST__T *e)
{
    MIST__T p = a * b;
#if defined(MIST__FAST_FMA) || defined(__CUDA_ARCH__)
    *e = MIST__M(fma)(a, b, -p);
#else
    const MIST__T k = (MIST__T)(MIST__DBL ? 134217729.0 : 4097.0);
    MIST__T c = k * a, ah = c - (c - a), al = a - ah;
    MIST__T d = k * b, bh = d - (d - b), bl = b - bh;
    *e = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
#endif
    return p;
}

/* p + *e = a * b exactly, any finite a, b: without fma a factor so large
 * that Veltkamp's split overflows is scaled down by 2^32 (2^16) first and
 * the low part back up, exactly (found by the fuzzer: a float column
 * whose whole exponent was in the low part became NaN, then 0). */
MIST__F MIST__HOT MIST__T MIST__FN(mist__two_prod)(MIST__T a, MIST__T b, MIST__T *e)
{
#if defined(MIST__FAST_FMA) || defined(__CUDA_ARCH__)
    return MIST__FN(mist__two_prod_b)(a, b, e);
#else
    const MIST__T lim = MIST__BIG / MIST__C(MIST__DBL ? 268435458.0 : 8194.0);   /* 2k */
    const MIST__T dn = (MIST__T)(MIST__DBL ? 1.0 / 4294967296.0 : 1.0 / 65536.0);
    MIST__T p = a * b, sc = MIST__C(1);
    if (!(a <= lim && a >= -lim)) { a *= dn; sc /= dn; }
    if (!(b <= lim && b >= -lim)) { b *= dn; sc /= dn; }
    MIST__FN(mist__two_prod_b)(a, b, e);
    *e *= sc;
    return p;
#endif
}

/* c - a b, exact where c is within a factor 2 of the rounded a b (the
 * remainder of a division c / b = a or of a square root, c = a^2), a and b
 * bounded as for mist__two_prod_b: one fma where the hardware has it, else
 * Dekker's product, whose rounded part then cancels against c exactly
 * (Sterbenz). */
MIST__F MIST__HOT MIST__T MIST__FN(mist__fms)(MIST__T a, MIST__T b, MIST__T c)
{
#if defined(MIST__FAST_FMA) || defined(__CUDA_ARCH__)
    return MIST__M(fma)(-a, b, c);
#else
    MIST__T e, p = MIST__FN(mist__two_prod_b)(a, b, &e);
    return (c - p) - e;
#endif
}
#endif /* !MIST__INTERNAL_ONLY */

/* ======================================================================== */
/* Henyey-Greenstein and Draine: evaluation                                 */
/* [HG41], [JD23 eq. 2, 5], [D03]                                           */
/*                                                                          */
/*   p(u) = 1/(4 pi) (1 - g^2) / V^3 * (1 + alpha u^2) / (1 + alpha m2)    */
/*   V^2  = 1 + g^2 - 2 g u,   m2 = (1 + 2 g^2)/3 = E_HG[u^2].              */
/*                                                                          */
/* Reformulated for stability: V^2 is written as a sum of non-negative     */
/* terms, (1-|g|)^2 + 2|g|(1 - sgn(g) u), so the forward peak of g -> 1     */
/* keeps full relative precision (the printed form cancels to 0 there).     */
/* The Draine weight is carried as (c0 + c1 u^2)/(c0 + c1 m2) with          */
/* (c0, c1) = (1, alpha) for alpha <= 1 and (1/alpha, 1) beyond, so alpha = */
/* +inf is the exact limit instead of inf/inf.                              */
/* ======================================================================== */

/* |x| by fabs, for the hot paths: gcc compiles some x < 0 ? -x : x to a
 * branch, mispredicted where the sign is random (~15% of the prepared
 * Draine sampler's time, measured with gcc 12 -O3 -march=native) */
MIST__F MIST__HOT MIST__T MIST__FN(mist__abs)(MIST__T x)
{
    return MIST__M(fabs)(x);
}

/* V^2 = 1 + g^2 - 2 g u as a sum of non-negative terms. */
MIST__F MIST__HOT MIST__T MIST__FN(mist__v2)(MIST__T g, MIST__T u)
{   /* the mirror by copysign (1 + u = 1 - (-1) u exactly), not a branch: g
     * of either sign per call then costs no mispredictions (HG eval with
     * random-sign g: 3.2x the bare formula with the branch, 1.08x now) */
    MIST__T ag = MIST__M(fabs)(g), omg = MIST__C(1) - ag;
    return omg * omg + MIST__C(2) * ag * (MIST__C(1) - MIST__M(copysign)(MIST__C(1), g) * u);
}

#ifndef MIST_NO_DRAINE
/* Draine weights (c0, c1) from alpha; see the section comment. */
MIST__F void MIST__FN(mist__draine_c)(MIST__T alpha, MIST__T *c0, MIST__T *c1)
{
    if (!(alpha > MIST__C(0))) alpha = MIST__C(0);           /* NaN, negative -> 0 */
    if (alpha <= MIST__C(1)) { *c0 = MIST__C(1); *c1 = alpha; }
    else               { *c0 = MIST__C(1) / alpha; *c1 = MIST__C(1); }   /* inf -> 0 */
}
#endif

/* ======================================================================== */
/* Henyey-Greenstein: exact sampling                                        */
/* [JD23 eq. 3-4] print  u = (1 + g^2 - t^2)/(2g),  t = (1-g^2)/(1-g+2g xi), */
/* which divides by g (NaN at g = 0, cancellation for small g: the text's   */
/* isotropic fallback is wrong by O(g)).  Multiplying out gives the same    */
/* inverse with no division by g and no sqrt (D = 1 - g + 2 g xi):          */
/*   1 + u = 2 xi     (1+g)^2 (1 - g + g xi) / D^2    used for u < -1/2,    */
/*   1 - u = 2 (1-xi) (1-g)^2 (1 + g xi)     / D^2    used for u > +1/2,    */
/*   u     = (2 xi (1+g^2)(1 - g + g xi) - (1-g)^2) / D^2   in between.     */
/* The first two are products of non-negative factors (exact in relative    */
/* terms, so the tails keep full precision); in the third, for g >= 0, both */
/* terms are O(D^2), so its cancellation near u = 0 costs no more than the  */
/* rounding of xi itself.  g < 0 by the mirror image u(g,xi) = -u(-g,1-xi). */
/* Measured against a float128 inversion this is within 1.1x the bar of     */
/* tests/test_accuracy.c in T, and in double not monotone in adjacent xi    */
/* (0.01-2.5% of adjacent pairs reversed, g .1 to .8, 1e7 each): the Draine */
/* sampler starts from it.  The float samplers need less: in double one     */
/* form, 1 - nb/D^2, is accurate enough everywhere and for either sign of   */
/* g, no mirror (mist__hg_one: one division, no branch, vectorisable;       */
/* measured 0.125x the float bar).  The double samplers evaluate that form  */
/* in DOUBLE-DOUBLE: every term an unevaluated sum hi + lo (products by fma */
/* where it is one instruction, else Dekker's product, mist__two_prod_b;   */
/* sums by Knuth's two-sum; 1 - xi exact as such a pair), one division and  */
/* its remainder (mist__hg_dd).  About 2^-104 of error, relative to the    */
/* terms (~1): correctly rounded in practice but near u = 0, where 1 - q    */
/* keeps it as an absolute error (test_accuracy holds it to half an ulp +   */
/* 2^-100; against exact rational references not the rounded root only     */
/* where |u| < ~2^-40, up to ~100 ulps at |u| ~ 2^-59; such u are ~1e-12 of */
/* samples), and at                                                         */
/* |g| < ~2^-105 where u's leading term, 2 xi - 1 or 3g/2, is exactly a     */
/* rounding tie that the term of relative size g, below double-double's     */
/* reach, would break (1 ulp).  bench/mist_ddcheck.c: 1e5 random (g, xi), g */
/* from 1e-300 to 1 - 2^-53, xi down to 2^-1074, against float128: within   */
/* 0.25x the bar; every sample the rounded root but at such ties (checked  */
/* exactly: bench/hg_exact.py).  Monotone (0 reversed pairs), branch-free   */
/* (the batch form vectorises where fma is one instruction); ~3x eq. 3 with */
/* fma (./build/mist_bench).  Every build that rounds each operation        */
/* computes the same samples.  Long double instead would put ~0.1% of      */
/* samples an ulp off, and Dekker's product for these bounded terms needs  */
/* no overflow branches, so it costs about what long double does.          */
/* ======================================================================== */

/* The terms, for g in [0, 1), given x = xi and y = 1 - xi (either may carry
 * the rounding of 1 - xi: both only enter sums of non-negative terms and
 * relative factors): na = (1 + u) D^2, nb = (1 - u) D^2, D^2; ea and omg
 * for the middle form (mist__hg_mid).  See the section comment. */
MIST__F MIST__HOT void MIST__FN(mist__hg_terms)(MIST__T g, MIST__T x, MIST__T y, MIST__T *na,
                                      MIST__T *nb, MIST__T *d2, MIST__T *ea, MIST__T *omg)
{
    MIST__T opg = MIST__C(1) + g, d, eb;
    *omg = MIST__C(1) - g;
    d   = *omg + MIST__C(2) * g * x;              /* D = 1 - g + 2 g xi */
    *ea = *omg + g * x;                           /*     1 - g +   g xi */
    eb  = MIST__C(1) + g * x;                     /*     1     +   g xi */
    *na = MIST__C(2) * x * (opg * opg) * *ea;
    *nb = MIST__C(2) * y * (*omg * *omg) * eb;
    *d2 = d * d;
}

/* |u| <= 1/2: u D^2 = 2 xi (1+g^2)(1 - g + g xi) - (1-g)^2 */
MIST__F MIST__HOT MIST__T MIST__FN(mist__hg_mid)(MIST__T g, MIST__T x, MIST__T ea, MIST__T omg)
{
    return MIST__FN(mist__fma)(MIST__C(2) * x * (MIST__C(1) + g * g), ea, -(omg * omg));
}

/* u for g in [0, 1): the form that keeps precision, chosen by branches (for
 * one g they are well predicted: faster scalar code than the blend below,
 * measured 4.2 against 5.7 ns in float, 10 against 15 ns in double). */
MIST__F MIST__T MIST__FN(mist__hg_core)(MIST__T g, MIST__T x, MIST__T y)
{
    MIST__T na, nb, d2, ea, omg;
    MIST__FN(mist__hg_terms)(g, x, y, &na, &nb, &d2, &ea, &omg);
    if (MIST__C(3) * na < nb) return na / d2 - MIST__C(1);   /* u < -1/2 */
    if (MIST__C(3) * nb < na) return MIST__C(1) - nb / d2;   /* u > +1/2 */
    return MIST__FN(mist__hg_mid)(g, x, ea, omg) / d2;
}

/* u for g in (-1, 1), xi in [0, 1]: g < 0 by the mirror image
 * u(g, xi) = -u(-g, 1 - xi). */
MIST__F MIST__T MIST__FN(mist__hg_sample)(MIST__T g, MIST__T xi)
{
    MIST__T u = g >= MIST__C(0)
        ?  MIST__FN(mist__hg_core)( g, xi, MIST__C(1) - xi)
        : -MIST__FN(mist__hg_core)(-g, MIST__C(1) - xi, xi);
    return u < MIST__C(-1) ? MIST__C(-1) : (u > MIST__C(1) ? MIST__C(1) : u);
}

/* ONE FORM, for the float samplers, evaluated in double: u = 1 - nb/D^2,
 * x = xi, y = 1 - xi, given the parameter's terms omg = 1 - g and
 * c = 2 (1 - g)^2 (mist__hg_pre: a caller's loop over one medium hoists
 * them).  With float g and xi every input term is exact in double, or
 * carries one relative rounding where it cannot cancel (1 - g and 1 - xi
 * for |g|, xi < 2^-29), and D = 1 - g + 2 g xi and 1 + g xi are each one
 * fma of exact terms: one rounding, cancellation or not.  So nb/D^2 = 1 - u
 * in [0, 2] carries a few double roundings in relative terms, and u an
 * absolute error of ~1e-15 for any g in (-1, 1): no mirror for g < 0 (it
 * only moved that cancellation into D).  The float bar
 * (tests/test_accuracy.c) is never below ~1e-10 in absolute terms: 4 ulp
 * of u* where |u*| > 1e-3, and near u* = 0 its xi term, 4 eps_f xi du/dxi
 * >= 1e-7 (xi du/dxi = F(u)/(2 pi p(u)) is 0.5 to 1 there for g >= 0,
 * larger for g < 0).  So one division and no branch: the cost of eq. 3 in
 * float (two divisions), and vectorisable as it stands.  No clamp: u <= 1
 * (nb/D^2 >= 0) and u >= -1 - 1e-15, which rounds to a float >= -1 (half
 * a float ulp there is 3e-8); xi = 0 gives D^2 = (1 - g)^2 and u = -1
 * exactly.  (In double the same form misses its bar 1.5-2x near u = 0 and
 * u = -1: the double samplers evaluate it in double-double, mist__hg_dd.) */
MIST__F MIST__HOT void MIST__FN(mist__hg_pre)(MIST__T g, MIST__T *omg, MIST__T *c)
{
    *omg = MIST__C(1) - g;
    *c = MIST__C(2) * (*omg * *omg);
}

MIST__F MIST__HOT MIST__T MIST__FN(mist__hg_one)(MIST__T g, MIST__T omg, MIST__T c, MIST__T x,
                                                 MIST__T y)
{
    /* (fma where it is one instruction: with float g and xi the products
     * are exact in double, so the results are the same bits, in fewer
     * instructions: 4-11% faster with g at run time, measured) */
    MIST__T d = MIST__FN(mist__fma)(MIST__C(2) * g, x, omg);
    return MIST__C(1) - y * c * MIST__FN(mist__fma)(g, x, MIST__C(1)) / (d * d);
}

#if defined(MIST__W_EXACT)
/* float: the terms of g in double, t = (g, 1 - g, 2 (1 - g)^2), computed
 * once per g (mist_hg_sample before its branch, a prepared medium), and
 * the sample at a float xi from them: the one form in double */
MIST__F MIST__HOT void MIST__FN(mist__hg_par)(MIST__T g, MIST__W *t)
{
    t[0] = (MIST__W)g;
    MIST__WFN(mist__hg_pre)(t[0], &t[1], &t[2]);
}
MIST__F MIST__HOT MIST__T MIST__FN(mist__hg_at)(const MIST__W *t, MIST__T xi)
{
    MIST__W x = (MIST__W)xi;
    return (MIST__T)MIST__WFN(mist__hg_one)(t[0], t[1], t[2], x, 1 - x);
}
#endif

#if defined(MIST__DD)
/* DOUBLE-DOUBLE (see the section comment): u for g in [0, 1) at x = xh + xl,
 * y = yh + yl = 1 - x exactly (one of the pairs has lo = 0) */
MIST__F MIST__HOT MIST__T MIST__FN(mist__hg_dd)(MIST__T g, MIST__T xh, MIST__T xl, MIST__T yh,
                                                MIST__T yl)
{
    MIST__T oh, ol, gh, gl, eh, el, dh, dl, qh, ql, ph, pl, ah, al, nh, nl, iv, q1, q2, sh, sl;
    oh = MIST__FN(mist__fast_two_sum)(MIST__C(1), -g, &ol);                    /* 1 - g */
    gh = MIST__FN(mist__two_prod_b)(g, xh, &gl); gl += g * xl;                 /* g x */
    eh = MIST__FN(mist__fast_two_sum)(MIST__C(1), gh, &el); el += gl;          /* 1 + g x */
    dh = MIST__FN(mist__two_sum)(oh, MIST__C(2) * gh, &dl);                    /* D */
    dl += ol + MIST__C(2) * gl;
    qh = MIST__FN(mist__two_prod_b)(dh, dh, &ql); ql += MIST__C(2) * dh * dl;  /* D^2 */
    ph = MIST__FN(mist__two_prod_b)(oh, oh, &pl); pl += MIST__C(2) * oh * ol;  /* (1-g)^2 */
    ah = MIST__FN(mist__two_prod_b)(yh, ph, &al); al += yh * pl + yl * ph;     /* y (1-g)^2 */
    nh = MIST__FN(mist__two_prod_b)(ah, eh, &nl); nl += ah * el + al * eh;     /* nb / 2 */
    nh *= MIST__C(2); nl *= MIST__C(2);
    iv = MIST__C(1) / qh; q1 = nh * iv;                                       /* nb / D^2 */
    q2 = (MIST__FN(mist__fms)(q1, qh, nh) + nl - q1 * ql) * iv;   /* (the remainder is exact) */
    sh = MIST__FN(mist__two_sum)(MIST__C(1), -q1, &sl);                        /* 1 - q */
    return sh + (sl - q2);
}
#endif

/* xi clamped to [0, 1] (z = 0, one = 1, read from a volatile by the batch
 * forms: see mist_hg_sample_n), NaN -> 0. */
MIST__F MIST__HOT MIST__T MIST__FN(mist__clamp01)(MIST__T xi, MIST__T z, MIST__T one)
{
    xi = xi > z ? xi : z;               /* two selects, not nested: max, min */
    return xi < one ? xi : one;
}

/* u clamped to [-1, 1] as selects; NaN stays NaN (callers select 0). */
MIST__F MIST__HOT MIST__T MIST__FN(mist__clamp11)(MIST__T u)
{
    return u < MIST__C(-1) ? MIST__C(-1) : (u > MIST__C(1) ? MIST__C(1) : u);
}

/* The Draine samplers' mirror for the vectorised kernels, xi in [0, 1]:
 * returns -1 with *x = 1 - xi (exact) where xi > 1/2, else 1 with *x = xi,
 * by copysign and a min: on selects of xi > 1/2 gcc specialised the whole
 * kernel for sg = +-1 and would not vectorise it with AVX2 (the scalar
 * samplers keep the selects, which were faster there: 42 against 47 ns a
 * float sample, gcc 12 -O3 -march=native, measured). */
MIST__F MIST__HOT MIST__T MIST__FN(mist__mirror)(MIST__T xi, MIST__T *x)
{
    *x = xi < MIST__C(1) - xi ? xi : MIST__C(1) - xi;
    return MIST__M(copysign)(MIST__C(1), MIST__C(0.5) - xi);
}

#ifndef MIST_NO_RAYLEIGH
/* ======================================================================== */
/* Rayleigh: exact sampling                                                 */
/* CDF (u^3 + 3u + 4)/8 = xi: the depressed cubic u^3 + 3u = q, q = 8xi-4,  */
/* one real root, u = A - 1/A with A^3 = q/2 + sqrt(q^2/4 + 1) (Cardano).   */
/* Cardano costs a cbrt and a sqrt, cancels near u = 0 and, worse, carries  */
/* its rounding relative to |u| near u = -1, where u moves by less than     */
/* that per ulp of xi: the 1e10-call stress run found adjacent double xi    */
/* in the wrong order (xi 0x1.308dea28b34p-11 and its successor).  So mist  */
/* solves for v = 1 + u on the lower half, x = min(xi, 1 - xi) in [0, 1/2] */
/* (1 - xi exact there), v in [0, 1]:                                       */
/*   v (v^2 - 3v + 6) = 8x,                                                 */
/* exact in x, well conditioned (the derivative 3v^2 - 6v + 6 >= 3); u =   */
/* v - 1, mirrored for xi > 1/2.  One Halley step from a polynomial start,  */
/* no branch, no libm call (mist__rayleigh_v): float evaluates it in double */
/* (the batch form vectorises).  Double finishes in double-double: one      */
/* Newton step on the residual by compensated Horner (products by fma where */
/* it is one instruction, else Dekker's), u = v - 1 summed exactly          */
/* (mist__rayleigh_udd; bench/mist_ddcheck.c: 19998 of 2e4 random xi, down  */
/* to 2^-1074, the rounded float128 root, 0 reversed; the batch form        */
/* vectorises, with fma or Dekker's product).  Every build that rounds each */
/* operation computes the same samples (long double, two Halley steps from  */
/* a cubic start, put ~0.03% of samples an ulp off, measured over 2e6       */
/* random xi, and was no faster).                                           */
/* ======================================================================== */

/* v = 1 + u with v (v^2 - 3v + 6) = 8x, x in [0, 1/2]: one Halley step from
 * a degree-8 start (Chebyshev fit of v/x, 2.2e-6 relative), with f as
 * (v - 1)(v^2 - 2v + 4) - 8 (x - 1/2), whose terms vanish together at
 * x = 1/2, so that v(1/2) = 1 exactly (u = 0 at xi = 1/2).  Its error is
 * absolute, ~4 eps: enough for float's u = v - 1 (every 7th float xi in
 * [0, 1] gives the sample of two steps from a cubic start, 1.5e8 checked,
 * no reversal over all floats in [1/2, 1]; 0.80x the time); double's Newton
 * step on the exact residual then leaves ~1e-31 (mist__rayleigh_udd: the
 * same samples as from two steps, 2e7 random xi crowded to 0 and 1, at
 * ~0.65x their time). */
MIST__F MIST__HOT MIST__T MIST__FN(mist__rayleigh_v)(MIST__T x)
{
    MIST__T v, f, fp, x2 = x * x, x4 = x2 * x2;
    v = x * ((MIST__C(1.3333361718295621) + x * MIST__C(0.88797168161472789))
             + x2 * (MIST__C(0.83837344366430536) + x * MIST__C(-0.30598031546183578))
             + x4 * ((MIST__C(9.8310325223208421) + x * MIST__C(-51.110549075671468))
                     + x2 * (MIST__C(150.69234358110555) + x * MIST__C(-241.0054130602601)
                             + x2 * MIST__C(143.97033175839185))));
    f  = (v - MIST__C(1)) * (v * (v - MIST__C(2)) + MIST__C(4)) - MIST__C(8) * (x - MIST__C(0.5));
    fp = v * (MIST__C(3) * v - MIST__C(6)) + MIST__C(6);
    return v - MIST__C(2) * f * fp / (MIST__C(2) * fp * fp - f * (MIST__C(6) * v - MIST__C(6)));
}

/* u from xi in [0, 1]: the lower half's v, mirrored (u(xi) = -u(1 - xi)) */
MIST__F MIST__HOT MIST__T MIST__FN(mist__rayleigh_u)(MIST__T xi)
{
    MIST__T y = MIST__C(1) - xi, x = xi < y ? xi : y;
    MIST__T s = xi > MIST__C(0.5) ? MIST__C(-1) : MIST__C(1);
    return s * (MIST__FN(mist__rayleigh_v)(x) - MIST__C(1));
}

#if defined(MIST__DD)
/* DOUBLE-DOUBLE (see the section comment): mist__rayleigh_u to ~2^-100.
 * The residual p(v) = ((v - 3) v + 6) v - 8x at the double root by
 * compensated Horner, its products exact (fma or Dekker's: as if in twice
 * the precision), one Newton
 * step as a correction -p/p', and u = v - 1 summed exactly before its one
 * rounding. */
MIST__F MIST__HOT MIST__T MIST__FN(mist__rayleigh_udd)(MIST__T xi)
{
    MIST__T y = MIST__C(1) - xi, x = xi < y ? xi : y;
    MIST__T sg = xi > MIST__C(0.5) ? MIST__C(-1) : MIST__C(1);
    MIST__T v = MIST__FN(mist__rayleigh_v)(x), s, p, e, c, d;
    s = MIST__FN(mist__fast_two_sum)(MIST__C(-3), v, &c);           /* v - 3 */
    p = MIST__FN(mist__two_prod_b)(s, v, &e);                       /* times v, + 6 */
    s = MIST__FN(mist__fast_two_sum)(MIST__C(6), p, &d);
    c = c * v + (e + d);
    p = MIST__FN(mist__two_prod_b)(s, v, &e);                       /* times v, - 8x */
    s = MIST__FN(mist__two_sum)(p, -MIST__C(8) * x, &d);
    c = c * v + (e + d);
    d = (s + c) / ((MIST__C(3) * v - MIST__C(6)) * v + MIST__C(6)); /* Newton */
    s = MIST__FN(mist__fast_two_sum)(MIST__C(-1), v, &c);           /* (v - d) - 1 */
    return sg * (s + (c - d));
}
#endif
#endif /* !MIST_NO_RAYLEIGH */

#ifndef MIST__INTERNAL_ONLY
/* HG's constant factor (1 - g^2)/(4 pi), at sanitised g. */
MIST__F MIST__T MIST__FN(mist__hg_k)(MIST__T g)
{
    return MIST__C(MIST__INV4PI) * (MIST__C(1) - g) * (MIST__C(1) + g);
}

/* The HG density at sanitised |g| < 1, u in [-1, 1], k = mist__hg_k(g):
 * one sqrt, one division (HG has no Draine factor to divide by). */
MIST__F MIST__HOT MIST__T MIST__FN(mist__hg_d)(MIST__T k, MIST__T g, MIST__T u)
{
    MIST__T v2 = MIST__FN(mist__v2)(g, u);
    return k / (v2 * MIST__M(sqrt)(v2));
}

#ifndef MIST_NO_DRAINE
/* The Draine weight's denominator cn = c0 + c1 m2, m2 = (1 + 2 g^2)/3. */
MIST__F MIST__T MIST__FN(mist__draine_cn)(MIST__T g, MIST__T c0, MIST__T c1)
{
    return c0 + c1 * ((MIST__C(1) + MIST__C(2) * g * g) / MIST__C(3));
}

/* The Draine density at sanitised |g| < 1, u: HG times its weight. */
MIST__F MIST__HOT MIST__T MIST__FN(mist__draine_d)(MIST__T k, MIST__T g, MIST__T c0, MIST__T c1,
                                         MIST__T cn, MIST__T u)
{
    return MIST__FN(mist__hg_d)(k, g, u) * ((c0 + c1 * u * u) / cn);
}

#endif

/* A density's arguments off the domain (the caller tests |g| < 1 and |u|
 * <= 1 first, false for NaN): *g and *u sanitised; returns 1 with the
 * answer in *r where it is fixed: NaN u gives 0, the Dirac limit |g| = 1
 * +inf at u = g, else 0. */
MIST__F int MIST__FN(mist__dens_off)(MIST__T *g, MIST__T *u, MIST__T *r)
{
    if (!(*u == *u)) { *r = MIST__C(0); return 1; }
    *g = MIST__FN(mist__g)(*g);
    *u = MIST__FN(mist__clamp11)(*u);
    if (*g == MIST__C(1) || *g == MIST__C(-1)) {
        *r = *u == *g ? (MIST__T)INFINITY : MIST__C(0);
        return 1;
    }
    return 0;
}

/* Henyey-Greenstein density per steradian, [JD23 eq. 2].
 * Domain: g in [-1, 1], u in [-1, 1] (see DOMAIN AND BAD INPUT). */
MIST__F MIST__T MIST__FN(mist__impl_hg_eval)(MIST__T g, MIST__T u)
{   /* one test of the domain (NaN fails), the sanitising only off it, and
     * one copy of the formula (two copies may contract into fma
     * differently: a clamped u then differed from u = +-1 by an ulp under
     * -ffp-contract=fast).  With g known at run time only (a renderer's
     * medium) nested tests on every call cost 1.9x the bare formula,
     * measured; now 1.00x (g fixed) and 1.08x (g new each call) */
    MIST__T r;
    if (!((MIST__M(fabs)(g) < MIST__C(1)) & (MIST__M(fabs)(u) <= MIST__C(1)))
        && MIST__FN(mist__dens_off)(&g, &u, &r)) return r;
    return MIST__FN(mist__hg_d)(MIST__FN(mist__hg_k)(g), g, u);
}

#ifndef MIST_NO_DRAINE
/* Draine density per steradian, [JD23 eq. 5].
 * Domain: g in [-1, 1], alpha in [0, +inf], u in [-1, 1]. */
MIST__F MIST__T MIST__FN(mist__impl_draine_eval)(MIST__T g, MIST__T alpha, MIST__T u)
{
    MIST__T c0, c1, r;
    MIST__FN(mist__draine_c)(alpha, &c0, &c1);
    if (!((MIST__M(fabs)(g) < MIST__C(1)) & (MIST__M(fabs)(u) <= MIST__C(1)))   /* as HG's */
        && MIST__FN(mist__dens_off)(&g, &u, &r)) return r;
    return MIST__FN(mist__draine_d)(MIST__FN(mist__hg_k)(g), g, c0, c1,
                                    MIST__FN(mist__draine_cn)(g, c0, c1), u);
}

/* Cornette-Shanks density per steradian [CS92]: Draine with alpha = 1. */
MIST__F MIST__T MIST__FN(mist__impl_cs_eval)(MIST__T g, MIST__T u)
{
    return MIST__FN(mist__impl_draine_eval)(g, MIST__C(1), u);
}
#endif /* !MIST_NO_DRAINE */

#ifndef MIST_NO_RAYLEIGH
/* Rayleigh density per steradian: 3/(16 pi) (1 + u^2).  Domain u in [-1,1]. */
MIST__F MIST__T MIST__FN(mist__impl_rayleigh_eval)(MIST__T u)
{
    MIST__T c = MIST__FN(mist__clamp11)(u);
    return u == u ? MIST__C(MIST__3_16PI) * (MIST__C(1) + c * c) : MIST__C(0);
}
#endif

#if defined(MIST__DD)
/* the double sampler in double-double: sanitised |g| < 1, xi in [0, 1];
 * g < 0 by the mirror u(g, xi) = -u(-g, 1 - xi), 1 - xi as an exact pair,
 * by selects on factors z = 0 and one = 1 (the batch form reads them from
 * a volatile so that they stay selects and its loop vectorises, where fma
 * is one instruction) */
MIST__F MIST__HOT MIST__T MIST__FN(mist__hg_ddu)(MIST__T g, MIST__T xi, MIST__T z, MIST__T one)
{
    MIST__T ga = g < z ? -g : g, neg = g < z ? one : z;
    MIST__T cl, c = MIST__FN(mist__fast_two_sum)(one, -xi, &cl);                  /* 1 - xi */
    MIST__T u = MIST__FN(mist__hg_dd)(ga, neg > z ? c : xi, neg > z ? cl : z,
                                      neg > z ? xi : c, neg > z ? z : cl);
    return MIST__FN(mist__clamp11)(u) * (one - MIST__C(2) * neg);
}
#endif

/* The HG sample at sanitised |g| < 1, xi in [0, 1]: float in double by the
 * one form (mist__hg_one), double in double-double (mist__hg_ddu). */
MIST__F MIST__HOT MIST__T MIST__FN(mist__hg_u)(MIST__T g, MIST__T xi)
{
#if defined(MIST__W_EXACT)
    MIST__W t[3];
    MIST__FN(mist__hg_par)(g, t);
    return MIST__FN(mist__hg_at)(t, xi);
#else
    return MIST__FN(mist__hg_ddu)(g, xi, MIST__C(0), MIST__C(1));
#endif
}

/* The HG sample at any g and xi: outside |g| < 1, xi in (0, 1] sanitised */
MIST__F MIST__HOT MIST__T MIST__FN(mist__hg_any)(MIST__T g, MIST__T xi)
{
    if (!((MIST__M(fabs)(g) < MIST__C(1)) & (xi > MIST__C(0)) & (xi <= MIST__C(1)))) {
        g  = MIST__FN(mist__g)(g);              /* outside: sanitise */
        xi = MIST__FN(mist__clamp01)(xi, MIST__C(0), MIST__C(1));
        if (g == MIST__C(1) || g == MIST__C(-1)) return g;
    }
    return MIST__FN(mist__hg_u)(g, xi);
}

/* Henyey-Greenstein: u with P(cos <= u) = xi, exact.
 * Domain: g in [-1, 1], xi in [0, 1]. */
MIST__F MIST__API_HOT MIST__T MIST__FN(mist__impl_hg_sample)(MIST__T g, MIST__T xi)
{
#if defined(MIST__W_EXACT)
    /* float: the parameter's terms before any branch, so that a caller's
     * loop over one medium hoists them (gcc does not hoist work out of a
     * conditional block: 1.28x eq. 3 with g at run time inside the branch,
     * ~0.9x before it).  The unprepared float Draine sampler calls
     * mist__hg_any for alpha = 0: in CUDA device code nvcc allocates it 90
     * registers with this inlined, 80 without (ptxas -v, sm_90) */
    MIST__W t[3];
    MIST__FN(mist__hg_par)(g, t);
    if (MIST__FN(mist__gxi_in)(g, xi)) return MIST__FN(mist__hg_at)(t, xi);
#endif
    return MIST__FN(mist__hg_any)(g, xi);
}

#endif /* !MIST__INTERNAL_ONLY */

#ifndef MIST_NO_DRAINE
/* ======================================================================== */
/* Draine and Cornette-Shanks: exact sampling                               */
/*                                                                          */
/* [JD23 eq. 6] inverts the CDF with a quartic in closed form.  Typed in    */
/* verbatim it is NaN at g = 0 and alpha = 0, wrong by 0.056 in u at g =    */
/* 1e-5 in double, and by 0.82 at g = 0.01, alpha = 250 in float (measured  */
/* against a float128 inversion): its terms cancel as 1/g^3.                */
/*                                                                          */
/* mist inverts the same CDF, written without cancellation, by safeguarded  */
/* Newton iteration.  Integrating [JD23 eq. 5] (substituting V for u) and   */
/* dividing the factors g^3 out analytically, with V1 = 1 + g, a = 1 + g^2, */
/* P = V V1, V0 = sqrt(a) = V(0):                                           */
/*  u <= 0:  F(u) = K (c0 + c1 Qp / (3 (P+a)^2)) / cn,                      */
/*           K  = (1-g)(1+u) / (V (V1 + V))          (the HG CDF),          */
/*           Qp = (P + 3a)(V^2 + a u^2) - u V (V (V1^2 + 3a) - 2 g u V1);   */
/*  u >= 0:  F(u) = F(0) + (c0 dH + c1 dM2) / cn,                           */
/*           dH  = (1-g^2) u / (V V0 (V0 + V)),                             */
/*           dM2 = (1-g^2) u^3 (2a + V0 (V0 + V)) / (3 V V0 (V0 + V)^3),    */
/* where cn = c0 + c1 (1 + 2g^2)/3.  Every term is non-negative (for g < 0  */
/* one difference in Qp loses at most a factor 1.5), so F keeps relative    */
/* precision however small it is: the bar's 4 eps xi du/dxi is relative to  */
/* xi, so the solver targets F(u) = xi for xi <= 1/2 and, above, the mirror */
/* image F_{-g}(-u) = 1 - xi (exact for xi >= 1/2).  The bracket starts as  */
/* [-1, 1] and shrinks by the residual's sign; Newton steps that leave it   */
/* bisect.  A step costs one square root and one division (F - x and the    */
/* step come from F's numerator and denominator).                           */
/*                                                                          */
/* F takes ~20 roundings, up to 10 eps in T (measured): more than the bar   */
/* allows.  So the iteration in T stops at T's noise and finishes with      */
/* Newton steps in the wider type (long double for double; float iterates   */
/* in double from the start), which is correctly rounded in practice (0.25x */
/* the bar) where the bar's ulp term dominates; where its xi term does      */
/* (near u = 0 at large alpha) the steps stop well inside the bar, not at   */
/* the rounded root (g 1.6e-8, alpha 3457, xi 0.49999952 in float: ~1000    */
/* ulps of u from it, 1e-4 of the bar, F(u) - xi = 2.5e-11; measured).      */
/* Where eq. 6 itself is good in double (1e-3 <= |g| <= 0.9999,             */
/* 1e-6 <= alpha <= 1e4: within 1.3e-5, measured) it is only the starting   */
/* point: one wide Newton step then lands (checked by the step's predicted  */
/* successor), and the iteration in T is skipped.  The stop is judged with  */
/* the density at the step's far end and a bound on f'/f over the whole     */
/* step: near alpha -> inf and u = 0 the density is ~u^2 and f at the       */
/* iterate alone stops far from the root.                                   */
/* DOUBLE-DOUBLE: where fma is one instruction the double samplers finish   */
/* instead with Newton steps whose residual is the same formula in          */
/* compensated arithmetic (mist__draine_resc: within 2^-101 of its terms'   */
/* magnitude near the roots, measured against float128 over 1.6e6 points),  */
/* rounded by a window and, where it straddles a midpoint, the residual's   */
/* sign there (mist__draine_ddfin); long double remains the fallback where  */
/* those steps do not settle in 64.  Correctly rounded in practice and      */
/* monotone, with or without long double (test_accuracy_nold_native), and   */
/* faster than the long double finish (0.7x, mist_draine_sample at g .5,    */
/* alpha 17: the step's divisions are moved off its chain of dependent     */
/* operations).                                                             */
/* Where there is neither (MSVC x64, or MIST_NO_LONG_DOUBLE without fma)    */
/* the same double-double finish runs with Dekker's product (mist__two_prod_b*/
/* after scaling the weights below 1, mist__fms): the full bar and monotone */
/* (test_accuracy_nold; mist_ddcheck built so: 0.25x, 19998 of 2e4 rounded),*/
/* at about long double's cost unprepared and ~1.4x it prepared.  Double    */
/* alone, without the wide steps, is not enough: not monotone, and up to    */
/* 3.1x the bar near u = 0 (xi near F(0)).                                  */
/* The float sampler first rounds eq. 6's double answer to float and        */
/* certifies it by one residual at that answer and the density there        */
/* (mist__draine_cert): where the residual is certainly below half the      */
/* density times the distance to the nearer rounding midpoint, it is the    */
/* root correctly rounded, and no Newton step is taken (92% of random (g,   */
/* alpha, xi) in eq. 6's domain, all but a few in 1e6 at g .5, alpha 17;    */
/* measured): one residual where Newton steps take several, so the float   */
/* sampler costs ~2-3x the printed eq. 6 in float (./build/mist_bench; on  */
/* a GPU ~4x, docs/gpu.md).                                                 */
/* WORST CASE.  Newton in u creeps where F is far from linear over a step: */
/* next to u = +-1 at |g| -> 1 (the lobe narrower than an ulp: the steps    */
/* round back to u or overshoot past +-1 and bisect) and near u = 0 at      */
/* large alpha (density ~u^2: 2/3 of the way a step).  So such steps go in  */
/* 1/V (HG's CDF is linear in it) or in y = c0 u + c1 u^3 / 3 (the         */
/* weight's integral; mist__draine_next), small |g| at alpha > 1 starts     */
/* from F linear in y (mist__draine_uy), and +-1 and its neighbour are      */
/* decided by the residual's signs.  bench/mist_worst.c: the worst call of  */
/* an adversarial grid (|g| to 1 - 2^-53, alpha 1e-300 to +inf) 3-8x the   */
/* median random call in every build measured, gcc 12 and clang 14, with    */
/* and without long double and fma (Newton in u alone: up to 110x).       */
/* A prepared phase function (mist_phase_draine) starts from its table      */
/* instead of eq. 6, and in float usually ends after one straight-line      */
/* Newton step (mist__draine_step; see "Prepared phase functions").         */
/* ======================================================================== */

/* The Draine CDF as a function of y = c0 u + c1 u^3 / 3 (the weight's
 * integral): F ~ F(0) + (1 - g^2) y / (2 cn V^3), nearly linear in y where
 * the HG factor V^-3 varies little, however flat or steep it is in u
 * (alpha -> inf: the density ~u^2 near u = 0, where Newton in u crept, the
 * tangent's root 2/3 of the way in a step, and from near 0 overshot).  u
 * of y (clamped to y(+-1)), c1 > 0: u^3 + 3 p u = 2 q, p = c0/c1 >= 0, q =
 * 3 y / (2 c1), whose one real root is, by Cardano, t - p/t with t^3 = |q|
 * + sqrt(q^2 + p^3), written 2 q / (t^2 + p + p^2/t^2) (no cancellation;
 * q = 0 at t = 0). */
MIST__F MIST__T MIST__FN(mist__draine_uy)(MIST__T c0, MIST__T c1, MIST__T y)
{
    MIST__T p = c0 / c1, ym = c0 + c1 / MIST__C(3), q, aq, t, t2;
    y = y < -ym ? -ym : y > ym ? ym : y;
    q = MIST__C(1.5) * y / c1; aq = MIST__FN(mist__abs)(q);
    t = MIST__M(cbrt)(aq + MIST__M(sqrt)(aq * aq + p * p * p)); t2 = t * t;
    return t2 > MIST__C(0) ? MIST__C(2) * q / (t2 + p + p * p / t2)
         : p > MIST__C(0) ? q / (MIST__C(1.5) * p) : MIST__C(0);
}

/* The next iterate after a Newton step s = (F - x) / f at u (V^2 = v2, V =
 * v) that did not stop, in the variable that suits the step.  The step
 * moves the HG factor V^-3 by ~3 |g s| / V^2 and the weight w = c0 + c1
 * u^2 by c1 |s| |2u - s| / w; where the larger exceeds 1/4 (the stops'
 * models' limit): the weight's (alpha > 1), the step in y (mist__draine_uy;
 * dy/du = w); the HG factor's, the step in t = 1/V (dt/du = g/V^3): HG's
 * CDF is linear in 1/V, so with a slowly varying weight this lands near
 * the root, where Newton in u crept next to u = +-1 at |g| -> 1, the
 * tangent's root a factor ~3 closer in 1 -+ u a step (g 0.9999, from the
 * table's first interval: 18 steps); the new u from V^2 = (1 - |g|)^2 +
 * 2 |g| (1 - sgn(g) u), without cancellation next to the peak.  Else
 * u - s.  Out of [-1, 1] (2) where t would not be positive: the callers
 * then bisect.  (The t step first, whatever the weight did, overshot at
 * g 0.5, alpha 1e4 from u -0.036 to -0.95 for a root at -0.139.) */
MIST__F MIST__T MIST__FN(mist__draine_next)(MIST__T g, MIST__T c0, MIST__T c1, MIST__T u,
                                            MIST__T s, MIST__T v2, MIST__T v)
{
    MIST__T ag = MIST__FN(mist__abs)(g), as = MIST__FN(mist__abs)(s), wt = c0 + c1 * u * u;
    MIST__T eh = MIST__C(3) * ag * as * wt, ew = c1 * as * MIST__FN(mist__abs)(MIST__C(2) * u - s)
                                                 * v2;      /* the changes, times V^2 w */
    if (c1 > c0 && ew > eh && ew > MIST__C(0.25) * wt * v2)
        return MIST__FN(mist__draine_uy)(c0, c1, u * (c0 + c1 * u * u / MIST__C(3)) - s * wt);
    if (eh > MIST__C(0.25) * wt * v2) {
        MIST__T dv = v2 - s * g, vn = v * (v2 / dv), om = MIST__C(1) - ag;
        MIST__T w1 = (vn - om) * (vn + om) / (MIST__C(2) * ag);
        return dv > MIST__C(0) ? (g < MIST__C(0) ? w1 - MIST__C(1) : MIST__C(1) - w1)
                               : MIST__C(2);
    }
    return u - s;
}

/* F_g(0) = (1-g)(c0 d0 + c1 (P0 + 3a) a) / (V0 cn (V1 + V0) d0),
 * P0 = V0 V1, d0 = 3 (P0 + a)^2: the u <= 0 form at u = 0. */
MIST__F MIST__T MIST__FN(mist__draine_f0)(MIST__T g, MIST__T c0, MIST__T c1)
{
    MIST__T v1 = MIST__C(1) + g, a = MIST__C(1) + g * g, v0 = MIST__M(sqrt)(a);
    MIST__T cn = c0 + c1 * (a + g * g) / MIST__C(3), p = v0 * v1, d = p + a;
    d = MIST__C(3) * d * d;
    return (MIST__C(1) - g) * (c0 * d + c1 * (p + MIST__C(3) * a) * a)
           / (v0 * cn * (v1 + v0) * d);
}

/* Safeguarded Newton for F_g(u) = x, x in (0, 1/2], |g| < 1, in this pass's
 * type: at most n steps from *u inside the bracket [-1, 1] (a step that
 * leaves it, or is NaN or inf, bisects).  F is the u <= 0 or u >= 0 form
 * by the sign of the iterate (both are accurate near 0); t0 = F(0) - x
 * where known (have0), else computed at the first iterate u > 0.  A step
 * costs one square root and one division on its critical path: r = F - x
 * and s = r / f are formed from F's numerator and denominator, with
 * f = dF/du = (1-g^2)(c0 + c1 u^2) / (2 cn V^3).
 * Converged (returns 1) when the error left is below tol (|u| + x / f):
 * the step itself or, where Newton's quadratic model holds, the predicted
 * next step ~ |f'/f| s^2 / 2 (f'/f = 3g/V^2 + 2 c1 u/(c0 + c1 u^2), bounded
 * over the whole step), so a good start costs one evaluation.  Either is
 * trusted only where f changes by less than 1/4 over the step (its weight
 * c0 + c1 u^2 exactly, its HG factor by 3 g s / V^2), and f is taken at
 * the step's larger end: with alpha -> inf the density is ~u^2 near u = 0,
 * and f at an iterate there says nothing about f at the root (a stop on
 * the iterate's f alone returned -0.0208 for -0.00366 at g = 0, alpha =
 * 2^20 in float).  All in this pass's type; the callers run it in T to T's
 * noise (tol 16 eps) and then in the wide type (tol eps_T / 64).
 * Where the model is not valid the next iterate comes from the step in a
 * better variable (mist__draine_next: 1/V, or the weight's integral); a
 * step below half an ulp that does not stop moves to the neighbour, and a
 * return to the iterate of two steps before (a cycle within the
 * residual's noise) bisects: linear creeping was the worst case's cost
 * (bench/mist_worst.c). */
MIST__F int MIST__FN(mist__draine_newton)(MIST__T g, MIST__T c0, MIST__T c1, MIST__T x,
                                          MIST__T t0, int have0, MIST__T tol, int n,
                                          MIST__T *up)
{
    MIST__T u = *up, lo = MIST__C(-1), hi = MIST__C(1);
    MIST__T v1 = MIST__C(1) + g, omg = MIST__C(1) - g, a = MIST__C(1) + g * g;
    MIST__T v0 = MIST__M(sqrt)(a), omg2 = omg * v1;
    MIST__T cn = c0 + c1 * (a + g * g) / MIST__C(3);
    MIST__T ag = g < MIST__C(0) ? -g : g, t0d = MIST__C(1), u2 = MIST__C(2);
    int it, valid;
    if (!have0) t0 = MIST__C(0);
    for (it = 0; it < n; ++it) {
        MIST__T v2 = MIST__FN(mist__v2)(g, u), v = MIST__M(sqrt)(v2);
        MIST__T wt = c0 + c1 * u * u, dd, r, s, as, un, w1, m, tl, k;
        if (u > MIST__C(0)) {      /* F(0) + (c0 dH + c1 dM2) / cn */
            MIST__T sp = v0 + v;
            if (!have0) {          /* F(0) - x = t0 / t0d: see mist__draine_f0 */
                MIST__T p0 = v0 * v1, d0 = p0 + a;
                d0 = MIST__C(3) * d0 * d0;
                t0d = v0 * cn * (v1 + v0) * d0;
                t0  = omg * (c0 * d0 + c1 * (p0 + MIST__C(3) * a) * a) - x * t0d;
                have0 = 1;
            }
            dd = MIST__C(3) * sp * sp * sp * v0;
            r  = t0 * (v * cn * dd) + t0d * omg2 * u * (MIST__C(3) * sp * sp * c0
                 + c1 * u * u * (MIST__C(2) * a + v0 * sp));
            dd *= t0d;             /* r = (F - x) V cn dd, as below */
        } else {                   /* K (c0 + c1 Qp / (3 (P+a)^2)) / cn */
            MIST__T p = v * v1, pa = p + a, d = MIST__C(3) * pa * pa;
            MIST__T qp = (p + MIST__C(3) * a) * (v2 + a * u * u)
                       - u * v * (v * (v1 * v1 + MIST__C(3) * a) - MIST__C(2) * g * u * v1);
            dd = (v1 + v) * d;
            r  = omg * (MIST__C(1) + u) * (c0 * d + c1 * qp) - x * (v * cn * dd);
        }                          /* r = (F - x) V cn dd */
        if (r == MIST__C(0)) break;            /* (selects, not branches: r's */
        hi = r > MIST__C(0) ? u : hi;          /*  sign is random in xi)      */
        lo = r < MIST__C(0) ? u : lo;
        s  = r * v2 * (MIST__C(1) / (MIST__C(0.5) * omg2 * wt * dd));  /* (F - x) / f;
                                                  the division overlaps r's terms */
        as = s < MIST__C(0) ? -s : s;
        w1 = MIST__C(2) * u - s;
        valid = c1 * as * (w1 < MIST__C(0) ? -w1 : w1) <= MIST__C(0.25) * wt
                && MIST__C(3) * ag * as <= MIST__C(0.25) * v2;
        un = valid ? u - s : MIST__FN(mist__draine_next)(g, c0, c1, u, s, v2, v);
        if (!(un >= lo && un <= hi)) {                /* left the bracket: bisect */
            un = MIST__C(0.5) * (lo + hi);
            if (un == lo || un == hi) break;          /* bracket is 1 ulp */
            u2 = u;
            u = un;
            continue;
        }
        /* Valid model: |w1 - wt| = c1 |s| |2u - s| <= wt/4 (w1 = c0 + c1
         * un^2: w >= 3/4 wt over the step) and 3 |g s| <= V^2/4 (V^2 >=
         * 5/6 v2 over the step).  Then converged when as = |s| <= tl =
         * tol (|un| + x / f), f taken at the weight m = 5/4 wt >= w1, or
         * 2 K as^2 <= tl with K >= |f'/f| over the whole step,
         * K = (3.6 |g| / v2 + 2 c1 (|u| + as) / (3/4 wt)): f'/f at u alone
         * misses its growth over a step away from u = 0 (alpha 250, g
         * 1e-7: 14x the bar).  Multiplied out, with |un| >= |u| - as, so
         * that all but a few operations are done before s is known. */
        m  = omg2 * MIST__C(1.25) * wt;
        w1 = u < MIST__C(0) ? -u : u;
        tl = tol * (w1 * m + MIST__C(2) * x * v * cn * v2);
        k  = MIST__C(2.7) * ag * wt + MIST__C(2) * c1 * (w1 + as) * v2;   /* K 3/4 v2 wt */
        if (valid
            && (as * m * (MIST__C(1) + tol) <= tl
                || as * (MIST__C(2) * k * as * m + MIST__C(0.75) * tol * m * v2 * wt)
                   <= MIST__C(0.75) * tl * v2 * wt)) {
            *up = un;
            return 1;
        }
        if (un == u) {             /* a step below half an ulp that did not stop:
                                    * the neighbour, else the same step again
                                    * (next to u = -+1 at |g| -> 1, where the
                                    * peak is narrower than an ulp, 64 steps at
                                    * one u, in T and again in W) */
            un = MIST__M(nextafter)(u, s > MIST__C(0) ? MIST__C(-2) : MIST__C(2));
            if (!(un > lo && un < hi)) break;   /* the bracket is 1 ulp */
        } else if (un == u2) {     /* back to where it was two steps ago (a
                                    * cycle within the residual's noise, near
                                    * u = 0 at large alpha): bisect */
            un = MIST__C(0.5) * (lo + hi);
            if (un == lo || un == hi) break;
        }
        u2 = u;
        u = un;
    }
    *up = u;
    return it < n;                              /* exact hit (r = 0) */
}

/* The residual's sign at u for the rounding of mist__draine_round: > 0 when
 * F_g(u) > xi (the root lies below u), < 0 when it lies above: the u <= 0
 * form of mist__draine_newton, mirrored for xi > 1/2, r = S (F_g(u)
 * - xi) with S = V cn (v1 + V) d > 0.  For a fixed u it is non-increasing
 * in xi however it rounds (r = A - fl(xi B), B > 0), so decisions taken by
 * it at one u are monotone in xi.  *sc (unless NULL): the sum of the
 * magnitudes of its terms, so that its rounding error is below 32 eps sc (a
 * few dozen roundings, each relative to a term: all factors are sums of
 * non-negative terms but the one difference in Qp, whose two terms sc
 * counts separately; inputs exact, or u any double: one more rounding, in
 * 1 + u; measured in double against __float128 at 3e5 points near the
 * roots of the certificate's domain: at most 8.2 eps sc).  *fs (unless
 * NULL): S f V^2, f = F_g'(u) = (1 - g^2) w V^-3 / (2 cn), w = c0 + c1 u^2
 * (r and fs: mist__draine_step's Newton step, u - r V^2 / fs). */
MIST__F MIST__HOT MIST__T MIST__FN(mist__draine_res)(MIST__T g, MIST__T c0, MIST__T c1, MIST__T xi,
                                                     MIST__T st, MIST__T *sc, MIST__T *fs)
{
    MIST__T sg = MIST__C(1) - MIST__C(2) * (MIST__T)(xi > MIST__C(0.5));  /* mirror: -1 */
    MIST__T u = sg * st, gg = sg * g, x = MIST__C(0.5) * (MIST__C(1) - sg) + sg * xi;
    MIST__T v2 = MIST__FN(mist__v2)(g, st), v = MIST__M(sqrt)(v2);
    MIST__T v1 = MIST__C(1) + gg, omg = MIST__C(1) - gg, a = MIST__C(1) + g * g;
    MIST__T cn = c0 + c1 * (a + g * g) / MIST__C(3);
    MIST__T p = v * v1, pa = p + a, d = MIST__C(3) * pa * pa;
    MIST__T q1 = (p + MIST__C(3) * a) * (v2 + a * u * u);
    MIST__T q2 = u * v * (v * (v1 * v1 + MIST__C(3) * a) - MIST__C(2) * gg * u * v1);
    MIST__T k = omg * (MIST__C(1) + u), b = x * (v * cn * ((v1 + v) * d));
    if (sc) *sc = k * (c0 * d + c1 * (q1 + MIST__FN(mist__abs)(q2))) + b;
    if (fs) *fs = MIST__C(0.5) * ((omg * v1) * (c0 + c1 * u * u)) * ((v1 + v) * d);
    return sg * (k * (c0 * d + c1 * (q1 - q2)) - b);
}

/* The prepared sampler's common path: ONE Newton step from the table's
 * start st, straight-line (no branch on xi, so that independent samples
 * pipeline as eq. 6's straight-line code does), with an a-priori stop.
 * xi in [0, 1]; the mirror xi > 1/2 (F_-g(-u) = 1 - xi, exact) is taken by
 * selects.  F is the u <= 0 form of mist__draine_newton at every u: for
 * u > 0 its one difference (in Qp) cancels by at most ~3x (Qp >= 0: it is
 * the integral of u^2 times HG), harmless in the wide type this runs in.
 * Newton's error: u1 - u* = f'(z) e^2 / (2 f(u0)), e = u0 - u* = s f(u0) /
 * f(z') (z, z' between u0 and u*), so |u1 - u*| <= kb s^2 with kb =
 * max|f'| max f^2 / (2 min f^3) over an interval holding u0 and u*
 * (mist__draine_kb; both lie in the table interval of xi, widened for
 * rounding).  *ok: that bound is below tol (|u1| + x / f(u0)); *eb: the
 * bound kb s^2.  Returns u1 (NaN or inf with *ok = 0 where f = 0). */
MIST__F MIST__HOT MIST__T MIST__FN(mist__draine_step)(MIST__T g, MIST__T c0, MIST__T c1, MIST__T xi,
                                            MIST__T st, MIST__T kb, MIST__T tol, int *ok,
                                            MIST__T *eb)
{
    MIST__T sg = MIST__C(1) - MIST__C(2) * (MIST__T)(xi > MIST__C(0.5));  /* mirror: -1 */
    MIST__T u = sg * st, gg = sg * g, x = MIST__C(0.5) * (MIST__C(1) - sg) + sg * xi;
    MIST__T v2 = MIST__FN(mist__v2)(g, st), v = MIST__M(sqrt)(v2);   /* = V(gg, u) */
    MIST__T a = MIST__C(1) + g * g, cn = c0 + c1 * (a + g * g) / MIST__C(3);
    MIST__T m = ((MIST__C(1) - gg) * (MIST__C(1) + gg)) * (c0 + c1 * u * u), fs, r, s, un;
    r = sg * MIST__FN(mist__draine_res)(g, c0, c1, xi, st, MIST__NULL, &fs);   /* unmirrored */
    s = r * v2 / fs; un = u - s;                                  /* (F - x) / f */
    *eb = kb * s * s;
    *ok = *eb * m <= tol * (MIST__FN(mist__abs)(un) * m
                            + MIST__C(2) * x * cn * v2 * v);
    return sg * un;
}

/* kb of mist__draine_step for u in [lo, hi]: f = A w h with w = c0 + c1 u^2
 * (monotone on each side of 0) and h = V^-3 (monotone: V^2 is linear in
 * u), so min f >= A min w min h and max f <= A max w max h, and |f'| =
 * A |2 c1 u h + 3 g w h / V^2| <= A (2 c1 max|u| + 3 |g| max w / min V^2)
 * max h; as ratios (no overflow as g -> 1), times 1.25 for the rounding of
 * this bound and of the step (a few ulps of the type it runs in).  +inf or
 * NaN where min f = 0 (alpha = inf at u = 0): never accepted there. */
MIST__F MIST__T MIST__FN(mist__draine_kb)(MIST__T g, MIST__T c0, MIST__T c1, MIST__T lo,
                                          MIST__T hi)
{
    MIST__T va = MIST__FN(mist__v2)(g, lo), vb = MIST__FN(mist__v2)(g, hi);
    MIST__T vl = va < vb ? va : vb, vh = va < vb ? vb : va, rh = vh / vl * MIST__M(sqrt)(vh / vl);
    MIST__T al = lo < MIST__C(0) ? -lo : lo, ah = hi < MIST__C(0) ? -hi : hi;
    MIST__T um = al > ah ? al : ah, un = lo <= MIST__C(0) && hi >= MIST__C(0)
                                         ? MIST__C(0) : (al < ah ? al : ah);
    MIST__T wl = c0 + c1 * un * un, rw = (c0 + c1 * um * um) / wl, ag = g < MIST__C(0) ? -g : g;
    return MIST__C(1.25) * rh * (MIST__C(2) * c1 * um / wl + rw * MIST__C(3) * ag / vl)
           * (rh * rw) * (rh * rw) / MIST__C(2);
}
#endif /* !MIST_NO_DRAINE */

#if defined(MIST__DDR) && !defined(MIST_NO_DRAINE)
/* DOUBLE-DOUBLE FINISH (double where fma is one instruction or long double
 * is no wider; see "Draine and Cornette-Shanks: exact sampling").
 * Compensated arithmetic: a value is a pair h + l, l its error to first
 * order (products' roundings by fma or Dekker's product, sums' by two-sum; the products of two errors, ~eps^2 of the value, are
 * dropped).  h + *l = (ah + al)(bh + bl): */
MIST__F MIST__HOT MIST__T MIST__FN(mist__cm)(MIST__T ah, MIST__T al, MIST__T bh, MIST__T bl,
                                             MIST__T *l)
{
    MIST__T e, p = MIST__FN(mist__two_prod_b)(ah, bh, &e);
    *l = MIST__FN(mist__fma)(ah, bl, MIST__FN(mist__fma)(al, bh, e));
    return p;
}
/* h + *l = a (bh + bl), a exact */
MIST__F MIST__HOT MIST__T MIST__FN(mist__cs)(MIST__T a, MIST__T bh, MIST__T bl, MIST__T *l)
{
    MIST__T e, p = MIST__FN(mist__two_prod_b)(a, bh, &e);
    *l = MIST__FN(mist__fma)(a, bl, e);
    return p;
}
/* h + *l = (ah + al) + (bh + bl) */
MIST__F MIST__HOT MIST__T MIST__FN(mist__ca)(MIST__T ah, MIST__T al, MIST__T bh, MIST__T bl,
                                             MIST__T *l)
{
    MIST__T e, s = MIST__FN(mist__two_sum)(ah, bh, &e);
    *l = e + (al + bl);
    return s;
}

/* mist__draine_res in compensated arithmetic, at u = uh + ul (a double, or
 * the midpoint of two: |ul| <= ulp(uh) / 2), weights c0, c1 and g, xi
 * exact: the same terms, each a pair.  Its error: ~2 eps^2 per operation
 * relative to the operation's terms, all non-negative but the one
 * difference in Qp, ~40 operations: below 2^-96 sc (*sc as in
 * mist__draine_res), against 8 eps sc = 2^-50 sc in double.  *fs: S f V^2
 * and *v2: V^2, in double. */
MIST__F MIST__HOT MIST__T MIST__FN(mist__draine_resc)(MIST__T g, MIST__T c0, MIST__T c1,
                                                      MIST__T xi, MIST__T uh, MIST__T ul,
                                                      MIST__T *sc, MIST__T *fs, MIST__T *v2)
{
    MIST__T sg = MIST__C(1) - MIST__C(2) * (MIST__T)(xi > MIST__C(0.5));  /* mirror: -1 */
    MIST__T gg = sg * g, x = MIST__C(0.5) * (MIST__C(1) - sg) + sg * xi;  /* exact */
    MIST__T ag = MIST__M(fabs)(g), sn = MIST__M(copysign)(MIST__C(1), g);
    MIST__T oh, ol, th, tl, wh, wl, vh, vl, v1h, v1l, mh, ml, g2h, g2l, ah, al, nh, nl, qh, ql;
    MIST__T cnh, cnl, ph, pl, dh, dl, a3h, a3l, eh, el, zh, zl, q1h, q1l, q2h, q2l, kh, kl;
    MIST__T bh, bl;
    /* V^2 = (1 - |g|)^2 + 2 |g| (1 - sgn(g) u) at the unmirrored u (mist__v2) */
    oh = MIST__FN(mist__fast_two_sum)(MIST__C(1), -ag, &ol);
    oh = MIST__FN(mist__cm)(oh, ol, oh, ol, &ol);
    th = MIST__FN(mist__fast_two_sum)(MIST__C(1), -sn * uh, &tl);
    th = MIST__FN(mist__fast_two_sum)(th, tl - sn * ul, &tl);   /* renormalised: */
    /* near u = sgn(g) ul is no first-order term beside 1 - sgn(g) u (the
     * square root's first-order low part then erred by 1e-7 relative) */
    th = MIST__FN(mist__cs)(MIST__C(2) * ag, th, tl, &tl);
    wh = MIST__FN(mist__ca)(oh, ol, th, tl, &wl);
    *v2 = wh;
    vh = MIST__M(sqrt)(wh);                                           /* V */
    vl = (MIST__FN(mist__fms)(vh, vh, wh) + wl) / (MIST__C(2) * vh);
    uh *= sg; ul *= sg;                                               /* mirrored */
    v1h = MIST__FN(mist__fast_two_sum)(MIST__C(1), gg, &v1l);         /* 1 + gg */
    mh = MIST__FN(mist__fast_two_sum)(MIST__C(1), -gg, &ml);          /* 1 - gg */
    g2h = MIST__FN(mist__two_prod_b)(g, g, &g2l);
    ah = MIST__FN(mist__fast_two_sum)(MIST__C(1), g2h, &al);          /* a = 1 + g^2 */
    al += g2l;
    nh = MIST__FN(mist__fast_two_sum)(MIST__C(1), MIST__C(2) * g2h, &nl);
    nl += MIST__C(2) * g2l;                                           /* 1 + 2 g^2 */
    qh = nh / MIST__C(3);
    ql = (MIST__FN(mist__fms)(qh, MIST__C(3), nh) + nl) / MIST__C(3);
    qh = MIST__FN(mist__cs)(c1, qh, ql, &ql);
    cnh = MIST__FN(mist__ca)(c0, MIST__C(0), qh, ql, &cnl);          /* cn */
    ph = MIST__FN(mist__cm)(vh, vl, v1h, v1l, &pl);                   /* P = V v1 */
    dh = MIST__FN(mist__ca)(ph, pl, ah, al, &dl);                     /* P + a */
    dh = MIST__FN(mist__cm)(dh, dl, dh, dl, &dl);
    dh = MIST__FN(mist__cs)(MIST__C(3), dh, dl, &dl);                 /* d */
    a3h = MIST__FN(mist__cs)(MIST__C(3), ah, al, &a3l);               /* 3a */
    eh = MIST__FN(mist__ca)(ph, pl, a3h, a3l, &el);                   /* P + 3a */
    zh = MIST__FN(mist__cm)(uh, ul, uh, ul, &zl);                     /* u^2 */
    zh = MIST__FN(mist__cm)(ah, al, zh, zl, &zl);
    zh = MIST__FN(mist__ca)(wh, wl, zh, zl, &zl);                     /* V^2 + a u^2 */
    q1h = MIST__FN(mist__cm)(eh, el, zh, zl, &q1l);
    eh = MIST__FN(mist__cm)(v1h, v1l, v1h, v1l, &el);                 /* v1^2 */
    eh = MIST__FN(mist__ca)(eh, el, a3h, a3l, &el);
    eh = MIST__FN(mist__cm)(vh, vl, eh, el, &el);                     /* V (v1^2 + 3a) */
    zh = MIST__FN(mist__cm)(uh, ul, v1h, v1l, &zl);
    zh = MIST__FN(mist__cs)(MIST__C(-2) * gg, zh, zl, &zl);           /* -2 gg u v1 */
    eh = MIST__FN(mist__ca)(eh, el, zh, zl, &el);
    zh = MIST__FN(mist__cm)(uh, ul, vh, vl, &zl);                     /* u V */
    q2h = MIST__FN(mist__cm)(zh, zl, eh, el, &q2l);
    kh = MIST__FN(mist__fast_two_sum)(MIST__C(1), uh, &kl);           /* 1 + u */
    kh = MIST__FN(mist__fast_two_sum)(kh, kl + ul, &kl);
    kh = MIST__FN(mist__cm)(mh, ml, kh, kl, &kl);                     /* k */
    eh = MIST__FN(mist__ca)(q1h, q1l, -q2h, -q2l, &el);               /* Qp */
    eh = MIST__FN(mist__cs)(c1, eh, el, &el);
    zh = MIST__FN(mist__cs)(c0, dh, dl, &zl);
    eh = MIST__FN(mist__ca)(zh, zl, eh, el, &el);
    eh = MIST__FN(mist__cm)(kh, kl, eh, el, &el);                     /* A = S F */
    bh = MIST__FN(mist__ca)(v1h, v1l, vh, vl, &bl);
    bh = MIST__FN(mist__cm)(bh, bl, dh, dl, &bl);
    bh = MIST__FN(mist__cm)(cnh, cnl, bh, bl, &bl);
    bh = MIST__FN(mist__cm)(vh, vl, bh, bl, &bl);
    bh = MIST__FN(mist__cs)(x, bh, bl, &bl);                          /* B = S x */
    *sc = kh * (c0 * dh + c1 * (q1h + MIST__M(fabs)(q2h))) + bh;
    *fs = MIST__C(0.5) * (mh * v1h) * (c0 + c1 * uh * uh) * ((v1h + vh) * dh);
    return sg * ((eh - bh) + (el - bl));
}

/* One step of mist__draine_ddfin (see there) at u, straight-line (no
 * branch: the prepared double batch vectorises it): 1 where it settles
 * (*out: u where the residual is within its error, else the trusted
 * window's answer), 0 where it does not (*rp, *sp: the residual and the
 * step, *uhp: u - s rounded, *lop, *hip: the window's ends, both *uhp where
 * the model is not trusted), -1 where the residual is NaN or its scale sc
 * is not finite (a term overflowed: r = -inf passed the test of r against
 * sc = +inf; the weights are scaled so that none does: mist__draine_cx). */
MIST__F MIST__HOT int MIST__FN(mist__draine_dd1)(MIST__T g, MIST__T c0, MIST__T c1, MIST__T xi,
                                                MIST__T u, MIST__T *out, MIST__T *rp,
                                                MIST__T *sp, MIST__T *uhp, MIST__T *lop,
                                                MIST__T *hip)
{
    MIST__T ag = MIST__M(fabs)(g), r, sc, fs, v2, iv, iw, s, as, au, wt, k, e, uh, ul, lo, hi;
    MIST__T ew;
    int tiny, valid, bad;
    r = MIST__FN(mist__draine_resc)(g, c0, c1, xi, u, MIST__C(0), &sc, &fs, &v2);
    iv = v2 / fs;                         /* 1 / (S f): with the hi parts, before r */
    s = r * iv;                                           /* (F - xi) / f */
    as = MIST__M(fabs)(s); au = MIST__M(fabs)(u); wt = c0 + c1 * u * u;
    iw = MIST__C(1) / wt;
    uh = MIST__FN(mist__two_sum)(u, -s, &ul);
    valid = (MIST__C(16) * c1 * as * (au + as) <= wt) & (MIST__C(24) * ag * as <= v2);
    k = MIST__C(3.6) * ag / v2 + MIST__C(2.67) * c1 * (au + MIST__C(2) * as) * iw;
    e = MIST__C(2.5) * k * s * s + (MIST__C(8.077935669463161e-28) * sc * iv   /* 2^-90 */
                                    + MIST__C(3.552713678800501e-15) * as);    /* 2^-48 */
    ew = MIST__C(1.01) * e + MIST__C(8.881784197001252e-16) * MIST__M(fabs)(ul);  /* 2^-50 */
    lo = uh + (ul - ew); hi = uh + (ul + ew);
    tiny = !(MIST__M(fabs)(r) > MIST__C(8.077935669463161e-28) * sc);  /* 2^-90; NaN */
    ew = lo == hi ? lo : uh;              /* (two selects, not nested, and the */
    *out = tiny ? u : ew;                 /*  NaN code by arithmetic: else gcc */
    *rp = r; *sp = s; *uhp = uh;          /*  branches and will not vectorise) */
    *lop = valid ? lo : uh; *hip = valid ? hi : uh;
    tiny |= valid & ((lo == hi) | (e <= MIST__C(3.469446951953614e-18) * sc * iv));  /* 2^-58 */
    bad = (r != r) | !(sc <= MIST__BIG);  /* a term overflowed: no test above holds */
    return (tiny | bad) - 2 * bad;
}

/* The root of F_g(u) = xi (sanitised |g| < 1, weights c0, c1 exact and
 * finite, xi in (0, 1)) from a double u near it, by Newton steps with the
 * compensated residual: 1 with the sample in *out, else 0 (not settled in
 * 64 steps: the caller goes on as without it).  Steps that leave the
 * bracket the residual's signs keep bisect it; a step that rounds back to
 * u (where the model is not trusted: V^2 varies fast next to u = +-1 for
 * |g| -> 1) probes the neighbour; a bracket of two adjacent doubles is
 * decided by the residual's sign at their midpoint (the root next to +-1
 * within an ulp: those steps had bisected from [-1, 1] and stalled there,
 * 11 of 2e4 random samples an ulp off without long double, measured with
 * bench/mist_ddcheck.c).  A step s = r / f lands on uw = u - s, exact as
 * the pair (uh, ul); its error is
 * bounded by e = 2.5 K s^2 (Newton's, with K >= |f'/f| over u +- 2|s|,
 * which holds the root: there w = c0 + c1 u^2 stays within wt/4 of its
 * value at u and V^2 within V^2/6, so f within [0.59, 1.65] f(u) and
 * e <= max|f'| f(u) s^2 / (2 min f^2) <= 2.32 K s^2) plus the residual's
 * error over f (2^-90 sc / f) and the step's own rounding (2^-48 |s|).
 * Then: uw - e and uw + e round alike: that is the root correctly rounded;
 * or they round to adjacent doubles: the compensated residual's sign at
 * their midpoint picks one (as mist__draine_pick: monotone in xi at a
 * fixed point); or e <= eps/8 xi / f (near u = 0 at large alpha, where
 * the bar's xi term is the larger): uw rounded, within the bar and
 * monotone in xi (adjacent xi move the root by >= eps xi / f, 4x the two
 * errors).  Else another step, from uh or, where the model does not hold,
 * from the step in a better variable (mist__draine_next). */
MIST__F int MIST__FN(mist__draine_ddfin)(MIST__T g, MIST__T c0, MIST__T c1, MIST__T xi,
                                         MIST__T u, MIST__T *out)
{
    MIST__T bl = MIST__C(-1), bh = MIST__C(1), r, s, uh, ul, lo, hi;
    int it, c;
#if !defined(MIST__FAST_FMA) && !defined(__CUDA_ARCH__)
    {   /* Dekker's product (mist__two_prod_b) needs bounded factors: the
         * weights scaled by a power of 2 to a larger one in [1/2, 1), which
         * scales the residual and leaves the steps and their tests as they
         * were, exactly (with alpha up to 1e270 unscaled, the products
         * needed mist__two_prod's overflow tests: 142-147 against 122-125
         * ns unprepared, 133-146 against 110-117 prepared, gcc 12 -O2,
         * MIST_NO_LONG_DOUBLE; measured) */
        int e;
        MIST__M(frexp)(c0 > c1 ? c0 : c1, &e);
        c0 = MIST__M(ldexp)(c0, -e);
        c1 = MIST__M(ldexp)(c1, -e);
    }
#endif
    for (it = 0; it < MIST__MAXIT; ++it) {
        c = MIST__FN(mist__draine_dd1)(g, c0, c1, xi, u, out, &r, &s, &uh, &lo, &hi);
        if (c) return c > 0;
        bh = r > MIST__C(0) ? u : bh;                     /* the bracket */
        bl = r < MIST__C(0) ? u : bl;
        if (lo != hi && MIST__M(nextafter)(lo, MIST__C(2)) == hi) {
            bl = lo; bh = hi;             /* the window: two adjacent doubles */
        }
        if (MIST__M(nextafter)(bl, MIST__C(2)) == bh) {   /* the root between two */
            MIST__T sc, fs, v2;                           /* adjacent doubles */
            r = MIST__FN(mist__draine_resc)(g, c0, c1, xi, bl, MIST__C(0.5) * (bh - bl),
                                            &sc, &fs, &v2);
            *out = r > MIST__C(0) ? bl : bh;
            return 1;
        }
        {                                 /* the step in the variable that suits it */
            MIST__T v2 = MIST__FN(mist__v2)(g, u);
            uh = MIST__FN(mist__draine_next)(g, c0, c1, u, s, v2, MIST__M(sqrt)(v2));
            uh = uh == u - s ? MIST__FN(mist__two_sum)(u, -s, &ul) : uh;
        }
        if (uh == u)                      /* a step below half an ulp: the neighbour */
            uh = MIST__M(nextafter)(u, s > MIST__C(0) ? MIST__C(-2) : MIST__C(2));
        u = uh > bl && uh < bh ? uh : MIST__C(0.5) * (bl + bh);   /* else bisect */
    }
    return 0;
}
#endif

#ifndef MIST__INTERNAL_ONLY
/* Blocks for the vectorised loops (the batch forms; the Draine kernel that
 * also builds a prepared table's nodes). */
/* 32: gcc -O3 completely unrolls loops of up to 16 iterations before it
 * vectorises, and the unrolled, branchy code no longer vectorises. */
#define MIST__BLK 32
/* Runs STMT (which sets y_[j_] from x_[j_]) over in[0..n) in blocks. */
#define MIST__BLOCKS(STMT) MIST__BLOCKS_FB(STMT, 0, (void)0)
/* The same; where NEED, STMT may set f_[j_] != 0 to have FIX (branchy;
 * x_[j_] is the element's input, out[i_ + j_] its place, already holding
 * y_[j_]) redo that element after the block is stored.  The flags are
 * short: gcc takes the vectorisation factor from the narrowest type in the
 * loop, and with one-byte flags it made it 32, the whole block at once,
 * each double 8 registers (spills, and a body of 40 KB for the double
 * Draine kernel); short flags (16) were the fastest of char, short and
 * int (gcc 12 -O3 -march=native, AVX-512 and AVX2: 0.85-0.93x the time of
 * one-byte flags an element, and 0.85x the code). */
#define MIST__BLOCKS_FB(STMT, NEED, FIX)                                     \
    {   MIST__T x_[MIST__BLK], y_[MIST__BLK];                                \
        short f_[MIST__BLK];                                                 \
        size_t i_, j_, m_;                                                   \
        for (i_ = 0; i_ < n; i_ += m_) {                                     \
            m_ = n - i_;                                                     \
            if (m_ >= MIST__BLK) {                                           \
                m_ = MIST__BLK;                                              \
                for (j_ = 0; j_ < MIST__BLK; ++j_) x_[j_] = in[i_ + j_];     \
            } else {                                                         \
                for (j_ = 0; j_ < MIST__BLK; ++j_)                           \
                    x_[j_] = j_ < m_ ? in[i_ + j_] : MIST__C(0);             \
            }                                                                \
            for (j_ = 0; j_ < MIST__BLK; ++j_) { STMT; }                     \
            if (m_ == MIST__BLK)                                             \
                for (j_ = 0; j_ < MIST__BLK; ++j_) out[i_ + j_] = y_[j_];    \
            else                                                             \
                for (j_ = 0; j_ < m_; ++j_) out[i_ + j_] = y_[j_];           \
            if (NEED)                                                        \
                for (j_ = 0; j_ < m_; ++j_) if (f_[j_]) { FIX; }             \
        } }

#ifndef MIST_NO_DRAINE
#ifdef MIST__W
/* The half-width of the window a step's u1 is rounded within: its bound
 * eb twice, and W's rounding of u1 (|u| eps_T / 512 >= 4 ulp of W): ~2^-9
 * of an ulp of T, so the rounding by the residual is rare. */
MIST__F MIST__HOT MIST__W MIST__FN(mist__draine_win)(MIST__W uw, MIST__W eb)
{
    return 2 * eb + MIST__WFN(mist__abs)(uw) * ((MIST__W)MIST__EPS / 512);
}

/* uw, the wide solution at xi in [0, 1] (within eps_T / 64 (|u| + xi/f) of
 * the root, by the stops of mist__draine_newton and _step), rounded to T
 * monotonically in xi.  Plain rounding is not: where a rounding boundary
 * (the midpoint between two T values) lies within uw's error, xi and its
 * successor could round to opposite sides (g = 0x1.ffea16p-1, alpha = 2^32
 * in float: u* = 1 - 2^-25 - 4.5e-11 rounded up to 1 at xi = 0x1.2116e4p-1
 * and down at 0x1.2116e6p-1 ... 0x1.211712p-1, by errors of ~1e-11 that
 * vary in xi).  So where the window uw +- w (w: the error bound; eps_T
 * |uw| / 16 after mist__draine_newton, 4x its stop's |u| term) holds a
 * boundary, the residual's sign there picks the side (mist__draine_res:
 * monotone in xi at a fixed point, and far more exact than the window).
 * One more evaluation of F, for the window's share of an ulp of the
 * samples (1/16 to 1/8 after the solver, ~2^-9 after the prepared step).
 * Where xi/f dominates |u| (u within ~xi/f of 0) the solver's error may
 * exceed its window: there uw itself must be monotone. */
/* of lo and hi, the values of T at either end of the window, the one the
 * residual's sign at their midpoint picks (exact in W) */
MIST__F MIST__HOT MIST__T MIST__FN(mist__draine_pick)(MIST__W g, MIST__W c0, MIST__W c1,
                                                      MIST__W xi, MIST__T lo, MIST__T hi)
{
    MIST__W mid = (MIST__W)0.5 * ((MIST__W)lo + (MIST__W)hi);
    return MIST__WFN(mist__draine_res)(g, c0, c1, xi, mid, MIST__NULL, MIST__NULL) > 0
           ? lo : hi;
}
MIST__F MIST__T MIST__FN(mist__draine_round)(MIST__T g, MIST__W c0, MIST__W c1, MIST__T xi,
                                             MIST__W uw, MIST__W w)
{
    MIST__T lo = (MIST__T)(uw - w), hi = (MIST__T)(uw + w);
    if (lo == hi) return lo;
    return MIST__FN(mist__draine_pick)((MIST__W)g, c0, c1, (MIST__W)xi, lo, hi);
}
#endif

/* Where a prepared table's start is used (sanitised g): |g| <= 0.9999.
 * Beyond, its first and last intervals span nearly [-1, 1], and the steps
 * from the far side of the root crept: Newton in double stopped at 1 for
 * 1 - 1.2e-13 (g = 1 - 2^-40, alpha = 1e4, xi = 0x1.0fe683p-18), and the
 * compensated steps took 54 (g = 1 - 2^-46, xi 1e-3); there the HG answer
 * is the better start (mist__draine_solve). */
MIST__F int MIST__FN(mist__phase_tab)(MIST__T g)
{
    return MIST__FN(mist__abs)(g) <= MIST__C(0.9999);
}

/* 1 where the table's interval j spans more than half of [-1, 1] (the
 * first or last one at |g| -> 1, the lobe's far side): its cubic start may
 * lie across the peak from the root, and the steps from there bisected
 * towards it (g 0.9999, alpha DBL_MAX, xi 1e-3: 8 compensated steps, 1.5
 * us without fma).  The double samplers start there as without a table
 * (eq. 6 or the HG answer: mist__draine_solve). */
MIST__F MIST__HOT int MIST__FN(mist__phase_wide)(const MIST__T *tab, int j)
{
    return tab[j + 1] - tab[j] > MIST__C(1);
}

/* Where [JD23 eq. 6] in double is a good start (sanitised g, alpha): within
 * 1.3e-5 of the root there (see mist__draine_solve). */
MIST__F int MIST__FN(mist__draine_ok6)(MIST__T g, MIST__T alpha)
{
    MIST__T ag = MIST__FN(mist__abs)(g);
    return ag >= MIST__C(1e-3) && ag <= MIST__C(0.9999) && alpha >= MIST__C(1e-6)
           && alpha <= MIST__C(1e4);
}

/* Where the unprepared samplers' first try takes eq. 6's answer (and the
 * batch kernel runs): double, eq. 6's domain above, where its one
 * compensated step settles from that start; float, wider: the certificate
 * (mist__draine_cert) proves each answer it accepts for any |g| < 1 and
 * finite alpha > 0, and there eq. 6 in double is good enough for it to
 * accept all of 2e4 random xi at each of |g| 0.999 ... 1 - 25 2^-24 and
 * alpha 1e-12 ... 1e20 (97% at 1 - 20 2^-24, 88.6% at 1 - 17 2^-24 =
 * 0.999998987, 12% at 1 - 2 2^-24), 99.5-100% at |g| 1e-3 ... 0.5 and
 * alpha 1e-12 ... 1e-6, 91-99.9% at |g| 0.5 ... 0.99 and alpha 1e4 ...
 * 1e20 (flat in alpha beyond 1e5), against 0-25% at alpha 1e-30 and 49-81%
 * at |g| 0.01 ... 0.3 and alpha 1e5 ... 1e20 (counted over 2e4 random xi).
 * So the float try's domain is 1e-3 <= |g| <= 0.999999 with 1e-6 <=
 * alpha <= 1e4, and up to alpha 1e30 where |g| >= 0.5 (outside eq. 6's
 * domain a refused answer's fallback starts from the HG answer, as
 * before).  There the float samplers took 70-140 ns a sample, scalar and
 * batch alike (now ~70 scalar, ~9 in the batch kernel).  Not below alpha
 * 1e-6, where the HG answer is a start the solver finishes in one step,
 * faster than eq. 6 (38-54 against 64-71 ns one at a time, measured). */
MIST__F int MIST__FN(mist__draine_okt)(MIST__T g, MIST__T alpha)
{
    MIST__T ag = MIST__FN(mist__abs)(g);
    if (MIST__DBL) return MIST__FN(mist__draine_ok6)(g, alpha);
    return ag >= MIST__C(1e-3) && ag <= MIST__C(0.999999) && alpha >= MIST__C(1e-6)
           && alpha <= (ag >= MIST__C(0.5) ? MIST__C(1e30) : MIST__C(1e4));
}

/* u in [-1, 1] with F_g(u) = x, for x in [0, 1/2], g in (-1, 1); c0, c1:
 * the weights of alpha; f0: F_g(0) as hi + lo (a prepared phase function)
 * or NULL; st: the start, a double also for float (mist__draine_try6x), 2
 * for none.  Newton in the wide type from [JD23 eq. 6] where it is good;
 * else from the HG answer, in T to its noise and then in the wide type
 * (float: all in double, which costs no more). */
MIST__F MIST__T MIST__FN(mist__draine_solve)(MIST__T g, MIST__T alpha, MIST__T c0,
                                             MIST__T c1, MIST__T x, const MIST__T *f0,
                                             double st)
{
    MIST__T u, t0 = MIST__C(0);
    int good;
#ifdef MIST__W
    MIST__W uw, c0w, c1w, t0w = 0;
#endif
#if defined(MIST__DDR)
    MIST__T c0d, c1d;
#endif
    if (!(x > MIST__C(0))) return MIST__C(-1);
    /* The start (good: 1 the table's, 2 eq. 6, 0 none): the prepared
     * table's; else [JD23 eq. 6] in double, which lands within 1.3e-5 of
     * the answer for 1e-3 <= |g| <= 0.9999 and 1e-6 <= alpha <= 1e4
     * (measured; typically within 1e-12); else the HG answer.  Not the
     * table's for |g| > 0.9999 (mist__phase_tab). */
    good = st > -1 && st < 1 && MIST__FN(mist__phase_tab)(g);
    if (!good && MIST__FN(mist__draine_ok6)(g, alpha)) {
        double ud = mist__draine_eq6((double)g, (double)alpha, (double)x);
        good = ud > -1 && ud < 1 ? 2 : 0;
        st = ud;
    }
    if (!good) st = (double)MIST__FN(mist__hg_sample)(g, x);
    if (MIST__DBL && good != 2 && alpha > MIST__C(1e4) && MIST__FN(mist__abs)(g) < MIST__C(1e-3)) {
        /* small |g|, alpha > 1e4: F as linear in y (mist__draine_uy) with the
         * HG factor at u = 0, y = 2 (x - F(0)) cn V0^3 / (1 - g^2), V0^2 =
         * 1 + g^2: within ~3 |g u| of the root in relative terms, where the
         * HG answer was far off near u = 0 at large alpha; a start as good
         * as eq. 6's, so straight to the wide steps (in T, near u = 0 at
         * large alpha, the steps are within T's noise of xi over f).  Not
         * in the tails (|u| > 1/2), where the weight varies little and the
         * HG answer is the better start; nor at alpha <= 1e4, where the
         * HG answer's steps cost less (g 5e-4, alpha 100: 230 against 290
         * ns, long double). */
        MIST__T a = MIST__C(1) + g * g, cn = c0 + c1 * (a + g * g) / MIST__C(3);
        MIST__T xd = f0 ? (x - f0[0]) - f0[1]   /* x - F(0); F(0) = 1/2 - 3 g (2 c0 +
                                                   c1) / (8 cn) + O(g^3), odd in g */
            : (x - MIST__C(0.5)) + MIST__C(3) * g * (MIST__C(2) * c0 + c1) / (MIST__C(8) * cn);
        MIST__T uc = MIST__FN(mist__draine_uy)(c0, c1, MIST__C(2) * xd * cn
                         * (a * MIST__M(sqrt)(a)) / ((MIST__C(1) - g) * (MIST__C(1) + g)));
        if (uc >= MIST__C(-0.5) && uc <= MIST__C(0.5)) { st = (double)uc; good = 2; }
    }
#if defined(MIST__DDR)
    /* double where fma is one instruction or long double is no wider: the
     * compensated finish, with the weights (1, alpha), exact, while they
     * cannot overflow */
    c0d = alpha <= MIST__C(1e270) ? MIST__C(1) : c0;
    c1d = alpha <= MIST__C(1e270) ? alpha : c1;
    if (good == 2 && MIST__FN(mist__draine_ddfin)(g, c0d, c1d, x, st, &u)) return u;
#endif
#ifdef MIST__W
    MIST__WFN(mist__draine_c)((MIST__W)alpha, &c0w, &c1w);
    if (f0) t0w = ((MIST__W)f0[0] - (MIST__W)x) + (MIST__W)f0[1];
    if (!MIST__DBL) {                           /* float: all in double */
        uw = (MIST__W)st;
        MIST__WFN(mist__draine_newton)((MIST__W)g, c0w, c1w, (MIST__W)x, t0w, f0 != MIST__NULL,
                                       (MIST__W)MIST__EPS / 64, 2 * MIST__MAXIT, &uw);
        return MIST__FN(mist__draine_round)(g, c0w, c1w, x, uw,
                                            MIST__WFN(mist__abs)(uw) * ((MIST__W)MIST__EPS / 16));
    }
    /* double: from eq. 6 straight to the wide steps (one usually lands);
     * from the table or HG first in T to its noise (long double is slower) */
    uw = (MIST__W)st;
    if (good == 2
        && MIST__WFN(mist__draine_newton)((MIST__W)g, c0w, c1w, (MIST__W)x, t0w, f0 != MIST__NULL,
                                          (MIST__W)MIST__EPS / 64, 6, &uw))
        return MIST__FN(mist__draine_round)(g, c0w, c1w, x, uw,
                                            MIST__WFN(mist__abs)(uw) * ((MIST__W)MIST__EPS / 16));
#endif
    if (f0) t0 = (f0[0] - x) + f0[1];
    u = (MIST__T)st;
    MIST__FN(mist__draine_newton)(g, c0, c1, x, t0, f0 != MIST__NULL, MIST__C(16) * MIST__EPS,
                                  MIST__MAXIT, &u);
#if defined(MIST__DDR)
    if (MIST__FN(mist__draine_ddfin)(g, c0d, c1d, x, u, &st)) return st;
#endif
#ifdef MIST__W
    if (MIST__FN(mist__abs)(u) >= MIST__C(1) - MIST__C(4) * MIST__EPS) {
        /* u = +-1 or within two ulps of it, where the lobe may peak
         * narrower than an ulp of W too: the wide steps then overshot past
         * +-1 and bisected towards it, a dozen steps (g = 1 - 2^-46).  The
         * residual's sign at the midpoint m between +-1 and its neighbour
         * n, else at the one between n and its own, says whether the root
         * lies beyond it: then +-1, resp. n, is the root correctly rounded,
         * as mist__draine_round's pick there would decide. */
        MIST__T sn = u > MIST__C(0) ? MIST__C(1) : MIST__C(-1), n1 = sn * (MIST__C(1) - MIST__EPS);
        MIST__W m1 = (MIST__W)sn * (1 - (MIST__W)MIST__EPS / 2), m2 = (MIST__W)sn
                     * (1 - (MIST__W)MIST__EPS * 3 / 2);
        if ((MIST__W)sn * MIST__WFN(mist__draine_res)((MIST__W)g, c0w, c1w, (MIST__W)x, m1,
                                                      MIST__NULL, MIST__NULL) < 0)
            return sn;
        if (u == n1 && (MIST__W)sn * MIST__WFN(mist__draine_res)((MIST__W)g, c0w, c1w,
                                           (MIST__W)x, m2, MIST__NULL, MIST__NULL) < 0)
            return n1;
    }
    uw = (MIST__W)u;
    MIST__WFN(mist__draine_newton)((MIST__W)g, c0w, c1w, (MIST__W)x, t0w, f0 != MIST__NULL,
                                   (MIST__W)MIST__EPS / 64, MIST__MAXIT, &uw);
    u = MIST__FN(mist__draine_round)(g, c0w, c1w, x, uw,
                                     MIST__WFN(mist__abs)(uw) * ((MIST__W)MIST__EPS / 16));
#endif
    return u;
}

/* The prepared start at xi in [0, 1]: the table's cubic Hermite
 * interpolant in interval *j (tab: u at xi = j/K, then the slopes
 * du/dxi / K). */
/* xi's table interval.  xi is in [+0, 1] here, sanitised by the caller;
 * the index is still clamped in integers after the conversion, so that a
 * NaN that reaches it (a build without the fast-math guard, where the
 * caller's clamp may fold away) gives an interval inside the table (x86
 * converts NaN to INT_MIN, ARM to 0), never a read outside it.  Selects
 * on integers: the batch loops stay vectorised. */
MIST__F MIST__HOT int MIST__FN(mist__phase_k)(MIST__T xi)
{
    int k = (int)(xi * MIST__PHASE_K);
    k = k < 0 ? 0 : k;
    return k < MIST__PHASE_K ? k : MIST__PHASE_K - 1;
}
MIST__F MIST__HOT MIST__T MIST__FN(mist__phase_start)(const MIST__T *tab, MIST__T xi, int *j)
{
    int k = MIST__FN(mist__phase_k)(xi);
    MIST__T t = xi * MIST__PHASE_K - (MIST__T)k, d, m0, m1;
    d = tab[k + 1] - tab[k];
    m0 = tab[MIST__PHASE_K + 1 + k]; m1 = tab[MIST__PHASE_K + 2 + k];
    *j = k;
    return tab[k] + t * (m0 + t * ((MIST__C(3) * d - MIST__C(2) * m0 - m1)
                                   + t * (m0 + m1 - MIST__C(2) * d)));
}

/* The prepared samplers' weights in T for the step in T and the compensated
 * finish: (1, alpha), exact (mist__draine_c's 1/alpha rounds), (0, 1) at
 * alpha = +inf, and for alpha > MIST__BIG / 2^34 both times 2^-32, still
 * exact.  The residual and its step are homogeneous in (c0, c1), so the
 * scale leaves every step and test as it was, but their terms stay finite:
 * S = V cn (V1 + V) 3 (P + a)^2 reaches ~900 (c0 + c1), and with c1 =
 * alpha above ~8e306 it overflowed, the residual to -inf and its scale sc
 * to +inf, which the finish took for a residual within its error (samples
 * 0.6 off in F; under clang -ffast-math's contraction at every alpha from
 * 1e307 to DBL_MAX). */
MIST__F MIST__HOT void MIST__FN(mist__draine_cx)(MIST__T alpha, MIST__T *c0, MIST__T *c1)
{
    const MIST__T dn = MIST__C(2.3283064365386963e-10);   /* 2^-32 */
    int inf = !(alpha < (MIST__T)INFINITY), big = alpha > MIST__BIG * (dn * MIST__C(0.25));
    *c0 = inf ? MIST__C(0) : big ? dn : MIST__C(1);
    *c1 = inf ? MIST__C(1) : big ? alpha * dn : alpha;
}

/* The prepared sampler's first try at sanitised |g| < 1, alpha, c1 != 0, xi
 * in [0, 1]: *st, the start from tab (u at xi = j/K, then the slopes du/dxi
 * / K, then the step bounds): cubic Hermite; returns 1 with the sample in
 * *u where the compensated finish (double where fma is one instruction or
 * long double is no wider: mist__draine_ddfin) or wide Newton steps with an a-priori stop
 * (mist__draine_step) finish it, else 0 (the caller goes on from *st:
 * mist__draine_finish). */
MIST__F MIST__HOT int MIST__FN(mist__phase_try)(MIST__T g, MIST__T alpha, const MIST__T *tab,
                                                MIST__T xi, double *st, MIST__T *u)
{
    int j;
    MIST__T s0;
    if (MIST__DBL && !MIST__FN(mist__phase_tab)(g)) { *st = 2; return 0; }   /* no start */
    s0 = MIST__FN(mist__phase_start)(tab, xi, &j);
    *st = (double)s0;
    if (MIST__DBL && MIST__FN(mist__phase_wide)(tab, j)) { *st = 2; return 0; }
#if defined(MIST__W) || defined(MIST__DDR)
    {   /* no branch on xi (see mist__draine_step); a second step only from
         * inside [u_j, u_j+1], kb's range.  Double: first one step in T (long
         * double is slow), then where fma is one instruction or long double
         * is no wider the compensated finish (mist__draine_ddfin), else the
         * wide steps. */
        int ok;
        MIST__T kb, ut, us = s0, cx0, cx1;
        MIST__FN(mist__draine_cx)(alpha, &cx0, &cx1);
        kb = tab[2 * MIST__PHASE_K + 2 + j];
        if (MIST__DBL) {
            MIST__T et;
            ut = MIST__FN(mist__draine_step)(g, cx0, cx1, xi, s0, kb, MIST__C(0), &ok, &et);
            if (ut >= tab[j] && ut <= tab[j + 1]) us = ut;
        }
#if defined(MIST__DDR)
        if (MIST__FN(mist__draine_ddfin)(g, cx0, cx1, xi, us, u)) return 1;
#endif
#ifdef MIST__W
        {
            MIST__W uw = (MIST__W)us, eb;   /* weights (1, alpha): exact */
            MIST__T fin = alpha < (MIST__T)INFINITY ? MIST__C(1) : MIST__C(0);
            int k;
            for (k = 0; k < 2; ++k) {
                uw = MIST__WFN(mist__draine_step)((MIST__W)g, (MIST__W)fin, fin > 0
                    ? (MIST__W)alpha : 1, (MIST__W)xi, uw, (MIST__W)kb,
                    (MIST__W)MIST__EPS / 64, &ok, &eb);
                if (ok) {
                    *u = MIST__FN(mist__draine_round)(g, (MIST__W)fin, fin > 0
                        ? (MIST__W)alpha : 1, xi, MIST__WFN(mist__clamp11)(uw),
                        MIST__FN(mist__draine_win)(uw, eb));
                    return 1;
                }
                if (!(uw >= (MIST__W)tab[j] && uw <= (MIST__W)tab[j + 1])) break;
            }
        }
#endif
    }
#else
    (void)g; (void)alpha; (void)u;
#endif
    return 0;
}

/* The float Draine samplers' certificate: 1 where ud (0 < |ud| < 1, a W)
 * rounded to float is the root u* of F_g(u) = xi correctly rounded, as one
 * residual at ud proves (sanitised |g| < 1, alpha > 0 finite, xi in
 * [0, 1]); else 0 (also where ud rounds to 0 or to a subnormal, or is
 * NaN).  Let h be
 * the distance from ud to the nearer of the midpoints between its rounding
 * uf and uf's two float neighbours (exact: Sterbenz; h <= 2^-25, half the
 * float spacing below 1).  Where uf = +-1 (|ud| < 1) that is the midpoint
 * towards 0, 1 - 2^-25 (the one beyond, 1 + 2^-24, is farther), and the
 * proof below needs only [ud - h, ud] (|u*| <= 1 puts u* on uf's side of
 * the other; refusing them would refuse 62% of xi at g .9999, alpha 17,
 * counted).  If f = F_g' >= fm on [ud - h, ud + h], then
 * |F_g(ud) - xi| < h fm puts F_g(ud - h) < xi < F_g(ud + h): u* lies within
 * h of ud, so on uf's side of both midpoints.  fm: f = (1 - g^2) w V^-3 /
 * (2 cn) with w = 1 + alpha u^2; over the interval w is least where |u|
 * is, and |u| >= |ud| - h >= (1 - 2^-24) |ud| (for normal uf, h is at most
 * half its float spacing, 2^-24 |uf|), so w >= (1 - 2^-24)^2 w(ud) for any
 * alpha (a bound from w's change 2 alpha (|ud| + h) h would need alpha
 * <= 2^21); V^2 moves by at
 * most 2 |g| h, so with q = 2 |g| h / V^2(ud) and (1 + q)^-3/2 >=
 * 1 / (1 + 3q/2 + 3q^2/8) (the Taylor polynomial of (1 + q)^3/2 bounds it
 * above for q >= 0: its third derivative is negative), f >= 0.9999998
 * f(ud) / (1 + 3 |g| h / V^2 + 1.5 g^2 h^2 / V^4) = fm, positive for every
 * h (the first-order factor 1 - 3q/2 would be negative where h is
 * comparable with V^2, near |g| = 1 and u = 1).  The residual r = S (F_g(ud)
 * - xi) and fs = S f(ud) V^2 (mist__draine_res); |r| is taken as at most
 * |r~| + 2^-46 sc, 16x its measured rounding error (4x the bound); the test
 * multiplied by V^4 (no division), with k = 0.7 in place of 0.9999998:
 * the margin covers the few roundings of fs and V^2 (the test's negative
 * control passes a looser k).  One residual, where the signs of two
 * residuals at the midpoints would decide the same answers at twice the
 * work waiting on eq. 6's long chain. */
#if defined(MIST__W_EXACT)
MIST__F MIST__HOT int MIST__FN(mist__draine_cert)(MIST__T g, MIST__T alpha, MIST__T xi,
                                                  MIST__W ud, MIST__W k)
{
    MIST__W aw = (MIST__W)alpha, mg = (MIST__W)1 / 70368744177664.0;   /* 2^-46 */
    MIST__W r, sc, fs, hi, ho, h, v2, ag, ar;
    MIST__T uf = (MIST__T)ud, fi, fo;
    uint32_t b, bi, bo;
    int in;
    memcpy(&b, &uf, sizeof b);
    in = ((b & 0x7fffffffu) - 1u < 0x3f800000u)       /* not 0, NaN or beyond +-1 */
         & ((b & 0x7f800000u) != 0u)                  /* nor subnormal */
         & (MIST__WFN(mist__abs)(ud) < 1);
    bi = b - 1u; bo = b + 1u;                  /* the neighbours towards 0, away */
    memcpy(&fi, &bi, sizeof fi);
    memcpy(&fo, &bo, sizeof fo);
    hi = MIST__WFN(mist__abs)(ud - (MIST__W)0.5 * ((MIST__W)uf + (MIST__W)fi));
    ho = MIST__WFN(mist__abs)(ud - (MIST__W)0.5 * ((MIST__W)uf + (MIST__W)fo));
    h = hi < ho ? hi : ho;
    r = MIST__WFN(mist__draine_res)((MIST__W)g, 1, aw, (MIST__W)xi, ud, &sc, &fs);
    v2 = MIST__WFN(mist__v2)((MIST__W)g, ud);
    ag = MIST__WFN(mist__abs)((MIST__W)g);
    ar = MIST__WFN(mist__abs)(r);
    return ((ar + mg * sc) * (v2 * (v2 + 3 * ag * h) + (MIST__W)1.5 * (ag * h) * (ag * h))
            < k * h * fs * v2) & in;                                  /* no branch */
}

/* The unprepared float sampler's first try at sanitised |g| < 1, alpha, xi
 * in [0, 1]: [JD23 eq. 6] in double where it is good (as in
 * mist__draine_solve; x = min(xi, 1 - xi) by the mirror), rounded to float
 * and certified (mist__draine_cert): returns 1 with the sample in *u, else
 * 0 with eq. 6's answer in *st for mist__draine_finish, in double: rounded
 * to float it had been a poor start where the certificate fails most, near
 * |g| = 1 and u = 1, where V^2 is comparable with a float ulp (Newton from
 * a float ulp away crept: mist_bench, mist_draine_samplef at g .9999,
 * alpha 17: 149-154 -> 80-89 ns, the same samples).  Eq. 6 is within
 * 1e-12 of u* almost everywhere there, so it fails mostly where u* lies
 * within that of a midpoint.  Against eq. 6 and the solver's Newton step
 * and rounding, this is eq. 6 and one residual's latency (measured in
 * "Draine and Cornette-Shanks: exact sampling").  mist__draine_try6x: the
 * try without its domain test (mist__draine_okt), branch-free: the batch
 * form runs it over a block (vec = 1: mist__cbrt_m, and 0 where eq. 6's
 * cube root argument s is odd, which the scalar try gives to libm's cbrt;
 * elsewhere the same arithmetic, so the same answers). */
MIST__F MIST__HOT int MIST__FN(mist__draine_try6x)(MIST__T g, MIST__T alpha, MIST__T xi,
                                                   int vec, double *st, MIST__T *u)
{
    int m = xi > MIST__C(0.5), odd;         /* the mirror: see mist__mirror */
    MIST__W xw = (MIST__W)xi, ud, sg, x;
    if (vec) sg = MIST__WFN(mist__mirror)(xw, &x);
    else { sg = m ? -1 : 1; x = m ? 1 - xw : xw; }
    ud = sg * (MIST__W)mist__draine_eq6x((double)sg * (double)g, (double)alpha, (double)x,
                                         vec, &odd);
    *st = ud;
    *u = (MIST__T)ud;
    return MIST__FN(mist__draine_cert)(g, alpha, xi, ud, (MIST__W)0.7) & !(vec & odd)
           & (x > 0);
}
MIST__F MIST__HOT int MIST__FN(mist__draine_try6)(MIST__T g, MIST__T alpha, MIST__T xi,
                                                  double *st, MIST__T *u)
{
    if (!MIST__FN(mist__draine_okt)(g, alpha)) return 0;
    return MIST__FN(mist__draine_try6x)(g, alpha, xi, 0, st, u);
}
#endif

/* The solver's sample at sanitised |g| < 1, alpha (c0, c1 != 0 its weights),
 * xi in [0, 1], from the start st (2: none); f0 (prepared, else NULL): F_g(0)
 * and F_-g(0) as hi + lo pairs.  xi > 1/2 by the mirror image u(g, xi) =
 * -u(-g, 1 - xi), 1 - xi exact: one call on selected arguments, not one
 * call in each branch (on a GPU a warp whose xi fall on both sides ran
 * both: 2.2x, measured on an H200 in CUDA device code; the same arithmetic
 * either way) */
MIST__F MIST__T MIST__FN(mist__draine_finish)(MIST__T g, MIST__T alpha, MIST__T c0,
                                              MIST__T c1, MIST__T xi, const MIST__T *f0,
                                              double st)
{
    int m = xi > MIST__C(0.5);
    MIST__T s = m ? MIST__C(-1) : MIST__C(1);
    MIST__T u = s * MIST__FN(mist__draine_solve)(s * g, alpha, c0, c1, m ? MIST__C(1) - xi : xi,
                                                 f0 ? f0 + 2 * m : f0, (double)s * st);
    return u < MIST__C(-1) ? MIST__C(-1) : (u > MIST__C(1) ? MIST__C(1) : u);
}

/* The sampler at sanitised g, alpha (c0, c1 its weights), xi in [0, 1];
 * prepared (else NULL): f0 and tab (mist__phase_try, mist__draine_finish). */
MIST__F MIST__T MIST__FN(mist__draine_sample)(MIST__T g, MIST__T alpha, MIST__T c0,
                                              MIST__T c1, MIST__T xi, const MIST__T *f0,
                                              const MIST__T *tab)
{
    MIST__T u;
    double st = 2;
    if (g == MIST__C(1) || g == MIST__C(-1)) return g;
    if (c1 == MIST__C(0)) return MIST__FN(mist__hg_any)(g, xi);   /* (mist_hg_sample) */
    if (tab && MIST__FN(mist__phase_try)(g, alpha, tab, xi, &st, &u)) return u;
#if defined(MIST__W_EXACT)
    if (!tab && MIST__FN(mist__draine_try6)(g, alpha, xi, &st, &u)) return u;
#endif
    return MIST__FN(mist__draine_finish)(g, alpha, c0, c1, xi, f0, st);
}

/* Draine: u with P(cos <= u) = xi, within the accuracy bar (a few ulps of
 * u, or where u is ill-conditioned in xi, near u = 0 at large alpha, 4 eps
 * xi du/dxi: see the section comment).
 * Domain: g in [-1, 1], alpha in [0, +inf], xi in [0, 1]. */
MIST__F MIST__T MIST__FN(mist__impl_draine_sample)(MIST__T g, MIST__T alpha, MIST__T xi)
{
    MIST__T c0, c1;
    MIST__FN(mist__draine_c)(alpha, &c0, &c1);
    if (MIST__DBL && c1 == MIST__C(0))   /* alpha = 0 (NaN, < 0): HG, through
                             * mist_hg_sample itself (the same sanitising; a copy
                             * inlined by another route contracted into fma
                             * differently: an ulp apart under gcc -O3 -march=native
                             * -ffp-contract=fast; float keeps mist__hg_any, which
                             * costs fewer registers in CUDA device code) */
        return MIST__FN(mist__impl_hg_sample)(g, xi);
    return MIST__FN(mist__draine_sample)(MIST__FN(mist__g)(g),
                                         alpha > MIST__C(0) ? alpha : MIST__C(0), c0, c1,
                                         MIST__FN(mist__clamp)(xi, MIST__C(0), MIST__C(1)),
                                         MIST__NULL, MIST__NULL);
}

/* Cornette-Shanks: Draine with alpha = 1. Domain: g in [-1,1], xi in [0,1]. */
MIST__F MIST__T MIST__FN(mist__impl_cs_sample)(MIST__T g, MIST__T xi)
{
    return MIST__FN(mist__impl_draine_sample)(g, MIST__C(1), xi);
}

/* The unprepared Draine batch samplers' kernel, where square roots
 * vectorise (no errno: -fno-math-errno, implied by -ffast-math) and on the
 * host: in float, and in double where fma is one instruction.  It computes
 * the scalar sampler's first try over a block: [JD23 eq. 6] in double and
 * its certificate (float: mist__draine_try6x) or one compensated Newton
 * step (double: mist__draine_dd1, the first step of mist__draine_ddfin,
 * which mist__draine_solve takes from eq. 6's answer); the elements it does
 * not settle (the certificate fails, or the step does not settle: 0-4%)
 * take the scalar function.  So every value is mist_draine_sample's, bit
 * for bit, with no preparation (from MIST_DRAINE_PREPARE_N elements on it
 * is taken where it leaves few elements: mist__draine_vn).  A prepared
 * medium's start table takes its 129 nodes from it too: the same nodes,
 * and preparing costs a quarter of 129 scalar samples. */
#if !defined(__CUDA_ARCH__) && defined(__NO_MATH_ERRNO__) \
    && (defined(MIST__W_EXACT) || defined(MIST__DDV))
#  define MIST__DRAINE_V 1
#endif
/* 1 where mist_draine_sample_n of n elements takes that kernel: eq. 6's
 * domain, after sanitising (a prepared medium's table too, n = 129); from
 * MIST_DRAINE_PREPARE_N elements on, where that batch can be prepared
 * instead, only where the kernel settles enough elements to stay near the
 * prepared batch's cost: |g| >= 0.01 and alpha <= 300, or |g| >= 0.5.
 * Elsewhere in eq. 6's domain eq. 6 is too far off for the float
 * certificate or the double step (its terms cancel as 1/g^3; and at large
 * alpha many roots lie near u = 0, where the float spacing is fine):
 * kernel / prepared batch with its preparation, ns an element at n = 4096
 * (gcc 12 -O3 -march=native -fno-math-errno, AMD EPYC, measured): float
 * g 1e-3, alpha 1: 95 / 9.2; g 3e-3, alpha 10:
 * 48 / 7.5; g 0.1, alpha 1e4: 43 / 10; double 211 / 18, 138 / 17, 84 / 22;
 * inside the rule at most 1.7x (float g 0.01, alpha 10: 10.8 / 6.5; double
 * g 0.5, alpha 1e4: 30 / 20), and the kernel's values are the scalar
 * function's bit for bit.  Below MIST_DRAINE_PREPARE_N the kernel is
 * taken on the whole domain: in batches of 64 it is at worst ~1.1x a loop
 * of scalar calls (g 1e-3, alpha >= 10), and 2-8x faster elsewhere. */
MIST__F int MIST__FN(mist__draine_vn)(MIST__T g, MIST__T alpha, size_t n)
{
#if defined(MIST__DRAINE_V)
    MIST__T gs = MIST__FN(mist__g)(g), as = alpha > MIST__C(0) ? alpha : MIST__C(0);
    MIST__T ag = MIST__FN(mist__abs)(gs);
    if (!MIST__FN(mist__draine_okt)(gs, as)) return 0;
#if !defined(MIST_NO_FOG)
    if (n >= (size_t)MIST_DRAINE_PREPARE_N)
        return (ag >= MIST__C(0.01) && as <= MIST__C(300)) || ag >= MIST__C(0.5);
#endif
    (void)n; (void)ag;
    return 1;
#else
    (void)g; (void)alpha; (void)n;
    return 0;
#endif
}

#if defined(MIST__DRAINE_V)
/* That kernel over in[0..n) at sanitised g and alpha in eq. 6's domain
 * (c0, c1 its weights), f0 as for mist__draine_sample (a prepared medium's
 * F_g(0), for the elements it leaves; else NULL). */
MIST__F void MIST__FN(mist__draine_vk)(MIST__T g, MIST__T alpha, MIST__T c0, MIST__T c1,
                                       const MIST__T *f0, const MIST__T *in, MIST__T *out,
                                       size_t n)
{
    volatile MIST__T z0 = 0;
    MIST__T z = z0, one = z + 1;
#if defined(MIST__W_EXACT)
    MIST__BLOCKS_FB(
        MIST__T xi = MIST__FN(mist__clamp01)(x_[j_], z, one);
        double st; MIST__T u;
        f_[j_] = (short)!MIST__FN(mist__draine_try6x)(g, alpha, xi, 1, &st, &u);
        y_[j_] = u;,
        1,
        out[i_ + j_] = MIST__FN(mist__draine_sample)(g, alpha, c0, c1,
            MIST__FN(mist__clamp)(x_[j_], MIST__C(0), MIST__C(1)), f0, MIST__NULL);)
#else
    MIST__BLOCKS_FB(    /* mist__draine_finish, _solve, _ddfin's first step */
        MIST__T xi = MIST__FN(mist__clamp01)(x_[j_], z, one);
        MIST__T x; MIST__T sg = MIST__FN(mist__mirror)(xi, &x);
        MIST__T u; MIST__T r; MIST__T s; MIST__T uh; MIST__T lo; MIST__T hi;
        int odd; int c;
        MIST__T ud = mist__draine_eq6x(sg * g, alpha, x, 1, &odd);
        c = MIST__FN(mist__draine_dd1)(sg * g, MIST__C(1), alpha, x, ud, &u, &r, &s,
                                       &uh, &lo, &hi);
        y_[j_] = MIST__FN(mist__clamp11)(sg * u);          /* as mist__draine_finish */
        f_[j_] = (short)!((c == 1) & !odd & (x > z) & (ud > -one) & (ud < one));,
        1,
        out[i_ + j_] = MIST__FN(mist__draine_sample)(g, alpha, c0, c1,
            MIST__FN(mist__clamp)(x_[j_], MIST__C(0), MIST__C(1)), f0, MIST__NULL);)
#endif
}
#endif
#endif /* !MIST_NO_DRAINE */

#ifndef MIST_NO_RAYLEIGH
/* Rayleigh: u with P(cos <= u) = xi, exact.  Domain: xi in [0, 1]. */
MIST__F MIST__T MIST__FN(mist__impl_rayleigh_sample)(MIST__T xi)
{
    MIST__T u;
    xi = MIST__FN(mist__clamp)(xi, MIST__C(0), MIST__C(1));
#if defined(MIST__DD)
    u = MIST__FN(mist__rayleigh_udd)(xi);
#else                    /* float, in double */
    u = (MIST__T)MIST__WFN(mist__rayleigh_u)((MIST__W)xi);
#endif
    return u < MIST__C(-1) ? MIST__C(-1) : (u > MIST__C(1) ? MIST__C(1) : u);
}
#endif /* !MIST_NO_RAYLEIGH */

#ifndef MIST_NO_FOG
/* ======================================================================== */
/* The Jendersie-d'Eon fog phase function [JD23 eq. 1]                      */
/* (1 - w_d) HG(g_hg) + w_d Draine(g_d, alpha).  Sampling as the            */
/* supplemental says: one xi picks the Draine lobe when xi < w_d, and is    */
/* rescaled to [0, 1] and reused for the lobe (near a lobe's top by its     */
/* complement, exactly: mist__fog_pick).  The density (and so the pdf       */
/* of a sample) is the whole mixture's, as multiple importance sampling     */
/* needs.  The mixture sampler is exact but NOT monotone in xi.             */
/* ======================================================================== */

/* A fog phase function from its four parameters, sanitised: g's clamped to
 * [-1, 1] (NaN -> 0), alpha >= 0 (NaN, negative -> 0), w_d in [0, 1]. */
MIST__F MIST__FOG MIST__FN(mist__impl_fog_make)(MIST__T g_hg, MIST__T g_d, MIST__T alpha, MIST__T w_d)
{
    MIST__FOG f;
    f.g_hg  = MIST__FN(mist__g)(g_hg);
    f.g_d   = MIST__FN(mist__g)(g_d);
    f.alpha = alpha > MIST__C(0) ? alpha : MIST__C(0);
    f.w_d   = MIST__FN(mist__clamp)(w_d, MIST__C(0), MIST__C(1));
    return f;
}

/* The fog density of *fog at u (mist_fog_eval).  By pointer for the
 * height fog: gcc 12 -O3 -march=native copied the 32-byte double struct
 * for a by-value call through a ymm register and then called on without
 * vzeroupper, which left the SSE/AVX transition penalty on every later
 * call into glibc's legacy-SSE code (frexp, ldexp, the exp wrapper: ~80
 * a ray): mist_hfog_inscatter took 15-20 us a ray in the benchmark
 * instead of ~0.65 (perf: the time on those functions' first SSE
 * instruction). */
MIST__F MIST__T MIST__FN(mist__fog_eval)(const MIST__FOG *fog, MIST__T u)
{
    MIST__T w = MIST__FN(mist__clamp)(fog->w_d, MIST__C(0), MIST__C(1));
    MIST__T d = w > MIST__C(0) ? MIST__FN(mist__impl_draine_eval)(fog->g_d, fog->alpha, u)
                               : MIST__C(0);
    MIST__T h = w < MIST__C(1) ? MIST__FN(mist__impl_hg_eval)(fog->g_hg, u) : MIST__C(0);
    return (MIST__C(1) - w) * h + w * d;
}

/* Fog density per steradian.  Domain: u in [-1, 1]; the parameters are
 * sanitised again here, so a hand-filled struct is safe too. */
MIST__F MIST__T MIST__FN(mist__impl_fog_eval)(MIST__FOG fog, MIST__T u)
{
    return MIST__FN(mist__fog_eval)(&fog, u);
}

/* The lobe and its xi' at xi, w in [0, 1] (mist_fog_sample, and prepared):
 * returns 1 for the Draine lobe (xi < w, or w = 1), xi' = xi / w, else 0,
 * xi' = (xi - w) / (1 - w).  Each is within 1.5 eps of xi' in relative
 * terms (xi - w is one rounding), but 1 - xi' is not where it is a few
 * ulps: there a lobe near the Dirac limit (g -> -1, whose CDF is flat to
 * u = 1) took xi' rounded to 1 to u = 1 instead of -0.78 (g = -(1 -
 * 2^-52), w 0.49999, xi = 1 - 2^-53: 1.5x the bar, found by an independent
 * check).  So within 1024 eps of 1, *x = 1 - xi' = (w - xi) / w resp.
 * (1 - xi) / (1 - w) (w - xi and 1 - xi exact, Sterbenz) and *s = -1: the
 * caller takes the mirror image u(g, xi') = -u(-g, 1 - xi'). */
MIST__F int MIST__FN(mist__fog_pick)(MIST__T xi, MIST__T w, MIST__T *x, MIST__T *s)
{
    int dr = xi < w || w >= MIST__C(1);
    MIST__T lo = dr ? MIST__C(0) : w, top = dr ? w : MIST__C(1), d = top - lo;
    *x = (xi - lo) / d;
    *s = MIST__C(1);
    if (w > MIST__C(0) && w < MIST__C(1) && *x > MIST__C(1) - MIST__C(1024) * MIST__EPS) {
        *x = (top - xi) / d;
        *s = MIST__C(-1);
    }
    return dr;
}

/* Fog: a sample u of the mixture, from one xi in [0, 1].  Domain: xi in
 * [0, 1] (clamped; NaN taken as 0); fog sanitised as mist_fog_make. */
MIST__F MIST__T MIST__FN(mist__impl_fog_sample)(MIST__FOG fog, MIST__T xi)
{
    MIST__T w = MIST__FN(mist__clamp)(fog.w_d, MIST__C(0), MIST__C(1)), x, s;
    xi = MIST__FN(mist__clamp)(xi, MIST__C(0), MIST__C(1));
    if (MIST__FN(mist__fog_pick)(xi, w, &x, &s))
        return s * MIST__FN(mist__impl_draine_sample)(s * fog.g_d, fog.alpha, x);
    return s * MIST__FN(mist__impl_hg_sample)(s * fog.g_hg, x);
}

/* ======================================================================== */
/* Prepared phase functions                                                 */
/* A medium's phase function is fixed while a renderer draws millions of    */
/* samples from it, so mist_phase_* computes once what depends only on the  */
/* parameters: the sanitised parameters, the lobes' density factors         */
/* (1-g^2)/(4 pi) and (1-g^2)/(4 pi (c0 + c1 m2)), Draine's weights c0, c1  */
/* and F(0) for +g and -g (the CDF at u = 0, in the wide type, kept as a    */
/* hi + lo pair: the sampler's u >= 0 branch needs it to the wide type's    */
/* precision), the fog's mixture weight, the density as one lobe            */
/* (a1 + b1 u^2) / V^3 where HG and Draine share g (two lobes only for a    */
/* fog with g_hg != g_d), and a start table for the Draine sampler: the     */
/* exact u at xi = j/128 (j = 0..128) with its slopes du/dxi, interpolated  */
/* by monotone cubic Hermite (slopes limited to 3x the neighbouring         */
/* secants), and per interval the bound kb of mist__draine_step.  In float  */
/* the start is finished by at most two straight-line Newton steps in       */
/* double with an a-priori stop (error <= kb s^2 <= eps/64 of the bar's     */
/* scale); the first step alone lands for 95-100% of xi (measured at g      */
/* .5/.1/.7/.9, alpha 17/250/1/1).  The rest, and double always, go on with */
/* the same safeguarded Newton iteration and stop as the unprepared         */
/* sampler, so the result meets the same bar (tested in                     */
/* tests/test_accuracy.c, which fails with an unsound stop, kb = 0).        */
/* Preparing Draine costs 129 exact samples (by the unprepared batch       */
/* sampler's kernel where it applies: mist__draine_vk); the struct is ~3.1  */
/* KB (double), ~1.6 KB (float).                                            */
/* Results equal the unprepared functions' to a few ulps (the density's     */
/* rounding order differs, and the sampler's stop may land one ulp apart),  */
/* except where the inverse CDF is ill-conditioned: both samplers meet the  */
/* bar, within a few eps of xi, but where the density is tiny (Draine at    */
/* alpha 1e100 near u = 0) that is up to 1e6 eps of u apart (measured).     */
/* A fog with tiny w_d (and 1 - g_d^2) keeps its Draine lobe: w_d applies  */
/* after the lobe's division (multiplying the normalisation instead would  */
/* underflow: w_d 2^-1020 with g_hg = 1 and g_d = -(1 - 2^-53) would give  */
/* density 0 at u = -1 where the lobe's is ~1e-276; tests/test_domain.c).  */
/* HG, Draine, Cornette-Shanks and the fog are one mixture                  */
/* (1 - w) HG(g_hg) + w Draine(g, alpha): HG is w = 0, Draine w = 1.        */
/* mist_phase_sample is the inverse CDF (monotone in xi) for every kind but */
/* the fog mixture, which picks its lobe as mist_fog_sample does.           */
/* DOMAIN AND BAD INPUT: the constructors sanitise their parameters as the  */
/* unprepared functions do (see the top of the file), so every function     */
/* gives the unprepared one's documented result.  A NULL phase pointer is   */
/* the isotropic phase function (density 1/(4 pi), u = 2 xi - 1).           */
/* ======================================================================== */

#define MIST__PHASE MIST__FN(mist_phase)
#define MIST__PHC MIST__FN(mist_phasec)

/* The parameters' part of a prepared phase function (all of a compact one:
 * see "Compact prepared phase functions"): the sanitised parameters, the
 * density's lobes, Draine's weights and F(0) for +g and -g. */
MIST__F MIST__PHC MIST__FN(mist__phasec_make)(int kind, MIST__T g_hg, MIST__T g,
                                              MIST__T alpha, MIST__T w)
{
    MIST__PHC p;
    MIST__T c0, c1, cn, nh, nd;
    int i;
#ifdef MIST__W
    MIST__W c0w, c1w, fw;
#endif
    p.kind  = kind;
    p.g_hg  = MIST__FN(mist__g)(g_hg);
    p.g     = MIST__FN(mist__g)(g);
    p.alpha = alpha > MIST__C(0) ? alpha : MIST__C(0);
    p.w     = MIST__FN(mist__clamp)(w, MIST__C(0), MIST__C(1));
    MIST__FN(mist__draine_c)(p.alpha, &c0, &c1);
    p.c0 = c0; p.c1 = c1;
    cn = c0 + c1 * ((MIST__C(1) + MIST__C(2) * p.g * p.g) / MIST__C(3));
    nh = MIST__C(MIST__INV4PI) * (MIST__C(1) - p.g_hg) * (MIST__C(1) + p.g_hg);
    nd = MIST__C(MIST__INV4PI) * (MIST__C(1) - p.g) * (MIST__C(1) + p.g) / cn;
    if (kind == 1) {                        /* Rayleigh: (1 + u^2) 3/(16 pi) */
        p.ge = MIST__C(0); p.a1 = p.b1 = MIST__C(MIST__3_16PI); p.a2 = MIST__C(0);
    } else if (p.w <= MIST__C(0)) {         /* HG */
        p.ge = p.g_hg; p.a1 = nh; p.b1 = p.a2 = MIST__C(0);
    } else if (p.w >= MIST__C(1) || p.g == p.g_hg) {   /* Draine, or both at one g */
        p.ge = p.g;
        p.a1 = p.w * nd * c0 + (p.w >= MIST__C(1) ? MIST__C(0) : (MIST__C(1) - p.w) * nh);
        p.b1 = p.w * nd * c1; p.a2 = MIST__C(0);
    } else {                                /* two lobes; w applies after the
                                               division (mist_phase_eval: w nd c0
                                               underflowed for tiny w, 1 - g^2) */
        p.kind = 2;
        p.ge = p.g; p.a1 = nd * c0; p.b1 = nd * c1;
        p.a2 = (MIST__C(1) - p.w) * nh;
    }
    if (p.kind == 0 && p.w <= MIST__C(0)) {     /* HG: no Draine lobe, f0 unused */
        for (i = 0; i < 4; ++i) p.f0[i] = MIST__C(0);
        return p;
    }
#ifdef MIST__W
    MIST__WFN(mist__draine_c)((MIST__W)p.alpha, &c0w, &c1w);
#endif
    for (i = 0; i < 2; ++i) {
        MIST__T gi = i ? -p.g : p.g;
#ifdef MIST__W
        fw = MIST__WFN(mist__draine_f0)((MIST__W)gi, c0w, c1w);
        p.f0[2 * i] = (MIST__T)fw;
        p.f0[2 * i + 1] = (MIST__T)(fw - (MIST__W)p.f0[2 * i]);
#else
        p.f0[2 * i] = MIST__FN(mist__draine_f0)(gi, c0, c1);
        p.f0[2 * i + 1] = MIST__C(0);
#endif
    }
    return p;
}

MIST__F MIST__PHASE MIST__FN(mist__phase_make)(int kind, MIST__T g_hg, MIST__T g,
                                               MIST__T alpha, MIST__T w)
{
    MIST__PHASE p;
    MIST__PHC h = MIST__FN(mist__phasec_make)(kind, g_hg, g, alpha, w);
    MIST__T c0 = h.c0, c1 = h.c1, cn;
    int i, nodes = 0;
    p.kind = h.kind; p.g_hg = h.g_hg; p.g = h.g; p.alpha = h.alpha; p.w = h.w;
    p.ge = h.ge; p.c0 = h.c0; p.c1 = h.c1; p.a1 = h.a1; p.b1 = h.b1; p.a2 = h.a2;
    for (i = 0; i < 4; ++i) p.f0[i] = h.f0[i];
#if defined(MIST__W_EXACT)
    MIST__FN(mist__hg_par)(p.g_hg, p.hg);
#endif
    if (p.kind == 0 && p.w <= MIST__C(0)) {     /* HG: no Draine lobe, f0 and the table
                                                 * unused (zeroed: filling the table cost
                                                 * 0.3 us, measured; F(0) of the lobe ~25
                                                 * ns of an HG medium's 60, mist_bench) */
        for (i = 0; i < 3 * MIST__PHASE_K + 2; ++i) p.tab[i] = MIST__C(0);
        return p;
    }
    cn = c0 + c1 * ((MIST__C(1) + MIST__C(2) * p.g * p.g) / MIST__C(3));
    /* the start table: the exact u at xi = j/K and the slopes du/dxi / K =
     * 2 cn V^3 / ((1-g^2)(c0 + c1 u^2) K), limited to 3x the neighbouring
     * secants (finite where the density is 0, and a monotone interpolant) */
#if defined(MIST__DRAINE_V)
    if (p.w > MIST__C(0)
        && MIST__FN(mist__draine_vn)(p.g, p.alpha, (size_t)MIST__PHASE_K + 1)) {  /* the kernel: */
        MIST__T xs[MIST__PHASE_K + 1];                 /* the same nodes, 4-5x faster */
        for (i = 0; i <= MIST__PHASE_K; ++i) xs[i] = (MIST__T)i / MIST__PHASE_K;
        MIST__FN(mist__draine_vk)(p.g, p.alpha, c0, c1, p.f0, xs, p.tab,
                                  (size_t)MIST__PHASE_K + 1);
        nodes = 1;
    }
#endif
    for (i = 0; i <= MIST__PHASE_K && !nodes; ++i) {
        MIST__T u = MIST__C(0);
        if (p.w > MIST__C(0) && c1 != MIST__C(0) && p.g < MIST__C(1) && p.g > MIST__C(-1))
            u = MIST__FN(mist__draine_sample)(p.g, p.alpha, c0, c1,
                                              (MIST__T)i / MIST__PHASE_K, p.f0, MIST__NULL);
        p.tab[i] = u;
    }
    for (i = 0; i <= MIST__PHASE_K; ++i) {
        MIST__T u = p.tab[i], v2 = MIST__FN(mist__v2)(p.g, u);
        p.tab[MIST__PHASE_K + 1 + i] = MIST__C(2) * cn * v2 * MIST__M(sqrt)(v2)
            / ((MIST__C(1) - p.g) * (MIST__C(1) + p.g) * (c0 + c1 * u * u) * MIST__PHASE_K);
    }
    for (i = 0; i <= MIST__PHASE_K; ++i) {
        MIST__T *m = &p.tab[MIST__PHASE_K + 1 + i], lim = (MIST__T)INFINITY;
        if (i > 0) lim = MIST__C(3) * (p.tab[i] - p.tab[i - 1]);
        if (i < MIST__PHASE_K && MIST__C(3) * (p.tab[i + 1] - p.tab[i]) < lim)
            lim = MIST__C(3) * (p.tab[i + 1] - p.tab[i]);
        if (!(*m <= lim)) *m = lim;         /* NaN and inf too */
    }
    /* the step bounds (mist__draine_step) per interval: the start (monotone
     * Hermite) and the root lie in [u_j, u_j+1] up to a few ulps of each;
     * widened by a quarter of the interval and 64 eps for that */
    for (i = 0; i < MIST__PHASE_K; ++i) {
        MIST__T dl = MIST__C(0.25) * (p.tab[i + 1] - p.tab[i]) + MIST__C(64) * MIST__EPS;
        MIST__T lo = p.tab[i] - dl, hi = p.tab[i + 1] + dl;
        p.tab[2 * MIST__PHASE_K + 2 + i] = MIST__FN(mist__draine_kb)(p.g, c0, c1,
            lo < MIST__C(-1) ? MIST__C(-1) : lo, hi > MIST__C(1) ? MIST__C(1) : hi);
    }
    return p;
}

/* Henyey-Greenstein, Draine, Cornette-Shanks (Draine at alpha = 1), the
 * Jendersie-d'Eon fog (sanitised as mist_fog_make), Rayleigh: prepared.
 * Domain: any parameters, sanitised as the unprepared functions do. */
MIST__F MIST__PHASE MIST__FN(mist__impl_phase_hg)(MIST__T g)
{
    return MIST__FN(mist__phase_make)(0, g, MIST__C(0), MIST__C(0), MIST__C(0));
}

MIST__F MIST__PHASE MIST__FN(mist__impl_phase_draine)(MIST__T g, MIST__T alpha)
{
    return MIST__FN(mist__phase_make)(0, MIST__C(0), g, alpha, MIST__C(1));
}

MIST__F MIST__PHASE MIST__FN(mist__impl_phase_cs)(MIST__T g)
{
    return MIST__FN(mist__phase_make)(0, MIST__C(0), g, MIST__C(1), MIST__C(1));
}

MIST__F MIST__PHASE MIST__FN(mist__impl_phase_fog)(MIST__FOG fog)
{
    return MIST__FN(mist__phase_make)(0, fog.g_hg, fog.g_d, fog.alpha, fog.w_d);
}

#ifndef MIST_NO_RAYLEIGH
MIST__F MIST__PHASE MIST__FN(mist__impl_phase_rayleigh)(void)
{
    return MIST__FN(mist__phase_make)(1, MIST__C(0), MIST__C(0), MIST__C(1), MIST__C(1));
}
#endif

/* (a + b u^2) / V^3 at sanitised g, u: one lobe's density. */
MIST__F MIST__T MIST__FN(mist__phase_lobe)(MIST__T g, MIST__T a, MIST__T b, MIST__T u)
{
    MIST__T v2;
    if (g == MIST__C(1) || g == MIST__C(-1))                   /* Dirac limit */
        return u == g ? (MIST__T)INFINITY : MIST__C(0);
    v2 = MIST__FN(mist__v2)(g, u);
    return (a + b * u * u) / (v2 * MIST__M(sqrt)(v2));
}

/* The density of a prepared function's lobes (mist_phase, mist_phasec) at
 * u in [-1, 1] (clamped; NaN gives 0). */
MIST__F MIST__T MIST__FN(mist__phase_ev)(int kind, MIST__T ge, MIST__T a1, MIST__T b1,
                                         MIST__T w, MIST__T g_hg, MIST__T a2, MIST__T u)
{
    MIST__T r;
    if (!(u == u)) return MIST__C(0);
    u = MIST__FN(mist__clamp)(u, MIST__C(-1), MIST__C(1));
    r = MIST__FN(mist__phase_lobe)(ge, a1, b1, u);
    if (kind == 2)
        r = w * r + MIST__FN(mist__phase_lobe)(g_hg, a2, MIST__C(0), u);
    return r;
}

/* Density per steradian.  Domain: u in [-1, 1] (clamped; NaN gives 0). */
MIST__F MIST__T MIST__FN(mist__impl_phase_eval)(const MIST__PHASE *p, MIST__T u)
{
    if (!p) return u == u ? MIST__C(MIST__INV4PI) : MIST__C(0);
    return MIST__FN(mist__phase_ev)(p->kind, p->ge, p->a1, p->b1, p->w, p->g_hg, p->a2, u);
}

/* The HG lobe's sample at xi: float with the terms of g read from the
 * medium (p->hg), the same arithmetic as mist_hg_sample's, so that a
 * sample does not recompute them (~0.75x the time, and ~0.85x in
 * mist_bench's four media against the printed eq. 3) */
MIST__F MIST__HOT MIST__T MIST__FN(mist__phase_hg)(const MIST__PHASE *p, MIST__T xi)
{
#if defined(MIST__W_EXACT)
    if (MIST__FN(mist__gxi_in)(p->g_hg, xi)) return MIST__FN(mist__hg_at)(p->hg, xi);
#endif
    return MIST__FN(mist__impl_hg_sample)(p->g_hg, xi);
}

#if defined(MIST__W_EXACT) && !defined(MIST_NO_DRAINE)
/* float: 1 where a prepared Draine lobe samples as the unprepared sampler
 * (|g| >= 0.999; its start table unused): there the table's float nodes
 * hold 1 - u (~1e-6 at g 0.999, where most of the lobe's mass lies near
 * u = 1) only to a few percent, and from their start both straight-line
 * steps miss their bound for 59% of xi (g 0.999, alpha 17, counted).
 * There the unprepared kernel makes the batch ~7x faster, and one at a
 * time the unprepared sampler is the faster one above 0.999 (below, the
 * table wins: 0.7x at .998; mist_bench).  The double lobe's compensated
 * step settles from its double table. */
MIST__F int MIST__FN(mist__phase_near1)(MIST__T g)
{
    return MIST__FN(mist__abs)(g) >= MIST__C(0.999);
}
#endif

/* The Draine lobe's sample at its xi' = x in [0, 1] (not mirrored), from
 * the medium's table (mist_phase_sample of a Draine medium, the fog's
 * Draine lobe, the batch samplers' fallbacks).  Forced inline in
 * mist__phase_sample_w: the prepared try inlined there, ahead of the
 * unprepared sampler's tests (one medium: 0.84x the time where that
 * function is inlined in the caller's loop, 0.97x where it is a call;
 * measured); the batch forms' fallbacks call mist__phase_drx. */
MIST__F MIST__HOT MIST__T MIST__FN(mist__phase_dr)(const MIST__PHASE *p, MIST__T x)
{
    MIST__T u;
    double st;
    if (MIST__M(fabs)(p->g) < MIST__C(1) && p->c1 != MIST__C(0)) {
#if defined(__CUDA_ARCH__) && defined(MIST__DDR)
        /* double in CUDA device code: eq. 6's start, as unprepared (an
         * H200: 0.85x the time; the table's start and its double step
         * cost more there than eq. 6, unlike on a CPU: docs/gpu.md) */
        (void)u; (void)st;
        return MIST__FN(mist__draine_sample)(p->g, p->alpha, p->c0, p->c1, x, p->f0,
                                             MIST__NULL);
#else
#if defined(MIST__W_EXACT)
        if (MIST__FN(mist__phase_near1)(p->g))      /* mist_draine_samplef's values */
            return MIST__FN(mist__draine_sample)(p->g, p->alpha, p->c0, p->c1, x,
                                                 MIST__NULL, MIST__NULL);
#endif
        if (MIST__FN(mist__phase_try)(p->g, p->alpha, p->tab, x, &st, &u)) return u;
        return MIST__FN(mist__draine_finish)(p->g, p->alpha, p->c0, p->c1, x, p->f0, st);
#endif
    }
    return MIST__FN(mist__draine_sample)(p->g, p->alpha, p->c0, p->c1, x, p->f0, p->tab);
}

/* mist_phase_sample past its HG test (p non-null, p->w > 0): Rayleigh,
 * Draine and the fog's mixture (also the batch forms' scalar fallbacks,
 * which need no HG test: called directly, they keep the HG sample out of
 * the batch functions' code) */
MIST__F MIST__T MIST__FN(mist__phase_sample_w)(const MIST__PHASE *p, MIST__T xi)
{
    MIST__T w;
    xi = MIST__FN(mist__clamp)(xi, MIST__C(0), MIST__C(1));
    w = p->w;                                   /* (Rayleigh has w = 1) */
#ifndef MIST_NO_RAYLEIGH
    if (p->kind == 1) return MIST__FN(mist__impl_rayleigh_sample)(xi);
#endif
    {
        MIST__T x, sg;
        int dr = MIST__FN(mist__fog_pick)(xi, w, &x, &sg);
        if (sg < MIST__C(0))       /* a fog's xi' within 1024 eps of 1: the
                                    * mirror, unprepared (mist_fog_sample) */
            return dr ? -MIST__FN(mist__impl_draine_sample)(-p->g, p->alpha, x)
                      : -MIST__FN(mist__impl_hg_sample)(-p->g_hg, x);
        if (!dr) return MIST__FN(mist__phase_hg)(p, x);
        return MIST__FN(mist__phase_dr)(p, x);
    }
}

/* mist__phase_dr as a call (the batch forms' rare fallbacks: one copy) */
MIST__F MIST__T MIST__FN(mist__phase_drx)(const MIST__PHASE *p, MIST__T x)
{
    return MIST__FN(mist__phase_dr)(p, x);
}

/* 1 where x > 0 (not NaN), on the bits: 1 <= bits <= those of +inf.  A
 * floating-point !(w > 0) in mist_phase_sample below lost its NaN case under
 * gcc -ffast-math, header guard or not (x86: -mno-ieee-fp for the whole
 * file; the compare came out as 0 >= w), and a medium with w NaN (set by
 * hand: the constructors clamp it to 0) took the Draine branch there, -1
 * for the HG sample. */
MIST__F MIST__HOT int MIST__FN(mist__gt0)(MIST__T x)
{
    MIST__UB b;
    memcpy(&b, &x, sizeof b);
    return (MIST__UB)(b - 1u) < ((MIST__UB)MIST__EB << MIST__MB);
}

/* u = cos theta from xi in [0, 1] (clamped; NaN taken as 0): the exact
 * inverse CDF, as the unprepared sampler of the same kind.  HG (g
 * sanitised already): the unprepared sampler's arithmetic with the
 * medium's terms of g (mist__phase_hg), here, in a function always inlined
 * (MIST__API_HOT), the rest a call (mist__phase_sample_w): as one
 * function gcc does not inline it in a large translation unit (its
 * unit-growth limits), and a call per HG sample costs ~1.8x the
 * unprepared sampler */
MIST__F MIST__API_HOT MIST__T MIST__FN(mist__impl_phase_sample)(const MIST__PHASE *p, MIST__T xi)
{
    if (!p) return MIST__FN(mist__impl_hg_sample)(MIST__C(0), xi);
    if (!MIST__FN(mist__gt0)(p->w)) return MIST__FN(mist__phase_hg)(p, xi);
    return MIST__FN(mist__phase_sample_w)(p, xi);
}

/* ======================================================================== */
/* Compact prepared phase functions                                         */
/* mist_phasec: the fog mixture or Draine prepared without the start table  */
/* (60 bytes in float, 120 in double, against mist_phase's 1632 and 3208),  */
/* for a GPU closure, where the full table per closure does not fit in     */
/* registers or shared memory.  It keeps what needs no table: the           */
/* sanitised parameters, the density's lobes (mist_phase_eval's arithmetic, */
/* the same values), Draine's weights and F(0) for +g and -g in the wide    */
/* type (hi + lo).  Sampling picks the lobe as mist_fog_sample; the HG lobe */
/* is mist_hg_sample's; the Draine lobe is the unprepared sampler's (float: */
/* [JD23 eq. 6] and its certificate, mist__draine_try6; double: eq. 6 and   */
/* the compensated finish) finished with the stored F(0), where the         */
/* unprepared sampler computes it, so the samples meet the same bar         */
/* |u - u*| <= 4 ulp(u*) + 4 eps xi du / dxi (tests/test_accuracy.c) and    */
/* the costs lie between the prepared and the unprepared sampler's         */
/* (bench/mist_bench.c, "Compact prepared").  Values may differ from       */
/* mist_phase_sample's and mist_fog_sample's in the last bits (each within */
/* the bar); the density is mist_phase_eval's bit for bit.                  */
/* DOMAIN AND BAD INPUT: as mist_phase (the constructors sanitise as       */
/* mist_fog_make); a NULL pointer is the isotropic phase function.         */
/* ======================================================================== */

MIST__F MIST__PHC MIST__FN(mist__impl_phasec_fog)(MIST__FOG fog)
{
    return MIST__FN(mist__phasec_make)(0, fog.g_hg, fog.g_d, fog.alpha, fog.w_d);
}

MIST__F MIST__PHC MIST__FN(mist__impl_phasec_draine)(MIST__T g, MIST__T alpha)
{
    return MIST__FN(mist__phasec_make)(0, MIST__C(0), g, alpha, MIST__C(1));
}

/* Density per steradian.  Domain: u in [-1, 1] (clamped; NaN gives 0). */
MIST__F MIST__T MIST__FN(mist__impl_phasec_eval)(const MIST__PHC *p, MIST__T u)
{
    if (!p) return u == u ? MIST__C(MIST__INV4PI) : MIST__C(0);
    return MIST__FN(mist__phase_ev)(p->kind, p->ge, p->a1, p->b1, p->w, p->g_hg, p->a2, u);
}

/* u = cos theta from xi in [0, 1] (clamped; NaN taken as 0). */
MIST__F MIST__T MIST__FN(mist__impl_phasec_sample)(const MIST__PHC *p, MIST__T xi)
{
    MIST__T x, sg;
    int dr;
    if (!p) return MIST__FN(mist__impl_hg_sample)(MIST__C(0), xi);
    if (!MIST__FN(mist__gt0)(p->w)) return MIST__FN(mist__impl_hg_sample)(p->g_hg, xi);
    xi = MIST__FN(mist__clamp)(xi, MIST__C(0), MIST__C(1));
    dr = MIST__FN(mist__fog_pick)(xi, p->w, &x, &sg);
    if (sg < MIST__C(0))            /* xi' within 1024 eps of 1: the mirror */
        return dr ? -MIST__FN(mist__impl_draine_sample)(-p->g, p->alpha, x)
                  : -MIST__FN(mist__impl_hg_sample)(-p->g_hg, x);
    if (!dr) return MIST__FN(mist__impl_hg_sample)(p->g_hg, x);
    return MIST__FN(mist__draine_sample)(p->g, p->alpha, p->c0, p->c1, x, p->f0, MIST__NULL);
}

#ifndef MIST_NO_DIR
MIST__F MIST__V3 MIST__FN(mist__impl_dir_from_cos)(MIST__V3 wi, MIST__T u, MIST__T xi);

/* Scattered direction around wi and its pdf (may be NULL), as *_sample_dir. */
MIST__F MIST__V3 MIST__FN(mist__impl_phasec_sample_dir)(const MIST__PHC *p, MIST__V3 wi,
                                                        MIST__T xi1, MIST__T xi2, MIST__T *pdf)
{
    MIST__T u = MIST__FN(mist__impl_phasec_sample)(p, xi1);
    if (pdf) *pdf = MIST__FN(mist__impl_phasec_eval)(p, u);
    return MIST__FN(mist__impl_dir_from_cos)(wi, u, xi2);
}

/* Scattered direction around the propagation direction wi and its pdf
 * (= mist_phase_eval at its cosine; pdf may be NULL), as *_sample_dir. */
MIST__F MIST__V3 MIST__FN(mist__impl_phase_sample_dir)(const MIST__PHASE *p, MIST__V3 wi,
                                                   MIST__T xi1, MIST__T xi2, MIST__T *pdf)
{
    MIST__T u = MIST__FN(mist__impl_phase_sample)(p, xi1);
    if (pdf) *pdf = MIST__FN(mist__impl_phase_eval)(p, u);
    return MIST__FN(mist__impl_dir_from_cos)(wi, u, xi2);
}
#endif
#undef MIST__PHASE
#undef MIST__PHC

/* ======================================================================== */
/* Droplet-size fits [JD23 supplemental, eq. 7-22]                          */
/* The fog phase function's four parameters as functions of the droplet    */
/* diameter d in micrometres, 0 < d <= 50, in the paper's four ranges:      */
/*   d <= 0.1       eq. 11-14     0.1 < d < 1.5   eq. 15-18                 */
/*   1.5 <= d < 5   eq. 19-22     5 <= d <= 50    eq. 7-10                  */
/* log is the natural logarithm.  Eq. 8 and 10 are printed with the         */
/* constants -0.428934 and -0.665888 outside the exponential; mist reads    */
/* them INSIDE, g_d = exp(-2.20679/(d+3.91029) - 0.428934) and w_d =        */
/* exp(-0.599085/(d-0.641583) - 0.665888), as Blender Cycles does: only     */
/* this reading meets the 1.5-5 um fit at d = 5 (w_d 0.442 vs 0.448; the    */
/* printed reading jumps to 0.206), and it is the one closer to Lorenz-Mie  */
/* (measured: tests/test_fits.c, docs/mie.md).                              */
/* The published ranges do not meet at d = 0.1 and 1.5: the fits are kept   */
/* as published, with the jumps measured in docs/mie.md.  Each type       */
/* compares d with its own rounding of the bounds, so that the literal 0.1  */
/* (0.1f) lands in eq. 11-14 in both: mist_fog_from_diameterf(0.1f) and     */
/* mist_fog_from_diameter(0.1) agree, while mist_fog_from_diameter((double) */
/* 0.1f), 1.5e-9 above 0.1, takes eq. 15-18 (the 0.1 um jump: g_hg 0.138   */
/* against 0.104; found by an independent check).                          */
/* Domain: d in (0, 50].  d <= 0 and NaN give the d -> 0 limit of eq. 11-14 */
/* (g_hg = g_d = 0, alpha = 250, w_d = 0.252977: Rayleigh-like); d > 50     */
/* (and +inf) is clamped to 50, the end of the fitted range.                */
/* ======================================================================== */

MIST__F MIST__FOG MIST__FN(mist__impl_fog_from_diameter)(MIST__T d)
{
    MIST__T gh, gd, a, w, l;
    if (!(d > MIST__C(0))) d = MIST__C(0);          /* NaN, d <= 0: d -> 0 */
    if (d > MIST__C(50)) d = MIST__C(50);
    if (d <= MIST__C(0.1)) {                         /* eq. 11-14 */
        gh = MIST__C(13.8) * d * d;
        gd = MIST__C(1.1456) * d * MIST__M(sin)(MIST__C(9.29044) * d);
        a  = MIST__C(250);
        w  = MIST__C(0.252977) - MIST__C(312.983) * MIST__M(pow)(d, MIST__C(4.3));
    } else if (d < MIST__C(1.5)) {                   /* eq. 15-18 */
        l  = MIST__M(log)(d);
        gh = MIST__C(0.862) - MIST__C(0.143) * l * l;
        gd = MIST__C(0.379685) * MIST__M(cos)(MIST__C(1.19692) * MIST__M(cos)(
                 (l - MIST__C(0.238604)) * (l + MIST__C(1.00667))
                 / (MIST__C(0.507522) - MIST__C(0.15677) * l))
                 + MIST__C(1.37932) * l + MIST__C(0.0625835)) + MIST__C(0.344213);
        a  = MIST__C(250);
        w  = MIST__C(0.146209) * MIST__M(cos)(MIST__C(3.38707) * l + MIST__C(2.11193))
           + MIST__C(0.316072) + MIST__C(0.0778917) * l;
    } else if (d < MIST__C(5)) {                     /* eq. 19-22 */
        l  = MIST__M(log)(d);
        gh = MIST__C(0.0604931) * MIST__M(log)(l) + MIST__C(0.940256);
        gd = MIST__C(0.500411) - MIST__C(0.081287)
             / (MIST__C(-2) * l + MIST__M(tan)(l) + MIST__C(1.27551));
        a  = MIST__C(7.30354) * l + MIST__C(6.31675);
        w  = MIST__C(0.026914) * (l - MIST__M(cos)(MIST__C(5.68947)
             * (MIST__M(log)(l) - MIST__C(0.0292149)))) + MIST__C(0.376475);
    } else {                                         /* eq. 7-10 */
        gh = MIST__M(exp)(MIST__C(-0.0990567) / (d - MIST__C(1.67154)));
        gd = MIST__M(exp)(MIST__C(-2.20679) / (d + MIST__C(3.91029)) - MIST__C(0.428934));
        a  = MIST__M(exp)(MIST__C(3.62489) - MIST__C(8.29288) / (d + MIST__C(5.52825)));
        w  = MIST__M(exp)(MIST__C(-0.599085) / (d - MIST__C(0.641583)) - MIST__C(0.665888));
    }
    return MIST__FN(mist__impl_fog_make)(gh, gd, a, w);
}

/* ======================================================================== */
/* Droplet sizes fitted to Lorenz-Mie, continuous in d                      */
/* The fog mix's four parameters fitted by tools/fit_droplet.c to the       */
/* Lorenz-Mie phase function of water droplets, averaged over 450, 550 and  */
/* 650 nm and a lognormal size distribution of median diameter d and        */
/* geometric width 1.1 (the reference of docs/mie.md's fit-error table),    */
/* minimising logRMS^2 + (0.35 L1)^2 (tests/mist_dropfit.h) at MIST__DROP_N */
/* nodes uniform in log d from 0.01 to 50 um, and at the points between     */
/* them as interpolated.  Each parameter (alpha as log alpha) is a cubic    */
/* Hermite interpolant in log d with Fritsch-Butland slopes (the harmonic   */
/* mean of the two secants, 0 where they differ in sign; at the ends the    */
/* end secant): monotone where the nodes are and never outside the two      */
/* nodes' values, so every parameter is continuous in d and valid (|g| <=   */
/* 1, 0 < alpha <= 1000, w_d in [0, 1]) by construction.  The first node is */
/* eq. 11-14 at d = 0.01, which the function is below it (and for d <= 0    */
/* and NaN, as mist_fog_from_diameter): the join is continuous.  d > 50     */
/* (and +inf) is clamped to 50.  Against the published fits: no worse at    */
/* docs/mie.md's 17 diameters, geometric mean L1 0.026 and logRMS 0.018     */
/* there against 0.113 and 0.067 (tests/test_fits_mie.c).  mist__fog_interp */
/* reads the table as rows (g_hg, g_d, log alpha, w_d), n >= 2 of them, so  */
/* that the tool evaluates its candidates with this code.                   */
/* ======================================================================== */
#define MIST__DROP_N 56

MIST__F MIST__FOG MIST__FN(mist__fog_interp)(const double *tab, int n, MIST__T d)
{
    /* in double for both types (the float pass rounds the four results
     * once: in float t near 55 would move in steps of 4e-6, a staircase) */
    double lo = -4.60517018598809136804,               /* log 0.01 */
           hi = 3.91202300542814605862,                /* log 50 */
           x = (double)d, t, s, v[4], h00, h10, h01, h11;
    int i, j;
    if (!(d > MIST__C(0.01))) return MIST__FN(mist__impl_fog_from_diameter)(d);
    if (x > 50) x = 50;
    t = (log(x) - lo) / (hi - lo) * (double)(n - 1);
    i = t < 0 ? 0 : t >= (double)(n - 2) ? n - 2 : (int)t;
    s = t - (double)i;
    s = s < 0 ? 0 : s > 1 ? 1 : s;
    h01 = s * s * (3 - 2 * s);
    h00 = 1 - h01;
    h10 = s * (1 - s) * (1 - s);
    h11 = s * s * (s - 1);
    for (j = 0; j < 4; ++j) {
        double y0 = tab[4 * i + j], y1 = tab[4 * (i + 1) + j];
        double c = y1 - y0, a = i > 0 ? y0 - tab[4 * (i - 1) + j] : c,
               b = i + 2 < n ? tab[4 * (i + 2) + j] - y1 : c;
        double m0 = a * c > 0 ? 2 * a * c / (a + c) : 0,
               m1 = c * b > 0 ? 2 * c * b / (c + b) : 0;
        v[j] = h00 * y0 + h10 * m0 + h01 * y1 + h11 * m1;
    }
    v[2] = exp(v[2]);
    v[2] = v[2] < 1000 ? v[2] : 1000;             /* the bound, exactly in float too */
    return MIST__FN(mist__impl_fog_make)((MIST__T)v[0], (MIST__T)v[1], (MIST__T)v[2],
                                         (MIST__T)v[3]);
}

MIST__F MIST__FOG MIST__FN(mist__impl_fog_from_diameter_mie)(MIST__T d)
{
    static const double tab[4 * MIST__DROP_N] = {
        /* BEGIN TABLE: tools/fit_droplet.c --header include/mist.h */
        0.001380000, 0.001062782, 5.521460918, 0.252976214, /* 0.01 um */
        0.000975359, 0.000722201, 5.521460918, 0.253002764, /* 0.01167 um */
        0.001455591, 0.001186066, 5.521491672, 0.252997753, /* 0.01363 um */
        0.001991769, 0.001480018, 5.521426824, 0.252996392, /* 0.01591 um */
        0.002710372, 0.002065200, 5.521438738, 0.252992909, /* 0.01858 um */
        0.003692092, 0.002802323, 5.521450809, 0.252986327, /* 0.02169 um */
        0.005031144, 0.003821075, 5.521453703, 0.252974131, /* 0.02532 um */
        0.006854792, 0.005202153, 5.521456533, 0.252951958, /* 0.02957 um */
        0.009339066, 0.007081560, 5.521456533, 0.252910746, /* 0.03452 um */
        0.012722486, 0.009634444, 5.521456483, 0.252834260, /* 0.0403 um */
        0.017330970, 0.013098491, 5.521453642, 0.252692263, /* 0.04705 um */
        0.023610602, 0.017789804, 5.521446604, 0.252428139, /* 0.05493 um */
        0.032176298, 0.024126119, 5.521456255, 0.251935886, /* 0.06413 um */
        0.043890340, 0.032645772, 5.521514213, 0.251012792, /* 0.07487 um */
        0.059974476, 0.044027544, 5.521888863, 0.249267873, /* 0.08741 um */
        0.082347787, 0.059023947, 5.521251993, 0.245873363, /* 0.102 um */
        0.113489213, 0.078269153, 5.514052510, 0.239296321, /* 0.1191 um */
        0.159987272, 0.099725721, 5.537095029, 0.224624217, /* 0.1391 um */
        0.231810771, 0.109926608, 5.703255921, 0.186096015, /* 0.1624 um */
        0.317730767, 0.130457853, 6.109915960, 0.129624820, /* 0.1896 um */
        0.413533558, 0.004211232, 6.907755278, 0.020152152, /* 0.2214 um */
        0.515859588, 0.447959009, 6.907755278, 0.000000000, /* 0.2584 um */
        0.607515892, 0.556923386, 6.907755278, 0.000000000, /* 0.3017 um */
        0.662784943, 0.610163401, 6.907755278, 0.113460676, /* 0.3522 um */
        0.693185331, 0.649573509, 6.907755278, 0.359793212, /* 0.4112 um */
        0.706090746, 0.668826463, 6.907755278, 0.540854875, /* 0.4801 um */
        0.732034527, 0.709533623, 6.907755278, 0.581968393, /* 0.5605 um */
        0.750553580, 0.737437021, 6.907755278, 0.599606733, /* 0.6544 um */
        0.783409312, 0.750751488, 6.907755278, 0.522215976, /* 0.764 um */
        0.511322252, 0.779573597, 0.675540292, 0.979364569, /* 0.892 um */
        -0.105394802, 0.789087747, 0.737927095, 0.985230186, /* 1.041 um */
        0.895176008, 0.748964817, 0.680866932, 0.862483203, /* 1.216 um */
        0.851213295, 0.444908725, 2.493697067, 0.245403092, /* 1.419 um */
        0.869973904, 0.380172055, 2.040690373, 0.372050054, /* 1.657 um */
        0.905478381, 0.383782571, 1.944333175, 0.506002447, /* 1.935 um */
        0.917087448, 0.332926250, 2.164226425, 0.422373828, /* 2.259 um */
        0.920789897, 0.303841354, 2.446531865, 0.328405534, /* 2.637 um */
        0.927052975, 0.325521097, 2.757293230, 0.289167418, /* 3.079 um */
        0.938916758, 0.398831064, 2.726321579, 0.338174146, /* 3.595 um */
        0.952053259, 0.463337333, 2.594653727, 0.427552496, /* 4.197 um */
        0.960859600, 0.474409484, 2.671896094, 0.423019622, /* 4.9 um */
        0.966648220, 0.487994946, 2.726625851, 0.436814725, /* 5.72 um */
        0.971555315, 0.499908011, 2.750563462, 0.444785249, /* 6.678 um */
        0.976355477, 0.517309391, 2.774745376, 0.455868384, /* 7.797 um */
        0.980153826, 0.534734785, 2.810048306, 0.467318387, /* 9.103 um */
        0.983161839, 0.544397103, 2.845957712, 0.468678459, /* 10.63 um */
        0.985831941, 0.553943759, 2.877452840, 0.474963729, /* 12.41 um */
        0.987996670, 0.562828907, 2.952128017, 0.477521469, /* 14.49 um */
        0.989831959, 0.570342511, 2.984934992, 0.480015282, /* 16.91 um */
        0.991327673, 0.575943116, 3.023434911, 0.481470733, /* 19.74 um */
        0.992601908, 0.582610544, 3.058539604, 0.480929651, /* 23.05 um */
        0.993653291, 0.591241388, 3.082706559, 0.480071919, /* 26.91 um */
        0.994580502, 0.597487334, 3.106492259, 0.481030589, /* 31.42 um */
        0.995356312, 0.604720870, 3.117076122, 0.478994191, /* 36.68 um */
        0.996024744, 0.609592296, 3.112900957, 0.478994191, /* 42.83 um */
        0.996594487, 0.615274313, 3.139123041, 0.476895011,  /* 50 um */
        /* END TABLE */
    };
    return MIST__FN(mist__fog_interp)(tab, MIST__DROP_N, d);
}
#endif /* !MIST_NO_FOG */

/* ======================================================================== */
/* Directions                                                               */
/* The frame around the propagation direction is the branchless orthonormal */
/* basis of [DHB17], exact to rounding for every unit direction (including  */
/* the poles, where the classic Frisvad frame breaks).  sin(theta) is       */
/* sqrt((1-u)(1+u)): no cancellation near u = +-1.                          */
/* ======================================================================== */

#if !defined(MIST__W_EXACT)
/* A power of 2 that scales finite m > 0 into [2, 4): 2^(EB - E) for m's
 * exponent field E in [1, EB - 1] (m 2^(EB - E) = 1.f 2^(EB - 2 bias) =
 * 1.f 2); for subnormal m (E = 0) 2^bias, the largest normal power, which
 * makes it >= 2^(1 - MB).  Exact to multiply by; no division. */
MIST__F MIST__T MIST__FN(mist__pow2inv)(MIST__T m)
{
    MIST__UB b, e, f = (MIST__UB)MIST__EB << MIST__MB;
    MIST__T s;
    memcpy(&b, &m, sizeof b);
    e = b & f;
    b = f - (e ? e : (MIST__UB)1 << MIST__MB);
    memcpy(&s, &b, sizeof s);
    return s;
}
#endif

/* Unit vector along v; zero, NaN or infinite v gives (0, 0, 1).  Double:
 * scaled first by a power of 2 that puts the largest component in [2, 4)
 * (mist__pow2inv: exact), so no overflow or underflow.  Float: in double,
 * where the squares of floats neither overflow nor underflow (<= 1.2e77,
 * >= 2e-90), so |v|^2 itself tells 0, NaN and inf apart; one rounding at
 * the end.  One division, for 1/|v| (dividing by the largest component
 * would take three more) */
MIST__F MIST__V3 MIST__FN(mist__impl_normalize)(MIST__V3 v)
{
#if defined(MIST__W_EXACT)
    MIST__W x = (MIST__W)v.x, y = (MIST__W)v.y, z = (MIST__W)v.z, d = x * x + y * y + z * z, il;
    if (!(d > 0 && d < 1e300)) {                         /* 0, NaN, inf */
        v.x = MIST__C(0); v.y = MIST__C(0); v.z = MIST__C(1);
        return v;
    }
    il = 1 / sqrt(d);
    v.x = (MIST__T)(x * il); v.y = (MIST__T)(y * il); v.z = (MIST__T)(z * il);
#else
    MIST__T ax = MIST__M(fabs)(v.x), ay = MIST__M(fabs)(v.y), az = MIST__M(fabs)(v.z);
    MIST__T m = ax > ay ? ax : ay, s, il;
    m = m > az ? m : az;
    if (!(m > MIST__C(0)) || !(v.x - v.x == MIST__C(0) && v.y - v.y == MIST__C(0)
                               && v.z - v.z == MIST__C(0))) {  /* 0, NaN, inf */
        v.x = MIST__C(0); v.y = MIST__C(0); v.z = MIST__C(1);
        return v;
    }
    s = MIST__FN(mist__pow2inv)(m);
    v.x *= s; v.y *= s; v.z *= s;
    il = MIST__C(1) / MIST__M(sqrt)(v.x * v.x + v.y * v.y + v.z * v.z);
    v.x *= il; v.y *= il; v.z *= il;
#endif
    return v;
}

#ifndef MIST_NO_DIR
/* The direction at cosine u to wi and azimuth 2 pi xi around it.
 * Domain: wi any vector (normalised as mist_normalize), u in [-1, 1],
 * xi in [0, 1]. */
MIST__F MIST__V3 MIST__FN(mist__impl_dir_from_cos)(MIST__V3 wi, MIST__T u, MIST__T xi)
{
    MIST__V3 n = MIST__FN(mist__impl_normalize)(wi), t, b, o;
    MIST__T sgn = MIST__M(copysign)(MIST__C(1), n.z + MIST__C(0));   /* -0 + 0 = +0: +1 */
    MIST__T a = MIST__C(-1) / (sgn + n.z), bb = n.x * n.y * a;
    MIST__T s, phi, cp, sp;
    u  = MIST__FN(mist__clamp)(u, MIST__C(-1), MIST__C(1));
    xi = MIST__FN(mist__clamp)(xi, MIST__C(0), MIST__C(1));
    s = MIST__M(sqrt)((MIST__C(1) - u) * (MIST__C(1) + u));
    phi = MIST__C(MIST__2PI) * xi;
    cp = MIST__M(cos)(phi); sp = MIST__M(sin)(phi);
    t.x = MIST__C(1) + sgn * n.x * n.x * a; t.y = sgn * bb; t.z = -sgn * n.x;
    b.x = bb; b.y = sgn + n.y * n.y * a; b.z = -n.y;
    o.x = u * n.x + s * (cp * t.x + sp * b.x);
    o.y = u * n.y + s * (cp * t.y + sp * b.y);
    o.z = u * n.z + s * (cp * t.z + sp * b.z);
    return o;
}

/* Scattered direction and its pdf (= the density, per steradian) for each
 * phase function.  wi: the incident PROPAGATION direction; xi1 picks
 * cos(theta) (exact inverse CDF), xi2 the azimuth.  pdf may be NULL.
 * Domain: the phase function's parameters as its sampler's; wi any vector
 * (zero, NaN, inf: (0, 0, 1)); xi1, xi2 in [0, 1] (clamped; NaN as 0). */
MIST__F MIST__V3 MIST__FN(mist__impl_hg_sample_dir)(MIST__T g, MIST__V3 wi, MIST__T xi1, MIST__T xi2,
                                                MIST__T *pdf)
{
    MIST__T u = MIST__FN(mist__impl_hg_sample)(g, xi1);
    if (pdf) *pdf = MIST__FN(mist__impl_hg_eval)(g, u);
    return MIST__FN(mist__impl_dir_from_cos)(wi, u, xi2);
}

#ifndef MIST_NO_DRAINE
MIST__F MIST__V3 MIST__FN(mist__impl_draine_sample_dir)(MIST__T g, MIST__T alpha, MIST__V3 wi,
                                                    MIST__T xi1, MIST__T xi2, MIST__T *pdf)
{
    MIST__T u = MIST__FN(mist__impl_draine_sample)(g, alpha, xi1);
    if (pdf) *pdf = MIST__FN(mist__impl_draine_eval)(g, alpha, u);
    return MIST__FN(mist__impl_dir_from_cos)(wi, u, xi2);
}

MIST__F MIST__V3 MIST__FN(mist__impl_cs_sample_dir)(MIST__T g, MIST__V3 wi, MIST__T xi1, MIST__T xi2,
                                                MIST__T *pdf)
{
    return MIST__FN(mist__impl_draine_sample_dir)(g, MIST__C(1), wi, xi1, xi2, pdf);
}
#endif

#ifndef MIST_NO_RAYLEIGH
MIST__F MIST__V3 MIST__FN(mist__impl_rayleigh_sample_dir)(MIST__V3 wi, MIST__T xi1, MIST__T xi2,
                                                      MIST__T *pdf)
{
    MIST__T u = MIST__FN(mist__impl_rayleigh_sample)(xi1);
    if (pdf) *pdf = MIST__FN(mist__impl_rayleigh_eval)(u);
    return MIST__FN(mist__impl_dir_from_cos)(wi, u, xi2);
}
#endif

#ifndef MIST_NO_FOG
MIST__F MIST__V3 MIST__FN(mist__impl_fog_sample_dir)(MIST__FOG fog, MIST__V3 wi,
                                                 MIST__T xi1, MIST__T xi2, MIST__T *pdf)
{
    MIST__T u = MIST__FN(mist__impl_fog_sample)(fog, xi1);
    if (pdf) *pdf = MIST__FN(mist__impl_fog_eval)(fog, u);
    return MIST__FN(mist__impl_dir_from_cos)(wi, u, xi2);
}
#endif
#endif /* !MIST_NO_DIR */

#ifndef MIST_NO_BATCH
/* ======================================================================== */
/* Batch forms: out[i] = f(in[i]), i < n                                    */
/* Each equals its scalar function element by element (the same kernels:   */
/* mist__hg_d, mist__hg_one, mist__rayleigh_u, mist__draine_step,           */
/* mist__clamp01/11, forced inline: MIST__HOT), with the parameters         */
/* sanitised once.  The work goes in blocks of MIST__BLK into local arrays: */
/* the block loop has a constant trip count, no aliasing (so in == out is   */
/* allowed) and a branch-free body, which gcc's -O2 "very cheap" cost model */
/* and clang vectorise.  The unprepared Draine sampler outside its eq. 6   */
/* kernel (iterations, below MIST_DRAINE_PREPARE_N), the double Draine      */
/* samplers in long double and the double HG sampler without fma are plain  */
/* loops over the scalar one.                                               */
/* Domain of each: the scalar function's, element by element; n = 0 does   */
/* nothing (in, out may then be NULL); out == in is allowed, other overlaps */
/* are not.                                                                 */
/* ======================================================================== */

/* The Dirac limit |g| = 1 of every eval: +inf at u = g, else 0 (NaN: 0). */
MIST__F void MIST__FN(mist__dirac_n)(MIST__T g, const MIST__T *in, MIST__T *out, size_t n)
{
    MIST__BLOCKS(y_[j_] = MIST__FN(mist__clamp11)(x_[j_]) == g ? (MIST__T)INFINITY
                                                              : MIST__C(0))
}

/* HG density per steradian of each in[i] = u: mist_hg_eval(g, u). */
MIST__F void MIST__FN(mist__impl_hg_eval_n)(MIST__T g, const MIST__T *in, MIST__T *out, size_t n)
{
    MIST__T k;
    g = MIST__FN(mist__g)(g);
    if (g == MIST__C(1) || g == MIST__C(-1)) {
        MIST__FN(mist__dirac_n)(g, in, out, n);
        return;
    }
    k = MIST__FN(mist__hg_k)(g);
    MIST__BLOCKS(MIST__T u = x_[j_];
                 MIST__T p = MIST__FN(mist__hg_d)(k, g, MIST__FN(mist__clamp11)(u));
                 y_[j_] = u == u ? p : MIST__C(0))
}

/* HG sample of each in[i] = xi: mist_hg_sample(g, xi). */
MIST__F void MIST__FN(mist__impl_hg_sample_n)(MIST__T g, const MIST__T *in, MIST__T *out, size_t n)
{
    size_t i;
    g = MIST__FN(mist__g)(g);
    if (g == MIST__C(1) || g == MIST__C(-1)) {
        for (i = 0; i < n; ++i) out[i] = g;
        return;
    }
#if defined(MIST__W_EXACT)
    {   /* float: the one form in double, branch-free (mist__hg_one); the 0
         * and 1 of the clamp at run time (see below) */
        volatile MIST__T z0 = 0;
        MIST__T z = z0, one = z + 1;
        MIST__W t[3];
        MIST__FN(mist__hg_par)(g, t);
        MIST__BLOCKS(y_[j_] = MIST__FN(mist__hg_at)(t, MIST__FN(mist__clamp01)(x_[j_], z, one)))
    }
#elif defined(MIST__DDV)
    {   /* double-double (mist__hg_ddu), branch-free, 0 and 1 read at run
         * time (see below) */
        volatile MIST__T z0 = 0;
        MIST__T z = z0, one = z + 1;
        MIST__BLOCKS(MIST__T xi = MIST__FN(mist__clamp01)(x_[j_], z, one);
                     y_[j_] = MIST__FN(mist__hg_ddu)(g, xi, z, one))
    }
#else
    /* double-double by Dekker's product: the loop was faster than the
     * vectorised kernel (see mist_rayleigh_sample_n) */
    for (i = 0; i < n; ++i) out[i] = MIST__FN(mist__impl_hg_sample)(g, in[i]);
#endif
}

#ifndef MIST_NO_DRAINE
/* Draine density per steradian of each in[i] = u: mist_draine_eval. */
MIST__F void MIST__FN(mist__impl_draine_eval_n)(MIST__T g, MIST__T alpha, const MIST__T *in,
                                          MIST__T *out, size_t n)
{
    MIST__T k, c0, c1, cn;
    g = MIST__FN(mist__g)(g);
    if (g == MIST__C(1) || g == MIST__C(-1)) {
        MIST__FN(mist__dirac_n)(g, in, out, n);
        return;
    }
    MIST__FN(mist__draine_c)(alpha, &c0, &c1);
    k = MIST__FN(mist__hg_k)(g);
    cn = MIST__FN(mist__draine_cn)(g, c0, c1);
    MIST__BLOCKS(MIST__T u = x_[j_];
                 MIST__T p = MIST__FN(mist__draine_d)(k, g, c0, c1, cn,
                                                      MIST__FN(mist__clamp11)(u));
                 y_[j_] = u == u ? p : MIST__C(0))
}

#ifndef MIST_NO_FOG
MIST__F void MIST__FN(mist__impl_phase_sample_n)(const MIST__FN(mist_phase) *p, const MIST__T *in,
                                           MIST__T *out, size_t n);
#endif

/* Draine sample of each in[i] = xi.  Where the kernel above applies
 * (mist__draine_vn), the scalar values.  Elsewhere: below MIST_DRAINE_PREPARE_N
 * elements a loop over mist_draine_sample; from there on the batch is one
 * medium, so it is prepared once (mist_phase_draine: the cost of ~130-140
 * samples) and sampled by mist_phase_sample_n: the prepared sampler's
 * values, which meet the same bar and are monotone in xi but may differ
 * from mist_draine_sample's in the last bit (measured: 1.1e-4 of random xi
 * in float, 1.2e-3 in double; see "Prepared phase functions").  Without
 * the prepared functions (MIST_NO_FOG) and in CUDA device code (a 1.6-3.1
 * KB table per thread): always the loop. */
MIST__F void MIST__FN(mist__impl_draine_sample_n)(MIST__T g, MIST__T alpha, const MIST__T *in,
                                            MIST__T *out, size_t n)
{
    size_t i;
#if defined(MIST__DRAINE_V)
    if (MIST__FN(mist__draine_vn)(g, alpha, n)) {
        MIST__T c0, c1;
        MIST__FN(mist__draine_c)(alpha, &c0, &c1);
        MIST__FN(mist__draine_vk)(MIST__FN(mist__g)(g), alpha, c0, c1, MIST__NULL, in, out, n);
        return;
    }
#endif
#if !defined(MIST_NO_FOG) && !defined(__CUDA_ARCH__)
    if (n != 0 && n >= (size_t)MIST_DRAINE_PREPARE_N) {
        MIST__FN(mist_phase) p = MIST__FN(mist__impl_phase_draine)(g, alpha);
        MIST__FN(mist__impl_phase_sample_n)(&p, in, out, n);
        return;
    }
#endif
    for (i = 0; i < n; ++i) out[i] = MIST__FN(mist__impl_draine_sample)(g, alpha, in[i]);
}
#endif /* !MIST_NO_DRAINE */

#ifndef MIST_NO_RAYLEIGH
/* Rayleigh density per steradian of each in[i] = u: mist_rayleigh_eval. */
MIST__F void MIST__FN(mist__impl_rayleigh_eval_n)(const MIST__T *in, MIST__T *out, size_t n)
{
    MIST__BLOCKS(y_[j_] = MIST__FN(mist__impl_rayleigh_eval)(x_[j_]))   /* branch-free */
}

/* Rayleigh sample of each in[i] = xi: mist_rayleigh_sample (float:
 * vectorised, the same root in double; double: vectorised, in double-double,
 * also by Dekker's product where fma is no instruction: 15.6 -> 9.5 ns an
 * element with SSE2, 5.8 with AVX, gcc 12 -O2/-O3, measured; the HG batch
 * so vectorised was slower than its loop, 14.1 against 12.2 ns). */
MIST__F void MIST__FN(mist__impl_rayleigh_sample_n)(const MIST__T *in, MIST__T *out, size_t n)
{
#if defined(MIST__W_EXACT)
    volatile MIST__T z0 = 0;
    MIST__T z = z0, one = z + 1;
    MIST__BLOCKS(MIST__W x = (MIST__W)MIST__FN(mist__clamp01)(x_[j_], z, one);
                 y_[j_] = MIST__FN(mist__clamp11)((MIST__T)MIST__WFN(mist__rayleigh_u)(x)))
#elif defined(MIST__DD)
    volatile MIST__T z0 = 0;
    MIST__T z = z0, one = z + 1;
    MIST__BLOCKS(MIST__T x = MIST__FN(mist__clamp01)(x_[j_], z, one);
                 y_[j_] = MIST__FN(mist__clamp11)(MIST__FN(mist__rayleigh_udd)(x)))
#else
    size_t i;
    for (i = 0; i < n; ++i) out[i] = MIST__FN(mist__impl_rayleigh_sample)(in[i]);
#endif
}
#endif /* !MIST_NO_RAYLEIGH */

#ifndef MIST_NO_FOG
/* Prepared density of each in[i] = u: mist_phase_eval(p, u).  One lobe
 * (HG, Draine, CS, Rayleigh, a fog whose lobes share g) branch-free. */
MIST__F void MIST__FN(mist__impl_phase_eval_n)(const MIST__FN(mist_phase) *p, const MIST__T *in,
                                         MIST__T *out, size_t n)
{
    size_t i;
    if (p && p->kind != 2 && p->ge > MIST__C(-1) && p->ge < MIST__C(1)) {
        MIST__T ge = p->ge, a = p->a1, b = p->b1;
        MIST__BLOCKS(MIST__T u = x_[j_];
                     MIST__T c = MIST__FN(mist__clamp11)(u);
                     MIST__T v2 = MIST__FN(mist__v2)(ge, c);
                     MIST__T r = (a + b * c * c) / (v2 * MIST__M(sqrt)(v2));
                     y_[j_] = u == u ? r : MIST__C(0))
        return;
    }
    if (p && p->kind == 2 && p->ge > MIST__C(-1) && p->ge < MIST__C(1)
        && p->g_hg > MIST__C(-1) && p->g_hg < MIST__C(1)) {   /* two lobes, branch-free */
        MIST__T ge = p->ge, a = p->a1, b = p->b1, gh = p->g_hg, a2 = p->a2, w = p->w;
        MIST__BLOCKS(MIST__T u = x_[j_];
                     MIST__T c = MIST__FN(mist__clamp11)(u);
                     MIST__T v2 = MIST__FN(mist__v2)(ge, c);
                     MIST__T h2 = MIST__FN(mist__v2)(gh, c);
                     MIST__T r = (a + b * c * c) / (v2 * MIST__M(sqrt)(v2));
                     MIST__T rh = (a2 + MIST__C(0) * c * c) / (h2 * MIST__M(sqrt)(h2));
                     y_[j_] = u == u ? w * r + rh : MIST__C(0))
        return;
    }
    for (i = 0; i < n; ++i) out[i] = MIST__FN(mist__impl_phase_eval)(p, in[i]);
}

#if defined(MIST__W_EXACT) && !defined(MIST_NO_DRAINE)
/* The pending elements of mist_phase_sample_n: those whose first step did
 * not give the rounded u, with what that step left (the start of a second
 * step, or the bound to round within). */
typedef struct {
    int m;                                      /* elements pending */
    size_t at[MIST__BLK];                       /* their places in out */
    MIST__T xi[MIST__BLK];                      /* xi, clamped */
    MIST__W u[MIST__BLK], eb[MIST__BLK], kb[MIST__BLK];   /* the step's u1, bound, kb */
    unsigned char again[MIST__BLK];             /* 1: a second step; 0: only rounding */
} MIST__FN(mist__pend);

/* Finishes the pending elements as mist__draine_sample does after its
 * first step: a second step from u1 (again = 1: the first did not meet its
 * bound and u1 lies in the table interval), then mist__draine_round (the
 * residual's sign where the bound straddles two values of T).  A
 * straight-line pass over MIST__BLK lanes of local copies, the unused ones
 * repeating lane 0, so that it vectorises; then the scalar sampler for the
 * rare element whose second step did not meet its bound either. */
MIST__F void MIST__FN(mist__phase_finish)(const MIST__FN(mist_phase) *p, MIST__W gw, MIST__W fin,
                                          MIST__W aw, MIST__FN(mist__pend) *q, MIST__T *out)
{
    MIST__T xs[MIST__BLK], y[MIST__BLK];
    MIST__W us[MIST__BLK], es[MIST__BLK], ks[MIST__BLK];
    int ag[MIST__BLK], bad[MIST__BLK], j;   /* int: with chars gcc wants 64 lanes */
    for (j = 0; j < MIST__BLK; ++j) {           /* local copies: vectorisable */
        int l = j < q->m ? j : 0;
        xs[j] = q->xi[l]; us[j] = q->u[l]; es[j] = q->eb[l]; ks[j] = q->kb[l];
        ag[j] = q->again[l];
    }
    for (j = 0; j < MIST__BLK; ++j) {
        MIST__W x = (MIST__W)xs[j], u1 = us[j], e1 = es[j], e2, w;
        int ok, again = ag[j];
        MIST__W u2 = MIST__WFN(mist__draine_step)(gw, fin, aw, x, u1, ks[j],
                                                  (MIST__W)MIST__EPS / 64, &ok, &e2);
        MIST__W uw = again ? u2 : u1, eb = again ? e2 : e1;
        MIST__T lo, hi, pk;
        w = MIST__FN(mist__draine_win)(uw, eb);
        uw = MIST__WFN(mist__clamp11)(uw);
        lo = (MIST__T)(uw - w); hi = (MIST__T)(uw + w);
        pk = MIST__FN(mist__draine_pick)(gw, fin, aw, x, lo, hi);   /* (all lanes) */
        y[j] = lo == hi ? lo : pk;
        bad[j] = again * (1 - ok);
    }
    for (j = 0; j < q->m; ++j)
        out[q->at[j]] = bad[j] ? MIST__FN(mist__phase_drx)(p, xs[j]) : y[j];
    q->m = 0;
}
#endif

/* Prepared sample of each in[i] = xi: mist_phase_sample(p, xi).  HG as
 * mist_hg_sample_n; the fog mixture by lobes (mist__mix_n, below); in double where fma is one instruction, Draine and
 * Cornette-Shanks vectorised as said below the float code
 * (./build/mist_bench, g .5, alpha 17: ~4x the scalar loop; the step's
 * selects are written apart in mist__draine_dd1, which gcc would otherwise
 * turn into a branch); in float, Draine and Cornette-Shanks vectorised: the
 * start table and one straight-line Newton step in double
 * (mist__draine_step) for a block; the elements that step did not finish
 * (4-5% at alpha 17: the table intervals around u = 0) wait in a pending
 * block, which is finished by the same second step and rounding in another
 * straight-line pass (mist__phase_finish); only what falls out of both (no
 * table interval, no converged step) takes the scalar function. Before the
 * pending pass those elements took the scalar function, ~86 ns each: 38% of
 * the batch's time.  ./build/mist_bench (gcc 12 -O3 -march=native
 * -fno-math-errno, AVX-512, n = 4096, g .5, alpha 17, three runs): 7.9-8.1
 * ns a sample, 3.9x the scalar loop (2.6-2.9x before); at g .1, alpha 250 a
 * third of the pending elements still need the scalar function (their
 * second step misses too). */
#if defined(MIST__DDV) && !defined(MIST_NO_DRAINE)
/* c ? x : y (c 0 or 1) by the bits: a select gcc does not thread into
 * branches.  The prepared double batch's interval test as a plain select
 * was (gcc 12, AVX2: "control flow in loop", the batch a loop at 67-72 ns
 * an element; by the bits 13-16 with -march=haswell, measured). */
MIST__F MIST__HOT double mist__bsel(int c, double x, double y)
{
    uint64_t bx, by, m = (uint64_t)0 - (uint64_t)c;
    memcpy(&bx, &x, sizeof bx);
    memcpy(&by, &y, sizeof by);
    bx = (bx & m) | (by & ~m);
    memcpy(&x, &bx, sizeof x);
    return x;
}
#endif
/* The Draine lobe's samples of a prepared medium (p: Draine, or a fog
 * whose Draine lobe it is) at each in[i] = xi' (clamped to [0, 1]):
 * mist__phase_dr, vectorised as said above where the table applies, else
 * a loop over it. */
MIST__F void MIST__FN(mist__phase_dr_n)(const MIST__FN(mist_phase) *p, const MIST__T *in,
                                        MIST__T *out, size_t n)
{
    size_t i;
#if defined(MIST__W_EXACT) || defined(MIST__DDV)
    if (p->c1 != MIST__C(0) && p->g > MIST__C(-1) && p->g < MIST__C(1)
        && (!MIST__DBL || MIST__FN(mist__phase_tab)(p->g))) {   /* double: table's g */
        volatile MIST__T z0 = 0;
        MIST__T z = z0, one = z + 1;
        const MIST__T *tab = p->tab;
#if defined(MIST__W_EXACT)
        MIST__W gw = (MIST__W)p->g, fin = p->alpha < (MIST__T)INFINITY ? 1 : 0;
        if (MIST__FN(mist__phase_near1)(p->g)) {    /* as unprepared: the kernel */
#if defined(MIST__DRAINE_V)
            if (MIST__FN(mist__draine_vn)(p->g, p->alpha, n)) {
                MIST__FN(mist__draine_vk)(p->g, p->alpha, p->c0, p->c1, MIST__NULL, in, out, n);
                return;
            }
#endif
            for (i = 0; i < n; ++i)
                out[i] = MIST__FN(mist__phase_drx)(p, MIST__FN(mist__clamp)(in[i], z, one));
            return;
        }
        MIST__W aw = fin > 0 ? (MIST__W)p->alpha : 1;
        MIST__W u1[MIST__BLK], e1[MIST__BLK];
        MIST__FN(mist__pend) q;
        q.m = 0;
        MIST__BLOCKS_FB(
            MIST__T xi = MIST__FN(mist__clamp01)(x_[j_], z, one);
            MIST__T lo; MIST__T hi;
            MIST__W uw; MIST__W eb; MIST__W w; MIST__W kb;
            int k; int ok;
            MIST__T st = MIST__FN(mist__phase_start)(tab, xi, &k);
            kb = (MIST__W)tab[2 * MIST__PHASE_K + 2 + k];
            uw = MIST__WFN(mist__draine_step)(gw, fin, aw, (MIST__W)xi, (MIST__W)st, kb,
                                              (MIST__W)MIST__EPS / 64, &ok, &eb);
            u1[j_] = uw; e1[j_] = eb;
            w = MIST__FN(mist__draine_win)(uw, eb);
            uw = MIST__WFN(mist__clamp11)(uw);           /* as mist__draine_sample */
            lo = (MIST__T)(uw - w); hi = (MIST__T)(uw + w);
            y_[j_] = lo;
            /* 0: done; 1: to round by the residual; 2: the step missed */
            f_[j_] = (short)(ok * (lo != hi) + (1 - ok) * 2);,
            1,
            MIST__T xi = MIST__FN(mist__clamp01)(x_[j_], z, one);   /* as above */
            MIST__W uw = u1[j_];
            int k = MIST__FN(mist__phase_k)(xi);
            if (f_[j_] == 2 && !(uw >= (MIST__W)tab[k] && uw <= (MIST__W)tab[k + 1])) {
                out[i_ + j_] = MIST__FN(mist__phase_drx)(p,     /* no second step */
                    MIST__FN(mist__clamp)(x_[j_], MIST__C(0), MIST__C(1)));
            } else {
                q.at[q.m] = i_ + j_; q.xi[q.m] = xi; q.u[q.m] = uw; q.eb[q.m] = e1[j_];
                q.kb[q.m] = (MIST__W)tab[2 * MIST__PHASE_K + 2 + k]; q.again[q.m] = f_[j_] == 2;
                if (++q.m == MIST__BLK) MIST__FN(mist__phase_finish)(p, gw, fin, aw, &q, out);
            })
        if (q.m) MIST__FN(mist__phase_finish)(p, gw, fin, aw, &q, out);
#else
        /* double where fma is one instruction: the scalar sampler's first
         * steps (mist__phase_try: the table's start, one step in double, one
         * compensated step, mist__draine_dd1) straight-line over a block;
         * the elements that step does not settle continue as the scalar
         * sampler does from there (mist__draine_ddfin, which repeats that
         * step, else the whole scalar function): the same values bit for
         * bit */
        MIST__T g = p->g, fin, a, us_[MIST__BLK];
        MIST__FN(mist__draine_cx)(p->alpha, &fin, &a);     /* the weights, exact */
        MIST__BLOCKS_FB(
            MIST__T xi = MIST__FN(mist__clamp01)(x_[j_], z, one);
            MIST__T st; MIST__T ut; MIST__T et; MIST__T r; MIST__T s; MIST__T uh;
            MIST__T lo; MIST__T hi; MIST__T u;
            int k; int ok;
            st = MIST__FN(mist__phase_start)(tab, xi, &k);
            ut = MIST__FN(mist__draine_step)(g, fin, a, xi, st, tab[2 * MIST__PHASE_K + 2 + k],
                                             MIST__C(0), &ok, &et);
            ut = mist__bsel((ut >= tab[k]) & (ut <= tab[k + 1]), ut, st);   /* no branch */
            us_[j_] = ut;
            f_[j_] = (short)((MIST__FN(mist__draine_dd1)(g, fin, a, xi, ut, &u, &r, &s,
                                                                 &uh, &lo, &hi) != 1)
                             | MIST__FN(mist__phase_wide)(tab, k));
            y_[j_] = u;,
            1,
            MIST__T u;                    /* the scalar sampler's finish from there */
            MIST__T xi = MIST__FN(mist__clamp01)(x_[j_], z, one);
            out[i_ + j_] = !MIST__FN(mist__phase_wide)(tab, MIST__FN(mist__phase_k)(xi))
                           && MIST__FN(mist__draine_ddfin)(g, fin, a, xi, us_[j_], &u) ? u
                           : MIST__FN(mist__phase_drx)(p, MIST__FN(mist__clamp)(x_[j_],
                                                       MIST__C(0), MIST__C(1)));)
#endif
        return;
    }
#endif
    for (i = 0; i < n; ++i)
        out[i] = MIST__FN(mist__phase_drx)(p, MIST__FN(mist__clamp)(in[i], MIST__C(0), MIST__C(1)));
}

/* The fog mixture's batch (0 < w < 1): a prepared medium p, else the
 * unprepared fog *f.  Per chunk of MIST__MIXC elements: (1) a
 * branch-free pass picks each clamped xi's lobe and xi' as the scalar
 * sampler does (mist__fog_pick's operations: the same lobe and xi', bit
 * for bit; the clamp's -0 becomes +0 there, which no lobe sampler tells
 * apart: each clamps xi' to [+0, 1] as its batch does); (2) the HG batch
 * (mist_hg_sample_n: the scalar HG sample's values) runs over the whole
 * chunk, ~0.3 ns an element, so that only the Draine elements are
 * gathered, branch-free, into a list for the Draine lobe's batch sampler
 * (prepared: mist__phase_dr_n; unprepared: the eq. 6 kernel where it
 * applies, else a loop over mist_draine_sample), whose results are put
 * back in place; (3) the few xi' within 1024 eps of a lobe's top (the
 * scalar sampler's mirror, unprepared) take the scalar function.  So every
 * value is the scalar function's, bit for bit.  The chunk is read before
 * any of it is written: out == in is allowed.  Computing the Draine lobe
 * for every element and selecting would pay it (~4-8 ns an element in
 * float) for the HG elements too.  Chunks of 1024: the chunk's arrays take
 * 16 KB of stack in float, 28 KB in double (chunks of 256 cost ~1.1x the
 * time: the Draine lobe's pending block is flushed once a chunk). */
#define MIST__MIXC (32 * MIST__BLK)
/* The unprepared fog's Draine lobe at each in[i] = xi' in [0, 1]:
 * mist_draine_sample's values (its eq. 6 kernel where that applies, else a
 * loop; not the prepared batch, whose values differ in the last bit). */
MIST__F void MIST__FN(mist__fog_dr_n)(const MIST__FOG *f, const MIST__T *in, MIST__T *out,
                                      size_t n)
{
    size_t i;
#if defined(MIST__DRAINE_V)
    if (MIST__FN(mist__draine_vn)(f->g_d, f->alpha, 1)) {      /* eq. 6's kernel */
        MIST__T c0, c1;
        MIST__FN(mist__draine_c)(f->alpha, &c0, &c1);
        MIST__FN(mist__draine_vk)(MIST__FN(mist__g)(f->g_d), f->alpha, c0, c1, MIST__NULL,
                                  in, out, n);
        return;
    }
#endif
    for (i = 0; i < n; ++i) out[i] = MIST__FN(mist__impl_draine_sample)(f->g_d, f->alpha, in[i]);
}

MIST__F void MIST__FN(mist__mix_n)(const MIST__FN(mist_phase) *p, const MIST__FOG *f,
                                   const MIST__T *in, MIST__T *out, size_t n)
{
    MIST__T xs[MIST__MIXC], ys[MIST__MIXC], xd[MIST__MIXC];
    short fl[MIST__MIXC];
    unsigned short id[MIST__MIXC];
    MIST__T w = p ? p->w : MIST__FN(mist__clamp)(f->w_d, MIST__C(0), MIST__C(1));
    MIST__T ghg = p ? p->g_hg : f->g_hg, lim = MIST__C(1) - MIST__C(1024) * MIST__EPS;
    volatile MIST__T z0 = 0;
    MIST__T z = z0, one = z + 1;
    size_t i0, j, m, nd;
    int mr;
    for (i0 = 0; i0 < n; i0 += m) {
        m = n - i0 < (size_t)MIST__MIXC ? n - i0 : (size_t)MIST__MIXC;
        mr = 0;
        for (j = 0; j < m; ++j) {               /* mist__fog_pick at 0 < w < 1 */
            MIST__T xi = MIST__FN(mist__clamp01)(in[i0 + j], z, one);
            int dr = xi < w, c;
            MIST__T lo = dr ? z : w, top = dr ? w : one, x = (xi - lo) / (top - lo);
            xs[j] = x;
            c = dr + 2 * (x > lim);             /* 0 HG, 1 Draine, >= 2 mirror */
            fl[j] = (short)c;
            mr |= c;
        }
        nd = 0;
        for (j = 0; j < m; ++j) {               /* the Draine list, branch-free */
            id[nd] = (unsigned short)j;
            nd += (size_t)(fl[j] == 1);
        }
        for (j = 0; j < nd; ++j) xd[j] = xs[id[j]];
        MIST__FN(mist__impl_hg_sample_n)(ghg, xs, ys, m);
        if (mr & 2)                             /* the mirror: scalar, from in */
            for (j = 0; j < m; ++j)
                if (fl[j] >= 2)
                    ys[j] = p ? MIST__FN(mist__phase_sample_w)(p, in[i0 + j])
                              : MIST__FN(mist__impl_fog_sample)(*f, in[i0 + j]);
        if (p) MIST__FN(mist__phase_dr_n)(p, xd, xd, nd);
        else MIST__FN(mist__fog_dr_n)(f, xd, xd, nd);
        for (j = 0; j < nd; ++j) ys[id[j]] = xd[j];
        for (j = 0; j < m; ++j) out[i0 + j] = ys[j];
    }
}

/* 1 where a fog (w, sanitised, p->kind != 1) samples as a mixture */
MIST__F int MIST__FN(mist__mix_w)(MIST__T w)
{
    return w > MIST__C(0) && w < MIST__C(1);
}

MIST__F void MIST__FN(mist__impl_phase_sample_n)(const MIST__FN(mist_phase) *p, const MIST__T *in,
                                           MIST__T *out, size_t n)
{
    size_t i;
    if (p && p->kind != 1 && !MIST__FN(mist__gt0)(p->w)) {
        MIST__FN(mist__impl_hg_sample_n)(p->g_hg, in, out, n);
        return;
    }
    if (p && p->kind != 1 && p->w == MIST__C(1)) {             /* Draine: xi' = xi */
        MIST__FN(mist__phase_dr_n)(p, in, out, n);
        return;
    }
#if !defined(__CUDA_ARCH__) && (defined(MIST__W_EXACT) || defined(MIST__DDV))
    /* (not in device code: the chunk's arrays take 16-28 KB of stack; not
     * in double without fma as one instruction, where neither lobe's batch
     * vectorises: there sorting cost 1.1x the loop, gcc 12 -O2, measured) */
    if (p && p->kind != 1 && MIST__FN(mist__mix_w)(p->w)) {   /* the fog mixture */
        MIST__FN(mist__mix_n)(p, MIST__NULL, in, out, n);
        return;
    }
#endif
    for (i = 0; i < n; ++i) out[i] = MIST__FN(mist__impl_phase_sample)(p, in[i]);
}

/* Fog density per steradian of each in[i] = u: mist_fog_eval(fog, u), in
 * chunks of MIST__MIXC: the two lobes' batch densities, then the mixture
 * as mist__fog_eval forms it. */
MIST__F void MIST__FN(mist__impl_fog_eval_n)(MIST__FOG fog, const MIST__T *in, MIST__T *out,
                                             size_t n)
{
#if defined(__CUDA_ARCH__)                  /* (no 16 KB of stack a thread) */
    size_t i;
    for (i = 0; i < n; ++i) out[i] = MIST__FN(mist__impl_fog_eval)(fog, in[i]);
#else
    MIST__T hb[MIST__MIXC], db[MIST__MIXC];
    MIST__T w = MIST__FN(mist__clamp)(fog.w_d, MIST__C(0), MIST__C(1));
    size_t i0, j, m;
    for (i0 = 0; i0 < n; i0 += m) {
        m = n - i0 < (size_t)MIST__MIXC ? n - i0 : (size_t)MIST__MIXC;
        MIST__FN(mist__impl_hg_eval_n)(fog.g_hg, in + i0, hb, m);
        MIST__FN(mist__impl_draine_eval_n)(fog.g_d, fog.alpha, in + i0, db, m);
        for (j = 0; j < m; ++j) {
            MIST__T d = w > MIST__C(0) ? db[j] : MIST__C(0);
            MIST__T h = w < MIST__C(1) ? hb[j] : MIST__C(0);
            out[i0 + j] = (MIST__C(1) - w) * h + w * d;
        }
    }
#endif
}

/* Fog sample of each in[i] = xi: mist_fog_sample(fog, xi).  A mixture as
 * mist_phase_sample_n's (mist__mix_n); one lobe (w = 0 or 1, xi' = xi):
 * that lobe's batch (HG: mist_hg_sample_n; Draine: mist__fog_dr_n). */
MIST__F void MIST__FN(mist__impl_fog_sample_n)(MIST__FOG fog, const MIST__T *in, MIST__T *out,
                                               size_t n)
{
    size_t i;
    MIST__T w = MIST__FN(mist__clamp)(fog.w_d, MIST__C(0), MIST__C(1));
    if (w <= MIST__C(0)) {
        MIST__FN(mist__impl_hg_sample_n)(fog.g_hg, in, out, n);
        return;
    }
#if !defined(__CUDA_ARCH__) && (defined(MIST__W_EXACT) || defined(MIST__DDV))
    if (w >= MIST__C(1)) {                  /* (the kernel clamps xi as the scalar) */
        MIST__FN(mist__fog_dr_n)(&fog, in, out, n);
        return;
    }
    if (MIST__FN(mist__mix_w)(w)) {         /* (as in mist_phase_sample_n) */
        MIST__FN(mist__mix_n)(MIST__NULL, &fog, in, out, n);
        return;
    }
#endif
    for (i = 0; i < n; ++i) out[i] = MIST__FN(mist__impl_fog_sample)(fog, in[i]);
}
#endif /* !MIST_NO_FOG */

#endif /* !MIST_NO_BATCH */
#undef MIST__DRAINE_V

#ifndef MIST_NO_TAB
/* ======================================================================== */
/* Tabulated phase functions                                                */
/* A measured or computed phase function (Lorenz-Mie: mist_mie.h) given at  */
/* n nodes -1 = mu_0 < mu_1 < ... < mu_{n-1} = 1 with values                */
/* p[i C + c] >= 0 for C channels (colour bands, wavelengths), any scale.   */
/*   Interpolant: piecewise LINEAR in mu per channel, normalised in closed  */
/*   form: q_c(u) = ((mu_{k+1} - u) p_k + (u - mu_k) p_{k+1}) / h_k times  */
/*   1 / (2 pi I_c), I_c = sum_k h_k (p_k + p_{k+1}) / 2 (h_k = mu_{k+1} -  */
/*   mu_k; summed compensated in the wide type).  Why linear: it is        */
/*   positive wherever the data is, cannot ring (a 1e6 : 1 forward peak    */
/*   stays a peak; a cubic overshoots below 0 next to it), integrates and   */
/*   inverts exactly; its accuracy is the nodes' placement (mist_mie.h's    */
/*   builder places them adaptively).  It passes through the nodes: q_c is */
/*   p times the channel's factor (the data is scaled by a power of 2 per   */
/*   channel, exactly, then stored in double).  Integral over the sphere:   */
/*   1 within a few eps (the factor's rounding; tested to 1e-12).           */
/*   Sampling density: the mean of the normalised channels, s(u) = (1/C)    */
/*   sum_c q_c(u), again linear per cell with node values f_i (stored in    */
/*   double, scaled to integrate to tot ~ 1 over mu); mist_tab_eval returns */
/*   it as f(u) / (2 pi tot), the exact density of mist_tab_sample, and     */
/*   each q_c(u) in channel[c]: a renderer's weight q_c / s <= C.           */
/*   Sampling: the CDF's cell prefix F_k = sum_{j<k} h_j (f_j + f_{j+1})/2  */
/*   in the wide type W (long double for double where it is wider, double   */
/*   for float), compensated, stored as hi + lo doubles (exact in W),       */
/*   forced non-decreasing, equal across zero-mass cells.  x = xi tot (W);  */
/*   the cell is the largest k with F_k <= x (so x < F_{k+1}: never a cell  */
/*   of zero mass, whatever the zero runs), x >= tot gives the top of the   */
/*   support.  In the cell, the exact root t of a t + b t^2/2 = r (a = f_k, */
/*   b = (f_{k+1} - f_k)/h) in one of two forms, each without cancellation */
/*   where it matters and MONOTONE BY CONSTRUCTION (every operation's       */
/*   rounding is monotone and each operand moves one way as xi grows):      */
/*     b >= 0: r = x - F_k, q = a/r,  t = 2 / (q + sqrt(q^2 + 2b/r))        */
/*     b < 0:  r = x - F_k,           t = 2r / (a + sqrt(max(0, a^2 + 2br)))*/
/*   then u = mu_k + t in W, clamped to the cell.  The second form cancels  */
/*   only where the density f(u) = sqrt(a^2 + 2br) -> 0, its error there   */
/*   ~eps_W x / f(u), which is the bar's xi term (du/dxi = tot/f(u)) times  */
/*   eps_W/eps; the first is a ratio of positive terms (relative error a    */
/*   few eps_W in t, and t f(u) <= 2x).  So |u - u*| <= 1/2 ulp(u*) (the   */
/*   final rounding) + O(eps_W) (xi d(u*)/dxi + |u*|), within the bar       */
/*   4 ulp(u*) + 4 eps xi d(u*)/dxi: worst measured 0.125 of it (the final  */
/*   rounding), double and float, eight tables (tests/test_tab.c).          */
/*   Where long double is no wider (MSVC, CUDA device code,                 */
/*   MIST_NO_LONG_DOUBLE) the double sampler keeps the prefix and x = xi    */
/*   tot as double-double pairs (the cell chosen as with W: an error there  */
/*   would jump a zero run), solves the cell in double by the same forms   */
/*   (t within ~3 eps: up to 1.5x the bar where u* ~ 0 in a cell whose      */
/*   density starts at 0) and corrects t by one Newton step                 */
/*   with a double-double residual (mist__tab_polish): measured worst 0.25  */
/*   of the bar, monotone in the sweeps (test tab_nold); monotone there by  */
/*   accuracy (t to ~eps^2, while one ulp of xi moves t by >= eps/2 of t),  */
/*   not by construction.                                                   */
/*   Cost: O(1) expected in n.  Two guide tables of n - 1 buckets: over xi  */
/*   (bucket j: the cell of x = j tot/(n-1)) and over u, uniform in the     */
/*   warped v = 1 - sqrt(1 - u) (u >= 0), sqrt(1 + u) - 1 (u < 0), which is */
/*   linear in theta near u = +-1 (nodes dense in theta near the forward    */
/*   peak spread over buckets); the cell lies between a bucket's entry and  */
/*   the next one's, found by bisection there.  Expected cells per lookup   */
/*   for uniform xi: <= 1 + (n-1)/(n-1) = 2; worst case one bucket holding  */
/*   m cells, log2(m) steps (never more than log2(n)).                      */
/*   Float eval: the bucket over u from v in float, without branches, and   */
/*   one step: u in [mu_lo, mu_lo+2) (lo the bucket's entry) gives the cell */
/*   lo or lo + 1 by one comparison (verified against mu, so exact; else    */
/*   the search above: 0.5-0.7% of uniform u, HG .9 at 64 to 16382 nodes   */
/*   uniform in theta); the weights by the cell's stored 1/h (no division): */
/*   the value within ~6 eps (double) of the interpolant, rounded to float  */
/*   once (the double eval: two divisions, its weights exactly 1 and 0 at   */
/*   the nodes).  The float batch forms run these steps (and the sampler's  */
/*   bucket, one step and both root forms, selected) in blocks of 32 as     */
/*   passes without branches that gcc vectorises (gathers; clang 14 all but */
/*   the bucket pass); the elements off the fast path are redone by the     */
/*   scalar function.  Costs: bench/mist_bench.c (./mist_bench tab).        */
/*   Memory: mist_tab_bytes(n, C) = (48 + 8 C) n + 8 C + ~120 bytes.        */
/* DOMAIN AND BAD INPUT: mist_tab_init checks everything before it writes   */
/* the arrays and writes nothing past `bytes`; on an error (MIST_TAB_E*,    */
/* negative) it marks a header that fits in `bytes` as failed.  A table     */
/* that is NULL or failed is the isotropic phase function (density          */
/* 1/(4 pi), u = 2 xi - 1; a failed table's channels 1/(4 pi) each); one    */
/* never built (no magic) likewise, its channel array left alone.  u        */
/* clamped to [-1, 1], NaN gives density 0 (channels 0); xi clamped to      */
/* [0, 1], NaN taken as 0.  mist_tab_bytes is 0 (no table) for n < 2, n >=  */
/* 2^32, channels outside [1, 64], or a size past SIZE_MAX.                 */
/* Float: mist_tab_initf takes float arrays (converted exactly); the float  */
/* functions compute in double and round the result once.                   */
/* ======================================================================== */

#define MIST__TAB MIST__FN(mist_tab)
#ifdef MIST__W
#  define MIST__TW     MIST__W
#  define MIST__TWM(f) MIST__WFN(f)
#else
#  define MIST__TW     MIST__T
#  define MIST__TWM(f) MIST__M(f)
#endif

/* the table's double array at byte offset off, its guide at off */
MIST__F const double *MIST__FN(mist__tab_d)(const MIST__TAB *t, size_t off)
{
    return (const double *)(const void *)((const char *)t + off);
}
MIST__F const uint32_t *MIST__FN(mist__tab_g)(const MIST__TAB *t, size_t off)
{
    return (const uint32_t *)(const void *)((const char *)t + off);
}

/* The layout: o[0..7] = offsets of mu (n), f (n), F (2n: hi, lo), q (n C),
 * kc (C), gx (n), gm (n), ih (n: 1 / h_k), each a multiple of 8; returns
 * the total bytes,
 * 0 where n < 2, n >= 2^32 (the guides' cell indices are 32-bit), channels
 * outside [1, 64] or on overflow. */
MIST__F size_t MIST__FN(mist__tab_layout)(size_t n, int channels, size_t *o)
{
    size_t c, at, i, per[8], fix[8];
    const size_t top = (size_t)-1;
    if (n < 2 || n > (size_t)0xffffffffu || channels < 1 || channels > 64) return 0;
    c = (size_t)channels;
    per[0] = 8; per[1] = 8; per[2] = 16; per[3] = 8 * c; per[4] = 0; per[5] = 4; per[6] = 4;
    per[7] = 8;
    for (i = 0; i < 8; ++i) fix[i] = 0;
    fix[4] = 8 * c;
    at = (sizeof(MIST__TAB) + 7u) / 8u * 8u;
    for (i = 0; i < 8; ++i) {
        o[i] = at;
        if (per[i] && n > (top - at - fix[i] - 7u) / per[i]) return 0;
        at += n * per[i] + fix[i];
        at = (at + 7u) / 8u * 8u;
    }
    return at;
}

/* Bytes a table of n nodes and `channels` channels needs (0: see above). */
MIST__F size_t MIST__FN(mist__impl_tab_bytes)(size_t n, int channels)
{
    size_t o[8];
    return MIST__FN(mist__tab_layout)(n, channels, o);
}

/* 1 where t is a built table */
MIST__F int MIST__FN(mist__tab_ok)(const MIST__TAB *t)
{
    return t && t->magic == MIST__TAB_OK;
}

/* A compensated running sum in W (Neumaier): *s + *e += y. */
MIST__F void MIST__FN(mist__tab_acc)(MIST__TW *s, MIST__TW *e, MIST__TW y)
{
    MIST__TW z = *s + y;
    *e += MIST__TWM(fabs)(*s) >= MIST__TWM(fabs)(y) ? (*s - z) + y : (y - z) + *s;
    *s = z;
}

/* Builds the table in t's `bytes` bytes from mu[n] and p[n * channels]
 * (node-major: p[i * channels + c]).  Returns 0, or MIST_TAB_E* (see the
 * section; nothing written past bytes). */
MIST__F int MIST__FN(mist__impl_tab_init)(MIST__TAB *t, size_t bytes, const MIST__T *mu,
                                    const MIST__T *p, size_t n, int channels)
{
    size_t o[8], need, i, k, c, C, G, last;
    int err = 0;
    double *m, *f, *F, *q, *kc, *ih;
    uint32_t *gx, *gm;
    MIST__TW s, e, tot;
#ifdef MIST__W
    MIST__TW prev;
#endif
    if (!t) return MIST_TAB_EINVAL;
    need = MIST__FN(mist__tab_layout)(n, channels, o);
    if (!mu || !p || n < 2 || channels < 1 || channels > 64) err = MIST_TAB_EINVAL;
    else if (need == 0 || bytes < need) err = MIST_TAB_ESIZE;
    else if (!(mu[0] == MIST__C(-1)) || !(mu[n - 1] == MIST__C(1))) err = MIST_TAB_EMU;
    else {
        for (i = 0; i + 1 < n && !err; ++i)
            if (!(mu[i] < mu[i + 1])) err = MIST_TAB_EMU;
        for (i = 0; i < n * (size_t)channels && !err; ++i)
            if (!(p[i] >= MIST__C(0) && p[i] <= MIST__BIG)) err = MIST_TAB_EVALUE;
    }
    if (err) {
        if (bytes >= sizeof(MIST__TAB)) {
            t->magic = MIST__TAB_BAD;
            t->channels = err == MIST_TAB_EINVAL ? 0 : channels;
        }
        return err;
    }
    C = (size_t)channels;
    G = n - 1;
    last = n - 2;
    m  = (double *)(void *)((char *)t + o[0]);
    f  = (double *)(void *)((char *)t + o[1]);
    F  = (double *)(void *)((char *)t + o[2]);
    q  = (double *)(void *)((char *)t + o[3]);
    kc = (double *)(void *)((char *)t + o[4]);
    gx = (uint32_t *)(void *)((char *)t + o[5]);
    gm = (uint32_t *)(void *)((char *)t + o[6]);
    ih = (double *)(void *)((char *)t + o[7]);
    for (i = 0; i < n; ++i) m[i] = (double)mu[i];
    for (i = 0; i < G; ++i) ih[i] = 1 / (m[i + 1] - m[i]);
    ih[G] = 0;
    /* each channel scaled by 2^-e (exact) to a maximum in [1/2, 1), its
     * integral I over mu (compensated), kc = 1/I for now */
    for (c = 0; c < C && !err; ++c) {
        double mx = 0, sc;
        int ex;
        for (i = 0; i < n; ++i) mx = (double)p[i * C + c] > mx ? (double)p[i * C + c] : mx;
        if (!(mx > 0)) { err = MIST_TAB_EZERO; break; }
        (void)frexp(mx, &ex);
        sc = ldexp(1.0, -ex);
        for (i = 0; i < n; ++i) q[i * C + c] = (double)p[i * C + c] * sc;
        s = 0; e = 0;
        for (k = 0; k < G; ++k)
            MIST__FN(mist__tab_acc)(&s, &e, ((MIST__TW)m[k + 1] - (MIST__TW)m[k])
                                    * ((MIST__TW)q[k * C + c] + (MIST__TW)q[(k + 1) * C + c])
                                    / 2);
        s += e;
        kc[c] = (double)(1 / s);
        if (!(s > 0) || !(kc[c] < (double)INFINITY)) err = MIST_TAB_EZERO;
    }
    if (!err) {
        /* the sampling density's nodes f_i = (1/C) sum_c q_ic / I_c */
        for (i = 0; i < n; ++i) {
            s = 0;
            for (c = 0; c < C; ++c) s += (MIST__TW)q[i * C + c] * (MIST__TW)kc[c];
            f[i] = (double)(s / (MIST__TW)C);
        }
        /* the channels' factors per steradian: 1 / (2 pi I_c) */
        for (c = 0; c < C; ++c)
            kc[c] = (double)((MIST__TW)kc[c] / (MIST__TW)MIST__2PI);
        /* the CDF's cell prefix, compensated, as a normalised pair hi + lo:
         * with a wider W, W's sum split (exact); without, the running sum
         * and its compensation as a double-double */
        s = 0; e = 0;
        F[0] = 0; F[1] = 0;
        t->klo = G; t->khi = 0;
        for (k = 0; k < G; ++k) {
            MIST__TW mk = ((MIST__TW)m[k + 1] - (MIST__TW)m[k])
                        * ((MIST__TW)f[k] + (MIST__TW)f[k + 1]) / 2;
            double hi, lo;
            MIST__FN(mist__tab_acc)(&s, &e, mk);
#ifdef MIST__W
            prev = s + e;
            hi = (double)prev;
            lo = (double)(prev - (MIST__TW)hi);
#else
            hi = s + e;
            lo = e - (hi - s);
#endif
            if (!(mk > 0) || hi < F[2 * k] || (hi == F[2 * k] && lo <= F[2 * k + 1])) {
                hi = F[2 * k];                        /* zero cells: a plateau */
                lo = F[2 * k + 1];
            } else {
                if (t->klo == G) t->klo = k;
                t->khi = k;
            }
            F[2 * k + 2] = hi;
            F[2 * k + 3] = lo;
        }
        tot = (MIST__TW)F[2 * G] + (MIST__TW)F[2 * G + 1];
        if (!(tot > 0) || t->klo == G) err = MIST_TAB_EZERO;
        else {
            t->tot[0] = F[2 * G];
            t->tot[1] = F[2 * G + 1];
            t->norm = (double)(1 / ((MIST__TW)MIST__2PI * tot));
        }
    }
    if (err) {
        t->magic = MIST__TAB_BAD;
        t->channels = channels;
        return err;
    }
    /* the guide over xi: bucket j's entry, the largest k with F_k <= j tot/G;
     * over u: the largest k with mu_k <= the start of bucket j in v */
    for (k = 0, i = 0; i <= G; ++i) {
        MIST__TW x = tot * (MIST__TW)i / (MIST__TW)G;
        while (k < last && (MIST__TW)F[2 * k + 2] + (MIST__TW)F[2 * k + 3] <= x) ++k;
        gx[i] = (uint32_t)k;
    }
    for (k = 0, i = 0; i <= G; ++i) {
        double v = 2 * (double)i / (double)G - 1;
        double u = v >= 0 ? 1 - (1 - v) * (1 - v) : (1 + v) * (1 + v) - 1;
        while (k < last && m[k + 1] <= u) ++k;
        gm[i] = (uint32_t)k;
    }
    t->channels = channels;
    t->n = n;
    t->o_mu = o[0]; t->o_f = o[1]; t->o_F = o[2]; t->o_q = o[3];
    t->o_kc = o[4]; t->o_gx = o[5]; t->o_gm = o[6]; t->o_ih = o[7];
    t->magic = MIST__TAB_OK;
    return 0;
}

/* The cell of u in [-1, 1]: the largest k <= n - 2 with mu_k <= u. */
MIST__F size_t MIST__FN(mist__tab_cell)(const MIST__TAB *t, double u)
{
    const double *m = MIST__FN(mist__tab_d)(t, t->o_mu);
    const uint32_t *g = MIST__FN(mist__tab_g)(t, t->o_gm);
    size_t G = t->n - 1, last = t->n - 2, j, lo, hi;
    double v = u >= 0 ? 1 - sqrt(1 - u) : sqrt(1 + u) - 1;
    double b = (v + 1) * 0.5 * (double)G;
    j = b < (double)G ? (size_t)b : G - 1;
    lo = g[j]; hi = g[j + 1];
    while (lo > 0 && u < m[lo]) --lo;                 /* (rounding of v) */
    while (hi < last && !(u < m[hi + 1])) ++hi;
    while (lo < hi) {
        size_t mid = lo + (hi - lo + 1) / 2;
        if (m[mid] <= u) lo = mid; else hi = mid - 1;
    }
    return lo;
}

/* The float eval's cell, branch-free (the batch form vectorises it): the
 * guide's bucket from v in T, its entry lo, and the largest k <= n - 2
 * with mu_k <= u if u lies in [mu_lo, mu_lo+2) (lo + 1 or lo); else G = n -
 * 1 (a bucket of more cells, or v's rounding: the caller's mist__tab_cell). */
MIST__F size_t MIST__FN(mist__tab_cell1)(const double *m, const uint32_t *g, size_t G, MIST__T u)
{
    MIST__T v = MIST__M(copysign)(MIST__C(1) - MIST__M(sqrt)(MIST__C(1) - MIST__M(fabs)(u)), u);
    MIST__T b = (v + MIST__C(1)) * MIST__C(0.5) * (MIST__T)G;
    size_t j = b < (MIST__T)G ? (size_t)b : G - 1, lo = g[j], last = G - 1;
    size_t top = (size_t)(lo == last), k;
    double x = (double)u;
    int in = (m[lo] <= x) & ((int)top | (x < m[lo + 2 - top]));
    k = lo + (size_t)((lo < last) & (m[lo + 1] <= x));
    return in ? k : G;
}

/* The float eval's value in cell k at x: the weights by the cell's stored
 * 1/h (no division); a few eps of double from the interpolant, then
 * rounded to T once. */
MIST__F MIST__T MIST__FN(mist__tab_v1)(const double *m, const double *ih, const double *f,
                                       double norm, size_t k, double x)
{
    double wa = (m[k + 1] - x) * ih[k], wb = (x - m[k]) * ih[k];
    return (MIST__T)((wa * f[k] + wb * f[k + 1]) * norm);
}

/* mist_tab_eval of a built table */
MIST__F MIST__T MIST__FN(mist__tab_ev)(const MIST__TAB *t, MIST__T u, MIST__T *channel)
{
    const double *m = MIST__FN(mist__tab_d)(t, t->o_mu);
    const double *f = MIST__FN(mist__tab_d)(t, t->o_f);
    size_t k, c, C = (size_t)t->channels;
    double x, h, wa, wb;
    if (!(u == u)) {
        if (channel) for (c = 0; c < C; ++c) channel[c] = MIST__C(0);
        return MIST__C(0);
    }
    u = MIST__FN(mist__clamp11)(u);
    x = (double)u;
    if (!MIST__DBL) {                 /* float: one guide step, 1/h stored */
        const double *ih = MIST__FN(mist__tab_d)(t, t->o_ih);
        k = MIST__FN(mist__tab_cell1)(m, MIST__FN(mist__tab_g)(t, t->o_gm), t->n - 1, u);
        if (k == t->n - 1) k = MIST__FN(mist__tab_cell)(t, x);
        if (!channel) return MIST__FN(mist__tab_v1)(m, ih, f, t->norm, k, x);
        wa = (m[k + 1] - x) * ih[k];
        wb = (x - m[k]) * ih[k];
    } else {
        k = MIST__FN(mist__tab_cell)(t, x);
        h = m[k + 1] - m[k];
        wa = (m[k + 1] - x) / h;                      /* exactly 1, 0 at mu_k */
        wb = (x - m[k]) / h;
    }
    if (channel) {
        const double *q = MIST__FN(mist__tab_d)(t, t->o_q) + k * C;
        const double *kc = MIST__FN(mist__tab_d)(t, t->o_kc);
        for (c = 0; c < C; ++c) channel[c] = (MIST__T)((wa * q[c] + wb * q[C + c]) * kc[c]);
    }
    return (MIST__T)((wa * f[k] + wb * f[k + 1]) * t->norm);
}

/* Density per steradian of the sampling density (the mean of the
 * normalised channels) at u; each channel's into channel[0..C) (channel
 * may be NULL).  Domain: see the section. */
MIST__F MIST__T MIST__FN(mist__impl_tab_eval)(const MIST__TAB *t, MIST__T u, MIST__T *channel)
{
    if (!MIST__FN(mist__tab_ok)(t)) {
        MIST__T r = u == u ? MIST__C(MIST__INV4PI) : MIST__C(0);
        if (channel && t && t->magic == MIST__TAB_BAD && t->channels >= 1
            && t->channels <= 64) {
            int c;
            for (c = 0; c < t->channels; ++c) channel[c] = r;
        }
        return r;
    }
    return MIST__FN(mist__tab_ev)(t, u, channel);
}

/* The sampler's x = xi tot against the prefix F_k (pairs hi + lo).  With a
 * wider W, x and F_k are W numbers (hi + lo exact in W), xl = 0; without,
 * x = xh + xl and F_k are double-doubles, compared as pairs, and the
 * difference x - F_k is taken pairwise (xh - F_hi exact where they are
 * within a factor 2, Sterbenz). */
MIST__F int MIST__FN(mist__tab_le)(const double *F, size_t k, MIST__TW xh, MIST__TW xl)
{
#ifdef MIST__W
    (void)xl;
    return (MIST__TW)F[2 * k] + (MIST__TW)F[2 * k + 1] <= xh;
#else
    return F[2 * k] < xh || (F[2 * k] == xh && F[2 * k + 1] <= xl);
#endif
}
MIST__F MIST__TW MIST__FN(mist__tab_r)(const double *F, size_t k, MIST__TW xh, MIST__TW xl)
{
#ifdef MIST__W
    (void)xl;
    return xh - ((MIST__TW)F[2 * k] + (MIST__TW)F[2 * k + 1]);
#else
    return (xh - F[2 * k]) + (xl - F[2 * k + 1]);
#endif
}

#ifndef MIST__W
/* Without a wider W: the Newton correction dt of the cell's root t (from
 * the monotone forms, ~3 eps) for a t + (c - a) t^2 / (2h) = R (R = rh +
 * rl, h = mh - ml), its residual in double-double (h, c - a, t^2 and a t
 * error-free, the quotient by 2h with its remainder): t - dt within
 * ~eps^2, and u = ml + t - dt is rounded once by the caller.  Taken only
 * where it is small (2^-40 t): near a zero of the density, where the
 * bar's xi term is wide, 0. */
MIST__F MIST__T MIST__FN(mist__tab_polish)(MIST__T a, MIST__T c, MIST__T ml, MIST__T mh,
                                           MIST__T rh, MIST__T rl, MIST__T t)
{
    MIST__T hl, hh = MIST__FN(mist__two_sum)(mh, -ml, &hl);
    MIST__T dl, dh = MIST__FN(mist__two_sum)(c, -a, &dl);
    MIST__T t2l, t2h = MIST__FN(mist__two_prod)(t, t, &t2l);
    MIST__T ql, qh = MIST__FN(mist__two_prod)(dh, t2h, &ql);
    MIST__T s2h, s2l, p1l, p1h, e1l, e1, e2l, e2, e, fp, dt;
    ql += dh * t2l + dl * t2h;
    s2h = qh / (2 * hh);                                   /* (c - a) t^2 / (2h) */
    s2l = (MIST__FN(mist__fms)(s2h, 2 * hh, qh) + ql - s2h * (2 * hl)) / (2 * hh);
    p1h = MIST__FN(mist__two_prod)(a, t, &p1l);            /* a t */
    e1 = MIST__FN(mist__two_sum)(p1h, s2h, &e1l);
    e2 = MIST__FN(mist__two_sum)(e1, -rh, &e2l);
    e = e2 + (((e1l + e2l) + (p1l + s2l)) - rl);           /* the residual */
    fp = a + dh * (t / hh);                                /* the density at t */
    if (!(fp > 0)) return MIST__C(0);
    dt = e / fp;
    return MIST__FN(mist__abs)(dt) <= MIST__C(0x1p-40) * t ? dt : MIST__C(0);
}
#endif

/* mist_tab_sample of a built table, xi in [0, 1] */
MIST__F MIST__T MIST__FN(mist__tab_sm)(const MIST__TAB *t, MIST__T xi)
{
    const double *m = MIST__FN(mist__tab_d)(t, t->o_mu);
    const double *f = MIST__FN(mist__tab_d)(t, t->o_f);
    const double *F = MIST__FN(mist__tab_d)(t, t->o_F);
    const uint32_t *g = MIST__FN(mist__tab_g)(t, t->o_gx);
    size_t G = t->n - 1, last = t->n - 2, j, lo, hi;
    MIST__TW x, xl, b, a, r, w, u, ml, mh;
#ifdef MIST__W
    x = (MIST__TW)xi * ((MIST__TW)t->tot[0] + (MIST__TW)t->tot[1]);
    xl = 0;
#else
    x = MIST__FN(mist__two_prod)(xi, t->tot[0], &xl);
    xl += xi * t->tot[1];
#endif
    if (MIST__FN(mist__tab_le)(F, G, x, xl))         /* xi = 1: the support's top */
        return (MIST__T)m[t->khi + 1];
    b = (MIST__TW)xi * (MIST__TW)G;
    j = b < (MIST__TW)G ? (size_t)b : G - 1;
    lo = g[j]; hi = g[j + 1];
    while (lo > 0 && !MIST__FN(mist__tab_le)(F, lo, x, xl)) --lo;
    while (hi < last && MIST__FN(mist__tab_le)(F, hi + 1, x, xl)) ++hi;
    while (lo < hi) {
        size_t mid = lo + (hi - lo + 1) / 2;
        if (MIST__FN(mist__tab_le)(F, mid, x, xl)) lo = mid; else hi = mid - 1;
    }
    ml = (MIST__TW)m[lo]; mh = (MIST__TW)m[lo + 1];
    a = (MIST__TW)f[lo];
    b = ((MIST__TW)f[lo + 1] - a) / (mh - ml);        /* the density's slope */
    r = MIST__FN(mist__tab_r)(F, lo, x, xl);
    if (!(r > 0)) w = 0;
    else if (b >= 0) {
        MIST__TW qa = a / r;
        w = 2 / (qa + MIST__TWM(sqrt)(qa * qa + 2 * b / r));
    } else {
        MIST__TW d = a * a + 2 * b * r;
        w = 2 * r / (a + MIST__TWM(sqrt)(d > 0 ? d : 0));
    }
#ifndef MIST__W
    if (w > 0 && w < mh - ml) {                       /* ml + w - dt, rounded once */
        MIST__T dt = MIST__FN(mist__tab_polish)(a, f[lo + 1], ml, mh, x - F[2 * lo],
                                                xl - F[2 * lo + 1], w), el;
        u = MIST__FN(mist__two_sum)(ml, w, &el);
        u = u + (el - dt);
    } else
#endif
    u = ml + w;
    return (MIST__T)(u < mh ? u : mh);
}

/* u = cos theta from xi: the exact inverse CDF of the sampling density
 * (monotone in xi).  Domain: see the section. */
MIST__F MIST__T MIST__FN(mist__impl_tab_sample)(const MIST__TAB *t, MIST__T xi)
{
    if (!MIST__FN(mist__tab_ok)(t)) return MIST__FN(mist__impl_hg_sample)(MIST__C(0), xi);
    return MIST__FN(mist__tab_sm)(t, MIST__FN(mist__clamp)(xi, MIST__C(0), MIST__C(1)));
}

#ifndef MIST_NO_DIR
/* Scattered direction around the propagation direction wi and its pdf
 * (mist_tab_eval at its cosine; pdf may be NULL), as *_sample_dir. */
MIST__F MIST__V3 MIST__FN(mist__impl_tab_sample_dir)(const MIST__TAB *t, MIST__V3 wi, MIST__T xi1,
                                                 MIST__T xi2, MIST__T *pdf)
{
    MIST__T u = MIST__FN(mist__impl_tab_sample)(t, xi1);
    if (pdf) *pdf = MIST__FN(mist__impl_tab_eval)(t, u, MIST__NULL);
    return MIST__FN(mist__impl_dir_from_cos)(wi, u, xi2);
}
#endif

#ifndef MIST_NO_BATCH
/* Batch forms: out[i] = mist_tab_eval(t, in[i], NULL), mist_tab_sample(t,
 * in[i]), bit for bit (the same expressions, the table's check once).
 * Float: blocks of MIST__BLK (see the section's float eval); double: a
 * loop (the double eval's divisions and the sampler's wide type W). */
MIST__F void MIST__FN(mist__impl_tab_eval_n)(const MIST__TAB *t, const MIST__T *in, MIST__T *out,
                                       size_t n)
{
    size_t i;
    if (!MIST__FN(mist__tab_ok)(t)) {
        for (i = 0; i < n; ++i) out[i] = MIST__FN(mist__impl_tab_eval)(t, in[i], MIST__NULL);
        return;
    }
    if (!MIST__DBL && t->n - 1 < (size_t)0x7fffffff) {
        /* float: blocks of MIST__BLK in passes without branches (the
         * guide's bucket, its one step, the value: gathers), the elements
         * outside the fast path (NaN, a bucket of more cells) redone by the
         * scalar function.  The cell is exact either way (verified against
         * mu), and the value is mist__tab_v1's expression: bit for bit. */
        const double *m = MIST__FN(mist__tab_d)(t, t->o_mu);
        const double *f = MIST__FN(mist__tab_d)(t, t->o_f);
        const double *ih = MIST__FN(mist__tab_d)(t, t->o_ih);
        const uint32_t *g = MIST__FN(mist__tab_g)(t, t->o_gm);
        const int32_t last = (int32_t)(t->n - 2);
        const MIST__T gn = (MIST__T)(t->n - 1);
        const double norm = t->norm;
        MIST__T xb[MIST__BLK], yb[MIST__BLK];
        double xd[MIST__BLK], ma[MIST__BLK], mb[MIST__BLK];
        int32_t kb[MIST__BLK], fb[MIST__BLK];
        size_t i0, j, len;
        for (i0 = 0; i0 < n; i0 += len) {
            len = n - i0 < MIST__BLK ? n - i0 : MIST__BLK;
            for (j = 0; j < MIST__BLK; ++j) xb[j] = j < len ? in[i0 + j] : MIST__C(0);
            for (j = 0; j < MIST__BLK; ++j) {            /* the bucket (NaN: flagged) */
                MIST__T u = xb[j], a = MIST__M(fabs)(u), v;
                int32_t q;
                a = a < MIST__C(1) ? a : MIST__C(1);
                v = MIST__M(copysign)(MIST__C(1) - MIST__M(sqrt)(MIST__C(1) - a), u);
                q = (int32_t)((v + MIST__C(1)) * MIST__C(0.5) * gn);
                kb[j] = q < last ? q : last;
                xd[j] = (double)MIST__M(copysign)(a, u);      /* u clamped */
                fb[j] = u != u;
            }
            for (j = 0; j < MIST__BLK; ++j) kb[j] = (int32_t)g[kb[j]];   /* its entry */
            for (j = 0; j < MIST__BLK; ++j) {            /* its one step */
                int32_t lo = kb[j], top = lo == last, ok, up;
                double x = xd[j], m0 = m[lo], m1 = m[lo + 1], m2 = m[lo + 2 - top];
                ok = (int32_t)(m0 <= x) & (top | (int32_t)(x < m2));
                up = (int32_t)(lo < last) & (int32_t)(m1 <= x);
                fb[j] |= 1 - ok;
                kb[j] = (lo + up) * ok;
                ma[j] = up ? m1 : m0;                    /* mu_k, mu_k+1 */
                mb[j] = up ? m2 : m1;
            }
            for (j = 0; j < MIST__BLK; ++j) {            /* the value */
                int32_t k = kb[j];
                double x = xd[j];
                double wa = (mb[j] - x) * ih[k], wb = (x - ma[j]) * ih[k];
                yb[j] = (MIST__T)((wa * f[k] + wb * f[k + 1]) * norm);
            }
            for (j = 0; j < len; ++j) out[i0 + j] = yb[j];
            for (j = 0; j < len; ++j)
                if (fb[j]) out[i0 + j] = MIST__FN(mist__tab_ev)(t, xb[j], MIST__NULL);
        }
        return;
    }
    for (i = 0; i < n; ++i) out[i] = MIST__FN(mist__tab_ev)(t, in[i], MIST__NULL);
}

MIST__F void MIST__FN(mist__impl_tab_sample_n)(const MIST__TAB *t, const MIST__T *in, MIST__T *out,
                                         size_t n)
{
    size_t i;
    if (!MIST__FN(mist__tab_ok)(t)) {
        for (i = 0; i < n; ++i) out[i] = MIST__FN(mist__impl_hg_sample)(MIST__C(0), in[i]);
        return;
    }
    if (!MIST__DBL && t->n - 1 < (size_t)0x7fffffff) {
        /* float: blocks of MIST__BLK in passes without branches (the guide's
         * bucket, its one step, the root by both forms, selected), the
         * elements outside them (xi outside [0, 1] or NaN, the support's
         * top, a bucket of more cells) redone by the scalar function.  The
         * cell is exact either way (verified against F) and the root is
         * mist__tab_sm's expressions: bit for bit. */
        const double *m = MIST__FN(mist__tab_d)(t, t->o_mu);
        const double *f = MIST__FN(mist__tab_d)(t, t->o_f);
        const double *F = MIST__FN(mist__tab_d)(t, t->o_F);
        const uint32_t *g = MIST__FN(mist__tab_g)(t, t->o_gx);
        const size_t G = t->n - 1;
        const int32_t last = (int32_t)(G - 1);
        const MIST__TW tot = (MIST__TW)t->tot[0] + (MIST__TW)t->tot[1];
        const MIST__TW top_x = (MIST__TW)F[2 * G] + (MIST__TW)F[2 * G + 1];
        MIST__T xb[MIST__BLK], yb[MIST__BLK];
        MIST__TW xw[MIST__BLK], fk[MIST__BLK];
        int32_t kb[MIST__BLK], fb[MIST__BLK];
        size_t i0, j, len;
        for (i0 = 0; i0 < n; i0 += len) {
            len = n - i0 < MIST__BLK ? n - i0 : MIST__BLK;
            for (j = 0; j < MIST__BLK; ++j) xb[j] = j < len ? in[i0 + j] : MIST__C(0);
            for (j = 0; j < MIST__BLK; ++j) {            /* the bucket */
                MIST__T xi = xb[j];
                int32_t in01 = (int32_t)(xi >= MIST__C(0)) & (int32_t)(xi <= MIST__C(1)), q;
                MIST__TW x;
                xi = in01 ? xi : MIST__C(0);
                x = (MIST__TW)xi * tot;
                q = (int32_t)((MIST__TW)xi * (MIST__TW)G);
                kb[j] = q < last ? q : last;
                xw[j] = x;
                fb[j] = (1 - in01) | (int32_t)(top_x <= x);
            }
            for (j = 0; j < MIST__BLK; ++j) kb[j] = (int32_t)g[kb[j]];   /* its entry */
            for (j = 0; j < MIST__BLK; ++j) {            /* its one step */
                int32_t lo = kb[j], top = lo == last, ok, up, l2 = lo + 2 - top;
                MIST__TW x = xw[j];
                MIST__TW F0 = (MIST__TW)F[2 * lo] + (MIST__TW)F[2 * lo + 1];
                MIST__TW F1 = (MIST__TW)F[2 * lo + 2] + (MIST__TW)F[2 * lo + 3];
                MIST__TW F2 = (MIST__TW)F[2 * l2] + (MIST__TW)F[2 * l2 + 1];
                ok = (int32_t)(F0 <= x) & (top | (int32_t)(x < F2));
                up = (int32_t)(lo < last) & (int32_t)(F1 <= x);
                fb[j] |= 1 - ok;
                kb[j] = (lo + up) * ok;
                fk[j] = up ? F1 : F0;
            }
            for (j = 0; j < MIST__BLK; ++j) {            /* the root */
                int32_t k = kb[j];
                MIST__TW ml = (MIST__TW)m[k], mh = (MIST__TW)m[k + 1], a = (MIST__TW)f[k];
                MIST__TW b = ((MIST__TW)f[k + 1] - a) / (mh - ml), r = xw[j] - fk[j];
                MIST__TW qa = a / r, d = a * a + 2 * b * r, w1, w2, w, u;
                w1 = 2 / (qa + MIST__TWM(sqrt)(qa * qa + 2 * b / r));
                w2 = 2 * r / (a + MIST__TWM(sqrt)(d > 0 ? d : 0));
                w = b >= 0 ? w1 : w2;
                w = r > 0 ? w : 0;
                u = ml + w;
                yb[j] = (MIST__T)(u < mh ? u : mh);
            }
            for (j = 0; j < len; ++j) out[i0 + j] = yb[j];
            for (j = 0; j < len; ++j)
                if (fb[j])
                    out[i0 + j] = MIST__FN(mist__impl_tab_sample)(t, xb[j]);
        }
        return;
    }
    for (i = 0; i < n; ++i)
        out[i] = MIST__FN(mist__tab_sm)(t, MIST__FN(mist__clamp)(in[i], MIST__C(0), MIST__C(1)));
}
#endif /* !MIST_NO_BATCH */
#undef MIST__TAB
#undef MIST__TW
#undef MIST__TWM
#endif /* !MIST_NO_TAB */
#undef MIST__BLOCKS
#undef MIST__BLOCKS_FB
#undef MIST__BLK
#undef MIST__MIXC

#ifndef MIST_NO_HFOG
/* ======================================================================== */
/* Analytic height fog [I18]                                                */
/*                                                                          */
/* [I18] K. Ishiyama, "An analytic height fog model for real-time           */
/*       rendering", 2018.                                                  */
/* [B08] A. Bouthors, F. Neyret, N. Max, E. Bruneton, C. Crassin,           */
/*       "Interactive multiple anisotropic scattering in clouds", I3D 2008. */
/*                                                                          */
/* MODEL [I18 eq. 7-13].  Height is the y coordinate (or along `up`: THE    */
/* HEIGHT AXIS below).  A component's                                       */
/* (Rayleigh's, Mie's) extinction at height y is its coefficient times      */
/* rho(y) = density exp(-(y - base)/H), and so is its scattering.  Light:   */
/* a sun at infinity (irradiance E, direction l towards it) and an          */
/* isotropic ambient radiance La.  Along x(t) = origin + t dir, 0 <= t <= s */
/* (s may be +inf), with w = dir.y, st = sum of the extinctions:            */
/*   T = exp(-st C(s)),   C(t) = int_0^t rho(y(t')) dt'  (mist_hfog_column) */
/*   L = sum_j ss_j (p_j(u) E + La) int_0^s rho exp(-st C(t)) dt            */
/* with p_j mist's densities per steradian (Rayleigh; the Mie mist_fog) at  */
/* u = l . dir, the cosine between the sun's propagation direction and the */
/* light's towards the camera: g > 0 brightens looking at the sun.  A      */
/* surface or sky of radiance B seen along the ray becomes B T + L.        */
/*                                                                          */
/* REFORMULATION.  The printed closed forms [I18 eq. 14, 21-23] divide by  */
/* omega_y (0 for a level ray) and by st (0 without fog), and take          */
/* e^(-y0/H) and e^(-omega_y s/H) apart: each overflows, or the difference */
/* of the two cancels, for a camera far below or above the fog, a long ray */
/* down, or a ray to infinity.  mist writes them as                         */
/*   C(s) = density e^(-h_low) s phi1(|a|),  a = w s / H,                   */
/*   h_low = (y - base)/H + min(a, 0): the LOWER end of the ray, its        */
/*          densest point, so that every other factor is <= 1;              */
/*   phi1(z) = (1 - e^-z)/z = -expm1(-z)/z, phi1(0) = 1: level rays exact; */
/*   int_0^s rho e^(-st C) dt = C phi1(st C)  (= (1 - T)/st, no division by */
/*          st: zero extinction gives T = 1 and no in-scatter, not NaN);    */
/* h_low is carried in two parts (error-free transformations of y - base,  */
/* of w s and of the quotients by H) and combined before the one exp is     */
/* taken (in two halves where one alone would leave the range).  So the    */
/* rounding of the exponent itself (|h| eps: 700 eps at e^700) never        */
/* enters, and a finite input whose result is representable gets it to a   */
/* few ulps.  Rays to infinity: up, C = density e^(-h) H / w; level or     */
/* down, C = +inf, T = 0, L = its limit.  Measured against adaptive         */
/* quadrature of eq. 12-13 (tests/test_height_fog.c) over omega_y in {0,    */
/* +-1e-12, +-1e-6, +-1e-3, +-0.5, +-1}, density factors e^-700..e^700      */
/* (float: e^-80..e^80), lengths 0..inf, extinction 0..3000, H 1..1e4: the  */
/* relative error of T and L stays below 5 eps (1 + tau) in double and     */
/* in float (the test's bar is 16).                                         */
/*                                                                          */
/* THE COMMON CASE (a fog pass: moderate heights, coefficients and lights,  */
/* the sun not dimmed) takes THE STRAIGHT PATH below: the same closed form  */
/* in plain arithmetic (double for both types), checked once, with e^x and */
/* 1 - e^x from one polynomial evaluation; everything else the scaled       */
/* path.  It costs 1.3-2.6x the printed formulas (the scaled path 4-11x)   */
/* and vectorises over rays (mist_hfog_apply_n).  On 20000 random rays with */
/* sun and ambient (test_height_fog "common"): T 3.8, L 6.2 eps (1 + tau)   */
/* at worst in double, 3.1 and 3.7 in float; the scaled path alone there:   */
/* 3.9, 5.8 and 3.5, 5.2 (the three lit terms' sum adds its roundings).     */
/*                                                                          */
/* THE DIMMED SUN (sun_extinction != 0; beyond [I18]).  The sun reaches     */
/* y(t) through the column above it along l, rho(t) H / l_y (l_y > 0; a sun */
/* at or below the horizon gives no sun light).  With A(t) = st (C(t) +     */
/* rho(t) H / l_y), dA/dt = st rho (1 - w / l_y) = nu st rho, so the sun's  */
/* integral  int_0^s rho e^(-A) dt  is closed form too:                     */
/*   = e^(-min(A0, A1)) C(s) phi1(|nu| st C(s)),                            */
/*   A0 = st rho(0) H / l_y,  A1 = st C(s) + st rho(s) H / l_y,             */
/* the less lit end as reference (all exponents <= 0).  nu = (l_y - w)/l_y */
/* is exact near 0; at nu = 0 (view and sun at the same vertical component) */
/* phi1's argument is 0 and nothing divides by nu.  Measured: below 5 eps   */
/* (1 + tau + min(A0, A1)) in double and float, nu = 0, +-2^-45 (double),   */
/* +-2^-20 (float) and down to -19 included.                                */
/*                                                                          */
/* SEVERAL LAYERS (mist_hfog_layers_eval): different scale heights, as      */
/* Rayleigh ~8 km and Mie ~1.2 km, or artist layers.  The transmittance is  */
/* the product of the layers' (exact, as above).  The in-scatter has no     */
/* closed form: mist cuts the ray into pieces (equal steps of the square    */
/* root of the transmittance) and on each takes every layer's share         */
/* f_i = ext_i rho_i / sum_k ext_k rho_k of the extinction as constant,     */
/* equal to its column-weighted mean.  Then each piece is closed form, and  */
/* exact when the layers share a scale height (one exponential: [I18]).     */
/* The bound: on a piece, the in-scatter is int F g dtau with F = sum_i c_i */
/* f_i (c_i = layer i's scattering x light / extinction) and g = e^-tau     */
/* (e^-A for the dimmed sun); replacing F by its mean errs by at most       */
/* osc(F) min(int g, dtau/4 osc(g)) (Gruss' inequality), and osc(F) <=     */
/* (max c - min c)/2 sum_i osc(f_i), the f_i bounded from the layers'       */
/* density ratios, monotone along the ray.  The bound (rounding included)  */
/* falls as 1/pieces^2.  Measured (Earth-like and three artist layers, 8    */
/* pieces): median 1e-4 of the value, 90% below 1.2%, worst 20% (a ray     */
/* rising 1 m per km to infinity); the actual error never above 0.99 of    */
/* the bound in the tests and in an independent check's random layers.     */
/* Gruss' bound is blind to the weight: on a piece that starts in a dense  */
/* layer (a camera far below the base) it is the whole of c_max - c_min,   */
/* so the smaller of it and a second bound is taken, from the shares'      */
/* rate of change D = |w| (max 1/H - min 1/H) against the depth's growth   */
/* (see the code); and shares taken from the logs (densities beyond the    */
/* range) charge their rounding through each layer's share.                */
/* THE WEIGHT.  On a deep piece (dtau > 2, or unbounded) a third bound     */
/* follows the weight.  With tau the depth from the piece's start, g the   */
/* weight per unit depth (e^-tau; the dimmed sun's e^-A, A = A0 + nu tau,  */
/* as dA = nu dtau) and G(t) = int_t^dtau g its tail, by parts             */
/*   int (F - F(0)) g dtau = int_0^dtau (dF/dt) G(t) dt     (exact),       */
/* so, Fbar the estimate's F (column-mean shares; F(0) where unbounded),   */
/*   |error| <= int |dF/du| G du + |F(0) - Fbar| int g,                    */
/* u the distance along the piece.  dF/du = Cov_f(c, b) over the shares    */
/* (b_k = -w/H_k) = sum_(k != i) f_k (c_k - c_i)(b_k - bbar), so           */
/*   |dF/du| <= (c_max - c_min) D min(1/4, 1 - f_i)                        */
/* for any layer i (the densest at the start is taken); |F(0) - Fbar| <=   */
/* (c_max - c_min)/2 sum_k |fbar_k - f_k(0)|; G <= e^-tau (the sun:        */
/* e^-(A0 + nu tau)/nu, nu > 0).  The integral over u is cut where the     */
/* depth about doubles, from 1/4 to 4 - ln eps, and each interval bounded  */
/* in closed form (mist__hwbound: the extinction is monotone along a ray,  */
/* 1 - f_i largest at an interval's end); past the last point, (c_max -    */
/* c_min) times the weight left.  Where dF/dtau is constant the first term */
/* is the error itself (on an unbounded piece, the whole error), where     */
/* Gruss' is osc(F) int g: all of c_max - c_min on a nearly level ray to   */
/* infinity.  Over the tests' grid the bound is 3x the larger of the error */
/* and its rounding floor 4 (pieces + 8) eps L (median), 5x (90%), 42x     */
/* (99%), 287x at most: errors of opposite signs cancel there (a piece     */
/* with the column-mean shares under a falling weight errs by -F', the     */
/* unbounded one by +F', and the two lights each by its own albedo x light */
/* differences), which no sum of the terms' bounds follows.                */
/* Each share's variation is taken without cancellation: where the other   */
/* layers' share of a layer's piece is below eps (an absorbing layer       */
/* outweighing the scattering ones by 1/eps) 1 - share rounds to 1, and    */
/* the bound was half what the last, unbounded piece needs (1.95x          */
/* exceeded; found by that check, tested since); and where the other       */
/* layers outweigh a layer beyond the range at both ends of a piece, its   */
/* share varies by at most 1/BIG, not 0 (float: a 1e-40 share of a         */
/* subnormal in-scatter, 1.87x exceeded; tested).                          */
/*                                                                          */
/* FREE-FLIGHT DISTANCES (mist_hfog_sample_distance, for path tracers).     */
/* The t with 1 - e^-tau_c(t) = xi for channel c: with T = -log1p(-xi),     */
/* K = T e^h / (st density) (h = (y - base)/H; K is the distance at the     */
/* start's density) and a = |w| / H,                                        */
/*   tau(t) = st density e^-h (1 - e^(-+a t)) / (+-a)                       */
/* inverts to                                                               */
/*   t = -log1p(-z) / a  (up; z = a K >= 1: it escapes, +inf),              */
/*   t =  log1p(z) / a   (down),   t = K (level, uniform: a = 0).           */
/* K and z are one scaled product each (the start's height quotient in two  */
/* parts, as above; mantissas and exponents apart), so that nothing leaves  */
/* the range before the result does; z below 2^-(mant + 9) gives z / a      */
/* (log1p rounds to z there: the same chain, so t stays monotone in xi); z  */
/* beyond the range: ln z = ln(mantissa) + exponent ln 2; K beyond          */
/* e^(64 XLIM) (a start 1e5 scale heights above the base):                  */
/* t = (y - base)/|w| + (H/|w|) ln(|w| T / (H st density)), scaled.  Where  */
/* every intermediate is normal one plain-arithmetic pass does the same.    */
/* Near z = 1 (an up ray at the edge of escaping) t is as ill-conditioned   */
/* as 1/(1 - z): the bar's xi dt/dxi term.  Measured against a long double  */
/* root of ln tau(t) = ln T (bisection; tests/test_hfog_path.c) over level, */
/* 1e-300, nearly level and steep rays, starts e^+-690 and 1e5 scale        */
/* heights from the base, scale heights 2^-1060 (float 2^-140) to +inf,     */
/* tmax finite and infinite, random and rotated scenes: within 0.64         */
/* (double) and 0.85 (float) of the bar 4 ulp(t*) + 4 eps xi dt / dxi.      */
/* mist_hfog_optical_depth is the transmittance's exponent st C(t), within  */
/* 6 eps (1 + |w s / H|) (w s / H: the scale heights the ray crosses; 4.6   */
/* by an independent check, un-normalised dir and tilted axes included),    */
/* and mist_hfog_extinction st rho at a point, within 5 eps (4.53 measured  */
/* at a point 1000 scale heights from the base).                            */
/*                                                                          */
/* THE HEIGHT AXIS (up; all zero, or not finite: y).  Unit to rounding it   */
/* is used as given (its length taken as 1), else the axis is up / |up|:    */
/* the height and the slope are divided by |up| carried as hi + lo (a unit  */
/* vector rounded first erred by |origin| eps in the height, |origin| / H   */
/* eps in the density's exponent).  The start's height origin . up is an    */
/* exact dot product (error-free products summed into an expansion),        */
/* carried with the base as hi + lo, so that it enters h as an input y      */
/* would; the slope w = dir . up / |dir| likewise (the dot product exact,   */
/* then one division), so that a nearly level ray keeps w's relative        */
/* accuracy.  On the y axis every result is the same bit for bit as         */
/* without `up`.  Along another axis w is rounded once (relative error      */
/* <= eps): a depth over a finite length carries |w s / H| eps more (a ray  */
/* crossing many scale heights); a free-flight distance does not (its t     */
/* depends on w through log1p(z)/a).  mist_hfog_layers_eval takes           */
/* layers[0]'s axis, its height rounded once.                               */
/*                                                                          */
/* THE MIE PHASE FUNCTION: mie_tab (a tabulated one: each channel its own   */
/* where the table has 3, else their mean) if set, else mie_prepared (any   */
/* prepared mist_phase), else mie_phase.  The in-scatter is linear in the   */
/* phase value, so the bar holds for any of them (at the value as           */
/* evaluated).  Under MIST_NO_TAB mie_tab is ignored.                       */
/*                                                                          */
/* A RAY-MARCHING STEP (mist_segment_linear; [B08] integrates single        */
/* scattering per piecewise-linear segment).  Over a step of length len    */
/* the extinction is linear from k0 to k1 and the source (scattering x      */
/* phase x incident light) linear from s0 to s1:                            */
/*   L = len (s0 W0 + s1 W1),  W0 = int_0^1 (1-t) e^-tau,  W1 = int t e^-tau, */
/*   tau(t) = p t + b t^2,  p = k0 len,  b = (k1 - k0) len / 2.             */
/* Completing the square gives erfcx (b > 0, extinction rising) or Dawson's */
/* integral F (b < 0); M1 = int t e^-tau follows from 1 - e^-tau(1) - p M0, */
/* which cancels, so mist evaluates it through G(x) = 1 - sqrt(pi) x        */
/* erfcx(x) and K(y) = 2 y F(y) - 1, both small and computed directly       */
/* (piecewise Chebyshev series fitted to 50 digits, asymptotic series      */
/* beyond 8).  What remains loses at most 1.5 bits once tau(1) > 2 (the two */
/* terms differ by e^-tau(1)); below, where the extinction goes to 0, the   */
/* integrands are entire and small and a 16-point Gauss-Legendre rule is    */
/* exact to 1e-20 (no extinction: the trapezoid rule, exactly).  Measured   */
/* against quadrature: below 10 eps in double and float.                    */
/*                                                                          */
/* DOMAIN AND BAD INPUT (tested)                                            */
/*   fog NULL; density NaN or <= 0; scale_height NaN or <= 0; base or       */
/*       origin.y not finite; length NaN or <= 0: no fog (T = 1, L = 0,     */
/*       column 0).  scale_height +inf: uniform fog (the sun's column above */
/*       any point is then infinite: no dimmed sun light).  Subnormal and   */
/*       largest finite scale heights are ordinary values, but for one      */
/*       corner: a scale height below 2^-916 (float 2^-78) with w s beyond  */
/*       2^918 (float 2^80), where w s / H is far outside the range, misses */
/*       the bar by up to ~85x (an independent check's random draws: 5 of   */
/*       8e5 checks in double, 14 of 2e6 in float).  length +inf: allowed.  */
/*   coefficients, sun, ambient: NaN and negative count as 0, +inf as the   */
/*       largest finite value; an extinction below its scattering is raised */
/*       to it (albedo <= 1).  Sums and products of them are exact to      */
/*       rounding where the result is representable, even where a term is  */
/*       not (R + M extinction beyond the range, a column beyond the range */
/*       times a subnormal extinction: carried scaled).  A Dirac lobe       */
/*       (|g| = 1) seen on its peak: its +inf density counts as the largest */
/*       finite value.                                                      */
/*   dir, sun_dir: used as given when unit to rounding, else normalised (a  */
/*       zero, NaN or infinite vector is (0, 0, 1): level).  The vertical   */
/*       cosine w is the normalised y component as it rounds: a subnormal w */
/*       is a nearly level ray (up, C(inf) = density e^-h H / w, which      */
/*       overflows to +inf, T = 0, unless that product is tiny: continuous  */
/*       with the level ray's C = +inf as w -> 0), and a y that underflows  */
/*       to +-0 (as dir = (1, 1e-320, 0) in double) IS the level ray: to    */
/*       infinity, any positive density and extinction give C = +inf,      */
/*       T = 0.  (A subnormal w carries normalisation's absolute error, a  */
/*       few times the smallest subnormal.)                                 */
/*   mist_hfog_sample_distance: no fog (as above; channel outside 0..2;     */
/*       tmax NaN or <= 0): +inf, no collision; xi NaN or <= 0: 0 (the      */
/*       start); xi >= 1: +inf.  mist_hfog_optical_depth: no fog, t NaN or  */
/*       <= 0: 0.  mist_hfog_extinction: no fog: 0; +inf where it overflows.*/
/*       Along a non-y axis every origin component must be finite.          */
/*   layers: NULL or n < 1: no fog; a bad layer is left out; at most        */
/*       MIST_HFOG_MAX_LAYERS (8) are used; pieces <= 0: 8, at most 64.     */
/*   Finite input never gives NaN: T in [0, 1], L >= 0, bound >= 0 (+inf   */
/*       where the bound itself leaves the range).                          */
/* ======================================================================== */

#define MIST__RGB   MIST__FN(mist_rgb)
#define MIST__HFOG  MIST__FN(mist_hfog)
#define MIST__HRAY  MIST__FN(mist__hray)
#define MIST__HFK   MIST__FN(mist__hfk)
/* a bound on |x| with exp(+-x) normal (MIST__BIG: see mist__two_prod) */
#define MIST__XLIM  MIST__C(MIST__DBL ? 700 : 85)

/* x for x > 0 (at most the largest finite value), else 0 (NaN too), and
 * whether x is finite: on the bits.  These are the height fog's
 * sanitisers of input, and clang (14) gives the includer's fast-math flags
 * (nnan, ninf) to the ?: phis, negations and calls inside mist's functions
 * whatever the guard's pragma: a floating-point test there is folded away
 * (+inf came through as +inf, NaN as NaN), an integer test of the bits is
 * not (see FAST MATH at the top). */
MIST__F MIST__T MIST__FN(mist__pos)(MIST__T x)
{
    MIST__UB b;
    memcpy(&b, &x, sizeof b);
    if (b == 0 || (b >> (8 * sizeof b - 1)) != 0) return MIST__C(0);   /* +-0, sign set */
    if ((b >> MIST__MB) >= (MIST__UB)MIST__EB)                          /* +inf, +NaN */
        return b == ((MIST__UB)MIST__EB << MIST__MB) ? MIST__BIG : MIST__C(0);
    return x;
}

/* x clamped to +-the largest finite value, NaN to 0: on the bits (above) */
MIST__F MIST__T MIST__FN(mist__clampbig)(MIST__T x)
{
    MIST__UB b;
    memcpy(&b, &x, sizeof b);
    if (((b >> MIST__MB) & (MIST__UB)MIST__EB) != (MIST__UB)MIST__EB) return x;
    if ((b << (8 * sizeof b - MIST__MB)) != 0) return MIST__C(0);      /* NaN */
    return (b >> (8 * sizeof b - 1)) != 0 ? -MIST__BIG : MIST__BIG;
}

MIST__F int MIST__FN(mist__finite)(MIST__T x)
{
    MIST__UB b;
    memcpy(&b, &x, sizeof b);
    return ((b >> MIST__MB) & (MIST__UB)MIST__EB) != (MIST__UB)MIST__EB;
}

/* (n + ne) / H as hi + *lo (|lo| <= ~ulp(hi)): the remainder of the
 * rounded quotient is exact.  n + ne is renormalised first: a sum whose
 * high parts cancelled (y - yb + w s with y ~ w s) leaves the result in
 * ne (found by the stress test: a column e^-830 for e^+830). */
MIST__F MIST__T MIST__FN(mist__ddiv)(MIST__T n, MIST__T ne, MIST__T H, MIST__T *lo)
{
    MIST__T q, pe, p;
    /* (a low part that is not finite: Dekker's split of a product near
     * the largest value overflowed; it is dropped, as before) */
    if (MIST__FN(mist__finite)(n) && MIST__FN(mist__finite)(ne))
        n = MIST__FN(mist__two_sum)(n, ne, &ne);
    q = n / H;
    p = MIST__FN(mist__two_prod)(q, H, &pe);
    *lo = (((n - p) - pe) + ne) / H;
    return q;
}

/* frexp and ldexp on the bits where x (and for ldexp the result) is
 * normal: exact operations, so the same results as libm's, without its
 * call (frexpf 3.5 ns, ldexpf 5.1 ns of latency in a chain, glibc on x86,
 * measured; the height fog takes several a ray), and without glibc's
 * legacy-SSE code, which in mist_bench paid what looks like the SSE/AVX
 * transition penalty (perf: 62% of ldexpf's samples on its second
 * instruction; the caller issues vzeroupper before its calls, so the
 * dirty state's source is not pinned down): there the float layered fog
 * took 14 us a ray with libm's, 7.8 with these.  In a small program
 * without the penalty they cost the float transmittance and in-scatter
 * 5-7% (interleaved A/B) and gained the double in-scatter 5% and the
 * layers 6%.  libm elsewhere, and in CUDA device code (intrinsics there). */
MIST__F MIST__T MIST__FN(mist__frexp)(MIST__T x, int *e)
{
#if !defined(__CUDA_ARCH__)
    MIST__UB b;
    int ex;
    memcpy(&b, &x, sizeof b);
    ex = (int)((b >> MIST__MB) & MIST__EB);
    if (ex > 0 && ex < MIST__EB) {              /* x = m 2^e, m in [1/2, 1) */
        *e = ex - (MIST__EB >> 1) + 1;
        b = (b & ~((MIST__UB)MIST__EB << MIST__MB)) | ((MIST__UB)((MIST__EB >> 1) - 1) << MIST__MB);
        memcpy(&x, &b, sizeof x);
        return x;
    }
#endif
    return MIST__M(frexp)(x, e);
}
MIST__F MIST__T MIST__FN(mist__ldexp)(MIST__T x, int k)
{
#if !defined(__CUDA_ARCH__)
    MIST__UB b;
    int ex;
    memcpy(&b, &x, sizeof b);
    ex = (int)((b >> MIST__MB) & MIST__EB);
    if (ex > 0 && ex < MIST__EB && k > -MIST__EB && k < MIST__EB && ex + k > 0
        && ex + k < MIST__EB) {
        b = (b & ~((MIST__UB)MIST__EB << MIST__MB)) | ((MIST__UB)(ex + k) << MIST__MB);
        memcpy(&x, &b, sizeof x);
        return x;
    }
#endif
    return MIST__M(ldexp)(x, k);
}

/* e^x - 1 without cancellation.  Float: in double, e^x - 1 (a relative
 * error of 2^-53 / |x| at most from exp's rounding: below a quarter ulp of
 * float for |x| >= 2^-26) or x (1 + x/2) below (the next term is under
 * 2^-54 of it); within 0.75 ulp, and glibc's expm1f took 19.4 ns of
 * latency in a chain, this 13.8 (x86, measured).  Double and CUDA device
 * code: libm's expm1. */
MIST__F MIST__T MIST__FN(mist__expm1)(MIST__T x)
{
#if defined(MIST__W_EXACT) && !defined(__CUDA_ARCH__)
    double d = (double)x;
    return (MIST__T)(d > -1.4901161193847656e-08 && d < 1.4901161193847656e-08  /* 2^-26 */
                     ? d * (1 + 0.5 * d) : exp(d) - 1);
#else
    return MIST__M(expm1)(x);
#endif
}

/* ln(1 + x), x > -1.  Float: in double, a 4-term series below 2^-10 (the
 * next term under 2^-50 / 5 of the value) and log(1 + x) above (1 + x
 * exact for x < 0 there, within 2^-53 otherwise: 2^-43 of the value);
 * within 0.5 ulp plus 2^-40, and glibc's log1pf took 16 ns, logf 3.5
 * (x86, measured).  Double and CUDA device code: libm's log1p. */
MIST__F MIST__T MIST__FN(mist__log1p)(MIST__T x)
{
#if defined(MIST__W_EXACT) && !defined(__CUDA_ARCH__)
    double d = (double)x;
    if (d > -0.0009765625 && d < 0.0009765625)                          /* 2^-10 */
        return (MIST__T)(d * (1 - d * (0.5 - d * (1.0 / 3 - 0.25 * d))));
    return (MIST__T)log(1 + d);
#else
    return MIST__M(log1p)(x);
#endif
}

/* phi1(z) = (1 - e^-z) / z, phi1(0) = 1, phi1(+inf) = 0, with no
 * cancellation (expm1). */
MIST__F MIST__T MIST__FN(mist__phi1)(MIST__T z)
{
    return z == MIST__C(0) ? MIST__C(1) : -MIST__FN(mist__expm1)(-z) / z;
}

/* c1 c2 c3 c4 / d * exp(-(xh + xl)), for c1..c4 >= 0, d > 0 (+inf counts
 * as the largest finite value) and |xl| << 1 (else taken as 0: xh is then
 * far beyond exp's range).  Right whenever the result is representable:
 * the fast path is taken when every partial product and the result are
 * normal; else the factors' exponents are set aside (frexp) and the
 * exponential is taken in 2^m equal parts (an exact division of xh),
 * renormalising after each, so that no intermediate leaves the range;
 * ldexp rounds once at the end.  mist__expmul_s is the scaled form: the
 * result times 2^k0 as r 2^*k, r in [1/2, 1) (0 or +inf only beyond
 * e^(+-64 XLIM): float's 2^+-7800, as far as products of a few
 * factors in the range reach back), so that a column beyond the range (a
 * huge density times a subnormal extinction) is still carried exactly;
 * mist__expmul_k rounds it once (ldexp). */
MIST__F MIST__T MIST__FN(mist__expmul_s)(MIST__T c1, MIST__T c2, MIST__T c3, MIST__T c4,
                                         MIST__T d, MIST__T xh, MIST__T xl, int k0, int *ko)
{
    MIST__T p, r, e, x;
    int k, k1, k2, k3, k4, k5, n, i;
    *ko = 0;
    if (!(c1 > MIST__C(0) && c2 > MIST__C(0) && c3 > MIST__C(0) && c4 > MIST__C(0)) || xh != xh)
        return MIST__C(0);
    c1 = c1 < MIST__BIG ? c1 : MIST__BIG; c2 = c2 < MIST__BIG ? c2 : MIST__BIG;
    c3 = c3 < MIST__BIG ? c3 : MIST__BIG; c4 = c4 < MIST__BIG ? c4 : MIST__BIG;
    d = d < MIST__BIG ? d : MIST__BIG;
    if (!(xl < MIST__C(1e-3) && xl > MIST__C(-1e-3))) xl = MIST__C(0);
    p = MIST__FN(mist__frexp)(c1, &k1) * MIST__FN(mist__frexp)(c2, &k2);
    p = p * MIST__FN(mist__frexp)(c3, &k3) * MIST__FN(mist__frexp)(c4, &k4);
    p = p / MIST__FN(mist__frexp)(d, &k5);                 /* in [1/32, 2) */
    k = k1 + k2 + k3 + k4 - k5 + k0;
    /* e^-xh against 2^k: beyond these the result is 0 or +inf */
    x = xh - (MIST__T)k * MIST__C(0.693147180559945309);
    if (x > MIST__C(64) * MIST__XLIM) return MIST__C(0);
    if (x < MIST__C(-64) * MIST__XLIM) return (MIST__T)INFINITY;
    /* n bounded in integers: a NaN xh meets only the tests above, which
     * -ffinite-math-only may delete (MIST_ALLOW_FAST_MATH): n then doubled
     * past INT_MAX, an endless loop.  Finite input past them needs n <= 128
     * (|xh| <= 64 XLIM + |k| ln 2 < 128 XLIM). */
    for (n = 1; n < 4096 && !(xh / (MIST__T)n < MIST__XLIM && xh / (MIST__T)n > -MIST__XLIM);
         n *= 2) {}
    e = MIST__M(exp)(-xh / (MIST__T)n);
    r = MIST__FN(mist__frexp)(p * (MIST__C(1) - xl), &i);
    k += i;
    for (i = 0; i < n; ++i) {
        int j;
        r = MIST__FN(mist__frexp)(r * e, &j);
        k += j;
    }
    *ko = k;
    return r;
}

MIST__F MIST__T MIST__FN(mist__expmul_k)(MIST__T c1, MIST__T c2, MIST__T c3, MIST__T c4,
                                         MIST__T d, MIST__T xh, MIST__T xl, int k0)
{
    const MIST__T tmin = MIST__TMIN;
    MIST__T r;
    int k;
    if (k0 == 0 && xh > -MIST__XLIM && xh < MIST__XLIM && c1 > MIST__C(0) && c2 > MIST__C(0)
        && c3 > MIST__C(0) && c4 > MIST__C(0) && c1 <= MIST__BIG && c2 <= MIST__BIG
        && c3 <= MIST__BIG && c4 <= MIST__BIG && d <= MIST__BIG && xl < MIST__C(1e-3)
        && xl > MIST__C(-1e-3)) {
        MIST__T p1 = c1 * c2, p2 = p1 * c3, p3 = p2 * c4, p = p3 / d;
        if (p1 >= tmin && p1 <= MIST__BIG && p2 >= tmin && p2 <= MIST__BIG && p3 >= tmin
            && p3 <= MIST__BIG && p >= tmin && p <= MIST__BIG) {
            if (xh == MIST__C(0) && xl == MIST__C(0)) return p;
            r = p * MIST__M(exp)(-xh) * (MIST__C(1) - xl);
            if (r >= tmin && r <= MIST__BIG) return r;
        }
    }
    r = MIST__FN(mist__expmul_s)(c1, c2, c3, c4, d, xh, xl, k0, &k);
    return MIST__FN(mist__ldexp)(r, k);
}

MIST__F MIST__T MIST__FN(mist__expmul)(MIST__T c1, MIST__T c2, MIST__T c3, MIST__T c4,
                                       MIST__T d, MIST__T xh, MIST__T xl)
{
    return MIST__FN(mist__expmul_k)(c1, c2, c3, c4, d, xh, xl, 0);
}

/* c1 c2 c3 / d times m 2^e (a column or density carried scaled;
 * m = +inf: an infinite one) times e^-x. */
MIST__F MIST__T MIST__FN(mist__hmul)(MIST__T c1, MIST__T c2, MIST__T c3, MIST__T d, MIST__T m,
                                     int e, MIST__T x)
{
    if (!(m <= MIST__BIG))
        return c1 > MIST__C(0) && c2 > MIST__C(0) && c3 > MIST__C(0) && m > MIST__C(0)
               && !(x >= (MIST__T)INFINITY) ? (MIST__T)INFINITY : MIST__C(0);
    return MIST__FN(mist__expmul_k)(c1, c2, c3, m, d, x, MIST__C(0), e);
}

/* The sun's height ly as m 2^*k with m normal: a subnormal ly scaled up by
 * 2^(2 mant) (1/|nu| = ly/|ly - w| of the dimmed sun was a subnormal
 * quotient and lost its digits: 8.7% off at ly = 2^-1074, found by an
 * independent check); *k goes to mist__expmul_k's exponent. */
MIST__F MIST__T MIST__FN(mist__hly)(MIST__T ly, int *k)
{
    *k = ly < MIST__TMIN ? -2 * (MIST__MB + 1) : 0;
    return MIST__FN(mist__ldexp)(ly, -*k);
}

/* The sun's optical depth to a point of density m 2^e: st m 2^e H / ly
 * (the column above it along the sun), +inf in a uniform fog (H = +inf:
 * the column above never ends). */
MIST__F MIST__T MIST__FN(mist__hsun)(MIST__T st, MIST__T H, MIST__T ly, MIST__T m, int e)
{
    if (!(H <= MIST__BIG))
        return st > MIST__C(0) && m > MIST__C(0) ? (MIST__T)INFINITY : MIST__C(0);
    return MIST__FN(mist__hmul)(st, H, MIST__C(1), ly, m, e, MIST__C(0));
}

/* One exponential layer, density d0 exp(-(y - yb) / H), along the ray
 * y(t) = y + w t, t in [t0, t0 + s]: col = the integral of the density,
 * rho0 and rho1 = the density at the two ends; each also scaled,
 * cm 2^ce etc. (cm in [1/2, 1), 0, or +inf for an infinite column), so
 * that a product with a coefficient (mist__hmul) is right where the
 * column or the density alone leaves the range. */
typedef struct MIST__HRAY {
    MIST__T col, rho0, rho1, cm, r0m, r1m;
    int ce, r0e, r1e;
} MIST__HRAY;

/* c1 c2 c3 c4 / d exp(-(xh + xl)) scaled, as mist__expmul_s (the fast
 * path where the result is normal). */
MIST__F MIST__T MIST__FN(mist__expmul_f)(MIST__T c1, MIST__T c2, MIST__T c3, MIST__T c4,
                                         MIST__T d, MIST__T xh, MIST__T xl, int *k)
{
    const MIST__T tmin = MIST__TMIN;
    MIST__T r = MIST__FN(mist__expmul)(c1, c2, c3, c4, d, xh, xl);
    if (r >= tmin && r <= MIST__BIG) return MIST__FN(mist__frexp)(r, k);
    return MIST__FN(mist__expmul_s)(c1, c2, c3, c4, d, xh, xl, 0, k);
}

/* Requires d0 > 0 finite, H > 0 (+inf: uniform), y, yb, t0 finite,
 * w in [-1, 1], s >= 0 (+inf allowed).  The exponents are carried as
 * double-T (hi + lo) and combined before exp is taken; the lower end of the
 * segment is the reference, so the column is  d0 e^(-h_low) s phi1(|a|)
 * with a = w s / H and phi1 <= 1: nothing overflows unless the result does. */
MIST__F MIST__HRAY MIST__FN(mist__hray_eval)(MIST__T y, MIST__T w, MIST__T t0, MIST__T s,
                                             MIST__T yb, MIST__T H, MIST__T d0)
{
    MIST__HRAY r;
    MIST__T hh = 0, hl = 0, ah = 0, al = 0, xh = 0, xl = 0, za, aw, n = 0, ne = 0, p = 0, pe = 0;
    if (H <= MIST__BIG) {                        /* else uniform: h = a = 0 */
        /* numerators in two parts: y - yb (+ w t0), and w s.  They and H
         * are scaled by sc (exactly): by 2^(2 mant) for an H so small that
         * the error-free products' low parts would be subnormal (they are
         * divided by H); by 1/2 where a sum overflows though its terms do
         * not.  The quotients stay. */
        const MIST__T up = MIST__C(1) / (MIST__EPS * MIST__EPS);
        const MIST__T tiny = MIST__TMIN * up;
        MIST__T sc = H < tiny ? up : MIST__C(1), Hs = sc * H, f = 0, fe = 0;
        int pass;
        for (pass = 0; pass < 3; ++pass) {
            /* scaled up: the exact difference first (y = yb = 2^919 with a
             * subnormal H had overflowed sc y, and the fallback sc = 1 lost
             * the low parts: an independent check, 8e-5 off) */
            if (sc > MIST__C(1)) {
                n = MIST__FN(mist__two_sum)(y, -yb, &ne);
                n *= sc; ne *= sc;
            } else
                n = MIST__FN(mist__two_sum)(sc * y, -(sc * yb), &ne);
            if (t0 != MIST__C(0)) {                 /* y - yb + w t0 */
                MIST__T d = n, de = ne;
                p = MIST__FN(mist__two_prod)(w, sc * t0, &pe);
                n = MIST__FN(mist__two_sum)(d, p, &ne);
                ne += de + pe;
            }
            if (s <= MIST__BIG) {
                p = MIST__FN(mist__two_prod)(w, sc * s, &pe);
                f = MIST__FN(mist__two_sum)(n, p, &fe);
                fe += ne + pe;
            }
            if (MIST__FN(mist__finite)(n) && MIST__FN(mist__finite)(f)) break;
            sc = sc > MIST__C(1) ? MIST__C(1) : MIST__C(0.5);
            Hs = sc * H;
        }
        hh = MIST__FN(mist__ddiv)(n, ne, Hs, &hl);
        if (s <= MIST__BIG) {
            /* the far end's height over H: the numerators are added first,
             * so that two huge quotients never meet */
            ah = MIST__FN(mist__ddiv)(p, pe, Hs, &al);
            xh = MIST__FN(mist__ddiv)(f, fe, Hs, &xl);
        }
        /* THE COMMON CASE, straight: a finite ray (t0 = 0, not scaled) whose
         * exponents lie within XLIM and whose products below are normal.
         * mist__expmul_f is then these products times one exp each (its fast
         * path): the same operations in the same order, so the same values,
         * without its range tests and with e^-h taken once for the lower
         * end and for the density there. */
        if (s <= MIST__BIG && t0 == MIST__C(0) && sc == MIST__C(1) && d0 >= MIST__TMIN
            && hh > -MIST__XLIM && hh < MIST__XLIM && xh > -MIST__XLIM && xh < MIST__XLIM
            && hl > MIST__C(-1e-3) && hl < MIST__C(1e-3) && xl > MIST__C(-1e-3)
            && xl < MIST__C(1e-3)) {
            const MIST__T tmin = MIST__TMIN;
            MIST__T e0 = MIST__M(exp)(-hh), e1 = MIST__M(exp)(-xh), q0, q1, p1, p2, el, ll, cl;
            q0 = d0 * e0 * (MIST__C(1) - hl);
            q1 = d0 * e1 * (MIST__C(1) - xl);
            el = p < MIST__C(0) ? e1 : e0;              /* the lower end */
            ll = p < MIST__C(0) ? xl : hl;
            za = ah < MIST__C(0) ? -ah : ah;
            aw = w < MIST__C(0) ? -w : w;
            if (za < MIST__C(1)) {
                p1 = d0 * s;
                p2 = p1 * MIST__FN(mist__phi1)(za);
                cl = p2;
            } else {
                p1 = d0 * H;
                p2 = p1 * -MIST__FN(mist__expm1)(-za);
                cl = p2 / aw;
            }
            cl = cl * el * (MIST__C(1) - ll);
            if (q0 >= tmin && q0 <= MIST__BIG && q1 >= tmin && q1 <= MIST__BIG && p1 >= tmin
                && p1 <= MIST__BIG && p2 >= tmin && p2 <= MIST__BIG && cl >= tmin
                && cl <= MIST__BIG && (za < MIST__C(1) || (p2 / aw >= tmin && p2 / aw <= MIST__BIG))) {
                r.rho0 = q0; r.r0m = MIST__FN(mist__frexp)(q0, &r.r0e);
                r.rho1 = q1; r.r1m = MIST__FN(mist__frexp)(q1, &r.r1e);
                r.col = cl;  r.cm = MIST__FN(mist__frexp)(cl, &r.ce);
                return r;
            }
        }
    }
    r.r0m = MIST__FN(mist__expmul_f)(d0, MIST__C(1), MIST__C(1), MIST__C(1), MIST__C(1), hh, hl,
                                     &r.r0e);
    r.rho0 = MIST__FN(mist__ldexp)(r.r0m, r.r0e);
    if (!(s <= MIST__BIG)) {                     /* s = +inf */
        if (w > MIST__C(0) && H <= MIST__BIG) {  /* the column above: H / w */
            r.cm = MIST__FN(mist__expmul_f)(d0, H, MIST__C(1), MIST__C(1), w, hh, hl, &r.ce);
            r.r1m = MIST__C(0); r.r1e = 0;
        } else {                                /* down, level or uniform */
            r.cm = (MIST__T)INFINITY; r.ce = 0;
            if (w < MIST__C(0) && H <= MIST__BIG) { r.r1m = (MIST__T)INFINITY; r.r1e = 0; }
            else { r.r1m = r.r0m; r.r1e = r.r0e; }
        }
        r.col = MIST__FN(mist__ldexp)(r.cm, r.ce);
        r.rho1 = MIST__FN(mist__ldexp)(r.r1m, r.r1e);
        return r;
    }
    za = ah < MIST__C(0) ? -ah : ah;
    if (!(za == za)) za = (MIST__T)INFINITY;
    aw = w < MIST__C(0) ? -w : w;
    r.r1m = MIST__FN(mist__expmul_f)(d0, MIST__C(1), MIST__C(1), MIST__C(1), MIST__C(1), xh, xl,
                                     &r.r1e);
    if (!(p < MIST__C(0))) { xh = hh; xl = hl; }    /* the lower end */
    /* the length's factor, s phi1(za) or (H / |w|)(1 - e^-za): as factors
     * of the scaled product (a subnormal s or w loses nothing more) */
    if (za < MIST__C(1))
        r.cm = MIST__FN(mist__expmul_f)(d0, s, MIST__FN(mist__phi1)(za), MIST__C(1), MIST__C(1),
                                        xh, xl, &r.ce);
    else
        r.cm = MIST__FN(mist__expmul_f)(d0, H, -MIST__FN(mist__expm1)(-za), MIST__C(1), aw, xh, xl,
                                        &r.ce);
    r.col = MIST__FN(mist__ldexp)(r.cm, r.ce);
    r.rho1 = MIST__FN(mist__ldexp)(r.r1m, r.r1e);
    return r;
}

/* A direction used as given when it is unit to rounding (so the vertical
 * cosine is exactly dir.y), else normalised (zero, NaN, inf: (0, 0, 1)).
 * The vertical cosine is what normalisation gives: a subnormal one is a
 * nearly level ray, one that underflows to 0 a level ray (see DOMAIN AND
 * BAD INPUT). */
MIST__F MIST__V3 MIST__FN(mist__unit)(MIST__V3 v)
{
    MIST__T d = v.x * v.x + v.y * v.y + v.z * v.z - MIST__C(1);
    if (d <= MIST__C(16) * MIST__EPS && d >= MIST__C(-16) * MIST__EPS) return v;
    return MIST__FN(mist__impl_normalize)(v);
}

/* a . b as hi + *lo, hi the dot product rounded to within an ulp however
 * much it cancels: the six parts of the error-free products (two_prod)
 * summed exactly into a nonoverlapping expansion (Shewchuk's
 * Grow-Expansion: TwoSum chains), then the expansion added smallest
 * first.  (A compensated dot product, Dot2, errs by eps^2 of the terms: a
 * ray level to 1e-10 along a rotated float axis lost 15 eps.)  Exact but
 * for products whose low parts underflow (terms below ~2^-900 in double,
 * 2^-100 in float, of the largest). */
MIST__F MIST__T MIST__FN(mist__dot2)(MIST__V3 a, MIST__V3 b, MIST__T *lo)
{
    MIST__T x[6], e[6], q, h, s;
    int i, j, m = 0;
    x[0] = MIST__FN(mist__two_prod)(a.x, b.x, &x[1]);
    x[2] = MIST__FN(mist__two_prod)(a.y, b.y, &x[3]);
    x[4] = MIST__FN(mist__two_prod)(a.z, b.z, &x[5]);
    for (i = 0; i < 6; ++i) {
        q = x[i];
        for (j = 0; j < m; ++j) {
            q = MIST__FN(mist__two_sum)(q, e[j], &h);
            e[j] = h;
        }
        e[m++] = q;
    }
    s = e[0];
    for (j = 1; j < 5; ++j) s += e[j];
    return MIST__FN(mist__two_sum)(e[5], s, lo);
}

/* Whether the fog's up is all zero (the y axis: the common case, which
 * the callers below test first, inline, before the general axis). */
MIST__F MIST__HOT int MIST__FN(mist__hyup)(const MIST__HFOG *fog)
{
    return (fog->up.x == MIST__C(0)) & (fog->up.y == MIST__C(0)) & (fog->up.z == MIST__C(0));
}

/* The fog's height axis as used (*a): 0 where it is the y axis (up all
 * zero, or with a NaN or infinite component), else 1 with up itself when
 * unit to rounding, normalised otherwise. */
MIST__F int MIST__FN(mist__haxis)(const MIST__HFOG *fog, MIST__V3 *a)
{
    MIST__V3 u = fog->up;
    if (MIST__FN(mist__hyup)(fog)
        || !(MIST__FN(mist__finite)(u.x) && MIST__FN(mist__finite)(u.y)
             && MIST__FN(mist__finite)(u.z)))
        return 0;
    *a = MIST__FN(mist__unit)(u);
    return 1;
}

/* The vertical component of the unit vector l (the sun's direction). */
MIST__F MIST__HOT MIST__T MIST__FN(mist__hvert)(const MIST__HFOG *fog, MIST__V3 l)
{
    MIST__V3 a;
    MIST__T lo;
    if (MIST__FN(mist__hyup)(fog) || !MIST__FN(mist__haxis)(fog, &a)) return l.y;
    return MIST__FN(mist__dot2)(l, a, &lo);
}

/* A point's height along the fog's axis as the pair (*y, *yb), y - yb its
 * height above the base (see mist__hup); returns 1 where the axis is not y
 * (the axis is then *a / *an: up itself and 1 where unit to rounding, else
 * up scaled by a power of 2 and its length). */
MIST__F int MIST__FN(mist__hheight)(const MIST__HFOG *fog, MIST__V3 p, MIST__T *y, MIST__T *yb,
                                    MIST__V3 *a, MIST__T *an)
{
    MIST__T hl, ne, h;
    MIST__V3 u = fog->up;
    *an = MIST__C(1);
    if (!MIST__FN(mist__haxis)(fog, a)) { *y = p.y; *yb = fog->base; return 0; }
    if ((a->x == u.x && a->y == u.y && a->z == u.z)      /* unit: as given */
        || (u.x == MIST__C(0) && u.y == MIST__C(0)) || (u.x == MIST__C(0) && u.z == MIST__C(0))
        || (u.y == MIST__C(0) && u.z == MIST__C(0)))      /* an axis: exact */
        h = MIST__FN(mist__dot2)(p, *a, &hl);
    else {
        /* p . u / |u| to ~eps^2, u scaled to its largest component
         * (exactly): the rounded unit vector *a errs by an eps, |p| eps in
         * the height, that many eps of the density's exponent where |p|/H
         * is large (a start 300 scale heights up a tilted axis: 300 eps) */
        MIST__T m = MIST__M(fabs)(u.x), n2, n2l, N, Nl, q, pp, pe;
        int e;
        m = m > MIST__M(fabs)(u.y) ? m : MIST__M(fabs)(u.y);
        m = m > MIST__M(fabs)(u.z) ? m : MIST__M(fabs)(u.z);
        (void)MIST__FN(mist__frexp)(m, &e);
        u.x = MIST__FN(mist__ldexp)(u.x, -e);
        u.y = MIST__FN(mist__ldexp)(u.y, -e);
        u.z = MIST__FN(mist__ldexp)(u.z, -e);
        h = MIST__FN(mist__dot2)(p, u, &hl);
        n2 = MIST__FN(mist__dot2)(u, u, &n2l);                  /* in [1/4, 3) */
        N = MIST__M(sqrt)(n2);                                  /* |u| = N + Nl */
        pp = MIST__FN(mist__two_prod)(N, N, &pe);
        Nl = (((n2 - pp) - pe) + n2l) / (MIST__C(2) * N);
        q = h / N;                                               /* (h + hl) / (N + Nl) */
        pp = MIST__FN(mist__two_prod)(q, N, &pe);
        hl = MIST__FN(mist__finite)(q) && MIST__FN(mist__finite)(pe)
           ? ((((h - pp) - pe) + hl) - q * Nl) / N : MIST__C(0);
        h = q;
        *a = u; *an = N;
    }
    *y = MIST__FN(mist__two_sum)(h, -fog->base, &ne);
    *yb = -(ne + hl);
    return 1;
}

/* A ray's start and direction along the fog's height axis: *y and *yb
 * whose difference y - yb is the start's height above the base (what
 * mist__hray_eval takes), the unit direction *v (mist__unit) and its
 * vertical cosine *w in [-1, 1].  On the y axis y = origin.y, yb = base,
 * w = v.y.  On another axis a: the height origin . a - base is carried as
 * hi + lo exactly to ~eps^2 (y = hi, yb = -lo), so that it enters the
 * height's quotient by H as an input's y would (rounded once, |y| eps/H
 * in the density for |y| >> H); w = dir . a / |dir| with the dot product
 * compensated and dir scaled to its largest component (exactly), so that
 * a nearly level ray keeps w's relative accuracy (a few eps), as v.y has.
 * Returns 0 where the height is not finite. */
MIST__F int MIST__FN(mist__hup_axis)(const MIST__HFOG *fog, MIST__V3 origin, MIST__V3 dir,
                                     MIST__T *y, MIST__T *yb, MIST__V3 *v, MIST__T *w)
{
    MIST__V3 a;
    MIST__T wv, an;
    *v = MIST__FN(mist__unit)(dir);
    if (!MIST__FN(mist__hheight)(fog, origin, y, yb, &a, &an)) {
        wv = v->y;
    } else {
        MIST__T lo;
        if (v->x == dir.x && v->y == dir.y && v->z == dir.z)    /* unit: as given */
            wv = MIST__FN(mist__dot2)(dir, a, &lo);
        else {
            MIST__T ax = MIST__M(fabs)(dir.x), ay = MIST__M(fabs)(dir.y), az = MIST__M(fabs)(dir.z);
            MIST__T m = ax > ay ? ax : ay;
            m = m > az ? m : az;
            if (m > MIST__C(0) && m <= MIST__BIG) {
                MIST__V3 d;
                MIST__T n2;
                int e;
                (void)MIST__FN(mist__frexp)(m, &e);
                d.x = MIST__FN(mist__ldexp)(dir.x, -e);
                d.y = MIST__FN(mist__ldexp)(dir.y, -e);
                d.z = MIST__FN(mist__ldexp)(dir.z, -e);
                n2 = MIST__FN(mist__dot2)(d, d, &lo);
                wv = MIST__FN(mist__dot2)(d, a, &lo) / MIST__M(sqrt)(n2 + lo);
            } else                                  /* zero, NaN, inf: v */
                wv = MIST__FN(mist__dot2)(*v, a, &lo);
        }
        if (an != MIST__C(1)) wv /= an;             /* a non-unit axis */
    }
    *w = wv < MIST__C(-1) ? MIST__C(-1) : (wv > MIST__C(1) ? MIST__C(1) : wv);
    return MIST__FN(mist__finite)(*y) && MIST__FN(mist__finite)(*yb);
}
/* (the y axis, up all zero, inline: mist__hup_axis's first branch; the
 * general axis out of line, so that the common case's callers stay small) */
MIST__F MIST__HOT int MIST__FN(mist__hup_y)(const MIST__HFOG *fog, MIST__V3 origin, MIST__V3 dir,
                                            MIST__T *y, MIST__T *yb, MIST__V3 *v, MIST__T *w)
{
    *v = MIST__FN(mist__unit)(dir);
    *y = origin.y;
    *yb = fog->base;
    *w = v->y < MIST__C(-1) ? MIST__C(-1) : (v->y > MIST__C(1) ? MIST__C(1) : v->y);
    return MIST__FN(mist__finite)(*y) && MIST__FN(mist__finite)(*yb);
}
MIST__F MIST__HOT int MIST__FN(mist__hup)(const MIST__HFOG *fog, MIST__V3 origin, MIST__V3 dir,
                                          MIST__T *y, MIST__T *yb, MIST__V3 *v, MIST__T *w)
{
    if (!MIST__FN(mist__hyup)(fog))
        return MIST__FN(mist__hup_axis)(fog, origin, dir, y, yb, v, w);
    return MIST__FN(mist__hup_y)(fog, origin, dir, y, yb, v, w);
}

/* The integral of the density factor  density exp(-(y(t) - base)/H)  along
 * the ray y(t) = y + w t, 0 <= t <= length: the optical depth of a
 * component is its extinction coefficient times this.  w is the vertical
 * component of the unit direction, length may be +inf.  Bad input (see the
 * section comment) gives 0. */
MIST__F MIST__T MIST__FN(mist__impl_hfog_column)(const MIST__HFOG *fog, MIST__T y, MIST__T w,
                                           MIST__T length)
{
    MIST__T d0, H;
    if (!fog) return MIST__C(0);
    d0 = MIST__FN(mist__pos)(fog->density); H = fog->scale_height;
    if (!(d0 > MIST__C(0) && H > MIST__C(0) && length > MIST__C(0) && w == w
          && MIST__FN(mist__finite)(fog->base) && MIST__FN(mist__finite)(y)))
        return MIST__C(0);
    w = w < MIST__C(-1) ? MIST__C(-1) : (w > MIST__C(1) ? MIST__C(1) : w);
    return MIST__FN(mist__hray_eval)(y, w, MIST__C(0), length, fog->base, H, d0).col;
}

/* A fog's sanitised coefficients for channel c (see the section comment):
 * the scatterings *sR, *sM and the extinction *st = eR + eM, each
 * extinction raised to its scattering.  Where that sum leaves the range
 * all four are halved (exactly, but for subnormals) and *sx = 1: the
 * coefficients are (*sR, *sM, *st) 2^*sx, so the albedos stay <= 1 and
 * the optical depth takes the 2^*sx as an exponent (mist__hmul).  Returns
 * 0 when the fog (layer) is absent.  Always inlined: gcc 12 compiled its
 * out-of-line copy's NaN test of the scale height as under -ffinite-math-
 * only inside the fast-math guard (see FAST MATH). */
MIST__F MIST__HOT int MIST__FN(mist__hlayer)(const MIST__HFOG *f, int c, MIST__T *sR, MIST__T *sM,
                                    MIST__T *st, int *sx)
{
    MIST__T r, m, er, em;
    r  = c == 0 ? f->rayleigh_scat.r : (c == 1 ? f->rayleigh_scat.g : f->rayleigh_scat.b);
    m  = c == 0 ? f->mie_scat.r      : (c == 1 ? f->mie_scat.g      : f->mie_scat.b);
    er = c == 0 ? f->rayleigh_ext.r  : (c == 1 ? f->rayleigh_ext.g  : f->rayleigh_ext.b);
    em = c == 0 ? f->mie_ext.r       : (c == 1 ? f->mie_ext.g       : f->mie_ext.b);
    *sR = MIST__FN(mist__pos)(r); *sM = MIST__FN(mist__pos)(m);
    er = MIST__FN(mist__pos)(er); em = MIST__FN(mist__pos)(em);
    er = er > *sR ? er : *sR;     em = em > *sM ? em : *sM;
    *sx = 0;
    if (!(er + em <= MIST__BIG)) {
        er *= MIST__C(0.5); em *= MIST__C(0.5); *sR *= MIST__C(0.5); *sM *= MIST__C(0.5);
        *sx = 1;
    }
    *st = er + em;
    return MIST__FN(mist__pos)(f->density) > MIST__C(0) && f->scale_height > MIST__C(0)
        && MIST__FN(mist__finite)(f->base);
}

/* THE STRAIGHT PATH (mist__hfast): one ray in the common case, branch-free
 * (the batch forms vectorise it; the scalar functions take the same code,
 * so the two agree bit for bit), in double for both types (float's
 * inputs are exact there, its results rounded once).  A fog qualifies
 * (mist__hfk_make) where the sun is not dimmed, nothing was halved
 * (mist__hlayer) and its density, scale height and extinctions lie in
 * (lo, hi) = (1e-75, 1e75), its lights and scatterings there or at 0
 * (every positive float does); a ray where its lower end's exponent h is
 * within +-700, the density there e^-h normal, its length in (lo, hi) or
 * beyond going up, its column in (lo, hi), its phase values 0 or in (lo,
 * hi) and every tau <= 700.  Then no product leaves the normal range (at
 * most five factors in (lo, hi), the rest in [e^-700, 1]) and, with
 * e^x = 2^k (1 + p) (mist__hexp):
 *   C = density e^-h (1 - h_lo) s phi1(z),  z = |w| s / H  (s phi1(z) =
 *       (H/|w|)(1 - e^-z) for z >= 1: also the ray to infinity going up),
 *   T = e^x and 1 - T from one evaluation (x = -st C), within about an
 *       ulp each,
 *   L = (La (sR + sM) + E sR pR + E sM pM) (1 - T) / st  (below tau = 1
 *       as C phi1(tau), phi1(tau) = (1 - T) / tau: tau's rounding cancels),
 * h as hi + lo from error-free sums and products (as mist__hray_eval;
 * the remainder of hh = n / H taken with 1/H, exact), 1/H once.  The
 * scaled path does the rest.  Measured against long double quadrature:
 * tests/test_height_fog.c (grid and random rays). */
typedef struct MIST__HFK {
    double H, iH, d0, st[3], a[3], r[3], m[3];
} MIST__HFK;

/* e^x returned and *om = 1 - e^x, for x in [-700, 700]: x = k ln 2 + r,
 * k rounded by the 1.5 2^52 shift (2^k from its bits), r in two parts
 * (ln 2's high part has 32 bits: k ln2_hi exact), e^r - 1 = r + t, t =
 * r^2 q by its Taylor series to r^13 (float's pass r^8), |r| < 0.35:
 * within 1.3e-17 (1.7e-9), summed by Estrin's scheme (a short chain).
 * e^x = 2^k ((1 + r) + t) with 1 + r error-free (Fast2Sum): half an ulp
 * and t's rounding (|t| < 0.07); 1 - e^x = (1 - 2^k) - 2^k (r + t), 1 - 2^k
 * exact, |2^k (r + t)| <= 0.42 of it where k != 0: about an ulp. */
MIST__F MIST__HOT double MIST__FN(mist__hexp)(double x, double *om)
{
    const double sh = 6755399441055744.0;
    double kb = x * 1.44269504088896340736 + sh, k, r, q, r2, r4, sc, a, ae;
    uint64_t b, ks;
    memcpy(&ks, &sh, sizeof ks);
    memcpy(&b, &kb, sizeof b);
    b -= ks;                                    /* k, two's complement */
#if defined(MIST_ALLOW_FAST_MATH)   /* kb - sh may be folded to x / ln 2 there */
    k = (double)(int32_t)(uint32_t)(b & 0xffffffffu);
#else                               /* (the guard keeps it: and it vectorises) */
    k = kb - sh;
#endif
    b = (b + 1023u) << 52;
    memcpy(&sc, &b, sizeof b);
    r = (x - k * 6.93147180369123816490e-01) - k * 1.90821492927058770002e-10;
    r2 = r * r;
    r4 = r2 * r2;
#if MIST__DBL
    q = ((0.5 + r * (1.0 / 6.0)) + r2 * (1.0 / 24.0 + r * (1.0 / 120.0)))
        + r4 * (((1.0 / 720.0 + r * (1.0 / 5040.0)) + r2 * (1.0 / 40320.0 + r * (1.0 / 362880.0)))
                + r4 * ((1.0 / 3628800.0 + r * (1.0 / 39916800.0))
                        + r2 * (1.0 / 479001600.0 + r * (1.0 / 6227020800.0))));
#else
    q = ((0.5 + r * (1.0 / 6.0)) + r2 * (1.0 / 24.0 + r * (1.0 / 120.0)))
        + r4 * ((1.0 / 720.0 + r * (1.0 / 5040.0)) + r2 * (1.0 / 40320.0));
#endif
    q = r2 * q;
    *om = (1.0 - sc) - sc * (r + q);
    a = mist__fast_two_sum(1.0, r, &ae);
    return sc * (a + (ae + q));
}

/* The straight path for one ray (see above): returns 1 with tr[] and (ins)
 * ls[], else 0 (the caller takes the scaled path).  *okl: 0 where a phase
 * value is outside the path's range (ls[] then not valid; tr[] is: the
 * transmittance's path must not depend on whether the in-scatter is
 * wanted, so that every entry point gives the same T).  y - yb: the
 * start's height above the base; w in [-1, 1]; s > 0. */
MIST__F MIST__HOT int MIST__FN(mist__hfast)(const MIST__HFK *k, double y, double yb, double w,
                                            double s, double pR, const double *pM, int ins,
                                            double *tr, double *ls, int *okl)
{
    const double lo = 1e-75, hi = 1e75;
    double n, ne, p, pe, f, fe, hh, hl, t, te, z, aw, e, om, col;
    int c, ok, l = 1;
    n = mist__two_sum(y, -yb, &ne);                        /* y - yb */
    p = mist__two_prod_b(w, s < hi ? s : 0.0, &pe);        /* w s; s = inf: 0 */
    f = mist__two_sum(n, p, &fe);
    fe += ne + pe;
    n = w < 0.0 ? f : n;                                   /* the lower end */
    ne = w < 0.0 ? fe : ne;
    n = mist__two_sum(n, ne, &ne);
    hh = n * k->iH;                                        /* (n + ne) / H = hh + hl */
    t = mist__two_prod_b(hh, k->H, &te);
    hl = (((n - t) - te) + ne) * k->iH;
    /* (& and selects, no branch; every division has a safe divisor) */
    ok = (hh >= -700.0) & (hh <= 700.0) & (((s > lo) & (s < hi)) | ((s > hi) & (w > 0.0)));
    hh = ok ? hh : 0.0;
    e = MIST__FN(mist__hexp)(-hh, &om);
    e = k->d0 * (e - e * hl);                              /* e^-(hh + hl) */
    aw = w < 0.0 ? -w : w;
    z = aw * s * k->iH;
    (void)MIST__FN(mist__hexp)(z < 700.0 ? -z : -700.0, &om);   /* 1 - e^-z */
    /* s (1 - e^-z) / z for z < 1, (H (1 - e^-z)) / |w| beyond (z >= 1:
     * w != 0), s at z = 0: one division */
    t = (z < 1.0 ? s : k->H) * om;
    col = t / (z < 1.0 ? (z > 0.0 ? z : 1.0) : aw);
    /* below z = 2^-60 (1 - e^-z) / z is 1 to rounding (and a subnormal z
     * would carry only its few bits) */
    col = e * (z >= 8.6736173798840355e-19 ? col : s);
    ok &= (e >= DBL_MIN) & (e <= DBL_MAX) & (col > lo) & (col < hi);
    for (c = 0; c < 3; ++c) {
        double tau = k->st[c] * col;
        ok &= tau <= 700.0;
#if MIST__DBL   /* (float's sanitised phase values all lie in {0} and (lo, hi)) */
        l &= !ins | (pM[c] == 0.0) | ((pM[c] > lo) & (pM[c] < hi));
#endif
        tr[c] = MIST__FN(mist__hexp)(tau < 700.0 ? -tau : -700.0, &om);
        /* (1 - T) / st = C phi1(tau), phi1(tau) = (1 - T) / tau, below tau =
         * 1: the column itself, tau's rounding cancels in phi1 (the
         * transmittance alone skips it: a division a channel) */
        if (ins) {
            om = om / (tau < 1.0 ? tau : k->st[c]);
            om = tau < 1.0 ? om * col : om;
            ls[c] = (k->a[c] + k->r[c] * pR + k->m[c] * pM[c]) * om;
        }
    }
    *okl = l;
    return ok;
}

/* The straight path's constants of a fog (see THE STRAIGHT PATH): returns
 * whether it qualifies.  st, sR, sM, E, La: as mist__hlayer and the
 * sanitised lights give them. */
MIST__F int MIST__FN(mist__hfk_make)(const MIST__HFOG *fog, MIST__T d0, MIST__T H, const MIST__T *st,
                                     const int *sx, const MIST__T *sR, const MIST__T *sM,
                                     const MIST__T *E, const MIST__T *La, MIST__HFK *k)
{
    const double lo = 1e-75, hi = 1e75;
    int c, ok = !fog->sun_extinction & ((double)d0 > lo) & ((double)d0 < hi) & ((double)H > lo)
                & ((double)H < hi);
    k->H = (double)H; k->iH = 1.0 / (double)H; k->d0 = (double)d0;
    for (c = 0; c < 3; ++c) {
        double e = (double)E[c], l = (double)La[c], r = (double)sR[c], m = (double)sM[c];
        ok &= (sx[c] == 0) & ((double)st[c] > lo) & ((double)st[c] < hi);
#if MIST__DBL   /* (float's sanitised values all lie in {0} and (lo, hi)) */
        ok &= ((e == 0.0) | ((e > lo) & (e < hi))) & ((l == 0.0) | ((l > lo) & (l < hi)))
              & ((r == 0.0) | ((r > lo) & (r < hi))) & ((m == 0.0) | ((m > lo) & (m < hi)));
#endif
        k->st[c] = (double)st[c];
        k->a[c] = l * (double)(sR[c] + sM[c]);
        k->r[c] = e * r;
        k->m[c] = e * m;
    }
    return ok;
}

/* The Mie phase function's density per steradian at u for each channel
 * (p[0..2], mist__hmie; mist__hmie_ptr where a pointer is set): mie_tab's
 * where set (its channels' own where it has 3, else their mean), else
 * mie_prepared's, else mie_phase's.  A Dirac lobe on
 * its peak: +inf counts as the largest finite value (clamped here, before
 * phi1(tau), 1 - T or phi1(z) multiply it; else the factor is lost: 5% at
 * tau = 0.1); NaN as 0. */
MIST__F void MIST__FN(mist__hmie_ptr)(const MIST__HFOG *fog, MIST__T u, MIST__T *p)
{
#ifndef MIST_NO_TAB
    if (fog->mie_tab) {
        int c;     /* (a table not built: isotropic, as mist_tab_eval) */
        p[0] = p[1] = p[2] = MIST__FN(mist__impl_tab_eval)(fog->mie_tab, u, MIST__NULL);
        if (fog->mie_tab->channels == 3 && MIST__FN(mist__tab_ok)(fog->mie_tab))
            (void)MIST__FN(mist__impl_tab_eval)(fog->mie_tab, u, p);
        for (c = 0; c < 3; ++c) p[c] = MIST__FN(mist__pos)(p[c]);
        return;
    }
#endif
    if (fog->mie_prepared) p[0] = MIST__FN(mist__impl_phase_eval)(fog->mie_prepared, u);
    else p[0] = MIST__FN(mist__fog_eval)(&fog->mie_phase, u);
    p[0] = MIST__FN(mist__pos)(p[0]);
    p[1] = p[2] = p[0];
}
/* (both pointers NULL, the common case: mie_phase inline) */
MIST__F MIST__HOT void MIST__FN(mist__hmie_fog)(const MIST__HFOG *fog, MIST__T u, MIST__T *p)
{
    p[0] = MIST__FN(mist__pos)(MIST__FN(mist__fog_eval)(&fog->mie_phase, u));
    p[1] = p[2] = p[0];
}
MIST__F MIST__HOT void MIST__FN(mist__hmie)(const MIST__HFOG *fog, MIST__T u, MIST__T *p)
{
#ifndef MIST_NO_TAB
    if (fog->mie_tab) { MIST__FN(mist__hmie_ptr)(fog, u, p); return; }
#endif
    if (fog->mie_prepared) { MIST__FN(mist__hmie_ptr)(fog, u, p); return; }
    MIST__FN(mist__hmie_fog)(fog, u, p);
}

/* Transmittance and in-scattered radiance of the ray from `origin` along
 * `dir` over `length` (+inf allowed): the background seen through the fog
 * becomes  background * transmittance + inscatter.  Either pointer may be
 * NULL.  See the section comment for the model, the domain and bad input. */
MIST__F void MIST__FN(mist__impl_hfog_eval)(const MIST__HFOG *fog, MIST__V3 origin, MIST__V3 dir,
                                      MIST__T length, MIST__RGB *transmittance,
                                      MIST__RGB *inscatter)
{
    MIST__T tr[3], ls[3], st[3], sR[3], sM[3], E[3], La[3], tk[3];
    int sx[3], keep = 0;
    MIST__T d0 = fog ? MIST__FN(mist__pos)(fog->density) : MIST__C(0);
    MIST__T H = fog ? fog->scale_height : MIST__C(0), w = 0, y = 0, yb = 0;
    MIST__T pR = 0, pM[3] = { 0, 0, 0 }, ly = 0, nu = 0, anu = 0;
    MIST__V3 v;
    MIST__HRAY ray;
    int c, fogged;
    for (c = 0; c < 3; ++c) { tr[c] = MIST__C(1); ls[c] = MIST__C(0); }
    fogged = fog && d0 > MIST__C(0) && H > MIST__C(0) && length > MIST__C(0)
          && MIST__FN(mist__finite)(fog->base)
          && MIST__FN(mist__hup)(fog, origin, dir, &y, &yb, &v, &w);
    if (fogged) {
        E[0]  = fog->sun.r;           E[1]  = fog->sun.g;           E[2]  = fog->sun.b;
        La[0] = fog->ambient.r;       La[1] = fog->ambient.g;       La[2] = fog->ambient.b;
        for (c = 0; c < 3; ++c) {
            MIST__FN(mist__hlayer)(fog, c, &sR[c], &sM[c], &st[c], &sx[c]);
            E[c] = MIST__FN(mist__pos)(E[c]); La[c] = MIST__FN(mist__pos)(La[c]);
        }
        if (inscatter) {
            MIST__V3 l = MIST__FN(mist__unit)(fog->sun_dir);
            MIST__T u = l.x * v.x + l.y * v.y + l.z * v.z;
            pR = MIST__FN(mist__impl_rayleigh_eval)(u);
            MIST__FN(mist__hmie)(fog, u, pM);
            ly = MIST__FN(mist__hvert)(fog, l);
            if (fog->sun_extinction && ly > MIST__C(0)) {   /* nu = 1 - w / ly, exact near 0 */
                nu = (ly - w) / ly;             /* (its sign) */
                anu = ly - w;                   /* |nu| ly: |nu| overflows for a */
                anu = anu < MIST__C(0) ? -anu : anu;    /* subnormal ly */
            }
        }
        {   /* the common case: THE STRAIGHT PATH */
            MIST__HFK k;
            double T[3], L[3] = { 0, 0, 0 }, pm[3];
            for (c = 0; c < 3; ++c) pm[c] = (double)pM[c];
            int okl = 1;
            if (MIST__FN(mist__hfk_make)(fog, d0, H, st, sx, sR, sM, E, La, &k)
                && MIST__FN(mist__hfast)(&k, (double)y, (double)yb, (double)w,
                                         (double)length, (double)pR, pm,
                                         inscatter != MIST__NULL, T, L, &okl)) {
                for (c = 0; c < 3; ++c) { tr[c] = (MIST__T)T[c]; ls[c] = (MIST__T)L[c]; }
                if (okl) goto out;
                keep = 1;           /* T from here, the in-scatter by the scaled path */
                for (c = 0; c < 3; ++c) tk[c] = tr[c];
            }
        }
        ray = MIST__FN(mist__hray_eval)(y, w, MIST__C(0), length, yb, H, d0);
        for (c = 0; c < 3; ++c) {
            MIST__T tau, omt, f1, src = sR[c] + sM[c];
            /* the exponents of the scaled column and densities, with the
             * coefficients' 2^sx (mist__hlayer) */
            int ce = ray.ce + sx[c], r0e = ray.r0e + sx[c], r1e = ray.r1e + sx[c];
            if (!(st[c] > MIST__C(0)) || !(ray.cm > MIST__C(0))) continue;
            /* st col, scaled: right where the column alone overflows (a
             * subnormal extinction through a huge density) */
            tau = MIST__FN(mist__hmul)(st[c], MIST__C(1), MIST__C(1), MIST__C(1), ray.cm, ce,
                                       MIST__C(0));
            tr[c] = MIST__M(exp)(-tau);
            if (!inscatter) continue;
            /* st int_0^s rho e^-tau(t) dt = 1 - T = tau phi1(tau).  Each
             * term is one scaled product (mist__expmul, mist__hmul), so
             * that neither a large radiance nor a column or a ratio beyond
             * the range loses what the product keeps: for tau < 1 the
             * column itself enters (no division by st), beyond it the
             * albedo ss/st. */
            omt = -MIST__FN(mist__expm1)(-tau);
            f1 = tau < MIST__C(1) ? MIST__FN(mist__phi1)(tau) : MIST__C(0);
            if (tau < MIST__C(1)) {
                ls[c] = MIST__FN(mist__hmul)(La[c], src, f1, MIST__C(1), ray.cm, ce, MIST__C(0));
                if (!fog->sun_extinction)
                    ls[c] += MIST__FN(mist__hmul)(E[c], sR[c], pR * f1, MIST__C(1), ray.cm, ce, MIST__C(0))
                           + MIST__FN(mist__hmul)(E[c], sM[c], pM[c] * f1, MIST__C(1), ray.cm, ce, MIST__C(0));
            } else {
                ls[c] = MIST__FN(mist__expmul)(La[c], src, omt, MIST__C(1), st[c], MIST__C(0), MIST__C(0));
                if (!fog->sun_extinction)
                    ls[c] += MIST__FN(mist__expmul)(E[c], sR[c], pR * omt, MIST__C(1), st[c], MIST__C(0), MIST__C(0))
                           + MIST__FN(mist__expmul)(E[c], sM[c], pM[c] * omt, MIST__C(1), st[c], MIST__C(0), MIST__C(0));
            }
            if (fog->sun_extinction && ly > MIST__C(0)) {
                /* Sun dimmed by the column above each point, rho H / ly:
                 * int rho e^-(tau(t) + st rho(t) H/ly) dt
                 *   = e^-min(A0, A1) col phi1(tau |nu|),  nu = 1 - w/ly,
                 * A0, A1 the sun's optical depth to the start and (plus tau)
                 * to the end (e^-A enters expmul as its exponent).  See the
                 * section comment.  A sun at or below the horizon: none. */
                /* z = tau |nu| = st col |ly - w| / ly, scaled (found by the
                 * stress test: ly = 2^-149 overflowed |nu|, tau*inf) */
                MIST__T a, z = MIST__FN(mist__hmul)(st[c], anu, MIST__C(1), ly, ray.cm, ce, MIST__C(0));
                a = MIST__FN(mist__hsun)(st[c], H, ly, ray.r0m, r0e);               /* A0 */
                if (nu < MIST__C(0))                                                /* A1 */
                    a = tau + MIST__FN(mist__hsun)(st[c], H, ly, ray.r1m, r1e);
                if (a < (MIST__T)INFINITY) {
                    if (z < MIST__C(1)) {
                        MIST__T fz = MIST__FN(mist__phi1)(z);
                        ls[c] += MIST__FN(mist__hmul)(E[c], sR[c], pR * fz, MIST__C(1), ray.cm, ce, a)
                               + MIST__FN(mist__hmul)(E[c], sM[c], pM[c] * fz, MIST__C(1), ray.cm, ce, a);
                    } else {
                        /* 1/|nu| = ly/|ly - w|, ly scaled (mist__hly) */
                        int kl;
                        MIST__T oz = -MIST__FN(mist__expm1)(-z);
                        MIST__T inu = MIST__FN(mist__hly)(ly, &kl) / anu;
                        ls[c] += MIST__FN(mist__expmul_k)(E[c], sR[c], pR * oz, inu, st[c], a,
                                                          MIST__C(0), kl)
                               + MIST__FN(mist__expmul_k)(E[c], sM[c], pM[c] * oz, inu, st[c], a,
                                                          MIST__C(0), kl);
                    }
                }
            }
        }
    }
out:
    if (keep) for (c = 0; c < 3; ++c) tr[c] = tk[c];
    if (transmittance) { transmittance->r = tr[0]; transmittance->g = tr[1]; transmittance->b = tr[2]; }
    if (inscatter) { inscatter->r = ls[0]; inscatter->g = ls[1]; inscatter->b = ls[2]; }
}

/* Transmittance alone (per colour band).  Domain: as mist_hfog_eval (and
 * the two below). */
MIST__F MIST__RGB MIST__FN(mist__impl_hfog_transmittance)(const MIST__HFOG *fog, MIST__V3 origin,
                                                    MIST__V3 dir, MIST__T length)
{
    MIST__RGB t;
    MIST__FN(mist__impl_hfog_eval)(fog, origin, dir, length, &t, MIST__NULL);
    return t;
}

/* In-scattered radiance alone. */
MIST__F MIST__RGB MIST__FN(mist__impl_hfog_inscatter)(const MIST__HFOG *fog, MIST__V3 origin,
                                                MIST__V3 dir, MIST__T length)
{
    MIST__RGB l;
    MIST__FN(mist__impl_hfog_eval)(fog, origin, dir, length, MIST__NULL, &l);
    return l;
}

/* background * transmittance + inscatter: the radiance that reaches
 * `origin` from a surface at `length` along `dir` (+inf: the sky) of
 * radiance `background`. */
MIST__F MIST__RGB MIST__FN(mist__impl_hfog_apply)(const MIST__HFOG *fog, MIST__V3 origin,
                                            MIST__V3 dir, MIST__T length, MIST__RGB background)
{
    MIST__RGB t, l;
    MIST__FN(mist__impl_hfog_eval)(fog, origin, dir, length, &t, &l);
    l.r += background.r * t.r;
    l.g += background.g * t.g;
    l.b += background.b * t.b;
    return l;
}

#ifndef MIST_NO_BATCH
/* One ray's inputs to the straight path as mist__impl_hfog_eval takes
 * them (element j of the block's arrays); plain: the fog's up is all zero
 * and both phase pointers NULL (mist__hup's and mist__hmie's first tests,
 * known). */
MIST__F MIST__HOT void MIST__FN(mist__hprep)(const MIST__HFOG *fog, int plain, MIST__V3 l,
                                             MIST__V3 o, MIST__V3 d, MIST__T len, size_t j,
                                             int *ok, double *y, double *yb, double *w,
                                             double *s, double *pR, double (*pM)[32])
{
    MIST__V3 v;
    MIST__T u, yj, ybj, wj, p3[3];
    int c;
    if (plain) ok[j] = MIST__FN(mist__hup_y)(fog, o, d, &yj, &ybj, &v, &wj);
    else ok[j] = MIST__FN(mist__hup)(fog, o, d, &yj, &ybj, &v, &wj);
    ok[j] &= len > MIST__C(0);
    u = l.x * v.x + l.y * v.y + l.z * v.z;
    y[j] = (double)yj; yb[j] = (double)ybj; w[j] = (double)wj;
    s[j] = (double)len;
    pR[j] = (double)MIST__FN(mist__impl_rayleigh_eval)(u);
    if (plain) MIST__FN(mist__hmie_fog)(fog, u, p3);
    else MIST__FN(mist__hmie)(fog, u, p3);
    for (c = 0; c < 3; ++c) pM[c][j] = (double)p3[c];
}

/* mist_hfog_apply of each ray i < n: origin[i], dir[i], length[i],
 * background[i] -> out[i], bit for bit (out may equal background; n = 0
 * does nothing).  The fog is sanitised once; in blocks of 32, each ray's
 * direction, cosine to the sun and phase values as mist__impl_hfog_eval
 * takes them (a scalar loop), then THE STRAIGHT PATH over the block (a
 * branch-free loop: vectorised), and the scalar function for a ray it
 * does not take (and for every ray of a fog it does not take). */
MIST__F void MIST__FN(mist__impl_hfog_apply_n)(const MIST__HFOG *fog, const MIST__V3 *origin,
                                               const MIST__V3 *dir, const MIST__T *length,
                                               const MIST__RGB *background, MIST__RGB *out,
                                               size_t n)
{
    MIST__T st[3], sR[3], sM[3], E[3], La[3], d0 = 0, H = 0;
    double tr[3][32], ls[3][32], y[32], yb[32], w[32], s[32], pR[32], pM[3][32];
    int sx[3], ok[32], c, fast, plain = 0;
    MIST__HFK k;
    MIST__V3 l = { 0, 0, 1 };
    size_t i0, i;
    if (n == 0) return;
    memset(&k, 0, sizeof k);
    fast = fog != MIST__NULL;
    if (fast) {
        d0 = MIST__FN(mist__pos)(fog->density); H = fog->scale_height;
        E[0]  = fog->sun.r;           E[1]  = fog->sun.g;           E[2]  = fog->sun.b;
        La[0] = fog->ambient.r;       La[1] = fog->ambient.g;       La[2] = fog->ambient.b;
        for (c = 0; c < 3; ++c) {
            MIST__FN(mist__hlayer)(fog, c, &sR[c], &sM[c], &st[c], &sx[c]);
            E[c] = MIST__FN(mist__pos)(E[c]); La[c] = MIST__FN(mist__pos)(La[c]);
        }
        fast = d0 > MIST__C(0) && H > MIST__C(0) && MIST__FN(mist__finite)(fog->base)
            && MIST__FN(mist__hfk_make)(fog, d0, H, st, sx, sR, sM, E, La, &k);
        l = MIST__FN(mist__unit)(fog->sun_dir);
        plain = MIST__FN(mist__hyup)(fog) & (fog->mie_prepared == MIST__NULL);
#ifndef MIST_NO_TAB
        plain &= fog->mie_tab == MIST__NULL;
#endif
    }
    if (!fast) {
        for (i = 0; i < n; ++i)
            out[i] = MIST__FN(mist__impl_hfog_apply)(fog, origin[i], dir[i], length[i], background[i]);
        return;
    }
    for (i0 = 0; i0 < n; i0 += 32) {
        size_t m = n - i0 < 32 ? n - i0 : 32, j;
        /* (the common fog, y up and mie_phase, a loop of its own: the
         * tests once a call) */
        if (plain)
            for (j = 0; j < m; ++j)
                MIST__FN(mist__hprep)(fog, 1, l, origin[i0 + j], dir[i0 + j], length[i0 + j], j,
                                      ok, y, yb, w, s, pR, pM);
        else
            for (j = 0; j < m; ++j)
                MIST__FN(mist__hprep)(fog, 0, l, origin[i0 + j], dir[i0 + j], length[i0 + j], j,
                                      ok, y, yb, w, s, pR, pM);
        for (; j < 32; ++j) {
            y[j] = yb[j] = w[j] = pR[j] = 0; s[j] = 1; ok[j] = 0;
            for (c = 0; c < 3; ++c) pM[c][j] = 0;
        }
        for (j = 0; j < 32; ++j) {          /* THE STRAIGHT PATH: vectorised */
            double pm[3], t3[3], l3[3];
            for (c = 0; c < 3; ++c) pm[c] = pM[c][j];
            int okl;
            ok[j] &= MIST__FN(mist__hfast)(&k, y[j], yb[j], w[j], s[j], pR[j], pm, 1, t3, l3, &okl);
            ok[j] &= okl;
            for (c = 0; c < 3; ++c) { tr[c][j] = t3[c]; ls[c][j] = l3[c]; }
        }
        for (j = 0; j < m; ++j) {
            i = i0 + j;
            if (ok[j]) {
                MIST__RGB b = background[i], r;
                r.r = (MIST__T)ls[0][j]; r.g = (MIST__T)ls[1][j]; r.b = (MIST__T)ls[2][j];
                r.r += b.r * (MIST__T)tr[0][j];
                r.g += b.g * (MIST__T)tr[1][j];
                r.b += b.b * (MIST__T)tr[2][j];
                out[i] = r;
            } else
                out[i] = MIST__FN(mist__impl_hfog_apply)(fog, origin[i], dir[i], length[i], background[i]);
        }
    }
}
#endif

/* ------------------------------------------------------------------------ */
/* Path tracing: extinction, optical depth, free-flight distances           */
/* ------------------------------------------------------------------------ */

/* (y - yb) / H as hi + *lo for finite H > 0, exact to ~eps^2 of the
 * quotient (as mist__hray_eval's start: the difference error-free, the
 * numerator and H scaled by 2^(2 mant) for a tiny H, mist__ddiv); where
 * even that overflows, the plain quotient (then beyond every exponent's
 * range: *lo = 0). */
MIST__F MIST__T MIST__FN(mist__hquot)(MIST__T y, MIST__T yb, MIST__T H, MIST__T *lo)
{
    const MIST__T up = MIST__C(1) / (MIST__EPS * MIST__EPS);
    MIST__T n, ne, q;
    n = MIST__FN(mist__two_sum)(y, -yb, &ne);
    if (H >= MIST__TMIN * up && H <= MIST__BIG && MIST__FN(mist__finite)(n)) {
        /* one division: q = n (1/H) within 2 ulps, the remainder exact
         * (two_prod; n - p by Sterbenz), so hi + lo is as exact */
        MIST__T ih = MIST__C(1) / H, p, pe;
        q = n * ih;
        p = MIST__FN(mist__two_prod)(q, H, &pe);
        *lo = (((n - p) - pe) + ne) * ih;
        if (MIST__FN(mist__finite)(q) && MIST__FN(mist__finite)(*lo)) return q;
    }
    if (H < MIST__TMIN * up) { n *= up; ne *= up; H *= up; }
    *lo = MIST__C(0);
    if (!(MIST__FN(mist__finite)(n) && MIST__FN(mist__finite)(ne)))
        return (MIST__C(0.5) * y - MIST__C(0.5) * yb) / (MIST__C(0.5) * H);
    q = MIST__FN(mist__ddiv)(n, ne, H, lo);
    if (!(MIST__FN(mist__finite)(q) && MIST__FN(mist__finite)(*lo))) *lo = MIST__C(0);
    return q;
}

/* The extinction coefficient per channel at the point p: each channel's
 * st = Rayleigh + Mie extinction times density e^(-(height - base)/H).
 * Domain: as mist_hfog_eval's fog (no fog: 0); a value beyond the range
 * is +inf. */
MIST__F MIST__RGB MIST__FN(mist__impl_hfog_extinction)(const MIST__HFOG *fog, MIST__V3 p)
{
    MIST__T e[3] = { 0, 0, 0 }, sR, sM, st, y, yb, hh = 0, hl = 0, an;
    MIST__V3 a;
    MIST__RGB r;
    int c, sx;
    if (fog && MIST__FN(mist__hlayer)(fog, 0, &sR, &sM, &st, &sx)) {
        MIST__T d0 = MIST__FN(mist__pos)(fog->density), H = fog->scale_height;
        (void)MIST__FN(mist__hheight)(fog, p, &y, &yb, &a, &an);
        if (MIST__FN(mist__finite)(y) && MIST__FN(mist__finite)(yb)) {
            if (H <= MIST__BIG) hh = MIST__FN(mist__hquot)(y, yb, H, &hl);
            for (c = 0; c < 3; ++c) {
                MIST__FN(mist__hlayer)(fog, c, &sR, &sM, &st, &sx);
                if (st > MIST__C(0))
                    e[c] = MIST__FN(mist__expmul_k)(st, d0, MIST__C(1), MIST__C(1), MIST__C(1),
                                                    hh, hl, sx);
            }
        }
    }
    r.r = e[0]; r.g = e[1]; r.b = e[2];
    return r;
}

/* The optical depth per channel from origin to origin + t dir / |dir|
 * (t in [0, +inf]): st C(t), as mist_hfog_transmittance's exponent.
 * Domain: as mist_hfog_eval (no fog, t NaN or <= 0: 0); +inf where the
 * depth is (a ray to infinity level or down). */
MIST__F MIST__RGB MIST__FN(mist__impl_hfog_optical_depth)(const MIST__HFOG *fog, MIST__V3 origin,
                                                         MIST__V3 dir, MIST__T t)
{
    MIST__T tau[3] = { 0, 0, 0 }, sR, sM, st, y, yb, w;
    MIST__T d0 = fog ? MIST__FN(mist__pos)(fog->density) : MIST__C(0);
    MIST__T H = fog ? fog->scale_height : MIST__C(0);
    MIST__V3 v;
    MIST__RGB r;
    int c, sx;
    if (fog && d0 > MIST__C(0) && H > MIST__C(0) && t > MIST__C(0)
        && MIST__FN(mist__finite)(fog->base)
        && MIST__FN(mist__hup)(fog, origin, dir, &y, &yb, &v, &w)) {
        MIST__HRAY ray = MIST__FN(mist__hray_eval)(y, w, MIST__C(0), t, yb, H, d0);
        for (c = 0; c < 3; ++c) {
            MIST__FN(mist__hlayer)(fog, c, &sR, &sM, &st, &sx);
            if (st > MIST__C(0) && ray.cm > MIST__C(0))
                tau[c] = MIST__FN(mist__hmul)(st, MIST__C(1), MIST__C(1), MIST__C(1), ray.cm,
                                              ray.ce + sx, MIST__C(0));
        }
    }
    r.r = tau[0]; r.g = tau[1]; r.b = tau[2];
    return r;
}

/* A free-flight distance for channel c: the t with 1 - e^-tau_c(t) = xi,
 * or +inf where there is none in [0, tmax].  See the section comment
 * (FREE-FLIGHT DISTANCES) for the inversion and its bound. */
MIST__F MIST__T MIST__FN(mist__impl_hfog_sample_distance)(const MIST__HFOG *fog, MIST__V3 origin,
                                                         MIST__V3 dir, MIST__T tmax, int channel,
                                                         MIST__T xi)
{
    const MIST__T ln2 = MIST__C(0.693147180559945309417232121458176568);
    MIST__T sR, sM, st, y, yb, w, T, q, mK, t, H, hh = 0, hl = 0;
    MIST__V3 v;
    int sx, ks, kd, kK;
    if (!fog || channel < 0 || channel > 2 || !(tmax > MIST__C(0))
        || !MIST__FN(mist__hlayer)(fog, channel, &sR, &sM, &st, &sx) || !(st > MIST__C(0))
        || !MIST__FN(mist__hup)(fog, origin, dir, &y, &yb, &v, &w))
        return (MIST__T)INFINITY;
    xi = MIST__FN(mist__pos)(xi);                    /* NaN, <= 0: 0 */
    if (xi == MIST__C(0)) return MIST__C(0);
    if (!(xi < MIST__C(1))) return (MIST__T)INFINITY;
    T = -MIST__FN(mist__log1p)(-xi);                        /* the depth to reach */
    H = fog->scale_height;
    if (H <= MIST__BIG) hh = MIST__FN(mist__hquot)(y, yb, H, &hl);
    else w = MIST__C(0);                             /* uniform: as level */
    {   /* the common case, every intermediate normal: the same steps as
         * below in plain arithmetic (the scaled products' results agree
         * to rounding) */
        const MIST__T tmin = MIST__TMIN;
        MIST__T c = st * MIST__FN(mist__pos)(fog->density), aw = w < MIST__C(0) ? -w : w, a, z;
        if (hh < MIST__XLIM && hh > -MIST__XLIM && sx == 0 && c >= tmin && c <= MIST__BIG) {
            MIST__T p = T * (MIST__M(exp)(hh) * (MIST__C(1) + hl));
            mK = p / c;
            if (p >= tmin && p <= MIST__BIG && mK >= tmin && mK <= MIST__BIG) {
                if (w == MIST__C(0)) return mK <= tmax ? mK : (MIST__T)INFINITY;
                a = aw / H;
                z = mK * a;
                if (a >= tmin && a <= MIST__BIG && z >= tmin && z <= MIST__BIG) {
                    if (z < MIST__C(8.6736173798840354720596224069595336914e-19))   /* 2^-60 */
                        t = z / a;
                    else if (w > MIST__C(0)) {
                        if (!(z < MIST__C(1))) return (MIST__T)INFINITY;
                        t = -MIST__FN(mist__log1p)(-z) / a;
                    } else t = MIST__FN(mist__log1p)(z) / a;
                    return t <= tmax ? t : (MIST__T)INFINITY;
                }
            }
        }
    }
    /* K = T e^h / (st density) = mK 2^kK: the distance at the start's
     * density, one scaled product (nothing leaves the range before it) */
    q = MIST__FN(mist__frexp)(st, &ks)
      * MIST__FN(mist__frexp)(MIST__FN(mist__pos)(fog->density), &kd);
    mK = MIST__FN(mist__expmul_s)(T, MIST__C(1), MIST__C(1), MIST__C(1), q, -hh, -hl,
                                  -(ks + kd + sx), &kK);
    if (mK == MIST__C(0)) return MIST__C(0);         /* K < e^(-64 XLIM): t rounds to 0 */
    if (w == MIST__C(0)) {                           /* level: t = K */
        if (!(mK <= MIST__BIG)) return (MIST__T)INFINITY;
        t = MIST__FN(mist__ldexp)(mK, kK);
    } else {
        /* a = |w| / H = ma 2^ka, z = a K = zm 2^kz; t = -log1p(-z)/a up,
         * log1p(z)/a down */
        int kw, kH, ka, kz, j;
        MIST__T aw = w < MIST__C(0) ? -w : w;
        MIST__T ma = MIST__FN(mist__frexp)(aw, &kw) / MIST__FN(mist__frexp)(H, &kH), zm;
        ka = kw - kH;
        if (!(mK <= MIST__BIG)) {                    /* K > e^(64 XLIM) */
            /* up: z >> 1, no collision.  Down: t = H ln(z) / |w|
             * = (y - yb) / |w| + (H / |w|) ln A,  A = |w| T / (H st density),
             * |ln A| < 64 XLIM / 10 against ln z: no cancellation; H / |w|
             * = 2^-ka / ma, scaled (H ln A alone may be subnormal) */
            MIST__T mA, lnA, n, ne;
            int kT;
            if (w > MIST__C(0)) return (MIST__T)INFINITY;
            mA = MIST__FN(mist__frexp)(T, &kT) * ma / q;
            lnA = MIST__M(log)(mA) + (MIST__T)(kT + ka - ks - kd - sx) * ln2;
            n = MIST__FN(mist__two_sum)(y, -yb, &ne);
            t = n / aw + (MIST__FN(mist__ldexp)(lnA / ma, -ka) + ne / aw);
        } else {
            zm = MIST__FN(mist__frexp)(mK * ma, &j);
            kz = kK + ka + j;
            if (kz < -(MIST__MB + 8)) {
                /* z < 2^-(mant + 9): log1p(-+z) rounds to -+z, t = z / a */
                t = MIST__FN(mist__ldexp)(zm / ma, kz - ka);
            } else if (w > MIST__C(0)) {
                if (kz >= 1) return (MIST__T)INFINITY;   /* z >= 1: it escapes */
                t = MIST__FN(mist__ldexp)(-MIST__FN(mist__log1p)(-MIST__FN(mist__ldexp)(zm, kz)) / ma, -ka);
            } else if (kz < (MIST__EB >> 1) - 8) {
                t = MIST__FN(mist__ldexp)(MIST__FN(mist__log1p)(MIST__FN(mist__ldexp)(zm, kz)) / ma, -ka);
            } else {                                  /* log1p(z) = ln z to < eps^2 */
                t = MIST__FN(mist__ldexp)((MIST__M(log)(zm) + (MIST__T)kz * ln2) / ma, -ka);
            }
        }
    }
    return t <= tmax ? t : (MIST__T)INFINITY;
}

/* ------------------------------------------------------------------------ */
/* Several layers (different scale heights)                                 */
/* ------------------------------------------------------------------------ */

/* ln(st_k rho_k(yy) / (st_i rho_i(yy))) for channel c, written so that
 * layers with one scale height give the small difference of their bases
 * exactly: (yy - b_k)/H_k - (yy - b_i)/H_i = (yy - b_k)(1/H_k - 1/H_i)
 * + (b_i - b_k)/H_i.  *err (if not NULL): a bound on the rounding error
 * of the result (absolute: each operation's half ulp of the magnitudes it
 * meets, twice over; the height's term only where the scale heights
 * differ, as x), so e^result is known to relative *err. */
MIST__F MIST__T MIST__FN(mist__lrel)(const MIST__HFOG *ls, MIST__T (*st)[3], int (*sx)[3],
                                     const MIST__T *H, const MIST__T *lnd, int k, int i, int c,
                                     MIST__T yy, MIST__T *err)
{
    const MIST__T tmin = MIST__TMIN;
    MIST__T ik = H[k] <= MIST__BIG ? MIST__FN(mist__pos)(MIST__C(1) / H[k]) : MIST__C(0);
    MIST__T ii = H[i] <= MIST__BIG ? MIST__FN(mist__pos)(MIST__C(1) / H[i]) : MIST__C(0), x, lr, q, r;
    x = ik == ii ? MIST__C(0) : (yy - ls[k].base) * (ik - ii);
    if (ii != MIST__C(0)) x += (ls[i].base - ls[k].base) * ii;
    q = st[k][c] / st[i][c];                 /* the ratio where it is normal */
    lr = q >= tmin && q <= MIST__BIG ? MIST__M(log)(q)
                                     : MIST__M(log)(st[k][c]) - MIST__M(log)(st[i][c]);
    if (sx[k][c] != sx[i][c]) lr += (MIST__T)(sx[k][c] - sx[i][c]) * MIST__C(0.693147180559945309);
    r = lr + (lnd[k] - lnd[i]) - x;
    if (err) {
        MIST__T bk = MIST__M(fabs)(ls[k].base), bi = MIST__M(fabs)(ls[i].base);
        *err = MIST__C(4) * MIST__EPS
             * (MIST__C(2) + MIST__M(fabs)(r) + MIST__M(fabs)(lr) + MIST__M(fabs)(MIST__M(log)(st[k][c]))
                + MIST__M(fabs)(MIST__M(log)(st[i][c])) + MIST__M(fabs)(lnd[k])
                + MIST__M(fabs)(lnd[i]) + (ik == ii ? MIST__C(0) : (MIST__M(fabs)(yy) + bk) * (ik + ii))
                + (bi + bk) * ii);
    }
    return r;
}

#ifndef MIST_HFOG_MAX_LAYERS
#  define MIST_HFOG_MAX_LAYERS 8
#endif

/* A layer's extinction st rho at the start of its segment g, times 2^sx,
 * scaled: r 2^*k (r in [1/2, 1), or 0), +inf where the density is beyond
 * even that (mist__expmul_s). */
MIST__F MIST__T MIST__FN(mist__hstart)(MIST__T st, const MIST__HRAY *g, int sx, int *k)
{
    *k = 0;
    if (!(g->r0m <= MIST__BIG)) return (MIST__T)INFINITY;
    return MIST__FN(mist__expmul_s)(st, g->r0m, MIST__C(1), MIST__C(1), MIST__C(1), MIST__C(0),
                                    MIST__C(0), g->r0e + sx, k);
}

/* The weight-aware bound on a piece (see the section comment, "THE
 * WEIGHT"): for the rates r = 1 (e^-tau) and r = nu (e^-nu tau, the dimmed
 * sun; nu <= 0: none), an upper bound on  int_0^S |F'(u)| e^(-r tau(u))/r du
 * over (c_max - c_min), from a grid 0 = u_0 < u_1 < ... in u (the distance
 * along the piece) at optical depths about doubling.  e0[k]: layer k's
 * extinction at the piece start (0: not used), b[k] = -w / H_k its rate,
 * D = max b - min b.  On [u_m, u_m+1], e = sum e_k is monotone (all b_k of
 * one sign), 1 - f_i = (others)/e (f_i the share of the layer densest at
 * the start) is largest at an end (others/e_i is a sum of exponentials:
 * convex), and |F'| <= (c_max - c_min) D min(1/4, 1 - f_i), so the interval
 * adds the smaller of
 *   (a) D min(1/4, max_ends(1 - f_i)) (e^(-r tau_m) - e^(-r tau_m+1)) / (r^2 e_lo),
 *   (b) D R_m e^(-r tau_m) h E((D - r e_lo) h) / r,  E(z) = (e^z - 1)/z,
 *       R_m = others/e_i at u_m (1 - f_i <= R_m e^(D (u - u_m))) and
 *       tau >= tau_m + e_lo (u - u_m), e_lo the smaller end's e, h = u_m+1 - u_m;
 * beyond the last point (|F - F(u_M)| <= c_max - c_min) e^(-r tau_M)/r.
 * +inf where a start extinction is outside the normal range.  */
MIST__F void MIST__FN(mist__hwbound)(int n, const MIST__T *e0, const MIST__T *b, MIST__T S,
                                     MIST__T D, MIST__T nu, MIST__T *ja, MIST__T *js)
{
    const MIST__T tend = MIST__C(4) - MIST__M(log)(MIST__EPS);
    MIST__T e = MIST__C(0), o = MIST__C(0), ei, tau = MIST__C(0), u = MIST__C(0), t, tg;
    MIST__T rl = MIST__C(1), rh = MIST__C(1), acc[2];
    int k, i = -1, m, last = 0, q, nr = nu > MIST__C(0) ? 2 : 1;
    *ja = *js = (MIST__T)INFINITY;
    for (k = 0; k < n; ++k) {
        if (e0[k] == MIST__C(0)) continue;
        if (!(e0[k] >= MIST__TMIN && e0[k] <= MIST__BIG)) return;
        if (i < 0 || e0[k] > e0[i]) i = k;
        e += e0[k];
    }
    if (i < 0 || !(e <= MIST__BIG) || !(D >= MIST__C(0))) return;
    for (k = 0; k < n; ++k) if (k != i) o += e0[k];
    ei = e0[i];
    if (nr == 2) { if (nu < rl) rl = nu; else rh = nu; }
    acc[0] = acc[1] = MIST__C(0);
    tg = MIST__C(0.25) / rh;
    for (m = 0; m < 24; ++m) {
        MIST__T un = u + (tg - tau) / e, en = MIST__C(0), on = MIST__C(0), ein = MIST__C(0);
        MIST__T tn = MIST__C(0), elo, fmx, f2, h;
        if (!(un < S)) { un = S; last = 1; }
        if (!(un <= MIST__BIG)) { last = 0; break; }
        for (k = 0; k < n; ++k) {
            MIST__T x, r;
            if (e0[k] == MIST__C(0)) continue;
            x = b[k] * un;
            r = e0[k] * MIST__M(exp)(x);
            en += r;
            tn += e0[k] * un * (x == MIST__C(0) ? MIST__C(1) : MIST__FN(mist__expm1)(x) / x);
            if (k == i) ein = r; else on += r;
        }
        elo = en < e ? en : e;
        fmx = o / e;
        f2 = on / en;
        if (!(f2 <= MIST__C(1))) f2 = MIST__C(1);
        if (f2 > fmx) fmx = f2;
        if (fmx > MIST__C(0.25)) fmx = MIST__C(0.25);
        h = un - u;
        for (q = 0; q < nr; ++q) {
            MIST__T r = q ? nu : MIST__C(1), ga = MIST__M(exp)(-r * tau), gb = MIST__M(exp)(-r * tn);
            MIST__T a = elo > MIST__C(0) ? D * fmx * (ga - gb) / (r * r * elo) : (MIST__T)INFINITY;
            MIST__T z = (D - r * elo) * h, bb;
            if (!(gb <= ga)) a = D * fmx * ga / (r * r * elo);
            bb = z == MIST__C(0) ? MIST__C(1) : MIST__FN(mist__expm1)(z) / z;
            bb = D * (o / ei) * ga * h * bb / r;
            if (!(bb >= MIST__C(0))) bb = (MIST__T)INFINITY;
            if (!(a >= MIST__C(0))) a = (MIST__T)INFINITY;
            acc[q] += a < bb ? a : bb;
        }
        u = un; tau = tn; e = en; o = on; ei = ein;
        if (last || !(tau < tend / rl)) break;
        t = tg + tg;
        tg = t > tau + tau ? t : tau + tau;
    }
    if (!last)
        for (q = 0; q < nr; ++q) {
            MIST__T r = q ? nu : MIST__C(1);
            acc[q] += MIST__M(exp)(-r * tau) / r;
        }
    for (q = 0; q < nr; ++q)
        if (acc[q] >= MIST__C(0)) *(q ? js : ja) = acc[q] * (MIST__C(1) + MIST__C(64) * MIST__EPS);
}

/* Several exponential layers along one ray: see the section comment.
 * Domain: n >= 1 layers (layers NULL or n < 1: transmittance 1, in-scatter
 * and bound 0), each as mist_hfog_eval's fog.  Layer k contributes its own
 * coefficients, scale height and Mie phase function; the lights (sun, ambient, sun_extinction) are those of
 * layers[0].  At most MIST_HFOG_MAX_LAYERS layers are used.  `pieces` is
 * the number of pieces the ray is cut into for the in-scatter (<= 0: 8; at
 * most 64).  The transmittance is exact (closed form); the in-scatter is
 * within *bound of the exact value (per channel, rounding included); any
 * output pointer may be NULL. */
MIST__F void MIST__FN(mist__impl_hfog_layers_eval)(const MIST__HFOG *layers, int n, MIST__V3 origin,
                                             MIST__V3 dir, MIST__T length, int pieces,
                                             MIST__RGB *transmittance, MIST__RGB *inscatter,
                                             MIST__RGB *bound)
{
    MIST__T st[MIST_HFOG_MAX_LAYERS][3], sR[MIST_HFOG_MAX_LAYERS][3], sM[MIST_HFOG_MAX_LAYERS][3];
    MIST__T H[MIST_HFOG_MAX_LAYERS], d0[MIST_HFOG_MAX_LAYERS], pM[MIST_HFOG_MAX_LAYERS][3];
    MIST__T lnd[MIST_HFOG_MAX_LAYERS];
    int sx[MIST_HFOG_MAX_LAYERS][3];
    MIST__HRAY seg[MIST_HFOG_MAX_LAYERS];
    MIST__T tau[3], tr[3], ls[3], bd[3], E[3], La[3], tb[65];
    MIST__T w = 0, y = origin.y, s = length, pR = 0, ly = 0, anu = 0;
    int ok[MIST_HFOG_MAX_LAYERS], k, i, c, j, np = 0, cs = 0, same = 1, sunx = 0, any = 0;
    int lx[3] = { 0, 0, 0 };
    MIST__V3 v;
    for (c = 0; c < 3; ++c) { tau[c] = MIST__C(0); tr[c] = MIST__C(1); ls[c] = bd[c] = MIST__C(0); }
    if (!layers || n < 1 || !(s > MIST__C(0))) goto out;
    {   /* the height along layers[0]'s axis, rounded once; w as mist__hup */
        MIST__V3 a;
        MIST__T yb, lo;
        v = MIST__FN(mist__unit)(dir);
        w = v.y < MIST__C(-1) ? MIST__C(-1) : (v.y > MIST__C(1) ? MIST__C(1) : v.y);
        if (MIST__FN(mist__haxis)(&layers[0], &a)) {
            (void)MIST__FN(mist__hup)(&layers[0], origin, dir, &y, &yb, &v, &w);
            y = MIST__FN(mist__dot2)(origin, a, &lo);
        }
        if (!MIST__FN(mist__finite)(y)) goto out;
    }
    if (n > MIST_HFOG_MAX_LAYERS) n = MIST_HFOG_MAX_LAYERS;
    for (k = 0; k < n; ++k) {
        for (c = 0; c < 3; ++c)
            ok[k] = MIST__FN(mist__hlayer)(&layers[k], c, &sR[k][c], &sM[k][c], &st[k][c],
                                           &sx[k][c]);
        H[k] = layers[k].scale_height;
        d0[k] = MIST__FN(mist__pos)(layers[k].density);
        memset(&seg[k], 0, sizeof seg[k]);   /* (both read only where ok[k]: */
        lnd[k] = MIST__C(0);                 /* gcc 12 -O3 -Wall could not tell) */
        if (!ok[k]) continue;
        lnd[k] = MIST__M(log)(d0[k]);
        if (H[k] != H[0]) same = 0;
        seg[k] = MIST__FN(mist__hray_eval)(y, w, MIST__C(0), s, layers[k].base, H[k], d0[k]);
        for (c = 0; c < 3; ++c)
            if (st[k][c] > MIST__C(0) && seg[k].cm > MIST__C(0)) {  /* scaled: as mist_hfog_eval */
                tau[c] += MIST__FN(mist__hmul)(st[k][c], MIST__C(1), MIST__C(1), MIST__C(1),
                                               seg[k].cm, seg[k].ce + sx[k][c], MIST__C(0));
                any = 1;       /* (tau may underflow where the in-scatter does not) */
            }
    }
    for (c = 0; c < 3; ++c) tr[c] = MIST__M(exp)(-tau[c]);
    if (!inscatter && !bound) goto out;
    for (c = 1; c < 3; ++c) if (tau[c] > tau[cs]) cs = c;
    if (!any) goto out;
    {   /* lights, phase functions */
        MIST__V3 l = MIST__FN(mist__unit)(layers[0].sun_dir);
        MIST__T u = l.x * v.x + l.y * v.y + l.z * v.z;
        pR = MIST__FN(mist__impl_rayleigh_eval)(u);
        for (k = 0; k < n; ++k) MIST__FN(mist__hmie)(&layers[k], u, pM[k]);
        E[0]  = layers[0].sun.r;     E[1]  = layers[0].sun.g;     E[2]  = layers[0].sun.b;
        La[0] = layers[0].ambient.r; La[1] = layers[0].ambient.g; La[2] = layers[0].ambient.b;
        for (c = 0; c < 3; ++c) { E[c] = MIST__FN(mist__pos)(E[c]); La[c] = MIST__FN(mist__pos)(La[c]); }
        /* The lights' scale 2^lx[c]: albedo x light (ca, cu below) is at
         * most La + E p, p the largest phase value (a Dirac lobe's is the
         * largest finite value), which may leave the range though the
         * in-scatter, times 1 - T, does not.  Where La + E p may pass
         * 2^(MAX_EXP - 5) (room for the bound's sums, < 16 c), everything
         * linear in the lights is carried times 2^-lx[c] (exactly, in the
         * scaled products) and scaled back once at the end. */
        {
            MIST__T pmax = pR;
            int eE, eL, ep, m;
            for (k = 0; k < n; ++k)
                for (c = 0; c < 3; ++c) if (pM[k][c] > pmax) pmax = pM[k][c];
            (void)MIST__FN(mist__frexp)(pmax, &ep);
            for (c = 0; c < 3; ++c) {
                (void)MIST__FN(mist__frexp)(E[c], &eE);
                (void)MIST__FN(mist__frexp)(La[c], &eL);
                m = E[c] > MIST__C(0) && eE + ep > eL ? eE + ep : eL;   /* La + E p < 2^(m+1) */
                m = m + 1 - ((MIST__EB >> 1) + 1 - 5);
                lx[c] = m > 0 ? m : 0;
            }
        }
        sunx = layers[0].sun_extinction != 0;
        ly = MIST__FN(mist__hvert)(&layers[0], l);
        if (ly > MIST__C(0)) {   /* anu = |nu| ly, nu = 1 - w/ly (|nu| overflows for tiny ly) */
            anu = ly - w; anu = anu < MIST__C(0) ? -anu : anu;
        }
    }
    /* piece boundaries: equal steps of the square root of the
     * transmittance of channel cs (each piece's bound is then ~ its share
     * of the variation / pieces^2, the unbounded last one included), found
     * by Newton's method on ln tau(t); they need not be exact: the estimate
     * and its bound hold for any cut */
    np = pieces <= 0 ? 8 : (pieces > 64 ? 64 : pieces);
    if (same || w == MIST__C(0)) np = 1;        /* one exponential: exact */
    if (!(tau[cs] > MIST__C(0))) np = 1;        /* below the range: no cuts */
    tb[0] = MIST__C(0);
    {
        MIST__T om = -MIST__FN(mist__expm1)(MIST__C(-0.5) * tau[cs]);
        MIST__T tprev = MIST__C(0), mprev = MIST__C(0);
        for (k = 0; k < n; ++k)
            if (ok[k] && st[k][cs] > MIST__C(0)) mprev += st[k][cs] * seg[k].rho0;
        for (j = 1; j < np; ++j) {
            MIST__T target = MIST__C(-2) * MIST__M(log1p)(-om * (MIST__T)j / (MIST__T)np);
            MIST__T lo = tb[j - 1], hi = s, t = lo, tv = tprev, mu = mprev, tn, r;
            int it;
            for (it = 0; it < 40; ++it) {
                if (it == 0) tn = t + (target - tv) / mu;     /* from the last cut */
                else {
                    r = MIST__M(log)(tv / target);
                    if (r < MIST__C(1e-3) && r > MIST__C(-1e-3)) break;
                    if (r < MIST__C(0)) lo = t; else hi = t;
                    tn = t - r * tv / mu;
                }
                if (!(tn > lo && tn < hi))
                    tn = hi <= MIST__BIG ? MIST__C(0.5) * (lo + hi)
                                        : lo + MIST__C(2) * (t > lo ? t - lo : (lo > MIST__C(1) ? lo : MIST__C(1)));
                if (tn == t) break;
                t = tn;
                tv = mu = MIST__C(0);
                for (k = 0; k < n; ++k) {
                    MIST__HRAY q;
                    if (!ok[k] || !(st[k][cs] > MIST__C(0))) continue;
                    q = MIST__FN(mist__hray_eval)(y, w, MIST__C(0), t, layers[k].base, H[k], d0[k]);
                    tv += st[k][cs] * q.col;
                    mu += st[k][cs] * q.rho1;
                }
            }
            if (!(t > tb[j - 1] && t < s)) { np = j; break; }
            tb[j] = t;
            tprev = tv;
            mprev = mu;
        }
    }
    tb[np] = s;
    {
        MIST__T tj[3], psi[3], rnd[3];
        for (c = 0; c < 3; ++c) { tj[c] = MIST__C(0); psi[c] = MIST__C(0); rnd[c] = MIST__C(0); }
        if (sunx && ly > MIST__C(0))
            for (k = 0; k < n; ++k)
                if (ok[k]) for (c = 0; c < 3; ++c)
                    if (st[k][c] > MIST__C(0))   /* st rho0 H / ly, scaled */
                        psi[c] += MIST__FN(mist__hsun)(st[k][c], H[k], ly, seg[k].r0m,
                                                       seg[k].r0e + sx[k][c]);
        for (j = 0; j < np; ++j) {
            MIST__T dt = tb[j + 1] - tb[j];
            for (k = 0; k < n; ++k)
                if (ok[k]) seg[k] = np == 1
                    ? MIST__FN(mist__hray_eval)(y, w, MIST__C(0), s, layers[k].base, H[k], d0[k])
                    : MIST__FN(mist__hray_eval)(y, w, tb[j], dt, layers[k].base, H[k], d0[k]);
            for (c = 0; c < 3; ++c) {
                MIST__T dtau = MIST__C(0), psi1 = MIST__C(0), wsum = MIST__C(0), dsh = MIST__C(0);
                MIST__T le[MIST_HFOG_MAX_LAYERS], gsh[2] = { MIST__C(0), MIST__C(0) };
                MIST__T wk[MIST_HFOG_MAX_LAYERS], lk[MIST_HFOG_MAX_LAYERS], ca[MIST_HFOG_MAX_LAYERS];
                MIST__T wm[MIST_HFOG_MAX_LAYERS];
                MIST__T cu[MIST_HFOG_MAX_LAYERS], famb = MIST__C(0), fsun = MIST__C(0), lmax = MIST__C(0);
                MIST__T gj, om, osc = MIST__C(0), cmin[2], cmax[2];
                MIST__T wjs = (MIST__T)INFINITY, wsd = MIST__C(0);   /* the weight-aware
                                             * bound's sun part and share difference */
                int ke[MIST_HFOG_MAX_LAYERS], first = 1, ref = 0, emax = 0, unb = 0, have = 0, tie;
                int hv = 0;                       /* lmax set */
                for (k = 0; k < n; ++k) {
                    wk[k] = lk[k] = wm[k] = cu[k] = ca[k] = le[k] = MIST__C(0);   /* (set below
                                             * where used: gcc 12 -O2/-O3 -Wall
                                             * could not tell) */
                    ke[k] = 0;
                    if (!ok[k] || !(st[k][c] > MIST__C(0))) continue;
                    /* the layer's optical depth over the piece, scaled
                     * (wk 2^ke): exact shares even where it or the column
                     * alone leaves the range; +inf: an unbounded piece */
                    if (seg[k].cm <= MIST__BIG)
                        wk[k] = MIST__FN(mist__expmul_s)(st[k][c], seg[k].cm, MIST__C(1), MIST__C(1),
                                                         MIST__C(1), MIST__C(0), MIST__C(0),
                                                         seg[k].ce + sx[k][c], &ke[k]);
                    else wk[k] = (MIST__T)INFINITY;
                    if (!(wk[k] <= MIST__BIG)) unb = 1;
                    else if (wk[k] > MIST__C(0)) {
                        dtau += MIST__FN(mist__ldexp)(wk[k], ke[k]);
                        if (!have || ke[k] > emax) emax = ke[k];
                        have = 1;
                    }
                    if (sunx && ly > MIST__C(0))
                        psi1 += MIST__FN(mist__hsun)(st[k][c], H[k], ly, seg[k].r1m,
                                                     seg[k].r1e + sx[k][c]);
                    if (first) ref = k;
                    first = 0;
                    /* albedo x light: ambient (and undimmed sun), dimmed sun */
                    /* (times 2^-lx[c]: the lights' scale above) */
                    cu[k] = MIST__FN(mist__expmul_k)(E[c], sR[k][c], pR, MIST__C(1), st[k][c], MIST__C(0), MIST__C(0), -lx[c])
                          + MIST__FN(mist__expmul_k)(E[c], sM[k][c], pM[k][c], MIST__C(1), st[k][c], MIST__C(0), MIST__C(0), -lx[c]);
                    ca[k] = MIST__FN(mist__expmul_k)(La[c], sR[k][c] + sM[k][c], MIST__C(1), MIST__C(1), st[k][c], MIST__C(0), MIST__C(0), -lx[c])
                          + (sunx ? MIST__C(0) : cu[k]);
                }
                if (unb) dtau = (MIST__T)INFINITY;
                if (!(dtau > MIST__C(0)) && !have) continue;   /* (dtau may underflow) */
                /* each layer's share of the piece's extinction: of its
                 * optical depth (scaled by the largest's exponent), or for
                 * an unbounded piece its share at the start: of st rho0
                 * (scaled), or where a density is beyond even that, from
                 * the logs (rounded to le[k], which enters the bound) */
                if (unb) {
                    have = 0;
                    for (k = 0; k < n; ++k) {
                        if (!ok[k] || !(st[k][c] > MIST__C(0))) continue;
                        wk[k] = MIST__FN(mist__hstart)(st[k][c], &seg[k], sx[k][c], &ke[k]);
                        if (!(wk[k] <= MIST__BIG)) unb = 2;
                        else if (wk[k] > MIST__C(0) && (!have || ke[k] > emax)) { emax = ke[k]; have = 1; }
                    }
                    if (!have) unb = 2;
                }
                if (unb == 2) {
                    /* the logs relative to the dominant layer kx (found
                     * against ref first): its own is 0 exactly, so that
                     * another's rounding (le[k], far more than its value
                     * where the ray's height over H is huge) enters the
                     * bound through that layer's share alone (below) */
                    MIST__T lbest = MIST__C(0);
                    int kx = ref;
                    for (k = 0; k < n; ++k) {
                        MIST__T e;
                        if (k == ref || !ok[k] || !(st[k][c] > MIST__C(0))) continue;
                        e = MIST__FN(mist__lrel)(layers, st, sx, H, lnd, k, ref, c, y + w * tb[j],
                                                 MIST__NULL);
                        if (e > lbest) { lbest = e; kx = k; }
                    }
                    ref = kx;
                }
                for (k = 0; k < n; ++k) {
                    if (!ok[k] || !(st[k][c] > MIST__C(0))) continue;
                    if (unb == 2) {
                        lk[k] = k == ref ? MIST__C(0)
                              : MIST__FN(mist__lrel)(layers, st, sx, H, lnd, k, ref, c,
                                                     y + w * tb[j], &le[k]);
                        if (lk[k] == lk[k] && (!hv || lk[k] > lmax)) {   /* NaN: unordered,
                                                                           * no share */
                            lmax = lk[k]; hv = 1;
                        }
                    } else {
                        wm[k] = wk[k];
                        wk[k] = MIST__FN(mist__ldexp)(wk[k], ke[k] - emax);
                    }
                }
                /* logs beyond the type's range (a camera ~1e38 scale heights
                 * from a layer in float): the layers at +inf cannot be
                 * ordered, so they share equally and the shares' error is
                 * taken as unbounded (the bound then caps at the lights'
                 * whole range below) */
                tie = unb == 2 && !(lmax <= MIST__BIG);
                for (k = 0; k < n; ++k) {
                    if (!ok[k] || !(st[k][c] > MIST__C(0))) continue;
                    if (tie) wk[k] = lk[k] == lmax ? MIST__C(1) : MIST__C(0);
                    else if (unb == 2) wk[k] = lk[k] == lmax ? MIST__C(1) : MIST__M(exp)(lk[k] - lmax);
                    if (!(wk[k] >= MIST__C(0))) wk[k] = MIST__C(0);
                    wsum += wk[k];
                }
                if (!(wsum > MIST__C(0))) continue;
                /* sum_k share_k c_k, each term one scaled product: a share
                 * below the normal range keeps its precision (found by the
                 * fuzzer: a 2e-40 share of a large light, 1200 eps off) */
                for (k = 0; k < n; ++k) {
                    if (!ok[k] || !(st[k][c] > MIST__C(0))) continue;
                    if (tie) {
                        if (wk[k] > MIST__C(0)) { famb += ca[k] / wsum; fsun += cu[k] / wsum; }
                    } else if (unb == 2) {
                        famb += MIST__FN(mist__expmul)(ca[k], MIST__C(1), MIST__C(1), MIST__C(1), wsum,
                                                       lmax - lk[k], MIST__C(0));
                        fsun += MIST__FN(mist__expmul)(cu[k], MIST__C(1), MIST__C(1), MIST__C(1), wsum,
                                                       lmax - lk[k], MIST__C(0));
                    } else {
                        famb += MIST__FN(mist__expmul_k)(wm[k], ca[k], MIST__C(1), MIST__C(1), wsum,
                                                         MIST__C(0), MIST__C(0), ke[k] - emax);
                        fsun += MIST__FN(mist__expmul_k)(wm[k], cu[k], MIST__C(1), MIST__C(1), wsum,
                                                         MIST__C(0), MIST__C(0), ke[k] - emax);
                    }
                }
                if (tie) dsh = MIST__C(1);
                else if (unb == 2)
                    /* the shares' rounding: w_k = e^(lk - lmax) within
                     * e^+-x, x = le[k] + eps (2 + |lk - lmax|) (exp and its
                     * argument); dsh = sum_k f_k (e^x - 1) and gsh = sum_k
                     * c_k f_k (e^x - 1) (ambient, sun), f_k = w_k / wsum */
                    for (k = 0; k < n; ++k) {
                        MIST__T x, t;
                        if (!ok[k] || !(st[k][c] > MIST__C(0))) continue;
                        x = le[k] + MIST__EPS * (MIST__C(2) + MIST__M(fabs)(lk[k] - lmax));
                        t = wk[k] > MIST__C(0) && x < MIST__XLIM ? wk[k] * MIST__FN(mist__expm1)(x)
                                                                : MIST__M(exp)(lk[k] - lmax + x);
                        t = t / wsum;
                        dsh += t;
                        if (ca[k] > MIST__C(0)) gsh[0] += ca[k] * t;
                        if (cu[k] > MIST__C(0)) gsh[1] += cu[k] * t;
                    }
                gj = MIST__M(exp)(-tj[c]);
                om = dtau <= MIST__BIG ? -MIST__FN(mist__expm1)(-dtau)
                                       : MIST__C(1);                      /* 1 - e^-dtau */
                if (famb > MIST__C(0) && gj > MIST__C(0)) {
                    /* below 1, 1 - e^-dtau = dtau phi1(dtau) with dtau =
                     * wsum 2^emax (the shares' scale): one scaled product,
                     * right where dtau or the term is subnormal */
                    MIST__T lv = !unb && dtau < MIST__C(1)
                        ? MIST__FN(mist__expmul_k)(famb, gj, wsum, MIST__FN(mist__phi1)(dtau),
                                                   MIST__C(1), MIST__C(0), MIST__C(0), emax)
                        : famb * gj * om;
                    ls[c] += lv;
                    rnd[c] += lv * tj[c];
                }
                /* Bound: the piece's estimate takes each layer's share f_i of
                 * the extinction as constant; F = sum c_i f_i varies by at
                 * most osc = (c_max - c_min)/2 sum_i osc f_i, so the error is
                 * below osc * min(int g, dtau/4 * osc g) (Gruss), g the weight
                 * e^-tau or e^-psi. */
                first = 1;
                cmin[0] = cmin[1] = cmax[0] = cmax[1] = MIST__C(0);
                for (i = 0; i < n; ++i) {
                    MIST__T sa = MIST__C(0), sb = MIST__C(0), sd = MIST__C(0), oi;
                    if (!ok[i] || !(st[i][c] > MIST__C(0))) continue;
                    if (first) { cmin[0] = cmax[0] = ca[i]; cmin[1] = cmax[1] = cu[i]; first = 0; }
                    cmin[0] = ca[i] < cmin[0] ? ca[i] : cmin[0]; cmax[0] = ca[i] > cmax[0] ? ca[i] : cmax[0];
                    cmin[1] = cu[i] < cmin[1] ? cu[i] : cmin[1]; cmax[1] = cu[i] > cmax[1] ? cu[i] : cmax[1];
                    if (np == 1 && same) continue;
                    for (k = 0; k < n; ++k) {
                        /* r_ik = st_k rho_k / (st_i rho_i), monotone along the
                         * ray: in logs, at the piece start and its change */
                        MIST__T dl, ra, rb;
                        if (k == i || !ok[k] || !(st[k][c] > MIST__C(0))) continue;
                        dl = w * (MIST__C(1) / H[i] - MIST__C(1) / H[k]);
                        dl = dl == MIST__C(0) ? MIST__C(0) : dl * dt;
                        ra = MIST__FN(mist__lrel)(layers, st, sx, H, lnd, k, i, c, y + w * tb[j],
                                                  MIST__NULL);
                        rb = MIST__M(exp)(ra + dl);
                        ra = MIST__M(exp)(ra);
                        sa += ra > rb ? ra : rb;
                        sb += ra < rb ? ra : rb;
                        sd += ra > rb ? ra - rb : rb - ra;
                    }
                    /* osc f_i = 1/(1 + sb) - 1/(1 + sa), without the
                     * difference: where the other layers' share is below
                     * eps both round to 1 (an absorbing layer outweighing
                     * the scattering ones: the bound was then half what it
                     * must be, 1.95x exceeded; found by an independent check) */
                    oi = sa <= MIST__BIG ? sd / (MIST__C(1) + sa) / (MIST__C(1) + sb)
                       : sb <= MIST__BIG ? MIST__C(1) / (MIST__C(1) + sb)
                       : MIST__C(1) / MIST__BIG;   /* the ratios beyond the range
                        * at both ends: f_i <= 1/BIG, not 0 (float: the share
                        * 1e-40 of a subnormal in-scatter, 1.9x its bound) */
                    osc += oi >= MIST__C(0) ? oi : MIST__C(1);   /* NaN: all */
                }
                {
                    MIST__T gr = MIST__C(0.5) * (cmax[0] - cmin[0]) * osc
                               * (dtau < MIST__C(4) ? MIST__C(0.25) * dtau : MIST__C(1));
                    /* A second bound, for a piece that starts in a dense
                     * layer (a camera far below the base), where Gruss',
                     * blind to the weight e^-sigma (sigma the piece's optical
                     * depth), is the whole of c_max - c_min.  Along the piece
                     * each ratio of two layers' extinctions moves by
                     * e^(+-D s) at most, D = |w| (max 1/H - min 1/H), so each
                     * share f_i(s) is within e^(+-D s) of f_i(0) and
                     * |F(s) - F(0)| <= (c_max - c_min) min((1 - f0) (e^(D s) - 1), 1),
                     * f0 the largest share at the start.  Against e^-sigma
                     * dsigma, sigma' >= m on [0, s*], s* = ln 3 / D (m from
                     * each layer's density at the start and at s*; e^x - 1
                     * <= 3x below ln 3), the estimate's error is at most
                     * (c_max - c_min) (min(1.5, 3 (1 - f0)) D / m + e^(-m s*))
                     * (or (1 - f0) D / (m - D) + e^(-m s*), no tail down), plus
                     * om (c_max - c_min)/2 sum_i |fbar_i - f_i(0)| where the
                     * estimate's shares fbar are the piece's column means
                     * (bounded pieces; the unbounded one takes f(0) itself). */
                    if (gr > MIST__C(0) && om > MIST__C(0)) {
                        MIST__T imin = MIST__C(0), imax = MIST__C(0), dd, sst, m = MIST__C(0), e2;
                        MIST__T f0 = MIST__C(0), sdiff = MIST__C(0), wz[MIST_HFOG_MAX_LAYERS], zs = MIST__C(0);
                        int fi = 1, kz[MIST_HFOG_MAX_LAYERS], ez = 0, okz = 1;
                        for (k = 0; k < n; ++k) {
                            MIST__T ih;
                            wz[k] = MIST__C(0); kz[k] = 0;
                            if (!ok[k] || !(st[k][c] > MIST__C(0))) continue;
                            ih = H[k] <= MIST__BIG ? MIST__C(1) / H[k] : MIST__C(0);
                            if (fi || ih < imin) imin = ih;
                            if (fi || ih > imax) imax = ih;
                            /* the shares at the start, scaled (their own
                             * where the piece's are the start's) */
                            if (!unb) {
                                wz[k] = MIST__FN(mist__hstart)(st[k][c], &seg[k], sx[k][c], &kz[k]);
                                if (!(wz[k] <= MIST__BIG)) okz = 0;
                                else if (wz[k] > MIST__C(0) && (fi || kz[k] > ez)) ez = kz[k];
                            }
                            fi = 0;
                        }
                        for (k = 0; k < n && okz; ++k) {
                            if (!ok[k] || !(st[k][c] > MIST__C(0))) continue;
                            if (!unb) wz[k] = MIST__FN(mist__ldexp)(wz[k], kz[k] - ez);
                            else wz[k] = wk[k];
                            zs += wz[k];
                        }
                        okz = okz && zs > MIST__C(0);
                        for (k = 0; k < n && okz; ++k) {
                            MIST__T fb, fz;
                            if (!ok[k] || !(st[k][c] > MIST__C(0))) continue;
                            fz = wz[k] / zs;
                            if (fz > f0) f0 = fz;
                            if (!unb) {   /* each share to (n + 4) eps: its scaled
                                           * product, the sum of n, the quotient */
                                fb = wk[k] / wsum;
                                sdiff += (fb > fz ? fb - fz : fz - fb) + (MIST__T)(n + 8) * MIST__EPS * (fb + fz);
                            }
                        }
                        dd = (w < MIST__C(0) ? -w : w) * (imax - imin);
                        sst = dd > MIST__C(0) ? MIST__C(1.0986122886681098) / dd : (MIST__T)INFINITY;
                        for (k = 0; k < n && okz; ++k)
                            if (ok[k] && st[k][c] > MIST__C(0))
                                m += MIST__FN(mist__hmul)(st[k][c], MIST__C(1), MIST__C(1), MIST__C(1),
                                                          seg[k].r0m, seg[k].r0e + sx[k][c],
                                                          w > MIST__C(0) && H[k] <= MIST__BIG
                                                          ? w * (sst / H[k]) : MIST__C(0));
                        if (okz && m > MIST__C(0)) {
                            MIST__T f1 = MIST__C(1) - f0 + (MIST__T)(n + 8) * MIST__EPS, a = MIST__C(3) * f1;
                            MIST__T tl = MIST__M(exp)(-(m * sst));
                            MIST__T b = (a < MIST__C(1.5) ? a : MIST__C(1.5)) * (dd / m) + tl;
                            /* or, the depth's distribution below that of
                             * sigma = m s (to s*; down: everywhere, no tail)
                             * against the increasing (1 - f0)(e^(D s) - 1):
                             * (1 - f0) D / (m - D) */
                            if (m > dd) {
                                MIST__T b2 = f1 * (dd / (m - dd)) + (w > MIST__C(0) ? tl : MIST__C(0));
                                if (b2 < b) b = b2;
                            }
                            e2 = (cmax[0] - cmin[0]) * (b / om + MIST__C(0.5) * sdiff);
                            if (e2 < gr) gr = e2;
                        }
                    }
                    /* The weight-aware bound (section comment, THE WEIGHT)
                     * where the piece is deep (dtau > 2; below, Gruss' is
                     * within 3x where F is linear in the depth) and its
                     * densities normal; the sun's part (wjs) is taken below */
                    if (osc > MIST__C(0) && unb != 2 && w != MIST__C(0)
                        && (unb || dtau > MIST__C(2))) {
                        MIST__T e0[MIST_HFOG_MAX_LAYERS], bk[MIST_HFOG_MAX_LAYERS], ez0 = MIST__C(0);
                        MIST__T imn = MIST__C(0), imx = MIST__C(0), ja, nuv = MIST__C(0);
                        int fi = 1, okw = 1;
                        for (k = 0; k < n; ++k) {
                            MIST__T ih;
                            e0[k] = bk[k] = MIST__C(0);
                            if (!ok[k] || !(st[k][c] > MIST__C(0))) continue;
                            if (sx[k][c] != 0 || !(seg[k].rho0 <= MIST__BIG)) okw = 0;
                            ih = H[k] <= MIST__BIG ? MIST__C(1) / H[k] : MIST__C(0);
                            if (fi || ih < imn) imn = ih;
                            if (fi || ih > imx) imx = ih;
                            fi = 0;
                            e0[k] = st[k][c] * seg[k].rho0;   /* (a layer whose
                             * density at the start underflows may still dominate
                             * later: not taken) */
                            if (!(e0[k] >= MIST__TMIN)) okw = 0;
                            bk[k] = -w * ih;
                            ez0 += e0[k];
                        }
                        if (okw && ez0 > MIST__C(0)) {
                            if (sunx && ly > w) nuv = (ly - w) / ly;
                            MIST__FN(mist__hwbound)(n, e0, bk, dt, (w < MIST__C(0) ? -w : w) * (imx - imn),
                                                    nuv, &ja, &wjs);
                            /* |F(0) - Fbar| <= (c_max - c_min)/2 sum_k |fbar_k - f_k(0)|,
                             * each share to (n + 8) eps */
                            for (k = 0; k < n && !unb; ++k) {
                                MIST__T fb, fz;
                                if (!ok[k] || !(st[k][c] > MIST__C(0))) continue;
                                fb = wk[k] / wsum;
                                fz = e0[k] / ez0;
                                wsd += (fb > fz ? fb - fz : fz - fb) + (MIST__T)(n + 8) * MIST__EPS * (fb + fz);
                            }
                            if (om > MIST__C(0)) {
                                ja = (cmax[0] - cmin[0]) * (ja / om + MIST__C(0.5) * wsd);
                                if (ja < gr) gr = ja;
                            }
                        } else wjs = (MIST__T)INFINITY;
                    }
                    bd[c] += gr * gj * om;
                }
                /* Shares from the logs (unb == 2), each weight w_k within a
                 * factor e^+-x_k of its value, x_k = 0 for the dominant one:
                 * the true shares are f_k e^-h_k / D, |h_k| <= x_k, D =
                 * sum_j f_j e^-h_j within dsh of 1, so F = sum c_k f_k moves
                 * by at most (gsh + F dsh) / (1 - dsh), and never by more
                 * than c_max - c_min.  Proportional to the other layers'
                 * shares, not to the rounding of their logs (4 x the largest
                 * le[k] of the whole piece would be 3e9 eps in double for a
                 * camera 1e8 scale heights below the base, where the value
                 * is right to 2 eps). */
                if (unb == 2) {
                    MIST__T ea = dsh < MIST__C(1) ? (gsh[0] + famb * dsh) / (MIST__C(1) - dsh)
                                                  : (MIST__T)INFINITY;
                    MIST__T es = dsh < MIST__C(1) ? (gsh[1] + fsun * dsh) / (MIST__C(1) - dsh)
                                                  : (MIST__T)INFINITY;
                    gsh[0] = ea < cmax[0] - cmin[0] ? ea : cmax[0] - cmin[0];
                    gsh[1] = es < cmax[1] - cmin[1] ? es : cmax[1] - cmin[1];
                    if (gsh[0] > MIST__C(0)) bd[c] += gsh[0] * gj * om;   /* as famb's */
                }
                if (sunx && ly > MIST__C(0)) {
                    MIST__T pj = psi[c] + tj[c], pk = dtau <= MIST__BIG ? psi1 + tj[c] + dtau : (MIST__T)INFINITY;
                    MIST__T plo = pj < pk ? pj : pk, el = MIST__M(exp)(-plo), ej = MIST__M(exp)(-pj);
                    MIST__T ek = MIST__M(exp)(-pk), dg = ej > ek ? ej - ek : ek - ej, gs, fac, ob;
                    /* int over the piece of e^-(psi - psi_low) dtau; z =
                     * dtau |nu| scaled (dtau may underflow where |nu|
                     * overflows: 0 inf was NaN, found by the fuzzer) */
                    MIST__T z = unb ? (MIST__T)INFINITY
                              : MIST__FN(mist__expmul_k)(wsum, anu, MIST__C(1), MIST__C(1), ly,
                                                         MIST__C(0), MIST__C(0), emax);
                    /* 1/|nu| = ly/|ly - w|, ly scaled (mist__hly; unscaled it
                     * was 2.6e-4 off at ly = 2^-1074, against a reported
                     * bound of 4e-15) */
                    int kl;
                    MIST__T lys = MIST__FN(mist__hly)(ly, &kl);
                    if (!(el > MIST__C(0))) gs = MIST__C(0);
                    else if (!unb)
                        gs = z < MIST__C(1) ? dtau * MIST__FN(mist__phi1)(z)
                                            : -MIST__FN(mist__expm1)(-z) * (lys / anu);
                    else gs = anu > MIST__C(0) ? lys / anu : MIST__C(0);
                    if (fsun > MIST__C(0) && el > MIST__C(0) && (gs > MIST__C(0) || !unb)) {
                        /* scaled as above where dtau |nu| < 1 */
                        MIST__T lv = !unb && z < MIST__C(1)
                            ? MIST__FN(mist__expmul_k)(fsun, el, wsum, MIST__FN(mist__phi1)(z),
                                                       MIST__C(1), MIST__C(0), MIST__C(0), emax)
                            : MIST__FN(mist__expmul_k)(fsun, el, gs, MIST__C(1), MIST__C(1),
                                                       MIST__C(0), MIST__C(0), kl);
                        ls[c] += lv;
                        rnd[c] += lv * plo;
                    }
                    fac = MIST__C(0.25) * dtau;              /* min(1/|nu|, dtau/4) */
                    if (anu * fac > ly) fac = ly / anu;
                    ob = MIST__C(0.5) * (cmax[1] - cmin[1]) * osc * dg;
                    if (ob > MIST__C(0) && wjs <= MIST__BIG) {   /* weight-aware */
                        MIST__T ow = (cmax[1] - cmin[1]) * (MIST__M(exp)(-pj) * wjs
                                                            + MIST__C(0.5) * wsd * el * gs);
                        if (ow < ob * fac) { ob = ow; fac = MIST__C(1); }
                    }
                    if (ob > MIST__C(0)) bd[c] += ob * fac;   /* (0 x inf: 0; it was
                        * NaN, reported +inf, where nu = 0 and dtau = inf) */
                    if (unb == 2 && gsh[1] > MIST__C(0) && el > MIST__C(0) && gs > MIST__C(0))
                        bd[c] += MIST__FN(mist__expmul_k)(gsh[1], el, gs, MIST__C(1), MIST__C(1),
                                                          MIST__C(0), MIST__C(0), kl);   /* as fsun's */
                    psi[c] = psi1;
                }
                tj[c] += dtau;
            }
        }
        /* rounding of the estimate itself: a few eps per piece, and the
         * exponentials' eps times their arguments (rnd) */
        for (c = 0; c < 3; ++c) {
            /* (and below the normal range each of the ~2 n + 8 roundings
             * of a piece loses up to the smallest subnormal, absolutely) */
            const MIST__T tsub = (MIST__T)(MIST__DBL ? DBL_MIN * DBL_EPSILON
                                                     : (double)(FLT_MIN * FLT_EPSILON));
            bd[c] = bd[c] * (MIST__C(1) + MIST__C(64) * MIST__EPS)
                  + MIST__C(4) * (MIST__T)(np + 8) * MIST__EPS * ls[c] + MIST__C(8) * MIST__EPS * rnd[c]
                  + (MIST__T)(np * (2 * n + 8)) * tsub;
            if (!(bd[c] >= MIST__C(0))) bd[c] = (MIST__T)INFINITY;   /* beyond range: none */
            if (lx[c]) {                        /* the lights' scale, back */
                ls[c] = MIST__FN(mist__ldexp)(ls[c], lx[c]);
                bd[c] = MIST__FN(mist__ldexp)(bd[c], lx[c]);
                /* an in-scatter beyond the range is +inf (as mist_hfog_eval's),
                 * and its bound then +inf too */
                if (!(ls[c] <= MIST__BIG)) bd[c] = (MIST__T)INFINITY;
            }
        }
    }
out:
    if (transmittance) { transmittance->r = tr[0]; transmittance->g = tr[1]; transmittance->b = tr[2]; }
    if (inscatter) { inscatter->r = ls[0]; inscatter->g = ls[1]; inscatter->b = ls[2]; }
    if (bound) { bound->r = bd[0]; bound->g = bd[1]; bound->b = bd[2]; }
}

/* ------------------------------------------------------------------------ */
/* A ray-marching step with linear extinction [B08]                          */
/* ------------------------------------------------------------------------ */

/* sum_{k<n} c_k T_k(u), u in [-1, 1] (Clenshaw) */
MIST__F MIST__T MIST__FN(mist__cheb)(const double *c, int n, MIST__T u)
{
    MIST__T b0 = MIST__C(0), b1 = MIST__C(0), b2, u2 = u + u;
    int k;
    for (k = n - 1; k >= 1; --k) { b2 = b1; b1 = b0; b0 = (MIST__T)c[k] + u2 * b1 - b2; }
    return (MIST__T)c[0] + u * b0 - b1;
}

#define MIST__SQRTPI 1.77245385090551602729816748334114518
#define MIST__NC(nd, nf) (MIST__DBL ? (nd) : (nf))

/* erfcx(x) = e^(x^2) erfc(x) and *g = G(x) = 1 - sqrt(pi) x erfcx(x), both
 * to relative precision, for x >= 0 (+inf too).  Piecewise Chebyshev series
 * (erfcx on [0, 1/2], G on [1/2, 2], 2 x^2 G on [2, 4] and [4, 8]; fitted to
 * 50-digit values) and the asymptotic series of 2 x^2 G beyond 8. */
MIST__F MIST__T MIST__FN(mist__erfcx)(MIST__T x, MIST__T *g)
{
    /* erfcx(x), x in [0, 0.5]: Chebyshev series on [0, 0.5], 16 terms (float: 9) */
    static const double ex0[16] = {
        0.788974204329831875789, -0.190549590765591830907, 0.0187487664140465659436,
        -0.00159673853951946177843, 0.000121653708538792932327, -0.00000846556070795415573408,
        5.45763458055360256486e-7, -3.29360853217168330576e-8, 1.87534689888528002932e-9,
        -1.01373576635176259836e-10, 5.22845056525538442818e-12, -2.58354146020934923514e-13,
        1.22730252463624798877e-14, -5.6215578912286297107e-16, 2.48901885680302079966e-17,
        -1.06763023502818901048e-18
    };
    /* G(x) = 1 - sqrt(pi) x erfcx(x), x in [0.5, 2]: Chebyshev series on [0.5, 2], 21 terms (float: 12) */
    static const double gx1[21] = {
        0.227884784802039895534, -0.169722604592898790106, 0.0446645461623479120367,
        -0.00979042862878067859415, 0.00189691093524192984201, -0.000334750160553996303435,
        0.0000547816251730823193888, -0.00000841386413337517572126, 0.0000012232799925600718326,
        -1.69443958748515753091e-7, 2.24740936021165952242e-8, -2.86583279589083535166e-9,
        3.52514063877018207639e-10, -4.19439025848149078005e-11, 4.83901656280491568786e-12,
        -5.4241036550024913763e-13, 5.9177133155913318007e-14, -6.293819411137766434e-15,
        6.53448601752675770724e-16, -6.63106691805052433306e-17, 6.58436401076366973961e-18
    };
    /* 2 x^2 G(x), x in [2, 4]: Chebyshev series on [2, 4], 21 terms (float: 11) */
    static const double gx2[21] = {
        0.852876285034102207581, 0.0782420178532644881193, -0.0147870059587151229521,
        0.00232322961820125838878, -0.00031596838472959288683, 0.0000371029896178874017416,
        -0.00000356259196223612520627, 2.17342948832857427808e-7, 1.10596279751669682873e-8,
        -6.98350174585785958344e-9, 1.6161241914719252319e-9, -2.92582209597950979499e-10,
        4.67300927650283326541e-11, -6.87957752999648259211e-12, 9.53810759522416890552e-13,
        -1.26087460318976182831e-13, 1.60191092391976658991e-14, -1.96673490233997309088e-15,
        2.34281210762551187828e-16, -2.71608490948211749982e-17, 3.07194212784227614355e-18
    };
    /* 2 x^2 G(x), x in [4, 8]: Chebyshev series on [4, 8], 23 terms (float: 11) */
    static const double gx3[23] = {
        0.954685005315027637447, 0.0281631157423555443027, -0.00653006717712385006797,
        0.00132224360215378549138, -0.000245885968249216119529, 0.0000429321081118007241049,
        -0.00000711560645499629330446, 0.00000112536042612593393637, -1.70071282988430828933e-7,
        2.45088765233489174025e-8, -3.34599989233202081632e-9, 4.26666179212920076953e-10,
        -4.92695504825715366478e-11, 4.7515490101804018382e-12, -2.68607040611429654878e-13,
        -3.08742071754613795616e-14, 1.55669763350802244415e-14, -3.95273243519772696601e-15,
        8.2357287015564925681e-16, -1.55213667482183615823e-16, 2.74583754575748056807e-17,
        -4.64366518163922052996e-18, 7.58601270912598060748e-19
    };
    MIST__T e, gg, h;
    if (x <= MIST__C(0.5)) {
        e  = MIST__FN(mist__cheb)(ex0, MIST__NC(16, 9), MIST__C(4) * x - MIST__C(1));
        *g = MIST__C(1) - MIST__C(MIST__SQRTPI) * x * e;
        return e;
    }
    if (x <= MIST__C(2))
        gg = MIST__FN(mist__cheb)(gx1, MIST__NC(21, 12), (MIST__C(4) * x - MIST__C(5)) / MIST__C(3));
    else {
        if (x <= MIST__C(4)) h = MIST__FN(mist__cheb)(gx2, MIST__NC(21, 11), x - MIST__C(3));
        else if (x <= MIST__C(8)) h = MIST__FN(mist__cheb)(gx3, MIST__NC(23, 11), MIST__C(0.5) * x - MIST__C(3));
        else {   /* 2 x^2 G = sum (-1)^n (2n+1)!! / (2x^2)^n */
            MIST__T v = MIST__C(0.5) / x / x, t = MIST__C(1);
            int n;
            h = MIST__C(1);
            for (n = 1; n < 40; ++n) {
                t *= -(MIST__T)(2 * n + 1) * v;
                h += t;
                if ((t < MIST__C(0) ? -t : t) < MIST__C(0.125) * MIST__EPS) break;
            }
        }
        gg = h * (MIST__C(0.5) / x) / x;
    }
    *g = gg;
    return (MIST__C(1) - gg) / (MIST__C(MIST__SQRTPI) * x);
}

/* Dawson's F(y) = e^(-y^2) int_0^y e^(t^2) dt and *k = K(y) = 2 y F(y) - 1,
 * for y >= 0 (+inf too): F on [0, 1/2], K on [1/2, 2], 2 y^2 K on [2, 4]
 * and [4, 8] (Chebyshev), the asymptotic series of 2 y^2 K beyond. */
MIST__F MIST__T MIST__FN(mist__dawson)(MIST__T y, MIST__T *k)
{
    /* F(y) (Dawson), y in [0, 0.5]: Chebyshev series on [0, 0.5], 15 terms (float: 9) */
    static const double dw0[15] = {
        0.225890317645815001125, 0.214147860632557119854, -0.0138096567231503625153,
        -0.00194001509605431526956, 0.000138356467229671520007, 0.0000103850305827859059789,
        -8.2917102661030543078e-7, -3.89262960066620559686e-8, 3.543878078013367532e-9,
        1.10467916967845344038e-10, -1.17664861431452134943e-11, -2.46791609571394808832e-13,
        3.19293617326914988835e-14, 4.39388958561342182005e-16, -7.32348515902251146031e-17
    };
    /* K(y) = 2 y F(y) - 1, y in [0.5, 2]: Chebyshev series on [0.5, 2], 24 terms (float: 14) */
    static const double kd1[24] = {
        0.0123236795027359259311, 0.375259884587860605562, -0.21219394469860614479,
        0.0192593804721557872845, 0.0149304102070197254552, -0.0042699997174450247629,
        -0.00014158238755822222005, 0.00021871363977412240054, -0.0000207285680059763648878,
        -0.00000544503044365577725003, 0.00000116878683798916877803, 5.09106505632588164008e-8,
        -3.3878986528792405334e-8, 1.29936584052933958303e-9, 6.43169039118701811787e-10,
        -6.69445750879055798024e-11, -8.05857662080858212023e-12, 1.62651594444968919926e-12,
        4.72536199484339934886e-14, -2.77536366064071349315e-14, 6.1899523882088560815e-16,
        3.62001361519224473522e-16, -2.38939098456715242365e-17, -3.63973219372683005578e-18
    };
    /* 2 y^2 K(y), y in [2, 4]: Chebyshev series on [2, 4], 27 terms (float: 16) */
    static const double kd2[27] = {
        1.32808446687388698156, -0.276314500351450781577, 0.0634996684879336320246,
        0.00593773738823753607371, -0.0125552915989507663559, 0.00554630121583894694271,
        -0.00114203522960673341239, -0.0000440946584322324892902, 0.000102023001755718296614,
        -0.0000286153091803084798282, 0.00000189549354745843228075, 0.00000108009643114950136717,
        -3.55025943915935941431e-7, 2.98819429291511816563e-8, 8.78971639250287103242e-9,
        -2.89799513428592572777e-9, 2.13695257478742160188e-10, 6.18571049107776689431e-11,
        -1.70757813695915072027e-11, 8.06574830090500737475e-13, 3.67599222119310535668e-13,
        -7.41680270351012697438e-14, 6.35229572383124776667e-16, 1.73400830395049213751e-15,
        -2.31566086395579551624e-16, -1.09533350162480778118e-17, 6.22406863561150083956e-18
    };
    /* 2 y^2 K(y), y in [4, 8]: Chebyshev series on [4, 8], 32 terms (float: 15) */
    static const double kd3[32] = {
        1.05596665147414905499, -0.0408995184256726372584, 0.0118710753579476923081,
        -0.00319878445595639502717, 0.000843867259722393469586, -0.000223829836775395644678,
        0.0000606771423142433878504, -0.0000169729782010883110563, 0.00000490518762992204890296,
        -0.00000144952422056554163114, 4.27535597403592641205e-7, -1.20952060101269124733e-7,
        3.07503282406167416979e-8, -6.06967838693738852914e-9, 3.7215218422496417949e-10,
        4.35147798223347600009e-10, -2.96069745691878076738e-10, 1.24476870258757077011e-10,
        -3.94980895987388369341e-11, 9.25693235440570560585e-12, -1.17160538123931948167e-12,
        -2.2467366545163878716e-13, 2.04875677476135586671e-13, -7.62383456340401958925e-14,
        1.80189337305108064986e-14, -2.03302736572863980511e-15, -4.64827045713939032701e-16,
        3.3300201920309775211e-16, -9.95860646049855284994e-17, 1.60243642192026902138e-17,
        4.65198468760252382846e-19, -1.17643039128226114545e-18
    };
    MIST__T f, kk, h;
    if (y <= MIST__C(0.5)) {
        f  = MIST__FN(mist__cheb)(dw0, MIST__NC(15, 9), MIST__C(4) * y - MIST__C(1));
        *k = MIST__C(2) * y * f - MIST__C(1);
        return f;
    }
    if (y <= MIST__C(2))
        kk = MIST__FN(mist__cheb)(kd1, MIST__NC(24, 14), (MIST__C(4) * y - MIST__C(5)) / MIST__C(3));
    else {
        if (y <= MIST__C(4)) h = MIST__FN(mist__cheb)(kd2, MIST__NC(27, 16), y - MIST__C(3));
        else if (y <= MIST__C(8)) h = MIST__FN(mist__cheb)(kd3, MIST__NC(32, 15), MIST__C(0.5) * y - MIST__C(3));
        else {   /* 2 y^2 K = sum (2n+1)!! / (2y^2)^n */
            MIST__T v = MIST__C(0.5) / y / y, t = MIST__C(1);
            int n;
            h = MIST__C(1);
            for (n = 1; n < 40; ++n) {
                t *= (MIST__T)(2 * n + 1) * v;
                h += t;
                if (t < MIST__C(0.125) * MIST__EPS) break;
            }
        }
        kk = h * (MIST__C(0.5) / y) / y;
    }
    *k = kk;
    return (MIST__C(1) + kk) * (MIST__C(0.5) / y);
}

/* The step's weights W0 = int_0^1 (1-t) e^-tau(t) dt, W1 = int_0^1 t e^-tau(t)
 * dt for tau(t) = p t + b t^2, b = (q - p)/2, p, q >= 0 finite (the optical
 * depth rates at the two ends, times the length).  See the section comment. */
MIST__F void MIST__FN(mist__seg_w)(MIST__T p, MIST__T q, MIST__T *w0, MIST__T *w1)
{
    static const double gx[8] = {
        0.0950125098376374401853, 0.28160355077925891323, 0.458016777657227386342,
        0.617876244402643748447, 0.755404408355003033895, 0.86563120238783174388,
        0.944575023073232576078, 0.989400934991649932596 };
    static const double gw[8] = {
        0.189450610455068496285, 0.182603415044923588867, 0.169156519395002538189,
        0.149595988816576732082, 0.124628971255533872052, 0.0951585116824927848099,
        0.0622535239386478928628, 0.0271524594117540948518 };
    MIST__T t1 = MIST__C(0.5) * p + MIST__C(0.5) * q, b = MIST__C(0.5) * (q - p), m0, m1, e;
    int i;
    if (t1 <= MIST__C(2)) {
        /* Gauss-Legendre, 16 points: the integrands are entire and small
         * here, so the rule's error is below 1e-22 (Bernstein ellipse 8) */
        MIST__T a0 = MIST__C(0), a1 = MIST__C(0);
        for (i = 0; i < 8; ++i) {
            MIST__T d = MIST__C(0.5) * (MIST__T)gx[i], wt = MIST__C(0.5) * (MIST__T)gw[i];
            MIST__T tl = MIST__C(0.5) - d, th = MIST__C(0.5) + d;
            MIST__T el = wt * MIST__M(exp)(-tl * (p + b * tl)), eh = wt * MIST__M(exp)(-th * (p + b * th));
            a0 += th * el + tl * eh;            /* (1 - t) at tl is th */
            a1 += tl * el + th * eh;
        }
        *w0 = a0; *w1 = a1;
        return;
    }
    e = MIST__M(exp)(-t1);
    if ((b < MIST__C(0) ? -b : b) <= MIST__EPS * MIST__EPS * p * p) {
        /* constant extinction (the t^2 term below eps^2 of the rest) */
        m0 = MIST__FN(mist__phi1)(p);                 /* (p = t1 > 2) */
        m1 = (m0 - MIST__M(exp)(-p)) / p;
    } else if (b > MIST__C(0)) {
        /* extinction rising: t = (x - x0)/sqrt(b) turns tau into x^2 - x0^2
         *   M0 = sqrt(pi)/(2 sqrt b) (erfcx(x0) - e^-t1 erfcx(x1))
         *   2 b M1 = G(x0) - e^-t1 (sqrt(b)/x1 + x0/x1 G(x1)),
         * x0 = p/(2 sqrt b), x1 = q/(2 sqrt b): no difference loses more than
         * 1.5 bits for t1 > 2 (the two terms differ by e^-t1 at least). */
        MIST__T sb = MIST__M(sqrt)(b), x0 = MIST__C(0.5) * p / sb, x1 = MIST__C(0.5) * q / sb;
        MIST__T g0, g1, e0 = MIST__FN(mist__erfcx)(x0, &g0), e1 = MIST__FN(mist__erfcx)(x1, &g1);
        m0 = MIST__C(0.5) * MIST__C(MIST__SQRTPI) / sb * (e0 - e * e1);
        m1 = (g0 - e * (sb / x1 + x0 / x1 * g1)) / (MIST__C(2) * b);
    } else {
        /* extinction falling: t = (y1 - y)/sqrt(-b) gives Dawson's F
         *   M0 = (F(y1) - e^-t1 F(y0)) / sqrt(-b)
         *   -2 b M1 = K(y1) - e^-t1 (2 y1 F(y0) - 1),
         * y1 = p/(2 sqrt(-b)) > y0 = q/(2 sqrt(-b)) (1.5 bits at most, as above). */
        MIST__T sb = MIST__M(sqrt)(-b), y1 = MIST__C(0.5) * p / sb, y0 = MIST__C(0.5) * q / sb;
        MIST__T k0, k1, f0 = MIST__FN(mist__dawson)(y0, &k0), f1 = MIST__FN(mist__dawson)(y1, &k1);
        /* 2 y1 F(y0) - 1 = (y1/y0)(1 + K(y0)) - 1 = (sqrt(-b) + y1 K(y0))/y0
         * (y1 - y0 = sqrt(-b)): the right side is a sum of positive terms
         * where K(y0) >= 0 (y0 >= 0.93), the left has no cancellation below */
        MIST__T c = y0 >= MIST__C(1) ? (sb + y1 * k0) / y0 : MIST__C(2) * y1 * f0 - MIST__C(1);
        m0 = (f1 - e * f0) / sb;
        m1 = (k1 - e * c) / (MIST__C(-2) * b);
    }
    *w1 = m1;
    *w0 = m0 - m1;                  /* m1 <= m0/2: e^-tau falls, so t's mean <= 1/2 */
}

/* One step of a ray march through a heterogeneous medium [B08]: over a
 * segment of `length` whose extinction varies linearly from k0 to k1 and
 * whose source (scattering coefficient x phase x incident radiance, per
 * unit length) varies linearly from s0 to s1, returns the single-scattered
 * radiance  int_0^length s(x) exp(-int_0^x k) dx  in closed form and sets
 * *transmittance (may be NULL) to exp(-length (k0 + k1)/2).  Exact and
 * stable as the extinction goes to 0 (the trapezoid rule of s, then) and
 * grows without bound; see the section comment.  k0, k1: NaN, negative -> 0;
 * s0, s1 NaN -> 0, +-inf taken as +-the largest finite value (so
 * mist_segment_linear(2, 2, INFINITY, 0, 1, &t) is 5.1e307, not +inf);
 * length NaN or <= 0 -> 0 (transmittance 1); length +inf: the limit,
 * s0/k0 (transmittance 0; +inf if k0 = 0, unless s0 = 0). */
MIST__F MIST__T MIST__FN(mist__impl_segment_linear)(MIST__T k0, MIST__T k1, MIST__T s0, MIST__T s1,
                                              MIST__T length, MIST__T *transmittance)
{
    MIST__T p, q, w0, w1, tr = MIST__C(1), r = MIST__C(0);
    k0 = MIST__FN(mist__pos)(k0); k1 = MIST__FN(mist__pos)(k1);
    /* the sources clamped here, before any branch multiplies them (NaN: 0;
     * +-inf: +-the largest finite value) */
    s0 = MIST__FN(mist__clampbig)(s0);
    s1 = MIST__FN(mist__clampbig)(s1);
    if (length > MIST__C(0)) {
        p = k0 * length; q = k1 * length;
        tr = length <= MIST__BIG && p <= MIST__BIG && q <= MIST__BIG
             ? MIST__M(exp)(MIST__C(-0.5) * p - MIST__C(0.5) * q) : MIST__C(0);
        /* where e^-tau(1) underflows the large-argument forms below are the
         * same integrals, with the length scaled out: in these, W1 ~ 1/p^2
         * underflowed once k len passed 2^511 (float 2^63) though len W1 did
         * not (an independent check: 0 for 4.7e-169) */
        if (tr > MIST__C(0)) {
            MIST__FN(mist__seg_w)(p, q, &w0, &w1);
            /* len s w, scaled (mist__expmul) against underflow and overflow
             * on the way; a source of each sign */
            r = (s0 < MIST__C(0) ? -MIST__FN(mist__expmul)(length, -s0, w0, MIST__C(1), MIST__C(1), MIST__C(0), MIST__C(0))
                                 : MIST__FN(mist__expmul)(length, s0, w0, MIST__C(1), MIST__C(1), MIST__C(0), MIST__C(0)))
              + (s1 < MIST__C(0) ? -MIST__FN(mist__expmul)(length, -s1, w1, MIST__C(1), MIST__C(1), MIST__C(0), MIST__C(0))
                                 : MIST__FN(mist__expmul)(length, s1, w1, MIST__C(1), MIST__C(1), MIST__C(0), MIST__C(0)));
            if (r != r) r = length * (s0 * w0 + s1 * w1);   /* +inf - inf: sum first */
        } else {
            /* k len beyond the range (or len = +inf): e^-tau(1) = 0, and
             * the large-argument forms of mist__seg_w are taken with the
             * length scaled out: len M0 = n0 / d0 and len M1 = n1 / d1 2^e1
             * (M0 ~ 1/p, M1 ~ 1/p^2 or G/(2b)), each term s len M one
             * scaled product (mist__expmul_s): len M1 ~ len / p^2 is below
             * the range where s len M1 is not (1e300 k0, len 1: 1e-600, for
             * a source near the largest value, 1.8e-292). */
            MIST__T n0, d0 = MIST__C(1), n1, d1, rt = MIST__C(0), a0, a1, x, sd, g, f;
            MIST__T rl = MIST__M(sqrt)(length);
            int e0, e1 = 0, e;
            tr = k0 > MIST__C(0) || k1 > MIST__C(0) ? MIST__C(0) : MIST__C(1);
            if (!(length <= MIST__BIG)) {       /* the limit: k0 and s0 throughout */
                if (transmittance) *transmittance = tr;
                if (k0 > MIST__C(0)) return s0 / k0;
                return s0 == MIST__C(0) ? MIST__C(0) : s0 * (MIST__T)INFINITY;
            }
            /* with x = k0 sqrt(len) / (2 sd), 2 x^2 = k0^2 len / |k1 - k0|:
             * where x >= 1, len M0 = sqrt(pi) x erfcx(x) / k0 = (1 - G(x)) / k0
             * (rising), 2 x F(x) / k0 = (1 + K(x)) / k0 (falling), and
             * len M1 = G / |k1 - k0| = h / (k0^2 len), h = 2 x^2 G (K): near 1
             * and flat in x, so the roundings of x cancel (constant: h = 1);
             * no sqrt(len) / sd, which overflows (k, len near the largest
             * value: found by the fuzzer).  Below (rising only: falling has
             * x > 19 here), len M0 = sqrt(pi)/2 (sqrt(len) / sd) erfcx(x),
             * len M1 = G / (k1 - k0).  W0 = M0 - M1 = M0 (1 - rt), rt =
             * M1 / M0 in [0, 1/2]: h / (p (1 -+ G)) (0 where p = k0 len
             * overflows), or G / (sqrt(pi) sd sqrt(len) erfcx(x)). */
            x = MIST__C(1);
            n0 = n1 = MIST__C(1);               /* constant (k0 > 0: p, q finite) */
            d1 = MIST__C(1);
            if (k1 != k0) {
                MIST__T dk = k1 > k0 ? k1 - k0 : k0 - k1;
                sd = MIST__M(sqrt)(MIST__C(0.5) * dk);
                x = MIST__C(0.5) * (k0 / sd) * rl;
                f = k1 > k0 ? MIST__FN(mist__erfcx)(x, &g) : MIST__FN(mist__dawson)(x, &g);
                if (x >= MIST__C(1)) {
                    n0 = k1 > k0 ? MIST__C(1) - g : MIST__C(1) + g;
                    /* h = 2 x^2 G: 1 to rounding where x^2 would overflow */
                    n1 = x < MIST__C(MIST__DBL ? 1e150 : 1e18) ? MIST__C(2) * x * x * g : MIST__C(1);
                } else {
                    n0 = MIST__C(0.5) * MIST__C(MIST__SQRTPI) * f * rl;
                    n1 = g;
                    d0 = sd; d1 = dk;
                    rt = g / (MIST__C(MIST__SQRTPI) * sd * rl * f);
                }
            }
            if (x >= MIST__C(1)) {              /* d1 2^-e1 = k0^2 len, exactly scaled */
                int ek, el;
                MIST__T mk = MIST__FN(mist__frexp)(k0, &ek), ml = MIST__FN(mist__frexp)(length, &el);
                MIST__T pp = k0 * length;
                d0 = k0;
                d1 = mk * mk * ml;
                e1 = -(2 * ek + el);
                rt = pp <= MIST__BIG ? n1 / (pp * n0) : MIST__C(0);
            }
            /* s0 n0 (1 - rt) / d0 + s1 n1 / d1 2^e1: each a scaled product,
             * summed at the larger exponent and rounded once into the range
             * (a term beyond it, or +inf - inf, loses nothing) */
            a0 = MIST__FN(mist__expmul_s)(s0 < MIST__C(0) ? -s0 : s0, n0, MIST__C(1) - rt, MIST__C(1), d0,
                                          MIST__C(0), MIST__C(0), 0, &e0);
            a1 = MIST__FN(mist__expmul_s)(s1 < MIST__C(0) ? -s1 : s1, n1, MIST__C(1), MIST__C(1), d1,
                                          MIST__C(0), MIST__C(0), e1, &e1);
            if (s0 < MIST__C(0)) a0 = -a0;
            if (s1 < MIST__C(0)) a1 = -a1;
            e = a0 == MIST__C(0) ? e1 : (a1 == MIST__C(0) || e0 > e1 ? e0 : e1);
            r = MIST__FN(mist__ldexp)(MIST__FN(mist__ldexp)(a0, e0 - e) + MIST__FN(mist__ldexp)(a1, e1 - e), e);
        }
    }
    if (transmittance) *transmittance = tr;
    return r;
}

#undef MIST__SQRTPI
#undef MIST__NC

#undef MIST__RGB
#undef MIST__HFOG
#undef MIST__HRAY
#undef MIST__HFK
#undef MIST__BIG
#undef MIST__TMIN
#undef MIST__XLIM
/* end of the analytic height fog */
#endif /* !MIST_NO_HFOG */

#endif /* !MIST__INTERNAL_ONLY */

#undef MIST__C
#undef MIST__DD
#undef MIST__DDR
#undef MIST__DDV

#endif /* MIST__TEMPLATE */

/*
MIT License

Copyright (c) 2026 the mist authors

Permission is hereby granted, free of charge, to any person obtaining a copy
of this software and associated documentation files (the "Software"), to deal
in the Software without restriction, including without limitation the rights
to use, copy, modify, merge, publish, distribute, sublicense, and/or sell
copies of the Software, and to permit persons to whom the Software is
furnished to do so, subject to the following conditions:

The above copyright notice and this permission notice shall be included in all
copies or substantial portions of the Software.

THE SOFTWARE IS PROVIDED "AS IS", WITHOUT WARRANTY OF ANY KIND, EXPRESS OR
IMPLIED, INCLUDING BUT NOT LIMITED TO THE WARRANTIES OF MERCHANTABILITY,
FITNESS FOR A PARTICULAR PURPOSE AND NONINFRINGEMENT. IN NO EVENT SHALL THE
AUTHORS OR COPYRIGHT HOLDERS BE LIABLE FOR ANY CLAIM, DAMAGES OR OTHER
LIABILITY, WHETHER IN AN ACTION OF CONTRACT, TORT OR OTHERWISE, ARISING FROM,
OUT OF OR IN CONNECTION WITH THE SOFTWARE OR THE USE OR OTHER DEALINGS IN THE
SOFTWARE.
*/
