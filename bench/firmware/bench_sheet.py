#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""A whole sheet through the firmware in the s51 emulator, against the plan
(never run by the unit tests: about two minutes of the chip's time, more on
the wall clock).

    make -C firmware emu && ninja -C build/default app/tactus-cli
    python3 bench/firmware/bench_sheet.py [--doc resources/samples/welcome.md] [--sheet 1]

`tactus-cli plan --json --firmware-tables` plans the document for the
firmware; `tactus-cli sim --firmware --pty --pin-trace` runs the chip and
`tactus-cli emboss` sends the job (9600 baud) until the sheet is struck.
Compares:
  * the strikes read from the pins with the plan's (sheet, hammer, carriage
    and feed step);
  * every carriage and feed step edge and every hammer going down and up
    with the plan's time, in machine cycles (emulated minus planned: one
    constant, the step interrupt compensating its latency, firmware/src/step.asm;
    edge_spread_cycles must be 0);
  * the plan's sheet time with the emulated one (from the sheet's first step
    to its last hammer going up, plus the plan's time before that first step):
    equal to the cycle.
Prints the s51 wall time. Writes bench/firmware/last-sheet.json.
"""
import argparse
import json
import os
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "firmware" / "tools"))
import fwhost  # noqa: E402

TICK_HZ = 11.0592e6 / 12


def planned_edges(sheet, gap, clock, hammer):
    """(kind, tick) of every step and hammer edge (down "H", up "h": `hammer`
    ticks later) of the sheet's passes,
    and the sheet's end: the plan's clock (s) at the sheet's start is `clock`.
    Table moves: each segment is `count` steps of one whole interval."""
    out = []

    def steps(move):
        t, ts = 0, []
        for iv, count, add in move["segments"]:
            assert add == 0 and iv % 65536 == 0, "not a table move"
            for _ in range(count):
                t += iv // 65536
                ts.append(t)
        return ts
    for p in sheet["passes"]:
        start = round(clock * TICK_HZ)
        if p["feed"]["steps"]:
            out += [("F", start + gap + t) for t in steps(p["feed"])]
        for k in p["strikes"]:
            strike = round(k["time_s"] * TICK_HZ)
            ts = steps(k["move"])
            last = strike - k["move"]["settle_ticks"]
            out += [("C", last - ts[-1] + t) for t in ts] if ts else []
            out.append(("H", strike))
            out.append(("h", strike + hammer))
        clock += p["duration_s"]
    return out, round(clock * TICK_HZ)


def pin_edges(vcd):
    out, prev = [], None
    changes, ids = fwhost.read_vcd(vcd)
    for t, ident, v in changes:
        if v is None or ids.get(ident) != "port1_value":  # the sheet number's RAM is traced too
            continue
        if prev is not None:
            rise, fall = v & ~prev, prev & ~v
            if rise & 0x01:
                out.append(("C", t))
            if rise & 0x04:
                out.append(("F", t))
            if rise & 0x30:
                out.append(("H", t))
            if fall & 0x30 and prev != 0xFF:
                out.append(("h", t))
        prev = v
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cli", default=str(ROOT / "build" / "default" / "app" / "tactus-cli"))
    ap.add_argument("--doc", default=str(ROOT / "resources" / "samples" / "welcome.md"))
    ap.add_argument("--sheet", type=int, default=1)
    ap.add_argument("--baud", type=int, default=9600)
    ap.add_argument("--fw-dir", default=str(ROOT / "firmware" / "build-emu"),
                    help="the emulator build to run (e.g. a diagnostic build)")
    a = ap.parse_args()
    fw = Path(a.fw_dir)
    ramp = fw / "ramp.json"
    gap = json.loads(ramp.read_text())["start_gap_ticks"]
    plan = json.loads(subprocess.run([a.cli, "plan", "--json", "--firmware-tables", str(ramp), a.doc],
                                     check=True, capture_output=True, text=True).stdout)
    sheet = next(s for s in plan["sheets"] if s["index"] == a.sheet)
    clock = sum(s["duration_s"] for s in plan["sheets"] if s["index"] < a.sheet)
    # The hammer pulse CONFIGURE gives the firmware (machine/controller_config.cpp).
    dwell = json.loads((ROOT / "resources" / "profiles" / "default.json").read_text())["head"]["dwell_s"]
    want_edges, sheet_end = planned_edges(sheet, gap, clock, int(dwell * TICK_HZ))
    want_strikes = [(a.sheet, k["hammer"], k["carriage_step"], p["feed_step"])
                    for p in sheet["passes"] for k in p["strikes"]]
    tmp = Path(tempfile.mkdtemp(prefix="tactus-sheet-"))
    log, vcd = tmp / "strikes.jsonl", tmp / "pins.vcd"
    sim = subprocess.Popen([a.cli, "sim", "--firmware", str(fw / "tactus-fw.ihx"), "--pty", "--strike-log", str(log),
                            "--pin-trace", str(vcd)], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    pty = sim.stdout.readline().strip()
    t0 = time.monotonic()
    host = subprocess.Popen([a.cli, "emboss", a.doc, "--device", f"pty:{pty}?baud={a.baud}", "--firmware-tables",
                             str(ramp), "--start-sheet", str(a.sheet)],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    got = []
    while host.poll() is None:
        time.sleep(1)
        got = [json.loads(l) for l in log.read_text().splitlines()] if log.exists() else []
        if len([s for s in got if s["sheet"] == a.sheet]) >= len(want_strikes) or \
                any(s["sheet"] > a.sheet for s in got):
            time.sleep(1)  # the last hammer goes up
            break
    wall = time.monotonic() - t0
    if host.poll() is None:
        host.send_signal(signal.SIGINT)
    host.wait(timeout=60)
    # The emulator build counts the receive bytes its queue dropped
    # (STATUS_REPLY byte 23, firmware/src/uart.c): asked in a session of our own.
    dropped = stack = None
    try:
        link = fwhost.Link(pty)
        try:
            link.hello(nonce=0x5A5A)
            st = link.reliable(fwhost.T_STATUS)
            dropped, stack = st.payload[23], st.payload[24]
        finally:
            link.close()
    except (OSError, TimeoutError) as e:
        print(f"no STATUS after the sheet: {e}", file=sys.stderr)
    sim.send_signal(signal.SIGTERM)
    sim.wait(timeout=60)
    got = [json.loads(l) for l in log.read_text().splitlines()]
    got_strikes = [(s["sheet"], s["hammer"], s["carriage_step"], s["feed_step"]) for s in got
                   if s["sheet"] == a.sheet]
    edges = pin_edges(vcd)
    # The sheet's edges: the job starts at this sheet, so from the first step.
    first = next(i for i, e in enumerate(edges) if e[0] in "CF")
    edges = edges[first:]
    hammer_ups = [t for k, t in edges if k == "h"]
    got_edges = edges[:len(want_edges)]
    kinds_equal = [k for k, _ in got_edges] == [k for k, _ in want_edges]
    offsets = {}
    for (_, t), (_, w) in zip(got_edges, want_edges):
        d = round(t * TICK_HZ) - w
        offsets[d] = offsets.get(d, 0) + 1
    lo = min(offsets)
    # Where the offset changes: inside a move's steps it never may (the
    # interrupt's schedule); at a phase program's start it may only grow (the
    # main loop started it late: its data or its turn came late).
    ds = [round(t * TICK_HZ) - w for (_, t), (_, w) in zip(got_edges, want_edges)]
    inside_jumps, late_starts = 0, []
    for i in range(1, len(ds)):
        if ds[i] == ds[i - 1]:
            continue
        k, kp = want_edges[i][0], want_edges[i - 1][0]
        if k == kp and k in "CF":
            inside_jumps += 1
        else:
            late_starts.append([i, k, ds[i] - ds[i - 1]])
    emulated_end = hammer_ups[len(want_strikes) - 1] * TICK_HZ if len(hammer_ups) >= len(want_strikes) else float("nan")
    # The emulated sheet: from its start (the first step's time less the
    # plan's time before it) to its last hammer going up.
    emulated_start = got_edges[0][1] * TICK_HZ - (want_edges[0][1] - round(clock * TICK_HZ))
    emulated = (emulated_end - emulated_start) / TICK_HZ
    planned = sheet["duration_s"]
    results = {
        "document": Path(a.doc).name, "sheet": a.sheet, "strikes_planned": len(want_strikes),
        "strikes_equal_plan": got_strikes == want_strikes,
        "edges_compared": len(got_edges), "edge_kinds_equal": kinds_equal,
        "edge_offsets_cycles": {str(d - lo): n for d, n in sorted(offsets.items())},
        "edge_spread_cycles": max(offsets) - lo,
        "edge_jumps_inside_moves": inside_jumps,
        "late_program_starts": late_starts,
        "planned_sheet_s": round(planned, 6), "emulated_sheet_s": round(emulated, 6),
        "sheet_time_error_pct": round(100 * (emulated / planned - 1), 4),
        "sheet_time_error_cycles": round((emulated - planned) * TICK_HZ, 1),
        "rx_bytes_dropped": dropped, "stack_high_water_bytes": stack,
        "s51_wall_s": round(wall, 1),
        "baud": a.baud,
    }
    print(json.dumps(results, indent=1))
    (ROOT / "bench" / "firmware" / "last-sheet.json").write_text(json.dumps(results, indent=1) + "\n")
    if not os.environ.get("TACTUS_KEEP_EMULATOR_DIR"):
        for f in tmp.iterdir():
            f.unlink()
        tmp.rmdir()


if __name__ == "__main__":
    main()
