#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Benchmark of the firmware in the s51 emulator (never run by the unit tests).

    make -C firmware emu && python3 bench/firmware/bench_firmware.py

Measures with the emulator's own cycle counters (s51's "time" and "isr"
timers, printed when the emulator build ends its run at JOB_END) and its pin
trace:
  * interrupt cycles per step in cruise and averaged over a ramp, by
    difference between runs that share every fixed cost (boot, frames, ACKs,
    homing, the settle and hammer waits) and differ only in steps;
  * the highest step rate the interrupt sustains, and CPU use at the
    profile's top rate (its cruise interval);
  * the worst delay of a step edge after its timer event, with keep-alives
    on the serial line during the move.
Writes bench/firmware/last-run.json.
"""
import json
import re
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "firmware" / "tools"))
import fwhost  # noqa: E402

FW = ROOT / "firmware" / "build-emu" / "tactus-fw.ihx"
RAMP = json.loads((ROOT / "firmware" / "build-emu" / "ramp.json").read_text())
TAB = RAMP["carriage"]["intervals"]
R = len(TAB) - 1
GRID = RAMP["carriage"]["grid_steps"]
BACK = RAMP["carriage"]["backlash_steps"]
CYCLE = 12 / 11.0592e6


def interval(k, n):
    return TAB[min(k, n + 2 - k, R + 1) - 1]


def run_job(tmp, units, vcd=None, poll=False):
    """One emulator run: home, one carriage move of `units` grid units, JOB_END
    (which ends the run); returns s51's total and in-interrupt machine cycles."""
    tmp.mkdir(parents=True, exist_ok=True)
    args = [str(ROOT / "firmware" / "tools" / "run-s51.sh"), str(FW), "--dir", str(tmp), "--stop-at-job-end"]
    if vcd:
        args += ["--vcd", str(vcd)]
    proc = subprocess.Popen(args, stdout=subprocess.PIPE, text=True)
    link = fwhost.Link(proc.stdout.readline().split()[1])
    polls = 0
    try:
        hr = link.hello()
        link.configure(travel=17760, home_iv=288, hammer=3686, settle=920)
        stream = (fwhost.job_begin(1) + fwhost.sheet_begin(1) + fwhost.home() +
                  fwhost.pass_record(0, units, [(False, 0)]) + fwhost.job_end())
        link.send_stream(stream, hr.payload[5])
        end = time.monotonic() + 120
        while proc.poll() is None and time.monotonic() < end:
            if poll:
                try:
                    link.request(fwhost.T_KEEPALIVE, timeout=0.5)
                    polls += 1
                except TimeoutError:
                    pass
            else:
                link.read_reply(0.2)
        proc.wait(timeout=10)
    finally:
        link.close()
        if proc.poll() is None:
            proc.send_signal(signal.SIGTERM)
            proc.wait(timeout=10)
    log = (tmp / "s51.log").read_text()
    total = int(re.search(r'"time"\).*?\((\d+) clks\)', log).group(1)) // 12
    isr = int(re.search(r'"isr"\).*?\((\d+) clks\)', log).group(1)) // 12
    return total, isr, polls


def main():
    if not FW.exists():
        sys.exit(f"{FW} missing: run make -C firmware emu")
    tmp = Path(tempfile.mkdtemp(prefix="tactus-bench-"))
    results = {}
    runs = {}
    # Frames of equal size in each pair: 1 and 25 units (one-byte uvar),
    # 150 and 450 (two bytes). HOME leaves the carriage last moving toward
    # home, so each first move adds the backlash.
    for units in (1, (2 * R) // GRID + 1, 150, 450):
        n = units * GRID + BACK
        runs[n] = run_job(tmp / f"u{units}", units)
        print(f"move of {n:5d} steps: {runs[n][1]:8d} of {runs[n][0]:9d} cycles in interrupts", flush=True)
    small, ramp_n, c1, c2 = sorted(runs)
    cruise = (runs[c2][1] - runs[c1][1]) / (c2 - c1)
    cruise_time = (runs[c2][0] - runs[c1][0]) / (c2 - c1)
    ramp = (runs[ramp_n][1] - runs[small][1]) / (ramp_n - small)
    top = TAB[R]
    results.update(
        cruise_isr_cycles_per_step=round(cruise, 2),
        cruise_cycles_per_step=round(cruise_time, 2),
        ramp_isr_cycles_per_step_avg=round(ramp, 2),
        saturation_steps_per_s=round(1 / (cruise * CYCLE)),
        steps_per_s_at_70pct_cpu=round(0.7 / (cruise * CYCLE)),
        top_rate_steps_per_s=round(1 / (top * CYCLE)),
        top_interval_cycles=top,
        cpu_at_top_rate_pct=round(100 * cruise / top, 1))
    # Edge delays: a long move with keep-alives on the line the whole time.
    units = 300
    vcd = tmp / "pins.vcd"
    _, _, polls = run_job(tmp / "lat", units, vcd=vcd, poll=True)
    results["keepalives_during_latency_run"] = polls
    changes, _ = fwhost.read_vcd(vcd)
    edges = []
    prev = 0xFF
    for t, _, v in changes:
        if v is None:
            continue
        if v & ~prev & 0x01:
            edges.append(t)
        prev = v
    n = units * GRID + BACK
    last = edges[-n:]
    sched = [0.0]
    for k in range(2, n + 1):
        sched.append(sched[-1] + interval(k, n))
    offs = [(last[i] - last[0]) / CYCLE - sched[i] for i in range(n)]
    base = min(offs)
    late = [o - base for o in offs]
    # The earliest edges are fast-path ones: 7 cycles after the timer event.
    results["worst_step_edge_latency_cycles"] = round(max(late) + 7, 1)
    results["edges_more_than_4_cycles_late"] = sum(1 for x in late if x > 4)
    results["edges_measured"] = n
    print(json.dumps(results, indent=1))
    out = ROOT / "bench" / "firmware" / "last-run.json"
    out.write_text(json.dumps(results, indent=1) + "\n")


if __name__ == "__main__":
    main()
