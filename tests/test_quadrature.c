/* test_quadrature.c - every closed form checked by numerical quadrature and
 * by an independent high-precision evaluation.  Mirrors the "evaluation"
 * sections of include/mist.h:
 *   - each density integrates to 1 over the sphere (1e-10 in double);
 *   - its mean cosine matches the closed form (HG: g; Draine:
 *     g (1 + alpha (3 + 2 g^2)/5) / (1 + alpha (1 + 2 g^2)/3); Rayleigh: 0;
 *     the fog mix: the w_d-weighted mean of its lobes);
 *   - the value of each density agrees with the __float128 formula of
 *     tests/mist_ref.h to a few ulps;
 *   - the pdf returned with a sampled direction equals the evaluated density
 *     at the sampled cosine, and the direction has that cosine. */
#include "mist.h"
#include "mist_ref.h"
#include "mist_test.h"

#define PI 3.14159265358979323846

typedef struct {
    int kind;                 /* 0 HG, 1 Draine, 2 Rayleigh, 3 fog, 4 CS */
    double g, a;
    mist_fog fog;
} dens_ctx;

static double dens(const dens_ctx *c, double u)
{
    switch (c->kind) {
    case 0: return mist_hg_eval(c->g, u);
    case 1: return mist_draine_eval(c->g, c->a, u);
    case 2: return mist_rayleigh_eval(u);
    case 3: return mist_fog_eval(c->fog, u);
    default: return mist_cs_eval(c->g, u);
    }
}

static double f_norm(double u, const void *c) { return 2 * PI * dens((const dens_ctx *)c, u); }
static double f_mean(double u, const void *c) { return 2 * PI * u * dens((const dens_ctx *)c, u); }

/* Integral over [-1, 1], split at 1 - 10^-k and -1 + 10^-k so that the
 * adaptive rule sees the narrow peaks of |g| -> 1 (width ~ 1 - |g|). */
static double sphere_integral(mt_fn f, const dens_ctx *c, double tol, double *err)
{
    double edges[40], sum = 0, e, etot = 0;
    int n = 0, k, i;
    edges[n++] = -1;
    for (k = 12; k >= 1; --k) edges[n++] = -1 + pow(10, -k);
    edges[n++] = 0;
    for (k = 1; k <= 12; ++k) edges[n++] = 1 - pow(10, -k);
    edges[n++] = 1;
    for (i = 0; i + 1 < n; ++i) {
        sum += mt_integrate(f, c, edges[i], edges[i + 1], tol / (n - 1), &e);
        etot += e;
    }
    *err = etot;
    return sum;
}

static double draine_mean(double g, double a)
{
    if (isinf(a)) return g * (3 + 2 * g * g) / 5 * 3 / (1 + 2 * g * g);
    return g * (1 + a * (3 + 2 * g * g) / 5) / (1 + a * (1 + 2 * g * g) / 3);
}

static double closed_mean(const dens_ctx *c)
{
    switch (c->kind) {
    case 0: return c->g;
    case 1: return draine_mean(c->g, c->a);
    case 2: return 0;
    case 3: return (1 - c->fog.w_d) * c->fog.g_hg + c->fog.w_d * draine_mean(c->fog.g_d, c->fog.alpha);
    default: return draine_mean(c->g, 1);
    }
}

static const char *names[] = { "hg", "draine", "rayleigh", "fog", "cs" };

static void check_moments(dens_ctx c)
{
    /* quadrature tolerance 1e-13, far below the 1e-10 bar */
    double tol = 1e-10, qtol = 1e-13, e1, e2;
    double norm = sphere_integral(f_norm, &c, qtol, &e1);
    double mean = sphere_integral(f_mean, &c, qtol, &e2);
    double want = closed_mean(&c);
    mt_check(e1 < 10 * qtol && e2 < 10 * qtol, "%s quadrature converged (g=%g a=%g): err %g %g",
             names[c.kind], c.g, c.a, e1, e2);
    mt_check(fabs(norm - 1) <= tol, "%s g=%g alpha=%g integrates to %.15g",
             names[c.kind], c.g, c.a, norm);
    mt_check(fabs(mean - want) <= tol, "%s g=%g alpha=%g mean cosine %.15g, closed form %.15g",
             names[c.kind], c.g, c.a, mean, want);
}

/* Values against the __float128 density (per unit u / (2 pi)).  Bound:
 * the density takes ~12 roundings, so 16 eps relative (double), and for
 * float 16 eps_f; the peak of |g| -> 1 amplifies the rounding of u itself
 * (relative sensitivity 3 g u'/V^2 |u|) which is added to the bound. */
static void check_values(void)
{
    static const double gs[] = { 0, 1e-7, -1e-4, 0.3, -0.3, 0.9, -0.9, 0.999, -0.999 };
    static const double as[] = { 0, 1e-3, 1, 17, 250, 1e4 };
    mt_rng rng = { 4242 };
    size_t ig, ia;
    int k;
    for (ig = 0; ig < sizeof gs / sizeof *gs; ++ig)
        for (ia = 0; ia < sizeof as / sizeof *as; ++ia) {
            double g = gs[ig], a = as[ia], worst = 0, worstf = 0;
            for (k = 0; k < 200; ++k) {
                double u = k == 0 ? -1 : (k == 1 ? 1 : (k == 2 ? 0 : 2 * mt_uniform(&rng) - 1));
                double want = (double)(ref_density_u(g, a, u) / (2 * (qreal)PI));
                double got = mist_draine_eval(g, a, u);
                float gf = (float)g, af = (float)a, uf = (float)u;
                double wantf = (double)(ref_density_u(gf, af, uf) / (2 * (qreal)PI));
                double gotf = mist_draine_evalf(gf, af, uf);
                double sens = 3 * fabs(g) * fabs(u) / (1 + g * g - 2 * g * u + 1e-300);
                double r = fabs(got - want) / want / (0x1p-53 * (16 + sens));
                double rf = fabs(gotf - wantf) / wantf / (0x1p-24 * (16 + sens));
                if (r > worst) worst = r;
                if (rf > worstf) worstf = rf;
                if (a == 0) {
                    mt_check(mist_hg_eval(g, u) == got && mist_hg_evalf(gf, uf) == (float)gotf,
                             "hg_eval equals draine_eval at alpha = 0 (g=%g u=%g)", g, u);
                }
            }
            mt_check(worst <= 1 && worstf <= 1,
                     "draine_eval g=%g alpha=%g vs float128: worst %.2f (double), %.2f "
                     "(float) of the bound", g, a, worst, worstf);
        }
    for (k = 0; k < 200; ++k) {
        double u = 2 * mt_uniform(&rng) - 1;
        double want = 3.0 / (16 * PI) * (1 + u * u);
        mt_check(fabs(mist_rayleigh_eval(u) - want) <= 4 * 0x1p-53 * want &&
                 fabs(mist_rayleigh_evalf((float)u) - want) <= 8 * 0x1p-24 * want,
                 "rayleigh_eval(%g)", u);
        mt_check(mist_cs_eval(0.5, u) == mist_draine_eval(0.5, 1, u), "cs = draine(alpha=1)");
    }
}

/* The pdf reported with a sampled direction is the evaluated density at the
 * sampled cosine (exactly: the same function of the same u), and the
 * direction has that cosine to wi within a few ulps (16 eps: the frame and
 * the sum of three products). */
static void check_pdf_dir(void)
{
    mt_rng rng = { 5 };
    mist_vec3 wis[3];
    int k, j;
    wis[0].x = 0; wis[0].y = 0; wis[0].z = 1;
    wis[1].x = 0.48; wis[1].y = -0.6; wis[1].z = 0.64;
    wis[2].x = 1e-9; wis[2].y = 0; wis[2].z = -1;
    for (j = 0; j < 3; ++j)
        for (k = 0; k < 2000; ++k) {
            double x1 = mt_uniform(&rng), x2 = mt_uniform(&rng), pdf, u, c;
            mist_vec3 wi = mist_normalize(wis[j]), wo;
            mist_fog fog = mist_fog_make(0.98, 0.5, 600, 0.4);
            int which = k % 5;
            switch (which) {
            case 0: wo = mist_hg_sample_dir(0.9, wi, x1, x2, &pdf); u = mist_hg_sample(0.9, x1);
                    mt_check(pdf == mist_hg_eval(0.9, u), "hg pdf == eval"); break;
            case 1: wo = mist_draine_sample_dir(0.5, 250, wi, x1, x2, &pdf);
                    u = mist_draine_sample(0.5, 250, x1);
                    mt_check(pdf == mist_draine_eval(0.5, 250, u), "draine pdf == eval"); break;
            case 2: wo = mist_cs_sample_dir(-0.7, wi, x1, x2, &pdf); u = mist_cs_sample(-0.7, x1);
                    mt_check(pdf == mist_cs_eval(-0.7, u), "cs pdf == eval"); break;
            case 3: wo = mist_rayleigh_sample_dir(wi, x1, x2, &pdf); u = mist_rayleigh_sample(x1);
                    mt_check(pdf == mist_rayleigh_eval(u), "rayleigh pdf == eval"); break;
            default: wo = mist_fog_sample_dir(fog, wi, x1, x2, &pdf); u = mist_fog_sample(fog, x1);
                    mt_check(pdf == mist_fog_eval(fog, u), "fog pdf == eval"); break;
            }
            c = wi.x * wo.x + wi.y * wo.y + wi.z * wo.z;
            mt_check(fabs(c - u) <= 16 * 0x1p-53, "direction %d has the sampled cosine: %.17g vs %.17g",
                     which, c, u);
        }
    /* float */
    for (k = 0; k < 2000; ++k) {
        float x1 = mt_uniformf(&rng), x2 = mt_uniformf(&rng), pdf, u, c;
        mist_vec3f wi, wo;
        wi.x = 0.48f; wi.y = -0.6f; wi.z = 0.64f;
        wi = mist_normalizef(wi);
        wo = mist_draine_sample_dirf(0.8f, 17, wi, x1, x2, &pdf);
        u = mist_draine_samplef(0.8f, 17, x1);
        c = wi.x * wo.x + wi.y * wo.y + wi.z * wo.z;
        mt_check(pdf == mist_draine_evalf(0.8f, 17, u) && fabsf(c - u) <= 16 * 0x1p-24f,
                 "float direction: pdf == eval and cosine %.9g vs %.9g", c, u);
    }
}

/* fog parameters from the Jendersie-d'Eon large-droplet fits (eq. 7-10,
 * constants inside the exponentials) at diameter d in um */
static mist_fog fog_at(double d)
{
    return mist_fog_make(exp(-0.0990567 / (d - 1.67154)),
                         exp(-2.20679 / (d + 3.91029) - 0.428934),
                         exp(3.62489 - 8.29288 / (d + 5.52825)),
                         exp(-0.599085 / (d - 0.641583) - 0.665888));
}

int main(void)
{
    static const double gs[] = { 0, 1e-7, -1e-7, 1e-4, 0.3, -0.3, 0.9, -0.9, 0.999,
                                 -0.999, 0.9999 };
    static const double as[] = { 0, 1e-3, 1, 17, 250, 1e4, INFINITY };
    static const double ds[] = { 5, 10, 20, 50 };
    size_t i, j;
    /* Quadrature of the double densities.  The float densities are checked
     * value by value against float128 at float inputs (check_values): a
     * quadrature of a float density over double u would integrate the
     * staircase of u's rounding, which near a peak of width 1 - g ~ 1e-4 is
     * coarser than the peak itself. */
    for (i = 0; i < sizeof gs / sizeof *gs; ++i) {
        dens_ctx c = { 0, 0, 0, { 0, 0, 0, 0 } };
        c.g = gs[i];
        c.kind = 0; check_moments(c);
        c.kind = 4; check_moments(c);
        c.kind = 1;
        for (j = 0; j < sizeof as / sizeof *as; ++j) { c.a = as[j]; check_moments(c); }
    }
    {
        dens_ctx c = { 2, 0, 0, { 0, 0, 0, 0 } };
        check_moments(c);
        c.kind = 3;
        for (i = 0; i < sizeof ds / sizeof *ds; ++i) { c.fog = fog_at(ds[i]); check_moments(c); }
        c.fog = mist_fog_make(13.8 * 0.05 * 0.05, 1.1456 * 0.05 * sin(9.29044 * 0.05), 250,
                              0.252977 - 312.983 * pow(0.05, 4.3));
        check_moments(c);
    }
    check_values();
    check_pdf_dir();
    return mt_done("test_quadrature");
}
