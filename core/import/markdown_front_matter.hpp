// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// YAML front matter at the top of a Markdown file (pandoc, Jekyll, Hugo, R
// Markdown): a block between a first line `---` and a line `---` or `...`. It
// is the document's metadata, not text: its title, author, date, language and
// description go into Document::metadata under their Dublin Core names (the
// PEF's head), and the rest of the block is left out. Only the plain
// `key: value` lines and `- item` lists of these keys are read; a YAML
// construct beyond that (a folded block, nested maps) is skipped.
#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

#include "document/document.hpp"

namespace tactus::import::detail {

struct FrontMatter {
    std::size_t length = 0;  // bytes of the block, its closing line included
    int lines = 0;           // lines it spans
    std::vector<document::MetadataItem> metadata;
};

// The front matter `markdown` begins with, if it begins with one.
std::optional<FrontMatter> front_matter(std::string_view markdown);

}  // namespace tactus::import::detail
