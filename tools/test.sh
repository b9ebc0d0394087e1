#!/usr/bin/env bash
# Set up, build and run every test: the default build (GCC, warnings are
# errors, every test), then one clang build with AddressSanitizer and UBSan of
# core, the CLI, their tests and the libFuzzer targets (core is compiled once
# for both: its tests run under the sanitizers, then each fuzz target runs for
# its share of a bounded time). Each stage's wall time is printed as it ends
# and in a table at the end (bench/ci/RESULTS.md keeps the figures of cold runs).
# SPDX-License-Identifier: GPL-3.0-or-later
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)
# The fuzz stage's whole budget in seconds, shared by the targets (at least
# 10 s each), two at a time on a machine with two cores or more.
fuzz_total=${TACTUS_FUZZ_SECONDS_TOTAL:-160}

stages=()
stage_start=0
stage() {
  stage_end
  stage_name=$1
  stage_start=$(date +%s)
  echo "== $1"
}
stage_end() {
  if [ "$stage_start" -gt 0 ]; then
    local took=$(( $(date +%s) - stage_start ))
    stages+=("$(printf '%5d s  %s' "$took" "$stage_name")")
    echo "-- $stage_name: ${took} s"
  fi
  stage_start=0
}
report() {
  stage_end
  echo "== stage times (wall, $(nproc) cores)"
  printf '%s\n' "${stages[@]}"
  echo "$(printf '%5d s' $(( $(date +%s) - run_start )))  total"
}
run_start=$(date +%s)
trap report EXIT

stage "dependencies (tools/install-deps.sh)"
tools/install-deps.sh

stage "architecture (stage order, declared includes, no cycles)"
python3 tools/check-architecture.py

stage "89C52 firmware: build, fit in 8 KB flash and 256 B RAM, native link tests"
make -C firmware clean >/dev/null 2>&1 || true
make -C firmware
make -C firmware test

stage "default build (warnings are errors)"
cmake --preset default >/dev/null
cmake --build build/default -j"$jobs"

# The default tests wait more than they compute (ptys, the simulated
# machine's time, s51, a cupsd, kills and restarts): measured, 674 s of CPU
# over 987 tests in 581 s of wall on 2 cores, so about 40 % of the machine
# sat idle. The sanitize build takes that idle time at the lowest priority
# (nice 19: it gets a core only when no test wants it) instead of starting
# after them. Its output goes to a log, shown when it fails.
stage "default tests (all but the Orca scenarios), the sanitize build beside them at the lowest priority"
cmake --preset sanitize >/dev/null
build_log=$(mktemp)
build_start=$(date +%s)
nice -n 19 cmake --build build/sanitize -j"$jobs" >"$build_log" 2>&1 &
build_pid=$!
orca_pid=
stop_background() {
  kill "$build_pid" 2>/dev/null || true
  [ -n "$orca_pid" ] && kill "$orca_pid" 2>/dev/null || true
  report
}
trap stop_background EXIT
ctest --preset default -j"$jobs" -LE orca

# The Orca scenarios mostly wait for speech (about 120 s of CPU in 420 s), so
# they run two at a time beside the rest of the sanitize build and its tests
# rather than holding test slots; those run at a lower priority, so Orca, the
# app and Xvfb get a core at once when they need one. Their log is shown
# when one fails.
stage "the rest of the sanitize build (clang: core, the CLI, their tests, the fuzz targets), beside the Orca scenarios"
orca_log=$(mktemp)
orca_start=$(date +%s)
ctest --preset default -j2 -L orca --output-on-failure >"$orca_log" 2>&1 &
orca_pid=$!
build_rc=0
wait "$build_pid" || build_rc=$?
echo "-- the sanitize build took $(( $(date +%s) - build_start )) s in all"
if [ "$build_rc" -ne 0 ]; then cat "$build_log"; exit "$build_rc"; fi
tail -n 1 "$build_log"
rm -f "$build_log"

stage "AddressSanitizer + UBSan tests, beside the Orca scenarios"
nice -n 10 ctest --preset sanitize -j"$jobs"

orca_rc=0
wait "$orca_pid" || orca_rc=$?
orca_pid=
trap report EXIT
grep -E '^ *[0-9]+/[0-9]+ Test|tests passed|tests failed' "$orca_log" || true
echo "-- the Orca scenarios took $(( $(date +%s) - orca_start )) s beside the build and the sanitize tests"
if [ "$orca_rc" -ne 0 ]; then cat "$orca_log"; rm -f "$orca_log"; exit "$orca_rc"; fi
rm -f "$orca_log"

stage "fuzz targets (libFuzzer, ${fuzz_total} s in all)"
targets=()
for target in build/sanitize/tests/fuzz/fuzz_*; do
  [ -x "$target" ] && targets+=("$target")
done
parallel=$(( jobs >= 2 ? 2 : 1 ))
per_target=$(( fuzz_total * parallel / (${#targets[@]} > 0 ? ${#targets[@]} : 1) ))
[ "$per_target" -ge 10 ] || per_target=10
echo "${#targets[@]} targets, ${per_target} s each, ${parallel} at a time"
fuzz_one() {
  local target=$1 seconds=$2 name work log rc=0
  name=$(basename "$target")
  work=$(mktemp -d)
  log=$(mktemp)
  tools/fuzz-corpus.sh "$name" "$work"
  "$target" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 \
    -print_final_stats=1 "$work" >"$log" 2>&1 || rc=$?
  echo "-- $name (exit $rc)"
  if [ "$rc" -ne 0 ]; then cat "$log"; else tail -n 3 "$log"; fi
  rm -rf "$work" "$log"
  return "$rc"
}
# The leaks of third-party libraries the sanitize tests also suppress
# (liblouis's lou_getTableInfo): the fuzz targets reach the same calls.
export LSAN_OPTIONS="suppressions=$PWD/tests/lsan.supp"
export -f fuzz_one
printf '%s\n' "${targets[@]}" | xargs -P "$parallel" -I{} bash -c 'fuzz_one "$1" "$2"' _ {} "$per_target"

# The Windows side made here (docs/windows.md): the vendored libraries and
# tactus-cli.exe cross-compiled with MinGW-w64, the NSIS installer, and that
# installer installed silently under Wine into a fresh prefix without the
# build machine's files, its CLI's BRF and plans compared byte for byte with
# the Linux CLI's, and uninstalled; then the core's translate, layout,
# plan, edit, encode, estimate and motion tests, built in the same folder
# (core is compiled once), under Wine two at a time.
stage "Windows: MinGW-w64 build, NSIS installer, installed and checked under Wine; core tests under Wine"
JOBS=$jobs tools/windows-build.sh package
tools/windows-installer-check.sh
JOBS=$jobs tools/windows-build.sh tests
tools/windows-core-tests.sh

echo "== all tests passed"
