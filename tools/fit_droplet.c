/* fit_droplet.c - makes the table of mist_fog_from_diameter_mie (include/
 * mist.h, "Droplet sizes fitted to Lorenz-Mie"): the fog mix's four
 * parameters fitted to Lorenz-Mie at diameters 0.01 to 50 um, and the
 * comparison with the published fits (docs/mie.md).
 *
 * The reference, the metrics and the objective: tests/mist_dropfit.h
 * (water, 450/550/650 nm averaged, lognormal width 1.1; L1 and logRMS as
 * in docs/mie.md's fit-error table; minimise logRMS^2 + (0.35 L1)^2, plus
 * a smoothness term too small to move what the error sees).
 * Two stages:
 *   1. each node alone, d increasing: Nelder-Mead from the previous node's
 *      parameters (continuation), and from the published fit and 8 spread
 *      starts, which replace the continued fit only when 2% better (a
 *      branch change is a change of shape, kept to where it pays);
 *   2. sweeps over the nodes: each node moves to minimise the objective
 *      summed over the fine grid points its value reaches through the
 *      interpolation (tests/mist_dropfit.h, dropfit_node), starting from
 *      its value and from its neighbours' (so a change of branch between
 *      two nodes is fitted as interpolated, not only at the nodes).
 * The first node is the published eq. 11-14 at d = 0.01 (the function
 * continues with them below it) and is not moved.
 *
 * Output (stdout): the table as a C initialiser; each node's parameters
 * and errors; the errors at docs/mie.md's diameters beside the published
 * fits'; the fine grid's summary (where the model is worse than the
 * published fits, geometric means).
 *   --nodes N      nodes (default MIST__DROP_N, 56)
 *   --fine F       fine points a node interval (default 4)
 *   --radii R      radii of the size average (default 200, as fit_error)
 *   --sweeps S     at most S stage-2 sweeps (default 8); they end when
 *                  one gains less than 0.1% of the objective
 *   --channel C    fit one wavelength: r (650 nm), g (550), b (450);
 *                  default the average of the three
 *   --header FILE  write the table into FILE (include/mist.h) between its
 *                  lines "BEGIN TABLE" and "END TABLE"
 *   --svg FILE     plot the errors and the parameters against d, beside
 *                  the published fits' (docs/droplet_fit.svg)
 *   --table        no fit: report on (and plot) the header's table
 *   --five         also fit a fifth parameter at docs/mie.md's diameters:
 *                  a second Draine lobe (g2, weight w2, alpha as the first)
 *                  for the backward glory, and print what it gains
 * Build: cmake --build build --target mist_fit_droplet
 * Run:   ./build/mist_fit_droplet --header include/mist.h --svg docs/droplet_fit.svg
 *        (about 7 minutes of one core: 2 sweeps);
 *        ./build/mist_fit_droplet --table --five  (the header's table, ~1 minute) */
#include "mist.h"
#include "mist_mie.h"
#include "mist_dropfit.h"

#include <string.h>

static const double table_ds[] = { 0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1, 1.5, 2, 3, 5, 7, 10,
                                    15, 20, 30, 50 };
#define N_TABLE_DS (sizeof table_ds / sizeof *table_ds)

/* ---- stage 1 ------------------------------------------------------------ */
/* one node's objective, plus the smoothness term (tests/mist_dropfit.h)
 * against the previous node's parameters */
static double prev_row[4];
static double stage1_obj(const double *x, const void *ref)
{
    double r[4], s = dropfit_obj(x, ref);
    int q;
    dropfit_set_row(r, 0, dropfit_fog(x));
    for (q = 0; q < 4; ++q) s += DF_SMOOTH * (r[q] - prev_row[q]) * (r[q] - prev_row[q]);
    return s;
}

static void stage1(double *tab, int n, int ch, int nr)
{
    static double ref[NTH];
    double x[4];
    int k, s;
    dropfit_coords(mist_fog_from_diameter(0.01), x);
    dropfit_set_row(tab, 0, mist_fog_from_diameter(0.01));
    for (k = 1; k < n; ++k) {
        double d = dropfit_node_d(k, n), o = 0, z[4], oz;
        memcpy(prev_row, tab + 4 * (k - 1), sizeof prev_row);
        dropfit_ref(d, ch, ref, nr);
        o = dropfit_nm_fn(x, stage1_obj, ref, 0.3, 4000);
        for (s = 0; s < 9; ++s) {
            static const double gh[4] = { 0.3, 0.6, 0.8, 0.95 }, gd[4] = { 0.2, 0.4, 0.6, 0.8 },
                                al[2] = { 10, 1000 }, wd[2] = { 0.3, 0.6 };
            dropfit_coords(s == 0 ? mist_fog_from_diameter(d)
                                  : mist_fog_make(gh[(s - 1) % 4], gd[(s - 1) / 2 % 4],
                                                  al[(s - 1) % 2], wd[(s - 1) / 4 % 2]), z);
            oz = dropfit_nm_fn(z, stage1_obj, ref, 0.3, 4000);
            if (oz < 0.98 * o) { o = oz; memcpy(x, z, sizeof z); }
        }
        dropfit_set_row(tab, k, dropfit_fog(x));
    }
}

/* ---- stage 2 ------------------------------------------------------------ */
static void stage2(double *tab, int n, int fine, const double *refs, int sweeps)
{
    dropfit_joint c;
    int sw, k;
    c.tab = tab; c.n = n; c.fine = fine; c.refs = refs;
    for (sw = 0; sw < sweeps; ++sw) {
        double b = 0, a = 0;
        for (k = 1; k < n; ++k) {
            int from[2], nf = 0;
            double ob, oa;
            if (k > 1) from[nf++] = k - 1;
            if (k + 1 < n) from[nf++] = k + 1;
            c.k = k;
            dropfit_node(&c, from, nf, &ob, &oa);
            b += ob; a += oa;
        }
        printf("/* sweep %d: objective summed over the nodes %.6f -> %.6f */\n", sw + 1, b, a);
        fflush(stdout);
        if (b - a < 1e-3 * b) break;
    }
}

/* ---- the header --------------------------------------------------------- */
/* 9 decimals; log alpha at most 6.907755278, below log 1000 (so that alpha
 * <= 1000 holds after rounding too) */
static void print_table(FILE *f, const double *tab, int n)
{
    int k;
    for (k = 0; k < n; ++k)
        fprintf(f, "        %.9f, %.9f, %.9f, %.9f,%s /* %.4g um */\n", tab[4 * k],
                tab[4 * k + 1], tab[4 * k + 2] < 6.907755278 ? tab[4 * k + 2] : 6.907755278,
                tab[4 * k + 3], k + 1 < n ? "" : " ", dropfit_node_d(k, n));
}

static int write_header(const char *path, const double *tab, int n)
{
    FILE *f = fopen(path, "rb");
    char *buf, *b, *e;
    long len;
    if (!f) { perror(path); return 1; }
    fseek(f, 0, SEEK_END); len = ftell(f); fseek(f, 0, SEEK_SET);
    buf = (char *)malloc((size_t)len + 1);
    if (!buf || fread(buf, 1, (size_t)len, f) != (size_t)len) { fclose(f); return 1; }
    fclose(f);
    buf[len] = 0;
    b = strstr(buf, "BEGIN TABLE");
    e = b ? strstr(b, "END TABLE") : NULL;
    if (!b || !e) { fprintf(stderr, "%s: no BEGIN TABLE ... END TABLE\n", path); return 1; }
    b = strchr(b, '\n');
    if (!b || b > e) { fprintf(stderr, "%s: BEGIN TABLE must end its line\n", path); return 1; }
    ++b;
    while (e > buf && e[-1] != '\n') --e;
    f = fopen(path, "wb");
    if (!f) { perror(path); return 1; }
    fwrite(buf, 1, (size_t)(b - buf), f);
    print_table(f, tab, n);
    fputs(e, f);
    fclose(f);
    free(buf);
    return 0;
}

/* ---- the plot ----------------------------------------------------------- */
typedef struct { double x0, y0, w, h, lo, hi; int logy; } panel;

static double px(const panel *p, double d)
{
    return p->x0 + p->w * (log10(d) + 2) / (log10(50.0) + 2);
}

static double py(const panel *p, double v)
{
    double t = p->logy ? (log10(v) - log10(p->lo)) / (log10(p->hi) - log10(p->lo))
                       : (v - p->lo) / (p->hi - p->lo);
    t = t < -0.02 ? -0.02 : t > 1.02 ? 1.02 : t;
    return p->y0 + p->h * (1 - t);
}

static void svg_frame(FILE *f, const panel *p, const char *title, const double *ticks, int nt)
{
    static const double dt[] = { 0.01, 0.1, 1, 10, 50 };
    int i;
    fprintf(f, "<text x='%.0f' y='%.0f' font-size='14' font-weight='bold'>%s</text>\n", p->x0,
            p->y0 - 10, title);
    fprintf(f, "<rect x='%.0f' y='%.0f' width='%.0f' height='%.0f' fill='white' "
               "stroke='#444'/>\n", p->x0, p->y0, p->w, p->h);
    for (i = 0; i < 5; ++i) {
        double x = px(p, dt[i]);
        fprintf(f, "<line x1='%.1f' y1='%.0f' x2='%.1f' y2='%.0f' stroke='#e2e2e2'/>\n", x,
                p->y0, x, p->y0 + p->h);
        fprintf(f, "<text x='%.1f' y='%.0f' font-size='11' text-anchor='middle'>%g</text>\n",
                x, p->y0 + p->h + 14, dt[i]);
    }
    for (i = 0; i < nt; ++i) {
        double y = py(p, ticks[i]);
        fprintf(f, "<line x1='%.0f' y1='%.1f' x2='%.0f' y2='%.1f' stroke='#e2e2e2'/>\n", p->x0,
                y, p->x0 + p->w, y);
        fprintf(f, "<text x='%.0f' y='%.1f' font-size='11' text-anchor='end'>%g</text>\n",
                p->x0 - 4, y + 4, ticks[i]);
    }
    fprintf(f, "<text x='%.0f' y='%.0f' font-size='12' text-anchor='middle'>droplet diameter "
               "d (um)</text>\n", p->x0 + p->w / 2, p->y0 + p->h + 30);
}

/* a curve through (d[i], v[i]); a new path where the published fits
 * change range between two points (no line drawn across a jump) */
static void svg_curve(FILE *f, const panel *p, const double *d, const double *v, int n,
                      const char *color, int dashed, int breaks)
{
    static const double cuts[] = { 0.1, 1.5, 5 };
    int i, c;
    fprintf(f, "<path fill='none' stroke='%s' stroke-width='1.6'%s d='", color,
            dashed ? " stroke-dasharray='5,3'" : "");
    for (i = 0; i < n; ++i) {
        int br = i == 0;
        for (c = 0; c < 3 && breaks && i > 0; ++c)
            br |= d[i - 1] < cuts[c] && d[i] >= cuts[c];
        fprintf(f, "%s%.1f,%.1f ", br ? "M" : "L", px(p, d[i]), py(p, v[i]));
    }
    fprintf(f, "'/>\n");
}

static void svg_legend(FILE *f, double x, double y, const char *color, int dashed,
                       const char *text)
{
    fprintf(f, "<line x1='%.0f' y1='%.0f' x2='%.0f' y2='%.0f' stroke='%s' stroke-width='1.6'%s/>"
               "<text x='%.0f' y='%.0f' font-size='12'>%s</text>\n", x, y, x + 26, y, color,
            dashed ? " stroke-dasharray='5,3'" : "", x + 32, y + 4, text);
}

static int write_svg(const char *path, const double *tab, int n, int fine, const double *refs)
{
    int m = (n - 1) * fine, j, q;
    double *d = (double *)malloc(sizeof(double) * 11 * (size_t)(m + 1)), *e = d + m + 1;
    FILE *f = fopen(path, "w");
    static const double tl1[] = { 0.001, 0.01, 0.1, 1 }, tlr[] = { 0.001, 0.01, 0.1, 1 },
                        tg[] = { -0.2, 0, 0.25, 0.5, 0.75, 1 }, ta[] = { 1, 10, 100, 1000 };
    panel pl[4];
    if (!f || !d) { perror(path); return 1; }
    /* e: L1 new, published, logRMS new, published, then g_hg, g_d, w_d, alpha new and
     * published interleaved per point (8 values) */
    for (j = 0; j <= m; ++j) {
        mist_fog a, b;
        d[j] = dropfit_fine_d(j, n, fine);
        a = mist__fog_interp(tab, n, d[j]);
        b = mist_fog_from_diameter(d[j]);
        dropfit_err(a, refs + (size_t)j * NTH, &e[j], &e[2 * (m + 1) + j]);
        dropfit_err(b, refs + (size_t)j * NTH, &e[(m + 1) + j], &e[3 * (m + 1) + j]);
        e[4 * (m + 1) + j] = a.g_hg; e[5 * (m + 1) + j] = b.g_hg;
        e[6 * (m + 1) + j] = a.g_d;  e[7 * (m + 1) + j] = b.g_d;
        e[8 * (m + 1) + j] = a.w_d;  e[9 * (m + 1) + j] = b.w_d;
    }
    fprintf(f, "<?xml version='1.0' encoding='UTF-8'?>\n<svg xmlns='http://www.w3.org/2000/svg' "
               "version='1.1' width='1100' height='830' font-family='sans-serif'>\n"
               "<rect width='1100' height='830' fill='#fafafa'/>\n"
               "<text x='20' y='28' font-size='18' font-weight='bold'>mist: the fog mix "
               "against Lorenz-Mie, droplet diameters 0.01-50 um</text>\n"
               "<text x='20' y='48' font-size='12'>Water, 450/550/650 nm averaged, lognormal "
               "width 1.1 (docs/mie.md); errors below 1e-4 are drawn at the axis.</text>\n");
    pl[0].x0 = 80;  pl[0].y0 = 90;  pl[0].lo = 1e-4; pl[0].hi = 1;   pl[0].logy = 1;
    pl[1].x0 = 620; pl[1].y0 = 90;  pl[1].lo = 1e-4; pl[1].hi = 1;   pl[1].logy = 1;
    pl[2].x0 = 80;  pl[2].y0 = 460; pl[2].lo = -0.2;  pl[2].hi = 1;  pl[2].logy = 0;
    pl[3].x0 = 620; pl[3].y0 = 460; pl[3].lo = 1;    pl[3].hi = 1000; pl[3].logy = 1;
    for (q = 0; q < 4; ++q) { pl[q].w = 440; pl[q].h = 270; }
    svg_frame(f, &pl[0], "L1 = \xe2\x88\xab |p - p_Mie| d\xce\xa9", tl1, 4);
    svg_frame(f, &pl[1], "logRMS = RMS over \xce\xb8 of log10(p / p_Mie)", tlr, 4);
    svg_frame(f, &pl[2], "g_hg (blue), g_d (red), w_d (green)", tg, 6);
    svg_frame(f, &pl[3], "alpha", ta, 4);
    svg_curve(f, &pl[0], d, e, m + 1, "#1f5fbf", 0, 0);
    svg_curve(f, &pl[0], d, e + (m + 1), m + 1, "#1f5fbf", 1, 1);
    svg_curve(f, &pl[1], d, e + 2 * (m + 1), m + 1, "#c0392b", 0, 0);
    svg_curve(f, &pl[1], d, e + 3 * (m + 1), m + 1, "#c0392b", 1, 1);
    for (q = 0; q < 3; ++q) {
        static const char *col[3] = { "#1f5fbf", "#c0392b", "#2e8b57" };
        double *v = (double *)malloc(sizeof(double) * (size_t)(m + 1));
        for (j = 0; j <= m; ++j) v[j] = e[(4 + 2 * q) * (m + 1) + j];
        svg_curve(f, &pl[2], d, v, m + 1, col[q], 0, 0);
        for (j = 0; j <= m; ++j) v[j] = e[(5 + 2 * q) * (m + 1) + j];
        svg_curve(f, &pl[2], d, v, m + 1, col[q], 1, 1);
        free(v);
    }
    {
        double *v = (double *)malloc(sizeof(double) * 2 * (size_t)(m + 1));
        for (j = 0; j <= m; ++j) {
            v[j] = mist__fog_interp(tab, n, d[j]).alpha;
            v[m + 1 + j] = mist_fog_from_diameter(d[j]).alpha;
        }
        svg_curve(f, &pl[3], d, v, m + 1, "#555", 0, 0);
        svg_curve(f, &pl[3], d, v + m + 1, m + 1, "#555", 1, 1);
        free(v);
    }
    svg_legend(f, 80, 790, "#333", 0, "mist_fog_from_diameter_mie: fitted to Mie, continuous");
    svg_legend(f, 80, 810, "#333", 1, "mist_fog_from_diameter: the published fits [JD23 "
               "eq. 7-22], broken where their ranges meet (0.1, 1.5, 5 um)");
    fprintf(f, "<text x='620' y='794' font-size='12'>%d diameters uniform in log d; the table "
               "has %d nodes (tools/fit_droplet.c)</text>\n</svg>\n", m + 1, n);
    fclose(f);
    free(d);
    return 0;
}

/* ---- a fifth parameter -------------------------------------------------- */
/* (1 - w - w2) HG(g_hg) + w Draine(g_d, alpha) + w2 Draine(g2, alpha):
 * x[4] = atanh g2, x[5] = logit of w2's share of the Draine weight */
static const double *five_ref;

static void five_errors(const double *x6, const double *ref, double *l1, double *lr)
{
    mist_fog f = dropfit_fog(x6);
    double g2 = tanh(x6[4]), sh = 1 / (1 + exp(-x6[5])), p[NTH];
    int i;
    for (i = 0; i < NTH; ++i)
        p[i] = (1 - f.w_d) * mist_hg_eval(f.g_hg, mu[i])
             + f.w_d * ((1 - sh) * mist_draine_eval(f.g_d, f.alpha, mu[i])
                        + sh * mist_draine_eval(g2, f.alpha, mu[i]));
    fitref_errors(p, ref, l1, lr);
}

static double five_obj6(const double *x6)
{
    double l1, lr;
    five_errors(x6, five_ref, &l1, &lr);
    return lr * lr + DF_L1_WEIGHT * DF_L1_WEIGHT * l1 * l1;
}

/* Nelder-Mead in 4 of the 6 coordinates at a time (dropfit_nm_fn is 4-D):
 * alternately the fog's four and (g2, share) with the fog's alpha, w_d */
static double five_x[6];
static double five_obj_a(const double *x, const void *c)
{
    double y[6];
    (void)c;
    memcpy(y, x, 4 * sizeof *y); y[4] = five_x[4]; y[5] = five_x[5];
    return five_obj6(y);
}
static double five_obj_b(const double *x, const void *c)
{
    double y[6];
    (void)c;
    memcpy(y, five_x, sizeof y); y[2] = x[0]; y[3] = x[1]; y[4] = x[2]; y[5] = x[3];
    return five_obj6(y);
}

static void five(const double *tab, int n, int ch, int nr)
{
    static double ref[NTH];
    size_t i;
    printf("\nA fifth parameter: a second Draine lobe (g2, its share of w_d; alpha shared)\n"
           "| d (um) | 4-param L1 | logRMS | 5-param L1 | logRMS | g2 | share |\n"
           "|---|---|---|---|---|---|---|\n");
    for (i = 0; i < N_TABLE_DS; ++i) {
        double d = table_ds[i], l1, lr, l5, r5, best = 1e300, g2s[3] = { -0.7, -0.3, 0.3 },
               y[4], o;
        int s, it;
        mist_fog f = mist__fog_interp(tab, n, d);
        double keep[6];
        if (d < 0.05) continue;
        dropfit_ref(d, ch, ref, nr);
        five_ref = ref;
        dropfit_err(f, ref, &l1, &lr);
        for (s = 0; s < 4; ++s) {        /* the last start is the 4-parameter fit */
            dropfit_coords(f, five_x);
            five_x[4] = atanh(g2s[s % 3]); five_x[5] = s < 3 ? log(0.1 / 0.9) : -14;
            for (it = 0; it < 6; ++it) {
                memcpy(y, five_x, sizeof y);
                o = dropfit_nm_fn(y, five_obj_a, NULL, 0.2, 2000);
                memcpy(five_x, y, sizeof y);
                y[0] = five_x[2]; y[1] = five_x[3]; y[2] = five_x[4]; y[3] = five_x[5];
                o = dropfit_nm_fn(y, five_obj_b, NULL, 0.3, 2000);
                five_x[2] = y[0]; five_x[3] = y[1]; five_x[4] = y[2]; five_x[5] = y[3];
            }
            if (o < best) { best = o; memcpy(keep, five_x, sizeof keep); }
        }
        five_errors(keep, ref, &l5, &r5);
        printf("| %g | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f |\n", d, l1, lr, l5, r5,
               tanh(keep[4]), 1 / (1 + exp(-keep[5])));
        fflush(stdout);
    }
}

int main(int argc, char **argv)
{
    int n = MIST__DROP_N, fine = 4, nr = 200, sweeps = 8, ch = -1, i, m, j, worse = 0, do5 = 0,
        fit = 1;
    const char *header = NULL, *svg = NULL;
    double *tab, *refs, sl = 0, sr = 0, spl = 0, spr = 0;
    for (i = 1; i < argc; ++i) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--five")) { do5 = 1; continue; }
        if (!strcmp(a, "--table")) { fit = 0; continue; }
        if (!v) { fprintf(stderr, "%s: needs a value\n", a); return 2; }
        ++i;
        if (!strcmp(a, "--nodes")) n = atoi(v);
        else if (!strcmp(a, "--fine")) fine = atoi(v);
        else if (!strcmp(a, "--radii")) nr = atoi(v);
        else if (!strcmp(a, "--sweeps")) sweeps = atoi(v);
        else if (!strcmp(a, "--channel")) {
            ch = !strcmp(v, "r") ? 0 : !strcmp(v, "g") ? 1 : !strcmp(v, "b") ? 2 : -2;
            if (ch < -1) { fprintf(stderr, "--channel takes r, g or b\n"); return 2; }
        }
        else if (!strcmp(a, "--header")) header = v;
        else if (!strcmp(a, "--svg")) svg = v;
        else { fprintf(stderr, "unknown option %s\n", a); return 2; }
    }
    if (n < 4 || n > 1000 || fine < 1 || fine > 64 || nr < 10) {
        fprintf(stderr, "bad --nodes, --fine or --radii\n");
        return 2;
    }
    if ((header || !fit) && (ch >= 0 || n != MIST__DROP_N)) {
        fprintf(stderr, "--header and --table take the default channel and node count only\n");
        return 2;
    }
    (void)fitref_compare;       /* tests/mist_fitref.h's, not used here */
    fitref_grid();
    m = (n - 1) * fine;
    tab = (double *)malloc(sizeof(double) * 4 * (size_t)n);
    refs = (double *)malloc(sizeof(double) * NTH * (size_t)(m + 1));
    if (!tab || !refs) return 1;
    for (j = 0; j <= m; ++j) dropfit_ref(dropfit_fine_d(j, n, fine), ch, refs + (size_t)j * NTH, nr);
    if (fit) {
        stage1(tab, n, ch, nr);
        stage2(tab, n, fine, refs, sweeps);
    } else {                     /* the header's nodes: the interpolant at them */
        for (i = 0; i < n; ++i)
            dropfit_set_row(tab, i, mist_fog_from_diameter_mie(dropfit_node_d(i, n)));
    }

    printf("/* %d nodes, log d uniform from 0.01 to 50 um: g_hg, g_d, log alpha, w_d */\n", n);
    print_table(stdout, tab, n);
    printf("\n| node | d (um) | g_hg | g_d | alpha | w_d | L1 | logRMS | published L1 | logRMS |\n"
           "|---|---|---|---|---|---|---|---|---|---|\n");
    for (i = 0; i < n; ++i) {
        mist_fog f = mist__fog_interp(tab, n, dropfit_node_d(i, n)), p;
        double l1, lr, pl1, plr;
        const double *r = refs + (size_t)i * fine * NTH;
        p = mist_fog_from_diameter(dropfit_node_d(i, n));
        dropfit_err(f, r, &l1, &lr);
        dropfit_err(p, r, &pl1, &plr);
        printf("| %d | %.4g | %.4f | %.4f | %.2f | %.4f | %.3f | %.3f | %.3f | %.3f |\n", i,
               dropfit_node_d(i, n), f.g_hg, f.g_d, f.alpha, f.w_d, l1, lr, pl1, plr);
    }
    {
        static double ref[NTH];
        double a = 0, b = 0, c = 0, e = 0;
        printf("\nAt docs/mie.md's diameters:\n| d (um) | L1 | logRMS | published L1 | logRMS |%s\n"
               "|---|---|---|---|---|%s\n", ch >= 0 ? " the header's (RGB mean) L1 | logRMS |" : "",
               ch >= 0 ? "---|---|" : "");
        for (i = 0; i < (int)N_TABLE_DS; ++i) {
            double l1, lr, pl1, plr, hl1, hlr;
            dropfit_ref(table_ds[i], ch, ref, nr);
            dropfit_err(mist__fog_interp(tab, n, table_ds[i]), ref, &l1, &lr);
            dropfit_err(mist_fog_from_diameter(table_ds[i]), ref, &pl1, &plr);
            printf("| %g | %.4f | %.4f | %.4f | %.4f |", table_ds[i], l1, lr, pl1, plr);
            if (ch >= 0) {             /* the header's model against this channel */
                dropfit_err(mist_fog_from_diameter_mie(table_ds[i]), ref, &hl1, &hlr);
                printf(" %.4f | %.4f |", hl1, hlr);
            }
            printf("\n");
            a += log(l1); b += log(lr); c += log(pl1); e += log(plr);
        }
        printf("geometric means: L1 %.4f (published %.4f), logRMS %.4f (published %.4f)\n",
               exp(a / N_TABLE_DS), exp(c / N_TABLE_DS), exp(b / N_TABLE_DS),
               exp(e / N_TABLE_DS));
    }
    for (j = 0; j <= m; ++j) {
        double d = dropfit_fine_d(j, n, fine), l1, lr, pl1, plr;
        const double *r = refs + (size_t)j * NTH;
        dropfit_err(mist__fog_interp(tab, n, d), r, &l1, &lr);
        dropfit_err(mist_fog_from_diameter(d), r, &pl1, &plr);
        sl += log(l1); sr += log(lr); spl += log(pl1); spr += log(plr);
        if (l1 > pl1 || lr > plr) {
            if (!worse++) printf("\nFine grid, where worse than the published fits:\n");
            printf("  d %.4g: L1 %.4f logRMS %.4f, published %.4f %.4f\n", d, l1, lr, pl1, plr);
        }
    }
    printf("Fine grid, %d diameters: worse than the published fits in either metric at %d; "
           "geometric means L1 %.4f (published %.4f), logRMS %.4f (published %.4f)\n", m + 1,
           worse, exp(sl / (m + 1)), exp(spl / (m + 1)), exp(sr / (m + 1)), exp(spr / (m + 1)));
    if (header && write_header(header, tab, n)) return 1;
    if (svg && write_svg(svg, tab, n, fine, refs)) return 1;
    if (do5) five(tab, n, ch, nr);
    return 0;
}
