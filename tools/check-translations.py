#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Fails when the zh_TW interface is incomplete or uses a wrong term.

Runs Qt's lupdate over the same sources the app build translates (widgets/ and
app/gui/main.cpp) into a scratch copy of resources/i18n/tactus_zh_TW.ts, so a
tr() string added in the code but missing from the .ts counts as missing, and
then lists every message that is unfinished or has an empty translation.

usage: check-translations.py [LUPDATE]     exit 0 complete, 1 incomplete, 2 setup error
"""
import glob
import os
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TS = os.path.join(ROOT, "resources", "i18n", "tactus_zh_TW.ts")

# Words that read naturally but name the wrong thing on this machine. 筆架 is a
# pen rest; the embosser's moving head is a carriage, 字車 as on a typewriter.
WRONG_TERMS = {"筆架": "字車 (carriage)"}


def main():
    lupdate = sys.argv[1] if len(sys.argv) > 1 else shutil.which("lupdate") or "/usr/lib/qt6/bin/lupdate"
    if not os.path.exists(lupdate):
        print(f"check-translations: lupdate not found at {lupdate}", file=sys.stderr)
        return 2
    sources = sorted(glob.glob(os.path.join(ROOT, "widgets", "*.cpp")) + glob.glob(os.path.join(ROOT, "widgets", "*.hpp")))
    sources.append(os.path.join(ROOT, "app", "gui", "main.cpp"))
    with tempfile.TemporaryDirectory() as work:
        scratch = os.path.join(work, "tactus_zh_TW.ts")
        shutil.copy(TS, scratch)
        run = subprocess.run([lupdate, "-silent", "-no-obsolete", *sources, "-ts", scratch],
                             capture_output=True, text=True)
        if run.returncode != 0:
            print(f"check-translations: lupdate failed:\n{run.stderr}", file=sys.stderr)
            return 2
        root = ET.parse(scratch).getroot()
    total, missing = 0, []
    for context in root.iter("context"):
        name = context.findtext("name")
        for message in context.iter("message"):
            total += 1
            tr = message.find("translation")
            plural = tr is not None and list(tr.iter("numerusform"))
            text = "".join((f.text or "") for f in tr.iter("numerusform")) if plural else (tr.text if tr is not None else "")
            if tr is None or tr.get("type") == "unfinished" or not (text or "").strip():
                loc = message.find("location")
                where = f"{loc.get('filename')}:{loc.get('line')}" if loc is not None else "?"
                missing.append(f"{name}: \"{message.findtext('source')}\" ({os.path.basename(where)})")
    wrong = []
    for context in root.iter("context"):
        for message in context.iter("message"):
            text = "".join(message.find("translation").itertext()) if message.find("translation") is not None else ""
            for bad, good in WRONG_TERMS.items():
                if bad in text:
                    wrong.append(f"\"{message.findtext('source')}\" -> \"{text}\": {bad} should be {good}")
    print(f"zh_TW: {total} strings, {len(missing)} untranslated, {len(wrong)} with a wrong term")
    for w in wrong:
        print("  wrong term: " + w)
    for m in missing:
        print("  untranslated: " + m)
    if missing:
        print("Add them to resources/i18n/zh_TW_glossary.py, run lupdate and the glossary "
              "(see resources/i18n/README or the glossary's docstring).")
    return 1 if missing or wrong else 0


if __name__ == "__main__":
    sys.exit(main())
