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
  * the step edges against their timer events, with keep-alives on the
    serial line during the move: each must come EDGE_TICKS after its event
    (step.asm), a spread of 0 cycles;
  * link efficiency against the firmware: DATA payload bytes per second of
    the chip's clock over what the baud rate carries, for a stream of ops
    that take no time to execute (so the link is the only limit), sent with
    the window (4 frames, the ring's free bytes), by difference between a
    long and a short stream.
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


def windowed_send(link, stream, max_payload, window=4):
    """Sends the stream in DATA frames as the window allows: at most `window`
    frames unacknowledged and never more bytes than the last ACK's free
    bytes (docs/protocol.md, "Reliability"). No noise here, so nothing is
    lost; a silence re-sends from the first unacknowledged frame."""
    max_data = max_payload - 2
    chunks = [stream[i:i + max_data] for i in range(0, len(stream), max_data)]
    base_seq = link.seq
    acked = 0     # chunks acknowledged
    nxt = 0       # next chunk to send
    free = None   # ring bytes free after what `acked` covers
    while acked < len(chunks):
        in_flight = sum(len(c) for c in chunks[acked:nxt])
        while (nxt < len(chunks) and nxt - acked < window and
               (free is None and nxt == acked or free is not None and in_flight + len(chunks[nxt]) <= free)):
            link.write(fwhost.frame((base_seq + nxt) & 0xFF, fwhost.T_DATA, chunks[nxt]))
            in_flight += len(chunks[nxt])
            nxt += 1
        r = link.read_reply(1.0)
        if r is None:
            if nxt == len(chunks):
                return  # all sent: JOB_END may have ended the run before its ACK
            nxt = acked  # go back
            continue
        if r.type in (fwhost.T_ACK, fwhost.T_NAK):
            done = (r.seq - base_seq) & 0xFF
            if done > acked and done <= nxt:
                acked = done
            free = r.ack["free"]
            if r.type == fwhost.T_NAK and r.payload[0] == 1:
                nxt = acked
    link.seq = (base_seq + len(chunks)) & 0xFF


def run_stream(tmp, pairs):
    """Boot, HELLO, CONFIGURE and a job of `pairs` SHEET_BEGIN/SHEET_END pairs
    (no motion) sent with the window; JOB_END ends the run. Returns s51's
    machine cycles and the DATA payload bytes sent."""
    tmp.mkdir(parents=True, exist_ok=True)
    args = [str(ROOT / "firmware" / "tools" / "run-s51.sh"), str(FW), "--dir", str(tmp), "--stop-at-job-end"]
    proc = subprocess.Popen(args, stdout=subprocess.PIPE, text=True)
    link = fwhost.Link(proc.stdout.readline().split()[1])
    try:
        hr = link.hello()
        link.configure(travel=17760, home_iv=288, hammer=3686, settle=920)
        stream = fwhost.job_begin(1) + (fwhost.sheet_begin(1) + fwhost.sheet_end()) * pairs + fwhost.job_end()
        try:
            windowed_send(link, stream, hr.payload[5], window=hr.payload[6])
        except OSError:
            pass  # the emulator ended the run at JOB_END before its last ACK went out
        proc.wait(timeout=120)
    finally:
        link.close()
        if proc.poll() is None:
            proc.send_signal(signal.SIGTERM)
            proc.wait(timeout=10)
    log = (tmp / "s51.log").read_text()
    total = int(re.search(r'"time"\).*?\((\d+) clks\)', log).group(1)) // 12
    max_data = hr.payload[5] - 2
    payload = len(stream) + 2 * -(-len(stream) // max_data)
    return total, payload


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
    offs = [round((last[i] - last[0]) / CYCLE - sched[i]) for i in range(n)]
    base = min(offs)
    late = [o - base for o in offs]
    # Every edge comes EDGE_TICKS after its timer event whatever the
    # interrupt's latency (step.asm compensates latencies up to LAT_MAX, the
    # assembler's symbol table has both): the spread must be 0.
    sym = (FW.parent / "step.sym").read_text()
    results["step_edge_after_timer_event_cycles"] = int(re.search(r"EDGE_TIC=\s*([0-9A-Fa-f]+)", sym).group(1), 16)
    results["latency_compensated_up_to_cycles"] = int(re.search(r"LAT_MAX\s*=\s*([0-9A-Fa-f]+)", sym).group(1), 16)
    results["step_edge_spread_cycles"] = max(late)
    results["edges_off_the_schedule"] = sum(1 for x in late if x)
    results["edges_measured"] = n
    # Link efficiency against the firmware (9600 baud, the emulator build's).
    baud = 9600
    short = run_stream(tmp / "s1", 20)
    long_ = run_stream(tmp / "s2", 1020)
    seconds = (long_[0] - short[0]) * CYCLE
    results["link_efficiency_9600"] = round((long_[1] - short[1]) / (seconds * baud / 10), 3)
    results["link_efficiency_ceiling"] = round(33 / (33 + 6), 3)  # a full DATA frame: 6 bytes of framing
    print(json.dumps(results, indent=1))
    out = ROOT / "bench" / "firmware" / "last-run.json"
    out.write_text(json.dumps(results, indent=1) + "\n")


if __name__ == "__main__":
    main()
