#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""What one command on s51's console costs, the simulation stopped: the way
into the chip's pins that the parallel-port bridge has (bench/firmware/lpt-bridge.md).

    bench/firmware/lpt_console_latency.py build/default/firmware-emu/tactus-fw.ihx \
        [build/default/app/tactus-s51-wake.so]

Modes: the console on a pty (-c), on TCP (-Z), and on TCP with a second
console kept busy with no-op commands, so s51 never finds its input empty
and never takes its 100 ms nap. With the wake library (firmware/tools/s51_wake.c,
preloaded: the nap becomes a wait for the next line) also the pty and the
TCP console with it, TCP acknowledging each answer at once (TCP_QUICKACK:
s51 writes its answer a byte at a time, and Nagle's rule held the rest of it
for the host's delayed acknowledgement). Each prints the mean and worst round
trip of a lockstep line (the host's lines set, the status read, a short step)
and the CPU time s51 spent a line.
"""
import os
import pty
import select
import socket
import subprocess
import sys
import tempfile
import threading
import time
import tty

LINE = (b"set memory port_0_cfg 1 0x55;set memory port_2_cfg 1 0xff;set memory port_3_cfg 1 0xff;"
        b"get sfr 0xa0;get sfr 0xb0;step 20\n")
N = 100
DEPTH = int(os.environ.get("DEPTH", "4"))  # no-ops in flight on the busy console


class Console:
    def __init__(self, rd, wr):
        self.rd, self.wr, self.buf = rd, wr, b""

    def prompt(self):
        while b"\0" not in self.buf:
            chunk = self.rd()
            if not chunk:
                raise RuntimeError("s51 closed its console")
            self.buf += chunk
        out, _, self.buf = self.buf.partition(b"\0")
        return out


def start(ihx, args, wake=None):
    d = tempfile.mkdtemp(prefix="tactus-lat-")
    env = dict(os.environ)
    if wake:
        env["LD_PRELOAD"] = wake
    return subprocess.Popen(["s51", "-t", "C52", "-X", "11.0592M", "-b", "-P"] + args + [ihx],
                            stdin=subprocess.DEVNULL, stdout=open(os.path.join(d, "s51.log"), "w"),
                            stderr=subprocess.STDOUT, cwd=d, env=env)


def cpu_seconds(pid):
    f = open(f"/proc/{pid}/stat").read().rsplit(")", 1)[1].split()
    return (int(f[11]) + int(f[12])) / os.sysconf("SC_CLK_TCK")


def tcp(port):
    for _ in range(200):
        try:
            sk = socket.create_connection(("127.0.0.1", port))
            sk.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
            return sk
        except OSError:
            time.sleep(0.05)
    raise RuntimeError("no s51 console on TCP")


def measure(name, con, s51):
    con.prompt()
    time.sleep(2.5)  # s51 never naps in its first two seconds: measure past them
    worst, t0, c0 = 0.0, time.monotonic(), cpu_seconds(s51.pid)
    for _ in range(N):
        t = time.monotonic()
        con.wr(LINE)
        con.prompt()
        worst = max(worst, time.monotonic() - t)
    mean = (time.monotonic() - t0) / N
    cpu = (cpu_seconds(s51.pid) - c0) / N
    print(f"{name:44s} {mean * 1000:7.2f} ms mean {worst * 1000:7.1f} ms worst {cpu * 1000:6.2f} ms s51 CPU")
    s51.kill()
    s51.wait()


def main():
    ihx = os.path.abspath(sys.argv[1])
    m, s = pty.openpty()
    tty.setraw(s)
    s51 = start(ihx, ["-c", os.ttyname(s)])
    measure("pty console (-c)", Console(lambda: os.read(m, 65536), lambda b: os.write(m, b)), s51)
    port = 41000 + os.getpid() % 20000
    s51 = start(ihx, ["-Z", str(port)])
    a = tcp(port)
    measure("TCP console (-Z)", Console(lambda: a.recv(65536), a.sendall), s51)
    port += 1
    s51 = start(ihx, ["-Z", str(port)])
    a, b = tcp(port), tcp(port)
    busy = Console(lambda: b.recv(65536), b.sendall)
    busy.prompt()
    done = False

    def keep_busy():  # no-ops on the second console, a few in flight at a time
        try:
            owed = 0
            while not done:
                if owed < DEPTH:
                    b.sendall(b"echo\n" * (DEPTH - owed))
                    owed = DEPTH
                r, _, _ = select.select([b], [], [], 0.1)
                if r:
                    owed -= b.recv(65536).count(b"\0")
        except OSError:
            pass  # s51 ended
    threading.Thread(target=keep_busy, daemon=True).start()
    measure("TCP console, a second one kept busy", Console(lambda: a.recv(65536), a.sendall), s51)
    done = True
    if len(sys.argv) < 3:
        return
    wake = os.path.abspath(sys.argv[2])
    m, s = pty.openpty()
    tty.setraw(s)
    s51 = start(ihx, ["-c", os.ttyname(s)], wake)
    measure("pty console, wake library", Console(lambda: os.read(m, 65536), lambda b: os.write(m, b)), s51)
    port += 1
    s51 = start(ihx, ["-Z", str(port)], wake)
    c = tcp(port)

    def quick_recv():
        chunk = c.recv(65536)
        c.setsockopt(socket.IPPROTO_TCP, socket.TCP_QUICKACK, 1)
        return chunk
    measure("TCP console, wake library, quick ACKs", Console(quick_recv, c.sendall), s51)


if __name__ == "__main__":
    main()
