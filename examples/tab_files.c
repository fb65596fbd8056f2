/* tab_files.c - a tabulated phase function (mist_tab) from files: MiePlot's
 * text output or a plain CSV in, a table file for a renderer out.
 *
 *   tab_files mieplot IN.txt [OUT.tab]   MiePlot's text export: the lines
 *       after the header "Angle Wavelength Perpendicular Parallel" (any
 *       case, any separators), one row per angle and wavelength: angle in
 *       degrees, wavelength, |S1|^2, |S2|^2 (any scale).  Unpolarised: the
 *       mean of the two.  Each wavelength is a channel (in the order of
 *       first appearance), rows in any order (per wavelength or per angle);
 *       every wavelength must have every angle, and 0 and 180 degrees must
 *       be among them.
 *   tab_files csv IN.csv [OUT.tab]       rows "angle, v_0, v_1, ...": angle
 *       in degrees, then one value per channel (same count on every row);
 *       lines starting with '#' or a letter are skipped.
 *   tab_files --selftest [DIR]           the ctest: see selftest().
 * OUT.tab defaults to tab_files_out.tab beside the program (examples/
 * beside.h); the self-test writes into DIR, else beside the program.
 *
 * THE TABLE FILE (text; every number "%.17g", so it reads back bit for bit):
 *   # comment lines start with '#'
 *   mist_tab 1 N C              format version 1, N nodes, C channels
 *   mu_0 p_00 ... p_0(C-1)      N lines: mu ascending, mu_0 = -1, mu_N-1 = 1
 *   ...                         (mu = cos theta), values >= 0, any scale
 * which is mist_tab_init's input as it stands: tabfile_load below reads it
 * (copy it into a renderer), mist_tab_init normalises each channel.
 *
 * Build and run (from the repository root):
 *   cc -std=c99 -O2 -Iinclude examples/tab_files.c -o tab_files -lm
 *   ./tab_files --selftest /tmp */
#include "mist.h"
#include "mist_mie.h"
#include "beside.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

/* a table's input: n nodes mu[] ascending from -1 to 1, p[i * C + c] */
typedef struct tabdata {
    size_t n;
    int C;
    double *mu, *p;
} tabdata;

static void tabdata_free(tabdata *d)
{
    free(d->mu); free(d->p);
    d->mu = d->p = NULL; d->n = 0; d->C = 0;
}

/* ------------------------------------------------------------------------ */
/* The table file's loader: what a renderer copies.  Returns 0, or -1 with
 * a message on stderr.  d's arrays are malloc'ed (tabdata_free). */
static int tabfile_load(const char *path, tabdata *d)
{
    char line[256];
    unsigned long n = 0;
    int C = 0, ver = 0, ok = 0;
    size_t i;
    FILE *f = fopen(path, "r");
    d->mu = d->p = NULL; d->n = 0; d->C = 0;
    if (!f) { fprintf(stderr, "%s: cannot open\n", path); return -1; }
    while (fgets(line, sizeof line, f)) {
        if (line[0] == '#') continue;
        ok = sscanf(line, "mist_tab %d %lu %d", &ver, &n, &C) == 3 && ver == 1 && n >= 2
             && C >= 1 && C <= 64;
        break;
    }
    if (ok) {
        d->mu = (double *)malloc(n * sizeof(double));
        d->p = (double *)malloc(n * (size_t)C * sizeof(double));
        ok = d->mu && d->p;
    }
    for (i = 0; ok && i < n; ++i) {
        int c;
        ok = fscanf(f, "%lf", &d->mu[i]) == 1;
        for (c = 0; ok && c < C; ++c) ok = fscanf(f, "%lf", &d->p[i * (size_t)C + (size_t)c]) == 1;
    }
    fclose(f);
    if (!ok) { fprintf(stderr, "%s: not a mist_tab 1 file\n", path); tabdata_free(d); return -1; }
    d->n = n; d->C = C;
    return 0;
}

/* Writes d as a table file; 0 or -1. */
static int tabfile_write(const char *path, const tabdata *d)
{
    size_t i;
    int c;
    FILE *f = fopen(path, "w");
    if (!f) { fprintf(stderr, "%s: cannot write\n", path); return -1; }
    fprintf(f, "# a tabulated phase function: mu = cos theta, then one value per channel\n");
    fprintf(f, "mist_tab 1 %lu %d\n", (unsigned long)d->n, d->C);
    for (i = 0; i < d->n; ++i) {
        fprintf(f, "%.17g", d->mu[i]);
        for (c = 0; c < d->C; ++c) fprintf(f, " %.17g", d->p[i * (size_t)d->C + (size_t)c]);
        fprintf(f, "\n");
    }
    return fclose(f) == 0 ? 0 : -1;
}

/* A built table of d (malloc'ed), or NULL with a message. */
static mist_tab *tab_build(const tabdata *d)
{
    size_t bytes = mist_tab_bytes(d->n, d->C);
    mist_tab *t = bytes ? (mist_tab *)malloc(bytes) : NULL;
    int e;
    if (!t) { fprintf(stderr, "no table of %lu nodes\n", (unsigned long)d->n); return NULL; }
    e = mist_tab_init(t, bytes, d->mu, d->p, d->n, d->C);
    if (e) { fprintf(stderr, "mist_tab_init: %d\n", e); free(t); return NULL; }
    return t;
}

/* ------------------------------------------------------------------------ */
/* Readers: rows (angle, key, value) onto the grid of distinct angles and
 * keys (wavelengths, or column numbers). */

typedef struct rows {
    size_t n, cap;
    double *a, *k, *v;
} rows;

static int rows_add(rows *r, double a, double k, double v)
{
    if (r->n == r->cap) {
        size_t cap = r->cap ? 2 * r->cap : 1024;
        double *na = (double *)realloc(r->a, cap * sizeof(double));
        double *nk = na ? (double *)realloc(r->k, cap * sizeof(double)) : NULL;
        double *nv = nk ? (double *)realloc(r->v, cap * sizeof(double)) : NULL;
        if (na) r->a = na;
        if (nk) r->k = nk;
        if (!nv) return -1;
        r->v = nv;
        r->cap = cap;
    }
    r->a[r->n] = a; r->k[r->n] = k; r->v[r->n] = v;
    ++r->n;
    return 0;
}

static int cmp_desc(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return a > b ? -1 : a < b;
}

/* The grid: angles descending (so mu ascending), keys in order of first
 * appearance.  0, or -1 with a message. */
static int rows_grid(const rows *r, const char *path, tabdata *d)
{
    double keys[64], *ang;
    unsigned char *seen;
    size_t i, na = 0, j;
    int C = 0, c;
    d->mu = d->p = NULL; d->n = 0; d->C = 0;
    for (i = 0; i < r->n; ++i) {
        for (c = 0; c < C && keys[c] != r->k[i]; ++c) {}
        if (c == C) {
            if (C == 64) { fprintf(stderr, "%s: more than 64 channels\n", path); return -1; }
            keys[C++] = r->k[i];
        }
        if (!(r->a[i] >= 0 && r->a[i] <= 180 && r->v[i] >= 0)) {
            fprintf(stderr, "%s: angle %g or value %g out of range\n", path, r->a[i], r->v[i]);
            return -1;
        }
    }
    ang = (double *)malloc((r->n + 1) * sizeof(double));
    if (!ang || r->n == 0) { free(ang); fprintf(stderr, "%s: no rows\n", path); return -1; }
    memcpy(ang, r->a, r->n * sizeof(double));
    qsort(ang, r->n, sizeof(double), cmp_desc);
    for (i = 0; i < r->n; ++i) if (i == 0 || ang[i] != ang[na - 1]) ang[na++] = ang[i];
    if (na < 2 || ang[0] != 180 || ang[na - 1] != 0) {
        fprintf(stderr, "%s: the angles must include 0 and 180 degrees\n", path);
        free(ang);
        return -1;
    }
    d->mu = (double *)malloc(na * sizeof(double));
    d->p = (double *)malloc(na * (size_t)C * sizeof(double));
    seen = (unsigned char *)calloc(na * (size_t)C, 1);
    if (!d->mu || !d->p || !seen) { free(ang); free(seen); tabdata_free(d); return -1; }
    for (i = 0; i < r->n; ++i) {
        double *hit = (double *)bsearch(&r->a[i], ang, na, sizeof(double), cmp_desc);
        size_t at;
        for (c = 0; keys[c] != r->k[i]; ++c) {}
        at = (size_t)(hit - ang) * (size_t)C + (size_t)c;
        if (seen[at]) {
            fprintf(stderr, "%s: angle %g twice for channel %d\n", path, r->a[i], c);
            free(ang); free(seen); tabdata_free(d);
            return -1;
        }
        seen[at] = 1;
        d->p[at] = r->v[i];
    }
    for (j = 0; j < na * (size_t)C; ++j)
        if (!seen[j]) {
            fprintf(stderr, "%s: angle %g missing for channel %d\n", path, ang[j / (size_t)C],
                    (int)(j % (size_t)C));
            free(ang); free(seen); tabdata_free(d);
            return -1;
        }
    for (i = 0; i < na; ++i)           /* the ends exactly, cos elsewhere */
        d->mu[i] = ang[i] == 180 ? -1 : ang[i] == 0 ? 1 : cos(ang[i] * (PI / 180));
    d->n = na; d->C = C;
    free(ang); free(seen);
    return 0;
}

/* the numbers on a line (separators: anything that does not start one) */
static int numbers(const char *s, double *v, int max)
{
    int k = 0;
    char *end;
    while (*s && k < max) {
        if (isdigit((unsigned char)*s) || *s == '-' || *s == '+' || *s == '.') {
            v[k] = strtod(s, &end);
            if (end == s) return -1;
            ++k;
            s = end;
        } else if (isalpha((unsigned char)*s)) {
            return -1;                   /* text: not a data line */
        } else {
            ++s;
        }
    }
    return k;
}

static int read_lines(const char *path, int mieplot, tabdata *d)
{
    char line[4096];
    double v[65];
    rows r = { 0, 0, NULL, NULL, NULL };
    int in = !mieplot, width = -1, err = 0, k;
    FILE *f = fopen(path, "r");
    if (!f) { fprintf(stderr, "%s: cannot open\n", path); return -1; }
    while (!err && fgets(line, sizeof line, f)) {
        if (!in) {                       /* MiePlot: find the section's header */
            char low[4096];
            size_t i;
            for (i = 0; line[i]; ++i) low[i] = (char)tolower((unsigned char)line[i]);
            low[i] = 0;
            in = strstr(low, "angle") && strstr(low, "wavelength") && strstr(low, "perpendicular")
                 && strstr(low, "parallel");
            continue;
        }
        if (line[0] == '#') continue;
        k = numbers(line, v, 65);
        if (k <= 0) {
            if (mieplot && r.n) break;   /* the section's end */
            continue;
        }
        if (mieplot) {
            if (k != 4) { fprintf(stderr, "%s: a row of %d numbers\n", path, k); err = 1; break; }
            err = rows_add(&r, v[0], v[1], (v[2] + v[3]) / 2) != 0;
        } else {
            int c;
            if (width < 0) width = k;
            if (k != width || k < 2) {
                fprintf(stderr, "%s: rows of %d and %d numbers\n", path, width, k);
                err = 1;
                break;
            }
            for (c = 1; c < k && !err; ++c) err = rows_add(&r, v[0], c - 1, v[c]) != 0;
        }
    }
    fclose(f);
    if (!err && !in) { fprintf(stderr, "%s: no MiePlot angle section\n", path); err = 1; }
    if (!err) err = rows_grid(&r, path, d) != 0;
    free(r.a); free(r.k); free(r.v);
    return err ? -1 : 0;
}

static int read_mieplot(const char *path, tabdata *d) { return read_lines(path, 1, d); }
static int read_csv(const char *path, tabdata *d) { return read_lines(path, 0, d); }

/* ------------------------------------------------------------------------ */
/* The self-test: a MiePlot-format file written from mist_mie (one water
 * droplet, r = 2 um, at 450, 550 and 650 nm; angles 0 to 180 every 0.25
 * degrees; "%.6E" as a text export prints), read back, and the table
 * (mist_tab_eval's channels at the nodes) against mist_mie_phase there,
 * scaled by the factor mist_tab's normalisation applies: the trapezoid
 * integral of the exact values (computed here).  Bound 1e-6 relative: the
 * 7 printed digits (5e-7 per value, the mean of two and the integral no
 * more) plus mist_tab's few eps.  Negative control: channel 0 against
 * 650 nm is far outside it.  The same data per angle instead of per
 * wavelength reads to the same arrays, a CSV of it to values within the
 * bound, the table file back bit for bit; a file without the 0 degree row,
 * a row twice, or no header is refused. */

#define ST_NA 721
#define ST_NW 3

static int fails = 0;

static void check(int ok, const char *what, double v)
{
    if (!ok) ++fails;
    printf("%s %s (%.3g)\n", ok ? "ok  " : "FAIL", what, v);
}

/* the MiePlot file: per wavelength (order 0) or per angle (order 1); skip
 * omits one row (-1: none), dup repeats one */
static int write_mieplot(const char *path, mist_mie_sphere *s, const double *lam, int order,
                         int skip, int header)
{
    int i, l, at = 0;
    FILE *f = fopen(path, "w");
    if (!f) return -1;
    fprintf(f, "MiePlot-format results written by mist's tab_files self-test\n");
    fprintf(f, "Sphere radius 2 um, water (mist_mie_water), medium 1.0\n\n");
    if (header) fprintf(f, "Angle\tWavelength\tPerpendicular\tParallel\n");
    for (at = 0; at < ST_NA * ST_NW; ++at) {
        double a, mu;
        mist_mie_complex s1, s2;
        i = order ? at / ST_NW : at % ST_NA;
        l = order ? at % ST_NW : at / ST_NA;
        if (at == skip) continue;
        a = 0.25 * i;
        mu = i == 0 ? 1 : i == ST_NA - 1 ? -1 : cos(a * (PI / 180));
        mist_mie_amplitudes(&s[l], mu, &s1, &s2);
        fprintf(f, "%.6E\t%.6E\t%.6E\t%.6E\n", a, lam[l], s1.re * s1.re + s1.im * s1.im,
                s2.re * s2.re + s2.im * s2.im);
    }
    fprintf(f, "\nEnd of results\n");
    return fclose(f) == 0 ? 0 : -1;
}

static int selftest(const char *dir, const char *argv0)
{
    static const double lam[ST_NW] = { 0.45, 0.55, 0.65 };
    mist_mie_sphere s[ST_NW];
    char pm[1024], pa[1024], pc[1024], pt[1024], pb[1024];
    tabdata d, d2, d3, d4;
    mist_tab *t, *t4;
    double worst = 0, ctl = 0, k[ST_NW], q[ST_NW];
    size_t i;
    int l, c;
    FILE *f;
    if (dir) {
        snprintf(pm, sizeof pm, "%s/tab_files_mieplot.txt", dir);
        snprintf(pa, sizeof pa, "%s/tab_files_mieplot_by_angle.txt", dir);
        snprintf(pc, sizeof pc, "%s/tab_files.csv", dir);
        snprintf(pt, sizeof pt, "%s/tab_files_out.tab", dir);
        snprintf(pb, sizeof pb, "%s/tab_files_bad.txt", dir);
    } else {
        beside_program(pm, sizeof pm, argv0, "tab_files_mieplot.txt");
        beside_program(pa, sizeof pa, argv0, "tab_files_mieplot_by_angle.txt");
        beside_program(pc, sizeof pc, argv0, "tab_files.csv");
        beside_program(pt, sizeof pt, argv0, "tab_files_out.tab");
        beside_program(pb, sizeof pb, argv0, "tab_files_bad.txt");
    }
    for (l = 0; l < ST_NW; ++l)
        s[l] = mist_mie_sphere_new(2 * PI * 2 / lam[l], mist_mie_water(1000 * lam[l], NULL));
    if (write_mieplot(pm, s, lam, 0, -1, 1) || read_mieplot(pm, &d)) return 1;
    check(d.n == ST_NA && d.C == ST_NW && d.mu[0] == -1 && d.mu[d.n - 1] == 1,
          "MiePlot file read: 721 nodes, 3 channels", (double)d.n);
    t = tab_build(&d);
    if (!t) return 1;
    /* the normalisation's factor per channel: trapezoids of the exact values */
    for (l = 0; l < ST_NW; ++l) {
        double sum = 0;
        for (i = 0; i + 1 < d.n; ++i)
            sum += (d.mu[i + 1] - d.mu[i])
                   * (mist_mie_phase(&s[l], d.mu[i]) + mist_mie_phase(&s[l], d.mu[i + 1])) / 2;
        k[l] = 1 / (2 * PI * sum);
    }
    for (i = 0; i < d.n; ++i) {
        (void)mist_tab_eval(t, d.mu[i], q);
        for (l = 0; l < ST_NW; ++l) {
            double e = fabs(q[l] / (k[l] * mist_mie_phase(&s[l], d.mu[i])) - 1);
            if (e > worst) worst = e;
        }
        {
            double e = fabs(q[0] / (k[2] * mist_mie_phase(&s[2], d.mu[i])) - 1);
            if (e > ctl) ctl = e;
        }
    }
    check(worst <= 1e-6, "table = mist_mie_phase at the nodes, worst relative", worst);
    check(ctl > 1e-2, "negative control: 450 nm channel against 650 nm", ctl);
    check(k[0] > 0.99 && k[0] < 1.01, "trapezoid factor near 1 (0.25 degree grid)", k[0]);

    if (write_mieplot(pa, s, lam, 1, -1, 1) || read_mieplot(pa, &d2)) return 1;
    check(d2.n == d.n && d2.C == d.C && !memcmp(d2.mu, d.mu, d.n * sizeof(double))
          && !memcmp(d2.p, d.p, d.n * (size_t)d.C * sizeof(double)),
          "rows per angle read as rows per wavelength", 0);

    f = fopen(pc, "w");                /* the CSV: angle, then the three values */
    if (!f) return 1;
    fprintf(f, "# angle_deg, 450nm, 550nm, 650nm\nangle,r,g,b\n");
    for (i = d.n; i-- > 0;) {
        double a = 0.25 * (double)(d.n - 1 - i);
        fprintf(f, "%.17g", a);
        for (c = 0; c < d.C; ++c) fprintf(f, ", %.17g", d.p[i * (size_t)d.C + (size_t)c]);
        fprintf(f, "\n");
    }
    fclose(f);
    if (read_csv(pc, &d3)) return 1;
    check(d3.n == d.n && d3.C == d.C && !memcmp(d3.mu, d.mu, d.n * sizeof(double))
          && !memcmp(d3.p, d.p, d.n * (size_t)d.C * sizeof(double)),
          "CSV read to the same arrays", 0);

    if (tabfile_write(pt, &d) || tabfile_load(pt, &d4)) return 1;
    check(d4.n == d.n && d4.C == d.C && !memcmp(d4.mu, d.mu, d.n * sizeof(double))
          && !memcmp(d4.p, d.p, d.n * (size_t)d.C * sizeof(double)),
          "table file read back bit for bit", 0);
    t4 = tab_build(&d4);
    if (!t4) return 1;
    {
        int same = 1;
        for (i = 0; i < 4096; ++i) {
            double u = -1 + 2 * ((double)i + 0.5) / 4096, q4[ST_NW];
            same &= mist_tab_eval(t, u, q) == mist_tab_eval(t4, u, q4) && q[1] == q4[1];
            same &= mist_tab_sample(t, u * u) == mist_tab_sample(t4, u * u);
        }
        check(same, "the loaded table evaluates and samples as the built one", 0);
    }

    {   /* refused: no 0 degree row (blocks per wavelength: row 0), a row
         * twice (the by-angle file appended to itself), no header */
        tabdata e;
        int r1, r2, r3;
        if (write_mieplot(pb, s, lam, 0, 0, 1)) return 1;
        r1 = read_mieplot(pb, &e);
        if (!r1) tabdata_free(&e);
        if (write_mieplot(pb, s, lam, 0, -1, 0)) return 1;
        r3 = read_mieplot(pb, &e);
        if (!r3) tabdata_free(&e);
        f = fopen(pb, "w");
        if (!f) return 1;
        fprintf(f, "Angle Wavelength Perpendicular Parallel\n0 0.5 1 1\n180 0.5 1 1\n0 0.5 1 1\n");
        fclose(f);
        r2 = read_mieplot(pb, &e);
        if (!r2) tabdata_free(&e);
        check(r1 != 0 && r2 != 0 && r3 != 0, "missing angle, repeated row, no header refused", 0);
    }
    free(t); free(t4);
    tabdata_free(&d); tabdata_free(&d2); tabdata_free(&d3); tabdata_free(&d4);
    for (l = 0; l < ST_NW; ++l) mist_mie_sphere_free(&s[l]);
    printf("tab_files self-test: %d failed\n", fails);
    return fails != 0;
}

int main(int argc, char **argv)
{
    char out[1024];
    const char *dst;
    tabdata d;
    mist_tab *t;
    double q[64];
    if (argc >= 2 && !strcmp(argv[1], "--selftest"))
        return selftest(argc > 2 ? argv[2] : NULL, argv[0]);
    if (argc < 3 || (strcmp(argv[1], "mieplot") && strcmp(argv[1], "csv"))) {
        fprintf(stderr, "usage: %s mieplot|csv IN [OUT.tab] | --selftest [DIR]\n", argv[0]);
        return 2;
    }
    if ((!strcmp(argv[1], "mieplot") ? read_mieplot : read_csv)(argv[2], &d)) return 1;
    t = tab_build(&d);
    if (!t) { tabdata_free(&d); return 1; }
    dst = argc > 3 ? argv[3] : beside_program(out, sizeof out, argv[0], "tab_files_out.tab");
    if (tabfile_write(dst, &d)) { free(t); tabdata_free(&d); return 1; }
    (void)mist_tab_eval(t, 1, q);
    printf("%s: %lu nodes, %d channels -> %s (forward peak of channel 0: %.6g /sr)\n", argv[2],
           (unsigned long)d.n, d.C, dst, q[0]);
    free(t);
    tabdata_free(&d);
    return 0;
}
