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
# has confirmed executing every pass); the last lines are the summary.
"$cli" emboss --device "sim?speed=max" resources/samples/welcome.md | tail -n 2
