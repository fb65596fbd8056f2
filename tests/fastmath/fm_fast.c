/* The cases of fm_cases.h compiled with the includer's flags (fast math). */
#include "mist.h"
#define FM_CAT2(a, b) a##b
#define FM_CAT(a, b) FM_CAT2(a, b)
#define FM_RUN fm_run_fast
int fm_run_fast(const double *v, const float *vf, int n, double *out);
#include "fm_cases.h"
