/* test_domain.c - the documented domain and bad input of every function
 * (the "DOMAIN AND BAD INPUT" block at the top of include/mist.h), in
 * double and float:
 *   g: NaN -> 0, |g| > 1 clamped, |g| = 1 the Dirac limit;
 *   alpha: NaN and < 0 -> 0, +inf the exact limit;
 *   u: clamped to [-1, 1], NaN -> density 0;
 *   xi: clamped to [0, 1], NaN -> 0;
 *   directions: normalised; zero, NaN, infinite -> (0, 0, 1);
 *   fog: parameters sanitised.
 * And: finite input never gives NaN (|g| < 1: always finite), over the
 * edges of every domain (+-0, subnormals, one ulp inside and outside the
 * bounds, huge values). */
#include "mist.h"
#include "mist_test.h"

#include <float.h>

static void test_g(void)
{
    static const double us[] = { -1, -0.3, 0, 0.7, 1 };
    static const double xs[] = { 0, 0.2, 0.5, 0.9, 1 };
    size_t i;
    for (i = 0; i < 5; ++i) {
        double u = us[i], x = xs[i];
        float uf = (float)u, xf = (float)x;
        /* NaN g is g = 0 */
        mt_check(mist_hg_eval(NAN, u) == mist_hg_eval(0, u) &&
                 mist_hg_evalf(NAN, uf) == mist_hg_evalf(0, uf), "hg_eval(NaN g) = g 0");
        mt_check(mist_hg_sample(NAN, x) == mist_hg_sample(0, x) &&
                 mist_hg_samplef(NAN, xf) == mist_hg_samplef(0, xf), "hg_sample(NaN g)");
        mt_check(mist_draine_eval(NAN, 3, u) == mist_draine_eval(0, 3, u) &&
                 mist_draine_sample(NAN, 3, x) == mist_draine_sample(0, 3, x) &&
                 mist_draine_samplef(NAN, 3, xf) == mist_draine_samplef(0, 3, xf),
                 "draine NaN g");
        mt_check(mist_cs_eval(NAN, u) == mist_cs_eval(0, u) &&
                 mist_cs_sample(NAN, x) == mist_cs_sample(0, x), "cs NaN g");
        /* |g| > 1 is clamped to +-1 */
        mt_check(mist_hg_eval(1.5, u) == mist_hg_eval(1, u) &&
                 mist_hg_eval(-7, u) == mist_hg_eval(-1, u) &&
                 mist_hg_evalf(INFINITY, uf) == mist_hg_evalf(1, uf), "hg_eval |g| > 1");
        mt_check(mist_hg_sample(1.5, x) == 1 && mist_hg_sample(-INFINITY, x) == -1 &&
                 mist_draine_sample(2, 5, x) == 1 && mist_draine_samplef(-2, 5, xf) == -1 &&
                 mist_cs_samplef(3, xf) == 1, "sample |g| > 1");
        /* |g| = 1: the Dirac limit, 0 off the peak, +inf on it */
        mt_check(mist_hg_eval(1, u) == (u == 1 ? INFINITY : 0) &&
                 mist_hg_eval(-1, u) == (u == -1 ? INFINITY : 0) &&
                 mist_draine_evalf(1, 2, uf) == (uf == 1 ? INFINITY : 0) &&
                 mist_cs_eval(-1, u) == (u == -1 ? INFINITY : 0),
                 "|g| = 1 density at u=%g", u);
    }
}

static void test_alpha(void)
{
    int k;
    for (k = 0; k <= 10; ++k) {
        double u = -1 + 0.2 * k, x = 0.1 * k;
        float uf = (float)u, xf = (float)x;
        mt_check(mist_draine_eval(0.4, -3, u) == mist_draine_eval(0.4, 0, u) &&
                 mist_draine_eval(0.4, NAN, u) == mist_draine_eval(0.4, 0, u) &&
                 mist_draine_evalf(0.4f, -INFINITY, uf) == mist_draine_evalf(0.4f, 0, uf),
                 "alpha < 0 and NaN are alpha = 0 (eval, u=%g)", u);
        mt_check(mist_draine_sample(0.4, -3, x) == mist_draine_sample(0.4, 0, x) &&
                 mist_draine_sample(0.4, NAN, x) == mist_draine_sample(0.4, 0, x) &&
                 mist_draine_samplef(0.4f, NAN, xf) == mist_draine_samplef(0.4f, 0, xf),
                 "alpha < 0 and NaN are alpha = 0 (sample, xi=%g)", x);
        /* alpha = 0 is exactly HG */
        mt_check(mist_draine_sample(-0.6, 0, x) == mist_hg_sample(-0.6, x) &&
                 mist_draine_eval(-0.6, 0, u) == mist_hg_eval(-0.6, u), "alpha 0 is HG");
        /* alpha = +inf: the limit HG u^2 / E[u^2], finite, and the limit of
         * large alpha (relative difference ~ 1/alpha: 1e-12 at alpha 1e15) */
        {
            double di = mist_draine_eval(0.4, INFINITY, u);
            double dl = mist_draine_eval(0.4, 1e15, u);
            double want = mist_hg_eval(0.4, u) * u * u / ((1 + 2 * 0.16) / 3);
            mt_check(isfinite(di) && fabs(di - dl) <= 1e-12 * mist_hg_eval(0.4, u) &&
                     fabs(di - want) <= 1e-14 * want,
                     "alpha inf density at u=%g: %g vs %g", u, di, want);
            mt_check(isfinite(mist_draine_sample(0.4, INFINITY, x)) &&
                     fabs(mist_draine_sample(0.4, INFINITY, x) - mist_draine_sample(0.4, 1e15, x))
                     <= 1e-9, "alpha inf sample at xi=%g", x);
        }
    }
}

static void test_u_xi(void)
{
    /* u outside [-1, 1] is clamped; NaN u has density 0 */
    mt_check(mist_hg_eval(0.5, 1.0000001) == mist_hg_eval(0.5, 1) &&
             mist_hg_eval(0.5, -5) == mist_hg_eval(0.5, -1) &&
             mist_draine_eval(0.5, 2, INFINITY) == mist_draine_eval(0.5, 2, 1) &&
             mist_rayleigh_eval(-3) == mist_rayleigh_eval(-1) &&
             mist_hg_evalf(0.5f, 1.5f) == mist_hg_evalf(0.5f, 1), "u clamped");
    mt_check(mist_hg_eval(0.5, NAN) == 0 && mist_draine_eval(0.5, 2, NAN) == 0 &&
             mist_cs_evalf(0.5f, NAN) == 0 && mist_rayleigh_eval(NAN) == 0 &&
             mist_rayleigh_evalf(NAN) == 0, "NaN u: density 0");
    /* xi outside [0, 1] is clamped; NaN xi is 0 */
    mt_check(mist_hg_sample(0.5, -0.1) == mist_hg_sample(0.5, 0) &&
             mist_hg_sample(0.5, 1.5) == mist_hg_sample(0.5, 1) &&
             mist_hg_sample(0.5, NAN) == mist_hg_sample(0.5, 0) &&
             mist_draine_sample(0.5, 9, -INFINITY) == mist_draine_sample(0.5, 9, 0) &&
             mist_draine_sample(0.5, 9, NAN) == mist_draine_sample(0.5, 9, 0) &&
             mist_rayleigh_sample(2) == mist_rayleigh_sample(1) &&
             mist_rayleigh_samplef(NAN) == mist_rayleigh_samplef(0) &&
             mist_cs_samplef(0.5f, 7.f) == mist_cs_samplef(0.5f, 1), "xi clamped");
    /* the ends of [0, 1] give the ends of [-1, 1] */
    mt_check(mist_hg_sample(0.3, 0) == -1 && mist_hg_sample(0.3, 1) == 1 &&
             mist_draine_sample(-0.3, 250, 0) == -1 && mist_draine_sample(-0.3, 250, 1) == 1 &&
             mist_rayleigh_sample(0) == -1 && mist_rayleigh_sample(1) == 1 &&
             mist_draine_samplef(0.9f, 17, 0) == -1 && mist_draine_samplef(0.9f, 17, 1) == 1,
             "xi = 0 and 1 give u = -1 and 1");
}

static double len3(mist_vec3 v) { return sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }

static void test_directions(void)
{
    mist_vec3 z = { 0, 0, 1 }, bad[6], v, w;
    mist_vec3f zf = { 0, 0, 1 }, vf, wf;
    double pdf1, pdf2;
    float pf1, pf2;
    int i;
    bad[0].x = 0; bad[0].y = 0; bad[0].z = 0;
    bad[1].x = NAN; bad[1].y = 0; bad[1].z = 1;
    bad[2].x = INFINITY; bad[2].y = 0; bad[2].z = 0;
    bad[3].x = -0.0; bad[3].y = 0; bad[3].z = -0.0;
    bad[4].x = 1; bad[4].y = NAN; bad[4].z = NAN;
    bad[5].x = -INFINITY; bad[5].y = INFINITY; bad[5].z = 1;
    for (i = 0; i < 6; ++i) {
        v = mist_hg_sample_dir(0.7, bad[i], 0.3, 0.6, &pdf1);
        w = mist_hg_sample_dir(0.7, z, 0.3, 0.6, &pdf2);
        mt_check(v.x == w.x && v.y == w.y && v.z == w.z && pdf1 == pdf2,
                 "bad direction %d is (0, 0, 1)", i);
        vf.x = (float)bad[i].x; vf.y = (float)bad[i].y; vf.z = (float)bad[i].z;
        vf = mist_draine_sample_dirf(0.7f, 3, vf, 0.3f, 0.6f, &pf1);
        wf = mist_draine_sample_dirf(0.7f, 3, zf, 0.3f, 0.6f, &pf2);
        mt_check(vf.x == wf.x && vf.y == wf.y && vf.z == wf.z && pf1 == pf2,
                 "bad float direction %d is (0, 0, 1)", i);
    }
    /* non-unit directions are normalised: tiny, huge and subnormal lengths
     * give the direction of the unit vector, to 8 eps (scaling by the
     * largest component, one sqrt, three products) */
    {
        static const double scales[] = { 1e-300, 1e-30, 3, 1e30, 1e300 };
        mist_vec3 u = { 0.48, -0.6, 0.64 }, s, a, b;
        size_t k;
        a = mist_rayleigh_sample_dir(u, 0.8, 0.1, &pdf1);
        for (k = 0; k < sizeof scales / sizeof *scales; ++k) {
            s.x = u.x * scales[k]; s.y = u.y * scales[k]; s.z = u.z * scales[k];
            b = mist_rayleigh_sample_dir(s, 0.8, 0.1, &pdf2);
            mt_check(fabs(a.x - b.x) + fabs(a.y - b.y) + fabs(a.z - b.z) <= 8 * DBL_EPSILON &&
                     fabs(len3(b) - 1) <= 4 * DBL_EPSILON,
                     "direction scaled by %g is normalised", scales[k]);
        }
    }
    /* subnormal components carry fewer bits, but still give a unit vector */
    {
        mist_vec3 s = { 4.9406564584124654e-324, -1e-310, 3e-311 };
        v = mist_hg_sample_dir(0.3, s, 0.4, 0.2, &pdf1);
        mt_check(fabs(len3(v) - 1) <= 4 * DBL_EPSILON && fabs(len3(mist_normalize(s)) - 1)
                 <= 4 * DBL_EPSILON, "subnormal direction gives a unit vector");
    }
    /* pdf may be NULL */
    v = mist_cs_sample_dir(0.2, z, 0.5, 0.5, NULL);
    mt_check(fabs(len3(v) - 1) < 4 * DBL_EPSILON, "NULL pdf accepted");
    /* |g| = 1: the direction is exactly +-wi and the pdf is +inf */
    v = mist_hg_sample_dir(1, z, 0.3, 0.9, &pdf1);
    w = mist_hg_sample_dir(-1, z, 0.3, 0.9, &pdf2);
    mt_check(v.z == 1 && fabs(v.x) + fabs(v.y) == 0 && w.z == -1 && pdf1 == INFINITY &&
             pdf2 == INFINITY, "|g| = 1 direction is +-wi with pdf +inf");
}

/* mist_normalize(f) over the whole range of finite vectors: components of
 * random sign and exponent (float: 2^-149..2^127, double: 2^-1074..2^1023,
 * each component 1 in 8 times zero), against v/|v| in long double (64-bit
 * significand; where long double is no wider the test still runs, with a
 * reference good to a few eps).  Bars: float 1 ulp of 1 per component (one
 * rounding of a double result), double 4 eps (the power-of-2 scaling is
 * exact; then |v|^2, sqrt, 1/x and a product: 3 roundings of ~1/2 eps and
 * the sum's).  Control: the bare formula (no scaling, in T)
 * over the same vectors must fail (overflow and underflow of |v|^2). */
/* The direction's sine near u = +-1: the part of mist_dir_from_cos(n, u,
 * xi) across n has length sin theta = sqrt((1 - u)(1 + u)), which 1 - u^2
 * would lose where u is within a few ulps of +-1 (a mutation audit: with
 * sqrt(1 - u u), 3.6e-5 off at float u = 1 - 3 2^-14, and no test saw it).
 * n along each axis, so the across part is two components exactly; u =
 * +-(1 - k ulp), k = 1..300; against sqrt((1 - u)(1 + u)) in long double:
 * within 4 eps (the sine's rounding and the azimuth's cos, sin). */
static void test_dir_sine(void)
{
    static const double ax[6][3] = { { 0, 0, 1 }, { 0, 0, -1 }, { 1, 0, 0 }, { 0, -1, 0 },
                                     { -1, 0, 0 }, { 0, 1, 0 } };
    double worst = 0, worstf = 0;
    int a, k, sg;
    for (a = 0; a < 6; ++a)
        for (sg = -1; sg <= 1; sg += 2)
            for (k = 1; k <= 300; ++k) {
                mist_vec3 n = { ax[a][0], ax[a][1], ax[a][2] }, o;
                mist_vec3f nf = { (float)ax[a][0], (float)ax[a][1], (float)ax[a][2] }, of;
                double u = sg * (1 - k * 0x1p-53), s1, s2, e;
                float uf = (float)sg * (1 - (float)k * 0x1p-24f);
                long double r;
                o = mist_dir_from_cos(n, u, 0.3 + k * 1e-3);
                of = mist_dir_from_cosf(nf, uf, 0.3f + (float)k * 1e-3f);
                s1 = ax[a][0] != 0 ? o.y : o.x;
                s2 = ax[a][2] != 0 ? o.y : o.z;
                r = sqrtl((1 - (long double)u) * (1 + (long double)u));
                e = (double)(fabsl(sqrtl((long double)s1 * s1 + (long double)s2 * s2) - r) / r);
                if (e > worst) worst = e;
                s1 = ax[a][0] != 0 ? of.y : of.x;
                s2 = ax[a][2] != 0 ? of.y : of.z;
                r = sqrtl((1 - (long double)uf) * (1 + (long double)uf));
                e = (double)(fabsl(sqrtl((long double)s1 * s1 + (long double)s2 * s2) - r) / r);
                if (e > worstf) worstf = e;
            }
    mt_check(worst <= 4 * DBL_EPSILON && worstf <= 4 * FLT_EPSILON,
             "direction's sine near u = +-1: worst %.2f eps (double), %.2f eps (float)",
             worst / DBL_EPSILON, worstf / FLT_EPSILON);
}

static void test_normalize(void)
{
    mt_rng r = { 909 };
    long n = mt_scale(200000, 20000), i, badf = 0, badd = 0, ctlf = 0, ctld = 0;
    double worstf = 0, worstd = 0;
    for (i = 0; i < n; ++i) {
        long double c[3], l2 = 0, cf[3], lf2 = 0;
        mist_vec3 v, o; mist_vec3f vf, of;
        int k;
        float bf; double bd, ef = 0, ed = 0, e;
        for (k = 0; k < 3; ++k) {
            double m = 1 + mt_uniform(&r);
            int z = mt_next(&r) % 8 == 0, sg = mt_next(&r) % 2 ? -1 : 1;
            double x = z ? 0 : sg * ldexp(m, (int)(mt_next(&r) % 2098) - 1075);
            float xf = z ? 0 : (float)(sg * ldexp(m, (int)(mt_next(&r) % 278) - 150));
            c[k] = x; cf[k] = xf;
        }
        v.x = (double)c[0]; v.y = (double)c[1]; v.z = (double)c[2];
        vf.x = (float)cf[0]; vf.y = (float)cf[1]; vf.z = (float)cf[2];
        c[0] = v.x; c[1] = v.y; c[2] = v.z;                /* (what was passed) */
        cf[0] = vf.x; cf[1] = vf.y; cf[2] = vf.z;
        {   /* |v| in long double, scaled by a power of 2 */
            long double mx = fabsl(c[0]) > fabsl(c[1]) ? fabsl(c[0]) : fabsl(c[1]);
            long double mf = fabsl(cf[0]) > fabsl(cf[1]) ? fabsl(cf[0]) : fabsl(cf[1]);
            int ex, exf;
            mx = mx > fabsl(c[2]) ? mx : fabsl(c[2]);
            mf = mf > fabsl(cf[2]) ? mf : fabsl(cf[2]);
            if (mx == 0 || mf == 0) continue;
            frexpl(mx, &ex); frexpl(mf, &exf);
            for (k = 0; k < 3; ++k) {
                c[k] = ldexpl(c[k], -ex); cf[k] = ldexpl(cf[k], -exf);
                l2 += c[k] * c[k]; lf2 += cf[k] * cf[k];
            }
            l2 = sqrtl(l2); lf2 = sqrtl(lf2);
        }
        o = mist_normalize(v); of = mist_normalizef(vf);
        ed = fabs((double)(o.x - c[0] / l2));
        e = fabs((double)(o.y - c[1] / l2)); ed = e > ed ? e : ed;
        e = fabs((double)(o.z - c[2] / l2)); ed = e > ed ? e : ed;
        ef = fabs((double)(of.x - cf[0] / lf2));
        e = fabs((double)(of.y - cf[1] / lf2)); ef = e > ef ? e : ef;
        e = fabs((double)(of.z - cf[2] / lf2)); ef = e > ef ? e : ef;
        badd += !(ed <= 4 * DBL_EPSILON);
        badf += !(ef <= FLT_EPSILON);
        worstd = ed > worstd ? ed : worstd;
        worstf = ef > worstf ? ef : worstf;
        /* control: the bare formula */
        bd = 1 / sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
        bf = 1 / sqrtf(vf.x * vf.x + vf.y * vf.y + vf.z * vf.z);
        ctld += !(fabs((double)(v.x * bd - c[0] / l2)) <= 4 * DBL_EPSILON);
        ctlf += !(fabs((double)(vf.x * bf - cf[0] / lf2)) <= FLT_EPSILON);
    }
    mt_check(badd == 0 && badf == 0, "mist_normalize within 4 eps, mist_normalizef within 1 "
             "ulp of 1, of v/|v|: %ld and %ld of %ld fail (worst %.2f, %.2f eps)", badd, badf,
             n, worstd / DBL_EPSILON, worstf / FLT_EPSILON);
    mt_check(ctld > 0 && ctlf > 0, "control: the bare normalisation must fail somewhere "
             "(%ld double, %ld float)", ctld, ctlf);
    printf("test_domain: normalize worst %.2f eps (double), %.2f eps (float) over %ld vectors; "
           "control %ld, %ld\n", worstd / DBL_EPSILON, worstf / FLT_EPSILON, n, ctld, ctlf);
}

static void test_fog(void)
{
    mist_fog f = mist_fog_make(NAN, 3, -2, 1.5), h;
    mist_fogf ff = mist_fog_makef(0.5f, -0.5f, NAN, NAN);
    mt_check(f.g_hg == 0 && f.g_d == 1 && f.alpha == 0 && f.w_d == 1, "fog_make sanitises");
    mt_check(ff.g_hg == 0.5f && ff.g_d == -0.5f && ff.alpha == 0 && ff.w_d == 0,
             "fog_makef sanitises NaN alpha and w_d");
    /* a hand-filled struct with bad values is safe: w_d is clamped */
    h.g_hg = 0.5; h.g_d = 0.2; h.alpha = 3; h.w_d = NAN;
    mt_check(mist_fog_eval(h, 0.3) == mist_hg_eval(0.5, 0.3) &&
             mist_fog_sample(h, 0.3) == mist_hg_sample(0.5, 0.3), "fog w_d NaN is 0");
    h.w_d = 2;
    mt_check(mist_fog_eval(h, 0.3) == mist_draine_eval(0.2, 3, 0.3) &&
             mist_fog_sample(h, 0.3) == mist_draine_sample(0.2, 3, 0.3), "fog w_d > 1 is 1");
    /* xi = 1 with w_d = 1: the Draine lobe's upper end */
    mt_check(mist_fog_sample(h, 1) == 1, "fog xi 1");
}

/* Finite input never yields NaN; for |g| < 1 everything is finite; samples
 * lie in [-1, 1] and directions are unit. */
static void test_sweep(void)
{
    static const double gs[] = { 0, -0.0, 4.9406564584124654e-324, -DBL_MIN, 1e-300, 1e-8, 0.5,
                                 0.999999, 1 - DBL_EPSILON / 2, -(1 - DBL_EPSILON / 2),
                                 1, -1, 1 + DBL_EPSILON, -1e300 };
    static const double as[] = { 0, -0.0, 4.9406564584124654e-324, 1e-300, 1e-8, 1, 1e8, 1e300,
                                 DBL_MAX, INFINITY, -1 };
    static const double xs[] = { 0, -0.0, 4.9406564584124654e-324, 1e-300, 1e-16, 0.5, 1 - DBL_EPSILON / 2,
                                 1, 1 + DBL_EPSILON, -DBL_MIN, DBL_MAX };
    size_t i, j, k;
    int bad = 0, badf = 0;
    for (i = 0; i < sizeof gs / sizeof *gs; ++i)
        for (j = 0; j < sizeof as / sizeof *as; ++j)
            for (k = 0; k < sizeof xs / sizeof *xs; ++k) {
                double g = gs[i], a = as[j], x = xs[k], pdf;
                float gf = (float)g, af = (float)a, xf = (float)x, pf;
                int interior = fabs(g) < 1, interiorf = fabsf(gf) < 1;
                double u = mist_draine_sample(g, a, x);
                double p = mist_draine_eval(g, a, 2 * x - 1);
                float uf = mist_draine_samplef(gf, af, xf);
                float pff = mist_draine_evalf(gf, af, 2 * xf - 1);
                mist_vec3 wi = { 0.1, -0.2, 0.97 }, wo;
                mist_vec3f wif = { 0.1f, -0.2f, 0.97f }, wof;
                wo = mist_draine_sample_dir(g, a, wi, x, 1 - x, &pdf);
                wof = mist_draine_sample_dirf(gf, af, wif, xf, 1 - xf, &pf);
                bad += !(u >= -1 && u <= 1) || p != p || p < 0 || pdf != pdf ||
                       (interior && (!isfinite(p) || !isfinite(pdf))) ||
                       !(fabs(len3(wo) - 1) <= 4 * DBL_EPSILON);
                badf += !(uf >= -1 && uf <= 1) || pff != pff || pff < 0 || pf != pf ||
                        (interiorf && (!isfinite(pff) || !isfinite(pf))) ||
                        !(fabsf(sqrtf(wof.x * wof.x + wof.y * wof.y + wof.z * wof.z) - 1)
                          <= 4 * FLT_EPSILON);
                bad += mist_hg_sample(g, x) != mist_hg_sample(g, x);   /* NaN */
                badf += mist_hg_samplef(gf, xf) != mist_hg_samplef(gf, xf);
            }
    mt_check(bad == 0, "double sweep over domain edges: %d bad results", bad);
    mt_check(badf == 0, "float sweep over domain edges: %d bad results", badf);
}

/* The float HG sampler tests its domain on the bits of g and xi (|g| < 1,
 * xi in [+0, 1]; mist__gxi_in) before any floating-point test: on both
 * sides of every edge of that test (the last float below 1, 1, the first
 * above, -0, the smallest subnormals, infinities, NaN of either sign) the
 * answer must be the documented one: the sample at the sanitised g and xi
 * (u = g where |g| = 1), in [-1, 1], u = -1 at xi = 0 and +1 at xi = 1,
 * and the batch form and the prepared HG medium (mist__phase_hg: the same
 * bit test, the terms of g stored) the same. */
static void test_hg_bits(void)
{
    /* each input beside its sanitised value (written out: the fast-math
     * variant builds this file with -ffast-math, where x != x is false) */
    static const float gs[][2] = {
        { 0, 0 }, { -0.0f, -0.0f }, { 0x1p-149f, 0x1p-149f }, { -0x1p-149f, -0x1p-149f },
        { 0.5f, 0.5f }, { -0.5f, -0.5f }, { 0x1.fffffep-1f, 0x1.fffffep-1f },
        { -0x1.fffffep-1f, -0x1.fffffep-1f }, { 1, 1 }, { -1, -1 }, { 0x1.000002p0f, 1 },
        { -0x1.000002p0f, -1 }, { INFINITY, 1 }, { -INFINITY, -1 }, { NAN, 0 }, { -NAN, 0 } };
    static const float xs[] = { 0, -0.0f, 0x1p-149f, -0x1p-149f, -1e-30f, 0.5f, 0x1.fffffep-1f,
                                1, 0x1.000002p0f, INFINITY, -INFINITY, NAN, -NAN };
    static const float xc[] = { 0, 0, 0x1p-149f, 0, 0, 0.5f, 0x1.fffffep-1f,
                                1, 1, 1, 0, 0, 0 };
    enum { NX = sizeof xs / sizeof *xs };
    size_t i, j;
    int bad = 0;
    for (i = 0; i < sizeof gs / sizeof *gs; ++i) {
        float g = gs[i][0], gc = gs[i][1], out[NX];
        mist_phasef ph = mist_phase_hgf(g);
        mist_hg_sample_nf(g, xs, out, NX);
        for (j = 0; j < NX; ++j) {
            float u = mist_hg_samplef(g, xs[j]);
            float want = (gc == 1 || gc == -1) ? gc
                       : xc[j] == 0 ? -1 : xc[j] == 1 ? 1 : mist_hg_samplef(gc, xc[j]);
            bad += !(u == want) || !(u >= -1 && u <= 1) || !(out[j] == u)
                 || !(mist_phase_samplef(&ph, xs[j]) == u);
        }
    }
    mt_check(bad == 0, "float HG sampler on the edges of its bit test: %d bad", bad);
}

/* Prepared phase functions (mist_phase_*): bad parameters and inputs give
 * what the unprepared functions give (to a few ulps: the prepared density
 * rounds in another order, and the sampler's F(0) is stored, not
 * recomputed: 4 ulps allow for both); the Dirac limits exactly; a NULL
 * phase pointer is isotropic; the pdf reported is mist_phase_eval. */
static int near_d(double a, double b)
{
    if (a == b) return 1;
    if (!isfinite(a) || !isfinite(b)) return 0;
    return fabs(a - b) <= 4 * DBL_EPSILON * fmax(fabs(a), fabs(b)) + 4 * 0x1p-1074;
}
static int near_f(float a, float b)
{
    if (a == b) return 1;
    if (!isfinite(a) || !isfinite(b)) return 0;
    return fabsf(a - b) <= 4 * FLT_EPSILON * fmaxf(fabsf(a), fabsf(b)) + 4 * 0x1p-149f;
}

static void test_prepared(void)
{
    static const double gs[] = { NAN, 1.5, -INFINITY, 1, -1, 0.3, -0.999, 0 };
    static const double as[] = { -3, NAN, 0, INFINITY, 17, 1e30 };
    static const double ws[] = { NAN, -1, 2, 0, 1, 0.4 };
    static const double us[] = { -1.5, NAN, -1, 0.3, 1, 1.0000001, -INFINITY };
    static const double xs[] = { -0.1, NAN, 0, 0.5, 0.77, 1, 1.5, INFINITY };
    mist_vec3 wi = { 0.3, -0.4, 0.5 };
    size_t ig, ia, iw, k;
    int bad = 0, badf = 0;
    for (ig = 0; ig < sizeof gs / sizeof *gs; ++ig)
        for (ia = 0; ia < sizeof as / sizeof *as; ++ia)
            for (iw = 0; iw < sizeof ws / sizeof *ws; ++iw) {
                double g = gs[ig], a = as[ia];
                float gf = (float)g, af = (float)a;
                mist_fog fog = { 0.5, g, a, ws[iw] };
                mist_fogf fogf = { 0.5f, gf, af, (float)ws[iw] };
                mist_phase pd = mist_phase_draine(g, a), pf = mist_phase_fog(fog);
                mist_phase ph = mist_phase_hg(g), pc = mist_phase_cs(g);
                mist_phasef pdf_ = mist_phase_drainef(gf, af), pff = mist_phase_fogf(fogf);
                mist_phasef phf = mist_phase_hgf(gf);
                for (k = 0; k < sizeof us / sizeof *us; ++k) {
                    double u = us[k];
                    bad += !near_d(mist_phase_eval(&pd, u), mist_draine_eval(g, a, u));
                    bad += !near_d(mist_phase_eval(&pf, u), mist_fog_eval(fog, u));
                    bad += !near_d(mist_phase_eval(&ph, u), mist_hg_eval(g, u));
                    bad += !near_d(mist_phase_eval(&pc, u), mist_cs_eval(g, u));
                    badf += !near_f(mist_phase_evalf(&pdf_, (float)u),
                                    mist_draine_evalf(gf, af, (float)u));
                    badf += !near_f(mist_phase_evalf(&pff, (float)u),
                                    mist_fog_evalf(fogf, (float)u));
                    badf += !near_f(mist_phase_evalf(&phf, (float)u), mist_hg_evalf(gf, (float)u));
                }
                for (k = 0; k < sizeof xs / sizeof *xs; ++k) {
                    double x = xs[k], pdf = -1, uu;
                    float xf = (float)x;
                    mist_vec3 o;
                    bad += !near_d(mist_phase_sample(&pd, x), mist_draine_sample(g, a, x));
                    bad += !near_d(mist_phase_sample(&pf, x), mist_fog_sample(fog, x));
                    bad += !near_d(mist_phase_sample(&ph, x), mist_hg_sample(g, x));
                    bad += !near_d(mist_phase_sample(&pc, x), mist_cs_sample(g, x));
                    badf += !near_f(mist_phase_samplef(&pdf_, xf), mist_draine_samplef(gf, af, xf));
                    badf += !near_f(mist_phase_samplef(&pff, xf), mist_fog_samplef(fogf, xf));
                    badf += !near_f(mist_phase_samplef(&phf, xf), mist_hg_samplef(gf, xf));
                    o = mist_phase_sample_dir(&pf, wi, x, 0.3, &pdf);
                    uu = mist_phase_sample(&pf, x);
                    bad += !(pdf == mist_phase_eval(&pf, uu) && isfinite(o.x) && isfinite(o.z));
                }
            }
    {   /* a fog with tiny w_d and a Draine lobe near the Dirac limit: the
         * lobe's density at u = -1 is normal although w_d times its
         * normalisation underflows (taken in that order, the prepared
         * density would be 0 there, and the pdf of a sample 0).
         * Reference: the closed form w (1 - g^2) / (4 pi cn V^3) (1 + a u^2),
         * V = 1 + g at u = -1, g_hg = 1 adding 0 there, divided before w
         * multiplies (no underflow in double); bar 8 eps relative: a few
         * roundings on each side.  Normal w_d only (-ffast-math reads a
         * subnormal as 0). */
        static const double wd[] = { 0x1p-1020, 0x1p-1000, 1e-300, 0x1p-1022 };
        static const float wfs[] = { 1e-37f, 0x1p-126f, 0x1p-100f };
        const double gd = -(1 - 0x1p-53);
        const float gfd = -(1 - 0x1p-24f);
        mist_vec3f wif = { 0.3f, -0.4f, 0.5f };
        int okd = 1, okf = 1;
        size_t j;
        for (j = 0; j < sizeof wd / sizeof *wd; ++j) {
            mist_fog fog = { 1, gd, 1, wd[j] };
            mist_phase pf = mist_phase_fog(fog);
            double v = 1 + gd, ref = (1 - gd) * (1 + gd) / (v * v * v) / (4 * 3.14159265358979323846)
                       * 2 / (1 + (1 + 2 * gd * gd) / 3) * wd[j];
            double p = mist_phase_eval(&pf, -1), pdf = -1;
            double us = mist_phase_sample(&pf, wd[j] / 4);
            (void)mist_phase_sample_dir(&pf, wi, wd[j] / 4, 0.3, &pdf);
            okd &= fabs(p - ref) <= 8 * DBL_EPSILON * ref && near_d(p, mist_fog_eval(fog, -1))
                   && pdf > 0 && pdf == mist_phase_eval(&pf, us);
        }
        for (j = 0; j < sizeof wfs / sizeof *wfs; ++j) {
            mist_fogf fog = { 1, gfd, 1, wfs[j] };
            mist_phasef pf = mist_phase_fogf(fog);
            double v = 1 + (double)gfd, g2 = (double)gfd * gfd;
            double ref = (1 - (double)gfd) * v / (v * v * v) / (4 * 3.14159265358979323846)
                         * 2 / (1 + (1 + 2 * g2) / 3) * wfs[j];
            float p = mist_phase_evalf(&pf, -1), pdf = -1;
            float us = mist_phase_samplef(&pf, wfs[j] / 4);
            (void)mist_phase_sample_dirf(&pf, wif, wfs[j] / 4, 0.3f, &pdf);
            okf &= fabs(p - ref) <= 8 * FLT_EPSILON * ref + 0x1p-149 &&
                   near_f(p, mist_fog_evalf(fog, -1)) && pdf > 0 &&
                   pdf == mist_phase_evalf(&pf, us);
        }
        mt_check(okd, "prepared fog, tiny w_d: the Draine lobe's density kept (double)");
        mt_check(okf, "prepared fog, tiny w_d: the Draine lobe's density kept (float)");
    }
    mt_check(bad == 0, "prepared = unprepared over bad input (double): %d differ", bad);
    mt_check(badf == 0, "prepared = unprepared over bad input (float): %d differ", badf);
    {   /* Rayleigh, and NULL: isotropic */
        mist_phase r = mist_phase_rayleigh();
        mist_phasef rf = mist_phase_rayleighf();
        double pdf = -1;
        float pdff = -1;
        mist_vec3 o = mist_phase_sample_dir(NULL, wi, 0.25, 0.5, &pdf);
        mist_vec3f wf = { 0, 0, 1 }, of = mist_phase_sample_dirf(NULL, wf, 0.25f, 0.5f, &pdff);
        mt_check(near_d(mist_phase_eval(&r, 0.3), mist_rayleigh_eval(0.3)) &&
                 mist_phase_sample(&r, 0.3) == mist_rayleigh_sample(0.3) &&
                 mist_phase_evalf(&rf, NAN) == 0 &&
                 mist_phase_samplef(&rf, 0.3f) == mist_rayleigh_samplef(0.3f),
                 "prepared Rayleigh");
        mt_check(mist_phase_eval(NULL, 0.7) == 1 / (4 * 3.14159265358979323846) &&
                 mist_phase_evalf(NULL, -0.2f) == (float)(1 / (4 * 3.14159265358979323846)) &&
                 mist_phase_eval(NULL, NAN) == 0 &&
                 mist_phase_sample(NULL, 0.25) == -0.5 && mist_phase_sample(NULL, NAN) == -1 &&
                 mist_phase_samplef(NULL, 1) == 1 && pdf == mist_phase_eval(NULL, 0) &&
                 pdff == mist_phase_evalf(NULL, 0) && fabs(len3(o) - 1) < 4 * DBL_EPSILON &&
                 isfinite(of.x),
                 "NULL phase: isotropic");
    }
    /* a medium whose w was set by hand to NaN (or -0): HG, as w <= 0.  In
     * the fast-math variant a floating-point !(w > 0) in the small
     * mist_phase_sample took the Draine branch for NaN (gcc -ffast-math:
     * -1 for the HG sample at xi 0.9); mist__gt0 tests the bits */
    {
        static const double ws[] = { 0, -0.0, -1, 0 };
        mist_phase ph = mist_phase_hg(0.8);
        mist_phasef phf = mist_phase_hgf(0.8f);
        int bad = 0;
        size_t i, j;
        for (i = 0; i < 4; ++i) {
            ph.w = i == 3 ? NAN : ws[i];
            phf.w = i == 3 ? NAN : (float)ws[i];
            for (j = 1; j < 10; j += 4) {
                double x = 0.1 * (double)j;
                bad += mist_phase_sample(&ph, x) != mist_hg_sample(0.8, x);
                bad += mist_phase_samplef(&phf, (float)x) != mist_hg_samplef(0.8f, (float)x);
            }
        }
        ph.w = -NAN; phf.w = -NAN;
        bad += mist_phase_sample(&ph, 0.9) != mist_hg_sample(0.8, 0.9);
        bad += mist_phase_samplef(&phf, 0.9f) != mist_hg_samplef(0.8f, 0.9f);
        mt_check(bad == 0, "prepared HG with w set to 0, -0, -1, NaN, -NaN: the HG sample "
                 "(%d wrong)", bad);
    }
}

int main(void)
{
    test_prepared();
    test_g();
    test_alpha();
    test_u_xi();
    test_directions();
    test_dir_sine();
    test_normalize();
    test_fog();
    test_sweep();
    test_hg_bits();
    return mt_done("test_domain");
}
