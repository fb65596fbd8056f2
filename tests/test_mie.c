/* test_mie.c - the Lorenz-Mie reference (include/mist_mie.h) against
 * published values and independent checks:
 *   - Wiscombe's MIEV0 test driver: all 19 cases (Q_ext, Q_sca, g Q_sca,
 *     S1, S2 at 0, 30, ..., 180 degrees);
 *   - Du (2004), Table 1 (Q_ext, Q_sca) and Table 2 (S1 at 0 and 180 deg);
 *   - Bohren & Huffman's Appendix A example (efficiencies and the S11, POL,
 *     S33, S34 table) and two further cases computed by miepython;
 *   - m close to 1 (small x, x to 20000, the dipole limit) against an
 *     mpmath series, with negative controls; S1(1) = S2(1), S2(-1) =
 *     -S1(-1) exactly; the dipole limit with a subnormal m - 1;
 *   - the small-particle limits; normalisation and mean cosine of the phase
 *     function by quadrature; no NaN or overflow up to x = 1e4 (and 1e5);
 *   - size-distribution averages against an independent trapezoid rule and
 *     closed-form moments; wavelength averages; water's index table; the
 *     averages' workspace at the steps of the term count;
 *   - the spectral-to-RGB tables (CIE 1931, D65) against the standard's
 *     white points; the spectral integration against Rayleigh's closed form;
 *   - bad input gets the documented result;
 *   - the benchmark's workload (1800 angles x 3 wavelengths, one droplet of
 *     10 and 50 um) gives a valid average; its speed is the benchmark's.
 * Set MIST_VERBOSE=1 in the environment to print the worst deviations. */
#include "mist_mie.h"
#include "mist_test.h"

#include <string.h>
#include <time.h>

#define PI 3.14159265358979323846

static int verbose = 0;

/* One unit in the last digit of a value published with `sig` significant
 * digits. */
static double last_unit(double ref, int sig)
{
    double a = fabs(ref);
    if (a == 0) return 0;
    return pow(10, floor(log10(a)) - sig + 1);
}

/* |got - ref| <= units x (one unit in the last published digit) + abs_floor */
static int near_pub(double got, double ref, int sig, double units, double abs_floor)
{
    return fabs(got - ref) <= units * last_unit(ref, sig) + abs_floor && got == got;
}

static int near_rel(double got, double ref, double rel)
{
    return fabs(got - ref) <= rel * fabs(ref) && got == got;
}

static mist_mie_complex conj_c(mist_mie_complex z) { return mist_mie_cplx(z.re, -z.im); }

/* ======================================================================== */
/* The series' tail: against an independent mpmath series                   */
/* tests/mie_mpmath_ref.py (the Riccati-Bessel recurrences upward at 40+    */
/* digits plus those the recurrence loses, to N + 40 terms, checked with 25 */
/* digits more) printed these to 17 digits.  Wiscombe's N alone leaves its  */
/* tail in the results: below x = 0.0148 (N = 1) b_1 and a_2 are dropped    */
/* (Q_back and p off by 0.2 x^2, g by 30-46%; found by an independent       */
/* check), past x ~ 20 Q_back keeps 1e-7 (x = 339) to 6.3e-6 (x = 1e4,      */
/* nearly lossless: Du's case f), and a narrow resonance of an order past N */
/* is missed (m = 4 at 1e-9 from the peak: 2e-5; m = 30 at 1e-10: 0.012 for */
/* 0.47).  mist_mie sums on until a term is below 1e-18 of the largest.     */
/* Tolerance 1e-11 + 1e-13 N relative (g: of max(|g|, 1e-3)): the series'   */
/* rounding, which grows with the N terms its recurrences run over:         */
/* measured 3.5e-13 (x = 0.003), 5e-12 (x = 339, Q_back), 1e-10 (x = 1e4):  */
/* 10-30x inside; the dropped tails are 4.7e-10 (x = 5.2, 40x the tolerance */
/* there) to 0.97.                                                          */
/* Next to the resonances the results move by their sensitivity to x times  */
/* the roundings of x and m x (~1e-16): m = 4, 1e-9 from its peak (width    */
/* ~1e-11): the resonant part, 1.5e-2 of Q_back, changes by 2/1e-9 per unit */
/* of relative x: 3e7 x 4 eps ~ 3e-8, tolerance 1e-7 (measured 6.3e-10); m  */
/* = 30, 1e-10 from its peak, where Q is all resonance: 2e10 x 4 eps ~      */
/* 2e-5, tolerance 1e-4 (measured 4e-8).  The header before the sixth       */
/* session of 2026-11-27 fails 67 of these 91 checks.                       */
/* ======================================================================== */
static void test_series_tail(void)
{
    static const double ref[][10] = {
        {1e-06, 1.33, 0.0,
         1.1098881769078389e-25, 1.1098881769078389e-25,
         1.8327783260423164e-13, 1.6648322653610201e-25,
         1.1936620731897443e-1, 5.9683103659460751e-2, 1.1936620731886857e-1},
        {0.003, 0.75, 0.0,
         6.2962140849304419e-12, 6.2962140849304419e-12,
         1.3278427834844047e-6, 9.4442890059550481e-12,
         1.1936661330061673e-1, 5.9683103659346966e-2, 1.1936580133796341e-1},
        {0.01, 1.5, 0.1,
         1.9926315271122832e-3, 2.402255032440821e-9,
         1.9797349304062521e-5, 3.6032126624117377e-9,
         1.193718351181568e-1, 5.9683103636591729e-2, 1.193605796407597e-1},
        {0.007748, 1000.0, 0.0,
         1.1960948592156536e-8, 1.1960948592156536e-8,
         -3.9796275018393078e-1, 3.2217967773199707e-8,
         2.4344543603120384e-2, 5.9692674555343726e-2, 2.1434958891314874e-1},
        {0.0119817209456378, 431.86451, 0.1,
         1.7995814794828517e-5, 5.9891456796744243e-8,
         -2.7490183902820003e-1, 1.3922591430101408e-7,
         5.3735664944442883e-2, 5.9685101492426256e-2, 1.8498875843590726e-1},
        {0.099, 0.75, 0.0,
         7.4178591149122304e-6, 7.4178591149122304e-6,
         1.4482309882535273e-3, 1.1085554050132108e-5,
         1.1980944150639779e-1, 5.9682968368107473e-2, 1.1892384963500223e-1},
        {0.3, 1.33, 0.0,
         8.924603817483722e-4, 8.924603817483722e-4,
         1.6435545442861088e-2, 1.2859856110276818e-3,
         1.241559741103193e-1, 5.9666664561149909e-2, 1.1466669609419906e-1},
        {4.301104666247005, 4.0, 0.0,
         1.6899313247569444, 1.6899313247569444,
         3.1575986926186165e-1, 3.8633097445168307,
         6.5954034327388816e-1, 5.1877122246254963e-2, 1.8192006785345975e-1},
        {0.2328940182647092, 30.0, 0.0,
         4.7081862609148322e-1, 4.7081862609148322e-1,
         -1.1847916697092218e-2, 1.5638306514145283,
         3.3125354290867034e-1, 7.9352730124858152e-2, 2.643176847074011e-1},
        {5.212822, 1.55, 0.0,
         3.1054199767788696, 3.1054199767788696,
         6.331363400773825e-1, 2.9253260153863894,
         1.9562849715671546, 2.4375569111904801e-2, 7.4962500883212217e-2},
        {339.04523060942176, 2.813618935933415, 0.0001,
         2.1121544860876372, 1.9903913639302782,
         6.4218270013510417e-1, 2.3735212243555708e-1,
         5.1359825023748749e+3, 3.5777812792112903e-2, 9.4895316126117688e-3},
        {1000.0, 1.33, 0.01,
         2.0198370226941349, 1.0785038040930087,
         9.7193799778076317e-1, 2.0077368262494519e-2,
         7.5270770615397822e+4, 2.0323890537464468e-3, 1.4814098898517991e-3},
        {10000.0, 1.33, 1e-05,
         2.0040889342296031, 1.7238572177488215,
         9.0784036607211531e-1, 3.7571933750882999e-2,
         4.6351833086079912e+6, 1.134810823633208e-3, 1.7344124897371691e-3},
    };
    static const char *name[7] = { "Qext", "Qsca", "g", "Qback", "p(1)", "p(0)", "p(-1)" };
    size_t i;
    int k;
    double worst = 0;
    for (i = 0; i < sizeof ref / sizeof ref[0]; ++i) {
        const double *r = ref[i];
        mist_mie_sphere s = mist_mie_sphere_new(r[0], mist_mie_cplx(r[1], r[2]));
        double got[7], tol = r[1] == 30 ? 1e-4 : r[1] == 4 ? 1e-7
                       : 1e-11 + 1e-13 * mist_mie_terms(r[0]), cw = 0;
        got[0] = s.q_ext; got[1] = s.q_sca; got[2] = s.g; got[3] = s.q_back;
        got[4] = mist_mie_phase(&s, 1); got[5] = mist_mie_phase(&s, 0);
        got[6] = mist_mie_phase(&s, -1);
        for (k = 0; k < 7; ++k) {
            double sc = k == 2 ? (fabs(r[5]) > 1e-3 ? fabs(r[5]) : 1e-3) : fabs(r[3 + k]);
            double e = fabs(got[k] - r[3 + k]) / sc;
            if (e > cw) cw = e;
            if (e / tol > worst) worst = e / tol;
            mt_check(e <= tol, "series tail x=%.17g m=%g+%gi %s: %.17g vs %.17g (%.2e)",
                     r[0], r[1], r[2], name[k], got[k], r[3 + k], e);
        }
        if (verbose) printf("  x=%g m=%g: %.2e\n", r[0], r[1], cw);
        mist_mie_sphere_free(&s);
    }
    if (verbose) printf("series tail: worst %.2f of the tolerance\n", worst);
}

/* ======================================================================== */
/* m close to 1: against the mpmath series                                  */
/* tests/mie_mpmath_ref.py near1 printed these to 20 digits (Q_sca, g,      */
/* Q_back, then S1, S2 at mu = 0.5 and at mu = -1, re and im; the series    */
/* at 40 digits plus those its recurrences and m - 1 cost, checked with 25  */
/* more).  Values below double's range are written 0.                       */
/* Where n > max(x, |m| x) the coefficients come from recurrences with      */
/* (m^2 - 1) factored out (mist_mie.h, the sphere): at x |m| < 1 that is    */
/* every term, and Q, g and S are within a few eps whatever m - 1 (the      */
/* dipole limit, x |m| < 1e-8, adds g's leading term 0.16 x^2, exact to    */
/* O(x^2 |m|^2) relative).  Tolerance 1e-13 relative there (measured at     */
/* most 1e-15; the cancelling numerator had given g 3.1e-7 off at m =       */
/* 1.0001, x = 0.003, 0.6 at x = 1e-7).  At x |m| >= 1 the terms n <=      */
/* |m| x still lose 1/|m - 1| of their digits: Q_sca, g and S within       */
/* 1e-15 / |m - 1| relative (measured at most 4e-16 / |m - 1|: g at x =    */
/* 1.5, m = 1 + 1e-7).  The amplitudes also carry the rounding of their N  */
/* ~ x terms, each up to (2n+1)/2 |a_n - b_n| <= 2n: a random walk of       */
/* eps sqrt(sum 4 n^2) = 1.2 eps x^(3/2) absolutely, tolerance 2 eps        */
/* x^(3/2) (measured at most 0.49 of it: S(-1) at x = 8000, m = 1.001).    */
/* Q_back = 4 |S1(-1)|^2 / x^2 is tiny for m near 1 (the sum cancels), so   */
/* that absolute error is 2 |dS| / |S1(-1)| = 4 eps sqrt(x / Q_back) of it  */
/* relative, far above 1e-15 / |m - 1|: 1.4e-9 at x = 8000, m = 1.0001     */
/* (Q_back = 9.8e-11), where 4 eps sqrt(x / Q_back) is 8e-9.  Every check  */
/* is also made with the reference moved by 10 tolerances: it must fail    */
/* (negative control).                                                      */
/* ======================================================================== */
static const double near1_ref[][14] = {
        {0.003, 1.0001, 0.0,
         9.5996454104447722391e-19, 1.4400535433318919492e-6, 1.4399416276220842743e-18,
         2.1599202173486741113e-24, -1.7999683769348617333e-12, 1.0799601086748621128e-24, -8.9998418856463281335e-13,
         2.1599202173444749142e-24, -1.7999635168940757595e-12, -2.1599202173444749142e-24, 1.7999635168940757595e-12},
        {0.01, 1.0001, 0.0,
         1.1850982820254753027e-16, 1.600067807306519725e-5, 1.7775763155703542023e-16,
         2.9627457048266486332e-21, -6.6664889127541853704e-11, 1.4813728525022408886e-21, -3.3332444603771740464e-11,
         2.9627457041155293929e-21, -6.6662889143254852563e-11, -2.9627457041155293929e-21, 6.6662889143254852563e-11},
        {0.005, 1.001, 0.0,
         7.4048613372694794371e-16, 4.0014732392446327768e-6, 1.1107180903472037661e-15,
         4.6280383357702675971e-21, -8.3319218810817056467e-11, 2.3140191678938438143e-21, -4.1659609530433501081e-11,
         4.6280383357007958657e-21, -8.3318593751155112899e-11, -4.6280383357007958657e-21, 8.3318593751155112899e-11},
        {1e-07, 1.0001, 0.0,
         1.1851456740743787025e-36, 1.6000586702400135605e-15, 1.7777185111115609427e-36,
         2.9628641851859464881e-51, -6.6665555407413569534e-26, 1.4814320925929732441e-51, -3.3332777703706784771e-26,
         2.9628641851859464881e-51, -6.6665555407413369532e-26, -2.9628641851859464881e-51, 6.6665555407413369532e-26},
        {2e-08, 1.000001, 1e-06,
         3.7925913280832683307e-43, 6.4000023466666668876e-17, 5.6888869921249015859e-43,
         5.3333315555531852115e-30, -5.3333333328969485647e-30, 2.6666657777765926058e-30, -2.6666666664484742823e-30,
         5.3333315555531845715e-30, -5.3333333328969479247e-30, -5.3333315555531845715e-30, 5.3333333328969479247e-30},
        {0.05, 1.00001, 0.0,
         7.3999799729629241287e-16, 4.0005857735684225037e-4, 1.1088871229680138136e-15,
         4.6249872517847012433e-19, -8.3312364169576629475e-10, 2.312493712638874523e-19, -4.1656182209789647551e-10,
         4.6249865578333396618e-19, -8.3249892003233776582e-10, -4.6249865578333396618e-19, 8.3249892003233776582e-10},
        {0.3, 1.0001, 0.0001,
         1.852303378378912106e-10, 1.447319698057287501e-2, 2.6788528507701948888e-10,
         1.7838097604195735679e-6, -1.783847825662522207e-6, 8.9190682521282415019e-7, -8.9192391268459759652e-7,
         1.7359842986565703298e-6, -1.7360234529092035521e-6, -1.7359842986565703298e-6, 1.7360234529092035521e-6},
        {1.5, 1.0001, 0.0,
         2.706468105851942875e-8, 3.7675667714048325464e-1, 1.0754167828301654668e-8,
         1.4495274354319994654e-8, -1.7828297165419369128e-4, 7.5163672752023221569e-9, -8.9144611541402060326e-5,
         1.2364402709098220889e-8, -7.7776726920983415719e-5, -1.2364402709098220889e-8, 7.7776726920983415719e-5},
        {30.0, 1.0001, 0.0,
         1.7919658989538479985e-5, 9.9568202856066532038e-1, 8.933159040140322882e-9,
         2.7394208607733912165e-6, 1.1394426619713363587e-3, 3.8288903559268793944e-6, 5.6969276278822943634e-4,
         8.1146658418645370293e-6, -1.4177076342567417822e-3, -8.1146658418645370293e-6, 1.4177076342567417822e-3},
        {8000.0, 1.0001, 0.0,
         1.1093011853434401464, 9.9999982866945482006e-1, 9.8254428419940331495e-11,
         7.6797509060793468315e-1, -7.4694375599006293736e-1, 3.8367352992267946168e-1, -3.7359897059480653445e-1,
         3.9631561462971435634e-2, -1.1875145160218903313e-3, -3.9631561462971435634e-2, 1.1875145160218903313e-3},
        {100.0, 1.0001, 0.0,
         1.9990983765420460484e-4, 9.9949290779035391368e-1, 2.5850513501962383996e-9,
         -1.8275996780908927702e-4, 1.7455888351239677189e-2, -9.2741188449747503449e-5, 8.7312776503021931713e-3,
         -4.749052846085024655e-5, 2.5417263867688640675e-3, 4.749052846085024655e-5, -2.5417263867688640675e-3},
        {300.0, 1.0001, 0.0,
         1.7996947657145225001e-3, 9.9993140351546776747e-1, 1.0008593865026603314e-8,
         -1.8949372000907414537e-5, 6.9551944804436623128e-4, -2.0350641714376056248e-6, 3.5316664549554356033e-4,
         9.1751397358594111953e-4, -1.4978368738663536838e-2, -9.1751397358594111953e-4, 1.4978368738663536838e-2},
        {1000.0, 1.0001, 0.0,
         1.9957458796536436964e-2, 9.9999260075081950708e-1, 2.9633619397550323259e-9,
         -9.5946736461510020645e-3, 9.4628705244344154397e-2, -4.8415931603885403512e-3, 4.7286374327406604955e-2,
         5.5082952190664395797e-3, -2.665519027728685875e-2, -5.5082952190664395797e-3, 2.665519027728685875e-2},
        {3000.0, 1.0001, 0.0,
         1.764497678913326721e-1, 9.9999903694565422598e-1, 9.7747580965652143645e-9,
         1.7649374969266602281e-1, -5.7129124043006053749e-1, 8.8204350160159566774e-2, -2.856503636778895868e-1,
         -8.4224965854210271706e-2, 1.2206293804480066715e-1, 8.4224965854210271706e-2, -1.2206293804480066715e-1},
        {20000.0, 1.0001, 0.0,
         3.1705307692283740648, 9.9999993398723014422e-1, 2.4501233315149373457e-9,
         3.1595187249113410133, 1.4402396065244932326, 1.5810326091817132957, 7.192783595784229798e-1,
         3.7446931160672328682e-1, -3.2370521746842529205e-1, -3.7446931160672328682e-1, 3.2370521746842529205e-1},
        {1000.0, 1.001, 0.0,
         1.5991453924631687521, 9.9999062005771220216e-1, 4.5938619309913874352e-7,
         6.6950897989068841938e-1, -4.3625731380628309517e-1, 3.368950514668571272e-1, -2.2343298122982687472e-1,
         3.1171578922438533228e-1, 1.3296546552771987735e-1, -3.1171578922438533228e-1, -1.3296546552771987735e-1},
        {8000.0, 1.001, 0.0,
         2.1046306205485330679, 9.9999045521618423796e-1, 9.746341091232445414e-7,
         1.5970889257439334593e+1, 2.2395980145692739463, 8.0343749867690270524, 1.1503001532526418142,
         8.7723441149698589149e-1, -3.8502734361675469827, -8.7723441149698589149e-1, 3.8502734361675469827},
        {8000.0, 1.00001, 0.0,
         1.2781933339726766506e-2, 9.9999985204332847148e-1, 9.9802526195087262636e-11,
         1.7886655259516858465e-4, -2.2918424614694152999e-3, 8.6023278626546880273e-5, -1.143662194252931025e-3,
         6.3792969600711965965e-3, -3.9448003617630925584e-2, -6.3792969600711965965e-3, 3.9448003617630925584e-2},
        {2000.0, 1.0000001, 0.0,
         7.9999841136561251962e-8, 9.9999798385692582776e-1, 5.3216948955995832914e-15,
         2.8896784394524618134e-8, -1.4724433276353950561e-4, 1.4264111752334908654e-8, -7.3622206939780664216e-5,
         2.9306913518465524402e-8, -7.2949941992467706914e-5, -2.9306913518465524402e-8, 7.2949941992467706914e-5},
        {1.5, 1.0000001, 0.0,
         2.7063227265520670894e-14, 3.7674210739554195711e-1, 1.075436386231573922e-14,
         1.4494557742533334567e-14, -1.7827784206080107744e-7, 7.515867916755841155e-15, -8.9138924155789826615e-8,
         1.2363983575117263677e-14, -7.7777436783121430166e-8, -1.2363983575117263677e-14, 7.7777436783121430166e-8},
        {30.0, 1.000001, 0.0,
         1.7917801090793037513e-9, 9.9568273337804196535e-1, 8.9739844211937169825e-13,
         2.7840651487549512075e-10, 1.1232781915040831562e-5, 3.84934798332546623e-10, 5.6163871393131013591e-6,
         8.136068536482247355e-10, -1.4209667442093869067e-5, -8.136068536482247355e-10, 1.4209667442093869067e-5},
        {1e-09, 1.0001, 0.0,
         1.1851456740743839511e-44, 1.600058670240012991e-19, 1.777718511111575926e-44,
         2.9628641851859602469e-63, -6.6665555407413657662e-32, 1.4814320925929801234e-63, -3.3332777703706828831e-32,
         2.9628641851859602469e-63, -6.6665555407413657642e-32, -2.9628641851859602469e-63, 6.6665555407413657642e-32},
        {5e-09, 1.5, 0.1,
         1.5013984517405006258e-34, 4.9493772612755964151e-18, 2.2520976776107509121e-34,
         6.2266155991941383737e-27, -3.6997166198056191463e-26, 3.1133077995970691999e-27, -1.8498583099028095763e-26,
         6.226615599194138306e-27, -3.6997166198056191138e-26, -6.226615599194138306e-27, 3.6997166198056191138e-26},
        {3e-10, 1.0, 1e-200,
         0.0, 1.4399999999999999809e-20, 0.0,
         1.7999999999999999319e-229, 0.0, 8.9999999999999996593e-230, 0.0,
         1.7999999999999999318e-229, 0.0, -1.7999999999999999318e-229, 0.0},
        {1e-09, 1.0, 1e-300,
         0.0, 1.6000000000000001994e-19, 0.0,
         0.0, 0.0, 0.0, 0.0,
         0.0, 0.0, 0.0, 0.0},
        {2e-09, 1.0000000000000002, 0.0,
         9.3494625803971785753e-67, 6.4000000000000013197e-19, 1.402419387059576784e-66,
         9.3494625803971797399e-85, -1.1842378929335004868e-42, 4.6747312901985898699e-85, -5.9211894646675024338e-43,
         9.3494625803971797399e-85, -1.1842378929335004853e-42, -9.3494625803971797399e-85, 1.1842378929335004853e-42},
};

/* |got - ref| <= tol (complex: the modulus), measured in units of sc > 0
 * (so no square underflows, also where -ffast-math makes hypot naive) */
static int near1_check(const double *got, const double *ref, int cplx, double tol, double sc)
{
    double d = cplx ? hypot((got[0] - ref[0]) / sc, (got[1] - ref[1]) / sc)
                    : fabs(got[0] - ref[0]) / sc;
    return d <= tol / sc && got[0] == got[0];
}

static void test_near_one(void)
{
    static const char *name[7] = { "Qsca", "g", "Qback", "S1(.5)", "S2(.5)", "S1(-1)", "S2(-1)" };
    const double sum_abs = 2 * DBL_EPSILON;     /* |dS| <= 2 eps x^(3/2), see above */
    size_t i;
    int k, controls = 0;
    double worst = 0;
    for (i = 0; i < sizeof near1_ref / sizeof near1_ref[0]; ++i) {
        const double *r = near1_ref[i];
        double x = r[0], dm = hypot(r[1] - 1, r[2]), am = hypot(r[1], r[2]);
        int inner = x * (am > 1 ? am : 1) < 1;
        mist_mie_sphere s = mist_mie_sphere_new(x, mist_mie_cplx(r[1], r[2]));
        mist_mie_complex a, b, c, d;
        double got[11], tol[7], e;
        mt_check(s.status == MIST_MIE_OK, "near 1: x=%g m=%.17g+%gi status %d", x, r[1], r[2],
                 s.status);
        mist_mie_amplitudes(&s, 0.5, &a, &b);
        mist_mie_amplitudes(&s, -1, &c, &d);
        got[0] = s.q_sca; got[1] = s.g; got[2] = s.q_back;
        got[3] = a.re; got[4] = a.im; got[5] = b.re; got[6] = b.im;
        got[7] = c.re; got[8] = c.im; got[9] = d.re; got[10] = d.im;
        for (k = 0; k < 7; ++k) {
            const double *rk = r + 3 + (k < 3 ? k : 3 + 2 * (k - 3));
            int cx = k >= 3;
            double ar = cx ? hypot(rk[0], rk[1]) : fabs(rk[0]);
            if (inner) tol[k] = 1e-13 * ar;
            else if (k < 2) tol[k] = (1e-13 + 1e-15 / dm) * ar;
            else if (k == 2)
                tol[k] = (1e-13 + 1e-15 / dm + 4 * sum_abs * sqrt(x) / sqrt(rk[0])) * ar;
            else tol[k] = (1e-13 + 1e-15 / dm) * ar + sum_abs * x * sqrt(x);
            tol[k] += 2e-323;                      /* (values past double's range) */
            {
                const double *gk = got + (k < 3 ? k : 3 + 2 * (k - 3));
                double moved[2];
                e = cx ? hypot(gk[0] - rk[0], gk[1] - rk[1]) : fabs(gk[0] - rk[0]);
                if (e / tol[k] > worst) worst = e / tol[k];
                mt_check(near1_check(gk, rk, cx, tol[k], ar > 0 ? ar : 1),
                         "near 1: x=%g m=%.17g+%gi %s: %.17g vs %.17g (%.2e, tol %.2e)", x,
                         r[1], r[2], name[k], gk[0], rk[0], e, tol[k]);
                if (ar > 0) {                          /* negative control */
                    double f = 1 + 10 * tol[k] / ar;   /* 10 tolerances out */
                    moved[0] = rk[0] * f;
                    moved[1] = cx ? rk[1] * f : 0;
                    mt_check(!near1_check(gk, moved, cx, tol[k], ar),
                             "near 1 control: x=%g %s accepted a moved reference", x, name[k]);
                    ++controls;
                }
            }
        }
        mist_mie_sphere_free(&s);
    }
    if (verbose) printf("near 1: worst %.2f of the tolerance, %d controls\n", worst, controls);
}

/* ======================================================================== */
/* mu = +-1: S1(1) = S2(1) and S2(-1) = -S1(-1), bit for bit               */
/* There pi_n = tau_n = n(n+1)/2 (mu = 1) and pi_n = -tau_n = (-1)^(n-1)    */
/* n(n+1)/2 (mu = -1) are integers, and mist_mie__sums computes them        */
/* exactly; the recurrence's rounded factors had made S1 and S2 at mu = -1  */
/* differ by 5.7e-6 relative (x = 8000, m = 1.0001), 1.1e-5 in S1 + S2.     */
/* Also: the phase table at -1 alone equals mist_mie_phase, paired within  */
/* the amplitudes' rounding;                                                */
/* and S1(-1) at x = 20000, m = 1.0001 is within test_near_one's bound of   */
/* the mpmath value (tests/mie_mpmath_ref.py near1: 0.37446931160672328682 */
/* - 0.32370521746842529205 i).                                             */
/* ======================================================================== */
static void test_edge_symmetry(void)
{
    static const double cases[][3] = {
        {8000, 1.0001, 0}, {20000, 1.0001, 0}, {1000, 1.33, 1e-5}, {339.04523060942176,
        2.8136189359334152, 1e-4}, {0.3, 1.5, 0.1}, {5000, 1.5, 0}, {30, 1000, 0},
        {100, 1.33, 2}, {1e-9, 1.33, 0}, {0.1, 0.75, 0}, {12345.678, 1.0001, 1e-3},
    };
    size_t i, j;
    for (i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        mist_mie_sphere s = mist_mie_sphere_new(cases[i][0], mist_mie_cplx(cases[i][1], cases[i][2]));
        mist_mie_complex a, b, c, d;
        double mu[7] = {1, 0.5, 0.2, 0, -0.2, -0.5, -1}, p[7], q1, q2;
        double one[1] = {-1}, p1[1];
        mist_mie_amplitudes(&s, 1, &a, &b);
        mist_mie_amplitudes(&s, -1, &c, &d);
        mt_check(s.status == MIST_MIE_OK && a.re == b.re && a.im == b.im,
                 "S1(1) = S2(1): x=%g m=%g+%gi: %.17g %.17g vs %.17g %.17g", cases[i][0],
                 cases[i][1], cases[i][2], a.re, a.im, b.re, b.im);
        mt_check(c.re == -d.re && c.im == -d.im,
                 "S2(-1) = -S1(-1): x=%g m=%g+%gi: %.17g %.17g vs %.17g %.17g (%.2e)",
                 cases[i][0], cases[i][1], cases[i][2], c.re, c.im, d.re, d.im,
                 hypot(c.re + d.re, c.im + d.im) / hypot(c.re, c.im));
        mist_mie_phase_table(&s, mu, 7, p);
        mist_mie_phase_table(&s, one, 1, p1);
        q1 = mist_mie_phase(&s, 1);
        q2 = mist_mie_phase(&s, -1);
        mt_check(p1[0] == q2, "phase table at -1 alone: x=%g: %.17g vs %.17g", cases[i][0],
                 p1[0], q2);
        /* the table (paired: other loops, other roundings; bit for bit but
         * where the compiler contracts differently) against
         * mist_mie_phase.  Two roundings of each S: where its partial sums
         * stay ~n (backward), 2 eps x^(3/2) absolutely (test_near_one), so
         * p = (|S1|^2 + |S2|^2) / (2 pi x^2 Q_sca) within 2 |S| 4 eps x^(3/2)
         * / (2 pi x^2 Q_sca) = 8 eps sqrt(x p / (pi Q_sca)); where they
         * grow to S (forward), eps sqrt(N) of S, 4 eps sqrt(N) of p. */
        for (j = 0; j < 7; ++j) {
            double q = j == 0 ? q1 : j == 6 ? q2 : mist_mie_phase(&s, mu[j]);
            double tol = 8 * DBL_EPSILON * sqrt(cases[i][0] * q / (PI * s.q_sca))
                       + 4 * DBL_EPSILON * sqrt((double)s.n_terms) * q;
            mt_check(fabs(p[j] - q) <= tol, "phase table: x=%g mu=%g: %.17g vs %.17g (tol %.2e)",
                     cases[i][0], mu[j], p[j], q, tol);
        }
        if (i == 1) {               /* x = 20000, m = 1.0001: the mpmath S1(-1) */
            double tol = (1e-13 + 1e-15 / 1e-4) * 0.4945 + 2 * DBL_EPSILON * 20000 * sqrt(20000.0);
            double e = hypot(c.re - 3.7446931160672328682e-1, c.im + 3.2370521746842529205e-1);
            mt_check(e <= tol, "S1(-1) at x = 20000: %.3e off (tol %.2e)", e, tol);
        }
        mist_mie_sphere_free(&s);
    }
}

/* ======================================================================== */
/* The dipole limit with a subnormal or tiny m - 1                          */
/* x < 1e-8, m = 1 + dr + i mi with mi down to the smallest subnormal and  */
/* dr down to one ulp of 1: the coefficients are scaled by powers of 2 (the */
/* factor 2^-e from frexp of a subnormal overflowed: S and p were NaN with  */
/* status OK).  p is the dipole's 3 (1 + mu^2) / (16 pi) to 1e-15; the      */
/* amplitude S1(0) = -i x^3 K (|K| from m - 1, its scale 2^e exact) to     */
/* 1e-12 where it is a normal double, finite and tiny where not; g =        */
/* 0.16 x^2 (m -> 1) to 1e-12.                                              */
/* ======================================================================== */
/* 1 where subnormal results are flushed to 0 (-ffast-math's start-up
 * code; subnormal input then reads as 0: m = 1 exactly, see FAST MATH in
 * mist.h) */
static int flushes(void)
{
    volatile double v = DBL_MIN;
    v = v / 4;
    return !(v > 0);
}

static void test_dipole_tiny(void)
{
    static const double xs[3] = {1e-9, 3e-12, 1e-150};
    static const double mis[7] = {0, 1e-308, 2.2e-311, 4.9e-324, 1e-300, 1e-200, 1e-20};
    static const double drs[4] = {0, 2.220446049250313e-16, -1.1102230246251565e-16, 1e-12};
    size_t i, j, k, l;
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 7; ++j)
            for (k = 0; k < 4; ++k) {
                double x = xs[i], mi = mis[j], mr = 1 + drs[k];
                double mu[5] = {1, 0.5, 0, -0.5, -1}, p[5];
                double buf[128];
                mist_mie_sphere s;
                mist_mie_complex a, b;
                int bad = 0;
                if (mi == 0 && drs[k] == 0) continue;           /* m = 1 */
                if (mi > 0 && mi < DBL_MIN && flushes()) continue;  /* read as 0 */
                s = mist_mie_sphere_make(x, mist_mie_cplx(mr, mi), buf, 128);
                mist_mie_phase_table(&s, mu, 5, p);
                for (l = 0; l < 5; ++l) {
                    double q = mist_mie_phase(&s, mu[l]), want = 3 * (1 + mu[l] * mu[l]) / (16 * PI);
                    mist_mie_amplitudes(&s, mu[l], &a, &b);
                    if (!(near_rel(q, want, 1e-15) && near_rel(p[l], want, 1e-15))) bad = 1;
                    if (!(a.re - a.re == 0 && a.im - a.im == 0 && b.re - b.re == 0
                          && b.im - b.im == 0)) bad = 1;
                }
                mt_check(s.status == MIST_MIE_OK && !bad,
                         "dipole x=%g m=1%+g+%gi: p %.17g (want %.17g)", x, drs[k], mi,
                         mist_mie_phase(&s, 0), 3 / (16 * PI));
                mt_check(near_rel(s.g, 0.16 * x * x, 1e-12) || (x * x < 1e-300 && s.g >= 0),
                         "dipole x=%g m=1%+g+%gi: g %.17g vs %.17g", x, drs[k], mi, s.g,
                         0.16 * x * x);
                if (drs[k] == 0 && x == 1e-9 && mi >= 1e-300) {   /* S1(0) = -i x^3 K, K ~ 2/3 i mi */
                    mist_mie_amplitudes(&s, 0, &a, &b);
                    mt_check(near_rel(a.re, 2.0 / 3 * mi * 1e-27, 1e-12) || mi * 1e-27 < 1e-290,
                             "dipole S1(0) x=%g mi=%g: %.17g vs %.17g", x, mi, a.re,
                             2.0 / 3 * mi * 1e-27);
                }
            }
}

/* ======================================================================== */
/* mist_mie_average's workspace at the steps of the term count              */
/* The workspace was sized at xmax = 2 pi n_medium r_max / lambda_min, the  */
/* spheres made at 2 pi n_medium / lambda r: an ulp apart, and where that   */
/* ulp crossed a step of mist_mie_workspace_size the average answered       */
/* ENOMEM with every number 0 (r = 0.8937 um at 0.55 um, n_medium 1.0003,   */
/* m 1.33; and the size is not monotone: N steps down at x = 4200).  Here:  */
/* the reported case; radii at 40 steps of the workspace size (the step     */
/* found by bisection in x, then r = x / k and 8 ulps either side), one     */
/* and two wavelengths; a table law over x = 4199.99 .. 4200.              */
/* ======================================================================== */
static void test_average_steps(void)
{
    const double lam = 0.55, nm = 1.0003, k = 2 * PI * nm / lam;
    mist_mie_wavelength wl[2];
    mist_mie_dist d;
    mist_mie_avg a;
    int step, fails = 0, tries = 0, u;
    double x0 = 0.5;
    wl[0] = mist_mie_wl(lam, 1, mist_mie_cplx(1.33, 0));
    wl[1] = mist_mie_wl(0.45, 1, mist_mie_cplx(1.34, 1e-9));
    d = mist_mie_dist_mono(0.8937);
    a = mist_mie_average(&d, wl, 1, nm, NULL, 0, NULL);
    mt_check(a.status == MIST_MIE_OK && a.c_sca > 0, "average r = 0.8937: status %d, C_sca %g",
             a.status, a.c_sca);
    for (step = 0; step < 40; ++step) {
        /* the next x where the workspace size changes, to the ulp */
        double lo = x0, hi = x0, r;
        size_t w0 = mist_mie_workspace_size(lo);
        while (mist_mie_workspace_size(hi) == w0) hi += 0.25;
        while (nextafter(lo, hi) < hi) {
            double mid = lo + (hi - lo) / 2;
            if (mid <= lo || mid >= hi) break;
            if (mist_mie_workspace_size(mid) == w0) lo = mid; else hi = mid;
        }
        r = hi / k;
        for (u = -8; u <= 8; ++u) {
            double rr = r;
            int t;
            for (t = 0; t < (u < 0 ? -u : u); ++t) rr = nextafter(rr, u < 0 ? 0 : 1e9);
            d = mist_mie_dist_mono(rr);
            a = mist_mie_average(&d, wl, (size_t)(1 + (u & 1)), nm, NULL, 0, NULL);
            ++tries;
            if (a.status != MIST_MIE_OK) {
                if (fails++ < 5)
                    printf("FAIL: average at a step: r = %.17g (x = %.17g): status %d\n", rr,
                           rr * k, a.status);
            }
        }
        x0 = hi * 1.25;
    }
    mt_check(fails == 0, "average at the steps: %d of %d failed", fails, tries);
    {   /* N(x) steps down at x = 4200: a node just below needs more */
        double r[2], w[2] = {1, 1};
        r[0] = 4199.99 / k; r[1] = 4200 / k;
        d = mist_mie_dist_table(r, w, 2);
        a = mist_mie_average(&d, wl, 1, nm, NULL, 0, NULL);
        mt_check(a.status == MIST_MIE_OK && a.c_sca > 0,
                 "average over x = 4199.99, 4200: status %d", a.status);
    }
}

/* ======================================================================== */
/* Wiscombe's MIEV0 test driver                                             */
/* Source: W. Wiscombe, MVTstNew.f, BLOCK DATA CHEKMI ("'correct' answers  */
/* to test problems", computed on a Cray with 14 digits, printed with 7),   */
/* as distributed with MIEV0; copy read from the GitHub repository          */
/* cfinch/Mie_scattering, file Wiscombe/MVTstNew.f.  Same cases in          */
/* Wiscombe, NCAR TN-140+STR (1979), appendix.                              */
/* Wiscombe writes m = mr - i mi: his S1, S2 are the complex conjugates of  */
/* mist_mie's (see mist_mie.h CONVENTIONS); the tables below are his, as    */
/* printed, and the test conjugates.  Cases 1-4: perfectly conducting.      */
/* ======================================================================== */

typedef struct {
    double x, mr, mi;            /* mi as Wiscombe writes it (<= 0)  */
    int pec, small;              /* small: MIEV0 used its small-particle
                                    expansion, not the series        */
    double qe, qs, gq;
    double s[7][4];              /* S1 re, im, S2 re, im at 0..180 by 30 deg */
} wcase;

static const wcase wiscombe[19] = {
  /* 1 */ {0.099, 0, 0, 1, 1, 3.209674E-04, 3.209674E-04, -1.275386E-04,
   {{ 7.878422E-07, 4.911194E-04,  7.878422E-07, 4.911194E-04},
    { 7.670447E-07, 5.558947E-04,  7.030888E-07, 3.604144E-04},
    { 7.102250E-07, 7.326708E-04,  4.715383E-07, 3.612002E-06},
    { 6.326078E-07, 9.736939E-04,  1.552344E-07,-4.831029E-04},
    { 5.549907E-07, 1.214189E-03, -1.610695E-07,-9.690253E-04},
    { 4.981709E-07, 1.389908E-03, -3.926201E-07,-1.324243E-03},
    { 4.773735E-07, 1.454155E-03, -4.773735E-07,-1.454155E-03}}},
  /* 2 */ {0.101, 0, 0, 1, 0, 3.477160E-04, 3.477160E-04, -1.381344E-04,
   {{ 8.867628E-07, 5.217024E-04,  8.867628E-07, 5.217024E-04},
    { 8.633471E-07, 5.904742E-04,  7.913746E-07, 3.828897E-04},
    { 7.993742E-07, 7.781489E-04,  5.307693E-07, 3.966328E-06},
    { 7.119857E-07, 1.034013E-03,  1.747762E-07,-5.128950E-04},
    { 6.245974E-07, 1.289294E-03, -1.812167E-07,-1.028882E-03},
    { 5.606248E-07, 1.475804E-03, -4.418213E-07,-1.406055E-03},
    { 5.372092E-07, 1.543993E-03, -5.372092E-07,-1.543993E-03}}},
  /* 3 */ {100, 0, 0, 1, 0, 2.008102E+00, 2.008102E+00, 1.005911E+00,
   {{ 5.020256E+03,-1.746518E+01,  5.020256E+03,-1.746518E+01},
    { 5.352638E+01,-1.123588E+01, -3.353061E+01,-7.285853E+00},
    {-2.621449E+01,-4.290513E+01,  2.171234E+01, 4.412456E+01},
    {-2.489003E+00, 4.997035E+01,  3.504192E+00,-4.991006E+01},
    {-2.045134E+01, 4.563103E+01,  2.055790E+01,-4.554104E+01},
    {-4.999320E+01, 8.991646E-01,  5.000835E+01,-8.611726E-01},
    {-4.352508E+01,-2.455873E+01,  4.352508E+01, 2.455873E+01}}},
  /* 4 */ {10000, 0, 0, 1, 0, 2.000289E+00, 2.000289E+00, 1.000284E+00,
   {{ 5.000722E+07,-1.211371E+04,  5.000722E+07,-1.211373E+04},
    {-4.114082E+03,-2.841914E+03,  4.097371E+03, 2.864462E+03},
    {-1.527121E+03, 4.761086E+03,  1.529975E+03,-4.760161E+03},
    {-4.836681E+03,-1.267485E+03,  4.836501E+03, 1.268169E+03},
    {-3.940804E+03, 3.077347E+03,  3.940922E+03,-3.077195E+03},
    {-3.800110E+03, 3.249487E+03,  3.800134E+03,-3.249459E+03},
    { 2.910127E+03,-4.065854E+03, -2.910127E+03, 4.065854E+03}}},
  /* 5 */ {0.099, 0.75, 0, 0, 1, 7.417859E-06, 7.417859E-06, 1.074279E-08,
   {{ 1.817558E-08,-1.654225E-04,  1.817558E-08,-1.654225E-04},
    { 1.817558E-08,-1.653815E-04,  1.574051E-08,-1.432172E-04},
    { 1.817558E-08,-1.652694E-04,  9.087788E-09,-8.261265E-05},
    { 1.817558E-08,-1.651163E-04,  9.797186E-23, 2.938374E-08},
    { 1.817558E-08,-1.649631E-04, -9.087788E-09, 8.250360E-05},
    { 1.817558E-08,-1.648510E-04, -1.574051E-08, 1.427725E-04},
    { 1.817558E-08,-1.648100E-04, -1.817558E-08, 1.648100E-04}}},
  /* 6 */ {0.101, 0.75, 0, 0, 0, 8.033542E-06, 8.033542E-06, 1.211000E-08,
   {{ 2.048754E-08,-1.756419E-04,  2.048754E-08,-1.756419E-04},
    { 2.048754E-08,-1.755965E-04,  1.774273E-08,-1.520629E-04},
    { 2.048753E-08,-1.754726E-04,  1.024377E-08,-8.771198E-05},
    { 2.048751E-08,-1.753033E-04,  1.845057E-15, 3.247270E-08},
    { 2.048750E-08,-1.751341E-04, -1.024375E-08, 8.759147E-05},
    { 2.048749E-08,-1.750103E-04, -1.774269E-08, 1.515715E-04},
    { 2.048749E-08,-1.749650E-04, -2.048749E-08, 1.749650E-04}}},
  /* 7 */ {10, 0.75, 0, 0, 0, 2.232265E+00, 2.232265E+00, 2.001164E+00,
   {{ 5.580662E+01,-9.758097E+00,  5.580662E+01,-9.758097E+00},
    {-7.672879E+00, 1.087317E+01, -1.092923E+01, 9.629667E+00},
    { 3.587894E+00,-1.756177E+00,  3.427411E+00, 8.082691E-02},
    {-1.785905E+00,-5.232828E-02, -5.148748E-01,-7.027288E-01},
    { 1.537971E+00,-8.329374E-02, -6.908338E-01, 2.152693E-01},
    {-4.140427E-01, 1.876851E-01,  5.247557E-01,-1.923391E-01},
    {-1.078568E+00,-3.608807E-02,  1.078568E+00, 3.608807E-02}}},
  /* 8 */ {1000, 0.75, 0, 0, 0, 1.997908E+00, 1.997908E+00, 1.688121E+00,
   {{ 4.994770E+05,-1.336502E+04,  4.994770E+05,-1.336502E+04},
    {-3.999296E+02,-3.316361E+02, -3.946018E+02,-1.147791E+02},
    {-5.209852E+02,-5.776614E+02, -1.970767E+02,-6.937470E+02},
    {-1.600887E+02, 1.348013E+02, -4.152365E+01, 1.143000E+02},
    { 8.431720E+01,-1.209493E+02, -4.261732E+01, 5.535055E+01},
    {-7.556092E+01,-8.134810E+01,  4.218303E+01, 9.100831E+01},
    { 1.705778E+01, 4.842510E+02, -1.705778E+01,-4.842510E+02}}},
  /* 9 */ {1, 1.33, -1e-5, 0, 0, 9.395198E-02, 9.392330E-02, 1.733048E-02,
   {{ 2.348800E-02, 2.281705E-01,  2.348800E-02, 2.281705E-01},
    { 2.341722E-02, 2.217102E-01,  2.034830E-02, 1.938171E-01},
    { 2.322408E-02, 2.046815E-01,  1.181704E-02, 1.075976E-01},
    { 2.296081E-02, 1.828349E-01,  2.729533E-04, 6.702879E-03},
    { 2.269820E-02, 1.625401E-01, -1.114466E-02,-7.646326E-02},
    { 2.250635E-02, 1.486170E-01, -1.942300E-02,-1.271557E-01},
    { 2.243622E-02, 1.437106E-01, -2.243622E-02,-1.437106E-01}}},
  /* 10 */ {100, 1.33, -1e-5, 0, 0, 2.101321E+00, 2.096594E+00, 1.821854E+00,
   {{ 5.253302E+03,-1.243188E+02,  5.253302E+03,-1.243188E+02},
    {-5.534573E+01,-2.971881E+01, -8.467204E+01,-1.999470E+01},
    { 1.710488E+01,-1.520096E+01,  3.310764E+01,-2.709787E+00},
    {-3.655758E+00, 8.769860E+00, -6.550512E+00,-4.675370E+00},
    { 2.414318E+00, 5.380874E-01,  6.039011E+00,-1.169971E+01},
    {-1.222996E+00, 3.283917E+01, -9.653812E+00, 1.474455E+01},
    {-5.659205E+01, 4.650974E+01,  5.659205E+01,-4.650974E+01}}},
  /* 11 */ {10000, 1.33, -1e-5, 0, 0, 2.004089E+00, 1.723857E+00, 1.564987E+00,
   {{ 5.010222E+07,-1.535815E+05,  5.010222E+07,-1.535815E+05},
    { 3.786814E+03,-7.654293E+03,  5.074755E+03,-7.515986E+03},
    {-2.731172E+03, 1.326633E+03, -3.076558E+03,-1.775975E+02},
    {-1.061003E+03,-1.930155E+02,  2.430920E+02, 8.409836E+01},
    {-1.058140E+03, 2.298414E+01,  5.906487E+01,-5.370283E+02},
    {-2.748855E+03, 2.298181E+03, -8.036201E+01,-4.939186E+00},
    {-1.821193E+02,-9.519122E+02,  1.821194E+02, 9.519123E+02}}},
  /* 12 */ {0.055, 1.5, -1, 0, 1, 1.014910E-01, 1.131687E-05, 5.558541E-09,
   {{ 7.675259E-05, 8.343879E-05,  7.675259E-05, 8.343879E-05},
    { 7.674331E-05, 8.343495E-05,  6.646948E-05, 7.225169E-05},
    { 7.671794E-05, 8.342445E-05,  3.838246E-05, 4.169695E-05},
    { 7.668328E-05, 8.341012E-05,  3.132066E-08,-2.037399E-08},
    { 7.664863E-05, 8.339578E-05, -3.830082E-05,-4.171317E-05},
    { 7.662326E-05, 8.338529E-05, -6.634986E-05,-7.221887E-05},
    { 7.661398E-05, 8.338145E-05, -7.661398E-05,-8.338145E-05}}},
  /* 13 */ {0.056, 1.5, -1, 0, 0, 1.033467E-01, 1.216311E-05, 6.193255E-09,
   {{ 8.102381E-05, 8.807251E-05,  8.102381E-05, 8.807251E-05},
    { 8.101364E-05, 8.806830E-05,  7.016844E-05, 7.626381E-05},
    { 8.098587E-05, 8.805682E-05,  4.051865E-05, 4.401169E-05},
    { 8.094795E-05, 8.804113E-05,  3.427277E-08,-2.229631E-08},
    { 8.091003E-05, 8.802545E-05, -4.042932E-05,-4.402945E-05},
    { 8.088228E-05, 8.801396E-05, -7.003755E-05,-7.622790E-05},
    { 8.087213E-05, 8.800976E-05, -8.087213E-05,-8.800976E-05}}},
  /* 14 */ {1, 1.5, -1, 0, 0, 2.336321E+00, 6.634538E-01, 1.274736E-01,
   {{ 5.840802E-01, 1.905153E-01,  5.840802E-01, 1.905153E-01},
    { 5.657020E-01, 1.871997E-01,  5.001610E-01, 1.456112E-01},
    { 5.175251E-01, 1.784426E-01,  2.879639E-01, 4.105398E-02},
    { 4.563396E-01, 1.671665E-01,  3.622847E-02,-6.182646E-02},
    { 4.002117E-01, 1.566427E-01, -1.748750E-01,-1.229586E-01},
    { 3.621572E-01, 1.493910E-01, -3.056823E-01,-1.438460E-01},
    { 3.488438E-01, 1.468286E-01, -3.488438E-01,-1.468286E-01}}},
  /* 15 */ {100, 1.5, -1, 0, 0, 2.097502E+00, 1.283697E+00, 1.091466E+00,
   {{ 5.243754E+03,-2.934167E+02,  5.243754E+03,-2.934167E+02},
    { 4.049055E+01,-1.898456E+01,  2.019198E+01, 3.110731E+00},
    {-2.646835E+01,-1.929564E+01,  9.152743E+00,-7.470202E+00},
    { 1.268890E+01, 2.397474E+01, -1.232914E+01,-7.823167E+00},
    { 5.149886E+00, 2.290736E+01, -7.173357E+00,-1.655464E+01},
    {-1.605395E+01, 1.418642E+01,  1.448052E+01,-1.393594E+01},
    {-2.029360E+01, 4.384435E+00,  2.029360E+01,-4.384435E+00}}},
  /* 16 */ {10000, 1.5, -1, 0, 0, 2.004368E+00, 1.236574E+00, 1.046525E+00,
   {{ 5.010919E+07,-1.753404E+05,  5.010919E+07,-1.753404E+05},
    {-3.690394E+03,-1.573897E+03, -9.333175E+02,-1.839736E+03},
    { 2.391551E+02, 3.247786E+03, -1.202951E+03,-1.899647E+02},
    {-2.607463E+03, 7.414859E+02,  1.013073E+03,-1.064666E+03},
    {-6.183154E+02, 2.264970E+03,  1.334826E+02,-1.800859E+03},
    {-3.368019E+02, 2.115750E+03,  2.293862E+02,-1.996754E+03},
    {-2.184719E+02,-2.064610E+03,  2.184719E+02, 2.064610E+03}}},
  /* 17 */ {1, 10, -10, 0, 0, 2.532993E+00, 2.049405E+00, -2.267961E-01,
   {{ 6.332483E-01, 4.179305E-01,  6.332483E-01, 4.179305E-01},
    { 6.162264E-01, 4.597163E-01,  5.573186E-01, 2.954338E-01},
    { 5.736317E-01, 5.602514E-01,  3.525107E-01,-5.921611E-03},
    { 5.238628E-01, 6.675352E-01,  7.881172E-02,-3.435544E-01},
    { 4.825816E-01, 7.434033E-01, -1.881212E-01,-6.028739E-01},
    { 4.570214E-01, 7.809867E-01, -3.793898E-01,-7.473279E-01},
    { 4.485464E-01, 7.912365E-01, -4.485464E-01,-7.912365E-01}}},
  /* 18 */ {100, 10, -10, 0, 0, 2.071124E+00, 1.836785E+00, 1.021648E+00,
   {{ 5.177811E+03,-2.633811E+01,  5.177811E+03,-2.633811E+01},
    { 5.227436E+01,-1.270012E+01, -2.380252E+01,-3.872567E-01},
    {-2.705712E+01,-3.951751E+01,  2.585821E+01, 3.323624E+01},
    { 1.008860E+00, 4.663027E+01, -3.479935E+00,-4.364245E+01},
    {-1.505640E+01, 4.333057E+01,  1.360634E+01,-4.238302E+01},
    {-4.510770E+01, 5.199554E+00,  4.474564E+01,-5.452513E+00},
    {-4.145383E+01,-1.821808E+01,  4.145383E+01, 1.821808E+01}}},
  /* 19 */ {10000, 10, -10, 0, 0, 2.005914E+00, 1.795393E+00, 9.842238E-01,
   {{ 5.014786E+07,-1.206004E+05,  5.014786E+07,-1.206004E+05},
    {-4.080090E+03,-2.664399E+03,  3.351286E+03, 7.291906E+02},
    {-1.224040E+03, 4.596569E+03,  4.497446E+02,-4.072999E+03},
    {-4.579490E+03,-8.590486E+02,  4.313394E+03, 4.969719E+02},
    {-3.356286E+03, 3.125121E+03,  3.171910E+03,-3.129068E+03},
    {-3.149584E+03, 3.270358E+03,  3.105243E+03,-3.269355E+03},
    { 2.252480E+03,-3.924468E+03, -2.252480E+03, 3.924468E+03}}},
};

/* MIEV0 and Du (2004) sum Wiscombe's N terms; mist_mie sums on until the
 * terms die out (mist_mie.h, ACCURACY).  Their printed amplitudes keep the
 * tail of their cut: MIEV0's case 2 (conductor, x = 0.101, N = 2) 2e-7 of
 * |S|, two units of the 7th digit (Im S2(60 deg): printed 3.966328e-6, the
 * 60-digit series cut at 2 terms 3.9663284e-6, summed to 30 terms
 * 3.9660260e-6, mist_mie 3.9660260e-6), Du's case f (x = 1e4) S1(180 deg)
 * 3.7e-6 relative.  So their amplitudes are compared with the sphere's
 * coefficients summed to N, as theirs were (n_terms set to N: the sums
 * read the stored a_n, b_n up to n_terms); the full sums are held to an
 * independent series in test_series_tail. */
static mist_mie_sphere cut_at_n(mist_mie_sphere s)
{
    int n = mist_mie_terms(s.x);
    if (s.n_terms > n) s.n_terms = n;
    return s;
}

static mist_mie_sphere make_case(const wcase *c)
{
    mist_mie_complex m = c->pec ? mist_mie_conductor() : mist_mie_cplx(c->mr, -c->mi);
    return mist_mie_sphere_new(c->x, m);
}

static void test_wiscombe(void)
{
    int i, j, k;
    double worst_q = 0, worst_s = 0, worst_small = 0;
    for (i = 0; i < 19; ++i) {
        const wcase *c = &wiscombe[i];
        mist_mie_sphere s = make_case(c);
        double smax = 0, got[4];
        if (!mt_check(s.status == MIST_MIE_OK, "wiscombe %d: status %d", i + 1, s.status))
            continue;
        for (j = 0; j < 7; ++j)
            for (k = 0; k < 4; ++k) if (fabs(c->s[j][k]) > smax) smax = fabs(c->s[j][k]);
        if (c->small) {
            /* MIEV0 evaluated these with its small-particle expansions
             * (x |m| < 0.1, conductor x < 0.1), not the series (the
             * driver: "the lower value uses small-particle approximations,
             * the upper value uses the full Mie series"): they carry the
             * expansion's
             * O(x^4) ~ 1e-4 relative error ("the results should be
             * close").
             * Tolerance 2e-4 of each quantity's scale (S: the largest |S|
             * of the case); measured 5.2e-5 (case 1).  That the difference
             * is MIEV0's, not ours, was confirmed with a 40-digit mpmath
             * evaluation of the series (not used as a test value); cases 5
             * and 12 are checked to all of Du's digits below (his a, g). */
            double e;
            mt_check(near_rel(s.q_ext, c->qe, 2e-4),
                     "wiscombe %d Qext %.7e vs %.7e", i + 1, s.q_ext, c->qe);
            mt_check(near_rel(s.q_sca, c->qs, 2e-4),
                     "wiscombe %d Qsca %.7e vs %.7e", i + 1, s.q_sca, c->qs);
            mt_check(near_rel(s.g * s.q_sca, c->gq, 2e-4),
                     "wiscombe %d gQsca %.7e vs %.7e", i + 1, s.g * s.q_sca, c->gq);
            for (j = 0; j < 7; ++j) {
                mist_mie_complex s1, s2;
                mist_mie_amplitudes(&s, cos(PI / 6 * j), &s1, &s2);
                s1 = conj_c(s1); s2 = conj_c(s2);
                got[0] = s1.re; got[1] = s1.im; got[2] = s2.re; got[3] = s2.im;
                for (k = 0; k < 4; ++k) {
                    e = fabs(got[k] - c->s[j][k]) / smax;
                    if (e > worst_small) worst_small = e;
                    mt_check(e <= 2e-4, "wiscombe %d S%d(%d deg) %d: %.7e vs %.7e",
                             i + 1, k / 2 + 1, 30 * j, k % 2, got[k], c->s[j][k]);
                }
            }
        } else {
            /* Series cases, published to 7 digits: tolerance 1 unit in the
             * 7th digit (half a unit of rounding, half for the Cray run's
             * own error; measured worst 0.5 units).  Except case 6 (x =
             * 0.101, the most cancelling series): MIEV0 prints Q = 8.033542e-6
             * where Du's double-precision recomputation (Table 1, case b,
             * checked below) is 8.033538e-6, and S1(0) 1.756419e-4 where Du
             * has 1.75642e-4 - 4 units: tolerance 5 units there.  Amplitude
             * components are compared to their own last digit, but at least
             * to 1e-7 of the case's largest |S| (its 7 digits): a component
             * far below |S| is roundoff of the Cray run (case 6: Re S2(90)
             * = 1.8e-15 with |S| = 1.8e-4). */
            double e, units = i + 1 == 6 ? 5 : 1;
            mt_check(near_pub(s.q_ext, c->qe, 7, units, 0),
                     "wiscombe %d Qext %.7e vs %.7e", i + 1, s.q_ext, c->qe);
            mt_check(near_pub(s.q_sca, c->qs, 7, units, 0),
                     "wiscombe %d Qsca %.7e vs %.7e", i + 1, s.q_sca, c->qs);
            mt_check(near_pub(s.g * s.q_sca, c->gq, 7, units, 0),
                     "wiscombe %d gQsca %.7e vs %.7e", i + 1, s.g * s.q_sca, c->gq);
            if (i + 1 != 6) {
                e = fabs(s.q_ext - c->qe) / last_unit(c->qe, 7);
                if (e > worst_q) worst_q = e;
                e = fabs(s.q_sca - c->qs) / last_unit(c->qs, 7);
                if (e > worst_q) worst_q = e;
                e = fabs(s.g * s.q_sca - c->gq) / last_unit(c->gq, 7);
                if (e > worst_q) worst_q = e;
            }
            for (j = 0; j < 7; ++j) {
                mist_mie_complex s1, s2;
                mist_mie_sphere sn = cut_at_n(s);          /* as MIEV0 summed */
                mist_mie_amplitudes(&sn, cos(PI / 6 * j), &s1, &s2);
                s1 = conj_c(s1); s2 = conj_c(s2);
                got[0] = s1.re; got[1] = s1.im; got[2] = s2.re; got[3] = s2.im;
                for (k = 0; k < 4; ++k) {
                    double tol = last_unit(c->s[j][k], 7);
                    if (tol < 1e-7 * smax) tol = 1e-7 * smax;
                    tol *= units;
                    e = fabs(got[k] - c->s[j][k]) / tol;
                    if (e * units > worst_s && i + 1 != 6) worst_s = e * units;
                    mt_check(e <= 1, "wiscombe %d S%d(%d deg) %s: %.7e vs %.7e",
                             i + 1, k / 2 + 1, 30 * j, k % 2 ? "im" : "re", got[k], c->s[j][k]);
                }
            }
        }
        mist_mie_sphere_free(&s);
    }
    if (verbose)
        printf("wiscombe (series cases but 6): worst Q %.2f, worst S %.2f units of the"
               " 7th digit; small-x cases %.2e of |S|max\n", worst_q, worst_s, worst_small);
}

/* ======================================================================== */
/* Du (2004), "Mie-scattering calculation", Appl. Opt. 43, 1951-1956:       */
/* Table 1 (Q_ext, Q_sca) and Table 2 (S1 at 0 and 180 degrees), computed in */
/* double precision, printed to 7 resp. 6 digits, in the m = mr + i mi      */
/* convention of mist_mie.  Values as quoted in the GitHub repository       */
/* ovidiopr/scattnlay, file tests/test_bulk_sphere.cc (parameters_and_results */
/* and DuTable2Amplitudes; that file comments out cases f and k of Table 2  */
/* for its own code's sake, the values are Du's).                           */
/* ======================================================================== */

typedef struct { double x, mr, mi, qe, qs, s0r, s0i, s180r, s180i; char id; } ducase;

static const ducase du[13] = {
    {0.099, 0.75, 0, 7.417859e-06, 7.417859e-06,
     1.81756e-8, 1.65423e-4, 1.81756e-8, 1.64810e-4, 'a'},
    {0.101, 0.75, 0, 8.033538e-06, 8.033538e-06,
     2.04875e-8, 1.75642e-4, 2.04875e-8, 1.74965e-4, 'b'},
    {10, 0.75, 0, 2.232265, 2.232265, 55.8066, 9.75810, -1.07857, 0.0360881, 'c'},
    {1000, 0.75, 0, 1.997908, 1.997908, 499477.0, 13365.0, 17.0578, -484.251, 'd'},
    {100, 1.33, 1e-5, 2.101321, 2.096594, 5253.30, 124.319, -56.5921, -46.5097, 'e'},
    {10000, 1.33, 1e-5, 2.004089, 1.723857, 5.01022e7, 153582.0, -182.119, 951.912, 'f'},
    {0.055, 1.5, 1, 0.10149104, 1.131687e-05,
     7.67526e-5, -8.34388e-5, 7.66140e-5, -8.33814e-5, 'g'},
    {0.056, 1.5, 1, 0.1033467, 1.216311e-05, 8.10238e-5, -8.80725e-5, 8.08721e-5, -8.80098e-5, 'h'},
    {100, 1.5, 1, 2.097502, 1.283697, 5243.75, 293.417, -20.2936, -4.38444, 'i'},
    {10000, 1.5, 1, 2.004368, 1.236574, 5.01092e7, 175340.0, -218.472, 2064.61, 'j'},
    {1, 10, 10, 2.532993, 2.049405, 0.633248, -0.417931, 0.448546, -0.791236, 'k'},
    {100, 10, 10, 2.071124, 1.836785, 5177.81, 26.3381, -41.4538, 18.2181, 'l'},
    {10000, 10, 10, 2.005914, 1.795393, 5.01479e7, 120600.0, 2252.48, 3924.47, 'm'},
};

static void test_du(void)
{
    int i;
    for (i = 0; i < 13; ++i) {
        const ducase *c = &du[i];
        mist_mie_sphere s = mist_mie_sphere_new(c->x, mist_mie_cplx(c->mr, c->mi)), sn;
        mist_mie_complex f, b;
        /* Q: 7 significant digits (case g's Q_ext 8); tolerance one unit
         * of the last digit.  S1: 6 digits, one unit. */
        int qd = c->id == 'g' ? 8 : 7;
        mt_check(near_pub(s.q_ext, c->qe, qd, 1, 0),
                 "du %c Qext %.8e vs %.8e", c->id, s.q_ext, c->qe);
        mt_check(near_pub(s.q_sca, c->qs, 7, 1, 0),
                 "du %c Qsca %.8e vs %.8e", c->id, s.q_sca, c->qs);
        sn = cut_at_n(s);                               /* as Du summed */
        mist_mie_amplitudes(&sn, 1, &f, NULL);
        mist_mie_amplitudes(&sn, -1, &b, NULL);
        mt_check(near_pub(f.re, c->s0r, 6, 1, 0) && near_pub(f.im, c->s0i, 6, 1, 0),
                 "du %c S1(0) (%.6e, %.6e) vs (%.6e, %.6e)", c->id, f.re, f.im, c->s0r, c->s0i);
        mt_check(near_pub(b.re, c->s180r, 6, 1, 0) && near_pub(b.im, c->s180i, 6, 1, 0),
                 "du %c S1(180) (%.6e, %.6e) vs (%.6e, %.6e)",
                 c->id, b.re, b.im, c->s180r, c->s180i);
        mist_mie_sphere_free(&s);
    }
}

/* ======================================================================== */
/* Bohren & Huffman, Appendix A (BHMIE's example output): m = 1.55, sphere  */
/* radius 0.525, wavelength 0.6328 (x = 5.21282): Q_sca = Q_ext = 3.10543,  */
/* Q_back = 2.92534, g = 0.63314, and the table of S11 / S11(0), POL =      */
/* -S12/S11, S33/S11, S34/S11 at 0, 9, ..., 180 degrees.  Values as quoted  */
/* in the GitHub repository scottprahl/miepython, file tests/test_nojit.py  */
/* (test_03_bh_dielectric and test_mie_phase_matrix_bohren, "output from    */
/* Bohren's program").  With S11 = (|S1|^2 + |S2|^2)/2, S12 = (|S2|^2 -     */
/* |S1|^2)/2, S33 = Re(S2 S1*), S34 = Im(S2 S1*) (BH83's Mueller matrix).   */
/* The same file gives two cases computed by miepython itself (an           */
/* independent double-precision code), in its m = mr - i mi convention:     */
/* test_04_non_dielectric (m = 1.55 - 0.1i, same x) and                     */
/* test_09_single_nonmagnetic (m = 1.5 - 0.5i, x = 2.5).                    */
/* ======================================================================== */

static const double bh_table[21][5] = {
    {  0.0, 0.100000E+01,  0.000000E+00,  0.100000E+01,  0.000000E+00},
    {  9.0, 0.785390E+00, -0.459811E-02,  0.999400E+00,  0.343261E-01},
    { 18.0, 0.356897E+00, -0.458541E-01,  0.986022E+00,  0.160184E+00},
    { 27.0, 0.766119E-01, -0.364744E+00,  0.843603E+00,  0.394076E+00},
    { 36.0, 0.355355E-01, -0.534997E+00,  0.686967E+00, -0.491787E+00},
    { 45.0, 0.701845E-01,  0.959953E-02,  0.959825E+00, -0.280434E+00},
    { 54.0, 0.574313E-01,  0.477927E-01,  0.985371E+00,  0.163584E+00},
    { 63.0, 0.219660E-01, -0.440604E+00,  0.648043E+00,  0.621216E+00},
    { 72.0, 0.125959E-01, -0.831996E+00,  0.203255E+00, -0.516208E+00},
    { 81.0, 0.173750E-01,  0.341670E-01,  0.795354E+00, -0.605182E+00},
    { 90.0, 0.124601E-01,  0.230462E+00,  0.937497E+00,  0.260742E+00},
    { 99.0, 0.679093E-02, -0.713472E+00, -0.717397E-02,  0.700647E+00},
    {108.0, 0.954239E-02, -0.756255E+00, -0.394748E-01, -0.653085E+00},
    {117.0, 0.863419E-02, -0.281215E+00,  0.536251E+00, -0.795835E+00},
    {126.0, 0.227421E-02, -0.239612E+00,  0.967602E+00,  0.795798E-01},
    {135.0, 0.543998E-02, -0.850804E+00,  0.187531E+00, -0.490882E+00},
    {144.0, 0.160243E-01, -0.706334E+00,  0.495254E+00, -0.505781E+00},
    {153.0, 0.188852E-01, -0.891081E+00,  0.453277E+00, -0.226817E-01},
    {162.0, 0.195254E-01, -0.783319E+00, -0.391613E+00,  0.482752E+00},
    {171.0, 0.301676E-01, -0.196194E+00, -0.962069E+00,  0.189556E+00},
    {180.0, 0.383189E-01,  0.000000E+00, -0.100000E+01,  0.000000E+00},
};

static void test_bohren_huffman(void)
{
    double x = 2 * PI * 0.525 / 0.6328, s110 = 0, worst = 0;
    mist_mie_sphere s = mist_mie_sphere_new(x, mist_mie_cplx(1.55, 0));
    int i, k;
    /* 6 digits: one unit of the last */
    mt_check(near_pub(s.q_sca, 3.10543, 6, 1, 0), "BH Qsca %.7f", s.q_sca);
    mt_check(near_pub(s.q_ext, 3.10543, 6, 1, 0), "BH Qext %.7f", s.q_ext);
    mt_check(near_pub(s.q_back, 2.92534, 6, 1, 0), "BH Qback %.7f", s.q_back);
    mt_check(near_pub(s.g, 0.63314, 5, 1, 0), "BH g %.7f", s.g);
    for (i = 0; i < 21; ++i) {
        mist_mie_complex s1, s2;
        double i1, i2, s11, got[4];
        mist_mie_amplitudes(&s, cos(bh_table[i][0] * PI / 180), &s1, &s2);
        i1 = s1.re * s1.re + s1.im * s1.im;
        i2 = s2.re * s2.re + s2.im * s2.im;
        s11 = 0.5 * (i1 + i2);
        if (i == 0) s110 = s11;
        got[0] = s11 / s110;
        got[1] = -0.5 * (i2 - i1) / s11;
        got[2] = (s2.re * s1.re + s2.im * s1.im) / s11;
        got[3] = (s2.im * s1.re - s2.re * s1.im) / s11;
        for (k = 0; k < 4; ++k) {
            /* BHMIE ran in single precision (REAL*4, COMPLEX*8) and prints
             * 6 digits; the ratios lose up to 2 digits where S11 is 1/400
             * of its peak.  Tolerance: 3e-5 absolute on these O(1) ratios
             * (S11 relative to its own value), measured worst 6e-6. */
            double ref = bh_table[i][k + 1];
            double e = k == 0 ? fabs(got[k] - ref) / ref : fabs(got[k] - ref);
            if (e > worst) worst = e;
            mt_check(e <= 3e-5, "BH table %g deg, column %d: %.6e vs %.6e",
                     bh_table[i][0], k + 1, got[k], ref);
        }
    }
    if (verbose) printf("BH S11 table: worst deviation %.2e\n", worst);
    mist_mie_sphere_free(&s);

    {   /* miepython, printed to 11 and 15 digits.  It sums x + 4.05 x^(1/3)
         * + 2 terms where MIEV0 (and mist_mie) sum x + 4 x^(1/3) + 1 for
         * x <= 8: one term fewer, which moves Q_back by 6e-9 and Q_ext by
         * 1e-9 relative here (the truncation; confirmed by a 30-digit
         * mpmath series with both N, not used as a test value).
         * Tolerance 1e-8 relative, Q_back 2e-8. */
        static const double mp[2][7] = {
            {0, 1.55, 0.1, 2.86165188243, 1.66424911991, 0.20599534080, 0.80128972639},
            {2.5, 1.5, 0.5, 2.562873497454734, 1.097071819088392, 0.123586468179818,
             0.748905978948507}};
        double w = 0;
        for (i = 0; i < 2; ++i) {
            double xx = mp[i][0] > 0 ? mp[i][0] : x;
            mist_mie_sphere t = mist_mie_sphere_new(xx, mist_mie_cplx(mp[i][1], mp[i][2]));
            double got[4];
            got[0] = t.q_ext; got[1] = t.q_sca; got[2] = t.q_back; got[3] = t.g;
            for (k = 0; k < 4; ++k) {
                double e = fabs(got[k] - mp[i][3 + k]) / mp[i][3 + k];
                if (e > w) w = e;
                mt_check(e <= (k == 2 ? 2e-8 : 1e-8),
                         "miepython case %d, quantity %d: %.15g vs %.15g",
                         i, k, got[k], mp[i][3 + k]);
            }
            mist_mie_sphere_free(&t);
        }
        if (verbose) printf("miepython cases: worst relative deviation %.2e\n", w);
    }
}

/* ======================================================================== */
/* Small particles [BH83 ch. 5; Kerker 1969 for the conductor]: as x -> 0,  */
/* Q_sca -> 8/3 x^4 |K|^2, Q_abs -> 4 x Im K, Q_back -> 4 x^4 |K|^2,        */
/* K = (m^2-1)/(m^2+2), p -> 3/(16 pi) (1 + mu^2); conductor: Q_sca ->      */
/* 10/3 x^4, Q_back -> 9 x^4, g -> -2/5 (MIEV0 test driver's x = 0.001      */
/* self-test: Q_sca = 3.3333e-12 as quoted in miepython tests/test_nojit.py). */
/* The corrections are O(x^2) relative: at x = 1e-4 below 1e-7.  And the    */
/* switch from the series to the dipole formulas at x = 1e-8 is seamless.  */
/* ======================================================================== */

static void test_small(void)
{
    static const double ms[4][2] = {{1.33, 0}, {1.5, 1}, {0.75, 0}, {10, 10}};
    int i, j;
    double x = 1e-4;
    for (i = 0; i < 4; ++i) {
        mist_mie_complex m = mist_mie_cplx(ms[i][0], ms[i][1]), m2 = {0, 0}, k;
        mist_mie_sphere s;
        double k2, tol = 1e-7 * (1 + 100 * (ms[i][0] > 5));   /* |m|^2 x^2 terms */
        m2.re = m.re * m.re - m.im * m.im; m2.im = 2 * m.re * m.im;
        k = mist_mie__div(mist_mie_cplx(m2.re - 1, m2.im), mist_mie_cplx(m2.re + 2, m2.im));
        k2 = k.re * k.re + k.im * k.im;
        s = mist_mie_sphere_new(x, m);
        mt_check(near_rel(s.q_sca, 8.0 / 3 * pow(x, 4) * k2, tol), "small Qsca m=%g", m.re);
        mt_check(near_rel(s.q_back, 4 * pow(x, 4) * k2, tol), "small Qback m=%g", m.re);
        if (m.im > 0) mt_check(near_rel(s.q_abs, 4 * x * k.im, tol), "small Qabs m=%g", m.re);
        for (j = 0; j <= 4; ++j) {
            double u = -1 + 0.5 * j;
            mt_check(near_rel(mist_mie_phase(&s, u), 3 / (16 * PI) * (1 + u * u), tol),
                     "small phase m=%g u=%g", m.re, u);
        }
        mist_mie_sphere_free(&s);
    }
    {
        mist_mie_sphere s = mist_mie_sphere_new(1e-3, mist_mie_conductor());
        mt_check(near_pub(s.q_sca, 3.3333e-12, 5, 1, 0), "conductor x=1e-3: Qsca %.6e", s.q_sca);
        mist_mie_sphere_free(&s);
        s = mist_mie_sphere_new(x, mist_mie_conductor());
        mt_check(near_rel(s.q_sca, 10.0 / 3 * pow(x, 4), 1e-7), "conductor Qsca");
        mt_check(near_rel(s.q_back, 9 * pow(x, 4), 1e-7), "conductor Qback");
        mt_check(fabs(s.g + 0.4) < 1e-7, "conductor g %.9f", s.g);
        mist_mie_sphere_free(&s);
    }
    /* the switch at x = 1e-8 (x |m| for |m| > 1) */
    for (i = 0; i < 5; ++i) {
        mist_mie_complex m = i < 4 ? mist_mie_cplx(ms[i][0], ms[i][1]) : mist_mie_conductor();
        double am = i < 4 ? sqrt(m.re * m.re + m.im * m.im) : 1;
        double xs = 1e-8 / (am > 1 ? am : 1), lo = xs * (1 - 1e-12), hi = xs * (1 + 1e-12);
        mist_mie_sphere a = mist_mie_sphere_new(lo, m), b = mist_mie_sphere_new(hi, m);
        mist_mie_complex sa, sb;
        double sc = pow(lo, 3);
        mt_check(near_rel(a.q_sca / pow(lo, 4), b.q_sca / pow(hi, 4), 1e-9)
                 && near_rel(a.q_back / pow(lo, 4), b.q_back / pow(hi, 4), 1e-9)
                 && near_rel(a.q_ext / lo, b.q_ext / hi, 1e-9)
                 && fabs(a.g - b.g) < 1e-9, "switch at x=1e-8, case %d", i);
        for (j = 0; j <= 4; ++j) {
            double u = -1 + 0.5 * j;
            mist_mie_amplitudes(&a, u, &sa, NULL);
            mist_mie_amplitudes(&b, u, &sb, NULL);
            mt_check(near_rel(mist_mie_phase(&a, u), mist_mie_phase(&b, u), 1e-9)
                     && fabs(sa.re - sb.re) + fabs(sa.im - sb.im) <= 1e-9 * sc,
                     "switch at x=1e-8, case %d, u=%g", i, u);
        }
        mist_mie_sphere_free(&a);
        mist_mie_sphere_free(&b);
    }
    /* far below: exact formulas, nothing underflows to NaN */
    {
        mist_mie_sphere s = mist_mie_sphere_new(1e-200, mist_mie_cplx(1.33, 1e-9));
        mt_check(s.status == MIST_MIE_OK && s.q_sca == 0 && s.q_ext > 0
                 && near_rel(mist_mie_phase(&s, 0.5), 3 / (16 * PI) * 1.25, 1e-15),
                 "x=1e-200: Qext %g, p %g", s.q_ext, mist_mie_phase(&s, 0.5));
        mist_mie_sphere_free(&s);
    }
}

/* ======================================================================== */
/* Normalisation and mean cosine by quadrature.  |S1|^2 + |S2|^2 is a       */
/* polynomial of degree 2N in mu, so (N+2)-point Gauss-Legendre integrates  */
/* p and mu p exactly (up to rounding): 2 pi int p = 1, 2 pi int mu p = g.  */
/* Also the adaptive Gauss-Kronrod of mist_test.h for moderate x.           */
/* ======================================================================== */

/* n-point Gauss-Legendre nodes and weights on [-1, 1] (Newton on P_n). */
static void gauss_legendre(int n, double *x, double *w)
{
    int i, j, it;
    for (i = 0; i < (n + 1) / 2; ++i) {
        double z = cos(PI * (i + 0.75) / (n + 0.5)), pp = 0, p1, p2, p3;
        for (it = 0; it < 100; ++it) {
            double dz;
            p1 = 1; p2 = 0;
            for (j = 1; j <= n; ++j) {
                p3 = p2; p2 = p1;
                p1 = ((2.0 * j - 1) * z * p2 - (j - 1.0) * p3) / j;
            }
            pp = n * (z * p1 - p2) / (z * z - 1);
            dz = p1 / pp;
            z -= dz;
            if (fabs(dz) < 1e-16) break;
        }
        x[i] = z; x[n - 1 - i] = -z;
        w[i] = w[n - 1 - i] = 2 / ((1 - z * z) * pp * pp);
    }
    if (n & 1) x[n / 2] = 0;
}

static double f_phase(double u, const void *c)
{
    return 2 * PI * mist_mie_phase((const mist_mie_sphere *)c, u);
}

static double f_mcos(double u, const void *c)
{
    return 2 * PI * u * mist_mie_phase((const mist_mie_sphere *)c, u);
}

static void test_quadrature(void)
{
    static const double cs[][3] = {
        {0.5, 1.33, 0}, {5.213, 1.55, 0}, {57.1, 1.333, 1.96e-9}, {285.5, 1.333, 1.96e-9},
        {100, 1.5, 1}, {30, 10, 10}, {1000, 0.75, 0}, {10000, 1.33, 1e-5}, {20, -1, 0}};
    size_t i, j, nc = sizeof cs / sizeof cs[0];
    double worst = 0;
    for (i = 0; i < nc; ++i) {
        mist_mie_complex m = cs[i][1] < 0 ? mist_mie_conductor()
                                          : mist_mie_cplx(cs[i][1], cs[i][2]);
        mist_mie_sphere s;
        int n;
        /* quick mode (MIST_TEST_QUICK, the variants) leaves out x = 1e4:
         * 1e4 nodes times 1e4 terms: test_mie under ASan at -O0, quick 8,
         * 11.7 -> 6.3 s of CPU (measured 2026-12-01); test_large still takes
         * x = 1e4 and 1e5 there, and the main build this case */
        if (mt_quick() > 1 && cs[i][0] > 1000) continue;
        s = mist_mie_sphere_new(cs[i][0], m);
        n = s.n_terms + 2;
        double *x = (double *)malloc(2 * (size_t)n * sizeof(double)), *w = x + n;
        double *p = (double *)malloc((size_t)n * sizeof(double));
        double i0 = 0, i1 = 0;
        gauss_legendre(n, x, w);
        mist_mie_phase_table(&s, x, (size_t)n, p);     /* paired: x[n-1-j] = -x[j] */
        for (j = 0; j < (size_t)n; ++j) {
            i0 += 2 * PI * w[j] * p[j];
            i1 += 2 * PI * w[j] * x[j] * p[j];
        }
        /* Exact up to rounding.  Near the forward peak p varies on a scale
         * 1/x^2 in mu, so the nodes' own rounding (1e-16 absolute) moves p
         * by up to ~x^2 eps relative: tolerance 1e-10 + 5 x^2 eps
         * (measured 8e-10 at x = 1e4, below 1e-12 for x <= 1000). */
        double tq = 1e-10 + 5 * cs[i][0] * cs[i][0] * DBL_EPSILON;
        mt_check(fabs(i0 - 1) < tq, "GL normalisation x=%g: %.15f", cs[i][0], i0);
        mt_check(fabs(i1 - s.g) < tq, "GL mean cosine x=%g: %.15f vs g %.15f", cs[i][0], i1, s.g);
        if (fabs(i0 - 1) > worst) worst = fabs(i0 - 1);
        if (fabs(i1 - s.g) > worst) worst = fabs(i1 - s.g);
        /* the table agrees with single evaluations (the pairing is exact) */
        for (j = 0; j < (size_t)n; j += (size_t)n / 7 + 1)
            mt_check(near_rel(p[j], mist_mie_phase(&s, x[j]), 1e-9) || fabs(p[j]) < 1e-300,
                     "table vs phase x=%g", cs[i][0]);
        if (cs[i][0] <= 300) {
            /* adaptive Gauss-Kronrod, split towards the forward peak */
            double e, a = 0, b = 0, et = 0, lo = -1;
            int k;
            for (k = 0; k <= 8; ++k) {
                double hi = k < 8 ? 1 - pow(10, -k / 2.0 - 0.5) : 1;
                a += mt_integrate(f_phase, &s, lo, hi, 1e-12, &e); et += e;
                b += mt_integrate(f_mcos, &s, lo, hi, 1e-12, &e); et += e;
                lo = hi;
            }
            mt_check(fabs(a - 1) < 1e-9 && fabs(b - s.g) < 1e-9,
                     "GK x=%g: int p = %.12f, int mu p = %.12f, g = %.12f (err %.1e)",
                     cs[i][0], a, b, s.g, et);
        }
        free(x); free(p);
        mist_mie_sphere_free(&s);
    }
    if (verbose) printf("quadrature: worst |int p - 1|, |int mu p - g| = %.2e\n", worst);
}

/* ======================================================================== */
/* Large spheres: x = 1e4 (Wiscombe 11, 16, 19 above check the values) and  */
/* the domain's end x = 1e5: every output finite, Q_ext near the extinction */
/* paradox value 2 for a large weakly absorbing sphere (Q_ext = 2 + O(x^-2/3):*/
/* within 0.01 at 1e4, 0.002 at 1e5), the phase function finite and >= 0.  */
/* ======================================================================== */

static void test_large(void)
{
    static const double xs[2] = {1e4, 1e5};
    int i, j, bad = 0;
    for (i = 0; i < 2; ++i) {
        mist_mie_sphere s = mist_mie_sphere_new(xs[i], mist_mie_water(550, NULL));
        double tol = i == 0 ? 0.01 : 0.002;
        mt_check(s.status == MIST_MIE_OK && fabs(s.q_ext - 2) < tol && s.q_sca > 1.9
                 && s.q_sca <= s.q_ext && s.g > 0.8 && s.g < 0.95 && isfinite(s.q_back),
                 "x=%g: Qext %.6f Qsca %.6f g %.6f Qback %g",
                 xs[i], s.q_ext, s.q_sca, s.g, s.q_back);
        int na = i == 0 ? 1000 : 200;
        for (j = 0; j <= na; ++j) {
            double u = cos(PI * j / na), p = mist_mie_phase(&s, u);
            mist_mie_complex a, b;
            mist_mie_amplitudes(&s, u, &a, &b);
            if (!(p >= 0 && isfinite(p) && isfinite(a.re) && isfinite(a.im) && isfinite(b.re)
                  && isfinite(b.im)))
                ++bad;
        }
        mist_mie_sphere_free(&s);
    }
    mt_check(bad == 0, "large x: %d non-finite values", bad);
}

/* ======================================================================== */
/* Size distributions.  Cross sections checked against an independent      */
/* fixed-step trapezoid rule written here (its own range, its own step,    */
/* the distributions typed in from their definitions), and the closed-form */
/* moments: gamma [HT74] <r^2> = b^2 (a+1)(a+2), <r^3>/<r^2> = r_eff;       */
/* modified gamma <r^2> = Gamma(a+3)/Gamma(a+1) / B^2 (gamma = 1); lognormal */
/* <r^2> = r_g^2 exp(2 ln^2 sigma_g).                                       */
/* ======================================================================== */

static double trap_csca(int kind, double p1, double p2, double lo, double hi, int n,
                        double lambda, mist_mie_complex m, double *cext, double *g)
{
    double h = (hi - lo) / n, sw = 0, sc = 0, se = 0, sg = 0;
    double rhi = kind == 0 ? hi : exp(hi);
    size_t nw = mist_mie_workspace_size(2 * PI * rhi / lambda);
    double *work = (double *)malloc(nw * sizeof(double));
    int i, bad = 0;
    for (i = 0; i <= n; ++i) {
        double t = lo + h * i, r, w, a2;
        mist_mie_sphere s;
        if (kind == 0) {            /* gamma [HT74]: r^((1-3v)/v) exp(-r/(r_eff v)) */
            double a = (1 - 3 * p2) / p2, b = p1 * p2;
            r = t;
            w = r > 0 ? exp(a * log(r / (a * b)) - (r - a * b) / b) : 0;
        } else {                    /* lognormal, in t = ln r */
            double y = (t - log(p1)) / log(p2);
            r = exp(t);
            w = exp(-0.5 * y * y);
        }
        if (i == 0 || i == n) w *= 0.5;
        sw += w;
        if (!(w > 0)) continue;
        s = mist_mie_sphere_make(2 * PI * r / lambda, m, work, nw);
        bad += s.status != MIST_MIE_OK;
        a2 = PI * r * r;
        sc += w * s.q_sca * a2;
        se += w * s.q_ext * a2;
        sg += w * s.g * s.q_sca * a2;
    }
    free(work);
    mt_check(bad == 0, "trapezoid: %d spheres failed", bad);
    *cext = se / sw;
    *g = sg / sc;
    return sc / sw;
}

static void test_distributions(void)
{
    mist_mie_complex mw = mist_mie_water(550, NULL);
    mist_mie_wavelength wl = mist_mie_wl(0.55, 1, mw);
    mist_mie_dist d;
    mist_mie_avg a;
    double cext, g, csca;
    int i;

    /* gamma, r_eff = 2 um, v_eff = 0.1 (alpha = 7, b = 0.2): x up to ~120.
     * Two quadratures of the same integral: the trapezoid over [0, 14] um
     * with steps of 0.0057 in x, the library's automatic Gauss-Legendre
     * nodes over its own range (spacing <= 0.05 in x).
     * (1) m = 1.33 + 1e-3 i, whose absorption damps the narrow resonances:
     * both rules converge smoothly (measured: the library 4.8e-6 from a
     * 256000-step trapezoid at its automatic density, 4e-8 at 6400 nodes);
     * tolerance 3e-5 relative, 3e-5 in g.
     * (2) water at 550 nm (Im m = 2e-9): its resonances are so narrow and
     * tall that any fixed-node rule is noisy - a node that lands on one
     * overweights it (measured: the library scatters by up to 4.3e-4 around
     * the trapezoid as n_radii goes from 2000 to 2600); tolerance 1.5e-3. */
    d = mist_mie_dist_gamma(2, 0.1);
    for (i = 0; i < 2; ++i) {
        mist_mie_complex m = i == 0 ? mist_mie_cplx(1.33, 1e-3) : mw;
        double tol = i == 0 ? 3e-5 : 1.5e-3;
        wl.m = m;
        a = mist_mie_average(&d, &wl, 1, 1, NULL, 0, NULL);
        csca = trap_csca(0, 2, 0.1, 0, 14, 28000, 0.55, m, &cext, &g);
        mt_check(a.status == MIST_MIE_OK && near_rel(a.c_sca, csca, tol)
                 && near_rel(a.c_ext, cext, tol) && fabs(a.g - g) < tol,
                 "gamma, m %g+%gi: Csca %.8f vs trapezoid %.8f, Cext %.8f vs %.8f,"
                 " g %.7f vs %.7f (%d nodes)",
                 m.re, m.im, a.c_sca, csca, a.c_ext, cext, a.g, g, a.n_radii);
        if (verbose)
            printf("gamma, m %g+%gi: Csca %.8f vs %.8f (rel %.1e), Cext rel %.1e,"
                   " g %.7f vs %.7f, nodes %d, r in [%g, %g]\n",
                   m.re, m.im, a.c_sca, csca, fabs(a.c_sca / csca - 1), fabs(a.c_ext / cext - 1),
                   a.g, g, a.n_radii, a.r_min, a.r_max);
    }
    /* closed-form moments: to the quadrature's precision (GL of a smooth
     * integrand: 1e-12 measured) */
    mt_check(near_rel(a.area, PI * 0.04 * 8 * 9, 1e-9), "gamma <pi r^2> %.12f", a.area);
    mt_check(near_rel(0.75 * a.volume / a.area, 2, 1e-9),
             "gamma r_eff %.12f", 0.75 * a.volume / a.area);
    mt_check(near_rel(a.albedo, a.c_sca / a.c_ext, 1e-15) && a.c_abs >= 0
             && a.c_abs < 1e-5 * a.c_ext, "gamma albedo/absorption");

    /* wide gamma laws, v_eff 0.3 to 0.49 (alpha = (1-3v)/v from 1/3 down to
     * -0.96: n(r) = r^alpha e^(-r/b) not smooth, then singular, at r = 0):
     * <pi r^2> = pi b^2 (alpha+1)(alpha+2) and <4/3 pi r^3> = 4/3 pi b^3
     * (alpha+1)(alpha+2)(alpha+3), closed forms.  The number is exact
     * (incomplete gamma); the area's integrand r^(alpha+2) is not smooth at
     * 0 either: 1.2e-8 measured (v 0.45), tolerance 1e-7.  The previous
     * header: 2.3e-5 at v = 0.3, a factor 3.8 at 0.49 (an independent
     * check found it). */
    {
        static const double vw[] = { 0.3, 0.35, 0.4, 0.45, 0.49 };
        size_t iv;
        for (iv = 0; iv < sizeof vw / sizeof *vw; ++iv) {
            double v = vw[iv], al = (1 - 3 * v) / v, bb = 1.5 * v;
            mist_mie_dist dg = mist_mie_dist_gamma(1.5, v);
            mist_mie_wavelength wg = mist_mie_wl(0.55, 1, mist_mie_cplx(1.33, 1e-3));
            mist_mie_avg ag = mist_mie_average(&dg, &wg, 1, 1, NULL, 0, NULL);
            double ar = PI * bb * bb * (al + 1) * (al + 2);
            double vo = 4.0 / 3 * PI * bb * bb * bb * (al + 1) * (al + 2) * (al + 3);
            mt_check(ag.status == MIST_MIE_OK && near_rel(ag.area, ar, 1e-7)
                     && near_rel(ag.volume, vo, 1e-7),
                     "wide gamma v_eff %g: <pi r^2> %.12g (exact %.12g), volume %.12g (%.12g)",
                     v, ag.area, ar, ag.volume, vo);
        }
    }

    /* lognormal, r_g = 1 um, sigma_g = 1.5, in ln r, water: here the
     * automatic nodes are dense in x where the droplets are (spacing 0.05
     * at r_max, 0.004 at r_g): measured 2e-6 (the trapezoid, 0.0003 in
     * ln r, is the coarser of the two); tolerance 2e-5 */
    wl.m = mw;
    d = mist_mie_dist_lognormal(1, 1.5);
    a = mist_mie_average(&d, &wl, 1, 1, NULL, 0, NULL);
    csca = trap_csca(1, 1, 1.5, -8 * log(1.5), 2 * log(1.5) * log(1.5) + 8 * log(1.5), 24000,
                     0.55, mw, &cext, &g);
    mt_check(a.status == MIST_MIE_OK && near_rel(a.c_sca, csca, 2e-5)
             && near_rel(a.c_ext, cext, 2e-5)
             && fabs(a.g - g) < 2e-5,
             "lognormal: Csca %.8f vs trapezoid %.8f, g %.7f vs %.7f", a.c_sca, csca, a.g, g);
    if (verbose)
        printf("lognormal: Csca %.8f vs %.8f (rel %.1e), g %.7f vs %.7f, nodes %d\n",
               a.c_sca, csca, fabs(a.c_sca / csca - 1), a.g, g, a.n_radii);
    mt_check(near_rel(a.area, PI * exp(2 * log(1.5) * log(1.5)), 1e-9),
             "lognormal <pi r^2> %.12f", a.area);

    /* Deirmendjian's cloud C.1: alpha 6, gamma 1, r_c 4 um: B = 1.5,
     * <r^2> = 8 * 7 / 1.5^2 */
    d = mist_mie_dist_modgamma(6, 1, 4);
    a = mist_mie_average(&d, &wl, 1, 1, NULL, 0, NULL);
    mt_check(a.status == MIST_MIE_OK && near_rel(a.area, PI * 56 / 2.25, 1e-9),
             "modgamma <pi r^2> %.12f", a.area);
    /* large droplets: C_ext -> 2 <pi r^2> (+ the x^-2/3 edge term) */
    mt_check(a.c_ext / a.area > 2 && a.c_ext / a.area < 2.2,
             "modgamma Cext/area %.5f", a.c_ext / a.area);

    /* user range and node count are honoured */
    d = mist_mie_dist_gamma(2, 0.1);
    d.r_min = 0.5; d.r_max = 3; d.n_radii = 100;
    a = mist_mie_average(&d, &wl, 1, 1, NULL, 0, NULL);
    mt_check(a.status == MIST_MIE_OK && a.r_min == 0.5 && a.r_max == 3 && a.n_radii == 104,
             "user range: [%g, %g], %d nodes", a.r_min, a.r_max, a.n_radii);
}

/* Phase tables of averages: normalised (Gauss-Legendre, exact for the
 * polynomial of degree 2 N_max), and consistent with single spheres and
 * with the weighted sums over wavelengths and explicit nodes. */
static void test_average_phase(void)
{
    enum { NG = 260 };
    double mu[NG], w[NG], p[NG], q[NG], p1[NG], p2[NG], i0 = 0, i1 = 0;
    mist_mie_wavelength wl[2];
    mist_mie_dist d;
    mist_mie_avg a, b, c;
    mist_mie_sphere s;
    int j, ok;

    wl[0] = mist_mie_wl(0.45, 1, mist_mie_water(450, NULL));
    wl[1] = mist_mie_wl(0.65, 3, mist_mie_water(650, NULL));
    gauss_legendre(NG, mu, w);

    /* gamma r_eff = 5 um, v = 0.2, r_max well below x = 250 (N < NG - 2) */
    d = mist_mie_dist_gamma(5, 0.2);
    d.r_min = 0.01; d.r_max = 16; d.n_radii = 200;
    a = mist_mie_average(&d, wl, 2, 1.0, mu, NG, p);
    for (j = 0; j < NG; ++j) { i0 += 2 * PI * w[j] * p[j]; i1 += 2 * PI * w[j] * mu[j] * p[j]; }
    mt_check(a.status == MIST_MIE_OK && fabs(i0 - 1) < 1e-10 && fabs(i1 - a.g) < 1e-10,
             "average: int p = %.13f, int mu p = %.13f vs g %.13f", i0, i1, a.g);

    /* mono + one wavelength = the sphere */
    d = mist_mie_dist_mono(3);
    a = mist_mie_average(&d, wl, 1, 1.0003, mu, NG, p);
    s = mist_mie_sphere_new(2 * PI * 3 * 1.0003 / 0.45,
                            mist_mie_cplx(wl[0].m.re / 1.0003, wl[0].m.im / 1.0003));
    ok = a.status == MIST_MIE_OK && near_rel(a.c_ext, s.q_ext * PI * 9, 1e-14)
         && near_rel(a.c_sca, s.q_sca * PI * 9, 1e-14) && near_rel(a.g, s.g, 1e-14)
         && near_rel(a.c_back, s.q_back * PI * 9, 1e-14);
    for (j = 0; j < NG; ++j) ok = ok && near_rel(p[j], mist_mie_phase(&s, mu[j]), 1e-12);
    mt_check(ok, "mono average = sphere");
    mist_mie_sphere_free(&s);

    /* two wavelengths = the scattering-weighted mix of each alone */
    a = mist_mie_average(&d, wl, 2, 1, mu, NG, p);
    b = mist_mie_average(&d, wl, 1, 1, mu, NG, p1);
    c = mist_mie_average(&d, wl + 1, 1, 1, mu, NG, p2);
    ok = near_rel(a.c_sca, (b.c_sca + 3 * c.c_sca) / 4, 1e-13)
         && near_rel(a.c_ext, (b.c_ext + 3 * c.c_ext) / 4, 1e-13)
         && near_rel(a.g, (b.g * b.c_sca + 3 * c.g * c.c_sca) / (b.c_sca + 3 * c.c_sca), 1e-13);
    for (j = 0; j < NG; ++j)
        ok = ok && near_rel(p[j], (b.c_sca * p1[j] + 3 * c.c_sca * p2[j])
                                  / (b.c_sca + 3 * c.c_sca), 1e-12);
    mt_check(ok, "two wavelengths = weighted mix");

    /* explicit nodes = the weighted mix of monodisperse averages */
    {
        static const double rr[2] = {1, 2.5}, ww[2] = {2, 1};
        mist_mie_dist t = mist_mie_dist_table(rr, ww, 2);
        d = mist_mie_dist_mono(1);   b = mist_mie_average(&d, wl, 1, 1, mu, NG, p1);
        d = mist_mie_dist_mono(2.5); c = mist_mie_average(&d, wl, 1, 1, mu, NG, p2);
        a = mist_mie_average(&t, wl, 1, 1, mu, NG, q);
        ok = near_rel(a.c_sca, (2 * b.c_sca + c.c_sca) / 3, 1e-13)
             && near_rel(a.area, PI * (2 * 1 + 6.25) / 3, 1e-14);
        for (j = 0; j < NG; ++j)
            ok = ok && near_rel(q[j], (2 * b.c_sca * p1[j] + c.c_sca * p2[j])
                                      / (2 * b.c_sca + c.c_sca), 1e-12);
        mt_check(ok, "table nodes = weighted mix");
    }
}

/* ======================================================================== */
/* Water [HQ73 Table I]: the header's table against an independent          */
/* transcription (refractiveindex.info's copy of Hale & Querry, as in the   */
/* GitHub repository joeftiger/Rust-V, src/refractive_index/water.rs; the   */
/* same numbers as the 6S/LIDORT table), its interpolation and its edges.  */

/* Averages at the edges of their domain (the scaled sums of
 * mist_mie_average).  Exact invariances: scaling every weight, or every
 * length, by a power of two scales each rounded operation exactly (no
 * over- or underflow inside the domain), so the results are equal bit for
 * bit (lengths: C by 2^2k, volume by 2^3k).  Then four inputs that broke
 * the plain sums (fuzz/fuzz_mie.c found them: NaN or zero results with
 * status OK), and moments of extreme laws against closed forms and an
 * independent long-double Simpson rule. */
/* -ffast-math links start-up code that flushes subnormals (FTZ/DAZ: see
 * FAST MATH in mist.h): a subnormal weight is read as 0 there (EDOMAIN),
 * so those two checks are left out of such builds (variant_fastmath). */
#ifdef __FAST_MATH__
#  define SUBNORMAL_OK 0
#else
#  define SUBNORMAL_OK 1
#endif

static int same_avg(const mist_mie_avg *a, const mist_mie_avg *b, double c2, double c3)
{
    return a->status == MIST_MIE_OK && b->status == MIST_MIE_OK && b->c_ext == a->c_ext * c2
           && b->c_sca == a->c_sca * c2 && b->c_abs == a->c_abs * c2
           && b->c_back == a->c_back * c2 && b->g == a->g && b->albedo == a->albedo
           && b->area == a->area * c2 && b->volume == a->volume * c3
           && b->n_radii == a->n_radii;
}

/* <r^k> / <1> of n(r) = exp(alpha ln(r / r1) - (r - r1) / beta) over
 * [r0, r1]: composite Simpson in long double, 20000 intervals (the
 * integrand's fourth derivative over itself is below (alpha / r0)^4: the
 * rule's relative error is below h^4 (alpha / r0)^4 / 180 < 1e-12 for
 * alpha = 97 on [0.001, 0.002]) */
static double simpson_moment(double alpha, double beta, double r0, double r1, int k)
{
    int i, n = 20000;
    long double h = ((long double)r1 - r0) / n, s0 = 0, sk = 0;
    for (i = 0; i <= n; ++i) {
        long double r = r0 + h * i;
        long double f = expl(alpha * logl(r / r1) - (r - r1) / beta);
        long double c = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
        s0 += c * f;
        sk += c * f * powl(r, k);
    }
    return (double)(sk / s0);
}

static void test_average_extremes(void)
{
    enum { NM = 5 };
    double mu[NM] = {1, 0.5, 0, -0.5, -1}, p[NM], q[NM];
    mist_mie_wavelength wl[2], w2[2];
    mist_mie_dist d, e;
    mist_mie_avg a, b, c;
    int j, k, ok;

    /* weights of any scale: subnormal (2^-1060) and huge (2^1000) */
    wl[0] = mist_mie_wl(0.45, 1, mist_mie_water(450, NULL));
    wl[1] = mist_mie_wl(0.65, 3, mist_mie_water(650, NULL));
    d = mist_mie_dist_gamma(5, 0.2);
    d.r_min = 0.01; d.r_max = 16; d.n_radii = 64;
    a = mist_mie_average(&d, wl, 2, 1.0, mu, NM, p);
    for (k = SUBNORMAL_OK ? 0 : 1; k < 2; ++k) {
        double sc = k ? 0x1p1000 : 0x1p-1060;
        static const double rr[2] = {1, 2.5};
        double tw[2], tw2[2];
        w2[0] = wl[0]; w2[1] = wl[1];
        w2[0].weight *= sc; w2[1].weight *= sc;
        b = mist_mie_average(&d, w2, 2, 1.0, mu, NM, q);
        ok = same_avg(&a, &b, 1, 1);
        for (j = 0; j < NM; ++j) ok = ok && q[j] == p[j];
        mt_check(ok, "average: wavelength weights x %a: status %d, C_sca %.17g vs %.17g", sc,
                 b.status, b.c_sca, a.c_sca);
        tw[0] = 2; tw[1] = 1; tw2[0] = 2 * sc; tw2[1] = sc;
        e = mist_mie_dist_table(rr, tw, 2);
        b = mist_mie_average(&e, wl, 2, 1.0, mu, NM, p);
        e = mist_mie_dist_table(rr, tw2, 2);
        c = mist_mie_average(&e, wl, 2, 1.0, mu, NM, q);
        ok = same_avg(&b, &c, 1, 1);
        for (j = 0; j < NM; ++j) ok = ok && q[j] == p[j];
        mt_check(ok, "average: table weights x %a", sc);
        a = mist_mie_average(&d, wl, 2, 1.0, mu, NM, p);       /* restore p */
    }

    /* lengths of any scale inside [LEN_MIN, LEN_MAX]: 2^-90 (radii down to
     * 7.9e-30) and 2^90 (up to 2e28) */
    for (k = -90; k <= 90; k += 180) {
        double sc = ldexp(1, k);
        w2[0] = wl[0]; w2[1] = wl[1];
        w2[0].lambda *= sc; w2[1].lambda *= sc;
        e = mist_mie_dist_gamma(5 * sc, 0.2);
        e.r_min = 0.01 * sc; e.r_max = 16 * sc; e.n_radii = 64;
        b = mist_mie_average(&e, w2, 2, 1.0, mu, NM, q);
        ok = same_avg(&a, &b, sc * sc, sc * sc * sc);
        for (j = 0; j < NM; ++j) ok = ok && q[j] == p[j];
        mt_check(ok, "average: lengths x 2^%d: status %d, C_sca %.17g vs %.17g", k, b.status,
                 b.c_sca, a.c_sca * sc * sc);
    }

    /* (1) a wavelength of LEN_MAX next to a visible one (x ~ 1e-33: the
     * dipole limit, whose x^6 and k^2 both underflowed: phase 0/0).  Its
     * scattering is ~x^4 below the other's: the average is the visible
     * one's, its cross sections times the weight share 1 / (1 + 0.01).
     * Past LEN_MAX (1e300, the fuzzer's input): EDOMAIN.  Tolerance 1e-14:
     * the two averages differ by a few roundings of their sums (the second
     * wavelength's share is ~1e-130 of the first's). */
    d = mist_mie_dist_gamma(0.1, 0.01);
    d.r_min = 0.001; d.r_max = 0.002; d.n_radii = 1;
    w2[0] = mist_mie_wl(0.55, 1, mist_mie_cplx(1.329, 1.25e-7));
    w2[1] = mist_mie_wl(MIST_MIE_LEN_MAX, 0.01, mist_mie_cplx(1.329, 1.25e-7));
    b = mist_mie_average(&d, w2, 1, 1.02, mu, NM, p);
    c = mist_mie_average(&d, w2, 2, 1.02, mu, NM, q);
    ok = c.status == MIST_MIE_OK && near_rel(c.c_sca, b.c_sca / 1.01, 1e-14)
         && near_rel(c.g, b.g, 1e-14);
    for (j = 0; j < NM; ++j) ok = ok && near_rel(q[j], p[j], 1e-14);
    mt_check(ok, "average: wavelength LEN_MAX: status %d C_sca %g vs %g, phase(-1) %g vs %g",
             c.status, c.c_sca, b.c_sca / 1.01, q[NM - 1], p[NM - 1]);
    w2[1].lambda = 1e300;
    c = mist_mie_average(&d, w2, 2, 1.02, mu, NM, q);
    mt_check(c.status == MIST_MIE_EDOMAIN && q[0] == 0, "average: wavelength 1e300: status %d",
             c.status);

    /* (2) a subnormal wavelength weight (5.1e-315): the same as weight 1 */
    if (SUBNORMAL_OK) {
        d = mist_mie_dist_modgamma(0.5, 0.5, 0.1);
        d.r_min = 0.001; d.r_max = 0.002; d.n_radii = 8;
        w2[0] = mist_mie_wl(0.532, 1, mist_mie_cplx(1.01, 0));
        b = mist_mie_average(&d, w2, 1, 1.217, mu, NM, p);
        w2[0].weight = 5.1e-315;
        c = mist_mie_average(&d, w2, 1, 1.217, mu, NM, q);
        ok = same_avg(&b, &c, 1, 1) && c.area > 0 && c.c_sca > 0;
        for (j = 0; j < NM; ++j) ok = ok && q[j] == p[j];
        mt_check(ok, "average: weight 5.1e-315: status %d C_sca %g area %g (weight 1: %g, %g)",
                 c.status, c.c_sca, c.area, b.c_sca, b.area);
    }

    /* (3) weights 1.9e214 (wavelength) x 3.9e137 (table) overflowed the
     * products: the same as the one radius alone (normalised weights 1 and
     * rho = 1 in both: the same operations; 1e-15 allows one rounding) */
    {
        static const double rr[2] = {74.3, 2.6}, tw[2] = {3.9e137, 0};
        w2[0] = mist_mie_wl(0.798, 1.9e214, mist_mie_cplx(1.329, 1.26e-7));
        e = mist_mie_dist_table(rr, tw, 2);
        b = mist_mie_average(&e, w2, 1, 1.18, mu, NM, p);
        d = mist_mie_dist_mono(74.3);
        c = mist_mie_average(&d, w2, 1, 1.18, mu, NM, q);
        ok = b.status == MIST_MIE_OK && near_rel(b.c_ext, c.c_ext, 1e-15)
             && near_rel(b.c_sca, c.c_sca, 1e-15) && near_rel(b.g, c.g, 1e-15)
             && near_rel(b.albedo, c.albedo, 1e-15);
        for (j = 0; j < NM; ++j) ok = ok && near_rel(p[j], q[j], 1e-15);
        mt_check(ok, "average: weights 1.9e214 x 3.9e137: status %d C_ext %g g %g (mono %g %g)",
                 b.status, b.c_ext, b.g, c.c_ext, c.g);
    }

    /* (4) a gamma r_eff of 1e300 (outside [LEN_MIN, LEN_MAX]): EDOMAIN */
    d = mist_mie_dist_gamma(1e300, 0.335);
    d.r_min = 0.001; d.r_max = 1; d.n_radii = 8;
    b = mist_mie_average(&d, wl, 1, 1.0, NULL, 0, NULL);
    mt_check(b.status == MIST_MIE_EDOMAIN, "average: r_eff 1e300: status %d", b.status);

    /* a range far in a law's tail: gamma r_eff 10, v 0.01 (alpha 97,
     * beta 0.1, mode 9.7) on [0.001, 0.002], where n(r) is 1e-500 of its
     * peak (the plain sums gave 0 with status OK).  Area and volume means
     * against Simpson (1e-12); tolerance 1e-10 (Gauss-Legendre, 8 panels
     * of 8 nodes, of a smooth integrand: below 1e-13) */
    d = mist_mie_dist_gamma(10, 0.01);
    d.r_min = 0.001; d.r_max = 0.002; d.n_radii = 64;
    w2[0] = mist_mie_wl(0.55, 1, mist_mie_cplx(1.33, 0));
    a = mist_mie_average(&d, w2, 1, 1, mu, NM, p);
    e = mist_mie_dist_mono(0.001);
    b = mist_mie_average(&e, w2, 1, 1, NULL, 0, NULL);
    e = mist_mie_dist_mono(0.002);
    c = mist_mie_average(&e, w2, 1, 1, NULL, 0, NULL);
    {
        double m2 = simpson_moment(97, 0.1, 0.001, 0.002, 2);
        double m3 = simpson_moment(97, 0.1, 0.001, 0.002, 3);
        ok = a.status == MIST_MIE_OK && near_rel(a.area, PI * m2, 1e-10)
             && near_rel(a.volume, 4.0 / 3 * PI * m3, 1e-10)
             && a.c_sca > b.c_sca && a.c_sca < c.c_sca && fabs(a.g) <= 1 && p[0] > 0;
        mt_check(ok, "average: far tail: status %d area %.15g vs %.15g, volume %.15g vs %.15g,"
                 " C_sca %g in (%g, %g)", a.status, a.area, PI * m2, a.volume,
                 4.0 / 3 * PI * m3, a.c_sca, b.c_sca, c.c_sca);
    }

    /* extreme law parameters, moments against closed forms (tolerance
     * 1e-9: the truncated tails are below 1e-20, Gauss-Legendre of these
     * smooth integrands below 1e-12, the density's rounding below 1e-12):
     * a narrow gamma, v = 1e-12 (alpha ~ 1e12): <r^2> = beta^2 (alpha + 1)
     * (alpha + 2); a modified gamma with gamma = 1e-300, alpha = 1e302
     * (alpha/gamma overflows; the law is exp(-alpha gamma L^2 / 2) in
     * L = ln(r/r_c), a Gaussian of variance s2 = 1/(alpha gamma) = 0.01 in
     * L times dr = r dL): <r^2> = r_c^2 exp(4 s2) */
    w2[0] = mist_mie_wl(100, 1, mist_mie_cplx(1.33, 0));     /* x < 0.1: cheap */
    {
        double v = 1e-12, al = (1 - 3 * v) / v, be = 1 * v, s2;
        d = mist_mie_dist_gamma(1, v);
        a = mist_mie_average(&d, w2, 1, 1, NULL, 0, NULL);
        mt_check(a.status == MIST_MIE_OK
                 && near_rel(a.area, PI * be * be * (al + 1) * (al + 2), 1e-9),
                 "average: gamma v 1e-12: status %d area %.15g vs %.15g", a.status, a.area,
                 PI * be * be * (al + 1) * (al + 2));
        /* narrower than double resolves r (v < 1e-32: mist_mie_dist_gamma
         * takes the monodisperse law; its range had rounded to nothing,
         * EDOMAIN, from v = 1e-34 on): <r^2> = (1 - 2v)(1 - v) r_eff^2 */
        for (k = 0; k < 3; ++k) {
            double vv = k == 0 ? 1e-30 : k == 1 ? 1e-40 : 1e-300;
            d = mist_mie_dist_gamma(1, vv);
            a = mist_mie_average(&d, w2, 1, 1, NULL, 0, NULL);
            mt_check(a.status == MIST_MIE_OK
                     && near_rel(a.area, PI * (1 - 2 * vv) * (1 - vv), 1e-12),
                     "average: gamma v %g: status %d area %.17g", vv, a.status, a.area);
        }
        d = mist_mie_dist_modgamma(1e302, 1e-300, 1);
        s2 = 1 / (1e302 * 1e-300);
        d.r_min = exp(-12 * sqrt(s2)); d.r_max = exp(12 * sqrt(s2)); d.n_radii = 256;
        a = mist_mie_average(&d, w2, 1, 1, NULL, 0, NULL);
        mt_check(a.status == MIST_MIE_OK && near_rel(a.area, PI * exp(4 * s2), 1e-9),
                 "average: modified gamma alpha 1e302, gamma 1e-300: status %d area %.15g vs "
                 "%.15g", a.status, a.area, PI * exp(4 * s2));
    }

    /* the length domain's edges, each on its own: in, and one ulp out */
    for (k = 0; k < 4; ++k) {
        double edge = k < 2 ? MIST_MIE_LEN_MIN : MIST_MIE_LEN_MAX;
        double out = nextafter(edge, k < 2 ? 0 : INFINITY), in[2];
        int i;
        in[0] = edge; in[1] = out;
        for (i = 0; i < 2; ++i) {
            int want = i == 0 ? MIST_MIE_OK : MIST_MIE_EDOMAIN;
            double r1 = in[i], tw = 1;
            w2[0] = mist_mie_wl(k % 2 ? in[i] : (k < 2 ? 1e-29 : 1e29), 1, mist_mie_cplx(1.33, 0));
            if (k % 2 == 0) r1 = in[i]; else r1 = k < 2 ? 1e-30 : 1e30;
            /* k even: the radius at the edge (mono and table), odd: the
             * wavelength (with a radius inside) */
            d = mist_mie_dist_mono(r1);
            a = mist_mie_average(&d, w2, 1, 1, mu, NM, p);
            e = mist_mie_dist_table(&r1, &tw, 1);
            b = mist_mie_average(&e, w2, 1, 1, NULL, 0, NULL);
            ok = a.status == want && b.status == want
                 && (want != MIST_MIE_OK || (a.c_sca > 0 && a.area > 0 && a.volume > 0
                                            && p[0] > 0 && b.c_sca == a.c_sca));
            mt_check(ok, "average: %s %a: status %d/%d (want %d), C_sca %g, volume %g",
                     k % 2 ? "wavelength" : "radius", in[i], a.status, b.status, want, a.c_sca,
                     a.volume);
        }
    }
    /* a law's given range and radius at the edges: r_min = 0 or LEN_MIN and
     * r_max = LEN_MAX in; r_min one ulp below LEN_MIN (not 0), r_max one ulp
     * above LEN_MAX, r_g one ulp below LEN_MIN out */
    w2[0] = mist_mie_wl(1e29, 1, mist_mie_cplx(1.33, 0));
    for (k = 0; k < 6; ++k) {
        int want = k < 3 ? MIST_MIE_OK : MIST_MIE_EDOMAIN;
        d = mist_mie_dist_gamma(1e29, 0.1);
        d.r_min = k == 0 ? 0 : (k == 1 || k == 4 ? MIST_MIE_LEN_MIN
                                : k == 2 ? 1e28 : nextafter(MIST_MIE_LEN_MIN, 0));
        d.r_max = k == 4 ? nextafter(MIST_MIE_LEN_MAX, INFINITY) : MIST_MIE_LEN_MAX;
        d.n_radii = 16;
        if (k == 5) {
            d = mist_mie_dist_lognormal(nextafter(MIST_MIE_LEN_MIN, 0), 1.5);
            w2[0].lambda = 1e-29;
        }
        a = mist_mie_average(&d, w2, 1, 1, NULL, 0, NULL);
        mt_check(a.status == want && (want != MIST_MIE_OK || (a.c_sca > 0 && a.volume > 0)),
                 "average: law range edge case %d: status %d (want %d)", k, a.status, want);
    }

    /* a law whose automatic range ends past LEN_MAX: EDOMAIN; one at LEN_MIN: fine */
    d = mist_mie_dist_gamma(MIST_MIE_LEN_MAX, 0.1);
    w2[0] = mist_mie_wl(1e29, 1, mist_mie_cplx(1.33, 0));
    a = mist_mie_average(&d, w2, 1, 1, NULL, 0, NULL);
    mt_check(a.status == MIST_MIE_EDOMAIN, "average: gamma r_eff LEN_MAX auto: status %d",
             a.status);
    d = mist_mie_dist_gamma(MIST_MIE_LEN_MIN, 0.1);
    w2[0] = mist_mie_wl(1e-29, 1, mist_mie_cplx(1.33, 0));
    a = mist_mie_average(&d, w2, 1, 1, NULL, 0, NULL);
    mt_check(a.status == MIST_MIE_OK && a.c_sca > 0 && a.volume > 0,
             "average: gamma r_eff LEN_MIN: status %d", a.status);
}

/* ======================================================================== */

static void test_water(void)
{
    static const double n[19] = {1.343, 1.341, 1.339, 1.338, 1.337, 1.336, 1.335, 1.334, 1.333,
        1.333, 1.332, 1.332, 1.331, 1.331, 1.331, 1.33, 1.33, 1.33, 1.329};
    static const double k[19] = {6.50E-09, 3.50E-09, 1.86E-09, 1.30E-09, 1.02E-09, 9.35E-10,
        1.00E-09, 1.32E-09, 1.96E-09, 3.60E-09, 1.09E-08, 1.39E-08, 1.64E-08, 2.23E-08,
        3.35E-08, 9.15E-08, 1.56E-07, 1.48E-07, 1.25E-07};
    int i, st;
    mist_mie_complex m;
    for (i = 0; i < 19; ++i) {
        m = mist_mie_water(350 + 25 * i, &st);
        mt_check(st == MIST_MIE_OK && near_rel(m.re, n[i], 1e-15) && near_rel(m.im, k[i], 1e-15),
                 "water %d nm: (%.4f, %.3e)", 350 + 25 * i, m.re, m.im);
        if (i < 18) {   /* linear interpolation, checked at a fifth of the way */
            m = mist_mie_water(350 + 25 * i + 5, &st);
            mt_check(st == MIST_MIE_OK && near_rel(m.re, 0.8 * n[i] + 0.2 * n[i + 1], 1e-14)
                     && near_rel(m.im, 0.8 * k[i] + 0.2 * k[i + 1], 1e-12),
                     "water %d nm interpolated", 350 + 25 * i + 5);
        }
    }
    m = mist_mie_water(300, &st);
    mt_check(st == MIST_MIE_CLAMPED && m.re == n[0] && m.im == k[0], "water 300 nm clamped");
    m = mist_mie_water(-INFINITY, &st);
    mt_check(st == MIST_MIE_CLAMPED && m.re == n[0] && m.im == k[0], "water -inf clamped");
    m = mist_mie_water(1e9, &st);
    mt_check(st == MIST_MIE_CLAMPED && m.re == n[18] && m.im == k[18], "water 1e9 nm clamped");
    m = mist_mie_water(NAN, &st);
    mt_check(st == MIST_MIE_EDOMAIN && m.re == 0 && m.im == 0, "water NaN");
    m = mist_mie_water(550, NULL);     /* status may be NULL */
    mt_check(m.re == 1.333, "water, NULL status");
}

/* ======================================================================== */
/* Spectral to RGB (mist_mie_spectral_rgb and its tables)                   */
/* The tables against the standard's published properties: the 5 nm CMF    */
/* sums times 5 are the 1 nm integrals, 106.857 (CIE 15:2004; a 5 nm subset */
/* of a smooth curve sums to the 1 nm sum within ~1e-4 relative: bound      */
/* 0.01), equal-energy white at x = y = 1/3 (the CMFs are scaled to equal   */
/* integrals; 6-digit rows: bound 1e-4), D65 at (0.3127, 0.3290) (its       */
/* published white point to 4 digits: bound 1e-4), sRGB's matrix takes D65  */
/* to (1, 1, 1) (4-digit entries, ~5e-5 each, three terms: bound 1e-3).     */
/* The integration: droplets of r = 1e-4 um are Rayleigh scatterers (x <=   */
/* 1.7e-3, corrections O(x^2) = 3e-6: bound 2e-5), so every channel is      */
/* 3 / (16 pi) (1 + mu^2) and c_sca[c] is the closed-form cross section     */
/* (8 pi / 3) k^4 r^6 |(m^2 - 1) / (m^2 + 2)|^2 summed with the channel's   */
/* weights (D65 times rbar_c, trapezoids), computed here.  A fog (d = 4 um):*/
/* each channel integrates to 1 and has the returned g (trapezoids in mu on */
/* a 0.25 degree grid: the forward peak, ~10 degrees wide, gives ~1e-4;     */
/* bound 1e-3); the spectral sum has converged in its step (41 vs 81        */
/* wavelengths) far below the shortcut's difference (negative control: one  */
/* wavelength, 440 nm, for blue).                                           */
/* ======================================================================== */

static void test_spectral(void)
{
    enum { NM = 721 };
    static double mu[NM], p[3 * NM], q[3 * NM], one[NM];
    double sx = 0, sy = 0, sz = 0, X = 0, Y = 0, Z = 0, xyz[3], rgb[3], a[3];
    double w_ray[3] = { 0, 0, 0 }, resp[3] = { 0, 0, 0 }, worst = 0;
    mist_mie_complex mw[MIST_MIE_CIE_N];
    double spd[MIST_MIE_CIE_N], l1q = 0, l1s = 0;
    mist_mie_dist d;
    mist_mie_rgb r, r2;
    mist_mie_wavelength wl;
    mist_mie_avg av;
    int i, c;
    const double rad = 1e-4;

    for (i = 0; i < MIST_MIE_CIE_N; ++i) {
        double l = 380 + 5 * i, s = mist_mie_d65(l);
        mist_mie_cie1931(l, xyz);
        sx += xyz[0]; sy += xyz[1]; sz += xyz[2];
        X += s * xyz[0]; Y += s * xyz[1]; Z += s * xyz[2];
    }
    mt_check(fabs(5 * sx - 106.857) < 0.01 && fabs(5 * sy - 106.857) < 0.01
             && fabs(5 * sz - 106.857) < 0.01, "CMF integrals %.4f %.4f %.4f", 5 * sx,
             5 * sy, 5 * sz);
    mt_check(fabs(sx / (sx + sy + sz) - 1.0 / 3) < 1e-4 && fabs(sy / (sx + sy + sz) - 1.0 / 3)
             < 1e-4, "equal-energy white %.6f %.6f", sx / (sx + sy + sz), sy / (sx + sy + sz));
    mt_check(fabs(X / (X + Y + Z) - 0.3127) < 1e-4 && fabs(Y / (X + Y + Z) - 0.3290) < 1e-4,
             "D65 white %.6f %.6f", X / (X + Y + Z), Y / (X + Y + Z));
    xyz[0] = X / Y; xyz[1] = 1; xyz[2] = Z / Y;
    mist_mie_xyz_srgb(xyz, rgb);
    mt_check(fabs(rgb[0] - 1) < 1e-3 && fabs(rgb[1] - 1) < 1e-3 && fabs(rgb[2] - 1) < 1e-3,
             "D65 in sRGB %.5f %.5f %.5f", rgb[0], rgb[1], rgb[2]);
    /* between rows: linear; outside: 0 */
    mist_mie_cie1931(552.5, xyz);
    mt_check(fabs(xyz[1] - (0.994950 + 1.0) / 2) < 1e-15, "ybar(552.5) %.8f", xyz[1]);
    mt_check(fabs(mist_mie_d65(557.5) - (102.023 + 100.0) / 2) < 1e-12, "D65(557.5)");
    mist_mie_cie1931(379.9, xyz);
    mt_check(xyz[0] == 0 && xyz[1] == 0 && xyz[2] == 0 && mist_mie_d65(780.1) == 0
             && mist_mie_d65(NAN) == 0, "outside 380-780: 0");

    /* Rayleigh droplets */
    for (i = 0; i < NM; ++i) mu[i] = cos(PI * (NM - 1 - i) / (NM - 1));
    mu[0] = -1; mu[NM - 1] = 1;
    d = mist_mie_dist_mono(rad);
    r = mist_mie_spectral_rgb(&d, 1.0, NULL, NULL, MIST_MIE_CIE_N, mu, NM, p);
    for (i = 0; i < MIST_MIE_CIE_N; ++i) {
        double l = 380 + 5 * i, s = mist_mie_d65(l), k = 2 * PI / (l / 1000), w, cr;
        mist_mie_complex m = mist_mie_water(l, NULL);
        /* (m^2 - 1) / (m^2 + 2), m = a + i b */
        double re2 = m.re * m.re - m.im * m.im, im2 = 2 * m.re * m.im;
        double nr = re2 - 1, dr = re2 + 2, kk = (nr * nr + im2 * im2) / (dr * dr + im2 * im2);
        cr = 8 * PI / 3 * pow(k, 4) * pow(rad, 6) * kk;
        w = (i == 0 || i == MIST_MIE_CIE_N - 1 ? 0.5 : 1) * s;
        mist_mie_cie1931(l, xyz);
        mist_mie_xyz_srgb(xyz, rgb);
        for (c = 0; c < 3; ++c) { w_ray[c] += w * rgb[c] * cr; resp[c] += w * rgb[c]; }
        spd[i] = s;
        mw[i] = m;
    }
    for (i = 0; i < NM; ++i)
        for (c = 0; c < 3; ++c) {
            double ref = 3 / (16 * PI) * (1 + mu[i] * mu[i]), e = fabs(p[i * 3 + c] / ref - 1);
            if (e > worst) worst = e;
        }
    for (c = 0; c < 3; ++c) a[c] = w_ray[c] / resp[c];
    mt_check(r.status == MIST_MIE_OK && r.negative == 0 && worst < 2e-5,
             "spectral Rayleigh phase: status %d, worst %.2e", r.status, worst);
    mt_check(near_rel(r.c_sca[0], a[0], 2e-5) && near_rel(r.c_sca[1], a[1], 2e-5)
             && near_rel(r.c_sca[2], a[2], 2e-5) && r.c_sca[2] > r.c_sca[1]
             && r.c_sca[1] > r.c_sca[0], "spectral Rayleigh c_sca %.6e %.6e %.6e (%.6e %.6e %.6e)",
             r.c_sca[0], r.c_sca[1], r.c_sca[2], a[0], a[1], a[2]);
    r2 = mist_mie_spectral_rgb(&d, 1.0, mw, spd, MIST_MIE_CIE_N, mu, NM, q);
    mt_check(r2.status == MIST_MIE_OK && memcmp(p, q, sizeof p) == 0
             && r2.c_sca[0] == r.c_sca[0] && r2.c_sca[2] == r.c_sca[2],
             "spectral: given D65 and water = the defaults");

    /* a fog */
    d = mist_mie_dist_lognormal(2, 1.1);
    d.n_radii = 100;
    r = mist_mie_spectral_rgb(&d, 1.0, NULL, NULL, 81, mu, NM, p);
    r2 = mist_mie_spectral_rgb(&d, 1.0, NULL, NULL, 41, mu, NM, q);
    wl = mist_mie_wl(0.44, 1, mist_mie_water(440, NULL));
    av = mist_mie_average(&d, &wl, 1, 1.0, mu, NM, one);
    mt_check(r.status == MIST_MIE_OK && r2.status == MIST_MIE_OK && av.status == MIST_MIE_OK,
             "spectral fog: status %d %d %d", r.status, r2.status, av.status);
    for (c = 0; c < 3; ++c) {
        double s0 = 0, s1 = 0;
        for (i = 0; i + 1 < NM; ++i) {
            double h = mu[i + 1] - mu[i];
            s0 += h * (p[i * 3 + c] + p[(i + 1) * 3 + c]) / 2;
            s1 += h * (mu[i] * p[i * 3 + c] + mu[i + 1] * p[(i + 1) * 3 + c]) / 2;
            if (c == 2) {
                l1q += 2 * PI * h * (fabs(p[i * 3 + 2] - q[i * 3 + 2])
                                     + fabs(p[(i + 1) * 3 + 2] - q[(i + 1) * 3 + 2])) / 2;
                l1s += 2 * PI * h * (fabs(p[i * 3 + 2] - one[i])
                                     + fabs(p[(i + 1) * 3 + 2] - one[i + 1])) / 2;
            }
        }
        mt_check(fabs(2 * PI * s0 - 1) < 1e-3 && fabs(2 * PI * s1 - r.g[c]) < 1e-3,
                 "spectral fog channel %d: integral %.6f, g %.6f (returned %.6f)", c,
                 2 * PI * s0, 2 * PI * s1, r.g[c]);
    }
    mt_check(l1q < 0.2 * l1s, "spectral fog blue: 41 vs 81 wavelengths L1 %.2e, vs 440 nm %.2e",
             l1q, l1s);
    if (verbose)
        printf("spectral: fog L1 41/81 %.2e, 440 nm %.2e; negative %lu\n", l1q, l1s,
               (unsigned long)r.negative);

    /* bad input */
    p[0] = 7;
    r = mist_mie_spectral_rgb(&d, 1.0, NULL, NULL, 1, mu, NM, p);
    mt_check(r.status == MIST_MIE_EDOMAIN && p[0] == 0, "spectral: n_lambda 1");
    spd[3] = -1;
    r = mist_mie_spectral_rgb(&d, 1.0, NULL, spd, MIST_MIE_CIE_N, mu, NM, p);
    mt_check(r.status == MIST_MIE_EDOMAIN && r.c_sca[0] == 0, "spectral: negative spd");
    spd[3] = NAN;
    r = mist_mie_spectral_rgb(&d, 1.0, NULL, spd, MIST_MIE_CIE_N, mu, NM, p);
    mt_check(r.status == MIST_MIE_EDOMAIN, "spectral: NaN spd");
    r = mist_mie_spectral_rgb(&d, 1.0, NULL, NULL, MIST_MIE_CIE_N, NULL, NM, p);
    mt_check(r.status == MIST_MIE_EDOMAIN, "spectral: NULL mu");
    r = mist_mie_spectral_rgb(&d, -1.0, NULL, NULL, MIST_MIE_CIE_N, mu, NM, p);
    mt_check(r.status == MIST_MIE_EDOMAIN && p[5] == 0, "spectral: n_medium < 0");
}

/* ======================================================================== */
/* Bad input gets the documented result (mist_mie.h DOMAIN AND BAD INPUT)   */
/* ======================================================================== */

static int all_zero(const mist_mie_sphere *s)
{
    return s->n_terms == 0 && s->x == 0 && s->q_ext == 0 && s->q_sca == 0 && s->q_abs == 0
        && s->q_back == 0 && s->g == 0 && s->m.re == 0 && s->m.im == 0;
}

static int zero_outputs(const mist_mie_sphere *s)
{
    mist_mie_complex a = {1, 1}, b = {1, 1};
    double mu[3] = {1, 0, -1}, p[3] = {7, 7, 7};
    mist_mie_amplitudes(s, 0.3, &a, &b);
    mist_mie_phase_table(s, mu, 3, p);
    return a.re == 0 && a.im == 0 && b.re == 0 && b.im == 0 && mist_mie_phase(s, 0.3) == 0
        && p[0] == 0 && p[1] == 0 && p[2] == 0;
}

static void test_bad_input(void)
{
    static const double bad_x[] = {0, -0.0, -1, NAN, INFINITY, -INFINITY,
                                   MIST_MIE_X_MAX * 1.000001};
    mist_mie_complex bad_m[9];
    double work[256];
    size_t i;
    mist_mie_sphere s;
    for (i = 0; i < sizeof bad_x / sizeof bad_x[0]; ++i) {
        s = mist_mie_sphere_new(bad_x[i], mist_mie_cplx(1.33, 0));
        mt_check(s.status == MIST_MIE_EDOMAIN && all_zero(&s) && zero_outputs(&s),
                 "bad x %g", bad_x[i]);
        mt_check(mist_mie_terms(bad_x[i]) == 0 && mist_mie_workspace_size(bad_x[i]) == 0,
                 "terms of bad x %g", bad_x[i]);
    }
    bad_m[0] = mist_mie_cplx(1.33, -1e-9);     /* mi < 0 */
    bad_m[1] = mist_mie_cplx(0, 1);            /* mr = 0 */
    bad_m[2] = mist_mie_cplx(-1.5, 0);
    bad_m[3] = mist_mie_cplx(NAN, 0);
    bad_m[4] = mist_mie_cplx(1.33, NAN);
    bad_m[5] = mist_mie_cplx(INFINITY, NAN);
    bad_m[6] = mist_mie_cplx(2e6, 0);          /* |m| > MIST_MIE_M_MAX */
    bad_m[7] = mist_mie_cplx(1e-7, 0);         /* |m| < MIST_MIE_M_MIN */
    bad_m[8] = mist_mie_cplx(-INFINITY, 0);
    for (i = 0; i < 9; ++i) {
        s = mist_mie_sphere_new(1.5, bad_m[i]);
        mt_check(s.status == MIST_MIE_EDOMAIN && all_zero(&s) && zero_outputs(&s),
                 "bad m (%g, %g)", bad_m[i].re, bad_m[i].im);
    }
    s = mist_mie_sphere_new(1e4, mist_mie_cplx(2000, 0));   /* |m| x > MIST_MIE_MX_MAX */
    mt_check(s.status == MIST_MIE_EDOMAIN, "|m| x too large");
    /* the conductor: +inf in either part */
    s = mist_mie_sphere_new(2, mist_mie_cplx(1.5, INFINITY));
    {
        mist_mie_sphere t = mist_mie_sphere_new(2, mist_mie_conductor());
        mt_check(s.status == MIST_MIE_OK && s.q_sca == t.q_sca && s.g == t.g,
                 "(1.5, inf) is the conductor");
        mist_mie_sphere_free(&t);
    }
    mist_mie_sphere_free(&s);
    mist_mie_sphere_free(&s);             /* twice: harmless */
    mist_mie_sphere_free(NULL);

    /* workspace */
    s = mist_mie_sphere_make(2, mist_mie_cplx(1.33, 0), NULL, 100);
    mt_check(s.status == MIST_MIE_ENOMEM && all_zero(&s), "NULL workspace");
    mt_check(mist_mie_workspace_size(2) <= 256, "workspace size at x=2");
    s = mist_mie_sphere_make(2, mist_mie_cplx(1.33, 0), work, mist_mie_workspace_size(2) - 1);
    mt_check(s.status == MIST_MIE_ENOMEM && zero_outputs(&s), "workspace one short");
    s = mist_mie_sphere_make(2, mist_mie_cplx(1.33, 0), work, mist_mie_workspace_size(2));
    mt_check(s.status == MIST_MIE_OK && s.q_sca > 0, "workspace exact");

    /* mu: clamped, NaN gives 0 */
    {
        mist_mie_complex a, b, c, d;
        mist_mie_amplitudes(&s, 1.5, &a, &b);
        mist_mie_amplitudes(&s, 1, &c, &d);
        mt_check(a.re == c.re && a.im == c.im && b.re == d.re
                 && mist_mie_phase(&s, 7) == mist_mie_phase(&s, 1)
                 && mist_mie_phase(&s, -INFINITY) == mist_mie_phase(&s, -1), "mu clamped");
        mist_mie_amplitudes(&s, NAN, &a, &b);
        mt_check(a.re == 0 && a.im == 0 && b.re == 0 && b.im == 0 && mist_mie_phase(&s, NAN) == 0,
                 "mu NaN");
        mist_mie_amplitudes(&s, 0.2, NULL, NULL);   /* NULL outputs allowed */
    }
    /* m = 1: nothing scatters */
    s = mist_mie_sphere_new(3, mist_mie_cplx(1, 0));
    mt_check(s.status == MIST_MIE_OK && s.q_sca == 0 && s.q_ext == 0 && s.g == 0
             && mist_mie_phase(&s, 0.5) == 0,
             "m = 1: Qsca %g, p %g", s.q_sca, mist_mie_phase(&s, 0.5));
    mist_mie_sphere_free(&s);
    s = mist_mie_sphere_new(1e-10, mist_mie_cplx(1, 0));   /* the dipole branch too */
    mt_check(s.status == MIST_MIE_OK && s.q_sca == 0 && mist_mie_phase(&s, 0.5) == 0,
             "m = 1, tiny x");
    mist_mie_sphere_free(&s);
    /* m = 1 + 1e-158 i ... 1e-165 i: the dipole's coefficients' squares
     * leave the range, while p is their ratio: the dipole's 3 (1 + mu^2) /
     * (16 pi) (closed form; 2 ulps for the roundings of the scaled sum).
     * The previous header gave +inf (1e-158, 1e-161) and 0 (1e-165), status
     * OK; an independent check found it.  The series (x = 1e-3) there:
     * finite (0: documented, the accuracy near m = 1 at the top) */
    {
        static const double mi[] = { 1e-150, 1e-158, 1e-161, 1e-165 };
        size_t k;
        for (k = 0; k < sizeof mi / sizeof *mi; ++k) {
            double p, pd = 3 * (1 + 0.25) / (16 * PI);
            s = mist_mie_sphere_new(1e-20, mist_mie_cplx(1, mi[k]));
            p = mist_mie_phase(&s, 0.5);
            mt_check(s.status == MIST_MIE_OK && near_rel(p, pd, 4.5e-16),
                     "dipole, m = 1 + %g i: p(0.5) %.17g, closed form %.17g", mi[k], p, pd);
            mist_mie_sphere_free(&s);
            s = mist_mie_sphere_new(1e-3, mist_mie_cplx(1, mi[k]));
            p = mist_mie_phase(&s, 0.5);
            mt_check(s.status == MIST_MIE_OK && p >= 0 && p < 1,
                     "series, m = 1 + %g i: p(0.5) %g", mi[k], p);
            mist_mie_sphere_free(&s);
        }
    }

    /* averages */
    {
        mist_mie_wavelength wl[2];
        mist_mie_dist d = mist_mie_dist_gamma(2, 0.1), dd;
        double mu[4] = {1, 0.5, -0.5, -1}, p[4];
        mist_mie_avg a;
        int k, bad = 0;
        wl[0] = mist_mie_wl(0.55, 1, mist_mie_water(550, NULL));
        wl[1] = mist_mie_wl(0.45, 1, mist_mie_water(450, NULL));
        for (k = 0; k < 24; ++k) {
            mist_mie_wavelength w2[2];
            const mist_mie_dist *dp = &dd;
            size_t nwl = 2;
            double nmed = 1;
            w2[0] = wl[0]; w2[1] = wl[1];
            dd = d;
            switch (k) {
            case 0: dp = NULL; break;
            case 1: nwl = 0; break;
            case 2: w2[1].lambda = 0; break;
            case 3: w2[1].lambda = NAN; break;
            case 4: w2[1].weight = -1; break;
            case 5: w2[0].weight = w2[1].weight = 0; break;
            case 6: nmed = 0; break;
            case 7: nmed = NAN; break;
            case 8: dd = mist_mie_dist_gamma(0, 0.1); break;
            case 9: dd = mist_mie_dist_gamma(2, 0.5); break;
            case 10: dd = mist_mie_dist_lognormal(1, 1); break;
            case 11: dd = mist_mie_dist_modgamma(0, 1, 4); break;
            case 12: dd.r_min = 3; dd.r_max = 1; break;
            case 13: dd.n_radii = -8; break;
            case 14: dd = mist_mie_dist_mono(-1); break;
            case 15: dd = mist_mie_dist_table(NULL, NULL, 3); break;
            case 16: w2[1].m = mist_mie_cplx(1.33, -1); break;
            case 17: dd = mist_mie_dist_mono(1e5); break;                 /* x > X_MAX */
            case 18: dd.kind = 42; break;
            case 19: w2[1].weight = INFINITY; break;
            case 20: dd = mist_mie_dist_lognormal(1, 1.5); dd.r_min = 0; dd.r_max = 2; break;
            case 21: dd = mist_mie_dist_modgamma(6, -1, 4); break;
            case 22: dd.r_min = NAN; break;
            case 23: dd = mist_mie_dist_mono(NAN); break;
            }
            p[0] = p[1] = p[2] = p[3] = 5;
            a = mist_mie_average(dp, w2, nwl, nmed, mu, 4, p);
            if (!(a.status == MIST_MIE_EDOMAIN && a.c_ext == 0 && a.c_sca == 0 && a.g == 0
                  && a.area == 0 && p[0] == 0 && p[1] == 0 && p[2] == 0 && p[3] == 0)) {
                ++bad;
                printf("FAIL: average bad input case %d: status %d\n", k, a.status);
            }
        }
        mt_check(bad == 0, "average bad input: %d not rejected", bad);
        a = mist_mie_average(&d, wl, 2, 1, mu, 4, NULL);
        mt_check(a.status == MIST_MIE_EDOMAIN, "average: phase NULL with n_mu > 0");
        a = mist_mie_average(&d, wl, 2, 1, NULL, 0, NULL);
        mt_check(a.status == MIST_MIE_OK, "average: no phase table");
    }
}

/* Random valid input over the whole domain: never NaN or infinity,
 * 0 <= Q_sca <= Q_ext, Q_abs >= 0, |g| <= 1, p >= 0. */
static void test_sweep(void)
{
    mt_rng rng = {12345};
    int i, j, bad = 0;
    for (i = 0; i < 3000; ++i) {
        double x = pow(10, -14 + 17 * mt_uniform(&rng));          /* 1e-14 .. 1e3 */
        double mr = pow(10, -2 + 3 * mt_uniform(&rng));            /* 0.01 .. 10 */
        double mi = mt_uniform(&rng) < 0.3 ? 0 : pow(10, -10 + 11 * mt_uniform(&rng));
        mist_mie_complex m = i % 50 == 0 ? mist_mie_conductor() : mist_mie_cplx(mr, mi);
        mist_mie_sphere s;
        if (i % 7 == 0) x = 1e-8 * (0.5 + mt_uniform(&rng));       /* near the switch */
        if (i % 11 == 0) m = mist_mie_cplx(1 + 1e-12 * mt_uniform(&rng), 0);
        s = mist_mie_sphere_new(x, m);
        if (s.status != MIST_MIE_OK || !(s.q_sca >= 0 && s.q_ext >= s.q_sca && s.q_abs >= 0
            && isfinite(s.q_ext) && isfinite(s.q_back) && s.q_back >= 0 && fabs(s.g) <= 1)) {
            ++bad;
            if (bad < 5) printf("sweep: x %g m (%g, %g): status %d Qe %g Qs %g g %g\n",
                                x, m.re, m.im, s.status, s.q_ext, s.q_sca, s.g);
        }
        for (j = 0; j < 5; ++j) {
            double u = -1 + 0.5 * j, p = mist_mie_phase(&s, u);
            mist_mie_complex a, b;
            mist_mie_amplitudes(&s, u, &a, &b);
            if (!(p >= 0 && isfinite(p) && isfinite(a.re + a.im + b.re + b.im))) {
                ++bad;
                if (bad < 5) printf("sweep: x %g m (%g, %g) u %g: p %g\n", x, m.re, m.im, u, p);
            }
        }
        mist_mie_sphere_free(&s);
    }
    mt_check(bad == 0, "sweep: %d bad results", bad);
}

/* ======================================================================== */
/* The benchmark's workload: one droplet diameter, 1800 angles uniform in   */
/* theta, three wavelengths (450, 550, 650 nm), through mist_mie_average:   */
/* d = 10 um (x ~ 57 at 550 nm) and d = 50 um (x ~ 285).                    */
/* ======================================================================== */

/* It runs and gives a valid average: status OK, a positive finite phase,
 * and an asymmetry in a loose band, 0.8-0.9, around the ~0.86 of large
 * water droplets in visible light (a sanity band: the Mie values
 * themselves are tested above against published ones).  Its speed
 * is the benchmark's to measure (issue 3: "measure it in the benchmarks"),
 * not this test's: a time bound here was removed. */
static void test_bench_workload(void)
{
    static const double dia[2] = {10, 50};
    double mu[1800], p[1800];
    mist_mie_wavelength wl[3];
    int i;
    wl[0] = mist_mie_wl(0.45, 1, mist_mie_water(450, NULL));
    wl[1] = mist_mie_wl(0.55, 1, mist_mie_water(550, NULL));
    wl[2] = mist_mie_wl(0.65, 1, mist_mie_water(650, NULL));
    mist_mie_theta_grid(1800, mu);
    for (i = 0; i < 2; ++i) {
        mist_mie_dist d = mist_mie_dist_mono(dia[i] / 2);
        mist_mie_avg a = mist_mie_average(&d, wl, 3, 1.0, mu, 1800, p);
        mt_check(a.status == MIST_MIE_OK && a.g > 0.8 && a.g < 0.9 && p[0] > 0 && p[0] == p[0],
                 "d = %g um, 1800 angles x 3 wavelengths: status %d, g %g", dia[i],
                 (int)a.status, a.g);
    }
}

int main(void)
{
    const char *v = getenv("MIST_VERBOSE");
    clock_t t0 = clock();
    verbose = v && *v && *v != '0';
    test_wiscombe();
    test_series_tail();
    test_near_one();
    test_edge_symmetry();
    test_dipole_tiny();
    test_average_steps();
    test_du();
    test_bohren_huffman();
    test_small();
    test_quadrature();
    test_large();
    test_distributions();
    test_average_phase();
    test_average_extremes();
    test_water();
    test_spectral();
    test_bad_input();
    test_sweep();
    test_bench_workload();
    if (verbose) printf("total: %.2f s\n", (double)(clock() - t0) / CLOCKS_PER_SEC);
    return mt_done("test_mie");
}
