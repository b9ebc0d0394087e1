#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Keyboard-only walkthrough under Xvfb: xdotool types what a keyboard user types.
Opens a sample through the Open dialog, switches to uncontracted braille with the
table picker, previews the back side, exports BRF, and checks the result against
`tactus-cli layout` and what the screen reader is told (AT-SPI).

With --emboss (builds that have the link stage) it then embosses to the built-in
simulator with Ctrl+P and waits for the app to report every strike checked against
the plan.

usage: keyboard_walkthrough.py [--emboss] TACTUS TACTUS_CLI SAMPLE [SCREENSHOT_DIR]
"""
import filecmp
import os
import subprocess
import sys
import time

import pyatspi

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from atspi_walk import find_app, walk, wait_for  # noqa: E402


def xdo(*args):
    subprocess.run(["xdotool", *args], check=True, timeout=20)


def key(*keys):
    for k in keys:
        xdo("key", "--clearmodifiers", k)
        time.sleep(0.25)


def type_text(text):
    xdo("type", "--delay", "15", text)
    time.sleep(0.3)


def focused_window_name():
    out = subprocess.run(["xdotool", "getwindowfocus", "getwindowname"], capture_output=True, text=True, timeout=20)
    return out.stdout.strip() if out.returncode == 0 else ""


def wait_keyboard_in(title):
    # Keys typed before a dialog holds the keyboard land in the main window
    # (a path typed into the document); under load a dialog can take seconds
    # to appear, so wait for the X input focus to be on it, never for a time.
    wait_for(lambda: title in focused_window_name(), f"the {title!r} dialog to take the keyboard", 60)


def objects_of(app):
    out = []
    walk(app, ["app"], out)
    return out


def announcement(app):
    for o, _ in objects_of(app):
        if o.getRole() == pyatspi.ROLE_NOTIFICATION:
            return o.name or ""
    return ""


def main():
    args = sys.argv[1:]
    emboss = "--emboss" in args
    args = [a for a in args if a != "--emboss"]
    tactus, cli, sample = (os.path.abspath(a) for a in args[:3])
    shots = args[3] if len(args) > 3 else None
    work = os.environ.get("TACTUS_WORK", "/tmp")
    brf = os.path.join(work, "walkthrough.brf")
    expected = os.path.join(work, "expected.brf")
    proc = subprocess.Popen([tactus, "--no-recovery"], cwd=work)
    try:
        app = find_app("tactus", time.time() + 60)
        if app is None:
            raise SystemExit("FAIL: tactus did not start")
        wid = wait_for(lambda: subprocess.run(["xdotool", "search", "--onlyvisible", "--name", "Tactus"], capture_output=True,
                                              text=True).stdout.split(), "the Tactus window")[0]
        def focus_main():
            # No window manager under Xvfb: when a dialog closes nobody gives the main
            # window the input focus back, so do what a window manager would.
            xdo("windowfocus", "--sync", wid)
            time.sleep(0.3)

        focus_main()

        # 1. Open the sample: Ctrl+O, type the path, Enter.
        key("ctrl+o")
        wait_keyboard_in("Open or import")
        type_text(sample)
        key("Return")
        wait_for(lambda: "Opened" in announcement(app), "the sample to open", 30)
        print("opened:", announcement(app))

        # 2. Table picker (Ctrl+T opens its list); uncontracted English is just above contracted.
        focus_main()
        key("ctrl+t")
        # The list must be open before Up: on the closed combo box Up would
        # already change the table, and Return then do nothing.
        wait_for(lambda: any(o.getRole() == pyatspi.ROLE_COMBO_BOX and o.name == "Braille table"
                             and o.getState().contains(pyatspi.STATE_EXPANDED) for o, _ in objects_of(app)),
                 "the table list to open", 60)
        if shots:
            subprocess.run(["import", "-window", "root", os.path.join(shots, "walkthrough-tables.png")], check=False)
        key("Up", "Return")
        wait_for(lambda: "uncontracted" in announcement(app), "the table switch")
        print("table:", announcement(app))

        # 3. The back side in the preview, then the preview itself (Ctrl+3).
        key("ctrl+alt+b", "ctrl+3")
        preview = wait_for(lambda: next((o for o, _ in objects_of(app) if o.name == "Interpoint preview"), None),
                           "the preview")
        wait_for(lambda: "back" in (preview.description or ""), "the preview to show the back")
        key("Right")
        print("preview says:", preview.description)
        if shots:
            subprocess.run(["import", "-window", "root", os.path.join(shots, "walkthrough-back.png")], check=False)

        # 4. Export BRF (Ctrl+E), typing the file name into the dialog.
        focus_main()
        key("ctrl+e")
        wait_keyboard_in("Export")
        key("ctrl+a")
        type_text(brf)
        key("Return")
        wait_for(lambda: os.path.exists(brf) and "Exported" in announcement(app), "the BRF export", 30)
        print("export:", announcement(app))

        # 5. Emboss to the simulator (Ctrl+P); the app checks the simulator's strikes.
        if emboss:
            focus_main()
            key("ctrl+p")
            wait_for(lambda: "Embossed" in announcement(app) or "stopped" in announcement(app),
                     "the job to finish", 120)
            said = announcement(app)
            print("emboss:", said)
            if "strikes checked against the plan" not in said:
                raise SystemExit(f"FAIL: embossing did not check out: {said!r}")
    finally:
        proc.terminate()
        try:
            proc.wait(10)
        except subprocess.TimeoutExpired:
            proc.kill()

    subprocess.run([cli, "layout", "--preset", "a4", "--interpoint", "--table", "en-ueb-g1.ctb", "--to", "brf", "-o", expected,
                    sample], check=True, timeout=60)
    if not filecmp.cmp(brf, expected, shallow=False):
        print("FAIL: the exported BRF differs from tactus-cli layout")
        return 1
    print("PASS: keyboard-only open, table, back side and export" + (", emboss" if emboss else "")
          + "; BRF equals tactus-cli's")
    return 0


if __name__ == "__main__":
    sys.exit(main())
