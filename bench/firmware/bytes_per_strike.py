#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Line bytes per strike of protocol v3 on a real plan, and the lowest baud at
which the firmware never waits for data.

    tactus-cli plan --json --firmware-tables firmware/build-emu/ramp.json \
        resources/samples/welcome.md > plan.json
    python3 bench/firmware/bytes_per_strike.py plan.json [--sheet N]

Encodes every pass of the plan as v3 pass records (tools/fwhost.py, the same
encoder the emulator tests use; split into records the firmware's ring can
in one record each), cuts the stream into DATA frames of the firmware's
largest payload, and counts the line bytes. Then it runs the firmware's timing
(table moves from build-emu/ramp.json, settle, hammer) against a link at a
given baud: a pass's feed starts once its header is in the ring, each strike
once its entry is, and bytes free as they are executed. The firmware's
schedule (docs/protocol.md, "Timing"): each move START_GAP cycles after the
event before it, the settle (the plan's) and the hammer pulse. The controller
"waits" whenever it is ready for the next header or entry and it has not
arrived. The host sends a frame when the ring has room for a full one.
"""
import argparse
import json
import math
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "firmware" / "tools"))
import fwhost  # noqa: E402

RAMP = json.loads((ROOT / "firmware" / "build-emu" / "ramp.json").read_text())
PROFILE = json.loads((ROOT / "resources" / "profiles" / "default.json").read_text())
CYCLE = 12 / 11.0592e6
RING = 47          # HELLO_REPLY of the default build (BUF_CAP 64)
MAX_PAYLOAD = 33   # ops + the 2-byte DATA check
MAX_DATA = MAX_PAYLOAD - 2
MAX_ENTRIES = 255
SETTLE = 7650      # profile::strike_timing of the default profile; the plan's when it has one
HAMMER = 3686      # 4 ms dwell
GAP = RAMP["start_gap_ticks"]
OVERHEAD = 8       # frame bytes besides the ops: SYNC LEN SEQ TYPE, CRC, DATA check


def move_cycles(tab, n):
    r = len(tab) - 1
    return sum(tab[min(k, n + 2 - k, r + 1) - 1] for k in range(1, n + 1))


def encode(plan, sheet_filter=None):
    """[(record bytes, header bytes, [entry bytes], [cycles per strike], feed cycles)] and op bytes."""
    c_spm = PROFILE["carriage"]["steps_per_mm"]
    f_grid = RAMP["feed"]["grid_steps"]
    c_grid = RAMP["carriage"]["grid_steps"]
    off = PROFILE["head"]["concave_offset_mm"]
    ctab, ftab = RAMP["carriage"]["intervals"], RAMP["feed"]["intervals"]
    records = []
    other = len(fwhost.job_begin(1)) + len(fwhost.job_end()) + len(fwhost.home())
    strikes = 0
    pos = 0  # carriage grid units
    c_neg = True
    for sheet in plan["sheets"]:
        if sheet_filter and sheet["index"] != sheet_filter:
            continue
        other += len(fwhost.sheet_begin(1)) + len(fwhost.sheet_end())
        for p in sheet["passes"]:
            back = p["side"] == "back"
            targets = []
            for x in p["strikes_mm"]:
                steps = (x - (off if back else 0)) * c_spm
                units = steps / c_grid
                if abs(units - round(units)) > 1e-6:
                    raise SystemExit(f"strike at {x} mm is not on the {c_grid}-step grid")
                targets.append(round(units))
            feed = p["feed_steps"]
            if feed % f_grid:
                raise SystemExit(f"feed of {feed} steps is not on the {f_grid}-step grid")
            feed_units = feed // f_grid
            for c in range(0, len(targets), MAX_ENTRIES):
                chunk = targets[c:c + MAX_ENTRIES]
                first = chunk[0] - pos
                entries = [(back, 0)] + [(back, abs(b - a)) for a, b in zip(chunk, chunk[1:])]
                sweep_neg = len(chunk) > 1 and chunk[1] < chunk[0]
                rec = fwhost.pass_record(feed_units if c == 0 else 0, abs(first), entries,
                                         sweep_neg=sweep_neg, first_neg=first < 0, back=back, no_feed=c > 0)
                # Entry sizes and the time each strike takes (move + settle + hammer).
                sizes = [2 if (i and d >= 64) else 1 for i, (_, d) in enumerate(entries)]
                times = []
                prev = pos
                for t in chunk:
                    n = abs(t - prev) * c_grid
                    neg = t < prev
                    if n and neg != c_neg:
                        n += RAMP["carriage"]["backlash_steps"]
                    if n:
                        c_neg = neg
                    times.append((GAP + move_cycles(ctab, n) if n else 0) + SETTLE + HAMMER)
                    prev = t
                pos = chunk[-1]
                fsteps = abs(feed_units) * f_grid if c == 0 else 0
                header = len(rec) - sum(sizes) - 2
                records.append((len(rec), header, sizes, times, GAP + move_cycles(ftab, fsteps) if fsteps else 0))
                strikes += len(chunk)
    return records, other, strikes


def simulate(records, baud):
    """Seconds the controller waited (after the first pass header arrived),
    the job's length, frames and bytes sent."""
    byte_s = 10 / baud
    units = []  # (stream end offset, bytes, cycles to execute, freed when done?)
    off = 0
    for size, header, sizes, times, feed in records:
        off += header
        units.append((off, header, feed))
        for b, c in zip(sizes, times):
            off += b
            units.append((off, b, c))
    total = off
    frees = []   # (time, bytes)
    sent = 0
    line_t = 0.0
    arrived_to = 0       # stream bytes whole in the ring
    arrival = []         # (end offset, time)
    frames = 0
    t = 0.0
    waited = 0.0
    first = True
    for end, nbytes, cycles in units:
        while arrived_to < end:
            chunk = min(MAX_DATA, total - sent)
            frees.sort()
            t_send = line_t
            freed = sum(b for ft, b in frees if ft <= t_send)
            if sent - freed + chunk > RING:
                for ft, b in frees:
                    if ft <= t_send:
                        continue
                    freed += b
                    if sent - freed + chunk <= RING:
                        t_send = ft
                        break
                else:
                    # No full frame fits before the controller frees more,
                    # and it cannot go on without these bytes: send what fits.
                    chunk = RING - (sent - freed)
                    if chunk <= 0:
                        raise RuntimeError("deadlock: ring full of unexecutable bytes")
            line_t = t_send + (chunk + OVERHEAD) * byte_s
            sent += chunk
            frames += 1
            arrived_to = sent
            arrival.append((sent, line_t))
        ready = next(at for e, at in arrival if e >= end)
        if first:
            t = max(t, ready)
            first = False
        elif ready > t:
            waited += ready - t
            t = ready
        t += cycles * CYCLE
        frees.append((t, nbytes))
    return waited, t, frames, sent


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("plan")
    ap.add_argument("--sheet", type=int)
    a = ap.parse_args()
    plan = json.loads(Path(a.plan).read_text())
    global SETTLE
    settles = {k["move"]["settle_ticks"] for sh in plan["sheets"] for p in sh["passes"] for k in p["strikes"]}
    if plan.get("protocol") == 3 and len(settles) == 1:
        SETTLE = settles.pop()  # planned for the firmware: its CONFIGURE settle
    records, other, strikes = encode(plan, a.sheet)
    stream = sum(r[0] for r in records) + other
    frames = math.ceil(stream / MAX_DATA)
    line = stream + frames * OVERHEAD  # full frames
    print(f"{strikes} strikes, {len(records)} pass records, {stream} stream bytes, {frames} frames, "
          f"{line} line bytes: {line / strikes:.2f} line bytes per strike "
          f"({stream / strikes:.2f} stream bytes)")
    for baud in (1200, 2400, 4800, 9600):
        w, t, nf, nb = simulate(records, baud)
        line = nb + nf * OVERHEAD + other
        print(f"{baud:6d} baud: waited {w:.3f} s of {t:.1f} s; {nf} frames as sent: "
              f"{line / strikes:.2f} line bytes per strike")
    lo, hi = 100, 9600
    if simulate(records, hi)[0] > 0:
        print("waits even at 9600 baud")
        return
    while hi - lo > 10:
        mid = (lo + hi) // 2
        if simulate(records, mid)[0] > 0:
            lo = mid
        else:
            hi = mid
    print(f"lowest baud with no wait: about {hi}")


if __name__ == "__main__":
    main()
