#!/usr/bin/env bash
# Runs a command inside a private X server (Xvfb), D-Bus session and AT-SPI bus,
# the way a screen reader user's desktop has them, and always cleans up.
# Exit 77 (ctest SKIP_RETURN_CODE) only when Xvfb or the AT-SPI bus is not installed.
# SPDX-License-Identifier: GPL-3.0-or-later
set -euo pipefail
if ! command -v Xvfb >/dev/null || ! command -v dbus-run-session >/dev/null ||
   [ ! -x /usr/libexec/at-spi-bus-launcher ]; then
  echo "SKIP: Xvfb, dbus-run-session or at-spi-bus-launcher not installed (tools/install-deps.sh)" >&2
  exit 77
fi
if [ "${TACTUS_IN_SESSION:-}" != 1 ]; then
  export TACTUS_IN_SESSION=1
  exec dbus-run-session -- "$0" "$@"
fi

work=$(mktemp -d)
pids=()
cleanup() {
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do wait "$pid" 2>/dev/null || true; done
  # TACTUS_KEEP_WORK=DIR keeps the session's logs (Orca's, the app's, its spool) for a look afterwards.
  if [ -n "${TACTUS_KEEP_WORK:-}" ]; then mkdir -p "$TACTUS_KEEP_WORK" && cp -r "$work"/. "$TACTUS_KEEP_WORK"/ 2>/dev/null || true; fi
  rm -rf "$work"
}
trap cleanup EXIT INT TERM

# -displayfd picks a free display number and tells us which.
exec 3>"$work/display"
Xvfb -displayfd 3 -screen 0 1400x900x24 -nolisten tcp -noreset >"$work/xvfb.log" 2>&1 &
pids+=($!)
for _ in $(seq 100); do [ -s "$work/display" ] && break; sleep 0.1; done
[ -s "$work/display" ] || { echo "Xvfb did not start:" >&2; cat "$work/xvfb.log" >&2; exit 1; }
export DISPLAY=":$(head -1 "$work/display")"

/usr/libexec/at-spi-bus-launcher --launch-immediately >"$work/atspi.log" 2>&1 &
pids+=($!)
sleep 0.5

# A clean profile: no settings, recent files or autosaves from the user.
export XDG_CONFIG_HOME="$work/config" XDG_DATA_HOME="$work/data" XDG_RUNTIME_DIR="$work/run"
mkdir -p "$XDG_RUNTIME_DIR" && chmod 700 "$XDG_RUNTIME_DIR"
# One setting: the printer panel starts on the built-in simulator at full speed
# (`sim?speed=max`). By default it takes the plan's own time, minutes for the
# scenarios' books; at full speed a 70-sheet job still lasts long enough for
# Alt+P to reach it, as before the simulator ran at the machine's speed.
mkdir -p "$XDG_CONFIG_HOME/Tactus"
printf '[printer]\nlast="sim?speed=max"\n' >"$XDG_CONFIG_HOME/Tactus/tactus.conf"
export QT_QPA_PLATFORM=xcb QT_LINUX_ACCESSIBILITY_ALWAYS_ON=1 QT_ACCESSIBILITY=1 NO_AT_BRIDGE=0
export TACTUS_WORK="$work"
"$@"
