/* The height fog under the includer's fast-math flags (tests/fastmath/
 * run.sh builds fm_fast.c with them, fm_ref.c and this file without):
 * every bad-input case of fm_cases.h must give what the precise build
 * gives.  Compared here, in precise code: no NaN where the precise build
 * has none, +-inf where it has +-inf, else within 2^-40 relative (double)
 * or 2^-17 (the float result: clang 14 keeps the includer's flags on libm
 * calls, so a float sqrt may come from the reciprocal estimate, 3.3 ulp,
 * through a few operations: 2^-17 = 128 ulp leaves room; double's libm
 * calls are the same functions, the bar covers a last-bit difference
 * through the closed forms' ~10 roundings times tau <= ~30 here). */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <float.h>

#define FM_NV 10
#define FM_PER 21
#define FM_NCASE 640
int fm_run_fast(const double *v, const float *vf, int n, double *out);
int fm_run_ref(const double *v, const float *vf, int n, double *out);

int main(void)
{
    volatile double inf = INFINITY, zero = 0;
    double v[FM_NV], a[FM_PER], r[FM_PER];
    float vf[FM_NV];
    int n, i, bad = 0, cases = 0;
    v[0] = inf; v[1] = -inf; v[2] = zero / zero; v[3] = 0; v[4] = -1; v[5] = DBL_MAX;
    v[6] = 4.9e-324; v[7] = 1e-3; v[8] = 7; v[9] = 1e300;
    for (i = 0; i < FM_NV; ++i)      /* the same in float (beyond its range: +-inf) */
        vf[i] = v[i] > FLT_MAX ? (float)inf : (v[i] < -FLT_MAX ? -(float)inf : (float)v[i]);
    vf[6] = 1e-45f;
    for (n = 0; n < FM_NCASE; ++n) {
        if (!fm_run_ref(v, vf, n, r)) break;
        fm_run_fast(v, vf, n, a);
        ++cases;
        for (i = 0; i < FM_PER; ++i) {
            double tol = i == 20 ? 0x1p-17 : 0x1p-40;
            int ok;
            if (r[i] != r[i]) ok = 0;                          /* the reference: never NaN */
            else if (r[i] == inf || r[i] == -inf) ok = a[i] == r[i];
            else ok = a[i] == a[i] && fabs(a[i] - r[i]) <= tol * fabs(r[i]);
            if (!ok && ++bad <= 20)
                printf("FAIL: case %d (field %d, value %g) result %d: fast %.17g, precise %.17g\n",
                       n, n / FM_NV, v[n % FM_NV], i, a[i], r[i]);
        }
    }
    printf("fastmath: %d cases x %d results, %d differ\n", cases, FM_PER, bad);
    return bad ? 1 : 0;
}
