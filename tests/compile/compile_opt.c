/* compile_opt.c - compiled with optimisation (-O2, -O3) and warnings as
 * errors by ctest (compile_opt_*): flow-sensitive warnings appear only
 * there.  A caller of mist_hfog_layers_eval with one constant layer count
 * made gcc 12 -O2 -Wall warn -Wmaybe-uninitialized inside the header
 * (arrays set only where they are read, now initialised); this file is
 * the regression test. */
#include "mist.h"

double compile_opt_layers(const mist_hfog *f, mist_vec3 o, mist_vec3 d);
double compile_opt_layers(const mist_hfog *f, mist_vec3 o, mist_vec3 d)
{
    mist_rgb t, l, b;
    mist_hfog_layers_eval(f, 1, o, d, 1e30, 8, &t, &l, &b);
    return t.r + l.r + b.r;
}

float compile_opt_layersf(const mist_hfogf *f, mist_vec3f o, mist_vec3f d);
float compile_opt_layersf(const mist_hfogf *f, mist_vec3f o, mist_vec3f d)
{
    mist_rgbf t, l, b;
    mist_hfog_layers_evalf(f, 1, o, d, 1e30f, 8, &t, &l, &b);
    return t.r + l.r + b.r;
}
