#!/usr/bin/env bash
# The main job: set up, build, and emboss the bundled sample document.
# SPDX-License-Identifier: GPL-3.0-or-later
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install-deps.sh
cmake --preset default >/dev/null
cmake --build build/default -j"$(nproc)" --target tactus-cli
cli=build/default/app/tactus-cli
mkdir -p out
"$cli" layout --interpoint --to brf -o out/welcome.brf resources/samples/welcome.md
"$cli" layout --interpoint --to pef -o out/welcome.pef resources/samples/welcome.md
"$cli" layout --interpoint --summary resources/samples/welcome.md
# Emboss it on the built-in simulated controller (exit 0 only when the controller
# has confirmed executing every pass); the last lines are the summary. It speaks
# protocol 3 with the ramp tables the firmware would be built with from the same
# profile (the summary ends "(protocol 3)"; sim?protocol=2 for the older one).
"$cli" emboss --device "sim?speed=max" resources/samples/welcome.md | tail -n 2

# The same host on the real controller code: the reference firmware (firmware/,
# its emulator build) in the s51 emulator behind a pty. The host finds protocol 3
# in HELLO_REPLY, plans with the firmware's ramp tables and checks their id; the
# strikes are read back from the emulated chip's port pins. A one-line sample:
# the emulator runs in about real time.
make -C firmware emu >/dev/null
"$cli" sim --firmware firmware/build-emu/tactus-fw.ihx --pty --strike-log out/firmware-strikes.jsonl \
  > out/firmware-sim.txt &
sim=$!
trap 'kill "$sim" 2>/dev/null || true' EXIT
for _ in $(seq 100); do [ -s out/firmware-sim.txt ] && break; sleep 0.1; done
pty=$(head -n 1 out/firmware-sim.txt)
"$cli" emboss --device "pty:$pty?baud=9600" --firmware-tables firmware/build-emu/ramp.json \
  resources/samples/firmware-note.md | tail -n 1
kill "$sim"
wait "$sim" || true
echo "firmware in s51: $(wc -l < out/firmware-strikes.jsonl) strikes read from its pins (out/firmware-strikes.jsonl)"
