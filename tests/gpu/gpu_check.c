/* gpu_check.c - checks what tests/gpu/mist_gpu.cu wrote: mist's answers in
 * CUDA device code, against the __float128 reference (tests/mist_ref.h) and
 * against the host's answers to the same inputs.  Runs on any machine:
 *   cc -O2 -Iinclude -Itests tests/gpu/gpu_check.c -o gpu_check -lm
 *   ./gpu_check gpu.bin
 * What is checked (mist_gpu.cu's header says why):
 *   - samples, scalar and prepared, float and double, HG / Draine / CS /
 *     Rayleigh, and the batch forms: test_accuracy.c's bar,
 *       |u - u*| <= 4 ulp(u*) + 4 eps xi du/dxi,
 *     device and host alike (device code has no long double: its double
 *     samplers finish in double-double, with the same bar);
 *   - densities: relative error against the __float128 density, in units of
 *     the type's eps; the device's worst may not exceed twice the host's
 *     worst on the same inputs plus 8 (fma contraction moves a few roundings);
 *   - directions: |wo| = 1 within 8 eps, wo . wi/|wi| = the sample of the
 *     same call within 8 eps plus the sample's distance to the host's, pdf
 *     finite >= 0 (8 eps: the frame's few roundings; tests/test_stress.c
 *     sees 2.8 eps at worst on the CPU);
 *   - fog mixture samples: the lobe mist picks (Draine where xi < w), at
 *     the remapped xi' = xi / w or (xi - w) / (1 - w) computed in
 *     __float128, against twice the bar (the remap's three roundings move
 *     xi' by up to 3 eps xi', within a second bar's xi term); fog
 *     densities against (1 - w) HG + w Draine in __float128;
 *   - bad and edge input: the device's answer is NaN
 *     exactly where the host's is, and within 1e-3 (relative, or absolute
 *     below 1) of it elsewhere: the documented behaviour is the host's,
 *     which tests/test_domain.c checks; this only has to tell a wrong
 *     branch (0 for 1, -1 for g, a clamp missed) from the same answer, and
 *     device code has no long double, so an ill-conditioned sample may
 *     move by more than its ulps (precision is the random points' job).
 * `./gpu_check gpu.bin control`: the negative control.  It moves one point
 * in 97 of the device's answers (a float sample by 1e-4, a double density
 * by 1e-12 relative, a direction off the unit sphere, a NaN into a bad-input
 * answer, a batch sample), checks only those points, and passes only if the
 * checks above fail on them.
 * Not in CI: CI has no GPU (the file comes from a device run). */
#include "mist_ref.h"
#include "mist_test.h"
#include "gpu_data.h"

#include <float.h>
#include <string.h>

static void ref_params(int kind, double g, double a, double *rg, qreal *ra)
{
    *rg = kind == GP_RAYLEIGH ? 0 : g;
    *ra = kind == GP_HG ? 0 : (kind == GP_DRAINE ? a : 1);
}

/* the bar's ratio (<= 1 passes) for one sample u of type eps at (g, a, xi) */
static double bar_ratio(int kind, double g, double a, double xi, double u, int flt)
{
    double rg, us;
    qreal ra;
    ref_params(kind, g, a, &rg, &ra);
    return ref_bar(rg, ra, xi, u, flt, &us);
}


static double worst[2][10];  /* [device, host][ds, dp, fs, fp, bd, bpd, bf, bpf, fog d, fog f] */
static const char *wname[10] = { "double sample", "double prepared sample", "float sample",
                                 "float prepared sample", "double batch", "double prepared batch",
                                 "float batch", "float prepared batch", "double fog (2x bar)",
                                 "float fog (2x bar)" };
static const char *kname[5] = { "hg", "draine", "cs", "rayleigh", "fog" };

static void check_sample(int dev, int slot, int kind, double g, double a, double xi, double u,
                         int flt)
{
    double r = bar_ratio(kind, g, a, xi, u, flt);
    if (r > worst[!dev][slot]) worst[!dev][slot] = r;
    mt_check(r <= 1, "%s %s %s g=%.17g alpha=%.17g xi=%.17g: u=%.17g (%.2f x the bar)",
             dev ? "device" : "host", kname[kind], wname[slot], g, a, xi, u, r);
}

/* density relative error in eps units */
#define TWO_PI_Q (2 * (qreal)3.14159265358979323846264338327950288)

static double dens_err(int kind, double g, double a, double u, double e, int flt)
{
    double rg, ref;
    qreal ra;
    ref_params(kind, g, a, &rg, &ra);
    if (!(fabs(rg) < 1) || !(u >= -1 && u <= 1)) return 0;
    ref = (double)(ref_density_u(rg, ra, u) / TWO_PI_Q);
    return fabs(e - ref) / ref / (flt ? 0x1p-24 : 0x1p-53);
}

/* a fog sample u (mist_fog_make(g, g2, a, w): HG g, Draine g2, alpha a,
 * Draine weight w; inputs already of the type checked) */
static void check_fog(int dev, int flt, double g, double g2, double a, double w, double xi,
                      double u)
{
    double r, xr;
    int kd = xi < w || w >= 1 ? GP_DRAINE : GP_HG;
    qreal xq = kd == GP_DRAINE ? (qreal)xi / (qreal)w : ((qreal)xi - w) / (1 - (qreal)w);
    xr = (double)xq;
    if (kd == GP_DRAINE) r = bar_ratio(GP_DRAINE, g2, a, xr, u, flt);
    else r = bar_ratio(GP_HG, g, 0, xr, u, flt);
    r /= 2;
    if (r > worst[!dev][8 + flt]) worst[!dev][8 + flt] = r;
    mt_check(r <= 1, "%s fog %s g=%.17g g2=%.17g alpha=%.17g w=%.17g xi=%.17g: u=%.17g "
             "(%.2f x twice the bar)", dev ? "device" : "host", flt ? "float" : "double", g, g2,
             a, w, xi, u, r);
}
static double fog_dens_err(double g, double g2, double a, double w, double u, double e, int flt)
{
    double ref;
    if (!(fabs(g) < 1 && fabs(g2) < 1) || !(u >= -1 && u <= 1)) return 0;
    ref = (double)(((1 - (qreal)w) * ref_density_u(g, 0, u) + w * ref_density_u(g2, a, u))
                   / TWO_PI_Q);
    return fabs(e - ref) / ref / (flt ? 0x1p-24 : 0x1p-53);
}

static int same_nan(double d, double h) { return isnan(d) == isnan(h); }
static int near(double d, double h)
{
    if (isnan(d) || isnan(h)) return isnan(d) && isnan(h);
    if (d == h) return 1;
    return fabs(d - h) <= 1e-3 * (fabs(h) > 1 ? fabs(h) : 1);
}

static void compare_all(const gp_in *in, const gp_out *d, const gp_out *h, long *bad)
{
    double dv[16] = { d->ds, d->dp, d->de, d->dpe, d->dpdf, d->dwo[0], d->dwo[1], d->dwo[2],
                      d->fs, d->fp, d->fe, d->fpe, d->fpdf, d->fwo[0], d->fwo[1], d->fwo[2] };
    double hv[16] = { h->ds, h->dp, h->de, h->dpe, h->dpdf, h->dwo[0], h->dwo[1], h->dwo[2],
                      h->fs, h->fp, h->fe, h->fpe, h->fpdf, h->fwo[0], h->fwo[1], h->fwo[2] };
    static const char *fn[16] = { "ds", "dp", "de", "dpe", "dpdf", "dwo.x", "dwo.y", "dwo.z",
                                  "fs", "fp", "fe", "fpe", "fpdf", "fwo.x", "fwo.y", "fwo.z" };
    int k;
    for (k = 0; k < 16; ++k)
        if (!near(dv[k], hv[k])) {
            if (++*bad <= 20)
                printf("  differs: %s g=%g g2=%g a=%g w=%g xi=%.17g xi2=%.17g wi=(%g,%g,%g): "
                       "%s device %.9g host %.9g\n", kname[in->kind], in->g, in->g2, in->a,
                       in->w, in->xi, in->xi2, in->wi[0], in->wi[1], in->wi[2], fn[k], dv[k],
                       hv[k]);
            mt_check(same_nan(dv[k], hv[k]), "%s: NaN on one side only", fn[k]);
        }
}

/* direction: unit, at the sampled cosine, pdf finite >= 0 */
static void check_dir(const gp_in *in, const double *wo, double u, double pdf, double ubar,
                      int flt, long *bad)
{
    double eps = flt ? 0x1p-24 : 0x1p-53, n = sqrt(in->wi[0] * in->wi[0] + in->wi[1] * in->wi[1]
                                                   + in->wi[2] * in->wi[2]);
    double len = sqrt(wo[0] * wo[0] + wo[1] * wo[1] + wo[2] * wo[2]);
    double c = (wo[0] * in->wi[0] + wo[1] * in->wi[1] + wo[2] * in->wi[2]) / n;
    int ok = fabs(len - 1) <= 8 * eps && fabs(c - u) <= 8 * eps + ubar && isfinite(pdf)
             && pdf >= 0;
    if (!ok && ++*bad <= 10)
        printf("  direction %s %s g=%g a=%g xi=%.17g: |wo|-1=%g cos-u=%g pdf=%g\n",
               flt ? "float" : "double", kname[in->kind], in->g, in->a, in->xi, len - 1, c - u,
               pdf);
    mt_check(ok, "direction");
}

int main(int argc, char **argv)
{
    gp_header h;
    gp_in *in;
    gp_out *dev, *host;
    gp_chunk *ch;
    double *cxi, *bd[2], *bpd[2], dmax[2][4][5];
    float *bf[2], *bpf[2];
    size_t n, m, i, j;
    long bad_cmp = 0, bad_dir = 0, equal_f = 0, equal_fp = 0, nf = 0;
    int s, k, control = argc > 2 && !strcmp(argv[2], "control");
    FILE *f;
    if (argc < 2) { fprintf(stderr, "usage: %s gpu.bin [control]\n", argv[0]); return 2; }
    f = fopen(argv[1], "rb");
    if (!f || fread(&h, sizeof h, 1, f) != 1 || h.magic != GP_MAGIC || h.nrand != GP_NRAND
        || h.nc != GP_NC || h.ch != GP_CH) {
        fprintf(stderr, "%s: not a mist_gpu file of this version\n", argv[1]);
        return 2;
    }
    n = (size_t)h.n; m = (size_t)h.nc * h.ch;
    in = malloc(n * sizeof *in); dev = malloc(n * sizeof *dev); host = malloc(n * sizeof *host);
    ch = malloc(h.nc * sizeof *ch); cxi = malloc(m * sizeof *cxi);
    for (s = 0; s < 2; ++s) {
        bd[s] = malloc(m * sizeof(double)); bpd[s] = malloc(m * sizeof(double));
        bf[s] = malloc(m * sizeof(float)); bpf[s] = malloc(m * sizeof(float));
    }
    if (fread(in, sizeof *in, n, f) != n || fread(dev, sizeof *dev, n, f) != n
        || fread(host, sizeof *host, n, f) != n || fread(ch, sizeof *ch, h.nc, f) != (size_t)h.nc
        || fread(cxi, sizeof *cxi, m, f) != m) { fprintf(stderr, "short file\n"); return 2; }
    for (s = 0; s < 2; ++s)
        if (fread(bd[s], sizeof(double), m, f) != m || fread(bf[s], sizeof(float), m, f) != m
            || fread(bpd[s], sizeof(double), m, f) != m || fread(bpf[s], sizeof(float), m, f) != m)
        { fprintf(stderr, "short file\n"); return 2; }
    fclose(f);
    printf("%s: %zu points (%d random), %d batches of %d; device: %s\n", argv[1], n, h.nrand,
           h.nc, h.ch, h.device);
    memset(dmax, 0, sizeof dmax);
    if (control)
        for (i = 0; i < n; i += 97) {
            dev[i].fs += dev[i].fs > 0 ? -1e-4f : 1e-4f;
            dev[i].de *= 1 + 1e-12;
            dev[i].fwo[0] += 1e-3f;
            if (i >= (size_t)h.nrand) dev[i].ds = NAN;
            if (i < m) bf[0][i] += bf[0][i] > 0 ? -1e-4f : 1e-4f;
        }

    /* random points */
    for (i = 0; i < (size_t)h.nrand; i += control ? 97 : 1) {
        const gp_in *p = &in[i];
        int kd = p->kind;
        double ue = 2 * p->xi2 - 1;
        float gf = (float)p->g, af = (float)p->a, xf = (float)p->xi, uef = (float)ue;
        if (kd == GP_FOG) {
            float g2f = (float)p->g2, wf = (float)p->w;
            for (s = 0; s < 2; ++s) {
                const gp_out *o = s == 0 ? &dev[i] : &host[i];
                double e[4];
                check_fog(s == 0, 0, p->g, p->g2, p->a, p->w, p->xi, o->ds);
                check_fog(s == 0, 0, p->g, p->g2, p->a, p->w, p->xi, o->dp);
                check_fog(s == 0, 1, gf, g2f, af, wf, xf, o->fs);
                check_fog(s == 0, 1, gf, g2f, af, wf, xf, o->fp);
                e[0] = fog_dens_err(p->g, p->g2, p->a, p->w, ue, o->de, 0);
                e[1] = fog_dens_err(p->g, p->g2, p->a, p->w, ue, o->dpe, 0);
                e[2] = fog_dens_err(gf, g2f, af, wf, uef, o->fe, 1);
                e[3] = fog_dens_err(gf, g2f, af, wf, uef, o->fpe, 1);
                for (k = 0; k < 4; ++k) if (e[k] > dmax[s][k][kd]) dmax[s][k][kd] = e[k];
            }
        } else
        for (s = 0; s < 2; ++s) {
            const gp_out *o = s == 0 ? &dev[i] : &host[i];
            double e[4];
            check_sample(s == 0, 0, kd, p->g, p->a, p->xi, o->ds, 0);
            check_sample(s == 0, 1, kd, p->g, p->a, p->xi, o->dp, 0);
            check_sample(s == 0, 2, kd, gf, af, xf, o->fs, 1);
            check_sample(s == 0, 3, kd, gf, af, xf, o->fp, 1);
            e[0] = dens_err(kd, p->g, p->a, ue, o->de, 0);
            e[1] = dens_err(kd, p->g, p->a, ue, o->dpe, 0);
            e[2] = dens_err(kd, gf, af, uef, o->fe, 1);
            e[3] = dens_err(kd, gf, af, uef, o->fpe, 1);
            for (k = 0; k < 4; ++k) if (e[k] > dmax[s][k][kd]) dmax[s][k][kd] = e[k];
        }
        {   /* directions (the sample's bar in absolute terms bounds cos - u) */
            double ubd = fabs(dev[i].ds - host[i].ds), ubf = fabs((double)dev[i].fs - host[i].fs);
            double fwo[3] = { dev[i].fwo[0], dev[i].fwo[1], dev[i].fwo[2] };
            check_dir(p, dev[i].dwo, dev[i].ds, dev[i].dpdf, ubd, 0, &bad_dir);
            check_dir(p, fwo, dev[i].fs, dev[i].fpdf, ubf, 1, &bad_dir);
        }
        ++nf;
        equal_f += dev[i].fs == host[i].fs;
        equal_fp += dev[i].fp == host[i].fp;
    }
    /* bad and edge input */
    for (i = (size_t)h.nrand; i < n; ++i)
        if (!control || i % 97 == 0) compare_all(&in[i], &dev[i], &host[i], &bad_cmp);
    /* batches */
    for (j = 0; j < (size_t)h.nc; ++j) {
        int kd = ch[j].kind;
        float gf = (float)ch[j].g, af = (float)ch[j].a;
        for (i = j * h.ch; i < (j + 1) * h.ch; ++i)
            for (s = 0; s < 2 && (!control || i % 97 == 0); ++s) {
                check_sample(s == 0, 4, kd, ch[j].g, ch[j].a, cxi[i], bd[s][i], 0);
                check_sample(s == 0, 5, kd, ch[j].g, ch[j].a, cxi[i], bpd[s][i], 0);
                check_sample(s == 0, 6, kd, gf, af, (float)cxi[i], bf[s][i], 1);
                check_sample(s == 0, 7, kd, gf, af, (float)cxi[i], bpf[s][i], 1);
            }
    }
    mt_check(bad_cmp == 0, "%ld answers to bad input or of the fog differ from the host's",
             bad_cmp);

    printf("\nworst sample against its bar (<= 1 passes)\n%-24s %10s %10s\n", "", "device",
           "host");
    for (k = 0; k < 10; ++k) printf("%-24s %10.3f %10.3f\n", wname[k], worst[0][k], worst[1][k]);
    printf("float samples equal to the host's: %.4f scalar, %.4f prepared\n",
           (double)equal_f / nf, (double)equal_fp / nf);
    printf("\nworst density error in eps (device / host)\n%-10s %15s %15s %15s %15s\n", "",
           "double", "double prep", "float", "float prep");
    for (k = 0; k < 5; ++k) {
        printf("%-10s", kname[k]);
        for (s = 0; s < 4; ++s) printf(" %7.1f/%-7.1f", dmax[0][s][k], dmax[1][s][k]);
        printf("\n");
    }
    for (k = 0; k < 5; ++k)
        for (s = 0; s < 4; ++s)
            mt_check(dmax[0][s][k] <= 2 * dmax[1][s][k] + 8, "%s density (%d): device %.1f eps, "
                     "host %.1f", kname[k], s, dmax[0][s][k], dmax[1][s][k]);
    printf("directions off: %ld; answers differing from the host's: %ld\n", bad_dir, bad_cmp);
    if (control) {
        printf("control: %d checks failed on the moved answers (must be > 0)\n", mt_failed);
        return mt_failed > 0 ? 0 : 1;
    }
    return mt_done("gpu_check");
}
