/* mist_render.c - a small CPU renderer of fog with mist: images of what the
 * phase functions, the analytic height fog and the droplet size change.
 *
 *   mist_render phase [options]   a fog slab lit by the sun, volumetric
 *       path tracing (multiple scattering, up to 12 bounces) with mist's
 *       exact samplers, one panel per phase function at one droplet size
 *       (d = 10 um): HG with the Lorenz-Mie asymmetry, Cornette-Shanks with
 *       it, the Draine lobe of the Jendersie-d'Eon fit, the fit itself (the
 *       fog mix, mist_fog_from_diameter) and a tabulated Lorenz-Mie RGB
 *       phase function (mist_tab, built from mist_mie_average at 650, 550
 *       and 450 nm).  Top row: the sun behind the camera (the glory at the
 *       antisolar point, the fogbow 35-42 degrees from it: only the Mie
 *       table has them); bottom row: the sun in front, behind the fog (the
 *       forward peak).
 *   mist_render hfog [options]    a ground, three spheres, sun and sky,
 *       seen through the analytic height fog (mist_hfog_apply per pixel),
 *       beside a ray-marched reference of the same integrals (midpoint
 *       rule, 2048 steps a ray) and their difference x 10^4; prints the
 *       difference and the time of each.
 *   mist_render size [options]    the phase scene with the Jendersie-d'Eon
 *       fit at d = 0.1, 2, 10 and 50 um, each channel's scattering
 *       coefficient from Lorenz-Mie (its cross section at 650, 550, 450 nm,
 *       the green optical depth the same): fog colour and halo.
 * Options:
 *   -o FILE        the PNG (default: mist_render_SCENE.png beside the
 *                  program, examples/beside.h); FILE.pfm gets the linear
 *                  HDR image too (with --pfm)
 *   --pfm          also write the linear image as PFM (FILE with .pfm)
 *   -q Q           quality: samples (and the reference's steps) times Q
 *   -r R           resolution times R
 *   -t N           threads (default: 2)
 * A progress line goes to stderr for anything longer than a second.
 *
 * Build and run (from the repository root):
 *   cmake -S . -B build && cmake --build build --target mist_render
 *   ./build/mist_render phase -o docs/render_phase.png
 * or without CMake:
 *   cc -std=c99 -O2 -Iinclude examples/mist_render.c -o mist_render -lm -lpthread */
#if !defined(_POSIX_C_SOURCE) && (defined(__unix__) || defined(__APPLE__))
#  define _POSIX_C_SOURCE 200809L       /* clock_gettime, pthreads */
#endif
#include "mist.h"
#include "mist_mie.h"
#include "beside.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#if defined(__unix__) || defined(__APPLE__)
#  include <unistd.h>
#endif
#if defined(_POSIX_THREADS) && _POSIX_THREADS > 0 && !defined(MIST_RENDER_NO_THREADS)
#  include <pthread.h>
#  define HAVE_THREADS 1
#endif

#define PI 3.14159265358979323846

/* ------------------------------------------------------------------------ */
/* Time                                                                     */
/* ------------------------------------------------------------------------ */
static double now(void)
{
#if defined(_POSIX_TIMERS) && _POSIX_TIMERS > 0
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
#else
    return (double)clock() / CLOCKS_PER_SEC;
#endif
}

/* ------------------------------------------------------------------------ */
/* PNG: 8-bit RGB, zlib stream of stored (uncompressed) deflate blocks.     */
/* ------------------------------------------------------------------------ */
static unsigned long crc_table[256];

static void crc_init(void)
{
    unsigned long c;
    int n, k;
    for (n = 0; n < 256; ++n) {
        c = (unsigned long)n;
        for (k = 0; k < 8; ++k) c = c & 1 ? 0xedb88320UL ^ (c >> 1) : c >> 1;
        crc_table[n] = c;
    }
}

/* CRC-32 (ISO 3309, PNG's), continued from crc */
static unsigned long crc32_of(unsigned long crc, const unsigned char *b, size_t n)
{
    size_t i;
    crc ^= 0xffffffffUL;
    for (i = 0; i < n; ++i) crc = crc_table[(crc ^ b[i]) & 0xff] ^ (crc >> 8);
    return crc ^ 0xffffffffUL;
}

static void put32(unsigned char *p, unsigned long v)
{
    p[0] = (unsigned char)(v >> 24); p[1] = (unsigned char)(v >> 16);
    p[2] = (unsigned char)(v >> 8); p[3] = (unsigned char)v;
}

static int chunk(FILE *f, const char *type, const unsigned char *data, size_t n)
{
    unsigned char h[8];
    unsigned long crc;
    put32(h, (unsigned long)n);
    memcpy(h + 4, type, 4);
    crc = crc32_of(0, h + 4, 4);
    crc = crc32_of(crc, data, n);
    if (fwrite(h, 1, 8, f) != 8 || (n && fwrite(data, 1, n, f) != n)) return -1;
    put32(h, crc);
    return fwrite(h, 1, 4, f) == 4 ? 0 : -1;
}

/* writes w x h 8-bit RGB pixels (rows top first); 0 or -1 */
static int png_write(const char *path, const unsigned char *rgb, int w, int h)
{
    static const unsigned char sig[8] = { 137, 80, 78, 71, 13, 10, 26, 10 };
    size_t row = (size_t)w * 3 + 1, raw = row * (size_t)h;
    size_t blocks = (raw + 65534) / 65535, n = 2 + raw + 5 * blocks + 4, i, o = 0;
    unsigned char *z = (unsigned char *)malloc(n), ihdr[13];
    unsigned long a = 1, b = 0;          /* Adler-32 */
    FILE *f;
    int ok;
    if (!z) return -1;
    z[o++] = 0x78; z[o++] = 0x01;        /* zlib: deflate, 32K window, no dictionary */
    for (i = 0; i < raw; ) {
        size_t len = raw - i < 65535 ? raw - i : 65535, k;
        z[o++] = (unsigned char)(i + len == raw);           /* BFINAL, BTYPE 00 */
        z[o++] = (unsigned char)len; z[o++] = (unsigned char)(len >> 8);
        z[o++] = (unsigned char)~len; z[o++] = (unsigned char)(~len >> 8);
        for (k = 0; k < len; ++k, ++i) {
            size_t yy = i / row, xx = i % row;
            unsigned char v = xx == 0 ? 0 : rgb[yy * (size_t)w * 3 + xx - 1];   /* filter 0 */
            z[o++] = v;
            a = (a + v) % 65521; b = (b + a) % 65521;
        }
    }
    put32(z + o, (b << 16) | a); o += 4;
    put32(ihdr, (unsigned long)w); put32(ihdr + 4, (unsigned long)h);
    ihdr[8] = 8; ihdr[9] = 2; ihdr[10] = ihdr[11] = ihdr[12] = 0;  /* 8-bit RGB */
    f = fopen(path, "wb");
    if (!f) { free(z); return -1; }
    ok = fwrite(sig, 1, 8, f) == 8 && chunk(f, "IHDR", ihdr, 13) == 0
         && chunk(f, "IDAT", z, o) == 0 && chunk(f, "IEND", NULL, 0) == 0;
    ok = (fclose(f) == 0) && ok;
    free(z);
    return ok ? 0 : -1;
}

/* PFM: linear float RGB, rows bottom first, little-endian (scale -1) */
static int pfm_write(const char *path, const float *img, int w, int h)
{
    FILE *f = fopen(path, "wb");
    int y, ok = 1;
    unsigned one = 1;
    if (!f) return -1;
    fprintf(f, "PF\n%d %d\n%s\n", w, h, *(const unsigned char *)&one ? "-1.0" : "1.0");
    for (y = h - 1; y >= 0; --y)
        if (fwrite(img + (size_t)y * w * 3, sizeof(float), (size_t)w * 3, f) != (size_t)w * 3)
            ok = 0;
    return (fclose(f) == 0 && ok) ? 0 : -1;
}

/* exposure, 1 - e^-x, sRGB's curve, 8 bits */
static void tonemap(const float *img, unsigned char *out, size_t n, double exposure)
{
    size_t i;
    for (i = 0; i < n; ++i) {
        double x = 1 - exp(-exposure * (img[i] > 0 ? img[i] : 0));
        x = x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1 / 2.4) - 0.055;
        out[i] = (unsigned char)(x * 255 + 0.5);
    }
}

/* ------------------------------------------------------------------------ */
/* Rows over threads, with a progress line                                  */
/* ------------------------------------------------------------------------ */
typedef void (*pixel_fn)(const void *ctx, int x, int y, float *rgb);

typedef struct job {
    const void *ctx;
    pixel_fn fn;
    float *img;
    int w, h, next, done;
    double t0, shown;
    const char *label;
    int printed;
#ifdef HAVE_THREADS
    pthread_mutex_t lock;
#endif
} job;

static void *worker(void *arg)
{
    job *j = (job *)arg;
    for (;;) {
        int y, x;
#ifdef HAVE_THREADS
        pthread_mutex_lock(&j->lock);
#endif
        y = j->next < j->h ? j->next++ : -1;
#ifdef HAVE_THREADS
        pthread_mutex_unlock(&j->lock);
#endif
        if (y < 0) break;
        for (x = 0; x < j->w; ++x) j->fn(j->ctx, x, y, j->img + ((size_t)y * j->w + x) * 3);
#ifdef HAVE_THREADS
        pthread_mutex_lock(&j->lock);
#endif
        ++j->done;
        if (now() - j->t0 > 1 && (now() - j->shown > 0.5 || j->done == j->h)) {
            j->shown = now();
            fprintf(stderr, "\r%s: %3d%% (%.1f s)", j->label, 100 * j->done / j->h,
                    now() - j->t0);
            j->printed = 1;
        }
#ifdef HAVE_THREADS
        pthread_mutex_unlock(&j->lock);
#endif
    }
    return NULL;
}

static int nthreads = 2;

/* renders fn into img (w x h); returns the seconds it took */
static double render(const void *ctx, pixel_fn fn, float *img, int w, int h, const char *label)
{
    job j;
    j.ctx = ctx; j.fn = fn; j.img = img; j.w = w; j.h = h; j.next = j.done = 0;
    j.label = label; j.printed = 0; j.t0 = now(); j.shown = 0;
#ifdef HAVE_THREADS
    {
        pthread_t th[64];
        int i, n = nthreads < 1 ? 1 : nthreads > 64 ? 64 : nthreads, started = 0;
        pthread_mutex_init(&j.lock, NULL);
        for (i = 1; i < n; ++i)
            if (pthread_create(&th[started], NULL, worker, &j) == 0) ++started;
        worker(&j);
        for (i = 0; i < started; ++i) pthread_join(th[i], NULL);
        pthread_mutex_destroy(&j.lock);
    }
#else
    worker(&j);
#endif
    if (j.printed) fprintf(stderr, "\n");
    return now() - j.t0;
}

/* ------------------------------------------------------------------------ */
/* Random numbers: a counter hash per pixel and sample (the image does not  */
/* depend on the thread count)                                              */
/* ------------------------------------------------------------------------ */
typedef struct { unsigned long long s; } rng;

static double rnd(rng *r)
{
    unsigned long long z = (r->s += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    return (double)(z >> 11) * (1.0 / 9007199254740992.0);
}

static rng rng_at(int x, int y, int s, int salt)
{
    rng r;
    r.s = ((unsigned long long)(unsigned)y << 40) ^ ((unsigned long long)(unsigned)x << 20)
          ^ (unsigned long long)(unsigned)s ^ ((unsigned long long)(unsigned)salt << 60);
    rnd(&r);
    return r;
}

static mist_vec3 v3(double x, double y, double z) { mist_vec3 v; v.x = x; v.y = y; v.z = z; return v; }
static double dot(mist_vec3 a, mist_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static mist_vec3 add(mist_vec3 a, mist_vec3 b, double t)
{
    return v3(a.x + t * b.x, a.y + t * b.y, a.z + t * b.z);
}

/* ------------------------------------------------------------------------ */
/* Phase functions: mist's prepared ones, or a table with RGB channels      */
/* ------------------------------------------------------------------------ */
typedef struct phasefn {
    mist_phase ph;
    const mist_tab *tab;        /* non-NULL: the table */
} phasefn;

/* the density at u per channel */
static void phase_eval(const phasefn *p, double u, double *f)
{
    if (p->tab) { mist_tab_eval(p->tab, u, f); return; }
    f[0] = f[1] = f[2] = mist_phase_eval(&p->ph, u);
}

static mist_vec3 phase_sample(const phasefn *p, mist_vec3 w, double x1, double x2, double *pdf)
{
    return p->tab ? mist_tab_sample_dir(p->tab, w, x1, x2, pdf)
                  : mist_phase_sample_dir(&p->ph, w, x1, x2, pdf);
}

/* ------------------------------------------------------------------------ */
/* The fog slab: z in [Z0, Z1], extinction = scattering sigma[c] (water     */
/* absorbs nothing in the visible), camera at the origin looking along +z,  */
/* sun and a uniform sky.  Spectral tracking [Kutz et al. 2017] with the    */
/* majorant max sigma; next-event estimation of the sun (a delta light,     */
/* analytic transmittance); the sky by escaping paths.                      */
/* ------------------------------------------------------------------------ */
#define Z0 1.0
#define Z1 2.0
#define MAXB 12
#define SPP 128                 /* paths a pixel at quality 1 */

typedef struct slab {
    phasefn phase;
    double sigma[3];
    mist_vec3 sun;              /* towards the sun */
    double sun_e[3], sky[3];
    double tanfov;              /* half the field of view's tangent */
    int w, h, spp;              /* the panel */
} slab;

/* distance along w from p to the slab's far side (p inside) */
static double slab_exit(mist_vec3 p, mist_vec3 w)
{
    if (w.z > 1e-12) return (Z1 - p.z) / w.z;
    if (w.z < -1e-12) return (Z0 - p.z) / w.z;
    return 1e30;
}

static void slab_path(const slab *s, mist_vec3 w, rng *r, double *L)
{
    double beta[3] = { 1, 1, 1 }, smax = s->sigma[0], t0;
    mist_vec3 p;
    int c, b = 0;
    if (s->sigma[1] > smax) smax = s->sigma[1];
    if (s->sigma[2] > smax) smax = s->sigma[2];
    L[0] = L[1] = L[2] = 0;
    if (w.z <= 0) { for (c = 0; c < 3; ++c) L[c] = s->sky[c]; return; }
    t0 = Z0 / w.z;
    p = add(v3(0, 0, 0), w, t0);
    for (;;) {
        double t = -log(1 - rnd(r)) / smax, d = slab_exit(p, w);
        if (t >= d) {                         /* leaves: the sky */
            for (c = 0; c < 3; ++c) L[c] += beta[c] * s->sky[c];
            return;
        }
        p = add(p, w, t);
        {   /* real or null collision: probability the mean real share */
            double pr = (s->sigma[0] + s->sigma[1] + s->sigma[2]) / (3 * smax);
            if (rnd(r) >= pr) {
                for (c = 0; c < 3; ++c) beta[c] *= (smax - s->sigma[c]) / (smax * (1 - pr));
                continue;
            }
            for (c = 0; c < 3; ++c) beta[c] *= s->sigma[c] / (smax * pr);
        }
        {   /* the sun: phase at u = w . sun, transmittance to the slab's side */
            double f[3] = { 0, 0, 0 }, u = dot(w, s->sun), ds = slab_exit(p, s->sun);
            phase_eval(&s->phase, u, f);
            for (c = 0; c < 3; ++c)
                L[c] += beta[c] * f[c] * s->sun_e[c] * exp(-s->sigma[c] * ds);
        }
        if (++b > MAXB) return;
        {   /* the next direction: weight density / pdf */
            double f[3] = { 0, 0, 0 }, pdf, x1 = rnd(r), x2 = rnd(r);
            mist_vec3 wo = phase_sample(&s->phase, w, x1, x2, &pdf);
            if (!(pdf > 0) || pdf > 1e300) return;
            phase_eval(&s->phase, dot(w, wo), f);
            for (c = 0; c < 3; ++c) beta[c] *= f[c] / pdf;
            w = wo;
        }
    }
}

static void slab_pixel(const void *ctx, int x, int y, float *out)
{
    const slab *s = (const slab *)ctx;
    double acc[3] = { 0, 0, 0 }, L[3];
    int i, c;
    for (i = 0; i < s->spp; ++i) {
        rng r = rng_at(x, y, i, 1);
        double px = (2 * (x + rnd(&r)) / s->w - 1) * s->tanfov;
        double py = (1 - 2 * (y + rnd(&r)) / s->h) * s->tanfov;
        mist_vec3 w = mist_normalize(v3(px, py, 1));
        slab_path(s, w, &r, L);
        for (c = 0; c < 3; ++c) acc[c] += L[c];
    }
    for (c = 0; c < 3; ++c) out[c] = (float)(acc[c] / s->spp);
}

/* copies a panel into the image at (ox, oy) */
static void blit(float *img, int iw, const float *p, int pw, int ph, int ox, int oy)
{
    int y;
    for (y = 0; y < ph; ++y)
        memcpy(img + (((size_t)(oy + y) * iw) + ox) * 3, p + (size_t)y * pw * 3,
               sizeof(float) * 3 * (size_t)pw);
}

static int quality = 1, resf = 1, want_pfm = 0;
static const char *outpath = NULL;
static char outbuf[4096];

/* the PNG (tone mapped: the image's rows in nb equal bands, band i at
 * exposure ex[i]) and with --pfm the linear image */
static int save(const char *scene, const char *argv0, const float *img, int w, int h,
                const double *ex, int nb)
{
    char name[64];
    unsigned char *b = (unsigned char *)malloc((size_t)w * h * 3);
    const char *path;
    int rc;
    if (!b) return -1;
    snprintf(name, sizeof name, "mist_render_%s.png", scene);
    path = outpath ? outpath : beside_program(outbuf, sizeof outbuf, argv0, name);
    {
        int i;
        size_t band = (size_t)w * (size_t)(h / nb) * 3;
        for (i = 0; i < nb; ++i) tonemap(img + i * band, b + i * band, band, ex[i]);
    }
    rc = png_write(path, b, w, h);
    free(b);
    if (rc) { fprintf(stderr, "cannot write %s\n", path); return -1; }
    printf("wrote %s (%d x %d)\n", path, w, h);
    if (want_pfm) {
        char pf[4200];
        size_t n = strlen(path);
        if (n > 4 && strcmp(path + n - 4, ".png") == 0) n -= 4;
        snprintf(pf, sizeof pf, "%.*s.pfm", (int)n, path);
        if (pfm_write(pf, img, w, h)) { fprintf(stderr, "cannot write %s\n", pf); return -1; }
        printf("wrote %s\n", pf);
    }
    return 0;
}

/* a Lorenz-Mie table at 650, 550, 450 nm (channels R, G, B) for water
 * droplets of diameter d (lognormal, geometric width 1.1), n nodes uniform
 * in theta; *g the asymmetry (mean of the channels), cs[c] the cross
 * sections.  NULL where it fails. */
static mist_tab *mie_table(double d, size_t n, double *g, double *cs)
{
    static const double lam[3] = { 650, 550, 450 };
    double *mu = (double *)malloc(sizeof(double) * n), *q = (double *)malloc(sizeof(double) * n);
    double *p = (double *)malloc(sizeof(double) * n * 3);
    mist_tab *t = NULL;
    size_t i, bytes = mist_tab_bytes(n, 3);
    int c;
    if (!mu || !q || !p) goto out;
    mist_mie_theta_grid(n, q);                      /* descending from 1 */
    for (i = 0; i < n; ++i) mu[i] = q[n - 1 - i];
    *g = 0;
    for (c = 0; c < 3; ++c) {
        mist_mie_dist dist = mist_mie_dist_lognormal(d / 2, 1.1);
        mist_mie_wavelength wl = mist_mie_wl(lam[c] / 1000, 1, mist_mie_water(lam[c], NULL));
        mist_mie_avg a = mist_mie_average(&dist, &wl, 1, 1.0, mu, n, q);
        if (a.status != MIST_MIE_OK) goto out;
        for (i = 0; i < n; ++i) p[i * 3 + c] = q[i];
        *g += a.g / 3;
        if (cs) cs[c] = a.c_sca;
    }
    t = (mist_tab *)malloc(bytes);
    if (t && mist_tab_init(t, bytes, mu, p, n, 3) != 0) { free(t); t = NULL; }
out:
    free(mu); free(q); free(p);
    return t;
}

/* ------------------------------------------------------------------------ */
/* Scene 1: the phase functions side by side                                */
/* ------------------------------------------------------------------------ */
static const double EXPO[2] = { 5.0, 1.2 };   /* per row: the sun behind, in front */

static void slab_lights(slab *s, int front)
{
    s->sun = front ? mist_normalize(v3(0.25, 0.2, 1)) : mist_normalize(v3(0, 0.12, -1));
    s->sun_e[0] = 3.0; s->sun_e[1] = 2.9; s->sun_e[2] = 2.7;
    s->sky[0] = 0.05; s->sky[1] = 0.08; s->sky[2] = 0.14;
}

/* One panel of a slab scene: its lights for the row, the camera, the
 * render, its time printed, and the panel copied into img at (ox, oy). */
static void slab_panel(slab *s, int row, int P, float *pan, const char *label, float *img,
                       int iw, int ox, int oy)
{
    double tt;
    slab_lights(s, row);
    s->tanfov = tan(50 * PI / 180);
    s->w = s->h = P;
    s->spp = SPP * quality;
    tt = render(s, slab_pixel, pan, P, P, label);
    printf("%-45s %6.1f s\n", label, tt);
    blit(img, iw, pan, P, P, ox, oy);
}

static int scene_phase(const char *argv0)
{
    const double d = 10;
    const int P = 96 * resf, NM = 5;
    const char *names[5] = { "HG (Mie g)", "Cornette-Shanks (Mie g)", "Draine (fit's lobe)",
                             "Jendersie-d'Eon fit", "Lorenz-Mie table RGB" };
    double g = 0, t0 = now();
    mist_tab *tab = mie_table(d, (size_t)1025 * (size_t)(quality > 4 ? 4 : quality), &g, NULL);
    mist_fog fog = mist_fog_from_diameter(d);
    float *img = (float *)calloc((size_t)P * NM * P * 2 * 3, sizeof(float));
    float *pan = (float *)malloc(sizeof(float) * 3 * (size_t)P * P);
    int m, row;
    if (!tab || !img || !pan) { fprintf(stderr, "Mie table or memory failed\n"); return 1; }
    printf("Lorenz-Mie table, d = %g um: %.1f s; asymmetry g = %.4f; fit: g_hg %.4f g_d %.4f "
           "alpha %.2f w_d %.4f\n", d, now() - t0, g, fog.g_hg, fog.g_d, fog.alpha, fog.w_d);
    for (row = 0; row < 2; ++row)
        for (m = 0; m < NM; ++m) {
            slab s;
            char label[96];
            memset(&s, 0, sizeof s);
            s.phase.tab = NULL;
            switch (m) {
            case 0: s.phase.ph = mist_phase_hg(g); break;
            case 1: s.phase.ph = mist_phase_cs(g); break;
            case 2: s.phase.ph = mist_phase_draine(fog.g_d, fog.alpha); break;
            case 3: s.phase.ph = mist_phase_fog(fog); break;
            default: s.phase.tab = tab; break;
            }
            s.sigma[0] = s.sigma[1] = s.sigma[2] = 1.0;
            snprintf(label, sizeof label, "%s, sun %s", names[m], row ? "in front" : "behind");
            slab_panel(&s, row, P, pan, label, img, P * NM, m * P, row * P);
        }
    free(pan);
    free(tab);
    m = save("phase", argv0, img, P * NM, 2 * P, EXPO, 2);
    free(img);
    return m ? 1 : 0;
}

/* ------------------------------------------------------------------------ */
/* Scene 3: the droplet size                                                */
/* ------------------------------------------------------------------------ */
static int scene_size(const char *argv0)
{
    static const double D[4] = { 0.1, 2, 10, 50 };
    static const double lam[3] = { 650, 550, 450 };
    const int P = 104 * resf;
    float *img = (float *)calloc((size_t)P * 4 * P * 2 * 3, sizeof(float));
    float *pan = (float *)malloc(sizeof(float) * 3 * (size_t)P * P);
    int k, row, c;
    if (!img || !pan) return 1;
    for (k = 0; k < 4; ++k) {
        double cs[3];
        mist_fog fog = mist_fog_from_diameter(D[k]);
        for (c = 0; c < 3; ++c) {   /* the cross sections: 2 angles are enough */
            static const double mu2[2] = { -1, 1 };
            double q[2];
            mist_mie_dist dist = mist_mie_dist_lognormal(D[k] / 2, 1.1);
            mist_mie_wavelength wl = mist_mie_wl(lam[c] / 1000, 1, mist_mie_water(lam[c], NULL));
            mist_mie_avg a = mist_mie_average(&dist, &wl, 1, 1.0, mu2, 2, q);
            if (a.status != MIST_MIE_OK) { fprintf(stderr, "Mie failed\n"); return 1; }
            cs[c] = a.c_sca;
        }
        printf("d = %g um: fit g_hg %.4f g_d %.4f alpha %.2f w_d %.4f; sigma R:G:B = "
               "%.3f : 1 : %.3f\n", D[k], fog.g_hg, fog.g_d, fog.alpha, fog.w_d, cs[0] / cs[1],
               cs[2] / cs[1]);
        for (row = 0; row < 2; ++row) {
            slab s;
            char label[96];
            memset(&s, 0, sizeof s);
            s.phase.ph = mist_phase_fog(fog);
            for (c = 0; c < 3; ++c) s.sigma[c] = cs[c] / cs[1];
            snprintf(label, sizeof label, "fit d = %g um, sun %s", D[k], row ? "in front" : "behind");
            slab_panel(&s, row, P, pan, label, img, P * 4, k * P, row * P);
        }
    }
    free(pan);
    k = save("size", argv0, img, P * 4, 2 * P, EXPO, 2);
    free(img);
    return k ? 1 : 0;
}

/* ------------------------------------------------------------------------ */
/* Scene 2: the height fog, analytic and ray-marched                        */
/* ------------------------------------------------------------------------ */
typedef struct hscene {
    mist_hfog fog;
    int w, h, steps, mode;      /* mode 0 analytic, 1 marched */
    mist_vec3 cam, fwd, right, up;
    double tanfov;
} hscene;

static const double SPH[3][4] = { { -6, 2, 30, 2 }, { 3, 3, 45, 3 }, { 14, 5, 80, 5 } };
static const double SPC[3][3] = { { 0.7, 0.2, 0.15 }, { 0.2, 0.5, 0.7 }, { 0.8, 0.8, 0.8 } };

/* nearest hit of the ground (y = 0) and the spheres: distance (+inf for
 * the sky), normal, albedo */
static double trace(mist_vec3 o, mist_vec3 d, mist_vec3 *n, double *alb)
{
    double best = HUGE_VAL;
    int i;
    if (d.y < 0) {
        double t = -o.y / d.y;
        mist_vec3 p = add(o, d, t);
        int chk = ((int)floor(p.x / 4) + (int)floor(p.z / 4)) & 1;
        best = t; *n = v3(0, 1, 0);
        alb[0] = alb[1] = alb[2] = chk ? 0.45 : 0.25;
        alb[1] += 0.05;
    }
    for (i = 0; i < 3; ++i) {
        mist_vec3 oc = v3(o.x - SPH[i][0], o.y - SPH[i][1], o.z - SPH[i][2]);
        double b = dot(oc, d), c = dot(oc, oc) - SPH[i][3] * SPH[i][3], disc = b * b - c;
        if (disc > 0) {
            double t = -b - sqrt(disc);
            if (t > 1e-6 && t < best) {
                mist_vec3 p = add(o, d, t);
                best = t;
                *n = v3((p.x - SPH[i][0]) / SPH[i][3], (p.y - SPH[i][1]) / SPH[i][3],
                        (p.z - SPH[i][2]) / SPH[i][3]);
                alb[0] = SPC[i][0]; alb[1] = SPC[i][1]; alb[2] = SPC[i][2];
            }
        }
    }
    return best;
}

/* the background radiance along the ray: a lit surface, or the sky */
static mist_rgb background(const hscene *s, mist_vec3 d, double *len)
{
    mist_vec3 n;
    double alb[3], t = trace(s->cam, d, &n, alb);
    mist_rgb B;
    *len = t;
    if (t == HUGE_VAL) {
        double k = d.y > 0 ? d.y : 0;
        B.r = 0.35 + 0.1 * (1 - k); B.g = 0.5 + 0.1 * (1 - k); B.b = 0.8;
        return B;
    } else {
        mist_vec3 p = add(add(s->cam, d, t), n, 1e-6), n2;
        double alb2[3], cosl = dot(n, s->fog.sun_dir), sh;
        sh = cosl > 0 && trace(p, s->fog.sun_dir, &n2, alb2) == HUGE_VAL ? cosl : 0;
        B.r = alb[0] / PI * (s->fog.sun.r * sh + PI * 0.45);
        B.g = alb[1] / PI * (s->fog.sun.g * sh + PI * 0.55);
        B.b = alb[2] / PI * (s->fog.sun.b * sh + PI * 0.75);
        return B;
    }
}

/* the reference: the same integrals [I18 eq. 12-13, with the dimmed sun]
 * by the midpoint rule on `steps` steps (graded, below), the column C(t) summed
 * along; a ray to infinity ends where the density has fallen by e^-40
 * or the optical depth has passed 40 (bounded from the density alone) */
static mist_rgb march(const mist_hfog *f, mist_vec3 o, mist_vec3 d, double len, int steps,
                      mist_rgb B)
{
    double st[3], ssR[3], ssM[3], E[3], La[3], L[3] = { 0, 0, 0 }, T[3], C = 0, dt;
    double u = dot(f->sun_dir, d), pR = mist_rayleigh_eval(u), pM = mist_fog_eval(f->mie_phase, u);
    double ly = f->sun_dir.y, H = f->scale_height;
    mist_rgb out;
    int i, c;
    st[0] = f->rayleigh_ext.r + f->mie_ext.r; st[1] = f->rayleigh_ext.g + f->mie_ext.g;
    st[2] = f->rayleigh_ext.b + f->mie_ext.b;
    ssR[0] = f->rayleigh_scat.r; ssR[1] = f->rayleigh_scat.g; ssR[2] = f->rayleigh_scat.b;
    ssM[0] = f->mie_scat.r; ssM[1] = f->mie_scat.g; ssM[2] = f->mie_scat.b;
    E[0] = f->sun.r; E[1] = f->sun.g; E[2] = f->sun.b;
    La[0] = f->ambient.r; La[1] = f->ambient.g; La[2] = f->ambient.b;
    if (!(len < HUGE_VAL)) {
        double smin = st[0] < st[1] ? st[0] : st[1], r0 = f->density * exp(-(o.y - f->base) / H);
        if (st[2] < smin) smin = st[2];
        if (d.y > 1e-9) {   /* rising: the density falls along the ray */
            double top = (o.y > f->base ? o.y : f->base) + 40 * H;
            len = (top - o.y) / d.y;
            /* the depth to L/2 is at least that of the density at L/2:
             * above 40, all beyond L/2 is dimmed by e^-40 */
            while (smin * f->density * exp(-(o.y + d.y * len / 2 - f->base) / H) * len / 2 > 40)
                len /= 2;
        } else {            /* level or falling: the density never falls below r0 */
            len = 40 / (smin * r0);
        }
    }
    for (i = 0; i < steps; ++i) {
        /* steps graded as t = len s^2, s uniform: fine near the camera,
         * where the density is highest on a rising ray */
        double s0 = (double)i / steps, s1 = (double)(i + 1) / steps;
        double y = o.y + len * (s0 * s0 + s1 * s1) / 2 * d.y, r = f->density * exp(-(y - f->base) / H);
        dt = len * (s1 * s1 - s0 * s0);
        double Cm = C + r * dt / 2;
        for (c = 0; c < 3; ++c) {
            double sun = ly > 0 ? (ssR[c] * pR + ssM[c] * pM) * E[c]
                                  * exp(-st[c] * (Cm + r * H / ly)) : 0;
            L[c] += dt * r * (sun + (ssR[c] + ssM[c]) * La[c] * exp(-st[c] * Cm));
        }
        C += r * dt;
    }
    for (c = 0; c < 3; ++c) T[c] = exp(-st[c] * C);
    out.r = B.r * T[0] + L[0]; out.g = B.g * T[1] + L[1]; out.b = B.b * T[2] + L[2];
    return out;
}

typedef struct hctx {
    hscene s;
    mist_rgb *B;
    double *len;
} hctx;

static mist_vec3 hdir(const hscene *s, int x, int y)
{
    double px = (2 * (x + 0.5) / s->w - 1) * s->tanfov * s->w / s->h;
    double py = (1 - 2 * (y + 0.5) / s->h) * s->tanfov;
    return mist_normalize(v3(s->fwd.x + px * s->right.x + py * s->up.x,
                             s->fwd.y + px * s->right.y + py * s->up.y,
                             s->fwd.z + px * s->right.z + py * s->up.z));
}

static void h_background(const void *ctx, int x, int y, float *out)
{
    const hctx *h = (const hctx *)ctx;
    size_t i = (size_t)y * h->s.w + x;
    h->B[i] = background(&h->s, hdir(&h->s, x, y), &h->len[i]);
    out[0] = (float)h->B[i].r; out[1] = (float)h->B[i].g; out[2] = (float)h->B[i].b;
}

static void h_fog(const void *ctx, int x, int y, float *out)
{
    const hctx *h = (const hctx *)ctx;
    size_t i = (size_t)y * h->s.w + x;
    mist_vec3 d = hdir(&h->s, x, y);
    mist_rgb c = h->s.mode ? march(&h->s.fog, h->s.cam, d, h->len[i], h->s.steps, h->B[i])
                           : mist_hfog_apply(&h->s.fog, h->s.cam, d, h->len[i], h->B[i]);
    out[0] = (float)c.r; out[1] = (float)c.g; out[2] = (float)c.b;
}

static int scene_hfog(const char *argv0)
{
    const int W = 192 * resf, Hh = 108 * resf;
    size_t n = (size_t)W * Hh, i;
    hctx h;
    float *a = (float *)malloc(sizeof(float) * 3 * n), *m = (float *)malloc(sizeof(float) * 3 * n);
    float *img = (float *)malloc(sizeof(float) * 9 * n);
    double ta, tm, tb, maxd = 0, maxv = 0, s2 = 0, s1 = 0;
    int y;
    memset(&h, 0, sizeof h);
    h.B = (mist_rgb *)malloc(sizeof(mist_rgb) * n);
    h.len = (double *)malloc(sizeof(double) * n);
    if (!a || !m || !img || !h.B || !h.len) return 1;
    h.s.w = W; h.s.h = Hh;
    h.s.steps = 2048 * quality;
    h.s.cam = v3(0, 2, 0);
    h.s.fwd = mist_normalize(v3(0, -0.04, 1));
    h.s.right = v3(1, 0, 0);
    h.s.up = v3(0, h.s.fwd.z, -h.s.fwd.y);      /* fwd x right */
    h.s.tanfov = tan(22 * PI / 180);
    h.s.fog.base = 0;
    h.s.fog.density = 1;
    h.s.fog.scale_height = 6;
    h.s.fog.rayleigh_scat.r = 0.0008; h.s.fog.rayleigh_scat.g = 0.0017;
    h.s.fog.rayleigh_scat.b = 0.0040;
    h.s.fog.rayleigh_ext = h.s.fog.rayleigh_scat;
    h.s.fog.mie_scat.r = h.s.fog.mie_scat.g = h.s.fog.mie_scat.b = 0.025;
    h.s.fog.mie_ext = h.s.fog.mie_scat;
    h.s.fog.mie_phase = mist_fog_from_diameter(10);
    h.s.fog.sun_dir = mist_normalize(v3(-0.35, 0.3, 1));
    h.s.fog.sun.r = 3.2; h.s.fog.sun.g = 3.0; h.s.fog.sun.b = 2.7;
    h.s.fog.ambient.r = 0.35; h.s.fog.ambient.g = 0.45; h.s.fog.ambient.b = 0.65;
    h.s.fog.sun_extinction = 1;
    tb = render(&h, h_background, a, W, Hh, "background");
    h.s.mode = 0;
    ta = render(&h, h_fog, a, W, Hh, "analytic height fog");
    h.s.mode = 1;
    tm = render(&h, h_fog, m, W, Hh, "ray-marched reference");
    for (i = 0; i < 3 * n; ++i) {
        double dd = fabs((double)a[i] - m[i]);
        if (dd > maxd) maxd = dd;
        if (m[i] > maxv) maxv = m[i];
        s2 += dd * dd; s1 += m[i];
    }
    printf("%d x %d pixels; background (ray casting, shading): %.3f s\n", W, Hh, tb);
    printf("analytic (mist_hfog_apply):      %.4f s, %.0f ns a pixel\n", ta, 1e9 * ta / n);
    printf("ray-marched (%d steps a ray):  %.4f s, %.0f ns a pixel (%.0fx the analytic)\n",
           h.s.steps, tm, 1e9 * tm / n, tm / ta);
    printf("difference: max %.3g (%.2g of the largest value), RMS %.3g (%.2g of the mean)\n",
           maxd, maxd / maxv, sqrt(s2 / (3 * n)), sqrt(s2 / (3 * n)) / (s1 / (3 * n)));
    for (y = 0; y < Hh; ++y) {
        int x, c;
        for (x = 0; x < W; ++x)
            for (c = 0; c < 3; ++c) {
                size_t k = ((size_t)y * W + x) * 3 + c;
                img[((size_t)y * 3 * W + x) * 3 + c] = a[k];
                img[((size_t)y * 3 * W + W + x) * 3 + c] = m[k];
                img[((size_t)y * 3 * W + 2 * W + x) * 3 + c] = (float)(1e4 * fabs((double)a[k] - m[k]));
            }
    }
    free(a); free(m); free(h.B); free(h.len);
    {
        static const double ex = 1.0;
        y = save("hfog", argv0, img, 3 * W, Hh, &ex, 1);
    }
    free(img);
    return y ? 1 : 0;
}

static int usage(void)
{
    fprintf(stderr, "usage: mist_render phase|hfog|size [-o FILE.png] [--pfm] [-q QUALITY] "
            "[-r RESOLUTION] [-t THREADS]\n");
    return 2;
}

int main(int argc, char **argv)
{
    const char *scene;
    int i;
    double t0 = now();
    if (argc < 2) return usage();
    scene = argv[1];
    for (i = 2; i < argc; ++i) {
        if (!strcmp(argv[i], "-o") && i + 1 < argc) outpath = argv[++i];
        else if (!strcmp(argv[i], "--pfm")) want_pfm = 1;
        else if (!strcmp(argv[i], "-q") && i + 1 < argc) quality = atoi(argv[++i]);
        else if (!strcmp(argv[i], "-r") && i + 1 < argc) resf = atoi(argv[++i]);
        else if (!strcmp(argv[i], "-t") && i + 1 < argc) nthreads = atoi(argv[++i]);
        else return usage();
    }
    if (quality < 1 || quality > 1000 || resf < 1 || resf > 16 || nthreads < 1) return usage();
#ifndef HAVE_THREADS
    nthreads = 1;
#endif
    crc_init();
    if (!strcmp(scene, "phase")) i = scene_phase(argv[0]);
    else if (!strcmp(scene, "hfog")) i = scene_hfog(argv[0]);
    else if (!strcmp(scene, "size")) i = scene_size(argv[0]);
    else return usage();
    printf("total %.1f s, %d thread%s\n", now() - t0, nthreads, nthreads > 1 ? "s" : "");
    return i;
}
