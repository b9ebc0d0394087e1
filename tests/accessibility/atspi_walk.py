#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Starts tactus on the AT-SPI bus and walks its accessible tree the way a screen
reader does. Fails on any focusable object without a name, any object with no
role, a preview that does not speak its cell, or an announcer that stays silent.

usage: atspi_walk.py TACTUS SAMPLE
"""
import os
import subprocess
import sys
import time

import pyatspi

TIMEOUT = 60


def find_app(name, deadline):
    while time.time() < deadline:
        desktop = pyatspi.Registry.getDesktop(0)
        for i in range(desktop.childCount):
            app = desktop.getChildAtIndex(i)
            if app is not None and app.name == name:
                return app
        time.sleep(0.3)
    return None


def walk(obj, path, out, depth=0):
    if obj is None or depth > 60:
        return
    out.append((obj, path))
    for i in range(obj.childCount):
        try:
            child = obj.getChildAtIndex(i)
        except Exception:  # object went away while walking
            continue
        walk(child, path + [f"{child.getRoleName() if child else '?'}:{child.name if child else ''}"], out, depth + 1)


def describe(path):
    return " > ".join(path[-4:])


def wait_for(predicate, what, seconds=20):
    deadline = time.time() + seconds
    while time.time() < deadline:
        value = predicate()
        if value:
            return value
        time.sleep(0.2)
    raise SystemExit(f"FAIL: timed out waiting for {what}")


def main():
    tactus, sample = sys.argv[1], sys.argv[2]
    proc = subprocess.Popen([tactus, "--no-recovery", sample], stdout=sys.stdout, stderr=sys.stderr)
    failures = []
    try:
        app = find_app("tactus", time.time() + TIMEOUT)
        if app is None:
            raise SystemExit("FAIL: tactus never appeared on the AT-SPI bus")

        def notification():
            objs = []
            walk(app, ["app"], objs)
            for o, _ in objs:
                if o.getRole() == pyatspi.ROLE_NOTIFICATION and "Opened" in (o.name or ""):
                    return o
            return None

        note = wait_for(notification, "the 'Opened ...' announcement")
        print(f"announcement: {note.name!r}")

        objects = []
        walk(app, ["app"], objects)
        focusable = 0
        for obj, path in objects:
            role = obj.getRole()
            states = obj.getState()
            if role in (pyatspi.ROLE_INVALID, pyatspi.ROLE_UNKNOWN):
                failures.append(f"no role: {describe(path)}")
            if states.contains(pyatspi.STATE_FOCUSABLE) and states.contains(pyatspi.STATE_SHOWING):
                focusable += 1
                if not (obj.name or "").strip():
                    failures.append(f"focusable without a name: {obj.getRoleName()} at {describe(path)}")
        print(f"walked {len(objects)} objects, {focusable} focusable and showing")
        if focusable < 5:
            failures.append(f"only {focusable} focusable objects: the tree is not exposed")

        previews = [o for o, _ in objects if o.name == "Interpoint preview"]
        if not previews:
            failures.append("no accessible 'Interpoint preview'")
        else:
            preview = previews[0]
            if preview.getRole() in (pyatspi.ROLE_INVALID, pyatspi.ROLE_UNKNOWN):
                failures.append("preview has no role")
            description = preview.description or ""
            print(f"preview: role={preview.getRoleName()} description={description!r}")
            if "dots" not in description and "blank" not in description:
                failures.append(f"preview does not describe its cell: {description!r}")
            try:
                text = preview.queryText()
                line = text.getText(0, -1)
                print(f"preview line as text: {line!r}")
                if not line or not all(0x2800 <= ord(c) <= 0x28FF for c in line):
                    failures.append(f"preview text is not the braille line: {line!r}")
            except NotImplementedError:
                failures.append("preview has no text interface")
        for name in ("Print text", "Braille"):
            if not any(o.name == name for o, _ in objects):
                failures.append(f"no accessible '{name}'")
        # A combo box speaks its current item as its name; its purpose is the description.
        if not any(o.getRole() == pyatspi.ROLE_COMBO_BOX and "braille code" in (o.description or "")
                   for o, _ in objects):
            failures.append("no described braille table picker")
    finally:
        proc.terminate()
        try:
            proc.wait(10)
        except subprocess.TimeoutExpired:
            proc.kill()
    if failures:
        print("\n".join("FAIL: " + f for f in failures))
        return 1
    print("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())
