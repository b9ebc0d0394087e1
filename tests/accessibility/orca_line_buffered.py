#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Runs the installed Orca (/usr/bin/orca's own main(), unchanged) for a test
session, with two differences that only matter to tests:

- its --debug-file is line-buffered. Orca opens that file with Python's default
  block buffering, so a test reading it while Orca runs would see each utterance
  only kilobytes later; line buffering makes every phrase readable at once.
- it ignores Orcas of other sessions. /usr/bin/orca refuses to start when any
  process of the same user is named "orca" (pgrep -x orca), and renames itself
  "orca". Each test session has its own X display and AT-SPI bus, so Orcas of
  parallel tests (or of a developer's desktop) cannot disturb each other; the
  check would only make parallel tests fail, and the rename would make ours
  stop theirs.

usage: orca_line_buffered.py ORCA_ARGS...   (the same arguments as orca)
"""
import builtins
import sys

ORCA = "/usr/bin/orca"


def main():
    args = sys.argv[1:]
    debug_file = args[args.index("--debug-file") + 1] if "--debug-file" in args else None
    real_open = builtins.open

    def open_line_buffered(file, mode="r", *rest, **kw):
        if debug_file is not None and file == debug_file and "w" in mode and not rest and "buffering" not in kw:
            kw["buffering"] = 1
        return real_open(file, mode, *rest, **kw)

    with real_open(ORCA, encoding="utf-8") as f:
        code = compile(f.read(), ORCA, "exec")
    orca = {"__name__": "orca_launcher", "__file__": ORCA}
    exec(code, orca)  # defines Orca's functions; its main() runs only below
    orca["otherOrcas"] = lambda: []
    orca["setProcessName"] = lambda name: None
    builtins.open = open_line_buffered
    sys.argv = [ORCA, *args]
    return orca["main"]()


if __name__ == "__main__":
    sys.exit(main())
