#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Regenerates the fixtures of this folder: constructs.odt and constructs.docx
# by LibreOffice from constructs.fodt (a flat ODT written by hand), and
# content_controls.docx and pictures_only.docx by python-docx (make_docx.py).
# Needs soffice (Debian: libreoffice-writer-nogui, libreoffice-math-nogui)
# and Debian's python3-docx. Then: TACTUS_UPDATE_GOLDEN=1 on the import tests.
set -eu
cd "$(dirname "$0")"
soffice --headless --convert-to odt constructs.fodt
soffice --headless --convert-to 'docx:MS Word 2007 XML' constructs.fodt
/usr/bin/python3 make_docx.py
