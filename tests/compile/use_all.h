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
    sf += mist_hg_evalf(0.5f, xf) + mist_hg_samplef(0.5f, xf);
    sf += mist_cs_evalf(0.5f, xf) + mist_cs_samplef(0.5f, xf);
    sf += mist_draine_evalf(0.5f, 2.0f, xf) + mist_draine_samplef(0.5f, 2.0f, xf);
    sf += mist_rayleigh_evalf(xf) + mist_rayleigh_samplef(xf);
    sf += mist_fog_evalf(fogf, xf) + mist_fog_samplef(fogf, xf);
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
    return s + sf;
}
#endif
