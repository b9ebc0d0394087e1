#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""A minimal protocol-v3 host for the emulated firmware: frames, replies, the
job-stream encoding of docs/protocol.md, and a VCD reader for the pins. Used by
tests/firmware/emu_test.py and bench/firmware. (The real host is tactus-cli;
this is the firmware's own test harness, kept small and independent of it.)"""
import os
import random
import select
import struct
import termios
import time
import tty

SYNC = 0x7E
T_HELLO, T_CONFIGURE, T_DATA, T_PAUSE, T_RESUME, T_ABORT, T_STATUS, T_KEEPALIVE = range(1, 9)
T_HELLO_REPLY, T_ACK, T_NAK, T_STATUS_REPLY = 0x81, 0x82, 0x83, 0x84
ST_NAMES = ["idle", "running", "waiting", "paused", "fault", "homing"]


def crc16(data, crc=0xFFFF, poly=0x1021):
    for b in data:
        crc ^= b << 8
        for _ in range(8):
            crc = ((crc << 1) ^ poly) & 0xFFFF if crc & 0x8000 else (crc << 1) & 0xFFFF
    return crc


def data_check(ops):
    """The DATA payload's check: CRC-16, poly 0x8BB7, over the ops."""
    c = crc16(ops, poly=0x8BB7)
    return bytes([c >> 8, c & 0xFF])


def frame(seq, typ, payload=b""):
    """A frame; a DATA payload gets its check appended."""
    if typ == T_DATA:
        payload = bytes(payload) + data_check(payload)
    body = bytes([len(payload), seq & 0xFF, typ]) + bytes(payload)
    c = crc16(body)
    return bytes([SYNC]) + body + bytes([c >> 8, c & 0xFF])


# --- job stream (docs/protocol.md)
def uvar(v):
    if not 0 <= v < 0x8000:
        raise ValueError(f"uvar out of range: {v}")
    return bytes([v]) if v < 0x80 else bytes([0x80 | (v >> 8), v & 0xFF])


def svar(v):
    if -64 <= v < 64:
        return bytes([v & 0x7F])
    if not -0x4000 <= v < 0x4000:
        raise ValueError(f"svar out of range: {v}")
    u = v & 0x7FFF
    return bytes([0x80 | (u >> 8), u & 0xFF])


def job_begin(job, first_pass=0):
    return bytes([0x10]) + struct.pack(">HH", job, first_pass)


def job_end():
    return b"\x11"


def sheet_begin(sheet):
    return bytes([0x12]) + struct.pack(">H", sheet)


def sheet_end():
    return b"\x13"


def home():
    return b"\x40"


def pass_record(feed_units, first_units, entries, sweep_neg=False, first_neg=False,
                back=False, no_feed=False, skip=None):
    """entries: [(concave: bool, distance_units)], the first entry's distance
    is ignored (the move to it is first_units). Up to 255 entries."""
    flags = (1 if back else 0) | (2 if no_feed else 0) | (4 if sweep_neg else 0) | \
        (8 if first_neg else 0) | (0x10 if skip is not None else 0)
    out = bytearray([0x14, flags])
    if skip is not None:
        out.append(skip)
    out += svar(feed_units) + uvar(first_units) + bytes([len(entries)])
    for i, (concave, d) in enumerate(entries):
        d = 0 if i == 0 else d
        h = 0x80 if concave else 0
        if d < 64:
            out.append(h | d)
        elif d < 0x4000:
            out += bytes([h | 0x40 | (d >> 8), d & 0xFF])
        else:
            raise ValueError(f"strike distance {d} units out of range")
    return bytes(out)


class Reply:
    def __init__(self, seq, typ, payload):
        self.seq, self.type, self.payload = seq, typ, payload

    @property
    def ack(self):
        p = self.payload[1:] if self.type == T_NAK else self.payload
        free, executed, state, faults, strikes, job = struct.unpack(">BHBBBH", p[:8])
        return dict(free=free, executed=executed, state=state, faults=faults, strikes=strikes, job=job)

    def __repr__(self):
        return f"Reply(seq={self.seq}, type=0x{self.type:02x}, {self.payload.hex()})"


class Link:
    """noise: probability that a byte on the line (either way) has a bit
    flipped, for the noisy-line tests (seeded: reproducible)."""

    def __init__(self, path, noise=0.0, seed=1):
        self.noise = noise
        self.rng = random.Random(seed)
        self.corrupted = 0
        self.fd = os.open(path, os.O_RDWR | os.O_NOCTTY)
        tty.setraw(self.fd)
        attrs = termios.tcgetattr(self.fd)
        attrs[4] = attrs[5] = termios.B9600
        termios.tcsetattr(self.fd, termios.TCSANOW, attrs)
        self.buf = bytearray()
        self.seq = 0
        self.sent_bytes = 0

    def close(self):
        os.close(self.fd)

    def _noisy(self, data):
        if not self.noise:
            return data
        out = bytearray(data)
        for i in range(len(out)):
            if self.rng.random() < self.noise:
                out[i] ^= 1 << self.rng.randrange(8)
                self.corrupted += 1
        return bytes(out)

    def write(self, data):
        self.sent_bytes += len(data)
        os.write(self.fd, self._noisy(data))

    def read_reply(self, timeout):
        end = time.monotonic() + timeout
        while True:
            r = self._parse()
            if r:
                return r
            left = end - time.monotonic()
            if left <= 0:
                return None
            rd, _, _ = select.select([self.fd], [], [], left)
            if rd:
                self.buf += self._noisy(os.read(self.fd, 256))

    def _parse(self):
        while self.buf:
            if self.buf[0] != SYNC:
                del self.buf[0]
                continue
            if len(self.buf) < 2:
                return None
            n = self.buf[1]
            if n > 80:
                del self.buf[0]
                continue
            if len(self.buf) < n + 6:
                return None
            body = bytes(self.buf[1:4 + n])
            c = (self.buf[4 + n] << 8) | self.buf[5 + n]
            if crc16(body) != c:
                del self.buf[0]
                continue
            del self.buf[:n + 6]
            return Reply(body[1], body[2], body[3:])
        return None

    def request(self, typ, payload=b"", timeout=3.0, seq=None):
        """Sends one frame and waits for the reply that answers it."""
        s = self.seq if seq is None else seq
        self.write(frame(s, typ, payload))
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            r = self.read_reply(end - time.monotonic())
            if r is None:
                break
            if typ == T_HELLO and r.type == T_HELLO_REPLY:
                self.seq = r.seq
                return r
            if typ == T_STATUS and r.type == T_ACK and r.seq == (s + 1) & 0xFF:
                # STATUS was taken but its reply may have been lost: a repeat
                # with this SEQ would only be acknowledged (a duplicate), so
                # the next try asks again under the new SEQ.
                self.seq = r.seq
                continue
            if r.type == T_NAK or (r.type in (T_ACK, T_STATUS_REPLY) and r.seq == (s + 1) & 0xFF):
                if r.type != T_NAK:
                    self.seq = r.seq
                return r
        raise TimeoutError(f"no reply to frame type {typ} seq {s}")

    def reliable(self, typ, payload=b"", tries=40, seq=None):
        """request(), re-sent on silence or NAK out-of-order/no-space (the
        same SEQ: the controller acknowledges a duplicate, never runs it)."""
        for _ in range(tries):
            try:
                r = self.request(typ, payload, timeout=0.8, seq=seq)
            except TimeoutError:
                continue
            if r.type == T_NAK and r.payload[0] in (1, 2):
                time.sleep(0.1)
                continue
            return r
        raise TimeoutError(f"frame type {typ} not acknowledged after {tries} tries")

    def hello(self, nonce=0x1234):
        return self.reliable(T_HELLO, struct.pack(">HB", nonce, 3), seq=0)

    def configure(self, travel, home_iv, hammer, settle, keepalive=0):
        return self.reliable(T_CONFIGURE, struct.pack(">HHHHH", travel, home_iv, hammer, settle, keepalive))

    def send_stream(self, stream, max_payload, wait_free=True, timeout=120.0):
        """Sends the job stream in DATA frames (ops + 2-byte check, at most
        max_payload), one frame in flight, each once the ring has room."""
        max_data = max_payload - 2
        free = None
        pos = 0
        deadline = time.monotonic() + timeout
        last = None
        while pos < len(stream):
            chunk = stream[pos:pos + max_data]
            if free is not None and free < len(chunk):
                r = self.read_reply(0.5)
                if r is None:
                    r = self.reliable(T_KEEPALIVE)
                if r.type in (T_ACK, T_NAK):
                    free = r.ack["free"]
                    last = r
                if time.monotonic() > deadline:
                    raise TimeoutError("the ring never had room")
                continue
            r = self.reliable(T_DATA, chunk)
            if r.type == T_NAK:
                raise RuntimeError(f"NAK {r.payload[0]} for DATA at {pos}: {r}")
            free = r.ack["free"]
            last = r
            if r.ack["faults"] & 0x80:
                raise RuntimeError(f"stream fault after DATA at {pos}: {r.ack}")
            pos += len(chunk)
        return last

    def wait_state(self, pred, timeout):
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            r = self.read_reply(0.5)
            if r is None:
                r = self.reliable(T_KEEPALIVE)
            if r.type in (T_ACK, T_NAK) and pred(r.ack):
                return r.ack
        raise TimeoutError("state not reached")


def read_vcd(path):
    """(time_s, pin values as an int of port 1) at every change."""
    scale = 1e-12
    changes = []
    t = 0.0
    ids = {}
    with open(path) as f:
        for line in f:
            line = line.strip()
            if line.startswith("$timescale"):
                parts = line.split()
                unit = parts[1] if len(parts) > 1 and parts[1] != "$end" else next(f).strip()
                num = "".join(ch for ch in unit if ch.isdigit()) or "1"
                suffix = unit[len(num):]
                scale = int(num) * {"s": 1, "ms": 1e-3, "us": 1e-6, "ns": 1e-9, "ps": 1e-12, "fs": 1e-15}[suffix]
            elif line.startswith("$var"):
                parts = line.split()
                ids[parts[3]] = parts[4]
            elif line.startswith("#"):
                t = int(line[1:]) * scale
            elif line.startswith("b"):
                val, ident = line[1:].split()
                changes.append((t, ident, int(val, 2) if set(val) <= {"0", "1"} else None))
            elif line and line[0] in "01" and len(line) > 1:
                changes.append((t, line[1:], int(line[0])))
    return changes, ids
