#!/bin/sh
# x87_check.sh INCLUDE_DIR COMPILE_DIR OUT -- the EXCESS PRECISION guard of
# mist.h: a 32-bit x86 build with x87 math (gcc -m32: FLT_EVAL_METHOD 2)
# must stop with its error; with MIST_ALLOW_EXCESS_PRECISION, or with SSE
# math (-msse2 -mfpmath=sse: FLT_EVAL_METHOD 0), it must compile.  Exits 77
# (ctest: skipped) where gcc cannot build 32-bit code against the C
# library headers mist.h includes (no multilib: gcc's own <float.h> alone
# compiles with only libc6-i386 installed, <math.h> then does not).
inc=$1; dir=$2; out=$3
printf '%s\n' '#include <math.h>' '#include <float.h>' '#include <stddef.h>' \
    '#include <stdint.h>' '#include <string.h>' \
    'int main(void) { return FLT_EVAL_METHOD != 2 || sqrt(4.0) != 2.0; }' > "$out.probe.c"
if ! gcc -m32 -c "$out.probe.c" -o "$out.probe.o" >/dev/null 2>&1; then
    echo "gcc -m32 cannot build against the C headers (no libc6-dev-i386): test skipped"
    exit 77
fi
w="-std=c99 -Wall -Wextra -Wpedantic -Werror -I$inc -I$dir -c $dir/compile_c.c -o $out.o"
if gcc -m32 $w 2>"$out.err"; then
    echo "FAIL: gcc -m32 (x87) compiled without MIST_ALLOW_EXCESS_PRECISION"; exit 1
fi
grep -q "MIST_ALLOW_EXCESS_PRECISION" "$out.err" || { cat "$out.err"; echo "FAIL: not the guard's error"; exit 1; }
gcc -m32 -DMIST_ALLOW_EXCESS_PRECISION $w || { echo "FAIL: with MIST_ALLOW_EXCESS_PRECISION"; exit 1; }
gcc -m32 -msse2 -mfpmath=sse $w || { echo "FAIL: with -msse2 -mfpmath=sse"; exit 1; }
echo "x87: stopped with the guard's error; opt-out and SSE math compile"
