/* The cases of fm_cases.h compiled without fast math: the reference. */
#include "mist.h"
#define FM_CAT2(a, b) a##b
#define FM_CAT(a, b) FM_CAT2(a, b)
#define FM_RUN fm_run_ref
int fm_run_ref(const double *v, const float *vf, int n, double *out);
#include "fm_cases.h"
