#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Puts a NOP first in the low-priority interrupt vectors SDCC wrote.

    tools/vectors.py BUILD/main.asm

SDCC writes each vector as `ljmp _isr` and 5 bytes of padding. In s51 the
step interrupt (timer 2, high priority) loses to a low-priority request
pending at the same instruction boundary: s51 takes the first pending source
in its own list (INT0, timer 0, INT1, timer 1, the UART, then timer 2), not
the highest priority, and runs one instruction of it before the step
interrupt preempts it. That instruction is the vector's; as a 2-cycle LJMP it
put the step interrupt 6-7 cycles late after a RETI, past the 5 cycles it
compensates (step.asm, LAT_MAX; firmware/README.md, "Step timing"). A
1-cycle NOP first keeps it within them. Fails when the vectors are not as
expected.
"""
import re
import sys

LOW = ("_strobe_isr", "_uart_isr")


def main():
    path = sys.argv[1]
    text = open(path).read()
    for isr in LOW:
        pat = re.compile(r"^\tljmp\t" + isr + r"\n\t\.ds\t5\n", re.M)
        text, n = pat.subn("\tnop\n\tljmp\t" + isr + "\n\t.ds\t4\n", text)
        if n != 1:
            sys.exit(f"vectors.py: {path}: the vector `ljmp {isr}` with 5 bytes of padding not found")
    open(path, "w").write(text)


if __name__ == "__main__":
    main()
