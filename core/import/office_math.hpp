// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Equations in word-processor documents as linear text, in reading order,
// until Tactus writes math braille: Word's OMML (m:oMath) and MathML (an ODF
// formula object). Fractions are "a/b" (parenthesised when a side has more
// than one character), roots "√(x)", delimiters as print has them, and
// superscripts and subscripts are raised and lowered runs
// (document::Position), so the translator writes the code's level indicators.
#include <pugixml.hpp>

#include <functional>
#include <string_view>

#include "document/document.hpp"

namespace tactus::import::detail {

using MathSink = std::function<void(std::string_view utf8, document::Position position)>;

// <m:oMath> or <m:oMathPara>.
void omml_linear(const pugi::xml_node& math, const MathSink& out);
// <math:math> (MathML 2, as LibreOffice Math stores it).
void mathml_linear(const pugi::xml_node& math, const MathSink& out);

}  // namespace tactus::import::detail
