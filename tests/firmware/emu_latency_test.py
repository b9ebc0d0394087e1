#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Every step and hammer edge on its cycle while low-priority interrupts
collide with the step interrupt (s51, deterministic: no pty, no host).

    make -C firmware probe && python3 tests/firmware/emu_latency_test.py [PROBE.ihx]

tests/firmware/latency_probe.c runs the same block of moves (feed, long and
short carriage moves, a hammer down and up) five times: alone, then with TI
(the UART interrupt), IE0 (the strobe interrupt) and both raised at every
alignment with the timer events, then with a byte sent every 4th event. The
UART receives all the while (s51 reads a file at 9600 baud: RI). The edges
of every block must equal block 0's to the machine cycle, measured from the
block's first edge, and the blocks must start the same time after the block
before.

Why (firmware/README.md, "Step timing"): s51 accepts the first pending
source in its own list (INT0, timer 0, INT1, timer 1, the UART, then timer 2),
not the highest priority, and runs one instruction of the low-priority
interrupt before the step interrupt preempts it: the vector's. After a RETI
and the instruction after it, that put the step interrupt 6 cycles past its
minimum, past the 5 it compensates (step.asm, LAT_MAX), and the edge 2 cycles
late. On the firmware before the fix (vectors of a 2-cycle LJMP) this test
fails: a feed edge +2 cycles in the IE0 block, a feed and a carriage edge +2
in the IE0-and-TI block (3 of 22,695 edges). With a NOP first in the
low-priority vectors (tools/vectors.py) all are exact.
"""
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "firmware" / "tools"))
import fwhost  # noqa: E402

PROBE = Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "firmware" / "build-probe" / "latency-probe.ihx"
CYCLE = 12 / 11.0592e6
BLOCKS = 5


def run_probe(tmp):
    vcd = tmp / "pins.vcd"
    cmds = tmp / "cmds"
    cmds.write_text(
        f'file "{PROBE}"\n'
        f'set hw vcd[0] output "{vcd}"\n'
        "set hw vcd[0] add port_1_cfg 2\n"
        "set hw vcd[0] start\n"
        "run\n"
        "kill\n")
    # The UART receives all the while, at 9600 baud (RI from the emulated
    # line: s51 reads a file as fast as the baud lets it).
    rx = tmp / "rx.bin"
    rx.write_bytes(bytes((i * 37 + 11) & 0xFF for i in range(40000)))
    with open(tmp / "s51.log", "w") as log:
        subprocess.run(["s51", "-t", "C52", "-X", "11.0592M", "-b", "-I", "if=xram[0xffff]",
                        "-S", f"in={rx},out=/dev/null", "-e", "uart0_check_often=1", "-C", str(cmds)],
                       stdin=subprocess.DEVNULL, stdout=log, stderr=subprocess.STDOUT, timeout=600, check=False)
    return vcd


def edges(vcd):
    """(kind, cycle) of every rising step edge and every hammer edge."""
    changes, _ = fwhost.read_vcd(vcd)
    out, prev = [], None
    for t, _, v in changes:
        if v is None:
            continue
        if prev is None:
            prev = v
            continue
        rise, fall = v & ~prev, prev & ~v
        for bit, kind in ((0x01, "C"), (0x04, "F"), (0x30, "H")):
            if rise & bit:
                out.append((kind, round(t / CYCLE)))
        if fall & 0x30 and out:  # not the reset's high pins going low
            out.append(("h", round(t / CYCLE)))
        prev = v
    return out


def main():
    if not PROBE.exists():
        sys.exit(f"{PROBE} missing: run make -C firmware probe")
    with tempfile.TemporaryDirectory(prefix="tactus-latency-") as d:
        tmp = Path(d)
        got = edges(run_probe(tmp))
        if os.environ.get("TACTUS_LATENCY_KEEP"):
            (Path(os.environ["TACTUS_LATENCY_KEEP"])).write_text("\n".join(f"{k} {c}" for k, c in got))
    if len(got) % BLOCKS:
        sys.exit(f"FAIL: {len(got)} edges, not {BLOCKS} equal blocks")
    n = len(got) // BLOCKS
    blocks = [got[i * n:(i + 1) * n] for i in range(BLOCKS)]
    ref = blocks[0]
    fails = 0
    names = ["alone", "TI raised", "IE0 raised", "IE0 and TI raised", "bytes sent"]
    starts = []
    for b, blk in enumerate(blocks):
        if [k for k, _ in blk] != [k for k, _ in ref]:
            sys.exit(f"FAIL: block {b} has other edges than block 0")
        offs = [(c - blk[0][1]) - (r - ref[0][1]) for (_, c), (_, r) in zip(blk, ref)]
        late = [(i, o) for i, o in enumerate(offs) if o]
        worst = max((abs(o) for o in offs), default=0)
        print(f"block {b} ({names[b]}): {len(blk)} edges, {len(late)} off, max deviation {worst} cycles")
        for i, o in late[:5]:
            print(f"  edge {i} ({blk[i][0]}) {o:+d} cycles")
        fails += len(late)
        if b:
            starts.append(blk[0][1] - blocks[b - 1][-1][1])
    if len(set(starts)) > 1:
        print(f"FAIL: blocks start at different offsets from the block before: {starts}")
        fails += 1
    if fails:
        sys.exit(f"FAIL: {fails} edges off their cycle")
    print(f"PASS: {BLOCKS} x {n} edges, every one on its cycle")


if __name__ == "__main__":
    main()
