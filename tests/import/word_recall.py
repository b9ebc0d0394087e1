#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Word recall of Tactus's DOCX and ODT import against pandoc's.

For each document: the words of pandoc's plain text, and the words of
Tactus's uncontracted braille (en-ueb-g1) back-translated by tactus-cli. The
recall is the share of pandoc's words (counted with repeats, compared without
case) that Tactus's text holds as well. Every file where pandoc finds at
least MIN_WORDS words must reach THRESHOLD; a failure lists the words lost.

Usage: word_recall.py TACTUS_CLI FILE_OR_FOLDER...   (exit 77: no pandoc)
"""
import collections
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile
import unicodedata

THRESHOLD = 0.95
MIN_WORDS = 20
TABLE = "en-ueb-g1.ctb"
WORD = re.compile(r"[^\W_]+", re.UNICODE)


# liblouis's back-translation writes a braille indicator it has no print for
# (UEB's level indicators ⠔ ⠢, dots 35 and 26) as an escape, "\\35/".
LIST_MARKER = re.compile(r"(?m)^[ \t]*(?:\d+|[A-Za-z]|[ivxlcdmIVXLCDM]+)[.)][ \t]+")
ESCAPE = re.compile(r"\\\d+/")


def words(text):
    # NFKC: print's m² is the word m2, as the braille's level indicator and 2.
    text = unicodedata.normalize("NFKC", ESCAPE.sub("", text))
    return collections.Counter(w.lower() for w in WORD.findall(text))


def pandoc_words(path):
    out = subprocess.run(["pandoc", "--to", "plain", "--wrap", "none", str(path)],
                         capture_output=True, text=True, timeout=120)
    if out.returncode != 0:
        raise RuntimeError(f"pandoc failed on {path}: {out.stderr.strip()}")
    # pandoc's plain writer numbers every ordered list from its own start
    # (a continued ODT list starts again at 1): its list markers are not the
    # document's words, so they are left out of the count.
    return words(LIST_MARKER.sub("", out.stdout))


def tactus_words(cli, path, tmp):
    braille = pathlib.Path(tmp) / "out.txt"
    # Wide, long pages without page numbers: every word on one line, no
    # running numbers among the words.
    lay = subprocess.run([cli, "layout", "-t", TABLE, "--to", "unicode", "--cells", "200", "--lines", "200",
                          "--page-numbers", "none", "--no-print-pages", str(path), "-o", str(braille)],
                         capture_output=True, text=True, timeout=120)
    if lay.returncode != 0:
        raise RuntimeError(f"tactus-cli layout failed on {path} ({lay.returncode}): {lay.stderr.strip()}")
    text = braille.read_text(encoding="utf-8").replace("\f", "\n")
    back = subprocess.run([cli, "translate", "--back", "-t", TABLE, "-"], input=text,
                          capture_output=True, text=True, timeout=120)
    if back.returncode != 0:
        raise RuntimeError(f"back-translation failed on {path}: {back.stderr.strip()}")
    return words(back.stdout)


def main(argv):
    if len(argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    if shutil.which("pandoc") is None:
        print("pandoc not found: skipped", file=sys.stderr)
        return 77
    cli = argv[1]
    files = []
    for arg in argv[2:]:
        p = pathlib.Path(arg)
        files += sorted(q for q in p.iterdir() if q.suffix in (".docx", ".odt")) if p.is_dir() else [p]
    failed = 0
    with tempfile.TemporaryDirectory() as tmp:
        for f in files:
            try:
                expected = pandoc_words(f)
            except RuntimeError as e:  # pandoc cannot read it: nothing to compare
                print(f"skip {f.name}: {e}")
                continue
            total = sum(expected.values())
            try:
                got = tactus_words(cli, f, tmp)
            except RuntimeError as e:  # refused (no text): nothing found
                print(f"     {e}")
                got = collections.Counter()
            found = sum(min(n, got[w]) for w, n in expected.items())
            recall = found / total if total else 1.0
            checked = total >= MIN_WORDS
            ok = not checked or recall >= THRESHOLD
            failed += not ok
            print(f"{'ok  ' if ok else 'FAIL'} {recall:7.1%} {found:5}/{total:<5} {f.name}"
                  + ("" if checked else " (fewer than %d words: not checked)" % MIN_WORDS))
            if not ok:
                lost = sorted(w for w, n in expected.items() if got[w] < n)
                print("     lost: " + " ".join(lost[:40]))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
