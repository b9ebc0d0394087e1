// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A soft line break: a line break inside a block's text, as a hard-wrapped
// paragraph of a text file keeps it (import/text_import.cpp). Print keeps the
// line as written; braille reflows it: the break, with the spaces and tabs at
// the end of the line before it and the start of the line after it, reads as
// one space (translate/translated_document.cpp; the Markdown writer, which
// writes a paragraph on one line). The editor shows the lines as written.
#include <string>
#include <string_view>

namespace tactus::document {

// The text with each line break (LF, CR) and the spaces and tabs (and vertical tabs) around it as
// one space: "one  \n  two" -> "one two". Text without a line break is returned
// as it is.
std::string soft_breaks_as_spaces(std::string_view utf8);

}  // namespace tactus::document
