#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Cross-compiles the platform layer's Windows side (core/platform/, *_win.cpp) and
# tests/platform/platform_test.cpp with MinGW-w64, links them with GoogleTest
# built from Debian's sources (/usr/src/googletest, kept in the cache folder for
# later runs), and runs the tests under Wine (docs/windows.md).
# Needs g++-mingw-w64-x86-64, googletest and wine64.
# Usage: tools/windows-platform-tests.sh [CACHE_DIR]   (default: build/windows-platform)
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-"$root/build/windows-platform"}
cxx=${MINGW_CXX:-x86_64-w64-mingw32-g++-posix}
gtest=/usr/src/googletest/googletest
wine=$(command -v wine64 || command -v wine || { [ -x /usr/lib/wine/wine64 ] && echo /usr/lib/wine/wine64; } || true)
command -v "$cxx" >/dev/null 2>&1 || { echo "windows-platform-tests: $cxx not found (apt-get install g++-mingw-w64-x86-64)" >&2; exit 2; }
[ -d "$gtest/src" ] || { echo "windows-platform-tests: no GoogleTest sources in $gtest (apt-get install googletest)" >&2; exit 2; }
mkdir -p "$out"
flags="-std=c++23 -O1 -DWIN32_LEAN_AND_MEAN -DNOMINMAX -DUNICODE -D_UNICODE"
for f in gtest-all gtest_main; do
    [ -f "$out/$f.o" ] || $cxx $flags -I"$gtest/include" -I"$gtest" -c "$gtest/src/$f.cc" -o "$out/$f.o"
done
objs=""
# The layer's Windows side: every source but the POSIX ones (the shared
# worker_process.cpp too), as core/platform/CMakeLists.txt picks them.
for f in "$root"/core/platform/*.cpp "$root"/tests/platform/platform_test.cpp; do
    case $f in *_posix.cpp) continue ;; esac
    o="$out/$(basename "$f" .cpp).o"
    $cxx $flags -Wall -Wextra -Werror -I"$root/core" -I"$gtest/include" -c "$f" -o "$o"
    objs="$objs $o"
done
# shellcheck disable=SC2086
$cxx -static -o "$out/platform_tests.exe" $objs "$out/gtest-all.o" "$out/gtest_main.o" -ladvapi32 -lusp10
echo "windows-platform-tests: built $out/platform_tests.exe"
if [ -z "$wine" ]; then
    echo "windows-platform-tests: no Wine (apt-get install wine64): not run" >&2
    exit 2
fi
export WINEPREFIX="${WINEPREFIX:-$out/wineprefix}" WINEDEBUG="${WINEDEBUG:--all}"
"$wine" "$out/platform_tests.exe"
