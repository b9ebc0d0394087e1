#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Compiles every Windows implementation of the platform layer (core/platform/*_win.cpp)
# with the MinGW-w64 cross compiler, syntax and types only, with the default
# build's warnings as errors. Needs g++-mingw-w64-x86-64 (docs/windows.md).
# About 2 s of CPU per file, so it is a script and not a ctest.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
cxx=${MINGW_CXX:-x86_64-w64-mingw32-g++-posix}
if ! command -v "$cxx" >/dev/null 2>&1; then
    echo "check-windows-syntax: $cxx not found (apt-get install g++-mingw-w64-x86-64)" >&2
    exit 2
fi
failed=0
count=0
for f in "$root"/core/platform/*_win.cpp; do
    count=$((count + 1))
    if ! "$cxx" -std=c++23 -fsyntax-only -DWIN32_LEAN_AND_MEAN -DNOMINMAX -DUNICODE -D_UNICODE \
        -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wold-style-cast -Wcast-align \
        -Wunused -Woverloaded-virtual -Wconversion -Wsign-conversion -Wdouble-promotion -Wformat=2 \
        -Wimplicit-fallthrough -Werror \
        -I"$root/core" "$f"; then
        echo "check-windows-syntax: FAILED ${f#"$root"/}" >&2
        failed=$((failed + 1))
    fi
done
if [ "$failed" -ne 0 ]; then
    echo "check-windows-syntax: $failed of $count Windows files do not compile" >&2
    exit 1
fi
echo "check-windows-syntax: $count Windows files compile with $cxx ($("$cxx" -dumpversion))"
