/* test_hfog_path.c - the height fog's functions for path tracers (include/
 * mist.h, "Analytic height fog": mist_hfog_extinction, _optical_depth,
 * _sample_distance), its height axis (up) and its Mie phase function
 * (mie_prepared, mie_tab):
 *
 *   exact      sample_distance against an independent long double root of
 *              the optical depth's logarithm (bisection, never the closed
 *              inversion), double and float, over level, nearly level and
 *              steep rays, starts far below and far above the base, scale
 *              heights from subnormal to +inf, densities e^+-690, any tmax,
 *              and over rotated scenes (the height along any unit axis);
 *   monotone   t non-decreasing in xi over dense runs of xi;
 *   chi2       sampled distances against the density integrated by
 *              adaptive quadrature (mist_test.h), with negative controls
 *              that must be rejected;
 *   depth      optical_depth and extinction against long double;
 *   pt         a path-traced estimate of the single-scattered in-scatter
 *              (free-flight distances, the phase functions, the sun's
 *              transmittance from optical_depth) against mist_hfog_inscatter
 *              within its Monte Carlo error, and a control that must fail;
 *   up, phase  the up axis and the Mie phase function's forms;
 *   bad        bad input: the documented values, never NaN.
 *
 * The bar for a distance: |t - t*| <= 4 ulp(t*) + 4 eps xi dt* / dxi, eps of
 * the type (unit roundoff), dt* / d xi = 1 / ((1 - xi) sigma(t*)), plus the
 * reference's own rounding (REF_ERR below, reported). */
#include "mist.h"
#include "mist_test.h"

#include <float.h>
#include <string.h>

#if LDBL_MANT_DIG < 64 || LDBL_MAX_EXP < 16384
#  error "test_hfog_path needs an x87 or binary128 long double"
#endif
typedef long double LD;

/* ------------------------------------------------------------------------ */
/* Reference (long double, log domain)                                      */
/* ------------------------------------------------------------------------ */

/* One channel of one fog along one ray, in long double: ln(st d0) (lc0),
 * the start's height over H (h0 = (y - base)/H; 0 when uniform), the
 * vertical rate a = w / H, and M, the largest magnitude the logarithm of
 * the depth sums (its rounding is 2^-63 M at most: REF_ERR). */
typedef struct { LD lc0, h0, a; int uniform; LD M; } rray;

static LD fabsld(LD x) { return x < 0 ? -x : x; }

/* a . b for vectors of doubles (or floats) as hi + *lo in long double:
 * products error-free (fmal), sums too (TwoSum), exact to ~2^-128 of the
 * terms: the rotated scenes' heights and slopes without the reference's
 * own cancellation */
static LD two_sum_ld(LD a, LD b, LD *e)
{
    volatile LD s = a + b, bb = s - a;
    *e = (a - (s - bb)) + (b - bb);
    return s;
}
static LD dot_ld(const LD *a, const LD *b, LD *lo)
{
    LD s = 0, e = 0, q;
    int k;
    for (k = 0; k < 3; ++k) {
        LD p = a[k] * b[k], pe = fmal(a[k], b[k], -p);
        s = two_sum_ld(s, p, &q);
        e += q + pe;
    }
    s = two_sum_ld(s, e, lo);
    return s;
}

/* ln(phi1(x)), phi1(x) = (1 - e^-x)/x */
static LD lnphi1(LD x)
{
    if (x == 0) return 0;
    if (x > 0) return logl(-expm1l(-x) / x);
    x = -x;
    if (x < 40) return logl(expm1l(x) / x);
    return x + log1pl(-expl(-x)) - logl(x);
}

/* ln tau(t) (t > 0; -inf-free) */
static LD ln_tau(const rray *r, LD t)
{
    return r->lc0 - r->h0 + logl(t) + (r->uniform ? 0 : lnphi1(r->a * t));
}

/* ln tau(+inf) for an up ray (a > 0): ln(C0 / a); +inf otherwise */
static LD ln_tau_inf(const rray *r)
{
    if (r->uniform || !(r->a > 0)) return INFINITY;
    return r->lc0 - r->h0 - logl(r->a);
}

/* The root t* of ln tau(t) = lnT by bisection (first on ln t, then on t):
 * +inf where there is none. */
static LD ref_root(const rray *r, LD lnT)
{
    LD lo = -11300, hi = 11300, m, a, b;
    int i;
    if (!(lnT < ln_tau_inf(r))) return INFINITY;
    for (i = 0; i < 90; ++i) {
        m = (lo + hi) / 2;
        if (ln_tau(r, expl(m)) < lnT) lo = m; else hi = m;
    }
    a = expl(lo); b = expl(hi);
    for (i = 0; i < 80; ++i) {
        m = (a + b) / 2;
        if (m == a || m == b) break;
        if (ln_tau(r, m) < lnT) a = m; else b = m;
    }
    return (a + b) / 2;
}

/* the reference's relative rounding of ln tau: 2^-63 per magnitude met */
#define REF_ERR(M) ((M) * 0x1p-62L)

/* A fog's channel c along the ray, as mist's semantics define it: dir
 * used as given where |dir|^2 is 1 to 16 eps (eps of the type), else
 * normalised; the height along axis `up` (NULL: y). */
static rray ref_ray(const mist_hfog *f, int c, const LD *o, const LD *d, const LD *up, LD eps)
{
    rray r;
    LD st, y, w, n2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2], e1, e2, ylo = 0, wlo = 0;
    LD sR = c == 0 ? f->rayleigh_scat.r : c == 1 ? f->rayleigh_scat.g : f->rayleigh_scat.b;
    LD sM = c == 0 ? f->mie_scat.r : c == 1 ? f->mie_scat.g : f->mie_scat.b;
    e1 = c == 0 ? f->rayleigh_ext.r : c == 1 ? f->rayleigh_ext.g : f->rayleigh_ext.b;
    e2 = c == 0 ? f->mie_ext.r : c == 1 ? f->mie_ext.g : f->mie_ext.b;
    st = (e1 > sR ? e1 : sR) + (e2 > sM ? e2 : sM);
    if (up) {
        LD u2 = up[0] * up[0] + up[1] * up[1] + up[2] * up[2], N = 1, Nl = 0;
        if (fabsld(u2 - 1) > 16 * eps) {      /* normalised, as mist does: */
            LD nl, n = dot_ld(up, up, &nl);   /* |up| = N + Nl, and the height */
            N = sqrtl(n);                     /* divided by it with its remainder */
            Nl = (fmal(-N, N, n) + nl) / (2 * N);   /* (a unit vector rounded */
        }                                     /* to long double: |o| 2^-64 off) */
        y = dot_ld(o, up, &ylo);
        w = dot_ld(d, up, &wlo);
        w += wlo;
        if (N != 1 || Nl != 0) {
            LD q = y / N;
            ylo = (fmal(-q, N, y) + ylo - q * Nl) / N;
            y = q;
            w /= N + Nl;
        }
    } else { y = o[1]; w = d[1]; }
    if (fabsld(n2 - 1) > 16 * eps) w /= sqrtl(n2);
    r.uniform = !(f->scale_height <= DBL_MAX);
    r.lc0 = logl(st) + logl((LD)f->density);
    {
        LD dl, dh = two_sum_ld(y, -(LD)f->base, &dl);
        r.h0 = r.uniform ? 0 : (dh + (dl + ylo)) / (LD)f->scale_height;
    }
    r.a = r.uniform ? 0 : w / (LD)f->scale_height;
    r.M = fabsld(r.lc0) + fabsld(r.h0) + 8;
    return r;
}

/* One check of a distance against the bar; returns got/bar's error ratio
 * (0 where both agree there is no root).  flt: float's eps and ulp. */
static double worst_ratio = 0, worst_ref = 0;
static long n_checked = 0, n_bad = 0;
static double check_t(const rray *r, double xi, double tmax, double got, int flt, const char *what)
{
    LD eps = flt ? 0x1p-24L : 0x1p-53L, lnT = logl(-log1pl(-(LD)xi)), ts, bar, ulp, sig, lm;
    LD tmaxl = tmax, ratio;
    int e;
    ts = ref_root(r, lnT);
    lm = r->M + fabsld(lnT);
    ++n_checked;
    if (ts > tmaxl || !(ts < INFINITY)) {
        /* no root in [0, tmax]: +inf, or (within the bar) tmax itself */
        if (got == INFINITY) return 0;
        /* a root beyond tmax: a finite t is checked against it below (it
         * may be tmax itself, within the bar).  No root at all (an up ray
         * that escapes): lnT within the rounding of ln tau(inf), 8 eps,
         * of the edge is fair */
        if (!(ts < INFINITY)) {
            if (lnT > ln_tau_inf(r) - 8 * eps - REF_ERR(lm) && got <= tmax && got >= 0) return 0;
            ++n_bad;
            if (n_bad < 10) printf("  %s: xi %.17g: got %.17g, no root\n", what, xi, got);
            return 1e30;
        }
    }
    /* ulp(t*) in the type, subnormals included */
    (void)frexpl(ts, &e);
    if (flt) ulp = ldexpl(1, (e - 24 > -149) ? e - 24 : -149);
    else ulp = ldexpl(1, (e - 53 > -1074) ? e - 53 : -1074);
    sig = r->lc0 - r->h0 - r->a * ts;               /* ln sigma(t*) */
    bar = 4 * ulp + 4 * eps * expl(logl((LD)xi) - log1pl(-(LD)xi) - sig);
    /* the reference's rounding: 2^-63 M relative in tau, T dt/dT = tau/sigma */
    bar += REF_ERR(lm + fabsld(r->a * ts)) * expl(lnT - sig);
    if (got == INFINITY) {
        if (ts >= (flt ? (LD)FLT_MAX : (LD)DBL_MAX) || ts + bar >= tmaxl) return 0;
        ++n_bad;
        if (n_bad < 10) printf("  %s: xi %.17g: got +inf, t* %.17Lg\n", what, xi, ts);
        return 1e30;
    }
    if (!(got >= 0)) { ++n_bad; return 1e30; }
    ratio = fabsld((LD)got - ts) / bar;
    if (ratio > worst_ratio) {
        worst_ratio = (double)ratio;
        worst_ref = (double)(REF_ERR(lm + fabsld(r->a * ts)) * expl(lnT - sig) / bar);
    }
    if (ratio > 1) {
        ++n_bad;
        if (n_bad < 10)
            printf("  %s: xi %.17g tmax %g: got %.17g, t* %.20Lg (%.3Lg of the bar)\n", what, xi,
                   tmax, got, ts, ratio);
    }
    return (double)ratio;
}

/* ------------------------------------------------------------------------ */
/* Fogs                                                                      */
/* ------------------------------------------------------------------------ */

static mist_hfog fog_make(double base, double dens, double H, double eR, double eM)
{
    mist_hfog f;
    memset(&f, 0, sizeof f);
    f.base = base; f.density = dens; f.scale_height = H;
    f.rayleigh_scat.r = eR; f.rayleigh_scat.g = 2 * eR; f.rayleigh_scat.b = 4 * eR;
    f.rayleigh_ext = f.rayleigh_scat;
    f.mie_scat.r = f.mie_scat.g = f.mie_scat.b = 0.9 * eM;
    f.mie_ext.r = f.mie_ext.g = f.mie_ext.b = eM;
    f.mie_phase = mist_fog_make(0.6, 0.4, 1.5, 0.2);
    return f;
}

static mist_hfogf fog_tof(const mist_hfog *f)
{
    mist_hfogf g;
    memset(&g, 0, sizeof g);
    g.base = (float)f->base; g.density = (float)f->density; g.scale_height = (float)f->scale_height;
    g.rayleigh_scat.r = (float)f->rayleigh_scat.r; g.rayleigh_scat.g = (float)f->rayleigh_scat.g;
    g.rayleigh_scat.b = (float)f->rayleigh_scat.b;
    g.rayleigh_ext.r = (float)f->rayleigh_ext.r; g.rayleigh_ext.g = (float)f->rayleigh_ext.g;
    g.rayleigh_ext.b = (float)f->rayleigh_ext.b;
    g.mie_scat.r = (float)f->mie_scat.r; g.mie_scat.g = (float)f->mie_scat.g;
    g.mie_scat.b = (float)f->mie_scat.b;
    g.mie_ext.r = (float)f->mie_ext.r; g.mie_ext.g = (float)f->mie_ext.g; g.mie_ext.b = (float)f->mie_ext.b;
    g.mie_phase = mist_fog_makef((float)f->mie_phase.g_hg, (float)f->mie_phase.g_d,
                                 (float)f->mie_phase.alpha, (float)f->mie_phase.w_d);
    g.sun_dir.x = (float)f->sun_dir.x; g.sun_dir.y = (float)f->sun_dir.y; g.sun_dir.z = (float)f->sun_dir.z;
    g.sun.r = (float)f->sun.r; g.sun.g = (float)f->sun.g; g.sun.b = (float)f->sun.b;
    g.ambient.r = (float)f->ambient.r; g.ambient.g = (float)f->ambient.g; g.ambient.b = (float)f->ambient.b;
    g.sun_extinction = f->sun_extinction;
    g.up.x = (float)f->up.x; g.up.y = (float)f->up.y; g.up.z = (float)f->up.z;
    return g;
}

/* the fog as the type sees it (float: rounded) */
static mist_hfog fog_round(const mist_hfog *f, int flt)
{
    mist_hfog r = *f;
    if (flt) {
        mist_hfogf g = fog_tof(f);
        r.base = g.base; r.density = g.density; r.scale_height = g.scale_height;
        r.rayleigh_scat.r = g.rayleigh_scat.r; r.rayleigh_scat.g = g.rayleigh_scat.g;
        r.rayleigh_scat.b = g.rayleigh_scat.b;
        r.rayleigh_ext.r = g.rayleigh_ext.r; r.rayleigh_ext.g = g.rayleigh_ext.g;
        r.rayleigh_ext.b = g.rayleigh_ext.b;
        r.mie_scat.r = g.mie_scat.r; r.mie_scat.g = g.mie_scat.g; r.mie_scat.b = g.mie_scat.b;
        r.mie_ext.r = g.mie_ext.r; r.mie_ext.g = g.mie_ext.g; r.mie_ext.b = g.mie_ext.b;
        r.up.x = g.up.x; r.up.y = g.up.y; r.up.z = g.up.z;
    }
    return r;
}

/* one distance: the type's function on the (rounded) inputs, checked */
static double one(const mist_hfog *f0, int flt, const double *o, const double *d, double tmax,
                  int c, double xi, const char *what)
{
    mist_hfog f = fog_round(f0, flt);
    LD ol[3], dl[3], ul[3], eps = flt ? 0x1p-24L : 0x1p-53L;
    double got;
    int k, axis = !(f.up.x == 0 && f.up.y == 0 && f.up.z == 0);
    rray r;
    if (flt) {
        mist_hfogf g = fog_tof(f0);
        mist_vec3f of = { (float)o[0], (float)o[1], (float)o[2] }, df = { (float)d[0], (float)d[1], (float)d[2] };
        float xf = (float)xi, tf = (float)tmax;
        got = mist_hfog_sample_distancef(&g, of, df, tf, c, xf);
        ol[0] = of.x; ol[1] = of.y; ol[2] = of.z; dl[0] = df.x; dl[1] = df.y; dl[2] = df.z;
        xi = xf; tmax = tf;
    } else {
        mist_vec3 od = { o[0], o[1], o[2] }, dd = { d[0], d[1], d[2] };
        got = mist_hfog_sample_distance(&f, od, dd, tmax, c, xi);
        for (k = 0; k < 3; ++k) { ol[k] = o[k]; dl[k] = d[k]; }
    }
    ul[0] = f.up.x; ul[1] = f.up.y; ul[2] = f.up.z;
    r = ref_ray(&f, c, ol, dl, axis ? ul : NULL, eps);
    if (got != got) { ++n_bad; printf("  %s: NaN\n", what); return 1e30; }
    {
        long b0 = n_bad;
        double q = check_t(&r, xi, tmax, got, flt, what);
        if (n_bad > b0 && n_bad < 10)
            printf("    (H %g, h0 %.6Lg, a %.6Lg, ln(st d0) %.6Lg, o %.17g %.17g %.17g, d %.17g %.17g %.17g, c %d)\n",
                   f.scale_height, r.h0, r.a, r.lc0, o[0], o[1], o[2], d[0], d[1], d[2], c);
        return q;
    }
}

/* ------------------------------------------------------------------------ */
/* Exactness over a grid                                                    */
/* ------------------------------------------------------------------------ */

static void test_exact(int flt)
{
    /* scale heights: subnormal, tiny, ordinary, huge, uniform */
    const double Hs_d[] = { 0x1p-1060, 1e-200, 1e-3, 1, 1000, 1e200, INFINITY };
    const double Hs_f[] = { 0x1p-140, 1e-30, 1e-3, 1, 1000, 1e30, INFINITY };
    /* the start's height over H: density factors e^+-690 (float e^+-80),
     * and far beyond (1e5: the density under- or overflows) */
    const double h0s_d[] = { -1e5, -690, -30, -1, 0, 0.5, 30, 690, 1e5 };
    const double h0s_f[] = { -1e5, -80, -10, -1, 0, 0.5, 10, 80, 1e5 };
    const double ws_d[] = { 0, 1e-300, -1e-300, 1e-12, -1e-12, 1e-6, -1e-6, 1e-3, -1e-3, 0.3, -0.3, 1, -1 };
    const double ws_f[] = { 0, 1e-38, -1e-38, 1e-7, -1e-7, 1e-3, -1e-3, 0.3, -0.3, 1, -1 };
    const double xis[] = { 0x1p-60, 1e-9, 1e-3, 0.1, 0.5, 0.9, 1 - 1e-6, 1 - 0x1p-24 };
    const double dens[] = { 1e-5, 1, 3e4 };
    const double *Hs = flt ? Hs_f : Hs_d, *h0s = flt ? h0s_f : h0s_d, *ws = flt ? ws_f : ws_d;
    int nH = 7, nh = 9, nw = flt ? 11 : 13, iH, ih, iw, ix, id, it;
    double before = worst_ratio;
    long bad0 = n_bad, n0 = n_checked;
    mt_rng rng;
    rng.s = 7 + (uint64_t)flt;
    worst_ratio = 0;
    for (iH = 0; iH < nH; ++iH)
        for (ih = 0; ih < nh; ++ih)
            for (iw = 0; iw < nw; ++iw)
                for (id = 0; id < 3; ++id) {
                    double H = Hs[iH], base = id == 1 ? 0 : 37.25, o[3], d[3], sc;
                    double w = ws[iw], hz = sqrt(1 - w * w);
                    mist_hfog f = fog_make(base, dens[id], H, 1e-3, id == 2 ? 0 : 0.02);
                    o[0] = 3; o[2] = -1;
                    o[1] = H < INFINITY ? base + h0s[ih] * H : base + h0s[ih];
                    if (flt && !(fabs(o[1]) <= FLT_MAX)) continue;
                    /* a direction of length 1, 3.5 or 2^-30 */
                    sc = id == 0 ? 1 : (id == 1 ? 3.5 : 0x1p-30);
                    d[0] = sc * hz; d[1] = sc * w; d[2] = 0;
                    for (ix = 0; ix < 8; ++ix)
                        for (it = 0; it < 3; ++it) {
                            double xi = xis[ix], tmax;
                            int c = (ix + it) % 3;
                            if (flt && xi < 1e-30) xi = 0x1p-100;
                            tmax = it == 0 ? INFINITY : (it == 1 ? pow(10, 12 * mt_uniform(&rng) - 6) : DBL_MAX);
                            if (flt && it == 2) tmax = FLT_MAX;
                            one(&f, flt, o, d, tmax, c, xi, flt ? "exact float" : "exact double");
                        }
                }
    printf("exact %s: %ld distances, worst %.3f of the bar (the reference's share of that bar "
           "%.2g)\n", flt ? "float" : "double", n_checked - n0, worst_ratio, worst_ref);
    mt_check(n_bad == bad0, "exact %s: %ld of %ld distances beyond the bar", flt ? "float" : "double",
             n_bad - bad0, n_checked - n0);
    if (before > worst_ratio) worst_ratio = before;
}

/* Random configurations: heights, slopes (log-uniform to 1e-15), scale
 * heights, densities, extinctions, xi, tmax; and the same scenes rotated
 * (an axis `up` that is any unit vector, the vectors rotated with it in
 * long double and rounded). */
static void test_random(int flt, int rotate, long n)
{
    mt_rng rng;
    long i, bad0 = n_bad, n0 = n_checked;
    double w0 = worst_ratio;
    rng.s = 1234567 + 2 * (uint64_t)flt + (uint64_t)rotate + (rotate == 2 ? 1000 : 0);
    worst_ratio = 0;
    for (i = 0; i < n; ++i) {
        double H = pow(10, -2 + 6 * mt_uniform(&rng)), base = 200 * (mt_uniform(&rng) - 0.5);
        double h0 = (mt_uniform(&rng) < 0.5 ? -1 : 1) * pow(10, -3 + 5 * mt_uniform(&rng));
        double w = (mt_uniform(&rng) < 0.5 ? -1 : 1)
                 * pow(10, (mt_uniform(&rng) < 0.1 ? (flt ? -37 : -250) : -15) * mt_uniform(&rng));
        double dn = pow(10, -6 + 8 * mt_uniform(&rng)), xi = mt_uniform(&rng);
        double tmax = mt_uniform(&rng) < 0.4 ? INFINITY : pow(10, -3 + 8 * mt_uniform(&rng));
        double o[3], d[3], y, hz;
        mist_hfog f;
        if (flt && fabs(h0) > 80) h0 = h0 > 0 ? 80 * mt_uniform(&rng) : -80 * mt_uniform(&rng);
        f = fog_make(base, dn, H, pow(10, -5 + 3 * mt_uniform(&rng)), pow(10, -4 + 3 * mt_uniform(&rng)));
        y = base + h0 * H;
        hz = sqrt(1 - w * w);
        o[0] = 1000 * (mt_uniform(&rng) - 0.5); o[1] = y; o[2] = 1000 * (mt_uniform(&rng) - 0.5);
        d[0] = hz * cos(7 * mt_uniform(&rng)); d[2] = hz * sin(7 * mt_uniform(&rng)); d[1] = w;
        if (rotate) {
            /* a random rotation R (Rodrigues, long double): up = R e_y,
             * o' = R o, d' = R d, rounded to the type */
            LD ax[3], an = 7 * mt_uniform(&rng), nn, R[3][3], ca, sa, v[3];
            double o2[3], d2[3];
            int a, b;
            ax[0] = mt_uniform(&rng) - 0.5; ax[1] = mt_uniform(&rng) - 0.5; ax[2] = mt_uniform(&rng) - 0.5;
            nn = sqrtl(ax[0] * ax[0] + ax[1] * ax[1] + ax[2] * ax[2]);
            for (a = 0; a < 3; ++a) ax[a] /= nn;
            ca = cosl(an); sa = sinl(an);
            for (a = 0; a < 3; ++a)
                for (b = 0; b < 3; ++b) R[a][b] = (a == b ? ca : 0) + (1 - ca) * ax[a] * ax[b];
            R[0][1] -= sa * ax[2]; R[0][2] += sa * ax[1]; R[1][0] += sa * ax[2];
            R[1][2] -= sa * ax[0]; R[2][0] -= sa * ax[1]; R[2][1] += sa * ax[0];
            for (a = 0; a < 3; ++a) {
                v[a] = R[a][1];
                o2[a] = (double)(R[a][0] * o[0] + R[a][1] * o[1] + R[a][2] * o[2]);
                d2[a] = (double)(R[a][0] * d[0] + R[a][1] * d[1] + R[a][2] * d[2]);
            }
            f.up.x = (double)v[0]; f.up.y = (double)v[1]; f.up.z = (double)v[2];
            if (flt) {   /* up unit to float's rounding (else it is normalised) */
                f.up.x = (float)f.up.x; f.up.y = (float)f.up.y; f.up.z = (float)f.up.z;
            }
            if (rotate == 2) {   /* up of any length: the height and slope
                                  * along up / |up| (the reference divides by
                                  * |up| in long double; mist rounding the
                                  * unit vector instead erred by |o|/H eps) */
                double k = pow(10, -3 + 6 * mt_uniform(&rng));
                f.up.x *= k; f.up.y *= k; f.up.z *= k;
                if (flt) { f.up.x = (float)f.up.x; f.up.y = (float)f.up.y; f.up.z = (float)f.up.z; }
            }
            memcpy(o, o2, sizeof o); memcpy(d, d2, sizeof d);
        }
        one(&f, flt, o, d, tmax, (int)(i % 3), xi, rotate ? "rotated" : "random");
    }
    printf("%s %s: %ld distances, worst %.3f of the bar\n",
           rotate == 2 ? "rotated, up not unit," : rotate ? "rotated" : "random",
           flt ? "float" : "double", n_checked - n0, worst_ratio);
    mt_check(n_bad == bad0, "%s %s: %ld of %ld distances beyond the bar",
             rotate == 2 ? "rotated, up not unit," : rotate ? "rotated" : "random",
             flt ? "float" : "double", n_bad - bad0, n_checked - n0);
    if (w0 > worst_ratio) worst_ratio = w0;
}

/* ------------------------------------------------------------------------ */
/* Monotone in xi                                                           */
/* ------------------------------------------------------------------------ */

/* t(xi) non-decreasing (+inf above all) over sorted random xi and over
 * runs of consecutive xi (nextafter) around: small, 1/2, near 1, the
 * escape of an up ray, and the point where z = a K passes 2^-60 (the
 * inversion's switch from z / a to log1p(z) / a). */
static int cmp_dbl(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}
static long mono_run(const mist_hfog *f, const mist_vec3 *o, const mist_vec3 *d, double tmax,
                     const double *xs, long n)
{
    mist_hfogf g = fog_tof(f);
    mist_vec3f of = { (float)o->x, (float)o->y, (float)o->z }, df = { (float)d->x, (float)d->y, (float)d->z };
    double prev = -1;
    float prevf = -1;
    long i, bad = 0;
    for (i = 0; i < n; ++i) {
        double t = mist_hfog_sample_distance(f, *o, *d, tmax, 1, xs[i]);
        float tf = mist_hfog_sample_distancef(&g, of, df, (float)tmax, 1, (float)xs[i]);
        if (!(t >= prev)) ++bad;
        if (!(tf >= prevf)) ++bad;
        prev = t; prevf = tf;
    }
    return bad;
}
static void test_monotone(void)
{
    static double xs[40000];
    const double ws[] = { 0, 1e-300, -1e-300, 1e-9, -1e-9, 0.2, -0.2, 1, -1 };
    mt_rng rng;
    long bad = 0, runs = 0, n, i;
    size_t iw;
    rng.s = 99;
    for (iw = 0; iw < sizeof ws / sizeof *ws; ++iw) {
        int ih;
        for (ih = 0; ih < 3; ++ih) {
            mist_hfog f = fog_make(5, 0.5, 300, 1e-3, 0.01);
            mist_vec3 o = { 0, 5 + (ih - 1) * 3000.0, 0 }, d;
            double w = ws[iw], s, xc[6];
            int k;
            d.x = sqrt(1 - w * w); d.y = w; d.z = 0;
            for (i = 0; i < 20000; ++i) xs[i] = mt_uniform(&rng);
            qsort(xs, 20000, sizeof *xs, cmp_dbl);
            bad += mono_run(&f, &o, &d, INFINITY, xs, 20000);
            bad += mono_run(&f, &o, &d, 5000, xs, 20000);
            runs += 2;
            /* centres of runs of consecutive xi: the switch z = 2^-60 and
             * the escape z = 1 (up), in the fog's own terms */
            s = 2e-3 * 0.5 * exp(-(o.y - 5) / 300);     /* st rho0 of channel 1 */
            s += 0.01 * 0.5 * exp(-(o.y - 5) / 300);
            xc[0] = 1e-12; xc[1] = 0.5; xc[2] = 1 - 1e-12;
            xc[3] = w != 0 ? -expm1(-0x1p-60 * s * 300 / fabs(w)) : 0.25;
            xc[4] = w > 0 ? -expm1(-s * 300 / w) : 0.75;
            xc[5] = 0x1p-70;
            for (k = 0; k < 6; ++k) {
                double x = xc[k] * (1 - 1e-12);
                if (!(x > 0 && x < 1)) continue;
                for (n = 0; n < 4000; ++n) { xs[n] = x; x = nextafter(x, 1); }
                bad += mono_run(&f, &o, &d, INFINITY, xs, 4000);
                ++runs;
            }
        }
    }
    printf("monotone: %ld runs (double and float), %ld decreasing steps\n", runs, bad);
    mt_check(bad == 0, "monotone: %ld decreasing steps", bad);
}

/* ------------------------------------------------------------------------ */
/* Chi-square: sampled distances against the density                       */
/* ------------------------------------------------------------------------ */

/* The density along the ray (double, for quadrature): sigma(t) =
 * st d0 exp(-(y + w t - base) / H). */
typedef struct { double st, d0, y, w, base, H; } chi_ray;
static double chi_sigma(double t, const void *c)
{
    const chi_ray *r = (const chi_ray *)c;
    return r->st * r->d0 * exp(-(r->y + r->w * t - r->base) / r->H);
}
/* tau(t) by adaptive Gauss-Kronrod (independent of every closed form) */
static double chi_tau(const chi_ray *r, double t)
{
    double err, a = 0, sum = 0, step = r->w != 0 ? r->H / fabs(r->w) : t;
    if (step > t) step = t;
    while (a < t) {                /* pieces of a scale height: smooth integrands */
        double b = a + step < t ? a + step : t;
        double s0 = chi_sigma(a, r), s1 = chi_sigma(b, r);
        sum += mt_integrate(chi_sigma, r, a, b, 1e-13 * (s0 > s1 ? s0 : s1) * (b - a), &err);
        a = b;
        if (sum > 60) return sum;
    }
    return sum;
}
/* edges t_j with P(t < t_j) = j/K of the collision probability P(tmax)
 * (bisection on the quadrature's CDF); returns P(tmax) */
static double chi_edges(const chi_ray *r, double tmax, double *edge, int K)
{
    double tend = tmax, P, hi;
    int j, it;
    if (!(tmax < INFINITY)) tend = r->w > 0 ? 60 * r->H / r->w : 1e7;
    P = -expm1(-chi_tau(r, tend));
    hi = tend;
    for (j = 1; j < K; ++j) {
        double lo = 0, h = hi, target = P * j / K;
        for (it = 0; it < 60; ++it) {
            double m = 0.5 * (lo + h);
            if (-expm1(-chi_tau(r, m)) < target) lo = m; else h = m;
        }
        edge[j] = 0.5 * (lo + h);
    }
    edge[0] = 0; edge[K] = tmax;
    return P;
}
/* counts of t in the K cells and the "no collision" cell K */
static void chi_count(const double *t, long n, const double *edge, int K, double *obs)
{
    long i;
    int j;
    for (j = 0; j <= K; ++j) obs[j] = 0;
    for (i = 0; i < n; ++i) {
        int lo = 0, hi = K;
        if (!(t[i] <= edge[K]) || t[i] == INFINITY) { obs[K] += 1; continue; }
        while (hi - lo > 1) { int m = (lo + hi) / 2; if (t[i] < edge[m]) hi = m; else lo = m; }
        obs[lo] += 1;
    }
}
static void test_chi2(void)
{
    enum { K = 40 };
    /* rays: down from above the base to tmax, up and escaping (tmax inf),
     * level, nearly level down to infinity, uniform fog */
    const double ys[] = { 400, -50, 10, 300, 0 }, ws[] = { -0.6, 0.5, 0, -1e-3, 0.3 };
    const double tms[] = { 2000, INFINITY, 500, INFINITY, 300 };
    const double Hs[] = { 150, 150, 150, 150, INFINITY };
    static double t[200000], tb[200000];
    /* (not scaled down by MIST_TEST_QUICK: at 2e5 samples the weakest
     * control is rejected at p = 2e-8, at 2.5e4 it was not) */
    long n = 200000, i;
    int c, k, dof, nk = 5;
    double alpha = mt_sidak(1e-3, 2 * nk);
    mt_rng rng;
    rng.s = 4242;
    for (k = 0; k < nk; ++k) {
        for (c = 0; c < 2; ++c) {     /* double, float */
            mist_hfog f = fog_make(0, 1.0, Hs[k], 2e-4, 2e-3);
            mist_hfogf g = fog_tof(&f);
            mist_vec3 o = { 1, ys[k], 2 }, d;
            mist_vec3f of, df;
            chi_ray r;
            double edge[K + 1], obs[K + 1], ex[K + 1], P, p, pb, pc;
            int j;
            d.x = sqrt(1 - ws[k] * ws[k]); d.y = ws[k]; d.z = 0;
            of.x = (float)o.x; of.y = (float)o.y; of.z = (float)o.z;
            df.x = (float)d.x; df.y = (float)d.y; df.z = (float)d.z;
            r.st = 4e-4 + 2e-3; r.d0 = 1; r.y = o.y; r.w = d.y; r.base = 0;
            r.H = Hs[k] < INFINITY ? Hs[k] : 1e300;
            P = chi_edges(&r, tms[k], edge, K);
            for (j = 0; j < K; ++j) ex[j] = (double)n * P / K;
            ex[K] = (double)n * (1 - P);
            for (i = 0; i < n; ++i) {
                double xi = mt_uniform(&rng);
                t[i] = c ? (double)mist_hfog_sample_distancef(&g, of, df, (float)tms[k], 1, (float)xi)
                         : mist_hfog_sample_distance(&f, o, d, tms[k], 1, xi);
                /* control (b): the density at the start taken as constant */
                tb[i] = -log1p(-xi) / (r.st * exp(-(o.y - 0) / r.H));
                if (tb[i] > tms[k]) tb[i] = INFINITY;
            }
            chi_count(t, n, edge, K, obs);
            p = mt_chi2(obs, ex, K + 1, &dof);
            mt_check(p > alpha, "chi2 %s ray %d: p = %.3g (alpha %.3g)", c ? "float" : "double", k, p, alpha);
            /* control (a): against a fog of 3% larger scale height (uniform:
             * 3% more extinction) */
            {
                chi_ray r2 = r;
                double e2[K + 1], P2;
                if (Hs[k] < INFINITY && ws[k] != 0) r2.H *= 1.03; else r2.st *= 1.03;
                P2 = chi_edges(&r2, tms[k], e2, K);
                for (j = 0; j < K; ++j) ex[j] = (double)n * P2 / K;
                ex[K] = (double)n * (1 - P2);
                chi_count(t, n, e2, K, obs);
                pc = mt_chi2(obs, ex, K + 1, &dof);
                for (j = 0; j < K; ++j) ex[j] = (double)n * P / K;
                ex[K] = (double)n * (1 - P);
            }
            chi_count(tb, n, edge, K, obs);
            pb = mt_chi2(obs, ex, K + 1, &dof);
            printf("chi2 %s ray %d (y %g, w %g, tmax %g): p = %.3g; controls: H x 1.03 p = %.3g, "
                   "constant density p = %.3g\n", c ? "float" : "double", k, ys[k], ws[k], tms[k], p,
                   pc, pb);
            mt_check(pc < alpha, "chi2 control (H x 1.03) ray %d not rejected: p = %.3g", k, pc);
            if (k != 4 && k != 2)   /* (uniform fog, level ray: the constant density is right) */
                mt_check(pb < alpha, "chi2 control (constant density) ray %d not rejected: p = %.3g", k, pb);
        }
    }
}

/* ------------------------------------------------------------------------ */
/* Optical depth and extinction                                             */
/* ------------------------------------------------------------------------ */

/* optical_depth against exp(ln tau) of the reference, and extinction
 * against st d0 e^-h0 (long double), over the random scenes of
 * test_random (y axis and rotated).  The bar: 6 eps relative (the
 * column's few ulps [section comment] and the product with st), plus the
 * reference's rounding. */
static void test_depth(int flt, int rotate, long n)
{
    mt_rng rng;
    long i, bad = 0, nd = 0;
    double worst = 0, worste = 0;
    LD eps = flt ? 0x1p-24L : 0x1p-53L;
    rng.s = 555 + 2 * (uint64_t)flt + (uint64_t)rotate;
    for (i = 0; i < n; ++i) {
        double H = pow(10, -2 + 6 * mt_uniform(&rng)), base = 200 * (mt_uniform(&rng) - 0.5);
        double h0 = (mt_uniform(&rng) < 0.5 ? -1 : 1) * pow(10, -3 + (flt ? 1.9 : 2.8) * mt_uniform(&rng));
        double w = (mt_uniform(&rng) < 0.5 ? -1 : 1) * pow(10, -15 * mt_uniform(&rng));
        double s = mt_uniform(&rng) < 0.2 ? INFINITY : pow(10, -3 + 8 * mt_uniform(&rng));
        double o[3], d[3], hz = sqrt(1 - w * w);
        mist_hfog f = fog_make(base, pow(10, -3 + 4 * mt_uniform(&rng)), H, 1e-4, 1e-3);
        int c = (int)(i % 3), k;
        LD ol[3], dl[3], ul[3], ref, got, lt, ref_e, got_e, bar;
        rray r;
        o[0] = 100 * (mt_uniform(&rng) - 0.5); o[1] = base + h0 * H; o[2] = 100 * mt_uniform(&rng);
        d[0] = hz * cos(2.0 * i); d[1] = w; d[2] = hz * sin(2.0 * i);
        if (rotate) {
            double an = 0.3 + i * 1e-3, ca = cos(an), sa = sin(an), t0 = o[1], t1 = d[1];
            /* a rotation about z by an: up = (-sin, cos, 0) */
            o[1] = ca * t0 + sa * o[0]; o[0] = ca * o[0] - sa * t0;
            d[1] = ca * t1 + sa * d[0]; d[0] = ca * d[0] - sa * t1;
            f.up.x = -sa; f.up.y = ca; f.up.z = 0;
        }
        f = fog_round(&f, flt);
        if (flt) {
            mist_hfogf g = fog_tof(&f);
            mist_vec3f of = { (float)o[0], (float)o[1], (float)o[2] }, df = { (float)d[0], (float)d[1], (float)d[2] };
            mist_rgbf tf = mist_hfog_optical_depthf(&g, of, df, (float)s);
            mist_rgbf ef = mist_hfog_extinctionf(&g, of);
            got = c == 0 ? tf.r : c == 1 ? tf.g : tf.b;
            got_e = c == 0 ? ef.r : c == 1 ? ef.g : ef.b;
            ol[0] = of.x; ol[1] = of.y; ol[2] = of.z; dl[0] = df.x; dl[1] = df.y; dl[2] = df.z;
            s = (float)s;
        } else {
            mist_vec3 od = { o[0], o[1], o[2] }, dd = { d[0], d[1], d[2] };
            mist_rgb td = mist_hfog_optical_depth(&f, od, dd, s), ed = mist_hfog_extinction(&f, od);
            got = c == 0 ? td.r : c == 1 ? td.g : td.b;
            got_e = c == 0 ? ed.r : c == 1 ? ed.g : ed.b;
            for (k = 0; k < 3; ++k) { ol[k] = o[k]; dl[k] = d[k]; }
        }
        ul[0] = f.up.x; ul[1] = f.up.y; ul[2] = f.up.z;
        r = ref_ray(&f, c, ol, dl, rotate ? ul : NULL, eps);
        if (s < INFINITY) lt = ln_tau(&r, s);
        else lt = r.a > 0 ? ln_tau_inf(&r) : INFINITY;
        ref = expl(lt);
        ref_e = expl(r.lc0 - r.h0);
        if (ref >= (flt ? FLT_MIN / eps : DBL_MIN / eps) && ref <= (flt ? FLT_MAX : DBL_MAX)) {
            LD e = fabsld(got - ref) / ref;
            bar = 6 * eps + REF_ERR(r.M + fabsld(lt) + (s < INFINITY ? fabsld(r.a * s) : 0));
            /* along a rotated axis the slope w = dir . up is rounded once
             * (relative error <= eps): the depth's exponent w s / H then
             * carries |w s / H| eps (see the section comment, THE HEIGHT AXIS) */
            if (rotate) bar += eps * (1 + (s < INFINITY ? fabsld(r.a * s) : 0));
            ++nd;
            if (e / bar > worst) worst = (double)(e / bar);
            if (e > bar) {
                if (bad < 3)
                    printf("  depth: got %.17Lg ref %.20Lg (o %a %a %a d %a %a %a up %a %a %a s %a H %a base %a h0 %Lg a %Lg)\n",
                           got, ref, o[0], o[1], o[2], d[0], d[1], d[2], f.up.x, f.up.y, f.up.z, s,
                           f.scale_height, f.base, r.h0, r.a);
                ++bad;
            }
        } else if (ref == INFINITY && got != INFINITY) ++bad;
        if (ref_e >= (flt ? FLT_MIN / eps : DBL_MIN / eps) && ref_e <= (flt ? FLT_MAX : DBL_MAX)) {
            LD e = fabsld(got_e - ref_e) / ref_e;
            bar = 4 * eps + REF_ERR(r.M);
            if (e / bar > worste) worste = (double)(e / bar);
            if (e > bar) { if (bad < 5) printf("  extinction: got %.17Lg ref %.20Lg\n", got_e, ref_e); ++bad; }
        }
        if (got != got || got_e != got_e) ++bad;
    }
    printf("depth %s%s: %ld optical depths, worst %.3f of the bar (6 eps%s); extinction worst %.3f "
           "of the bar (4 eps)\n", flt ? "float" : "double", rotate ? " rotated" : "", nd, worst,
           rotate ? " + (1 + |w s/H|) eps" : "", worste);
    mt_check(bad == 0, "depth %s%s: %ld beyond the bar", flt ? "float" : "double", rotate ? " rotated" : "", bad);
}

/* ------------------------------------------------------------------------ */
/* Bad input                                                                */
/* ------------------------------------------------------------------------ */

static int rgb_is(mist_rgb a, double v) { return a.r == v && a.g == v && a.b == v; }
static void test_bad(void)
{
    mist_hfog f = fog_make(0, 1, 100, 1e-3, 1e-2), g;
    mist_vec3 o = { 0, 10, 0 }, d = { 0.6, 0.8, 0 }, z = { 0, 0, 0 }, nanv = { NAN, 0, 0 };
    mist_vec3 io = { 0, INFINITY, 0 };
    double t;
    int ok = 1, c;
    mist_hfogf ff = fog_tof(&f);
    mist_vec3f of = { 0, 10, 0 }, df = { 0.6f, 0.8f, 0 };
    /* no fog: +inf (no collision), depth and extinction 0 */
    ok &= mist_hfog_sample_distance(NULL, o, d, 10, 0, 0.5) == INFINITY;
    ok &= rgb_is(mist_hfog_optical_depth(NULL, o, d, 10), 0) && rgb_is(mist_hfog_extinction(NULL, o), 0);
    ok &= mist_hfog_sample_distance(&f, o, d, 10, -1, 0.5) == INFINITY;
    ok &= mist_hfog_sample_distance(&f, o, d, 10, 3, 0.5) == INFINITY;
    g = f; g.density = 0;
    ok &= mist_hfog_sample_distance(&g, o, d, 10, 0, 0.5) == INFINITY && rgb_is(mist_hfog_optical_depth(&g, o, d, 10), 0);
    g = f; g.density = NAN;
    ok &= mist_hfog_sample_distance(&g, o, d, 10, 0, 0.5) == INFINITY && rgb_is(mist_hfog_extinction(&g, o), 0);
    g = f; g.scale_height = -1;
    ok &= mist_hfog_sample_distance(&g, o, d, 10, 0, 0.5) == INFINITY && rgb_is(mist_hfog_optical_depth(&g, o, d, 10), 0);
    g = f; g.scale_height = NAN;
    ok &= mist_hfog_sample_distance(&g, o, d, 10, 0, 0.5) == INFINITY && rgb_is(mist_hfog_extinction(&g, o), 0);
    g = f; g.base = INFINITY;
    ok &= mist_hfog_sample_distance(&g, o, d, 10, 0, 0.5) == INFINITY && rgb_is(mist_hfog_extinction(&g, o), 0);
    g = f; memset(&g.rayleigh_scat, 0, 4 * sizeof g.rayleigh_scat);   /* no extinction */
    ok &= mist_hfog_sample_distance(&g, o, d, 10, 0, 0.5) == INFINITY && rgb_is(mist_hfog_extinction(&g, o), 0);
    ok &= mist_hfog_sample_distance(&f, io, d, 10, 0, 0.5) == INFINITY && rgb_is(mist_hfog_extinction(&f, io), 0);
    ok &= rgb_is(mist_hfog_optical_depth(&f, io, d, 10), 0);
    mt_check(ok, "bad input: no fog gives +inf distances, 0 depth and extinction");
    /* xi: NaN and <= 0 give 0, >= 1 (inf too) +inf; tmax NaN or <= 0 +inf */
    ok = mist_hfog_sample_distance(&f, o, d, 10, 0, NAN) == 0 && mist_hfog_sample_distance(&f, o, d, 10, 0, -1) == 0
      && mist_hfog_sample_distance(&f, o, d, 10, 0, 0) == 0 && mist_hfog_sample_distance(&f, o, d, INFINITY, 0, 1) == INFINITY
      && mist_hfog_sample_distance(&f, o, d, INFINITY, 0, INFINITY) == INFINITY
      && mist_hfog_sample_distance(&f, o, d, NAN, 0, 0.5) == INFINITY
      && mist_hfog_sample_distance(&f, o, d, -3, 0, 0.5) == INFINITY
      && mist_hfog_sample_distance(&f, o, d, 0, 0, 0.5) == INFINITY
      && mist_hfog_sample_distancef(&ff, of, df, 10, 0, NAN) == 0
      && mist_hfog_sample_distancef(&ff, of, df, INFINITY, 0, 1) == INFINITY;
    mt_check(ok, "bad input: xi NaN, <= 0: 0; xi >= 1: +inf; tmax NaN, <= 0: +inf");
    /* t of the depth NaN, <= 0: 0; +inf allowed */
    ok = rgb_is(mist_hfog_optical_depth(&f, o, d, NAN), 0) && rgb_is(mist_hfog_optical_depth(&f, o, d, -1), 0);
    {
        mist_vec3 dn = { 0, -1, 0 };
        mist_rgb a = mist_hfog_optical_depth(&f, o, dn, INFINITY);
        ok &= a.r == INFINITY && a.g == INFINITY && a.b == INFINITY;
    }
    mt_check(ok, "bad input: depth to t NaN or <= 0 is 0; down to infinity +inf");
    /* a zero, NaN or infinite direction: (0, 0, 1), level (as mist_hfog_eval) */
    for (c = 0; c < 3; ++c) {
        mist_vec3 lv = { 0, 0, 1 };
        t = mist_hfog_sample_distance(&f, o, z, INFINITY, c, 0.3);
        ok = t == mist_hfog_sample_distance(&f, o, lv, INFINITY, c, 0.3);
        t = mist_hfog_sample_distance(&f, o, nanv, INFINITY, c, 0.3);
        ok &= t == mist_hfog_sample_distance(&f, o, lv, INFINITY, c, 0.3);
        mt_check(ok, "bad input: a zero or NaN direction is (0, 0, 1), channel %d", c);
    }
    /* a Mie table not built (zeroed; or its init failed): isotropic, as
     * mist_tab_eval; a NULL one: mie_phase */
    {
        mist_tab zt;
        mist_hfog h = f;
        mist_phase iso = mist_phase_hg(0);
        mist_rgb a, b;
        memset(&zt, 0, sizeof zt);
        zt.channels = 3;
        h.sun_dir.x = 0.3; h.sun_dir.y = 0.5; h.sun_dir.z = 0.2; h.sun.r = h.sun.g = h.sun.b = 1;
        h.mie_tab = &zt;
        a = mist_hfog_inscatter(&h, o, d, 100);
        h.mie_tab = NULL; h.mie_prepared = &iso;
        b = mist_hfog_inscatter(&h, o, d, 100);
        mt_check(fabs(a.r - b.r) <= 1e-14 * b.r && fabs(a.b - b.b) <= 1e-14 * b.b,
                 "bad input: a Mie table not built is isotropic (%.17g, %.17g)", a.r, b.r);
    }
    /* never NaN over a grid of bad and extreme values */
    {
        const double v[] = { 0, -0.0, 1e-320, -1, 1, 1e300, INFINITY, -INFINITY, NAN };
        int i, j, k2, nan_seen = 0;
        for (i = 0; i < 9; ++i)
            for (j = 0; j < 9; ++j)
                for (k2 = 0; k2 < 9; ++k2) {
                    mist_hfog h = f;
                    mist_vec3 oo = { v[i], v[j], 1 }, dd = { 1, v[k2], v[i] };
                    mist_rgb a, e;
                    h.density = v[j] == 0 ? 1 : fabs(v[j]); h.scale_height = v[k2]; h.base = v[i];
                    h.up.x = v[k2]; h.up.y = v[j];
                    a = mist_hfog_optical_depth(&h, oo, dd, v[k2]);
                    e = mist_hfog_extinction(&h, oo);
                    t = mist_hfog_sample_distance(&h, oo, dd, v[j], k2 % 3, fabs(v[i]) < 1 ? 0.5 : v[i]);
                    nan_seen += t != t || !(t >= 0) || a.r != a.r || a.g != a.g || a.b != a.b
                             || e.r != e.r || e.g != e.g || e.b != e.b;
                }
        mt_check(nan_seen == 0, "bad input: %d NaN or negative results over the grid", nan_seen);
    }
}

/* ------------------------------------------------------------------------ */
/* The Mie phase function: mie_prepared, mie_tab                            */
/* ------------------------------------------------------------------------ */

/* The in-scatter is linear in the Mie phase value p: L = A + B p per
 * channel, for one ray.  With three prepared phase functions (HG .2,
 * Draine .5 / 17, Rayleigh) and a 3-channel table (HG .2, .5, .8 on 513
 * nodes, each channel its own), the results must lie on one line in p,
 * p as mist_phase_eval / mist_tab_eval give it: |L - line| <= 16 eps L
 * (each L within 5 eps (1 + tau) of exact, the section's bar, and the
 * line's two points as well; tau < 1 here).  mie_prepared with
 * mist_phase_fog(mie_phase) against mie_phase itself: their phase values
 * differ by rounding alone, 16 eps likewise.  Also the layers. */
static void test_phase(void)
{
    enum { NT = 513 };
    static double mu[NT], pv[3 * NT];
    size_t b3 = mist_tab_bytes(NT, 3), b1 = mist_tab_bytes(NT, 1);
    mist_tab *tab = (mist_tab *)malloc(b3), *tab1 = (mist_tab *)malloc(b1);
    mist_phase P[3];
    mist_hfog f = fog_make(0, 1, 200, 1e-4, 2e-4);
    mist_vec3 o = { 0, 50, 0 }, d = { 0.6, -0.1, 0 };
    double worst = 0, eps = 0x1p-53;
    int i, c, bad = 0, r;
    for (i = 0; i < NT; ++i) {
        mu[i] = i == NT - 1 ? 1 : -1 + 2.0 * i / (NT - 1);
        for (c = 0; c < 3; ++c) pv[3 * i + c] = mist_hg_eval(0.2 + 0.3 * c, mu[i]);
    }
    if (!tab || !tab1) { mt_check(0, "phase: out of memory"); free(tab); free(tab1); return; }
    r = mist_tab_init(tab, b3, mu, pv, NT, 3);
    mt_check(r == 0, "phase: the 3-channel table builds (%d)", r);
    for (i = 0; i < NT; ++i) pv[i] = mist_hg_eval(0.5, mu[i]);
    r = mist_tab_init(tab1, b1, mu, pv, NT, 1);
    mt_check(r == 0, "phase: the 1-channel table builds (%d)", r);
    P[0] = mist_phase_hg(0.2); P[1] = mist_phase_draine(0.5, 17); P[2] = mist_phase_rayleigh();
    f.sun.r = 2; f.sun.g = 3; f.sun.b = 4; f.ambient.r = 0.1; f.ambient.g = 0.2; f.ambient.b = 0.3;
    for (i = 0; i < 40; ++i) {
        double an = 0.1 + 0.15 * i, u, pp[3], L[3][3], pt[3], Lt[3], L1t[3], p1;
        mist_vec3 v;
        mist_rgb l;
        int k;
        f.sun_dir.x = cos(an); f.sun_dir.y = sin(an) * 0.6 + 0.2; f.sun_dir.z = 0.3;
        f.sun_dir = mist_normalize(f.sun_dir);
        f.sun_extinction = i & 1;
        d.y = -0.5 + 0.025 * i; d = mist_normalize(d);
        v = d;
        u = f.sun_dir.x * v.x + f.sun_dir.y * v.y + f.sun_dir.z * v.z;
        for (k = 0; k < 3; ++k) {
            f.mie_prepared = &P[k];
            l = mist_hfog_inscatter(&f, o, d, 300);
            L[k][0] = l.r; L[k][1] = l.g; L[k][2] = l.b;
            pp[k] = mist_phase_eval(&P[k], u);
        }
        f.mie_prepared = NULL;
        f.mie_tab = tab;
        l = mist_hfog_inscatter(&f, o, d, 300); Lt[0] = l.r; Lt[1] = l.g; Lt[2] = l.b;
        (void)mist_tab_eval(tab, u, pt);
        f.mie_tab = tab1;
        l = mist_hfog_inscatter(&f, o, d, 300); L1t[0] = l.r; L1t[1] = l.g; L1t[2] = l.b;
        p1 = mist_tab_eval(tab1, u, NULL);
        f.mie_tab = NULL;
        for (c = 0; c < 3; ++c) {
            /* the line through the HG and Rayleigh points */
            double B = (L[2][c] - L[0][c]) / (pp[2] - pp[0]), A = L[0][c] - B * pp[0], e;
            if (fabs(pp[2] - pp[0]) < 0.02) continue;   /* too close to draw a line */
            e = fabs(L[1][c] - (A + B * pp[1])) / L[1][c];
            if (e > worst) worst = e;
            bad += e > 16 * eps * (1 + fabs(B * pp[1] / L[1][c]) * 2 / fabs(pp[2] - pp[0]));
            e = fabs(Lt[c] - (A + B * pt[c])) / Lt[c];
            if (e > worst) worst = e;
            bad += e > 16 * eps * (1 + fabs(B * pt[c] / Lt[c]) * 2 / fabs(pp[2] - pp[0]));
            e = fabs(L1t[c] - (A + B * p1)) / L1t[c];
            bad += e > 16 * eps * (1 + fabs(B * p1 / L1t[c]) * 2 / fabs(pp[2] - pp[0]));
        }
        {   /* mie_prepared = the fog's own mix: as mie_phase */
            mist_phase pf = mist_phase_fog(f.mie_phase);
            mist_rgb a = mist_hfog_inscatter(&f, o, d, 300), b;
            f.mie_prepared = &pf;
            b = mist_hfog_inscatter(&f, o, d, 300);
            f.mie_prepared = NULL;
            bad += fabs(a.r - b.r) > 16 * eps * a.r || fabs(a.g - b.g) > 16 * eps * a.g
                || fabs(a.b - b.b) > 16 * eps * a.b;
        }
    }
    /* control: channel 2's in-scatter against the line at channel 0's
     * phase value (a table read at the wrong channel) must miss it */
    {
        mist_hfog g = f;
        double u, pp0, pp2, Lc, Lr, B, A, pt[3];
        mist_rgb l;
        mist_phase P0 = mist_phase_hg(0.2);
        g.sun_dir.x = 0.8; g.sun_dir.y = 0.3; g.sun_dir.z = 0.1; g.sun_dir = mist_normalize(g.sun_dir);
        u = g.sun_dir.x * d.x + g.sun_dir.y * d.y + g.sun_dir.z * d.z;
        g.mie_prepared = &P0; l = mist_hfog_inscatter(&g, o, d, 300); Lc = l.b; pp0 = mist_phase_eval(&P0, u);
        g.mie_prepared = &P[2]; l = mist_hfog_inscatter(&g, o, d, 300); Lr = l.b; pp2 = mist_phase_eval(&P[2], u);
        B = (Lr - Lc) / (pp2 - pp0); A = Lc - B * pp0;
        g.mie_prepared = NULL; g.mie_tab = tab;
        l = mist_hfog_inscatter(&g, o, d, 300);
        (void)mist_tab_eval(tab, u, pt);
        mt_check(fabs(l.b - (A + B * pt[0])) > 1e3 * eps * l.b,
                 "phase control: channel 2 (HG .8) taken for channel 0's (HG .2) was not told apart");
    }
    {   /* the layers: per layer, mie_prepared as the fog's own mix */
        mist_hfog ly[2];
        mist_phase pf;
        mist_rgb t1, l1, b1, t2, l2, b2;
        ly[0] = f; ly[1] = fog_make(100, 0.5, 1000, 2e-5, 1e-4);
        ly[1].mie_phase = mist_fog_make(0.7, 0.3, 2, 0.3);
        mist_hfog_layers_eval(ly, 2, o, d, 500, 8, &t1, &l1, &b1);
        pf = mist_phase_fog(ly[1].mie_phase);
        ly[1].mie_prepared = &pf;
        mist_hfog_layers_eval(ly, 2, o, d, 500, 8, &t2, &l2, &b2);
        bad += t1.r != t2.r || t1.g != t2.g || t1.b != t2.b;
        bad += fabs(l1.r - l2.r) > 16 * eps * l1.r + b1.r || fabs(l1.b - l2.b) > 16 * eps * l1.b + b1.b;
    }
    free(tab); free(tab1);
    printf("phase: in-scatter linear in the Mie phase value, worst %.3g eps off the line\n", worst / eps);
    mt_check(bad == 0, "phase: %d in-scatter values off the line (16 eps)", bad);
}

/* ------------------------------------------------------------------------ */
/* The height axis along z: the same results as y                          */
/* ------------------------------------------------------------------------ */

/* A scene with y and z swapped and up = (0, 0, 1) (or (0, 0, 7): it is
 * normalised) gives the same transmittance, depth and distances bit for
 * bit (the dot products are exact, the direction unit as given), and the
 * same in-scatter without the sun (with it, the cosine u sums its terms
 * in another order: within the phase function's change over 4 eps of u). */
static void test_zup(void)
{
    mt_rng rng;
    int i, bad = 0, badl = 0;
    rng.s = 77;
    for (i = 0; i < 3000; ++i) {
        mist_hfog f = fog_make(20 * mt_uniform(&rng), 1, pow(10, 4 * mt_uniform(&rng) - 1), 1e-4, 1e-3), g;
        mist_vec3 o, d, oz, dz;
        mist_rgb t1, t2, l1, l2, a1, a2;
        double s = mt_uniform(&rng) < 0.2 ? INFINITY : 2000 * mt_uniform(&rng), xi = mt_uniform(&rng);
        double w = (mt_uniform(&rng) - 0.5) * (mt_uniform(&rng) < 0.3 ? 1e-8 : 2), hz = sqrt(1 - w * w);
        double u, du, p0, pa, pb;
        o.x = 100 * mt_uniform(&rng); o.y = 300 * mt_uniform(&rng) - 50; o.z = 100 * mt_uniform(&rng);
        d.x = hz * cos(3.0 * i); d.y = w; d.z = hz * sin(3.0 * i);
        f.sun_dir.x = 0.3; f.sun_dir.y = 0.8; f.sun_dir.z = 0.52; f.sun_dir = mist_normalize(f.sun_dir);
        f.ambient.r = f.ambient.g = f.ambient.b = 0.3;
        f.sun_extinction = i & 1;
        g = f;
        g.up.x = 0; g.up.y = 0; g.up.z = (i & 2) ? 7 : 1;
        g.sun_dir.y = f.sun_dir.z; g.sun_dir.z = f.sun_dir.y;
        oz = o; oz.y = o.z; oz.z = o.y;
        dz = d; dz.y = d.z; dz.z = d.y;
        f.sun.r = f.sun.g = f.sun.b = 0; g.sun = f.sun;
        mist_hfog_eval(&f, o, d, s, &t1, &l1);
        mist_hfog_eval(&g, oz, dz, s, &t2, &l2);
        bad += memcmp(&t1, &t2, sizeof t1) != 0 || memcmp(&l1, &l2, sizeof l1) != 0;
        a1 = mist_hfog_optical_depth(&f, o, d, s); a2 = mist_hfog_optical_depth(&g, oz, dz, s);
        bad += memcmp(&a1, &a2, sizeof a1) != 0;
        a1 = mist_hfog_extinction(&f, o); a2 = mist_hfog_extinction(&g, oz);
        bad += memcmp(&a1, &a2, sizeof a1) != 0;
        bad += mist_hfog_sample_distance(&f, o, d, s, i % 3, xi) != mist_hfog_sample_distance(&g, oz, dz, s, i % 3, xi);
        /* with the sun */
        f.sun.r = f.sun.g = f.sun.b = 3; g.sun = f.sun;
        l1 = mist_hfog_inscatter(&f, o, d, s); l2 = mist_hfog_inscatter(&g, oz, dz, s);
        u = f.sun_dir.x * d.x + f.sun_dir.y * d.y + f.sun_dir.z * d.z;
        du = 4 * 0x1p-53;
        p0 = mist_fog_eval(f.mie_phase, u);
        pa = mist_fog_eval(f.mie_phase, u + du); pb = mist_fog_eval(f.mie_phase, u - du);
        pa = fabs(pa - p0) > fabs(pb - p0) ? fabs(pa - p0) : fabs(pb - p0);
        badl += fabs(l1.g - l2.g) > l1.g * (pa / p0 + 4 * 0x1p-53);
    }
    mt_check(bad == 0, "up (0, 0, 1): %d of 3000 scenes not the same bit for bit as y", bad);
    mt_check(badl == 0, "up (0, 0, 1) with the sun: %d of 3000 in-scatters beyond the phase's change", badl);
    printf("up along z: 3000 scenes, %d differ from y (bits), %d with the sun beyond the bound\n", bad, badl);
}

/* ------------------------------------------------------------------------ */
/* Path tracing the single-scattered in-scatter                            */
/* ------------------------------------------------------------------------ */

/* The in-scatter of mist_hfog_inscatter estimated by tracing: a distance
 * t from mist_hfog_sample_distance (density sigma_t T along the ray, none
 * beyond the length), the albedo sigma_s / sigma_t from
 * mist_hfog_extinction (of the fog, and of the fog with its extinctions
 * set to its scatterings), the sun by next-event estimation through the
 * phase functions (mist_rayleigh_eval, the Mie one: mist_fog_eval or the
 * prepared mist_phase_eval) dimmed by exp(-mist_hfog_optical_depth) to
 * infinity along the sun where the fog dims it, and the ambient through a
 * direction sampled from the phase function (mist_phase_sample_dir: its
 * weight p / pdf is 1).  The estimate agrees within 4.5 standard errors
 * (two-sided 7e-6 per case: Sidak over the cases at 1e-4); the controls
 * (the Mie phase at -u; the sun undimmed where the fog dims it) must be
 * off by more than that. */
typedef struct { double mean, se; } pt_est;
static pt_est pt_run(const mist_hfog *f, mist_vec3 o, mist_vec3 d, double s, int c, long n,
                     mt_rng *rng, int control)
{
    mist_hfog fs = *f;
    mist_phase pr = mist_phase_rayleigh(), pm = f->mie_prepared ? *f->mie_prepared : mist_phase_fog(f->mie_phase);
    mist_vec3 l = mist_normalize(f->sun_dir), dn = mist_normalize(d);
    double sum = 0, sum2 = 0, u = l.x * dn.x + l.y * dn.y + l.z * dn.z;
    double E = c == 0 ? f->sun.r : c == 1 ? f->sun.g : f->sun.b;
    double La = c == 0 ? f->ambient.r : c == 1 ? f->ambient.g : f->ambient.b;
    double sR = c == 0 ? f->rayleigh_scat.r : c == 1 ? f->rayleigh_scat.g : f->rayleigh_scat.b;
    double sM = c == 0 ? f->mie_scat.r : c == 1 ? f->mie_scat.g : f->mie_scat.b;
    double pR = mist_rayleigh_eval(u), pM = mist_phase_eval(&pm, control == 1 ? -u : u);
    long i;
    pt_est r;
    fs.rayleigh_ext = fs.rayleigh_scat; fs.mie_ext = fs.mie_scat;
    for (i = 0; i < n; ++i) {
        double t = mist_hfog_sample_distance(f, o, d, s, c, mt_uniform(rng)), v = 0;
        if (t < INFINITY) {
            mist_vec3 x = { o.x + t * dn.x, o.y + t * dn.y, o.z + t * dn.z }, wo;
            mist_rgb et = mist_hfog_extinction(f, x), es = mist_hfog_extinction(&fs, x);
            double st = c == 0 ? et.r : c == 1 ? et.g : et.b, ss = c == 0 ? es.r : c == 1 ? es.g : es.b;
            double Ts = 1, pdf, rho = ss / (sR + sM), wgt;
            if (f->sun_extinction && control != 2) {
                mist_rgb a = mist_hfog_optical_depth(f, x, l, INFINITY);
                Ts = exp(-(c == 0 ? a.r : c == 1 ? a.g : a.b));
            }
            /* the ambient: one direction from the phase function chosen
             * by the scatterings (Rayleigh or Mie), weight p / pdf */
            {
                const mist_phase *ph = mt_uniform(rng) * (sR + sM) < sR ? &pr : &pm;
                double x1 = mt_uniform(rng), x2 = mt_uniform(rng);
                wo = mist_phase_sample_dir(ph, dn, x1, x2, &pdf);
                wgt = mist_phase_eval(ph, wo.x * dn.x + wo.y * dn.y + wo.z * dn.z) / pdf;
            }
            v = (rho * (sR * pR + sM * pM) * E * Ts + ss * La * wgt) / st;
        }
        sum += v; sum2 += v * v;
    }
    r.mean = sum / n;
    r.se = sqrt((sum2 / n - r.mean * r.mean) / (n - 1));
    return r;
}
static void test_pt(void)
{
    /* rays: down, up to infinity, nearly level; the sun dimmed or not;
     * the Mie phase the fog's mix or a prepared HG */
    const double ys[] = { 150, -20, 60 }, ws[] = { -0.4, 0.3, 0.02 }, ss[] = { 600, INFINITY, 3000 };
    long n = mt_scale(100000, 20000);
    mt_rng rng;
    int k, dim, prep, c, bad = 0, cases = 0;
    double worst = 0, z = 4.5;
    mist_phase hg = mist_phase_hg(0.7);
    rng.s = 31337;
    for (k = 0; k < 3; ++k)
        for (dim = 0; dim < 2; ++dim)
            for (prep = 0; prep < 2; ++prep) {
                mist_hfog f = fog_make(0, 1, 120, 3e-4, 2e-3);
                mist_vec3 o = { 0, ys[k], 0 }, d = { sqrt(1 - ws[k] * ws[k]), ws[k], 0 };
                mist_rgb L;
                f.sun_dir.x = 0.5; f.sun_dir.y = 0.4; f.sun_dir.z = 0.2;
                f.sun.r = 2; f.sun.g = 3; f.sun.b = 4;
                f.ambient.r = 0.3; f.ambient.g = 0.2; f.ambient.b = 0.1;
                f.sun_extinction = dim;
                if (prep) f.mie_prepared = &hg;
                L = mist_hfog_inscatter(&f, o, d, ss[k]);
                for (c = 0; c < 3; c += 2) {
                    double ref = c == 0 ? L.r : L.b, e;
                    pt_est p = pt_run(&f, o, d, ss[k], c, n, &rng, 0), q;
                    e = fabs(p.mean - ref) / p.se;
                    if (e > worst) worst = e;
                    bad += e > z;
                    ++cases;
                    if (k == 0 && c == 0) {      /* the controls */
                        q = pt_run(&f, o, d, ss[k], c, n, &rng, 1);
                        mt_check(fabs(q.mean - ref) / q.se > z, "pt control (Mie phase at -u) not "
                                 "rejected: %.2f standard errors", fabs(q.mean - ref) / q.se);
                        if (dim) {
                            q = pt_run(&f, o, d, ss[k], c, n, &rng, 2);
                            mt_check(fabs(q.mean - ref) / q.se > z, "pt control (sun undimmed) not "
                                     "rejected: %.2f standard errors", fabs(q.mean - ref) / q.se);
                        }
                    }
                }
            }
    printf("path traced in-scatter: %d cases of %ld paths, worst %.2f standard errors from "
           "mist_hfog_inscatter\n", cases, n, worst);
    mt_check(bad == 0, "pt: %d of %d cases beyond %.1f standard errors", bad, cases, z);
}

/* The float ln(1 + x) the float distances use (mist__log1pf: in double)
 * against log1pl, over x from -1 + 2^-24 to 2^100 of every binade and
 * the series' edge 2^-10: within 0.5 ulp of float plus 2^-40 relative
 * (its derivation, mist.h).  Control: a result 2^-22 off must fail. */
static void test_log1pf(void)
{
    mt_rng rng;
    long i, n = 200000, bad = 0, ctl = 0, nctl = 0;
    double worst = 0;
    rng.s = 4711;
    for (i = 0; i < n; ++i) {
        float x;
        LD ref, ulp;
        int e;
        if (i < 1000) x = nextafterf(i & 1 ? -0.0009765625f : 0.0009765625f, (i & 2) ? 1.f : -1.f) ;
        else if (i & 1) x = (float)-ldexp(1 + mt_uniform(&rng), -(int)(mt_uniform(&rng) * 140) - 1);
        else x = (float)ldexp(1 + mt_uniform(&rng), (int)(mt_uniform(&rng) * 240) - 140);
        if (!(x > -1)) continue;
        ref = log1pl((LD)x);
        (void)frexpl(ref, &e);
        ulp = ldexpl(1, (e - 24 > -149) ? e - 24 : -149);
        {
            LD err = fabsld((LD)mist__log1pf(x) - ref) / ulp;
            LD lim = 0.5L + fabsld(ref) * 0x1p-40L / ulp;
            if (err - (lim - 0.5L) > worst) worst = (double)(err - (lim - 0.5L));
            bad += err > lim;
            if (fabsld(ref) >= FLT_MIN) {       /* (subnormal results: too coarse) */
                ++nctl;
                ctl += fabsld((LD)(mist__log1pf(x) * (1 + 0x1p-22f)) - ref) / ulp > lim;
            }
        }
    }
    printf("float log1p: worst %.4f ulp over %ld arguments\n", worst, n);
    mt_check(bad == 0, "float log1p: %ld beyond 0.5 ulp + 2^-40", bad);
    mt_check(ctl == nctl, "float log1p control: a result 2^-22 off passed %ld of %ld times", nctl - ctl, nctl);
}

/* Wild input, double and float: every field of the fog, the ray, the axis,
 * tmax and xi from edge values (+-0, subnormals, 1, huge, +-inf, NaN) or
 * raw bit patterns.  Invariants: no NaN anywhere; a distance in [0, tmax]
 * or +inf, non-decreasing over eight sorted xi; depths and extinctions
 * >= 0. */
static double wild_d(mt_rng *r)
{
    static const double e[] = { 0, -0.0, 0x1p-1074, -0x1p-1074, 0x1p-1022, 1, -1, 0.5, 1e-300,
                                1e300, -1e300, DBL_MAX, -DBL_MAX, INFINITY, -INFINITY, NAN, 3, 100 };
    uint64_t b = mt_next(r);
    double x;
    if (b % 3 == 0) return e[(b >> 8) % (sizeof e / sizeof *e)];
    if (b % 3 == 1) { b = mt_next(r); memcpy(&x, &b, sizeof x); return x; }
    return ldexp(mt_uniform(r) - 0.5, (int)((b >> 8) % 200) - 100);
}
#define WILD_CHECK(T, S, HF, V3, RGB)                                                      \
static long wild_##S(long n)                                                               \
{                                                                                          \
    mt_rng r;                                                                              \
    long i, bad = 0;                                                                       \
    r.s = 2718 + sizeof(T);                                                                \
    for (i = 0; i < n; ++i) {                                                              \
        HF f;                                                                              \
        V3 o, d, p;                                                                        \
        T tmax, xs[8], prev = 0;                                                           \
        RGB a, e;                                                                          \
        int k, c = (int)(mt_next(&r) % 5) - 1;                                             \
        memset(&f, 0, sizeof f);                                                           \
        f.base = (T)wild_d(&r); f.density = (T)wild_d(&r); f.scale_height = (T)wild_d(&r);   \
        f.rayleigh_scat.r = (T)wild_d(&r); f.rayleigh_scat.g = (T)wild_d(&r);               \
        f.rayleigh_ext.g = (T)wild_d(&r); f.mie_scat.b = (T)wild_d(&r);                     \
        f.mie_ext.r = (T)wild_d(&r); f.mie_ext.g = (T)wild_d(&r); f.mie_ext.b = (T)wild_d(&r); \
        if (mt_next(&r) % 2) { f.up.x = (T)wild_d(&r); f.up.y = (T)wild_d(&r); f.up.z = (T)wild_d(&r); } \
        o.x = (T)wild_d(&r); o.y = (T)wild_d(&r); o.z = (T)wild_d(&r);                     \
        d.x = (T)wild_d(&r); d.y = (T)wild_d(&r); d.z = (T)wild_d(&r);                     \
        tmax = (T)wild_d(&r);                                                              \
        for (k = 0; k < 8; ++k) xs[k] = (T)(k == 0 ? wild_d(&r) : mt_uniform(&r));         \
        for (k = 2; k < 8; ++k) {    /* sorted (from the second: the first is wild) */    \
            int j = k;                                                                     \
            while (j > 1 && xs[j - 1] > xs[j]) { T t_ = xs[j]; xs[j] = xs[j - 1]; xs[j - 1] = t_; --j; } \
        }                                                                                  \
        for (k = 0; k < 8; ++k) {                                                          \
            T t = mist_hfog_sample_distance##S(&f, o, d, tmax, c, xs[k]);                   \
            bad += t != t || t < 0 || (t != (T)INFINITY && !(t <= tmax));                  \
            if (k > 1) bad += !(t >= prev);                                                \
            prev = t;                                                                      \
        }                                                                                  \
        a = mist_hfog_optical_depth##S(&f, o, d, tmax);                                     \
        p = o; p.y = (T)wild_d(&r);                                                        \
        e = mist_hfog_extinction##S(&f, p);                                                \
        bad += !(a.r >= 0) || !(a.g >= 0) || !(a.b >= 0) || !(e.r >= 0) || !(e.g >= 0) || !(e.b >= 0); \
    }                                                                                      \
    return bad;                                                                            \
}
WILD_CHECK(double, , mist_hfog, mist_vec3, mist_rgb)
WILD_CHECK(float, f, mist_hfogf, mist_vec3f, mist_rgbf)
static void test_wild(void)
{
    long n = mt_scale(200000, 20000), bd = wild_(n), bf = wild_f(n);
    printf("wild input: %ld fogs and rays a type, %ld (double) and %ld (float) broken invariants\n",
           n, bd, bf);
    mt_check(bd == 0 && bf == 0, "wild input: %ld and %ld broken invariants", bd, bf);
}

int main(int argc, char **argv)
{
    int k;
    (void)argc; (void)argv;
    test_exact(0);
    test_exact(1);
    for (k = 0; k < 6; ++k) test_random(k & 1, k >> 1, mt_scale(20000, 2000));
    test_monotone();
    test_chi2();
    for (k = 0; k < 4; ++k) test_depth(k & 1, k >> 1, mt_scale(20000, 2000));
    test_bad();
    test_phase();
    test_zup();
    test_pt();
    test_log1pf();
    test_wild();
    return mt_done("test_hfog_path");
}
