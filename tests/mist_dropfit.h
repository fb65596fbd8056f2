/* mist_dropfit.h - the fit behind mist_fog_from_diameter_mie's table, shared
 * by tools/fit_droplet.c (which makes the table) and tests/test_fits_mie.c
 * (which checks it).  The reference and the two error metrics are
 * tests/mist_fitref.h's (examples/fit_error.c lists its assumptions).
 *
 * The fit at one diameter d: the four parameters of the fog mix [JD23
 * eq. 1] that minimise logRMS^2 + (0.35 L1)^2 against the Mie reference.
 * logRMS, the log-space error, weighs the side and back lobes, orders of
 * magnitude below the forward peak, as much as the peak; the L1 term keeps
 * the peak's mass right, which logRMS over theta barely sees (0.35: the
 * largest weight at which no node's logRMS is worse than the published
 * fits'; at 0.5 it was at 0.4 um, by 0.002).  Searched in unbounded
 * coordinates, g = tanh(x), alpha = e^x (capped at 1000, four times the
 * published fits' 250: the small droplets' optimum runs off to alpha ->
 * inf, where Draine's lobe is u^2 HG(g)), w_d = 1 / (1 + e^-x), by
 * Nelder-Mead. */
#ifndef MIST_DROPFIT_H
#define MIST_DROPFIT_H
#include "mist_fitref.h"

#include <string.h>

#define DF_ALPHA_MAX 1000.0
#ifndef DF_L1_WEIGHT
#define DF_L1_WEIGHT 0.35
#endif

/* the Mie reference at d on fitref's grid: ch < 0 averages 450, 550 and
 * 650 nm as fitref_mie does; ch = 0, 1, 2 takes one of them (R = 650, G =
 * 550, B = 450 nm) */
static void dropfit_ref(double d, int ch, double *ref, int n_radii)
{
    static const double lam[3] = { 0.65, 0.55, 0.45 };
    mist_mie_wavelength wl;
    mist_mie_dist dist;
    mist_mie_avg a;
    if (ch < 0) { fitref_mie(d, ref, n_radii); return; }
    dist = mist_mie_dist_lognormal(d / 2, 1.1);
    dist.n_radii = n_radii;
    wl = mist_mie_wl(lam[ch], 1, mist_mie_water(lam[ch] * 1000, NULL));
    a = mist_mie_average(&dist, &wl, 1, 1.0, mu, NTH, ref);
    if (a.status != MIST_MIE_OK) { fprintf(stderr, "mie failed at d = %g\n", d); exit(1); }
}

static mist_fog dropfit_fog(const double *x)
{
    double la = x[2] < log(DF_ALPHA_MAX) ? x[2] : log(DF_ALPHA_MAX);
    return mist_fog_make(tanh(x[0]), tanh(x[1]), exp(la), 1 / (1 + exp(-x[3])));
}

static void dropfit_coords(mist_fog f, double *x)
{
    double c = 1 - 1e-12;
    x[0] = atanh(f.g_hg < -c ? -c : f.g_hg > c ? c : f.g_hg);
    x[1] = atanh(f.g_d < -c ? -c : f.g_d > c ? c : f.g_d);
    x[2] = log(f.alpha > 1e-12 ? f.alpha : 1e-12);
    x[3] = f.w_d <= 1e-12 ? log(1e-12) : f.w_d >= 1 - 1e-12 ? -log(1e-12)
                                        : log(f.w_d / (1 - f.w_d));
}

/* errors of a fog against the reference */
static void dropfit_err(mist_fog f, const double *ref, double *l1, double *lr)
{
    static double p[NTH];
    int i;
    for (i = 0; i < NTH; ++i) p[i] = mist_fog_eval(f, mu[i]);
    fitref_errors(p, ref, l1, lr);
}

static double dropfit_obj_fog(mist_fog f, const double *ref)
{
    double l1, lr;
    dropfit_err(f, ref, &l1, &lr);
    return lr * lr + DF_L1_WEIGHT * DF_L1_WEIGHT * l1 * l1;
}

static double dropfit_obj(const double *x, const void *ref)
{
    return dropfit_obj_fog(dropfit_fog(x), (const double *)ref);
}

/* Nelder-Mead from x (step 'step' in each coordinate), restarted until a
 * restart gains less than 1e-12; x gets the minimum, which is returned */
typedef double (*dropfit_fn)(const double *x, const void *ctx);

static double dropfit_nm_fn(double *x, dropfit_fn fn, const void *ref, double step, int max_eval)
{
    double s[5][4], f[5], best = fn(x, ref), prev;
    int ne = 0, rounds;
    for (rounds = 0; rounds < 20 && ne < max_eval; ++rounds) {
        int i, j;
        prev = best;
        for (i = 0; i < 5; ++i) {
            for (j = 0; j < 4; ++j) s[i][j] = x[j] + (i == j + 1 ? step : 0);
            f[i] = fn(s[i], ref); ++ne;
        }
        while (ne < max_eval) {
            int hi = 0, lo = 0, nh = 0;
            double c[4], r[4], fr;
            for (i = 1; i < 5; ++i) { if (f[i] > f[hi]) hi = i; if (f[i] < f[lo]) lo = i; }
            nh = lo;
            for (i = 0; i < 5; ++i) if (i != hi && f[i] > f[nh]) nh = i;
            if (f[hi] - f[lo] <= 1e-14 * (fabs(f[lo]) + 1e-14)) break;
            for (j = 0; j < 4; ++j) {
                c[j] = 0;
                for (i = 0; i < 5; ++i) if (i != hi) c[j] += s[i][j] / 4;
                r[j] = c[j] + (c[j] - s[hi][j]);
            }
            fr = fn(r, ref); ++ne;
            if (fr < f[lo]) {
                double e[4], fe;
                for (j = 0; j < 4; ++j) e[j] = c[j] + 2 * (c[j] - s[hi][j]);
                fe = fn(e, ref); ++ne;
                if (fe < fr) { memcpy(s[hi], e, sizeof e); f[hi] = fe; }
                else { memcpy(s[hi], r, sizeof r); f[hi] = fr; }
            } else if (fr < f[nh]) {
                memcpy(s[hi], r, sizeof r); f[hi] = fr;
            } else {
                double k[4], fk;
                int out = fr < f[hi];
                for (j = 0; j < 4; ++j)
                    k[j] = out ? c[j] + 0.5 * (r[j] - c[j]) : c[j] + 0.5 * (s[hi][j] - c[j]);
                fk = fn(k, ref); ++ne;
                if (fk < (out ? fr : f[hi])) { memcpy(s[hi], k, sizeof k); f[hi] = fk; }
                else {
                    for (i = 0; i < 5; ++i) if (i != lo) {
                        for (j = 0; j < 4; ++j) s[i][j] = s[lo][j] + 0.5 * (s[i][j] - s[lo][j]);
                        f[i] = fn(s[i], ref); ++ne;
                    }
                }
            }
        }
        {
            int lo = 0;
            for (i = 1; i < 5; ++i) if (f[i] < f[lo]) lo = i;
            if (f[lo] < best) { best = f[lo]; memcpy(x, s[lo], sizeof s[lo]); }
        }
        step *= 0.5;
        if (prev - best < 1e-12 && rounds > 0) break;
    }
    return best;
}

/* The table: n nodes uniform in log d from 0.01 to 50 um, rows (g_hg, g_d,
 * log alpha, w_d) as mist__fog_interp reads them; and a fine grid of
 * 'fine' points a node interval (fine (n - 1) + 1 in all). */
static double dropfit_node_d(int k, int n)
{
    return exp(log(0.01) + (log(50.0) - log(0.01)) * k / (n - 1));
}

static double dropfit_fine_d(int j, int n, int fine)
{
    return exp(log(0.01) + (log(50.0) - log(0.01)) * j / ((n - 1) * fine));
}

static void dropfit_set_row(double *tab, int k, mist_fog f)
{
    tab[4 * k] = f.g_hg; tab[4 * k + 1] = f.g_d; tab[4 * k + 2] = log(f.alpha);
    tab[4 * k + 3] = f.w_d;
}

static mist_fog dropfit_row(const double *tab, int k)
{
    return mist_fog_make(tab[4 * k], tab[4 * k + 1], exp(tab[4 * k + 2]), tab[4 * k + 3]);
}

/* The second stage: node k's value moves to minimise the objective summed
 * over the fine points whose interpolated parameters it reaches (those of
 * the intervals k - 2 to k + 1: mist__fog_interp's slopes at k +- 1 read
 * node k), the model between the nodes included.  refs: the Mie
 * reference at every fine point, NTH values each.  Plus DF_SMOOTH times the
 * squared distance of each of the node's parameters (g_hg, g_d, log alpha,
 * w_d) from its neighbours' mean: it settles what the error does not see
 * (alpha and g_d where w_d -> 0 ran off to alpha = 1e-13) and costs the
 * fit nothing measurable elsewhere (a parameter 0.1 off its neighbours'
 * mean adds 1e-7 to a node objective of 0.01-0.5). */
#define DF_SMOOTH 1e-5
typedef struct { double *tab; int n, fine, k; const double *refs; } dropfit_joint;


static double dropfit_node_obj(const double *x, const void *ctx)
{
    const dropfit_joint *c = (const dropfit_joint *)ctx;
    int j, m = (c->n - 1) * c->fine, j0 = (c->k - 2) * c->fine, j1 = (c->k + 2) * c->fine;
    double s = 0;
    dropfit_set_row(c->tab, c->k, dropfit_fog(x));
    if (j0 < 0) j0 = 0;
    if (j1 > m) j1 = m;
    for (j = j0; j <= j1; ++j)
        s += dropfit_obj_fog(mist__fog_interp(c->tab, c->n, dropfit_fine_d(j, c->n, c->fine)),
                             c->refs + (size_t)j * NTH);
    if (c->k + 1 < c->n) {                 /* the smoothness term */
        int q;
        for (q = 0; q < 4; ++q) {
            double e = c->tab[4 * c->k + q]
                     - (c->tab[4 * (c->k - 1) + q] + c->tab[4 * (c->k + 1) + q]) / 2;
            s += DF_SMOOTH * e * e;
        }
    }
    return s;
}

/* re-optimise node k from its value in the table, and from the values of
 * the nodes in 'from' (count nf); the table keeps the best; returns the
 * objective before and after */
static void dropfit_node(dropfit_joint *c, const int *from, int nf, double *before,
                         double *after)
{
    double x[4], z[4], o, oz;
    int i;
    dropfit_coords(dropfit_row(c->tab, c->k), x);
    *before = dropfit_node_obj(x, c);
    o = dropfit_nm_fn(x, dropfit_node_obj, c, 0.2, 3000);
    for (i = 0; i < nf; ++i) {
        dropfit_coords(dropfit_row(c->tab, from[i]), z);
        oz = dropfit_nm_fn(z, dropfit_node_obj, c, 0.2, 3000);
        if (oz < o) { o = oz; memcpy(x, z, sizeof z); }
    }
    *after = dropfit_node_obj(x, c);
}
#endif
