#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Every accessible text of the app answers a screen reader's reads at once.

Starts tactus on the AT-SPI bus with a document open, finds every object with
a Text interface (whether shown or on a hidden tab), and asks each one what a
screen reader asks while the caret moves: the text at, before and after the
offset, by character, word, sentence and line (start and end), and by
paragraph, at the first offset, the middle and the end. Every answer must come
within 100 ms and hold a sane range. A text interface that loops (the preview's
first cell once spun the GUI thread for ever) fails here: libatspi gives up on
the call, and a watchdog ends the test if it does not.

usage: atspi_text_walk.py TACTUS SAMPLE
"""
import os
import subprocess
import sys
import threading
import time

import pyatspi

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from atspi_walk import find_app, walk  # noqa: E402

LIMIT_S = 0.100
BOUNDARIES = [("char", pyatspi.TEXT_BOUNDARY_CHAR), ("word start", pyatspi.TEXT_BOUNDARY_WORD_START),
              ("word end", pyatspi.TEXT_BOUNDARY_WORD_END), ("sentence start", pyatspi.TEXT_BOUNDARY_SENTENCE_START),
              ("sentence end", pyatspi.TEXT_BOUNDARY_SENTENCE_END), ("line start", pyatspi.TEXT_BOUNDARY_LINE_START),
              ("line end", pyatspi.TEXT_BOUNDARY_LINE_END)]
GRANULARITIES = [("paragraph", pyatspi.TEXT_GRANULARITY_PARAGRAPH)]


class Watchdog:
    """Ends the process when one call blocks far beyond any timeout: the GUI
    thread spinning must fail the test, never hang it."""

    def __init__(self, seconds):
        self.seconds = seconds
        self.what = None
        self.since = None
        self.proc = None
        threading.Thread(target=self._run, daemon=True).start()

    def _run(self):
        while True:
            time.sleep(0.5)
            if self.since is not None and time.monotonic() - self.since > self.seconds:
                print(f"FAIL: {self.what} did not answer in {self.seconds} s: the app hangs", flush=True)
                if self.proc is not None:
                    self.proc.kill()
                os._exit(1)


def main():
    tactus, sample = sys.argv[1], sys.argv[2]
    proc = subprocess.Popen([tactus, "--no-recovery", sample], stdout=sys.stdout, stderr=sys.stderr)
    dog = Watchdog(20)
    dog.proc = proc
    failures = []
    calls = 0
    slowest = (0.0, "")
    try:
        app = find_app("tactus", time.time() + 60)
        if app is None:
            raise SystemExit("FAIL: tactus never appeared on the AT-SPI bus")
        # Wait for the document: the preview's line holds braille cells then.
        deadline = time.time() + 60
        texts = []
        while time.time() < deadline:
            objects = []
            walk(app, ["app"], objects)
            texts = []
            for obj, path in objects:
                try:
                    texts.append((obj, path, obj.queryText()))
                except NotImplementedError:
                    continue
            preview = [t for o, _, t in texts if o.name == "Interpoint preview"]
            if preview and preview[0].characterCount > 0:
                break
            time.sleep(0.3)
        else:
            raise SystemExit("FAIL: the preview never held a line of braille")
        names = sorted({f"{o.getRoleName()}:{o.name}" for o, _, _ in texts})
        print(f"{len(texts)} text objects: {names}", flush=True)
        for must in ("Interpoint preview", "Braille", "Print text"):
            if not any(o.name == must for o, _, _ in texts):
                failures.append(f"no text interface on '{must}'")

        unsupported = set()

        def timed(what, call, optional=False):
            nonlocal calls, slowest
            dog.what, dog.since = what, time.monotonic()
            t0 = time.monotonic()
            try:
                result = call()
            except Exception as e:  # libatspi's timeout: the app did not answer
                # Qt's bridge (6.4) answers a method it lacks with "No such object path".
                if optional and ("UnknownMethod" in str(e) or "No such object path" in str(e)):
                    unsupported.add(what.split(": ")[-1].split("(")[0])
                else:
                    failures.append(f"{what}: {type(e).__name__}: {str(e)[:120]}")
                result = None
            finally:
                dog.since = None
            dt = time.monotonic() - t0
            if dt > LIMIT_S and result is not None:
                # Once more: a busy machine (CI runs jobs side by side) may delay
                # one answer; a read that is slow itself is slow twice.
                t0 = time.monotonic()
                try:
                    call()
                except Exception:
                    pass
                dt = min(dt, time.monotonic() - t0)
            calls += 1
            if dt > slowest[0]:
                slowest = (dt, what)
            if dt > LIMIT_S:
                failures.append(f"{what}: {dt * 1000:.0f} ms, more than {LIMIT_S * 1000:.0f} ms")
            return result

        for obj, path, text in texts:
            label = " > ".join(path[-3:])
            n = text.characterCount
            for offset in sorted({0, n // 2, max(0, n - 1), n}):
                for bname, b in BOUNDARIES:
                    for fname in ("getTextAtOffset", "getTextBeforeOffset", "getTextAfterOffset"):
                        what = f"{label}: {fname}({offset}, {bname}) of {n}"
                        r = timed(what, lambda f=fname, o=offset, bb=b: getattr(text, f)(o, bb))
                        if r is None:
                            continue
                        got, start, end = r
                        if start == end == -1 and not got:
                            continue  # Qt's way of saying there is no such unit
                        if not (0 <= start <= end <= n):
                            failures.append(f"{what}: range {start}..{end} outside the text")
                        elif fname == "getTextAtOffset" and offset < n and not (start <= offset < end):
                            failures.append(f"{what}: range {start}..{end} does not hold the offset")
                for gname, g in GRANULARITIES:
                    timed(f"{label}: getStringAtOffset({offset}, {gname}) of {n}",
                          lambda o=offset, gg=g: text.getStringAtOffset(o, gg), optional=True)
                if failures and any("did not answer" in f or "Error" in f for f in failures):
                    raise SystemExit(1)
    except SystemExit as e:
        if e.code not in (None, 1):
            print(e.code)
            failures.append("setup failed")
    finally:
        proc.terminate()
        try:
            proc.wait(10)
        except subprocess.TimeoutExpired:
            proc.kill()
    if unsupported:
        print(f"not offered by Qt's AT-SPI bridge: {sorted(unsupported)}")
    print(f"{calls} reads, slowest {slowest[0] * 1000:.1f} ms ({slowest[1]})")
    if failures:
        print("\n".join("FAIL: " + f for f in failures[:40]))
        return 1
    print("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())
