/* tab_size.c - how many nodes a tabulated phase function (mist_tab, linear
 * in mu) needs for fog, and the error it then has: mist_mie_tab_nodes at
 * requested log-RMS errors, for water droplets of diameter 2, 10 and 50
 * um (tests/mist_fitref.h's reference: lognormal sizes of geometric width
 * 1.1, 450/550/650 nm averaged, 200 radii), and for comparison tables of
 * the same size with nodes uniform in theta.  The errors are measured
 * independently of the builder: the table (mist_tab_eval) against the
 * reference on the fit grid of examples/fit_error.c (1001 angles,
 * geometric from 1e-3 to 5 degrees, then uniform): logRMS = RMS over theta
 * of log10(p / p_Mie), L1 = int |p - p_Mie| dOmega.  Prints a Markdown
 * table.
 *
 * Build and run (from the repository root):
 *   cc -std=c99 -O2 -Iinclude -Itests examples/tab_size.c -o tab_size -lm
 *   ./tab_size          (about a minute: the 50 um reference is the cost) */
#include "mist.h"
#include "mist_mie.h"
#include "mist_fitref.h"

#define NMAX 4096

static double tmu[NMAX], tp[NMAX];

/* the table's errors on the fit grid */
static void tab_errors(const double *m, const double *p, size_t n, const double *ref,
                       double *l1, double *lrms)
{
    static double q[NTH];
    size_t bytes = mist_tab_bytes(n, 1);
    mist_tab *t = (mist_tab *)malloc(bytes);
    int i;
    if (!t || mist_tab_init(t, bytes, m, p, n, 1) != 0) { printf("table failed\n"); exit(1); }
    for (i = 0; i < NTH; ++i) q[i] = mist_tab_eval(t, mu[i], NULL);
    fitref_errors(q, ref, l1, lrms);
    free(t);
}

int main(void)
{
    static const double D[3] = { 2, 10, 50 }, TARGET[3] = { 0.03, 0.01, 0.003 };
    static double ref[NTH], um[16385], up[16385];
    int k, j;
    fitref_grid();
    printf("| d (um) | target logRMS | nodes | logRMS | L1 | theta-uniform, same nodes: "
           "logRMS | L1 |\n|---|---|---|---|---|---|---|\n");
    for (k = 0; k < 3; ++k) {
        mist_mie_wavelength wl[3];
        mist_mie_dist dist = mist_mie_dist_lognormal(D[k] / 2, 1.1);
        dist.n_radii = 200;
        wl[0] = mist_mie_wl(0.45, 1, mist_mie_water(450, NULL));
        wl[1] = mist_mie_wl(0.55, 1, mist_mie_water(550, NULL));
        wl[2] = mist_mie_wl(0.65, 1, mist_mie_water(650, NULL));
        fitref_mie(D[k], ref, 200);
        for (j = 0; j < 3; ++j) {
            double l1, lr, ul1, ulr;
            size_t i, n;
            mist_mie_tabfit r = mist_mie_tab_nodes(&dist, wl, 3, 0, 1.0, TARGET[j], 1.0, NMAX,
                                                   tmu, tp);
            if (r.status != MIST_MIE_OK) { printf("mist_mie_tab_nodes: %d\n", r.status); return 1; }
            n = r.n;
            tab_errors(tmu, tp, n, ref, &l1, &lr);
            /* the same number of nodes uniform in theta */
            mist_mie_theta_grid(n, um);
            for (i = 0; i < n / 2; ++i) { double s = um[i]; um[i] = um[n - 1 - i]; um[n - 1 - i] = s; }
            fitref_mie_at(D[k], um, n, up, 200);
            tab_errors(um, up, n, ref, &ul1, &ulr);
            printf("| %g | %g | %zu | %.4f | %.4f | %.4f | %.4f |\n", D[k], TARGET[j], n, lr, l1,
                   ulr, ul1);
            fflush(stdout);
        }
    }
    (void)fitref_compare;          /* (tests/mist_fitref.h's; not used here) */
    return 0;
}
