#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes structure.docx and structure.odt: the document of structure.md as a
word processor stores it (WordprocessingML, OpenDocument), hand-made with
zipfile because the build machine has no LibreOffice. Run it only to change the
inputs on purpose; the golden test reads the committed files."""
import zipfile

W = 'xmlns:w="http://schemas.openxmlformats.org/wordprocessingml/2006/main"'
R = 'xmlns:r="http://schemas.openxmlformats.org/officeDocument/2006/relationships"'
FIXED = (1980, 1, 1, 0, 0, 0)  # a fixed date: the same bytes on every run


def write(path, parts):
    with zipfile.ZipFile(path, "w") as z:
        for name, text in parts:
            info = zipfile.ZipInfo(name, FIXED)
            info.compress_type = zipfile.ZIP_STORED if name == "mimetype" else zipfile.ZIP_DEFLATED
            z.writestr(info, text)


def p(text, style=None, num=None):
    ppr = ""
    if style or num:
        ppr = "<w:pPr>"
        if style:
            ppr += f'<w:pStyle w:val="{style}"/>'
        if num:
            ppr += f'<w:numPr><w:ilvl w:val="{num[1]}"/><w:numId w:val="{num[0]}"/></w:numPr>'
        ppr += "</w:pPr>"
    return f"<w:p>{ppr}{text}</w:p>"


def r(text):
    return f'<w:r><w:t xml:space="preserve">{text}</w:t></w:r>'


def cell(text):
    return f"<w:tc>{p(r(text))}</w:tc>"


def row(cells, header=False):
    trpr = "<w:trPr><w:tblHeader/></w:trPr>" if header else ""
    return "<w:tr>" + trpr + "".join(cell(c) for c in cells) + "</w:tr>"


docx_body = "".join([
    p(r("Field Trip"), "Heading1"),
    p(r("Our class visited the river.") + '<w:r><w:rPr><w:rStyle w:val="FootnoteReference"/></w:rPr>'
      '<w:footnoteReference w:id="2"/></w:r>' + r(" We saw herons and a kingfisher.")),
    p(r("What to bring"), "Heading2"),
    p(r("A notebook"), num=("1", 0)),
    p(r("Two pencils"), num=("1", 0)),
    p(r("one sharp, one spare"), num=("1", 1)),
    p(r("Lunch"), num=("1", 0)),
    p(r("Meet at the gate."), num=("2", 0)),
    p(r("Walk to the bridge."), num=("2", 0)),
    p(r("Rivers are the roads of the land; they carry water, soil and life from the hills down to the sea."),
      "Quote"),
    "<w:tbl><w:tblPr/>" + row(["Bird", "Seen", "Where"], True) + row(["Heron", "3", "reeds"]) +
    row(["Kingfisher", "1", "bridge"]) + "</w:tbl>",
    p(r("Plants by the water:")),
    "<w:tbl><w:tblPr/>" + row(["Plant", "Where it grows", "What it needs"], True) +
    row(["Willow", "on the river bank", "wet soil and sun"]) + row(["Reed", "in shallow water", "still water"]) +
    "</w:tbl>",
    # A header and its part exist, and are left out on purpose. The last
    # section's properties sit in the body, as Word writes them (in a
    # paragraph they would be a section break: a print page break at the end).
    '<w:sectPr><w:headerReference w:type="default" r:id="rIdHeader"/></w:sectPr>',
])

docx = [
    ("[Content_Types].xml",
     '<?xml version="1.0" encoding="UTF-8"?><Types xmlns="http://schemas.openxmlformats.org/package/2006/content-types">'
     '<Default Extension="rels" ContentType="application/vnd.openxmlformats-package.relationships+xml"/>'
     '<Default Extension="xml" ContentType="application/xml"/></Types>'),
    ("_rels/.rels",
     '<?xml version="1.0" encoding="UTF-8"?><Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">'
     '<Relationship Id="rId1" Type="http://schemas.openxmlformats.org/officeDocument/2006/relationships/officeDocument" Target="word/document.xml"/>'
     '</Relationships>'),
    ("word/_rels/document.xml.rels",
     '<?xml version="1.0" encoding="UTF-8"?><Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">'
     '<Relationship Id="rId1" Type="http://schemas.openxmlformats.org/officeDocument/2006/relationships/styles" Target="styles.xml"/>'
     '<Relationship Id="rId2" Type="http://schemas.openxmlformats.org/officeDocument/2006/relationships/numbering" Target="numbering.xml"/>'
     '<Relationship Id="rId3" Type="http://schemas.openxmlformats.org/officeDocument/2006/relationships/footnotes" Target="footnotes.xml"/>'
     '<Relationship Id="rIdHeader" Type="http://schemas.openxmlformats.org/officeDocument/2006/relationships/header" Target="header1.xml"/>'
     '</Relationships>'),
    ("word/document.xml",
     f'<?xml version="1.0" encoding="UTF-8"?><w:document {W} {R}><w:body>{docx_body}</w:body></w:document>'),
    ("word/styles.xml",
     f'<?xml version="1.0" encoding="UTF-8"?><w:styles {W}>'
     '<w:style w:type="paragraph" w:default="1" w:styleId="Normal"><w:name w:val="Normal"/></w:style>'
     '<w:style w:type="paragraph" w:styleId="Heading1"><w:name w:val="heading 1"/><w:basedOn w:val="Normal"/></w:style>'
     '<w:style w:type="paragraph" w:styleId="Heading2"><w:name w:val="heading 2"/><w:basedOn w:val="Normal"/></w:style>'
     '<w:style w:type="paragraph" w:styleId="Quote"><w:name w:val="Quote"/><w:basedOn w:val="Normal"/>'
     '<w:rPr><w:i/></w:rPr></w:style>'
     '<w:style w:type="character" w:styleId="FootnoteReference"><w:name w:val="footnote reference"/>'
     '<w:rPr><w:vertAlign w:val="superscript"/></w:rPr></w:style>'
     '</w:styles>'),
    ("word/numbering.xml",
     f'<?xml version="1.0" encoding="UTF-8"?><w:numbering {W}>'
     '<w:abstractNum w:abstractNumId="0">'
     '<w:lvl w:ilvl="0"><w:numFmt w:val="bullet"/><w:lvlText w:val="\uf0b7"/></w:lvl>'
     '<w:lvl w:ilvl="1"><w:numFmt w:val="bullet"/><w:lvlText w:val="o"/></w:lvl></w:abstractNum>'
     '<w:abstractNum w:abstractNumId="1"><w:lvl w:ilvl="0"><w:start w:val="1"/><w:numFmt w:val="decimal"/>'
     '<w:lvlText w:val="%1."/></w:lvl></w:abstractNum>'
     '<w:num w:numId="1"><w:abstractNumId w:val="0"/></w:num>'
     '<w:num w:numId="2"><w:abstractNumId w:val="1"/></w:num>'
     '</w:numbering>'),
    ("word/footnotes.xml",
     f'<?xml version="1.0" encoding="UTF-8"?><w:footnotes {W}>'
     '<w:footnote w:type="separator" w:id="-1"><w:p><w:r><w:separator/></w:r></w:p></w:footnote>'
     '<w:footnote w:type="continuationSeparator" w:id="0"><w:p><w:r><w:continuationSeparator/></w:r></w:p></w:footnote>'
     '<w:footnote w:id="2"><w:p><w:r><w:rPr><w:rStyle w:val="FootnoteReference"/></w:rPr><w:footnoteRef/></w:r>'
     '<w:r><w:t xml:space="preserve"> The walk took an hour.</w:t></w:r></w:p></w:footnote>'
     '</w:footnotes>'),
    ("word/header1.xml",
     f'<?xml version="1.0" encoding="UTF-8"?><w:hdr {W}><w:p><w:r><w:t>Class 4 newsletter</w:t></w:r></w:p></w:hdr>'),
]
write("structure.docx", docx)

NS = ('xmlns:office="urn:oasis:names:tc:opendocument:xmlns:office:1.0" '
      'xmlns:style="urn:oasis:names:tc:opendocument:xmlns:style:1.0" '
      'xmlns:text="urn:oasis:names:tc:opendocument:xmlns:text:1.0" '
      'xmlns:table="urn:oasis:names:tc:opendocument:xmlns:table:1.0" '
      'xmlns:fo="urn:oasis:names:tc:opendocument:xmlns:xsl-fo-compatible:1.0" office:version="1.3"')


def tp(text, style="Standard"):
    return f'<text:p text:style-name="{style}">{text}</text:p>'


def trow(cells):
    return "<table:table-row>" + "".join(
        f'<table:table-cell office:value-type="string">{tp(c)}</table:table-cell>' for c in cells) + "</table:table-row>"


odt_text = "".join([
    '<text:h text:style-name="Heading_20_1" text:outline-level="1">Field Trip</text:h>',
    tp('Our class visited the river.<text:note text:id="ftn1" text:note-class="footnote">'
       '<text:note-citation>1</text:note-citation><text:note-body>'
       '<text:p text:style-name="Footnote">The walk took an hour.</text:p></text:note-body></text:note>'
       ' We saw herons and a kingfisher.'),
    '<text:h text:style-name="Heading_20_2" text:outline-level="2">What to bring</text:h>',
    '<text:list text:style-name="L1">'
    f'<text:list-item>{tp("A notebook")}</text:list-item>'
    f'<text:list-item>{tp("Two pencils")}<text:list><text:list-item>{tp("one sharp, one spare")}'
    '</text:list-item></text:list></text:list-item>'
    f'<text:list-item>{tp("Lunch")}</text:list-item></text:list>',
    '<text:list text:style-name="L2">'
    f'<text:list-item>{tp("Meet at the gate.")}</text:list-item>'
    f'<text:list-item>{tp("Walk to the bridge.")}</text:list-item></text:list>',
    tp("Rivers are the roads of the land; they carry water, soil and life from the hills down to the sea.",
       "Quotations"),
    '<table:table table:name="Birds"><table:table-column table:number-columns-repeated="3"/>'
    "<table:table-header-rows>" + trow(["Bird", "Seen", "Where"]) + "</table:table-header-rows>" +
    trow(["Heron", "3", "reeds"]) + trow(["Kingfisher", "1", "bridge"]) + "</table:table>",
    tp("Plants by the water:"),
    '<table:table table:name="Plants"><table:table-column table:number-columns-repeated="3"/>'
    "<table:table-header-rows>" + trow(["Plant", "Where it grows", "What it needs"]) + "</table:table-header-rows>" +
    trow(["Willow", "on the river bank", "wet soil and sun"]) + trow(["Reed", "in shallow water", "still water"]) +
    "</table:table>",
])

odt = [
    ("mimetype", "application/vnd.oasis.opendocument.text"),
    ("META-INF/manifest.xml",
     '<?xml version="1.0" encoding="UTF-8"?><manifest:manifest xmlns:manifest="urn:oasis:names:tc:opendocument:xmlns:manifest:1.0" manifest:version="1.3">'
     '<manifest:file-entry manifest:full-path="/" manifest:media-type="application/vnd.oasis.opendocument.text"/>'
     '<manifest:file-entry manifest:full-path="content.xml" manifest:media-type="text/xml"/>'
     '<manifest:file-entry manifest:full-path="styles.xml" manifest:media-type="text/xml"/>'
     '</manifest:manifest>'),
    ("content.xml",
     f'<?xml version="1.0" encoding="UTF-8"?><office:document-content {NS}><office:automatic-styles>'
     '<text:list-style style:name="L1">'
     '<text:list-level-style-bullet text:level="1" text:bullet-char="•"/>'
     '<text:list-level-style-bullet text:level="2" text:bullet-char="◦"/></text:list-style>'
     '<text:list-style style:name="L2"><text:list-level-style-number text:level="1" style:num-suffix="." '
     'style:num-format="1"/></text:list-style>'
     f'</office:automatic-styles><office:body><office:text>{odt_text}</office:text></office:body>'
     '</office:document-content>'),
    ("styles.xml",
     f'<?xml version="1.0" encoding="UTF-8"?><office:document-styles {NS}><office:styles>'
     '<style:style style:name="Standard" style:family="paragraph"/>'
     '<style:style style:name="Quotations" style:family="paragraph" style:parent-style-name="Standard">'
     '<style:paragraph-properties fo:margin-left="1cm"/></style:style>'
     '</office:styles><office:master-styles><style:master-page style:name="Standard">'
     '<style:header><text:p>Class 4 newsletter</text:p></style:header></style:master-page>'
     '</office:master-styles></office:document-styles>'),
]
write("structure.odt", odt)

# A print page break inside a table cell: it must come after the table
# (tests/import/structure_import_test.cpp).
break_body = ("<w:tbl>" + row(["one", "two"]) + "<w:tr><w:tc>" + p(r("three ") + '<w:r><w:br w:type="page"/></w:r>' +
                                                       r("four")) + "</w:tc></w:tr></w:tbl>" + p(r("after")))
write("table_break.docx", [docx[0], docx[1],
                           ("word/document.xml",
                            f'<?xml version="1.0" encoding="UTF-8"?><w:document {W} {R}><w:body>{break_body}'
                            '</w:body></w:document>')])

# Merged cells: a table whose first heading is merged down over two
# header rows and whose second heading is merged across two columns, with a
# body row merged across them too (a simple table: it fits the line); and a
# table too wide for the line (listed format) with a merged entry and a row
# that starts one column in (DOCX w:gridBefore; ODT: an empty first cell).
# structure-spans.docx and structure-spans.odt are the same document and lay
# out to the same braille (tests/golden/golden_test.cpp).


def scell(text, span=1, vmerge=None):
    tcpr = ""
    if span > 1 or vmerge:
        tcpr = "<w:tcPr>" + (f'<w:gridSpan w:val="{span}"/>' if span > 1 else "")
        tcpr += ('<w:vMerge w:val="restart"/>' if vmerge == "restart" else "<w:vMerge/>" if vmerge else "")
        tcpr += "</w:tcPr>"
    return f"<w:tc>{tcpr}{p(r(text)) if text else '<w:p/>'}</w:tc>"


def srow(cells, header=False, before=0):
    trpr = ""
    if header or before:
        trpr = "<w:trPr>" + (f'<w:gridBefore w:val="{before}"/>' if before else "") + (
            "<w:tblHeader/>" if header else "") + "</w:trPr>"
    return "<w:tr>" + trpr + "".join(cells) + "</w:tr>"


spans_docx_body = "".join([
    p(r("Birds by the river"), "Heading1"),
    "<w:tbl><w:tblPr/>" +
    srow([scell("Bird", vmerge="restart"), scell("Seen", span=2)], True) +
    srow([scell("", vmerge="continue"), scell("Morning"), scell("Evening")], True) +
    srow([scell("Heron"), scell("3"), scell("1")]) +
    srow([scell("Owl"), scell("none", span=2)]) +
    srow([scell("Kingfisher"), scell("1"), scell("2")]) + "</w:tbl>",
    p(r("Plants by the water:")),
    "<w:tbl><w:tblPr/>" +
    srow([scell("Plant"), scell("Where it grows"), scell("What it needs")], True) +
    srow([scell("Willow"), scell("on the river bank"), scell("wet soil and sun")]) +
    srow([scell("Moss"), scell("anywhere damp and shady, on stones and bark", span=2)]) +
    srow([scell("by the gate"), scell("little water")], before=1) + "</w:tbl>",
    p(r("After the tables.")),
])
spans_rels = ('<?xml version="1.0" encoding="UTF-8"?><Relationships '
              'xmlns="http://schemas.openxmlformats.org/package/2006/relationships">'
              '<Relationship Id="rId1" Type="http://schemas.openxmlformats.org/officeDocument/2006/relationships/styles"'
              ' Target="styles.xml"/></Relationships>')
write("structure-spans.docx", [docx[0], docx[1], ("word/_rels/document.xml.rels", spans_rels),
                               ("word/document.xml",
                                f'<?xml version="1.0" encoding="UTF-8"?><w:document {W} {R}><w:body>{spans_docx_body}'
                                '</w:body></w:document>'),
                               docx[4]])


def tcell(text, columns=1, rows=1):
    attrs = ""
    if columns > 1:
        attrs += f' table:number-columns-spanned="{columns}"'
    if rows > 1:
        attrs += f' table:number-rows-spanned="{rows}"'
    return f'<table:table-cell office:value-type="string"{attrs}>{tp(text) if text else ""}</table:table-cell>'


def covered(n=1):
    return (f'<table:covered-table-cell table:number-columns-repeated="{n}"/>' if n > 1
            else "<table:covered-table-cell/>")


def trow_cells(cells):
    return "<table:table-row>" + "".join(cells) + "</table:table-row>"


spans_odt_text = "".join([
    '<text:h text:style-name="Heading_20_1" text:outline-level="1">Birds by the river</text:h>',
    '<table:table table:name="Birds"><table:table-column table:number-columns-repeated="3"/>'
    "<table:table-header-rows>" +
    trow_cells([tcell("Bird", rows=2), tcell("Seen", columns=2), covered()]) +
    trow_cells([covered(), tcell("Morning"), tcell("Evening")]) + "</table:table-header-rows>" +
    trow_cells([tcell("Heron"), tcell("3"), tcell("1")]) +
    trow_cells([tcell("Owl"), tcell("none", columns=2), covered()]) +
    trow_cells([tcell("Kingfisher"), tcell("1"), tcell("2")]) + "</table:table>",
    tp("Plants by the water:"),
    '<table:table table:name="Plants"><table:table-column table:number-columns-repeated="3"/>'
    "<table:table-header-rows>" + trow(["Plant", "Where it grows", "What it needs"]) + "</table:table-header-rows>" +
    trow(["Willow", "on the river bank", "wet soil and sun"]) +
    trow_cells([tcell("Moss"), tcell("anywhere damp and shady, on stones and bark", columns=2), covered()]) +
    trow_cells([tcell(""), tcell("by the gate"), tcell("little water")]) + "</table:table>",
    tp("After the tables."),
])
write("structure-spans.odt", [odt[0], odt[1],
                              ("content.xml",
                               f'<?xml version="1.0" encoding="UTF-8"?><office:document-content {NS}>'
                               f'<office:body><office:text>{spans_odt_text}</office:text></office:body>'
                               '</office:document-content>'),
                              odt[3]])
