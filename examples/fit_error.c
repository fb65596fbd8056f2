/* fit_error.c - how far the Jendersie-d'Eon droplet fits are from Lorenz-Mie.
 *
 * For each droplet diameter d, the reference is the Mie phase function of
 * water droplets (include/mist_mie.h) under these assumptions:
 *   - refractive index of water, Hale & Querry 1973 (mist_mie_water), in air
 *     (n_medium = 1: air's 1.0003 changes x by 3e-4);
 *   - three wavelengths, 450, 550 and 650 nm, equal weights: the fit has no
 *     wavelength parameter and renderers use it for all of RGB, so it is
 *     meant to match the visible average;
 *   - a narrow lognormal size distribution, median diameter d, geometric
 *     standard deviation 1.1 (radii within +-10%): a four-parameter smooth fit
 *     cannot follow the resonance ripple of one exact size, and real fog is
 *     never monodisperse; 1.1 smooths the ripple yet keeps the shape at d.
 *   - intensities and cross sections averaged, not normalised phase functions
 *     (mist_mie_average).
 * Error metrics, over a theta grid fine near the forward peak:
 *   L1     = int |p_fit - p_mie| dOmega  (0: equal, 2: disjoint);
 *   logRMS = sqrt(1/pi int_0^pi log10(p_fit / p_mie)^2 dtheta), the log-space
 *            kind of error a fit of phase-function plots minimises.
 * Columns: the fit (eq. 7-22, eq. 8 and 10 read with the constants inside
 * the exponential, as mist does), mist_fog_from_diameter_mie (the same
 * mix fitted to this reference by tools/fit_droplet.c, continuous in d),
 * the printed reading of eq. 8 and 10 (5-50 um only), and HG with the Mie
 * asymmetry g as the baseline a renderer would otherwise use.
 *
 * Run: ./build/mist_fit_error  (prints a Markdown table; README "Fit error"
 * is its output). */
#include "mist.h"
#include "mist_mie.h"
#include "mist_fitref.h"

#include <stdio.h>
#include <stdlib.h>

int main(int argc, char **argv)
{
    static const double ds[] = { 0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1, 1.5, 2, 3, 5, 7, 10,
                                 15, 20, 30, 50 };
    int n_radii = argc > 1 ? atoi(argv[1]) : 200;
    size_t k, nd = sizeof ds / sizeof *ds;
    double gm[4] = { 0, 0, 0, 0 };
    fitref_grid();
    printf("| d (um) | Mie g | fit L1 | fit logRMS | fitted to Mie: L1 | logRMS "
           "| printed eq. 8, 10: L1 | logRMS | HG(g_Mie) L1 | logRMS |\n"
           "|---|---|---|---|---|---|---|---|---|---|\n");
    for (k = 0; k < nd; ++k) {
        double d = ds[k];
        fitref_row r = fitref_compare(d, n_radii);
        if (d >= 5)
            printf("| %g | %.4f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f |\n", d,
                   r.g, r.l1, r.lr, r.l1m, r.lrm, r.l1p, r.lrp, r.l1h, r.lrh);
        else
            printf("| %g | %.4f | %.3f | %.3f | %.3f | %.3f | | | %.3f | %.3f |\n", d, r.g, r.l1,
                   r.lr, r.l1m, r.lrm, r.l1h, r.lrh);
        gm[0] += log(r.l1); gm[1] += log(r.lr); gm[2] += log(r.l1m); gm[3] += log(r.lrm);
        fflush(stdout);
    }
    printf("\nGeometric means over these diameters: the fits L1 %.3f, logRMS %.3f; fitted to "
           "Mie L1 %.3f, logRMS %.3f\n", exp(gm[0] / (double)nd), exp(gm[1] / (double)nd),
           exp(gm[2] / (double)nd), exp(gm[3] / (double)nd));
    return 0;
}
