/* size_all.c - a translation unit that uses every public function of
 * mist.h (tests/compile/use_all.h, plus the batch forms, the prepared
 * phase functions and the height fog), compiled as size_one.c. */
#include "mist.h"
#include "use_all.h"
#include <string.h>

double size_all(double x, double *a, float *af, size_t n);
double size_all(double x, double *a, float *af, size_t n)
{
    mist_hfog hf;
    mist_hfogf hff;
    mist_vec3 o = { 0, 0, 0 }, d = { 0, 1, 0 };
    mist_vec3f of = { 0, 0, 0 }, df = { 0, 1, 0 };
    mist_rgb t, l, b;
    mist_rgbf tf, lf, bf;
    mist_phase ph = mist_phase_fog(mist_fog_from_diameter(x));
    mist_phasef phf = mist_phase_fogf(mist_fog_from_diameterf((float)x));
    double s = use_all(x), tr = 0;
    float trf = 0;
    memset(&hf, 0, sizeof hf);
    memset(&hff, 0, sizeof hff);
    mist_hg_eval_n(x, a, a, n);         mist_hg_eval_nf((float)x, af, af, n);
    mist_hg_sample_n(x, a, a, n);       mist_hg_sample_nf((float)x, af, af, n);
    mist_draine_eval_n(x, 2, a, a, n);  mist_draine_eval_nf((float)x, 2, af, af, n);
    mist_draine_sample_n(x, 2, a, a, n); mist_draine_sample_nf((float)x, 2, af, af, n);
    mist_rayleigh_eval_n(a, a, n);      mist_rayleigh_eval_nf(af, af, n);
    mist_rayleigh_sample_n(a, a, n);    mist_rayleigh_sample_nf(af, af, n);
    s += mist_phase_eval(&ph, x) + mist_phase_sample(&ph, x)
       + mist_phase_evalf(&phf, (float)x) + mist_phase_samplef(&phf, (float)x)
       + mist_phase_sample_dir(&ph, d, x, x, &tr).x
       + mist_phase_sample_dirf(&phf, df, (float)x, (float)x, &trf).x;
    mist_hfog_eval(&hf, o, d, x, &t, &l);
    mist_hfog_evalf(&hff, of, df, (float)x, &tf, &lf);
    b = mist_hfog_apply(&hf, o, d, x, t);
    bf = mist_hfog_applyf(&hff, of, df, (float)x, tf);
    mist_hfog_layers_eval(&hf, 1, o, d, x, 8, &t, &l, &b);
    mist_hfog_layers_evalf(&hff, 1, of, df, (float)x, 8, &tf, &lf, &bf);
    s += mist_hfog_column(&hf, 0, x, x) + mist_hfog_columnf(&hff, 0, (float)x, (float)x)
       + mist_hfog_transmittance(&hf, o, d, x).r + mist_hfog_inscatterf(&hff, of, df, (float)x).g
       + mist_segment_linear(1, 2, x, x, x, &tr) + mist_segment_linearf(1, 2, 1, 1, (float)x, &trf)
       + t.r + l.g + b.b + tf.r + lf.g + bf.b + tr + trf;
    return s;
}
