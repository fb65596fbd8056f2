/* A renderer's view of mist: include the header, link nothing but libm. */
#include <mist.h>
#include <stdio.h>
int main(void)
{
    double u = mist_hg_sample(0.8, 0.5);
    printf("mist %s: u = %f, p = %f\n", MIST_VERSION_STRING, u, mist_hg_eval(0.8, u));
    return !(u > -1 && u < 1);
}
