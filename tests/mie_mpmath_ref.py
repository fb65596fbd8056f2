#!/usr/bin/env python3
"""Reference values for tests/test_mie.c (test_series_tail): the Lorenz-Mie
series in mpmath, independent of mist_mie.h's algorithm.  a_n, b_n from
[BH83 eq. 4.53] with the Riccati-Bessel functions psi_n, chi_n by their
upward three-term recurrence (unstable past n ~ |z|, so the working
precision is raised by the digits that recurrence loses and checked by
recomputing with 25 digits more), summed to N = x + 4 x^(1/3) + 40 terms
(past every term above 1e-40 of the largest here).  BH83 convention: m = mr +
i mi, mi >= 0.  Prints a C table: x, mr, mi, Q_ext, Q_sca, g, Q_back,
p(1), p(0), p(-1) (per steradian, normalised over the sphere).
Run: python3 tests/mie_mpmath_ref.py   (mpmath; a few minutes).
     python3 tests/mie_mpmath_ref.py near1: test_near_one's table (m close
     to 1: Q_sca, g, Q_back, S1 and S2 at mu = 0.5 and -1; about a minute).
     python3 tests/mie_mpmath_ref.py near1x: test_near_one's second table
     (the same at x |m| >= 1; a few minutes); near1x_ext: Q_ext of its
     absorbing cases."""
import math
import mpmath as mp

def riccati(z, n_max):
    s, c = mp.sin(z), mp.cos(z)
    psi, chi = [c, s], [-s, c]               # n = -1, 0  (chi_n = -z y_n)
    for n in range(1, n_max + 1):
        f = (2 * n - 1) / z
        psi.append(f * psi[-1] - psi[-2])
        chi.append(f * chi[-1] - chi[-2])
    return psi, chi

def series(x, m, n_max):
    z = m * x
    px, cx = riccati(x, n_max)
    pz, _ = riccati(z, n_max)
    a, b = [], []
    for n in range(1, n_max + 1):
        ps, ps1 = px[n + 1], px[n]
        xi, xi1 = px[n + 1] - 1j * cx[n + 1], px[n] - 1j * cx[n]
        qs, qs1 = pz[n + 1], pz[n]
        dps, dxi, dqs = ps1 - n / x * ps, xi1 - n / x * xi, qs1 - n / z * qs
        a.append((m * qs * dps - ps * dqs) / (m * qs * dxi - xi * dqs))
        b.append((qs * dps - m * ps * dqs) / (qs * dxi - m * xi * dqs))
    return a, b

def quantities(x, a, b):
    qe = qs = gq = mp.mpf(0)
    bk = mp.mpc(0)
    n_max = len(a)
    for i in range(n_max):
        n = i + 1
        qe += (2 * n + 1) * mp.re(a[i] + b[i])
        qs += (2 * n + 1) * (abs(a[i]) ** 2 + abs(b[i]) ** 2)
        gq += mp.mpf(2 * n + 1) / (n * (n + 1)) * mp.re(a[i] * mp.conj(b[i]))
        if i + 1 < n_max:
            gq += mp.mpf(n * (n + 2)) / (n + 1) * mp.re(a[i] * mp.conj(a[i + 1])
                                                      + b[i] * mp.conj(b[i + 1]))
        bk += (2 * n + 1) * (-1) ** n * (a[i] - b[i])
    out = [2 / x ** 2 * qe, 2 / x ** 2 * qs, 2 * gq / qs, abs(bk) ** 2 / x ** 2]
    for mu in (1, 0, -1):
        pim, pin = mp.mpf(0), mp.mpf(1)
        s1 = s2 = mp.mpc(0)
        for i in range(n_max):
            n = i + 1
            tau = n * mu * pin - (n + 1) * pim
            c = mp.mpf(2 * n + 1) / (n * (n + 1))
            s1 += c * (a[i] * pin + b[i] * tau)
            s2 += c * (a[i] * tau + b[i] * pin)
            pim, pin = pin, ((2 * n + 1) * mu * pin - (n + 1) * pim) / n
        out.append((abs(s1) ** 2 + abs(s2) ** 2) / (2 * mp.pi * x ** 2 * out[1]))
    return out

def converged(x, mr, mi, n_max, values):
    """values(xx, m, a, b) -> list, at the working precision the series'
    loss needs and again 25 digits higher; the two must agree to 1e-25."""
    lo = min(x, math.hypot(mr, mi) * x)
    loss = sum(2 * math.log10((k + 1.0) / lo) for k in range(1, n_max + 1) if k + 1 > lo)
    dm = abs(complex(mr, mi) - 1)
    res = []
    for extra in (0, 25):
        mp.mp.dps = int(40 + loss + max(0, -math.log10(dm)) + extra)
        xx, m = mp.mpf(x), mp.mpc(mr, mi)
        res.append(values(xx, m, *series(xx, m, n_max)))
    err = max(float(abs(u - v) / abs(v)) for u, v in zip(*res) if v != 0)
    assert err < 1e-25, err
    return res[1]

def reference(x, mr, mi):
    return converged(x, mr, mi, int(x + 4 * x ** (1.0 / 3) + 40),
                     lambda xx, m, a, b: quantities(xx, a, b))

CASES = [  # x, mr, mi (the double nearest each literal)
    (1e-6, 1.33, 0.0), (0.003, 0.75, 0.0), (0.01, 1.5, 0.1), (0.007748, 1000.0, 0.0),
    (0.0119817209456378, 431.86451, 0.1), (0.099, 0.75, 0.0), (0.3, 1.33, 0.0),
    (4.301104666247005, 4.0, 0.0), (0.2328940182647092, 30.0, 0.0),
    (5.212822, 1.55, 0.0), (339.04523060942176, 2.8136189359334152, 1e-4),
    (1000.0, 1.33, 0.01), (10000.0, 1.33, 1e-5),
]
if __name__ == '__main__' and len(__import__('sys').argv) == 1:
    for x, mr, mi in CASES:
        v = reference(x, mr, mi)
        print('    {%s, %s, %s,\n     %s},' % (repr(x), repr(mr), repr(mi),
              ', '.join(mp.nstr(t, 17, min_fixed=1, max_fixed=0) for t in v)), flush=True)

def amplitudes(x, a, b, mu):
    """S1, S2 at mu from the series a, b (BH83 convention)."""
    pim, pin = mp.mpf(0), mp.mpf(1)
    s1 = s2 = mp.mpc(0)
    mu = mp.mpf(mu)
    for i in range(len(a)):
        n = i + 1
        tau = n * mu * pin - (n + 1) * pim
        c = mp.mpf(2 * n + 1) / (n * (n + 1))
        s1 += c * (a[i] * pin + b[i] * tau)
        s2 += c * (a[i] * tau + b[i] * pin)
        pim, pin = pin, ((2 * n + 1) * mu * pin - (n + 1) * pim) / n
    return s1, s2

def reference_near1(x, mr, mi, mus):
    """As reference(), m close to 1: Q_sca, g, Q_back and S1, S2 at mus.
    Summed to x + 8 x^(1/3) + 40 terms: at x = 1e5, m = 1 + 1e-9 the term
    at x + 4 x^(1/3) + 40 is still 2e-9 of S1(-1) (which cancels to 1e-5
    of its terms' moduli); past x + 8 x^(1/3) + 40 below 1e-20 of it."""
    def values(xx, m, a, b):
        q = quantities(xx, a, b)
        v = [q[1], q[2], q[3]]
        for mu in mus:
            s1, s2 = amplitudes(xx, a, b, mu)
            v += [s1.real, s1.imag, s2.real, s2.imag]
        return v
    return converged(x, mr, mi, int(x + 8 * x ** (1.0 / 3) + 40), values)

# m close to 1 (test_mie.c, test_near_one): x, mr, mi; amplitudes at mu =
# 0.5 and -1.  Small x, where m D_n(mx) - D_n(x) cancelled; x from 30 to
# 20000 (the amplitude error there); the dipole limit (x < 1e-8), also
# with m - 1 far below double's range for the efficiencies.
NEAR1 = [
    (0.003, 1.0001, 0.0), (0.01, 1.0001, 0.0), (0.005, 1.001, 0.0),
    (1e-7, 1.0001, 0.0), (2e-8, 1.000001, 1e-6), (0.05, 1.00001, 0.0),
    (0.3, 1.0001, 1e-4), (1.5, 1.0001, 0.0), (30.0, 1.0001, 0.0),
    (8000.0, 1.0001, 0.0),
    (100.0, 1.0001, 0.0), (300.0, 1.0001, 0.0), (1000.0, 1.0001, 0.0),
    (3000.0, 1.0001, 0.0), (20000.0, 1.0001, 0.0), (1000.0, 1.001, 0.0),
    (8000.0, 1.001, 0.0), (8000.0, 1.00001, 0.0), (2000.0, 1.0000001, 0.0),
    (1.5, 1.0000001, 0.0), (30.0, 1.000001, 0.0),
    (1e-9, 1.0001, 0.0), (5e-9, 1.5, 0.1), (3e-10, 1.0, 1e-200),
    (1e-9, 1.0, 1e-300), (2e-9, 1.0000000000000002, 0.0),
]

# m close to 1 at x |m| >= 1 (test_near_one, near1x_ref): the terms n <= |m| x,
# x = 1.5 to 1e5 and m - 1 from 9e-4 down to 1e-12, some with an
# imaginary part, some below 1, two purely imaginary, three with m - 1 far
# below double's range for the efficiencies (Q_sca, Q_back print 0 there;
# g and the amplitudes stay meaningful).
NEAR1X = [
    (1.5, 1.00001, 0.0), (1.5, 1.0000001, 5e-8), (1.5, 1.000000001, 0.0),
    (1.5, 1.000000000001, 1e-12),
    (10.0, 1.00001, 1e-6), (10.0, 1.0000001, 0.0), (10.0, 1.000000001, 3e-10),
    (10.0, 1.000000000001, 0.0), (10.0, 1.0, 1e-10),
    (100.0, 1.00001, 0.0), (100.0, 1.0000001, 1e-8), (100.0, 1.000000001, 0.0),
    (100.0, 1.000000000001, 5e-13),
    (1000.0, 1.00001, 2e-6), (1000.0, 1.0000001, 0.0), (1000.0, 1.000000001, 1e-9),
    (1000.0, 1.000000000001, 0.0), (1000.0, 1.0, 1e-14),
    (8000.0, 1.00001, 1e-7), (8000.0, 1.0000001, 0.0), (8000.0, 1.000000001, 0.0),
    (8000.0, 1.000000000001, 1e-12),
    (10.0, 1.0, 1e-200), (1.5, 1.0, 1e-310), (0.01, 1.0, 1e-200),
    (1.5, 0.99999999, 0.0), (100.0, 0.9999999, 0.0), (8000.0, 0.99999, 1e-6),
    (100000.0, 1.000000001, 0.0), (100000.0, 1.0001, 1e-7), (100000.0, 1.0009, 0.0),
]

def main_near1(cases):
    for x, mr, mi in cases:
        v = reference_near1(x, mr, mi, (0.5, -1))
        print('    {%s, %s, %s,\n     %s},' % (repr(x), repr(mr), repr(mi),
              ',\n     '.join(mp.nstr(t, 20, min_fixed=1, max_fixed=0) for t in v)), flush=True)

def main_near1x_ext():
    """Q_ext of NEAR1X's absorbing cases (x, mr, mi, Q_ext)."""
    for x, mr, mi in NEAR1X:
        if mi == 0 or mi < 1e-100:
            continue
        n_max = int(x + 4 * x ** (1.0 / 3) + 40)
        lo = min(x, math.hypot(mr, mi) * x)
        loss = sum(2 * math.log10((k + 1.0) / lo) for k in range(1, n_max + 1) if k + 1 > lo)
        res = []
        for extra in (0, 25):
            mp.mp.dps = int(40 + loss + max(0, -math.log10(abs(complex(mr, mi) - 1))) + extra)
            xx, m = mp.mpf(x), mp.mpc(mr, mi)
            res.append(quantities(xx, *series(xx, m, n_max))[0])
        assert abs(res[0] - res[1]) < 1e-25 * abs(res[1])
        print('    {%s, %s, %s, %s},' % (repr(x), repr(mr), repr(mi),
              mp.nstr(res[1], 20, min_fixed=1, max_fixed=0)), flush=True)

if __name__ == '__main__' and len(__import__('sys').argv) > 1:
    mode = __import__('sys').argv[1]
    if mode == 'near1x_ext':
        main_near1x_ext()
    else:
        main_near1(NEAR1X if mode == 'near1x' else NEAR1)
