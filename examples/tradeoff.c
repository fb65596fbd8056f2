/* tradeoff.c - error against run time: how close each phase-function model
 * comes to Lorenz-Mie for fog droplets, and what it costs per evaluation
 * and per sample, measured in the same run.  Prints Markdown tables
 * (stdout) and writes an SVG plot (argv[1], default tradeoff.svg beside the program).
 *
 * Build and run (from the repository root):
 *   cc -std=c99 -O2 -Iinclude -Itests examples/tradeoff.c -o tradeoff -lm
 *   ./tradeoff [out.svg]            (about 20 s: the tables need their Mie references)
 * tests/mist_ref.h needs __float128 (gcc or clang on x86-64).
 *
 * PART 1: phase functions against Lorenz-Mie, droplet diameters 2, 5, 10,
 * 20 um.  The reference and the two error metrics are those of
 * examples/fit_error.c (tests/mist_fitref.h: water, 450/550/650 nm with
 * equal weights, lognormal sizes of geometric width 1.1, 1001 angles fine
 * near the forward peak; L1 = int |p - p_Mie| dOmega, logRMS = RMS over
 * theta of log10(p / p_Mie)).  The models, each given what a renderer would
 * have for that fog:
 *   HG(g)        mist_hg_eval with the Mie asymmetry g;
 *   CS(g')       mist_cs_eval with g' chosen so that its mean cosine
 *                3g'(4+g'^2)/(5(2+g'^2)) is the Mie g (bisection);
 *   Draine fit   mist_draine_eval with (g, alpha) fitted here to the Mie
 *                curve: a coarse grid, then a compass search, minimising
 *                logRMS;
 *   Schlick      (1-k^2) / (4 pi (1 - k u)^2), k = 1.55g - 0.55g^3 (the
 *                usual mapping from g), from tests/mist_alt.h: NOT in mist.
 *                It integrates to 1 as written; its inverse CDF is
 *                u = (2 xi - 1 + k) / (1 - k + 2 k xi);
 *   XLF          the blog's "Xiao-Lei Fan" function, as its code prints it:
 *                1/(4 pi) [3/2 (1-g^2)/(2+g^2) (1+u^2)/(1+g^2-2gu) + g u].
 *                INVALID: not a probability density (its integral is not 1,
 *                and it is negative backwards from about g = 0.5 on; the
 *                numbers are printed).  Its L1 error is computed anyway, as
 *                evaluated (not renormalised); logRMS does not exist;
 *   JD23 fit     mist_fog_eval(mist_fog_from_diameter(d), u);
 *   LUT theta N  a table of the Mie phase function at N angles uniform in
 *                theta, linear interpolation, lookup through acos;
 *   LUT warp N   the same in a warped coordinate s(u) made of three
 *                square roots (no acos): nodes crowd into the forward peak
 *                and stay about uniform in theta elsewhere (see warp_s).
 *                Both tables hold the exact Mie values at their nodes and
 *                are scaled so that the interpolant integrates to 1 (their
 *                raw integrals are printed);
 *   mist_tab N   mist.h's tabulated phase function (mist_tab_eval,
 *                mist_tab_sample: exact sampling) through the nodes
 *                mist_mie_tab_nodes places adaptively, at most N of them
 *                (the best table of at most N nodes; the count is printed).
 * Costs: ns per call, double precision, on 4096 random u (resp. xi) per
 * repetition, read through volatile (no vectorised loops: a renderer calls
 * these one at a time), median of 15 repetitions (bench/mist_bench.c's
 * method), at each diameter's parameters, then the median over the four.
 * The parameters are variables, not constants: bench/mist_bench.c's
 * constant g lets the compiler fold part of HG (3.3 vs 6.4 ns there).
 *
 * PART 2: the exact HG samplers (mist_hg_sample[f]) against eq. 3 as
 * printed with its eq. 4 fallback, float and double, g in {1e-4, 0.01,
 * 0.5, 0.9}, the same xi; and the exact Draine samplers (mist_draine_sample[f], and the
 * prepared mist_phase_sample[f], prepared once per (g, alpha) outside the
 * timed loop) against eq. 6 of the supplemental typed in as printed, float
 * and double: max |u - u*| over g in {0.01, 0.1, 0.5,
 * 0.9}, alpha in {1, 17, 250} (the fits' regime) and 1006 xi (1000 uniform,
 * plus 1e-7, 1e-5, 1e-3 from either end), u* = tests/mist_ref.h's __float128
 * inversion of the exact CDF at the inputs each function actually receives
 * (float-rounded for float).  Cost: ns per sample at each (g, alpha),
 * median and range over the 12.
 */
#define _POSIX_C_SOURCE 199309L
#include "mist.h"
#include "mist_mie.h"
#include "mist_fitref.h"
#include "mist_ref.h"
#include "mist_printed.h"
#include "mist_alt.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "beside.h"

#define NB      4096       /* inputs per timed repetition */
#define REPS    15
#define N_RADII 200        /* radii per Mie average (as fit_error.c) */
#define ND      4
#define NLUT    4
#define NM      (6 + 3 * NLUT)

static const double DS[ND] = { 2, 5, 10, 20 };
static const int LUT_N[NLUT] = { 16, 64, 256, 1024 };

/* ======================================================================== */
/* Timing (as bench/mist_bench.c)                                           */
/* ======================================================================== */

/* The inputs are read through volatile so that no compiler vectorises a
 * timed loop: gcc -O2 does for the branch-free Schlick and XLF (about 2x),
 * not for mist's functions; a renderer calls them one at a time. */
static volatile double ub[NB], xb[NB];
static volatile float  xbf[NB];
static volatile double sink;

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

typedef double (*bench_fn)(void);

static void machine(void)
{
    FILE *f = fopen("/proc/cpuinfo", "r");
    char line[256];
    printf("machine: ");
    if (f) {
        int found = 0;
        while (fgets(line, sizeof line, f))
            if (strncmp(line, "model name", 10) == 0) {
                char *p = strchr(line, ':');
                printf("%s", p ? p + 2 : line);
                found = 1;
                break;
            }
        fclose(f);
        if (!found) printf("unknown\n");
    } else {
        printf("unknown\n");
    }
#ifdef __VERSION__
    printf("compiler: %s\n", __VERSION__);
#endif
}

/* ======================================================================== */
/* Models written here                                                      */
/* ======================================================================== */

/* the blog's code, as printed (see the top) */
static double xlf_eval(double g, double u)
{
    double g2 = g * g;
    double denom = 1 + g2 - 2 * g * u;
    double r = 1.5 * ((1 - g2) / (2 + g2)) * ((1 + u * u) / denom) + g * u;
    return 1.0 / (4.0 * PI) * r;
}

/* ---- tables: N nodes at s = 0 .. 1 (s = 0 is the forward direction) ---- */

enum { WARP_THETA, WARP_BLEND };

/* The warped coordinate, x = (1 - u)/2 = sin^2(theta/2):
 *   s = 0.3 x^(1/4) + 0.35 (sqrt(x) + 1 - sqrt(1 - x)).
 * The second term is linear in theta at both ends (sqrt(x) ~ theta/2,
 * sqrt(1 - x) ~ (pi - theta)/2), the first crowds nodes into the forward
 * peak (theta ~ s^2).  Three square roots, no acos.  Chosen by measurement
 * at these sizes among sqrt(x) (= sin(theta/2)), x^(1/4), log(1 + 1e4 x)
 * and blends: x^(1/4) alone has the lowest L1 at 16 entries but is coarse
 * backwards (the glory): logRMS 6x to hundreds of times that of uniform
 * theta at 256-1024 entries.  Against uniform theta this blend has a lower
 * L1 at every size and N (up to 8x), a lower logRMS at 16-64 entries (up to
 * 8x), and up to 1.6x the logRMS at 256-1024 entries for 2-5 um. */
static double warp_s(double u)
{
    double x = 0.5 - 0.5 * u, r = sqrt(x);
    return 0.3 * sqrt(r) + 0.35 * (r + 1 - sqrt(0.5 + 0.5 * u));
}

/* |ds/du| of warp_s */
static double warp_ds(double u)
{
    double x = 0.5 - 0.5 * u, y = 0.5 + 0.5 * u;
    return 0.5 * (0.075 / sqrt(sqrt(x * x * x)) + 0.175 / sqrt(x) + 0.175 / sqrt(y));
}

/* u at table coordinate s in [0, 1] */
static double lut_u(int warp, double s)
{
    double lo = -1, hi = 1;
    int i;
    if (warp == WARP_THETA) return cos(PI * s);
    if (s <= 0) return 1;
    if (s >= 1) return -1;
    for (i = 0; i < 200 && hi - lo > 1e-17; ++i) {  /* bisection: s decreases in u */
        double m = 0.5 * (lo + hi);
        if (warp_s(m) > s) lo = m; else hi = m;
    }
    return 0.5 * (lo + hi);
}

/* |du/ds| */
static double lut_dus(int warp, double s)
{
    if (warp == WARP_THETA) return PI * sin(PI * s);
    return 1 / warp_ds(lut_u(warp, s));
}

static double lut_theta_eval(const double *t, int n, double u)
{
    double x, f;
    int i;
    u = u < -1 ? -1 : (u > 1 ? 1 : u);
    x = acos(u) * ((n - 1) / PI);
    i = (int)x;
    if (i > n - 2) i = n - 2;
    f = x - i;
    return t[i] + f * (t[i + 1] - t[i]);
}

static double lut_warp_eval(const double *t, int n, double u)
{
    double x, f;
    int i;
    u = u < -1 ? -1 : (u > 1 ? 1 : u);
    x = warp_s(u) * (n - 1);
    i = (int)x;
    if (i > n - 2) i = n - 2;
    f = x - i;
    return t[i] + f * (t[i + 1] - t[i]);
}

/* 2 pi int p du of the interpolant (5-point Gauss-Legendre per interval) */
static double lut_integral(int warp, const double *t, int n)
{
    static const double gx[5] = { -0.9061798459386640, -0.5384693101056831, 0,
                                  0.5384693101056831, 0.9061798459386640 };
    static const double gw[5] = { 0.2369268850561891, 0.4786286704993665,
                                  0.5688888888888889, 0.4786286704993665,
                                  0.2369268850561891 };
    double h = 1.0 / (n - 1), sum = 0;
    int i, k;
    for (i = 0; i + 1 < n; ++i)
        for (k = 0; k < 5; ++k) {
            double f = 0.5 + 0.5 * gx[k], s = (i + f) * h;
            sum += 0.5 * h * gw[k] * (t[i] + f * (t[i + 1] - t[i])) * lut_dus(warp, s);
        }
    return 2 * PI * sum;
}

/* ======================================================================== */
/* Per diameter: the Mie reference and each model's parameters              */
/* ======================================================================== */

typedef struct {
    double g_mie, g_cs, g_dr, a_dr, k_sch;
    mist_fog fog;
    double *lut[2][NLUT];
    double lut_raw[2][NLUT];           /* integral before scaling */
    mist_tab *tab[NLUT];               /* mist_tab through adaptive nodes */
    size_t tab_n[NLUT];
} diam;

static diam D[ND];
static double ref[ND][NTH];

/* the Mie phase function of fitref_mie's fog at arbitrary mu */
static void mie_at(double d, const double *m, int n, double *p)
{
    (void)fitref_mie_at(d, m, (size_t)n, p, N_RADII);
}

static double cs_mean_cos(double g) { return 3 * g * (4 + g * g) / (5 * (2 + g * g)); }

static double cs_g_for(double gm)
{
    double lo = 0, hi = 1;
    int i;
    for (i = 0; i < 80; ++i) {
        double m = 0.5 * (lo + hi);
        if (cs_mean_cos(m) < gm) lo = m; else hi = m;
    }
    return 0.5 * (lo + hi);
}

/* logRMS of Draine(g, 10^la) against the reference whose log10 is lref */
static double dr_obj(const double *lref, double g, double la)
{
    double a = pow(10, la), s = 0;
    int i;
    if (g < -0.99 || g > 0.999 || la < -4 || la > 5) return 1e300;
    for (i = 0; i < NTH; ++i) {
        double l = log10(mist_draine_eval(g, a, mu[i])) - lref[i];
        s += wq[i] / PI * l * l;
    }
    return sqrt(s);
}

static void draine_fit(const double *r, double *g_out, double *a_out)
{
    static double lref[NTH];
    double bg = 0, bl = 0, bj = 1e300, sg = 0.02, sl = 0.25;
    int i, j, it;
    for (i = 0; i < NTH; ++i) lref[i] = log10(r[i]);
    for (i = 0; i < 50; ++i)            /* g = 0 .. 0.98, log10 alpha = -2 .. 4 */
        for (j = 0; j <= 24; ++j) {
            double jj = dr_obj(lref, 0.02 * i, -2 + 0.25 * j);
            if (jj < bj) { bj = jj; bg = 0.02 * i; bl = -2 + 0.25 * j; }
        }
    for (it = 0; it < 400 && sg > 1e-5; ++it) {   /* compass search */
        static const int dg[8] = { 1, -1, 0, 0, 1, 1, -1, -1 };
        static const int dl[8] = { 0, 0, 1, -1, 1, -1, 1, -1 };
        int k, moved = 0;
        for (k = 0; k < 8; ++k) {
            double jj = dr_obj(lref, bg + dg[k] * sg, bl + dl[k] * sl);
            if (jj < bj) { bj = jj; bg += dg[k] * sg; bl += dl[k] * sl; moved = 1; break; }
        }
        if (!moved) { sg *= 0.5; sl *= 0.5; }
    }
    *g_out = bg; *a_out = pow(10, bl);
}

/* ======================================================================== */
/* Part 1 models: evaluation (for the errors) and timing                    */
/* ======================================================================== */

enum { M_HG, M_CS, M_DR, M_SCH, M_XLF, M_FOG, M_LUT };   /* M_LUT + 4 w + k; w = 2: mist_tab */

static const char *model_name(int m, char *buf)
{
    static const char *nm[] = { "HG (Mie g)", "Cornette-Shanks (same mean cosine)",
                                "Draine, (g, alpha) fitted", "Schlick (not in mist)",
                                "XLF **INVALID: not a density**", "Jendersie-d'Eon fit" };
    if (m < M_LUT) return nm[m];
    if ((m - M_LUT) / NLUT == 2) {
        sprintf(buf, "mist_tab, adaptive nodes, at most %d", LUT_N[(m - M_LUT) % NLUT]);
        return buf;
    }
    sprintf(buf, "LUT %s, %d entries", (m - M_LUT) / NLUT == 0 ? "uniform theta" : "warped",
            LUT_N[(m - M_LUT) % NLUT]);
    return buf;
}

static double model_eval(int m, const diam *q, double u)
{
    switch (m) {
    case M_HG:  return mist_hg_eval(q->g_mie, u);
    case M_CS:  return mist_cs_eval(q->g_cs, u);
    case M_DR:  return mist_draine_eval(q->g_dr, q->a_dr, u);
    case M_SCH: return alt_schlick_eval(q->k_sch, u);
    case M_XLF: return xlf_eval(q->g_mie, u);
    case M_FOG: return mist_fog_eval(q->fog, u);
    default: {
        int w = (m - M_LUT) / NLUT, k = (m - M_LUT) % NLUT;
        if (w == 2) return mist_tab_eval(q->tab[k], u, NULL);
        return w == 0 ? lut_theta_eval(q->lut[0][k], LUT_N[k], u)
                      : lut_warp_eval(q->lut[1][k], LUT_N[k], u);
    }
    }
}

/* the parameters the timed loops read */
static double cg, ca, ck;
static mist_fog cfog;
static const double *ct;
static int cn;
static const mist_tab *ctab;

#define LOOP(T, EXPR) { T s = 0; int i; for (i = 0; i < NB; ++i) s += EXPR; return (double)s; }

static double t_hg_e(void)   LOOP(double, mist_hg_eval(cg, ub[i]))
static double t_cs_e(void)   LOOP(double, mist_cs_eval(cg, ub[i]))
static double t_dr_e(void)   LOOP(double, mist_draine_eval(cg, ca, ub[i]))
static double t_sch_e(void)  LOOP(double, alt_schlick_eval(ck, ub[i]))
static double t_xlf_e(void)  LOOP(double, xlf_eval(cg, ub[i]))
static double t_fog_e(void)  LOOP(double, mist_fog_eval(cfog, ub[i]))
static double t_lutt_e(void) LOOP(double, lut_theta_eval(ct, cn, ub[i]))
static double t_lutw_e(void) LOOP(double, lut_warp_eval(ct, cn, ub[i]))
static double t_tab_e(void)  LOOP(double, mist_tab_eval(ctab, ub[i], NULL))
static double t_tab_s(void)  LOOP(double, mist_tab_sample(ctab, xb[i]))
static double t_hg_s(void)   LOOP(double, mist_hg_sample(cg, xb[i]))
static double t_cs_s(void)   LOOP(double, mist_cs_sample(cg, xb[i]))
static double t_dr_s(void)   LOOP(double, mist_draine_sample(cg, ca, xb[i]))
static double t_sch_s(void)  LOOP(double, alt_schlick_sample(ck, xb[i]))
static double t_fog_s(void)  LOOP(double, mist_fog_sample(cfog, xb[i]))

/* Part 2 samplers */
static float cgf, caf;
static double t_eq6f(void)   LOOP(float, draine_eq6f(cgf, caf, xbf[i]))
static double t_eq6d(void)   LOOP(double, draine_eq6(cg, ca, xb[i]))
static double t_mistf(void)  LOOP(float, mist_draine_samplef(cgf, caf, xbf[i]))
static double t_mistd(void)  LOOP(double, mist_draine_sample(cg, ca, xb[i]))
static mist_phase  cph;         /* prepared once per job (job_setup) */
static mist_phasef cphf;
static double t_prepf(void)  LOOP(float, mist_phase_samplef(&cphf, xbf[i]))
static double t_prepd(void)  LOOP(double, mist_phase_sample(&cph, xb[i]))
static double t_hg3f(void)   LOOP(float, hg_sample_printed(cgf, xbf[i]))
static double t_hg3d(void)   LOOP(double, hg_sample_printed_d(cg, xb[i]))
static double t_hgf(void)    LOOP(float, mist_hg_samplef(cgf, xbf[i]))
static double t_hgd(void)    LOOP(double, mist_hg_sample(cg, xb[i]))

/* Timing jobs: a loop and the parameters it reads.  Each is timed as
 * bench/mist_bench.c does: a warm-up, then REPS repetitions in a row, the
 * median.  (Timed round-robin instead, one repetition of each job per round,
 * the acos table and the HG sampler come out 10-25% slower: colder caches
 * and predictors.) */
typedef struct {
    bench_fn fn;
    double g, a, k;
    mist_fog fog;
    const double *t;
    const mist_tab *tab;
    int n;
    double *out;
    double ts[REPS];
} job;

#define MAXJOB 256
static job jobs[MAXJOB];
static int njobs;

static void add_job(bench_fn fn, double g, double a, double k, mist_fog fog, const double *t,
                    int n, double *out)
{
    job *j = &jobs[njobs++];
    if (njobs > MAXJOB) { fprintf(stderr, "too many timing jobs\n"); exit(1); }
    j->fn = fn; j->g = g; j->a = a; j->k = k; j->fog = fog; j->t = t; j->n = n; j->out = out;
    j->tab = NULL;
}

static void job_setup(const job *j)
{
    cg = j->g; ca = j->a; ck = j->k; cfog = j->fog; ct = j->t; cn = j->n; ctab = j->tab;
    cgf = (float)j->g; caf = (float)j->a;
    if (j->fn == t_prepf) cphf = mist_phase_drainef(cgf, caf);
    if (j->fn == t_prepd) cph = mist_phase_draine(cg, ca);
}

static void run_jobs(void)
{
    int i, r, q, s;
    for (i = 0; i < njobs; ++i) {
        job_setup(&jobs[i]);
        sink += jobs[i].fn();                   /* warm-up */
        for (r = 0; r < REPS; ++r) {
            double t0 = now();
            sink += jobs[i].fn();
            jobs[i].ts[r] = (now() - t0) / NB * 1e9;
        }
    }
    for (i = 0; i < njobs; ++i) {
        double *t = jobs[i].ts, tmp;
        for (q = 0; q < REPS; ++q)
            for (s = q + 1; s < REPS; ++s)
                if (t[s] < t[q]) { tmp = t[q]; t[q] = t[s]; t[s] = tmp; }
        *jobs[i].out = t[REPS / 2];
    }
    njobs = 0;
}

/* the median (of the middle two for even n), min and max of v[0..n), n <= 16 */
static void med_range(const double *v, int n, double *med, double *lo, double *hi)
{
    double t[16], tmp;
    int i, j;
    memcpy(t, v, (size_t)n * sizeof *t);
    for (i = 0; i < n; ++i)
        for (j = i + 1; j < n; ++j)
            if (t[j] < t[i]) { tmp = t[i]; t[i] = t[j]; t[j] = tmp; }
    *med = 0.5 * (t[(n - 1) / 2] + t[n / 2]); *lo = t[0]; *hi = t[n - 1];
}

/* the timing jobs of model m at diameter q: ns per eval into *ne, per
 * sample into *ns (-1: no sampler) */
static void model_jobs(int m, const diam *q, double *ne, double *ns)
{
    mist_fog f0 = q->fog;
    *ns = -1;
    switch (m) {
    case M_HG:  add_job(t_hg_e, q->g_mie, 0, 0, f0, NULL, 0, ne);
                add_job(t_hg_s, q->g_mie, 0, 0, f0, NULL, 0, ns); break;
    case M_CS:  add_job(t_cs_e, q->g_cs, 0, 0, f0, NULL, 0, ne);
                add_job(t_cs_s, q->g_cs, 0, 0, f0, NULL, 0, ns); break;
    case M_DR:  add_job(t_dr_e, q->g_dr, q->a_dr, 0, f0, NULL, 0, ne);
                add_job(t_dr_s, q->g_dr, q->a_dr, 0, f0, NULL, 0, ns); break;
    case M_SCH: add_job(t_sch_e, 0, 0, q->k_sch, f0, NULL, 0, ne);
                add_job(t_sch_s, 0, 0, q->k_sch, f0, NULL, 0, ns); break;
    case M_XLF: add_job(t_xlf_e, q->g_mie, 0, 0, f0, NULL, 0, ne); break;
    case M_FOG: add_job(t_fog_e, 0, 0, 0, f0, NULL, 0, ne);
                add_job(t_fog_s, 0, 0, 0, f0, NULL, 0, ns); break;
    default: {
        int w = (m - M_LUT) / NLUT, k = (m - M_LUT) % NLUT;
        if (w == 2) {
            add_job(t_tab_e, 0, 0, 0, f0, NULL, 0, ne);
            jobs[njobs - 1].tab = q->tab[k];
            add_job(t_tab_s, 0, 0, 0, f0, NULL, 0, ns);
            jobs[njobs - 1].tab = q->tab[k];
            break;
        }
        add_job(w == 0 ? t_lutt_e : t_lutw_e, 0, 0, 0, f0, q->lut[w][k], LUT_N[k], ne);
    }
    }
}

/* ======================================================================== */
/* SVG                                                                      */
/* ======================================================================== */

typedef struct {
    double x, y, xlo, xhi, ylo, yhi;   /* centre and bars (lo = hi: none) */
    const char *label;
    const char *color;
    int shape;                         /* 0 circle 1 square 2 diamond 3 triangle 4 cross */
    int hollow;                        /* outline only (overlaps stay visible) */
    int invalid;                       /* flag: dashed red ring, red bold label */
    int series;                        /* > 0: joined to the others of its series */
    double size;
} pt;

typedef struct { double y; const char *label; } hline;

typedef struct { double x0, y0, x1, y1; } box;
static box placed[256];
static int n_placed;

static int overlaps(box b)
{
    int i;
    for (i = 0; i < n_placed; ++i)
        if (b.x0 < placed[i].x1 && placed[i].x0 < b.x1 && b.y0 < placed[i].y1
            && placed[i].y0 < b.y1)
            return 1;
    return 0;
}

static void svg_marker(FILE *f, double x, double y, int shape, double r, const char *c,
                       int hollow)
{
    char paint[64];
    if (hollow) sprintf(paint, "fill='none' stroke='%s' stroke-width='2'", c);
    else sprintf(paint, "fill='%s'", c);
    switch (shape) {
    case 0: fprintf(f, "<circle cx='%.1f' cy='%.1f' r='%.1f' %s/>\n", x, y, r, paint); break;
    case 1: fprintf(f, "<rect x='%.1f' y='%.1f' width='%.1f' height='%.1f' %s/>\n",
                    x - r, y - r, 2 * r, 2 * r, paint); break;
    case 2: fprintf(f, "<polygon points='%.1f,%.1f %.1f,%.1f %.1f,%.1f %.1f,%.1f' %s/>\n",
                    x, y - 1.3 * r, x + 1.3 * r, y, x, y + 1.3 * r, x - 1.3 * r, y, paint); break;
    case 3: fprintf(f, "<polygon points='%.1f,%.1f %.1f,%.1f %.1f,%.1f' %s/>\n",
                    x, y - 1.3 * r, x + 1.2 * r, y + 0.9 * r, x - 1.2 * r, y + 0.9 * r, paint);
            break;
    default:
        fprintf(f, "<path d='M%.1f,%.1f L%.1f,%.1f M%.1f,%.1f L%.1f,%.1f' stroke='%s' "
                "stroke-width='3'/>\n", x - r, y - r, x + r, y + r, x - r, y + r, x + r, y - r, c);
    }
}

static double nice_lo(double v) /* largest 1-2-5 x 10^k <= v */
{
    double e = pow(10, floor(log10(v))), m = v / e;
    return (m >= 5 ? 5 : m >= 2 ? 2 : 1) * e;
}
static double nice_hi(double v)
{
    double e = pow(10, floor(log10(v))), m = v / e;
    return (m <= 1 ? 1 : m <= 2 ? 2 : m <= 5 ? 5 : 10) * e;
}

/* One panel: log x, log y, dashed reference lines.  Labels are placed where
 * they hit no marker and no earlier label (flagged points first); a label
 * that finds no room is left out (the legend names every marker), except a
 * flagged one. */
static void svg_panel(FILE *f, double ox, double oy, double w, double h, const char *title,
                      const char *xlab, const char *ylab, const pt *p, int n, const char *note,
                      const hline *hl, int nh)
{
    double xmin = 1e300, xmax = 0, ymin = 1e300, ymax = 0, lx0, lx1, ly0, ly1, v;
    int i, j, s, e, pass;
#define PX(x) (ox + (log10(x) - lx0) / (lx1 - lx0) * w)
#define PY(y) (oy + h - (log10(y) - ly0) / (ly1 - ly0) * h)
    /* ranges over the positive finite values only (bars of lo = hi = 0 are
     * absent), then clamped, so that the loops below stay bounded */
    for (i = 0; i < n + nh; ++i) {
        double v6[6];
        int q;
        if (i < n) {
            v6[0] = p[i].x; v6[1] = p[i].xlo; v6[2] = p[i].xhi;
            v6[3] = p[i].y; v6[4] = p[i].ylo; v6[5] = p[i].yhi;
        } else {
            v6[0] = v6[1] = v6[2] = 0;
            v6[3] = v6[4] = v6[5] = hl[i - n].y;
        }
        for (q = 0; q < 6; ++q) {
            if (!(v6[q] > 0 && v6[q] < 1e300)) continue;
            if (q < 3 && v6[q] < xmin) xmin = v6[q];
            if (q < 3 && v6[q] > xmax) xmax = v6[q];
            if (q >= 3 && v6[q] < ymin) ymin = v6[q];
            if (q >= 3 && v6[q] > ymax) ymax = v6[q];
        }
    }
    if (!(xmax > 0)) { xmin = 1; xmax = 10; }
    if (!(ymax > 0)) { ymin = 1e-3; ymax = 1; }
    if (xmin < 1e-3) xmin = 1e-3;
    if (xmax > 1e6) xmax = 1e6;
    if (ymin < 1e-20) ymin = 1e-20;
    if (ymax > 1e5) ymax = 1e5;
    xmin = nice_lo(xmin / 1.15); xmax = nice_hi(xmax * 1.3);
    lx0 = log10(xmin); lx1 = log10(xmax);
    ly0 = floor(log10(ymin) - 0.15); ly1 = ceil(log10(ymax) + 0.3);
    fprintf(f, "<text x='%.1f' y='%.1f' font-size='15' font-weight='bold'>%s</text>\n",
            ox, oy - 12, title);
    fprintf(f, "<rect x='%.1f' y='%.1f' width='%.1f' height='%.1f' fill='white' "
            "stroke='#444'/>\n", ox, oy, w, h);
    /* y grid: decades */
    for (e = (int)ly0; e <= (int)ly1; ++e) {
        double y = PY(pow(10, e));
        if (e > ly0 && e < ly1)
            fprintf(f, "<line x1='%.1f' y1='%.1f' x2='%.1f' y2='%.1f' stroke='#e2e2e2'/>\n",
                    ox, y, ox + w, y);
        if (e == 0)
            fprintf(f, "<text x='%.1f' y='%.1f' font-size='12' text-anchor='end'>1</text>\n",
                    ox - 5, y + 4);
        else
            fprintf(f, "<text x='%.1f' y='%.1f' font-size='12' text-anchor='end'>10"
                    "<tspan dy='-6' font-size='9'>%d</tspan></text>\n", ox - 5, y + 4, e);
    }
    /* x grid: 1, 2, 5 x 10^k */
    for (e = (int)floor(lx0); e <= (int)ceil(lx1); ++e)
        for (s = 0; s < 3; ++s) {
            static const double m[3] = { 1, 2, 5 };
            double x;
            v = m[s] * pow(10, e);
            if (v < xmin * 0.999 || v > xmax * 1.001) continue;
            x = PX(v);
            if (v > xmin * 1.001 && v < xmax * 0.999)
                fprintf(f, "<line x1='%.1f' y1='%.1f' x2='%.1f' y2='%.1f' stroke='#e2e2e2'/>\n",
                        x, oy, x, oy + h);
            fprintf(f, "<text x='%.1f' y='%.1f' font-size='12' text-anchor='middle'>%g</text>\n",
                    x, oy + h + 16, v);
        }
    fprintf(f, "<text x='%.1f' y='%.1f' font-size='13' text-anchor='middle'>%s</text>\n",
            ox + w / 2, oy + h + 36, xlab);
    fprintf(f, "<text x='%.1f' y='%.1f' font-size='13' text-anchor='middle' "
            "transform='rotate(-90 %.1f %.1f)'>%s</text>\n",
            ox - 48, oy + h / 2, ox - 48, oy + h / 2, ylab);
    n_placed = 0;
    for (i = 0; i < nh; ++i) {
        double y = PY(hl[i].y);
        box b;
        fprintf(f, "<line x1='%.1f' y1='%.1f' x2='%.1f' y2='%.1f' stroke='#888' "
                "stroke-dasharray='6,4'/>\n", ox, y, ox + w, y);
        fprintf(f, "<text x='%.1f' y='%.1f' font-size='11' fill='#666' text-anchor='end'>%s"
                "</text>\n", ox + w - 6, y - 4, hl[i].label);
        b.x1 = ox + w - 6; b.x0 = b.x1 - 6.3 * (double)strlen(hl[i].label);
        b.y0 = y - 16; b.y1 = y - 2;
        placed[n_placed++] = b;
    }
    if (note) {
        box b;
        fprintf(f, "<text x='%.1f' y='%.1f' font-size='12' fill='#c00'>%s</text>\n",
                ox + 8, oy + h - 10, note);
        b.x0 = ox; b.x1 = ox + 8 + 6.5 * (double)strlen(note); b.y0 = oy + h - 24; b.y1 = oy + h;
        placed[n_placed++] = b;
    }
    /* series lines, bars, markers */
    for (i = 0; i < n; ++i)
        for (j = i + 1; j < n; ++j)
            if (p[i].series > 0 && p[j].series == p[i].series) {
                fprintf(f, "<line x1='%.1f' y1='%.1f' x2='%.1f' y2='%.1f' stroke='%s' "
                        "stroke-width='1.5'/>\n", PX(p[i].x), PY(p[i].y), PX(p[j].x),
                        PY(p[j].y), p[i].color);
                break;
            }
    for (i = 0; i < n; ++i) {
        double x = PX(p[i].x), y = PY(p[i].y), r = p[i].size;
        box b;
        if (p[i].yhi > p[i].ylo)
            fprintf(f, "<path d='M%.1f,%.1f L%.1f,%.1f M%.1f,%.1f L%.1f,%.1f M%.1f,%.1f "
                    "L%.1f,%.1f' stroke='%s' stroke-width='1.2' opacity='0.7'/>\n",
                    x, PY(p[i].ylo), x, PY(p[i].yhi), x - 3, PY(p[i].ylo), x + 3,
                    PY(p[i].ylo), x - 3, PY(p[i].yhi), x + 3, PY(p[i].yhi), p[i].color);
        if (p[i].xhi > p[i].xlo) {
            fprintf(f, "<path d='M%.1f,%.1f L%.1f,%.1f M%.1f,%.1f L%.1f,%.1f M%.1f,%.1f "
                    "L%.1f,%.1f' stroke='%s' stroke-width='1.2' opacity='0.7'/>\n",
                    PX(p[i].xlo), y, PX(p[i].xhi), y, PX(p[i].xlo), y - 3, PX(p[i].xlo),
                    y + 3, PX(p[i].xhi), y - 3, PX(p[i].xhi), y + 3, p[i].color);
            b.x0 = PX(p[i].xlo) - 1; b.x1 = PX(p[i].xhi) + 1; b.y0 = y - 4; b.y1 = y + 4;
            placed[n_placed++] = b;             /* no label across the bar */
        }
        if (p[i].invalid)
            fprintf(f, "<circle cx='%.1f' cy='%.1f' r='%.1f' fill='none' stroke='#d00' "
                    "stroke-width='2' stroke-dasharray='4,3'/>\n", x, y, r + 6);
        svg_marker(f, x, y, p[i].shape, r, p[i].color, p[i].hollow);
        b.x0 = x - r - 2; b.x1 = x + r + 2; b.y0 = y - r - 2; b.y1 = y + r + 2;
        placed[n_placed++] = b;
    }
    for (pass = 0; pass < 2; ++pass)           /* flagged labels first */
        for (i = 0; i < n; ++i) {
            double x = PX(p[i].x), y = PY(p[i].y), r = p[i].size + (p[i].invalid ? 7 : 2);
            double tw = (p[i].invalid ? 7.4 : 7.0) * (double)strlen(p[i].label), th = 13;
            box b, first;
            int k, found = 0;
            if (!p[i].label[0] || (pass == 0) != (p[i].invalid != 0)) continue;
            for (k = 0; k < 24 && !found; ++k) {  /* 8 directions, 3 distances */
                static const int cx[8] = { 1, -1, 0, 0, 1, 1, -1, -1 };
                static const int cy[8] = { 0, 0, -1, 1, -1, 1, -1, 1 };
                double d = 3 + 9 * (k / 8);
                b.x0 = cx[k % 8] > 0 ? x + r + d : cx[k % 8] < 0 ? x - r - d - tw : x - tw / 2;
                b.y0 = cy[k % 8] < 0 ? y - r - d - th : cy[k % 8] > 0 ? y + r + d : y - th / 2;
                b.x1 = b.x0 + tw; b.y1 = b.y0 + th;
                if (k == 0) first = b;
                if (b.x0 >= ox + 2 && b.x1 <= ox + w - 2 && b.y0 >= oy + 2
                    && b.y1 <= oy + h - 2 && !overlaps(b))
                    found = 1;
            }
            if (!found && !p[i].invalid) continue;
            if (!found) b = first;
            placed[n_placed++] = b;
            fprintf(f, "<text x='%.1f' y='%.1f' font-size='%s' fill='%s'%s>%s</text>\n", b.x0,
                    b.y1 - 3, p[i].invalid ? "12" : "11", p[i].invalid ? "#d00" : "#222",
                    p[i].invalid ? " font-weight='bold'" : "", p[i].label);
        }
#undef PX
#undef PY
}

/* ======================================================================== */

/* an error for the table: 3 decimals, 2 significant digits below 0.01 */
static const char *num(double v)
{
    static char b[8][32];
    static int k;
    k = (k + 1) % 8;
    if (v >= 0.01 || v == 0) sprintf(b[k], "%.3f", v);
    else sprintf(b[k], "%.2g", v);
    return b[k];
}

/* the median of 4: the mean of the middle two */
static double median4(const double *v)
{
    double t[4], tmp;
    int i, j;
    memcpy(t, v, sizeof t);
    for (i = 0; i < 4; ++i)
        for (j = i + 1; j < 4; ++j)
            if (t[j] < t[i]) { tmp = t[i]; t[i] = t[j]; t[j] = tmp; }
    return 0.5 * (t[1] + t[2]);
}

static double gmean(const double *v, int n)
{
    double s = 0;
    int i;
    for (i = 0; i < n; ++i) s += log(v[i]);
    return exp(s / n);
}

int main(int argc, char **argv)
{
    static const char *colors[NM] = { "#1f77b4", "#ff7f0e", "#2ca02c", "#9467bd", "#d00000",
                                      "#000000", "#8c564b", "#8c564b", "#8c564b", "#8c564b",
                                      "#17becf", "#17becf", "#17becf", "#17becf",
                                      "#e377c2", "#e377c2", "#e377c2", "#e377c2" };
    static const int shapes[NM] = { 0, 1, 2, 3, 4, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2 };
    static const double SG[4] = { 0.01, 0.1, 0.5, 0.9 }, SA[3] = { 1, 17, 250 };
    static const char *short_name[NM] = { "HG", "CS", "Draine fit", "Schlick",
                                          "XLF: INVALID, not a density", "JD23 fit",
                                          "LUT \xce\xb8 16", "64", "256", "1024",
                                          "LUT warped 16", "64", "256", "1024",
                                          "mist_tab \xe2\x89\xa4" "16", "\xe2\x89\xa4" "64",
                                          "\xe2\x89\xa4" "256", "\xe2\x89\xa4" "1024" };
    const char *legend_text[M_LUT + 3] = {
        "HG, g = the Mie asymmetry (mist_hg_eval)",
        "Cornette-Shanks, same mean cosine as Mie (mist_cs_eval)",
        "Draine, (g, \xce\xb1) fitted to Mie by logRMS (mist_draine_eval)",
        "Schlick, k = 1.55g \xe2\x88\x92 0.55g\xc2\xb3 (not in mist)",
        "",
        "Jendersie-d'Eon fit, HG + Draine (mist_fog_from_diameter)",
        "LUT uniform in \xce\xb8 (acos), 16 / 64 / 256 / 1024 entries",
        "LUT in a warped coordinate (3 sqrt), 16 / 64 / 256 / 1024 entries",
        "mist_tab (exact sampling), adaptive nodes, at most 16 / 64 / 256 / 1024" };
    char defout[4096];
    const char *out = argc > 1 ? argv[1] : beside_program(defout, sizeof defout, argv[0],
                                                          "tradeoff.svg");
    double l1[NM][ND], lr[NM][ND], ne[NM][ND], nsa[NM][ND], ne_m[NM], ns_m[NM];
    double t_start = now(), xlf_int[ND], xlf_min[ND], xlf_neg[ND];
    int neg[NM];
    char buf[64];
    int i, k, m, w;
    unsigned long long rs = 88172645463325252ULL;
    FILE *f;

    (void)fitref_compare;               /* in mist_fitref.h; not used here */
    for (i = 0; i < NB; ++i) {
        rs ^= rs << 13; rs ^= rs >> 7; rs ^= rs << 17;
        xb[i] = (double)(rs >> 11) * 0x1p-53;
        ub[i] = 2 * xb[i] - 1;
        xbf[i] = (float)xb[i];
    }
    machine();
    fitref_grid();

    /* ---- references, parameters, tables --------------------------------- */
    for (k = 0; k < ND; ++k) {
        diam *q = &D[k];
        int tot = 0, off = 0;
        double *nodes, *vals;
        for (i = 0; i < NLUT; ++i) tot += 2 * LUT_N[i];
        nodes = (double *)malloc(sizeof(double) * tot);
        vals  = (double *)malloc(sizeof(double) * tot);
        if (!nodes || !vals) return 1;
        q->g_mie = fitref_mie(DS[k], ref[k], N_RADII);
        q->g_cs = cs_g_for(q->g_mie);
        q->k_sch = alt_schlick_k(q->g_mie);
        q->fog = mist_fog_from_diameter(DS[k]);
        draine_fit(ref[k], &q->g_dr, &q->a_dr);
        for (w = 0; w < 2; ++w)
            for (i = 0; i < NLUT; ++i) {
                int j;
                for (j = 0; j < LUT_N[i]; ++j)
                    nodes[off + j] = lut_u(w, (double)j / (LUT_N[i] - 1));
                off += LUT_N[i];
            }
        mie_at(DS[k], nodes, tot, vals);
        off = 0;
        for (w = 0; w < 2; ++w)
            for (i = 0; i < NLUT; ++i) {
                int j;
                double *t = (double *)malloc(sizeof(double) * LUT_N[i]), c;
                if (!t) return 1;
                memcpy(t, vals + off, sizeof(double) * LUT_N[i]);
                off += LUT_N[i];
                q->lut_raw[w][i] = c = lut_integral(w, t, LUT_N[i]);
                for (j = 0; j < LUT_N[i]; ++j) t[j] /= c;
                q->lut[w][i] = t;
            }
        free(nodes); free(vals);
        for (i = 0; i < NLUT; ++i) {           /* mist_tab: the best of at most N nodes */
            mist_mie_wavelength wl[3];
            mist_mie_dist dist = mist_mie_dist_lognormal(DS[k] / 2, 1.1);
            mist_mie_tabfit tf;
            double *tmu = (double *)malloc(sizeof(double) * 2 * LUT_N[i]), *tp = tmu + LUT_N[i];
            size_t bytes;
            if (!tmu) return 1;
            wl[0] = mist_mie_wl(0.45, 1, mist_mie_water(450, NULL));
            wl[1] = mist_mie_wl(0.55, 1, mist_mie_water(550, NULL));
            wl[2] = mist_mie_wl(0.65, 1, mist_mie_water(650, NULL));
            dist.n_radii = N_RADII;
            tf = mist_mie_tab_nodes(&dist, wl, 3, 0, 1.0, 1e-9, 1e-9, (size_t)LUT_N[i], tmu, tp);
            bytes = mist_tab_bytes(tf.n, 1);
            q->tab[i] = (mist_tab *)malloc(bytes ? bytes : 1);
            q->tab_n[i] = tf.n;
            if (tf.status != MIST_MIE_OK || !q->tab[i]
                || mist_tab_init(q->tab[i], bytes, tmu, tp, tf.n, 1) != 0) {
                fprintf(stderr, "mist_tab at d = %g failed\n", DS[k]);
                return 1;
            }
            free(tmu);
        }
    }

    /* ---- errors and costs ----------------------------------------------- */
    for (m = 0; m < NM; ++m) {
        neg[m] = 0; ne_m[m] = 0; ns_m[m] = 0;
        for (k = 0; k < ND; ++k) {
            static double p[NTH];
            for (i = 0; i < NTH; ++i) {
                p[i] = model_eval(m, &D[k], mu[i]);
                if (!(p[i] > 0)) neg[m] = 1;
            }
            fitref_errors(p, ref[k], &l1[m][k], &lr[m][k]);
            model_jobs(m, &D[k], &ne[m][k], &nsa[m][k]);
        }
    }
    run_jobs();
    for (m = 0; m < NM; ++m) {
        ne_m[m] = median4(ne[m]);
        ns_m[m] = median4(nsa[m]);
    }
    /* XLF: its integral, minimum and where it is negative, at each Mie g */
    for (k = 0; k < ND; ++k) {
        double s = 0, mn = 1e300, un = -2, g = D[k].g_mie;
        int nq = 200000;
        for (i = 0; i < nq; ++i) {
            double u = -1 + (i + 0.5) * 2.0 / nq, v = xlf_eval(g, u);
            s += v * 2.0 / nq;
            if (v < mn) mn = v;
            if (v < 0) un = u;                  /* the largest u with v < 0 */
        }
        xlf_int[k] = 2 * PI * s; xlf_min[k] = mn;
        xlf_neg[k] = un > -2 ? acos(un) * 180 / PI : 180;
    }

    printf("\nLorenz-Mie reference: tests/mist_fitref.h (water, 450/550/650 nm, lognormal "
           "width 1.1, %d radii, %d angles).\n", N_RADII, NTH);
    printf("Costs: ns per call in double, 4096 random inputs, median of %d repetitions, "
           "median over the %d diameters.\n\n", REPS, ND);

    printf("### Parameters per diameter\n\n");
    printf("| d (um) | Mie g | CS g (same mean cosine) | Draine fit g | Draine fit alpha "
           "| Schlick k | JD23 fit g_hg, g_d, alpha, w_d |\n|---|---|---|---|---|---|---|\n");
    for (k = 0; k < ND; ++k)
        printf("| %g | %.4f | %.4f | %.4f | %.3g | %.4f | %.4f, %.4f, %.2f, %.4f |\n", DS[k],
               D[k].g_mie, D[k].g_cs, D[k].g_dr, D[k].a_dr, D[k].k_sch, D[k].fog.g_hg,
               D[k].fog.g_d, D[k].fog.alpha, D[k].fog.w_d);

    printf("\nXLF is not a probability density (blog code, as printed). Its integral over "
           "the sphere at the Mie g of these droplets:");
    for (k = 0; k < ND; ++k) printf(" %.3f (d = %g)", xlf_int[k], DS[k]);
    printf("; minimum %.3f /sr (d = %g); negative beyond theta = %.0f deg (d = %g) to "
           "%.0f deg (d = %g).", xlf_min[ND - 1], DS[ND - 1], xlf_neg[ND - 1], DS[ND - 1],
           xlf_neg[0], DS[0]);
    {
        static const double eg[3] = { 0.2, 0.5, 0.9 };
        printf(" Errata check, integral:");
        for (i = 0; i < 3; ++i) {
            double s = 0, mn = 1e300;
            int j, nq = 200000;
            for (j = 0; j < nq; ++j) {
                double v = xlf_eval(eg[i], -1 + (j + 0.5) * 2.0 / nq);
                s += v * 2.0 / nq;
                if (v < mn) mn = v;
            }
            printf(" %.3f (g = %g)%s", 2 * PI * s, eg[i], i < 2 ? "," : "");
            if (i == 2) printf("; min %.3f /sr at g = 0.9.", mn);
        }
    }
    printf(" Its L1 below is of the function as evaluated; logRMS does not exist (log of "
           "a negative density).\n\n");

    printf("### Phase functions against Lorenz-Mie\n\n");
    printf("| model | ns/eval | ns/sample | L1 d=2 | d=5 | d=10 | d=20 | L1 geo. mean "
           "| logRMS d=2 | d=5 | d=10 | d=20 | logRMS geo. mean |\n"
           "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (m = 0; m < NM; ++m) {
        printf("| %s | %.2f | ", model_name(m, buf), ne_m[m]);
        if (nsa[m][0] >= 0) printf("%.2f |", ns_m[m]); else printf("- |");
        for (k = 0; k < ND; ++k) printf(" %s |", num(l1[m][k]));
        printf(" **%s** |", num(gmean(l1[m], ND)));
        for (k = 0; k < ND; ++k)
            if (neg[m]) printf(" - |"); else printf(" %s |", num(lr[m][k]));
        if (neg[m]) printf(" undefined (p < 0) |\n");
        else printf(" **%s** |\n", num(gmean(lr[m], ND)));
    }
    printf("\nLUT raw integrals (before scaling to 1), d = 2 / 20 um:");
    for (w = 0; w < 2; ++w)
        for (i = 0; i < NLUT; ++i)
            printf(" %s %d: %.3f / %.3f%s", w ? "warped" : "theta", LUT_N[i],
                   D[0].lut_raw[w][i], D[ND - 1].lut_raw[w][i],
                   w == 1 && i == NLUT - 1 ? ".\n" : ";");
    printf("mist_tab nodes placed (d = 2 / 5 / 10 / 20 um):");
    for (i = 0; i < NLUT; ++i)
        printf(" at most %d: %lu / %lu / %lu / %lu%s", LUT_N[i], (unsigned long)D[0].tab_n[i],
               (unsigned long)D[1].tab_n[i], (unsigned long)D[2].tab_n[i],
               (unsigned long)D[3].tab_n[i], i == NLUT - 1 ? ".\n" : ";");

    /* ---- part 2: samplers ------------------------------------------------ */
    {
        enum { NX = 1006, NI = 6, NH = 4 };
        static const char *sname[NI] = { "eq. 6 as printed (float)",
                                         "eq. 6 as printed (double)", "mist float",
                                         "mist double", "mist float, prepared",
                                         "mist double, prepared" };
        static const char *iname[NI] = { "eq. 6 as printed, float", "eq. 6 as printed, double",
                                         "mist_draine_samplef", "mist_draine_sample",
                                         "mist_phase_samplef (prepared)",
                                         "mist_phase_sample (prepared)" };
        double xs[NX], worst[NI], wg[NI][4], at[NI][3], cost[NI][12], med[NI], lo[NI], hi[NI];
        double hworst[NH], hwg[NH][4], hat[NH][2], hcost[NH][4], hmed[NH], hlo[NH], hhi[NH];
        static const double SGH[4] = { 1e-4, 0.01, 0.5, 0.9 };
        static const char *hname[NH] = { "eq. 3 as printed, float", "eq. 3 as printed, double",
                                         "mist_hg_samplef", "mist_hg_sample" };
        static const char *hsname[NH] = { "HG eq. 3 (float)", "HG eq. 3 (double)",
                                          "HG mist float", "HG mist double" };
        static bench_fn hfn[NH] = { t_hg3f, t_hg3d, t_hgf, t_hgd };
        long bad[NI];
        int a, gi, c;
        for (i = 0; i < 1000; ++i) xs[i] = (i + 0.5) / 1000;
        xs[1000] = 1e-7; xs[1001] = 1e-5; xs[1002] = 1e-3;
        xs[1003] = 1 - 1e-3; xs[1004] = 1 - 1e-5; xs[1005] = 1 - 1e-7;
        for (c = 0; c < NI; ++c) {
            worst[c] = 0; bad[c] = 0;
            for (gi = 0; gi < 4; ++gi) wg[c][gi] = 0;
        }
        for (gi = 0; gi < 4; ++gi)
            for (a = 0; a < 3; ++a) {
                double g = SG[gi], al = SA[a];
                float gf = (float)g, af = (float)al;
                mist_phase ph = mist_phase_draine(g, al);
                mist_phasef phf = mist_phase_drainef(gf, af);
                for (i = 0; i < NX; ++i) {
                    float xf = (float)xs[i];
                    double ud = mist_draine_sample(g, al, xs[i]);
                    float uf = mist_draine_samplef(gf, af, xf);
                    double rd = (double)ref_sample_from(g, al, xs[i], ud);
                    double rf = (double)ref_sample_from(gf, af, xf, uf);
                    double u[NI], r[NI];
                    u[0] = draine_eq6f(gf, af, xf);  r[0] = rf;
                    u[1] = draine_eq6(g, al, xs[i]); r[1] = rd;
                    u[2] = uf;                 r[2] = rf;
                    u[3] = ud;                 r[3] = rd;
                    u[4] = mist_phase_samplef(&phf, xf); r[4] = (double)ref_sample_from(gf, af, xf, u[4]);
                    u[5] = mist_phase_sample(&ph, xs[i]); r[5] = (double)ref_sample_from(g, al, xs[i], u[5]);
                    for (c = 0; c < NI; ++c) {
                        double e = fabs(u[c] - r[c]);
                        if (!(u[c] >= -1 && u[c] <= 1)) ++bad[c];
                        if (!(e == e)) e = 2;           /* NaN: count as the worst */
                        if (e > wg[c][gi]) wg[c][gi] = e;
                        if (e > worst[c]) {
                            worst[c] = e; at[c][0] = g; at[c][1] = al;
                            at[c][2] = c == 0 || c == 2 || c == 4 ? (double)xf : xs[i];
                        }
                    }
                }
                add_job(t_eq6f, g, al, 0, D[0].fog, NULL, 0, &cost[0][gi * 3 + a]);
                add_job(t_eq6d, g, al, 0, D[0].fog, NULL, 0, &cost[1][gi * 3 + a]);
                add_job(t_mistf, g, al, 0, D[0].fog, NULL, 0, &cost[2][gi * 3 + a]);
                add_job(t_mistd, g, al, 0, D[0].fog, NULL, 0, &cost[3][gi * 3 + a]);
                add_job(t_prepf, g, al, 0, D[0].fog, NULL, 0, &cost[4][gi * 3 + a]);
                add_job(t_prepd, g, al, 0, D[0].fog, NULL, 0, &cost[5][gi * 3 + a]);
            }
        run_jobs();
        for (c = 0; c < NI; ++c) med_range(cost[c], 12, &med[c], &lo[c], &hi[c]);
        printf("\n### Draine samplers against a __float128 inversion of the exact CDF\n\n"
               "g in {0.01, 0.1, 0.5, 0.9}, alpha in {1, 17, 250}, %d xi each.\n\n", NX);
        printf("| implementation | max abs(u - u*) | at (g, alpha, xi) | g=0.01 | g=0.1 "
               "| g=0.5 | g=0.9 | outside [-1, 1] or NaN | ns/sample median [min..max] |\n"
               "|---|---|---|---|---|---|---|---|---|\n");
        for (c = 0; c < NI; ++c) {
            if (worst[c] > 0)
                printf("| %s | %.2g | (%g, %g, %.9g) |", iname[c], worst[c], at[c][0],
                       at[c][1], at[c][2]);
            else
                printf("| %s | 0 | - |", iname[c]);   /* every sample the rounded root */
            for (gi = 0; gi < 4; ++gi) printf(" %.2g |", wg[c][gi]);
            printf(" %ld of %d | %.2f [%.2f..%.2f] |\n", bad[c], 12 * NX, med[c], lo[c],
                   hi[c]);
        }

        /* the HG samplers the same way: g in SGH (1e-4: eq. 4's isotropic
         * fallback; 0.01: eq. 3's cancellation as 1/g), the same xi */
        for (c = 0; c < NH; ++c) {
            hworst[c] = 0;
            for (gi = 0; gi < 4; ++gi) hwg[c][gi] = 0;
        }
        for (gi = 0; gi < 4; ++gi) {
            double g = SGH[gi];
            float gf = (float)g;
            for (i = 0; i < NX; ++i) {
                float xf = (float)xs[i];
                double u[NH], r[NH];
                u[0] = hg_sample_printed(gf, xf);
                u[1] = hg_sample_printed_d(g, xs[i]);
                u[2] = mist_hg_samplef(gf, xf);
                u[3] = mist_hg_sample(g, xs[i]);
                r[0] = r[2] = (double)ref_sample_from(gf, 0, xf, u[2]);
                r[1] = r[3] = (double)ref_sample_from(g, 0, xs[i], u[3]);
                for (c = 0; c < NH; ++c) {
                    double e = fabs(u[c] - r[c]);
                    if (!(e == e)) e = 2;
                    if (e > hwg[c][gi]) hwg[c][gi] = e;
                    if (e > hworst[c]) {
                        hworst[c] = e; hat[c][0] = g;
                        hat[c][1] = c == 0 || c == 2 ? (double)xf : xs[i];
                    }
                }
            }
            for (c = 0; c < NH; ++c) add_job(hfn[c], g, 0, 0, D[0].fog, NULL, 0, &hcost[c][gi]);
        }
        run_jobs();
        for (c = 0; c < NH; ++c) med_range(hcost[c], 4, &hmed[c], &hlo[c], &hhi[c]);
        printf("\n### HG samplers against a __float128 inversion of the exact CDF\n\n"
               "g in {1e-4, 0.01, 0.5, 0.9}, the same %d xi.\n\n", NX);
        printf("| implementation | max abs(u - u*) | at (g, xi) | g=1e-4 | g=0.01 | g=0.5 "
               "| g=0.9 | ns/sample median [min..max] |\n|---|---|---|---|---|---|---|---|\n");
        for (c = 0; c < NH; ++c) {
            if (hworst[c] > 0)
                printf("| %s | %.2g | (%g, %.9g) |", hname[c], hworst[c], hat[c][0], hat[c][1]);
            else
                printf("| %s | 0 | - |", hname[c]);
            for (gi = 0; gi < 4; ++gi) printf(" %.2g |", hwg[c][gi]);
            printf(" %.2f [%.2f..%.2f] |\n", hmed[c], hlo[c], hhi[c]);
        }

        /* ---- the SVG ----------------------------------------------------- */
        f = fopen(out, "w");
        if (!f) { fprintf(stderr, "cannot write %s\n", out); return 1; }
        fprintf(f, "<?xml version='1.0' encoding='UTF-8'?>\n"
                "<svg xmlns='http://www.w3.org/2000/svg' version='1.1' width='1500' "
                "height='1060' viewBox='0 0 1500 1060' font-family='DejaVu Sans, Helvetica, "
                "Arial, sans-serif'>\n<rect width='1500' height='1060' fill='#fafafa'/>\n");
        fprintf(f, "<text x='20' y='30' font-size='20' font-weight='bold'>mist: error "
                "against run time</text>\n");
        fprintf(f, "<text x='20' y='52' font-size='13'>Phase functions against Lorenz-Mie "
                "for water droplets of d = 2, 5, 10, 20 \xc2\xb5m: marker = geometric mean "
                "over the four diameters, bar = min..max. Lower left is better.</text>\n");
        for (w = 0; w < 2; ++w) {
            pt P[NM];
            int np = 0;
            for (m = 0; m < NM; ++m) {
                double mn = 1e300, mx = 0, *ev = w == 0 ? l1[m] : lr[m];
                pt q;
                if (w == 1 && neg[m]) continue;
                for (k = 0; k < ND; ++k) {
                    if (ev[k] < mn) mn = ev[k];
                    if (ev[k] > mx) mx = ev[k];
                }
                q.x = ne_m[m]; q.xlo = q.xhi = 0;
                q.y = gmean(ev, ND); q.ylo = mn; q.yhi = mx;
                q.color = colors[m]; q.shape = shapes[m]; q.invalid = m == M_XLF;
                q.hollow = m < M_LUT && m != M_FOG && m != M_XLF;
                q.series = m >= M_LUT ? 1 + (m - M_LUT) / NLUT : 0;
                q.size = m >= M_LUT ? 4 : 7;
                q.label = short_name[m];
                P[np++] = q;
            }
            svg_panel(f, 90, w == 0 ? 95 : 580, 620, 400,
                      w == 0 ? "Phase functions: L1 error" : "Phase functions: logRMS error",
                      "ns per evaluation (log scale)",
                      w == 0 ? "L1 = \xe2\x88\xab |p \xe2\x88\x92 p_Mie| d\xce\xa9"
                             : "logRMS = RMS over \xce\xb8 of log10(p / p_Mie)",
                      P, np, w == 1 ? "XLF not shown: p &lt; 0 backwards, no logarithm" : NULL,
                      NULL, 0);
        }
        {
            pt P[NI + NH];
            hline H[2];
            static const char *cl[NI] = { "#d00000", "#ff7f0e", "#17becf", "#1f77b4",
                                          "#2ca02c", "#9467bd" };
            static const int sh[NI] = { 4, 3, 1, 0, 2, 2 };
            static char lb0[80];
            sprintf(lb0, "eq. 6 float: %ld results outside [-1, 1]", bad[0]);
            for (c = 0; c < NI; ++c) {
                P[c].x = med[c]; P[c].xlo = lo[c]; P[c].xhi = hi[c];
                P[c].y = worst[c] > 0 ? worst[c] : 1e-17; P[c].ylo = P[c].yhi = 0;
                P[c].label = c == 0 && bad[0] > 0 ? lb0 : sname[c];
                P[c].color = cl[c]; P[c].shape = sh[c];
                P[c].invalid = 0; P[c].series = 0; P[c].size = 7; P[c].hollow = 0;
            }
            static char lbz[NI + NH][96];   /* an error of 0 is drawn at 1e-17, and says so */
            for (c = 0; c < NI; ++c)
                if (!(worst[c] > 0)) {
                    sprintf(lbz[c], "%s (error 0: drawn at 1e-17)", sname[c]);
                    P[c].label = lbz[c];
                }
            for (c = 0; c < NH; ++c) {          /* HG: hollow, colours as their Draine kin */
                pt *q = &P[NI + c];
                q->x = hmed[c]; q->xlo = hlo[c]; q->xhi = hhi[c];
                q->y = hworst[c] > 0 ? hworst[c] : 1e-17; q->ylo = q->yhi = 0;
                q->label = hsname[c];
                if (!(hworst[c] > 0)) {
                    sprintf(lbz[NI + c], "%s (error 0: drawn at 1e-17)", hsname[c]);
                    q->label = lbz[NI + c];
                }
                q->color = cl[c]; q->shape = sh[c];
                q->invalid = 0; q->series = 0; q->size = 7; q->hollow = 1;
            }
            H[0].y = 0x1p-24; H[0].label = "float: 1 ulp just below 1";
            H[1].y = 0x1p-53; H[1].label = "double: 1 ulp just below 1";
            svg_panel(f, 860, 95, 600, 400, "Samplers: error of u = cos \xce\xb8 (filled: Draine, "
                      "hollow: HG)",
                      "ns per sample (log scale; bar: min..max over the (g, \xce\xb1))",
                      "max |u \xe2\x88\x92 u*| over the grid", P, NI + NH, NULL, H, 2);
        }
        /* legend and notes */
        {
            static char xl[160];
            double a0 = 1e300, a1 = 0;
            for (k = 0; k < ND; ++k) {
                if (xlf_int[k] < a0) a0 = xlf_int[k];
                if (xlf_int[k] > a1) a1 = xlf_int[k];
            }
            sprintf(xl, "XLF (blog): INVALID, not a density: integral %.2f-%.2f, p &lt; 0 "
                    "backwards", a0, a1);
            legend_text[M_XLF] = xl;
        }
        {
            double lx = 860, ly = 580;
            int row = 0;
            fprintf(f, "<rect x='%.0f' y='%.0f' width='600' height='390' fill='white' "
                    "stroke='#444'/>\n", lx, ly);
            fprintf(f, "<text x='%.0f' y='%.0f' font-size='15' font-weight='bold'>Legend"
                    "</text>\n", lx, ly - 12);
            for (m = 0; m <= M_LUT + 2 * NLUT; m += m < M_LUT ? 1 : NLUT) {
                double yy = ly + 24 + 22 * row++;
                int hol = m < M_LUT && m != M_FOG && m != M_XLF;
                if (m >= M_LUT)
                    fprintf(f, "<line x1='%.0f' y1='%.1f' x2='%.0f' y2='%.1f' stroke='%s' "
                            "stroke-width='1.5'/>\n", lx + 10, yy, lx + 34, yy, colors[m]);
                if (m == M_XLF)
                    fprintf(f, "<circle cx='%.0f' cy='%.1f' r='11' fill='none' stroke='#d00' "
                            "stroke-width='2' stroke-dasharray='4,3'/>\n", lx + 22, yy);
                svg_marker(f, lx + 22, yy, shapes[m], m >= M_LUT ? 4 : 6, colors[m], hol);
                fprintf(f, "<text x='%.0f' y='%.1f' font-size='12'%s>%s</text>\n", lx + 44,
                        yy + 4, m == M_XLF ? " fill='#d00' font-weight='bold'" : "",
                        legend_text[m < M_LUT ? m : M_LUT + (m - M_LUT) / NLUT]);
            }
            row++;
            {
                static const char *notes[] = {
                    "Reference: Lorenz-Mie (mist_mie.h), water, 450/550/650 nm,",
                    "lognormal sizes of width 1.1 (tests/mist_fitref.h). LUTs: Mie at",
                    "the nodes, linear interpolation, scaled to integrate to 1.",
                    "Samplers: against a __float128 inversion of the exact CDF; Draine:",
                    "g in {0.01, 0.1, 0.5, 0.9}, \xce\xb1 in {1, 17, 250}; HG: g in {1e-4,",
                    "0.01, 0.5, 0.9}; 1006 \xce\xbe each; float",
                    "inputs rounded first. Costs: double unless marked, one call at a",
                    "time, median of 15 repetitions of 4096 random inputs.",
                };
                size_t q;
                for (q = 0; q < sizeof notes / sizeof *notes; ++q)
                    fprintf(f, "<text x='%.0f' y='%.1f' font-size='12' fill='#333'>%s</text>\n",
                            lx + 12, ly + 24 + 22 * row + 17 * (double)q, notes[q]);
            }
        }
        fprintf(f, "<text x='20' y='1045' font-size='12' fill='#555'>");
        {
            FILE *ci = fopen("/proc/cpuinfo", "r");
            char line[256];
            int done = 0;
            if (ci) {
                while (!done && fgets(line, sizeof line, ci))
                    if (strncmp(line, "model name", 10) == 0) {
                        char *p = strchr(line, ':'), *e;
                        p = p ? p + 2 : line;
                        if ((e = strchr(p, '\n')) != NULL) *e = 0;
                        fprintf(f, "machine: %s. ", p);
                        done = 1;
                    }
                fclose(ci);
            }
        }
        fprintf(f, "Made by examples/tradeoff.c; Schlick, XLF and the LUTs are written there, "
                "not in mist.</text>\n</svg>\n");
        fclose(f);
    }
    fprintf(stderr, "wrote %s; %.1f s\n", out, now() - t_start);
    return 0;
}
