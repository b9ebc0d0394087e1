#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Writes content_controls.docx with python-docx (Debian's python3-docx):
# content controls around a block, a table row, a cell and a run (with Word's
# placeholder text), a picture with a description and one without,
# superscript and subscript runs, a ruby (Phonetic Guide), an equation (OMML)
# in a numbered item, and a cell of two paragraphs. The parts python-docx has
# no API for are added with its own oxml element factory.
# Run: /usr/bin/python3 make_docx.py (from this folder).
import copy
import pathlib
import docx
from docx.oxml import parse_xml
from docx.oxml.ns import nsdecls

HERE = pathlib.Path(__file__).parent
W = nsdecls("w")
M = 'xmlns:m="http://schemas.openxmlformats.org/officeDocument/2006/math"'

d = docx.Document()
body = d.element.body


def sdt_around(element, alias):
    sdt = parse_xml(f'<w:sdt {W}><w:sdtPr><w:alias w:val="{alias}"/></w:sdtPr><w:sdtContent/></w:sdt>')
    element.addprevious(sdt)
    sdt[1].append(element)


d.add_heading("Cover", level=1)
sdt_around(d.add_paragraph("Annual report title")._p, "Title")
sdt_around(d.add_paragraph("A subtitle under it")._p, "Subtitle")
p = d.add_paragraph("Pick one: ")
run = p.add_run("Choose an item.")
sdt_around(run._r, "Dropdown")
p.add_run(" then go on.")

t = d.add_table(rows=2, cols=2)
t.cell(0, 0).text = "Author name"
t.cell(0, 1).text = "Jane Doe"
t.cell(1, 0).text = "Cell first paragraph"
t.cell(1, 0).add_paragraph("Cell second paragraph")
t.cell(1, 1).text = "Plain cell"
row, cell = t.rows[0]._tr, t.cell(1, 1)._tc
sdt_around(row, "Row")
sdt_around(cell, "Cell")

p = d.add_paragraph("Area m")
p.add_run("2").font.superscript = True
p.add_run(" and mass m")
p.add_run("2").font.subscript = True
p.add_run(".")

p = d.add_paragraph("Read ")
p._p.append(parse_xml(f'<w:r {W}><w:ruby><w:rubyPr><w:rubyAlign w:val="center"/></w:rubyPr>'
                      '<w:rt><w:r><w:t>toh kyoh</w:t></w:r></w:rt>'
                      '<w:rubyBase><w:r><w:t>Tokyo</w:t></w:r></w:rubyBase></w:ruby></w:r>'))
p.add_run(" aloud.")

p = d.add_paragraph("The formula ", style="List Number")
p._p.append(parse_xml(f'<m:oMath {M} {W}><m:r><m:t>E=m</m:t></m:r><m:sSup><m:e><m:r><m:t>c</m:t></m:r></m:e>'
                      '<m:sup><m:r><m:t>2</m:t></m:r></m:sup></m:sSup></m:oMath>'))
p.add_run(" holds.")
p = d.add_paragraph("", style="List Number")
p._p.append(parse_xml(f'<m:oMath {M}><m:f><m:num><m:r><m:t>a+b</m:t></m:r></m:num>'
                      '<m:den><m:r><m:t>2</m:t></m:r></m:den></m:f></m:oMath>'))

p = d.add_paragraph("A picture: ")
p.add_run().add_picture(str(HERE / "red.png"))
p.add_run(" and one without: ")
p.add_run().add_picture(str(HERE / "red.png"))
pics = d.element.body.findall(".//{http://schemas.openxmlformats.org/drawingml/2006/wordprocessingDrawing}docPr")
pics[0].set("descr", "A red square")
pics[1].set("descr", "")
d.add_paragraph("The end.")
d.save(HERE / "content_controls.docx")

# A document of nothing but pictures without a description.
d = docx.Document()
d.add_paragraph().add_run().add_picture(str(HERE / "red.png"))
d.add_paragraph().add_run().add_picture(str(HERE / "red.png"))
d.save(HERE / "pictures_only.docx")
