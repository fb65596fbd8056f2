/* use_all.h - calls every public function once, so that a compile test
 * type-checks the whole header (included by the C, C++ and CUDA tests). */
#ifndef USE_ALL_H
#define USE_ALL_H
#include "mist.h"

MIST_FUNC double use_all(double x)
{
    mist_vec3 wi, wo;
    mist_vec3f wif, wof;
    mist_fog fog = mist_fog_make(0.9, 0.5, 250.0, 0.3);
    mist_fogf fogf = mist_fog_makef(0.9f, 0.5f, 250.0f, 0.3f);
    double pdf = 0, s = 0;
    float pdff = 0, sf = 0, xf = (float)x;
    wi.x = 0; wi.y = 0; wi.z = 1;
    wif.x = 0; wif.y = 0; wif.z = 1;
    s += mist_hg_eval(0.5, x) + mist_hg_sample(0.5, x);
    s += mist_cs_eval(0.5, x) + mist_cs_sample(0.5, x);
    s += mist_draine_eval(0.5, 2.0, x) + mist_draine_sample(0.5, 2.0, x);
    s += mist_rayleigh_eval(x) + mist_rayleigh_sample(x);
    s += mist_fog_eval(fog, x) + mist_fog_sample(fog, x);
    s += mist_fog_from_diameter_mie(x).g_hg;
    sf += mist_hg_evalf(0.5f, xf) + mist_hg_samplef(0.5f, xf);
    sf += mist_cs_evalf(0.5f, xf) + mist_cs_samplef(0.5f, xf);
    sf += mist_draine_evalf(0.5f, 2.0f, xf) + mist_draine_samplef(0.5f, 2.0f, xf);
    sf += mist_rayleigh_evalf(xf) + mist_rayleigh_samplef(xf);
    sf += mist_fog_evalf(fogf, xf) + mist_fog_samplef(fogf, xf);
    sf += mist_fog_from_diameter_mief(xf).g_hg;
    wo = mist_hg_sample_dir(0.5, wi, x, x, &pdf); s += wo.x + pdf;
    wo = mist_cs_sample_dir(0.5, wi, x, x, &pdf); s += wo.y + pdf;
    wo = mist_draine_sample_dir(0.5, 2.0, wi, x, x, &pdf); s += wo.z + pdf;
    wo = mist_rayleigh_sample_dir(wi, x, x, &pdf); s += wo.x + pdf;
    wo = mist_fog_sample_dir(fog, wi, x, x, &pdf); s += wo.x + pdf;
    wo = mist_dir_from_cos(mist_normalize(wi), x, x); s += wo.x;
    wof = mist_hg_sample_dirf(0.5f, wif, xf, xf, &pdff); sf += wof.x + pdff;
    wof = mist_cs_sample_dirf(0.5f, wif, xf, xf, &pdff); sf += wof.y + pdff;
    wof = mist_draine_sample_dirf(0.5f, 2.0f, wif, xf, xf, &pdff); sf += wof.z + pdff;
    wof = mist_rayleigh_sample_dirf(wif, xf, xf, &pdff); sf += wof.x + pdff;
    wof = mist_fog_sample_dirf(fogf, wif, xf, xf, &pdff); sf += wof.x + pdff;
    wof = mist_dir_from_cosf(mist_normalizef(wif), xf, xf); sf += wof.x;
    {   /* the prepared phase functions */
        mist_phase ph[5];
        mist_phasef phf[5];
        int k;
        ph[0] = mist_phase_hg(0.5); ph[1] = mist_phase_draine(0.5, 2.0);
        ph[2] = mist_phase_cs(0.5); ph[3] = mist_phase_rayleigh(); ph[4] = mist_phase_fog(fog);
        phf[0] = mist_phase_hgf(0.5f); phf[1] = mist_phase_drainef(0.5f, 2.0f);
        phf[2] = mist_phase_csf(0.5f); phf[3] = mist_phase_rayleighf();
        phf[4] = mist_phase_fogf(fogf);
        for (k = 0; k < 5; ++k) {
            s += mist_phase_eval(&ph[k], x) + mist_phase_sample(&ph[k], x);
            wo = mist_phase_sample_dir(&ph[k], wi, x, x, &pdf); s += wo.x + pdf;
            sf += mist_phase_evalf(&phf[k], xf) + mist_phase_samplef(&phf[k], xf);
            wof = mist_phase_sample_dirf(&phf[k], wif, xf, xf, &pdff); sf += wof.x + pdff;
        }
    }
    {   /* the compact prepared phase functions */
        mist_phasec pc[2];
        mist_phasecf pcf[2];
        int k;
        pc[0] = mist_phasec_fog(fog); pc[1] = mist_phasec_draine(0.5, 2.0);
        pcf[0] = mist_phasec_fogf(fogf); pcf[1] = mist_phasec_drainef(0.5f, 2.0f);
        for (k = 0; k < 2; ++k) {
            s += mist_phasec_eval(&pc[k], x) + mist_phasec_sample(&pc[k], x);
            wo = mist_phasec_sample_dir(&pc[k], wi, x, x, &pdf); s += wo.x + pdf;
            sf += mist_phasec_evalf(&pcf[k], xf) + mist_phasec_samplef(&pcf[k], xf);
            wof = mist_phasec_sample_dirf(&pcf[k], wif, xf, xf, &pdff); sf += wof.x + pdff;
        }
    }
    {   /* the batch forms, in place */
        double a[3];
        float af[3];
        a[0] = a[1] = a[2] = x;
        af[0] = af[1] = af[2] = xf;
        mist_hg_eval_n(0.5, a, a, 3);              mist_hg_eval_nf(0.5f, af, af, 3);
        mist_hg_sample_n(0.5, a, a, 3);            mist_hg_sample_nf(0.5f, af, af, 3);
        mist_draine_eval_n(0.5, 2.0, a, a, 3);     mist_draine_eval_nf(0.5f, 2.0f, af, af, 3);
        mist_draine_sample_n(0.5, 2.0, a, a, 3);   mist_draine_sample_nf(0.5f, 2.0f, af, af, 3);
        mist_rayleigh_eval_n(a, a, 3);             mist_rayleigh_eval_nf(af, af, 3);
        mist_rayleigh_sample_n(a, a, 3);           mist_rayleigh_sample_nf(af, af, 3);
        mist_fog_eval_n(fog, a, a, 3);             mist_fog_eval_nf(fogf, af, af, 3);
        mist_fog_sample_n(fog, a, a, 3);           mist_fog_sample_nf(fogf, af, af, 3);
        s += a[1];
        sf += af[1];
    }
    {   /* the tabulated phase functions, in a local buffer */
        double mem[64], mu[2], p[2], ch[1], a[2];
        float memf[128], muf[2], pf[2], chf[1], af[2];
        mist_tab *t = (mist_tab *)(void *)mem;
        mist_tabf *tf = (mist_tabf *)(void *)memf;
        mu[0] = -1; mu[1] = 1; p[0] = 1; p[1] = x * x;
        muf[0] = -1; muf[1] = 1; pf[0] = 1; pf[1] = xf * xf;
        s += (double)mist_tab_bytes(2, 1) + (double)mist_tab_bytesf(2, 1);
        s += mist_tab_init(t, sizeof mem, mu, p, 2, 1);
        s += mist_tab_initf(tf, sizeof memf, muf, pf, 2, 1);
        s += mist_tab_eval(t, x, ch) + ch[0] + mist_tab_sample(t, x);
        sf += mist_tab_evalf(tf, xf, chf) + chf[0] + mist_tab_samplef(tf, xf);
        wo = mist_tab_sample_dir(t, wi, x, x, &pdf); s += wo.x + pdf;
        wof = mist_tab_sample_dirf(tf, wif, xf, xf, &pdff); sf += wof.x + pdff;
        a[0] = a[1] = x;
        af[0] = af[1] = xf;
        mist_tab_eval_n(t, a, a, 2);               mist_tab_eval_nf(tf, af, af, 2);
        mist_tab_sample_n(t, a, a, 2);             mist_tab_sample_nf(tf, af, af, 2);
        s += a[1];
        sf += af[1];
    }
    {   /* the analytic height fog */
        mist_hfog hf[2];
        mist_hfogf hff[2];
        mist_vec3 o;
        mist_vec3f of;
        mist_rgb t, l, b;
        mist_rgbf tf, lf, bf;
        double tr = 0;
        float trf = 0;
        int k;
        o.x = 0; o.y = x; o.z = 0;
        of.x = 0; of.y = xf; of.z = 0;
        for (k = 0; k < 2; ++k) {
            memset(&hf[k], 0, sizeof hf[k]);     /* up, mie_prepared, mie_tab: none */
            memset(&hff[k], 0, sizeof hff[k]);
            hf[k].base = 0; hf[k].density = 1; hf[k].scale_height = 1000.0 * (k + 1);
            hf[k].rayleigh_scat.r = hf[k].rayleigh_scat.g = hf[k].rayleigh_scat.b = 1e-5;
            hf[k].rayleigh_ext = hf[k].rayleigh_scat;
            hf[k].mie_scat = hf[k].rayleigh_scat; hf[k].mie_ext = hf[k].rayleigh_scat;
            hf[k].mie_phase = fog; hf[k].sun_dir = wi;
            hf[k].sun.r = hf[k].sun.g = hf[k].sun.b = 1;
            hf[k].ambient = hf[k].sun; hf[k].sun_extinction = k;
            hff[k].base = 0; hff[k].density = 1; hff[k].scale_height = 1000.0f * (float)(k + 1);
            hff[k].rayleigh_scat.r = hff[k].rayleigh_scat.g = hff[k].rayleigh_scat.b = 1e-5f;
            hff[k].rayleigh_ext = hff[k].rayleigh_scat;
            hff[k].mie_scat = hff[k].rayleigh_scat; hff[k].mie_ext = hff[k].rayleigh_scat;
            hff[k].mie_phase = fogf; hff[k].sun_dir = wif;
            hff[k].sun.r = hff[k].sun.g = hff[k].sun.b = 1;
            hff[k].ambient = hff[k].sun; hff[k].sun_extinction = k;
        }
        s += mist_hfog_column(&hf[0], x, 0.5, 100.0);
        mist_hfog_eval(&hf[0], o, wi, 100.0, &t, &l); s += t.r + l.g;
        s += mist_hfog_transmittance(&hf[0], o, wi, 100.0).b;
        s += mist_hfog_inscatter(&hf[0], o, wi, 100.0).r;
        s += mist_hfog_apply(&hf[0], o, wi, 100.0, t).g;
        mist_hfog_layers_eval(hf, 2, o, wi, 100.0, 4, &t, &l, &b); s += t.r + l.r + b.r;
        s += mist_hfog_extinction(&hf[0], o).g;
        s += mist_hfog_optical_depth(&hf[0], o, wi, 100.0).r;
        s += mist_hfog_sample_distance(&hf[0], o, wi, 100.0, 1, 0.5);
        s += mist_segment_linear(0.1, 0.2, 1.0, 2.0, x, &tr) + tr;
        sf += mist_hfog_columnf(&hff[0], xf, 0.5f, 100.0f);
        mist_hfog_evalf(&hff[0], of, wif, 100.0f, &tf, &lf); sf += tf.r + lf.g;
        sf += mist_hfog_transmittancef(&hff[0], of, wif, 100.0f).b;
        sf += mist_hfog_inscatterf(&hff[0], of, wif, 100.0f).r;
        sf += mist_hfog_applyf(&hff[0], of, wif, 100.0f, tf).g;
        mist_hfog_layers_evalf(hff, 2, of, wif, 100.0f, 4, &tf, &lf, &bf); sf += tf.r + lf.r + bf.r;
        {   /* the batch form, in place */
            double len = 100.0;
            float lenf = 100.0f;
            mist_hfog_apply_n(&hf[0], &o, &wi, &len, &t, &t, 1); s += t.r;
            mist_hfog_apply_nf(&hff[0], &of, &wif, &lenf, &tf, &tf, 1); sf += tf.r;
        }
        sf += mist_hfog_extinctionf(&hff[0], of).g;
        sf += mist_hfog_optical_depthf(&hff[0], of, wif, 100.0f).r;
        sf += mist_hfog_sample_distancef(&hff[0], of, wif, 100.0f, 1, 0.5f);
        sf += mist_segment_linearf(0.1f, 0.2f, 1.0f, 2.0f, xf, &trf) + trf;
    }
    return s + (double)sf;
}
#endif
