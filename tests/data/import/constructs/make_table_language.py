#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Writes table_language.docx with python-docx (Debian's python3-docx): a
# table whose table style (python-docx's own template's "Light Grid Accent 1")
# gives its text French for Latin script and Chinese (Taiwan) for East Asian
# script in the style's w:rPr/w:lang, with one run in the table marked English
# directly; a second table in "Table Grid", which names no language; body
# text before and after. The style's w:lang is added with python-docx's own
# oxml element factory (it has no API for a style's language).
# Run: /usr/bin/python3 make_table_language.py (from this folder).
import pathlib
import docx
from docx.oxml import parse_xml
from docx.oxml.ns import nsdecls

HERE = pathlib.Path(__file__).parent
W = nsdecls("w")

d = docx.Document()
style = d.styles["Light Grid Accent 1"]
rpr = style.element.get_or_add_rPr()
rpr.append(parse_xml(f'<w:lang {W} w:val="fr-FR" w:eastAsia="zh-TW"/>'))

d.add_paragraph("A paragraph before the tables.")
t = d.add_table(rows=2, cols=2)
t.style = style
t.cell(0, 0).text = "Bonjour le monde"
t.cell(0, 1).text = "中文字"
t.cell(1, 0).text = "Au revoir"
p = t.cell(1, 1).paragraphs[0]
run = p.add_run("Hello")
run._r.get_or_add_rPr().append(parse_xml(f'<w:lang {W} w:val="en-US"/>'))
plain = d.add_table(rows=1, cols=1)
plain.style = d.styles["Table Grid"]
plain.cell(0, 0).text = "Plain words"
d.add_paragraph("A paragraph after the tables.")
d.save(HERE / "table_language.docx")
