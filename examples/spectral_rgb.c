/* spectral_rgb.c - how far the common shortcut of one wavelength per
 * channel (650, 510, 440 nm for R, G, B) is from the phase functions
 * integrated over the visible spectrum (mist_mie_spectral_rgb: CIE 1931
 * 2-degree observer, D65, linear sRGB, 380-780 nm every 5 nm), for water
 * droplets of diameter 2, 10 and 20 um (tests/mist_fitref.h's sizes:
 * lognormal of geometric width 1.1, 200 radii).  Per channel: L1 = int |p_short
 * - p_spectral| dOmega and logRMS = RMS over theta of log10(p_short /
 * p_spectral), both normalised, on the fit grid of examples/fit_error.c
 * (1001 angles), and the ratio of the channels' cross sections.  Then the
 * colour of the light scattered into the fogbow (138-145 degrees) and the
 * glory (175-180 degrees) under D65: the mean of c_sca[c] p_c over the band
 * (the grid's angles there, 0.25 degrees apart), as CIE xy, and each
 * channel's ratio shortcut / spectral.  Prints Markdown tables.  With the
 * argument "solar": sunlight above the atmosphere (mist_mie_solar) in
 * place of D65.
 *
 * Build and run (from the repository root):
 *   cc -std=c99 -O2 -Iinclude -Itests examples/spectral_rgb.c -o spectral_rgb -lm
 *   ./spectral_rgb [solar]   (about 20 s: 84 size averages per diameter) */
#include "mist.h"
#include "mist_mie.h"
#include "mist_fitref.h"
#include <string.h>

static double spec[NTH * 3], sp[3][NTH], sh[3][NTH];

/* CIE xy of linear sRGB (IEC 61966-2-1's sRGB -> XYZ) */
static void srgb_xy(const double *rgb, double *x, double *y)
{
    double X = 0.4124 * rgb[0] + 0.3576 * rgb[1] + 0.1805 * rgb[2];
    double Y = 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
    double Z = 0.0193 * rgb[0] + 0.1192 * rgb[1] + 0.9505 * rgb[2];
    *x = X / (X + Y + Z);
    *y = Y / (X + Y + Z);
}

/* the mean of c[k] p[k](theta) over theta in [a, b] degrees, per channel */
static void band(double p[3][NTH], const double *c, double a, double b, double *rgb)
{
    int i, k, n = 0;
    for (k = 0; k < 3; ++k) rgb[k] = 0;
    for (i = 0; i < NTH; ++i) {
        double d = th[i] * 180 / PI;
        if (d < a - 1e-9 || d > b + 1e-9) continue;
        for (k = 0; k < 3; ++k) rgb[k] += c[k] * p[k][i];
        ++n;
    }
    for (k = 0; k < 3; ++k) rgb[k] /= n;
}

int main(int argc, char **argv)
{
    static double solar[MIST_MIE_CIE_N];
    const double *spd = NULL;
    static const double D[3] = { 2, 10, 20 }, LAM[3] = { 650, 510, 440 };
    static const double BA[2] = { 138, 175 }, BB[2] = { 145, 180 };
    static const char *CH = "RGB", *BN[2] = { "fogbow 138-145", "glory 175-180" };
    double cs[3][3], csp[3][3], l1[3][3], lr[3][3], xy[3][2][4], ratio[3][2][3];
    size_t neg[3];
    int k, c, i, b;
    fitref_grid();
    if (argc > 1 && strcmp(argv[1], "solar") == 0) {
        for (i = 0; i < MIST_MIE_CIE_N; ++i) solar[i] = mist_mie_solar(380 + 5 * i);
        spd = solar;
    }
    printf("Illuminant: %s\n\n", spd ? "extraterrestrial sunlight (mist_mie_solar)" : "D65");
    for (k = 0; k < 3; ++k) {
        mist_mie_dist dist = mist_mie_dist_lognormal(D[k] / 2, 1.1);
        mist_mie_rgb r;
        dist.n_radii = 200;
        r = mist_mie_spectral_rgb(&dist, 1.0, NULL, spd, MIST_MIE_CIE_N, mu, NTH, spec);
        if (r.status != MIST_MIE_OK) { printf("spectral: %d\n", r.status); return 1; }
        neg[k] = r.negative;
        for (c = 0; c < 3; ++c) {
            mist_mie_wavelength wl = mist_mie_wl(LAM[c] / 1000, 1, mist_mie_water(LAM[c], NULL));
            mist_mie_avg a = mist_mie_average(&dist, &wl, 1, 1.0, mu, NTH, sh[c]);
            if (a.status != MIST_MIE_OK) { printf("average: %d\n", a.status); return 1; }
            for (i = 0; i < NTH; ++i) sp[c][i] = spec[i * 3 + c];
            cs[k][c] = a.c_sca;
            csp[k][c] = r.c_sca[c];
            fitref_errors(sh[c], sp[c], &l1[k][c], &lr[k][c]);
        }
        for (b = 0; b < 2; ++b) {
            double rs[3], rh[3];
            band(sp, csp[k], BA[b], BB[b], rs);
            band(sh, cs[k], BA[b], BB[b], rh);
            srgb_xy(rs, &xy[k][b][0], &xy[k][b][1]);
            srgb_xy(rh, &xy[k][b][2], &xy[k][b][3]);
            for (c = 0; c < 3; ++c) ratio[k][b][c] = rh[c] / rs[c];
        }
    }
    printf("| d (um) | channel | L1 | logRMS | c_sca shortcut / spectral |\n"
           "|---|---|---|---|---|\n");
    for (k = 0; k < 3; ++k)
        for (c = 0; c < 3; ++c)
            printf("| %g | %c (%g nm) | %.4f | %.4f | %.4f |\n", D[k], CH[c], LAM[c], l1[k][c],
                   lr[k][c], cs[k][c] / csp[k][c]);
    printf("\n| d (um) | band (deg) | xy spectral | xy shortcut | dxy | R, G, B shortcut / "
           "spectral |\n|---|---|---|---|---|---|\n");
    for (k = 0; k < 3; ++k)
        for (b = 0; b < 2; ++b)
            printf("| %g | %s | %.4f, %.4f | %.4f, %.4f | %.4f | %.3f, %.3f, %.3f |\n", D[k],
                   BN[b], xy[k][b][0], xy[k][b][1], xy[k][b][2], xy[k][b][3],
                   sqrt((xy[k][b][0] - xy[k][b][2]) * (xy[k][b][0] - xy[k][b][2])
                        + (xy[k][b][1] - xy[k][b][3]) * (xy[k][b][1] - xy[k][b][3])),
                   ratio[k][b][0], ratio[k][b][1], ratio[k][b][2]);
    printf("\n(spectral channel values below 0, set to 0: %lu, %lu, %lu of %d)\n",
           (unsigned long)neg[0], (unsigned long)neg[1], (unsigned long)neg[2], 3 * NTH);
    (void)fitref_compare;          /* (tests/mist_fitref.h's; not used here) */
    return 0;
}
