#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The Windows CLI against the Linux one on the same input (docs/windows.md):
# `plan` (text and JSON) must be byte-identical, and `emboss --device sim`
# must end with the same "embossed N passes" line. Runs tactus-cli.exe under
# Wine in a private prefix (build/wineprefix unless WINEPREFIX is set).
# Usage: tools/windows-cli-check.sh [INPUT]   (default: resources/samples/welcome.md)
# Environment: LINUX_CLI (default build/default/app/tactus-cli),
#              WINDOWS_CLI (default build/windows/app/tactus-cli.exe).
# Exit status: 0 the same, 1 a difference (shown), 2 something missing.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
input=${1:-"$root/resources/samples/welcome.md"}
linux=${LINUX_CLI:-"$root/build/default/app/tactus-cli"}
windows=${WINDOWS_CLI:-"$root/build/windows/app/tactus-cli.exe"}
wine=$(command -v wine64 || command -v wine || { [ -x /usr/lib/wine/wine64 ] && echo /usr/lib/wine/wine64; } || true)
[ -x "$linux" ] || { echo "windows-cli-check: no Linux CLI at $linux" >&2; exit 2; }
[ -f "$windows" ] || { echo "windows-cli-check: no Windows CLI at $windows (tools/windows-build.sh)" >&2; exit 2; }
[ -n "$wine" ] || { echo "windows-cli-check: no Wine (apt-get install wine64)" >&2; exit 2; }
export WINEPREFIX="${WINEPREFIX:-$root/build/wineprefix}" WINEDEBUG="${WINEDEBUG:--all}"
# The Windows CLI reads "/x" as a Windows-style option (CLI11): an absolute
# path goes to it through Wine's drive Z:, which is /.
case $input in
    /*) win_input="Z:$input" ;;
    *) win_input=$input ;;
esac
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
status=0
same() {  # same WHAT FILE_A FILE_B
    if cmp -s "$2" "$3"; then
        echo "windows-cli-check: $1: identical ($(wc -c <"$2") bytes)"
    else
        echo "windows-cli-check: $1: DIFFERENT" >&2
        diff "$2" "$3" | head -20 >&2 || true
        status=1
    fi
}
"$linux" plan "$input" >"$out/plan.linux"
"$wine" "$windows" plan "$win_input" >"$out/plan.windows"
same "plan" "$out/plan.linux" "$out/plan.windows"
"$linux" plan --json "$input" >"$out/plan-json.linux"
"$wine" "$windows" plan --json "$win_input" >"$out/plan-json.windows"
same "plan --json" "$out/plan-json.linux" "$out/plan-json.windows"
"$linux" emboss --device sim "$input" 2>&1 | grep '^embossed ' >"$out/emboss.linux" || true
"$wine" "$windows" emboss --device sim "$win_input" 2>&1 | tr -d '\r' | grep '^embossed ' >"$out/emboss.windows" || true
[ -s "$out/emboss.linux" ] || { echo "windows-cli-check: the Linux CLI printed no 'embossed' line" >&2; status=1; }
same "emboss --device sim: $(cat "$out/emboss.linux")" "$out/emboss.linux" "$out/emboss.windows"
exit $status
