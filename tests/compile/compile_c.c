/* The header as C (C99, C11, C17) with warnings as errors; mist.h is
 * included twice to check its include guard. */
#include "mist.h"
#include "mist.h"
#include "use_all.h"
int main(void) { return use_all(0.25) != use_all(0.25); }
