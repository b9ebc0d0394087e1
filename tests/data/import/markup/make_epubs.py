#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Writes the small EPUB 3 and EPUB 2 test books next to this script (run it
# only to change them): mimetype first and stored, as OCF requires.
import os
import zipfile

HERE = os.path.dirname(os.path.abspath(__file__))
CONTAINER = """<?xml version="1.0"?>
<container version="1.0" xmlns="urn:oasis:names:tc:opendocument:xmlns:container">
<rootfiles><rootfile full-path="{opf}" media-type="application/oebps-package+xml"/></rootfiles>
</container>"""


def write(name, opf_path, parts):
    with zipfile.ZipFile(os.path.join(HERE, name), "w") as z:
        z.writestr(zipfile.ZipInfo("mimetype", (2020, 1, 1, 0, 0, 0)), "application/epub+zip",
                   compress_type=zipfile.ZIP_STORED)
        parts = [("META-INF/container.xml", CONTAINER.format(opf=opf_path))] + parts
        for path, text in parts:
            info = zipfile.ZipInfo(path, (2020, 1, 1, 0, 0, 0))
            info.compress_type = zipfile.ZIP_DEFLATED
            z.writestr(info, text)


XHTML = """<?xml version="1.0" encoding="UTF-8"?>
<html xmlns="http://www.w3.org/1999/xhtml" xmlns:epub="http://www.idpf.org/2007/ops" xml:lang="en" lang="en">
<head><title>{title}</title></head>
<body>{body}</body>
</html>"""

OPF3 = """<?xml version="1.0" encoding="UTF-8"?>
<package xmlns="http://www.idpf.org/2007/opf" version="3.0" unique-identifier="id">
<metadata xmlns:dc="http://purl.org/dc/elements/1.1/">
<dc:identifier id="id">urn:uuid:2b6f0c3e-0000-4000-8000-000000000001</dc:identifier>
<dc:title>The Water Cycle</dc:title>
<dc:creator>C. Author</dc:creator>
<dc:publisher>Tactus Test Press</dc:publisher>
<dc:date>2024</dc:date>
<dc:language>en</dc:language>
</metadata>
<manifest>
<item id="nav" href="nav.xhtml" media-type="application/xhtml+xml" properties="nav"/>
<item id="c1" href="text/chapter%201.xhtml" media-type="application/xhtml+xml"/>
<item id="c2" href="text/chapter-2.xhtml" media-type="application/xhtml+xml" properties="mathml"/>
<item id="notes" href="text/endnotes.xhtml" media-type="application/xhtml+xml"/>
<item id="pic" href="images/sun.png" media-type="image/png"/>
</manifest>
<spine>
<itemref idref="c1"/>
<itemref idref="c2"/>
<itemref idref="pic"/>
<itemref idref="notes"/>
</spine>
</package>"""

CH1 = """<section epub:type="chapter"><h2>Evaporation</h2>
<p>The sun warms the sea<a href="endnotes.xhtml#note-1" epub:type="noteref">1</a>, and water rises.</p>
<span epub:type="pagebreak" id="page-2" title="2"/>
<p>It rises as <i>vapour</i>.</p></section>"""
CH2 = """<section epub:type="chapter"><h2>Rain</h2>
<p>Drops fall<a href="../text/endnotes.xhtml#note-2" epub:type="noteref">2</a>. A drop weighs
<math xmlns="http://www.w3.org/1998/Math/MathML"><msup><mi>r</mi><mn>3</mn></msup></math> units.</p>
<p xml:lang="de">Es regnet.</p></section>"""
NOTES = """<section epub:type="endnotes"><h2>Endnotes</h2><ol>
<li id="note-1" epub:type="endnote"><p>Mostly the oceans. <a href="chapter%201.xhtml#x" epub:type="backlink">\u21a9</a></p></li>
<li id="note-2" epub:type="endnote"><p>As rain or snow.</p></li>
</ol></section>"""
NAV = """<nav epub:type="toc"><ol><li><a href="text/chapter%201.xhtml">Evaporation</a></li></ol></nav>"""

write("water-cycle.epub", "OEBPS/content.opf", [
    ("OEBPS/content.opf", OPF3),
    ("OEBPS/nav.xhtml", XHTML.format(title="Contents", body=NAV)),
    ("OEBPS/text/chapter 1.xhtml", XHTML.format(title="Evaporation", body=CH1)),
    ("OEBPS/text/chapter-2.xhtml", XHTML.format(title="Rain", body=CH2)),
    ("OEBPS/text/endnotes.xhtml", XHTML.format(title="Endnotes", body=NOTES)),
])

OPF2 = """<?xml version="1.0" encoding="UTF-8"?>
<package xmlns="http://www.idpf.org/2007/opf" version="2.0" unique-identifier="id">
<metadata xmlns:dc="http://purl.org/dc/elements/1.1/" xmlns:opf="http://www.idpf.org/2007/opf">
<dc:title>Snow</dc:title><dc:creator opf:role="aut">D. Author</dc:creator>
<dc:language>en</dc:language><dc:identifier id="id">snow-1</dc:identifier>
</metadata>
<manifest>
<item id="ncx" href="toc.ncx" media-type="application/x-dtbncx+xml"/>
<item id="a" href="a.html" media-type="application/xhtml+xml"/>
</manifest>
<spine toc="ncx"><itemref idref="a"/></spine>
</package>"""
# EPUB 2 content is XHTML 1.1; this one uses HTML entities, so it is not
# well-formed XML and is read by the HTML parser.
A = """<html xmlns="http://www.w3.org/1999/xhtml"><head><title>Snow</title></head>
<body><h1>Snow</h1><p>Snow&nbsp;falls in winter.<br/>It is cold.</p></body></html>"""
write("snow-epub2.epub", "content.opf", [("content.opf", OPF2), ("a.html", A)])
