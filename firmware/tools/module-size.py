#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""What each module of the image costs: flash (code and constants) and RAM,
from the segment sizes the assembler wrote into BUILD/*.rel.

    tools/module-size.py BUILD [MODULE.rel ...]

Flash counts every code-space segment (CSEG, CONST, HOME, the GSINIT parts,
CABS); RAM the direct (DSEG), indirect (ISEG) and bit (BSEG, in bits) data a
module owns. Overlaid locals (OSEG) share one area across modules: their
largest is what the image pays. The library code the linker adds (SDCC's
startup, __mulint) is the image's total less the modules' sum."""
import pathlib
import re
import sys

CODE = re.compile(r"^(CSEG|CONST|HOME|GSINIT\d?|GSFINAL|CABS)$")


def sizes(rel):
    out = {}
    for line in rel.read_text(errors="replace").splitlines():
        m = re.match(r"^A (\S+) size ([0-9A-Fa-f]+) flags", line)
        if m:
            out[m.group(1)] = out.get(m.group(1), 0) + int(m.group(2), 16)
    return out


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    build = pathlib.Path(sys.argv[1])
    rels = [pathlib.Path(p) for p in sys.argv[2:]] or sorted(build.glob("*.rel"))
    rows = []
    for rel in rels:
        s = sizes(rel)
        code = sum(v for k, v in s.items() if CODE.match(k))
        rows.append((rel.stem, code, s.get("DSEG", 0), s.get("ISEG", 0), s.get("BSEG", 0), s.get("OSEG", 0)))
    rows.sort(key=lambda r: -r[1])
    print(f"{'module':<14}{'flash':>7}{'DSEG':>6}{'ISEG':>6}{'bits':>6}{'OSEG':>6}")
    for r in rows:
        print(f"{r[0]:<14}{r[1]:>7}{r[2]:>6}{r[3]:>6}{r[4]:>6}{r[5]:>6}")
    print(f"{'sum':<14}{sum(r[1] for r in rows):>7}{sum(r[2] for r in rows):>6}"
          f"{sum(r[3] for r in rows):>6}{sum(r[4] for r in rows):>6}{max((r[5] for r in rows), default=0):>6}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
