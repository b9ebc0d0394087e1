#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Prints the firmware's flash and internal-RAM use from the linker's .mem and
.map files, and fails (exit 1) when it does not fit an AT89C52: more than
8,192 bytes of code, or fewer than 24 bytes of internal RAM left for the stack.

usage: check-size.py BUILD/tactus-fw   (reads tactus-fw.mem and tactus-fw.map)
"""
import re
import sys
from pathlib import Path

FLASH = 8192
IRAM = 256
MIN_STACK = 24


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: check-size.py BUILD/tactus-fw")
    base = Path(sys.argv[1])
    mem_path = base.with_suffix(".mem")
    map_path = base.with_suffix(".map")
    try:
        mem = mem_path.read_text()
    except OSError as e:
        sys.exit(f"check-size: cannot read {mem_path}: {e.strerror} (did the link run?)")
    errors = []
    m = re.search(r"ROM/EPROM/FLASH\s+0x[0-9a-fA-F]+\s+0x[0-9a-fA-F]+\s+(\d+)", mem)
    code = int(m.group(1)) if m else None
    m = re.search(r"Stack starts at: 0x([0-9a-fA-F]+) \(sp set to 0x[0-9a-fA-F]+\) with (\d+) bytes available", mem)
    stack = int(m.group(2)) if m else None
    # Internal RAM the linker placed: every area in the map that lives in it.
    used = {}
    if map_path.exists():
        for line in map_path.read_text().splitlines():
            mm = re.match(r"^(REG_BANK_\d|BSEG_BYTES|DSEG|OSEG|ISEG|IABS|DABS)\s+[0-9A-F]+\s+[0-9A-F]+\s+=\s+(\d+)\.", line)
            if mm:
                used[mm.group(1)] = used.get(mm.group(1), 0) + int(mm.group(2))
    for line in mem.splitlines():
        if line.startswith("ERROR"):
            errors.append(line.strip())
    ram_used = sum(used.values()) if used else None
    detail = ", ".join(f"{k} {v}" for k, v in sorted(used.items()))
    print(f"flash: {code if code is not None else '?'} of {FLASH} bytes"
          + (f" ({FLASH - code} free)" if code is not None else ""))
    # The stack takes what the linker left at the top of internal RAM.
    ram_used = IRAM - stack if stack is not None else None
    print(f"internal RAM: {ram_used if ram_used is not None else '?'} of {IRAM} bytes used ({detail}); "
          f"{stack if stack is not None else '?'} left for the stack (at least {MIN_STACK} required)")
    if code is None or code > FLASH:
        errors.append(f"code is {code} bytes, over the AT89C52's {FLASH}")
    if stack is None or stack < MIN_STACK:
        errors.append(f"only {stack} bytes of internal RAM left for the stack, fewer than {MIN_STACK}")
    if errors:
        for e in errors:
            print(f"check-size: FAIL: {e}", file=sys.stderr)
        sys.exit(1)
    print("check-size: fits")


if __name__ == "__main__":
    main()
