// The opt-in Mie header, alone and after mist.h, as C and C++.
#include "mist_mie.h"
#include "mist.h"
#include "mist_mie.h"
int main(void)
{
    mist_mie_sphere s = mist_mie_sphere_new(5.213, mist_mie_cplx(1.55, 0));
    double q = s.q_sca + mist_mie_phase(&s, 0.5) + mist_hg_eval(0.5, 0.5);
    mist_mie_sphere_free(&s);
    return !(q > 0);
}
