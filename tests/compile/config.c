/* config.c - one configuration of mist.h (CONFIGURATION at the top of the
 * header: MIST_NO_DRAINE, _RAYLEIGH, _FOG, _HFOG, _DIR, _BATCH,
 * MIST_ONLY_HG; MIST_NO_LONG_DOUBLE and MIST_DRAINE_PREPARE_N, which keep
 * every name), given by -D on the command line.  CMake compiles it for
 * every documented configuration with gcc and clang, -std=c99 -Wall
 * -Wextra -Wpedantic -Werror.
 *
 * What a configuration keeps is called (so it must be declared); what it
 * leaves out must be ABSENT: the file declares a variable of the same name,
 * which is an error ("redeclared as a different kind of symbol") if the
 * header still declares the function.  The expectations follow the
 * documented implications, worked out here from the macros given, before
 * the header can define any. */
#if defined(MIST_NO_DRAINE) || defined(MIST_ONLY_HG)
#  define EXPECT_NO_DRAINE
#endif
#if defined(MIST_NO_RAYLEIGH) || defined(MIST_ONLY_HG)
#  define EXPECT_NO_RAYLEIGH
#endif
#if defined(MIST_NO_FOG) || defined(EXPECT_NO_DRAINE)
#  define EXPECT_NO_FOG
#endif
#if defined(MIST_NO_HFOG) || defined(EXPECT_NO_FOG) || defined(EXPECT_NO_RAYLEIGH)
#  define EXPECT_NO_HFOG
#endif
#if defined(MIST_NO_TAB) || defined(MIST_ONLY_HG)
#  define EXPECT_NO_TAB
#endif
#if defined(MIST_NO_DIR)
#  define EXPECT_NO_DIR
#endif
#if defined(MIST_NO_BATCH)
#  define EXPECT_NO_BATCH
#endif

#include "mist.h"
#include "mist.h"

/* a name that must be undeclared, in both types (f suffix) */
#define ABSENT(n) static const int n = 1, n##f = 1;
#define USE(n) + n + n##f

/* ---- always there ------------------------------------------------------- */
static double always(double x)
{
    mist_vec3 v = { 0, 0, 2 };
    mist_vec3f vf = { 0, 0, 2 };
    float xf = (float)x;
    return mist_hg_eval(0.5, x) + mist_hg_sample(0.5, x) + mist_normalize(v).z
         + (double)(mist_hg_evalf(0.5f, xf) + mist_hg_samplef(0.5f, xf) + mist_normalizef(vf).z);
}

/* ---- Draine and Cornette-Shanks ------------------------------------------ */
#ifdef EXPECT_NO_DRAINE
#  define DRAINE_NAMES(X) X(mist_draine_eval) X(mist_draine_sample) X(mist_cs_eval) \
     X(mist_cs_sample) X(mist_draine_sample_dir) X(mist_cs_sample_dir)              \
     X(mist_draine_eval_n) X(mist_draine_sample_n) X(mist_phase_draine)
DRAINE_NAMES(ABSENT)
static const int mist__draine_eq6 = 1;
static double draine(double x) { (void)x; return 0 DRAINE_NAMES(USE) + mist__draine_eq6; }
#else
static double draine(double x)
{
    float xf = (float)x;
    return mist_draine_eval(0.5, 2.0, x) + mist_draine_sample(0.5, 2.0, x)
         + mist_cs_eval(0.5, x) + mist_cs_sample(0.5, x)
         + (double)(mist_draine_evalf(0.5f, 2.0f, xf) + mist_draine_samplef(0.5f, 2.0f, xf)
                    + mist_cs_evalf(0.5f, xf) + mist_cs_samplef(0.5f, xf));
}
#endif

/* ---- Rayleigh ------------------------------------------------------------ */
#ifdef EXPECT_NO_RAYLEIGH
#  define RAYLEIGH_NAMES(X) X(mist_rayleigh_eval) X(mist_rayleigh_sample)          \
     X(mist_rayleigh_sample_dir) X(mist_rayleigh_eval_n) X(mist_rayleigh_sample_n)   \
     X(mist_phase_rayleigh)
RAYLEIGH_NAMES(ABSENT)
static double rayleigh(double x) { (void)x; return 0 RAYLEIGH_NAMES(USE); }
#else
static double rayleigh(double x)
{
    return mist_rayleigh_eval(x) + mist_rayleigh_sample(x)
         + (double)(mist_rayleigh_evalf((float)x) + mist_rayleigh_samplef((float)x));
}
#endif

/* ---- the fog mixture, droplet fits (and the prepared phase functions) ---- */
#ifdef EXPECT_NO_FOG
#  define FOG_NAMES(X) X(mist_fog_make) X(mist_fog_eval) X(mist_fog_sample)          \
     X(mist_fog_sample_dir) X(mist_fog_from_diameter) X(mist_phase_fog) X(mist_phase_hg) \
     X(mist_phase_eval) X(mist_phase_sample) X(mist_fog_from_diameter_mie)
FOG_NAMES(ABSENT)
static double fog(double x) { (void)x; return 0 FOG_NAMES(USE); }
#else
static double fog(double x)
{
    mist_fog f = mist_fog_from_diameter(10.0);
    mist_fogf ff = mist_fog_makef(0.9f, 0.5f, 20.0f, 0.4f);
    mist_phasef ph = mist_phase_hgf(0.5f);
    return mist_fog_eval(f, x) + mist_fog_sample(f, x)
         + (double)(mist_fog_evalf(ff, (float)x) + mist_fog_samplef(ff, (float)x)
                    + mist_phase_evalf(&ph, (float)x) + mist_phase_samplef(&ph, (float)x));
}
#endif

/* ---- the height fog ------------------------------------------------------ */
#ifdef EXPECT_NO_HFOG
#  define HFOG_NAMES(X) X(mist_hfog_column) X(mist_hfog_eval) X(mist_hfog_transmittance) \
     X(mist_hfog_inscatter) X(mist_hfog_apply) X(mist_hfog_layers_eval)               \
     X(mist_segment_linear)
HFOG_NAMES(ABSENT)
static double hfog(double x) { (void)x; return 0 HFOG_NAMES(USE); }
#else
static double hfog(double x)
{
    double t = 0;
    float tf = 0;
    return mist_segment_linear(1.0, 2.0, 0.5, 0.5, x, &t) + t
         + (double)(mist_segment_linearf(1.0f, 2.0f, 0.5f, 0.5f, (float)x, &tf) + tf);
}
#endif

/* ---- tabulated phase functions ------------------------------------------ */
#ifdef EXPECT_NO_TAB
#  define TAB_NAMES(X) X(mist_tab_bytes) X(mist_tab_init) X(mist_tab_eval)        \
     X(mist_tab_sample) X(mist_tab_sample_dir) X(mist_tab_eval_n) X(mist_tab_sample_n)
TAB_NAMES(ABSENT)
static double tab(double x) { (void)x; return 0 TAB_NAMES(USE); }
#else
static double tab(double x)
{
    static double mem[64], mu[2] = { -1, 1 }, p[2] = { 1, 2 };
    static float memf[128], muf[2] = { -1, 1 }, pf[2] = { 1, 2 };
    mist_tab *t = (mist_tab *)(void *)mem;
    mist_tabf *tf = (mist_tabf *)(void *)memf;
    double s = (double)mist_tab_bytes(2, 1) + (double)mist_tab_bytesf(2, 1);
    float xf = (float)x;
    s += mist_tab_init(t, sizeof mem, mu, p, 2, 1) + mist_tab_initf(tf, sizeof memf, muf, pf, 2, 1);
    s += mist_tab_eval(t, x, NULL) + mist_tab_sample(t, x)
       + (double)(mist_tab_evalf(tf, xf, NULL) + mist_tab_samplef(tf, xf));
#  ifndef EXPECT_NO_DIR
    {
        mist_vec3 wi = { 0, 0, 1 };
        mist_vec3f wif = { 0, 0, 1 };
        double pdf = 0;
        float pdff = 0;
        s += mist_tab_sample_dir(t, wi, x, x, &pdf).z + pdf
           + (double)(mist_tab_sample_dirf(tf, wif, xf, xf, &pdff).z + pdff);
    }
#  endif
#  ifndef EXPECT_NO_BATCH
    {
        double a[2] = { 0.1, 0.5 };
        float af[2] = { 0.1f, 0.5f };
        mist_tab_eval_n(t, a, a, 2);
        mist_tab_sample_n(t, a, a, 2);
        mist_tab_eval_nf(tf, af, af, 2);
        mist_tab_sample_nf(tf, af, af, 2);
        s += a[0] + (double)af[1];
    }
#  endif
    return s;
}
#endif

/* ---- directions ---------------------------------------------------------- */
#ifdef EXPECT_NO_DIR
#  define DIR_NAMES(X) X(mist_dir_from_cos) X(mist_hg_sample_dir)
DIR_NAMES(ABSENT)
static double dir(double x) { (void)x; return 0 DIR_NAMES(USE); }
#else
static double dir(double x)
{
    mist_vec3 wi = { 0, 0, 1 };
    mist_vec3f wif = { 0, 0, 1 };
    double pdf = 0;
    float pdff = 0;
    return mist_dir_from_cos(wi, x, x).x + mist_hg_sample_dir(0.5, wi, x, x, &pdf).z + pdf
         + (double)(mist_dir_from_cosf(wif, (float)x, (float)x).x
                    + mist_hg_sample_dirf(0.5f, wif, (float)x, (float)x, &pdff).z + pdff)
#  ifndef EXPECT_NO_DRAINE
         + mist_draine_sample_dir(0.5, 2.0, wi, x, x, &pdf).z
         + (double)mist_cs_sample_dirf(0.5f, wif, (float)x, (float)x, &pdff).z
#  endif
#  ifndef EXPECT_NO_RAYLEIGH
         + mist_rayleigh_sample_dir(wi, x, x, &pdf).z
#  endif
         ;
}
#endif

/* ---- batch forms --------------------------------------------------------- */
#ifdef EXPECT_NO_BATCH
#  define BATCH_NAMES(X) X(mist_hg_eval_n) X(mist_hg_sample_n)
BATCH_NAMES(ABSENT)
static double batch(double x) { (void)x; return 0 BATCH_NAMES(USE); }
#else
static double batch(double x)
{
    double a[3] = { 0.1, 0.5, 0.9 };
    float af[3] = { 0.1f, 0.5f, 0.9f };
    a[0] = x;
    mist_hg_eval_n(0.5, a, a, 3);
    mist_hg_sample_nf(0.5f, af, af, 3);
#  ifndef EXPECT_NO_DRAINE
    mist_draine_eval_n(0.5, 2.0, a, a, 3);
    mist_draine_sample_nf(0.5f, 2.0f, af, af, 3);
#  endif
#  ifndef EXPECT_NO_RAYLEIGH
    mist_rayleigh_eval_n(a, a, 3);
    mist_rayleigh_sample_nf(af, af, 3);
#  endif
    return a[0] + a[2] + (double)af[1];
}
#endif

int main(void)
{
    double x = 0.25;
    double s = always(x) + draine(x) + rayleigh(x) + fog(x) + hfog(x) + dir(x) + batch(x) + tab(x);
    return !(s == s);
}
