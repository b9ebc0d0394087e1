#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""A whole book through the book layout against the same text as plain lines,
in one run: `tactus-cli layout --volumes` of the KJV as an EPUB (kjv_epub.py)
against `tactus-cli layout` of the plain-text KJV, both to BRF, alternated so
a busy machine slows both alike. Prints each run's wall and CPU seconds, the
medians and their ratio (the aim: the EPUB book at most 1.2 times the text),
and the book's volumes and sheets.

    bench/layout/bench_book.py build/default/app/tactus-cli kjv.txt kjv.epub [RUNS]
"""
import os
import statistics
import subprocess
import sys
import tempfile
import time


def timed(args):
    start = time.monotonic()
    proc = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.monotonic() - start
    out, err = proc.stdout.read(), proc.stderr.read()
    proc.returncode = os.waitstatus_to_exitcode(status)
    if proc.returncode != 0:
        sys.exit(f"{' '.join(args)}: exit {proc.returncode}\n{err}")
    return wall, usage.ru_utime + usage.ru_stime, out + err


def main():
    if len(sys.argv) < 4:
        sys.exit("usage: bench_book.py TACTUS_CLI KJV.txt KJV.epub [RUNS]")
    cli, text, epub = sys.argv[1:4]
    runs = int(sys.argv[4]) if len(sys.argv) > 4 else 3
    out = tempfile.mkdtemp(prefix="tactus-bench-book-")
    cases = {
        "text, layout": [cli, "layout", "--to", "brf", "-o", os.path.join(out, "kjv.brf"), text],
        "EPUB, layout --volumes": [cli, "layout", "--volumes", "--to", "brf", "-o", os.path.join(out, "book.brf"),
                                   epub],
    }
    results = {name: [] for name in cases}
    said = {}
    for i in range(runs):
        for name, args in cases.items():
            wall, cpu, text_out = timed(args)
            results[name].append((wall, cpu))
            said[name] = text_out.strip().splitlines()[-1] if text_out.strip() else ""
            print(f"run {i + 1}  {name:24} {wall:7.2f} s wall {cpu:7.2f} s CPU", flush=True)
    medians = {name: (statistics.median(w for w, _ in r), statistics.median(c for _, c in r))
               for name, r in results.items()}
    for name, (wall, cpu) in medians.items():
        print(f"median  {name:24} {wall:7.2f} s wall {cpu:7.2f} s CPU   ({said[name]})")
    (tw, tc), (bw, bc) = medians["text, layout"], medians["EPUB, layout --volumes"]
    print(f"ratio EPUB book / text: {bw / tw:.2f} wall, {bc / tc:.2f} CPU (aim: at most 1.20)")


if __name__ == "__main__":
    main()
