#!/usr/bin/env python3
"""regress.py - writes the regression inputs of the fuzz corpus:
fuzz/corpus/<harness>/regress-<name>, one per failure found (see the
input format at the top of each fuzz/fuzz_<harness>.c).  Each case names
the invariant it broke when it was found; fuzz/replay.c runs them all
(ctest: fuzz_replay_<harness>).  Run from anywhere: python3 fuzz/regress.py
"""
import math
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
RAW = struct.pack('<Q', 14)            # mi_gen recipe 14: the value's raw bits


def d(x):
    return struct.pack('<d', float.fromhex(x) if isinstance(x, str) else x)


def f(x):
    return struct.pack('<f', float.fromhex(x) if isinstance(x, str) else x)


def phase(op, typ, *args):
    """a fuzz_phase record: op, then g, alpha, x, x2 (each: a 64-bit word
    picking the recipe 'raw bits', then a 64-bit word of bits)"""
    enc = d if typ == 'd' else (lambda x: f(x) + bytes(4))
    out = bytes([op << 1 | (typ == 'f')])
    for a in args:
        out += RAW + enc(a)
    return out


HFOG_DEFAULT = dict(base=10.0, density=0.5, H=100.0,
                    rs=(0.01, 0.02, 0.04), re=(0.01, 0.02, 0.04),
                    ms=(0.05, 0.05, 0.05), me=(0.06, 0.06, 0.06),
                    mie=(0.8, 0.5, 20.0, 0.4), sun_dir=(0.6, 0.48, 0.64),
                    sun=(5.0, 5.0, 5.0), ambient=(1.0, 1.0, 1.0), sun_ext=0,
                    origin=(1.0, 10.0, 2.0), dir=(1.0, 0.0, 0.0), length=1000.0,
                    bg=(0.5, 0.5, 0.5), w=0.0)


def hfog(typ, **kw):
    """a direct fuzz_hfog record: every field's bits in struct order"""
    v = dict(HFOG_DEFAULT)
    v.update(kw)
    enc = d if typ == 'd' else f
    out = bytes([2 | (typ == 'f')])
    for x in ([v['base'], v['density'], v['H']] + list(v['rs']) + list(v['re'])
              + list(v['ms']) + list(v['me']) + list(v['mie']) + list(v['sun_dir'])
              + list(v['sun']) + list(v['ambient'])):
        out += enc(x)
    out += bytes([v['sun_ext'] & 0xff])
    for x in list(v['origin']) + list(v['dir']) + [v['length']] + list(v['bg']) + [v['w']]:
        out += enc(x)
    return out


def layers(typ, pieces, *fogs):
    """a direct fuzz_hfog record of mist_hfog_layers_eval: n + 1, pieces + 2,
    then each layer's fields (each a dict for hfog(); the first's ray)"""
    out = bytes([(1 << 2) | 2 | (typ == 'f'), len(fogs) + 1, pieces + 2])
    for kw in fogs:
        out += hfog(typ, **kw)[1:]
    return out


def segment(typ, k0, k1, s0, s1, length):
    """a direct fuzz_hfog record of mist_segment_linear"""
    enc = d if typ == 'd' else f
    return bytes([(2 << 2) | 2 | (typ == 'f')]) + b''.join(enc(x) for x in (k0, k1, s0, s1, length))


def down(w):
    """a unit direction with vertical component w"""
    return (math.sqrt(1 - w * w), w, 0.0)


def sweep(typ, g, alpha, ks):
    """fuzz_phase records of mist_draine_sample at (g, alpha): xi pairs
    (1/2 - s 2^-k, 1/2 - s 2^-(k+1)) on both sides of 1/2 (s = +-1), so that
    whatever the compiler's rounding, some pair straddles a jump"""
    out = b''
    for k in ks:
        for sgn in (1, -1):
            out += phase(6, typ, g, alpha, 0.5 - sgn * 2.0**-k, 0.5 - sgn * 2.0**-(k + 1))
    return out


CASES = {
    'phase': {
        # the same, as sweeps of xi pairs at every scale down to the ulp
        'draine-half-sweep-d': sweep('d', 2.0**-45, 1e20, range(2, 54))
                               + sweep('d', 0.0, math.inf, range(2, 54))
                               + sweep('d', 2.0**-40, 1e14, range(2, 54)),
        'draine-half-sweep-f': sweep('f', 0.0, 1e8, range(2, 25))
                               + sweep('f', 2.0**-23, math.inf, range(2, 25))
                               + sweep('f', 2.0**-20, 1e6, range(2, 25)),
        # after the fix of 87d4f1b, float still: alpha 1e5 .. 3e6, |g| < 2e-6:
        # mist_draine_samplef(0, 2^20, 0x1.fffffep-2) = -0.0208 (F^-1 = -0.00366;
        # -0.00473 one ulp of xi below)
        'draine-half-f2': phase(6, 'f', 0.0, 2.0**20, '0x1.fffffcp-2', '0x1.fffffep-2'),
        'draine-half-sweep-f2': sweep('f', 0.0, 2.0**20, range(2, 25))
                                + sweep('f', 2.0**-27, 3e6, range(2, 25))
                                + sweep('f', -2.0**-24, 3e5, range(2, 25))
                                + sweep('f', 2.0**-22, 1e5, range(2, 25)),
        # mist_draine_sample: small g, huge alpha, xi near 1/2: not monotone,
        # u = 1 where F^-1 = 4.8e-6
        'draine-half-d': phase(6, 'd', 2.0**-45, 1e20, '0x1.ffffffffffdcp-2',
                               '0x1.ffffffffffdc1p-2'),
        # g = 0, alpha = +inf: -0.296 at the xi below 1/2 (F^-1 = -4.8e-6)
        'draine-half-inf-d': phase(6, 'd', 0.0, math.inf, '0x1.fffffffffffffp-2',
                                   0.5 - 2.0**-40),
        # float, g = 0, alpha = 1e8: -0.296 at 0x1.fffffep-2 (F^-1 = -0.0039)
        'draine-half-f': phase(6, 'f', 0.0, 1e8, '0x1.fffffep-2', 0.5 - 2.0**-17),
        # float, |g| -> 1, huge alpha (stress test, 1e9 calls): not monotone,
        # 1 then 1 - 2^-24 (F^-1 = 1 - 2^-25 - 4.5e-11 at both): rounding a
        # root whose error varies in xi across the last rounding boundary
        'draine-near1-f': phase(6, 'f', '0x1.ffea16p-1', 2.0**32, '0x1.2116e4p-1',
                                '0x1.211712p-1'),
        'draine-near1-neg-f': phase(6, 'f', '-0x1.ffea16p-1', '0x1.93e596p+99',
                                    '0x1.bdd228p-2', '0x1.bdd264p-2'),
    },
    'hfog': {
        # column -inf (the exponent's low part (1 - xl) < 0 for |a| >= 2^53)
        'col-neg-inf-d': hfog('d', H=1e-30, origin=(1.0, 10.0, 2.0), dir=down(-1e-12),
                              w=-1e-12, length=1000.0),
        # column NaN: looking down 1e300 through H = 1
        'col-nan-d': hfog('d', H=1.0, origin=(1.0, 11.0, 2.0), dir=down(-0.5), w=-0.5,
                          length=1e300),
        # float column -0.0577: H = 3e-30, heights and the exponent cancel
        'col-neg-f': hfog('f', base='-0x1.54e578p-60', density='0x1.d8b98p+9',
                          H='0x1.365d66p-98', origin=(1.0, '0x1.f3fffep+9', 2.0),
                          dir=(0.0, -1.0, 0.0), w='-0x1.0fd176p+27', length='0x1.f3fffcp+9'),
        # column +inf, true 7.1e27: density * length overflows before the exponential
        'col-overflow-d': hfog('d', base='0x1.4ff3e3a7bbbe8p+4', density='0x1.ffffffffffffep+1023',
                               H='0x1.a9361018c4e55p+13', origin=(1.0, '0x1.0d367087ce97ap+23', 2.0),
                               dir=(0.0, -1.0, 0.0), w='-0x1.ffffffffffffcp-1',
                               length='0x1.ca9cd16ddb5c4p+3'),
        # column 0, true 2.1e47: density * length underflows before the exponential
        'col-underflow-d': hfog('d', base='0x1.cc63464cdab38p+5', density='0x0.0000000000001p-1022',
                                H='0x1.4f905f0927ap-5', origin=(1.0, '0x1.6503da660c46p+4', 2.0),
                                dir=down(float.fromhex('0x1.a23301ad0040cp-201')),
                                w='0x1.a23301ad0040cp-201', length='0x1.29d41a30df3e5p-10'),
        # length +inf, w = 1e-300: H / w overflows, column +inf and T = 0, true 1.8e-18, T = 1
        'col-inf-len-d': hfog('d', H='0x1.93e5939a08ceap+99',
                              origin=(1.0, '0x1.3b8b5b5056e17p+109', 2.0),
                              dir=down(float.fromhex('0x1.56e1fc2f8f359p-997')),
                              w='0x1.56e1fc2f8f359p-997', length=math.inf),
        # H = FLT_MAX taken as +inf (uniform): column 0.70, true 0.276
        'col-hmax-f': hfog('f', base='0x1.097dc4p+3', density='0x1.251f24p-6',
                           H='0x1.fffffep+127', origin=(1.0, '0x1.dc4efap+127', 2.0),
                           dir=down(-0.5), w='-0x1.fffffep-2', length='0x1.38d53cp+5'),
        # in-scattering +inf, bound 152: ambient * sigma_s overflows (sigma_s = 1.8e308)
        'ls-overflow-d': hfog('d', rs=('0x1.ffffffffffffep+1023', 0.02, 0.04),
                              re=(100.0, 0.02, 0.04), ambient=(9.3, 1.0, 1.0),
                              dir=(0.43, 0.72, -0.54), length=200.0),
        # mist_hfog_layers_eval: a layer whose density at the camera overflows
        # (e^710): L = 0 and bound 0, where mist_hfog_eval gives L = 10
        # (opaque, albedo 1, ambient 10)
        'layers-overflow-d': layers('d', 8, dict(base=0.0, density=1.0, H=1.0,
                                                 rs=(0.5, 0.5, 0.5), re=(0.5, 0.5, 0.5),
                                                 ms=(0.0, 0.0, 0.0), me=(0.0, 0.0, 0.0),
                                                 sun=(0.0, 0.0, 0.0), ambient=(10.0, 10.0, 10.0),
                                                 origin=(0.0, -710.0, 0.0), dir=(0.8, -0.6, 0.0),
                                                 length=10.0)),
        # mist_segment_linear: k1 length overflows but k0 length does not: the
        # "unbounded" limit s0/k0 (+inf for k0 = 0) is taken; exact sqrt(pi/2)
        'segment-q-overflow-d': segment('d', 0.0, 1e300, 1.0, 0.0, 1e300),
        'segment-q-overflow2-d': segment('d', '0x1.56e1fc2f8f359p-997', 1e300, 1.0, 1.0, 1e300),
        # length = DBL_MAX taken as +inf: T = 0, L = -inf; exact T = e^-2
        'segment-len-max-d': segment('d', 0.0, '0x0.fffffffffffffp-1022', -112.0, 0.0,
                                     '0x1.fffffffffffffp+1023'),
        # NaN: (length w0) s0 + (length w1) s1 = -inf + inf (exact: -9.5e309, -inf)
        'segment-nan-d': segment('d', 0.0, 0.0, '-0x1.ce5beeea71fdep+8', '0x1.641a732a51c14p+8',
                                 '0x1.ffffffffffffep+1023'),
        # --- found by the stress test (each failed before its fix) ---
        # (a) the direction's normalised y underflows to 0 (a level ray, the
        # documented convention): to infinity, C = +inf and T = 0 (was
        # 0.0032: y taken as +TMIN, a ray going up; H subnormal too)
        'level-underflow-f': hfog('f', base='-0x1.2f7e1p+6', density='0x1.ed6ee4p-8',
                                  H='0x1.fffffcp-127', rs=('0x1.5f56ap-15',) * 3,
                                  re=('0x1.ea1ab6p-15',) * 3, ms=('0x1.10c0cp-15',) * 3,
                                  me=(0.0, 0.0, 0.0), origin=(1.0, '-0x1.2f7e1p+6', 2.0),
                                  dir=('-0x1.fffffcp+127', '0x1p-149', '0x1.000002p+1'),
                                  length=math.inf),
        # (b) the same with a density far below the range at the camera
        # (e^-790): any positive density over an infinite level path, T = 0
        # (was 1)
        'level-underflow-thin-f': hfog('f', base='0x1.0e88dep+6', density='0x1.7d669p-6',
                                       H='0x1.d0a43ep-2', origin=(1.0, '0x1.a9345cp+8', 2.0),
                                       dir=('-0x1.c1b0cap+122', '0x1.0c90cp-40', '-0x1.bfbe24p-116'),
                                       length=math.inf),
        'level-underflow-thin-d': hfog('d', base=0.0, density=1.0, H=1.0,
                                       origin=(0.0, 800.0, 0.0),
                                       dir=(-0.5, '0x0.0000000000001p-1022', -2.0),
                                       length=math.inf),
        # a subnormal extinction through a column beyond the range (density
        # DBL_MAX): T = 1 - 4e-15 (was 0: the column alone overflowed)
        'col-overflow-tiny-ext-d': hfog('d', base='0x1.fa7118f215868p+4',
                                        density='0x1.fffffffffffffp+1023', H='0x1.659cb120c4132p+14',
                                        rs=(0.0, 0.0, '0x0.0000000000001p-1022'),
                                        re=(0.0, 0.0, '0x0.0000000000001p-1022'),
                                        ms=(0.0, 0.0, 0.0), me=(0.0, 0.0, 0.0), sun_ext=1,
                                        origin=(1.0, '0x1.dbbc5cff2b657p-920', 2.0),
                                        dir=('0x1.1fc5ddec79e58p-1011', '-0x1.dcde6e3d17218p-1011',
                                             '-0x1.ada39852b1513p-1010'),
                                        length='0x1.2b94b8f74f39cp+2'),
        # float: T = 0.27 (was 0), the column e^155 over float's range
        'col-overflow-tiny-ext-f': hfog('f', base='0x1.0fa74ap+6', density='0x1.a2f5bp-8',
                                        H='0x1.baf17p-2', rs=(0.0, '0x1p-149', 0.0),
                                        re=(0.0, 0.0, 0.0), ms=(0.0, 0.0, 0.0), me=(0.0, 0.0, 0.0),
                                        sun_ext=1, origin=(1.0, '0x1.de6e9ap-7', 2.0),
                                        dir=('-0x1.34c6bcp-1', '0x1p-11', '0x1.9869b6p-1'),
                                        length='0x1.292c1p-70'),
        # the extinction R + M beyond the range (2 DBL_MAX, albedo 1), the
        # sun straight ahead (u = 1): the albedos sR/st + sM/st were 2 (the
        # sum clamped, not the scatterings), L above E max p (1 - T)
        'ext-sum-overflow-d': hfog('d', rs=('0x1.ffffffffffffep+1023',) * 3,
                                   re=(825.0, 825.0, 825.0),
                                   ms=('0x1.ffffffffffffep+1023',) * 3,
                                   me=(787.0, 787.0, 787.0), ambient=(0.0, 0.0, 0.0),
                                   dir=(0.6, 0.48, 0.64), length=1000.0),
        # (d) scale heights: subnormal (the exponent's low part is divided
        # by it: now scaled first) and the largest finite value, each on a
        # ray up, down and level, finite and infinite (edge coverage: these
        # passed before too; the failures with such H were (a)'s)
        'h-subnormal-d': b''.join(hfog('d', H='0x0.0000000000001p-1022', base=0.0,
                                       origin=(0.0, y, 0.0), dir=dv, length=ln)
                                  for y in (0.0, '0x0.0000000000003p-1022', '-0x0.0000000000002p-1022')
                                  for dv in (down(0.5), down(-0.5), (1.0, 0.0, 0.0))
                                  for ln in (1.0, math.inf)),
        'h-subnormal-f': b''.join(hfog('f', H='0x1p-149', base=0.0, origin=(0.0, y, 0.0),
                                       dir=dv, length=ln)
                                  for y in (0.0, '0x1.8p-148', '-0x1p-148')
                                  for dv in (down(0.5), down(-0.5), (1.0, 0.0, 0.0))
                                  for ln in (1.0, math.inf)),
        'h-max-d': b''.join(hfog('d', H='0x1.fffffffffffffp+1023', base=0.0,
                                 origin=(0.0, y, 0.0), dir=dv, length=ln)
                            for y in (0.0, 1e308, -1e308)
                            for dv in (down(0.5), down(-0.5), (1.0, 0.0, 0.0))
                            for ln in (1.0, 1e308, math.inf)),
        'h-max-f': b''.join(hfog('f', H='0x1.fffffep+127', base=0.0, origin=(0.0, y, 0.0),
                                 dir=dv, length=ln)
                            for y in (0.0, 3e38, -3e38)
                            for dv in (down(0.5), down(-0.5), (1.0, 0.0, 0.0))
                            for ln in (1.0, 3e38, math.inf)),
        # a ray down from DBL_MAX to 0 (w len = -DBL_MAX): Dekker's split of
        # w len overflowed, the low part (which held the whole exponent
        # -2.6e169) became NaN and was dropped: column 7e4 for +inf
        'col-dekker-overflow-d': hfog('d', base='0x1.a29bb1f8316d3p+570',
                                      density='0x1.9d0f8e72afb1ap+9', H='0x1.54p+6',
                                      origin=(1.0, '0x1.ffffffffffffep+1023', 2.0),
                                      dir=(0.0, -1.0, 0.0), w=-1.0,
                                      length='0x1.ffffffffffffep+1023'),
        # mist_hfog_layers_eval, a fog at extinction 1e295 split into its
        # Rayleigh and Mie layers (the exact case): the shares came from
        # logs, 250 eps off, outside the bound (now: scaled optical depths)
        'layers-log-weights-d': layers('d', -1, dict(
            base='-0x1.f7ddfdea61eecp+5', density='0x1.2f9888d6fda8bp+1',
            H='0x1.b4fbc70644551p+15', rs=('0x1.0670137110671p-8', 0.02, 0.04),
            re=('0x1.9a4e8060ff8cfp-8', 0.02, 0.04), ms=('0x1.93e30f0c78488p-100', 0.05, 0.05),
            me=('0x1.2ee394251b524p+981', 0.06, 0.06), sun=('0x1.d4faa8843df04p+2', 5.0, 5.0),
            ambient=('0x1.5a86c0e35e368p+1', 1.0, 1.0), sun_ext=1,
            sun_dir=(0.0, '0x1.76d8daf5c7473p-1', 0.6), origin=(0.0, '-0x1.5298cc2fa7a6dp+25', 0.0),
            dir=('-0x1.74d2e15ee2cd5p+449', '0x1.a00568740f026p+450', '0x1.d22331793e2b4p+449'),
            length='0x1.694bd6d6a0787p-4')),
        # in-scattering NaN: sigma_t subnormal (1 / sigma_t overflows), ambient 0
        'ls-nan-f': hfog('f', base='-0x1.b73738p+3', density='0x1.b36446p-5', H='0x1.dcdcdcp+93',
                         rs=('0x1.fedcp-134', 0.0, 0.0), re=('0x1.fedcp-134', 0.0, 0.0),
                         ms=(0.0, 0.0, 0.0), me=(0.0, 0.0, 0.0), sun_dir=(-1.0, 0.0, 0.0),
                         sun=(0.1, 0.1, 0.1), ambient=(0.0, 0.0, 0.0),
                         origin=(0.0, '-0x1.2a0a0ap+97', 0.0), dir=(-1.0, 0.0, 0.0),
                         length=math.inf),
    },
}

for harness, cases in CASES.items():
    os.makedirs(os.path.join(HERE, 'corpus', harness), exist_ok=True)
    for name, data in cases.items():
        with open(os.path.join(HERE, 'corpus', harness, 'regress-' + name), 'wb') as fh:
            fh.write(data)
        print('fuzz/corpus/%s/regress-%s: %d bytes' % (harness, name, len(data)))
