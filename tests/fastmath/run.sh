#!/bin/sh
# run.sh CC BIN SRC_INCLUDE FLAGS...
# Builds the height fog's bad-input cases (fm_cases.h) twice with the C
# compiler CC: fm_fast.c with FLAGS (the includer's fast-math flags), fm_ref.c
# and fm_main.c with -O2, links them in the folder BIN and runs the
# comparison (fm_main.c).  Exits 77 (ctest: skipped) when CC is absent or
# cannot build a program with FLAGS (e.g. -march=native elsewhere).
set -u
cc=$1; bin=$2; inc=$3; shift 3
here=$(dirname "$0")
if ! command -v "$cc" >/dev/null 2>&1; then
    echo "fastmath: no $cc: skipped"; exit 77
fi
mkdir -p "$bin" || exit 1
printf 'int main(void) { return 0; }\n' > "$bin/probe.c"
if ! "$cc" "$@" "$bin/probe.c" -o "$bin/probe" >/dev/null 2>&1; then
    echo "fastmath: $cc cannot build with '$*': skipped"; exit 77
fi
echo "fastmath: $cc $*"
"$cc" -std=c99 "$@" -I"$inc" -c "$here/fm_fast.c" -o "$bin/fm_fast.o" &&
"$cc" -std=c99 -O2 -I"$inc" -c "$here/fm_ref.c" -o "$bin/fm_ref.o" &&
"$cc" -std=c99 -O2 -c "$here/fm_main.c" -o "$bin/fm_main.o" &&
"$cc" "$bin/fm_fast.o" "$bin/fm_ref.o" "$bin/fm_main.o" -o "$bin/fm" -lm || exit 1
exec "$bin/fm"
