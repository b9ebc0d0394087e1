#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Worst-case stack depth of the firmware, from the assembly SDCC wrote
(BUILD/*.asm) and the hand-written step interrupt (BUILD/step.asm).

Every function's cost is the most stack it can hold at once: its pushes
(counted in program order, which SDCC keeps balanced on every path) plus,
at each call, the 2 bytes of the return address and the callee's own cost.
A tail jump (ljmp to another function) adds the callee's cost without a
return address. An interrupt costs its 2-byte return address plus its body.

The 89C52 nests at most one interrupt of each priority level on top of the
main loop: the worst case is main's deepest chain, plus the deepest
low-priority interrupt (serial, strobe), plus the deepest high-priority one
(timer 2, PT2 = 1). The figure is printed against the bytes the linker left
for the stack (BUILD/tactus-fw.mem), and the script fails (exit 1) when
fewer than MARGIN bytes would be left.

usage: stack-depth.py BUILD [--margin N] [--verbose]
"""
import argparse
import re
import sys
from pathlib import Path

HIGH = {"_t2_isr"}               # PT2 = 1 (motion.c)
LOW = {"_uart_isr", "_strobe_isr"}
ENTRY = "_main"

LABEL = re.compile(r"^([A-Za-z_][A-Za-z0-9_]*):")
LOCAL = re.compile(r"^[0-9]+\$:")
INSN = re.compile(r"^\s+([a-z]+)\s*([^;]*)")
# SDCC library routines linked in without their source here: the most stack
# each holds (read from /usr/share/sdcc/lib/src, small model, not reentrant).
LIBRARY = {"__mulint": 1}  # _mulint.c: one push b


def parse(files):
    """{function: [(op, arg), ...]} in program order. A function runs from its
    label (a global name starting with '_', or any named label that an lcall
    or ljmp reaches, such as step.asm's slow and nextph_isr) to the next one;
    local labels (123$:) are folded into it. A jump into another function is
    a tail call: that function's stack counts on top of the jumper's."""
    called = set()
    for f in files:
        for line in f.read_text().splitlines():
            m = re.match(r"^(?:\S+:)?\s+(?:[la]call|ljmp)\s+([A-Za-z_][A-Za-z_0-9]*)\s*(?:;.*)?$", line)
            if m:
                called.add(m.group(1))
    funcs = {}
    for f in files:
        cur = None
        area_code = False
        for line in f.read_text().splitlines():
            s = line.strip()
            if s.startswith(".area"):
                area_code = bool(re.match(r"\.area\s+(CSEG|HOME|GSINIT|GSFINAL)", s))
                cur = None
                continue
            if not area_code:
                continue
            m = LABEL.match(line)
            if m and (m.group(1).startswith("_") or m.group(1) in called):
                cur = m.group(1)
                funcs.setdefault(cur, [])
            if m or LOCAL.match(line):
                line = " " + line.split(":", 1)[1]  # the instruction on the label's line
            m = INSN.match(line)
            if m and cur is not None:
                funcs[cur].append((m.group(1), m.group(2).strip()))
    return funcs


MASK = {"_ET2", "ET2", "_EA", "EA"}  # clr masks the step interrupt, setb unmasks it


def costs(funcs):
    """Per function: D, the most stack it holds at any point; U, the most it
    holds at a point where the step interrupt may come (not between a clr ET2
    or clr EA and the setb after it, in program order); and whether it (or
    anything it calls) unmasks. A callee called while masked counts with its
    U only if it unmasks itself. Each with its deepest chain."""
    memo = {}

    def cost(name, stack=()):
        if name in memo:
            return memo[name]
        if name in stack:
            sys.exit(f"stack-depth: recursion through {' -> '.join(stack + (name,))}")
        body = funcs.get(name)
        if body is None:
            c = LIBRARY.get(name, 0)
            memo[name] = (c, [], c, [], False)
            return memo[name]
        depth = 0
        masked = False
        unmasks = False
        d, dp, u, up = 0, [], 0, []
        for op, arg in body:
            callee = None
            if op == "push":
                depth += 1
                if depth > d:
                    d, dp = depth, []
                if not masked and depth > u:
                    u, up = depth, []
            elif op == "pop":
                depth -= 1
            elif op in ("clr", "setb") and arg in MASK:
                masked = op == "clr"
                unmasks = unmasks or op == "setb"
            elif op in ("lcall", "acall"):
                callee, extra = arg, 2
            elif op in ("ljmp", "ajmp", "sjmp") and arg in funcs and arg != name:
                callee, extra = arg, 0
            if callee is None:
                continue
            cd, cdp, cu, cup, cun = cost(callee, stack + (name,))
            unmasks = unmasks or cun
            if depth + extra + cd > d:
                d, dp = depth + extra + cd, [callee] + cdp
            if (not masked or cun) and depth + extra + cu > u:
                u, up = depth + extra + cu, [callee] + cup
        memo[name] = (d, dp, u, up, unmasks)
        return memo[name]

    for n in funcs:
        cost(n)
    return memo


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build")
    ap.add_argument("--margin", type=int, default=0)
    ap.add_argument("--verbose", action="store_true")
    a = ap.parse_args()
    build = Path(a.build)
    files = sorted(build.glob("*.asm"))
    if not files:
        sys.exit(f"stack-depth: no .asm files in {build}")
    funcs = parse(files)
    memo = costs(funcs)
    unknown = sorted({arg for body in funcs.values() for op, arg in body
                      if op in ("lcall", "acall") and arg not in funcs and arg not in LIBRARY})
    if unknown:
        print(f"stack-depth: WARNING: calls without a body here, counted as 0: {', '.join(unknown)}")
    # MUL AB and DIV AB take 4 cycles and lengthen the step interrupt's
    # latency past what step.asm compensates; SDCC's __mul*/__div*/__mod*
    # routines use them.
    slow = sorted({f"{name}: {op} {arg}".strip() for name, body in funcs.items() for op, arg in body
                   if op in ("mul", "div") or (op in ("lcall", "acall", "ljmp") and
                                               arg.startswith(("__mul", "__div", "__mod")))})
    if slow:
        sys.exit("stack-depth: MUL or DIV in the image (4 cycles: the step interrupt's latency "
                 "compensation covers 0-3, step.asm): " + "; ".join(slow))

    def chain(name, p):
        return " -> ".join([name] + p)

    lo = max(LOW, key=lambda n: memo[n][0])
    hi = max(HIGH, key=lambda n: memo[n][0])
    d_main, dp_main, u_main, up_main, _ = memo[ENTRY]
    lo_c, hi_c = memo[lo][0] + 2, memo[hi][0] + 2  # + the interrupt's return address
    total = max(u_main + lo_c + hi_c, d_main + lo_c)
    print("worst stack depth, bytes above the stack's start:")
    print(f"  main loop, step interrupt enabled {u_main:3d} B  {chain(ENTRY, up_main)}")
    print(f"  main loop, anywhere               {d_main:3d} B  {chain(ENTRY, dp_main)}")
    print(f"  low-priority interrupt            {lo_c:3d} B  {chain(lo, memo[lo][1])}")
    print(f"  step interrupt (high priority)    {hi_c:3d} B  {chain(hi, memo[hi][1])}")
    print(f"  worst: max({u_main} + {lo_c} + {hi_c}, {d_main} + {lo_c}) = {total} B")
    if a.verbose:
        for n in sorted(funcs, key=lambda n: -memo[n][0]):
            print(f"    D {memo[n][0]:3d}  U {memo[n][2]:3d}  {n}")
    avail = None
    mem = build / "tactus-fw.mem"
    if mem.exists():
        m = re.search(r"with (\d+) bytes available", mem.read_text())
        avail = int(m.group(1)) if m else None
    if avail is None:
        print(f"  total {total} B")
        return
    left = avail - total
    print(f"  total {total} B of {avail} B left by the linker: {left} B spare (at least {a.margin} required)")
    if left < a.margin:
        print(f"stack-depth: FAIL: the worst case needs {total} B, {avail} B are there", file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
