#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Generates the firmware's motion tables from a printer profile.

The controller does not compute trajectories: it walks step-interval tables
kept in flash. This script builds them from the profile's carriage and feed
limits when the firmware is built, and gives them an identity that the
firmware reports in HELLO_REPLY, so a host with another profile is refused.

Each table is the acceleration half of the sources' S-curve from rest to
v_max: acceleration rises as a smoothstep over dt_a and falls back over dt_a
(docs/motion.md). Step k (1-based) fires when the position crosses k - 0.5
steps; T[i] is the interval, in machine cycles (timer ticks, 921 600 Hz),
before step i + 1, and T[R] is the cruise interval. A move of n steps uses
T[min(k, n + 2 - k, R + 1) - 1] before step k (firmware/PROTOCOL-v3.md).

Outputs (into OUTDIR): ramp.h, ramp_tables.c, ramp_up.inc, ramp_dn.inc and
ramp.json (the same tables for the host's planner).
"""
import json
import math
import sys
import zlib
from functools import reduce
from pathlib import Path

TICK_HZ = 11_059_200 / 12
# The shortest interval the fast step-interrupt paths (step.asm) keep exact:
# a short move's turn and the switch to cruise end 46 cycles after their
# timer event (counted), and the next event's latency (that overrun + the
# instruction after RETI, up to 2) must stay within LAT_MAX (5): 43, and one
# cycle to spare. Was 40 before the latency compensation (firmware/README.md).
MIN_CRUISE_TICKS = 44
# The slow (16-bit) path, used for the feed and for intervals over 256 ticks:
# 120 before the compensation moved every edge 15 cycles later.
MIN_SLOW_TICKS = 136
FAST_BIAS = 7          # bytes between the MOVC in step.asm and its table
MAX_FAST_ENTRIES = 255 - FAST_BIAS + 1


class ProfileError(Exception):
    pass


# Machine cycles from the last timer event of one phase to the start of a
# move (its first step comes START_GAP + T[0] after that event): the time the
# main loop is given to notice the event and build the move's phases. The
# firmware schedules every phase from the timer (step.asm, timer_go), so this
# is exact, not a measured latency; the host's planner adds it (ramp.json).
START_GAP_TICKS = 3000


def s_curve_table(axis, name):
    spm = axis["steps_per_mm"]
    v = axis["v_max_mm_s"]
    a = axis["a_max_mm_s2"]
    j = axis["j_max_mm_s3"]
    for key in ("steps_per_mm", "v_max_mm_s", "a_max_mm_s2", "j_max_mm_s3"):
        if not axis[key] > 0:
            raise ProfileError(f"{name}.{key} must be positive")
    # Peak acceleration alpha_d, ramp half-time dt_a: alpha_d * dt_a = v and
    # the peak jerk 1.5 alpha_d / dt_a within j.
    alpha = min(a, math.sqrt(v * j / 1.5))
    dta = v / alpha
    # Position over the ramp, integrated finely (1/64 tick).
    dt = 1 / TICK_HZ / 64
    t = x = vel = 0.0
    times = []
    total = 2 * dta
    target = 0.5 / spm
    while t < total:
        tau = t / dta
        if tau <= 1:
            acc = alpha * (3 * tau**2 - 2 * tau**3)
        else:
            u = tau - 1
            acc = alpha * (1 - (3 * u**2 - 2 * u**3))
        vel += acc * dt
        x += vel * dt
        t += dt
        while x >= target:
            times.append(t * TICK_HZ)
            target += 1 / spm
    cruise = round(TICK_HZ / (v * spm))
    ticks = [round(tt) for tt in times]
    intervals = [ticks[0]] + [b - a_ for a_, b in zip(ticks, ticks[1:])]
    # Near the top the ramp's intervals must not undercut the cruise interval.
    intervals = [max(i, cruise) for i in intervals]
    if cruise > 65535 or intervals[0] > 65535:
        raise ProfileError(f"{name}.v_max_mm_s or {name}.a_max_mm_s2: a step interval exceeds the 16-bit timer")
    return intervals + [cruise], cruise, alpha, dta


def grid_steps(values, spm, names, axis):
    steps = []
    for v, n in zip(values, names):
        s = v * spm
        if abs(s - round(s)) > 1e-6:
            raise ProfileError(f"{n} = {v} mm is not a whole number of {axis} steps ({s:.3f}); "
                               "the firmware moves on a grid of whole steps")
        if round(s):
            steps.append(abs(round(s)))
    return reduce(math.gcd, steps)


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: gen-ramp.py PROFILE.json OUTDIR")
    prof = json.loads(Path(sys.argv[1]).read_text())
    out = Path(sys.argv[2])
    out.mkdir(parents=True, exist_ok=True)
    try:
        c_tab, c_cruise, c_alpha, c_dta = s_curve_table(prof["carriage"], "carriage")
        f_tab, f_cruise, _, _ = s_curve_table(prof["feed"], "feed")
        if c_cruise < MIN_CRUISE_TICKS:
            rate = TICK_HZ / c_cruise
            limit = TICK_HZ / MIN_CRUISE_TICKS
            raise ProfileError(
                f"carriage.v_max_mm_s: {prof['carriage']['v_max_mm_s']} mm/s x "
                f"{prof['carriage']['steps_per_mm']} steps/mm = {rate:.0f} steps/s; "
                f"the 89C52 step interrupt sustains at most {limit:.0f} steps/s")
        if f_cruise < MIN_SLOW_TICKS:
            limit = TICK_HZ / MIN_SLOW_TICKS
            raise ProfileError(
                f"feed.v_max_mm_s: {prof['feed']['v_max_mm_s']} mm/s x {prof['feed']['steps_per_mm']} "
                f"steps/mm exceeds the {limit:.0f} steps/s the feed's interrupt path sustains")
        # Entries below K need both reload bytes (interval over 256 ticks).
        # At least two: motion.c preloads T[0] and T[1] from the 16-bit table.
        k = max(2, next(i for i, v in enumerate(c_tab) if v <= 256))
        fast = c_tab[k:]
        if len(fast) > MAX_FAST_ENTRIES:
            raise ProfileError(
                f"carriage.a_max_mm_s2 / carriage.j_max_mm_s3: the ramp needs {len(fast)} table "
                f"entries above 3600 steps/s; the firmware holds {MAX_FAST_ENTRIES}")
        g = prof["geometry"]
        p = prof["paper"]
        h = prof["head"]
        c_grid = grid_steps(
            [g["cell_pitch_mm"], g["dot_pitch_mm"], g["back_offset_x_mm"], h["concave_offset_mm"],
             p["margin_left_mm"], p["width_mm"]],
            prof["carriage"]["steps_per_mm"],
            ["geometry.cell_pitch_mm", "geometry.dot_pitch_mm", "geometry.back_offset_x_mm",
             "head.concave_offset_mm", "paper.margin_left_mm", "paper.width_mm"], "carriage")
        f_grid = grid_steps(
            [g["line_pitch_mm"], g["dot_pitch_mm"], g["back_offset_y_mm"], p["margin_top_mm"]],
            prof["feed"]["steps_per_mm"],
            ["geometry.line_pitch_mm", "geometry.dot_pitch_mm", "geometry.back_offset_y_mm",
             "paper.margin_top_mm"], "feed")
        if c_grid > 255 or f_grid > 255:
            raise ProfileError("geometry: the dot grid is over 255 steps")
    except ProfileError as e:
        sys.exit(f"{sys.argv[1]}: {e}")
    except KeyError as e:
        sys.exit(f"{sys.argv[1]}: missing field {e}")

    c_back = round(prof["carriage"]["backlash_mm"] * prof["carriage"]["steps_per_mm"])
    f_back = round(prof["feed"]["backlash_mm"] * prof["feed"]["steps_per_mm"])
    blob = json.dumps([c_tab, f_tab, c_grid, f_grid, c_back, f_back]).encode()
    ident = zlib.crc32(blob) & 0xFFFFFFFF
    idb = ident.to_bytes(4, "big")

    def reload(i):
        return 65536 - i

    (out / "ramp.h").write_text(f"""/* Generated by tools/gen-ramp.py from {Path(sys.argv[1]).name}: do not edit. */
#ifndef TACTUS_FW_RAMP_H
#define TACTUS_FW_RAMP_H
#include "fw.h"
#define RAMP_R {len(c_tab) - 1}       /* carriage ramp steps; T[R] is the cruise interval */
#define RAMP_K {k}                    /* entries below K use the 16-bit table */
#define RAMP_FAST_BIAS {FAST_BIAS}
#define FEED_R {len(f_tab) - 1}
#define C_GRID {c_grid}               /* carriage steps per grid unit */
#define F_GRID {f_grid}               /* feed steps per grid unit */
#define C_BACKLASH {c_back}
#define F_BACKLASH {f_back}
#define TABLE_ID 0x{ident:08X}UL
#define START_GAP {START_GAP_TICKS}u        /* cycles from a phase's last event to a move's start */
extern FW_CODE uint8_t ramp_slow[{2 * (k + 1)}];      /* T[0..K] as big-endian reloads */
extern FW_CODE uint8_t feed_table[{2 * len(f_tab)}]; /* feed T[0..FEED_R] */
#endif
""")
    def rows(vals):
        return ",\n".join("    " + ", ".join(f"0x{v:02X}" for v in vals[i:i + 12]) for i in range(0, len(vals), 12))
    # T[K] too: the step before the fast ascent writes its high byte (0xFF),
    # so the fast ascent writes low bytes only (step.asm).
    slow = [b for i in c_tab[:k + 1] for b in reload(i).to_bytes(2, "big")]
    feed = [b for i in f_tab for b in reload(i).to_bytes(2, "big")]
    (out / "ramp_tables.c").write_text(f"""/* Generated by tools/gen-ramp.py: do not edit. */
#include "ramp.h"
#include "link.h"
FW_CODE uint8_t ramp_slow[{len(slow)}] = {{
{rows(slow)}
}};
FW_CODE uint8_t feed_table[{len(feed)}] = {{
{rows(feed)}
}};
FW_CODE uint8_t fw_table_id[4] = {{0x{idb[0]:02X}, 0x{idb[1]:02X}, 0x{idb[2]:02X}, 0x{idb[3]:02X}}};
""")
    lows = [reload(i) & 0xFF for i in fast]
    inc = "".join(f"        .db {', '.join(f'0x{v:02X}' for v in lows[i:i + 12])}\n" for i in range(0, len(lows), 12))
    (out / "ramp_up.inc").write_text("; Generated by tools/gen-ramp.py: reload low bytes of T[K..R]\n" + inc)
    # The whole fast descent (after a cruise), as step.asm switches to it inline.
    dn = len(c_tab) - 1 - k
    (out / "ramp_eq.inc").write_text(
        "; Generated by tools/gen-ramp.py: the fast descent of a whole ramp\n"
        f"RAMP_DN_CL = {dn & 0xFF}\nRAMP_DN_CH = {((dn - 1) >> 8) + 1}\nRAMP_DN_TOP = {FAST_BIAS + dn - 1}\n")
    (out / "ramp_dn.inc").write_text("; Generated by tools/gen-ramp.py: reload low bytes of T[K..R]\n" + inc)
    (out / "ramp.json").write_text(json.dumps({
        "table_id": f"{ident:08x}", "carriage": {"intervals": c_tab, "grid_steps": c_grid, "backlash_steps": c_back},
        "feed": {"intervals": f_tab, "grid_steps": f_grid, "backlash_steps": f_back},
        "fast_from": k, "start_gap_ticks": START_GAP_TICKS}, indent=1))
    ramp_mm = sum(1 for _ in c_tab[:-1]) / prof["carriage"]["steps_per_mm"]
    print(f"ramp: carriage {len(c_tab) - 1} steps ({ramp_mm:.2f} mm, {sum(c_tab[:-1]) / TICK_HZ * 1000:.1f} ms), "
          f"cruise {c_cruise} ticks ({TICK_HZ / c_cruise:.0f} steps/s), first {c_tab[0]} ticks; "
          f"feed {len(f_tab) - 1} steps, cruise {f_cruise} ticks; grid {c_grid}/{f_grid} steps; id {ident:08x}")


if __name__ == "__main__":
    main()
