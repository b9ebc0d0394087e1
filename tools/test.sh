#!/usr/bin/env bash
# Set up, build and run every test: the default build (warnings are errors),
# an AddressSanitizer/UBSan build of the tests, and each fuzz target for a
# bounded time.
# SPDX-License-Identifier: GPL-3.0-or-later
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install-deps.sh
jobs=$(nproc)

echo "== architecture (stage order, declared includes, no cycles)"
python3 tools/check-architecture.py

echo "== 89C52 firmware: build, fit in 8 KB flash and 256 B RAM, native link tests"
make -C firmware clean >/dev/null 2>&1 || true
make -C firmware
make -C firmware test

echo "== default build (warnings are errors)"
cmake --preset default >/dev/null
cmake --build build/default -j"$jobs"
ctest --preset default -j"$jobs"

echo "== AddressSanitizer + UBSan build"
cmake --preset asan >/dev/null
cmake --build build/asan -j"$jobs"
ctest --preset asan -j"$jobs"

echo "== fuzz targets (libFuzzer, ${TACTUS_FUZZ_SECONDS:-30} s each)"
cmake --preset fuzz >/dev/null
cmake --build build/fuzz -j"$jobs"
for target in build/fuzz/tests/fuzz/fuzz_*; do
  [ -x "$target" ] || continue
  name=$(basename "$target")
  corpus=tests/fuzz/corpus/${name#fuzz_}
  [ -d "$corpus" ] || corpus=tests/fuzz/corpus/$name
  work=$(mktemp -d)
  [ -d "$corpus" ] && cp -r "$corpus"/. "$work"/
  echo "-- $name"
  "$target" -max_total_time="${TACTUS_FUZZ_SECONDS:-30}" -rss_limit_mb=2048 -timeout=10 \
    -print_final_stats=1 "$work" 2>&1 | tail -n 3
  rm -rf "$work"
done
echo "== all tests passed"
