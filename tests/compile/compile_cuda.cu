// The header under nvcc: every function called from device code.
#include "mist.h"
#include "use_all.h"
__global__ void kernel(double *out, int n)
{
    int i = blockIdx.x * blockDim.x + threadIdx.x;
    if (i < n) out[i] = use_all((i + 0.5) / n);
}
int main() { return use_all(0.25) != use_all(0.25); }
