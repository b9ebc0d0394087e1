#!/usr/bin/env bash
# Runs the benchmarks on a built tree (default preset) and prints their figures.
# SPDX-License-Identifier: GPL-3.0-or-later
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD:-build/default}
data=${BENCH_DATA:-$build/bench-data}
mkdir -p "$data"
[ -s "$data/kjv.txt" ] || bible -f gen1:1-rev22:21 > "$data/kjv.txt"
[ -s "$data/genesis.txt" ] || bible -f gen1:1-gen50:26 > "$data/genesis.txt"
[ -s "$data/genesis1-3.txt" ] || bible -f gen1:1-gen3:24 > "$data/genesis1-3.txt"
run() { echo "== $1"; shift; "$@"; }
run "layout: KJV, Tactus pipeline vs lou_translate" "$build/bench/layout/bench_layout" "$data/kjv.txt"
run "plan + estimate: KJV" "$build/bench/plan/bench_plan" "$data/kjv.txt"
run "single-line text: 1, 4, 16 MB" "$build/bench/single_line/bench_single_line"
run "import: 100 MiB text" "$build/bench/import/bench_import"
run "link: efficiency on the pty simulator" "$build/bench/link/bench_link"
run "spool: 10,000 jobs" "$build/bench/spool/bench_spool"
run "emboss --dry-run: peak memory against pages (Genesis, 1x and 5x)" bench/dry_run/dry_run_memory.sh "$data/genesis.txt" 1 5
if [ -x "$build/bench/gui/bench_gui" ]; then
  QT_QPA_PLATFORM=offscreen run "gui: keystroke to preview, 1,000 pages" "$build/bench/gui/bench_gui" "$data/kjv.txt"
  QT_QPA_PLATFORM=offscreen run "gui: keystroke to preview, 1,000 pages of hard-wrapped .txt" \
    "$build/bench/gui/bench_gui" "$data/kjv.txt" 1000 --text
  # Ready-made braille kept page for page: 1,026 pages of 40 x 30.
  [ -s "$data/kjv-40x30.pef" ] || { head -c 1300000 "$data/kjv.txt" > "$data/kjv-part.txt" &&
    "$build/app/tactus-cli" layout --cells 40 --lines 30 --to pef "$data/kjv-part.txt" -o "$data/kjv-40x30.pef"; }
  QT_QPA_PLATFORM=offscreen run "gui: braille cell to preview, a 1,026-page PEF kept page for page" \
    "$build/bench/gui/bench_gui" "$data/kjv-40x30.pef"
fi
run "firmware: v3 line bytes per strike (host encoder)" "$build/bench/firmware/bench_v3_stream" \
  resources/samples/welcome.md "$data/genesis1-3.txt"
if command -v s51 >/dev/null && command -v sdcc >/dev/null; then
  # The reference firmware in s51 (docs/protocol.md, "The firmware's figures").
  make -s -C firmware emu >/dev/null
  run "firmware: interrupt cycles, step rate, edge latency, CPU, link efficiency (s51)" \
    python3 bench/firmware/bench_firmware.py
  for doc in resources/samples/welcome.md "$data/genesis1-3.txt"; do
    "$build/app/tactus-cli" plan --json --firmware-tables firmware/build-emu/ramp.json "$doc" > "$data/fw-plan.json"
    run "firmware: line bytes per strike, lowest baud without a wait: $(basename "$doc") sheet 1" \
      python3 bench/firmware/bytes_per_strike.py "$data/fw-plan.json" --sheet 1
  done
  run "firmware: welcome.md sheet 1 through s51 against the plan (about 6 minutes)" \
    python3 bench/firmware/bench_sheet.py --cli "$build/app/tactus-cli"
fi
