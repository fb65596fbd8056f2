/* fuzz_mie.c - libFuzzer harness for the opt-in Lorenz-Mie solver,
 * include/mist_mie.h: mist_mie_sphere_{make,new,free}, mist_mie_phase,
 * mist_mie_amplitudes, mist_mie_phase_table, mist_mie_theta_grid,
 * mist_mie_water, mist_mie_dist_*, mist_mie_average, mist_mie_terms,
 * mist_mie_workspace_size, mist_mie_cplx, mist_mie_conductor, mist_mie_wl,
 * against the behaviour the header documents (DOMAIN AND BAD INPUT and the
 * comment of each function); a violation prints the inputs and aborts.
 *
 * The input is a sequence of records: one byte picks the operation
 * (modulo 5: sphere, sphere from a caller's workspace, theta grid, water,
 * average), then each number takes one little-endian 64-bit word w (two
 * for raw bits; missing bytes read as 0): w & 7 = 0..5: a value in the
 * operation's in-domain range from the top 53 bits (even: uniform, odd:
 * log-uniform); 6: a bad or edge value from a table (NaN, +-inf, 0, -0,
 * -1, a subnormal, 1e300); 7: the raw bits of the next word.
 *
 * Sizes stay small so that a run stays fast: size parameters x <= 2000
 * (X_CAP; a larger in-domain x from raw bits skips the record),
 * |m| x <= 2e5, tables <= 64 entries, averages <= 64 radii and 3
 * wavelengths with x <= 2000.
 *
 * Under -ffast-math (MI_FAST, tests/mist_inv.h) only finite values reach
 * the library (the table's NaN and infinities and raw bits are replaced by
 * in-domain draws), as fuzz_hfog.c does: they are outside what -ffast-math
 * promises.  -DMI_ALL_INPUTS reads them anyway.
 *
 *   clang -fsanitize=fuzzer,address,undefined -Iinclude -Itests fuzz/fuzz_mie.c
 * or without libFuzzer, replaying files: fuzz/replay.c. */
#include "mist_inv.h"
#include "mist_mie.h"
#define FZ_OWN_ENTRY     /* its own record format */
#include "fuzz_common.h"

#define X_CAP  2000.0
#define MX_CAP 2e5
#define N_CAP  64

/* A number: in [lo, hi] (hi > lo > 0 for the log-uniform recipes), or a
 * bad/edge value, or raw bits (see the top). */
static double fz_num(mi_bytes *b, double lo, double hi)
{
    uint64_t w = mi_take(b, 8);
    unsigned k = (unsigned)(w & 7);
    double u = (double)(w >> 11) * 0x1p-53;
    if (k == 7 && !MI_FAST) return mi_from_bits_d(mi_take(b, 8));
    if (k == 6) {
        static const uint64_t bad[8] = {
            0x7ff8000000000000ULL, 0x7ff0000000000000ULL, 0xfff0000000000000ULL,
            0, 0x8000000000000000ULL, 0xbff0000000000000ULL /* -1 */,
            0x0000000000000001ULL, 0x7e37e43c8800759cULL /* 1e300 */ };
        unsigned i = (unsigned)((w >> 3) % 8);
        if (!MI_FAST || (i != 0 && i != 1 && i != 2 && i != 6))
            return mi_from_bits_d(bad[i]);
    }
    if ((k & 1) && lo > 0) return lo * pow(hi / lo, u);
    return lo + (hi - lo) * u;
}

static int fz_fin(double v) { return mi_fin_d(v); }

/* the sphere's domain (DOMAIN AND BAD INPUT), from the bits */
static int fz_valid(double x, mist_mie_complex m, int *pec)
{
    double am;
    *pec = 0;
    if (mi_nan_d(x) || mi_nan_d(m.re) || mi_nan_d(m.im)) return 0;
    if (!(x > 0 && x <= MIST_MIE_X_MAX) || !(m.re > 0) || !(m.im >= 0)) return 0;
    if (mi_inf_d(m.re) || mi_inf_d(m.im)) { *pec = 1; return 1; }
    am = sqrt(m.re * m.re + m.im * m.im);
    return am >= MIST_MIE_M_MIN && am <= MIST_MIE_M_MAX && am * x <= MIST_MIE_MX_MAX;
}

static void fz_zero_sphere(const mist_mie_sphere *s, int st, double x, mist_mie_complex m)
{
    if (s->status != st || s->n_terms != 0 || s->x != 0 || s->m.re != 0 || s->m.im != 0
        || s->q_ext != 0 || s->q_sca != 0 || s->q_abs != 0 || s->q_back != 0 || s->g != 0
        || s->owned_ != NULL)
        mi_fail("mie sphere(x=%a, m=(%a, %a)): status %d (want %d) and not all zero", x, m.re,
                m.im, s->status, st);
}

/* the documented properties of a sphere, its phase function, amplitudes and
 * tables at the angles mu[0..n) */
static void fz_check_sphere(const mist_mie_sphere *s, double x, mist_mie_complex m,
                            const double *mu, size_t n)
{
    int pec, valid = fz_valid(x, m, &pec);
    size_t j;
    double p[N_CAP];
    mist_mie_complex s1, s2;
    if (!valid) {                       /* bad x or m: EDOMAIN, all 0, functions give 0 */
        fz_zero_sphere(s, MIST_MIE_EDOMAIN, x, m);
    } else if (s->status != MIST_MIE_OK) {
        mi_fail("mie sphere(x=%a, m=(%a, %a)): status %d for valid input", x, m.re, m.im,
                s->status);
        return;
    } else {
        /* Finite valid input: finite results, Q >= 0, Q_abs = Q_ext - Q_sca >= 0 (the
         * library clamps it; for mi = 0 and the conductor Q_ext is Q_sca exactly),
         * Q_sca <= Q_ext (the header sets q_abs = max(q_ext - q_sca, 0): the two
         * series are separate sums, so a nearly absorption-free sphere may have
         * Q_sca above Q_ext by their rounding; a sum of N <= 2100 terms of one sign
         * errs by < N eps relative, 2100 * 1.1e-16 = 2.4e-13, and the coefficients'
         * own error grows like 1e-16 / |m - 1| (the header): 1e-9 relative plus
         * 1e-16 / |m - 1| covers both with room), |g| <= 1, 1 <= N <= the most
         * terms the workspace holds, mist_mie_workspace_size / 9 - 1 (m = 1 and
         * the dipole limit store one term). */
        double dm = sqrt((m.re - 1) * (m.re - 1) + m.im * m.im);
        double tol = pec ? 1e-9 : 1e-9 + (dm > 0 ? 1e-16 / dm : 1);
        if (!(fz_fin(s->q_ext) && fz_fin(s->q_sca) && fz_fin(s->q_abs) && fz_fin(s->q_back)
              && fz_fin(s->g) && s->q_ext >= 0 && s->q_sca >= 0 && s->q_abs >= 0
              && s->q_back >= 0 && s->q_sca <= s->q_ext * (1 + tol) && fabs(s->g) <= 1
              && s->n_terms >= 1
              && (size_t)s->n_terms <= mist_mie_workspace_size(x) / 9 - 1 && s->x == x))
            mi_fail("mie sphere(x=%a, m=(%a, %a)): N %d Qe %a Qs %a Qa %a Qb %a g %a", x,
                    m.re, m.im, s->n_terms, s->q_ext, s->q_sca, s->q_abs, s->q_back, s->g);
    }
    for (j = 0; j < n; ++j) {
        double ph = mist_mie_phase(s, mu[j]);
        mist_mie_amplitudes(s, mu[j], &s1, &s2);
        if (mi_nan_d(mu[j]) || !valid) {
            if (ph != 0 || s1.re != 0 || s1.im != 0 || s2.re != 0 || s2.im != 0)
                mi_fail("mie x=%a m=(%a, %a) mu=%a: want 0, got p %a S1 (%a, %a) S2 (%a, %a)",
                        x, m.re, m.im, mu[j], ph, s1.re, s1.im, s2.re, s2.im);
        } else if (!(fz_fin(ph) && ph >= 0 && fz_fin(s1.re) && fz_fin(s1.im) && fz_fin(s2.re)
                     && fz_fin(s2.im)))
            mi_fail("mie x=%a m=(%a, %a) mu=%a: p %a S1 (%a, %a) S2 (%a, %a)", x, m.re, m.im,
                    mu[j], ph, s1.re, s1.im, s2.re, s2.im);
    }
    mist_mie_amplitudes(s, 0.5, NULL, NULL);               /* s1, s2 may be NULL */
    mist_mie_phase_table(s, NULL, 0, NULL);                /* n = 0: NULL allowed */
    if (n == 0) return;
    mist_mie_phase_table(s, mu, n, p);
    for (j = 0; j < n; ++j)
        if (mi_nan_d(mu[j]) || !valid ? p[j] != 0 : !(fz_fin(p[j]) && p[j] >= 0))
            mi_fail("mie phase_table x=%a m=(%a, %a) mu[%u]=%a: %a", x, m.re, m.im,
                    (unsigned)j, mu[j], p[j]);
}

/* x, m and a few cosines; skips in-domain input past the size caps */
static int fz_sphere_input(mi_bytes *b, double *x, mist_mie_complex *m, double *mu, size_t *n)
{
    unsigned sel = (unsigned)mi_take(b, 1), j;
    int pec;
    *x = fz_num(b, 1e-12, X_CAP);
    switch (sel % 4) {
    case 0: *m = mist_mie_conductor(); break;
    case 1: *m = mist_mie_cplx(1, 0); break;             /* nothing scatters */
    default:
        *m = mist_mie_cplx(fz_num(b, 1e-3, 20), (sel & 4) ? 0 : fz_num(b, 1e-12, 10));
    }
    *n = (sel >> 3) % 9;
    for (j = 0; j < *n; ++j) mu[j] = fz_num(b, -1.25, 1.25);   /* some clamped */
    if (fz_valid(*x, *m, &pec)
        && (*x > X_CAP || (!pec && sqrt(m->re * m->re + m->im * m->im) * *x > MX_CAP)))
        return 0;
    return 1;
}

static void fz_op_sphere(mi_bytes *b)
{
    double x, mu[8];
    mist_mie_complex m;
    mist_mie_sphere s;
    size_t n;
    int pec, valid;
    if (!fz_sphere_input(b, &x, &m, mu, &n)) return;
    valid = fz_valid(x, m, &pec);
    /* the workspace: 9 doubles for each of Wiscombe's N + 4 x^(1/3) + 8 terms
     * (the most mist_mie sums), and one more term's */
    if (valid ? mist_mie_terms(x) <= 0
                || mist_mie_workspace_size(x)
                   != 9 * ((size_t)mist_mie_terms(x) + (size_t)(4 * pow(x, 1.0 / 3.0)) + 9)
              : (x > 0 && x <= MIST_MIE_X_MAX) ? 0
              : mist_mie_terms(x) != 0 || mist_mie_workspace_size(x) != 0)
        mi_fail("mie terms(%a) = %d, workspace_size %u", x, mist_mie_terms(x),
                (unsigned)mist_mie_workspace_size(x));
    s = mist_mie_sphere_new(x, m);
    if (s.status == MIST_MIE_ENOMEM) fz_zero_sphere(&s, MIST_MIE_ENOMEM, x, m);
    else fz_check_sphere(&s, x, m, mu, n);
    mist_mie_sphere_free(&s);
    if (s.owned_ != NULL || s.coef_ != NULL || s.n_terms != 0)
        mi_fail("mie sphere_free(x=%a): not zeroed", x);
    mist_mie_sphere_free(&s);                      /* twice: nothing */
    mist_mie_sphere_free(NULL);
}

static void fz_op_make(mi_bytes *b)
{
    static double work[9 * 2200];
    double x, mu[8];
    mist_mie_complex m;
    mist_mie_sphere s;
    size_t n, need, give;
    unsigned short_by;
    int pec;
    if (!fz_sphere_input(b, &x, &m, mu, &n)) return;
    need = mist_mie_workspace_size(x);
    short_by = (unsigned)mi_take(b, 1) % 4;        /* 0: enough; else too small or NULL */
    give = short_by == 0 ? need : short_by == 1 ? (need ? need - 1 : 0) : short_by == 2 ? 0 : need;
    if (give > sizeof work / sizeof work[0]) return;
    s = mist_mie_sphere_make(x, m, short_by == 3 ? NULL : work, give);
    if (!fz_valid(x, m, &pec)) fz_zero_sphere(&s, MIST_MIE_EDOMAIN, x, m);
    else if (short_by) fz_zero_sphere(&s, MIST_MIE_ENOMEM, x, m);
    else fz_check_sphere(&s, x, m, mu, n);
    mist_mie_sphere_free(&s);                      /* not owned: only zeroes it */
}

static void fz_op_grid(mi_bytes *b)
{
    double mu[N_CAP + 1];
    size_t n = (size_t)(mi_take(b, 1) % (N_CAP + 1)), j;
    mu[n < N_CAP ? n : N_CAP] = 42;                /* the grid writes n entries only */
    mist_mie_theta_grid(n, mu);
    if (n < N_CAP && mu[n] != 42) mi_fail("mie theta_grid(%u) wrote past n", (unsigned)n);
    if (n == 1 && mu[0] != 1) mi_fail("mie theta_grid(1): mu[0] = %a", mu[0]);
    for (j = 0; j < n; ++j)
        if (!(mu[j] >= -1 && mu[j] <= 1) || (n > 1 && mu[n - 1 - j] != -mu[j])
            || (j > 0 && !(mu[j] < mu[j - 1])) || (n > 1 && j == 0 && mu[0] != 1)
            || (n > 1 && 2 * j + 1 == n && mu[j] != 0))
            mi_fail("mie theta_grid(%u): mu[%u] = %a", (unsigned)n, (unsigned)j, mu[j]);
}

static void fz_op_water(mi_bytes *b)
{
    double lam = fz_num(b, 200, 1000);
    int st = -1;
    mist_mie_complex m = mist_mie_water(lam, &st), m2 = mist_mie_water(lam, NULL);
    int want = mi_nan_d(lam) ? MIST_MIE_EDOMAIN
             : (lam >= 350 && lam <= 800) ? MIST_MIE_OK : MIST_MIE_CLAMPED;
    if (st != want || mi_bits_d(m.re) != mi_bits_d(m2.re) || mi_bits_d(m.im) != mi_bits_d(m2.im)
        || (want == MIST_MIE_EDOMAIN ? m.re != 0 || m.im != 0
            : !(m.re > 1.3 && m.re < 1.4 && m.im >= 0 && m.im < 1e-6)))
        mi_fail("mie water(%a): status %d (want %d) m (%a, %a)", lam, st, want, m.re, m.im);
}

static void fz_op_average(mi_bytes *b)
{
    unsigned sel = (unsigned)mi_take(b, 2), bad = (sel >> 8) % 16, l, j;
    size_t n_wl = 1 + (sel >> 3) % 3, n_mu = (sel >> 5) % 9, i;
    double wsum = 0, n_med = fz_num(b, 1, 1.5), r[8], w[8], mu[8], ph[8], rcap;
    mist_mie_wavelength wl[3];
    mist_mie_dist d;
    mist_mie_avg a;
    int valid = 1, pec, wpos = 0, wzero = 0;
    /* the radii keep x = 2 pi n_medium r / lambda <= X_CAP at lambda >= 0.35 */
    rcap = X_CAP * 0.35 / (2 * MIST_MIE__PI * 1.5);
    for (l = 0; l < n_wl; ++l) {
        double lam = fz_num(b, 0.35, 0.8), wt = fz_num(b, 0.01, 1);
        mist_mie_complex m = (sel >> 11) & 1 ? mist_mie_water(lam * 1000, NULL)
                                            : mist_mie_cplx(fz_num(b, 1.01, 3), fz_num(b, 0, 1));
        wl[l] = mist_mie_wl(lam, wt, m);
        if (fz_fin(lam) && lam > 0 && lam < 0.35) return;                /* x cap */
        /* lengths inside [MIST_MIE_LEN_MIN, MIST_MIE_LEN_MAX]; weights of any
         * scale (they are normalised: subnormal and 1e300 allowed) */
        if (!(lam >= MIST_MIE_LEN_MIN && lam <= MIST_MIE_LEN_MAX && wt >= 0 && fz_fin(wt)
              && fz_valid(1e-3, mist_mie_cplx(m.re / n_med, m.im / n_med), &pec)))
            valid = 0;                             /* a bad draw: must be refused */
        wsum += wt;
        if (m.re > 3 || mi_inf_d(m.re) || mi_inf_d(m.im) || m.im > 1) return;   /* x cap */
        if (mi_bits_d(wl[l].lambda) != mi_bits_d(lam) || mi_bits_d(wl[l].weight) != mi_bits_d(wt))
            mi_fail("mie_wl: fields");
    }
    if (!(wsum > 0)) valid = 0;
    if (fz_fin(n_med) && n_med > 0 && !(n_med >= 1 && n_med <= 1.5)) return;   /* x cap */
    if (!(n_med > 0 && fz_fin(n_med))) valid = 0;
    for (j = 0; j < n_mu; ++j) mu[j] = fz_num(b, -1, 1);
    switch (sel % 5) {
    case 0: d = mist_mie_dist_mono(fz_num(b, 1e-4, rcap)); break;
    case 1: d = mist_mie_dist_gamma(fz_num(b, 0.1, 10), fz_num(b, 0.01, 0.45)); break;
    case 2: d = mist_mie_dist_modgamma(fz_num(b, 0.5, 8), fz_num(b, 0.5, 3), fz_num(b, 0.1, 8));
            break;
    case 3: d = mist_mie_dist_lognormal(fz_num(b, 0.1, 10), fz_num(b, 1.05, 3)); break;
    default: {
        size_t nn = 1 + (sel >> 12) % 8;
        for (i = 0; i < nn; ++i) { r[i] = fz_num(b, 1e-4, rcap); w[i] = fz_num(b, 0.01, 1); }
        d = mist_mie_dist_table(r, w, nn);
        for (i = 0; i < nn; ++i) {
            if (!(r[i] >= MIST_MIE_LEN_MIN && r[i] <= rcap && w[i] >= 0 && fz_fin(w[i])))
                valid = 0;
            if (w[i] > 0) wpos = 1;
        }
        if (valid && (int)(sel >> 15) % 2) for (i = 0; i < nn; ++i) w[i] = 0;   /* sum 0 */
        if (valid && !wpos) wzero = 1;            /* every drawn weight 0: EDOMAIN */
        if (!valid) for (i = 0; i < nn; ++i) if (fz_fin(r[i]) && r[i] > rcap) return;
        break;
    }
    }
    if (d.kind != MIST_MIE_DIST_MONO && d.kind != MIST_MIE_DIST_TABLE) {
        /* explicit range and nodes keep x and the cost bounded */
        d.r_min = fz_num(b, 1e-3, 1);
        d.r_max = d.r_min + fz_num(b, 1e-3, rcap - 1);
        d.n_radii = (int)(mi_take(b, 1) % N_CAP) + 1;
        if (!(d.r_min > 0) && !mi_nan_d(d.r_min)) return;   /* r_min <= 0: not documented */
        if (!(d.p1 > 0 && fz_fin(d.p1) && d.p2 > 0 && fz_fin(d.p2))) valid = 0;
        if (d.kind == MIST_MIE_DIST_MODGAMMA
            && !(d.p3 >= MIST_MIE_LEN_MIN && d.p3 <= MIST_MIE_LEN_MAX)) valid = 0;
        if (d.kind != MIST_MIE_DIST_MODGAMMA
            && !(d.p1 >= MIST_MIE_LEN_MIN && d.p1 <= MIST_MIE_LEN_MAX)) valid = 0;
        if (d.kind == MIST_MIE_DIST_GAMMA && !(d.p2 < 0.5)) valid = 0;
        if (d.kind == MIST_MIE_DIST_LOGNORMAL && !(d.p2 > 1)) valid = 0;
        if (!(d.r_min >= MIST_MIE_LEN_MIN && d.r_max > d.r_min && d.r_max <= rcap)) {
            if (fz_fin(d.r_max) && d.r_max > rcap) return;
            valid = 0;
        }
    } else if (d.kind == MIST_MIE_DIST_MONO
               && !(d.p1 >= MIST_MIE_LEN_MIN && d.p1 <= rcap)) {
        if (fz_fin(d.p1) && d.p1 > rcap) return;
        valid = 0;
    }
    switch (bad) {                     /* documented bad input: one field made bad */
    case 1: n_wl = 0; valid = 0; break;
    case 2: valid = 0; break;          /* NULL wl below */
    case 3: if (n_mu) valid = 0; break;   /* NULL phase below */
    default: break;
    }
    for (j = 0; j < n_mu; ++j) ph[j] = -1;
    a = mist_mie_average(bad == 0 && (sel >> 14) % 8 == 0 ? NULL : &d, bad == 2 ? NULL : wl,
                         n_wl, n_med, mu, n_mu, bad == 3 ? NULL : ph);
    if (bad == 0 && (sel >> 14) % 8 == 0) valid = 0;
    if (valid && d.kind == MIST_MIE_DIST_TABLE && (wzero || (w[0] == 0 && (int)(sel >> 15) % 2)))
        valid = -1;
    if (valid > 0) {
        /* a node of zero weight is skipped: gamma with r_min past its mass may leave
         * none, EDOMAIN then (sw = 0); modified gamma likewise */
        if (a.status == MIST_MIE_EDOMAIN && d.kind != MIST_MIE_DIST_MONO
            && d.kind != MIST_MIE_DIST_TABLE)
            return;
        if (a.status != MIST_MIE_OK
            || !(fz_fin(a.c_ext) && fz_fin(a.c_sca) && fz_fin(a.c_abs) && fz_fin(a.c_back)
                 && fz_fin(a.g) && a.c_ext >= 0 && a.c_sca >= 0 && a.c_abs >= 0 && a.c_back >= 0
                 && fabs(a.g) <= 1 && a.albedo >= 0 && a.albedo <= 1 + 1e-9
                 && a.area > 0 && a.volume > 0 && a.r_min <= a.r_max && a.n_radii > 0))
            mi_fail("mie average(kind %d p %a %a %a, n_wl %u, n_med %a): status %d Ce %a Cs %a "
                    "Ca %a Cb %a g %a albedo %a", d.kind, d.p1, d.p2, d.p3, (unsigned)n_wl,
                    n_med, a.status, a.c_ext, a.c_sca, a.c_abs, a.c_back, a.g, a.albedo);
        for (j = 0; j < n_mu; ++j)
            if (!(fz_fin(ph[j]) && ph[j] >= 0))
                mi_fail("mie average(kind %d p %a %a %a, range %a %a, %d radii, n_wl %u: "
                        "lambda %a weight %a m (%a, %a), n_med %a): Cs %a, phase(mu=%a) = %a",
                        d.kind, d.p1, d.p2, d.p3, d.r_min, d.r_max, d.n_radii, (unsigned)n_wl,
                        wl[0].lambda, wl[0].weight, wl[0].m.re, wl[0].m.im, n_med, a.c_sca,
                        mu[j], ph[j]);
    } else if (valid == 0) {
        if (a.status != MIST_MIE_EDOMAIN || a.c_ext != 0 || a.c_sca != 0 || a.g != 0
            || a.n_radii != 0)
            mi_fail("mie average(kind %d p %a %a %a, bad %u, n_med %a): status %d, want "
                    "EDOMAIN and 0", d.kind, d.p1, d.p2, d.p3, bad, n_med, a.status);
        if (bad != 3)
            for (j = 0; j < n_mu; ++j)
                if (ph[j] != 0) mi_fail("mie average: bad input, phase[%u] = %a", j, ph[j]);
    } else if (a.status != MIST_MIE_EDOMAIN) {
        mi_fail("mie average: table weights all 0, status %d", a.status);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    mi_bytes b;
    mist_mie_complex c = mist_mie_cplx(1.5, 0.25);
    b.p = data; b.n = size; b.i = 0;
    mi_abort_on_fail = fz_abort();
    if (c.re != 1.5 || c.im != 0.25 || !mi_inf_d(mist_mie_conductor().re)
        || mist_mie_conductor().im != 0)
        mi_fail("mie_cplx / mie_conductor");
    while (b.i < b.n) {
        switch (data[b.i++] % 5) {
        case 0: fz_op_sphere(&b); break;
        case 1: fz_op_make(&b); break;
        case 2: fz_op_grid(&b); break;
        case 3: fz_op_water(&b); break;
        default: fz_op_average(&b); break;
        }
    }
    return 0;
}
