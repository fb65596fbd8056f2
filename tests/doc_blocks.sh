#!/bin/sh
# doc_blocks.sh CC INCLUDE_DIR WORK FILE...: compiles every ```c block of
# the Markdown FILEs with CC -std=c99 -Wall -Wextra -Wpedantic -Werror and
# runs it, so that the documentation cannot drift from the header.  A block
# with its own main is a program; any other block is a fragment, compiled
# inside a main() after mist.h and mist_mie.h (its variables are its own).
set -u
cc=$1; inc=$2; work=$3; shift 3
mkdir -p "$work" || exit 1
n=0; fail=0
for f in "$@"; do
    base=$(basename "$f" .md)
    # split the file's C blocks into $work/BASE_K.blk
    awk -v out="$work/$base" '
        /^```c[ \t]*$/ { k++; inb = 1; file = out "_" k ".blk"; printf "" > file; next }
        /^```/ && inb  { inb = 0; close(file); next }
        inb            { print >> file }' "$f"
    for blk in "$work/$base"_*.blk; do
        [ -e "$blk" ] || continue
        n=$((n + 1))
        src="${blk%.blk}.c"
        if grep -q 'main *(' "$blk"; then
            cp "$blk" "$src"
        else
            { printf '#include "mist.h"\n#include "mist_mie.h"\n#include <stdio.h>\n#include <stdlib.h>\n'
              printf 'int main(void)\n{\n'; cat "$blk"; printf '    return 0;\n}\n'; } > "$src"
        fi
        if "$cc" -std=c99 -Wall -Wextra -Wpedantic -Werror -Wno-unused-variable \
               -Wno-unused-but-set-variable -I"$inc" "$src" -o "${blk%.blk}" -lm &&
           "${blk%.blk}" >/dev/null; then
            echo "ok: $f, block $(basename "$blk" .blk)"
        else
            echo "FAILED: $f, block $(basename "$blk" .blk) ($src)"; fail=$((fail + 1))
        fi
    done
done
echo "doc_blocks: $n C blocks, $fail failed"
[ "$n" -gt 0 ] && [ "$fail" -eq 0 ]
