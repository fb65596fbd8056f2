#!/bin/sh
# variant.sh NAME SRC BIN CC GENERATOR FLAGS STRESS_CALLS EXCLUDE [QUICK [NATIVE]]
# Configures, builds and tests a sub-build of the mist tree SRC in BIN with
# the C compiler CC, CMAKE_C_FLAGS=FLAGS (build type "Variant": no other
# optimisation flags), MIST_ROBUSTNESS=ON (the stress and replay tests) and
# MIST_VARIANTS=OFF, MIST_FUZZ_SECONDS=0 (no recursion, no libFuzzer runs),
# then builds the programs of, and runs, every ctest test of that build
# except those that choose their
# own compiler flags (the compile tests, the consumer test, doc_blocks,
# fastmath_* and mie_fastmath: FLAGS change nothing there) and those whose
# names match the
# regular expression EXCLUDE ("" for none), with
# MIST_STRESS_CALLS=STRESS_CALLS for the stress test and MIST_TEST_QUICK=QUICK
# (default 1: full size) for test_accuracy, test_chi2, test_height_fog and
# test_batch (tests/mist_test.h: their random draws and sample counts /
# QUICK, the fixed edge cases and grids in full), and MIST_TEST_NATIVE=NATIVE (default
# ON: the tests' builds with the benchmark's flags too).  Exits 77 (ctest:
# skipped) with a message when CC cannot build and run a program with FLAGS
# (e.g. no sanitizer runtime).
set -u
name=$1; src=$2; bin=$3; cc=$4; gen=$5; flags=$6; calls=$7; exclude=$8; quick=${9:-1}; native=${10:-ON}
mkdir -p "$bin" || exit 1
probe="$bin/probe.c"
printf '%s\n' '#include <math.h>' '#include <stdio.h>' \
    'int main(void) { volatile double x = 2; printf("%g\n", sqrt(x)); return 0; }' > "$probe"
if ! "$cc" $flags "$probe" -o "$bin/probe" -lm >/dev/null 2>&1 || ! "$bin/probe" >/dev/null 2>&1
then
    echo "variant $name: $cc cannot build and run with '$flags': test skipped"
    exit 77
fi
echo "variant $name: $cc $flags"
t0=$(date +%s)
cmake -S "$src" -B "$bin" -G "$gen" -DCMAKE_C_COMPILER="$cc" -DCMAKE_BUILD_TYPE=Variant \
      -DCMAKE_C_FLAGS="$flags" -DMIST_BUILD_EXAMPLES=OFF -DMIST_ROBUSTNESS=ON \
      -DMIST_VARIANTS=OFF -DMIST_SUBBUILD=ON -DMIST_FUZZ_SECONDS=0 -DMIST_TEST_NATIVE="$native" >"$bin/configure.log" 2>&1 ||
    { cat "$bin/configure.log"; exit 1; }
skip="^(compile_.*|consumer|doc_blocks|fastmath_.*|mie_fastmath)\$"
[ -n "$exclude" ] && skip="$skip|$exclude"
# Only the programs the tests that run call (the build is most of a
# variant's time): every path under BIN in those tests' commands.
targets=$(cd "$bin" && for n in $(ctest -N -E "$skip" | sed -n 's/^ *Test *#[0-9]*: //p'); do
              grep -E "^add_test\((\[=\[)?$n(\]=\])? " CTestTestfile.cmake
          done | grep -o "$bin/[A-Za-z0-9_]*" | sed 's|.*/||' | sort -u)
[ -n "$targets" ] || { echo "variant $name: no test programs found"; exit 1; }
# shellcheck disable=SC2086
cmake --build "$bin" -j 2 --target $targets >"$bin/build.log" 2>&1 ||
    { cat "$bin/build.log"; exit 1; }
t1=$(date +%s)
echo "variant $name: configured and built" $targets "in $((t1 - t0)) s"
cd "$bin" || exit 1
MIST_STRESS_CALLS=$calls MIST_TEST_QUICK=$quick ctest -E "$skip" -j 2 --output-on-failure
rc=$?
echo "variant $name: tests ran in $(($(date +%s) - t1)) s"
exit $rc
