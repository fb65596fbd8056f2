#!/bin/sh
# run_fuzz.sh SRC WORK HARNESS SECONDS [OPT] - builds fuzz/fuzz_HARNESS.c
# with clang's libFuzzer, AddressSanitizer and UndefinedBehaviorSanitizer at
# the optimisation level OPT (default -O1; ctest passes MIST_FUZZ_OPT) and
# runs it for SECONDS over the kept corpus fuzz/corpus/HARNESS/ (read only:
# new inputs go to WORK/corpus-HARNESS, a crash to WORK/HARNESS-crash-*).
# Exits 77 (ctest: skipped) with a message when no clang with libFuzzer is
# found.  MIST_FUZZ_CC picks the compiler (default: clang).
set -u
src=$1; work=$2; name=$3; secs=$4; opt=${5:--O1}
cc=${MIST_FUZZ_CC:-clang}
mkdir -p "$work/corpus-$name" || exit 1
probe="$work/probe-$name.c"   # one a harness: ctest -j runs them side by side
printf '%s\n' '#include <stddef.h>' '#include <stdint.h>' \
    'int LLVMFuzzerTestOneInput(const uint8_t *d, size_t n);' \
    'int LLVMFuzzerTestOneInput(const uint8_t *d, size_t n) { (void)d; (void)n; return 0; }' \
    > "$probe"
if ! command -v "$cc" >/dev/null 2>&1 ||
   ! "$cc" -fsanitize=fuzzer,address,undefined "$probe" -o "$work/probe-$name" >/dev/null 2>&1
then
    echo "$cc with libFuzzer (-fsanitize=fuzzer,address,undefined) not available: test skipped"
    exit 77
fi
echo "building fuzz_$name with $cc $opt"
"$cc" -std=c99 -g "$opt" -Wall -Wextra -Wpedantic -Werror \
      -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all \
      -I"$src/include" -I"$src/tests" "$src/fuzz/fuzz_$name.c" -o "$work/fuzz_$name" -lm || exit 1
# -error_exitcode: libFuzzer's default, 77, would read as "skipped"
echo "running fuzz_$name for $secs s over $src/fuzz/corpus/$name"
exec "$work/fuzz_$name" -max_total_time="$secs" -error_exitcode=1 -timeout=10 \
     -print_final_stats=1 -artifact_prefix="$work/$name-" \
     "$work/corpus-$name" "$src/fuzz/corpus/$name"
