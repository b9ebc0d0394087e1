// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The individual importers behind import_bytes(). Each returns a Document whose
// errors carry a location inside the input (line:column, byte N, part:line:column);
// import_bytes() prefixes the source name.
#include <string_view>

#include "common/result.hpp"
#include "document/document.hpp"

namespace tactus::import_detail {

// `utf8` is already decoded and validated (see encoding.hpp).
Result<Document> import_text(std::string_view utf8);
Result<Document> import_markdown(std::string_view utf8);
Result<Document> import_docx(std::string_view bytes);
Result<Document> import_brf(std::string_view bytes);
Result<Document> import_pef(std::string_view bytes);

}  // namespace tactus::import_detail
