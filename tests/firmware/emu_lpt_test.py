#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The firmware's parallel port in s51, on its pins, with no serial line.

s51 runs the emulator build with its command console on a pty and no UART
at all; this script is the PC's side of the cable. It drives the chip's input
pins (P0 the data lines, P3.2 nStrobe, P2.4 nAutoFd, P2.5 nSelectIn) and
reads its output latches (P2.0-P2.3 nFault, Select, PError, Busy; P3.5 nAck)
through the console, the simulation stopped between commands and advanced by
`step` (lockstep: s51's console answers about 0.1 s a command while stopped,
about 1 s while running). It sends HELLO and STATUS in compatibility mode
(strobe, Busy) and reads HELLO_REPLY and STATUS_REPLY back in IEEE 1284
nibble mode (negotiation, HostBusy, the nibbles, termination), and checks the
condition lines (PError, nFault, Select) between transfers, paper in and out.

    tests/firmware/emu_lpt_test.py firmware/build-emu/tactus-fw.ihx [--status]
"""
import os
import pathlib
import pty
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import tty

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "firmware" / "tools"))
import fwhost  # noqa: E402

STEPS = 3000  # instructions s51 runs after each change of the host's lines


class Chip:
    def __init__(self, ihx, paper=True):
        self.master, slave = pty.openpty()
        tty.setraw(slave)
        self.dir = tempfile.mkdtemp(prefix="tactus-lpt-")
        # The console on the pty, prompts as NUL bytes (-P); no -S: no UART.
        self.proc = subprocess.Popen(
            ["s51", "-t", "C52", "-X", "11.0592M", "-b", "-P", "-c", os.ttyname(slave), ihx],
            stdin=subprocess.DEVNULL, stdout=open(os.path.join(self.dir, "s51.log"), "w"),
            stderr=subprocess.STDOUT, cwd=self.dir)
        self.slave = slave  # held open: until s51 opens it, a read of the master fails
        self.buf = b""
        self.read_prompt()
        self.ctl = {"strobe": 1, "autofd": 1, "selectin": 0}
        self.data = 0
        self.paper = paper  # P3.6, the paper sensor
        self.lines()
        self.cmd("step 200000")  # boot: the stack painted, the ports set

    def close(self):
        self.proc.kill()
        self.proc.wait()
        os.close(self.master)
        os.close(self.slave)
        shutil.rmtree(self.dir, ignore_errors=True)

    def read_prompt(self):
        while b"\0" not in self.buf:
            chunk = os.read(self.master, 65536)
            if not chunk:
                raise RuntimeError("s51 closed its console")
            self.buf += chunk
        out, _, self.buf = self.buf.partition(b"\0")
        return out.decode(errors="replace")

    def cmd(self, line):
        os.write(self.master, line.encode() + b"\n")
        return self.read_prompt()

    def pin_cmds(self):
        p3 = 0xff & ~(0 if self.ctl["strobe"] else 0x04)
        p3 &= 0xff if self.paper else 0xbf
        p2 = 0xff & ~(0 if self.ctl["autofd"] else 0x10) & ~(0 if self.ctl["selectin"] else 0x20)
        return [f"set memory port_0_cfg 1 {self.data:#x}", f"set memory port_2_cfg 1 {p2:#x}",
                f"set memory port_3_cfg 1 {p3:#x}"]

    def lines(self, steps=STEPS):
        """Puts the host's lines on the pins, runs `steps` instructions, reads
        the status lines: (nAck, Busy, PError, Select, nFault)."""
        out = self.cmd(";".join(self.pin_cmds() + [f"step {steps}", "get sfr 0xa0", "get sfr 0xb0"]))
        self.last = out
        p2 = int(re.findall(r"0xa0 P2:\s+0b[01]+ 0x([0-9a-f]{2})", out)[-1], 16)
        p3 = int(re.findall(r"0xb0 P3:\s+0b[01]+ 0x([0-9a-f]{2})", out)[-1], 16)
        return {"nack": (p3 >> 5) & 1, "busy": (p2 >> 3) & 1, "perror": (p2 >> 2) & 1,
                "select": (p2 >> 1) & 1, "nfault": p2 & 1, "p2": p2}

    def wait(self, pred, what, tries=40):
        for _ in range(tries):
            st = self.lines()
            if pred(st):
                return st
        raise AssertionError(f"the chip never showed {what}: {st}\n{self.last[-1500:]}")

    # --- compatibility mode
    def write(self, data):
        for b in data:
            self.wait(lambda s: not s["busy"], "Busy low before a byte")
            self.data = b
            self.ctl["strobe"] = 0
            self.lines(steps=20)
            self.ctl["strobe"] = 1
            self.wait(lambda s: not s["busy"], "Busy low after a byte")

    # --- IEEE 1284 nibble mode
    def read(self):
        self.data = 0x00  # request: nibble mode
        self.ctl.update(selectin=1, autofd=0)
        self.wait(lambda s: not s["nack"] and s["perror"] and s["nfault"] and s["select"], "event 2")
        self.ctl["strobe"] = 0
        self.lines(steps=20)
        self.ctl.update(strobe=1, autofd=1)
        st = self.wait(lambda s: s["nack"], "event 6")
        assert not st["select"], "XFlag must be low: nibble mode is supported"
        out = bytearray()
        more = not st["nfault"]
        while more:
            value = 0
            for half in range(2):
                self.ctl["autofd"] = 0
                st = self.wait(lambda s: not s["nack"], "a nibble (nAck low)")
                value |= (st["p2"] & 0x0F) << (4 * half)
                self.ctl["autofd"] = 1
                st = self.wait(lambda s: s["nack"], "the nibble's end (nAck high)")
            out.append(value)
            more = not st["nfault"]
        self.ctl.update(selectin=0, autofd=1)
        self.wait(lambda s: not s["nack"], "event 24")
        self.ctl["autofd"] = 0
        self.wait(lambda s: s["nack"], "event 27")
        self.ctl["autofd"] = 1
        self.lines()
        return bytes(out)

    def reply(self, tries=20):
        """Polls in nibble mode until one whole frame came back."""
        buf = bytearray()
        for _ in range(tries):
            buf += self.read()
            while buf and buf[0] != fwhost.SYNC:
                del buf[0]
            if len(buf) >= 2 and len(buf) >= buf[1] + 6:
                n = buf[1]
                body = bytes(buf[1:4 + n])
                crc = (buf[4 + n] << 8) | buf[5 + n]
                assert fwhost.crc16(body) == crc, f"reply CRC: {buf.hex()}"
                return fwhost.Reply(body[1], body[2], body[3:])
        raise AssertionError(f"no whole reply frame: {buf.hex()}")


def main():
    if shutil.which("s51") is None:
        print("emu_lpt_test: s51 not found (apt-get install sdcc-ucsim)")
        return 77
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    ihx = os.path.abspath(args[0] if args else "firmware/build-emu/tactus-fw.ihx")
    chip = Chip(ihx)
    try:
        st = chip.lines()
        # Compatibility mode, idle after a power-up: on line, no paper fault.
        assert st["select"] and not st["perror"] and not st["busy"] and st["nack"], st
        chip.write(fwhost.frame(0, fwhost.T_HELLO, struct.pack(">HB", 0x1234, 3)))
        r = chip.reply()
        assert r.type == fwhost.T_HELLO_REPLY, r
        assert r.payload[0] == 3 and r.payload[3] & 0x02, f"protocol 3, LPT capable: {r.payload.hex()}"
        print(f"HELLO_REPLY over nibble mode: {r.payload.hex()}")
        if "--status" in sys.argv:  # the longest reply, 31 bytes: about a minute more
            chip.write(fwhost.frame(r.seq, fwhost.T_STATUS))
            s = chip.reply()
            assert s.type == fwhost.T_STATUS_REPLY and len(s.payload) == 25, s
            assert s.payload[3] == 0 and s.payload[4] == 0, f"idle, no fault: {s.payload.hex()}"
            assert s.payload[8] & 0x08, "paper present"
            print(f"STATUS_REPLY over nibble mode: {s.payload.hex()}")
        st = chip.lines()
        assert st["select"] and st["nfault"] and not st["perror"], st
    finally:
        chip.close()
    # Paper out: a job's SHEET_BEGIN finds none; PError goes high and nFault
    # low (the fault), read from the pins in compatibility mode.
    chip = Chip(ihx, paper=False)
    try:
        # The replies (HELLO_REPLY, the ACK) wait unread: the condition lines
        # show between transfers all the same.
        chip.write(fwhost.frame(0, fwhost.T_HELLO, struct.pack(">HB", 0x4321, 3)))
        chip.write(fwhost.frame(1, fwhost.T_DATA, fwhost.job_begin(7) + fwhost.sheet_begin(1)))
        st = chip.wait(lambda s: s["perror"], "PError (paper out)")
        assert not st["nfault"] and st["select"], st
        print("paper out: PError high, nFault low")
    finally:
        chip.close()
    print("emu_lpt_test: ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
