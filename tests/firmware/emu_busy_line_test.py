#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The main loop keeps up with a busy line during top-speed moves (s51).

    make -C firmware emu && python3 tests/firmware/emu_busy_line_test.py [FW.ihx]

At the top step rate the step interrupt takes about two thirds of the CPU,
so the main loop has about 320 of its own machine cycles for each byte the
line brings at 9600 baud, and the UART's receive queue (8 bytes, uart.c)
holds about 2,500 of them. A byte that finds the queue full is dropped, its
frame fails its CRC and is sent again: on a whole sheet that started one or
two carriage moves 0.06-0.30 s late (firmware/README.md, "Main loop").

This test runs two moves of 16,000 carriage steps (about 0.8 s each at the
top rate) while the host keeps the line full: DATA frames the controller has
already accepted (duplicates: each is received, checked and acknowledged
like new data, never executed), several in flight at all times. The emulator
build counts the bytes the receive queue dropped (STATUS_REPLY byte 23): it
must be 0, and the duplicates must have gone through and been answered.
Fails on the firmware whose frame CRC and DATA check were SDCC's C (about
360 main-loop cycles a DATA byte, now 175): 36 or 10 bytes dropped with the
counter added to it; without it, 4 frames of 132 bytes got through.
"""
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "firmware" / "tools"))
import fwhost  # noqa: E402

FW = Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "firmware" / "build-emu" / "tactus-fw.ihx"
UNITS = 800  # 16,000 steps of the 17,760 the carriage travels (20 a unit)


def main():
    if not FW.exists():
        sys.exit(f"{FW} missing: run make -C firmware emu")
    import tempfile
    with tempfile.TemporaryDirectory(prefix="tactus-busy-") as d:
        args = [str(ROOT / "firmware" / "tools" / "run-s51.sh"), str(FW), "--dir", d]
        if os.environ.get("TACTUS_BUSY_VCD"):  # the pins, for a diagnostic build (firmware/README.md)
            args += ["--vcd", os.environ["TACTUS_BUSY_VCD"]]
        proc = subprocess.Popen(args, stdout=subprocess.PIPE, text=True)
        link = fwhost.Link(proc.stdout.readline().split()[1])
        try:
            return run(link)
        finally:
            link.close()
            proc.send_signal(signal.SIGTERM)
            proc.wait(timeout=10)


def run(link):
    hr = link.hello()
    max_data = hr.payload[5]
    link.configure(travel=17760, home_iv=288, hammer=3686, settle=920)
    passes = 2
    stream = (fwhost.job_begin(5) + fwhost.sheet_begin(1) + fwhost.home() +
              fwhost.pass_record(0, UNITS, [(False, 0)], no_feed=True) +
              fwhost.pass_record(0, UNITS, [(True, 0)], first_neg=True, sweep_neg=True, no_feed=True) +
              fwhost.sheet_end() + fwhost.job_end())
    # The last DATA frame accepted, sent again and again: a duplicate costs
    # the controller what new data does until its SEQ is read (every byte
    # through the frame CRC and the DATA check as it arrives).
    dup_seq = link.seq
    link.send_stream(stream, max_data)
    dup = fwhost.frame(dup_seq, fwhost.T_DATA, stream[-(max_data - 2):])
    in_flight, sent, acks, done = 0, 0, 0, None
    deadline = time.monotonic() + 240
    while done is None and time.monotonic() < deadline:
        while in_flight < 3:  # about 120 bytes queued: never a gap on the line
            link.write(dup)
            in_flight += 1
            sent += 1
        r = link.read_reply(2.0)
        if r is None:
            in_flight = 0  # frames lost to dropped bytes: never answered
            continue
        if r.type in (fwhost.T_ACK, fwhost.T_NAK):
            in_flight = max(0, in_flight - 1)
            acks += 1
            a = r.ack
            if a["executed"] == passes and a["state"] == 0:
                done = a
    if done is None:
        print("FAIL: the job did not end")
        return 1
    time.sleep(1.0)  # the answers to the last duplicates
    while True:
        r = link.read_reply(0.5)
        if r is None:
            break
        if r.type in (fwhost.T_ACK, fwhost.T_NAK):
            acks += 1
    st = link.reliable(fwhost.T_STATUS)
    dropped = st.payload[23]
    print(f"{sent} duplicate DATA frames ({sent * len(dup)} bytes) during two moves of {UNITS * 20} steps, "
          f"{acks} answers; receive bytes dropped: {dropped}; faults {done['faults']:#x}")
    ok = True
    if done["faults"] != 0:
        print("FAIL: the job ended with a fault")
        ok = False
    # Independent of the counter (a firmware without it reports 0): a lost
    # byte loses its frame, the host waits for an answer that never comes,
    # and the line falls silent. About 1,300 bytes fit in the two moves; the
    # firmware before took 132 in the same time (4 frames, 3 answered).
    if sent * len(dup) < 800 or acks < sent - 1:
        print(f"FAIL: the line was not kept busy ({sent * len(dup)} bytes, {acks} of {sent} frames answered)")
        ok = False
    if dropped != 0:
        print(f"FAIL: the receive queue dropped {dropped} bytes (the main loop fell behind the line)")
        ok = False
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
