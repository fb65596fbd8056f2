/* test_mie_fastmath.c - include/mist_mie.h built with -O2 -ffast-math
 * -DMIST_ALLOW_FAST_MATH (CMakeLists.txt; with AddressSanitizer where the
 * compiler has it): the opt-out may give wrong numbers, but no input may
 * make mist write outside the memory it was given, or loop without end.
 * -ffinite-math-only lets the compiler assume that no double is NaN or
 * infinite and delete the comparisons that reject them: x = NaN then
 * passed the domain check and mist_mie_sphere_make wrote before its
 * workspace (the index of D_n(x) came from (int)floor(NaN)), or hung.
 *
 * Every entry point with NaN (both signs, quiet and signalling payloads),
 * +-inf, huge, tiny and negative x, m, wavelengths, radii, n_medium and
 * weights; the workspace and the phase table sit between guard blocks
 * filled with a canary, checked after every call (this works without ASan;
 * ASan also checks mist_mie_sphere_new's, mist_mie_average's own memory
 * and mist_mie_water's table reads).  The values come from their bits
 * through a volatile, so the compiler cannot see them.  A hang is caught by
 * ctest's TIMEOUT (the whole run takes well under a second).
 * Negative control: a deliberate write one past the workspace is detected
 * by the same canary check.
 * Also mist.h, where the same pattern (a count or an index from a double)
 * appears: the height fog's exponential in 2^n parts (n doubled until
 * xh / n is in exp's range: with xh = NaN under these flags n overflowed
 * and the loop never ended: mist_hfog_eval with NaN, inf and huge
 * parameters) and the prepared Draine sampler's table index (NaN and inf
 * xi; ASan checks the reads). */
#include "mist.h"
#include "mist_mie.h"
#include "mist_test.h"

#include <string.h>

#define GUARD 64
#define CANARY 0x5a5aa5a5c3c33c3cULL

static double from_bits(uint64_t b)
{
    volatile double v;
    double d;
    memcpy(&d, &b, sizeof d);
    v = d;
    return v;
}

static void fill(double *p, size_t n)
{
    size_t i;
    uint64_t c = CANARY;
    for (i = 0; i < n; ++i) memcpy(&p[i], &c, sizeof c);
}

static int intact(const double *p, size_t n)
{
    size_t i;
    for (i = 0; i < n; ++i) {
        uint64_t b;
        memcpy(&b, &p[i], sizeof b);
        if (b != CANARY) return 0;
    }
    return 1;
}

/* buf: GUARD, n, GUARD doubles; the guards hold the canary */
static double *guarded(size_t n)
{
    double *b = (double *)malloc((n + 2 * GUARD) * sizeof(double));
    if (!b) { printf("out of memory\n"); exit(1); }
    fill(b, n + 2 * GUARD);
    return b;
}

static int guards_ok(const double *b, size_t n)
{
    return intact(b, GUARD) && intact(b + GUARD + n, GUARD);
}

int main(void)
{
    double vals[20];
    size_t nv = 0, i, j, k, w;
    size_t works[5];
    double *buf;
    size_t nbuf;
    int calls = 0;

    vals[nv++] = from_bits(0x7ff8000000000000ULL);       /* NaN */
    vals[nv++] = from_bits(0xfff8000000000000ULL);       /* -NaN */
    vals[nv++] = from_bits(0x7ff0000000000001ULL);       /* signalling NaN */
    vals[nv++] = from_bits(0x7fffffffffffffffULL);       /* NaN, all payload */
    vals[nv++] = from_bits(0x7ff0000000000000ULL);       /* +inf */
    vals[nv++] = from_bits(0xfff0000000000000ULL);       /* -inf */
    vals[nv++] = from_bits(0x7fefffffffffffffULL);       /* DBL_MAX */
    vals[nv++] = from_bits(0xffefffffffffffffULL);       /* -DBL_MAX */
    vals[nv++] = from_bits(0x0000000000000001ULL);       /* smallest subnormal */
    vals[nv++] = from_bits(0x8000000000000000ULL);       /* -0 */
    vals[nv++] = 0;
    vals[nv++] = 1e300;
    vals[nv++] = 3e9;                                    /* past INT_MAX */
    vals[nv++] = 1e5;                                    /* MIST_MIE_X_MAX */
    vals[nv++] = 100000.00000000001;
    vals[nv++] = -5;
    vals[nv++] = 0.5;
    vals[nv++] = 1.33;

    works[0] = 0;
    works[1] = 9;
    works[2] = 9 * 40;
    works[3] = mist_mie_workspace_size(1000);
    works[4] = mist_mie_workspace_size(MIST_MIE_X_MAX);
    nbuf = works[4];
    buf = guarded(nbuf);

    /* mist_mie_terms, _workspace_size: bounded answers */
    for (i = 0; i < nv; ++i) {
        int t = mist_mie_terms(vals[i]);
        size_t ws = mist_mie_workspace_size(vals[i]);
        mt_check(t >= 0 && t <= 100300 && ws <= works[4],
                 "terms(%g) = %d, workspace %zu", vals[i], t, ws);
    }

    /* the sphere: x and m from the list, every workspace size */
    for (i = 0; i < nv; ++i)
        for (j = 0; j < nv; ++j)
            for (k = 0; k < 3; ++k)
                for (w = 0; w < 5; ++w) {
                    double x = vals[i];
                    mist_mie_complex m = k == 0 ? mist_mie_cplx(vals[j], 0)
                                       : k == 1 ? mist_mie_cplx(1.33, vals[j])
                                                : mist_mie_cplx(vals[j], vals[j]);
                    double *wk = buf + GUARD + (nbuf - works[w]);   /* flush right */
                    mist_mie_sphere s;
                    double mu[4] = {1, 0.3, -0.3, -1}, p[4 + 2 * GUARD], *pp = p + GUARD;
                    mist_mie_complex s1, s2;
                    {
                        s = mist_mie_sphere_make(x, m, wk, works[w]);
                        ++calls;
                        fill(p, 4 + 2 * GUARD);
                        mist_mie_phase_table(&s, mu, 4, pp);
                        (void)mist_mie_phase(&s, vals[j]);
                        mist_mie_amplitudes(&s, vals[j], &s1, &s2);
                        mt_check(intact(p, GUARD) && intact(p + GUARD + 4, GUARD),
                                 "phase table guards, x = %g, m = %g (%d)", x, vals[j], (int)k);
                    }
                    if (!mt_check(guards_ok(buf, nbuf),
                                  "sphere_make(%g, %g (%d)) with %zu doubles wrote outside",
                                  x, vals[j], (int)k, works[w]))
                        fill(buf, nbuf + 2 * GUARD);
                }

    /* mist_mie_sphere_new (ASan checks its own memory) */
    for (i = 0; i < nv; ++i)
        for (j = 0; j < nv; ++j) {
            mist_mie_sphere s;
            s = mist_mie_sphere_new(vals[i], mist_mie_cplx(vals[j], 0.01));
            mist_mie_sphere_free(&s);
            ++calls;
        }

    /* water: a NaN or huge wavelength must not index outside its table */
    for (i = 0; i < nv; ++i) {
        int st = -1;
        mist_mie_complex m = mist_mie_water(vals[i], &st);
        mt_check(st >= 0 && st <= 3, "water(%g): status %d", vals[i], st);
        (void)m;
    }

    /* averages: bad lengths, indices, weights; the phase table guarded */
    for (i = 0; i < nv; ++i)
        for (k = 0; k < 8; ++k) {
            double mu[5], *ph = guarded(5);
            double r = 0.8, lam = 0.55, nm = 1.0003, wt = 1, v = vals[i];
            mist_mie_wavelength wl;
            mist_mie_dist d;
            mist_mie_avg a;
            mist_mie_theta_grid(5, mu);
            switch (k) {
            case 0: d = mist_mie_dist_mono(v); break;
            case 1: d = mist_mie_dist_gamma(v, 0.1); d.n_radii = 16; break;
            case 2: d = mist_mie_dist_gamma(1, v); d.n_radii = 16; break;
            case 3: d = mist_mie_dist_lognormal(0.5, v); d.n_radii = 16; break;
            case 4: d = mist_mie_dist_modgamma(2, v, 0.5); d.n_radii = 16; break;
            case 5: d = mist_mie_dist_gamma(0.5, 0.1); d.r_min = 0.1; d.r_max = v; break;
            case 6: d = mist_mie_dist_mono(r); lam = v; break;
            default: d = mist_mie_dist_mono(r); nm = v; wt = v; break;
            }
            wl = mist_mie_wl(lam, wt, mist_mie_cplx(k == 6 ? 1.33 : v, 0));
            if (k == 6 || k == 7) wl.m = mist_mie_cplx(1.33, 0);
            a = mist_mie_average(&d, &wl, 1, nm, mu, 5, ph + GUARD);
            ++calls;
            mt_check(guards_ok(ph, 5) && a.status >= 0 && a.status <= 2,
                     "average case %d, value %g: status %d, guards %d", (int)k, v, a.status,
                     guards_ok(ph, 5));
            free(ph);
        }

    /* mist.h: the height fog and the prepared sampler with bad values */
    for (i = 0; i < nv; ++i)
        for (j = 0; j < nv; ++j)
            for (k = 0; k < 6; ++k) {
                mist_hfog f;
                mist_vec3 o = {0, 1, 0}, d = {0.6, 0.8, 0};
                mist_rgb t, sc;
                double len = 10;
                memset(&f, 0, sizeof f);
                f.density = 1; f.scale_height = 2;
                f.rayleigh_scat.r = f.rayleigh_scat.g = f.rayleigh_scat.b = 0.01;
                f.rayleigh_ext = f.rayleigh_scat; f.mie_scat = f.rayleigh_scat;
                f.mie_ext = f.rayleigh_scat;
                f.mie_phase = mist_fog_make(0.8, 0.5, 0.9, 0.3);
                f.sun_dir.y = 1; f.sun.r = f.sun.g = f.sun.b = 1; f.ambient = f.sun;
                f.sun_extinction = 1;
                switch (k) {
                case 0: f.density = vals[i]; f.scale_height = vals[j]; break;
                case 1: o.y = vals[i]; d.y = vals[j]; break;
                case 2: len = vals[i]; f.base = vals[j]; break;
                case 3: f.mie_ext.r = vals[i]; f.rayleigh_ext.g = vals[j]; break;
                case 4: d.x = vals[i]; o.x = vals[j]; break;
                default: f.sun_dir.x = vals[i]; f.scale_height = vals[j]; break;
                }
                mist_hfog_eval(&f, o, d, len, &t, &sc);
                ++calls;
            }
    {
        mist_phase ph = mist_phase_draine(0.7, 0.5);
        double in[64], out[64];
        for (i = 0; i < 64; ++i) in[i] = vals[i % nv];
        for (i = 0; i < nv; ++i) (void)mist_phase_sample(&ph, vals[i]);
        mist_phase_sample_n(&ph, in, out, 64);
        calls += (int)nv + 64;
    }
    mt_check(1, "mist.h: returned");

    /* negative control: the canary check sees a write one past the end */
    buf[GUARD + nbuf] = 0;
    mt_check(!guards_ok(buf, nbuf), "negative control: a write past the end not seen");
    free(buf);
    printf("%d calls\n", calls);
    return mt_done("test_mie_fastmath");
}
