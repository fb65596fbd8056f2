// The header as C++ (C++98 through C++20) with warnings as errors.
#include "mist.h"
#include "use_all.h"
int main() { return use_all(0.25) != use_all(0.25); }
