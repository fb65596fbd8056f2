/* mist_fitref.h - the Lorenz-Mie reference that the droplet fits are
 * measured against, shared by examples/fit_error.c (the README table) and
 * tests/test_fits.c (which reading of eq. 8 and 10 is right).  Its
 * assumptions are listed in examples/fit_error.c. */
#ifndef MIST_FITREF_H
#define MIST_FITREF_H
#include "mist.h"
#include "mist_mie.h"

#include <stdio.h>
#include <stdlib.h>

#define PI 3.14159265358979323846
#define NTH 1001   /* angles: 0, 300 geometric to 5 deg, 700 uniform */

static double th[NTH], mu[NTH], wq[NTH];

static void fitref_grid(void)
{
    int i;
    /* 0, then geometric from 1e-3 to 5 degrees (300), then uniform to 180 */
    th[0] = 0;
    for (i = 1; i <= 300; ++i) th[i] = 1e-3 * pow(5e3, (i - 1) / 299.0) * PI / 180;
    for (i = 301; i < NTH; ++i) th[i] = (5 + 175.0 * (i - 300) / (NTH - 301)) * PI / 180;
    for (i = 0; i < NTH; ++i) { mu[i] = cos(th[i]); wq[i] = 0; }
    for (i = 0; i + 1 < NTH; ++i) {            /* trapezoid weights in theta */
        double h = th[i + 1] - th[i];
        wq[i] += h / 2; wq[i + 1] += h / 2;
    }
}

static void fitref_errors(const double *p, const double *ref, double *l1, double *lrms)
{
    int i;
    double a = 0, b = 0;
    for (i = 0; i < NTH; ++i) {
        double lr = log10(p[i] / ref[i]);
        a += wq[i] * 2 * PI * sin(th[i]) * fabs(p[i] - ref[i]);
        b += wq[i] / PI * lr * lr;
    }
    *l1 = a; *lrms = sqrt(b);
}

/* Mie reference for diameter d (um) at the n cosines m[] into p[]; returns
 * the asymmetry g */
static double fitref_mie_at(double d, const double *m, size_t n, double *p, int n_radii)
{
    mist_mie_wavelength wl[3];
    mist_mie_dist dist = mist_mie_dist_lognormal(d / 2, 1.1);
    mist_mie_avg a;
    wl[0] = mist_mie_wl(0.45, 1, mist_mie_water(450, NULL));
    wl[1] = mist_mie_wl(0.55, 1, mist_mie_water(550, NULL));
    wl[2] = mist_mie_wl(0.65, 1, mist_mie_water(650, NULL));
    dist.n_radii = n_radii;
    a = mist_mie_average(&dist, wl, 3, 1.0, m, n, p);
    if (a.status != MIST_MIE_OK) { fprintf(stderr, "mie failed at d = %g\n", d); exit(1); }
    return a.g;
}

/* the same on the grid mu[] */
static double fitref_mie(double d, double *p, int n_radii)
{
    return fitref_mie_at(d, mu, NTH, p, n_radii);
}

/* the printed reading of eq. 8 and 10: constants outside the exponential */
static mist_fog fog_printed(double d)
{
    mist_fog f = mist_fog_from_diameter(d);
    f.g_d = exp(-2.20679 / (d + 3.91029)) - 0.428934;
    f.w_d = exp(-0.599085 / (d - 0.641583)) - 0.665888;
    return f;
}

/* One diameter: Mie's g and the errors (L1, logRMS) of the fit, of the
 * printed reading of eq. 8 and 10, of HG with the Mie asymmetry, and of
 * mist_fog_from_diameter_mie (fitted to this reference). */
typedef struct { double g, l1, lr, l1p, lrp, l1h, lrh, l1m, lrm; } fitref_row;

static fitref_row fitref_compare(double d, int n_radii)
{
    static double ref[NTH], p[NTH], q[NTH], h[NTH], m[NTH];
    fitref_row r;
    mist_fog f = mist_fog_from_diameter(d), fp = fog_printed(d), fm = mist_fog_from_diameter_mie(d);
    int i;
    r.g = fitref_mie(d, ref, n_radii);
    for (i = 0; i < NTH; ++i) {
        p[i] = mist_fog_eval(f, mu[i]);
        q[i] = mist_fog_eval(fp, mu[i]);
        h[i] = mist_hg_eval(r.g, mu[i]);
        m[i] = mist_fog_eval(fm, mu[i]);
    }
    fitref_errors(p, ref, &r.l1, &r.lr);
    fitref_errors(q, ref, &r.l1p, &r.lrp);
    fitref_errors(h, ref, &r.l1h, &r.lrh);
    fitref_errors(m, ref, &r.l1m, &r.lrm);
    return r;
}

#endif
