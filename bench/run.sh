#!/usr/bin/env bash
# Runs the benchmarks on a built tree (default preset) and prints their figures.
# SPDX-License-Identifier: GPL-3.0-or-later
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD:-build/default}
data=${BENCH_DATA:-$build/bench-data}
mkdir -p "$data"
[ -s "$data/kjv.txt" ] || bible -f gen1:1-rev22:21 > "$data/kjv.txt"
echo "== layout (KJV)"
"$build/bench/layout/bench_layout" "$data/kjv.txt"
for extra in "$build"/bench/*/bench_*; do
  case "$extra" in */bench_layout) continue ;; esac
  [ -x "$extra" ] || continue
  echo "== $(basename "$extra")"
  "$extra" "$data/kjv.txt" || true
done
