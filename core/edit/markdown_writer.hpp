// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The editor's lines as the Markdown file it saves: one block per line, and the
// blank line between blocks that Markdown needs, so core's importer reads the
// file back to the same blocks (tests/edit/markdown_writer_test.cpp).
#include <span>
#include <string>

namespace tactus::edit {

std::string to_markdown(std::span<const std::string> editor_lines);

}  // namespace tactus::edit
