#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Tactus's DOCX and ODT as another program reads them: LibreOffice.

Each document is saved by Tactus as DOCX and as ODT (tactus-cli convert);
LibreOffice converts each to the other format (its DOCX to ODT, its ODT to
DOCX), and Tactus opens LibreOffice's file. The document Tactus reads from
LibreOffice's file must be the one it wrote (compared as Markdown, one block a
line): headings, lists and their numbers, tables, notes and emphasis survive a
word processor that knows nothing of Tactus's importers.

Usage: libreoffice_round_trip.py TACTUS_CLI DATA_DIR   (exit 77: no soffice)
"""
import pathlib
import shutil
import subprocess
import sys
import tempfile

# Real documents nobody here wrote, and the hand-made lessons
# (tests/data/import/README.md). Text boxes are left out: LibreOffice turns a
# text box into a drawing shape, which the ODT importer does not read as one.
DOCUMENTS = [
    "lesson.md", "lesson.docx", "lesson.odt",
    "public/pandoc-lists.docx", "public/pandoc-tables.docx", "public/pandoc-notes.docx",
    "public/pandoc-block_quotes.docx", "public/pandoc-inline_formatting.docx",
    "public/pandoc-orderedListRoman.odt", "public/pandoc-footnote.odt", "public/pandoc-tableWithContents.odt",
    "public/python-docx-tbl-cell-access.docx",
]


def run(*args):
    done = subprocess.run(args, capture_output=True, text=True, timeout=300)
    if done.returncode != 0:
        sys.exit(f"{' '.join(map(str, args))} failed ({done.returncode}): {done.stderr}")
    return done


def main():
    cli, data = sys.argv[1], pathlib.Path(sys.argv[2]) / "import"
    soffice = shutil.which("soffice")
    if not soffice:
        print("libreoffice_round_trip: no soffice; skipped")
        return 77
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        written, converted = tmp / "written", tmp / "converted"
        written.mkdir()
        converted.mkdir()
        for doc in DOCUMENTS:
            stem = pathlib.Path(doc).stem
            for ext in ("docx", "odt"):
                run(cli, "convert", data / doc, written / f"{stem}.{ext}")
        profile = f"-env:UserInstallation=file://{tmp / 'profile'}"
        run(soffice, profile, "--headless", "--convert-to", "odt", "--outdir", converted,
            *sorted(written.glob("*.docx")))
        run(soffice, profile, "--headless", "--convert-to", "docx:MS Word 2007 XML", "--outdir", converted,
            *sorted(written.glob("*.odt")))
        for ours in sorted(written.iterdir()):
            other = "odt" if ours.suffix == ".docx" else "docx"
            theirs = converted / f"{ours.stem}.{other}"
            if not theirs.exists():
                failures.append(f"{ours.name}: LibreOffice did not convert it")
                continue
            a, b = tmp / "a.md", tmp / "b.md"
            run(cli, "convert", ours, a)
            run(cli, "convert", theirs, b)
            if a.read_text() != b.read_text():
                failures.append(f"{ours.name} -> LibreOffice {other}:\n--- Tactus wrote\n{a.read_text()}"
                                f"\n--- Tactus read from LibreOffice's file\n{b.read_text()}")
    for f in failures:
        print(f)
    print(f"libreoffice_round_trip: {2 * len(DOCUMENTS) - len(failures)} of {2 * len(DOCUMENTS)} files the same")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
