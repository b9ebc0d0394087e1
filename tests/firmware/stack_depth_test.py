#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""firmware/tools/stack-depth.py on small hand-written programs in SDCC's
assembly layout, with the depths worked out by hand: pushes, calls, tail
jumps, code run with the step interrupt masked, the sum over the two
interrupt levels, and the margin check against the linker's .mem.

    python3 tests/firmware/stack_depth_test.py
"""
import subprocess
import sys
import tempfile
from pathlib import Path

TOOL = Path(__file__).resolve().parents[2] / "firmware" / "tools" / "stack-depth.py"
failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL:", what)


def run(files, avail, margin):
    with tempfile.TemporaryDirectory() as d:
        for name, text in files.items():
            (Path(d) / name).write_text(text)
        (Path(d) / "tactus-fw.mem").write_text(
            f"Stack starts at: 0xE7 (sp set to 0xE6) with {avail} bytes available.\n")
        r = subprocess.run([sys.executable, str(TOOL), d, "--margin", str(margin)],
                           capture_output=True, text=True)
        return r.returncode, r.stdout + r.stderr


MAIN = """\
\t.area CSEG    (CODE)
_main:
\tlcall\t_deep
00101$:\tlcall\t_masked
\tsjmp\t00101$
_deep:
\tpush\tacc
\tlcall\t_leaf
\tpop\tacc
\tljmp\t_leaf2
_leaf:
\tpush\tar0
\tpush\tpsw
\tpop\tpsw
\tpop\tar0
\tret
_leaf2:
\tpush\tacc
\tpush\tb
\tpush\tdpl
\tpop\tdpl
\tpop\tb
\tpop\tacc
\tret
_masked:
\tclr\t_ET2
\tlcall\t_nest
\tsetb\t_ET2
\tret
_nest:
\tlcall\t_leaf
\tlcall\t_leaf
\tret
_uart_isr:
\tpush\tacc
\tpush\tpsw
\tpop\tpsw
\tpop\tacc
\treti
_strobe_isr:
\tpush\tacc
\tpop\tacc
\treti
"""
# main -> deep: 2 + max(1 + 2 + leaf 2, 1 - 1 + leaf2 3) = 2 + 5 = 7, step
# interrupt possible everywhere there: U 7. main -> masked -> nest -> leaf:
# 2 + 2 + 2 + 2 = 8, with ET2 off: D 8, U stays 7.
# Old shape of the step interrupt: a phase change called under the slow
# path's four pushes; the phase loader pushes three: 2 + 4 + 2 + 3 = 11.
T2_CALL = """\
\t.area CSEG    (CODE)
_t2_isr:
\tjb\t_m_slow, 2$
\treti
2$:\tljmp\tslow
slow:\tpush\tPSW
\tpush\tACC
\tpush\tDPL
\tpush\tDPH
\tdjnz\t_c_cl, 60$
\tlcall\t_nextph
60$:\tpop\tDPH
\tpop\tDPL
\tpop\tACC
\tpop\tPSW
\treti
_nextph:
\tpush\tPSW
\tpush\tACC
\tpush\t0
\tpop\t0
\tpop\tACC
\tpop\tPSW
\tret
"""
# The shape it has now: restore, then jump to a loader that returns from the
# interrupt itself: max(2 + 4, 2 + 0 + 3) = 6.
T2_JUMP = T2_CALL.replace("\tlcall\t_nextph\n", "\tpop\tDPH\n\tpop\tDPL\n\tpop\tACC\n\tpop\tPSW\n"
                          "\tljmp\tnextph_isr\n").replace(
    "_nextph:", "nextph_isr:\n\tpush\tPSW\n\tpush\tACC\n\tpush\t0\n\tpop\t0\n\tpop\tACC\n\tpop\tPSW\n\treti\n_nextph:")


def main():
    code, out = run({"main.asm": MAIN, "step.asm": T2_CALL}, avail=25, margin=0)
    print(out)
    check("main loop, step interrupt enabled   7 B  _main -> _deep -> _leaf" in out, "U of main is 7 through deep")
    check("main loop, anywhere                 8 B  _main -> _masked -> _nest -> _leaf" in out,
          "D of main is 8 through the masked call")
    check("low-priority interrupt              4 B  _uart_isr" in out, "the deeper low interrupt: 2 + 2")
    check("step interrupt (high priority)     11 B  _t2_isr -> slow -> _nextph" in out,
          "the old phase change: 2 + 4 + 2 + 3")
    check("worst: max(7 + 4 + 11, 8 + 4) = 22 B" in out, "the sum over both levels")
    check(code == 0 and "3 B spare" in out, "22 of 25 fits with 3 to spare")
    code, out = run({"main.asm": MAIN, "step.asm": T2_CALL}, avail=23, margin=2)
    check(code == 1 and "FAIL: the worst case needs 22 B, 23 B are there" in out,
          f"1 byte to spare fails a margin of 2 (exit {code})")
    code, out = run({"main.asm": MAIN, "step.asm": T2_JUMP}, avail=25, margin=2)
    print(out)
    check("step interrupt (high priority)      6 B  _t2_isr -> slow" in out, "the phase change by a jump: 6")
    check(code == 0 and "worst: max(7 + 4 + 6, 8 + 4) = 17 B" in out, "and the sum with it")
    # MUL AB and DIV AB take 4 cycles, past the step interrupt's latency
    # compensation (step.asm): the tool fails a build with them, inline or
    # through SDCC's library routines. (The firmware had both before the
    # compensation: crc16.c and link.c indexed their tables with MUL, exec.c
    # multiplied through __mulint.)
    with_mul = MAIN.replace("_masked:\n", "_masked:\n\tmov\tb,#0x02\n\tmul\tab\n")
    code, out = run({"main.asm": with_mul, "step.asm": T2_JUMP}, avail=25, margin=2)
    check(code != 0 and "MUL or DIV in the image" in out and "_masked: mul ab" in out,
          f"an inline MUL fails the build, named (exit {code}): {out.strip()[-200:]}")
    with_call = MAIN.replace("\tlcall\t_leaf\n\tpop\tacc", "\tlcall\t__mulint\n\tpop\tacc")
    code, out = run({"main.asm": with_call, "step.asm": T2_JUMP}, avail=25, margin=2)
    check(code != 0 and "_deep: lcall __mulint" in out, f"a call to __mulint fails the build (exit {code})")
    if failures:
        print(f"{len(failures)} check(s) failed")
        sys.exit(1)
    print("stack-depth tests passed")


if __name__ == "__main__":
    main()
