#!/bin/sh
# ctags_check.sh HEADER CALLS: every public function that CALLS (a file that
# calls each one, tests/compile/use_all.h) names must be indexed by ctags,
# with its default options, as a function definition of HEADER under its
# real name (double and float alike), so that an editor's go-to-definition
# finds its plain-C signature.  Skipped (77) without ctags.
set -u
hdr=$1; calls=$2
command -v ctags >/dev/null 2>&1 || { echo "ctags not found: skipped"; exit 77; }
have=$(ctags -x "$hdr" 2>/dev/null | awk '$2 == "function" { print $1 }' | sort -u)
want=$(grep -o 'mist_[a-z0-9_]*(' "$calls" | tr -d '(' | sort -u)
missing=$(printf '%s\n' "$want" | while read -r f; do
    printf '%s\n' "$have" | grep -qx "$f" || echo "$f"; done)
n=$(printf '%s\n' "$want" | wc -l)
if [ -n "$missing" ]; then
    echo "ctags does not list these public functions of $hdr:"; echo "$missing"; exit 1
fi
echo "ctags lists all $n public functions that $(basename "$calls") calls"
