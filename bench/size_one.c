/* size_one.c - a translation unit that uses one mist function
 * (mist_hg_evalf): what a renderer pays for HG alone.  Compiled by CMake
 * at the benchmark's flags; mist_bench reports its object-code size beside
 * size_all.c's. */
#include "mist.h"

float size_one(float g, float u);
float size_one(float g, float u) { return mist_hg_evalf(g, u); }
