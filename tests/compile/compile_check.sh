#!/bin/sh
# compile_check.sh COMPILER FLAGS... -- compiles with warnings as errors.
# Exits 77 (ctest: skipped) with a message when the compiler is absent.
cc=$1; shift
if ! command -v "$cc" >/dev/null 2>&1; then
    echo "$cc not found: test skipped"
    exit 77
fi
echo "$cc $*"
exec "$cc" "$@"
