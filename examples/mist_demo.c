/* mist_demo.c - a first tour of mist.h: plot every phase function, check it.
 *
 * Build and run (from the repository root):
 *   cc -std=c99 -O2 -Iinclude examples/mist_demo.c -o mist_demo -lm
 *   ./mist_demo [out.svg]   (default: phase_functions.svg beside the program,
 *                            so a CMake build writes it into the build tree)
 *
 * It does two things:
 *   1. writes an SVG (plain SVG 1.1, no external resources; open it in a
 *      browser) with one panel per family: Henyey-Greenstein, Cornette-
 *      Shanks, Draine, Rayleigh and the Jendersie-d'Eon fog function, each
 *      as log10 of the density per steradian against theta in degrees, plus
 *      the fog again on a logarithmic theta axis to show its narrow forward
 *      peak;
 *   2. prints a table: for every curve the normalisation
 *      int 2 pi p(u) du over [-1, 1] (should be 1) and the mean cosine
 *      int u 2 pi p(u) du, both by adaptive Gauss-Kronrod quadrature written
 *      here, next to the closed-form mean cosine where one exists.
 *
 * Convention (see mist.h): u = cos(theta), theta between the incident and
 * the scattered PROPAGATION directions, so g > 0 scatters forward.
 */
#include "mist.h"

#include <stdio.h>
#include "beside.h"

#define PI 3.14159265358979323846

/* ------------------------------------------------------------------------ */
/* The curves                                                               */
/* ------------------------------------------------------------------------ */

enum family { HG, CS, DRAINE, RAYLEIGH, FOG, NFAMILY };

typedef struct curve {
    enum family fam;
    double g, alpha;  /* HG, CS, Draine */
    double d;         /* fog: droplet diameter in micrometres */
    mist_fog fog;     /* fog: the four parameters from d */
} curve;

/* The Jendersie-d'Eon fog parameters for droplet diameter d (micrometres),
 * from the large-droplet fit, valid for 5 <= d <= 50 um: Jendersie & d'Eon
 * 2023, "An Approximate Mie Scattering Function for Fog and Cloud
 * Rendering", supplemental, eq. 7-10.  The text of eq. 8 and 10 prints the
 * constants -0.428934 and -0.665888 outside the exponential; we read them
 * INSIDE it, as Blender Cycles does (with that reading the fit meets the
 * 1.5-5 um fit at d = 5; the outside reading jumps there). */
static mist_fog fog_from_diameter(double d)
{
    double g_hg  = exp(-0.0990567 / (d - 1.67154));            /* eq. 7  */
    double g_d   = exp(-2.20679 / (d + 3.91029) - 0.428934);   /* eq. 8  */
    double alpha = exp(3.62489 - 8.29288 / (d + 5.52825));     /* eq. 9  */
    double w_d   = exp(-0.599085 / (d - 0.641583) - 0.665888); /* eq. 10 */
    return mist_fog_make(g_hg, g_d, alpha, w_d);
}

/* Density per steradian of curve c at u = cos(theta). */
static double curve_eval(const curve *c, double u)
{
    switch (c->fam) {
    case HG:       return mist_hg_eval(c->g, u);
    case CS:       return mist_cs_eval(c->g, u);
    case DRAINE:   return mist_draine_eval(c->g, c->alpha, u);
    case RAYLEIGH: return mist_rayleigh_eval(u);
    case FOG:      return mist_fog_eval(c->fog, u);
    default:       return 0.0;
    }
}

/* Closed-form mean cosine of Draine(g, alpha) (HG: alpha = 0, CS: 1). */
static double draine_mean(double g, double alpha)
{
    double g2 = g * g;
    return g * (1.0 + alpha * (3.0 + 2.0 * g2) / 5.0)
             / (1.0 + alpha * (1.0 + 2.0 * g2) / 3.0);
}

static double curve_mean_exact(const curve *c)
{
    switch (c->fam) {
    case HG:       return c->g;
    case CS:       return draine_mean(c->g, 1.0);
    case DRAINE:   return draine_mean(c->g, c->alpha);
    case RAYLEIGH: return 0.0;
    case FOG:      return (1.0 - c->fog.w_d) * c->fog.g_hg
                        + c->fog.w_d * draine_mean(c->fog.g_d, c->fog.alpha);
    default:       return 0.0;
    }
}

static const char *family_name[NFAMILY] = {
    "HG", "Cornette-Shanks", "Draine", "Rayleigh", "Fog (JD23)"
};

/* ------------------------------------------------------------------------ */
/* Quadrature: adaptive Gauss-Kronrod (7-point Gauss, 15-point Kronrod).     */
/* The forward peaks of g near 1 are very narrow in u (1 - u ~ (1-g)^2: at  */
/* d = 50 um, g_hg = 0.998 and the peak is ~1e-6 wide), so [-1, 1] is first */
/* cut at 1 - 10^-k and -1 + 10^-k, k = 1..15, and each piece is refined.   */
/* ------------------------------------------------------------------------ */

typedef struct integrand { const curve *c; int moment; } integrand;

static double f_eval(const integrand *in, double u)
{
    double p = 2.0 * PI * curve_eval(in->c, u);
    return in->moment ? u * p : p;
}

static double gk15(const integrand *in, double a, double b, double *err)
{
    static const double xk[8] = {   /* Kronrod nodes, xk[1,3,5,7] Gauss */
        0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
        0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
        0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
        0.207784955007898467600689403773245, 0.000000000000000000000000000000000
    };
    static const double wk[8] = {
        0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
        0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
        0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
        0.204432940075298892414161999234649, 0.209482141084727828012999174891714
    };
    static const double wg[4] = {   /* Gauss weights at xk[1], xk[3], xk[5], xk[7] */
        0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
        0.381830050505118944950369775488975, 0.417959183673469387755102040816327
    };
    double c = 0.5 * (a + b), h = 0.5 * (b - a);
    double fc = f_eval(in, c);
    double rk = wk[7] * fc, rg = wg[3] * fc;
    int j;
    for (j = 0; j < 7; ++j) {
        double s = f_eval(in, c - h * xk[j]) + f_eval(in, c + h * xk[j]);
        rk += wk[j] * s;
        if (j & 1) rg += wg[j / 2] * s;
    }
    *err = fabs((rk - rg) * h);
    return rk * h;
}

static double adapt(const integrand *in, double a, double b, double tol, int depth)
{
    double err, r = gk15(in, a, b, &err), m = 0.5 * (a + b);
    if (err <= tol || err <= 1e-15 * fabs(r) || depth >= 50 || m <= a || m >= b)
        return r;
    return adapt(in, a, m, 0.5 * tol, depth + 1)
         + adapt(in, m, b, 0.5 * tol, depth + 1);
}

static double integrate(const curve *c, int moment)
{
    integrand in;
    double cut[32], sum = 0.0, e = 1.0;
    int n = 0, k, i;
    in.c = c;
    in.moment = moment;
    cut[n++] = -1.0;
    for (k = 0; k < 15; ++k) e *= 0.1;           /* e = 1e-15 */
    for (k = 15; k >= 1; --k, e *= 10.0) cut[n++] = -1.0 + e;
    e = 0.1;
    for (k = 1; k <= 15; ++k, e *= 0.1) cut[n++] = 1.0 - e;
    cut[n++] = 1.0;
    for (i = 0; i + 1 < n; ++i)
        sum += adapt(&in, cut[i], cut[i + 1], 1e-14, 0);
    return sum;
}

/* ------------------------------------------------------------------------ */
/* SVG                                                                      */
/* ------------------------------------------------------------------------ */

static const char *colour[5] = {
    "#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd"
};

#define NLIN 1000            /* samples of a linear-theta panel (at most) */
#define NLOG 600             /* samples of the log-theta panel */

/* theta samples in degrees for a linear axis: 0, then 200 points geometric
 * from 1e-3 to 10 degrees (the fog peaks are a fraction of a degree wide),
 * then uniform steps of 0.25 degree up to 180. */
static int theta_linear(double *t)
{
    int n = 0, i;
    t[n++] = 0.0;
    for (i = 0; i < 200; ++i) t[n++] = 1e-3 * pow(1e4, i / 200.0);
    for (i = 0; i <= 680; ++i) t[n++] = 10.0 + 0.25 * i;
    return n;
}

/* theta samples for a log axis: geometric from 0.01 to 180 degrees. */
static int theta_log(double *t)
{
    int i;
    for (i = 0; i < NLOG; ++i) t[i] = 0.01 * pow(18000.0, i / (NLOG - 1.0));
    return NLOG;
}

typedef struct panel {
    double x, y, w, h;       /* plot area in the SVG */
    double x0, x1;           /* theta range, degrees */
    int xlog;                /* log10 theta axis */
    int y0, y1;              /* log10 density range (decades) */
    int id;                  /* for the clip path's id */
} panel;

static double px(const panel *p, double theta)
{
    double t = p->xlog ? (log10(theta) - log10(p->x0)) / (log10(p->x1) - log10(p->x0))
                       : (theta - p->x0) / (p->x1 - p->x0);
    return p->x + t * p->w;
}

static double py(const panel *p, double lg)
{
    return p->y + p->h - (lg - p->y0) / (double)(p->y1 - p->y0) * p->h;
}

/* "10^k" with a raised exponent, right-aligned at (x, y). */
static void svg_pow10(FILE *f, double x, double y, int k)
{
    fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\">10<tspan dy=\"-6\" "
               "font-size=\"9\">%d</tspan></text>\n", x, y, k);
}

/* Inside a <text>: SUB("D") "text" SUB_END writes a subscript D, then a
 * small gap and "text" back on the baseline (dx, dy sit on non-empty tspans:
 * renderers drop those of an empty one, and trim spaces at a tspan edge). */
#define SUB(s) "<tspan font-size=\"7.5\" dy=\"2.5\">" s "</tspan><tspan dx=\"3\" dy=\"-2.5\">"
#define SUB_END "</tspan>"

/* One panel: frame, grid, ticks, axis titles, curves, legend. */
static void draw_panel(FILE *f, const panel *p, const char *title,
                       const curve *cs, const char *const *labels, int n)
{
    double theta[NLIN + 16];
    int nt = p->xlog ? theta_log(theta) : theta_linear(theta);
    int i, k, m;

    /* title */
    fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"15\" font-weight=\"bold\">",
            p->x, p->y - 12);
    fputs(title, f);
    fputs("</text>\n", f);

    /* grid and y ticks: decades, with minor ticks at 2..9 */
    fputs("<g stroke=\"#e4e4e4\" stroke-width=\"1\">\n", f);
    for (k = p->y0; k <= p->y1; ++k)
        fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\"/>\n",
                p->x, py(p, k), p->x + p->w, py(p, k));
    fputs("</g>\n<g stroke=\"#333\" stroke-width=\"1\">\n", f);
    for (k = p->y0; k <= p->y1; ++k) {
        fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\"/>\n",
                p->x - 5, py(p, k), p->x, py(p, k));
        if (k < p->y1 && p->y1 - p->y0 <= 5)
            for (m = 2; m <= 9; ++m) {
                double yy = py(p, k + log10((double)m));
                fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\"/>\n",
                        p->x - 3, yy, p->x, yy);
            }
    }
    fputs("</g>\n<g font-size=\"11\">\n", f);
    for (k = p->y0; k <= p->y1; ++k) svg_pow10(f, p->x - 8, py(p, k) + 4, k);
    fputs("</g>\n", f);

    /* x grid and ticks */
    fputs("<g stroke=\"#e4e4e4\" stroke-width=\"1\">\n", f);
    if (p->xlog) {
        static const double dec[5] = { 0.01, 0.1, 1.0, 10.0, 100.0 };
        for (i = 0; i < 5; ++i)
            fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\"/>\n",
                    px(p, dec[i]), p->y, px(p, dec[i]), p->y + p->h);
        fputs("</g>\n<g font-size=\"11\" text-anchor=\"middle\">\n", f);
        for (i = 0; i < 5; ++i) {   /* 100 unlabelled: too close to 180 */
            fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#333\"/>\n",
                    px(p, dec[i]), p->y + p->h, px(p, dec[i]), p->y + p->h + 5);
            if (i < 4)
                fprintf(f, "<text x=\"%.1f\" y=\"%.1f\">%g</text>\n",
                        px(p, dec[i]), p->y + p->h + 18, dec[i]);
        }
        fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#333\"/>"
                   "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\">180</text>\n",
                px(p, 180.0), p->y + p->h, px(p, 180.0), p->y + p->h + 5,
                px(p, 180.0) + 4, p->y + p->h + 18);
    } else {
        for (i = 0; i <= 6; ++i)
            fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\"/>\n",
                    px(p, 30.0 * i), p->y, px(p, 30.0 * i), p->y + p->h);
        fputs("</g>\n<g font-size=\"11\" text-anchor=\"middle\">\n", f);
        for (i = 0; i <= 6; ++i)
            fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#333\"/>"
                       "<text x=\"%.1f\" y=\"%.1f\">%d</text>\n",
                    px(p, 30.0 * i), p->y + p->h, px(p, 30.0 * i), p->y + p->h + 5,
                    px(p, 30.0 * i), p->y + p->h + 18, 30 * i);
    }
    fputs("</g>\n", f);

    /* axis titles */
    fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"12\" text-anchor=\"middle\">"
               "scattering angle &#952; (degrees%s)</text>\n",
            p->x + 0.5 * p->w, p->y + p->h + 36, p->xlog ? ", log scale" : "");
    fprintf(f, "<text transform=\"translate(%.1f %.1f) rotate(-90)\" font-size=\"12\" "
               "text-anchor=\"middle\">density per steradian</text>\n",
            p->x - 48, p->y + 0.5 * p->h);

    /* curves, clipped to the plot area */
    fprintf(f, "<defs><clipPath id=\"clip%d\"><rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" "
               "height=\"%.1f\"/></clipPath></defs>\n",
            p->id, p->x, p->y, p->w, p->h);
    fprintf(f, "<g clip-path=\"url(#clip%d)\" fill=\"none\" stroke-width=\"1.8\" "
               "stroke-linejoin=\"round\">\n", p->id);
    for (i = 0; i < n; ++i) {
        double lx = 0, ly = 0;
        int first = 1, j;
        fprintf(f, "<polyline stroke=\"%s\" points=\"", colour[i % 5]);
        for (j = 0; j < nt; ++j) {
            double v = curve_eval(&cs[i], cos(theta[j] * (PI / 180.0)));
            double x, y;
            if (!(v > 0.0) || v > 1e300) continue;
            x = px(p, theta[j]);
            y = py(p, log10(v));
            /* drop points within 0.3 px of the last one written */
            if (!first && j + 1 < nt && fabs(x - lx) < 0.3 && fabs(y - ly) < 0.3)
                continue;
            fprintf(f, "%s%.2f,%.2f", first ? "" : " ", x, y);
            lx = x; ly = y; first = 0;
        }
        fputs("\"/>\n", f);
    }
    fputs("</g>\n", f);

    /* frame */
    fprintf(f, "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"none\" "
               "stroke=\"#333\"/>\n", p->x, p->y, p->w, p->h);

    /* legend, to the right of the plot area; a fog curve also lists its
     * four parameters on two small lines */
    for (i = 0; i < n; ++i) {
        int fog = cs[i].fam == FOG;
        double lx = p->x + p->w + 14, ly = p->y + 10 + i * (fog ? 46 : 20);
        fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" "
                   "stroke-width=\"2.5\"/>\n", lx, ly, lx + 22, ly, colour[i % 5]);
        fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"12\">%s</text>\n",
                lx + 28, ly + 4, labels[i]);
        if (fog) {
            fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"10\" fill=\"#555\">"
                       "g" SUB("HG") "= %.4f, w" SUB_END SUB("D") "= %.3f" SUB_END
                       "</text>\n",
                    lx + 28, ly + 18, cs[i].fog.g_hg, cs[i].fog.w_d);
            fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"10\" fill=\"#555\">"
                       "g" SUB("D") "= %.3f, &#945;&#160;= %.2f" SUB_END "</text>\n",
                    lx + 28, ly + 31, cs[i].fog.g_d, cs[i].fog.alpha);
        }
    }
}

/* Decade range [floor, ceil] of log10 of the curves over the panel's theta. */
static void panel_range(panel *p, const curve *cs, int n)
{
    double theta[NLIN + 16], lo = 1e300, hi = -1e300;
    int nt = p->xlog ? theta_log(theta) : theta_linear(theta), i, j;
    for (i = 0; i < n; ++i)
        for (j = 0; j < nt; ++j) {
            double v = curve_eval(&cs[i], cos(theta[j] * (PI / 180.0)));
            if (!(v > 0.0) || v > 1e300) continue;
            if (log10(v) < lo) lo = log10(v);
            if (log10(v) > hi) hi = log10(v);
        }
    if (!(lo <= hi)) lo = hi = 0.0;     /* no positive value: one decade (cppcheck) */
    p->y0 = (int)floor(lo);
    p->y1 = (int)ceil(hi);
    if (p->y1 - p->y0 < 2) p->y1 = p->y0 + 2;
}

/* ------------------------------------------------------------------------ */

#define NCURVE 19


int main(int argc, char **argv)
{
    static const double gs[5] = { 0.0, 0.3, 0.6, 0.9, -0.5 };
    static const double alphas[4] = { 0.0, 1.0, 17.0, 250.0 };
    static const double ds[4] = { 5.0, 10.0, 20.0, 50.0 };
    char defpath[4096];
    const char *path = argc > 1 ? argv[1] : beside_program(defpath, sizeof defpath, argv[0],
                                                           "phase_functions.svg");
    curve cs[NCURVE];
    char lab[NCURVE][64];
    const char *labp[NCURVE];
    int first[NFAMILY + 1];
    int n = 0, i, fam;
    FILE *f;

    /* the curves, family by family */
    for (fam = HG; fam < NFAMILY; ++fam) {
        first[fam] = n;
        if (fam == HG || fam == CS)
            for (i = 0; i < 5; ++i, ++n) {
                cs[n].fam = (enum family)fam;
                cs[n].g = gs[i];
                cs[n].alpha = fam == CS ? 1.0 : 0.0;
                sprintf(lab[n], "g = %g", gs[i]);
            }
        else if (fam == DRAINE)
            for (i = 0; i < 4; ++i, ++n) {
                cs[n].fam = DRAINE;
                cs[n].g = 0.5;
                cs[n].alpha = alphas[i];
                sprintf(lab[n], "g = 0.5, &#945; = %g", alphas[i]);
            }
        else if (fam == RAYLEIGH) {
            cs[n].fam = RAYLEIGH;
            cs[n].g = cs[n].alpha = 0.0;
            sprintf(lab[n++], "3/(16&#960;) (1 + cos&#178;&#952;)");
        } else
            for (i = 0; i < 4; ++i, ++n) {
                cs[n].fam = FOG;
                cs[n].d = ds[i];
                cs[n].fog = fog_from_diameter(ds[i]);
                sprintf(lab[n], "d = %g &#181;m", ds[i]);
            }
    }
    first[NFAMILY] = n;
    for (i = 0; i < n; ++i) labp[i] = lab[i];

    /* 1. the SVG: a 2 x 3 grid of panels */
    f = fopen(path, "w");
    if (!f) { perror(path); return 1; }
    {
        static const char *titles[6] = {
            "Henyey-Greenstein", "Cornette-Shanks", "Draine (g = 0.5)", "Rayleigh",
            "Fog, Jendersie-d'Eon (5-50 &#181;m fit)",
            "Fog, forward peak (log &#952; axis)"
        };
        const double cw = 640, ch = 340, top = 70;
        fputs("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
              "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" "
              "width=\"1280\" height=\"1110\" viewBox=\"0 0 1280 1110\" "
              "font-family=\"Helvetica, Arial, sans-serif\">\n"
              "<rect width=\"1280\" height=\"1110\" fill=\"white\"/>\n", f);
        fprintf(f, "<text x=\"640\" y=\"30\" font-size=\"20\" font-weight=\"bold\" "
                   "text-anchor=\"middle\">mist %s: phase functions, density per "
                   "steradian against scattering angle</text>\n", MIST_VERSION_STRING);
        fputs("<text x=\"640\" y=\"50\" font-size=\"12\" fill=\"#555\" text-anchor=\"middle\">"
              "&#952; between incident and scattered propagation directions: "
              "0 = straight on (forward), 180 = back</text>\n", f);
        for (i = 0; i < 6; ++i) {
            int fm = i < 5 ? i : FOG;
            panel p;
            p.x = (i % 2) * cw + 80;
            p.y = top + (i / 2) * ch + 30;
            p.w = cw - 80 - 190;
            p.h = ch - 30 - 60;
            p.xlog = i == 5;
            p.id = i;
            p.x0 = p.xlog ? 0.01 : 0.0;
            p.x1 = 180.0;
            panel_range(&p, cs + first[fm], first[fm + 1] - first[fm]);
            draw_panel(f, &p, titles[i], cs + first[fm], labp + first[fm],
                       first[fm + 1] - first[fm]);
        }
        fputs("<text x=\"640\" y=\"1090\" font-size=\"11\" fill=\"#555\" "
              "text-anchor=\"middle\">Fog: Jendersie &amp; d'Eon 2023, large-droplet fit "
              "(eq. 7-10, 5-50 &#181;m), the constants of eq. 8 and 10 read inside the "
              "exponential as in Blender Cycles.</text>\n</svg>\n", f);
    }
    if (fclose(f) != 0) { perror(path); return 1; }

    /* 2. the table */
    printf("mist %s: normalisation int 2pi p(u) du and mean cosine int u 2pi p(u) du\n"
           "(adaptive Gauss-Kronrod 7-15 over u in [-1, 1]), closed form beside it\n\n",
           MIST_VERSION_STRING);
    printf("%-16s %-18s %14s %12s %12s\n", "curve", "parameters", "normalisation",
           "<u> quad", "<u> closed");
    for (i = 0; i < n; ++i) {
        char par[64];
        double norm = integrate(&cs[i], 0), mean = integrate(&cs[i], 1);
        double exact = curve_mean_exact(&cs[i]);
        switch (cs[i].fam) {
        case HG: case CS: sprintf(par, "g = %g", cs[i].g); break;
        case DRAINE:      sprintf(par, "g = %g, a = %g", cs[i].g, cs[i].alpha); break;
        case FOG:         sprintf(par, "d = %g um", cs[i].d); break;
        default:          sprintf(par, "-"); break;
        }
        if (fabs(mean) < 5e-9) mean = 0.0;        /* no "-0.00000000" */
        printf("%-16s %-18s %14.10f %12.8f %12.8f\n",
               family_name[cs[i].fam], par, norm, mean, exact);
    }
    printf("\nFog parameters (JD23 eq. 7-10, constants inside exp as in Cycles):\n");
    for (i = first[FOG]; i < first[FOG + 1]; ++i)
        printf("  d = %2g um: g_hg = %.6f  g_d = %.6f  alpha = %8.4f  w_d = %.6f\n",
               cs[i].d, cs[i].fog.g_hg, cs[i].fog.g_d, cs[i].fog.alpha, cs[i].fog.w_d);
    printf("\nwrote %s\n", path);
    return 0;
}
