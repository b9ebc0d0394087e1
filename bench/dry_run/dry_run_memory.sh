#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Peak memory of `tactus-cli emboss --dry-run` against the number of braille
# pages, with `tactus-cli layout --summary` on the same text as the peer (the
# layout alone): a dry run must not hold every page (100,000 pages once took
# 2.4 GB). Prints, per
# size: pages, peak RSS of each, the ratio, and MB per page.
#
#   bench/dry_run/dry_run_memory.sh [TEXT] [COPIES...]
# TEXT defaults to $BENCH_DATA/kjv.txt (bench/run.sh makes it); the text is
# repeated COPIES times (default 1 2) for the larger sizes.
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${BUILD:-build/default}
cli=$build/app/tactus-cli
text=${1:-${BENCH_DATA:-$build/bench-data}/kjv.txt}
shift || true
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(1 2)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# Peak RSS in KB; the command may fail (a book over the controller's 65,535
# passes is refused with exit 3: its row says so).
peak_kb() { /usr/bin/time -f %M -o "$work/time" "$@" > "$work/out" 2>/dev/null || echo $? > "$work/exit"; tail -n 1 "$work/time"; }
printf '%8s %12s %12s %8s %10s %8s %5s\n' pages dryrun_MB layout_MB ratio MB/page seconds exit
for n in "${sizes[@]}"; do
  : > "$work/doc.txt"
  for _ in $(seq "$n"); do cat "$text" >> "$work/doc.txt"; done
  layout_kb=$(peak_kb "$cli" layout --summary "$work/doc.txt")
  pages=$(sed -n 's/^pages: *\([0-9]*\) braille pages.*/\1/p' "$work/out")
  echo 0 > "$work/exit"
  start=$(date +%s.%N)
  dry_kb=$(peak_kb "$cli" emboss --dry-run "$work/doc.txt")
  secs=$(echo "$(date +%s.%N) - $start" | bc)
  awk -v p="$pages" -v d="$dry_kb" -v l="$layout_kb" -v s="$secs" -v e="$(cat "$work/exit")" \
    'BEGIN { printf "%8d %12.1f %12.1f %8.1f %10.3f %8.1f %5d\n", p, d/1024, l/1024, d/l, d/1024/p, s, e }'
done
