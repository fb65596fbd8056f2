#!/bin/sh
# run.sh SOURCE WORK: install mist into WORK/prefix (configured for another
# prefix and moved there by `cmake --install --prefix`, as a packager does),
# then build and run the consumer (tests/consumer) against it with
# find_package, with pkg-config (skipped with a message if pkg-config is
# absent), with add_subdirectory and with FetchContent; the last two must not
# install mist's files with the parent project (MIST_INSTALL is off there).
set -e
src=$1; work=$2
rm -rf "$work"; mkdir -p "$work"
cmake -S "$src" -B "$work/mist" -DMIST_BUILD_TESTS=OFF -DMIST_BUILD_EXAMPLES=OFF \
      -DCMAKE_INSTALL_PREFIX="$work/elsewhere" >/dev/null
cmake --install "$work/mist" --prefix "$work/prefix" >/dev/null
[ ! -e "$work/elsewhere" ] || { echo "installed into the configured prefix"; exit 1; }
echo "installed:"; (cd "$work/prefix" && find . -type f | sort)

cmake -S "$src/tests/consumer" -B "$work/pkg" -DMODE=package \
      -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
cmake --build "$work/pkg" >/dev/null
"$work/pkg/consumer"

for mode in subdir fetch; do
    cmake -S "$src/tests/consumer" -B "$work/$mode" -DMODE=$mode -DMIST_SOURCE="$src" >/dev/null
    cmake --build "$work/$mode" >/dev/null
    "$work/$mode/consumer"
    cmake --install "$work/$mode" --prefix "$work/$mode-inst" >/dev/null
    if [ -n "$(find "$work/$mode-inst" -type f 2>/dev/null)" ]; then
        echo "$mode: the parent project's install shipped mist's files:"
        find "$work/$mode-inst" -type f; exit 1
    fi
done

if command -v pkg-config >/dev/null 2>&1; then
    PKG_CONFIG_PATH="$work/prefix/share/pkgconfig" pkg-config --cflags --libs mist
    cc -std=c99 -Wall -Wextra -Wpedantic -Werror $(PKG_CONFIG_PATH="$work/prefix/share/pkgconfig" \
       pkg-config --cflags mist) "$src/tests/consumer/main.c" -o "$work/pc" \
       $(PKG_CONFIG_PATH="$work/prefix/share/pkgconfig" pkg-config --libs mist)
    "$work/pc"
else
    echo "pkg-config not found: its part skipped"
fi
echo "consumer: all builds passed"
