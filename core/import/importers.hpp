// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <filesystem>
// The individual importers behind import_bytes(). Each returns a Document whose
// errors carry a location inside the input (line:column, byte N, part:line:column);
// import_bytes() prefixes the source name.
#include <string_view>

#include "common/result.hpp"
#include "document/document.hpp"
#include "import/import.hpp"

namespace tactus::import::detail {

// `utf8` is already decoded and validated (see encoding.hpp).
Result<document::Document> import_text(std::string_view utf8);
// `image_folder`: keep the pictures found in it or below (ImportOptions::images).
// picture_marks: ImportOptions::picture_marks.
Result<document::Document> import_markdown(std::string_view utf8, const std::filesystem::path* image_folder = nullptr,
                                           bool picture_marks = false);
Result<document::Document> import_docx(std::string_view bytes, RubyGuide ruby = RubyGuide::after, bool images = false);
Result<document::Document> import_brf(std::string_view bytes);
Result<document::Document> import_pef(std::string_view bytes);
Result<document::Document> import_odt(std::string_view bytes, RubyGuide ruby = RubyGuide::after, bool images = false);
// HTML5 or XHTML (markup_import.cpp), EPUB 2/3 (epub_import.cpp), DTBook/NIMAS.
Result<document::Document> import_html(std::string_view bytes, const std::filesystem::path* image_folder = nullptr);
Result<document::Document> import_epub(std::string_view bytes, bool images = false);
Result<document::Document> import_dtbook(std::string_view bytes);

}  // namespace tactus::import::detail
