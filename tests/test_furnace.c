/* test_furnace.c - the white furnace: every phase function's sampler,
 * density and reported pdf used together as a volumetric path tracer uses
 * them (many bounces, directions, pdfs and weights).
 *
 * The scene: a sphere of radius 1 filled with a homogeneous medium of
 * extinction sigma and scattering sigma (albedo 1: nothing is absorbed),
 * inside an environment of uniform radiance 1.  The radiance leaving the
 * sphere in any direction is then exactly 1, whatever sigma and whatever
 * the phase function p (the radiative transfer equation has the constant
 * solution L = 1 when p integrates to 1 and nothing is absorbed).  A small
 * orthographic image of the sphere must therefore be 1 in every pixel.
 *
 * Two estimates from each path (RGB), with x on a ray of direction w, d
 * its distance to the sphere's boundary, T(s) = exp(-sigma s):
 *   - a free-flight distance t from the pdf sigma exp(-sigma t); t >= d
 *     leaves the sphere; else the throughput beta is multiplied by
 *     sigma T(t) / pdf(t) (evaluated density over reported pdf);
 *   - a direction w' from the phase sampler, which reports pdf p_s; beta
 *     *= f(w.w') / p_s, f EVALUATED by the model's own density at the
 *     cosine of the returned direction (never taken as 1).
 * The escape estimate E is beta when the path leaves (the environment is
 * 1): with exact weights it is 1 for every path, up to rounding, so it
 * checks f / p_s to a few ulps per vertex.  The next-event estimate L
 * adds, on the same path, the camera ray's T(d), and at each scattering
 * point a direction w_l uniform on the sphere (p_l = 1/(4 pi)), beta f
 * T(d_l) / (p_l + p_s(w.w_l)), and the environment behind w', beta T(d')
 * p_s / (p_s + p_l) (balance heuristic; T analytic).  L is 1 on average
 * only if f integrates to 1 (the uniform directions integrate it), p_s is
 * the density of the directions drawn (the two strategies' weights then
 * add to 1) and the flights are drawn from sigma T(t) (the analytic T
 * terms must match the sampled flights).
 * f is the medium's density (the unprepared mist_*_eval; a table's
 * channels q_c), p_s(u) the sampler's (the prepared sampler's own
 * mist_phase_eval, a table's channel mean).  The negative controls must
 * be REJECTED: a density scaled by 0.99, an HG sampler drawing from g =
 * 0.9 but reporting the pdf of g = 0.8, and flights 1% short.  (The
 * furnace cannot see a wrong azimuth or frame: tests/test_chi2.c covers
 * those.)
 *
 * Covered: HG at g = 0, 0.5, 0.99, -0.9; Cornette-Shanks at the fits'
 * g_hg, Draine at the fits' (g_d, alpha) and the fog mix at the fits, for
 * d = 0.05, 1, 3, 10, 50 um (each of the fits' four ranges, both ends of
 * the widest); Rayleigh; each by its unprepared *_sample_dir and by the
 * prepared mist_phase_sample_dir; float and double; a 3-channel table
 * (mist_tab_*, float and double).  Densities sigma = 0.5, 2, 4 in turn
 * (the table at 0.5: its channels' weights q_c / s multiply over the
 * vertices, and a product of many has the heavy tail the CLT needs more
 * paths for).
 *
 * The bar.  A pixel's estimate is the mean m of n independent path values
 * X_i.  L is a sum of per-vertex terms in [0, beta], with exact weights
 * beta = 1 (a table's channels: q_c / s <= C = 3 per vertex), and the
 * number of vertices has a geometric tail (each flight leaves with
 * probability >= exp(-2 sigma), the sphere's longest chord), so every
 * moment of X exists.  By the central limit theorem m ~ N(1, s^2 / n), s^2
 * the sample variance, and a check is |m - 1| <= Z s / sqrt(n) + b.  Z =
 * 6: a two-sided normal tail of 2.0e-9 per check; over the ~18000 checks
 * below a false alarm rate of 4e-5 for the whole test (the skew of X moves
 * a tail at 6 sigma by a factor of at most ~2 at n = 256: Edgeworth's
 * first term gamma (Z^2 - 1) / (6 sqrt n) with skewness gamma <= 3).  The
 * seeds are fixed, so a pass is reproducible.  b (allowance, below) is the
 * bias the estimator has without any error in mist: paths are cut after
 * KMAX = 100000 vertices, and the expected radiance still to come from a
 * point inside is 1 times the probability of having survived, <= (1 -
 * exp(-2 sigma))^KMAX = exp(-33) at sigma = 4, so 1e-12; and the weights'
 * rounding, derived at allowance().
 *
 * The controls are rejected by the same check on the image's mean (all
 * pixels' paths, or more where the bias is small): density x 0.99 lowers
 * each vertex's weight by 1% (E: 0.99^k, hundreds of standard errors off);
 * g 0.9 / 0.8 raises the mean weight per vertex by the chi-square distance
 * int p_0.9^2 / p_0.8 - 1 (0.16, compounding over the vertices); flights
 * 1% short leave E at 1 but move each vertex's environment term in L by
 * T(d) (T(d)^(1/0.99 - 1) - 1) (up to -0.37%), which 2^20 paths (se ~ 7e-4
 * at sigma 1) resolve. */
#include "mist.h"
#include "mist_test.h"

#include <float.h>
#include <string.h>

#define PI 3.14159265358979323846
#define KMAX 100000
#define NPIX 6                   /* an NPIX x NPIX image */
#define SPP 256                  /* paths per pixel */
#define ZBAR 6.0
#define BIAS 1e-12

enum { HG, CS, DRAINE, FOG, RAYLEIGH, TAB, HG_BAD_PDF };

typedef struct {
    int kind, prepared, isfloat;
    double g, alpha, scale;      /* HG, CS, Draine's parameters; scale: the density's factor */
    mist_fog fog;
    mist_fogf fogf;
    mist_phase ph;
    mist_phasef phf;
    const mist_tab *tab;
    const mist_tabf *tabf;
    char name[96];
} model;

static mist_vec3 v3(double x, double y, double z) { mist_vec3 v; v.x = x; v.y = y; v.z = z; return v; }
static double dot(mist_vec3 a, mist_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static mist_vec3f tof(mist_vec3 a)
{
    mist_vec3f v;
    v.x = (float)a.x; v.y = (float)a.y; v.z = (float)a.z;
    return v;
}
/* a float direction in double, renormalised in double (the frame's exit
 * distances assume unit length) */
static mist_vec3 tod(mist_vec3f a)
{
    return mist_normalize(v3(a.x, a.y, a.z));
}

/* the medium's density at u, per channel (the unprepared evaluation) */
static int model_eval(const model *m, double u, double *f)
{
    double v = 0;
    float fu = (float)u;
    if (m->kind == TAB) {
        if (m->isfloat) {
            float ch[3];
            mist_tab_evalf(m->tabf, fu, ch);
            f[0] = ch[0]; f[1] = ch[1]; f[2] = ch[2];
        } else {
            mist_tab_eval(m->tab, u, f);
        }
        return 3;
    }
    switch (m->kind) {
    case HG: case HG_BAD_PDF:
        v = m->isfloat ? mist_hg_evalf((float)m->g, fu) : mist_hg_eval(m->g, u); break;
    case CS: v = m->isfloat ? mist_cs_evalf((float)m->g, fu) : mist_cs_eval(m->g, u); break;
    case DRAINE:
        v = m->isfloat ? mist_draine_evalf((float)m->g, (float)m->alpha, fu)
                       : mist_draine_eval(m->g, m->alpha, u);
        break;
    case FOG: v = m->isfloat ? mist_fog_evalf(m->fogf, fu) : mist_fog_eval(m->fog, u); break;
    case RAYLEIGH: v = m->isfloat ? mist_rayleigh_evalf(fu) : mist_rayleigh_eval(u); break;
    }
    f[0] = f[1] = f[2] = v * m->scale;
    return 1;
}

/* the sampler's own density at u (its pdf function: for the MIS weights) */
static double model_pdf(const model *m, double u)
{
    float fu = (float)u;
    if (m->kind == TAB)
        return m->isfloat ? mist_tab_evalf(m->tabf, fu, NULL) : mist_tab_eval(m->tab, u, NULL);
    if (m->kind == HG_BAD_PDF) return mist_hg_eval(0.8, u);
    if (m->prepared)
        return m->isfloat ? mist_phase_evalf(&m->phf, fu) : mist_phase_eval(&m->ph, u);
    {
        double f[3];
        model old = *m;
        old.scale = 1;
        model_eval(&old, u, f);
        return f[0];
    }
}

/* a scattered direction about w and the pdf the sampler reports */
static mist_vec3 model_sample(const model *m, mist_vec3 w, double x1, double x2, double *pdf)
{
    if (m->isfloat) {
        mist_vec3f wf = tof(w), o;
        float a = (float)x1, b = (float)x2, p = 0;
        if (m->prepared) o = mist_phase_sample_dirf(&m->phf, wf, a, b, &p);
        else switch (m->kind) {
        case HG: o = mist_hg_sample_dirf((float)m->g, wf, a, b, &p); break;
        case CS: o = mist_cs_sample_dirf((float)m->g, wf, a, b, &p); break;
        case DRAINE: o = mist_draine_sample_dirf((float)m->g, (float)m->alpha, wf, a, b, &p); break;
        case FOG: o = mist_fog_sample_dirf(m->fogf, wf, a, b, &p); break;
        case RAYLEIGH: o = mist_rayleigh_sample_dirf(wf, a, b, &p); break;
        default: o = mist_tab_sample_dirf(m->tabf, wf, a, b, &p); break;
        }
        *pdf = p;
        return tod(o);
    }
    if (m->prepared) return mist_phase_sample_dir(&m->ph, w, x1, x2, pdf);
    switch (m->kind) {
    case HG: return mist_hg_sample_dir(m->g, w, x1, x2, pdf);
    case HG_BAD_PDF: {      /* draws from g = 0.9, reports the pdf of g = 0.8 */
        mist_vec3 o = mist_hg_sample_dir(0.9, w, x1, x2, pdf);
        *pdf = mist_hg_eval(0.8, dot(w, o));
        return o;
    }
    case CS: return mist_cs_sample_dir(m->g, w, x1, x2, pdf);
    case DRAINE: return mist_draine_sample_dir(m->g, m->alpha, w, x1, x2, pdf);
    case FOG: return mist_fog_sample_dir(m->fog, w, x1, x2, pdf);
    case RAYLEIGH: return mist_rayleigh_sample_dir(w, x1, x2, pdf);
    default: return mist_tab_sample_dir(m->tab, w, x1, x2, pdf);
    }
}

/* distance from x (|x| <= 1) along the unit w to the unit sphere:
 * t^2 + 2 b t + c = 0, c = |x|^2 - 1 <= 0, the positive root without
 * cancellation */
static double exit_dist(mist_vec3 x, mist_vec3 w)
{
    double b = dot(x, w), c = dot(x, x) - 1, q;
    if (c > 0) c = 0;
    q = sqrt(b * b - c);
    return b > 0 ? -c / (b + q) : q - b;
}

/* one path entering the sphere at x along w: L the next-event (MIS)
 * estimate, E the escape estimate (the throughput when the path leaves),
 * both RGB; returns the number of scattering vertices */
static long path(const model *m, double sigma, double shortf, mt_rng *r, mist_vec3 x,
                 mist_vec3 w, double *L, double *E)
{
    double beta[3] = { 1, 1, 1 }, d = exit_dist(x, w), T = exp(-sigma * d);
    const double pl = 1 / (4 * PI);
    long k;
    int c;
    for (c = 0; c < 3; ++c) L[c] = T;
    for (k = 0; k < KMAX; ++k) {
        double t = -log(1 - mt_uniform(r)) / sigma * shortf, pt, f[3], pdf, u, ps, Tl, dl;
        mist_vec3 wl, wo;
        if (t >= d) break;
        pt = sigma * exp(-sigma * t);                      /* the reported pdf */
        for (c = 0; c < 3; ++c) beta[c] *= sigma * exp(-sigma * t) / pt;
        x = v3(x.x + t * w.x, x.y + t * w.y, x.z + t * w.z);
        {   /* next event: a uniform direction */
            double z = 1 - 2 * mt_uniform(r), ph = 2 * PI * mt_uniform(r);
            double s = sqrt(1 - z * z > 0 ? 1 - z * z : 0);
            wl = v3(s * cos(ph), s * sin(ph), z);
        }
        u = dot(w, wl);
        model_eval(m, u, f);
        ps = model_pdf(m, u);
        dl = exit_dist(x, wl);
        Tl = exp(-sigma * dl);
        for (c = 0; c < 3; ++c) L[c] += beta[c] * f[c] * Tl / (pl + ps);
        {   /* the phase sampler */
            double x1 = mt_uniform(r), x2 = mt_uniform(r);
            wo = model_sample(m, w, x1, x2, &pdf);
        }
        if (!(pdf > 0) || pdf > 1e300) {                   /* no |g| = 1 here */
            beta[0] = beta[1] = beta[2] = 0;
            break;
        }
        /* the cosine of the direction as returned (a float sampler's: of
         * the float vectors it was given and returned) */
        u = m->isfloat ? dot(tod(tof(w)), wo) : dot(w, wo);
        model_eval(m, u, f);
        for (c = 0; c < 3; ++c) beta[c] *= f[c] / pdf;
        d = exit_dist(x, wo);
        T = exp(-sigma * d);
        for (c = 0; c < 3; ++c) L[c] += beta[c] * T * pdf / (pdf + pl);
        w = wo;
    }
    for (c = 0; c < 3; ++c) E[c] = beta[c];
    return k;
}

typedef struct {
    double mean[6], se[6];       /* the image's: L's channels, then E's */
    double vertices;             /* mean scattering vertices a path */
    double pm[NPIX * NPIX][6], pse[NPIX * NPIX][6];   /* each pixel's mean, standard error */
} furnace_result;

/* renders the NPIX x NPIX image (spp paths a pixel): each pixel's and the
 * image's means and standard errors, both estimates */
static void furnace(furnace_result *res_, const model *m, double sigma, double shortf, long spp,
                    uint64_t seed)
{
#define res (*res_)
    double S[6] = { 0 }, S2[6] = { 0 }, K = 0;
    mt_rng r;
    int i, j, c;
    long n;
    r.s = seed;
    for (j = 0; j < NPIX; ++j)
        for (i = 0; i < NPIX; ++i) {
            double s1[6] = { 0 }, s2[6] = { 0 };
            for (n = 0; n < spp; ++n) {
                /* the square [-0.7, 0.7]^2 inside the sphere's disc, jittered */
                double px = -0.7 + 1.4 * (i + mt_uniform(&r)) / NPIX;
                double py = -0.7 + 1.4 * (j + mt_uniform(&r)) / NPIX, V[6];
                mist_vec3 x = v3(px, py, sqrt(1 - px * px - py * py));
                K += (double)path(m, sigma, shortf, &r, x, v3(0, 0, -1), V, V + 3);
                for (c = 0; c < 6; ++c) { s1[c] += V[c]; s2[c] += V[c] * V[c]; }
            }
            for (c = 0; c < 6; ++c) {
                double mu = s1[c] / spp, var = (s2[c] - s1[c] * mu) / (spp - 1);
                double se = sqrt(var > 0 ? var : 0) / sqrt((double)spp);
                S[c] += s1[c]; S2[c] += s2[c];
                res.pm[j * NPIX + i][c] = mu;
                res.pse[j * NPIX + i][c] = se;
            }
        }
    n = (long)NPIX * NPIX * spp;
    res.vertices = K / (double)n;
    for (c = 0; c < 6; ++c) {
        double var = (S2[c] - S[c] * S[c] / (double)n) / (double)(n - 1);
        res.mean[c] = S[c] / (double)n;
        res.se[c] = sqrt(var > 0 ? var : 0) / sqrt((double)n);
    }
#undef res
}

/* every pixel's every channel within the bar; returns the failures */
static double worst = 0;         /* the largest |m - 1| / bar of any pixel */

static int check_pixels(const furnace_result *f, const model *m, double sigma, double b)
{
    int i, c, bad = 0;
    for (i = 0; i < NPIX * NPIX; ++i)
        for (c = 0; c < 6; ++c) {
            double r = fabs(f->pm[i][c] - 1) / (ZBAR * f->pse[i][c] + b);
            if (r > worst) worst = r;
            if (!mt_check(fabs(f->pm[i][c] - 1) <= ZBAR * f->pse[i][c] + b,
                          "%s sigma %g: pixel %d %s channel %d: %.9f, bar %.3g", m->name, sigma,
                          i, c < 3 ? "next-event" : "escape", c % 3, f->pm[i][c],
                          ZBAR * f->pse[i][c] + b))
                ++bad;
        }
    return bad;
}

/* the image's mean within the bar in every channel of both estimates */
static int mean_ok(const furnace_result *f, double b)
{
    int c;
    for (c = 0; c < 6; ++c)
        if (!(fabs(f->mean[c] - 1) <= ZBAR * f->se[c] + b)) return 0;
    return 1;
}

/* the largest |d ln f / d theta| of the model's density, u = cos theta,
 * on a grid geometric towards both theta = 0 and theta = pi (ratio 1.008;
 * the secants' slopes, within ~1% of the tangents' where f is smooth, so
 * twice their maximum); *su the same for |d ln f / du| */
static double log_slope(const model *m, double *su)
{
    double best = 0, bu = 0, prev_t = 0, prev_u = 1, prev_l[3] = { 0, 0, 0 }, f[3];
    int j, side, c, first = 1;
    model dm = *m;
    dm.isfloat = 0;
    dm.scale = 1;
    for (side = 0; side < 2; ++side)
        for (j = 0; j <= 2400; ++j) {
            double x = PI / 2 * pow(10, -8 + 8.0 * (side ? 2400 - j : j) / 2400);
            double th = side ? PI - x : x;
            if (!first && th <= prev_t) continue;
            model_eval(&dm, cos(th), f);
            for (c = 0; c < 3; ++c) {
                double l = log(f[c] > 1e-300 ? f[c] : 1e-300);
                if (!first && fabs(l - prev_l[c]) / (th - prev_t) > best)
                    best = fabs(l - prev_l[c]) / (th - prev_t);
                if (!first && prev_u > cos(th) && fabs(l - prev_l[c]) / (prev_u - cos(th)) > bu)
                    bu = fabs(l - prev_l[c]) / (prev_u - cos(th));
                prev_l[c] = l;
            }
            prev_t = th;
            prev_u = cos(th);
            first = 0;
        }
    *su = 2 * bu;
    return 2 * best;
}

/* b, the bar's allowance for what is not Monte Carlo noise (see the top):
 * the paths' truncation, 1e-12, and the weights' rounding.  Per vertex f /
 * p_s is two evaluations of one density, each within 4 eps, at angles
 * that differ by the rounding of the directions: each direction (the
 * incident one as the sampler got it, the returned one) within 8 eps of
 * its exact angle, so theta within 16 eps; and a length off 1 by 4 eps
 * each, in double, moves the cosine by 8 eps_double (a float direction is
 * renormalised in double here, which leaves that much of its radial
 * rounding).  So f / p_s is within exp(S 16 eps + S_u 8 eps_double) (1 +
 * 8 eps) - 1, S the density's largest |d ln p / d theta| (for HG at theta
 * ~ (1 - g) / sqrt(g): 1.5 sqrt(g) / (1 - g)), S_u its largest |d ln p /
 * du| (HG: 3 g / (1 - g)^2).  Over a path, that times its vertices (to
 * first order), on average the mean vertex count. */
static double allowance(const model *m, double eps, double vertices)
{
    double su, st = log_slope(m, &su);
    double per = exp(st * 16 * eps + su * 8 * (DBL_EPSILON / 2)) * (1 + 8 * eps) - 1;
    return BIAS + per * vertices;
}

static int nmodels = 0;
static model models[128];

static model *add(int kind, int prepared, int isfloat, double g, double alpha, const char *what)
{
    model *m = &models[nmodels++];
    memset(m, 0, sizeof *m);
    m->kind = kind; m->prepared = prepared; m->isfloat = isfloat;
    m->g = g; m->alpha = alpha; m->scale = 1;
    snprintf(m->name, sizeof m->name, "%s %s %s", what, prepared ? "prepared" : "unprepared",
             isfloat ? "float" : "double");
    return m;
}

static void report(const model *m, const furnace_result *f)
{
    printf("%s: next-event %.5f (%.1f standard errors from 1), escape %.5f (%.3g)\n", m->name,
           f->mean[0], fabs(f->mean[0] - 1) / f->se[0], f->mean[3],
           fabs(f->mean[3] - 1) / (f->se[3] > 0 ? f->se[3] : 1e-300));
}

int main(void)
{
    static const double G[4] = { 0, 0.5, 0.99, -0.9 };
    static const double D[5] = { 0.05, 1, 3, 10, 50 };
    static const double SIG[3] = { 0.5, 2, 4 };
    static double mu[513], p[513 * 3];
    mist_tab *tab;
    mist_tabf *tabf;
    size_t bytes;
    int i, k, pr, fl;
    char what[64];

    /* the table: three HG channels (g = 0.2, 0.6, 0.9), 513 nodes uniform
     * in theta (any data would do: the table is normalised itself) */
    for (i = 0; i < 513; ++i) {
        mu[i] = -cos(PI * i / 512);
        p[i * 3 + 0] = mist_hg_eval(0.2, mu[i]);
        p[i * 3 + 1] = mist_hg_eval(0.6, mu[i]);
        p[i * 3 + 2] = mist_hg_eval(0.9, mu[i]);
    }
    mu[0] = -1; mu[512] = 1; mu[256] = 0;
    bytes = mist_tab_bytes(513, 3);
    tab = (mist_tab *)malloc(bytes);
    tabf = (mist_tabf *)malloc(mist_tab_bytesf(513, 3));
    if (!tab || !tabf) { printf("out of memory\n"); return 1; }
    if (mist_tab_init(tab, bytes, mu, p, 513, 3) != 0) { printf("mist_tab_init failed\n"); return 1; }
    {
        static float muf[513], pf[513 * 3];
        for (i = 0; i < 513; ++i) muf[i] = (float)mu[i];
        for (i = 0; i < 513 * 3; ++i) pf[i] = (float)p[i];
        if (mist_tab_initf(tabf, mist_tab_bytesf(513, 3), muf, pf, 513, 3) != 0) {
            printf("mist_tab_initf failed\n");
            return 1;
        }
    }

    for (fl = 0; fl < 2; ++fl)
        for (pr = 0; pr < 2; ++pr) {
            for (k = 0; k < 4; ++k) {
                model *m;
                snprintf(what, sizeof what, "HG g %g", G[k]);
                m = add(HG, pr, fl, G[k], 0, what);
                m->ph = mist_phase_hg(G[k]); m->phf = mist_phase_hgf((float)G[k]);
            }
            for (k = 0; k < 5; ++k) {
                mist_fog fg = mist_fog_from_diameter(D[k]);
                mist_fogf ff = mist_fog_from_diameterf((float)D[k]);
                model *m;
                snprintf(what, sizeof what, "CS g %.4g (d %g um)", fg.g_hg, D[k]);
                m = add(CS, pr, fl, fl ? ff.g_hg : fg.g_hg, 0, what);
                m->ph = mist_phase_cs(fg.g_hg); m->phf = mist_phase_csf(ff.g_hg);
                snprintf(what, sizeof what, "Draine g %.4g alpha %.4g", fg.g_d, fg.alpha);
                m = add(DRAINE, pr, fl, fl ? ff.g_d : fg.g_d, fl ? ff.alpha : fg.alpha, what);
                m->ph = mist_phase_draine(fg.g_d, fg.alpha);
                m->phf = mist_phase_drainef(ff.g_d, ff.alpha);
                snprintf(what, sizeof what, "fog d %g um", D[k]);
                m = add(FOG, pr, fl, 0, 0, what);
                m->fog = fg; m->fogf = ff;
                m->ph = mist_phase_fog(fg); m->phf = mist_phase_fogf(ff);
            }
            {
                model *m = add(RAYLEIGH, pr, fl, 0, 0, "Rayleigh");
                m->ph = mist_phase_rayleigh(); m->phf = mist_phase_rayleighf();
            }
        }
    for (fl = 0; fl < 2; ++fl) {
        model *m = add(TAB, 0, fl, 0, 0, "table (3 channels)");
        m->tab = tab; m->tabf = tabf;
    }

    for (i = 0; i < nmodels; ++i) {
        static furnace_result f;
        double sigma = models[i].kind == TAB ? 0.5 : SIG[i % 3];
        const model *m = &models[i];
        double eps = m->isfloat ? FLT_EPSILON / 2 : DBL_EPSILON / 2, b;
        furnace(&f, m, sigma, 1, SPP, 1000 + (uint64_t)i);
        b = allowance(m, eps, f.vertices);
        check_pixels(&f, m, sigma, b);
        mt_check(mean_ok(&f, b), "%s sigma %g: mean %.6f %.6f, se %.2g %.2g, b %.2g", m->name,
                 sigma, f.mean[0], f.mean[3], f.se[0], f.se[3], b);
        if (getenv("FURNACE_VERBOSE"))
            printf("%-48s sigma %g: next-event %.5f (se %.1e), escape %.9f (se %.1e), b %.1e, "
                   "%.2f vertices\n", m->name, sigma, f.mean[0], f.se[0], f.mean[3], f.se[3], b,
                   f.vertices);
    }
    printf("%d phase functions, %d x %d pixels x %d paths each, two estimates x 3 channels: "
           "the worst pixel at %.3f of its bar\n", nmodels, NPIX, NPIX, SPP, worst);

    /* the negative controls: each must be rejected by the image's mean */
    {
        model m;
        static furnace_result f;
        const double eps = DBL_EPSILON / 2;
        memset(&m, 0, sizeof m);
        m.kind = HG; m.g = 0.5; m.scale = 0.99;
        strcpy(m.name, "control: HG 0.5 density x 0.99");
        furnace(&f, &m, 2, 1, SPP * 16, 77);
        mt_check(!mean_ok(&f, allowance(&m, eps, f.vertices)), "%s not rejected: mean %.6f se %.2g", m.name, f.mean[0], f.se[0]);
        report(&m, &f);

        m.kind = HG_BAD_PDF; m.g = 0.9; m.scale = 1;
        strcpy(m.name, "control: HG drawn at g 0.9, pdf of g 0.8");
        furnace(&f, &m, 2, 1, SPP, 78);
        mt_check(!mean_ok(&f, allowance(&m, eps, f.vertices)), "%s not rejected: mean %.6f se %.2g", m.name, f.mean[0], f.se[0]);
        report(&m, &f);

        m.kind = HG; m.g = 0.5;
        strcpy(m.name, "control: HG 0.5 flights 1% short");
        furnace(&f, &m, 1, 0.99, SPP * 128, 79);
        mt_check(!mean_ok(&f, allowance(&m, eps, f.vertices)), "%s not rejected: mean %.6f se %.2g", m.name, f.mean[0], f.se[0]);
        report(&m, &f);
    }
    free(tab);
    free(tabf);
    return mt_done("furnace");
}
