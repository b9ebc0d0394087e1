#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Makes an EPUB 3 of the King James Version from Debian's bible-kjv text, so
a whole book can be timed through the EPUB importer and the book layout
(volumes, title page, contents, running heads) against the same text as plain
lines. One content document per book of the Bible: the book's name as h1,
each chapter as h2, each verse a paragraph with its number; the navigation
document lists the books.

    bible -f gen1:1-rev22:21 > kjv.txt
    bench/layout/kjv_epub.py kjv.txt kjv.epub
"""
import html
import re
import sys
import zipfile

NAMES = [
    "Genesis", "Exodus", "Leviticus", "Numbers", "Deuteronomy", "Joshua", "Judges", "Ruth", "1 Samuel",
    "2 Samuel", "1 Kings", "2 Kings", "1 Chronicles", "2 Chronicles", "Ezra", "Nehemiah", "Esther", "Job",
    "Psalms", "Proverbs", "Ecclesiastes", "Song of Solomon", "Isaiah", "Jeremiah", "Lamentations", "Ezekiel",
    "Daniel", "Hosea", "Joel", "Amos", "Obadiah", "Jonah", "Micah", "Nahum", "Habakkuk", "Zephaniah", "Haggai",
    "Zechariah", "Malachi", "Matthew", "Mark", "Luke", "John", "Acts", "Romans", "1 Corinthians",
    "2 Corinthians", "Galatians", "Ephesians", "Philippians", "Colossians", "1 Thessalonians",
    "2 Thessalonians", "1 Timothy", "2 Timothy", "Titus", "Philemon", "Hebrews", "James", "1 Peter", "2 Peter",
    "1 John", "2 John", "3 John", "Jude", "Revelation"]
VERSE = re.compile(r"^(\d?[A-Za-z]+)(\d+):(\d+) (.*)$")


def books(lines):
    """[(abbreviation, [(chapter, [(verse, text)])])] in the order of the text."""
    out = []
    for line in lines:
        m = VERSE.match(line.rstrip("\n"))
        if not m:
            if out and line.strip():  # a verse continued on the next line
                out[-1][1][-1][1][-1] = (out[-1][1][-1][1][-1][0], out[-1][1][-1][1][-1][1] + " " + line.strip())
            continue
        book, chapter, verse, text = m.group(1), int(m.group(2)), int(m.group(3)), m.group(4)
        if not out or out[-1][0] != book:
            out.append((book, []))
        chapters = out[-1][1]
        if not chapters or chapters[-1][0] != chapter:
            chapters.append((chapter, []))
        chapters[-1][1].append((verse, text))
    return out


def xhtml(title, body):
    return ('<?xml version="1.0" encoding="UTF-8"?>\n<!DOCTYPE html>\n'
            '<html xmlns="http://www.w3.org/1999/xhtml" xmlns:epub="http://www.idpf.org/2007/ops" '
            'xml:lang="en" lang="en">\n<head><title>' + html.escape(title) + '</title></head>\n<body>\n' +
            body + '</body>\n</html>\n')


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: kjv_epub.py KJV.txt OUT.epub")
    with open(sys.argv[1], encoding="utf-8") as f:
        parsed = books(f)
    if len(parsed) != len(NAMES):
        sys.exit(f"{sys.argv[1]}: {len(parsed)} books, expected {len(NAMES)} (bible -f gen1:1-rev22:21)")
    with zipfile.ZipFile(sys.argv[2], "w") as z:
        z.writestr("mimetype", "application/epub+zip", compress_type=zipfile.ZIP_STORED)
        z.writestr("META-INF/container.xml",
                   '<?xml version="1.0"?>\n<container version="1.0" '
                   'xmlns="urn:oasis:names:tc:opendocument:xmlns:container"><rootfiles>'
                   '<rootfile full-path="OEBPS/content.opf" media-type="application/oebps-package+xml"/>'
                   '</rootfiles></container>\n', compress_type=zipfile.ZIP_DEFLATED)
        items, spine, nav = [], [], []
        for i, ((_, chapters), name) in enumerate(zip(parsed, NAMES), 1):
            body = f"<section epub:type=\"chapter\">\n<h1>{html.escape(name)}</h1>\n"
            for chapter, verses in chapters:
                body += f"<h2>Chapter {chapter}</h2>\n"
                body += "".join(f"<p>{v} {html.escape(t)}</p>\n" for v, t in verses)
            body += "</section>\n"
            z.writestr(f"OEBPS/book{i:02d}.xhtml", xhtml(name, body), compress_type=zipfile.ZIP_DEFLATED)
            items.append(f'<item id="b{i:02d}" href="book{i:02d}.xhtml" media-type="application/xhtml+xml"/>')
            spine.append(f'<itemref idref="b{i:02d}"/>')
            nav.append(f'<li><a href="book{i:02d}.xhtml">{html.escape(name)}</a></li>')
        z.writestr("OEBPS/nav.xhtml", xhtml("Contents", '<nav epub:type="toc"><ol>' + "".join(nav) + "</ol></nav>\n"),
                   compress_type=zipfile.ZIP_DEFLATED)
        z.writestr("OEBPS/content.opf",
                   '<?xml version="1.0" encoding="UTF-8"?>\n<package xmlns="http://www.idpf.org/2007/opf" '
                   'version="3.0" unique-identifier="id"><metadata xmlns:dc="http://purl.org/dc/elements/1.1/">'
                   '<dc:identifier id="id">tactus-bench-kjv</dc:identifier>'
                   '<dc:title>The Holy Bible, King James Version</dc:title><dc:language>en</dc:language>'
                   '<dc:creator>Debian bible-kjv-text</dc:creator>'
                   '<meta property="dcterms:modified">2000-01-01T00:00:00Z</meta></metadata><manifest>'
                   '<item id="nav" href="nav.xhtml" media-type="application/xhtml+xml" properties="nav"/>' +
                   "".join(items) + '</manifest><spine>' + "".join(spine) + '</spine></package>\n',
                   compress_type=zipfile.ZIP_DEFLATED)


if __name__ == "__main__":
    main()
