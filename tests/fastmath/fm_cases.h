/* The height fog's bad-input cases, run by a translation unit that defines
 * FM_RUN (its name) and FM_CAT (token pasting) before including this file
 * after mist.h.  tests/fastmath/fm_main.c builds it twice: with the
 * includer's fast-math flags (fm_fast.c) and without (fm_ref.c), and
 * compares.  The special values come in through v[] from the precise
 * main (v[] and the same in float, vf[]: a double beyond float's range
 * converted is undefined), so that no fast-math code of the includer
 * computes with them. */
#ifndef FM_NV
#define FM_NV 10      /* v[]: inf, -inf, NaN, 0, -1, largest, subnormal, 1e-3, 7, 1e300 */
#define FM_PER 21     /* results per case */
#define FM_NCASE 640  /* at most */
#endif

static mist_hfog FM_CAT(fm_fog_, FM_RUN)(void)
{
    mist_hfog f;
    memset(&f, 0, sizeof f);
    f.base = 10; f.density = 1.5; f.scale_height = 800;
    f.rayleigh_scat.r = 0.01; f.rayleigh_scat.g = 0.02; f.rayleigh_scat.b = 0.03;
    f.rayleigh_ext = f.rayleigh_scat;
    f.mie_scat.r = f.mie_scat.g = f.mie_scat.b = 0.02;
    f.mie_ext.r = f.mie_ext.g = f.mie_ext.b = 0.025;
    f.mie_phase = mist_fog_make(0.7, 0.5, 10, 0.3);
    f.sun_dir.x = 0.6; f.sun_dir.y = 0.8; f.sun_dir.z = 0;
    f.sun.r = f.sun.g = f.sun.b = 3;
    f.ambient.r = f.ambient.g = f.ambient.b = 0.5;
    return f;
}

/* case n (0 <= n < FM_NCASE): one field of a good fog, ray or step set to
 * v[j]; out[0..FM_PER): T, L of mist_hfog_eval, T, L, bound of
 * mist_hfog_layers_eval (the fog and a second layer), the step's value and
 * transmittance.  Returns 0 past the last case. */
int FM_RUN(const double *v, const float *vf, int n, double *out)
{
    mist_hfog f = FM_CAT(fm_fog_, FM_RUN)(), ly[2];
    mist_vec3 o, d;
    mist_rgb t, l, b;
    double a[5] = { 0.3, 0.9, 2, 1, 40 }, x, tr;
    float xf = vf[n % FM_NV];
    int field = n / FM_NV, j = n % FM_NV, i;
    o.x = 0; o.y = 50; o.z = 0;
    d.x = 0.8; d.y = 0.6; d.z = 0;
    x = v[j];
    switch (field) {
    case 0: f.density = x; break;
    case 1: f.scale_height = x; break;
    case 2: f.base = x; break;
    case 3: f.rayleigh_scat.r = x; break;
    case 4: f.rayleigh_ext.g = x; break;
    case 5: f.mie_scat.b = x; break;
    case 6: f.mie_ext.r = x; break;
    case 7: f.sun.g = x; break;
    case 8: f.ambient.b = x; break;
    case 9: f.sun_dir.y = x; break;
    case 10: f.sun_dir.x = x; break;
    case 11: o.y = x; break;
    case 12: d.y = x; break;
    case 13: d.x = x; break;
    case 14: f.mie_phase = mist_fog_make(x, 0, 0, 0); break;   /* g (+-1: Dirac) */
    case 15: f.sun_extinction = 1; f.sun.r = x; break;
    case 16: f.sun_extinction = 1; f.mie_ext.g = x; break;
    case 17: f.sun_extinction = 1; f.mie_scat.b = x; f.mie_ext.b = x; break;
    case 18: f.sun_extinction = 1; f.density = x; break;
    case 19: case 20: case 21: case 22: case 23: break;      /* the step's arguments */
    case 24: case 25: case 26: f.mie_phase = mist_fog_make(1, 0, 0, 0);
        f.sun_dir = d; f.sun_extinction = field - 24 == 2;       /* a Dirac lobe on its peak */
        f.sun.r = field == 24 ? x : 1;
        if (field == 25) f.mie_scat.r = f.mie_ext.r = x;
        break;
    default: return 0;
    }
    if (field >= 19 && field <= 23) a[field - 19] = x;
    for (i = 0; i < FM_PER; ++i) out[i] = 0;
    mist_hfog_eval(&f, o, d, field == 11 ? 300 : (field >= 19 ? 1e300 : 300), &t, &l);
    out[0] = t.r; out[1] = t.g; out[2] = t.b; out[3] = l.r; out[4] = l.g; out[5] = l.b;
    ly[0] = f; ly[1] = FM_CAT(fm_fog_, FM_RUN)(); ly[1].scale_height = 150; ly[1].base = -20;
    mist_hfog_layers_eval(ly, 2, o, d, 300, 4, &t, &l, &b);
    out[6] = t.r; out[7] = t.g; out[8] = t.b; out[9] = l.r; out[10] = l.g; out[11] = l.b;
    out[12] = b.r; out[13] = b.g; out[14] = b.b;
    out[15] = mist_segment_linear(a[0], a[1], a[2], a[3], a[4], &tr);
    out[16] = tr;
    /* the header's own example, and the step with a long, dense medium */
    out[17] = mist_segment_linear(2, 2, x, 0, 1, &tr);
    out[18] = mist_segment_linear(1e300, 1, 1, x, 1, &tr);
    out[19] = (double)mist_segment_linearf(2, 2, (float)x, 0, 1, (float *)0);
    {
        mist_hfogf ff;
        mist_vec3f of, df;
        mist_rgbf tf, lf;
        memset(&ff, 0, sizeof ff);
        ff.density = 1; ff.scale_height = 100;
        ff.mie_scat.r = ff.mie_ext.r = 0.01f;
        ff.rayleigh_scat.r = ff.rayleigh_ext.r = xf;
        ff.mie_phase = mist_fog_makef(0.5f, 0, 0, 0);
        ff.sun_dir.y = 1; ff.sun.r = 1; ff.ambient.r = xf;
        of.x = of.y = of.z = 0; df.x = 0.6f; df.y = 0.8f; df.z = 0;
        mist_hfog_evalf(&ff, of, df, 50, &tf, &lf);
        out[20] = (double)lf.r;
    }
    return 1;
}
