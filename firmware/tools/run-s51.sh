#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs the firmware in s51 (an emulated 8052 at 11.0592 MHz) with its UART on a
# pseudo-terminal, the way docs/emulator.md explains:
# two FIFOs for the emulator's serial port, bridged by socat to a raw pty (the
# TCP and tty options of s51 are not binary-clean).
#
#   tools/run-s51.sh FW.ihx [--vcd FILE] [--paper-out] [--console PORT] [--dir DIR]
#
# Prints "PTY /dev/pts/N" once the pty exists, then runs until killed (SIGTERM
# or SIGINT stops s51 and socat). --stop-at-job-end: the emulator build ends
# the run at JOB_END; s51 prints its cycle counters into DIR/s51.log and quits. --vcd logs port 1 (steps, directions,
# hammers) as a value-change dump with the emulator's clock. --console opens
# s51's command console on a local TCP port (bench/firmware reads its cycle
# counters there: "timer get").
set -euo pipefail
ihx=""
vcd=""
paper=1
dir=""
console=""
stop=0
while [ $# -gt 0 ]; do
  case "$1" in
    --vcd) vcd=$(realpath -m "$2"); shift 2 ;;
    --paper-out) paper=0; shift ;;
    --console) console="$2"; shift 2 ;;
    --stop-at-job-end) stop=1; shift ;;
    --dir) dir="$2"; shift 2 ;;
    -h|--help) sed -n 2,12p "$0"; exit 0 ;;
    -*) echo "run-s51.sh: unknown option $1" >&2; exit 2 ;;
    *) ihx=$(realpath "$1"); shift ;;
  esac
done
[ -n "$ihx" ] && [ -f "$ihx" ] || { echo "run-s51.sh: give the firmware .ihx (make -C firmware)" >&2; exit 2; }
for tool in s51 socat; do
  command -v $tool >/dev/null || { echo "run-s51.sh: $tool not found (apt-get install sdcc-ucsim socat)" >&2; exit 2; }
done
[ -n "$dir" ] || dir=$(mktemp -d /tmp/tactus-s51.XXXXXX)
mkdir -p "$dir"
cd "$dir"
rm -f h2t t2h con ttyFW
mkfifo h2t t2h con
exec 3<>h2t 4<>t2h            # hold both FIFOs open, or the opens deadlock
# s51's stdin console: a FIFO held open here and never written. At an end of
# file (/dev/null) s51 closes its stdin and stdout descriptors, and files it
# opens later reuse them: its output then went astray, at times into what it
# read back as commands.
exec 5<>con
{
  # A command file runs before a hex file named on the command line is loaded,
  # so the image is loaded here.
  echo "file \"$ihx\""
  # P3.6 is the paper sensor (high = paper).
  if [ "$paper" = 0 ]; then echo "set memory port_3_cfg 1 0xbf"; fi
  if [ -n "$vcd" ]; then
    echo "set hw vcd[0] output \"$vcd\""
    echo "set hw vcd[0] add port_1_cfg 2"
    echo "set hw vcd[0] start"
  fi
  # With a console, its user starts the run ("run"): s51 serves the console
  # only while it is not running a command file's run.
  [ -n "$console" ] || echo "run"
  # The emulator build stops the run at JOB_END through the simulator
  # interface; then print the cycle counters (total, in interrupts) and end
  # s51 ("kill": "quit" only leaves this command file, and the stdin console
  # stays open).
  if [ "$stop" = 1 ]; then echo "timer get"; echo "kill"; fi
} > cmds
pids=()
cleanup() {
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done
  wait 2>/dev/null || true
}
trap cleanup EXIT INT TERM
socat PTY,link="$dir/ttyFW",raw,echo=0 'PIPE:t2h!!PIPE:h2t' &
pids+=($!)
extra=(-b)                    # batch: no interactive console ...
[ -n "$console" ] && extra=(-Z "$console")   # ... unless one is asked for
[ "$stop" = 1 ] && extra+=(-I 'if=xram[0xffff]')
s51 -t C52 -X 11.0592M -S in=h2t,out=t2h -e 'uart0_check_often=1' "${extra[@]}" -C cmds <con >s51.log 2>&1 &
pids+=($!)
for _ in $(seq 100); do [ -e "$dir/ttyFW" ] && break; sleep 0.05; done
[ -e "$dir/ttyFW" ] || { echo "run-s51.sh: socat made no pty" >&2; exit 1; }
echo "PTY $(readlink -f "$dir/ttyFW")"
echo "DIR $dir"
wait "${pids[1]}"
